//! `ballscrew.diagnose(data, spec=None, columns=None, delimiter=None)`: the diagnosis of
//! measured torques from Python, returning the report of `ballscrew diagnose --report` as Python
//! dicts and lists, its tables of numbers as numpy arrays, with the torques per data row beside
//! it (a DataFrame on the data's index for a DataFrame); and `ballscrew.predict(...)`, the model's torque (extension terms of the spec
//! included) per row, as `ballscrew predict` gives it, with its warnings (unknown columns) as
//! Python warnings.
//!
//! Columns are read as [`crate::numbers`] reads every number argument. Ctrl-C ends both calls
//! within a fraction of a second ([`crate::interrupt`]): a prediction stops between two rows; a
//! diagnosis runs on a thread of its own while the calling thread watches for signals, and on
//! Ctrl-C its cancellation flag (`ballscrew_diagnose::diagnose_cancellable`) stops it within
//! about one evaluation of the model; the call returns once it has stopped.

use crate::batch::{self, BatchError, Stop};
use crate::errors::{parse_errors, read_text, report_failures, value_error, warn_quasi_static};
use crate::interrupt;
use crate::numbers::{self, shown};
use crate::screw::{Screw, batch_error};
use ballscrew_config as config;
use ballscrew_core::{Model, ScrewSpec};
use ballscrew_diagnose::data::{Column, DataError, Dataset, Delimiter, Table, Use};
use ballscrew_diagnose::model::{Rows, predict_rows, temperature_note};
use ballscrew_diagnose::{self as core_diagnose};
use core::sync::atomic::{AtomicBool, Ordering};
use numpy::PyArray1;
use pyo3::exceptions::{PyRuntimeError, PyUserWarning};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyInt, PyList, PyString};
extern crate alloc;
use alloc::ffi::CString;
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

/// Where the data came from: a file (its path), or a table in memory (a pandas DataFrame is
/// kept to index the prediction as it is).
enum Source<'py> {
    File(PathBuf),
    Columns,
    Frame(Bound<'py, PyAny>),
}

/// Named columns, and whether they came from a DataFrame.
type TableColumns<'py> = (Vec<(String, Bound<'py, PyAny>)>, bool);

/// The named columns of a table in memory: a dict of columns, a pandas (or any) DataFrame (an
/// object with `columns` whose items `data[name]` are columns), or a numpy structured array
/// (`dtype.names`); `None` for anything else.
fn table_columns<'py>(data: &Bound<'py, PyAny>) -> PyResult<Option<TableColumns<'py>>> {
    if let Ok(dict) = data.cast::<PyDict>() {
        let mut out = Vec::new();
        for (k, v) in dict.iter() {
            let name: String = k.extract().map_err(|_| value_error("data: column names must be strings"))?;
            out.push((name, v));
        }
        return Ok(Some((out, false)));
    }
    let names = if data.hasattr("columns")? && data.hasattr("__getitem__")? && !data.is_instance_of::<PyString>() {
        Some((data.getattr("columns")?, true))
    } else if data.hasattr("dtype")? {
        let names = data.getattr("dtype")?.getattr("names")?;
        (!names.is_none()).then_some((names, false))
    } else {
        None
    };
    let Some((names, frame)) = names else { return Ok(None) };
    let mut out = Vec::new();
    for k in names.try_iter()? {
        let k = k?;
        let name: String = k
            .extract()
            .map_err(|_| value_error(format!("data: column names must be strings (found {})", shown(&k))))?;
        let column = data.get_item(&k)?;
        // A pandas column (a Series) as its numpy values.
        let column = if column.hasattr("to_numpy")? { column.call_method0("to_numpy")? } else { column };
        out.push((name, column));
    }
    Ok(Some((out, frame)))
}

/// Reads the data for `used`: a table in memory ([`table_columns`]: names -> 1-d sequences of
/// real numbers) or a CSV path (read with `delimiter`: `","`, `";"`, `"\t"` or their names, found
/// from the header when `None`); the text that names it in warnings, and where it came from.
fn dataset<'py>(
    data: &Bound<'py, PyAny>,
    map: &[(Column, String)],
    used: Use,
    delimiter: Option<&str>,
) -> PyResult<(Dataset, String, Source<'py>)> {
    if let Some((columns, frame)) = table_columns(data)? {
        if delimiter.is_some() {
            return Err(value_error("delimiter: only for a CSV path, not a table of columns"));
        }
        let mut named = Vec::new();
        for (name, v) in columns {
            let label = format!("data column {name:?}");
            let values = numbers::reals(&label, &v, COLUMN)?;
            if values.shape().len() != 1 {
                return Err(numbers::refusal(&label, &shown(&v), COLUMN));
            }
            named.push((name, values.view().iter().copied().collect()));
        }
        let d = Dataset::parse_columns(named, map, used).map_err(value_error)?;
        let source = if frame { Source::Frame(data.clone()) } else { Source::Columns };
        return Ok((d, "data".to_string(), source));
    }
    let path: PathBuf = data.extract().map_err(|_| {
        value_error(format!(
            "invalid data: {} (valid: a CSV path, a dict of columns, a DataFrame or a numpy structured array)",
            shown(data)
        ))
    })?;
    let delimiter = delimiter.map(Delimiter::parse).transpose().map_err(value_error)?;
    let text = read_text(&path, "data file")?;
    let in_file = |e: DataError| value_error(format!("{}: {e}", path.display()));
    let table = Table::parse(&text, delimiter).map_err(in_file)?;
    let d = Dataset::from_table(&table, map, used).map_err(in_file)?;
    Ok((d, path.display().to_string(), Source::File(path)))
}

/// The spec of a `Screw`, of a TOML path, or the built-in DKFZD4012 (`None`).
fn load_spec(spec: Option<&Bound<'_, PyAny>>) -> PyResult<ScrewSpec> {
    let Some(spec) = spec.filter(|s| !s.is_none()) else {
        return config::builtin_spec().map_err(value_error);
    };
    if let Ok(screw) = spec.cast::<Screw>() {
        return Ok(*screw.borrow().spec());
    }
    let path: PathBuf = spec.extract().map_err(|_| {
        value_error(format!("invalid spec: {} (valid: a ballscrew.Screw or the path of a TOML spec file)", shown(spec)))
    })?;
    let text = read_text(&path, "spec file")?;
    config::spec_from_toml_str(&text, &path.display().to_string()).map_err(value_error)
}

/// Diagnoses measured drag torques against a screw spec.
///
/// `data`: a CSV path, or a dict of columns, each a 1-d sequence of real numbers (`torque_nm`
/// required; `preload_n`, `speed_rpm` signed, `axial_load_n`, `position_mm`, `temperature_c`,
/// `time_h`, `repeat` optional; bools, datetimes, texts, None and masked arrays are refused).
/// `spec`: a `Screw` or a TOML spec path (default: the built-in DKFZD4012). `columns`: a mapping
/// `{"time_h": "hours"}` taking a column from a differently named one. `delimiter`: of a CSV
/// file, `","`, `";"` or `"\t"` (or `"comma"`, `"semicolon"`, `"tab"`); found from the header
/// line when not given. Returns the report as `ballscrew diagnose --report` writes it, its keys
/// and values: dicts, lists of records (`findings`, `candidates`, `steps`, `calibration`,
/// `residuals`), floats, ints, texts and None, and its tables of numbers as one 1-d numpy array
/// per column (float64; int64 for counts and harmonics): each residual's `bins` (`from`, `to`,
/// `mean_residual_nm`, `rows`) and the `position_periodogram` (`harmonic`,
/// `baseline_amplitude_nm`, `extended_amplitude_nm`). Beside the report's keys, `row_torques`:
/// one row per data row, in the data's order, of `measured_torque_nm`, `spec_model_torque_nm`,
/// `calibrated_torque_nm` and `extended_torque_nm` (the model as specified, calibrated, and
/// extended by the findings, all rows; what `--plots` draws): a dict of float64 arrays, or for a
/// pandas DataFrame a DataFrame on the frame's index. Bad input raises `ValueError` naming the row (in a file, its line) and the
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
    let (d, _, source) = dataset(data, &map, Use::Diagnosis, delimiter)?;
    let spec = load_spec(spec)?;
    let run = |cancel: &AtomicBool| {
        core_diagnose::diagnose_cancellable(&spec, &d, cancel).map_err(|e| e.to_string()).and_then(|r| {
            let json = serde_json::to_string(&r.to_json()).map_err(|e| e.to_string())?;
            Ok((json, r.series))
        })
    };
    let cancel = AtomicBool::new(false);
    let (json, series) = interrupt::detach(py, |watch| {
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
    let report = py.import("json")?.call_method1("loads", (json,))?.cast_into::<PyDict>()?;
    // The tables of numbers, one array per column.
    if let Some(residuals) = report.get_item("residuals")? {
        for residual in residuals.try_iter()? {
            let residual = residual?;
            let bins = columns_of_records(py, &residual.get_item("bins")?)?;
            residual.set_item("bins", bins)?;
        }
    }
    if let Some(pg) = report.get_item("position_periodogram")?.filter(|p| !p.is_none()) {
        let pg = pg.cast_into::<PyDict>()?;
        for (key, values) in pg.iter() {
            pg.set_item(key, number_array(py, &values)?)?;
        }
    }
    let rows = PyDict::new(py);
    for (key, values) in [
        ("measured_torque_nm", series.measured),
        ("spec_model_torque_nm", series.spec_model),
        ("calibrated_torque_nm", series.baseline),
        ("extended_torque_nm", series.extended),
    ] {
        rows.set_item(key, PyArray1::from_vec(py, values))?;
    }
    let rows = match source {
        Source::Frame(frame) if is_pandas_frame(py, &frame)? => {
            let kwargs = PyDict::new(py);
            kwargs.set_item("index", frame.getattr("index")?)?;
            py.import("pandas")?.getattr("DataFrame")?.call((rows,), Some(&kwargs))?
        }
        _ => rows.into_any(),
    };
    report.set_item("row_torques", rows)?;
    Ok(report.into_any())
}

/// A list of records with the same keys (`[{"from": 0.0, "rows": 3}, ...]`) as a dict of
/// columns, each a numpy array ([`number_array`]), in the keys' order.
fn columns_of_records<'py>(py: Python<'py>, records: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
    let columns = PyDict::new(py);
    let records: Vec<Bound<'py, PyAny>> = records.try_iter()?.collect::<PyResult<_>>()?;
    let Some(first) = records.first() else { return Ok(columns) };
    for key in first.cast::<PyDict>()?.keys() {
        let values = records.iter().map(|r| r.get_item(&key)).collect::<PyResult<Vec<_>>>()?;
        columns.set_item(&key, number_array(py, PyList::new(py, values)?.as_any())?)?;
    }
    Ok(columns)
}

/// A JSON column of numbers as a 1-d numpy array: int64 when there are values and every one
/// is an int (counts, harmonics), else float64 (a null, which JSON writes for NaN, as NaN).
fn number_array<'py>(py: Python<'py>, values: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    let values: Vec<Bound<'py, PyAny>> = values.try_iter()?.collect::<PyResult<_>>()?;
    let ints = !values.is_empty() && values.iter().all(|v| v.is_exact_instance_of::<PyInt>());
    let dtype = if ints { "int64" } else { "float64" };
    py.import("numpy")?.call_method1("asarray", (PyList::new(py, values)?, dtype))
}

/// The model's drive torque, N m, for every row of `data` (a CSV path, a dict of columns, a
/// pandas DataFrame or a numpy structured array, as for `diagnose`, with its `delimiter` for a
/// CSV path; the torque column is not needed): the spec's extension terms included, with each
/// row's position, temperature and running time, as `ballscrew predict` computes it (each row's
/// canonical state, the model's cold solve over the machine's cores: the same bits as
/// `Screw.torque` at the row's point). Returns a float64 numpy array, or for a pandas DataFrame a Series
/// `torque_nm` on the frame's index. A row the model cannot evaluate raises `ValueError` naming
/// it: `data row N` (from 1) in a table, `PATH: row N` (its line) in a file, as `ballscrew
/// predict`; with `errors="nan"` it gives NaN instead and the others are computed (a
/// `RuntimeWarning` says how many and why the first failed). Columns it does not use give a
/// `UserWarning` naming them (the command line warns on stderr), and so does a `temperature_c`
/// column under the lubricated model (it is not the oil's temperature: the oil at the contacts
/// stays at the spec's `lubricant.temperature_c`). Rows where the balls' inertia is not small
/// give one `QuasiStaticWarning`, the command line's text. Ctrl-C stops it between two rows
/// (KeyboardInterrupt).
#[pyfunction]
#[pyo3(signature = (data, spec = None, columns = None, delimiter = None, *, errors = "raise"))]
pub fn predict<'py>(
    py: Python<'py>,
    data: &Bound<'py, PyAny>,
    spec: Option<&Bound<'_, PyAny>>,
    columns: Option<&Bound<'_, PyAny>>,
    delimiter: Option<&str>,
    errors: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let policy = parse_errors(errors)?;
    let map = column_map(columns)?;
    let (d, origin, source) = dataset(data, &map, Use::Prediction, delimiter)?;
    // A note on the data, as a `UserWarning` naming where the data came from.
    let warn = |what: &str| -> PyResult<()> {
        let text = CString::new(format!("{origin}: {what}").replace('\0', "\\0")).map_err(value_error)?;
        PyErr::warn(py, &py.get_type::<PyUserWarning>(), &text, 1)
    };
    for w in &d.warnings {
        warn(w)?;
    }
    let spec = load_spec(spec)?;
    if let Some(note) = temperature_note(&spec, &d) {
        warn(&note)?;
    }
    let model = Model::new(&spec).map_err(value_error)?;
    let rows = Rows::new(&d, &spec.operating);
    warn_quasi_static(py, &spec, rows.op.iter().copied())?;
    let row_name = |index: usize| match &source {
        Source::File(p) => format!("{}: row {}", p.display(), d.row_number(index)),
        _ => format!("data row {}", index + 1),
    };
    // As the command line's prediction: the evaluator over the cores, bands of speed.
    let out = interrupt::detach(py, |watch| predict_rows(&model, &rows, watch, policy))?;
    let values = match out {
        Ok(v) => v,
        Err(BatchError::Point { index, error }) => return Err(value_error(format!("{}: {error}", row_name(index)))),
        Err(other) => return Err(batch_error(&other, &[], &[])),
    };
    let torques = report_failures(py, values, "row", |index, error| format!("{}: {error}", row_name(index)))?;
    let array = PyArray1::from_vec(py, torques).into_any();
    match source {
        Source::Frame(frame) if is_pandas_frame(py, &frame)? => {
            let pd = py.import("pandas")?;
            let kwargs = PyDict::new(py);
            kwargs.set_item("index", frame.getattr("index")?)?;
            kwargs.set_item("name", "torque_nm")?;
            pd.getattr("Series")?.call((array,), Some(&kwargs))
        }
        _ => Ok(array),
    }
}

/// Whether `obj` is a pandas DataFrame (pandas imported by whoever made it).
fn is_pandas_frame(py: Python<'_>, obj: &Bound<'_, PyAny>) -> PyResult<bool> {
    let modules = py.import("sys")?.getattr("modules")?;
    match modules.get_item("pandas") {
        Ok(pd) => obj.is_instance(&pd.getattr("DataFrame")?),
        Err(_) => Ok(false),
    }
}
