//! The evaluator's public API: [`Evaluator`] built from a model (its constants and start
//! table), what it supports, and the torque of a call (validated, moved by the spec's extension
//! terms, handed to the model where a ball is light).

use super::memory::EvalState;
use super::table::{LIGHT_BALL_N, StartTable, TABLE_LEN, TableEntries, table_speed_rad_s};
use crate::ball::balance::{self, Constants};
use crate::ball::lubrication::BallFilms;
use crate::ball::solve::{self, JacobianStep};
use crate::error::Error;
use crate::input::extensions::Conditions;
use crate::input::operating::{AXIAL_LOAD_RANGE_N, MAX_SPEED_RAD_S, PRELOAD_RANGE_N};
use crate::input::screw::check_preload_for;
use crate::input::{ContactTheory, MAX_CIRCLES_PER_NUT, MAX_NUTS, OperatingPoint, Preload, ScrewSpec};
use crate::real::Real;
use crate::screw::load;
use crate::screw::model::{Model, SolverState};

/// Newton iterations of one solve in the evaluator.
pub(super) const MAX_ITERATIONS: u32 = 40;
/// A model ready for the control loop in float type `F`.
///
/// Built once, then called every cycle with its state (warm start, no allocation); in f32 it
/// agrees with f64 to the rounding of f32, and in f64 with the model to the solver's tolerance:
///
/// ```
/// use ballscrew_core::input::rpm_to_rad_s;
/// use ballscrew_core::{EvalState, Evaluator, Model, OperatingPoint, ScrewSpec, SolverState};
///
/// let model = Model::new(&ScrewSpec::dkfzd4012())?;
/// let (ev32, ev64) = (Evaluator::<f32>::new(&model)?, Evaluator::<f64>::new(&model)?);
/// let (mut s32, mut s64) = (EvalState::new(), EvalState::new());
/// for speed_rpm in [-1000.0, 10.0, 100.0, 3000.0] {
///     let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(speed_rpm), preload_n: 2000.0, axial_load_n: 0.0 };
///     let t32 = f64::from(ev32.torque_nm(&op, &mut s32)?);
///     let t64 = ev64.torque_nm(&op, &mut s64)?;
///     let model_nm = model.torque(&op, &mut SolverState::new())?;
///     assert!((t32 - t64).abs() <= 1e-4 * t64.abs(), "{speed_rpm} rpm: {t32} against {t64}");
///     assert!((t64 - model_nm).abs() <= 1e-6 * model_nm.abs(), "{speed_rpm} rpm: {t64} against {model_nm}");
/// }
/// # Ok::<(), ballscrew_core::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Evaluator<F: Real> {
    pub(super) model: Model,
    /// The films' friction of every ball, with lubricated contacts.
    pub(super) films: Option<BallFilms>,
    /// Per flank: index 0 for +1, 1 for -1.
    pub(super) constants: [Constants<F>; 2],
    /// `constants` in every lane of [`Real::Wide`], per flank.
    pub(super) wide: [Constants<F::Wide>; 2],
    /// The start table.
    pub(super) table: StartTable<F>,
    pub(super) fractions: [F; MAX_CIRCLES_PER_NUT],
    /// The circle shares in f64 (the heaviest ball's load for the acceptance of light balls).
    pub(super) shares: load::CircleShares,
    pub(super) weights: [F; MAX_CIRCLES_PER_NUT],
    pub(super) nuts: usize,
    pub(super) circles: usize,
    pub(super) balls_per_circle: F,
    pub(super) tolerance: F,
    pub(super) step: JacobianStep,
    /// The relative step of finite differences in f64 (the Jacobians an f32 evaluator takes in
    /// f64).
    pub(super) step_f64: JacobianStep,
    /// The smallest circle share of a nut's load.
    pub(super) lightest_fraction: f64,
}

impl<F: Real> Evaluator<F> {
    /// Prepares `model` for the control loop: the constants of both flanks and the start table
    /// (about 100 ball solves in f64). The linear-saturated contact theory only: FASTSIM is an
    /// analysis option.
    pub fn new(model: &Model) -> Result<Self, Error> {
        let mut ev = Self::without_table(model)?;
        let model = ev.model;
        ev.table.fill(&model);
        Ok(ev)
    }

    /// Whether the evaluator takes `spec`: [`Error::Unsupported`] naming the option it does not
    /// take (FASTSIM contacts; the four-point balls of an oversize-ball nut; a lead deviation,
    /// which makes the circles' shares depend on the load; a load ramp; circuits of several loaded turns,
    /// whose ball train [`crate::screw::circuit`] balances: the model solves them), else `Ok`. What [`Evaluator::new`] checks first.
    pub fn supports(spec: &ScrewSpec) -> Result<(), Error> {
        if spec.model.contact_theory != ContactTheory::LinearSaturated {
            return Err(Error::Unsupported {
                field: "model.contact_theory",
                value: spec.model.contact_theory.name(),
                valid: "linear-saturated, for the real-time evaluator",
            });
        }
        if spec.geometry.preload == Preload::OversizeBall {
            return Err(Error::Unsupported {
                field: "geometry.preload",
                value: spec.geometry.preload.name(),
                valid: "double-nut, offset-lead or none, for the real-time evaluator (the four-point \
                        balls of oversize-ball nuts are solved by the model)",
            });
        }
        if spec.circulation.lead_deviation_m != 0.0 {
            return Err(Error::Unsupported {
                field: "circulation.lead_deviation_um",
                value: "a lead deviation",
                valid: "0 for the real-time evaluator (the load of each circle with a lead deviation is solved by \
                        the model)",
            });
        }
        if spec.circulation.load_ramp_balls > 0 {
            return Err(Error::Unsupported {
                field: "circulation.load_ramp_balls",
                value: "a load ramp",
                valid: "0 for the real-time evaluator (the balls of a load ramp are solved by the model)",
            });
        }
        if Model::solves_circuits(spec) {
            return Err(Error::Unsupported {
                field: "circulation.turns_per_circuit",
                value: "several loaded turns per circuit",
                valid: "1 for the real-time evaluator (the balance of a circuit of several loaded turns is solved \
                        by the model)",
            });
        }
        Ok(())
    }

    /// Everything of [`Evaluator::new`] but the table (no entry solved).
    fn without_table(model: &Model) -> Result<Self, Error> {
        let spec = model.spec();
        Self::supports(spec)?;
        let g = &spec.geometry;
        let groups = load::groups(g, 0.0, 0.0);
        let shares = load::circle_shares(groups.circles, spec.model.load_distribution);
        let approach = model.ball_ball_approach_m();
        let setup = |flank: f64| Constants::new(&model.ball_setup_for(1.0, flank), approach);
        let js = solve::jacobian_step(&model.ball_setup_for(1.0, 1.0));
        let floor = F::JACOBIAN_STEP.to_f64();
        Ok(Self {
            model: *model,
            films: model.oil().map(|oil| BallFilms::new(&model.ball_setup_for(1.0, 1.0), &spec.lubricant, oil)),
            constants: [setup(1.0), setup(-1.0)],
            wide: [setup(1.0), setup(-1.0)].map(|c| Constants::gather(&[&c])),
            table: StartTable::empty(table_speed_rad_s(model, model.spec().operating.speed_rad_s)),
            fractions: core::array::from_fn(|i| F::of(shares.load_fraction[i])),
            shares,
            weights: core::array::from_fn(|i| F::of(shares.weight[i])),
            nuts: groups.count,
            circles: groups.circles as usize,
            balls_per_circle: F::of(f64::from(g.balls_per_circle)),
            tolerance: F::TOLERANCE,
            step: JacobianStep { far: js.far.max(floor), near: js.near.max(floor), near_below: js.near_below },
            step_f64: js,
            lightest_fraction: shares
                .load_fraction
                .iter()
                .take(groups.circles as usize)
                .fold(f64::INFINITY, |m, &f| m.min(f)),
        })
    }

    /// The same evaluator with the tolerance `tolerance` on the residual (max norm of the
    /// imbalances over the nominal normal load Q, the friction-borne ones weighted by f). Below about
    /// [`Real::TOLERANCE`] a solve in f32 meets the rounding noise of the residual and falls back
    /// to the model's continuation.
    pub fn with_tolerance(mut self, tolerance: F) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// The tolerance on the residual (see [`Evaluator::with_tolerance`]).
    pub fn tolerance(&self) -> F {
        self.tolerance
    }

    /// The model this evaluator was built from.
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// The drive torque (N m) at the operating point `op`, by the model's torque route with the
    /// spec's extension terms at their default conditions. The evaluator sees the point in its
    /// float type `F`: an f32 evaluator rounds each value of `op` to f32 first, within its range
    /// (an end of the range f32 does not hold, 30000 rpm, to the f32 next to it inside).
    pub fn torque_nm(&self, op: &OperatingPoint, state: &mut EvalState<F>) -> Result<F, Error> {
        self.torque_at_nm(op, &Conditions::default(), state)
    }

    /// [`Evaluator::torque_nm`] under `cond` (position, temperature, running time).
    pub fn torque_at_nm(&self, op: &OperatingPoint, cond: &Conditions, state: &mut EvalState<F>) -> Result<F, Error> {
        // Rounded within each value's range: 30000 rpm, the top of the speed range, is 3141.5927
        // rad/s rounded to the nearest f32, above the end; the f32 below it is inside.
        let speed_rad_s = F::of_within(op.speed_rad_s, -MAX_SPEED_RAD_S, MAX_SPEED_RAD_S);
        let given = op;
        let ((p_lo, p_hi), (a_lo, a_hi)) = (PRELOAD_RANGE_N, AXIAL_LOAD_RANGE_N);
        let op = OperatingPoint {
            speed_rad_s: speed_rad_s.to_f64(),
            preload_n: F::of_within(op.preload_n, p_lo, p_hi).to_f64(),
            axial_load_n: F::of_within(op.axial_load_n, a_lo, a_hi).to_f64(),
        };
        // A load below the smallest number `F` holds (1e-300 N in f32) would round to no load
        // at all: its balls are far lighter than [`LIGHT_BALL_N`], so the point is the model's,
        // on the loads as given, as in f64.
        let vanished = |given: f64, rounded: f64| given != 0.0 && rounded == 0.0;
        if vanished(given.preload_n, op.preload_n) || vanished(given.axial_load_n, op.axial_load_n) {
            state.reset();
            return self.model.torque_at(given, cond, &mut SolverState::new()).map(F::of);
        }
        let eff = self.effective_point(&op, cond)?;
        let ext = &self.model.spec().extensions;
        let solved = if ext.is_empty() {
            self.creep_torque(&op, speed_rad_s, state, None)?.map(|(torque, _)| torque)
        } else {
            self.creep_torque(&eff, F::of(eff.speed_rad_s), state, None)?.map(|(torque, axial)| {
                F::of(self.model.with_extensions_nm(torque.to_f64(), axial.to_f64(), &eff, &op, cond))
            })
        };
        match solved {
            Some(torque) => Ok(torque),
            // A light ball (see [`LIGHT_BALL_N`]): the model's own answer, value or error.
            None => {
                state.reset();
                self.model.torque_at(&op, cond, &mut SolverState::new()).map(F::of)
            }
        }
    }

    /// Whether [`Evaluator::torque_at_nm`] hands the point (the spec's extension terms under
    /// `cond` applied, as there) to the model because a loaded ball is lighter than
    /// [`LIGHT_BALL_N`]; `false` where the evaluator answers itself or refuses the point (the
    /// same error as the model's). A batch sends such points to the model directly, where their
    /// cost (a cold solve of the model, about a millisecond on DKFZD4012) is not carried by the
    /// evaluator's warm sequence.
    pub fn hands_to_model(&self, op: &OperatingPoint, cond: &Conditions) -> bool {
        self.effective_point(op, cond)
            .and_then(|eff| self.ball_loads(&eff))
            .is_ok_and(|(loads, _)| self.has_light_ball(&loads))
    }

    /// `op` and `cond` validated (in the model's order, conditions first, so that a call with
    /// both wrong names the same field as the model's error), and the operating point the
    /// creep model sees: `op` moved by the spec's extension terms under `cond`.
    fn effective_point(&self, op: &OperatingPoint, cond: &Conditions) -> Result<OperatingPoint, Error> {
        cond.validate()?;
        op.validate()?;
        let ext = &self.model.spec().extensions;
        Ok(if ext.is_empty() { *op } else { ext.effective_operating(op, cond) })
    }

    /// The nuts' loads (N, with their flanks) at `op` and the heaviest ball's load (N: for the
    /// static capacity, and for the model's acceptance of light balls); the model's error where
    /// the preload or the static capacity refuses the point.
    pub(super) fn ball_loads(&self, op: &OperatingPoint) -> Result<([(f64, f64); MAX_NUTS], f64), Error> {
        let spec = self.model.spec();
        self.model.check_thermal_loading(op.speed_rad_s)?;
        check_preload_for(spec.geometry.preload, op.preload_n)?;
        let loads = load::groups(&spec.geometry, op.preload_n, op.axial_load_n).loads;
        let z64 = f64::from(spec.geometry.balls_per_circle);
        let p_max = load::heaviest_ball_load_n(&loads, self.nuts, &self.shares, self.circles, z64);
        self.model.check_static_capacity(p_max)?;
        Ok((loads, p_max))
    }

    /// Whether a loaded nut of `loads` (N, with its flank) carries a ball lighter than
    /// [`LIGHT_BALL_N`] (the model answers there).
    pub(super) fn has_light_ball(&self, loads: &[(f64, f64)]) -> bool {
        let z64 = f64::from(self.model.spec().geometry.balls_per_circle);
        loads.iter().take(self.nuts).any(|&(l, _)| l > 0.0 && l * self.lightest_fraction / z64 < LIGHT_BALL_N)
    }

    /// This evaluator with its start table solved again with the films of screw speed
    /// `speed_rad_s` (its magnitude, at least the standstill speed; rad/s), each entry by the
    /// model's solver from this table's entry of the same load. Lubricated balls' friction
    /// follows the speed, and a start from a table whose films are those of a speed more than
    /// about 5 % away takes Newton's method or the continuation (DKFZD4012: 13 us a cold point
    /// at the table's speed, 57 us at 10 % off, 0.2-17 ms at 3-30 times it). A batch of points
    /// at many speeds is evaluated band by band of speed, each with its own table, each table
    /// solved from the one of the nearest band (a few milliseconds where [`Evaluator::new`]
    /// solves every entry from the one beside it by continuation). Entries lighter than
    /// [`LIGHT_BALL_N`] over [`TABLE_RATIO`](super::TABLE_RATIO) are left out: the evaluator hands such balls to the
    /// model. An entry that Newton's method does not solve from there nor from the entry below
    /// it is left out too; a table start then takes the nearest solved one. An entry last
    /// solved at another speed (left as it was by [`Evaluator::with_table_speed_for`]) is
    /// solved along the speed in steps of at most [`CARRY_SPEED_RATIO`](super::CARRY_SPEED_RATIO); where that fails, from
    /// the next heavier entry solved at the speed, as the table is first solved. The dry
    /// model's table does not depend on the speed: it is returned as it is.
    pub fn with_table_speed(&self, speed_rad_s: f64) -> Self {
        let speed = table_speed_rad_s(&self.model, speed_rad_s);
        if self.model.oil().is_none() {
            return *self;
        }
        let mut out = *self;
        out.table.speed_rad_s = speed;
        out.table.carry(&self.model, &self.table, &TableEntries::ALL);
        out
    }

    /// [`Evaluator::with_table_speed`] for the entries `entries` only (those the points of a
    /// batch start from, [`Evaluator::table_entries`] joined over them): the other entries stay
    /// as they are, starts whose films are those of the speed they were last solved at (a start
    /// off in speed still converges, by Newton's method or the continuation where Broyden's
    /// does not, at more cost). A band of a batch whose ball loads span a few entries so costs
    /// a few ball solves instead of the table's whole. Where one of them does not solve (its
    /// branch of steady states ended, docs/model-notes.md item 24) the whole table is solved
    /// again, as [`Evaluator::with_table_speed`] does: its lighter entries give the start on
    /// the other branch.
    pub fn with_table_speed_for(&self, speed_rad_s: f64, entries: &TableEntries) -> Self {
        let speed = table_speed_rad_s(&self.model, speed_rad_s);
        if self.model.oil().is_none() {
            return *self;
        }
        let mut out = *self;
        out.table.speed_rad_s = speed;
        if !out.table.carry(&self.model, &self.table, entries) {
            // An entry's branch of steady states ended (item 24): the whole table, whose
            // lighter entries give the start of the other branch. The entries just solved are
            // kept (solved at this speed), the others solved as from this table.
            let partial = out.table;
            out.table.carry(&self.model, &partial, &TableEntries::ALL);
        }
        out
    }

    /// The entries of the start table that the balls of the point `op` under `cond` start from
    /// (each ball on its flank as it is solved, turning forwards; see
    /// [`Evaluator::with_table_speed_for`]). Empty for a point the evaluator refuses.
    pub fn table_entries(&self, op: &OperatingPoint, cond: &Conditions) -> TableEntries {
        let mut out = TableEntries::default();
        if op.validate().is_err() || cond.validate().is_err() {
            return out;
        }
        let spec = self.model.spec();
        let eff = spec.extensions.effective_operating(op, cond);
        let loads = load::groups(&spec.geometry, eff.preload_n, eff.axial_load_n).loads;
        let z = f64::from(spec.geometry.balls_per_circle);
        let backwards = eff.speed_rad_s < 0.0;
        for &(nut_load, flank) in loads.iter().take(self.nuts) {
            if !(nut_load > 0.0) {
                continue;
            }
            let fi = balance::flank_index(if backwards { -flank } else { flank });
            for circle in 0..self.circles {
                let p = nut_load * self.fractions[circle].to_f64() / z;
                let pos = self.table.position(p);
                if pos.is_finite() {
                    let i = libm::floor(pos.clamp(0.0, (TABLE_LEN - 1) as f64)) as usize;
                    out.add(fi, i, (i + 1).min(TABLE_LEN - 1));
                }
            }
        }
        out
    }

    /// The screw speed whose films the start table's balls carry, rad/s (the spec's operating
    /// speed, at least the standstill speed, unless set by [`Evaluator::with_table_speed`]).
    pub fn table_speed_rad_s(&self) -> f64 {
        self.table.speed_rad_s
    }
}
