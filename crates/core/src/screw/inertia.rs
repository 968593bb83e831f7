//! Where the quasi-static model holds: the ball's inertia forces it leaves out, against the
//! contact loads it balances.
//!
//! Every ball is balanced without inertia (Xu et al. 2015, Section 2: the ball's forces and
//! moments sum to zero), as in the quasi-static analyses of ball bearings below their speed
//! limits. At speed the orbiting ball is pressed outward by the centrifugal force
//! `F_c = m_b r_m Omega_c^2` (Harris and Kotzalas, Rolling Bearing Analysis, 5th ed., Vol. 2,
//! Ch. 2: `F_c = 1/2 m D_m omega_m^2`) with the ball's mass `m_b = rho pi D_w^3 / 6`, the pitch
//! radius `r_m` and the orbit rate `Omega_c = omega (1 - D_w cos(beta) / d_m) / 2` of the rolling
//! ball, and its spin about an axis inclined to the orbit's asks for the gyroscopic moment
//! `M_g = J omega_R Omega_c sin(beta)`, `J = m_b D_w^2 / 10` (same chapter; the rolling axis is
//! square to the contact line, so inclined to the screw's axis by the contact angle beta). Where they are a small share of
//! what the contacts carry (`F_c` against the normal load, `M_g` against the moment of the
//! friction `mu Q D_w`), the quasi-static balance stands; where not, the two contacts' loads and
//! angles part and the ball's spin changes: the model's torque is then an extrapolation, which
//! the shells warn about ([`INERTIA_WARNING_SHARE`]) with the one text of [`InertiaWarning`]
//! ([`check`] finds it over the points of a call).

use crate::error::Short;
use crate::input::ScrewSpec;
use crate::input::operating::OperatingPoint;
use crate::screw::load;
use core::fmt;

/// Density of the balls, kg/m^3: through-hardened bearing steel 100Cr6 (SAE 52100), 7.81e3 kg/m^3
/// (ISO 683-17 material data; Harris and Kotzalas use 7.8e3). The spec has no density: the balls
/// of ball screws are of this steel.
pub const BALL_DENSITY_KG_M3: f64 = 7.81e3;

/// Share of the contact load (or of the friction moment) above which an inertia effect the
/// model leaves out is no longer small: a quarter. Both shares grow as the square of the speed;
/// DKFZD4012 at 500 N of preload reaches it at about 4,650 rpm (the gyroscopic share; 10 % at
/// 3000 rpm), a d_m n of about 186,000 mm rpm, beyond the 50,000 to 150,000 mm rpm that
/// manufacturers' catalogs allow ball screws: the warning marks points far outside the range
/// the quasi-static model is made for, not the edge of it.
pub const INERTIA_WARNING_SHARE: f64 = 0.25;

/// The inertia the model leaves out at an operating point, for its most loaded ball.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inertia {
    /// The ball's centrifugal force, N.
    pub centrifugal_force_n: f64,
    /// Its gyroscopic moment (spin at the rolling ball's rate), N m.
    pub gyroscopic_moment_nm: f64,
    /// The most loaded ball's nominal normal load, N (0 when no ball is loaded).
    pub normal_load_n: f64,
    /// `centrifugal_force_n / normal_load_n` (infinite for an unloaded screw turning).
    pub centrifugal_share: f64,
    /// `gyroscopic_moment_nm` over the friction moment `mu Q D_w` of that ball (the spec's
    /// friction coefficient).
    pub gyroscopic_share: f64,
}

impl Inertia {
    /// Whether either share is above [`INERTIA_WARNING_SHARE`].
    pub fn beyond_quasi_static(&self) -> bool {
        self.centrifugal_share > INERTIA_WARNING_SHARE || self.gyroscopic_share > INERTIA_WARNING_SHARE
    }
}

/// The inertia of the most loaded ball of `spec` at `op` (see the module).
pub fn inertia(spec: &ScrewSpec, helix_angle_rad: f64, op: &OperatingPoint) -> Inertia {
    let q = heaviest_normal_load_n(spec, helix_angle_rad, op);
    inertia_at_load(spec, helix_angle_rad, op, q)
}

/// The most loaded ball's nominal normal load at `op`, N (its speed does not enter), from the
/// load distribution's nominal shares: a stated lead deviation, which moves load between the
/// circles, is not in this threshold's estimate (docs/model-notes.md, "The lead deviation"),
/// nor a load ramp, which loads a circle's full balls more (up to 27 % on DKFZD4012 with 4
/// balls): the estimate's load is then low, and its shares high, on the side of warning.
fn heaviest_normal_load_n(spec: &ScrewSpec, helix_angle_rad: f64, op: &OperatingPoint) -> f64 {
    let g = &spec.geometry;
    let groups = load::groups(g, op.preload_n, op.axial_load_n);
    let shares = load::circle_shares(groups.circles, spec.model.load_distribution);
    let p_max = load::heaviest_ball_load_n(
        &groups.loads,
        groups.count,
        &shares,
        groups.circles as usize,
        f64::from(g.balls_per_circle),
    );
    p_max / (libm::sin(g.contact_angle_rad) * libm::cos(helix_angle_rad))
}

/// [`inertia`] with the most loaded ball's normal load `q` (N) known.
fn inertia_at_load(spec: &ScrewSpec, helix_angle_rad: f64, op: &OperatingPoint, q: f64) -> Inertia {
    let g = &spec.geometry;
    let d = g.ball_diameter_m;
    let mass = BALL_DENSITY_KG_M3 * core::f64::consts::PI * d * d * d / 6.0;
    let beta = g.contact_angle_rad;
    let orbit = 0.5 * (1.0 - d * libm::cos(beta) / g.pitch_diameter_m) * libm::fabs(op.speed_rad_s);
    let rm = 0.5 * g.pitch_diameter_m;
    let centrifugal = mass * rm * orbit * orbit;
    // The rolling ball's spin: its surface rolls on the screw at the orbit's relative speed.
    let spin = orbit * rm / (0.5 * d * libm::cos(helix_angle_rad));
    let gyroscopic = mass * d * d / 10.0 * spin * orbit * libm::sin(beta);
    let share = |x: f64, of: f64| {
        if x == 0.0 {
            0.0
        } else if of > 0.0 {
            x / of
        } else {
            f64::INFINITY
        }
    };
    Inertia {
        centrifugal_force_n: centrifugal,
        gyroscopic_moment_nm: gyroscopic,
        normal_load_n: q,
        centrifugal_share: share(centrifugal, q),
        gyroscopic_share: share(gyroscopic, spec.friction.coefficient * q * d),
    }
}

/// What the shells warn about when the balls' inertia is not small at some of the points of a
/// call: the worst of them and how many. Its text (`Display`) is the one warning the command
/// line prints after `warning: ` and Python's `ballscrew.QuasiStaticWarning` says.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InertiaWarning {
    /// The point of the largest share (see [`Inertia`]).
    pub point: OperatingPoint,
    /// The inertia there.
    pub inertia: Inertia,
    /// How many of the points are beyond the quasi-static model ([`Inertia::beyond_quasi_static`]).
    pub beyond: usize,
    /// How many points were checked.
    pub total: usize,
}

/// The [`InertiaWarning`] over `ops` (the operating points of one call), or `None` when the
/// quasi-static model holds at every one of them. `helix_angle_rad` is the model's
/// (`Model::helix_angle_rad`).
pub fn check(
    spec: &ScrewSpec,
    helix_angle_rad: f64,
    ops: impl IntoIterator<Item = OperatingPoint>,
) -> Option<InertiaWarning> {
    let larger = |j: &Inertia| j.centrifugal_share.max(j.gyroscopic_share);
    let mut worst: Option<(OperatingPoint, Inertia)> = None;
    let (mut beyond, mut total) = (0, 0);
    // The ball load of the point before, by its (preload, axial load): points of a grid or a
    // sweep over the speed share it, and it is most of the work (about 0.2 us a point).
    let mut last: Option<(f64, f64, f64)> = None;
    for op in ops {
        total += 1;
        let q = match last {
            Some((p, a, q)) if p == op.preload_n && a == op.axial_load_n => q,
            _ => heaviest_normal_load_n(spec, helix_angle_rad, &op),
        };
        last = Some((op.preload_n, op.axial_load_n, q));
        let i = inertia_at_load(spec, helix_angle_rad, &op, q);
        if i.beyond_quasi_static() {
            beyond += 1;
            if worst.as_ref().is_none_or(|(_, w)| larger(&i) > larger(w)) {
                worst = Some((op, i));
            }
        }
    }
    worst.map(|(point, inertia)| InertiaWarning { point, inertia, beyond, total })
}

impl fmt::Display for InertiaWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.total > 1 {
            write!(f, "at {} of {} points, the worst ", self.beyond, self.total)?;
        }
        let i = &self.inertia;
        if !(i.normal_load_n > 0.0) {
            // No share to state: nothing but the left-out inertia presses the balls.
            return write!(
                f,
                "at {}: no ball carries a load, so only the balls' centrifugal force ({} N), which the \
                 quasi-static model leaves out, presses them on the raceways: the torque there is an extrapolation",
                self.point,
                Short(i.centrifugal_force_n)
            );
        }
        write!(
            f,
            "at {}: the most loaded ball's gyroscopic moment is {} of its friction moment and its centrifugal \
             force {} of its {} N contact load, above the {:.0} % within which the quasi-static model (which \
             leaves both out) holds: the torque there is an extrapolation",
            self.point,
            Percent(i.gyroscopic_share, 0),
            Percent(i.centrifugal_share, 1),
            Short(i.normal_load_n),
            100.0 * INERTIA_WARNING_SHARE
        )
    }
}

/// A share as a percentage with `.1` decimals below a million per cent (`260 %`, `54.9 %`), in
/// three digits above (`1.20e10 %`, not 300 digits); a share without bound (of a friction moment of
/// 0: a friction coefficient of 0) in words, not `inf %`.
struct Percent(f64, usize);

impl fmt::Display for Percent {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (p, decimals) = (100.0 * self.0, self.1);
        if !p.is_finite() {
            f.write_str("without bound")
        } else if libm::fabs(p) < 1e6 {
            write!(f, "{p:.decimals$} %")
        } else {
            write!(f, "{p:.2e} %")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::rpm_to_rad_s;

    /// DKFZD4012 (the spec's ball, pitch diameter and contact angle), by hand: m_b = rho pi D^3 / 6,
    /// F_c = m_b r_m Omega_c^2 with Omega_c = omega (1 - D cos(beta) / d_m) / 2.
    #[test]
    fn centrifugal_force_by_hand() {
        let spec = ScrewSpec::dkfzd4012();
        let g = &spec.geometry;
        let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(-3000.0), preload_n: 2000.0, axial_load_n: 0.0 };
        let alpha = libm::atan(g.lead_m / (core::f64::consts::PI * g.pitch_diameter_m));
        let i = inertia(&spec, alpha, &op);
        let d = g.ball_diameter_m;
        let m = 7810.0 * core::f64::consts::PI * d.powi(3) / 6.0;
        let w = 314.159_265_358_979_3 * 0.5 * (1.0 - d * g.contact_angle_rad.cos() / g.pitch_diameter_m);
        let fc = m * 0.5 * g.pitch_diameter_m * w * w;
        assert!((i.centrifugal_force_n - fc).abs() < 1e-9 * fc, "{} vs {fc}", i.centrifugal_force_n);
        // Grows as the square of the speed; none at standstill.
        let half = inertia(&spec, alpha, &OperatingPoint { speed_rad_s: op.speed_rad_s / 2.0, ..op });
        assert!((4.0 * half.centrifugal_force_n - i.centrifugal_force_n).abs() < 1e-12);
        let still = inertia(&spec, alpha, &OperatingPoint { speed_rad_s: 0.0, ..op });
        assert_eq!((still.centrifugal_share, still.gyroscopic_share), (0.0, 0.0));
        assert!(!still.beyond_quasi_static());
        // An unloaded screw turning: no load to compare with.
        let free = inertia(&spec, alpha, &OperatingPoint { preload_n: 0.0, ..op });
        assert!(free.centrifugal_share.is_infinite() && free.beyond_quasi_static());
    }

    /// Where the warning starts on DKFZD4012: printed for the record of the guide's numbers.
    #[test]
    fn shares_on_dkfzd4012() {
        let spec = ScrewSpec::dkfzd4012();
        let g = &spec.geometry;
        let alpha = libm::atan(g.lead_m / (core::f64::consts::PI * g.pitch_diameter_m));
        for (rpm, preload) in [(3000.0, 500.0), (3000.0, 2000.0), (1000.0, 500.0), (6000.0, 500.0)] {
            let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: preload, axial_load_n: 0.0 };
            let i = inertia(&spec, alpha, &op);
            std::println!(
                "{rpm} rpm {preload} N: F_c {:.3} N, Q {:.1} N, share {:.4}; M_g {:.3e} N m, share {:.4}",
                i.centrifugal_force_n,
                i.normal_load_n,
                i.centrifugal_share,
                i.gyroscopic_moment_nm,
                i.gyroscopic_share
            );
        }
        // The catalog's range (to 3000 rpm, from 500 N) is quasi-static; 4650 rpm at 500 N is
        // where the gyroscopic share reaches a quarter.
        let at = |rpm: f64, preload_n: f64| {
            inertia(&spec, alpha, &OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n, axial_load_n: 0.0 })
        };
        assert!(!at(3000.0, 500.0).beyond_quasi_static() && !at(-3000.0, 2000.0).beyond_quasi_static());
        assert!(at(4600.0, 500.0).gyroscopic_share < 0.25 && at(4700.0, 500.0).gyroscopic_share > 0.25);
        assert!(at(6000.0, 500.0).beyond_quasi_static());
    }

    /// The warning's text over the points of a call: the worst point, how many, the shares; the
    /// unloaded screw's own wording; none where the model holds.
    #[test]
    fn warning_text() {
        let spec = ScrewSpec::dkfzd4012();
        let g = &spec.geometry;
        let alpha = libm::atan(g.lead_m / (core::f64::consts::PI * g.pitch_diameter_m));
        let at =
            |rpm: f64, preload_n: f64| OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n, axial_load_n: 0.0 };
        assert_eq!(check(&spec, alpha, [at(100.0, 2000.0), at(-3000.0, 500.0)]), None);
        let one = check(&spec, alpha, [at(6000.0, 500.0)]).map(|w| std::format!("{w}")).unwrap_or_default();
        assert!(
            one.starts_with(
                "at speed 6000 rpm, preload 500 N, axial load 0 N: the most loaded ball's gyroscopic moment is 42 %"
            ),
            "{one}"
        );
        assert!(one.ends_with("above the 25 % within which the quasi-static model (which leaves both out) holds: the torque there is an extrapolation"), "{one}");
        let w = check(&spec, alpha, [at(1000.0, 500.0), at(-6000.0, 500.0), at(5000.0, 500.0)]).expect("beyond");
        assert_eq!((w.beyond, w.total, w.point), (2, 3, at(-6000.0, 500.0)));
        let many = std::format!("{w}");
        assert!(many.starts_with("at 2 of 3 points, the worst at speed -6000 rpm, preload 500 N"), "{many}");
        // Shares a friction coefficient near or at 0 makes huge: short, no "inf %".
        assert_eq!(
            std::format!("{} and {}", Percent(1e298, 0), Percent(f64::INFINITY, 1)),
            "1.00e300 % and without bound"
        );
        assert_eq!(std::format!("{} and {}", Percent(2.6, 0), Percent(0.549, 1)), "260 % and 54.9 %");
        let free = check(&spec, alpha, [at(2000.0, 0.0)]).map(|w| std::format!("{w}")).unwrap_or_default();
        assert!(free.starts_with("at speed 2000 rpm, preload 0 N, axial load 0 N: no ball carries a load"), "{free}");
    }
}
