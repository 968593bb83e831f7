//! Several values of one float type computed at once: the lanes of a SIMD register.
//!
//! The balance of a ball ([`crate::ball::balance`]) is written once, over [`Lanes`]: a float
//! type is its own single lane (`f64`, `f32`), so the model and the evaluator run it ball by
//! ball as they always did, and [`Real::Wide`](crate::real::Real::Wide) (`wide::f64x4`, `wide::f32x8` where the target
//! has SSE2 or NEON) runs it for four or eight balls in one pass, each lane the same operations
//! in the same order as the single lane, so each lane's result is the single lane's to the bit
//! (tested in `ball::balance`). A branch of the single-lane code is a [`Lanes::select`] here:
//! both sides are computed and each lane takes its own.
//!
//! On targets without such registers (`thumbv7em-none-eabihf`) `Real::Wide` is the scalar type
//! itself, one lane.

use core::ops::{Add, Div, Mul, Neg, Sub};

/// A vector of [`Lanes::LANES`] values of the float type [`Lanes::Scalar`], with lane-wise
/// arithmetic, comparisons into a mask, and selection by a mask.
pub trait Lanes:
    Copy
    + Send
    + Sync
    + Default
    + core::fmt::Debug
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The float type of one lane.
    type Scalar: Copy + Default + core::fmt::Debug + PartialEq + Send + Sync;
    /// The result of a lane-wise comparison (`bool` for a single lane).
    type Mask: Copy;
    /// The number of lanes.
    const LANES: usize;
    /// Every lane `x`.
    fn splat(x: Self::Scalar) -> Self;
    /// Every lane the f64 constant `k` rounded to the lanes' type (`as`).
    fn splat_f64(k: f64) -> Self;
    /// Lane `i` is `f(i)`.
    fn from_fn(f: impl FnMut(usize) -> Self::Scalar) -> Self;
    /// Lane `i` (`i < LANES`).
    fn lane(self, i: usize) -> Self::Scalar;
    /// The correctly rounded square root of each lane.
    fn sqrt_lanes(self) -> Self;
    /// The magnitude of each lane.
    fn abs_lanes(self) -> Self;
    /// `self > rhs`, lane by lane (false where either is NaN).
    fn gt_mask(self, rhs: Self) -> Self::Mask;
    /// `self >= rhs`, lane by lane (false where either is NaN).
    fn ge_mask(self, rhs: Self) -> Self::Mask;
    /// `self <= rhs`, lane by lane (false where either is NaN).
    fn le_mask(self, rhs: Self) -> Self::Mask;
    /// Whether each lane is finite.
    fn finite_mask(self) -> Self::Mask;
    /// Both masks.
    fn and_mask(a: Self::Mask, b: Self::Mask) -> Self::Mask;
    /// Each lane from `yes` where `mask` holds, else from `no`.
    fn select(mask: Self::Mask, yes: Self, no: Self) -> Self;
    /// Whether `mask` holds in any lane.
    fn any(mask: Self::Mask) -> bool;
    /// [`Lanes::select`] of `yes()` and `no()`: a single lane computes only the side it takes
    /// (a branch), several lanes both.
    #[inline(always)]
    fn choose(mask: Self::Mask, yes: impl FnOnce() -> Self, no: impl FnOnce() -> Self) -> Self {
        Self::select(mask, yes(), no())
    }
    /// The cube root of each lane ([`crate::real::Real::cube_root`]).
    fn cube_root_lanes(self) -> Self;
    /// (sin, cos) of each lane ([`crate::real::Real::small_sin_cos`]).
    fn small_sin_cos_lanes(self) -> (Self, Self);
}

/// The constant `k` (an f64 literal) in every lane, rounded to the lanes' type.
#[inline(always)]
pub(crate) fn splat_of<V: Lanes>(k: f64) -> V {
    V::splat_f64(k)
}

/// Halley's step for the cube root of `x` from `y`: cubic convergence.
#[inline(always)]
pub(crate) fn halley<V: Lanes>(x: V, y: V) -> V {
    let two = splat_of::<V>(2.0);
    let y3 = y * y * y;
    y * (y3 + two * x) / (two * y3 + x)
}

/// The start of the cube root of a positive normal f64: the exponent divided by three, the
/// mantissa roughly (within 3.2 %, musl's cbrt).
#[inline(always)]
pub(crate) fn cbrt_guess_f64(x: f64) -> f64 {
    f64::from_bits(x.to_bits() / 3 + (0x2a9f_7893_u64 << 32))
}

/// The start of the cube root of a positive normal f32.
#[inline(always)]
pub(crate) fn cbrt_guess_f32(x: f32) -> f32 {
    f32::from_bits(x.to_bits() / 3 + 0x2a51_37a0)
}

/// (sin, cos) by their Taylor series to x^13 / 13! (below 1e-23 at 0.1 rad), for
/// [`crate::real::Real::small_sin_cos`] within 0.1 rad.
#[inline(always)]
pub(crate) fn taylor_sin_cos<V: Lanes>(x: V) -> (V, V) {
    let x2 = x * x;
    let c = |k: f64| splat_of::<V>(k);
    let one = c(1.0);
    let s = x
        * (one
            - x2 * c(1.0 / 6.0)
                * (one
                    - x2 * c(1.0 / 20.0)
                        * (one - x2 * c(1.0 / 42.0) * (one - x2 * c(1.0 / 72.0) * (one - x2 * c(1.0 / 110.0))))));
    let co = one
        - x2 * c(0.5)
            * (one
                - x2 * c(1.0 / 12.0)
                    * (one - x2 * c(1.0 / 30.0) * (one - x2 * c(1.0 / 56.0) * (one - x2 * c(1.0 / 90.0)))));
    (s, co)
}

/// The cube root of an f64 to within a few units in the last place: a positive normal number
/// from [`cbrt_guess_f64`] by three Halley steps, anything else by the correctly rounded `cbrt`.
#[inline]
pub(crate) fn cube_root_f64(x: f64) -> f64 {
    if !(f64::MIN_POSITIVE..f64::INFINITY).contains(&x) {
        return libm::cbrt(x);
    }
    halley(x, halley(x, halley(x, cbrt_guess_f64(x))))
}

/// The cube root of an f32: a positive normal number from [`cbrt_guess_f32`] by two Halley
/// steps, anything else by `cbrtf`.
#[inline]
pub(crate) fn cube_root_f32(x: f32) -> f32 {
    if !(f32::MIN_POSITIVE..f32::INFINITY).contains(&x) {
        return libm::cbrtf(x);
    }
    halley(x, halley(x, cbrt_guess_f32(x)))
}

/// (sin, cos) of `x`: by the Taylor series within 0.1 rad ([`taylor_sin_cos`]), else by
/// nalgebra's `sin_cos` (libm).
#[inline]
fn small_sin_cos<T: Lanes + nalgebra::ComplexField<RealField = T> + PartialOrd>(x: T) -> (T, T) {
    if !(nalgebra::ComplexField::abs(x) <= T::splat_f64(0.1)) {
        return nalgebra::ComplexField::sin_cos(x);
    }
    taylor_sin_cos(x)
}

/// A float type as its own single lane.
macro_rules! single_lane {
    ($t:ty, $cube_root:path) => {
        impl Lanes for $t {
            type Scalar = $t;
            type Mask = bool;
            const LANES: usize = 1;
            #[inline(always)]
            fn splat(x: $t) -> $t {
                x
            }
            #[inline(always)]
            fn splat_f64(k: f64) -> $t {
                k as $t
            }
            #[inline(always)]
            fn from_fn(mut f: impl FnMut(usize) -> $t) -> $t {
                f(0)
            }
            #[inline(always)]
            fn lane(self, _: usize) -> $t {
                self
            }
            #[inline(always)]
            fn sqrt_lanes(self) -> $t {
                nalgebra::ComplexField::sqrt(self)
            }
            #[inline(always)]
            fn abs_lanes(self) -> $t {
                nalgebra::ComplexField::abs(self)
            }
            #[inline(always)]
            fn gt_mask(self, rhs: $t) -> bool {
                self > rhs
            }
            #[inline(always)]
            fn ge_mask(self, rhs: $t) -> bool {
                self >= rhs
            }
            #[inline(always)]
            fn le_mask(self, rhs: $t) -> bool {
                self <= rhs
            }
            #[inline(always)]
            fn finite_mask(self) -> bool {
                self.is_finite()
            }
            #[inline(always)]
            fn and_mask(a: bool, b: bool) -> bool {
                a && b
            }
            #[inline(always)]
            fn select(mask: bool, yes: $t, no: $t) -> $t {
                if mask { yes } else { no }
            }
            #[inline(always)]
            fn any(mask: bool) -> bool {
                mask
            }
            #[inline(always)]
            fn choose(mask: bool, yes: impl FnOnce() -> $t, no: impl FnOnce() -> $t) -> $t {
                if mask { yes() } else { no() }
            }
            #[inline(always)]
            fn cube_root_lanes(self) -> $t {
                $cube_root(self)
            }
            #[inline(always)]
            fn small_sin_cos_lanes(self) -> ($t, $t) {
                small_sin_cos(self)
            }
        }
    };
}

single_lane!(f64, cube_root_f64);
single_lane!(f32, cube_root_f32);

/// The lanes of [`Real::Wide`](crate::real::Real::Wide) where the target has SIMD registers
/// (x86-64's SSE2, AArch64's NEON): `wide`'s vectors of four f64 and eight f32.
#[cfg(any(target_feature = "sse2", all(target_arch = "aarch64", target_feature = "neon")))]
mod simd {
    use super::*;

    /// A `wide` vector type as lanes of `$t`: `$guess` starts the cube root, `$steps` Halley steps
    /// finish it, as `$cube_root` does for one value (and does itself for a lane that is not a
    /// positive normal number).
    macro_rules! wide_lanes {
        ($w:ty, $t:ty, $n:expr, $guess:path, $steps:expr, $cube_root:path) => {
            impl Lanes for $w {
                type Scalar = $t;
                type Mask = $w;
                const LANES: usize = $n;
                #[inline(always)]
                fn splat(x: $t) -> Self {
                    <$w>::splat(x)
                }
                #[inline(always)]
                fn splat_f64(k: f64) -> Self {
                    <$w>::splat(k as $t)
                }
                #[inline(always)]
                fn from_fn(f: impl FnMut(usize) -> $t) -> Self {
                    <$w>::new(core::array::from_fn(f))
                }
                #[inline(always)]
                fn lane(self, i: usize) -> $t {
                    self.as_array()[i]
                }
                #[inline(always)]
                fn sqrt_lanes(self) -> Self {
                    self.sqrt()
                }
                #[inline(always)]
                fn abs_lanes(self) -> Self {
                    self.abs()
                }
                #[inline(always)]
                fn gt_mask(self, rhs: Self) -> Self {
                    self.simd_gt(rhs)
                }
                #[inline(always)]
                fn ge_mask(self, rhs: Self) -> Self {
                    self.simd_ge(rhs)
                }
                #[inline(always)]
                fn le_mask(self, rhs: Self) -> Self {
                    self.simd_le(rhs)
                }
                #[inline(always)]
                fn finite_mask(self) -> Self {
                    self.is_finite()
                }
                #[inline(always)]
                fn and_mask(a: Self, b: Self) -> Self {
                    a & b
                }
                #[inline(always)]
                fn select(mask: Self, yes: Self, no: Self) -> Self {
                    mask.select(yes, no)
                }
                #[inline(always)]
                fn any(mask: Self) -> bool {
                    mask.any()
                }
                #[inline]
                fn cube_root_lanes(self) -> Self {
                    let x = self.to_array();
                    let normal = |v: $t| (<$t>::MIN_POSITIVE..<$t>::INFINITY).contains(&v);
                    let mut y = <$w>::new(core::array::from_fn(|i| if normal(x[i]) { $guess(x[i]) } else { 1.0 }));
                    for _ in 0..$steps {
                        y = halley(self, y);
                    }
                    if x.iter().all(|&v| normal(v)) {
                        return y;
                    }
                    let y = y.to_array();
                    <$w>::new(core::array::from_fn(|i| if normal(x[i]) { y[i] } else { $cube_root(x[i]) }))
                }
                #[inline]
                fn small_sin_cos_lanes(self) -> (Self, Self) {
                    let (s, c) = taylor_sin_cos(self);
                    let small = self.abs().simd_le(<$w>::splat(0.1 as $t));
                    if small.all() {
                        return (s, c);
                    }
                    // Some lane beyond 0.1 rad: every lane as the single lane takes it.
                    let x = self.to_array();
                    let each: [($t, $t); $n] = core::array::from_fn(|i| small_sin_cos(x[i]));
                    (<$w>::new(core::array::from_fn(|i| each[i].0)), <$w>::new(core::array::from_fn(|i| each[i].1)))
                }
            }
        };
    }

    wide_lanes!(wide::f64x4, f64, 4, cbrt_guess_f64, 3, cube_root_f64);
    wide_lanes!(wide::f32x8, f32, 8, cbrt_guess_f32, 2, cube_root_f32);

    /// Four f64 in lanes.
    pub type WideF64 = wide::f64x4;
    /// Eight f32 in lanes.
    pub type WideF32 = wide::f32x8;
}

/// Without SIMD registers (`thumbv7em-none-eabihf`): each float type is its own one lane.
#[cfg(not(any(target_feature = "sse2", all(target_arch = "aarch64", target_feature = "neon"))))]
mod simd {
    /// f64, one lane.
    pub type WideF64 = f64;
    /// f32, one lane.
    pub type WideF32 = f32;
}

pub use simd::{WideF32, WideF64};
