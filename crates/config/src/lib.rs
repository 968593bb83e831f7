//! # ballscrew-config
//!
//! TOML screw specs: the file format with units in the key names, mapped to and from the core's
//! [`ScrewSpec`] (SI). A crate of its own because parsing a file needs `std` and allocation,
//! which the no_std core never does.
//!
//! ```toml
//! [geometry]
//! pitch_diameter_mm = 40.0
//! lead_mm = 12.0
//! ball_diameter_mm = 5.953
//! conformity_screw = 0.52
//! conformity_nut = 0.52
//! contact_angle_deg = 45.0
//! nuts = 2
//! preload = "double-nut"           # optional: "double-nut" | "offset-lead" | "oversize-ball" | "none"
//! circles_per_nut = 4
//! balls_per_circle = 19
//! [material]
//! youngs_modulus_gpa = 210.0
//! poisson_ratio = 0.3
//! [friction]
//! coefficient = 0.03
//! ball_ball_load_n = 0.0          # optional, default 0
//! standstill_speed_rpm = 0.1      # optional, default 0.1
//! creep_reduction = 1.0           # optional, default 1
//! seal_torque_per_nut_nm = 0.0    # optional, default 0: seal torque of each nut
//! [operating]
//! speed_rpm = 100.0
//! preload_n = 2000.0
//! axial_load_n = 0.0
//! [model]                          # optional; every key defaults to the decided reading
//! load_distribution = "geometric"  # "geometric" | "paper-literal" | "uniform"
//! creep_coefficients = "kalker-table" # "kalker-table" | "paper-fit"
//! torque = "energy"                # "energy" | "paper-eq27"
//! heathcote = true
//! spin_moment = "combined"         # "combined" | "separate"
//! contact_theory = "linear-saturated" # "linear-saturated" | "fastsim"
//! fastsim_grid = 20                # elements per axis of the ellipse (FASTSIM)
//! lubrication = "ehl"              # "ehl" (lubricated contacts) | "dry" (the paper's model)
//! [lubricant]                      # optional; every key defaults to ISO VG 68 mineral oil at 40 C
//! iso_vg = 68.0                    # ISO 3448 grade, or both viscosities below (not both)
//! # viscosity_40c_mm2_s = 68.0
//! # viscosity_100c_mm2_s = 9.59
//! density_15c_kg_m3 = 870.0
//! density_temperature_coefficient_kg_m3_k = -0.6
//! pressure_viscosity_per_gpa = 22.0
//! thermal_conductivity_w_m_k = 0.134
//! temperature_c = 40.0             # oil temperature at the contacts
//! roughness_ball_rq_um = 0.025
//! roughness_raceway_rq_um = 0.16
//! boundary_friction = 0.15         # mu of asperity contact
//! full_film_traction = 0.03        # traction coefficient of a full film
//! asperity_load_b = 2.32           # asperity load share exp(-B Lambda^C)
//! asperity_load_c = 0.97
//! hysteresis_loss_factor = 0.002
//! # inlet_distance_ratio = 5.0     # starvation (absent: fully flooded)
//! [extensions.seal_drag]           # optional terms beyond the paper (`ballscrew_core::input::extensions`)
//! torque_nm = 0.02
//! ```
//!
//! Every key of every table (`[extensions.<name>]` included), with its unit, default, valid
//! values and meaning, is listed in the spec reference, `docs/spec-reference.md`; the crate's
//! test `tests/spec_reference.rs` checks that page against this parser (the keys, each range
//! end and option, each default).
//!
//! Under `lubrication = "ehl"` the raceway contacts' friction coefficient comes from each
//! contact's film (`[lubricant]`); `friction.coefficient` is the dry model's. The `[lubricant]`
//! table is read and its ranges checked under either model.
//!
//! Unknown keys and tables are rejected with their line and column. Values are checked by the
//! core's own validation ([`Model::new`]); its errors, which name SI fields, are mapped back to
//! the TOML key and unit by one table (`KEYS`).

use ballscrew_core::error::{Error, InputError, Shown};
use ballscrew_core::input::extensions::{
    AxialLoadLoss, DirectionAsymmetry, Extensions, LevelFactor, PreloadLaw, PreloadLoss, RacewayWaviness, SealDrag,
    ThermalViscosity, ViscousDrag,
};
use ballscrew_core::input::geometry::max_balls_per_circle;
use ballscrew_core::input::lubricant::m2_s_to_mm2_s;
use ballscrew_core::input::{
    ContactTheory, CreepCoefficientSource, Friction, Geometry, LoadDistribution, Lubricant, Lubrication, Material,
    ModelOptions, OperatingPoint, Preload, ScrewSpec, SpinMoment, TorqueRoute, rad_s_to_rpm, rpm_to_rad_s,
};
use ballscrew_core::screw::model::Model;
use core::fmt;
use core::ops::Range;
use serde::{Deserialize, Serialize};
use std::path::Path;

/// The built-in spec: DKFZD4012 of Table 1 (`configs/dkfzd4012.toml`).
pub const DKFZD4012_TOML: &str = include_str!("../../../configs/dkfzd4012.toml");

/// Name of the built-in spec in messages and reports (command line and Python alike).
pub const BUILTIN_ORIGIN: &str = "built-in DKFZD4012 (configs/dkfzd4012.toml)";

/// Most preloads of one sweep (a sweep keeps every row's full summary).
pub const MAX_SWEEP_POINTS: usize = 100_000;

/// The default preload sweep: from [`DEFAULT_SWEEP_FROM_N`] to [`DEFAULT_SWEEP_TO_N`] in steps of
/// [`DEFAULT_SWEEP_STEP_N`], N.
pub const DEFAULT_SWEEP_FROM_N: f64 = 500.0;
/// See [`DEFAULT_SWEEP_FROM_N`].
pub const DEFAULT_SWEEP_TO_N: f64 = 3000.0;
/// See [`DEFAULT_SWEEP_FROM_N`].
pub const DEFAULT_SWEEP_STEP_N: f64 = 100.0;

/// Millimetres per metre.
const MM_PER_M: f64 = 1.0e3;
/// Pascals per gigapascal.
const PA_PER_GPA: f64 = 1.0e9;

/// Why a TOML spec was rejected.
#[derive(Debug, Clone, PartialEq)]
pub enum ConfigError {
    /// The text is not valid TOML or does not have the spec's shape (unknown or missing key,
    /// wrong type, unknown option name).
    Parse {
        /// Where the text came from (a file name).
        origin: String,
        /// 1-based line of the offending text.
        line: usize,
        /// 1-based column (in characters).
        column: usize,
        /// What is wrong.
        message: String,
    },
    /// A value is out of its valid range.
    Invalid {
        /// The TOML key, e.g. `geometry.pitch_diameter_mm`.
        field: String,
        /// The value, in the key's unit.
        value: f64,
        /// The valid range, in words.
        valid: String,
    },
    /// The spec passed validation but the model could not be set up.
    Model(Error),
    /// The file could not be read.
    Io {
        /// The path as given.
        path: String,
        /// The operating system's message.
        message: String,
    },
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Keys, file names and the parser's quotes of the text are the user's: their control
        // characters are escaped (`\u{1b}`) so that a message cannot drive the terminal.
        let text = match self {
            ConfigError::Parse { origin, line, column, message } => format!("{origin}:{line}:{column}: {message}"),
            ConfigError::Invalid { field, value, valid } => {
                format!("invalid {field}: {} (valid: {valid})", Shown(*value))
            }
            ConfigError::Model(e) => format!("{e}"),
            ConfigError::Io { path, message } => format!("{path}: {message}"),
        };
        text.chars()
            .try_for_each(|c| if c.is_control() { write!(f, "{}", c.escape_default()) } else { write!(f, "{c}") })
    }
}

impl core::error::Error for ConfigError {}

// ---------------------------------------------------------------------------------------------
// The file's shape (serde).

/// A whole-number key (nuts, circles, balls, grid), read as any TOML number so that a negative
/// or fractional value gets a range message rather than a type error; written as an integer.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Count(f64);

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

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawGeometry {
    pitch_diameter_mm: f64,
    lead_mm: f64,
    ball_diameter_mm: f64,
    conformity_screw: f64,
    conformity_nut: f64,
    contact_angle_deg: f64,
    nuts: Count,
    /// Optional: absent, a double nut for two nuts and no preload for one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    preload: Option<Preload>,
    circles_per_nut: Count,
    balls_per_circle: Count,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMaterial {
    youngs_modulus_gpa: f64,
    poisson_ratio: f64,
}

fn default_standstill_rpm() -> f64 {
    0.1
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFriction {
    coefficient: f64,
    #[serde(default)]
    ball_ball_load_n: f64,
    #[serde(default = "default_standstill_rpm")]
    standstill_speed_rpm: f64,
    #[serde(default = "default_creep_reduction")]
    creep_reduction: f64,
    #[serde(default)]
    seal_torque_per_nut_nm: f64,
}

fn default_creep_reduction() -> f64 {
    1.0
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawOperating {
    speed_rpm: f64,
    preload_n: f64,
    axial_load_n: f64,
}

fn default_true() -> bool {
    true
}

fn default_grid() -> Count {
    Count(ballscrew_core::input::DEFAULT_FASTSIM_GRID as f64)
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawModel {
    #[serde(default)]
    load_distribution: LoadDistribution,
    #[serde(default)]
    creep_coefficients: CreepCoefficientSource,
    #[serde(default)]
    torque: TorqueRoute,
    #[serde(default = "default_true")]
    heathcote: bool,
    #[serde(default)]
    spin_moment: SpinMoment,
    #[serde(default)]
    contact_theory: ContactTheory,
    #[serde(default = "default_grid")]
    fastsim_grid: Count,
    #[serde(default)]
    lubrication: Lubrication,
}

impl Default for RawModel {
    fn default() -> Self {
        Self::from(ModelOptions::default())
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSpec {
    geometry: RawGeometry,
    material: RawMaterial,
    friction: RawFriction,
    operating: RawOperating,
    #[serde(default)]
    model: RawModel,
    #[serde(default)]
    lubricant: RawLubricant,
    #[serde(default, skip_serializing_if = "RawExtensions::is_empty")]
    extensions: RawExtensions,
}

// ---------------------------------------------------------------------------------------------
// The lubricant: `[lubricant]` (see `ballscrew_core::input::lubricant`). Every key is optional;
// absent keys take the default oil's values (ISO VG 68 mineral oil at 40 degrees C).

/// Metres per micrometre (a product, so that round values such as 0.025 um read exactly as
/// the core's `0.025e-6` m).
const M_PER_UM: f64 = 1.0e-6;

/// The thinnest ISO VG grade the file takes: the grade whose oil (with the reference mineral
/// oil's temperature slope) is 2 mm^2/s at 100 degrees C, the lower end of that viscosity's
/// range (5.3626611 to 8 digits), rounded up.
pub const MIN_ISO_VG: f64 = 5.362662;
/// The thickest ISO VG grade the file takes (the upper end of the 40 degrees C viscosity).
pub const MAX_ISO_VG: f64 = 5000.0;

#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawLubricant {
    /// ISO 3448 viscosity grade (mineral oil): the 40 C viscosity with the reference oil's
    /// temperature slope. Not together with the viscosities.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    iso_vg: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    viscosity_40c_mm2_s: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    viscosity_100c_mm2_s: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    density_15c_kg_m3: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    density_temperature_coefficient_kg_m3_k: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pressure_viscosity_per_gpa: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    thermal_conductivity_w_m_k: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    temperature_c: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    roughness_ball_rq_um: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    roughness_raceway_rq_um: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    boundary_friction: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    full_film_traction: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    asperity_load_b: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    asperity_load_c: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    hysteresis_loss_factor: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    inlet_distance_ratio: Option<f64>,
}

impl RawLubricant {
    fn to_core(self) -> Result<Lubricant, ConfigError> {
        let r = self;
        let base = match (r.iso_vg, r.viscosity_40c_mm2_s, r.viscosity_100c_mm2_s) {
            (Some(_), Some(_), _) | (Some(_), _, Some(_)) => {
                return Err(ConfigError::Invalid {
                    field: "lubricant.iso_vg".to_string(),
                    value: r.iso_vg.unwrap_or(f64::NAN),
                    valid: "either iso_vg or viscosity_40c_mm2_s and viscosity_100c_mm2_s, not both".to_string(),
                });
            }
            (Some(grade), None, None) => {
                if !(grade.is_finite() && (MIN_ISO_VG..=MAX_ISO_VG).contains(&grade)) {
                    return Err(ConfigError::Invalid {
                        field: "lubricant.iso_vg".to_string(),
                        value: grade,
                        valid: format!(
                            "[{MIN_ISO_VG}, {MAX_ISO_VG}] (the 40 C viscosity in mm^2/s; a thinner grade's oil is below \
                             2 mm^2/s at 100 C)"
                        ),
                    });
                }
                Lubricant::iso_vg(grade)
            }
            (None, Some(nu40), Some(nu100)) => Lubricant::from_mm2_s(nu40, nu100),
            (None, None, None) => Lubricant::default(),
            (None, Some(_), None) | (None, None, Some(_)) => {
                let missing =
                    if r.viscosity_40c_mm2_s.is_none() { "viscosity_40c_mm2_s" } else { "viscosity_100c_mm2_s" };
                return Err(ConfigError::Invalid {
                    field: format!("lubricant.{missing}"),
                    value: f64::NAN,
                    valid: "both viscosities (40 and 100 C) or iso_vg".to_string(),
                });
            }
        };
        let or = |v: Option<f64>, d: f64| v.unwrap_or(d);
        Ok(Lubricant {
            density_15c_kg_m3: or(r.density_15c_kg_m3, base.density_15c_kg_m3),
            density_temperature_coefficient_kg_m3_k: or(
                r.density_temperature_coefficient_kg_m3_k,
                base.density_temperature_coefficient_kg_m3_k,
            ),
            pressure_viscosity_per_pa: r
                .pressure_viscosity_per_gpa
                .map_or(base.pressure_viscosity_per_pa, |v| v / PA_PER_GPA),
            thermal_conductivity_w_m_k: or(r.thermal_conductivity_w_m_k, base.thermal_conductivity_w_m_k),
            temperature_c: or(r.temperature_c, base.temperature_c),
            roughness_ball_rq_m: r.roughness_ball_rq_um.map_or(base.roughness_ball_rq_m, |v| v * M_PER_UM),
            roughness_raceway_rq_m: r.roughness_raceway_rq_um.map_or(base.roughness_raceway_rq_m, |v| v * M_PER_UM),
            boundary_friction: or(r.boundary_friction, base.boundary_friction),
            full_film_traction: or(r.full_film_traction, base.full_film_traction),
            asperity_load_b: or(r.asperity_load_b, base.asperity_load_b),
            asperity_load_c: or(r.asperity_load_c, base.asperity_load_c),
            hysteresis_loss_factor: or(r.hysteresis_loss_factor, base.hysteresis_loss_factor),
            inlet_distance_ratio: r.inlet_distance_ratio.or(base.inlet_distance_ratio),
            ..base
        })
    }

    /// Every key written out (viscosities, not the grade), so that a written spec reads back
    /// to the same oil.
    fn from_core(l: &Lubricant) -> Self {
        Self {
            iso_vg: None,
            viscosity_40c_mm2_s: Some(m2_s_to_mm2_s(l.viscosity_40c_m2_s)),
            viscosity_100c_mm2_s: Some(m2_s_to_mm2_s(l.viscosity_100c_m2_s)),
            density_15c_kg_m3: Some(l.density_15c_kg_m3),
            density_temperature_coefficient_kg_m3_k: Some(l.density_temperature_coefficient_kg_m3_k),
            pressure_viscosity_per_gpa: Some(l.pressure_viscosity_per_pa * PA_PER_GPA),
            thermal_conductivity_w_m_k: Some(l.thermal_conductivity_w_m_k),
            temperature_c: Some(l.temperature_c),
            roughness_ball_rq_um: Some(l.roughness_ball_rq_m / M_PER_UM),
            roughness_raceway_rq_um: Some(l.roughness_raceway_rq_m / M_PER_UM),
            boundary_friction: Some(l.boundary_friction),
            full_film_traction: Some(l.full_film_traction),
            asperity_load_b: Some(l.asperity_load_b),
            asperity_load_c: Some(l.asperity_load_c),
            hysteresis_loss_factor: Some(l.hysteresis_loss_factor),
            inlet_distance_ratio: l.inlet_distance_ratio,
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Extension terms: `[extensions.<name>]` tables (see `ballscrew_core::input::extensions`).

fn default_reference_rpm() -> f64 {
    1000.0
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSeal {
    torque_nm: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawViscous {
    torque_nm: f64,
    exponent: f64,
    #[serde(default = "default_reference_rpm")]
    reference_speed_rpm: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawThermal {
    torque_nm: f64,
    exponent: f64,
    #[serde(default = "default_reference_rpm")]
    reference_speed_rpm: f64,
    viscosity_coefficient_per_k: f64,
    reference_temperature_c: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawWaviness {
    harmonic: Count,
    amplitude_nm: f64,
    #[serde(default)]
    phase_deg: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPreloadLoss {
    loss_per_1000_h: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawAsymmetry {
    reverse_factor: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawLevelFactor {
    factor: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPreloadLaw {
    exponent: f64,
    reference_preload_n: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawAxialLoss {
    torque_per_kn_nm: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawExtensions {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    seal_drag: Option<RawSeal>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    viscous_drag: Option<RawViscous>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    thermal_viscosity: Option<RawThermal>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    raceway_waviness: Option<RawWaviness>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    preload_loss: Option<RawPreloadLoss>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    direction_asymmetry: Option<RawAsymmetry>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    preload_law: Option<RawPreloadLaw>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    axial_load_loss: Option<RawAxialLoss>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    level_factor: Option<RawLevelFactor>,
}

/// Newton metres per kilonewton -> newton metres per newton.
const N_PER_KN: f64 = 1.0e3;

impl RawExtensions {
    fn is_empty(&self) -> bool {
        *self == Self::default()
    }

    fn to_core(self) -> Result<Extensions, ConfigError> {
        let viscous =
            |torque_nm, exponent, rpm| ViscousDrag { torque_nm, exponent, reference_speed_rad_s: rpm_to_rad_s(rpm) };
        Ok(Extensions {
            seal_drag: self.seal_drag.map(|r| SealDrag { torque_nm: r.torque_nm }),
            viscous_drag: self.viscous_drag.map(|r| viscous(r.torque_nm, r.exponent, r.reference_speed_rpm)),
            thermal_viscosity: self.thermal_viscosity.map(|r| ThermalViscosity {
                drag: viscous(r.torque_nm, r.exponent, r.reference_speed_rpm),
                viscosity_coefficient_per_k: r.viscosity_coefficient_per_k,
                reference_temperature_c: r.reference_temperature_c,
            }),
            raceway_waviness: match self.raceway_waviness {
                Some(r) => Some(RacewayWaviness {
                    harmonic: count("extensions.raceway_waviness.harmonic", r.harmonic)?,
                    amplitude_nm: r.amplitude_nm,
                    phase_rad: r.phase_deg.to_radians(),
                }),
                None => None,
            },
            preload_loss: self.preload_loss.map(|r| PreloadLoss { loss_per_1000_h: r.loss_per_1000_h }),
            direction_asymmetry: self
                .direction_asymmetry
                .map(|r| DirectionAsymmetry { reverse_factor: r.reverse_factor }),
            preload_law: self
                .preload_law
                .map(|r| PreloadLaw { exponent: r.exponent, reference_preload_n: r.reference_preload_n }),
            axial_load_loss: self
                .axial_load_loss
                .map(|r| AxialLoadLoss { torque_per_n_nm: r.torque_per_kn_nm / N_PER_KN }),
            level_factor: self.level_factor.map(|r| LevelFactor { factor: r.factor }),
        })
    }

    fn from_core(e: &Extensions) -> Self {
        let viscous = |v: &ViscousDrag| RawViscous {
            torque_nm: v.torque_nm,
            exponent: v.exponent,
            reference_speed_rpm: rad_s_to_rpm(v.reference_speed_rad_s),
        };
        Self {
            seal_drag: e.seal_drag.map(|s| RawSeal { torque_nm: s.torque_nm }),
            viscous_drag: e.viscous_drag.as_ref().map(viscous),
            thermal_viscosity: e.thermal_viscosity.map(|t| {
                let v = viscous(&t.drag);
                RawThermal {
                    torque_nm: v.torque_nm,
                    exponent: v.exponent,
                    reference_speed_rpm: v.reference_speed_rpm,
                    viscosity_coefficient_per_k: t.viscosity_coefficient_per_k,
                    reference_temperature_c: t.reference_temperature_c,
                }
            }),
            raceway_waviness: e.raceway_waviness.map(|w| RawWaviness {
                harmonic: Count(w.harmonic as f64),
                amplitude_nm: w.amplitude_nm,
                phase_deg: w.phase_rad.to_degrees(),
            }),
            preload_loss: e.preload_loss.map(|p| RawPreloadLoss { loss_per_1000_h: p.loss_per_1000_h }),
            direction_asymmetry: e.direction_asymmetry.map(|d| RawAsymmetry { reverse_factor: d.reverse_factor }),
            preload_law: e
                .preload_law
                .map(|l| RawPreloadLaw { exponent: l.exponent, reference_preload_n: l.reference_preload_n }),
            axial_load_loss: e.axial_load_loss.map(|a| RawAxialLoss { torque_per_kn_nm: a.torque_per_n_nm * N_PER_KN }),
            level_factor: e.level_factor.map(|l| RawLevelFactor { factor: l.factor }),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Model options: file names <-> core enums.

impl RawModel {
    fn to_core(self) -> Result<ModelOptions, ConfigError> {
        let r = self;
        Ok(ModelOptions {
            load_distribution: r.load_distribution,
            creep_coefficients: r.creep_coefficients,
            torque: r.torque,
            heathcote: r.heathcote,
            spin_moment: r.spin_moment,
            contact_theory: r.contact_theory,
            fastsim_grid: count("model.fastsim_grid", r.fastsim_grid)?,
            lubrication: r.lubrication,
        })
    }
}

impl From<ModelOptions> for RawModel {
    fn from(m: ModelOptions) -> Self {
        Self {
            load_distribution: m.load_distribution,
            creep_coefficients: m.creep_coefficients,
            torque: m.torque,
            heathcote: m.heathcote,
            spin_moment: m.spin_moment,
            contact_theory: m.contact_theory,
            fastsim_grid: Count(m.fastsim_grid as f64),
            lubrication: m.lubrication,
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Units: file <-> SI.

/// Converts a whole-number key; non-whole or negative values are rejected here, the range by
/// the core's validation. Values above `u32::MAX` saturate (and then fail the core's range).
fn count(key: &str, c: Count) -> Result<u32, ConfigError> {
    let v = c.0;
    if v.is_finite() && v >= 0.0 && v.fract() == 0.0 {
        Ok(if v > u32::MAX as f64 { u32::MAX } else { v as u32 })
    } else {
        Err(ConfigError::Invalid { field: key.to_string(), value: v, valid: "a whole number >= 1".to_string() })
    }
}

impl RawSpec {
    fn to_spec(self) -> Result<ScrewSpec, ConfigError> {
        let g = &self.geometry;
        let geometry = Geometry {
            pitch_diameter_m: g.pitch_diameter_mm / MM_PER_M,
            lead_m: g.lead_mm / MM_PER_M,
            ball_diameter_m: g.ball_diameter_mm / MM_PER_M,
            conformity_screw: g.conformity_screw,
            conformity_nut: g.conformity_nut,
            contact_angle_rad: g.contact_angle_deg.to_radians(),
            nuts: count("geometry.nuts", g.nuts)?,
            circles_per_nut: count("geometry.circles_per_nut", g.circles_per_nut)?,
            balls_per_circle: count("geometry.balls_per_circle", g.balls_per_circle)?,
            preload: Preload::DoubleNut,
        };
        let geometry =
            Geometry { preload: g.preload.unwrap_or_else(|| Preload::default_for_nuts(geometry.nuts)), ..geometry };
        Ok(ScrewSpec {
            geometry,
            material: Material {
                youngs_modulus_pa: self.material.youngs_modulus_gpa * PA_PER_GPA,
                poisson_ratio: self.material.poisson_ratio,
            },
            friction: Friction {
                coefficient: self.friction.coefficient,
                ball_ball_load_n: self.friction.ball_ball_load_n,
                standstill_speed_rad_s: rpm_to_rad_s(self.friction.standstill_speed_rpm),
                creep_reduction: self.friction.creep_reduction,
                seal_torque_per_nut_nm: self.friction.seal_torque_per_nut_nm,
            },
            operating: OperatingPoint {
                speed_rad_s: rpm_to_rad_s(self.operating.speed_rpm),
                preload_n: self.operating.preload_n,
                axial_load_n: self.operating.axial_load_n,
            },
            model: self.model.to_core()?,
            lubricant: self.lubricant.to_core()?,
            extensions: self.extensions.to_core()?,
        })
    }

    fn from_spec(s: &ScrewSpec) -> Self {
        let g = &s.geometry;
        Self {
            geometry: RawGeometry {
                pitch_diameter_mm: g.pitch_diameter_m * MM_PER_M,
                lead_mm: g.lead_m * MM_PER_M,
                ball_diameter_mm: g.ball_diameter_m * MM_PER_M,
                conformity_screw: g.conformity_screw,
                conformity_nut: g.conformity_nut,
                contact_angle_deg: g.contact_angle_rad.to_degrees(),
                nuts: Count(g.nuts as f64),
                preload: Some(g.preload),
                circles_per_nut: Count(g.circles_per_nut as f64),
                balls_per_circle: Count(g.balls_per_circle as f64),
            },
            material: RawMaterial {
                youngs_modulus_gpa: s.material.youngs_modulus_pa / PA_PER_GPA,
                poisson_ratio: s.material.poisson_ratio,
            },
            friction: RawFriction {
                coefficient: s.friction.coefficient,
                ball_ball_load_n: s.friction.ball_ball_load_n,
                standstill_speed_rpm: rad_s_to_rpm(s.friction.standstill_speed_rad_s),
                creep_reduction: s.friction.creep_reduction,
                seal_torque_per_nut_nm: s.friction.seal_torque_per_nut_nm,
            },
            operating: RawOperating {
                speed_rpm: rad_s_to_rpm(s.operating.speed_rad_s),
                preload_n: s.operating.preload_n,
                axial_load_n: s.operating.axial_load_n,
            },
            model: s.model.into(),
            lubricant: RawLubricant::from_core(&s.lubricant),
            extensions: RawExtensions::from_core(&s.extensions),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The core's field names -> TOML keys.

/// One spec value: its TOML key, the core's field name (as in [`InputError::field`]), where the
/// core's wording names an SI unit the valid range in the key's unit, and how to read the value
/// from the file (in the key's unit).
struct KeyMap {
    toml: &'static str,
    core: &'static str,
    valid: Option<&'static str>,
    value: fn(&RawSpec) -> f64,
}

macro_rules! key {
    ($toml:literal, $core:literal, $valid:expr, |$r:ident| $get:expr) => {
        KeyMap { toml: $toml, core: $core, valid: $valid, value: |$r: &RawSpec| $get }
    };
}

/// Every validated spec value, core field to TOML key.
static KEYS: &[KeyMap] = &[
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
    key!("friction.ball_ball_load_n", "friction.ball_ball_load_n", None, |r| r.friction.ball_ball_load_n),
    key!("friction.standstill_speed_rpm", "friction.standstill_speed_rad_s", Some("(0, 100] rpm"), |r| r
        .friction
        .standstill_speed_rpm),
    key!("operating.speed_rpm", "speed_rad_s", Some("[-30000, 30000] rpm"), |r| r.operating.speed_rpm),
    key!("operating.preload_n", "preload_n", None, |r| r.operating.preload_n),
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

/// Restates the core's error on the file's terms: TOML key, the value as written, its range
/// (with the ends that depend on other keys worked out for `spec`).
fn invalid(raw: &RawSpec, spec: &ScrewSpec, e: &InputError) -> ConfigError {
    if e.field == "geometry.balls_per_circle" {
        let most = max_balls_per_circle(&spec.geometry);
        return ConfigError::Invalid {
            field: e.field.to_string(),
            value: raw.geometry.balls_per_circle.0,
            valid: format!(
                "[1, {most}] (as many as fit one turn of the helix with this pitch diameter, lead and ball)"
            ),
        };
    }
    // A grade stands for both viscosities: their errors are the grade's.
    if let (Some(grade), true) = (raw.lubricant.iso_vg, e.field.starts_with("lubricant.viscosity_")) {
        return ConfigError::Invalid {
            field: "lubricant.iso_vg".to_string(),
            value: grade,
            valid: format!("a grade whose oil has {} in {}", &e.field["lubricant.".len()..], e.valid),
        };
    }
    match KEYS.iter().find(|k| k.core == e.field) {
        Some(k) => ConfigError::Invalid {
            field: k.toml.to_string(),
            value: (k.value)(raw),
            valid: k.valid.unwrap_or(e.valid).to_string(),
        },
        None => ConfigError::Invalid { field: e.field.to_string(), value: e.value, valid: e.valid.to_string() },
    }
}

// ---------------------------------------------------------------------------------------------
// Parse errors: byte offset -> line:column, with the key or table the error sits on.

/// 1-based line and column (in characters) of a byte offset.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let offset = floor_char_boundary(text, offset);
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (line, text[line_start..offset].chars().count() + 1)
}

fn floor_char_boundary(text: &str, offset: usize) -> usize {
    let mut i = offset.min(text.len());
    while !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// The line holding a byte offset.
fn line_at(text: &str, offset: usize) -> &str {
    let offset = floor_char_boundary(text, offset);
    let start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let end = text[offset..].find('\n').map_or(text.len(), |i| offset + i);
    &text[start..end]
}

/// The table name of a header line (`[geometry]` -> `geometry`), if the line is one.
fn header_name(line: &str) -> Option<&str> {
    let t = line.trim_start();
    if !t.starts_with('[') {
        return None;
    }
    let inner = t.trim_start_matches('[');
    let end = inner.find(']')?;
    Some(inner[..end].trim())
}

/// The table of the last header before a byte offset (`None`: the root table).
fn table_at(text: &str, offset: usize) -> Option<&str> {
    let offset = floor_char_boundary(text, offset);
    text[..offset].lines().rev().find_map(header_name)
}

/// The key of a `key = value` line.
fn key_of(line: &str) -> Option<&str> {
    let (k, _) = line.split_once('=')?;
    let k = k.trim();
    (!k.is_empty() && !k.starts_with('#')).then_some(k)
}

/// Rewords serde's message with the table and key its span points at: a span on a table header
/// is that table (a missing key, or an unknown table); an empty span is the root table (a
/// missing table); a span on a `key = value` line is that key.
fn reword(text: &str, span: &Range<usize>, message: &str) -> String {
    let missing = message.strip_prefix("missing field `").map(|r| r.trim_end_matches('`'));
    if span.is_empty() {
        return match missing {
            Some(table) => format!("missing table `[{table}]`"),
            None => message.to_string(),
        };
    }
    let line = line_at(text, span.start);
    if let Some(table) = header_name(line) {
        if let Some(key) = missing {
            return format!("missing key `{table}.{key}`");
        }
        if let Some(rest) = message.strip_prefix("unknown field") {
            return format!("unknown table `[{table}]`{}", rest.trim_start_matches(|c| c != ','));
        }
        return format!("[{table}]: {message}");
    }
    let Some(key) = key_of(line) else { return message.to_string() };
    let table = table_at(text, span.start);
    match (table, message.split_once(", expected")) {
        (Some(table), Some((head, tail))) if message.starts_with("unknown field") => {
            format!("{head} in [{table}], expected{tail}")
        }
        (_, _) if message.starts_with("unknown field") => message.to_string(),
        (Some(table), _) => format!("{table}.{key}: {message}"),
        (None, _) => format!("{key}: {message}"),
    }
}

/// Names serde's Rust types in words: a real-valued key expects "a number" (whole-number keys
/// say "a whole number" themselves, [`Count`]).
fn plain_types(message: &str) -> String {
    message.replace(", expected f64", ", expected a number")
}

fn parse_error(text: &str, origin: &str, e: &toml::de::Error) -> ConfigError {
    let span = e.span().unwrap_or(0..0);
    let (line, column) = line_column(text, span.start);
    let message = reword(text, &span, &plain_types(e.message()));
    ConfigError::Parse { origin: origin.to_string(), line, column, message }
}

// ---------------------------------------------------------------------------------------------
// Public entry points.

/// Parses a TOML spec, converts it to SI and validates it (the core's [`Model::new`]).
///
/// `origin` names the text in error messages (a file name).
pub fn spec_from_toml_str(text: &str, origin: &str) -> Result<ScrewSpec, ConfigError> {
    let raw: RawSpec = toml::from_str(text).map_err(|e| parse_error(text, origin, &e))?;
    let spec = raw.to_spec()?;
    match Model::new(&spec) {
        Ok(_) => Ok(spec),
        Err(Error::Input(e)) => Err(invalid(&raw, &spec, &e)),
        Err(e) => Err(ConfigError::Model(e)),
    }
}

/// Reads and parses a TOML spec file (see [`spec_from_toml_str`]); errors name the path.
pub fn spec_from_toml_file(path: &Path) -> Result<ScrewSpec, ConfigError> {
    let origin = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|e| ConfigError::Io { path: origin.clone(), message: format!("cannot read spec file: {e}") })?;
    spec_from_toml_str(&text, &origin)
}

/// The built-in spec ([`DKFZD4012_TOML`], named [`BUILTIN_ORIGIN`]).
pub fn builtin_spec() -> Result<ScrewSpec, ConfigError> {
    spec_from_toml_str(DKFZD4012_TOML, BUILTIN_ORIGIN)
}

/// Steps of `step` from `lo` until `hi` is reached, the last one possibly shorter (`lo <= hi`,
/// `step > 0`). A range a whole number of steps long is not given one more by rounding: the
/// quotient is shrunk by 1e-12 relative before it is rounded up.
pub fn steps_to_reach(lo: f64, hi: f64, step: f64) -> f64 {
    ((hi - lo) / step * (1.0 - 1e-12)).ceil()
}

/// The points from `lo` to `hi`, both ends included, `step` apart with the last step possibly
/// shorter (see [`steps_to_reach`]); `[lo]` when `lo == hi`. The caller bounds the count.
pub fn range_points(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    let steps = steps_to_reach(lo, hi, step) as usize;
    (0..steps).map(|i| lo + i as f64 * step).chain([hi]).collect()
}

/// The preloads of the default sweep, N: 500 to 3000 in steps of 100.
pub fn default_sweep_preloads_n() -> Vec<f64> {
    range_points(DEFAULT_SWEEP_FROM_N, DEFAULT_SWEEP_TO_N, DEFAULT_SWEEP_STEP_N)
}

/// Writes a spec as TOML (units in the key names); [`spec_from_toml_str`] reads it back.
pub fn spec_to_toml(spec: &ScrewSpec) -> String {
    let body = toml::to_string(&RawSpec::from_spec(spec))
        .unwrap_or_else(|e| format!("# the spec could not be written: {e}\n"));
    format!("# ballscrew screw spec (units in the key names)\n\n{body}")
}

#[cfg(test)]
mod tests {
    use super::*;

    const ORIGIN: &str = "dkfzd4012.toml";

    #[test]
    fn ranges_keep_both_ends_and_no_rounding_step() {
        let d = default_sweep_preloads_n();
        assert_eq!(d.len(), 26);
        assert_eq!((d[0], d[1], d[25]), (500.0, 600.0, 3000.0));
        assert_eq!(range_points(0.0, 250.0, 100.0), [0.0, 100.0, 200.0, 250.0]);
        assert_eq!(range_points(1000.0, 1000.0, 100.0), [1000.0]);
        // 0.9 / 0.03 is 30.000000000000004 in floating point: still 30 steps.
        assert_eq!(steps_to_reach(0.0, 0.9, 0.03), 30.0);
        assert_eq!(range_points(0.0, 0.9, 0.03).len(), 31);
        assert_eq!(steps_to_reach(0.0, 250.0, 100.0), 3.0);
        assert_eq!(builtin_spec().unwrap(), ScrewSpec::dkfzd4012());
    }

    fn close(a: f64, b: f64) -> bool {
        a == b || (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
    }

    fn assert_spec_close(a: &ScrewSpec, b: &ScrewSpec) {
        let (ga, gb) = (&a.geometry, &b.geometry);
        let pairs = [
            (ga.pitch_diameter_m, gb.pitch_diameter_m),
            (ga.lead_m, gb.lead_m),
            (ga.ball_diameter_m, gb.ball_diameter_m),
            (ga.conformity_screw, gb.conformity_screw),
            (ga.conformity_nut, gb.conformity_nut),
            (ga.contact_angle_rad, gb.contact_angle_rad),
            (a.material.youngs_modulus_pa, b.material.youngs_modulus_pa),
            (a.material.poisson_ratio, b.material.poisson_ratio),
            (a.friction.coefficient, b.friction.coefficient),
            (a.friction.ball_ball_load_n, b.friction.ball_ball_load_n),
            (a.friction.standstill_speed_rad_s, b.friction.standstill_speed_rad_s),
            (a.operating.speed_rad_s, b.operating.speed_rad_s),
            (a.operating.preload_n, b.operating.preload_n),
            (a.operating.axial_load_n, b.operating.axial_load_n),
        ];
        for (i, (x, y)) in pairs.iter().enumerate() {
            assert!(close(*x, *y), "field {i}: {x} vs {y}");
        }
        assert_eq!(
            (ga.nuts, ga.preload, ga.circles_per_nut, ga.balls_per_circle),
            (gb.nuts, gb.preload, gb.circles_per_nut, gb.balls_per_circle)
        );
        assert_eq!(a.model, b.model);
    }

    /// `geometry.preload` names the arrangement; absent, two nuts are a double nut and one nut
    /// is a nut without preload (which then takes no preload); an unknown name is refused with
    /// the names that are valid; a name that does not suit `nuts` is refused on `nuts`.
    #[test]
    fn preload_arrangement_key() {
        let base = DKFZD4012_TOML;
        assert_eq!(spec_from_toml_str(base, ORIGIN).unwrap().geometry.preload, Preload::DoubleNut);
        let absent = with_line("geometry", "preload", "");
        assert_eq!(spec_from_toml_str(&absent, ORIGIN).unwrap().geometry.preload, Preload::DoubleNut);
        let one = with_line("geometry", "nuts", "nuts = 1").replace("preload = \"double-nut\"", "");
        let (field, value, _) = invalid_err(&one);
        assert_eq!((field.as_str(), value), ("operating.preload_n", 2000.0), "no preload on a nut without one");
        let one = one.replace("preload_n = 2000.0", "preload_n = 0.0");
        assert_eq!(spec_from_toml_str(&one, ORIGIN).unwrap().geometry.preload, Preload::None);
        for p in Preload::ALL {
            let text = with_line("geometry", "preload", &format!("preload = \"{}\"", p.name()))
                .replace("nuts = 2", &format!("nuts = {}", p.nuts()));
            let text = if p == Preload::None { text.replace("preload_n = 2000.0", "preload_n = 0.0") } else { text };
            assert_eq!(spec_from_toml_str(&text, ORIGIN).unwrap_or_else(|e| panic!("{e}")).geometry.preload, p);
        }
        let (_, _, message) = parse_err(&with_line("geometry", "preload", "preload = \"spring\""));
        for name in ["double-nut", "offset-lead", "oversize-ball", "none"] {
            assert!(message.contains(name), "{message}");
        }
        let (field, value, valid) = invalid_err(&with_line("geometry", "preload", "preload = \"oversize-ball\""));
        assert_eq!((field.as_str(), value), ("geometry.nuts", 2.0), "{valid}");
    }

    /// The built-in file with `key = ...` (first occurrence, within `table`) replaced by `line`.
    fn with_line(table: &str, key: &str, line: &str) -> String {
        let mut in_table = false;
        let mut out = Vec::new();
        for l in DKFZD4012_TOML.lines() {
            if let Some(t) = header_name(l) {
                in_table = t == table;
            }
            if in_table && key_of(l) == Some(key) {
                out.push(line.to_string());
            } else {
                out.push(l.to_string());
            }
        }
        out.join("\n")
    }

    /// The 1-based line of `key` in `table` of the built-in file.
    fn line_of(table: &str, key: &str) -> usize {
        line_of_opt(table, key).unwrap_or_else(|| panic!("{table}.{key} not in the built-in file"))
    }

    /// The 1-based line of `key` in `table` of the built-in file, if it is there.
    fn line_of_opt(table: &str, key: &str) -> Option<usize> {
        let mut in_table = false;
        for (i, l) in DKFZD4012_TOML.lines().enumerate() {
            if let Some(t) = header_name(l) {
                in_table = t == table;
            }
            if in_table && key_of(l) == Some(key) {
                return Some(i + 1);
            }
        }
        None
    }

    fn parse_err(text: &str) -> (usize, usize, String) {
        match spec_from_toml_str(text, ORIGIN) {
            Err(ConfigError::Parse { line, column, message, origin }) => {
                assert_eq!(origin, ORIGIN);
                (line, column, message)
            }
            other => panic!("expected a parse error, got {other:?}"),
        }
    }

    fn invalid_err(text: &str) -> (String, f64, String) {
        match spec_from_toml_str(text, ORIGIN) {
            Err(ConfigError::Invalid { field, value, valid }) => (field, value, valid),
            other => panic!("expected an invalid-value error, got {other:?}"),
        }
    }

    #[test]
    fn embedded_file_is_dkfzd4012() {
        let spec = spec_from_toml_str(DKFZD4012_TOML, ORIGIN).unwrap();
        assert_spec_close(&spec, &ScrewSpec::dkfzd4012());
    }

    #[test]
    fn optional_tables_and_keys_default() {
        let text = DKFZD4012_TOML.split("[model]").next().unwrap().replace("ball_ball_load_n = 0.0", "");
        let text = text.replace("standstill_speed_rpm = 0.1", "");
        let spec = spec_from_toml_str(&text, ORIGIN).unwrap();
        assert_spec_close(&spec, &ScrewSpec::dkfzd4012());
    }

    #[test]
    fn unknown_key_in_each_table_names_key_and_line() {
        for (table, key) in [
            ("geometry", "pitch_diameter_mm"),
            ("material", "poisson_ratio"),
            ("friction", "coefficient"),
            ("operating", "preload_n"),
            ("model", "torque"),
        ] {
            let bad = format!("{key}_typo");
            let value = if table == "model" { "\"energy\"" } else { "1.0" };
            let text = with_line(table, key, &format!("{bad} = {value}"));
            let (line, column, message) = parse_err(&text);
            assert_eq!(line, line_of(table, key), "{message}");
            assert_eq!(column, 1);
            assert!(message.contains(&format!("unknown field `{bad}`")), "{message}");
            assert!(message.contains(&format!("[{table}]")), "{message}");
            assert!(message.contains(&format!("`{key}`")), "the valid keys are listed: {message}");
            let shown = ConfigError::Parse { origin: ORIGIN.into(), line, column, message }.to_string();
            assert!(shown.starts_with(&format!("{ORIGIN}:{line}:1: unknown field")), "{shown}");
        }
    }

    #[test]
    fn unknown_table_rejected() {
        let text = format!("{DKFZD4012_TOML}\n[lubrication]\nviscosity = 1.0\n");
        let (line, _, message) = parse_err(&text);
        assert_eq!(line, DKFZD4012_TOML.lines().count() + 2);
        assert!(message.contains("unknown table `[lubrication]`"), "{message}");
        assert!(message.contains("`geometry`"), "{message}");
    }

    #[test]
    fn missing_required_key_named() {
        let text = with_line("geometry", "lead_mm", "");
        let (line, _, message) = parse_err(&text);
        assert_eq!(message, "missing key `geometry.lead_mm`");
        assert_eq!(line, DKFZD4012_TOML.lines().position(|l| l == "[geometry]").unwrap() + 1);

        let text = DKFZD4012_TOML.replace("[operating]", "[nothing]");
        let (_, _, message) = parse_err(&text);
        assert!(message.contains("[nothing]"), "{message}");

        let text: String = DKFZD4012_TOML.split("[material]").next().unwrap().to_string();
        let (_, _, message) = parse_err(&text);
        assert_eq!(message, "missing table `[material]`");
    }

    #[test]
    fn wrong_type_names_key() {
        let text = with_line("geometry", "lead_mm", "lead_mm = \"twelve\"");
        let (line, _, message) = parse_err(&text);
        assert_eq!(line, line_of("geometry", "lead_mm"));
        assert!(message.starts_with("geometry.lead_mm: "), "{message}");
    }

    #[test]
    fn wrong_type_says_number_or_whole_number() {
        let cases = [
            (
                "geometry",
                "lead_mm",
                "lead_mm = \"twelve\"",
                "geometry.lead_mm: invalid type: string \"twelve\", expected a number",
            ),
            (
                "material",
                "poisson_ratio",
                "poisson_ratio = true",
                "material.poisson_ratio: invalid type: boolean `true`, expected a number",
            ),
            (
                "geometry",
                "nuts",
                "nuts = \"two\"",
                "geometry.nuts: invalid type: string \"two\", expected a whole number",
            ),
            (
                "model",
                "fastsim_grid",
                "fastsim_grid = \"x\"",
                "model.fastsim_grid: invalid type: string \"x\", expected a whole number",
            ),
        ];
        for (table, key, line, message) in cases {
            let (at, _, m) = parse_err(&with_line(table, key, line));
            assert_eq!((at, m.as_str()), (line_of(table, key), message));
        }
        // A negative, fractional or huge grid is a range error, as for the other counts.
        for (line, value) in
            [("fastsim_grid = -1", -1.0), ("fastsim_grid = 2.5", 2.5), ("fastsim_grid = 99999999999", 99999999999.0)]
        {
            let (field, v, _) = invalid_err(&with_line("model", "fastsim_grid", line));
            assert_eq!((field.as_str(), v), ("model.fastsim_grid", value), "{line}");
        }
    }

    #[test]
    fn syntax_error_has_line_and_column() {
        let text = with_line("material", "poisson_ratio", "poisson_ratio = = 0.3");
        let (line, column, _) = parse_err(&text);
        assert_eq!(line, line_of("material", "poisson_ratio"));
        assert!(column > 1);
    }

    #[test]
    fn invalid_values_name_toml_key_value_and_range() {
        let cases = [
            (
                "geometry",
                "conformity_screw",
                "conformity_screw = 0.5",
                "geometry.conformity_screw",
                0.5,
                "[0.501, 0.6]",
            ),
            ("geometry", "contact_angle_deg", "contact_angle_deg = 90", "geometry.contact_angle_deg", 90.0, "[20, 70]"),
            (
                "geometry",
                "ball_diameter_mm",
                "ball_diameter_mm = 40.0",
                "geometry.ball_diameter_mm",
                40.0,
                "pitch diameter",
            ),
            ("geometry", "lead_mm", "lead_mm = -12.0", "geometry.lead_mm", -12.0, "[0.5, 200] mm"),
            (
                "geometry",
                "pitch_diameter_mm",
                "pitch_diameter_mm = 0",
                "geometry.pitch_diameter_mm",
                0.0,
                "[3, 300] mm",
            ),
            // Beyond the physical ranges (these once ended in "did not converge" or were accepted).
            ("geometry", "lead_mm", "lead_mm = 1e300", "geometry.lead_mm", 1e300, "[0.5, 200] mm"),
            (
                "geometry",
                "ball_diameter_mm",
                "ball_diameter_mm = 1e-9",
                "geometry.ball_diameter_mm",
                1e-9,
                "[0.5, 50] mm and below pitch diameter / 2",
            ),
            (
                "material",
                "youngs_modulus_gpa",
                "youngs_modulus_gpa = 1e-300",
                "material.youngs_modulus_gpa",
                1e-300,
                "[1, 1000] GPa",
            ),
            (
                "friction",
                "ball_ball_load_n",
                "ball_ball_load_n = 1e300",
                "friction.ball_ball_load_n",
                1e300,
                "[0, 1000] N",
            ),
            (
                "geometry",
                "conformity_nut",
                "conformity_nut = 0.5000001",
                "geometry.conformity_nut",
                0.5000001,
                "[0.501, 0.6]",
            ),
            (
                "geometry",
                "pitch_diameter_mm",
                "pitch_diameter_mm = 1e9",
                "geometry.pitch_diameter_mm",
                1e9,
                "[3, 300] mm",
            ),
            (
                "friction",
                "standstill_speed_rpm",
                "standstill_speed_rpm = 1e300",
                "friction.standstill_speed_rpm",
                1e300,
                "(0, 100] rpm",
            ),
            (
                "geometry",
                "pitch_diameter_mm",
                "pitch_diameter_mm = 11.0",
                "geometry.ball_diameter_mm",
                5.953,
                "pitch diameter / 2",
            ),
            ("operating", "speed_rpm", "speed_rpm = 1e9", "operating.speed_rpm", 1e9, "[-30000, 30000] rpm"),
            ("operating", "preload_n", "preload_n = -1", "operating.preload_n", -1.0, "[0, 1e7] N"),
            (
                "friction",
                "standstill_speed_rpm",
                "standstill_speed_rpm = 0",
                "friction.standstill_speed_rpm",
                0.0,
                "(0, 100] rpm",
            ),
            (
                "material",
                "youngs_modulus_gpa",
                "youngs_modulus_gpa = -inf",
                "material.youngs_modulus_gpa",
                f64::NEG_INFINITY,
                "[1, 1000] GPa",
            ),
        ];
        for (table, key, line, field, value, valid) in cases {
            let (f, v, r) = invalid_err(&with_line(table, key, line));
            assert_eq!(f, field, "{line}");
            assert_eq!(v, value, "{line}");
            assert!(r.contains(valid), "{line}: {r}");
        }
    }

    #[test]
    fn messages_show_huge_and_tiny_values_in_exponent_form() {
        let cases = [
            ("geometry", "lead_mm", "lead_mm = 1e300", "invalid geometry.lead_mm: 1e300 (valid: [0.5, 200] mm)"),
            (
                "material",
                "youngs_modulus_gpa",
                "youngs_modulus_gpa = 1e-300",
                "invalid material.youngs_modulus_gpa: 1e-300 (valid: [1, 1000] GPa)",
            ),
            (
                "operating",
                "preload_n",
                "preload_n = -2000",
                "invalid operating.preload_n: -2000 (valid: finite, [0, 1e7] N)",
            ),
        ];
        for (table, key, line, shown) in cases {
            let e = spec_from_toml_str(&with_line(table, key, line), ORIGIN).unwrap_err();
            assert_eq!(e.to_string(), shown);
        }
    }

    #[test]
    fn nan_rejected_naming_the_field() {
        for (table, key) in [("geometry", "lead_mm"), ("operating", "speed_rpm"), ("friction", "coefficient")] {
            let (field, value, _) = invalid_err(&with_line(table, key, &format!("{key} = nan")));
            assert_eq!(field, format!("{table}.{key}"));
            assert!(value.is_nan());
        }
        let e = spec_from_toml_str(&with_line("geometry", "lead_mm", "lead_mm = nan"), ORIGIN).unwrap_err();
        assert_eq!(e.to_string(), "invalid geometry.lead_mm: NaN (valid: [0.5, 200] mm)");
    }

    #[test]
    fn counts_reject_negative_and_fractional() {
        for (line, value) in [("nuts = -2", -2.0), ("nuts = 1.5", 1.5), ("nuts = nan", f64::NAN)] {
            let (field, v, valid) = invalid_err(&with_line("geometry", "nuts", line));
            assert_eq!(field, "geometry.nuts");
            assert!(v == value || (v.is_nan() && value.is_nan()), "{line}");
            assert!(valid.contains("whole number"), "{valid}");
        }
        let (field, v, valid) = invalid_err(&with_line("geometry", "nuts", "nuts = 3"));
        assert_eq!((field.as_str(), v, valid.as_str()), ("geometry.nuts", 3.0, "1 or 2"));
        let (field, v, _) = invalid_err(&with_line("geometry", "balls_per_circle", "balls_per_circle = 5000000000"));
        assert_eq!((field.as_str(), v), ("geometry.balls_per_circle", 5.0e9));
        let (field, v, _) = invalid_err(&with_line("geometry", "circles_per_nut", "circles_per_nut = 0"));
        assert_eq!((field.as_str(), v), ("geometry.circles_per_nut", 0.0));
        // A whole float is a count.
        let spec = spec_from_toml_str(&with_line("geometry", "nuts", "nuts = 2.0"), ORIGIN).unwrap();
        assert_eq!(spec.geometry.nuts, 2);
    }

    #[test]
    fn model_options_parsed() {
        let text = DKFZD4012_TOML.split("[model]").next().unwrap().to_string()
            + "[model]\nload_distribution = \"paper-literal\"\ncreep_coefficients = \"paper-fit\"\n\
               torque = \"paper-eq27\"\nheathcote = false\nspin_moment = \"separate\"\nlubrication = \"dry\"\n";
        let spec = spec_from_toml_str(&text, ORIGIN).unwrap();
        assert_eq!(spec.model, ModelOptions { heathcote: false, ..ModelOptions::paper_literal() });
        let text =
            DKFZD4012_TOML.split("[model]").next().unwrap().to_string() + "[model]\nload_distribution = \"uniform\"\n";
        let spec = spec_from_toml_str(&text, ORIGIN).unwrap();
        assert_eq!(
            spec.model,
            ModelOptions { load_distribution: LoadDistribution::Uniform, ..ModelOptions::default() }
        );
    }

    /// Each option's `name()` (what reports print) is the name a spec file takes and writes.
    #[test]
    fn option_names_are_the_spec_file_names() {
        use ballscrew_core::input::{ContactTheory, CreepCoefficientSource, LoadDistribution, SpinMoment, TorqueRoute};
        let mut specs = Vec::new();
        for d in [LoadDistribution::Geometric, LoadDistribution::PaperLiteral, LoadDistribution::Uniform] {
            let mut s = ScrewSpec::dkfzd4012();
            s.model.load_distribution = d;
            specs.push((s, "load_distribution", d.name()));
        }
        for c in [CreepCoefficientSource::KalkerTable, CreepCoefficientSource::PaperFit] {
            let mut s = ScrewSpec::dkfzd4012();
            s.model.creep_coefficients = c;
            specs.push((s, "creep_coefficients", c.name()));
        }
        for t in [TorqueRoute::Energy, TorqueRoute::PaperEq27] {
            let mut s = ScrewSpec::dkfzd4012();
            s.model.torque = t;
            specs.push((s, "torque", t.name()));
        }
        for m in [SpinMoment::Combined, SpinMoment::Separate] {
            let mut s = ScrewSpec::dkfzd4012();
            s.model.spin_moment = m;
            specs.push((s, "spin_moment", m.name()));
        }
        for c in [ContactTheory::LinearSaturated, ContactTheory::Fastsim] {
            let mut s = ScrewSpec::dkfzd4012();
            s.model.contact_theory = c;
            specs.push((s, "contact_theory", c.name()));
        }
        for (spec, key, name) in specs {
            let text = spec_to_toml(&spec);
            assert!(text.contains(&format!("{key} = \"{name}\"")), "{key} = {name} in:\n{text}");
            assert_eq!(spec_from_toml_str(&text, "test").unwrap().model, spec.model);
        }
    }

    #[test]
    fn bad_option_names_list_valid_ones() {
        let cases = [
            ("load_distribution", &["geometric", "paper-literal", "uniform"][..]),
            ("creep_coefficients", &["kalker-table", "paper-fit"][..]),
            ("torque", &["energy", "paper-eq27"][..]),
            ("spin_moment", &["combined", "separate"][..]),
        ];
        for (key, valid) in cases {
            let text = with_line("model", key, &format!("{key} = \"bogus\""));
            let (line, _, message) = parse_err(&text);
            assert_eq!(line, line_of("model", key));
            assert!(message.contains(&format!("model.{key}")), "{message}");
            assert!(message.contains("`bogus`"), "{message}");
            for v in valid {
                assert!(message.contains(&format!("`{v}`")), "{message}");
            }
        }
        let (_, _, message) = parse_err(&with_line("model", "heathcote", "heathcote = \"yes\""));
        assert!(message.contains("model.heathcote"), "{message}");
    }

    #[test]
    fn round_trip() {
        let mut specs = [ScrewSpec::dkfzd4012(); 3];
        specs[1].model = ModelOptions::paper_literal();
        specs[1].operating.speed_rad_s = -7.3;
        specs[1].friction.ball_ball_load_n = 12.5;
        specs[2].geometry.nuts = 1;
        specs[2].geometry.preload = Preload::OversizeBall;
        specs[2].geometry.contact_angle_rad = 0.7;
        specs[2].geometry.pitch_diameter_m = 0.0451;
        specs[2].material.youngs_modulus_pa = 2.07e11;
        for spec in &specs {
            let text = spec_to_toml(spec);
            let back = spec_from_toml_str(&text, "round-trip").unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert_spec_close(&back, spec);
        }
        assert!(spec_to_toml(&specs[0]).contains("nuts = 2\n"));
    }

    #[test]
    fn missing_file_names_path() {
        let e = spec_from_toml_file(Path::new("/nonexistent/dir/spec.toml")).unwrap_err();
        assert!(matches!(e, ConfigError::Io { .. }));
        assert!(e.to_string().starts_with("/nonexistent/dir/spec.toml: "), "{e}");
    }

    #[test]
    fn every_core_field_is_mapped() {
        // Each spec value the core validates has one TOML key, and every key's core name is
        // what the core reports: break each value in turn and check the key that comes back.
        for k in KEYS {
            let (table, key) = k.toml.rsplit_once('.').unwrap();
            // Counts of the [model] table are integers in TOML (nan does not parse): 2 is out of range.
            let bad = if table == "model" { "2" } else { "nan" };
            let text = if table == "lubricant" {
                let lub: Vec<String> = LUBRICANT_TOML
                    .lines()
                    .map(|l| if key_of(l) == Some(key) { format!("{key} = {bad}") } else { l.to_string() })
                    .collect();
                format!("{}\n{}", without_table(DKFZD4012_TOML, "lubricant"), lub.join("\n"))
            } else if line_of_opt(table, key).is_none() && !table.starts_with("extensions") {
                // An optional key the built-in file leaves out: added under its table's header.
                DKFZD4012_TOML.replacen(&format!("[{table}]\n"), &format!("[{table}]\n{key} = {bad}\n"), 1)
            } else if table.starts_with("extensions") {
                // The key is broken in every table that has it; only `table` is kept.
                let ext: Vec<String> = EXTENSIONS_TOML
                    .lines()
                    .map(|l| if key_of(l) == Some(key) { format!("{key} = {bad}") } else { l.to_string() })
                    .collect();
                format!("{DKFZD4012_TOML}\n{}", only_table(&ext.join("\n"), table))
            } else {
                with_line(table, key, &format!("{key} = {bad}"))
            };
            match spec_from_toml_str(&text, ORIGIN) {
                Err(ConfigError::Invalid { field, .. }) => assert_eq!(field, k.toml),
                other => panic!("{}: expected an invalid-value error, got {other:?}", k.toml),
            }
        }
    }

    /// A `[lubricant]` table with every key (valid values, the viscosities rather than a grade).
    const LUBRICANT_TOML: &str = "[lubricant]\nviscosity_40c_mm2_s = 100.0\nviscosity_100c_mm2_s = 11.0\n\
        density_15c_kg_m3 = 880.0\ndensity_temperature_coefficient_kg_m3_k = -0.65\n\
        pressure_viscosity_per_gpa = 20.0\nthermal_conductivity_w_m_k = 0.13\ntemperature_c = 55.0\n\
        roughness_ball_rq_um = 0.03\nroughness_raceway_rq_um = 0.2\nboundary_friction = 0.12\n\
        full_film_traction = 0.04\nasperity_load_b = 2.0\nasperity_load_c = 1.1\n\
        hysteresis_loss_factor = 0.003\ninlet_distance_ratio = 5.0\n";

    /// `text` without its `[table]` (header and keys), if it has one.
    fn without_table(text: &str, table: &str) -> String {
        let mut keep = true;
        let mut out = Vec::new();
        for l in text.lines() {
            if let Some(t) = header_name(l) {
                keep = t != table;
            }
            if keep {
                out.push(l);
            }
        }
        out.join("\n") + "\n"
    }

    /// The built-in file with its `[lubricant]` table replaced by `table`.
    fn with_lubricant(table: &str) -> String {
        format!("{}\n{table}", without_table(DKFZD4012_TOML, "lubricant"))
    }

    #[test]
    fn lubricant_table_read_written_and_read_back() {
        let spec = spec_from_toml_str(&with_lubricant(LUBRICANT_TOML), ORIGIN).unwrap();
        let l = &spec.lubricant;
        assert!(close(l.viscosity_40c_m2_s, 100.0e-6) && close(l.viscosity_100c_m2_s, 11.0e-6), "{l:?}");
        assert!(close(l.pressure_viscosity_per_pa, 2.0e-8) && close(l.roughness_raceway_rq_m, 0.2e-6), "{l:?}");
        assert_eq!((l.temperature_c, l.inlet_distance_ratio), (55.0, Some(5.0)));
        for spec in [spec, ScrewSpec::dkfzd4012()] {
            let text = spec_to_toml(&spec);
            assert!(text.contains("[lubricant]"), "{text}");
            let back = spec_from_toml_str(&text, ORIGIN).unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert_lubricant_close(&back.lubricant, &spec.lubricant);
        }
        // No table: the default oil; a grade alone: that grade with the default slope.
        let spec = spec_from_toml_str(&without_table(DKFZD4012_TOML, "lubricant"), ORIGIN).unwrap();
        assert_eq!(spec.lubricant, Lubricant::default());
        let spec = spec_from_toml_str(&with_lubricant("[lubricant]\niso_vg = 32\n"), ORIGIN).unwrap();
        assert_eq!(spec.lubricant, Lubricant::iso_vg(32.0));
    }

    fn assert_lubricant_close(a: &Lubricant, b: &Lubricant) {
        let pairs = [
            (a.viscosity_40c_m2_s, b.viscosity_40c_m2_s),
            (a.viscosity_100c_m2_s, b.viscosity_100c_m2_s),
            (a.density_15c_kg_m3, b.density_15c_kg_m3),
            (a.density_temperature_coefficient_kg_m3_k, b.density_temperature_coefficient_kg_m3_k),
            (a.pressure_viscosity_per_pa, b.pressure_viscosity_per_pa),
            (a.thermal_conductivity_w_m_k, b.thermal_conductivity_w_m_k),
            (a.temperature_c, b.temperature_c),
            (a.roughness_ball_rq_m, b.roughness_ball_rq_m),
            (a.roughness_raceway_rq_m, b.roughness_raceway_rq_m),
            (a.boundary_friction, b.boundary_friction),
            (a.full_film_traction, b.full_film_traction),
            (a.asperity_load_b, b.asperity_load_b),
            (a.asperity_load_c, b.asperity_load_c),
            (a.hysteresis_loss_factor, b.hysteresis_loss_factor),
        ];
        for (i, (x, y)) in pairs.iter().enumerate() {
            assert!(close(*x, *y), "lubricant field {i}: {x} vs {y}");
        }
        assert_eq!(a.inlet_distance_ratio.is_some(), b.inlet_distance_ratio.is_some());
        if let (Some(x), Some(y)) = (a.inlet_distance_ratio, b.inlet_distance_ratio) {
            assert!(close(x, y));
        }
    }

    #[test]
    fn unknown_lubricant_key_names_line_and_column() {
        let text = with_lubricant("[lubricant]\ntemperature_c = 50.0\n  viscosity_40_mm2_s = 68.0\n");
        let (line, column, message) = parse_err(&text);
        assert_eq!(line, text.lines().position(|l| l.contains("viscosity_40_mm2_s")).unwrap() + 1);
        assert_eq!(column, 3);
        assert!(message.contains("unknown field `viscosity_40_mm2_s`") && message.contains("[lubricant]"), "{message}");
        assert!(message.contains("`viscosity_40c_mm2_s`"), "the valid keys are listed: {message}");
    }

    /// The grade range's ends are where the oil's viscosities leave theirs: the thinnest grade's
    /// oil is valid, a grade 1e-6 thinner is below 2 mm^2/s at 100 degrees C; the thickest
    /// grade's oil is valid.
    #[test]
    fn iso_vg_range_ends_are_the_oils_range_ends() {
        assert!(Lubricant::iso_vg(MIN_ISO_VG).validate().is_ok());
        let e = Lubricant::iso_vg(MIN_ISO_VG * (1.0 - 1e-6)).validate().unwrap_err();
        assert_eq!(e.field, "lubricant.viscosity_100c_mm2_s", "{e}");
        assert!(Lubricant::iso_vg(MAX_ISO_VG).validate().is_ok());
        let (field, value, valid) = invalid_err(&with_lubricant("[lubricant]\niso_vg = 5.3\n"));
        assert_eq!((field.as_str(), value), ("lubricant.iso_vg", 5.3));
        assert!(valid.starts_with("[5.362662, 5000]"), "{valid}");
    }

    #[test]
    fn iso_vg_with_viscosities_is_an_error_naming_the_key() {
        for extra in ["viscosity_40c_mm2_s = 68.0", "viscosity_100c_mm2_s = 9.0"] {
            let e = spec_from_toml_str(&with_lubricant(&format!("[lubricant]\niso_vg = 68\n{extra}\n")), ORIGIN)
                .unwrap_err();
            let shown = e.to_string();
            assert!(matches!(&e, ConfigError::Invalid { field, .. } if field == "lubricant.iso_vg"), "{e:?}");
            assert!(shown.contains("iso_vg") && shown.contains("viscosity_40c_mm2_s"), "{shown}");
        }
        // One viscosity alone names the missing one.
        let (field, _, valid) = invalid_err(&with_lubricant("[lubricant]\nviscosity_40c_mm2_s = 68.0\n"));
        assert_eq!(field, "lubricant.viscosity_100c_mm2_s");
        assert!(valid.contains("iso_vg"), "{valid}");
        // A grade too thin for the viscosity law is the grade's error.
        let (field, value, _) = invalid_err(&with_lubricant("[lubricant]\niso_vg = 2\n"));
        assert_eq!((field.as_str(), value), ("lubricant.iso_vg", 2.0));
    }

    #[test]
    fn bad_lubricant_value_names_key_value_and_range() {
        let cases = [
            ("temperature_c = 250.0", "invalid lubricant.temperature_c: 250 (valid: [-30, 200] degrees C)"),
            ("roughness_ball_rq_um = 7.0", "invalid lubricant.roughness_ball_rq_um: 7 (valid: [0, 5] um)"),
            (
                "pressure_viscosity_per_gpa = 500.0",
                "invalid lubricant.pressure_viscosity_per_gpa: 500 (valid: [1, 100] 1/GPa)",
            ),
            ("viscosity_40c_mm2_s = 68.0\nviscosity_100c_mm2_s = 80.0", "invalid lubricant.viscosity_100c_mm2_s: 80"),
            ("iso_vg = 10000", "invalid lubricant.iso_vg: 10000 (valid: [5.362662, 5000]"),
            ("boundary_friction = 1.5", "invalid lubricant.boundary_friction: 1.5 (valid: [0, 1])"),
        ];
        for (line, shown) in cases {
            let e = spec_from_toml_str(&with_lubricant(&format!("[lubricant]\n{line}\n")), ORIGIN).unwrap_err();
            assert!(e.to_string().starts_with(shown), "{line}: {e}");
        }
    }

    #[test]
    fn lubrication_option_parsed_and_written() {
        let text = DKFZD4012_TOML.split("[model]").next().unwrap().to_string() + "[model]\nlubrication = \"dry\"\n";
        let spec = spec_from_toml_str(&text, ORIGIN).unwrap();
        assert_eq!(spec.model, ModelOptions { lubrication: Lubrication::Dry, ..ModelOptions::default() });
        assert!(spec_to_toml(&spec).contains("lubrication = \"dry\""));
        let text = DKFZD4012_TOML.split("[model]").next().unwrap().to_string() + "[model]\nlubrication = \"wet\"\n";
        let (_, _, message) = parse_err(&text);
        assert!(message.contains("`ehl`") && message.contains("`dry`"), "{message}");
        assert_eq!(builtin_spec().unwrap().model.lubrication, Lubrication::Ehl);
    }

    /// Every extension table with valid values.
    const EXTENSIONS_TOML: &str = "[extensions.seal_drag]\ntorque_nm = 0.02\n\
        [extensions.viscous_drag]\ntorque_nm = 0.01\nexponent = 0.7\nreference_speed_rpm = 1000.0\n\
        [extensions.thermal_viscosity]\ntorque_nm = 0.01\nexponent = 0.7\nreference_speed_rpm = 500.0\n\
        viscosity_coefficient_per_k = 0.03\nreference_temperature_c = 40.0\n\
        [extensions.raceway_waviness]\nharmonic = 2\namplitude_nm = 0.005\nphase_deg = 30.0\n\
        [extensions.preload_loss]\nloss_per_1000_h = 0.3\n\
        [extensions.direction_asymmetry]\nreverse_factor = 1.2\n\
        [extensions.preload_law]\nexponent = -0.2\nreference_preload_n = 1500.0\n\
        [extensions.axial_load_loss]\ntorque_per_kn_nm = 0.3\n";

    /// The lines of one `[table]` of `text`.
    fn only_table(text: &str, table: &str) -> String {
        let mut keep = false;
        let mut out = Vec::new();
        for l in text.lines() {
            if let Some(t) = header_name(l) {
                keep = t == table;
            }
            if keep {
                out.push(l);
            }
        }
        out.join("\n")
    }

    #[test]
    fn extension_tables_round_trip_and_act_on_the_torque() {
        let text = format!("{DKFZD4012_TOML}\n{EXTENSIONS_TOML}");
        let spec = spec_from_toml_str(&text, ORIGIN).unwrap();
        let e = &spec.extensions;
        assert_eq!(e.raceway_waviness.unwrap().harmonic, 2);
        assert!((e.axial_load_loss.unwrap().torque_per_n_nm - 0.3e-3).abs() < 1e-15);
        assert!((e.thermal_viscosity.unwrap().drag.reference_speed_rad_s - rpm_to_rad_s(500.0)).abs() < 1e-12);
        let back = spec_from_toml_str(&spec_to_toml(&spec), ORIGIN).unwrap();
        assert_eq!(back.extensions.seal_drag, e.seal_drag);
        assert_eq!(back.extensions.preload_law, e.preload_law);
        assert!(
            (back.extensions.raceway_waviness.unwrap().phase_rad - e.raceway_waviness.unwrap().phase_rad).abs() < 1e-12
        );
        // The seal drag alone adds its torque to the model's at the spec's operating point.
        let seal = format!("{DKFZD4012_TOML}\n[extensions.seal_drag]\ntorque_nm = 0.02\n");
        let with = Model::new(&spec_from_toml_str(&seal, ORIGIN).unwrap()).unwrap();
        let without = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let op = ScrewSpec::dkfzd4012().operating;
        let mut st = ballscrew_core::screw::model::SolverState::new();
        let d = with.torque(&op, &mut st).unwrap() - without.torque(&op, &mut st).unwrap();
        assert!((d - 0.02).abs() < 1e-9, "{d}");
    }

    #[test]
    fn unknown_extension_table_or_key_is_rejected() {
        let (_, _, m) = parse_err(&format!("{DKFZD4012_TOML}\n[extensions.lubrication]\nviscosity = 1.0\n"));
        assert!(m.contains("lubrication") && m.contains("seal_drag"), "{m}");
        let (line, _, m) = parse_err(&format!("{DKFZD4012_TOML}\n[extensions.seal_drag]\ntorque = 1.0\n"));
        assert_eq!(line, DKFZD4012_TOML.lines().count() + 3);
        assert!(m.contains("unknown field `torque`") && m.contains("torque_nm"), "{m}");
    }

    #[test]
    fn creep_reduction_is_optional_and_checked() {
        let text = DKFZD4012_TOML.replace("coefficient = 0.03", "coefficient = 0.03\ncreep_reduction = 1.5");
        let (field, value, _) = invalid_err(&text);
        assert_eq!((field.as_str(), value), ("friction.creep_reduction", 1.5));
    }

    #[test]
    fn line_column_counts_characters() {
        let text = "a = 1\nb = \"\u{e9}\u{e9}\" x\n";
        let off = text.find(" x").unwrap() + 1;
        assert_eq!(line_column(text, off), (2, 10));
        assert_eq!(line_column(text, 0), (1, 1));
        assert_eq!(line_column(text, text.len() + 5), (3, 1));
    }
}
