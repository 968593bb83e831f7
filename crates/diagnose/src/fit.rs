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

/// Standard errors of the parameters `free` of a fit at `x` (the others held where they are:
/// parameters on a bound of the fit, or not identifiable from the rows): the square roots of
/// the diagonal of `s^2 (J^T J)^-1`, `J` the forward-difference Jacobian of the `m` residuals
/// and `s^2 = RSS / (m - p)` (the linearised fit's curvature, rows taken as independent).
/// `None` when `J^T J` is singular over `free` or fewer rows than parameters remain.
pub fn standard_errors(
    resid: &dyn Fn(&[f64], &mut [f64]),
    m: usize,
    x: &[f64],
    free: &[usize],
    scale: &[f64],
) -> Option<Vec<f64>> {
    standard_errors_and_inflation(resid, m, x, free, scale).map(|v| v.into_iter().map(|(se, _)| se).collect())
}

/// [`standard_errors`], each with its variance inflation factor: the diagonal of the inverse of
/// `J^T J` scaled to a unit diagonal (the correlation form), 1 for a parameter whose column of
/// `J` is orthogonal to the others', `1 / (1 - R^2)` for one the others' columns explain to
/// `R^2` (Belsley, Kuh & Welsch, *Regression Diagnostics*, 1980, ch. 3). A forward-difference
/// Jacobian carries relative errors of about 1e-6, so an inflation beyond about 1e6 is a
/// singular curvature made regular by rounding, and the error then says nothing.
pub fn standard_errors_and_inflation(
    resid: &dyn Fn(&[f64], &mut [f64]),
    m: usize,
    x: &[f64],
    free: &[usize],
    scale: &[f64],
) -> Option<Vec<(f64, f64)>> {
    let p = free.len();
    if p == 0 || m <= p {
        return None;
    }
    let mut r = vec![0.0; m];
    resid(x, &mut r);
    let s2 = sum_sq(&r) / (m - p) as f64;
    let mut rt = vec![0.0; m];
    let jac: Vec<Vec<f64>> = free
        .iter()
        .map(|&j| {
            let h = 1e-6 * x[j].abs().max(scale[j]);
            let mut xt = x.to_vec();
            xt[j] += h;
            resid(&xt, &mut rt);
            (0..m).map(|i| (rt[i] - r[i]) / h).collect()
        })
        .collect();
    let jtj: Vec<Vec<f64>> =
        (0..p).map(|a| (0..p).map(|b| (0..m).map(|i| jac[a][i] * jac[b][i]).sum()).collect()).collect();
    (0..p)
        .map(|a| {
            let e: Vec<f64> = (0..p).map(|b| f64::from(u8::from(a == b))).collect();
            let col = solve_dense(jtj.clone(), e)?;
            let v = s2 * col[a];
            let inflation = col[a] * jtj[a][a];
            (v >= 0.0 && v.is_finite()).then(|| (v.sqrt(), inflation))
        })
        .collect()
}

/// The variance inflation beyond which [`standard_errors_and_inflation`] reads a curvature as
/// singular: the data cannot tell the parameter from the others.
pub const MAX_INFLATION: f64 = 1e6;

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
    fn standard_errors_of_a_straight_line_are_the_textbook_ones() {
        // y = a + b t with residuals +-0.1 alternating: s^2 = RSS / (n - 2), and the standard
        // errors are s sqrt(diag((X^T X)^-1)) (ordinary least squares).
        let t: Vec<f64> = (0..10).map(f64::from).collect();
        let y: Vec<f64> =
            t.iter().enumerate().map(|(i, t)| 1.0 + 2.0 * t + if i % 2 == 0 { 0.1 } else { -0.1 }).collect();
        let resid = |x: &[f64], out: &mut [f64]| {
            for i in 0..t.len() {
                out[i] = x[0] + x[1] * t[i] - y[i];
            }
        };
        let fit = least_squares(&resid, t.len(), &[0.0, 0.0], &[-10.0, -10.0], &[10.0, 10.0], &[1.0, 1.0]);
        let se = standard_errors(&resid, t.len(), &fit.x, &[0, 1], &[1.0, 1.0]).unwrap();
        let n = t.len() as f64;
        let (st, stt) = (t.iter().sum::<f64>(), t.iter().map(|v| v * v).sum::<f64>());
        let det = n * stt - st * st;
        let s2 = fit.rss / (n - 2.0);
        assert!((se[0] - (s2 * stt / det).sqrt()).abs() < 1e-5 * se[0], "{se:?}");
        assert!((se[1] - (s2 * n / det).sqrt()).abs() < 1e-5 * se[1], "{se:?}");
        // Held at its value: the other's error is the conditional one; nothing free: none.
        let b = standard_errors(&resid, t.len(), &fit.x, &[1], &[1.0, 1.0]).unwrap();
        let s2_held = fit.rss / (n - 1.0);
        assert!((b[0] - (s2_held / stt).sqrt()).abs() < 1e-5 * b[0], "{b:?}");
        assert_eq!(standard_errors(&resid, t.len(), &fit.x, &[], &[1.0, 1.0]), None);
    }

    #[test]
    fn two_parameters_the_rows_cannot_tell_apart_have_an_inflation_beyond_the_limit() {
        // y = (a + b) t: only the sum is measured; a third, c t^2, is apart from both.
        let t: Vec<f64> = (1..12).map(f64::from).collect();
        let y: Vec<f64> =
            t.iter().enumerate().map(|(i, t)| 3.0 * t + 0.5 * t * t + if i % 2 == 0 { 0.1 } else { -0.1 }).collect();
        let resid = |x: &[f64], out: &mut [f64]| {
            for i in 0..t.len() {
                out[i] = (x[0] + x[1]) * t[i] + x[2] * t[i] * t[i] - y[i];
            }
        };
        let x = [1.5, 1.5, 0.5];
        match standard_errors_and_inflation(&resid, t.len(), &x, &[0, 1, 2], &[1.0; 3]) {
            None => {}
            Some(v) => assert!(v[0].1 > MAX_INFLATION && v[1].1 > MAX_INFLATION, "{v:?}"),
        }
        // Without the second: every inflation finite and small, the errors the plain ones.
        let v = standard_errors_and_inflation(&resid, t.len(), &x, &[0, 2], &[1.0; 3]).unwrap();
        assert!(v.iter().all(|(_, f)| (1.0..100.0).contains(f)), "{v:?}");
        let plain = standard_errors(&resid, t.len(), &x, &[0, 2], &[1.0; 3]).unwrap();
        assert_eq!(plain, v.iter().map(|p| p.0).collect::<Vec<_>>());
    }

    #[test]
    fn singular_systems_are_reported() {
        assert_eq!(solve_dense(vec![vec![1.0, 2.0], vec![2.0, 4.0]], vec![1.0, 2.0]), None);
        assert_eq!(solve_dense(vec![vec![2.0, 0.0], vec![0.0, 4.0]], vec![1.0, 2.0]), Some(vec![0.5, 0.5]));
    }
}
