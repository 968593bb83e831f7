//! Drive torques at many operating points by the control-loop evaluator
//! ([`ballscrew_core::Evaluator`], f64), band by band of speed.
//!
//! The evaluator starts a ball that has no near solution in its memory from a table of solved
//! balls, whose lubricated contacts carry the films of one speed. A lubricated ball's friction
//! follows the speed, and a start from a table more than about 5 % off the point's speed takes
//! Newton's method or the model's continuation: on DKFZD4012 a point of random load costs
//! 13 us at the table's speed, 57 us at 10 % off and 0.2-17 ms at 3 to 30 times it. So the
//! points are grouped in bands of speed magnitude (ratio [`BAND_RATIO`] between a band's edges,
//! centred on the speeds `w0 BAND_RATIO^k` about the base table's speed `w0`), each band
//! evaluated with a table solved at its centre speed, for the entries its points start from
//! ([`ballscrew_core::Evaluator::with_table_speed_for`]: from the table of the band before, a
//! ball solve per entry, a few entries for a band of similar loads where the whole table takes
//! a few milliseconds). Within a band the points are walked in the caller's order where at least
//! half of them follow a path there ([`crate::pool::path_share`]: a drive cycle sampled in
//! time, whose passes through the band each start from the point before), else in
//! [`crate::pool::warm_order`], so that each starts from a near neighbour. The bands, in
//! ascending order, are split in contiguous chunks over the threads; each thread carries its
//! own evaluator and state from band to band. The dry model's table does not depend on the
//! speed: all its points form one band. (Evaluating a drive cycle unbanded, in its order, each
//! chunk from a table at its first point's speed, was measured slower on 10,000 points of one
//! at 50-550 rpm: 62 ms against 58-60 ms for `predict`. Where a light nut's ball loads move by
//! more than 1 % a point, the start from a table far off the speed costs more than the 25
//! band tables saved.)
//!
//! Every point is solved in full to the evaluator's tolerance: the torques agree with the
//! model's within the evaluator's stated agreement (1e-8, `tests/realtime.rs`), whatever the
//! order. A point with a ball lighter than the evaluator's light-ball limit is the model's
//! cold solve, as the evaluator itself would give it ([`Evaluator::hands_to_model`]), so a
//! point the model refuses is refused here too. Such points (a nut nearly unloaded) cost a
//! millisecond each against microseconds for the others: they are set apart and, after the
//! others, shared out over the threads one by one ([`crate::pool::map_shared`]), so that a
//! chunk that holds many of them does not hold up the batch. They come last in the evaluation
//! order: with [`Errors::Raise`] a failing point among the others is the one reported, before
//! any failing point among them.
//!
//! Where the evaluator does not apply (the FASTSIM contact theory, oversize-ball nuts) the
//! model's own solver evaluates the points ([`crate::pool::map_points_warm`]); also where the batch
//! has fewer than [`EVALUATOR_MIN_POINTS`] points and the caller holds no evaluator, as
//! building one (its table: about 170 ball solves by continuation, 120-150 ms on DKFZD4012)
//! would cost more than the points.

use crate::pool::{
    BatchError, Errors, Stop, callers_index, map_points_or_nan, map_shared, map_with_state, over_distinct_points,
    path_share, permuted, torque_points_or_nan, warm_order,
};
use alloc::collections::BTreeMap;
use ballscrew_core::input::extensions::Conditions;
use ballscrew_core::{EvalState, Evaluator, Model, OperatingPoint, SolverState, TableEntries};

/// Ratio of the speeds at the edges of one band: a band's points lie within about 5 % of the
/// speed its table is solved at.
pub const BAND_RATIO: f64 = 1.1;

/// Fewest points for which a batch builds its own evaluator (the caller may pass one).
pub const EVALUATOR_MIN_POINTS: usize = 100;

/// Least share of neighbours among a band's points at which they are walked in the caller's
/// order.
const BAND_PATH_SHARE: f64 = 0.5;

/// Torques (or each point's error) of a batch, or why the batch stopped.
type Values = Result<Vec<Result<f64, ballscrew_core::Error>>, BatchError>;

/// One thread's evaluator, the band its table is solved for, and its warm-start memory.
struct Worker {
    ev: Box<Evaluator<f64>>,
    band: i32,
    state: EvalState<f64>,
}

/// The drive torque (N m) at every point of `ops`, under the conditions `conditions` (one per
/// point; `None`: the default conditions), in the caller's order, over `threads` threads, until
/// `stop` says to stop; what happens at a point that fails is `errors`' ([`Errors`]). By the
/// control-loop evaluator band by band of speed (see the module docs): `evaluator` when given
/// (it must be built from `model`), else one built here when the batch has at least
/// [`EVALUATOR_MIN_POINTS`] points and the evaluator applies to the model; else by the model.
///
/// # Panics
/// When `conditions` is given with a length other than `ops`'s.
pub fn torques(
    model: &Model,
    evaluator: Option<&Evaluator<f64>>,
    ops: &[OperatingPoint],
    conditions: Option<&[Conditions]>,
    threads: usize,
    stop: &dyn Stop,
    errors: Errors,
) -> Result<Vec<Result<f64, ballscrew_core::Error>>, BatchError> {
    if let Some(c) = conditions {
        assert_eq!(c.len(), ops.len(), "one condition per operating point");
    }
    // Where the torque depends on the direction only above the standstill speed (the dry model
    // without speed-dependent terms, docs/model-notes.md item 12), each distinct point is
    // evaluated once and stands for the others (as `torque_points` does).
    match conditions {
        None => {
            over_distinct_points(model, ops, |points| each_point(model, evaluator, points, None, threads, stop, errors))
        }
        Some(_) => each_point(model, evaluator, ops, conditions, threads, stop, errors),
    }
}

/// [`torques`] without the shortcut of distinct points.
fn each_point(
    model: &Model,
    evaluator: Option<&Evaluator<f64>>,
    ops: &[OperatingPoint],
    conditions: Option<&[Conditions]>,
    threads: usize,
    stop: &dyn Stop,
    errors: Errors,
) -> Result<Vec<Result<f64, ballscrew_core::Error>>, BatchError> {
    let built;
    let base = match evaluator {
        Some(ev) => Some(ev),
        None if ops.len() >= EVALUATOR_MIN_POINTS => {
            built = Evaluator::<f64>::new(model).ok();
            built.as_ref()
        }
        None => None,
    };
    let Some(base) = base else {
        return match conditions {
            None => torque_points_or_nan(model, ops, threads, stop, errors),
            Some(conds) => model_with_conditions(model, ops, conds, threads, stop, errors),
        };
    };
    let default = Conditions::default();
    let condition = |i: usize| conditions.map_or(&default, |c| &c[i]);
    let bands = Bands::new(base, model);
    // Points with a ball the evaluator hands to the model go to the model directly, after the
    // others: each is a cold solve of the model (about a millisecond, against microseconds for
    // a warm point), so they are split over the threads apart, by count, where among the
    // others they would load one chunk far more than the rest.
    let (handed, kept): (Vec<usize>, Vec<usize>) =
        (0..ops.len()).partition(|&i| base.hands_to_model(&ops[i], condition(i)));
    let (kept_order, entries) = bands.order(base, ops, &kept, &condition);
    let eval = |&i: &usize, w: &mut Worker| {
        let op = &ops[i];
        let band = bands.band(op.speed_rad_s);
        if band != w.band {
            *w.ev = w.ev.with_table_speed_for(bands.speed(band), &entries[&band]);
            w.band = band;
        }
        w.ev.torque_at_nm(op.speed_rad_s, op.preload_n, op.axial_load_n, condition(i), &mut w.state)
    };
    let new_worker = || Worker { ev: Box::new(*base), band: 0, state: EvalState::new() };
    // The model's answer from a fresh state, as the evaluator gives it for such a point (the
    // same whatever thread takes it).
    let by_model = |&i: &usize| model.torque_at(&ops[i], condition(i), &mut SolverState::new());
    // The kept points, then the handed ones; a failure's index in that whole order.
    let both = |kept_values: Values, handed: &dyn Fn() -> Values| -> Values {
        let mut v = kept_values?;
        v.extend(handed().map_err(|e| match e {
            BatchError::Point { index, error } => BatchError::Point { index: kept_order.len() + index, error },
            other => other,
        })?);
        Ok(v)
    };
    let values = match errors {
        Errors::Raise => {
            both(map_with_state(&kept_order, threads, stop, new_worker, |i, w| eval(i, w).map(Ok)), &|| {
                map_shared(&handed, threads, stop, |i| by_model(i).map(Ok))
            })
        }
        Errors::Nan => both(map_with_state(&kept_order, threads, stop, new_worker, |i, w| Ok(eval(i, w))), &|| {
            map_shared(&handed, threads, stop, |i| Ok(by_model(i)))
        }),
    };
    let order: Vec<usize> = kept_order.iter().chain(&handed).copied().collect();
    Ok(permuted(&order, values.map_err(|e| callers_index(&order, e))?))
}

/// The bands of speed of a batch (see the module docs).
struct Bands {
    /// Speed of the base table, rad/s.
    base_rad_s: f64,
    /// Whether the table depends on the speed (lubricated contacts).
    by_speed: bool,
    standstill_rad_s: f64,
}

impl Bands {
    fn new(base: &Evaluator<f64>, model: &Model) -> Self {
        Self {
            base_rad_s: base.table_speed_rad_s(),
            by_speed: model.oil().is_some(),
            standstill_rad_s: model.spec().friction.standstill_speed_rad_s,
        }
    }

    /// The band of screw speed `speed_rad_s` (0: the base table's).
    fn band(&self, speed_rad_s: f64) -> i32 {
        if !self.by_speed {
            return 0;
        }
        let w = speed_rad_s.abs().max(self.standstill_rad_s);
        let k = (w / self.base_rad_s).ln() / BAND_RATIO.ln();
        // Speeds are validated finite; the clamp keeps the cast defined for any input.
        k.round().clamp(-1e6, 1e6) as i32
    }

    /// The centre speed of band `band`, rad/s.
    fn speed(&self, band: i32) -> f64 {
        self.base_rad_s * BAND_RATIO.powi(band)
    }

    /// The evaluation order of the points `these` of `ops` (point `i` under the conditions
    /// `condition(i)`): bands ascending, each in the caller's order where its points follow a
    /// path ([`path_share`] at least [`BAND_PATH_SHARE`]: a drive cycle), else in [`warm_order`];
    /// and by band the entries of `base`'s start table its points start from (the only ones its
    /// table solves again).
    fn order<'c>(
        &self,
        base: &Evaluator<f64>,
        ops: &[OperatingPoint],
        these: &[usize],
        condition: &dyn Fn(usize) -> &'c Conditions,
    ) -> (Vec<usize>, BTreeMap<i32, TableEntries>) {
        let mut groups: BTreeMap<i32, (Vec<usize>, TableEntries)> = BTreeMap::new();
        for &i in these {
            let op = &ops[i];
            let (members, entries) = groups.entry(self.band(op.speed_rad_s)).or_default();
            members.push(i);
            if self.by_speed {
                let these = base.table_entries(op.speed_rad_s, op.preload_n, op.axial_load_n, condition(i));
                *entries = entries.join(&these);
            }
        }
        let mut order = Vec::with_capacity(ops.len());
        let mut entries = BTreeMap::new();
        for (band, (members, these)) in groups {
            let sub: Vec<OperatingPoint> = members.iter().map(|&i| ops[i]).collect();
            if path_share(&sub, self.standstill_rad_s) >= BAND_PATH_SHARE {
                order.extend(members);
            } else {
                order.extend(warm_order(&sub, self.standstill_rad_s).into_iter().map(|k| members[k]));
            }
            entries.insert(band, these);
        }
        (order, entries)
    }
}

/// The model's torque at every point under its conditions, warm-started in [`warm_order`].
fn model_with_conditions(
    model: &Model,
    ops: &[OperatingPoint],
    conditions: &[Conditions],
    threads: usize,
    stop: &dyn Stop,
    errors: Errors,
) -> Result<Vec<Result<f64, ballscrew_core::Error>>, BatchError> {
    let order = warm_order(ops, model.spec().friction.standstill_speed_rad_s);
    let values = map_points_or_nan(model, &order, threads, stop, errors, |m, &i, state| {
        m.torque_at(&ops[i], &conditions[i], state)
    });
    Ok(permuted(&order, values.map_err(|e| callers_index(&order, e))?))
}
