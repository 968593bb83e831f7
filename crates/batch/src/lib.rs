//! Many operating points evaluated over the machine's cores: what Python's `Screw.torque` on
//! arrays, `predict` (command line and Python) and other batches call.
//!
//! - [`torques`] ([`evaluated`]): drive torques at many points by the control-loop evaluator,
//!   band by band of speed, each band with a start table at its own speed; the model's own
//!   solver where the evaluator does not apply (FASTSIM, oversize balls) or the batch is small.
//! - [`pool`]: the threads of every batch; [`map_points`], [`map_points_warm`]: any evaluation
//!   by the model, point by point; [`map_shared`]: evaluations that carry nothing from one to
//!   the next (cold solves, fits), each taken by the next free thread.
//! - [`sweep`]: a range `A..B` in steps, as a sweep takes it ([`SweepRange`]: the range flags of
//!   the command line read, checked and turned into points; Python's default preloads).
//!
//! The points are split into one contiguous chunk per thread; each thread keeps its own
//! solver state and warm-starts every point from the one before it (as the command line's
//! sweep does). A point's result therefore agrees with a cold evaluation to the solver's
//! tolerance, not bit for bit, and depends on no shortcut: every point is solved in full.
//! Points solved cold one by one (those the control-loop evaluator hands to the model) are
//! shared out instead, each to the next free thread ([`map_shared`]): their results are the
//! same whatever thread takes them.
//!
//! [`map_points`] keeps the caller's order. [`map_points_warm`] first orders the points so that
//! each starts from a near neighbour ([`warm_order`]): a warm start from a distant point (say
//! 500 N to 3000 N) fails and falls back to a cold solve by continuation, hundreds of times
//! slower, so a batch in random order would spend nearly all its time in cold solves. Results
//! come back in the caller's order either way. The first failing point in evaluation order is
//! reported, whatever the thread that met it.
//!
//! Every thread asks a [`Stop`] before each point whether to stop (the Python side stops on
//! Ctrl-C); the calling thread asks it too while it waits for the others.

extern crate alloc;

pub mod evaluated;
pub mod pool;
pub mod sweep;

pub use evaluated::{BAND_RATIO, EVALUATOR_MIN_POINTS, MIN_BAND_RATIO, POINTS_PER_BAND, torques};
pub use pool::*;
pub use sweep::{MAX_SWEEP_POINTS, RangeText, SweepError, SweepFlags, SweepRange};
