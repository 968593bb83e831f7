//! The figure of `ballscrew contact --plot FILE.svg`: the traction field over one contact's
//! ellipse by FASTSIM (Fig. 10 of the paper), arrows where the ball slips, the adhesion area
//! shaded.

use crate::error::CliError;
use crate::plots::figure::{FONT, GRID_BOLD, num, page, plot_error, tick};
use ballscrew_core::contact::analysis::ContactRun;
use ballscrew_core::contact::fastsim::Element;
use plotters::coord::Shift;
use plotters::prelude::*;

/// Most arrows drawn per axis of the ellipse; finer grids show every k-th element.
const MAX_ARROWS_PER_AXIS: usize = 40;
/// Bands across a strip in which the adhesion area is shaded (each cut to the ellipse).
const SHADE_BANDS: usize = 4;
/// Axis margin around the ellipse, as a fraction of its semi-axes.
const MARGIN: f64 = 1.12;

const ARROW: RGBColor = RGBColor(178, 24, 43);
/// Fill of the adhesion area of the traction field.
const ADHESION: RGBColor = RGBColor(198, 219, 239);
const OUTLINE: RGBColor = RGBColor(0, 0, 0);

/// The traction field over the ellipse, Fig. 10 style: the outline, an arrow per element in slip
/// (the traction on the ball, true direction, length proportional to its magnitude), the
/// elements in adhesion shaded (a rectangle per run of them along a strip and band across it,
/// cut to the ellipse). Axes in mm; when the ellipse is slender the x axis is stretched (the
/// factor is printed on the axis). `source` says where the contact came from.
pub fn svg(run: &ContactRun, source: &str, elements: &[Element]) -> Result<String, CliError> {
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
