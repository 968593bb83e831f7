//! Exact Hertz point contact of two bodies of the same material.
//!
//! The paper (Xu et al. 2015) needs the contact ellipse and the elastic approach at the
//! ball-nut (A), ball-screw (B) and ball-ball (m) contacts: the approaches delta_N, delta_S,
//! delta_m of Eqs. (5), (13) and (19) ("calculated based on Hertz contact theory") and the
//! semi-axes a, b with c0 = sqrt(ab) of Eq. (23). The paper gives no formulas; this module
//! implements the classical exact solution in the Hamrock/Harris formulation (Harris &
//! Kotzalas, *Rolling Bearing Analysis*, ch. 6), with the complete elliptic integrals from
//! [`crate::contact::elliptic`] (no curve fits).
//!
//! Conventions (those of `docs/reference/hertz_point_contact.csv`):
//! - curvatures `rho_ij` (1/m) of body `i` in principal plane `j`; concave surfaces negative;
//! - plane 1 is the rolling plane, plane 2 the lateral plane (across the groove);
//! - curvature sum `sum rho = rho11 + rho12 + rho21 + rho22`, curvature difference
//!   `F(rho) = |(rho11 - rho12) + (rho21 - rho22)| / sum rho`, in `[0, 1)`;
//! - ellipticity `k = a_major / b_minor >= 1`, `m = 1 - 1/k^2`, `K = K(m)`, `E = E(m)`;
//! - `E' = E / (1 - nu^2)` for two bodies of the same material.
//!
//! The ellipticity solves the exact relation `F = ((k^2 + 1) E - 2 K) / ((k^2 - 1) E)`,
//! written here without cancellation as `(1 + F)/(1 - F) = (K - D) / ((1 - m) D)` with
//! `D = (K - E)/m` (the ratio of the larger to the smaller principal curvature sum). Then,
//! with `s = (3 Q / (E' sum rho))^(1/3)`:
//! `a_major = (2 k^2 E / pi)^(1/3) s`, `b_minor = (2 E / (pi k))^(1/3) s`,
//! `delta = (2 K / pi) (pi / (2 k^2 E))^(1/3) s^2 sum rho / 2`, `p0 = 3 Q / (2 pi a b)`.
//!
//! The major axis lies in the plane of the *smaller* curvature sum. For a ball in a conforming
//! groove `rho11 + rho21 > rho12 + rho22`: the ellipse is long across the groove (plane 2), so
//! the semi-axis along the rolling direction is the minor one. [`HertzContact`] therefore
//! reports the rolling and lateral semi-axes, not major and minor.
//!
//! Speed: [`HertzShape::new`] does the root finding once per geometry; [`HertzShape::contact`]
//! then applies the exact Hertz scaling `a_i = c_i Q^(1/3)`, `delta = c_d Q^(2/3)`.

use core::f64::consts::PI;

use crate::contact::elliptic::{complete_ked, complete_ked_mc};
use crate::error::{InputError, check_range};

/// Principal curvatures (1/m) of the two bodies at the contact; concave surfaces negative.
///
/// Plane 1 is the rolling plane, plane 2 the lateral plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Curvatures {
    /// Body 1 (e.g. the ball) in plane 1 (rolling), 1/m.
    pub rho11: f64,
    /// Body 1 in plane 2 (lateral), 1/m.
    pub rho12: f64,
    /// Body 2 (e.g. the raceway) in plane 1 (rolling), 1/m.
    pub rho21: f64,
    /// Body 2 in plane 2 (lateral), 1/m; negative for a groove.
    pub rho22: f64,
}

impl Curvatures {
    /// Curvature sum `rho11 + rho12 + rho21 + rho22`, 1/m.
    pub fn sum(&self) -> f64 {
        self.rho11 + self.rho12 + self.rho21 + self.rho22
    }

    /// Signed curvature difference `((rho11 - rho12) + (rho21 - rho22)) / sum`: positive when
    /// plane 1 is the more curved one (then the major axis is lateral).
    pub fn signed_difference(&self) -> f64 {
        ((self.rho11 - self.rho12) + (self.rho21 - self.rho22)) / self.sum()
    }
}

/// Geometry- and material-dependent part of a Hertz point contact, precomputed once.
///
/// For any normal load `Q`: semi-axes `c_i Q^(1/3)`, approach `c_d Q^(2/3)`,
/// peak pressure `c_p Q^(1/3)` (see [`HertzShape::contact`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzShape {
    ellipticity: f64,
    major_in_plane1: bool,
    k_value: f64,
    e_value: f64,
    curvature_sum: f64,
    effective_modulus: f64,
    coef_major: f64,
    coef_minor: f64,
    coef_approach: f64,
    coef_pressure: f64,
}

/// One Hertz contact at a given load: the contact ellipse, the approach and the peak pressure.
///
/// All zeros for a load `<= 0` (no contact).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HertzContact {
    /// Semi-axis of the contact ellipse along the rolling direction (plane 1), m.
    pub semi_axis_rolling_m: f64,
    /// Semi-axis of the contact ellipse across it (plane 2, lateral), m.
    pub semi_axis_lateral_m: f64,
    /// Elastic approach of the two bodies (sum of both deformations), m.
    pub approach_m: f64,
    /// Peak (central) contact pressure `p0 = 3 Q / (2 pi a b)`, Pa.
    pub peak_pressure_pa: f64,
}

impl HertzContact {
    /// The larger semi-axis, m.
    pub fn semi_major_m(&self) -> f64 {
        self.semi_axis_rolling_m.max(self.semi_axis_lateral_m)
    }

    /// The smaller semi-axis, m.
    pub fn semi_minor_m(&self) -> f64 {
        self.semi_axis_rolling_m.min(self.semi_axis_lateral_m)
    }

    /// Kalker's `a/b`: semi-axis along rolling over the lateral one (0 without contact).
    pub fn rolling_over_lateral(&self) -> f64 {
        if self.semi_axis_lateral_m > 0.0 { self.semi_axis_rolling_m / self.semi_axis_lateral_m } else { 0.0 }
    }
}

/// Cube root of a load, the one transcendental function of [`HertzShape::contact`], which the
/// kinematic solve calls twice per residual: an estimate from the exponent bits refined by
/// Newton's iteration y <- (2 y + x / y^2) / 3 (relative error below 1e-15 after four steps from
/// the estimate's 4 %); `libm::cbrt` outside [1e-100, 1e100], NaN and infinities included.
pub(crate) fn cbrt(x: f64) -> f64 {
    if !(1e-100..=1e100).contains(&x) {
        return libm::cbrt(x);
    }
    let mut y = f64::from_bits(x.to_bits() / 3 + 0x2a9f_7893_782d_a1ce);
    for _ in 0..4 {
        y = (2.0 * y + x / (y * y)) * (1.0 / 3.0);
    }
    y
}

/// Largest ellipticity the solver looks for; `F(rho)` would then be `1 - 1e-13` or so.
const MAX_LN_ELLIPTICITY: f64 = 25.0;
/// Iteration cap of the bracketed root search (it takes about 10).
const MAX_ITER: usize = 200;

impl HertzShape {
    /// Solves the Hertz ellipse of curvatures `c` for two bodies of the same material.
    ///
    /// # Errors
    /// An [`InputError`] naming the first invalid input: curvature sum not finite or `<= 0` (`hertz.curvature_sum_per_m`), one principal
    /// curvature sum `<= 0` so that the bodies do not touch at a point
    /// (`hertz.curvature_difference`, valid `[0, 1)`), `E` not finite and `> 0`
    /// (`material.youngs_modulus_pa`), `nu` outside `[0, 0.5]` (`material.poisson_ratio`).
    pub fn new(c: &Curvatures, youngs_modulus_pa: f64, poisson_ratio: f64) -> Result<Self, InputError> {
        let sum = c.sum();
        check_range("hertz.curvature_sum_per_m", sum, 0.0, true, f64::INFINITY, true, "finite and > 0")?;
        let plane1 = c.rho11 + c.rho21;
        let plane2 = c.rho12 + c.rho22;
        let f = libm::fabs(plane1 - plane2) / sum;
        check_range(
            "hertz.curvature_difference",
            f,
            0.0,
            false,
            1.0,
            true,
            "[0, 1): both principal curvature sums > 0",
        )?;
        check_range("material.youngs_modulus_pa", youngs_modulus_pa, 0.0, true, f64::INFINITY, true, "finite and > 0")?;
        check_range("material.poisson_ratio", poisson_ratio, 0.0, false, 0.5, false, "[0, 0.5]")?;
        // Both plane sums must be positive as numbers too (f < 1 implies it up to rounding).
        if !(plane1 > 0.0 && plane2 > 0.0) {
            return Err(InputError {
                field: "hertz.curvature_difference",
                value: f,
                valid: "[0, 1): both principal curvature sums > 0",
            });
        }
        let effective_modulus = youngs_modulus_pa / (1.0 - poisson_ratio * poisson_ratio);
        let ratio = plane1.max(plane2) / plane1.min(plane2);
        let ln_k = solve_ln_ellipticity(ratio);
        let k = libm::exp(ln_k);
        let (k_int, e_int, _) = elliptic_of_ln_k(ln_k);
        // s = (3 Q / (E' sum))^(1/3) = s1 Q^(1/3)
        let s1 = libm::cbrt(3.0 / (effective_modulus * sum));
        let coef_major = libm::cbrt(2.0 * k * k * e_int / PI) * s1;
        let coef_minor = libm::cbrt(2.0 * e_int / (PI * k)) * s1;
        let coef_approach = (2.0 * k_int / PI) * libm::cbrt(PI / (2.0 * k * k * e_int)) * s1 * s1 * 0.5 * sum;
        let coef_pressure = 3.0 / (2.0 * PI * coef_major * coef_minor);
        Ok(Self {
            ellipticity: k,
            major_in_plane1: plane1 < plane2,
            k_value: k_int,
            e_value: e_int,
            curvature_sum: sum,
            effective_modulus,
            coef_major,
            coef_minor,
            coef_approach,
            coef_pressure,
        })
    }

    /// The contact at normal load `load_n` (N); a load `<= 0` or NaN gives all zeros.
    pub fn contact(&self, load_n: f64) -> HertzContact {
        if load_n.is_nan() || load_n <= 0.0 {
            return HertzContact::default();
        }
        self.contact_at_cube_root(cbrt(load_n))
    }

    /// The contact at a positive load whose cube root is `load_cube_root` (N^(1/3)):
    /// [`HertzShape::contact`] where contacts of one load share the root.
    pub fn contact_at_cube_root(&self, load_cube_root: f64) -> HertzContact {
        let q13 = load_cube_root;
        let major = self.coef_major * q13;
        let minor = self.coef_minor * q13;
        let (rolling, lateral) = if self.major_in_plane1 { (major, minor) } else { (minor, major) };
        HertzContact {
            semi_axis_rolling_m: rolling,
            semi_axis_lateral_m: lateral,
            approach_m: self.coef_approach * q13 * q13,
            peak_pressure_pa: self.coef_pressure * q13,
        }
    }

    /// Normal load (N) that gives the approach `approach_m` (m): the inverse of the
    /// `delta = c_d Q^(2/3)` law. Zero for an approach `<= 0` or NaN.
    pub fn load_for_approach(&self, approach_m: f64) -> f64 {
        if approach_m.is_nan() || approach_m <= 0.0 {
            return 0.0;
        }
        let r = approach_m / self.coef_approach;
        r * libm::sqrt(r)
    }

    /// Contact stiffness `dQ/d delta = (3/2) Q^(1/3) / c_d` (N/m) at load `load_n`.
    pub fn stiffness(&self, load_n: f64) -> f64 {
        if load_n.is_nan() || load_n <= 0.0 {
            return 0.0;
        }
        1.5 * libm::cbrt(load_n) / self.coef_approach
    }

    /// Ellipticity `k = a_major / b_minor >= 1` (1 for a circle).
    pub fn ellipticity(&self) -> f64 {
        self.ellipticity
    }

    /// True when the major axis lies in plane 1 (rolling direction); false for a ball in a
    /// conforming groove, whose ellipse is long across the groove. False for a circle.
    pub fn major_axis_in_plane1(&self) -> bool {
        self.major_in_plane1
    }

    /// Complete elliptic integral of the first kind `K(m)` of the ellipse, `m = 1 - 1/k^2`.
    pub fn complete_k_value(&self) -> f64 {
        self.k_value
    }

    /// Complete elliptic integral of the second kind `E(m)` of the ellipse, `m = 1 - 1/k^2`
    /// (e.g. for the full-slip spin moment arm `(3/8) b_major E(m)`).
    pub fn complete_e_value(&self) -> f64 {
        self.e_value
    }

    /// Curvature sum `sum rho` (1/m).
    pub fn curvature_sum_per_m(&self) -> f64 {
        self.curvature_sum
    }

    /// Effective modulus `E' = E / (1 - nu^2)` (Pa).
    pub fn effective_modulus_pa(&self) -> f64 {
        self.effective_modulus
    }

    /// Kalker's `a/b` (rolling semi-axis over lateral semi-axis): independent of the load.
    pub fn rolling_over_lateral(&self) -> f64 {
        if self.major_in_plane1 { self.ellipticity } else { 1.0 / self.ellipticity }
    }
}

/// `(K, E, D)` at ellipticity `k = exp(ln_k)`, from the complementary parameter
/// `1 - m = 1/k^2 = exp(-2 ln_k)` so that slender ellipses keep their digits.
fn elliptic_of_ln_k(ln_k: f64) -> (f64, f64, f64) {
    if ln_k < 0.35 {
        // m = 1 - exp(-2 ln_k) without cancellation near the circle.
        complete_ked(-libm::expm1(-2.0 * ln_k))
    } else {
        complete_ked_mc(libm::exp(-2.0 * ln_k))
    }
}

/// `ln` of the ratio of the larger to the smaller principal curvature sum that the ellipse of
/// ellipticity `exp(ln_k)` belongs to: `ln((K - D) / ((1 - m) D))`. Increasing, 0 at 0.
fn ln_curvature_ratio(ln_k: f64) -> f64 {
    let (k, _, d) = elliptic_of_ln_k(ln_k);
    let mc = libm::exp(-2.0 * ln_k);
    libm::log((k - d) / (mc * d))
}

/// Solves `ln_curvature_ratio(u) = ln(ratio)` for `u = ln k` (ratio >= 1) by a bracketed
/// secant (Illinois) search. Monotone, so the bracket `[0, hi]` always holds the root.
fn solve_ln_ellipticity(ratio: f64) -> f64 {
    let target = libm::log(ratio);
    if target.is_nan() || target <= 0.0 {
        return 0.0;
    }
    let g = |u: f64| ln_curvature_ratio(u) - target;
    // Hamrock & Brewe's fit k = 1.0339 ratio^0.636 as the first upper guess.
    let mut lo = 0.0_f64;
    let mut g_lo = -target;
    let mut hi = (libm::log(1.0339) + 0.636 * target + 0.1).min(MAX_LN_ELLIPTICITY);
    let mut g_hi = g(hi);
    while g_hi < 0.0 && hi < MAX_LN_ELLIPTICITY {
        lo = hi;
        g_lo = g_hi;
        hi = (2.0 * hi).min(MAX_LN_ELLIPTICITY);
        g_hi = g(hi);
    }
    if g_hi <= 0.0 {
        return hi;
    }
    let mut side = 0_i8;
    for _ in 0..MAX_ITER {
        let u = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
        let u = if u > lo && u < hi { u } else { 0.5 * (lo + hi) };
        let g_u = g(u);
        if g_u == 0.0 || hi - lo <= 4.0 * f64::EPSILON * hi {
            return u;
        }
        if g_u < 0.0 {
            lo = u;
            g_lo = g_u;
            if side == -1 {
                g_hi *= 0.5;
            }
            side = -1;
        } else {
            hi = u;
            g_hi = g_u;
            if side == 1 {
                g_lo *= 0.5;
            }
            side = 1;
        }
        if libm::fabs(g_u) <= 1e-15 * target.max(1.0) {
            return u;
        }
    }
    0.5 * (lo + hi)
}

/// Closed-form Hertz contact of two spheres of the same material (e.g. ball on ball).
///
/// Radii in m (a concave sphere negative, as long as `1/r1 + 1/r2 > 0`), load in N. The contact
/// is a circle of radius `a = (3 Q R / (4 E*))^(1/3)` with `1/R = 1/r1 + 1/r2` and
/// `1/E* = 2 (1 - nu^2) / E`; approach `a^2 / R`; `p0 = 3 Q / (2 pi a^2)`. All zeros for a load
/// `<= 0` or invalid inputs (non-positive or non-finite `1/R`, `E` not finite and `> 0`,
/// `nu` outside `[0, 0.5]`); validate the spec first to report those.
pub fn sphere_on_sphere(
    radius1_m: f64,
    radius2_m: f64,
    load_n: f64,
    youngs_modulus_pa: f64,
    poisson_ratio: f64,
) -> HertzContact {
    let inv_r = 1.0 / radius1_m + 1.0 / radius2_m;
    let valid = inv_r > 0.0
        && inv_r.is_finite()
        && youngs_modulus_pa > 0.0
        && youngs_modulus_pa.is_finite()
        && (0.0..=0.5).contains(&poisson_ratio)
        && load_n > 0.0;
    if !valid {
        return HertzContact::default();
    }
    let r = 1.0 / inv_r;
    let e_star = youngs_modulus_pa / (2.0 * (1.0 - poisson_ratio * poisson_ratio));
    let a = libm::cbrt(3.0 * load_n * r / (4.0 * e_star));
    HertzContact {
        semi_axis_rolling_m: a,
        semi_axis_lateral_m: a,
        approach_m: a * a / r,
        peak_pressure_pa: 3.0 * load_n / (2.0 * PI * a * a),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_root_agrees_with_libm() {
        let mut x = 1e-120_f64;
        while x < 1e120 {
            for m in [1.0, 1.37, 2.0, 3.1, 5.5, 7.999] {
                let v = x * m;
                let (a, b) = (cbrt(v), libm::cbrt(v));
                assert!(((a - b) / b).abs() <= 4e-16, "{v}: {a} vs {b}");
            }
            x *= 10.0;
        }
        assert_eq!(cbrt(0.0), 0.0);
        assert!(cbrt(f64::NAN).is_nan());
        assert_eq!(cbrt(f64::INFINITY), f64::INFINITY);
    }

    fn rel(a: f64, b: f64) -> f64 {
        libm::fabs(a - b) / libm::fabs(b)
    }

    /// One row of `docs/reference/hertz_point_contact.csv`: inputs, then semi-major (mm),
    /// semi-minor (mm), approach (um) and p0 (MPa) as computed there (exact elliptic integrals).
    struct Row {
        case: &'static str,
        rho: [f64; 4],
        load_n: f64,
        e_pa: f64,
        nu: f64,
        major_mm: f64,
        minor_mm: f64,
        approach_um: f64,
        p0_mpa: f64,
    }

    // docs/reference/hertz_point_contact.csv, rows 1-8 (header excluded), numbers copied verbatim.
    const ROWS: [Row; 8] = [
        Row {
            case: "harris_209_inner",
            rho: [157.480315, 157.480315, 38.248874, -151.423380],
            load_n: 1000.0,
            e_pa: 2.08e11,
            nu: 0.3,
            major_mm: 1.53753,
            minor_mm: 0.165590,
            approach_um: 9.8427,
            p0_mpa: 1875.4,
        },
        Row {
            case: "harris_209_outer",
            rho: [157.480315, 157.480315, -25.738424, -151.423380],
            load_n: 1000.0,
            e_pa: 2.08e11,
            nu: 0.3,
            major_mm: 1.49101,
            minor_mm: 0.204383,
            approach_um: 9.4842,
            p0_mpa: 1566.8,
        },
        Row {
            case: "dkfzd4012_screw_Fp500",
            rho: [335.965060, 335.965060, 39.513555, -323.043327],
            load_n: 9.3464,
            e_pa: 2.1e11,
            nu: 0.3,
            major_mm: 0.24879,
            minor_mm: 0.028577,
            approach_um: 0.5532,
            p0_mpa: 627.7,
        },
        Row {
            case: "dkfzd4012_nut_Fp500",
            rho: [335.965060, 335.965060, -31.988974, -323.043327],
            load_n: 9.3464,
            e_pa: 2.1e11,
            nu: 0.3,
            major_mm: 0.24473,
            minor_mm: 0.031974,
            approach_um: 0.5424,
            p0_mpa: 570.3,
        },
        Row {
            case: "dkfzd4012_screw_Fp2000",
            rho: [335.965060, 335.965060, 39.513555, -323.043327],
            load_n: 37.3854,
            e_pa: 2.1e11,
            nu: 0.3,
            major_mm: 0.39493,
            minor_mm: 0.045363,
            approach_um: 1.3940,
            p0_mpa: 996.4,
        },
        Row {
            case: "dkfzd4012_nut_Fp2000",
            rho: [335.965060, 335.965060, -31.988974, -323.043327],
            load_n: 37.3854,
            e_pa: 2.1e11,
            nu: 0.3,
            major_mm: 0.38849,
            minor_mm: 0.050756,
            approach_um: 1.3667,
            p0_mpa: 905.3,
        },
        Row {
            case: "dkfzd4012_screw_Fp3000",
            rho: [335.965060, 335.965060, 39.513555, -323.043327],
            load_n: 56.0782,
            e_pa: 2.1e11,
            nu: 0.3,
            major_mm: 0.45208,
            minor_mm: 0.051928,
            approach_um: 1.8267,
            p0_mpa: 1140.5,
        },
        Row {
            case: "dkfzd4012_nut_Fp3000",
            rho: [335.965060, 335.965060, -31.988974, -323.043327],
            load_n: 56.0782,
            e_pa: 2.1e11,
            nu: 0.3,
            major_mm: 0.44471,
            minor_mm: 0.058101,
            approach_um: 1.7908,
            p0_mpa: 1036.3,
        },
    ];

    fn curv(r: &Row) -> Curvatures {
        Curvatures { rho11: r.rho[0], rho12: r.rho[1], rho21: r.rho[2], rho22: r.rho[3] }
    }

    #[test]
    fn reference_csv_rows_within_0_1_percent() {
        for r in &ROWS {
            let shape = HertzShape::new(&curv(r), r.e_pa, r.nu).unwrap();
            let c = shape.contact(r.load_n);
            let tol = 1e-3;
            assert!(rel(c.semi_major_m() * 1e3, r.major_mm) < tol, "{}: major {}", r.case, c.semi_major_m());
            assert!(rel(c.semi_minor_m() * 1e3, r.minor_mm) < tol, "{}: minor {}", r.case, c.semi_minor_m());
            assert!(rel(c.approach_m * 1e6, r.approach_um) < tol, "{}: approach {}", r.case, c.approach_m);
            assert!(rel(c.peak_pressure_pa * 1e-6, r.p0_mpa) < tol, "{}: p0 {}", r.case, c.peak_pressure_pa);
            // Ball in a groove: plane 1 is the more curved, so the ellipse is long laterally.
            assert!(!shape.major_axis_in_plane1(), "{}", r.case);
            assert_eq!(c.semi_axis_lateral_m, c.semi_major_m());
            assert_eq!(c.semi_axis_rolling_m, c.semi_minor_m());
            // Load balance: the Hertz pressure integrates to Q.
            let q = 2.0 * PI / 3.0 * c.peak_pressure_pa * c.semi_axis_rolling_m * c.semi_axis_lateral_m;
            assert!(rel(q, r.load_n) < 1e-12);
        }
    }

    #[test]
    fn dkfzd4012_rolling_over_lateral_is_about_0_11_to_0_13() {
        // docs/model-notes.md item 4: a/b (rolling/lateral) is about 0.11-0.13 for DKFZD4012.
        for r in &ROWS[2..] {
            let shape = HertzShape::new(&curv(r), r.e_pa, r.nu).unwrap();
            let ab = shape.rolling_over_lateral();
            assert!((0.10..0.14).contains(&ab), "{}: a/b = {ab}", r.case);
            assert!(rel(ab, shape.contact(r.load_n).rolling_over_lateral()) < 1e-14);
        }
    }

    #[test]
    fn ellipticity_satisfies_the_exact_relation() {
        // F = ((k^2 + 1) E - 2 K) / ((k^2 - 1) E), evaluated directly at the solved k.
        for &(p1, p2) in &[(400.0, 12.0), (100.0, 99.0), (1000.0, 1.0), (3.0, 2.0), (2.0, 3.0)] {
            let c = Curvatures { rho11: p1 / 2.0, rho12: p2 / 2.0, rho21: p1 / 2.0, rho22: p2 / 2.0 };
            let shape = HertzShape::new(&c, 2e11, 0.3).unwrap();
            let k = shape.ellipticity();
            let (kk, ee) = (shape.complete_k_value(), shape.complete_e_value());
            let f = ((k * k + 1.0) * ee - 2.0 * kk) / ((k * k - 1.0) * ee);
            let f_given = libm::fabs(p1 - p2) / (p1 + p2);
            assert!(libm::fabs(f - f_given) < 1e-12, "F {f} vs {f_given}");
            assert_eq!(shape.major_axis_in_plane1(), p1 < p2);
        }
    }

    #[test]
    fn equal_curvatures_give_the_closed_form_sphere_contact() {
        // Ball on ball: D = 6.35 mm balls, F = 0 in the general code.
        let rb = 3.175e-3;
        let c = Curvatures { rho11: 1.0 / rb, rho12: 1.0 / rb, rho21: 1.0 / rb, rho22: 1.0 / rb };
        let shape = HertzShape::new(&c, 2.1e11, 0.3).unwrap();
        assert_eq!(shape.ellipticity(), 1.0);
        assert!(!shape.major_axis_in_plane1());
        for &q in &[0.1, 10.0, 1000.0] {
            let g = shape.contact(q);
            let s = sphere_on_sphere(rb, rb, q, 2.1e11, 0.3);
            assert!(rel(g.semi_axis_rolling_m, s.semi_axis_rolling_m) < 1e-14);
            assert!(rel(g.semi_axis_lateral_m, s.semi_axis_lateral_m) < 1e-14);
            assert!(rel(g.approach_m, s.approach_m) < 1e-14);
            assert!(rel(g.peak_pressure_pa, s.peak_pressure_pa) < 1e-14);
        }
        // Sphere in a spherical seat (concave, larger radius): 1/R = 1/r1 - 1/r2.
        let seat = Curvatures { rho11: 1.0 / rb, rho12: 1.0 / rb, rho21: -1.0 / 4e-3, rho22: -1.0 / 4e-3 };
        let g = HertzShape::new(&seat, 2.1e11, 0.3).unwrap().contact(50.0);
        let s = sphere_on_sphere(rb, -4e-3, 50.0, 2.1e11, 0.3);
        assert!(rel(g.semi_major_m(), s.semi_major_m()) < 1e-14);
        assert!(rel(g.approach_m, s.approach_m) < 1e-14);
    }

    #[test]
    fn nearly_circular_contact_is_continuous() {
        let rb = 3.175e-3;
        let circle =
            HertzShape::new(&Curvatures { rho11: 1.0 / rb, rho12: 1.0 / rb, rho21: 0.0, rho22: 0.0 }, 2.1e11, 0.3)
                .unwrap()
                .contact(10.0);
        let near =
            HertzShape::new(&Curvatures { rho11: 1.0 / rb, rho12: 1.0 / rb, rho21: 1e-6, rho22: 0.0 }, 2.1e11, 0.3)
                .unwrap();
        assert!(near.ellipticity() > 1.0 && near.ellipticity() < 1.0 + 1e-8);
        let c = near.contact(10.0);
        assert!(rel(c.semi_major_m(), circle.semi_major_m()) < 1e-8);
        assert!(rel(c.approach_m, circle.approach_m) < 1e-8);
    }

    #[test]
    fn semi_axes_scale_with_cube_root_of_load() {
        let r = &ROWS[4];
        let shape = HertzShape::new(&curv(r), r.e_pa, r.nu).unwrap();
        let c1 = shape.contact(10.0);
        let c8 = shape.contact(80.0);
        assert!(rel(c8.semi_axis_rolling_m, 2.0 * c1.semi_axis_rolling_m) < 1e-14);
        assert!(rel(c8.semi_axis_lateral_m, 2.0 * c1.semi_axis_lateral_m) < 1e-14);
        assert!(rel(c8.approach_m, 4.0 * c1.approach_m) < 1e-14);
        assert!(rel(c8.peak_pressure_pa, 2.0 * c1.peak_pressure_pa) < 1e-14);
        // Inverse law and stiffness (finite difference).
        assert!(rel(shape.load_for_approach(c8.approach_m), 80.0) < 1e-13);
        let h = 1e-4;
        let fd = (shape.contact(80.0 + h).approach_m - shape.contact(80.0 - h).approach_m) / (2.0 * h);
        assert!(rel(shape.stiffness(80.0), 1.0 / fd) < 1e-6);
    }

    #[test]
    fn no_load_gives_zeros() {
        let shape = HertzShape::new(&curv(&ROWS[0]), 2.08e11, 0.3).unwrap();
        assert_eq!(shape.contact(0.0), HertzContact::default());
        assert_eq!(shape.contact(-5.0), HertzContact::default());
        assert_eq!(shape.contact(f64::NAN), HertzContact::default());
        assert_eq!(shape.load_for_approach(-1e-6), 0.0);
        assert_eq!(sphere_on_sphere(1e-3, 1e-3, 0.0, 2e11, 0.3), HertzContact::default());
        assert_eq!(sphere_on_sphere(1e-3, -1e-3, 1.0, 2e11, 0.3), HertzContact::default());
        assert_eq!(HertzContact::default().rolling_over_lateral(), 0.0);
    }

    #[test]
    fn invalid_inputs_are_named() {
        let ok = curv(&ROWS[0]);
        let err = |c: &Curvatures, e: f64, nu: f64| HertzShape::new(c, e, nu).unwrap_err().field;
        let neg = Curvatures { rho11: -1.0, rho12: -1.0, rho21: 0.5, rho22: 0.5 };
        assert_eq!(err(&neg, 2e11, 0.3), "hertz.curvature_sum_per_m");
        let nan = Curvatures { rho11: f64::NAN, ..ok };
        assert_eq!(err(&nan, 2e11, 0.3), "hertz.curvature_sum_per_m");
        // A saddle that does not close in plane 2: rho12 + rho22 < 0.
        let open = Curvatures { rho11: 100.0, rho12: 100.0, rho21: 0.0, rho22: -150.0 };
        assert_eq!(err(&open, 2e11, 0.3), "hertz.curvature_difference");
        // Cylinder on a plane along its axis: line contact, F = 1.
        let line = Curvatures { rho11: 100.0, rho12: 0.0, rho21: 0.0, rho22: 0.0 };
        assert_eq!(err(&line, 2e11, 0.3), "hertz.curvature_difference");
        assert_eq!(err(&ok, 0.0, 0.3), "material.youngs_modulus_pa");
        assert_eq!(err(&ok, f64::INFINITY, 0.3), "material.youngs_modulus_pa");
        assert_eq!(err(&ok, 2e11, 0.6), "material.poisson_ratio");
        assert_eq!(err(&ok, 2e11, -0.1), "material.poisson_ratio");
    }

    #[test]
    fn very_slender_ellipse_stays_finite() {
        // F = 1 - 1e-9: k of a few thousand.
        let c = Curvatures { rho11: 1.0, rho12: 1e-9 * 0.5, rho21: 0.0, rho22: 0.0 };
        let shape = HertzShape::new(&c, 2e11, 0.3).unwrap();
        let k = shape.ellipticity();
        assert!(k > 1e3 && k.is_finite(), "k = {k}");
        let contact = shape.contact(1.0);
        assert!(contact.approach_m.is_finite() && contact.approach_m > 0.0);
        assert!(contact.peak_pressure_pa.is_finite() && contact.peak_pressure_pa > 0.0);
    }
}
