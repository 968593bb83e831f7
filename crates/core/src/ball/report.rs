//! Ball kinematics from the quasi-static balance of one ball (docs/model-notes.md item 11).
//!
//! The paper never gives the ball's spin omega_R, its attitude angles beta, beta' (Eq. 3) or its
//! orbit speed. Here they follow from the balance of one ball, in the frame of the nut (which
//! does not rotate; the screw turns at omega and slides along its own helix). By the helical
//! symmetry every ball of a circle is in the same state, so one ball per circle is solved.
//!
//! Unknowns (per unit screw speed where they are rates):
//! - the ball's angular velocity (omega_t, omega_n, omega_b) in its Frenet frame (Eq. 3),
//! - the orbit rate of the ball centre about the screw axis Omega_c / omega,
//! - the normal loads Q_A (nut) and Q_B (screw), as ratios to the nominal load,
//! - the tilt gamma of the contact normals: the lateral friction is carried by the normal forces,
//!   which is possible because the ball centre shifts sideways in the conforming grooves: the
//!   screw normal turns by gamma and the nut normal by atan(tan(gamma) d_s / d_N) the other way
//!   (d = (f - 1/2) D_w, the arc-centre offsets), so the contact angles at nut and screw differ
//!   by about 2 f.
//!
//! Equations: force balance along t, n, b; moment balance about t, n, b; and the axial load the
//! ball carries between screw and nut (its share of the nut load).

use crate::ball::balance::{Constants, Load};
use crate::ball::frames::rotate_z;
use crate::ball::setup::{BallSetup, N, RacewaySetup, Unknowns};
use crate::contact::creep::{RelativeMotion, creepages, direction};
use crate::contact::fastsim::{self, FastsimInput, Grid, TractionBound};
use crate::contact::forces;
use crate::contact::forces::{ContactForce, ContactStiffness, creep_force};
use crate::contact::hertz::HertzContact;
use crate::contact::patch::{Contact, Creep};
use crate::input::ContactTheory;
use nalgebra::Vector3;

/// One raceway contact of a ball in a given state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RacewayState {
    /// Normal load Q, N.
    pub load_n: f64,
    /// Contact angle beta (between n and the contact line), rad.
    pub contact_angle_rad: f64,
    /// Hertz contact.
    pub hertz: HertzContact,
    /// Contact centre, m (global frame, ball at theta = 0).
    pub point: Vector3<f64>,
    /// Point where the tangential force acts (Heathcote depth), m.
    pub point_eff: Vector3<f64>,
    /// Contact normal, towards the ball centre.
    pub normal: Vector3<f64>,
    /// Creepages.
    pub creep: crate::contact::creep::Creepage,
    /// Creep forces (on the ball).
    pub force: ContactForce,
    /// Tangential force on the ball (vector), N.
    pub tangential: Vector3<f64>,
    /// Slip speed of the ball over the raceway at the actual speed, m/s.
    pub slip_speed_m_s: f64,
    /// Dissipated power per unit screw speed D / omega, J/rad (sign of omega).
    pub dissipation_per_speed: f64,
    /// Friction bound f Q (f the contact's friction coefficient), N.
    pub friction_bound_n: f64,
    /// Rolling resistance on the ball (through its centre), N ([`crate::ball::lubrication`]).
    pub rolling_resistance: Vector3<f64>,
    /// The rolling resistance's part of `dissipation_per_speed`, J/rad (EHL and hysteresis).
    pub rolling_dissipation_per_speed: f64,
    /// The hysteresis part of `rolling_dissipation_per_speed`, J/rad.
    pub hysteresis_dissipation_per_speed: f64,
}

/// The ball-ball contact ahead of a ball.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallBallState {
    /// Normal load Q_m, N.
    pub load_n: f64,
    /// Contact point, m.
    pub point: Vector3<f64>,
    /// Friction force on the ball (vector), N.
    pub friction: Vector3<f64>,
    /// Slip speed between the two balls at the actual speed, m/s.
    pub slip_speed_m_s: f64,
    /// Rolling speed (mean surface speed relative to the contact point), m/s.
    pub rolling_speed_m_s: f64,
    /// Dissipated power per unit screw speed, J/rad.
    pub dissipation_per_speed: f64,
}

/// A ball's full state: contacts, residual, and what it exerts on the screw.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallState {
    /// Ball centre, m.
    pub centre: Vector3<f64>,
    /// Frenet frame (t, n, b) at the centre.
    pub t: Vector3<f64>,
    /// Principal normal.
    pub n: Vector3<f64>,
    /// Binormal.
    pub b: Vector3<f64>,
    /// Ball angular velocity per unit screw speed (global frame).
    pub omega_ball: Vector3<f64>,
    /// Nut contact (A).
    pub nut: RacewayState,
    /// Screw contact (B).
    pub screw: RacewayState,
    /// Ball-ball contact ahead (zero load when Q_m = 0).
    pub ball_ball: BallBallState,
    /// Scaled residual of the balance.
    pub residual: [f64; N],
    /// Moment about the screw axis of everything the ball exerts on the screw, N m.
    pub screw_moment_z_nm: f64,
    /// Axial force the ball exerts on the screw, N.
    pub screw_force_z_n: f64,
}

/// Axis of the screw.
pub(crate) fn z_axis() -> Vector3<f64> {
    Vector3::z()
}

/// Velocity per unit screw speed of a point rigidly carried by a helical motion of rate `rate`
/// about z with lead per radian `h`: rate (z x p + h z).
pub(crate) fn helical_velocity(p: &Vector3<f64>, rate: f64, h: f64) -> Vector3<f64> {
    Vector3::new(-p.y, p.x, h) * rate
}

/// Surface motion of ball and raceway at point `x`.
#[allow(clippy::too_many_arguments)]
fn motion_at(
    x: &Vector3<f64>,
    centre: &Vector3<f64>,
    v_centre: &Vector3<f64>,
    omega_ball: &Vector3<f64>,
    orbit: f64,
    h: f64,
    screw: bool,
    g: &Vector3<f64>,
) -> RelativeMotion {
    let v_ball = v_centre + omega_ball.cross(&(x - centre));
    let (v_race, omega_race) =
        if screw { (helical_velocity(x, 1.0, h), z_axis()) } else { (Vector3::zeros(), Vector3::zeros()) };
    let v_point = helical_velocity(x, orbit, h);
    RelativeMotion {
        slip: v_ball - v_race,
        mean: (v_ball + v_race) * 0.5 - v_point,
        spin: (omega_ball - omega_race).dot(g),
    }
}

/// The ball's motion per unit screw speed, shared by its contacts.
pub(crate) struct BallMotion {
    pub(crate) centre: Vector3<f64>,
    pub(crate) v_centre: Vector3<f64>,
    pub(crate) omega_ball: Vector3<f64>,
    pub(crate) orbit: f64,
    pub(crate) t: Vector3<f64>,
    pub(crate) n: Vector3<f64>,
    /// Screw speed, rad/s.
    pub(crate) speed_rad_s: f64,
    /// Standstill factor on the creep forces.
    pub(crate) factor: f64,
}

pub(crate) fn raceway_state(
    s: &BallSetup,
    rs: &RacewaySetup,
    screw: bool,
    u: &Vector3<f64>,
    load_n: f64,
    m: &BallMotion,
) -> RacewayState {
    let q = if load_n > 0.0 { load_n } else { 0.0 };
    let hz = rs.shape.contact(q);
    let rho = s.rb_m - 0.5 * hz.approach_m;
    let depth = if s.heathcote && rs.pressure_radius_m > 0.0 {
        hz.semi_axis_lateral_m * hz.semi_axis_lateral_m / (10.0 * rs.pressure_radius_m)
    } else {
        0.0
    };
    let g = -u;
    let point = m.centre + u * rho;
    let point_eff = m.centre + u * (rho - depth);
    let h = s.lead_per_rad_m;
    let at_depth = motion_at(&point_eff, &m.centre, &m.v_centre, &m.omega_ball, m.orbit, h, screw, &g);
    // The motion at the contact centre gives only the Heathcote part of xi (reported, and used
    // by FASTSIM); xi itself is taken at the effective point.
    let at_centre = motion_at(&point, &m.centre, &m.v_centre, &m.omega_ball, m.orbit, h, screw, &g);
    let cr = creepages(&at_depth, &at_centre, &m.t, &g, m.speed_rad_s);
    let stiffness = ContactStiffness::for_ellipse(
        s.shear_modulus_pa * s.stiffness_scale,
        hz.semi_axis_rolling_m,
        hz.semi_axis_lateral_m,
        rs.shape.complete_e_value(),
        rs.coefficients,
        rs.friction.mu * q,
    );
    let mut force = match s.contact_theory {
        ContactTheory::LinearSaturated => creep_force(&cr, &stiffness, s.spin),
        ContactTheory::Fastsim => fastsim_force(s, rs.friction.mu, &cr, &hz, q, &stiffness),
    };
    // Standstill regularisation (docs/model-notes.md item 13) on the saturated forces.
    force.e_n *= m.factor;
    force.f_n *= m.factor;
    force.moment_nm *= m.factor;
    let tangential = cr.e * force.e_n + cr.f * force.f_n;
    // Rolling resistance through the ball centre along the rolling direction t, in the sense of
    // the entrainment velocity at the actual speed; its power is over the speed of the centre
    // relative to the raceway.
    let v_unit = at_depth.mean.norm();
    let rr = rs.friction.rolling_resistance_n();
    let rolling = if rr > 0.0 && v_unit > 0.0 && v_unit.is_finite() {
        let sense = if at_depth.mean.dot(&m.t) >= 0.0 { 1.0 } else { -1.0 };
        m.t * (sense * direction(m.speed_rad_s) * rr)
    } else {
        Vector3::zeros()
    };
    let v_body_centre = if screw { helical_velocity(&m.centre, 1.0, h) } else { Vector3::zeros() };
    let rolling_dissipation = -rolling.dot(&(m.v_centre - v_body_centre));
    RacewayState {
        load_n: q,
        contact_angle_rad: libm::atan2(libm::fabs(u.dot(&(m.t.cross(&m.n)))), libm::fabs(u.dot(&m.n))),
        hertz: hz,
        point,
        point_eff,
        normal: g,
        creep: cr,
        force,
        tangential,
        slip_speed_m_s: libm::fabs(m.speed_rad_s) * at_depth.slip.norm(),
        dissipation_per_speed: -(tangential.dot(&at_depth.slip) + force.moment_nm * at_depth.spin)
            + rolling_dissipation,
        friction_bound_n: rs.friction.mu * q,
        rolling_resistance: rolling,
        rolling_dissipation_per_speed: rolling_dissipation,
        hysteresis_dissipation_per_speed: rolling_dissipation * rs.friction.hysteresis_fraction(),
    }
}

/// Creep forces of a raceway contact by FASTSIM (Kalker's simplified theory) instead of Eq. (24):
/// the centre-line creepage is xi minus its Heathcote mean, and the Heathcote field k_h y^2 has
/// the pressure-weighted mean k_h b^2 / 5 = that part. The linear forces are reported beside.
fn fastsim_force(
    s: &BallSetup,
    mu: f64,
    cr: &crate::contact::creep::Creepage,
    hz: &HertzContact,
    q: f64,
    k: &ContactStiffness,
) -> ContactForce {
    let (fe, ff, m) = forces::linear(cr, k);
    let b = hz.semi_axis_lateral_m;
    let input = FastsimInput {
        contact: Contact {
            semi_axis_rolling_m: hz.semi_axis_rolling_m,
            semi_axis_lateral_m: b,
            normal_load_n: q,
            shear_modulus_pa: k.shear_modulus_pa,
            poisson_ratio: s.poisson_ratio,
            friction_coefficient: mu,
        },
        creep: Creep {
            xi: cr.xi - cr.heathcote,
            eta: cr.eta,
            phi_per_m: cr.phi,
            heathcote_per_m2: fastsim::heathcote_per_m2(cr.heathcote, b),
        },
        bound: TractionBound::Parabolic,
        grid: Grid::Strips,
    };
    let n = s.fastsim_grid as usize;
    match fastsim::fastsim(&input, n, n, None) {
        Ok(r) => {
            let lin = libm::sqrt(fe * fe + ff * ff);
            let sat = libm::sqrt(r.force_e_n * r.force_e_n + r.force_f_n * r.force_f_n);
            ContactForce {
                linear_e_n: fe,
                linear_f_n: ff,
                linear_moment_nm: m,
                e_n: r.force_e_n,
                f_n: r.force_f_n,
                moment_nm: r.spin_moment_nm,
                saturation: if lin > 0.0 { sat / lin } else { 1.0 },
            }
        }
        // No contact (zero load): no force.
        Err(_) => ContactForce { linear_e_n: fe, linear_f_n: ff, linear_moment_nm: m, ..ContactForce::default() },
    }
}

/// Force and moment (about the ball centre) on the ball from the neighbour at angle `offset`
/// (+spacing: ahead, -spacing: behind), and the contact's state.
#[allow(clippy::too_many_arguments)]
pub(crate) fn ball_ball(
    s: &BallSetup,
    offset: f64,
    centre: &Vector3<f64>,
    v_centre: &Vector3<f64>,
    omega_ball: &Vector3<f64>,
    (q, q_friction): (f64, f64),
    orbit: f64,
    speed_rad_s: f64,
    factor: f64,
) -> (Vector3<f64>, Vector3<f64>, BallBallState) {
    let h = s.lead_per_rad_m;
    let other = Vector3::new(s.rm_m * libm::cos(offset), s.rm_m * libm::sin(offset), h * offset);
    let omega_other = rotate_z(omega_ball, offset);
    let v_other = helical_velocity(&other, orbit, h);
    let point = (centre + other) * 0.5;
    let g = (centre - other).normalize();
    let v_this = v_centre + omega_ball.cross(&(point - centre));
    let v_that = v_other + omega_other.cross(&(point - other));
    let slip = v_this - v_that;
    let slip_t = slip - g * slip.dot(&g);
    let mean = (v_this + v_that) * 0.5 - helical_velocity(&point, orbit, h);
    let sn = slip_t.norm();
    // Full slip (adjacent balls turn the same way): friction f Q_m against the slip at the
    // actual speed, with the standstill factor.
    let friction = if sn > 0.0 && q_friction > 0.0 {
        slip_t * (-direction(speed_rad_s) * s.ball_ball_mu * q_friction * factor / sn)
    } else {
        Vector3::zeros()
    };
    let normal = g * q;
    let moment = (point - centre).cross(&friction);
    let state = BallBallState {
        load_n: q,
        point,
        friction,
        slip_speed_m_s: libm::fabs(speed_rad_s) * sn,
        rolling_speed_m_s: libm::fabs(speed_rad_s) * (mean - g * mean.dot(&g)).norm(),
        dissipation_per_speed: -friction.dot(&slip_t),
    };
    (normal + friction, moment, state)
}

/// Evaluates a ball in state `x` at screw speed `speed_rad_s` with standstill factor `factor`:
/// every contact with what a report shows. The frame, the contact lines and the scaling of the
/// residual are those of [`balance`](crate::ball::balance), whose lean form of the same balance Newton's method
/// evaluates for the linear-saturated contacts.
pub fn ball_state(s: &BallSetup, x: &Unknowns, speed_rad_s: f64, factor: f64) -> BallState {
    let c = Constants::new(s, 0.0);
    let fr = c.frame();
    let (centre, t, n, b) = (fr.centre, fr.t, fr.n, fr.b);
    let omega_ball = t * x[0] + n * x[1] + b * x[2];
    let orbit = x[3];
    let v_centre = helical_velocity(&centre, orbit, s.lead_per_rad_m);
    let load = Load { axial_load_n: s.axial_load_n, direction: direction(speed_rad_s), factor };
    let q0 = c.nominal_load_n(s.axial_load_n);
    let (u_screw, u_nut) = c.contact_lines(&fr, x[6]);
    let motion = BallMotion { centre, v_centre, omega_ball, orbit, t, n, speed_rad_s, factor };
    let screw = raceway_state(s, &s.screw, true, &u_screw, x[5] * q0, &motion);
    let nut = raceway_state(s, &s.nut, false, &u_nut, x[4] * q0, &motion);

    let mut force = screw.normal * screw.load_n
        + screw.tangential
        + screw.rolling_resistance
        + nut.normal * nut.load_n
        + nut.tangential
        + nut.rolling_resistance;
    let mut moment = (screw.point_eff - centre).cross(&screw.tangential)
        + screw.normal * screw.force.moment_nm
        + (nut.point_eff - centre).cross(&nut.tangential)
        + nut.normal * nut.force.moment_nm;
    let mut ahead = BallBallState {
        load_n: 0.0,
        point: centre,
        friction: Vector3::zeros(),
        slip_speed_m_s: 0.0,
        rolling_speed_m_s: 0.0,
        dissipation_per_speed: 0.0,
    };
    if s.has_ball_ball_load() {
        let plus = (s.ball_ball_plus_n, s.ball_ball_plus_friction_n);
        let minus = (s.ball_ball_minus_n, s.ball_ball_minus_friction_n);
        let (f1, m1, st) =
            ball_ball(s, s.spacing_rad, &centre, &v_centre, &omega_ball, plus, orbit, speed_rad_s, factor);
        let (f2, m2, _) =
            ball_ball(s, -s.spacing_rad, &centre, &v_centre, &omega_ball, minus, orbit, speed_rad_s, factor);
        force += f1 + f2;
        moment += m1 + m2;
        ahead = st;
    }
    // What the ball exerts on the screw: minus the screw's force on the ball, at the contact.
    let on_screw = -(screw.normal * screw.load_n);
    let on_screw_t = -screw.tangential;
    let z = z_axis();
    let on_screw_r = -screw.rolling_resistance;
    let screw_moment_z_nm = z.dot(&(screw.point.cross(&on_screw)))
        + z.dot(&(screw.point_eff.cross(&on_screw_t)))
        + z.dot(&(centre.cross(&on_screw_r)))
        - z.dot(&screw.normal) * screw.force.moment_nm;
    let screw_force_z_n = (on_screw + on_screw_t + on_screw_r).z;
    let residual = c.residual(&fr, &force, &moment, screw_force_z_n, &load);
    BallState {
        centre,
        t,
        n,
        b,
        omega_ball,
        nut,
        screw,
        ball_ball: ahead,
        residual,
        screw_moment_z_nm,
        screw_force_z_n,
    }
}

/// Attitude of the ball's angular velocity (Eq. 3): (omega_R, beta, beta') from
/// (omega_t, omega_n, omega_b): omega_t = omega_R cos(beta) sin(beta'),
/// omega_b = omega_R cos(beta) cos(beta'), omega_n = omega_R sin(beta).
pub fn attitude(x: &Unknowns) -> (f64, f64, f64) {
    let (wt, wn, wb) = (x[0], x[1], x[2]);
    let wr = libm::sqrt(wt * wt + wn * wn + wb * wb);
    if wr == 0.0 {
        return (0.0, 0.0, 0.0);
    }
    (wr, libm::asin((wn / wr).clamp(-1.0, 1.0)), libm::atan2(wt, wb))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Model, ScrewSpec};

    /// docs/model-notes.md item 3: the paper's scalar creepage formulas are kept as a check in the limit
    /// where they agree with each other. Without helix (alpha -> 0) and with the ball's angular
    /// velocity in the t-n plane (omega_b = 0, where the sign conflict of Eqs. 12c/14c between
    /// the omega_b terms vanishes):
    /// - Eq. (14c): phi_B = (omega_bSg - omega_Sg) / V_rB with omega_bSg = -omega_n cos(beta_B)
    ///   and omega_Sg = -omega sin(beta_B) (Eq. 11c);
    /// - Eq. (8b): xi_fA = (V_bNf - V_Nf) / V_rA with V_bNf = omega_t (r_b - delta) (Eq. 5b),
    ///   V_Nf = 0 (Eq. 4b): the lateral creepage at the nut comes from omega_t alone.
    #[test]
    fn paper_scalar_formulas_agree_in_their_consistent_limit() {
        // A lead of 1e-9 m is below the spec's valid range: set the ball's helix directly.
        let mut geometry = ScrewSpec::dkfzd4012().geometry;
        geometry.lead_m = 1e-9;
        let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
        let s = BallSetup {
            lead_per_rad_m: crate::input::geometry::lead_per_rad(&geometry),
            helix_angle_rad: crate::input::geometry::helix_angle_rad(&geometry),
            ..model.ball_setup_for(30.0, 1.0)
        };
        let beta = s.contact_angle_rad;
        for &(wt, wn, orbit) in &[(0.05, 2.6, 0.45), (-0.2, 3.1, 0.44), (0.0, 2.0, 0.47)] {
            let x = [wt, wn, 0.0, orbit, 1.0, 1.0, 0.0];
            let st = ball_state(&s, &x, 1.0, 1.0);
            let v_b = st.screw.creep.rolling_speed_m_s;
            let phi_paper = (-wn * libm::cos(beta) + libm::sin(beta)) / v_b;
            assert!((st.screw.creep.phi - phi_paper).abs() < 1e-9 * phi_paper.abs().max(1.0), "Eq. 14c");
            // The lever is the effective point's radius (Heathcote depth included, creep.rs).
            let rho = (st.nut.point_eff - st.centre).norm();
            let v_a = st.nut.creep.rolling_speed_m_s;
            let eta_paper = rho * wt / v_a;
            assert!(
                (st.nut.creep.eta.abs() - eta_paper.abs()).abs() < 1e-9,
                "Eq. 8b: {} vs {eta_paper}",
                st.nut.creep.eta
            );
        }
    }
}
