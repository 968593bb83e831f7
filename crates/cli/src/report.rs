//! The three renderings of reported quantities: text tables, CSV and JSON.
//!
//! A [`Quantity`] (the table of reported quantities, [`ballscrew_batch::quantities`], and the
//! command line's own in [`crate::quantities`]) names one reported value (CSV/JSON key, table
//! heading, long label, unit) and reads it from a result; every command lists its quantities
//! once and the renderers below do the rest, each value as a [`Cell`].
//!
//! An undefined number (not finite: a ratio to a zero catalog torque) is written the same way
//! by every command, one convention per format: JSON `null`, CSV an empty field
//! ([`csv_number`]), tables `n/a` ([`crate::table::format_number`]).

use crate::table::{Cell, Table};
pub use ballscrew_batch::quantities::Quantity;
use serde_json::{Map, Value};

/// The cell of `quantity` of `item`.
pub fn cell<T>(quantity: &Quantity<T>, item: &T) -> Cell {
    Cell::from((quantity.get)(item))
}

/// The cells of `item` for `quantities`.
pub fn cells<T>(quantities: &[Quantity<T>], item: &T) -> Vec<Cell> {
    quantities.iter().map(|q| cell(q, item)).collect()
}

/// One row per item, one column per quantity, headings over units in brackets: a leading
/// column `lead` of the items, then `rest` of `view` of each item.
pub fn horizontal_table_led<R, T>(lead: &Quantity<R>, rest: &[Quantity<T>], items: &[R], view: fn(&R) -> &T) -> Table {
    let heads = core::iter::once(lead.head).chain(rest.iter().map(|q| q.head));
    let units = core::iter::once(lead.unit).chain(rest.iter().map(|q| q.unit));
    Table {
        header: vec![heads.map(str::to_string).collect(), units.map(|u| format!("[{u}]")).collect()],
        rows: items.iter().map(|i| led_cells(lead, rest, i, view)).collect(),
    }
}

/// The cells of one item of [`horizontal_table_led`].
pub fn led_cells<R, T>(lead: &Quantity<R>, rest: &[Quantity<T>], item: &R, view: fn(&R) -> &T) -> Vec<Cell> {
    core::iter::once(cell(lead, item)).chain(cells(rest, view(item))).collect()
}

/// Appends the columns of `quantities` of `view` of each item to `table` (one row per item, as
/// [`horizontal_table_led`] lays them out).
pub fn append_columns<R, T>(table: &mut Table, quantities: &[Quantity<T>], items: &[R], view: fn(&R) -> &T) {
    if let [heads, units, ..] = table.header.as_mut_slice() {
        heads.extend(quantities.iter().map(|q| q.head.to_string()));
        units.extend(quantities.iter().map(|q| format!("[{}]", q.unit)));
    }
    for (row, item) in table.rows.iter_mut().zip(items) {
        row.extend(cells(quantities, view(item)));
    }
}

/// One row per quantity (label, a value per item, unit), one column per item.
pub fn vertical_table<T>(quantities: &[Quantity<T>], items: &[T], item_heads: &[&str]) -> Table {
    let mut header = vec!["quantity".to_string()];
    header.extend(item_heads.iter().map(|h| h.to_string()));
    header.push("unit".to_string());
    let rows = quantities
        .iter()
        .map(|q| {
            let mut row = vec![Cell::Text(q.label.to_string())];
            row.extend(items.iter().map(|i| cell(q, i)));
            row.push(Cell::Text(q.unit.to_string()));
            row
        })
        .collect();
    Table { header: vec![header], rows }
}

/// CSV: a header of keys, then one line per row; numbers in full precision (shortest text that
/// reads back to the same `f64`).
pub fn csv(keys: &[&str], rows: &[Vec<Cell>]) -> String {
    let mut out = keys.join(",");
    out.push('\n');
    for row in rows {
        out.push_str(&csv_line(row));
    }
    out
}

/// One row of [`csv`], its line end included.
pub fn csv_line(row: &[Cell]) -> String {
    let fields: Vec<String> = row.iter().map(csv_field).collect();
    fields.join(",") + "\n"
}

/// A number as a CSV field: full precision, empty when undefined (not finite).
pub fn csv_number(x: f64) -> String {
    // `x + 0.0`: -0 is written as 0.
    if x.is_finite() { format!("{:?}", x + 0.0) } else { String::new() }
}

fn csv_field(c: &Cell) -> String {
    match c {
        Cell::Num(x) => csv_number(*x),
        Cell::Int(n) => n.to_string(),
        Cell::Text(s) if s.contains([',', '"', '\n']) => format!("\"{}\"", s.replace('"', "\"\"")),
        Cell::Text(s) => s.clone(),
    }
}

/// The keys of `quantities`.
pub fn keys<T>(quantities: &[Quantity<T>]) -> Vec<&'static str> {
    quantities.iter().map(|q| q.key).collect()
}

/// A JSON value of a cell: numbers in full precision, non-finite numbers as `null`.
pub fn json_value(c: &Cell) -> Value {
    match c {
        Cell::Num(x) => Value::from(*x + 0.0),
        Cell::Int(n) => Value::from(*n),
        Cell::Text(s) => Value::from(s.as_str()),
    }
}

/// A JSON object of `item`, keyed by the quantities' keys.
pub fn json_object<T>(quantities: &[Quantity<T>], item: &T) -> Map<String, Value> {
    quantities.iter().map(|q| (q.key.to_string(), json_value(&cell(q, item)))).collect()
}

/// Pretty JSON text with a final newline.
pub fn json_text(v: &Value) -> String {
    let mut s = serde_json::to_string_pretty(v).unwrap_or_else(|e| format!("\"JSON error: {e}\""));
    s.push('\n');
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use ballscrew_batch::quantities::Value as V;

    static Q: &[Quantity<(f64, &'static str)>] = &[
        Quantity { key: "x_m", head: "x", label: "the x", unit: "m", get: |p| V::Num(p.0) },
        Quantity { key: "name", head: "name", label: "its name", unit: "-", get: |p| V::Text(p.1) },
    ];

    #[test]
    fn csv_is_full_precision_and_quoted() {
        let rows: Vec<Vec<Cell>> = [(0.1 + 0.2, "a,b"), (1e-300, "c")].iter().map(|i| cells(Q, i)).collect();
        let text = csv(&keys(Q), &rows);
        assert_eq!(text, "x_m,name\n0.30000000000000004,\"a,b\"\n1e-300,c\n");
    }

    #[test]
    fn undefined_numbers_are_empty_in_csv_and_null_in_json() {
        let rows: Vec<Vec<Cell>> =
            [(f64::NAN, "a"), (f64::INFINITY, "b"), (-0.0, "c")].iter().map(|i| cells(Q, i)).collect();
        assert_eq!(csv(&keys(Q), &rows), "x_m,name\n,a\n,b\n0.0,c\n");
        assert_eq!(json_object(Q, &(-0.0, "a"))["x_m"].to_string(), "0.0");
        assert!(json_object(Q, &(f64::NEG_INFINITY, "a"))["x_m"].is_null());
    }

    #[test]
    fn json_keeps_full_precision_and_nulls_nan() {
        let o = json_object(Q, &(0.1 + 0.2, "a"));
        assert_eq!(o["x_m"].as_f64(), Some(0.1 + 0.2));
        assert!(json_object(Q, &(f64::NAN, "a"))["x_m"].is_null());
    }

    #[test]
    fn vertical_table_has_label_values_unit() {
        let t = vertical_table(Q, &[(1.0, "a"), (2.0, "b")], &["first", "second"]);
        assert_eq!(t.header[0], ["quantity", "first", "second", "unit"]);
        assert_eq!(t.rows[0][0], Cell::Text("the x".into()));
        assert_eq!(t.rows[0][3], Cell::Text("m".into()));
    }
}
