//! Sweeps: a range `A..B` taken in steps, both ends included, the last step possibly shorter, as
//! the command line's `sweep` runs it; and what every sweep shares, Python's `Screw.sweep` on
//! arrays too: at most [`MAX_SWEEP_POINTS`] points, the default preloads
//! ([`default_sweep_preloads_n`]).
//!
//! - [`RangeText`]: a range flag as typed, `A..B` or one value `A`; what the command line's
//!   parser reads such a flag into. Its ends are checked by the flag that uses them
//!   ([`RangeText::ends`]), each flag by its own rule.
//! - [`SweepRange`]: a range with its step, validated ([`SweepRange::from_flags`]: the ends, the
//!   step, the number of points), and its points ([`SweepRange::points`]).
//! - [`SweepError`]: what is wrong, naming the flag, the value as typed and the valid values, as
//!   the command line prints it.
//! - [`steps_to_reach`], [`range_points`]: the arithmetic of the points, which the command
//!   line's torque map shares (its axis by a step).
//! - [`sweep`]: the rows of a sweep ([`SweepRow`]: the summary, the oil temperature, the
//!   efficiency), its points ([`SweepPoint`]) each solved cold over the threads, a failing
//!   point ending the sweep or giving its error in its place ([`Errors`]); the one evaluation
//!   of `ballscrew sweep` and Python's `Screw.sweep`.

use crate::pool::{BatchError, Errors, Stop, map_shared};
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;
use ballscrew_core::screw::catalog::BAND_RELATIVE;
use ballscrew_core::{
    Efficiency, Error, Measured, Model, OperatingPoint, Short, Shown, SolverState, Summary, efficiency_beside,
};
use core::convert::Infallible;
use core::fmt;
use core::str::FromStr;

/// Most points of one sweep (a sweep keeps every row's full summary).
pub const MAX_SWEEP_POINTS: usize = 100_000;

/// The default preload sweep: from [`DEFAULT_SWEEP_FROM_N`] to [`DEFAULT_SWEEP_TO_N`] in steps of
/// [`DEFAULT_SWEEP_STEP_N`], N.
pub const DEFAULT_SWEEP_FROM_N: f64 = 500.0;
/// See [`DEFAULT_SWEEP_FROM_N`].
pub const DEFAULT_SWEEP_TO_N: f64 = 3000.0;
/// See [`DEFAULT_SWEEP_FROM_N`].
pub const DEFAULT_SWEEP_STEP_N: f64 = 100.0;

/// Steps of `step` from `lo` until `hi` is reached, the last one possibly shorter (`lo <= hi`,
/// `step > 0`). A range a whole number of steps long is not given one more by rounding: the
/// quotient is shrunk by 1e-12 relative before it is rounded up.
pub fn steps_to_reach(lo: f64, hi: f64, step: f64) -> f64 {
    ((hi - lo) / step * (1.0 - 1e-12)).ceil()
}

/// The points from `lo` to `hi`, both ends included, `step` apart with the last step possibly
/// shorter (see [`steps_to_reach`]); `[lo]` when `lo == hi`. The caller bounds the count.
pub fn range_points(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    let steps = steps_to_reach(lo, hi, step) as usize;
    (0..steps).map(|i| lo + i as f64 * step).chain([hi]).collect()
}

/// The preloads of the default sweep, N: 500 to 3000 in steps of 100.
pub fn default_sweep_preloads_n() -> Vec<f64> {
    range_points(DEFAULT_SWEEP_FROM_N, DEFAULT_SWEEP_TO_N, DEFAULT_SWEEP_STEP_N)
}

/// A range flag's value as typed: `A..B`, or one value `A`; each number finite, spaces around it
/// allowed (` -1 .. 2.5`).
///
/// Reading the text never fails ([`FromStr`], and `From<String>`, through which the command
/// line's parser reads the flag as any text flag): which values a flag takes (a range, or also
/// one value; `A <= B` or `A < B`) is the flag's own rule, its message names the flag, and a
/// command checks its flags in its own order (the spec first, then which quantity is swept, then
/// the values). So the ends are checked where the flag is used, [`RangeText::ends`]; the text is
/// kept for the messages, which quote it as typed.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct RangeText(String);

impl RangeText {
    /// The text as typed.
    pub fn as_str(&self) -> &str {
        &self.0
    }

    /// Whether the text asks for a range (it holds `..`) rather than one value; its ends may
    /// still be invalid.
    pub fn is_range(&self) -> bool {
        self.0.contains("..")
    }

    /// The ends `(A, B)` of `A..B`, both finite, when `ok(A, B)` holds; with `single`, one value
    /// `A` is read as `A..A`. Else `invalid FLAG: TEXT (valid: VALID)`.
    pub fn ends(
        &self,
        flag: &str,
        single: bool,
        ok: fn(f64, f64) -> bool,
        valid: &str,
    ) -> Result<(f64, f64), SweepError> {
        let number = |s: &str| s.trim().parse::<f64>().ok().filter(|x| x.is_finite());
        let parsed = match self.0.split_once("..") {
            Some((a, b)) => number(a).zip(number(b)),
            None if single => number(&self.0).map(|a| (a, a)),
            None => None,
        };
        match parsed {
            Some((a, b)) if ok(a, b) => Ok((a, b)),
            _ => Err(SweepError::Invalid { flag: flag.to_string(), value: self.0.clone(), valid: valid.to_string() }),
        }
    }
}

impl FromStr for RangeText {
    type Err = Infallible;

    fn from_str(text: &str) -> Result<Self, Infallible> {
        Ok(Self(text.to_string()))
    }
}

impl From<String> for RangeText {
    fn from(text: String) -> Self {
        Self(text)
    }
}

impl fmt::Display for RangeText {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

/// The flags of one swept quantity as the messages name them, and the unit of both.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SweepFlags<'a> {
    /// The range flag, e.g. `--speed-rpm`.
    pub range: &'a str,
    /// The step flag, e.g. `--speed-step-rpm`.
    pub step: &'a str,
    /// The unit of both, e.g. `rpm`.
    pub unit: &'a str,
    /// Whether one value `A` is taken too, as the range `A..A`.
    pub single: bool,
}

/// The preload's flags: `--preload-n` and `--preload-step-n` (the command line names an alias
/// instead where one was typed, `--preload` or `--step`).
pub const PRELOAD_FLAGS: SweepFlags<'static> =
    SweepFlags { range: "--preload-n", step: "--preload-step-n", unit: "N", single: true };
/// The screw speed's flags.
pub const SPEED_FLAGS: SweepFlags<'static> =
    SweepFlags { range: "--speed-rpm", step: "--speed-step-rpm", unit: "rpm", single: false };
/// The axial load's flags.
pub const AXIAL_LOAD_FLAGS: SweepFlags<'static> =
    SweepFlags { range: "--axial-load-n", step: "--axial-load-step-n", unit: "N", single: false };
/// The oil temperature's flags.
pub const OIL_TEMPERATURE_FLAGS: SweepFlags<'static> =
    SweepFlags { range: "--oil-temperature-c", step: "--oil-temperature-step-c", unit: "C", single: false };

/// A range `lo..hi` taken in steps of `step` (the last possibly shorter): `lo <= hi`, both
/// finite, `step` finite and positive, at most [`MAX_SWEEP_POINTS`] points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepRange {
    lo: f64,
    hi: f64,
    step: f64,
}

impl SweepRange {
    /// The range of a flag's text and its step flag's value, checked in that order: the ends
    /// (`A..B` with `A <= B`, or with [`SweepFlags::single`] one value), the step (finite and
    /// positive), the number of points (at most [`MAX_SWEEP_POINTS`]). The values themselves are
    /// the caller's to check (an operating point, a spec).
    pub fn from_flags(text: &RangeText, step: f64, flags: &SweepFlags<'_>) -> Result<Self, SweepError> {
        let valid = if flags.single {
            format!("A..B with A <= B, or a single value, in {}", flags.unit)
        } else {
            format!("A..B with A <= B, in {}", flags.unit)
        };
        let (lo, hi) = text.ends(flags.range, flags.single, |a, b| a <= b, &valid)?;
        if !(step.is_finite() && step > 0.0) {
            let valid = format!("finite and > 0 {}", flags.unit);
            return Err(SweepError::Invalid {
                flag: flags.step.to_string(),
                value: Measured { value: step, field: flags.step, valid: &valid }.to_string(),
                valid,
            });
        }
        if steps_to_reach(lo, hi, step) + 1.0 > MAX_SWEEP_POINTS as f64 {
            return Err(SweepError::TooManyPoints {
                range_flag: flags.range.to_string(),
                text: text.as_str().to_string(),
                step_flag: flags.step.to_string(),
                step,
            });
        }
        Ok(Self { lo, hi, step })
    }

    /// The first point.
    pub fn lo(&self) -> f64 {
        self.lo
    }

    /// The last point.
    pub fn hi(&self) -> f64 {
        self.hi
    }

    /// The step between points (the last one possibly shorter).
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The points, both ends included ([`range_points`]).
    pub fn points(&self) -> Vec<f64> {
        range_points(self.lo, self.hi, self.step)
    }
}

/// Why a range flag was refused.
#[derive(Debug, Clone, PartialEq)]
pub enum SweepError {
    /// A flag's value is not valid: `invalid FLAG: VALUE (valid: VALID)`.
    Invalid {
        /// The flag, e.g. `--preload-n`.
        flag: String,
        /// The value: a range's text as typed, a step as a number.
        value: String,
        /// The valid values, in words.
        valid: String,
    },
    /// The step is too small for the range: more than [`MAX_SWEEP_POINTS`] points.
    TooManyPoints {
        /// The range flag as the message names it.
        range_flag: String,
        /// The range as typed.
        text: String,
        /// The step flag as the message names it.
        step_flag: String,
        /// The step.
        step: f64,
    },
}

impl fmt::Display for SweepError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SweepError::Invalid { flag, value, valid } => write!(f, "invalid {flag}: {value} (valid: {valid})"),
            SweepError::TooManyPoints { range_flag, text, step_flag, step } => write!(
                f,
                "{range_flag} {text} with {step_flag} {} gives more than {MAX_SWEEP_POINTS} points: use a larger step",
                Shown(*step)
            ),
        }
    }
}

impl core::error::Error for SweepError {}

/// One row of a sweep: the torque summary at its point, the oil temperature at the contacts it
/// was computed at (the spec's, or the swept value) and the efficiency there.
#[derive(Debug, Clone, Copy)]
pub struct SweepRow {
    /// The torque summary.
    pub summary: Summary,
    /// `lubricant.temperature_c` of the point, degrees C.
    pub oil_temperature_c: f64,
    /// Forward and backdrive efficiency (`None`: no axial load or no speed, n/a).
    pub efficiency: Option<Efficiency>,
}

impl SweepRow {
    /// The row of a point the model could not evaluate (under [`Errors::Nan`]): its operating
    /// point and oil temperature, every other value NaN (the iteration count 0, no efficiency:
    /// a renderer shows such a row's columns as NaN whatever they hold but the point's).
    pub fn failed(point: &SweepPoint<'_>) -> SweepRow {
        let nan = f64::NAN;
        let summary = Summary {
            operating: point.op,
            torque_nm: nan,
            extension_nm: nan,
            torque_energy_nm: nan,
            torque_moment_nm: nan,
            torque_eq27_nm: nan,
            axial_term_nm: nan,
            dissipation_torque_nm: nan,
            creep_torque_nm: nan,
            rolling_resistance_torque_nm: nan,
            hysteresis_torque_nm: nan,
            ball_ball_torque_nm: nan,
            return_torque_nm: nan,
            seal_torque_nm: nan,
            screw_axial_force_n: nan,
            nut_loads_n: [nan; ballscrew_core::input::MAX_NUTS],
            catalog_nm: nan,
            iterations: 0,
            max_residual: nan,
        };
        SweepRow { summary, oil_temperature_c: point.model.spec().lubricant.temperature_c, efficiency: None }
    }
}

/// One point of a sweep: its operating point and the model that evaluates it (the spec's, or the
/// spec's with the oil at the point's temperature).
#[derive(Debug, Clone, Copy)]
pub struct SweepPoint<'a> {
    /// The operating point.
    pub op: OperatingPoint,
    /// The model, whose spec gives the row's oil temperature.
    pub model: &'a Model,
}

/// What failed at a point of a sweep: its summary, or the efficiency after it.
#[derive(Debug, Clone, PartialEq)]
pub enum RowError {
    /// The torque summary.
    Summary(Error),
    /// The forward and backdrive efficiency.
    Efficiency(Error),
}

impl RowError {
    /// The model's error.
    pub fn error(&self) -> &Error {
        match self {
            RowError::Summary(e) | RowError::Efficiency(e) => e,
        }
    }
}

/// Why a sweep ended before its last point.
#[derive(Debug, Clone, PartialEq)]
pub enum SweepEnd {
    /// The [`Stop`] said so.
    Stopped,
    /// The first failing point, under [`Errors::Raise`].
    Point {
        /// Its index in the points.
        index: usize,
        /// What failed.
        error: RowError,
    },
    /// The rows could not be reserved ([`BatchError::OutOfMemory`]).
    OutOfMemory {
        /// The size of the reservation that failed, bytes.
        bytes: usize,
    },
    /// A worker thread failed ([`BatchError::Internal`]): a bug, said as one.
    Internal(String),
}

impl From<SweepEnd> for BatchError {
    /// The end of a sweep as a batch's: a failing point with the model's error.
    fn from(end: SweepEnd) -> Self {
        match end {
            SweepEnd::Stopped => BatchError::Stopped,
            SweepEnd::Point { index, error } => BatchError::Point { index, error: *error.error() },
            SweepEnd::OutOfMemory { bytes } => BatchError::OutOfMemory { bytes },
            SweepEnd::Internal(m) => BatchError::Internal(m),
        }
    }
}

/// Points a sweep evaluates at a time over its threads before it gives their rows, in order,
/// to its caller: a sweep streams its rows (`sweep --format csv` into a pipe) a block at a time.
pub const SWEEP_BLOCK_POINTS: usize = 32;

/// The row of `point`: its summary solved cold (the canonical state: the numbers `ballscrew
/// torque` gives at the point, to the bit) and, under an axial load, its efficiency (the other
/// rotation solved cold too, [`efficiency_beside`]).
pub fn sweep_row(point: &SweepPoint<'_>) -> Result<SweepRow, RowError> {
    let summary = point.model.summary(&point.op, &mut SolverState::new()).map_err(RowError::Summary)?;
    let efficiency = efficiency_beside(point.model, &point.op, &summary).map_err(RowError::Efficiency)?;
    Ok(SweepRow { summary, oil_temperature_c: point.model.spec().lubricant.temperature_c, efficiency })
}

/// The rows of a sweep, in the points' order: every point solved on its own from the cold start
/// ([`sweep_row`]), so a row is the point's stateless answer whatever the other points, and
/// the same bits on any number of threads. The points are shared over `threads` threads
/// [`SWEEP_BLOCK_POINTS`] at a time (each thread takes the next point not yet taken), and
/// `on_row` gets each row of a block and its index, in order, once the block is done. `stop`
/// is asked before each point and told after it. Under [`Errors::Raise`] the first failing
/// point ends the sweep ([`SweepEnd::Point`]) and every row given is `Ok`; under
/// [`Errors::Nan`] a failing point gives its error in its place.
pub fn sweep(
    points: &[SweepPoint<'_>],
    threads: usize,
    stop: &dyn Stop,
    errors: Errors,
    on_row: &mut dyn FnMut(usize, &SweepRow),
) -> Result<Vec<Result<SweepRow, RowError>>, SweepEnd> {
    // Reserved before the first point (a failure is an error, not an abort of the process).
    let mut rows = Vec::new();
    rows.try_reserve_exact(points.len()).map_err(|_| SweepEnd::OutOfMemory {
        bytes: points.len().saturating_mul(core::mem::size_of::<Result<SweepRow, RowError>>()),
    })?;
    for (b, block) in points.chunks(SWEEP_BLOCK_POINTS).enumerate() {
        let block_rows = map_shared(block, threads, stop, |p| Ok(sweep_row(p))).map_err(|e| match e {
            BatchError::Stopped => SweepEnd::Stopped,
            BatchError::OutOfMemory { bytes } => SweepEnd::OutOfMemory { bytes },
            // The evaluation above fails at no point: its errors are rows.
            BatchError::Point { index, error } => {
                SweepEnd::Point { index: b * SWEEP_BLOCK_POINTS + index, error: RowError::Summary(error) }
            }
            BatchError::Internal(m) => SweepEnd::Internal(m),
        })?;
        for (k, row) in block_rows.into_iter().enumerate() {
            let index = b * SWEEP_BLOCK_POINTS + k;
            match (row, errors) {
                (Ok(row), _) => {
                    on_row(index, &row);
                    rows.push(Ok(row));
                }
                (Err(error), Errors::Raise) => return Err(SweepEnd::Point { index, error }),
                (Err(error), Errors::Nan) => rows.push(Err(error)),
            }
        }
    }
    Ok(rows)
}

/// One line: where the drag torque of `rows` (the load torque left out) stands against the
/// catalog band, by magnitude; `what` names the swept values (`preloads`, `speeds`, ...).
pub fn band_note(rows: &[SweepRow], what: &str) -> String {
    let ratios: Vec<f64> = rows.iter().map(|r| r.summary.catalog_ratio().abs()).filter(|r| r.is_finite()).collect();
    let band = format!("catalog x [{}, {}]", Short(1.0 - BAND_RELATIVE), Short(1.0 + BAND_RELATIVE));
    if ratios.is_empty() {
        return format!("Catalog band ({band}): no comparison (zero catalog torque).");
    }
    let below = ratios.iter().filter(|&&r| r < 1.0 - BAND_RELATIVE).count();
    let above = ratios.iter().filter(|&&r| r > 1.0 + BAND_RELATIVE).count();
    let within = ratios.len() - below - above;
    let lo = ratios.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = ratios.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    format!(
        "Drag torque against the catalog band ({band}): model below at {below}, within at {within}, above at {above} of {} {what}; \
         |model/catalog| {:.3} to {:.3}.",
        ratios.len(),
        lo,
        hi
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The preload's flags as the command line names them.
    const PRELOAD: SweepFlags<'static> = PRELOAD_FLAGS;

    fn text(t: &str) -> RangeText {
        t.parse().unwrap()
    }

    fn preload_points(t: &str, step: f64) -> Result<Vec<f64>, SweepError> {
        SweepRange::from_flags(&text(t), step, &PRELOAD).map(|r| r.points())
    }

    #[test]
    fn ranges_keep_both_ends_and_no_rounding_step() {
        let d = default_sweep_preloads_n();
        assert_eq!(d.len(), 26);
        assert_eq!((d[0], d[1], d[25]), (500.0, 600.0, 3000.0));
        assert_eq!(range_points(0.0, 250.0, 100.0), [0.0, 100.0, 200.0, 250.0]);
        assert_eq!(range_points(1000.0, 1000.0, 100.0), [1000.0]);
        // 0.9 / 0.03 is 30.000000000000004 in floating point: still 30 steps.
        assert_eq!(steps_to_reach(0.0, 0.9, 0.03), 30.0);
        assert_eq!(range_points(0.0, 0.9, 0.03).len(), 31);
        assert_eq!(steps_to_reach(0.0, 250.0, 100.0), 3.0);
    }

    #[test]
    fn default_range_has_26_points() {
        let p = preload_points("500..3000", 100.0).unwrap();
        assert_eq!(p.len(), 26);
        assert_eq!((p[0], p[1], p[25]), (500.0, 600.0, 3000.0));
        assert_eq!(p, default_sweep_preloads_n());
    }

    #[test]
    fn uneven_range_keeps_both_ends() {
        assert_eq!(preload_points("0..250", 100.0).unwrap(), [0.0, 100.0, 200.0, 250.0]);
        assert_eq!(preload_points("1000", 100.0).unwrap(), [1000.0]);
        assert_eq!(preload_points("1000..1000", 100.0).unwrap(), [1000.0]);
        assert_eq!(preload_points("0.5..0.7", 0.1).unwrap().len(), 3);
        let r = SweepRange::from_flags(&text(" 0 .. 250 "), 100.0, &PRELOAD).unwrap();
        assert_eq!((r.lo(), r.hi(), r.step()), (0.0, 250.0, 100.0));
    }

    #[test]
    fn ranges_parse_by_the_callers_rule() {
        let below = |a: f64, b: f64| a < b;
        assert_eq!(text(" -1 .. 2.5").ends("--x", false, below, "V").unwrap(), (-1.0, 2.5));
        assert_eq!(text("7").ends("--x", true, |a, b| a <= b, "V").unwrap(), (7.0, 7.0));
        for t in ["7", "2..1", "1..1", "1..inf", "a..2", "1..2..3"] {
            let e = text(t).ends("--x", false, below, "A..B with A < B").unwrap_err();
            assert_eq!(e.to_string(), format!("invalid --x: {t} (valid: A..B with A < B)"));
        }
        assert!(text("1..x").is_range() && !text("7").is_range());
        assert_eq!(text(" 1..2").to_string(), " 1..2");
        assert_eq!(RangeText::from(String::from("1..2")), text("1..2"));
    }

    /// The messages name the flag, the value as typed (a step as a number) and the valid values,
    /// as the command line prints them.
    #[test]
    fn messages_name_the_flag_value_and_range() {
        let cases = [
            ("3000..500", 100.0, "invalid --preload-n: 3000..500 (valid: A..B with A <= B, or a single value, in N)"),
            ("five", 100.0, "invalid --preload-n: five (valid: A..B with A <= B, or a single value, in N)"),
            ("500..3000", 0.0, "invalid --preload-step-n: 0 N (valid: finite and > 0 N)"),
            ("500..3000", f64::NAN, "invalid --preload-step-n: NaN (valid: finite and > 0 N)"),
            (
                "0..1",
                1e-300,
                "--preload-n 0..1 with --preload-step-n 1e-300 gives more than 100000 points: use a larger step",
            ),
        ];
        for (t, step, message) in cases {
            assert_eq!(preload_points(t, step).unwrap_err().to_string(), message);
        }
        let speed = SPEED_FLAGS;
        let e = |t: &str, step: f64| SweepRange::from_flags(&text(t), step, &speed).unwrap_err().to_string();
        assert_eq!(e("100", 10.0), "invalid --speed-rpm: 100 (valid: A..B with A <= B, in rpm)");
        assert_eq!(e("0..100", -1.0), "invalid --speed-step-rpm: -1 (valid: finite and > 0 rpm)");
        assert_eq!(
            e("0..100", 1e-9),
            "--speed-rpm 0..100 with --speed-step-rpm 1e-9 gives more than 100000 points: use a larger step"
        );
        assert!(preload_points("0..1e7", 1e-3).is_err());
        assert_eq!(preload_points("0..9999.9", 0.1).unwrap().len(), MAX_SWEEP_POINTS);
    }

    /// The rows are the points in order, each the point's cold summary and efficiency to the
    /// bit (on one thread and on two, over more than one block); a point the model refuses
    /// ends the sweep under `Raise` and takes its place under `Nan`.
    #[test]
    fn a_sweep_evaluates_its_points_in_order_and_keeps_or_stops_at_a_failure() {
        use crate::pool::Never;
        use ballscrew_core::{ScrewSpec, efficiency_if_defined};
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let at = |preload_n: f64, axial_load_n: f64| SweepPoint {
            op: OperatingPoint { preload_n, axial_load_n, ..model.spec().operating },
            model: &model,
        };
        let mut points: Vec<SweepPoint<'_>> = (0..SWEEP_BLOCK_POINTS + 3)
            .map(|k| at(1000.0 + 40.0 * k as f64, if k % 2 == 0 { 0.0 } else { -80.0 }))
            .collect();
        points[1] = at(-5.0, 0.0);
        let failing = SWEEP_BLOCK_POINTS + 1;
        points[failing] = at(f64::NAN, 0.0);
        for threads in [1, 2] {
            let mut seen = Vec::new();
            let rows = sweep(&points, threads, &Never, Errors::Nan, &mut |i, _| seen.push(i)).unwrap();
            let expected: Vec<usize> = (0..points.len()).filter(|&i| i != 1 && i != failing).collect();
            assert_eq!(seen, expected);
            assert!(matches!(&rows[1], Err(RowError::Summary(Error::Input(e))) if e.field == "preload_n"));
            assert!(rows[failing].is_err());
            for &k in &expected {
                let row = rows[k].as_ref().unwrap();
                let op = points[k].op;
                let cold = model.summary(&op, &mut SolverState::new()).unwrap();
                assert_eq!(row.summary, cold, "point {k}");
                assert_eq!(row.efficiency, efficiency_if_defined(&model, &op).unwrap(), "point {k}");
                assert_eq!(row.efficiency.is_some(), op.axial_load_n != 0.0);
                assert_eq!(row.oil_temperature_c, model.spec().lubricant.temperature_c);
            }
        }
        let end = sweep(&points, 2, &Never, Errors::Raise, &mut |_, _| {}).unwrap_err();
        assert!(matches!(end, SweepEnd::Point { index: 1, error: RowError::Summary(_) }), "{end:?}");
    }
}
