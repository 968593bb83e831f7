//! The float types the control-loop evaluation runs in: `f64`, and `f32` for firmware whose FPU
//! has single precision only.
//!
//! [`Real`] adds to nalgebra's `RealField` (sqrt, cbrt, sin_cos, ... through `libm` in no_std)
//! the conversion from the f64 constants the model is set up with, and the tolerances that
//! depend on the precision. [`lanes`]: several values of one float type computed at once, for
//! the balance of several balls in one pass ([`Lanes`]).

pub mod lanes;

pub use lanes::Lanes;

use nalgebra::RealField;

/// A float type of the evaluation: `f64` or `f32`. Each is also its own single lane
/// ([`Lanes`]), and names the SIMD lanes of its type that the target has ([`Real::Wide`]).
pub trait Real: RealField + Copy + Default + PartialOrd + Lanes<Scalar = Self> {
    /// Several values of this type at once in the target's SIMD registers ([`lanes`]): 4 in f64
    /// and 8 in f32 on x86-64 (SSE2) and AArch64 (NEON), the type itself (one lane) elsewhere.
    type Wide: Lanes<Scalar = Self>;
    /// Tolerance of the real-time evaluator's solve on the residual (max norm of the force and
    /// moment imbalances over the nominal normal load): f64 1e-9, where the torque agrees with
    /// the analysis model's (solved to 1e-12) to about 1e-10 (measured: 6e-11 on DKFZD4012;
    /// 1e-10 gives 1e-12 at about a tenth more time from a cold start); f32 1e-5, at the
    /// residual's rounding noise, where the torque stays within 1e-4 of f64 over the default
    /// sweep (a test; measured: 5e-6).
    const TOLERANCE: Self;
    /// Relative step of a finite-difference Jacobian (about the square root of the epsilon).
    const JACOBIAN_STEP: Self;
    /// Whether a forward-difference Jacobian of the balance is accurate in this type (f64); in
    /// f32 it drowns in the rounding noise of the friction-borne equations.
    const FINITE_DIFFERENCES: bool;
    /// Zero (usable in constants).
    const ZERO: Self;
    /// A tiny positive number, far above the smallest normal one: a floor that keeps a
    /// damping term positive.
    const TINY: Self;
    /// Rounds an f64 to this type (`as`: out of range gives infinity).
    fn of(x: f64) -> Self;
    /// Rounds an f64 of the range `[lo, hi]` to this type without leaving the range: the
    /// nearest value, or where that lies past an end the type does not hold (30000 rpm in rad/s
    /// in f32, 3141.5927 above 3141.59265...), the next one toward the inside, the largest not
    /// above `hi` or the smallest not below `lo`. A value outside the range, or NaN, is rounded
    /// as by [`Real::of`], for the range's check to refuse it.
    fn of_within(x: f64, lo: f64, hi: f64) -> Self;
    /// Widens to f64 (exact).
    fn to_f64(self) -> f64;
    /// The cube root of a positive normal number to within a few units in the last place (an
    /// estimate from the exponent bits refined by Halley's iteration), about a tenth of the
    /// instructions of the correctly rounded `cbrt`; other arguments go to `cbrt`.
    #[inline]
    fn cube_root(self) -> Self {
        self.cube_root_lanes()
    }
    /// (sin, cos) of an angle, by their Taylor series for |angle| <= 0.1 rad (the tilt of the
    /// contact normals: to within an ulp, in a few multiplications), by `sin_cos` otherwise.
    #[inline]
    fn small_sin_cos(self) -> (Self, Self) {
        self.small_sin_cos_lanes()
    }
}

impl Real for f64 {
    type Wide = lanes::WideF64;
    const TOLERANCE: f64 = 1e-9;
    const JACOBIAN_STEP: f64 = 1e-8;
    const TINY: f64 = 1e-300;
    const ZERO: f64 = 0.0;
    const FINITE_DIFFERENCES: bool = true;
    #[inline(always)]
    fn of(x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn of_within(x: f64, _lo: f64, _hi: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn to_f64(self) -> f64 {
        self
    }
}

impl Real for f32 {
    type Wide = lanes::WideF32;
    const TOLERANCE: f32 = 1e-5;
    const JACOBIAN_STEP: f32 = 1e-3;
    const TINY: f32 = 1e-37;
    const ZERO: f32 = 0.0;
    const FINITE_DIFFERENCES: bool = false;
    #[inline(always)]
    fn of(x: f64) -> f32 {
        x as f32
    }
    #[inline]
    fn of_within(x: f64, lo: f64, hi: f64) -> f32 {
        let r = x as f32;
        if x <= hi && f64::from(r) > hi {
            r.next_down()
        } else if x >= lo && f64::from(r) < lo {
            r.next_up()
        } else {
            r
        }
    }
    #[inline(always)]
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
}

#[cfg(test)]
mod tests {
    use super::Real;

    /// A value of a range stays in it when rounded to f32: at an end f32 does not hold (30000
    /// rpm in rad/s), the neighbour toward the inside; inside the range and outside it, the
    /// nearest f32, as `as` gives it.
    #[test]
    fn rounding_within_a_range_stays_in_it() {
        use crate::input::MAX_SPEED_RAD_S as MAX;
        assert!(f64::from(MAX as f32) > MAX, "the end is not held by f32: the case this is for");
        let top = f32::of_within(MAX, -MAX, MAX);
        assert!(f64::from(top) <= MAX && f64::from(top.next_up()) > MAX, "{top}");
        let bottom = f32::of_within(-MAX, -MAX, MAX);
        assert!(f64::from(bottom) >= -MAX && f64::from(bottom.next_down()) < -MAX, "{bottom}");
        for x in [0.0, 1.0, 0.1, -2.5e3, 3141.0, 1e7, -1e7, MAX * (1.0 - 1e-6)] {
            assert_eq!(f32::of_within(x, -1e7, 1e7), x as f32, "{x}");
        }
        // Outside the range (and NaN) as `as` rounds, for the range check to refuse.
        assert_eq!(f32::of_within(2.0 * MAX, -MAX, MAX), (2.0 * MAX) as f32);
        assert!(f32::of_within(f64::NAN, -MAX, MAX).is_nan());
        assert_eq!(f64::of_within(MAX, -MAX, MAX), MAX);
    }

    /// Against the correctly rounded libm over 40 decades (and the edge cases passed on).
    #[test]
    fn cube_root_is_within_a_few_ulps() {
        let mut worst64: f64 = 0.0;
        let mut worst32: f64 = 0.0;
        let mut x = 1e-20_f64;
        while x < 1e20 {
            worst64 = worst64.max((x.cube_root() / libm::cbrt(x) - 1.0).abs());
            let y = x as f32;
            worst32 = worst32.max((f64::from(y.cube_root()) / f64::from(libm::cbrtf(y)) - 1.0).abs());
            x *= 1.000_37;
        }
        assert!(worst64 <= 4.0 * f64::EPSILON, "f64: {worst64:e}");
        assert!(worst32 <= 4.0 * f64::from(f32::EPSILON), "f32: {worst32:e}");
        assert_eq!(0.0_f64.cube_root(), 0.0);
        assert_eq!(8.0_f64.cube_root(), 2.0);
        assert!(f64::NAN.cube_root().is_nan() && f32::NAN.cube_root().is_nan());
        assert_eq!(f64::INFINITY.cube_root(), f64::INFINITY);
        assert!((1e-310_f64.cube_root() / libm::cbrt(1e-310) - 1.0).abs() < 1e-15);
    }

    /// The series against libm up to 0.1 rad, and libm itself beyond.
    #[test]
    fn small_sin_cos_is_within_an_ulp() {
        let mut x = -0.1_f64;
        while x <= 0.1 {
            let (s, c) = x.small_sin_cos();
            let (ls, lc) = libm::sincos(x);
            assert!((s - ls).abs() <= 2.0 * f64::EPSILON * ls.abs().max(1e-300), "sin {x}: {s} vs {ls}");
            assert!((c - lc).abs() <= f64::EPSILON, "cos {x}: {c} vs {lc}");
            let (s32, c32) = (x as f32).small_sin_cos();
            let (ls32, lc32) = libm::sincosf(x as f32);
            assert!((s32 - ls32).abs() <= 2.0 * f32::EPSILON * ls32.abs(), "sin f32 {x}");
            assert!((c32 - lc32).abs() <= f32::EPSILON, "cos f32 {x}");
            x += 1.37e-4;
        }
        assert_eq!(0.3_f64.small_sin_cos(), libm::sincos(0.3));
    }
}
