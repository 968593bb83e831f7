//! Diagnosis of measured torques: where the creep model is wrong, which physical term is
//! missing, and what the extended model gains on data its fit never saw.
//!
//! 1. Calibration of the level, first: the model's level parameters within their physical
//!    ranges (the friction coefficient f of the dry model; the lubricant's full-film traction
//!    [`creep_cache::FULL_FILM_TRACTION_RANGE`] and boundary friction
//!    [`creep_cache::BOUNDARY_FRICTION_RANGE`] of the lubricated one, which carry the level at high
//!    and at low speed; see [`creep_cache::Level`]) and the reduction factor kappa on Kalker's creep
//!    coefficients (tried at 1, 0.5, 0.25 when the data has at least three preloads, kept only
//!    when the BIC falls by at least 10); then a level factor on the model's friction
//!    ([`model::LEVEL_FACTOR_RANGE`]), kept only by the selection's rule ([`select::cuts`]) and
//!    read back into the oil's friction coefficients ([`LevelFinding`]): a level the physical
//!    parameters cannot carry is reported as "the model is k times below (or above) this
//!    screw", never handed to a named term nor fitted out of a physical range.
//! 2. What the calibrated model gets wrong: bias along the motion (each direction apart), RMSE,
//!    held-out RMSE, the level ratio measured/model with its interval, and the residual against
//!    every column present (signed with the direction of motion, so that a missing drag shows
//!    with one sign in both directions).
//! 3. Candidates (`terms`), each evaluated only when the data can show it, added by the rule
//!    of [`select`]; "no missing effect found" when none passes. A round's fits (each
//!    candidate's held-out folds and its fit on every row) run over the machine's cores, each
//!    taken by the next free thread; a fit depends on nothing but its rows and the model's
//!    tables, so it is the same whatever thread runs it. (The tables come from batches of the
//!    model over the cores, each point to the evaluator's 1e-8 of the model: see
//!    `ballscrew_batch`.)
//! 4. What remains: trends and serial correlation of the extended model's residual along each
//!    column, reported without a name.
//!
//! [`diagnose_cancellable`] is the same diagnosis stopped midway when its caller sets a flag
//! (Ctrl-C of an interactive session, a deadline): the flag is read before each evaluation of
//! the model at one operating point and before each fit of the selection, so the call returns
//! [`DiagnoseError::Cancelled`] within about one evaluation (milliseconds) of the flag's being
//! set.
//! [`diagnose_with_progress`] is the same again, telling its caller how far it has come
//! ([`Progress`]: steps done of a total fixed at its start), for a progress bar; the crate draws
//! nothing itself.
//!
//! A crate of its own: it needs `std` and allocation, which the no_std core never does. It
//! reads spec files through `ballscrew-config` and evaluates the core's model; the terms
//! themselves live in the core ([`ballscrew_core::input::extensions`]).

extern crate alloc;

pub mod creep_cache;
pub mod data;
pub mod fit;
pub mod model;
pub mod outcome;
pub mod report;
pub mod residual;
pub mod select;
pub mod terms;
pub mod text;

use ballscrew_core::input::ScrewSpec;
use ballscrew_core::screw::inertia;
use core::cell::{Cell, RefCell};
use core::fmt;
use core::sync::atomic::{AtomicBool, Ordering};
use creep_cache::{CreepCache, Level};
use data::{Column, DataError, Dataset};
use model::{Rows, Structure};
use residual::Dependence;
use select::Trial;
use terms::{Effect, Settings};

pub use outcome::{BandNarrowing, Calibrated, Finding, LevelFinding, Metrics, Reading, Series};
pub use report::Report;

/// Creep reductions tried by the calibration besides the spec's.
const KAPPAS: [f64; 2] = [0.5, 0.25];
/// Extent of the f grid below and above the first estimate (factors): the estimate is made
/// without any term, and a term can take over much of the torque (an axial-load or seal drag
/// absorbed by f at first).
const F_SPAN_DOWN: f64 = 6.0;
/// See [`F_SPAN_DOWN`].
const F_SPAN_UP: f64 = 4.0;
/// Most terms selected.
const MAX_TERMS: usize = 4;
/// Why the creep reduction has no standard error.
const ON_A_GRID: &str = "chosen among a few trial values by BIC, not fitted by least squares";
/// Why a parameter the final model does not have (a level factor not kept) has no standard
/// error.
const NOT_IN_THE_MODEL: &str = "not in the final model";

/// Why a diagnosis failed.
#[derive(Debug, Clone, PartialEq)]
pub enum DiagnoseError {
    /// The data.
    Data(DataError),
    /// The model could not be evaluated at the data's operating points.
    Model(String),
    /// The caller's cancellation flag was set before the diagnosis ended
    /// ([`diagnose_cancellable`]).
    Cancelled,
}

impl fmt::Display for DiagnoseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DiagnoseError::Data(e) => write!(f, "{e}"),
            DiagnoseError::Model(m) => write!(f, "{m}"),
            DiagnoseError::Cancelled => write!(f, "{}", creep_cache::CANCELLED),
        }
    }
}

impl core::error::Error for DiagnoseError {}

impl From<DataError> for DiagnoseError {
    fn from(e: DataError) -> Self {
        DiagnoseError::Data(e)
    }
}

/// The metrics of predictions `pred` against `meas` (N m), rows of signed speed `speed`
/// (any unit) and load torque `load` (N m), with the held-out RMSE `heldout`.
fn metrics(pred: &[f64], meas: &[f64], heldout: f64, speed: &[f64], load: &[f64]) -> Metrics {
    let along = |i: usize| (pred[i] - meas[i]) * if speed[i] < 0.0 { -1.0 } else { 1.0 };
    let mean_of = |keep: &dyn Fn(f64) -> bool| {
        let rows: Vec<f64> = (0..meas.len()).filter(|&i| keep(speed[i])).map(along).collect();
        if rows.is_empty() { f64::NAN } else { rows.iter().sum::<f64>() / rows.len() as f64 }
    };
    let n = meas.len().max(1) as f64;
    let rmse = (pred.iter().zip(meas).map(|(p, m)| (p - m).powi(2)).sum::<f64>() / n).sqrt();
    let (level_ratio, level_ratio_interval) = level_ratio(pred, meas, load);
    Metrics {
        bias_nm: mean_of(&|_| true),
        bias_forward_nm: mean_of(&|v| v > 0.0),
        bias_reverse_nm: mean_of(&|v| v < 0.0),
        rmse_nm: rmse,
        heldout_rmse_nm: heldout,
        level_ratio,
        level_ratio_interval,
    }
}

/// Measured over modelled drag (torque less the load torque `load`): the least-squares factor
/// `r = sum(m p) / sum(p^2)` through the origin and its 95 % interval `r +- 1.96 s / sqrt(sum
/// p^2)`, `s^2` the scatter about it over `n - 1` rows. NaN where the model has no drag.
fn level_ratio(pred: &[f64], meas: &[f64], load: &[f64]) -> (f64, (f64, f64)) {
    let drag = |v: &[f64], i: usize| v[i] - load[i];
    let n = meas.len();
    let den: f64 = (0..n).map(|i| drag(pred, i).powi(2)).sum();
    let r = (0..n).map(|i| drag(meas, i) * drag(pred, i)).sum::<f64>() / den;
    if !(den > 0.0) || !r.is_finite() || n < 2 {
        return (f64::NAN, (f64::NAN, f64::NAN));
    }
    let s2 = (0..n).map(|i| (drag(meas, i) - r * drag(pred, i)).powi(2)).sum::<f64>() / (n - 1) as f64;
    let half = 1.96 * (s2 / den).sqrt();
    (r, (r - half, r + half))
}

fn median(v: &[f64]) -> f64 {
    let mut s = v.to_vec();
    s.sort_by(f64::total_cmp);
    if s.is_empty() { f64::NAN } else { s[s.len() / 2] }
}

/// How far a diagnosis has come ([`diagnose_with_progress`]): `done` of `total` steps.
///
/// A step is one pass of the model over every distinct operating point of the data (the
/// calibration's tabulation: one evaluation per point) or one candidate term tried by the
/// selection (its held-out and full fits). Steps differ in time, so the count is no clock.
/// `total` is the most steps the diagnosis can take, fixed at its start; a selection that stops
/// before its last round, or a level grid clamped at its bounds, takes fewer, and the last report
/// of a diagnosis that succeeds is `done == total`. `done` only grows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress {
    /// Steps done.
    pub done: usize,
    /// Steps in all, at most.
    pub total: usize,
}

/// The steps of one diagnosis, reported to its caller as they are done.
struct Steps<'p> {
    report: RefCell<&'p mut dyn FnMut(Progress)>,
    done: Cell<usize>,
    total: Cell<usize>,
}

impl<'p> Steps<'p> {
    fn new(report: &'p mut dyn FnMut(Progress)) -> Self {
        Self { report: RefCell::new(report), done: Cell::new(0), total: Cell::new(0) }
    }

    /// Fixes the total and reports that nothing is done yet.
    fn plan(&self, total: usize) {
        self.total.set(total);
        self.tell();
    }

    /// One step done (never past the total).
    fn step(&self) {
        if self.done.get() < self.total.get() {
            self.done.set(self.done.get() + 1);
            self.tell();
        }
    }

    /// Every step done: the steps left out count as done.
    fn finish(&self) {
        if self.done.get() < self.total.get() {
            self.done.set(self.total.get());
            self.tell();
        }
    }

    fn tell(&self) {
        let p = Progress { done: self.done.get(), total: self.total.get() };
        if let Ok(mut report) = self.report.try_borrow_mut() {
            report(p);
        }
    }
}

/// Most candidate trials of the forward selection with `candidates` applicable terms: every
/// candidate not yet taken, in each of at most [`MAX_TERMS`] rounds.
fn trials_at_most(candidates: usize) -> usize {
    (0..MAX_TERMS.min(candidates)).map(|round| candidates - round).sum()
}

/// One part of a candidate's trial: a fold's held-out predictions, or the fit on every row.
enum Part {
    Fold(Vec<(usize, f64)>),
    Full(fit::Fit),
}

/// Diagnoses `data` against the screw `spec`.
pub fn diagnose(spec: &ScrewSpec, data: &Dataset) -> Result<Report, DiagnoseError> {
    run(spec, data, &AtomicBool::new(false), &mut |_| {})
}

/// Diagnoses `data` against the screw `spec` as [`diagnose`] does, unless `cancel` is set
/// (by another thread: a signal handler, a deadline) before it ends: then it stops within about
/// one evaluation of the model at one operating point (milliseconds) and returns
/// [`DiagnoseError::Cancelled`], whatever it had found by then. The flag is only read; once set
/// it is expected to stay set. A diagnosis that ends before the flag is set returns its result;
/// one that is given a flag already set returns `Cancelled` without evaluating the model.
pub fn diagnose_cancellable(spec: &ScrewSpec, data: &Dataset, cancel: &AtomicBool) -> Result<Report, DiagnoseError> {
    diagnose_with_progress(spec, data, cancel, &mut |_| {})
}

/// Diagnoses `data` against the screw `spec` as [`diagnose_cancellable`] does, calling
/// `progress` as it goes: first with nothing done and the total, then after each step (see
/// [`Progress`]; the steps of a round of the selection, one per candidate, whose fits run
/// together over the cores, are told together when the round ends), last, when it succeeds,
/// with every step done. `progress` is called on the caller's thread, between steps (a step
/// takes from milliseconds to about a second); it should return at once (draw a bar, store
/// the count).
pub fn diagnose_with_progress(
    spec: &ScrewSpec,
    data: &Dataset,
    cancel: &AtomicBool,
    progress: &mut dyn FnMut(Progress),
) -> Result<Report, DiagnoseError> {
    if cancel.load(Ordering::Relaxed) {
        return Err(DiagnoseError::Cancelled);
    }
    run(spec, data, cancel, progress)
}

/// The diagnosis; `Cancelled` when `cancel` is set by its end. A cancelled evaluation fails, and
/// a failure that the diagnosis passes over (a creep reduction that cannot be solved is not
/// tried) may change its course: the flag, which stays set, is read at the end, so that no
/// report of a cancelled run is returned.
fn run(
    spec: &ScrewSpec,
    data: &Dataset,
    cancel: &AtomicBool,
    progress: &mut dyn FnMut(Progress),
) -> Result<Report, DiagnoseError> {
    let steps = Steps::new(progress);
    let result = diagnosis(spec, data, cancel, &steps);
    if cancel.load(Ordering::Relaxed) {
        return Err(DiagnoseError::Cancelled);
    }
    if result.is_ok() {
        steps.finish();
    }
    result
}

fn diagnosis(spec: &ScrewSpec, data: &Dataset, cancel: &AtomicBool, progress: &Steps) -> Result<Report, DiagnoseError> {
    let cancelled = || if cancel.load(Ordering::Relaxed) { Err(DiagnoseError::Cancelled) } else { Ok(()) };
    let rows = Rows::new(data, &spec.operating);
    let (pre, ax, sp) = rows.physics_columns();
    let pass = || progress.step();
    let mut physics = CreepCache::new(spec, &pre, &ax, &sp).cancelled_by(cancel).watched_by(&pass);
    let meas = &rows.torque;
    let n = meas.len();
    let lead_mm = spec.geometry.lead_m * 1000.0;

    // What the data can show, and so the steps the diagnosis may take.
    let mut applicable: Vec<(Effect, Result<(), String>)> =
        terms::ALL.iter().map(|&e| (e, e.applicable(data, lead_mm))).collect();
    let shows = |effect: Effect| applicable.iter().any(|(e, a)| *e == effect && a.is_ok());
    let mut slopes = shows(Effect::PreloadLoss);
    let kappa_spec = spec.friction.creep_reduction;
    let mut kappas = vec![kappa_spec];
    if shows(Effect::PreloadLaw) {
        kappas.extend(KAPPAS.iter().copied().filter(|k| *k != kappa_spec));
    }
    // The lubricated model's preload shapes depend on the level (its offset and its traction
    // part fall differently with the preload): they are tabulated once, at the calibrated level
    // of the chosen creep reduction (the calibration itself needs none).
    let late_slopes = slopes && physics.level == Level::FullFilmTraction;
    progress.plan(
        1 + usize::from(physics.level == Level::FullFilmTraction)
            + kappas.len() * physics.passes_at_most(F_SPAN_DOWN * F_SPAN_UP, slopes && !late_slopes)
            + if late_slopes { physics.shape_passes() } else { 0 }
            + trials_at_most(applicable.iter().filter(|(_, a)| a.is_ok()).count()),
    );

    // The spec's model as it stands, and a first estimate of f from its near-proportionality.
    let (fr_spec, ax_spec) = physics.at_spec().map_err(DiagnoseError::Model)?;
    let spec_pred: Vec<f64> = (0..n).map(|i| ax_spec[i] + fr_spec[i]).collect();
    let num: f64 = (0..n).map(|i| (meas[i] - ax_spec[i]) * fr_spec[i]).sum();
    let den: f64 = fr_spec.iter().map(|v| v * v).sum();
    if !(den > 0.0) {
        return Err(DiagnoseError::Model(
            "the model predicts no friction at any row (zero preload or standstill everywhere)".into(),
        ));
    }
    let f_spec = spec.friction.coefficient;
    let level = physics.level;
    let level_spec = level.get(spec);
    let (level_min, level_max) = level.fit_bounds();
    let f_est = match level {
        Level::FrictionCoefficient => (f_spec * num / den).clamp(level_min, level_max),
        // The lubricated friction is an offset (boundary friction, rolling resistance) plus a
        // part close to proportional to mu_EHL: its slope per row from a second level.
        Level::FullFilmTraction => {
            let l1 = if 2.0 * level_spec <= level_max { 2.0 * level_spec } else { 0.5 * level_spec };
            let (fr1, _) = physics.at_level(l1).map_err(DiagnoseError::Model)?;
            let slope: Vec<f64> = (0..n).map(|i| (fr1[i] - fr_spec[i]) / (l1 - level_spec)).collect();
            let num: f64 = (0..n).map(|i| (meas[i] - ax_spec[i] - fr_spec[i]) * slope[i]).sum();
            let den: f64 = slope.iter().map(|v| v * v).sum();
            let est = level_spec + num / den;
            if den > 0.0 && est.is_finite() { est.clamp(level_min, level_max) } else { level_spec }
        }
    };
    physics.set_grid(f_est / F_SPAN_DOWN, f_est * F_SPAN_UP);
    physics.f_estimate = f_est;

    let torque_scale = (meas.iter().zip(&ax_spec).map(|(m, a)| (m - a).abs()).sum::<f64>() / n as f64).max(1e-12);
    let mut settings = Settings {
        reference_temperature_c: data.get(Column::TemperatureC).map_or(20.0, median),
        reference_preload_n: median(&pre),
        harmonic: 1,
        lead_m: spec.geometry.lead_m,
        torque_scale_nm: torque_scale,
        boundary_start: spec.lubricant.boundary_friction,
    };

    // Calibration: f, and kappa when the preloads can tell.
    let all: Vec<usize> = (0..n).collect();
    // (kappa, BIC, the fit without extension terms at that kappa)
    let mut best_kappa = (kappa_spec, f64::INFINITY, None);
    for (j, &k) in kappas.iter().enumerate() {
        cancelled()?;
        match physics.prepare(k, slopes && !late_slopes) {
            Ok(()) => {}
            // A reduced creep stiffness the model cannot solve at these points is not tried.
            Err(_) if j > 0 => continue,
            // The worn screw's preloads the model cannot solve: the preload loss is an
            // infeasible candidate, not the end of the diagnosis.
            Err(e) if slopes && !late_slopes && e != creep_cache::CANCELLED => {
                slopes = false;
                not_solvable(&mut applicable, &e);
                physics.prepare(k, false).map_err(DiagnoseError::Model)?;
            }
            Err(e) => return Err(DiagnoseError::Model(e)),
        }
        let s = Structure { physics: &physics, rows: &rows, kappa: k, level_factor: false, effects: vec![], settings };
        let fit = s.fit(&all, f_est);
        let b = select::bic(fit.rss, n, s.parameters() + usize::from(j > 0));
        let threshold = if j == 0 { 0.0 } else { select::MIN_DELTA_BIC };
        if j == 0 || b - best_kappa.1 <= threshold {
            best_kappa = (k, b, Some(fit));
        }
    }
    let kappa = best_kappa.0;
    if late_slopes {
        if let Some(fit) = &best_kappa.2 {
            physics.f_estimate = fit.x[0].exp();
        }
        match physics.prepare(kappa, true) {
            Ok(()) => {}
            Err(e) if e != creep_cache::CANCELLED => not_solvable(&mut applicable, &e),
            Err(e) => return Err(DiagnoseError::Model(e)),
        }
    }
    // From here on the physics is only read: its fits run on the machine's cores.
    let physics = physics.unwatched();
    let (fold, k) = select::folds(n, data.get(Column::Repeat));

    let structure = |effects: Vec<Effect>, settings: Settings, level_factor: bool| Structure {
        physics: &physics,
        rows: &rows,
        kappa,
        level_factor,
        effects,
        settings,
    };
    let speed: Vec<f64> = rows.op.iter().map(|o| o.speed_rad_s).collect();
    let load = &ax_spec;
    let metrics = |pred: &[f64], heldout: f64| metrics(pred, meas, heldout, &speed, load);

    // The physical calibration: the level parameter within its physical range, the creep
    // reduction.
    let physical = structure(vec![], settings, false);
    let physical_fit = best_kappa.2.unwrap_or_else(|| physical.fit(&all, f_est));
    let f_cal = physical_fit.x[0].exp();
    let grid = physics.f_range();
    let (physical_heldout, _) = select::heldout(&physical, &fold, k, f_cal);
    // From here on every fit starts where the physical calibration ended.
    settings.boundary_start = physical.boundary(&physical_fit.x);

    // The level factor, tried before any term: kept when it cuts the held-out RMSE by the
    // selection's rule.
    cancelled()?;
    let scaled = structure(vec![], settings, true);
    let scaled_fit = scaled.fit(&all, f_cal);
    let (scaled_heldout, _) = select::heldout(&scaled, &fold, k, f_cal);
    let factor_bic =
        select::bic(scaled_fit.rss, n, scaled.parameters()) - select::bic(physical_fit.rss, n, physical.parameters());
    let mut factor = select::cuts(scaled_heldout, factor_bic, physical_heldout);
    let factor_trial = (physical_heldout, scaled_heldout, factor_bic);

    // The level-calibrated model: the baseline every term is measured against.
    let (mut base_fit, mut base_heldout) =
        if factor { (scaled_fit, scaled_heldout) } else { (physical_fit.clone(), physical_heldout) };
    let mut base = structure(vec![], settings, factor);
    let mut base_pred = base.predict(&base_fit.x, &all);

    // Forward selection.
    let mut current: Vec<Effect> = Vec::new();
    let mut cur_fit = base_fit.clone();
    let mut cur_heldout = base_heldout;
    let mut steps: Vec<Vec<Trial>> = Vec::new();
    let mut accepted: Vec<(Effect, f64, f64, f64)> = Vec::new();
    while current.len() < MAX_TERMS {
        let cur = structure(current.clone(), settings, factor);
        if !current.contains(&Effect::RacewayWaviness)
            && let Some(pos) = data.get(Column::PositionMm)
        {
            let pred = cur.predict(&cur_fit.x, &all);
            let resid: Vec<f64> = (0..n).map(|i| meas[i] - pred[i]).collect();
            let pg = residual::periodogram(pos, &physics.motion, &resid, lead_mm, terms::MAX_HARMONIC);
            settings.harmonic = pg.iter().max_by(|a, b| a.1.total_cmp(&b.1)).map_or(1, |p| p.0);
        }
        let cur_bic = select::bic(cur_fit.rss, n, cur.parameters());
        let candidates: Vec<Effect> = applicable
            .iter()
            .filter(|(e, a)| a.is_ok() && !current.contains(e) && !current.iter().any(|c| c.excludes(*e)))
            .map(|(e, _)| *e)
            .collect();
        cancelled()?;
        // Each candidate's held-out folds and its fit on every row, all of them over the cores
        // (each a fit of its own, taken by the next free thread); the trials in the candidates'
        // order, whatever the threads.
        let structures: Vec<Structure> = candidates
            .iter()
            .map(|e| {
                let mut effects = current.clone();
                effects.push(*e);
                structure(effects, settings, factor)
            })
            .collect();
        let parts: Vec<(usize, Option<usize>)> =
            (0..structures.len()).flat_map(|c| (0..k).map(Some).chain([None]).map(move |j| (c, j))).collect();
        let part = |&(c, j): &(usize, Option<usize>)| {
            let s = &structures[c];
            Ok(match j {
                Some(j) => Part::Fold(select::fold_predictions(s, &fold, j, f_cal)),
                None => Part::Full(s.fit(&all, f_cal)),
            })
        };
        let cancel = creep_cache::Cancel(cancel);
        let batch = ballscrew_batch::Batch::new(parts.len()).stop(&cancel).start(ballscrew_batch::Start::Independent);
        let done = batch.map(&parts, || (), |p, _| part(p)).map_err(|e| match e {
            ballscrew_batch::BatchError::Stopped => DiagnoseError::Cancelled,
            // A fit cannot fail; a thread that ended abnormally is a bug.
            other => panic!("the candidates' trials: {other:?}"),
        })?;
        let mut trials = Vec::with_capacity(structures.len());
        let mut fits = Vec::with_capacity(structures.len());
        // Every result is a fit (a fit cannot fail: with the batch's first failure raised,
        // none is an error).
        let mut done = done.into_iter().flatten();
        for (s, e) in structures.iter().zip(&candidates) {
            let mut predictions = Vec::new();
            let mut full = None;
            for p in done.by_ref().take(k + 1) {
                match p {
                    Part::Fold(f) => predictions.extend(f),
                    Part::Full(f) => full = Some(f),
                }
            }
            let Some(full) = full else { unreachable!("every candidate's parts end with its full fit") };
            let (h, _) = select::heldout_rmse(s, predictions);
            trials.push(Trial {
                effect: *e,
                heldout_rmse_nm: h,
                heldout_before_nm: cur_heldout,
                delta_bic: select::bic(full.rss, n, s.parameters()) - cur_bic,
            });
            fits.push(full);
        }
        for _ in &trials {
            progress.step();
        }
        let pick = select::best(&trials).cloned();
        steps.push(trials);
        let Some(t) = pick.filter(|t| select::passes(t, cur_heldout)) else { break };
        accepted.push((t.effect, cur_heldout, t.heldout_rmse_nm, t.delta_bic));
        current.push(t.effect);
        // The accepted trial's fit on all rows is the new current fit.
        let at = steps.last().and_then(|tr| tr.iter().position(|x| x.effect == t.effect));
        cur_fit = match at {
            Some(i) => fits.swap_remove(i),
            None => structure(current.clone(), settings, factor).fit(&all, f_cal),
        };
        cur_heldout = t.heldout_rmse_nm;
    }
    // A level factor kept before the terms must still earn its place beside them (a term may
    // explain what looked like a level): without it, the final model must not do better than
    // the rule allows.
    if factor && !current.is_empty() {
        cancelled()?;
        let without = structure(current.clone(), settings, false);
        let fit = without.fit(&all, f_cal);
        let (h, _) = select::heldout(&without, &fold, k, f_cal);
        let with = structure(current.clone(), settings, true);
        let dbic = select::bic(cur_fit.rss, n, with.parameters()) - select::bic(fit.rss, n, without.parameters());
        if !select::cuts(cur_heldout, dbic, h) {
            factor = false;
            cur_fit = fit;
            cur_heldout = h;
            // The level-calibrated model is then the physical calibration.
            base = structure(vec![], settings, false);
            (base_fit, base_heldout) = (physical_fit.clone(), physical_heldout);
            base_pred = base.predict(&base_fit.x, &all);
        }
    }
    let baseline = metrics(&base_pred, base_heldout);
    let base_resid: Vec<f64> = (0..n).map(|i| base_pred[i] - meas[i]).collect();

    let ext_s = structure(current.clone(), settings, factor);
    let ext_pred = ext_s.predict(&cur_fit.x, &all);
    let extended = metrics(&ext_pred, cur_heldout);
    let ext_resid: Vec<f64> = (0..n).map(|i| ext_pred[i] - meas[i]).collect();
    let split = ext_s.split(&cur_fit.x);
    let findings: Vec<Finding> = accepted
        .iter()
        .map(|&(e, before, after, dbic)| {
            let p = split.iter().find(|(x, _)| *x == e).map_or(&[][..], |s| s.1);
            let parameters = e.report(p, &settings);
            Finding {
                effect: e,
                evidence: format!(
                    "{}: held-out RMSE {} -> {} ({:.0} % less), BIC {:+.0}",
                    e.meaning(),
                    text::torque_text(before),
                    text::torque_text(after),
                    100.0 * (1.0 - after / before),
                    dbic
                ),
                parameters,
                heldout_before_nm: before,
                heldout_after_nm: after,
                delta_bic: dbic,
            }
        })
        .collect();

    let columns = data.present();
    let operating: Vec<Column> =
        columns.iter().copied().filter(|c| !matches!(c, Column::TorqueNm | Column::Repeat)).collect();
    // Residuals signed with the direction of motion: a drag the model lacks shows with one sign
    // in both directions.
    let along_motion = |r: &[f64]| -> Vec<f64> {
        r.iter().zip(&rows.op).map(|(v, o)| v * ballscrew_core::contact::creep::direction(o.speed_rad_s)).collect()
    };
    let (base_motion, ext_motion) = (along_motion(&base_resid), along_motion(&ext_resid));
    let dependences: Vec<Dependence> =
        operating.iter().filter_map(|&c| data.get(c).map(|x| residual::dependence(c, x, &base_motion))).collect();
    let remaining: Vec<String> = operating
        .iter()
        .filter_map(|&c| data.get(c).map(|x| residual::dependence(c, x, &ext_motion)))
        .filter_map(|d| remaining_structure(&d, &ext_motion))
        .collect();
    let periodogram = data.get(Column::PositionMm).map(|pos| {
        let neg = |r: &[f64]| r.iter().map(|v| -v).collect::<Vec<f64>>();
        (
            residual::periodogram(pos, &physics.motion, &neg(&base_resid), lead_mm, terms::MAX_HARMONIC),
            residual::periodogram(pos, &physics.motion, &neg(&ext_resid), lead_mm, terms::MAX_HARMONIC),
        )
    });

    let mut extended_spec = *spec;
    let level_ext = f_cal_final(&cur_fit.x);
    level.set(&mut extended_spec, level_ext);
    let boundary_ext = ext_s.boundary(&cur_fit.x);
    extended_spec.lubricant.boundary_friction = boundary_ext;
    extended_spec.friction.creep_reduction = kappa;
    extended_spec.extensions = ext_s.extensions(&cur_fit.x);
    let gain = 1.0 - extended.heldout_rmse_nm / baseline.heldout_rmse_nm;
    let factor_value = ext_s.factor_interval(&cur_fit.x);
    let base_factor = if factor { base.factor(&base_fit.x) } else { 1.0 };

    // The standard errors of the extended model's level parameters (those written to the
    // calibrated spec), from its fit's curvature: level, boundary friction, level factor.
    let mut errors = ext_s.level_errors(&cur_fit.x).into_iter();
    let mut next_error = || match errors.next() {
        Some(Ok(se)) => (se, None),
        Some(Err(why)) => (f64::NAN, Some(why)),
        None => (f64::NAN, Some(NOT_IN_THE_MODEL)),
    };
    let level_error = next_error();
    let boundary_error = if physics.boundary_range().is_some() { next_error() } else { (f64::NAN, None) };
    let factor_error = if factor { next_error() } else { (f64::NAN, Some(NOT_IN_THE_MODEL)) };

    // The fitted physical parameters, their ranges, and what a value out of them means.
    let calibration = vec![
        Calibrated {
            name: level.name(),
            spec_field: level.field(),
            spec: level_spec,
            calibrated: f_cal_final(&base_fit.x),
            extended: level_ext,
            fit_bounds: grid,
            physical_range: level.physical_range(),
            standard_error: level_error.0,
            standard_error_note: level_error.1,
        },
        Calibrated {
            name: "creep_reduction",
            spec_field: "friction.creep_reduction",
            spec: kappa_spec,
            calibrated: kappa,
            extended: kappa,
            fit_bounds: (
                kappas.iter().copied().fold(f64::INFINITY, f64::min),
                kappas.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            ),
            physical_range: Some((0.0, 1.0)),
            standard_error: f64::NAN,
            standard_error_note: Some(ON_A_GRID),
        },
        Calibrated {
            name: "level_factor",
            spec_field: "extensions.level_factor.factor",
            spec: 1.0,
            calibrated: base_factor,
            extended: factor_value.map_or(1.0, |v| v.0),
            fit_bounds: model::LEVEL_FACTOR_RANGE,
            physical_range: None,
            standard_error: factor_error.0,
            standard_error_note: factor_error.1,
        },
    ];
    let mut calibration = calibration;
    if let Some(range) = physics.boundary_range() {
        calibration.push(Calibrated {
            name: "boundary_friction",
            spec_field: "lubricant.boundary_friction",
            spec: spec.lubricant.boundary_friction,
            calibrated: base.boundary(&base_fit.x),
            extended: boundary_ext,
            fit_bounds: range,
            physical_range: Some(creep_cache::BOUNDARY_FRICTION_RANGE),
            standard_error: boundary_error.0,
            standard_error_note: boundary_error.1,
        });
    }
    // The calibrated spec carries the fit's spread of the inputs it calibrated, and the band
    // of the drag torque at the data's median point says how much that narrowed it.
    extended_spec.uncertainty = calibrated_uncertainty(&spec.uncertainty, &calibration);
    cancelled()?;
    let band_narrowing = band_narrowing(spec, &extended_spec, &rows, cancel)?;
    let mut warnings = data.warnings.clone();
    // The balls' inertia, which the quasi-static model leaves out, where the data's points
    // reach it: the model's torque there is an extrapolation (the command line's and Python's
    // quasi-static warning).
    if let Some(w) = inertia::check(spec, spec.helix_angle_rad(), rows.op.iter().copied()) {
        warnings.push(format!("the data's operating points: {w}"));
    }
    if level == Level::FullFilmTraction {
        let c = &calibration[1];
        if kappas.len() > 1 && c.calibrated <= c.fit_bounds.0 && c.calibrated < kappa_spec {
            warnings.push(format!(
                "the calibrated creep reduction {} is the smallest value tried: the data may want a softer creep \
                 stiffness still",
                c.calibrated
            ));
        }
    }

    // The level: against the spec's model, and what carries it.
    let spec_metrics = metrics(&spec_pred, f64::NAN);
    let (lo, hi) = spec_metrics.level_ratio_interval;
    let differs = !(lo..=hi).contains(&1.0) && (spec_metrics.level_ratio - 1.0).abs() > outcome::LEVEL_TOLERANCE;
    let mut readings = Vec::new();
    let mut absorbed = true;
    let mut reading_rms_nm = f64::NAN;
    match factor_value {
        None => {
            for c in calibration.iter().filter(|c| c.name == level.name() || c.name == "boundary_friction") {
                readings.push(Reading {
                    name: c.name,
                    spec_field: c.spec_field,
                    spec: c.spec,
                    value: c.extended,
                    range: c.physical_range,
                });
            }
        }
        Some((k_value, _, _)) => {
            readings = match level {
                Level::FullFilmTraction => vec![
                    Reading {
                        name: "boundary_friction",
                        spec_field: "lubricant.boundary_friction",
                        spec: spec.lubricant.boundary_friction,
                        value: k_value * boundary_ext,
                        range: Some(creep_cache::BOUNDARY_FRICTION_RANGE),
                    },
                    Reading {
                        name: level.name(),
                        spec_field: level.field(),
                        spec: level_spec,
                        value: k_value * level_ext,
                        range: level.physical_range(),
                    },
                ],
                Level::FrictionCoefficient => vec![Reading {
                    name: level.name(),
                    spec_field: level.field(),
                    spec: level_spec,
                    value: k_value * level_ext,
                    range: Some(level.fit_bounds()),
                }],
            };
            absorbed = readings.iter().all(Reading::physical);
            if absorbed {
                // The model evaluated at the readings against the model times the factor, both
                // without terms, at every row.
                cancelled()?;
                let mut at = physics.clone();
                let values: Vec<f64> = readings.iter().map(|r| r.value).collect();
                let fr = at.friction_with(|s| {
                    s.friction.creep_reduction = kappa;
                    match level {
                        Level::FullFilmTraction => {
                            s.lubricant.boundary_friction = values[0];
                            s.lubricant.full_film_traction = values[1];
                        }
                        Level::FrictionCoefficient => s.friction.coefficient = values[0],
                    }
                });
                match fr {
                    Ok(fr) => {
                        let d2: f64 = (0..n)
                            .map(|i| (fr[i] - k_value * physics.row(kappa, level_ext, boundary_ext, i).0).powi(2))
                            .sum();
                        reading_rms_nm = (d2 / n as f64).sqrt();
                        absorbed = reading_rms_nm <= extended.rmse_nm;
                    }
                    Err(e) if e == creep_cache::CANCELLED => return Err(DiagnoseError::Cancelled),
                    Err(_) => absorbed = false,
                }
            }
        }
    }
    let level_finding = LevelFinding {
        spec_ratio: spec_metrics.level_ratio,
        spec_ratio_interval: spec_metrics.level_ratio_interval,
        differs,
        factor: factor_value,
        trial: factor_trial,
        readings,
        absorbed,
        reading_rms_nm,
    };
    // A factor within the level tolerance of 1 is no finding about the model's level (a preload
    // law's reference, for one, sets a constant of that order that the factor takes).
    let off = factor_value.is_some_and(|(k, _, _)| (k - 1.0).abs() > outcome::LEVEL_TOLERANCE);
    let level_off = (off && !absorbed).then(|| level_finding.sentence());
    Ok(Report {
        rows: n,
        columns,
        warnings,
        distinct_points: physics.points(),
        folds: k,
        spec_friction_coefficient: f_spec,
        spec_creep_reduction: kappa_spec,
        // f is fitted only by the dry model (under EHL it stays the spec's: it does not act
        // on the raceway contacts).
        friction_coefficient: if level == Level::FrictionCoefficient { f_cal_final(&base_fit.x) } else { f_spec },
        creep_reduction: kappa,
        spec_model: spec_metrics,
        baseline,
        residuals: dependences,
        candidates: applicable.into_iter().map(|(e, a)| (e, a.err())).collect(),
        steps,
        findings,
        extended,
        extended_friction_coefficient: extended_spec.friction.coefficient,
        lubrication: spec.model.lubrication,
        calibration,
        level: level_finding,
        level_off,
        gain,
        remaining,
        periodogram,
        series: Series {
            measured: meas.clone(),
            spec_model: spec_pred,
            baseline: base_pred,
            extended: ext_pred,
            columns: operating.iter().filter_map(|&c| data.get(c).map(|v| (c, v.to_vec()))).collect(),
        },
        extended_spec,
        band_narrowing,
    })
}

/// The `[uncertainty]` of a calibrated spec: `spec`'s, but each calibrated parameter that is an
/// uncertain input (the full-film traction, the boundary friction: absolute half-widths; the
/// dry model's friction coefficient: a relative one) spread uniformly with the variance of its
/// fit's estimate, its half-width `sqrt(3)` times its standard error ([`Calibrated::half_width`];
/// relative: over the value), capped to the key's valid range. A parameter without a standard
/// error (on a bound of its fit, a singular curvature) keeps `spec`'s spread.
pub fn calibrated_uncertainty(
    spec: &ballscrew_core::input::Uncertainty,
    calibration: &[Calibrated],
) -> ballscrew_core::input::Uncertainty {
    use ballscrew_core::input::UNCERTAIN_INPUTS;
    let mut u = *spec;
    for (i, h) in calibration.iter().filter_map(Calibrated::uncertain_input) {
        if h.is_finite() {
            let (lo, hi) = UNCERTAIN_INPUTS[i].range;
            u.half_widths[i] = h.clamp(lo, hi);
        }
    }
    u
}

/// The band of the drag torque (5-95 %, the default sample and seed) of `spec` and of
/// `calibrated` at the data's median operating point ([`BandNarrowing`]). A band that cannot
/// be computed is NaN with the reason; a cancellation ends the diagnosis.
fn band_narrowing(
    spec: &ScrewSpec,
    calibrated: &ScrewSpec,
    rows: &Rows,
    cancel: &AtomicBool,
) -> Result<BandNarrowing, DiagnoseError> {
    use ballscrew_batch::uncertainty::{BandError, BandSettings, band};
    let of = |f: &dyn Fn(&ballscrew_core::OperatingPoint) -> f64| median(&rows.op.iter().map(f).collect::<Vec<_>>());
    let op = ballscrew_core::OperatingPoint {
        speed_rad_s: of(&|o| o.speed_rad_s.abs()),
        preload_n: of(&|o| o.preload_n),
        axial_load_n: of(&|o| o.axial_load_n),
    };
    let settings = BandSettings::default();
    let stop = creep_cache::Cancel(cancel);
    let mut notes = Vec::new();
    let mut band_of = |s: &ScrewSpec, which: &str| -> Result<(f64, f64, f64), DiagnoseError> {
        let nan = (f64::NAN, f64::NAN, f64::NAN);
        let model = match ballscrew_core::Model::new(s) {
            Ok(m) => m,
            Err(e) => {
                notes.push(format!("the {which} spec's band: {e}"));
                return Ok(nan);
            }
        };
        let point = [ballscrew_batch::sweep::SweepPoint { op, model: &model }];
        let batch = ballscrew_batch::Batch::new(settings.samples as usize).stop(&stop);
        match band(&batch, &point, &settings) {
            Ok(b) => Ok((b[0].low_nm, b[0].median_nm, b[0].high_nm)),
            Err(BandError::Batch(ballscrew_batch::BatchError::Stopped)) => Err(DiagnoseError::Cancelled),
            Err(e) => {
                notes.push(format!("the {which} spec's band: {e}"));
                Ok(nan)
            }
        }
    };
    let spec_band = band_of(spec, "input")?;
    let calibrated_band = band_of(calibrated, "calibrated")?;
    Ok(BandNarrowing {
        speed_rpm: ballscrew_core::input::rad_s_to_rpm(op.speed_rad_s),
        preload_n: op.preload_n,
        axial_load_n: op.axial_load_n,
        spec_band,
        calibrated_band,
        note: (!notes.is_empty()).then(|| notes.join("; ")),
    })
}

/// Marks the preload loss as a candidate the model cannot evaluate: the worn screw's preloads
/// (the tabulated shares of the data's preloads) have no solution of the model.
fn not_solvable(applicable: &mut [(Effect, Result<(), String>)], why: &str) {
    for (e, a) in applicable.iter_mut() {
        if *e == Effect::PreloadLoss {
            *a = Err(format!("the model cannot be solved at the worn screw's reduced preloads ({why})"));
        }
    }
}

fn f_cal_final(x: &[f64]) -> f64 {
    x[0].exp()
}

/// A sentence when the extended model's residual still has structure along a column.
fn remaining_structure(d: &Dependence, resid: &[f64]) -> Option<String> {
    let n = resid.len() as f64;
    let limit = (3.0 / n.sqrt()).max(0.3);
    let mut what = Vec::new();
    if d.correlation.abs() > limit {
        what.push(format!("a trend (r = {:.2})", d.correlation));
    }
    if d.serial_correlation > limit.max(0.4) {
        what.push(format!("serial correlation {:.2} (neighbouring values alike)", d.serial_correlation));
    }
    (!what.is_empty())
        .then(|| format!("along {}: {} that no candidate of the library explains", d.column.name(), what.join(" and ")))
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::time::Duration;
    use data::Use;
    use std::time::Instant;

    /// Measured-like data of the built-in screw: its own torque (dry model) plus a running-time
    /// drift, at `n` preloads, both directions.
    fn data(n: usize) -> (ScrewSpec, Dataset) {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.model = ballscrew_core::input::ModelOptions::dry();
        let model = ballscrew_core::Model::new(&spec).unwrap();
        let mut columns: [(String, Vec<f64>); 4] =
            ["preload_n", "speed_rpm", "time_h", "torque_nm"].map(|c| (c.to_string(), Vec::new()));
        for i in 0..n {
            let preload = 1000.0 + 2000.0 * i as f64 / n as f64;
            let speed = if i % 2 == 0 { 100.0 } else { -100.0 };
            let op = ballscrew_core::OperatingPoint {
                speed_rad_s: ballscrew_core::input::rpm_to_rad_s(speed),
                preload_n: preload,
                axial_load_n: 0.0,
            };
            let t = model.torque(&op, &mut ballscrew_core::SolverState::new()).unwrap();
            let hours = 10.0 * i as f64;
            for (c, v) in columns.iter_mut().zip([preload, speed, hours, t * (1.0 - 1e-4 * hours)]) {
                c.1.push(v);
            }
        }
        (spec, Dataset::parse_columns(columns.to_vec(), &[], Use::Diagnosis).unwrap())
    }

    #[test]
    fn a_flag_set_before_the_call_cancels_it_without_evaluating_the_model() {
        let (spec, d) = data(12);
        let start = Instant::now();
        assert_eq!(diagnose_cancellable(&spec, &d, &AtomicBool::new(true)).unwrap_err(), DiagnoseError::Cancelled);
        assert!(start.elapsed() < Duration::from_millis(50), "{:?}", start.elapsed());
        assert_eq!(DiagnoseError::Cancelled.to_string(), "the diagnosis was cancelled");
        // Never set: the report of `diagnose` (compared as printed: it holds NaN).
        let free = diagnose_cancellable(&spec, &d, &AtomicBool::new(false)).unwrap();
        assert_eq!(format!("{free:?}"), format!("{:?}", diagnose(&spec, &d).unwrap()));
    }

    #[test]
    fn progress_counts_up_to_its_total_and_leaves_the_report_as_it_is() {
        let (spec, d) = data(12);
        let mut seen: Vec<Progress> = Vec::new();
        let r = diagnose_with_progress(&spec, &d, &AtomicBool::new(false), &mut |p| seen.push(p)).unwrap();
        assert_eq!(format!("{r:?}"), format!("{:?}", diagnose(&spec, &d).unwrap()));
        let total = seen[0].total;
        assert!(total > 10, "{seen:?}");
        assert_eq!(seen[0].done, 0);
        assert!(seen.iter().all(|p| p.total == total && p.done <= total), "{seen:?}");
        assert!(seen.windows(2).all(|w| w[1].done > w[0].done), "{seen:?}");
        assert_eq!(*seen.last().unwrap(), Progress { done: total, total });
        // Counted as they are done, not only at the end: most steps are reported one by one.
        assert!(seen.len() > total / 2, "{} reports of {total} steps", seen.len());
        // Cancelled: no report of every step done.
        let mut last = None;
        let e = diagnose_with_progress(&spec, &d, &AtomicBool::new(true), &mut |p| last = Some(p));
        assert_eq!((e.unwrap_err(), last), (DiagnoseError::Cancelled, None));
    }

    #[test]
    fn the_selection_tries_at_most_every_untaken_candidate_in_each_round() {
        assert_eq!(trials_at_most(0), 0);
        assert_eq!(trials_at_most(2), 2 + 1);
        assert_eq!(trials_at_most(7), 7 + 6 + 5 + 4);
    }

    #[test]
    fn a_flag_set_midway_stops_the_diagnosis_within_a_few_evaluations() {
        let (spec, d) = data(40);
        let start = Instant::now();
        let whole = diagnose(&spec, &d).unwrap();
        let uninterrupted = start.elapsed();
        assert!(whole.rows == 40);
        let cancel = AtomicBool::new(false);
        let after = uninterrupted / 4;
        let (result, stopped) = std::thread::scope(|s| {
            let run = s.spawn(|| {
                let r = diagnose_cancellable(&spec, &d, &cancel);
                (r, Instant::now())
            });
            std::thread::sleep(after);
            let set = Instant::now();
            cancel.store(true, Ordering::Relaxed);
            let (r, end) = run.join().unwrap();
            (r, end.saturating_duration_since(set))
        });
        assert_eq!(result.unwrap_err(), DiagnoseError::Cancelled);
        // One evaluation of the model at one point takes milliseconds.
        assert!(stopped < Duration::from_millis(100), "{stopped:?} after the flag (uninterrupted: {uninterrupted:?})");
    }
}
