//! `ballscrew.diagnose(data, spec=None, columns=None, delimiter=None)`: the diagnosis of
//! measured torques from Python, returning the report of `ballscrew diagnose --report` as Python
//! dicts and lists; and `ballscrew.predict(...)`, the model's torque (extension terms of the spec
//! included) per row, as `ballscrew predict` gives it.

use crate::errors::value_error;
use crate::screw::Screw;
use ballscrew_config as config;
use ballscrew_core::{Model, ScrewSpec};
use ballscrew_diagnose::data::{Column, Dataset, Delimiter, Use};
use ballscrew_diagnose::model::{Rows, predict as predict_rows};
use ballscrew_diagnose::{self as core_diagnose};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::collections::HashMap;
use std::path::PathBuf;

/// The `columns` mapping (column name -> source name) in the core's terms.
fn column_map(columns: Option<HashMap<String, String>>) -> PyResult<Vec<(Column, String)>> {
    let mut map: Vec<(Column, String)> = Vec::new();
    for (name, source) in columns.unwrap_or_default() {
        let c = Column::parse(&name).map_err(|e| value_error(format!("invalid columns: {e}")))?;
        map.push((c, source));
    }
    map.sort_by_key(|(c, _)| *c);
    Ok(map)
}

/// Reads the data for `used`: a dict of columns (name -> sequence of numbers) or a CSV path
/// (read with `delimiter`: `","`, `";"`, `"\t"` or their names, found from the header when
/// `None`). Returns the path too.
fn dataset(
    data: &Bound<'_, PyAny>,
    map: &[(Column, String)],
    used: Use,
    delimiter: Option<&str>,
) -> PyResult<(Dataset, Option<PathBuf>)> {
    if let Ok(dict) = data.cast::<PyDict>() {
        if delimiter.is_some() {
            return Err(value_error("delimiter: only for a CSV path, not a dict of columns"));
        }
        let mut named = Vec::new();
        for (k, v) in dict.iter() {
            let name: String = k.extract().map_err(|_| value_error("data: column names must be strings"))?;
            let values: Vec<f64> =
                v.extract().map_err(|_| value_error(format!("data: column {name:?} is not a sequence of numbers")))?;
            named.push((name, values));
        }
        return Ok((Dataset::parse_columns(named, map, used).map_err(value_error)?, None));
    }
    let path: PathBuf = data.extract().map_err(|_| value_error("data: a CSV path or a dict of columns"))?;
    let delimiter = delimiter.map(Delimiter::parse).transpose().map_err(value_error)?;
    let d = Dataset::read_csv(&path, map, used, delimiter).map_err(value_error)?.1;
    Ok((d, Some(path)))
}

/// The spec of a `Screw`, of a TOML path, or the built-in DKFZD4012 (`None`).
fn load_spec(spec: Option<&Bound<'_, PyAny>>) -> PyResult<ScrewSpec> {
    let Some(spec) = spec else {
        return config::builtin_spec().map_err(value_error);
    };
    if let Ok(screw) = spec.cast::<Screw>() {
        return Ok(*screw.borrow().spec());
    }
    let path: PathBuf =
        spec.extract().map_err(|_| value_error("spec: a ballscrew.Screw or the path of a TOML spec file"))?;
    config::spec_from_toml_file(&path).map_err(value_error)
}

/// Diagnoses measured drag torques against a screw spec.
///
/// `data`: a CSV path, or a dict of columns (`torque_nm` required; `preload_n`, `speed_rpm`
/// signed, `axial_load_n`, `position_mm`, `temperature_c`, `time_h`, `repeat` optional).
/// `spec`: a `Screw` or a TOML spec path (default: the built-in DKFZD4012). `columns`: a mapping
/// `{"time_h": "hours"}` taking a column from a differently named one. `delimiter`: of a CSV
/// file, `","`, `";"` or `"\t"` (or `"comma"`, `"semicolon"`, `"tab"`); found from the header
/// line when not given. Returns the report as `ballscrew diagnose --report` writes it (dicts,
/// lists, floats); bad input raises `ValueError` naming the row (in a file, its line) and the
/// column.
#[pyfunction]
#[pyo3(signature = (data, spec = None, columns = None, delimiter = None))]
pub fn diagnose<'py>(
    py: Python<'py>,
    data: &Bound<'py, PyAny>,
    spec: Option<&Bound<'_, PyAny>>,
    columns: Option<HashMap<String, String>>,
    delimiter: Option<&str>,
) -> PyResult<Bound<'py, PyAny>> {
    let map = column_map(columns)?;
    let (d, _) = dataset(data, &map, Use::Diagnosis, delimiter)?;
    let spec = load_spec(spec)?;
    let json = py
        .detach(|| core_diagnose::diagnose(&spec, &d).map(|r| serde_json::to_string(&r.to_json())))
        .map_err(value_error)?
        .map_err(value_error)?;
    py.import("json")?.call_method1("loads", (json,))
}

/// The model's drive torque, N m, for every row of `data` (a CSV path or a dict of columns, as
/// for `diagnose`, with its `delimiter`; the torque column is not needed): the spec's extension
/// terms included, with each row's position, temperature and running time. Returns a list of
/// floats; a row the model cannot evaluate raises `ValueError` naming it: `data row N` (from 1)
/// in a dict, `PATH: row N` (its line) in a file, as `ballscrew predict`.
#[pyfunction]
#[pyo3(signature = (data, spec = None, columns = None, delimiter = None))]
pub fn predict(
    py: Python<'_>,
    data: &Bound<'_, PyAny>,
    spec: Option<&Bound<'_, PyAny>>,
    columns: Option<HashMap<String, String>>,
    delimiter: Option<&str>,
) -> PyResult<Vec<f64>> {
    let map = column_map(columns)?;
    let (d, path) = dataset(data, &map, Use::Prediction, delimiter)?;
    let spec = load_spec(spec)?;
    let model = Model::new(&spec).map_err(value_error)?;
    py.detach(|| predict_rows(&model, &Rows::new(&d, &spec.operating))).map_err(|(row, e)| match &path {
        Some(p) => value_error(format!("{}: row {}: {e}", p.display(), d.row_number(row))),
        None => value_error(format!("data row {}: {e}", row + 1)),
    })
}
