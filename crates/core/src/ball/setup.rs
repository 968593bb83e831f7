//! What one ball's balance depends on and solves for: the unknowns (the ball's angular velocity
//! in the contact frame, its orbit speed, the normal-load departures and the tilt), the solver's
//! tolerances, and the setup of the ball and its two raceway contacts that does not change while
//! the ball is solved.

use crate::contact::hertz::HertzShape;
use crate::contact::kalker::CreepCoefficients;
use crate::input::{ContactTheory, SpinMoment};

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
/// lateral friction) would still change (MODEL-NOTES item 13).
pub const MIN_SOLVE_FACTOR: f64 = 1e-3;

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
    /// Friction coefficient f of every contact.
    pub mu: f64,
    /// Factor on the creep stiffness G (1 for the model; lowered by the continuation).
    pub stiffness_scale: f64,
    /// The ball's share of its nut's axial load, N (> 0).
    pub axial_load_n: f64,
    /// Normal load between adjacent balls Q_m, N.
    pub ball_ball_load_n: f64,
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
    /// Nominal normal load Q = P / (sin beta cos alpha), N.
    pub fn nominal_load_n(&self) -> f64 {
        self.axial_load_n / (libm::sin(self.contact_angle_rad) * libm::cos(self.helix_angle_rad))
    }
}
