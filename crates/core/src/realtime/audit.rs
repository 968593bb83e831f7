//! A stateful stepper's check of its answers against the canonical state.
//!
//! A ball's balance can have more than one steady state at the same operating point
//! (docs/model-notes.md item 24). A stateless request reports the *canonical* state, the one
//! the model's cold continuation from the linear ball reaches ([`Model::torque`] from
//! [`SolverState::new`]); a stepper that warm-starts each point from the one before (the
//! control-loop evaluator, the model's warm solve, the FMU and Python's `Evaluator` that run
//! them: [`crate::Stepper`]) follows its history, as a real screw does, and may sit on another
//! state. No cheap test tells which state the cold continuation would reach, so an [`Audit`]
//! solves it: on every `every`-th call (the first call, then each `every` calls after it) it
//! solves the point cold and compares. A call *departs* when the stepper's torque differs from
//! the canonical torque by more than the audit's tolerance, relative to the canonical drag
//! torque, or to [`TORQUE_SHARE`] of the canonical torque where the drag is smaller (at
//! standstill under an axial load the drag is zero and the torque the load's: the stepper's
//! rounding of that torque is no departure), and to [`DRAG_FLOOR_NM`] at least; a point whose
//! cold solve fails while the stepper gave a number departs too (its departure infinite, the
//! cold solve's error kept). The reversal model
//! ([`crate::ReversalModel`]) leaves the steady torque on purpose after every reversal: what is
//! audited there is the steady torque its state settles on at a step's speed
//! ([`crate::ReversalModel::steady_torque_at`], through [`Audit::check_lazily`]).
//!
//! An audited call costs a cold solve of the model (about 0.3-2 ms of a core on DKFZD4012,
//! against a few microseconds for the evaluator's warm step): an audit is for simulations and
//! studies, not for a firmware's control loop. With `every = 0` it counts the calls and solves
//! nothing. No allocation.

use crate::error::{Error, InputError, Short};
use crate::input::OperatingPoint;
use crate::screw::model::{Model, SolverState};
use core::fmt;

/// Tolerance of an audit of an `f64` stepper, relative to the canonical drag torque: a hundred
/// times the f64 evaluator's agreement with the model off the states' fold (1e-8, docs/real-time.md),
/// below the smallest departure measured on the other state of DKFZD4012 (1e-5 to 5e-5).
pub const F64_TOLERANCE: f64 = 1e-6;
/// Tolerance of an audit of an `f32` stepper: five times the f32 evaluator's stated agreement
/// with the model (1e-4); a departure smaller than f32's own error is not told from it.
pub const F32_TOLERANCE: f64 = 5e-4;
/// Smallest share of the canonical torque a departure is taken relative to: where the drag
/// torque is smaller (the torque nearly all the axial load's), a thousandth of the torque, so
/// that f32's rounding of the load's torque (about 1e-7 of it) stays far below the tolerance.
pub const TORQUE_SHARE: f64 = 1e-3;
/// Smallest torque a departure is taken relative to, N m (no torque at all at standstill
/// without an axial load).
pub const DRAG_FLOOR_NM: f64 = 1e-9;
/// Valid tolerances, for messages.
pub const TOLERANCE_VALID: &str = "finite and > 0, relative to the drag torque";

/// A call whose torque departed from the canonical state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Departure {
    /// Where: the call's operating point.
    pub op: OperatingPoint,
    /// The stepper's torque, N m.
    pub torque_nm: f64,
    /// The canonical torque (the model's cold solve), N m; NaN where that solve fails.
    pub canonical_torque_nm: f64,
    /// `|torque - canonical| / max(|canonical drag|, TORQUE_SHARE |canonical|, DRAG_FLOOR_NM)`;
    /// infinite where the cold solve fails.
    pub relative: f64,
    /// The cold solve's error, where it fails.
    pub cold_error: Option<Error>,
}

impl fmt::Display for Departure {
    /// `2.67721 N m against the canonical 2.67998 N m, 0.0191 of the drag torque apart`, or
    /// `2.5 N m where the cold solve fails: ...`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.cold_error {
            Some(e) => write!(f, "{} N m where the cold solve fails: {e}", Short(self.torque_nm)),
            None => write!(
                f,
                "{} N m against the canonical {} N m, {} of the drag torque apart",
                Short(self.torque_nm),
                Short(self.canonical_torque_nm),
                Short(self.relative)
            ),
        }
    }
}

/// What a stepper's audit found so far (see the module's documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Audit {
    every: u32,
    tolerance: f64,
    calls: u64,
    audited: u64,
    departed: u64,
    largest: f64,
    first: Option<Departure>,
}

impl Audit {
    /// An audit of every `every`-th call (0: none) at `tolerance` (relative to the canonical
    /// drag torque); an error naming `tolerance` where it is not finite and positive.
    pub fn new(every: u32, tolerance: f64) -> Result<Self, InputError> {
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(InputError { field: "audit tolerance", value: tolerance, valid: TOLERANCE_VALID });
        }
        Ok(Self { every, tolerance, calls: 0, audited: 0, departed: 0, largest: 0.0, first: None })
    }

    /// An audit that solves nothing (it counts the calls).
    pub const fn off() -> Self {
        Self { every: 0, tolerance: F64_TOLERANCE, calls: 0, audited: 0, departed: 0, largest: 0.0, first: None }
    }

    /// Counts a call of a stepper of `model` that gave `torque_nm` at `op` and, if it is one to
    /// audit, solves the point cold and compares: the departure where the call departs.
    pub fn check(&mut self, model: &Model, op: &OperatingPoint, torque_nm: f64) -> Option<Departure> {
        self.check_lazily(model, || Some((*op, torque_nm)))
    }

    /// [`Audit::check`] for a stepper whose compared answer costs a computation (the reversal
    /// model's steady torque at a step's speed): `answer` gives the point and the torque, and is
    /// called only for a call to audit; `None` (nothing to compare: a step that does not turn,
    /// an answer that fails) counts the call but audits nothing.
    pub fn check_lazily(
        &mut self,
        model: &Model,
        answer: impl FnOnce() -> Option<(OperatingPoint, f64)>,
    ) -> Option<Departure> {
        self.calls += 1;
        if self.every == 0 || !(self.calls - 1).is_multiple_of(u64::from(self.every)) {
            return None;
        }
        let (op, torque_nm) = answer()?;
        self.audited += 1;
        let (canonical_torque_nm, relative, cold_error) = match model.torque(&op, &mut SolverState::new()) {
            Ok(t) => {
                let drag = (t - model.load_torque_nm(&op)).abs();
                let scale = drag.max(TORQUE_SHARE * t.abs()).max(DRAG_FLOOR_NM);
                (t, (torque_nm - t).abs() / scale, None)
            }
            Err(e) => (f64::NAN, f64::INFINITY, Some(e)),
        };
        self.largest = self.largest.max(relative);
        if relative <= self.tolerance {
            return None;
        }
        let d = Departure { op, torque_nm, canonical_torque_nm, relative, cold_error };
        self.departed += 1;
        self.first.get_or_insert(d);
        Some(d)
    }

    /// Forgets what was found (the calls too); the interval and tolerance stay.
    pub fn reset(&mut self) {
        *self = Self { every: self.every, tolerance: self.tolerance, ..Self::off() };
    }

    /// Every how many calls a call is audited (0: none).
    pub const fn every(&self) -> u32 {
        self.every
    }

    /// The tolerance, relative to the canonical drag torque.
    pub const fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// Calls counted.
    pub const fn calls(&self) -> u64 {
        self.calls
    }

    /// Calls audited (solved cold and compared).
    pub const fn audited(&self) -> u64 {
        self.audited
    }

    /// Audited calls that departed from the canonical state by more than the tolerance.
    pub const fn departed(&self) -> u64 {
        self.departed
    }

    /// Largest relative departure of an audited call (0 before any; infinite where a cold solve
    /// failed).
    pub const fn largest_departure(&self) -> f64 {
        self.largest
    }

    /// The first call that departed.
    pub const fn first_departure(&self) -> Option<Departure> {
        self.first
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::{ScrewSpec, rpm_to_rad_s};

    fn op(rpm: f64) -> OperatingPoint {
        OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: 2000.0, axial_load_n: 0.0 }
    }

    #[test]
    fn it_audits_the_first_call_then_every_nth_and_counts_departures() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let canonical = model.torque(&op(100.0), &mut SolverState::new()).unwrap();
        let mut a = Audit::new(3, F64_TOLERANCE).unwrap();
        // Calls 1, 4, 7 are audited: the first exact, the fourth 1e-5 off, the seventh 1e-7 off.
        let given = [1.0, 2.0, 2.0, 1.0 + 1e-5, 2.0, 2.0, 1.0 + 1e-7];
        let found = given.map(|g| a.check(&model, &op(100.0), canonical * g));
        assert_eq!((a.calls(), a.audited(), a.departed()), (7, 3, 1));
        assert!(found[3].is_some() && found.iter().filter(|f| f.is_some()).count() == 1);
        let d = a.first_departure().unwrap();
        assert_eq!(d.canonical_torque_nm, canonical);
        assert!((d.relative - 1e-5).abs() < 1e-9, "{}", d.relative);
        assert_eq!(a.largest_departure(), d.relative);
        a.reset();
        assert_eq!((a.calls(), a.audited(), a.departed(), a.every()), (0, 0, 0, 3));
        let mut off = Audit::off();
        assert!(off.check(&model, &op(100.0), 2.0 * canonical).is_none());
        assert_eq!((off.calls(), off.audited()), (1, 0));
        // At standstill under an axial load the drag is zero: a torque off by f32's rounding of
        // the load's torque is no departure, one off by a hundredth of it is.
        let still = OperatingPoint { speed_rad_s: 0.0, preload_n: 2000.0, axial_load_n: 300.0 };
        let load = model.torque(&still, &mut SolverState::new()).unwrap();
        assert_eq!(load, model.load_torque_nm(&still));
        let mut a = Audit::new(1, F32_TOLERANCE).unwrap();
        assert!(a.check(&model, &still, f64::from(load as f32) * (1.0 + 1e-7)).is_none());
        assert!(a.check(&model, &still, load * 1.01).is_some());
        // A point whose cold solve fails departs, the error kept and said.
        let nowhere = OperatingPoint { speed_rad_s: 10.0, preload_n: 1e-200, axial_load_n: 0.0 };
        let d = Audit::new(1, F64_TOLERANCE).unwrap().check(&model, &nowhere, 0.5).unwrap();
        assert!(d.cold_error.is_some() && d.relative.is_infinite() && d.canonical_torque_nm.is_nan());
        let text = std::format!("{d}");
        assert!(text.starts_with("0.5 N m where the cold solve fails: "), "{text}");
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            let e = Audit::new(1, bad).unwrap_err();
            assert_eq!(e.field, "audit tolerance");
        }
    }
}
