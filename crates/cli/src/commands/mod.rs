//! The subcommands. Each turns a [`Context`] and its flags into the text to emit, in the format
//! asked for; nothing here writes output. Each is a leaf: what several share is here or in a
//! module outside (`args`, `spec_and_flags`, `data_file`, `curves`, `quantities`, `report`,
//! `reversal_run`, the figures in `plots`).

pub mod completions;
pub mod contact;
pub mod creep_curves;
pub mod diagnose;
pub mod fmu;
pub mod init;
pub mod inspect;
pub mod man;
pub mod map;
pub mod predict;
pub mod reversal;
pub mod sensitivity;
pub mod sweep;
pub mod torque;

use crate::error::CliError;
use crate::report::vertical_table;
use crate::spec_and_flags::{self, PointInput};
use ballscrew_batch::quantities::POINT;
use ballscrew_core::Summary;
use ballscrew_core::input::Lubrication;
use ballscrew_core::screw::inertia;
use ballscrew_core::{Efficiency, Error, Model, OperatingPoint, ScrewSpec};
use clap::{Args, ValueEnum};
use serde_json::{Map, Value};
use std::path::Path;

/// The flag of the oil temperature at the contacts, the same in `sweep` and in every command of
/// one operating point.
pub const OIL_TEMPERATURE_FLAG: &str = "--oil-temperature-c";

/// Output format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// Aligned text for people.
    Table,
    /// Comma-separated values, full precision.
    Csv,
    /// JSON, full precision.
    Json,
}

/// `--format` of the report commands (`sweep`, `torque`, `inspect`, `contact`, `creep-curves`,
/// `reversal`): the formats they write, and only those (`map`, `predict` and `diagnose` have
/// their own).
#[derive(Debug, Clone, Copy, Args)]
pub struct FormatArg {
    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

/// Flags of `ballscrew torque`: one operating point, the format and the band.
#[derive(Debug, Clone, Args)]
pub struct PointCmdArgs {
    #[command(flatten)]
    pub output: FormatArg,
    #[command(flatten)]
    pub point: crate::args::PointArgs,
    #[command(flatten)]
    pub band: crate::band::BandArgs,
}

/// The spec, its model and the output format: what every command needs. `F` is the command's
/// format type (`ballscrew map` has formats of its own).
#[derive(Debug, Clone)]
pub struct Context<F = Format> {
    /// The validated spec.
    pub spec: ScrewSpec,
    /// Where the spec came from.
    pub origin: String,
    /// The model built from it.
    pub model: Model,
    /// Output format.
    pub format: F,
}

impl<F> Context<F> {
    /// Warns on stderr, once, when at any of `ops` the balls' inertia (which the quasi-static
    /// model leaves out: `ballscrew_core::screw::inertia`) is not small: the torque is then an
    /// extrapolation. Names the worst point and how many of `ops` are beyond (the core's
    /// `InertiaWarning`, the text Python's `QuasiStaticWarning` says too).
    pub fn warn_inertia(&self, ops: impl IntoIterator<Item = OperatingPoint>) {
        if let Some(w) = inertia::check(&self.spec, self.model.helix_angle_rad(), ops) {
            eprintln!("warning: {w}");
        }
    }

    /// Loads the spec (`None`: the built-in DKFZD4012) and builds its model.
    pub fn load(spec_path: Option<&Path>, format: F) -> Result<Self, CliError> {
        let loaded = spec_and_flags::load_spec(spec_path)?;
        let model = Model::new(&loaded.spec).map_err(|e| CliError::eval(&loaded.origin, &e))?;
        Ok(Self { spec: loaded.spec, origin: loaded.origin, model, format })
    }

    /// The spec's model with the oil at `temperature_c` (degrees C) at the contacts, as
    /// `--oil-temperature-c` sets it: refused under the dry model, which has no oil; the core's
    /// range check of `lubricant.temperature_c` restated with the flag.
    pub fn model_at_oil_temperature(&self, temperature_c: f64) -> Result<Model, CliError> {
        if self.spec.model.lubrication == Lubrication::Dry {
            return Err(CliError::Input(format!(
                "{OIL_TEMPERATURE_FLAG} needs the lubricated model: the spec has lubrication = \"dry\", which has no \
                 oil (set [model] lubrication = \"ehl\")"
            )));
        }
        let mut spec = self.spec;
        spec.lubricant.temperature_c = temperature_c;
        Model::new(&spec).map_err(|e| match e {
            Error::Input(i) if i.field == "lubricant.temperature_c" => CliError::Input(
                ballscrew_core::Invalid { field: OIL_TEMPERATURE_FLAG, value: temperature_c, valid: i.valid }
                    .to_string(),
            ),
            e => CliError::eval(&self.origin, &e),
        })
    }

    /// The context with the oil at `temperature_c` at the contacts (`None`: the spec's), its
    /// spec and model both: what a command of one operating point evaluates.
    pub fn with_oil_temperature(mut self, temperature_c: Option<f64>) -> Result<Self, CliError> {
        if let Some(t) = temperature_c {
            self.model = self.model_at_oil_temperature(t)?;
            self.spec.lubricant.temperature_c = t;
        }
        Ok(self)
    }

    /// The oil temperature at the contacts, degrees C, under the lubricated model (`None` under
    /// the dry one).
    pub fn oil_temperature_c(&self) -> Option<f64> {
        (self.spec.model.lubrication == Lubrication::Ehl).then_some(self.spec.lubricant.temperature_c)
    }

    /// What a report of one operating point holds fixed, in words: the point, and the oil
    /// temperature under the lubricated model (`speed 100 rpm, ..., oil 40 C`, as `sweep` says).
    pub fn describe_point(&self, op: &OperatingPoint) -> String {
        let mut text = crate::args::describe(op);
        if let Some(t) = self.oil_temperature_c() {
            text.push_str(&format!(", oil {} C", crate::table::format_short(t)));
        }
        text
    }

    /// The head of a JSON report of one operating point: [`Context::json_head`] and, under the
    /// lubricated model, `oil_temperature_c`.
    pub fn json_point_head(&self, command: &str) -> Map<String, Value> {
        let mut m = self.json_head(command);
        if let Some(t) = self.oil_temperature_c() {
            m.insert("oil_temperature_c".into(), t.into());
        }
        m
    }

    /// The spec's torque route, as written in a spec file.
    pub fn route_name(&self) -> &'static str {
        self.spec.model.torque.name()
    }

    /// The operating point of the flags, validated (see [`spec_and_flags::operating_point`]).
    pub fn operating_point(&self, input: &PointInput) -> Result<OperatingPoint, CliError> {
        spec_and_flags::operating_point(&self.spec, input)
    }

    /// First line of a table report: command, spec and what is fixed.
    pub fn title(&self, command: &str, fixed: &str) -> String {
        format!("ballscrew {command}: {}; {fixed}; torque route: {}\n", self.origin, self.route_name())
    }

    /// The head of a JSON report.
    pub fn json_head(&self, command: &str) -> Map<String, Value> {
        let mut m = Map::new();
        m.insert("command".into(), command.into());
        m.insert("spec".into(), self.origin.as_str().into());
        m.insert("torque_route".into(), self.route_name().into());
        m
    }
}

/// The forward and backdrive efficiency at the point of `summary` (solved cold), `None` (n/a)
/// where it is not defined ([`ballscrew_core::efficiency_beside`]: only the other rotation is
/// solved); `context` names the point in an evaluation error.
pub fn efficiency_at(model: &Model, summary: &Summary, context: &str) -> Result<Option<Efficiency>, CliError> {
    ballscrew_core::efficiency_beside(model, &summary.operating, summary).map_err(|e| CliError::eval(context, &e))
}

/// The torque summary of an operating point as a table (label, value, unit): `torque`,
/// `inspect`.
pub fn summary_table(summary: &Summary) -> String {
    vertical_table(POINT, core::slice::from_ref(summary), &["value"]).render(0)
}
