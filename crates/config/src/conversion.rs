//! The file's units to the core's SI and back: each table of the file ([`crate::file_format`])
//! to its part of the core's [`ScrewSpec`] (mm to m, GPa to Pa, rpm to rad/s, degrees to
//! radians, whole-number keys to counts, the lubricant's grade or viscosities to an oil) and the
//! spec back to a file's tables, every key written out. Values are checked here only where the
//! core cannot (a whole number, a grade in range, one way to give the oil's viscosity); the
//! ranges are the core's ([`ballscrew_core::screw::model::Model::new`]).

use crate::error::ConfigError;
use crate::file_format::{
    Count, RawAsymmetry, RawAxialLoss, RawCirculation, RawExtensions, RawFriction, RawGeometry, RawLevelFactor,
    RawLubricant, RawMaterial, RawModel, RawOperating, RawPreloadLaw, RawPreloadLoss, RawSeal, RawSpec, RawThermal,
    RawUncertainty, RawViscous, RawWaviness,
};
use crate::keys::{MAX_ISO_VG, MIN_ISO_VG, key_named};
use ballscrew_core::input::extensions::{
    AxialLoadLoss, DirectionAsymmetry, Extensions, LevelFactor, PreloadLaw, PreloadLoss, RacewayWaviness, SealDrag,
    ThermalViscosity, ViscousDrag,
};
use ballscrew_core::input::lubricant::m2_s_to_mm2_s;
use ballscrew_core::input::{
    Circulation, Friction, Geometry, Lubricant, Material, ModelOptions, OperatingPoint, Preload, ScrewSpec,
    UNCERTAIN_INPUTS, Uncertainty, rad_s_to_rpm, rpm_to_rad_s,
};

/// Millimetres per metre.
const MM_PER_M: f64 = 1.0e3;
/// Pascals per gigapascal.
const PA_PER_GPA: f64 = 1.0e9;
/// Metres per micrometre (a product, so that round values such as 0.025 um read exactly as
/// the core's `0.025e-6` m).
const M_PER_UM: f64 = 1.0e-6;
/// Newton metres per kilonewton -> newton metres per newton.
const N_PER_KN: f64 = 1.0e3;

// ---------------------------------------------------------------------------------------------
// The lubricant: a grade or both viscosities, over the default oil (absent keys keep its values).

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
                            "{} (the 40 C viscosity in mm^2/s; a thinner grade's oil is below 2 mm^2/s at 100 C)",
                            key_named("lubricant.iso_vg").valid.code()
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
                return Err(ConfigError::Missing {
                    field: format!("lubricant.{missing}"),
                    valid: "both viscosities (40 and 100 C), or iso_vg alone".to_string(),
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
// Extension terms: `[extensions.<name>]` tables <-> `ballscrew_core::input::extensions`.

impl RawExtensions {
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
// The whole spec: units, file <-> SI.

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
    pub(crate) fn to_spec(self) -> Result<ScrewSpec, ConfigError> {
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
                // Absent, 0 N: `spec_from_toml_str` refuses an absent preload on a preloaded
                // nut before this (`crate::error::missing_preload`).
                preload_n: self.operating.preload_n.unwrap_or(0.0),
                axial_load_n: self.operating.axial_load_n,
            },
            model: self.model.to_core()?,
            lubricant: self.lubricant.to_core()?,
            extensions: self.extensions.to_core()?,
            circulation: Circulation {
                kind: self.circulation.kind,
                turns_per_circuit: match self.circulation.turns_per_circuit {
                    Some(t) => Some(count("circulation.turns_per_circuit", t)?),
                    None => None,
                },
                return_balls: match self.circulation.return_balls {
                    // A count from 0 (a circuit whose return holds no ball).
                    Some(n) if n.0 >= 0.0 => Some(count("circulation.return_balls", n)?),
                    Some(n) => {
                        return Err(ConfigError::Invalid {
                            field: "circulation.return_balls".to_string(),
                            value: n.0,
                            valid: "an integer in [0, 1000]".to_string(),
                        });
                    }
                    None => None,
                },
                return_friction: self.circulation.return_friction,
                lead_deviation_m: self.circulation.lead_deviation_um.map_or(0.0, |v| v * M_PER_UM),
                load_ramp_balls: match self.circulation.load_ramp_balls {
                    None => 0,
                    Some(n) if n.0.is_finite() && n.0 >= 0.0 && n.0.fract() == 0.0 => {
                        if n.0 > u32::MAX as f64 {
                            u32::MAX
                        } else {
                            n.0 as u32
                        }
                    }
                    Some(n) => {
                        return Err(ConfigError::Invalid {
                            field: "circulation.load_ramp_balls".to_string(),
                            value: n.0,
                            valid: "an integer in [0, 4]".to_string(),
                        });
                    }
                },
                spacer_balls: self.circulation.spacer_balls,
            },
            uncertainty: self.uncertainty.to_core(),
        })
    }

    pub(crate) fn from_spec(s: &ScrewSpec) -> Self {
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
                preload_n: Some(s.operating.preload_n),
                axial_load_n: s.operating.axial_load_n,
            },
            model: s.model.into(),
            lubricant: RawLubricant::from_core(&s.lubricant),
            extensions: RawExtensions::from_core(&s.extensions),
            circulation: RawCirculation {
                kind: s.circulation.kind,
                turns_per_circuit: s.circulation.turns_per_circuit.map(|t| Count(f64::from(t))),
                return_balls: s.circulation.return_balls.map(|n| Count(f64::from(n))),
                return_friction: s.circulation.return_friction,
                lead_deviation_um: (s.circulation.lead_deviation_m != 0.0)
                    .then(|| s.circulation.lead_deviation_m / M_PER_UM),
                load_ramp_balls: (s.circulation.load_ramp_balls > 0)
                    .then(|| Count(f64::from(s.circulation.load_ramp_balls))),
                spacer_balls: s.circulation.spacer_balls,
            },
            uncertainty: RawUncertainty::from_core(&s.uncertainty),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The uncertainty: absent keys take the inputs' documented defaults; written back only where a
// half-width differs from its default.

impl RawUncertainty {
    fn to_core(self) -> Uncertainty {
        let values = self.values();
        Uncertainty { half_widths: core::array::from_fn(|i| values[i].unwrap_or(UNCERTAIN_INPUTS[i].default)) }
    }

    fn from_core(u: &Uncertainty) -> Self {
        Self::from_values(core::array::from_fn(|i| {
            let h = u.half_widths[i];
            (h != UNCERTAIN_INPUTS[i].default).then_some(h)
        }))
    }
}
