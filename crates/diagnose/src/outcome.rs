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
