//! The small dense linear algebra of the evaluator's solves: the inverse Jacobian ([`Matrix`]),
//! its product with a residual, Broyden's update, and conversions between f64 and `F`.

use crate::ball::setup::{N, Unknowns};
use crate::ball::solve;
use crate::real::Real;

pub(super) type Matrix<F> = [[F; N]; N];

pub(super) fn convert<F: Real>(x: &Unknowns) -> [F; N] {
    core::array::from_fn(|i| F::of(x[i]))
}

/// The inverse of `m` (Gaussian elimination, column by column); `None` when singular.
pub(super) fn invert<F: Real>(m: &Matrix<F>) -> Option<Matrix<F>> {
    let mut inv = [[F::zero(); N]; N];
    for j in 0..N {
        let mut e = [F::zero(); N];
        e[j] = F::one();
        let col = solve::solve_linear(*m, e)?;
        for i in 0..N {
            inv[i][j] = col[i];
        }
    }
    Some(inv)
}

/// `m v`.
#[inline(always)]
pub(super) fn times<F: Real>(m: &Matrix<F>, v: &[F; N]) -> [F; N] {
    core::array::from_fn(|i| (0..N).fold(F::zero(), |acc, k| acc + m[i][k] * v[k]))
}

/// Broyden's ("good") update of the inverse Jacobian `h` after the step `dx` changed the
/// residual by `dr` (Sherman-Morrison): h += (dx - h dr) (dx^T h) / (dx^T h dr).
pub(super) fn update_inverse<F: Real>(h: &mut Matrix<F>, dx: &[F; N], dr: &[F; N]) {
    let hdr = times(h, dr);
    let denom = (0..N).fold(F::zero(), |acc, k| acc + dx[k] * hdr[k]);
    if !(denom.abs() > F::TINY) {
        return;
    }
    let row: [F; N] = core::array::from_fn(|j| (0..N).fold(F::zero(), |acc, k| acc + dx[k] * h[k][j]) / denom);
    for i in 0..N {
        let u = dx[i] - hdr[i];
        for j in 0..N {
            h[i][j] += u * row[j];
        }
    }
}

pub(super) fn convert_matrix<F: Real>(m: &solve::Jacobian) -> Matrix<F> {
    core::array::from_fn(|r| core::array::from_fn(|c| F::of(m[r][c])))
}
