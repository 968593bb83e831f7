//! Drive torques at many operating points: each point's canonical state (the model's cold
//! solve, shared over the threads point by point: what every stateless request reports), or by
//! the control-loop evaluator ([`ballscrew_core::Evaluator`], f64) band by band of speed, as
//! follows.
//!
//! The evaluator starts a ball that has no near solution in its memory from a table of solved
//! balls, whose lubricated contacts carry the films of one speed. A lubricated ball's friction
//! follows the speed, and a start from a table more than about 5 % off the point's speed takes
//! Newton's method or the model's continuation: on DKFZD4012 a point of random load costs
//! 13 us at the table's speed, 57 us at 10 % off and 0.2-17 ms at 3 to 30 times it. So the
//! points are grouped in bands of speed magnitude (ratio `r` between a band's edges, centred on
//! the speeds `w0 r^k` about the base table's speed `w0`; `r` is [`BAND_RATIO`] for points that
//! follow a path, and for many points that do not it narrows to hold [`POINTS_PER_BAND`] points
//! a band on average, down to [`MIN_BAND_RATIO`]), each band
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
//! model's canonical state within the evaluator's stated agreement (1e-8,
//! `crates/core/tests/realtime.rs`), whatever the order, except where a ball has two steady
//! states (docs/model-notes.md item 24), where the evaluator may hold the other one. A point with a ball lighter than the evaluator's light-ball limit is the model's
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
    BatchError, Errors, Stop, callers_index, collect_in, map_points_or_nan, map_shared, map_with_state, out_of_memory,
    over_distinct_points, path_share, permuted, push, room, torque_points_or_nan, warm_order,
};
use alloc::collections::BTreeMap;
use ballscrew_core::input::extensions::Conditions;
use ballscrew_core::{EvalState, Evaluator, Model, OperatingPoint, SolverState, TableEntries};

/// Ratio of the speeds at the edges of one band, at most: a band's points lie within about 5 %
/// of the speed its table is solved at. A batch whose points follow a path (a drive cycle), or
/// that has few points for its span of speeds, takes it.
pub const BAND_RATIO: f64 = 1.1;

/// Ratio of the speeds at the edges of one band, at least: a batch of many points that follow
/// no path takes bands of [`POINTS_PER_BAND`] points on average, within this and
/// [`BAND_RATIO`]. A point's start from a table at another speed costs more the farther off it
/// is, most where a ball has two steady states: on DKFZD4012 (5000 random loads, one thread) at
/// 2000 rpm 27 us a point from a table at its speed and at 0.5 % off, 48 us at 1 % and 47 us at
/// 2.5 %; at 500 rpm 7.4, 7.6, 8.6 and 11 us at 0, 0.4, 1 and 5 % off. A band's table costs
/// a few ball solves per entry its points start from.
pub const MIN_BAND_RATIO: f64 = 1.02;

/// Points per band on average, for the band ratio of a batch that follows no path (between
/// [`MIN_BAND_RATIO`] and [`BAND_RATIO`]). Measured on DKFZD4012 over 10-3000 rpm, 2 threads:
/// 20,000 random points 0.41 s with bands of 1.1 (about 330 points a band), 0.40 s at 1.05,
/// 0.29 s at 1.02 (70), 0.31 s at 1.01; 100,000 points 1.95, 1.82, 1.27 and 1.29 s; 1000
/// points at 10-1000 rpm 31, 38 and 42 ms at 1.1 (21 points a band), 1.05 and 1.02.
pub const POINTS_PER_BAND: f64 = 50.0;

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
/// `stop` says to stop; what happens at a point that fails is `errors`' ([`Errors`]). With
/// `canonical`, each point's canonical state ([`cold_points`]); else by the control-loop
/// evaluator band by band of speed (see the module docs): `evaluator` when given (it must be
/// built from `model`), else one built here when the batch has at least
/// [`EVALUATOR_MIN_POINTS`] points and the evaluator applies to the model; else by the model.
///
/// `conditions`, when given, holds one condition per point ([`crate::Batch::torques`] checks).
#[allow(clippy::too_many_arguments)]
pub(crate) fn torques(
    model: &Model,
    evaluator: Option<&Evaluator<f64>>,
    ops: &[OperatingPoint],
    conditions: Option<&[Conditions]>,
    threads: usize,
    stop: &dyn Stop,
    errors: Errors,
    canonical: bool,
) -> Result<Vec<Result<f64, ballscrew_core::Error>>, BatchError> {
    if canonical {
        return match conditions {
            None => over_distinct_points(model, ops, |points| cold_points(model, points, None, threads, stop, errors)),
            Some(_) => cold_points(model, ops, conditions, threads, stop, errors),
        };
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

/// Points a canonical batch shares over its threads at a time: its results are reserved whole
/// before the first point (a batch too large for the memory fails at once, not hours later),
/// and each chunk's own vectors stay small.
const COLD_CHUNK_POINTS: usize = 256;

/// The canonical torques: each point solved by the model from the cold start
/// ([`Model::torque_at`] with a fresh [`SolverState`]), the points shared over the threads one
/// by one ([`COLD_CHUNK_POINTS`] at a time): each the number a stateless request gives at its
/// point (`ballscrew torque`, Python's scalar `Screw.torque`), to the bit, on any number of
/// threads and whatever the other points. (Where the torque does not depend on the speed's
/// magnitude, [`torques`] solves each distinct point once: the cold solve there gives the same
/// bits at every such speed, which a test checks.)
fn cold_points(
    model: &Model,
    ops: &[OperatingPoint],
    conditions: Option<&[Conditions]>,
    threads: usize,
    stop: &dyn Stop,
    errors: Errors,
) -> Values {
    let mut out = room(ops.len())?;
    let default = Conditions::default();
    let cold = |&i: &usize| model.torque_at(&ops[i], conditions.map_or(&default, |c| &c[i]), &mut SolverState::new());
    let mut indices = room(COLD_CHUNK_POINTS.min(ops.len()))?;
    for first in (0..ops.len()).step_by(COLD_CHUNK_POINTS) {
        indices.clear();
        indices.extend(first..(first + COLD_CHUNK_POINTS).min(ops.len()));
        let values = match errors {
            Errors::Raise => map_shared(&indices, threads, stop, |i| cold(i).map(Ok)),
            Errors::Nan => map_shared(&indices, threads, stop, |i| Ok(cold(i))),
        };
        match values {
            Ok(v) => out.extend(v),
            Err(BatchError::Point { index, error }) => return Err(BatchError::Point { index: first + index, error }),
            Err(e) => return Err(e),
        }
    }
    Ok(out)
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
    // Points with a ball the evaluator hands to the model go to the model directly, after the
    // others: each is a cold solve of the model (about a millisecond, against microseconds for
    // a warm point), so they are split over the threads apart, by count, where among the
    // others they would load one chunk far more than the rest.
    let (mut handed, mut kept) = (Vec::new(), room(ops.len())?);
    for i in 0..ops.len() {
        if base.hands_to_model(&ops[i], condition(i)) { push(&mut handed, i)? } else { kept.push(i) }
    }
    let bands = Bands::new(base, model, ops, &kept)?;
    let (kept_order, entries) = bands.order(base, ops, &kept, &condition)?;
    let eval = |&i: &usize, w: &mut Worker| {
        let op = &ops[i];
        let band = bands.band(op.speed_rad_s);
        if band != w.band {
            *w.ev = w.ev.with_table_speed_for(bands.speed(band), &entries[&band]);
            w.band = band;
        }
        w.ev.torque_at_nm(op, condition(i), &mut w.state)
    };
    let new_worker = || Worker { ev: Box::new(*base), band: 0, state: EvalState::new() };
    // The model's answer from a fresh state, as the evaluator gives it for such a point (the
    // same whatever thread takes it).
    let by_model = |&i: &usize| model.torque_at(&ops[i], condition(i), &mut SolverState::new());
    // The kept points, then the handed ones; a failure's index in that whole order.
    let both = |kept_values: Values, handed: &dyn Fn() -> Values| -> Values {
        let mut v = kept_values?;
        let more = handed().map_err(|e| match e {
            BatchError::Point { index, error } => BatchError::Point { index: kept_order.len() + index, error },
            other => other,
        })?;
        v.try_reserve_exact(more.len()).map_err(|_| out_of_memory::<Result<f64, ballscrew_core::Error>>(more.len()))?;
        v.extend(more);
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
    let order: Vec<usize> = collect_in(kept_order.len() + handed.len(), kept_order.iter().chain(&handed).copied())?;
    permuted(&order, values.map_err(|e| callers_index(&order, e))?)
}

/// The bands of speed of a batch (see the module docs).
struct Bands {
    /// Speed of the base table, rad/s.
    base_rad_s: f64,
    /// Whether the table depends on the speed (lubricated contacts).
    by_speed: bool,
    standstill_rad_s: f64,
    /// Natural logarithm of the ratio of the speeds at a band's edges.
    log_ratio: f64,
}

impl Bands {
    /// The bands for the points `these` of `ops`, the base table `base`'s speed among their
    /// centres: of ratio [`BAND_RATIO`] where the points follow a path in their order
    /// ([`path_share`] at least [`BAND_PATH_SHARE`]: each pass of a drive cycle through a
    /// band starts warm from the point before, and narrower bands would cut the passes into
    /// more cold starts: 10,000 points of one, 40-51 ms at 1.1, 59-61 ms at 1.02), else of
    /// [`POINTS_PER_BAND`] points on average over the span of their speeds, within
    /// [`MIN_BAND_RATIO`] and [`BAND_RATIO`].
    fn new(base: &Evaluator<f64>, model: &Model, ops: &[OperatingPoint], these: &[usize]) -> Result<Self, BatchError> {
        let standstill_rad_s = model.spec().friction.standstill_speed_rad_s;
        let mut bands = Self {
            base_rad_s: base.table_speed_rad_s(),
            by_speed: model.oil().is_some(),
            standstill_rad_s,
            log_ratio: BAND_RATIO.ln(),
        };
        if !bands.by_speed || these.len() < 2 {
            return Ok(bands);
        }
        let points: Vec<OperatingPoint> = collect_in(these.len(), these.iter().map(|&i| ops[i]))?;
        if path_share(&points, standstill_rad_s) >= BAND_PATH_SHARE {
            return Ok(bands);
        }
        let (lo, hi) = points.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), op| {
            let w = op.speed_rad_s.abs().max(standstill_rad_s);
            (lo.min(w), hi.max(w))
        });
        let wanted = POINTS_PER_BAND * (hi / lo).ln() / points.len() as f64;
        // A NaN (no finite span) keeps the widest bands.
        bands.log_ratio = wanted.clamp(MIN_BAND_RATIO.ln(), BAND_RATIO.ln()).min(BAND_RATIO.ln());
        Ok(bands)
    }

    /// The band of screw speed `speed_rad_s` (0: the base table's).
    fn band(&self, speed_rad_s: f64) -> i32 {
        if !self.by_speed {
            return 0;
        }
        let w = speed_rad_s.abs().max(self.standstill_rad_s);
        let k = (w / self.base_rad_s).ln() / self.log_ratio;
        // Speeds are validated finite; the clamp keeps the cast defined for any input.
        k.round().clamp(-1e6, 1e6) as i32
    }

    /// The centre speed of band `band`, rad/s.
    fn speed(&self, band: i32) -> f64 {
        self.base_rad_s * (self.log_ratio * f64::from(band)).exp()
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
    ) -> Result<(Vec<usize>, BTreeMap<i32, TableEntries>), BatchError> {
        let mut groups: BTreeMap<i32, (Vec<usize>, TableEntries)> = BTreeMap::new();
        for &i in these {
            let op = &ops[i];
            let (members, entries) = groups.entry(self.band(op.speed_rad_s)).or_default();
            push(members, i)?;
            if self.by_speed {
                let these = base.table_entries(op, condition(i));
                *entries = entries.join(&these);
            }
        }
        let mut order = room(these.len())?;
        let mut entries = BTreeMap::new();
        for (band, (members, these)) in groups {
            let sub: Vec<OperatingPoint> = collect_in(members.len(), members.iter().map(|&i| ops[i]))?;
            if path_share(&sub, self.standstill_rad_s) >= BAND_PATH_SHARE {
                order.extend(members);
            } else {
                order.extend(warm_order(&sub, self.standstill_rad_s)?.into_iter().map(|k| members[k]));
            }
            entries.insert(band, these);
        }
        Ok((order, entries))
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
    let order = warm_order(ops, model.spec().friction.standstill_speed_rad_s)?;
    let values = map_points_or_nan(model, &order, threads, stop, errors, |m, &i, state| {
        m.torque_at(&ops[i], &conditions[i], state)
    });
    permuted(&order, values.map_err(|e| callers_index(&order, e))?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use ballscrew_core::input::rpm_to_rad_s;
    use ballscrew_core::{Lubrication, ScrewSpec};

    /// `n` points of scattered loads, their speeds' magnitudes spread evenly in the logarithm
    /// over `lo..hi` rpm, in no order (each coordinate the fractional part of `k` times an
    /// irrational number: no point near the one before), or in time order along a drive cycle
    /// (`path`).
    fn points(n: usize, lo: f64, hi: f64, path: bool) -> Vec<OperatingPoint> {
        let scattered = |k: usize, a: f64| (k as f64 * a).fract();
        (0..n)
            .map(|k| {
                let t = k as f64 / n as f64;
                if path {
                    OperatingPoint {
                        preload_n: 2000.0 - 300.0 * t,
                        speed_rad_s: rpm_to_rad_s(lo + (hi - lo) * (0.5 - 0.5 * (6.0 * t).cos())),
                        axial_load_n: 200.0 * (31.0 * t).sin(),
                    }
                } else {
                    OperatingPoint {
                        preload_n: 500.0 + 2500.0 * scattered(k, core::f64::consts::SQRT_2),
                        speed_rad_s: rpm_to_rad_s(lo * (hi / lo).powf(scattered(k, 0.618_033_988_749_894_9))),
                        axial_load_n: -500.0 + 1000.0 * scattered(k, core::f64::consts::E),
                    }
                }
            })
            .collect()
    }

    fn log_ratio(lubrication: Lubrication, ops: &[OperatingPoint]) -> f64 {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.model.lubrication = lubrication;
        let model = Model::new(&spec).unwrap();
        let base = Evaluator::<f64>::new(&model).unwrap();
        let all: Vec<usize> = (0..ops.len()).collect();
        Bands::new(&base, &model, ops, &all).unwrap().log_ratio
    }

    /// The band ratio: the widest for a drive cycle, for few points, and for the dry model;
    /// for many points that follow no path [`POINTS_PER_BAND`] points a band on average over
    /// the span of their speeds, down to [`MIN_BAND_RATIO`].
    #[test]
    fn bands_narrow_for_many_points_that_follow_no_path() {
        let (wide, narrow) = (BAND_RATIO.ln(), MIN_BAND_RATIO.ln());
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
        assert!(close(log_ratio(Lubrication::Ehl, &points(10_000, 50.0, 550.0, true)), wide));
        assert!(close(log_ratio(Lubrication::Ehl, &points(1000, 10.0, 1000.0, false)), wide));
        assert!(close(log_ratio(Lubrication::Ehl, &points(20_000, 10.0, 3000.0, false)), narrow));
        assert!(close(log_ratio(Lubrication::Dry, &points(20_000, 10.0, 3000.0, false)), wide));
        // 5000 points over a span of ln 300 in speed: 50 points a band.
        let ops = points(5000, 10.0, 3000.0, false);
        let (lo, hi) = ops.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), op| {
            (lo.min(op.speed_rad_s.abs()), hi.max(op.speed_rad_s.abs()))
        });
        let got = log_ratio(Lubrication::Ehl, &ops);
        assert!(close(got, POINTS_PER_BAND * (hi / lo).ln() / 5000.0), "{got}");
        assert!(got > narrow && got < wide);
    }
}
