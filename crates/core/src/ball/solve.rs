//! The solvers of one ball's balance ([`crate::ball::balance`], docs/model-notes.md item 11):
//! Newton's method with its Jacobians, the continuation that selects the physical branch, warm
//! and predicted starts.
//!
//! With both raceway contacts saturated at the same f Q the balance is degenerate (a family of
//! attitudes satisfies it). The physical branch is selected by continuation in the friction
//! coefficient: with the forces linear (Kalker) the kinematic balance has one solution; the
//! coefficient is then lowered step by step to the spec's value, each solve starting from the
//! last. Newton's method (finite-difference Jacobian, backtracking, Levenberg-Marquardt fallback
//! where the Jacobian is singular) reports its iterations and final residual.

use crate::ball::balance::{self, Constants, Load};
use crate::ball::report::{BallState, RacewayState, ball_state};
use crate::ball::setup::{self, BallSetup, MAX_ITERATIONS, MIN_SOLVE_FACTOR, N, TOLERANCE, Unknowns};
use crate::contact::creep::direction;
use crate::input::ContactTheory;
use crate::real::Real;

/// Pure-rolling estimate of the ball's motion, the start of the continuation.
pub fn rolling_guess(s: &BallSetup) -> Unknowns {
    let beta = s.contact_angle_rad;
    // Epicyclic estimate: the centre moves at half the screw's surface speed at its contact.
    let orbit = setup::rolling_orbit_ratio(s);
    let (sb, cb) = (libm::sin(beta), libm::cos(beta));
    // omega = (v_c / r_b) (u0 x t); in (t, n, b) with u0 = cb n + flank sb b: u0 x t = flank sb n - cb b.
    let w = setup::rolling_spin(s);
    [0.0, w * s.flank * sb, -w * cb, orbit, 1.0, 1.0, 0.0]
}

/// Outcome of a solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveReport {
    /// Newton iterations (all continuation steps included).
    pub iterations: u32,
    /// Final scaled residual, max norm.
    pub residual: f64,
    /// Continuation steps taken (0 for a warm start).
    pub continuation_steps: u32,
}

pub(crate) fn max_abs<F: Real, const M: usize>(r: &[F; M]) -> F {
    // NaN counts as infinitely large.
    r.iter().fold(F::zero(), |m, &v| if !v.is_finite() { F::of(f64::INFINITY) } else { m.max(v.abs()) })
}

/// Max norm of the residual `r` weighted by `weights` (NaN counts as infinitely large).
pub(crate) fn weighted_max_abs<F: Real, const M: usize>(r: &[F; M], weights: &[F; M]) -> F {
    let mut m = F::zero();
    for (&v, &k) in r.iter().zip(weights) {
        let v = v * k;
        if !v.is_finite() {
            return F::of(f64::INFINITY);
        }
        m = m.max(v.abs());
    }
    m
}

pub(crate) fn norm2<F: Real, const M: usize>(r: &[F; M]) -> F {
    r.iter().fold(F::zero(), |acc, &v| acc + v * v)
}

/// Solves a x = b by Gaussian elimination with partial pivoting; `None` when singular.
pub(crate) fn solve_linear<F: Real, const M: usize>(mut a: [[F; M]; M], mut b: [F; M]) -> Option<[F; M]> {
    for col in 0..M {
        let mut piv = col;
        for row in col + 1..M {
            if a[row][col].abs() > a[piv][col].abs() {
                piv = row;
            }
        }
        if !(a[piv][col].abs() > F::zero()) || !a[piv][col].is_finite() {
            return None;
        }
        a.swap(col, piv);
        b.swap(col, piv);
        for row in col + 1..M {
            let k = a[row][col] / a[col][col];
            if k != F::zero() {
                for c in col..M {
                    let v = a[col][c];
                    a[row][c] -= k * v;
                }
                let v = b[col];
                b[row] -= k * v;
            }
        }
    }
    let mut x = [F::zero(); M];
    for row in (0..M).rev() {
        let mut s = b[row];
        for c in row + 1..M {
            s -= a[row][c] * x[c];
        }
        x[row] = s / a[row][row];
    }
    if x.iter().all(|v| v.is_finite()) { Some(x) } else { None }
}

/// Largest starting residual (scaled, max norm) at which Newton's method starts from a
/// Jacobian brought in from a previous solve: a warm start from a nearby operating point
/// begins at about 1e-2 (DKFZD4012, 0.5 % change of load); from farther, a Jacobian carried
/// over takes more solves to the cold fallback than it saves.
const CARRY_RESIDUAL: f64 = 0.1;

/// Finite-difference Jacobian of `f` at `x` (where `f(x) = r`) with relative step `rel_step`:
/// M evaluations.
pub(crate) fn jacobian<F: Real, const M: usize>(
    x: &[F; M],
    r: &[F; M],
    rel_step: F,
    f: &mut impl FnMut(&[F; M]) -> [F; M],
) -> [[F; M]; M] {
    let mut jac = [[F::zero(); M]; M];
    for j in 0..M {
        let h = rel_step * x[j].abs().max(F::of(1e-2));
        let mut xp = *x;
        xp[j] += h;
        let rp = f(&xp);
        for i in 0..M {
            jac[i][j] = (rp[i] - r[i]) / h;
        }
    }
    jac
}

/// Broyden's rank-one update of `jac` after the step `dx` changed the residual by `dr`:
/// J += (dr - J dx) dx^T / (dx . dx).
fn broyden_update<F: Real, const M: usize>(jac: &mut [[F; M]; M], dx: &[F; M], dr: &[F; M]) {
    let dd = norm2(dx);
    if !(dd > F::zero()) {
        return;
    }
    for i in 0..M {
        let jdx = (0..M).fold(F::zero(), |acc, k| acc + jac[i][k] * dx[k]);
        let c = (dr[i] - jdx) / dd;
        for k in 0..M {
            jac[i][k] += c * dx[k];
        }
    }
}

/// Newton's method on M unknowns with backtracking, and a Levenberg-Marquardt step where
/// Newton's step does not reduce the residual.
///
/// The Jacobian is taken by finite differences (M residuals), then carried from step to step
/// by Broyden's rank-one update (no extra residual) as long as each step at least halves the
/// residual norm; otherwise, and whenever a step with the carried Jacobian fails, it is taken
/// afresh. The fallback to Levenberg-Marquardt uses a fresh Jacobian only. `carried` brings a
/// Jacobian in (e.g. from the previous solve of the same ball) and takes the last one out.
/// `fresh_jacobian`, when given, stands in for the finite differences (in f32 they drown in the
/// rounding noise of the friction-borne equations).
#[allow(clippy::too_many_arguments)]
pub(crate) fn newton<F: Real, const M: usize>(
    x: &mut [F; M],
    mut f: impl FnMut(&[F; M]) -> [F; M],
    weights: &[F; M],
    tol: F,
    max_iter: u32,
    rel_step: JacobianStep,
    carried: &mut Option<[[F; M]; M]>,
    fresh_jacobian: Option<&[[F; M]; M]>,
) -> (u32, F) {
    let mut r = f(x);
    if max_abs(&r) > F::of(CARRY_RESIDUAL) {
        // Far from the solution a Jacobian from elsewhere leads astray: start afresh.
        *carried = None;
    }
    let weighted = |r: &[F; M]| weighted_max_abs(r, weights);
    let mut it = 0;
    while it < max_iter {
        let res = weighted(&r);
        if res <= tol || !res.is_finite() {
            return (it, res);
        }
        it += 1;
        let fresh = carried.is_none();
        let mut jac = match carried.take() {
            Some(j) => j,
            None => match fresh_jacobian {
                Some(j) => *j,
                None => jacobian(x, &r, rel_step.at(res), &mut f),
            },
        };
        let n0 = norm2(&r);
        let mut accepted = None;
        if let Some(step) = solve_linear(jac, r) {
            let mut lambda = F::one();
            for _ in 0..12 {
                let mut xn = *x;
                for j in 0..M {
                    xn[j] -= lambda * step[j];
                }
                let rn = f(&xn);
                // A carried Jacobian must earn its keep: its full step has to halve the
                // residual norm, else the Jacobian is taken afresh.
                // A step that reaches the tolerance is taken whatever the norm says (in f32 the
                // norm of the friction-borne equations stalls at their rounding noise).
                if weighted(&rn) <= tol || norm2(&rn) < if fresh { n0 } else { F::of(0.25) * n0 } {
                    accepted = Some((xn, rn));
                    break;
                }
                if !fresh {
                    break;
                }
                lambda *= F::of(0.5);
            }
        }
        if accepted.is_none() && !fresh {
            // Retry this iteration with a fresh Jacobian (not counted twice).
            it -= 1;
            continue;
        }
        if accepted.is_none() {
            // Levenberg-Marquardt: (J^T J + mu I) step = J^T r.
            let mut jtj = [[F::zero(); M]; M];
            let mut g = [F::zero(); M];
            let mut dmax = F::zero();
            for a in 0..M {
                for b in 0..M {
                    jtj[a][b] = (0..M).fold(F::zero(), |acc, k| acc + jac[k][a] * jac[k][b]);
                }
                g[a] = (0..M).fold(F::zero(), |acc, k| acc + jac[k][a] * r[k]);
                dmax = dmax.max(jtj[a][a]);
            }
            let mut mu = F::of(1e-6) * dmax.max(F::TINY);
            for _ in 0..20 {
                let mut a = jtj;
                for (k, row) in a.iter_mut().enumerate() {
                    row[k] += mu;
                }
                if let Some(step) = solve_linear(a, g) {
                    let mut xn = *x;
                    for j in 0..M {
                        xn[j] -= step[j];
                    }
                    let rn = f(&xn);
                    if norm2(&rn) < n0 {
                        accepted = Some((xn, rn));
                        break;
                    }
                }
                mu *= F::of(10.0);
            }
        }
        let Some((xn, rn)) = accepted else { break };
        if norm2(&rn) <= F::of(0.25) * n0 {
            let mut dx = [F::zero(); M];
            let mut dr = [F::zero(); M];
            for k in 0..M {
                dx[k] = xn[k] - x[k];
                dr[k] = rn[k] - r[k];
            }
            broyden_update(&mut jac, &dx, &dr);
            *carried = Some(jac);
        }
        *x = xn;
        r = rn;
    }
    (it, weighted(&r))
}

/// Relative steps of the finite-difference Jacobian: `far` while the scaled residual is above
/// `near_below`, `near` below it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct JacobianStep {
    pub(crate) far: f64,
    pub(crate) near: f64,
    pub(crate) near_below: f64,
}

impl JacobianStep {
    /// The relative step at the scaled residual `res`: `far` above `near_below`, else `near`.
    pub(crate) fn at<F: Real>(&self, res: F) -> F {
        F::of(if res > F::of(self.near_below) { self.far } else { self.near })
    }
}

/// The balance is strongly curved where a contact is deep in full slip, so near the solution
/// the truncation error of a forward difference dominates down to steps of about 1e-9 for the
/// smooth linear-saturated law (a step of 1e-8 takes a warm solve from 6 Newton iterations to
/// 4); far from it (a warm start from twice or half the load) the step of 1e-7 is the robust
/// one. FASTSIM's forces come from a grid and are only piecewise smooth: 1e-7 throughout.
pub(crate) fn jacobian_step(s: &BallSetup) -> JacobianStep {
    match s.contact_theory {
        ContactTheory::LinearSaturated => JacobianStep { far: 1e-7, near: 1e-8, near_below: 1e-3 },
        ContactTheory::Fastsim => JacobianStep { far: 1e-7, near: 1e-7, near_below: 0.0 },
    }
}

/// Solves the full balance (7 unknowns) from `x`.
pub fn solve_full(s: &BallSetup, x: &mut Unknowns, speed: f64, factor: f64) -> (u32, f64) {
    solve_carrying(s, x, speed, factor, &mut None)
}

/// Jacobian of one ball's balance with respect to its unknowns (scaled residuals).
pub type Jacobian = [[f64; N]; N];

/// [`solve_full`] starting from the Jacobian in `jacobian` (when there is one) and leaving the
/// last one there.
fn solve_carrying(
    s: &BallSetup,
    x: &mut Unknowns,
    speed: f64,
    factor: f64,
    jacobian: &mut Option<Jacobian>,
) -> (u32, f64) {
    let step = jacobian_step(s);
    let mut solve = |f: &mut dyn FnMut(&Unknowns) -> Unknowns| {
        newton(x, f, &[1.0; N], TOLERANCE, MAX_ITERATIONS, step, jacobian, None)
    };
    // The lean form of the same balance (the ball-ball approach only enters Eq. 27).
    let c = Constants::new(s, 0.0);
    let (it, res) = if s.contact_theory == ContactTheory::Fastsim {
        solve(&mut |xx| ball_state(s, xx, speed, factor).residual)
    } else {
        let load = Load { axial_load_n: s.axial_load_n, direction: direction(speed), factor };
        solve(&mut |xx| balance::evaluate(&c, xx, &load).residual)
    };
    // A state that is not physical is no solution, whatever its residual (see `setup`): every
    // caller then goes on as for a solve that did not converge.
    if c.check_state(x).is_err() { (it, f64::INFINITY) } else { (it, res) }
}

/// The Jacobian of the balance of `s` (lean form, linear-saturated contacts) at `x` by forward
/// differences with the near step of [`jacobian_step`], at unit speed above standstill.
pub(crate) fn balance_jacobian(s: &BallSetup, x: &Unknowns) -> Jacobian {
    let c = Constants::new(s, 0.0);
    let load = Load { axial_load_n: s.axial_load_n, direction: 1.0, factor: 1.0 };
    let mut f = |xx: &Unknowns| balance::evaluate(&c, xx, &load).residual;
    let r = f(x);
    jacobian(x, &r, jacobian_step(s).near, &mut f)
}

/// Largest raceway-contact utilisation F_lin / (f Q) of a state.
fn utilisation(st: &BallState) -> f64 {
    let u = |c: &RacewayState| {
        let f = &c.force;
        let m = libm::sqrt(f.linear_e_n * f.linear_e_n + f.linear_f_n * f.linear_f_n);
        if c.friction_bound_n > 0.0 { m / c.friction_bound_n } else { 0.0 }
    };
    u(&st.screw).max(u(&st.nut))
}

/// Utilisation below which the contacts count as linear at the start of the continuation.
const LINEAR_UTILISATION: f64 = 0.05;

/// Solves one ball from a cold start by continuation (docs/model-notes.md item 11).
///
/// The notes lower the friction coefficient from a value where every contact is linear to the
/// spec's. For the friction-only equations (force along t, the three moments) this is the same
/// path as raising the creep stiffness G by a factor kappa from a small value to 1 at the spec's
/// f: both move the contacts' utilisation kappa F_lin / (f Q) along the same saturation curve,
/// and the balance is homogeneous in the friction forces. Continuing in kappa keeps the friction
/// forces below f Q throughout, so the normal loads and the tilt of the contact normals (which
/// carry the lateral friction) stay physical at every step, and the full balance (7 unknowns)
/// is solved at every step.
pub fn solve_cold(s: &BallSetup, speed: f64, factor: f64) -> (Unknowns, SolveReport) {
    let (x, rep) = solve_cold_here(s, speed, factor);
    let lubricated = s.has_rolling_resistance();
    if rep.residual <= TOLERANCE || !lubricated {
        return (x, rep);
    }
    // At the fold itself (docs/model-notes.md item 22) neither branch is reached from here:
    // from a ball a little lighter or heavier, solved cold, by continuation in the load.
    let fk = factor.max(MIN_SOLVE_FACTOR);
    let mut iterations = rep.iterations;
    let mut steps = rep.continuation_steps;
    for ratio in [0.8, 1.25] {
        let mut near = *s;
        near.axial_load_n = s.axial_load_n * ratio;
        let (mut y, r) = solve_cold_here(&near, speed, factor);
        iterations += r.iterations;
        steps += r.continuation_steps;
        if !(r.residual <= TOLERANCE) {
            continue;
        }
        let (it, res, st) = continue_load(s, &mut y, near.axial_load_n, s.axial_load_n, speed, fk);
        iterations += it;
        steps += st;
        if res <= TOLERANCE {
            return (y, SolveReport { iterations, residual: res, continuation_steps: steps });
        }
    }
    (x, SolveReport { iterations, residual: rep.residual, continuation_steps: steps })
}

/// [`solve_cold`] from this ball's own rolling state only.
fn solve_cold_here(s: &BallSetup, speed: f64, factor: f64) -> (Unknowns, SolveReport) {
    let fk = factor.max(MIN_SOLVE_FACTOR);
    let mut x = rolling_guess(s);
    // The rolling resistance of lubricated contacts joins after the creep stiffness, by a
    // continuation of its own from a hundredth: with it the balance has a second branch at
    // high speed (the ball turning about another axis), and only this path stays on the one
    // that continues the dry ball's.
    let rolling = [s.screw.friction, s.nut.friction];
    let lubricated = s.has_rolling_resistance();
    let scaled = |sk: &mut BallSetup, v: f64| {
        for (race, f) in [&mut sk.screw, &mut sk.nut].into_iter().zip(rolling) {
            race.friction.rolling_resistance_ehl_n = v * f.rolling_resistance_ehl_n;
            race.friction.rolling_resistance_hysteresis_n = v * f.rolling_resistance_hysteresis_n;
        }
    };
    let mut sd = *s;
    if lubricated {
        scaled(&mut sd, RR_START);
    }
    // Utilisation of the contacts at pure rolling sets the starting stiffness.
    let u0 = utilisation(&ball_state(&sd, &x, speed, fk));
    let kappa = if u0 > LINEAR_UTILISATION { LINEAR_UTILISATION / u0 } else { 1.0 };
    let mut sk = sd;
    sk.stiffness_scale = kappa;
    let (it0, _) = solve_full(&sk, &mut x, speed, fk);
    let (it, mut res, mut steps) = continue_stiffness(&sd, &mut x, kappa, 1.0, speed, fk);
    let mut iterations = it0 + it;
    if lubricated && res <= TOLERANCE {
        let (it, r, st) = continue_in(s, &mut x, RR_START, 1.0, speed, fk, 4.0, scaled);
        iterations += it;
        res = r;
        steps += st;
    }
    if lubricated && !(res <= TOLERANCE) {
        // That branch ends at a fold before the full rolling resistance (a flank at high speed
        // and light load): the ball turns over to the branch of nearly pure rolling, which a
        // Newton solve from the rolling ball reaches.
        let mut y = rolling_guess(s);
        let (it, r) = solve_full(s, &mut y, speed, fk);
        iterations += it;
        if r <= TOLERANCE {
            x = y;
            res = r;
        } else {
            // Else by the continuation in the creep stiffness with the full rolling resistance.
            let mut y = rolling_guess(s);
            let mut sk = *s;
            sk.stiffness_scale = kappa;
            let (it0, _) = solve_full(&sk, &mut y, speed, fk);
            let (it, r, st) = continue_stiffness(s, &mut y, kappa, 1.0, speed, fk);
            iterations += it0 + it;
            steps += st;
            if r <= TOLERANCE {
                x = y;
                res = r;
            }
        }
    }
    (x, SolveReport { iterations, residual: res, continuation_steps: steps })
}

/// Share of the rolling resistance at which the cold solve's continuation in it starts.
const RR_START: f64 = 1e-2;

/// Follows the branch through `x` (solved at creep-stiffness scale `from`) to the scale `to`,
/// in either direction. Returns (Newton iterations, final residual, steps). `s.stiffness_scale`
/// is ignored.
pub fn continue_stiffness(
    s: &BallSetup,
    x: &mut Unknowns,
    from: f64,
    to: f64,
    speed: f64,
    factor: f64,
) -> (u32, f64, u32) {
    continue_in(s, x, from, to, speed, factor, 4.0, |sk, v| sk.stiffness_scale = v)
}

/// Follows the branch through `x` (solved with the ball's axial load `from`, N) to the load `to`.
pub fn continue_load(s: &BallSetup, x: &mut Unknowns, from: f64, to: f64, speed: f64, factor: f64) -> (u32, f64, u32) {
    continue_load_by(s, x, from, to, speed, factor, 4.0)
}

/// [`continue_load`] with a first step of the ratio `first_ratio` (> 1) in load: short steps for
/// a start that a direct solve may not reach (the ball of the neighbouring circle, whose load
/// differs by the circle share, 3/2 for DKFZD4012).
pub fn continue_load_by(
    s: &BallSetup,
    x: &mut Unknowns,
    from: f64,
    to: f64,
    speed: f64,
    factor: f64,
    first_ratio: f64,
) -> (u32, f64, u32) {
    continue_in(s, x, from, to, speed, factor, first_ratio, |sk, v| sk.axial_load_n = v)
}

/// Continuation in one positive parameter of the setup (set by `set`), from `from` to `to` in
/// either direction, by steps in its logarithm (the first by the ratio `first_growth`) with a
/// secant predictor and adaptive step size.
#[allow(clippy::too_many_arguments)]
fn continue_in(
    s: &BallSetup,
    x: &mut Unknowns,
    from: f64,
    to: f64,
    speed: f64,
    factor: f64,
    first_growth: f64,
    set: impl Fn(&mut BallSetup, f64),
) -> (u32, f64, u32) {
    let mut solve = |sk: &BallSetup, y: &mut Unknowns| solve_full(sk, y, speed, factor);
    let (mut iters, mut res, steps, reached) = follow(s, x, from, to, first_growth, &set, &mut solve);
    if !reached {
        let mut sk = *s;
        set(&mut sk, to);
        let (it, r) = solve(&sk, x);
        iters += it;
        res = r;
    }
    (iters, res, steps)
}

/// The path of a continuation in one positive parameter of a setup `s` of any kind (set by
/// `set`), from `from` to `to` in either direction: steps in its logarithm, the first by the
/// ratio `first_growth`, each from a secant predictor through the last two points and solved by
/// `solve` (to [`TOLERANCE`]); a step that fails is halved in the logarithm, one that takes at
/// most 5 iterations doubles the next. Returns (iterations, last residual, steps, whether `to`
/// was reached); `x` holds the last point solved.
pub(crate) fn follow<S: Copy, const M: usize>(
    s: &S,
    x: &mut [f64; M],
    from: f64,
    to: f64,
    first_growth: f64,
    set: &impl Fn(&mut S, f64),
    solve: &mut impl FnMut(&S, &mut [f64; M]) -> (u32, f64),
) -> (u32, f64, u32, bool) {
    let mut sk = *s;
    let mut p = from;
    let mut iters = 0;
    let mut steps = 0;
    let mut res = f64::INFINITY;
    let up = to >= from;
    let mut growth = first_growth;
    // The last accepted point before x, for the secant predictor.
    let mut prev: Option<(f64, [f64; M])> = None;
    while p != to && steps < 400 {
        let next = if up { (p * growth).min(to) } else { (p / growth).max(to) };
        let mut trial = *x;
        if let Some((pp, xp)) = prev {
            let t = libm::log(next / p) / libm::log(p / pp);
            for j in 0..M {
                trial[j] += t * (x[j] - xp[j]);
            }
        }
        set(&mut sk, next);
        let (it, r) = solve(&sk, &mut trial);
        iters += it;
        steps += 1;
        if r <= TOLERANCE {
            prev = Some((p, *x));
            *x = trial;
            p = next;
            res = r;
            if it <= 5 {
                growth = (growth * growth).min(16.0);
            }
        } else {
            growth = libm::sqrt(growth);
            if growth < 1.0 + 1e-6 {
                break;
            }
        }
    }
    (iters, res, steps, p == to)
}

/// Solves one ball from a previous state; falls back to a cold start when Newton fails.
pub fn solve_warm(s: &BallSetup, x0: &Unknowns, speed: f64, factor: f64) -> (Unknowns, SolveReport) {
    solve(s, Some(x0), speed, factor)
}

/// Solves one ball: from `x0` when given, else (or when that fails) cold by continuation in
/// the creep stiffness; where that fails too (light balls, whose contacts saturate fully and
/// make the balance nearly degenerate), by continuation in load from a heavier ball that
/// solves, down to this one's load.
pub fn solve(s: &BallSetup, x0: Option<&Unknowns>, speed: f64, factor: f64) -> (Unknowns, SolveReport) {
    solve_remembering(s, x0, speed, factor, &mut None)
}

/// [`solve`], with the Jacobian of the last warm solve of this ball: a warm start begins with
/// it (Broyden's method carries it on; it is taken afresh where it no longer serves), and the
/// Jacobian the solve ends with is left in `jacobian` (`None` after a cold solve).
pub fn solve_remembering(
    s: &BallSetup,
    x0: Option<&Unknowns>,
    speed: f64,
    factor: f64,
    jacobian: &mut Option<Jacobian>,
) -> (Unknowns, SolveReport) {
    let fk = factor.max(MIN_SOLVE_FACTOR);
    let mut iterations = 0;
    if let Some(x0) = x0 {
        let mut x = *x0;
        let (it, res) = solve_carrying(s, &mut x, speed, fk, jacobian);
        if res <= TOLERANCE {
            return (x, SolveReport { iterations: it, residual: res, continuation_steps: 0 });
        }
        iterations += it;
    }
    *jacobian = None;
    let (x, mut rep) = solve_cold(s, speed, factor);
    rep.iterations += iterations;
    if rep.residual <= TOLERANCE {
        return (x, rep);
    }
    let mut best = (x, rep);
    let mut heavy = *s;
    for _ in 0..6 {
        heavy.axial_load_n *= 4.0;
        let (mut y, r) = solve_cold(&heavy, speed, factor);
        best.1.iterations += r.iterations;
        best.1.continuation_steps += r.continuation_steps;
        if r.residual > TOLERANCE {
            continue;
        }
        let (it, res, steps) = continue_load(s, &mut y, heavy.axial_load_n, s.axial_load_n, speed, fk);
        best.1.iterations += it;
        best.1.continuation_steps += steps;
        if res < best.1.residual {
            best = (y, SolveReport { residual: res, ..best.1 });
        }
        break;
    }
    best
}

/// [`solve_remembering`] that first tries `predicted`, a start extrapolated from the ball's
/// last two solutions (a secant in load), and falls back to the last solution `x0` when that
/// start does not converge. The Jacobian is carried as there.
pub fn solve_predicted(
    s: &BallSetup,
    predicted: &Unknowns,
    x0: &Unknowns,
    speed: f64,
    factor: f64,
    jacobian: &mut Option<Jacobian>,
) -> (Unknowns, SolveReport) {
    let fk = factor.max(MIN_SOLVE_FACTOR);
    let mut x = *predicted;
    let mut carried = *jacobian;
    let (it, res) = solve_carrying(s, &mut x, speed, fk, &mut carried);
    if res <= TOLERANCE {
        *jacobian = carried;
        return (x, SolveReport { iterations: it, residual: res, continuation_steps: 0 });
    }
    let (x, mut rep) = solve_remembering(s, Some(x0), speed, factor, jacobian);
    rep.iterations += it;
    (x, rep)
}

/// The state at standstill factor `factor` from one solved at `max(factor, MIN_SOLVE_FACTOR)`.
///
/// The friction-only equations are homogeneous in the factor, so the angular velocity and orbit
/// carry over; the departures of the normal loads from nominal and the tilt of the normals carry
/// the friction forces, so they shrink with them (to exactly nominal and no tilt at standstill).
pub fn scale_to_factor<F: Real>(x: &[F; N], factor: F) -> [F; N] {
    let min = F::of(MIN_SOLVE_FACTOR);
    if factor >= min {
        return *x;
    }
    scale_friction_terms(x, factor.max(F::zero()) / min)
}

/// The state `x` with the friction forces scaled by `ratio` (a standstill factor f carried to
/// f * ratio): the departures of the normal loads from nominal and the tilt of the normals,
/// which carry the friction forces, scale with them; the rates carry over.
pub(crate) fn scale_friction_terms<F: Real>(x: &[F; N], ratio: F) -> [F; N] {
    let mut y = *x;
    y[4] = F::one() + (x[4] - F::one()) * ratio;
    y[5] = F::one() + (x[5] - F::one()) * ratio;
    y[6] = x[6] * ratio;
    y
}

/// A start for a ball now loaded with `load_n`, extrapolated along the secant through its last
/// two solutions (`last` at `last_load_n`, `before` at `before_load_n`): `None` when the two were
/// at the same load, the load has not changed, or the new load lies further from the last than
/// twice their distance (a jump, where the last solution alone is the better start).
pub(crate) fn secant_start<F: Real>(
    last: &[F; N],
    last_load_n: F,
    before: &[F; N],
    before_load_n: F,
    load_n: F,
) -> Option<[F; N]> {
    let step = last_load_n - before_load_n;
    if step == F::zero() {
        return None;
    }
    let r = (load_n - last_load_n) / step;
    if !(r.abs() <= F::of(2.0)) || r == F::zero() {
        return None;
    }
    Some(core::array::from_fn(|i| last[i] + r * (last[i] - before[i])))
}
