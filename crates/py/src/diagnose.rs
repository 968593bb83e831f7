//! `ballscrew.diagnose(data, spec=None, columns=None, delimiter=None)`: the diagnosis of
//! measured torques from Python, returning the report of `ballscrew diagnose --report` as Python
//! dicts and lists; and `ballscrew.predict(...)`, the model's torque (extension terms of the spec
//! included) per row, as `ballscrew predict` gives it, with its warnings (unknown columns) as
//! Python warnings.
//!
//! Columns are read as [`crate::numbers`] reads every number argument. Ctrl-C ends both calls
//! within a fraction of a second ([`crate::interrupt`]): a prediction stops between two rows; a
//! diagnosis runs on a thread of its own while the calling thread watches for signals, and on
//! Ctrl-C its cancellation flag (`ballscrew_diagnose::diagnose_cancellable`) stops it within
//! about one evaluation of the model; the call returns once it has stopped.

use crate::batch::{self, BatchError, Stop};
use crate::errors::value_error;
use crate::interrupt;
use crate::numbers::{self, shown};
use crate::screw::{Screw, batch_error};
use ballscrew_config as config;
use ballscrew_core::{Model, ScrewSpec};
use ballscrew_diagnose::data::{Column, Dataset, Delimiter, Use};
use ballscrew_diagnose::model::Rows;
use ballscrew_diagnose::{self as core_diagnose};
use core::sync::atomic::{AtomicBool, Ordering};
use pyo3::exceptions::{PyRuntimeError, PyUserWarning};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use std::ffi::CString;
use std::path::PathBuf;

/// What a column of `data` may be, as error messages say it.
const COLUMN: &str = "a 1-d sequence of real numbers";

/// The `columns` mapping (column name -> source name, both texts) in the core's terms.
fn column_map(columns: Option<&Bound<'_, PyAny>>) -> PyResult<Vec<(Column, String)>> {
    let mut map: Vec<(Column, String)> = Vec::new();
    let Some(columns) = columns.filter(|c| !c.is_none()) else {
        return Ok(map);
    };
    let dict = columns
        .cast::<PyDict>()
        .map_err(|_| numbers::refusal("columns", &shown(columns), "a dict of column names to the data's names"))?;
    for (name, source) in dict.iter() {
        let text = |v: &Bound<'_, PyAny>| {
            v.cast::<PyString>()
                .map(|t| t.to_string())
                .map_err(|_| numbers::refusal("columns", &shown(v), "texts, e.g. {\"time_h\": \"hours\"}"))
        };
        let c = Column::parse(&text(&name)?).map_err(|e| value_error(format!("invalid columns: {e}")))?;
        map.push((c, text(&source)?));
    }
    map.sort_by_key(|(c, _)| *c);
    Ok(map)
}

/// Reads the data for `used`: a dict of columns (name -> 1-d sequence of real numbers) or a CSV
/// path (read with `delimiter`: `","`, `";"`, `"\t"` or their names, found from the header when
/// `None`); the text that names it in warnings, and the path of a file.
fn dataset(
    data: &Bound<'_, PyAny>,
    map: &[(Column, String)],
    used: Use,
    delimiter: Option<&str>,
) -> PyResult<(Dataset, String, Option<PathBuf>)> {
    if let Ok(dict) = data.cast::<PyDict>() {
        if delimiter.is_some() {
            return Err(value_error("delimiter: only for a CSV path, not a dict of columns"));
        }
        let mut named = Vec::new();
        for (k, v) in dict.iter() {
            let name: String = k.extract().map_err(|_| value_error("data: column names must be strings"))?;
            let label = format!("data column {name:?}");
            let values = numbers::reals(&label, &v, COLUMN)?;
            if values.shape().len() != 1 {
                return Err(numbers::refusal(&label, &shown(&v), COLUMN));
            }
            named.push((name, values.view().iter().copied().collect()));
        }
        return Ok((Dataset::parse_columns(named, map, used).map_err(value_error)?, "data".to_string(), None));
    }
    let path: PathBuf = data.extract().map_err(|_| value_error("data: a CSV path or a dict of columns"))?;
    let delimiter = delimiter.map(Delimiter::parse).transpose().map_err(value_error)?;
    let d = Dataset::read_csv(&path, map, used, delimiter).map_err(value_error)?.1;
    Ok((d, path.display().to_string(), Some(path)))
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
/// `data`: a CSV path, or a dict of columns, each a 1-d sequence of real numbers (`torque_nm`
/// required; `preload_n`, `speed_rpm` signed, `axial_load_n`, `position_mm`, `temperature_c`,
/// `time_h`, `repeat` optional; bools, datetimes, texts, None and masked arrays are refused).
/// `spec`: a `Screw` or a TOML spec path (default: the built-in DKFZD4012). `columns`: a mapping
/// `{"time_h": "hours"}` taking a column from a differently named one. `delimiter`: of a CSV
/// file, `","`, `";"` or `"\t"` (or `"comma"`, `"semicolon"`, `"tab"`); found from the header
/// line when not given. Returns the report as `ballscrew diagnose --report` writes it (dicts,
/// lists, floats); bad input raises `ValueError` naming the row (in a file, its line) and the
/// column. Ctrl-C raises `KeyboardInterrupt` within a fraction of a second, the diagnosis
/// stopped (nothing keeps computing after the call).
#[pyfunction]
#[pyo3(signature = (data, spec = None, columns = None, delimiter = None))]
pub fn diagnose<'py>(
    py: Python<'py>,
    data: &Bound<'py, PyAny>,
    spec: Option<&Bound<'_, PyAny>>,
    columns: Option<&Bound<'_, PyAny>>,
    delimiter: Option<&str>,
) -> PyResult<Bound<'py, PyAny>> {
    let map = column_map(columns)?;
    let (d, _, _) = dataset(data, &map, Use::Diagnosis, delimiter)?;
    let spec = load_spec(spec)?;
    let run = |cancel: &AtomicBool| {
        core_diagnose::diagnose_cancellable(&spec, &d, cancel)
            .map_err(|e| e.to_string())
            .and_then(|r| serde_json::to_string(&r.to_json()).map_err(|e| e.to_string()))
    };
    let cancel = AtomicBool::new(false);
    let json = interrupt::detach(py, |watch| {
        // On a thread of its own, so that this one can watch for signals; on Ctrl-C the flag
        // stops the diagnosis within about one evaluation of the model, and the call returns
        // when it has stopped (nothing is left running).
        std::thread::scope(|scope| {
            let worker = std::thread::Builder::new().spawn_scoped(scope, || run(&cancel));
            let Ok(worker) = worker else {
                return Some(run(&cancel));
            };
            while !worker.is_finished() {
                if watch.stop() {
                    cancel.store(true, Ordering::Relaxed);
                    break;
                }
                std::thread::sleep(batch::WAIT);
            }
            // A panic of the diagnosis (a bug) is reported, not propagated through Python.
            worker.join().ok()
        })
    })?
    .ok_or_else(|| PyRuntimeError::new_err("the diagnosis thread ended abnormally"))?
    .map_err(value_error)?;
    py.import("json")?.call_method1("loads", (json,))
}

/// The model's drive torque, N m, for every row of `data` (a CSV path or a dict of columns, as
/// for `diagnose`, with its `delimiter`; the torque column is not needed): the spec's extension
/// terms included, with each row's position, temperature and running time, each row
/// warm-started from the one before (as `ballscrew predict`). Returns a list of floats; a row the
/// model cannot evaluate raises `ValueError` naming it: `data row N` (from 1) in a dict,
/// `PATH: row N` (its line) in a file, as `ballscrew predict`. Columns it does not use give a
/// `UserWarning` naming them (the command line warns on stderr). Ctrl-C stops it between two
/// rows (KeyboardInterrupt).
#[pyfunction]
#[pyo3(signature = (data, spec = None, columns = None, delimiter = None))]
pub fn predict(
    py: Python<'_>,
    data: &Bound<'_, PyAny>,
    spec: Option<&Bound<'_, PyAny>>,
    columns: Option<&Bound<'_, PyAny>>,
    delimiter: Option<&str>,
) -> PyResult<Vec<f64>> {
    let map = column_map(columns)?;
    let (d, origin, path) = dataset(data, &map, Use::Prediction, delimiter)?;
    for w in &d.warnings {
        let text = CString::new(format!("{origin}: {w}").replace('\0', "\\0")).map_err(value_error)?;
        PyErr::warn(py, &py.get_type::<PyUserWarning>(), &text, 1)?;
    }
    let spec = load_spec(spec)?;
    let model = Model::new(&spec).map_err(value_error)?;
    let rows = Rows::new(&d, &spec.operating);
    let points: Vec<_> = rows.op.into_iter().zip(rows.cond).collect();
    // One thread: every row warm-started from the one before, as the command line's prediction.
    interrupt::detach(py, |watch| {
        batch::map_points(&model, &points, 1, watch, |m, (op, cond), state| m.torque_at(op, cond, state))
    })?
    .map_err(|e| match e {
        BatchError::Point { index, error } => match &path {
            Some(p) => value_error(format!("{}: row {}: {error}", p.display(), d.row_number(index))),
            None => value_error(format!("data row {}: {error}", index + 1)),
        },
        other => batch_error(&other, &[], &[]),
    })
}
