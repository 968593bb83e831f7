//! `ballscrew reversal`: the friction torque through a reversal of the screw by the state
//! (presliding) model of [`ballscrew_core::realtime::reversal`], against the static model that
//! simulators get today (its torque fades linearly to zero below the standstill speed).
//!
//! The screw moves as `theta = A sin(2 pi t / period)` (a circular interpolation's axis through
//! its quadrant change), from the steady state at the peak speed at one zero crossing of the
//! angle, through the turning point, to the next; steps of equal time, none turning the screw
//! by more than `--step-rad`. Reported: the samples (every so many steps), and the stiffness, the
//! steady torques and how far the screw turns from the turning point until the torque (less
//! the axial term, the load torque) crosses zero and reaches 90 % of its new steady value, read
//! off every step. With `--plot`, the torque against the angle through the reversal and the
//! hysteresis loop of a small oscillation about standstill. The simulation is
//! [`crate::reversal_run`]'s, every torque the core's.

use super::{Context, Format, FormatArg};
use crate::args::describe_point;
use crate::error::CliError;
use crate::output::{Named, Output};
use crate::plots;
use crate::quantities::{REVERSAL_ROW, REVERSAL_SUMMARY};
use crate::report::{cell, cells, csv, csv_number, horizontal_table_led, json_object, json_text, keys, vertical_table};
use crate::reversal_run::{self, Precision, Reversal, Setup};
use crate::spec_and_flags::{PointInput, checked, count};
use crate::table::{Cell, format_short};
use ballscrew_core::Shown;
use ballscrew_core::input::rad_s_to_rpm;
use clap::Args;
use core::fmt::Write as _;
use serde_json::Value;
use std::path::PathBuf;

/// Default peak speed, rpm (a slow contour: a quadrant of a circular interpolation).
pub const DEFAULT_SPEED_RPM: f64 = 10.0;
/// Smallest and largest amplitude, rad.
const AMPLITUDE_RAD: (f64, f64) = (1e-6, 100.0);
/// Fewest and most steps in the amplitude (`--amplitude-rad` / `--step-rad`): the reversal takes
/// about `pi` times as many (the plot's loop at most `3 x 2 pi x 500`, whatever the step).
const STEPS_IN_AMPLITUDE: (f64, f64) = (10.0, 1e5);
/// Most rows.
const MAX_ROWS: i64 = 100_000;

/// Flags of `ballscrew reversal`.
#[derive(Debug, Clone, Args)]
pub struct ReversalArgs {
    #[command(flatten)]
    pub output: FormatArg,
    /// Preload, N [default: the spec's]
    #[arg(long, visible_alias = "preload", value_name = "N", allow_negative_numbers = true)]
    pub preload_n: Option<f64>,
    /// External axial load on the nut, N [default: the spec's]
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub axial_load_n: Option<f64>,
    /// Peak screw speed of the motion, rpm, nonzero; negative to start backwards
    #[arg(long, value_name = "RPM", default_value_t = DEFAULT_SPEED_RPM, allow_negative_numbers = true)]
    pub speed_rpm: f64,
    /// Amplitude A of the motion theta = A sin(2 pi t / period), rad, in [1e-6, 100] (the period
    /// is 2 pi A / the peak speed)
    #[arg(long, value_name = "RAD", default_value_t = 0.01, allow_negative_numbers = true)]
    pub amplitude_rad: f64,
    /// Largest rotation of one time step, rad, in [A / 1e5, A / 10] (A: --amplitude-rad); the
    /// steps are of equal time
    #[arg(long, value_name = "RAD", default_value_t = 1e-6, allow_negative_numbers = true)]
    pub step_rad: f64,
    /// Most samples reported through the reversal (every k-th step, the first and the last
    /// included)
    #[arg(long, value_name = "N", default_value_t = 400, allow_negative_numbers = true)]
    pub rows: i64,
    /// Float type of the state model and the evaluator
    #[arg(long, value_enum, default_value_t = Precision::F64)]
    pub precision: Precision,
    /// Also draw the torque against the angle through the reversal and the hysteresis loop of a
    /// small oscillation about standstill (from rest, amplitude 3 times the 90 % angle, the same
    /// peak speed, three cycles, steps of the larger of --step-rad and the amplitude / 500) to
    /// FILE as SVG (atomically)
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
}

/// The file the flags name (`--plot`).
pub fn outputs(args: &ReversalArgs) -> Named<'_> {
    Named { files: args.plot.iter().map(|p| ("--plot", p.as_path())).collect(), dirs: Vec::new() }
}

/// `x` to 6 significant digits (a bound in a message: `0.0003`, not `0.00030000000000000003`).
fn rounded(x: f64) -> f64 {
    format!("{x:.5e}").parse().unwrap_or(x)
}

/// The flags, validated (nothing evaluated).
fn setup(ctx: &Context, args: &ReversalArgs) -> Result<Setup, CliError> {
    let input = PointInput {
        speed_rpm: Some(args.speed_rpm),
        preload_n: args.preload_n,
        axial_load_n: args.axial_load_n,
        preload_flag: "--preload-n",
    };
    let op = ctx.operating_point(&input)?;
    checked("--speed-rpm", args.speed_rpm, args.speed_rpm != 0.0, "finite, nonzero, |speed| <= 30000 rpm")?;
    let (lo, hi) = AMPLITUDE_RAD;
    let a = args.amplitude_rad;
    checked("--amplitude-rad", a, (lo..=hi).contains(&a), "finite, [1e-6, 100] rad")?;
    let (few, many) = STEPS_IN_AMPLITUDE;
    let h = args.step_rad;
    checked(
        "--step-rad",
        h,
        h.is_finite() && h >= a / many && h <= a / few,
        &format!(
            "finite, [--amplitude-rad / 1e5, --amplitude-rad / 10] = [{}, {}] rad",
            Shown(rounded(a / many)),
            Shown(rounded(a / few))
        ),
    )?;
    let rows = count("--rows", args.rows, 2, MAX_ROWS)?;
    Ok(Setup {
        preload_n: op.preload_n,
        axial_load_n: op.axial_load_n,
        peak_speed_rpm: args.speed_rpm,
        amplitude_rad: a,
        max_step_rad: h,
        rows: rows as u64,
        plot: args.plot.is_some(),
        precision: args.precision,
    })
}

/// Runs `ballscrew reversal` and renders it.
pub fn run(ctx: &Context, args: &ReversalArgs) -> Result<Output, CliError> {
    let setup = setup(ctx, args)?;
    let r = reversal_run::simulate(&ctx.model, &setup)?;
    if let Some(d) = r.audit.first_departure() {
        eprintln!(
            "warning: the steady torque of the steps at speed_rpm {} departs from the canonical state (the model's cold \
             solve, what `ballscrew torque` gives): {d}; the state model follows its history and its evaluator sits on \
             another steady state of the balls there ({} of {} audited steps)",
            Shown(rad_s_to_rpm(d.op.speed_rad_s)),
            r.audit.departed(),
            r.audit.audited()
        );
    }
    let text = match ctx.format {
        Format::Table => table(ctx, &r),
        Format::Csv => csv_text(ctx, &r),
        Format::Json => json(ctx, &r),
    };
    let plot = match &args.plot {
        Some(path) => Some((path.clone(), plots::reversal::svg(&r, &ctx.origin)?)),
        None => None,
    };
    Ok(Output::with_plot(Some(text), plot))
}

/// The motion and the rows, in words.
fn motion_line(r: &Reversal) -> String {
    let s = &r.summary;
    let m = &s.motion;
    format!(
        "motion theta = A sin(2 pi t / period), A = {} rad, period {} s, {} steps per period of at most {} rad ({}); \
         from the steady state at the zero crossing (step 0) through the turning point (step {}) to the next zero \
         crossing (step {}), a row every {} steps",
        format_short(m.amplitude_rad()),
        format_short(m.period_s()),
        m.steps_per_period(),
        format_short(s.max_step_rad),
        s.precision.name(),
        m.steps_per_period() / 4,
        s.steps,
        r.stride
    )
}

/// What the static column is, and how the re-formation is measured.
const NOTES: [&str; 2] = [
    "static: the static model at the step's speed (its torque fades linearly to zero below the standstill speed)",
    "angles from the turning point, read off every step: the torque less the axial term crosses zero, then \
     reaches 90 % of its steady value after the reversal (at the peak speed)",
];

fn fixed(r: &Reversal) -> String {
    let s = &r.summary;
    let point = describe_point(None, Some(s.preload_n), Some(s.axial_load_n));
    format!("peak speed {} rpm, {point}", format_short(s.peak_speed_rpm))
}

fn table(ctx: &Context, r: &Reversal) -> String {
    let mut out = ctx.title("reversal", &fixed(r));
    let _ = writeln!(out, "{}", motion_line(r));
    for note in NOTES {
        let _ = writeln!(out, "{note}");
    }
    out.push('\n');
    out.push_str(&vertical_table(REVERSAL_SUMMARY, core::slice::from_ref(&r.summary), &["value"]).render(0));
    out.push('\n');
    out.push_str(&horizontal_table_led(&REVERSAL_ROW[0], &REVERSAL_ROW[1..], &r.rows, |s| s).render(0));
    out
}

/// `#` lines (the title, the motion, the notes, then the summary as `key = value`, full
/// precision, an undefined value empty), then the rows.
fn csv_text(ctx: &Context, r: &Reversal) -> String {
    let mut out = String::new();
    let title = ctx.title("reversal", &fixed(r));
    for line in [title.trim_end(), &motion_line(r)].into_iter().chain(NOTES) {
        let _ = writeln!(out, "# {line}");
    }
    for q in REVERSAL_SUMMARY {
        let value = match cell(q, &r.summary) {
            Cell::Num(x) => csv_number(x),
            Cell::Int(n) => n.to_string(),
            Cell::Text(t) => t,
        };
        let _ = writeln!(out, "# {} = {value}", q.key);
    }
    let rows: Vec<Vec<Cell>> = r.rows.iter().map(|s| cells(REVERSAL_ROW, s)).collect();
    out.push_str(&csv(&keys(REVERSAL_ROW), &rows));
    out
}

fn json(ctx: &Context, r: &Reversal) -> String {
    let mut head = ctx.json_head("reversal");
    head.extend(json_object(REVERSAL_SUMMARY, &r.summary));
    head.insert("row_stride_steps".into(), r.stride.into());
    let rows: Vec<Value> = r.rows.iter().map(|s| Value::Object(json_object(REVERSAL_ROW, s))).collect();
    head.insert("rows".into(), Value::Array(rows));
    json_text(&Value::Object(head))
}
