//! `ballscrew predict`: the model's torque (with the spec's extension terms) for every row of a
//! CSV file, written as the input plus a `model_torque_nm` column (in the input's delimiter), or
//! as JSON: the columns the model read and its torque, row by row.

use super::Context;
use crate::data_file::{self, DataArgs};
use crate::error::CliError;
use crate::progress::Bar;
use crate::report::{csv_number, json_text};
use ballscrew_batch::{BatchError, Errors};
use ballscrew_core::input::rad_s_to_rpm;
use ballscrew_diagnose::data::{Column, Dataset, Use};
use ballscrew_diagnose::model::{Rows, predict_rows, temperature_note};
use clap::Args;
use serde_json::{Map, Value};

/// What `predict` writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum PredictFormat {
    /// The input's rows and a `model_torque_nm` column, in the input's delimiter.
    Csv,
    /// JSON, full precision: each row's line in the file, the known columns read from it (by
    /// their own names) and `model_torque_nm`; the spec's values of the operating columns the
    /// file lacks in the head.
    Json,
}

/// Flags of `predict`.
#[derive(Debug, Clone, Args)]
pub struct PredictArgs {
    /// Output format
    #[arg(long, value_enum, default_value_t = PredictFormat::Csv)]
    pub format: PredictFormat,
    /// The operating points.
    #[command(flatten)]
    pub data: DataArgs,
}

/// Name of the added column.
pub use crate::data_file::MODEL_COLUMN;

/// Runs the command: the input's rows with the model's torque appended (CSV: comment and blank
/// lines left out, an undefined torque an empty field; JSON: [`json`]). A row the model cannot
/// evaluate is named by its line in the file, as a bad cell is.
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
        Err(e @ BatchError::OutOfMemory { .. }) => return Err(CliError::Eval(format!("predict: {e}"))),
        Err(other) => return Err(CliError::Eval(format!("prediction stopped: {other:?}"))),
    };
    match args.format {
        PredictFormat::Csv => {
            let cells: Vec<String> = torques.iter().map(|&t| csv_number(t)).collect();
            table.with_column(MODEL_COLUMN, &cells).map_err(CliError::Output)
        }
        PredictFormat::Json => Ok(json(ctx, args, &d, &torques)),
    }
}

/// The prediction as JSON: the report's head, the data file, the spec's value of each operating
/// column the file lacks (`speed_rpm`, `preload_n`, `axial_load_n`, as a sweep names what it
/// holds), then `rows`: each row's `row` (its line in the file, as errors name it), the known
/// columns it gives and `model_torque_nm` (`null` where undefined).
fn json(ctx: &Context, args: &PredictArgs, d: &Dataset, torques: &[f64]) -> String {
    let mut head = ctx.json_head("predict");
    head.insert("data".into(), args.data.data.display().to_string().into());
    let op = &ctx.spec.operating;
    for (column, spec_value) in [
        (Column::SpeedRpm, rad_s_to_rpm(op.speed_rad_s)),
        (Column::PreloadN, op.preload_n),
        (Column::AxialLoadN, op.axial_load_n),
    ] {
        if d.get(column).is_none() {
            head.insert(column.name().into(), (spec_value + 0.0).into());
        }
    }
    let present = d.present();
    let rows: Vec<Value> = torques
        .iter()
        .enumerate()
        .map(|(r, &t)| {
            let mut o = Map::new();
            o.insert("row".into(), d.row_number(r).into());
            for &c in &present {
                let v = d.get(c).map_or(f64::NAN, |values| values[r]);
                o.insert(c.name().into(), (v + 0.0).into());
            }
            o.insert(MODEL_COLUMN.into(), (t + 0.0).into());
            Value::Object(o)
        })
        .collect();
    head.insert("rows".into(), rows.into());
    json_text(&Value::Object(head))
}
