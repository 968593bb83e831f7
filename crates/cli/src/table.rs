//! The one place that lays out text tables: cells, number formatting, aligned columns.

use ballscrew_batch::quantities::Value;
use ballscrew_core::{Short, Significant};
use core::fmt::Write as _;

/// One value of a report.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// A real number (shown to 6 significant digits in tables, in full elsewhere).
    Num(f64),
    /// A count.
    Int(u64),
    /// A word.
    Text(String),
}

impl From<Value> for Cell {
    fn from(v: Value) -> Self {
        match v {
            Value::Num(x) => Cell::Num(x),
            Value::Int(n) => Cell::Int(n),
            Value::Text(s) => Cell::Text(s.to_string()),
        }
    }
}

impl Cell {
    /// The cell as table text.
    pub fn display(&self) -> String {
        match self {
            Cell::Num(x) => format_number(*x),
            Cell::Int(n) => n.to_string(),
            Cell::Text(s) => s.clone(),
        }
    }

    /// Numbers are right-aligned, words left-aligned.
    fn right_aligned(&self) -> bool {
        !matches!(self, Cell::Text(_))
    }
}

/// A number to 6 significant digits: whole numbers below 1e9 as integers, others fixed point
/// between 1e-3 and 1e6 and scientific outside (the core's `Significant`).
pub fn format_number(x: f64) -> String {
    Significant(x).to_string()
}

/// A number for running text: [`format_number`] without trailing zeros (`100`, `0.5`; the
/// core's `Short`).
pub fn format_short(x: f64) -> String {
    Short(x).to_string()
}

/// A table: header lines (plain text, aligned like the body) over rows of cells.
#[derive(Debug, Clone, Default)]
pub struct Table {
    /// Header lines, one string per column.
    pub header: Vec<Vec<String>>,
    /// Body rows.
    pub rows: Vec<Vec<Cell>>,
}

impl Table {
    /// Lays the table out with `indent` spaces before each line and two spaces between columns;
    /// a column is right-aligned when its first body cell is a number.
    pub fn render(&self, indent: usize) -> String {
        let ncols = self.header.iter().map(Vec::len).chain(self.rows.iter().map(Vec::len)).max().unwrap_or(0);
        let body: Vec<Vec<String>> = self.rows.iter().map(|r| r.iter().map(Cell::display).collect()).collect();
        let right: Vec<bool> =
            (0..ncols).map(|c| self.rows.first().and_then(|r| r.get(c)).is_some_and(Cell::right_aligned)).collect();
        let width: Vec<usize> = (0..ncols)
            .map(|c| {
                let cells = self.header.iter().chain(body.iter()).filter_map(|r| r.get(c));
                cells.map(|s| s.chars().count()).max().unwrap_or(0)
            })
            .collect();
        let mut out = String::new();
        let rule: Vec<String> = width.iter().map(|w| "-".repeat(*w)).collect();
        let header_lines = self.header.iter().chain((!self.header.is_empty()).then_some(&rule));
        for line in header_lines.chain(body.iter()) {
            write_line(&mut out, indent, line, &width, &right);
        }
        out
    }
}

fn write_line(out: &mut String, indent: usize, cells: &[String], width: &[usize], right: &[bool]) {
    let mut line = " ".repeat(indent);
    for (c, w) in width.iter().enumerate() {
        let s = cells.get(c).map_or("", String::as_str);
        let pad = w.saturating_sub(s.chars().count());
        if c > 0 {
            line.push_str("  ");
        }
        if right[c] {
            line.push_str(&" ".repeat(pad));
            line.push_str(s);
        } else {
            line.push_str(s);
            line.push_str(&" ".repeat(pad));
        }
    }
    let _ = writeln!(out, "{}", line.trim_end());
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_have_six_significant_digits() {
        assert_eq!(format_number(0.0712345678), "0.0712346");
        assert_eq!(format_number(2000.0), "2000");
        assert_eq!(format_number(2000.5), "2000.50");
        // A negative zero (a product with a zero axial load under reverse rotation) shows as 0.
        assert_eq!(format_number(-0.0), "0");
        assert_eq!(format_short(-0.0), "0");
        assert_eq!(format_number(-1.5), "-1.50000");
        assert_eq!(format_number(3.2e-13), "3.2000e-13");
        assert_eq!(format_number(0.0), "0");
        assert_eq!(format_number(f64::NAN), "n/a");
        assert_eq!(format_short(100.0), "100");
        assert_eq!(format_short(99.99999999999999), "100");
        assert_eq!(format_short(0.5), "0.5");
        assert_eq!(format_short(1e-9), "1.0000e-9");
    }

    #[test]
    fn columns_align() {
        let t = Table {
            header: vec![vec!["name".into(), "value".into()]],
            rows: vec![vec![Cell::Text("a".into()), Cell::Int(5)], vec![Cell::Text("long".into()), Cell::Int(12345)]],
        };
        assert_eq!(t.render(1), " name  value\n ----  -----\n a         5\n long  12345\n");
    }
}
