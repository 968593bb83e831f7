//! `ballscrew inspect`: one operating point in full, per nut, circle and contact; with `--plot`,
//! each circle's contact loads and torque shares as bars and the chain force along the ball
//! train ([`crate::plots::inspect`]).

use super::{Context, Format, summary_table};
use crate::args::PointArgs;
use crate::error::CliError;
use crate::output::{Named, Output};
use crate::plots;
use crate::report::{cells, csv, json_object, json_text, keys, vertical_table};
use crate::table::format_short;
use ballscrew_batch::quantities::{BALL, BALL_ID, CONTACT, CONTACT_ID, POINT};
use ballscrew_core::input::rad_s_to_rpm;
use ballscrew_core::{BallReport, Evaluation};
use clap::Args;
use core::fmt::Write as _;
use serde_json::{Map, Value};
use std::path::PathBuf;

/// Flags of `ballscrew inspect`.
#[derive(Debug, Clone, Args)]
pub struct InspectArgs {
    #[command(flatten)]
    pub output: super::FormatArg,
    #[command(flatten)]
    pub point: PointArgs,
    /// Also draw each circle's contact loads (N) and torque shares (N m) as bars, and the chain
    /// force between the balls along each circle (N), to FILE as SVG (atomically)
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
}

/// The file the flags name (`--plot`).
pub fn outputs(args: &InspectArgs) -> Named<'_> {
    Named { files: args.plot.iter().map(|p| ("--plot", p.as_path())).collect(), dirs: Vec::new() }
}

/// Runs the command and renders it (and its figure with `--plot`).
pub fn run(ctx: &Context, args: &InspectArgs) -> Result<Output, CliError> {
    let ev = args.point.evaluate(&ctx.spec, &ctx.model)?;
    ctx.warn_inertia([ev.summary.operating]);
    let text = match ctx.format {
        Format::Table => table(ctx, &ev),
        Format::Csv => csv_text(&ev),
        Format::Json => json(ctx, &ev),
    };
    let plot = match &args.plot {
        Some(path) => {
            let title = ctx.title("inspect", &ctx.describe_point(&ev.summary.operating));
            Some((path.clone(), plots::inspect::svg(title.trim_end(), &ev)?))
        }
        None => None,
    };
    Ok(Output::with_plot(Some(text), plot))
}

/// The balls of the evaluation (one per nut and circle), in order.
fn balls(ev: &Evaluation) -> impl Iterator<Item = &BallReport> {
    ev.balls.iter().take(ev.nuts).flat_map(move |nut| nut.iter().take(ev.circles))
}

fn table(ctx: &Context, ev: &Evaluation) -> String {
    let mut out = ctx.title("inspect", &ctx.describe_point(&ev.summary.operating));
    let loads: Vec<String> = ev
        .summary
        .nut_loads_n
        .iter()
        .take(ev.nuts)
        .enumerate()
        .map(|(i, l)| format!("{} {} N", ev.preload.group_label(i), format_short(*l)))
        .collect();
    let _ = writeln!(out, "preload arrangement: {}; axial loads: {}", ev.preload.name(), loads.join(", "));
    for b in balls(ev) {
        let group = ev.preload.group_label(b.nut);
        if b.ramp_balls == 0 {
            let _ = writeln!(out, "\n{group}, circle {} (every ball of the circle alike)", b.circle + 1);
        } else {
            let _ = writeln!(
                out,
                "\n{group}, circle {} (its {} full-load balls alike; its {} load ramp balls are in the totals only)",
                b.circle + 1,
                b.balls,
                b.ramp_balls
            );
        }
        out.push_str(&vertical_table(BALL, core::slice::from_ref(b), &["value"]).render(2));
        out.push('\n');
        let heads: Vec<&str> = b.contacts.iter().map(|c| c.kind.name()).collect();
        out.push_str(&vertical_table(CONTACT, &b.contacts, &heads).render(2));
    }
    out.push_str("\ntorque summary\n");
    out.push_str(&summary_table(&ev.summary));
    out
}

/// One row per contact: ball columns, then contact columns.
fn csv_text(ev: &Evaluation) -> String {
    let header: Vec<&str> = [keys(BALL_ID), keys(BALL), keys(CONTACT_ID), keys(CONTACT)].concat();
    let mut rows = Vec::new();
    for b in balls(ev) {
        let ball = [cells(BALL_ID, b), cells(BALL, b)].concat();
        for c in &b.contacts {
            rows.push([ball.clone(), cells(CONTACT_ID, c), cells(CONTACT, c)].concat());
        }
    }
    csv(&header, &rows)
}

/// Nested: nuts, their circles, each circle's three contacts; then the torque summary.
fn json(ctx: &Context, ev: &Evaluation) -> String {
    let mut head = ctx.json_point_head("inspect");
    let op = ev.summary.operating;
    let operating: Map<String, Value> =
        [("speed_rpm", rad_s_to_rpm(op.speed_rad_s)), ("preload_n", op.preload_n), ("axial_load_n", op.axial_load_n)]
            .into_iter()
            .map(|(k, v)| (k.to_string(), Value::from(v)))
            .collect();
    head.insert("operating".into(), Value::Object(operating));
    head.insert("preload_arrangement".into(), ev.preload.name().into());
    let nuts: Vec<Value> = (0..ev.nuts).map(|n| json_nut(ev, n)).collect();
    head.insert("nuts".into(), Value::Array(nuts));
    head.insert("torque".into(), Value::Object(json_object(POINT, &ev.summary)));
    json_text(&Value::Object(head))
}

fn json_nut(ev: &Evaluation, nut: usize) -> Value {
    let circles: Vec<Value> = ev.balls[nut].iter().take(ev.circles).map(json_circle).collect();
    let mut m = Map::new();
    m.insert("nut".into(), (nut as u64 + 1).into());
    m.insert("group".into(), ev.preload.group_label(nut).into());
    m.insert("axial_load_n".into(), ev.summary.nut_loads_n[nut].into());
    m.insert("circles".into(), Value::Array(circles));
    Value::Object(m)
}

fn json_circle(b: &BallReport) -> Value {
    let mut m = json_object(BALL_ID, b);
    m.extend(json_object(BALL, b));
    let contacts: Vec<Value> = b
        .contacts
        .iter()
        .map(|c| {
            let mut o = json_object(CONTACT_ID, c);
            o.extend(json_object(CONTACT, c));
            Value::Object(o)
        })
        .collect();
    m.insert("contacts".into(), Value::Array(contacts));
    Value::Object(m)
}
