//! A screw's drive torque point after point, each warm-started from the one before: the
//! control-loop [`Evaluator`] where it takes the spec, else the model's own solve
//! ([`Model::torque`] with its [`SolverState`]) for the specs it does not take (the four-point
//! balls of an oversize-ball nut, FASTSIM contacts: [`Evaluator::supports`]). What a drive
//! simulation steps (the FMU, Python's `Evaluator`). No allocation.

use crate::error::Error;
use crate::input::OperatingPoint;
use crate::real::Real;
use crate::realtime::evaluator::{EvalState, Evaluator};
use crate::screw::model::{Model, SolverState};

/// What evaluates the torques, with its warm state (see the module's documentation). Large
/// (the evaluator's start table: tens of kB): keep it on the heap where the stack is small.
#[allow(clippy::large_enum_variant, reason = "one per simulation, never moved in a loop")]
#[derive(Debug, Clone)]
pub enum Stepper<F: Real> {
    /// The control-loop evaluator in `F`.
    Evaluator {
        /// The evaluator.
        evaluator: Evaluator<F>,
        /// Its warm state.
        state: EvalState<F>,
    },
    /// The model's own solve (f64), for a spec the evaluator does not take.
    Model {
        /// The model.
        model: Model,
        /// Its warm state.
        state: SolverState,
    },
}

impl<F: Real> Stepper<F> {
    /// The control-loop evaluator of `model` in `F` with an empty state; its error where it
    /// does not take the spec ([`Evaluator::supports`]).
    pub fn evaluator(model: &Model) -> Result<Self, Error> {
        Ok(Self::Evaluator { evaluator: Evaluator::new(model)?, state: EvalState::new() })
    }

    /// The drive torque (N m) at `op`, warm-started from the last call.
    pub fn torque_nm(&mut self, op: &OperatingPoint) -> Result<f64, Error> {
        match self {
            Self::Evaluator { evaluator, state } => evaluator.torque_nm(op, state).map(Real::to_f64),
            Self::Model { model, state } => model.torque(op, state),
        }
    }

    /// Forgets the warm state: the next point starts cold (from the evaluator's table; on the
    /// model's solve, by its continuation).
    pub fn reset(&mut self) {
        match self {
            Self::Evaluator { state, .. } => state.reset(),
            Self::Model { state, .. } => *state = SolverState::new(),
        }
    }

    /// The model whose torque it steps (the evaluator's own).
    pub fn model(&self) -> &Model {
        match self {
            Self::Evaluator { evaluator, .. } => evaluator.model(),
            Self::Model { model, .. } => model,
        }
    }

    /// "evaluator" or "model": what evaluates the torques.
    pub fn name(&self) -> &'static str {
        match self {
            Self::Evaluator { .. } => "evaluator",
            Self::Model { .. } => "model",
        }
    }

    /// Tolerance of the ball balance's solve on the scaled residual (max norm): the
    /// evaluator's, or the model's [`crate::ball::setup::TOLERANCE`].
    pub fn tolerance(&self) -> f64 {
        match self {
            Self::Evaluator { evaluator, .. } => evaluator.tolerance().to_f64(),
            Self::Model { .. } => crate::ball::setup::TOLERANCE,
        }
    }
}

impl Stepper<f64> {
    /// The control-loop evaluator of `model` where it takes the spec, else the model's own
    /// solve; both with an empty state.
    pub fn new(model: &Model) -> Result<Self, Error> {
        if Evaluator::<f64>::supports(model.spec()).is_ok() {
            Self::evaluator(model)
        } else {
            Ok(Self::Model { model: *model, state: SolverState::new() })
        }
    }
}
