//! The balance of a circuit of several loaded turns: every ball of the circuit at one orbit
//! rate, the pushes between them from that.
//!
//! A circuit of an external return holds several loaded turns (circles) of one nut. Its circles
//! carry different loads (the load distribution over the circles), so their balls would orbit
//! at different rates if each were free: on DKFZD4012 at 2000 N and 100 rpm the free orbit
//! ratios of one nut's four circles are 0.444336, 0.443989, 0.443655 and 0.443342. In a closed
//! circuit they cannot: the balls follow each other, so the faster push the slower, and every
//! ball of the circuit orbits at one rate. Each circle is represented by one ball (a segment of
//! the train, [`crate::screw::train`]) with the mean loads of its contacts. A stated load ramp
//! ([`crate::input::circulation`]) adds each of its balls as a segment of its own, ahead of the
//! circuit's first circle and behind its last, so a circuit of one turn with a ramp is balanced
//! here as well.
//!
//! # The balance
//!
//! Unknowns: each segment's ball state `x_i` (the seven unknowns of [`crate::ball::setup`]) and
//! its push `p_i` (N: the load of the contact behind less that ahead, per ball). Equations:
//!
//! - each segment's ball in balance with the loads the pushes give its contacts
//!   ([`train::chain_of_pushes`]: the chain force, zero at the one gap);
//! - one orbit rate: `orbit_i = orbit_(i+1)` for neighbouring segments;
//! - the pushes carry the return: `sum_i n_i p_i = -R`.
//!
//! The balance's level matters as well as its pushes: a compressed chain on the helix presses
//! each ball outwards and brakes its spin by the ball-ball friction, which raises the orbit
//! rate of every ball, the light ones most. So the orbit rates and the pushes are solved
//! together: Newton's method on all unknowns, the Jacobian of each ball's balance in its own
//! state and in its contacts' loads taken by finite differences, and the segments' states
//! eliminated block by block, leaving a system in the pushes alone (at most
//! [`train::MAX_SEGMENTS`] unknowns, no allocation).
//!
//! # The path to it
//!
//! A cold solve starts from the circles solved one by one with the return's resistance shared
//! evenly (their free orbit rates, what [`crate::screw::model::Model`] solves for circuits of one
//! turn), and closes the differences of their orbit rates by continuation: the orbit equations
//! ask `orbit_i - orbit_(i+1) = (1 - t) d_i`, `d_i` the free difference, from `t = 0` (the start
//! balances them) to `t = 1`, in steps that grow while Newton's method settles in a few
//! iterations and shrink where it does not. The model solves every circuit so, whatever it
//! solved before (the canonical state: the same answer on every path).

use crate::ball::balance::{self, Constants, Load};
use crate::ball::setup::{N, TOLERANCE, Unknowns};
use crate::ball::solve::solve_linear;
use crate::screw::train::{self, Chain, MAX_SEGMENTS};

/// Most Newton iterations at one step of the continuation.
const MAX_ITERATIONS: u32 = 40;
/// Smallest step of the continuation before the solve gives up.
const MIN_STEP: f64 = 1.0 / 4096.0;
/// Relative step of the finite differences in a ball's state: far from the solution, near it
/// (below [`NEAR_BELOW`] of the scaled residual), as for one ball ([`crate::ball::solve`]).
const STEP_FAR: f64 = 1e-7;
const STEP_NEAR: f64 = 1e-8;
const NEAR_BELOW: f64 = 1e-3;

/// One segment of a circuit: the balls of one circle, in the order of travel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Segment {
    /// The lean constants of the segment's ball (its raceway contacts' friction included).
    pub constants: Constants<f64>,
    /// The ball's share of its nut's axial load, N.
    pub axial_load_n: f64,
    /// Balls in the segment.
    pub balls: f64,
    /// The scale of the ball's force equations, N (f Q): the tolerance of the pushes' sum is
    /// taken against the largest.
    pub force_scale_n: f64,
}

/// A circuit to balance: its segments in the order of travel and the return's resistance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Problem {
    /// The segments; the first `segments` hold.
    pub segment: [Segment; MAX_SEGMENTS],
    /// Segments in the circuit (at least 2).
    pub segments: usize,
    /// The return's resistance, N (with the standstill factor).
    pub resistance_n: f64,
    /// Whether the balls travel towards +theta (the screw turning forwards).
    pub forwards: bool,
    /// The load of every ball's balance: the direction and the standstill factor of the solve
    /// (its axial load is each segment's own).
    pub direction: f64,
    /// The standstill factor of the solve.
    pub factor: f64,
    /// The largest residual accepted where Newton's method stalls above [`TOLERANCE`].
    pub accept: f64,
    /// Factor on the ball-ball contacts' friction (1; lowered by the continuation in it).
    pub friction_scale: f64,
}

/// A state of the circuit: each segment's ball state and push.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct State {
    /// Each segment's ball state.
    pub x: [Unknowns; MAX_SEGMENTS],
    /// Each segment's push per ball, N.
    pub push_n: [f64; MAX_SEGMENTS],
    /// The segment at whose entry the gap is held while Newton's method runs (the chain is
    /// then smooth in the pushes); checked against the pushes after each solve.
    pub gap: usize,
}

/// How a circuit's solve went.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Report {
    /// Newton iterations, over every step.
    pub iterations: u32,
    /// Steps of the continuation taken.
    pub steps: u32,
    /// The scaled residual (max norm over the balls' balances, the orbit equations and the
    /// pushes' sum) where the solve ended.
    pub residual: f64,
    /// The segment whose ball's residual is the largest there.
    pub worst_segment: usize,
}

impl Problem {
    fn balls(&self) -> [f64; MAX_SEGMENTS] {
        let mut balls = [0.0; MAX_SEGMENTS];
        for (b, seg) in balls.iter_mut().zip(&self.segment).take(self.segments) {
            *b = seg.balls;
        }
        balls
    }

    /// The chain of the pushes of `s`, the gap where their running sum is largest.
    pub fn chain(&self, s: &State) -> Chain {
        let n = self.segments;
        train::chain_of_pushes(&self.balls()[..n], &s.push_n[..n])
    }

    /// The chain of the pushes of `s` with its gap held at `s.gap`.
    fn chain_held(&self, s: &State) -> Chain {
        let n = self.segments;
        train::chain_with_gap(&self.balls()[..n], &s.push_n[..n], Some(s.gap))
    }

    /// Where the gap of the pushes of `s` lies.
    pub fn gap_of(&self, s: &State) -> usize {
        let n = self.segments;
        train::gap_of_pushes(&self.balls()[..n], &s.push_n[..n])
    }

    /// The loads `(plus, minus, plus_friction, minus_friction)` (N) of segment `i`'s ball in
    /// the chain `c`: ahead is `+theta` when the balls travel forwards.
    pub fn ball_ball_loads(&self, c: &Chain, i: usize) -> (f64, f64, f64, f64) {
        let l = &c.loads[i];
        if self.forwards {
            (l.ahead_n, l.behind_n, l.ahead_friction_n, l.behind_friction_n)
        } else {
            (l.behind_n, l.ahead_n, l.behind_friction_n, l.ahead_friction_n)
        }
    }

    /// Segment `i`'s constants with the loads `loads` on its ball-ball contacts.
    pub fn constants_with(&self, i: usize, loads: (f64, f64, f64, f64)) -> Constants<f64> {
        let c = self.segment[i].constants.with_ball_ball_loads(loads);
        if self.friction_scale == 1.0 { c } else { c.with_ball_ball_mu_scaled(self.friction_scale) }
    }

    fn load(&self, i: usize) -> Load<f64> {
        Load { axial_load_n: self.segment[i].axial_load_n, direction: self.direction, factor: self.factor }
    }

    fn ball_residual(&self, i: usize, x: &Unknowns, loads: (f64, f64, f64, f64)) -> [f64; N] {
        balance::evaluate(&self.constants_with(i, loads), x, &self.load(i)).residual
    }

    /// The residuals of `s` at continuation parameter `t` with the free differences `d`:
    /// each ball's (scaled), the orbit equations, the pushes' sum (over the largest force
    /// scale); and their max norm with the segment of the worst ball.
    fn residuals(&self, s: &State, t: f64, d: &[f64; MAX_SEGMENTS]) -> Residuals {
        let n = self.segments;
        let c = self.chain_held(s);
        let mut out = Residuals { ball: [[0.0; N]; MAX_SEGMENTS], link: [0.0; MAX_SEGMENTS], max: 0.0, worst: 0 };
        let mut sum = self.resistance_n;
        let mut scale: f64 = 0.0;
        let mut worst = 0.0;
        for i in 0..n {
            out.ball[i] = self.ball_residual(i, &s.x[i], self.ball_ball_loads(&c, i));
            let m = out.ball[i].iter().fold(0.0_f64, |m, v| m.max(libm::fabs(*v)));
            if !(m <= worst) {
                worst = m;
                out.worst = i;
            }
            sum += self.segment[i].balls * s.push_n[i];
            scale = scale.max(self.segment[i].force_scale_n);
            if i + 1 < n {
                out.link[i] = s.x[i][3] - s.x[i + 1][3] - (1.0 - t) * d[i];
            }
        }
        out.link[n - 1] = sum / scale;
        out.max = out.link[..n].iter().fold(worst, |m, v| m.max(libm::fabs(*v)));
        if !out.max.is_finite() {
            out.max = f64::INFINITY;
        }
        out
    }

    /// Sum of squares of the residuals (the line search's merit).
    fn merit(r: &Residuals, n: usize) -> f64 {
        let mut m = 0.0;
        for i in 0..n {
            m += r.ball[i].iter().map(|v| v * v).sum::<f64>() + r.link[i] * r.link[i];
        }
        m
    }

    /// One Newton step from `s` (residuals `r`) at `t`: `None` where a linear system is
    /// singular.
    fn newton_step(&self, s: &State, r: &Residuals, t: f64, d: &[f64; MAX_SEGMENTS]) -> Option<State> {
        let n = self.segments;
        let c = self.chain_held(s);
        let rel = if r.max > NEAR_BELOW { STEP_FAR } else { STEP_NEAR };
        // The loads of every segment's contacts per push (the chain is piecewise linear in them).
        let mut dloads = [[[0.0; 4]; MAX_SEGMENTS]; MAX_SEGMENTS];
        let push_scale = (0..n).fold(0.0_f64, |m, i| m.max(self.segment[i].force_scale_n));
        for j in 0..n {
            let h = 1e-6 * push_scale.max(libm::fabs(s.push_n[j]));
            let mut sp = *s;
            sp.push_n[j] += h;
            let cp = self.chain_held(&sp);
            for i in 0..n {
                let a = self.ball_ball_loads(&c, i);
                let b = self.ball_ball_loads(&cp, i);
                dloads[i][j] = [(b.0 - a.0) / h, (b.1 - a.1) / h, (b.2 - a.2) / h, (b.3 - a.3) / h];
            }
        }
        // Each segment: dx_i = -a_i - C_i dp, from A_i dx_i + B_i G_i dp = -r_i.
        let mut a = [[0.0; N]; MAX_SEGMENTS];
        let mut cm = [[[0.0; N]; MAX_SEGMENTS]; MAX_SEGMENTS];
        for i in 0..n {
            let loads = self.ball_ball_loads(&c, i);
            let x = s.x[i];
            let mut jac = [[0.0; N]; N];
            for k in 0..N {
                let h = rel * libm::fabs(x[k]).max(1e-2);
                let mut xp = x;
                xp[k] += h;
                let rp = self.ball_residual(i, &xp, loads);
                for (row, (p, r0)) in jac.iter_mut().zip(rp.iter().zip(&r.ball[i])) {
                    row[k] = (p - r0) / h;
                }
            }
            // The residual per unit load of each of the four ball-ball loads.
            let mut b = [[0.0; 4]; N];
            let l = [loads.0, loads.1, loads.2, loads.3];
            for k in 0..4 {
                let h = 1e-6 * push_scale.max(libm::fabs(l[k]));
                let mut lp = l;
                lp[k] += h;
                let rp = self.ball_residual(i, &x, (lp[0], lp[1], lp[2], lp[3]));
                for (row, (p, r0)) in b.iter_mut().zip(rp.iter().zip(&r.ball[i])) {
                    row[k] = (p - r0) / h;
                }
            }
            a[i] = solve_linear(jac, r.ball[i])?;
            for j in 0..n {
                let mut rhs = [0.0; N];
                for (row, bk) in rhs.iter_mut().zip(&b) {
                    *row = (0..4).map(|k| bk[k] * dloads[i][j][k]).sum();
                }
                if rhs.iter().any(|v| *v != 0.0) {
                    cm[i][j] = solve_linear(jac, rhs)?;
                }
            }
        }
        // The pushes' system: the orbit equations and the sum.
        let mut m = [[0.0; MAX_SEGMENTS]; MAX_SEGMENTS];
        let mut rhs = [0.0; MAX_SEGMENTS];
        let scale = push_scale;
        for i in 0..n {
            if i + 1 < n {
                // orbit_i + dx_i[3] - orbit_(i+1) - dx_(i+1)[3] = (1 - t) d_i
                for j in 0..n {
                    m[i][j] = -cm[i][j][3] + cm[i + 1][j][3];
                }
                rhs[i] = (1.0 - t) * d[i] - (s.x[i][3] - s.x[i + 1][3]) + a[i][3] - a[i + 1][3];
            } else {
                for j in 0..n {
                    m[i][j] = self.segment[j].balls / scale;
                }
                rhs[i] = -r.link[i];
            }
        }
        for (k, row) in m.iter_mut().enumerate().skip(n) {
            row[k] = 1.0;
        }
        let dp = solve_linear(m, rhs)?;
        let mut out = *s;
        for i in 0..n {
            out.push_n[i] += dp[i];
            for k in 0..N {
                out.x[i][k] -= a[i][k] + (0..n).map(|j| cm[i][j][k] * dp[j]).sum::<f64>();
            }
        }
        Some(out)
    }

    /// Newton's method at `t` from `s` (changed in place only when it converges): whether it
    /// reached [`TOLERANCE`], or stalled (the chain's gap switching, the finite differences'
    /// noise) at a physical state within [`Problem::accept`].
    fn solve_at(&self, s: &mut State, t: f64, d: &[f64; MAX_SEGMENTS], report: &mut Report) -> bool {
        let n = self.segments;
        let mut x = *s;
        let mut r = self.residuals(&x, t, d);
        let mut best = (x, r);
        for _ in 0..MAX_ITERATIONS {
            if r.max <= TOLERANCE && self.physical(&x) {
                best = (x, r);
                break;
            }
            if !r.max.is_finite() {
                break;
            }
            report.iterations += 1;
            let Some(full) = self.newton_step(&x, &r, t, d) else { break };
            let m0 = Self::merit(&r, n);
            let mut lambda = 1.0;
            let mut next = None;
            for _ in 0..12 {
                let mut y = x;
                for i in 0..n {
                    y.push_n[i] += lambda * (full.push_n[i] - x.push_n[i]);
                    for k in 0..N {
                        y.x[i][k] += lambda * (full.x[i][k] - x.x[i][k]);
                    }
                }
                let ry = self.residuals(&y, t, d);
                if Self::merit(&ry, n) < m0 {
                    next = Some((y, ry));
                    break;
                }
                lambda *= 0.5;
            }
            let Some((y, ry)) = next else { break };
            x = y;
            r = ry;
            if r.max < best.1.max && self.physical(&x) {
                best = (x, r);
            }
        }
        let (x, r) = best;
        report.residual = r.max;
        report.worst_segment = r.worst;
        if r.max <= self.accept && self.physical(&x) {
            *s = x;
            return true;
        }
        false
    }

    /// [`Problem::solve_at`], the gap moved to where the running sum of the pushes is largest
    /// and solved again until it stays there (a held gap lets the chain force pass through
    /// zero, and the gap moves where it does).
    fn solve_with_gap(&self, s: &mut State, t: f64, d: &[f64; MAX_SEGMENTS], report: &mut Report) -> bool {
        let mut x = *s;
        x.gap = self.gap_of(&x);
        for _ in 0..=self.segments {
            if !self.solve_at(&mut x, t, d, report) {
                return false;
            }
            let gap = self.gap_of(&x);
            if gap == x.gap || self.chain(&x) == self.chain_held(&x) {
                *s = x;
                return true;
            }
            x.gap = gap;
        }
        false
    }

    /// Whether every segment's ball state is physical ([`crate::ball::setup::check_state`]).
    pub fn physical(&self, s: &State) -> bool {
        (0..self.segments).all(|i| self.segment[i].constants.check_state(&s.x[i]).is_ok())
    }

    /// Balances the circuit from `start` (each segment's ball solved alone with the pushes of
    /// `start`, in balance there): by continuation from their free orbit rates (the module's
    /// documentation), the gap following the pushes. Where that path ends at a fold (the gap
    /// switching back and forth between two places, neither of which balances), by the same
    /// path without friction between the balls (the chain's level then acts only by pressing
    /// the balls outwards), then by continuation in that friction up to its value. `Err` with
    /// the report of the last step tried when neither gets there.
    pub fn solve_cold(&self, start: &State) -> Result<(State, Report), Report> {
        let n = self.segments;
        let mut d = [0.0; MAX_SEGMENTS];
        for i in 0..n.saturating_sub(1) {
            d[i] = start.x[i][3] - start.x[i + 1][3];
        }
        let mut report = Report::default();
        let mut s = *start;
        s.gap = self.gap_of(start);
        if march(&mut s, &mut report, |s, t, r| self.solve_with_gap(s, t, &d, r)) {
            return Ok((s, report));
        }
        let mut frictionless = *self;
        frictionless.friction_scale = 0.0;
        let mut s = *start;
        // The start balances with the friction; without it, it is balanced at t = 0 first.
        if frictionless.solve_with_gap(&mut s, 0.0, &d, &mut report)
            && march(&mut s, &mut report, |s, t, r| frictionless.solve_with_gap(s, t, &d, r))
            && march(&mut s, &mut report, |s, k, r| {
                let mut p = *self;
                p.friction_scale = k;
                p.solve_with_gap(s, 1.0, &d, r)
            })
        {
            return Ok((s, report));
        }
        Err(report)
    }
}

/// A continuation of `s` in a parameter from 0 (where `s` holds) to 1, `solve_at(s, p, report)`
/// balancing it at `p`: steps that double while a step takes at most 4 Newton iterations and
/// shrink fourfold where it fails, down to [`MIN_STEP`]. Whether it got to 1.
fn march(s: &mut State, report: &mut Report, mut solve_at: impl FnMut(&mut State, f64, &mut Report) -> bool) -> bool {
    let (mut p, mut dp) = (0.0, 1.0);
    while p < 1.0 {
        let next = if p + dp >= 1.0 { 1.0 } else { p + dp };
        let before = report.iterations;
        if solve_at(s, next, report) {
            p = next;
            report.steps += 1;
            if report.iterations - before <= 4 {
                dp *= 2.0;
            }
        } else {
            dp *= 0.25;
            if dp < MIN_STEP {
                return false;
            }
        }
    }
    true
}

/// The residuals of a circuit's state.
#[derive(Debug, Clone, Copy)]
struct Residuals {
    ball: [[f64; N]; MAX_SEGMENTS],
    /// The orbit equations, then (at the last segment) the pushes' sum.
    link: [f64; MAX_SEGMENTS],
    max: f64,
    worst: usize,
}
