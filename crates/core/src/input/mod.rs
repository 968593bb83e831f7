//! What the user describes, in SI units, and its validation: the ground floor every layer above
//! reads.
//!
//! - [`geometry`]: screw, nut and balls (Table 1) and the helix quantities that follow from them;
//! - [`screw`]: the whole [`ScrewSpec`]: geometry, material, friction, a default operating point,
//!   the model options and the extensions;
//! - [`operating`]: an [`OperatingPoint`] (speed, preload, axial load);
//! - [`options`]: the [`ModelOptions`], every reading of the paper the model can take;
//! - [`circulation`]: how the balls circulate (the return, the turns of a circuit, the load ramp,
//!   the return path's resistance);
//! - [`extensions`]: terms beyond the paper's physics (seals, lubricant, waviness, wear), off by
//!   default;
//! - [`lubricant`]: the oil at the raceway contacts, the surfaces' roughness and the parameters of
//!   the lubricated contact laws (read by [`crate::contact::ehl`]);
//! - [`uncertainty`]: the inputs nobody measures on a given screw, each with its spread (the
//!   spec's `[uncertainty]`), which the model does not read: a band of predictions samples them.
//!
//! The names of the files below are re-exported here; inside this folder each file names the
//! sibling it takes from.

pub mod circulation;
pub mod extensions;
pub mod geometry;
pub mod lubricant;
pub mod operating;
pub mod options;
pub mod screw;
pub mod uncertainty;

pub use circulation::{Circulation, Return};
pub use extensions::{Conditions, Extensions};
pub use geometry::{
    BALL_DIAMETER_RANGE_M, CONFORMITY_RANGE, CONTACT_ANGLE_RANGE_DEG, Geometry, LEAD_RANGE_M, PITCH_DIAMETER_RANGE_M,
    Preload,
};
pub use lubricant::{Lubricant, OilState};
pub use operating::{MAX_SPEED_RAD_S, OperatingPoint, rad_s_to_rpm, rpm_to_rad_s};
pub use options::{
    ContactTheory, CreepCoefficientSource, DEFAULT_FASTSIM_GRID, LoadDistribution, Lubrication, ModelOptions,
    SpinMoment, TorqueRoute,
};
pub use screw::{
    Friction, MAX_BALL_BALL_LOAD_N, MAX_CIRCLES_PER_NUT, MAX_NUTS, MAX_SEAL_TORQUE_NM, MAX_STANDSTILL_SPEED_RAD_S,
    Material, ScrewSpec, YOUNGS_MODULUS_RANGE_PA, shear_modulus_pa,
};
pub use uncertainty::{INPUTS, SpreadError, UNCERTAIN_INPUTS, UncertainInput, Uncertainty};
