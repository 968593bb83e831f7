//! How a residual depends on the columns: trend, binned means, serial correlation along a
//! column, and the periodogram along the nut position.

use super::data::Column;

/// The residual against one column.
#[derive(Debug, Clone, PartialEq)]
pub struct Dependence {
    /// The column.
    pub column: Column,
    /// Pearson correlation of residual and column.
    pub correlation: f64,
    /// Least-squares slope, N m per unit of the column.
    pub slope_nm_per_unit: f64,
    /// Mean residual in up to [`BINS`] bins of equal count: (lowest value, highest value, mean
    /// residual N m, rows).
    pub bins: Vec<(f64, f64, f64, usize)>,
    /// Lag-1 autocorrelation of the residual ordered along the column.
    pub serial_correlation: f64,
    /// One sentence.
    pub sentence: String,
}

/// Bins of the binned means.
pub const BINS: usize = 5;

fn mean(v: &[f64]) -> f64 {
    v.iter().sum::<f64>() / v.len().max(1) as f64
}

/// Pearson correlation and least-squares slope of `y` on `x`.
pub fn trend(x: &[f64], y: &[f64]) -> (f64, f64) {
    let (mx, my) = (mean(x), mean(y));
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx).powi(2)).sum();
    let syy: f64 = y.iter().map(|b| (b - my).powi(2)).sum();
    if sxx <= 0.0 || syy <= 0.0 {
        return (0.0, 0.0);
    }
    (sxy / (sxx * syy).sqrt(), sxy / sxx)
}

/// Lag-1 autocorrelation of `y` ordered by `x` (rows with equal x averaged first).
pub fn serial_correlation(x: &[f64], y: &[f64]) -> f64 {
    let mut idx: Vec<usize> = (0..x.len()).collect();
    idx.sort_by(|&a, &b| x[a].total_cmp(&x[b]));
    let mut seq = Vec::new();
    let mut i = 0;
    while i < idx.len() {
        let mut j = i;
        let mut s = 0.0;
        while j < idx.len() && x[idx[j]] == x[idx[i]] {
            s += y[idx[j]];
            j += 1;
        }
        seq.push(s / (j - i) as f64);
        i = j;
    }
    if seq.len() < 4 {
        return 0.0;
    }
    let m = mean(&seq);
    let c0: f64 = seq.iter().map(|v| (v - m).powi(2)).sum();
    let c1: f64 = seq.windows(2).map(|w| (w[0] - m) * (w[1] - m)).sum();
    if c0 > 0.0 { c1 / c0 } else { 0.0 }
}

/// The dependence of `resid` on column `c` with values `x`.
pub fn dependence(c: Column, x: &[f64], resid: &[f64]) -> Dependence {
    let (r, slope) = trend(x, resid);
    let mut idx: Vec<usize> = (0..x.len()).collect();
    idx.sort_by(|&a, &b| x[a].total_cmp(&x[b]));
    let mut bins = Vec::new();
    let per = x.len().div_ceil(BINS).max(1);
    for chunk in idx.chunks(per) {
        let ys: Vec<f64> = chunk.iter().map(|&i| resid[i]).collect();
        bins.push((x[chunk[0]], x[chunk[chunk.len() - 1]], mean(&ys), chunk.len()));
    }
    let serial = serial_correlation(x, resid);
    // To the 1e-4 N m shown, a mean that rounds to zero without its sign (not `-0.0000`).
    let shown = |v: f64| (v * 1e4).round() / 1e4 + 0.0;
    let (lo, hi) = (shown(bins.first().map_or(0.0, |b| b.2)), shown(bins.last().map_or(0.0, |b| b.2)));
    let strength = if r.abs() >= 0.5 {
        "strongly"
    } else if r.abs() >= 0.2 {
        "clearly"
    } else {
        "hardly"
    };
    let sentence = format!(
        "The residual {} with {} (r = {r:.2}, slope {} N m per {}): mean {lo:+.4} N m in the lowest fifth, {hi:+.4} N m in the highest.",
        if r.abs() < 0.2 {
            format!("{strength} changes")
        } else if r > 0.0 {
            format!("{strength} rises")
        } else {
            format!("{strength} falls")
        },
        c.name(),
        crate::text::sig(slope),
        if c.unit().is_empty() { "unit" } else { c.unit() }
    );
    Dependence { column: c, correlation: r, slope_nm_per_unit: slope, bins, serial_correlation: serial, sentence }
}

/// Amplitude of the residual at harmonics 1..=`max` of the lead along the position `x_mm`
/// (least-squares sine and cosine of `sign * sin(2 pi h x / L)`; `sign` the direction).
pub fn periodogram(x_mm: &[f64], sign: &[f64], resid: &[f64], lead_mm: f64, max: u32) -> Vec<(u32, f64)> {
    (1..=max)
        .map(|h| {
            let k = 2.0 * core::f64::consts::PI * h as f64 / lead_mm;
            let (mut ss, mut sc, mut cc, mut ys, mut yc) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for i in 0..x_mm.len() {
                let s = sign[i] * (k * x_mm[i]).sin();
                let c = sign[i] * (k * x_mm[i]).cos();
                ss += s * s;
                sc += s * c;
                cc += c * c;
                ys += resid[i] * s;
                yc += resid[i] * c;
            }
            let det = ss * cc - sc * sc;
            if det.abs() < 1e-300 {
                return (h, 0.0);
            }
            let a = (ys * cc - yc * sc) / det;
            let b = (yc * ss - ys * sc) / det;
            (h, a.hypot(b))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trend_and_serial_correlation_see_a_line_and_a_sine() {
        let x: Vec<f64> = (0..50).map(|i| i as f64).collect();
        let y: Vec<f64> = x.iter().map(|v| 2.0 * v + 1.0).collect();
        let (r, s) = trend(&x, &y);
        assert!((r - 1.0).abs() < 1e-12 && (s - 2.0).abs() < 1e-12);
        let w: Vec<f64> = x.iter().map(|v| (v * 0.2).sin()).collect();
        assert!(serial_correlation(&x, &w) > 0.9);
        let d = dependence(Column::PreloadN, &x, &y);
        assert_eq!(d.bins.len(), BINS);
        assert!(d.sentence.contains("strongly rises"), "{}", d.sentence);
    }

    /// A bin mean that rounds to zero at the 1e-4 N m the sentence shows is `+0.0000`, not
    /// `-0.0000`.
    #[test]
    fn a_mean_that_rounds_to_zero_shows_no_sign() {
        let x: Vec<f64> = (0..50).map(f64::from).collect();
        let y: Vec<f64> = x.iter().map(|v| if *v < 10.0 { -1e-6 } else { 0.01 * v }).collect();
        let d = dependence(Column::PreloadN, &x, &y);
        assert!(d.bins[0].2 < 0.0, "{:?}", d.bins);
        assert!(d.sentence.contains("mean +0.0000 N m in the lowest fifth"), "{}", d.sentence);
    }

    #[test]
    fn periodogram_finds_the_harmonic() {
        let x: Vec<f64> = (0..200).map(|i| i as f64 * 1.37).collect();
        let sign: Vec<f64> = (0..200).map(|i| if i % 2 == 0 { 1.0 } else { -1.0 }).collect();
        let y: Vec<f64> =
            (0..200).map(|i| sign[i] * 0.3 * (2.0 * core::f64::consts::PI * 3.0 * x[i] / 12.0 + 0.4).sin()).collect();
        let p = periodogram(&x, &sign, &y, 12.0, 6);
        assert!((p[2].1 - 0.3).abs() < 1e-9, "{p:?}");
        assert!(p[0].1 < 0.05 && p[4].1 < 0.05, "{p:?}");
    }
}
