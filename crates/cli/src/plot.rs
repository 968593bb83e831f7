//! The SVG plots: the traction field of one contact (Fig. 10 of the paper) and the creep curves
//! (Fig. 9), and what every figure shares (the page, the axes, numbers, the legend's place).
//! Drawn with `plotters`' SVG backend into a string; text goes out as SVG `<text>`
//! (generic `sans-serif`), so any SVG viewer shows the plot without fonts shipped here. Nothing
//! here writes files: the caller hands the text to `output`.

use crate::curves::{Curve, Curves};
use crate::error::CliError;
use crate::table::format_short;
use ballscrew_core::contact::analysis::{ContactRun, Law, Parameter};
use ballscrew_core::contact::fastsim::{Element, TractionBound};
use core::fmt::Display;
use plotters::coord::Shift;
use plotters::element::{DashedPathElement, MultiLineText};
use plotters::prelude::*;

pub(crate) const FONT: &str = "sans-serif";
/// Most arrows drawn per axis of the ellipse; finer grids show every k-th element.
const MAX_ARROWS_PER_AXIS: usize = 40;
/// Bands across a strip in which the adhesion area is shaded (each cut to the ellipse).
const SHADE_BANDS: usize = 4;
/// Axis margin around the ellipse, as a fraction of its semi-axes.
const MARGIN: f64 = 1.12;

const ARROW: RGBColor = RGBColor(178, 24, 43);
/// Fill of the adhesion area of the traction field.
pub(crate) const ADHESION: RGBColor = RGBColor(198, 219, 239);
/// Colour of a marked point (a ring and its note): the detected harmonic, the worst map cell.
pub(crate) const MARK: RGBColor = RGBColor(230, 159, 0);
const OUTLINE: RGBColor = RGBColor(0, 0, 0);
pub(crate) const GRID_BOLD: RGBColor = RGBColor(215, 215, 215);
pub(crate) const GREY: RGBColor = RGBColor(130, 130, 130);

pub(crate) fn plot_error(e: impl Display) -> CliError {
    CliError::Output(format!("cannot draw the plot: {e}"))
}

/// Header lines over the plot: the first larger.
pub(crate) fn header(area: &DrawingArea<SVGBackend<'_>, Shift>, lines: &[String]) -> Result<(), CliError> {
    let mut y = 14;
    for (i, line) in lines.iter().enumerate() {
        let size = if i == 0 { 22 } else { 17 };
        let style = TextStyle::from((FONT, size).into_font()).color(&BLACK);
        area.draw_text(line, &style, (24, y)).map_err(plot_error)?;
        y += size + 8;
    }
    Ok(())
}

/// A drawing area of the SVG backend, in pixels.
pub(crate) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// An SVG page of `size` pixels: white, the header `lines` in its top `header_px`, and what
/// `draw` puts on the page (`root`, in page pixels) and below the header (`body`).
pub(crate) fn page(
    size: (u32, u32),
    header_px: u32,
    lines: &[String],
    draw: impl FnOnce(&Area<'_>, &Area<'_>) -> Result<(), CliError>,
) -> Result<String, CliError> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_error)?;
        let (top, body) = root.split_vertically(header_px);
        header(&top, lines)?;
        draw(&root, &body)?;
        root.present().map_err(plot_error)?;
    }
    Ok(svg)
}

/// A number for plot text: 4 significant digits, a typographic minus.
pub(crate) fn num(x: f64) -> String {
    let a = x.abs();
    let text = if x == 0.0 {
        "0".to_string()
    } else if !x.is_finite() {
        format_short(x)
    } else if (1e-3..1e5).contains(&a) {
        let decimals = (3 - a.log10().floor() as i32).max(0) as usize;
        let t = format!("{x:.decimals$}");
        if t.contains('.') { t.trim_end_matches('0').trim_end_matches('.').to_string() } else { t }
    } else {
        let t = format!("{x:.3e}");
        match t.split_once('e') {
            Some((m, e)) if m.contains('.') => format!("{}e{e}", m.trim_end_matches('0').trim_end_matches('.')),
            _ => t,
        }
    };
    text.replace('-', "−")
}

/// A chart with f64 axes on an SVG string.
pub(crate) type Chart<'a, 'b> = ChartContext<
    'a,
    SVGBackend<'b>,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// A single-panel chart on `body` over `x` by `y` (the margin and label areas of the sweep and
/// diagnosis figures).
pub(crate) fn chart_on<'a, 'b>(
    body: &'a Area<'b>,
    x: core::ops::Range<f64>,
    y: core::ops::Range<f64>,
) -> Result<Chart<'a, 'b>, CliError> {
    ChartBuilder::on(body)
        .margin(20)
        .x_label_area_size(56)
        .y_label_area_size(90)
        .build_cartesian_2d(x, y)
        .map_err(plot_error)
}

/// The axes of a chart (its x axis linear or logarithmic): light grid, 8 labels a side, short
/// numbers, descriptions.
pub(crate) fn axes<X>(
    chart: &mut ChartContext<'_, SVGBackend<'_>, Cartesian2d<X, plotters::coord::types::RangedCoordf64>>,
    x_desc: &str,
    y_desc: &str,
) -> Result<(), CliError>
where
    X: Ranged<ValueType = f64> + plotters::coord::ranged1d::ValueFormatter<f64>,
{
    chart
        .configure_mesh()
        .max_light_lines(0)
        .bold_line_style(GRID_BOLD)
        .x_labels(8)
        .y_labels(8)
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .label_style((FONT, 14))
        .axis_desc_style((FONT, 16))
        .draw()
        .map_err(plot_error)
}

/// A tick label: the value rounded off its floating-point noise.
pub(crate) fn tick(x: &f64) -> String {
    num((x * 1e9).round() / 1e9)
}

/// Margin and marker room plotters gives a legend (its defaults), pixels.
const LEGEND_MARGIN: i32 = 10;
const LEGEND_MARKER: i32 = 30;
/// Gap plotters leaves between a legend in a corner and the plot's edge, pixels.
const LEGEND_GAP: i32 = 5;
/// Font size of the legends, pixels.
pub(crate) const LEGEND_FONT: u32 = 14;

/// The size (width, height) in pixels of the legend plotters draws for `labels` (the same
/// estimate plotters makes).
pub(crate) fn legend_size(labels: &[&str]) -> Result<(i32, i32), CliError> {
    let style = TextStyle::from((FONT, LEGEND_FONT).into_font());
    let mut text = MultiLineText::<_, &str>::new((0, 0), &style);
    for l in labels {
        text.push_line(*l);
    }
    let (w, h) = text.estimate_dimension().map_err(plot_error)?;
    Ok((w + LEGEND_MARKER + 2 * LEGEND_MARGIN, h + 2 * LEGEND_MARGIN))
}

/// The corners a legend may take, in order of preference.
const CORNERS: [SeriesLabelPosition; 4] = [
    SeriesLabelPosition::UpperLeft,
    SeriesLabelPosition::UpperRight,
    SeriesLabelPosition::LowerRight,
    SeriesLabelPosition::LowerLeft,
];

/// The box (left, top, right, bottom) of a legend of `size` in corner `at` of a plotting area of
/// `area` pixels, relative to the area.
fn legend_box(at: &SeriesLabelPosition, size: (i32, i32), area: (i32, i32)) -> (i32, i32, i32, i32) {
    let left = match at {
        SeriesLabelPosition::UpperRight | SeriesLabelPosition::LowerRight => area.0 - size.0 - LEGEND_GAP,
        _ => LEGEND_GAP,
    };
    let top = match at {
        SeriesLabelPosition::LowerLeft | SeriesLabelPosition::LowerRight => area.1 - size.1 - LEGEND_GAP,
        _ => LEGEND_GAP,
    };
    (left, top, left + size.0, top + size.1)
}

/// Where a chart's legend goes: a chart of `y` range (built by `build`) whose legend of `size`
/// pixels covers none of `marked` (data coordinates, each with `pad` pixels around) and as few
/// of `points` as can be; when every corner covers a point, the y range is raised until the
/// top of the plot is free for the legend. Returns the chart and the legend's corner.
pub(crate) fn with_legend<'a, 'b>(
    build: impl Fn(f64, f64) -> Result<Chart<'a, 'b>, CliError>,
    (y0, y1): (f64, f64),
    size: (i32, i32),
    marked: &[(f64, f64)],
    pad: i32,
    points: &[(f64, f64)],
) -> Result<(Chart<'a, 'b>, SeriesLabelPosition), CliError> {
    let chart = build(y0, y1)?;
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let area = (xs.end - xs.start, ys.end - ys.start);
    let base = (xs.start, ys.start);
    let inside = |chart: &Chart<'_, '_>, b: (i32, i32, i32, i32), p: &(f64, f64), pad: i32| {
        let (x, y) = chart.backend_coord(p);
        let (x, y) = (x - base.0, y - base.1);
        x >= b.0 - pad && x <= b.2 + pad && y >= b.1 - pad && y <= b.3 + pad
    };
    let best = |chart: &Chart<'_, '_>| {
        CORNERS
            .iter()
            .filter(|c| !marked.iter().any(|m| inside(chart, legend_box(c, size, area), m, pad)))
            .map(|c| (points.iter().filter(|p| inside(chart, legend_box(c, size, area), p, 2)).count(), c.clone()))
            .min_by_key(|(n, _)| *n)
    };
    if let Some((0, corner)) = best(&chart) {
        return Ok((chart, corner));
    }
    // Room on top: the data keep to the plot's height less the legend's (and its gaps).
    let free = f64::from(size.1 + 2 * LEGEND_GAP + pad);
    let h = f64::from(area.1);
    let raised = if h > free + 20.0 { y1 + (y1 - y0) * free / (h - free) } else { y1 + (y1 - y0) };
    drop(chart);
    let chart = build(y0, raised)?;
    let corner = best(&chart).map_or(SeriesLabelPosition::UpperLeft, |(_, c)| c);
    Ok((chart, corner))
}

/// Draws the series labels of `chart` in `corner`, as every figure does.
pub(crate) fn legend<'a, 'b: 'a>(chart: &mut Chart<'a, 'b>, corner: SeriesLabelPosition) -> Result<(), CliError> {
    chart
        .configure_series_labels()
        .position(corner)
        .background_style(WHITE.mix(0.9))
        .border_style(GREY)
        .label_font((FONT, LEGEND_FONT))
        .draw()
        .map_err(plot_error)
}

/// `10^e` as text with superscript digits.
fn power_of_ten(e: i32) -> String {
    let sup = |c: char| match c {
        '-' => '⁻',
        '0' => '⁰',
        '1' => '¹',
        '2' => '²',
        '3' => '³',
        '4' => '⁴',
        '5' => '⁵',
        '6' => '⁶',
        '7' => '⁷',
        '8' => '⁸',
        _ => '⁹',
    };
    format!("10{}", e.to_string().chars().map(sup).collect::<String>())
}

/// The traction field over the ellipse, Fig. 10 style: the outline, an arrow per element in slip
/// (the traction on the ball, true direction, length proportional to its magnitude), the
/// elements in adhesion shaded (a rectangle per run of them along a strip and band across it,
/// cut to the ellipse). Axes in mm; when the ellipse is slender the x axis is stretched (the
/// factor is printed on the axis). `source` says where the contact came from.
pub fn traction_svg(run: &ContactRun, source: &str, elements: &[Element]) -> Result<String, CliError> {
    const SIZE: (u32, u32) = (1100, 1200);
    const HEADER: u32 = 165;
    // Room of the axes (labels, descriptions, margins) around the plot area, pixels.
    const AXES: (f64, f64) = (190.0, 130.0);
    let c = &run.contact;
    let (a, b) = (c.semi_axis_rolling_m * 1e3, c.semi_axis_lateral_m * 1e3);
    let n = run.grid;
    let field = &elements[..(n * n).min(elements.len())];

    // Plot area: the largest box of the drawn aspect that fits. The drawn aspect is the
    // ellipse's own within [0.8, 1.25]; a more slender ellipse is drawn with a stretched (or
    // squeezed) x axis, nearly a circle as in Fig. 10 of the paper, so that the arrows along
    // both axes stay readable.
    let (avail_w, avail_h) = (SIZE.0 as f64 - AXES.0, (SIZE.1 - HEADER) as f64 - AXES.1);
    let drawn = (a / b).clamp(0.8, 1.25);
    let (w, h) = if avail_w / avail_h > drawn { (avail_h * drawn, avail_h) } else { (avail_w, avail_w / drawn) };
    let stretch = drawn / (a / b);
    let x_desc = if (stretch - 1.0).abs() > 0.005 {
        format!("x along rolling, mm (leading edge at +a) — x axis drawn at {:.2}× the scale of y", stretch)
    } else {
        "x along rolling, mm (leading edge at +a)".to_string()
    };

    // Arrows: one per element in slip (every stride-th element on grids finer than 40), scaled
    // as large as the element pitch (central strip) allows without overlap.
    let stride = n.div_ceil(MAX_ARROWS_PER_AXIS);
    let shown = n.div_ceil(stride);
    let pitch_x = w / (2.0 * MARGIN * a) * (2.0 * a / n as f64) * stride as f64;
    let pitch_y = h / (2.0 * MARGIN * b) * (2.0 * b / n as f64) * stride as f64;
    let arrows: Vec<&Element> = field
        .iter()
        .enumerate()
        .filter(|(k, e)| e.sliding && (k % n) % stride == stride / 2 && (k / n) % stride == stride / 2)
        .map(|(_, e)| e)
        .collect();
    let max_x = arrows.iter().map(|e| e.traction_x_pa.abs()).fold(0.0, f64::max);
    let max_y = arrows.iter().map(|e| e.traction_y_pa.abs()).fold(0.0, f64::max);
    let fits = |pitch: f64, max: f64| if max > 0.0 { 0.9 * pitch / max } else { f64::INFINITY };
    let scale = fits(pitch_x, max_x).min(fits(pitch_y, max_y));
    let longest = arrows.iter().map(|e| e.traction_x_pa.hypot(e.traction_y_pa)).fold(0.0, f64::max);

    let cr = &run.creep;
    let lines = [
        "Traction on the ball by FASTSIM: arrows where the ball slips, shaded where it adheres".to_string(),
        format!(
            "ξ(y=0) = {}, η = {}, φ = {} 1/mm, k_h = {} 1/mm²   →   adhesion {:.1} % of the ellipse, |F|/(μQ) = {}",
            num(cr.xi),
            num(cr.eta),
            num(cr.phi_per_m * 1e-3),
            num(cr.heathcote_per_m2 * 1e-6),
            100.0 * run.fastsim.result.adhesion_share(),
            num(run.fastsim.forces.force_ratio),
        ),
        format!(
            "a = {} mm, b = {} mm, Q = {} N, μ = {}; {} traction bound, {n} × {n} strips (x: elements along each strip)",
            num(a),
            num(b),
            num(c.normal_load_n),
            num(c.friction_coefficient),
            run.bound.name(),
        ),
        format!(
            "shaded: adhesion; arrow: traction on the ball at an element, length ∝ |traction|, longest {} MPa{}",
            num(longest * 1e-6),
            if stride > 1 {
                format!("; one element in {stride} per axis drawn ({shown} × {shown})")
            } else {
                String::new()
            }
        ),
        source.to_string(),
    ];

    page(SIZE, HEADER, &lines, |root, body| {
        let (body_w, body_h) = body.dim_in_pixel();
        let spare_w = ((body_w as f64 - AXES.0 - w) / 2.0).max(0.0) as u32;
        let spare_h = ((body_h as f64 - AXES.1 - h) / 2.0).max(0.0) as u32;
        let mut chart = ChartBuilder::on(body)
            .margin_left(20 + spare_w)
            .margin_right(50 + spare_w)
            .margin_top(20 + spare_h)
            .margin_bottom(20 + spare_h)
            .x_label_area_size(90)
            .y_label_area_size(120)
            .build_cartesian_2d(-MARGIN * a..MARGIN * a, -MARGIN * b..MARGIN * b)
            .map_err(plot_error)?;
        chart
            .configure_mesh()
            .max_light_lines(0)
            .bold_line_style(GRID_BOLD)
            .x_labels(7)
            .y_labels(11)
            .x_label_formatter(&tick)
            .y_label_formatter(&tick)
            .x_desc(x_desc)
            .y_desc("y lateral, mm")
            .label_style((FONT, 17))
            .axis_desc_style((FONT, 19))
            .draw()
            .map_err(plot_error)?;
        // The adhesion area: each strip's runs of adhering elements, a rectangle per run and band.
        let dy = 2.0 * b / n as f64;
        let mut shaded = Vec::new();
        for strip in field.chunks(n) {
            let mut run: Option<(f64, f64, f64)> = None;
            for e in strip.iter().chain(core::iter::once(&Element { sliding: true, ..Element::default() })) {
                let dx = if e.area_m2 > 0.0 { e.area_m2 * 1e6 / dy } else { 0.0 };
                let (x, y) = (e.x_m * 1e3, e.y_m * 1e3);
                match (&mut run, e.sliding || dx <= 0.0) {
                    (Some(r), false) => r.1 = x + 0.5 * dx,
                    (None, false) => run = Some((x - 0.5 * dx, x + 0.5 * dx, y)),
                    (Some(r), true) => {
                        // In bands across the strip, each cut to the ellipse at its outer edge.
                        for k in 0..SHADE_BANDS {
                            let y0 = r.2 - 0.5 * dy + dy * k as f64 / SHADE_BANDS as f64;
                            let y1 = y0 + dy / SHADE_BANDS as f64;
                            let outer = y0.abs().max(y1.abs()).min(b);
                            let half = a * (1.0 - (outer / b).powi(2)).max(0.0).sqrt();
                            let (x0, x1) = (r.0.max(-half), r.1.min(half));
                            if x1 > x0 {
                                // A quarter band's overlap: no seam between the bands.
                                shaded.push([(x0, y0), (x1, y1 + 0.25 * dy / SHADE_BANDS as f64)]);
                            }
                        }
                        run = None;
                    }
                    (None, true) => {}
                }
            }
        }
        chart
            .draw_series(shaded.into_iter().map(|corners| Rectangle::new(corners, ADHESION.filled())))
            .map_err(plot_error)?;
        let outline = (0..=240).map(|i| {
            let t = core::f64::consts::TAU * f64::from(i) / 240.0;
            (a * t.cos(), b * t.sin())
        });
        chart.draw_series(LineSeries::new(outline, OUTLINE.stroke_width(2))).map_err(plot_error)?;
        if scale.is_finite() {
            for e in &arrows {
                let centre = chart.backend_coord(&(e.x_m * 1e3, e.y_m * 1e3));
                arrow(root, centre, (e.traction_x_pa * scale, -e.traction_y_pa * scale))?;
            }
        }
        Ok(())
    })
}

/// An arrow centred on `centre` (pixels), vector `v` in pixels (y down).
fn arrow(root: &DrawingArea<SVGBackend<'_>, Shift>, centre: (i32, i32), v: (f64, f64)) -> Result<(), CliError> {
    let len = v.0.hypot(v.1);
    if len < 2.0 {
        return Ok(());
    }
    let (ux, uy) = (v.0 / len, v.1 / len);
    let (cx, cy) = (f64::from(centre.0), f64::from(centre.1));
    let tail = (cx - 0.5 * v.0, cy - 0.5 * v.1);
    let tip = (cx + 0.5 * v.0, cy + 0.5 * v.1);
    let head = (0.38 * len).clamp(2.0, 8.0);
    let half = 0.45 * head;
    let base = (tip.0 - ux * head, tip.1 - uy * head);
    let px = |p: (f64, f64)| (p.0.round() as i32, p.1.round() as i32);
    root.draw(&PathElement::new(vec![px(tail), px(base)], ARROW.stroke_width(1))).map_err(plot_error)?;
    let left = (base.0 - uy * half, base.1 + ux * half);
    let right = (base.0 + uy * half, base.1 - ux * half);
    root.draw(&Polygon::new(vec![px(tip), px(left), px(right)], ARROW.filled())).map_err(plot_error)?;
    Ok(())
}

/// Colour and dash of a law's curve.
fn law_style(law: Law) -> (RGBColor, bool) {
    match law {
        Law::Fastsim(TractionBound::Parabolic) => (RGBColor(31, 119, 180), false),
        Law::Fastsim(TractionBound::Elliptical) => (RGBColor(44, 160, 44), false),
        Law::Eq24 => (RGBColor(214, 39, 40), true),
    }
}

/// A law in words, for legends.
fn law_label(law: Law) -> &'static str {
    match law {
        Law::Fastsim(TractionBound::Parabolic) => "FASTSIM, parabolic bound",
        Law::Fastsim(TractionBound::Elliptical) => "FASTSIM, elliptical bound",
        Law::Eq24 => "Eq. 24 (the model's law)",
    }
}

/// Axis symbol of a parameter.
fn symbol(p: Parameter) -> &'static str {
    match p {
        Parameter::Xi => "ξ",
        Parameter::Eta => "η",
        Parameter::PhiC => "φ c",
        Parameter::KhB2 => "k_h b²",
    }
}

/// Words of a parameter, for panel captions.
fn caption(p: Parameter) -> &'static str {
    match p {
        Parameter::Xi => "longitudinal creepage ξ",
        Parameter::Eta => "lateral creepage η",
        Parameter::PhiC => "spin φ c",
        Parameter::KhB2 => "Heathcote k_h b²",
    }
}

/// Which component carries the force of a set of curves, e.g. `F along −e (F_f = 0)`.
fn direction_note(set: &[&Curve]) -> String {
    let (mut e, mut f) = (0.0_f64, 0.0_f64);
    let (mut e_sum, mut f_sum) = (0.0, 0.0);
    for p in set.iter().flat_map(|c| &c.points) {
        e = e.max(p.forces.force_e_n.abs());
        f = f.max(p.forces.force_f_n.abs());
        e_sum += p.forces.force_e_n;
        f_sum += p.forces.force_f_n;
    }
    let sign = |s: f64| if s < 0.0 { "−" } else { "+" };
    if f <= 1e-9 * e {
        format!("F along {}e, F_f = 0", sign(e_sum))
    } else if e <= 1e-9 * f {
        format!("F along {}f, F_e = 0", sign(f_sum))
    } else {
        "F in the e-f plane".to_string()
    }
}

/// The creep curves, Fig. 9 style: four panels (xi, eta, phi c, k_h b^2), |F|/(mu Q) against
/// the parameter under each law, with Kalker's linear theory as a thin grey line.
pub fn curves_svg(curves: &Curves) -> Result<String, CliError> {
    const SIZE: (u32, u32) = (1300, 1080);
    const HEADER: u32 = 110;
    let (s, c) = (&curves.setup, &curves.setup.contact);
    let lines = [
        "Friction against each creep parameter, the other three zero (Fig. 9)".to_string(),
        format!(
            "a = {} mm, b = {} mm (a/b = {}), c = √(ab) = {} mm, Q = {} N, μ = {}; FASTSIM on {} × {} strips",
            num(c.semi_axis_rolling_m * 1e3),
            num(c.semi_axis_lateral_m * 1e3),
            num(c.a_over_b()),
            num(c.creep_length_m() * 1e3),
            num(c.normal_load_n),
            num(c.friction_coefficient),
            s.grid,
            s.grid
        ),
        s.source.clone(),
    ];
    page(SIZE, HEADER, &lines, |_, body| {
        for (parameter, panel) in Parameter::ALL.into_iter().zip(body.split_evenly((2, 2))) {
            let set: Vec<&Curve> = curves.of(parameter).collect();
            panel_chart(&panel, parameter, &set, curves.span)?;
        }
        Ok(())
    })
}

fn panel_chart(
    panel: &DrawingArea<SVGBackend<'_>, Shift>,
    parameter: Parameter,
    set: &[&Curve],
    span: f64,
) -> Result<(), CliError> {
    let Some(first) = set.first() else { return Ok(()) };
    let sat = first.saturation_value;
    let max = span * sat;
    // Axis numbers of order 1: the parameter times 10^-e.
    let e = if max > 0.0 { max.log10().floor() as i32 } else { 0 };
    let (unit, x_desc) = if (-1..=1).contains(&e) {
        (1.0, symbol(parameter).to_string())
    } else {
        (10f64.powi(e), format!("{} × {}", symbol(parameter), power_of_ten(-e)))
    };
    let y_top = set.iter().flat_map(|c| &c.points).map(|p| p.forces.force_ratio).fold(1.0, f64::max) * 1.08;
    let caption = format!("{} alone ({})", caption(parameter), direction_note(set));
    let mut chart = ChartBuilder::on(panel)
        .caption(caption, (FONT, 18))
        .margin(16)
        .x_label_area_size(52)
        .y_label_area_size(64)
        .build_cartesian_2d(0.0..max / unit, 0.0..y_top)
        .map_err(plot_error)?;
    axes(&mut chart, &x_desc, "|F| / (μQ)")?;
    // |F| = mu Q, and Kalker's linear theory up to the top of the panel.
    chart.draw_series(LineSeries::new([(0.0, 1.0), (max / unit, 1.0)], GREY.stroke_width(1))).map_err(plot_error)?;
    let x_end = (y_top * sat).min(max);
    chart
        .draw_series(LineSeries::new([(0.0, 0.0), (x_end / unit, x_end / sat)], GREY.stroke_width(1)))
        .map_err(plot_error)?
        .label("Kalker linear theory (Eq. 23)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], GREY.stroke_width(1)));
    for curve in set {
        let (colour, dashed) = law_style(curve.law);
        let style = colour.stroke_width(2);
        let pts: Vec<(f64, f64)> = curve.points.iter().map(|p| (p.value / unit, p.forces.force_ratio)).collect();
        if dashed {
            chart
                .draw_series(DashedLineSeries::new(pts, 8, 5, style))
                .map_err(plot_error)?
                .label(law_label(curve.law))
                .legend(move |(x, y)| DashedPathElement::new([(x, y), (x + 24, y)], 8, 5, style));
        } else {
            chart
                .draw_series(LineSeries::new(pts, style))
                .map_err(plot_error)?
                .label(law_label(curve.law))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
        }
    }
    // The legend where the curves are not: low curves (spin) leave the top free.
    let high = set.iter().flat_map(|c| &c.points).any(|p| p.forces.force_ratio > 0.5 * y_top);
    chart
        .configure_series_labels()
        .position(if high { SeriesLabelPosition::LowerRight } else { SeriesLabelPosition::UpperRight })
        .background_style(WHITE.mix(0.9))
        .border_style(GREY)
        .label_font((FONT, 14))
        .draw()
        .map_err(plot_error)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plot_numbers_are_short_with_a_typographic_minus() {
        assert_eq!(num(-0.00209734), "−0.002097");
        assert_eq!(num(2e-4), "2e−4");
        assert_eq!(num(62.10315), "62.1");
        assert_eq!(num(0.0), "0");
        assert_eq!(num(-0.0), "0");
        assert_eq!(num(1.5e6), "1.5e6");
        assert_eq!(tick(&-1e-17), "0");
        assert_eq!(tick(&0.30000000000000004), "0.3");
        assert_eq!(power_of_ten(-4), "10⁻⁴");
        assert_eq!(power_of_ten(3), "10³");
    }
}
