//! `ballscrew contact`: one contact by FASTSIM (Kalker's simplified theory,
//! [`ballscrew_core::contact::fastsim`]) from its creepages, or from a screw operating point and a contact
//! name: the creep forces, the spin moment, the adhesion share and, with `--plot`, the traction
//! field over the contact ellipse (Fig. 10 of the paper). The model's own law, Kalker's linear
//! theory saturated by Eq. (24), is reported alongside for comparison.
//!
//! The contact set-up ([`ContactArgs`], [`Contact`]) and the two force laws are shared with
//! `ballscrew creep-curves`.

use super::torque::{self, PointArgs};
use super::{Context, Format};
use crate::error::CliError;
use crate::input::{checked, count, in_range};
use crate::output::Output;
use crate::plot;
use crate::quantities::{CONTACT_DATA, CREEPAGES, EQ24_EXTRA, FASTSIM_EXTRA, FORCES};
use crate::report::{Quantity, cells, csv, json_object, json_text, keys, vertical_table};
use ballscrew_core::contact::creep::Creepage;
use ballscrew_core::contact::elliptic::ellipse_complete_e;
use ballscrew_core::contact::fastsim::{
    self, Element, FastsimInput, FastsimResult, Grid, TractionBound, fastsim, heathcote_per_m2,
};
use ballscrew_core::contact::forces::{self, ContactForce, ContactStiffness, creep_force};
use ballscrew_core::contact::kalker::{self, CreepCoefficients, kalker_table};
use ballscrew_core::input::rad_s_to_rpm;
use ballscrew_core::{ContactKind, Error, OperatingPoint, SolverState, SpinMoment};
use clap::{Args, ValueEnum};
use nalgebra::Vector3;
use serde_json::{Map, Value};
use std::path::PathBuf;

/// Most FASTSIM elements per axis accepted on the command line.
pub const MAX_GRID: i64 = 400;
/// Smallest semi-axis accepted, mm (0.1 um: below it the contact's numbers leave double
/// precision together with the other flags' extremes).
const MIN_SEMI_AXIS_MM: f64 = 1.0e-4;
/// Largest semi-axis accepted, mm.
const MAX_SEMI_AXIS_MM: f64 = 100.0;
/// Largest normal load accepted, N (the spec's largest preload).
const MAX_LOAD_N: f64 = 1.0e7;
/// Smallest normal load accepted, N.
const MIN_LOAD_N: f64 = 1.0e-6;
/// Smallest friction coefficient accepted (with the smallest load, mu Q stays far from underflow).
const MIN_FRICTION: f64 = 1.0e-4;
/// Largest creepage magnitude accepted, in the flag's unit.
const MAX_CREEPAGE: f64 = 1.0e3;

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

    /// `parabolic` or `elliptical`.
    pub fn name(self) -> &'static str {
        match self {
            Bound::Parabolic => "parabolic",
            Bound::Elliptical => "elliptical",
        }
    }
}

/// Which contact, and the flags that override its data (`contact`, `creep-curves`).
#[derive(Debug, Clone, Args)]
pub struct ContactArgs {
    #[command(flatten)]
    pub point: PointArgs,
    /// Nut of the contact, 1-based (the contact's data come from the model at the operating point)
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
    /// Coefficient of friction mu [default: the spec's]
    #[arg(long, value_name = "MU", allow_hyphen_values = true)]
    pub friction: Option<f64>,
    /// FASTSIM grid: strips across the ellipse, and elements along each strip
    #[arg(long, value_name = "N", default_value_t = 40, allow_negative_numbers = true)]
    pub grid: i64,
}

/// Creepage flags of `ballscrew contact`. Given any of them, the others are 0 and the contact's
/// own creepages are not used.
#[derive(Debug, Clone, Args)]
pub struct CreepArgs {
    /// Longitudinal creepage xi on the centre line y = 0 (the Heathcote term adds k_h y^2)
    /// [default: 0, or the contact's without creepage flags]
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub xi: Option<f64>,
    /// Lateral creepage eta [default: 0, or the contact's]
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub eta: Option<f64>,
    /// Spin creepage phi, 1/mm [default: 0, or the contact's]
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub phi_per_mm: Option<f64>,
    /// Heathcote coefficient k_h, 1/mm^2: longitudinal creepage k_h y^2 at the lateral coordinate
    /// y, mean k_h b^2/5 over the ellipse [default: 0, or the contact's]
    #[arg(long, value_name = "X", allow_hyphen_values = true)]
    pub heathcote_per_mm2: Option<f64>,
}

/// Flags of `ballscrew contact`.
#[derive(Debug, Clone, Args)]
pub struct ContactCmdArgs {
    #[command(flatten)]
    pub target: ContactArgs,
    #[command(flatten)]
    pub creep: CreepArgs,
    /// FASTSIM's traction bound
    #[arg(long, value_enum, default_value_t = Bound::Parabolic)]
    pub bound: Bound,
    /// Also draw the traction field over the ellipse (Fig. 10) to FILE as SVG (atomically)
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
}

/// Creepages of the ball over the other body, FASTSIM's way: `xi` on the centre line and the
/// Heathcote field `k_h y^2` apart (SI units).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Creep {
    /// Longitudinal creepage at `y = 0`.
    pub xi: f64,
    /// Lateral creepage.
    pub eta: f64,
    /// Spin creepage, 1/m.
    pub phi_per_m: f64,
    /// Heathcote coefficient k_h, 1/m^2.
    pub kh_per_m2: f64,
}

/// The screw contact a [`Contact`] was taken from.
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

/// One contact: ellipse, load, friction, material and the model's options (SI units).
#[derive(Debug, Clone, PartialEq)]
pub struct Contact {
    /// Semi-axis a along rolling, m.
    pub a_m: f64,
    /// Semi-axis b lateral, m.
    pub b_m: f64,
    /// Normal load Q, N.
    pub load_n: f64,
    /// Coefficient of friction mu.
    pub mu: f64,
    /// Shear modulus G, Pa.
    pub shear_modulus_pa: f64,
    /// Poisson's ratio.
    pub poisson_ratio: f64,
    /// Creep coefficients of the model's law (the spec's source).
    pub law_coefficients: CreepCoefficients,
    /// Spin moment option of the model's law.
    pub spin: SpinMoment,
    /// FASTSIM elements per axis.
    pub grid: usize,
    /// Where the data came from, in words.
    pub source: String,
    /// The screw contact, when the model was evaluated.
    pub screw: Option<ScrewContact>,
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
    /// The core's totals.
    pub result: FastsimResult,
    /// The forces.
    pub forces: Forces,
}

impl Creep {
    /// The creepages of the flags (`None` when no creepage flag is given), validated.
    fn of_flags(args: &CreepArgs) -> Result<Option<Self>, CliError> {
        let flags = [
            ("--xi", args.xi, 1.0),
            ("--eta", args.eta, 1.0),
            ("--phi-per-mm", args.phi_per_mm, 1e3),
            ("--heathcote-per-mm2", args.heathcote_per_mm2, 1e6),
        ];
        if flags.iter().all(|(_, v, _)| v.is_none()) {
            return Ok(None);
        }
        let mut si = [0.0; 4];
        for (out, (flag, value, to_si)) in si.iter_mut().zip(flags) {
            let v = value.unwrap_or(0.0);
            checked(flag, v, v.abs() <= MAX_CREEPAGE, "finite, |value| <= 1000")?;
            *out = v * to_si;
        }
        Ok(Some(Creep { xi: si[0], eta: si[1], phi_per_m: si[2], kh_per_m2: si[3] }))
    }
}

/// The flags' contact: validates every flag, then evaluates the model when something is to come
/// from it (a semi-axis or the load not given, or `want_creep`).
pub fn resolve(ctx: &Context, args: &ContactArgs, want_creep: bool) -> Result<Contact, CliError> {
    let g = &ctx.spec.geometry;
    let grid = count("--grid", args.grid, 1, MAX_GRID)?;
    let nut = count("--nut", args.nut, 1, i64::from(g.nuts))?;
    let circle = count("--circle", args.circle, 1, i64::from(g.circles_per_nut))?;
    let semi_axis = |flag, v: Option<f64>| {
        v.map(|v| in_range(flag, v, MIN_SEMI_AXIS_MM, MAX_SEMI_AXIS_MM, "finite, [1e-4, 100] mm").map(|mm| mm * 1e-3))
            .transpose()
    };
    let a = semi_axis("--semi-axis-rolling-mm", args.semi_axis_rolling_mm)?;
    let b = semi_axis("--semi-axis-lateral-mm", args.semi_axis_lateral_mm)?;
    let load = args
        .normal_load_n
        .map(|q| in_range("--normal-load-n", q, MIN_LOAD_N, MAX_LOAD_N, "finite, [1e-6, 1e7] N"))
        .transpose()?;
    let mu = match args.friction {
        Some(f) => in_range("--friction", f, MIN_FRICTION, 1.0, "[1e-4, 1]")?,
        None => ctx.spec.friction.coefficient,
    };
    let input = crate::input::PointInput {
        speed_rpm: args.point.speed_rpm,
        preload_n: args.point.preload_n,
        axial_load_n: args.point.axial_load_n,
        preload_flag: "--preload-n",
    };
    let op = ctx.operating_point(&input)?;

    let m = &ctx.spec.material;
    let mut contact = Contact {
        a_m: a.unwrap_or(f64::NAN),
        b_m: b.unwrap_or(f64::NAN),
        load_n: load.unwrap_or(f64::NAN),
        mu,
        shear_modulus_pa: m.shear_modulus_pa(),
        poisson_ratio: m.poisson_ratio,
        law_coefficients: CreepCoefficients { c11: f64::NAN, c22: f64::NAN, c23: f64::NAN, c33: f64::NAN },
        spin: ctx.spec.model.spin_moment,
        grid,
        source: "contact given by the flags".to_string(),
        screw: None,
    };
    if want_creep || a.is_none() || b.is_none() || load.is_none() {
        let ev = ctx.model.evaluate(&op, &mut SolverState::new()).map_err(|e| CliError::eval("evaluation", &e))?;
        let ball = &ev.balls[nut - 1][circle - 1];
        let side = args.contact;
        let where_ = format!("{} contact of nut {nut}, circle {circle} at {}", side.name(), torque::describe(&op));
        let Some(r) = ball.contacts.iter().find(|c| c.kind == side.kind()) else {
            return Err(CliError::Eval(format!("{where_}: no such contact in the evaluation")));
        };
        if !(r.normal_load_n > 0.0 && r.semi_axis_lateral_m > 0.0) {
            return Err(CliError::Input(format!(
                "the {where_} carries no load: choose another contact or operating point, or give \
                 --semi-axis-rolling-mm, --semi-axis-lateral-mm, --normal-load-n and creepages"
            )));
        }
        let heathcote = r.creep_heathcote;
        let creep = Creep {
            xi: r.creep_longitudinal - heathcote,
            eta: r.creep_lateral,
            phi_per_m: r.creep_spin_per_m,
            kh_per_m2: heathcote_per_m2(heathcote, r.semi_axis_lateral_m),
        };
        contact.a_m = a.unwrap_or(r.semi_axis_rolling_m);
        contact.b_m = b.unwrap_or(r.semi_axis_lateral_m);
        contact.load_n = load.unwrap_or(r.normal_load_n);
        let given: Vec<&str> =
            [(a, "a"), (b, "b"), (load, "Q")].iter().filter(|(v, _)| v.is_some()).map(|(_, name)| *name).collect();
        contact.source =
            if given.is_empty() { where_ } else { format!("{where_}, {} from the flags", given.join(", ")) };
        contact.screw = Some(ScrewContact { nut, circle, side, op, creep });
    }
    // The model's coefficients (torque::Model::new), the spec's creep reduction included.
    contact.law_coefficients = kalker::coefficients(
        ctx.spec.model.creep_coefficients,
        contact.a_m / contact.b_m,
        contact.poisson_ratio,
        ctx.spec.friction.creep_reduction,
    );
    Ok(contact)
}

impl Contact {
    /// c = sqrt(a b), m.
    pub fn c_m(&self) -> f64 {
        forces::creep_length_m(self.a_m, self.b_m)
    }

    /// The friction bound mu Q, N.
    pub fn bound_n(&self) -> f64 {
        self.mu * self.load_n
    }

    /// Hertz peak pressure 3 Q / (2 pi a b), Pa.
    pub fn peak_pressure_pa(&self) -> f64 {
        1.5 * self.load_n / (core::f64::consts::PI * self.a_m * self.b_m)
    }

    /// Kalker's table at this contact's a/b: the coefficients FASTSIM's flexibilities are made of.
    pub fn kalker(&self) -> CreepCoefficients {
        kalker_table(self.a_m / self.b_m, self.poisson_ratio)
    }

    /// The Heathcote part of xi (its mean over the ellipse, `k_h b^2 / 5`).
    pub fn heathcote_mean(&self, creep: &Creep) -> f64 {
        fastsim::heathcote_mean(creep.kh_per_m2, self.b_m)
    }

    /// FASTSIM over the Hertz ellipse on the strips grid; the field goes to `elements` when given
    /// (`grid^2` entries).
    pub fn fastsim(
        &self,
        creep: &Creep,
        bound: Bound,
        elements: Option<&mut [Element]>,
    ) -> Result<FastsimForces, CliError> {
        let input = FastsimInput {
            semi_axis_rolling_m: self.a_m,
            semi_axis_lateral_m: self.b_m,
            normal_load_n: self.load_n,
            shear_modulus_pa: self.shear_modulus_pa,
            poisson_ratio: self.poisson_ratio,
            friction_coefficient: self.mu,
            xi: creep.xi,
            eta: creep.eta,
            phi_per_m: creep.phi_per_m,
            heathcote_per_m2: creep.kh_per_m2,
            bound: bound.traction(),
            grid: Grid::Strips,
        };
        let result =
            fastsim(&input, self.grid, self.grid, elements).map_err(|e| CliError::eval("FASTSIM", &Error::Input(e)))?;
        let forces = Forces {
            force_e_n: unsigned_zero(result.force_e_n),
            force_f_n: unsigned_zero(result.force_f_n),
            spin_moment_nm: unsigned_zero(result.spin_moment_nm),
            force_ratio: result.force_e_n.hypot(result.force_f_n) / self.bound_n(),
            dissipation_per_speed_n: result.dissipation_per_speed_n,
        };
        finite(FastsimForces { result, forces }, &forces, "FASTSIM")
    }

    /// The model's law: Kalker's linear theory (Eq. 23) saturated by Eq. (24), the contact built
    /// as the model builds it (`kinematics::raceway_state`): c = sqrt(a b), the spec's creep
    /// coefficients, bound mu Q, full-slip spin arm (3/8) b_major E(m), the spec's spin option;
    /// xi carries the Heathcote mean.
    pub fn linear_saturated(&self, creep: &Creep) -> Result<(ContactForce, Forces), CliError> {
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
            self.a_m,
            self.b_m,
            ellipse_complete_e(self.a_m, self.b_m),
            self.law_coefficients,
            self.bound_n(),
        );
        let f = creep_force(&cr, &stiffness, self.spin);
        let forces = Forces {
            force_e_n: unsigned_zero(f.e_n),
            force_f_n: unsigned_zero(f.f_n),
            spin_moment_nm: unsigned_zero(f.moment_nm),
            force_ratio: f.e_n.hypot(f.f_n) / self.bound_n(),
            dissipation_per_speed_n: -(f.e_n * xi + f.f_n * creep.eta + f.moment_nm * creep.phi_per_m),
        };
        finite((f, forces), &forces, "Eq. 24")
    }

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

/// `x` with a negative zero made positive (a zero creepage times a coefficient).
fn unsigned_zero(x: f64) -> f64 {
    if x == 0.0 { 0.0 } else { x }
}

/// `value` when every force is finite, else an evaluation error (exit code 1).
fn finite<T>(value: T, f: &Forces, law: &str) -> Result<T, CliError> {
    let all = [f.force_e_n, f.force_f_n, f.spin_moment_nm, f.force_ratio, f.dissipation_per_speed_n];
    if all.iter().all(|x| x.is_finite()) {
        Ok(value)
    } else {
        Err(CliError::Eval(format!("{law}: the forces are not finite for this contact")))
    }
}

/// One contact solved by both laws.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactRun {
    /// The contact.
    pub contact: Contact,
    /// Its creepages.
    pub creep: Creep,
    /// FASTSIM's bound.
    pub bound: Bound,
    /// FASTSIM.
    pub fastsim: FastsimForces,
    /// The model's law, in full.
    pub law: ContactForce,
    /// The model's law, as forces.
    pub law_forces: Forces,
}

impl ContactRun {
    /// Solves `contact` under `creep` by FASTSIM (field to `elements` when given) and Eq. 24.
    pub fn new(
        contact: Contact,
        creep: Creep,
        bound: Bound,
        elements: Option<&mut [Element]>,
    ) -> Result<Self, CliError> {
        let fastsim = contact.fastsim(&creep, bound, elements)?;
        let (law, law_forces) = contact.linear_saturated(&creep)?;
        Ok(Self { contact, creep, bound, fastsim, law, law_forces })
    }
}

/// Runs `ballscrew contact` and renders it.
pub fn run(ctx: &Context, args: &ContactCmdArgs) -> Result<Output, CliError> {
    let flags = Creep::of_flags(&args.creep)?;
    let contact = resolve(ctx, &args.target, flags.is_none())?;
    let creep = flags.or(contact.screw.map(|s| s.creep)).unwrap_or_default();
    let mut elements = vec![Element::default(); contact.grid * contact.grid];
    let run = ContactRun::new(contact, creep, args.bound, Some(&mut elements))?;
    let text = match ctx.format {
        Format::Table => table(ctx, &run),
        Format::Csv => csv_text(&run),
        Format::Json => json(ctx, &run),
    };
    let plot = match &args.plot {
        Some(path) => Some((path.clone(), plot::traction_svg(&run, &elements)?)),
        None => None,
    };
    Ok(Output::with_plot(Some(text), plot))
}

/// FASTSIM against Eq. 24, one column each.
const LAW_HEADS: [&str; 2] = ["FASTSIM", "Eq. 24"];

fn table(ctx: &Context, run: &ContactRun) -> String {
    let mut out = format!("ballscrew contact: {}; {}\n", ctx.origin, run.contact.source);
    let section = |out: &mut String, title: &str, body: String| {
        out.push('\n');
        out.push_str(title);
        out.push('\n');
        out.push_str(&body);
    };
    section(
        &mut out,
        "contact",
        vertical_table(CONTACT_DATA, core::slice::from_ref(&run.contact), &["value"]).render(2),
    );
    section(
        &mut out,
        "creepages of the ball over the raceway",
        vertical_table(CREEPAGES, core::slice::from_ref(run), &["value"]).render(2),
    );
    section(
        &mut out,
        "forces on the ball (contact frame: e rolling, f lateral)",
        vertical_table(FORCES, &[run.fastsim.forces, run.law_forces], &LAW_HEADS).render(2),
    );
    section(
        &mut out,
        "FASTSIM (Kalker's simplified theory), strips grid",
        vertical_table(FASTSIM_EXTRA, core::slice::from_ref(run), &["value"]).render(2),
    );
    section(
        &mut out,
        "Eq. 24 (Kalker's linear theory, saturated; the model's law)",
        vertical_table(EQ24_EXTRA, core::slice::from_ref(run), &["value"]).render(2),
    );
    out
}

/// `prefix` + each key.
fn prefixed<T>(prefix: &str, quantities: &[Quantity<T>]) -> Vec<String> {
    keys(quantities).iter().map(|k| format!("{prefix}{k}")).collect()
}

/// One row: contact, creepages, FASTSIM (`fastsim_*`), Eq. 24 (`eq24_*`).
fn csv_text(run: &ContactRun) -> String {
    let header: Vec<String> = [
        prefixed("", CONTACT_DATA),
        prefixed("", CREEPAGES),
        prefixed("fastsim_", FORCES),
        prefixed("fastsim_", FASTSIM_EXTRA),
        prefixed("eq24_", FORCES),
        prefixed("eq24_", EQ24_EXTRA),
    ]
    .concat();
    let row = [
        cells(CONTACT_DATA, &run.contact),
        cells(CREEPAGES, run),
        cells(FORCES, &run.fastsim.forces),
        cells(FASTSIM_EXTRA, run),
        cells(FORCES, &run.law_forces),
        cells(EQ24_EXTRA, run),
    ]
    .concat();
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    csv(&header, &[row])
}

fn json(ctx: &Context, run: &ContactRun) -> String {
    let mut head = ctx.json_head("contact");
    head.insert("source".into(), run.contact.source.as_str().into());
    head.insert("screw".into(), run.contact.screw_json());
    head.insert("contact".into(), Value::Object(json_object(CONTACT_DATA, &run.contact)));
    head.insert("creepages".into(), Value::Object(json_object(CREEPAGES, run)));
    let mut f = json_object(FORCES, &run.fastsim.forces);
    f.extend(json_object(FASTSIM_EXTRA, run));
    head.insert("fastsim".into(), Value::Object(f));
    let mut l = json_object(FORCES, &run.law_forces);
    l.extend(json_object(EQ24_EXTRA, run));
    head.insert("eq24".into(), Value::Object(l));
    json_text(&Value::Object(head))
}
