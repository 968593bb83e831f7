//! The operating point of the screw (speed, preload, axial load), its validation and the rpm
//! conversions of the file format and the command line.

use crate::error::{InputError, check_range};
use core::f64::consts::PI;

/// An operating point of the screw.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OperatingPoint {
    /// Screw angular speed omega, rad/s; the sign is the direction of rotation.
    pub speed_rad_s: f64,
    /// Preload F_p, N (>= 0): the axial force each flank's set of contacts carries without
    /// external load, in every arrangement ([`crate::input::geometry::Preload`]); 0 for a nut
    /// without preload.
    pub preload_n: f64,
    /// External axial load on the nut F_a, N: positive when it opposes the nut's travel under
    /// positive rotation (it then adds `F_a L / (2 pi)` to the drive torque).
    pub axial_load_n: f64,
}

/// Converts rpm to rad/s.
pub fn rpm_to_rad_s(rpm: f64) -> f64 {
    rpm * 2.0 * PI / 60.0
}

/// Converts rad/s to rpm.
pub fn rad_s_to_rpm(rad_s: f64) -> f64 {
    rad_s * 60.0 / (2.0 * PI)
}

/// Largest screw speed accepted, rad/s (30,000 rpm).
pub const MAX_SPEED_RAD_S: f64 = 30_000.0 * 2.0 * PI / 60.0;

impl OperatingPoint {
    /// Checks the operating point alone.
    pub fn validate(&self) -> Result<(), InputError> {
        check_range(
            "speed_rad_s",
            self.speed_rad_s,
            -MAX_SPEED_RAD_S,
            false,
            MAX_SPEED_RAD_S,
            false,
            "finite, |speed| <= 30000 rpm",
        )?;
        check_range("preload_n", self.preload_n, 0.0, false, 1.0e7, false, "finite, [0, 1e7] N")?;
        check_range("axial_load_n", self.axial_load_n, -1.0e7, false, 1.0e7, false, "finite, [-1e7, 1e7] N")?;
        Ok(())
    }
}
