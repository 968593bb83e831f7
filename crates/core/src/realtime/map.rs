//! Torque map for firmware: the model's torque tabulated over preload and screw speed, looked up
//! by bilinear interpolation in a borrowed slice of `f32` (no_std, no allocation, no panics).
//!
//! Layout. A [`MapGrid`] has `preload_points` uniformly spaced preloads and `speed_points`
//! uniformly spaced speed *magnitudes*; the values slice holds, in this order:
//! - the standstill row: the torque at zero speed for each preload (`preload_points` values;
//!   with no axial load this is 0, with one it is the load's lead torque F_a L / (2 pi));
//! - the forward sheet: the *running* torque at positive speeds, row by preload
//!   (`preload_points x speed_points`, index `p * speed_points + s`);
//! - the reverse sheet: the same at negative speeds.
//!
//! The running torque of a node is the model's torque at that speed, or at the standstill speed
//! omega0 (with the node's direction) where the node's magnitude lies below it. Reversal and
//! standstill (docs/model-notes.md item 13) are handled as the model handles them: the lookup blends
//! from the standstill row to the direction's sheet with the model's own standstill factor
//! s = x (2 - x), x = |omega| / omega0 (1 above omega0), so the map is continuous through zero
//! speed (both sides meet the standstill row) and C1 at omega0, and never leaves the range of
//! its tabulated values. The torque does not depend on the speed's magnitude above omega0
//! (docs/model-notes.md item 12), so few speed points suffice unless speed-dependent terms are added.
//!
//! Outside the grid the lookup clamps: a preload or speed magnitude beyond the grid takes the
//! value at the nearest edge. A NaN or infinite input gives NaN.
//!
//! [`tabulate`] (with the `std` feature) builds a map from a [`Model`](crate::Model) and states
//! its largest interpolation error against the model, checked at the midpoint of every grid
//! cell in both directions and in the middle of the standstill band.

use crate::error::InputError;

/// The grid of a torque map (SI units; `f32`, the precision a firmware map is stored in).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapGrid {
    /// First preload of the grid, N.
    pub preload_min_n: f32,
    /// Spacing of the preloads, N (> 0).
    pub preload_step_n: f32,
    /// Number of preloads (>= 2).
    pub preload_points: u32,
    /// Smallest speed magnitude of the grid, rad/s (>= 0).
    pub speed_min_rad_s: f32,
    /// Spacing of the speed magnitudes, rad/s (> 0).
    pub speed_step_rad_s: f32,
    /// Number of speed magnitudes (>= 2).
    pub speed_points: u32,
    /// Standstill speed omega0 of the model, rad/s (> 0): below it the lookup blends to the
    /// standstill row.
    pub standstill_speed_rad_s: f32,
}

/// Most grid points along one axis.
pub const MAX_AXIS_POINTS: u32 = 10_000;

fn check(field: &'static str, value: f32, ok: bool, valid: &'static str) -> Result<(), InputError> {
    if ok { Ok(()) } else { Err(InputError { field, value: f64::from(value), valid }) }
}

impl MapGrid {
    /// The grid with `preload_points` preloads from `preload_min_n` to `preload_max_n` (N) and
    /// `speed_points` speed magnitudes from `speed_min_rad_s` to `speed_max_rad_s` (rad/s), with
    /// the model's standstill speed (rad/s). Not validated: see [`MapGrid::validate`].
    pub fn spanning(
        (preload_min_n, preload_max_n, preload_points): (f64, f64, u32),
        (speed_min_rad_s, speed_max_rad_s, speed_points): (f64, f64, u32),
        standstill_speed_rad_s: f64,
    ) -> Self {
        let step = |lo: f64, hi: f64, n: u32| (hi - lo) / f64::from(n.max(2) - 1);
        Self {
            preload_min_n: preload_min_n as f32,
            preload_step_n: step(preload_min_n, preload_max_n, preload_points) as f32,
            preload_points,
            speed_min_rad_s: speed_min_rad_s as f32,
            speed_step_rad_s: step(speed_min_rad_s, speed_max_rad_s, speed_points) as f32,
            speed_points,
            standstill_speed_rad_s: standstill_speed_rad_s as f32,
        }
    }

    /// Number of values a map on this grid holds: `preload_points * (1 + 2 * speed_points)`.
    pub const fn len(&self) -> usize {
        self.preload_points as usize * (1 + 2 * self.speed_points as usize)
    }

    /// Always false for a valid grid (it has at least 2 x 2 points).
    pub const fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Last preload of the grid, N.
    pub fn preload_max_n(&self) -> f32 {
        self.preload_min_n + self.preload_step_n * (self.preload_points.max(1) - 1) as f32
    }

    /// Largest speed magnitude of the grid, rad/s.
    pub fn speed_max_rad_s(&self) -> f32 {
        self.speed_min_rad_s + self.speed_step_rad_s * (self.speed_points.max(1) - 1) as f32
    }

    /// Checks every field; the error names the field, the value and the valid range.
    pub fn validate(&self) -> Result<(), InputError> {
        let count = |n: u32| (2..=MAX_AXIS_POINTS).contains(&n);
        check("map.preload_points", self.preload_points as f32, count(self.preload_points), "integer in [2, 10000]")?;
        check("map.speed_points", self.speed_points as f32, count(self.speed_points), "integer in [2, 10000]")?;
        let v = self.preload_min_n;
        check("map.preload_min_n", v, v.is_finite() && v >= 0.0, "finite and >= 0 N")?;
        let v = self.preload_step_n;
        check("map.preload_step_n", v, v.is_finite() && v > 0.0, "finite and > 0 N")?;
        let v = self.speed_min_rad_s;
        check("map.speed_min_rad_s", v, v.is_finite() && v >= 0.0, "finite and >= 0 rad/s")?;
        let v = self.speed_step_rad_s;
        check("map.speed_step_rad_s", v, v.is_finite() && v > 0.0, "finite and > 0 rad/s")?;
        let v = self.standstill_speed_rad_s;
        check("map.standstill_speed_rad_s", v, v.is_finite() && v > 0.0, "finite and > 0 rad/s")?;
        let (p, s) = (self.preload_max_n(), self.speed_max_rad_s());
        check("map.preload_max_n", p, p.is_finite(), "finite")?;
        check("map.speed_max_rad_s", s, s.is_finite(), "finite")
    }
}

/// A torque map: a grid and the values it borrows (see the module docs for the layout).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TorqueMap<'a> {
    grid: MapGrid,
    values: &'a [f32],
    /// 1 / preload step, 1 / speed step, 1 / standstill speed (multiplications are cheaper
    /// than divisions in the lookup).
    inverse: [f32; 3],
}

/// Cell index and fraction of `x` on the axis `min + k / inverse_step`, `k = 0..points`,
/// clamped to the axis without branches; a NaN or infinite `x` gives a NaN fraction.
#[inline]
#[allow(clippy::eq_op)] // `u - u` is deliberate: it carries NaN and infinities into the result.
fn locate(x: f32, min: f32, inverse_step: f32, points: u32) -> (usize, f32) {
    let u = (x - min) * inverse_step;
    // f32::max and f32::min return the number when the other operand is NaN.
    let clamped = u.max(0.0).min((points - 1) as f32);
    let cell = (clamped as u32).min(points - 2);
    // `u - u` is 0 for a finite u and NaN otherwise.
    (cell as usize, clamped - cell as f32 + (u - u))
}

/// The standstill factor of the map, `x (2 - x)` below 1 (docs/model-notes.md item 13), in `f32`.
#[inline]
fn standstill_factor(speed_magnitude: f32, inverse_standstill_speed: f32) -> f32 {
    let x = speed_magnitude * inverse_standstill_speed;
    if x < 1.0 { x * (2.0 - x) } else { 1.0 }
}

impl<'a> TorqueMap<'a> {
    /// A map over `grid` borrowing `values`; checks the grid, the length and that every value
    /// is finite.
    pub fn new(grid: MapGrid, values: &'a [f32]) -> Result<Self, InputError> {
        grid.validate()?;
        check(
            "map.values_len",
            values.len() as f32,
            values.len() == grid.len(),
            "preload_points * (1 + 2 * speed_points)",
        )?;
        for &v in values {
            check("map.values", v, v.is_finite(), "finite torques, N m")?;
        }
        Ok(Self::unchecked(grid, values))
    }

    fn unchecked(grid: MapGrid, values: &'a [f32]) -> Self {
        let inverse = [1.0 / grid.preload_step_n, 1.0 / grid.speed_step_rad_s, 1.0 / grid.standstill_speed_rad_s];
        Self { grid, values, inverse }
    }

    /// The grid.
    pub fn grid(&self) -> &MapGrid {
        &self.grid
    }

    /// The values (layout in the module docs).
    pub fn values(&self) -> &'a [f32] {
        self.values
    }

    /// Drive torque, N m, at preload `preload_n` (N) and screw speed `speed_rad_s` (rad/s,
    /// signed): bilinear in the direction's sheet, linear in the standstill row, blended by the
    /// standstill factor. Clamped outside the grid; a NaN or infinite input gives NaN.
    #[inline]
    pub fn torque_nm(&self, preload_n: f32, speed_rad_s: f32) -> f32 {
        let g = &self.grid;
        let [inverse_dp, inverse_ds, inverse_omega0] = self.inverse;
        let (p, fp) = locate(preload_n, g.preload_min_n, inverse_dp, g.preload_points);
        let magnitude = libm::fabsf(speed_rad_s);
        let (s, fs) = locate(magnitude, g.speed_min_rad_s, inverse_ds, g.speed_points);
        let np = g.preload_points as usize;
        let ns = g.speed_points as usize;
        let v = self.values;
        let still = v[p] + fp * (v[p + 1] - v[p]);
        let sheet = if speed_rad_s < 0.0 { np + np * ns } else { np };
        let i = sheet + p * ns + s;
        let lo = v[i] + fs * (v[i + 1] - v[i]);
        let hi = v[i + ns] + fs * (v[i + ns + 1] - v[i + ns]);
        let running = lo + fp * (hi - lo);
        still + standstill_factor(magnitude, inverse_omega0) * (running - still)
    }
}

#[cfg(feature = "std")]
pub use tabulate::{MapError, Tabulated, tabulate};

#[cfg(feature = "std")]
mod tabulate {
    //! Building a map from the model (std: the values live in a `Vec`).

    use super::{MapGrid, TorqueMap};
    use crate::error::Error;
    use crate::input::OperatingPoint;
    use crate::screw::torque::{Model, SolverState};
    extern crate alloc;
    use alloc::vec::Vec;

    /// A map built from the model, with its largest interpolation error against the model.
    #[derive(Debug, Clone, PartialEq)]
    pub struct Tabulated {
        /// The grid.
        pub grid: MapGrid,
        /// The values (layout in the module docs).
        pub values: Vec<f32>,
        /// External axial load the map was tabulated at, N.
        pub axial_load_n: f64,
        /// Largest |map - model| / |model| over the check points.
        pub max_relative_error: f64,
        /// Largest |map - model| over the check points, N m.
        pub max_absolute_error_nm: f64,
        /// Where the largest relative error is: (preload N, speed rad/s).
        pub worst_point: (f64, f64),
        /// Number of check points (cell midpoints in both directions, and the standstill band).
        pub checked_points: usize,
    }

    impl Tabulated {
        /// The map over the owned values.
        pub fn map(&self) -> TorqueMap<'_> {
            TorqueMap::unchecked(self.grid, &self.values)
        }
    }

    /// Why a map could not be built.
    #[derive(Debug, Clone, Copy, PartialEq)]
    pub enum MapError {
        /// The model failed at an operating point (preload N, speed rad/s).
        Model {
            /// The error.
            error: Error,
            /// Preload, N.
            preload_n: f64,
            /// Speed, rad/s.
            speed_rad_s: f64,
        },
        /// The grid or a tabulated value is invalid.
        Input(crate::error::InputError),
    }

    impl core::fmt::Display for MapError {
        fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
            match self {
                MapError::Model { error, preload_n, speed_rad_s } => {
                    write!(f, "at preload {preload_n} N, speed {speed_rad_s} rad/s: {error}")
                }
                MapError::Input(e) => e.fmt(f),
            }
        }
    }

    impl core::error::Error for MapError {}

    /// Tabulates `model` on `grid` at external axial load `axial_load_n` (N) and checks the map
    /// against the model at the midpoint of every grid cell (both directions) and at half the
    /// standstill speed (both directions) at every preload-cell midpoint.
    pub fn tabulate(model: &Model, grid: &MapGrid, axial_load_n: f64) -> Result<Tabulated, MapError> {
        grid.validate().map_err(MapError::Input)?;
        let omega0 = f64::from(grid.standstill_speed_rad_s);
        let mut state = SolverState::new();
        let mut torque = |preload_n: f64, speed_rad_s: f64| {
            let op = OperatingPoint { speed_rad_s, preload_n, axial_load_n };
            model.torque(&op, &mut state).map_err(|error| MapError::Model { error, preload_n, speed_rad_s })
        };
        let preload = |k: u32| f64::from(grid.preload_min_n) + f64::from(grid.preload_step_n) * f64::from(k);
        let speed = |k: u32| f64::from(grid.speed_min_rad_s) + f64::from(grid.speed_step_rad_s) * f64::from(k);
        let mut values = Vec::with_capacity(grid.len());
        for p in 0..grid.preload_points {
            values.push(torque(preload(p), 0.0)? as f32);
        }
        for direction in [1.0, -1.0] {
            for p in 0..grid.preload_points {
                for s in 0..grid.speed_points {
                    values.push(torque(preload(p), direction * speed(s).max(omega0))? as f32);
                }
            }
        }
        let map = TorqueMap::new(*grid, &values).map_err(MapError::Input)?;
        let mut worst = (0.0_f64, 0.0_f64, (0.0, 0.0));
        let mut checked = 0;
        let mut check = |p: f64, w: f64, model_t: f64| {
            let m = f64::from(map.torque_nm(p as f32, w as f32));
            let abs = (m - model_t).abs();
            let rel = if model_t != 0.0 {
                abs / model_t.abs()
            } else if abs == 0.0 {
                0.0
            } else {
                f64::INFINITY
            };
            if rel > worst.0 || rel.is_nan() {
                worst.2 = (p, w);
            }
            worst.0 = worst.0.max(rel);
            worst.1 = worst.1.max(abs);
            checked += 1;
        };
        for p in 0..grid.preload_points - 1 {
            let pm = 0.5 * (preload(p) + preload(p + 1));
            for direction in [1.0, -1.0] {
                for s in 0..grid.speed_points - 1 {
                    let w = direction * 0.5 * (speed(s) + speed(s + 1));
                    check(pm, w, torque(pm, w)?);
                }
                let w = direction * 0.5 * omega0;
                check(pm, w, torque(pm, w)?);
            }
        }
        Ok(Tabulated {
            grid: *grid,
            values,
            axial_load_n,
            max_relative_error: worst.0,
            max_absolute_error_nm: worst.1,
            worst_point: worst.2,
            checked_points: checked,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid() -> MapGrid {
        MapGrid {
            preload_min_n: 0.0,
            preload_step_n: 10.0,
            preload_points: 3,
            speed_min_rad_s: 0.0,
            speed_step_rad_s: 1.0,
            speed_points: 2,
            standstill_speed_rad_s: 0.5,
        }
    }

    /// Standstill row 0; forward sheet T = p / 10 + w; reverse sheet -(p / 10) - 2 w.
    fn values() -> [f32; 15] {
        [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 0.0, -2.0, -1.0, -3.0, -2.0, -4.0]
    }

    #[test]
    fn bilinear_inside_and_clamped_outside() {
        let v = values();
        let m = TorqueMap::new(grid(), &v).unwrap();
        assert!((m.torque_nm(5.0, 0.75) - 1.25).abs() < 1e-6);
        assert!((m.torque_nm(15.0, 1.0) - 2.5).abs() < 1e-6);
        assert!((m.torque_nm(15.0, -0.75) + 3.0).abs() < 1e-6);
        // Clamped: beyond the last preload and speed.
        assert_eq!(m.torque_nm(100.0, 50.0), 3.0);
        assert_eq!(m.torque_nm(-5.0, -50.0), -2.0);
        assert!(m.torque_nm(f32::NAN, 1.0).is_nan());
        assert!(m.torque_nm(5.0, f32::NAN).is_nan());
        assert!(m.torque_nm(f32::INFINITY, 1.0).is_nan());
        assert!(m.torque_nm(5.0, f32::NEG_INFINITY).is_nan());
    }

    #[test]
    fn continuous_through_zero_speed() {
        let v = values();
        let m = TorqueMap::new(grid(), &v).unwrap();
        assert_eq!(m.torque_nm(10.0, 0.0), 0.0);
        let e = 1e-6;
        assert!(m.torque_nm(10.0, e).abs() < 1e-5 && m.torque_nm(10.0, -e).abs() < 1e-5);
        // Half the standstill speed: factor 0.75 of the running torque.
        assert!((m.torque_nm(10.0, 0.25) - 0.75 * 1.25).abs() < 1e-6);
    }

    #[test]
    fn bad_grids_and_values_are_named() {
        let v = values();
        let mut g = grid();
        g.preload_points = 1;
        assert_eq!(TorqueMap::new(g, &v).unwrap_err().field, "map.preload_points");
        let mut g = grid();
        g.speed_step_rad_s = 0.0;
        assert_eq!(TorqueMap::new(g, &v).unwrap_err().field, "map.speed_step_rad_s");
        assert_eq!(TorqueMap::new(grid(), &v[..14]).unwrap_err().field, "map.values_len");
        let mut w = v;
        w[3] = f32::INFINITY;
        assert_eq!(TorqueMap::new(grid(), &w).unwrap_err().field, "map.values");
    }
}
