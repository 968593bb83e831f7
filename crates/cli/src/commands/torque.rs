//! `ballscrew torque`: one operating point, the torque by every route, its drag and load parts,
//! the catalog value, and the forward and backdrive efficiency under an axial load; the oil
//! temperature at the contacts (`--oil-temperature-c`) in the table's title and the JSON.

use super::{Context, Format, efficiency_at, summary_table};
use crate::args::PointArgs;
use crate::error::CliError;
use crate::report::{cells, csv, json_object, json_text, keys, vertical_table};
use ballscrew_batch::quantities::{EFFICIENCY, POINT};
use serde_json::Value;

/// Runs the command and renders it.
pub fn run(ctx: &Context, args: &PointArgs) -> Result<String, CliError> {
    let summary = args.evaluate(&ctx.spec, &ctx.model)?.summary;
    ctx.warn_inertia([summary.operating]);
    let efficiency = efficiency_at(&ctx.model, &summary.operating, "efficiency")?;
    Ok(match ctx.format {
        Format::Table => format!(
            "{}\n{}\nefficiency under the axial load (n/a without one)\n{}",
            ctx.title("torque", &ctx.describe_point(&summary.operating)),
            summary_table(&summary),
            vertical_table(EFFICIENCY, core::slice::from_ref(&efficiency), &["value"]).render(0)
        ),
        Format::Csv => csv(
            &[keys(POINT), keys(EFFICIENCY)].concat(),
            &[[cells(POINT, &summary), cells(EFFICIENCY, &efficiency)].concat()],
        ),
        Format::Json => {
            let mut head = ctx.json_point_head("torque");
            head.extend(json_object(POINT, &summary));
            head.extend(json_object(EFFICIENCY, &efficiency));
            json_text(&Value::Object(head))
        }
    })
}
