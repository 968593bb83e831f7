//! Contact mechanics of one contact, whatever bodies it joins: the layer every other one stands on
//! for forces.
//!
//! - [`elliptic`], [`hertz`]: exact Hertz point contact (complete elliptic integrals by AGM);
//! - [`creep`]: creepages with spin and Heathcote slip from one vector computation (Eqs. 3-22);
//! - [`kalker`]: Kalker's linear creep coefficients C11, C22, C23, C33 (Eq. 23);
//! - [`saturation`]: the Shen-Hedrick-Elkins saturation into Coulomb friction (Eq. 24);
//! - [`forces`]: creep force and spin moment of a contact, linear and saturated;
//! - [`patch`]: one contact as data: its Hertz ellipse, load, material and friction, and its
//!   creepages FASTSIM's way (centre-line xi, the Heathcote field apart);
//! - [`fastsim`]: Kalker's simplified theory solved on a grid over the ellipse (FASTSIM);
//! - [`presliding`]: friction re-forming after a reversal of rolling: the simplified theory
//!   stepped in rolling distance, its initial slope, and Dahl's first-order element;
//! - [`ehl`]: the lubricated contact: elastohydrodynamic film, film parameter, mixed friction
//!   and rolling resistance (pure functions, not yet in the ball's balance);
//! - [`presliding`]: friction re-forming after a reversal: a contact's rate of change in
//!   adhesion and Dahl's first-order law;
//! - [`analysis`]: one contact analysed alone: its forces by FASTSIM and by the model's law
//!   (Kalker's linear theory saturated by Eq. 24), and the points of the creep curves (Fig. 9);
//! - [`limits`]: the ranges of a contact given by hand (the command line's flags, Python's
//!   arguments).
//!
//! It uses the spec's option enums ([`crate::input::options`]) and the material's range
//! ([`crate::input::YOUNGS_MODULUS_RANGE_PA`]), and nothing above it.

pub mod analysis;
pub mod creep;
pub mod ehl;
pub mod elliptic;
pub mod fastsim;
pub mod forces;
pub mod hertz;
pub mod kalker;
pub mod limits;
pub mod patch;
pub mod presliding;
pub mod saturation;
