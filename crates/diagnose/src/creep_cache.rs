//! The creep model's torque at every row, cached for fitting.
//!
//! The calibrated level parameter is the friction coefficient f of the dry contacts
//! (`lubrication = "dry"`) or the full-film traction coefficient `mu_EHL` of the lubricant
//! (`lubrication = "ehl"`, where f no longer acts on the raceway contacts); see [`Level`].
//!
//! The dry model's torque does not depend on the speed's magnitude above the standstill speed
//! (docs/model-notes.md item 12), and its friction part is close to proportional to f. So the
//! dry model is evaluated once per distinct (preload, axial load, direction) of the data, on a
//! grid of f (log-spaced nodes, ratio [`NODE_RATIO`]) around a first estimate, for each creep
//! reduction tried; between nodes the friction part over f is interpolated linearly in log f
//! (error well below 0.1 %). Rows below the standstill speed scale the friction by the
//! standstill factor.
//!
//! When the model's torque depends on the speed magnitude
//! ([`Model::torque_depends_on_speed_magnitude`], the lubricated model), the speed magnitude is
//! part of each point (exact values deduplicated, nothing rounded) and every point is evaluated
//! at its own speed (the model applies the standstill factor itself; rows at zero speed have no
//! friction). The lubricated friction part is an offset (boundary friction, rolling resistance)
//! plus a part close to proportional to `mu_EHL`: it is interpolated quadratically in `mu_EHL`
//! through the three nearest nodes (ratio [`NODE_RATIO_EHL`]; error below 0.1 %, a test), and
//! its preload shapes, which depend on the level (the offset and the traction part fall
//! differently with the preload), are tabulated at two levels either side of the calibrated
//! one (once the creep reduction is chosen) and interpolated linearly in `mu_EHL`.
//!
//! The lubricated model's boundary friction `mu_bl` is the second level parameter (every
//! raceway contact's friction coefficient is the blend of `mu_bl` and `mu_EHL` by its asperity
//! share): each level node is tabulated at three boundary frictions over
//! [`BOUNDARY_FRICTION_RANGE`] (its ends and their geometric mean) and interpolated
//! quadratically between them (error below 0.1 %, a test). The preload shapes below are
//! tabulated at the spec's boundary friction.
//!
//! The running-time term (`preload_loss`) needs the friction at a lower preload: per point it is
//! tabulated at [`PRELOAD_RATIOS`] of the preload (at the first estimate of the level) and
//! interpolated linearly in the ratio, as friction over ratio.

use alloc::collections::BTreeMap;
use ballscrew_core::Evaluator;
use ballscrew_core::contact::creep::{direction, standstill_factor};
use ballscrew_core::input::{Lubrication, OperatingPoint, ScrewSpec, rpm_to_rad_s};
use ballscrew_core::screw::model::{Model, SolverState};
use core::sync::atomic::{AtomicBool, Ordering};

/// The flag of a diagnosis nobody stops.
static NEVER: AtomicBool = AtomicBool::new(false);

/// A batch stopped by the diagnosis's cancellation flag.
pub(crate) struct Cancel<'c>(pub(crate) &'c AtomicBool);

impl ballscrew_batch::Stop for Cancel<'_> {
    fn stop(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }
}

/// What a [`CreepCache`] does after each pass of the model over every distinct point: how the
/// diagnosis counts its progress.
pub trait Watch {
    /// One pass done.
    fn pass(&self);
}

/// Nobody watches: nothing is done after a pass. A physics that nobody watches can be shared
/// between threads (its fits, once its tables are filled).
#[derive(Debug, Clone, Copy)]
pub struct Unwatched;

impl Watch for Unwatched {
    fn pass(&self) {}
}

/// A function called after each pass ([`CreepCache::watched_by`]).
#[derive(Clone, Copy)]
pub struct Watched<'c>(&'c dyn Fn());

impl Watch for Watched<'_> {
    fn pass(&self) {
        (self.0)();
    }
}

impl core::fmt::Debug for Watched<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("Watched")
    }
}

/// Ratio of neighbouring level nodes (dry model: f).
pub const NODE_RATIO: f64 = 1.5;
/// Ratio of neighbouring level nodes of the lubricated model (`mu_EHL`; quadratic
/// interpolation in `mu_EHL`).
pub const NODE_RATIO_EHL: f64 = 2.0;
/// Speed at which a point above the standstill speed is evaluated when the torque does not
/// depend on the speed magnitude, rpm (any would do).
const EVAL_SPEED_RPM: f64 = 100.0;
/// Smallest and largest friction coefficient the calibration may reach (the spec accepts down
/// to 0.005, where light balls may already lose their quasi-static state).
pub const F_MIN: f64 = 0.008;
/// See [`F_MIN`].
pub const F_MAX: f64 = 1.0;
/// Smallest and largest full-film traction coefficient the calibration may reach: its physical
/// range [`FULL_FILM_TRACTION_RANGE`]. A level the lubricated model cannot reach at a physical
/// traction is the level factor's (`model::LEVEL_FACTOR_RANGE`): a finding about the model's
/// level, not a traction pushed out of range.
pub const MU_EHL_MIN: f64 = FULL_FILM_TRACTION_RANGE.0;
/// See [`MU_EHL_MIN`].
pub const MU_EHL_MAX: f64 = FULL_FILM_TRACTION_RANGE.1;
/// Physical range of the full-film (EHL) traction coefficient of a mineral oil: measured
/// traction coefficients of mineral oils in rolling EHL contacts lie at about 0.02-0.06
/// (Harris & Kotzalas, *Rolling Bearing Analysis*, 5th ed., 2007, the traction of EHL
/// contacts; SKF's rolling bearings catalogue takes 0.05 for mineral oils in ball bearings,
/// Xu et al. 2015 use 0.03); with a margin either side, [0.01, 0.08]. A calibrated value
/// outside it says that the model's level is off, not that the oil is.
pub const FULL_FILM_TRACTION_RANGE: (f64, f64) = (0.01, 0.08);
/// Physical range of the boundary (asperity) friction coefficient `mu_bl` of steel raceways
/// under a mineral oil: SKF's "generally about 0.15" for the boundary sliding friction (SKF
/// rolling bearings catalogue, the SKF model for calculating the frictional moment; the core's
/// default), with a margin of a third either side, [0.1, 0.2]: the project's convention, not a
/// measured range. The diagnosis reads a level change through it (with the full-film traction)
/// and never fits it out of this range.
pub const BOUNDARY_FRICTION_RANGE: (f64, f64) = (0.1, 0.2);
/// Preload ratios at which the friction of a worn screw is tabulated (descending from 1).
pub const PRELOAD_RATIOS: [f64; 6] = [1.0, 0.8, 0.6, 0.4, 0.2, 0.05];

/// The parameter that sets the level of the model's friction in a calibration.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Level {
    /// `friction.coefficient` f: the dry contacts' friction (`lubrication = "dry"`).
    FrictionCoefficient,
    /// `lubricant.full_film_traction` `mu_EHL` (`lubrication = "ehl"`: the raceway contacts'
    /// friction is the mixed-lubrication coefficient, on which f has no effect).
    FullFilmTraction,
}

impl Level {
    /// The level parameter of `spec`'s model.
    pub fn of(spec: &ScrewSpec) -> Self {
        match spec.model.lubrication {
            Lubrication::Dry => Level::FrictionCoefficient,
            Lubrication::Ehl => Level::FullFilmTraction,
        }
    }

    /// Its value in `spec`.
    pub fn get(self, spec: &ScrewSpec) -> f64 {
        match self {
            Level::FrictionCoefficient => spec.friction.coefficient,
            Level::FullFilmTraction => spec.lubricant.full_film_traction,
        }
    }

    /// Sets it in `spec`.
    pub fn set(self, spec: &mut ScrewSpec, value: f64) {
        match self {
            Level::FrictionCoefficient => spec.friction.coefficient = value,
            Level::FullFilmTraction => spec.lubricant.full_film_traction = value,
        }
    }

    /// Its name in the report (and the spec field it is written to).
    pub fn name(self) -> &'static str {
        match self {
            Level::FrictionCoefficient => "friction_coefficient",
            Level::FullFilmTraction => "full_film_traction",
        }
    }

    /// The spec field it is written to.
    pub fn field(self) -> &'static str {
        match self {
            Level::FrictionCoefficient => "friction.coefficient",
            Level::FullFilmTraction => "lubricant.full_film_traction",
        }
    }

    /// Bounds of the fit.
    pub fn fit_bounds(self) -> (f64, f64) {
        match self {
            Level::FrictionCoefficient => (F_MIN, F_MAX),
            Level::FullFilmTraction => (MU_EHL_MIN, MU_EHL_MAX),
        }
    }

    /// The range a calibrated value must stay within to be physical, when one is stated: the
    /// dry model's f keeps its former behaviour (no range beyond the fit's bounds).
    pub fn physical_range(self) -> Option<(f64, f64)> {
        match self {
            Level::FrictionCoefficient => None,
            Level::FullFilmTraction => Some(FULL_FILM_TRACTION_RANGE),
        }
    }
}

/// One distinct operating point of the data.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Point {
    preload_n: f64,
    axial_load_n: f64,
    dir: f64,
    /// Speed magnitude the point is evaluated at, rad/s.
    speed_rad_s: f64,
}

/// Model friction per point on level nodes, for one creep reduction.
#[derive(Debug, Clone)]
struct Table {
    /// `value[b][node][point]`: friction over f (N m per unit f) for the dry model, friction
    /// (N m) for the lubricated one, at boundary-friction node `b` (one node, the spec's value,
    /// for the dry model).
    value: Vec<Vec<Vec<f64>>>,
    /// Friction at each of [`PRELOAD_RATIOS`] over (ratio times the friction at ratio 1), per
    /// point.
    shape: Vec<[f64; PRELOAD_RATIOS.len()]>,
    /// Whether `shape` is filled (else all ones).
    slopes: bool,
    /// Lubricated model: two levels and the friction at each of [`PRELOAD_RATIOS`] per point
    /// at each (the shape at another level interpolates them linearly in the level).
    levels: Option<Shapes>,
}

/// Friction at two levels and each preload ratio, per point.
#[derive(Debug, Clone)]
struct Shapes {
    at: [f64; 2],
    friction: [Vec<[f64; PRELOAD_RATIOS.len()]>; 2],
}

/// The cached model of one dataset.
///
/// Its evaluations stop at once when its cancellation flag ([`CreepCache::cancelled_by`]) is set:
/// every evaluation then fails, and the caller, which may pass over a failed evaluation,
/// reads the flag at its end ([`CreepCache::cancelled`]).
#[derive(Debug, Clone)]
pub struct CreepCache<'c, W = Unwatched> {
    spec: ScrewSpec,
    /// Set by the caller to stop the evaluations.
    cancel: &'c AtomicBool,
    /// Told of each pass over the points.
    pass: W,
    /// The calibrated level parameter.
    pub level: Level,
    /// Whether the model's torque depends on the speed magnitude (points carry their speed).
    pub speed_dependent: bool,
    points: Vec<Point>,
    /// Point of each row.
    pub row_point: Vec<usize>,
    /// Standstill factor times direction per row.
    pub motion: Vec<f64>,
    /// Factor on the point's friction per row: the standstill factor when points are evaluated
    /// above the standstill speed; 1 when each is evaluated at its own speed (0 at zero speed).
    scale: Vec<f64>,
    /// `F_a L / (2 pi)` per point (independent of the level).
    axial: Vec<f64>,
    /// Level of node 0 and number of nodes.
    f0: f64,
    nodes: usize,
    /// Level of each node (for the interpolation).
    grid: Vec<f64>,
    /// Boundary friction of each boundary node: three over [`CreepCache::boundary_range`] for the
    /// lubricated model (quadratic interpolation), the spec's value alone for the dry one.
    boundary: Vec<f64>,
    /// First estimate of the level (f or `mu_EHL`; where the preload shapes are tabulated).
    pub f_estimate: f64,
    tables: BTreeMap<u64, Table>,
    /// Warm-start memory per point: each evaluation starts from the last solution at the same
    /// point (a neighbouring level, kappa or preload), not from the previous point.
    states: Vec<SolverState>,
    /// The control-loop evaluator of the last evaluation's model (with many points, see
    /// [`CreepCache::evaluate`]).
    evaluator: Option<Box<Evaluator<f64>>>,
}

/// Why the model could not be evaluated.
pub type PhysicsError = String;

/// The [`PhysicsError`] of an evaluation stopped by the cancellation flag.
pub const CANCELLED: &str = "the diagnosis was cancelled";

impl CreepCache<'static> {
    /// Groups the rows (preload N, axial load N, speed rpm per row) into distinct points.
    pub fn new(spec: &ScrewSpec, preload: &[f64], axial: &[f64], speed_rpm: &[f64]) -> Self {
        let mut base = *spec;
        base.extensions = ballscrew_core::input::extensions::Extensions::NONE;
        // A spec the model rejects depends on nothing; the error shows at the first evaluation.
        let speed_dependent = Model::new(&base).is_ok_and(|m| m.torque_depends_on_speed_magnitude());
        let mut points: Vec<Point> = Vec::new();
        let mut index: BTreeMap<(u64, u64, bool, u64), usize> = BTreeMap::new();
        let mut row_point = Vec::with_capacity(preload.len());
        let mut motion = Vec::with_capacity(preload.len());
        let mut scale = Vec::with_capacity(preload.len());
        let w0 = spec.friction.standstill_speed_rad_s;
        for i in 0..preload.len() {
            let w = rpm_to_rad_s(speed_rpm[i]);
            let factor = standstill_factor(w, w0);
            // At zero speed the model has no friction: such rows share the point at the
            // standstill speed, scaled by zero.
            let (speed, s) = if !speed_dependent {
                (rpm_to_rad_s(EVAL_SPEED_RPM), factor)
            } else if w.abs() > 0.0 {
                (w.abs(), 1.0)
            } else {
                (w0, 0.0)
            };
            let p = Point { preload_n: preload[i], axial_load_n: axial[i], dir: direction(w), speed_rad_s: speed };
            let key = (p.preload_n.to_bits(), p.axial_load_n.to_bits(), p.dir > 0.0, speed.to_bits());
            let k = *index.entry(key).or_insert_with(|| {
                points.push(p);
                points.len() - 1
            });
            row_point.push(k);
            motion.push(direction(w) * factor);
            scale.push(s);
        }
        let level = Level::of(spec);
        let spec_boundary = spec.lubricant.boundary_friction;
        let boundary = match level {
            Level::FullFilmTraction => {
                let (lo, hi) = boundary_range_of(spec_boundary);
                vec![lo, (lo * hi).sqrt(), hi]
            }
            Level::FrictionCoefficient => vec![spec_boundary],
        };
        Self {
            spec: *spec,
            cancel: &NEVER,
            pass: Unwatched,
            level,
            speed_dependent,
            points,
            row_point,
            motion,
            scale,
            axial: Vec::new(),
            f0: level.fit_bounds().0,
            nodes: 0,
            grid: Vec::new(),
            boundary,
            f_estimate: level.get(spec),
            tables: BTreeMap::new(),
            states: Vec::new(),
            evaluator: None,
        }
    }
}

impl<'c, W: Watch> CreepCache<'c, W> {
    /// The same physics, its evaluations stopped once `cancel` is set (see [`CreepCache`]).
    pub fn cancelled_by<'d>(self, cancel: &'d AtomicBool) -> CreepCache<'d, W>
    where
        'c: 'd,
    {
        CreepCache { cancel, ..self }
    }

    /// The same physics, calling `pass` after each evaluation of the model over every distinct
    /// point (each pass takes one evaluation per point: about a millisecond each).
    pub fn watched_by<'d>(self, pass: &'d dyn Fn()) -> CreepCache<'d, Watched<'d>>
    where
        'c: 'd,
    {
        self.told(Watched(pass))
    }

    /// The same physics, watched by nobody: it can then be shared between threads.
    pub fn unwatched(self) -> CreepCache<'c> {
        self.told(Unwatched)
    }

    /// The same physics, `pass` told of each pass.
    fn told<V: Watch>(self, pass: V) -> CreepCache<'c, V> {
        CreepCache {
            spec: self.spec,
            cancel: self.cancel,
            pass,
            level: self.level,
            speed_dependent: self.speed_dependent,
            points: self.points,
            row_point: self.row_point,
            motion: self.motion,
            scale: self.scale,
            axial: self.axial,
            f0: self.f0,
            nodes: self.nodes,
            grid: self.grid,
            boundary: self.boundary,
            f_estimate: self.f_estimate,
            tables: self.tables,
            states: self.states,
            evaluator: self.evaluator,
        }
    }

    /// Most passes over the points that [`CreepCache::set_grid`] over a span of `span` (the ratio
    /// of its ends) and [`CreepCache::prepare`] of one creep reduction take: the level nodes, and
    /// with `slopes` the preload shapes (a failing lowest node takes one pass fewer). Each level
    /// node is a pass at each boundary-friction node.
    pub fn passes_at_most(&self, span: f64, slopes: bool) -> usize {
        self.nodes_over(span) * self.boundary.len() + if slopes { self.shape_passes() } else { 0 }
    }

    /// Passes over the points that the preload shapes take: every ratio of [`PRELOAD_RATIOS`],
    /// at one level (dry) or at two (lubricated).
    pub fn shape_passes(&self) -> usize {
        match self.level {
            Level::FrictionCoefficient => PRELOAD_RATIOS.len(),
            Level::FullFilmTraction => 2 * PRELOAD_RATIOS.len(),
        }
    }

    /// Whether the cancellation flag is set.
    pub fn cancelled(&self) -> bool {
        self.cancel.load(Ordering::Relaxed)
    }

    /// Ratio of neighbouring level nodes.
    fn ratio(&self) -> f64 {
        match self.level {
            Level::FrictionCoefficient => NODE_RATIO,
            Level::FullFilmTraction => NODE_RATIO_EHL,
        }
    }

    /// Nodes of a grid whose ends are `span` apart (a ratio).
    fn nodes_over(&self, span: f64) -> usize {
        1 + (span.ln() / self.ratio().ln()).ceil().max(1.0) as usize
    }

    /// Level of node `k`.
    fn node(&self, k: usize) -> f64 {
        (self.f0 * self.ratio().powi(k as i32)).min(self.level.fit_bounds().1)
    }

    /// Number of distinct points.
    pub fn points(&self) -> usize {
        self.points.len()
    }

    /// The spec (its level and creep reduction are the ones given, not the fitted ones).
    pub fn spec(&self) -> &ScrewSpec {
        &self.spec
    }

    /// The drag torque and the load torque (N m) of every distinct point at level `f`, creep
    /// reduction `kappa` and the points' preloads times `preload_scale`. With at least
    /// [`ballscrew_batch::EVALUATOR_MIN_POINTS`] points by the control-loop evaluator over the
    /// cores (`Batch::torques` with `Start::Warm`, one evaluator per model, within 1e-8 of the
    /// model's canonical state but where a ball has two steady states, docs/model-notes.md
    /// item 24);
    /// with fewer, by the model, each point warm-started from its own last solution.
    fn evaluate(&mut self, f: f64, kappa: f64, preload_scale: f64) -> Result<(Vec<f64>, Vec<f64>), PhysicsError> {
        self.evaluate_at(f, self.spec.lubricant.boundary_friction, kappa, preload_scale)
    }

    /// [`CreepCache::evaluate`] at boundary friction `boundary` (no effect on the dry model).
    fn evaluate_at(
        &mut self,
        f: f64,
        boundary: f64,
        kappa: f64,
        preload_scale: f64,
    ) -> Result<(Vec<f64>, Vec<f64>), PhysicsError> {
        let mut spec = self.spec;
        self.level.set(&mut spec, f);
        spec.lubricant.boundary_friction = boundary;
        spec.friction.creep_reduction = kappa;
        self.evaluate_spec(spec, preload_scale)
    }

    /// The range the boundary friction is fitted within, when it is fitted (the lubricated
    /// model): [`BOUNDARY_FRICTION_RANGE`], widened to the spec's own value.
    pub fn boundary_range(&self) -> Option<(f64, f64)> {
        (self.boundary.len() > 1).then(|| boundary_range_of(self.spec.lubricant.boundary_friction))
    }

    /// [`CreepCache::evaluate`] of `spec` as given (its level and creep reduction).
    fn evaluate_spec(&mut self, mut spec: ScrewSpec, preload_scale: f64) -> Result<(Vec<f64>, Vec<f64>), PhysicsError> {
        spec.extensions = ballscrew_core::input::extensions::Extensions::NONE;
        let (f, kappa) = (self.level.get(&spec), spec.friction.creep_reduction);
        let model = Model::new(&spec).map_err(|e| format!("the spec cannot be evaluated: {e}"))?;
        let mut friction = Vec::with_capacity(self.points.len());
        let mut axial = Vec::with_capacity(self.points.len());
        let name = self.level.name();
        let ops: Vec<OperatingPoint> = self
            .points
            .iter()
            .map(|p| OperatingPoint {
                speed_rad_s: p.dir * p.speed_rad_s,
                preload_n: p.preload_n * preload_scale,
                axial_load_n: p.axial_load_n,
            })
            .collect();
        let fails = |op: &OperatingPoint, e: &ballscrew_core::Error| {
            format!(
                "the model fails at preload {} N, axial load {} N, speed {:.4} rpm, {name} = {f:.4}, creep reduction {kappa}: {e}",
                op.preload_n,
                op.axial_load_n,
                ballscrew_core::input::rad_s_to_rpm(op.speed_rad_s)
            )
        };
        if ops.len() >= ballscrew_batch::EVALUATOR_MIN_POINTS {
            let stop = Cancel(self.cancel);
            // One evaluator per model (level and creep reduction), kept for the preload shapes.
            // (A table carried over from the last level's by Newton's method leaves out the
            // entries whose balls change most, and the points among them fall back to the
            // continuation: measured slower than a table of its own.)
            if !self.evaluator.as_ref().is_some_and(|ev| ev.model() == &model) {
                self.evaluator = Evaluator::new(&model).ok().map(Box::new);
            }
            let ev = self.evaluator.as_deref();
            let torques = ballscrew_batch::Batch::new(ops.len())
                .stop(&stop)
                .start(ballscrew_batch::Start::Warm)
                .torques(&model, ev, &ops, None)
                .map_err(|e| match e {
                    ballscrew_batch::BatchError::Point { index, error } => fails(&ops[index], &error),
                    ballscrew_batch::BatchError::Stopped => CANCELLED.to_string(),
                    other => format!("the model's evaluation stopped: {other:?}"),
                })?;
            for (op, t) in ops.iter().zip(torques) {
                let load = model.load_torque_nm(op);
                friction.push(t.map_err(|e| fails(op, &e))? - load);
                axial.push(load);
            }
            self.pass.pass();
            return Ok((friction, axial));
        }
        // The warm-start memory of each point, kept from call to call (the model's path only).
        if self.states.len() != ops.len() {
            self.states = vec![SolverState::new(); ops.len()];
        }
        for (op, state) in ops.iter().zip(self.states.iter_mut()) {
            if self.cancel.load(Ordering::Relaxed) {
                return Err(CANCELLED.to_string());
            }
            let s = model.summary(op, state).map_err(|e| fails(op, &e))?;
            friction.push(s.drag_torque_nm());
            axial.push(s.load_torque_nm());
        }
        self.pass.pass();
        Ok((friction, axial))
    }

    /// Sets the level grid to span `f_lo..f_hi` (clamped to the level's fit bounds).
    pub fn set_grid(&mut self, f_lo: f64, f_hi: f64) {
        let (min, max) = self.level.fit_bounds();
        let lo = f_lo.clamp(min, max);
        let hi = f_hi.clamp(lo, max);
        self.nodes = self.nodes_over(hi / lo);
        // The top node at most the upper bound: the grid shifts down (not below the lower
        // bound) when it would pass.
        self.f0 = (max / self.ratio().powi(self.nodes as i32 - 1)).min(lo).max(min);
        self.tables.clear();
        self.grid = (0..self.nodes).map(|k| self.node(k)).collect();
    }

    /// The level range the grid covers.
    pub fn f_range(&self) -> (f64, f64) {
        let max = self.level.fit_bounds().1;
        (self.f0, (self.f0 * self.ratio().powi(self.nodes.saturating_sub(1) as i32)).min(max))
    }

    /// Model torque per row at `level` and the spec's creep reduction, N m (friction and axial
    /// term).
    pub fn at_level(&mut self, level: f64) -> Result<(Vec<f64>, Vec<f64>), PhysicsError> {
        let (fr, ax) = self.evaluate(level, self.spec.friction.creep_reduction, 1.0)?;
        self.axial = ax.clone();
        let rows = self.row_point.len();
        Ok((
            (0..rows).map(|i| fr[self.row_point[i]] * self.scale[i]).collect(),
            (0..rows).map(|i| ax[self.row_point[i]]).collect(),
        ))
    }

    /// Model torque per row at the spec's level and creep reduction, N m (friction and axial
    /// term).
    pub fn at_spec(&mut self) -> Result<(Vec<f64>, Vec<f64>), PhysicsError> {
        self.at_level(self.level.get(&self.spec))
    }

    /// Model friction per row (N m, with the row's standstill factor, signed) of the spec with
    /// `change` made to it (a lubricant's friction coefficients, a creep reduction): one pass
    /// over the points, no table.
    pub fn friction_with(&mut self, change: impl FnOnce(&mut ScrewSpec)) -> Result<Vec<f64>, PhysicsError> {
        let mut spec = self.spec;
        change(&mut spec);
        let (fr, _) = self.evaluate_spec(spec, 1.0)?;
        Ok((0..self.row_point.len()).map(|i| fr[self.row_point[i]] * self.scale[i]).collect())
    }

    /// Fills the table of creep reduction `kappa` (every level node, and the preload slopes
    /// when `slopes`).
    pub fn prepare(&mut self, kappa: f64, slopes: bool) -> Result<(), PhysicsError> {
        let key = kappa.to_bits();
        if let Some(t) = self.tables.get(&key) {
            if slopes && !t.slopes {
                let (shape, levels) = self.shapes(kappa)?;
                if let Some(t) = self.tables.get_mut(&key) {
                    t.shape = shape;
                    t.levels = levels;
                    t.slopes = true;
                }
            }
            return Ok(());
        }
        let per_unit = self.level == Level::FrictionCoefficient;
        let mut value: Vec<Vec<Vec<f64>>> = vec![Vec::with_capacity(self.nodes); self.boundary.len()];
        let mut k = 0;
        while k < self.nodes {
            let f = self.node(k);
            // Every boundary node at this level, or the level fails as a whole.
            let at_level: Result<Vec<Vec<f64>>, PhysicsError> = self
                .boundary
                .clone()
                .into_iter()
                .map(|b| {
                    let (fr, ax) = self.evaluate_at(f, b, kappa, 1.0)?;
                    self.axial = ax;
                    Ok(if per_unit { fr.iter().map(|t| t / f).collect::<Vec<f64>>() } else { fr })
                })
                .collect();
            match at_level {
                Ok(frictions) => {
                    for (v, fr) in value.iter_mut().zip(frictions) {
                        v.push(fr);
                    }
                    k += 1;
                }
                // At the lowest friction coefficients light balls may have no quasi-static
                // state (every contact in full slip): the grid starts one node higher.
                Err(_) if k == 0 && self.tables.is_empty() && self.nodes > 2 => {
                    self.f0 *= self.ratio();
                    self.nodes -= 1;
                    self.grid = (0..self.nodes).map(|k| self.node(k)).collect();
                }
                // A level the model cannot solve at these points is a level the fit cannot
                // reach: the grid ends below it (the first table only, which sets the grid;
                // its fits stay within it, so none of them ever reaches it).
                Err(e) if e != CANCELLED && k >= 2 && self.tables.is_empty() => {
                    self.nodes = k;
                    self.grid.truncate(k);
                    for v in &mut value {
                        v.truncate(k);
                    }
                }
                Err(e) => return Err(e),
            }
        }
        let (shape, levels) =
            if slopes { self.shapes(kappa)? } else { (vec![[1.0; PRELOAD_RATIOS.len()]; self.points.len()], None) };
        self.tables.insert(key, Table { value, shape, slopes, levels });
        Ok(())
    }

    /// The preload shapes of every point at [`CreepCache::f_estimate`] and `kappa`; for the
    /// lubricated model the frictions at two levels either side of it instead.
    #[allow(clippy::type_complexity)]
    fn shapes(&mut self, kappa: f64) -> Result<(Vec<[f64; PRELOAD_RATIOS.len()]>, Option<Shapes>), PhysicsError> {
        let mut shape = vec![[1.0; PRELOAD_RATIOS.len()]; self.points.len()];
        let (lo, hi) = self.f_range();
        if self.level == Level::FullFilmTraction {
            let at = [(self.f_estimate / 1.5).clamp(lo, hi), (self.f_estimate * 1.5).clamp(lo, hi)];
            let mut friction = [shape.clone(), shape.clone()];
            for (l, &f) in at.iter().enumerate() {
                for (j, &ratio) in PRELOAD_RATIOS.iter().enumerate() {
                    let (fr, _) = self.evaluate(f, kappa, ratio)?;
                    for p in 0..self.points.len() {
                        friction[l][p][j] = fr[p];
                    }
                }
            }
            return Ok((shape, Some(Shapes { at, friction })));
        }
        let f = self.f_estimate.clamp(lo, hi);
        let (full, _) = self.evaluate(f, kappa, 1.0)?;
        for (j, &ratio) in PRELOAD_RATIOS.iter().enumerate().skip(1) {
            let (low, _) = self.evaluate(f, kappa, ratio)?;
            for p in 0..self.points.len() {
                shape[p][j] = if full[p] != 0.0 { low[p] / (ratio * full[p]) } else { 1.0 };
            }
        }
        Ok((shape, None))
    }

    /// Friction at `ratio` of the preload over the friction at the full preload, point of row
    /// `i` (tables of `prepare(kappa, true)`).
    pub fn worn(&self, kappa: f64, f: f64, i: usize, ratio: f64) -> f64 {
        let t = &self.tables[&kappa.to_bits()];
        let p = self.row_point[i];
        let g = match &t.levels {
            None => t.shape[p],
            Some(s) => {
                let w = if s.at[1] > s.at[0] { (f - s.at[0]) / (s.at[1] - s.at[0]) } else { 0.0 };
                let fr = |j: usize| (1.0 - w) * s.friction[0][p][j] + w * s.friction[1][p][j];
                let full = fr(0);
                core::array::from_fn(|j| if full != 0.0 { fr(j) / (PRELOAD_RATIOS[j] * full) } else { 1.0 })
            }
        };
        let r = &PRELOAD_RATIOS;
        let j = (1..r.len()).find(|&j| ratio >= r[j]).unwrap_or(r.len() - 1);
        if t.levels.is_some() {
            // Lubricated: quadratic in the ratio through the three nearest ratios (the friction
            // over the ratio bends more than the dry model's), not beyond the table.
            let ratio = ratio.clamp(r[r.len() - 1], r[0]);
            let j0 = if j == 1 || (j + 1 < r.len() && ratio < 0.5 * (r[j - 1] + r[j])) { j - 1 } else { j - 2 };
            let j0 = j0.min(r.len() - 3);
            let l = |a: usize| -> f64 {
                (j0..j0 + 3).filter(|&b| b != a).map(|b| (ratio - r[b]) / (r[a] - r[b])).product()
            };
            return ratio * (j0..j0 + 3).map(|a| l(a) * g[a]).sum::<f64>();
        }
        let w = ((r[j - 1] - ratio) / (r[j - 1] - r[j])).clamp(0.0, 1.0);
        ratio * ((1.0 - w) * g[j - 1] + w * g[j])
    }

    /// The model at level `f`, boundary friction `boundary` (lubricated model; the dry model
    /// has none) and `kappa` (prepared) for row `i`: (friction part with the row's standstill
    /// factor, signed with the direction; axial term). Quadratic in the boundary friction
    /// through its three nodes (the contacts' mixed friction coefficient is linear in it).
    pub fn row(&self, kappa: f64, f: f64, boundary: f64, i: usize) -> (f64, f64) {
        let t = &self.tables[&kappa.to_bits()];
        let p = self.row_point[i];
        let b = &self.boundary;
        let fr = if b.len() == 3 {
            (0..3)
                .map(|a| {
                    let l: f64 = (0..3).filter(|&c| c != a).map(|c| (boundary - b[c]) / (b[a] - b[c])).product();
                    l * self.along_level(&t.value[a], f, p)
                })
                .sum()
        } else {
            self.along_level(&t.value[0], f, p)
        };
        (fr * self.scale[i], self.axial[p])
    }

    /// The friction of point `p` at level `f` from one boundary node's values `v[node][point]`.
    fn along_level(&self, v: &[Vec<f64>], f: f64, p: usize) -> f64 {
        let x = ((f / self.f0).ln() / self.ratio().ln()).clamp(0.0, (self.nodes - 1) as f64);
        let k = (x.floor() as usize).min(self.nodes.saturating_sub(2));
        if self.nodes == 1 {
            let v = v[0][p];
            return if self.level == Level::FrictionCoefficient { v * f } else { v };
        }
        // The table holds signed friction (negative in reverse).
        match self.level {
            Level::FrictionCoefficient => {
                let w = x - k as f64;
                ((1.0 - w) * v[k][p] + w * v[k + 1][p]) * f
            }
            // Quadratic in mu_EHL through the three nodes nearest (Lagrange; linear with two
            // nodes). The fit's bounds are the grid's: no extrapolation.
            Level::FullFilmTraction => {
                let m = self.nodes.min(3);
                let j0 = if m < 3 {
                    0
                } else if k == 0 || (k + 2 < self.nodes && x - k as f64 > 0.5) {
                    k.min(self.nodes - 3)
                } else {
                    k - 1
                };
                (0..m)
                    .map(|a| {
                        let l: f64 = (0..m)
                            .filter(|&b| b != a)
                            .map(|b| (f - self.grid[j0 + b]) / (self.grid[j0 + a] - self.grid[j0 + b]))
                            .product();
                        l * v[j0 + a][p]
                    })
                    .sum()
            }
        }
    }
}

/// [`BOUNDARY_FRICTION_RANGE`] widened to a spec's own boundary friction `spec_value`.
fn boundary_range_of(spec_value: f64) -> (f64, f64) {
    (BOUNDARY_FRICTION_RANGE.0.min(spec_value), BOUNDARY_FRICTION_RANGE.1.max(spec_value))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Under the lubricated model every speed magnitude is its own point, and the tabulated
    /// friction between level nodes matches the model evaluated there within 0.1 %; under the
    /// dry model speeds of one direction share a point.
    #[test]
    fn lubricated_points_carry_their_speed_and_interpolate_the_traction() {
        let spec = ScrewSpec::dkfzd4012();
        let pre = [1000.0, 1000.0, 1000.0, 2000.0, 1000.0, 1000.0];
        let ax = [0.0; 6];
        let rpm = [100.0, 100.0, 1000.0, 1000.0, -1000.0, 0.0];
        let mut ph = CreepCache::new(&spec, &pre, &ax, &rpm);
        assert!(ph.speed_dependent && ph.level == Level::FullFilmTraction);
        assert_eq!(ph.points(), 5, "{:?}", ph.row_point);
        assert_eq!(ph.row_point[0], ph.row_point[1]);
        ph.set_grid(0.01, 0.1);
        ph.prepare(1.0, false).unwrap();
        for mu in [0.013, 0.029, 0.047, 0.083] {
            let (direct, _) = ph.at_level(mu).unwrap();
            for (i, &d) in direct.iter().enumerate() {
                let (t, _) = ph.row(1.0, mu, spec.lubricant.boundary_friction, i);
                assert!((t - d).abs() <= 1e-3 * d.abs(), "mu {mu}, row {i}: {t} vs {d}");
            }
            // Speed matters: 100 and 1000 rpm differ.
            assert!((direct[0] - direct[2]).abs() > 1e-3 * direct[2].abs(), "{direct:?}");
            // No friction at zero speed.
            assert_eq!(direct[5], 0.0);
        }
        // Between boundary-friction nodes too (quadratic through three over [0.1, 0.2]): within
        // 0.1 % of the model evaluated there, at levels between nodes.
        assert_eq!(ph.boundary_range(), Some(BOUNDARY_FRICTION_RANGE));
        for (mu, b) in [(0.013, 0.11), (0.029, 0.17), (0.047, 0.125), (0.07, 0.195)] {
            let direct = ph
                .friction_with(|s| {
                    s.lubricant.full_film_traction = mu;
                    s.lubricant.boundary_friction = b;
                })
                .unwrap();
            for (i, &d) in direct.iter().enumerate() {
                let (t, _) = ph.row(1.0, mu, b, i);
                assert!((t - d).abs() <= 1e-3 * d.abs(), "mu {mu}, boundary {b}, row {i}: {t} vs {d}");
            }
        }
        let mut dry = spec;
        dry.model = ballscrew_core::input::ModelOptions::dry();
        // The paper's dry model (no load between balls): its torque does not depend on the
        // speed's magnitude.
        dry.friction.ball_ball_load_n = Some(0.0);
        let ph = CreepCache::new(&dry, &pre, &ax, &rpm);
        assert!(!ph.speed_dependent && ph.level == Level::FrictionCoefficient && ph.boundary_range().is_none());
        assert_eq!(ph.points(), 3, "{:?}", ph.row_point);
    }
}
