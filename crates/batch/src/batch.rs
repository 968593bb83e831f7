//! The one way into a batch: [`Batch`], its options (threads, stop, what a failing point does,
//! how the points share the threads) and its two evaluations, any evaluation point by point
//! ([`Batch::map`]) and the drive torques ([`Batch::torques`]: each point's canonical state,
//! or the control-loop evaluator's warm starts).

use crate::pool::{BatchError, Errors, Never, Stop, map_shared, map_with_state, threads_for};
use ballscrew_core::input::extensions::Conditions;
use ballscrew_core::{Error, Evaluator, Model, OperatingPoint};

/// How the points of a batch share the threads, and what each carries to the next. For
/// [`Batch::torques`]: `Independent` is each point's canonical state (the model's cold solve,
/// what a stateless request answers, to the bit), `Warm` the control-loop evaluator's warm
/// starts band by band of speed (faster; within its tolerance of the canonical state except
/// where a ball has several steady states, docs/model-notes.md item 24).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Start {
    /// Contiguous chunks of the points in the caller's order (set by their number, not by the
    /// threads), each chunk's state carried from point to point: each point warm-starts from
    /// the one before it, and the results are the same to the bit on any number of threads.
    Warm,
    /// Each point to the next free thread, with a fresh state: nothing is carried, so the
    /// results do not depend on the threads, and points of unequal cost (cold solves, fits)
    /// share the threads evenly.
    Independent,
}

/// A batch: many evaluations over the machine's threads (see the crate's documentation).
///
/// ```
/// use ballscrew_batch::{Batch, Errors};
/// use ballscrew_core::{Model, OperatingPoint, ScrewSpec};
///
/// let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
/// let ops: Vec<OperatingPoint> =
///     [500.0, 1000.0, 2000.0].iter().map(|&p| OperatingPoint { preload_n: p, ..model.spec().operating }).collect();
/// let torques = Batch::new(ops.len()).errors(Errors::Nan).torques(&model, None, &ops, None).unwrap();
/// assert!(torques.iter().all(|t| t.as_ref().is_ok_and(|t| *t > 0.0)));
/// ```
#[derive(Clone, Copy)]
pub struct Batch<'a> {
    /// Worker threads, at least 1 ([`threads_for`]: the machine's cores for a batch).
    pub threads: usize,
    /// Asked by every thread before each point whether to stop, and told after it.
    pub stop: &'a dyn Stop,
    /// What a point that fails does: stop the batch with its error, or give its error in its
    /// place and go on.
    pub errors: Errors,
    /// How the points share the threads and where each starts ([`Batch::torques`] with
    /// [`Start::Warm`] walks its points its own way: band by band of speed, see `torques.rs`).
    pub start: Start,
}

impl core::fmt::Debug for Batch<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Batch")
            .field("threads", &self.threads)
            .field("errors", &self.errors)
            .field("start", &self.start)
            .finish_non_exhaustive()
    }
}

impl Batch<'static> {
    /// A batch of `points` points over the machine's cores ([`threads_for`]), that nobody
    /// stops, whose first failing point stops it, each point started on its own
    /// ([`Start::Independent`]: for the torques, each point's canonical state).
    pub fn new(points: usize) -> Self {
        Batch { threads: threads_for(points), stop: &Never, errors: Errors::Raise, start: Start::Independent }
    }
}

impl<'a> Batch<'a> {
    /// The same batch over `threads` threads (at least 1).
    pub fn threads(self, threads: usize) -> Self {
        Batch { threads: threads.max(1), ..self }
    }

    /// The same batch, stopped by `stop`.
    pub fn stop<'b>(self, stop: &'b dyn Stop) -> Batch<'b> {
        Batch { threads: self.threads, stop, errors: self.errors, start: self.start }
    }

    /// The same batch under `errors`.
    pub fn errors(self, errors: Errors) -> Self {
        Batch { errors, ..self }
    }

    /// The same batch with its points started as `start` says.
    pub fn start(self, start: Start) -> Self {
        Batch { start, ..self }
    }

    /// `eval` at every item of `items`, with a state from `new_state` (per thread and carried
    /// from item to item, or fresh for each item: [`Start`]); each item's result or error in
    /// the items' order. With [`Errors::Raise`] the first failing item in the items' order
    /// stops the batch ([`BatchError::Point`]) and every result given is `Ok`; with
    /// [`Errors::Nan`] no item does (the one after a failure warm-starts from what the failure
    /// left, and falls back to a cold solve as any point does).
    pub fn map<P, S, T, N, F>(&self, items: &[P], new_state: N, eval: F) -> Result<Vec<Result<T, Error>>, BatchError>
    where
        P: Sync,
        T: Send,
        N: Fn() -> S + Sync,
        F: Fn(&P, &mut S) -> Result<T, Error> + Sync,
    {
        let (threads, stop) = (self.threads, self.stop);
        match (self.start, self.errors) {
            (Start::Warm, Errors::Raise) => map_with_state(items, threads, stop, new_state, |p, s| eval(p, s).map(Ok)),
            (Start::Warm, Errors::Nan) => map_with_state(items, threads, stop, new_state, |p, s| Ok(eval(p, s))),
            (Start::Independent, Errors::Raise) => {
                map_shared(items, threads, stop, |p| eval(p, &mut new_state()).map(Ok))
            }
            (Start::Independent, Errors::Nan) => map_shared(items, threads, stop, |p| Ok(eval(p, &mut new_state()))),
        }
    }

    /// The drive torque (N m) at every point of `ops`, under the conditions `conditions` (one
    /// per point; `None`: the default conditions), in the caller's order. With
    /// [`Start::Independent`], each point's canonical state: the model's cold solve, the same
    /// bits as [`Model::torque_at`] from a fresh state (`evaluator` unused). With
    /// [`Start::Warm`], by the control-loop evaluator band by band of speed (`evaluator` when
    /// given, built from `model`; else one built here when the batch has at least
    /// [`crate::EVALUATOR_MIN_POINTS`] points and the evaluator applies to the model), else by
    /// the model warm-started (see `torques.rs`).
    ///
    /// With [`Errors::Nan`] a point the model refuses gives its error in its place, and the
    /// others their torque:
    ///
    /// ```
    /// use ballscrew_batch::{Batch, Errors, Start};
    /// use ballscrew_core::{Error, Model, OperatingPoint, ScrewSpec, SolverState};
    ///
    /// let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
    /// let at = |preload_n: f64| OperatingPoint { preload_n, ..model.spec().operating };
    /// let ops = [at(1000.0), at(-5.0), at(3000.0)];
    /// let canonical = Batch::new(ops.len()).errors(Errors::Nan).start(Start::Independent);
    /// let torques = canonical.torques(&model, None, &ops, None).unwrap();
    /// assert!(matches!(torques[1], Err(Error::Input(e)) if e.field == "preload_n" && e.value == -5.0));
    /// let warm = Batch::new(ops.len()).errors(Errors::Nan).start(Start::Warm).torques(&model, None, &ops, None).unwrap();
    /// for k in [0, 2] {
    ///     let want = model.torque(&ops[k], &mut SolverState::new()).unwrap();
    ///     assert_eq!(*torques[k].as_ref().unwrap(), want);
    ///     let got = *warm[k].as_ref().unwrap();
    ///     assert!((got - want).abs() <= 1e-8 * want, "{got} against {want}");
    /// }
    /// ```
    ///
    /// # Errors
    /// [`BatchError::Point`] for the first failing point with [`Errors::Raise`];
    /// [`BatchError::Stopped`] when the stop says so; [`BatchError::Internal`] when
    /// `conditions` is given with a length other than `ops`'s.
    pub fn torques(
        &self,
        model: &Model,
        evaluator: Option<&Evaluator<f64>>,
        ops: &[OperatingPoint],
        conditions: Option<&[Conditions]>,
    ) -> Result<Vec<Result<f64, Error>>, BatchError> {
        if let Some(c) = conditions
            && c.len() != ops.len()
        {
            return Err(BatchError::Internal(alloc::format!(
                "{} conditions for {} operating points: one condition per point",
                c.len(),
                ops.len()
            )));
        }
        crate::torques::torques(
            model,
            evaluator,
            ops,
            conditions,
            self.threads,
            self.stop,
            self.errors,
            self.start == Start::Independent,
        )
    }
}
