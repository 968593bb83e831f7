//! Geometry of screw, nut and balls (Table 1 of the paper) and the helix quantities that follow
//! from it alone: helix (lead) angle, lead per radian, the angle between touching balls and how
//! many balls fit one turn, the groove-arc offsets.

use core::f64::consts::PI;

// Physical ranges of the spec's values, wide enough for every real ball screw (miniature screws
// of 4 mm shafts to heavy screws of 200 mm); outside them the model is not set up.

/// Pitch diameter, m: [3, 300] mm.
pub const PITCH_DIAMETER_RANGE_M: (f64, f64) = (3.0e-3, 0.3);
/// Lead, m: [0.5, 200] mm.
pub const LEAD_RANGE_M: (f64, f64) = (0.5e-3, 0.2);
/// Ball diameter, m: [0.5, 50] mm (and below half the pitch diameter).
pub const BALL_DIAMETER_RANGE_M: (f64, f64) = (0.5e-3, 50.0e-3);
/// Groove conformity (groove radius / ball diameter): [0.501, 0.6]. Closer to 0.5 the contact
/// ellipse grows without bound and the ball balance stops converging under heavy load
/// (DKFZD4012 with both grooves at 0.5002 fails at a 200 kN preload; at 0.501 it converges to
/// 1 MN).
pub const CONFORMITY_RANGE: (f64, f64) = (0.501, 0.6);
/// Valid nominal contact angle beta, degrees (closed): the span of ball-screw grooves. Gothic-arch
/// and circular-arc ball-screw grooves are made for about 45 degrees and run between about 30
/// and 60 degrees under load; at a few degrees (or near 90) the ball's balance has several
/// solutions and the creep model's rolling ball is no longer the state selected.
pub const CONTACT_ANGLE_RANGE_DEG: (f64, f64) = (20.0, 70.0);

/// How the nut is preloaded: which balls bear on which flank of the grooves.
///
/// - `DoubleNut`: two nuts pressed apart (or together) by a spacer; the balls of one nut bear
///   on one flank, those of the other on the other flank (`nuts = 2`).
/// - `OffsetLead`: one nut whose lead is shifted by a small offset between its two halves: the
///   double nut's physics inside one nut (`nuts = 1`, an even number of circles, half of them
///   in each half).
/// - `OversizeBall`: one nut with balls a few micrometres larger than the groove's gap: each
///   ball touches both flanks of both grooves (four-point contact), two contact diagonals
///   pressed against each other by the interference (`nuts = 1`).
/// - `None`: one nut without preload: the axial load alone presses the balls onto one flank
///   (`nuts = 1`, preload 0).
///
/// In every arrangement the preload `preload_n` is the axial force each flank's set of contacts
/// carries with no external load (for oversize balls: the force the interference produces).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "kebab-case"))]
pub enum Preload {
    /// Two nuts, each on its own flank.
    #[default]
    DoubleNut,
    /// One nut, its halves on opposite flanks by a lead offset.
    OffsetLead,
    /// One nut, four-point contact of oversize balls.
    OversizeBall,
    /// One nut, no preload.
    None,
}

impl Preload {
    /// Every arrangement, in the order of the spec's documentation.
    pub const ALL: [Preload; 4] = [Preload::DoubleNut, Preload::OffsetLead, Preload::OversizeBall, Preload::None];

    /// The name in a spec file: `double-nut`, `offset-lead`, `oversize-ball`, `none`.
    pub fn name(&self) -> &'static str {
        match self {
            Preload::DoubleNut => "double-nut",
            Preload::OffsetLead => "offset-lead",
            Preload::OversizeBall => "oversize-ball",
            Preload::None => "none",
        }
    }

    /// The arrangement named `name` (see [`Preload::name`]).
    pub fn from_name(name: &str) -> Option<Preload> {
        Preload::ALL.into_iter().find(|p| p.name() == name)
    }

    /// The number of nuts the arrangement has: 2 for a double nut, else 1.
    pub fn nuts(&self) -> u32 {
        if *self == Preload::DoubleNut { 2 } else { 1 }
    }

    /// What the arrangement's load group `index` (0 or 1) is, for reports: the nuts of a double
    /// nut, the halves of an offset-lead nut, the contact diagonals of the oversize balls (on
    /// flank +1 and -1), the one nut without preload.
    pub fn group_label(&self, index: usize) -> &'static str {
        match (self, index) {
            (Preload::DoubleNut, 0) => "nut 1",
            (Preload::DoubleNut, _) => "nut 2",
            (Preload::OffsetLead, 0) => "half 1",
            (Preload::OffsetLead, _) => "half 2",
            (Preload::OversizeBall, 0) => "diagonal +",
            (Preload::OversizeBall, _) => "diagonal -",
            (Preload::None, _) => "nut",
        }
    }

    /// The arrangement a spec without one means: a double nut for two nuts, none for one.
    pub fn default_for_nuts(nuts: u32) -> Preload {
        if nuts >= 2 { Preload::DoubleNut } else { Preload::None }
    }
}

/// Geometry of screw, nut and balls (Table 1).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Geometry {
    /// Pitch diameter d_m (ball-centre helix diameter), m: [`PITCH_DIAMETER_RANGE_M`].
    pub pitch_diameter_m: f64,
    /// Lead L (axial advance per screw revolution), m: [`LEAD_RANGE_M`].
    pub lead_m: f64,
    /// Ball diameter D_w, m: [`BALL_DIAMETER_RANGE_M`], below d_m / 2.
    pub ball_diameter_m: f64,
    /// Conformity of the screw groove f_s = groove radius / ball diameter, [0.501, 0.6].
    pub conformity_screw: f64,
    /// Conformity of the nut groove f_N = groove radius / ball diameter, [0.501, 0.6].
    pub conformity_nut: f64,
    /// Nominal contact angle beta (from the radial direction), rad.
    pub contact_angle_rad: f64,
    /// Number of nuts: 2 for a double nut, 1 for every single-nut arrangement.
    pub nuts: u32,
    /// How the nut is preloaded ([`Preload`]).
    pub preload: Preload,
    /// Load-carrying circles (turns) per nut.
    pub circles_per_nut: u32,
    /// Balls per circle.
    pub balls_per_circle: u32,
}

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::screw::ScrewSpec;

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
        assert!(n >= 19, "docs/model-notes.md item 14: about 21 balls fit one turn, got {n}");
        assert!(n <= 22);
    }
}
