//! Where the quasi-static model holds: the ball's inertia forces it leaves out, against the
//! contact loads it balances.
//!
//! Every ball is balanced without inertia (Xu et al. 2015, Section 2: the ball's forces and
//! moments sum to zero), as in the quasi-static analyses of ball bearings below their speed
//! limits. At speed the orbiting ball is pressed outward by the centrifugal force
//! `F_c = m_b r_m Omega_c^2` (Harris and Kotzalas, Rolling Bearing Analysis, 5th ed., Vol. 2,
//! Ch. 2: `F_c = 1/2 m D_m omega_m^2`) with the ball's mass `m_b = rho pi D_w^3 / 6`, the pitch
//! radius `r_m` and the orbit rate `Omega_c = omega (1 - D_w cos(beta) / d_m) / 2` of the rolling
//! ball, and its spin about an axis inclined to the orbit's asks for the gyroscopic moment
//! `M_g = J omega_R Omega_c sin(beta)`, `J = m_b D_w^2 / 10` (same chapter; the rolling axis is
//! square to the contact line, so inclined to the screw's axis by the contact angle beta). Where they are a small share of
//! what the contacts carry (`F_c` against the normal load, `M_g` against the moment of the
//! friction `mu Q D_w`), the quasi-static balance stands; where not, the two contacts' loads and
//! angles part and the ball's spin changes: the model's torque is then an extrapolation, which
//! the shells warn about ([`INERTIA_WARNING_SHARE`]).

use crate::input::ScrewSpec;
use crate::input::operating::OperatingPoint;
use crate::screw::load;

/// Density of the balls, kg/m^3: through-hardened bearing steel 100Cr6 (SAE 52100), 7.81e3 kg/m^3
/// (ISO 683-17 material data; Harris and Kotzalas use 7.8e3). The spec has no density: the balls
/// of ball screws are of this steel.
pub const BALL_DENSITY_KG_M3: f64 = 7.81e3;

/// Share of the contact load (or of the friction moment) above which an inertia effect the
/// model leaves out is no longer small: a quarter. Both shares grow as the square of the speed;
/// DKFZD4012 at 500 N of preload reaches it at about 4,650 rpm (the gyroscopic share; 10 % at
/// 3000 rpm), a d_m n of about 186,000 mm rpm, beyond the 50,000 to 150,000 mm rpm that
/// manufacturers' catalogs allow ball screws: the warning marks points far outside the range
/// the quasi-static model is made for, not the edge of it.
pub const INERTIA_WARNING_SHARE: f64 = 0.25;

/// The inertia the model leaves out at an operating point, for its most loaded ball.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inertia {
    /// The ball's centrifugal force, N.
    pub centrifugal_force_n: f64,
    /// Its gyroscopic moment (spin at the rolling ball's rate), N m.
    pub gyroscopic_moment_nm: f64,
    /// The most loaded ball's nominal normal load, N (0 when no ball is loaded).
    pub normal_load_n: f64,
    /// `centrifugal_force_n / normal_load_n` (infinite for an unloaded screw turning).
    pub centrifugal_share: f64,
    /// `gyroscopic_moment_nm` over the friction moment `mu Q D_w` of that ball (the spec's
    /// friction coefficient).
    pub gyroscopic_share: f64,
}

impl Inertia {
    /// Whether either share is above [`INERTIA_WARNING_SHARE`].
    pub fn beyond_quasi_static(&self) -> bool {
        self.centrifugal_share > INERTIA_WARNING_SHARE || self.gyroscopic_share > INERTIA_WARNING_SHARE
    }
}

/// The inertia of the most loaded ball of `spec` at `op` (see the module).
pub fn inertia(spec: &ScrewSpec, helix_angle_rad: f64, op: &OperatingPoint) -> Inertia {
    let g = &spec.geometry;
    let d = g.ball_diameter_m;
    let mass = BALL_DENSITY_KG_M3 * core::f64::consts::PI * d * d * d / 6.0;
    let beta = g.contact_angle_rad;
    let orbit = 0.5 * (1.0 - d * libm::cos(beta) / g.pitch_diameter_m) * libm::fabs(op.speed_rad_s);
    let rm = 0.5 * g.pitch_diameter_m;
    let centrifugal = mass * rm * orbit * orbit;
    // The rolling ball's spin: its surface rolls on the screw at the orbit's relative speed.
    let spin = orbit * rm / (0.5 * d * libm::cos(helix_angle_rad));
    let gyroscopic = mass * d * d / 10.0 * spin * orbit * libm::sin(beta);
    let groups = load::groups(g, op.preload_n, op.axial_load_n);
    let shares = load::circle_shares(groups.circles, spec.model.load_distribution);
    let p_max = load::heaviest_ball_load_n(
        &groups.loads,
        groups.count,
        &shares,
        groups.circles as usize,
        f64::from(g.balls_per_circle),
    );
    let q = p_max / (libm::sin(beta) * libm::cos(helix_angle_rad));
    let share = |x: f64, of: f64| {
        if x == 0.0 {
            0.0
        } else if of > 0.0 {
            x / of
        } else {
            f64::INFINITY
        }
    };
    Inertia {
        centrifugal_force_n: centrifugal,
        gyroscopic_moment_nm: gyroscopic,
        normal_load_n: q,
        centrifugal_share: share(centrifugal, q),
        gyroscopic_share: share(gyroscopic, spec.friction.coefficient * q * d),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::rpm_to_rad_s;

    /// DKFZD4012 (the spec's ball, pitch diameter and contact angle), by hand: m_b = rho pi D^3 / 6,
    /// F_c = m_b r_m Omega_c^2 with Omega_c = omega (1 - D cos(beta) / d_m) / 2.
    #[test]
    fn centrifugal_force_by_hand() {
        let spec = ScrewSpec::dkfzd4012();
        let g = &spec.geometry;
        let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(-3000.0), preload_n: 2000.0, axial_load_n: 0.0 };
        let alpha = libm::atan(g.lead_m / (core::f64::consts::PI * g.pitch_diameter_m));
        let i = inertia(&spec, alpha, &op);
        let d = g.ball_diameter_m;
        let m = 7810.0 * core::f64::consts::PI * d.powi(3) / 6.0;
        let w = 314.159_265_358_979_3 * 0.5 * (1.0 - d * g.contact_angle_rad.cos() / g.pitch_diameter_m);
        let fc = m * 0.5 * g.pitch_diameter_m * w * w;
        assert!((i.centrifugal_force_n - fc).abs() < 1e-9 * fc, "{} vs {fc}", i.centrifugal_force_n);
        // Grows as the square of the speed; none at standstill.
        let half = inertia(&spec, alpha, &OperatingPoint { speed_rad_s: op.speed_rad_s / 2.0, ..op });
        assert!((4.0 * half.centrifugal_force_n - i.centrifugal_force_n).abs() < 1e-12);
        let still = inertia(&spec, alpha, &OperatingPoint { speed_rad_s: 0.0, ..op });
        assert_eq!((still.centrifugal_share, still.gyroscopic_share), (0.0, 0.0));
        assert!(!still.beyond_quasi_static());
        // An unloaded screw turning: no load to compare with.
        let free = inertia(&spec, alpha, &OperatingPoint { preload_n: 0.0, ..op });
        assert!(free.centrifugal_share.is_infinite() && free.beyond_quasi_static());
    }

    /// Where the warning starts on DKFZD4012: printed for the record of the README's numbers.
    #[test]
    fn shares_on_dkfzd4012() {
        let spec = ScrewSpec::dkfzd4012();
        let g = &spec.geometry;
        let alpha = libm::atan(g.lead_m / (core::f64::consts::PI * g.pitch_diameter_m));
        for (rpm, preload) in [(3000.0, 500.0), (3000.0, 2000.0), (1000.0, 500.0), (6000.0, 500.0)] {
            let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: preload, axial_load_n: 0.0 };
            let i = inertia(&spec, alpha, &op);
            std::println!(
                "{rpm} rpm {preload} N: F_c {:.3} N, Q {:.1} N, share {:.4}; M_g {:.3e} N m, share {:.4}",
                i.centrifugal_force_n,
                i.normal_load_n,
                i.centrifugal_share,
                i.gyroscopic_moment_nm,
                i.gyroscopic_share
            );
        }
        // The catalog's range (to 3000 rpm, from 500 N) is quasi-static; 4650 rpm at 500 N is
        // where the gyroscopic share reaches a quarter.
        let at = |rpm: f64, preload_n: f64| {
            inertia(&spec, alpha, &OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n, axial_load_n: 0.0 })
        };
        assert!(!at(3000.0, 500.0).beyond_quasi_static() && !at(-3000.0, 2000.0).beyond_quasi_static());
        assert!(at(4600.0, 500.0).gyroscopic_share < 0.25 && at(4700.0, 500.0).gyroscopic_share > 0.25);
        assert!(at(6000.0, 500.0).beyond_quasi_static());
    }
}
