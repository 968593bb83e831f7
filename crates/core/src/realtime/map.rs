//! Torque map for firmware: the model's torque tabulated over preload and screw speed, looked up
//! by bilinear interpolation in a borrowed slice of `f32` (no_std, no allocation, no panics).
//!
//! Layout. A [`MapGrid`] has `preload_points` uniformly spaced preloads and `speed_points` speed
//! *magnitudes*, spaced as its [`Spacing`] says; the values slice holds, in this order:
//! - the standstill row: the torque at zero speed for each preload (`preload_points` values;
//!   with no axial load this is 0, with one it is the load's lead torque F_a L / (2 pi));
//! - the forward sheet: the *running* torque at positive speeds, row by preload
//!   (`preload_points x speed_points`, index `p * speed_points + s`);
//! - the reverse sheet: the same at negative speeds.
//!
//! Speed axis. [`Spacing::Uniform`]: node `k` at `speed_min + k * speed_step` (rad/s), linear
//! interpolation in the speed. [`Spacing::Geometric`]: node `k` at `speed_min * exp(k *
//! speed_step)`, `speed_step = h` the natural logarithm of the ratio of neighbouring nodes,
//! `speed_min > 0`. The lubricated model's torque changes over decades of speed (a
//! mixed-friction dip at a few rpm, then roughly a power 0.4 to 0.6 of the speed), and an error
//! relative to the torque needs cells of equal *relative* width: a geometric axis. Within a
//! geometric cell the lookup is linear in `w^q`, q = [`GEOMETRIC_EXPONENT`] = 0.5, not in the
//! speed (q = 1) nor in its logarithm (q -> 0): for a power law T ~ w^b the leading relative
//! error of a cell is about |b (b - q)| h^2 / 8, which a q in the middle of the model's
//! exponents keeps small at both ends of the speed range (b (1 - b) for q = 1 and b^2 for
//! ln w are four to ten times larger for b from 0.4 to 0.6). Measured on the built-in lubricated DKFZD4012,
//! 16 preloads x 38 speeds from 0.01 to 3000 rpm: 0.70 % with q = 1, 0.47 % with q = 0.35,
//! 0.43 % with q = 0.5, 0.41 % with q = 0.65 (0.5 is kept: the square root is the middle of the
//! exponents, and the gain of the best q is small). In the lookup the cell and its fraction f
//! come from the logarithm of the speed, and the fraction in `w^q` is
//! `(exp(q h f) - 1) / (exp(q h) - 1)`, exactly 0 and 1 at the nodes, so the cells meet there.
//! [`ln`] and [`exp`] are short `f32` polynomials of this module (no libm), which the C header
//! of the command line repeats operation for operation, so that both lookups give the same bits.
//!
//! The running torque of a node is the model's torque at that speed, or, on a uniform axis, at
//! the standstill speed omega0 (with the node's direction) where the node's magnitude lies below
//! it. Reversal and standstill (docs/model-notes.md item 13) are handled as the model handles
//! them: the lookup blends from the standstill row to the direction's sheet with the model's own
//! standstill factor s = x (2 - x), x = |omega| / omega0 (1 above omega0), so the map is
//! continuous through zero speed (both sides meet the standstill row) and C1 at omega0. The
//! lubricated model's torque in the standstill band is not the blend of its torque at omega0
//! (its film and its contact state change with the speed there: at half omega0 the blend is
//! 2.6 % off): a geometric axis may start inside the band (the command line starts it at
//! omega0 / 10 when the range contains zero), and a node there holds the running torque that
//! the blend turns into the model's torque at the node, `still + (T - still) / s`. Between the
//! nodes, and everywhere on a uniform axis, the map never leaves the range of its tabulated
//! values. With the dry model the torque does not depend on the speed's magnitude above omega0
//! (docs/model-notes.md item 12), so a few uniform speed points suffice.
//!
//! Outside the grid the lookup clamps: a preload or speed magnitude beyond the grid takes the
//! value at the nearest edge (on a geometric axis a magnitude below its first node takes that
//! node's running torque, blended to the standstill row below omega0). A NaN or infinite input
//! gives NaN.
//!
//! [`tabulate`] (with the `std` feature) builds a map from a [`Model`](crate::Model) and states
//! its largest interpolation error against the model, checked at the midpoint of every grid
//! cell in both directions (the mean of its two preloads and, in the coordinate the lookup is
//! linear in, of its two speeds) and in the middle of the standstill band (on a geometric axis
//! that starts inside it, of the span below its first node).

use crate::error::InputError;

/// How the speed magnitudes of a [`MapGrid`] are spaced (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Spacing {
    /// Node `k` at `speed_min_rad_s + k * speed_step`; linear interpolation in the speed.
    #[default]
    Uniform,
    /// Node `k` at `speed_min_rad_s * exp(k * speed_step)` ([`exp`]); within a cell linear
    /// interpolation in the speed's power [`GEOMETRIC_EXPONENT`].
    Geometric,
}

impl Spacing {
    /// The name the command line and the generated files use: `uniform`, `geometric`.
    pub const fn name(self) -> &'static str {
        match self {
            Spacing::Uniform => "uniform",
            Spacing::Geometric => "geometric",
        }
    }
}

/// The grid of a torque map (SI units; `f32`, the precision a firmware map is stored in).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapGrid {
    /// First preload of the grid, N.
    pub preload_min_n: f32,
    /// Spacing of the preloads, N (> 0).
    pub preload_step_n: f32,
    /// Number of preloads (>= 2).
    pub preload_points: u32,
    /// How the speed magnitudes are spaced.
    pub speed_spacing: Spacing,
    /// Smallest speed magnitude of the grid, rad/s (>= 0; > 0 and normal when geometric).
    pub speed_min_rad_s: f32,
    /// Step of the speed axis: uniform, the spacing of the speed magnitudes, rad/s (> 0);
    /// geometric, the natural logarithm of the ratio of neighbouring magnitudes (>= 0.001, and
    /// `(speed_points - 1) * speed_step <= 87`).
    pub speed_step: f32,
    /// Number of speed magnitudes (>= 2).
    pub speed_points: u32,
    /// Standstill speed omega0 of the model, rad/s (> 0): below it the lookup blends to the
    /// standstill row.
    pub standstill_speed_rad_s: f32,
}

/// Most grid points along one axis.
pub const MAX_AXIS_POINTS: u32 = 10_000;

/// Smallest step of a geometric speed axis (ln of the ratio of neighbouring nodes): closer
/// nodes would not be distinct and increasing in `f32`.
pub const MIN_GEOMETRIC_STEP: f32 = 1e-3;
/// Largest span of a geometric speed axis, `(speed_points - 1) * speed_step` (ln of the ratio
/// of its last node to its first), within the range of [`exp`].
pub const MAX_GEOMETRIC_SPAN: f32 = 87.0;

fn check(field: &'static str, value: f32, ok: bool, valid: &'static str) -> Result<(), InputError> {
    if ok { Ok(()) } else { Err(InputError { field, value: f64::from(value), valid }) }
}

const LN_2: f32 = core::f32::consts::LN_2;
/// ln 2 = LN_2_HI + LN_2_LO, LN_2_HI with 16 significant bits (its product with an exponent is exact).
const LN_2_HI: f32 = 0.693_145_75;
const LN_2_LO: f32 = 1.428_606_8e-6;

/// Natural logarithm of a positive, normal, finite `x` (the map's own, to within a few units in
/// the last place; other inputs give meaningless numbers, no panic): `x = 2^e m`,
/// m in [sqrt(1/2), sqrt(2)), ln m = 2 atanh(s), s = (m - 1) / (m + 1), by its series to s^7.
/// The C header of the command line repeats it operation for operation.
#[inline]
pub fn ln(x: f32) -> f32 {
    let bits = x.to_bits();
    let mut e = ((bits >> 23) & 0xff) as i32 - 127;
    let mut m = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000);
    if m > core::f32::consts::SQRT_2 {
        m *= 0.5;
        e += 1;
    }
    let s = (m - 1.0) / (m + 1.0);
    let z = s * s;
    e as f32 * LN_2 + s * (2.0 + z * (0.666_666_7 + z * (0.4 + z * 0.285_714_3)))
}

/// Exponential of `x` in [0, 87] (the map's own, to within a few units in the last place;
/// `exp(0) == 1` exactly; other inputs give meaningless numbers, no panic): `x = n ln 2 + t`,
/// |t| <= ln 2 / 2 (ln 2 in two parts, the first exact times n), e^t by its Taylor series to
/// t^6, times 2^n. The C header of the command line repeats it operation for operation.
#[inline]
pub fn exp(x: f32) -> f32 {
    let n = (x * core::f32::consts::LOG2_E + 0.5) as i32;
    let t = (x - n as f32 * LN_2_HI) - n as f32 * LN_2_LO;
    let p = 1.0
        + t * (1.0 + t * (0.5 + t * (0.166_666_67 + t * (0.041_666_668 + t * (0.008_333_334 + t * 0.001_388_888_9)))));
    p * f32::from_bits(((n.clamp(-126, 127) + 127) as u32) << 23)
}

/// The first node and the step (f32) of a uniform axis of `points` nodes from `lo` to `hi`, its
/// last node not above `hi`: the first node the f32 nearest `lo` (the axes start at 0 or
/// above, where the nearest f32 stays in the model's ranges), the step the f32 nearest
/// `(hi - lo) / (points - 1)` lowered by units in the last place while the last node, as the
/// lookup and the tabulation compute it (f32), lies above `hi` (the nearest f32 of 0..3000
/// rpm's top, 314.15927 rad/s, is above its 314.159265...; that of 30000 rpm above the model's
/// speed range). Ends and steps that are not finite are rounded as they are, for the grid's
/// check.
fn uniform_axis(lo: f64, hi: f64, points: u32) -> (f32, f32) {
    let first = lo as f32;
    let cells = points.max(2) - 1;
    let mut step = ((hi - lo) / f64::from(cells)) as f32;
    let last = |step: f32| f64::from(first + step * cells as f32);
    while last(step) > hi && step > 0.0 && step.is_finite() {
        step = step.next_down();
    }
    (first, step)
}

impl MapGrid {
    /// The grid with `preload_points` preloads from `preload_min_n` to `preload_max_n` (N) and
    /// `speed_points` uniformly spaced speed magnitudes from `speed_min_rad_s` to
    /// `speed_max_rad_s` (rad/s), with the model's standstill speed (rad/s); in f32, the last
    /// node of each axis not above its top (within a few units in the last place of it). Not
    /// validated: see [`MapGrid::validate`].
    pub fn spanning(
        (preload_min_n, preload_max_n, preload_points): (f64, f64, u32),
        (speed_min_rad_s, speed_max_rad_s, speed_points): (f64, f64, u32),
        standstill_speed_rad_s: f64,
    ) -> Self {
        let (preload_min, preload_step) = uniform_axis(preload_min_n, preload_max_n, preload_points);
        let (speed_min, speed_step) = uniform_axis(speed_min_rad_s, speed_max_rad_s, speed_points);
        Self {
            preload_min_n: preload_min,
            preload_step_n: preload_step,
            preload_points,
            speed_spacing: Spacing::Uniform,
            speed_min_rad_s: speed_min,
            speed_step,
            speed_points,
            standstill_speed_rad_s: standstill_speed_rad_s as f32,
        }
    }

    /// As [`MapGrid::spanning`] with geometrically spaced speed magnitudes from
    /// `speed_min_rad_s` (> 0) to `speed_max_rad_s` (the last node not above it, and below it
    /// by at most about 1e-5 of it: a unit in the last place of the step moves the last node by
    /// `speed_points - 1` of them). Not validated: see [`MapGrid::validate`].
    pub fn geometric(
        preload: (f64, f64, u32),
        (speed_min_rad_s, speed_max_rad_s, speed_points): (f64, f64, u32),
        standstill_speed_rad_s: f64,
    ) -> Self {
        let mut g = Self::spanning(preload, (speed_min_rad_s, speed_max_rad_s, speed_points), standstill_speed_rad_s);
        g.speed_spacing = Spacing::Geometric;
        g.speed_step = (libm::log(speed_max_rad_s / speed_min_rad_s) / f64::from(speed_points.max(2) - 1)) as f32;
        // The last node as the lookup computes it (f32) not above the range's top: the step
        // lowered by units in the last place while it is (a span beyond `exp`'s range, an
        // infinite node, is left for the grid's check).
        let above = |g: &Self| {
            let last = g.speed_max_rad_s();
            last.is_finite() && f64::from(last) > speed_max_rad_s
        };
        while above(&g) && g.speed_step > 0.0 {
            g.speed_step = g.speed_step.next_down();
        }
        g
    }

    /// Number of values a map on this grid holds: `preload_points * (1 + 2 * speed_points)`.
    pub const fn len(&self) -> usize {
        self.preload_points as usize * (1 + 2 * self.speed_points as usize)
    }

    /// Always false for a valid grid (it has at least 2 x 2 points).
    pub const fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Preload `k` of the grid, N.
    pub fn preload_n(&self, k: u32) -> f32 {
        self.preload_min_n + self.preload_step_n * k as f32
    }

    /// Last preload of the grid, N.
    pub fn preload_max_n(&self) -> f32 {
        self.preload_n(self.preload_points.max(1) - 1)
    }

    /// Speed magnitude `k` of the grid (a node of the speed axis), rad/s: the speed the
    /// tabulation evaluates the model at and the lookup interpolates between. Infinite for a
    /// geometric `k * speed_step` above [`MAX_GEOMETRIC_SPAN`].
    pub fn speed_rad_s(&self, k: u32) -> f32 {
        match self.speed_spacing {
            Spacing::Uniform => self.speed_min_rad_s + self.speed_step * k as f32,
            Spacing::Geometric => {
                let x = self.speed_step * k as f32;
                if x <= MAX_GEOMETRIC_SPAN { self.speed_min_rad_s * exp(x) } else { f32::INFINITY }
            }
        }
    }

    /// Whether the speed axis reaches standstill: its first node at or below the standstill
    /// speed (a uniform axis from 0, a geometric one from a tenth of the standstill speed).
    pub fn reaches_standstill(&self) -> bool {
        self.speed_min_rad_s <= self.standstill_speed_rad_s
    }

    /// Largest speed magnitude of the grid, rad/s.
    pub fn speed_max_rad_s(&self) -> f32 {
        self.speed_rad_s(self.speed_points.max(1) - 1)
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
        let (v, h) = (self.speed_min_rad_s, self.speed_step);
        match self.speed_spacing {
            Spacing::Uniform => {
                check("map.speed_min_rad_s", v, v.is_finite() && v >= 0.0, "finite and >= 0 rad/s")?;
                check("map.speed_step", h, h.is_finite() && h > 0.0, "finite and > 0 rad/s (uniform spacing)")?;
            }
            Spacing::Geometric => {
                let ok = v.is_normal() && v > 0.0;
                check("map.speed_min_rad_s", v, ok, "finite and > 0 rad/s, normal (geometric spacing)")?;
                let ok = h.is_finite() && h >= MIN_GEOMETRIC_STEP;
                check("map.speed_step", h, ok, ">= 0.001 (ln of the ratio of neighbouring speeds; geometric spacing)")?;
                let span = h * (self.speed_points - 1) as f32;
                let ok = span <= MAX_GEOMETRIC_SPAN;
                check("map.speed_step", h, ok, "(speed_points - 1) x speed_step <= 87 (geometric spacing)")?;
            }
        }
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
    /// than divisions in the lookup), ln of the first speed and q times the speed step
    /// (geometric spacing; 0 when uniform).
    inverse: [f32; 5],
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

/// Exponent q of the speed in whose power `w^q` a geometric cell is interpolated linearly
/// (module docs).
pub const GEOMETRIC_EXPONENT: f32 = 0.5;

/// Cell index and fraction of the speed magnitude `x` on a geometric axis: the magnitude
/// clamped below to the first node, its cell and its fraction `f` in the logarithm of the speed
/// by [`locate`] (clamped to the axis), and the fraction turned from ln w to w^q,
/// `(exp(q h f) - 1) / (exp(q h) - 1)` (`q_step = q h`; exactly 0 at f = 0 and 1 at f = 1, so
/// the cells meet at the nodes); a NaN or infinite `x` gives a NaN fraction.
#[inline]
#[allow(clippy::eq_op)] // `x - x` is deliberate: it carries NaN and infinities into the result.
fn locate_geometric(x: f32, g: &MapGrid, ln_min: f32, inverse_step: f32, q_step: f32) -> (usize, f32) {
    // f32::max returns the number when the other operand is NaN: ln always sees a normal number.
    let w = x.max(g.speed_min_rad_s);
    let (cell, f) = locate(ln(w), ln_min, inverse_step, g.speed_points);
    let fraction = (exp(q_step * f) - 1.0) / (exp(q_step) - 1.0);
    (cell, fraction + (x - x))
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
        let (ln_min, q_step) = match grid.speed_spacing {
            Spacing::Uniform => (0.0, 0.0),
            Spacing::Geometric => (ln(grid.speed_min_rad_s), GEOMETRIC_EXPONENT * grid.speed_step),
        };
        let inverse =
            [1.0 / grid.preload_step_n, 1.0 / grid.speed_step, 1.0 / grid.standstill_speed_rad_s, ln_min, q_step];
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

    /// Whether the point lies on the grid, where [`TorqueMap::torque_nm`] interpolates: the
    /// preload within the first and last preload of the grid (N) and the speed's magnitude
    /// (rad/s) at most the last speed node and at least the first, or below it when the grid
    /// reaches standstill (its first speed node at or below the standstill speed: the lookup
    /// blends to the standstill row there as the model does). Elsewhere the lookup clamps to the
    /// grid's edges, an extrapolation a firmware can flag with this; a NaN or infinite input is
    /// outside.
    #[inline]
    pub fn in_grid(&self, preload_n: f32, speed_rad_s: f32) -> bool {
        let g = &self.grid;
        let magnitude = libm::fabsf(speed_rad_s);
        preload_n >= g.preload_min_n
            && preload_n <= g.preload_max_n()
            && magnitude <= g.speed_max_rad_s()
            && (magnitude >= g.speed_min_rad_s || g.reaches_standstill())
    }

    /// Drive torque, N m, at preload `preload_n` (N) and screw speed `speed_rad_s` (rad/s,
    /// signed): bilinear in the direction's sheet (linear in the preload and, within the cell,
    /// in the speed), linear in the standstill row, blended by the standstill factor. Clamped
    /// outside the grid; a NaN or infinite input gives NaN.
    #[inline]
    pub fn torque_nm(&self, preload_n: f32, speed_rad_s: f32) -> f32 {
        let g = &self.grid;
        let [inverse_dp, inverse_ds, inverse_omega0, ln_min, q_step] = self.inverse;
        let (p, fp) = locate(preload_n, g.preload_min_n, inverse_dp, g.preload_points);
        let magnitude = libm::fabsf(speed_rad_s);
        let (s, fs) = match g.speed_spacing {
            Spacing::Uniform => locate(magnitude, g.speed_min_rad_s, inverse_ds, g.speed_points),
            Spacing::Geometric => locate_geometric(magnitude, g, ln_min, inverse_ds, q_step),
        };
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
pub use tabulate::{MapError, Tabulated, evaluations, tabulate, tabulate_with_progress};

#[cfg(feature = "std")]
mod tabulate {
    //! Building a map from the model (std: the values live in a `Vec`).

    use super::{MapGrid, Spacing, TorqueMap};
    use crate::error::Error;
    use crate::input::OperatingPoint;
    use crate::screw::model::{Model, SolverState};
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

    /// Tabulates `model` on `grid` at external axial load `axial_load_n` (N) (a geometric node
    /// below the standstill speed holds the running torque the lookup's blend turns into the
    /// model's torque there: module docs) and checks the map
    /// against the model at the midpoint of every grid cell (both directions; the mean of the
    /// cell's node speeds, on a geometric axis too, where the lookup is linear in the speed) and
    /// at half the standstill speed, or half the first node's speed on a geometric axis that
    /// starts below it (both directions), at every preload-cell midpoint.
    ///
    /// ```
    /// use ballscrew_core::input::rpm_to_rad_s;
    /// use ballscrew_core::realtime::map::{MapGrid, tabulate};
    /// use ballscrew_core::{Model, OperatingPoint, ScrewSpec, SolverState};
    ///
    /// let model = Model::new(&ScrewSpec::dkfzd4012())?;
    /// let omega0 = model.spec().friction.standstill_speed_rad_s;
    /// let grid = MapGrid::geometric((1000.0, 3000.0, 3), (rpm_to_rad_s(10.0), rpm_to_rad_s(1000.0), 5), omega0);
    /// let t = tabulate(&model, &grid, 0.0)?;
    /// assert_eq!(t.values.len(), 3 * (1 + 2 * 5));
    /// // At a node the map holds the model's torque (in f32); between nodes it is within the
    /// // largest error the tabulation found at the cells' midpoints.
    /// let at = |preload_n: f64, speed_rad_s: f64| {
    ///     let op = OperatingPoint { speed_rad_s, preload_n, axial_load_n: 0.0 };
    ///     model.torque(&op, &mut SolverState::new())
    /// };
    /// let node = f64::from(grid.speed_rad_s(2));
    /// let looked_up = f64::from(t.map().torque_nm(2000.0, node as f32));
    /// assert!((looked_up - at(2000.0, node)?).abs() <= 1e-5 * looked_up);
    /// // The middle of a cell (preload 1500 N; the lookup is linear in the square root of the
    /// // speed on a geometric axis), one of the points the tabulation checked.
    /// let (w2, w3) = (f64::from(grid.speed_rad_s(2)), f64::from(grid.speed_rad_s(3)));
    /// let middle = (0.5 * (w2.sqrt() + w3.sqrt())).powi(2);
    /// let (looked_up, modelled) = (f64::from(t.map().torque_nm(1500.0, middle as f32)), at(1500.0, middle)?);
    /// assert!((looked_up - modelled).abs() <= t.max_relative_error * modelled * (1.0 + 1e-6));
    /// assert!(t.max_relative_error > 0.0 && t.checked_points == 2 * 2 * (4 + 1));
    /// # Ok::<(), Box<dyn core::error::Error>>(())
    /// ```
    pub fn tabulate(model: &Model, grid: &MapGrid, axial_load_n: f64) -> Result<Tabulated, MapError> {
        tabulate_with_progress(model, grid, axial_load_n, &mut |_, _| {})
    }

    /// Model evaluations of [`tabulate`] on `preload_points` x `speed_points`: the standstill
    /// row, both sheets, and the check points (every cell's midpoint in both directions and
    /// half the standstill speed, at every preload-cell midpoint).
    pub fn evaluations(preload_points: usize, speed_points: usize) -> usize {
        let (np, ns) = (preload_points, speed_points);
        np + 2 * np * ns + 2 * np.saturating_sub(1) * ns
    }

    /// [`tabulate`], calling `progress(done, total)` after each evaluation of the model:
    /// `total` is [`evaluations`] of the grid, `done` counts up to it one by one (the last call
    /// of a map that is built has `done == total`). For a progress bar: `progress` should
    /// return at once.
    pub fn tabulate_with_progress(
        model: &Model,
        grid: &MapGrid,
        axial_load_n: f64,
        progress: &mut dyn FnMut(usize, usize),
    ) -> Result<Tabulated, MapError> {
        grid.validate().map_err(MapError::Input)?;
        let omega0 = f64::from(grid.standstill_speed_rad_s);
        let total = evaluations(grid.preload_points as usize, grid.speed_points as usize);
        let mut done = 0;
        let mut torque = |preload_n: f64, speed_rad_s: f64| {
            let op = OperatingPoint { speed_rad_s, preload_n, axial_load_n };
            // From the cold start: the node is the point's canonical state, what `ballscrew
            // torque` gives there (docs/real-time.md, "One question, one answer").
            let t = model.torque(&op, &mut SolverState::new()).map_err(|error| MapError::Model {
                error,
                preload_n,
                speed_rad_s,
            });
            done += 1;
            progress(done, total);
            t
        };
        // The nodes as the lookup computes them (`f32`), which the grid keeps within the ranges
        // asked for (an f64 sum of the f32 first node and steps could lie past the last).
        let preload = |k: u32| f64::from(grid.preload_n(k));
        let speed = |k: u32| f64::from(grid.speed_rad_s(k));
        let mut values = Vec::with_capacity(grid.len());
        let mut still = Vec::with_capacity(grid.preload_points as usize);
        for p in 0..grid.preload_points {
            still.push(torque(preload(p), 0.0)?);
            values.push(still[p as usize] as f32);
        }
        for direction in [1.0, -1.0] {
            for p in 0..grid.preload_points {
                for s in 0..grid.speed_points {
                    let w = speed(s);
                    let running = if grid.speed_spacing == Spacing::Uniform || w >= omega0 {
                        torque(preload(p), direction * w.max(omega0))?
                    } else {
                        // A geometric node in the standstill band: the running torque that the
                        // lookup's blend turns into the model's torque at the node.
                        let x = w / omega0;
                        let t = torque(preload(p), direction * w)?;
                        still[p as usize] + (t - still[p as usize]) / (x * (2.0 - x))
                    };
                    values.push(running as f32);
                }
            }
        }
        let map = TorqueMap::new(*grid, &values).map_err(MapError::Input)?;
        // The band checked at its middle: the standstill band, or on a geometric axis that starts
        // below omega0, the span from zero to the first node (where the running torque is clamped).
        let band = match grid.speed_spacing {
            Spacing::Uniform => omega0,
            Spacing::Geometric => omega0.min(speed(0)),
        };
        // The middle of a speed cell in the coordinate the lookup is linear in.
        let midpoint = |a: f64, b: f64| match grid.speed_spacing {
            Spacing::Uniform => 0.5 * (a + b),
            Spacing::Geometric => {
                let q = f64::from(super::GEOMETRIC_EXPONENT);
                (0.5 * (a.powf(q) + b.powf(q))).powf(1.0 / q)
            }
        };
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
                    let w = direction * midpoint(speed(s), speed(s + 1));
                    check(pm, w, torque(pm, w)?);
                }
                let w = direction * 0.5 * band;
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
            speed_spacing: Spacing::Uniform,
            speed_min_rad_s: 0.0,
            speed_step: 1.0,
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
    fn in_grid_is_where_the_lookup_interpolates() {
        let v = values();
        let m = TorqueMap::new(grid(), &v).unwrap();
        // Preloads 0..20 N, speed magnitudes 0..1 rad/s (from 0: standstill reached).
        for (p, w) in [(0.0, 0.0), (20.0, 1.0), (20.0, -1.0), (10.0, 0.3), (0.0, -1e-30)] {
            assert!(m.in_grid(p, w), "{p} N, {w} rad/s");
        }
        for (p, w) in [(20.001, 0.5), (-0.001, 0.5), (10.0, 1.001), (10.0, -1.001), (f32::NAN, 0.5), (5.0, f32::NAN)] {
            assert!(!m.in_grid(p, w), "{p} N, {w} rad/s");
        }
        assert!(!m.in_grid(f32::INFINITY, 0.5) && !m.in_grid(5.0, f32::NEG_INFINITY));
        // An axis from 0.6 rad/s (above the standstill speed 0.5): below it the lookup clamps.
        let g = MapGrid { speed_min_rad_s: 0.6, ..grid() };
        let m = TorqueMap::new(g, &v).unwrap();
        assert!(!g.reaches_standstill() && !m.in_grid(10.0, 0.59) && m.in_grid(10.0, -0.6));
        // A geometric axis from a tenth of the standstill speed: slower speeds blend to standstill.
        let g = MapGrid { speed_spacing: Spacing::Geometric, speed_min_rad_s: 0.05, speed_step: 3.0, ..grid() };
        let m = TorqueMap::new(g, &v).unwrap();
        assert!(g.reaches_standstill() && m.in_grid(10.0, 0.001) && m.in_grid(10.0, 0.0));
        assert!(!m.in_grid(10.0, 1.01 * g.speed_max_rad_s()));
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
        g.speed_step = 0.0;
        assert_eq!(TorqueMap::new(g, &v).unwrap_err().field, "map.speed_step");
        assert_eq!(TorqueMap::new(grid(), &v[..14]).unwrap_err().field, "map.values_len");
        let mut w = v;
        w[3] = f32::INFINITY;
        assert_eq!(TorqueMap::new(grid(), &w).unwrap_err().field, "map.values");
    }

    /// Nodes at 1, 2, 4 rad/s (step ln 2), preloads 0 and 10 N; standstill row 0; forward sheet
    /// T = p / 10 + sqrt(w); reverse sheet -(p / 10) - 2 sqrt(w): linear in the coordinate
    /// sqrt(w) of a geometric cell.
    fn geometric() -> (MapGrid, [f32; 14]) {
        let g = MapGrid::geometric((0.0, 10.0, 2), (1.0, 4.0, 3), 0.5);
        let (a, b, c) = (1.0, core::f32::consts::SQRT_2, 2.0);
        let (ra, rb, rc) = (-2.0 * a, -2.0 * b, -2.0 * c);
        (g, [0.0, 0.0, a, b, c, 1.0 + a, 1.0 + b, 1.0 + c, ra, rb, rc, ra - 1.0, rb - 1.0, rc - 1.0])
    }

    #[test]
    fn ln_and_exp_are_close_to_the_true_functions() {
        let mut x = 1e-6_f32;
        while x < 1e6 {
            let (l, t) = (ln(x), f64::from(x).ln());
            assert!((f64::from(l) - t).abs() <= 3e-7 * t.abs().max(1.0), "ln {x}: {l} vs {t}");
            x *= 1.013;
        }
        assert_eq!(exp(0.0), 1.0);
        let mut x = 0.0_f32;
        while x <= MAX_GEOMETRIC_SPAN {
            let (e, t) = (exp(x), f64::from(x).exp());
            assert!((f64::from(e) - t).abs() <= 4e-7 * t, "exp {x}: {e} vs {t}");
            x += 0.0173;
        }
    }

    #[test]
    fn geometric_axis_is_linear_in_the_root_of_speed_within_a_cell_and_clamped_outside() {
        let (g, v) = geometric();
        let m = TorqueMap::new(g, &v).unwrap();
        assert_eq!(g.speed_spacing, Spacing::Geometric);
        assert_eq!(g.speed_rad_s(0), 1.0);
        assert!((g.speed_rad_s(1) - 2.0).abs() < 1e-6 && (g.speed_max_rad_s() - 4.0).abs() < 4e-6);
        // The tabulated function is linear in sqrt(w), so the map is exact to rounding.
        for w in [1.0_f32, 1.1, 1.5, 1.99, 2.0, 2.5, 3.0, 3.9, 4.0] {
            let r = libm::sqrtf(w);
            assert!((m.torque_nm(5.0, w) - (0.5 + r)).abs() < 2e-6, "{w}");
            assert!((m.torque_nm(5.0, -w) - (-0.5 - 2.0 * r)).abs() < 4e-6, "{w}");
        }
        // Clamped: below the first node the running torque is the first node's (blended to the
        // standstill row below omega0 = 0.5), above the last node the last node's.
        assert_eq!(m.torque_nm(0.0, 0.75), 1.0);
        assert_eq!(m.torque_nm(0.0, 0.25), 0.75);
        assert_eq!(m.torque_nm(0.0, 0.0), 0.0);
        assert_eq!(m.torque_nm(0.0, -0.0), 0.0);
        assert_eq!(m.torque_nm(10.0, 100.0), v[7]);
        assert_eq!(m.torque_nm(10.0, -f32::MAX), v[13]);
        assert!(m.torque_nm(5.0, f32::NAN).is_nan());
        assert!(m.torque_nm(5.0, f32::INFINITY).is_nan());
        assert!(m.torque_nm(5.0, f32::NEG_INFINITY).is_nan());
        assert!(m.torque_nm(f32::NAN, 2.0).is_nan());
        assert!(m.torque_nm(5.0, 1e-45).is_finite());
    }

    #[test]
    fn bad_geometric_grids_are_named() {
        let (g, v) = geometric();
        let mut b = g;
        b.speed_min_rad_s = 0.0;
        assert_eq!(TorqueMap::new(b, &v).unwrap_err().field, "map.speed_min_rad_s");
        let mut b = g;
        b.speed_step = 1e-4;
        assert_eq!(TorqueMap::new(b, &v).unwrap_err().field, "map.speed_step");
        let mut b = g;
        b.speed_step = 50.0;
        let e = TorqueMap::new(b, &v).unwrap_err();
        assert_eq!((e.field, e.valid), ("map.speed_step", "(speed_points - 1) x speed_step <= 87 (geometric spacing)"));
        let mut b = g;
        b.speed_min_rad_s = 1e30;
        b.speed_step = 30.0;
        assert_eq!(TorqueMap::new(b, &v).unwrap_err().field, "map.speed_max_rad_s");
        assert_eq!(Spacing::Geometric.name(), "geometric");
        assert_eq!(Spacing::default(), Spacing::Uniform);
    }
}
