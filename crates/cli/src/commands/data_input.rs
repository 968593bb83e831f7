//! Measured or operating data from a CSV file for `predict` and `diagnose`: the file, the
//! `--column NAME=SOURCE` mapping, and the core's checks restated with the file name.

use crate::error::CliError;
use ballscrew_core::diagnose::data::{self, Column, Dataset};
use clap::Args;
use std::path::{Path, PathBuf};

/// Flags of a data file.
#[derive(Debug, Clone, Args)]
pub struct DataArgs {
    /// CSV file with a header: torque_nm, preload_n, speed_rpm (signed), axial_load_n,
    /// position_mm, temperature_c, time_h, repeat (missing operating columns take the spec's
    /// values; unknown columns are ignored with a warning)
    #[arg(long, value_name = "FILE")]
    pub data: PathBuf,
    /// Take a column from a differently named one, e.g. `--column time_h=hours`
    /// (repeatable)
    #[arg(long = "column", value_name = "NAME=SOURCE")]
    pub columns: Vec<String>,
}

/// The mapping of the `--column` flags.
pub fn column_map(flags: &[String]) -> Result<Vec<(Column, String)>, CliError> {
    flags
        .iter()
        .map(|f| {
            let (name, source) = f.split_once('=').ok_or_else(|| {
                CliError::Input(format!("invalid --column: {f:?} (valid: NAME=SOURCE, e.g. time_h=hours)"))
            })?;
            let c = Column::from_name(name.trim()).ok_or_else(|| {
                CliError::Input(format!(
                    "invalid --column: unknown column {:?} (valid: {})",
                    name.trim(),
                    data::ALL.map(Column::name).join(", ")
                ))
            })?;
            Ok((c, source.trim().to_string()))
        })
        .collect()
}

/// Reads the file's text.
pub fn read(path: &Path) -> Result<String, CliError> {
    std::fs::read_to_string(path)
        .map_err(|e| CliError::Input(format!("{}: cannot read data file: {e}", path.display())))
}

/// Parses the file as measured data (`for_prediction`: torque optional).
pub fn load(args: &DataArgs, text: &str, for_prediction: bool) -> Result<Dataset, CliError> {
    let map = column_map(&args.columns)?;
    let parsed =
        if for_prediction { Dataset::operating_points_from_csv(text, &map) } else { Dataset::from_csv(text, &map) };
    let d = parsed.map_err(|e| CliError::Input(format!("{}: {e}", args.data.display())))?;
    // The diagnosis report carries its warnings; a prediction has only stderr for them.
    if for_prediction {
        for w in &d.warnings {
            eprintln!("warning: {}: {w}", args.data.display());
        }
    }
    Ok(d)
}
