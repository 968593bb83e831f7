//! Friction re-forming after a reversal of rolling, at the level of one contact: how the traction
//! of a rolling contact goes over from one steady state to the reversed one, and the lumped
//! first-order element that stands for a contact in a state model of the whole screw.
//!
//! Three parts, all on the conventions of [`crate::contact::fastsim`] (contact frame x along the
//! rolling direction e, leading edge at `x = +a` in the steady sense, y lateral, traction on the
//! ball, Kalker's flexibilities `u = (L1 px, L2 py)`):
//!
//! - [`reversal_slope`]: the rate at which the *creepage power* `P` changes per unit rolling
//!   distance when the traction changes in adhesion everywhere (from zero traction, or just
//!   after a reversal of a steady state), in closed form.
//! - [`Transient`]: Kalker's simplified theory stepped in rolling distance (the transient,
//!   time-stepping form of the simplified theory in J.J. Kalker, *Three-dimensional elastic
//!   bodies in rolling contact*, Kluwer, Dordrecht 1990, chapter on the simplified theory; its
//!   steady form is FASTSIM, J.J. Kalker, "A fast algorithm for the simplified theory of rolling
//!   contact", Veh. Syst. Dyn. 11 (1982) 1-13), on CONTACT's rectangle grid, the traction field
//!   in a caller's buffer as the state.
//! - [`dahl_step`]: the first-order friction model of P.R. Dahl ("A solid friction model",
//!   Aerospace Corp. TOR-0158(3107-18)-1, 1968; "Solid friction damping of mechanical
//!   vibrations", AIAA J. 14 (1976) 1675-1682), `dz/ds = sigma (1 - z sign(ds) / z_max)`,
//!   integrated exactly over a step.
//!
//! # Creepage power
//! With `s = (xi + k_h y^2 - phi y, eta + phi x)` the rigid slip of the ball per unit rolling
//! speed (the physical one; FASTSIM's `w` scales the spin by `L1/L3`, `L2/L3`), the measure is
//! `P = -int p . s dA` (N) = `-(F_e xi + F_f eta + M phi + k_h int px y^2 dA)`: the power of the
//! contact forces on the rigid creepages over the rolling speed, which in steady rolling is the
//! power the contact takes from the bodies' rigid motion (positive in every steady state tested).
//! FASTSIM's `dissipation_per_speed_n` (`-sum p . slip dA`) is a different number in general: in
//! the continuum the stored elastic energy leaves at the trailing edge with zero traction, so
//! the dissipation is `-int p . w dA`, equal to `P` when `L1 = L2 = L3` (then `w = s`) up to the
//! scheme's numerical dissipation, and off it by the spin's scaling with Kalker's three
//! flexibilities. [`field_totals`] gives `P` of any field (the steady one of [`fastsim`], or a
//! transient one) from its definition.
//!
//! # Reversal slope
//! In adhesion a material point's displacement changes by `du = -w ds` per rolling distance
//! `ds` in the steady sense (the simplified theory's `du/dx = w`), i.e. its traction by
//! `dp = -(w_x/L1, w_y/L2) ds`. Every point changes in adhesion from zero traction, and just
//! after a reversal of a steady state: a point slides in the steady state because the rigid slip
//! carries its traction outward faster than the bound grows along its path; reversed, both rates
//! change sign and the point leaves the bound. The points leaving and entering the ellipse carry
//! no traction (none at the steady leading edge, and the bound vanishes at the trailing edge).
//! So, from zero traction, `P` changes at the rate `K = int (w_x s_x / L1 + w_y s_y / L2) dA`
//! (N/m). Just after a reversal of a steady state it falls at `K + phi F_f` (`F_f` the lateral
//! force before): the material also carries its traction along x, where the lateral rigid slip
//! `s_y = eta + phi x` varies (in the continuum; the transient confirms it on a round contact in
//! pure spin, 0.51 K against 0.50 K predicted). On a ball screw's contacts `phi F_f` is within
//! 1 % of `K`, and the Dahl element below takes `K`. Over the ellipse (odd moments vanish,
//! `int y^2 dA = pi a b^3/4`, `int y^4 dA = pi a b^5/8`):
//! `K = pi a b [(xi^2 + xi k_h b^2/2 + k_h^2 b^4/8)/L1 + eta^2/L2 + phi^2 (a^2 + b^2)/(4 L3)]`.
//!
//! # Transient simplified theory
//! The grid is `nx x ny` equal cells over the ellipse's bounding rectangle `[-a, a] x [-b, b]`,
//! the cells whose centres lie strictly inside the ellipse in contact (CONTACT's grid,
//! [`Grid::Rectangle`] with `scale = 1`; `elements[j nx + i]`, `i` along x, `j` along y; a
//! cell outside has zero area and stays without traction). One [`Transient::step`] rolls the
//! field over a distance `0 < ds <= dx` (`dx = 2a/nx`) in a [`Direction`] `d = +1` (forward:
//! material moves toward -x and enters at `x = +a(y)`, the steady sense of `fastsim`) or
//! `d = -1` (reversed: toward +x, entering at `x = -a(y)`):
//! 1. advection, first-order upwind: `u_i <- (1 - ds/dx) u_i + (ds/dx) u_up`, `u_up` the cell
//!    upstream, zero for the material entering through the leading edge of the row (at
//!    `ds = dx` an exact shift by one cell);
//! 2. the rigid-slip increment `du = -d w ds`, the lateral (spin) part of `w` taken a sixth of a
//!    cell upstream, at `x + d dx/6` (CONTACT's `FACPHI = 1/6`, as `fastsim` does on this grid);
//! 3. the traction `p = (u_x/L1, u_y/L2)` clipped to the bound `mu p_n` at the cell centre along
//!    its own direction; the displacement the clip removes, over `ds`, is the cell's slip.
//!
//! The scheme's fixed point, for any `ds`, is FASTSIM's march on the same grid
//! (`u_i = clip(u_up - dx w_i)`), so [`Transient::start_steady`] runs [`fastsim`] on
//! [`Grid::Rectangle`] with `scale = 1` instead of rolling. The reversed steady state follows
//! from the forward one by a half turn about the normal: `(x, y, u) -> (-x, -y, -u)` carries the
//! reversed problem of the creepages `(xi, eta, phi, k_h)` into the forward problem of
//! `(xi, eta, -phi, k_h)`. So after a reversal `F_e`, `F_f` and `P` go over to minus those of
//! the forward state with the spin reversed, and `M` to that state's moment. All four negate
//! when there is neither spin nor lateral creepage; with `eta` and no spin, `M` keeps its sign
//! (the lateral traction moves to the other half of the ellipse); with spin and no `eta`, `F_f`
//! keeps its sign. On the contacts of a ball screw `P` after a reversal is within a few % of
//! `-P` before.
//!
//! # Dahl element
//! For a contact `z` stands for `P`, the bound for the steady `P` and the stiffness `sigma` for
//! `K/2`: Dahl's slope from the reversed steady state (`z = -z_max`) is `2 sigma`, which then
//! matches the contact's slope just after a reversal to within `phi F_f` (from zero, Dahl's
//! slope is `K/2` where the contact's is `K`). The relaxation length is `z_max / sigma`.
//!
//! Nothing allocates: the fields live in caller-provided `&mut [Element]` buffers.
//!
//! [`fastsim`]: crate::contact::fastsim::fastsim

use core::f64::consts::PI;

use crate::contact::fastsim::{
    self, Element, FIELD_NAMES, FastsimInput, Flexibilities, Grid, March, Setup, check_contact_values,
    check_flexibilities, validate,
};
use crate::contact::patch::Creep;
use crate::error::{InputError, check_range};
use crate::real::Real;

/// Sense of rolling.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// The steady sense of `fastsim`: material moves toward -x, entering at `x = +a(y)`.
    Forward,
    /// Reversed: material moves toward +x, entering at `x = -a(y)`.
    Reversed,
}

impl Direction {
    /// +1 forward, -1 reversed.
    pub fn sign(self) -> f64 {
        match self {
            Direction::Forward => 1.0,
            Direction::Reversed => -1.0,
        }
    }

    /// The other sense.
    pub fn reversed(self) -> Self {
        match self {
            Direction::Forward => Direction::Reversed,
            Direction::Reversed => Direction::Forward,
        }
    }
}

/// Totals of a traction field (steady or transient).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FieldTotals {
    /// Force on the ball along e, N.
    pub force_e_n: f64,
    /// Force on the ball along f, N.
    pub force_f_n: f64,
    /// Spin moment on the ball about g through the ellipse centre, `sum (x py - y px) dA`, N m.
    pub spin_moment_nm: f64,
    /// The creepage power `P = -sum p . s dA` with `s` the physical rigid slip per unit rolling
    /// speed, N (see the module documentation).
    pub creepage_power_n: f64,
    /// `-sum p . slip dA` with the elements' slip, N: per unit rolling speed for a `fastsim`
    /// field (its `dissipation_per_speed_n`), per unit rolling distance over the last step for
    /// a transient one.
    pub dissipation_n: f64,
    /// Elements in contact and in adhesion.
    pub adhesion_elements: u32,
    /// Elements in contact and sliding.
    pub slip_elements: u32,
}

/// [`reversal_slope_with_flexibilities`] with Kalker's flexibilities ([`Flexibilities::kalker`]).
///
/// # Errors
/// An [`InputError`] naming the first invalid contact value (`fastsim.*`; the bound and grid of
/// `input` are not used).
pub fn reversal_slope(input: &FastsimInput) -> Result<f64, InputError> {
    check_contact_values(input, &FIELD_NAMES)?;
    let flex = kalker(input);
    Ok(slope(input, &flex))
}

/// The rate `K` (N/m) at which the creepage power `P` changes per unit rolling distance when the
/// traction changes in adhesion everywhere: `K = int (w_x s_x / L1 + w_y s_y / L2) dA` over the
/// ellipse, in closed form (module documentation). `K >= 0`; its load, friction, bound and grid
/// do not enter.
///
/// # Errors
/// As [`reversal_slope`], and `fastsim.flexibility_l1/l2/l3` for a flexibility not finite and
/// > 0.
pub fn reversal_slope_with_flexibilities(input: &FastsimInput, flex: &Flexibilities) -> Result<f64, InputError> {
    check_contact_values(input, &FIELD_NAMES)?;
    check_flexibilities(flex)?;
    Ok(slope(input, flex))
}

fn kalker(input: &FastsimInput) -> Flexibilities {
    let c = &input.contact;
    Flexibilities::kalker(c.semi_axis_rolling_m, c.semi_axis_lateral_m, c.shear_modulus_pa, c.poisson_ratio)
}

fn slope(input: &FastsimInput, flex: &Flexibilities) -> f64 {
    let (a, b) = (input.contact.semi_axis_rolling_m, input.contact.semi_axis_lateral_m);
    let Creep { xi, eta, phi_per_m: phi, heathcote_per_m2: kh } = input.creep;
    let b2 = b * b;
    let longitudinal = (xi * xi + 0.5 * xi * kh * b2 + 0.125 * kh * kh * b2 * b2) / flex.l1_m_per_pa;
    let lateral = eta * eta / flex.l2_m_per_pa;
    let spin = 0.25 * phi * phi * (a * a + b2) / flex.l3_m_per_pa;
    PI * a * b * (longitudinal + lateral + spin)
}

/// Totals of a field for the creepages of `input` (its contact values validated, its bound and
/// grid not used): forces, moment, the creepage power `P` from its definition, the dissipation
/// of the elements' slip, and the counts. Elements of zero area (outside the ellipse on a
/// rectangle grid) are skipped.
///
/// # Errors
/// An [`InputError`] naming the first invalid contact value of `input` (`fastsim.*`).
pub fn field_totals(input: &FastsimInput, elements: &[Element]) -> Result<FieldTotals, InputError> {
    check_contact_values(input, &FIELD_NAMES)?;
    Ok(totals(input, elements))
}

fn totals(input: &FastsimInput, elements: &[Element]) -> FieldTotals {
    let Creep { xi, eta, phi_per_m: phi, heathcote_per_m2: kh } = input.creep;
    let mut t = FieldTotals::default();
    for e in elements.iter().filter(|e| e.area_m2 > 0.0) {
        let (x, y, px, py, da) = (e.x_m, e.y_m, e.traction_x_pa, e.traction_y_pa, e.area_m2);
        t.force_e_n += px * da;
        t.force_f_n += py * da;
        t.spin_moment_nm += (x * py - y * px) * da;
        let (sx, sy) = (xi + kh * y * y - phi * y, eta + phi * x);
        t.creepage_power_n -= (px * sx + py * sy) * da;
        t.dissipation_n -= (px * e.slip_x + py * e.slip_y) * da;
        if e.sliding {
            t.slip_elements += 1;
        } else {
            t.adhesion_elements += 1;
        }
    }
    t
}

/// The simplified theory stepped in rolling distance over one contact (module documentation):
/// the contact, its flexibilities and the grid, validated once. The state is the caller's
/// buffer of [`Element`]s (at least [`cells`](Self::cells) of them), started by
/// [`start_zero`](Self::start_zero) or [`start_steady`](Self::start_steady) and advanced by
/// [`step`](Self::step).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transient {
    input: FastsimInput,
    flex: Flexibilities,
    nx: usize,
    ny: usize,
}

impl Transient {
    /// With Kalker's flexibilities ([`Flexibilities::kalker`]); `nx` cells along rolling and
    /// `ny` across (each in `1..=1000`). The grid of `input` is not used: the transient grid is
    /// always the ellipse's bounding rectangle.
    ///
    /// # Errors
    /// An [`InputError`] naming the first invalid field (`fastsim.*`, `nx`, `ny`).
    pub fn new(input: &FastsimInput, nx: usize, ny: usize) -> Result<Self, InputError> {
        Self::with_flexibilities(input, &kalker(input), nx, ny)
    }

    /// With given flexibilities (`shear_modulus_pa` and `poisson_ratio` of `input` validated but
    /// not used).
    ///
    /// # Errors
    /// As [`new`](Self::new), and `fastsim.flexibility_l1/l2/l3` for a flexibility not finite
    /// and > 0.
    pub fn with_flexibilities(
        input: &FastsimInput,
        flex: &Flexibilities,
        nx: usize,
        ny: usize,
    ) -> Result<Self, InputError> {
        let input = FastsimInput { grid: Grid::Rectangle { scale: 1.0 }, ..*input };
        validate(&input, nx, ny, None)?;
        check_flexibilities(flex)?;
        Ok(Transient { input, flex: *flex, nx, ny })
    }

    /// Cells of the grid, `nx ny`: the least length of a state buffer.
    pub fn cells(&self) -> usize {
        self.nx * self.ny
    }

    /// Cell length along rolling `dx = 2a/nx`, m: the largest step.
    pub fn cell_length_m(&self) -> f64 {
        2.0 * self.input.contact.semi_axis_rolling_m / self.nx as f64
    }

    /// The flexibilities in use.
    pub fn flexibilities(&self) -> Flexibilities {
        self.flex
    }

    /// [`reversal_slope_with_flexibilities`] of this contact, N/m.
    pub fn reversal_slope(&self) -> f64 {
        slope(&self.input, &self.flex)
    }

    fn check(&self, cells: &[Element]) -> Result<(), InputError> {
        if cells.len() < self.cells() {
            return Err(InputError { field: "elements.len", value: cells.len() as f64, valid: ">= nx * ny" });
        }
        Ok(())
    }

    /// Starts the state without traction: the cells' centres, areas and bounds, zero traction
    /// and slip. Returns the totals (all zero).
    ///
    /// # Errors
    /// `elements.len` when `cells` is shorter than [`cells`](Self::cells).
    pub fn start_zero(&self, cells: &mut [Element]) -> Result<FieldTotals, InputError> {
        self.check(cells)?;
        let still = FastsimInput { creep: Creep::default(), ..self.input };
        fastsim::solve(&still, &self.flex, self.nx, self.ny, Some(cells));
        Ok(totals(&self.input, &cells[..self.cells()]))
    }

    /// Starts the state in steady rolling in `direction`: [`fastsim`] on this grid, the step's
    /// fixed point; for [`Direction::Reversed`], the forward solution with the spin reversed
    /// turned half about the normal (module documentation). Returns its totals.
    ///
    /// # Errors
    /// `elements.len` when `cells` is shorter than [`cells`](Self::cells).
    ///
    /// [`fastsim`]: crate::contact::fastsim::fastsim
    pub fn start_steady(&self, direction: Direction, cells: &mut [Element]) -> Result<FieldTotals, InputError> {
        self.check(cells)?;
        let n = self.cells();
        match direction {
            Direction::Forward => {
                fastsim::solve(&self.input, &self.flex, self.nx, self.ny, Some(cells));
            }
            Direction::Reversed => {
                let mirror = FastsimInput {
                    creep: Creep { phi_per_m: -self.input.creep.phi_per_m, ..self.input.creep },
                    ..self.input
                };
                fastsim::solve(&mirror, &self.flex, self.nx, self.ny, Some(cells));
                // (i, j) -> (nx-1-i, ny-1-j) is index k -> n-1-k.
                let field = &mut cells[..n];
                field.reverse();
                for e in field {
                    e.x_m = -e.x_m;
                    e.y_m = -e.y_m;
                    e.traction_x_pa = -e.traction_x_pa;
                    e.traction_y_pa = -e.traction_y_pa;
                    e.slip_x = -e.slip_x;
                    e.slip_y = -e.slip_y;
                }
            }
        }
        Ok(totals(&self.input, &cells[..n]))
    }

    /// Rolls the state `cells` over the distance `ds_m` (m, `0 < ds_m <= dx`, the
    /// [`cell_length_m`](Self::cell_length_m)) in `direction`: advection, rigid-slip increment, clip
    /// (module documentation). Each cell's slip becomes the displacement the clip removed over
    /// `ds_m`. Returns the totals of the new field. The buffer must have been started by
    /// [`start_zero`](Self::start_zero) or [`start_steady`](Self::start_steady) of this contact
    /// and grid.
    ///
    /// # Errors
    /// `elements.len` when `cells` is too short; `ds_m` outside `(0, dx]`.
    pub fn step(&self, cells: &mut [Element], ds_m: f64, direction: Direction) -> Result<FieldTotals, InputError> {
        self.check(cells)?;
        let dx = self.cell_length_m();
        check_range("ds_m", ds_m, 0.0, true, dx, false, "> 0 and <= the cell length 2a/nx")?;
        let setup = Setup::new(&self.input, &self.flex);
        let (l1, l2) = (self.flex.l1_m_per_pa, self.flex.l2_m_per_pa);
        let d = direction.sign();
        let theta = ds_m / dx;
        let n = self.cells();
        for row in cells[..n].chunks_exact_mut(self.nx) {
            advect(row, theta, direction);
            for c in row.iter_mut().filter(|c| c.area_m2 > 0.0) {
                let mut st = March { ux: l1 * c.traction_x_pa, uy: l2 * c.traction_y_pa };
                let (px, py, dux, duy, sliding) =
                    setup.step(&mut st, d * ds_m, c.y_m, c.x_m + d * dx / 6.0, c.bound_pa);
                let (sx, sy) = if sliding { (dux / ds_m, duy / ds_m) } else { (0.0, 0.0) };
                *c = Element { traction_x_pa: px, traction_y_pa: py, slip_x: sx, slip_y: sy, sliding, ..*c };
            }
        }
        Ok(totals(&self.input, &cells[..n]))
    }
}

/// First-order upwind advection of one row's traction (the displacement over constant
/// flexibilities) by `theta` cells; material entering through the leading edge carries none.
fn advect(row: &mut [Element], theta: f64, direction: Direction) {
    let n = row.len();
    let mut blend = |i: usize, up: Option<usize>| {
        if !(row[i].area_m2 > 0.0) {
            return;
        }
        let (ux, uy) = match up {
            Some(k) if row[k].area_m2 > 0.0 => (row[k].traction_x_pa, row[k].traction_y_pa),
            _ => (0.0, 0.0),
        };
        let c = &mut row[i];
        c.traction_x_pa = (1.0 - theta) * c.traction_x_pa + theta * ux;
        c.traction_y_pa = (1.0 - theta) * c.traction_y_pa + theta * uy;
    };
    // Downstream first, so that each cell blends with its upstream neighbour's old value.
    match direction {
        Direction::Forward => (0..n).for_each(|i| blend(i, if i + 1 < n { Some(i + 1) } else { None })),
        Direction::Reversed => (0..n).rev().for_each(|i| blend(i, i.checked_sub(1))),
    }
}

/// One step of Dahl's first-order friction model `dz/ds = sigma (1 - z sign(ds) / z_max)` over
/// the signed distance `ds` at a constant bound `z_max`, integrated exactly:
/// `z <- z_ss + (z - z_ss) exp(-sigma |ds| / z_max)` with `z_ss = sign(ds) z_max` (P.R. Dahl,
/// 1968, 1976; module documentation). `state` and `bound` share a unit (N for a contact's
/// creepage power), `stiffness` is that unit per unit distance, `ds` a distance. A zero bound
/// gives 0 whatever `ds`; otherwise a zero `ds` leaves the state. Generic over the evaluation's
/// float types (f64, f32).
///
/// # Errors
/// An [`InputError`] naming the first invalid argument: `dahl.state` and `dahl.ds` must be
/// finite, `dahl.bound` and `dahl.stiffness` finite and >= 0.
pub fn dahl_step<T: Real>(state: T, bound: T, stiffness: T, ds: T) -> Result<T, InputError> {
    let inf = f64::INFINITY;
    check_range("dahl.state", state.to_f64(), -inf, true, inf, true, "finite")?;
    check_range("dahl.bound", bound.to_f64(), 0.0, false, inf, true, "finite and >= 0")?;
    check_range("dahl.stiffness", stiffness.to_f64(), 0.0, false, inf, true, "finite and >= 0")?;
    check_range("dahl.ds", ds.to_f64(), -inf, true, inf, true, "finite")?;
    if bound == T::zero() {
        return Ok(T::zero());
    }
    if ds == T::zero() {
        return Ok(state);
    }
    let steady = if ds > T::zero() { bound } else { -bound };
    Ok(steady + (state - steady) * (-(stiffness * ds.abs() / bound)).exp())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::fastsim::tests::ball_screw_like;
    use crate::contact::fastsim::{TractionBound, fastsim, fastsim_with_flexibilities};
    use crate::contact::patch::Contact;
    extern crate alloc;
    use alloc::vec;
    use alloc::vec::Vec;

    /// A field buffer on the heap (a test's large grids would overflow its stack).
    fn buffer(n: usize) -> Vec<Element> {
        vec![Element::default(); n]
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a / b - 1.0).abs()
    }

    /// A groove contact of a ball screw (a/b = 0.12) in partial slip: all four creepages.
    fn groove(xi: f64, eta: f64, phi: f64, kh: f64) -> FastsimInput {
        let like = ball_screw_like(xi, eta, phi, TractionBound::Parabolic);
        FastsimInput { creep: Creep { heathcote_per_m2: kh, ..like.creep }, ..like }
    }

    /// Forces and moment equal to rounding (`arm` scales the moment).
    fn same_totals(t: &FieldTotals, fe: f64, ff: f64, m: f64, arm: f64) -> bool {
        let tol = 1e-12 * fe.hypot(ff);
        (t.force_e_n - fe).abs() < tol && (t.force_f_n - ff).abs() < tol && (t.spin_moment_nm - m).abs() < tol * arm
    }

    /// Partial slip cases: mixed creepages on the groove contact, and pure eta on a round one.
    fn cases() -> [FastsimInput; 3] {
        let eta = groove(0.0, 8e-4, 0.0, 0.0);
        [
            groove(2e-4, -1e-4, 1.0, 100.0),
            groove(-2e-4, 0.0, -2.0, 0.0),
            FastsimInput {
                contact: Contact { semi_axis_rolling_m: 1e-3, semi_axis_lateral_m: 1e-3, ..eta.contact },
                bound: TractionBound::Elliptical,
                ..eta
            },
        ]
    }

    #[test]
    fn reversal_slope_closed_form_matches_quadrature() {
        // Midpoint rule in elliptic coordinates (x, y) = (a r cos t, b r sin t), dA = a b r dr dt.
        let inp = cases()[0];
        let flex = kalker(&inp);
        let k = reversal_slope(&inp).unwrap();
        let (a, b) = (inp.contact.semi_axis_rolling_m, inp.contact.semi_axis_lateral_m);
        let quadrature = |n: usize| {
            let (cx, cy) = (flex.l1_m_per_pa / flex.l3_m_per_pa, flex.l2_m_per_pa / flex.l3_m_per_pa);
            let mut sum = 0.0;
            for i in 0..n {
                let r = (i as f64 + 0.5) / n as f64;
                for j in 0..4 * n {
                    let t = 2.0 * PI * (j as f64 + 0.5) / (4 * n) as f64;
                    let (x, y) = (a * r * t.cos(), b * r * t.sin());
                    let ax = inp.creep.xi + inp.creep.heathcote_per_m2 * y * y;
                    let (wx, wy) = (ax - cx * inp.creep.phi_per_m * y, inp.creep.eta + cy * inp.creep.phi_per_m * x);
                    let (sx, sy) = (ax - inp.creep.phi_per_m * y, inp.creep.eta + inp.creep.phi_per_m * x);
                    let da = a * b * r * (1.0 / n as f64) * (2.0 * PI / (4 * n) as f64);
                    sum += (wx * sx / flex.l1_m_per_pa + wy * sy / flex.l2_m_per_pa) * da;
                }
            }
            sum
        };
        // Second order: 0.70, 0.18, 0.044 % (measured).
        let errors = [8, 16, 32].map(|n| rel(quadrature(n), k));
        assert!(errors[0] > 3.5 * errors[1] && errors[1] > 3.5 * errors[2], "{errors:?}");
        assert!(errors[2] < 1e-3, "{errors:?}");
        // Each term alone is > 0, and the slope does not depend on the signs of the creepages.
        let flipped = FastsimInput {
            creep: Creep {
                xi: -inp.creep.xi,
                eta: -inp.creep.eta,
                phi_per_m: -inp.creep.phi_per_m,
                heathcote_per_m2: -inp.creep.heathcote_per_m2,
            },
            ..inp
        };
        assert!(rel(reversal_slope(&flipped).unwrap(), k) < 1e-15);
        for only in [groove(1e-4, 0.0, 0.0, 0.0), groove(0.0, 1e-4, 0.0, 0.0), groove(0.0, 0.0, 10.0, 0.0)] {
            assert!(reversal_slope(&only).unwrap() > 0.0);
        }
        assert_eq!(reversal_slope(&groove(0.0, 0.0, 0.0, 0.0)).unwrap(), 0.0);
    }

    #[test]
    fn creepage_power_of_a_steady_field() {
        let mut buf = buffer(200 * 200);
        for inp in cases() {
            let r = fastsim(&inp, 100, 100, Some(&mut buf[..])).unwrap();
            let t = field_totals(&inp, &buf[..100 * 100]).unwrap();
            assert_eq!((t.adhesion_elements, t.slip_elements), (r.adhesion_elements, r.slip_elements));
            assert!(same_totals(&t, r.force_e_n, r.force_f_n, r.spin_moment_nm, inp.contact.semi_axis_lateral_m));
            assert!(rel(t.dissipation_n, r.dissipation_per_speed_n) < 1e-12);
            // P is the power of the forces on the creepages, Heathcote field included.
            let heathcote: f64 = buf[..100 * 100].iter().map(|e| e.traction_x_pa * e.y_m * e.y_m * e.area_m2).sum();
            let power = -(r.force_e_n * inp.creep.xi
                + r.force_f_n * inp.creep.eta
                + r.spin_moment_nm * inp.creep.phi_per_m
                + inp.creep.heathcote_per_m2 * heathcote);
            assert!(rel(t.creepage_power_n, power) < 1e-9, "{} vs {power}", t.creepage_power_n);
            assert!(t.creepage_power_n > 0.0);
            // With one flexibility for all three (w = s), FASTSIM's dissipation is P up to its
            // numerical dissipation, which shrinks with the grid.
            let l = kalker(&inp).l1_m_per_pa;
            let same = Flexibilities { l1_m_per_pa: l, l2_m_per_pa: l, l3_m_per_pa: l };
            let gap = |n: usize, buf: &mut [Element]| {
                let r = fastsim_with_flexibilities(&inp, &same, n, n, Some(buf)).unwrap();
                rel(r.dissipation_per_speed_n, field_totals(&inp, &buf[..n * n]).unwrap().creepage_power_n)
            };
            // First order: 6 % at 50 x 50, 1.6 % at 200 x 200 (measured, the worst case).
            let (coarse, fine) = (gap(50, &mut buf), gap(200, &mut buf));
            assert!(fine < 0.02 && fine < coarse / 3.0, "{coarse} {fine}");
        }
        // With Kalker's flexibilities the spin's scaling separates them: by 50 % for pure spin
        // on the groove contact (L1/L3 and L2/L3 far from 1 at a/b = 0.12).
        let inp = groove(0.0, 0.0, 60.0, 0.0);
        let r = fastsim(&inp, 100, 100, Some(&mut buf[..])).unwrap();
        let p = field_totals(&inp, &buf[..100 * 100]).unwrap().creepage_power_n;
        assert!(rel(r.dissipation_per_speed_n, p) > 0.3, "D {} P {p}", r.dissipation_per_speed_n);
    }

    /// Rolls `cells` over `distance` in steps of at most `ds`; returns the last totals.
    fn roll(t: &Transient, cells: &mut [Element], distance: f64, ds: f64, dir: Direction) -> FieldTotals {
        // Whole steps of `ds` when the distance is a multiple of it (to rounding).
        let steps = (distance / ds * (1.0 - 1e-12)).ceil() as usize;
        let mut last = FieldTotals::default();
        for _ in 0..steps {
            last = t.step(cells, distance / steps as f64, dir).unwrap();
        }
        last
    }

    fn max_traction_gap(a: &[Element], b: &[Element]) -> f64 {
        let scale = a.iter().map(|e| e.bound_pa).fold(0.0, f64::max);
        a.iter()
            .zip(b)
            .map(|(p, q)| (p.traction_x_pa - q.traction_x_pa).hypot(p.traction_y_pa - q.traction_y_pa))
            .fold(0.0, f64::max)
            / scale
    }

    #[test]
    fn the_step_has_fastsim_on_the_rectangle_as_fixed_point() {
        let (nx, ny) = (30, 24);
        let mut rolled = buffer(30 * 24);
        let mut steady = buffer(30 * 24);
        for inp in cases() {
            let t = Transient::new(&inp, nx, ny).unwrap();
            let dx = t.cell_length_m();
            for dir in [Direction::Forward, Direction::Reversed] {
                let s = t.start_steady(dir, &mut steady).unwrap();
                // Rolled from zero in whole cells: the march itself, exact after nx steps.
                t.start_zero(&mut rolled).unwrap();
                let r = roll(&t, &mut rolled, 2.0 * inp.contact.semi_axis_rolling_m, dx, dir);
                assert!(max_traction_gap(&rolled, &steady) < 1e-12, "{dir:?}");
                assert!(rel(r.creepage_power_n, s.creepage_power_n) < 1e-12);
                assert_eq!((r.adhesion_elements, r.slip_elements), (s.adhesion_elements, s.slip_elements));
                // In fractions of a cell: the same fixed point, reached asymptotically.
                let r = roll(&t, &mut rolled, 8.0 * inp.contact.semi_axis_rolling_m, 0.37 * dx, dir);
                assert!(max_traction_gap(&rolled, &steady) < 1e-9, "{dir:?}");
                assert!(rel(r.creepage_power_n, s.creepage_power_n) < 1e-9);
                // And a step from the steady state stays there.
                let again = t.step(&mut steady, 0.5 * dx, dir).unwrap();
                assert!(rel(again.creepage_power_n, s.creepage_power_n) < 1e-12);
            }
            // The forward start is fastsim's field on the same grid.
            let f = fastsim(&FastsimInput { grid: Grid::Rectangle { scale: 1.0 }, ..inp }, nx, ny, None).unwrap();
            let s = t.start_steady(Direction::Forward, &mut steady).unwrap();
            assert!(same_totals(&s, f.force_e_n, f.force_f_n, f.spin_moment_nm, inp.contact.semi_axis_lateral_m));
            assert_eq!((s.adhesion_elements, s.slip_elements), (f.adhesion_elements, f.slip_elements));
        }
    }

    #[test]
    fn rolling_from_zero_reaches_fastsim_on_kalkers_grid() {
        // The transient grid is first order: the largest of the errors in F_e, F_f (over |F|), M
        // (over |F| max(a, b)) and P against Kalker's strips grid at 200 x 200, measured at
        // n = 20, 40, 80, 160: 2.9, 1.3, 0.79, 0.35 %; 2.5, 0.96, 0.42, 0.21 %; 0.27, 0.12,
        // 0.067, 0.046 %.
        let mut cells = buffer(160 * 160);
        let mut strips = buffer(200 * 200);
        for inp in cases() {
            let f = fastsim(&inp, 200, 200, Some(&mut strips[..])).unwrap();
            let p = field_totals(&inp, &strips).unwrap().creepage_power_n;
            let force = f.force_e_n.hypot(f.force_f_n);
            let arm = inp.contact.semi_axis_rolling_m.max(inp.contact.semi_axis_lateral_m);
            let mut previous = f64::INFINITY;
            for n in [20, 40, 80, 160] {
                let t = Transient::new(&inp, n, n).unwrap();
                t.start_zero(&mut cells).unwrap();
                let r =
                    roll(&t, &mut cells, 2.5 * inp.contact.semi_axis_rolling_m, t.cell_length_m(), Direction::Forward);
                let error = [
                    (r.force_e_n - f.force_e_n).abs() / force,
                    (r.force_f_n - f.force_f_n).abs() / force,
                    (r.spin_moment_nm - f.spin_moment_nm).abs() / (force * arm),
                    rel(r.creepage_power_n, p),
                ]
                .into_iter()
                .fold(0.0, f64::max);
                assert!(error < 2.0 / n as f64, "n {n}: {error}");
                assert!(error < previous, "n {n}: {error} after {previous}");
                previous = error;
            }
            assert!(previous < 0.01);
        }
    }

    #[test]
    fn reversal_goes_over_to_the_half_turned_steady_state() {
        let mut cells = buffer(80 * 80);
        let mut strips = buffer(200 * 200);
        for inp in cases() {
            let t = Transient::new(&inp, 80, 80).unwrap();
            let fwd = t.start_steady(Direction::Forward, &mut cells).unwrap();
            let r = roll(&t, &mut cells, 2.5 * inp.contact.semi_axis_rolling_m, t.cell_length_m(), Direction::Reversed);
            // Fastsim with the spin reversed: F_e, F_f, P negate, M does not. Measured at 80 x 80
            // (largest of the four errors, scaled as in the test above): 0.59, 0.42, 0.07 %.
            let half_turn = FastsimInput { creep: Creep { phi_per_m: -inp.creep.phi_per_m, ..inp.creep }, ..inp };
            let f = fastsim(&half_turn, 200, 200, Some(&mut strips[..])).unwrap();
            let p = field_totals(&half_turn, &strips).unwrap().creepage_power_n;
            let force = f.force_e_n.hypot(f.force_f_n);
            let arm = inp.contact.semi_axis_rolling_m.max(inp.contact.semi_axis_lateral_m);
            assert!((r.force_e_n + f.force_e_n).abs() < 0.01 * force, "{} {}", r.force_e_n, f.force_e_n);
            assert!((r.force_f_n + f.force_f_n).abs() < 0.01 * force, "{} {}", r.force_f_n, f.force_f_n);
            assert!((r.spin_moment_nm - f.spin_moment_nm).abs() < 0.01 * force * arm);
            assert!(rel(-r.creepage_power_n, p) < 0.01, "{} {p}", r.creepage_power_n);
            // Without spin, the forces and P negate exactly on the grid (the moment keeps its sign).
            if inp.creep.phi_per_m == 0.0 {
                let tol = 1e-9 * force;
                assert!((r.force_e_n + fwd.force_e_n).abs() < tol && (r.force_f_n + fwd.force_f_n).abs() < tol);
                assert!(rel(-r.creepage_power_n, fwd.creepage_power_n) < 1e-9);
                assert!((r.spin_moment_nm - fwd.spin_moment_nm).abs() < tol * arm);
            }
        }
        // With eta = 0, F_e, M and P negate and F_f keeps its sign (y mirror of the spin).
        let inp = cases()[1];
        let t = Transient::new(&inp, 80, 80).unwrap();
        let fwd = t.start_steady(Direction::Forward, &mut cells).unwrap();
        let rev = t.start_steady(Direction::Reversed, &mut cells).unwrap();
        let tol = 1e-9 * fwd.force_e_n.hypot(fwd.force_f_n);
        assert!((rev.force_e_n + fwd.force_e_n).abs() < tol && (rev.force_f_n - fwd.force_f_n).abs() < tol);
        assert!((rev.spin_moment_nm + fwd.spin_moment_nm).abs() < tol * 1e-3);
        assert!(rel(-rev.creepage_power_n, fwd.creepage_power_n) < 1e-9);
        assert!(fwd.force_f_n.abs() > 0.05 * fwd.force_e_n.abs(), "the lateral force is not negligible");
    }

    #[test]
    fn slope_just_after_a_reversal_is_the_reversal_slope() {
        // Measured (|slope/K - 1| at n = 20, 40, 80, 160): 4.7, 2.8, 1.1, 0.63 %; 2.6, 1.3, 0.32,
        // 0.56 %; 2.3, 1.7, 0.86, 0.60 %: about 1/n, from the ellipse's staircase edge and the
        // traction the first cells of the new leading edge carry out.
        let mut cells = buffer(160 * 160);
        for inp in cases() {
            let k = reversal_slope(&inp).unwrap();
            let mut errors = [0.0; 4];
            for (e, n) in errors.iter_mut().zip([20, 40, 80, 160]) {
                let t = Transient::new(&inp, n, n).unwrap();
                let before = t.start_steady(Direction::Forward, &mut cells).unwrap();
                assert!(before.slip_elements as usize > n, "partial slip");
                // A short step: the initial slope; every cell leaves the bound.
                let ds = 1e-3 * t.cell_length_m();
                let after = t.step(&mut cells, ds, Direction::Reversed).unwrap();
                assert_eq!(after.slip_elements, 0, "n {n}");
                *e = rel(-(after.creepage_power_n - before.creepage_power_n) / ds, k);
                assert!(*e < 1.5 / n as f64, "n {n}: {e}");
            }
            assert!(errors[3] < errors[0] / 3.0 && errors[3] < 0.01, "{errors:?}");
        }
    }

    #[test]
    fn linear_limit_from_zero_grows_with_the_slope_and_is_steady_at_two_a() {
        let n = 80;
        let mut cells = buffer(80 * 80);
        let mut steady = buffer(80 * 80);
        for inp in cases() {
            let inp = FastsimInput { contact: Contact { friction_coefficient: 1e3, ..inp.contact }, ..inp };
            let t = Transient::new(&inp, n, n).unwrap();
            let k = reversal_slope(&inp).unwrap();
            let s = t.start_steady(Direction::Forward, &mut steady).unwrap();
            assert_eq!(s.slip_elements, 0);
            t.start_zero(&mut cells).unwrap();
            let ds = t.cell_length_m();
            let mut p = 0.0;
            for step in 1..=n {
                let r = t.step(&mut cells, ds, Direction::Forward).unwrap();
                assert_eq!(r.slip_elements, 0);
                if step == 1 {
                    assert!(rel(r.creepage_power_n / ds, k) < 0.02, "{} vs {k}", r.creepage_power_n / ds);
                }
                // Growing, at most at the initial slope.
                assert!(r.creepage_power_n > p && r.creepage_power_n - p <= k * ds * 1.02);
                p = r.creepage_power_n;
            }
            // After 2a, steady.
            assert!(rel(p, s.creepage_power_n) < 1e-12, "{p} vs {}", s.creepage_power_n);
        }
    }

    #[test]
    fn dahl_step_is_exact_and_bounded() {
        let (bound, sigma) = (2.0_f64, 5e3);
        // Two half steps are one step.
        let one = dahl_step(-1.5, bound, sigma, 3e-4).unwrap();
        let two = dahl_step(dahl_step(-1.5, bound, sigma, 1.5e-4).unwrap(), bound, sigma, 1.5e-4).unwrap();
        assert!((one - two).abs() < 1e-14);
        // Slope from the reversed steady state is 2 sigma, from zero sigma.
        let h = 1e-9;
        assert!(rel((dahl_step(-bound, bound, sigma, h).unwrap() + bound) / h, 2.0 * sigma) < 1e-5);
        assert!(rel(dahl_step(0.0, bound, sigma, -h).unwrap() / -h, sigma) < 1e-5);
        // Half-way from -bound to +bound after ln 2 relaxation lengths.
        let half = dahl_step(-bound, bound, sigma, bound / sigma * core::f64::consts::LN_2).unwrap();
        assert!(half.abs() < 1e-12);
        // Stays within the bound, tends to it.
        assert!((dahl_step(0.3, bound, sigma, 1.0).unwrap() - bound).abs() < 1e-12);
        assert!((dahl_step(0.3, bound, sigma, -1.0).unwrap() + bound).abs() < 1e-12);
        // Edge cases: zero bound, zero step, zero stiffness.
        assert_eq!(dahl_step(0.7, 0.0, sigma, 1e-3).unwrap(), 0.0);
        assert_eq!(dahl_step(0.7, bound, sigma, 0.0).unwrap(), 0.7);
        assert_eq!(dahl_step(0.7, bound, 0.0, 1e-3).unwrap(), 0.7);
        // f32 follows f64.
        let z32 = dahl_step(-1.5_f32, 2.0, 5e3, 3e-4).unwrap();
        assert!((f64::from(z32) - one).abs() < 1e-6);
        // Bad input names the argument.
        assert_eq!(dahl_step(f64::NAN, 1.0, 1.0, 1.0).unwrap_err().field, "dahl.state");
        assert_eq!(dahl_step(0.0, -1.0, 1.0, 1.0).unwrap_err().field, "dahl.bound");
        assert_eq!(dahl_step(0.0, 1.0, f64::INFINITY, 1.0).unwrap_err().field, "dahl.stiffness");
        assert_eq!(dahl_step(0.0_f32, 1.0, 1.0, f32::NAN).unwrap_err().field, "dahl.ds");
    }

    #[test]
    fn invalid_inputs_name_the_field() {
        let ok = cases()[0];
        assert_eq!(
            reversal_slope(&FastsimInput { creep: Creep { xi: f64::NAN, ..ok.creep }, ..ok }).unwrap_err().field,
            "fastsim.xi"
        );
        let bad = Flexibilities { l1_m_per_pa: 1.0, l2_m_per_pa: 1.0, l3_m_per_pa: -1.0 };
        assert_eq!(reversal_slope_with_flexibilities(&ok, &bad).unwrap_err().field, "fastsim.flexibility_l3");
        assert_eq!(Transient::with_flexibilities(&ok, &bad, 4, 4).unwrap_err().field, "fastsim.flexibility_l3");
        let e = |inp: FastsimInput, nx, ny| Transient::new(&inp, nx, ny).unwrap_err().field;
        assert_eq!(
            e(FastsimInput { contact: Contact { semi_axis_rolling_m: 0.0, ..ok.contact }, ..ok }, 4, 4),
            "fastsim.semi_axis_rolling_m"
        );
        assert_eq!(e(ok, 0, 4), "nx");
        assert_eq!(e(ok, 4, 1001), "ny");
        // The grid of the input is not used.
        assert!(Transient::new(&FastsimInput { grid: Grid::Rectangle { scale: 0.0 }, ..ok }, 4, 4).is_ok());
        assert_eq!(
            field_totals(&FastsimInput { creep: Creep { eta: f64::INFINITY, ..ok.creep }, ..ok }, &[])
                .unwrap_err()
                .field,
            "fastsim.eta"
        );
        let t = Transient::new(&ok, 4, 4).unwrap();
        let mut small = [Element::default(); 15];
        assert_eq!(t.start_zero(&mut small).unwrap_err().field, "elements.len");
        assert_eq!(t.start_steady(Direction::Forward, &mut small).unwrap_err().field, "elements.len");
        assert_eq!(t.step(&mut small, 1e-6, Direction::Forward).unwrap_err().field, "elements.len");
        let mut cells = [Element::default(); 16];
        t.start_zero(&mut cells).unwrap();
        let dx = t.cell_length_m();
        for ds in [0.0, -dx, 1.001 * dx, f64::NAN] {
            assert_eq!(t.step(&mut cells, ds, Direction::Forward).unwrap_err().field, "ds_m");
        }
        assert!(t.step(&mut cells, dx, Direction::Reversed).is_ok());
        assert_eq!(Direction::Forward.reversed(), Direction::Reversed);
        assert_eq!(Direction::Reversed.sign(), -1.0);
    }
}
