//! The threads of a batch: contiguous chunks of the points, one per thread, each thread with its
//! own solver state carried from point to point; the results in the caller's order, the first
//! failure in evaluation order, a [`Stop`] asked before and told after every point (see the
//! crate's documentation). Evaluations that carry nothing from one point to the next (cold
//! solves, fits) are shared out one by one instead, each to the next free thread
//! ([`map_shared`]).

use ballscrew_core::{Error, Model, OperatingPoint, SolverState};
use core::sync::atomic::{AtomicUsize, Ordering};
use core::time::Duration;
use std::collections::HashMap;
use std::collections::hash_map::Entry;
use std::sync::mpsc::{self, RecvTimeoutError};

/// Asked by every thread of a batch before each point whether to stop, and by the calling thread
/// at least every [`WAIT`] while it waits for the others; told by every thread after each point
/// that it is done (for a progress display).
pub trait Stop: Sync {
    /// Whether the batch should stop now.
    fn stop(&self) -> bool;

    /// One more point evaluated (whatever its result), by any thread. Nothing by default.
    fn done(&self) {}
}

/// Never stops (for batches nobody can interrupt, e.g. in tests).
#[derive(Debug, Clone, Copy)]
pub struct Never;

impl Stop for Never {
    fn stop(&self) -> bool {
        false
    }
}

/// Longest wait of the calling thread for the other threads between two questions to [`Stop`].
pub const WAIT: Duration = Duration::from_millis(20);

/// Why a batch stopped.
#[derive(Debug, Clone, PartialEq)]
pub enum BatchError {
    /// The point at flat index `index` failed with the core's `error`.
    Point {
        /// Flat (C-order) index of the point in the batch.
        index: usize,
        /// The core's error.
        error: Error,
    },
    /// A worker thread ended abnormally (a bug, not an input problem).
    Internal(String),
    /// The [`Stop`] said to stop.
    Stopped,
    /// Memory for the batch (its results, or its points' order) could not be reserved: `bytes`
    /// more were asked for. Reserved before the points it holds are evaluated, so a batch too
    /// large for the memory left ends with this error rather than an abort of the process.
    OutOfMemory {
        /// The size of the reservation that failed, bytes.
        bytes: usize,
    },
}

impl core::fmt::Display for BatchError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            BatchError::Point { index, error } => write!(f, "at point {index}: {error}"),
            BatchError::Internal(m) => f.write_str(m),
            BatchError::Stopped => f.write_str("the batch was stopped"),
            BatchError::OutOfMemory { bytes } => write!(
                f,
                "out of memory: {} more for the batch could not be reserved (fewer points at a time)",
                bytes_text(*bytes)
            ),
        }
    }
}

impl core::error::Error for BatchError {}

/// A size in bytes in short form: `240.0 MB`, `1.8e19 B` from a petabyte on.
fn bytes_text(bytes: usize) -> String {
    let b = bytes as f64;
    match [(1e9, "GB"), (1e6, "MB"), (1e3, "kB")].into_iter().find(|&(scale, _)| b >= scale) {
        _ if b >= 1e15 => format!("{b:.1e} B"),
        Some((scale, unit)) => format!("{:.1} {unit}", b / scale),
        None => format!("{bytes} B"),
    }
}

/// The error of a reservation of `len` values of `T` that failed.
pub(crate) fn out_of_memory<T>(len: usize) -> BatchError {
    BatchError::OutOfMemory { bytes: len.saturating_mul(core::mem::size_of::<T>()) }
}

/// An empty vector with room for `len` values of `T`, reserved at once: a failed reservation
/// is [`BatchError::OutOfMemory`] (`Vec::with_capacity` and `collect` abort the process).
pub(crate) fn room<T>(len: usize) -> Result<Vec<T>, BatchError> {
    let mut v = Vec::new();
    v.try_reserve_exact(len).map_err(|_| out_of_memory::<T>(len))?;
    Ok(v)
}

/// The `len` values of `values` in a vector reserved by [`room`] (more values than `len` are
/// taken too, each reserved as [`push`] does).
pub(crate) fn collect_in<T>(len: usize, values: impl IntoIterator<Item = T>) -> Result<Vec<T>, BatchError> {
    let mut v = room(len)?;
    for x in values {
        push(&mut v, x)?;
    }
    Ok(v)
}

/// `v.push(x)`, its growth reserved as [`room`] does.
pub(crate) fn push<T>(v: &mut Vec<T>, x: T) -> Result<(), BatchError> {
    if v.len() == v.capacity() {
        v.try_reserve(1).map_err(|_| out_of_memory::<T>(v.len().saturating_add(1)))?;
    }
    v.push(x);
    Ok(())
}

/// Worker threads for `points` points: the machine's cores, at most one per point, at least 1.
pub fn threads_for(points: usize) -> usize {
    let cores = std::thread::available_parallelism().map_or(1, |c| c.get());
    cores.min(points).max(1)
}

/// Contiguous chunk lengths of `n` points over `threads` threads, as equal as possible.
pub(crate) fn chunk_lengths(n: usize, threads: usize) -> Vec<usize> {
    let threads = threads.clamp(1, n.max(1));
    (0..threads).map(|t| n / threads + usize::from(t < n % threads)).collect()
}

/// `eval` at every point of `ops` (operating points, or rows that hold one), in order, over
/// `threads` threads, until `stop` says to stop (see the module docs).
pub(crate) fn map_points<P, T, F>(
    model: &Model,
    ops: &[P],
    threads: usize,
    stop: &dyn Stop,
    eval: F,
) -> Result<Vec<T>, BatchError>
where
    P: Sync,
    T: Send,
    F: Fn(&Model, &P, &mut SolverState) -> Result<T, Error> + Sync,
{
    map_with_state(ops, threads, stop, SolverState::new, |op, state| eval(model, op, state))
}

/// Fewest points of a chunk of a warm-started batch ([`crate::Start::Warm`]; but a batch of fewer).
pub const MIN_CHUNK_POINTS: usize = 100;

/// Most chunks of a warm-started batch ([`crate::Start::Warm`]): a larger batch has longer chunks. Each chunk starts from a
/// fresh state (the evaluator's band table solved again from its base table): with 64 chunks of
/// at least 50 points a batch of 5000 random DKFZD4012 points took 1.7 times as long as with one
/// chunk a thread, with 8 of at least 100 about as long (2 threads).
pub const MAX_CHUNKS: usize = 8;

/// Chunks of the points of a batch, each with its results, in the order of the chunks.
type ChunkResults<T> = Vec<(usize, Vec<T>)>;

/// The lengths of the chunks of a batch of `n` points: at least [`MIN_CHUNK_POINTS`] points
/// each and at most [`MAX_CHUNKS`] of them, as equal as possible; from `n` alone, so that the
/// chunks, and the state each point starts from, are the same on any number of threads.
pub(crate) fn state_chunks(n: usize) -> Vec<usize> {
    let chunks = n.div_ceil(MIN_CHUNK_POINTS).clamp(1, MAX_CHUNKS);
    chunk_lengths(n, chunks)
}

/// `eval` at every point of `ops`, in order, with a state from `new_state` carried from point to
/// point within each chunk of consecutive points ([`state_chunks`]: set by the number of points,
/// not of threads), the chunks shared out over `threads` threads, each to the next free thread;
/// until `stop` says to stop (see the module docs). The chunks, and so every result, are the
/// same on any number of threads.
pub(crate) fn map_with_state<P, S, T, N, F>(
    ops: &[P],
    threads: usize,
    stop: &dyn Stop,
    new_state: N,
    eval: F,
) -> Result<Vec<T>, BatchError>
where
    P: Sync,
    T: Send,
    N: Fn() -> S + Sync,
    F: Fn(&P, &mut S) -> Result<T, Error> + Sync,
{
    let first_failure = AtomicUsize::new(usize::MAX);
    let run_chunk = |start: usize, chunk: &[P]| -> Result<Vec<T>, BatchError> {
        let mut state = new_state();
        let mut out = room(chunk.len())?;
        for (i, op) in chunk.iter().enumerate() {
            let index = start + i;
            // A failure earlier in the caller's order makes the rest of this chunk moot.
            if first_failure.load(Ordering::Relaxed) < index {
                break;
            }
            if stop.stop() {
                return Err(BatchError::Stopped);
            }
            let result = eval(op, &mut state);
            stop.done();
            match result {
                Ok(v) => out.push(v),
                Err(error) => {
                    first_failure.fetch_min(index, Ordering::Relaxed);
                    return Err(BatchError::Point { index, error });
                }
            }
        }
        Ok(out)
    };
    let mut bounds = Vec::new();
    let mut start = 0;
    for len in state_chunks(ops.len()) {
        bounds.push((start, &ops[start..start + len]));
        start += len;
    }
    // Each thread takes the next chunk not yet taken; a thread's results are its chunks' (by
    // chunk number), or the failure that ended it.
    let next = AtomicUsize::new(0);
    let work = || -> Result<ChunkResults<T>, BatchError> {
        let mut out = Vec::new();
        loop {
            let k = next.fetch_add(1, Ordering::Relaxed);
            let Some(&(s, chunk)) = bounds.get(k) else { return Ok(out) };
            if first_failure.load(Ordering::Relaxed) < s {
                return Ok(out);
            }
            out.push((k, run_chunk(s, chunk)?));
        }
    };
    let results: Vec<Result<ChunkResults<T>, BatchError>> = std::thread::scope(|scope| {
        let (done, finished) = mpsc::channel::<()>();
        let spawned: Vec<_> = (1..threads.clamp(1, bounds.len().max(1)))
            .filter_map(|_| {
                let done = done.clone();
                std::thread::Builder::new()
                    .spawn_scoped(scope, move || {
                        let r = work();
                        // The receiver outlives every thread of the scope.
                        let _ = done.send(());
                        r
                    })
                    .ok()
            })
            .collect();
        drop(done);
        let mut results = vec![work()];
        // The calling thread keeps asking `stop` while the others run (a panicked thread never
        // says it is done: the wait ends when every thread has ended).
        wait_asking(stop, &finished, spawned.len());
        for handle in spawned {
            results
                .push(handle.join().unwrap_or_else(|_| Err(BatchError::Internal("a worker thread panicked".into()))));
        }
        results
    });
    let mut chunks = merge(results)?;
    chunks.sort_unstable_by_key(|(k, _)| *k);
    // Without a failure every chunk was evaluated in full; one missing would be a bug.
    if chunks.len() != bounds.len() || chunks.iter().zip(&bounds).any(|((_, v), (_, c))| v.len() != c.len()) {
        return Err(BatchError::Internal("a chunk of the batch was not evaluated".into()));
    }
    collect_in(ops.len(), chunks.into_iter().flat_map(|(_, v)| v))
}

/// Waits until `running` threads have said on `finished` that they are done (or every sender
/// is gone: a panicked thread never says it), asking `stop` at least every [`WAIT`] meanwhile.
fn wait_asking(stop: &dyn Stop, finished: &mpsc::Receiver<()>, mut running: usize) {
    while running > 0 {
        match finished.recv_timeout(WAIT) {
            Ok(()) => running -= 1,
            Err(RecvTimeoutError::Timeout) => {
                stop.stop();
            }
            Err(RecvTimeoutError::Disconnected) => break,
        }
    }
}

/// `eval` at every item of `items`, over `threads` threads that each take the next item not
/// yet taken, so that items of unequal cost share the threads evenly; the results in the items'
/// order. For evaluations that carry nothing from item to item (a cold solve, a fit): their
/// results then do not depend on the threads. `stop` is asked before and told after every item,
/// and by the calling thread at least every [`WAIT`] once it has no item left while the others
/// finish theirs; the failure reported is the one of the first failing item.
pub(crate) fn map_shared<P, T, F>(items: &[P], threads: usize, stop: &dyn Stop, eval: F) -> Result<Vec<T>, BatchError>
where
    P: Sync,
    T: Send,
    F: Fn(&P) -> Result<T, Error> + Sync,
{
    let next = AtomicUsize::new(0);
    let first_failure = AtomicUsize::new(usize::MAX);
    let work = || -> Result<Vec<(usize, T)>, BatchError> {
        let mut out = Vec::new();
        loop {
            let index = next.fetch_add(1, Ordering::Relaxed);
            // Past the end, or after a failure earlier in the items' order: nothing to do.
            if index >= items.len() || first_failure.load(Ordering::Relaxed) < index {
                return Ok(out);
            }
            if stop.stop() {
                return Err(BatchError::Stopped);
            }
            let result = eval(&items[index]);
            stop.done();
            match result {
                Ok(v) => push(&mut out, (index, v))?,
                Err(error) => {
                    first_failure.fetch_min(index, Ordering::Relaxed);
                    return Err(BatchError::Point { index, error });
                }
            }
        }
    };
    let results: Vec<Result<Vec<(usize, T)>, BatchError>> = std::thread::scope(|scope| {
        let (done, finished) = mpsc::channel::<()>();
        let spawned: Vec<_> = (1..threads.clamp(1, items.len().max(1)))
            .filter_map(|_| {
                let done = done.clone();
                std::thread::Builder::new()
                    .spawn_scoped(scope, move || {
                        let r = work();
                        // The receiver outlives every thread of the scope.
                        let _ = done.send(());
                        r
                    })
                    .ok()
            })
            .collect();
        drop(done);
        let mut results = vec![work()];
        // Then the calling thread keeps asking `stop` while the others finish their items.
        wait_asking(stop, &finished, spawned.len());
        for handle in spawned {
            results
                .push(handle.join().unwrap_or_else(|_| Err(BatchError::Internal("a worker thread panicked".into()))));
        }
        results
    });
    let mut slots: Vec<Option<T>> = collect_in(items.len(), core::iter::repeat_with(|| None).take(items.len()))?;
    for (index, v) in merge(results)? {
        slots[index] = Some(v);
    }
    // Without a failure every item was evaluated; one missing would be a bug, said as one
    // rather than a shorter result.
    let mut out = room(items.len())?;
    for v in slots {
        out.push(v.ok_or_else(|| BatchError::Internal("an item was not evaluated".into()))?);
    }
    Ok(out)
}

/// Largest step between consecutive points of a path ([`path_share`]), relative to the
/// larger of their preloads and axial loads (for preload and axial load) and to the speed's
/// magnitude: the evaluator's warm start gives way to its table where a ball's load moves by
/// more than 1 %.
pub const PATH_STEP: f64 = 0.01;

/// The direction class of screw speed `speed_rad_s` for warm starts: reverse, standstill
/// (within the standstill speed `standstill_rad_s`, where the creep forces are scaled) or
/// forward.
fn direction_class(speed_rad_s: f64, standstill_rad_s: f64) -> u8 {
    if speed_rad_s <= -standstill_rad_s {
        0
    } else if speed_rad_s < standstill_rad_s {
        1
    } else {
        2
    }
}

/// The share of the consecutive pairs of the points `ops`, in their own order, that are
/// neighbours on a path: in one direction class ([`warm_order`]) with preload and axial load
/// within [`PATH_STEP`] of the largest magnitude of the two points' preloads and axial loads
/// (a screw without preload carries its axial load alone) and speed magnitudes within it of
/// the speed (the standstill speed `standstill_rad_s` at least); 0 for fewer than two points. Near 1 for a
/// drive cycle sampled in time: in their own order each point starts warm from the one before,
/// where [`warm_order`] would interleave the cycle's passes through a region.
pub(crate) fn path_share(ops: &[OperatingPoint], standstill_rad_s: f64) -> f64 {
    if ops.len() < 2 {
        return 0.0;
    }
    let neighbours = ops
        .windows(2)
        .filter(|w| {
            let (a, b) = (&w[0], &w[1]);
            let scale = a.preload_n.abs().max(b.preload_n.abs()).max(a.axial_load_n.abs()).max(b.axial_load_n.abs());
            let speed = a.speed_rad_s.abs().max(b.speed_rad_s.abs()).max(standstill_rad_s);
            direction_class(a.speed_rad_s, standstill_rad_s) == direction_class(b.speed_rad_s, standstill_rad_s)
                && (a.preload_n - b.preload_n).abs() <= PATH_STEP * scale
                && (a.axial_load_n - b.axial_load_n).abs() <= PATH_STEP * scale
                && (a.speed_rad_s.abs() - b.speed_rad_s.abs()).abs() <= PATH_STEP * speed
        })
        .count();
    neighbours as f64 / (ops.len() - 1) as f64
}

/// An evaluation order in which consecutive points are close, for warm starts.
///
/// Points are grouped by direction of rotation (reverse, standstill, forward: within the
/// standstill speed `standstill_rad_s` the creep forces are scaled, above it they are not), then
/// into about sqrt(n) bands of axial load, and walked through each band by preload and speed,
/// up and down in turn (a snake), so that neither a band nor the step between bands jumps far.
pub(crate) fn warm_order(ops: &[OperatingPoint], standstill_rad_s: f64) -> Result<Vec<usize>, BatchError> {
    let class = |s: f64| direction_class(s, standstill_rad_s);
    let (lo, hi) =
        ops.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), o| (l.min(o.axial_load_n), h.max(o.axial_load_n)));
    let bands = if hi > lo { (ops.len() as f64).sqrt().ceil().max(1.0) } else { 1.0 };
    let band = |a: f64| if hi > lo { (((a - lo) / (hi - lo)) * bands).floor().min(bands - 1.0) as u64 } else { 0 };
    let mut keyed: Vec<(u8, u64, f64, f64, usize)> = collect_in(
        ops.len(),
        ops.iter().enumerate().map(|(i, o)| {
            let b = band(o.axial_load_n);
            let sign = if b % 2 == 0 { 1.0 } else { -1.0 };
            (class(o.speed_rad_s), b, sign * o.preload_n, sign * o.speed_rad_s.abs(), i)
        }),
    )?;
    keyed.sort_unstable_by(|x, y| {
        x.0.cmp(&y.0).then(x.1.cmp(&y.1)).then(x.2.total_cmp(&y.2)).then(x.3.total_cmp(&y.3)).then(x.4.cmp(&y.4))
    });
    collect_in(keyed.len(), keyed.into_iter().map(|k| k.4))
}

/// [`map_points`] in [`warm_order`], results and errors in the caller's order and indices.
pub(crate) fn map_points_warm<T, F>(
    model: &Model,
    ops: &[OperatingPoint],
    threads: usize,
    stop: &dyn Stop,
    eval: F,
) -> Result<Vec<T>, BatchError>
where
    T: Send,
    F: Fn(&Model, &OperatingPoint, &mut SolverState) -> Result<T, Error> + Sync,
{
    let order = warm_order(ops, model.spec().friction.standstill_speed_rad_s)?;
    let sorted: Vec<OperatingPoint> = collect_in(order.len(), order.iter().map(|&i| ops[i]))?;
    let values = map_points(model, &sorted, threads, stop, eval).map_err(|e| callers_index(&order, e))?;
    permuted(&order, values)
}

/// The values `values`, computed in the order `order` (a permutation of the points: the
/// caller's index of each value), back in the caller's order.
pub(crate) fn permuted<T>(order: &[usize], values: Vec<T>) -> Result<Vec<T>, BatchError> {
    let mut out: Vec<Option<T>> = collect_in(order.len(), core::iter::repeat_with(|| None).take(order.len()))?;
    for (&i, v) in order.iter().zip(values) {
        out[i] = Some(v);
    }
    // `order` is a permutation: every slot is filled.
    collect_in(order.len(), out.into_iter().flatten())
}

/// `e` of a batch evaluated in the order `order`, with the failing point's index in the
/// caller's order.
pub(crate) fn callers_index(order: &[usize], e: BatchError) -> BatchError {
    match e {
        BatchError::Point { index, error } => BatchError::Point { index: order[index], error },
        other => other,
    }
}

/// What a batch does with a point the model cannot evaluate (Python's `errors=`): raise the
/// error of the first such point, or give NaN for each and compute the others.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Errors {
    /// The first failing point stops the batch (`errors="raise"`, the default).
    Raise,
    /// Each failing point gives NaN, with its error kept for the report (`errors="nan"`).
    Nan,
}

/// [`map_points`] under `errors`: every point's result or error, in order. With
/// [`Errors::Raise`] the first failing point stops the batch as in [`map_points`]; with
/// [`Errors::Nan`] no point does (the one after a failure warm-starts from what the failure left,
/// and falls back to a cold solve as any point does).
pub(crate) fn map_points_or_nan<P, T, F>(
    model: &Model,
    ops: &[P],
    threads: usize,
    stop: &dyn Stop,
    errors: Errors,
    eval: F,
) -> Result<Vec<Result<T, Error>>, BatchError>
where
    P: Sync,
    T: Send,
    F: Fn(&Model, &P, &mut SolverState) -> Result<T, Error> + Sync,
{
    match errors {
        Errors::Raise => {
            let values = map_points(model, ops, threads, stop, eval)?;
            collect_in(values.len(), values.into_iter().map(Ok))
        }
        Errors::Nan => map_points(model, ops, threads, stop, |m, p, s| Ok(eval(m, p, s))),
    }
}

/// Torques at `ops`, N m, in the caller's order, as [`map_points_warm`] gives them, with one
/// shortcut that changes no result: when the model's torque does not depend on the speed's
/// magnitude above the standstill speed ([`Model::torque_depends_on_speed_magnitude`];
/// docs/model-notes.md item 12), the points with the same preload, axial load and direction at or above
/// that speed are solved once, the first of them in the caller's order standing for all. A
/// study over a grid of speeds then costs what its preloads and axial loads cost. An error is
/// reported at the index of the point that was solved.
pub(crate) fn torque_points(
    model: &Model,
    ops: &[OperatingPoint],
    threads: usize,
    stop: &dyn Stop,
) -> Result<Vec<f64>, BatchError> {
    torque_points_with(model, ops, threads, stop, |m, o, s| m.torque(o, s))
}

/// [`torque_points`] under `errors` ([`map_points_or_nan`]): each point's torque or error (a
/// point that stands for others gives them its error too).
pub(crate) fn torque_points_or_nan(
    model: &Model,
    ops: &[OperatingPoint],
    threads: usize,
    stop: &dyn Stop,
    errors: Errors,
) -> Result<Vec<Result<f64, Error>>, BatchError> {
    match errors {
        Errors::Raise => {
            let values = torque_points(model, ops, threads, stop)?;
            collect_in(values.len(), values.into_iter().map(Ok))
        }
        Errors::Nan => torque_points_with(model, ops, threads, stop, |m, o, s| Ok(m.torque(o, s))),
    }
}

/// [`torque_points`] with the evaluation `eval` of a point.
fn torque_points_with<T, F>(
    model: &Model,
    ops: &[OperatingPoint],
    threads: usize,
    stop: &dyn Stop,
    eval: F,
) -> Result<Vec<T>, BatchError>
where
    T: Send + Clone,
    F: Fn(&Model, &OperatingPoint, &mut SolverState) -> Result<T, Error> + Sync,
{
    over_distinct_points(model, ops, |points| map_points_warm(model, points, threads, stop, eval))
}

/// `eval` of the batch `ops`, with the shortcut of [`torque_points`] where it changes no
/// result: when the model's torque does not depend on the speed's magnitude above the
/// standstill speed, `eval` runs on the distinct points only ([`distinct_points`]) and each
/// value stands for the points it stands for; an error keeps the caller's index.
pub(crate) fn over_distinct_points<T, F>(model: &Model, ops: &[OperatingPoint], eval: F) -> Result<Vec<T>, BatchError>
where
    T: Clone,
    F: FnOnce(&[OperatingPoint]) -> Result<Vec<T>, BatchError>,
{
    if model.torque_depends_on_speed_magnitude() {
        return eval(ops);
    }
    let (solved, stands_for) = distinct_points(ops, model.spec().friction.standstill_speed_rad_s)?;
    let unique: Vec<OperatingPoint> = collect_in(solved.len(), solved.iter().map(|&i| ops[i]))?;
    let values = eval(&unique).map_err(|e| callers_index(&solved, e))?;
    collect_in(stands_for.len(), stands_for.iter().map(|&k| values[k].clone()))
}

/// The points to solve when only the direction of a speed at or above `standstill_rad_s`
/// counts: their indices in `ops` (first occurrences, in order), and for every point the
/// position of the one that stands for it in that list. Points below the standstill speed, and
/// points the model refuses (a speed beyond the valid range or not finite: its own error, not
/// another point's torque), stand for themselves and their exact duplicates only.
pub(crate) fn distinct_points(
    ops: &[OperatingPoint],
    standstill_rad_s: f64,
) -> Result<(Vec<usize>, Vec<usize>), BatchError> {
    /// Direction class: running in reverse, running forward, or exactly this speed (its bits:
    /// within the standstill band, or an operating point that does not validate).
    #[derive(PartialEq, Eq, Hash)]
    enum Speed {
        Reverse,
        Forward,
        Exact(u64),
    }
    let mut first: HashMap<(u64, u64, Speed), usize> = HashMap::new();
    let mut solved = Vec::new();
    let mut stands_for = room(ops.len())?;
    for (i, o) in ops.iter().enumerate() {
        let speed = if o.validate().is_err() {
            Speed::Exact(o.speed_rad_s.to_bits())
        } else if o.speed_rad_s >= standstill_rad_s {
            Speed::Forward
        } else if o.speed_rad_s <= -standstill_rad_s {
            Speed::Reverse
        } else {
            Speed::Exact(o.speed_rad_s.to_bits())
        };
        first.try_reserve(1).map_err(|_| out_of_memory::<((u64, u64, Speed), usize)>(first.len().saturating_add(1)))?;
        let k = match first.entry((o.preload_n.to_bits(), o.axial_load_n.to_bits(), speed)) {
            Entry::Occupied(e) => *e.get(),
            Entry::Vacant(e) => {
                push(&mut solved, i)?;
                *e.insert(solved.len() - 1)
            }
        };
        stands_for.push(k);
    }
    Ok((solved, stands_for))
}

/// The chunks' results in order, or the error of the earliest failing point (a stop, then an
/// abnormal end of a thread, before any point).
fn merge<T>(results: Vec<Result<Vec<T>, BatchError>>) -> Result<Vec<T>, BatchError> {
    // A stop first, then memory that ran out, then an abnormal end of a thread, then the
    // earliest failing point.
    let rank = |e: &BatchError| match e {
        BatchError::Stopped => 0,
        BatchError::OutOfMemory { .. } => 1,
        BatchError::Internal(_) => 2,
        BatchError::Point { .. } => 3,
    };
    let mut first: Option<BatchError> = None;
    for e in results.iter().filter_map(|r| r.as_ref().err()) {
        let earlier = match (&first, e) {
            (None, _) => true,
            (Some(BatchError::Point { index: a, .. }), BatchError::Point { index: b, .. }) => b < a,
            (Some(f), e) => rank(e) < rank(f),
        };
        if earlier {
            first = Some(e.clone());
        }
    }
    if let Some(e) = first {
        return Err(e);
    }
    let total = results.iter().map(|r| r.as_ref().map_or(0, Vec::len)).sum();
    let mut out = room(total)?;
    for chunk in results.into_iter().flatten() {
        out.extend(chunk);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use ballscrew_core::ScrewSpec;
    use ballscrew_core::input::rpm_to_rad_s;

    fn op(preload_n: f64) -> OperatingPoint {
        OperatingPoint { speed_rad_s: rpm_to_rad_s(100.0), preload_n, axial_load_n: 0.0 }
    }

    /// A drive cycle sampled in time is a path (a jump in it breaks two pairs); the same points
    /// shuffled, a study grid in its broadcast order and a cycle through standstill sampled too
    /// coarsely are not; a single point has no pair.
    /// A reservation larger than the memory left (here larger than any: usize::MAX / 16 values
    /// of 8 bytes, and of 32, whose size overflows) is an error naming its size, not an abort of
    /// the process, as `Vec::with_capacity` and `collect` would be; smaller ones are made.
    #[test]
    fn a_reservation_that_cannot_be_made_is_an_error_not_an_abort() {
        let n = usize::MAX / 16;
        assert_eq!(room::<f64>(n).unwrap_err(), BatchError::OutOfMemory { bytes: n * 8 });
        assert_eq!(room::<[f64; 4]>(n).unwrap_err(), BatchError::OutOfMemory { bytes: usize::MAX });
        assert_eq!(collect_in::<u64>(n, core::iter::empty()).unwrap_err(), BatchError::OutOfMemory { bytes: n * 8 });
        let text = room::<f64>(n).unwrap_err().to_string();
        assert_eq!(text, "out of memory: 9.2e18 B more for the batch could not be reserved (fewer points at a time)");
        assert_eq!(
            BatchError::OutOfMemory { bytes: 720_000_000 }.to_string().split(':').nth(1),
            Some(" 720.0 MB more for the batch could not be reserved (fewer points at a time)")
        );
        let v = room::<f64>(1000).unwrap();
        assert!(v.is_empty() && v.capacity() >= 1000);
        assert_eq!(collect_in(3, [1, 2, 3]).unwrap(), [1, 2, 3]);
        let mut grown = Vec::new();
        for k in 0..100 {
            push(&mut grown, k).unwrap();
        }
        assert_eq!(grown, (0..100).collect::<Vec<_>>());
    }

    /// Memory that ran out in a chunk ends the batch with its error ahead of a failing point's,
    /// and behind a stop.
    #[test]
    fn memory_that_ran_out_is_reported_ahead_of_a_point_and_behind_a_stop() {
        let point = || BatchError::Point {
            index: 0,
            error: Error::Input(ballscrew_core::InputError { field: "preload_n", value: -1.0, valid: "[0, 1e7] N" }),
        };
        let oom = BatchError::OutOfMemory { bytes: 8 };
        let results: Vec<Result<Vec<f64>, BatchError>> = vec![Err(point()), Err(oom.clone())];
        assert_eq!(merge(results).unwrap_err(), oom);
        let results: Vec<Result<Vec<f64>, BatchError>> = vec![Err(oom.clone()), Err(point())];
        assert_eq!(merge(results).unwrap_err(), oom);
        let results: Vec<Result<Vec<f64>, BatchError>> = vec![Err(oom), Err(BatchError::Stopped)];
        assert_eq!(merge(results).unwrap_err(), BatchError::Stopped);
    }

    #[test]
    fn drive_cycles_follow_a_path_and_grids_and_shuffles_do_not() {
        let standstill = rpm_to_rad_s(0.1);
        let cycle = |n: usize, rpm: f64| -> Vec<OperatingPoint> {
            (0..n)
                .map(|k| {
                    let t = k as f64 / n as f64;
                    OperatingPoint {
                        speed_rad_s: rpm_to_rad_s(rpm + 250.0 * (2.0 * core::f64::consts::PI * 5.0 * t).sin()),
                        preload_n: 2000.0 - 300.0 * t,
                        axial_load_n: 200.0 * (2.0 * core::f64::consts::PI * 3.0 * t).sin(),
                    }
                })
                .collect()
        };
        let drive = cycle(10_000, 300.0);
        assert_eq!(path_share(&drive, standstill), 1.0);
        // Without preload (a single nut), the axial load carries the balls.
        let unpreloaded: Vec<OperatingPoint> = drive
            .iter()
            .map(|o| OperatingPoint { preload_n: 0.0, axial_load_n: 1000.0 + o.axial_load_n, ..*o })
            .collect();
        assert_eq!(path_share(&unpreloaded, standstill), 1.0);
        // One jump back to the start in the middle.
        let mut jumped = drive.clone();
        jumped[5000] = drive[0];
        assert!((path_share(&jumped, standstill) - (1.0 - 2.0 / 9999.0)).abs() < 1e-12);
        // Shuffled by a fixed stride coprime with the length.
        let shuffled: Vec<OperatingPoint> = (0..drive.len()).map(|k| drive[(k * 7919) % drive.len()]).collect();
        assert!(path_share(&shuffled, standstill) < 0.1);
        let grid: Vec<OperatingPoint> = (0..1000)
            .map(|k| OperatingPoint {
                speed_rad_s: rpm_to_rad_s(10.0 + 300.0 * (k % 10) as f64),
                preload_n: 500.0 + 250.0 * (k / 100) as f64,
                axial_load_n: -500.0 + 100.0 * ((k / 10) % 10) as f64,
            })
            .collect();
        assert!(path_share(&grid, standstill) < 0.1);
        assert_eq!(path_share(&drive[..1], standstill), 0.0);
        // 100 samples of a cycle through standstill (speed +-250 rpm about 0): steps of about
        // 80 rpm.
        assert!(path_share(&cycle(100, 0.0), standstill) < 0.1);
    }

    #[test]
    fn distinct_points_merge_running_speeds_of_one_direction_only() {
        let standstill = rpm_to_rad_s(0.1);
        let at =
            |p: f64, rpm: f64, a: f64| OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: p, axial_load_n: a };
        let ops = [
            at(1000.0, 100.0, 0.0),  // 0: solved
            at(1000.0, 3000.0, 0.0), // same as 0
            at(1000.0, -100.0, 0.0), // 1: other direction
            at(1000.0, 100.0, 5.0),  // 2: other axial load
            at(1000.0, 0.05, 0.0),   // 3: standstill band
            at(1000.0, 0.05, 0.0),   // same as 3
            at(1000.0, 0.06, 0.0),   // 4: another standstill speed
            at(1000.0, 0.1, 0.0),    // at the standstill speed: running, same as 0
            at(1500.0, 100.0, 0.0),  // 5: other preload
        ];
        let (solved, stands_for) = distinct_points(&ops, standstill).unwrap();
        assert_eq!(solved, [0, 2, 3, 4, 6, 8]);
        assert_eq!(stands_for, [0, 0, 1, 2, 3, 3, 4, 0, 5]);
    }

    #[test]
    fn a_speed_the_model_refuses_stands_for_itself_only() {
        let at = |rpm: f64| OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: 1000.0, axial_load_n: 0.0 };
        let ops = [
            at(100.0),         // 0: solved
            at(40_000.0),      // 1: beyond 30000 rpm
            at(f64::INFINITY), // 2: not finite
            at(3000.0),        // same as 0
            at(40_000.0),      // same as 1
            at(-50_000.0),     // 3: beyond -30000 rpm
            at(-100.0),        // 4: reverse
        ];
        let (solved, stands_for) = distinct_points(&ops, rpm_to_rad_s(0.1)).unwrap();
        assert_eq!(solved, [0, 1, 2, 5, 6]);
        assert_eq!(stands_for, [0, 1, 2, 0, 1, 3, 4]);
    }

    #[test]
    fn torque_points_equal_a_solve_of_every_point() {
        let grid = |model: &Model| {
            let standstill = model.spec().friction.standstill_speed_rad_s;
            let mut ops = Vec::new();
            for p in [700.0, 1800.0, 2600.0] {
                for a in [0.0, 300.0] {
                    for rpm in [-2500.0, -40.0, 0.0, 0.03, 1.0, 250.0, 2500.0] {
                        ops.push(OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: p, axial_load_n: a });
                    }
                    ops.push(OperatingPoint { speed_rad_s: standstill, preload_n: p, axial_load_n: a });
                }
            }
            ops
        };
        let mut viscous = ScrewSpec::dkfzd4012();
        viscous.extensions.viscous_drag = Some(ballscrew_core::input::extensions::ViscousDrag {
            torque_nm: 0.02,
            exponent: 0.8,
            reference_speed_rad_s: rpm_to_rad_s(1000.0),
        });
        for spec in [ScrewSpec::dkfzd4012(), viscous] {
            let model = Model::new(&spec).unwrap();
            let ops = grid(&model);
            let each: Vec<f64> = ops.iter().map(|o| model.torque(o, &mut SolverState::new()).unwrap()).collect();
            let batch = torque_points(&model, &ops, 2, &Never).unwrap();
            for (i, (b, e)) in batch.iter().zip(&each).enumerate() {
                assert!((b - e).abs() <= 1e-12 * e.abs().max(1e-9), "point {i} {:?}: {b} vs {e}", ops[i]);
            }
        }
    }

    #[test]
    fn a_stop_ends_every_thread_of_the_batch() {
        /// Says stop from its `after`-th question on.
        struct After(AtomicUsize, usize);
        impl Stop for After {
            fn stop(&self) -> bool {
                self.0.fetch_add(1, Ordering::Relaxed) >= self.1
            }
        }
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let ops: Vec<_> = (0..1000).map(|i| op(f64::from(i))).collect();
        for threads in 1..=3 {
            let evaluated = AtomicUsize::new(0);
            let stop = After(AtomicUsize::new(0), 10);
            let e = map_points(&model, &ops, threads, &stop, |_, o, _| {
                evaluated.fetch_add(1, Ordering::Relaxed);
                Ok(o.preload_n)
            })
            .unwrap_err();
            assert_eq!(e, BatchError::Stopped, "threads {threads}");
            assert!(evaluated.load(Ordering::Relaxed) <= 10, "threads {threads}");
        }
        // A stop outranks a failing point.
        let results: Vec<Result<Vec<f64>, BatchError>> = vec![
            Err(BatchError::Point {
                index: 0,
                error: Error::Input(ballscrew_core::InputError { field: "preload_n", value: -1.0, valid: "" }),
            }),
            Err(BatchError::Stopped),
        ];
        assert_eq!(merge(results).unwrap_err(), BatchError::Stopped);
    }

    /// `map_shared`: items of very unequal cost (one a thousand times another) share the
    /// threads by who is free, and the results come back in the items' order; the failure
    /// reported is the first failing item's, whatever the threads; a stop ends every thread.
    #[test]
    fn shared_items_keep_their_order_and_the_first_failure() {
        let items: Vec<u64> = (0..40).collect();
        let cost = |&i: &u64| {
            // Item 3 is long: the other threads take the rest meanwhile (hundreds of times
            // the time they need).
            if i == 3 {
                std::thread::sleep(Duration::from_millis(300));
            }
            Ok((i * i, std::thread::current().id()))
        };
        for threads in 1..=3 {
            let out = map_shared(&items, threads, &Never, cost).unwrap();
            assert_eq!(out.iter().map(|o| o.0).collect::<Vec<_>>(), items.iter().map(|i| i * i).collect::<Vec<_>>());
            if threads > 1 {
                let long = out[3].1;
                let others = out.iter().filter(|o| o.1 != long).count();
                assert!(others >= 30, "threads {threads}: {others} items on the other threads");
            }
        }
        let refuse = |&i: &u64| {
            if i % 7 == 5 {
                Err(Error::Input(ballscrew_core::InputError { field: "preload_n", value: i as f64, valid: "" }))
            } else {
                Ok(i)
            }
        };
        for threads in 1..=4 {
            match map_shared(&items, threads, &Never, refuse).unwrap_err() {
                BatchError::Point { index, .. } => assert_eq!(index, 5, "threads {threads}"),
                other => panic!("unexpected {other:?}"),
            }
        }
        /// Says stop from its `after`-th question on.
        struct After(AtomicUsize, usize);
        impl Stop for After {
            fn stop(&self) -> bool {
                self.0.fetch_add(1, Ordering::Relaxed) >= self.1
            }
        }
        for threads in 1..=3 {
            let evaluated = AtomicUsize::new(0);
            let count = |&i: &u64| {
                evaluated.fetch_add(1, Ordering::Relaxed);
                Ok(i)
            };
            let e = map_shared(&items, threads, &After(AtomicUsize::new(0), 10), count).unwrap_err();
            assert_eq!(e, BatchError::Stopped, "threads {threads}");
            assert!(evaluated.load(Ordering::Relaxed) <= 10, "threads {threads}");
        }
        assert_eq!(map_shared(&[] as &[u64], 2, &Never, |&i| Ok(i)).unwrap(), Vec::<u64>::new());
    }

    #[test]
    fn chunks_cover_every_point_once() {
        assert_eq!(chunk_lengths(10, 3), [4, 3, 3]);
        assert_eq!(chunk_lengths(2, 8), [1, 1]);
        assert_eq!(chunk_lengths(0, 2), [0]);
        assert_eq!(chunk_lengths(7, 0), [7]);
    }

    #[test]
    fn results_keep_the_callers_order_over_threads() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let ops: Vec<_> = (0..7).map(|i| op(f64::from(i))).collect();
        let out = map_points(&model, &ops, 3, &Never, |_, o, _| Ok(o.preload_n)).unwrap();
        assert_eq!(out, [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    }

    /// The chunks a state is carried through are set by the number of points alone.
    #[test]
    fn state_chunks_are_set_by_the_points_not_the_threads() {
        assert_eq!(state_chunks(0), [0]);
        assert_eq!(state_chunks(10), [10]);
        assert_eq!(state_chunks(100), [100]);
        assert_eq!(state_chunks(201), [67, 67, 67]);
        let big = state_chunks(100_000);
        assert_eq!((big.len(), big.iter().sum::<usize>()), (MAX_CHUNKS, 100_000));
    }

    /// Each chunk starts from a fresh state and carries it from point to point; which thread
    /// runs it changes nothing.
    #[test]
    fn each_chunk_carries_one_state_whatever_the_threads() {
        let items: Vec<usize> = (0..240).collect();
        let count = |threads: usize| {
            map_with_state(
                &items,
                threads,
                &Never,
                || 0usize,
                |_, n| {
                    *n += 1;
                    Ok(*n)
                },
            )
            .unwrap()
        };
        let one = count(1);
        // 240 points: three chunks of 80.
        let want: Vec<usize> = (0..240).map(|i| i % 80 + 1).collect();
        assert_eq!(one, want);
        for threads in [2, 3, 5, 64] {
            assert_eq!(count(threads), one, "{threads} threads");
        }
    }

    #[test]
    fn the_earliest_failure_is_reported_whichever_thread_meets_it() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let ops: Vec<_> = [1000.0, 2000.0, -1.0, 1500.0, -5.0, 600.0].into_iter().map(op).collect();
        for threads in 1..=4 {
            let e = map_points(&model, &ops, threads, &Never, |m, o, s| m.torque(o, s)).unwrap_err();
            match e {
                BatchError::Point { index, error: Error::Input(i) } => {
                    assert_eq!((index, i.field, i.value), (2, "preload_n", -1.0), "threads {threads}");
                }
                other => panic!("unexpected {other:?}"),
            }
        }
    }

    #[test]
    fn warm_order_is_a_permutation_grouped_by_direction_and_near_in_preload() {
        let standstill = rpm_to_rad_s(0.1);
        let mut ops = Vec::new();
        for (i, p) in [3000.0, 500.0, 2000.0, 1000.0, 2500.0, 1500.0].into_iter().enumerate() {
            let speed = if i % 2 == 0 { 100.0 } else { -100.0 };
            ops.push(OperatingPoint { speed_rad_s: rpm_to_rad_s(speed), preload_n: p, axial_load_n: 0.0 });
        }
        let order = warm_order(&ops, standstill).unwrap();
        let mut seen = order.clone();
        seen.sort_unstable();
        assert_eq!(seen, [0, 1, 2, 3, 4, 5]);
        // Reverse rotation first, then forward; each by preload.
        assert_eq!(order, [1, 3, 5, 2, 4, 0]);
    }

    #[test]
    fn warm_order_snakes_through_bands_of_axial_load() {
        let ops: Vec<_> = (0..16)
            .map(|i| OperatingPoint {
                speed_rad_s: 10.0,
                preload_n: f64::from(i % 4) * 100.0,
                axial_load_n: f64::from(i / 4) * 10.0,
            })
            .collect();
        let order = warm_order(&ops, rpm_to_rad_s(0.1)).unwrap();
        let walk: Vec<(f64, f64)> = order.iter().map(|&i| (ops[i].axial_load_n, ops[i].preload_n)).collect();
        for pair in walk.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            assert!((a.0 - b.0).abs() <= 10.0 && (a.1 - b.1).abs() <= 100.0, "{walk:?}");
        }
    }

    #[test]
    fn warm_batch_returns_the_callers_order_and_indices() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let ops: Vec<_> = [3000.0, 500.0, 2000.0].into_iter().map(op).collect();
        assert_eq!(
            map_points_warm(&model, &ops, 2, &Never, |_, o, _| Ok(o.preload_n)).unwrap(),
            [3000.0, 500.0, 2000.0]
        );
        let ops: Vec<_> = [3000.0, 500.0, -2.0, 2000.0].into_iter().map(op).collect();
        let e = map_points_warm(&model, &ops, 2, &Never, |m, o, s| m.torque(o, s)).unwrap_err();
        assert!(matches!(e, BatchError::Point { index: 2, .. }), "{e:?}");
    }

    #[test]
    fn warm_started_chunks_agree_with_cold_points() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let ops: Vec<_> = [500.0, 1000.0, 2000.0, 3000.0].into_iter().map(op).collect();
        let batch = map_points(&model, &ops, 2, &Never, |m, o, s| m.torque(o, s)).unwrap();
        for (o, t) in ops.iter().zip(&batch) {
            let cold = model.torque(o, &mut SolverState::new()).unwrap();
            assert!((t - cold).abs() <= 1e-10 * cold.abs(), "{t} vs {cold}");
        }
    }
}
