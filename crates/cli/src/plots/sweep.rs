//! The figure of `ballscrew sweep --plot FILE.svg`: the torque against the swept quantity
//! (preload, speed, axial load or oil temperature): the spec's route as a thick line with a dot
//! at each point, the catalog band shaded (the band the drag torque is compared with, by
//! magnitude: drawn with the sign of the speed) and the catalog estimate dashed, the other routes
//! (energy, moment) as thinner lines, and under an axial load the drag and the load torque. Eq. 27
//! as printed (about ten times the model's torque, which it would flatten against the y-axis it
//! sets) only when asked for (`--plot-paper-eq27`).

use crate::error::CliError;
use crate::plots::figure::{Chart, GREY, axes, chart_on, legend, legend_size, page, plot_error, with_legend};
use crate::report::{Quantity, cell};
use crate::table::{Cell, format_short};
use ballscrew_batch::SweepRow;
use ballscrew_batch::uncertainty::Band;
use ballscrew_core::screw::catalog::BAND_RELATIVE;
use plotters::element::DashedPathElement;
use plotters::prelude::*;

const SIZE: (u32, u32) = (1200, 820);
const HEADER: u32 = 90;
/// Fill of the model's own band (`--band`: the spread of its uncertain inputs), at
/// [`BAND_OPACITY`].
const MODEL_BAND: RGBColor = RGBColor(116, 169, 207);
/// Fill of the catalog band (drawn at [`BAND_OPACITY`]).
pub const BAND: RGBColor = RGBColor(253, 174, 97);
const BAND_OPACITY: f64 = 0.35;
const CATALOG: RGBColor = RGBColor(217, 95, 2);
const TORQUE: RGBColor = RGBColor(31, 119, 180);
const DRAG: RGBColor = RGBColor(44, 160, 44);
const LOAD: RGBColor = RGBColor(140, 86, 75);
const ENERGY: RGBColor = RGBColor(148, 103, 189);
const MOMENT: RGBColor = RGBColor(23, 190, 207);
const EQ27: RGBColor = RGBColor(127, 127, 127);

/// The unit of a swept quantity as an axis shows it.
fn axis_unit(unit: &str) -> &str {
    if unit == "C" { "°C" } else { unit }
}

/// The number of a cell (NaN for text).
fn value(c: Cell) -> f64 {
    match c {
        Cell::Num(x) => x,
        Cell::Int(n) => n as f64,
        Cell::Text(_) => f64::NAN,
    }
}

/// The catalog estimate, N m, with the sign of the speed: the catalog states a magnitude,
/// compared with the drag's, and is drawn beside the torque it is compared with.
fn signed_catalog(s: &ballscrew_core::Summary) -> f64 {
    if s.operating.speed_rad_s < 0.0 { -s.catalog_nm } else { s.catalog_nm }
}

/// `lo..hi` padded by a share of the span (by a tenth of the value when the span is empty).
fn padded(lo: f64, hi: f64, share: f64) -> (f64, f64) {
    let d = if hi > lo { (hi - lo) * share } else { lo.abs().max(1e-3) * 0.1 };
    (lo - d, hi + d)
}

/// One line of the figure: legend label, colour, width, dashed, points.
struct Line {
    label: String,
    colour: RGBColor,
    width: u32,
    dashed: bool,
    points: Vec<(f64, f64)>,
}

/// The figure: `title` (what was run, then the band's verdict), `swept` the first column of
/// the rows, `rows` the sweep; `paper_eq27`: Eq. 27 as printed drawn too.
pub fn svg(
    title: &[String],
    swept: &Quantity<SweepRow>,
    rows: &[SweepRow],
    paper_eq27: bool,
    model_band: Option<(String, &[Band])>,
) -> Result<String, CliError> {
    let xs: Vec<f64> = rows.iter().map(|r| value(cell(swept, r))).collect();
    let series = |get: fn(&ballscrew_core::Summary) -> f64| -> Vec<(f64, f64)> {
        xs.iter().zip(rows).map(|(&x, r)| (x, get(&r.summary))).collect()
    };
    let loaded = rows.iter().any(|r| r.summary.load_torque_nm() != 0.0);
    let mut lines = Vec::new();
    if paper_eq27 {
        lines.push(Line {
            label: "Eq. 27 as printed".into(),
            colour: EQ27,
            width: 1,
            dashed: true,
            points: series(|s| s.torque_eq27_nm),
        });
    }
    lines.extend([
        Line {
            label: "moment route (moment about the axis)".into(),
            colour: MOMENT,
            width: 1,
            dashed: false,
            points: series(|s| s.torque_moment_nm),
        },
        Line {
            label: "energy route F_a L/2π + D/ω".into(),
            colour: ENERGY,
            width: 1,
            dashed: false,
            points: series(|s| s.torque_energy_nm),
        },
    ]);
    if loaded {
        lines.push(Line {
            label: "load torque F_a L/2π".into(),
            colour: LOAD,
            width: 1,
            dashed: true,
            points: series(|s| s.load_torque_nm()),
        });
        lines.push(Line {
            label: "drag torque (torque − F_a L/2π), against the band".into(),
            colour: DRAG,
            width: 2,
            dashed: false,
            points: series(|s| s.drag_torque_nm()),
        });
    }
    let torque = series(|s| s.torque_nm);
    // The catalog states a magnitude, compared with the drag's: drawn with the sign of the
    // speed, beside the torque it is compared with.
    let catalog = series(signed_catalog);
    let low = series(|s| signed_catalog(s) * (1.0 - BAND_RELATIVE));
    let high = series(|s| signed_catalog(s) * (1.0 + BAND_RELATIVE));
    let reverse = rows.iter().any(|r| r.summary.operating.speed_rad_s < 0.0);
    let band_label = format!(
        "catalog band, catalog × [{}, {}]{}",
        format_short(1.0 - BAND_RELATIVE),
        format_short(1.0 + BAND_RELATIVE),
        if reverse { ", signed as the speed" } else { "" }
    );
    let torque_label = "torque (the spec's route)";
    let catalog_label = "catalog estimate";

    // The model's band of the drag torque (`--band`): its low and high ends at each point.
    let bands: &[Band] = model_band.as_ref().map_or(&[], |(_, b)| b);
    let band_low: Vec<(f64, f64)> = xs.iter().zip(bands).map(|(&x, b)| (x, b.low_nm)).collect();
    let band_high: Vec<(f64, f64)> = xs.iter().zip(bands).map(|(&x, b)| (x, b.high_nm)).collect();
    let all: Vec<(f64, f64)> = lines
        .iter()
        .flat_map(|l| l.points.iter().copied())
        .chain(band_low.iter().copied())
        .chain(band_high.iter().copied())
        .chain(torque.iter().copied())
        .chain(low.iter().copied())
        .chain(high.iter().copied())
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect();
    let fold = |f: fn(&(f64, f64)) -> f64| {
        all.iter().map(f).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)))
    };
    let (x0, x1) = fold(|p| p.0);
    let (y0, y1) = fold(|p| p.1);
    if !(x0.is_finite() && y0.is_finite()) {
        return Err(CliError::Eval("sweep plot: no finite torque to draw".into()));
    }
    let (x0, x1) = padded(x0, x1, 0.02);
    let (y0, y1) = padded(y0.min(0.0), y1.max(0.0), 0.05);
    let x_desc = format!("{}, {}", swept.label, axis_unit(swept.unit));

    let mut labels: Vec<&str> = vec![band_label.as_str(), catalog_label];
    if let Some((label, _)) = &model_band {
        labels.push(label.as_str());
    }
    labels.extend(lines.iter().map(|l| l.label.as_str()));
    labels.push(torque_label);
    let size = legend_size(&labels)?;

    page(SIZE, HEADER, title, |_, body| {
        let build = |lo: f64, hi: f64| -> Result<Chart<'_, '_>, CliError> { chart_on(body, x0..x1, lo..hi) };
        let (mut chart, corner) = with_legend(build, (y0, y1), size, &[], 0, &all)?;
        axes(&mut chart, &x_desc, "torque, N m")?;
        chart.draw_series(LineSeries::new([(x0, 0.0), (x1, 0.0)], GREY.stroke_width(1))).map_err(plot_error)?;
        let outline: Vec<(f64, f64)> = high.iter().copied().chain(low.iter().rev().copied()).collect();
        let fill = BAND.mix(BAND_OPACITY);
        chart
            .draw_series(core::iter::once(Polygon::new(outline, fill.filled())))
            .map_err(plot_error)?
            .label(band_label.as_str())
            .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 24, y + 6)], fill.filled()));
        if let Some((label, _)) = &model_band {
            let outline: Vec<(f64, f64)> = band_high.iter().copied().chain(band_low.iter().rev().copied()).collect();
            let fill = MODEL_BAND.mix(BAND_OPACITY);
            chart
                .draw_series(core::iter::once(Polygon::new(outline, fill.filled())))
                .map_err(plot_error)?
                .label(label.as_str())
                .legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 24, y + 6)], fill.filled()));
        }
        let style = CATALOG.stroke_width(1);
        chart
            .draw_series(DashedLineSeries::new(catalog, 6, 4, style))
            .map_err(plot_error)?
            .label(catalog_label)
            .legend(move |(x, y)| DashedPathElement::new([(x, y), (x + 24, y)], 6, 4, style));
        for line in &lines {
            let style = line.colour.stroke_width(line.width);
            let points = line.points.clone();
            if line.dashed {
                chart
                    .draw_series(DashedLineSeries::new(points, 6, 4, style))
                    .map_err(plot_error)?
                    .label(line.label.as_str())
                    .legend(move |(x, y)| DashedPathElement::new([(x, y), (x + 24, y)], 6, 4, style));
            } else {
                chart
                    .draw_series(LineSeries::new(points, style))
                    .map_err(plot_error)?
                    .label(line.label.as_str())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
            }
        }
        let style = TORQUE.stroke_width(3);
        chart
            .draw_series(LineSeries::new(torque.clone(), style))
            .map_err(plot_error)?
            .label(torque_label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
        chart.draw_series(torque.iter().map(|&p| Circle::new(p, 3, TORQUE.filled()))).map_err(plot_error)?;
        legend(&mut chart, corner)
    })
}
