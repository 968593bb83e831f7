//! Kalker's simplified theory of rolling contact solved by FASTSIM (J.J. Kalker, "A fast
//! algorithm for the simplified theory of rolling contact", Veh. Syst. Dyn. 11 (1982) 1-13,
//! ref. \[11\] of Xu et al. 2015) over a Hertz ellipse: the traction field, slip field and the
//! resulting creep forces of one contact.
//!
//! Xu et al. use Kalker's linear theory (Eq. 23) for the forces, but their sections 3.2 and 3.3
//! (Figs. 9 and 10) discuss how the creep force grows non-linearly with the creepages and how the
//! slip area spreads from the trailing edge over the ellipse; Fig. 10 is a traction field.
//! FASTSIM computes exactly that: the non-linear creep force without an empirical saturation
//! law, the spin moment, the Heathcote slip as a field (`xi(y) = xi + k_h y^2`, `docs/model-notes.md`
//! item 5) and the adhesion/slip division of the ellipse.
//!
//! # Theory
//! The simplified theory replaces the elastic half-space by independent springs: the surface
//! displacement difference is `u = (L1 px, L2 py)` with Kalker's three flexibilities
//! (`a` the semi-axis along rolling, `b` the lateral one, `G` the shear modulus):
//! `L1 = 8a/(3 G C11)`, `L2 = 8a/(3 G C22)`, `L3 = pi a sqrt(a/b)/(4 G C23)`
//! ([`Flexibilities::kalker`], coefficients from [`kalker_table`]). With them the linear limit
//! of the simplified theory reproduces Kalker's linear theory exactly for `F_e(xi)`, `F_f(eta)`
//! and `F_f(phi)`; the spin moment is not reproduced (the simplified theory gives
//! `M(eta) = pi a^3 b eta/(4 L2)` and `M(phi) = -8 a^2 b^3 phi/(15 L3)`, off Kalker's `C23`,
//! `C33` by tens of % depending on `a/b`: a known limit of FASTSIM).
//!
//! Rigid slip per unit rolling speed (spin scaled by `L1/L3`, `L2/L3` as in CONTACT's
//! three-flexibility FASTSIM): `w = (xi + k_h y^2 - (L1/L3) phi y, eta + (L2/L3) phi x)`.
//! Steady rolling, the material entering at the leading edge `x = +a(y)` without traction:
//! in adhesion `du/dx = w`, i.e. `u(x) = -int_x^a(y) w dx'`. Each strip is integrated from its
//! leading edge; where the trial traction `|p| > g` (the traction bound `g = mu p_n`) the
//! traction is scaled back onto the bound along its own direction, and the difference in
//! displacement is the local slip `s = (u - u_trial)/dx`. The traction on the ball opposes the
//! ball's slip, so `p . s <= 0` in every sliding element.
//!
//! Traction bound (`mu` times a pressure): [`TractionBound::Elliptical`] is the Hertz pressure
//! `3 Fn/(2 pi a b) sqrt(1 - x^2/a^2 - y^2/b^2)`; [`TractionBound::Parabolic`] is Kalker's choice
//! for FASTSIM, `2 Fn/(pi a b) (1 - x^2/a^2 - y^2/b^2)`, which matches the simplified theory's
//! linear traction near the leading edge better (the elliptical bound, with its infinite slope at
//! the edge, gives FASTSIM spurious slip patches: CONTACT's `fastsim.inp` shows them).
//!
//! # Conventions (the project's, `forces`, `creep`)
//! Forces and moment on the ball, in the contact frame (e, f, g): x along the rolling direction
//! e (the direction in which the contact moves over the bodies; leading edge at `x = +a`),
//! y along f = g x e, spin about g; `xi`, `eta`, `phi` the creepages of the ball relative to the
//! other body. Kalker's linear limit is then `F_e = -G c^2 C11 xi`,
//! `F_f = -G c^2 (C22 eta + C23 c phi)` ([`forces::linear`]).
//!
//! This is also CONTACT's convention (E.A.H. Vollebregt, open source, `eve70a/CONTACT`) with
//! rolling direction `CHI = 0` (its FASTSIM processes every row from the largest x down):
//! CONTACT's body 1 is the ball, `(CKSI, CETA, CPHI) = (xi, eta, phi)`, `(FX, FY, MZ) =
//! (F_e, F_f, M)`, `(FLX1, FLX2, FLX3) = (L1, L2, L3)`; no sign changes. The reference case
//! `fastsim.inp` (lateral creepage and spin) comes out with the same signs as CONTACT's output.
//!
//! # Grids
//! - [`Grid::Strips`] (Kalker's FASTSIM, the recommended choice): `ny` strips of equal width over
//!   `[-b, b]`, each strip's chord `[-a(y), a(y)]` cut into `nx` equal elements. Displacements
//!   are integrated exactly at the element centres for a rigid slip linear in x (a half step
//!   from the leading edge, then whole steps with the slip at the interval midpoints), so the
//!   linear limit converges like the midpoint rule (error about `1/(2 ny^2)` in the force).
//!   The bound of an element is `mu` times its share of the exact Hertz (or parabolic) load of
//!   its strip, so the bounds add up to exactly `mu Fn` for any grid: at full slip
//!   `|F| = mu Fn` exactly.
//! - [`Grid::Rectangle`] (CONTACT's discretisation, to reproduce its numbers): `nx x ny` equal
//!   cells over the rectangle `[-s a, s a] x [-s b, s b]` (`s` = CONTACT's `SCALE`); the cells
//!   whose centres lie strictly inside the ellipse are in contact, the others are exterior
//!   (zero area in [`Element`]). Each row is marched from its first cell with an implicit-Euler
//!   step `u_i = u_(i+1) - dx w(x_i, y)` (CONTACT's `dq = dx` for steady rolling), the spin's
//!   lateral slip taken at `x_i + dx/6` (CONTACT's default `FACPHI = 1/6`), the bound taken at
//!   the cell centres. CONTACT's `MX, MY, SCALE` map one to one onto `nx, ny, s`
//!   (`MX = 44, SCALE = 1.1` is the same grid as `nx = 40, s = 1`). This scheme overestimates
//!   the linear-limit force by roughly `1.5/n` (7 % at 20 x 20 over the ellipse, 3 % at
//!   CONTACT's 48 x 44 of `tractcurv.inp`), against 0.13 % for [`Grid::Strips`] at 20 x 20; both
//!   converge to the same solution.
//!
//! Nothing allocates: the element field goes to a caller-provided buffer when wanted
//! (`elements[j nx + i]`, `i` along x increasing from the trailing edge, `j` along y
//! increasing); without a buffer only the totals are computed.
//!
//! [`kalker_table`]: crate::contact::kalker::kalker_table
//! [`forces::linear`]: crate::contact::forces::linear

use core::f64::consts::PI;

use crate::contact::kalker::kalker_table;
use crate::contact::patch::{Contact, Creep};
use crate::error::{InputError, check_range};

/// Largest grid size along either axis.
pub const MAX_GRID: usize = 1000;

/// Shape of the traction bound `g = mu p_n` over the ellipse.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TractionBound {
    /// Kalker's parabolic pressure `2 Fn/(pi a b) (1 - x^2/a^2 - y^2/b^2)` (FASTSIM's usual bound).
    Parabolic,
    /// The Hertz (semi-ellipsoidal) pressure `3 Fn/(2 pi a b) sqrt(1 - x^2/a^2 - y^2/b^2)`.
    Elliptical,
}

impl TractionBound {
    /// Both, Kalker's first.
    pub const ALL: [TractionBound; 2] = [TractionBound::Parabolic, TractionBound::Elliptical];

    /// Its name in reports and arguments: `parabolic` or `elliptical`.
    pub fn name(self) -> &'static str {
        match self {
            TractionBound::Parabolic => "parabolic",
            TractionBound::Elliptical => "elliptical",
        }
    }

    /// The bound of a [`name`](Self::name); `None` for any other text.
    pub fn parse(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|b| b.name() == name)
    }
}

/// How the ellipse is discretised (see the module documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Grid {
    /// Kalker's FASTSIM grid: `ny` strips of equal width, each chord cut into `nx` equal
    /// elements; bounds normalised so that they add up to `mu Fn` exactly.
    Strips,
    /// CONTACT's grid: `nx x ny` equal cells over `[-scale a, scale a] x [-scale b, scale b]`,
    /// the cells with centres inside the ellipse in contact, implicit-Euler marching.
    Rectangle {
        /// Rectangle over ellipse bounding box, CONTACT's `SCALE`: finite, in `[1, 10]`.
        scale: f64,
    },
}

/// One contact for [`fastsim`]: Hertz ellipse, load, material, friction and creepages, with the
/// traction bound and the grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FastsimInput {
    /// Semi-axes `a` (along the rolling direction e) and `b` (along the lateral direction f),
    /// normal load Fn, shear modulus G, Poisson's ratio and friction coefficient mu. G enters
    /// through the flexibilities only, Poisson's ratio through Kalker's coefficients only.
    pub contact: Contact,
    /// Creepages, each finite: `xi` at the centre line `y = 0` (from a `creep::Creepage`, its
    /// `xi` minus its `heathcote` part), eta, the spin phi about g (1/m), and the Heathcote
    /// coefficient `k_h` (1/m^2) of the extra longitudinal creepage `k_h y^2`, whose
    /// Hertz-pressure-weighted mean over the ellipse is `k_h b^2/5` (the scalar
    /// `creep::Creepage::heathcote`).
    pub creep: Creep,
    /// Shape of the traction bound.
    pub bound: TractionBound,
    /// Discretisation of the ellipse.
    pub grid: Grid,
}

/// Kalker's flexibilities of the simplified theory, m/Pa (= m^3/N): `u = (L1 px, L2 py)`, the
/// spin acting through `L3`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Flexibilities {
    /// Longitudinal flexibility L1.
    pub l1_m_per_pa: f64,
    /// Lateral flexibility L2.
    pub l2_m_per_pa: f64,
    /// Spin flexibility L3.
    pub l3_m_per_pa: f64,
}

impl Flexibilities {
    /// Kalker's choice, which makes the simplified theory's linear limit match the linear theory
    /// for `F_e(xi)`, `F_f(eta)`, `F_f(phi)`: `L1 = 8a/(3 G C11)`, `L2 = 8a/(3 G C22)`,
    /// `L3 = pi a sqrt(a/b)/(4 G C23)`, with `C11, C22, C23` from [`kalker_table`] at `a/b`, nu
    /// (clamped outside `a/b in [0.1, 10]`, see `kalker`). No validation: NaN in, NaN out.
    ///
    /// [`kalker_table`]: crate::contact::kalker::kalker_table
    pub fn kalker(
        semi_axis_rolling_m: f64,
        semi_axis_lateral_m: f64,
        shear_modulus_pa: f64,
        poisson_ratio: f64,
    ) -> Self {
        let a = semi_axis_rolling_m;
        let b = semi_axis_lateral_m;
        let g = shear_modulus_pa;
        let c = kalker_table(a / b, poisson_ratio);
        Flexibilities {
            l1_m_per_pa: 8.0 * a / (3.0 * g * c.c11),
            l2_m_per_pa: 8.0 * a / (3.0 * g * c.c22),
            l3_m_per_pa: PI * a * libm::sqrt(a / b) / (4.0 * g * c.c23),
        }
    }
}

/// One element of the traction field.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Element {
    /// Centre, along e (rolling), m.
    pub x_m: f64,
    /// Centre, along f (lateral), m.
    pub y_m: f64,
    /// Area, m^2 (0 for a cell outside the ellipse on a [`Grid::Rectangle`]).
    pub area_m2: f64,
    /// Traction on the ball along e, Pa.
    pub traction_x_pa: f64,
    /// Traction on the ball along f, Pa.
    pub traction_y_pa: f64,
    /// Traction bound `mu p_n`, Pa ([`Grid::Strips`]: `mu` times the element's mean pressure,
    /// normalised to the exact strip load; [`Grid::Rectangle`]: at the cell centre).
    pub bound_pa: f64,
    /// Local slip of the ball along e per unit rolling speed (the displacement jump over the
    /// element divided by its length; 0 in adhesion).
    pub slip_x: f64,
    /// Local slip of the ball along f per unit rolling speed.
    pub slip_y: f64,
    /// True where the traction is on the bound (slip area).
    pub sliding: bool,
}

/// Totals of one FASTSIM solution.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FastsimResult {
    /// Creep force on the ball along e, N.
    pub force_e_n: f64,
    /// Creep force on the ball along f, N.
    pub force_f_n: f64,
    /// Spin moment on the ball about g through the ellipse centre, `sum (x py - y px) dA`, N m.
    pub spin_moment_nm: f64,
    /// Dissipated power over rolling speed, N: `-sum p . s dA` over the sliding elements
    /// (the traction on the ball opposes its slip, so every term is >= 0).
    pub dissipation_per_speed_n: f64,
    /// Number of elements in adhesion.
    pub adhesion_elements: u32,
    /// Number of elements sliding.
    pub slip_elements: u32,
}

impl FastsimResult {
    /// Elements in adhesion over all elements in contact, in `[0, 1]`. NaN when no element is
    /// in contact, which happens only on a [`Grid::Rectangle`] whose cell centres all miss the
    /// ellipse, never on [`Grid::Strips`] (every element lies in the ellipse).
    pub fn adhesion_share(&self) -> f64 {
        let in_contact = self.adhesion_elements + self.slip_elements;
        if in_contact > 0 { f64::from(self.adhesion_elements) / f64::from(in_contact) } else { f64::NAN }
    }
}

/// `k_h b^2` over the Heathcote mean: the Hertz-pressure-weighted mean over the ellipse of the
/// extra longitudinal creepage `k_h y^2` is `k_h b^2 / 5`.
pub const HEATHCOTE_B2_PER_MEAN: f64 = 5.0;

/// Heathcote coefficient `k_h` (1/m^2, [`Creep::heathcote_per_m2`]) of the field whose
/// mean over an ellipse of lateral semi-axis `semi_axis_lateral_m` (b, m) is
/// `heathcote_mean` (the scalar `creep::Creepage::heathcote`): `5 xi_h / b^2`; 0 when b is not
/// positive (no contact).
pub fn heathcote_per_m2(heathcote_mean: f64, semi_axis_lateral_m: f64) -> f64 {
    let b = semi_axis_lateral_m;
    if b > 0.0 { HEATHCOTE_B2_PER_MEAN * heathcote_mean / (b * b) } else { 0.0 }
}

/// The Heathcote mean `k_h b^2 / 5` (dimensionless) of the coefficient `heathcote_per_m2`
/// (`k_h`, 1/m^2) over an ellipse of lateral semi-axis `semi_axis_lateral_m` (b, m): the
/// inverse of [`heathcote_per_m2`].
pub fn heathcote_mean(heathcote_per_m2: f64, semi_axis_lateral_m: f64) -> f64 {
    let b = semi_axis_lateral_m;
    heathcote_per_m2 * b * b / HEATHCOTE_B2_PER_MEAN
}

/// FASTSIM over the Hertz ellipse with Kalker's flexibilities ([`Flexibilities::kalker`]).
///
/// `nx` elements along rolling and `ny` across (each in `1..=1000`); when `elements` is given it
/// must hold at least `nx ny` entries and receives the field (`elements[j nx + i]`).
///
/// # Errors
/// An [`InputError`] naming the first invalid field (`fastsim.*`, `nx`, `ny`, `elements.len`).
pub fn fastsim(
    input: &FastsimInput,
    nx: usize,
    ny: usize,
    elements: Option<&mut [Element]>,
) -> Result<FastsimResult, InputError> {
    validate(input, nx, ny, elements.as_deref())?;
    let c = &input.contact;
    let flex = Flexibilities::kalker(c.semi_axis_rolling_m, c.semi_axis_lateral_m, c.shear_modulus_pa, c.poisson_ratio);
    Ok(solve(input, &flex, nx, ny, elements))
}

/// FASTSIM with given flexibilities (e.g. CONTACT's `FLX1..3`, or one flexibility for all
/// three); `shear_modulus_pa` and `poisson_ratio` of `input` are validated but not used.
///
/// # Errors
/// As [`fastsim`], and `fastsim.flexibility_l1/l2/l3` when a flexibility is not finite and > 0.
pub fn fastsim_with_flexibilities(
    input: &FastsimInput,
    flexibilities: &Flexibilities,
    nx: usize,
    ny: usize,
    elements: Option<&mut [Element]>,
) -> Result<FastsimResult, InputError> {
    validate(input, nx, ny, elements.as_deref())?;
    check_flexibilities(flexibilities)?;
    Ok(solve(input, flexibilities, nx, ny, elements))
}

/// Checks that each flexibility is finite and > 0: an [`InputError`] naming the first that is
/// not (`fastsim.flexibility_l1/l2/l3`).
pub(crate) fn check_flexibilities(flexibilities: &Flexibilities) -> Result<(), InputError> {
    let positive = "finite and > 0";
    check_range("fastsim.flexibility_l1", flexibilities.l1_m_per_pa, 0.0, true, f64::INFINITY, true, positive)?;
    check_range("fastsim.flexibility_l2", flexibilities.l2_m_per_pa, 0.0, true, f64::INFINITY, true, positive)?;
    check_range("fastsim.flexibility_l3", flexibilities.l3_m_per_pa, 0.0, true, f64::INFINITY, true, positive)?;
    Ok(())
}

/// Names in errors of the contact's values of a [`FastsimInput`], in field order: the semi-axes,
/// the load, the shear modulus, Poisson's ratio, the friction coefficient and the four creepages.
pub(crate) type ContactFieldNames = [&'static str; 10];

/// FASTSIM's own names.
pub(crate) const FIELD_NAMES: ContactFieldNames = [
    "fastsim.semi_axis_rolling_m",
    "fastsim.semi_axis_lateral_m",
    "fastsim.normal_load_n",
    "fastsim.shear_modulus_pa",
    "fastsim.poisson_ratio",
    "fastsim.friction_coefficient",
    "fastsim.xi",
    "fastsim.eta",
    "fastsim.phi_per_m",
    "fastsim.heathcote_per_m2",
];

/// Checks the contact's values of `input` (everything but its bound and grid): an
/// [`InputError`] naming the first invalid one by `names`.
pub(crate) fn check_contact_values(input: &FastsimInput, names: &ContactFieldNames) -> Result<(), InputError> {
    let (c, cr) = (&input.contact, &input.creep);
    let inf = f64::INFINITY;
    let positive = "finite and > 0";
    let non_negative = "finite and >= 0";
    let finite = "finite";
    // (value, lower end, open there, upper end, open there, the valid range in words)
    let rules = [
        (c.semi_axis_rolling_m, 0.0, true, inf, true, positive),
        (c.semi_axis_lateral_m, 0.0, true, inf, true, positive),
        (c.normal_load_n, 0.0, false, inf, true, non_negative),
        (c.shear_modulus_pa, 0.0, true, inf, true, positive),
        (c.poisson_ratio, 0.0, false, 0.5, false, "[0, 0.5]"),
        (c.friction_coefficient, 0.0, false, inf, true, non_negative),
        (cr.xi, -inf, true, inf, true, finite),
        (cr.eta, -inf, true, inf, true, finite),
        (cr.phi_per_m, -inf, true, inf, true, finite),
        (cr.heathcote_per_m2, -inf, true, inf, true, finite),
    ];
    for (&name, (value, lo, lo_open, hi, hi_open, valid)) in names.iter().zip(rules) {
        check_range(name, value, lo, lo_open, hi, hi_open, valid)?;
    }
    Ok(())
}

/// Checks `input`, the grid size and the buffer's length: an [`InputError`] naming the first
/// invalid field (`fastsim.*`, `nx`, `ny`, `elements.len`).
pub(crate) fn validate(
    input: &FastsimInput,
    nx: usize,
    ny: usize,
    elements: Option<&[Element]>,
) -> Result<(), InputError> {
    check_contact_values(input, &FIELD_NAMES)?;
    if let Grid::Rectangle { scale } = input.grid {
        check_range("fastsim.grid.scale", scale, 1.0, false, 10.0, false, "[1, 10]")?;
    }
    let grid_valid = "integer in [1, 1000]";
    check_range("nx", nx as f64, 1.0, false, MAX_GRID as f64, false, grid_valid)?;
    check_range("ny", ny as f64, 1.0, false, MAX_GRID as f64, false, grid_valid)?;
    if let Some(buf) = elements
        && buf.len() < nx * ny
    {
        return Err(InputError { field: "elements.len", value: buf.len() as f64, valid: ">= nx * ny" });
    }
    Ok(())
}

/// Everything the march needs that does not change over the ellipse.
pub(crate) struct Setup {
    l1: f64,
    l2: f64,
    /// 1/L1, 1/L2.
    k1: f64,
    k2: f64,
    /// L1/L3 and L2/L3: spin scaling of the rigid slip.
    spin_x: f64,
    spin_y: f64,
    xi: f64,
    eta: f64,
    phi: f64,
    kh: f64,
}

/// Running totals.
#[derive(Default)]
struct Totals {
    fe: f64,
    ff: f64,
    m: f64,
    diss: f64,
    adhesion: u32,
    slip: u32,
}

/// State carried along a strip: the elastic displacement difference of the previous point.
pub(crate) struct March {
    pub(crate) ux: f64,
    pub(crate) uy: f64,
}

impl Setup {
    /// The constants of `input` with the flexibilities `flex`.
    pub(crate) fn new(input: &FastsimInput, flex: &Flexibilities) -> Self {
        Setup {
            l1: flex.l1_m_per_pa,
            l2: flex.l2_m_per_pa,
            k1: 1.0 / flex.l1_m_per_pa,
            k2: 1.0 / flex.l2_m_per_pa,
            spin_x: flex.l1_m_per_pa / flex.l3_m_per_pa,
            spin_y: flex.l2_m_per_pa / flex.l3_m_per_pa,
            xi: input.creep.xi,
            eta: input.creep.eta,
            phi: input.creep.phi_per_m,
            kh: input.creep.heathcote_per_m2,
        }
    }

    /// One step of the march: from the upstream displacement over a distance `h`, with the
    /// longitudinal rigid slip taken at `y` and the lateral one at `x_w`; returns the element
    /// (traction x, y; displacement change by the clip x, y; sliding).
    pub(crate) fn step(&self, st: &mut March, h: f64, y: f64, x_w: f64, bound: f64) -> (f64, f64, f64, f64, bool) {
        let wx = self.xi + self.kh * y * y - self.spin_x * self.phi * y;
        let wy = self.eta + self.spin_y * self.phi * x_w;
        let ux_t = st.ux - h * wx;
        let uy_t = st.uy - h * wy;
        let mut px = ux_t * self.k1;
        let mut py = uy_t * self.k2;
        let pt2 = px * px + py * py;
        if pt2 > bound * bound {
            let k = bound / libm::sqrt(pt2);
            px *= k;
            py *= k;
            st.ux = self.l1 * px;
            st.uy = self.l2 * py;
            (px, py, st.ux - ux_t, st.uy - uy_t, true)
        } else {
            st.ux = ux_t;
            st.uy = uy_t;
            (px, py, 0.0, 0.0, false)
        }
    }
}

/// Adds one element to the totals and, when wanted, stores it.
#[allow(clippy::too_many_arguments, reason = "one element's data, private helper")]
fn record(
    tot: &mut Totals,
    out: &mut Option<&mut [Element]>,
    index: usize,
    x: f64,
    y: f64,
    dx: f64,
    area: f64,
    bound: f64,
    r: (f64, f64, f64, f64, bool),
) {
    let (px, py, dux, duy, sliding) = r;
    let (sx, sy) = if sliding { (dux / dx, duy / dx) } else { (0.0, 0.0) };
    tot.fe += px * area;
    tot.ff += py * area;
    tot.m += (x * py - y * px) * area;
    if sliding {
        tot.diss -= (px * sx + py * sy) * area;
        tot.slip += 1;
    } else {
        tot.adhesion += 1;
    }
    if let Some(buf) = out.as_deref_mut() {
        buf[index] = Element {
            x_m: x,
            y_m: y,
            area_m2: area,
            traction_x_pa: px,
            traction_y_pa: py,
            bound_pa: bound,
            slip_x: sx,
            slip_y: sy,
            sliding,
        };
    }
}

/// FASTSIM on a validated input (see [`validate`], [`check_flexibilities`]).
pub(crate) fn solve(
    input: &FastsimInput,
    flex: &Flexibilities,
    nx: usize,
    ny: usize,
    mut elements: Option<&mut [Element]>,
) -> FastsimResult {
    let setup = Setup::new(input, flex);
    let mut tot = Totals::default();
    match input.grid {
        Grid::Strips => strips(input, &setup, nx, ny, &mut tot, &mut elements),
        Grid::Rectangle { scale } => rectangle(input, &setup, scale, nx, ny, &mut tot, &mut elements),
    }
    FastsimResult {
        force_e_n: tot.fe,
        force_f_n: tot.ff,
        spin_moment_nm: tot.m,
        dissipation_per_speed_n: tot.diss,
        adhesion_elements: tot.adhesion,
        slip_elements: tot.slip,
    }
}

/// Peak pressure of the bound's shape for load `fn_n` over the ellipse `a b`.
fn peak_pressure(bound: TractionBound, fn_n: f64, a: f64, b: f64) -> f64 {
    match bound {
        TractionBound::Parabolic => 2.0 * fn_n / (PI * a * b),
        TractionBound::Elliptical => 1.5 * fn_n / (PI * a * b),
    }
}

/// `int_{-1}^{t} (1 - s^2)^{3/2} ds` up to a constant: the parabolic load across the strips.
fn parabolic_strip_primitive(t: f64) -> f64 {
    let t = t.clamp(-1.0, 1.0);
    t * (5.0 - 2.0 * t * t) * libm::sqrt(libm::fmax(0.0, 1.0 - t * t)) / 8.0 + 0.375 * libm::asin(t)
}

/// `int (1 - s^2) ds` up to a constant: the elliptical load across the strips.
fn elliptical_strip_primitive(t: f64) -> f64 {
    let t = t.clamp(-1.0, 1.0);
    t - t * t * t / 3.0
}

/// Pressure integrated along x over `[-c, x]` (up to a constant) on a chord of half-length
/// `c`, for the shape only (`c^2 - x^2` or `sqrt(c^2 - x^2)`).
fn chord_primitive(bound: TractionBound, c: f64, x: f64) -> f64 {
    let x = x.clamp(-c, c);
    match bound {
        TractionBound::Parabolic => c * c * x - x * x * x / 3.0,
        TractionBound::Elliptical => {
            0.5 * (x * libm::sqrt(libm::fmax(0.0, c * c - x * x)) + c * c * libm::asin((x / c).clamp(-1.0, 1.0)))
        }
    }
}

fn strips(input: &FastsimInput, s: &Setup, nx: usize, ny: usize, tot: &mut Totals, out: &mut Option<&mut [Element]>) {
    let a = input.contact.semi_axis_rolling_m;
    let b = input.contact.semi_axis_lateral_m;
    let mu = input.contact.friction_coefficient;
    let p0 = peak_pressure(input.bound, input.contact.normal_load_n, a, b);
    let dy = 2.0 * b / ny as f64;
    for j in 0..ny {
        let y = -b + (j as f64 + 0.5) * dy;
        let t = y / b;
        let c = a * libm::sqrt(libm::fmax(0.0, 1.0 - t * t));
        let dx = 2.0 * c / nx as f64;
        let area = dx * dy;
        // Exact load of the strip [y - dy/2, y + dy/2]; shared over its elements in proportion
        // to the x-integral of the pressure shape along the centre line.
        let (t_lo, t_hi) = ((y - 0.5 * dy) / b, (y + 0.5 * dy) / b);
        let strip_load = match input.bound {
            TractionBound::Parabolic => {
                p0 * (4.0 / 3.0) * a * b * (parabolic_strip_primitive(t_hi) - parabolic_strip_primitive(t_lo))
            }
            TractionBound::Elliptical => {
                p0 * (0.5 * PI * a * b) * (elliptical_strip_primitive(t_hi) - elliptical_strip_primitive(t_lo))
            }
        };
        let shape_total = chord_primitive(input.bound, c, c) - chord_primitive(input.bound, c, -c);
        // mu times the load per unit of the shape's x-integral, per unit area.
        let bound_per_shape = if shape_total > 0.0 { mu * strip_load / (shape_total * area) } else { 0.0 };
        let mut st = March { ux: 0.0, uy: 0.0 };
        // From the leading edge (i = nx - 1, x near +c) to the trailing edge.
        let mut upper = chord_primitive(input.bound, c, c);
        for k in 0..nx {
            let i = nx - 1 - k;
            let x = -c + (i as f64 + 0.5) * dx;
            let lower = chord_primitive(input.bound, c, x - 0.5 * dx);
            let bound = bound_per_shape * (upper - lower);
            upper = lower;
            // Half a step from the leading edge to the first centre, whole steps after; the
            // lateral rigid slip (linear in x) at the middle of each step.
            let (h, x_w) = if k == 0 { (0.5 * dx, x + 0.25 * dx) } else { (dx, x + 0.5 * dx) };
            let r = s.step(&mut st, h, y, x_w, bound);
            record(tot, out, j * nx + i, x, y, dx, area, bound, r);
        }
    }
}

fn rectangle(
    input: &FastsimInput,
    s: &Setup,
    scale: f64,
    nx: usize,
    ny: usize,
    tot: &mut Totals,
    out: &mut Option<&mut [Element]>,
) {
    let a = input.contact.semi_axis_rolling_m;
    let b = input.contact.semi_axis_lateral_m;
    let mu = input.contact.friction_coefficient;
    let p0 = peak_pressure(input.bound, input.contact.normal_load_n, a, b);
    let dx = 2.0 * scale * a / nx as f64;
    let dy = 2.0 * scale * b / ny as f64;
    let area = dx * dy;
    let (inv_a2, inv_b2) = (1.0 / (a * a), 1.0 / (b * b));
    for j in 0..ny {
        let y = -scale * b + (j as f64 + 0.5) * dy;
        let row = 1.0 - y * y * inv_b2;
        let mut st = March { ux: 0.0, uy: 0.0 };
        for k in 0..nx {
            let i = nx - 1 - k;
            let x = -scale * a + (i as f64 + 0.5) * dx;
            let inside = row - x * x * inv_a2;
            if !(inside > 0.0) {
                st = March { ux: 0.0, uy: 0.0 };
                if let Some(buf) = out.as_deref_mut() {
                    buf[j * nx + i] = Element { x_m: x, y_m: y, ..Element::default() };
                }
                continue;
            }
            let pressure = match input.bound {
                TractionBound::Parabolic => p0 * inside,
                TractionBound::Elliptical => p0 * libm::sqrt(inside),
            };
            let bound = mu * pressure;
            let r = s.step(&mut st, dx, y, x + dx / 6.0, bound);
            record(tot, out, j * nx + i, x, y, dx, area, bound, r);
        }
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::contact::creep::Creepage;
    use crate::contact::forces::{ContactStiffness, linear};
    use nalgebra::Vector3;

    // CONTACT's example `fastsim.inp` (docs/reference/saturation_and_fastsim.csv, rows
    // fastsim_lateral_spin): a = 8 mm, b = 4 mm, G = 82000 MPa, nu = 0.28, mu = 0.3, Fn = 82 kN,
    // eta = -6.25e-4, phi = 6.25e-4 1/mm, CHI = 0, grid MX = MY = 44 with SCALE = 1.1.
    fn contact_example(bound: TractionBound, grid: Grid) -> FastsimInput {
        FastsimInput {
            contact: Contact {
                semi_axis_rolling_m: 8e-3,
                semi_axis_lateral_m: 4e-3,
                normal_load_n: 82e3,
                shear_modulus_pa: 82e9,
                poisson_ratio: 0.28,
                friction_coefficient: 0.3,
            },
            creep: Creep { xi: 0.0, eta: -6.25e-4, phi_per_m: 0.625, heathcote_per_m2: 0.0 },
            bound,
            grid,
        }
    }
    /// CONTACT's flexibilities for that case (`FLX1..3` in fastsim.ref_out), mm^3/N -> m^3/N.
    const CONTACT_FLX: Flexibilities =
        Flexibilities { l1_m_per_pa: 0.4914e-13, l2_m_per_pa: 0.5122e-13, l3_m_per_pa: 0.4095e-13 };
    const CONTACT_GRID: Grid = Grid::Rectangle { scale: 1.1 };

    fn rel(a: f64, b: f64) -> f64 {
        (a / b - 1.0).abs()
    }

    // The csv's numbers come from an older fastsim.ref_out; CONTACT's current one (trunk
    // revision 2427, eve70a/CONTACT commit 8a6e3fca78b918624f9f1d50b024586bd986d94f) prints
    // slightly different values, which this implementation reproduces to 0.1 % and to the element:
    // parabolic 44: -0.6098, -3.904e4 N mm, 742/522; elliptical 44: -0.6008, -4.828e4 N mm,
    // 622/642; parabolic 220: -0.6338, -3.801e4 N mm.

    #[test]
    fn fastsim_reproduces_contact_parabolic_44() {
        // Expected (csv): Fy/(mu Fn) = -0.6118, Mz = -3.900e4 N mm, adhesion/slip = 738/526.
        let inp = contact_example(TractionBound::Parabolic, CONTACT_GRID);
        let r = fastsim_with_flexibilities(&inp, &CONTACT_FLX, 44, 44, None).unwrap();
        let fy = r.force_f_n / (0.3 * 82e3);
        assert!(rel(fy, -0.6118) < 0.01, "Fy/(mu Fn) = {fy}");
        assert!(rel(r.spin_moment_nm, -39.00) < 0.01, "Mz = {}", r.spin_moment_nm);
        assert!(r.force_e_n.abs() < 1e-9 * 82e3, "Fx = {}", r.force_e_n);
        assert_eq!(r.adhesion_elements + r.slip_elements, 1264, "elements in contact");
        assert!((r.adhesion_elements as i64 - 738).abs() <= 10, "{} adhesion", r.adhesion_elements);
        // CONTACT revision 2427.
        assert!(rel(fy, -0.6098) < 1e-3 && rel(r.spin_moment_nm, -39.04) < 1e-3);
        assert_eq!((r.adhesion_elements, r.slip_elements), (742, 522));
        // MX = 44 at SCALE 1.1 is the grid nx = 40 at scale 1.
        let same = fastsim_with_flexibilities(
            &contact_example(TractionBound::Parabolic, Grid::Rectangle { scale: 1.0 }),
            &CONTACT_FLX,
            40,
            40,
            None,
        )
        .unwrap();
        assert!(rel(same.force_f_n, r.force_f_n) < 1e-9 && rel(same.spin_moment_nm, r.spin_moment_nm) < 1e-9);
        assert_eq!((same.adhesion_elements, same.slip_elements), (r.adhesion_elements, r.slip_elements));
    }

    #[test]
    fn fastsim_reproduces_contact_elliptical_44() {
        // Expected (csv): Fy/(mu Fn) = -0.6016, Mz = -4.829e4 N mm, adhesion/slip = 618/646.
        let inp = contact_example(TractionBound::Elliptical, CONTACT_GRID);
        let r = fastsim_with_flexibilities(&inp, &CONTACT_FLX, 44, 44, None).unwrap();
        let fy = r.force_f_n / (0.3 * 82e3);
        assert!(rel(fy, -0.6016) < 0.01, "Fy/(mu Fn) = {fy}");
        assert!(rel(r.spin_moment_nm, -48.29) < 0.01, "Mz = {}", r.spin_moment_nm);
        assert_eq!(r.adhesion_elements + r.slip_elements, 1264, "elements in contact");
        assert!((r.adhesion_elements as i64 - 618).abs() <= 10, "{} adhesion", r.adhesion_elements);
        // CONTACT revision 2427.
        assert!(rel(fy, -0.6008) < 1e-3 && rel(r.spin_moment_nm, -48.28) < 1e-3);
        assert_eq!((r.adhesion_elements, r.slip_elements), (622, 642));
    }

    #[test]
    fn fastsim_reproduces_contact_parabolic_220() {
        // Expected (csv): Fy/(mu Fn) = -0.6359, Mz = -3.798e4 N mm (220x220, SCALE 1.1).
        let inp = contact_example(TractionBound::Parabolic, CONTACT_GRID);
        let r = fastsim_with_flexibilities(&inp, &CONTACT_FLX, 220, 220, None).unwrap();
        let fy = r.force_f_n / (0.3 * 82e3);
        assert!(rel(fy, -0.6359) < 0.01, "Fy/(mu Fn) = {fy}");
        assert!(rel(r.spin_moment_nm, -37.98) < 0.01, "Mz = {}", r.spin_moment_nm);
        // CONTACT revision 2427.
        assert!(rel(fy, -0.6338) < 1e-3 && rel(r.spin_moment_nm, -38.01) < 1e-3);
        assert_eq!(r.adhesion_elements + r.slip_elements, 31428, "elements in contact");
    }

    #[test]
    fn strips_and_contact_grids_converge_to_the_same_solution() {
        // CONTACT's scheme is first order in the cell size: extrapolate its 44 and 220 grids
        // (cell sizes 5 : 1) and compare with the strips grid at 100 x 100.
        let inp = contact_example(TractionBound::Parabolic, CONTACT_GRID);
        let coarse = fastsim_with_flexibilities(&inp, &CONTACT_FLX, 44, 44, None).unwrap();
        let fine = fastsim_with_flexibilities(&inp, &CONTACT_FLX, 220, 220, None).unwrap();
        let extrapolate = |c: f64, f: f64| f + (f - c) / 4.0;
        let fy = extrapolate(coarse.force_f_n, fine.force_f_n);
        let mz = extrapolate(coarse.spin_moment_nm, fine.spin_moment_nm);
        let strips = FastsimInput { grid: Grid::Strips, ..inp };
        let r = fastsim_with_flexibilities(&strips, &CONTACT_FLX, 100, 100, None).unwrap();
        assert!(rel(r.force_f_n, fy) < 0.005, "Fy {} vs {fy}", r.force_f_n);
        assert!(rel(r.spin_moment_nm, mz) < 0.005, "Mz {} vs {mz}", r.spin_moment_nm);
    }

    #[test]
    fn fastsim_contact_example_with_kalker_table_flexibilities() {
        // The project's own coefficients (kalker_table, linear in nu) differ from CONTACT's
        // (quadratic in 1/C) by 1-2 % at a/b = 2, nu = 0.28: the result stays within 2 %.
        let inp = contact_example(TractionBound::Parabolic, CONTACT_GRID);
        let r = fastsim(&inp, 44, 44, None).unwrap();
        let fy = r.force_f_n / (0.3 * 82e3);
        assert!(rel(fy, -0.6118) < 0.02, "Fy/(mu Fn) = {fy}");
        assert!(rel(r.spin_moment_nm, -39.00) < 0.02, "Mz = {}", r.spin_moment_nm);
    }

    // CONTACT's `tractcurv.inp`, third series (reference csv rows longitudinal_creep):
    // a = 6.304 mm, b = 12.61 mm, Fn = 106.7 kN, mu = 0.33, parabolic bound, L1 = 5.491e-5 mm^3/N
    // (CONTACT's FLX1; G = 82000 MPa, nu = 0.28), MX x MY = 48 x 44, SCALE 1.1.
    const TRACTCURV: [(f64, f64, f64); 4] =
        [(0.0004, 0.2588, 0.2577), (0.0012, 0.6482, 0.6281), (0.002, 0.8816, 0.8433), (0.0032, 0.9976, 0.977)];

    fn tractcurv_input(xi: f64, grid: Grid) -> FastsimInput {
        FastsimInput {
            contact: Contact {
                semi_axis_rolling_m: 6.304e-3,
                semi_axis_lateral_m: 12.61e-3,
                normal_load_n: 106.7e3,
                shear_modulus_pa: 82e9,
                poisson_ratio: 0.28,
                friction_coefficient: 0.33,
            },
            creep: Creep { xi, eta: 0.0, phi_per_m: 0.0, heathcote_per_m2: 0.0 },
            bound: TractionBound::Parabolic,
            grid,
        }
    }

    #[test]
    fn fastsim_reproduces_contact_longitudinal_creep_curve() {
        let l1 = 5.491e-14;
        let flex = Flexibilities { l1_m_per_pa: l1, l2_m_per_pa: l1, l3_m_per_pa: l1 };
        for &(xi, exact, fastsim_ref) in &TRACTCURV {
            let inp = tractcurv_input(xi, Grid::Rectangle { scale: 1.1 });
            let r = fastsim_with_flexibilities(&inp, &flex, 48, 44, None).unwrap();
            let fx = -r.force_e_n / (0.33 * 106.7e3);
            assert!(rel(fx, fastsim_ref) < 0.01, "xi {xi}: -Fx/(mu Fn) = {fx} vs {fastsim_ref}");
            // FASTSIM's distance to the exact theory is what CONTACT's FASTSIM shows, not more.
            let known = (fastsim_ref / exact - 1.0).abs();
            assert!(rel(fx, exact) <= known + 0.01, "xi {xi}: {fx} vs exact {exact}");
            assert_eq!(r.force_f_n, 0.0);
            assert!(r.spin_moment_nm.abs() < 1e-9);
        }
    }

    /// A groove contact of a ball screw: long across the rolling direction (a/b = 0.12), 200 N,
    /// steel, mu = 0.1, no Heathcote field (also the contact of `presliding`'s tests).
    pub(crate) fn ball_screw_like(xi: f64, eta: f64, phi: f64, bound: TractionBound) -> FastsimInput {
        FastsimInput {
            contact: Contact {
                semi_axis_rolling_m: 0.12e-3,
                semi_axis_lateral_m: 1.0e-3,
                normal_load_n: 200.0,
                shear_modulus_pa: 80.8e9,
                poisson_ratio: 0.3,
                friction_coefficient: 0.1,
            },
            creep: Creep { xi, eta, phi_per_m: phi, heathcote_per_m2: 0.0 },
            bound,
            grid: Grid::Strips,
        }
    }

    fn kalker_linear(inp: &FastsimInput) -> (f64, f64, f64) {
        let (a, b) = (inp.contact.semi_axis_rolling_m, inp.contact.semi_axis_lateral_m);
        let k = ContactStiffness {
            shear_modulus_pa: inp.contact.shear_modulus_pa,
            c_m: (a * b).sqrt(),
            coefficients: kalker_table(a / b, inp.contact.poisson_ratio),
            friction_bound_n: 1.0,
            spin_arm_m: 1.0,
        };
        let cr = Creepage {
            xi: inp.creep.xi,
            eta: inp.creep.eta,
            phi: inp.creep.phi_per_m,
            heathcote: 0.0,
            rolling_speed_m_s: 1.0,
            e: Vector3::x(),
            f: Vector3::y(),
        };
        linear(&cr, &k)
    }

    #[test]
    fn linear_limit_matches_kalker_linear_theory() {
        for &(a, b) in &[(0.12e-3, 1.0e-3), (8e-3, 4e-3), (1e-3, 1e-3)] {
            let like = ball_screw_like(0.0, 0.0, 0.0, TractionBound::Parabolic);
            let base = FastsimInput {
                contact: Contact { semi_axis_rolling_m: a, semi_axis_lateral_m: b, ..like.contact },
                ..like
            };
            let c = (a * b).sqrt();
            // Pure xi and pure eta: exact in the simplified theory; midpoint error only.
            for (xi, eta) in [(1e-9, 0.0), (0.0, -1e-9)] {
                let inp = FastsimInput { creep: Creep { xi, eta, ..base.creep }, ..base };
                let r = fastsim(&inp, 20, 20, None).unwrap();
                assert_eq!(r.slip_elements, 0);
                let (fe, ff, _) = kalker_linear(&inp);
                if xi != 0.0 {
                    assert!(rel(r.force_e_n, fe) < 0.005, "a/b {}: Fe {} vs {fe}", a / b, r.force_e_n);
                    assert!(r.force_f_n.abs() < 1e-12 * fe.abs());
                } else {
                    assert!(rel(r.force_f_n, ff) < 0.005, "a/b {}: Ff {} vs {ff}", a / b, r.force_f_n);
                    assert!(r.force_e_n.abs() < 1e-12 * ff.abs());
                    // The simplified theory's own moment, pi a^3 b eta / (4 L2).
                    let l2 = Flexibilities::kalker(a, b, inp.contact.shear_modulus_pa, inp.contact.poisson_ratio)
                        .l2_m_per_pa;
                    let m = PI * a * a * a * b * eta / (4.0 * l2);
                    assert!(rel(r.spin_moment_nm, m) < 0.01, "M {} vs {m}", r.spin_moment_nm);
                }
            }
            // Pure spin: F_f(phi) is Kalker's C23 coupling, within a few %.
            let phi = 1e-9 / c;
            let inp = FastsimInput { creep: Creep { phi_per_m: phi, ..base.creep }, ..base };
            let r = fastsim(&inp, 20, 20, None).unwrap();
            let (_, ff, _) = kalker_linear(&inp);
            assert!(rel(r.force_f_n, ff) < 0.01, "a/b {}: Ff(phi) {} vs {ff}", a / b, r.force_f_n);
            let l3 = Flexibilities::kalker(a, b, inp.contact.shear_modulus_pa, inp.contact.poisson_ratio).l3_m_per_pa;
            let m = -8.0 * a * a * b * b * b * phi / (15.0 * l3);
            assert!(rel(r.spin_moment_nm, m) < 0.01, "M(phi) {} vs {m}", r.spin_moment_nm);
        }
    }

    #[test]
    fn large_creepage_saturates_at_mu_fn() {
        for bound in [TractionBound::Parabolic, TractionBound::Elliptical] {
            for &(xi, eta) in &[(0.5, 0.0), (0.0, -0.5), (0.3, 0.4)] {
                let inp = ball_screw_like(xi, eta, 0.0, bound);
                let r = fastsim(&inp, 20, 20, None).unwrap();
                let f = r.force_e_n.hypot(r.force_f_n);
                assert!(rel(f, 0.1 * 200.0) < 2e-3, "{bound:?} {xi} {eta}: |F| = {f}");
                // Direction opposite to the creepage.
                assert!(r.force_e_n * xi <= 0.0 && r.force_f_n * eta <= 0.0);
            }
            // Full slip: the bounds add up to mu Fn exactly on the strips grid.
            let inp = ball_screw_like(1e3, 0.0, 0.0, bound);
            let r = fastsim(&inp, 7, 5, None).unwrap();
            assert_eq!(r.adhesion_elements, 0);
            assert!(rel(-r.force_e_n, 20.0) < 1e-12, "{}", r.force_e_n);
        }
    }

    #[test]
    fn field_respects_bound_and_dissipation_is_consistent() {
        let cases = [
            ball_screw_like(2e-3, -1e-3, 30.0, TractionBound::Parabolic),
            ball_screw_like(-1e-3, 4e-3, -300.0, TractionBound::Elliptical),
            FastsimInput {
                creep: Creep { heathcote_per_m2: 5e3, ..Creep::default() },
                ..ball_screw_like(0.0, 0.0, 0.0, TractionBound::Elliptical)
            },
            contact_example(TractionBound::Elliptical, CONTACT_GRID),
        ];
        let mut buf = [Element::default(); 44 * 44];
        for inp in &cases {
            let (nx, ny) = if matches!(inp.grid, Grid::Strips) { (20, 20) } else { (44, 44) };
            let r = fastsim(inp, nx, ny, Some(&mut buf)).unwrap();
            let field = &buf[..nx * ny];
            let mut sum = 0.0;
            let (mut fe, mut ff, mut m) = (0.0, 0.0, 0.0);
            let mut n_slip = 0;
            for e in field {
                let t = e.traction_x_pa.hypot(e.traction_y_pa);
                assert!(t <= e.bound_pa * (1.0 + 1e-12), "traction {t} over bound {}", e.bound_pa);
                if e.sliding {
                    n_slip += 1;
                    let d = -(e.traction_x_pa * e.slip_x + e.traction_y_pa * e.slip_y) * e.area_m2;
                    assert!(d >= 0.0);
                    sum += d;
                } else {
                    assert_eq!((e.slip_x, e.slip_y), (0.0, 0.0));
                }
                fe += e.traction_x_pa * e.area_m2;
                ff += e.traction_y_pa * e.area_m2;
                m += (e.x_m * e.traction_y_pa - e.y_m * e.traction_x_pa) * e.area_m2;
            }
            assert!(r.dissipation_per_speed_n >= 0.0 && r.slip_elements > 0);
            assert_eq!(n_slip, r.slip_elements);
            assert!((sum - r.dissipation_per_speed_n).abs() <= 1e-12 * sum.abs());
            let force_scale = r.force_e_n.hypot(r.force_f_n);
            assert!((fe - r.force_e_n).abs() <= 1e-12 * force_scale);
            assert!((ff - r.force_f_n).abs() <= 1e-12 * force_scale);
            assert!((m - r.spin_moment_nm).abs() <= 1e-12 * force_scale * inp.contact.semi_axis_lateral_m);
        }
    }

    #[test]
    fn dissipation_balances_creepage_power_with_equal_flexibilities() {
        // With L1 = L2 = L3 the rigid slip is exactly (xi - phi y, eta + phi x), and in steady
        // rolling the power of the creep forces is dissipated: D = -(Fe xi + Ff eta + M phi),
        // up to the scheme's own O(1/n) numerical dissipation.
        let inp = ball_screw_like(1e-3, -1e-3, 20.0, TractionBound::Parabolic);
        let l = Flexibilities::kalker(0.12e-3, 1e-3, 80.8e9, 0.3).l1_m_per_pa;
        let flex = Flexibilities { l1_m_per_pa: l, l2_m_per_pa: l, l3_m_per_pa: l };
        let r = fastsim_with_flexibilities(&inp, &flex, 100, 100, None).unwrap();
        let power =
            -(r.force_e_n * inp.creep.xi + r.force_f_n * inp.creep.eta + r.spin_moment_nm * inp.creep.phi_per_m);
        assert!(rel(r.dissipation_per_speed_n, power) < 0.01, "D {} vs {power}", r.dissipation_per_speed_n);
    }

    #[test]
    fn zero_creepage_gives_zero_force_and_reversal_reverses_forces() {
        let r = fastsim(&ball_screw_like(0.0, 0.0, 0.0, TractionBound::Elliptical), 20, 20, None).unwrap();
        assert_eq!((r.force_e_n, r.force_f_n, r.spin_moment_nm, r.dissipation_per_speed_n), (0.0, 0.0, 0.0, 0.0));
        assert_eq!(r.slip_elements, 0);
        for grid in [Grid::Strips, CONTACT_GRID] {
            for bound in [TractionBound::Parabolic, TractionBound::Elliptical] {
                let like = ball_screw_like(1e-3, -2e-3, 40.0, bound);
                let fwd = FastsimInput { grid, creep: Creep { heathcote_per_m2: 2e3, ..like.creep }, ..like };
                let rev = FastsimInput {
                    creep: Creep {
                        xi: -fwd.creep.xi,
                        eta: -fwd.creep.eta,
                        phi_per_m: -fwd.creep.phi_per_m,
                        heathcote_per_m2: -fwd.creep.heathcote_per_m2,
                    },
                    ..fwd
                };
                let a = fastsim(&fwd, 24, 24, None).unwrap();
                let b = fastsim(&rev, 24, 24, None).unwrap();
                assert_eq!(
                    (a.force_e_n, a.force_f_n, a.spin_moment_nm),
                    (-b.force_e_n, -b.force_f_n, -b.spin_moment_nm)
                );
                assert_eq!(a.dissipation_per_speed_n, b.dissipation_per_speed_n);
                assert_eq!((a.adhesion_elements, a.slip_elements), (b.adhesion_elements, b.slip_elements));
            }
        }
    }

    #[test]
    fn heathcote_slip_acts_at_the_lateral_edges() {
        // k_h y^2 > 0 drives the outer strips only: force against +xi, slip at |y| near b
        // (Fig. 10 of the paper), no lateral force and no moment by symmetry.
        let inp = FastsimInput {
            creep: Creep { heathcote_per_m2: 1e3, ..Creep::default() },
            ..ball_screw_like(0.0, 0.0, 0.0, TractionBound::Parabolic)
        };
        let mut buf = [Element::default(); 400];
        let r = fastsim(&inp, 20, 20, Some(&mut buf)).unwrap();
        assert!(r.force_e_n < 0.0);
        assert!(r.force_f_n.abs() < 1e-12 * r.force_e_n.abs() && r.spin_moment_nm.abs() < 1e-12);
        // Dissipation (and so the slip) sits in the outer strips, |y| > b/2.
        let d = |e: &Element| -(e.traction_x_pa * e.slip_x + e.traction_y_pa * e.slip_y) * e.area_m2;
        let outer: f64 = buf.iter().filter(|e| e.y_m.abs() > 0.5e-3).map(d).sum();
        let inner: f64 = buf.iter().filter(|e| e.y_m.abs() < 0.5e-3).map(d).sum();
        assert!(outer > 10.0 * inner, "outer {outer} inner {inner}");
        let slip_outer = buf.iter().filter(|e| e.sliding && e.y_m.abs() > 0.5e-3).count();
        let slip_inner = buf.iter().filter(|e| e.sliding && e.y_m.abs() < 0.5e-3).count();
        assert!(slip_outer > 2 * slip_inner, "slip elements outer {slip_outer} inner {slip_inner}");
    }

    #[test]
    fn invalid_inputs_name_the_field() {
        let ok = ball_screw_like(1e-3, 0.0, 0.0, TractionBound::Parabolic);
        let err = |inp: FastsimInput, nx: usize, ny: usize| fastsim(&inp, nx, ny, None).unwrap_err().field;
        let contact = |f: fn(&mut Contact)| {
            let mut inp = ok;
            f(&mut inp.contact);
            err(inp, 5, 5)
        };
        let creep = |f: fn(&mut Creep)| {
            let mut inp = ok;
            f(&mut inp.creep);
            err(inp, 5, 5)
        };
        assert_eq!(contact(|c| c.semi_axis_rolling_m = -1.0), "fastsim.semi_axis_rolling_m");
        assert_eq!(contact(|c| c.semi_axis_lateral_m = f64::NAN), "fastsim.semi_axis_lateral_m");
        assert_eq!(contact(|c| c.normal_load_n = -1.0), "fastsim.normal_load_n");
        assert_eq!(contact(|c| c.shear_modulus_pa = 0.0), "fastsim.shear_modulus_pa");
        assert_eq!(contact(|c| c.poisson_ratio = 0.6), "fastsim.poisson_ratio");
        assert_eq!(contact(|c| c.friction_coefficient = -0.1), "fastsim.friction_coefficient");
        assert_eq!(creep(|c| c.xi = f64::NAN), "fastsim.xi");
        assert_eq!(creep(|c| c.eta = f64::INFINITY), "fastsim.eta");
        assert_eq!(creep(|c| c.phi_per_m = f64::NAN), "fastsim.phi_per_m");
        assert_eq!(creep(|c| c.heathcote_per_m2 = f64::NAN), "fastsim.heathcote_per_m2");
        assert_eq!(err(FastsimInput { grid: Grid::Rectangle { scale: 0.9 }, ..ok }, 5, 5), "fastsim.grid.scale");
        assert_eq!(err(ok, 0, 5), "nx");
        assert_eq!(err(ok, 5, 1001), "ny");
        let mut small = [Element::default(); 24];
        let e = fastsim(&ok, 5, 5, Some(&mut small)).unwrap_err();
        assert_eq!((e.field, e.value), ("elements.len", 24.0));
        let bad = Flexibilities { l1_m_per_pa: 1e-13, l2_m_per_pa: 0.0, l3_m_per_pa: 1e-13 };
        assert_eq!(fastsim_with_flexibilities(&ok, &bad, 5, 5, None).unwrap_err().field, "fastsim.flexibility_l2");
        // Zero load or zero friction: no traction, no error.
        let r =
            fastsim(&FastsimInput { contact: Contact { normal_load_n: 0.0, ..ok.contact }, ..ok }, 5, 5, None).unwrap();
        assert_eq!((r.force_e_n, r.force_f_n), (0.0, 0.0));
    }

    #[test]
    fn heathcote_coefficient_has_the_pressure_weighted_mean() {
        let b = 1.0e-3;
        let kh = heathcote_per_m2(2e-4, b);
        assert!(rel(kh, 1e3) < 1e-15);
        assert!(rel(heathcote_mean(kh, b), 2e-4) < 1e-15);
        assert_eq!(heathcote_per_m2(2e-4, 0.0), 0.0);
        // In the linear limit FASTSIM's force of the field k_h y^2 is that of a uniform xi
        // equal to the mean: each strip's force goes with a(y)^2, and the mean of y^2 with
        // weight 1 - y^2/b^2 over [-b, b] is b^2 / 5.
        let field = FastsimInput {
            creep: Creep { heathcote_per_m2: 1.0, ..Creep::default() },
            ..ball_screw_like(0.0, 0.0, 0.0, TractionBound::Parabolic)
        };
        let uniform = ball_screw_like(heathcote_mean(1.0, b), 0.0, 0.0, TractionBound::Parabolic);
        let (rf, ru) = (fastsim(&field, 40, 200, None).unwrap(), fastsim(&uniform, 40, 200, None).unwrap());
        assert_eq!(rf.slip_elements, 0);
        assert!(rel(rf.force_e_n, ru.force_e_n) < 1e-3, "{} vs {}", rf.force_e_n, ru.force_e_n);
    }

    #[test]
    fn adhesion_share_counts_the_elements_in_contact() {
        let r = FastsimResult { adhesion_elements: 3, slip_elements: 1, ..FastsimResult::default() };
        assert_eq!(r.adhesion_share(), 0.75);
        assert!(FastsimResult::default().adhesion_share().is_nan());
        // On the strips grid every element is in contact; a coarse rectangle can miss the ellipse.
        let strips = fastsim(&ball_screw_like(1e-4, 0.0, 0.0, TractionBound::Parabolic), 1, 1, None).unwrap();
        assert_eq!(strips.adhesion_elements + strips.slip_elements, 1);
        let rect = FastsimInput {
            grid: Grid::Rectangle { scale: 10.0 },
            ..ball_screw_like(1e-4, 0.0, 0.0, TractionBound::Parabolic)
        };
        let r = fastsim(&rect, 2, 2, None).unwrap();
        assert_eq!(r.adhesion_elements + r.slip_elements, 0);
        assert!(r.adhesion_share().is_nan());
    }
}
