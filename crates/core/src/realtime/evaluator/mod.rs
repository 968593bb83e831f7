//! Evaluation for a control loop: the torque of [`Model`] in `f64` or `f32`, with no allocation,
//! warm-started from the previous calls and cold-started from a table of solved balls.
//!
//! [`Evaluator`] is built once from a model. It keeps, per flank, the load-independent factors
//! of the balance ([`balance::Constants`]) and a table of solved balls over a geometric grid of
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
//! the lean balance ([`balance::evaluate`], Eqs. 3-24), the balance at every ball's first start
//! evaluated for four f64 or eight f32 balls at once in SIMD lanes ([`Real::Wide`], each lane
//! the single ball's result to the bit), by Broyden's method on the inverse
//! Jacobian (one matrix-vector product a step, no linear solve) to the tolerance
//! [`Evaluator::tolerance`], and sums the torque (Eqs. 25-27 by the model's route, the model notes (docs/model-notes.md)
//! item 9). A warm start whose remembered inverse Jacobian stalls is retried once with a fresh
//! one there (finite differences, f64). A table start that stalls falls back to Newton's method
//! with a fresh Jacobian from each of the two entries around the load (nearest first), after
//! which the ball keeps the inverse of the Jacobian at its solution, then
//! to the model's continuation in f64 (a load outside the table, a ball that does not converge from
//! it), whose result is taken where the model takes it (a light ball, whose nearly degenerate
//! balance reaches no tight residual: see [`crate::screw::torque::ACCEPT_RESIDUAL`]). What stays in
//! f64: the table (at build), the split of the preload between the nuts (a scalar root) and the
//! extension terms of the spec.
//!
//! The rooms: this file holds the public API ([`Evaluator`]: build, support, the torque of a
//! call and its sum over the balls); `table.rs` the start table; `memory.rs` the warm-start memory
//! ([`EvalState`]); `lanes.rs` the balls of a call in groups of the SIMD lanes; `solver.rs` one
//! ball's solver steps (Broyden, Newton, the continuation, f32's check in f64); `stats.rs` what
//! the tests count (nothing outside them).

mod lanes;
mod memory;
mod solver;
mod stats;
mod table;
#[cfg(test)]
mod tests;

use crate::ball::balance::{self, Constants};
use crate::ball::kinematics::{self, JacobianStep};
use crate::ball::lubrication::BallFilms;
use crate::ball::setup::N;
use crate::contact::creep::standstill_factor;
use crate::error::Error;
use crate::input::extensions::Conditions;
use crate::input::screw::check_preload_for;
use crate::input::{ContactTheory, MAX_CIRCLES_PER_NUT, MAX_NUTS, OperatingPoint, Preload, ScrewSpec};
use crate::real::{Lanes, Real};
use crate::screw::load;
use crate::screw::torque::{Model, SolverState};
use lanes::{Ball, MAX_GROUP};
use table::{Entry, table_speed_rad_s};

pub use memory::EvalState;
pub use table::{CARRY_SPEED_RATIO, TABLE_FIRST_LOAD_N, TABLE_LEN, TABLE_RATIO, TableEntries};

/// Ball load (N) below which the evaluator hands the whole point to the model
/// ([`Model::torque_at`] from a fresh state), so that both give the same torque or the same
/// error. Light balls make the balance nearly degenerate (both raceway contacts in full slip,
/// README "Light balls"): there the model's continuation decides whether a physical state is
/// found at all (on DKFZD4012 it is not below about 2 N of preload, 0.04 N per ball), and a
/// start from the evaluator's table or memory could land on a state the model does not reach.
/// 0.5 N is 25 N of preload on DKFZD4012, above the balls of 0.03-0.2 N whose solutions are
/// ill-determined.
pub const LIGHT_BALL_N: f64 = 0.5;
/// Newton iterations of one solve in the evaluator.
const MAX_ITERATIONS: u32 = 40;
type Matrix<F> = [[F; N]; N];

/// Per nut and circle, a circle's friction torque by mechanism ([`MECHANISMS`]), N m.
pub(crate) type Groups<F> = [[[F; MECHANISMS]; MAX_CIRCLES_PER_NUT]; MAX_NUTS];

/// The mechanisms of a circle's friction torque, in the order of [`Groups`]: the raceway
/// contacts' creep and sliding, their rolling resistance (EHL and hysteresis), the ball-ball
/// contacts.
pub(crate) const MECHANISMS: usize = 3;

/// A model ready for the control loop in float type `F`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Evaluator<F: Real> {
    model: Model,
    /// The films' friction of every ball, with lubricated contacts.
    films: Option<BallFilms>,
    /// Per flank: index 0 for +1, 1 for -1.
    constants: [Constants<F>; 2],
    /// `constants` in every lane of [`Real::Wide`], per flank.
    wide: [Constants<F::Wide>; 2],
    table: [[Entry<F>; TABLE_LEN]; 2],
    table_ok: [[bool; TABLE_LEN]; 2],
    fractions: [F; MAX_CIRCLES_PER_NUT],
    /// The circle shares in f64 (the heaviest ball's load for the acceptance of light balls).
    shares: load::CircleShares,
    weights: [F; MAX_CIRCLES_PER_NUT],
    nuts: usize,
    circles: usize,
    balls_per_circle: F,
    tolerance: F,
    step: JacobianStep,
    /// The relative step of finite differences in f64 (the Jacobians an f32 evaluator takes in
    /// f64).
    step_f64: JacobianStep,
    /// 1 / ln([`TABLE_RATIO`]).
    per_log_ratio: f64,
    /// The smallest circle share of a nut's load.
    lightest_fraction: f64,
    /// Screw speed whose films the table's balls carry, rad/s ([`table_speed_rad_s`]).
    table_speed_rad_s: f64,
}

impl<F: Real> Evaluator<F> {
    /// Prepares `model` for the control loop: the constants of both flanks and the start table
    /// (about 100 ball solves in f64). The linear-saturated contact theory only: FASTSIM is an
    /// analysis option.
    pub fn new(model: &Model) -> Result<Self, Error> {
        let mut ev = Self::without_table(model)?;
        ev.fill_table();
        Ok(ev)
    }

    /// Whether the evaluator takes `spec`: [`Error::Unsupported`] naming the option it does not
    /// take (FASTSIM contacts; the four-point balls of an oversize-ball nut, which the model
    /// solves), else `Ok`. What [`Evaluator::new`] checks first.
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
        let empty = Entry { x: [F::zero(); N], slope: [F::zero(); N], inverse: [[F::zero(); N]; N], speed_rad_s: 0.0 };
        let setup = |flank: f64| Constants::new(&model.ball_setup_for(1.0, flank), approach);
        let js = kinematics::jacobian_step(&model.ball_setup_for(1.0, 1.0));
        let floor = F::JACOBIAN_STEP.to_f64();
        Ok(Self {
            model: *model,
            films: model.oil().map(|oil| BallFilms::new(&model.ball_setup_for(1.0, 1.0), &spec.lubricant, oil)),
            constants: [setup(1.0), setup(-1.0)],
            wide: [setup(1.0), setup(-1.0)].map(|c| Constants::gather(&[&c])),
            table: [[empty; TABLE_LEN]; 2],
            table_ok: [[false; TABLE_LEN]; 2],
            fractions: core::array::from_fn(|i| F::of(shares.load_fraction[i])),
            shares,
            weights: core::array::from_fn(|i| F::of(shares.weight[i])),
            nuts: groups.count,
            circles: groups.circles as usize,
            balls_per_circle: F::of(f64::from(g.balls_per_circle)),
            tolerance: F::TOLERANCE,
            step: JacobianStep { far: js.far.max(floor), near: js.near.max(floor), near_below: js.near_below },
            step_f64: js,
            per_log_ratio: 1.0 / libm::log(TABLE_RATIO),
            lightest_fraction: shares
                .load_fraction
                .iter()
                .take(groups.circles as usize)
                .fold(f64::INFINITY, |m, &f| m.min(f)),
            table_speed_rad_s: table_speed_rad_s(model, model.spec().operating.speed_rad_s),
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

    /// The drive torque (N m) at screw speed `speed_rad_s` (rad/s), preload `preload_n` (N) and
    /// axial load `axial_load_n` (N), by the model's torque route with the spec's extension
    /// terms at their default conditions.
    pub fn torque_nm(
        &self,
        speed_rad_s: F,
        preload_n: F,
        axial_load_n: F,
        state: &mut EvalState<F>,
    ) -> Result<F, Error> {
        self.torque_at_nm(speed_rad_s, preload_n, axial_load_n, &Conditions::default(), state)
    }

    /// [`Evaluator::torque_nm`] under `cond` (position, temperature, running time).
    pub fn torque_at_nm(
        &self,
        speed_rad_s: F,
        preload_n: F,
        axial_load_n: F,
        cond: &Conditions,
        state: &mut EvalState<F>,
    ) -> Result<F, Error> {
        let op = OperatingPoint {
            speed_rad_s: speed_rad_s.to_f64(),
            preload_n: preload_n.to_f64(),
            axial_load_n: axial_load_n.to_f64(),
        };
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
    fn ball_loads(&self, op: &OperatingPoint) -> Result<([(f64, f64); MAX_NUTS], f64), Error> {
        let spec = self.model.spec();
        check_preload_for(spec.geometry.preload, op.preload_n)?;
        let loads = load::groups(&spec.geometry, op.preload_n, op.axial_load_n).loads;
        let z64 = f64::from(spec.geometry.balls_per_circle);
        let p_max = load::heaviest_ball_load_n(&loads, self.nuts, &self.shares, self.circles, z64);
        self.model.check_static_capacity(p_max)?;
        Ok((loads, p_max))
    }

    /// Whether a loaded nut of `loads` (N, with its flank) carries a ball lighter than
    /// [`LIGHT_BALL_N`] (the model answers there).
    fn has_light_ball(&self, loads: &[(f64, f64)]) -> bool {
        let z64 = f64::from(self.model.spec().geometry.balls_per_circle);
        loads.iter().take(self.nuts).any(|&(l, _)| l > 0.0 && l * self.lightest_fraction / z64 < LIGHT_BALL_N)
    }

    /// The creep model's torque (with the axial term and the seals, as the model sums them) and
    /// its axial term F_a L / (2 pi), N m; `None` when a loaded ball is lighter than
    /// [`LIGHT_BALL_N`] (the model answers there). `groups`, when given, receives each circle's
    /// friction torque (all its balls, signed as the torque) by mechanism, N m, per nut and
    /// circle (0 for a circle without load; by the paper's Eq. (27) route all of it is counted
    /// as creep).
    pub(crate) fn creep_torque(
        &self,
        op: &OperatingPoint,
        speed: F,
        state: &mut EvalState<F>,
        mut groups: Option<&mut Groups<F>>,
    ) -> Result<Option<(F, F)>, Error> {
        if let Some(g) = groups.as_deref_mut() {
            *g = [[[F::zero(); MECHANISMS]; MAX_CIRCLES_PER_NUT]; MAX_NUTS];
        }
        let spec = self.model.spec();
        let (loads, p_max) = self.ball_loads(op)?;
        if self.has_light_ball(&loads) {
            return Ok(None);
        }
        let factor = F::of(standstill_factor(op.speed_rad_s, spec.friction.standstill_speed_rad_s));
        let backwards = speed < F::zero();
        let direction = if backwards { -F::one() } else { F::one() };
        let z = self.balls_per_circle;
        let film_speed = self.film_speed(op.speed_rad_s);
        let mut sum = F::zero();
        // The balls of the call in groups of the lanes (`Real::Wide`): each group's first
        // evaluations in one pass, then each ball's solve, in the balls' order.
        let lanes = <F::Wide as Lanes>::LANES.min(MAX_GROUP);
        let mut group: [Option<Ball<F>>; MAX_GROUP] = core::array::from_fn(|_| None);
        let mut count = 0;
        for (nut, &(nut_load, flank)) in loads.iter().enumerate().take(self.nuts) {
            // Solved turning forwards on the mirrored flank (see the module's documentation).
            let fi = balance::flank_index(if backwards { -flank } else { flank });
            let nut_load = F::of(nut_load);
            for circle in 0..self.circles {
                // A ball whose memory a ball of the group still has to use waits for the group.
                let taken = group[..count].iter().flatten().any(|b| b.fi == fi && b.circle == circle);
                if count == lanes || taken {
                    self.solve_group(&mut group[..count], state, direction, &mut groups, &mut sum)?;
                    count = 0;
                }
                let p = nut_load * self.fractions[circle] / z;
                if !(p > F::zero()) {
                    state.balls[fi][circle].stored = 0;
                    continue;
                }
                let memory = &state.balls[fi][circle];
                group[count] = Some(self.prepare(nut, circle, fi, p, p_max, film_speed.as_ref(), factor, op, memory));
                count += 1;
            }
        }
        self.solve_group(&mut group[..count], state, direction, &mut groups, &mut sum)?;
        let axial = F::of(self.model.axial_term_nm(op));
        let seals = F::of(self.model.seal_torque_nm(op.speed_rad_s));
        Ok(Some((axial + sum + seals, axial)))
    }
}
