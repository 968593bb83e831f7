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

use crate::ball::balance::{self, Constants, Load, Outcome};
use crate::ball::kinematics::{self, JacobianStep};
use crate::ball::lubrication::{BallFilms, FilmSpeed};
use crate::ball::setup::{self, ContactFriction, MIN_SOLVE_FACTOR, N, Unknowns};
use crate::contact::creep::standstill_factor;
use crate::error::Error;
use crate::input::extensions::Conditions;
use crate::input::screw::check_preload_for;
use crate::input::{ContactTheory, MAX_CIRCLES_PER_NUT, MAX_NUTS, OperatingPoint, Preload, ScrewSpec, TorqueRoute};
use crate::real::{Lanes, Real};
use crate::screw::load;
use crate::screw::torque::{Model, SolverState, accepted_residual};

/// Ball load of the first entry of the start table, N.
pub const TABLE_FIRST_LOAD_N: f64 = 1e-2;
/// Ratio of the ball loads of adjacent entries of the start table.
pub const TABLE_RATIO: f64 = 1.25;
/// Entries of the start table per flank: 1e-2 N to about 2e6 N.
pub const TABLE_LEN: usize = 86;
/// Ball load (N) below which the evaluator hands the whole point to the model
/// ([`Model::torque_at`] from a fresh state), so that both give the same torque or the same
/// error. Light balls make the balance nearly degenerate (both raceway contacts in full slip,
/// README "Light balls"): there the model's continuation decides whether a physical state is
/// found at all (on DKFZD4012 it is not below about 2 N of preload, 0.04 N per ball), and a
/// start from the evaluator's table or memory could land on a state the model does not reach.
/// 0.5 N is 25 N of preload on DKFZD4012, above the balls of 0.03-0.2 N whose solutions are
/// ill-determined.
pub const LIGHT_BALL_N: f64 = 0.5;
/// Relative change of a ball's load above which a warm start gives way to the table.
const JUMP: f64 = 0.01;
/// Newton iterations of one solve in the evaluator.
const MAX_ITERATIONS: u32 = 40;
/// Broyden steps of one lean solve before it gives way to Newton's method.
const LEAN_ITERATIONS: u32 = 8;
/// Multiple of the tolerance below which a solve that stops improving has met the rounding
/// noise of the residual and stops there (f32, see [`Evaluator::tolerance`]).
const STALL: f64 = 4.0;
/// Newton step (max norm over the unknowns, by the inverse Jacobian at the solution) above which
/// a solution within the tolerance is ill-determined: the balance of a light ball (0.03-0.2 N on
/// DKFZD4012) is nearly degenerate, a residual of 1e-9 there leaves steps of 1e-4 and an error of
/// 1e-6 in the torque, where well-determined balls leave steps below 1e-8. f64 only.
const SETTLE_STEP: f64 = 1e-6;
/// Factor on the tolerance to which an ill-determined solution is solved on (Newton's method).
const SETTLE_TIGHTEN: f64 = 1e-3;
/// Largest ratio of screw speeds over which an entry of the start table is solved again in one
/// Newton solve from its solution at the other speed ([`Evaluator::with_table_speed_for`]): that of
/// a batch's bands of speed, whose tables are each solved from the band's before.
pub const CARRY_SPEED_RATIO: f64 = 1.1;
/// Most Newton solves along the speed for one entry (1.1^16 = 4.6: beyond that the steps are
/// longer, and an entry whose start does not converge is left out, as a table start then takes
/// the nearest solved one).
const MAX_CARRY_STEPS: f64 = 16.0;
/// Entries of an evaluator's start table, a range of indices per flank
/// ([`Evaluator::table_entries`], [`Evaluator::with_table_speed_for`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct TableEntries {
    /// First and last index, per flank (`None`: none).
    ranges: [Option<(usize, usize)>; 2],
}

impl TableEntries {
    /// Every entry.
    pub const ALL: Self = Self { ranges: [Some((0, TABLE_LEN - 1)); 2] };

    fn add(&mut self, fi: usize, first: usize, last: usize) {
        self.ranges[fi] = Some(match self.ranges[fi] {
            Some((a, b)) => (a.min(first), b.max(last)),
            None => (first, last),
        });
    }

    /// The entries of both.
    pub fn join(&self, other: &Self) -> Self {
        let mut out = *self;
        for (fi, r) in other.ranges.iter().enumerate() {
            if let &Some((a, b)) = r {
                out.add(fi, a, b);
            }
        }
        out
    }
}

/// Newton step in f64 (max norm over the unknowns) from a solution found in f32 above which it
/// is solved on in f64 ([`Evaluator::settle_in_f64`]). The unknowns are the ball's rates and
/// loads relative to their nominal values, of order one: a step of 1e-4 moves the torque by
/// about 1e-4 of one ball's share (measured: 5.7e-5 of the drag at worst over the balls of
/// `f32_where_balls_have_two_states`), within f32's stated 1e-4.
const F32_SETTLE_STEP: f64 = 1e-4;
/// Fraction of [`F32_SETTLE_STEP`] below which the step in f32 alone clears a solution.
const F32_PREFILTER: f64 = 0.25;
/// Newton step (max norm over the unknowns, in f32) within which a warm start whose residual
/// is within [`STALL`] times the tolerance (f32's rounding noise) is a solution without the
/// step ([`Evaluator::broyden`]): a tenth of [`F32_SETTLE_STEP`]. At [`F32_PREFILTER`] of it
/// (2.5e-5, what clears a solution in [`Evaluator::settle_in_f64`]) the f32 torque's worst
/// departure from the model over the default sweep doubled (3.0e-6 to 6.0e-6); at 1e-5 it
/// stays 3.0e-6, at 0.01 residuals a ball more on `warm_ramp`.
const F32_START_STEP: f64 = 1e-5;
/// Whether the Newton step `step` is at most `bound` in every unknown (`all`: a NaN step
/// fails).
fn step_within<F: Real>(step: &[F; N], bound: f64) -> bool {
    let bound = F::of(bound);
    step.iter().all(|e| e.abs() <= bound)
}
/// What builds a ball's constants in f64 for f32's checks ([`Evaluator::settle_in_f64`],
/// [`Evaluator::broyden_refreshed`]), which most solves do not reach: a copy of the model's
/// constants with the films' friction, built for every ball, cost about a tenth of an f32 warm
/// call lubricated and a sixth dry.
#[derive(Clone, Copy)]
struct Wide<'a> {
    model: &'a Model,
    flank: f64,
    /// The raceway contacts' friction (screw, nut) with lubricated contacts, `None` dry.
    friction: Option<(ContactFriction, ContactFriction)>,
}

impl Wide<'_> {
    /// The constants in f64.
    fn constants(&self) -> Constants<f64> {
        match &self.friction {
            Some((screw, nut)) => self.model.lean_with(self.flank, screw, nut),
            None => self.model.lean_dry(self.flank),
        }
    }
}

/// The most balls whose first evaluations share one pass of the lanes (f32's eight).
const MAX_GROUP: usize = 8;

/// A ball of one call, ready for its solve ([`Evaluator::prepare`], [`Evaluator::solve_ball`]).
struct Ball<F: Real> {
    nut: usize,
    circle: usize,
    /// Flank index as solved (turning forwards).
    fi: usize,
    /// The ball's axial load, N.
    p: F,
    /// The residual the model accepts for this ball ([`accepted_residual`]).
    accept: f64,
    /// The raceway contacts' friction (screw, nut) from the films, with lubricated contacts.
    friction: Option<(ContactFriction, ContactFriction)>,
    /// The ball's load turning forwards at the solve's standstill factor.
    load: Load<F>,
    /// The call's standstill factor.
    factor: F,
    /// The call's screw speed, rad/s.
    speed_rad_s: f64,
    first: First<F>,
    /// The ball evaluated at its first start, where the lanes did ([`Evaluator::solve_group`]).
    evaluated: Option<Outcome<F>>,
}

impl<F: Real> Ball<F> {
    /// The first start, if there is one.
    fn start(&self) -> Option<[F; N]> {
        match self.first {
            First::Warm(x) | First::Table(x) => Some(x),
            First::None => None,
        }
    }
}

/// Where a ball's solve starts first.
#[derive(Clone, Copy)]
enum First<F: Real> {
    /// Extrapolated from the ball's memory (with the remembered inverse Jacobian).
    Warm([F; N]),
    /// Interpolated in the table (with the table's inverse Jacobian, taken when it is solved).
    Table([F; N]),
    /// No start: no memory, no solved table entry.
    None,
}

/// Solutions the quadratic warm start takes: a ball's newest three.
const HISTORY: usize = 3;
/// Solutions a ball remembers for its warm start: the quadratic takes the newest
/// [`HISTORY`], the cubic of lubricated contacts in f64 all four (see `BallMemory::start`).
const REMEMBERED: usize = 4;
/// Relative departure of a point's film speed (or load) from the quadratic of the remembered
/// ones in the load (or the film speed) within which the point is taken to lie on their path
/// (see `BallMemory::start`): far below a step of a control loop (1e-4 to 1e-2 of the speed),
/// far above rounding.
const ON_PATH: f64 = 1e-6;
/// Largest sum of the magnitudes of the extrapolation weights (the factor by which the
/// rounding of the remembered solutions can grow) at which a quadratic start is taken.
const MAX_LEBESGUE: f64 = 8.0;
/// The same for the cubic start (equal steps give 15, the quadratic's 7).
const MAX_LEBESGUE_CUBIC: f64 = 16.0;
/// [`ON_PATH`] for the cubic start, whose larger weights make it the more sensitive to a path
/// that is not smooth. A drive cycle's log with its loads written to 1e-3 N (a step of the
/// preload is 0.03 N there, its rounding 3 % of it) lies on its path within 1e-6 but not
/// within 1e-8: at 1e-6 the cubic took 1 % more residuals than the quadratic over its 10,000
/// rows, at 1e-8 0.1 % fewer; on the same cycle unrounded 9 % and 7 % fewer (counted through
/// `ballscrew predict`).
const ON_PATH_CUBIC: f64 = 1e-8;

type Matrix<F> = [[F; N]; N];

/// Per nut and circle, a circle's friction torque by mechanism ([`MECHANISMS`]), N m.
pub(crate) type Groups<F> = [[[F; MECHANISMS]; MAX_CIRCLES_PER_NUT]; MAX_NUTS];

/// The mechanisms of a circle's friction torque, in the order of [`Groups`]: the raceway
/// contacts' creep and sliding, their rolling resistance (EHL and hysteresis), the ball-ball
/// contacts.
pub(crate) const MECHANISMS: usize = 3;

/// One entry of the start table: a ball solved at the entry's load, turning forwards.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Entry<F: Real> {
    x: [F; N],
    /// d x / d ln(load) times ln([`TABLE_RATIO`]): the change over one entry, to first order.
    slope: [F; N],
    /// Inverse of the Jacobian of the balance (scaled residual) at the entry.
    inverse: Matrix<F>,
    /// The screw speed whose films the entry's ball carries, rad/s.
    speed_rad_s: f64,
}

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

/// Warm-start memory of an [`Evaluator`]: per flank as solved (turning forwards) and circle,
/// the ball's last four solutions and its inverse Jacobian.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EvalState<F: Real> {
    balls: [[BallMemory<F>; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct BallMemory<F: Real> {
    /// Number of stored solutions (0 to [`REMEMBERED`]), newest first.
    stored: u8,
    x: [[F; N]; REMEMBERED],
    load_n: [F; REMEMBERED],
    /// The speed whose films each solution's friction is that of: the screw speed's magnitude
    /// (rad/s) with lubricated contacts; 0 with dry ones, whose solutions do not depend on it
    /// (`Evaluator::solve_ball`).
    film_speed: [F; REMEMBERED],
    /// Standstill factor the stored solutions were solved at.
    factor: F,
    /// Inverse Jacobian at the newest solution (Broyden's estimate, or in f64 after a fallback
    /// the finite-difference one there), valid when `stored > 0`.
    inverse: Matrix<F>,
    /// Solves that gave up the warm start for Newton's method or the continuation (test hook).
    #[cfg(test)]
    fallbacks: u32,
    /// Warm starts retried with a fresh Jacobian (test hook).
    #[cfg(test)]
    refreshes: u32,
}

impl<F: Real> BallMemory<F> {
    const EMPTY: Self = Self {
        stored: 0,
        x: [[F::ZERO; N]; REMEMBERED],
        load_n: [F::ZERO; REMEMBERED],
        film_speed: [F::ZERO; REMEMBERED],
        factor: F::ZERO,
        inverse: [[F::ZERO; N]; N],
        #[cfg(test)]
        fallbacks: 0,
        #[cfg(test)]
        refreshes: 0,
    };

    /// Remembers the solution `x` at load `load_n`, film speed `film_speed` and factor
    /// `factor`: on top of the history when the factor is the same, else alone.
    fn push(&mut self, x: [F; N], load_n: F, film_speed: F, factor: F) {
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
    fn start(&self, p: F, film_speed: F, factor: F) -> Option<[F; N]> {
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
            return Some(kinematics::scale_friction_terms(&self.x[0], factor / self.factor));
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
                kinematics::secant_start(&self.x[0], p0, &self.x[1], p1, p)
            } else {
                kinematics::secant_start(&self.x[0], s0, &self.x[1], s1, film_speed)
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
fn combine<F: Real, const K: usize>(weights: &[F; K], x: &[[F; N]; REMEMBERED]) -> [F; N] {
    core::array::from_fn(|i| (1..K).fold(weights[0] * x[0][i], |sum, k| sum + weights[k] * x[k][i]))
}

/// Whether `value` lies on the path of the `remembered` values (a load or a speed): within
/// `tolerance` ([`ON_PATH`], [`ON_PATH_CUBIC`]) of their extrapolation with `weights`.
fn on_path<F: Real, const K: usize>(weights: &[F; K], remembered: &[F; K], value: F, tolerance: f64) -> bool {
    let predicted = (0..K).fold(F::zero(), |sum, k| sum + weights[k] * remembered[k]);
    (predicted - value).abs() <= F::of(tolerance) * value.abs()
}

/// The weights of the cubic through four values of a parameter `t` at `at`
/// ([`lagrange_weights`], bounded by [`MAX_LEBESGUE_CUBIC`]).
fn cubic_weights<F: Real>(t: &[F; REMEMBERED], at: F) -> Option<[F; REMEMBERED]> {
    lagrange_weights(t, at, MAX_LEBESGUE_CUBIC)
}

/// The weights of the quadratic through three values of a parameter `t` at `at`
/// ([`lagrange_weights`], bounded by [`MAX_LEBESGUE`]).
fn quadratic_weights<F: Real>(t: &[F; HISTORY], at: F) -> Option<[F; HISTORY]> {
    lagrange_weights(t, at, MAX_LEBESGUE)
}

/// The weights of the polynomial through the `K` values of a parameter `t` at `at`
/// (Lagrange's: the product of `at - t_j` over that of `t_k - t_j`, `j` not `k`); `None` where
/// the values are not distinct or the sum of the weights' magnitudes exceeds `max_lebesgue`.
fn lagrange_weights<F: Real, const K: usize>(t: &[F; K], at: F, max_lebesgue: f64) -> Option<[F; K]> {
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
fn plane_weights<F: Real>(loads: &[F; HISTORY], speeds: &[F; HISTORY], p: F, s: F) -> Option<[F; HISTORY]> {
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
fn small_weights<F: Real, const K: usize>(weights: [F; K], max_lebesgue: f64) -> Option<[F; K]> {
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
}

fn convert<F: Real>(x: &Unknowns) -> [F; N] {
    core::array::from_fn(|i| F::of(x[i]))
}

/// The inverse of `m` (Gaussian elimination, column by column); `None` when singular.
fn invert<F: Real>(m: &Matrix<F>) -> Option<Matrix<F>> {
    let mut inv = [[F::zero(); N]; N];
    for j in 0..N {
        let mut e = [F::zero(); N];
        e[j] = F::one();
        let col = kinematics::solve_linear(*m, e)?;
        for i in 0..N {
            inv[i][j] = col[i];
        }
    }
    Some(inv)
}

/// `m v`.
#[inline(always)]
fn times<F: Real>(m: &Matrix<F>, v: &[F; N]) -> [F; N] {
    core::array::from_fn(|i| (0..N).fold(F::zero(), |acc, k| acc + m[i][k] * v[k]))
}

/// Broyden's ("good") update of the inverse Jacobian `h` after the step `dx` changed the
/// residual by `dr` (Sherman-Morrison): h += (dx - h dr) (dx^T h) / (dx^T h dr).
fn update_inverse<F: Real>(h: &mut Matrix<F>, dx: &[F; N], dr: &[F; N]) {
    let hdr = times(h, dr);
    let denom = (0..N).fold(F::zero(), |acc, k| acc + dx[k] * hdr[k]);
    if !(denom.abs() > F::TINY) {
        return;
    }
    let row: [F; N] = core::array::from_fn(|j| (0..N).fold(F::zero(), |acc, k| acc + dx[k] * h[k][j]) / denom);
    for i in 0..N {
        let u = dx[i] - hdr[i];
        for j in 0..N {
            h[i][j] += u * row[j];
        }
    }
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

    /// Solves the table: per flank the entry nearest 10 N cold (continuation), then outwards
    /// entry by entry, each from its neighbour.
    fn fill_table(&mut self) {
        let model = self.model;
        for (k, flank) in [1.0, -1.0].into_iter().enumerate() {
            let mut solved = [[0.0; N]; TABLE_LEN];
            self.table_ok[k] = [false; TABLE_LEN];
            fill_table(&model, flank, self.table_speed_rad_s, &mut solved, &mut self.table_ok[k]);
            for i in 0..TABLE_LEN {
                if !self.table_ok[k][i] {
                    continue;
                }
                match entry(&model, flank, self.table_speed_rad_s, i, &solved[i]) {
                    Some(e) => self.table[k][i] = e,
                    None => self.table_ok[k][i] = false,
                }
            }
        }
    }

    /// Solves the entries `entries` of this evaluator's table (its model, its table speed), and
    /// one more on either side of each range (for a start between entries), from `from`'s
    /// entries: each by Newton's method from `from`'s entry of the same load (along the speed
    /// in steps of at most [`CARRY_SPEED_RATIO`] from the speed that entry was last solved at),
    /// else from the last entry solved here (the next lighter ball that solved), else from
    /// `from`'s next lighter entry (the same way along the speed); then, downwards, an entry
    /// that none of these solved from the next heavier entry solved here ([`fill_table`]'s
    /// step, with the model's solve as its fallback). Entries lighter
    /// than [`LIGHT_BALL_N`] over [`TABLE_RATIO`] are left out (the evaluator hands such balls
    /// to the model), and so is an entry that does not solve. The other entries stay as they
    /// are. Whether every entry solved.
    fn carry_entries(&mut self, from: &Self, entries: &TableEntries) -> bool {
        let model = self.model;
        let speed = self.table_speed_rad_s;
        let mut all = true;
        for (k, flank) in [1.0, -1.0].into_iter().enumerate() {
            let Some((first, last)) = entries.ranges[k] else { continue };
            let (lo, hi) = (first.saturating_sub(1), (last + 1).min(TABLE_LEN - 1));
            let mut failed = [false; TABLE_LEN];
            let mut below = None;
            for i in lo..=hi {
                // An entry keeps its last solution (at its speed) when a carry fails: still a
                // start. Speed 0: never solved (light, or beyond the span the table was built
                // for, [`fill_table`]), left out as it is.
                let kept = |j: usize| {
                    let e = &from.table[k][j];
                    (e.speed_rad_s > 0.0).then_some((e.x, e.speed_rad_s))
                };
                if from.table_ok[k][i] && from.table[k][i].speed_rad_s == speed {
                    // Solved at this speed already: kept, and the next entry's start.
                    below = kept(i);
                    continue;
                }
                self.table_ok[k][i] = false;
                if table_load_n(i) * TABLE_RATIO < LIGHT_BALL_N || kept(i).is_none() {
                    continue;
                }
                let lighter = if i > 0 { kept(i - 1) } else { None };
                let solved = [kept(i), below, lighter].into_iter().flatten().find_map(|(start, from_speed)| {
                    let mut x: Unknowns = core::array::from_fn(|j| start[j].to_f64());
                    // Along the speed in steps of at most CARRY_SPEED_RATIO (at most
                    // MAX_CARRY_STEPS of them): an entry left as it was while the bands passed
                    // it is a start of a far speed.
                    let ratio = speed / from_speed;
                    let steps = libm::ceil(libm::fabs(libm::log(ratio)) / libm::log(CARRY_SPEED_RATIO))
                        .clamp(1.0, MAX_CARRY_STEPS);
                    for j in 1..=(steps as u32) {
                        let at = from_speed * libm::pow(ratio, f64::from(j) / steps);
                        let setup = table_setup(&model, table_load_n(i), flank, at);
                        let (_, residual) = kinematics::solve_full(&setup, &mut x, 1.0, 1.0);
                        if !(residual <= setup::TOLERANCE) {
                            return None;
                        }
                    }
                    entry(&model, flank, speed, i, &x)
                });
                if let Some(e) = solved {
                    self.table[k][i] = e;
                    self.table_ok[k][i] = true;
                    below = Some((e.x, speed));
                } else {
                    failed[i] = true;
                }
            }
            // Downwards, each entry that did not carry from the next heavier one solved here,
            // as the table is first solved ([`fill_table`]). Along the speed an entry's steps
            // can end where its branch of steady states ends (docs/model-notes.md item 24), and
            // then every lighter entry lacked a start: carried from 100 to 1745 rpm,
            // DKFZD4012's entries of 0.44-6.5 N on one flank, whose balls each took the
            // model's continuation (2000 random points at 1700-1800 rpm: 1.5 ms a point,
            // against 41 us with them).
            for i in (lo..hi).rev() {
                if !failed[i] || !self.table_ok[k][i + 1] {
                    continue;
                }
                let heavier = |j: usize| {
                    (j < TABLE_LEN && self.table_ok[k][j] && self.table[k][j].speed_rad_s == speed)
                        .then(|| -> Unknowns { core::array::from_fn(|c| self.table[k][j].x[c].to_f64()) })
                };
                let Some(next) = heavier(i + 1) else { continue };
                if let Some(e) = solve_from_neighbours(&model, flank, speed, i, &next, heavier(i + 2).as_ref())
                    .and_then(|x| entry(&model, flank, speed, i, &x))
                {
                    self.table[k][i] = e;
                    self.table_ok[k][i] = true;
                    failed[i] = false;
                }
            }
            all &= !failed.contains(&true);
        }
        all
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
    /// [`LIGHT_BALL_N`] over [`TABLE_RATIO`] are left out: the evaluator hands such balls to the
    /// model. An entry that Newton's method does not solve from there nor from the entry below
    /// it is left out too; a table start then takes the nearest solved one. An entry last
    /// solved at another speed (left as it was by [`Evaluator::with_table_speed_for`]) is
    /// solved along the speed in steps of at most [`CARRY_SPEED_RATIO`]; where that fails, from
    /// the next heavier entry solved at the speed, as the table is first solved. The dry
    /// model's table does not depend on the speed: it is returned as it is.
    pub fn with_table_speed(&self, speed_rad_s: f64) -> Self {
        let speed = table_speed_rad_s(&self.model, speed_rad_s);
        if self.model.oil().is_none() {
            return *self;
        }
        let mut out = *self;
        out.table_speed_rad_s = speed;
        out.carry_entries(self, &TableEntries::ALL);
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
        out.table_speed_rad_s = speed;
        if !out.carry_entries(self, entries) {
            // An entry's branch of steady states ended (item 24): the whole table, whose
            // lighter entries give the start of the other branch. The entries just solved are
            // kept (solved at this speed), the others solved as from this table.
            let partial = out;
            out.carry_entries(&partial, &TableEntries::ALL);
        }
        out
    }

    /// The entries of the start table that the balls of the point at screw speed `speed_rad_s`
    /// (rad/s), preload `preload_n` and axial load `axial_load_n` (N) under `cond` start from
    /// (each ball on its flank as it is solved, turning forwards; see
    /// [`Evaluator::with_table_speed_for`]). Empty for a point the evaluator refuses.
    pub fn table_entries(
        &self,
        speed_rad_s: f64,
        preload_n: f64,
        axial_load_n: f64,
        cond: &Conditions,
    ) -> TableEntries {
        let mut out = TableEntries::default();
        let op = OperatingPoint { speed_rad_s, preload_n, axial_load_n };
        if op.validate().is_err() || cond.validate().is_err() {
            return out;
        }
        let spec = self.model.spec();
        let eff = spec.extensions.effective_operating(&op, cond);
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
                let pos = self.table_position(p);
                if pos.is_finite() {
                    let i = libm::floor(pos.clamp(0.0, (TABLE_LEN - 1) as f64)) as usize;
                    out.add(fi, i, (i + 1).min(TABLE_LEN - 1));
                }
            }
        }
        out
    }

    /// Where the load `load_n` (N) lies in the start table: the index of its entry, fractional
    /// between entries (negative below the first).
    fn table_position(&self, load_n: f64) -> f64 {
        libm::log(load_n / TABLE_FIRST_LOAD_N) * self.per_log_ratio
    }

    /// The screw speed whose films the start table's balls carry, rad/s (the spec's operating
    /// speed, at least the standstill speed, unless set by [`Evaluator::with_table_speed`]).
    pub fn table_speed_rad_s(&self) -> f64 {
        self.table_speed_rad_s
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

    /// The start for a ball of load `load_n` (N) on flank `fi`, turning forwards at factor 1,
    /// from the table, with its inverse Jacobian: the solution interpolated in log load (cubic
    /// Hermite through the two entries around the load) and the inverse Jacobian (written to
    /// `inverse`, where given) linearly; else the nearest solved entry.
    fn table_start(&self, fi: usize, load_n: F, inverse: Option<&mut Matrix<F>>) -> Option<[F; N]> {
        let pos = self.table_position(load_n.to_f64());
        let ok = &self.table_ok[fi];
        let t = &self.table[fi];
        if pos >= 0.0 && pos < (TABLE_LEN - 1) as f64 {
            let i = pos as usize;
            if ok[i] && ok[i + 1] {
                let w = F::of(pos - i as f64);
                let (a, b) = (&t[i], &t[i + 1]);
                let (w2, w3) = (w * w, w * w * w);
                let (two, three) = (F::of(2.0), F::of(3.0));
                let h00 = two * w3 - three * w2 + F::one();
                let h10 = w3 - two * w2 + w;
                let h01 = three * w2 - two * w3;
                let h11 = w3 - w2;
                let x = core::array::from_fn(|j| h00 * a.x[j] + h10 * a.slope[j] + h01 * b.x[j] + h11 * b.slope[j]);
                let v = F::one() - w;
                for (r, row) in inverse.into_iter().flatten().enumerate() {
                    for (c, m) in row.iter_mut().enumerate() {
                        *m = v * a.inverse[r][c] + w * b.inverse[r][c];
                    }
                }
                return Some(x);
            }
        }
        let near = (libm::round(pos.max(0.0)) as usize).min(TABLE_LEN - 1);
        let nearest =
            if ok[near] { near } else { (0..TABLE_LEN).filter(|&i| ok[i]).min_by_key(|&i| i.abs_diff(near))? };
        if let Some(inverse) = inverse {
            *inverse = t[nearest].inverse;
        }
        Some(t[nearest].x)
    }
    /// The two solved entries of flank `fi`'s table around the load `load_n` (N), nearest first,
    /// each as its solution and inverse Jacobian.
    #[allow(clippy::type_complexity)]
    fn table_neighbours(&self, fi: usize, load_n: F) -> [Option<([F; N], Matrix<F>)>; 2] {
        let pos = self.table_position(load_n.to_f64());
        if !(pos >= 0.0 && pos < (TABLE_LEN - 1) as f64) {
            return [None, None];
        }
        let i = pos as usize;
        let (near, far) = if pos - i as f64 <= 0.5 { (i, i + 1) } else { (i + 1, i) };
        let entry = |k: usize| self.table_ok[fi][k].then(|| (self.table[fi][k].x, self.table[fi][k].inverse));
        [entry(near), entry(far)]
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

    /// A ball of load `p` (N) on flank `fi` of nut `nut`, circle `circle`, ready for its solve
    /// ([`Evaluator::solve_ball`]): its constants and load, and its first start, from its
    /// `memory` where that gives one, else from the table. Reads `memory` only.
    #[allow(clippy::too_many_arguments)]
    fn prepare(
        &self,
        nut: usize,
        circle: usize,
        fi: usize,
        p: F,
        p_max: f64,
        film_speed: Option<&FilmSpeed>,
        factor: F,
        op: &OperatingPoint,
        memory: &BallMemory<F>,
    ) -> Ball<F> {
        let friction = self.friction_at(p, film_speed, factor);
        let fk = factor.max(F::of(MIN_SOLVE_FACTOR));
        let speed = self.start_speed(op.speed_rad_s);
        let first = match memory.start(p, speed, fk) {
            Some(x) => First::Warm(x),
            None => match self.table_start(fi, p, None) {
                Some(x) => First::Table(kinematics::scale_friction_terms(&x, fk)),
                None => First::None,
            },
        };
        Ball {
            nut,
            circle,
            fi,
            p,
            accept: accepted_residual(p.to_f64(), p_max),
            friction,
            load: Load { axial_load_n: p, direction: F::one(), factor: fk },
            factor,
            speed_rad_s: op.speed_rad_s,
            first,
            evaluated: None,
        }
    }

    /// The friction of the (screw, nut) contacts of a ball of load `p` (N) at the films' speed
    /// `film_speed` ([`Evaluator::film_speed`]) with standstill factor `factor`, with
    /// lubricated contacts ([`BallFilms`]: the model's, to the bit, the films evaluated once
    /// per ball and call); `None` dry.
    fn friction_at(
        &self,
        p: F,
        film_speed: Option<&FilmSpeed>,
        factor: F,
    ) -> Option<(ContactFriction, ContactFriction)> {
        let (films, speed) = (self.films.as_ref()?, film_speed?);
        Some(films.friction(speed, p.to_f64(), factor.to_f64()))
    }

    /// The constants of a ball on flank `fi` with the contacts' friction `friction`
    /// ([`Evaluator::friction_at`]; dry, the evaluator's own).
    fn constants_with(&self, fi: usize, friction: &Option<(ContactFriction, ContactFriction)>) -> Constants<F> {
        match friction {
            Some((screw, nut)) => self.constants[fi].with_friction(screw, nut),
            None => self.constants[fi],
        }
    }

    /// The constants of `ball`, and in f32 what builds them in f64 (for the Jacobian of a
    /// refreshed start and the check of a solution, [`Evaluator::settle_in_f64`]; built only
    /// where one needs them, [`Wide`]).
    fn ball_constants(&self, ball: &Ball<F>) -> (Constants<F>, Option<Wide<'_>>) {
        let flank = if ball.fi == 0 { 1.0 } else { -1.0 };
        let wide = (!F::FINITE_DIFFERENCES).then_some(Wide { model: &self.model, flank, friction: ball.friction });
        (self.constants_with(ball.fi, &ball.friction), wide)
    }

    /// Solves the balls of `group` (in order, each with its memory in `state`) and adds each
    /// circle's torque to `sum` (and its mechanisms to `groups`): the balance at every ball's
    /// first start evaluated in one pass of the lanes ([`Real::Wide`]: one ball a lane, each
    /// lane the single ball's result to the bit), then each ball's solve from there. Empties
    /// `group`; the first ball that finds no solution is the error.
    fn solve_group(
        &self,
        group: &mut [Option<Ball<F>>],
        state: &mut EvalState<F>,
        direction: F,
        groups: &mut Option<&mut Groups<F>>,
        sum: &mut F,
    ) -> Result<(), Error> {
        let mut which = [0; MAX_GROUP];
        let mut k = 0;
        for (i, ball) in group.iter().enumerate() {
            if ball.as_ref().and_then(Ball::start).is_some() {
                which[k] = i;
                k += 1;
            }
        }
        if k > 1 {
            let mut constants = [&self.constants[0]; MAX_GROUP];
            let dry = ContactFriction::dry(0.0);
            let mut frictions = [(&dry, &dry); MAX_GROUP];
            let mut starts = [[F::zero(); N]; MAX_GROUP];
            let mut loads = [Load { axial_load_n: F::zero(), direction: F::zero(), factor: F::zero() }; MAX_GROUP];
            for (lane, &i) in which[..k].iter().enumerate() {
                if let Some(ball) = group[i].as_ref() {
                    constants[lane] = &self.constants[ball.fi];
                    if let Some((screw, nut)) = &ball.friction {
                        frictions[lane] = (screw, nut);
                    }
                    (starts[lane], loads[lane]) = (ball.start().unwrap_or_default(), ball.load);
                }
            }
            // Every lane on one flank (a nut's circles): that flank's constants in lanes; else
            // gathered lane by lane. With lubricated contacts, each ball's films' friction.
            let fi = group[which[0]].as_ref().map_or(0, |b| b.fi);
            let one_flank = which[..k].iter().all(|&i| group[i].as_ref().is_some_and(|b| b.fi == fi));
            let gathered;
            let c = if one_flank {
                &self.wide[fi]
            } else {
                gathered = Constants::<F::Wide>::gather(&constants[..k]);
                &gathered
            };
            let lubricated;
            let c = if self.films.is_some() {
                let screw: [&ContactFriction; MAX_GROUP] = core::array::from_fn(|i| frictions[i].0);
                let nut: [&ContactFriction; MAX_GROUP] = core::array::from_fn(|i| frictions[i].1);
                lubricated = c.with_frictions(&screw[..k], &nut[..k]);
                &lubricated
            } else {
                c
            };
            let loads = Load::gather(&loads[..k]);
            let first = balance::evaluate(c, &balance::gather_states::<F::Wide>(&starts[..k]), &loads);
            for (lane, &i) in which[..k].iter().enumerate() {
                if let Some(ball) = group[i].as_mut() {
                    // A residual of the ball's solve, counted as where it evaluates one itself.
                    #[cfg(test)]
                    tests::BROYDEN_RESIDUALS.with(|n| n.set(n.get() + 1));
                    ball.evaluated = Some(first.lane(lane));
                }
            }
        }
        let spec = self.model.spec();
        let z = self.balls_per_circle;
        for ball in group.iter().flatten() {
            let (nut, circle) = (ball.nut, ball.circle);
            let memory = &mut state.balls[ball.fi][circle];
            let o = self.solve_ball(ball, memory).ok_or(Error::NoConvergence {
                nut,
                circle,
                iterations: MAX_ITERATIONS,
                residual: f64::INFINITY,
                unphysical: None,
            })?;
            let wz = self.weights[circle] * z;
            let circle_nm = wz
                * direction
                * match spec.model.torque {
                    TorqueRoute::Energy => o.dissipation_per_speed,
                    TorqueRoute::PaperEq27 => o.eq27_nm,
                };
            if let Some(g) = groups.as_deref_mut() {
                g[nut][circle] = match spec.model.torque {
                    TorqueRoute::Energy => {
                        let (rolling, ball_ball) = (o.rolling_dissipation_per_speed, o.ball_ball_dissipation_per_speed);
                        let creep = o.dissipation_per_speed - rolling - ball_ball;
                        [creep, rolling, ball_ball].map(|d| wz * direction * d)
                    }
                    TorqueRoute::PaperEq27 => [circle_nm, F::zero(), F::zero()],
                };
            }
            *sum += circle_nm;
        }
        Ok(())
    }

    /// The speed a lubricated ball's warm start follows (the screw speed's magnitude, rad/s; 0
    /// dry, whose solutions do not depend on it).
    fn start_speed(&self, speed_rad_s: f64) -> F {
        if self.model.oil().is_some() { F::of(libm::fabs(speed_rad_s)) } else { F::zero() }
    }

    /// What screw speed `speed_rad_s` sets in the films of every ball of a call (lubricated
    /// contacts; `None` dry).
    fn film_speed(&self, speed_rad_s: f64) -> Option<FilmSpeed> {
        self.films.as_ref().map(|f| f.speed(speed_rad_s))
    }

    /// Solves `ball` (constants `c`, and in f32 `c64`, the same in f64; load `p` on flank `fi`,
    /// turning forwards at its standstill factor) with its `memory`: by Broyden's method from
    /// its first start (the memory's, with the remembered inverse Jacobian, else with a fresh
    /// one; or the table's), where its group did not run it already ([`Evaluator::solve_group`]);
    /// else from the table; else by Newton's method from the
    /// table's entries around the load, nearest first; else by the model's continuation in f64.
    /// In f32 every solution is checked in f64 ([`Evaluator::settle_in_f64`]) and one that is no
    /// solution there gives way to the next start.
    /// Returns the ball evaluated at its solution, or `None` when nothing converges.
    fn solve_ball(&self, ball: &Ball<F>, memory: &mut BallMemory<F>) -> Option<Outcome<F>> {
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
                    #[cfg(test)]
                    {
                        memory.refreshes += 1;
                    }
                    let refreshed = self.broyden_refreshed(c, c64, &at, start, &mut memory.inverse);
                    settle(refreshed, &mut memory.inverse)
                });
            }
            First::Table(start) => {
                // The table's inverse Jacobian at the load (the start is the one prepared).
                let _ = self.table_start(fi, p, Some(&mut memory.inverse));
                let first = self.broyden(c, &at, start, evaluated, &mut memory.inverse);
                (solved, from_table) = (settle(first, &mut memory.inverse), true);
            }
            First::None => from_table = true,
        }
        if solved.is_none()
            && !from_table
            && let Some(start) = self.table_start(fi, p, Some(&mut memory.inverse))
        {
            let start = kinematics::scale_friction_terms(&start, fk);
            let first = self.broyden(c, &at, start, None, &mut memory.inverse);
            solved = settle(first, &mut memory.inverse);
        }
        if solved.is_none() {
            #[cfg(test)]
            {
                memory.fallbacks += 1;
            }
            // Newton's method from each entry around the load, nearest first, not from the
            // interpolated start: where Broyden's method failed from that, the two entries
            // mostly lie on different steady states (docs/model-notes.md item 24), and the
            // interpolated start on neither. Newton's method from it took its 40 iterations
            // in vain at about two balls in three there (DKFZD4012 at 2250 rpm, balls of
            // 10-16 N), and where it converged it found another state than the model's cold
            // solve more often than the entries do: over 20,000 random points at 10-3000 rpm
            // through the batch, 101 points beyond 1e-8 of the model with it, 59 without, and
            // 46.5 against 22.3 us a point.
            for (x, inverse) in self.table_neighbours(fi, p).into_iter().flatten() {
                memory.inverse = inverse;
                let start = kinematics::scale_friction_terms(&x, fk);
                let next = self.newton(c, &at, start, self.tolerance, &mut memory.inverse);
                solved = settle(next, &mut memory.inverse);
                if solved.is_some() {
                    break;
                }
            }
        }
        if solved.is_none() {
            #[cfg(test)]
            {
                memory.fallbacks += 1;
            }
            solved = self.continuation(fi, &at, c, speed_rad_s, accept, &mut memory.inverse);
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
        Some(balance::evaluate(c, &kinematics::scale_to_factor(&x, factor), &load))
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
    fn broyden(
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
    fn broyden_refreshed(
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
            let res = kinematics::weighted_max_abs(&r, &weights(c64.residual_mu()));
            let mut f = |xx: &[f64; N]| balance::evaluate(c64, xx, &l64).residual;
            *inverse = convert_matrix(&invert(&kinematics::jacobian(&x, &r, self.step_f64.at(res), &mut f))?);
            return self.broyden(c, load, start, None, inverse);
        }
        let r = balance::evaluate(c, &start, load).residual;
        let res = kinematics::weighted_max_abs(&r, &weights(c.residual_mu()));
        let mut f = |xx: &[F; N]| balance::evaluate(c, xx, load).residual;
        *inverse = invert(&kinematics::jacobian(&start, &r, self.step.at(res), &mut f))?;
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
    fn settle_in_f64(
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
        let (_, res) = kinematics::newton(
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
    fn broyden_steps(
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
                #[cfg(test)]
                tests::BROYDEN_RESIDUALS.with(|n| n.set(n.get() + 1));
                balance::evaluate(c, &start, load)
            }
        };
        let w = weights(c.residual_mu());
        let (mut x, mut o) = (start, o);
        let mut res = kinematics::weighted_max_abs(&o.residual, &w);
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
            #[cfg(test)]
            tests::BROYDEN_RESIDUALS.with(|n| n.set(n.get() + 1));
            let res_n = kinematics::weighted_max_abs(&on.residual, &w);
            if res_n <= self.tolerance {
                // Done: the inverse Jacobian here serves the next call as it is.
                return Some((xn, on));
            }
            if !(kinematics::norm2(&on.residual) <= F::of(0.25) * kinematics::norm2(&o.residual)) {
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
    fn newton(
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
        let (_, res) = kinematics::newton(
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
            Some(kinematics::jacobian(&x, &o.residual, F::of(self.step.near), &mut f))
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
    /// [`crate::screw::torque::ACCEPT_RESIDUAL`], or [`crate::screw::torque::LIGHT_BALL_RESIDUAL`] for a ball
    /// below [`crate::screw::torque::LIGHT_BALL_SHARE`] of the heaviest ball's load.
    #[allow(clippy::too_many_arguments)]
    fn continuation(
        &self,
        fi: usize,
        load: &Load<F>,
        c: &Constants<F>,
        speed_rad_s: f64,
        accept: f64,
        inverse: &mut Matrix<F>,
    ) -> Option<([F; N], Outcome<F>)> {
        let flank = if fi == 0 { 1.0 } else { -1.0 };
        let (setup, _) = self.model.ball_setup_at(load.axial_load_n.to_f64(), flank, speed_rad_s, load.factor.to_f64());
        let (x, rep) = kinematics::solve(&setup, None, 1.0, load.factor.to_f64());
        if !(rep.residual <= accept.max(self.tolerance.to_f64())) {
            return None;
        }
        let y = convert(&x);
        *inverse = convert_matrix(&invert(&kinematics::balance_jacobian(&setup, &x))?);
        // Polish in F (the f64 solution rounded may sit just above the tolerance).
        self.newton(c, load, y, self.tolerance, inverse)
            .or_else(|| Some((y, balance::evaluate(c, &y, load))))
            .filter(|(x, _)| c.check_state(x).is_ok())
    }
}

fn convert_matrix<F: Real>(m: &kinematics::Jacobian) -> Matrix<F> {
    core::array::from_fn(|r| core::array::from_fn(|c| F::of(m[r][c])))
}

/// The table entry `i` of flank `flank` from its solution `x` (f64): the inverse Jacobian, and
/// the slope d x / d ln(load) = -J^-1 d r / d ln(load) (the residual's derivative at fixed x by
/// central differences).
fn entry<F: Real>(model: &Model, flank: f64, speed_rad_s: f64, i: usize, x: &Unknowns) -> Option<Entry<F>> {
    let p = table_load_n(i);
    let setup = table_setup(model, p, flank, speed_rad_s);
    let j = kinematics::balance_jacobian(&setup, x);
    let inverse = invert(&j)?;
    let c = Constants::new(&setup, 0.0);
    let eps = 1e-6;
    let r = |q: f64| balance::evaluate(&c, x, &Load { axial_load_n: q, direction: 1.0, factor: 1.0 }).residual;
    let (up, down) = (r(p * libm::exp(eps)), r(p * libm::exp(-eps)));
    let dr: Unknowns = core::array::from_fn(|k| (up[k] - down[k]) / (2.0 * eps));
    let dx = times(&inverse, &dr);
    let h = libm::log(TABLE_RATIO);
    Some(Entry {
        x: convert(x),
        slope: core::array::from_fn(|k| F::of(-dx[k] * h)),
        inverse: convert_matrix(&inverse),
        speed_rad_s,
    })
}

/// Weights of the residual's equations in the convergence test: every equation relative to
/// the nominal load Q. The friction-borne ones (force along t, the three moments) are scaled by
/// f Q in [`balance`] (which keeps Newton's steps well conditioned) and are weighted by f here.
/// Their rounding noise is that of the creep forces, whose stiffness amplifies the rounding of
/// the creepages (about 5e-4 of f Q in f32), while the normal-load equations carry the torque:
/// one tolerance on loads then serves both float types.
fn weights<F: Real>(mu: F) -> [F; N] {
    [mu, F::one(), F::one(), mu, mu, mu, F::one()]
}

/// The setup of a table ball of load `load_n` (N) on `flank`: with lubricated contacts, their
/// films at the spec's operating speed (the table is a start, and the balls' friction changes
/// with the speed: a start near it converges in a few steps where a dry ball's, whose friction
/// coefficient may be a fifth of the lubricated one, does not).
fn table_setup(model: &Model, load_n: f64, flank: f64, speed_rad_s: f64) -> setup::BallSetup {
    model.ball_setup_at(load_n, flank, speed_rad_s, 1.0).0
}

/// The speed of a table's films for screw speed `speed_rad_s`: its magnitude, at least the
/// standstill speed, rad/s.
fn table_speed_rad_s(model: &Model, speed_rad_s: f64) -> f64 {
    libm::fabs(speed_rad_s).max(model.spec().friction.standstill_speed_rad_s)
}

/// Ball load of table entry `i`, N.
fn table_load_n(i: usize) -> f64 {
    TABLE_FIRST_LOAD_N * libm::pow(TABLE_RATIO, i as f64)
}

/// Table entry `i` of flank `flank` at screw speed `speed_rad_s` solved from its neighbour's
/// solution `next` (and `after`, the neighbour's own neighbour on the same side): Newton's method
/// from the line through the two (equally spaced in log load), else the model's solve from
/// `next` (with its fallbacks).
fn solve_from_neighbours(
    model: &Model,
    flank: f64,
    speed_rad_s: f64,
    i: usize,
    next: &Unknowns,
    after: Option<&Unknowns>,
) -> Option<Unknowns> {
    let setup = table_setup(model, table_load_n(i), flank, speed_rad_s);
    let ahead = after.map(|b| -> Unknowns { core::array::from_fn(|j| 2.0 * next[j] - b[j]) });
    let quick = ahead.and_then(|mut y| {
        let (_, residual) = kinematics::solve_full(&setup, &mut y, 1.0, 1.0);
        (residual <= setup::TOLERANCE).then_some(y)
    });
    quick.or_else(|| {
        let (y, rep) = kinematics::solve(&setup, Some(next), 1.0, 1.0);
        (rep.residual <= setup::TOLERANCE).then_some(y)
    })
}

/// Solves the table of one flank: the entry nearest 10 N cold (continuation), then outwards
/// entry by entry, each from its neighbour, from the entry below [`LIGHT_BALL_N`] to the one
/// above the static capacity.
fn fill_table(
    model: &Model,
    flank: f64,
    speed_rad_s: f64,
    table: &mut [Unknowns; TABLE_LEN],
    ok: &mut [bool; TABLE_LEN],
) {
    let load = table_load_n;
    let centre = (libm::log(10.0 / TABLE_FIRST_LOAD_N) / libm::log(TABLE_RATIO)) as usize;
    let solve = |i: usize, from: Option<&Unknowns>| {
        let setup = table_setup(model, load(i), flank, speed_rad_s);
        kinematics::solve(&setup, from, 1.0, 1.0)
    };
    let (x, rep) = solve(centre, None);
    if !(rep.residual <= setup::TOLERANCE) {
        return;
    }
    table[centre] = x;
    ok[centre] = true;
    for dir in [1_isize, -1] {
        let (mut last, mut before) = (x, None::<Unknowns>);
        let mut i = centre as isize + dir;
        // From the lightest to the heaviest entry a table start reads: the evaluator hands
        // lighter balls to the model, and refuses a ball above the static capacity (as the
        // model does); the balances beyond, nearly degenerate or hugely overloaded, are the
        // costliest to solve.
        let read = |i: usize| {
            load(i) * TABLE_RATIO >= LIGHT_BALL_N && model.check_static_capacity(load(i) / TABLE_RATIO).is_ok()
        };
        while (0..TABLE_LEN as isize).contains(&i) && read(i as usize) {
            let Some(y) = solve_from_neighbours(model, flank, speed_rad_s, i as usize, &last, before.as_ref()) else {
                break;
            };
            table[i as usize] = y;
            ok[i as usize] = true;
            (before, last) = (Some(last), y);
            i += dir;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ScrewSpec;
    use crate::input::rpm_to_rad_s;

    std::thread_local! {
        /// Residuals evaluated by Broyden's method on this thread (every test has its own).
        pub(super) static BROYDEN_RESIDUALS: core::cell::Cell<u64> = const { core::cell::Cell::new(0) };
    }

    /// Call `k` of a triangle of period 400 calls (0, 1, ..., 200, ..., 1, 0, ...): the
    /// ramps of the criterion benchmarks `warm_ramp` and `warm_speed_ramp`.
    fn triangle(k: u32) -> f64 {
        let k = k % 400;
        f64::from(if k < 200 { k } else { 400 - k })
    }

    /// In f32 a warm start within the residual's rounding noise whose Newton step is within
    /// `F32_START_STEP` is taken as the solution: on the benchmark's `warm_ramp`
    /// (preload 1900-2100 N, 100-150 rpm, axial load 0-50 N, one step of the triangle a call),
    /// lubricated and dry, Broyden's method evaluates fewer than 1.7 residuals a ball (measured:
    /// 1.46 lubricated, 1.29 dry; 2.10 and 1.93 when every start above the tolerance took a
    /// step, though a third of the balls' exact solutions, rounded to f32, lie above it). No
    /// ball falls back to Newton's method, and fewer than 300 and 150 of the 16,000 ball
    /// solves retry with a fresh Jacobian (measured: 194 and 52; the build before: 548 and
    /// 346), whose residuals in f64 the count leaves out.
    #[test]
    fn f32_warm_starts_within_the_noise_take_no_step() {
        for (lubrication, most_refreshes) in [(crate::Lubrication::Ehl, 300), (crate::Lubrication::Dry, 150)] {
            let (per_ball, fell_back, refreshed) = warm_ramp_residuals_per_ball::<f32>(lubrication);
            std::println!("{lubrication:?}: {per_ball:.3} residuals a ball, {fell_back} fallbacks, {refreshed} fresh");
            assert!(per_ball < 1.7, "{lubrication:?}: {per_ball} residuals a ball");
            assert!(fell_back == 0 && refreshed < most_refreshes, "{lubrication:?}: {fell_back}, {refreshed}");
        }
    }

    /// Broyden's residuals a ball of DKFZD4012 with `lubrication` in `F` over 2000 calls of the
    /// benchmark's `warm_ramp` (preload 1900-2100 N, 100-150 rpm, axial load 0-50 N, one step
    /// of the triangle a call), after 800 calls to warm up; and the fallbacks (Newton's method,
    /// the continuation) and the warm starts retried with a fresh Jacobian over those calls.
    fn warm_ramp_residuals_per_ball<F: Real>(lubrication: crate::Lubrication) -> (f64, u32, u32) {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.model.lubrication = lubrication;
        let ev = Evaluator::<F>::new(&Model::new(&spec).unwrap()).unwrap();
        let mut state = EvalState::new();
        let call = |k: u32, state: &mut EvalState<F>| {
            let t = triangle(k);
            let (w, p, a) = (rpm_to_rad_s(100.0 + 0.25 * t), 1900.0 + t, 0.25 * t);
            ev.torque_nm(F::of(w), F::of(p), F::of(a), state).unwrap();
        };
        (0..800).for_each(|k| call(k, &mut state));
        BROYDEN_RESIDUALS.with(|n| n.set(0));
        let before = fallbacks(&state);
        let calls = 2000;
        (800..800 + calls).for_each(|k| call(k, &mut state));
        let after = fallbacks(&state);
        let balls = f64::from(calls * ev.nuts as u32 * ev.circles as u32);
        (BROYDEN_RESIDUALS.with(|n| n.get()) as f64 / balls, after.0 - before.0, after.1 - before.1)
    }

    /// f32's remembered solutions are taken a Newton step further on, as f64's, so that its warm
    /// start can follow the speed of lubricated contacts: on the benchmark's `warm_speed_ramp`
    /// (2000 N, 100-150 rpm by 0.25 rpm a call; here the triangle shifted by 3 rpm and the
    /// preload by 7 N every period), Broyden's method evaluates fewer than 1.8 residuals a ball
    /// (measured: 1.43; 2.01 extrapolating in the load alone), and the f32 torque departs from
    /// the f64 one at the same inputs by less than 3.5e-7 on average (measured: 2.0e-7; 4.8e-7).
    /// (It retries with a fresh Jacobian more often than the build before, at 826 of the 64,000
    /// ball solves against 428, which the count leaves out; criterion's f32 `warm_speed_ramp`
    /// is faster all the same, 5.4 -> 4.9 us.)
    #[test]
    fn f32_follows_the_speed_of_lubricated_contacts() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let (e32, e64) = (Evaluator::<f32>::new(&model).unwrap(), Evaluator::<f64>::new(&model).unwrap());
        let (mut s32, mut s64) = (EvalState::new(), EvalState::new());
        let (mut sum, mut worst, n) = (0.0, 0.0_f64, 8000);
        let mut residuals = 0;
        for k in 0..n {
            let period = f64::from(k / 400);
            let w = rpm_to_rad_s(100.0 + 0.25 * triangle(k) + 3.0 * period) as f32;
            let p = (2000.0 + 7.0 * period) as f32;
            let before = BROYDEN_RESIDUALS.with(|n| n.get());
            let t32 = f64::from(e32.torque_nm(w, p, 0.0, &mut s32).unwrap());
            residuals += BROYDEN_RESIDUALS.with(|n| n.get()) - before;
            let t64 = e64.torque_nm(f64::from(w), f64::from(p), 0.0, &mut s64).unwrap();
            let d = libm::fabs(t32 - t64) / libm::fabs(t64);
            (sum, worst) = (sum + d, worst.max(d));
        }
        let mean = sum / f64::from(n);
        let per_ball = residuals as f64 / f64::from(n * e32.nuts as u32 * e32.circles as u32);
        std::println!("{per_ball:.3} residuals a ball; mean departure {mean:.2e}, worst {worst:.2e}");
        assert!(per_ball < 1.8, "{per_ball} residuals a ball");
        assert!(mean < 3.5e-7 && worst < 1e-4, "mean {mean:e}, worst {worst:e}");
    }

    /// The Newton and continuation fallbacks of every ball of `state` so far, and the warm starts
    /// retried with a fresh Jacobian.
    fn fallbacks<F: Real>(state: &EvalState<F>) -> (u32, u32) {
        state.balls.iter().flatten().fold((0, 0), |(f, r), m| (f + m.fallbacks, r + m.refreshes))
    }

    /// A warm call at low speed on the lubricated model whose speed differs from the last call's
    /// by a relative 1e-4 (the friction of the films follows the speed, so the remembered
    /// solution is off by about 1e-6) solves from the ball's memory: Broyden's method with the
    /// remembered inverse Jacobian converges, without a fresh Jacobian, and no ball falls back
    /// to Newton's method from the table. The first call, cold, solves from the table (whose
    /// films are the spec's 100 rpm ones, off at low speed) by Newton's method; the inverse it
    /// leaves must be the Jacobian's at the solution (Newton's last Jacobian is Broyden's
    /// estimate carried from the table start, whose inverse failed every following call's first
    /// step at 1-30 rpm).
    #[test]
    fn small_speed_changes_at_low_lubricated_speed_stay_warm() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        assert!(model.oil().is_some(), "the default model is lubricated");
        let ev = Evaluator::<f64>::new(&model).unwrap();
        for rpm in [1.0, 5.0, 10.0, 30.0, 100.0] {
            let w = rpm_to_rad_s(rpm);
            let mut state = EvalState::new();
            ev.torque_nm(w, 2000.0, 0.0, &mut state).unwrap();
            let cold = fallbacks(&state);
            for k in 0..6 {
                let speed = if k % 2 == 0 { w * (1.0 + 1e-4) } else { w };
                ev.torque_nm(speed, 2000.0, 0.0, &mut state).unwrap();
                assert_eq!(fallbacks(&state), cold, "{rpm} rpm, warm call {k}: (Newton fallbacks, fresh Jacobians)");
            }
        }
    }

    /// A sinusoidal motion at 10 rpm peak sampled 500 times a period (what the reversal model
    /// steps through), from 2.5 rpm over the peak and back: the speed changes by up to 1.3 % a
    /// call, and each ball's remembered inverse Jacobian, carried by Broyden's updates over
    /// many calls while the films' friction follows the speed, now and then fails a first step
    /// from a good start. Then a fresh Jacobian at the start, not the table, solves it: no ball
    /// falls back to Newton's method.
    #[test]
    fn a_slow_sinusoid_stays_warm() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let ev = Evaluator::<f64>::new(&model).unwrap();
        let speed = |k: u32| rpm_to_rad_s(10.0) * libm::sin(2.0 * core::f64::consts::PI * f64::from(k) / 500.0);
        let mut state = EvalState::new();
        ev.torque_nm(speed(20), 2000.0, 0.0, &mut state).unwrap();
        let cold = fallbacks(&state);
        for k in 21..=230 {
            ev.torque_nm(speed(k), 2000.0, 0.0, &mut state).unwrap();
            assert_eq!(
                fallbacks(&state).0,
                cold.0,
                "call {k} ({} rad/s): a ball fell back to Newton's method",
                speed(k)
            );
        }
    }

    /// A table solved again at another speed ([`Evaluator::with_table_speed`]) gives the same
    /// torques (the start changes, not the solution): at 1000 rpm, from the spec's 100 rpm
    /// table, points of random preload and axial load agree with the model within 1e-8 (the
    /// evaluator's own agreement), and its entries agree with those of an evaluator built at
    /// 1000 rpm within 1e-6 (both solved to the model's tolerance from different starts).
    #[test]
    fn a_table_at_another_speed_gives_the_same_torques() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let ev = Evaluator::<f64>::new(&model).unwrap();
        let w = rpm_to_rad_s(1000.0);
        let at = ev.with_table_speed(w);
        assert_eq!(at.table_speed_rad_s(), w);
        assert_eq!(ev.with_table_speed(-w).table_speed_rad_s(), w, "the magnitude");
        let mut spec = *model.spec();
        spec.operating.speed_rad_s = w;
        let built = Evaluator::<f64>::new(&Model::new(&spec).unwrap()).unwrap();
        let mut compared = 0;
        for k in 0..2 {
            for i in 0..TABLE_LEN {
                if !(at.table_ok[k][i] && built.table_ok[k][i]) {
                    continue;
                }
                compared += 1;
                for j in 0..N {
                    let (a, b) = (at.table[k][i].x[j], built.table[k][i].x[j]);
                    assert!((a - b).abs() <= 1e-6 * b.abs().max(1.0), "flank {k} entry {i} unknown {j}: {a} vs {b}");
                }
            }
        }
        // (The table spans the balls a start reads: 0.4 N to the static capacity, 75 entries
        // of both flanks on DKFZD4012.)
        // (The table spans the balls a start reads, 0.4 N to the static capacity: 90 entries of
        // both flanks on DKFZD4012. Newton's method does not carry every entry: a jump from 100
        // to 1000 rpm keeps 75, a batch's steps of 10 % 83; a start near a missing entry reads
        // the nearest one or falls back to the continuation, with the same torque.)
        let entries = |e: &Evaluator<f64>| e.table_ok.iter().flatten().filter(|&&ok| ok).count();
        assert!(compared > 60, "{compared} of {} entries compared", entries(&built));
        let mut stepped = ev;
        while stepped.table_speed_rad_s() * 1.1 < w {
            stepped = stepped.with_table_speed(stepped.table_speed_rad_s() * 1.1);
        }
        let kept = entries(&stepped.with_table_speed(w));
        assert!(kept * 10 >= entries(&built) * 8, "in steps of 10 %: {kept} of {} entries", entries(&built));
        let (mut s1, mut s2) = (EvalState::new(), SolverState::new());
        for k in 0..40 {
            let p = 500.0 + 61.3 * f64::from(k);
            let a = -400.0 + 19.7 * f64::from(k);
            let got = at.torque_nm(w, p, a, &mut s1).unwrap();
            let want =
                model.torque(&OperatingPoint { speed_rad_s: w, preload_n: p, axial_load_n: a }, &mut s2).unwrap();
            assert!((got - want).abs() <= 1e-8 * want.abs(), "{p} N, {a} N: {got} vs {want}");
        }
        let mut dry = *model.spec();
        dry.model.lubrication = crate::Lubrication::Dry;
        let dry_ev = Evaluator::<f64>::new(&Model::new(&dry).unwrap()).unwrap();
        assert_eq!(dry_ev.with_table_speed(w), dry_ev, "the dry table does not depend on the speed");
    }

    /// A drive cycle in f32 (the speed a sine of 300 rpm amplitude through its reversals, the
    /// axial load one of 400 N, 2000 calls): where Broyden's method from a ball's memory fails, a
    /// Jacobian taken in f64 restarts it (f32's own finite differences drown in its rounding),
    /// so that few calls fall back to the table's Newton or the continuation (without it, three
    /// in four did, at about 200 us a call against 15 us in f64; with it 24 us).
    #[test]
    fn an_f32_drive_cycle_stays_warm() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let ev = Evaluator::<f32>::new(&model).unwrap();
        let n = 2000;
        let mut state = EvalState::new();
        let mut calls_with_fallbacks = 0;
        for i in 0..n {
            let phase = 2.0 * core::f64::consts::PI * f64::from(i) / f64::from(n);
            let w = rpm_to_rad_s(300.0 * libm::sin(10.0 * phase));
            let a = 400.0 * libm::sin(7.0 * phase);
            let before = fallbacks(&state);
            ev.torque_nm(w as f32, 2000.0, a as f32, &mut state).unwrap();
            let after = fallbacks(&state);
            calls_with_fallbacks += u32::from(after.0 > before.0);
        }
        // Measured: 71 of 2000 calls (1479 without the f64 Jacobian).
        assert!(calls_with_fallbacks < 200, "{calls_with_fallbacks} of {n} calls fell back");
    }

    /// Where both the operating point and the conditions are invalid, the evaluator names the
    /// same field as the model (it named the speed where the model named the running time).
    #[test]
    fn invalid_point_and_conditions_give_the_models_error() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let cond = Conditions { time_h: f64::NAN, ..Conditions::default() };
        let op = OperatingPoint { speed_rad_s: f64::NAN, preload_n: 2000.0, axial_load_n: 0.0 };
        // (Compared as text: the value, NaN, is not equal to itself.)
        let want = std::format!("{:?}", model.torque_at(&op, &cond, &mut SolverState::new()).unwrap_err());
        assert!(want.contains("time_h"), "{want}");
        let ev = Evaluator::<f64>::new(&model).unwrap();
        let got = ev.torque_at_nm(op.speed_rad_s, op.preload_n, op.axial_load_n, &cond, &mut EvalState::new());
        assert_eq!(std::format!("{:?}", got.unwrap_err()), want);
        let ev = Evaluator::<f32>::new(&model).unwrap();
        let got = ev.torque_at_nm(f32::NAN, 2000.0, 0.0, &cond, &mut EvalState::new());
        assert_eq!(std::format!("{:?}", got.unwrap_err()), want);
    }

    /// In f32 a table start can end in a residual valley with no solution. A spec whose
    /// operating speed is 3000 rpm builds its table there; at 1496 rpm a ball of the light nut
    /// (5-9 N) starts from an entry on the other steady state (docs/model-notes.md item 24),
    /// whose branch ends near these loads at this speed, and Newton's method in f32 stops at a
    /// weighted residual of 6e-6 to 9e-6, inside the f32 tolerance of 1e-5, where Newton's
    /// method in f64 from the same state finds no solution. The residual alone cannot tell this
    /// valley from a solution in f32 (its rounding noise is of the same size); the torque was
    /// 1.35e-4 off the model, beyond the 1e-4 the f32 evaluator states. Newton's step from the
    /// solution tells ([`Evaluator::settle_in_f64`]): the evaluator now lands within 1e-4.
    #[test]
    fn f32_table_start_at_a_far_table_speed() {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.operating.speed_rad_s = rpm_to_rad_s(3000.0);
        let model = Model::new(&spec).unwrap();
        let (w, p, a) = (rpm_to_rad_s(1496.406) as f32, 468.331_f32, -216.29_f32);
        let op = OperatingPoint { speed_rad_s: f64::from(w), preload_n: f64::from(p), axial_load_n: f64::from(a) };
        let want = model.torque(&op, &mut SolverState::new()).unwrap();
        let e64 = Evaluator::<f64>::new(&model).unwrap();
        let t64 = e64.torque_nm(op.speed_rad_s, op.preload_n, op.axial_load_n, &mut EvalState::new()).unwrap();
        assert!((t64 - want).abs() <= 1e-8 * want.abs(), "f64 {t64} vs {want}");
        let e32 = Evaluator::<f32>::new(&model).unwrap();
        let t32 = f64::from(e32.torque_nm(w, p, a, &mut EvalState::new()).unwrap());
        let err = (t32 - want).abs() / want.abs();
        assert!(err <= 1e-4, "f32 {t32} vs model {want}: {err:e}");
    }

    /// Broyden's inverse update satisfies the secant condition: the new inverse maps the change
    /// of the residual to the step.
    #[test]
    fn inverse_update_meets_the_secant_condition() {
        let mut h: Matrix<f64> = core::array::from_fn(|i| {
            core::array::from_fn(|j| if i == j { 2.0 } else { 0.1 * (i + 2 * j) as f64 / 7.0 })
        });
        let dx: [f64; N] = core::array::from_fn(|i| 0.3 - 0.07 * i as f64);
        let dr: [f64; N] = core::array::from_fn(|i| 0.5 + 0.11 * (i * i) as f64 / 7.0);
        update_inverse(&mut h, &dx, &dr);
        let back = times(&h, &dr);
        for i in 0..N {
            assert!((back[i] - dx[i]).abs() < 1e-12, "{i}: {back:?} vs {dx:?}");
        }
    }

    /// A ball's memory of the solutions `f(p, w)` at the loads and film speeds `points`,
    /// newest first.
    fn memory_of(f: impl Fn(f64, f64) -> [f64; N], points: &[(f64, f64)]) -> BallMemory<f64> {
        let mut m = BallMemory::<f64>::EMPTY;
        for &(p, w) in points.iter().rev() {
            m.push(f(p, w), p, w, 1.0);
        }
        m
    }

    #[track_caller]
    fn close(got: [f64; N], want: [f64; N], tol: f64) {
        for i in 0..N {
            assert!((got[i] - want[i]).abs() < tol, "{i}: {} against {}", got[i], want[i]);
        }
    }

    /// The quadratic start reproduces a quadratic in load exactly, and refuses loads that are
    /// not distinct or an extrapolation whose weights would amplify the stored solutions' errors.
    #[test]
    fn warm_starts_are_exact_on_quadratics_along_their_path_and_refuse_wild_extrapolation() {
        // A solution quadratic in the load and in the film speed, linear in both together.
        let f = |p: f64, w: f64| -> [f64; N] {
            core::array::from_fn(|i| 1.0 + i as f64 * p - 0.01 * p * p + 0.3 * w - 0.002 * w * w + 0.001 * p * w)
        };
        let memory = |points: &[(f64, f64)]| memory_of(f, points);
        // Along a line in load and speed (a ramp of both, or a dry ball at speed 0): exact.
        for (w0, dw) in [(0.0, 0.0), (10.0, 0.01), (10.0, 0.0)] {
            let m = memory(&[(20.0, w0), (19.9, w0 - dw), (19.8, w0 - 2.0 * dw)]);
            close(m.start(20.1, w0 + dw, 1.0).unwrap(), f(20.1, w0 + dw), 1e-11);
        }
        // A change of speed at constant load: exact (it was the last solution before).
        let m = memory(&[(20.0, 10.0), (20.0, 9.98), (20.0, 9.96)]);
        close(m.start(20.0, 10.02, 1.0).unwrap(), f(20.0, 10.02), 1e-11);
        // Off the path: the plane through the three, first order. With the offsets (u, v) from
        // (20, 10), the others at (u1, 0) and (0, v2), its error is that of the quadratic part
        // a u^2 + b v^2 + c u v: a u (u - u1) + b v (v - v2) + c u v.
        let m = memory(&[(20.0, 10.0), (19.9, 10.0), (20.0, 9.95)]);
        let (u, u1, v, v2) = (0.05, -0.1, 0.025, -0.05);
        let plane_error = -0.01 * u * (u - u1) - 0.002 * v * (v - v2) + 0.001 * u * v;
        close(m.start(20.05, 10.025, 1.0).unwrap(), f(20.05, 10.025).map(|x| x - plane_error), 1e-11);
        // A jump of 5 % in the speed: the quadratic in the load alone.
        let m = memory(&[(20.0, 10.0), (19.9, 9.9), (19.8, 9.8)]);
        let l = quadratic_weights(&[20.0, 19.9, 19.8], 20.1).unwrap();
        let x = [f(20.0, 10.0), f(19.9, 9.9), f(19.8, 9.8)];
        close(
            m.start(20.1, 10.5, 1.0).unwrap(),
            core::array::from_fn(|i| l[0] * x[0][i] + l[1] * x[1][i] + l[2] * x[2][i]),
            1e-12,
        );
        // A jump of 5 % where the speed's quadratic would be taken (its weights 3, -3, 1 and the
        // load on the path): the load alone, here no quadratic (two equal loads) and no secant
        // (three steps ahead), so the last solution.
        let m = memory(&[(20.0, 10.0), (19.95, 9.5), (20.0, 9.0)]);
        assert_eq!(m.start(20.15, 10.5, 1.0).unwrap(), f(20.0, 10.0));
        // Within 1 % of the last solution's speed but not of an older one's: likewise (with the
        // last one's alone the plane through the three would be taken, weights 2.55, -3, 1.45).
        assert_eq!(m.start(20.15, 10.05, 1.0).unwrap(), f(20.0, 10.0));
        // The secant with two solutions, in the speed at constant load: off by
        // f_ww / 2 (w - w0) (w - w1) = -0.002 * 0.02 * 0.04.
        let m = memory(&[(20.0, 10.0), (20.0, 9.98)]);
        close(m.start(20.0, 10.02, 1.0).unwrap(), f(20.0, 10.02).map(|v| v + 0.002 * 0.02 * 0.04), 1e-11);
        // Not distinct, or ten steps ahead (weights above the bound).
        assert!(quadratic_weights(&[20.0, 20.0, 19.8], 20.1).is_none());
        assert!(quadratic_weights(&[20.0, 19.9, 19.8], 21.0).is_none(), "ten steps ahead: weights above the bound");
        assert!(plane_weights(&[20.0, 19.9, 19.8], &[10.0, 10.0, 10.0], 20.1, 10.1).is_none(), "on a line");
        // A jump in load: none (the table's start).
        assert!(memory(&[(20.0, 10.0)]).start(20.3, 10.0, 1.0).is_none());
    }

    /// With four solutions on their path a lubricated ball in f64 starts from the cubic through
    /// them: exact on a cubic along a ramp of load and speed together and along a change of
    /// speed at constant load. Dry (film speed 0) and in f32 it stays the quadratic through the
    /// newest three; off the path, or with equal loads, likewise.
    #[test]
    fn lubricated_warm_starts_in_f64_take_the_cubic_along_their_path() {
        // Cubic in the load and in the film speed.
        let f = |p: f64, w: f64| -> [f64; N] {
            core::array::from_fn(|i| {
                1.0 + i as f64 * p - 0.01 * p * p + 5e-4 * p * p * p + 0.3 * w - 0.002 * w * w
                    + 1e-4 * w * w * w
                    + 0.001 * p * w
            })
        };
        let memory = |points: &[(f64, f64)]| memory_of(f, points);
        let quadratic = |points: &[(f64, f64); 3], p: f64| -> [f64; N] {
            let l = quadratic_weights(&points.map(|(p, _)| p), p).unwrap();
            let x = points.map(|(p, w)| f(p, w));
            core::array::from_fn(|i| l[0] * x[0][i] + l[1] * x[1][i] + l[2] * x[2][i])
        };
        // A ramp of load and speed together: exact (the quadratic is not: the test can fail).
        let ramp = [(20.0, 10.0), (19.9, 9.99), (19.8, 9.98), (19.7, 9.97)];
        let m = memory(&ramp);
        close(m.start(20.1, 10.01, 1.0).unwrap(), f(20.1, 10.01), 1e-11);
        let q = quadratic(&[ramp[0], ramp[1], ramp[2]], 20.1);
        assert!((q[1] - f(20.1, 10.01)[1]).abs() > 1e-8, "the quadratic is off the cubic");
        // A change of speed at constant load: exact.
        let m = memory(&[(20.0, 10.0), (20.0, 9.98), (20.0, 9.96), (20.0, 9.94)]);
        close(m.start(20.0, 10.02, 1.0).unwrap(), f(20.0, 10.02), 1e-11);
        // Dry (film speed 0): the quadratic in the load through the newest three.
        let dry = [(20.0, 0.0), (19.9, 0.0), (19.8, 0.0), (19.7, 0.0)];
        close(memory(&dry).start(20.1, 0.0, 1.0).unwrap(), quadratic(&[dry[0], dry[1], dry[2]], 20.1), 1e-12);
        // f32: the quadratic, here 50 * 6 * 0.1^3 = 0.3 off a steep cubic (the cubic's 0).
        let steep = |p: f64| 1.0 + 50.0 * (p - 20.0) * (p - 20.0) * (p - 20.0);
        let mut m32 = BallMemory::<f32>::EMPTY;
        for &(p, w) in ramp.iter().rev() {
            m32.push([steep(p) as f32; N], p as f32, w as f32, 1.0);
        }
        let got = f64::from(m32.start(20.1, 10.01, 1.0).unwrap()[0]);
        assert!((got - (steep(20.1) - 0.3)).abs() < 1e-4, "f32 takes the quadratic: {got}");
        // Off the path by 1e-7 of the speed (a log's rounding): within the quadratic's 1e-6,
        // not within the cubic's 1e-8, so the quadratic.
        let rounded = [ramp[0], ramp[1], ramp[2], (19.7, 9.97 * (1.0 + 1e-7))];
        close(memory(&rounded).start(20.1, 10.01, 1.0).unwrap(), q, 1e-12);
        // Off the path (the oldest solution at another speed, within 1 % of the point's): the
        // quadratic.
        let off = [(20.0, 10.0), (19.9, 9.99), (19.8, 9.98), (19.7, 9.95)];
        let got = memory(&off).start(20.1, 10.01, 1.0).unwrap();
        let q = quadratic(&[off[0], off[1], off[2]], 20.1);
        close(got, q, 1e-12);
        // A change of speed at constant load whose oldest load is off by 1e-7: the quadratic
        // in the speed through the newest three.
        let speed_path = [(20.0, 10.0), (20.0, 9.98), (20.0, 9.96), (20.0 * (1.0 + 1e-7), 9.94)];
        let l = quadratic_weights(&[10.0, 9.98, 9.96], 10.02).unwrap();
        let x = [f(20.0, 10.0), f(20.0, 9.98), f(20.0, 9.96)];
        let want: [f64; N] = core::array::from_fn(|i| l[0] * x[0][i] + l[1] * x[1][i] + l[2] * x[2][i]);
        close(memory(&speed_path).start(20.0, 10.02, 1.0).unwrap(), want, 1e-12);
        assert!((want[1] - f(20.0, 10.02)[1]).abs() > 1e-9, "the quadratic in the speed is off the cubic");
        // The oldest speed more than 1 % off (a jump before the newest three), on the path: no
        // cubic, and the newest three decide alone, here the quadratic in the speed (not the
        // last solution, as for a jump among them).
        let jumped = [(20.0, 10.0), (20.0, 9.98), (20.0, 9.96), (20.0, 9.5)];
        close(memory(&jumped).start(20.0, 10.02, 1.0).unwrap(), want, 1e-12);
        // Not distinct, or ten steps ahead (weights above the bound).
        assert!(cubic_weights(&[20.0, 19.9, 19.9, 19.7], 20.1).is_none());
        assert!(cubic_weights(&[20.0, 19.9, 19.8, 19.7], 21.0).is_none(), "ten steps ahead");
        assert!(cubic_weights(&[20.0, 19.9, 19.8, 19.7], 20.1).is_some(), "one step ahead: weights 4, -6, 4, -1");
    }

    /// The cubic start saves lubricated balls in f64 the residual the quadratic's error cost
    /// them: on the benchmark's `warm_ramp` Broyden's method evaluates fewer than 1.35
    /// residuals a ball (measured: 1.20; 1.57 with the quadratic).
    #[test]
    fn lubricated_f64_warm_ramp_takes_few_residuals() {
        let (per_ball, fell_back, refreshed) = warm_ramp_residuals_per_ball::<f64>(crate::Lubrication::Ehl);
        std::println!("{fell_back} fallbacks, {refreshed} fresh");
        assert!(fell_back == 0 && refreshed < 60, "{fell_back}, {refreshed}");
        std::println!("{per_ball:.3} residuals a ball");
        assert!(per_ball < 1.35, "{per_ball} residuals a ball");
    }

    /// The table's start and inverse Jacobian, between its entries (where the interpolation is
    /// worst): the start's weighted residual is below 1e-5 of Q (measured about 1e-6 at most),
    /// and one step with the interpolated inverse Jacobian gains at least a factor 100 on it.
    #[test]
    fn table_start_is_close_and_its_inverse_jacobian_steps_well() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let ev = Evaluator::<f64>::new(&model).unwrap();
        for fi in 0..2 {
            for i in 18..57 {
                // Midway between entries, 0.5 N to 3 kN per ball, with the table's friction
                // (the lubricated contacts' at the spec's operating speed).
                let p = table_load_n(i) * TABLE_RATIO.sqrt();
                let speed = ev.film_speed(model.spec().operating.speed_rad_s);
                let c = &ev.constants_with(fi, &ev.friction_at(p, speed.as_ref(), 1.0));
                let w = weights(c.residual_mu());
                let mut h = [[0.0; N]; N];
                let x = ev.table_start(fi, p, Some(&mut h)).unwrap();
                let load = Load { axial_load_n: p, direction: 1.0, factor: 1.0 };
                let r0 = balance::evaluate(c, &x, &load).residual;
                let step = times(&h, &r0);
                let x1: [f64; N] = core::array::from_fn(|i| x[i] - step[i]);
                let r1 = balance::evaluate(c, &x1, &load).residual;
                let (a, b) = (kinematics::weighted_max_abs(&r0, &w), kinematics::weighted_max_abs(&r1, &w));
                // (The lubricated balls' friction changes with their load through the film, so
                // the interpolated start is a little less close than a dry ball's, 1e-5.)
                assert!(a < 3e-5, "flank {fi}, {p} N: start {a:e}");
                assert!(b < 1e-2 * a.max(1e-9), "flank {fi}, {p} N: {a:e} -> {b:e}");
            }
        }
    }
}

#[cfg(test)]
mod partial_table_tests {
    use super::*;
    use crate::input::rpm_to_rad_s;
    use crate::{OperatingPoint, ScrewSpec, SolverState};

    /// A table solved again at another speed for the entries a point starts from
    /// (`with_table_speed_for`): those entries (and one on either side) equal the whole table's
    /// solved at that speed (`with_table_speed`), the others stay the base table's, and the
    /// point's torque from a fresh state is the model's within 1e-8, as with the whole table.
    #[test]
    fn a_table_for_the_entries_of_a_point() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let base = Evaluator::<f64>::new(&model).unwrap();
        let w = rpm_to_rad_s(330.0);
        let (p, a) = (1800.0, 150.0);
        let entries = base.table_entries(w, p, a, &Conditions::default());
        // The four circles' shares of two nuts' loads: 8 of the 86 entries on one flank here.
        let (lo, hi) = entries.ranges[0].unwrap();
        assert!(hi - lo < 10, "{lo}..{hi}");
        let part = base.with_table_speed_for(w, &entries);
        let whole = base.with_table_speed(w);
        assert_eq!(part.table_speed_rad_s(), whole.table_speed_rad_s());
        for (k, r) in entries.ranges.iter().enumerate() {
            for i in 0..TABLE_LEN {
                let carried = r.is_some_and(|(lo, hi)| i + 1 >= lo && i <= hi + 1);
                let want = if carried { &whole } else { &base };
                assert_eq!(part.table_ok[k][i], want.table_ok[k][i], "flank {k}, entry {i}");
                if part.table_ok[k][i] {
                    assert_eq!(part.table[k][i].x, want.table[k][i].x, "flank {k}, entry {i}");
                }
            }
        }
        let op = OperatingPoint { speed_rad_s: w, preload_n: p, axial_load_n: a };
        let m = model.torque(&op, &mut SolverState::new()).unwrap();
        for ev in [&part, &whole] {
            let t = ev.torque_nm(w, p, a, &mut EvalState::new()).unwrap();
            assert!((t - m).abs() <= 1e-8 * m.abs(), "{t} vs model {m}");
        }
        // A point the evaluator refuses starts from no entry.
        assert_eq!(base.table_entries(f64::NAN, p, a, &Conditions::default()), TableEntries::default());
    }

    /// A table carried far along the speed holds every entry that a table solved afresh at
    /// that speed holds. Carried from 100 to 1745 rpm, the Newton steps of one flank's entry
    /// of about 8 N ended where its branch of steady states ends (docs/model-notes.md item
    /// 24), and every lighter entry of that flank, 0.44-6.5 N, was left without a start: each
    /// ball there took the model's continuation (2000 random points at 1700-1800 rpm, 1.5 ms
    /// a point against 41 us). And its points' torques are the model's.
    #[test]
    fn a_table_carried_far_in_speed_holds_every_entry_of_a_fresh_one() {
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let base = Evaluator::<f64>::new(&model).unwrap();
        for rpm in [1735.0, 1744.9, 2250.0] {
            let w = rpm_to_rad_s(rpm);
            let mut spec = ScrewSpec::dkfzd4012();
            spec.operating.speed_rad_s = w;
            let fresh = Evaluator::<f64>::new(&Model::new(&spec).unwrap()).unwrap();
            assert_eq!(fresh.table_speed_rad_s(), w);
            let all = TableEntries::ALL;
            for carried in [base.with_table_speed(w), base.with_table_speed_for(w, &all)] {
                assert_eq!(carried.table_speed_rad_s(), w);
                for k in 0..2 {
                    for i in 0..TABLE_LEN {
                        if fresh.table_ok[k][i] {
                            assert!(carried.table_ok[k][i], "{rpm} rpm: flank {k}, entry {i} not carried");
                            assert_eq!(carried.table[k][i].speed_rad_s, w);
                        }
                    }
                }
            }
            // Its torques are those of the fresh table, the model's at the spec's loads. (At
            // light balls above about 1700 rpm a ball has two steady states, item 24, and an
            // evaluator's table start may land on the one the model's cold solve does not.)
            let ev = base.with_table_speed(w);
            for (p, a) in [(520.0, -452.7), (512.2, 484.5), (1045.2, -214.8), (2000.0, 0.0)] {
                for sign in [1.0, -1.0] {
                    let t = ev.torque_nm(sign * w, p, a, &mut EvalState::new()).unwrap();
                    let f = fresh.torque_nm(sign * w, p, a, &mut EvalState::new()).unwrap();
                    assert!((t - f).abs() <= 1e-8 * f.abs(), "{rpm} rpm, {p} N, {a} N: {t} vs fresh {f}");
                    if p == 2000.0 {
                        let op = OperatingPoint { speed_rad_s: sign * w, preload_n: p, axial_load_n: a };
                        let m = model.torque(&op, &mut SolverState::new()).unwrap();
                        assert!((t - m).abs() <= 1e-8 * m.abs(), "{rpm} rpm: {t} vs model {m}");
                    }
                }
            }
        }
    }
}
