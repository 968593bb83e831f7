//! Measured data: the columns a diagnosis reads, from CSV text or from named columns, checked
//! row by row.
//!
//! Every column is optional except `torque_nm`. A missing operating column takes the spec's
//! value (position 0, no temperature, time 0). Unknown columns are named in a warning and
//! ignored. A malformed row, an empty or non-numeric cell, NaN or a value outside its range is
//! an error naming the row (the line of the file, the header being line 1) and the column.

use alloc::collections::BTreeMap;
use ballscrew_core::Shown;
use core::fmt;
use std::path::Path;

/// The columns a diagnosis knows, with their units in the names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Column {
    /// Measured drive torque, N m.
    TorqueNm,
    /// Preload, N.
    PreloadN,
    /// Screw speed, rpm (signed: negative is the reverse direction).
    SpeedRpm,
    /// External axial load on the nut, N.
    AxialLoadN,
    /// Nut position along the stroke, mm.
    PositionMm,
    /// Temperature, degrees C.
    TemperatureC,
    /// Hours since the start.
    TimeH,
    /// Group id of repeated measurements.
    Repeat,
}

/// Every column, in the order of [`Column`].
pub const ALL: [Column; 8] = [
    Column::TorqueNm,
    Column::PreloadN,
    Column::SpeedRpm,
    Column::AxialLoadN,
    Column::PositionMm,
    Column::TemperatureC,
    Column::TimeH,
    Column::Repeat,
];

impl Column {
    /// The column's name in a CSV header.
    pub fn name(self) -> &'static str {
        match self {
            Column::TorqueNm => "torque_nm",
            Column::PreloadN => "preload_n",
            Column::SpeedRpm => "speed_rpm",
            Column::AxialLoadN => "axial_load_n",
            Column::PositionMm => "position_mm",
            Column::TemperatureC => "temperature_c",
            Column::TimeH => "time_h",
            Column::Repeat => "repeat",
        }
    }

    /// The column of a name.
    pub fn from_name(name: &str) -> Option<Column> {
        ALL.iter().copied().find(|c| c.name() == name)
    }

    /// The column of a name, or `unknown column "NAME" (valid: ...)` listing every name.
    pub fn parse(name: &str) -> Result<Column, String> {
        Self::from_name(name)
            .ok_or_else(|| format!("unknown column {name:?} (valid: {})", ALL.map(Column::name).join(", ")))
    }

    /// Unit for the report.
    pub fn unit(self) -> &'static str {
        match self {
            Column::TorqueNm => "N m",
            Column::PreloadN | Column::AxialLoadN => "N",
            Column::SpeedRpm => "rpm",
            Column::PositionMm => "mm",
            Column::TemperatureC => "degrees C",
            Column::TimeH => "h",
            Column::Repeat => "",
        }
    }

    /// Valid range (inclusive) and its wording.
    fn range(self) -> (f64, f64, &'static str) {
        match self {
            Column::TorqueNm => (-1.0e4, 1.0e4, "finite, |torque| <= 1e4 N m"),
            Column::PreloadN => (0.0, 1.0e7, "[0, 1e7] N"),
            Column::SpeedRpm => (-30_000.0, 30_000.0, "|speed| <= 30000 rpm"),
            Column::AxialLoadN => (-1.0e7, 1.0e7, "[-1e7, 1e7] N"),
            Column::PositionMm => (-1.0e6, 1.0e6, "|position| <= 1e6 mm"),
            Column::TemperatureC => (-100.0, 300.0, "[-100, 300] degrees C"),
            Column::TimeH => (0.0, 1.0e7, "[0, 1e7] h"),
            Column::Repeat => (-1.0e15, 1.0e15, "a finite group id"),
        }
    }
}

/// Why data were rejected.
#[derive(Debug, Clone, PartialEq)]
pub enum DataError {
    /// A cell or a row is wrong.
    Cell {
        /// Row: the line of the file (header = 1), or the 1-based index for columns given as
        /// arrays.
        row: usize,
        /// The column's name as given.
        column: String,
        /// What is wrong.
        message: String,
    },
    /// The data as a whole is unusable (no torque column, too few rows, ...).
    Shape(String),
}

impl fmt::Display for DataError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Headers and cells are the file's: their control characters are escaped (`\u{1b}`) so
        // that a message cannot drive the terminal.
        match self {
            DataError::Cell { row, column, message } => {
                write!(f, "{}", printable(&format!("row {row}, column `{column}`: {message}")))
            }
            DataError::Shape(m) => write!(f, "{}", printable(m)),
        }
    }
}

/// `text` with its control characters escaped (`\u{1b}`).
fn printable(text: &str) -> String {
    text.chars().map(|c| if c.is_control() { c.escape_default().to_string() } else { c.to_string() }).collect()
}

impl core::error::Error for DataError {}

/// Measured rows, column by column (SI conversion happens where the model is called).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Dataset {
    columns: BTreeMap<Column, Vec<f64>>,
    rows: usize,
    /// Warnings (unknown columns).
    pub warnings: Vec<String>,
}

/// A renaming of columns: `(column, source header)`, e.g. `(TimeH, "hours")`.
pub type ColumnMap = [(Column, String)];

impl Dataset {
    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// A column, if present.
    pub fn get(&self, c: Column) -> Option<&[f64]> {
        self.columns.get(&c).map(Vec::as_slice)
    }

    /// The measured torque, N m.
    pub fn torque(&self) -> &[f64] {
        self.get(Column::TorqueNm).unwrap_or(&[])
    }

    /// The columns present, in the order of [`Column`].
    pub fn present(&self) -> Vec<Column> {
        self.columns.keys().copied().collect()
    }

    /// Reads the CSV file `path` for `used`. Returns the file's text too (for callers that echo
    /// its lines); every error names the file.
    pub fn read_csv(path: &Path, map: &ColumnMap, used: Use) -> Result<(String, Self), String> {
        let text =
            std::fs::read_to_string(path).map_err(|e| format!("{}: cannot read data file: {e}", path.display()))?;
        let d = Self::parse_csv(&text, map, used).map_err(|e| format!("{}: {e}", path.display()))?;
        Ok((text, d))
    }

    /// Builds a dataset for `used` from named columns (names as in a CSV header, after `map`).
    /// Rows are numbered from 1 in errors.
    pub fn parse_columns(named: Vec<(String, Vec<f64>)>, map: &ColumnMap, used: Use) -> Result<Self, DataError> {
        let mut b = Builder::new(named.iter().map(|(n, _)| n.as_str()), map, used)?;
        let rows = named.first().map_or(0, |(_, v)| v.len());
        for (name, v) in &named {
            if v.len() != rows {
                return Err(DataError::Shape(format!(
                    "column `{name}` has {} values, the first column {rows}",
                    v.len()
                )));
            }
        }
        for r in 0..rows {
            for (i, (_, v)) in named.iter().enumerate() {
                b.push(i, v[r], r + 1)?;
            }
        }
        b.finish(rows)
    }

    /// Parses measured data for a diagnosis from CSV text ([`Self::parse_csv`] for
    /// [`Use::Diagnosis`]).
    pub fn from_csv(text: &str, map: &ColumnMap) -> Result<Self, DataError> {
        Self::parse_csv(text, map, Use::Diagnosis)
    }

    /// The data lines of CSV text as [`Self::parse_csv`] reads them (header first).
    pub fn csv_lines(text: &str) -> impl Iterator<Item = &str> {
        text.lines().filter(|l| is_data_line(l))
    }

    /// Parses CSV text with a header line for `used` (commas; blank lines and lines starting
    /// with `#` are skipped).
    pub fn parse_csv(text: &str, map: &ColumnMap, used: Use) -> Result<Self, DataError> {
        let mut lines = text.lines().enumerate().filter(|(_, l)| is_data_line(l));
        let Some((_, header)) = lines.next() else {
            return Err(DataError::Shape("the data has no header line".into()));
        };
        let names: Vec<String> = header.split(',').map(|s| s.trim().trim_matches('"').to_string()).collect();
        let mut b = Builder::new(names.iter().map(String::as_str), map, used)?;
        let mut rows = 0;
        for (i, line) in lines {
            let cells: Vec<&str> = line.split(',').collect();
            if cells.len() != names.len() {
                return Err(DataError::Cell {
                    row: i + 1,
                    column: names.last().cloned().unwrap_or_default(),
                    message: format!("{} cells, the header has {}", cells.len(), names.len()),
                });
            }
            for (k, cell) in cells.iter().enumerate() {
                let cell = cell.trim().trim_matches('"');
                if b.target[k].is_none() {
                    continue;
                }
                let v: f64 = cell.parse().map_err(|_| DataError::Cell {
                    row: i + 1,
                    column: names[k].clone(),
                    message: if cell.is_empty() { "empty cell".into() } else { format!("not a number: {cell:?}") },
                })?;
                b.push(k, v, i + 1)?;
            }
            rows += 1;
        }
        b.finish(rows)
    }
}

/// Whether a CSV line holds data (the header or a row): not blank, not a `#` comment.
fn is_data_line(line: &str) -> bool {
    !line.trim().is_empty() && !line.trim_start().starts_with('#')
}

/// What the data is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Use {
    /// Torque required, at least [`MIN_ROWS`] rows.
    Diagnosis,
    /// Torque optional, one row enough.
    Prediction,
}

/// Collects checked values column by column.
struct Builder {
    used: Use,
    names: Vec<String>,
    target: Vec<Option<Column>>,
    data: BTreeMap<Column, Vec<f64>>,
    warnings: Vec<String>,
}

impl Builder {
    fn new<'a>(names: impl Iterator<Item = &'a str>, map: &ColumnMap, used: Use) -> Result<Self, DataError> {
        let names: Vec<String> = names.map(str::to_string).collect();
        for (c, source) in map {
            if !names.iter().any(|n| n == source) {
                return Err(DataError::Shape(format!(
                    "column mapping {}={source}: the data has no column `{source}` (columns: {})",
                    c.name(),
                    names.join(", ")
                )));
            }
        }
        let mut target = Vec::new();
        let mut unknown = Vec::new();
        let mut seen = Vec::new();
        for n in &names {
            let c = map.iter().find(|(_, s)| s == n).map(|(c, _)| *c).or_else(|| {
                // A header named like a known column is used unless a mapping takes that
                // column from elsewhere.
                Column::from_name(n).filter(|c| !map.iter().any(|(m, _)| m == c))
            });
            if let Some(c) = c {
                if seen.contains(&c) {
                    return Err(DataError::Shape(format!("column `{}` is given twice", c.name())));
                }
                seen.push(c);
            } else {
                unknown.push(n.clone());
            }
            target.push(c);
        }
        if used == Use::Diagnosis && !seen.contains(&Column::TorqueNm) {
            return Err(DataError::Shape(format!(
                "the data has no `torque_nm` column (columns: {}); map one with torque_nm=NAME",
                names.join(", ")
            )));
        }
        let warnings = if unknown.is_empty() {
            Vec::new()
        } else {
            vec![format!(
                "unknown column(s) ignored: {} (known: {})",
                printable(&unknown.join(", ")),
                ALL.map(Column::name).join(", ")
            )]
        };
        Ok(Self { used, names, target, data: BTreeMap::new(), warnings })
    }

    fn push(&mut self, k: usize, v: f64, row: usize) -> Result<(), DataError> {
        let Some(c) = self.target[k] else { return Ok(()) };
        let (lo, hi, valid) = c.range();
        if !(v >= lo && v <= hi) {
            return Err(DataError::Cell {
                row,
                column: self.names[k].clone(),
                message: format!("{} is out of range for {} (valid: {valid})", Shown(v), c.name()),
            });
        }
        self.data.entry(c).or_default().push(v);
        Ok(())
    }

    fn finish(self, rows: usize) -> Result<Dataset, DataError> {
        let min = if self.used == Use::Diagnosis { MIN_ROWS } else { 1 };
        if rows < min {
            return Err(DataError::Shape(format!("{rows} data rows; at least {min} needed")));
        }
        Ok(Dataset { columns: self.data, rows, warnings: self.warnings })
    }
}

/// Fewest rows accepted.
pub const MIN_ROWS: usize = 8;

#[cfg(test)]
mod tests {
    use super::*;

    fn csv(body: &str) -> String {
        let mut s = String::from("torque_nm,preload_n,speed_rpm,wind\n");
        for i in 0..8 {
            s.push_str(&format!("0.0{i},1000,100,3\n"));
        }
        s.push_str(body);
        s
    }

    #[test]
    fn reads_known_columns_and_warns_about_the_rest() {
        let d = Dataset::from_csv(&csv(""), &[]).unwrap();
        assert_eq!(d.rows(), 8);
        assert_eq!(d.present(), vec![Column::TorqueNm, Column::PreloadN, Column::SpeedRpm]);
        assert!(d.warnings[0].contains("wind"), "{:?}", d.warnings);
    }

    #[test]
    fn bad_cells_name_row_and_column() {
        let e = Dataset::from_csv(&csv("0.1,NaN,100,1\n"), &[]).unwrap_err();
        assert_eq!(e, DataError::Cell { row: 10, column: "preload_n".into(), message: e_msg(&e) });
        assert!(e.to_string().contains("row 10, column `preload_n`"), "{e}");
        let e = Dataset::from_csv(&csv("0.1,1000,,1\n"), &[]).unwrap_err();
        assert!(e.to_string().contains("row 10, column `speed_rpm`: empty cell"), "{e}");
        let e = Dataset::from_csv(&csv("0.1,-5,100,1\n"), &[]).unwrap_err();
        assert!(e.to_string().contains("-5 is out of range"), "{e}");
        let e = Dataset::from_csv(&csv("0.1,1000\n"), &[]).unwrap_err();
        assert!(e.to_string().contains("row 10") && e.to_string().contains("2 cells"), "{e}");
        let e = Dataset::from_csv("preload_n\n1\n", &[]).unwrap_err();
        assert!(e.to_string().contains("no `torque_nm` column"), "{e}");
    }

    fn e_msg(e: &DataError) -> String {
        match e {
            DataError::Cell { message, .. } => message.clone(),
            DataError::Shape(m) => m.clone(),
        }
    }

    #[test]
    fn column_names_parse_or_list_the_valid_ones() {
        assert_eq!(Column::parse("time_h"), Ok(Column::TimeH));
        let e = Column::parse("hours").unwrap_err();
        assert!(e.starts_with("unknown column \"hours\" (valid: torque_nm, preload_n,"), "{e}");
        assert!(e.ends_with("time_h, repeat)"), "{e}");
    }

    #[test]
    fn a_file_is_read_for_its_use_and_named_in_errors() {
        let dir = std::env::temp_dir().join(format!("ballscrew-data-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("ops.csv");
        std::fs::write(&path, "# operating points\npreload_n\n1000\n").unwrap();
        let (text, d) = Dataset::read_csv(&path, &[], Use::Prediction).unwrap();
        assert!(text.starts_with("# operating points"));
        assert_eq!(d.get(Column::PreloadN), Some(&[1000.0][..]));
        let e = Dataset::read_csv(&path, &[], Use::Diagnosis).unwrap_err();
        assert!(e.starts_with(&format!("{}: the data has no `torque_nm` column", path.display())), "{e}");
        let missing = dir.join("missing.csv");
        let e = Dataset::read_csv(&missing, &[], Use::Prediction).unwrap_err();
        assert!(e.starts_with(&format!("{}: cannot read data file: ", missing.display())), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_mapping_renames_columns() {
        let text = "hours,up\n".to_string() + &(0..9).map(|i| format!("{i},0.3\n")).collect::<String>();
        let map = [(Column::TimeH, "hours".to_string()), (Column::TorqueNm, "up".to_string())];
        let d = Dataset::from_csv(&text, &map).unwrap();
        assert_eq!(d.get(Column::TimeH).unwrap()[8], 8.0);
        let bad = [(Column::TimeH, "hour".to_string())];
        assert!(Dataset::from_csv(&text, &bad).unwrap_err().to_string().contains("no column `hour`"));
    }
}
