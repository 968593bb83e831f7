//! Shen-Hedrick-Elkins saturation of the linear creep force, Eq. (24) of Xu et al. (2015).
//!
//! With `u = F_lin / (mu Q) >= 0` the ratio of the linear (Kalker, Eq. 23) force magnitude to
//! the Coulomb bound, Eq. (24) gives the saturated magnitude
//! `F / (mu Q) = u - u^2/3 + u^3/27 = 1 - (1 - u/3)^3` for `u <= 3`, and `1` for `u > 3`.
//!
//! Properties: slope 1 at `u = 0` (Kalker's linear theory), monotone, never above 1, and C1 at
//! `u = 3` (value 1 and slope `(1 - u/3)^2 = 0` on both sides); the second derivative jumps
//! there. The saturated force keeps the direction of the linear force vector (`docs/model-notes.md`
//! item 6): scale the vector by [`she_ratio`].
//!
//! The functions are defined for `u >= 0`; a negative `u` is taken as a signed magnitude
//! (`she(-u) = -she(u)`, `she_ratio` even) and NaN propagates. Nothing panics.

use crate::real::Lanes;
use crate::real::lanes::splat_of;

/// Point where Eq. (24) reaches full sliding: `F_lin = 3 mu Q`.
pub const FULL_SLIP_U: f64 = 3.0;

/// Saturated force over the Coulomb bound, `F / (mu Q)`, for `u = F_lin / (mu Q)` (Eq. 24).
///
/// `u - u^2/3 + u^3/27` for `|u| <= 3`, `±1` beyond.
pub fn she(u: f64) -> f64 {
    let x = libm::fabs(u);
    let s = if x <= FULL_SLIP_U {
        x * (1.0 + x * (-1.0 / 3.0 + x / 27.0))
    } else if x > FULL_SLIP_U {
        1.0
    } else {
        return f64::NAN;
    };
    libm::copysign(s, u)
}

/// Saturated over linear force, `F / F_lin = she(u) / u`, to scale a linear force vector
/// (direction preserved).
///
/// `1 - u/3 + u^2/27` for `|u| <= 3` (exactly 1 at `u = 0`), `1/|u|` beyond; in `(0, 1]`.
pub fn she_ratio(u: f64) -> f64 {
    she_ratio_of(u)
}

/// [`she_ratio`] in any float type of the evaluation (f32 for firmware), and lane by lane in
/// [`Lanes`] (both sides computed, each lane taking its own).
#[inline(always)]
pub fn she_ratio_of<V: Lanes>(u: V) -> V {
    let x = u.abs_lanes();
    let full = splat_of::<V>(FULL_SLIP_U);
    let one = splat_of::<V>(1.0);
    V::choose(
        x.le_mask(full),
        || one + x * (splat_of::<V>(-1.0 / 3.0) + x / splat_of::<V>(27.0)),
        || V::choose(x.gt_mask(full), || one / x, || u),
    )
}

/// Derivative `d she / d u = (1 - |u|/3)^2` for `|u| <= 3`, 0 beyond (the tangent stiffness
/// factor of a creep force along its own direction).
pub fn she_derivative(u: f64) -> f64 {
    let x = libm::fabs(u);
    if x <= FULL_SLIP_U {
        let t = 1.0 - x / 3.0;
        t * t
    } else if x > FULL_SLIP_U {
        0.0
    } else {
        f64::NAN
    }
}

/// Derivative of [`she_ratio`] with respect to `u`: `-1/3 + 2u/27` for `0 <= u <= 3`,
/// `-1/u^2` beyond (continuous at `u = 3`, value `-1/9`). At `u = 0` it is the slope for
/// `u -> 0+`, `-1/3`; for a negative `u` the sign flips (`she_ratio` is even).
pub fn she_ratio_derivative(u: f64) -> f64 {
    let x = libm::fabs(u);
    let d = if x <= FULL_SLIP_U {
        -1.0 / 3.0 + 2.0 * x / 27.0
    } else if x > FULL_SLIP_U {
        -1.0 / (x * x)
    } else {
        return f64::NAN;
    };
    if u < 0.0 { -d } else { d }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_values_of_saturation_csv() {
        // docs/reference/saturation_and_fastsim.csv, kind she_saturation (5 decimals).
        let rows = [(0.5, 0.42130), (1.0, 0.70370), (2.0, 0.96296), (3.0, 1.00000), (4.0, 1.00000)];
        for (u, expected) in rows {
            assert!(libm::fabs(she(u) - expected) < 5e-6, "she({u}) = {}", she(u));
            assert!(libm::fabs(she_ratio(u) * u - expected) < 5e-6);
        }
    }

    #[test]
    fn linear_slope_one_at_zero() {
        assert_eq!(she(0.0), 0.0);
        assert_eq!(she_ratio(0.0), 1.0);
        assert_eq!(she_derivative(0.0), 1.0);
        let h = 1e-8;
        assert!(libm::fabs(she(h) / h - 1.0) < 1e-8);
    }

    #[test]
    fn continuous_and_c1_at_full_slip() {
        let below = FULL_SLIP_U - 1e-9;
        let above = FULL_SLIP_U + 1e-9;
        assert_eq!(she(FULL_SLIP_U), 1.0);
        assert!(libm::fabs(she(below) - she(above)) < 1e-12);
        assert!(libm::fabs(she_derivative(below) - she_derivative(above)) < 1e-12);
        assert!(libm::fabs(she_ratio(below) - she_ratio(above)) < 1e-9);
        assert!(libm::fabs(she_ratio_derivative(below) - she_ratio_derivative(above)) < 1e-9);
        assert!(libm::fabs(she_ratio_derivative(FULL_SLIP_U) + 1.0 / 9.0) < 1e-15);
    }

    #[test]
    fn derivatives_match_finite_differences() {
        let h = 1e-6;
        for i in 1..60 {
            let u = 0.1 * f64::from(i) - 0.05;
            let fd = (she(u + h) - she(u - h)) / (2.0 * h);
            assert!(libm::fabs(fd - she_derivative(u)) < 1e-8, "u = {u}");
            let fd = (she_ratio(u + h) - she_ratio(u - h)) / (2.0 * h);
            assert!(libm::fabs(fd - she_ratio_derivative(u)) < 1e-8, "u = {u}");
        }
    }

    #[test]
    fn never_exceeds_one_and_is_monotone() {
        let mut last = 0.0;
        for i in 0..=10_000 {
            let u = 1e-3 * f64::from(i);
            let s = she(u);
            assert!(s <= 1.0 && s >= last, "u = {u}");
            assert!(s <= u + 1e-15, "saturated above linear at u = {u}");
            let r = she_ratio(u);
            assert!(r > 0.0 && r <= 1.0);
            last = s;
        }
        assert_eq!(she(1e300), 1.0);
        assert_eq!(she(f64::INFINITY), 1.0);
        assert_eq!(she_ratio(f64::INFINITY), 0.0);
    }

    #[test]
    fn signed_and_nan_inputs() {
        assert_eq!(she(-2.0), -she(2.0));
        assert_eq!(she_ratio(-2.0), she_ratio(2.0));
        assert_eq!(she_derivative(-1.0), she_derivative(1.0));
        assert!(she(f64::NAN).is_nan());
        assert!(she_ratio(f64::NAN).is_nan());
        assert!(she_derivative(f64::NAN).is_nan());
        assert!(she_ratio_derivative(f64::NAN).is_nan());
    }
}
