//! `ballscrew torque`: one operating point, the torque by every route, its drag and load parts,
//! the catalog value, and the forward and backdrive efficiency under an axial load; the oil
//! temperature at the contacts (`--oil-temperature-c`) in the table's title and the JSON; with
//! `--band`, the band of the drag torque that the spread of the spec's uncertain inputs gives.

use super::{Context, Format, PointCmdArgs, efficiency_at, summary_table};
use crate::band;
use crate::error::CliError;
use crate::report::{cells, csv, json_object, json_text, keys, vertical_table};
use ballscrew_batch::quantities::{BAND, EFFICIENCY, POINT};
use ballscrew_batch::sweep::SweepPoint;
use serde_json::Value;

/// Runs the command and renders it.
pub fn run(ctx: &Context, args: &PointCmdArgs) -> Result<String, CliError> {
    let settings = args.band.settings()?;
    let summary = args.point.evaluate(&ctx.spec, &ctx.model)?.summary;
    ctx.warn_inertia([summary.operating]);
    let efficiency = efficiency_at(&ctx.model, &summary, "efficiency")?;
    let bands = match &settings {
        Some(s) => {
            let point = [SweepPoint { op: summary.operating, model: &ctx.model }];
            ballscrew_batch::uncertainty::band(&band::batch(s), &point, s).map_err(|e| band::error("band", &e))?
        }
        None => Vec::new(),
    };
    Ok(match ctx.format {
        Format::Table => {
            let mut text = format!(
                "{}\n{}\nefficiency under the axial load (n/a without one)\n{}",
                ctx.title("torque", &ctx.describe_point(&summary.operating)),
                summary_table(&summary),
                vertical_table(EFFICIENCY, core::slice::from_ref(&efficiency), &["value"]).render(0)
            );
            if let Some(s) = &settings {
                text.push_str(&format!(
                    "\nband of the drag torque ({}; the spec's [uncertainty])\n{}",
                    band::describe(s),
                    vertical_table(BAND, &bands, &["value"]).render(0)
                ));
            }
            text
        }
        Format::Csv => {
            let (mut head, mut row) = (
                [keys(POINT), keys(EFFICIENCY)].concat(),
                [cells(POINT, &summary), cells(EFFICIENCY, &efficiency)].concat(),
            );
            if let Some(b) = bands.first() {
                head.extend(keys(BAND));
                row.extend(cells(BAND, b));
            }
            csv(&head, &[row])
        }
        Format::Json => {
            let mut head = ctx.json_point_head("torque");
            head.extend(json_object(POINT, &summary));
            head.extend(json_object(EFFICIENCY, &efficiency));
            if let (Some(s), Some(b)) = (&settings, bands.first()) {
                head.extend(json_object(BAND, b));
                head.insert("band".into(), band::json(s));
            }
            json_text(&Value::Object(head))
        }
    })
}
