//! Friction re-forming after a reversal of rolling (presliding), contact by contact: the rate at
//! which a contact's tractions change when every element is in adhesion, and Dahl's first-order
//! friction law that the screw-level state model uses.
//!
//! In Kalker's simplified theory (J.J. Kalker, Three-dimensional elastic bodies in rolling
//! contact, Kluwer 1990, ch. 3 and 5) each element of the contact area carries a traction
//! `p = (u_x / L1, u_y / L2)` from its elastic displacement `u`; while it adheres, `u` changes
//! by the rigid slip `w` per unit rolling distance (FASTSIM's field with the spin scaled by the
//! flexibilities, [`crate::contact::fastsim`]). The work of the tractions on the physical rigid
//! slip `s = (xi + k_h y^2 - phi y, eta + phi x)`, `P = -integral p . s dA` (N: the dissipated
//! power over the rolling speed in steady rolling), therefore changes at the rate
//! `K = integral (w_x s_x / L1 + w_y s_y / L2) dA` per unit rolling distance after a reversal,
//! until elements reach their friction bound. Over the ellipse (`integral x^2 dA = pi a^3 b / 4`,
//! `integral y^2 dA = pi a b^3 / 4`, `integral y^4 dA = pi a b^5 / 8`, odd moments zero):
//!
//! `K = pi a b [ (xi^2 + xi k_h b^2 / 2 + k_h^2 b^4 / 8) / L1 + eta^2 / L2 + phi^2 (a^2 + b^2) / (4 L3) ]`.
//!
//! Dahl's law (P.R. Dahl, "A solid friction model", Aerospace Corp. TOR-0158, 1968):
//! `dz/ds = sigma (1 - z sign(ds) / g)`, integrated exactly for a step at constant bound `g`.

use crate::contact::fastsim::{FastsimInput, Flexibilities};
use crate::error::InputError;
use crate::real::Real;
use core::f64::consts::PI;

/// The rate `K` (N per metre of rolling) at which the contact's work measure `P` changes after a
/// reversal while every element adheres (the module's closed form, Kalker's flexibilities).
///
/// # Errors
/// An [`InputError`] naming the first invalid field of `input` (as [`crate::contact::fastsim::fastsim`]).
pub fn reversal_slope(input: &FastsimInput) -> Result<f64, InputError> {
    crate::contact::fastsim::validate_contact(input)?;
    let (a, b) = (input.semi_axis_rolling_m, input.semi_axis_lateral_m);
    let l = Flexibilities::kalker(a, b, input.shear_modulus_pa, input.poisson_ratio);
    let (xi, eta, phi, k) = (input.xi, input.eta, input.phi_per_m, input.heathcote_per_m2);
    let b2 = b * b;
    let longitudinal = (xi * xi + xi * k * b2 / 2.0 + k * k * b2 * b2 / 8.0) / l.l1_m_per_pa;
    let lateral = eta * eta / l.l2_m_per_pa;
    let spin = phi * phi * (a * a + b2) / (4.0 * l.l3_m_per_pa);
    Ok(PI * a * b * (longitudinal + lateral + spin))
}

/// One step of Dahl's law: the state `z` after a displacement `ds` (signed) at bound `bound`
/// (>= 0) and stiffness `stiffness` (state per unit displacement): `z_ss + (z - z_ss)
/// exp(-stiffness |ds| / bound)` with `z_ss = sign(ds) bound`; a bound of 0 gives 0, a step of
/// 0 leaves `z`.
pub fn dahl_step<F: Real>(z: F, bound: F, stiffness: F, ds: F) -> F {
    if ds == F::zero() {
        return z;
    }
    if !(bound > F::zero()) {
        return F::zero();
    }
    let target = if ds > F::zero() { bound } else { -bound };
    target + (z - target) * (-(stiffness * ds.abs() / bound)).exp()
}
