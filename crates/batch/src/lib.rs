//! Many operating points evaluated over the machine's cores: what Python's `Screw.torque` on
//! arrays, `predict` (command line and Python) and other batches call.
//!
//! One way in: a [`Batch`] (threads, a [`Stop`], what a failing point does ([`Errors`]), how
//! the points share the threads ([`Start`])) and its two evaluations:
//!
//! - [`Batch::torques`] (`torques`): drive torques at many points: with [`Start::Independent`]
//!   (the default) each point's canonical state, the model's cold solve (what every stateless
//!   request reports, to the bit); with [`Start::Warm`] by the control-loop evaluator, band by
//!   band of speed, each band with a start table at its own speed, the model's own solver where
//!   the evaluator does not apply (FASTSIM, oversize balls) or the batch is small;
//! - [`Batch::map`]: any evaluation, point by point, over the threads of `pool`;
//! - [`sweep`]: a range `A..B` in steps, as a sweep takes it ([`SweepRange`]: the range flags of
//!   the command line read, checked and turned into points; Python's default preloads), and the
//!   sweep itself ([`sweep::sweep`]: each point solved cold over the threads, one [`SweepRow`] each),
//!   which the command line's `sweep` and Python's `Screw.sweep` both run.
//!
//! - [`uncertainty`]: the band of the drag torque from the spread of the spec's uncertain inputs
//!   (scrambled Sobol samples through the model), and each input's share of it.
//!
//! And what the shells report of the results: [`quantities`], every reported quantity named once
//! (key with its unit, heading, label, unit, how it is read and scaled), the one table the
//! command line renders as tables, CSV and JSON and Python turns into its objects.
//!
//! With [`Start::Warm`] the points are split into contiguous chunks (at most
//! [`MAX_CHUNKS`], of at least [`MIN_CHUNK_POINTS`] points: set by the number of points,
//! not of threads), each thread taking the next chunk not yet taken; each chunk starts from a
//! fresh state and warm-starts every point from the one before it. A point's result therefore
//! agrees with a cold evaluation to the solver's tolerance (where the point has one steady
//! state), not bit for bit, and depends on no shortcut: every point is solved in full; and the same
//! batch gives the same bits on any number of threads. With [`Start::Independent`] each point
//! goes to the next free thread with a fresh state: the results are the same whatever thread
//! takes them. The torques order their points so that each starts from a near neighbour: a warm
//! start from a distant point (say 500 N to 3000 N) fails and falls back to a cold solve by
//! continuation, hundreds of times slower.
//! Results come back in the caller's order either way. The first failing point in evaluation
//! order is reported, whatever the thread that met it.
//!
//! Every thread asks a [`Stop`] before each point whether to stop (the Python side stops on
//! Ctrl-C); the calling thread asks it too while it waits for the others.

extern crate alloc;

mod batch;
mod pool;
pub mod quantities;
pub mod sweep;
mod torques;
pub mod uncertainty;

pub use batch::{Batch, Start};
pub use pool::{BatchError, Errors, MAX_CHUNKS, MIN_CHUNK_POINTS, Never, Stop, WAIT, threads_for};
pub use quantities::{Quantity, Value};
pub use sweep::{
    MAX_SWEEP_POINTS, RangeText, RowError, SweepEnd, SweepError, SweepFlags, SweepPoint, SweepRange, SweepRow,
};
pub use torques::{BAND_RATIO, EVALUATOR_MIN_POINTS, MIN_BAND_RATIO, POINTS_PER_BAND};
