//! Core results as rows of (key, value), keyed and scaled exactly as the command line's CSV and
//! JSON output (`ballscrew torque`, `sweep`, `inspect`), so a table from Python and one from the
//! command line line up column for column. Units are in the keys.

use ballscrew_core::input::rad_s_to_rpm;
use ballscrew_core::screw::catalog::BAND_RELATIVE;
use ballscrew_core::{BallReport, ContactReport, Efficiency, Summary};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// One reported value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// A real number.
    Num(f64),
    /// A count.
    Int(u64),
    /// A name.
    Text(&'static str),
}

/// A key (with its unit) and how to read its value from a `T`.
pub type Field<T> = (&'static str, fn(&T) -> Value);

use Value::{Int, Num, Text};

/// Everything reported for one operating point (`ballscrew torque --format json`, before the
/// efficiency): the torque by every route, its drag and load parts, the dissipation torque and its shares by mechanism (creep and sliding at the
/// raceways, EHL rolling resistance, elastic hysteresis, ball-ball sliding), the seals' torque, the catalog estimate and band, Newton iterations and the largest residual.
pub static POINT: &[Field<Summary>] = &[
    ("speed_rpm", |s| Num(rad_s_to_rpm(s.operating.speed_rad_s))),
    ("preload_n", |s| Num(s.operating.preload_n)),
    ("axial_load_n", |s| Num(s.operating.axial_load_n)),
    ("torque_nm", |s| Num(s.torque_nm)),
    ("drag_torque_nm", |s| Num(s.drag_torque_nm())),
    ("load_torque_nm", |s| Num(s.load_torque_nm())),
    ("torque_energy_nm", |s| Num(s.torque_energy_nm)),
    ("torque_moment_nm", |s| Num(s.torque_moment_nm)),
    ("torque_eq27_nm", |s| Num(s.torque_eq27_nm)),
    ("dissipation_torque_nm", |s| Num(s.dissipation_torque_nm)),
    ("creep_torque_nm", |s| Num(s.creep_torque_nm)),
    ("rolling_resistance_torque_nm", |s| Num(s.rolling_resistance_torque_nm)),
    ("hysteresis_torque_nm", |s| Num(s.hysteresis_torque_nm)),
    ("ball_ball_torque_nm", |s| Num(s.ball_ball_torque_nm)),
    ("return_torque_nm", |s| Num(s.return_torque_nm)),
    ("seal_torque_nm", |s| Num(s.seal_torque_nm)),
    ("catalog_nm", |s| Num(s.catalog_nm)),
    ("catalog_low_nm", |s| Num(s.catalog_nm * (1.0 - BAND_RELATIVE))),
    ("catalog_high_nm", |s| Num(s.catalog_nm * (1.0 + BAND_RELATIVE))),
    ("ratio", |s| Num(s.catalog_ratio())),
    ("iterations", |s| Int(u64::from(s.iterations))),
    ("max_residual", |s| Num(s.max_residual)),
];

/// The columns of a sweep (`ballscrew sweep --format csv`) after its first column, the swept
/// quantity ([`SWEPT`]): those of [`POINT`] without the operating point, the two parts of the
/// energy route and the shares by mechanism.
pub const SWEEP_KEYS: [&str; 12] = [
    "torque_nm",
    "drag_torque_nm",
    "load_torque_nm",
    "torque_energy_nm",
    "torque_moment_nm",
    "torque_eq27_nm",
    "catalog_nm",
    "catalog_low_nm",
    "catalog_high_nm",
    "ratio",
    "iterations",
    "max_residual",
];

/// The forward and backdrive efficiency under the axial load (`ballscrew torque` and `sweep`,
/// after the other columns): NaN (n/a) without an axial load or at standstill.
pub static EFFICIENCY: &[Field<Option<Efficiency>>] = &[
    ("forward_efficiency", |e| Num(e.map_or(f64::NAN, |e| e.forward_efficiency))),
    ("backdrive_efficiency", |e| Num(e.map_or(f64::NAN, |e| e.backdrive_efficiency))),
    ("backdrive_torque_nm", |e| Num(e.map_or(f64::NAN, |e| e.backdrive_torque_nm))),
];

/// The quantities a sweep can run over, as the first column of the command line's sweep names
/// them: the preload (`sweep`, the default), the screw speed (`sweep --speed-rpm A..B`), the
/// axial load (`sweep --axial-load-n A..B`) and the oil temperature at the contacts
/// (`sweep --oil-temperature-c A..B`).
pub const SWEPT: [&str; 4] = ["preload_n", "speed_rpm", "axial_load_n", "oil_temperature_c"];

/// The ball of a circle (`ballscrew inspect --format csv`, the columns before `contact`).
pub static BALL: &[Field<BallReport>] = &[
    ("nut", |b| Int(b.nut as u64 + 1)),
    ("circle", |b| Int(b.circle as u64 + 1)),
    ("balls", |b| Int(u64::from(b.balls))),
    ("flank", |b| Num(b.flank)),
    ("weight", |b| Num(b.weight)),
    ("axial_load_n", |b| Num(b.axial_load_n)),
    ("circle_axial_load_n", |b| Num(b.axial_load_n * f64::from(b.balls))),
    ("iterations", |b| Int(u64::from(b.solve.iterations))),
    ("residual", |b| Num(b.solve.residual)),
    ("continuation_steps", |b| Int(u64::from(b.solve.continuation_steps))),
    ("spin_ratio", |b| Num(b.spin_ratio)),
    ("beta_deg", |b| Num(b.beta_rad.to_degrees())),
    ("beta_prime_deg", |b| Num(b.beta_prime_rad.to_degrees())),
    ("orbit_ratio", |b| Num(b.orbit_ratio)),
    ("omega_t_per_screw", |b| Num(b.omega_tnb_per_screw[0])),
    ("omega_n_per_screw", |b| Num(b.omega_tnb_per_screw[1])),
    ("omega_b_per_screw", |b| Num(b.omega_tnb_per_screw[2])),
];

/// One contact of a ball (`ballscrew inspect --format csv`, from `contact` on).
pub static CONTACT: &[Field<ContactReport>] = &[
    ("contact", |c| Text(c.kind.name())),
    ("normal_load_n", |c| Num(c.normal_load_n)),
    ("contact_angle_deg", |c| Num(c.contact_angle_rad.to_degrees())),
    ("semi_axis_rolling_mm", |c| Num(c.semi_axis_rolling_m * 1e3)),
    ("semi_axis_lateral_mm", |c| Num(c.semi_axis_lateral_m * 1e3)),
    ("approach_um", |c| Num(c.approach_m * 1e6)),
    ("peak_pressure_mpa", |c| Num(c.peak_pressure_pa * 1e-6)),
    ("rolling_speed_m_s", |c| Num(c.rolling_speed_m_s)),
    ("slip_speed_m_s", |c| Num(c.slip_speed_m_s)),
    ("creep_xi", |c| Num(c.creep_longitudinal)),
    ("creep_eta", |c| Num(c.creep_lateral)),
    ("creep_phi_per_mm", |c| Num(c.creep_spin_per_m * 1e-3)),
    ("creep_heathcote", |c| Num(c.creep_heathcote)),
    ("linear_force_rolling_n", |c| Num(c.linear_force_rolling_n)),
    ("linear_force_lateral_n", |c| Num(c.linear_force_lateral_n)),
    ("linear_spin_moment_nm", |c| Num(c.linear_spin_moment_nm)),
    ("force_rolling_n", |c| Num(c.force_rolling_n)),
    ("force_lateral_n", |c| Num(c.force_lateral_n)),
    ("spin_moment_nm", |c| Num(c.spin_moment_nm)),
    ("saturation", |c| Num(c.saturation)),
    ("friction_bound_n", |c| Num(c.friction_bound_n)),
    ("friction_coefficient", |c| Num(c.friction_coefficient)),
    ("film_central_um", |c| Num(c.film_central_m * 1e6)),
    ("film_minimum_um", |c| Num(c.film_minimum_m * 1e6)),
    ("lambda", |c| Num(c.lambda)),
    ("rolling_resistance_ehl_n", |c| Num(c.rolling_resistance_ehl_n)),
    ("rolling_resistance_hysteresis_n", |c| Num(c.rolling_resistance_hysteresis_n)),
    ("dissipation_per_ball_nm", |c| Num(c.dissipation_per_ball_nm)),
    ("torque_share_nm", |c| Num(c.torque_share_nm)),
    ("creep_torque_share_nm", |c| Num(c.creep_torque_share_nm)),
    ("rolling_torque_share_nm", |c| Num(c.rolling_torque_share_nm)),
    ("hysteresis_torque_share_nm", |c| Num(c.hysteresis_torque_share_nm)),
];

/// The field of `fields` named `key`.
pub fn field<T>(fields: &[Field<T>], key: &str) -> Option<fn(&T) -> Value> {
    fields.iter().find(|(k, _)| *k == key).map(|(_, f)| *f)
}

/// The value as a Python object.
pub fn to_py<'py>(py: Python<'py>, v: Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        Num(x) => x.into_pyobject(py)?.into_any(),
        Int(n) => n.into_pyobject(py)?.into_any(),
        Text(s) => s.into_pyobject(py)?.into_any(),
    })
}

/// Adds every field of `item` to `dict`.
pub fn fill<T>(dict: &Bound<'_, PyDict>, fields: &[Field<T>], item: &T) -> PyResult<()> {
    for (key, get) in fields {
        dict.set_item(*key, to_py(dict.py(), get(item))?)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sweep_columns_are_point_fields_and_keys_are_unique() {
        for k in SWEEP_KEYS.iter().chain(&SWEPT[..3]) {
            assert!(field(POINT, k).is_some(), "{k}");
        }
        let mut keys: Vec<&str> = BALL.iter().map(|f| f.0).chain(CONTACT.iter().map(|f| f.0)).collect();
        let n = keys.len();
        keys.sort_unstable();
        keys.dedup();
        assert_eq!(keys.len(), n);
    }
}
