//! `ballscrew`: the friction (drag) torque of a preloaded ball screw from the command line.
//!
//! ```text
//! ballscrew sweep   [--preload A..B] [--step N] [--speed-rpm X] [--axial-load-n X]
//! ballscrew torque  [--preload-n X] [--speed-rpm X] [--axial-load-n X]
//! ballscrew inspect [--preload-n X] [--speed-rpm X] [--axial-load-n X]
//! global: [--spec FILE] [--format table|csv|json] [--out FILE]
//! ```
//!
//! Exit codes: 0 success, 2 usage or input error, 1 evaluation or output error. Errors go to
//! stderr as `error: ...`.

mod commands;
mod error;
mod input;
mod output;
mod quantities;
mod report;
mod table;

use clap::{Parser, Subcommand};
use commands::inspect;
use commands::sweep::{self, SweepArgs};
use commands::torque::{self, PointArgs};
use commands::{Context, Format};
use error::CliError;
use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

/// Friction (drag) torque of a preloaded ball screw by rolling-contact creep analysis
/// (Xu et al. 2015, with the corrections of the project's model notes).
#[derive(Debug, Parser)]
#[command(name = "ballscrew", version)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// Screw spec (TOML, units in the key names) [default: built-in DKFZD4012 of Table 1]
    #[arg(long, global = true, value_name = "FILE")]
    spec: Option<PathBuf>,
    /// Output format.
    #[arg(long, global = true, value_enum, default_value_t = Format::Table)]
    format: Format,
    /// Write the output to FILE (atomically: complete or not at all) instead of stdout.
    #[arg(long, global = true, value_name = "FILE")]
    out: Option<PathBuf>,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Torque over a range of preloads (catalog band alongside).
    Sweep(SweepArgs),
    /// Torque at one operating point by every route, and the catalog value.
    Torque(PointArgs),
    /// One operating point in full: every nut, circle and contact.
    Inspect(PointArgs),
}

fn run(cli: &Cli) -> Result<(), CliError> {
    let ctx = Context::load(cli.spec.as_deref(), cli.format)?;
    let text = match &cli.command {
        Command::Sweep(args) => sweep::run(&ctx, args)?,
        Command::Torque(args) => torque::run(&ctx, args)?,
        Command::Inspect(args) => inspect::run(&ctx, args)?,
    };
    output::emit(&text, cli.out.as_deref())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "error: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}
