//! `ballscrew diagnose`: where the model is wrong on measured data, the missing physical term,
//! the extended model and its gain on held-out data (see `ballscrew_diagnose`).
//!
//! The format is one of [`DiagnoseFormat`] (checked by the flag's parser) and the files are
//! checked before the diagnosis
//! ([`outputs`]); everything is computed before anything is written, then the files are
//! written all or none ([`Output::write`]).

use super::{Context, Format};
use crate::data_file::{self, DataArgs};
use crate::error::CliError;
use crate::output::{Named, Output, SideDir, SideFile};
use crate::plots;
use crate::progress::Bar;
use ballscrew_config::spec_to_toml;
use ballscrew_diagnose::data::Use;
use ballscrew_diagnose::{self as diagnose, DiagnoseError, Report};
use clap::Args;
use core::sync::atomic::AtomicBool;
use std::path::PathBuf;

/// What `diagnose` writes: a report for people or its JSON (the diagnosis is no table of rows).
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum DiagnoseFormat {
    /// Aligned text for people.
    Table,
    /// JSON, full precision.
    Json,
}

impl DiagnoseFormat {
    /// The report format it is.
    pub fn report(self) -> Format {
        match self {
            DiagnoseFormat::Table => Format::Table,
            DiagnoseFormat::Json => Format::Json,
        }
    }
}

/// Flags of `diagnose`.
#[derive(Debug, Clone, Args)]
pub struct DiagnoseArgs {
    /// Output format (a figure set with --plots, the JSON report with --report)
    #[arg(long, value_enum, default_value_t = DiagnoseFormat::Table)]
    pub format: DiagnoseFormat,
    /// The measured data.
    #[command(flatten)]
    pub data: DataArgs,
    /// Write the report as JSON to FILE.
    #[arg(long, value_name = "FILE")]
    pub report: Option<PathBuf>,
    /// Write SVG figures into DIR (created if missing): measured vs. models, the residual
    /// against each column, measured and model torque against time_h (when the data has it),
    /// the residual's periodogram along the position with the detected harmonic ringed.
    #[arg(long, value_name = "DIR")]
    pub plots: Option<PathBuf>,
    /// Write the calibrated, extended spec (TOML) to FILE.
    #[arg(long, value_name = "FILE")]
    pub out_spec: Option<PathBuf>,
}

/// Runs the diagnosis of the data file.
pub fn report(ctx: &Context, args: &DiagnoseArgs) -> Result<Report, CliError> {
    let (_, d) = data_file::load(&args.data, Use::Diagnosis)?;
    let bar = Bar::new("diagnose", 0);
    // Not cancelled here: a signal ends the whole process (`output::abandon_and_exit`).
    let never = AtomicBool::new(false);
    let report = diagnose::diagnose_with_progress(&ctx.spec, &d, &never, &mut |p| bar.set(p.done, p.total));
    drop(bar);
    report.map_err(|e| match e {
        DiagnoseError::Data(e) => CliError::Input(format!("{}: {e}", args.data.data.display())),
        DiagnoseError::Model(m) => CliError::Eval(format!("{}: {m}", args.data.data.display())),
        e @ DiagnoseError::Cancelled => CliError::Eval(e.to_string()),
    })
}

/// The files and the directory the flags name.
pub fn outputs(args: &DiagnoseArgs) -> Named<'_> {
    let files = [("--report", &args.report), ("--out-spec", &args.out_spec)];
    Named {
        files: files.into_iter().filter_map(|(flag, p)| Some((flag, p.as_deref()?))).collect(),
        dirs: args.plots.iter().map(|d| ("--plots", d.as_path())).collect(),
    }
}

/// Runs the command: the text for stdout (`--out`) and the side files, all computed before
/// anything is written.
pub fn run(ctx: &Context, args: &DiagnoseArgs) -> Result<Output, CliError> {
    let r = report(ctx, args)?;
    let json = serde_json::to_string_pretty(&r.to_json()).map_err(|e| CliError::Output(e.to_string()))? + "\n";
    let text = if ctx.format == Format::Json { json.clone() } else { r.to_text() };
    let mut out = Output { text: Some(text), ..Output::default() };
    if let Some(dir) = &args.plots {
        for (name, svg) in plots::diagnose::figures(&r, ctx.spec.geometry.lead_m * 1e3)? {
            out.files.push(SideFile { flag: "--plots", path: dir.join(name), text: svg });
        }
        out.dirs.push(SideDir { flag: "--plots", path: dir.clone() });
    }
    if let Some(path) = &args.report {
        out.files.push(SideFile { flag: "--report", path: path.clone(), text: json });
    }
    if let Some(path) = &args.out_spec {
        let text = format!(
            "# Calibrated and extended by `ballscrew diagnose --data {}` from {}\n# {}\n# [uncertainty]: each \
             calibrated input's half-width is sqrt(3) times its standard error from the fit (a uniform spread with the \
             fit's variance); the others are the input spec's\n{}\n",
            args.data.data.display(),
            ctx.origin,
            r.verdict(),
            spec_to_toml(&r.extended_spec)
        );
        out.files.push(SideFile { flag: "--out-spec", path: path.clone(), text });
    }
    Ok(out)
}
