//! Flag groups shared by several commands, and what they resolve to: an operating point
//! ([`PointArgs`]: `torque`, `inspect`, `contact`, `creep-curves`) and one contact of the screw
//! ([`ContactArgs`]: `contact`, `creep-curves`), resolved into the core's contact analysis
//! ([`ballscrew_core::contact::analysis`]) with where its data came from ([`ContactSetup`]).

use crate::error::CliError;
use crate::spec_and_flags::{self, PointInput, count, in_range};
use crate::table::format_short;
use ballscrew_core::contact::analysis::{Contact, Creep, Forces, ModelLaw};
use ballscrew_core::contact::fastsim::TractionBound;
use ballscrew_core::contact::limits::{self, FRICTION, NORMAL_LOAD_N, SEMI_AXIS_MM};
use ballscrew_core::input::rad_s_to_rpm;
use ballscrew_core::{ContactKind, Evaluation, Model, OperatingPoint, ScrewSpec, SolverState};
use clap::{Args, ValueEnum};
use serde_json::{Map, Value};

/// Flags of one operating point (`ballscrew torque`, `ballscrew inspect`, and the screw point of
/// `contact` and `creep-curves`), the oil temperature at the contacts among them (applied to the
/// context's model by [`crate::commands::Context::with_oil_temperature`]).
#[derive(Debug, Clone, Args)]
pub struct PointArgs {
    /// Preload, N [default: the spec's]
    #[arg(long, visible_alias = "preload", value_name = "N", allow_negative_numbers = true)]
    pub preload_n: Option<f64>,
    /// Screw speed, rpm; negative for reverse rotation [default: the spec's]
    #[arg(long, value_name = "RPM", allow_negative_numbers = true)]
    pub speed_rpm: Option<f64>,
    /// External axial load on the nut, N [default: the spec's]
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub axial_load_n: Option<f64>,
    /// Oil temperature at the contacts, degrees C (lubrication = "ehl" only) [default: the
    /// spec's lubricant.temperature_c]
    #[arg(long, value_name = "C", allow_negative_numbers = true)]
    pub oil_temperature_c: Option<f64>,
}

impl PointArgs {
    /// The flags as typed.
    pub fn input(&self) -> PointInput {
        PointInput {
            speed_rpm: self.speed_rpm,
            preload_n: self.preload_n,
            axial_load_n: self.axial_load_n,
            preload_flag: "--preload-n",
        }
    }

    /// Validates the point and evaluates it (cold start).
    pub fn evaluate(&self, spec: &ScrewSpec, model: &Model) -> Result<Evaluation, CliError> {
        let op = spec_and_flags::operating_point(spec, &self.input())?;
        model.evaluate(&op, &mut SolverState::new()).map_err(|e| CliError::eval("evaluation", &e))
    }
}

/// `speed 100 rpm, preload 2000 N, axial load 0 N`, leaving out what is `None`.
pub fn describe_point(speed_rpm: Option<f64>, preload_n: Option<f64>, axial_load_n: Option<f64>) -> String {
    let mut parts = Vec::new();
    if let Some(s) = speed_rpm {
        parts.push(format!("speed {} rpm", format_short(s)));
    }
    if let Some(p) = preload_n {
        parts.push(format!("preload {} N", format_short(p)));
    }
    if let Some(a) = axial_load_n {
        parts.push(format!("axial load {} N", format_short(a)));
    }
    parts.join(", ")
}

/// `speed 100 rpm, preload 2000 N, axial load 0 N`.
pub fn describe(op: &OperatingPoint) -> String {
    op.to_string()
}

/// A raceway contact of the ball.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Side {
    /// Ball-nut contact (A).
    Nut,
    /// Ball-screw contact (B).
    Screw,
}

impl Side {
    fn kind(self) -> ContactKind {
        match self {
            Side::Nut => ContactKind::Nut,
            Side::Screw => ContactKind::Screw,
        }
    }

    /// `nut` or `screw`.
    pub fn name(self) -> &'static str {
        self.kind().name()
    }
}

/// Shape of FASTSIM's traction bound over the ellipse.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Bound {
    /// Kalker's parabolic pressure (FASTSIM's usual bound).
    Parabolic,
    /// The Hertz (semi-ellipsoidal) pressure.
    Elliptical,
}

impl Bound {
    /// The core's bound.
    pub fn traction(self) -> TractionBound {
        match self {
            Bound::Parabolic => TractionBound::Parabolic,
            Bound::Elliptical => TractionBound::Elliptical,
        }
    }
}

/// Which contact, and the flags that override its data (`contact`, `creep-curves`).
#[derive(Debug, Clone, Args)]
pub struct ContactArgs {
    #[command(flatten)]
    pub point: PointArgs,
    /// Nut of the contact, 1-based: of a double nut, its nut; of an offset-lead nut, its half; of
    /// oversize balls, the contact diagonal (1: flank +, 2: flank -) (the contact's data come from
    /// the model at the operating point)
    #[arg(long, value_name = "N", default_value_t = 1, allow_negative_numbers = true)]
    pub nut: i64,
    /// Circle (turn) of that nut, 1-based
    #[arg(long, value_name = "C", default_value_t = 1, allow_negative_numbers = true)]
    pub circle: i64,
    /// Which raceway contact of the ball
    #[arg(long, value_enum, default_value_t = Side::Nut)]
    pub contact: Side,
    /// Hertz semi-axis a along the rolling direction, mm [default: the contact's]
    #[arg(long, value_name = "MM", allow_hyphen_values = true)]
    pub semi_axis_rolling_mm: Option<f64>,
    /// Hertz semi-axis b across the rolling direction (lateral), mm [default: the contact's]
    #[arg(long, value_name = "MM", allow_hyphen_values = true)]
    pub semi_axis_lateral_mm: Option<f64>,
    /// Normal load Q, N [default: the contact's]
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    pub normal_load_n: Option<f64>,
    /// Coefficient of friction mu, the bound of Eq. 24 and FASTSIM [default: the model contact's
    /// own: under lubrication = "ehl" the mixed-film coefficient of that contact at the operating
    /// point, under "dry" friction.coefficient; a contact given by the flags alone (semi-axes,
    /// load and creepages: no film without the model) takes friction.coefficient, as the output
    /// says]
    #[arg(long, value_name = "MU", allow_hyphen_values = true)]
    pub friction: Option<f64>,
    /// FASTSIM grid: strips across the ellipse, and elements along each strip
    #[arg(long, value_name = "N", default_value_t = 40, allow_negative_numbers = true)]
    pub grid: i64,
}

/// The screw contact a [`ContactSetup`] was taken from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScrewContact {
    /// Nut, 1-based.
    pub nut: usize,
    /// Circle, 1-based.
    pub circle: usize,
    /// Which raceway.
    pub side: Side,
    /// The operating point.
    pub op: OperatingPoint,
    /// The contact's creepages at that point.
    pub creep: Creep,
}

/// The contact of the flags: the core's contact, the model's law at it, FASTSIM's grid, and
/// where the data came from.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactSetup {
    /// Ellipse, load, material and friction (SI units).
    pub contact: Contact,
    /// The model's law at the contact (the spec's creep coefficients and spin option).
    pub law: ModelLaw,
    /// FASTSIM elements per axis.
    pub grid: usize,
    /// Where the data came from, in words.
    pub source: String,
    /// The screw contact, when the model was evaluated.
    pub screw: Option<ScrewContact>,
    /// Where the friction coefficient came from, in words (`--friction`, the model contact's,
    /// or the spec's `friction.coefficient`).
    pub friction_source: String,
}

/// The flags' contact: validates every flag, then evaluates the model when something is to come
/// from it (a semi-axis or the load not given, or `want_creep`).
pub fn resolve(
    spec: &ScrewSpec,
    model: &Model,
    args: &ContactArgs,
    want_creep: bool,
) -> Result<ContactSetup, CliError> {
    let g = &spec.geometry;
    let grid = count("--grid", args.grid, 1, limits::MAX_GRID)?;
    // The load groups: the nuts of a double nut, the halves of an offset-lead nut, the two
    // contact diagonals of oversize balls, the one nut without preload.
    let groups = ballscrew_core::screw::load::groups(g, 0.0, 0.0);
    let nut = count("--nut", args.nut, 1, groups.count as i64)?;
    let circle = count("--circle", args.circle, 1, i64::from(groups.circles))?;
    let semi_axis = |flag, v: Option<f64>| {
        v.map(|v| in_range(flag, v, SEMI_AXIS_MM.lo, SEMI_AXIS_MM.hi, SEMI_AXIS_MM.valid).map(|mm| mm * 1e-3))
            .transpose()
    };
    let a = semi_axis("--semi-axis-rolling-mm", args.semi_axis_rolling_mm)?;
    let b = semi_axis("--semi-axis-lateral-mm", args.semi_axis_lateral_mm)?;
    let load = args
        .normal_load_n
        .map(|q| in_range("--normal-load-n", q, NORMAL_LOAD_N.lo, NORMAL_LOAD_N.hi, NORMAL_LOAD_N.valid))
        .transpose()?;
    let given_mu =
        args.friction.map(|f| in_range("--friction", f, FRICTION.lo, FRICTION.hi, FRICTION.valid)).transpose()?;
    let op = spec_and_flags::operating_point(spec, &args.point.input())?;

    let (mut a_m, mut b_m, mut load_n) = (a.unwrap_or(f64::NAN), b.unwrap_or(f64::NAN), load.unwrap_or(f64::NAN));
    let mut source = "contact given by the flags".to_string();
    let mut screw = None;
    let mut model_mu = None;
    if want_creep || a.is_none() || b.is_none() || load.is_none() {
        let ev = model.evaluate(&op, &mut SolverState::new()).map_err(|e| CliError::eval("evaluation", &e))?;
        let ball = &ev.balls[nut - 1][circle - 1];
        let side = args.contact;
        let where_ = format!("{} contact of nut {nut}, circle {circle} at {}", side.name(), describe(&op));
        let Some(r) = ball.contacts.iter().find(|c| c.kind == side.kind()) else {
            return Err(CliError::Eval(format!("{where_}: no such contact in the evaluation")));
        };
        if !(r.normal_load_n > 0.0 && r.semi_axis_lateral_m > 0.0) {
            return Err(CliError::Input(format!(
                "the {where_} carries no load: choose another contact or operating point, or give \
                 --semi-axis-rolling-mm, --semi-axis-lateral-mm, --normal-load-n and creepages"
            )));
        }
        let creep = Creep::of_model(
            r.creep_longitudinal,
            r.creep_lateral,
            r.creep_spin_per_m,
            r.creep_heathcote,
            r.semi_axis_lateral_m,
        );
        a_m = a.unwrap_or(r.semi_axis_rolling_m);
        b_m = b.unwrap_or(r.semi_axis_lateral_m);
        load_n = load.unwrap_or(r.normal_load_n);
        let given: Vec<&str> =
            [(a, "a"), (b, "b"), (load, "Q")].iter().filter(|(v, _)| v.is_some()).map(|(_, name)| *name).collect();
        source = if given.is_empty() { where_ } else { format!("{where_}, {} from the flags", given.join(", ")) };
        screw = Some(ScrewContact { nut, circle, side, op, creep });
        model_mu = Some(r.friction_coefficient);
    }
    let (mu, friction_source) = match (given_mu, model_mu) {
        (Some(f), _) => (f, "--friction".to_string()),
        (None, Some(f)) => (f, format!("the model contact's ({})", spec.model.lubrication.name())),
        (None, None) => (spec.friction.coefficient, "friction.coefficient of the spec".to_string()),
    };
    let m = &spec.material;
    let contact = Contact {
        semi_axis_rolling_m: a_m,
        semi_axis_lateral_m: b_m,
        normal_load_n: load_n,
        shear_modulus_pa: m.shear_modulus_pa(),
        poisson_ratio: m.poisson_ratio,
        friction_coefficient: mu,
    };
    // The model's coefficients (torque::Model::new), the spec's creep reduction included.
    let law =
        ModelLaw::new(spec.model.creep_coefficients, spec.friction.creep_reduction, spec.model.spin_moment, &contact);
    Ok(ContactSetup { contact, law, grid, source, screw, friction_source })
}

impl ContactSetup {
    /// The screw contact as JSON (`null` when the model was not used).
    pub fn screw_json(&self) -> Value {
        let Some(s) = &self.screw else { return Value::Null };
        let mut m = Map::new();
        m.insert("nut".into(), (s.nut as u64).into());
        m.insert("circle".into(), (s.circle as u64).into());
        m.insert("contact".into(), s.side.name().into());
        m.insert("speed_rpm".into(), rad_s_to_rpm(s.op.speed_rad_s).into());
        m.insert("preload_n".into(), s.op.preload_n.into());
        m.insert("axial_load_n".into(), s.op.axial_load_n.into());
        Value::Object(m)
    }
}

/// Ok when every force of a law (`FASTSIM`, `Eq. 24`) is finite, else an evaluation error (exit
/// code 1): values valid one by one can still overflow together.
pub fn finite(forces: &Forces, law: &str) -> Result<(), CliError> {
    if forces.is_finite() {
        Ok(())
    } else {
        Err(CliError::Eval(format!("{law}: the forces are not finite for this contact")))
    }
}
