//! The spec file's shape: the serde structs of its tables (`[geometry]`, `[material]`,
//! `[friction]`, `[operating]`, `[model]`, `[lubricant]`, `[extensions.<name>]`, `[circulation]`, `[uncertainty]`) with the keys as
//! written, units in their names, and the defaults of the optional keys and tables. Unknown keys
//! are refused (`deny_unknown_fields`). Nothing here converts or checks a value: the units go to
//! SI in `conversion.rs`, the ranges are the core's.

use ballscrew_core::input::{
    ContactTheory, CreepCoefficientSource, LoadDistribution, Lubrication, ModelOptions, Preload, Return, SpinMoment,
    TorqueRoute,
};
use core::fmt;
use serde::{Deserialize, Serialize};

/// A whole-number key (nuts, circles, balls, grid), read as any TOML number so that a negative
/// or fractional value gets a range message rather than a type error; written as an integer.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Count(pub(crate) f64);

impl<'de> Deserialize<'de> for Count {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct Number;
        impl serde::de::Visitor<'_> for Number {
            type Value = Count;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a whole number")
            }
            fn visit_f64<E>(self, v: f64) -> Result<Count, E> {
                Ok(Count(v))
            }
            fn visit_i64<E>(self, v: i64) -> Result<Count, E> {
                Ok(Count(v as f64))
            }
            fn visit_u64<E>(self, v: u64) -> Result<Count, E> {
                Ok(Count(v as f64))
            }
        }
        d.deserialize_any(Number)
    }
}

impl Serialize for Count {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let v = self.0;
        if v.fract() == 0.0 && v.abs() <= 9.0e15 { s.serialize_i64(v as i64) } else { s.serialize_f64(v) }
    }
}

/// `[geometry]`: the screw, the nut and the balls (Table 1), lengths in mm, the angle in degrees.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawGeometry {
    pub(crate) pitch_diameter_mm: f64,
    pub(crate) lead_mm: f64,
    pub(crate) ball_diameter_mm: f64,
    pub(crate) conformity_screw: f64,
    pub(crate) conformity_nut: f64,
    pub(crate) contact_angle_deg: f64,
    pub(crate) nuts: Count,
    /// Optional: absent, a double nut for two nuts and no preload for one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) preload: Option<Preload>,
    pub(crate) circles_per_nut: Count,
    pub(crate) balls_per_circle: Count,
}

/// `[material]`: the elastic constants of balls and raceways.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawMaterial {
    pub(crate) youngs_modulus_gpa: f64,
    pub(crate) poisson_ratio: f64,
}

fn default_standstill_rpm() -> f64 {
    0.1
}

/// `[friction]`: the dry model's coefficient and the friction terms beside the contacts.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawFriction {
    /// Optional: absent, Table 1's 0.03 (the dry model's; `lubrication = "ehl"` takes the film's).
    #[serde(default = "default_coefficient")]
    pub(crate) coefficient: f64,
    /// Optional: absent, the loads between balls follow from the ball train (`[circulation]`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) ball_ball_load_n: Option<f64>,
    #[serde(default = "default_standstill_rpm")]
    pub(crate) standstill_speed_rpm: f64,
    #[serde(default = "default_creep_reduction")]
    pub(crate) creep_reduction: f64,
    #[serde(default)]
    pub(crate) seal_torque_per_nut_nm: f64,
}

fn default_creep_reduction() -> f64 {
    1.0
}

/// Table 1's friction coefficient f = 0.03.
pub(crate) const DEFAULT_FRICTION_COEFFICIENT: f64 = 0.03;

fn default_coefficient() -> f64 {
    DEFAULT_FRICTION_COEFFICIENT
}

/// The operating point's speed when `[operating]` leaves it out (Table 1's 100 rpm).
pub(crate) const DEFAULT_SPEED_RPM: f64 = 100.0;

fn default_speed_rpm() -> f64 {
    DEFAULT_SPEED_RPM
}

/// `[operating]`: the spec's operating point; the table is optional. Absent, the speed is
/// 100 rpm and the axial load 0 N. The preload has a default only for a nut without preload
/// (`geometry.preload = "none"`: 0 N): a preload is the screw's own (its maker sets it from the
/// screw's load rating, which the spec does not hold), so a preloaded nut must state it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawOperating {
    #[serde(default = "default_speed_rpm")]
    pub(crate) speed_rpm: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) preload_n: Option<f64>,
    #[serde(default)]
    pub(crate) axial_load_n: f64,
}

impl Default for RawOperating {
    fn default() -> Self {
        Self { speed_rpm: DEFAULT_SPEED_RPM, preload_n: None, axial_load_n: 0.0 }
    }
}

fn default_true() -> bool {
    true
}

fn default_grid() -> Count {
    Count(ballscrew_core::input::DEFAULT_FASTSIM_GRID as f64)
}

/// `[model]`: the model's readings of the paper; every key optional.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawModel {
    #[serde(default)]
    pub(crate) load_distribution: LoadDistribution,
    #[serde(default)]
    pub(crate) creep_coefficients: CreepCoefficientSource,
    #[serde(default)]
    pub(crate) torque: TorqueRoute,
    #[serde(default = "default_true")]
    pub(crate) heathcote: bool,
    #[serde(default)]
    pub(crate) spin_moment: SpinMoment,
    #[serde(default)]
    pub(crate) contact_theory: ContactTheory,
    #[serde(default = "default_grid")]
    pub(crate) fastsim_grid: Count,
    #[serde(default)]
    pub(crate) lubrication: Lubrication,
}

impl Default for RawModel {
    fn default() -> Self {
        Self::from(ModelOptions::default())
    }
}

/// A whole spec file.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawSpec {
    pub(crate) geometry: RawGeometry,
    pub(crate) material: RawMaterial,
    pub(crate) friction: RawFriction,
    #[serde(default)]
    pub(crate) operating: RawOperating,
    #[serde(default)]
    pub(crate) model: RawModel,
    #[serde(default)]
    pub(crate) lubricant: RawLubricant,
    #[serde(default, skip_serializing_if = "RawExtensions::is_empty")]
    pub(crate) extensions: RawExtensions,
    #[serde(default)]
    pub(crate) circulation: RawCirculation,
    #[serde(default, skip_serializing_if = "RawUncertainty::is_empty")]
    pub(crate) uncertainty: RawUncertainty,
}

/// `[uncertainty]`: each uncertain input's half-width (see `ballscrew_core::input::uncertainty`,
/// whose `UNCERTAIN_INPUTS` lists them in this order); every key optional (absent: the input's
/// documented default).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawUncertainty {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) viscosity_relative: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) pressure_viscosity_relative: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) temperature_k: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) roughness_ball_relative: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) roughness_raceway_relative: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) boundary_friction: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) full_film_traction: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) preload_relative: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) friction_coefficient_relative: Option<f64>,
}

impl RawUncertainty {
    /// The keys in `UNCERTAIN_INPUTS`' order.
    pub(crate) fn values(&self) -> [Option<f64>; ballscrew_core::input::INPUTS] {
        [
            self.viscosity_relative,
            self.pressure_viscosity_relative,
            self.temperature_k,
            self.roughness_ball_relative,
            self.roughness_raceway_relative,
            self.boundary_friction,
            self.full_film_traction,
            self.preload_relative,
            self.friction_coefficient_relative,
        ]
    }

    /// From the keys in `UNCERTAIN_INPUTS`' order.
    pub(crate) fn from_values(v: [Option<f64>; ballscrew_core::input::INPUTS]) -> Self {
        let [
            viscosity_relative,
            pressure_viscosity_relative,
            temperature_k,
            roughness_ball_relative,
            roughness_raceway_relative,
            boundary_friction,
            full_film_traction,
            preload_relative,
            friction_coefficient_relative,
        ] = v;
        Self {
            viscosity_relative,
            pressure_viscosity_relative,
            temperature_k,
            roughness_ball_relative,
            roughness_raceway_relative,
            boundary_friction,
            full_film_traction,
            preload_relative,
            friction_coefficient_relative,
        }
    }

    fn is_empty(&self) -> bool {
        self.values().iter().all(Option::is_none)
    }
}

/// `[circulation]`: how the balls circulate (see `ballscrew_core::input::circulation`); every
/// key optional.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawCirculation {
    /// `"internal"` (a deflector, one loaded turn per circuit) or `"external"` (a tube or end
    /// caps).
    #[serde(default, rename = "return")]
    pub(crate) kind: Return,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) turns_per_circuit: Option<Count>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) return_balls: Option<Count>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) return_friction: Option<f64>,
    /// The screw's lead deviation between a nut's first and last circle, um (absent: 0, the
    /// nominal lead).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) lead_deviation_um: Option<f64>,
    /// Balls of the load ramp at each end of a circuit's loaded zone (absent: 0, no ramp).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) load_ramp_balls: Option<Count>,
    /// Whether a spacer ball sits between each two load balls (absent: false).
    #[serde(default, skip_serializing_if = "core::ops::Not::not")]
    pub(crate) spacer_balls: bool,
}

// ---------------------------------------------------------------------------------------------
// The lubricant: `[lubricant]` (see `ballscrew_core::input::lubricant`). Every key is optional;
// absent keys take the default oil's values (ISO VG 68 mineral oil at 40 degrees C).

/// `[lubricant]`: the oil and the surfaces; every key optional.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawLubricant {
    /// ISO 3448 viscosity grade (mineral oil): the 40 C viscosity with the reference oil's
    /// temperature slope. Not together with the viscosities.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) iso_vg: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) viscosity_40c_mm2_s: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) viscosity_100c_mm2_s: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) density_15c_kg_m3: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) density_temperature_coefficient_kg_m3_k: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) pressure_viscosity_per_gpa: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) thermal_conductivity_w_m_k: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) temperature_c: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) roughness_ball_rq_um: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) roughness_raceway_rq_um: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) boundary_friction: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) full_film_traction: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) asperity_load_b: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) asperity_load_c: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) hysteresis_loss_factor: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) inlet_distance_ratio: Option<f64>,
}

// ---------------------------------------------------------------------------------------------
// Extension terms: `[extensions.<name>]` tables (see `ballscrew_core::input::extensions`).

fn default_reference_rpm() -> f64 {
    1000.0
}

/// `[extensions.seal_drag]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawSeal {
    pub(crate) torque_nm: f64,
}

/// `[extensions.viscous_drag]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawViscous {
    pub(crate) torque_nm: f64,
    pub(crate) exponent: f64,
    #[serde(default = "default_reference_rpm")]
    pub(crate) reference_speed_rpm: f64,
}

/// `[extensions.thermal_viscosity]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawThermal {
    pub(crate) torque_nm: f64,
    pub(crate) exponent: f64,
    #[serde(default = "default_reference_rpm")]
    pub(crate) reference_speed_rpm: f64,
    pub(crate) viscosity_coefficient_per_k: f64,
    pub(crate) reference_temperature_c: f64,
}

/// `[extensions.raceway_waviness]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawWaviness {
    pub(crate) harmonic: Count,
    pub(crate) amplitude_nm: f64,
    #[serde(default)]
    pub(crate) phase_deg: f64,
}

/// `[extensions.preload_loss]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPreloadLoss {
    pub(crate) loss_per_1000_h: f64,
}

/// `[extensions.direction_asymmetry]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawAsymmetry {
    pub(crate) reverse_factor: f64,
}

/// `[extensions.level_factor]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawLevelFactor {
    pub(crate) factor: f64,
}

/// `[extensions.preload_law]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPreloadLaw {
    pub(crate) exponent: f64,
    pub(crate) reference_preload_n: f64,
}

/// `[extensions.axial_load_loss]`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawAxialLoss {
    pub(crate) torque_per_kn_nm: f64,
}

/// `[extensions]`: the optional terms beyond the paper, a table each.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawExtensions {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) seal_drag: Option<RawSeal>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) viscous_drag: Option<RawViscous>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) thermal_viscosity: Option<RawThermal>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) raceway_waviness: Option<RawWaviness>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) preload_loss: Option<RawPreloadLoss>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) direction_asymmetry: Option<RawAsymmetry>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) preload_law: Option<RawPreloadLaw>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) axial_load_loss: Option<RawAxialLoss>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub(crate) level_factor: Option<RawLevelFactor>,
}

impl RawExtensions {
    pub(crate) fn is_empty(&self) -> bool {
        *self == Self::default()
    }
}
