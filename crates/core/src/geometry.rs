//! Geometry of the screw that the model derives from the spec: helix angle, ball spacing along
//! the helix, groove-arc offsets and the principal curvatures at the ball-screw and ball-nut
//! contacts (the inputs of the Hertz problem, section 2.3 of the paper).
//!
//! The grooves are treated as canal surfaces swept along helices: the profile circle (radius
//! f D_w) is one line of curvature, and the curvature along the helix at the contact point is
//! kappa cos(psi) / (1 - kappa rho cos(psi)) with kappa the curvature of the swept arc centre's
//! helix (r / (r^2 + h^2), h = L / 2 pi). With the helix angle set to zero this reduces to the
//! familiar cos(beta) / (r_m -+ r_b cos(beta)) of bearing practice.

use crate::hertz::Curvatures;
use crate::spec::Geometry;
use core::f64::consts::PI;

/// Helix (lead) angle alpha = atan(L / (pi d_m)), rad.
pub fn helix_angle_rad(g: &Geometry) -> f64 {
    libm::atan(g.lead_m / (PI * g.pitch_diameter_m))
}

/// Lead per radian h = L / (2 pi), m/rad.
pub fn lead_per_rad(g: &Geometry) -> f64 {
    g.lead_m / (2.0 * PI)
}

/// Angle about the screw axis between the centres of two adjacent balls that touch, rad:
/// the root of |c(theta) - c(0)| = D_w for the ball-centre helix c.
pub fn ball_spacing_rad(g: &Geometry) -> f64 {
    let r = 0.5 * g.pitch_diameter_m;
    let h = lead_per_rad(g);
    let d = g.ball_diameter_m;
    // chord^2(theta) = (2 r sin(theta/2))^2 + (h theta)^2 is increasing on (0, pi]; Newton from
    // the arc-length estimate, kept inside the bracket.
    let mut th = d / libm::sqrt(r * r + h * h);
    let (mut lo, mut hi) = (0.0_f64, PI);
    for _ in 0..60 {
        let s = libm::sin(0.5 * th);
        let f = 4.0 * r * r * s * s + h * h * th * th - d * d;
        if f > 0.0 {
            hi = th
        } else {
            lo = th
        }
        let df = 2.0 * r * r * libm::sin(th) + 2.0 * h * h * th;
        let mut next = th - f / df;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if libm::fabs(next - th) <= 1e-15 * th {
            th = next;
            break;
        }
        th = next;
    }
    th
}

/// How many touching balls fit one turn of the helix (the most one circle can hold).
pub fn max_balls_per_circle(g: &Geometry) -> u32 {
    let sane = g.pitch_diameter_m > 0.0
        && g.ball_diameter_m > 0.0
        && g.lead_m > 0.0
        && g.ball_diameter_m < 0.5 * g.pitch_diameter_m
        && g.pitch_diameter_m.is_finite()
        && g.lead_m.is_finite();
    if !sane {
        return 0;
    }
    let n = libm::floor(2.0 * PI / ball_spacing_rad(g) + 1e-9);
    if n > 1.0e6 { 1_000_000 } else { n as u32 }
}

/// Distance between the ball centre and the centre of a groove's profile arc, (f - 1/2) D_w, m.
pub fn arc_offset_m(conformity: f64, ball_diameter_m: f64) -> f64 {
    (conformity - 0.5) * ball_diameter_m
}

/// Which raceway a contact is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Raceway {
    /// The screw (inner, convex along the helix).
    Screw,
    /// The nut (outer, concave along the helix).
    Nut,
}

/// Principal curvatures (1/m) of ball (body 1) and raceway (body 2) at a contact with contact
/// angle `beta_rad`, plane 1 along the helix (rolling), plane 2 across the groove.
pub fn contact_curvatures(g: &Geometry, raceway: Raceway, beta_rad: f64) -> Curvatures {
    let rb = 0.5 * g.ball_diameter_m;
    let rm = 0.5 * g.pitch_diameter_m;
    let h = lead_per_rad(g);
    let (conf, sign) = match raceway {
        Raceway::Screw => (g.conformity_screw, 1.0),
        Raceway::Nut => (g.conformity_nut, -1.0),
    };
    let rg = conf * g.ball_diameter_m;
    let cb = libm::cos(beta_rad);
    // The screw's arc centre lies beyond the ball centre on the nut side (radius r_m + d cos b),
    // the nut's on the screw side (r_m - d cos b).
    let spine_r = rm + sign * arc_offset_m(conf, g.ball_diameter_m) * cb;
    let kappa = spine_r / (spine_r * spine_r + h * h);
    let rho21 = sign * kappa * cb / (1.0 - sign * kappa * rg * cb);
    Curvatures { rho11: 1.0 / rb, rho12: 1.0 / rb, rho21, rho22: -1.0 / rg }
}

/// Radius of the deformed (pressure) surface of a ball in a groove across the groove,
/// 2 r_g r_b / (r_g + r_b) (Harris): the curvature behind Heathcote slip.
pub fn pressure_surface_radius_m(conformity: f64, ball_diameter_m: f64) -> f64 {
    let rb = 0.5 * ball_diameter_m;
    let rg = conformity * ball_diameter_m;
    2.0 * rg * rb / (rg + rb)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec::ScrewSpec;

    #[test]
    fn helix_angle_of_dkfzd4012() {
        let g = ScrewSpec::dkfzd4012().geometry;
        // tan(alpha) = 12 / (40 pi)
        assert!((libm::tan(helix_angle_rad(&g)) - 12.0 / (40.0 * PI)).abs() < 1e-15);
    }

    #[test]
    fn adjacent_balls_touch_and_19_fit_one_turn() {
        let g = ScrewSpec::dkfzd4012().geometry;
        let th = ball_spacing_rad(&g);
        let r = 0.5 * g.pitch_diameter_m;
        let h = lead_per_rad(&g);
        let chord = libm::sqrt((2.0 * r * libm::sin(0.5 * th)).powi(2) + (h * th).powi(2));
        assert!((chord - g.ball_diameter_m).abs() < 1e-15);
        let n = max_balls_per_circle(&g);
        assert!(n >= 19, "MODEL-NOTES item 14: about 21 balls fit one turn, got {n}");
        assert!(n <= 22);
    }

    #[test]
    fn curvatures_reduce_to_reference_without_helix() {
        // reference/hertz_point_contact.csv (dkfzd4012 rows) neglects the helix angle:
        // rho21 = 39.513555 (screw), -31.988974 (nut), rho22 = -323.043327, rho11 = 335.965060.
        let mut g = ScrewSpec::dkfzd4012().geometry;
        g.lead_m = 1e-12;
        let b = 45.0_f64.to_radians();
        let s = contact_curvatures(&g, Raceway::Screw, b);
        let n = contact_curvatures(&g, Raceway::Nut, b);
        assert!((s.rho11 - 335.965060).abs() < 1e-5);
        assert!((s.rho21 - 39.513555).abs() < 1e-5, "{}", s.rho21);
        assert!((n.rho21 + 31.988974).abs() < 1e-5, "{}", n.rho21);
        assert!((s.rho22 + 323.043327).abs() < 1e-5);
        // With the helix (alpha = 5.46 deg) the rolling curvatures fall by about cos^2(alpha).
        let g = ScrewSpec::dkfzd4012().geometry;
        let s = contact_curvatures(&g, Raceway::Screw, b);
        let ca2 = libm::cos(helix_angle_rad(&g)).powi(2);
        assert!((s.rho21 / 39.513555 - ca2).abs() < 2e-3);
    }
}
