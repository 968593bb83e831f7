//! The ranges of a contact given by hand: what `ballscrew contact` and `ballscrew creep-curves`
//! accept in their flags and Python's `ballscrew.contact` in its arguments, in the units both
//! give them (mm, N, 1/mm, 1/mm^2, GPa). One table, so both front ends refuse the same values
//! with the same words. FASTSIM's own checks ([`crate::contact::fastsim`]) are wider (any
//! positive ellipse, up to [`crate::contact::fastsim::MAX_GRID`] elements per axis); these are
//! the ranges in which the numbers of one contact stay far from the limits of double precision
//! whatever the other values, and the grid within a second or so.

use crate::input::YOUNGS_MODULUS_RANGE_PA;

/// A closed range `[lo, hi]` of a real value and its words in error messages.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limit {
    /// Smallest value accepted.
    pub lo: f64,
    /// Largest value accepted.
    pub hi: f64,
    /// The range in words, e.g. `"finite, [1e-4, 100] mm"`.
    pub valid: &'static str,
}

impl Limit {
    /// Whether `value` is in the range (NaN is not).
    pub fn contains(&self, value: f64) -> bool {
        (self.lo..=self.hi).contains(&value)
    }
}

/// Most FASTSIM elements per axis (the grid is this squared at most).
pub const MAX_GRID: i64 = 400;

/// A Hertz semi-axis, mm (0.1 um: below it the contact's numbers leave double precision together
/// with the other extremes).
pub const SEMI_AXIS_MM: Limit = Limit { lo: 1.0e-4, hi: 100.0, valid: "finite, [1e-4, 100] mm" };

/// The normal load, N (the spec's largest preload at most).
pub const NORMAL_LOAD_N: Limit = Limit { lo: 1.0e-6, hi: 1.0e7, valid: "finite, [1e-6, 1e7] N" };

/// The friction coefficient (with the smallest load, mu Q stays far from underflow).
pub const FRICTION: Limit = Limit { lo: 1.0e-4, hi: 1.0, valid: "[1e-4, 1]" };

/// A creepage in its unit: xi and eta dimensionless, phi in 1/mm, the Heathcote coefficient in
/// 1/mm^2.
pub const CREEPAGE: Limit = Limit { lo: -1.0e3, hi: 1.0e3, valid: "finite, |value| <= 1000" };

/// Young's modulus, GPa: the spec's range ([`YOUNGS_MODULUS_RANGE_PA`]).
pub const YOUNGS_MODULUS_GPA: Limit =
    Limit { lo: YOUNGS_MODULUS_RANGE_PA.0 / 1e9, hi: YOUNGS_MODULUS_RANGE_PA.1 / 1e9, valid: "[1, 1000] GPa" };

/// Poisson's ratio: the spec's range.
pub const POISSON_RATIO: Limit = Limit { lo: 0.0, hi: 0.5, valid: "[0, 0.5]" };

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limits_hold_their_ends_and_refuse_nan() {
        for l in [SEMI_AXIS_MM, NORMAL_LOAD_N, FRICTION, CREEPAGE, YOUNGS_MODULUS_GPA, POISSON_RATIO] {
            assert!(l.contains(l.lo) && l.contains(l.hi), "{l:?}");
            assert!(!l.contains(f64::NAN) && !l.contains(f64::INFINITY), "{l:?}");
        }
        assert!(MAX_GRID as usize <= crate::contact::fastsim::MAX_GRID);
        assert_eq!((YOUNGS_MODULUS_GPA.lo, YOUNGS_MODULUS_GPA.hi), (1.0, 1000.0));
    }
}
