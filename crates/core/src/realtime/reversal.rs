//! The friction torque through reversals, for a servo simulation stepping the screw's rotation:
//! a friction state per circle of balls that re-forms over the rolling distance its contacts
//! travel, instead of the static curve's linear fade through zero speed.
//!
//! After a reversal the tangential tractions of a rolling contact do not flip at once: every
//! element of the contact area keeps its elastic displacement and changes it at the rate of the
//! rigid slip until it reaches its friction bound (Kalker's simplified theory in its transient,
//! time-stepped form; [`crate::contact::presliding`]). The drag therefore re-forms over a small
//! rotation of the screw (the presliding regime), whose size and path set the quadrant glitch a
//! servo engineer tunes friction feed-forward against.
//!
//! # The state model
//! Each circle of balls `g` (nut and circle: all balls of a circle carry the same load) holds its
//! friction torque `z_g` (N m) as three states, one per mechanism (the raceway contacts' creep and
//! sliding, their rolling resistance, the ball-ball contacts: their relaxation lengths differ by
//! orders of magnitude), advanced with the screw rotation `dtheta` of each step
//! by Dahl's first-order law (P.R. Dahl, "A solid friction model", Aerospace Corp. TOR-0158,
//! 1968; "Solid friction damping of mechanical vibrations", AIAA J. 14 (1976) 1675-1682):
//!
//! `dz/dtheta = sigma_g (1 - z sign(dtheta) / g_g(omega))`
//!
//! integrated exactly for each step ([`crate::contact::presliding::dahl_step`]). The bound
//! `g_g(omega)` is the mechanism's share of the circle's steady friction torque from the
//! [`Evaluator`] at the step's speed
//! `omega = dtheta / dt` (lubricated or dry: the model's torque-speed curve), so at constant
//! speed the state settles on, and stays at, the static model's torque. Below the standstill
//! speed (`friction.standstill_speed_rad_s`) the bound is taken at the standstill speed without
//! the static fade: the state model replaces the fade, which is kept only for the static curve
//! and for the seals (see below).
//!
//! The stiffness `sigma_g` (N m per radian of screw rotation) is the initial slope of the
//! mechanism's torque after a reversal, from the circle's contacts at the spec's operating speed
//! ([`Model::evaluate`]), summed over the balls of the circle. Dahl's slope from the reversed
//! steady state is `2 sigma`, so each mechanism's stiffness is half its own reversal slope:
//! - creep and sliding at each raceway contact: `d^2 K / 2`, with `K` the contact's
//!   [`reversal_slope`] (the rate, per unit rolling
//!   distance, at which the work of its tractions on the rigid slip changes while every element
//!   is in adhesion: Kalker's flexibilities over the Hertz ellipse and the contact's creepages)
//!   and `d` the contact's rolling distance per radian of screw rotation;
//! - the rolling resistance (EHL and hysteresis) of each raceway contact: its torque share
//!   re-forms over a rolling distance of the contact's semi-axis `a` along rolling (the pressure
//!   field's asymmetry is renewed as the material passes the ellipse, of length `2a`; Dahl's
//!   curve then reaches 86 % of the bound after `2a`): `T_rr d / a`. This length is a stated
//!   assumption of the order the theory of transient rolling gives (Kalker 1990, ch. 5), not a
//!   derived result;
//! - the ball-ball contact (sliding between neighbours): Mindlin's initial tangential stiffness
//!   of two elastic spheres `k_t = 8 G* a` with `1/G* = 2 (2 - nu) / G` (R.D. Mindlin, "Compliance
//!   of elastic bodies in contact", J. Appl. Mech. 16 (1949) 259-268; K.L. Johnson, Contact
//!   Mechanics, 1985, section 7.1), times the square of its sliding distance per radian, halved.
//!
//! The contacts' slopes differ a little between the directions of rotation under an axial load
//! (the balls' states are not mirror images then); the stiffness is their mean, one value for
//! both directions, because Dahl's law with a stiffness that depends on the direction is not
//! passive (a small out-and-back from rest would return work, and a dither would pump up a
//! one-sided torque).
//!
//! The axial term `F_a L / (2 pi)` is a load torque and passes through unchanged. The seals
//! (`friction.seal_torque_per_nut_nm`) are not contacts of the model: their torque keeps the
//! static curve's standstill fade. Extension terms are not supported: a spec with extensions is
//! refused.
//!
//! # Driving it
//! [`SineMotion`] samples the angles of a sinusoidal motion `theta = A sin(2 pi t / period)`
//! (a circular interpolation's axis through its quadrant change) at equal time steps no longer
//! than a given rotation, its turning points and zero crossings on samples; [`Reformation`]
//! reads off a stepped reversal the angle from the turning point at which the friction torque
//! crosses zero and reaches a fraction of its new steady value. Neither stores more than a few
//! numbers.
//!
//! # Properties (tests)
//! At constant speed above the standstill speed the torque equals the static model's; a reversal
//! stepped at `1e-4` and `1e-6` rad agrees within 1 % (the integration is exact per step, so only
//! the bound's speed dependence sees the step); the work over any closed cycle of rotation
//! started from the relaxed state is non-negative, with and without an axial load (Dahl's law
//! is passive: with the storage `z^2 / (2 sigma)` the work exceeds the change of storage by
//! `integral |dtheta| z^2 / g >= 0`); the lumped curve of one contact against transient
//! FASTSIM (`crates/core/tests/presliding.rs`); no allocation.

use crate::contact::presliding::{dahl_step, reversal_slope};
use crate::error::{Error, InputError};
use crate::input::operating::MAX_SPEED_RAD_S;
use crate::input::{MAX_CIRCLES_PER_NUT, MAX_NUTS, OperatingPoint};
use crate::real::Real;
use crate::realtime::evaluator::{EvalState, Evaluator, Groups, MECHANISMS};
use crate::screw::model::{Model, SolverState};
use crate::screw::report::ContactReport;

/// The reversal (presliding) model of one screw at one preload and axial load: the evaluator for
/// the steady bounds and the stiffness of every circle of balls, mechanism by mechanism.
///
/// From the steady state of one direction, stepped the other way at constant speed, the torque
/// flips over a small rotation and settles on the static model's torque:
///
/// ```
/// use ballscrew_core::input::rpm_to_rad_s;
/// use ballscrew_core::{EvalState, Evaluator, Model, OperatingPoint, ReversalModel, ScrewSpec};
///
/// let model = Model::new(&ScrewSpec::dkfzd4012())?;
/// let ev = Evaluator::<f64>::new(&model)?;
/// let reversal = ReversalModel::new(&ev, 2000.0, 0.0)?;
/// let speed_rad_s = rpm_to_rad_s(-10.0);
/// let op = OperatingPoint { speed_rad_s, preload_n: 2000.0, axial_load_n: 0.0 };
/// let static_nm = ev.torque_nm(&op, &mut EvalState::new())?;
/// let mut state = reversal.steady(-speed_rad_s)?;
/// // A step of 1e-8 rad just after the reversal: the friction still holds its old sign.
/// let first_nm = reversal.step(speed_rad_s * 1e-8, 1e-8, &mut state)?;
/// assert!(first_nm > 0.0 && static_nm < 0.0);
/// // A second at 10 rpm: a turn of 1 rad.
/// let mut torque_nm = first_nm;
/// for _ in 0..1000 {
///     torque_nm = reversal.step(speed_rad_s * 1e-3, 1e-3, &mut state)?;
/// }
/// assert!((torque_nm - static_nm).abs() <= 1e-6 * static_nm.abs(), "{torque_nm} against {static_nm}");
/// # Ok::<(), ballscrew_core::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReversalModel<F: Real> {
    evaluator: Evaluator<F>,
    preload_n: f64,
    axial_load_n: f64,
    /// Per nut, circle and mechanism: Dahl's stiffness, N m/rad.
    stiffness: Groups<F>,
    /// The axial term F_a L / (2 pi), N m.
    axial_nm: F,
    /// The speed the stiffness was found at, rad/s (> 0).
    reference_speed_rad_s: f64,
}

/// The friction state of a [`ReversalModel`]: each circle's friction torque and the evaluator's
/// warm-start memory.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReversalState<F: Real> {
    /// Per nut, circle and mechanism: the friction torque, N m (signed as the drive torque).
    friction_nm: Groups<F>,
    eval: EvalState<F>,
}

/// Number of friction values of a [`ReversalState`] ([`ReversalState::friction_values`]): per
/// nut and circle (all the core's room, used or not), one per mechanism.
pub const FRICTION_VALUES: usize = MAX_NUTS * MAX_CIRCLES_PER_NUT * MECHANISMS;

impl<F: Real> ReversalState<F> {
    /// The friction torque the state holds (all circles), N m, without the axial term and the
    /// seals.
    pub fn friction_nm(&self) -> F {
        self.friction_nm.iter().flatten().flatten().fold(F::zero(), |s, &z| s + z)
    }

    /// The friction torques the state holds, N m: [`FRICTION_VALUES`] values, by nut, circle
    /// and mechanism (0 for circles the screw does not have), for saving the state and setting
    /// it again with [`ReversalModel::with_friction`].
    pub fn friction_values(&self) -> impl Iterator<Item = F> + '_ {
        self.friction_nm.iter().flatten().flatten().copied()
    }

    /// The evaluator's warm-start memory the state carries (the bounds of its last steps'
    /// speed): saved with [`ReversalState::friction_values`] and set again with
    /// [`ReversalState::set_evaluator_state`], a copy continues bit for bit as the original.
    pub fn evaluator_state(&self) -> &EvalState<F> {
        &self.eval
    }

    /// Sets the evaluator's warm-start memory ([`ReversalState::evaluator_state`]).
    pub fn set_evaluator_state(&mut self, eval: EvalState<F>) {
        self.eval = eval;
    }
}

fn input(field: &'static str, value: f64, valid: &'static str) -> Error {
    Error::Input(InputError { field, value, valid })
}

/// The refusal of a point with a ball lighter than [`LIGHT_BALL_N`](crate::realtime::evaluator::LIGHT_BALL_N).
fn light(preload_n: f64) -> Error {
    input("preload_n", preload_n, "every loaded ball above 0.5 N (with the axial load), for the reversal model")
}

/// The refusal of a point where no ball carries a load: no friction to reverse.
fn unloaded(preload_n: f64) -> Error {
    input(
        "preload_n",
        preload_n,
        "a load on the balls (a preload, or an axial load), for the reversal model: without one there is no friction to reverse",
    )
}

/// The Dahl stiffness (N m/rad) of one raceway contact's creep and sliding and of its rolling
/// resistance, for all `balls` (weighted) of its circle, at screw speed `speed_rad_s` (rad/s, > 0).
fn raceway_stiffness(c: &ContactReport, model: &Model, balls: f64, speed_rad_s: f64) -> Result<[f64; 2], Error> {
    if !(c.normal_load_n > 0.0) {
        return Ok([0.0; 2]);
    }
    let d = libm::fabs(c.rolling_speed_m_s) / speed_rad_s;
    let k = reversal_slope(&c.fastsim_input(&model.spec().material))?;
    let rolling = libm::fabs(c.rolling_torque_share_nm + c.hysteresis_torque_share_nm) * d / c.semi_axis_rolling_m;
    Ok([balls * d * d * k / 2.0, rolling])
}

/// The Dahl stiffness (N m/rad) of one ball-ball contact for all `balls` of its circle (Mindlin).
fn ball_ball_stiffness(c: &ContactReport, model: &Model, balls: f64, speed_rad_s: f64) -> f64 {
    if !(c.normal_load_n > 0.0) {
        return 0.0;
    }
    let m = &model.spec().material;
    let g_star = m.shear_modulus_pa() / (2.0 * (2.0 - m.poisson_ratio));
    let k_t = 8.0 * g_star * c.semi_axis_rolling_m;
    let d = libm::fabs(c.slip_speed_m_s) / speed_rad_s;
    balls * k_t * d * d / 2.0
}

/// A step of `rotation_rad` (rad) over `dt_s` (s) as [`ReversalModel::step`] takes it in float
/// type `F`, checked on the values in `F`: the rotation finite, the time step finite and
/// positive, the step's speed at most the model's 30000 rpm. A value that is fine in f64 but not
/// in f32 (a rotation beyond f32's range, a time step that rounds to 0) is refused, so a caller
/// can check a whole series before stepping it. The error names the argument and shows the value
/// as given.
///
/// # Errors
/// An [`InputError`] naming `rotation_rad` or `dt_s`.
pub fn check_step<F: Real>(rotation_rad: f64, dt_s: f64) -> Result<(F, F), InputError> {
    let bad = |field, value, valid| Err(InputError { field, value, valid });
    let dt = F::of(dt_s);
    // A step at the top speed stays at it: a rotation whose speed is within the range in f64
    // is rounded within the rotations the rounded time step allows (30000 rpm over it), not
    // past them (the rounding of dt_s may lower them below the rotation given).
    let most = MAX_SPEED_RAD_S * libm::fabs(dt.to_f64());
    let inside = libm::fabs(rotation_rad / dt_s) <= MAX_SPEED_RAD_S;
    let given = if inside { rotation_rad.max(-most).min(most) } else { rotation_rad };
    let rotation = F::of_within(given, -most, most);
    if !rotation_rad.is_finite() {
        return bad("rotation_rad", rotation_rad, "finite");
    }
    if !rotation.to_f64().is_finite() {
        return bad("rotation_rad", rotation_rad, "finite in f32 (|rotation_rad| below 3.4e38)");
    }
    if !(dt_s.is_finite() && dt_s > 0.0) {
        return bad("dt_s", dt_s, "finite and > 0");
    }
    if !(dt.to_f64().is_finite() && dt.to_f64() > 0.0) {
        return bad("dt_s", dt_s, "finite and > 0 in f32 (1.4e-45 to 3.4e38)");
    }
    if !(libm::fabs(rotation.to_f64() / dt.to_f64()) <= MAX_SPEED_RAD_S) {
        return bad("rotation_rad", rotation_rad, "a rotation whose speed over dt_s is at most 30000 rpm");
    }
    Ok((rotation, dt))
}

impl<F: Real> ReversalModel<F> {
    /// The reversal model of `evaluator`'s screw at `preload_n` and `axial_load_n` (N): the
    /// stiffness of every circle in both directions from the model's contacts at the spec's
    /// operating speed (at least the standstill speed), in f64 (two evaluations of the model:
    /// not for the control loop; build it once per load).
    ///
    /// # Errors
    /// The operating point's errors; `extensions` when the spec has extension terms; `preload_n`
    /// when a loaded ball is lighter than [`LIGHT_BALL_N`](crate::realtime::evaluator::LIGHT_BALL_N); the model's errors at the reference
    /// speed.
    pub fn new(evaluator: &Evaluator<F>, preload_n: f64, axial_load_n: f64) -> Result<Self, Error> {
        let model = evaluator.model();
        let spec = model.spec();
        if !spec.extensions.is_empty() {
            return Err(Error::Unsupported {
                field: "extensions",
                value: "extension terms",
                valid: "none, for the reversal model",
            });
        }
        let standstill = spec.friction.standstill_speed_rad_s;
        let reference = libm::fabs(spec.operating.speed_rad_s).max(standstill);
        let mut stiffness = [[[0.0; MECHANISMS]; MAX_CIRCLES_PER_NUT]; MAX_NUTS];
        let mut axial_nm = 0.0;
        for sign in [1.0, -1.0] {
            let op = OperatingPoint { speed_rad_s: sign * reference, preload_n, axial_load_n };
            op.validate()?;
            // The evaluator's refusal of light balls (and its other errors) first.
            let speed = F::of_within(op.speed_rad_s, -MAX_SPEED_RAD_S, MAX_SPEED_RAD_S);
            if evaluator.creep_torque(&op, speed, &mut EvalState::new(), None)?.is_none() {
                return Err(light(preload_n));
            }
            let e = model.evaluate(&op, &mut SolverState::new())?;
            if !e.balls.iter().take(e.nuts).flat_map(|row| row.iter().take(e.circles)).any(|b| b.axial_load_n > 0.0) {
                return Err(unloaded(preload_n));
            }
            axial_nm = e.summary.axial_term_nm;
            for (nut, row) in e.balls.iter().enumerate().take(e.nuts) {
                for (circle, ball) in row.iter().enumerate().take(e.circles) {
                    let balls = ball.weight * f64::from(ball.balls);
                    let [nut_contact, screw_contact, ball_ball] = &ball.contacts;
                    let [n_creep, n_rolling] = raceway_stiffness(nut_contact, model, balls, reference)?;
                    let [s_creep, s_rolling] = raceway_stiffness(screw_contact, model, balls, reference)?;
                    let bb = ball_ball_stiffness(ball_ball, model, balls, reference);
                    // The mean of the two directions (see the module's documentation).
                    for (k, v) in stiffness[nut][circle].iter_mut().zip([n_creep + s_creep, n_rolling + s_rolling, bb])
                    {
                        *k += v / 2.0;
                    }
                }
            }
        }
        Ok(Self {
            evaluator: *evaluator,
            preload_n,
            axial_load_n,
            stiffness: stiffness.map(|row| row.map(|m| m.map(F::of))),
            axial_nm: F::of(axial_nm),
            reference_speed_rad_s: reference,
        })
    }

    /// The speed the stiffness was found at, rad/s.
    pub fn reference_speed_rad_s(&self) -> f64 {
        self.reference_speed_rad_s
    }

    /// The axial term `F_a L / (2 pi)` of the drive torque, N m: the load torque, the same in
    /// both directions and through a reversal (the friction re-forms on top of it).
    pub fn axial_term_nm(&self) -> F {
        self.axial_nm
    }

    /// The sum of the stiffness of every circle and mechanism, N m/rad: the slope of the friction
    /// torque against the screw angle when the screw starts from rest. Just after a reversal
    /// from steady running each state's slope is its stiffness times `1 + g_before / g_after`
    /// (its steady torques before and after), about twice.
    pub fn stiffness_nm_per_rad(&self) -> F {
        self.stiffness.iter().flatten().flatten().fold(F::zero(), |s, &k| s + k)
    }

    /// A state with no friction stored (every circle's torque 0): the screw at rest after
    /// assembly, or the start of a passivity check.
    pub fn relaxed(&self) -> ReversalState<F> {
        ReversalState {
            friction_nm: [[[F::zero(); MECHANISMS]; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
            eval: EvalState::new(),
        }
    }

    /// A state holding the friction torques `values` (N m, as [`ReversalState::friction_values`]
    /// gives them) with the evaluator's warm-start memory empty (its next solve starts cold,
    /// agreeing with a warm one to the solver's tolerance).
    ///
    /// # Errors
    /// `friction_nm` unless there are [`FRICTION_VALUES`] finite values, 0 for every circle the
    /// screw does not have.
    pub fn with_friction(&self, values: &[F]) -> Result<ReversalState<F>, Error> {
        const VALID: &str =
            "finite friction torques, one per nut, circle and mechanism, 0 where the screw has no circle";
        if values.len() != FRICTION_VALUES {
            return Err(input("friction_nm", values.len() as f64, VALID));
        }
        let g = &self.evaluator.model().spec().geometry;
        let mut state = self.relaxed();
        let mut values = values.iter();
        for (nut, circles) in state.friction_nm.iter_mut().enumerate() {
            for (circle, mechanisms) in circles.iter_mut().enumerate() {
                let present = nut < g.nuts as usize && circle < g.circles_per_nut as usize;
                for (z, &v) in mechanisms.iter_mut().zip(&mut values) {
                    let x = v.to_f64();
                    if !x.is_finite() || (!present && x != 0.0) {
                        return Err(input("friction_nm", x, VALID));
                    }
                    *z = v;
                }
            }
        }
        Ok(state)
    }

    /// A state at the steady friction of screw speed `speed_rad_s` (rad/s, nonzero): the screw
    /// running at that speed for a while. In f32, give 30000 rpm as
    /// `F::of_within(speed, -MAX_SPEED_RAD_S, MAX_SPEED_RAD_S)` ([`Real::of_within`]): the
    /// nearest f32 lies above the range.
    ///
    /// # Errors
    /// `speed_rad_s` when it is zero or not finite or above 30000 rpm; the evaluator's errors.
    pub fn steady(&self, speed_rad_s: F) -> Result<ReversalState<F>, Error> {
        let w = speed_rad_s.to_f64();
        if !(w != 0.0 && libm::fabs(w) <= MAX_SPEED_RAD_S) {
            return Err(input("speed_rad_s", w, "nonzero, |speed| <= 30000 rpm"));
        }
        let mut state = self.relaxed();
        let bounds = self.bounds(w, &mut state.eval)?;
        state.friction_nm = bounds;
        Ok(state)
    }

    /// The model it steps (its evaluator's).
    pub fn model(&self) -> &Model {
        self.evaluator.model()
    }

    /// The steady drive torque the state settles on turning at `speed_rad_s` (rad/s), from the
    /// state's warm evaluator memory (copied: the state is not changed), with the operating
    /// point it is the model's torque at: the speed at least the standstill speed, as
    /// [`ReversalModel::step`] takes the bounds. What an audit
    /// ([`crate::realtime::audit::Audit::check`]) compares with the canonical torque there.
    ///
    /// # Errors
    /// The evaluator's errors at that speed.
    pub fn steady_torque_at(&self, speed_rad_s: f64, state: &ReversalState<F>) -> Result<(OperatingPoint, F), Error> {
        let standstill = self.evaluator.model().spec().friction.standstill_speed_rad_s;
        let w = libm::copysign(libm::fabs(speed_rad_s).max(standstill), speed_rad_s);
        let mut eval = state.eval;
        let bounds = self.bounds(w, &mut eval)?;
        let friction = bounds.iter().flatten().flatten().fold(F::zero(), |s, &z| s + z);
        let op = OperatingPoint { speed_rad_s: w, preload_n: self.preload_n, axial_load_n: self.axial_load_n };
        Ok((op, self.axial_nm + F::of(self.evaluator.model().seal_torque_nm(w)) + friction))
    }

    /// Each circle's steady friction torque by mechanism (signed) turning at `speed_rad_s`, taken
    /// at the standstill speed when slower, without the fade.
    fn bounds(&self, speed_rad_s: f64, eval: &mut EvalState<F>) -> Result<Groups<F>, Error> {
        let standstill = self.evaluator.model().spec().friction.standstill_speed_rad_s;
        let w = libm::copysign(libm::fabs(speed_rad_s).max(standstill), speed_rad_s);
        let op = OperatingPoint { speed_rad_s: w, preload_n: self.preload_n, axial_load_n: self.axial_load_n };
        let mut groups = [[[F::zero(); MECHANISMS]; MAX_CIRCLES_PER_NUT]; MAX_NUTS];
        let speed = F::of_within(w, -MAX_SPEED_RAD_S, MAX_SPEED_RAD_S);
        match self.evaluator.creep_torque(&op, speed, eval, Some(&mut groups))? {
            Some(_) => Ok(groups),
            None => Err(light(self.preload_n)),
        }
    }

    /// Advances `state` by the screw rotation `rotation_rad` (rad, signed) over the time step
    /// `dt_s` (s, > 0) and returns the drive torque at its end, N m: the circles' friction
    /// torques, the axial term and the seals. The step's speed `rotation_rad / dt_s` sets the
    /// steady bounds; a step of zero rotation leaves the friction as it is.
    ///
    /// # Errors
    /// `rotation_rad` or `dt_s` out of range ([`check_step`]); the evaluator's errors at the
    /// step's speed.
    pub fn step(&self, rotation_rad: F, dt_s: F, state: &mut ReversalState<F>) -> Result<F, Error> {
        check_step::<F>(rotation_rad.to_f64(), dt_s.to_f64()).map_err(Error::Input)?;
        let dtheta = rotation_rad.to_f64();
        let speed = dtheta / dt_s.to_f64();
        if dtheta != 0.0 {
            let bounds = self.bounds(speed, &mut state.eval)?;
            for (nut, row) in state.friction_nm.iter_mut().enumerate() {
                for (circle, states) in row.iter_mut().enumerate() {
                    for (m, z) in states.iter_mut().enumerate() {
                        let (bound, stiffness) = (bounds[nut][circle][m].abs(), self.stiffness[nut][circle][m]);
                        *z = dahl_step(*z, bound, stiffness, rotation_rad).map_err(Error::Input)?;
                    }
                }
            }
        }
        let seals = self.evaluator.model().seal_torque_nm(speed);
        Ok(self.axial_nm + F::of(seals) + state.friction_nm())
    }
}

/// Most time steps per period of a [`SineMotion`] (a bound that keeps the step count an exact
/// integer and the phase of every step exact in f64).
pub const MAX_SINE_STEPS_PER_PERIOD: u64 = 1 << 40;

/// A sinusoidal motion of the screw, `theta(t) = A sin(2 pi t / period)`, sampled at equal time
/// steps: the angles a servo simulation steps a [`ReversalModel`] with through its reversals
/// (a circular interpolation's axis reverses so, at the quadrant change).
///
/// The period is `2 pi |A| / peak speed`; the number of steps per period is the smallest
/// multiple of 4 for which no step turns the screw by more than the given largest step (a step
/// turns it by at most `2 |A| sin(pi / n) <= 2 pi |A| / n`). Being a multiple of 4, the zero
/// crossings (steps `0`, `n/2`) and the turning points (`n/4`, `3n/4`) fall on samples, where
/// the angle is exactly `0` or `+-A`. Step `k` is at time `k dt`; nothing is stored but the
/// motion's three numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SineMotion {
    amplitude_rad: f64,
    period_s: f64,
    steps_per_period: u64,
}

impl SineMotion {
    /// The motion of amplitude `amplitude_rad` (rad, signed: negative starts backwards) and peak
    /// speed `peak_speed_rad_s` (rad/s, > 0), sampled so that no step turns the screw by more
    /// than `max_step_rad` (rad, > 0).
    ///
    /// # Errors
    /// `amplitude_rad` when it is zero or not finite; `peak_speed_rad_s` when it is not finite
    /// and > 0; `max_step_rad` when it is not finite and > 0, or so small against the amplitude
    /// that a period would take more than [`MAX_SINE_STEPS_PER_PERIOD`] steps.
    pub fn new(amplitude_rad: f64, peak_speed_rad_s: f64, max_step_rad: f64) -> Result<Self, Error> {
        if !(amplitude_rad.is_finite() && amplitude_rad != 0.0) {
            return Err(input("amplitude_rad", amplitude_rad, "finite and nonzero"));
        }
        if !(peak_speed_rad_s.is_finite() && peak_speed_rad_s > 0.0) {
            return Err(input("peak_speed_rad_s", peak_speed_rad_s, "finite and > 0"));
        }
        if !(max_step_rad.is_finite() && max_step_rad > 0.0) {
            return Err(input("max_step_rad", max_step_rad, "finite and > 0"));
        }
        let a = libm::fabs(amplitude_rad);
        let quarters = libm::ceil(2.0 * core::f64::consts::PI * a / max_step_rad / 4.0).max(1.0);
        if !(quarters * 4.0 <= MAX_SINE_STEPS_PER_PERIOD as f64) {
            return Err(input(
                "max_step_rad",
                max_step_rad,
                "at least 2 pi |amplitude_rad| / 2^40 (at most 2^40 steps per period)",
            ));
        }
        Ok(Self {
            amplitude_rad,
            period_s: 2.0 * core::f64::consts::PI * a / peak_speed_rad_s,
            steps_per_period: 4 * quarters as u64,
        })
    }

    /// The amplitude `A`, rad (signed).
    pub fn amplitude_rad(&self) -> f64 {
        self.amplitude_rad
    }

    /// The period, s.
    pub fn period_s(&self) -> f64 {
        self.period_s
    }

    /// The time steps per period (a multiple of 4).
    pub fn steps_per_period(&self) -> u64 {
        self.steps_per_period
    }

    /// The time step, s.
    pub fn dt_s(&self) -> f64 {
        self.period_s / self.steps_per_period as f64
    }

    /// The time of step `k`, s.
    pub fn time_s(&self, k: u64) -> f64 {
        k as f64 * self.dt_s()
    }

    /// The quadrant of step `k` and its phase in it, rad (`[0, pi/2)`), exact at the quadrant
    /// boundaries.
    fn phase(&self, k: u64) -> (u64, f64) {
        let quarter = self.steps_per_period / 4;
        let j = k % self.steps_per_period;
        (j / quarter, core::f64::consts::FRAC_PI_2 * (j % quarter) as f64 / quarter as f64)
    }

    /// The screw angle at step `k`, rad: `A sin(2 pi k / n)`.
    pub fn angle_rad(&self, k: u64) -> f64 {
        let (q, x) = self.phase(k);
        let s = match q {
            0 => libm::sin(x),
            1 => libm::cos(x),
            2 => 0.0 - libm::sin(x),
            _ => 0.0 - libm::cos(x),
        };
        // `+ 0.0`: a zero angle is +0, whatever the signs.
        self.amplitude_rad * s + 0.0
    }

    /// The screw speed at step `k`, rad/s: `A (2 pi / period) cos(2 pi k / n)`.
    pub fn speed_rad_s(&self, k: u64) -> f64 {
        let (q, x) = self.phase(k);
        let c = match q {
            0 => libm::cos(x),
            1 => 0.0 - libm::sin(x),
            2 => 0.0 - libm::cos(x),
            _ => libm::sin(x),
        };
        self.amplitude_rad * 2.0 * core::f64::consts::PI / self.period_s * c + 0.0
    }

    /// The rotation of step `k` (from step `k - 1` to `k`), rad; 0 for step 0.
    pub fn rotation_rad(&self, k: u64) -> f64 {
        if k == 0 { 0.0 } else { self.angle_rad(k) - self.angle_rad(k - 1) }
    }
}

/// How far the screw turns after a reversal before its friction has re-formed, read off the
/// samples of a stepped reversal: the angle from the turning point at which the friction torque
/// first crosses zero, and at which it first reaches a fraction of its new steady value; each
/// interpolated linearly between the two samples around it.
///
/// The friction torque is the drive torque less the load torque ([`ReversalModel::axial_term_nm`]);
/// the new steady value is its value after the reversal at constant speed (signed: of the new
/// direction). A level reached at the first sample is reached at that sample's angle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reformation {
    steady_after_nm: f64,
    fraction: f64,
    last: Option<(f64, f64)>,
    zero_crossing_rad: Option<f64>,
    reformed_rad: Option<f64>,
}

impl Reformation {
    /// A record of the re-formation toward `steady_after_nm` (N m, nonzero, signed) up to
    /// `fraction` of it (in `(0, 1]`).
    ///
    /// # Errors
    /// `steady_after_nm` when it is zero or not finite; `fraction` out of `(0, 1]`.
    pub fn new(steady_after_nm: f64, fraction: f64) -> Result<Self, Error> {
        if !(steady_after_nm.is_finite() && steady_after_nm != 0.0) {
            return Err(input("steady_after_nm", steady_after_nm, "finite and nonzero"));
        }
        if !(fraction > 0.0 && fraction <= 1.0) {
            return Err(input("fraction", fraction, "(0, 1]"));
        }
        Ok(Self { steady_after_nm, fraction, last: None, zero_crossing_rad: None, reformed_rad: None })
    }

    /// Records a sample: the screw angle from the turning point `angle_rad` (rad, not
    /// decreasing from sample to sample) and the friction torque then, `friction_nm` (N m).
    pub fn record(&mut self, angle_rad: f64, friction_nm: f64) {
        // The friction in units of its new steady value: about -1 at the turning point, 1 after.
        let u = friction_nm / self.steady_after_nm;
        let at = |level: f64| match self.last {
            Some((a0, u0)) if u0 < level && u > u0 => a0 + (angle_rad - a0) * (level - u0) / (u - u0),
            _ => angle_rad,
        };
        if self.zero_crossing_rad.is_none() && u >= 0.0 {
            self.zero_crossing_rad = Some(at(0.0));
        }
        if self.reformed_rad.is_none() && u >= self.fraction {
            self.reformed_rad = Some(at(self.fraction));
        }
        self.last = Some((angle_rad, u));
    }

    /// The angle from the turning point at which the friction torque crossed zero, rad (`None`:
    /// not within the samples).
    pub fn zero_crossing_rad(&self) -> Option<f64> {
        self.zero_crossing_rad
    }

    /// The angle from the turning point at which the friction torque reached the fraction of
    /// its new steady value, rad (`None`: not within the samples).
    pub fn reformed_rad(&self) -> Option<f64> {
        self.reformed_rad
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::PI;

    /// The friction values of a stepped state set again give the same friction, and the next
    /// step agrees to the solver's tolerance (its warm-start memory is not carried); values of
    /// the wrong count, not finite, or on a circle the screw does not have are refused.
    #[test]
    fn friction_values_set_again_give_the_state_back() {
        let evaluator = Evaluator::<f64>::new(&Model::new(&crate::input::ScrewSpec::dkfzd4012()).unwrap()).unwrap();
        let model = ReversalModel::new(&evaluator, 2000.0, 100.0).unwrap();
        let mut state = model.relaxed();
        for _ in 0..5 {
            model.step(2e-5, 1e-3, &mut state).unwrap();
        }
        let values: Vec<f64> = state.friction_values().collect();
        assert_eq!(values.len(), FRICTION_VALUES);
        let mut copy = model.with_friction(&values).unwrap();
        assert_eq!(copy.friction_nm(), state.friction_nm());
        assert!(state.friction_nm() != 0.0);
        let (a, b) = (model.step(-1e-5, 1e-3, &mut state).unwrap(), model.step(-1e-5, 1e-3, &mut copy).unwrap());
        assert!((a - b).abs() <= 1e-9 * a.abs(), "{a} vs {b}");
        for short in [&values[1..], &[]] {
            assert!(matches!(model.with_friction(short), Err(Error::Input(InputError { field: "friction_nm", .. }))));
        }
        let mut bad = values.clone();
        bad[0] = f64::NAN;
        assert!(model.with_friction(&bad).is_err());
        // DKFZD4012 has 2 nuts of 4 circles: the last value is a circle it does not have.
        let mut bad = values;
        *bad.last_mut().unwrap() = 1e-3;
        assert!(matches!(model.with_friction(&bad), Err(Error::Input(InputError { field: "friction_nm", .. }))));
    }

    /// A step is checked on its values in the float type: what f64 holds and f32 does not is
    /// refused in f32, naming the argument; a speed above 30000 rpm is refused in both.
    #[test]
    fn steps_are_checked_in_their_float_type() {
        assert!(check_step::<f64>(1e-3, 1e-3).is_ok());
        let e = check_step::<f32>(1e-3, 1e-50).unwrap_err();
        assert_eq!(e.field, "dt_s");
        assert!(e.valid.contains("in f32"), "{e}");
        let e = check_step::<f32>(1e39, 1e300).unwrap_err();
        assert_eq!(e.field, "rotation_rad");
        for (r, d) in [(1e-3, 1e-50), (1.0, 1e-6), (-1.0, 1e-6)] {
            let e = check_step::<f64>(r, d).unwrap_err();
            assert!(e.field == "rotation_rad" && e.valid.contains("30000 rpm"), "{e}");
        }
        for (r, d, field) in [(f64::NAN, 1.0, "rotation_rad"), (1.0, 0.0, "dt_s"), (1.0, -1.0, "dt_s")] {
            assert_eq!(check_step::<f64>(r, d).unwrap_err().field, field);
        }
        // 3000 rpm over a step is fine; 0 rotation is fine.
        assert!(check_step::<f64>(PI * 100.0 * 1e-3, 1e-3).is_ok());
        assert!(check_step::<f32>(0.0, 1e-3).is_ok());
    }

    #[test]
    fn a_sine_motion_lands_on_its_zero_crossings_and_turning_points() {
        let m = SineMotion::new(0.01, 1.0, 1e-4).unwrap();
        let n = m.steps_per_period();
        assert_eq!(n % 4, 0);
        // The smallest multiple of 4 at or above 2 pi A / h = 628.3.
        assert_eq!(n, 632);
        assert!((m.period_s() - 2.0 * PI * 0.01).abs() < 1e-15);
        assert_eq!(
            [m.angle_rad(0), m.angle_rad(n / 4), m.angle_rad(n / 2), m.angle_rad(3 * n / 4)],
            [0.0, 0.01, -0.0, -0.01]
        );
        assert_eq!(m.angle_rad(n), 0.0);
        assert_eq!(m.angle_rad(n + n / 4), 0.01);
        assert_eq!((m.speed_rad_s(0), m.speed_rad_s(n / 2)), (1.0, -1.0));
        // Zeros are +0 (no `-0` in a report).
        for z in [m.angle_rad(n / 2), m.speed_rad_s(n / 4), m.speed_rad_s(3 * n / 4)] {
            assert!(z == 0.0 && z.is_sign_positive(), "{z}");
        }
        // No step turns by more than the largest step; the steps of a period add up to none.
        let mut largest = 0.0_f64;
        let mut sum = 0.0;
        for k in 1..=n {
            let r = m.rotation_rad(k);
            largest = largest.max(r.abs());
            sum += r;
            let t = m.time_s(k);
            assert!((m.angle_rad(k) - 0.01 * (2.0 * PI * t / m.period_s()).sin()).abs() < 1e-15);
            assert!((m.speed_rad_s(k) - (2.0 * PI * t / m.period_s()).cos()).abs() < 1e-12);
        }
        assert!(largest <= 1e-4 && largest > 0.99e-4, "{largest}");
        assert!(sum.abs() < 1e-15, "{sum}");
        assert_eq!(m.rotation_rad(0), 0.0);
        // Negative amplitude: the mirror image.
        let back = SineMotion::new(-0.01, 1.0, 1e-4).unwrap();
        assert_eq!(back.angle_rad(n / 4), -0.01);
        assert_eq!(back.speed_rad_s(0), -1.0);
        assert!(back.angle_rad(n / 2).is_sign_positive() && back.angle_rad(0).is_sign_positive());
    }

    #[test]
    fn a_sine_motion_refuses_what_it_cannot_sample() {
        for (a, w, h, field) in [
            (0.0, 1.0, 1e-4, "amplitude_rad"),
            (f64::NAN, 1.0, 1e-4, "amplitude_rad"),
            (0.01, 0.0, 1e-4, "peak_speed_rad_s"),
            (0.01, -1.0, 1e-4, "peak_speed_rad_s"),
            (0.01, 1.0, 0.0, "max_step_rad"),
            (0.01, 1.0, f64::INFINITY, "max_step_rad"),
            (1e3, 1.0, 1e-12, "max_step_rad"),
        ] {
            let e = SineMotion::new(a, w, h).unwrap_err();
            assert!(matches!(e, Error::Input(InputError { field: f, .. }) if f == field), "{e}");
        }
        // A step longer than the motion: one step per quarter.
        assert_eq!(SineMotion::new(0.01, 1.0, 1.0).unwrap().steps_per_period(), 4);
    }

    #[test]
    fn the_reformation_is_read_off_the_samples() {
        // A friction going from +1 to -2 N m linearly over 0.4 rad, sampled every 0.1 rad:
        // zero at 0.4/3, 90 % of -2 at 0.4 * 2.8 / 3.
        let mut r = Reformation::new(-2.0, 0.9).unwrap();
        for i in 0..=6 {
            let a = 0.1 * f64::from(i);
            r.record(a, (1.0 - 3.0 * a / 0.4).max(-2.0));
        }
        assert!((r.zero_crossing_rad().unwrap() - 0.4 / 3.0).abs() < 1e-15);
        assert!((r.reformed_rad().unwrap() - 0.4 * 2.8 / 3.0).abs() < 1e-15);
        // Not reached: none; reached at the first sample: its angle.
        let mut r = Reformation::new(1.0, 0.9).unwrap();
        r.record(0.0, -1.0);
        r.record(0.1, 0.5);
        assert!((r.zero_crossing_rad().unwrap() - 0.1 / 1.5).abs() < 1e-15);
        assert_eq!(r.reformed_rad(), None);
        let mut r = Reformation::new(1.0, 0.9).unwrap();
        r.record(0.2, 1.0);
        assert_eq!((r.zero_crossing_rad(), r.reformed_rad()), (Some(0.2), Some(0.2)));
        assert!(Reformation::new(0.0, 0.9).is_err() && Reformation::new(1.0, 1.5).is_err());
    }
}
