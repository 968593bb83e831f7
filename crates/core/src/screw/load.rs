//! Load over nuts, circles and balls (Eq. 26 and docs/model-notes.md item 8).
//!
//! A preloaded double nut shares an external axial load F_a between its two nuts through their
//! Hertzian stiffness (axial deflection proportional to the nut load to the power 2/3):
//! F1^(2/3) + F2^(2/3) = 2 Fp^(2/3), F1 - F2 = F_a, until the unloaded nut lifts off at
//! |F_a| = 2^(3/2) Fp. Within a nut the load is spread over the circles by the chosen
//! [`LoadDistribution`]; the balls of one circle share its load equally.

use crate::input::{Geometry, LoadDistribution, MAX_CIRCLES_PER_NUT, MAX_NUTS, Preload};
use crate::real::Real;

/// The sets of balls (or of contacts) that bear on one flank, and what each carries: the
/// double nut's two nuts, the offset-lead nut's two halves, the two contact diagonals of the
/// oversize balls, or the single unpreloaded nut's one set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadGroups {
    /// How many groups (1 or 2).
    pub count: usize,
    /// Circles in each group.
    pub circles: u32,
    /// Each group's axial load (N) and the flank it bears on (+1 / -1).
    pub loads: [(f64, f64); MAX_NUTS],
    /// The two groups are the two contact diagonals of the same balls (four-point contact).
    pub four_point: bool,
}

/// The load groups of a screw of geometry `g` at preload `preload_n` and axial load
/// `axial_load_n` (N). Two groups on opposite flanks share the axial load by [`nut_loads`]
/// (both for the oversize balls' diagonals: each diagonal's approach grows with the load to
/// the power 2/3 as a nut's does); a nut without preload carries the axial load alone on the
/// flank it pushes.
pub fn groups(g: &Geometry, preload_n: f64, axial_load_n: f64) -> LoadGroups {
    let two = |circles: u32, four_point: bool| LoadGroups {
        count: 2,
        circles,
        loads: nut_loads(preload_n, axial_load_n, 2),
        four_point,
    };
    match g.preload {
        Preload::DoubleNut => two(g.circles_per_nut, false),
        Preload::OffsetLead => two(g.circles_per_nut / 2, false),
        Preload::OversizeBall => two(g.circles_per_nut, true),
        Preload::None => LoadGroups {
            count: 1,
            circles: g.circles_per_nut,
            loads: nut_loads(0.0, axial_load_n, 1),
            four_point: false,
        },
    }
}

/// The axial load each nut carries, N, and the flank it bears on (+1 or -1) for nut index i.
///
/// Nut 0 bears on the flank whose balls push the nut towards -z (flank +1), nut 1 on the other.
/// `axial_load_n` > 0 loads nut 0 more. One nut (`nuts` = 1) carries `preload_n +
/// axial_load_n` on the flank of its sign.
pub fn nut_loads(preload_n: f64, axial_load_n: f64, nuts: u32) -> [(f64, f64); MAX_NUTS] {
    if nuts <= 1 {
        let f = preload_n + axial_load_n;
        let flank = if f >= 0.0 { 1.0 } else { -1.0 };
        return [(libm::fabs(f), flank), (0.0, -1.0)];
    }
    let fa = libm::fabs(axial_load_n);
    let (heavy, light) = if preload_n <= 0.0 || fa >= 2.0 * core::f64::consts::SQRT_2 * preload_n {
        // No preload, or the light nut has lifted off.
        (fa, 0.0)
    } else if fa == 0.0 {
        // No axial load: both nuts carry the preload (the root below, exactly).
        (preload_n, preload_n)
    } else {
        // Solve g(x) = (x + fa)^(2/3) + x^(2/3) - 2 fp^(2/3) = 0 for the light nut's load x in
        // [0, fp]: g is increasing and concave, g(0) <= 0 <= g(fp). Newton's method from
        // fp - fa / 2 (a start a few ulps off the root converges in one step), kept inside the
        // bracket by bisection; it stops once its step is below the rounding of x.
        let target = 2.0 * libm::cbrt(preload_n * preload_n);
        let (mut lo, mut hi) = (0.0, preload_n);
        let mut x = preload_n - 0.5 * fa;
        if !(x > lo && x < hi) {
            x = 0.5 * (lo + hi);
        }
        for _ in 0..200 {
            let (a, b) = ((x + fa).cube_root(), x.cube_root());
            let gx = a * a + b * b - target;
            if gx > 0.0 {
                hi = x
            } else {
                lo = x
            }
            let d = (2.0 / 3.0) * (1.0 / a + if b > 0.0 { 1.0 / b } else { f64::INFINITY });
            let step = gx / d;
            if libm::fabs(step) <= 1e-15 * preload_n {
                // Kept in the bracket: next to lift-off the root is a few ulps of the preload
                // above 0, and the last step may cross it.
                x = (x - step).max(lo).min(hi);
                break;
            }
            let next = x - step;
            x = if next > lo && next < hi { next } else { 0.5 * (lo + hi) };
        }
        (x + fa, x)
    };
    if axial_load_n >= 0.0 { [(heavy, 1.0), (light, -1.0)] } else { [(light, 1.0), (heavy, -1.0)] }
}

/// The heaviest ball's load, N: of the `nut_loads` (N) of the first `nuts` nuts, each spread over
/// its first `circles` circles by `shares` and over `balls_per_circle` balls.
pub fn heaviest_ball_load_n(
    nut_loads: &[(f64, f64); MAX_NUTS],
    nuts: usize,
    shares: &CircleShares,
    circles: usize,
    balls_per_circle: f64,
) -> f64 {
    let top = shares.largest(circles);
    nut_loads.iter().take(nuts).map(|&(l, _)| l * top / balls_per_circle).fold(0.0_f64, f64::max)
}

/// Share of the nut's load carried by each circle, and the weight applied to each circle's
/// friction, for `circles` circles (index 0 = the first, most loaded circle).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircleShares {
    /// Fraction of the nut load carried by circle j (sums to 1).
    pub load_fraction: [f64; MAX_CIRCLES_PER_NUT],
    /// Weight on circle j's friction and dissipation (1 except for the paper-literal reading).
    pub weight: [f64; MAX_CIRCLES_PER_NUT],
}

impl CircleShares {
    /// The largest share of the first `circles` circles (the heaviest circle's).
    pub fn largest(&self, circles: usize) -> f64 {
        self.load_fraction.iter().take(circles).fold(0.0_f64, |m, &f| m.max(f))
    }
}

/// Circle shares for the given distribution (Eq. 26; docs/model-notes.md item 8).
pub fn circle_shares(circles: u32, distribution: LoadDistribution) -> CircleShares {
    let n = (circles as usize).clamp(1, MAX_CIRCLES_PER_NUT);
    let mut load_fraction = [0.0; MAX_CIRCLES_PER_NUT];
    let mut weight = [0.0; MAX_CIRCLES_PER_NUT];
    let mut geo = [0.0; MAX_CIRCLES_PER_NUT];
    let mut w = 1.0;
    let mut sum = 0.0;
    for g in geo.iter_mut().take(n) {
        *g = w;
        sum += w;
        w *= 2.0 / 3.0;
    }
    for j in 0..n {
        match distribution {
            LoadDistribution::Geometric => {
                load_fraction[j] = geo[j] / sum;
                weight[j] = 1.0;
            }
            LoadDistribution::PaperLiteral => {
                load_fraction[j] = 1.0 / n as f64;
                weight[j] = geo[j];
            }
            LoadDistribution::Uniform => {
                load_fraction[j] = 1.0 / n as f64;
                weight[j] = 1.0;
            }
        }
    }
    CircleShares { load_fraction, weight }
}

/// The circles' shares of a nut's load with a lead deviation: circle `j` of `circles` gains
/// the axial approach `e_j = deviation_m j / (circles - 1)` (m) over the approach it has at its
/// share of the nominal lead, and the shares follow from every circle's approach again.
///
/// A ball of axial load `p` (N) approaches axially by `u = approach_per_load p^(2/3)` (Hertz:
/// both raceway contacts, [`crate::screw::model::Model::axial_approach_m_per_n23`]); the
/// nominal shares `s_j` give each circle the approach `a_j = u(s_j F / z)` at the nut's load
/// per ball `load_per_ball_n = F / z`. With the deviation, circle `j` approaches by
/// `t a_j + e_j`, `t` the one factor for which the circles' loads
/// `((t a_j + e_j)^+ / approach_per_load)^(3/2)` carry the nut's load again (a bisection: the
/// sum grows with `t`). A circle whose approach would be negative carries nothing. The
/// weights are kept; without a deviation, or with no load, `shares` is returned as it is.
pub fn shares_with_lead_deviation(
    shares: &CircleShares,
    circles: usize,
    load_per_ball_n: f64,
    approach_per_load: f64,
    deviation_m: f64,
) -> CircleShares {
    lead_deviation(shares, circles, load_per_ball_n, approach_per_load, deviation_m).0
}

/// The axial approach of a nut's first circle (m), the one the deviation does not move, at the
/// nut's load per ball `load_per_ball_n` (N), with [`shares_with_lead_deviation`]'s arguments:
/// `t a_0`, the nut's deflection against the screw. Without a deviation it is
/// `approach_per_load (s_0 F / z)^(2/3)`, the nut's Hertzian deflection that
/// [`nut_loads`] balances.
pub fn nut_approach_m(
    shares: &CircleShares,
    circles: usize,
    load_per_ball_n: f64,
    approach_per_load: f64,
    deviation_m: f64,
) -> f64 {
    let t = lead_deviation(shares, circles, load_per_ball_n, approach_per_load, deviation_m).1;
    let c = libm::cbrt(shares.load_fraction[0] * load_per_ball_n.max(0.0));
    t * approach_per_load * c * c
}

/// [`shares_with_lead_deviation`] and the factor `t` it found (1 where nothing moves).
fn lead_deviation(
    shares: &CircleShares,
    circles: usize,
    load_per_ball_n: f64,
    approach_per_load: f64,
    deviation_m: f64,
) -> (CircleShares, f64) {
    let n = circles.clamp(1, MAX_CIRCLES_PER_NUT);
    if deviation_m == 0.0 || n < 2 || !(load_per_ball_n > 0.0) || !(approach_per_load > 0.0) {
        return (*shares, 1.0);
    }
    let approach = |p: f64| {
        let c = libm::cbrt(p);
        approach_per_load * c * c
    };
    let mut nominal = [0.0; MAX_CIRCLES_PER_NUT];
    let mut misfit = [0.0; MAX_CIRCLES_PER_NUT];
    for j in 0..n {
        nominal[j] = approach(shares.load_fraction[j] * load_per_ball_n);
        misfit[j] = deviation_m * j as f64 / (n - 1) as f64;
    }
    let load_at = |t: f64, j: usize| {
        let u = (t * nominal[j] + misfit[j]).max(0.0) / approach_per_load;
        u * libm::sqrt(u)
    };
    let carried = |t: f64| (0..n).map(|j| load_at(t, j)).sum::<f64>();
    // At `lo` every circle's approach is <= 0 (nothing carried); at `hi` every circle's is at
    // least its nominal one (at least the nut's load).
    let least = nominal[..n].iter().fold(f64::INFINITY, |m, &a| m.min(a));
    let widest = misfit[..n].iter().fold(0.0_f64, |m, &e| m.max(libm::fabs(e)));
    let (mut lo, mut hi) = (-widest / least, 1.0 + widest / least);
    if !(least > 0.0 && lo.is_finite() && hi.is_finite()) {
        // A load so small that a circle's approach underflows: no share to move.
        return (*shares, 1.0);
    }
    // Until the bracket stops shrinking (at most about 2100 halvings of an f64 bracket).
    for _ in 0..2200 {
        let mid = 0.5 * (lo + hi);
        if !(mid > lo && mid < hi) {
            break;
        }
        if carried(mid) < load_per_ball_n {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let total = carried(hi);
    let mut out = *shares;
    for j in 0..n {
        out.load_fraction[j] = load_at(hi, j) / total;
    }
    (out, hi)
}

/// The two nuts' loads (as [`nut_loads`] with two nuts) where each nut's deflection at load F
/// is `deflection(F)` (m, increasing, 0 at 0): the nuts keep their summed deflection,
/// `deflection(F1) + deflection(F2) = 2 deflection(Fp)` with `F1 - F2 = F_a`, until the light
/// nut lifts off at `deflection(|F_a|) >= 2 deflection(Fp)`. A bisection in the light nut's
/// load, until its bracket stops shrinking.
pub fn nut_loads_by(preload_n: f64, axial_load_n: f64, deflection: &dyn Fn(f64) -> f64) -> [(f64, f64); MAX_NUTS] {
    let fa = libm::fabs(axial_load_n);
    let target = 2.0 * deflection(preload_n);
    let (heavy, light) = if preload_n <= 0.0 || deflection(fa) >= target {
        (fa, 0.0)
    } else if fa == 0.0 {
        (preload_n, preload_n)
    } else {
        let (mut lo, mut hi) = (0.0, preload_n);
        for _ in 0..2200 {
            let mid = 0.5 * (lo + hi);
            if !(mid > lo && mid < hi) {
                break;
            }
            if deflection(mid + fa) + deflection(mid) > target {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        (lo + fa, lo)
    };
    if axial_load_n >= 0.0 { [(heavy, 1.0), (light, -1.0)] } else { [(light, 1.0), (heavy, -1.0)] }
}

#[cfg(test)]
mod tests {

    /// Both nuts keep the same total deflection: (F1)^(2/3) + (F2)^(2/3) = 2 Fp^(2/3) with
    /// F1 - F2 = Fa, for axial loads from none to just below lift-off (2^1.5 Fp), the start
    /// Fp - Fa / 2 of the root search falling inside, on and outside its bracket.
    #[test]
    fn nut_loads_keep_the_deflection_up_to_lift_off() {
        let fp = 2000.0;
        for fa in [0.0, 1.0, 300.0, 2000.0, 3999.0, 4000.0, 4001.0, 5000.0, 5600.0] {
            let [(a, _), (b, _)] = nut_loads(fp, fa, 2);
            let sum = libm::cbrt(a * a) + libm::cbrt(b * b);
            let target = 2.0 * libm::cbrt(fp * fp);
            assert!((sum / target - 1.0).abs() < 1e-12, "Fa {fa}: {a} {b}");
            assert!((a - b - fa).abs() < 1e-9 * fp, "Fa {fa}: {a} - {b}");
        }
    }
    use super::*;

    #[test]
    fn no_axial_load_splits_evenly() {
        let l = nut_loads(2000.0, 0.0, 2);
        assert!((l[0].0 - 2000.0).abs() < 1e-9 && (l[1].0 - 2000.0).abs() < 1e-9);
        assert_eq!((l[0].1, l[1].1), (1.0, -1.0));
    }

    #[test]
    fn hertzian_split_satisfies_compatibility_and_lifts_off() {
        for &fa in &[100.0, 1000.0, 3000.0, 5000.0, -2500.0] {
            let l = nut_loads(2000.0, fa, 2);
            let (f1, f2) = (l[0].0, l[1].0);
            assert!((f1 - f2 - fa).abs() < 1e-9 * 2000.0, "F1 - F2 = Fa for {fa}");
            let c = libm::cbrt(f1 * f1) + libm::cbrt(f2 * f2) - 2.0 * libm::cbrt(2000.0_f64 * 2000.0);
            assert!(c.abs() < 1e-9, "deflection compatibility for {fa}: {c}");
        }
        let l = nut_loads(2000.0, 6000.0, 2);
        assert_eq!(l[1].0, 0.0, "lift-off beyond 2^(3/2) Fp = 5657 N");
        assert_eq!(l[0].0, 6000.0);
    }

    #[test]
    fn geometric_shares_are_normalised_two_thirds() {
        let s = circle_shares(4, LoadDistribution::Geometric);
        let sum: f64 = s.load_fraction.iter().sum();
        assert!((sum - 1.0).abs() < 1e-15);
        assert!((s.load_fraction[1] / s.load_fraction[0] - 2.0 / 3.0).abs() < 1e-15);
        let p = circle_shares(4, LoadDistribution::PaperLiteral);
        assert_eq!(p.load_fraction[3], 0.25);
        assert!((p.weight[3] - 8.0 / 27.0).abs() < 1e-15);
    }

    /// The split by a nut's deflection law: with the Hertzian F^(2/3) it is [`nut_loads`]'s
    /// (to 1e-12 of the preload), lift-off included; both nuts keep their summed deflection.
    #[test]
    fn the_split_by_a_deflection_law_is_the_hertzian_one_for_f_to_the_two_thirds() {
        let hertz = |f: f64| libm::cbrt(f * f);
        for fa in [0.0, 300.0, -2500.0, 4000.0, 5600.0, 6000.0] {
            let a = nut_loads(2000.0, fa, 2);
            let b = nut_loads_by(2000.0, fa, &hertz);
            for k in 0..2 {
                assert!((a[k].0 - b[k].0).abs() <= 1e-12 * 2000.0, "{fa}: {a:?} {b:?}");
                assert_eq!(a[k].1, b[k].1);
            }
        }
    }

    /// A lead deviation moves load between a nut's circles: none gives the nominal shares to
    /// the bit; the shares still sum to 1, none is negative, the spread grows with the
    /// deviation, a positive deviation evens the geometric decline and a negative one steepens
    /// it, and a deviation beyond the approach unloads circles altogether.
    #[test]
    fn a_lead_deviation_moves_load_between_circles() {
        let s = circle_shares(4, LoadDistribution::Geometric);
        // DKFZD4012: 4.4e-7 m / N^(2/3) of axial approach, 105 N of a 2000 N nut per ball.
        let (a, f) = (4.4e-7, 2000.0 / 19.0);
        assert_eq!(shares_with_lead_deviation(&s, 4, f, a, 0.0), s);
        let spread = |d: f64| {
            let x = shares_with_lead_deviation(&s, 4, f, a, d);
            let sum: f64 = x.load_fraction[..4].iter().sum();
            assert!((sum - 1.0).abs() < 1e-12, "{d}: {sum}");
            assert!(x.load_fraction[..4].iter().all(|&l| l >= 0.0), "{d}: {:?}", x.load_fraction);
            assert_eq!(x.weight, s.weight);
            x.load_fraction[0] - x.load_fraction[3]
        };
        let nominal = s.load_fraction[0] - s.load_fraction[3];
        let (down, up) = (spread(1e-6), spread(2e-6));
        assert!(up < down && down < nominal, "{nominal} {down} {up}");
        let (steeper, steepest) = (spread(-1e-6), spread(-2e-6));
        assert!(nominal < steeper && steeper < steepest, "{nominal} {steeper} {steepest}");
        let far = shares_with_lead_deviation(&s, 4, f, a, -1e-4);
        assert_eq!(far.load_fraction[3], 0.0);
        assert!((far.load_fraction[0] - 1.0).abs() < 1e-12);
        // One circle, or no load: nothing to move.
        assert_eq!(shares_with_lead_deviation(&s, 1, f, a, 1e-6), s);
        assert_eq!(shares_with_lead_deviation(&s, 4, 0.0, a, 1e-6), s);
        // A load whose approach underflows: the shares stay finite (the nominal ones).
        let tiny = shares_with_lead_deviation(&s, 4, 1e-200, a, 1e-6);
        assert!(tiny.load_fraction.iter().all(|f| f.is_finite()), "{:?}", tiny.load_fraction);
    }
}
