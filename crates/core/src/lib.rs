//! # ballscrew-core
//!
//! The friction (drag) torque of a preloaded ball screw from rolling-contact creep analysis:
//! the model of Xu, Tang, Chen, Bao and Guo, "Modeling analysis and experimental study for the
//! friction of a ball screw", Mechanism and Machine Theory 87 (2015), implemented end to end with
//! the corrections and decisions of the project's model notes.
//!
//! The chain, one module per idea:
//! - [`spec`]: the screw (Table 1), its validation and the model options;
//! - [`geometry`]: helix angle, ball spacing, principal curvatures at the contacts;
//! - [`elliptic`], [`hertz`]: exact Hertz point contact (complete elliptic integrals by AGM);
//! - [`frames`]: global, Frenet-Serret and contact frames (Eqs. 1-2, corrected);
//! - [`load`]: preload and axial load over nuts, circles and balls (Eq. 26);
//! - [`creep`]: creepages with spin and Heathcote slip from one vector computation (Eqs. 3-22);
//! - [`kalker`], [`saturation`], [`forces`]: Kalker's linear creep forces (Eq. 23) saturated
//!   into Coulomb friction (Eq. 24);
//! - [`kinematics`]: the quasi-static balance of one ball, solved by Newton with continuation;
//!   [`balance`]: the same balance in lean form, generic over the float type ([`real`]);
//! - [`torque`]: the friction torque of the whole screw (energy balance; Eq. 27 as an option);
//! - [`extensions`]: terms beyond the paper (seals, lubricant, waviness, wear), off by default.
//! - [`realtime`]: the torque for a control loop, in f64 or f32, warm- and table-started;
//! - [`map`]: the torque tabulated over preload and speed for firmware, bilinear lookup.
//!
//! The core is `#![no_std]` unless the `std` feature is on (default); it never allocates.
//! SI units throughout.
#![cfg_attr(not(feature = "std"), no_std)]

#[cfg(feature = "std")]
extern crate std;

#[cfg(feature = "diagnose")]
extern crate alloc;

pub mod balance;
pub mod catalog;
pub mod creep;
pub mod elliptic;
pub mod error;
pub mod extensions;
pub mod fastsim;
pub mod forces;
pub mod frames;
pub mod geometry;
pub mod hertz;
pub mod kalker;
pub mod kinematics;
pub mod load;
pub mod map;
pub mod real;
pub mod realtime;
pub mod saturation;
pub mod spec;
pub mod torque;

#[cfg(feature = "config")]
pub mod config;

#[cfg(feature = "diagnose")]
pub mod diagnose;

pub use error::{Error, InputError, Shown};
pub use extensions::{Conditions, Extensions};
pub use realtime::{EvalState, Evaluator};
pub use spec::{
    ContactTheory, CreepCoefficientSource, Friction, Geometry, LoadDistribution, Material, ModelOptions,
    OperatingPoint, ScrewSpec, SpinMoment, TorqueRoute,
};
pub use torque::{BallReport, ContactKind, ContactReport, Evaluation, Model, SolverState, Summary};
