//! Every prediction with its uncertainty: the band of the drag torque that the spread of the
//! spec's uncertain inputs ([`ballscrew_core::input::uncertainty`]) gives, and what drives it.
//!
//! # The band
//!
//! A band samples the inputs the model reads that are not pinned (half-width above 0), each
//! uniform over its spread, by a quasi-random sequence: Owen-scrambled Sobol points (Burley
//! 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4); the `sobol_burley` crate), seeded,
//! so that the same spec, points, sample size and seed give the same band on every run and on
//! any number of threads. Each sample is a spec and an operating point moved to the sample's
//! values ([`ballscrew_core::ScrewSpec::spread_to`]) and evaluated by the model at every point; the band at a
//! point is a pair of quantiles of the samples' drag torques (numpy's default, linear between
//! order statistics: Hyndman & Fan 1996, definition 7).
//!
//! Each sample is solved from the cold start, as `ballscrew torque` solves a point: its drag
//! torque is its spec's canonical state (the state the model's cold continuation reaches; the
//! model notes, "Several steady states"), the same bits alone, in a sweep or on any thread
//! count, and never the other state of a ball that has two.
//!
//! # What drives it
//!
//! [`sensitivity`] ranks the inputs at one point two ways:
//! - **swings** (one at a time): the drag torque with one input at each end of its spread and
//!   the others nominal, what a tornado chart draws;
//! - **Sobol indices** (variance-based): each input's first-order index `S_i`, the share of the
//!   band's variance it causes alone, and its total index `ST_i`, with its interactions; by
//!   Saltelli et al. (2010), "Variance based sensitivity analysis of model output", Computer
//!   Physics Communications 181, Table 2 (`S_i` by its formula (b), `ST_i` by Jansen's (f)), from
//!   `N (k + 2)` model evaluations of two Sobol sample matrices `A` and `B` and the `k` matrices
//!   `A_B^(i)`.

use crate::Batch;
use crate::pool::BatchError;
use crate::sweep::SweepPoint;
use alloc::vec::Vec;
use ballscrew_core::input::uncertainty::INPUTS;
use ballscrew_core::input::{OperatingPoint, UNCERTAIN_INPUTS};
use ballscrew_core::{Error, InputError, Model, SolverState};

/// Samples of a band by default: the band's ends of DKFZD4012's drag torque within about 0.06
/// of its width of their converged values, root mean square over seeds (`docs/uncertainty.md`,
/// checked by `crates/batch/tests/uncertainty.rs`); a point's band in about 60 ms at 100 rpm.
pub const DEFAULT_SAMPLES: u32 = 128;
/// Fewest samples of a band.
pub const MIN_SAMPLES: u32 = 8;
/// Most samples of a band: the Sobol sequence's length (2^16).
pub const MAX_SAMPLES: u32 = 1 << 16;
/// Valid sample sizes, for messages.
pub const SAMPLES_VALID: &str = "a whole number in [8, 65536]";
/// The seed by default.
pub const DEFAULT_SEED: u32 = 0;
/// The band's quantiles by default: 5 % and 95 %.
pub const DEFAULT_QUANTILES: (f64, f64) = (0.05, 0.95);
/// Valid quantile pairs, for messages.
pub const QUANTILES_VALID: &str = "two quantiles in [0, 1], the first below the second";

/// How a band samples: its size, its seed and its quantiles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BandSettings {
    /// Samples ([`MIN_SAMPLES`] to [`MAX_SAMPLES`]).
    pub samples: u32,
    /// Seed of the scrambled Sobol sequence.
    pub seed: u32,
    /// The band's low and high quantiles, in [0, 1], low < high.
    pub quantiles: (f64, f64),
}

impl Default for BandSettings {
    fn default() -> Self {
        Self { samples: DEFAULT_SAMPLES, seed: DEFAULT_SEED, quantiles: DEFAULT_QUANTILES }
    }
}

/// A setting of a band out of its range: which (`samples` or `quantiles`), what was given and
/// what is valid.
#[derive(Debug, Clone, PartialEq)]
pub struct SettingError {
    /// `samples` or `quantiles`.
    pub setting: &'static str,
    /// The value as given.
    pub value: alloc::string::String,
    /// What is valid.
    pub valid: &'static str,
}

impl BandSettings {
    /// Checks the sample size and the quantiles.
    pub fn validate(&self) -> Result<(), SettingError> {
        if !(MIN_SAMPLES..=MAX_SAMPLES).contains(&self.samples) {
            return Err(SettingError {
                setting: "samples",
                value: alloc::format!("{}", self.samples),
                valid: SAMPLES_VALID,
            });
        }
        let (lo, hi) = self.quantiles;
        if !(0.0..=1.0).contains(&lo) || !(0.0..=1.0).contains(&hi) || lo >= hi {
            return Err(SettingError {
                setting: "quantiles",
                value: alloc::format!("{lo},{hi}"),
                valid: QUANTILES_VALID,
            });
        }
        Ok(())
    }
}

/// The band of the drag torque at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Band {
    /// The nominal drag torque (every input at its value), N m: the summary's, to the bit.
    pub nominal_nm: f64,
    /// The low quantile of the samples' drag torque, N m.
    pub low_nm: f64,
    /// The samples' median drag torque, N m.
    pub median_nm: f64,
    /// The high quantile, N m.
    pub high_nm: f64,
}

impl Band {
    /// The band of zero width at `drag_nm` (every input pinned).
    pub fn at(drag_nm: f64) -> Self {
        Self { nominal_nm: drag_nm, low_nm: drag_nm, median_nm: drag_nm, high_nm: drag_nm }
    }
}

/// Why a band has no answer.
#[derive(Debug, Clone, PartialEq)]
pub enum BandError {
    /// A setting out of range.
    Setting(SettingError),
    /// A half-width out of range, or a point the spec refuses.
    Input(InputError),
    /// An input at one end of its spread leaves the spec's valid range (the others nominal).
    Spread(ballscrew_core::input::SpreadError),
    /// The nominal spec failed at point `point`.
    Nominal {
        /// The point's index.
        point: usize,
        /// The model's error.
        error: Error,
    },
    /// The model failed at point `point` with input `input` at one end of its spread (`end`: -1
    /// or 1), the others nominal.
    End {
        /// The input's index in [`UNCERTAIN_INPUTS`].
        input: usize,
        /// -1: the low end; 1: the high end.
        end: f64,
        /// The point's index.
        point: usize,
        /// The model's error.
        error: Error,
    },
    /// A sample failed at point `point` (cold).
    Sample {
        /// The sample's index.
        sample: usize,
        /// The sample's position in each input's spread (-1 to 1; 0 for a pinned input).
        at: alloc::boxed::Box<[f64; INPUTS]>,
        /// The point's index.
        point: usize,
        /// The model's error.
        error: Error,
    },
    /// The batch stopped, ran out of memory or failed inside.
    Batch(BatchError),
}

impl core::fmt::Display for BandError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            BandError::Setting(e) => write!(f, "invalid band {}: {} (valid: {})", e.setting, e.value, e.valid),
            BandError::Input(e) => write!(f, "{e}"),
            BandError::Spread(e) => write!(f, "{e}"),
            BandError::Nominal { error, .. } => write!(f, "{error}"),
            BandError::End { input, end, error, .. } => {
                let u = &UNCERTAIN_INPUTS[*input];
                let side = if *end < 0.0 { "low" } else { "high" };
                write!(f, "{} at the {side} end of its spread ({}): {error}", u.name, u.field)
            }
            BandError::Sample { sample, at, error, .. } => {
                write!(f, "sample {sample} of the band (")?;
                let mut first = true;
                for (i, input) in UNCERTAIN_INPUTS.iter().enumerate() {
                    if at[i] != 0.0 {
                        let sep = if first { "" } else { ", " };
                        write!(f, "{sep}{} at {:+.2} of its half-width", input.name, at[i])?;
                        first = false;
                    }
                }
                write!(f, "): {error}")
            }
            BandError::Batch(BatchError::Point { error, .. }) => write!(f, "{error}"),
            BandError::Batch(BatchError::Internal(m)) => write!(f, "internal error: {m}"),
            BandError::Batch(BatchError::Stopped) => write!(f, "stopped"),
            BandError::Batch(BatchError::OutOfMemory { bytes }) => write!(f, "out of memory ({bytes} bytes asked for)"),
        }
    }
}

impl core::error::Error for BandError {}

/// Where each sample of a band lies in each input's spread, -1 to 1 (0 for an input pinned or
/// not read by the model): the first `samples` points of the scrambled Sobol sequence of
/// `seed`, one dimension per active input, in [`UNCERTAIN_INPUTS`]' order from `dimension`.
pub fn sample_positions(active: &[usize], samples: u32, seed: u32, dimension: u32) -> Vec<[f64; INPUTS]> {
    (0..samples)
        .map(|s| {
            let mut u = [0.0; INPUTS];
            for (d, &i) in active.iter().enumerate() {
                let x = f64::from(sobol_burley::sample(s, dimension + d as u32, seed));
                u[i] = 2.0 * x - 1.0;
            }
            u
        })
        .collect()
}

/// The inputs of `points`' spec that spread the torque (see
/// [`ballscrew_core::input::Uncertainty::active`]).
pub fn active_inputs(points: &[SweepPoint<'_>]) -> Vec<usize> {
    match points.first() {
        Some(p) => p.model.spec().uncertainty.active(p.model.spec().model.lubrication).collect(),
        None => Vec::new(),
    }
}

/// The drag torque (N m) of `model` at `op`, solved from the cold start (the canonical state).
fn drag_nm(model: &Model, op: &OperatingPoint) -> Result<f64, Error> {
    Ok(model.torque(op, &mut SolverState::new())? - model.load_torque_nm(op))
}

/// What a point's band and sensitivity take besides the samples: the nominal drag torque and,
/// for each active input, the drag torques with it at each end of its spread (the others
/// nominal).
#[derive(Debug, Clone)]
struct PointEnds {
    nominal_nm: f64,
    /// Per active input: the drag torques at -1 and +1, N m.
    end_nm: Vec<[f64; 2]>,
}

/// The spec and operating point of `point` moved to the sample positions `u`, and its model.
fn moved(point: &SweepPoint<'_>, u: &[f64; INPUTS]) -> Result<(Model, OperatingPoint), Error> {
    let (spec, op) = point.model.spec().spread_to(u, &point.op);
    Ok((Model::new(&spec)?, op))
}

/// Each point's ends ([`PointEnds`]), over the threads of `batch`, each solved cold: a point's
/// ends depend on that point alone, so its band does not depend on the other points it is
/// computed with.
fn point_ends(batch: &Batch<'_>, points: &[SweepPoint<'_>], active: &[usize]) -> Result<Vec<PointEnds>, BandError> {
    // The end of a spread that failed at a point, by point (the batch's error carries the
    // model's error alone).
    let ends_failed = std::sync::Mutex::new(alloc::collections::BTreeMap::new());
    let eval = |&k: &usize, _: &mut ()| -> Result<PointEnds, Error> {
        let p = &points[k];
        // The summary's drag torque: the number `torque` and `sweep` report, to the bit.
        let nominal_nm = p.model.summary(&p.op, &mut SolverState::new())?.drag_torque_nm();
        let mut end_nm = Vec::with_capacity(active.len());
        for &i in active {
            let mut drags = [0.0; 2];
            for (e, end) in [-1.0, 1.0].into_iter().enumerate() {
                let mut u = [0.0; INPUTS];
                u[i] = end;
                let failed = |error: Error| {
                    ends_failed.lock().unwrap_or_else(|p| p.into_inner()).insert(k, (i, end));
                    error
                };
                let (model, op) = moved(p, &u).map_err(failed)?;
                drags[e] = drag_nm(&model, &op).map_err(failed)?;
            }
            end_nm.push(drags);
        }
        Ok(PointEnds { nominal_nm, end_nm })
    };
    let batch = Batch { start: crate::Start::Independent, errors: crate::Errors::Raise, ..*batch };
    let indices: Vec<usize> = (0..points.len()).collect();
    let error = |point: usize, error: Error| match ends_failed.lock().map(|m| m.get(&point).copied()) {
        Ok(Some((input, end))) => BandError::End { input, end, point, error },
        _ => BandError::Nominal { point, error },
    };
    let results = batch.map(&indices, || (), eval).map_err(|e| match e {
        BatchError::Point { index, error: e } => error(index, e),
        other => BandError::Batch(other),
    })?;
    results.into_iter().enumerate().map(|(point, r)| r.map_err(|e| error(point, e))).collect()
}

/// The drag torque (N m) of each sample position of `at` at each point of `points` (one row per
/// sample), over the threads of `batch`, each solved cold (its spec's canonical state).
fn drags_from(batch: &Batch<'_>, points: &[SweepPoint<'_>], at: &[[f64; INPUTS]]) -> Result<Vec<Vec<f64>>, BandError> {
    // The point each failing sample failed at, by sample (the batch's error carries the
    // model's error alone, of the failing sample of lowest index).
    let failed = std::sync::Mutex::new(alloc::collections::BTreeMap::new());
    let samples: Vec<usize> = (0..at.len()).collect();
    let eval = |&sample: &usize, _: &mut ()| -> Result<Vec<f64>, Error> {
        let u = &at[sample];
        let mut row = Vec::with_capacity(points.len());
        let mut built: Option<(*const Model, Model, OperatingPoint)> = None;
        for (k, p) in points.iter().enumerate() {
            let fail = |e: Error| {
                failed.lock().unwrap_or_else(|p| p.into_inner()).insert(sample, k);
                e
            };
            // One model per sample, built again only where the points' model changes (a sweep
            // of the oil temperature has one per point).
            let (model, op) = match &built {
                Some((key, m, _)) if core::ptr::eq(*key, p.model) => (m, p.model.spec().spread_to(u, &p.op).1),
                _ => {
                    let (m, op) = moved(p, u).map_err(fail)?;
                    let b = built.insert((p.model as *const Model, m, op));
                    (&b.1, b.2)
                }
            };
            row.push(drag_nm(model, &op).map_err(fail)?);
        }
        Ok(row)
    };
    let batch = Batch { start: crate::Start::Independent, errors: crate::Errors::Raise, ..*batch };
    let error = |sample: usize, error: Error| BandError::Sample {
        sample,
        at: alloc::boxed::Box::new(at[sample]),
        point: failed.lock().map_or(0, |f| f.get(&sample).copied().unwrap_or(0)),
        error,
    };
    // Under `Errors::Raise` the batch ends at the first failing sample: every result is `Ok`.
    let results = batch.map(&samples, || (), eval).map_err(|e| match e {
        BatchError::Point { index, error: e } => error(index, e),
        other => BandError::Batch(other),
    })?;
    results.into_iter().enumerate().map(|(sample, r)| r.map_err(|e| error(sample, e))).collect()
}

/// The drag torque (N m) at each point of `points` of each sample position of `at` (rows: the
/// samples; [`sample_positions`] gives a band's), over the threads of `batch`: what [`band`]
/// takes its quantiles of.
pub fn sample_drags(
    batch: &Batch<'_>,
    points: &[SweepPoint<'_>],
    at: &[[f64; INPUTS]],
) -> Result<Vec<Vec<f64>>, BandError> {
    check_spreads(points)?;
    drags_from(batch, points, at)
}

/// Checks each point's spread ([`ballscrew_core::ScrewSpec::check_spread`]).
fn check_spreads(points: &[SweepPoint<'_>]) -> Result<(), BandError> {
    for p in points {
        let spec = p.model.spec();
        spec.check_spread(&p.op).map_err(|e| match e {
            ballscrew_core::input::SpreadError::Nominal(e) => BandError::Input(e),
            end => BandError::Spread(end),
        })?;
    }
    Ok(())
}

/// The quantile `q` (0 to 1) of `sorted` (ascending, not empty): linear between order
/// statistics (Hyndman & Fan's definition 7, numpy's default).
pub fn quantile(sorted: &[f64], q: f64) -> f64 {
    let h = (sorted.len() - 1) as f64 * q;
    let (lo, frac) = (h.floor() as usize, h - h.floor());
    match sorted.get(lo + 1) {
        Some(&next) if frac > 0.0 => sorted[lo] + frac * (next - sorted[lo]),
        _ => sorted[lo],
    }
}

/// The band of the drag torque at each point of `points` (their spec's `[uncertainty]`), by
/// `settings`, over the threads of `batch`. With every input pinned each band is the nominal
/// drag torque, of zero width.
pub fn band(batch: &Batch<'_>, points: &[SweepPoint<'_>], settings: &BandSettings) -> Result<Vec<Band>, BandError> {
    settings.validate().map_err(BandError::Setting)?;
    check_spreads(points)?;
    let active = active_inputs(points);
    let at = if active.is_empty() { Vec::new() } else { sample_positions(&active, settings.samples, settings.seed, 0) };
    let mut bands = Vec::new();
    bands.try_reserve_exact(points.len()).map_err(|_| {
        BandError::Batch(BatchError::OutOfMemory { bytes: points.len().saturating_mul(core::mem::size_of::<Band>()) })
    })?;
    // A few points at a time: each point's ends hold 2k + 1 drag torques, and its samples'
    // drag torques `samples` numbers, so a long sweep is not held whole.
    for (c, chunk) in points.chunks(BAND_CHUNK_POINTS).enumerate() {
        let offset = c * BAND_CHUNK_POINTS;
        let ends = point_ends(batch, chunk, &active).map_err(|e| e.at_offset(offset))?;
        if active.is_empty() {
            bands.extend(ends.iter().map(|s| Band::at(s.nominal_nm)));
            continue;
        }
        let drags = drags_from(batch, chunk, &at).map_err(|e| e.at_offset(offset))?;
        bands.extend(
            (0..chunk.len()).map(|k| quantiles(drags.iter().map(|row| row[k]).collect(), settings, ends[k].nominal_nm)),
        );
    }
    Ok(bands)
}

/// The steps of [`band`] over `points` (each point's ends, then each sample of each chunk of
/// points), as its batch's [`crate::Stop`] is told of them: for a progress display.
pub fn band_steps(points: &[SweepPoint<'_>], settings: &BandSettings) -> usize {
    let samples = if active_inputs(points).is_empty() { 0 } else { settings.samples as usize };
    points.len() + points.len().div_ceil(BAND_CHUNK_POINTS) * samples
}

/// Points of a band evaluated together: at 2k + 1 drag torques a point and `samples` more
/// torques, 64 points hold a few tens of megabytes at most.
pub const BAND_CHUNK_POINTS: usize = 64;

impl BandError {
    /// The error with its point's index moved by `offset` (of a chunk of the points).
    fn at_offset(self, offset: usize) -> Self {
        match self {
            BandError::Nominal { point, error } => BandError::Nominal { point: point + offset, error },
            BandError::End { input, end, point, error } => BandError::End { input, end, point: point + offset, error },
            BandError::Sample { sample, at, point, error } => {
                BandError::Sample { sample, at, point: point + offset, error }
            }
            other => other,
        }
    }
}

/// The band of the drag torques `drags` (of one point, one per sample) by the quantiles of
/// `settings`, about the nominal drag torque `nominal_nm`.
fn quantiles(mut drags: Vec<f64>, settings: &BandSettings, nominal_nm: f64) -> Band {
    drags.sort_by(f64::total_cmp);
    Band {
        nominal_nm,
        low_nm: quantile(&drags, settings.quantiles.0),
        median_nm: quantile(&drags, 0.5),
        high_nm: quantile(&drags, settings.quantiles.1),
    }
}

/// What one input does to the drag torque at a point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InputSensitivity {
    /// The input's index in [`UNCERTAIN_INPUTS`].
    pub input: usize,
    /// Its half-width (in its unit: [`ballscrew_core::input::UncertainInput::unit`]).
    pub half_width: f64,
    /// The drag torque with the input at the low end of its spread, the others nominal, N m.
    pub low_end_nm: f64,
    /// The drag torque with the input at the high end, N m.
    pub high_end_nm: f64,
    /// First-order Sobol index: the share of the band's variance the input causes alone.
    pub first_order: f64,
    /// Total Sobol index: its share with every interaction it takes part in.
    pub total: f64,
}

impl InputSensitivity {
    /// The swing, `|high end - low end|`, N m.
    pub fn swing_nm(&self) -> f64 {
        (self.high_end_nm - self.low_end_nm).abs()
    }
}

/// The inputs' sensitivities at one point.
#[derive(Debug, Clone, PartialEq)]
pub struct Sensitivity {
    /// The nominal drag torque, N m.
    pub nominal_nm: f64,
    /// The variance of the drag torque over the sample, N^2 m^2.
    pub variance_nm2: f64,
    /// The band of the drag torque from the first of the two samples: the band [`band`] gives at
    /// the point with the same settings, to the bit.
    pub band: Band,
    /// Each active input, by swing, largest first.
    pub inputs: Vec<InputSensitivity>,
}

/// The sensitivity of the drag torque at `point` to each active input: the swings and the
/// Sobol indices from `settings.samples` base samples (`samples (k + 2)` evaluations for `k`
/// active inputs), over the threads of `batch`.
pub fn sensitivity(
    batch: &Batch<'_>,
    point: &SweepPoint<'_>,
    settings: &BandSettings,
) -> Result<Sensitivity, BandError> {
    settings.validate().map_err(BandError::Setting)?;
    let points = core::slice::from_ref(point);
    check_spreads(points)?;
    let active = active_inputs(points);
    let ends = point_ends(batch, points, &active)?;
    let s = &ends[0];
    let (k, n) = (active.len(), settings.samples as usize);
    // Rows: A; B; A_B^(i) for each input (A with input i's column from B).
    let mut at = Vec::new();
    if k > 0 {
        let a = sample_positions(&active, settings.samples, settings.seed, 0);
        let b = sample_positions(&active, settings.samples, settings.seed, k as u32);
        at.extend_from_slice(&a);
        at.extend_from_slice(&b);
        for &i in &active {
            at.extend(a.iter().zip(&b).map(|(ra, rb)| {
                let mut r = *ra;
                r[i] = rb[i];
                r
            }));
        }
    }
    let drags: Vec<f64> = drags_from(batch, points, &at)?.into_iter().map(|row| row[0]).collect();
    let (fa, fb) = if k > 0 { (&drags[..n], &drags[n..2 * n]) } else { (&[][..], &[][..]) };
    let all: Vec<f64> = fa.iter().chain(fb).copied().collect();
    let variance_nm2 = variance(&all);
    let band = if k > 0 { quantiles(fa.to_vec(), settings, s.nominal_nm) } else { Band::at(s.nominal_nm) };
    let mut inputs: Vec<InputSensitivity> = active
        .iter()
        .enumerate()
        .map(|(j, &input)| {
            let fab = &drags[(2 + j) * n..(3 + j) * n];
            let (first_order, total) = if variance_nm2 > 0.0 {
                let s = (0..n).map(|r| fb[r] * (fab[r] - fa[r])).sum::<f64>() / n as f64 / variance_nm2;
                let st = (0..n).map(|r| (fa[r] - fab[r]).powi(2)).sum::<f64>() / (2 * n) as f64 / variance_nm2;
                (s, st)
            } else {
                (0.0, 0.0)
            };
            let [low_end_nm, high_end_nm] = s.end_nm[j];
            let half_width = point.model.spec().uncertainty.half_widths[input];
            InputSensitivity { input, half_width, low_end_nm, high_end_nm, first_order, total }
        })
        .collect();
    inputs.sort_by(|a, b| b.swing_nm().total_cmp(&a.swing_nm()).then(a.input.cmp(&b.input)));
    Ok(Sensitivity { nominal_nm: s.nominal_nm, variance_nm2, band, inputs })
}

/// The variance of `x` (divided by its length; 0 for fewer than two values).
fn variance(x: &[f64]) -> f64 {
    if x.len() < 2 {
        return 0.0;
    }
    let mean = x.iter().sum::<f64>() / x.len() as f64;
    x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / x.len() as f64
}
