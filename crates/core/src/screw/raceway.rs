//! The raceways as the contacts see them: the principal curvatures at the ball-screw and
//! ball-nut contacts (the inputs of the Hertz problem, section 2.3 of the paper) and the radius
//! of the deformed surface across the groove behind Heathcote slip.
//!
//! The grooves are treated as canal surfaces swept along helices: the profile circle (radius
//! f D_w) is one line of curvature, and the curvature along the helix at the contact point is
//! kappa cos(psi) / (1 - kappa rho cos(psi)) with kappa the curvature of the swept arc centre's
//! helix (r / (r^2 + h^2), h = L / 2 pi). With the helix angle set to zero this reduces to the
//! familiar cos(beta) / (r_m -+ r_b cos(beta)) of bearing practice.

use crate::contact::hertz::Curvatures;
use crate::input::geometry::{Geometry, arc_offset_m, lead_per_rad};

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
    use crate::input::ScrewSpec;
    use crate::input::geometry::helix_angle_rad;

    #[test]
    fn curvatures_reduce_to_reference_without_helix() {
        // docs/reference/hertz_point_contact.csv (dkfzd4012 rows) neglects the helix angle:
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
