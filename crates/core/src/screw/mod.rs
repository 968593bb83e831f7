//! The whole screw: the raceways' curvatures, the load of every nut, circle and ball, and the
//! friction torque summed over them.
//!
//! - [`raceway`]: principal curvatures at the ball-screw and ball-nut contacts;
//! - [`load`]: preload and axial load over nuts, circles and balls (Eq. 26);
//! - [`model`]: the [`model::Model`], the crate's main type: every ball solved, the torque by the
//!   energy balance (Eq. 27 as an option), the terms of [`crate::input::extensions`] added;
//! - [`train`]: the ball train of a circuit: the loads between neighbouring balls from their
//!   orbit rates and the return's resistance;
//! - [`report`]: what the model reports of a solved screw (contacts, balls, the summary of a
//!   point);
//! - [`catalog`]: the manufacturers' catalog estimate of the drag torque, for comparison;
//! - [`efficiency`]: the forward and backdrive efficiency under an axial load, from the model's
//!   drive torque at both rotations;
//! - [`inertia`]: the ball's centrifugal force and gyroscopic moment the quasi-static model
//!   leaves out, against its contact load: where the model holds.
//!
//! It uses the ball and contact layers and the spec; nothing above it.

pub mod catalog;
pub mod circuit;
pub mod efficiency;
pub mod inertia;
pub mod load;
pub mod model;
pub mod raceway;
pub mod report;
pub mod train;
