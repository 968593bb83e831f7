//! `ballscrew sensitivity`: what drives the band of the drag torque at one operating point. Each
//! uncertain input of the spec's `[uncertainty]` read by its model: the drag torque with it at
//! each end of its spread (the others nominal), the swing between them, and its first-order and
//! total Sobol indices ([`ballscrew_batch::uncertainty::sensitivity`]); the band itself from the
//! same sample (the band `torque --band` gives with the same `--samples` and `--seed`). With
//! `--plot`, the swings as a tornado chart ([`crate::plots::sensitivity`]).

use super::{Context, Format, FormatArg};
use crate::args::PointArgs;
use crate::band::{self, SampleArgs};
use crate::error::CliError;
use crate::output::{Named, Output};
use crate::plots;
use crate::report::{cells, csv, horizontal_table_led, json_object, json_text, keys};
use crate::spec_and_flags;
use crate::table::format_short;
use ballscrew_batch::quantities::{BAND, SENSITIVITY};
use ballscrew_batch::sweep::SweepPoint;
use ballscrew_batch::uncertainty::{BandSettings, Sensitivity, sensitivity};
use clap::Args;
use serde_json::Value;
use std::path::PathBuf;

/// Flags of `ballscrew sensitivity`.
#[derive(Debug, Clone, Args)]
pub struct SensitivityArgs {
    #[command(flatten)]
    pub output: FormatArg,
    #[command(flatten)]
    pub point: PointArgs,
    #[command(flatten)]
    pub sample: SampleArgs,
    /// Also draw each input's swing as a tornado chart to FILE as SVG (atomically)
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
}

/// The file the flags name (`--plot`).
pub fn outputs(args: &SensitivityArgs) -> Named<'_> {
    Named { files: args.plot.iter().map(|p| ("--plot", p.as_path())).collect(), dirs: Vec::new() }
}

/// Runs the command and renders it (and its figure with `--plot`).
pub fn run(ctx: &Context, args: &SensitivityArgs) -> Result<Output, CliError> {
    let settings = args.sample.settings()?;
    let op = spec_and_flags::operating_point(&ctx.spec, &args.point.input())?;
    ctx.warn_inertia([op]);
    let point = SweepPoint { op, model: &ctx.model };
    let s = sensitivity(&band::batch(&settings), &point, &settings).map_err(|e| band::error("sensitivity", &e))?;
    let title = ctx.title("sensitivity", &ctx.describe_point(&op));
    let text = match ctx.format {
        Format::Table => table(&title, &s, &settings),
        Format::Csv => csv(&keys(SENSITIVITY), &s.inputs.iter().map(|i| cells(SENSITIVITY, i)).collect::<Vec<_>>()),
        Format::Json => {
            let mut head = ctx.json_point_head("sensitivity");
            head.insert("drag_torque_nm".into(), s.nominal_nm.into());
            head.extend(json_object(BAND, &s.band));
            head.insert("band".into(), band::json(&settings));
            head.insert("variance_nm2".into(), s.variance_nm2.into());
            let rows = s.inputs.iter().map(|i| Value::Object(json_object(SENSITIVITY, i))).collect();
            head.insert("inputs".into(), Value::Array(rows));
            json_text(&Value::Object(head))
        }
    };
    let plot = match &args.plot {
        Some(path) => {
            let lines = [title.trim_end().to_string(), summary_line(&s, &settings)];
            Some((path.clone(), plots::sensitivity::svg(&lines, &s)?))
        }
        None => None,
    };
    Ok(Output::with_plot(Some(text), plot))
}

/// `drag torque 0.1811 N m; band (5-95 %, 128 samples, seed 0): 0.1209 to 0.2573 N m, median
/// 0.1745 N m`.
fn summary_line(s: &Sensitivity, settings: &BandSettings) -> String {
    format!(
        "drag torque {} N m; band ({}): {} to {} N m, median {} N m",
        format_short(s.nominal_nm),
        band::describe(settings),
        format_short(s.band.low_nm),
        format_short(s.band.high_nm),
        format_short(s.band.median_nm)
    )
}

fn table(title: &str, s: &Sensitivity, settings: &BandSettings) -> String {
    let mut out = format!("{title}\n{}\n\n", summary_line(s, settings));
    if s.inputs.is_empty() {
        out.push_str(
            "every input is pinned (the spec's [uncertainty] has no half-width above 0 that its model reads)\n",
        );
        return out;
    }
    out.push_str("each input at the ends of its spread, the others nominal; Sobol indices from the sample\n");
    let (lead, rest) = SENSITIVITY.split_first().expect("the sensitivity table has columns");
    out.push_str(&horizontal_table_led(lead, rest, &s.inputs, |i| i).render(0));
    let sum: f64 = s.inputs.iter().map(|i| i.first_order).sum();
    out.push_str(&format!(
        "\nfirst-order indices sum to {}: {}\n",
        format_short((sum * 1000.0).round() / 1000.0),
        if sum >= 0.9 {
            "the inputs act nearly one by one (little interaction)"
        } else {
            "the rest of the variance comes from inputs acting together"
        }
    ));
    out
}
