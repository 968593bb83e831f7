//! The float types the control-loop evaluation runs in: `f64`, and `f32` for firmware whose FPU
//! has single precision only.
//!
//! [`Real`] adds to nalgebra's `RealField` (sqrt, cbrt, sin_cos, ... through `libm` in no_std)
//! the conversion from the f64 constants the model is set up with, and the tolerances that
//! depend on the precision.

use nalgebra::RealField;

/// A float type of the evaluation: `f64` or `f32`.
pub trait Real: RealField + Copy + Default + PartialOrd {
    /// Tolerance of the real-time evaluator's Newton solve on the residual (max norm of the
    /// force and moment imbalances over the nominal normal load): f64 1e-10, where the torque
    /// agrees with the analysis model's (solved to 1e-12) to about 1e-10; f32 1e-5, just above
    /// the residual's rounding noise, where the torque stays within 1e-4 of f64 over the
    /// default sweep (a test).
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
    /// Widens to f64 (exact).
    fn to_f64(self) -> f64;
}

impl Real for f64 {
    const TOLERANCE: f64 = 1e-10;
    const JACOBIAN_STEP: f64 = 1e-8;
    const TINY: f64 = 1e-300;
    const ZERO: f64 = 0.0;
    const FINITE_DIFFERENCES: bool = true;
    #[inline(always)]
    fn of(x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn to_f64(self) -> f64 {
        self
    }
}

impl Real for f32 {
    const TOLERANCE: f32 = 1e-5;
    const JACOBIAN_STEP: f32 = 1e-3;
    const TINY: f32 = 1e-37;
    const ZERO: f32 = 0.0;
    const FINITE_DIFFERENCES: bool = false;
    #[inline(always)]
    fn of(x: f64) -> f32 {
        x as f32
    }
    #[inline(always)]
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
}
