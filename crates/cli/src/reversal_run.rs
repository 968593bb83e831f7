//! A reversal of the screw (`ballscrew reversal`) as the command line holds it: the state model
//! of [`ballscrew_core::realtime::reversal`] stepped through a sinusoidal motion from the steady
//! state at its peak speed, the static model (the evaluator's torque, with its fade at
//! standstill) at the same speeds alongside, the samples kept every so many steps, and what the
//! core's [`Reformation`] reads off every step; with a plot, the hysteresis loop of a small
//! oscillation about standstill as well. Every torque is the core's.

use crate::error::CliError;
use ballscrew_core::input::MAX_SPEED_RAD_S;
use ballscrew_core::input::{rad_s_to_rpm, rpm_to_rad_s};
use ballscrew_core::real::Real;
use ballscrew_core::realtime::audit::{self, Audit};
use ballscrew_core::realtime::reversal::{Reformation, SineMotion, check_step};
use ballscrew_core::{Error, EvalState, Evaluator, Model, OperatingPoint, ReversalModel};
use clap::ValueEnum;

/// The share of the new steady value the re-formation is measured to.
pub const REFORMED_FRACTION: f64 = 0.9;
/// The amplitude of the hysteresis loop, in re-formation angles (to [`REFORMED_FRACTION`]).
pub const LOOP_AMPLITUDE_REFORMATIONS: f64 = 3.0;
/// Cycles of the hysteresis loop's oscillation from the relaxed state; the last is drawn.
pub const LOOP_CYCLES: u64 = 3;
/// The hysteresis loop's steps are no longer than the setup's and no shorter than its
/// amplitude over this (about `2 pi` times this many steps per period: the loop is drawn, and
/// the Dahl step is exact for a constant bound, so finer steps change little but the time).
pub const LOOP_STEPS_PER_AMPLITUDE: f64 = 500.0;
/// Points per plotted curve (at most).
const PLOT_POINTS: u64 = 2000;

/// The float type the state model and the evaluator run in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Precision {
    /// Double precision.
    F64,
    /// Single precision (firmware without a double-precision FPU).
    F32,
}

impl Precision {
    /// `f64` or `f32`.
    pub fn name(self) -> &'static str {
        match self {
            Precision::F64 => "f64",
            Precision::F32 => "f32",
        }
    }
}

/// What to simulate (validated by the command).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Setup {
    /// Preload, N.
    pub preload_n: f64,
    /// External axial load, N.
    pub axial_load_n: f64,
    /// Peak speed of the motion, rpm (signed: negative starts backwards; nonzero).
    pub peak_speed_rpm: f64,
    /// Amplitude of the motion, rad (> 0).
    pub amplitude_rad: f64,
    /// Largest rotation of one step, rad (> 0).
    pub max_step_rad: f64,
    /// Samples to keep through the reversal (at least 2).
    pub rows: u64,
    /// Also run the hysteresis loop and keep the curves to plot.
    pub plot: bool,
    /// The float type.
    pub precision: Precision,
}

/// One sample of a stepped motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Time from the start, s.
    pub time_s: f64,
    /// Screw angle, rad.
    pub angle_rad: f64,
    /// The mean speed of the step that ends here (the speed both models are evaluated at), rpm;
    /// at the start, the peak speed.
    pub speed_rpm: f64,
    /// The state model's drive torque, N m.
    pub torque_nm: f64,
    /// The static model's drive torque at the same speed, N m.
    pub static_torque_nm: f64,
}

/// What the reversal comes to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Summary {
    /// Preload, N.
    pub preload_n: f64,
    /// External axial load, N.
    pub axial_load_n: f64,
    /// Peak speed, rpm (signed).
    pub peak_speed_rpm: f64,
    /// The motion.
    pub motion: SineMotion,
    /// Largest rotation of a step asked for, rad.
    pub max_step_rad: f64,
    /// Steps simulated through the reversal (half a period).
    pub steps: u64,
    /// The float type.
    pub precision: Precision,
    /// Dahl's stiffness, all circles and mechanisms, N m/rad.
    pub stiffness_nm_per_rad: f64,
    /// The axial term F_a L / (2 pi), N m.
    pub axial_term_nm: f64,
    /// The steady torque at the peak speed before the reversal and after it, N m.
    pub steady_torque_nm: [f64; 2],
    /// The screw angle from the turning point to the torque's zero crossing, rad (NaN: none).
    pub zero_crossing_rad: f64,
    /// The screw angle from the turning point to [`REFORMED_FRACTION`] of the new steady
    /// value, rad (NaN: none).
    pub reformed_rad: f64,
    /// The lead, m.
    pub lead_m: f64,
}

impl Summary {
    /// The nut's travel for a screw angle, um.
    pub fn travel_um(&self, angle_rad: f64) -> f64 {
        angle_rad * self.lead_m / core::f64::consts::TAU * 1e6
    }
}

/// A small oscillation about standstill from the relaxed state: its motion and its last cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct Hysteresis {
    /// The oscillation.
    pub motion: SineMotion,
    /// Its largest rotation of a step, rad.
    pub max_step_rad: f64,
    /// The last cycle's samples.
    pub samples: Vec<Sample>,
}

/// A simulated reversal.
#[derive(Debug, Clone, PartialEq)]
pub struct Reversal {
    /// The summary.
    pub summary: Summary,
    /// Every `stride`-th step's sample from the start (step 0) to the end, the last included: at
    /// most the rows asked for.
    pub rows: Vec<Sample>,
    /// Steps between rows.
    pub stride: u64,
    /// The denser samples to plot (with a plot).
    pub curve: Vec<Sample>,
    /// The hysteresis loop (with a plot).
    pub hysteresis: Option<Hysteresis>,
    /// The audit of the steps through the reversal: every [`AUDIT_EVERY`]-th turning step's
    /// steady torque against the canonical state at its speed.
    pub audit: Audit,
}

/// Steps between two audited steps of a reversal (the first is audited): a cold solve of the
/// model per 1000 steps.
pub const AUDIT_EVERY: u32 = 1000;

/// A core error of the simulation, with where it happened.
fn core_error(context: &str, setup: &Setup, e: &Error) -> CliError {
    match e {
        // The model's refusal of light balls names the preload: the flag.
        Error::Input(i) if i.field == "preload_n" => CliError::Input(
            ballscrew_core::Invalid { field: "--preload-n", value: setup.preload_n, valid: i.valid }.to_string(),
        ),
        e => CliError::eval(context, e),
    }
}

/// Steps between kept samples so that about `wanted` samples cover `steps` steps.
fn stride(steps: u64, wanted: u64) -> u64 {
    steps.div_ceil(wanted.saturating_sub(1).max(1)).max(1)
}

/// Simulates the reversal (and, with a plot, the hysteresis loop) in the setup's precision.
pub fn simulate(model: &Model, setup: &Setup) -> Result<Reversal, CliError> {
    match setup.precision {
        Precision::F64 => simulate_in::<f64>(model, setup),
        Precision::F32 => simulate_in::<f32>(model, setup),
    }
}

/// A speed (rad/s) in the float type, rounded within the speed range: 30000 rpm, its top, is
/// the f32 below it, not the nearest f32 above it.
fn within_speed<F: Real>(speed_rad_s: f64) -> F {
    F::of_within(speed_rad_s, -MAX_SPEED_RAD_S, MAX_SPEED_RAD_S)
}

fn simulate_in<F: Real>(model: &Model, setup: &Setup) -> Result<Reversal, CliError> {
    let err = |context: &'static str| move |e: Error| core_error(context, setup, &e);
    let ev = Evaluator::<F>::new(model).map_err(err("evaluator"))?;
    let rm = ReversalModel::new(&ev, setup.preload_n, setup.axial_load_n).map_err(err("reversal model"))?;
    let peak = rpm_to_rad_s(setup.peak_speed_rpm);
    let amplitude = setup.amplitude_rad.copysign(peak);
    let motion = SineMotion::new(amplitude, peak.abs(), setup.max_step_rad).map_err(err("motion"))?;
    let mut static_state = EvalState::<F>::new();
    let mut static_nm = |speed: f64| -> Result<f64, CliError> {
        let t = ev
            .torque_nm(
                &OperatingPoint { speed_rad_s: speed, preload_n: setup.preload_n, axial_load_n: setup.axial_load_n },
                &mut static_state,
            )
            .map_err(err("static model"))?;
        Ok(t.to_f64())
    };
    let axial = rm.axial_term_nm().to_f64();
    // The state model's steady torques at the peak speed (below the standstill speed they are
    // the running torque, where the static model fades).
    let steady_nm = |speed: f64| -> Result<f64, CliError> {
        let state = rm.steady(within_speed(speed)).map_err(err("reversal model"))?;
        Ok(axial + model.seal_torque_nm(speed) + state.friction_nm().to_f64())
    };
    let (before, after) = (steady_nm(peak)?, steady_nm(-peak)?);
    let mut reformation = Reformation::new(after - axial, REFORMED_FRACTION).map_err(|_| {
        CliError::Eval(format!(
            "reversal: the steady friction torque after the reversal is {} N m: nothing to re-form",
            after - axial
        ))
    })?;

    let n = motion.steps_per_period();
    let (quarter, half) = (n / 4, n / 2);
    let dt_s = motion.dt_s();
    let stride = stride(half, setup.rows);
    let plot_stride = stride_for_plot(half);
    let start = Sample {
        time_s: 0.0,
        angle_rad: 0.0,
        speed_rpm: setup.peak_speed_rpm,
        torque_nm: before,
        static_torque_nm: static_nm(peak)?,
    };
    let mut rows = vec![start];
    let mut curve = if setup.plot { vec![start] } else { Vec::new() };
    let mut state = rm.steady(within_speed(peak)).map_err(err("reversal model"))?;
    let tolerance = match setup.precision {
        Precision::F32 => audit::F32_TOLERANCE,
        Precision::F64 => audit::F64_TOLERANCE,
    };
    let mut audit = Audit::new(AUDIT_EVERY, tolerance).map_err(|e| err("audit")(Error::Input(e)))?;
    for k in 1..=half {
        let rotation = motion.rotation_rad(k);
        let (rotation_f, dt) = check_step::<F>(rotation, dt_s).map_err(|e| err("reversal model")(Error::Input(e)))?;
        let torque = rm.step(rotation_f, dt, &mut state).map_err(err("reversal model"))?.to_f64();
        if rotation != 0.0 {
            let speed = rotation_f.to_f64() / dt.to_f64();
            audit.check_lazily(model, || rm.steady_torque_at(speed, &state).ok().map(|(op, t)| (op, t.to_f64())));
        }
        let angle = motion.angle_rad(k);
        if k >= quarter {
            reformation.record((amplitude - angle).abs(), torque - axial);
        }
        let in_rows = k % stride == 0 || k == half;
        let in_curve = setup.plot && (k % plot_stride == 0 || k == half);
        if in_rows || in_curve {
            let speed = rotation / dt_s;
            let sample = Sample {
                time_s: motion.time_s(k),
                angle_rad: angle,
                speed_rpm: rad_s_to_rpm(speed),
                torque_nm: torque,
                static_torque_nm: static_nm(speed)?,
            };
            if in_rows {
                rows.push(sample);
            }
            if in_curve {
                curve.push(sample);
            }
        }
    }
    let summary = Summary {
        preload_n: setup.preload_n,
        axial_load_n: setup.axial_load_n,
        peak_speed_rpm: setup.peak_speed_rpm,
        motion,
        max_step_rad: setup.max_step_rad,
        steps: half,
        precision: setup.precision,
        stiffness_nm_per_rad: rm.stiffness_nm_per_rad().to_f64(),
        axial_term_nm: axial,
        steady_torque_nm: [before, after],
        zero_crossing_rad: reformation.zero_crossing_rad().unwrap_or(f64::NAN),
        reformed_rad: reformation.reformed_rad().unwrap_or(f64::NAN),
        lead_m: model.spec().geometry.lead_m,
    };
    let hysteresis = if setup.plot {
        // A few re-formation angles (the whole amplitude when the friction did not re-form).
        let reformed = summary.reformed_rad * LOOP_AMPLITUDE_REFORMATIONS;
        let small = if reformed.is_finite() && reformed > 0.0 {
            reformed.min(setup.amplitude_rad)
        } else {
            setup.amplitude_rad
        };
        let step = setup.max_step_rad.max(small / LOOP_STEPS_PER_AMPLITUDE);
        let motion = SineMotion::new(small.copysign(peak), peak.abs(), step).map_err(err("motion"))?;
        let n = motion.steps_per_period();
        let dt_s = motion.dt_s();
        let plot_stride = stride_for_plot(n);
        let mut state = rm.relaxed();
        let mut samples = Vec::new();
        for k in 1..=LOOP_CYCLES * n {
            let rotation = motion.rotation_rad(k);
            let (rotation_f, dt) =
                check_step::<F>(rotation, dt_s).map_err(|e| err("reversal model")(Error::Input(e)))?;
            let torque = rm.step(rotation_f, dt, &mut state).map_err(err("reversal model"))?.to_f64();
            let last_cycle = (LOOP_CYCLES - 1) * n;
            if k >= last_cycle && ((k - last_cycle).is_multiple_of(plot_stride) || k == LOOP_CYCLES * n) {
                let speed = rotation / dt_s;
                samples.push(Sample {
                    time_s: motion.time_s(k),
                    angle_rad: motion.angle_rad(k),
                    speed_rpm: rad_s_to_rpm(speed),
                    torque_nm: torque,
                    static_torque_nm: static_nm(speed)?,
                });
            }
        }
        Some(Hysteresis { motion, max_step_rad: step, samples })
    } else {
        None
    };
    Ok(Reversal { summary, rows, stride, curve, hysteresis, audit })
}

/// Steps between plotted samples over `steps` steps.
fn stride_for_plot(steps: u64) -> u64 {
    stride(steps, PLOT_POINTS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strides_keep_about_the_rows_asked_for() {
        assert_eq!(stride(31_416, 400), 79);
        assert_eq!(stride(10, 400), 1);
        assert_eq!(stride(10, 2), 10);
        assert_eq!(stride(0, 400), 1);
        // 31416 / 79 = 397 rows after the start, and the last: 399 in all.
        assert!(31_416 / stride(31_416, 400) + 2 <= 400);
    }
}
