//! `ballscrew predict`: the model's torque (with the spec's extension terms) for every row of a
//! CSV file, written as the input plus a `model_torque_nm` column.

use super::Context;
use crate::data_input::{self, DataArgs};
use crate::error::CliError;
use crate::report::csv_number;
use ballscrew_diagnose::data::{Dataset, Use};
use ballscrew_diagnose::model::{Rows, predict};
use clap::Args;

/// Flags of `predict`.
#[derive(Debug, Clone, Args)]
pub struct PredictArgs {
    /// The operating points.
    #[command(flatten)]
    pub data: DataArgs,
}

/// Name of the added column.
pub const MODEL_COLUMN: &str = "model_torque_nm";

/// Runs the command: the input's lines with the model's torque appended (CSV in every format; an
/// undefined torque an empty field).
pub fn run(ctx: &Context, args: &PredictArgs) -> Result<String, CliError> {
    let (text, d) = data_input::load(&args.data, Use::Prediction)?;
    let torques = predict(&ctx.model, &Rows::new(&d, &ctx.spec.operating))
        .map_err(|(r, e)| CliError::eval(&format!("{}: data row {}", args.data.data.display(), r + 1), &e))?;
    let mut lines = Dataset::csv_lines(&text).map(|l| l.trim_end_matches('\r'));
    let header = lines.next().unwrap_or_default();
    let mut out = format!("{header},{MODEL_COLUMN}\n");
    for (line, t) in lines.zip(torques) {
        out.push_str(&format!("{line},{}\n", csv_number(t)));
    }
    Ok(out)
}
