//! What a diagnosis finds, in the shapes the report is written from: the metrics of a model,
//! the terms the selection kept and the predictions per row for the figures.

use crate::data::Column;
use crate::terms::Effect;

/// Bias, RMSE, held-out RMSE and level of a model against the measured torques, N m.
///
/// Biases are of the torque along the motion (prediction minus measurement, times the sign of
/// the speed; a row at standstill as it is): negative when the model's drag is below the
/// screw's, in either direction, so that data run both ways do not cancel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Metrics {
    /// Mean of prediction minus measurement along the motion, every row, N m.
    pub bias_nm: f64,
    /// The same over the rows of positive speed (NaN without any), N m.
    pub bias_forward_nm: f64,
    /// The same over the rows of negative speed (NaN without any), N m.
    pub bias_reverse_nm: f64,
    /// Root mean square of prediction minus measurement (fit on all rows), N m.
    pub rmse_nm: f64,
    /// Held-out RMSE (cross-validation), N m.
    pub heldout_rmse_nm: f64,
    /// Measured over modelled drag (the torque less the load torque `F_a L / (2 pi)`): the
    /// least-squares factor through the origin, with its 95 % interval `(low, high)` from the
    /// scatter about it (rows taken as independent). NaN where the model has no drag.
    pub level_ratio: f64,
    /// See `level_ratio`.
    pub level_ratio_interval: (f64, f64),
}

/// A physical parameter read as carrying the data's level: its spec value, the value the level
/// asks of it and its physical range.
#[derive(Debug, Clone, PartialEq)]
pub struct Reading {
    /// Name in the report (the spec key's last part).
    pub name: &'static str,
    /// The spec key.
    pub spec_field: &'static str,
    /// The spec's value.
    pub spec: f64,
    /// The value that carries the level.
    pub value: f64,
    /// Its physical range, when one is stated.
    pub range: Option<(f64, f64)>,
}

impl Reading {
    /// Whether the value lies within its physical range (true without one).
    pub fn physical(&self) -> bool {
        self.range.is_none_or(|(lo, hi)| (lo..=hi).contains(&self.value))
    }
}

/// What the diagnosis finds about the level of the data against the model.
///
/// The level is calibrated first: the physical level parameter of the model (f of the dry
/// model, the full-film traction of the lubricated one, within its physical range) and the
/// creep reduction; then a level factor `k` on the model's friction, kept only when it cuts the
/// held-out RMSE by the selection's rule (`select::cuts`). A kept factor is read back into the
/// oil's two friction coefficients (boundary friction and full-film traction times `k`, every
/// contact's mixed friction coefficient times `k`): when both stay within their physical
/// ranges and the model evaluated there reproduces the factor's drag within the extended
/// model's RMSE, the level is absorbed physically; otherwise the finding is "the model is k
/// times below (or above) this screw".
#[derive(Debug, Clone, PartialEq)]
pub struct LevelFinding {
    /// Measured over the spec model's drag ([`Metrics::level_ratio`]) and its interval.
    pub spec_ratio: f64,
    /// See `spec_ratio`.
    pub spec_ratio_interval: (f64, f64),
    /// Whether the data's level differs from the spec model's: the interval excludes 1 and the
    /// ratio is more than [`LEVEL_TOLERANCE`] from it.
    pub differs: bool,
    /// The level factor kept, with its 95 % interval from the fit's curvature: `(k, low, high)`.
    pub factor: Option<(f64, f64, f64)>,
    /// The level factor's trial against the physical calibration: held-out RMSE without and
    /// with it (N m), and the change of BIC on all rows.
    pub trial: (f64, f64, f64),
    /// The physical parameters that carry the level: the calibration's own values without a
    /// factor; the oil's friction coefficients times the factor (or f times it, dry) with one.
    pub readings: Vec<Reading>,
    /// Whether the readings carry the level: every value within its physical range and (with a
    /// factor) the model there within the extended model's RMSE of the factor's drag.
    pub absorbed: bool,
    /// With a factor: the RMS difference between the model at the readings and the model
    /// times the factor at the data's rows, N m (NaN when not evaluated: a reading out of its
    /// range, or a model that cannot be solved there).
    pub reading_rms_nm: f64,
}

/// A level within this share of the spec model's is no finding (the selection's
/// [`crate::select::MIN_CUT`]).
pub const LEVEL_TOLERANCE: f64 = crate::select::MIN_CUT;

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
    /// The standard error of the extended model's value, in its own unit, from the fit's
    /// curvature at its optimum (`s^2 (J^T J)^-1`: [`crate::model::Structure::level_errors`]);
    /// NaN where there is none (see `standard_error_note`).
    pub standard_error: f64,
    /// Why there is no standard error, when there is none: a value chosen on a grid (the creep
    /// reduction), one on a bound of its fit, one the final model does not have, a singular
    /// curvature.
    pub standard_error_note: Option<&'static str>,
}

impl Calibrated {
    /// The half-width of a uniform spread with the variance of the fit's estimate:
    /// `sqrt(3)` times the standard error (a uniform on `+-h` has the standard deviation
    /// `h / sqrt(3)`); NaN without a standard error.
    pub fn half_width(&self) -> f64 {
        3f64.sqrt() * self.standard_error
    }

    /// The uncertain input this parameter is (its index in `UNCERTAIN_INPUTS`), and the
    /// calibrated half-width in that input's terms (relative for the dry model's coefficient):
    /// `None` for a parameter that is no uncertain input (the creep reduction, the level factor).
    pub fn uncertain_input(&self) -> Option<(usize, f64)> {
        use ballscrew_core::input::uncertainty::index;
        match self.name {
            "full_film_traction" => Some((index::FULL_FILM_TRACTION, self.half_width())),
            "boundary_friction" => Some((index::BOUNDARY_FRICTION, self.half_width())),
            "friction_coefficient" => Some((index::FRICTION_COEFFICIENT, self.half_width() / self.extended)),
            _ => None,
        }
    }

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

/// How much the data narrowed the band of the drag torque at one operating point: the band
/// (5-95 %, [`ballscrew_batch::uncertainty::DEFAULT_SAMPLES`] samples, seed 0) from the input
/// spec's `[uncertainty]` and from the calibrated spec's, whose calibrated inputs carry the
/// fit's spread ([`crate::calibrated_uncertainty`]).
#[derive(Debug, Clone, PartialEq)]
pub struct BandNarrowing {
    /// The reference point: the data's median speed magnitude (rpm), median preload (N) and
    /// median axial load (N) (a column the data lack: the spec's operating value).
    pub speed_rpm: f64,
    /// See `speed_rpm`.
    pub preload_n: f64,
    /// See `speed_rpm`.
    pub axial_load_n: f64,
    /// The input spec's band: low, median, high drag torque, N m (NaN when it has none).
    pub spec_band: (f64, f64, f64),
    /// The calibrated spec's band, the same way.
    pub calibrated_band: (f64, f64, f64),
    /// Why a band has no value, when one has none (its spread leaves a key's valid range, a
    /// sample the model cannot solve).
    pub note: Option<String>,
}

impl BandNarrowing {
    /// The calibrated band's width over the input spec's (NaN without both).
    pub fn width_ratio(&self) -> f64 {
        (self.calibrated_band.2 - self.calibrated_band.0) / (self.spec_band.2 - self.spec_band.0)
    }

    /// The same of the widths relative to each band's median (a calibrated level far from the
    /// spec's scales the band with it).
    pub fn relative_width_ratio(&self) -> f64 {
        let rel = |b: (f64, f64, f64)| (b.2 - b.0) / b.1;
        rel(self.calibrated_band) / rel(self.spec_band)
    }
}
