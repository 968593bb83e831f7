//! `ballscrew`: the friction (drag) torque of a preloaded ball screw from the command line.
//!
//! ```text
//! ballscrew sweep   [--preload-n A..B] [--preload-step-n N] [--speed-rpm X] [--axial-load-n X]
//!                   [--speed-rpm A..B --speed-step-rpm X] [--axial-load-n A..B
//!                   --axial-load-step-n X] [--oil-temperature-c A..B
//!                   --oil-temperature-step-c X] (one range at a time) [--plot FILE.svg
//!                   [--plot-paper-eq27]]
//! ballscrew torque  [--preload-n X] [--speed-rpm X] [--axial-load-n X] [--oil-temperature-c X]
//!                   [--band [LOW,HIGH] [--samples N] [--seed N]]
//! ballscrew sensitivity [point flags as torque] [--samples N] [--seed N] [--plot FILE.svg]
//! ballscrew inspect [--preload-n X] [--speed-rpm X] [--axial-load-n X] [--oil-temperature-c X]
//!                   [--plot FILE.svg]
//! ballscrew contact [--xi X] [--eta X] [--phi-per-mm X] [--heathcote-per-mm2 X]
//!                   [--semi-axis-rolling-mm A] [--semi-axis-lateral-mm B] [--normal-load-n Q]
//!                   [--friction MU] [point flags] [--nut N] [--circle C] [--contact nut|screw]
//!                   [--grid N] [--bound parabolic|elliptical] [--plot FILE.svg]
//! ballscrew creep-curves [contact flags as above, no creepages] [--bound B] [--points N]
//!                   [--span X] [--plot FILE.svg]
//! ballscrew predict  --data OPS.csv [--column NAME=SOURCE]...
//! ballscrew diagnose --data MEASURED.csv [--column NAME=SOURCE]... [--report FILE.json]
//!                   [--plots DIR] [--out-spec FILE.toml]
//! ballscrew map     [--preload-n A..B] [--preload-points N | --preload-step-n N]
//!                   [--speed-rpm C..D] [--speed-points N | --speed-step-rpm X] [--axial-load-n X]
//!                   [--plot FILE.svg]
//! ballscrew fmu     --out FILE.fmu [--library LIB.so] [--model-name NAME]
//! ballscrew reversal [--preload-n X] [--axial-load-n X] [--speed-rpm X] [--amplitude-rad A]
//!                   [--step-rad H] [--rows N] [--precision f64|f32] [--plot FILE.svg]
//! ballscrew completions bash|zsh|fish|elvish|powershell
//! ballscrew man     [--format roff|markdown]
//! ballscrew init    --pitch-diameter-mm X --lead-mm X --ball-diameter-mm X [--nuts N]
//!                   [--preload-arrangement A] [--preload-n X] [--circles-per-nut N]
//!                   [--balls-per-circle N] [--contact-angle-deg X] [--conformity-screw F]
//!                   [--conformity-nut F] [--return internal|external] [--force]
//! global: [--spec FILE] [--out FILE|-] (completions, man and init read no spec)
//! --format: table|csv|json (sweep, torque, sensitivity, inspect, contact, creep-curves, reversal);
//!           table|c|rust|csv (map); table|json (diagnose); csv|json (predict); roff|markdown (man)
//! ```
//!
//! Every flag is checked before anything is evaluated: the format (each subcommand offers only
//! the formats it writes), then every output path (a `--plot` ends in `.svg`:
//! [`output::check_svg`]; [`output::check`]), then the command's own flags. Exit codes: 0 success, 2
//! usage or input error, 1 evaluation or output error, 130 interrupted (SIGINT, SIGTERM,
//! SIGHUP; the run's temporary files are removed first). Errors go to stderr as `error: ...`,
//! control characters escaped, each flag named as typed (an alias where one was: [`typed`]).

mod args;
mod band;
mod commands;
mod curves;
mod data_file;
mod error;
mod map_source;
mod output;
mod plots;
mod progress;
mod quantities;
mod reference;
mod report;
mod reversal_run;
mod spec_and_flags;
mod table;
mod typed;

use clap::{CommandFactory as _, Parser, Subcommand};
use commands::completions::{self, CompletionsArgs};
use commands::contact::{self, ContactCmdArgs};
use commands::creep_curves::{self, CurveArgs};
use commands::diagnose::{self, DiagnoseArgs};
use commands::fmu::{self, FmuArgs};
use commands::init::{self, InitArgs};
use commands::inspect::{self, InspectArgs};
use commands::man::{self, ManArgs};
use commands::map::{self, MapArgs};
use commands::predict::{self, PredictArgs};
use commands::reversal::{self, ReversalArgs};
use commands::sensitivity::{self, SensitivityArgs};
use commands::sweep::{self, SweepArgs};
use commands::torque;
use commands::{Context, Format, PointCmdArgs};
use error::CliError;
extern crate alloc;

use alloc::sync::Arc;
use core::sync::atomic::AtomicBool;
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
    /// Write the output to FILE instead of stdout (`-`: stdout). A regular file is replaced
    /// atomically (complete or not at all); a device or FIFO is written directly.
    #[arg(long, global = true, value_name = "FILE")]
    out: Option<PathBuf>,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Torque over a range of preloads, speeds, axial loads or oil temperatures (drag and load
    /// torque, the drag against the catalog band, efficiency under an axial load).
    ///
    /// The preload by default; --speed-rpm A..B sweeps the speed, --axial-load-n A..B the axial
    /// load, --oil-temperature-c A..B the oil temperature at the contacts (lubrication = "ehl"
    /// only). One range at a time; the first column names the swept quantity. --plot FILE.svg
    /// draws the torque against it with the catalog band.
    Sweep(SweepArgs),
    /// Torque at one operating point by every route, its drag and load parts, the catalog value,
    /// and the forward and backdrive efficiency under an axial load.
    Torque(PointCmdArgs),
    /// What drives the band of the drag torque at one operating point: each uncertain input of the
    /// spec's `[uncertainty]` at the ends of its spread (the swing), its first-order and total
    /// Sobol indices, and the band (--plot FILE.svg: a tornado chart of the swings).
    ///
    /// The sample is the band's of `torque --band` with the same --samples and --seed, which
    /// gives the same band; the indices take (inputs + 2) times --samples model evaluations.
    Sensitivity(SensitivityArgs),
    /// One operating point in full: every nut, circle and contact (--plot FILE.svg: each circle's
    /// contact loads and torque shares as bars, the chain force along the ball train).
    Inspect(InspectArgs),
    /// One contact by FASTSIM (Kalker's simplified theory) from its creepages or from the screw:
    /// forces, adhesion share, and the traction field with --plot (Fig. 10: arrows where the ball
    /// slips, the adhesion area shaded).
    ///
    /// The contact is one of the model at the operating point (--nut, --circle, --contact): its
    /// semi-axes, load and creepages. --semi-axis-rolling-mm, --semi-axis-lateral-mm,
    /// --normal-load-n and --friction override one value each; any creepage flag (--xi, --eta,
    /// --phi-per-mm, --heathcote-per-mm2) replaces all four creepages, the others 0. The model's
    /// law (Kalker's linear theory saturated by Eq. 24) is reported alongside.
    ///
    /// The friction coefficient mu bounding both laws is the model contact's own: under
    /// lubrication = "ehl" the mixed-film coefficient the model found for that contact, under
    /// "dry" friction.coefficient. A contact given by the flags alone (both semi-axes, the load
    /// and a creepage) has no film and takes friction.coefficient; --friction overrides either.
    /// The output states which was used.
    Contact(ContactCmdArgs),
    /// Friction of one contact against each creep parameter, the other three zero (Fig. 9).
    ///
    /// xi, eta, phi c and k_h b^2 (dimensionless, c = sqrt(a b)) each from 0 to --span times the
    /// value where Kalker's linear force reaches mu Q; FASTSIM (both bounds, or --bound) and the
    /// model's law (Eq. 24). The contact as for `ballscrew contact`. With --plot the data are
    /// written only with --out.
    CreepCurves(CurveArgs),
    /// The model's torque (with the spec's extension terms) for every row of a CSV file: the
    /// input plus a `model_torque_nm` column.
    Predict(PredictArgs),
    /// Diagnoses measured torques: calibrates f (and the creep reduction), reports what the
    /// model gets wrong, names the missing physical term by held-out error, fits the extended
    /// model and measures its gain on data the fit never saw.
    Diagnose(DiagnoseArgs),
    /// Torque map for firmware: the model tabulated over preload and speed, with its grid and
    /// its largest interpolation error (checked at the midpoint of every grid cell).
    ///
    /// --format c writes a C header (grid macros, values, an inline lookup), --format rust a
    /// Rust source file for `ballscrew_core::realtime::map::TorqueMap`, --format csv the values. Both
    /// directions of rotation are tabulated; standstill blends as the model does. --plot
    /// FILE.svg draws the map's torque against the speed, a curve per preload, the worst-error
    /// point ringed.
    Map(MapArgs),
    /// Torque through a reversal by the friction state (presliding) model, against the static
    /// model's fade through zero speed.
    ///
    /// The screw moves as theta = A sin(2 pi t / period) from the steady state at the peak speed
    /// (--speed-rpm) through the turning point to the next zero crossing of the angle. Reported:
    /// the samples (time, angle, speed, the state model's and the static model's torque), the
    /// stiffness, the steady torques, and the screw angle (and nut travel) from the turning point
    /// to the torque's zero crossing and to 90 % of its new steady value. --plot adds the
    /// hysteresis loop of a small oscillation about standstill. Specs with `[extensions]` are
    /// refused.
    Reversal(ReversalArgs),
    /// An FMI 2.0 co-simulation FMU of the spec for a simulator (Simulink, OpenModelica,
    /// Dymola, FMPy): inputs speed_rad_s and axial_load_n, parameter preload_n, outputs
    /// torque_nm, drag_torque_nm, load_torque_nm and dissipated_power_w (docs/fmu.md).
    ///
    /// --out FILE.fmu is needed. The FMU's shared library (libballscrew_fmu.so, built by
    /// `cargo build --release -p ballscrew-fmu`) is taken from --library, else from
    /// $BALLSCREW_FMU_LIBRARY, else from beside this executable. linux x86_64 only.
    Fmu(FmuArgs),
    /// The completion script of a shell for this command line, on stdout (or --out).
    ///
    /// Generated from the command's own definition: every subcommand, flag and value it
    /// completes is one `--help` shows. bash: source it, or save it as
    /// ~/.local/share/bash-completion/completions/ballscrew; zsh: save it as `_ballscrew` in a
    /// directory of $fpath; fish: save it as ~/.config/fish/completions/ballscrew.fish;
    /// elvish: `eval (slurp < FILE)` in rc.elv; PowerShell: dot-source it from $PROFILE.
    Completions(CompletionsArgs),
    /// The manual of this command line: the command and every subcommand with all its flags,
    /// as a roff man page (--format roff) or as the markdown reference (--format markdown,
    /// docs/cli-reference.md).
    ///
    /// Generated from the command's own definition, so it says what `--help` says. Install the
    /// man page with `ballscrew man --out ~/.local/share/man/man1/ballscrew.1` (then `man
    /// ballscrew`), or read it at once with `ballscrew man | man -l -`.
    Man(ManArgs),
    /// A commented spec file for a screw of one's own, from its dimensions: every value not
    /// given is written with `# assumed:` and why, every given one with `# given`.
    ///
    /// The pitch diameter, lead and ball diameter are needed; the nut (--nuts,
    /// --preload-arrangement, --preload-n, --circles-per-nut, --balls-per-circle), the grooves
    /// (--contact-angle-deg, --conformity-screw, --conformity-nut) and the return (--return)
    /// are assumed where not given. The spec is read back by the spec parser before it is
    /// written: a value the parser refuses is refused naming its flag, and nothing is written.
    /// --out FILE does not replace an existing file without --force.
    Init(InitArgs),
}

/// The side files and directories the subcommand's flags name.
fn named_outputs(command: &Command) -> output::Named<'_> {
    match command {
        Command::Sweep(args) => sweep::outputs(args),
        Command::Inspect(args) => inspect::outputs(args),
        Command::Map(args) => map::outputs(args),
        Command::Contact(args) => contact::outputs(args),
        Command::CreepCurves(args) => creep_curves::outputs(args),
        Command::Diagnose(args) => diagnose::outputs(args),
        Command::Reversal(args) => reversal::outputs(args),
        Command::Sensitivity(args) => sensitivity::outputs(args),
        _ => output::Named::default(),
    }
}

fn run(cli: &Cli) -> Result<(), CliError> {
    let mut named = named_outputs(&cli.command);
    for (flag, path) in &named.files {
        if *flag == "--plot" {
            output::check_svg(flag, path)?;
        }
    }
    let about = match &cli.command {
        Command::Map(args) => map::about_path(args.format, cli.out.as_deref()),
        _ => None,
    };
    if let Some(path) = &about {
        named.files.push((map::ABOUT_FLAG, path));
    }
    output::check(cli.out.as_deref(), &named)?;
    let spec = cli.spec.as_deref();
    // Each command's context, with the format of its own `--format`.
    let report = |format: Format| -> Result<Context, CliError> { Context::load(spec, format) };
    let rendered: output::Output = match &cli.command {
        Command::Sweep(args) => sweep::run(&report(args.output.format)?, args, cli.out.as_deref())?,
        // The commands of one operating point: the oil at `--oil-temperature-c` in the model.
        Command::Torque(args) => {
            let ctx = report(args.output.format)?.with_oil_temperature(args.point.oil_temperature_c)?;
            torque::run(&ctx, args)?.into()
        }
        Command::Sensitivity(args) => {
            sensitivity::run(&report(args.output.format)?.with_oil_temperature(args.point.oil_temperature_c)?, args)?
        }
        Command::Inspect(args) => {
            inspect::run(&report(args.output.format)?.with_oil_temperature(args.point.oil_temperature_c)?, args)?
        }
        Command::Contact(args) => {
            contact::run(&report(args.output.format)?.with_oil_temperature(args.target.point.oil_temperature_c)?, args)?
        }
        Command::CreepCurves(args) => {
            let ctx = report(args.output.format)?.with_oil_temperature(args.target.point.oil_temperature_c)?;
            creep_curves::run(&ctx, args, cli.out.is_some())?
        }
        // Predict has formats of its own (`PredictFormat`): the context's format is not read.
        Command::Predict(args) => predict::run(&report(Format::Csv)?, args)?.into(),
        Command::Diagnose(args) => diagnose::run(&report(args.format.report())?, args)?,
        Command::Map(args) => map::run(&Context::load(spec, args.format)?, args, cli.out.as_deref())?,
        Command::Reversal(args) => reversal::run(&report(args.output.format)?, args)?,
        Command::Fmu(args) => fmu::run(spec, cli.out.as_deref(), args)?,
        Command::Completions(args) => completions::run(without_spec(cli, "completions", DESCRIBES)?, args)?.into(),
        Command::Man(args) => man::run(without_spec(cli, "man", DESCRIBES)?, args)?.into(),
        Command::Init(args) => {
            without_spec(cli, "init", "it writes a new spec from its flags")?;
            init::run(args, cli.out.as_deref())?.into()
        }
    };
    rendered.write(cli.out.as_deref())
}

/// Why `completions` and `man` read no spec.
const DESCRIBES: &str = "it describes the command line itself";

/// The whole command line's definition, for `completions` and `man`; an input error when
/// `--spec` was given, which they (and `init`) do not read (`why`).
fn without_spec(cli: &Cli, subcommand: &str, why: &str) -> Result<clap::Command, CliError> {
    match &cli.spec {
        Some(path) => {
            Err(CliError::Input(format!("--spec {}: `ballscrew {subcommand}` reads no spec ({why})", path.display())))
        }
        None => Ok(Cli::command()),
    }
}

/// Exit code after SIGINT, SIGTERM or SIGHUP (128 + SIGINT, as shells report an interrupt).
const INTERRUPTED: i32 = 130;

fn main() -> ExitCode {
    let cli = Cli::parse();
    // Without the handler a signal while the files are written would leave their temporaries.
    if let Err(e) = ctrlc::set_handler(|| output::abandon_and_exit(INTERRUPTED)) {
        let _ = writeln!(std::io::stderr(), "warning: no signal handler ({e}): an interrupt may leave temporary files");
    }
    // A file-size limit (SIGXFSZ) ends the process by default, leaving its temporary files; with
    // a handler the write fails with EFBIG instead, and the run removes them as on any write
    // error (the flag it sets is not read).
    let limit_reached = Arc::new(AtomicBool::new(false));
    if let Err(e) = signal_hook::flag::register(signal_hook::consts::SIGXFSZ, limit_reached) {
        let _ = writeln!(
            std::io::stderr(),
            "warning: no SIGXFSZ handler ({e}): a file-size limit may leave temporary files"
        );
    }
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // The message names each flag as typed (an alias, where one was).
            let typed = typed::TypedFlags::from_args(&Cli::command(), std::env::args_os().skip(1));
            let _ = writeln!(std::io::stderr(), "error: {}", error::printable(&typed.restate(&e.to_string())));
            ExitCode::from(e.exit_code())
        }
    }
}
