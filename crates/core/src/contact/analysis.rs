//! One contact analysed alone, away from the screw: its Hertz ellipse, load, material and
//! friction ([`Contact`]), its creepages ([`Creep`]), and the forces on the ball by two laws:
//!
//! - FASTSIM ([`Contact::fastsim`]): Kalker's simplified theory over the Hertz ellipse
//!   ([`crate::contact::fastsim`]), on Kalker's strips grid, with the traction bound chosen
//!   ([`TractionBound`]): the creep forces, the spin moment, the adhesion share and, when a
//!   buffer is given, the traction field (Fig. 10 of the paper);
//! - the model's law ([`Contact::linear_saturated`]): Kalker's linear theory (Eq. 23) saturated
//!   by Eq. (24) ([`crate::contact::forces::creep_force`]), the contact built as the model builds
//!   it: `c = sqrt(a b)`, the spec's creep coefficients ([`ModelLaw`]), bound `mu Q`, full-slip
//!   spin arm `(3/8) b_major E(m)`, the spec's spin option; xi carries the Heathcote mean.
//!
//! Creepages are FASTSIM's: `xi` on the centre line `y = 0` and the Heathcote field `k_h y^2`
//! apart, whose Hertz-pressure-weighted mean over the ellipse is `k_h b^2 / 5`
//! ([`crate::contact::fastsim::heathcote_mean`]).
//!
//! The creep curves (Fig. 9 of the paper): the friction of the contact against each creep
//! parameter in turn, the other three zero ([`Parameter`]): xi, eta, the spin as `phi c` and the
//! Heathcote coefficient as `k_h b^2` (all dimensionless, `c = sqrt(a b)`), by FASTSIM and by
//! the model's law ([`Law`]); [`curve_point`] computes one point. A curve runs from 0 to a
//! multiple of its parameter's *linear saturation value* ([`Contact::saturation_value`]), where
//! Kalker's linear force (with FASTSIM's coefficients, [`kalker_table`]) reaches `mu Q`:
//! `xi_s = mu Q / (G c^2 C11)`, `eta_s = mu Q / (G c^2 C22)`, `(phi c)_s = mu Q / (G c^2 C23)`
//! and, the Heathcote mean being `k_h b^2 / 5`, `(k_h b^2)_s = 5 xi_s`.
//!
//! Forces and moment act on the ball, in the contact frame: e along rolling, f lateral, the spin
//! moment about the normal ([`Forces`]). SI units throughout; nothing allocates (the traction
//! field goes to a caller-provided buffer).
//!
//! Errors: FASTSIM validates its own input ([`crate::contact::fastsim::fastsim`]: fields
//! `fastsim.*`, `nx`, `ny`, `elements.len`); the model's law validates the contact and the
//! creepages by the same rules ([`Contact::validate`]: fields `contact.*`). Values valid one by
//! one can still overflow together: [`Forces::is_finite`] and [`elements_are_finite`] tell.

use nalgebra::Vector3;

use crate::contact::creep::Creepage;
use crate::contact::elliptic::ellipse_complete_e;
use crate::contact::fastsim::{
    self, ContactFieldNames, Element, FastsimInput, FastsimResult, Grid, HEATHCOTE_B2_PER_MEAN, TractionBound,
    check_contact_values, heathcote_per_m2,
};
use crate::contact::forces::{ContactForce, ContactStiffness, creep_force, creep_length_m};
use crate::contact::kalker::{self, CreepCoefficients, kalker_table};
use crate::error::InputError;
use crate::input::{CreepCoefficientSource, SpinMoment};

// Their home is `patch`, below FASTSIM; here, where a contact is analysed, is where they are used.
pub use crate::contact::patch::{Contact, Creep};

/// The model's law at a contact: its creep coefficients (Eq. 23) and spin moment option.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModelLaw {
    /// Creep coefficients of the law, the spec's source and creep reduction applied.
    pub coefficients: CreepCoefficients,
    /// How the spin moment saturates.
    pub spin: SpinMoment,
}

/// Forces and moment on the ball, in the contact frame, with what they add up to.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Forces {
    /// Force along the rolling direction e, N.
    pub force_e_n: f64,
    /// Force along the lateral direction f, N.
    pub force_f_n: f64,
    /// Spin moment about the normal, N m.
    pub spin_moment_nm: f64,
    /// |F| / (mu Q).
    pub force_ratio: f64,
    /// Dissipated power over rolling speed, N.
    pub dissipation_per_speed_n: f64,
}

/// A FASTSIM solution with its forces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FastsimForces {
    /// FASTSIM's totals, as it gives them.
    pub result: FastsimResult,
    /// The forces.
    pub forces: Forces,
}

/// The model's law solved: the saturated creep force in full, and as forces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LawForces {
    /// Linear and saturated forces and moment, and the saturation.
    pub force: ContactForce,
    /// The forces.
    pub forces: Forces,
}

/// One contact under one set of creepages, solved by FASTSIM and by the model's law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactRun {
    /// The contact.
    pub contact: Contact,
    /// Its creepages.
    pub creep: Creep,
    /// FASTSIM's traction bound.
    pub bound: TractionBound,
    /// FASTSIM's elements per axis.
    pub grid: usize,
    /// FASTSIM.
    pub fastsim: FastsimForces,
    /// The model's law.
    pub law: LawForces,
}

/// A creep parameter of Fig. 9, dimensionless.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Parameter {
    /// Longitudinal creepage xi.
    Xi,
    /// Lateral creepage eta.
    Eta,
    /// Spin phi times c = sqrt(a b).
    PhiC,
    /// Heathcote coefficient k_h times b^2.
    KhB2,
}

/// A force law of the creep curves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Law {
    /// FASTSIM with a traction bound.
    Fastsim(TractionBound),
    /// The model's law: Kalker's linear theory saturated by Eq. (24).
    Eq24,
}

/// One point of a creep curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurvePoint {
    /// The parameter varied.
    pub parameter: Parameter,
    /// The law.
    pub law: Law,
    /// The parameter's value (dimensionless).
    pub value: f64,
    /// Forces on the ball.
    pub forces: Forces,
    /// FASTSIM's adhesion share (NaN for Eq. 24).
    pub adhesion_share: f64,
}

/// The names of the contact's values in errors of the model's law.
const FIELD_NAMES: ContactFieldNames = [
    "contact.semi_axis_rolling_m",
    "contact.semi_axis_lateral_m",
    "contact.normal_load_n",
    "contact.shear_modulus_pa",
    "contact.poisson_ratio",
    "contact.friction_coefficient",
    "contact.xi",
    "contact.eta",
    "contact.phi_per_m",
    "contact.heathcote_per_m2",
];

impl Contact {
    /// Checks every field and every creepage of `creep`, by FASTSIM's rules (a positive ellipse,
    /// a load, shear modulus and friction coefficient, Poisson's ratio in `[0, 0.5]`, finite
    /// creepages).
    ///
    /// # Errors
    /// An [`InputError`] naming the first invalid value (`contact.semi_axis_rolling_m`, ...,
    /// `contact.xi`, ...).
    pub fn validate(&self, creep: &Creep) -> Result<(), InputError> {
        check_contact_values(&self.fastsim_input(creep, TractionBound::Parabolic), &FIELD_NAMES)
    }

    /// FASTSIM's input: this contact under `creep` with the traction bound `bound`, on Kalker's
    /// strips grid.
    fn fastsim_input(&self, creep: &Creep, bound: TractionBound) -> FastsimInput {
        FastsimInput { contact: *self, creep: *creep, bound, grid: Grid::Strips }
    }

    /// a/b.
    pub fn a_over_b(&self) -> f64 {
        self.semi_axis_rolling_m / self.semi_axis_lateral_m
    }

    /// c = sqrt(a b), m.
    pub fn creep_length_m(&self) -> f64 {
        creep_length_m(self.semi_axis_rolling_m, self.semi_axis_lateral_m)
    }

    /// The friction bound mu Q, N.
    pub fn friction_bound_n(&self) -> f64 {
        self.friction_coefficient * self.normal_load_n
    }

    /// Hertz peak pressure 3 Q / (2 pi a b), Pa.
    pub fn peak_pressure_pa(&self) -> f64 {
        1.5 * self.normal_load_n / (core::f64::consts::PI * self.semi_axis_rolling_m * self.semi_axis_lateral_m)
    }

    /// Kalker's table at this contact's a/b: the coefficients FASTSIM's flexibilities are made of.
    pub fn kalker(&self) -> CreepCoefficients {
        kalker_table(self.a_over_b(), self.poisson_ratio)
    }

    /// The Heathcote part of xi (its mean over the ellipse, `k_h b^2 / 5`).
    pub fn heathcote_mean(&self, creep: &Creep) -> f64 {
        fastsim::heathcote_mean(creep.heathcote_per_m2, self.semi_axis_lateral_m)
    }

    /// FASTSIM over the Hertz ellipse on the strips grid, `grid` elements per axis; the field goes
    /// to `elements` when given (at least `grid^2` entries, `elements[j grid + i]`).
    ///
    /// # Errors
    /// FASTSIM's [`InputError`] naming the first invalid field (`fastsim.*`, `nx`, `ny`,
    /// `elements.len`).
    pub fn fastsim(
        &self,
        creep: &Creep,
        bound: TractionBound,
        grid: usize,
        elements: Option<&mut [Element]>,
    ) -> Result<FastsimForces, InputError> {
        let result = fastsim::fastsim(&self.fastsim_input(creep, bound), grid, grid, elements)?;
        let forces = Forces {
            force_e_n: unsigned_zero(result.force_e_n),
            force_f_n: unsigned_zero(result.force_f_n),
            spin_moment_nm: unsigned_zero(result.spin_moment_nm),
            force_ratio: hypot(result.force_e_n, result.force_f_n) / self.friction_bound_n(),
            dissipation_per_speed_n: result.dissipation_per_speed_n,
        };
        Ok(FastsimForces { result, forces })
    }

    /// The model's law: Kalker's linear theory (Eq. 23) saturated by Eq. (24), the contact built
    /// as the model builds it (`report::raceway_state`): c = sqrt(a b), the law's creep
    /// coefficients, bound mu Q, full-slip spin arm (3/8) b_major E(m), the law's spin option;
    /// xi carries the Heathcote mean. The dissipation per rolling speed is
    /// `-(F_e xi + F_f eta + M phi)`.
    ///
    /// # Errors
    /// An [`InputError`] naming the first invalid field of the contact or the creepages
    /// (`contact.*`).
    pub fn linear_saturated(&self, creep: &Creep, law: &ModelLaw) -> Result<LawForces, InputError> {
        self.validate(creep)?;
        let (a, b) = (self.semi_axis_rolling_m, self.semi_axis_lateral_m);
        let heathcote = self.heathcote_mean(creep);
        let xi = creep.xi + heathcote;
        let cr = Creepage {
            xi,
            eta: creep.eta,
            phi: creep.phi_per_m,
            heathcote,
            rolling_speed_m_s: 1.0,
            e: Vector3::x(),
            f: Vector3::y(),
        };
        let stiffness = ContactStiffness::for_ellipse(
            self.shear_modulus_pa,
            a,
            b,
            ellipse_complete_e(a, b),
            law.coefficients,
            self.friction_bound_n(),
        );
        let f = creep_force(&cr, &stiffness, law.spin);
        let forces = Forces {
            force_e_n: unsigned_zero(f.e_n),
            force_f_n: unsigned_zero(f.f_n),
            spin_moment_nm: unsigned_zero(f.moment_nm),
            force_ratio: hypot(f.e_n, f.f_n) / self.friction_bound_n(),
            dissipation_per_speed_n: -(f.e_n * xi + f.f_n * creep.eta + f.moment_nm * creep.phi_per_m),
        };
        Ok(LawForces { force: f, forces })
    }

    /// The linear saturation value of `parameter`: where Kalker's linear force (FASTSIM's
    /// coefficients, [`Contact::kalker`]) reaches mu Q.
    pub fn saturation_value(&self, parameter: Parameter) -> f64 {
        let c = self.creep_length_m();
        let k = self.kalker();
        let per_coefficient = self.friction_bound_n() / (self.shear_modulus_pa * c * c);
        match parameter {
            Parameter::Xi => per_coefficient / k.c11,
            Parameter::Eta => per_coefficient / k.c22,
            Parameter::PhiC => per_coefficient / k.c23,
            Parameter::KhB2 => HEATHCOTE_B2_PER_MEAN * per_coefficient / k.c11,
        }
    }

    /// The creepages with `parameter` at `value` (dimensionless) and the other three zero.
    pub fn creep_of(&self, parameter: Parameter, value: f64) -> Creep {
        match parameter {
            Parameter::Xi => Creep { xi: value, ..Creep::default() },
            Parameter::Eta => Creep { eta: value, ..Creep::default() },
            Parameter::PhiC => Creep { phi_per_m: value / self.creep_length_m(), ..Creep::default() },
            Parameter::KhB2 => Creep {
                heathcote_per_m2: value / (self.semi_axis_lateral_m * self.semi_axis_lateral_m),
                ..Creep::default()
            },
        }
    }
}

impl Creep {
    /// The creepages of a contact of the model, whose longitudinal creepage `xi` (with the
    /// Heathcote mean), lateral `eta`, spin `phi_per_m` (1/m) and Heathcote mean `heathcote`
    /// come from a contact of lateral semi-axis `semi_axis_lateral_m` (b, m): `xi` less the
    /// Heathcote mean on the centre line, `k_h = 5 xi_h / b^2` (0 when b is not positive).
    pub fn of_model(xi: f64, eta: f64, phi_per_m: f64, heathcote: f64, semi_axis_lateral_m: f64) -> Self {
        Creep { xi: xi - heathcote, eta, phi_per_m, heathcote_per_m2: heathcote_per_m2(heathcote, semi_axis_lateral_m) }
    }
}

impl ModelLaw {
    /// The model's law at `contact`: the creep coefficients of `source` at its a/b and Poisson's
    /// ratio times `creep_reduction` ([`kalker::coefficients`], as the model builds them), and the
    /// spin option `spin`.
    pub fn new(source: CreepCoefficientSource, creep_reduction: f64, spin: SpinMoment, contact: &Contact) -> Self {
        ModelLaw {
            coefficients: kalker::coefficients(source, contact.a_over_b(), contact.poisson_ratio, creep_reduction),
            spin,
        }
    }
}

impl Forces {
    /// Whether every force, the ratio and the dissipation are finite.
    pub fn is_finite(&self) -> bool {
        [self.force_e_n, self.force_f_n, self.spin_moment_nm, self.force_ratio, self.dissipation_per_speed_n]
            .iter()
            .all(|x| x.is_finite())
    }
}

/// Whether every number of every element of a traction field is finite.
pub fn elements_are_finite(elements: &[Element]) -> bool {
    elements.iter().all(|e| {
        [e.x_m, e.y_m, e.area_m2, e.traction_x_pa, e.traction_y_pa, e.bound_pa, e.slip_x, e.slip_y]
            .iter()
            .all(|v| v.is_finite())
    })
}

impl ContactRun {
    /// Solves `contact` under `creep` by FASTSIM (traction bound `bound`, `grid` elements per
    /// axis, the field to `elements` when given) and by the model's law `law`.
    ///
    /// # Errors
    /// As [`Contact::fastsim`], then as [`Contact::linear_saturated`].
    pub fn new(
        contact: Contact,
        creep: Creep,
        law: &ModelLaw,
        bound: TractionBound,
        grid: usize,
        elements: Option<&mut [Element]>,
    ) -> Result<Self, InputError> {
        let fastsim = contact.fastsim(&creep, bound, grid, elements)?;
        let law = contact.linear_saturated(&creep, law)?;
        Ok(ContactRun { contact, creep, bound, grid, fastsim, law })
    }

    /// The Heathcote part of xi, `k_h b^2 / 5`.
    pub fn heathcote_mean(&self) -> f64 {
        self.contact.heathcote_mean(&self.creep)
    }

    /// The model's xi: the centre-line xi plus the Heathcote mean.
    pub fn model_xi(&self) -> f64 {
        self.creep.xi + self.heathcote_mean()
    }

    /// The dimensionless spin `phi c`.
    pub fn phi_c(&self) -> f64 {
        self.creep.phi_per_m * self.contact.creep_length_m()
    }

    /// The dimensionless Heathcote coefficient `k_h b^2`.
    pub fn kh_b2(&self) -> f64 {
        self.creep.heathcote_per_m2 * self.contact.semi_axis_lateral_m * self.contact.semi_axis_lateral_m
    }
}

impl Parameter {
    /// The four, in Fig. 9's order.
    pub const ALL: [Parameter; 4] = [Parameter::Xi, Parameter::Eta, Parameter::PhiC, Parameter::KhB2];

    /// Its name in reports: `xi`, `eta`, `phi_c`, `kh_b2`.
    pub fn name(self) -> &'static str {
        match self {
            Parameter::Xi => "xi",
            Parameter::Eta => "eta",
            Parameter::PhiC => "phi_c",
            Parameter::KhB2 => "kh_b2",
        }
    }
}

impl Law {
    /// Its name in reports: `fastsim-parabolic`, `fastsim-elliptical`, `eq24`.
    pub fn name(self) -> &'static str {
        match self {
            Law::Fastsim(TractionBound::Parabolic) => "fastsim-parabolic",
            Law::Fastsim(TractionBound::Elliptical) => "fastsim-elliptical",
            Law::Eq24 => "eq24",
        }
    }
}

/// One point of a creep curve of `contact`: `parameter` at `value` (dimensionless), the other
/// three zero, under `law` (FASTSIM on `grid` elements per axis, or the model's law
/// `model_law`).
///
/// # Errors
/// As [`Contact::fastsim`] or [`Contact::linear_saturated`].
pub fn curve_point(
    contact: &Contact,
    model_law: &ModelLaw,
    grid: usize,
    parameter: Parameter,
    law: Law,
    value: f64,
) -> Result<CurvePoint, InputError> {
    let creep = contact.creep_of(parameter, value);
    let (forces, adhesion_share) = match law {
        Law::Fastsim(bound) => {
            let f = contact.fastsim(&creep, bound, grid, None)?;
            (f.forces, f.result.adhesion_share())
        }
        Law::Eq24 => (contact.linear_saturated(&creep, model_law)?.forces, f64::NAN),
    };
    Ok(CurvePoint { parameter, law, value, forces, adhesion_share })
}

/// `x` with a negative zero made positive (a zero creepage times a coefficient).
fn unsigned_zero(x: f64) -> f64 {
    if x == 0.0 { 0.0 } else { x }
}

/// `sqrt(x^2 + y^2)` without overflow: the platform's `hypot` with the `std` feature (what the
/// command line has always printed), libm's without; the two can differ in the last bit.
fn hypot(x: f64, y: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.hypot(y)
    }
    #[cfg(not(feature = "std"))]
    {
        libm::hypot(x, y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::fastsim::MAX_GRID;
    use crate::contact::forces::linear;

    /// A raceway contact of DKFZD4012's size: long across the groove.
    fn contact() -> Contact {
        Contact {
            semi_axis_rolling_m: 0.12e-3,
            semi_axis_lateral_m: 0.95e-3,
            normal_load_n: 180.0,
            shear_modulus_pa: 80.77e9,
            poisson_ratio: 0.3,
            friction_coefficient: 0.03,
        }
    }

    fn law(c: &Contact, spin: SpinMoment) -> ModelLaw {
        ModelLaw::new(CreepCoefficientSource::KalkerTable, 1.0, spin, c)
    }

    fn rel(a: f64, b: f64) -> f64 {
        libm::fabs(a / b - 1.0)
    }

    #[test]
    fn linear_saturated_is_the_cores_creep_force() {
        let c = contact();
        let creep = Creep { xi: 2e-4, eta: -3e-4, phi_per_m: 20.0, heathcote_per_m2: 400.0 };
        for spin in [SpinMoment::Combined, SpinMoment::Separate] {
            let l = ModelLaw::new(CreepCoefficientSource::PaperFit, 0.7, spin, &c);
            let got = c.linear_saturated(&creep, &l).unwrap();
            let heathcote = 400.0 * 0.95e-3 * 0.95e-3 / 5.0;
            let cr = Creepage {
                xi: 2e-4 + heathcote,
                eta: -3e-4,
                phi: 20.0,
                heathcote,
                rolling_speed_m_s: 1.0,
                e: Vector3::x(),
                f: Vector3::y(),
            };
            let a_over_b = 0.12 / 0.95;
            let stiffness = ContactStiffness::for_ellipse(
                80.77e9,
                0.12e-3,
                0.95e-3,
                ellipse_complete_e(0.12e-3, 0.95e-3),
                kalker::coefficients(CreepCoefficientSource::PaperFit, a_over_b, 0.3, 0.7),
                0.03 * 180.0,
            );
            let want = creep_force(&cr, &stiffness, spin);
            assert!(rel(got.force.e_n, want.e_n) < 1e-14 && rel(got.force.f_n, want.f_n) < 1e-14, "{spin:?}");
            assert!(rel(got.force.moment_nm, want.moment_nm) < 1e-14, "{spin:?}");
            assert_eq!(got.forces.force_e_n, got.force.e_n);
            assert!(rel(got.forces.force_ratio, libm::hypot(want.e_n, want.f_n) / (0.03 * 180.0)) < 1e-14);
            // Saturated: the force is below the bound and opposes the creepage.
            assert!(got.forces.force_ratio <= 1.0 && got.forces.force_e_n < 0.0);
            assert!(got.forces.dissipation_per_speed_n > 0.0 && got.forces.is_finite());
        }
    }

    #[test]
    fn zero_creepage_gives_zero_force_on_every_curve() {
        let c = contact();
        let l = law(&c, SpinMoment::Combined);
        let laws = [Law::Fastsim(TractionBound::Parabolic), Law::Fastsim(TractionBound::Elliptical), Law::Eq24];
        for parameter in Parameter::ALL {
            for curve_law in laws {
                let p = curve_point(&c, &l, 20, parameter, curve_law, 0.0).unwrap();
                let f = p.forces;
                assert_eq!((f.force_e_n, f.force_f_n, f.spin_moment_nm, f.force_ratio), (0.0, 0.0, 0.0, 0.0));
                // Unsigned zeros: a zero force prints as 0, not -0.
                assert!(f.force_e_n.is_sign_positive() && f.force_f_n.is_sign_positive());
                assert_eq!((p.parameter, p.law, p.value), (parameter, curve_law, 0.0));
                match curve_law {
                    Law::Eq24 => assert!(p.adhesion_share.is_nan()),
                    Law::Fastsim(_) => assert_eq!(p.adhesion_share, 1.0),
                }
            }
        }
    }

    #[test]
    fn saturation_value_is_where_the_linear_force_reaches_the_bound() {
        // With FASTSIM's coefficients (Kalker's table, no reduction) the model's linear force at
        // the saturation value is mu Q, for every parameter.
        let c = contact();
        let l = law(&c, SpinMoment::Combined);
        let mu_q = c.friction_bound_n();
        for parameter in Parameter::ALL {
            let value = c.saturation_value(parameter);
            assert!(value > 0.0, "{parameter:?}");
            let f = c.linear_saturated(&c.creep_of(parameter, value), &l).unwrap().force;
            let linear = match parameter {
                Parameter::Eta | Parameter::PhiC => f.linear_f_n,
                Parameter::Xi | Parameter::KhB2 => f.linear_e_n,
            };
            assert!(rel(-linear, mu_q) < 1e-12, "{parameter:?}: {linear} vs {mu_q}");
        }
        // Far beyond it FASTSIM slides over the whole ellipse: |F| = mu Q.
        let value = 50.0 * c.saturation_value(Parameter::Eta);
        let far = curve_point(&c, &l, 20, Parameter::Eta, Law::Fastsim(TractionBound::Parabolic), value).unwrap();
        let far = far.forces.force_ratio;
        assert!(rel(far, 1.0) < 1e-9, "{far}");
    }

    #[test]
    fn creep_of_and_the_run_give_the_dimensionless_parameters_back() {
        let c = contact();
        let l = law(&c, SpinMoment::Combined);
        let mut elements = [Element::default(); 64];
        for parameter in Parameter::ALL {
            let creep = c.creep_of(parameter, 3e-4);
            let run = ContactRun::new(c, creep, &l, TractionBound::Elliptical, 8, Some(&mut elements)).unwrap();
            let back = match parameter {
                Parameter::Xi => run.creep.xi,
                Parameter::Eta => run.creep.eta,
                Parameter::PhiC => run.phi_c(),
                Parameter::KhB2 => run.kh_b2(),
            };
            assert!(rel(back, 3e-4) < 1e-14, "{parameter:?}: {back}");
            // The run is the two laws solved alone.
            assert_eq!(run.fastsim, c.fastsim(&creep, TractionBound::Elliptical, 8, None).unwrap());
            assert_eq!(run.law, c.linear_saturated(&creep, &l).unwrap());
            assert!(elements_are_finite(&elements) && run.fastsim.forces.is_finite());
        }
        assert!(!elements_are_finite(&[Element { slip_x: f64::NAN, ..Element::default() }]));
    }

    #[test]
    fn creepages_of_the_model_keep_the_heathcote_mean() {
        // The model's xi carries the Heathcote mean; FASTSIM's centre-line xi does not.
        let c = contact();
        let creep = Creep::of_model(5e-4, -1e-4, 30.0, 2e-4, c.semi_axis_lateral_m);
        assert!(rel(c.heathcote_mean(&creep), 2e-4) < 1e-14);
        assert!(rel(creep.xi + c.heathcote_mean(&creep), 5e-4) < 1e-14);
        assert_eq!((creep.eta, creep.phi_per_m), (-1e-4, 30.0));
        assert_eq!(Creep::of_model(5e-4, 0.0, 0.0, 2e-4, 0.0).heathcote_per_m2, 0.0);
    }

    #[test]
    fn invalid_input_names_the_field() {
        let c = contact();
        let l = law(&c, SpinMoment::Combined);
        let field = |r: Result<LawForces, InputError>| r.map(|_| ()).unwrap_err().field;
        let creep = Creep::default();
        let bad = |f: fn(&mut Contact)| {
            let mut c = contact();
            f(&mut c);
            c
        };
        let cases: [(Contact, &str); 6] = [
            (bad(|c| c.semi_axis_rolling_m = 0.0), "contact.semi_axis_rolling_m"),
            (bad(|c| c.semi_axis_lateral_m = f64::NAN), "contact.semi_axis_lateral_m"),
            (bad(|c| c.normal_load_n = -1.0), "contact.normal_load_n"),
            (bad(|c| c.shear_modulus_pa = f64::INFINITY), "contact.shear_modulus_pa"),
            (bad(|c| c.poisson_ratio = 0.6), "contact.poisson_ratio"),
            (bad(|c| c.friction_coefficient = -0.1), "contact.friction_coefficient"),
        ];
        for (contact, name) in cases {
            assert_eq!(field(contact.linear_saturated(&creep, &l)), name);
            assert_eq!(contact.validate(&creep).unwrap_err().field, name);
        }
        let nan = Creep { phi_per_m: f64::NAN, ..Creep::default() };
        assert_eq!(field(c.linear_saturated(&nan, &l)), "contact.phi_per_m");
        let e = curve_point(&c, &l, 10, Parameter::Xi, Law::Eq24, f64::INFINITY).unwrap_err();
        assert_eq!((e.field, e.valid), ("contact.xi", "finite"));
        // FASTSIM names its own fields.
        let e = c.fastsim(&Creep { eta: f64::NAN, ..creep }, TractionBound::Parabolic, 10, None).unwrap_err();
        assert_eq!(e.field, "fastsim.eta");
        let e = curve_point(&c, &l, 0, Parameter::Xi, Law::Fastsim(TractionBound::Parabolic), 1e-4).unwrap_err();
        assert_eq!(e.field, "nx");
        assert!(c.fastsim(&creep, TractionBound::Parabolic, MAX_GRID + 1, None).is_err());
        let mut short = [Element::default(); 3];
        let e = c.fastsim(&creep, TractionBound::Parabolic, 2, Some(&mut short)).unwrap_err();
        assert_eq!(e.field, "elements.len");
    }

    #[test]
    fn names_of_parameters_and_laws() {
        let names = Parameter::ALL.map(Parameter::name);
        assert_eq!(names, ["xi", "eta", "phi_c", "kh_b2"]);
        assert_eq!(Law::Fastsim(TractionBound::Elliptical).name(), "fastsim-elliptical");
        assert_eq!(Law::Eq24.name(), "eq24");
        for b in TractionBound::ALL {
            assert_eq!(TractionBound::parse(b.name()), Some(b));
        }
        assert_eq!(TractionBound::parse("round"), None);
    }

    #[test]
    fn linear_limit_of_fastsim_meets_the_models_law() {
        // A tiny creepage: FASTSIM in full adhesion reproduces Kalker's linear theory, as the
        // model's law does there (its coefficients set to FASTSIM's own).
        let c = contact();
        let l = ModelLaw { coefficients: c.kalker(), spin: SpinMoment::Combined };
        let creep = c.creep_of(Parameter::Xi, 1e-3 * c.saturation_value(Parameter::Xi));
        let run = ContactRun::new(c, creep, &l, TractionBound::Parabolic, 80, None).unwrap();
        assert_eq!(run.fastsim.result.slip_elements, 0);
        assert!(rel(run.fastsim.forces.force_e_n, run.law.forces.force_e_n) < 2e-3);
        let (fe, _, _) = linear(
            &Creepage {
                xi: creep.xi,
                eta: 0.0,
                phi: 0.0,
                heathcote: 0.0,
                rolling_speed_m_s: 1.0,
                e: Vector3::x(),
                f: Vector3::y(),
            },
            &ContactStiffness::for_ellipse(c.shear_modulus_pa, 0.12e-3, 0.95e-3, 1.0, c.kalker(), 1.0),
        );
        assert!(rel(run.law.force.linear_e_n, fe) < 1e-14);
    }
}
