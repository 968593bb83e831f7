//! `ballscrew torque`: one operating point, the torque by every route and the catalog value.

use super::{Context, Format, describe_point};
use crate::error::CliError;
use crate::input::PointInput;
use crate::quantities::{POINT, Summary};
use crate::report::{cells, csv, json_object, json_text, keys, vertical_table};
use ballscrew_core::input::rad_s_to_rpm;
use ballscrew_core::{Evaluation, OperatingPoint, SolverState};
use clap::Args;
use serde_json::Value;

/// Flags of one operating point (`ballscrew torque`, `ballscrew inspect`).
#[derive(Debug, Clone, Args)]
pub struct PointArgs {
    /// Preload, N [default: the spec's]
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub preload_n: Option<f64>,
    /// Screw speed, rpm; negative for reverse rotation [default: the spec's]
    #[arg(long, value_name = "RPM", allow_negative_numbers = true)]
    pub speed_rpm: Option<f64>,
    /// External axial load on the nut, N [default: the spec's]
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub axial_load_n: Option<f64>,
}

/// Validates the point and evaluates it (cold start).
pub fn evaluate(ctx: &Context, args: &PointArgs) -> Result<Evaluation, CliError> {
    let input = PointInput {
        speed_rpm: args.speed_rpm,
        preload_n: args.preload_n,
        axial_load_n: args.axial_load_n,
        preload_flag: "--preload-n",
    };
    let op = ctx.operating_point(&input)?;
    ctx.model.evaluate(&op, &mut SolverState::new()).map_err(|e| CliError::eval("evaluation", &e))
}

/// `speed 100 rpm, preload 2000 N, axial load 0 N`.
pub fn describe(op: &OperatingPoint) -> String {
    describe_point(Some(rad_s_to_rpm(op.speed_rad_s)), Some(op.preload_n), op.axial_load_n)
}

/// The torque summary as a table (label, value, unit).
pub fn summary_table(summary: &Summary) -> String {
    vertical_table(POINT, core::slice::from_ref(summary), &["value"]).render(0)
}

/// Runs the command and renders it.
pub fn run(ctx: &Context, args: &PointArgs) -> Result<String, CliError> {
    let summary = evaluate(ctx, args)?.summary;
    Ok(match ctx.format {
        Format::Table => format!("{}\n{}", ctx.title("torque", &describe(&summary.operating)), summary_table(&summary)),
        Format::Csv => csv(&keys(POINT), &[cells(POINT, &summary)]),
        Format::Json => {
            let mut head = ctx.json_head("torque");
            head.extend(json_object(POINT, &summary));
            json_text(&Value::Object(head))
        }
    })
}
