//! The friction torque of the whole screw (Eqs. 25-27, docs/model-notes.md items 7-9).
//!
//! The drive torque follows from the energy balance of the screw (item 9):
//! T omega = F_a v_nut + D, i.e. T = F_a L / (2 pi) + D / omega, with D the power dissipated
//! in every contact (friction force times slip velocity plus spin moment times spin, over all
//! balls). The moment about the screw axis of everything the balls exert on the screw (normal
//! and tangential forces and spin moments) gives the same T when each ball is in balance, which
//! [`Summary::torque_moment_nm`] reports beside it. Eq. (27) as printed (friction magnitudes
//! times r_b - delta, which is not a lever about the screw axis) is kept as an option and always
//! reported, never silently used. Forces are summed as free vectors (item 7): by the helical
//! symmetry all balls of a circle are in the same state, so a circle contributes Z times one
//! ball.

use crate::ball::balance::{self, Constants};
use crate::ball::four_point::{self, FourPointSetup, FourPointUnknowns};
use crate::ball::lubrication::{self, LubricatedContacts};
use crate::ball::report::{self, BallState};
use crate::ball::setup::{self, BallSetup, ContactFriction, RacewaySetup, Unknowns};
use crate::ball::solve::{self, Jacobian, SolveReport};
use crate::contact::creep::standstill_factor;
use crate::contact::ehl;
use crate::contact::hertz::{self, HertzContact, HertzShape};
use crate::contact::kalker::{self, CreepCoefficients};
use crate::error::{Error, InputError};
use crate::input::circulation;
use crate::input::extensions::Conditions;
use crate::input::geometry;
use crate::input::lubricant::OilState;
use crate::input::screw::check_preload_for;
use crate::input::{
    ContactTheory, Lubrication, MAX_CIRCLES_PER_NUT, MAX_NUTS, OperatingPoint, Preload, ScrewSpec, TorqueRoute,
};
use crate::screw::catalog;
use crate::screw::circuit;
use crate::screw::load::{self, CircleShares};
use crate::screw::raceway::{self, Raceway};
use crate::screw::report::{ContactKind, Evaluation, Summary, ball_ball_report, empty_ball, raceway_report};
use crate::screw::train;
use core::f64::consts::PI;

/// Residual (scaled, max norm: force imbalance over f Q) above which a solve is reported as not
/// converged. Normal solves reach 1e-12; balls whose two raceway contacts are both in full slip
/// (light loads) make the balance nearly degenerate, and Newton may stop between 1e-12 and this.
pub const ACCEPT_RESIDUAL: f64 = 1e-6;
/// A ball carrying less than this share of the heaviest ball's load (a nut close to lift-off)
/// is accepted at the best state reached when that state's residual is below
/// [`LIGHT_BALL_RESIDUAL`]: its share of the torque is below this fraction.
pub const LIGHT_BALL_SHARE: f64 = 0.01;
/// Residual accepted for a light ball (see [`LIGHT_BALL_SHARE`]).
pub const LIGHT_BALL_RESIDUAL: f64 = 1e-3;

/// Hertz peak pressure (Pa) of ISO 76 / ISO 3408-5's static load rating of ball bearings and ball
/// screws: the most loaded ball's contact is left with a permanent deformation of about 1e-4 of
/// the ball diameter.
pub const STATIC_RATING_PRESSURE_PA: f64 = 4.2e9;
/// Largest Hertz peak pressure (Pa) of the most loaded ball at which a point is evaluated: 1.5
/// times [`STATIC_RATING_PRESSURE_PA`]. The permanent deformation grows as the square of the
/// load (Palmgren), i.e. as the sixth power of the peak pressure, so at this pressure it is
/// about 11e-4 of the ball diameter, eleven times the static rating's: the point is beyond the
/// screw's static load capacity, the contact is no longer elastic (the Hertz model does not
/// hold) and the ball's balance may have several solutions.
pub const MAX_PEAK_PRESSURE_PA: f64 = 1.5 * STATIC_RATING_PRESSURE_PA;

/// Largest thermal loading `L = (-d eta0/dT) u^2 / K_f` of the oil at the raceway contacts
/// ([`crate::contact::ehl::thermal_loading`], at the entrainment speed of a ball rolling without
/// slip) at which a point is evaluated. The inlet-heating correction of the film (Zhu & Cheng's
/// factor as printed by Zhou & Hoeprich 1991, Eq. 21) has the numerator `1 - 13.2 (p_h/E')
/// L^0.42`, which reaches 0, and with it the film, at `L = 11.3` for the highest peak pressure
/// the model evaluates ([`MAX_PEAK_PRESSURE_PA`] on steel, `p_h/E' = 0.027`); at `L = 10` it is
/// still 0.05 there and 0.6 at the static rating's 4.2 GPa. A film that vanishes because a
/// curve fit is taken beyond its range is not physical, so the point is refused. Ball screws
/// run far below it (DKFZD4012 with ISO VG 68 at 40 degrees C: `L = 0.2` at 3000 rpm); a very
/// viscous oil at a low temperature reaches it (ISO VG 5000 at -30 degrees C above 3 rpm).
pub const MAX_THERMAL_LOADING: f64 = 10.0;

/// The largest residual accepted for a ball of load `p_n` (N) when the heaviest ball carries
/// `p_max_n` (N): [`LIGHT_BALL_RESIDUAL`] for a light ball, else [`ACCEPT_RESIDUAL`].
pub(crate) fn accepted_residual(p_n: f64, p_max_n: f64) -> f64 {
    if p_n < LIGHT_BALL_SHARE * p_max_n { LIGHT_BALL_RESIDUAL } else { ACCEPT_RESIDUAL }
}

/// Whether a ball of load `p_n` (N) carries the loads of the ball train when the heaviest ball
/// carries `p_max_n` (N): not a ball below [`LIGHT_BALL_SHARE`] of it, whose balance, near full
/// slip of both raceway contacts, has no state that carries the train's friction (its share of
/// the torque is below that fraction; the model notes, "The ball train").
pub(crate) fn carries_train(p_n: f64, p_max_n: f64) -> bool {
    p_n >= LIGHT_BALL_SHARE * p_max_n
}

/// Refuses a point whose most loaded contact has the Hertz peak pressure `peak_pa` (Pa) above
/// [`MAX_PEAK_PRESSURE_PA`]: beyond the screw's static load capacity.
fn check_peak_pressure(peak_pa: f64) -> Result<(), Error> {
    if peak_pa > MAX_PEAK_PRESSURE_PA {
        return Err(input(
            "peak Hertz pressure of the most loaded ball (preload_n, axial_load_n), Pa",
            peak_pa,
            "<= 6.3e9 Pa, 1.5 x the 4.2 GPa of the static load rating (ISO 76, ISO 3408-5): \
             beyond it the point exceeds the screw's static load capacity",
        ));
    }
    Ok(())
}

/// A validated screw with everything precomputed that does not depend on the operating point.
///
/// The drag torque of DKFZD4012 at 2000 N and 100 rpm by its two routes, the energy balance
/// (`F_a L / (2 pi) + D / omega`) and the moment of the balls' forces about the screw axis,
/// which agree:
///
/// ```
/// use ballscrew_core::input::rpm_to_rad_s;
/// use ballscrew_core::{Model, OperatingPoint, ScrewSpec, SolverState};
///
/// let model = Model::new(&ScrewSpec::dkfzd4012())?;
/// let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(100.0), preload_n: 2000.0, axial_load_n: 0.0 };
/// let s = model.summary(&op, &mut SolverState::new())?;
/// assert!(s.drag_torque_nm() > 0.0);
/// assert!((s.torque_energy_nm - s.torque_moment_nm).abs() <= 1e-9 * s.torque_energy_nm);
/// // The torque alone (no summary built) is the summary's.
/// let torque_nm = model.torque(&op, &mut SolverState::new())?;
/// assert!((torque_nm - s.torque_nm).abs() <= 1e-12 * torque_nm);
/// # Ok::<(), ballscrew_core::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Model {
    spec: ScrewSpec,
    helix_angle_rad: f64,
    spacing_rad: f64,
    shear_modulus_pa: f64,
    screw: RacewaySetup,
    nut: RacewaySetup,
    ball_ball_hertz: HertzContact,
    /// The lean balance's constants of a ball on flank +1 and -1 (index 0 and 1).
    lean: [Constants<f64>; 2],
    /// The lubricant's state at its temperature (`lubrication = "ehl"`), else `None`.
    oil: Option<OilState>,
    /// A ball's axial load over its nominal normal load ([`BallSetup::axial_per_nominal`]).
    axial_per_nominal: f64,
    /// The oil's thermal loading per squared screw speed, s^2/rad^2 ([`Model::thermal_loading`]).
    thermal_loading_per_speed2: f64,
}

/// Warm-start memory of the kinematic solves: one state per nut and circle, and the Jacobian
/// its last warm solve ended with (the next warm solve starts from it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverState {
    x: [[Unknowns; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
    valid: [[bool; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
    jacobian: [[Option<Jacobian>; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
    /// The ball load (N) at which `x` was solved.
    load_n: [[f64; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
    /// The solution before `x` and its ball load, for a secant start (`None`: no such).
    previous: [[Option<(Unknowns, f64)>; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
    /// The four-point balls' last states, per circle (oversize balls).
    four_point: [Option<FourPointUnknowns>; MAX_CIRCLES_PER_NUT],
}

impl Default for SolverState {
    fn default() -> Self {
        Self::new()
    }
}

impl SolverState {
    /// An empty state: the next evaluation starts cold (continuation).
    pub const fn new() -> Self {
        Self {
            x: [[[0.0; setup::N]; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
            valid: [[false; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
            jacobian: [[None; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
            load_n: [[0.0; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
            previous: [[None; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
            four_point: [None; MAX_CIRCLES_PER_NUT],
        }
    }

    /// Forgets every stored state.
    pub fn reset(&mut self) {
        *self = Self::new();
    }
}

/// A circle balanced in its circuit ([`Model::balance_circuits`]): its ball's state, the loads
/// `(plus, minus, plus_friction, minus_friction)` (N) of its ball-ball contacts, its solve, and
/// its free orbit ratio (its ball alone, the return's resistance shared evenly).
type Balanced = (Unknowns, (f64, f64, f64, f64), SolveReport, f64);

/// A segment of a circuit ([`Model::balance_circuits`]): a circle's full-load balls, or one
/// ball of a load ramp.
#[derive(Clone, Copy, Default)]
struct Seg {
    /// The circle it belongs to.
    circle: usize,
    /// Each ball's load, N.
    load_n: f64,
    /// Balls.
    balls: f64,
    /// Whether it is a ball of a load ramp.
    ramp: bool,
}

/// What the balance of one nut's circuits shares ([`Model::balance_circuits`]).
#[derive(Clone, Copy)]
struct NutPass<'a> {
    nut: usize,
    nut_load: f64,
    flank: f64,
    shares: &'a load::CircleShares,
    circles: usize,
    /// The heaviest ball's load, N.
    p_max: f64,
    speed: f64,
    factor: f64,
}

/// What a pass over four-point balls shares across its circles.
struct FourPointPass<'a> {
    shares: &'a load::CircleShares,
    circles: usize,
    /// Balls per circle.
    z: f64,
    speed: f64,
    factor: f64,
    /// The operating point (its preload and axial load, shared over the balls).
    op: &'a OperatingPoint,
}

/// Share of the heavier diagonal's load below which a diagonal's contact friction (films) is
/// taken at that share: beyond lift-off a diagonal carries no load of its own, only what the
/// ball's shift presses on it.
const LIGHT_DIAGONAL_SHARE: f64 = 1e-3;

/// Most passes of a four-point ball's solve with its films taken at its contacts' loads.
const FILM_PASSES: usize = 8;
/// Change of a contact's load between passes (over the heavier diagonal's nominal load) below
/// which the films are those of the loads the ball carries.
const FILM_LOAD_TOLERANCE: f64 = 1e-9;

/// What a pass over the balls hands each solved ball to: nut (or diagonal) and circle index,
/// the circle's weight, the flank, the ball's setup, and its state, unknowns, solve, films and
/// free orbit ratio.
type Visit<'v> = &'v mut dyn FnMut(
    usize,
    usize,
    f64,
    f64,
    &BallSetup,
    Option<(&BallState, &Unknowns, &SolveReport, Option<&LubricatedContacts>, f64)>,
);

/// Totals of one pass over the balls.
#[derive(Debug, Clone, Copy, Default)]
struct Totals {
    dissipation: f64,
    /// EHL rolling resistance's part of `dissipation`.
    rolling: f64,
    /// Hysteresis's part of `dissipation`.
    hysteresis: f64,
    /// Ball-ball contacts' part of `dissipation`.
    ball_ball: f64,
    /// The return path's part of `dissipation` (its resistance moved at the train's speed).
    return_path: f64,
    moment_z: f64,
    force_z: f64,
    eq27: f64,
    iterations: u32,
    max_residual: f64,
}

fn input(field: &'static str, value: f64, valid: &'static str) -> Error {
    Error::Input(InputError { field, value, valid })
}

impl Model {
    /// Validates `spec` and precomputes the contact shapes and creep coefficients.
    ///
    /// A spec out of range is refused with an error naming the field, its value and the valid
    /// range:
    ///
    /// ```
    /// use ballscrew_core::{Error, Model, ScrewSpec};
    ///
    /// let mut spec = ScrewSpec::dkfzd4012();
    /// spec.geometry.conformity_nut = 0.49;
    /// let Err(Error::Input(e)) = Model::new(&spec) else { panic!("a conformity below 0.5 is refused") };
    /// assert_eq!((e.field, e.value), ("geometry.conformity_nut", 0.49));
    /// assert!(e.to_string().starts_with("invalid geometry.conformity_nut: 0.49 (valid: "), "{e}");
    /// ```
    pub fn new(spec: &ScrewSpec) -> Result<Self, Error> {
        spec.validate()?;
        if spec.circulation.load_ramp_balls > 0 {
            if spec.geometry.preload == Preload::OversizeBall {
                return Err(Error::Unsupported {
                    field: "circulation.load_ramp_balls",
                    value: "a load ramp of four-point (oversize) balls",
                    valid: "0 for an oversize-ball nut: a ramp's balls are two-point balls",
                });
            }
            if spec.model.contact_theory != ContactTheory::LinearSaturated && spec.friction.ball_ball_load_n.is_none() {
                return Err(Error::Unsupported {
                    field: "circulation.load_ramp_balls",
                    value: "a load ramp with FASTSIM contacts",
                    valid: "0 with model.contact_theory = \"fastsim\": a ramp's balls are balanced in their circuit \
                            with linear-saturated contacts",
                });
            }
        }
        if Self::solves_circuits(spec) {
            if spec.geometry.preload == Preload::OversizeBall {
                return Err(Error::Unsupported {
                    field: "circulation.turns_per_circuit",
                    value: "several loaded turns per circuit of four-point (oversize) balls",
                    valid: "1 for an oversize-ball nut: the balance of a circuit of several loaded turns is solved for \
                            two-point balls; or give friction.ball_ball_load_n to set the load between balls",
                });
            }
            if spec.model.contact_theory != ContactTheory::LinearSaturated {
                return Err(Error::Unsupported {
                    field: "circulation.turns_per_circuit",
                    value: "several loaded turns per circuit with FASTSIM contacts",
                    valid: "1 with model.contact_theory = \"fastsim\": the balance of a circuit of several loaded turns \
                            is solved with linear-saturated contacts; or give friction.ball_ball_load_n",
                });
            }
        }
        let ramp = spec.circulation.load_ramp_balls;
        if ramp > 0 && 2 * ramp >= spec.geometry.balls_per_circle {
            return Err(input(
                "circulation.load_ramp_balls",
                f64::from(ramp),
                "fewer than half of geometry.balls_per_circle: a circle of a circuit of one turn holds both \
                 ramps and at least one ball at the full load",
            ));
        }
        if spec.circulation.lead_deviation_m != 0.0 && spec.geometry.preload == Preload::OversizeBall {
            return Err(Error::Unsupported {
                field: "circulation.lead_deviation_um",
                value: "a lead deviation in an oversize-ball nut",
                valid: "0 for an oversize-ball nut: a lead deviation moves load between the circles of \
                        two-point balls (the four-point balls' interference is the same in every ball)",
            });
        }
        let g = &spec.geometry;
        let m = &spec.material;
        let beta = g.contact_angle_rad;
        let oil = match spec.model.lubrication {
            Lubrication::Ehl => Some(spec.lubricant.state()),
            Lubrication::Dry => None,
        };
        let raceway = |r: Raceway, conformity: f64| -> Result<RacewaySetup, Error> {
            let curv = raceway::contact_curvatures(g, r, beta);
            let shape = HertzShape::new(&curv, m.youngs_modulus_pa, m.poisson_ratio)?;
            let probe = shape.contact(1.0);
            let a_over_b = probe.semi_axis_rolling_m / probe.semi_axis_lateral_m;
            if !a_over_b.is_finite() || a_over_b <= 0.0 {
                return Err(input("hertz.a_over_b", a_over_b, "finite and > 0"));
            }
            let coefficients = kalker::coefficients(
                spec.model.creep_coefficients,
                a_over_b,
                m.poisson_ratio,
                spec.friction.creep_reduction,
            );
            let mut setup = RacewaySetup {
                shape,
                coefficients,
                pressure_radius_m: raceway::pressure_surface_radius_m(conformity, g.ball_diameter_m),
                arc_offset_m: geometry::arc_offset_m(conformity, g.ball_diameter_m),
                rolling_radius_m: crate::contact::ehl::rolling_radius_m(&curv),
                film: None,
                friction: ContactFriction::dry(spec.friction.coefficient),
            };
            setup.film = oil.as_ref().map(|o| lubrication::film_constants(&setup, o));
            Ok(setup)
        };
        let screw = raceway(Raceway::Screw, g.conformity_screw)?;
        let nut = raceway(Raceway::Nut, g.conformity_nut)?;
        let rb = 0.5 * g.ball_diameter_m;
        let mut model = Self {
            spec: *spec,
            helix_angle_rad: geometry::helix_angle_rad(g),
            spacing_rad: geometry::ball_spacing_rad(g),
            shear_modulus_pa: m.shear_modulus_pa(),
            screw,
            nut,
            ball_ball_hertz: hertz::sphere_on_sphere(
                rb,
                rb,
                spec.friction.ball_ball_load_n.unwrap_or(0.0),
                m.youngs_modulus_pa,
                m.poisson_ratio,
            ),
            lean: Default::default(),
            oil,
            axial_per_nominal: 1.0,
            thermal_loading_per_speed2: 0.0,
        };
        let unit_ball = model.ball_setup_for(1.0, 1.0);
        model.axial_per_nominal = unit_ball.axial_per_nominal();
        model.thermal_loading_per_speed2 = model.oil.as_ref().map_or(0.0, |o| {
            let entrainment_m = lubrication::rolling_entrainment_m(&unit_ball);
            ehl::thermal_loading(o.viscosity_temperature_slope_pa_s_k, entrainment_m, o.thermal_conductivity_w_m_k)
        });
        let approach = model.ball_ball_approach_m();
        model.lean = [1.0, -1.0].map(|flank| Constants::new(&model.ball_setup_for(1.0, flank), approach));
        Ok(model)
    }

    /// The Hertz peak pressure (Pa) of a ball carrying axial load `axial_load_n` (N): the larger
    /// of its two raceway contacts' at the nominal normal load.
    pub fn peak_pressure_pa(&self, axial_load_n: f64) -> f64 {
        // The ball's nominal load (`BallSetup::nominal_load_n`) without building its setup: the
        // evaluator checks the capacity on every call.
        let q = axial_load_n / self.axial_per_nominal;
        self.screw.shape.contact(q).peak_pressure_pa.max(self.nut.shape.contact(q).peak_pressure_pa)
    }

    /// The thermal loading of the oil at the raceway contacts at screw speed `speed_rad_s`
    /// ([`MAX_THERMAL_LOADING`]); 0 for dry contacts.
    pub fn thermal_loading(&self, speed_rad_s: f64) -> f64 {
        self.thermal_loading_per_speed2 * speed_rad_s * speed_rad_s
    }

    /// Refuses an operating point at screw speed `speed_rad_s` where the oil's thermal loading
    /// is above [`MAX_THERMAL_LOADING`] (or not a number).
    pub(crate) fn check_thermal_loading(&self, speed_rad_s: f64) -> Result<(), Error> {
        let loading = self.thermal_loading(speed_rad_s);
        if !(loading <= MAX_THERMAL_LOADING) {
            return Err(input(
                "thermal loading L of the oil at the raceway contacts (the speed, and the lubricant at its temperature_c)",
                loading,
                "<= 10: beyond it the inlet-heating correction of the film (Zhou & Hoeprich 1991, Eq. 21) \
                 leaves no film at the contacts the model evaluates; the oil is too viscous at its \
                 temperature for this speed (a lower speed, a warmer or a thinner oil)",
            ));
        }
        Ok(())
    }

    /// Refuses an operating point whose most loaded ball (axial load `p_max_n`, N) has a peak
    /// pressure above [`MAX_PEAK_PRESSURE_PA`]: beyond the screw's static load capacity.
    pub(crate) fn check_static_capacity(&self, p_max_n: f64) -> Result<(), Error> {
        check_peak_pressure(self.peak_pressure_pa(p_max_n))
    }

    /// The spec this model was built from.
    pub fn spec(&self) -> &ScrewSpec {
        &self.spec
    }

    /// Helix angle, rad.
    pub fn helix_angle_rad(&self) -> f64 {
        self.helix_angle_rad
    }

    /// Kalker coefficients and a/b of the (screw, nut) contacts.
    pub fn creep_coefficients(&self) -> (CreepCoefficients, CreepCoefficients) {
        (self.screw.coefficients, self.nut.coefficients)
    }

    /// Elastic approach of the ball-ball contact at the spec's load Q_m, m.
    pub fn ball_ball_approach_m(&self) -> f64 {
        self.ball_ball_hertz.approach_m
    }

    /// Hertz shapes of the (screw, nut) contacts.
    pub fn hertz_shapes(&self) -> (HertzShape, HertzShape) {
        (self.screw.shape, self.nut.shape)
    }

    /// The axial approach of a ball under an axial load of 1 N, m: both raceway contacts'
    /// Hertz approach along the contact normal over `sin(beta) cos(alpha)`. A ball of axial load
    /// `p` approaches by this times `p^(2/3)`.
    pub fn axial_approach_m_per_n23(&self) -> f64 {
        let s = self.ball_setup_for(1.0, 1.0);
        let q = s.nominal_load_n();
        (self.screw.shape.contact(q).approach_m + self.nut.shape.contact(q).approach_m) / s.axial_per_nominal()
    }

    /// The circles' shares of a nut's load at `load_per_ball_n` (N: the nut's load over its
    /// balls per circle): the distribution's `nominal` shares, moved by the spec's
    /// `circulation.lead_deviation_m` ([`load::shares_with_lead_deviation`]). The deviation is
    /// stated between a nut's first and last circle; a load group of fewer `circles` (each half
    /// of an offset-lead nut) spans its share of it, `(circles - 1) / (circles_per_nut - 1)`.
    pub fn circle_shares_at(&self, nominal: &CircleShares, circles: usize, load_per_ball_n: f64) -> CircleShares {
        let deviation = self.group_lead_deviation_m(circles);
        if deviation == 0.0 {
            return *nominal;
        }
        load::shares_with_lead_deviation(nominal, circles, load_per_ball_n, self.axial_approach_m_per_n23(), deviation)
    }

    /// The lead deviation across a load group of `circles` circles, m: the spec's, stated between
    /// a nut's first and last circle, in proportion for a group of fewer circles.
    fn group_lead_deviation_m(&self, circles: usize) -> f64 {
        let total = self.spec.geometry.circles_per_nut as usize;
        let deviation = self.spec.circulation.lead_deviation_m;
        if circles < total && total > 1 {
            deviation * circles.saturating_sub(1) as f64 / (total - 1) as f64
        } else {
            deviation
        }
    }

    /// The load groups' loads at preload `preload_n` and axial load `axial_load_n` (N):
    /// [`load::groups`]'s, and where a lead deviation is stated and two groups of two-point balls
    /// share an axial load, split so that the groups keep their summed deflection with the
    /// deviation's shares ([`load::nut_loads_by`], [`load::nut_approach_m`]).
    fn group_loads(
        &self,
        groups: &load::LoadGroups,
        nominal: &CircleShares,
        preload_n: f64,
        axial_load_n: f64,
    ) -> [(f64, f64); MAX_NUTS] {
        let circles = groups.circles as usize;
        let deviation = self.group_lead_deviation_m(circles);
        if deviation == 0.0 || groups.count != 2 || groups.four_point || axial_load_n == 0.0 {
            return groups.loads;
        }
        let (z, a) = (f64::from(self.spec.geometry.balls_per_circle), self.axial_approach_m_per_n23());
        let deflection = |f: f64| load::nut_approach_m(nominal, circles, f / z, a, deviation);
        load::nut_loads_by(preload_n, axial_load_n, &deflection)
    }

    /// The setup of one ball carrying axial load `axial_load_n` (N) on `flank` (+1 / -1), for
    /// solving it directly with [`solve`].
    pub fn ball_setup_for(&self, axial_load_n: f64, flank: f64) -> BallSetup {
        let g = &self.spec.geometry;
        BallSetup {
            rm_m: 0.5 * g.pitch_diameter_m,
            lead_per_rad_m: geometry::lead_per_rad(g),
            helix_angle_rad: self.helix_angle_rad,
            rb_m: 0.5 * g.ball_diameter_m,
            contact_angle_rad: g.contact_angle_rad,
            flank,
            shear_modulus_pa: self.shear_modulus_pa,
            mu: self.spec.friction.coefficient,
            stiffness_scale: 1.0,
            axial_load_n,
            ball_ball_plus_n: self.spec.friction.ball_ball_load_n.unwrap_or(0.0),
            ball_ball_minus_n: self.spec.friction.ball_ball_load_n.unwrap_or(0.0),
            ball_ball_plus_friction_n: self.spec.friction.ball_ball_load_n.unwrap_or(0.0),
            ball_ball_minus_friction_n: self.spec.friction.ball_ball_load_n.unwrap_or(0.0),
            ball_ball_mu: self.ball_ball_mu(),
            spacing_rad: self.spacing_rad,
            screw: self.screw,
            nut: self.nut,
            heathcote: self.spec.model.heathcote,
            spin: self.spec.model.spin_moment,
            poisson_ratio: self.spec.material.poisson_ratio,
            contact_theory: self.spec.model.contact_theory,
            fastsim_grid: self.spec.model.fastsim_grid,
        }
    }

    /// The setup of one ball carrying axial load `axial_load_n` (N) on `flank` (+1 / -1) at
    /// screw speed `speed_rad_s` with standstill factor `factor`: [`Model::ball_setup_for`] with
    /// the friction of its lubricated contacts ([`lubrication`]) when the spec's lubrication is
    /// "ehl"; with the films.
    pub fn ball_setup_at(
        &self,
        axial_load_n: f64,
        flank: f64,
        speed_rad_s: f64,
        factor: f64,
    ) -> (BallSetup, Option<LubricatedContacts>) {
        let mut s = self.ball_setup_for(axial_load_n, flank);
        let films =
            self.oil.as_ref().map(|oil| lubrication::lubricate(&mut s, &self.spec.lubricant, oil, speed_rad_s, factor));
        (s, films)
    }

    /// The oil's state at the contacts (`lubrication = "ehl"`), else `None`.
    pub fn oil(&self) -> Option<&OilState> {
        self.oil.as_ref()
    }

    /// The lean constants of a ball on `flank` with the friction of `setup`'s contacts.
    pub(crate) fn lean_for(&self, flank: f64, setup: &BallSetup) -> Constants<f64> {
        self.lean_with(flank, &setup.screw.friction, &setup.nut.friction)
    }

    /// The lean constants of a ball on `flank` with the friction `screw` and `nut` at its
    /// raceway contacts (lubricated; dry contacts keep the spec's coefficient).
    pub(crate) fn lean_with(&self, flank: f64, screw: &ContactFriction, nut: &ContactFriction) -> Constants<f64> {
        if self.oil.is_none() {
            return self.lean_dry(flank);
        }
        self.lean[balance::flank_index(flank)].with_friction(screw, nut)
    }

    /// The lean constants of a ball on `flank` with the spec's friction coefficient at every
    /// contact (dry contacts: those of every ball whatever its load and speed).
    pub(crate) fn lean_dry(&self, flank: f64) -> Constants<f64> {
        self.lean[balance::flank_index(flank)]
    }

    /// Seal torque of the nuts at screw speed `speed_rad_s`, N m: the spec's torque per nut
    /// times the nuts, against the motion with the standstill factor.
    pub fn seal_torque_nm(&self, speed_rad_s: f64) -> f64 {
        let f = &self.spec.friction;
        crate::contact::creep::direction(speed_rad_s)
            * standstill_factor(speed_rad_s, f.standstill_speed_rad_s)
            * f.seal_torque_per_nut_nm
            * f64::from(self.spec.geometry.nuts)
    }

    /// One pass over the balls: solves each circle's ball, sums its report form, and hands
    /// each ball's full state to `visit`.
    fn run(
        &self,
        op: &OperatingPoint,
        state: &mut SolverState,
        visit: Visit<'_>,
    ) -> Result<(Totals, [f64; MAX_NUTS]), Error> {
        op.validate()?;
        self.check_thermal_loading(op.speed_rad_s)?;
        let g = &self.spec.geometry;
        check_preload_for(g.preload, op.preload_n)?;
        let groups = load::groups(g, op.preload_n, op.axial_load_n);
        let nuts = groups.count;
        let circles = groups.circles as usize;
        let z = g.balls_per_circle as f64;
        let nominal = load::circle_shares(groups.circles, self.spec.model.load_distribution);
        let loads = self.group_loads(&groups, &nominal, op.preload_n, op.axial_load_n);
        let speed = op.speed_rad_s;
        let factor = standstill_factor(speed, self.spec.friction.standstill_speed_rad_s);
        let mut tot = Totals::default();
        let mut nut_loads = [0.0; MAX_NUTS];
        if groups.four_point && (loads[0].0 > 0.0 || loads[1].0 > 0.0) {
            let pass = FourPointPass { shares: &nominal, circles, z, speed, factor, op };
            self.run_four_point(&pass, state, &mut tot, visit)?;
            return Ok((tot, [loads[0].0, loads[1].0]));
        }
        // Each nut's circles' shares: the distribution's, moved by a stated lead deviation.
        let nut_shares: [CircleShares; MAX_NUTS] =
            core::array::from_fn(|nut| self.circle_shares_at(&nominal, circles, loads[nut].0 / z));
        // The heaviest ball: a circle's full-load ball (a stated load ramp leaves the circle's
        // other balls carrying more than its share over its balls).
        let p_max = (0..nuts)
            .flat_map(|nut| {
                let (load, shares) = (loads[nut].0, &nut_shares[nut]);
                (0..circles).map(move |c| self.full_ball_load_n(load * shares.load_fraction[c], c, circles))
            })
            .fold(0.0, f64::max);
        self.check_static_capacity(p_max)?;
        let circuit = self.circuit(speed, factor);
        let (rm, h) = (0.5 * g.pitch_diameter_m, geometry::lead_per_rad(g));
        let turns = self.spec.circulation.turns(groups.circles) as usize;
        for (nut, &(nut_load, flank)) in loads.iter().enumerate().take(nuts) {
            nut_loads[nut] = nut_load;
            let shares = nut_shares[nut];
            // Circuits of several loaded turns, or with a load ramp's balls: balanced together
            // ([`circuit`]). At standstill every friction force is zero whatever the loads
            // between balls (a ramp's balls are then solved alone).
            let mut balanced = [None; MAX_CIRCLES_PER_NUT];
            let ramp = self.spec.circulation.load_ramp_balls > 0;
            let mut one_turn = [turns == 1 && !ramp; MAX_CIRCLES_PER_NUT];
            if (turns > 1 && factor > 0.0 && self.spec.friction.ball_ball_load_n.is_none()) || ramp {
                let nut_pass = NutPass { nut, nut_load, flank, shares: &shares, circles, p_max, speed, factor };
                if let Err(e) = self.balance_circuits(&nut_pass, turns, &mut tot, &mut balanced, &mut one_turn) {
                    state.valid[nut] = [false; MAX_CIRCLES_PER_NUT];
                    return Err(e);
                }
            }
            for circle in 0..circles {
                let p = self.full_ball_load_n(nut_load * shares.load_fraction[circle], circle, circles);
                let w = shares.weight[circle];
                let (mut setup, films) = self.ball_setup_at(p, flank, speed, factor);
                let circuit = circuit.filter(|_| one_turn[circle] && carries_train(p, p_max));
                if let Some(c) = &circuit {
                    c.apply(&mut setup, speed >= 0.0);
                }
                if !(p > 0.0) {
                    state.valid[nut][circle] = false;
                    visit(nut, circle, w, flank, &setup, None);
                    continue;
                }
                // Warm start from this circle's last state, else from the neighbouring circle
                // of the same nut just solved (same flank, similar load), else cold.
                let mut jacobian = None;
                let was_valid = state.valid[nut][circle];
                let (x, rep) = if let Some((x, loads, rep, _)) = balanced[circle] {
                    // Its circuit's balance (solved above, stored in `state`).
                    (setup.ball_ball_plus_n, setup.ball_ball_minus_n) = (loads.0, loads.1);
                    (setup.ball_ball_plus_friction_n, setup.ball_ball_minus_friction_n) = (loads.2, loads.3);
                    (x, rep)
                } else if was_valid {
                    jacobian = state.jacobian[nut][circle];
                    let last = &state.x[nut][circle];
                    let secant = state.previous[nut][circle].and_then(|(before, before_load_n)| {
                        solve::secant_start(last, state.load_n[nut][circle], &before, before_load_n, p)
                    });
                    match secant {
                        Some(start) => solve::solve_predicted(&setup, &start, last, speed, factor, &mut jacobian),
                        None => solve::solve_remembering(&setup, Some(last), speed, factor, &mut jacobian),
                    }
                } else if circle > 0 && state.valid[nut][circle - 1] {
                    let from = self.full_ball_load_n(nut_load * shares.load_fraction[circle - 1], circle - 1, circles);
                    solve_from_neighbour(&setup, state.x[nut][circle - 1], from, speed, factor)
                } else {
                    solve::solve(&setup, None, speed, factor)
                };
                state.jacobian[nut][circle] = jacobian;
                if balanced[circle].is_none() {
                    tot.iterations += rep.iterations;
                }
                tot.max_residual = tot.max_residual.max(rep.residual);
                // The solvers return no state that is not physical as converged; the check here
                // names what was wrong with the last state reached when nothing converged.
                let physical = self.lean[balance::flank_index(flank)].check_state(&x);
                if !(rep.residual <= accepted_residual(p, p_max)) || physical.is_err() {
                    state.valid[nut][circle] = false;
                    state.previous[nut][circle] = None;
                    return Err(Error::NoConvergence {
                        nut,
                        circle,
                        iterations: rep.iterations,
                        residual: rep.residual,
                        unphysical: physical.err(),
                    });
                }
                state.previous[nut][circle] = if was_valid && balanced[circle].is_none() {
                    Some((state.x[nut][circle], state.load_n[nut][circle]))
                } else {
                    None
                };
                state.x[nut][circle] = x;
                state.load_n[nut][circle] = p;
                state.valid[nut][circle] = true;
                let x = solve::scale_to_factor(&x, factor);
                let sgn = crate::contact::creep::direction(speed);
                if let Some(c) = &circuit {
                    // The return's share: its resistance moved at the balls' speed.
                    let d = sgn * w * c.return_dissipation_per_speed(x[3], rm, h);
                    tot.return_path += d;
                    tot.dissipation += d;
                }
                let st = self.add_balls(&mut tot, &setup, &x, speed, factor, w * self.full_balls(circle, circles));
                // The orbit rate the ball would have alone: its own where it is free (a circuit
                // of one turn, or no train), else the start of its circuit's balance.
                let free = balanced[circle].map_or(x[3], |b| b.3);
                visit(nut, circle, w, flank, &setup, Some((&st, &x, &rep, films.as_ref(), free)));
            }
        }
        Ok((tot, nut_loads))
    }

    /// Adds to `tot` what `balls` balls (weighted: a circle's weight times its balls) in the
    /// state `x` (at the point's standstill factor `factor`) of `setup` dissipate and exert on
    /// the screw; returns the ball's state.
    fn add_balls(
        &self,
        tot: &mut Totals,
        setup: &BallSetup,
        x: &Unknowns,
        speed: f64,
        factor: f64,
        balls: f64,
    ) -> BallState {
        let rb = 0.5 * self.spec.geometry.ball_diameter_m;
        let sgn = crate::contact::creep::direction(speed);
        let st = report::ball_state(setup, x, speed, factor);
        tot.dissipation += balls
            * (st.screw.dissipation_per_speed + st.nut.dissipation_per_speed + st.ball_ball.dissipation_per_speed);
        let rolling = |c: &report::RacewayState| c.rolling_dissipation_per_speed;
        let hysteresis = |c: &report::RacewayState| c.hysteresis_dissipation_per_speed;
        tot.rolling += balls * (rolling(&st.screw) + rolling(&st.nut) - hysteresis(&st.screw) - hysteresis(&st.nut));
        tot.hysteresis += balls * (hysteresis(&st.screw) + hysteresis(&st.nut));
        tot.ball_ball += balls * st.ball_ball.dissipation_per_speed;
        tot.moment_z += balls * st.screw_moment_z_nm;
        tot.force_z += balls * st.screw_force_z_n;
        let mag = |c: &report::RacewayState| libm::sqrt(c.force.e_n * c.force.e_n + c.force.f_n * c.force.f_n);
        tot.eq27 += balls
            * sgn
            * (mag(&st.nut) * (rb - st.nut.hertz.approach_m)
                + mag(&st.screw) * (rb - st.screw.hertz.approach_m)
                + st.ball_ball.friction.norm() * (rb - self.ball_ball_hertz.approach_m));
        st
    }

    /// Whether `spec`'s circuits hold several loaded turns whose balance the model solves
    /// ([`circuit`]): the train applies (no `friction.ball_ball_load_n`) and a circuit holds
    /// more than one of a nut's circles.
    pub fn solves_circuits(spec: &ScrewSpec) -> bool {
        let circles = load::groups(&spec.geometry, 0.0, 0.0).circles;
        spec.friction.ball_ball_load_n.is_none()
            && (spec.circulation.turns(circles) > 1 || spec.circulation.load_ramp_balls > 0)
    }

    /// The load ramps (0, 1 or 2) circle `circle` of a load group of `circles` circles holds:
    /// one at each end of its circuit's loaded zone (its first and last circle), none without a
    /// stated `circulation.load_ramp_balls`.
    fn ramps_in(&self, circle: usize, circles: usize) -> u32 {
        if self.spec.circulation.load_ramp_balls == 0 {
            return 0;
        }
        let turns = self.spec.circulation.turns(circles as u32).max(1) as usize;
        let first = circle / turns * turns;
        let last = (first + turns).min(circles) - 1;
        u32::from(circle == first) + u32::from(circle == last)
    }

    /// The balls of circle `circle`'s load ramps (of a load group of `circles` circles).
    fn ramp_balls_in(&self, circle: usize, circles: usize) -> u32 {
        self.ramps_in(circle, circles) * self.spec.circulation.load_ramp_balls
    }

    /// The balls of circle `circle` (of a load group of `circles`) at the circle's full load: its
    /// balls less those of its load ramps.
    fn full_balls(&self, circle: usize, circles: usize) -> f64 {
        f64::from(self.spec.geometry.balls_per_circle - self.ramp_balls_in(circle, circles))
    }

    /// The load of circle `circle`'s full-load ball (N) when the circle carries `circle_load_n`:
    /// its balls share it, a ramp's ball `k` of `m` carrying `k / (m + 1)` of a full ball's (a
    /// ramp carries `m / 2` full balls' load).
    fn full_ball_load_n(&self, circle_load_n: f64, circle: usize, circles: usize) -> f64 {
        let ramp_balls = f64::from(self.ramp_balls_in(circle, circles));
        circle_load_n / (f64::from(self.spec.geometry.balls_per_circle) - 0.5 * ramp_balls)
    }

    /// The ball train of each circuit at screw speed `speed_rad_s` (rad/s) with standstill
    /// factor `factor` ([`train`]): `None` where the spec's `friction.ball_ball_load_n`
    /// overrides it, or where no contact carries load (no resistance in the return).
    pub fn circuit(&self, speed_rad_s: f64, factor: f64) -> Option<train::Circuit> {
        if self.spec.friction.ball_ball_load_n.is_some() {
            return None;
        }
        let circuit = self.circuit_of_turns(1, speed_rad_s, factor);
        circuit.is_loaded().then_some(circuit)
    }

    /// The train of a circuit of `turns` loaded turns at screw speed `speed_rad_s` (rad/s) with
    /// standstill factor `factor`: the return's resistance and the chord of the helix (its
    /// return share, [`train::Circuit::return_dissipation_per_speed`]), whatever the loads.
    fn circuit_of_turns(&self, turns: u32, speed_rad_s: f64, factor: f64) -> train::Circuit {
        let g = &self.spec.geometry;
        let c = &self.spec.circulation;
        let wall = c.return_friction.unwrap_or_else(|| self.return_wall_friction());
        let resistance = factor * circulation::return_resistance_n(g, c.return_balls_for(g, turns), wall, speed_rad_s);
        let balls = f64::from(g.balls_per_circle) * f64::from(turns);
        train::Circuit::new(balls, resistance, self.spacing_rad, 0.5 * g.pitch_diameter_m, geometry::lead_per_rad(g))
    }

    /// Balances the circuits of one nut ([`circuit`]) whose circles or load ramps carry
    /// different loads: each circuit's circles (consecutive, `turns` of them, the last circuit
    /// taking what is left) in the order the balls travel, with the balls of a stated load ramp
    /// ([`crate::input::circulation`]) ahead of its first circle and behind its last, each a
    /// segment of its own; always from the cold start (the canonical state: the same answer
    /// whatever was solved before). Each solved circle's state, the loads of its ball-ball
    /// contacts and its circuit's solve go to `balanced`; the return's share and the ramps'
    /// balls go to `tot`. A circle or ramp ball too light to carry the train
    /// ([`carries_train`]) is left out of its circuit's balance, as a single light ball is left
    /// out of the train (a ramp's ball is then solved alone, as every ramp ball at standstill,
    /// where every friction force is zero whatever the loads between balls); a circuit left with
    /// one loaded circle (a circuit of one turn, or the others light) is marked in `one_turn`, for
    /// the pass over the circles to give it the train of one turn.
    fn balance_circuits(
        &self,
        pass: &NutPass<'_>,
        turns: usize,
        tot: &mut Totals,
        balanced: &mut [Option<Balanced>; MAX_CIRCLES_PER_NUT],
        one_turn: &mut [bool; MAX_CIRCLES_PER_NUT],
    ) -> Result<(), Error> {
        let NutPass { nut, nut_load, flank, shares, circles, p_max, speed, factor } = *pass;
        let fk = factor.max(setup::MIN_SOLVE_FACTOR);
        let g = &self.spec.geometry;
        let (rm, h) = (0.5 * g.pitch_diameter_m, geometry::lead_per_rad(g));
        let sgn = crate::contact::creep::direction(speed);
        // The balls travel from a nut's first circle to its last on flank +1 when the screw
        // turns forwards, the other way on flank -1 (the circles run from the loaded end, and
        // the balance is symmetric under flipping both flank and direction).
        let ascending = (speed >= 0.0) == (flank > 0.0);
        let loads_of = |c: usize| self.full_ball_load_n(nut_load * shares.load_fraction[c], c, circles);
        let ramp = self.spec.circulation.load_ramp_balls as usize;
        // The train's balance: in motion, where no stated load between balls bypasses it.
        let moving = factor > 0.0 && self.spec.friction.ball_ball_load_n.is_none();
        let mut first = 0;
        while first < circles {
            let end = (first + turns).min(circles);
            let span = first..end;
            first = end;
            // The circuit's segments in the order of travel: the entering ramp's balls (the
            // k-th from the return carrying k / (m + 1) of its circle's full load), the circles,
            // the leaving ramp's balls.
            let (entry, exit) = if ascending { (span.start, span.end - 1) } else { (span.end - 1, span.start) };
            let mut segs = [Seg::default(); train::MAX_SEGMENTS];
            let mut all = 0;
            let ramp_ball = |c: usize, k: usize| Seg {
                circle: c,
                load_n: loads_of(c) * k as f64 / (ramp + 1) as f64,
                balls: 1.0,
                ramp: true,
            };
            for k in 1..=ramp {
                segs[all] = ramp_ball(entry, k);
                all += 1;
            }
            for i in 0..span.len() {
                let c = if ascending { span.start + i } else { span.end - 1 - i };
                segs[all] = Seg { circle: c, load_n: loads_of(c), balls: self.full_balls(c, circles), ramp: false };
                all += 1;
            }
            for k in (1..=ramp).rev() {
                segs[all] = ramp_ball(exit, k);
                all += 1;
            }
            // The segments that carry the train (none at standstill, nor where only one does).
            let mut order = [0; train::MAX_SEGMENTS];
            let mut n = 0;
            for (j, seg) in segs.iter().enumerate().take(all) {
                if moving && seg.load_n > 0.0 && carries_train(seg.load_n, p_max) {
                    order[n] = j;
                    n += 1;
                }
            }
            if n == 1 && !segs[order[0]].ramp {
                one_turn[segs[order[0]].circle] = true;
            }
            if n < 2 {
                n = 0;
            }
            // A ramp's balls outside the balance: alone, without loads between balls.
            for (j, seg) in segs.iter().enumerate().take(all) {
                if seg.ramp && seg.load_n > 0.0 && !order[..n].contains(&j) {
                    self.add_ramp_ball(tot, nut, seg, flank, p_max, speed, factor, shares.weight[seg.circle], None)?;
                }
            }
            if n < 2 {
                continue;
            }
            let seg_of = |i: usize| segs[order[i]];
            // Solved at the standstill factor of the solve (as every ball, [`solve::solve`]),
            // its loads carried to the point's factor with the friction forces.
            let solve_ring = self.circuit_of_turns(span.len() as u32, speed, fk);
            let ring = self.circuit_of_turns(span.len() as u32, speed, factor);
            let to_factor = if factor < fk { factor / fk } else { 1.0 };
            let placeholder =
                circuit::Segment { constants: self.lean_dry(flank), axial_load_n: 0.0, balls: 0.0, force_scale_n: 0.0 };
            let mut problem = circuit::Problem {
                segment: [placeholder; train::MAX_SEGMENTS],
                segments: n,
                resistance_n: solve_ring.resistance_n,
                forwards: speed >= 0.0,
                direction: sgn,
                factor: fk,
                accept: ACCEPT_RESIDUAL,
                friction_scale: 1.0,
            };
            let mut setups = [None; train::MAX_SEGMENTS];
            let mut train_balls = 0.0;
            for i in 0..n {
                let seg = seg_of(i);
                let (setup, _) = self.ball_setup_at(seg.load_n, flank, speed, factor);
                let mu = setup.mu.max(setup.screw.friction.mu).max(setup.nut.friction.mu);
                problem.segment[i] = circuit::Segment {
                    constants: self.lean_for(flank, &setup).with_ball_ball(&setup),
                    axial_load_n: seg.load_n,
                    balls: seg.balls,
                    force_scale_n: mu * setup.nominal_load_n(),
                };
                setups[i] = Some(setup);
                train_balls += seg.balls;
            }
            // The start: each segment's ball alone with the return shared evenly (its free
            // orbit rate), the first cold, the next from its neighbour, as the pass over the
            // circles.
            let mut start = circuit::State {
                x: [[0.0; setup::N]; train::MAX_SEGMENTS],
                push_n: [0.0; train::MAX_SEGMENTS],
                gap: 0,
            };
            start.push_n = [-solve_ring.resistance_n / train_balls; train::MAX_SEGMENTS];
            let chain = problem.chain(&start);
            let mut iterations = 0;
            for i in 0..n {
                let Some(mut setup) = setups[i] else { continue };
                let l = problem.ball_ball_loads(&chain, i);
                (setup.ball_ball_plus_n, setup.ball_ball_minus_n) = (l.0, l.1);
                (setup.ball_ball_plus_friction_n, setup.ball_ball_minus_friction_n) = (l.2, l.3);
                let (x, rep) = if i == 0 {
                    solve::solve(&setup, None, speed, factor)
                } else {
                    solve_from_neighbour(&setup, start.x[i - 1], seg_of(i - 1).load_n, speed, factor)
                };
                iterations += rep.iterations;
                let physical = problem.segment[i].constants.check_state(&x);
                if !(rep.residual <= accepted_residual(seg_of(i).load_n, p_max)) || physical.is_err() {
                    return Err(Error::NoConvergence {
                        nut,
                        circle: seg_of(i).circle,
                        iterations,
                        residual: rep.residual,
                        unphysical: physical.err(),
                    });
                }
                start.x[i] = x;
            }
            let (s, rep) = problem.solve_cold(&start).map_err(|rep| Error::NoSteadyTrain {
                nut,
                circles: (span.start, span.end - 1),
                iterations: iterations + rep.iterations,
                residual: rep.residual,
            })?;
            let chain = problem.chain(&s);
            let report = SolveReport {
                iterations: iterations + rep.iterations,
                residual: rep.residual,
                continuation_steps: rep.steps,
            };
            for i in 0..n {
                let l = problem.ball_ball_loads(&chain, i);
                let loads = (l.0 * to_factor, l.1 * to_factor, l.2 * to_factor, l.3 * to_factor);
                let free = solve::scale_to_factor(&start.x[i], factor)[3];
                let seg = seg_of(i);
                if seg.ramp {
                    let balance = (s.x[i], loads, report, free);
                    self.add_ramp_ball(
                        tot,
                        nut,
                        &seg,
                        flank,
                        p_max,
                        speed,
                        factor,
                        shares.weight[seg.circle],
                        Some(balance),
                    )?;
                } else {
                    balanced[seg.circle] = Some((s.x[i], loads, report, free));
                }
            }
            tot.iterations += report.iterations;
            tot.max_residual = tot.max_residual.max(report.residual);
            // The return's share: its resistance moved at the circuit's one orbit rate, with
            // the circuit's mean weight (the paper-literal reading weighs each circle).
            let weight = span.clone().map(|c| shares.weight[c]).sum::<f64>() / span.len() as f64;
            let x0 = solve::scale_to_factor(&s.x[0], factor);
            let d = sgn * weight * ring.return_dissipation_per_speed(x0[3], rm, h);
            tot.return_path += d;
            tot.dissipation += d;
        }
        Ok(())
    }

    /// Adds one ball of a load ramp (`seg`, of a circle of weight `weight`) to `tot`: its state
    /// and loads from its circuit's balance when given, else solved alone without loads between
    /// balls.
    #[allow(clippy::too_many_arguments)]
    fn add_ramp_ball(
        &self,
        tot: &mut Totals,
        nut: usize,
        seg: &Seg,
        flank: f64,
        p_max: f64,
        speed: f64,
        factor: f64,
        weight: f64,
        balance: Option<Balanced>,
    ) -> Result<(), Error> {
        let (mut setup, _) = self.ball_setup_at(seg.load_n, flank, speed, factor);
        let x = match balance {
            Some((x, loads, _, _)) => {
                (setup.ball_ball_plus_n, setup.ball_ball_minus_n) = (loads.0, loads.1);
                (setup.ball_ball_plus_friction_n, setup.ball_ball_minus_friction_n) = (loads.2, loads.3);
                x
            }
            None => {
                let (x, rep) = solve::solve(&setup, None, speed, factor);
                tot.iterations += rep.iterations;
                tot.max_residual = tot.max_residual.max(rep.residual);
                let physical = self.lean[balance::flank_index(flank)].check_state(&x);
                if !(rep.residual <= accepted_residual(seg.load_n, p_max)) || physical.is_err() {
                    return Err(Error::NoConvergence {
                        nut,
                        circle: seg.circle,
                        iterations: rep.iterations,
                        residual: rep.residual,
                        unphysical: physical.err(),
                    });
                }
                x
            }
        };
        let x = solve::scale_to_factor(&x, factor);
        self.add_balls(tot, &setup, &x, speed, factor, weight * seg.balls);
        Ok(())
    }

    /// The default wall friction of a ball in the return ([`crate::input::circulation`]): the
    /// lubricant's full-film traction under the lubricated model (a lightly loaded ball moving
    /// over an oil-wetted wall at the train's speed, with entrainment: a film forms, unlike at
    /// the contact between neighbouring balls), the spec's coefficient dry.
    pub fn return_wall_friction(&self) -> f64 {
        match self.oil {
            Some(_) => self.spec.lubricant.full_film_traction,
            None => self.spec.friction.coefficient,
        }
    }

    /// Friction coefficient of the ball-ball contacts: the lubricant's boundary friction under
    /// the lubricated model (the surfaces slide at zero entrainment speed: no film forms), the
    /// spec's coefficient dry; 0 with spacer balls (`circulation.spacer_balls`: a spacer rolls
    /// on both its neighbours, nothing slides).
    pub fn ball_ball_mu(&self) -> f64 {
        if self.spec.circulation.spacer_balls {
            return 0.0;
        }
        match self.oil {
            Some(_) => self.spec.lubricant.boundary_friction,
            None => self.spec.friction.coefficient,
        }
    }

    /// The pass over the balls of an oversize-ball nut with both diagonals loaded: one
    /// four-point ball per circle ([`four_point`]), each diagonal handed to `visit` as the ball
    /// of "nut" 0 (flank +1) and 1 (flank -1).
    fn run_four_point(
        &self,
        pass: &FourPointPass<'_>,
        state: &mut SolverState,
        tot: &mut Totals,
        visit: Visit<'_>,
    ) -> Result<(), Error> {
        let rb = 0.5 * self.spec.geometry.ball_diameter_m;
        let (speed, factor) = (pass.speed, pass.factor);
        let sgn = crate::contact::creep::direction(speed);
        // The interference is the same in every ball: the preload per ball is uniform; the
        // axial load is spread over the circles by the load distribution. Each circle's balls
        // share them between their diagonals by the Hertz split of the double nut.
        let preload_per_ball = pass.op.preload_n / (pass.circles as f64 * pass.z);
        let axial_per_ball = |circle: usize| pass.op.axial_load_n * pass.shares.load_fraction[circle] / pass.z;
        let split = |circle: usize| load::nut_loads(preload_per_ball, axial_per_ball(circle), 2).map(|(l, _)| l);
        let p_max = (0..pass.circles).map(split).fold(0.0_f64, |m, [a, b]| m.max(a).max(b));
        let circuit = self.circuit(speed, factor);
        for circle in 0..pass.circles {
            let p = split(circle);
            let floor = LIGHT_DIAGONAL_SHARE * p[0].max(p[1]);
            let (mut plus, films_plus) = self.ball_setup_at(p[0].max(floor), 1.0, speed, factor);
            let circuit = circuit.filter(|_| carries_train(p[0].max(p[1]), p_max));
            if let Some(c) = &circuit {
                // The ball-ball contacts are the plus diagonal's setup's ([`four_point`]).
                c.apply(&mut plus, speed >= 0.0);
            }
            let (minus, films_minus) = self.ball_setup_at(p[1].max(floor), -1.0, speed, factor);
            let setup =
                FourPointSetup { plus, minus, preload_n: preload_per_ball, axial_load_n: axial_per_ball(circle) };
            let start = state.four_point[circle];
            let accept = accepted_residual(p[0].max(p[1]), p_max);
            let (setup, x, rep, films) =
                self.solve_four_point(setup, start, [films_plus, films_minus], speed, factor, accept);
            tot.iterations += rep.iterations;
            tot.max_residual = tot.max_residual.max(rep.residual);
            let physical = four_point::check_state(&setup, &x);
            if !(rep.residual <= accept) || physical.is_err() {
                state.four_point[circle] = None;
                return Err(Error::NoConvergence {
                    nut: 0,
                    circle,
                    iterations: rep.iterations,
                    residual: rep.residual,
                    unphysical: physical.err(),
                });
            }
            state.four_point[circle] = Some(x);
            let x = four_point::scale_to_factor(&setup, &x, factor);
            let st = four_point::four_point_state(&setup, &x, speed, factor);
            // The static capacity at the loads the contacts carry (a light diagonal's contacts
            // may carry more than their nominal load).
            let peak = st
                .diagonals
                .iter()
                .flat_map(|d| [d.screw.hertz.peak_pressure_pa, d.nut.hertz.peak_pressure_pa])
                .fold(0.0, f64::max);
            check_peak_pressure(peak)?;
            let w = pass.shares.weight[circle];
            let wz = w * pass.z;
            if let Some(c) = &circuit {
                // The return's share: its resistance moved at the balls' speed.
                let g = &self.spec.geometry;
                let d =
                    sgn * w * c.return_dissipation_per_speed(x[3], 0.5 * g.pitch_diameter_m, geometry::lead_per_rad(g));
                tot.return_path += d;
                tot.dissipation += d;
            }
            tot.dissipation += wz * st.dissipation_per_speed;
            tot.moment_z += wz * st.screw_moment_z_nm;
            tot.force_z += wz * st.screw_force_z_n;
            tot.ball_ball += wz * st.diagonals[0].ball_ball.dissipation_per_speed;
            tot.eq27 += wz * sgn * st.diagonals[0].ball_ball.friction.norm() * (rb - self.ball_ball_hertz.approach_m);
            let unknowns = four_point::diagonal_unknowns(&setup, &x);
            for (d, diagonal) in st.diagonals.iter().enumerate() {
                for c in [&diagonal.screw, &diagonal.nut] {
                    tot.rolling += wz * (c.rolling_dissipation_per_speed - c.hysteresis_dissipation_per_speed);
                    tot.hysteresis += wz * c.hysteresis_dissipation_per_speed;
                    let magnitude = libm::sqrt(c.force.e_n * c.force.e_n + c.force.f_n * c.force.f_n);
                    tot.eq27 += wz * sgn * magnitude * (rb - c.hertz.approach_m);
                }
                let (setup_d, flank) = if d == 0 { (&setup.plus, 1.0) } else { (&setup.minus, -1.0) };
                // Reported with the diagonal's own share of the load (zero once lifted off),
                // not the floor its films were taken at.
                let shown = BallSetup { axial_load_n: p[d], ..*setup_d };
                let free = unknowns[d][3];
                visit(d, circle, w, flank, &shown, Some((diagonal, &unknowns[d], &rep, films[d].as_ref(), free)));
            }
        }
        Ok(())
    }

    /// Solves a four-point ball of setup `setup` from `start`; with lubricated contacts, each
    /// contact's film is then taken at the load it carries and the ball solved again, until
    /// the loads stop changing (a light diagonal's contacts carry what the ball's shift presses
    /// on them, far from their nominal load). Returns the setup of the last solve, the state,
    /// the solve and each diagonal's films (`films`: those of the nominal loads).
    fn solve_four_point(
        &self,
        mut setup: FourPointSetup,
        start: Option<FourPointUnknowns>,
        mut films: [Option<LubricatedContacts>; 2],
        speed: f64,
        factor: f64,
        accept: f64,
    ) -> (FourPointSetup, FourPointUnknowns, SolveReport, [Option<LubricatedContacts>; 2]) {
        let (mut x, mut rep) = four_point::solve(&setup, start.as_ref(), speed, factor);
        let Some(oil) = self.oil.as_ref() else { return (setup, x, rep, films) };
        let lubricant = &self.spec.lubricant;
        let mut loads = [(f64::INFINITY, f64::INFINITY); 2];
        let mut settled = false;
        for pass in 0..=FILM_PASSES {
            if !(rep.residual <= accept) {
                // No solution to take the films from: the caller reports it as not converged.
                return (setup, x, rep, films);
            }
            let now = four_point::contact_loads(&setup, &x);
            let reference = setup.plus.nominal_load_n().max(setup.minus.nominal_load_n());
            let moved = (0..2).any(|d| {
                libm::fabs(now[d].0 - loads[d].0) > FILM_LOAD_TOLERANCE * reference
                    || libm::fabs(now[d].1 - loads[d].1) > FILM_LOAD_TOLERANCE * reference
            });
            if !moved {
                settled = true;
                break;
            }
            if pass == FILM_PASSES {
                break;
            }
            loads = now;
            for (d, diagonal) in [&mut setup.plus, &mut setup.minus].into_iter().enumerate() {
                let ball = *diagonal;
                let screw = lubrication::contact_film(&ball, &ball.screw, lubricant, oil, speed, now[d].0);
                let nut = lubrication::contact_film(&ball, &ball.nut, lubricant, oil, speed, now[d].1);
                diagonal.screw.friction = lubrication::contact_friction(&screw, factor);
                diagonal.nut.friction = lubrication::contact_friction(&nut, factor);
                let u = libm::fabs(speed) * lubrication::rolling_entrainment_m(&ball);
                films[d] = Some(LubricatedContacts { screw, nut, rolling_speed_m_s: u });
            }
            let (y, r) = four_point::solve(&setup, Some(&x), speed, factor);
            x = y;
            rep = SolveReport {
                iterations: rep.iterations + r.iterations,
                continuation_steps: rep.continuation_steps + r.continuation_steps,
                residual: r.residual,
            };
        }
        if !settled {
            // The films and the loads did not agree within the passes: no solution.
            rep.residual = f64::INFINITY;
        }
        (setup, x, rep, films)
    }

    /// The load torque F_a L / (2 pi) (N m) of the external axial load at `op`: the net axial
    /// force the balls carry between screw and nut in every arrangement (the two groups of a
    /// preloaded nut carry F1 - F2 = F_a, the preload cancelling).
    pub(crate) fn axial_term_nm(&self, op: &OperatingPoint) -> f64 {
        op.axial_load_n * self.spec.geometry.lead_m / (2.0 * PI)
    }

    /// The load torque at `op`, F_a L / (2 pi), N m: the part of the drive torque that moves
    /// the axial load ([`Summary::load_torque_nm`]), the rest being the drag torque.
    pub fn load_torque_nm(&self, op: &OperatingPoint) -> f64 {
        self.axial_term_nm(op)
    }

    fn pick(&self, energy: f64, eq27: f64) -> f64 {
        match self.spec.model.torque {
            TorqueRoute::Energy => energy,
            TorqueRoute::PaperEq27 => eq27,
        }
    }

    fn summarise(&self, op: &OperatingPoint, tot: &Totals, loads: [f64; MAX_NUTS]) -> Summary {
        let axial = self.axial_term_nm(op);
        let seals = self.seal_torque_nm(op.speed_rad_s);
        let energy = axial + tot.dissipation + seals;
        let eq27 = axial + tot.eq27 + seals;
        Summary {
            operating: *op,
            torque_nm: self.pick(energy, eq27),
            extension_nm: 0.0,
            torque_energy_nm: energy,
            torque_moment_nm: -tot.moment_z + seals,
            torque_eq27_nm: eq27,
            axial_term_nm: axial,
            dissipation_torque_nm: tot.dissipation,
            creep_torque_nm: tot.dissipation - tot.rolling - tot.hysteresis - tot.ball_ball - tot.return_path,
            rolling_resistance_torque_nm: tot.rolling,
            hysteresis_torque_nm: tot.hysteresis,
            ball_ball_torque_nm: tot.ball_ball,
            return_torque_nm: tot.return_path,
            seal_torque_nm: seals,
            screw_axial_force_n: tot.force_z,
            nut_loads_n: loads,
            catalog_nm: catalog::drag_torque_nm(&self.spec.geometry, op.preload_n),
            iterations: tot.iterations,
            max_residual: tot.max_residual,
        }
    }

    /// Whether [`Model::torque`] depends on the magnitude of the speed above the standstill
    /// speed. The lubricated model does (the film, its friction and its rolling resistance grow
    /// with the entrainment speed); the dry creep model does not (every creepage is a ratio of
    /// velocities, docs/model-notes.md item 12: above the standstill speed only the direction
    /// counts), unless the ball train loads the contacts between balls ([`Model::has_train`]); of
    /// the extension terms, `viscous_drag` and `thermal_viscosity` do. When this is
    /// false, two operating points with the same preload, axial load and direction, both at or
    /// above the standstill speed, have the same torque (a test), and a batch may solve such
    /// points once.
    pub fn torque_depends_on_speed_magnitude(&self) -> bool {
        let e = &self.spec.extensions;
        self.oil.is_some() || e.viscous_drag.is_some() || e.thermal_viscosity.is_some() || self.has_train()
    }

    /// Whether the ball train loads the contacts between balls: the return's resistance, which
    /// grows with the speed ([`crate::input::circulation`]), is not zero and the spec does not
    /// set the loads between balls itself.
    pub fn has_train(&self) -> bool {
        let c = &self.spec.circulation;
        self.spec.friction.ball_ball_load_n.is_none()
            && c.return_balls_for(&self.spec.geometry, 1) > 0
            && c.return_friction.unwrap_or_else(|| self.return_wall_friction()) > 0.0
    }

    /// The drive torque at `op`, N m, by the spec's torque route, with the spec's extension
    /// terms at their default conditions: [`Model::summary`]'s `torque_nm` to the bit.
    pub fn torque(&self, op: &OperatingPoint, state: &mut SolverState) -> Result<f64, Error> {
        self.torque_at(op, &Conditions::default(), state)
    }

    /// The drive torque at `op` under `cond` (position, temperature, running time), N m:
    /// [`Model::summary_at`]'s `torque_nm` to the bit.
    pub fn torque_at(&self, op: &OperatingPoint, cond: &Conditions, state: &mut SolverState) -> Result<f64, Error> {
        Ok(self.summary_at(op, cond, state)?.torque_nm)
    }

    /// The scalar results at `op` (every torque route), without the per-contact breakdown.
    ///
    /// Under an axial load the drive torque is the drag plus the load torque `F_a L / (2 pi)`:
    ///
    /// ```
    /// use ballscrew_core::input::rpm_to_rad_s;
    /// use ballscrew_core::{Model, OperatingPoint, ScrewSpec, SolverState};
    ///
    /// let model = Model::new(&ScrewSpec::dkfzd4012())?;
    /// let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(300.0), preload_n: 1500.0, axial_load_n: 500.0 };
    /// let s = model.summary(&op, &mut SolverState::new())?;
    /// let lead_m = model.spec().geometry.lead_m;
    /// assert!((s.load_torque_nm() - 500.0 * lead_m / core::f64::consts::TAU).abs() <= 1e-12);
    /// assert!((s.drag_torque_nm() + s.load_torque_nm() - s.torque_nm).abs() <= 1e-12);
    /// assert!(s.drag_torque_nm() > 0.0);
    /// # Ok::<(), ballscrew_core::Error>(())
    /// ```
    pub fn summary(&self, op: &OperatingPoint, state: &mut SolverState) -> Result<Summary, Error> {
        self.summary_at(op, &Conditions::default(), state)
    }

    /// The scalar results at `op` under `cond`: the creep model runs at the effective operating
    /// point of the extensions, whose terms then join `torque_nm` (see [`crate::input::extensions`]).
    pub fn summary_at(
        &self,
        op: &OperatingPoint,
        cond: &Conditions,
        state: &mut SolverState,
    ) -> Result<Summary, Error> {
        cond.validate()?;
        let ext = &self.spec.extensions;
        let eff = ext.effective_operating(op, cond);
        let (tot, loads) = self.run(&eff, state, &mut |_, _, _, _, _, _| {})?;
        Ok(self.extend(self.summarise(&eff, &tot, loads), op, cond))
    }

    /// Adds the extension terms to a summary of the effective operating point.
    fn extend(&self, mut s: Summary, op: &OperatingPoint, cond: &Conditions) -> Summary {
        let ext = &self.spec.extensions;
        if ext.is_empty() {
            return s;
        }
        let t = self.with_extensions_nm(s.torque_nm, s.axial_term_nm, &s.operating, op, cond);
        s.extension_nm = t - s.torque_nm;
        s.torque_nm = t;
        s.operating = *op;
        s
    }

    /// The torque with the spec's extension terms (N m), from the creep model's torque
    /// `torque_nm` and its axial term `axial_term_nm` (N m) at `eff`, the effective operating
    /// point of `op` under `cond`.
    pub(crate) fn with_extensions_nm(
        &self,
        torque_nm: f64,
        axial_term_nm: f64,
        eff: &OperatingPoint,
        op: &OperatingPoint,
        cond: &Conditions,
    ) -> f64 {
        let speed = op.speed_rad_s;
        let motion = crate::contact::creep::direction(speed)
            * standstill_factor(speed, self.spec.friction.standstill_speed_rad_s);
        self.spec.extensions.torque_nm(torque_nm, axial_term_nm, eff, cond, self.spec.geometry.lead_m, motion)
    }

    /// The full evaluation at `op` with the per-contact breakdown.
    pub fn evaluate(&self, op: &OperatingPoint, state: &mut SolverState) -> Result<Evaluation, Error> {
        let empty = empty_ball();
        let mut balls = [[empty; MAX_CIRCLES_PER_NUT]; MAX_NUTS];
        let z = self.spec.geometry.balls_per_circle;
        // The ball-ball contact's ellipse at the load it carries (the train's, or the spec's).
        let (rb, m) = (0.5 * self.spec.geometry.ball_diameter_m, &self.spec.material);
        let ball_ball_hertz =
            |load_n: f64| hertz::sphere_on_sphere(rb, rb, load_n, m.youngs_modulus_pa, m.poisson_ratio);
        let circles = load::groups(&self.spec.geometry, op.preload_n, op.axial_load_n).circles as usize;
        let (tot, loads) = self.run(op, state, &mut |nut, circle, w, flank, setup, solved| {
            let mut r = empty;
            r.nut = nut;
            r.circle = circle;
            r.flank = flank;
            // The circle's balls at its full load (a load ramp's balls are in the totals only).
            r.ramp_balls = self.ramp_balls_in(circle, circles);
            let z = z - r.ramp_balls;
            r.balls = z;
            r.weight = w;
            r.axial_load_n = setup.axial_load_n;
            if let Some((st, x, rep, films, free)) = solved {
                let (wr, beta, beta_p) = report::attitude(x);
                r.solve = *rep;
                r.omega_tnb_per_screw = [x[0], x[1], x[2]];
                r.spin_ratio = wr;
                r.beta_rad = beta;
                r.beta_prime_rad = beta_p;
                r.orbit_ratio = x[3];
                r.free_orbit_ratio = free;
                // The train's loads in the order of travel (towards +theta forwards): the mean
                // loads ahead and behind of the circle's balls, the chain force at its two ends.
                let (plus, minus) = (setup.ball_ball_plus_n, setup.ball_ball_minus_n);
                let (ahead, behind) = if op.speed_rad_s >= 0.0 { (plus, minus) } else { (minus, plus) };
                r.push_n = behind - ahead;
                // Both >= 0 by construction; the max takes off rounding at the gap.
                let chain_in = ahead + 0.5 * (f64::from(z) + 1.0) * r.push_n;
                r.chain_out_n = (chain_in - f64::from(z) * r.push_n).max(0.0);
                r.chain_in_n = chain_in.max(0.0);
                let share = w * z as f64;
                r.contacts = [
                    raceway_report(ContactKind::Nut, &st.nut, films.map(|f| &f.nut), share),
                    raceway_report(ContactKind::Screw, &st.screw, films.map(|f| &f.screw), share),
                    ball_ball_report(&st.ball_ball, &ball_ball_hertz(st.ball_ball.load_n), setup.ball_ball_mu, share),
                ];
            }
            balls[nut][circle] = r;
        })?;
        let g = &self.spec.geometry;
        let groups = load::groups(g, op.preload_n, op.axial_load_n);
        Ok(Evaluation {
            summary: self.extend(self.summarise(op, &tot, loads), op, &Conditions::default()),
            preload: g.preload,
            nuts: groups.count,
            circles,
            balls,
        })
    }
}

/// Solves a ball from the solved ball of the neighbouring circle (load `from_n`, N, state
/// `x`) by short steps in load, where a direct solve may fail (the balance is nearly
/// degenerate); cold when that fails too.
fn solve_from_neighbour(
    setup: &BallSetup,
    mut x: Unknowns,
    from_n: f64,
    speed: f64,
    factor: f64,
) -> (Unknowns, SolveReport) {
    let fk = factor.max(setup::MIN_SOLVE_FACTOR);
    let (it, res, steps) = solve::continue_load_by(setup, &mut x, from_n, setup.axial_load_n, speed, fk, 1.25);
    if res <= setup::TOLERANCE {
        return (x, SolveReport { iterations: it, residual: res, continuation_steps: steps });
    }
    let (x, mut rep) = solve::solve(setup, None, speed, factor);
    rep.iterations += it;
    rep.continuation_steps += steps;
    (x, rep)
}
