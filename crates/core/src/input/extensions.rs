//! Terms beyond the paper's physics: the extended model.
//!
//! Xu et al. (2015) leave out lubrication and raceway waviness (their section 3.1); real screws
//! also carry seals, heat up and wear. Each term here is a named physical effect with few
//! parameters, off unless the spec holds it (`[extensions.<name>]` in a TOML spec). They act on
//! the torque of the creep model in three ways:
//!
//! - on the operating point before the model runs: `preload_loss` lowers the effective preload
//!   with running time, `Fp_eff = Fp max(0, 1 - r t / 1000 h)`;
//! - on the model's friction part (torque minus the axial term `F_a L / (2 pi)`):
//!   `preload_law` multiplies it by `(Fp_eff / Fp_ref)^e`, `direction_asymmetry` by the factor
//!   `k_rev` in the reverse direction, `level_factor` by `k` in both (a screw whose drag is the
//!   model's times a constant: the diagnosis's level finding, written into the spec it fits);
//! - as drag torques against the motion, `s(omega) = sign(omega)` times the standstill factor
//!   of the model (docs/model-notes.md item 13), so every term is continuous through standstill:
//!   `seal_drag` `T_s`; `viscous_drag` `c (|omega| / omega_ref)^n`; `thermal_viscosity` the same
//!   with the oil's viscosity `exp(-b (theta - theta_ref))`; `raceway_waviness`
//!   `A sin(2 pi h x / L + phi)` in the nut position x; `axial_load_loss` `k |F_a|`.
//!
//! The conditions the terms need beyond the operating point (nut position, temperature,
//! running time) come in [`Conditions`]; absent values take neutral defaults. Everything here is
//! `no_std` and allocation-free.

use crate::error::{InputError, check_range};
use crate::input::operating::OperatingPoint;
use core::f64::consts::PI;

/// Names of the terms, in the order of [`Extensions`] (the names of the spec tables and of the
/// diagnosis).
pub const NAMES: [&str; 9] = [
    "seal_drag",
    "viscous_drag",
    "thermal_viscosity",
    "raceway_waviness",
    "preload_loss",
    "direction_asymmetry",
    "preload_law",
    "axial_load_loss",
    "level_factor",
];

/// Seals and wipers: a constant torque against the motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SealDrag {
    /// Drag torque, N m (>= 0).
    pub torque_nm: f64,
}

/// Lubricant drag growing with speed: `c (|omega| / omega_ref)^n` against the motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViscousDrag {
    /// Drag torque at the reference speed, N m.
    pub torque_nm: f64,
    /// Speed exponent n, [0.05, 3].
    pub exponent: f64,
    /// Reference speed omega_ref, rad/s: [`MIN_REFERENCE_SPEED_RAD_S`] to
    /// [`MAX_REFERENCE_SPEED_RAD_S`].
    pub reference_speed_rad_s: f64,
}

/// Viscous drag whose level follows the oil's viscosity with temperature (Reynolds' law
/// `eta(theta) = eta_ref exp(-b (theta - theta_ref))`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThermalViscosity {
    /// The drag at the reference temperature.
    pub drag: ViscousDrag,
    /// Viscosity-temperature coefficient b, 1/K, [0, 0.2].
    pub viscosity_coefficient_per_k: f64,
    /// Reference temperature theta_ref, degrees C.
    pub reference_temperature_c: f64,
}

/// Raceway waviness: a torque periodic in the nut position with the lead (one screw
/// revolution) or a harmonic of it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RacewayWaviness {
    /// Harmonic h of the revolution: period `L / h`, [1, 64].
    pub harmonic: u32,
    /// Amplitude A, N m (>= 0).
    pub amplitude_nm: f64,
    /// Phase phi at position 0, rad.
    pub phase_rad: f64,
}

/// Wear: the effective preload falls linearly with running time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreloadLoss {
    /// Fraction of the preload lost per 1000 h of running, [0, 10].
    pub loss_per_1000_h: f64,
}

/// A different friction level in the reverse direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DirectionAsymmetry {
    /// Friction torque in reverse over the friction torque forward, [0.1, 10].
    pub reverse_factor: f64,
}

/// The torque-preload relation differs in shape from the model's (load sharing over circles,
/// contact nonlinearity): the friction part is multiplied by `(Fp / Fp_ref)^e`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreloadLaw {
    /// Exponent e, [-1, 1] (0: the model's shape).
    pub exponent: f64,
    /// Reference preload Fp_ref, N ([`MIN_LAW_REFERENCE_PRELOAD_N`] to 1e7), where the factor is 1.
    pub reference_preload_n: f64,
}

/// Torque growing with the external axial load beyond the model's: `k |F_a|` against the
/// motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxialLoadLoss {
    /// Extra torque per newton of axial load, N m / N.
    pub torque_per_n_nm: f64,
}

/// The model's friction times a constant in both directions: the level a diagnosis finds when
/// the data's drag is the model's times a factor that no physical value of the model's
/// parameters carries.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelFactor {
    /// Friction torque over the model's, [0.01, 100].
    pub factor: f64,
}

/// The extension terms of a spec; `None` is off.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Extensions {
    /// `seal_drag`.
    pub seal_drag: Option<SealDrag>,
    /// `viscous_drag`.
    pub viscous_drag: Option<ViscousDrag>,
    /// `thermal_viscosity`.
    pub thermal_viscosity: Option<ThermalViscosity>,
    /// `raceway_waviness`.
    pub raceway_waviness: Option<RacewayWaviness>,
    /// `preload_loss`.
    pub preload_loss: Option<PreloadLoss>,
    /// `direction_asymmetry`.
    pub direction_asymmetry: Option<DirectionAsymmetry>,
    /// `preload_law`.
    pub preload_law: Option<PreloadLaw>,
    /// `axial_load_loss`.
    pub axial_load_loss: Option<AxialLoadLoss>,
    /// `level_factor`.
    pub level_factor: Option<LevelFactor>,
}

/// What the terms need beyond the operating point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Conditions {
    /// Nut position along the stroke, m (default 0).
    pub position_m: f64,
    /// Temperature, degrees C (`None`: each term's reference temperature).
    pub temperature_c: Option<f64>,
    /// Running time since the start, h (default 0).
    pub time_h: f64,
}

/// Valid nut positions of [`Conditions::position_m`], m (a stroke of 1 km either way).
pub const POSITION_RANGE_M: (f64, f64) = (-1.0e3, 1.0e3);
/// Valid temperatures of [`Conditions::temperature_c`], degrees C.
pub const CONDITION_TEMPERATURE_RANGE_C: (f64, f64) = (-100.0, 300.0);
/// Valid running times of [`Conditions::time_h`], h.
pub const TIME_RANGE_H: (f64, f64) = (0.0, 1.0e7);

impl Conditions {
    /// Checks each field against its range ([`POSITION_RANGE_M`],
    /// [`CONDITION_TEMPERATURE_RANGE_C`], [`TIME_RANGE_H`]): an [`InputError`] naming the first
    /// that is out of it or not finite. A NaN temperature would make a term's viscosity NaN, an
    /// infinite one silently zero it; an infinite position makes the waviness NaN.
    pub fn validate(&self) -> Result<(), InputError> {
        let (lo, hi) = POSITION_RANGE_M;
        check_range("position_m", self.position_m, lo, false, hi, false, "[-1e3, 1e3] m")?;
        if let Some(t) = self.temperature_c {
            let (lo, hi) = CONDITION_TEMPERATURE_RANGE_C;
            check_range("temperature_c", t, lo, false, hi, false, "[-100, 300] degrees C")?;
        }
        let (lo, hi) = TIME_RANGE_H;
        check_range("time_h", self.time_h, lo, false, hi, false, "[0, 1e7] h")?;
        Ok(())
    }
}

/// Smallest preload used in the preload law's ratio, N (the ratio stays finite at zero).
const MIN_LAW_PRELOAD_N: f64 = 1.0;
/// Smallest reference preload of `preload_law`, N: the law's own floor (below it the law holds
/// its value), so that its factor stays within `[1e-7, 1e7]` over the valid preloads (a
/// reference below the floor would be a preload the law never sees; at 1e-320 N the factor was
/// infinite).
pub const MIN_LAW_REFERENCE_PRELOAD_N: f64 = MIN_LAW_PRELOAD_N;
/// Smallest reference speed of `viscous_drag` and `thermal_viscosity`, rad/s (0.01 rpm): a
/// reference speed is a running speed at which the drag is known, not a standstill (at
/// 1e-320 rpm the term was infinite). With it the term stays below 3e6^3 times its torque at the
/// largest valid speed.
pub const MIN_REFERENCE_SPEED_RAD_S: f64 = 0.01 * 2.0 * PI / 60.0;
/// Largest reference speed of `viscous_drag` and `thermal_viscosity`, rad/s.
pub const MAX_REFERENCE_SPEED_RAD_S: f64 = 1.0e4;
/// Valid reference speeds of `viscous_drag` and `thermal_viscosity`, rad/s.
pub const REFERENCE_SPEED_RANGE_RAD_S: (f64, f64) = (MIN_REFERENCE_SPEED_RAD_S, MAX_REFERENCE_SPEED_RAD_S);
/// Valid torques of the terms, N m: [0, 1e4] (`seal_drag`'s torque, `viscous_drag`'s and
/// `thermal_viscosity`'s torque at the reference, `raceway_waviness`'s amplitude).
pub const TORQUE_RANGE_NM: (f64, f64) = (0.0, 1.0e4);
/// Valid speed exponents of `viscous_drag` and `thermal_viscosity`: [0.05, 3].
pub const SPEED_EXPONENT_RANGE: (f64, f64) = (0.05, 3.0);
/// Valid viscosity-temperature coefficients of `thermal_viscosity`, 1/K: [0, 0.2].
pub const VISCOSITY_COEFFICIENT_RANGE_PER_K: (f64, f64) = (0.0, 0.2);
/// Valid reference temperatures of `thermal_viscosity`, degrees C: [-100, 300].
pub const REFERENCE_TEMPERATURE_RANGE_C: (f64, f64) = (-100.0, 300.0);
/// Valid harmonics of `raceway_waviness`: [1, 64].
pub const HARMONIC_RANGE: (f64, f64) = (1.0, 64.0);
/// Valid phases of `raceway_waviness`, rad: [-1e3, 1e3].
pub const PHASE_RANGE_RAD: (f64, f64) = (-1.0e3, 1.0e3);
/// Valid preload losses of `preload_loss`, fraction of the preload per 1000 h: [0, 10].
pub const LOSS_PER_1000_H_RANGE: (f64, f64) = (0.0, 10.0);
/// Valid reverse factors of `direction_asymmetry`: [0.1, 10].
pub const REVERSE_FACTOR_RANGE: (f64, f64) = (0.1, 10.0);
/// Valid factors of `level_factor`: [0.01, 100].
pub const LEVEL_FACTOR_RANGE: (f64, f64) = (0.01, 100.0);
/// Valid exponents of `preload_law`: [-1, 1].
pub const PRELOAD_LAW_EXPONENT_RANGE: (f64, f64) = (-1.0, 1.0);
/// Valid reference preloads of `preload_law`, N: [[`MIN_LAW_REFERENCE_PRELOAD_N`], 1e7].
pub const LAW_REFERENCE_PRELOAD_RANGE_N: (f64, f64) = (MIN_LAW_REFERENCE_PRELOAD_N, 1.0e7);
/// Valid extra torques of `axial_load_loss`, N m per N of axial load: [0, 1].
pub const AXIAL_LOAD_LOSS_RANGE_NM_PER_N: (f64, f64) = (0.0, 1.0);

impl ViscousDrag {
    fn torque_nm(&self, speed_rad_s: f64) -> f64 {
        self.torque_nm * libm::pow(libm::fabs(speed_rad_s) / self.reference_speed_rad_s, self.exponent)
    }
}

impl ThermalViscosity {
    /// Viscosity over its value at the reference temperature.
    pub fn viscosity_ratio(&self, temperature_c: Option<f64>) -> f64 {
        let t = temperature_c.unwrap_or(self.reference_temperature_c);
        libm::exp(-self.viscosity_coefficient_per_k * (t - self.reference_temperature_c))
    }
}

impl RacewayWaviness {
    /// `A sin(2 pi h x / L + phi)`, N m.
    pub fn torque_nm(&self, position_m: f64, lead_m: f64) -> f64 {
        self.amplitude_nm * libm::sin(2.0 * PI * self.harmonic as f64 * position_m / lead_m + self.phase_rad)
    }
}

impl Extensions {
    /// No term.
    pub const NONE: Self = Self {
        seal_drag: None,
        viscous_drag: None,
        thermal_viscosity: None,
        raceway_waviness: None,
        preload_loss: None,
        direction_asymmetry: None,
        preload_law: None,
        axial_load_loss: None,
        level_factor: None,
    };

    /// Whether no term is on.
    pub fn is_empty(&self) -> bool {
        *self == Self::NONE
    }

    /// The operating point the creep model sees: the preload lowered by `preload_loss`.
    pub fn effective_operating(&self, op: &OperatingPoint, cond: &Conditions) -> OperatingPoint {
        let mut eff = *op;
        if let Some(p) = self.preload_loss {
            eff.preload_n = op.preload_n * preload_remaining(p.loss_per_1000_h, cond.time_h);
        }
        eff
    }

    /// The extended torque, N m, from the model's torque `model_torque_nm` and its axial term
    /// `axial_term_nm` at the effective operating point `eff` (see [`Self::effective_operating`]);
    /// `motion` is `direction(omega) s(omega)` (sign of rotation times the standstill factor).
    pub fn torque_nm(
        &self,
        model_torque_nm: f64,
        axial_term_nm: f64,
        eff: &OperatingPoint,
        cond: &Conditions,
        lead_m: f64,
        motion: f64,
    ) -> f64 {
        let mut friction = model_torque_nm - axial_term_nm;
        if let Some(l) = self.preload_law {
            friction *= preload_law_factor(l.exponent, l.reference_preload_n, eff.preload_n);
        }
        if let (Some(d), true) = (self.direction_asymmetry, eff.speed_rad_s < 0.0) {
            friction *= d.reverse_factor;
        }
        if let Some(l) = self.level_factor {
            friction *= l.factor;
        }
        let mut drag = 0.0;
        if let Some(s) = self.seal_drag {
            drag += s.torque_nm;
        }
        if let Some(v) = self.viscous_drag {
            drag += v.torque_nm(eff.speed_rad_s);
        }
        if let Some(t) = self.thermal_viscosity {
            drag += t.drag.torque_nm(eff.speed_rad_s) * t.viscosity_ratio(cond.temperature_c);
        }
        if let Some(w) = self.raceway_waviness {
            drag += w.torque_nm(cond.position_m, lead_m);
        }
        if let Some(a) = self.axial_load_loss {
            drag += a.torque_per_n_nm * libm::fabs(eff.axial_load_n);
        }
        axial_term_nm + friction + motion * drag
    }

    /// Checks every parameter of every term that is on.
    pub fn validate(&self) -> Result<(), InputError> {
        let (torque_lo, torque_hi) = TORQUE_RANGE_NM;
        if let Some(s) = self.seal_drag {
            let field = "extensions.seal_drag.torque_nm";
            check_range(field, s.torque_nm, torque_lo, false, torque_hi, false, "[0, 1e4] N m")?;
        }
        if let Some(v) = self.viscous_drag {
            check_viscous("extensions.viscous_drag", &v)?;
        }
        if let Some(t) = self.thermal_viscosity {
            check_viscous("extensions.thermal_viscosity", &t.drag)?;
            let (lo, hi) = VISCOSITY_COEFFICIENT_RANGE_PER_K;
            check_range(
                "extensions.thermal_viscosity.viscosity_coefficient_per_k",
                t.viscosity_coefficient_per_k,
                lo,
                false,
                hi,
                false,
                "[0, 0.2] 1/K",
            )?;
            let (lo, hi) = REFERENCE_TEMPERATURE_RANGE_C;
            check_range(
                "extensions.thermal_viscosity.reference_temperature_c",
                t.reference_temperature_c,
                lo,
                false,
                hi,
                false,
                "[-100, 300] degrees C",
            )?;
        }
        if let Some(w) = self.raceway_waviness {
            let (lo, hi) = HARMONIC_RANGE;
            check_range(
                "extensions.raceway_waviness.harmonic",
                w.harmonic as f64,
                lo,
                false,
                hi,
                false,
                "integer in [1, 64]",
            )?;
            check_range(
                "extensions.raceway_waviness.amplitude_nm",
                w.amplitude_nm,
                torque_lo,
                false,
                torque_hi,
                false,
                "[0, 1e4] N m",
            )?;
            let (lo, hi) = PHASE_RANGE_RAD;
            check_range("extensions.raceway_waviness.phase_rad", w.phase_rad, lo, false, hi, false, "finite")?;
        }
        if let Some(p) = self.preload_loss {
            let (lo, hi) = LOSS_PER_1000_H_RANGE;
            check_range(
                "extensions.preload_loss.loss_per_1000_h",
                p.loss_per_1000_h,
                lo,
                false,
                hi,
                false,
                "[0, 10] (fraction of the preload per 1000 h)",
            )?;
        }
        if let Some(d) = self.direction_asymmetry {
            let (lo, hi) = REVERSE_FACTOR_RANGE;
            check_range(
                "extensions.direction_asymmetry.reverse_factor",
                d.reverse_factor,
                lo,
                false,
                hi,
                false,
                "[0.1, 10]",
            )?;
        }
        if let Some(l) = self.level_factor {
            let (lo, hi) = LEVEL_FACTOR_RANGE;
            check_range("extensions.level_factor.factor", l.factor, lo, false, hi, false, "[0.01, 100]")?;
        }
        if let Some(l) = self.preload_law {
            let (lo, hi) = PRELOAD_LAW_EXPONENT_RANGE;
            check_range("extensions.preload_law.exponent", l.exponent, lo, false, hi, false, "[-1, 1]")?;
            let (lo, hi) = LAW_REFERENCE_PRELOAD_RANGE_N;
            check_range(
                "extensions.preload_law.reference_preload_n",
                l.reference_preload_n,
                lo,
                false,
                hi,
                false,
                "[1, 1e7] N",
            )?;
        }
        if let Some(a) = self.axial_load_loss {
            let (lo, hi) = AXIAL_LOAD_LOSS_RANGE_NM_PER_N;
            check_range(
                "extensions.axial_load_loss.torque_per_n_nm",
                a.torque_per_n_nm,
                lo,
                false,
                hi,
                false,
                "[0, 1] N m per N",
            )?;
        }
        Ok(())
    }
}

/// Share of the preload left after `time_h` hours at a loss of `loss_per_1000_h`, in [0, 1].
pub fn preload_remaining(loss_per_1000_h: f64, time_h: f64) -> f64 {
    (1.0 - loss_per_1000_h * time_h / 1000.0).clamp(0.0, 1.0)
}

/// `(max(Fp, 1 N) / Fp_ref)^e`.
pub fn preload_law_factor(exponent: f64, reference_preload_n: f64, preload_n: f64) -> f64 {
    libm::pow(preload_n.max(MIN_LAW_PRELOAD_N) / reference_preload_n, exponent)
}

fn check_viscous(field: &'static str, v: &ViscousDrag) -> Result<(), InputError> {
    // The field names of the three parameters under `field` (static strings for InputError).
    let names: [&'static str; 3] = match field {
        "extensions.viscous_drag" => [
            "extensions.viscous_drag.torque_nm",
            "extensions.viscous_drag.exponent",
            "extensions.viscous_drag.reference_speed_rad_s",
        ],
        _ => [
            "extensions.thermal_viscosity.torque_nm",
            "extensions.thermal_viscosity.exponent",
            "extensions.thermal_viscosity.reference_speed_rad_s",
        ],
    };
    let (lo, hi) = TORQUE_RANGE_NM;
    check_range(names[0], v.torque_nm, lo, false, hi, false, "[0, 1e4] N m")?;
    let (lo, hi) = SPEED_EXPONENT_RANGE;
    check_range(names[1], v.exponent, lo, false, hi, false, "[0.05, 3]")?;
    let (lo, hi) = REFERENCE_SPEED_RANGE_RAD_S;
    check_range(
        names[2],
        v.reference_speed_rad_s,
        lo,
        false,
        hi,
        false,
        "[0.00105, 1e4] rad/s, i.e. [0.01, 95492.965] rpm",
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn op(speed: f64) -> OperatingPoint {
        OperatingPoint { speed_rad_s: speed, preload_n: 2000.0, axial_load_n: 500.0 }
    }

    #[test]
    fn no_term_leaves_the_torque_alone() {
        let e = Extensions::NONE;
        let c = Conditions::default();
        assert_eq!(e.torque_nm(0.3, 0.1, &op(10.0), &c, 0.01, 1.0), 0.3);
        assert_eq!(e.effective_operating(&op(10.0), &c), op(10.0));
    }

    #[test]
    fn drag_terms_act_against_the_motion() {
        let e = Extensions {
            seal_drag: Some(SealDrag { torque_nm: 0.05 }),
            viscous_drag: Some(ViscousDrag { torque_nm: 0.02, exponent: 0.5, reference_speed_rad_s: 100.0 }),
            axial_load_loss: Some(AxialLoadLoss { torque_per_n_nm: 1e-5 }),
            ..Extensions::NONE
        };
        let c = Conditions::default();
        // Forward at 4x the reference speed: 0.05 + 0.02 * 2 + 1e-5 * 500.
        let fwd = e.torque_nm(0.3, 0.1, &op(400.0), &c, 0.01, 1.0);
        assert!((fwd - (0.3 + 0.05 + 0.04 + 0.005)).abs() < 1e-12);
        let rev = e.torque_nm(-0.1, 0.1, &op(-400.0), &c, 0.01, -1.0);
        assert!((rev - (-0.1 - 0.095)).abs() < 1e-12);
    }

    #[test]
    fn factors_act_on_the_friction_part_only() {
        let e = Extensions {
            direction_asymmetry: Some(DirectionAsymmetry { reverse_factor: 1.5 }),
            preload_law: Some(PreloadLaw { exponent: -0.5, reference_preload_n: 500.0 }),
            ..Extensions::NONE
        };
        let c = Conditions::default();
        // (2000 / 500)^-0.5 = 0.5 on the friction 0.2 (torque 0.3 minus axial term 0.1).
        assert!((e.torque_nm(0.3, 0.1, &op(1.0), &c, 0.01, 1.0) - 0.2).abs() < 1e-12);
        assert!((e.torque_nm(-0.1, 0.1, &op(-1.0), &c, 0.01, -1.0) - (0.1 - 0.15)).abs() < 1e-12);
        // The level factor scales the friction in both directions, not the axial term; it
        // composes with the others (here 0.5 from the preload law, 1.5 in reverse).
        let e = Extensions { level_factor: Some(LevelFactor { factor: 3.0 }), ..e };
        assert!((e.torque_nm(0.3, 0.1, &op(1.0), &c, 0.01, 1.0) - (0.1 + 0.3)).abs() < 1e-12);
        assert!((e.torque_nm(-0.1, 0.1, &op(-1.0), &c, 0.01, -1.0) - (0.1 - 0.45)).abs() < 1e-12);
        let bad = Extensions { level_factor: Some(LevelFactor { factor: 0.0 }), ..Extensions::NONE };
        assert_eq!(bad.validate().unwrap_err().field, "extensions.level_factor.factor");
    }

    #[test]
    fn waviness_temperature_and_wear_follow_their_conditions() {
        let lead = 0.01;
        let w = RacewayWaviness { harmonic: 2, amplitude_nm: 0.01, phase_rad: 0.0 };
        assert!((w.torque_nm(lead / 8.0, lead) - 0.01).abs() < 1e-15);
        assert!(w.torque_nm(lead / 4.0, lead).abs() < 1e-15);
        let t = ThermalViscosity {
            drag: ViscousDrag { torque_nm: 0.1, exponent: 1.0, reference_speed_rad_s: 100.0 },
            viscosity_coefficient_per_k: 0.02,
            reference_temperature_c: 40.0,
        };
        assert_eq!(t.viscosity_ratio(None), 1.0);
        assert!((t.viscosity_ratio(Some(90.0)) - (-1.0_f64).exp()).abs() < 1e-15);
        let e = Extensions { preload_loss: Some(PreloadLoss { loss_per_1000_h: 0.4 }), ..Extensions::NONE };
        let c = Conditions { time_h: 500.0, ..Conditions::default() };
        assert!((e.effective_operating(&op(1.0), &c).preload_n - 1600.0).abs() < 1e-9);
        assert_eq!(preload_remaining(0.4, 5000.0), 0.0);
    }

    #[test]
    fn bad_parameters_are_named() {
        let e = Extensions {
            preload_law: Some(PreloadLaw { exponent: 2.0, reference_preload_n: 1.0 }),
            ..Extensions::NONE
        };
        assert_eq!(e.validate().unwrap_err().field, "extensions.preload_law.exponent");
        let e = Extensions {
            thermal_viscosity: Some(ThermalViscosity {
                drag: ViscousDrag { torque_nm: 0.1, exponent: f64::NAN, reference_speed_rad_s: 1.0 },
                viscosity_coefficient_per_k: 0.0,
                reference_temperature_c: 20.0,
            }),
            ..Extensions::NONE
        };
        assert_eq!(e.validate().unwrap_err().field, "extensions.thermal_viscosity.exponent");
    }
}
