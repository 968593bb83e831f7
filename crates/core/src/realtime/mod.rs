//! The torque for a control loop and for firmware, built once from a [`crate::screw::model::Model`]:
//!
//! - [`audit`]: a stateful stepper's check of its answers against the canonical state (a cold
//!   solve every so many calls);
//! - [`evaluator`]: the [`evaluator::Evaluator`], in f64 or f32, table- and warm-started, no
//!   allocation;
//! - [`map`]: the torque tabulated over preload and speed, bilinear lookup;
//! - [`reversal`]: the friction torque through reversals, a state per circle of balls stepped
//!   with the screw's rotation (presliding), for servo simulations;
//! - [`stepper`]: point after point, warm-started, on the evaluator or (for a spec it does not
//!   take) the model's own solve: what a drive simulation steps.
//!
//! It is the top layer of the core: it uses the screw layer and everything below it.

pub mod audit;
pub mod evaluator;
pub mod map;
pub mod reversal;
pub mod stepper;
