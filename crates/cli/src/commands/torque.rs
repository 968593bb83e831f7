//! `ballscrew torque`: one operating point, the torque by every route and the catalog value.

use super::{Context, Format, summary_table};
use crate::args::{PointArgs, describe};
use crate::error::CliError;
use crate::quantities::POINT;
use crate::report::{cells, csv, json_object, json_text, keys};
use serde_json::Value;

/// Runs the command and renders it.
pub fn run(ctx: &Context, args: &PointArgs) -> Result<String, CliError> {
    let summary = args.evaluate(&ctx.spec, &ctx.model)?.summary;
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
