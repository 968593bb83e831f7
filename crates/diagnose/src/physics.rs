//! The creep model's torque at every row, cached for fitting.
//!
//! The model's torque does not depend on the speed's magnitude above the standstill speed
//! (docs/model-notes.md item 12), and its friction part is close to proportional to the friction
//! coefficient f. So the model is evaluated once per distinct (preload, axial load, direction)
//! of the data, on a grid of f (log-spaced nodes, ratio [`NODE_RATIO`]) around a first estimate,
//! for each creep reduction tried; between nodes the friction part over f is interpolated
//! linearly in log f (error well below 0.1 %). Rows below the standstill speed scale the friction
//! by the standstill factor. The running-time term (`preload_loss`) needs the friction at a
//! lower preload: per point it is tabulated at [`PRELOAD_RATIOS`] of the preload (at the first
//! estimate of f) and interpolated linearly in the ratio, as friction over ratio.

use alloc::collections::BTreeMap;
use ballscrew_core::contact::creep::{direction, standstill_factor};
use ballscrew_core::input::{OperatingPoint, ScrewSpec, rpm_to_rad_s};
use ballscrew_core::screw::torque::{Model, SolverState};

/// Ratio of neighbouring f nodes.
pub const NODE_RATIO: f64 = 1.5;
/// Speed at which a point above the standstill speed is evaluated, rpm (any would do).
const EVAL_SPEED_RPM: f64 = 100.0;
/// Smallest and largest friction coefficient the calibration may reach (the spec accepts down
/// to 0.005, where light balls may already lose their quasi-static state).
pub const F_MIN: f64 = 0.008;
/// See [`F_MIN`].
pub const F_MAX: f64 = 1.0;
/// Preload ratios at which the friction of a worn screw is tabulated (descending from 1).
pub const PRELOAD_RATIOS: [f64; 6] = [1.0, 0.8, 0.6, 0.4, 0.2, 0.05];

/// One distinct operating point of the data.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Point {
    preload_n: f64,
    axial_load_n: f64,
    dir: f64,
}

/// Model friction per point on f nodes, for one creep reduction.
#[derive(Debug, Clone)]
struct Table {
    /// `friction[node][point]` over f (N m per unit f).
    per_f: Vec<Vec<f64>>,
    /// Friction at each of [`PRELOAD_RATIOS`] over (ratio times the friction at ratio 1), per
    /// point.
    shape: Vec<[f64; PRELOAD_RATIOS.len()]>,
}

/// The cached model of one dataset.
#[derive(Debug, Clone)]
pub struct Physics {
    spec: ScrewSpec,
    points: Vec<Point>,
    /// Point of each row.
    pub row_point: Vec<usize>,
    /// Standstill factor times direction per row.
    pub motion: Vec<f64>,
    /// `F_a L / (2 pi)` per point (independent of f).
    axial: Vec<f64>,
    /// f of node 0 and number of nodes.
    f0: f64,
    nodes: usize,
    /// First estimate of f (where the preload shapes are tabulated).
    pub f_estimate: f64,
    tables: BTreeMap<u64, Table>,
    /// Warm-start memory per point: each evaluation starts from the last solution at the same
    /// point (a neighbouring f, kappa or preload), not from the previous point.
    states: Vec<SolverState>,
}

/// Why the model could not be evaluated.
pub type PhysicsError = String;

impl Physics {
    /// Groups the rows (preload N, axial load N, speed rpm per row) into distinct points.
    pub fn new(spec: &ScrewSpec, preload: &[f64], axial: &[f64], speed_rpm: &[f64]) -> Self {
        let mut points: Vec<Point> = Vec::new();
        let mut index: BTreeMap<(u64, u64, bool), usize> = BTreeMap::new();
        let mut row_point = Vec::with_capacity(preload.len());
        let mut motion = Vec::with_capacity(preload.len());
        let w0 = spec.friction.standstill_speed_rad_s;
        for i in 0..preload.len() {
            let w = rpm_to_rad_s(speed_rpm[i]);
            let p = Point { preload_n: preload[i], axial_load_n: axial[i], dir: direction(w) };
            let key = (p.preload_n.to_bits(), p.axial_load_n.to_bits(), p.dir > 0.0);
            let k = *index.entry(key).or_insert_with(|| {
                points.push(p);
                points.len() - 1
            });
            row_point.push(k);
            motion.push(direction(w) * standstill_factor(w, w0));
        }
        Self {
            spec: *spec,
            points,
            row_point,
            motion,
            axial: Vec::new(),
            f0: F_MIN,
            nodes: 0,
            f_estimate: spec.friction.coefficient,
            tables: BTreeMap::new(),
            states: Vec::new(),
        }
    }

    /// Number of distinct points.
    pub fn points(&self) -> usize {
        self.points.len()
    }

    /// The spec (its f and creep reduction are the ones given, not the fitted ones).
    pub fn spec(&self) -> &ScrewSpec {
        &self.spec
    }

    fn evaluate(&mut self, f: f64, kappa: f64, preload_scale: f64) -> Result<(Vec<f64>, Vec<f64>), PhysicsError> {
        let mut spec = self.spec;
        spec.friction.coefficient = f;
        spec.friction.creep_reduction = kappa;
        spec.extensions = ballscrew_core::input::extensions::Extensions::NONE;
        let model = Model::new(&spec).map_err(|e| format!("the spec cannot be evaluated: {e}"))?;
        if self.states.len() != self.points.len() {
            self.states = vec![SolverState::new(); self.points.len()];
        }
        let mut friction = Vec::with_capacity(self.points.len());
        let mut axial = Vec::with_capacity(self.points.len());
        for (p, state) in self.points.iter().zip(self.states.iter_mut()) {
            let op = OperatingPoint {
                speed_rad_s: p.dir * rpm_to_rad_s(EVAL_SPEED_RPM),
                preload_n: p.preload_n * preload_scale,
                axial_load_n: p.axial_load_n,
            };
            let s = model.summary(&op, state).map_err(|e| {
                format!(
                    "the model fails at preload {} N, axial load {} N, f = {f:.4}, creep reduction {kappa}: {e}",
                    op.preload_n, op.axial_load_n
                )
            })?;
            friction.push(s.torque_nm - s.axial_term_nm);
            axial.push(s.axial_term_nm);
        }
        Ok((friction, axial))
    }

    /// The friction part at the spec's own f and creep reduction per row, and sets the f grid to
    /// span `f_lo..f_hi` (clamped to [`F_MIN`], [`F_MAX`]).
    pub fn set_grid(&mut self, f_lo: f64, f_hi: f64) {
        let lo = f_lo.clamp(F_MIN, F_MAX);
        let hi = f_hi.clamp(lo, F_MAX);
        self.nodes = 1 + ((hi / lo).ln() / NODE_RATIO.ln()).ceil().max(1.0) as usize;
        // The top node at most F_MAX: the grid shifts down (not below F_MIN) when it would pass.
        self.f0 = (F_MAX / NODE_RATIO.powi(self.nodes as i32 - 1)).min(lo).max(F_MIN);
        self.tables.clear();
    }

    /// The f range the grid covers.
    pub fn f_range(&self) -> (f64, f64) {
        (self.f0, (self.f0 * NODE_RATIO.powi(self.nodes.saturating_sub(1) as i32)).min(F_MAX))
    }

    /// Model torque per row at the spec's f and creep reduction, N m (friction and axial term).
    pub fn at_spec(&mut self) -> Result<(Vec<f64>, Vec<f64>), PhysicsError> {
        let (fr, ax) = self.evaluate(self.spec.friction.coefficient, self.spec.friction.creep_reduction, 1.0)?;
        self.axial = ax.clone();
        let rows = self.row_point.len();
        Ok((
            (0..rows).map(|i| fr[self.row_point[i]] * self.motion[i].abs()).collect(),
            (0..rows).map(|i| ax[self.row_point[i]]).collect(),
        ))
    }

    /// Fills the table of creep reduction `kappa` (every f node, and the preload slopes when
    /// `slopes`).
    pub fn prepare(&mut self, kappa: f64, slopes: bool) -> Result<(), PhysicsError> {
        let key = kappa.to_bits();
        if self.tables.contains_key(&key) {
            return Ok(());
        }
        let mut per_f = Vec::with_capacity(self.nodes);
        let mut k = 0;
        while k < self.nodes {
            let f = (self.f0 * NODE_RATIO.powi(k as i32)).min(F_MAX);
            match self.evaluate(f, kappa, 1.0) {
                Ok((fr, ax)) => {
                    self.axial = ax;
                    per_f.push(fr.iter().map(|t| t / f).collect::<Vec<f64>>());
                    k += 1;
                }
                // At the lowest friction coefficients light balls may have no quasi-static
                // state (every contact in full slip): the grid starts one node higher.
                Err(_) if k == 0 && self.tables.is_empty() && self.nodes > 2 => {
                    self.f0 *= NODE_RATIO;
                    self.nodes -= 1;
                }
                Err(e) => return Err(e),
            }
        }
        let mut shape = vec![[1.0; PRELOAD_RATIOS.len()]; self.points.len()];
        if slopes {
            let f = self.f_estimate.clamp(self.f0, self.f_range().1);
            let (full, _) = self.evaluate(f, kappa, 1.0)?;
            for (j, &ratio) in PRELOAD_RATIOS.iter().enumerate().skip(1) {
                let (low, _) = self.evaluate(f, kappa, ratio)?;
                for p in 0..self.points.len() {
                    shape[p][j] = if full[p] != 0.0 { low[p] / (ratio * full[p]) } else { 1.0 };
                }
            }
        }
        self.tables.insert(key, Table { per_f, shape });
        Ok(())
    }

    /// Friction at `ratio` of the preload over the friction at the full preload, point of row
    /// `i` (tables of `prepare(kappa, true)`).
    pub fn worn(&self, kappa: f64, i: usize, ratio: f64) -> f64 {
        let g = &self.tables[&kappa.to_bits()].shape[self.row_point[i]];
        let r = &PRELOAD_RATIOS;
        let j = (1..r.len()).find(|&j| ratio >= r[j]).unwrap_or(r.len() - 1);
        let w = ((r[j - 1] - ratio) / (r[j - 1] - r[j])).clamp(0.0, 1.0);
        ratio * ((1.0 - w) * g[j - 1] + w * g[j])
    }

    /// The model at `(f, kappa)` (prepared) for row `i`: (friction part with the row's standstill
    /// factor, signed with the direction; axial term).
    pub fn row(&self, kappa: f64, f: f64, i: usize) -> (f64, f64) {
        let t = &self.tables[&kappa.to_bits()];
        let p = self.row_point[i];
        let x = ((f / self.f0).ln() / NODE_RATIO.ln()).clamp(0.0, (self.nodes - 1) as f64);
        let k = (x.floor() as usize).min(self.nodes.saturating_sub(2));
        let w = x - k as f64;
        let per_f = if self.nodes == 1 { t.per_f[0][p] } else { (1.0 - w) * t.per_f[k][p] + w * t.per_f[k + 1][p] };
        // The table holds signed friction (negative in reverse); scale by |standstill factor|.
        (per_f * f * self.motion[i].abs(), self.axial[p])
    }
}
