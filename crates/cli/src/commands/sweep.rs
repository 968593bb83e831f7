//! `ballscrew sweep`: the torque over a range of preloads, warm-started point to point.

use super::{Context, Format};
use crate::args::describe_point;
use crate::error::CliError;
use crate::input::{PointInput, preload_points};
use crate::quantities::{SWEEP, Summary};
use crate::report::{cells, csv, horizontal_table, json_object, json_text, keys};
use crate::table::format_short;
use ballscrew_config::{DEFAULT_SWEEP_FROM_N, DEFAULT_SWEEP_STEP_N, DEFAULT_SWEEP_TO_N};
use ballscrew_core::SolverState;
use ballscrew_core::input::rad_s_to_rpm;
use ballscrew_core::screw::catalog::BAND_RELATIVE;
use clap::Args;
use serde_json::Value;

/// Flags of `ballscrew sweep`.
#[derive(Debug, Clone, Args)]
pub struct SweepArgs {
    /// Preload range in N, both ends included: `A..B`, or a single value.
    #[arg(
        long,
        visible_alias = "preload-n",
        value_name = "A..B",
        default_value_t = format!("{DEFAULT_SWEEP_FROM_N}..{DEFAULT_SWEEP_TO_N}"),
        allow_hyphen_values = true
    )]
    pub preload: String,
    /// Preload step, N.
    #[arg(long, visible_alias = "step-n", value_name = "N", default_value_t = DEFAULT_SWEEP_STEP_N, allow_negative_numbers = true)]
    pub step: f64,
    /// Screw speed, rpm; negative for reverse rotation [default: the spec's]
    #[arg(long, value_name = "RPM", allow_negative_numbers = true)]
    pub speed_rpm: Option<f64>,
    /// External axial load on the nut, N [default: the spec's]
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub axial_load_n: Option<f64>,
}

/// Runs the sweep and renders it.
pub fn run(ctx: &Context, args: &SweepArgs) -> Result<String, CliError> {
    let rows = evaluate(ctx, args)?;
    Ok(match ctx.format {
        Format::Table => table(ctx, &rows),
        Format::Csv => csv(&keys(SWEEP), &rows.iter().map(|r| cells(SWEEP, r)).collect::<Vec<_>>()),
        Format::Json => json(ctx, &rows),
    })
}

/// Validates every point first, then evaluates them in order with one warm-started state.
fn evaluate(ctx: &Context, args: &SweepArgs) -> Result<Vec<Summary>, CliError> {
    let points = preload_points(&args.preload, args.step)?;
    let ops = points
        .iter()
        .map(|&p| {
            let input = PointInput {
                speed_rpm: args.speed_rpm,
                preload_n: Some(p),
                axial_load_n: args.axial_load_n,
                preload_flag: "--preload",
            };
            ctx.operating_point(&input)
        })
        .collect::<Result<Vec<_>, _>>()?;
    let mut state = SolverState::new();
    ops.iter()
        .map(|op| {
            let context = format!("at preload {} N", format_short(op.preload_n));
            ctx.model.summary(op, &mut state).map_err(|e| CliError::eval(&context, &e))
        })
        .collect()
}

fn table(ctx: &Context, rows: &[Summary]) -> String {
    let Some(first) = rows.first() else { return String::new() };
    let op = first.operating;
    let fixed = describe_point(Some(rad_s_to_rpm(op.speed_rad_s)), None, op.axial_load_n);
    let mut out = ctx.title("sweep", &fixed);
    out.push('\n');
    out.push_str(&horizontal_table(SWEEP, rows).render(0));
    out.push('\n');
    out.push_str(&band_note(rows));
    out.push('\n');
    out
}

fn json(ctx: &Context, rows: &[Summary]) -> String {
    let mut head = ctx.json_head("sweep");
    if let Some(first) = rows.first() {
        head.insert("speed_rpm".into(), rad_s_to_rpm(first.operating.speed_rad_s).into());
        head.insert("axial_load_n".into(), first.operating.axial_load_n.into());
    }
    head.insert("catalog_band_relative".into(), BAND_RELATIVE.into());
    let list: Vec<Value> = rows.iter().map(|r| Value::Object(json_object(SWEEP, r))).collect();
    head.insert("rows".into(), Value::Array(list));
    json_text(&Value::Object(head))
}

/// One line: where the model stands against the catalog band, by magnitude.
fn band_note(rows: &[Summary]) -> String {
    let ratios: Vec<f64> = rows.iter().map(|r| r.catalog_ratio().abs()).filter(|r| r.is_finite()).collect();
    let band = format!("catalog x [{}, {}]", format_short(1.0 - BAND_RELATIVE), format_short(1.0 + BAND_RELATIVE));
    if ratios.is_empty() {
        return format!("Catalog band ({band}): no comparison (zero catalog torque).");
    }
    let below = ratios.iter().filter(|&&r| r < 1.0 - BAND_RELATIVE).count();
    let above = ratios.iter().filter(|&&r| r > 1.0 + BAND_RELATIVE).count();
    let within = ratios.len() - below - above;
    let lo = ratios.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = ratios.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    format!(
        "Against the catalog band ({band}): model below at {below}, within at {within}, above at {above} of {} preloads; \
         |model/catalog| {:.3} to {:.3}.",
        ratios.len(),
        lo,
        hi
    )
}
