//! What the model reports of a solved screw: every contact ([`ContactReport`]), every ball
//! ([`BallReport`]), the summary of an operating point ([`Summary`]: the drive torque and its
//! parts, the catalog comparison) and the full evaluation ([`Evaluation`]), with the builders
//! that fill them from a solved ball.

use crate::ball::report::{self};
use crate::ball::solve::SolveReport;
use crate::contact::fastsim::{self, FastsimInput, Grid, TractionBound};
use crate::contact::hertz::HertzContact;
use crate::contact::patch::{Contact, Creep};
use crate::input::{MAX_CIRCLES_PER_NUT, MAX_NUTS, Material, OperatingPoint, Preload};

/// Which contact of a ball.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactKind {
    /// Ball-screw contact (B).
    Screw,
    /// Ball-nut contact (A).
    Nut,
    /// Ball-ball contact (m), the one ahead of the ball.
    BallBall,
}

impl ContactKind {
    /// Lower-case name: `screw`, `nut`, `ball-ball`.
    pub fn name(&self) -> &'static str {
        match self {
            ContactKind::Screw => "screw",
            ContactKind::Nut => "nut",
            ContactKind::BallBall => "ball-ball",
        }
    }
}

/// One contact of one ball, as `ballscrew inspect` shows it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactReport {
    /// Which contact.
    pub kind: ContactKind,
    /// Normal load, N.
    pub normal_load_n: f64,
    /// Contact angle (between the principal normal n and the contact line), rad; 0 for ball-ball.
    pub contact_angle_rad: f64,
    /// Hertz semi-axis along the rolling direction, m.
    pub semi_axis_rolling_m: f64,
    /// Hertz semi-axis across (lateral), m.
    pub semi_axis_lateral_m: f64,
    /// Hertz approach delta, m.
    pub approach_m: f64,
    /// Hertz peak pressure, Pa.
    pub peak_pressure_pa: f64,
    /// Rolling speed, m/s.
    pub rolling_speed_m_s: f64,
    /// Slip speed of the ball over the other body, m/s.
    pub slip_speed_m_s: f64,
    /// Longitudinal creepage xi (Heathcote part included); 0 for ball-ball (full slip).
    pub creep_longitudinal: f64,
    /// Lateral creepage eta.
    pub creep_lateral: f64,
    /// Spin creepage phi, 1/m.
    pub creep_spin_per_m: f64,
    /// Heathcote part of xi.
    pub creep_heathcote: f64,
    /// Linear (Kalker) force along the rolling direction, N.
    pub linear_force_rolling_n: f64,
    /// Linear force lateral, N.
    pub linear_force_lateral_n: f64,
    /// Linear spin moment, N m.
    pub linear_spin_moment_nm: f64,
    /// Saturated force along the rolling direction, N.
    pub force_rolling_n: f64,
    /// Saturated force lateral, N.
    pub force_lateral_n: f64,
    /// Saturated spin moment, N m.
    pub spin_moment_nm: f64,
    /// Friction bound f Q, N.
    pub friction_bound_n: f64,
    /// Saturated over linear magnitude (1: linear, -> 0: full slip); 0 for ball-ball.
    pub saturation: f64,
    /// This contact's dissipation per unit screw speed for one ball, J/rad (= N m).
    pub dissipation_per_ball_nm: f64,
    /// This contact's share of the drive torque over the balls of its circle at the full load
    /// (all of them without a load ramp; a ramp's balls are in the totals only), N m: the sum
    /// of the next three.
    pub torque_share_nm: f64,
    /// Creep and sliding's part of `torque_share_nm`, N m.
    pub creep_torque_share_nm: f64,
    /// EHL rolling resistance's part, N m.
    pub rolling_torque_share_nm: f64,
    /// Elastic hysteresis's part, N m.
    pub hysteresis_torque_share_nm: f64,
    /// Central film thickness h_c (Hamrock-Dowson, thermal and starvation factors), m; 0 for a
    /// dry or ball-ball contact.
    pub film_central_m: f64,
    /// Minimum film thickness, m.
    pub film_minimum_m: f64,
    /// Film parameter Lambda = h_c / sigma.
    pub lambda: f64,
    /// Friction coefficient of the contact: the bound of Eq. (24) over Q.
    pub friction_coefficient: f64,
    /// EHL rolling resistance on the ball, N.
    pub rolling_resistance_ehl_n: f64,
    /// Elastic hysteresis rolling resistance on the ball, N.
    pub rolling_resistance_hysteresis_n: f64,
}

impl ContactReport {
    /// This raceway contact as FASTSIM's input, with the shear modulus and Poisson's ratio of
    /// `material`: its Hertz semi-axes, load and friction coefficient; the centre-line creepage
    /// is `creep_longitudinal` without its Heathcote mean, the Heathcote field `k_h y^2` has that
    /// mean ([`fastsim::heathcote_per_m2`]); Kalker's parabolic bound on the strips grid.
    pub fn fastsim_input(&self, material: &Material) -> FastsimInput {
        FastsimInput {
            contact: Contact {
                semi_axis_rolling_m: self.semi_axis_rolling_m,
                semi_axis_lateral_m: self.semi_axis_lateral_m,
                normal_load_n: self.normal_load_n,
                shear_modulus_pa: material.shear_modulus_pa(),
                poisson_ratio: material.poisson_ratio,
                friction_coefficient: self.friction_coefficient,
            },
            creep: Creep {
                xi: self.creep_longitudinal - self.creep_heathcote,
                eta: self.creep_lateral,
                phi_per_m: self.creep_spin_per_m,
                heathcote_per_m2: fastsim::heathcote_per_m2(self.creep_heathcote, self.semi_axis_lateral_m),
            },
            bound: TractionBound::Parabolic,
            grid: Grid::Strips,
        }
    }
}

/// One ball (standing for its circle's balls at the full load: every ball of it without a load
/// ramp).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallReport {
    /// Nut index (0-based).
    pub nut: usize,
    /// Circle index within the nut (0-based).
    pub circle: usize,
    /// Flank (+1 / -1).
    pub flank: f64,
    /// Balls of the circle at its full load, which this ball stands for (its contacts' shares):
    /// the circle's balls less its load ramps' ([`crate::input::circulation`]).
    pub balls: u32,
    /// Balls of the circle's load ramps: together they carry half as many full balls' load; in
    /// the totals, not in this ball's shares. 0 without a ramp.
    pub ramp_balls: u32,
    /// Weight on this circle's friction (1 except for the paper-literal load option).
    pub weight: f64,
    /// The ball's share of the nut's axial load, N.
    pub axial_load_n: f64,
    /// Newton solve of the ball's balance.
    pub solve: SolveReport,
    /// Ball angular velocity per unit screw speed in (t, n, b) (Eq. 3's omega_t, omega_n, omega_b).
    pub omega_tnb_per_screw: [f64; 3],
    /// omega_R / omega.
    pub spin_ratio: f64,
    /// Attitude angle beta of Eq. 3, rad.
    pub beta_rad: f64,
    /// Attitude angle beta' of Eq. 3, rad.
    pub beta_prime_rad: f64,
    /// Orbit rate of the ball centre about the axis over the screw speed.
    pub orbit_ratio: f64,
    /// The orbit ratio the ball would have alone, free of its circuit's other circles (its own
    /// balance, the return's resistance shared evenly over the circuit's balls): where the
    /// circles of a circuit differ in it, the faster push the slower and all orbit at
    /// `orbit_ratio` ([`crate::screw::circuit`]). Equal to `orbit_ratio` in a circuit of one turn.
    pub free_orbit_ratio: f64,
    /// The ball's push along the ball train, N: the load of its contact with the ball behind
    /// less that of its contact with the ball ahead (in the direction the balls travel); the
    /// faster circles of a circuit are held back (negative), the slower pushed (positive)
    /// ([`crate::screw::train`], [`crate::screw::circuit`]).
    pub push_n: f64,
    /// The chain force at the contact behind the circle's first ball (in the order of travel),
    /// N: zero at the train's gap.
    pub chain_in_n: f64,
    /// The chain force at the contact ahead of the circle's last ball, N.
    pub chain_out_n: f64,
    /// Contacts: nut (A), screw (B), ball-ball (m).
    pub contacts: [ContactReport; 3],
}

/// The scalar results of one evaluation: the torque by every route and what it is made of.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Summary {
    /// The operating point.
    pub operating: OperatingPoint,
    /// The torque by the spec's torque route with the spec's extension terms, N m.
    pub torque_nm: f64,
    /// What the extension terms add to the route's torque, N m (0 without extensions).
    pub extension_nm: f64,
    /// T = F_a L / (2 pi) + D / omega, N m.
    pub torque_energy_nm: f64,
    /// Moment about the screw axis of everything the balls exert on the screw, N m.
    pub torque_moment_nm: f64,
    /// Eq. (27) as printed (plus F_a L / (2 pi)), N m.
    pub torque_eq27_nm: f64,
    /// F_a L / (2 pi), N m.
    pub axial_term_nm: f64,
    /// D / omega, N m: the sum of the next five shares.
    pub dissipation_torque_nm: f64,
    /// The raceway contacts' creep and sliding share of `dissipation_torque_nm`, N m.
    pub creep_torque_nm: f64,
    /// The EHL (film) rolling resistance's share, N m (0 for dry contacts).
    pub rolling_resistance_torque_nm: f64,
    /// The elastic hysteresis's share, N m (0 for dry contacts).
    pub hysteresis_torque_nm: f64,
    /// The ball-ball contacts' share, N m.
    pub ball_ball_torque_nm: f64,
    /// The return path's share: its resistance moved at the train's speed
    /// ([`crate::input::circulation`]), N m.
    pub return_torque_nm: f64,
    /// The nuts' seals, N m (in every torque route; `friction.seal_torque_per_nut_nm`).
    pub seal_torque_nm: f64,
    /// Axial force all balls exert on the screw (weighted), N.
    pub screw_axial_force_n: f64,
    /// Axial load of each nut, N.
    pub nut_loads_n: [f64; MAX_NUTS],
    /// Catalog estimate of the preload drag torque, N m.
    pub catalog_nm: f64,
    /// Newton iterations over all balls.
    pub iterations: u32,
    /// Largest final residual over all balls.
    pub max_residual: f64,
}

impl Summary {
    /// The friction (drag) torque, N m: the drive torque without the load torque,
    /// `torque_nm - axial_term_nm`: the dissipation, the seals and the extension terms.
    pub fn drag_torque_nm(&self) -> f64 {
        self.torque_nm - self.axial_term_nm
    }

    /// The load torque F_a L / (2 pi), N m: the part of the drive torque that lifts the load
    /// (`axial_term_nm`); `drag_torque_nm() + load_torque_nm() == torque_nm` to rounding.
    pub fn load_torque_nm(&self) -> f64 {
        self.axial_term_nm
    }

    /// The model's drag torque ([`Summary::drag_torque_nm`]) over the catalog estimate (NaN
    /// when the catalog value is zero). The catalog estimates the preload drag torque, so the
    /// load torque F_a L / (2 pi) of an axial load is left out of the comparison.
    pub fn catalog_ratio(&self) -> f64 {
        if self.catalog_nm != 0.0 { self.drag_torque_nm() / self.catalog_nm } else { f64::NAN }
    }
}

/// The result of one evaluation with the per-contact breakdown.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Evaluation {
    /// The scalar results.
    pub summary: Summary,
    /// The preload arrangement.
    pub preload: Preload,
    /// Number of load groups: the nuts of a double nut, the halves of an offset-lead nut, the
    /// two contact diagonals of an oversize-ball nut (both in each ball: `balls[0][j]` and
    /// `balls[1][j]` are the same balls' two diagonals), the one nut without preload.
    pub nuts: usize,
    /// Circles per group.
    pub circles: usize,
    /// Per group and circle (only `[..nuts][..circles]` are meaningful).
    pub balls: [[BallReport; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
}

pub(crate) fn empty_contact(kind: ContactKind) -> ContactReport {
    ContactReport {
        kind,
        normal_load_n: 0.0,
        contact_angle_rad: 0.0,
        semi_axis_rolling_m: 0.0,
        semi_axis_lateral_m: 0.0,
        approach_m: 0.0,
        peak_pressure_pa: 0.0,
        rolling_speed_m_s: 0.0,
        slip_speed_m_s: 0.0,
        creep_longitudinal: 0.0,
        creep_lateral: 0.0,
        creep_spin_per_m: 0.0,
        creep_heathcote: 0.0,
        linear_force_rolling_n: 0.0,
        linear_force_lateral_n: 0.0,
        linear_spin_moment_nm: 0.0,
        force_rolling_n: 0.0,
        force_lateral_n: 0.0,
        spin_moment_nm: 0.0,
        friction_bound_n: 0.0,
        saturation: 0.0,
        dissipation_per_ball_nm: 0.0,
        torque_share_nm: 0.0,
        creep_torque_share_nm: 0.0,
        rolling_torque_share_nm: 0.0,
        hysteresis_torque_share_nm: 0.0,
        film_central_m: 0.0,
        film_minimum_m: 0.0,
        lambda: 0.0,
        friction_coefficient: 0.0,
        rolling_resistance_ehl_n: 0.0,
        rolling_resistance_hysteresis_n: 0.0,
    }
}

pub(crate) fn empty_ball() -> BallReport {
    BallReport {
        nut: 0,
        circle: 0,
        flank: 1.0,
        balls: 0,
        ramp_balls: 0,
        weight: 0.0,
        axial_load_n: 0.0,
        solve: SolveReport { iterations: 0, residual: 0.0, continuation_steps: 0 },
        omega_tnb_per_screw: [0.0; 3],
        spin_ratio: 0.0,
        beta_rad: 0.0,
        beta_prime_rad: 0.0,
        orbit_ratio: 0.0,
        free_orbit_ratio: 0.0,
        push_n: 0.0,
        chain_in_n: 0.0,
        chain_out_n: 0.0,
        contacts: [
            empty_contact(ContactKind::Nut),
            empty_contact(ContactKind::Screw),
            empty_contact(ContactKind::BallBall),
        ],
    }
}

pub(crate) fn raceway_report(
    kind: ContactKind,
    c: &report::RacewayState,
    film: Option<&crate::contact::ehl::EhlContact>,
    share: f64,
) -> ContactReport {
    let f = film.copied().unwrap_or_default();
    let rolling = c.rolling_resistance.norm();
    let hysteresis_fraction = if c.rolling_dissipation_per_speed != 0.0 {
        c.hysteresis_dissipation_per_speed / c.rolling_dissipation_per_speed
    } else {
        0.0
    };
    ContactReport {
        film_central_m: f.film_central_m,
        film_minimum_m: f.film_minimum_m,
        lambda: f.lambda_central,
        friction_coefficient: if c.load_n > 0.0 { c.friction_bound_n / c.load_n } else { 0.0 },
        rolling_resistance_ehl_n: rolling * (1.0 - hysteresis_fraction),
        rolling_resistance_hysteresis_n: rolling * hysteresis_fraction,
        creep_torque_share_nm: share * (c.dissipation_per_speed - c.rolling_dissipation_per_speed),
        rolling_torque_share_nm: share * (c.rolling_dissipation_per_speed - c.hysteresis_dissipation_per_speed),
        hysteresis_torque_share_nm: share * c.hysteresis_dissipation_per_speed,
        kind,
        normal_load_n: c.load_n,
        contact_angle_rad: c.contact_angle_rad,
        semi_axis_rolling_m: c.hertz.semi_axis_rolling_m,
        semi_axis_lateral_m: c.hertz.semi_axis_lateral_m,
        approach_m: c.hertz.approach_m,
        peak_pressure_pa: c.hertz.peak_pressure_pa,
        rolling_speed_m_s: c.creep.rolling_speed_m_s,
        slip_speed_m_s: c.slip_speed_m_s,
        creep_longitudinal: c.creep.xi,
        creep_lateral: c.creep.eta,
        creep_spin_per_m: c.creep.phi,
        creep_heathcote: c.creep.heathcote,
        linear_force_rolling_n: c.force.linear_e_n,
        linear_force_lateral_n: c.force.linear_f_n,
        linear_spin_moment_nm: c.force.linear_moment_nm,
        force_rolling_n: c.force.e_n,
        force_lateral_n: c.force.f_n,
        spin_moment_nm: c.force.moment_nm,
        friction_bound_n: c.friction_bound_n,
        saturation: c.force.saturation,
        dissipation_per_ball_nm: c.dissipation_per_speed,
        torque_share_nm: share * c.dissipation_per_speed,
    }
}

pub(crate) fn ball_ball_report(c: &report::BallBallState, hz: &HertzContact, mu: f64, share: f64) -> ContactReport {
    let mut r = empty_contact(ContactKind::BallBall);
    r.normal_load_n = c.load_n;
    if c.load_n > 0.0 {
        r.semi_axis_rolling_m = hz.semi_axis_rolling_m;
        r.semi_axis_lateral_m = hz.semi_axis_lateral_m;
        r.approach_m = hz.approach_m;
        r.peak_pressure_pa = hz.peak_pressure_pa;
    }
    r.rolling_speed_m_s = c.rolling_speed_m_s;
    r.slip_speed_m_s = c.slip_speed_m_s;
    r.force_rolling_n = c.friction.norm();
    r.friction_bound_n = mu * c.load_n;
    r.dissipation_per_ball_nm = c.dissipation_per_speed;
    r.torque_share_nm = share * c.dissipation_per_speed;
    r.creep_torque_share_nm = r.torque_share_nm;
    r.friction_coefficient = mu;
    r
}
