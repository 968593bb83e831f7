//! The operating point of the screw (speed, preload, axial load), its validation and the rpm
//! conversions of the file format and the command line.

use crate::error::{InputError, Short, check_range};
use core::f64::consts::PI;
use core::fmt;

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

/// `speed 100 rpm, preload 2000 N, axial load 0 N`: the point as messages name it (the speed
/// in rpm as [`rad_s_to_rpm`] gives it, numbers as [`Short`] writes them).
impl fmt::Display for OperatingPoint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "speed {} rpm, preload {} N, axial load {} N",
            Short(rad_s_to_rpm(self.speed_rad_s)),
            Short(self.preload_n),
            Short(self.axial_load_n)
        )
    }
}

/// Converts rpm to rad/s.
pub fn rpm_to_rad_s(rpm: f64) -> f64 {
    rpm * 2.0 * PI / 60.0
}

/// Converts rad/s to rpm: the decimal rpm of fewest significant digits that [`rpm_to_rad_s`]
/// turns into `rad_s` exactly, so that a speed given in rpm reads back as given (1000 rpm, not
/// the 999.9999999999999 of the plain quotient); the plain quotient when no decimal of up to 16
/// digits does (a speed that did not come from rpm), or for 0 and non-finite values.
pub fn rad_s_to_rpm(rad_s: f64) -> f64 {
    let raw = rad_s * 60.0 / (2.0 * PI);
    if raw == 0.0 || !raw.is_finite() {
        return raw;
    }
    let magnitude = libm::floor(libm::log10(libm::fabs(raw))) as i32;
    for digits in 1..=16 {
        // Rounded to `digits` significant digits by an exact power of ten (10^e is exact in f64
        // up to e = 22; beyond, the plain quotient is kept).
        let e = digits - 1 - magnitude;
        if !(-22..=22).contains(&e) {
            break;
        }
        let scale = libm::pow(10.0, f64::from(e.abs()));
        let r = if e >= 0 { libm::round(raw * scale) / scale } else { libm::round(raw / scale) * scale };
        if rpm_to_rad_s(r) == rad_s {
            return r;
        }
    }
    raw
}

/// Largest screw speed accepted, rad/s (30,000 rpm).
pub const MAX_SPEED_RAD_S: f64 = 30_000.0 * 2.0 * PI / 60.0;
/// Valid preloads, N: [0, 1e7].
pub const PRELOAD_RANGE_N: (f64, f64) = (0.0, 1.0e7);
/// Valid external axial loads, N: [-1e7, 1e7].
pub const AXIAL_LOAD_RANGE_N: (f64, f64) = (-1.0e7, 1.0e7);

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
        let (lo, hi) = PRELOAD_RANGE_N;
        check_range("preload_n", self.preload_n, lo, false, hi, false, "finite, [0, 1e7] N")?;
        let (lo, hi) = AXIAL_LOAD_RANGE_N;
        check_range("axial_load_n", self.axial_load_n, lo, false, hi, false, "finite, [-1e7, 1e7] N")?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A speed given in rpm reads back as given: over 20,000 values with 0 to 3 decimals in
    /// +-30,000 rpm (the plain quotient `w 60 / (2 pi)` misses about 16 % of them, e.g. 1000 rpm
    /// as 999.9999999999999), and at the values of the report (1000, -250, 100).
    #[test]
    fn rpm_reads_back_as_given() {
        let mut x = 0x2545_f491_4f6c_dd1du64;
        let mut plain_misses = 0;
        for k in 0..20_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let decimals = [1.0, 10.0, 100.0, 1000.0][k % 4];
            let rpm = libm::round(((x >> 11) as f64 / (1u64 << 53) as f64 * 60_000.0 - 30_000.0) * decimals) / decimals;
            let w = rpm_to_rad_s(rpm);
            assert_eq!(rad_s_to_rpm(w), rpm, "{rpm} rpm");
            if w * 60.0 / (2.0 * PI) != rpm {
                plain_misses += 1;
            }
        }
        assert!(plain_misses > 1000, "the test exercises the rounding: {plain_misses}");
        for rpm in [1000.0, -250.0, 100.0, 3000.0, 0.01, 1e-9, 29_999.999] {
            assert_eq!(rad_s_to_rpm(rpm_to_rad_s(rpm)), rpm);
        }
    }

    /// Any speed converts to the rpm whose rad/s is that speed (to the last bit when a decimal
    /// of up to 16 digits gives it, else within 1e-15 relative); 0, -0, infinities and NaN as the
    /// plain quotient.
    #[test]
    fn any_speed_converts_within_rounding() {
        for w in [1.0, -0.1234567890123, 314.159, 1e-300, 1e300, f64::MIN_POSITIVE, 12345.678901234567] {
            let r = rad_s_to_rpm(w);
            assert!((rpm_to_rad_s(r) - w).abs() <= 1e-15 * w.abs(), "{w}: {r}");
            assert!((r - w * 60.0 / (2.0 * PI)).abs() <= 1e-15 * r.abs(), "{w}: {r}");
        }
        assert_eq!(rad_s_to_rpm(0.0), 0.0);
        assert!(rad_s_to_rpm(-0.0).is_sign_negative());
        assert_eq!(rad_s_to_rpm(f64::INFINITY), f64::INFINITY);
        assert!(rad_s_to_rpm(f64::NAN).is_nan());
    }
}
