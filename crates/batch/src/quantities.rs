//! What the shells report, each quantity named once: its key (the command line's CSV column and
//! JSON key, and Python's key, the unit in it), its table heading, label and unit, and how it is
//! read from a result of the core or of a sweep, scaled as reported (rad/s as rpm, metres as mm or
//! um, the catalog band). The command line renders the [`Value`]s as tables, CSV and JSON, Python
//! as its objects: both read this table, so a column from one lines up with the other's.
//!
//! The lists: the torque summary of an operating point ([`POINT`], a sweep's columns [`SWEEP`]
//! after the swept quantity ([`SWEPT`]) and the ones held ([`held`]), the [`EFFICIENCY`]), the
//! state of one ball standing for its circle ([`BALL_ID`], [`BALL`]) and of one of its contacts
//! ([`CONTACT_ID`], [`CONTACT`]); one contact solved by FASTSIM and by the model's law
//! ([`CONTACT_DATA`], [`CREEPAGES`], [`FORCES`], [`FASTSIM_EXTRA`], [`EQ24_EXTRA`]) and the
//! points of the creep curves ([`CURVE_ROW`]); the band of the drag torque ([`BAND`]) and each
//! uncertain input's part in it ([`SENSITIVITY`]).

use crate::sweep::{AXIAL_LOAD_FLAGS, OIL_TEMPERATURE_FLAGS, PRELOAD_FLAGS, SPEED_FLAGS, SweepFlags, SweepRow};
use crate::uncertainty::{Band, InputSensitivity};
use alloc::vec::Vec;
use ballscrew_core::contact::analysis::{Contact, ContactRun, CurvePoint, Forces};
use ballscrew_core::input::UNCERTAIN_INPUTS;
use ballscrew_core::input::uncertainty::Spread;
use ballscrew_core::input::{Lubrication, rad_s_to_rpm};
use ballscrew_core::screw::catalog::BAND_RELATIVE;
use ballscrew_core::{BallReport, ContactReport, Efficiency, Summary};

/// One reported value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// A real number (not finite: undefined, e.g. a ratio to a zero catalog torque).
    Num(f64),
    /// A count.
    Int(u64),
    /// A name.
    Text(&'static str),
}

use Value::{Int, Num, Text};

/// One reported value of a `T`.
pub struct Quantity<T> {
    /// CSV column and JSON key (unit in the name).
    pub key: &'static str,
    /// Short column heading of a table.
    pub head: &'static str,
    /// Long label (a row of a vertical table).
    pub label: &'static str,
    /// Unit shown in tables (`-` for none).
    pub unit: &'static str,
    /// The value.
    pub get: fn(&T) -> Value,
}

/// The quantity of `quantities` whose key is `key`.
pub fn by_key<'a, T>(quantities: &'a [Quantity<T>], key: &str) -> Option<&'a Quantity<T>> {
    quantities.iter().find(|q| q.key == key)
}

type Q<T> = Quantity<T>;

/// The screw speed.
pub const SPEED: Q<Summary> = Q {
    key: "speed_rpm",
    head: "speed",
    label: "screw speed",
    unit: "rpm",
    get: |s| Num(rad_s_to_rpm(s.operating.speed_rad_s)),
};
/// The preload.
pub const PRELOAD: Q<Summary> =
    Q { key: "preload_n", head: "preload", label: "preload F_p", unit: "N", get: |s| Num(s.operating.preload_n) };
/// The external axial load.
pub const AXIAL: Q<Summary> = Q {
    key: "axial_load_n",
    head: "axial load",
    label: "axial load F_a",
    unit: "N",
    get: |s| Num(s.operating.axial_load_n),
};
/// The drive torque by the spec's route.
pub const TORQUE: Q<Summary> =
    Q { key: "torque_nm", head: "torque", label: "torque (the spec's route)", unit: "N m", get: |s| Num(s.torque_nm) };
const ENERGY: Q<Summary> = Q {
    key: "torque_energy_nm",
    head: "energy",
    label: "energy route F_a L/2pi + D/omega",
    unit: "N m",
    get: |s| Num(s.torque_energy_nm),
};
const MOMENT: Q<Summary> = Q {
    key: "torque_moment_nm",
    head: "moment",
    label: "moment route (moment about the axis)",
    unit: "N m",
    get: |s| Num(s.torque_moment_nm),
};
const EQ27: Q<Summary> = Q {
    key: "torque_eq27_nm",
    head: "Eq. 27",
    label: "Eq. 27 as printed",
    unit: "N m",
    get: |s| Num(s.torque_eq27_nm),
};
const DRAG: Q<Summary> = Q {
    key: "drag_torque_nm",
    head: "drag",
    label: "drag torque (friction: torque - F_a L/2pi)",
    unit: "N m",
    get: |s| Num(s.drag_torque_nm()),
};
/// The load torque F_a L/2pi.
pub const LOAD: Q<Summary> = Q {
    key: "load_torque_nm",
    head: "load F_a L/2pi",
    label: "load torque F_a L/2pi",
    unit: "N m",
    get: |s| Num(s.load_torque_nm()),
};
const DISSIPATION: Q<Summary> = Q {
    key: "dissipation_torque_nm",
    head: "D/omega",
    label: "dissipation D/omega",
    unit: "N m",
    get: |s| Num(s.dissipation_torque_nm),
};
const CATALOG: Q<Summary> =
    Q { key: "catalog_nm", head: "catalog", label: "catalog estimate", unit: "N m", get: |s| Num(s.catalog_nm) };
const CATALOG_LOW: Q<Summary> = Q {
    key: "catalog_low_nm",
    head: "cat. low",
    label: "catalog band, low end",
    unit: "N m",
    get: |s| Num(s.catalog_nm * (1.0 - BAND_RELATIVE)),
};
const CATALOG_HIGH: Q<Summary> = Q {
    key: "catalog_high_nm",
    head: "cat. high",
    label: "catalog band, high end",
    unit: "N m",
    get: |s| Num(s.catalog_nm * (1.0 + BAND_RELATIVE)),
};
const RATIO: Q<Summary> =
    Q { key: "ratio", head: "drag/cat.", label: "drag torque / catalog", unit: "-", get: |s| Num(s.catalog_ratio()) };
const CREEP_TORQUE: Q<Summary> = Q {
    key: "creep_torque_nm",
    head: "creep",
    label: "  of which creep and sliding (raceways)",
    unit: "N m",
    get: |s| Num(s.creep_torque_nm),
};
const ROLLING_TORQUE: Q<Summary> = Q {
    key: "rolling_resistance_torque_nm",
    head: "EHL roll.",
    label: "  of which EHL rolling resistance",
    unit: "N m",
    get: |s| Num(s.rolling_resistance_torque_nm),
};
const HYSTERESIS_TORQUE: Q<Summary> = Q {
    key: "hysteresis_torque_nm",
    head: "hyst.",
    label: "  of which elastic hysteresis",
    unit: "N m",
    get: |s| Num(s.hysteresis_torque_nm),
};
const BALL_BALL_TORQUE: Q<Summary> = Q {
    key: "ball_ball_torque_nm",
    head: "ball-ball",
    label: "  of which ball-ball sliding",
    unit: "N m",
    get: |s| Num(s.ball_ball_torque_nm),
};
const RETURN_TORQUE: Q<Summary> = Q {
    key: "return_torque_nm",
    head: "return",
    label: "  of which the return path",
    unit: "N m",
    get: |s| Num(s.return_torque_nm),
};
const SEAL_TORQUE: Q<Summary> = Q {
    key: "seal_torque_nm",
    head: "seals",
    label: "seals (friction.seal_torque_per_nut_nm, every route)",
    unit: "N m",
    get: |s| Num(s.seal_torque_nm),
};
const ITERATIONS: Q<Summary> = Q {
    key: "iterations",
    head: "iterations",
    label: "Newton iterations (all balls)",
    unit: "-",
    get: |s| Int(u64::from(s.iterations)),
};
const MAX_RESIDUAL: Q<Summary> =
    Q { key: "max_residual", head: "max resid.", label: "largest residual", unit: "-", get: |s| Num(s.max_residual) };

/// The first column of a sweep: the swept quantity (the preload's, as in [`POINT`]).
pub static SWEPT_PRELOAD: Q<SweepRow> = Q {
    key: PRELOAD.key,
    head: PRELOAD.head,
    label: PRELOAD.label,
    unit: PRELOAD.unit,
    get: |r| (PRELOAD.get)(&r.summary),
};
/// The speed as the swept quantity (see [`SWEPT_PRELOAD`]).
pub static SWEPT_SPEED: Q<SweepRow> =
    Q { key: SPEED.key, head: SPEED.head, label: SPEED.label, unit: SPEED.unit, get: |r| (SPEED.get)(&r.summary) };
/// The axial load as the swept quantity (see [`SWEPT_PRELOAD`]).
pub static SWEPT_AXIAL_LOAD: Q<SweepRow> =
    Q { key: AXIAL.key, head: AXIAL.head, label: AXIAL.label, unit: AXIAL.unit, get: |r| (AXIAL.get)(&r.summary) };
/// The oil temperature at the contacts as the swept quantity (see [`SWEPT_PRELOAD`]).
pub static SWEPT_OIL_TEMPERATURE: Q<SweepRow> = Q {
    key: "oil_temperature_c",
    head: "oil temp.",
    label: "oil temperature at the contacts",
    unit: "C",
    get: |r| Num(r.oil_temperature_c),
};

/// The quantities a sweep runs over, in the order a row of a sweep names its operating point:
/// the preload (the default), the screw speed, the axial load and the oil temperature at the
/// contacts (lubricated model only).
pub static SWEPT: [&Q<SweepRow>; 4] = [&SWEPT_PRELOAD, &SWEPT_SPEED, &SWEPT_AXIAL_LOAD, &SWEPT_OIL_TEMPERATURE];

/// The quantity a sweep runs over: its column ([`SWEPT`]), its flags and how its values are
/// named in words.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Swept {
    /// The preload (the default).
    Preload,
    /// The screw speed.
    Speed,
    /// The external axial load.
    AxialLoad,
    /// The oil temperature at the contacts (lubricated model only).
    OilTemperature,
}

impl Swept {
    /// The first column of the sweep.
    pub fn quantity(self) -> &'static Q<SweepRow> {
        match self {
            Swept::Preload => &SWEPT_PRELOAD,
            Swept::Speed => &SWEPT_SPEED,
            Swept::AxialLoad => &SWEPT_AXIAL_LOAD,
            Swept::OilTemperature => &SWEPT_OIL_TEMPERATURE,
        }
    }

    /// The range and step flags, as the messages name them.
    pub fn flags(self) -> SweepFlags<'static> {
        match self {
            Swept::Preload => PRELOAD_FLAGS,
            Swept::Speed => SPEED_FLAGS,
            Swept::AxialLoad => AXIAL_LOAD_FLAGS,
            Swept::OilTemperature => OIL_TEMPERATURE_FLAGS,
        }
    }

    /// The swept values in words (`preloads`, ...), as the catalog band's line names them.
    pub fn values(self) -> &'static str {
        match self {
            Swept::Preload => "preloads",
            Swept::Speed => "speeds",
            Swept::AxialLoad => "axial loads",
            Swept::OilTemperature => "oil temperatures",
        }
    }

    /// The operating quantities held fixed ([`held`]).
    pub fn held(self, lubrication: Lubrication) -> Vec<&'static Q<SweepRow>> {
        held(self.quantity(), lubrication)
    }
}

/// The operating quantities held fixed in a sweep over `swept`, which a row names after the
/// swept one so that every row names its whole operating point and sweeps can be stacked: the
/// preload, the speed, the axial load and, under the lubricated model, the oil temperature, less
/// the swept one.
pub fn held(swept: &Q<SweepRow>, lubrication: Lubrication) -> Vec<&'static Q<SweepRow>> {
    let oil = |q: &Q<SweepRow>| q.key == SWEPT_OIL_TEMPERATURE.key;
    SWEPT.into_iter().filter(|q| q.key != swept.key && (!oil(q) || lubrication == Lubrication::Ehl)).collect()
}

/// The band of the drag torque at a point (`--band`; Python's `band=`): after the drag torque's
/// other columns.
pub static BAND: &[Q<Band>] = &[
    Q {
        key: "drag_torque_low_nm",
        head: "band low",
        label: "drag torque, the band's low quantile",
        unit: "N m",
        get: |b| Num(b.low_nm),
    },
    Q {
        key: "drag_torque_median_nm",
        head: "median",
        label: "drag torque, the samples' median",
        unit: "N m",
        get: |b| Num(b.median_nm),
    },
    Q {
        key: "drag_torque_high_nm",
        head: "band high",
        label: "drag torque, the band's high quantile",
        unit: "N m",
        get: |b| Num(b.high_nm),
    },
];

/// One uncertain input's part in the band at a point (`ballscrew sensitivity`, Python's
/// `Screw.sensitivity`), a row each, largest swing first.
pub static SENSITIVITY: &[Q<InputSensitivity>] = &[
    Q { key: "input", head: "input", label: "input", unit: "-", get: |s| Text(UNCERTAIN_INPUTS[s.input].name) },
    Q {
        key: "key",
        head: "spec key",
        label: "its half-width's key",
        unit: "-",
        get: |s| Text(UNCERTAIN_INPUTS[s.input].field),
    },
    Q { key: "half_width", head: "+-", label: "half-width", unit: "-", get: |s| Num(s.half_width) },
    Q {
        key: "half_width_unit",
        head: "unit",
        label: "the half-width's unit (`share`: of the value)",
        unit: "-",
        get: |s| {
            let input = &UNCERTAIN_INPUTS[s.input];
            Text(match input.spread {
                Spread::Relative => "share",
                Spread::Absolute => input.unit,
            })
        },
    },
    Q {
        key: "low_end_nm",
        head: "at low end",
        label: "drag torque, the input at the low end of its spread",
        unit: "N m",
        get: |s| Num(s.low_end_nm),
    },
    Q {
        key: "high_end_nm",
        head: "at high end",
        label: "drag torque, the input at the high end of its spread",
        unit: "N m",
        get: |s| Num(s.high_end_nm),
    },
    Q { key: "swing_nm", head: "swing", label: "swing |high - low|", unit: "N m", get: |s| Num(s.swing_nm()) },
    Q {
        key: "first_order",
        head: "S_i",
        label: "first-order Sobol index (share of the variance alone)",
        unit: "-",
        get: |s| Num(s.first_order),
    },
    Q {
        key: "total",
        head: "ST_i",
        label: "total Sobol index (with its interactions)",
        unit: "-",
        get: |s| Num(s.total),
    },
];

/// The columns of a sweep after the swept quantity.
pub static SWEEP: &[Q<Summary>] =
    &[TORQUE, DRAG, LOAD, ENERGY, MOMENT, EQ27, CATALOG, CATALOG_LOW, CATALOG_HIGH, RATIO, ITERATIONS, MAX_RESIDUAL];

/// A number of an efficiency, NaN (n/a) without one.
fn efficiency_value(e: &Option<Efficiency>, get: fn(&Efficiency) -> f64) -> Value {
    Num(e.as_ref().map_or(f64::NAN, get))
}

/// The forward and backdrive efficiency under the axial load (`ballscrew torque`, `sweep`):
/// n/a without an axial load or at standstill.
pub static EFFICIENCY: &[Q<Option<Efficiency>>] = &[
    Q {
        key: "forward_efficiency",
        head: "eta fwd",
        label: "forward efficiency F_a L/(2 pi T) (drive moves the load)",
        unit: "-",
        get: |e| efficiency_value(e, |e| e.forward_efficiency),
    },
    Q {
        key: "backdrive_efficiency",
        head: "eta back",
        label: "backdrive efficiency T_b/(F_a L/2pi) (load drives the screw; 0: self-locking)",
        unit: "-",
        get: |e| efficiency_value(e, |e| e.backdrive_efficiency),
    },
    Q {
        key: "backdrive_torque_nm",
        head: "T_b",
        label: "backdrive torque T_b the load produces at the screw (F_a L/2pi - drag)",
        unit: "N m",
        get: |e| efficiency_value(e, |e| e.backdrive_torque_nm),
    },
];

/// Everything reported for one operating point.
pub static POINT: &[Q<Summary>] = &[
    SPEED,
    PRELOAD,
    AXIAL,
    TORQUE,
    DRAG,
    LOAD,
    ENERGY,
    MOMENT,
    EQ27,
    DISSIPATION,
    CREEP_TORQUE,
    ROLLING_TORQUE,
    HYSTERESIS_TORQUE,
    BALL_BALL_TORQUE,
    RETURN_TORQUE,
    SEAL_TORQUE,
    CATALOG,
    CATALOG_LOW,
    CATALOG_HIGH,
    RATIO,
    ITERATIONS,
    MAX_RESIDUAL,
];

/// The drag torque's parts by mechanism (the "of which" rows of [`POINT`] and the seals), in
/// the order [`POINT`] lists them.
pub static MECHANISMS: &[Q<Summary>] =
    &[CREEP_TORQUE, ROLLING_TORQUE, HYSTERESIS_TORQUE, BALL_BALL_TORQUE, RETURN_TORQUE, SEAL_TORQUE];

/// Nut and circle of a ball, 1-based.
pub static BALL_ID: &[Q<BallReport>] = &[
    Q { key: "nut", head: "nut", label: "nut", unit: "-", get: |b| Int(b.nut as u64 + 1) },
    Q { key: "circle", head: "circle", label: "circle", unit: "-", get: |b| Int(b.circle as u64 + 1) },
];

/// The state of one ball (the same for every ball of its circle).
pub static BALL: &[Q<BallReport>] = &[
    Q {
        key: "balls",
        head: "balls",
        label: "balls of the circle at its full load",
        unit: "-",
        get: |b| Int(u64::from(b.balls)),
    },
    Q {
        key: "ramp_balls",
        head: "ramp",
        label: "balls of the circle's load ramps",
        unit: "-",
        get: |b| Int(u64::from(b.ramp_balls)),
    },
    Q { key: "flank", head: "flank", label: "flank", unit: "-", get: |b| Num(b.flank) },
    Q { key: "weight", head: "weight", label: "weight on friction", unit: "-", get: |b| Num(b.weight) },
    Q { key: "axial_load_n", head: "axial", label: "axial load per ball", unit: "N", get: |b| Num(b.axial_load_n) },
    Q {
        key: "circle_axial_load_n",
        head: "circle axial",
        label: "axial load of the circle",
        unit: "N",
        // A ramp's balls carry half as many full balls' load.
        get: |b| Num(b.axial_load_n * (f64::from(b.balls) + 0.5 * f64::from(b.ramp_balls))),
    },
    Q {
        key: "iterations",
        head: "it.",
        label: "solve: Newton iterations",
        unit: "-",
        get: |b| Int(u64::from(b.solve.iterations)),
    },
    Q { key: "residual", head: "residual", label: "solve: final residual", unit: "-", get: |b| Num(b.solve.residual) },
    Q {
        key: "continuation_steps",
        head: "cont.",
        label: "solve: continuation steps",
        unit: "-",
        get: |b| Int(u64::from(b.solve.continuation_steps)),
    },
    Q {
        key: "spin_ratio",
        head: "omega_R/omega",
        label: "spin ratio omega_R/omega",
        unit: "-",
        get: |b| Num(b.spin_ratio),
    },
    Q { key: "beta_deg", head: "beta", label: "attitude beta", unit: "deg", get: |b| Num(b.beta_rad.to_degrees()) },
    Q {
        key: "beta_prime_deg",
        head: "beta'",
        label: "attitude beta'",
        unit: "deg",
        get: |b| Num(b.beta_prime_rad.to_degrees()),
    },
    Q {
        key: "orbit_ratio",
        head: "orbit",
        label: "orbit ratio (ball centre / screw)",
        unit: "-",
        get: |b| Num(b.orbit_ratio),
    },
    Q {
        key: "free_orbit_ratio",
        head: "free orbit",
        label: "orbit ratio alone (free of the circuit's other circles)",
        unit: "-",
        get: |b| Num(b.free_orbit_ratio),
    },
    Q {
        key: "push_n",
        head: "push",
        label: "push along the train (contact behind less ahead)",
        unit: "N",
        get: |b| Num(b.push_n),
    },
    Q {
        key: "chain_in_n",
        head: "chain in",
        label: "chain force behind the circle's first ball",
        unit: "N",
        get: |b| Num(b.chain_in_n),
    },
    Q {
        key: "chain_out_n",
        head: "chain out",
        label: "chain force ahead of the circle's last ball",
        unit: "N",
        get: |b| Num(b.chain_out_n),
    },
    Q {
        key: "omega_t_per_screw",
        head: "omega_t",
        label: "ball omega_t / screw omega",
        unit: "-",
        get: |b| Num(b.omega_tnb_per_screw[0]),
    },
    Q {
        key: "omega_n_per_screw",
        head: "omega_n",
        label: "ball omega_n / screw omega",
        unit: "-",
        get: |b| Num(b.omega_tnb_per_screw[1]),
    },
    Q {
        key: "omega_b_per_screw",
        head: "omega_b",
        label: "ball omega_b / screw omega",
        unit: "-",
        get: |b| Num(b.omega_tnb_per_screw[2]),
    },
];

/// Which contact.
pub static CONTACT_ID: &[Q<ContactReport>] =
    &[Q { key: "contact", head: "contact", label: "contact", unit: "-", get: |c| Text(c.kind.name()) }];

/// The state of one contact of a ball.
pub static CONTACT: &[Q<ContactReport>] = &[
    Q { key: "normal_load_n", head: "Q", label: "normal load Q", unit: "N", get: |c| Num(c.normal_load_n) },
    Q {
        key: "contact_angle_deg",
        head: "angle",
        label: "contact angle",
        unit: "deg",
        get: |c| Num(c.contact_angle_rad.to_degrees()),
    },
    Q {
        key: "semi_axis_rolling_mm",
        head: "a",
        label: "Hertz semi-axis a (rolling)",
        unit: "mm",
        get: |c| Num(c.semi_axis_rolling_m * 1e3),
    },
    Q {
        key: "semi_axis_lateral_mm",
        head: "b",
        label: "Hertz semi-axis b (lateral)",
        unit: "mm",
        get: |c| Num(c.semi_axis_lateral_m * 1e3),
    },
    Q {
        key: "approach_um",
        head: "delta",
        label: "Hertz approach delta",
        unit: "um",
        get: |c| Num(c.approach_m * 1e6),
    },
    Q {
        key: "peak_pressure_mpa",
        head: "p0",
        label: "peak pressure",
        unit: "MPa",
        get: |c| Num(c.peak_pressure_pa * 1e-6),
    },
    Q { key: "rolling_speed_m_s", head: "V", label: "rolling speed", unit: "m/s", get: |c| Num(c.rolling_speed_m_s) },
    Q { key: "slip_speed_m_s", head: "slip", label: "slip speed", unit: "m/s", get: |c| Num(c.slip_speed_m_s) },
    Q {
        key: "creep_xi",
        head: "xi",
        label: "creepage xi (longitudinal)",
        unit: "-",
        get: |c| Num(c.creep_longitudinal),
    },
    Q { key: "creep_eta", head: "eta", label: "creepage eta (lateral)", unit: "-", get: |c| Num(c.creep_lateral) },
    Q {
        key: "creep_phi_per_mm",
        head: "phi",
        label: "creepage phi (spin)",
        unit: "1/mm",
        get: |c| Num(c.creep_spin_per_m * 1e-3),
    },
    Q {
        key: "creep_heathcote",
        head: "xi_h",
        label: "Heathcote part of xi",
        unit: "-",
        get: |c| Num(c.creep_heathcote),
    },
    Q {
        key: "linear_force_rolling_n",
        head: "F_e lin",
        label: "linear force F_e (rolling)",
        unit: "N",
        get: |c| Num(c.linear_force_rolling_n),
    },
    Q {
        key: "linear_force_lateral_n",
        head: "F_f lin",
        label: "linear force F_f (lateral)",
        unit: "N",
        get: |c| Num(c.linear_force_lateral_n),
    },
    Q {
        key: "linear_spin_moment_nm",
        head: "M_z lin",
        label: "linear spin moment M_z",
        unit: "N m",
        get: |c| Num(c.linear_spin_moment_nm),
    },
    Q { key: "force_rolling_n", head: "F_e", label: "saturated force F_e", unit: "N", get: |c| Num(c.force_rolling_n) },
    Q { key: "force_lateral_n", head: "F_f", label: "saturated force F_f", unit: "N", get: |c| Num(c.force_lateral_n) },
    Q {
        key: "spin_moment_nm",
        head: "M_z",
        label: "saturated spin moment M_z",
        unit: "N m",
        get: |c| Num(c.spin_moment_nm),
    },
    Q {
        key: "saturation",
        head: "sat.",
        label: "saturation (saturated / linear)",
        unit: "-",
        get: |c| Num(c.saturation),
    },
    Q { key: "friction_bound_n", head: "fQ", label: "friction bound f Q", unit: "N", get: |c| Num(c.friction_bound_n) },
    Q {
        key: "friction_coefficient",
        head: "mu",
        label: "friction coefficient (bound f Q / Q)",
        unit: "-",
        get: |c| Num(c.friction_coefficient),
    },
    Q {
        key: "film_central_um",
        head: "h_c",
        label: "central film thickness h_c",
        unit: "um",
        get: |c| Num(c.film_central_m * 1e6),
    },
    Q {
        key: "film_minimum_um",
        head: "h_min",
        label: "minimum film thickness h_min",
        unit: "um",
        get: |c| Num(c.film_minimum_m * 1e6),
    },
    Q {
        key: "lambda",
        head: "Lambda",
        label: "film parameter Lambda = h_c / sigma",
        unit: "-",
        get: |c| Num(c.lambda),
    },
    Q {
        key: "rolling_resistance_ehl_n",
        head: "F_R EHL",
        label: "EHL rolling resistance",
        unit: "N",
        get: |c| Num(c.rolling_resistance_ehl_n),
    },
    Q {
        key: "rolling_resistance_hysteresis_n",
        head: "F_R hyst",
        label: "hysteresis rolling resistance",
        unit: "N",
        get: |c| Num(c.rolling_resistance_hysteresis_n),
    },
    Q {
        key: "dissipation_per_ball_nm",
        head: "D/omega ball",
        label: "dissipation / omega, one ball",
        unit: "N m",
        get: |c| Num(c.dissipation_per_ball_nm),
    },
    Q {
        key: "torque_share_nm",
        head: "share",
        label: "torque share (the circle's full-load balls)",
        unit: "N m",
        get: |c| Num(c.torque_share_nm),
    },
    Q {
        key: "creep_torque_share_nm",
        head: "creep",
        label: "  of which creep and sliding",
        unit: "N m",
        get: |c| Num(c.creep_torque_share_nm),
    },
    Q {
        key: "rolling_torque_share_nm",
        head: "EHL roll.",
        label: "  of which EHL rolling resistance",
        unit: "N m",
        get: |c| Num(c.rolling_torque_share_nm),
    },
    Q {
        key: "hysteresis_torque_share_nm",
        head: "hyst.",
        label: "  of which elastic hysteresis",
        unit: "N m",
        get: |c| Num(c.hysteresis_torque_share_nm),
    },
];

/// The contact of `ballscrew contact` and `ballscrew creep-curves`.
pub static CONTACT_DATA: &[Q<Contact>] = &[
    Q {
        key: "semi_axis_rolling_mm",
        head: "a",
        label: "Hertz semi-axis a (rolling)",
        unit: "mm",
        get: |c| Num(c.semi_axis_rolling_m * 1e3),
    },
    Q {
        key: "semi_axis_lateral_mm",
        head: "b",
        label: "Hertz semi-axis b (lateral)",
        unit: "mm",
        get: |c| Num(c.semi_axis_lateral_m * 1e3),
    },
    Q { key: "a_over_b", head: "a/b", label: "a/b", unit: "-", get: |c| Num(c.a_over_b()) },
    Q { key: "c_mm", head: "c", label: "c = sqrt(a b)", unit: "mm", get: |c| Num(c.creep_length_m() * 1e3) },
    Q { key: "normal_load_n", head: "Q", label: "normal load Q", unit: "N", get: |c| Num(c.normal_load_n) },
    Q {
        key: "peak_pressure_mpa",
        head: "p0",
        label: "Hertz peak pressure",
        unit: "MPa",
        get: |c| Num(c.peak_pressure_pa() * 1e-6),
    },
    Q {
        key: "friction_coefficient",
        head: "mu",
        label: "friction coefficient mu",
        unit: "-",
        get: |c| Num(c.friction_coefficient),
    },
    Q {
        key: "friction_bound_n",
        head: "mu Q",
        label: "friction bound mu Q",
        unit: "N",
        get: |c| Num(c.friction_bound_n()),
    },
    Q {
        key: "shear_modulus_gpa",
        head: "G",
        label: "shear modulus G",
        unit: "GPa",
        get: |c| Num(c.shear_modulus_pa * 1e-9),
    },
];

/// The creepages of a contact run, as given and in the model's and Fig. 9's forms.
pub static CREEPAGES: &[Q<ContactRun>] = &[
    Q {
        key: "creep_xi_centre",
        head: "xi(0)",
        label: "xi on the centre line y = 0",
        unit: "-",
        get: |r| Num(r.creep.xi),
    },
    Q { key: "creep_eta", head: "eta", label: "eta (lateral)", unit: "-", get: |r| Num(r.creep.eta) },
    Q {
        key: "creep_phi_per_mm",
        head: "phi",
        label: "phi (spin)",
        unit: "1/mm",
        get: |r| Num(r.creep.phi_per_m * 1e-3),
    },
    Q {
        key: "heathcote_per_mm2",
        head: "k_h",
        label: "Heathcote coefficient k_h (xi + k_h y^2)",
        unit: "1/mm^2",
        get: |r| Num(r.creep.heathcote_per_m2 * 1e-6),
    },
    Q {
        key: "creep_heathcote",
        head: "xi_h",
        label: "Heathcote mean k_h b^2/5",
        unit: "-",
        get: |r| Num(r.heathcote_mean()),
    },
    Q {
        key: "creep_xi",
        head: "xi",
        label: "xi with the Heathcote mean (the model's xi)",
        unit: "-",
        get: |r| Num(r.model_xi()),
    },
    Q { key: "phi_c", head: "phi c", label: "phi c (dimensionless spin)", unit: "-", get: |r| Num(r.phi_c()) },
    Q { key: "kh_b2", head: "k_h b^2", label: "k_h b^2 (dimensionless Heathcote)", unit: "-", get: |r| Num(r.kh_b2()) },
];

/// Forces on the ball by one law.
pub static FORCES: &[Q<Forces>] = &[
    Q { key: "force_e_n", head: "F_e", label: "force F_e (rolling)", unit: "N", get: |f| Num(f.force_e_n) },
    Q { key: "force_f_n", head: "F_f", label: "force F_f (lateral)", unit: "N", get: |f| Num(f.force_f_n) },
    Q { key: "spin_moment_nm", head: "M_z", label: "spin moment M_z", unit: "N m", get: |f| Num(f.spin_moment_nm) },
    Q { key: "force_ratio", head: "|F|/muQ", label: "|F| / (mu Q)", unit: "-", get: |f| Num(f.force_ratio) },
    Q {
        key: "dissipation_per_speed_n",
        head: "D/V",
        label: "dissipation / rolling speed",
        unit: "N",
        get: |f| Num(f.dissipation_per_speed_n),
    },
];

/// What only FASTSIM reports.
pub static FASTSIM_EXTRA: &[Q<ContactRun>] = &[
    Q { key: "bound", head: "bound", label: "traction bound", unit: "-", get: |r| Text(r.bound.name()) },
    Q { key: "grid", head: "grid", label: "elements per axis", unit: "-", get: |r| Int(r.grid as u64) },
    Q {
        key: "adhesion_share",
        head: "adhesion",
        label: "adhesion share (elements)",
        unit: "-",
        get: |r| Num(r.fastsim.result.adhesion_share()),
    },
    Q {
        key: "adhesion_elements",
        head: "adh.",
        label: "elements in adhesion",
        unit: "-",
        get: |r| Int(u64::from(r.fastsim.result.adhesion_elements)),
    },
    Q {
        key: "slip_elements",
        head: "slip",
        label: "elements in slip",
        unit: "-",
        get: |r| Int(u64::from(r.fastsim.result.slip_elements)),
    },
];

/// What only the model's law (Eq. 24) reports.
pub static EQ24_EXTRA: &[Q<ContactRun>] = &[
    Q {
        key: "linear_force_e_n",
        head: "F_e lin",
        label: "linear force F_e (Eq. 23)",
        unit: "N",
        get: |r| Num(r.law.force.linear_e_n),
    },
    Q {
        key: "linear_force_f_n",
        head: "F_f lin",
        label: "linear force F_f (Eq. 23)",
        unit: "N",
        get: |r| Num(r.law.force.linear_f_n),
    },
    Q {
        key: "linear_spin_moment_nm",
        head: "M_z lin",
        label: "linear spin moment M_z",
        unit: "N m",
        get: |r| Num(r.law.force.linear_moment_nm),
    },
    Q {
        key: "saturation",
        head: "sat.",
        label: "saturation (saturated / linear)",
        unit: "-",
        get: |r| Num(r.law.force.saturation),
    },
];

/// One point of a creep curve (`ballscrew creep-curves`).
pub static CURVE_ROW: &[Q<CurvePoint>] = &[
    Q { key: "parameter", head: "parameter", label: "creep parameter", unit: "-", get: |p| Text(p.parameter.name()) },
    Q { key: "law", head: "law", label: "force law", unit: "-", get: |p| Text(p.law.name()) },
    Q { key: "value", head: "value", label: "parameter value", unit: "-", get: |p| Num(p.value) },
    Q { key: "force_e_n", head: "F_e", label: "force F_e", unit: "N", get: |p| Num(p.forces.force_e_n) },
    Q { key: "force_f_n", head: "F_f", label: "force F_f", unit: "N", get: |p| Num(p.forces.force_f_n) },
    Q {
        key: "spin_moment_nm",
        head: "M_z",
        label: "spin moment M_z",
        unit: "N m",
        get: |p| Num(p.forces.spin_moment_nm),
    },
    Q { key: "force_ratio", head: "|F|/muQ", label: "|F| / (mu Q)", unit: "-", get: |p| Num(p.forces.force_ratio) },
    Q {
        key: "adhesion_share",
        head: "adhesion",
        label: "adhesion share (FASTSIM)",
        unit: "-",
        get: |p| Num(p.adhesion_share),
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    /// A quantity's (key, unit) by its column head.
    fn by_head<T>(list: &[Q<T>], head: &str) -> Vec<(&'static str, &'static str)> {
        list.iter().filter(|q| q.head == head).map(|q| (q.key, q.unit)).collect()
    }

    #[test]
    fn the_spin_creepage_has_one_name_and_one_unit_in_every_command() {
        // `inspect` (every contact of the screw) and `contact` (one contact), and Python's
        // records under the same key (crates/py/tests/test_parity.py).
        let spin = [("creep_phi_per_mm", "1/mm")];
        assert_eq!(by_head(CONTACT, "phi"), spin);
        assert_eq!(by_head(CREEPAGES, "phi"), spin);
    }

    #[test]
    fn a_sweep_row_names_its_whole_operating_point() {
        let keys = |swept: &Q<SweepRow>, lubrication| -> Vec<&str> {
            held(swept, lubrication).iter().map(|q| q.key).collect()
        };
        let ehl = Lubrication::Ehl;
        assert_eq!(keys(&SWEPT_PRELOAD, ehl), ["speed_rpm", "axial_load_n", "oil_temperature_c"]);
        assert_eq!(keys(&SWEPT_PRELOAD, Lubrication::Dry), ["speed_rpm", "axial_load_n"]);
        assert_eq!(keys(&SWEPT_AXIAL_LOAD, ehl), ["preload_n", "speed_rpm", "oil_temperature_c"]);
        assert_eq!(keys(&SWEPT_OIL_TEMPERATURE, ehl), ["preload_n", "speed_rpm", "axial_load_n"]);
    }

    #[test]
    fn sweep_columns_are_point_quantities_and_a_row_of_inspect_has_unique_keys() {
        let names = |k: &'static str, h: &'static str, l: &'static str, u: &'static str| (k, h, l, u);
        let sweep = SWEEP.iter().map(|q| names(q.key, q.head, q.label, q.unit));
        let swept = SWEPT[..3].iter().map(|q| names(q.key, q.head, q.label, q.unit));
        for (key, head, label, unit) in sweep.chain(swept) {
            let p = by_key(POINT, key).unwrap_or_else(|| panic!("{key} is not in POINT"));
            assert_eq!((p.head, p.label, p.unit), (head, label, unit), "{key}");
        }
        assert!(by_key(POINT, SWEPT_OIL_TEMPERATURE.key).is_none());
        let mut keys: Vec<&str> = (BALL_ID.iter().chain(BALL).map(|q| q.key))
            .chain(CONTACT_ID.iter().chain(CONTACT).map(|q| q.key))
            .collect();
        let n = keys.len();
        keys.sort_unstable();
        keys.dedup();
        assert_eq!(keys.len(), n);
    }
}
