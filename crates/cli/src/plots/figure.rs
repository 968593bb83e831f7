//! What every figure shares: the SVG page with its header lines ([`page`]), the charts and their
//! axes ([`chart_on`], [`axes`]), numbers for plot text ([`num`], [`tick`], [`power_of_ten`]),
//! the legend and its place clear of the data ([`with_legend`], [`legend`]), the font and the
//! colours. Drawn with `plotters`' SVG backend into a string; text goes out as SVG `<text>`
//! (generic `sans-serif`), so any SVG viewer shows the plot without fonts shipped here.

use crate::error::CliError;
use crate::table::format_short;
use core::fmt::Display;
use plotters::coord::Shift;
use plotters::element::MultiLineText;
use plotters::prelude::*;

pub(crate) const FONT: &str = "sans-serif";
/// Colour of a marked point (a ring and its note): the detected harmonic, the worst map cell.
pub(crate) const MARK: RGBColor = RGBColor(230, 159, 0);
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
pub(crate) fn power_of_ten(e: i32) -> String {
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
