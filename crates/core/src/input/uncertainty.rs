//! The uncertain inputs of a prediction: which of the spec's values nobody measures on a given
//! screw, how far each may lie from the value the spec states, and where that spread comes from.
//!
//! A spec states one value for each input (the nominal); `[uncertainty]` states, for each input
//! below, a half-width: the input lies anywhere in `nominal (1 +- h)` for a relative spread, or
//! `nominal +- h` for an absolute one, with every value of that range equally likely (a uniform
//! distribution: a tolerance, not a measured scatter). A half-width of 0 pins the input at its
//! nominal value. The defaults, each with its source, are in [`UNCERTAIN_INPUTS`].
//!
//! What the spread does to the torque (the band of its quantiles, each input's share of it) is
//! computed above the model (`ballscrew_batch::uncertainty`): here are only the inputs and their
//! half-widths; [`crate::input::ScrewSpec::spread_to`] moves a spec and an operating point to one
//! sample's values.

use crate::error::{InputError, check_range};
use crate::input::options::Lubrication;

/// How many uncertain inputs there are.
pub const INPUTS: usize = 9;

/// How an input's half-width spreads it about its nominal value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Spread {
    /// `nominal (1 + u h)`, `u` in [-1, 1]: a share of the nominal value.
    Relative,
    /// `nominal + u h`, `u` in [-1, 1]: in the input's own unit.
    Absolute,
}

/// Which model reads an input.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ReadBy {
    /// Only the lubricated model (`lubrication = "ehl"`).
    Lubricated,
    /// Only the dry model (`lubrication = "dry"`).
    Dry,
    /// Both.
    Both,
}

/// One uncertain input: its key in `[uncertainty]`, what it spreads and its default half-width
/// with the source of that default.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UncertainInput {
    /// The key in the spec's `[uncertainty]` table (its unit at the end of its name).
    pub key: &'static str,
    /// `uncertainty.<key>`: the field errors name.
    pub field: &'static str,
    /// A short name for tables and charts, e.g. `viscosity`.
    pub name: &'static str,
    /// The spec value (or operating value) it spreads, in the spec file's words.
    pub spreads: &'static str,
    /// Relative or absolute.
    pub spread: Spread,
    /// The half-width's unit: `1` (a share, or a plain number) or `K`.
    pub unit: &'static str,
    /// The default half-width.
    pub default: f64,
    /// The valid half-widths (closed).
    pub range: (f64, f64),
    /// The valid half-widths in words.
    pub valid: &'static str,
    /// Which model reads it.
    pub read_by: ReadBy,
    /// Where the default comes from.
    pub source: &'static str,
}

impl UncertainInput {
    /// Whether the model `lubrication` reads this input.
    pub fn read_under(&self, lubrication: Lubrication) -> bool {
        match self.read_by {
            ReadBy::Both => true,
            ReadBy::Lubricated => lubrication == Lubrication::Ehl,
            ReadBy::Dry => lubrication == Lubrication::Dry,
        }
    }
}

/// One row of [`UNCERTAIN_INPUTS`]: a relative spread (unit `1`, [`RELATIVE_RANGE`]), or an
/// absolute spread of a friction coefficient ([`ABSOLUTE_FRICTION_RANGE`]). Any other absolute
/// spread (the temperature's, in K) is written out in full.
#[allow(clippy::too_many_arguments, reason = "a row of the table: one argument per column")]
const fn input(
    key: &'static str,
    field: &'static str,
    name: &'static str,
    spreads: &'static str,
    kind: Row,
    default: f64,
    read_by: ReadBy,
    source: &'static str,
) -> UncertainInput {
    let (spread, range, valid) = match kind {
        Row::Relative => (Spread::Relative, RELATIVE_RANGE, "[0, 0.9] (a share of the value)"),
        Row::Friction => (Spread::Absolute, ABSOLUTE_FRICTION_RANGE, "[0, 0.5]"),
    };
    UncertainInput { key, field, name, spreads, spread, unit: "1", default, range, valid, read_by, source }
}

/// The rows [`input`] writes.
#[derive(Clone, Copy)]
enum Row {
    /// A relative spread.
    Relative,
    /// An absolute spread of a friction coefficient.
    Friction,
}

/// Valid relative half-widths: [0, 0.9] (the value stays above a tenth of its nominal).
pub const RELATIVE_RANGE: (f64, f64) = (0.0, 0.9);
/// Valid absolute half-widths of a friction coefficient: [0, 0.5].
pub const ABSOLUTE_FRICTION_RANGE: (f64, f64) = (0.0, 0.5);
/// Valid half-widths of the oil temperature, K: [0, 50].
pub const TEMPERATURE_RANGE_K: (f64, f64) = (0.0, 50.0);

/// Index of each input in [`UNCERTAIN_INPUTS`] and [`Uncertainty::half_widths`].
pub mod index {
    /// Viscosity (both reference viscosities by one factor).
    pub const VISCOSITY: usize = 0;
    /// Pressure-viscosity coefficient.
    pub const PRESSURE_VISCOSITY: usize = 1;
    /// Oil temperature at the contacts.
    pub const TEMPERATURE: usize = 2;
    /// Roughness of the balls.
    pub const ROUGHNESS_BALL: usize = 3;
    /// Roughness of the raceways.
    pub const ROUGHNESS_RACEWAY: usize = 4;
    /// Boundary friction.
    pub const BOUNDARY_FRICTION: usize = 5;
    /// Full-film traction.
    pub const FULL_FILM_TRACTION: usize = 6;
    /// Preload.
    pub const PRELOAD: usize = 7;
    /// The dry model's friction coefficient.
    pub const FRICTION_COEFFICIENT: usize = 8;
}

/// The uncertain inputs, in the order of [`Uncertainty::half_widths`].
pub const UNCERTAIN_INPUTS: [UncertainInput; INPUTS] = [
    input(
        "viscosity_relative",
        "uncertainty.viscosity_relative",
        "viscosity",
        "lubricant.viscosity_40c_mm2_s and viscosity_100c_mm2_s (or iso_vg), by one factor",
        Row::Relative,
        0.10,
        ReadBy::Lubricated,
        "ISO 3448: a grade's kinematic viscosity at 40 C lies within +-10 % of its midpoint",
    ),
    input(
        "pressure_viscosity_relative",
        "uncertainty.pressure_viscosity_relative",
        "pressure-viscosity",
        "lubricant.pressure_viscosity_per_gpa",
        Row::Relative,
        0.25,
        ReadBy::Lubricated,
        "Stachowiak & Batchelor, Engineering Tribology, Table 2.3: mineral oils 16-35 1/GPa at 30-60 C",
    ),
    UncertainInput {
        key: "temperature_k",
        field: "uncertainty.temperature_k",
        name: "oil temperature",
        spreads: "lubricant.temperature_c",
        spread: Spread::Absolute,
        unit: "K",
        default: 5.0,
        range: TEMPERATURE_RANGE_K,
        valid: "[0, 50] K",
        read_by: ReadBy::Lubricated,
        source: "THK General Catalog, A-715: a running screw's temperature rise taken as 2-5 K",
    },
    input(
        "roughness_ball_relative",
        "uncertainty.roughness_ball_relative",
        "ball roughness",
        "lubricant.roughness_ball_rq_um",
        Row::Relative,
        0.3,
        ReadBy::Lubricated,
        "ISO 3290-1: Ra at most 0.014, 0.020, 0.025 um for grades G5, G10, G16 (the nominal Rq is G10's limit)",
    ),
    input(
        "roughness_raceway_relative",
        "uncertainty.roughness_raceway_relative",
        "raceway roughness",
        "lubricant.roughness_raceway_rq_um",
        Row::Relative,
        0.5,
        ReadBy::Lubricated,
        "IKO and ZKL catalogues: ground raceways Ra 0.2 um or better (the nominal Rq 0.16 um is Ra 0.13 um)",
    ),
    input(
        "boundary_friction",
        "uncertainty.boundary_friction",
        "boundary friction",
        "lubricant.boundary_friction",
        Row::Friction,
        0.05,
        ReadBy::Lubricated,
        "SKF rolling bearings catalogue: generally about 0.15; Zhang et al. (2021), Tribol. Lett. 69: 0.09-0.14",
    ),
    input(
        "full_film_traction",
        "uncertainty.full_film_traction",
        "full-film traction",
        "lubricant.full_film_traction",
        Row::Friction,
        0.015,
        ReadBy::Lubricated,
        "SKF rolling bearings catalogue: 0.05 for mineral oils; 0.015-0.045 about the nominal 0.03",
    ),
    input(
        "preload_relative",
        "uncertainty.preload_relative",
        "preload",
        "the operating point's preload (operating.preload_n, or --preload-n)",
        Row::Relative,
        0.30,
        ReadBy::Both,
        "JIS B 1192 / ISO 3408-3 (THK General Catalog, Table 13): preload torque of class C3 at 0.6-1.0 N m within +-30 %",
    ),
    input(
        "friction_coefficient_relative",
        "uncertainty.friction_coefficient_relative",
        "friction coefficient",
        "friction.coefficient (the dry model's)",
        Row::Relative,
        0.0,
        ReadBy::Dry,
        "pinned: Xu et al. (2015), Table 1, state one value and no spread",
    ),
];

/// The half-width of each uncertain input ([`UNCERTAIN_INPUTS`]' order): the spec's
/// `[uncertainty]` table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Uncertainty {
    /// Each input's half-width (relative or absolute: [`UncertainInput::spread`]).
    pub half_widths: [f64; INPUTS],
}

impl Default for Uncertainty {
    /// Every input at its documented default half-width.
    fn default() -> Self {
        Self::DEFAULT
    }
}

impl Uncertainty {
    /// Every input at its documented default half-width ([`UncertainInput::default`]).
    pub const DEFAULT: Self = {
        let mut half_widths = [0.0; INPUTS];
        let mut i = 0;
        while i < INPUTS {
            half_widths[i] = UNCERTAIN_INPUTS[i].default;
            i += 1;
        }
        Self { half_widths }
    };

    /// Every input pinned at its nominal value: no spread.
    pub const PINNED: Self = Self { half_widths: [0.0; INPUTS] };

    /// The inputs that spread a prediction of a model with `lubrication`: read by that model,
    /// with a half-width above 0. In [`UNCERTAIN_INPUTS`]' order.
    pub fn active(&self, lubrication: Lubrication) -> impl Iterator<Item = usize> + '_ {
        (0..INPUTS).filter(move |&i| self.half_widths[i] > 0.0 && UNCERTAIN_INPUTS[i].read_under(lubrication))
    }

    /// Input `i`'s factor (relative) or shift (absolute) at `u` of its half-width.
    pub fn offset(&self, i: usize, u: f64) -> f64 {
        match UNCERTAIN_INPUTS[i].spread {
            Spread::Relative => 1.0 + u * self.half_widths[i],
            Spread::Absolute => u * self.half_widths[i],
        }
    }

    /// Checks every half-width against its range (part of [`crate::input::ScrewSpec::validate`]). The first
    /// failure names the input's field (`uncertainty.<key>`) and its half-width.
    pub fn validate(&self) -> Result<(), InputError> {
        for (i, input) in UNCERTAIN_INPUTS.iter().enumerate() {
            let (lo, hi) = input.range;
            check_range(input.field, self.half_widths[i], lo, false, hi, false, input.valid)?;
        }
        Ok(())
    }
}

/// Why a spec's spread has no band at an operating point ([`crate::input::ScrewSpec::check_spread`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SpreadError {
    /// The spec at the operating point itself (every input nominal) is not valid.
    Nominal(InputError),
    /// Input `input` at one end of its spread (`end`: -1 or 1; the others nominal) takes a value
    /// out of its range: `error` says which and where the range ends.
    End {
        /// The input's index in [`UNCERTAIN_INPUTS`].
        input: usize,
        /// Its half-width.
        half_width: f64,
        /// -1: the low end; 1: the high end.
        end: f64,
        /// The value out of range.
        error: InputError,
    },
}

impl core::fmt::Display for SpreadError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            SpreadError::Nominal(e) => write!(f, "{e}"),
            SpreadError::End { input, half_width, end, error } => {
                let u = &UNCERTAIN_INPUTS[*input];
                let side = if *end < 0.0 { "low" } else { "high" };
                write!(
                    f,
                    "invalid {}: {half_width} (valid: {KEEPS_VALID}; at the {side} end of this spread of {}: {error})",
                    u.field, u.spreads
                )
            }
        }
    }
}

/// What a half-width that moves its input out of the input's own range is told.
pub const KEEPS_VALID: &str = "a half-width that keeps the value it spreads within its valid range at both ends";
