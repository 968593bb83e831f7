//! `ballscrew predict`: the model's torque (with the spec's extension terms) for every row of a
//! CSV file, written as the input plus a `model_torque_nm` column.

use super::Context;
use super::data_input::{self, DataArgs};
use crate::error::CliError;
use ballscrew_core::SolverState;
use ballscrew_core::diagnose::data::Dataset;
use ballscrew_core::diagnose::model::Rows;
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

/// Runs the command: the input's lines with the model's torque appended (CSV in every format).
pub fn run(ctx: &Context, args: &PredictArgs) -> Result<String, CliError> {
    let text = data_input::read(&args.data.data)?;
    let d = data_input::load(&args.data, &text, true)?;
    let rows = Rows::new(&d, &ctx.spec.operating);
    let mut state = SolverState::new();
    let mut out = String::new();
    for (i, line) in Dataset::csv_lines(&text).enumerate() {
        let line = line.trim_end_matches('\r');
        if i == 0 {
            out.push_str(&format!("{line},{MODEL_COLUMN}\n"));
            continue;
        }
        let r = i - 1;
        let t = ctx
            .model
            .torque_at(&rows.op[r], &rows.cond[r], &mut state)
            .map_err(|e| CliError::eval(&format!("{}: data row {}", args.data.data.display(), r + 1), &e))?;
        out.push_str(&format!("{line},{t}\n"));
    }
    Ok(out)
}
