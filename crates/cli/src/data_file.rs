//! Measured or operating data from a CSV file for `predict` and `diagnose`: the file, its
//! `--delimiter`, the `--column NAME=SOURCE` mapping, and the core's checks restated with the
//! file name.

use crate::error::{CliError, printable};
use ballscrew_diagnose::data::{Column, Dataset, Delimiter, Table, Use};
use clap::Args;
use std::path::PathBuf;

/// Flags of a data file.
#[derive(Debug, Clone, Args)]
pub struct DataArgs {
    /// CSV file with a header: torque_nm, preload_n, speed_rpm (signed), axial_load_n,
    /// position_mm, temperature_c, time_h, repeat (missing operating columns take the spec's
    /// values; unknown columns are ignored with a warning; numbers with a decimal point)
    #[arg(long, value_name = "FILE")]
    pub data: PathBuf,
    /// Field delimiter of the data file: comma, semicolon or tab (also `,` `;` `\t`); default:
    /// found from the header line and the first row
    #[arg(long, value_name = "DELIMITER", value_parser = Delimiter::parse)]
    pub delimiter: Option<Delimiter>,
    /// Take a column from a differently named one, e.g. `--column time_h=hours`
    /// (repeatable)
    #[arg(long = "column", value_name = "NAME=SOURCE")]
    pub columns: Vec<String>,
}

/// Name of the column `predict` adds to its data.
pub const MODEL_COLUMN: &str = "model_torque_nm";

/// Warns on stderr about the data file of `args`: `warning: FILE: what`, control characters
/// escaped.
pub fn warn(args: &DataArgs, what: &str) {
    eprintln!("warning: {}", printable(&format!("{}: {what}", args.data.display())));
}

/// The mapping of the `--column` flags.
pub fn column_map(flags: &[String]) -> Result<Vec<(Column, String)>, CliError> {
    flags
        .iter()
        .map(|f| {
            let (name, source) = f.split_once('=').ok_or_else(|| {
                CliError::Input(format!("invalid --column: {f:?} (valid: NAME=SOURCE, e.g. time_h=hours)"))
            })?;
            let c = Column::parse(name.trim()).map_err(|e| CliError::Input(format!("invalid --column: {e}")))?;
            Ok((c, source.trim().to_string()))
        })
        .collect()
}

/// Reads and parses the file as measured data (`used`: torque required or optional); returns
/// its fields too.
pub fn load(args: &DataArgs, used: Use) -> Result<(Table, Dataset), CliError> {
    let map = column_map(&args.columns)?;
    let (table, d) = Dataset::read_csv(&args.data, &map, used, args.delimiter).map_err(CliError::Input)?;
    // The diagnosis report carries its warnings; a prediction has only stderr for them.
    if used == Use::Prediction {
        // A prediction appends this column: a second column of the name would leave readers to
        // pick one (pandas takes the first, the stale one; `csv.DictReader` the last).
        let model = MODEL_COLUMN;
        if table.has_column(model) {
            return Err(CliError::Input(format!(
                "{}: the data already has a column `{model}` (line {}), the column predict adds; remove or \
                 rename it",
                args.data.display(),
                table.header_line
            )));
        }
        for w in &d.warnings {
            warn(args, w);
        }
    }
    Ok((table, d))
}
