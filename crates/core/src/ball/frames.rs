//! Coordinate frames: the global frame (x, y, z) with z on the screw axis, the Frenet-Serret
//! frame (t, n, b) at a ball centre (Eq. 1), and the contact frame (e, f, g) at a contact point
//! (Eq. 2).
//!
//! Corrections (docs/model-notes.md items 1, 2): the middle factor of Eq. (1) is Rot(y, 2 pi - alpha)
//! (printed `cos 2(pi - alpha)`); its final matrix is right, with columns t (helix tangent), n
//! (principal normal, pointing at the screw axis) and b (binormal). In Eq. (2) `e` is the rolling
//! direction (along t), `f` is lateral (across the groove) and `g` the contact normal pointing at
//! the ball centre; the nut contact lies on the far side of the ball from the screw contact, on
//! the contact line through the ball centre.

use nalgebra::{Matrix4, Vector3};

/// The Frenet-Serret frame of the ball-centre helix at angle `theta_rad` about the screw axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frenet {
    /// Ball-centre position, m.
    pub origin: Vector3<f64>,
    /// Unit tangent t (direction of increasing theta).
    pub t: Vector3<f64>,
    /// Unit principal normal n (towards the screw axis).
    pub n: Vector3<f64>,
    /// Unit binormal b = t x n.
    pub b: Vector3<f64>,
}

/// The homogeneous transform of Eq. (1): (t, n, b, 1) -> (x, y, z, 1) at angle `theta_rad`,
/// pitch radius `rm_m` and helix angle `alpha_rad`.
#[rustfmt::skip]
pub fn eq1_matrix(theta_rad: f64, rm_m: f64, alpha_rad: f64) -> Matrix4<f64> {
    let (st, ct) = (libm::sin(theta_rad), libm::cos(theta_rad));
    let (sa, ca) = (libm::sin(alpha_rad), libm::cos(alpha_rad));
    Matrix4::new(
        -ca * st, -ct, sa * st, rm_m * ct,
        ca * ct, -st, -sa * ct, rm_m * st,
        sa, 0.0, ca, rm_m * theta_rad * sa / ca,
        0.0, 0.0, 0.0, 1.0,
    )
}

/// Eq. (1) as the product of its three factors, Trans . Rot(z, theta + pi/2) . Rot(y, 2 pi - alpha),
/// with the printed `cos 2(pi - alpha)` read as cos(2 pi - alpha) (docs/model-notes.md item 1).
#[rustfmt::skip]
pub fn eq1_product(theta_rad: f64, rm_m: f64, alpha_rad: f64) -> Matrix4<f64> {
    let tr = Matrix4::new(
        1.0, 0.0, 0.0, rm_m * libm::cos(theta_rad),
        0.0, 1.0, 0.0, rm_m * libm::sin(theta_rad),
        0.0, 0.0, 1.0, rm_m * theta_rad * libm::tan(alpha_rad),
        0.0, 0.0, 0.0, 1.0,
    );
    let phi = theta_rad + core::f64::consts::FRAC_PI_2;
    let (sp, cp) = (libm::sin(phi), libm::cos(phi));
    let rz = Matrix4::new(
        cp, -sp, 0.0, 0.0, //
        sp, cp, 0.0, 0.0, //
        0.0, 0.0, 1.0, 0.0, //
        0.0, 0.0, 0.0, 1.0,
    );
    let psi = 2.0 * core::f64::consts::PI - alpha_rad;
    let (ss, cs) = (libm::sin(psi), libm::cos(psi));
    let ry = Matrix4::new(
        cs, 0.0, ss, 0.0, //
        0.0, 1.0, 0.0, 0.0, //
        -ss, 0.0, cs, 0.0, //
        0.0, 0.0, 0.0, 1.0,
    );
    tr * rz * ry
}

/// The Frenet-Serret frame at `theta_rad` (the columns of Eq. 1).
pub fn frenet(theta_rad: f64, rm_m: f64, alpha_rad: f64) -> Frenet {
    let (st, ct) = (libm::sin(theta_rad), libm::cos(theta_rad));
    let (sa, ca) = (libm::sin(alpha_rad), libm::cos(alpha_rad));
    Frenet {
        origin: Vector3::new(rm_m * ct, rm_m * st, rm_m * theta_rad * sa / ca),
        t: Vector3::new(-ca * st, ca * ct, sa),
        n: Vector3::new(-ct, -st, 0.0),
        b: Vector3::new(sa * st, -sa * ct, ca),
    }
}

/// Rotates a vector about the screw axis z by `angle_rad` (the helical symmetry of a circle of
/// balls maps one ball's vectors onto its neighbour's this way).
pub fn rotate_z(v: &Vector3<f64>, angle_rad: f64) -> Vector3<f64> {
    let (s, c) = (libm::sin(angle_rad), libm::cos(angle_rad));
    Vector3::new(c * v.x - s * v.y, s * v.x + c * v.y, v.z)
}

/// A contact frame (e, f, g): e rolling direction, f lateral, g normal (towards the ball centre).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactFrame {
    /// Rolling direction (unit).
    pub e: Vector3<f64>,
    /// Lateral direction f = g x e (unit).
    pub f: Vector3<f64>,
    /// Normal g, from the contact point towards the ball centre (unit).
    pub g: Vector3<f64>,
}

impl ContactFrame {
    /// Builds the right-handed frame from the rolling direction `e` and the normal `g`
    /// (both unit and orthogonal).
    pub fn new(e: Vector3<f64>, g: Vector3<f64>) -> Self {
        Self { e, f: g.cross(&e), g }
    }
}

/// Eq. (2) as corrected: the homogeneous transform (e, f, g, 1) -> (t, n, b, 1) of the contact
/// at angle `beta_rad` from n towards `flank` * b, at distance `rho_m` from the ball centre.
/// `screw_side = true` gives the ball-screw contact (towards the axis); false the ball-nut contact
/// on the far side of the ball.
#[rustfmt::skip]
pub fn eq2_matrix(beta_rad: f64, rho_m: f64, flank: f64, screw_side: bool) -> Matrix4<f64> {
    let (sb, cb) = (libm::sin(beta_rad), libm::cos(beta_rad));
    // Unit vector from the ball centre to the contact point, in (t, n, b).
    let side = if screw_side { 1.0 } else { -1.0 };
    let u = Vector3::new(0.0, side * cb, side * flank * sb);
    let g = -u;
    let e = Vector3::new(1.0, 0.0, 0.0);
    let f = g.cross(&e);
    Matrix4::new(
        e.x, f.x, g.x, rho_m * u.x,
        e.y, f.y, g.y, rho_m * u.y,
        e.z, f.z, g.z, rho_m * u.z,
        0.0, 0.0, 0.0, 1.0,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use core::f64::consts::PI;

    const RM: f64 = 0.02;
    fn alpha() -> f64 {
        libm::atan(0.012 / (PI * 0.04))
    }

    #[test]
    fn eq1_product_equals_final_matrix() {
        for &th in &[0.0, 0.3, 1.7, 4.0, -2.2] {
            let d = eq1_product(th, RM, alpha()) - eq1_matrix(th, RM, alpha());
            assert!(d.abs().max() < 1e-15, "theta {th}: {d}");
        }
    }

    #[test]
    fn frame_is_orthonormal_right_handed_and_tangent_is_helix_derivative() {
        let a = alpha();
        for &th in &[0.0, 0.7, 2.5, 5.9] {
            let fr = frenet(th, RM, a);
            assert!((fr.t.norm() - 1.0).abs() < 1e-15);
            assert!((fr.n.norm() - 1.0).abs() < 1e-15);
            assert!(fr.t.dot(&fr.n).abs() < 1e-15 && fr.t.dot(&fr.b).abs() < 1e-15);
            assert!((fr.t.cross(&fr.n) - fr.b).norm() < 1e-15, "right-handed");
            // t is the normalised derivative of the helix, n points at the axis.
            let dh = 1e-6;
            let d = (frenet(th + dh, RM, a).origin - frenet(th - dh, RM, a).origin) / (2.0 * dh);
            assert!((d.normalize() - fr.t).norm() < 1e-9);
            let radial = Vector3::new(fr.origin.x, fr.origin.y, 0.0).normalize();
            assert!((fr.n + radial).norm() < 1e-15);
            // Columns of Eq. (1) are t, n, b.
            let m = eq1_matrix(th, RM, a);
            assert!((m.fixed_view::<3, 1>(0, 0) - fr.t).norm() < 1e-15);
            assert!((m.fixed_view::<3, 1>(0, 1) - fr.n).norm() < 1e-15);
            assert!((m.fixed_view::<3, 1>(0, 3) - fr.origin).norm() < 1e-15);
        }
    }

    #[test]
    fn one_turn_advances_by_the_lead() {
        let a = alpha();
        let z0 = frenet(0.0, RM, a).origin;
        let z1 = frenet(2.0 * PI, RM, a).origin;
        assert!((z1.z - z0.z - 0.012).abs() < 1e-15);
        assert!((z1.x - z0.x).abs() < 1e-15 && (z1.y - z0.y).abs() < 1e-15);
    }

    #[test]
    fn eq2_contacts_lie_on_opposite_sides_with_e_along_t() {
        let b = 45.0_f64.to_radians();
        let ms = eq2_matrix(b, 0.003, 1.0, true);
        let mn = eq2_matrix(b, 0.003, 1.0, false);
        // e maps onto t (docs/model-notes.md item 2), g points from the contact to the ball centre.
        assert_eq!(ms.fixed_view::<3, 1>(0, 0).into_owned(), Vector3::new(1.0, 0.0, 0.0));
        let ps = ms.fixed_view::<3, 1>(0, 3).into_owned();
        let pn = mn.fixed_view::<3, 1>(0, 3).into_owned();
        assert!((ps + pn).norm() < 1e-15, "nut contact opposite the screw contact");
        assert!(ps.y > 0.0, "screw contact towards the axis (+n)");
        let gs = ms.fixed_view::<3, 1>(0, 2).into_owned();
        assert!((gs + ps.normalize()).norm() < 1e-15);
        let rot = ms.fixed_view::<3, 3>(0, 0).into_owned();
        assert!((rot.transpose() * rot - nalgebra::Matrix3::identity()).abs().max() < 1e-15);
        assert!((rot.determinant() - 1.0).abs() < 1e-15);
    }
}
