//! The figures of `ballscrew diagnose --plots DIR` (SVG): measured torque against the
//! calibrated and the extended model, the residual of both against each operating column, the
//! measured, calibrated and extended torque against the time when the data has `time_h`, and
//! the residual's amplitude at the harmonics of the lead along the nut position (the detected
//! harmonic marked). Each legend takes a corner clear of the marked points and, where one is, of
//! every point; else the plot makes room above the data for it.

use crate::error::CliError;
use crate::plots::figure::{
    Chart, FONT, GREY, MARK, axes, chart_on, legend, legend_size, page, plot_error, with_legend,
};
use ballscrew_diagnose::Report;
use ballscrew_diagnose::data::Column;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

const SIZE: (u32, u32) = (1000, 760);
const HEADER: u32 = 80;
const BASE: RGBColor = RGBColor(120, 120, 120);
const EXT: RGBColor = RGBColor(178, 24, 43);
const MEASURED: RGBColor = RGBColor(0, 0, 0);
/// Pixels kept clear around a marked point (its ring and note).
const MARK_CLEARANCE: i32 = 16;
/// Name of the torque-against-time figure.
pub const TIME_FIGURE: &str = "torque_vs_time.svg";

/// A marked point: where (data coordinates) and its note.
type Marked = ((f64, f64), String);

/// One scatter series: label, colour, points.
type Series<'a> = (&'a str, RGBColor, Vec<(f64, f64)>);

fn bounds(series: &[Series<'_>], extra: &[(f64, f64)]) -> ((f64, f64), (f64, f64)) {
    let pts = series.iter().flat_map(|s| s.2.iter()).chain(extra.iter());
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for &(x, y) in pts {
        if x.is_finite() && y.is_finite() {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
    }
    let pad = |a: f64, b: f64| {
        let d = if b > a { 0.05 * (b - a) } else { a.abs().max(1e-9) * 0.1 };
        (a - d, b + d)
    };
    if !x0.is_finite() {
        return ((0.0, 1.0), (0.0, 1.0));
    }
    (pad(x0, x1), pad(y0, y1))
}

/// A scatter chart with an optional line (drawn first) and marked points (a ring and a note);
/// the legend clear of the marked points.
fn scatter(
    title: &[String],
    x_desc: &str,
    y_desc: &str,
    series: &[Series<'_>],
    line: &[(f64, f64)],
    marked: &[Marked],
) -> Result<String, CliError> {
    let ((x0, x1), (y0, y1)) = bounds(series, line);
    let labels: Vec<&str> = series.iter().map(|s| s.0).collect();
    let size = legend_size(&labels)?;
    let points: Vec<(f64, f64)> = series.iter().flat_map(|s| s.2.iter().copied()).collect();
    let marks: Vec<(f64, f64)> = marked.iter().map(|m| m.0).collect();
    page(SIZE, HEADER, title, |_, body| {
        let build = |lo: f64, hi: f64| -> Result<Chart<'_, '_>, CliError> { chart_on(body, x0..x1, lo..hi) };
        let (mut chart, corner) = with_legend(build, (y0, y1), size, &marks, MARK_CLEARANCE, &points)?;
        axes(&mut chart, x_desc, y_desc)?;
        if line.len() >= 2 {
            chart.draw_series(LineSeries::new(line.to_vec(), GREY.stroke_width(1))).map_err(plot_error)?;
        }
        for (label, colour, pts) in series {
            let c = *colour;
            chart
                .draw_series(pts.iter().map(|&p| Circle::new(p, 3, c.mix(0.7).filled())))
                .map_err(plot_error)?
                .label(*label)
                .legend(move |(x, y)| Circle::new((x + 10, y), 4, c.filled()));
        }
        for (p, note) in marked {
            chart.draw_series(core::iter::once(Circle::new(*p, 9, MARK.stroke_width(3)))).map_err(plot_error)?;
            let (px, py) = chart.backend_coord(p);
            let base = body.get_base_pixel();
            let style = TextStyle::from((FONT, 14).into_font()).color(&BLACK).pos(Pos::new(HPos::Left, VPos::Center));
            body.draw_text(note, &style, (px - base.0 + 14, py - base.1)).map_err(plot_error)?;
        }
        legend(&mut chart, corner)
    })
}

/// Every figure: (file name, SVG text).
pub fn figures(r: &Report, lead_mm: f64) -> Result<Vec<(String, String)>, CliError> {
    let s = &r.series;
    let mut out = Vec::new();
    let pairs = |pred: &[f64]| -> Vec<(f64, f64)> { s.measured.iter().copied().zip(pred.iter().copied()).collect() };
    let lo = s.measured.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = s.measured.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    out.push((
        "measured_vs_model.svg".to_string(),
        scatter(
            &[
                "Measured torque against the model".to_string(),
                format!(
                    "calibrated ({}): held-out RMSE {}; extended ({}): {}",
                    r.calibrated_label(),
                    ballscrew_diagnose::text::torque_text(r.baseline.heldout_rmse_nm),
                    if r.findings.is_empty() { "no term".to_string() } else { r.effects().join(" + ") },
                    ballscrew_diagnose::text::torque_text(r.extended.heldout_rmse_nm)
                ),
            ],
            "measured torque, N m",
            "model torque, N m",
            &[("calibrated model", BASE, pairs(&s.baseline)), ("extended model", EXT, pairs(&s.extended))],
            &[(lo, lo), (hi, hi)],
            &[],
        )?,
    ));
    let resid = |pred: &[f64]| -> Vec<f64> { pred.iter().zip(&s.measured).map(|(p, m)| p - m).collect() };
    let (rb, re) = (resid(&s.baseline), resid(&s.extended));
    // Every figure says which parameters the calibrated and the extended model took.
    let models = format!(
        "calibrated: {}; extended: {}",
        r.calibrated_label(),
        if r.findings.is_empty() { "no term".to_string() } else { r.effects().join(" + ") }
    );
    for (c, x) in &s.columns {
        let unit = if c.unit().is_empty() { String::new() } else { format!(", {}", c.unit()) };
        let pts = |r: &[f64]| -> Vec<(f64, f64)> { x.iter().copied().zip(r.iter().copied()).collect() };
        let (x0, x1) = x.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
        out.push((
            format!("residual_{}.svg", c.name()),
            scatter(
                &[format!("Residual (model − measured) against {}", c.name()), models.clone()],
                &format!("{}{unit}", c.name()),
                "residual, N m",
                &[("calibrated model", BASE, pts(&rb)), ("extended model", EXT, pts(&re))],
                &[(x0, 0.0), (x1, 0.0)],
                &[],
            )?,
        ));
    }
    if let Some((_, time)) = s.columns.iter().find(|(c, _)| *c == Column::TimeH) {
        let pts = |v: &[f64]| -> Vec<(f64, f64)> { time.iter().copied().zip(v.iter().copied()).collect() };
        out.push((
            TIME_FIGURE.to_string(),
            scatter(
                &[
                    "Torque against time: measured, calibrated and extended model".to_string(),
                    format!("{} rows; {models}", s.measured.len()),
                ],
                "time, h",
                "torque, N m",
                &[
                    ("measured", MEASURED, pts(&s.measured)),
                    ("calibrated model", BASE, pts(&s.baseline)),
                    ("extended model", EXT, pts(&s.extended)),
                ],
                &[],
                &[],
            )?,
        ));
    }
    if let Some((b, e)) = &r.periodogram {
        let pts = |p: &[(u32, f64)]| -> Vec<(f64, f64)> { p.iter().map(|(h, a)| (f64::from(*h), *a)).collect() };
        // The detected harmonic: the waviness term's, else the calibrated residual's largest.
        let found = r
            .findings
            .iter()
            .find_map(|f| f.parameters.iter().find(|(name, _)| *name == "harmonic").map(|&(_, h)| (h, "detected")));
        let largest = b.iter().max_by(|x, y| x.1.total_cmp(&y.1)).map(|&(h, _)| (f64::from(h), "largest"));
        let marked: Vec<Marked> = found
            .or(largest)
            .and_then(|(h, what)| {
                let &(_, amplitude) = b.iter().find(|(k, _)| f64::from(*k) == h)?;
                let note = format!("{what}: h = {h}, period {} mm", crate::plots::figure::num(lead_mm / h));
                Some(((h, amplitude), note))
            })
            .into_iter()
            .collect();
        out.push((
            "periodogram_position.svg".to_string(),
            scatter(
                &[
                    "Residual amplitude at harmonics of the lead along the nut position".to_string(),
                    format!("harmonic h: period = lead / h = {lead_mm} mm / h"),
                    models.clone(),
                ],
                "harmonic h of the lead",
                "amplitude, N m",
                &[("calibrated model", BASE, pts(b)), ("extended model", EXT, pts(e))],
                &[],
                &marked,
            )?,
        ));
    }
    Ok(out)
}
