//! The calibrated, extended model of a dataset: prediction per row from the cached creep model
//! and the extension terms of the core, and its fit on a subset of rows.
//!
//! Parameters: `ln` of the level parameter first (the friction coefficient f of the dry model,
//! the full-film traction of the lubricated one: kept positive), then, for the lubricated
//! model, `ln` of the boundary friction (within its physical range: the two carry the level at
//! high and at low speed), then `ln k` of the level factor when the structure has one (the
//! model's friction times `k`: a screw whose drag is the model's times a constant,
//! [`LEVEL_FACTOR_RANGE`]), then each term's own.

use super::creep_cache::{CreepCache, Unwatched, Watch};
use super::data::{Column, Dataset};
use super::fit::{Fit, least_squares};
use super::terms::{Effect, Settings};
use ballscrew_batch::{Batch, BatchError, Errors, Start, Stop};
use ballscrew_core::Short;
use ballscrew_core::error::Error;
use ballscrew_core::input::extensions::{Conditions, Extensions, LevelFactor};
use ballscrew_core::input::{Lubrication, OperatingPoint, ScrewSpec, rpm_to_rad_s};
use ballscrew_core::screw::model::Model;

/// The rows in the model's terms.
#[derive(Debug, Clone)]
pub struct Rows {
    /// Operating point of each row (SI).
    pub op: Vec<OperatingPoint>,
    /// Conditions of each row.
    pub cond: Vec<Conditions>,
    /// Measured torque, N m.
    pub torque: Vec<f64>,
}

impl Rows {
    /// Fills missing operating columns from the spec's operating point.
    pub fn new(d: &Dataset, spec_op: &OperatingPoint) -> Self {
        let n = d.rows();
        let col = |c: Column, default: f64| -> Vec<f64> { d.get(c).map_or_else(|| vec![default; n], <[f64]>::to_vec) };
        let speed = col(Column::SpeedRpm, ballscrew_core::input::rad_s_to_rpm(spec_op.speed_rad_s));
        let preload = col(Column::PreloadN, spec_op.preload_n);
        let axial = col(Column::AxialLoadN, spec_op.axial_load_n);
        let pos = col(Column::PositionMm, 0.0);
        let time = col(Column::TimeH, 0.0);
        let temp = d.get(Column::TemperatureC);
        Self {
            op: (0..n)
                .map(|i| OperatingPoint {
                    speed_rad_s: rpm_to_rad_s(speed[i]),
                    preload_n: preload[i],
                    axial_load_n: axial[i],
                })
                .collect(),
            cond: (0..n)
                .map(|i| Conditions { position_m: pos[i] / 1000.0, temperature_c: temp.map(|t| t[i]), time_h: time[i] })
                .collect(),
            torque: d.torque().to_vec(),
        }
    }

    /// Preload, axial load and speed (rpm) columns, for [`CreepCache::new`].
    pub fn physics_columns(&self) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        (
            self.op.iter().map(|o| o.preload_n).collect(),
            self.op.iter().map(|o| o.axial_load_n).collect(),
            self.op.iter().map(|o| ballscrew_core::input::rad_s_to_rpm(o.speed_rad_s)).collect(),
        )
    }
}

/// The model's drive torque, N m, at every row (the spec's extension terms with each row's
/// conditions): each row's canonical state, the model's cold solve over the machine's cores
/// (`Batch::torques` with `Start::Independent`: the number `ballscrew torque` gives at the
/// row's point, to the bit, on any number of threads); `stop` is asked before every row (a
/// progress display may count the questions); a row that fails is `errors`' to handle.
pub fn predict_rows(
    model: &Model,
    rows: &Rows,
    stop: &dyn Stop,
    errors: Errors,
) -> Result<Vec<Result<f64, Error>>, BatchError> {
    Batch::new(rows.op.len()).stop(stop).errors(errors).start(Start::Independent).torques(
        model,
        None,
        &rows.op,
        Some(&rows.cond),
    )
}

/// What a data file's `temperature_c` column does not do in a prediction, said where it could
/// be taken for the oil's temperature: under the lubricated model (`lubrication = "ehl"`) the
/// oil at the contacts stays at the spec's `lubricant.temperature_c` on every row; the column
/// enters only the spec's `thermal_viscosity` term. `None` without the column or under the dry
/// model. (A diagnosis uses the column: the `thermal_viscosity` term it tries.)
pub fn temperature_note(spec: &ScrewSpec, data: &Dataset) -> Option<String> {
    if spec.model.lubrication != Lubrication::Ehl || data.get(Column::TemperatureC).is_none() {
        return None;
    }
    let term = if spec.extensions.thermal_viscosity.is_some() {
        "the spec's thermal_viscosity term"
    } else {
        "the thermal_viscosity term, which this spec does not have: here it changes nothing"
    };
    Some(format!(
        "column `temperature_c`: the lubricated model's oil at the contacts stays at the spec's \
         lubricant.temperature_c ({} degrees C) on every row; the column enters only {term}",
        Short(spec.lubricant.temperature_c)
    ))
}

/// Smallest and largest level factor `k` a fit may reach (the model's friction times `k`).
pub const LEVEL_FACTOR_RANGE: (f64, f64) = (0.05, 20.0);

/// Why a fitted parameter on a bound of its fit has no standard error.
pub const ON_A_BOUND: &str =
    "on a bound of its fit: the fit's curvature there is not that of a quadratic minimum, so it gives no error";
/// Why a fitted parameter has no standard error when the fit's curvature cannot be inverted.
pub const SINGULAR: &str =
    "the fit's curvature J^T J is singular or nearly so: the data cannot tell this parameter from the others";

/// A model structure: creep reduction, level factor, terms and their settings.
#[derive(Debug, Clone)]
pub struct Structure<'a, W = Unwatched> {
    /// Cached creep model.
    pub physics: &'a CreepCache<'a, W>,
    /// Rows.
    pub rows: &'a Rows,
    /// Creep reduction (fixed, prepared in `creep_cache`).
    pub kappa: f64,
    /// Whether the model's friction is multiplied by a fitted level factor `k` (the parameter
    /// after the level parameters).
    pub level_factor: bool,
    /// Terms.
    pub effects: Vec<Effect>,
    /// Settings of the terms.
    pub settings: Settings,
}

impl<W: Watch> Structure<'_, W> {
    /// Number of parameters (the level parameter and the level factor included).
    pub fn parameters(&self) -> usize {
        self.first_term() + self.effects.iter().map(|e| e.parameters()).sum::<usize>()
    }

    /// Whether the boundary friction is fitted (parameter 1: the lubricated model).
    fn fits_boundary(&self) -> bool {
        self.physics.boundary_range().is_some()
    }

    /// Index of the level factor's parameter (when the structure has one).
    fn factor_index(&self) -> usize {
        1 + usize::from(self.fits_boundary())
    }

    /// Index of the first term's first parameter.
    fn first_term(&self) -> usize {
        self.factor_index() + usize::from(self.level_factor)
    }

    /// The level factor of a parameter vector (1 without one).
    pub fn factor(&self, x: &[f64]) -> f64 {
        if self.level_factor { x[self.factor_index()].exp() } else { 1.0 }
    }

    /// The boundary friction of a parameter vector (the spec's when it is not fitted).
    pub fn boundary(&self, x: &[f64]) -> f64 {
        if self.fits_boundary() { x[1].exp() } else { self.physics.spec().lubricant.boundary_friction }
    }

    /// The extension terms of a parameter vector.
    pub fn extensions(&self, x: &[f64]) -> Extensions {
        let mut ext = Extensions::NONE;
        if self.level_factor {
            ext.level_factor = Some(LevelFactor { factor: self.factor(x) });
        }
        let mut k = self.first_term();
        for e in &self.effects {
            let n = e.parameters();
            e.apply(&x[k..k + n], &self.settings, &mut ext);
            k += n;
        }
        ext
    }

    /// Predicted torque of row `i` at level `f` with the terms (the level factor among them) of
    /// `ext`, N m.
    fn predict_row(&self, ext: &Extensions, f: f64, boundary: f64, i: usize) -> f64 {
        let (fr, ax) = self.physics.row(self.kappa, f, boundary, i);
        let op = &self.rows.op[i];
        let cond = &self.rows.cond[i];
        let eff = ext.effective_operating(op, cond);
        let fr = if eff.preload_n != op.preload_n && op.preload_n > 0.0 {
            fr * self.physics.worn(self.kappa, f, i, eff.preload_n / op.preload_n)
        } else {
            fr
        };
        ext.torque_nm(ax + fr, ax, &eff, cond, self.settings.lead_m, self.physics.motion[i])
    }

    /// Predictions for rows `idx`.
    pub fn predict(&self, x: &[f64], idx: &[usize]) -> Vec<f64> {
        let ext = self.extensions(x);
        let (f, b) = (x[0].exp(), self.boundary(x));
        idx.iter().map(|&i| self.predict_row(&ext, f, b, i)).collect()
    }

    /// Lower and upper bounds of every parameter of a fit, and each one's typical size (in the
    /// fit's terms: `ln` of the level parameters and of the level factor).
    fn bounds(&self) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let (f_lo, f_hi) = self.physics.f_range();
        let mut lo = vec![f_lo.ln()];
        let mut hi = vec![f_hi.ln()];
        let mut scale = vec![1.0];
        if let Some((b_lo, b_hi)) = self.physics.boundary_range() {
            lo.push(b_lo.ln());
            hi.push(b_hi.ln());
            scale.push(1.0);
        }
        if self.level_factor {
            lo.push(LEVEL_FACTOR_RANGE.0.ln());
            hi.push(LEVEL_FACTOR_RANGE.1.ln());
            scale.push(1.0);
        }
        for e in &self.effects {
            let (l, h, s) = e.bounds(&self.settings);
            lo.extend(l);
            hi.extend(h);
            scale.extend(s);
        }
        (lo, hi, scale)
    }

    /// Fits the parameters on rows `idx` from every combination of the terms' starts.
    pub fn fit(&self, idx: &[usize], f_start: f64) -> Fit {
        let (f_lo, f_hi) = self.physics.f_range();
        let (lo, hi, scale) = self.bounds();
        let mut starts: Vec<Vec<f64>> = vec![vec![f_start.clamp(f_lo, f_hi).ln()]];
        if let Some((b_lo, b_hi)) = self.physics.boundary_range() {
            let b0 = self.settings.boundary_start.clamp(b_lo, b_hi).ln();
            for s in &mut starts {
                s.push(b0);
            }
        }
        if self.level_factor {
            // From 1, and from the least-squares factor of the rows' friction at the start's
            // level (the torque is linear in k).
            let b0 = self.settings.boundary_start;
            let k0 = self.factor_estimate(idx, f_start.clamp(f_lo, f_hi), b0);
            starts = starts
                .iter()
                .flat_map(|a| {
                    let mut v = vec![[a.clone(), vec![0.0]].concat()];
                    if (k0 - 1.0).abs() > 1e-3 {
                        v.push([a.clone(), vec![k0.ln()]].concat());
                    }
                    v
                })
                .collect();
        }
        for e in &self.effects {
            starts = starts
                .iter()
                .flat_map(|a| e.starts(&self.settings).into_iter().map(move |b| [a.clone(), b].concat()))
                .collect();
        }
        let resid = |x: &[f64], out: &mut [f64]| self.residuals(x, idx, out);
        starts
            .iter()
            .map(|x0| least_squares(&resid, idx.len(), x0, &lo, &hi, &scale))
            .min_by(|a, b| a.rss.total_cmp(&b.rss))
            .unwrap_or(Fit { x: vec![f_start.ln()], rss: f64::INFINITY })
    }

    /// Prediction minus measurement at rows `idx`, N m.
    fn residuals(&self, x: &[f64], idx: &[usize], out: &mut [f64]) {
        let ext = self.extensions(x);
        let (f, b) = (x[0].exp(), self.boundary(x));
        for (o, &i) in out.iter_mut().zip(idx) {
            *o = self.predict_row(&ext, f, b, i) - self.rows.torque[i];
        }
    }

    /// The least-squares factor on the model's friction at level `f` (no term) that best meets
    /// the rows `idx` (within [`LEVEL_FACTOR_RANGE`]; 1 when the model has no friction there).
    fn factor_estimate(&self, idx: &[usize], f: f64, boundary: f64) -> f64 {
        let (mut num, mut den) = (0.0, 0.0);
        for &i in idx {
            let (fr, ax) = self.physics.row(self.kappa, f, boundary, i);
            num += (self.rows.torque[i] - ax) * fr;
            den += fr * fr;
        }
        let k = num / den;
        if den > 0.0 && k.is_finite() { k.clamp(LEVEL_FACTOR_RANGE.0, LEVEL_FACTOR_RANGE.1) } else { 1.0 }
    }

    /// The level factor of a fit on every row and its 95 % interval from the fit's curvature
    /// (the level parameters held where they are when they lie on a bound of the fit or cannot
    /// be told apart from the factor, its relative standard error then above one half; the
    /// terms' parameters free): `(k, low, high)`. `None` without a level factor.
    pub fn factor_interval(&self, x: &[f64]) -> Option<(f64, f64, f64)> {
        if !self.level_factor {
            return None;
        }
        let all: Vec<usize> = (0..self.rows.torque.len()).collect();
        let resid = |x: &[f64], out: &mut [f64]| self.residuals(x, &all, out);
        let (f_lo, f_hi) = self.physics.f_range();
        let mut bounds = vec![(f_lo.ln(), f_hi.ln())];
        if let Some((b_lo, b_hi)) = self.physics.boundary_range() {
            bounds.push((b_lo.ln(), b_hi.ln()));
        }
        let free_levels: Vec<usize> =
            (0..bounds.len()).filter(|&j| x[j] > bounds[j].0 + 1e-9 && x[j] < bounds[j].1 - 1e-9).collect();
        let at = self.factor_index();
        let terms: Vec<usize> = (self.first_term()..x.len()).collect();
        let scale = vec![1.0; x.len()];
        let se = |levels: &[usize]| {
            let free = [levels.to_vec(), vec![at], terms.clone()].concat();
            crate::fit::standard_errors(&resid, all.len(), x, &free, &scale).map(|se| se[levels.len()])
        };
        // The level parameters free where the data tell them apart from the factor (the
        // factor's relative error then below one half); else held at their calibrated values
        // (one operating point: the factor's interval is then conditional on them).
        let s = se(&free_levels).filter(|s| *s < 0.5).or_else(|| se(&[]))?;
        let k = x[at].exp();
        Some((k, (x[at] - 1.96 * s).exp(), (x[at] + 1.96 * s).exp()))
    }

    /// The standard error of each level parameter of a fit `x` on every row, in the
    /// parameter's own unit: the level parameter, the boundary friction (when fitted), the
    /// level factor (when the structure has one), in that order; `Err` with the reason where
    /// there is none.
    ///
    /// The covariance of the parameters at the least-squares optimum is `s^2 (J^T J)^-1`, `J`
    /// the Jacobian of the residuals and `s^2 = RSS / (m - p)` (m rows, p parameters free):
    /// the linearised fit's (Seber & Wild, *Nonlinear Regression*, 1989, section 2.1; Press et
    /// al., *Numerical Recipes*, 3rd ed., 15.5), the rows taken as independent with one
    /// scatter. The fit works in `ln` of these parameters: the error of the value `v = exp(t)`
    /// is `v se(t)` (the delta method). Every parameter is free (the terms' too) but those on a
    /// bound of the fit: a parameter there sits at no quadratic minimum, so its curvature is
    /// no error of it ([`ON_A_BOUND`]); it is held at the bound and the others' errors are
    /// conditional on it. A parameter whose column of `J` the others explain (a variance
    /// inflation beyond [`crate::fit::MAX_INFLATION`]: one operating point, where the level
    /// parameters and the level factor all scale the same torque) has none either ([`SINGULAR`]).
    pub fn level_errors(&self, x: &[f64]) -> Vec<Result<f64, &'static str>> {
        let all: Vec<usize> = (0..self.rows.torque.len()).collect();
        let resid = |x: &[f64], out: &mut [f64]| self.residuals(x, &all, out);
        let (lo, hi, scale) = self.bounds();
        let on_bound = |j: usize| x[j] <= lo[j] + 1e-9 || x[j] >= hi[j] - 1e-9;
        let free: Vec<usize> = (0..x.len()).filter(|&j| !on_bound(j)).collect();
        let se = crate::fit::standard_errors_and_inflation(&resid, all.len(), x, &free, &scale);
        (0..self.first_term())
            .map(|j| {
                if on_bound(j) {
                    return Err(ON_A_BOUND);
                }
                let at = free.iter().position(|&f| f == j).ok_or(SINGULAR)?;
                let (s, inflation) = se.as_ref().ok_or(SINGULAR)?[at];
                if !(inflation <= crate::fit::MAX_INFLATION) {
                    return Err(SINGULAR);
                }
                Ok(x[j].exp() * s)
            })
            .collect()
    }

    /// Parameters of each term: (effect, its slice of `x`).
    pub fn split<'x>(&self, x: &'x [f64]) -> Vec<(Effect, &'x [f64])> {
        let mut k = self.first_term();
        self.effects
            .iter()
            .map(|&e| {
                let n = e.parameters();
                let s = (e, &x[k..k + n]);
                k += n;
                s
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ballscrew_batch::Never;
    use ballscrew_core::input::ScrewSpec;
    use ballscrew_core::screw::model::SolverState;

    #[test]
    fn predict_gives_each_rows_torque_and_names_the_failing_row() {
        // The dry model, whose torque is close to proportional to the preload (checked below).
        let mut spec = ScrewSpec::dkfzd4012();
        spec.model = ballscrew_core::input::ModelOptions::dry();
        let model = Model::new(&spec).unwrap();
        let op = |preload_n: f64| OperatingPoint { preload_n, ..spec.operating };
        let cond = Conditions { position_m: 0.0, temperature_c: None, time_h: 0.0 };
        let mut rows = Rows { op: vec![op(1000.0), op(2000.0)], cond: vec![cond; 2], torque: vec![] };
        let raise = |rows: &Rows| predict_rows(&model, rows, &Never, Errors::Raise);
        let t: Vec<f64> = raise(&rows).unwrap().into_iter().map(Result::unwrap).collect();
        for (i, &t) in t.iter().enumerate() {
            let cold = model.torque_at(&rows.op[i], &cond, &mut SolverState::new()).unwrap();
            assert_eq!(t, cold, "row {i}: the row's canonical state, to the bit");
        }
        assert!(t[1] > 1.9 * t[0], "{t:?}");
        rows.op.push(OperatingPoint { speed_rad_s: f64::NAN, ..spec.operating });
        rows.cond.push(cond);
        // The first failing row ends the batch with its index and the model's error (an error,
        // never a panic, whatever the batch's error: `BatchError`).
        match raise(&rows) {
            Err(BatchError::Point { index: 2, error: Error::Input(_) }) => {}
            other => panic!("{other:?}"),
        }
        // With errors = NaN the others are computed, the failing row keeps its error.
        let each = predict_rows(&model, &rows, &Never, Errors::Nan).unwrap();
        assert_eq!(each.len(), 3);
        assert_eq!(*each[0].as_ref().unwrap(), t[0]);
        assert!(matches!(each[2], Err(Error::Input(_))), "{:?}", each[2]);
    }
}
