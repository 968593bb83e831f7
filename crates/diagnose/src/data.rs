//! Measured data: the columns a diagnosis reads, from a CSV file or from named columns, checked
//! row by row.
//!
//! CSV is read by the `csv` crate ([`Table`]): quoted fields, comma, semicolon or tab delimiters
//! (given, or found from the header line), LF, CRLF or CR line ends, a UTF-8 byte order mark,
//! blank lines and `#` comment lines. Every column is optional except `torque_nm`. A missing
//! operating column takes the spec's value (position 0, no temperature, time 0). Unknown columns
//! are named in a warning (with the known column a name is close to: `rpm`, did you mean
//! `speed_rpm`?) and ignored. A row with the wrong number of cells, an empty or
//! non-numeric cell (a decimal comma included; in a semicolon file, a point that may group
//! thousands, `1.500`), NaN or a value outside its range is an error naming the row by the line
//! of the file where it starts (the header and comment lines counted, as an editor shows them)
//! and the column. A column mapping must read each column once and leave no known column's own
//! header to another quantity unless that one is mapped from elsewhere too.

use alloc::collections::BTreeMap;
use ballscrew_core::input::extensions::{CONDITION_TEMPERATURE_RANGE_C, POSITION_RANGE_M, TIME_RANGE_H};
use ballscrew_core::{Measured, ValidRange};
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

    /// The column of a name, or `unknown column "NAME" (valid: ...)` listing every name, with
    /// `; did you mean `speed_rpm`?` when one is close ([`Column::suggest`]).
    pub fn parse(name: &str) -> Result<Column, String> {
        Self::from_name(name).ok_or_else(|| {
            let hint = Self::suggest(name, &ALL).map(|c| format!("; did you mean `{}`?", c.name())).unwrap_or_default();
            format!("unknown column {name:?} (valid: {}){hint}", ALL.map(Column::name).join(", "))
        })
    }

    /// The one column of `candidates` that an unknown header most likely means, if any: the
    /// same name in other case or punctuation (`Speed [rpm]`, `torque_Nm`), else a name it
    /// begins (`preload`, `temp`; 3 characters or more) or ends from a word's start (`rpm`,
    /// `load_n`), else one within 2 edits and a third of its length (`sped_rpm`). A header that
    /// fits several columns equally well gets no suggestion.
    pub fn suggest(header: &str, candidates: &[Column]) -> Option<Column> {
        let wanted = normalized(header);
        if wanted.is_empty() {
            return None;
        }
        let only = |fits: &dyn Fn(&str) -> bool| -> Option<Option<Column>> {
            let mut found = candidates.iter().copied().filter(|c| fits(c.name()));
            let first = found.next()?;
            Some(if found.next().is_some() { None } else { Some(first) })
        };
        let affix = |name: &str| {
            (wanted.len() >= 3 && name.starts_with(&wanted))
                || (wanted.len() >= 2 && name.len() > wanted.len() && {
                    let start = name.len() - wanted.len();
                    name.ends_with(&wanted) && name.as_bytes()[start - 1] == b'_'
                })
        };
        let close = |name: &str| {
            let d = edit_distance(&wanted, name);
            d <= 2 && 3 * d <= wanted.len()
        };
        let rules: [&dyn Fn(&str) -> bool; 3] = [&|name| name == wanted, &affix, &close];
        rules.iter().find_map(|rule| only(*rule)).flatten()
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
            // The core's ranges of the conditions, in the columns' units.
            Column::PositionMm => (POSITION_RANGE_M.0 * 1e3, POSITION_RANGE_M.1 * 1e3, "|position| <= 1e6 mm"),
            Column::TemperatureC => {
                (CONDITION_TEMPERATURE_RANGE_C.0, CONDITION_TEMPERATURE_RANGE_C.1, "[-100, 300] degrees C")
            }
            Column::TimeH => (TIME_RANGE_H.0, TIME_RANGE_H.1, "[0, 1e7] h"),
            Column::Repeat => (-1.0e15, 1.0e15, "a finite group id"),
        }
    }
}

/// Why data were rejected.
#[derive(Debug, Clone, PartialEq)]
pub enum DataError {
    /// A cell is wrong.
    Cell {
        /// Row: the line of the file where the row starts (from 1, the header and comment lines
        /// counted as the file has them), or the 1-based index for columns given as arrays.
        row: usize,
        /// The column's name as given.
        column: String,
        /// What is wrong.
        message: String,
    },
    /// A row as a whole is wrong (its number of cells); `row` as in [`DataError::Cell`].
    Row {
        /// Row: the line of the file where the row starts.
        row: usize,
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
            DataError::Row { row, message } => write!(f, "{}", printable(&format!("row {row}: {message}"))),
            DataError::Shape(m) => write!(f, "{}", printable(m)),
        }
    }
}

/// `text` with its control characters escaped (`\u{1b}`).
fn printable(text: &str) -> String {
    text.chars().map(|c| if c.is_control() { c.escape_default().to_string() } else { c.to_string() }).collect()
}

impl core::error::Error for DataError {}

/// The field delimiter of a CSV file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Delimiter {
    /// `,`
    Comma,
    /// `;` (the CSV of spreadsheets in locales with a decimal comma)
    Semicolon,
    /// A tab.
    Tab,
}

impl Delimiter {
    /// Every delimiter, in the order detection prefers them when the header is one field.
    pub const ALL: [Delimiter; 3] = [Delimiter::Comma, Delimiter::Semicolon, Delimiter::Tab];

    /// The byte.
    pub fn byte(self) -> u8 {
        match self {
            Delimiter::Comma => b',',
            Delimiter::Semicolon => b';',
            Delimiter::Tab => b'\t',
        }
    }

    /// A delimiter as a user names it: `comma` or `,`, `semicolon` or `;`, `tab`, `\t` or a tab
    /// character.
    pub fn parse(s: &str) -> Result<Delimiter, String> {
        match s {
            "," | "comma" => Ok(Delimiter::Comma),
            ";" | "semicolon" => Ok(Delimiter::Semicolon),
            "\t" | "\\t" | "tab" => Ok(Delimiter::Tab),
            _ => Err(format!("invalid delimiter {s:?} (valid: comma or \",\", semicolon or \";\", tab or \"\\t\")")),
        }
    }
}

impl fmt::Display for Delimiter {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Delimiter::Comma => "comma (`,`)",
            Delimiter::Semicolon => "semicolon (`;`)",
            Delimiter::Tab => "tab",
        })
    }
}

/// A CSV file's fields as read: the header and each row with the line where it starts. Blank
/// lines and comment lines (first non-blank character `#`) are skipped; a UTF-8 byte order mark
/// is dropped; fields may be quoted (`"a, b"`, `"1.5"`, `""` for a quote inside); lines may end
/// in LF, CRLF or CR.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// The delimiter, given or found ([`Table::parse`]).
    pub delimiter: Delimiter,
    /// The header's fields as written (quotes removed).
    pub header: Vec<String>,
    /// Line of the header, from 1.
    pub header_line: usize,
    /// Each row: the line where it starts (from 1) and its fields as written (quotes removed;
    /// rows are not checked against the header here, [`Dataset::from_table`] does).
    pub rows: Vec<(usize, Vec<String>)>,
}

impl Table {
    /// Whether the header has a column named `name` (blanks and quotes around it aside, as the
    /// dataset reads its names).
    pub fn has_column(&self, name: &str) -> bool {
        self.header.iter().any(|h| unquote(h) == name)
    }

    /// Reads CSV text with `delimiter`, or with the one found from the header line when `None`:
    /// of comma, semicolon and tab, the one that splits the header into the most fields and the
    /// first data row into as many. Refused with the lines and the delimiter when two split both
    /// alike into the same number of fields, or when only a split of the first data row into
    /// another number of fields divides the header at all.
    pub fn parse(text: &str, delimiter: Option<Delimiter>) -> Result<Table, DataError> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let delimiter = match delimiter {
            Some(d) => d,
            None => detect(text)?,
        };
        let mut records = Records::new(text, delimiter);
        let Some(first) = records.next() else {
            return Err(DataError::Shape("the data has no header line".into()));
        };
        let (header_line, header) = first?;
        let rows = records.collect::<Result<_, _>>()?;
        Ok(Table { delimiter, header, header_line, rows })
    }

    /// The table as CSV text in its own delimiter, with the column `name` of `values` appended
    /// (one value per row).
    pub fn with_column(&self, name: &str, values: &[String]) -> Result<String, String> {
        let mut w = csv::WriterBuilder::new()
            .delimiter(self.delimiter.byte())
            .flexible(true)
            .terminator(csv::Terminator::Any(b'\n'))
            .from_writer(Vec::new());
        let err = |e: csv::Error| format!("cannot write CSV: {e}");
        w.write_record(self.header.iter().map(String::as_str).chain([name])).map_err(err)?;
        for ((_, fields), v) in self.rows.iter().zip(values) {
            w.write_record(fields.iter().map(String::as_str).chain([v.as_str()])).map_err(err)?;
        }
        let bytes = w.into_inner().map_err(|e| format!("cannot write CSV: {e}"))?;
        String::from_utf8(bytes).map_err(|e| format!("cannot write CSV: {e}"))
    }
}

/// The delimiter of `text` (see [`Table::parse`]).
fn detect(text: &str) -> Result<Delimiter, DataError> {
    /// A candidate's split: the header's line and fields, the first data row's line and fields.
    struct Split {
        d: Delimiter,
        header_line: usize,
        header: usize,
        row: Option<(usize, usize)>,
    }
    impl Split {
        fn consistent(&self) -> bool {
            self.row.is_none_or(|(_, n)| n == self.header)
        }
    }
    let mut splits = Vec::new();
    for d in Delimiter::ALL {
        let mut records = Records::new(text, d);
        let Some(header) = records.next() else {
            // No header line at all: reading says so.
            return Ok(Delimiter::Comma);
        };
        let (header_line, header) = header?;
        let row = records.next().transpose()?.map(|(line, f)| (line, f.len()));
        splits.push(Split { d, header_line, header: header.len(), row });
    }
    let fields = splits.iter().filter(|s| s.consistent()).map(|s| s.header).max().unwrap_or(0);
    let best: Vec<&Split> = splits.iter().filter(|s| s.consistent() && s.header == fields).collect();
    match best[..] {
        [one] if fields > 1 => return Ok(one.d),
        [a, b, ..] if fields > 1 => {
            let row = a.row.map_or_else(String::new, |(line, _)| format!(" and line {line}"));
            return Err(DataError::Shape(format!(
                "cannot tell the delimiter: the header (line {}){row} split alike into {fields} fields at {} \
                 and at {}; give the delimiter",
                a.header_line, a.d, b.d
            )));
        }
        _ => {}
    }
    // No delimiter splits both the header and the first row alike: a file of one column, or
    // one whose first row splits differently from its header (a decimal comma, a missing cell).
    let unclear = |s: &Split| {
        let (line, n) = s.row.unwrap_or_default();
        DataError::Shape(format!(
            "cannot tell the delimiter: at {} the header (line {}) splits into {} field(s) but line {line} \
             into {n}; give the delimiter",
            s.d, s.header_line, s.header
        ))
    };
    if let Some(s) = splits.iter().filter(|s| s.header > 1).reduce(|a, b| if b.header > a.header { b } else { a }) {
        return Err(unclear(s));
    }
    match best.first() {
        Some(s) => Ok(s.d),
        None => Err(unclear(&splits[0])),
    }
}

/// The records of CSV text (no byte order mark), each with the line where it starts; blank
/// lines and comment lines skipped.
struct Records<'a> {
    text: &'a str,
    reader: csv::Reader<&'a [u8]>,
    record: csv::StringRecord,
    /// Byte after the last record read.
    end: usize,
    /// Bytes whose line breaks `line` counts.
    counted: usize,
    /// Line at byte `counted`, from 1.
    line: usize,
}

impl<'a> Records<'a> {
    fn new(text: &'a str, delimiter: Delimiter) -> Self {
        let reader = csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .delimiter(delimiter.byte())
            .comment(Some(b'#'))
            .from_reader(text.as_bytes());
        Self { text, reader, record: csv::StringRecord::new(), end: 0, counted: 0, line: 1 }
    }

    /// The line of byte `at` (not before the last one asked for): LF, CRLF and CR each end one.
    fn line_of(&mut self, at: usize) -> usize {
        let b = self.text.as_bytes();
        for i in self.counted..at {
            if b[i] == b'\n' || (b[i] == b'\r' && b.get(i + 1) != Some(&b'\n')) {
                self.line += 1;
            }
        }
        self.counted = at;
        self.line
    }
}

/// Where the record after byte `at` starts: past line ends and comment lines, as the reader
/// skips them (the reader reports only where the previous record ended).
fn record_start(b: &[u8], mut at: usize) -> usize {
    while let Some(&c) = b.get(at) {
        match c {
            b'\r' | b'\n' => at += 1,
            b'#' => {
                while b.get(at).is_some_and(|c| !matches!(c, b'\r' | b'\n')) {
                    at += 1;
                }
            }
            _ => break,
        }
    }
    at
}

impl Iterator for Records<'_> {
    type Item = Result<(usize, Vec<String>), DataError>;

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            let start = record_start(self.text.as_bytes(), self.end);
            let line = self.line_of(start);
            match self.reader.read_record(&mut self.record) {
                Ok(true) => {}
                Ok(false) => return None,
                Err(e) => return Some(Err(DataError::Row { row: line, message: format!("unreadable: {e}") })),
            }
            self.end = usize::try_from(self.reader.position().byte()).unwrap_or(self.text.len());
            // A blank line or a comment after blanks: the reader skips only empty lines and a
            // `#` in the first column.
            let rest = &self.text[start..];
            let first = rest[..rest.find(['\r', '\n']).unwrap_or(rest.len())].trim_start();
            if first.is_empty() || first.starts_with('#') {
                continue;
            }
            return Some(Ok((line, self.record.iter().map(str::to_string).collect())));
        }
    }
}

/// Measured rows, column by column (SI conversion happens where the model is called).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Dataset {
    columns: BTreeMap<Column, Vec<f64>>,
    /// Each row's number in errors: its line in the file, or its index from 1 for columns.
    numbers: Vec<usize>,
    /// Warnings (unknown columns).
    pub warnings: Vec<String>,
}

/// A renaming of columns: `(column, source header)`, e.g. `(TimeH, "hours")`.
pub type ColumnMap = [(Column, String)];

impl Dataset {
    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.numbers.len()
    }

    /// The number errors give row `i` (from 0): the line of the file where it starts, or `i + 1`
    /// for columns given as arrays.
    pub fn row_number(&self, i: usize) -> usize {
        self.numbers.get(i).copied().unwrap_or(i + 1)
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

    /// Reads the CSV file `path` for `used` with `delimiter` (found from the header when
    /// `None`, see [`Table::parse`]). Returns the file's fields too (for callers that echo its
    /// rows); every error names the file.
    pub fn read_csv(
        path: &Path,
        map: &ColumnMap,
        used: Use,
        delimiter: Option<Delimiter>,
    ) -> Result<(Table, Self), String> {
        let text =
            std::fs::read_to_string(path).map_err(|e| format!("{}: cannot read data file: {e}", path.display()))?;
        let in_file = |e: DataError| format!("{}: {e}", path.display());
        let table = Table::parse(&text, delimiter).map_err(in_file)?;
        let d = Self::from_table(&table, map, used).map_err(in_file)?;
        Ok((table, d))
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
        b.finish((1..=rows).collect())
    }

    /// Parses measured data for a diagnosis from CSV text ([`Self::parse_csv`] for
    /// [`Use::Diagnosis`]).
    pub fn from_csv(text: &str, map: &ColumnMap) -> Result<Self, DataError> {
        Self::parse_csv(text, map, Use::Diagnosis)
    }

    /// Parses CSV text with a header line for `used`, its delimiter found from the header (see
    /// [`Table`] for what is read).
    pub fn parse_csv(text: &str, map: &ColumnMap, used: Use) -> Result<Self, DataError> {
        Self::from_table(&Table::parse(text, None)?, map, used)
    }

    /// Builds a dataset for `used` from a table read from CSV: every row must have the header's
    /// number of cells, every cell of a used column a number (with a decimal point) in range.
    /// Errors name the row by its line in the file.
    pub fn from_table(table: &Table, map: &ColumnMap, used: Use) -> Result<Self, DataError> {
        let names: Vec<&str> = table.header.iter().map(|n| unquote(n)).collect();
        let mut b = Builder::new(names.iter().copied(), map, used)?;
        for (line, cells) in &table.rows {
            if cells.len() != names.len() {
                return Err(DataError::Row {
                    row: *line,
                    message: format!(
                        "{} cells, the header (line {}) has {}",
                        cells.len(),
                        table.header_line,
                        names.len()
                    ),
                });
            }
            for (k, cell) in cells.iter().enumerate() {
                if b.target[k].is_none() {
                    continue;
                }
                let v = number(unquote(cell), table.delimiter).map_err(|message| DataError::Cell {
                    row: *line,
                    column: names[k].to_string(),
                    message,
                })?;
                b.push(k, v, *line)?;
            }
        }
        b.finish(table.rows.iter().map(|(line, _)| *line).collect())
    }
}

/// A header name or a cell without the blanks around it, and without quotes left around it
/// after blanks (`a, "b"`: the reader takes quotes only at a field's start).
fn unquote(s: &str) -> &str {
    let s = s.trim();
    s.strip_prefix('"').and_then(|s| s.strip_suffix('"')).map_or(s, str::trim)
}

/// The number in a cell: a decimal point, no decimal comma (refused, never guessed). In a file
/// separated by semicolons, which the spreadsheets of decimal-comma locales write, a point that
/// groups thousands there (`1.500`, `12.000.000`: digits, then groups of exactly three) is
/// refused too: it could be 1500 as well as 1.5.
fn number(cell: &str, delimiter: Delimiter) -> Result<f64, String> {
    if cell.is_empty() {
        return Err("empty cell".into());
    }
    if delimiter == Delimiter::Semicolon && groups_thousands(cell) {
        return Err(format!(
            "{cell:?} in a file separated by semicolons: the point may group thousands there (1.500 for \
             1500) or be a decimal point (1.5); write the number without grouping, or with other than three \
             decimals"
        ));
    }
    cell.parse().map_err(|_| {
        let numeric = cell.bytes().all(|b| b.is_ascii_digit() || b"+-.,eE".contains(&b));
        if cell.contains(',') && numeric && cell.bytes().any(|b| b.is_ascii_digit()) {
            format!("decimal comma in {cell:?}: numbers take a decimal point (and no thousands separator)")
        } else {
            format!("not a number: {cell:?}")
        }
    })
}

/// Whether `cell` reads as a number with points grouping thousands: an optional sign, one to
/// three digits not starting with 0, then one or more groups of a point and three digits.
fn groups_thousands(cell: &str) -> bool {
    let digits = cell.strip_prefix(['+', '-']).unwrap_or(cell);
    let mut groups = digits.split('.');
    let first = groups.next().unwrap_or("");
    let lead = (1..=3).contains(&first.len()) && first.bytes().all(|b| b.is_ascii_digit()) && !first.starts_with('0');
    let mut rest = 0;
    for g in groups {
        if g.len() != 3 || !g.bytes().all(|b| b.is_ascii_digit()) {
            return false;
        }
        rest += 1;
    }
    lead && rest > 0
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
                    quoted(&names)
                )));
            }
        }
        // A header is read as one column: a source mapped to two columns would feed only the
        // first, the other silently taking the spec's value; a column mapped from two sources
        // is ambiguous. Both are refused (the same mapping given twice is harmless).
        for (i, (c, source)) in map.iter().enumerate() {
            for (d, other) in &map[..i] {
                if (c == d) != (source == other) {
                    let what = if c == d {
                        format!("map `{}` from two columns", c.name())
                    } else {
                        format!("take the column `{source}` for two quantities")
                    };
                    return Err(DataError::Shape(format!(
                        "column mappings {}={other} and {}={source} {what}; map each column once",
                        d.name(),
                        c.name()
                    )));
                }
            }
        }
        // A mapping whose source is another known column's own name, that column mapped from
        // nowhere else: the file's column of that name feeds the mapping, and its own quantity
        // would silently take the spec's value (a swap, each mapped from the other, is fine).
        for (c, source) in map {
            if let Some(named) = Column::from_name(source).filter(|n| n != c && !map.iter().any(|(m, _)| m == n)) {
                return Err(DataError::Shape(format!(
                    "column mapping {}={source} takes the column `{source}` for {}, so `{}` would take the spec's \
                     value; map {} from another column too ({}=SOURCE), or rename the column",
                    c.name(),
                    c.name(),
                    named.name(),
                    named.name(),
                    named.name()
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
                quoted(&names)
            )));
        }
        let warnings = if unknown.is_empty() {
            Vec::new()
        } else {
            // Suggested: a known column no header feeds, close to an ignored header's name.
            let free: Vec<Column> = ALL.iter().copied().filter(|c| !seen.contains(c)).collect();
            let hint: String = unknown
                .iter()
                .filter_map(|n| {
                    Column::suggest(n, &free).map(|c| format!("; `{}`: did you mean `{}`?", printable(n), c.name()))
                })
                .collect();
            vec![format!(
                "unknown column(s) ignored: {} (known: {}){hint}",
                printable(&quoted(&unknown)),
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
                message: format!(
                    "{} is out of range for {} (valid: {})",
                    Measured { value: v, field: c.name(), valid },
                    c.name(),
                    ValidRange(valid)
                ),
            });
        }
        self.data.entry(c).or_default().push(v);
        Ok(())
    }

    /// The dataset of the rows pushed, numbered `numbers` in errors.
    fn finish(self, numbers: Vec<usize>) -> Result<Dataset, DataError> {
        let min = if self.used == Use::Diagnosis { MIN_ROWS } else { 1 };
        let rows = numbers.len();
        if rows < min {
            return Err(DataError::Shape(format!("{rows} data rows; at least {min} needed")));
        }
        Ok(Dataset { columns: self.data, numbers, warnings: self.warnings })
    }
}

/// A header as a column name would write it: lower case, each run of other characters than
/// letters and digits one `_`, none at the ends (`Speed [rpm]` -> `speed_rpm`).
fn normalized(header: &str) -> String {
    let mut s = String::new();
    for ch in header.chars().flat_map(char::to_lowercase) {
        if ch.is_alphanumeric() {
            s.push(ch);
        } else if !s.is_empty() && !s.ends_with('_') {
            s.push('_');
        }
    }
    while s.ends_with('_') {
        s.pop();
    }
    s
}

/// Levenshtein distance of `a` and `b` in characters (insertions, deletions, substitutions).
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let next = (row[j + 1] + 1).min(row[j] + 1).min(diagonal + usize::from(ca != cb));
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// Header names in messages, each in backticks (a name may hold a comma or a blank).
fn quoted(names: &[String]) -> String {
    names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
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
        assert!(e.to_string().contains("-5 N is out of range"), "{e}");
        let e = Dataset::from_csv(&csv("0.1,1000\n"), &[]).unwrap_err();
        assert!(e.to_string().contains("row 10") && e.to_string().contains("2 cells"), "{e}");
        let e = Dataset::from_csv("preload_n\n1\n", &[]).unwrap_err();
        assert!(e.to_string().contains("no `torque_nm` column"), "{e}");
    }

    fn e_msg(e: &DataError) -> String {
        match e {
            DataError::Cell { message, .. } | DataError::Row { message, .. } => message.clone(),
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
    fn an_unknown_name_close_to_a_column_suggests_it() {
        let suggest = |h: &str| Column::suggest(h, &ALL).map(Column::name);
        for (header, column) in [
            ("rpm", "speed_rpm"),
            ("Speed [rpm]", "speed_rpm"),
            ("sped_rpm", "speed_rpm"),
            ("speed", "speed_rpm"),
            ("Torque_Nm", "torque_nm"),
            ("preload", "preload_n"),
            ("temp", "temperature_c"),
            ("time", "time_h"),
            ("load_n", "axial_load_n"),
            ("repeats", "repeat"),
        ] {
            assert_eq!(suggest(header), Some(column), "{header}");
        }
        // Far from every name, too short, or as close to two names: no suggestion.
        for header in ["wind", "bogus", "operator", "n", "t", "", "_n", "lower_screw_torque_Nm"] {
            assert_eq!(suggest(header), None, "{header}");
        }
        assert_eq!(Column::suggest("rpm", &[Column::TorqueNm, Column::PreloadN]), None);
        let e = Column::parse("rpm").unwrap_err();
        assert!(e.ends_with("time_h, repeat); did you mean `speed_rpm`?"), "{e}");
        assert_eq!(
            (edit_distance("sped_rpm", "speed_rpm"), edit_distance("", "ab"), edit_distance("ab", "ba")),
            (1, 2, 2)
        );
    }

    #[test]
    fn the_unknown_column_warning_suggests_a_column_the_file_lacks() {
        let text = "torque_nm,rpm,Preload,wind,torque\n".to_string() + &"0.1,100,1000,3,0.2\n".repeat(8);
        let d = Dataset::from_csv(&text, &[]).unwrap();
        assert_eq!(
            d.warnings,
            [format!(
                "unknown column(s) ignored: `rpm`, `Preload`, `wind`, `torque` (known: {}); `rpm`: did you mean \
                 `speed_rpm`?; `Preload`: did you mean `preload_n`?",
                ALL.map(Column::name).join(", ")
            )]
        );
        // `torque` is not sent to `torque_nm`, which the file has; nor is a header to a column
        // a mapping feeds.
        let map = [(Column::TorqueNm, "torque".to_string())];
        let d = Dataset::from_csv(&text, &map).unwrap();
        assert!(d.warnings[0].starts_with("unknown column(s) ignored: `torque_nm`, `rpm`,"), "{:?}", d.warnings);
        assert!(d.warnings[0].ends_with("; `Preload`: did you mean `preload_n`?"), "{:?}", d.warnings);
        assert_eq!(d.warnings[0].matches("did you mean").count(), 2, "{:?}", d.warnings);
    }

    #[test]
    fn a_file_is_read_for_its_use_and_named_in_errors() {
        let dir = std::env::temp_dir().join(format!("ballscrew-data-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("ops.csv");
        std::fs::write(&path, "# operating points\npreload_n\n1000\n").unwrap();
        let (table, d) = Dataset::read_csv(&path, &[], Use::Prediction, None).unwrap();
        assert_eq!((table.header_line, table.rows[0].0), (2, 3), "the comment line is counted");
        assert_eq!(d.get(Column::PreloadN), Some(&[1000.0][..]));
        let e = Dataset::read_csv(&path, &[], Use::Diagnosis, None).unwrap_err();
        assert!(e.starts_with(&format!("{}: the data has no `torque_nm` column", path.display())), "{e}");
        let missing = dir.join("missing.csv");
        let e = Dataset::read_csv(&missing, &[], Use::Prediction, None).unwrap_err();
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

    #[test]
    fn a_source_mapped_to_two_columns_or_a_column_mapped_twice_is_refused() {
        // The axial load was silently the spec's: `Fp` fed only the first mapping.
        let text = "Fp,n\n1500,300\n";
        let two = [(Column::PreloadN, "Fp".to_string()), (Column::AxialLoadN, "Fp".to_string())];
        let e = Dataset::parse_csv(text, &two, Use::Prediction).unwrap_err().to_string();
        assert_eq!(
            e,
            "column mappings preload_n=Fp and axial_load_n=Fp take the column `Fp` for two quantities; map each \
             column once"
        );
        let twice = [(Column::PreloadN, "Fp".to_string()), (Column::PreloadN, "n".to_string())];
        let e = Dataset::parse_csv(text, &twice, Use::Prediction).unwrap_err().to_string();
        assert_eq!(
            e,
            "column mappings preload_n=Fp and preload_n=n map `preload_n` from two columns; map each column once"
        );
        // The same mapping given twice is one mapping.
        let same = [(Column::PreloadN, "Fp".to_string()), (Column::PreloadN, "Fp".to_string())];
        let d = Dataset::parse_csv(text, &same, Use::Prediction).unwrap();
        assert_eq!(d.get(Column::PreloadN), Some(&[1500.0][..]));
        // A source that is another quantity's own column: that quantity would silently take the
        // spec's value. A swap of two columns maps each from the other and is read.
        let text = "preload_n,axial_load_n\n1500,300\n";
        let taken = [(Column::PreloadN, "axial_load_n".to_string())];
        let e = Dataset::parse_csv(text, &taken, Use::Prediction).unwrap_err().to_string();
        assert!(e.starts_with("column mapping preload_n=axial_load_n takes the column `axial_load_n` for preload_n, so `axial_load_n` would take the spec's value"), "{e}");
        let swap = [(Column::PreloadN, "axial_load_n".to_string()), (Column::AxialLoadN, "preload_n".to_string())];
        let d = Dataset::parse_csv(text, &swap, Use::Prediction).unwrap();
        assert_eq!((d.get(Column::PreloadN), d.get(Column::AxialLoadN)), (Some(&[300.0][..]), Some(&[1500.0][..])));
    }

    /// Eight rows of torque, preload and speed in `delimiter`, after `head` (comment lines).
    fn rows_with(delimiter: &str, head: &str) -> String {
        let mut s = format!("{head}torque_nm{delimiter}preload_n{delimiter}speed_rpm\n");
        for i in 0..8 {
            s.push_str(&format!("0.{i}{delimiter}{}{delimiter}-100\n", 1000 + i));
        }
        s
    }

    #[test]
    fn a_byte_order_mark_is_dropped() {
        let d = Dataset::parse_csv("\u{feff}preload_n,speed_rpm\r\n2000,100\r\n", &[], Use::Prediction).unwrap();
        assert_eq!(d.get(Column::PreloadN), Some(&[2000.0][..]));
        assert!(d.warnings.is_empty(), "{:?}", d.warnings);
        let t = Table::parse("\u{feff}torque_nm;preload_n\n1;2\n", None).unwrap();
        assert_eq!((t.delimiter, &t.header[0][..]), (Delimiter::Semicolon, "torque_nm"));
    }

    /// In a file separated by semicolons a point that may group thousands (`1.500`: 1500 in the
    /// decimal-comma locales that write such files, 1.5 elsewhere) is refused, naming the line
    /// and the column; other decimals read as numbers, and a comma file reads `1.500` as 1.5.
    #[test]
    fn a_thousands_point_in_a_semicolon_file_is_refused() {
        for cell in ["1.500", "-12.000", "+100.000", "1.500.000"] {
            let e = Dataset::parse_csv(&format!("preload_n;speed_rpm\n{cell};300\n"), &[], Use::Prediction)
                .unwrap_err()
                .to_string();
            assert!(
                e.starts_with(&format!("row 2, column `preload_n`: {cell:?} in a file separated by semicolons")),
                "{e}"
            );
        }
        for (cell, v) in [("1.5", 1.5), ("0.250", 0.25), ("1500", 1500.0), ("1.5000", 1.5), ("1000.5", 1000.5)] {
            let d = Dataset::parse_csv(&format!("preload_n;speed_rpm\n{cell};300\n"), &[], Use::Prediction).unwrap();
            assert_eq!(d.get(Column::PreloadN).unwrap()[0], v, "{cell}");
        }
        let d = Dataset::parse_csv("preload_n,speed_rpm\n1.500,300\n", &[], Use::Prediction).unwrap();
        assert_eq!(d.get(Column::PreloadN).unwrap()[0], 1.5);
    }

    #[test]
    fn semicolon_and_tab_files_are_read_and_their_delimiter_found() {
        for (sep, d) in [(",", Delimiter::Comma), (";", Delimiter::Semicolon), ("\t", Delimiter::Tab)] {
            let text = rows_with(sep, "");
            assert_eq!(Table::parse(&text, None).unwrap().delimiter, d);
            let data = Dataset::from_csv(&text, &[]).unwrap();
            assert_eq!(data.present(), vec![Column::TorqueNm, Column::PreloadN, Column::SpeedRpm], "{sep:?}");
            assert_eq!(data.get(Column::PreloadN).unwrap()[7], 1007.0);
            assert_eq!(data.get(Column::SpeedRpm).unwrap()[0], -100.0);
        }
        // A header with commas in its names still splits at the semicolon its first row has.
        let t = Table::parse("torque, N m;preload, N\n0.5;1000\n", None).unwrap();
        assert_eq!(
            (t.delimiter, t.header.clone()),
            (Delimiter::Semicolon, vec!["torque, N m".into(), "preload, N".into()])
        );
        // One column: the delimiter does not matter.
        assert_eq!(Table::parse("preload_n\n1000\n", None).unwrap().delimiter, Delimiter::Comma);
    }

    #[test]
    fn an_unclear_delimiter_is_refused_naming_it_and_the_lines() {
        // A decimal comma in a comma file: the first row splits into more fields than the header.
        let e = Table::parse("# units: SI\ntorque_nm,preload_n\n0,5,1000\n", None).unwrap_err().to_string();
        assert_eq!(
            e,
            "cannot tell the delimiter: at comma (`,`) the header (line 2) splits into 2 field(s) but line 3 \
             into 3; give the delimiter"
        );
        let e = Table::parse("a,b;c\n1,2;3\n", None).unwrap_err().to_string();
        assert!(e.contains("line 1) and line 2 split alike into 2 fields at comma (`,`) and at semicolon"), "{e}");
        // Given, the delimiter is taken as it is.
        assert_eq!(Table::parse("a,b;c\n1,2;3\n", Some(Delimiter::Semicolon)).unwrap().header, ["a,b", "c"]);
        let t = Table::parse(&rows_with(";", ""), Some(Delimiter::Comma)).unwrap();
        assert_eq!(t.header, ["torque_nm;preload_n;speed_rpm"]);
        assert_eq!(Delimiter::parse("tab"), Ok(Delimiter::Tab));
        assert_eq!(Delimiter::parse("\t"), Ok(Delimiter::Tab));
        assert_eq!(Delimiter::parse(";"), Ok(Delimiter::Semicolon));
        assert!(Delimiter::parse("|").unwrap_err().starts_with("invalid delimiter \"|\" (valid: comma"));
    }

    #[test]
    fn quoted_fields_are_read() {
        let text = "\"torque, N m\",\"preload_n\",note\n\"0.5\", \"1000\",\"a, b\"\n";
        let map = [(Column::TorqueNm, "torque, N m".to_string())];
        let t = Table::parse(text, None).unwrap();
        assert_eq!(t.header, ["torque, N m", "preload_n", "note"]);
        assert_eq!(t.rows[0].1[2], "a, b");
        let d = Dataset::from_table(&t, &map, Use::Prediction).unwrap();
        assert_eq!((d.torque(), d.get(Column::PreloadN)), (&[0.5][..], Some(&[1000.0][..])));
        assert!(d.warnings[0].contains("note"), "{:?}", d.warnings);
        // Unquoted, the header has one field more than its row: refused, naming the columns read.
        let unquoted = "torque, N m,preload_n\n0.5,1000\n";
        let e = Dataset::parse_csv(unquoted, &map, Use::Prediction).unwrap_err().to_string();
        assert!(e.starts_with("cannot tell the delimiter: at comma (`,`) the header (line 1) splits into 3"), "{e}");
        let t = Table::parse(unquoted, Some(Delimiter::Comma)).unwrap();
        let e = Dataset::from_table(&t, &map, Use::Prediction).unwrap_err().to_string();
        assert!(e.ends_with("no column `torque, N m` (columns: `torque`, `N m`, `preload_n`)"), "{e}");
    }

    #[test]
    fn a_decimal_comma_is_refused_naming_line_and_column() {
        let mut text = rows_with(";", "# exported\n");
        text.push_str("0,25;1000;100\n");
        let e = Dataset::from_csv(&text, &[]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "row 11, column `torque_nm`: decimal comma in \"0,25\": numbers take a decimal point (and no \
             thousands separator)"
        );
        // Quoted in a comma file too; a cell that is not a number at all says so.
        let e = Dataset::parse_csv("preload_n,x\n\"1,5\",1\n", &[], Use::Prediction).unwrap_err();
        assert!(e.to_string().starts_with("row 2, column `preload_n`: decimal comma in \"1,5\""), "{e}");
        let e = Dataset::parse_csv("preload_n\n\"a,b\"\n", &[], Use::Prediction).unwrap_err();
        assert_eq!(e.to_string(), "row 2, column `preload_n`: not a number: \"a,b\"");
    }

    #[test]
    fn a_row_of_the_wrong_length_names_its_line_and_no_column() {
        let mut text = rows_with(",", "");
        text.push_str("0.1,1000,100,7\n");
        let e = Dataset::from_csv(&text, &[]).unwrap_err();
        assert_eq!(e, DataError::Row { row: 10, message: "4 cells, the header (line 1) has 3".into() });
        assert_eq!(e.to_string(), "row 10: 4 cells, the header (line 1) has 3");
    }

    #[test]
    fn rows_are_numbered_by_their_line_in_the_file_for_every_error() {
        // Comment lines (also indented), blank lines, CRLF, a quoted cell over lines 6-7, then
        // the bad row on line 8.
        let head = "# exported\r\n\r\ntorque_nm,preload_n,note\r\n";
        let rows = "  # indented comment\r\n \t \r\n0.1,1000,\"two\r\nlines\"\r\n";
        let body: String = (0..8).map(|i| format!("0.{i},1000,x\r\n")).collect();
        let file = |bad: &str| format!("{head}{rows}{bad}\r\n{body}");
        let line = |bad: &str| match Dataset::from_csv(&file(bad), &[]).unwrap_err() {
            DataError::Cell { row, .. } | DataError::Row { row, .. } => row,
            DataError::Shape(m) => panic!("{m}"),
        };
        let parse = line("0.1,abc,x");
        let value = line("0.1,-5,x");
        let count = line("0.1,1000");
        let empty = line("0.1,,x");
        assert_eq!([parse, value, count, empty], [8; 4]);
        let d = Dataset::from_csv(&file("0.1,1000,x"), &[]).unwrap();
        assert_eq!((d.rows(), d.row_number(0), d.row_number(1), d.row_number(2)), (10, 6, 8, 9));
        // Old Mac line ends (CR only) count as lines too.
        let e = Dataset::parse_csv("preload_n\r1000\r\r-1\r", &[], Use::Prediction).unwrap_err();
        assert!(e.to_string().starts_with("row 4, column `preload_n`: -1 N is out of range"), "{e}");
        // Columns given as arrays are numbered from 1.
        let d = Dataset::parse_columns(vec![("preload_n".into(), vec![1.0, 2.0])], &[], Use::Prediction).unwrap();
        assert_eq!(d.row_number(1), 2);
    }

    #[test]
    fn a_table_is_written_back_in_its_delimiter_with_a_column() {
        let t = Table::parse("\u{feff}preload_n;note\n1000;\"a;b\"\n# c\n2000;x\n", None).unwrap();
        assert_eq!(
            t.with_column("model", &["0.5".to_string(), "1.25".to_string()]).unwrap(),
            "preload_n;note;model\n1000;\"a;b\";0.5\n2000;x;1.25\n"
        );
    }
}
