//! The four-point contact ball of an oversize-ball nut: its balance and its solver.
//!
//! A ball a few micrometres larger than the gap between the gothic-arch grooves touches both
//! flanks of both grooves. Its four contacts form two diagonals through the ball centre: the
//! diagonal "+" (screw contact on flank +1, towards +b, and nut contact towards -b: the contacts
//! of a two-contact ball on flank +1) and the diagonal "-" (the mirror). Each diagonal carries
//! the axial load of its flank's set of contacts, shared between the two sets as between the two
//! nuts of a double nut ([`crate::screw::load::groups`]): the interference presses the
//! diagonals against each other as the spacer presses the nuts.
//!
//! What a four-point ball cannot do is what makes it run with more drag: one ball turns about
//! one axis, and no axis rolls on both diagonals (a two-contact ball on flank +1 turns about
//! an axis normal to its contact line, the one on flank -1 about another), so at least one pair
//! of contacts slides, and the ball cannot shift sideways to carry its lateral friction by a
//! tilt of its contact normals as a two-contact ball does (a shift across one diagonal runs
//! along the other and loads or unloads its contacts).
//!
//! # The balance
//!
//! The contacts are those of the two-contact ball ([`crate::ball::report`]): Hertz ellipses,
//! creepages with spin and Heathcote slip, Kalker's creep forces saturated (the same contact
//! theory and lubrication), placed on the contact lines of `Constants::contact_lines`
//! (`ball::balance`). What changes is where the normal loads and tilts come from: the geometry
//! of the ball in its grooves. Each diagonal's total approach (the overlap of ball and grooves along its line) is
//! the interference's `D0` plus or minus the screw's displacement `W` relative to the nut along
//! the line: `D0 + W` for "+", `D0 - W` for "-". `D0` is the approach the preload alone gives,
//! (k_s + k_N) Q_p^(2/3) with Q_p = P_p / (sin(beta) cos(alpha)) and k the contacts' Hertz
//! approach per load^(2/3). The ball centre's displacement `Delta` in the (n, b) plane of its
//! groove section shares each diagonal's approach between its two contacts and tilts the
//! normals. With `u` and `v` the unit vectors along and across a diagonal's contact line
//! (`u = cos(beta) n + flank sin(beta) b`, `v = -sin(beta) n + flank cos(beta) b`):
//! - the screw contact's approach is its share k_s / (k_s + k_N) of the total plus `Delta . u`,
//!   the nut contact's its share minus `Delta . u`; the normal load is Hertz's,
//!   `Q = (delta / k)^(3/2)`, zero where the approach is negative (the contact opens);
//! - the normals tilt by the shift across the line: tan(gamma) = `Delta . v / d_s` at the screw
//!   and `Delta . v / d_N` at the nut (`d = (f - 1/2) D_w`, the arc-centre offsets), the tilt of
//!   `Constants::contact_lines` (`ball::balance`).
//!
//! For one diagonal alone, (`Delta . u`, `W`, `Delta . v`) is another name for the two-contact
//! ball's unknowns (nut load, screw load, tilt): where the other diagonal is open, the balance
//! is the two-contact ball's. Two diagonals share one `Delta`: `Delta . v` of each is fixed by
//! `Delta . u` of both. Without friction the diagonals carry the loads of the double nut's
//! split ([`crate::screw::load::nut_loads`]: the same Hertz law); beyond the light diagonal's
//! lift-off it opens by the heavy one's extra approach, and the ball becomes a two-contact
//! ball once that gap exceeds the sideways shift its lateral friction asks (below it, the ball
//! leans on a third contact).
//!
//! Unknowns (7): the ball's angular velocity per unit screw speed in (t, n, b), the orbit ratio,
//! `Delta . u` of each diagonal and `W`, the last three over a reference approach (that of the
//! heavier diagonal's nominal load). Equations (7): the ball's force and moment balance (6,
//! scaled as the two-contact ball's by that nominal load) and the net axial load the ball
//! carries between screw and nut.
//!
//! The solve starts from the heavier diagonal's two-contact ball (the solution itself where the
//! other diagonal stays open), else from the load-weighted mean of both diagonals' two-contact
//! balls, and else follows the creep stiffness from a small scale, where every contact is
//! linear, to 1 (as the two-contact ball's cold solve does, docs/model-notes.md item 11), then
//! the lubricated contacts' rolling resistance from a hundredth to its value, and last the
//! axial load from a thousandth of it or the preload from four times the axial load.

use crate::ball::balance::{Constants, Frame, Load};
use crate::ball::report::{BallBallState, BallMotion, BallState, ball_ball, helical_velocity, raceway_state, z_axis};
use crate::ball::setup::{self, BallSetup, MAX_ITERATIONS, MIN_SOLVE_FACTOR, TOLERANCE, Unknowns};
use crate::ball::solve::{self, JacobianStep, SolveReport};
use crate::contact::creep::direction;
use nalgebra::Vector3;

/// Number of unknowns of a four-point ball's balance.
pub const N4: usize = 7;
/// The unknowns: [omega_t, omega_n, omega_b, orbit, shift+, shift-, displacement] (see the
/// module's documentation).
pub type FourPointUnknowns = [f64; N4];

/// A four-point ball: its two diagonals as two-contact balls (their setups carry each
/// diagonal's flank, contact friction and its load of the double nut's split, by which its
/// films are taken and its equations scaled), and the ball's shares of the preload and the
/// axial load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FourPointSetup {
    /// The diagonal on flank +1 (`axial_load_n` > 0).
    pub plus: BallSetup,
    /// The diagonal on flank -1 (`axial_load_n` > 0).
    pub minus: BallSetup,
    /// The ball's share of the preload P_p, N (>= 0): the interference's approach.
    pub preload_n: f64,
    /// The ball's share of the external axial load, N: positive presses the diagonal "+".
    pub axial_load_n: f64,
}

/// A four-point ball in one state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FourPointState {
    /// Each diagonal as a two-contact ball: [flank +1, flank -1]. The ball-ball contact is the
    /// first's (the second's has no load); each diagonal's `screw_moment_z_nm` and
    /// `screw_force_z_n` are what its screw contact exerts on the screw, and its `residual` is
    /// zero (the balance is the whole ball's, `residual` below).
    pub diagonals: [BallState; 2],
    /// Scaled residual of the balance (zero when the ball is in balance).
    pub residual: [f64; N4],
    /// Power dissipated in the ball's contacts per unit screw speed, J/rad.
    pub dissipation_per_speed: f64,
    /// Moment about the screw axis of everything the ball exerts on the screw, N m.
    pub screw_moment_z_nm: f64,
    /// Axial force the ball exerts on the screw, N.
    pub screw_force_z_n: f64,
}

/// Load-independent data of the balance.
struct Geometry {
    constants: [Constants<f64>; 2],
    frame: Frame<f64>,
    sin_beta: f64,
    cos_beta: f64,
    /// Arc-centre offset of the screw groove d_s, m.
    screw_offset_m: f64,
    /// Hertz approach per load^(2/3) of the screw and nut contacts, m N^(-2/3).
    per_load: (f64, f64),
    /// The interference's approach of each diagonal, m.
    interference_m: f64,
    /// The reference approach (the heavier diagonal's nominal), m: the scale of the shifts.
    scale_m: f64,
    /// The heavier diagonal's nominal load, N.
    reference_load_n: f64,
    /// Index of the heavier diagonal.
    heavy: usize,
}

impl Geometry {
    fn new(s: &FourPointSetup) -> Self {
        let setups = [&s.plus, &s.minus];
        let constants = setups.map(|d| Constants::new(d, 0.0));
        let nominal = setups.map(|d| d.nominal_load_n());
        let heavy = if nominal[1] > nominal[0] { 1 } else { 0 };
        let per_load = (s.plus.screw.shape.contact(1.0).approach_m, s.plus.nut.shape.contact(1.0).approach_m);
        let (sb, cb) = libm::sincos(s.plus.contact_angle_rad);
        let k = per_load.0 + per_load.1;
        let preload_q = s.preload_n.max(0.0) / (sb * libm::cos(s.plus.helix_angle_rad));
        Self {
            frame: constants[0].frame(),
            constants,
            sin_beta: sb,
            cos_beta: cb,
            screw_offset_m: s.plus.screw.arc_offset_m,
            per_load,
            interference_m: k * libm::cbrt(preload_q * preload_q),
            scale_m: k * libm::cbrt(nominal[heavy] * nominal[heavy]),
            reference_load_n: nominal[heavy],
            heavy,
        }
    }

    /// The normal loads (screw, nut), N, and the tilt gamma (rad) of each diagonal in state `x`.
    fn contacts(&self, x: &FourPointUnknowns) -> [(f64, f64, f64); 2] {
        let along = [x[4] * self.scale_m, x[5] * self.scale_m];
        let w = x[6] * self.scale_m;
        let total = [self.interference_m + w, self.interference_m - w];
        // The centre's shift in (n, b) from its components along the two diagonals.
        let (sb, cb) = (self.sin_beta, self.cos_beta);
        let dn = (along[0] + along[1]) / (2.0 * cb);
        let db = (along[0] - along[1]) / (2.0 * sb);
        let across = [-sb * dn + cb * db, -sb * dn - cb * db];
        let (ks, kn) = self.per_load;
        let screw_share = ks / (ks + kn);
        let load = |delta: f64, k: f64| if delta > 0.0 { libm::pow(delta / k, 1.5) } else { 0.0 };
        [0, 1].map(|d| {
            (
                load(screw_share * total[d] + along[d], ks),
                load((1.0 - screw_share) * total[d] - along[d], kn),
                libm::atan(across[d] / self.screw_offset_m),
            )
        })
    }

    /// The state of the four-point ball that is the two-contact ball `x` (its unknowns) of the
    /// diagonal `d`: the same loads and tilt of `d`'s contacts (the four-point ball's state where
    /// the other diagonal stays open, a start where it does not).
    fn two_contact_state(&self, s: &FourPointSetup, d: usize, x: &Unknowns) -> FourPointUnknowns {
        let setup = [&s.plus, &s.minus][d];
        let q0 = setup.nominal_load_n();
        let (ks, kn) = self.per_load;
        let approach = |q: f64, k: f64| k * libm::cbrt(q * q).max(0.0);
        let (screw, nut) = (approach(x[5] * q0, ks), approach(x[4] * q0, kn));
        let total = screw + nut;
        let along = screw - ks / (ks + kn) * total;
        let across = self.screw_offset_m * libm::tan(x[6]);
        // The centre's shift in (n, b): along u and across v of diagonal d.
        let (sb, cb) = (self.sin_beta, self.cos_beta);
        let flank = if d == 0 { 1.0 } else { -1.0 };
        let dn = along * cb - across * sb;
        let db = flank * (along * sb + across * cb);
        let along_other = dn * cb - flank * db * sb;
        let w = flank * (total - self.interference_m);
        let (a_plus, a_minus) = if d == 0 { (along, along_other) } else { (along_other, along) };
        [x[0], x[1], x[2], x[3], a_plus / self.scale_m, a_minus / self.scale_m, w / self.scale_m]
    }

    /// The displacement (over the reference approach) at which each diagonal carries the nominal
    /// load of its setup with the ball centred.
    fn nominal_displacement(&self) -> f64 {
        // The heavier diagonal's total approach D0 + W ("+") or D0 - W ("-") is that of its
        // nominal load (the lighter's setup may carry a floor of a lifted-off diagonal).
        let k = self.per_load.0 + self.per_load.1;
        let q = self.reference_load_n;
        let sign = if self.heavy == 0 { 1.0 } else { -1.0 };
        sign * (k * libm::cbrt(q * q) - self.interference_m) / self.scale_m
    }
}

/// Evaluates a four-point ball in state `x` at screw speed `speed_rad_s` with standstill factor
/// `factor`.
pub fn four_point_state(s: &FourPointSetup, x: &FourPointUnknowns, speed_rad_s: f64, factor: f64) -> FourPointState {
    let geo = Geometry::new(s);
    state_with(s, &geo, x, speed_rad_s, factor)
}

fn state_with(
    s: &FourPointSetup,
    geo: &Geometry,
    x: &FourPointUnknowns,
    speed_rad_s: f64,
    factor: f64,
) -> FourPointState {
    let fr = &geo.frame;
    let (centre, t, n, b) = (fr.centre, fr.t, fr.n, fr.b);
    let omega_ball = t * x[0] + n * x[1] + b * x[2];
    let orbit = x[3];
    let v_centre = helical_velocity(&centre, orbit, s.plus.lead_per_rad_m);
    let motion = BallMotion { centre, v_centre, omega_ball, orbit, t, n, speed_rad_s, factor };
    let loads = geo.contacts(x);
    let setups = [&s.plus, &s.minus];
    let mut force = Vector3::zeros();
    let mut moment = Vector3::zeros();
    let z = z_axis();
    let no_ball_ball = BallBallState {
        load_n: 0.0,
        point: centre,
        friction: Vector3::zeros(),
        slip_speed_m_s: 0.0,
        rolling_speed_m_s: 0.0,
        dissipation_per_speed: 0.0,
    };
    let mut dissipation = 0.0;
    let mut moment_z = 0.0;
    let mut force_z = 0.0;
    let diagonals = [0, 1].map(|d| {
        let setup = setups[d];
        let (q_screw, q_nut, gamma) = loads[d];
        let (u_screw, u_nut) = geo.constants[d].contact_lines(fr, gamma);
        let screw = raceway_state(setup, &setup.screw, true, &u_screw, q_screw, &motion);
        let nut = raceway_state(setup, &setup.nut, false, &u_nut, q_nut, &motion);
        for c in [&screw, &nut] {
            force += c.normal * c.load_n + c.tangential + c.rolling_resistance;
            moment += (c.point_eff - centre).cross(&c.tangential) + c.normal * c.force.moment_nm;
        }
        let on_screw = -(screw.normal * screw.load_n);
        let screw_moment_z_nm = z.dot(&screw.point.cross(&on_screw))
            - z.dot(&screw.point_eff.cross(&screw.tangential))
            - z.dot(&centre.cross(&screw.rolling_resistance))
            - z.dot(&screw.normal) * screw.force.moment_nm;
        let screw_force_z_n = (on_screw - screw.tangential - screw.rolling_resistance).z;
        dissipation += screw.dissipation_per_speed + nut.dissipation_per_speed;
        moment_z += screw_moment_z_nm;
        force_z += screw_force_z_n;
        BallState {
            centre,
            t,
            n,
            b,
            omega_ball,
            nut,
            screw,
            ball_ball: no_ball_ball,
            residual: [0.0; 7],
            screw_moment_z_nm,
            screw_force_z_n,
        }
    });
    let mut diagonals = diagonals;
    let lead = &s.plus;
    if lead.has_ball_ball_load() {
        let plus = (lead.ball_ball_plus_n, lead.ball_ball_plus_friction_n);
        let minus = (lead.ball_ball_minus_n, lead.ball_ball_minus_friction_n);
        let (f1, m1, ahead) =
            ball_ball(lead, lead.spacing_rad, &centre, &v_centre, &omega_ball, plus, orbit, speed_rad_s, factor);
        let (f2, m2, _) =
            ball_ball(lead, -lead.spacing_rad, &centre, &v_centre, &omega_ball, minus, orbit, speed_rad_s, factor);
        force += f1 + f2;
        moment += m1 + m2;
        dissipation += ahead.dissipation_per_speed;
        diagonals[0].ball_ball = ahead;
    }
    // The balance scaled by the heavier diagonal's nominal load, then the net axial load.
    let h = geo.heavy;
    let load = Load { axial_load_n: setups[h].axial_load_n, direction: direction(speed_rad_s), factor };
    let balance = geo.constants[h].residual(fr, &force, &moment, 0.0, &load);
    let mut residual = [0.0; N4];
    residual[..6].copy_from_slice(&balance[..6]);
    residual[6] = (force_z - s.axial_load_n) / geo.reference_load_n;
    FourPointState {
        diagonals,
        residual,
        dissipation_per_speed: dissipation,
        screw_moment_z_nm: moment_z,
        screw_force_z_n: force_z,
    }
}

/// A start for the four-point ball from its two diagonals solved apart as two-contact balls
/// (`plus`, `minus`: their unknowns, `None` for a diagonal of no load): the load-weighted mean
/// of their orbit and of their rates along t and n, and the rate along b of a ball rolling
/// about b on both diagonals (its surface speed at the contacts, at the distance r_b cos(beta)
/// from that axis, that of the two-contact balls at r_b); the centre where both diagonals are
/// at their nominal approach.
pub fn start_from_diagonals(
    s: &FourPointSetup,
    plus: Option<&Unknowns>,
    minus: Option<&Unknowns>,
) -> FourPointUnknowns {
    let w = Geometry::new(s).nominal_displacement();
    let cos_beta = libm::cos(s.plus.contact_angle_rad);
    let weighted = [(plus, s.plus.axial_load_n), (minus, s.minus.axial_load_n)];
    let total: f64 = weighted.iter().filter(|(x, _)| x.is_some()).map(|(_, w)| w).sum();
    if !(total > 0.0) {
        // Neither diagonal solved alone: the ball rolling about b without slip.
        let spin = setup::rolling_spin(&s.plus) / cos_beta;
        return [0.0, 0.0, -spin, setup::rolling_orbit_ratio(&s.plus), 0.0, 0.0, w];
    }
    let mean = |f: &dyn Fn(&Unknowns) -> f64| -> f64 {
        weighted.iter().filter_map(|(x, w)| x.map(|x| w * f(x))).sum::<f64>() / total
    };
    let spin = |x: &Unknowns| libm::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    let about_b = -mean(&spin) / cos_beta;
    [mean(&|x| x[0]), mean(&|x| x[1]), about_b, mean(&|x| x[3]), 0.0, 0.0, w]
}

/// Whether the state `x` is physical: the rates within the bands of a two-contact ball of
/// both diagonals ([`crate::ball::setup::check_state`]), each contact's load within the band
/// of the heavier diagonal's nominal load (a light diagonal's contacts may carry many times
/// their own nominal load, pressed by the shift of the ball the heavy one sets), and the
/// shifts finite. A contact that has opened (no load) is physical.
pub fn check_state(s: &FourPointSetup, x: &FourPointUnknowns) -> Result<(), crate::error::Unphysical> {
    if let Some(&v) = x.iter().find(|v| !v.is_finite()) {
        return Err(crate::error::Unphysical { quantity: "state (rates, shifts)", value: v, valid: "finite" });
    }
    let geo = Geometry::new(s);
    let loads = geo.contacts(x);
    let heavy = geo.reference_load_n;
    for (d, setup) in [&s.plus, &s.minus].into_iter().enumerate() {
        let (qs, qn, gamma) = loads[d];
        let ratio = |q: f64| (q / heavy).max(f64::MIN_POSITIVE);
        let y = [x[0], x[1], x[2], x[3], ratio(qn), ratio(qs), gamma];
        Constants::<f64>::new(setup, 0.0).check_state(&y)?;
    }
    Ok(())
}

/// Newton's method on the four-point balance from `x` (the two-contact ball's solver and
/// Jacobian steps).
fn newton(s: &FourPointSetup, x: &mut FourPointUnknowns, speed: f64, factor: f64) -> (u32, f64) {
    let geo = Geometry::new(s);
    let step: JacobianStep = solve::jacobian_step(&s.plus);
    let (it, res) = solve::newton(
        x,
        |y| state_with(s, &geo, y, speed, factor).residual,
        &[1.0; N4],
        TOLERANCE,
        MAX_ITERATIONS,
        step,
        &mut None,
        None,
    );
    if check_state(s, x).is_err() { (it, f64::INFINITY) } else { (it, res) }
}

/// Follows the branch through `x` (solved with the setup `set(from)`) to `set(to)`
/// ([`solve::follow`]); (iterations, residual, steps), the residual infinite where `to` was
/// not reached.
fn continue_in(
    s: &FourPointSetup,
    x: &mut FourPointUnknowns,
    from: f64,
    to: f64,
    speed: f64,
    factor: f64,
    set: impl Fn(&mut FourPointSetup, f64),
) -> (u32, f64, u32) {
    let mut solve = |sk: &FourPointSetup, y: &mut FourPointUnknowns| newton(sk, y, speed, factor);
    let (iterations, res, steps, reached) = solve::follow(s, x, from, to, 4.0, &set, &mut solve);
    (iterations, if reached { res } else { f64::INFINITY }, steps)
}

/// Share of the creep stiffness at which the cold solve starts: every contact linear.
const STIFFNESS_START: f64 = 1e-3;
/// Share of the rolling resistance at which its continuation starts.
const ROLLING_START: f64 = 1e-2;

/// Solves a four-point ball: from `x0` when given, else (or when that fails) from its two
/// diagonals solved apart, directly and else by continuation in the creep stiffness and the
/// rolling resistance.
pub fn solve(
    s: &FourPointSetup,
    x0: Option<&FourPointUnknowns>,
    speed: f64,
    factor: f64,
) -> (FourPointUnknowns, SolveReport) {
    let fk = factor.max(MIN_SOLVE_FACTOR);
    let mut iterations = 0;
    if let Some(x0) = x0 {
        let mut x = *x0;
        let (it, res) = newton(s, &mut x, speed, fk);
        iterations += it;
        if res <= TOLERANCE {
            return (x, SolveReport { iterations, residual: res, continuation_steps: 0 });
        }
    }
    let (x, mut rep) = solve_cold(s, speed, factor);
    rep.iterations += iterations;
    (x, rep)
}

/// Load ratio to the heavier diagonal below which a diagonal is left out of the cold start.
const START_SHARE: f64 = 1e-2;

/// Share of the axial load from which [`solve_cold`] follows the axial load to its value when
/// the ball does not solve otherwise: from nearly the preloaded ball without axial load, whose
/// diagonals are alike.
const AXIAL_START: f64 = 1e-3;

/// [`solve`] without a start: from the two diagonals solved apart ([`solve_from_diagonals`]);
/// where that fails under an axial load, from the ball under a thousandth of it by
/// continuation in the axial load, and else from a preload of four times the axial load by
/// continuation in the preload.
fn solve_cold(s: &FourPointSetup, speed: f64, factor: f64) -> (FourPointUnknowns, SolveReport) {
    // The diagonals alone depend on their setups only, which every path below shares: solved
    // once.
    let (alone, iterations) = diagonals_alone(s, speed, factor);
    let (x, mut rep) = solve_from_diagonals(s, &alone, speed, factor);
    rep.iterations += iterations;
    if rep.residual <= TOLERANCE || s.axial_load_n == 0.0 || s.preload_n <= 0.0 {
        return (x, rep);
    }
    let fk = factor.max(MIN_SOLVE_FACTOR);
    // From a thousandth of the axial load up to it; then, for a preload below four times the
    // axial load, from that preload (both diagonals well pressed) down to the ball's own.
    let (axial, preload) = (s.axial_load_n, s.preload_n);
    let residual = rep.residual;
    let preload_start = PRELOAD_START * libm::fabs(axial) / preload;
    let by_axial = |sk: &mut FourPointSetup, v: f64| sk.axial_load_n = v * axial;
    let by_preload = |sk: &mut FourPointSetup, v: f64| sk.preload_n = v * preload;
    let mut attempt = |from: f64, set: &dyn Fn(&mut FourPointSetup, f64)| -> Option<FourPointUnknowns> {
        let mut start = *s;
        set(&mut start, from);
        let (mut y, r) = solve_from_diagonals(&start, &alone, speed, factor);
        rep.iterations += r.iterations;
        rep.continuation_steps += r.continuation_steps;
        if !(r.residual <= TOLERANCE) {
            return None;
        }
        let (it, res, steps) = continue_in(s, &mut y, from, 1.0, speed, fk, set);
        rep.iterations += it;
        rep.continuation_steps += steps;
        rep.residual = res;
        (res <= TOLERANCE).then_some(y)
    };
    if let Some(y) = attempt(AXIAL_START, &by_axial) {
        return (y, rep);
    }
    if preload_start > 1.0
        && let Some(y) = attempt(preload_start, &by_preload)
    {
        return (y, rep);
    }
    rep.residual = residual;
    (x, rep)
}

/// The preload, over the axial load, from which [`solve_cold`] follows the preload down to the
/// ball's own when nothing else solves it.
const PRELOAD_START: f64 = 4.0;

/// The two diagonals of `s` solved apart as two-contact balls ([flank +1, flank -1]; `None`
/// for a diagonal lighter than [`START_SHARE`] of the other or that does not solve), and the
/// Newton iterations spent.
fn diagonals_alone(s: &FourPointSetup, speed: f64, factor: f64) -> ([Option<Unknowns>; 2], u32) {
    let mut iterations = 0;
    let heaviest = s.plus.axial_load_n.max(s.minus.axial_load_n);
    let mut alone = |d: &BallSetup| {
        if !(d.axial_load_n >= START_SHARE * heaviest) {
            return None;
        }
        let (x, r) = solve::solve(d, None, speed, factor);
        iterations += r.iterations;
        (r.residual <= TOLERANCE).then_some(x)
    };
    ([alone(&s.plus), alone(&s.minus)], iterations)
}

/// [`solve_cold`] from the two diagonals solved apart (`alone`, [`diagonals_alone`] of the
/// same diagonal setups): directly, and by continuation in the creep stiffness and the rolling
/// resistance.
fn solve_from_diagonals(
    s: &FourPointSetup,
    alone: &[Option<Unknowns>; 2],
    speed: f64,
    factor: f64,
) -> (FourPointUnknowns, SolveReport) {
    let fk = factor.max(MIN_SOLVE_FACTOR);
    let mut iterations = 0;
    let mut steps = 0;
    let [xp, xm] = *alone;
    // Two starts: the heavier diagonal's two-contact ball with the other diagonal open (the
    // solution itself where that diagonal stays open), and the mean of both diagonals' balls.
    let geo = Geometry::new(s);
    let heavy = if s.minus.axial_load_n > s.plus.axial_load_n { (1, xm) } else { (0, xp) };
    let mut starts = [None, Some(start_from_diagonals(s, xp.as_ref(), xm.as_ref()))];
    if let (d, Some(x2)) = heavy {
        starts[0] = Some(geo.two_contact_state(s, d, &x2));
    }
    for start in starts.iter().flatten() {
        let mut x = *start;
        let (it, res) = newton(s, &mut x, speed, fk);
        iterations += it;
        if res <= TOLERANCE {
            return (x, SolveReport { iterations, residual: res, continuation_steps: steps });
        }
    }
    let start = starts.iter().flatten().next().copied().unwrap_or_else(|| start_from_diagonals(s, None, None));
    // From linear contacts without rolling resistance.
    let rolling = [[s.plus.screw.friction, s.plus.nut.friction], [s.minus.screw.friction, s.minus.nut.friction]];
    let scaled = |sk: &mut FourPointSetup, v: f64| {
        for (d, setup) in [&mut sk.plus, &mut sk.minus].into_iter().enumerate() {
            for (k, race) in [&mut setup.screw, &mut setup.nut].into_iter().enumerate() {
                race.friction.rolling_resistance_ehl_n = v * rolling[d][k].rolling_resistance_ehl_n;
                race.friction.rolling_resistance_hysteresis_n = v * rolling[d][k].rolling_resistance_hysteresis_n;
            }
        }
    };
    let lubricated = s.plus.has_rolling_resistance() || s.minus.has_rolling_resistance();
    let mut sd = *s;
    if lubricated {
        scaled(&mut sd, ROLLING_START);
    }
    let mut x = start;
    let mut sk = sd;
    sk.plus.stiffness_scale = STIFFNESS_START;
    sk.minus.stiffness_scale = STIFFNESS_START;
    let (it, r) = newton(&sk, &mut x, speed, fk);
    iterations += it;
    if !(r <= TOLERANCE) {
        return (x, SolveReport { iterations, residual: r, continuation_steps: steps });
    }
    let (it, mut res, st) = continue_in(&sd, &mut x, STIFFNESS_START, 1.0, speed, fk, |sk, v| {
        sk.plus.stiffness_scale = v;
        sk.minus.stiffness_scale = v;
    });
    iterations += it;
    steps += st;
    if lubricated && res <= TOLERANCE {
        let (it, r, st) = continue_in(s, &mut x, ROLLING_START, 1.0, speed, fk, scaled);
        iterations += it;
        steps += st;
        res = r;
    }
    (x, SolveReport { iterations, residual: res, continuation_steps: steps })
}

/// The state `x`, solved at the standstill factor [`MIN_SOLVE_FACTOR`], carried to the factor
/// `factor` below it: the shifts carry the friction forces and scale with them, the rates carry
/// over (as [`solve::scale_to_factor`] for a two-contact ball).
pub fn scale_to_factor(s: &FourPointSetup, x: &FourPointUnknowns, factor: f64) -> FourPointUnknowns {
    if factor >= MIN_SOLVE_FACTOR {
        return *x;
    }
    let ratio = factor.max(0.0) / MIN_SOLVE_FACTOR;
    // Without friction the centre sits where both diagonals are at their nominal approach and
    // the displacement is the one that carries the axial load.
    let w0 = Geometry::new(s).nominal_displacement();
    let mut y = *x;
    y[4] *= ratio;
    y[5] *= ratio;
    y[6] = w0 + (x[6] - w0) * ratio;
    y
}

/// The normal loads (screw, nut) of each diagonal in state `x`, N: [flank +1, flank -1].
pub fn contact_loads(s: &FourPointSetup, x: &FourPointUnknowns) -> [(f64, f64); 2] {
    Geometry::new(s).contacts(x).map(|(screw, nut, _)| (screw, nut))
}

/// Each diagonal's state `x` in the two-contact ball's unknowns ([`Unknowns`]: rates, orbit,
/// nut and screw loads over the diagonal's nominal load, tilt), for its report.
pub fn diagonal_unknowns(s: &FourPointSetup, x: &FourPointUnknowns) -> [Unknowns; 2] {
    let geo = Geometry::new(s);
    let loads = geo.contacts(x);
    [0, 1].map(|d| {
        let (qs, qn, gamma) = loads[d];
        let q0 = [&s.plus, &s.minus][d].nominal_load_n();
        [x[0], x[1], x[2], x[3], qn / q0, qs / q0, gamma]
    })
}
