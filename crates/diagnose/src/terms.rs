//! The candidate causes: each a term of [`ballscrew_core::input::extensions`] with its parameters, what data it
//! needs, where its fit starts and where it is bounded.

use super::data::{Column, Dataset};
use ballscrew_core::input::extensions::{
    AxialLoadLoss, DirectionAsymmetry, Extensions, PreloadLaw, PreloadLoss, RacewayWaviness, SealDrag,
    ThermalViscosity, ViscousDrag,
};
use ballscrew_core::input::rpm_to_rad_s;

/// A candidate cause.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Effect {
    /// Constant torque against the motion.
    SealDrag,
    /// Lubricant drag `c (|w| / w_ref)^n`.
    ViscousDrag,
    /// Viscous drag with the oil's viscosity following temperature.
    ThermalViscosity,
    /// Torque periodic in nut position (lead or a harmonic).
    RacewayWaviness,
    /// Effective preload falling with running time.
    PreloadLoss,
    /// Different friction level in reverse.
    DirectionAsymmetry,
    /// Torque-preload relation of another shape.
    PreloadLaw,
    /// Extra torque growing with the axial load.
    AxialLoadLoss,
}

/// Every candidate, in the order of [`ballscrew_core::input::extensions::NAMES`].
pub const ALL: [Effect; 8] = [
    Effect::SealDrag,
    Effect::ViscousDrag,
    Effect::ThermalViscosity,
    Effect::RacewayWaviness,
    Effect::PreloadLoss,
    Effect::DirectionAsymmetry,
    Effect::PreloadLaw,
    Effect::AxialLoadLoss,
];

/// Reference speed of the viscous terms, rpm.
pub const REFERENCE_SPEED_RPM: f64 = 1000.0;
/// Highest waviness harmonic searched.
pub const MAX_HARMONIC: u32 = 8;

/// Fixed settings of the terms taken from the data (not fitted).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Reference temperature of `thermal_viscosity` (median of the data), degrees C.
    pub reference_temperature_c: f64,
    /// Reference preload of `preload_law` (median of the data), N.
    pub reference_preload_n: f64,
    /// Harmonic of `raceway_waviness` (from the residual's periodogram).
    pub harmonic: u32,
    /// Lead, m.
    pub lead_m: f64,
    /// Typical friction torque of the data, N m (scales starts and bounds).
    pub torque_scale_nm: f64,
    /// Where the fits start the boundary friction (lubricated model): the spec's value for the
    /// physical calibration, the calibrated value after it, so that a level factor takes only
    /// what the physical parameters cannot (with one operating point they cannot be told apart
    /// from it, and stay where the calibration put them).
    pub boundary_start: f64,
}

fn distinct(v: &[f64]) -> usize {
    let mut s: Vec<u64> = v.iter().map(|x| x.to_bits()).collect();
    s.sort_unstable();
    s.dedup();
    s.len()
}

impl Effect {
    /// The name used in the output and in `[extensions.<name>]`.
    pub fn name(self) -> &'static str {
        ballscrew_core::input::extensions::NAMES[self as usize]
    }

    /// The effect of a name.
    pub fn from_name(name: &str) -> Option<Effect> {
        ALL.iter().copied().find(|e| e.name() == name)
    }

    /// Whether the data can show this effect; `Err` says what is missing.
    pub fn applicable(self, d: &Dataset, lead_mm: f64) -> Result<(), String> {
        let varied = |c: Column, k: usize| -> Result<(), String> {
            match d.get(c) {
                None => Err(format!("needs the column `{}`", c.name())),
                Some(v) if distinct(v) < k => Err(format!("needs at least {k} distinct values of `{}`", c.name())),
                Some(_) => Ok(()),
            }
        };
        match self {
            Effect::SealDrag => varied(Column::PreloadN, 3).or_else(|_| varied(Column::AxialLoadN, 3)).map_err(|_| {
                "needs at least 3 distinct preloads (or axial loads) to tell a constant from friction".into()
            }),
            Effect::ViscousDrag => {
                varied(Column::SpeedRpm, 2)?;
                let abs: Vec<f64> = d.get(Column::SpeedRpm).unwrap_or(&[]).iter().map(|v| v.abs()).collect();
                if distinct(&abs) < 3 { Err("needs at least 3 distinct speed magnitudes".into()) } else { Ok(()) }
            }
            Effect::ThermalViscosity => {
                Effect::ViscousDrag.applicable(d, lead_mm)?;
                varied(Column::TemperatureC, 3)
            }
            Effect::RacewayWaviness => {
                varied(Column::PositionMm, 8)?;
                let v = d.get(Column::PositionMm).unwrap_or(&[]);
                let span =
                    v.iter().fold(f64::NEG_INFINITY, |a, &b| a.max(b)) - v.iter().fold(f64::INFINITY, |a, &b| a.min(b));
                if span < lead_mm {
                    Err(format!("needs positions spanning at least one lead ({lead_mm} mm)"))
                } else {
                    Ok(())
                }
            }
            Effect::PreloadLoss => varied(Column::TimeH, 3),
            Effect::DirectionAsymmetry => {
                let v = d.get(Column::SpeedRpm).ok_or("needs the column `speed_rpm`")?;
                if v.iter().any(|s| *s > 0.0) && v.iter().any(|s| *s < 0.0) {
                    Ok(())
                } else {
                    Err("needs speeds in both directions".into())
                }
            }
            Effect::PreloadLaw => varied(Column::PreloadN, 3),
            Effect::AxialLoadLoss => varied(Column::AxialLoadN, 3),
        }
    }

    /// Candidates that describe the same physics: never both in one model.
    pub fn excludes(self, other: Effect) -> bool {
        matches!(
            (self, other),
            (Effect::ViscousDrag, Effect::ThermalViscosity) | (Effect::ThermalViscosity, Effect::ViscousDrag)
        )
    }

    /// The fitted parameters' names (with units) as reported.
    pub fn parameter_names(self) -> &'static [&'static str] {
        match self {
            Effect::SealDrag => &["torque_nm"],
            Effect::ViscousDrag => &["torque_nm", "exponent"],
            Effect::ThermalViscosity => &["torque_nm", "exponent", "viscosity_coefficient_per_k"],
            Effect::RacewayWaviness => &["sine_nm", "cosine_nm"],
            Effect::PreloadLoss => &["loss_per_1000_h"],
            Effect::DirectionAsymmetry => &["reverse_factor"],
            Effect::PreloadLaw => &["exponent"],
            Effect::AxialLoadLoss => &["torque_per_kn_nm"],
        }
    }

    /// Number of fitted parameters.
    pub fn parameters(self) -> usize {
        self.parameter_names().len()
    }

    /// Starting points (one or more) for the parameters.
    pub fn starts(self, s: &Settings) -> Vec<Vec<f64>> {
        let t = s.torque_scale_nm;
        match self {
            Effect::SealDrag => vec![vec![0.1 * t]],
            Effect::ViscousDrag => vec![vec![0.2 * t, 0.5], vec![0.2 * t, 1.2]],
            Effect::ThermalViscosity => vec![vec![0.2 * t, 0.5, 0.02], vec![0.2 * t, 1.2, 0.02]],
            Effect::RacewayWaviness => vec![vec![0.0, 0.0]],
            Effect::PreloadLoss => vec![vec![0.1]],
            Effect::DirectionAsymmetry => vec![vec![1.0]],
            Effect::PreloadLaw => vec![vec![0.0]],
            Effect::AxialLoadLoss => vec![vec![0.01 * t]],
        }
    }

    /// Lower and upper bounds, and a typical size, of each parameter.
    pub fn bounds(self, s: &Settings) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let t = s.torque_scale_nm;
        let big = 100.0 * t;
        match self {
            Effect::SealDrag => (vec![0.0], vec![big], vec![t]),
            Effect::ViscousDrag => (vec![0.0, 0.1], vec![big, 2.5], vec![t, 1.0]),
            Effect::ThermalViscosity => (vec![0.0, 0.1, 0.0], vec![big, 2.5, 0.2], vec![t, 1.0, 0.02]),
            Effect::RacewayWaviness => (vec![-big, -big], vec![big, big], vec![t, t]),
            Effect::PreloadLoss => (vec![0.0], vec![10.0], vec![0.1]),
            Effect::DirectionAsymmetry => (vec![0.2], vec![5.0], vec![1.0]),
            Effect::PreloadLaw => (vec![-0.95], vec![0.95], vec![0.1]),
            Effect::AxialLoadLoss => (vec![0.0], vec![1000.0 * t], vec![t]),
        }
    }

    /// Index of the main parameter (the one the report leads with).
    pub fn main_parameter(self) -> &'static str {
        match self {
            Effect::SealDrag => "torque_nm",
            Effect::ViscousDrag => "exponent",
            Effect::ThermalViscosity => "viscosity_coefficient_per_k",
            Effect::RacewayWaviness => "amplitude_nm",
            Effect::PreloadLoss => "loss_per_1000_h",
            Effect::DirectionAsymmetry => "reverse_factor",
            Effect::PreloadLaw => "exponent",
            Effect::AxialLoadLoss => "torque_per_kn_nm",
        }
    }

    /// Puts the term with parameters `p` into `ext`.
    pub fn apply(self, p: &[f64], s: &Settings, ext: &mut Extensions) {
        let w_ref = rpm_to_rad_s(REFERENCE_SPEED_RPM);
        match self {
            Effect::SealDrag => ext.seal_drag = Some(SealDrag { torque_nm: p[0] }),
            Effect::ViscousDrag => {
                ext.viscous_drag = Some(ViscousDrag { torque_nm: p[0], exponent: p[1], reference_speed_rad_s: w_ref })
            }
            Effect::ThermalViscosity => {
                ext.thermal_viscosity = Some(ThermalViscosity {
                    drag: ViscousDrag { torque_nm: p[0], exponent: p[1], reference_speed_rad_s: w_ref },
                    viscosity_coefficient_per_k: p[2],
                    reference_temperature_c: s.reference_temperature_c,
                })
            }
            Effect::RacewayWaviness => {
                // a sin(t) + b cos(t) = A sin(t + phi), A = hypot(a, b), phi = atan2(b, a).
                ext.raceway_waviness = Some(RacewayWaviness {
                    harmonic: s.harmonic,
                    amplitude_nm: p[0].hypot(p[1]),
                    phase_rad: p[1].atan2(p[0]),
                })
            }
            Effect::PreloadLoss => ext.preload_loss = Some(PreloadLoss { loss_per_1000_h: p[0] }),
            Effect::DirectionAsymmetry => ext.direction_asymmetry = Some(DirectionAsymmetry { reverse_factor: p[0] }),
            Effect::PreloadLaw => {
                ext.preload_law = Some(PreloadLaw { exponent: p[0], reference_preload_n: s.reference_preload_n })
            }
            Effect::AxialLoadLoss => ext.axial_load_loss = Some(AxialLoadLoss { torque_per_n_nm: p[0] / 1000.0 }),
        }
    }

    /// The parameters as reported: name and value (in the units of the name).
    pub fn report(self, p: &[f64], s: &Settings) -> Vec<(&'static str, f64)> {
        let mut e = Extensions::NONE;
        self.apply(p, s, &mut e);
        match self {
            Effect::SealDrag => vec![("torque_nm", p[0])],
            Effect::ViscousDrag => {
                vec![("torque_nm", p[0]), ("exponent", p[1]), ("reference_speed_rpm", REFERENCE_SPEED_RPM)]
            }
            Effect::ThermalViscosity => vec![
                ("torque_nm", p[0]),
                ("exponent", p[1]),
                ("viscosity_coefficient_per_k", p[2]),
                ("reference_speed_rpm", REFERENCE_SPEED_RPM),
                ("reference_temperature_c", s.reference_temperature_c),
            ],
            Effect::RacewayWaviness => {
                let w =
                    e.raceway_waviness.unwrap_or(RacewayWaviness { harmonic: 1, amplitude_nm: 0.0, phase_rad: 0.0 });
                vec![
                    ("amplitude_nm", w.amplitude_nm),
                    ("harmonic", w.harmonic as f64),
                    ("period_mm", s.lead_m * 1000.0 / w.harmonic as f64),
                    ("phase_deg", w.phase_rad.to_degrees()),
                ]
            }
            Effect::PreloadLoss => vec![("loss_per_1000_h", p[0])],
            Effect::DirectionAsymmetry => vec![("reverse_factor", p[0])],
            Effect::PreloadLaw => vec![("exponent", p[0]), ("reference_preload_n", s.reference_preload_n)],
            Effect::AxialLoadLoss => vec![("torque_per_kn_nm", p[0])],
        }
    }

    /// What to check on the machine when the term is found: its practical meaning, for the
    /// report's first paragraph.
    pub fn action(self) -> &'static str {
        match self {
            Effect::SealDrag => "check the seals and wipers (their fit, wear and dirt)",
            Effect::ViscousDrag => "check the oil's grade and temperature (a thicker or colder oil than the spec's)",
            Effect::ThermalViscosity => {
                "check the oil's grade and its temperature in service: the drag follows its viscosity"
            }
            Effect::RacewayWaviness => {
                "check the raceways for waviness or damage at that period (a lead error, a dented track)"
            }
            Effect::PreloadLoss => "the nut is wearing: re-preload it or replace it",
            Effect::DirectionAsymmetry => {
                "check what differs between the directions (a one-sided seal, the return's deflectors, the support's alignment)"
            }
            Effect::PreloadLaw => {
                "check the preload and its arrangement: the drag does not follow the preload as the model's does"
            }
            Effect::AxialLoadLoss => {
                "check the load path (alignment of nut and supports): the drag grows with the axial load beyond the model's"
            }
        }
    }

    /// One sentence on what the term means physically, for the report.
    pub fn meaning(self) -> &'static str {
        match self {
            Effect::SealDrag => "a constant torque against the motion (seals, wipers)",
            Effect::ViscousDrag => "lubricant drag growing with speed as |w|^n",
            Effect::ThermalViscosity => "viscous drag following the oil's viscosity with temperature",
            Effect::RacewayWaviness => "torque periodic in nut position with the screw revolution (raceway waviness)",
            Effect::PreloadLoss => "the effective preload falling with running time (wear)",
            Effect::DirectionAsymmetry => "a different friction level in the reverse direction",
            Effect::PreloadLaw => "a torque-preload relation of another shape than the model's",
            Effect::AxialLoadLoss => "torque growing with the axial load beyond the model's",
        }
    }
}
