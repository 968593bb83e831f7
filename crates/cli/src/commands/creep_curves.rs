//! `ballscrew creep-curves`: the friction of one contact against each creep parameter in turn,
//! the other three zero (Fig. 9 of the paper): xi, eta, the spin as `phi c` and the Heathcote
//! coefficient as `k_h b^2` (all dimensionless, c = sqrt(a b)), by FASTSIM and by the model's
//! law (Eq. 24).
//!
//! Each parameter runs from 0 to `--span` times its *linear saturation value*, where Kalker's
//! linear force (with FASTSIM's coefficients) reaches mu Q: `xi_s = mu Q / (G c^2 C11)`,
//! `eta_s = mu Q / (G c^2 C22)`, `(phi c)_s = mu Q / (G c^2 C23)` and, the Heathcote mean being
//! `k_h b^2 / 5`, `(k_h b^2)_s = 5 xi_s`.

use super::contact::{Bound, Contact, ContactArgs, Creep, Forces, resolve};
use super::{Context, Format};
use crate::error::CliError;
use crate::input::{checked, count};
use crate::output::Output;
use crate::plot;
use crate::quantities::{CONTACT_DATA, CURVE_ROW};
use crate::report::{cells, csv, json_object, json_text, keys};
use crate::table::{Cell, Table, format_short};
use ballscrew_core::contact::fastsim::HEATHCOTE_B2_PER_MEAN;
use clap::Args;
use core::fmt::Write as _;
use serde_json::{Map, Value};
use std::path::PathBuf;

/// Most points per curve.
const MAX_POINTS: i64 = 1000;
/// Largest span.
const MAX_SPAN: f64 = 1000.0;

/// Flags of `ballscrew creep-curves`.
#[derive(Debug, Clone, Args)]
pub struct CurveArgs {
    #[command(flatten)]
    pub target: ContactArgs,
    /// FASTSIM's traction bound [default: both]
    #[arg(long, value_enum)]
    pub bound: Option<Bound>,
    /// Points per curve, both ends included
    #[arg(long, value_name = "N", default_value_t = 41, allow_negative_numbers = true)]
    pub points: i64,
    /// Each parameter from 0 to SPAN times its linear saturation value (Kalker's linear force = mu Q)
    #[arg(long, value_name = "X", default_value_t = 4.0, allow_hyphen_values = true)]
    pub span: f64,
    /// Draw the curves (Fig. 9) to FILE as SVG (atomically); the data then go to --out only
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
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

impl Parameter {
    /// The four, in Fig. 9's order.
    pub const ALL: [Parameter; 4] = [Parameter::Xi, Parameter::Eta, Parameter::PhiC, Parameter::KhB2];

    /// CSV/JSON name.
    pub fn key(self) -> &'static str {
        match self {
            Parameter::Xi => "xi",
            Parameter::Eta => "eta",
            Parameter::PhiC => "phi_c",
            Parameter::KhB2 => "kh_b2",
        }
    }

    /// Words, for tables and plots.
    pub fn label(self) -> &'static str {
        match self {
            Parameter::Xi => "longitudinal creepage xi",
            Parameter::Eta => "lateral creepage eta",
            Parameter::PhiC => "spin phi c",
            Parameter::KhB2 => "Heathcote k_h b^2",
        }
    }

    /// The creepages with this parameter at `value` and the other three zero.
    pub fn creep(self, value: f64, contact: &Contact) -> Creep {
        match self {
            Parameter::Xi => Creep { xi: value, ..Creep::default() },
            Parameter::Eta => Creep { eta: value, ..Creep::default() },
            Parameter::PhiC => Creep { phi_per_m: value / contact.c_m(), ..Creep::default() },
            Parameter::KhB2 => Creep { kh_per_m2: value / (contact.b_m * contact.b_m), ..Creep::default() },
        }
    }

    /// The linear saturation value: where Kalker's linear force reaches mu Q.
    pub fn saturation_value(self, contact: &Contact) -> f64 {
        let c = contact.c_m();
        let k = contact.kalker();
        let per_coefficient = contact.bound_n() / (contact.shear_modulus_pa * c * c);
        match self {
            Parameter::Xi => per_coefficient / k.c11,
            Parameter::Eta => per_coefficient / k.c22,
            Parameter::PhiC => per_coefficient / k.c23,
            Parameter::KhB2 => HEATHCOTE_B2_PER_MEAN * per_coefficient / k.c11,
        }
    }
}

/// A force law of the curves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Law {
    /// FASTSIM with a bound.
    Fastsim(Bound),
    /// The model's law: Kalker's linear theory saturated by Eq. (24).
    Eq24,
}

impl Law {
    /// CSV/JSON name.
    pub fn key(self) -> &'static str {
        match self {
            Law::Fastsim(Bound::Parabolic) => "fastsim-parabolic",
            Law::Fastsim(Bound::Elliptical) => "fastsim-elliptical",
            Law::Eq24 => "eq24",
        }
    }

    /// Words, for legends.
    pub fn label(self) -> &'static str {
        match self {
            Law::Fastsim(Bound::Parabolic) => "FASTSIM, parabolic bound",
            Law::Fastsim(Bound::Elliptical) => "FASTSIM, elliptical bound",
            Law::Eq24 => "Eq. 24 (the model's law)",
        }
    }

    /// Short words, for table headings.
    fn head(self) -> &'static str {
        match self {
            Law::Fastsim(Bound::Parabolic) => "FASTSIM parab.",
            Law::Fastsim(Bound::Elliptical) => "FASTSIM ellip.",
            Law::Eq24 => "Eq. 24",
        }
    }
}

/// One point of a curve.
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

/// One curve: a parameter under a law.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// The parameter varied.
    pub parameter: Parameter,
    /// The law.
    pub law: Law,
    /// The parameter's linear saturation value.
    pub saturation_value: f64,
    /// The points, by increasing value.
    pub points: Vec<CurvePoint>,
}

/// All curves of one contact: for each parameter, one curve per law.
#[derive(Debug, Clone, PartialEq)]
pub struct Curves {
    /// The contact.
    pub contact: Contact,
    /// The laws, in order.
    pub laws: Vec<Law>,
    /// The span.
    pub span: f64,
    /// The curves, by parameter then law.
    pub curves: Vec<Curve>,
}

impl Curves {
    /// The curves of one parameter.
    pub fn of(&self, parameter: Parameter) -> impl Iterator<Item = &Curve> {
        self.curves.iter().filter(move |c| c.parameter == parameter)
    }
}

/// Evaluates every curve.
pub fn evaluate(contact: Contact, laws: Vec<Law>, points: usize, span: f64) -> Result<Curves, CliError> {
    let mut curves = Vec::new();
    for parameter in Parameter::ALL {
        let saturation_value = parameter.saturation_value(&contact);
        for &law in &laws {
            let values = (0..points).map(|i| span * saturation_value * i as f64 / (points - 1) as f64);
            let rows = values
                .map(|value| {
                    let creep = parameter.creep(value, &contact);
                    let (forces, adhesion_share) = match law {
                        Law::Fastsim(bound) => {
                            let f = contact.fastsim(&creep, bound, None)?;
                            (f.forces, f.result.adhesion_share())
                        }
                        Law::Eq24 => (contact.linear_saturated(&creep)?.1, f64::NAN),
                    };
                    Ok(CurvePoint { parameter, law, value, forces, adhesion_share })
                })
                .collect::<Result<Vec<_>, CliError>>()?;
            curves.push(Curve { parameter, law, saturation_value, points: rows });
        }
    }
    Ok(Curves { contact, laws, span, curves })
}

/// Runs `ballscrew creep-curves` and renders it. With `--plot` the data are rendered only when
/// they go to a file (`to_file`: `--out` given).
pub fn run(ctx: &Context, args: &CurveArgs, to_file: bool) -> Result<Output, CliError> {
    let points = count("--points", args.points, 2, MAX_POINTS)?;
    let span = checked("--span", args.span, args.span > 0.0 && args.span <= MAX_SPAN, "finite, (0, 1000]")?;
    let contact = resolve(ctx, &args.target, false)?;
    let laws = match args.bound {
        Some(b) => vec![Law::Fastsim(b), Law::Eq24],
        None => vec![Law::Fastsim(Bound::Parabolic), Law::Fastsim(Bound::Elliptical), Law::Eq24],
    };
    let curves = evaluate(contact, laws, points, span)?;
    let plot = match &args.plot {
        Some(path) => Some((path.clone(), plot::curves_svg(&curves)?)),
        None => None,
    };
    let text = (plot.is_none() || to_file).then(|| match ctx.format {
        Format::Table => table(ctx, &curves),
        Format::Csv => {
            let rows: Vec<Vec<Cell>> =
                curves.curves.iter().flat_map(|c| &c.points).map(|p| cells(CURVE_ROW, p)).collect();
            csv(&keys(CURVE_ROW), &rows)
        }
        Format::Json => json(ctx, &curves),
    });
    Ok(Output::with_plot(text, plot))
}

/// Per parameter: a row per value, for each law F_e, F_f and |F|/(mu Q).
fn table(ctx: &Context, curves: &Curves) -> String {
    let c = &curves.contact;
    let mut out = format!("ballscrew creep-curves: {}; {}\n", ctx.origin, c.source);
    let _ = writeln!(
        out,
        "a = {} mm, b = {} mm, Q = {} N, mu = {}; FASTSIM on {} x {} strips; each parameter alone, the other three 0",
        format_short(c.a_m * 1e3),
        format_short(c.b_m * 1e3),
        format_short(c.load_n),
        format_short(c.mu),
        c.grid,
        c.grid
    );
    for parameter in Parameter::ALL {
        let set: Vec<_> = curves.of(parameter).collect();
        let Some(first) = set.first() else { continue };
        let _ = writeln!(
            out,
            "\n{} (linear saturation at {}, span {})",
            parameter.label(),
            format_short(first.saturation_value),
            format_short(curves.span)
        );
        let mut laws = vec![String::new()];
        let mut heads = vec!["value".to_string()];
        for curve in &set {
            laws.extend([curve.law.head().to_string(), String::new(), String::new()]);
            heads.extend(["|F|/muQ", "F_e [N]", "F_f [N]"].map(String::from));
        }
        let rows = (0..first.points.len())
            .map(|i| {
                let mut row = vec![Cell::Num(first.points[i].value)];
                for curve in &set {
                    let f = &curve.points[i].forces;
                    row.extend([Cell::Num(f.force_ratio), Cell::Num(f.force_e_n), Cell::Num(f.force_f_n)]);
                }
                row
            })
            .collect();
        out.push_str(&Table { header: vec![laws, heads], rows }.render(2));
    }
    out
}

fn json(ctx: &Context, curves: &Curves) -> String {
    let c = &curves.contact;
    let mut head = ctx.json_head("creep-curves");
    head.insert("source".into(), c.source.as_str().into());
    head.insert("screw".into(), c.screw_json());
    let mut contact = json_object(CONTACT_DATA, c);
    contact.insert("grid".into(), (c.grid as u64).into());
    head.insert("contact".into(), Value::Object(contact));
    head.insert("span".into(), curves.span.into());
    let list: Vec<Value> = curves
        .curves
        .iter()
        .map(|curve| {
            let mut m = Map::new();
            m.insert("parameter".into(), curve.parameter.key().into());
            m.insert("law".into(), curve.law.key().into());
            m.insert("linear_saturation_value".into(), curve.saturation_value.into());
            let rows: Vec<Value> = curve
                .points
                .iter()
                .map(|p| {
                    let mut o = json_object(CURVE_ROW, p);
                    o.remove("parameter");
                    o.remove("law");
                    Value::Object(o)
                })
                .collect();
            m.insert("rows".into(), Value::Array(rows));
            Value::Object(m)
        })
        .collect();
    head.insert("curves".into(), Value::Array(list));
    json_text(&Value::Object(head))
}
