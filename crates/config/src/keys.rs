//! The table of keys: every key of the spec file, one row each ([`Key`], [`KEYS`]): its TOML
//! table and key, its unit, default, valid values (a range computed from the core's range
//! constant in the key's unit, or the options) and the conditions that tie it to other keys, its
//! meaning and the source of its default or range; for a value the core validates, the core's
//! field name and how to read the value as written from the file. Three readers: the core's
//! range errors restated on the file's terms (`crate::error`), the lubricant's grade check
//! (`crate::conversion`) and the spec reference page (`crate::reference`,
//! `docs/spec-reference.md`).

use crate::file_format::RawSpec;
use ballscrew_core::input::geometry::max_balls_per_circle;
use ballscrew_core::input::uncertainty::Spread;
use ballscrew_core::input::{
    MAX_SPEED_RAD_S, ScrewSpec, UNCERTAIN_INPUTS, circulation, extensions, geometry, lubricant, operating, options,
    screw,
};
use core::f64::consts::PI;
use std::sync::LazyLock;

/// The thinnest ISO VG grade the file takes: the grade whose oil (with the reference mineral
/// oil's temperature slope) is 2 mm^2/s at 100 degrees C, the lower end of that viscosity's
/// range (5.3626611 to 8 digits), rounded up.
pub const MIN_ISO_VG: f64 = 5.362662;
/// The thickest ISO VG grade the file takes (the upper end of the 40 degrees C viscosity).
pub const MAX_ISO_VG: f64 = lubricant::VISCOSITY_40C_RANGE_MM2_S.1;

// The key's unit per the core's SI unit.
const MM_PER_M: f64 = 1e3;
const UM_PER_M: f64 = 1e6;
const GPA_PER_PA: f64 = 1e-9;
const PER_GPA_PER_PER_PA: f64 = 1e9;
const PER_KN_PER_PER_N: f64 = 1e3;
const RPM_PER_RAD_S: f64 = 60.0 / (2.0 * PI);
const DEG_PER_RAD: f64 = 180.0 / PI;

/// Significant digits of a range end on the page and in messages; an end that needs more is
/// rounded towards the inside of the range (so that the end as written is a valid value).
const END_DIGITS: i32 = 8;

/// The values a key takes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Valid {
    /// Numbers from `lo` to `hi`, in the key's unit; an open end is not itself valid.
    Range { lo: f64, lo_open: bool, hi: f64, hi_open: bool },
    /// TOML literals: option names in quotes, or `true` and `false`.
    Options(&'static [&'static str]),
}

impl Valid {
    /// The closed range `range` of the core (in its SI unit) times `scale` (the key's unit per
    /// the core's).
    const fn closed(range: (f64, f64), scale: f64) -> Self {
        Valid::Range { lo: range.0 * scale, lo_open: false, hi: range.1 * scale, hi_open: false }
    }

    /// As [`Valid::closed`], the lower end open.
    const fn open_lo(range: (f64, f64), scale: f64) -> Self {
        Valid::Range { lo: range.0 * scale, lo_open: true, hi: range.1 * scale, hi_open: false }
    }

    /// As written on the page (without the backticks) and in messages: `[a, b]`, `(a, b]`, ...
    /// with each end to [`END_DIGITS`] digits (rounded inwards), or `"a" | "b"`.
    pub(crate) fn code(&self) -> String {
        match *self {
            Valid::Range { lo, lo_open, hi, hi_open } => format!(
                "{}{}, {}{}",
                if lo_open { '(' } else { '[' },
                number(inward(lo, true)),
                number(inward(hi, false)),
                if hi_open { ')' } else { ']' }
            ),
            Valid::Options(options) => options.join(" | "),
        }
    }
}

/// `x` to [`END_DIGITS`] significant digits, rounded up (`up`) or down where it has more; a
/// difference in the 11th digit is the unit conversion's rounding, not a digit of the value.
fn inward(x: f64, up: bool) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x + 0.0;
    }
    let shift = END_DIGITS - 1 - x.abs().log10().floor() as i32;
    // Scaled by an exact power of ten (a division for a negative shift).
    let scaled = if shift >= 0 { x * 10f64.powi(shift) } else { x / 10f64.powi(-shift) };
    let whole = if (scaled - scaled.round()).abs() < 1e-3 {
        scaled.round()
    } else if up {
        scaled.ceil()
    } else {
        scaled.floor()
    };
    let v = if shift >= 0 { whole / 10f64.powi(shift) } else { whole * 10f64.powi(-shift) };
    v + 0.0
}

/// A range end as written: a power of ten from 1e4 on as `1eN`, any other number in decimals.
fn number(x: f64) -> String {
    let exponent = x.abs().log10();
    if x != 0.0 && exponent >= 4.0 && exponent == exponent.round() && 10f64.powi(exponent as i32) == x.abs() {
        format!("{}1e{}", if x < 0.0 { "-" } else { "" }, exponent as i32)
    } else {
        format!("{x}")
    }
}

/// One key of the spec file.
pub(crate) struct Key {
    /// The TOML table, e.g. `geometry` or `extensions.viscous_drag`.
    pub(crate) table: &'static str,
    /// The key in its table, its unit at the end of its name.
    pub(crate) key: &'static str,
    /// The key's unit: `1` for a plain number, `count`, `option`, `bool`, or the unit in words.
    pub(crate) unit: &'static str,
    /// `required`; a TOML value in backticks (with a note where it depends on other keys); or
    /// words where no single value stands for leaving the key out (markdown).
    pub(crate) default: &'static str,
    /// The values the key takes on its own.
    pub(crate) valid: Valid,
    /// Conditions that tie the key to other keys, in words (markdown; empty where none).
    pub(crate) conditions: &'static str,
    /// What the key is (markdown).
    pub(crate) meaning: &'static str,
    /// Where the default or the range comes from, where one is cited (empty where none).
    pub(crate) source: &'static str,
    /// The core's field name (as in [`ballscrew_core::error::InputError::field`]) of a value
    /// whose error is restated with the key.
    pub(crate) core: Option<&'static str>,
    /// Where the core's message names an SI unit: the words after the range in the message on
    /// the file's terms (the key's unit, the conditions).
    pub(crate) restated: Option<&'static str>,
    /// The value as written in the file (in the key's unit), for a key with a core field.
    pub(crate) value: Option<fn(&RawSpec) -> f64>,
}

impl Key {
    /// `table.key`.
    pub(crate) fn full(&self) -> String {
        format!("{}.{}", self.table, self.key)
    }

    /// The valid range of a restated error: the range in the key's unit and the words after it.
    pub(crate) fn restated_valid(&self) -> Option<String> {
        self.restated.map(|words| format!("{}{words}", self.valid.code()))
    }

    fn source(self, source: &'static str) -> Self {
        Key { source, ..self }
    }

    /// A key whose value the core validates under the field `core`, read from the file by `value`.
    fn core(self, core: &'static str, value: fn(&RawSpec) -> f64) -> Self {
        Key { core: Some(core), value: Some(value), ..self }
    }

    /// As [`Key::core`], for a field whose message names an SI unit: restated with the range in
    /// the key's unit followed by `words`.
    fn restated(self, core: &'static str, words: &'static str, value: fn(&RawSpec) -> f64) -> Self {
        Key { restated: Some(words), ..self.core(core, value) }
    }
}

/// A row: table, key, unit, default, valid values, conditions, meaning (see [`Key`]).
fn key(
    table: &'static str,
    key: &'static str,
    unit: &'static str,
    default: &'static str,
    valid: Valid,
    conditions: &'static str,
    meaning: &'static str,
) -> Key {
    Key { table, key, unit, default, valid, conditions, meaning, source: "", core: None, restated: None, value: None }
}

/// The keys `viscous_drag` and `thermal_viscosity` share (`table`): the torque at the reference
/// (its meaning `torque`), the speed exponent and the reference speed (the core's field
/// `speed_core`, read from the file by `speed`).
fn drag_keys(
    table: &'static str,
    torque: &'static str,
    speed_core: &'static str,
    speed: fn(&RawSpec) -> f64,
) -> [Key; 3] {
    [
        key(table, "torque_nm", "N m", "required", Valid::closed(extensions::TORQUE_RANGE_NM, 1.0), "", torque),
        key(
            table,
            "exponent",
            "1",
            "required",
            Valid::closed(extensions::SPEED_EXPONENT_RANGE, 1.0),
            "",
            "speed exponent n",
        ),
        key(
            table,
            "reference_speed_rpm",
            "rpm",
            "`1000.0`",
            Valid::closed(extensions::REFERENCE_SPEED_RANGE_RAD_S, RPM_PER_RAD_S),
            "(the upper end is 1e4 rad/s)",
            "reference speed omega_ref",
        )
        .restated(speed_core, " rpm (the upper end is 1e4 rad/s)", speed),
    ]
}

/// The key `full` (`table.key`) of [`KEYS`].
pub(crate) fn key_named(full: &str) -> &'static Key {
    KEYS.iter().find(|k| k.full() == full).unwrap_or_else(|| panic!("{full} is in the table of keys"))
}

/// Every key of the spec file, table by table in the order of the reference page.
pub(crate) static KEYS: LazyLock<Vec<Key>> = LazyLock::new(|| {
    // The most balls of a circle of the built-in screw (the range the page states).
    let builtin_max_balls = max_balls_per_circle(&ScrewSpec::dkfzd4012().geometry) as f64;
    let mut keys = vec![
        key(
            "geometry",
            "pitch_diameter_mm",
            "mm",
            "required",
            Valid::closed(geometry::PITCH_DIAMETER_RANGE_M, MM_PER_M),
            "",
            "pitch diameter d_m: diameter of the helix through the ball centres",
        )
        .restated("geometry.pitch_diameter_m", " mm", |r| r.geometry.pitch_diameter_mm),
        key(
            "geometry",
            "lead_mm",
            "mm",
            "required",
            Valid::closed(geometry::LEAD_RANGE_M, MM_PER_M),
            "",
            "lead L: axial advance of the nut per screw revolution",
        )
        .restated("geometry.lead_m", " mm", |r| r.geometry.lead_mm),
        key(
            "geometry",
            "ball_diameter_mm",
            "mm",
            "required",
            Valid::closed(geometry::BALL_DIAMETER_RANGE_M, MM_PER_M),
            "and below `pitch_diameter_mm / 2`",
            "ball diameter D_w",
        )
        .restated("geometry.ball_diameter_m", " mm and below pitch diameter / 2", |r| r.geometry.ball_diameter_mm),
        key(
            "geometry",
            "conformity_screw",
            "1",
            "required",
            Valid::closed(geometry::CONFORMITY_RANGE, 1.0),
            "",
            "conformity f_s of the screw groove: groove radius / ball diameter",
        )
        .core("geometry.conformity_screw", |r| r.geometry.conformity_screw),
        key(
            "geometry",
            "conformity_nut",
            "1",
            "required",
            Valid::closed(geometry::CONFORMITY_RANGE, 1.0),
            "",
            "conformity f_N of the nut groove: groove radius / ball diameter",
        )
        .core("geometry.conformity_nut", |r| r.geometry.conformity_nut),
        key(
            "geometry",
            "contact_angle_deg",
            "deg",
            "required",
            Valid::closed(geometry::CONTACT_ANGLE_RANGE_DEG, 1.0),
            "",
            "nominal contact angle beta, from the radial direction",
        )
        .restated("geometry.contact_angle_rad", "", |r| r.geometry.contact_angle_deg),
        key(
            "geometry",
            "nuts",
            "count",
            "required",
            Valid::closed(screw::NUTS_RANGE, 1.0),
            "2 for `preload = \"double-nut\"`, 1 for the other arrangements",
            "number of nuts",
        )
        .core("geometry.nuts", |r| r.geometry.nuts.0),
        key(
            "geometry",
            "preload",
            "option",
            "`\"double-nut\"` for `nuts = 2`, `\"none\"` for `nuts = 1`",
            Valid::Options(&["\"double-nut\"", "\"offset-lead\"", "\"oversize-ball\"", "\"none\""]),
            "`\"offset-lead\"` needs an even `circles_per_nut`; `\"none\"` needs `operating.preload_n = \
            0`",
            "how the nut is preloaded: two nuts, one nut with a lead offset between its halves, one nut \
            with oversize balls (four-point contact), one nut without preload",
        ),
        key(
            "geometry",
            "circles_per_nut",
            "count",
            "required",
            Valid::closed(screw::CIRCLES_PER_NUT_RANGE, 1.0),
            "even for `preload = \"offset-lead\"`",
            "load-carrying circles (turns of balls) of each nut",
        )
        .core("geometry.circles_per_nut", |r| r.geometry.circles_per_nut.0),
        key(
            "geometry",
            "balls_per_circle",
            "count",
            "required",
            Valid::closed((screw::MIN_BALLS_PER_CIRCLE, builtin_max_balls), 1.0),
            "with the built-in geometry; in general at least 1 and no more than fit one turn of the \
            helix (from `pitch_diameter_mm`, `lead_mm`, `ball_diameter_mm`)",
            "balls in each circle",
        )
        .core("geometry.balls_per_circle", |r| r.geometry.balls_per_circle.0),
        key(
            "material",
            "youngs_modulus_gpa",
            "GPa",
            "required",
            Valid::closed(screw::YOUNGS_MODULUS_RANGE_PA, GPA_PER_PA),
            "",
            "Young's modulus E of balls and raceways",
        )
        .restated("material.youngs_modulus_pa", " GPa", |r| r.material.youngs_modulus_gpa),
        key(
            "material",
            "poisson_ratio",
            "1",
            "required",
            Valid::closed(screw::POISSON_RATIO_RANGE, 1.0),
            "",
            "Poisson's ratio nu of balls and raceways",
        )
        .core("material.poisson_ratio", |r| r.material.poisson_ratio),
        key(
            "friction",
            "coefficient",
            "1",
            "`0.03` (Table 1)",
            Valid::closed(screw::FRICTION_COEFFICIENT_RANGE, 1.0),
            "",
            "Coulomb friction coefficient of every contact under `model.lubrication = \"dry\"` (the \
            film gives it under `\"ehl\"`, which does not read this key)",
        )
        .core("friction.coefficient", |r| r.friction.coefficient)
        .source("Xu et al. (2015), Table 1"),
        key(
            "friction",
            "ball_ball_load_n",
            "N",
            "absent: the loads follow from the ball train (`[circulation]`)",
            Valid::closed(screw::BALL_BALL_LOAD_RANGE_N, 1.0),
            "",
            "normal load Q_m between adjacent balls: an explicit override, the same at every ball-ball \
            contact, that bypasses the ball train (the paper's reading: `0.0`)",
        )
        .core("friction.ball_ball_load_n", |r| r.friction.ball_ball_load_n.unwrap_or(f64::NAN)),
        key(
            "friction",
            "standstill_speed_rpm",
            "rpm",
            "`0.1`",
            Valid::open_lo(screw::STANDSTILL_SPEED_RANGE_RAD_S, RPM_PER_RAD_S),
            "",
            "below this screw speed the creep forces fade smoothly to zero at standstill",
        )
        .restated("friction.standstill_speed_rad_s", " rpm", |r| r.friction.standstill_speed_rpm),
        key(
            "friction",
            "creep_reduction",
            "1",
            "`1.0`",
            Valid::open_lo(screw::CREEP_REDUCTION_RANGE, 1.0),
            "",
            "factor on Kalker's creep coefficients (1: dry contact)",
        ),
        key(
            "friction",
            "seal_torque_per_nut_nm",
            "N m",
            "`0.0`",
            Valid::closed(screw::SEAL_TORQUE_RANGE_NM, 1.0),
            "",
            "drag torque of each nut's seals, against the motion",
        )
        .core("friction.seal_torque_per_nut_nm", |r| r.friction.seal_torque_per_nut_nm),
        key(
            "operating",
            "speed_rpm",
            "rpm",
            "`100.0`",
            Valid::closed((-MAX_SPEED_RAD_S, MAX_SPEED_RAD_S), RPM_PER_RAD_S),
            "",
            "screw speed; the sign is the direction of rotation",
        )
        .restated("speed_rad_s", " rpm", |r| r.operating.speed_rpm)
        .source("Xu et al. (2015), Table 1"),
        key(
            "operating",
            "preload_n",
            "N",
            "`0.0` for `geometry.preload = \"none\"`; required for every other arrangement",
            Valid::closed(operating::PRELOAD_RANGE_N, 1.0),
            "0 for `geometry.preload = \"none\"`",
            "preload F_p: the axial force each flank's set of contacts carries without external load",
        )
        .core("preload_n", |r| r.operating.preload_n.unwrap_or(0.0)),
        key(
            "operating",
            "axial_load_n",
            "N",
            "`0.0`",
            Valid::closed(operating::AXIAL_LOAD_RANGE_N, 1.0),
            "",
            "external axial load F_a on the nut, positive when it opposes the nut's travel under \
            positive rotation",
        )
        .core("axial_load_n", |r| r.operating.axial_load_n),
        key(
            "model",
            "load_distribution",
            "option",
            "`\"geometric\"`",
            Valid::Options(&["\"geometric\"", "\"paper-literal\"", "\"uniform\""]),
            "",
            "how the preload is shared among the balls",
        )
        .source("Xu et al. (2015), Eq. 26"),
        key(
            "model",
            "creep_coefficients",
            "option",
            "`\"kalker-table\"`",
            Valid::Options(&["\"kalker-table\"", "\"paper-fit\""]),
            "",
            "source of Kalker's creep coefficients",
        )
        .source("Kalker's table (E.3); Xu et al. (2015), Eq. 23"),
        key(
            "model",
            "torque",
            "option",
            "`\"energy\"`",
            Valid::Options(&["\"energy\"", "\"paper-eq27\""]),
            "",
            "how the friction torque is summed: energy balance or the paper's Eq. 27",
        )
        .source("Xu et al. (2015), Eq. 27"),
        key(
            "model",
            "heathcote",
            "bool",
            "`true`",
            Valid::Options(&["true", "false"]),
            "",
            "Heathcote slip in the contact ellipse",
        ),
        key(
            "model",
            "spin_moment",
            "option",
            "`\"combined\"`",
            Valid::Options(&["\"combined\"", "\"separate\""]),
            "",
            "spin moment saturated together with the creep forces, or on its own",
        ),
        key(
            "model",
            "contact_theory",
            "option",
            "`\"linear-saturated\"`",
            Valid::Options(&["\"linear-saturated\"", "\"fastsim\""]),
            "",
            "creep forces from the linear theory saturated at the friction limit, or Kalker's FASTSIM",
        )
        .source("Kalker's FASTSIM (ref. [11] of Xu et al. 2015)"),
        key(
            "model",
            "fastsim_grid",
            "count",
            "`20`",
            Valid::closed(options::FASTSIM_GRID_RANGE, 1.0),
            "",
            "FASTSIM elements per axis of the contact ellipse",
        )
        .core("model.fastsim_grid", |r| r.model.fastsim_grid.0),
        key(
            "model",
            "lubrication",
            "option",
            "`\"ehl\"`",
            Valid::Options(&["\"ehl\"", "\"dry\""]),
            "",
            "lubricated contacts (film, mixed friction, rolling resistance) or the paper's dry model",
        ),
        key(
            "circulation",
            "return",
            "option",
            "`\"internal\"`",
            Valid::Options(&["\"internal\"", "\"external\""]),
            "",
            "how a circuit is closed: a deflector in the nut (one loaded turn per circuit), or a tube \
            outside the nut or a bore with end caps (several turns per circuit)",
        )
        .source("HIWIN ballscrews catalogue, \"Nut configuration\"; Steinmeyer, \"Ball return\""),
        key(
            "circulation",
            "turns_per_circuit",
            "count",
            "1 for `\"internal\"`, `circles_per_nut` for `\"external\"`",
            Valid::closed(circulation::TURNS_PER_CIRCUIT_RANGE, 1.0),
            "1 for an internal return; a circuit of several loaded turns is balanced as one train \
            (every ball at one orbit rate); not with oversize balls or FASTSIM contacts, nor by the \
            real-time evaluator",
            "loaded turns (circles) per circuit",
        )
        .core("circulation.turns_per_circuit", |r| r.circulation.turns_per_circuit.map_or(f64::NAN, |c| c.0)),
        key(
            "circulation",
            "return_balls",
            "count",
            "2 for `\"internal\"`; for `\"external\"` the balls that fill the circuit's loaded length \
            plus two quarter bends of the pitch radius",
            Valid::closed(circulation::RETURN_BALLS_RANGE, 1.0),
            "",
            "balls in a circuit's return path",
        )
        .core("circulation.return_balls", |r| r.circulation.return_balls.map_or(f64::NAN, |c| c.0)),
        key(
            "circulation",
            "return_friction",
            "1",
            "the oil's full-film traction, `lubricant.full_film_traction` (`friction.coefficient` under \
            `model.lubrication = \"dry\"`)",
            Valid::closed(circulation::RETURN_FRICTION_RANGE, 1.0),
            "",
            "wall friction coefficient of a ball in the return (on its weight and its centrifugal force \
            in the bends)",
        )
        .core("circulation.return_friction", |r| r.circulation.return_friction.unwrap_or(f64::NAN)),
        key(
            "circulation",
            "lead_deviation_um",
            "um",
            "`0.0`: the nominal lead",
            Valid::closed(circulation::LEAD_DEVIATION_RANGE_M, UM_PER_M),
            "not with oversize balls, nor by the real-time evaluator",
            "the screw's lead deviation between a nut's first and last circle: the axial misfit of \
            its last circle against its first, which moves load between its circles (positive: \
            towards the circles away from the most loaded one)",
        )
        .source(
            "ISO 3408-3: the travel variation within 300 mm, v_300p, is 12, 23 and 52 um for tolerance \
            classes 3, 5 and 7; a share of it in proportion to the length between the nut's first and last \
            circle is an estimate",
        )
        .restated("circulation.lead_deviation_m", " um", |r| r.circulation.lead_deviation_um.unwrap_or(f64::NAN)),
        key(
            "circulation",
            "load_ramp_balls",
            "count",
            "`0`: every ball of the loaded zone carries its circle's load up to the return",
            Valid::closed(circulation::LOAD_RAMP_BALLS_RANGE, 1.0),
            "fewer than half of `geometry.balls_per_circle`; not with oversize balls, nor with FASTSIM \
            contacts unless `friction.ball_ball_load_n` is stated (which bypasses the train: every ball, a \
            ramp's too, then carries the stated load between balls), nor by the real-time evaluator",
            "balls at each end of a circuit's loaded zone whose load ramps between zero at the return and \
            their circle's full load: ball k of m, counted from the return, carries k / (m + 1) of it; the \
            circle keeps its share of the nut's load",
        )
        .source(
            "no standard or catalogue states it: the relief of the raceway at a deflector or tube on the \
            nut's drawing",
        )
        .core("circulation.load_ramp_balls", |r| r.circulation.load_ramp_balls.map_or(f64::NAN, |c| c.0)),
        key(
            "circulation",
            "spacer_balls",
            "bool",
            "`false`: neighbouring load balls touch",
            Valid::Options(&["true", "false"]),
            "",
            "a smaller spacer ball between each two load balls: it rolls on both, so the contacts between \
            balls carry the chain force and no friction; `geometry.balls_per_circle` counts the load balls, \
            `return_balls` every ball of the return",
        ),
        key(
            "lubricant",
            "iso_vg",
            "mm^2/s",
            "`68.0`",
            Valid::closed((MIN_ISO_VG, MAX_ISO_VG), 1.0),
            "the lower end is the grade whose 100 degrees C viscosity is 2 mm^2/s; not together with \
            the viscosities",
            "ISO 3448 viscosity grade of a mineral oil: its viscosity at 40 degrees C, with the \
            reference oil's temperature slope",
        )
        .source("ISO 3448; ASTM D341 (the lower end)"),
        key(
            "lubricant",
            "viscosity_40c_mm2_s",
            "mm^2/s",
            "absent: the oil of `iso_vg`",
            Valid::open_lo(lubricant::VISCOSITY_40C_RANGE_MM2_S, 1.0),
            "above `viscosity_100c_mm2_s`; only together with it",
            "kinematic viscosity at 40 degrees C",
        )
        .core("lubricant.viscosity_40c_mm2_s", |r| r.lubricant.viscosity_40c_mm2_s.unwrap_or(f64::NAN))
        .source("ASTM D341 (Walther, from 2 mm^2/s)"),
        key(
            "lubricant",
            "viscosity_100c_mm2_s",
            "mm^2/s",
            "absent: the oil of `iso_vg`",
            Valid::closed(lubricant::VISCOSITY_100C_RANGE_MM2_S, 1.0),
            "below `viscosity_40c_mm2_s`; only together with it",
            "kinematic viscosity at 100 degrees C",
        )
        .core("lubricant.viscosity_100c_mm2_s", |r| r.lubricant.viscosity_100c_mm2_s.unwrap_or(f64::NAN))
        .source("ASTM D341 (Walther, from 2 mm^2/s)"),
        key(
            "lubricant",
            "density_15c_kg_m3",
            "kg/m^3",
            "`870.0`",
            Valid::closed(lubricant::DENSITY_15C_RANGE_KG_M3, 1.0),
            "",
            "density at 15 degrees C",
        )
        .core("lubricant.density_15c_kg_m3", |r| r.lubricant.density_15c_kg_m3.unwrap_or(f64::NAN)),
        key(
            "lubricant",
            "density_temperature_coefficient_kg_m3_k",
            "kg/(m^3 K)",
            "`-0.6`",
            Valid::closed(lubricant::DENSITY_TEMPERATURE_COEFFICIENT_RANGE_KG_M3_K, 1.0),
            "",
            "change of the density per kelvin",
        )
        .core("lubricant.density_temperature_coefficient_kg_m3_k", |r| {
            r.lubricant.density_temperature_coefficient_kg_m3_k.unwrap_or(f64::NAN)
        })
        .source("FVA No. 3 oil (Wingertszahn et al. 2023, Table A1)"),
        key(
            "lubricant",
            "pressure_viscosity_per_gpa",
            "1/GPa",
            "`22.0`",
            Valid::closed(lubricant::PRESSURE_VISCOSITY_RANGE_PER_PA, PER_GPA_PER_PER_PA),
            "",
            "Barus pressure-viscosity coefficient alpha_p",
        )
        .restated("lubricant.pressure_viscosity_per_pa", " 1/GPa", |r| {
            r.lubricant.pressure_viscosity_per_gpa.unwrap_or(f64::NAN)
        })
        .source("FVA No. 3 oil (Wingertszahn et al. 2023, Table A1)"),
        key(
            "lubricant",
            "thermal_conductivity_w_m_k",
            "W/(m K)",
            "`0.134`",
            Valid::closed(lubricant::THERMAL_CONDUCTIVITY_RANGE_W_M_K, 1.0),
            "",
            "thermal conductivity of the oil",
        )
        .core("lubricant.thermal_conductivity_w_m_k", |r| r.lubricant.thermal_conductivity_w_m_k.unwrap_or(f64::NAN))
        .source("FVA No. 3 oil (Wingertszahn et al. 2023, Table A1)"),
        key(
            "lubricant",
            "temperature_c",
            "degrees C",
            "`40.0`",
            Valid::closed(lubricant::TEMPERATURE_RANGE_C, 1.0),
            "",
            "oil temperature at the contacts",
        )
        .core("lubricant.temperature_c", |r| r.lubricant.temperature_c.unwrap_or(f64::NAN)),
        key(
            "lubricant",
            "roughness_ball_rq_um",
            "um",
            "`0.025`",
            Valid::closed(lubricant::ROUGHNESS_RANGE_M, UM_PER_M),
            "",
            "RMS roughness Rq of the balls",
        )
        .restated("lubricant.roughness_ball_rq_m", " um", |r| r.lubricant.roughness_ball_rq_um.unwrap_or(f64::NAN))
        .source("ISO 3290-1 grade G10 balls"),
        key(
            "lubricant",
            "roughness_raceway_rq_um",
            "um",
            "`0.16`",
            Valid::open_lo(lubricant::ROUGHNESS_RANGE_M, UM_PER_M),
            "",
            "RMS roughness Rq of the raceways",
        )
        .restated("lubricant.roughness_raceway_rq_m", " um", |r| {
            r.lubricant.roughness_raceway_rq_um.unwrap_or(f64::NAN)
        })
        .source("Wingertszahn et al. (2023), Table 4"),
        key(
            "lubricant",
            "boundary_friction",
            "1",
            "`0.15`",
            Valid::closed(lubricant::FILM_FRICTION_RANGE, 1.0),
            "",
            "friction coefficient of asperity contact",
        )
        .core("lubricant.boundary_friction", |r| r.lubricant.boundary_friction.unwrap_or(f64::NAN))
        .source("SKF rolling bearings catalogue (the SKF friction model)"),
        key(
            "lubricant",
            "full_film_traction",
            "1",
            "`0.03`",
            Valid::closed(lubricant::FULL_FILM_TRACTION_RANGE, 1.0),
            "",
            "traction coefficient of a full film",
        )
        .core("lubricant.full_film_traction", |r| r.lubricant.full_film_traction.unwrap_or(f64::NAN))
        .source("Xu et al. (2015), Table 1; the lower end below oils' 0.02-0.06 (Harris & Kotzalas 2007)"),
        key(
            "lubricant",
            "asperity_load_b",
            "1",
            "`2.32`",
            Valid::open_lo(lubricant::ASPERITY_LOAD_B_RANGE, 1.0),
            "",
            "B of the asperity load share exp(-B Lambda^C)",
        )
        .core("lubricant.asperity_load_b", |r| r.lubricant.asperity_load_b.unwrap_or(f64::NAN))
        .source("Zhou & Hoeprich (1991), Eq. 29; Wingertszahn et al. (2023), Table 4"),
        key(
            "lubricant",
            "asperity_load_c",
            "1",
            "`0.97`",
            Valid::open_lo(lubricant::ASPERITY_LOAD_C_RANGE, 1.0),
            "",
            "C of the asperity load share exp(-B Lambda^C)",
        )
        .core("lubricant.asperity_load_c", |r| r.lubricant.asperity_load_c.unwrap_or(f64::NAN))
        .source("Zhou & Hoeprich (1991), Eq. 29; Wingertszahn et al. (2023), Table 4"),
        key(
            "lubricant",
            "hysteresis_loss_factor",
            "1",
            "`0.002`",
            Valid::closed(lubricant::HYSTERESIS_LOSS_FACTOR_RANGE, 1.0),
            "",
            "rolling hysteresis loss of the steel",
        )
        .core("lubricant.hysteresis_loss_factor", |r| r.lubricant.hysteresis_loss_factor.unwrap_or(f64::NAN)),
        key(
            "lubricant",
            "inlet_distance_ratio",
            "1",
            "absent: a fully flooded inlet",
            Valid::closed(lubricant::INLET_DISTANCE_RATIO_RANGE, 1.0),
            "",
            "inlet meniscus distance over the Hertzian half-width (starvation)",
        )
        .core("lubricant.inlet_distance_ratio", |r| r.lubricant.inlet_distance_ratio.unwrap_or(f64::NAN))
        .source("Hamrock & Dowson's starvation parameter"),
        key(
            "extensions.seal_drag",
            "torque_nm",
            "N m",
            "required",
            Valid::closed(extensions::TORQUE_RANGE_NM, 1.0),
            "",
            "drag torque T_s",
        ),
    ];
    keys.extend(drag_keys(
        "extensions.viscous_drag",
        "drag torque c at the reference speed",
        "extensions.viscous_drag.reference_speed_rad_s",
        |r| r.extensions.viscous_drag.map_or(f64::NAN, |v| v.reference_speed_rpm),
    ));
    keys.extend(drag_keys(
        "extensions.thermal_viscosity",
        "drag torque c at the reference speed and temperature",
        "extensions.thermal_viscosity.reference_speed_rad_s",
        |r| r.extensions.thermal_viscosity.map_or(f64::NAN, |v| v.reference_speed_rpm),
    ));
    keys.extend([
        key(
            "extensions.thermal_viscosity",
            "viscosity_coefficient_per_k",
            "1/K",
            "required",
            Valid::closed(extensions::VISCOSITY_COEFFICIENT_RANGE_PER_K, 1.0),
            "",
            "viscosity-temperature coefficient b",
        ),
        key(
            "extensions.thermal_viscosity",
            "reference_temperature_c",
            "degrees C",
            "required",
            Valid::closed(extensions::REFERENCE_TEMPERATURE_RANGE_C, 1.0),
            "",
            "reference temperature theta_ref",
        ),
        key(
            "extensions.raceway_waviness",
            "harmonic",
            "count",
            "required",
            Valid::closed(extensions::HARMONIC_RANGE, 1.0),
            "",
            "harmonic h of the screw revolution: period L / h",
        ),
        key(
            "extensions.raceway_waviness",
            "amplitude_nm",
            "N m",
            "required",
            Valid::closed(extensions::TORQUE_RANGE_NM, 1.0),
            "",
            "amplitude A",
        ),
        key(
            "extensions.raceway_waviness",
            "phase_deg",
            "deg",
            "`0.0`",
            Valid::closed(extensions::PHASE_RANGE_RAD, DEG_PER_RAD),
            "(1000 rad)",
            "phase phi at nut position 0",
        )
        .restated("extensions.raceway_waviness.phase_rad", " deg (1000 rad)", |r| {
            r.extensions.raceway_waviness.map_or(f64::NAN, |v| v.phase_deg)
        }),
        key(
            "extensions.preload_loss",
            "loss_per_1000_h",
            "1",
            "required",
            Valid::closed(extensions::LOSS_PER_1000_H_RANGE, 1.0),
            "",
            "fraction r of the preload lost per 1000 h of running",
        ),
        key(
            "extensions.direction_asymmetry",
            "reverse_factor",
            "1",
            "required",
            Valid::closed(extensions::REVERSE_FACTOR_RANGE, 1.0),
            "",
            "friction torque in reverse over the friction torque forward",
        ),
        key(
            "extensions.preload_law",
            "exponent",
            "1",
            "required",
            Valid::closed(extensions::PRELOAD_LAW_EXPONENT_RANGE, 1.0),
            "",
            "exponent e (0: the model's shape)",
        ),
        key(
            "extensions.preload_law",
            "reference_preload_n",
            "N",
            "required",
            Valid::closed(extensions::LAW_REFERENCE_PRELOAD_RANGE_N, 1.0),
            "",
            "reference preload Fp_ref, where the factor is 1",
        ),
        key(
            "extensions.axial_load_loss",
            "torque_per_kn_nm",
            "N m per kN",
            "required",
            Valid::closed(extensions::AXIAL_LOAD_LOSS_RANGE_NM_PER_N, PER_KN_PER_PER_N),
            "",
            "extra torque k per kilonewton of axial load",
        )
        .restated("extensions.axial_load_loss.torque_per_n_nm", " N m per kN", |r| {
            r.extensions.axial_load_loss.map_or(f64::NAN, |v| v.torque_per_kn_nm)
        }),
        key(
            "extensions.level_factor",
            "factor",
            "1",
            "required",
            Valid::closed(extensions::LEVEL_FACTOR_RANGE, 1.0),
            "",
            "friction torque over the model's",
        ),
    ]);
    // `[uncertainty]`: one row per uncertain input, from the core's table of them.
    keys.extend(UNCERTAIN_INPUTS.iter().map(|u| {
        let leak = |s: String| -> &'static str { Box::leak(s.into_boxed_str()) };
        let (unit, meaning) = match u.spread {
            Spread::Relative => ("1", leak(format!("half-width of {}, as a share of its value", u.spreads))),
            Spread::Absolute => (u.unit, leak(format!("half-width of {}", u.spreads))),
        };
        key(
            "uncertainty",
            u.key,
            unit,
            leak(format!("`{:?}`", u.default)),
            Valid::closed(u.range, 1.0),
            match u.read_by {
                ballscrew_core::input::uncertainty::ReadBy::Lubricated => "read by `lubrication = \"ehl\"` only",
                ballscrew_core::input::uncertainty::ReadBy::Dry => "read by `lubrication = \"dry\"` only",
                ballscrew_core::input::uncertainty::ReadBy::Both => "",
            },
            meaning,
        )
        .source(u.source)
    }));
    keys
});
