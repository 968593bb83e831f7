//! The figure of `ballscrew reversal --plot FILE.svg`: two panels, (a) the drive torque against
//! the screw angle through the reversal, by the state model and by the static model; (b) the
//! hysteresis loop of a small oscillation about standstill (the last of its cycles), both models.

use crate::error::CliError;
use crate::plots::figure::{Area, FONT, GREY, axes, num, page, plot_error};
use crate::reversal_run::{LOOP_AMPLITUDE_REFORMATIONS, LOOP_CYCLES, Reversal, Sample, Summary};
use plotters::element::DashedPathElement;
use plotters::prelude::*;

const SIZE: (u32, u32) = (1500, 820);
const HEADER: u32 = 160;
const STATE: RGBColor = RGBColor(31, 119, 180);
const STATIC: RGBColor = RGBColor(214, 39, 40);

/// The title of panel (a).
pub const REVERSAL_TITLE: &str = "(a) Torque through a reversal against the screw angle";
/// The title of panel (b).
pub const LOOP_TITLE: &str = "(b) Hysteresis loop of a small oscillation about standstill";

/// `x` to `y` padded by a share of the span (a tenth of the value when the span is empty).
fn padded(lo: f64, hi: f64, below: f64, above: f64) -> (f64, f64) {
    let d = if hi > lo { hi - lo } else { lo.abs().max(1e-12) * 0.1 };
    (lo - below * d, hi + above * d)
}

/// One panel: both models' torque against the angle; `marks` are angles drawn as thin grey
/// vertical lines (`mark_label` in the legend).
fn panel(area: &Area<'_>, caption: &str, samples: &[Sample], marks: &[f64], mark_label: &str) -> Result<(), CliError> {
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for s in samples {
        x0 = x0.min(s.angle_rad);
        x1 = x1.max(s.angle_rad);
        for t in [s.torque_nm, s.static_torque_nm] {
            y0 = y0.min(t);
            y1 = y1.max(t);
        }
    }
    if !(x0.is_finite() && y0.is_finite()) {
        return Ok(());
    }
    let (x0, x1) = padded(x0, x1, 0.03, 0.03);
    // Room above the curves for the legend.
    let (y0, y1) = padded(y0, y1, 0.06, 0.45);
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, 19))
        .margin(18)
        .x_label_area_size(52)
        .y_label_area_size(76)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(plot_error)?;
    axes(&mut chart, "screw angle θ, rad", "drive torque, N m")?;
    chart.draw_series(LineSeries::new([(x0, 0.0), (x1, 0.0)], GREY.stroke_width(1))).map_err(plot_error)?;
    let lines: Vec<_> = marks.iter().filter(|m| m.is_finite()).map(|&m| vec![(m, y0), (m, y1)]).collect();
    if !lines.is_empty() {
        chart
            .draw_series(lines.into_iter().map(|l| PathElement::new(l, GREY.stroke_width(1))))
            .map_err(plot_error)?
            .label(mark_label)
            .legend(|(x, y)| PathElement::new(vec![(x + 12, y - 7), (x + 12, y + 7)], GREY.stroke_width(1)));
    }
    let still = STATIC.stroke_width(2);
    chart
        .draw_series(DashedLineSeries::new(samples.iter().map(|s| (s.angle_rad, s.static_torque_nm)), 8, 5, still))
        .map_err(plot_error)?
        .label("static model (fades to zero below the standstill speed)")
        .legend(move |(x, y)| DashedPathElement::new([(x, y), (x + 24, y)], 8, 5, still));
    let state = STATE.stroke_width(2);
    chart
        .draw_series(LineSeries::new(samples.iter().map(|s| (s.angle_rad, s.torque_nm)), state))
        .map_err(plot_error)?
        .label("state model (friction re-formed over the rotation)")
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], state));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperMiddle)
        .background_style(WHITE.mix(0.9))
        .border_style(GREY)
        .label_font((FONT, 14))
        .draw()
        .map_err(plot_error)
}

/// `crosses zero after 2.184e−4 rad (0.4172 µm of nut travel)`, or that it does not.
fn after(s: &Summary, angle_rad: f64, what: &str) -> String {
    if angle_rad.is_finite() {
        format!("{what} after {} rad ({} µm of nut travel)", num(angle_rad), num(s.travel_um(angle_rad)))
    } else {
        format!("never {what} within the motion")
    }
}

/// The figure: (a) the reversal, (b) the hysteresis loop.
pub fn svg(r: &Reversal, origin: &str) -> Result<String, CliError> {
    let s = &r.summary;
    let a = s.motion.amplitude_rad();
    let turn = |from_turn: f64| a - from_turn.copysign(a);
    let mut lines = vec![
        "Friction torque through a reversal: the state (presliding) model against the static model".to_string(),
        format!(
            "{origin}; peak speed {} rpm, preload {} N, axial load {} N; Dahl stiffness σ {} N m/rad",
            num(s.peak_speed_rpm),
            num(s.preload_n),
            num(s.axial_load_n),
            num(s.stiffness_nm_per_rad),
        ),
        format!(
            "(a) θ = A sin(2π t / T), A = {} rad, T = {} s, from the steady state at the peak speed, steps of at most {} \
             rad",
            num(a),
            num(s.motion.period_s()),
            num(s.max_step_rad),
        ),
        format!(
            "from the turning point the torque (less the axial term) {} and {}",
            after(s, s.zero_crossing_rad, "crosses zero"),
            after(s, s.reformed_rad, "reaches 90 % of its new steady value"),
        ),
    ];
    if let Some(h) = &r.hysteresis {
        let small = h.motion.amplitude_rad().abs();
        let which = if small < s.motion.amplitude_rad().abs() {
            format!("{} × the 90 % angle", num(LOOP_AMPLITUDE_REFORMATIONS))
        } else {
            format!(
                "the amplitude of (a): {} × the 90 % angle is more, or the torque did not reach 90 %",
                num(LOOP_AMPLITUDE_REFORMATIONS)
            )
        };
        lines.push(format!(
            "(b) from rest, θ = A sin(2π t / T), A = {} rad ({which}), the same peak speed, steps of at most {} rad; \
             cycle {LOOP_CYCLES} of {LOOP_CYCLES} drawn",
            num(h.motion.amplitude_rad()),
            num(h.max_step_rad),
        ));
    }
    let marks = [turn(s.zero_crossing_rad), turn(s.reformed_rad)];
    page(SIZE, HEADER, &lines, |_, body| {
        let panels = body.split_evenly((1, 2));
        panel(&panels[0], REVERSAL_TITLE, &r.curve, &marks, "zero crossing, 90 % re-formed")?;
        if let Some(h) = &r.hysteresis {
            panel(&panels[1], LOOP_TITLE, &h.samples, &[], "")?;
        }
        Ok(())
    })
}
