//! The solver steps of one ball: Broyden's method on the lean balance (Eqs. 3-24) with the
//! remembered or tabled inverse Jacobian, a retry with a fresh Jacobian, Newton's method from the
//! table's entries, the model's continuation, and f32's check of a solution in f64
//! ([`Evaluator::solve_ball`] and the steps it takes).

use super::api::{Evaluator, MAX_ITERATIONS};
use super::lanes::{Ball, First, Wide};
use super::linear::{Matrix, convert, convert_matrix, invert, times, update_inverse};
use super::memory::BallMemory;
use super::stats;
use crate::ball::balance::{self, Constants, Load, Outcome};
use crate::ball::setup::N;
use crate::ball::solve::{self};
use crate::real::Real;
use crate::screw::train::Circuit;

/// Broyden steps of one lean solve before it gives way to Newton's method.
pub(super) const LEAN_ITERATIONS: u32 = 8;
/// Multiple of the tolerance below which a solve that stops improving has met the rounding
/// noise of the residual and stops there (f32, see [`Evaluator::tolerance`]).
pub(super) const STALL: f64 = 4.0;
/// Newton step (max norm over the unknowns, by the inverse Jacobian at the solution) above which
/// a solution within the tolerance is ill-determined: the balance of a light ball (0.03-0.2 N on
/// DKFZD4012) is nearly degenerate, a residual of 1e-9 there leaves steps of 1e-4 and an error of
/// 1e-6 in the torque, where well-determined balls leave steps below 1e-8. f64 only.
pub(super) const SETTLE_STEP: f64 = 1e-6;
/// Factor on the tolerance to which an ill-determined solution is solved on (Newton's method).
pub(super) const SETTLE_TIGHTEN: f64 = 1e-3;
/// Newton step in f64 (max norm over the unknowns) from a solution found in f32 above which it
/// is solved on in f64 ([`Evaluator::settle_in_f64`]). The unknowns are the ball's rates and
/// loads relative to their nominal values, of order one: a step of 1e-4 moves the torque by
/// about 1e-4 of one ball's share (measured: 5.7e-5 of the drag at worst over the balls of
/// `f32_where_balls_have_two_states`), within f32's stated 1e-4.
pub(super) const F32_SETTLE_STEP: f64 = 1e-4;
/// Fraction of [`F32_SETTLE_STEP`] below which the step in f32 alone clears a solution.
pub(super) const F32_PREFILTER: f64 = 0.25;
/// Newton step (max norm over the unknowns, in f32) within which a warm start whose residual
/// is within [`STALL`] times the tolerance (f32's rounding noise) is a solution without the
/// step ([`Evaluator::broyden`]): a tenth of [`F32_SETTLE_STEP`]. At [`F32_PREFILTER`] of it
/// (2.5e-5, what clears a solution in [`Evaluator::settle_in_f64`]) the f32 torque's worst
/// departure from the model over the default sweep doubled (3.0e-6 to 6.0e-6); at 1e-5 it
/// stays 3.0e-6, at 0.01 residuals a ball more on `warm_ramp`.
pub(super) const F32_START_STEP: f64 = 1e-5;
/// Whether the Newton step `step` is at most `bound` in every unknown (`all`: a NaN step
/// fails).
pub(super) fn step_within<F: Real>(step: &[F; N], bound: f64) -> bool {
    let bound = F::of(bound);
    step.iter().all(|e| e.abs() <= bound)
}

/// Weights of the residual's equations in the convergence test: every equation relative to
/// the nominal load Q. The friction-borne ones (force along t, the three moments) are scaled by
/// f Q in [`balance`] (which keeps Newton's steps well conditioned) and are weighted by f here.
/// Their rounding noise is that of the creep forces, whose stiffness amplifies the rounding of
/// the creepages (about 5e-4 of f Q in f32), while the normal-load equations carry the torque:
/// one tolerance on loads then serves both float types.
pub(super) fn weights<F: Real>(mu: F) -> [F; N] {
    [mu, F::one(), F::one(), mu, mu, mu, F::one()]
}

impl<F: Real> Evaluator<F> {
    /// Solves `ball` (constants `c`, and in f32 `c64`, the same in f64; load `p` on flank `fi`,
    /// turning forwards at its standstill factor) with its `memory`: by Broyden's method from
    /// its first start (the memory's, with the remembered inverse Jacobian, else with a fresh
    /// one; or the table's), where its group did not run it already ([`Evaluator::solve_group`]);
    /// else from the table; else by Newton's method from the
    /// table's entries around the load, nearest first; else by the model's continuation in f64.
    /// In f32 every solution is checked in f64 ([`Evaluator::settle_in_f64`]) and one that is no
    /// solution there gives way to the next start.
    /// Returns the ball evaluated at its solution, or `None` when nothing converges.
    pub(super) fn solve_ball(&self, ball: &Ball<F>, memory: &mut BallMemory<F>) -> Option<Outcome<F>> {
        let Ball { fi, p, accept, load: at, factor, speed_rad_s, first, evaluated, .. } = *ball;
        let (c, c64) = self.ball_constants(ball);
        let (c, c64) = (&c, c64.as_ref());
        let fk = at.factor;
        // f32: the Newton step from the solution where the check took it in f32 alone, for the
        // remembered solution below.
        let checked_step = core::cell::Cell::new(None);
        let settle = |solved: Option<([F; N], Outcome<F>)>, inverse: &mut Matrix<F>| match c64 {
            Some(c64) => solved.and_then(|found| self.settle_in_f64(c, c64, &at, found, inverse, &checked_step)),
            None => solved,
        };
        // The inverse Jacobian is kept (and updated) in the memory throughout.
        // Dry contacts' solutions do not depend on the speed (the rate unknowns are per unit
        // speed); lubricated ones do through the films, in f32 as in f64 ([`Evaluator::start_speed`]).
        // (f32 extrapolated in the load alone while its remembered solutions were not taken a
        // step further on: their rounding noise, amplified, made the quadratic in the speed
        // worse than the last solution. With the step, on DKFZD4012 at 2000 N, 100-150 rpm by
        // 0.25 rpm a call, the quadratic takes 12.6 residuals a call against 17.0 and brings
        // f32's mean departure from f64 from 1.5e-6 to 1.3e-7.)
        let film_speed = self.start_speed(speed_rad_s);
        let (mut solved, mut from_table) = (None, false);
        match first {
            First::Warm(start) => {
                let warm = self.broyden(c, &at, start, evaluated, &mut memory.inverse);
                solved = settle(warm, &mut memory.inverse).or_else(|| {
                    memory.stats.refresh();
                    let refreshed = self.broyden_refreshed(c, c64, &at, start, &mut memory.inverse);
                    settle(refreshed, &mut memory.inverse)
                });
            }
            First::Table(start) => {
                // The table's inverse Jacobian at the load (the start is the one prepared).
                let _ = self.table.start(fi, p, Some(&mut memory.inverse));
                let first = self.broyden(c, &at, start, evaluated, &mut memory.inverse);
                (solved, from_table) = (settle(first, &mut memory.inverse), true);
            }
            First::None => from_table = true,
        }
        if solved.is_none()
            && !from_table
            && let Some(start) = self.table.start(fi, p, Some(&mut memory.inverse))
        {
            let start = solve::scale_friction_terms(&start, fk);
            let first = self.broyden(c, &at, start, None, &mut memory.inverse);
            solved = settle(first, &mut memory.inverse);
        }
        if solved.is_none() {
            memory.stats.fallback();
            // Newton's method from each entry around the load, nearest first, not from the
            // interpolated start: where Broyden's method failed from that, the two entries
            // mostly lie on different steady states (docs/model-notes.md item 24), and the
            // interpolated start on neither. Newton's method from it took its 40 iterations
            // in vain at about two balls in three there (DKFZD4012 at 2250 rpm, balls of
            // 10-16 N), and where it converged it found another state than the model's cold
            // solve more often than the entries do: over 20,000 random points at 10-3000 rpm
            // through the batch, 101 points beyond 1e-8 of the model with it, 59 without, and
            // 46.5 against 22.3 us a point.
            for (x, inverse) in self.table.neighbours(fi, p).into_iter().flatten() {
                memory.inverse = inverse;
                let start = solve::scale_friction_terms(&x, fk);
                let next = self.newton(c, &at, start, self.tolerance, &mut memory.inverse);
                solved = settle(next, &mut memory.inverse);
                if solved.is_some() {
                    break;
                }
            }
        }
        if solved.is_none() {
            memory.stats.fallback();
            solved = self.continuation(fi, &at, c, speed_rad_s, accept, &ball.train, &mut memory.inverse);
        }
        let Some((mut x, mut outcome)) = solved else {
            memory.stored = 0;
            return None;
        };
        // Remember the solution one Newton step further on: at no cost of a residual it is
        // well inside the tolerance, so extrapolating from it does not amplify the tolerance.
        // In f32 too, where the residual at the solution is about its rounding noise: the step
        // still halves the remembered solutions' error (on `warm_ramp`, the mean departure of
        // the f32 torque from f64's fell from 1.7e-7 to 0.8e-7), which the quadratic start
        // would amplify. Only the step that cleared the solution in f32 (`settle_in_f64`): where
        // the check went on in f64, or the solution came from Newton's method or the
        // continuation, the inverse at hand may not be the one at the solution.
        let remembered = if F::FINITE_DIFFERENCES {
            let mut step = times(&memory.inverse, &outcome.residual);
            if !(step.iter().fold(F::zero(), |m, v| m.max(v.abs())) <= F::of(SETTLE_STEP)) {
                // Ill-determined (see [`SETTLE_STEP`]): solved on to a tighter tolerance.
                let tight = self.tolerance * F::of(SETTLE_TIGHTEN);
                if let Some(settled) = self.newton(c, &at, x, tight, &mut memory.inverse) {
                    (x, outcome) = settled;
                    step = [F::zero(); N];
                }
            }
            core::array::from_fn(|i| x[i] - step[i])
        } else {
            match checked_step.get() {
                Some(step) => core::array::from_fn(|i| x[i] - step[i]),
                None => x,
            }
        };
        memory.push(remembered, p, film_speed, fk);
        if factor >= fk {
            return Some(outcome);
        }
        let load = Load { factor, ..at };
        Some(balance::evaluate(c, &solve::scale_to_factor(&x, factor), &load))
    }

    /// Broyden's method on the lean balance from `start` with the inverse Jacobian `inverse`
    /// (updated in place): the solution and the ball evaluated there, or `None` when the steps
    /// run out or a step fails to quarter the residual's norm above [`STALL`] times the
    /// tolerance. Below that a step that fails is the rounding noise of the residual (f32): the
    /// better of the two points is the solution. In f32 a point below it whose Newton step is
    /// within [`F32_START_STEP`] is a solution without the step: f32's
    /// residual at the exact solution (the f64 one rounded) exceeds the tolerance at about a
    /// third of DKFZD4012's balls, so a warm start within the noise took a step that gained
    /// nothing (on `warm_ramp` every ball took two residuals; now 1.3-1.5). A solution that
    /// is not physical ([`Constants::check_state`]) is `None`. `evaluated` is the ball at
    /// `start` where it is already evaluated (the lanes of [`Evaluator::solve_group`]).
    pub(super) fn broyden(
        &self,
        c: &Constants<F>,
        load: &Load<F>,
        start: [F; N],
        evaluated: Option<Outcome<F>>,
        inverse: &mut Matrix<F>,
    ) -> Option<([F; N], Outcome<F>)> {
        // Only a physical state is a solution (see `ball::setup::check_state`).
        self.broyden_steps(c, load, start, evaluated, inverse).filter(|(x, _)| c.check_state(x).is_ok())
    }

    /// [`Evaluator::broyden`] from the warm start `start` again with the inverse of a fresh
    /// Jacobian there (finite differences, N + 1 residuals; written to `inverse`), where the
    /// remembered inverse failed: carried by Broyden's updates over many calls, it goes stale in
    /// the directions the steps did not explore while the films' friction follows the speed (a
    /// slow sinusoidal motion, 1 % of speed a call, fails a first step from a good start every
    /// few calls at 1-10 rpm on DKFZD4012), and the table's Newton fallback costs ten times
    /// more. In f32, whose finite differences drown in the rounding noise, the Jacobian is taken
    /// in f64 with the ball's constants in f64 (`c64`, given in f32), and its inverse rounded.
    pub(super) fn broyden_refreshed(
        &self,
        c: &Constants<F>,
        c64: Option<&Wide<'_>>,
        load: &Load<F>,
        start: [F; N],
        inverse: &mut Matrix<F>,
    ) -> Option<([F; N], Outcome<F>)> {
        if let Some(wide) = c64 {
            let c64 = &wide.constants();
            let x: [f64; N] = core::array::from_fn(|i| start[i].to_f64());
            let l64 = load.to_f64();
            let r = balance::evaluate(c64, &x, &l64).residual;
            let res = solve::weighted_max_abs(&r, &weights(c64.residual_mu()));
            let mut f = |xx: &[f64; N]| balance::evaluate(c64, xx, &l64).residual;
            *inverse = convert_matrix(&invert(&solve::jacobian(&x, &r, self.step_f64.at(res), &mut f))?);
            return self.broyden(c, load, start, None, inverse);
        }
        let r = balance::evaluate(c, &start, load).residual;
        let res = solve::weighted_max_abs(&r, &weights(c.residual_mu()));
        let mut f = |xx: &[F; N]| balance::evaluate(c, xx, load).residual;
        *inverse = invert(&solve::jacobian(&start, &r, self.step.at(res), &mut f))?;
        self.broyden(c, load, start, None, inverse)
    }

    /// The check in f64 of a solution `found` in f32 with constants `c` (`c64` the same in
    /// f64) and inverse Jacobian `inverse`. f32's rounding noise in the friction-borne equations
    /// is about the tolerance, so where a ball's balance is ill-conditioned (near a change of
    /// steady state, docs/model-notes.md item 24) a residual within the tolerance can leave the
    /// torque 1e-4 and more off, or lie in a valley of the residual that holds no solution.
    /// Newton's step from the solution tells: when it is at most [`F32_SETTLE_STEP`] (in f32
    /// at most [`F32_PREFILTER`] of it, else in f64 with `inverse` rounded up) the solution
    /// stands; else Newton's method in f64 (the model's solver, finite differences) from it
    /// gives the solution, rounded to `F`, or `None` when it finds none (a valley: the caller
    /// tries its next start). In the common case one matrix-vector product in f32, whose step
    /// goes to `checked_step` (`None` where the check goes on in f64) for the remembered
    /// solution ([`Evaluator::solve_ball`]).
    pub(super) fn settle_in_f64(
        &self,
        c: &Constants<F>,
        c64: &Wide<'_>,
        load: &Load<F>,
        found: ([F; N], Outcome<F>),
        inverse: &mut Matrix<F>,
        checked_step: &core::cell::Cell<Option<[F; N]>>,
    ) -> Option<([F; N], Outcome<F>)> {
        let x = found.0;
        // The same step in f32 first: it differs from f64's by the rounding of the residual,
        // which is small beside a step that matters (a step in f64 above F32_SETTLE_STEP had
        // one in f32 of at least 0.77 times its size, over 31,000 solves of random points).
        let step = times(inverse, &found.1.residual);
        if step_within(&step, F32_PREFILTER * F32_SETTLE_STEP) {
            checked_step.set(Some(step));
            return Some(found);
        }
        checked_step.set(None);
        let c64 = &c64.constants();
        let l64 = load.to_f64();
        let mut y: [f64; N] = core::array::from_fn(|i| x[i].to_f64());
        let r = balance::evaluate(c64, &y, &l64).residual;
        let h: Matrix<f64> = core::array::from_fn(|i| core::array::from_fn(|j| inverse[i][j].to_f64()));
        let step = times(&h, &r);
        if step.iter().all(|e| e.abs() <= F32_SETTLE_STEP) {
            return Some(found);
        }
        let mut carried = None;
        let (_, res) = solve::newton(
            &mut y,
            |yy| balance::evaluate(c64, yy, &l64).residual,
            &weights(c64.residual_mu()),
            <f64 as Real>::TOLERANCE,
            MAX_ITERATIONS,
            self.step_f64,
            &mut carried,
            None,
        );
        if !(res <= <f64 as Real>::TOLERANCE) {
            return None;
        }
        let x = convert(&y);
        c.check_state(&x).ok()?;
        Some((x, balance::evaluate(c, &x, load)))
    }

    /// The steps of [`Evaluator::broyden`], whose end state is not yet checked.
    pub(super) fn broyden_steps(
        &self,
        c: &Constants<F>,
        load: &Load<F>,
        start: [F; N],
        evaluated: Option<Outcome<F>>,
        inverse: &mut Matrix<F>,
    ) -> Option<([F; N], Outcome<F>)> {
        let o = match evaluated {
            Some(o) => o,
            None => {
                stats::residual();
                balance::evaluate(c, &start, load)
            }
        };
        let w = weights(c.residual_mu());
        let (mut x, mut o) = (start, o);
        let mut res = solve::weighted_max_abs(&o.residual, &w);
        for _ in 0..LEAN_ITERATIONS {
            if res <= self.tolerance {
                return Some((x, o));
            }
            if !res.is_finite() {
                return None;
            }
            let step = times(inverse, &o.residual);
            if !F::FINITE_DIFFERENCES && res <= F::of(STALL) * self.tolerance && step_within(&step, F32_START_STEP) {
                // f32: the residual is at its rounding noise and the step to the solution
                // below what the check in f64 clears (`settle_in_f64`).
                return Some((x, o));
            }
            let xn: [F; N] = core::array::from_fn(|i| x[i] - step[i]);
            let on = balance::evaluate(c, &xn, load);
            stats::residual();
            let res_n = solve::weighted_max_abs(&on.residual, &w);
            if res_n <= self.tolerance {
                // Done: the inverse Jacobian here serves the next call as it is.
                return Some((xn, on));
            }
            if !(solve::norm2(&on.residual) <= F::of(0.25) * solve::norm2(&o.residual)) {
                let stall = F::of(STALL) * self.tolerance;
                return if res_n <= res && res_n <= stall {
                    Some((xn, on))
                } else if res <= stall {
                    Some((x, o))
                } else {
                    None
                };
            }
            let dx: [F; N] = core::array::from_fn(|i| -step[i]);
            let dr: [F; N] = core::array::from_fn(|i| on.residual[i] - o.residual[i]);
            update_inverse(inverse, &dx, &dr);
            (x, o, res) = (xn, on, res_n);
        }
        None
    }

    /// Newton's method on the lean balance from `start` (the model's solver: backtracking and
    /// Levenberg-Marquardt), its Jacobian by finite differences in f64 and the inverse of
    /// `inverse` in f32, to the tolerance `tolerance`: the solution and the ball there (`None`
    /// when it is not physical, [`Constants::check_state`]). `inverse` becomes, in f64, the
    /// inverse of the Jacobian at the solution (finite differences, N more residuals), in f32
    /// that of Newton's last Jacobian. The solver's last Jacobian is no Jacobian at the solution:
    /// it is taken where the residual was last too large for a carried one (a start from the
    /// table, whose films are those of the spec's speed, begins at a residual of about 0.05 at
    /// low speed) and carried on by Broyden's updates, which are exact only along the steps
    /// taken. Its inverse failed the next call's first step at a slightly different speed (at
    /// 1-30 rpm on DKFZD4012), and every following call fell back here in turn.
    pub(super) fn newton(
        &self,
        c: &Constants<F>,
        load: &Load<F>,
        start: [F; N],
        tolerance: F,
        inverse: &mut Matrix<F>,
    ) -> Option<([F; N], Outcome<F>)> {
        let fresh = if F::FINITE_DIFFERENCES { None } else { invert(inverse) };
        let mut x = start;
        let mut last: Option<([F; N], Outcome<F>)> = None;
        let mut jacobian = None;
        let (_, res) = solve::newton(
            &mut x,
            |xx| {
                let o = balance::evaluate(c, xx, load);
                last = Some((*xx, o));
                o.residual
            },
            &weights(c.residual_mu()),
            tolerance,
            MAX_ITERATIONS,
            self.step,
            &mut jacobian,
            fresh.as_ref(),
        );
        if !(res <= tolerance) || c.check_state(&x).is_err() {
            return None;
        }
        let o = match last {
            Some((y, o)) if y == x => o,
            _ => balance::evaluate(c, &x, load),
        };
        let last = if F::FINITE_DIFFERENCES {
            let mut f = |xx: &[F; N]| balance::evaluate(c, xx, load).residual;
            Some(solve::jacobian(&x, &o.residual, F::of(self.step.near), &mut f))
        } else {
            jacobian
        };
        if let Some(h) = last.as_ref().and_then(invert) {
            *inverse = h;
        }
        Some((x, o))
    }

    /// The model's own solve in f64 (continuation), where the table gives no start that
    /// converges; polished in `F`. `inverse` becomes the inverse Jacobian at the solution.
    /// Accepted as the model accepts it, up to the residual `accept`: where the balance of a
    /// light ball is nearly degenerate no solve reaches the tolerance, and the model takes
    /// [`crate::screw::model::ACCEPT_RESIDUAL`], or [`crate::screw::model::LIGHT_BALL_RESIDUAL`] for a ball
    /// below [`crate::screw::model::LIGHT_BALL_SHARE`] of the heaviest ball's load.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn continuation(
        &self,
        fi: usize,
        load: &Load<F>,
        c: &Constants<F>,
        speed_rad_s: f64,
        accept: f64,
        train: &Option<Circuit>,
        inverse: &mut Matrix<F>,
    ) -> Option<([F; N], Outcome<F>)> {
        let flank = if fi == 0 { 1.0 } else { -1.0 };
        let (mut setup, _) =
            self.model.ball_setup_at(load.axial_load_n.to_f64(), flank, speed_rad_s, load.factor.to_f64());
        if let Some(t) = train {
            // Solved turning forwards (the mirrored flank where the screw turns backwards).
            t.apply(&mut setup, true);
        }
        let (x, rep) = solve::solve(&setup, None, 1.0, load.factor.to_f64());
        if !(rep.residual <= accept.max(self.tolerance.to_f64())) {
            return None;
        }
        let y = convert(&x);
        *inverse = convert_matrix(&invert(&solve::balance_jacobian(&setup, &x))?);
        // Polish in F (the f64 solution rounded may sit just above the tolerance).
        self.newton(c, load, y, self.tolerance, inverse)
            .or_else(|| Some((y, balance::evaluate(c, &y, load))))
            .filter(|(x, _)| c.check_state(x).is_ok())
    }
}
