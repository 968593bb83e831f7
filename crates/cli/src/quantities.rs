//! What only the command line reports, each quantity named once as the table of reported
//! quantities names the rest ([`ballscrew_batch::quantities`], which Python reads too): a
//! reversal's samples and what it comes to (`ballscrew reversal`, run by the command line alone
//! in [`crate::reversal_run`]).

use crate::reversal_run::{REFORMED_FRACTION, Sample, Summary as ReversalSummary};
use ballscrew_batch::quantities::Value::{Int, Num, Text};
use ballscrew_batch::quantities::{AXIAL, LOAD, PRELOAD, Quantity, SPEED, TORQUE};

type Q<T> = Quantity<T>;

/// One sample of `ballscrew reversal`.
pub static REVERSAL_ROW: &[Q<Sample>] = &[
    Q { key: "time_s", head: "time", label: "time", unit: "s", get: |r| Num(r.time_s) },
    Q { key: "angle_rad", head: "angle", label: "screw angle", unit: "rad", get: |r| Num(r.angle_rad) },
    Q {
        key: SPEED.key,
        head: SPEED.head,
        label: "screw speed (mean of the step)",
        unit: SPEED.unit,
        get: |r| Num(r.speed_rpm),
    },
    Q { key: TORQUE.key, head: "torque", label: "drive torque, state model", unit: "N m", get: |r| Num(r.torque_nm) },
    Q {
        key: "static_torque_nm",
        head: "static",
        label: "drive torque, static model (faded below the standstill speed)",
        unit: "N m",
        get: |r| Num(r.static_torque_nm),
    },
];

/// What a reversal comes to (`ballscrew reversal`).
pub static REVERSAL_SUMMARY: &[Q<ReversalSummary>] = &[
    Q { key: PRELOAD.key, head: PRELOAD.head, label: PRELOAD.label, unit: PRELOAD.unit, get: |s| Num(s.preload_n) },
    Q { key: AXIAL.key, head: AXIAL.head, label: AXIAL.label, unit: AXIAL.unit, get: |s| Num(s.axial_load_n) },
    Q {
        key: SPEED.key,
        head: "peak speed",
        label: "peak screw speed",
        unit: SPEED.unit,
        get: |s| Num(s.peak_speed_rpm),
    },
    Q {
        key: "amplitude_rad",
        head: "A",
        label: "amplitude A of theta = A sin(2 pi t / period)",
        unit: "rad",
        get: |s| Num(s.motion.amplitude_rad().abs()),
    },
    Q { key: "period_s", head: "period", label: "period", unit: "s", get: |s| Num(s.motion.period_s()) },
    Q { key: "step_rad", head: "step", label: "largest rotation of a step", unit: "rad", get: |s| Num(s.max_step_rad) },
    Q { key: "time_step_s", head: "dt", label: "time step", unit: "s", get: |s| Num(s.motion.dt_s()) },
    Q { key: "steps", head: "steps", label: "steps through the reversal", unit: "-", get: |s| Int(s.steps) },
    Q { key: "precision", head: "precision", label: "float type", unit: "-", get: |s| Text(s.precision.name()) },
    Q {
        key: "stiffness_nm_per_rad",
        head: "sigma",
        label: "Dahl stiffness sigma (slope from rest; about 2 sigma after a reversal)",
        unit: "N m/rad",
        get: |s| Num(s.stiffness_nm_per_rad),
    },
    Q { key: LOAD.key, head: LOAD.head, label: LOAD.label, unit: LOAD.unit, get: |s| Num(s.axial_term_nm) },
    Q {
        key: "steady_torque_before_nm",
        head: "before",
        label: "steady torque before the reversal (peak speed)",
        unit: "N m",
        get: |s| Num(s.steady_torque_nm[0]),
    },
    Q {
        key: "steady_torque_after_nm",
        head: "after",
        label: "steady torque after the reversal (peak speed)",
        unit: "N m",
        get: |s| Num(s.steady_torque_nm[1]),
    },
    Q {
        key: "zero_crossing_angle_rad",
        head: "zero angle",
        label: "screw angle from the turning point to the torque's zero crossing",
        unit: "rad",
        get: |s| Num(s.zero_crossing_rad),
    },
    Q {
        key: "zero_crossing_travel_um",
        head: "zero travel",
        label: "  nut travel (angle x lead / 2 pi)",
        unit: "um",
        get: |s| Num(s.travel_um(s.zero_crossing_rad)),
    },
    Q {
        key: "reformed_90_angle_rad",
        head: "90 % angle",
        label: "screw angle from the turning point to 90 % of the new steady torque",
        unit: "rad",
        get: |s| Num(s.reformed_rad),
    },
    Q {
        key: "reformed_90_travel_um",
        head: "90 % travel",
        label: "  nut travel (angle x lead / 2 pi)",
        unit: "um",
        get: |s| Num(s.travel_um(s.reformed_rad)),
    },
];

/// The share of the new steady torque in [`REVERSAL_SUMMARY`]'s `reformed_90` quantities.
const _: () = assert!(REFORMED_FRACTION == 0.9);
