//! The figure of `ballscrew sensitivity --plot FILE.svg`: a tornado chart. One bar per uncertain
//! input, largest swing on top, from the drag torque with the input at the low end of its spread
//! to the drag torque at its high end (the others nominal), about a vertical line at the nominal
//! drag torque; the band of the whole sample shaded behind.

use crate::error::CliError;
use crate::plots::figure::{FONT, GREY, GRID_BOLD, page, plot_error, tick};
use crate::table::format_short;
use ballscrew_batch::uncertainty::Sensitivity;
use ballscrew_core::input::UNCERTAIN_INPUTS;
use ballscrew_core::input::uncertainty::Spread;
use plotters::prelude::*;

const SIZE: (u32, u32) = (1400, 760);
const HEADER: u32 = 80;
/// The bar with the input at the low end of its spread.
const LOW: RGBColor = RGBColor(31, 119, 180);
/// The bar with the input at the high end.
const HIGH: RGBColor = RGBColor(255, 127, 14);
/// The band of the whole sample.
const BAND: RGBColor = RGBColor(160, 160, 160);

/// The figure; `title` says what was run and the band.
pub fn svg(title: &[String], s: &Sensitivity) -> Result<String, CliError> {
    let n = s.inputs.len().max(1);
    let ends = s.inputs.iter().flat_map(|i| [i.low_end_nm, i.high_end_nm]);
    let all: Vec<f64> = ends.chain([s.nominal_nm, s.band.low_nm, s.band.high_nm]).filter(|x| x.is_finite()).collect();
    let (lo, hi) = all.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
    if !lo.is_finite() {
        return Err(CliError::Eval("sensitivity plot: no finite torque to draw".into()));
    }
    let pad = if hi > lo { 0.08 * (hi - lo) } else { 0.1 * lo.abs().max(1e-3) };
    let (x0, x1) = (lo - pad, hi + pad);
    page(SIZE, HEADER, title, |_, body| {
        let mut chart = ChartBuilder::on(body)
            .margin(20)
            .x_label_area_size(56)
            .y_label_area_size(230)
            .build_cartesian_2d(x0..x1, 0.0..n as f64)
            .map_err(plot_error)?;
        // The inputs' names, largest swing on top.
        let name = |y: &f64| -> String {
            let row = n as f64 - y.floor() - 1.0;
            s.inputs
                .get(row as usize)
                .filter(|_| y.fract() == 0.5 && row >= 0.0)
                .map(|i| {
                    let input = &UNCERTAIN_INPUTS[i.input];
                    match input.spread {
                        Spread::Relative => format!("{} ±{} %", input.name, format_short(100.0 * i.half_width)),
                        Spread::Absolute if input.unit == "1" => {
                            format!("{} ±{}", input.name, format_short(i.half_width))
                        }
                        Spread::Absolute => format!("{} ±{} {}", input.name, format_short(i.half_width), input.unit),
                    }
                })
                .unwrap_or_default()
        };
        chart
            .configure_mesh()
            .disable_y_mesh()
            .max_light_lines(0)
            .bold_line_style(GRID_BOLD)
            .x_labels(8)
            .y_labels(2 * n + 1)
            .y_label_formatter(&name)
            .x_label_formatter(&tick)
            .x_desc("drag torque, N m (each input at the ends of its spread, the others nominal)")
            .label_style((FONT, 14))
            .axis_desc_style((FONT, 16))
            .draw()
            .map_err(plot_error)?;
        let band = BAND.mix(0.25);
        chart
            .draw_series(core::iter::once(Rectangle::new(
                [(s.band.low_nm, 0.0), (s.band.high_nm, n as f64)],
                band.filled(),
            )))
            .map_err(plot_error)?
            .label("band of the whole sample")
            .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 20, y + 6)], band.filled()));
        for (end, colour, label) in [(0, LOW, "input at the low end"), (1, HIGH, "input at the high end")] {
            chart
                .draw_series(s.inputs.iter().enumerate().map(|(row, i)| {
                    let y = (n - row - 1) as f64;
                    let x = if end == 0 { i.low_end_nm } else { i.high_end_nm };
                    Rectangle::new([(s.nominal_nm, y + 0.2), (x, y + 0.8)], colour.filled())
                }))
                .map_err(plot_error)?
                .label(label)
                .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 20, y + 6)], colour.filled()));
        }
        chart
            .draw_series(LineSeries::new([(s.nominal_nm, 0.0), (s.nominal_nm, n as f64)], BLACK.stroke_width(2)))
            .map_err(plot_error)?
            .label(format!("nominal {} N m", format_short(s.nominal_nm)))
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .background_style(WHITE.mix(0.9))
            .border_style(GREY)
            .label_font((FONT, 14))
            .draw()
            .map_err(plot_error)
    })
}
