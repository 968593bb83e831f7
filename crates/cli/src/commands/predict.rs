//! `ballscrew predict`: the model's torque (with the spec's extension terms) for every row of a
//! CSV file, written as the input plus a `model_torque_nm` column (in the input's delimiter).

use super::Context;
use crate::data_file::{self, DataArgs};
use crate::error::CliError;
use crate::progress::Bar;
use crate::report::csv_number;
use ballscrew_batch::{BatchError, Errors};
use ballscrew_diagnose::data::Use;
use ballscrew_diagnose::model::{Rows, predict_rows, temperature_note};
use clap::Args;

/// What `predict` writes: CSV, the one format that carries the input's rows as they are.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum PredictFormat {
    /// The input's rows and a `model_torque_nm` column, in the input's delimiter.
    Csv,
}

/// Flags of `predict`.
#[derive(Debug, Clone, Args)]
pub struct PredictArgs {
    /// Output format: the input's rows with the model's column added, in the input's delimiter
    #[arg(long, value_enum, default_value_t = PredictFormat::Csv)]
    pub format: PredictFormat,
    /// The operating points.
    #[command(flatten)]
    pub data: DataArgs,
}

/// Name of the added column.
pub use crate::data_file::MODEL_COLUMN;

/// Runs the command: the input's rows with the model's torque appended (CSV in every format,
/// comment and blank lines left out; an undefined torque an empty field). A row the model cannot evaluate is named by its line in
/// the file, as a bad cell is.
pub fn run(ctx: &Context, args: &PredictArgs) -> Result<String, CliError> {
    let (table, d) = data_file::load(&args.data, Use::Prediction)?;
    if let Some(note) = temperature_note(&ctx.spec, &d) {
        data_file::warn(&args.data, &note);
    }
    let rows = Rows::new(&d, &ctx.spec.operating);
    ctx.warn_inertia(rows.op.iter().copied());
    let bar = Bar::new("predict", rows.op.len());
    let torques = predict_rows(&ctx.model, &rows, &bar, Errors::Raise);
    drop(bar);
    let row = |r: usize| format!("{}: row {}", args.data.data.display(), d.row_number(r));
    let torques: Vec<f64> = match torques {
        Ok(values) => values
            .into_iter()
            .enumerate()
            .map(|(r, v)| v.map_err(|e| CliError::eval(&row(r), &e)))
            .collect::<Result<_, _>>()?,
        Err(BatchError::Point { index, error }) => return Err(CliError::eval(&row(index), &error)),
        Err(other) => return Err(CliError::Eval(format!("prediction stopped: {other:?}"))),
    };
    let cells: Vec<String> = torques.iter().map(|&t| csv_number(t)).collect();
    table.with_column(MODEL_COLUMN, &cells).map_err(CliError::Output)
}
