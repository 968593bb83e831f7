//! `ballscrew map`: the torque tabulated over preload and speed for firmware, written as a C
//! header, a Rust source file or CSV, with its grid and its largest interpolation error; with
//! `--plot`, the map's torque against the speed, a curve per preload, both directions, the
//! worst-error point marked ([`crate::plots::map`]).
//!
//! The speed axis is geometric by default (`--speed-spacing geometric`): the lubricated model's
//! torque changes over decades of speed, and 16 preloads x 38 geometric speeds from 0.01 to
//! 3000 rpm meet the 0.5 % target on the built-in DKFZD4012 (0.43 %). `--speed-step-rpm`, or
//! `--speed-spacing uniform`, gives the uniform axis (the dry model's torque does not depend on
//! the speed's magnitude: four uniform points suffice there).

use super::Context;
use crate::error::CliError;
use crate::map_source::{self, Provenance};
use crate::output::{self, Named, Output, SideFile};
use crate::plots;
use crate::progress::Bar;
use crate::spec_and_flags::{PointInput, checked, count};
use crate::table::format_short;
use ballscrew_batch::sweep::{RangeText, steps_to_reach};
use ballscrew_config::BUILTIN_ORIGIN;
use ballscrew_core::input::Lubrication;
use ballscrew_core::input::{rad_s_to_rpm, rpm_to_rad_s};
use ballscrew_core::realtime::map::{self, MapError, MapGrid, Spacing, Tabulated};
use ballscrew_core::{OperatingPoint, SolverState};
use clap::{Args, ValueEnum};
use std::path::{Path, PathBuf};

/// What `ballscrew map` writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MapFormat {
    /// A short report for people (grid, error, the forward sheet).
    Table,
    /// A C header: grid macros, the values, an inline lookup.
    C,
    /// A Rust source file: constants for `ballscrew_core::realtime::map::TorqueMap`.
    Rust,
    /// CSV, a header line and one row per value (any CSV reader takes it as it is); the
    /// description beside it (`FILE.about.txt` for `--out FILE.csv`, else on stderr).
    Csv,
}

/// How the speed magnitudes of the map are spaced (`--speed-spacing`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SpeedSpacing {
    /// Equal steps of speed from the smallest magnitude (0 when the range contains 0).
    Uniform,
    /// Equal ratios of speed from the standstill speed (or the smallest magnitude, if larger):
    /// the lubricated model's torque changes over decades of speed.
    Geometric,
}

/// Flags of `ballscrew map`.
#[derive(Debug, Clone, Args)]
pub struct MapArgs {
    /// Output format: a short report, or the map as a C header, a Rust source file or CSV
    #[arg(long, value_enum, default_value_t = MapFormat::Table)]
    pub format: MapFormat,
    /// Preload range in N, both ends included: `A..B` (A < B).
    #[arg(
        long = "preload-n",
        visible_alias = "preload",
        value_name = "A..B",
        default_value = "500..3000",
        allow_hyphen_values = true
    )]
    pub preload: RangeText,
    /// Number of preloads of the grid (or give --preload-step-n) [default: 16]
    #[arg(long, value_name = "N", conflicts_with = "preload_step")]
    pub preload_points: Option<i64>,
    /// Preload spacing, N; the grid runs from A in these steps until it reaches B.
    #[arg(long = "preload-step-n", visible_alias = "preload-step", value_name = "N", allow_negative_numbers = true)]
    pub preload_step: Option<f64>,
    /// Speed range in rpm: `C..D` (C < D). The map covers the speed magnitudes in it, in both
    /// directions (from 0 when the range contains 0: a geometric axis then has its first node at
    /// a tenth of the standstill speed, and below it blends to standstill as the model does).
    #[arg(long, value_name = "C..D", default_value = "0..3000", allow_hyphen_values = true)]
    pub speed_rpm: RangeText,
    /// Number of speed magnitudes of the grid (or give --speed-step-rpm) [default: 38 geometric,
    /// 4 uniform]
    #[arg(long, value_name = "N", conflicts_with = "speed_step_rpm")]
    pub speed_points: Option<i64>,
    /// Speed spacing, rpm (uniform spacing); the grid runs from the smallest magnitude until it
    /// reaches the largest.
    #[arg(long, value_name = "RPM", allow_negative_numbers = true)]
    pub speed_step_rpm: Option<f64>,
    /// Spacing of the speed magnitudes: geometric (nodes in equal ratios from the standstill
    /// speed; interpolated linearly in speed within a cell) or uniform [default: geometric, or
    /// uniform with --speed-step-rpm]
    #[arg(long, value_name = "SPACING")]
    pub speed_spacing: Option<SpeedSpacing>,
    /// External axial load on the nut, N [default: the spec's]
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub axial_load_n: Option<f64>,
    /// Also draw the map to FILE as SVG (atomically): its torque against the speed, a curve per
    /// preload (at most 24: every k-th of more), forward and reverse, the check point of the
    /// largest interpolation error marked
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
}

/// The file the flags name (`--plot`).
pub fn outputs(args: &MapArgs) -> Named<'_> {
    Named { files: args.plot.iter().map(|p| ("--plot", p.as_path())).collect(), dirs: Vec::new() }
}

/// Default number of preloads, and of speed magnitudes on a uniform and on a geometric axis
/// (the geometric default meets the 0.5 % target on the built-in lubricated DKFZD4012 from 0 to
/// 3000 rpm: docs/real-time.md, "Torque map for firmware").
const DEFAULT_PRELOAD_POINTS: usize = 16;
const DEFAULT_SPEED_POINTS: usize = 4;
const DEFAULT_GEOMETRIC_SPEED_POINTS: usize = 38;
/// First node of a geometric speed axis whose range starts at zero, in standstill speeds.
const GEOMETRIC_FIRST_SPEED: f64 = 0.1;

/// Estimated cost of one model evaluation, each node and check point solved from the cold
/// start (its canonical state), in seconds: release build on a 2-core x86-64 machine, rounded up
/// (dry model: 1.3 ms, the default 16 x 38 grid's 2372 evaluations in 3.0 s and an 11 x 4
/// uniform grid's 179 in 0.22 s; lubricated model: 0.85 ms, the default grid in 2.0 s).
const SECONDS_PER_DRY_EVALUATION: f64 = 1.5e-3;
const SECONDS_PER_LUBRICATED_EVALUATION: f64 = 1e-3;
/// Longest estimated tabulation accepted, seconds. A firmware map needs far less (the default
/// grid: 2 s with the lubricated model, 3 s with the dry one).
const MAX_ESTIMATED_SECONDS: f64 = 60.0;

/// Model evaluations of [`map::tabulate`] on `np` preloads and `ns` speeds ([`map::evaluations`])
/// and the estimated seconds at `per_evaluation` seconds per evaluation
/// ([`SECONDS_PER_DRY_EVALUATION`], [`SECONDS_PER_LUBRICATED_EVALUATION`]).
fn cost(np: usize, ns: usize, per_evaluation: f64) -> (f64, f64) {
    let evaluations = map::evaluations(np, ns) as f64;
    (evaluations, evaluations * per_evaluation)
}

/// An input error when the grid's estimated tabulation time passes [`MAX_ESTIMATED_SECONDS`].
fn check_cost(np: usize, ns: usize, per_evaluation: f64) -> Result<(), CliError> {
    let (evaluations, seconds) = cost(np, ns, per_evaluation);
    if seconds <= MAX_ESTIMATED_SECONDS {
        return Ok(());
    }
    Err(CliError::Input(format!(
        "invalid grid: {np} preloads x {ns} speeds need {evaluations} model evaluations, estimated {} (at {} us \
         per evaluation); the limit is {}: use fewer points (--preload-points, --speed-points) or larger steps",
        duration(seconds),
        per_evaluation * 1e6,
        duration(MAX_ESTIMATED_SECONDS)
    )))
}

/// `45 s`, `40 min`, `11 h`.
fn duration(seconds: f64) -> String {
    if seconds < 120.0 {
        format!("{seconds:.0} s")
    } else if seconds < 7200.0 {
        format!("{:.0} min", seconds / 60.0)
    } else {
        format!("{:.0} h", seconds / 3600.0)
    }
}

/// `A..B` with A < B, finite.
fn span(flag: &str, text: &RangeText, unit: &str) -> Result<(f64, f64), CliError> {
    Ok(text.ends(flag, false, |a, b| a < b, &format!("A..B with A < B, in {unit}"))?)
}

/// (first, last, points) of an axis from `lo` toward `hi` by a point count or a step (the last
/// point lies at or past `hi`), as [`MapGrid::spanning`] takes it.
fn axis(
    lo: f64,
    hi: f64,
    points: Option<i64>,
    (step_flag, step): (&str, Option<f64>),
    points_flag: &str,
    default_points: usize,
) -> Result<(f64, f64, usize), CliError> {
    let max = i64::from(map::MAX_AXIS_POINTS);
    match (points, step) {
        (_, Some(step)) => {
            let step = checked(step_flag, step, step.is_finite() && step > 0.0, "finite and > 0")?;
            let n = steps_to_reach(lo, hi, step) + 1.0;
            if n > max as f64 {
                return Err(CliError::Input(format!(
                    "invalid {step_flag}: {step} (gives more than {max} points: use a larger step)"
                )));
            }
            let n = (n as usize).max(2);
            Ok((lo, lo + step * (n - 1) as f64, n))
        }
        (Some(n), None) => Ok((lo, hi, count(points_flag, n, 2, max)?)),
        (None, None) => Ok((lo, hi, default_points)),
    }
}

/// The spacing of the flags: `--speed-spacing`, else uniform with `--speed-step-rpm`, else
/// geometric; a step with geometric spacing is an error.
fn spacing(args: &MapArgs) -> Result<Spacing, CliError> {
    match (args.speed_spacing, args.speed_step_rpm) {
        (Some(SpeedSpacing::Geometric), Some(step)) => Err(CliError::Input(format!(
            "invalid --speed-step-rpm: {step} (a step spaces the speeds uniformly: give --speed-points with \
             --speed-spacing geometric)"
        ))),
        (Some(SpeedSpacing::Uniform), _) | (None, Some(_)) => Ok(Spacing::Uniform),
        (Some(SpeedSpacing::Geometric), None) | (None, None) => Ok(Spacing::Geometric),
    }
}

/// Estimated seconds per model evaluation of the spec's model.
fn seconds_per_evaluation(ctx: &Context<MapFormat>) -> f64 {
    match ctx.spec.model.lubrication {
        Lubrication::Dry => SECONDS_PER_DRY_EVALUATION,
        _ => SECONDS_PER_LUBRICATED_EVALUATION,
    }
}

/// The grid of the flags, each end checked as an operating point of the spec.
fn grid(ctx: &Context<MapFormat>, args: &MapArgs) -> Result<MapGrid, CliError> {
    let (p_lo, p_hi) = span("--preload-n", &args.preload, "N")?;
    let (c, d) = span("--speed-rpm", &args.speed_rpm, "rpm")?;
    for (preload_n, speed_rpm) in [(p_lo, c), (p_hi, d)] {
        let input = PointInput {
            speed_rpm: Some(speed_rpm),
            preload_n: Some(preload_n),
            axial_load_n: args.axial_load_n,
            preload_flag: "--preload-n",
        };
        ctx.operating_point(&input)?;
    }
    let (s_lo, s_hi) =
        if c <= 0.0 && d >= 0.0 { (0.0, c.abs().max(d.abs())) } else { (c.abs().min(d.abs()), c.abs().max(d.abs())) };
    if !(s_hi > s_lo) {
        return Err(CliError::Input(format!(
            "invalid --speed-rpm: {} (valid: a range of speed magnitudes, e.g. 0..3000 or -3000..3000)",
            args.speed_rpm
        )));
    }
    let (p0, p1, np) = axis(
        p_lo,
        p_hi,
        args.preload_points,
        ("--preload-step-n", args.preload_step),
        "--preload-points",
        DEFAULT_PRELOAD_POINTS,
    )?;
    let omega0 = ctx.spec.friction.standstill_speed_rad_s;
    let g = match spacing(args)? {
        Spacing::Uniform => {
            let (s0, s1, ns) = axis(
                s_lo,
                s_hi,
                args.speed_points,
                ("--speed-step-rpm", args.speed_step_rpm),
                "--speed-points",
                DEFAULT_SPEED_POINTS,
            )?;
            check_cost(np, ns, seconds_per_evaluation(ctx))?;
            MapGrid::spanning((p0, p1, np as u32), (rpm_to_rad_s(s0), rpm_to_rad_s(s1), ns as u32), omega0)
        }
        Spacing::Geometric => {
            // From zero: the axis starts at a tenth of the standstill speed, where the running
            // torque the blend needs has nearly reached its limit at zero speed.
            let first = if s_lo > 0.0 { rpm_to_rad_s(s_lo) } else { GEOMETRIC_FIRST_SPEED * omega0 };
            if !(rpm_to_rad_s(s_hi) > first) {
                return Err(CliError::Input(format!(
                    "invalid --speed-rpm: {} with --speed-spacing geometric (valid: a range that reaches above {} rpm, \
                     where a geometric axis from zero starts; or --speed-spacing uniform)",
                    args.speed_rpm,
                    rad_s_to_rpm(first)
                )));
            }
            let ns = match args.speed_points {
                Some(n) => count("--speed-points", n, 2, i64::from(map::MAX_AXIS_POINTS))?,
                None => DEFAULT_GEOMETRIC_SPEED_POINTS,
            };
            check_cost(np, ns, seconds_per_evaluation(ctx))?;
            MapGrid::geometric((p0, p1, np as u32), (first, rpm_to_rad_s(s_hi), ns as u32), omega0)
        }
    };
    g.validate().map_err(|e| grid_error(&e, args))?;
    // The last grid point may lie past B (a step that does not divide the range): check it too.
    let input = PointInput {
        speed_rpm: Some(rad_s_to_rpm(f64::from(g.speed_max_rad_s()))),
        preload_n: Some(f64::from(g.preload_max_n())),
        axial_load_n: args.axial_load_n,
        preload_flag: "--preload-n",
    };
    ctx.operating_point(&input)?;
    Ok(g)
}

/// The core's refusal of the grid the flags give (a `map.*` field), restated with the flag that
/// sets that part of the grid, as typed, and the grid's value in words.
fn grid_error(e: &ballscrew_core::InputError, args: &MapArgs) -> CliError {
    let (flag, typed, what) = match e.field {
        "map.preload_points" => ("--preload-points", args.preload_points.map(|n| n.to_string()), "preloads"),
        "map.speed_points" => ("--speed-points", args.speed_points.map(|n| n.to_string()), "speed magnitudes"),
        "map.preload_step_n" => ("--preload-n", Some(args.preload.to_string()), "preload step, N"),
        "map.preload_min_n" | "map.preload_max_n" => ("--preload-n", Some(args.preload.to_string()), "preload, N"),
        "map.speed_step" => ("--speed-rpm", Some(args.speed_rpm.to_string()), "speed step"),
        "map.values" => return CliError::Eval(format!("the map's torques: {e}")),
        _ => ("--speed-rpm", Some(args.speed_rpm.to_string()), "speed, rad/s"),
    };
    CliError::Input(format!(
        "invalid {flag}: {} (its grid's {what} is {}; valid: {})",
        typed.unwrap_or_default(),
        format_short(e.value),
        e.valid
    ))
}

/// Tabulates the model on the grid of the flags.
pub fn tabulate(ctx: &Context<MapFormat>, args: &MapArgs) -> Result<Tabulated, CliError> {
    let g = grid(ctx, args)?;
    let axial = args.axial_load_n.unwrap_or(ctx.spec.operating.axial_load_n);
    let bar = Bar::new("map", map::evaluations(g.preload_points as usize, g.speed_points as usize));
    map::tabulate_with_progress(&ctx.model, &g, axial, &mut |done, total| bar.set(done, total)).map_err(|e| match e {
        MapError::Input(e) => grid_error(&e, args),
        MapError::Model { error, preload_n, speed_rad_s } => {
            CliError::eval(&format!("map at preload {preload_n} N, speed {} rpm", rad_s_to_rpm(speed_rad_s)), &error)
        }
    })
}

/// The command line that reproduces the map (for the file's head).
fn command_line(ctx: &Context<MapFormat>, args: &MapArgs, t: &Tabulated) -> String {
    let g = &t.grid;
    let spec = if ctx.origin == BUILTIN_ORIGIN { String::new() } else { format!(" --spec {}", ctx.origin) };
    let name = ctx.format.to_possible_value().map(|v| v.get_name().to_owned()).unwrap_or_default();
    format!(
        "ballscrew map{spec} --preload-n {} --preload-points {} --speed-rpm {} --speed-points {} --speed-spacing {} \
         --axial-load-n {} --format {name}",
        args.preload,
        g.preload_points,
        args.speed_rpm,
        g.speed_points,
        g.speed_spacing.name(),
        t.axial_load_n
    )
}

/// Interpolation error a firmware map aims at (relative to the model's torque): above it the
/// command warns.
const TARGET_RELATIVE_ERROR: f64 = 5e-3;

/// Where the description of a CSV map written to `out` goes: `out` with `.about.txt` in place
/// of its extension (`map.csv` -> `map.about.txt`); `None` for standard output.
pub fn about_path(format: MapFormat, out: Option<&Path>) -> Option<PathBuf> {
    match (format, out) {
        (MapFormat::Csv, Some(p)) if p != Path::new(output::STDOUT) => Some(p.with_extension("about.txt")),
        _ => None,
    }
}

/// The flag a CSV map's description is named by in messages.
pub const ABOUT_FLAG: &str = "--out (the map's description)";

/// Runs the command and renders it (and its figure with `--plot`); `out` is where the text goes
/// (`None`: standard output).
pub fn run(ctx: &Context<MapFormat>, args: &MapArgs, out: Option<&Path>) -> Result<Output, CliError> {
    let (mut rendered, t) = render(ctx, args, out)?;
    // The grid's corner of most inertia: its top speed at its lightest preload.
    ctx.warn_inertia([OperatingPoint {
        speed_rad_s: f64::from(t.grid.speed_max_rad_s()),
        preload_n: f64::from(t.grid.preload_min_n),
        axial_load_n: t.axial_load_n,
    }]);
    if let Some(path) = &args.plot {
        let title = [
            format!(
                "ballscrew map: {}; axial load {} N; torque route: {}",
                ctx.origin,
                format_short(t.axial_load_n),
                ctx.route_name()
            ),
            format!("grid: {}", map_source::grid_summary(&t.grid)),
        ];
        rendered.files.push(SideFile { flag: "--plot", path: path.clone(), text: plots::map::svg(&title, &t)? });
    }
    Ok(rendered)
}

/// The map in the format asked for, and the map.
fn render(ctx: &Context<MapFormat>, args: &MapArgs, out: Option<&Path>) -> Result<(Output, Tabulated), CliError> {
    let t = tabulate(ctx, args)?;
    let p = Provenance { spec: ctx.origin.clone(), command: command_line(ctx, args, &t) };
    let (p_worst, w_worst) = t.worst_point;
    if matches!(ctx.format, MapFormat::C | MapFormat::Rust) && !t.max_relative_error.is_finite() {
        // A source file has no way to state an undefined number that compiles.
        return Err(CliError::Eval(format!(
            "map: the largest relative interpolation error is undefined (the model's torque is 0 at preload {} N, \
             speed {} rpm, the map's is not): no C or Rust source is written",
            format_short(p_worst),
            format_short(rad_s_to_rpm(w_worst))
        )));
    }
    if t.max_relative_error > TARGET_RELATIVE_ERROR {
        // The map is written (its error is stated in it), but not silently.
        eprintln!(
            "warning: the map's largest interpolation error against the model is {:.2} % (at preload {} N, \
             speed {} rpm), above the {:.1} % a firmware map aims at: the lubricated model's torque \
             changes with the speed and the preload (--speed-spacing geometric, more --speed-points or \
             --preload-points, or a narrower range)",
            100.0 * t.max_relative_error,
            format_short(p_worst),
            format_short(rad_s_to_rpm(w_worst)),
            100.0 * TARGET_RELATIVE_ERROR
        );
    }
    let rendered = match ctx.format {
        MapFormat::C => map_source::c_header(&t, &p).into(),
        MapFormat::Rust => map_source::rust(&t, &p).into(),
        MapFormat::Csv => {
            let about = map_source::about(&t, &p);
            match about_path(ctx.format, out) {
                Some(path) => Output {
                    text: Some(map_source::csv(&t)),
                    files: vec![SideFile { flag: ABOUT_FLAG, path, text: about }],
                    ..Output::default()
                },
                None => {
                    // Standard output carries the CSV alone, for a reader with no options.
                    eprint!("{about}");
                    map_source::csv(&t).into()
                }
            }
        }
        MapFormat::Table => {
            let mut out = format!("ballscrew map: {}\n\n", ctx.origin);
            out.push_str(&format!("grid: {}\n", map_source::grid_summary(&t.grid)));
            let relative = if t.max_relative_error.is_finite() {
                format!("{:.4} %", 100.0 * t.max_relative_error)
            } else {
                "n/a".to_string()
            };
            out.push_str(&format!(
                "largest interpolation error against the model: {relative} ({:.3e} N m) over {} check points\n",
                t.max_absolute_error_nm, t.checked_points
            ));
            out.push_str(&load_line(ctx, &t)?);
            out.push_str("write it with --format c|rust|csv and --out FILE\n");
            out.into()
        }
    };
    Ok((rendered, t))
}

/// The map's drive torque split into drag and load torque at the grid's first preload and the
/// spec's speed: the load torque F_a L / (2 pi) is in every tabulated value.
fn load_line(ctx: &Context<MapFormat>, t: &Tabulated) -> Result<String, CliError> {
    let op = OperatingPoint {
        speed_rad_s: ctx.spec.operating.speed_rad_s,
        preload_n: f64::from(t.grid.preload_min_n),
        axial_load_n: t.axial_load_n,
    };
    let s = ctx.model.summary(&op, &mut SolverState::new()).map_err(|e| CliError::eval("map: drag and load", &e))?;
    Ok(format!(
        "axial load {} N: every tabulated torque is the drag torque plus the load torque F_a L/2pi; at preload {} N, \
         {} rpm: torque {} = drag {} + load {} N m\n",
        format_short(t.axial_load_n),
        format_short(op.preload_n),
        format_short(rad_s_to_rpm(op.speed_rad_s)),
        format_short(s.torque_nm),
        format_short(s.drag_torque_nm()),
        format_short(s.load_torque_nm())
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_axis_ends_at_b_by_count_and_at_or_past_b_by_step() {
        let by_count = |n| axis(500.0, 3000.0, n, ("--preload-step-n", None), "--preload-points", 11);
        assert_eq!(by_count(None).unwrap(), (500.0, 3000.0, 11));
        assert_eq!(by_count(Some(3)).unwrap(), (500.0, 3000.0, 3));
        assert!(by_count(Some(1)).unwrap_err().to_string().starts_with("invalid --preload-points: 1 "));
        let by_step = |s| axis(500.0, 3000.0, None, ("--preload-step-n", Some(s)), "--preload-points", 11);
        assert_eq!(by_step(500.0).unwrap(), (500.0, 3000.0, 6));
        assert_eq!(by_step(1000.0).unwrap(), (500.0, 3500.0, 4));
        assert_eq!(by_step(5000.0).unwrap(), (500.0, 5500.0, 2));
        assert!(by_step(0.0).unwrap_err().to_string().starts_with("invalid --preload-step-n: 0 N "));
        assert!(by_step(1e-3).unwrap_err().to_string().contains("use a larger step"));
    }

    #[test]
    fn the_cost_counts_every_evaluation_of_tabulate() {
        // 11 x 4: 11 standstill values, 2 x 44 sheet values, 10 cells x 2 directions x 4 checks.
        let (evaluations, seconds) = cost(11, 4, SECONDS_PER_DRY_EVALUATION);
        assert_eq!(evaluations, 179.0);
        assert!(seconds < 0.5);
        assert!(check_cost(11, 4, SECONDS_PER_DRY_EVALUATION).is_ok());
        // Dry, 120 x 100: 47,920 evaluations, 72 s at 1.5 ms: refused.
        let e = check_cost(120, 100, SECONDS_PER_DRY_EVALUATION).unwrap_err().to_string();
        assert!(e.starts_with("invalid grid: 120 preloads x 100 speeds need 47920 model evaluations"), "{e}");
        assert!(e.contains("at 1500 us per evaluation") && e.contains("the limit is 60 s"), "{e}");
        // The lubricated default, 16 x 38: 2372 evaluations, estimated under 3 s; 200 x 100 is
        // refused (80 s).
        let (np, ns) = (DEFAULT_PRELOAD_POINTS, DEFAULT_GEOMETRIC_SPEED_POINTS);
        let (evaluations, seconds) = cost(np, ns, SECONDS_PER_LUBRICATED_EVALUATION);
        assert_eq!(evaluations, 2372.0);
        assert!(seconds < 3.0, "{seconds}");
        let e = check_cost(200, 100, SECONDS_PER_LUBRICATED_EVALUATION).unwrap_err().to_string();
        assert!(e.contains("at 1000 us per evaluation"), "{e}");
        assert_eq!(duration(2400.0), "40 min");
    }
}
