//! # ballscrew-core
//!
//! The friction (drag) torque of a preloaded ball screw from rolling-contact creep analysis:
//! the model of Xu, Tang, Chen, Bao and Guo, "Modeling analysis and experimental study for the
//! friction of a ball screw", Mechanism and Machine Theory 87 (2015), implemented end to end with
//! the corrections and decisions of the project's model notes.
//!
//! The layers, from the ground up; each uses only those below it:
//! - [`error`], [`real`]: the error types and the float trait (f64, f32) every layer shares,
//!   with its SIMD lanes ([`real::lanes`]);
//! - [`input`]: what the user describes (Table 1, the model options, the extensions) and its
//!   validation;
//! - [`contact`]: one contact: Hertz, creepages, Kalker's creep forces saturated into Coulomb
//!   friction, FASTSIM;
//! - [`ball`]: one ball's quasi-static balance and its solvers;
//! - [`screw`]: the load of every ball and the torque of the whole screw ([`Model`]);
//! - [`realtime`]: the torque for a control loop ([`Evaluator`], f64 or f32) and the torque map.
//!
//! The core is `#![no_std]` unless the `std` feature is on (default); it never allocates.
//! SI units throughout.
#![cfg_attr(not(feature = "std"), no_std)]

#[cfg(feature = "std")]
extern crate std;

pub mod ball;
pub mod contact;
pub mod error;
pub mod input;
pub mod real;
pub mod realtime;
pub mod screw;

pub use error::{Error, InputError, Invalid, Measured, Short, Shown, Significant, Unphysical, ValidRange};
pub use input::{Conditions, Extensions};
pub use input::{
    ContactTheory, CreepCoefficientSource, Friction, Geometry, LoadDistribution, Lubricant, Lubrication, Material,
    ModelOptions, OperatingPoint, Preload, ScrewSpec, SpinMoment, TorqueRoute,
};
pub use realtime::evaluator::{EvalState, Evaluator, TableEntries};
pub use realtime::reversal::{ReversalModel, ReversalState};
pub use realtime::stepper::Stepper;
pub use screw::efficiency::{Efficiency, efficiency, efficiency_beside, efficiency_if_defined};
pub use screw::model::{Model, SolverState};
pub use screw::report::{BallReport, ContactKind, ContactReport, Evaluation, Summary};
