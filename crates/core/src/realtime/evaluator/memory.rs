//! The evaluator's warm-start memory ([`EvalState`]): per flank and circle, a ball's last four
//! solutions and its inverse Jacobian, and the start a call takes from them (the quadratic or
//! cubic along their path in load and speed by Lagrange's weights, the plane through three in
//! load and speed, the secant; [`BallMemory::start`]).

use super::linear::Matrix;
use super::stats::Stats;
use crate::ball::setup::N;
use crate::ball::solve::{self};
use crate::error::InputError;
use crate::input::{MAX_CIRCLES_PER_NUT, MAX_NUTS};
use crate::real::Real;

/// Relative change of a ball's load above which a warm start gives way to the table.
pub(super) const JUMP: f64 = 0.01;
/// Solutions the quadratic warm start takes: a ball's newest three.
pub(super) const HISTORY: usize = 3;
/// Solutions a ball remembers for its warm start: the quadratic takes the newest
/// [`HISTORY`], the cubic of lubricated contacts in f64 all four (see `BallMemory::start`).
pub(super) const REMEMBERED: usize = 4;
/// Relative departure of a point's film speed (or load) from the quadratic of the remembered
/// ones in the load (or the film speed) within which the point is taken to lie on their path
/// (see `BallMemory::start`): far below a step of a control loop (1e-4 to 1e-2 of the speed),
/// far above rounding.
pub(super) const ON_PATH: f64 = 1e-6;
/// Largest sum of the magnitudes of the extrapolation weights (the factor by which the
/// rounding of the remembered solutions can grow) at which a quadratic start is taken.
pub(super) const MAX_LEBESGUE: f64 = 8.0;
/// The same for the cubic start (equal steps give 15, the quadratic's 7).
pub(super) const MAX_LEBESGUE_CUBIC: f64 = 16.0;
/// [`ON_PATH`] for the cubic start, whose larger weights make it the more sensitive to a path
/// that is not smooth. A drive cycle's log with its loads written to 1e-3 N (a step of the
/// preload is 0.03 N there, its rounding 3 % of it) lies on its path within 1e-6 but not
/// within 1e-8: at 1e-6 the cubic took 1 % more residuals than the quadratic over its 10,000
/// rows, at 1e-8 0.1 % fewer; on the same cycle unrounded 9 % and 7 % fewer (counted through
/// `ballscrew predict`).
pub(super) const ON_PATH_CUBIC: f64 = 1e-8;

/// Warm-start memory of an [`Evaluator`](super::Evaluator): per flank as solved (turning forwards) and circle,
/// the ball's last four solutions and its inverse Jacobian.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EvalState<F: Real> {
    pub(super) balls: [[BallMemory<F>; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct BallMemory<F: Real> {
    /// Number of stored solutions (0 to [`REMEMBERED`]), newest first.
    pub(super) stored: u8,
    pub(super) x: [[F; N]; REMEMBERED],
    pub(super) load_n: [F; REMEMBERED],
    /// The speed whose films each solution's friction is that of: the screw speed's magnitude
    /// (rad/s) with lubricated contacts; 0 with dry ones, whose solutions do not depend on it
    /// (`Evaluator::solve_ball`).
    pub(super) film_speed: [F; REMEMBERED],
    /// Standstill factor the stored solutions were solved at.
    pub(super) factor: F,
    /// Inverse Jacobian at the newest solution (Broyden's estimate, or in f64 after a fallback
    /// the finite-difference one there), valid when `stored > 0`.
    pub(super) inverse: Matrix<F>,
    /// What the ball's solves counted (tests only: no size elsewhere).
    pub(super) stats: Stats,
}

impl<F: Real> BallMemory<F> {
    pub(super) const EMPTY: Self = Self {
        stored: 0,
        x: [[F::ZERO; N]; REMEMBERED],
        load_n: [F::ZERO; REMEMBERED],
        film_speed: [F::ZERO; REMEMBERED],
        factor: F::ZERO,
        inverse: [[F::ZERO; N]; N],
        stats: Stats::ZERO,
    };

    /// Remembers the solution `x` at load `load_n`, film speed `film_speed` and factor
    /// `factor`: on top of the history when the factor is the same, else alone.
    pub(super) fn push(&mut self, x: [F; N], load_n: F, film_speed: F, factor: F) {
        if self.stored == 0 || factor != self.factor {
            self.stored = 0;
        }
        let keep = (self.stored as usize).min(REMEMBERED - 1);
        for k in (0..keep).rev() {
            self.x[k + 1] = self.x[k];
            self.load_n[k + 1] = self.load_n[k];
            self.film_speed[k + 1] = self.film_speed[k];
        }
        self.x[0] = x;
        self.load_n[0] = load_n;
        self.film_speed[0] = film_speed;
        self.factor = factor;
        self.stored = keep as u8 + 1;
    }

    /// A start for load `p` at film speed `film_speed` and factor `factor` from the remembered
    /// solutions, or `None` when there is none or the load has jumped by more than [`JUMP`].
    ///
    /// A lubricated ball's solution follows its load and, through the films' friction, the
    /// speed. With three solutions the start is the quadratic through them along the path they
    /// lie on: in the load where the point's film speed lies on that path (the quadratic of the
    /// remembered speeds in the load gives it to within [`ON_PATH`]; dry contacts always,
    /// and a point at the same speed), else in the speed where the load lies on it (a change of
    /// speed at constant load); off both, the plane through the three in load and speed (first
    /// order), else the quadratic in the load alone. With two, the secant in the load, or in
    /// the speed where the two loads are equal and the speed has changed. A point whose film
    /// speed is more than [`JUMP`] off any remembered solution's (a batch's neighbour in
    /// another part of a band of speed, or a jump in the history) extrapolates in the load
    /// alone: the films' friction has moved too far for an extrapolation in the speed (on the
    /// lubricated study grid above 2000 rpm, where balls near the end of a branch of steady
    /// states take the continuation, it cost 15 %). With four solutions, lubricated contacts in
    /// f64 take the cubic through them along the path the quadratic was taken along, where the
    /// fourth lies on it too (to within [`ON_PATH_CUBIC`]) and its speed within [`JUMP`] of the
    /// point's.
    pub(super) fn start(&self, p: F, film_speed: F, factor: F) -> Option<[F; N]> {
        if self.stored == 0 {
            return None;
        }
        let p0 = self.load_n[0];
        if (p - p0).abs() > F::of(JUMP) * p0 {
            return None;
        }
        if factor != self.factor {
            // The loads' departure from nominal and the tilt carry the friction forces, which
            // scale with the factor.
            return Some(solve::scale_friction_terms(&self.x[0], factor / self.factor));
        }
        let newest = |a: &[F; REMEMBERED]| -> [F; HISTORY] { core::array::from_fn(|k| a[k]) };
        let (loads, speeds) = (&newest(&self.load_n), &newest(&self.film_speed));
        // A jump in the speed (the films' friction then moves far): in the load alone, as dry.
        // The quadratic's newest three, and for the cubic all four.
        let near_to = |s: F| (film_speed - s).abs() <= F::of(JUMP) * s;
        let near = self.film_speed[..(self.stored as usize).min(HISTORY)].iter().all(|&s| near_to(s));
        // The quadratic's weights, and whether they are along the load (`Some(true)`) or the
        // speed (`Some(false)`) on the path of the remembered solutions.
        let weights = if self.stored as usize >= 3 {
            let in_load = quadratic_weights(loads, p);
            in_load
                .filter(|l| !near || on_path(l, speeds, film_speed, ON_PATH))
                .map(|l| (l, near.then_some(true)))
                .or_else(|| {
                    near.then(|| quadratic_weights(speeds, film_speed))
                        .flatten()
                        .filter(|l| on_path(l, loads, p, ON_PATH))
                        .map(|l| (l, Some(false)))
                })
                .or_else(|| near.then(|| plane_weights(loads, speeds, p, film_speed)).flatten().map(|l| (l, None)))
                .or(in_load.map(|l| (l, None)))
        } else {
            None
        };
        // Lubricated contacts in f64 with four solutions on the path: the cubic along it. A
        // step of a quarter of a per cent in the speed moves a lubricated ball's solution so
        // far that the quadratic's own error (third order in the step) reaches the tolerance at
        // about half the balls, which then take one more residual (counted on `warm_ramp`: 12.6
        // residuals a call with the quadratic, 9.7 with the cubic). Not dry (every quadratic
        // start is within the tolerance there), nor in f32 (whose remembered solutions carry
        // its rounding noise, which the cubic's weights amplify twice as much).
        let cubic = match weights {
            Some((_, Some(along_load)))
                if F::FINITE_DIFFERENCES
                    && film_speed > F::zero()
                    && self.stored as usize == REMEMBERED
                    && near_to(self.film_speed[REMEMBERED - 1]) =>
            {
                if along_load {
                    cubic_weights(&self.load_n, p).filter(|l| on_path(l, &self.film_speed, film_speed, ON_PATH_CUBIC))
                } else {
                    cubic_weights(&self.film_speed, film_speed).filter(|l| on_path(l, &self.load_n, p, ON_PATH_CUBIC))
                }
            }
            _ => None,
        };
        if let Some(l) = cubic {
            return Some(combine(&l, &self.x));
        }
        if let Some((l, _)) = weights {
            return Some(combine(&l, &self.x));
        }
        if self.stored >= 2 {
            // In the speed only at one load: at an unchanged speed its secant, like the load's,
            // has no step and gives way to the last solution.
            let (s0, s1, p1) = (speeds[0], speeds[1], loads[1]);
            let secant = if p0 != p1 || !near {
                solve::secant_start(&self.x[0], p0, &self.x[1], p1, p)
            } else {
                solve::secant_start(&self.x[0], s0, &self.x[1], s1, film_speed)
            };
            if let Some(x) = secant {
                return Some(x);
            }
        }
        Some(self.x[0])
    }
}

/// The newest `K` of the remembered solutions `x` weighted by `weights` and summed (in that
/// order).
pub(super) fn combine<F: Real, const K: usize>(weights: &[F; K], x: &[[F; N]; REMEMBERED]) -> [F; N] {
    core::array::from_fn(|i| (1..K).fold(weights[0] * x[0][i], |sum, k| sum + weights[k] * x[k][i]))
}

/// Whether `value` lies on the path of the `remembered` values (a load or a speed): within
/// `tolerance` ([`ON_PATH`], [`ON_PATH_CUBIC`]) of their extrapolation with `weights`.
pub(super) fn on_path<F: Real, const K: usize>(
    weights: &[F; K],
    remembered: &[F; K],
    value: F,
    tolerance: f64,
) -> bool {
    let predicted = (0..K).fold(F::zero(), |sum, k| sum + weights[k] * remembered[k]);
    (predicted - value).abs() <= F::of(tolerance) * value.abs()
}

/// The weights of the cubic through four values of a parameter `t` at `at`
/// ([`lagrange_weights`], bounded by [`MAX_LEBESGUE_CUBIC`]).
pub(super) fn cubic_weights<F: Real>(t: &[F; REMEMBERED], at: F) -> Option<[F; REMEMBERED]> {
    lagrange_weights(t, at, MAX_LEBESGUE_CUBIC)
}

/// The weights of the quadratic through three values of a parameter `t` at `at`
/// ([`lagrange_weights`], bounded by [`MAX_LEBESGUE`]).
pub(super) fn quadratic_weights<F: Real>(t: &[F; HISTORY], at: F) -> Option<[F; HISTORY]> {
    lagrange_weights(t, at, MAX_LEBESGUE)
}

/// The weights of the polynomial through the `K` values of a parameter `t` at `at`
/// (Lagrange's: the product of `at - t_j` over that of `t_k - t_j`, `j` not `k`); `None` where
/// the values are not distinct or the sum of the weights' magnitudes exceeds `max_lebesgue`.
pub(super) fn lagrange_weights<F: Real, const K: usize>(t: &[F; K], at: F, max_lebesgue: f64) -> Option<[F; K]> {
    let mut weights = [F::one(); K];
    for (k, w) in weights.iter_mut().enumerate() {
        let (mut num, mut den) = (F::one(), F::one());
        for (j, &tj) in t.iter().enumerate() {
            if j != k {
                num *= at - tj;
                den *= t[k] - tj;
            }
        }
        if den == F::zero() {
            return None;
        }
        *w = num / den;
    }
    small_weights(weights, max_lebesgue)
}

/// The weights of the plane through three points `(loads[k], speeds[k])` at `(p, s)`: the
/// barycentric coordinates of the point in their triangle; `None` where the three are on a
/// line or the weights are large (see [`MAX_LEBESGUE`]).
pub(super) fn plane_weights<F: Real>(loads: &[F; HISTORY], speeds: &[F; HISTORY], p: F, s: F) -> Option<[F; HISTORY]> {
    let (a11, a12, b1) = (loads[1] - loads[0], loads[2] - loads[0], p - loads[0]);
    let (a21, a22, b2) = (speeds[1] - speeds[0], speeds[2] - speeds[0], s - speeds[0]);
    let det = a11 * a22 - a12 * a21;
    if det == F::zero() {
        return None;
    }
    let l1 = (b1 * a22 - a12 * b2) / det;
    let l2 = (a11 * b2 - a21 * b1) / det;
    small_weights([F::one() - l1 - l2, l1, l2], MAX_LEBESGUE)
}

/// `weights` where the sum of their magnitudes is at most `max_lebesgue` (and finite).
pub(super) fn small_weights<F: Real, const K: usize>(weights: [F; K], max_lebesgue: f64) -> Option<[F; K]> {
    let sum = weights.iter().fold(F::zero(), |sum, l| sum + l.abs());
    (sum <= F::of(max_lebesgue)).then_some(weights)
}

impl<F: Real> Default for EvalState<F> {
    fn default() -> Self {
        Self::new()
    }
}

impl<F: Real> EvalState<F> {
    /// An empty state: the next call starts every ball from the table.
    pub const fn new() -> Self {
        Self { balls: [[BallMemory::EMPTY; MAX_CIRCLES_PER_NUT]; MAX_NUTS] }
    }

    /// Forgets every stored solution.
    pub fn reset(&mut self) {
        *self = Self::new();
    }

    /// The state as [`EVAL_STATE_VALUES`] numbers, exact in f64 (for saving it: a pickle, a
    /// file), which [`EvalState::from_values`] takes back to the same state, bit for bit: per
    /// nut and circle, the count of stored solutions, the solutions, their loads, film speeds,
    /// the standstill factor and the inverse Jacobian.
    pub fn values(&self) -> impl Iterator<Item = f64> + '_ {
        self.balls.iter().flatten().flat_map(|b| {
            core::iter::once(f64::from(b.stored))
                .chain(b.x.iter().flatten().map(|v| v.to_f64()))
                .chain(b.load_n.iter().map(|v| v.to_f64()))
                .chain(b.film_speed.iter().map(|v| v.to_f64()))
                .chain(core::iter::once(b.factor.to_f64()))
                .chain(b.inverse.iter().flatten().map(|v| v.to_f64()))
        })
    }

    /// The state of [`EvalState::values`]; an [`InputError`] naming `eval_state` unless there
    /// are [`EVAL_STATE_VALUES`] finite values whose counts are whole numbers from 0 to 4 and
    /// whose other values `F` holds exactly.
    pub fn from_values(values: &[f64]) -> Result<Self, InputError> {
        const VALID: &str =
            "the values of a saved evaluator state: finite, exact in the float type, whole counts from 0 to 4";
        let refuse = |value: f64| InputError { field: "eval_state", value, valid: VALID };
        if values.len() != EVAL_STATE_VALUES {
            return Err(refuse(values.len() as f64));
        }
        let mut state = Self::new();
        let mut next = values.iter().copied();
        let mut take = || -> Result<F, InputError> {
            let v = next.next().unwrap_or(f64::NAN);
            let x = F::of(v);
            if v.is_finite() && x.to_f64() == v { Ok(x) } else { Err(refuse(v)) }
        };
        for ball in state.balls.iter_mut().flatten() {
            let stored = take()?.to_f64();
            if !(0.0..=REMEMBERED as f64).contains(&stored) || stored != libm::trunc(stored) {
                return Err(refuse(stored));
            }
            ball.stored = stored as u8;
            for v in ball.x.iter_mut().flatten().chain(&mut ball.load_n).chain(&mut ball.film_speed) {
                *v = take()?;
            }
            ball.factor = take()?;
            for v in ball.inverse.iter_mut().flatten() {
                *v = take()?;
            }
        }
        Ok(state)
    }
}

/// Number of values of an [`EvalState`] ([`EvalState::values`]).
pub const EVAL_STATE_VALUES: usize = MAX_NUTS * MAX_CIRCLES_PER_NUT * (1 + REMEMBERED * (N + 2) + 1 + N * N);
