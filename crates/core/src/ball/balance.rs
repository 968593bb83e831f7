//! The balance of one ball in lean form, generic over the float type and written over lanes:
//! what Newton's method evaluates, and what the torque of the screw needs from a solved ball.
//!
//! The equations are those of [`crate::ball::report`] (docs/model-notes.md item 11): creepages with spin
//! and Heathcote slip (Eqs. 3-22 as corrected in [`crate::contact::creep`]), Kalker's linear creep forces
//! (Eq. 23) saturated by Eq. (24) ([`crate::contact::forces`]), the force and moment balance of the ball,
//! and the power it dissipates (item 9). [`crate::ball::report::ball_state`] builds the same state
//! with every intermediate kept for the report; this module keeps only scalars and the handful
//! of vectors the balance needs, with every load-independent factor computed once per ball
//! setup ([`Constants`]): the Hertz semi-axes, the approach and the Heathcote depth follow from
//! one cube root of the load. A test holds the two forms together.
//!
//! [`evaluate`] is written over [`Lanes`] ([`crate::real::lanes`]): with `f64` or `f32` it is one
//! ball, with [`Real::Wide`] it is four balls (f64) or eight (f32) in one pass, their constants,
//! states and loads gathered lane by lane ([`Constants::gather`], [`Load::gather`]) and the
//! outcomes taken back ([`Outcome::lane`]). Every branch of one ball is a selection between
//! both sides there, in the same operations and order, so each lane is the single ball's result
//! to the bit (a test).
//!
//! The rate unknowns are per unit screw speed, so the speed enters through its direction alone
//! (item 12), and the standstill factor (item 13) scales the creep forces.

use crate::ball::setup::{self, BallSetup, ContactFriction, MIN_SOLVE_FACTOR, N, RacewaySetup, StateBounds};
use crate::contact::forces;
use crate::contact::saturation::she_ratio_of;
use crate::error::Unphysical;
use crate::input::SpinMoment;
use crate::real::lanes::splat_of;
use crate::real::{Lanes, Real};
use core::ops::{Add, Mul, Neg, Sub};
use nalgebra::{RealField, Vector3};

/// Load-independent factors of one raceway contact.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactConstants<F> {
    /// Semi-axis along the rolling direction per Q^(1/3), m N^(-1/3).
    k_rolling: F,
    /// Elastic approach per Q^(2/3), m N^(-2/3).
    k_approach: F,
    /// Heathcote depth b^2 / (10 R_d) per Q^(2/3) (0 without Heathcote slip), m N^(-2/3).
    k_depth: F,
    /// sqrt(a b) per Q^(1/3), m N^(-1/3).
    k_c: F,
    /// Full-slip spin-moment arm (3/8) a_major E(m) per Q^(1/3), m N^(-1/3).
    k_arm: F,
    /// Kalker's coefficients (creep reduction included).
    c11: F,
    c22: F,
    c23: F,
    c33: F,
    /// Friction coefficient of the contact (the bound of Eq. (24) over Q).
    mu: F,
    /// Rolling resistance on the ball, N ([`crate::ball::lubrication`]).
    rolling_resistance_n: F,
    /// Its hysteresis part.
    hysteresis_fraction: F,
}

/// Everything of one ball's setup that does not change while it is solved, except its load.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Constants<F> {
    rm: F,
    lead_per_rad: F,
    sin_helix: F,
    cos_helix: F,
    rb: F,
    sin_beta: F,
    cos_beta: F,
    /// 1 / (sin beta cos alpha): nominal normal load per axial load.
    nominal_per_axial: F,
    flank: F,
    arc_ratio: F,
    /// Friction coefficient of the ball-ball contacts.
    mu: F,
    /// The scale of the friction-borne equations of the residual (f Q): the largest of
    /// `friction.coefficient` and the raceway contacts' coefficients. Above f (a thin film's
    /// mixed friction) the creep forces, and their rounding noise, grow with the coefficient;
    /// below it (a full film of low traction) the scale stays f, where the balance nears the
    /// degenerate full slip of both contacts and a smaller scale would ask more than the
    /// solvers reach.
    residual_mu: F,
    /// Shear modulus times the continuation's stiffness scale, Pa.
    shear_pa: F,
    separate_spin: bool,
    /// Loads of the ball-ball contacts at +spacing and -spacing, N.
    ball_ball_plus_n: F,
    ball_ball_minus_n: F,
    /// The loads whose friction the two contacts carry, N.
    ball_ball_plus_friction_n: F,
    ball_ball_minus_friction_n: F,
    /// Friction coefficient of the ball-ball contacts.
    ball_ball_mu: F,
    /// (cos, sin, angle) of the spacing of adjacent balls.
    spacing: (F, F, F),
    /// Approach of the ball-ball contact (Eq. 27's lever), m.
    ball_ball_approach_m: F,
    screw: ContactConstants<F>,
    nut: ContactConstants<F>,
    /// The bounds of a physical state ([`setup::check_state`]); the default (unused) in lanes,
    /// whose states are checked ball by ball.
    bounds: StateBounds<F>,
}

impl<F: Real> ContactConstants<F> {
    fn new(s: &BallSetup, rs: &RacewaySetup) -> Self {
        let unit = rs.shape.contact(1.0);
        let (a, b) = (unit.semi_axis_rolling_m, unit.semi_axis_lateral_m);
        let k_depth =
            if s.heathcote && rs.pressure_radius_m > 0.0 { b * b / (10.0 * rs.pressure_radius_m) } else { 0.0 };
        let c = &rs.coefficients;
        Self {
            k_rolling: F::of(a),
            k_approach: F::of(unit.approach_m),
            k_depth: F::of(k_depth),
            k_c: F::of(forces::creep_length_m(a, b)),
            k_arm: F::of(forces::spin_arm_m(a.max(b), rs.shape.complete_e_value())),
            c11: F::of(c.c11),
            c22: F::of(c.c22),
            c23: F::of(c.c23),
            c33: F::of(c.c33),
            mu: F::of(rs.friction.mu),
            rolling_resistance_n: F::of(rs.friction.rolling_resistance_n()),
            hysteresis_fraction: F::of(rs.friction.hysteresis_fraction()),
        }
    }
}

impl<V: Lanes> ContactConstants<V> {
    /// These constants with the friction `f[i]` in lane `i` (the last again beyond `f.len()`,
    /// at least 1).
    fn with_friction(mut self, f: &[&ContactFriction]) -> Self
    where
        V::Scalar: Real,
    {
        let f = lanes_of(f);
        let at = |i: usize| f[i];
        self.mu = V::from_fn(|i| V::Scalar::of(at(i).mu));
        self.rolling_resistance_n = V::from_fn(|i| V::Scalar::of(at(i).rolling_resistance_n()));
        self.hysteresis_fraction = V::from_fn(|i| V::Scalar::of(at(i).hysteresis_fraction()));
        self
    }

    /// Lane `i` from `ball(i)`.
    #[inline(always)]
    fn gather<'a>(ball: impl Fn(usize) -> &'a ContactConstants<V::Scalar>) -> Self
    where
        V::Scalar: 'a,
    {
        macro_rules! lanes {
            ($($f:ident),*) => { Self { $($f: V::from_fn(|i| ball(i).$f)),* } };
        }
        lanes!(
            k_rolling,
            k_approach,
            k_depth,
            k_c,
            k_arm,
            c11,
            c22,
            c23,
            c33,
            mu,
            rolling_resistance_n,
            hysteresis_fraction
        )
    }
}

impl<F: Real> Constants<F> {
    /// The constants of `s` (its axial load is ignored: it is an argument of [`evaluate`]), with
    /// the approach of the ball-ball contact `ball_ball_approach_m` (m).
    pub fn new(s: &BallSetup, ball_ball_approach_m: f64) -> Self {
        let (sin_helix, cos_helix) = libm::sincos(s.helix_angle_rad);
        let (sin_beta, cos_beta) = libm::sincos(s.contact_angle_rad);
        let (ss, cs) = libm::sincos(s.spacing_rad);
        Self {
            rm: F::of(s.rm_m),
            lead_per_rad: F::of(s.lead_per_rad_m),
            sin_helix: F::of(sin_helix),
            cos_helix: F::of(cos_helix),
            rb: F::of(s.rb_m),
            sin_beta: F::of(sin_beta),
            cos_beta: F::of(cos_beta),
            nominal_per_axial: F::of(1.0 / (sin_beta * cos_helix)),
            flank: F::of(s.flank),
            arc_ratio: F::of(s.screw.arc_offset_m / s.nut.arc_offset_m),
            mu: F::of(s.mu),
            residual_mu: F::of(s.mu.max(s.screw.friction.mu).max(s.nut.friction.mu)),
            shear_pa: F::of(s.shear_modulus_pa * s.stiffness_scale),
            separate_spin: s.spin == SpinMoment::Separate,
            ball_ball_plus_n: F::of(s.ball_ball_plus_n),
            ball_ball_minus_n: F::of(s.ball_ball_minus_n),
            ball_ball_plus_friction_n: F::of(s.ball_ball_plus_friction_n),
            ball_ball_minus_friction_n: F::of(s.ball_ball_minus_friction_n),
            ball_ball_mu: F::of(s.ball_ball_mu),
            spacing: (F::of(cs), F::of(ss), F::of(s.spacing_rad)),
            ball_ball_approach_m: F::of(ball_ball_approach_m),
            screw: ContactConstants::new(s, &s.screw),
            nut: ContactConstants::new(s, &s.nut),
            bounds: StateBounds::new(s),
        }
    }

    /// These constants with the raceway contacts' friction `screw` and `nut` of one solve (the
    /// lubricated contacts' values of [`crate::ball::lubrication`]), everything else kept.
    pub fn with_friction(&self, screw: &ContactFriction, nut: &ContactFriction) -> Self {
        self.with_frictions(&[screw], &[nut])
    }

    /// These constants with the ball-ball contacts' loads and friction of `setup`.
    pub fn with_ball_ball(mut self, setup: &BallSetup) -> Self {
        self.ball_ball_plus_n = F::of(setup.ball_ball_plus_n);
        self.ball_ball_minus_n = F::of(setup.ball_ball_minus_n);
        self.ball_ball_plus_friction_n = F::of(setup.ball_ball_plus_friction_n);
        self.ball_ball_minus_friction_n = F::of(setup.ball_ball_minus_friction_n);
        self.ball_ball_mu = F::of(setup.ball_ball_mu);
        self
    }

    /// These constants with the ball-ball contacts' friction coefficient times `scale` (what a
    /// continuation in that friction steps through).
    pub fn with_ball_ball_mu_scaled(mut self, scale: F) -> Self {
        self.ball_ball_mu *= scale;
        self
    }

    /// Whether the state `x` is physical ([`setup::check_state`]): a solve is accepted only then.
    pub fn check_state(&self, x: &[F; N]) -> Result<(), Unphysical> {
        setup::check_state(x, &self.bounds)
    }

    /// The ball's centre and Frenet frame (ball at theta = 0).
    pub(crate) fn frame(&self) -> Frame<F> {
        self.lean_frame().into()
    }

    /// Unit vectors of the two contact lines for tilt gamma: (towards the screw contact,
    /// towards the nut contact); see [`Constants::lines`].
    pub(crate) fn contact_lines(&self, fr: &Frame<F>, gamma: F) -> (Vector3<F>, Vector3<F>) {
        let (u, v) = self.lines(&fr.into(), gamma);
        (u.into(), v.into())
    }

    /// The scaled residual of the balance (see [`Constants::scaled_residual`]) from nalgebra's
    /// vectors: the report form's.
    pub(crate) fn residual(
        &self,
        fr: &Frame<F>,
        force: &Vector3<F>,
        moment: &Vector3<F>,
        screw_force_z_n: F,
        load: &Load<F>,
    ) -> [F; N] {
        self.scaled_residual(&fr.into(), &(*force).into(), &(*moment).into(), screw_force_z_n, load)
    }
}

impl<V: Lanes> Constants<V> {
    /// The constants of [`Lanes::LANES`] balls in lanes: lane `i` is `balls[i]`, the last ball
    /// again beyond `balls.len()` (at least 1).
    pub fn gather(balls: &[&Constants<V::Scalar>]) -> Self {
        let lanes = lanes_of(balls);
        let at = |i: usize| *lanes[i];
        debug_assert!(balls.iter().all(|b| b.separate_spin == balls[0].separate_spin));
        macro_rules! lanes {
            ($($f:ident),*; $($k:ident),*) => {
                Self {
                    $($f: V::from_fn(|i| at(i).$f),)*
                    spacing: (V::from_fn(|i| at(i).spacing.0), V::from_fn(|i| at(i).spacing.1), V::from_fn(|i| at(i).spacing.2)),
                    separate_spin: at(0).separate_spin,
                    $($k: ContactConstants::gather(|i| &at(i).$k),)*
                    bounds: StateBounds::default(),
                }
            };
        }
        lanes!(
            rm, lead_per_rad, sin_helix, cos_helix, rb, sin_beta, cos_beta, nominal_per_axial, flank, arc_ratio, mu,
            residual_mu, shear_pa, ball_ball_plus_n, ball_ball_minus_n, ball_ball_plus_friction_n, ball_ball_minus_friction_n, ball_ball_mu,
            ball_ball_approach_m; screw, nut
        )
    }

    /// These constants with the ball-ball contacts' loads `(plus, minus, plus_friction,
    /// minus_friction)` (N) in every lane.
    pub fn with_ball_ball_loads(mut self, (plus, minus, plus_f, minus_f): (f64, f64, f64, f64)) -> Self {
        self.ball_ball_plus_n = V::splat_f64(plus);
        self.ball_ball_minus_n = V::splat_f64(minus);
        self.ball_ball_plus_friction_n = V::splat_f64(plus_f);
        self.ball_ball_minus_friction_n = V::splat_f64(minus_f);
        self
    }

    /// These constants with the raceway contacts' friction `screw[i]` and `nut[i]` in lane `i`
    /// (the last again beyond their length, at least 1), everything else kept: what the films of
    /// each ball set ([`Constants::with_friction`]).
    pub fn with_frictions(&self, screw: &[&ContactFriction], nut: &[&ContactFriction]) -> Self
    where
        V::Scalar: Real,
    {
        let (s, n) = (lanes_of(screw), lanes_of(nut));
        let mu = |i: usize| (V::Scalar::of(s[i].mu), V::Scalar::of(n[i].mu));
        Self {
            screw: self.screw.with_friction(screw),
            nut: self.nut.with_friction(nut),
            residual_mu: V::from_fn(|i| RealField::max(RealField::max(self.mu.lane(i), mu(i).0), mu(i).1)),
            ..*self
        }
    }

    /// The friction coefficient that scales the friction-borne equations of the residual: the
    /// largest of `friction.coefficient` and the raceway contacts'.
    pub fn residual_mu(&self) -> V {
        self.residual_mu
    }

    /// Nominal normal load Q = P / (sin beta cos alpha) of a ball carrying the axial load `p`, N.
    pub fn nominal_load_n(&self, axial_load_n: V) -> V {
        axial_load_n * self.nominal_per_axial
    }

    /// The ball's centre and Frenet frame (ball at theta = 0).
    fn lean_frame(&self) -> LeanFrame<V> {
        let zero = splat_of::<V>(0.0);
        let (sa, ca) = (self.sin_helix, self.cos_helix);
        LeanFrame {
            centre: V3::new(self.rm, zero, zero),
            t: V3::new(zero, ca, sa),
            n: V3::new(-splat_of::<V>(1.0), zero, zero),
            b: V3::new(zero, -sa, ca),
        }
    }

    /// Unit vectors of the two contact lines for tilt gamma: (towards the screw contact,
    /// towards the nut contact). The nut normal turns by gamma_N = atan(tan(gamma) d_s / d_N),
    /// whose cosine and sine follow from t = tan(gamma_N) as 1 / sqrt(1 + t^2) and
    /// t / sqrt(1 + t^2).
    fn lines(&self, fr: &LeanFrame<V>, gamma: V) -> (V3<V>, V3<V>) {
        let one = splat_of::<V>(1.0);
        let (sb, cb) = (self.sin_beta, self.cos_beta);
        let u0 = fr.n * cb + fr.b * (self.flank * sb);
        let v0 = fr.n * (-sb) + fr.b * (self.flank * cb);
        let (sg, cg) = gamma.small_sin_cos_lanes();
        let tn = sg / cg * self.arc_ratio;
        let cn = one / (one + tn * tn).sqrt_lanes();
        (u0 * cg + v0 * sg, -u0 * cn + v0 * (tn * cn))
    }

    /// The scaled residual of the balance from the force and moment (about the centre) on the
    /// ball and the axial force it exerts on the screw: the force along t and the moments over
    /// the friction scale f Q (f Q r_b), the other forces and the axial load over Q.
    fn scaled_residual(
        &self,
        fr: &LeanFrame<V>,
        force: &V3<V>,
        moment: &V3<V>,
        screw_force_z_n: V,
        load: &Load<V>,
    ) -> [V; N] {
        let one = splat_of::<V>(1.0);
        let q0 = self.nominal_load_n(load.axial_load_n);
        let floor = splat_of::<V>(MIN_SOLVE_FACTOR);
        let fs = self.residual_mu * q0 * V::select(load.factor.gt_mask(floor), load.factor, floor);
        let (per_q, per_f) = (one / q0, one / fs);
        let per_m = per_f / self.rb;
        [
            force.dot(&fr.t) * per_f,
            force.dot(&fr.n) * per_q,
            force.dot(&fr.b) * per_q,
            moment.dot(&fr.t) * per_m,
            moment.dot(&fr.n) * per_m,
            moment.dot(&fr.b) * per_m,
            (self.flank * screw_force_z_n - load.axial_load_n) * per_q,
        ]
    }
}

/// A ball's centre and its Frenet frame (t, n, b).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Frame<F: Real> {
    pub(crate) centre: Vector3<F>,
    pub(crate) t: Vector3<F>,
    pub(crate) n: Vector3<F>,
    pub(crate) b: Vector3<F>,
}

/// [`Frame`] in lanes.
#[derive(Clone, Copy)]
struct LeanFrame<V> {
    centre: V3<V>,
    t: V3<V>,
    n: V3<V>,
    b: V3<V>,
}

/// A vector in space whose components are lanes: nalgebra's `Vector3` operations, each in the
/// same order (a dot product as (x x' + y y') + z z', the cross product and the norm as there).
#[derive(Clone, Copy)]
struct V3<V> {
    x: V,
    y: V,
    z: V,
}

impl<V: Lanes> V3<V> {
    #[inline(always)]
    fn new(x: V, y: V, z: V) -> Self {
        Self { x, y, z }
    }

    #[inline(always)]
    fn zeros() -> Self {
        let z = splat_of::<V>(0.0);
        Self::new(z, z, z)
    }

    #[inline(always)]
    fn dot(&self, o: &Self) -> V {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    #[inline(always)]
    fn cross(&self, o: &Self) -> Self {
        Self::new(self.y * o.z - self.z * o.y, self.z * o.x - self.x * o.z, self.x * o.y - self.y * o.x)
    }

    #[inline(always)]
    fn norm(&self) -> V {
        self.dot(self).sqrt_lanes()
    }

    /// This vector over its norm, component by component.
    #[inline(always)]
    fn normalize(&self) -> Self {
        let n = self.norm();
        Self::new(self.x / n, self.y / n, self.z / n)
    }

    /// Each lane from `yes` where `mask` holds, else from `no`.
    #[inline(always)]
    fn select(mask: V::Mask, yes: Self, no: Self) -> Self {
        Self::new(V::select(mask, yes.x, no.x), V::select(mask, yes.y, no.y), V::select(mask, yes.z, no.z))
    }
}

impl<V: Lanes> Add for V3<V> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl<V: Lanes> Sub for V3<V> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl<V: Lanes> Neg for V3<V> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

impl<V: Lanes> Mul<V> for V3<V> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, k: V) -> Self {
        Self::new(self.x * k, self.y * k, self.z * k)
    }
}

impl<F: Real> From<Vector3<F>> for V3<F> {
    fn from(v: Vector3<F>) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}

impl<F: Real> From<V3<F>> for Vector3<F> {
    fn from(v: V3<F>) -> Self {
        Vector3::new(v.x, v.y, v.z)
    }
}

impl<F: Real> From<&Frame<F>> for LeanFrame<F> {
    fn from(fr: &Frame<F>) -> Self {
        Self { centre: fr.centre.into(), t: fr.t.into(), n: fr.n.into(), b: fr.b.into() }
    }
}

impl<F: Real> From<LeanFrame<F>> for Frame<F> {
    fn from(fr: LeanFrame<F>) -> Self {
        Self { centre: fr.centre.into(), t: fr.t.into(), n: fr.n.into(), b: fr.b.into() }
    }
}

/// Index of a flank (+1 or -1) in per-flank arrays: 0 and 1.
pub(crate) fn flank_index(flank: f64) -> usize {
    if flank > 0.0 { 0 } else { 1 }
}

/// Where a ball is evaluated: its axial load, the direction of rotation and the standstill
/// factor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Load<F> {
    /// The ball's share of its nut's axial load, N.
    pub axial_load_n: F,
    /// +1 or -1: the direction of the screw's rotation.
    pub direction: F,
    /// Standstill factor on the creep forces (1 above the standstill speed).
    pub factor: F,
}

impl<F: Real> Load<F> {
    /// The same load in f64.
    pub fn to_f64(&self) -> Load<f64> {
        Load {
            axial_load_n: self.axial_load_n.to_f64(),
            direction: self.direction.to_f64(),
            factor: self.factor.to_f64(),
        }
    }
}

impl<V: Lanes> Load<V> {
    /// The loads of [`Lanes::LANES`] balls in lanes: lane `i` is `balls[i]`, the last again
    /// beyond `balls.len()` (at least 1).
    pub fn gather(balls: &[Load<V::Scalar>]) -> Self {
        let lanes = lanes_of(balls);
        let at = |i: usize| *lanes[i];
        Load {
            axial_load_n: V::from_fn(|i| at(i).axial_load_n),
            direction: V::from_fn(|i| at(i).direction),
            factor: V::from_fn(|i| at(i).factor),
        }
    }
}

/// The states of [`Lanes::LANES`] balls in lanes: lane `i` is `states[i]`, the last again
/// beyond `states.len()` (at least 1).
pub fn gather_states<V: Lanes>(states: &[[V::Scalar; N]]) -> [V; N] {
    let lanes = lanes_of(states);
    core::array::from_fn(|j| V::from_fn(|i| lanes[i][j]))
}

/// The most lanes of any [`Lanes`] type of the crate.
pub const MAX_LANES: usize = 8;

/// One item a lane: lane `i` is `items[i]`, the last item again beyond `items.len()` (at least
/// 1), what every gathering into lanes takes.
fn lanes_of<T>(items: &[T]) -> [&T; MAX_LANES] {
    let last = items.len() - 1;
    core::array::from_fn(|i| &items[i.min(last)])
}

/// A ball evaluated in one state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome<F> {
    /// Scaled residual of the balance (zero when the ball is in balance).
    pub residual: [F; N],
    /// Power dissipated in the ball's contacts per unit screw speed, J/rad (the ball-ball
    /// contact ahead counted, the one behind belongs to the ball behind).
    pub dissipation_per_speed: F,
    /// Moment about the screw axis of everything the ball exerts on the screw, N m.
    pub screw_moment_z_nm: F,
    /// Axial force the ball exerts on the screw, N.
    pub screw_force_z_n: F,
    /// Eq. (27) as printed: friction magnitudes times (r_b - delta), summed over the contacts, N m.
    pub eq27_nm: F,
    /// The rolling resistances' part of `dissipation_per_speed` (EHL and hysteresis), J/rad.
    pub rolling_dissipation_per_speed: F,
    /// The hysteresis part of `rolling_dissipation_per_speed`, J/rad.
    pub hysteresis_dissipation_per_speed: F,
    /// The ball-ball contact's part of `dissipation_per_speed`, J/rad.
    pub ball_ball_dissipation_per_speed: F,
    /// The ball's orbit rate (rad per rad of the screw): the state's.
    pub orbit: F,
}

impl<V: Lanes> Outcome<V> {
    /// The ball of lane `i`.
    pub fn lane(&self, i: usize) -> Outcome<V::Scalar> {
        Outcome {
            residual: core::array::from_fn(|j| self.residual[j].lane(i)),
            dissipation_per_speed: self.dissipation_per_speed.lane(i),
            screw_moment_z_nm: self.screw_moment_z_nm.lane(i),
            screw_force_z_n: self.screw_force_z_n.lane(i),
            eq27_nm: self.eq27_nm.lane(i),
            rolling_dissipation_per_speed: self.rolling_dissipation_per_speed.lane(i),
            hysteresis_dissipation_per_speed: self.hysteresis_dissipation_per_speed.lane(i),
            ball_ball_dissipation_per_speed: self.ball_ball_dissipation_per_speed.lane(i),
            orbit: self.orbit.lane(i),
        }
    }
}

/// The ball's motion per unit screw speed.
struct Motion<V> {
    centre: V3<V>,
    v_centre: V3<V>,
    omega: V3<V>,
    orbit: V,
    t: V3<V>,
}

/// One raceway contact's share of the ball's balance.
struct ContactPart<V> {
    force: V3<V>,
    moment: V3<V>,
    dissipation: V,
    /// The rolling resistance's part of `dissipation`.
    rolling_dissipation: V,
    /// The hysteresis part of `rolling_dissipation`.
    hysteresis_dissipation: V,
    eq27: V,
    /// Moment about the screw axis and axial force of what the ball exerts on this body.
    on_body_moment_z: V,
    on_body_force_z: V,
}

#[inline(always)]
fn helical<V: Lanes>(p: &V3<V>, rate: V, h: V) -> V3<V> {
    V3::new(-p.y * rate, p.x * rate, h * rate)
}

#[inline(always)]
fn saturation_ratio<V: Lanes>(magnitude: V, bound: V) -> V {
    let zero = splat_of::<V>(0.0);
    V::choose(bound.gt_mask(zero), || she_ratio_of(magnitude / bound), || zero)
}

#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn contact<V: Lanes>(
    c: &Constants<V>,
    k: &ContactConstants<V>,
    screw: bool,
    u: &V3<V>,
    load_n: V,
    m: &Motion<V>,
    load: &Load<V>,
) -> ContactPart<V> {
    let zero = splat_of::<V>(0.0);
    let one = splat_of::<V>(1.0);
    let half = splat_of::<V>(0.5);
    let q = V::select(load_n.gt_mask(zero), load_n, zero);
    let q13 = V::choose(q.gt_mask(zero), || q.cube_root_lanes(), || zero);
    let q23 = q13 * q13;
    let approach = k.k_approach * q23;
    let rho = c.rb - half * approach;
    let arm = *u * (rho - k.k_depth * q23);
    let x = m.centre + arm;
    let h = c.lead_per_rad;
    let v_ball = m.v_centre + m.omega.cross(&arm);
    let g = -*u;
    let (v_race, spin) =
        if screw { (helical(&x, one, h), m.omega.dot(&g) - g.z) } else { (V3::zeros(), m.omega.dot(&g)) };
    let slip = v_ball - v_race;
    let mean = (v_ball + v_race) * half - helical(&x, m.orbit, h);
    let dir = load.direction;
    let sigma = V::select(mean.dot(&m.t).ge_mask(zero), one, -one);
    let e = m.t * (-sigma * dir);
    let f = g.cross(&e);
    let v_unit = mean.norm();
    // Rates so large that the rolling speed overflows: the creepages are not zero but unknown
    // (their ratios stay finite), and a residual built on zeros would balance any such state
    // with the normal loads alone. At no rolling speed, no creepage.
    let (finite, moving) = (v_unit.finite_mask(), v_unit.gt_mask(zero));
    let creepage = |value: V| V::select(finite, V::select(moving, value, zero), splat_of::<V>(f64::NAN));
    let kk = dir / v_unit;
    let (xi, eta, phi) = (creepage(kk * slip.dot(&e)), creepage(kk * slip.dot(&f)), creepage(kk * spin));
    // Kalker's linear forces (Eq. 23), c = sqrt(a b).
    let cc = k.k_c * q13;
    let gc2 = c.shear_pa * cc * cc;
    let fe = -gc2 * k.c11 * xi;
    let ff = -gc2 * (k.c22 * eta + k.c23 * cc * phi);
    let mz = gc2 * cc * (k.c23 * eta - k.c33 * cc * phi);
    // Saturation (Eq. 24), with the spin moment combined or on its own.
    let bound = k.mu * q;
    let spin_arm = k.k_arm * q13;
    let force_mag = (fe * fe + ff * ff).sqrt_lanes();
    let (ratio, moment_ratio) = if c.separate_spin {
        (saturation_ratio(force_mag, bound), saturation_ratio(mz.abs_lanes(), bound * spin_arm))
    } else {
        let ml = V::choose(spin_arm.gt_mask(zero), || mz / spin_arm, || zero);
        let r = saturation_ratio((force_mag * force_mag + ml * ml).sqrt_lanes(), bound);
        (r, r)
    };
    let fe = fe * ratio * load.factor;
    let ff = ff * ratio * load.factor;
    let mz = mz * moment_ratio * load.factor;
    let tangential = e * fe + f * ff;
    let normal_force = g * q;
    // Rolling resistance through the ball centre along the rolling direction, in the sense of
    // the entrainment velocity (crate::ball::lubrication); the raceway carries it back on the
    // same line.
    let resisting = V::and_mask(k.rolling_resistance_n.gt_mask(zero), V::and_mask(moving, finite));
    let rolling = V3::select(resisting, m.t * (sigma * dir * k.rolling_resistance_n), V3::zeros());
    let v_body_centre = if screw { helical(&m.centre, one, h) } else { V3::zeros() };
    let rolling_dissipation = -rolling.dot(&(m.v_centre - v_body_centre));
    let on_body = -(normal_force + tangential + rolling);
    // Moment about the axis of what the ball exerts on the body: the normal force at the
    // contact centre, the tangential force at the effective point, the spin moment about g,
    // the rolling resistance at the ball centre.
    let centre_point = m.centre + *u * rho;
    let on_body_moment_z = centre_point.x * (-normal_force.y) - centre_point.y * (-normal_force.x)
        + (x.x * (-tangential.y) - x.y * (-tangential.x))
        - g.z * mz
        + (m.centre.x * (-rolling.y) - m.centre.y * (-rolling.x));
    ContactPart {
        force: normal_force + tangential + rolling,
        moment: arm.cross(&tangential) + g * mz,
        dissipation: -(tangential.dot(&slip) + mz * spin) + rolling_dissipation,
        rolling_dissipation,
        hysteresis_dissipation: rolling_dissipation * k.hysteresis_fraction,
        eq27: force_mag * ratio * load.factor * (c.rb - approach),
        on_body_moment_z,
        on_body_force_z: on_body.z,
    }
}

/// The ball-ball contact at angle `offset` (+spacing: ahead, -spacing: behind): force and moment
/// on the ball, dissipation per unit screw speed and the friction magnitude.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn ball_ball<V: Lanes>(
    c: &Constants<V>,
    cos_off: V,
    sin_off: V,
    offset: V,
    q: V,
    q_friction: V,
    m: &Motion<V>,
    load: &Load<V>,
) -> (V3<V>, V3<V>, V, V) {
    let zero = splat_of::<V>(0.0);
    let half = splat_of::<V>(0.5);
    let h = c.lead_per_rad;
    let other = V3::new(c.rm * cos_off, c.rm * sin_off, h * offset);
    let w = &m.omega;
    let omega_other = V3::new(cos_off * w.x - sin_off * w.y, sin_off * w.x + cos_off * w.y, w.z);
    let v_other = helical(&other, m.orbit, h);
    let point = (m.centre + other) * half;
    let g = (m.centre - other).normalize();
    let v_this = m.v_centre + m.omega.cross(&(point - m.centre));
    let v_that = v_other + omega_other.cross(&(point - other));
    let slip = v_this - v_that;
    let slip_t = slip - g * slip.dot(&g);
    let sn = slip_t.norm();
    let sliding = V::and_mask(sn.gt_mask(zero), q_friction.gt_mask(zero));
    let friction =
        V3::select(sliding, slip_t * (-load.direction * c.ball_ball_mu * q_friction * load.factor / sn), V3::zeros());
    let moment = (point - m.centre).cross(&friction);
    (g * q + friction, moment, -friction.dot(&slip_t), friction.norm())
}

/// Evaluates a ball of constants `c` in state `x` ([omega_t, omega_n, omega_b, orbit, q_nut,
/// q_screw, gamma], rates per unit screw speed, loads as ratios to the nominal) at `load`: one
/// ball in `f64` or `f32`, or one ball a lane in [`Real::Wide`] (the module's documentation).
pub fn evaluate<V: Lanes>(c: &Constants<V>, x: &[V; N], load: &Load<V>) -> Outcome<V> {
    let zero = splat_of::<V>(0.0);
    let fr = c.lean_frame();
    let (centre, t) = (fr.centre, fr.t);
    let omega = t * x[0] + fr.n * x[1] + fr.b * x[2];
    let orbit = x[3];
    let v_centre = V3::new(zero, c.rm * orbit, c.lead_per_rad * orbit);
    let q0 = c.nominal_load_n(load.axial_load_n);
    let (u_screw, u_nut) = c.lines(&fr, x[6]);
    let m = Motion { centre, v_centre, omega, orbit, t };
    let screw = contact(c, &c.screw, true, &u_screw, x[5] * q0, &m, load);
    let nut = contact(c, &c.nut, false, &u_nut, x[4] * q0, &m, load);
    let mut force = screw.force + nut.force;
    let mut moment = screw.moment + nut.moment;
    let mut dissipation = screw.dissipation + nut.dissipation;
    let mut eq27 = screw.eq27 + nut.eq27;
    let mut ball_ball_dissipation = zero;
    // Each ball counts the dissipation of its contact at +spacing: over a circuit, every
    // contact once.
    let touching = (c.ball_ball_plus_n + c.ball_ball_minus_n).gt_mask(zero);
    if V::any(touching) {
        let (cs, ss, angle) = c.spacing;
        let (f1, m1, d1, fr1) = ball_ball(c, cs, ss, angle, c.ball_ball_plus_n, c.ball_ball_plus_friction_n, &m, load);
        let (f2, m2, _, _) = ball_ball(c, cs, -ss, -angle, c.ball_ball_minus_n, c.ball_ball_minus_friction_n, &m, load);
        force = V3::select(touching, force + (f1 + f2), force);
        moment = V3::select(touching, moment + (m1 + m2), moment);
        dissipation = V::select(touching, dissipation + d1, dissipation);
        ball_ball_dissipation = V::select(touching, d1, ball_ball_dissipation);
        eq27 = V::select(touching, eq27 + fr1 * (c.rb - c.ball_ball_approach_m), eq27);
    }
    Outcome {
        residual: c.scaled_residual(&fr, &force, &moment, screw.on_body_force_z, load),
        dissipation_per_speed: dissipation,
        screw_moment_z_nm: screw.on_body_moment_z,
        screw_force_z_n: screw.on_body_force_z,
        eq27_nm: eq27,
        rolling_dissipation_per_speed: screw.rolling_dissipation + nut.rolling_dissipation,
        hysteresis_dissipation_per_speed: screw.hysteresis_dissipation + nut.hysteresis_dissipation,
        ball_ball_dissipation_per_speed: ball_ball_dissipation,
        orbit,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    extern crate alloc;
    use crate::ball::report::ball_state;
    use crate::{Lubrication, Model, ScrewSpec};
    use alloc::vec::Vec;

    /// The lean form and the report form of the balance agree in every state: residual,
    /// dissipation, moment about the axis, axial force and Eq. (27)'s sum, for both flanks, both
    /// directions, below the standstill speed, with a ball-ball load and with the spin moment
    /// saturated on its own.
    #[test]
    fn lean_balance_equals_the_report_form() {
        let mut spec = ScrewSpec::dkfzd4012();
        for (q_m, separate, lubrication) in [
            (0.0, false, Lubrication::Dry),
            (2.0, false, Lubrication::Dry),
            (0.0, true, Lubrication::Dry),
            (0.0, false, Lubrication::Ehl),
            (0.2, true, Lubrication::Ehl),
        ] {
            spec.friction.ball_ball_load_n = Some(q_m);
            spec.model.spin_moment = if separate { SpinMoment::Separate } else { SpinMoment::Combined };
            spec.model.lubrication = lubrication;
            let model = Model::new(&spec).unwrap();
            for &(p, flank, speed, factor) in
                &[(40.0, 1.0, 10.0, 1.0), (13.0, -1.0, -10.0, 1.0), (400.0, 1.0, 1e-4, 0.3), (2.0, -1.0, 5.0, 1.0)]
            {
                // The speed of the film is the solve's: 100 times the unit rates here.
                let (s, _) = model.ball_setup_at(p, flank, 100.0 * speed, factor);
                let (x0, rep) = crate::ball::solve::solve(&s, None, speed, factor);
                assert!(rep.residual < 1e-9);
                // At the solution and away from it.
                for d in [0.0, 1e-3, -2e-2] {
                    let x: [f64; N] = core::array::from_fn(|i| x0[i] * (1.0 + d * (i as f64 + 1.0) / 7.0));
                    let full = ball_state(&s, &x, speed, factor);
                    let c = Constants::new(&s, model.ball_ball_approach_m());
                    let lean_c = model.lean_for(flank, &s);
                    assert_eq!(c.screw, lean_c.screw);
                    assert_eq!(c.nut, lean_c.nut);
                    let dir = if speed < 0.0 { -1.0 } else { 1.0 };
                    let lean = evaluate(&c, &x, &Load { axial_load_n: p, direction: dir, factor });
                    for i in 0..N {
                        let tol = 1e-9 * (1.0 + full.residual[i].abs());
                        assert!(
                            (lean.residual[i] - full.residual[i]).abs() < tol,
                            "residual {i}: {lean:?} vs {full:?}"
                        );
                    }
                    let diss = full.screw.dissipation_per_speed
                        + full.nut.dissipation_per_speed
                        + full.ball_ball.dissipation_per_speed;
                    let close = |a: f64, b: f64| (a - b).abs() <= 1e-10 * (1.0 + b.abs());
                    assert!(close(lean.dissipation_per_speed, diss), "{} vs {diss}", lean.dissipation_per_speed);
                    assert!(close(lean.screw_moment_z_nm, full.screw_moment_z_nm));
                    assert!(close(lean.screw_force_z_n, full.screw_force_z_n));
                    let mag = |f: &crate::contact::forces::ContactForce| (f.e_n * f.e_n + f.f_n * f.f_n).sqrt();
                    let eq27 = mag(&full.nut.force) * (s.rb_m - full.nut.hertz.approach_m)
                        + mag(&full.screw.force) * (s.rb_m - full.screw.hertz.approach_m)
                        + full.ball_ball.friction.norm() * (s.rb_m - model.ball_ball_approach_m());
                    assert!(close(lean.eq27_nm, eq27), "{} vs {eq27}", lean.eq27_nm);
                }
            }
        }
    }

    /// Reversing the screw and swapping the flank is a half turn of the screw about the radial
    /// line through the ball centre: the balance of a ball on flank s turning backwards at
    /// state x is that of a ball on flank -s turning forwards at x with omega_n negated. The
    /// residual's force along t, force along b and moments about t and b change sign, the
    /// dissipation per signed speed and the axial force change sign, Eq. (27)'s magnitudes
    /// stay. At solutions and away from them, with a ball-ball load, below standstill speed.
    #[test]
    fn reversal_is_the_mirrored_flank_turning_forwards() {
        for lubrication in [Lubrication::Dry, Lubrication::Ehl] {
            reversal_mirrors(lubrication);
        }
    }

    fn reversal_mirrors(lubrication: Lubrication) {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.friction.ball_ball_load_n = Some(3.0);
        spec.model.lubrication = lubrication;
        let model = Model::new(&spec).unwrap();
        let sign = [-1.0, 1.0, -1.0, -1.0, 1.0, -1.0, 1.0];
        for &(p, flank, factor) in &[(26.0, 1.0, 1.0), (26.0, -1.0, 0.7), (3.0, 1.0, 0.2), (300.0, -1.0, 1.0)] {
            // The films at 1000 rpm, the same for both directions.
            let (s, _) = model.ball_setup_at(p, flank, 104.7, factor);
            let (x0, _) = crate::ball::solve::solve(&s, None, -1.0, factor);
            let here = Constants::<f64>::new(&s, model.ball_ball_approach_m());
            let (mirror, _) = model.ball_setup_at(p, -flank, 104.7, factor);
            let there = Constants::<f64>::new(&mirror, model.ball_ball_approach_m());
            for d in [0.0, 2e-3, -3e-2] {
                let x: [f64; N] = core::array::from_fn(|i| x0[i] * (1.0 + d * (i as f64 - 3.0)));
                let mut y = x;
                y[1] = -y[1];
                let a = evaluate(&here, &x, &Load { axial_load_n: p, direction: -1.0, factor });
                let b = evaluate(&there, &y, &Load { axial_load_n: p, direction: 1.0, factor });
                let close = |u: f64, v: f64| (u - v).abs() <= 1e-12 * (1.0 + v.abs());
                for i in 0..N {
                    assert!(close(a.residual[i], sign[i] * b.residual[i]), "{i}: {a:?} vs {b:?}");
                }
                assert!(close(a.dissipation_per_speed, -b.dissipation_per_speed));
                assert!(close(a.screw_force_z_n, -b.screw_force_z_n));
                assert!(close(a.screw_moment_z_nm, -b.screw_moment_z_nm));
                assert!(close(a.eq27_nm, b.eq27_nm));
            }
        }
    }

    /// A ball of the lanes test: constants, a solution, load, direction, standstill factor.
    type Ball<F> = (Constants<F>, [f64; N], f64, f64, f64);

    /// The same bits, or both NaN.
    fn same<F: Real>(a: F, b: F) -> bool {
        let (a, b) = (a.to_f64(), b.to_f64());
        (a.is_nan() && b.is_nan()) || a.to_bits() == b.to_bits()
    }

    fn same_outcome<F: Real>(a: &Outcome<F>, b: &Outcome<F>) -> bool {
        (0..N).all(|i| same(a.residual[i], b.residual[i]))
            && [
                (a.dissipation_per_speed, b.dissipation_per_speed),
                (a.screw_moment_z_nm, b.screw_moment_z_nm),
                (a.screw_force_z_n, b.screw_force_z_n),
                (a.eq27_nm, b.eq27_nm),
                (a.rolling_dissipation_per_speed, b.rolling_dissipation_per_speed),
                (a.hysteresis_dissipation_per_speed, b.hysteresis_dissipation_per_speed),
                (a.ball_ball_dissipation_per_speed, b.ball_ball_dissipation_per_speed),
            ]
            .iter()
            .all(|&(u, v)| same(u, v))
    }

    /// Balls of different setups, states and loads in one pass of the lanes ([`Real::Wide`])
    /// are each the single ball evaluated alone, to the bit: dry and lubricated, with a
    /// ball-ball load and with the spin moment saturated on its own; states at and away from
    /// solutions, the tilt beyond the 0.1 rad of the small-angle series in some lanes, an
    /// unloaded contact, standstill factors, rates so large that the rolling speed overflows,
    /// NaN; groups smaller than the lanes (the last ball repeated); one flank's constants in
    /// every lane with each ball's friction set lane by lane. Returns the lanes compared.
    fn lanes_are_the_single_ball<F: Real>() -> usize {
        let mut seed = 0x1a4e_5eed_u64;
        let mut rnd = move || {
            seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            ((seed >> 11) as f64) / ((1u64 << 53) as f64)
        };
        let lanes = <F::Wide as Lanes>::LANES;
        let mut compared = 0;
        for (q_m, separate, lubrication) in [
            (0.0, false, Lubrication::Dry),
            (2.0, false, Lubrication::Dry),
            (0.0, true, Lubrication::Dry),
            (0.0, false, Lubrication::Ehl),
            (0.2, true, Lubrication::Ehl),
        ] {
            let mut spec = ScrewSpec::dkfzd4012();
            spec.friction.ball_ball_load_n = Some(q_m);
            spec.model.spin_moment = if separate { SpinMoment::Separate } else { SpinMoment::Combined };
            spec.model.lubrication = lubrication;
            let model = Model::new(&spec).unwrap();
            // Balls of both flanks, 2 to 400 N, both directions, with the films of their speed.
            let balls: Vec<Ball<F>> =
                [(40.0, 1.0, 10.0, 1.0), (13.0, -1.0, -10.0, 1.0), (400.0, 1.0, 1e-4, 0.3), (2.0, -1.0, 5.0, 1.0)]
                    .iter()
                    .map(|&(p, flank, speed, factor)| {
                        let (s, _) = model.ball_setup_at(p, flank, 100.0 * speed, factor);
                        let (x0, _) = crate::ball::solve::solve(&s, None, speed, factor);
                        (Constants::<F>::new(&s, model.ball_ball_approach_m()), x0, p, speed.signum(), factor)
                    })
                    .collect();
            for trial in 0..400 {
                let count = if trial % 5 == 4 { 1 + trial % lanes } else { lanes };
                let mut cs = Vec::new();
                let mut xs = Vec::new();
                let mut loads = Vec::new();
                for lane in 0..count {
                    let (c, x0, p, dir, factor) = balls[(trial + lane) % balls.len()];
                    let scale = [0.0, 1e-6, 1e-2, 0.5][(trial + 3 * lane) % 4];
                    let mut x: [F; N] = core::array::from_fn(|i| F::of(x0[i] * (1.0 + scale * (2.0 * rnd() - 1.0))));
                    match (trial + lane) % 23 {
                        3 => x[6] = F::of(0.3 * (2.0 * rnd() - 1.0)),
                        5 => x[4] = F::of(-0.1),
                        7 => x[0] = F::of(1e200),
                        11 => x[2] = F::of(f64::NAN),
                        _ => {}
                    }
                    let factor = if (trial + lane) % 7 == 0 { factor * rnd() } else { factor };
                    cs.push(c);
                    xs.push(x);
                    loads.push(Load {
                        axial_load_n: F::of(p * (1.0 + 0.1 * rnd())),
                        direction: F::of(dir),
                        factor: F::of(factor),
                    });
                }
                let refs: Vec<&Constants<F>> = cs.iter().collect();
                let wide = evaluate(
                    &Constants::<F::Wide>::gather(&refs),
                    &gather_states::<F::Wide>(&xs),
                    &Load::gather(&loads),
                );
                for lane in 0..lanes {
                    let one = lane.min(count - 1);
                    let alone = evaluate(&cs[one], &xs[one], &loads[one]);
                    assert!(same_outcome(&wide.lane(lane), &alone), "lane {lane}: {:?} vs {alone:?}", wide.lane(lane));
                    compared += 1;
                }
                let (screw, nut) = (ContactFriction::dry(0.04 + 0.01 * rnd()), ContactFriction::dry(0.07));
                let alone = cs[0].with_friction(&screw, &nut);
                let spread = Constants::<F::Wide>::gather(&[&cs[0]]).with_frictions(&[&screw], &[&nut]);
                let wide = evaluate(&spread, &gather_states::<F::Wide>(&xs[..1]), &Load::gather(&loads[..1]));
                assert!(same_outcome(&wide.lane(lanes - 1), &evaluate(&alone, &xs[0], &loads[0])));
            }
        }
        compared
    }

    #[test]
    fn lanes_are_the_single_ball_to_the_bit() {
        let (n64, n32) = (lanes_are_the_single_ball::<f64>(), lanes_are_the_single_ball::<f32>());
        // On every host these tests run on (x86-64, AArch64), several balls a pass.
        const { assert!(<<f64 as Real>::Wide as Lanes>::LANES >= 2 && <<f32 as Real>::Wide as Lanes>::LANES >= 4) };
        assert!(n64 >= 4000 && n32 >= 8000, "{n64} {n32}");
    }
}
