//! Complete elliptic integrals of the first and second kind, K(m) and E(m), by the
//! arithmetic-geometric mean (AGM).
//!
//! The paper (Xu et al. 2015) states that the contact semi-axes and the elastic approach of
//! Eqs. (5), (13) and (23) "can be calculated based on Hertz contact theory"; the exact Hertz
//! solution of an elliptical point contact needs K and E of the contact ellipse (see
//! [`crate::contact::hertz`]). These are computed here to machine precision (about 1e-15 relative), not
//! by polynomial approximations.
//!
//! Convention: the *parameter* `m = k^2` (k = elliptic modulus), so that
//! `K(m) = int_0^{pi/2} (1 - m sin^2 t)^{-1/2} dt` and
//! `E(m) = int_0^{pi/2} (1 - m sin^2 t)^{1/2} dt`.
//!
//! Besides K and E the AGM pass also yields, without cancellation, the integral
//! `D(m) = (K - E)/m = int_0^{pi/2} sin^2 t (1 - m sin^2 t)^{-1/2} dt`, which the Hertz
//! ellipticity equation needs near the circular contact (m -> 0), where `K - E` would lose all
//! its digits.
//!
//! Algorithm (Abramowitz & Stegun 17.6): `a0 = 1`, `b0 = sqrt(1 - m)`, `c0^2 = m`;
//! `a_{n+1} = (a_n + b_n)/2`, `b_{n+1} = sqrt(a_n b_n)`, `c_{n+1} = c_n^2 / (4 a_{n+1})`;
//! then `K = pi / (2 a_N)` and `K - E = K sum_{n>=0} 2^{n-1} c_n^2`. Computing `c_{n+1}` from
//! `c_n^2` (instead of `(a_n - b_n)/2`) keeps every term accurate.

use core::f64::consts::FRAC_PI_2;

/// Relative tolerance at which the AGM iteration stops (|a - b| <= TOL * a). The mean is then
/// taken as (a + b)/2, whose error is of order TOL^2: far below one ulp.
const TOL: f64 = 1.0e-12;
/// The AGM converges quadratically: 8 steps suffice for m < 1 - 1e-300; this is a safety cap.
const MAX_STEPS: usize = 64;

/// Complete elliptic integral of the first kind, K(m), with parameter `m = k^2`.
///
/// Exact to about 1e-15 relative for `m < 1` (negative `m` is allowed). `K(1) = +inf`; for
/// `m > 1` or a non-finite `m` the result is NaN.
pub fn complete_k(m: f64) -> f64 {
    complete_ke(m).0
}

/// Complete elliptic integral of the second kind, E(m), with parameter `m = k^2`.
///
/// Exact to about 1e-15 relative for `m <= 1` (negative `m` is allowed; `E(1) = 1`). For
/// `m > 1` or a non-finite `m` the result is NaN.
pub fn complete_e(m: f64) -> f64 {
    complete_ke(m).1
}

/// `E(m)` of the ellipse with semi-axes `semi_axis_1_m` and `semi_axis_2_m` (m, either order):
/// `m = 1 - (minor/major)^2`. For finite semi-axes > 0 (not checked).
pub fn ellipse_complete_e(semi_axis_1_m: f64, semi_axis_2_m: f64) -> f64 {
    let (major, minor) = (semi_axis_1_m.max(semi_axis_2_m), semi_axis_1_m.min(semi_axis_2_m));
    complete_e(1.0 - (minor / major) * (minor / major))
}

/// Both complete elliptic integrals `(K(m), E(m))` from one AGM pass.
///
/// Same domain as [`complete_k`] and [`complete_e`]. `E` is formed as `K - m D`; as `m -> 1`
/// it loses about `log10 K` digits (absolute error about `K * 1e-16`, e.g. 5e-15 at
/// `1 - m = 1e-20`).
pub fn complete_ke(m: f64) -> (f64, f64) {
    let (k, e, _) = complete_ked(m);
    (k, e)
}

/// `(K(m), E(m), D(m))` from one AGM pass, with `D(m) = (K - E)/m` computed without
/// cancellation (`D(0) = pi/4`).
///
/// For `m <= 1` and finite; `m = 1` gives `(+inf, 1, +inf)`; otherwise NaN.
pub fn complete_ked(m: f64) -> (f64, f64, f64) {
    if !m.is_finite() || m > 1.0 {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    complete_ked_mc(1.0 - m)
}

/// `(K, E, D)` as in [`complete_ked`], but from the complementary parameter `mc = 1 - m`.
///
/// Use it when the contact ellipse is very slender (`m` close to 1): `mc` then keeps the
/// digits that `1 - mc` would round away. Valid for finite `mc >= 0`; `mc = 0` gives
/// `(+inf, 1, +inf)`; a negative or non-finite `mc` gives NaN.
pub fn complete_ked_mc(mc: f64) -> (f64, f64, f64) {
    if !mc.is_finite() || mc < 0.0 {
        return (f64::NAN, f64::NAN, f64::NAN);
    }
    if mc == 0.0 {
        return (f64::INFINITY, 1.0, f64::INFINITY);
    }
    let m = 1.0 - mc;
    let mut a = 1.0_f64;
    let mut b = libm::sqrt(mc);
    // c_n^2 (signed: negative for m < 0, which the recurrence handles as it stands).
    let mut csq = m;
    // q_n = c_n^2 / m, computed by recurrence so that it stays finite at m = 0.
    let mut q = 1.0_f64;
    // sum_{n>=0} 2^{n-1} q_n; the n = 0 term is 1/2.
    let mut sum_q = 0.5_f64;
    let mut weight = 0.5_f64;
    for _ in 0..MAX_STEPS {
        if libm::fabs(a - b) <= TOL * a {
            break;
        }
        let a_next = 0.5 * (a + b);
        let b_next = libm::sqrt(a * b);
        let c_next = csq / (4.0 * a_next);
        let q_next = q * csq / (16.0 * a_next * a_next);
        weight *= 2.0;
        sum_q += weight * q_next;
        a = a_next;
        b = b_next;
        csq = c_next * c_next;
        q = q_next;
    }
    // The omitted terms are of order (TOL a)^2: negligible.
    let k = FRAC_PI_2 / (0.5 * (a + b));
    let d = k * sum_q;
    let e = k - m * d;
    (k, e, d)
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::{FRAC_PI_2, FRAC_PI_4};

    fn rel(a: f64, b: f64) -> f64 {
        libm::fabs(a - b) / libm::fabs(b)
    }

    #[test]
    fn circle_limit_is_half_pi() {
        let (k, e, d) = complete_ked(0.0);
        assert_eq!(k, FRAC_PI_2);
        assert_eq!(e, FRAC_PI_2);
        assert!(rel(d, FRAC_PI_4) < 1e-15);
        assert_eq!(complete_k(0.0), FRAC_PI_2);
        assert_eq!(complete_e(0.0), FRAC_PI_2);
    }

    #[test]
    fn known_values_at_one_half() {
        // Abramowitz & Stegun Table 17.1 / DLMF 19.
        assert!(rel(complete_k(0.5), 1.854_074_677_301_371_9) < 2e-15);
        assert!(rel(complete_e(0.5), 1.350_643_881_047_675_5) < 2e-15);
    }

    #[test]
    fn known_values_near_one() {
        // K(0.99), E(0.99): standard tables; independently checked by Simpson quadrature.
        let (k, e) = complete_ke(0.99);
        assert!(rel(k, 3.695_637_362_989_875) < 2e-15, "K(0.99) = {k}");
        assert!(rel(e, 1.015_993_545_025_224) < 2e-15, "E(0.99) = {e}");
        // K(0.9), E(0.9)
        let (k, e) = complete_ke(0.9);
        assert!(rel(k, 2.578_092_113_348_173) < 2e-15, "K(0.9) = {k}");
        assert!(rel(e, 1.104_774_732_704_073) < 2e-15, "E(0.9) = {e}");
    }

    #[test]
    fn d_matches_k_minus_e_over_m_and_small_m_series() {
        for &m in &[0.3, 0.5, 0.9, 0.99] {
            let (k, e, d) = complete_ked(m);
            assert!(rel(d, (k - e) / m) < 1e-13);
        }
        // D(m) = pi/4 (1 + 3m/8 + 15m^2/64 + ...) for small m: no cancellation.
        let m = 1e-9;
        let (_, _, d) = complete_ked(m);
        assert!(rel(d, FRAC_PI_4 * (1.0 + 3.0 * m / 8.0)) < 1e-15);
    }

    #[test]
    fn legendre_relation_holds() {
        // E K' + E' K - K K' = pi/2 with K' = K(1-m), E' = E(1-m).
        for &m in &[0.01, 0.2, 0.5, 0.7, 0.95] {
            let (k, e) = complete_ke(m);
            let (kp, ep) = complete_ke(1.0 - m);
            assert!(libm::fabs(e * kp + ep * k - k * kp - FRAC_PI_2) < 1e-14, "m = {m}");
        }
    }

    #[test]
    fn complementary_form_agrees_and_keeps_slender_ellipses() {
        let (k1, e1, d1) = complete_ked(0.75);
        let (k2, e2, d2) = complete_ked_mc(0.25);
        assert_eq!((k1, e1, d1), (k2, e2, d2));
        // mc = 1e-20 cannot be written as m = 1 - 1e-20, but the mc form handles it:
        // K ~ ln(4/sqrt(mc)) for mc -> 0.
        // E = K - m D loses about log10(K) digits there (K = 24.4): still 1e-14.
        let (k, e, _) = complete_ked_mc(1e-20);
        assert!(rel(k, libm::log(4.0 / 1e-10)) < 1e-9);
        assert!(libm::fabs(e - 1.0) < 1e-14);
    }

    #[test]
    fn edges_do_not_panic() {
        assert_eq!(complete_ke(1.0), (f64::INFINITY, 1.0));
        assert!(complete_k(1.5).is_nan());
        assert!(complete_e(f64::NAN).is_nan());
        assert!(complete_ked_mc(-1.0).0.is_nan());
        // Negative parameter: K(-1) = 1.3110287771460599, E(-1) = 1.9100988945138560.
        let (k, e) = complete_ke(-1.0);
        assert!(rel(k, 1.311_028_777_146_06) < 1e-14);
        assert!(rel(e, 1.910_098_894_513_856) < 1e-14);
    }
}
