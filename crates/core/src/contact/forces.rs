//! Creep forces of a contact: Kalker's linear theory (Eq. 23) saturated into Coulomb friction by
//! the Shen-Hedrick-Elkins blend (Eq. 24, docs/model-notes.md item 6).
//!
//! Linear theory (Kalker's sign convention, force on the ball, c = sqrt(a b)):
//! F_e = -G c^2 C11 xi, F_f = -G c^2 (C22 eta + C23 c phi), M = G c^3 (C23 eta - C33 c phi).
//! The paper's Eq. (23a) subtracts the Heathcote term from xi; here xi already carries it.
//!
//! Saturation keeps the direction of the linear force and blends its magnitude F_r by Eq. (24),
//! with bound f Q; it is continuous at F_r = 3 f Q. The spin moment (which the paper omits) is
//! saturated together with the forces ([`SpinMoment::Combined`], the default): the vector
//! (F_e, F_f, M / l) is blended as one, with l = (3/8) b_major E(m) the arm of the full-slip spin
//! moment of a Hertz ellipse (pressure-weighted mean distance from the centre); sharing one
//! friction bound keeps every contact's dissipation non-negative and |F| <= f Q, |M| <= f Q l.
//! Or ([`SpinMoment::Separate`]) Eq. (24) acts exactly as printed on (F_e, F_f), and the spin
//! moment is blended on its own with bound f Q l. Without any spin moment the ball's balance
//! is degenerate: every force passes through the contact line, so nothing fixes the ball's spin
//! about it.

use crate::contact::creep::Creepage;
use crate::contact::kalker::CreepCoefficients;
use crate::contact::saturation::she_ratio;
use crate::input::SpinMoment;

/// What a contact's tangential forces depend on besides the creepages.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactStiffness {
    /// Shear modulus G, Pa.
    pub shear_modulus_pa: f64,
    /// c = sqrt(a b), m.
    pub c_m: f64,
    /// Kalker's coefficients for this contact's a/b.
    pub coefficients: CreepCoefficients,
    /// Friction bound f Q, N.
    pub friction_bound_n: f64,
    /// Full-slip spin-moment arm l, m.
    pub spin_arm_m: f64,
}

impl ContactStiffness {
    /// The stiffness of a Hertz ellipse with semi-axes `semi_axis_rolling_m` (a, along rolling)
    /// and `semi_axis_lateral_m` (b), m: `c = sqrt(a b)` ([`creep_length_m`]) and the spin arm
    /// `(3/8) a_major E(m)` ([`spin_arm_m`]) with the ellipse's complete elliptic integral
    /// `complete_e` (`E(m)`, `m = 1 - (minor/major)^2`), besides the shear modulus
    /// `shear_modulus_pa` (Pa), the creep `coefficients` of the contact's a/b and the friction
    /// bound `friction_bound_n` (f Q, N).
    pub fn for_ellipse(
        shear_modulus_pa: f64,
        semi_axis_rolling_m: f64,
        semi_axis_lateral_m: f64,
        complete_e: f64,
        coefficients: CreepCoefficients,
        friction_bound_n: f64,
    ) -> Self {
        ContactStiffness {
            shear_modulus_pa,
            c_m: creep_length_m(semi_axis_rolling_m, semi_axis_lateral_m),
            coefficients,
            friction_bound_n,
            spin_arm_m: spin_arm_m(semi_axis_rolling_m.max(semi_axis_lateral_m), complete_e),
        }
    }
}

/// Kalker's length `c = sqrt(a b)` of an ellipse with semi-axes `semi_axis_rolling_m` and
/// `semi_axis_lateral_m`, m.
pub fn creep_length_m(semi_axis_rolling_m: f64, semi_axis_lateral_m: f64) -> f64 {
    libm::sqrt(semi_axis_rolling_m * semi_axis_lateral_m)
}

/// Arm of the full-slip spin moment of a Hertz ellipse, `l = (3/8) a_major E(m)`, m: the
/// pressure-weighted mean distance from the centre, with the larger semi-axis `semi_major_m`
/// (m) and the ellipse's `E(m)` `complete_e` (`m = 1 - (minor/major)^2`).
pub fn spin_arm_m(semi_major_m: f64, complete_e: f64) -> f64 {
    0.375 * semi_major_m * complete_e
}

/// Tangential forces and spin moment on the ball at one contact.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactForce {
    /// Linear-theory force along e, N.
    pub linear_e_n: f64,
    /// Linear-theory force along f, N.
    pub linear_f_n: f64,
    /// Linear-theory spin moment about g, N m.
    pub linear_moment_nm: f64,
    /// Saturated force along e, N.
    pub e_n: f64,
    /// Saturated force along f, N.
    pub f_n: f64,
    /// Saturated spin moment about g, N m.
    pub moment_nm: f64,
    /// Saturated over linear magnitude (1 in the linear range).
    pub saturation: f64,
}

/// Kalker's linear creep forces (Eq. 23) with the spin moment.
pub fn linear(cr: &Creepage, k: &ContactStiffness) -> (f64, f64, f64) {
    let c = k.c_m;
    let gc2 = k.shear_modulus_pa * c * c;
    let cc = &k.coefficients;
    let fe = -gc2 * cc.c11 * cr.xi;
    let ff = -gc2 * (cc.c22 * cr.eta + cc.c23 * c * cr.phi);
    let m = gc2 * c * (cc.c23 * cr.eta - cc.c33 * c * cr.phi);
    (fe, ff, m)
}

/// Saturated creep forces (Eqs. 23-24) of one contact.
pub fn creep_force(cr: &Creepage, k: &ContactStiffness, spin: SpinMoment) -> ContactForce {
    let (fe, ff, m) = linear(cr, k);
    let bound = k.friction_bound_n;
    let ratio_of = |mag: f64, bound: f64| if bound > 0.0 { she_ratio(mag / bound) } else { 0.0 };
    let force_mag = libm::sqrt(fe * fe + ff * ff);
    let (ratio, moment_ratio) = match spin {
        SpinMoment::Combined => {
            let ml = if k.spin_arm_m > 0.0 { m / k.spin_arm_m } else { 0.0 };
            let r = ratio_of(libm::sqrt(force_mag * force_mag + ml * ml), bound);
            (r, r)
        }
        SpinMoment::Separate => (ratio_of(force_mag, bound), ratio_of(libm::fabs(m), bound * k.spin_arm_m)),
    };
    ContactForce {
        linear_e_n: fe,
        linear_f_n: ff,
        linear_moment_nm: m,
        e_n: fe * ratio,
        f_n: ff * ratio,
        moment_nm: m * moment_ratio,
        saturation: ratio,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    fn stiff(bound: f64) -> ContactStiffness {
        ContactStiffness {
            shear_modulus_pa: 80e9,
            c_m: 1e-4,
            coefficients: CreepCoefficients { c11: 3.3, c22: 2.5, c23: 0.47, c33: 8.3 },
            friction_bound_n: bound,
            spin_arm_m: 1.5e-4,
        }
    }
    fn cr(xi: f64, eta: f64, phi: f64) -> Creepage {
        Creepage { xi, eta, phi, heathcote: 0.0, rolling_speed_m_s: 1.0, e: Vector3::x(), f: Vector3::y() }
    }

    #[test]
    fn small_creepage_is_linear_with_kalker_slope() {
        let k = stiff(1.0);
        let f = creep_force(&cr(1e-9, 0.0, 0.0), &k, SpinMoment::Separate);
        let slope = f.e_n / 1e-9;
        let kalker = -80e9 * 1e-8 * 3.3;
        assert!((slope / kalker - 1.0).abs() < 1e-5, "{slope} vs {kalker}");
    }

    #[test]
    fn large_creepage_saturates_at_f_q_and_is_continuous_at_three_f_q() {
        let k = stiff(1.0);
        let f = creep_force(&cr(1.0, 0.5, 0.0), &k, SpinMoment::Separate);
        assert!(((f.e_n * f.e_n + f.f_n * f.f_n).sqrt() - 1.0).abs() < 1e-12);
        // Direction kept.
        assert!((f.e_n / f.f_n - f.linear_e_n / f.linear_f_n).abs() < 1e-12);
        // At F_r = 3 f Q from both sides.
        let xi3 = 3.0 / (80e9 * 1e-8 * 3.3);
        let lo = creep_force(&cr(xi3 * (1.0 - 1e-9), 0.0, 0.0), &k, SpinMoment::Separate);
        let hi = creep_force(&cr(xi3 * (1.0 + 1e-9), 0.0, 0.0), &k, SpinMoment::Separate);
        assert!((lo.e_n - hi.e_n).abs() < 1e-8 && (lo.e_n.abs() - 1.0).abs() < 1e-8);
    }

    #[test]
    fn combined_spin_moment_is_bounded_and_dissipates() {
        let k = stiff(2.0);
        for &(xi, eta, phi) in &[(1e-3, -2e-3, 30.0), (-1e-2, 1e-3, -500.0), (0.0, 0.0, 1e4), (2e-4, 1e-4, -3.0)] {
            let c = cr(xi, eta, phi);
            let f = creep_force(&c, &k, SpinMoment::Combined);
            let fr = (f.e_n * f.e_n + f.f_n * f.f_n).sqrt();
            assert!(fr <= 2.0 + 1e-12 && f.moment_nm.abs() <= 2.0 * 1.5e-4 + 1e-15);
            // Power taken out of the motion per unit rolling speed.
            let diss = -(f.e_n * xi + f.f_n * eta + f.moment_nm * phi);
            assert!(diss >= 0.0, "dissipation {diss} for {xi} {eta} {phi}");
        }
    }

    #[test]
    fn stiffness_of_an_ellipse() {
        let coefficients = CreepCoefficients { c11: 3.3, c22: 2.5, c23: 0.47, c33: 8.3 };
        // A circle of radius a: E(0) = pi/2, so the arm is (3/8)(pi/2) a and the full-slip spin
        // moment f Q l is Johnson's 3 pi f Q a / 16 (Contact Mechanics, 1985, sec. 8.4).
        let a = 2e-4;
        let e = crate::contact::elliptic::ellipse_complete_e(a, a);
        let k = ContactStiffness::for_ellipse(80e9, a, a, e, coefficients, 3.0);
        assert!((k.spin_arm_m / (3.0 * core::f64::consts::PI * a / 16.0) - 1.0).abs() < 1e-15);
        assert_eq!((k.c_m, k.shear_modulus_pa, k.friction_bound_n), (a, 80e9, 3.0));
        assert_eq!(k.coefficients, coefficients);
        // An ellipse: c = sqrt(a b) and the arm on the major semi-axis, whichever is rolling.
        let e = crate::contact::elliptic::ellipse_complete_e(1e-4, 4e-4);
        assert!(e > 1.0 && e < core::f64::consts::FRAC_PI_2);
        for (ra, rb) in [(1e-4, 4e-4), (4e-4, 1e-4)] {
            let k = ContactStiffness::for_ellipse(80e9, ra, rb, e, coefficients, 3.0);
            assert!((k.c_m - 2e-4).abs() < 1e-19);
            assert_eq!(k.spin_arm_m, 0.375 * 4e-4 * e);
        }
    }
}
