//! Evaluation for a control loop: the torque of [`Model`](crate::Model) in `f64` or `f32`, with no allocation,
//! warm-started from the previous calls and cold-started from a table of solved balls.
//!
//! [`Evaluator`] is built once from a model. It keeps, per flank, the load-independent factors
//! of the balance ([`balance::Constants`](crate::ball::balance::Constants)) and a table of solved balls over a geometric grid of
//! ball loads (ratio [`TABLE_RATIO`], from [`TABLE_FIRST_LOAD_N`]), found in f64 by the model's
//! continuation (docs/model-notes.md item 11). Each entry holds the solution, its derivative in the
//! logarithm of the load (implicit differentiation of the balance) and the inverse of the
//! balance's Jacobian. A cold start interpolates the solution in log load (cubic Hermite) and
//! the inverse Jacobian (linear), and lands on the branch the continuation selects.
//!
//! Reversing the screw and swapping the flank is a half turn of the whole screw about the radial
//! line through the ball: the balance of a ball on flank s turning backwards is that of a ball
//! on flank -s turning forwards with omega_n negated, and its dissipation per signed speed
//! changes sign (a unit test holds the two to rounding). So every ball is solved turning
//! forwards on its mirrored flank, one table per flank serves both directions, and a reversal
//! at constant load finds the other nut's solution in the warm state.
//!
//! [`EvalState`] carries each ball's last four solutions and its inverse Jacobian. A warm start
//! extrapolates the solutions along their path in load and speed (the quadratic through the
//! newest three where they are well spread, the cubic through all four for lubricated
//! contacts in f64, else along the secant); a ball whose load has jumped by more than 1 % since its last solve starts from
//! the table instead. Each call then solves every circle's ball in the chosen float type with
//! the lean balance ([`balance::evaluate`](crate::ball::balance::evaluate), Eqs. 3-24), the balance at every ball's first start
//! evaluated for four f64 or eight f32 balls at once in SIMD lanes ([`Real::Wide`](crate::real::Real::Wide), each lane
//! the single ball's result to the bit), by Broyden's method on the inverse
//! Jacobian (one matrix-vector product a step, no linear solve) to the tolerance
//! [`Evaluator::tolerance`], and sums the torque (Eqs. 25-27 by the model's route, `docs/model-notes.md`
//! item 9). A warm start whose remembered inverse Jacobian stalls is retried once with a fresh
//! one there (finite differences, f64). A table start that stalls falls back to Newton's method
//! with a fresh Jacobian from each of the two entries around the load (nearest first), after
//! which the ball keeps the inverse of the Jacobian at its solution, then
//! to the model's continuation in f64 (a load outside the table, a ball that does not converge from
//! it), whose result is taken where the model takes it (a light ball, whose nearly degenerate
//! balance reaches no tight residual: see [`crate::screw::model::ACCEPT_RESIDUAL`]). What stays in
//! f64: the table (at build), the split of the preload between the nuts (a scalar root) and the
//! extension terms of the spec.
//!
//! The rooms: this file holds the public API ([`Evaluator`]: build, support, the torque of a
//! call and its sum over the balls); `table.rs` the start table; `memory.rs` the warm-start memory
//! ([`EvalState`]); `lanes.rs` the balls of a call in groups of the SIMD lanes; `solver.rs` one
//! ball's solver steps (Broyden, Newton, the continuation, f32's check in f64); `stats.rs` what
//! the tests count (nothing outside them).

mod api;
mod lanes;
mod linear;
mod memory;
mod solver;
mod stats;
mod table;
#[cfg(test)]
mod tests;

pub use api::Evaluator;
pub(crate) use lanes::{Groups, MECHANISMS};
pub use memory::{EVAL_STATE_VALUES, EvalState};
pub use table::{CARRY_SPEED_RATIO, LIGHT_BALL_N, TABLE_FIRST_LOAD_N, TABLE_LEN, TABLE_RATIO, TableEntries};
