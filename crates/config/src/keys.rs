//! The table of keys: every spec value the core validates, by its TOML key (unit in the name),
//! the core's field name, the valid range in the key's unit where the core's wording names an SI
//! unit, and how to read the value as written from the file ([`KEYS`]); and the range of the
//! lubricant's grade, which the file checks itself. The core's errors are restated on the file's
//! terms through this table (`crate::error`). Every key, with its unit, default and meaning, is
//! listed for users in `docs/spec-reference.md`.

use crate::file_format::RawSpec;

/// The thinnest ISO VG grade the file takes: the grade whose oil (with the reference mineral
/// oil's temperature slope) is 2 mm^2/s at 100 degrees C, the lower end of that viscosity's
/// range (5.3626611 to 8 digits), rounded up.
pub const MIN_ISO_VG: f64 = 5.362662;
/// The thickest ISO VG grade the file takes (the upper end of the 40 degrees C viscosity).
pub const MAX_ISO_VG: f64 = 5000.0;

/// One spec value: its TOML key, the core's field name (as in [`ballscrew_core::error::InputError::field`]), where the
/// core's wording names an SI unit the valid range in the key's unit, and how to read the value
/// from the file (in the key's unit).
pub(crate) struct KeyMap {
    pub(crate) toml: &'static str,
    pub(crate) core: &'static str,
    pub(crate) valid: Option<&'static str>,
    pub(crate) value: fn(&RawSpec) -> f64,
}

macro_rules! key {
    ($toml:literal, $core:literal, $valid:expr, |$r:ident| $get:expr) => {
        KeyMap { toml: $toml, core: $core, valid: $valid, value: |$r: &RawSpec| $get }
    };
}

/// Every validated spec value, core field to TOML key.
pub(crate) static KEYS: &[KeyMap] = &[
    key!("geometry.pitch_diameter_mm", "geometry.pitch_diameter_m", Some("[3, 300] mm"), |r| r
        .geometry
        .pitch_diameter_mm),
    key!("geometry.lead_mm", "geometry.lead_m", Some("[0.5, 200] mm"), |r| r.geometry.lead_mm),
    key!(
        "geometry.ball_diameter_mm",
        "geometry.ball_diameter_m",
        Some("[0.5, 50] mm and below pitch diameter / 2"),
        |r| r.geometry.ball_diameter_mm
    ),
    key!("geometry.conformity_screw", "geometry.conformity_screw", None, |r| r.geometry.conformity_screw),
    key!("geometry.conformity_nut", "geometry.conformity_nut", None, |r| r.geometry.conformity_nut),
    key!("geometry.contact_angle_deg", "geometry.contact_angle_rad", Some("[20, 70]"), |r| r
        .geometry
        .contact_angle_deg),
    key!("geometry.nuts", "geometry.nuts", None, |r| r.geometry.nuts.0),
    key!("geometry.circles_per_nut", "geometry.circles_per_nut", None, |r| r.geometry.circles_per_nut.0),
    key!("geometry.balls_per_circle", "geometry.balls_per_circle", None, |r| r.geometry.balls_per_circle.0),
    key!("material.youngs_modulus_gpa", "material.youngs_modulus_pa", Some("[1, 1000] GPa"), |r| r
        .material
        .youngs_modulus_gpa),
    key!("material.poisson_ratio", "material.poisson_ratio", None, |r| r.material.poisson_ratio),
    key!("friction.coefficient", "friction.coefficient", None, |r| r.friction.coefficient),
    key!("friction.ball_ball_load_n", "friction.ball_ball_load_n", None, |r| r
        .friction
        .ball_ball_load_n
        .unwrap_or(f64::NAN)),
    key!("circulation.turns_per_circuit", "circulation.turns_per_circuit", None, |r| r
        .circulation
        .turns_per_circuit
        .map_or(f64::NAN, |c| c.0)),
    key!("circulation.return_balls", "circulation.return_balls", None, |r| r
        .circulation
        .return_balls
        .map_or(f64::NAN, |c| c.0)),
    key!("circulation.return_friction", "circulation.return_friction", None, |r| r
        .circulation
        .return_friction
        .unwrap_or(f64::NAN)),
    key!("friction.standstill_speed_rpm", "friction.standstill_speed_rad_s", Some("(0, 100] rpm"), |r| r
        .friction
        .standstill_speed_rpm),
    key!("operating.speed_rpm", "speed_rad_s", Some("[-30000, 30000] rpm"), |r| r.operating.speed_rpm),
    key!("operating.preload_n", "preload_n", None, |r| r.operating.preload_n.unwrap_or(0.0)),
    key!("operating.axial_load_n", "axial_load_n", None, |r| r.operating.axial_load_n),
    key!("model.fastsim_grid", "model.fastsim_grid", None, |r| r.model.fastsim_grid.0),
    key!("friction.seal_torque_per_nut_nm", "friction.seal_torque_per_nut_nm", None, |r| r
        .friction
        .seal_torque_per_nut_nm),
    key!("lubricant.viscosity_40c_mm2_s", "lubricant.viscosity_40c_mm2_s", None, |r| r
        .lubricant
        .viscosity_40c_mm2_s
        .unwrap_or(f64::NAN)),
    key!("lubricant.viscosity_100c_mm2_s", "lubricant.viscosity_100c_mm2_s", None, |r| r
        .lubricant
        .viscosity_100c_mm2_s
        .unwrap_or(f64::NAN)),
    key!("lubricant.density_15c_kg_m3", "lubricant.density_15c_kg_m3", None, |r| r
        .lubricant
        .density_15c_kg_m3
        .unwrap_or(f64::NAN)),
    key!(
        "lubricant.density_temperature_coefficient_kg_m3_k",
        "lubricant.density_temperature_coefficient_kg_m3_k",
        None,
        |r| r.lubricant.density_temperature_coefficient_kg_m3_k.unwrap_or(f64::NAN)
    ),
    key!("lubricant.pressure_viscosity_per_gpa", "lubricant.pressure_viscosity_per_pa", Some("[1, 100] 1/GPa"), |r| r
        .lubricant
        .pressure_viscosity_per_gpa
        .unwrap_or(f64::NAN)),
    key!("lubricant.thermal_conductivity_w_m_k", "lubricant.thermal_conductivity_w_m_k", None, |r| r
        .lubricant
        .thermal_conductivity_w_m_k
        .unwrap_or(f64::NAN)),
    key!("lubricant.temperature_c", "lubricant.temperature_c", None, |r| r.lubricant.temperature_c.unwrap_or(f64::NAN)),
    key!("lubricant.roughness_ball_rq_um", "lubricant.roughness_ball_rq_m", Some("[0, 5] um"), |r| r
        .lubricant
        .roughness_ball_rq_um
        .unwrap_or(f64::NAN)),
    key!("lubricant.roughness_raceway_rq_um", "lubricant.roughness_raceway_rq_m", Some("(0, 5] um"), |r| r
        .lubricant
        .roughness_raceway_rq_um
        .unwrap_or(f64::NAN)),
    key!("lubricant.boundary_friction", "lubricant.boundary_friction", None, |r| r
        .lubricant
        .boundary_friction
        .unwrap_or(f64::NAN)),
    key!("lubricant.full_film_traction", "lubricant.full_film_traction", None, |r| r
        .lubricant
        .full_film_traction
        .unwrap_or(f64::NAN)),
    key!("lubricant.asperity_load_b", "lubricant.asperity_load_b", None, |r| r
        .lubricant
        .asperity_load_b
        .unwrap_or(f64::NAN)),
    key!("lubricant.asperity_load_c", "lubricant.asperity_load_c", None, |r| r
        .lubricant
        .asperity_load_c
        .unwrap_or(f64::NAN)),
    key!("lubricant.hysteresis_loss_factor", "lubricant.hysteresis_loss_factor", None, |r| r
        .lubricant
        .hysteresis_loss_factor
        .unwrap_or(f64::NAN)),
    key!("lubricant.inlet_distance_ratio", "lubricant.inlet_distance_ratio", None, |r| r
        .lubricant
        .inlet_distance_ratio
        .unwrap_or(f64::NAN)),
    key!(
        "extensions.viscous_drag.reference_speed_rpm",
        "extensions.viscous_drag.reference_speed_rad_s",
        Some("[0.01, 95492.965] rpm (the upper end is 1e4 rad/s)"),
        |r| r.extensions.viscous_drag.map_or(f64::NAN, |v| v.reference_speed_rpm)
    ),
    key!(
        "extensions.thermal_viscosity.reference_speed_rpm",
        "extensions.thermal_viscosity.reference_speed_rad_s",
        Some("[0.01, 95492.965] rpm (the upper end is 1e4 rad/s)"),
        |r| r.extensions.thermal_viscosity.map_or(f64::NAN, |v| v.reference_speed_rpm)
    ),
    key!(
        "extensions.raceway_waviness.phase_deg",
        "extensions.raceway_waviness.phase_rad",
        Some("[-57295.779, 57295.779] deg (1000 rad)"),
        |r| r.extensions.raceway_waviness.map_or(f64::NAN, |v| v.phase_deg)
    ),
    key!(
        "extensions.axial_load_loss.torque_per_kn_nm",
        "extensions.axial_load_loss.torque_per_n_nm",
        Some("[0, 1000] N m per kN"),
        |r| r.extensions.axial_load_loss.map_or(f64::NAN, |v| v.torque_per_kn_nm)
    ),
];
