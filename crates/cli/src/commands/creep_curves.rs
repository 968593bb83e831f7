//! `ballscrew creep-curves`: the friction of one contact against each creep parameter in turn,
//! the other three zero (Fig. 9 of the paper): xi, eta, the spin as `phi c` and the Heathcote
//! coefficient as `k_h b^2` (all dimensionless, c = sqrt(a b)), by FASTSIM and by the model's
//! law (Eq. 24).
//!
//! Each parameter runs from 0 to `--span` times its *linear saturation value*, where Kalker's
//! linear force (with FASTSIM's coefficients) reaches mu Q
//! ([`ballscrew_core::contact::analysis::Contact::saturation_value`]); the points are the core's
//! ([`crate::curves`]).

use super::{Context, Format, FormatArg};
use crate::args::{Bound, ContactArgs, resolve};
use crate::curves::Curves;
use crate::error::CliError;
use crate::output::{Named, Output};
use crate::plots;
use crate::report::{cells, csv, json_object, json_text, keys};
use crate::spec_and_flags::{checked, count};
use crate::table::{Cell, Table, format_short};
use ballscrew_batch::quantities::{CONTACT_DATA, CURVE_ROW};
use ballscrew_core::contact::analysis::{Law, Parameter};
use ballscrew_core::contact::fastsim::TractionBound;
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
    pub output: FormatArg,
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

/// A parameter in words, for tables.
fn label(parameter: Parameter) -> &'static str {
    match parameter {
        Parameter::Xi => "longitudinal creepage xi",
        Parameter::Eta => "lateral creepage eta",
        Parameter::PhiC => "spin phi c",
        Parameter::KhB2 => "Heathcote k_h b^2",
    }
}

/// A law in short words, for table headings.
fn head(law: Law) -> &'static str {
    match law {
        Law::Fastsim(TractionBound::Parabolic) => "FASTSIM parab.",
        Law::Fastsim(TractionBound::Elliptical) => "FASTSIM ellip.",
        Law::Eq24 => "Eq. 24",
    }
}

/// The file the flags name (`--plot`).
pub fn outputs(args: &CurveArgs) -> Named<'_> {
    Named { files: args.plot.iter().map(|p| ("--plot", p.as_path())).collect(), dirs: Vec::new() }
}

/// Runs `ballscrew creep-curves` and renders it. With `--plot` the data are rendered only when
/// asked for by `--out` (`to_file`: `--out` given, `--out -` for stdout included).
pub fn run(ctx: &Context, args: &CurveArgs, to_file: bool) -> Result<Output, CliError> {
    let points = count("--points", args.points, 2, MAX_POINTS)?;
    let span = checked("--span", args.span, args.span > 0.0 && args.span <= MAX_SPAN, "finite, (0, 1000]")?;
    let setup = resolve(&ctx.spec, &ctx.model, &args.target, false)?;
    let laws = match args.bound {
        Some(b) => vec![Law::Fastsim(b.traction()), Law::Eq24],
        None => vec![Law::Fastsim(TractionBound::Parabolic), Law::Fastsim(TractionBound::Elliptical), Law::Eq24],
    };
    let curves = Curves::evaluate(setup, laws, points, span)?;
    let plot = match &args.plot {
        Some(path) => Some((path.clone(), plots::creep_curves::svg(&curves)?)),
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
    let s = &curves.setup;
    let c = &s.contact;
    let mut out = format!("ballscrew creep-curves: {}; {}\n", ctx.origin, s.source);
    let _ = writeln!(
        out,
        "a = {} mm, b = {} mm, Q = {} N, mu = {}; FASTSIM on {} x {} strips; each parameter alone, the other three 0",
        format_short(c.semi_axis_rolling_m * 1e3),
        format_short(c.semi_axis_lateral_m * 1e3),
        format_short(c.normal_load_n),
        format_short(c.friction_coefficient),
        s.grid,
        s.grid
    );
    for parameter in Parameter::ALL {
        let set: Vec<_> = curves.of(parameter).collect();
        let Some(first) = set.first() else { continue };
        let _ = writeln!(
            out,
            "\n{} (linear saturation at {}, span {})",
            label(parameter),
            format_short(first.saturation_value),
            format_short(curves.span)
        );
        let mut laws = vec![String::new()];
        let mut heads = vec!["value".to_string()];
        for curve in &set {
            laws.extend([head(curve.law).to_string(), String::new(), String::new()]);
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
    let s = &curves.setup;
    let mut head = ctx.json_head("creep-curves");
    head.insert("source".into(), s.source.as_str().into());
    head.insert("screw".into(), s.screw_json());
    let mut contact = json_object(CONTACT_DATA, &s.contact);
    contact.insert("grid".into(), (s.grid as u64).into());
    head.insert("contact".into(), Value::Object(contact));
    head.insert("span".into(), curves.span.into());
    let list: Vec<Value> = curves
        .curves
        .iter()
        .map(|curve| {
            let mut m = Map::new();
            m.insert("parameter".into(), curve.parameter.name().into());
            m.insert("law".into(), curve.law.name().into());
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
