//! One contact patch as data: its Hertz ellipse, normal load, material and friction
//! ([`Contact`]) and the creepages of the ball over the other body, FASTSIM's way ([`Creep`]).
//!
//! What is known of a contact before any law is chosen: FASTSIM takes the two together
//! ([`crate::contact::fastsim::FastsimInput`]), and a contact analysed alone is made of them
//! ([`crate::contact::analysis`], where their methods are). SI units; nothing here computes.

/// One contact: Hertz ellipse, normal load, material and friction (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// Semi-axis a along the rolling direction e, m (finite, > 0).
    pub semi_axis_rolling_m: f64,
    /// Semi-axis b across the rolling direction (lateral), m (finite, > 0).
    pub semi_axis_lateral_m: f64,
    /// Normal load Q, N (finite, >= 0).
    pub normal_load_n: f64,
    /// Shear modulus G, Pa (finite, > 0).
    pub shear_modulus_pa: f64,
    /// Poisson's ratio, in `[0, 0.5]`.
    pub poisson_ratio: f64,
    /// Coefficient of friction mu (finite, >= 0).
    pub friction_coefficient: f64,
}

/// Creepages of the ball over the other body, FASTSIM's way: `xi` on the centre line and the
/// Heathcote field `k_h y^2` apart.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Creep {
    /// Longitudinal creepage at `y = 0`.
    pub xi: f64,
    /// Lateral creepage.
    pub eta: f64,
    /// Spin creepage, 1/m.
    pub phi_per_m: f64,
    /// Heathcote coefficient k_h, 1/m^2: longitudinal creepage `k_h y^2` at the lateral
    /// coordinate y.
    pub heathcote_per_m2: f64,
}
