//! Bounded nonlinear least squares (Levenberg-Marquardt with Marquardt's diagonal scaling,
//! forward-difference Jacobian, steps projected onto the bounds) for the few parameters of a
//! diagnosis.

/// Most iterations.
const MAX_ITER: usize = 60;

/// The result of a fit.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// The parameters.
    pub x: Vec<f64>,
    /// Residual sum of squares.
    pub rss: f64,
}

fn sum_sq(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum()
}

/// Solves the small dense system `a x = b` by Gaussian elimination with partial pivoting;
/// `None` when singular.
pub fn solve_dense(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Option<Vec<f64>> {
    let n = b.len();
    for c in 0..n {
        let p = (c..n).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))?;
        if !(a[p][c].abs() > 1e-300) {
            return None;
        }
        a.swap(c, p);
        b.swap(c, p);
        for r in c + 1..n {
            let m = a[r][c] / a[c][c];
            for k in c..n {
                a[r][k] -= m * a[c][k];
            }
            b[r] -= m * b[c];
        }
    }
    let mut x = vec![0.0; n];
    for c in (0..n).rev() {
        let s: f64 = (c + 1..n).map(|k| a[c][k] * x[k]).sum();
        x[c] = (b[c] - s) / a[c][c];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Minimises the sum of squares of `resid(x, out)` (`m` residuals) within `lo..=hi` from `x0`.
/// `scale[j]` is a typical size of parameter j (sets the difference step).
pub fn least_squares(
    resid: &dyn Fn(&[f64], &mut [f64]),
    m: usize,
    x0: &[f64],
    lo: &[f64],
    hi: &[f64],
    scale: &[f64],
) -> Fit {
    let n = x0.len();
    let clamp = |x: &mut [f64]| {
        for j in 0..n {
            x[j] = x[j].clamp(lo[j], hi[j]);
        }
    };
    let mut x = x0.to_vec();
    clamp(&mut x);
    let mut r = vec![0.0; m];
    resid(&x, &mut r);
    let mut rss = sum_sq(&r);
    if n == 0 || !rss.is_finite() {
        return Fit { x, rss };
    }
    let mut lambda = 1e-3;
    let mut jac = vec![vec![0.0; m]; n];
    let mut rt = vec![0.0; m];
    for _ in 0..MAX_ITER {
        for j in 0..n {
            let h = 1e-6 * x[j].abs().max(scale[j]);
            let mut xt = x.clone();
            // Step away from the nearer bound.
            xt[j] = if x[j] + h <= hi[j] { x[j] + h } else { x[j] - h };
            let dh = xt[j] - x[j];
            resid(&xt, &mut rt);
            for i in 0..m {
                jac[j][i] = (rt[i] - r[i]) / dh;
            }
        }
        let jtj: Vec<Vec<f64>> =
            (0..n).map(|a| (0..n).map(|b| (0..m).map(|i| jac[a][i] * jac[b][i]).sum()).collect()).collect();
        let jtr: Vec<f64> = (0..n).map(|a| (0..m).map(|i| jac[a][i] * r[i]).sum()).collect();
        let mut improved = false;
        for _ in 0..12 {
            let mut a = jtj.clone();
            for j in 0..n {
                a[j][j] += lambda * jtj[j][j].max(1e-30);
            }
            let Some(step) = solve_dense(a, jtr.iter().map(|v| -v).collect()) else {
                lambda *= 10.0;
                continue;
            };
            let mut xn: Vec<f64> = x.iter().zip(&step).map(|(a, b)| a + b).collect();
            clamp(&mut xn);
            resid(&xn, &mut rt);
            let rn = sum_sq(&rt);
            if rn.is_finite() && rn < rss {
                let rel = (rss - rn) / rss.max(1e-300);
                x = xn;
                core::mem::swap(&mut r, &mut rt);
                rss = rn;
                lambda = (lambda * 0.3).max(1e-12);
                improved = true;
                if rel < 1e-10 {
                    return Fit { x, rss };
                }
                break;
            }
            lambda *= 10.0;
        }
        if !improved {
            break;
        }
    }
    Fit { x, rss }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fits_an_exponential_within_bounds() {
        let t: Vec<f64> = (0..20).map(|i| i as f64 * 0.1).collect();
        let y: Vec<f64> = t.iter().map(|t| 2.0 * (-1.3 * t).exp()).collect();
        let resid = |x: &[f64], out: &mut [f64]| {
            for i in 0..t.len() {
                out[i] = x[0] * (-x[1] * t[i]).exp() - y[i];
            }
        };
        let f = least_squares(&resid, t.len(), &[1.0, 0.5], &[0.0, 0.0], &[10.0, 10.0], &[1.0, 1.0]);
        assert!((f.x[0] - 2.0).abs() < 1e-6 && (f.x[1] - 1.3).abs() < 1e-6, "{:?}", f);
        // A bound that excludes the optimum holds.
        let f = least_squares(&resid, t.len(), &[1.0, 0.5], &[0.0, 0.0], &[10.0, 1.0], &[1.0, 1.0]);
        assert_eq!(f.x[1], 1.0);
    }

    #[test]
    fn singular_systems_are_reported() {
        assert_eq!(solve_dense(vec![vec![1.0, 2.0], vec![2.0, 4.0]], vec![1.0, 2.0]), None);
        assert_eq!(solve_dense(vec![vec![2.0, 0.0], vec![0.0, 4.0]], vec![1.0, 2.0]), Some(vec![0.5, 0.5]));
    }
}
