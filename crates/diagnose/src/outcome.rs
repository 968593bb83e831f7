//! What a diagnosis finds, in the shapes the report is written from: the metrics of a model,
//! the terms the selection kept and the predictions per row for the figures.

use crate::data::Column;
use crate::terms::Effect;

/// Bias, RMSE and held-out RMSE of a model, N m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Metrics {
    /// Mean of prediction minus measurement, N m.
    pub bias_nm: f64,
    /// Root mean square of prediction minus measurement (fit on all rows), N m.
    pub rmse_nm: f64,
    /// Held-out RMSE (cross-validation), N m.
    pub heldout_rmse_nm: f64,
}

/// A term the selection kept.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    /// The term.
    pub effect: Effect,
    /// Its parameters in the final fit (names carry units).
    pub parameters: Vec<(&'static str, f64)>,
    /// Held-out RMSE before and after adding it, N m.
    pub heldout_before_nm: f64,
    /// See `heldout_before_nm`.
    pub heldout_after_nm: f64,
    /// Change of BIC on all rows.
    pub delta_bic: f64,
    /// The evidence in one sentence.
    pub evidence: String,
}

/// Predictions per row for the figures.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Series {
    /// Measured torque, N m.
    pub measured: Vec<f64>,
    /// The spec's model, N m.
    pub spec_model: Vec<f64>,
    /// Calibrated model (all rows), N m.
    pub baseline: Vec<f64>,
    /// Extended model (all rows), N m.
    pub extended: Vec<f64>,
    /// The operating columns of the data (not torque, not repeat).
    pub columns: Vec<(Column, Vec<f64>)>,
}

/// A fitted physical parameter of the calibration, with the ranges it is judged against.
#[derive(Debug, Clone, PartialEq)]
pub struct Calibrated {
    /// Its name in the report (`friction_coefficient`, `full_film_traction`,
    /// `creep_reduction`).
    pub name: &'static str,
    /// The spec field the calibrated value is written to.
    pub spec_field: &'static str,
    /// The spec's value.
    pub spec: f64,
    /// The calibrated model's value (no extension term).
    pub calibrated: f64,
    /// The extended model's value.
    pub extended: f64,
    /// The range the fit could reach (for the creep reduction: the smallest and largest
    /// value tried).
    pub fit_bounds: (f64, f64),
    /// The range of physical values, when one is stated.
    pub physical_range: Option<(f64, f64)>,
}

impl Calibrated {
    /// Why the calibrated value of the final (extended) model is not a physical one: out of the
    /// physical range, or on a bound of the fit (the data want a value beyond it); `None` when
    /// neither. The value without the extension terms may absorb a missing term (a seal drag
    /// raises the level): it is named, not judged.
    pub fn out_of_range(&self) -> Option<String> {
        let v = self.extended;
        let (lo, hi) = self.fit_bounds;
        let near = |b: f64| (v - b).abs() <= 1e-6 * b.abs();
        let why = match self.physical_range {
            Some((plo, phi)) if !(plo..=phi).contains(&v) => format!("outside its physical range [{plo}, {phi}]"),
            _ if near(lo) || near(hi) => format!("on a bound of the fit [{lo:.4}, {hi:.4}]"),
            _ => return None,
        };
        Some(format!("the calibrated {} {v:.4} (without extension terms {:.4}) is {why}", self.name, self.calibrated))
    }
}
