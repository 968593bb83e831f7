//! The torque for a control loop and for firmware, built once from a [`crate::screw::torque::Model`]:
//!
//! - [`evaluator`]: the [`evaluator::Evaluator`], in f64 or f32, table- and warm-started, no
//!   allocation;
//! - [`map`]: the torque tabulated over preload and speed, bilinear lookup.
//!
//! It is the top layer of the core: it uses the screw layer and everything below it.

pub mod evaluator;
pub mod map;
