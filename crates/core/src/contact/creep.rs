//! Creepages at a contact: longitudinal xi, lateral eta, spin phi, with Heathcote slip
//! (Eqs. 3-22 of the paper, as corrected in docs/model-notes.md items 3, 5, 13 and 16).
//!
//! The paper writes a scalar formula per contact and component, and its component equations
//! (5a), (13), (14a) disagree on signs and on sines and cosines. Here every creepage comes from
//! one vector computation, the same for the nut, screw and ball-ball contacts:
//! - the surface velocities of the two bodies at the contact point, relative to the moving
//!   contact point: w1 (ball), w2 (raceway);
//! - slip s = w1 - w2, rolling velocity V = |w1 + w2| / 2 (Eq. 6), rolling direction e
//!   the direction in which the contact moves over the bodies, e = -sign((w1 + w2).t) t;
//! - creepages (xi, eta) = (s.e, s.f) / V and spin phi = (Omega1 - Omega2).g / V.
//!
//! Heathcote slip (Eqs. 10, 16, 22): the contact surface of a ball in a conforming groove is
//! curved across the groove (radius R_d), so the rigid slip varies over the ellipse. Its
//! pressure-weighted mean (mean f^2 = b_lat^2 / 5) equals the slip at the depth
//! z = b_lat^2 / (10 R_d) below the contact centre towards the ball centre: the velocities are
//! evaluated at that effective point, and the tangential force acts there too (so the moment
//! balance and the dissipation see the same slip). The Heathcote part is reported separately.
//!
//! Every velocity is proportional to the screw speed omega, so the creepages are computed from
//! the velocities per unit screw speed: they are finite at standstill, and reversing the
//! rotation reverses the rolling direction (xi and eta keep their values in the rolling frame,
//! the spin creepage changes sign).
//!
//! Standstill (item 13): a creepage, a ratio of velocities, does not vanish as the speed does,
//! so without more the torque would jump at zero speed. The creep forces are therefore scaled by
//! the [`standstill_factor`], which rises smoothly (C1) from 0 at standstill to exactly 1 at the
//! standstill speed omega0 (a spec parameter) and stays 1 above it: the model is untouched above
//! omega0, and the torque is continuous and passes through zero with the direction of rotation.
//! Regularising the creepage instead (slip / sqrt(V^2 + V0^2)) would not do: the raceway
//! contacts run far into saturation (linear force about 100 times f Q for DKFZD4012), so the
//! torque would change over omega0 / 100 only.

use nalgebra::Vector3;

/// Relative motion at one contact, per unit screw speed (velocities in m/s per rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RelativeMotion {
    /// Slip velocity of the ball's surface relative to the other body's surface.
    pub slip: Vector3<f64>,
    /// Mean of the two surface velocities relative to the moving contact point.
    pub mean: Vector3<f64>,
    /// Relative angular velocity of the ball about the contact normal, (Omega1 - Omega2).g.
    pub spin: f64,
}

/// Creepages of a contact at a given screw speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Creepage {
    /// Longitudinal creepage xi (along e), including the Heathcote mean.
    pub xi: f64,
    /// Lateral creepage eta (along f).
    pub eta: f64,
    /// Spin creepage phi, 1/m.
    pub phi: f64,
    /// The Heathcote part of xi (already included in `xi`).
    pub heathcote: f64,
    /// Rolling speed V at the actual screw speed, m/s.
    pub rolling_speed_m_s: f64,
    /// Rolling direction e (unit).
    pub e: Vector3<f64>,
    /// Lateral direction f = g x e (unit).
    pub f: Vector3<f64>,
}

/// Standstill factor s(omega) = x (2 - x) with x = |omega| / omega0 below omega0, 1 above:
/// the factor on every creep force (docs/model-notes.md item 13). C1 at omega0, slope 2 / omega0 at 0.
pub fn standstill_factor(speed_rad_s: f64, standstill_speed_rad_s: f64) -> f64 {
    let x = libm::fabs(speed_rad_s) / standstill_speed_rad_s;
    if !(x < 1.0) { 1.0 } else { x * (2.0 - x) }
}

/// Sign of the screw speed with +1 at standstill.
pub fn direction(speed_rad_s: f64) -> f64 {
    if speed_rad_s < 0.0 { -1.0 } else { 1.0 }
}

/// Creepages from the relative motion at the effective point (`at_depth`) and at the contact
/// centre (`at_centre`, for the Heathcote part), the rolling axis `t` (unit, in the contact
/// plane) and normal `g`, at screw speed `speed_rad_s`.
pub fn creepages(
    at_depth: &RelativeMotion,
    at_centre: &RelativeMotion,
    t: &Vector3<f64>,
    g: &Vector3<f64>,
    speed_rad_s: f64,
) -> Creepage {
    let dir = direction(speed_rad_s);
    let sigma = if at_depth.mean.dot(t) >= 0.0 { 1.0 } else { -1.0 };
    // Rolling direction at positive speed, flipped with the direction of rotation.
    let e = t * (-sigma * dir);
    let f = g.cross(&e);
    let v_unit = at_depth.mean.norm();
    if !v_unit.is_finite() {
        // The rolling speed overflows (rates beyond about 1e154): the creepages are unknown,
        // not zero (see `ball::balance`).
        let nan = f64::NAN;
        return Creepage { xi: nan, eta: nan, phi: nan, heathcote: nan, rolling_speed_m_s: v_unit, e, f };
    }
    if v_unit <= 0.0 {
        return Creepage { xi: 0.0, eta: 0.0, phi: 0.0, heathcote: 0.0, rolling_speed_m_s: 0.0, e, f };
    }
    // Slip at the actual speed is speed * slip, rolling speed |speed| V_unit.
    let k = dir / v_unit;
    let xi = k * at_depth.slip.dot(&e);
    let xi_centre = k * at_centre.slip.dot(&e);
    Creepage {
        xi,
        eta: k * at_depth.slip.dot(&f),
        phi: k * at_depth.spin,
        heathcote: xi - xi_centre,
        rolling_speed_m_s: libm::fabs(speed_rad_s) * v_unit,
        e,
        f,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn motion(slip: [f64; 3], mean: [f64; 3], spin: f64) -> RelativeMotion {
        RelativeMotion { slip: Vector3::from(slip), mean: Vector3::from(mean), spin }
    }

    #[test]
    fn pure_rolling_without_spin_has_zero_creepage() {
        let m = motion([0.0; 3], [-0.1, 0.0, 0.0], 0.0);
        let c = creepages(&m, &m, &Vector3::x(), &Vector3::z(), 10.0);
        assert_eq!((c.xi, c.eta, c.phi), (0.0, 0.0, 0.0));
        assert_eq!(c.e, Vector3::x(), "contact moves along +x over the bodies");
    }

    #[test]
    fn creepage_is_slip_over_rolling_speed_and_flips_with_rotation() {
        let m = motion([1e-4, 2e-4, 0.0], [-0.1, 0.0, 0.0], 0.5);
        let c = creepages(&m, &m, &Vector3::x(), &Vector3::z(), 10.0);
        assert!((c.xi - 1e-3).abs() < 1e-15 && (c.eta - 2e-3).abs() < 1e-15);
        assert!((c.phi - 5.0).abs() < 1e-12);
        assert!((c.rolling_speed_m_s - 1.0).abs() < 1e-15);
        // Reversed rotation: the slip vector reverses and the rolling direction too, so xi and
        // eta keep their values in the rolling frame while the spin creepage changes sign.
        let r = creepages(&m, &m, &Vector3::x(), &Vector3::z(), -10.0);
        assert!((r.xi - c.xi).abs() < 1e-15 && (r.eta - c.eta).abs() < 1e-15);
        assert!((r.phi + c.phi).abs() < 1e-12);
        assert!((r.e + c.e).norm() < 1e-15);
        // Slip vectors in the global frame reverse with the rotation.
        let s_fwd = c.e * c.xi + c.f * c.eta;
        let s_rev = r.e * r.xi + r.f * r.eta;
        assert!((s_fwd + s_rev).norm() < 1e-15);
    }

    #[test]
    fn standstill_factor_is_c1_and_exactly_one_above_the_scale() {
        assert_eq!(standstill_factor(0.0, 0.01), 0.0);
        assert_eq!(standstill_factor(0.01, 0.01), 1.0);
        assert_eq!(standstill_factor(-5.0, 0.01), 1.0);
        assert!((standstill_factor(0.005, 0.01) - 0.75).abs() < 1e-15);
        // Slope 2 / omega0 at zero, 0 at omega0 from below (C1).
        let h = 1e-9;
        assert!((standstill_factor(h, 0.01) / h - 200.0).abs() < 1e-3);
        let d = (standstill_factor(0.01, 0.01) - standstill_factor(0.01 - h, 0.01)) / h;
        assert!(d.abs() < 1e-4);
        assert_eq!(standstill_factor(-3e-3, 0.01), standstill_factor(3e-3, 0.01));
    }
}
