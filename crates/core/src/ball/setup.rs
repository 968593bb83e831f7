//! What one ball's balance depends on and solves for: the unknowns (the ball's angular velocity
//! in the contact frame, its orbit speed, the normal-load departures and the tilt), the solver's
//! tolerances, the bounds of a physical state, and the setup of the ball and its two raceway
//! contacts that does not change while the ball is solved.
//!
//! A solve is accepted only when its state is physical ([`check_state`]): a residual below the
//! tolerance alone does not make a state. The balance is homogeneous of degree zero in the
//! rates once they are large (creepages are ratios of velocities), and with both raceway
//! contacts in full slip it is degenerate (docs/model-notes.md item 11: a family of attitudes satisfies
//! it), so Newton's method can drift along states far from rolling and balance there. The
//! bounds are wide bands around the rolling ball, whose orbit ratio is
//! (1 - D_w cos(beta) / d_m) / 2 and whose spin is that orbit times r_m / (r_b cos(alpha)):
//! - orbit ratio in (0, 1): the ball centre goes round with the screw and slower than it. Its
//!   speed is the mean of the ball's surface speeds at the two (nearly opposite) contacts, i.e.
//!   of the raceways' (0 at the nut, 1 at the screw) plus the mean slip; leaving (0, 1) needs
//!   slips beyond the rolling speed at both contacts in the same sense, which the friction
//!   along the track (the two contacts' forces, opposed) cannot balance in the quasi-static
//!   branch the continuation selects from rolling;
//! - spin |omega| within a factor [`SPIN_BAND`] of the rolling ball's: an effective rolling
//!   radius between 1 % of the ball's and a hundred times it;
//! - normal loads positive and at most [`LOAD_BAND`] times the nominal load P / (sin(beta)
//!   cos(alpha)): the ball's compression is set by the nut's axial deflection under P, and
//!   the friction forces that tilt the normals are at most f Q each;
//! - the tilt of the contact normals within a right angle (beyond it the contact leaves its
//!   flank of the groove);
//! - every unknown finite.

use crate::contact::hertz::HertzShape;
use crate::contact::kalker::CreepCoefficients;
use crate::error::Unphysical;
use crate::input::{ContactTheory, SpinMoment};
use crate::real::Real;

/// Number of unknowns of one ball's balance.
pub const N: usize = 7;
/// The unknowns: [omega_t, omega_n, omega_b, orbit, q_nut, q_screw, gamma].
pub type Unknowns = [f64; N];

/// Convergence tolerance on the scaled residual (max norm).
pub const TOLERANCE: f64 = 1e-12;
/// Most Newton iterations of one solve.
pub const MAX_ITERATIONS: u32 = 60;
/// Smallest standstill factor used for the kinematic solve. The friction-only equations are
/// homogeneous in the factor, so below it only the tilt of the normals (which carries the
/// lateral friction) would still change (docs/model-notes.md item 13).
pub const MIN_SOLVE_FACTOR: f64 = 1e-3;

/// Factor of the band around the rolling ball's spin within which a state is physical (see the
/// module's documentation).
pub const SPIN_BAND: f64 = 100.0;
/// Largest orbit ratio of a physical state over the rolling ball's (see the module's
/// documentation).
pub const ORBIT_BAND: f64 = 10.0;
/// Largest normal load of a physical state over the nominal load (see the module's
/// documentation).
pub const LOAD_BAND: f64 = 10.0;

/// The bounds of a physical state of one ball (see the module's documentation), in the float
/// type of the solve.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StateBounds<F> {
    /// Squared bounds on the ball's spin |omega| per unit screw speed.
    spin_squared: (F, F),
    /// The rolling ball's spin per unit screw speed.
    rolling_spin: F,
    /// Largest orbit ratio.
    orbit_max: F,
    /// The rolling ball's orbit ratio.
    rolling_orbit: F,
}

impl<F: Real> StateBounds<F> {
    /// The bounds of a ball of setup `s`.
    pub fn new(s: &BallSetup) -> Self {
        let spin = rolling_spin(s);
        let (lo, hi) = (spin / SPIN_BAND, spin * SPIN_BAND);
        let orbit = rolling_orbit_ratio(s);
        Self {
            spin_squared: (F::of(lo * lo), F::of(hi * hi)),
            rolling_spin: F::of(spin),
            orbit_max: F::of(ORBIT_BAND * orbit),
            rolling_orbit: F::of(orbit),
        }
    }
}

/// The orbit ratio of a ball rolling without slip on both raceways, (1 - D_w cos(beta) / d_m) / 2:
/// its centre moves at half the screw's surface speed at the contact.
pub fn rolling_orbit_ratio(s: &BallSetup) -> f64 {
    0.5 * (s.rm_m - s.rb_m * libm::cos(s.contact_angle_rad)) / s.rm_m
}

/// The spin |omega| per unit screw speed of a ball rolling without slip (orbit ratio
/// [`rolling_orbit_ratio`]): its centre's speed along the helix over the ball radius.
pub fn rolling_spin(s: &BallSetup) -> f64 {
    rolling_orbit_ratio(s) * s.rm_m / libm::cos(s.helix_angle_rad) / s.rb_m
}

/// Whether the state `x` (see [`Unknowns`]) of a ball with bounds `b` is physical (see the
/// module's documentation); else the first quantity out of its bounds.
pub fn check_state<F: Real>(x: &[F; N], b: &StateBounds<F>) -> Result<(), Unphysical> {
    if let Some(&v) = x.iter().find(|v| !v.is_finite()) {
        return Err(Unphysical { quantity: "state (rates, loads, tilt)", value: v.to_f64(), valid: "finite" });
    }
    let zero = F::zero();
    if !(x[3] > zero && x[3] <= b.orbit_max) {
        return Err(Unphysical {
            quantity: "orbit ratio over the rolling ball's",
            value: x[3].to_f64() / b.rolling_orbit.to_f64(),
            valid: "(0, 10]",
        });
    }
    let spin = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    if !(spin >= b.spin_squared.0 && spin <= b.spin_squared.1) {
        return Err(Unphysical {
            quantity: "ball spin over the rolling ball's",
            value: spin.sqrt().to_f64() / b.rolling_spin.to_f64(),
            valid: "[0.01, 100]",
        });
    }
    for q in [x[4], x[5]] {
        if !(q > zero && q <= F::of(LOAD_BAND)) {
            return Err(Unphysical {
                quantity: "normal load over the nominal load",
                value: q.to_f64(),
                valid: "(0, 10]",
            });
        }
    }
    if !(x[6].abs() < F::of(core::f64::consts::FRAC_PI_2)) {
        return Err(Unphysical {
            quantity: "tilt of the contact normals, rad",
            value: x[6].to_f64(),
            valid: "(-pi/2, pi/2)",
        });
    }
    Ok(())
}

/// The friction of one raceway contact in one solve: the bound of Eq. (24) and the rolling
/// resistance on the ball. Dry ([`ContactFriction::dry`]): `friction.coefficient` and none;
/// lubricated: the values of the contact's EHL film at the ball's nominal load and rolling
/// speed ([`crate::ball::lubrication`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactFriction {
    /// Friction coefficient, the bound of Eq. (24) over the normal load.
    pub mu: f64,
    /// EHL (film) rolling resistance on the ball, N: a force through the ball centre along the
    /// entrainment velocity of the contact (against the ball's rolling over this raceway).
    pub rolling_resistance_ehl_n: f64,
    /// Elastic hysteresis rolling resistance on the ball, N, on the same line.
    pub rolling_resistance_hysteresis_n: f64,
}

impl ContactFriction {
    /// A dry contact of friction coefficient `mu`: no rolling resistance.
    pub fn dry(mu: f64) -> Self {
        Self { mu, rolling_resistance_ehl_n: 0.0, rolling_resistance_hysteresis_n: 0.0 }
    }

    /// Total rolling resistance, N.
    pub fn rolling_resistance_n(&self) -> f64 {
        self.rolling_resistance_ehl_n + self.rolling_resistance_hysteresis_n
    }

    /// The hysteresis part of the rolling resistance (0 without rolling resistance).
    pub fn hysteresis_fraction(&self) -> f64 {
        let total = self.rolling_resistance_n();
        if total > 0.0 { self.rolling_resistance_hysteresis_n / total } else { 0.0 }
    }
}

/// What a raceway contact needs that does not change while its ball is solved.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RacewaySetup {
    /// Hertz ellipse shape (exact, elliptic integrals) at the nominal contact angle.
    pub shape: HertzShape,
    /// Kalker coefficients for this contact's a/b.
    pub coefficients: CreepCoefficients,
    /// Radius of the deformed contact surface across the groove (Heathcote slip), m.
    pub pressure_radius_m: f64,
    /// Arc-centre offset d = (f - 1/2) D_w of the groove, m.
    pub arc_offset_m: f64,
    /// Effective radius in the rolling plane R_x (the EHL film's), m.
    pub rolling_radius_m: f64,
    /// The constants of the contact's film laws with the model's oil
    /// ([`crate::ball::lubrication::film_constants`]); `None` for dry contacts.
    pub film: Option<crate::contact::ehl::FilmConstants>,
    /// Friction of the contact in this solve.
    pub friction: ContactFriction,
}

/// Everything one ball's balance depends on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallSetup {
    /// Pitch radius r_m, m.
    pub rm_m: f64,
    /// Lead per radian L / (2 pi), m/rad.
    pub lead_per_rad_m: f64,
    /// Helix angle alpha, rad.
    pub helix_angle_rad: f64,
    /// Ball radius r_b, m.
    pub rb_m: f64,
    /// Nominal contact angle beta, rad.
    pub contact_angle_rad: f64,
    /// Flank the ball bears on: +1 (screw contact towards +b) or -1.
    pub flank: f64,
    /// Shear modulus G, Pa.
    pub shear_modulus_pa: f64,
    /// Friction coefficient f (`friction.coefficient`): the scale of the residual. The raceway
    /// contacts carry their own ([`RacewaySetup::friction`]): f when dry, the film's when
    /// lubricated; the ball-ball contacts theirs ([`BallSetup::ball_ball_mu`]).
    pub mu: f64,
    /// Factor on the creep stiffness G (1 for the model; lowered by the continuation).
    pub stiffness_scale: f64,
    /// The ball's share of its nut's axial load, N (> 0).
    pub axial_load_n: f64,
    /// Normal load of the ball-ball contact with the neighbour at `+spacing_rad` (ahead in the
    /// direction of increasing angle), N.
    pub ball_ball_plus_n: f64,
    /// Normal load of the ball-ball contact with the neighbour at `-spacing_rad`, N.
    pub ball_ball_minus_n: f64,
    /// The load whose friction the contact at `+spacing_rad` carries, N: its normal load, but
    /// where the neighbour is a ball of the return, which turns freely and rolls on this one
    /// ([`crate::screw::train`]).
    pub ball_ball_plus_friction_n: f64,
    /// The load whose friction the contact at `-spacing_rad` carries, N.
    pub ball_ball_minus_friction_n: f64,
    /// Friction coefficient of the ball-ball contacts: the surfaces slide at zero entrainment
    /// speed, so no film forms (the lubricant's boundary friction; dry: `friction.coefficient`).
    pub ball_ball_mu: f64,
    /// Angle about the axis between adjacent ball centres, rad.
    pub spacing_rad: f64,
    /// Screw contact.
    pub screw: RacewaySetup,
    /// Nut contact.
    pub nut: RacewaySetup,
    /// Heathcote slip on or off.
    pub heathcote: bool,
    /// Spin moment option.
    pub spin: SpinMoment,
    /// Poisson's ratio (FASTSIM's flexibilities).
    pub poisson_ratio: f64,
    /// Contact theory of the raceway contacts.
    pub contact_theory: ContactTheory,
    /// FASTSIM grid, elements per axis.
    pub fastsim_grid: u32,
}

impl BallSetup {
    /// Whether a ball-ball contact carries load.
    pub fn has_ball_ball_load(&self) -> bool {
        self.ball_ball_plus_n > 0.0 || self.ball_ball_minus_n > 0.0
    }

    /// Whether a rolling resistance acts at either raceway contact (lubricated contacts).
    pub fn has_rolling_resistance(&self) -> bool {
        [self.screw.friction, self.nut.friction].iter().any(|f| f.rolling_resistance_n() > 0.0)
    }

    /// Nominal normal load Q = P / (sin beta cos alpha), N.
    pub fn nominal_load_n(&self) -> f64 {
        self.axial_load_n / self.axial_per_nominal()
    }

    /// `sin(beta) cos(alpha)`: the ball's axial load over its nominal normal load.
    pub fn axial_per_nominal(&self) -> f64 {
        libm::sin(self.contact_angle_rad) * libm::cos(self.helix_angle_rad)
    }
}
