//! `ballscrew.Screw`: a validated screw spec and its model, evaluated from Python.
//!
//! - `torque` over floats or numpy arrays (broadcast), the batch in Rust over every core with
//!   the GIL released ([`crate::batch`]);
//! - `sweep`: the command line's sweep over the preload, the speed, the axial load or the oil
//!   temperature at the contacts as columns (numpy arrays, or a pandas DataFrame when pandas is installed);
//! - `band`, `sweep(band=True)` and `sensitivity`: the band of the drag torque that the spread of
//!   the spec's `[uncertainty]` gives, and each uncertain input's part in it ([`crate::band`]);
//! - `with_oil_temperature`: the same screw with the oil at another temperature (the spec's
//!   `lubricant.temperature_c`, the command line's `--oil-temperature-c`);
//! - `summary` and `inspect`: one operating point as the command line's `torque` and `inspect`
//!   report it (cold start, so even the iteration counts are the command line's);
//! - read-only properties of the spec, units in their names (the lubricant as a dict of its
//!   spec-file keys);
//! - pickling (`__reduce__`, also `copy.copy` and `copy.deepcopy`): the spec as TOML text, the
//!   origin, and the SI value of each spec value the TOML text gives through a unit conversion
//!   (`EXACT`), so that the copy's spec is the original's bit for bit, whatever made it
//!   (a file, `with_oil_temperature`); checked when pickled.
//!
//! Every evaluation of a `Screw` is stateless: `torque` (scalar or arrays), `sweep`, `summary`
//! and `inspect` report each point's canonical state, the model's cold solve, the numbers the
//! command line gives to the bit, whatever was asked before and on any number of threads. A
//! loop that follows a history (a drive cycle, a control loop) takes `ballscrew.Evaluator`,
//! which warm-starts from its last point.

use crate::band;
use crate::batch::Errors;
use crate::batch::{self, Batch, BatchError, Start};
use crate::errors::{
    core_error, parse_errors, read_text, report_failures, room_for, value_error, warn_failures, warn_quasi_static,
};
use crate::interrupt;
use crate::numbers::{NUMBERS, index_text, real_number, reals, shown as numbers_shown, tuple_text};
use crate::points::{self, Args, Points};
use crate::records;
use ballscrew_batch::quantities::{
    BALL, BALL_ID, BAND, CONTACT, CONTACT_ID, EFFICIENCY, POINT, Quantity, SENSITIVITY, SWEEP, SWEPT,
    SWEPT_OIL_TEMPERATURE, SWEPT_PRELOAD, Value, by_key, held,
};
use ballscrew_batch::sweep::{RowError, SweepPoint, SweepRow, sweep, sweep_row};
use ballscrew_batch::threads_for;
use ballscrew_batch::uncertainty::{self, Band, BandError, BandSettings};
use ballscrew_config::{self as config, ConfigError};
use ballscrew_core::input::lubricant::m2_s_to_mm2_s;
use ballscrew_core::input::{Lubrication, MAX_NUTS, UNCERTAIN_INPUTS, rad_s_to_rpm};
use ballscrew_core::{Error, Evaluator, Measured, Model, OperatingPoint, ScrewSpec, Shown, SolverState, ValidRange};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::{PyKeyboardInterrupt, PyRuntimeError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple, PyType};
use std::path::PathBuf;
use std::sync::OnceLock;

// The built-in spec's name, the largest sweep and the default sweep are the command line's
// (larger studies than a sweep go through `torque` over arrays).
use ballscrew_batch::sweep::{MAX_SWEEP_POINTS, default_sweep_preloads_n};
use ballscrew_config::BUILTIN_ORIGIN;

/// A ball screw: a validated spec and its model.
///
/// Make one with `Screw.dkfzd4012()`, `Screw.from_toml(path)` or `Screw.from_toml_str(text)`.
/// Speeds are in rpm, loads in N, torques in N m; every name carries its unit. Invalid specs and
/// inputs raise ValueError with the field, the value and the valid range; anything but real
/// numbers (bools, complex numbers, datetimes, texts, None, masked arrays) raises ValueError
/// naming the argument.
#[pyclass(frozen, module = "ballscrew")]
pub struct Screw {
    model: Model,
    origin: String,
    /// The control-loop evaluator of array `torque` calls with `start="warm"`, built by the
    /// first such batch large enough to pay for it ([`batch::EVALUATOR_MIN_POINTS`]) and kept;
    /// `None` inside where the evaluator does not apply to the model (FASTSIM, oversize balls).
    evaluator: OnceLock<Option<Box<Evaluator<f64>>>>,
}

impl Screw {
    /// The evaluator for a warm batch of `points` points: the one built before, else built now
    /// when the batch is large enough to pay for it (see [`Screw::evaluator`]'s field).
    fn evaluator(&self, points: usize) -> Option<&Evaluator<f64>> {
        if let Some(ev) = self.evaluator.get() {
            return ev.as_deref();
        }
        if points < batch::EVALUATOR_MIN_POINTS {
            return None;
        }
        self.evaluator.get_or_init(|| Evaluator::new(&self.model).ok().map(Box::new)).as_deref()
    }

    fn new(spec: &ScrewSpec, origin: String) -> PyResult<Self> {
        let model = Model::new(spec).map_err(|e| value_error(format!("{origin}: {e}")))?;
        Ok(Self { model, origin, evaluator: OnceLock::new() })
    }

    fn from_config(result: Result<ScrewSpec, ConfigError>, origin: String) -> PyResult<Self> {
        match result {
            Ok(spec) => Self::new(&spec, origin),
            // Parse and I/O errors carry the origin already.
            Err(e @ (ConfigError::Parse { .. } | ConfigError::Io { .. })) => Err(value_error(e)),
            Err(e) => Err(value_error(format!("{origin}: {e}"))),
        }
    }

    pub(crate) fn spec(&self) -> &ScrewSpec {
        self.model.spec()
    }

    /// Where the spec came from (see the `origin` property).
    pub(crate) fn origin_text(&self) -> &str {
        &self.origin
    }

    /// A screw of `spec` (validated) from `origin`, for the copies of the other classes.
    pub(crate) fn of_spec(spec: &ScrewSpec, origin: String) -> PyResult<Self> {
        Self::new(spec, origin)
    }

    /// The model (for evaluators built from it).
    pub(crate) fn model(&self) -> &Model {
        &self.model
    }

    /// Exactly one operating point from the arguments (defaults: the spec's).
    fn one_point(&self, args: &Args<'_, '_>) -> PyResult<OperatingPoint> {
        points::one_point(args, &self.spec().operating)
    }

    /// The model with the oil at `temperature_c` (degrees C) at the contacts, the spec's
    /// `lubricant.temperature_c` changed; `ValueError` naming `oil_temperature_c` under the dry
    /// model (it has no oil) and out of range (`at` says where in an array).
    fn model_at(&self, temperature_c: f64, at: &str) -> PyResult<Model> {
        let mut spec = *self.spec();
        if spec.model.lubrication == Lubrication::Dry {
            return Err(value_error(format!(
                "invalid oil_temperature_c: {}{at} (valid: none under the dry model: the spec has lubrication = \"dry\", \
                 which has no oil; set [model] lubrication = \"ehl\")",
                Measured { value: temperature_c, field: "oil_temperature_c", valid: "" }
            )));
        }
        spec.lubricant.temperature_c = temperature_c;
        Model::new(&spec).map_err(|e| match e {
            Error::Input(i) if i.field == "lubricant.temperature_c" => value_error(format!(
                "invalid oil_temperature_c: {}{at} (valid: {})",
                Measured { value: temperature_c, field: "oil_temperature_c", valid: i.valid },
                ValidRange(i.valid)
            )),
            e => value_error(format!("{}: {e}", self.origin)),
        })
    }

    /// The oil-temperature sweep of [`Screw::sweep`]: the row at each temperature, each solved
    /// cold, and the model at each; the preload, speed and axial load one
    /// number each (or `None`: the spec's).
    #[allow(clippy::too_many_arguments)]
    fn sweep_oil_temperature<'py>(
        &self,
        py: Python<'py>,
        shape: &[usize],
        temps: Vec<f64>,
        preload_n: Option<&Bound<'py, PyAny>>,
        speed: &Option<Bound<'py, PyAny>>,
        axial: &Option<Bound<'py, PyAny>>,
        errors: Errors,
    ) -> PyResult<(Vec<SweepRow>, Vec<bool>, Vec<Model>)> {
        check_sweep_shape("oil_temperature_c", "oil temperatures", shape, temps.len())?;
        let args = Args { preload_n, speed_rpm: speed.as_ref(), axial_load_n: axial.as_ref() };
        let op = self.one_point(&args)?;
        let mut models = Vec::with_capacity(temps.len());
        for (i, &t) in temps.iter().enumerate() {
            let at = format!(" at index {} of oil_temperature_c", index_text(i, shape));
            models.push(self.model_at(t, &at)?);
        }
        let at = |index: usize| {
            let t = temps.get(index).copied().unwrap_or(f64::NAN);
            format!(
                "{}, oil_temperature_c {} (index {} of oil_temperature_c)",
                describe(&op),
                Shown(t),
                index_text(index, shape)
            )
        };
        let points: Vec<SweepPoint<'_>> = models.iter().map(|model| SweepPoint { op, model }).collect();
        let results =
            interrupt::detach(py, |watch| sweep(&points, threads_for(points.len()), watch, errors, &mut |_, _| {}))?
                .map_err(BatchError::from)
                .map_err(|e| match e {
                    BatchError::Point { index, error } => core_error(&error, &at(index)),
                    e => batch_error(&e, &[], shape),
                })?;
        let (rows, failed) = sweep_rows(py, results, &points, |i, e| format!("{e} {}", at(i)))?;
        Ok((rows, failed, models))
    }

    /// The band at each row of a sweep (`models`: the rows' model, one for all or one per row),
    /// NaN at the rows marked in `failed`; a point's band does not depend on the other points.
    fn sweep_band(
        &self,
        py: Python<'_>,
        rows: &[SweepRow],
        failed: &[bool],
        models: &[Model],
        settings: &BandSettings,
    ) -> PyResult<Vec<Band>> {
        let nan = Band::at(f64::NAN);
        let kept: Vec<usize> = (0..rows.len()).filter(|&i| failed.get(i) != Some(&true)).collect();
        let mut points = Vec::with_capacity(kept.len());
        for &i in &kept {
            let model = models.get(i).or(models.last()).ok_or_else(|| value_error("a sweep without a model"))?;
            points.push(SweepPoint { op: rows[i].summary.operating, model });
        }
        band::check_room(points.len(), settings.samples)?;
        let bands = interrupt::detach(py, |watch| {
            let batch = Batch::new(points.len().max(settings.samples as usize)).stop(watch);
            uncertainty::band(&batch, &points, settings).map_err(Box::new)
        })?
        .map_err(|e| {
            band::band_error(&e, |k| {
                let i = kept.get(k).copied().unwrap_or(k);
                let op = rows.get(i).map(|r| describe(&r.summary.operating)).unwrap_or_default();
                format!("{op} (row {i} of the sweep)")
            })
        })?;
        let mut out = vec![nan; rows.len()];
        for (&i, b) in kept.iter().zip(bands) {
            out[i] = b;
        }
        Ok(out)
    }

    /// The torque at `op`: its canonical state (the model's cold solve).
    fn torque_core(&self, py: Python<'_>, op: &OperatingPoint) -> Result<f64, Error> {
        py.detach(|| self.model.torque(op, &mut SolverState::new()))
    }
}

/// `at speed_rpm 100, preload_n 2000, axial_load_n 0` (numbers in short form: `1e-300`).
pub(crate) fn describe(op: &OperatingPoint) -> String {
    format!(
        "at speed_rpm {}, preload_n {}, axial_load_n {}",
        Shown(rad_s_to_rpm(op.speed_rad_s)),
        Shown(op.preload_n),
        Shown(op.axial_load_n)
    )
}

/// A batch failure as a Python exception naming the point.
pub(crate) fn batch_error(e: &BatchError, ops: &[OperatingPoint], shape: &[usize]) -> PyErr {
    match e {
        BatchError::Point { index, error } => {
            let op = ops.get(*index).map(describe).unwrap_or_default();
            core_error(error, &format!("{op} (index {} of the operating points)", index_text(*index, shape)))
        }
        BatchError::Internal(m) => pyo3::exceptions::PyRuntimeError::new_err(m.clone()),
        // The Python side stops a batch only with the exception of a signal handler at hand
        // (`interrupt::detach` returns that one); this is for a stop without it.
        BatchError::Stopped => PyKeyboardInterrupt::new_err("the batch was interrupted"),
        BatchError::OutOfMemory { .. } => pyo3::exceptions::PyMemoryError::new_err(e.to_string()),
    }
}

/// A TOML value of the spec as a Python object (tables as dicts, arrays as lists).
fn toml_to_py<'py>(py: Python<'py>, value: &toml::Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        toml::Value::Float(x) => x.into_pyobject(py)?.into_any(),
        toml::Value::Integer(n) => n.into_pyobject(py)?.into_any(),
        toml::Value::Boolean(b) => PyBool::new(py, *b).to_owned().into_any(),
        toml::Value::String(t) => t.into_pyobject(py)?.into_any(),
        toml::Value::Datetime(t) => t.to_string().into_pyobject(py)?.into_any(),
        toml::Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(toml_to_py(py, item)?)?;
            }
            list.into_any()
        }
        toml::Value::Table(table) => {
            let d = PyDict::new(py);
            for (k, v) in table {
                d.set_item(k, toml_to_py(py, v)?)?;
            }
            d.into_any()
        }
    })
}

/// `ValueError` unless `shape` is that of a sweep: 1-d, 1 to [`MAX_SWEEP_POINTS`] `what`.
fn check_sweep_shape(name: &str, what: &str, shape: &[usize], n: usize) -> PyResult<()> {
    if shape.len() != 1 || n == 0 || n > MAX_SWEEP_POINTS {
        let shape = tuple_text(shape);
        return Err(value_error(format!(
            "invalid {name}: shape {shape} (valid: a 1-d array of 1 to {MAX_SWEEP_POINTS} {what}, as `ballscrew sweep`)"
        )));
    }
    Ok(())
}

/// `a and b`, `a, b and c`: names in a message.
fn and_list(names: &[&str]) -> String {
    match names.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        Some((last, _)) => (*last).to_string(),
        None => String::new(),
    }
}

/// The quantity a sweep runs over whose key is `key` (one of [`SWEPT`]).
fn swept_quantity(key: &str) -> PyResult<&'static Quantity<SweepRow>> {
    SWEPT.iter().copied().find(|q| q.key == key).ok_or_else(|| value_error(format!("no {key} column")))
}

/// The rows of a sweep run under `errors` (each failed point its [`SweepRow::failed`] at `points[i]`),
/// which failed, and the `EvaluationWarning` when any did (`describe` names a failed point).
fn sweep_rows(
    py: Python<'_>,
    results: Vec<Result<SweepRow, RowError>>,
    points: &[SweepPoint<'_>],
    describe: impl Fn(usize, &Error) -> String,
) -> PyResult<(Vec<SweepRow>, Vec<bool>)> {
    let total = results.len();
    let mut first = None;
    let mut failed = Vec::with_capacity(total);
    let mut rows = Vec::with_capacity(total);
    for (i, r) in results.into_iter().enumerate() {
        match r {
            Ok(row) => {
                rows.push(row);
                failed.push(false);
            }
            Err(e) => {
                rows.push(SweepRow::failed(&points[i]));
                failed.push(true);
                first.get_or_insert((i, e));
            }
        }
    }
    if let Some((index, error)) = first {
        let count = failed.iter().filter(|f| **f).count();
        warn_failures(py, count, total, "point", index, &describe(index, error.error()))?;
    }
    Ok((rows, failed))
}

/// One sweep column of `view` of each row as a numpy array (integers for counts, floats
/// otherwise); the rows marked in `failed` (points the model could not evaluate, under
/// `errors="nan"`) NaN, which makes a count column float.
fn column<'py, R, T>(
    py: Python<'py>,
    get: fn(&T) -> Value,
    rows: &[R],
    view: fn(&R) -> &T,
    failed: &[bool],
) -> PyResult<Bound<'py, PyAny>> {
    let values: Vec<Value> = rows
        .iter()
        .enumerate()
        .map(|(i, r)| if failed.get(i) == Some(&true) { Value::Num(f64::NAN) } else { get(view(r)) })
        .collect();
    if values.iter().all(|v| matches!(v, Value::Int(_))) && !values.is_empty() {
        let ints: Vec<u64> = values.iter().map(|v| if let Value::Int(n) = v { *n } else { 0 }).collect();
        return Ok(PyArray1::from_vec(py, ints).into_any());
    }
    let nums: Vec<f64> = values
        .iter()
        .map(|v| match v {
            Value::Num(x) => *x,
            Value::Int(n) => *n as f64,
            _ => f64::NAN,
        })
        .collect();
    Ok(PyArray1::from_vec(py, nums).into_any())
}

/// An SI value of the spec: its name and where it is.
type ExactValue = (&'static str, fn(&mut ScrewSpec) -> Option<&mut f64>);

/// Every spec value that the TOML text (`config::spec_to_toml`) gives in another unit than the
/// core's (mm, degrees, GPa, rpm, mm^2/s, um, per GPa, per kN): a value read back from the text
/// may differ from the original in its last bits, so a pickle carries these as they are. The
/// pickle is checked when made ([`spec_state`]): a value missing here shows there.
pub(crate) const EXACT: &[ExactValue] = &[
    ("geometry.pitch_diameter_m", |s| Some(&mut s.geometry.pitch_diameter_m)),
    ("geometry.lead_m", |s| Some(&mut s.geometry.lead_m)),
    ("geometry.ball_diameter_m", |s| Some(&mut s.geometry.ball_diameter_m)),
    ("geometry.contact_angle_rad", |s| Some(&mut s.geometry.contact_angle_rad)),
    ("material.youngs_modulus_pa", |s| Some(&mut s.material.youngs_modulus_pa)),
    ("friction.standstill_speed_rad_s", |s| Some(&mut s.friction.standstill_speed_rad_s)),
    ("operating.speed_rad_s", |s| Some(&mut s.operating.speed_rad_s)),
    ("lubricant.viscosity_40c_m2_s", |s| Some(&mut s.lubricant.viscosity_40c_m2_s)),
    ("lubricant.viscosity_100c_m2_s", |s| Some(&mut s.lubricant.viscosity_100c_m2_s)),
    ("lubricant.pressure_viscosity_per_pa", |s| Some(&mut s.lubricant.pressure_viscosity_per_pa)),
    ("lubricant.roughness_ball_rq_m", |s| Some(&mut s.lubricant.roughness_ball_rq_m)),
    ("lubricant.roughness_raceway_rq_m", |s| Some(&mut s.lubricant.roughness_raceway_rq_m)),
    ("extensions.viscous_drag.reference_speed_rad_s", |s| {
        s.extensions.viscous_drag.as_mut().map(|v| &mut v.reference_speed_rad_s)
    }),
    ("extensions.thermal_viscosity.reference_speed_rad_s", |s| {
        s.extensions.thermal_viscosity.as_mut().map(|v| &mut v.drag.reference_speed_rad_s)
    }),
    ("extensions.raceway_waviness.phase_rad", |s| s.extensions.raceway_waviness.as_mut().map(|v| &mut v.phase_rad)),
    ("extensions.axial_load_loss.torque_per_n_nm", |s| {
        s.extensions.axial_load_loss.as_mut().map(|v| &mut v.torque_per_n_nm)
    }),
];

/// The spec of a pickle: `toml` read as a spec file, then each of `exact` (an SI value of
/// [`EXACT`] by name) set; ValueError naming the pickle's part that is wrong.
pub(crate) fn spec_from_state(toml: &str, origin: &str, exact: &Bound<'_, PyDict>) -> PyResult<ScrewSpec> {
    let mut spec = match config::spec_from_toml_str(toml, origin) {
        Ok(spec) => spec,
        Err(e) => return Err(value_error(format!("invalid pickled Screw: {e}"))),
    };
    for (name, value) in exact.iter() {
        let name: String =
            name.extract().map_err(|_| value_error("invalid pickled Screw: a value's name is no text"))?;
        let value = real_number(&name, &value)?;
        let slot = EXACT.iter().find(|(n, _)| *n == name).and_then(|(_, at)| at(&mut spec));
        match slot {
            Some(slot) => *slot = value,
            None => return Err(value_error(format!("invalid pickled Screw: no spec value {name}"))),
        }
    }
    Ok(spec)
}

/// The pickle of `spec` (from `origin`): its TOML text and its [`EXACT`] values, checked to give
/// back `spec` bit for bit (its printed form: every number in its shortest exact form, the sign
/// of zero included).
pub(crate) fn spec_state<'py>(py: Python<'py>, spec: &ScrewSpec, origin: &str) -> PyResult<Bound<'py, PyTuple>> {
    let toml = config::spec_to_toml(spec);
    let exact = PyDict::new(py);
    let mut copy = *spec;
    for (name, at) in EXACT {
        if let Some(v) = at(&mut copy) {
            exact.set_item(*name, *v)?;
        }
    }
    let back = spec_from_state(&toml, origin, &exact)?;
    if format!("{back:?}") != format!("{spec:?}") {
        return Err(PyRuntimeError::new_err(format!(
            "cannot pickle the Screw from {origin}: its spec does not read back exactly from its TOML text"
        )));
    }
    PyTuple::new(py, [toml.into_pyobject(py)?.into_any(), origin.into_pyobject(py)?.into_any(), exact.into_any()])
}

/// Every value of a spec's TOML text: its dotted path (`friction.coefficient`,
/// `extensions.viscous_drag.torque_nm`), in the text's order.
fn toml_leaves(table: &toml::Table, prefix: &str, out: &mut Vec<String>) {
    for (key, value) in table {
        let path = if prefix.is_empty() { key.clone() } else { format!("{prefix}.{key}") };
        match value {
            toml::Value::Table(t) => toml_leaves(t, &path, out),
            _ => out.push(path),
        }
    }
}

/// The names `Screw.replace` takes for the leaves `paths`: each dotted path, the path with
/// underscores for dots (`friction_coefficient`), and the last key alone where no other leaf has
/// it (`pitch_diameter_mm`); each name with the path it stands for.
fn replace_names(paths: &[String]) -> Vec<(String, String)> {
    let mut names = Vec::new();
    for path in paths {
        names.push((path.clone(), path.clone()));
        let flat = path.replace('.', "_");
        if flat != *path {
            names.push((flat, path.clone()));
        }
        let last = path.rsplit('.').next().unwrap_or(path);
        let unique = paths.iter().filter(|p| p.rsplit('.').next() == Some(last)).count() == 1;
        if unique && last != path && !names.iter().any(|(n, _)| n == last) {
            names.push((last.to_string(), path.clone()));
        }
    }
    names
}

/// A Python value as the TOML value of a spec key whose present value is `like` (an integer
/// given for a float key is a float; anything else goes to the spec's loader as given, which
/// checks its type).
fn py_to_toml(name: &str, value: &Bound<'_, PyAny>, like: Option<&toml::Value>) -> PyResult<toml::Value> {
    if value.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(value.extract()?));
    }
    if let Ok(text) = value.cast::<PyString>() {
        return Ok(toml::Value::String(text.to_string()));
    }
    if value.is_instance_of::<PyInt>()
        && !matches!(like, Some(toml::Value::Float(_)))
        && let Ok(n) = value.extract::<i64>()
    {
        return Ok(toml::Value::Integer(n));
    }
    Ok(toml::Value::Float(real_number(name, value)?))
}

/// The table of `table` at the dotted `path` (made where absent when `make`), and the last key.
fn table_at<'t>(table: &'t mut toml::Table, path: &'t str, make: bool) -> Option<(&'t mut toml::Table, &'t str)> {
    let mut parts: Vec<&str> = path.split('.').collect();
    let last = parts.pop()?;
    let mut at = table;
    for part in parts {
        if make && !at.contains_key(part) {
            at.insert(part.to_string(), toml::Value::Table(toml::Table::new()));
        }
        at = match at.get_mut(part) {
            Some(toml::Value::Table(t)) => t,
            _ => return None,
        };
    }
    Some((at, last))
}

#[pymethods]
impl Screw {
    /// The DKFZD4012 screw of Table 1 of Xu et al. (2015): the command line's built-in spec.
    #[staticmethod]
    fn dkfzd4012() -> PyResult<Self> {
        Self::from_config(config::builtin_spec(), BUILTIN_ORIGIN.to_string())
    }

    /// A screw from a TOML spec file (units in the key names, as `configs/dkfzd4012.toml`).
    ///
    /// Raises FileNotFoundError, IsADirectoryError or PermissionError (an OSError with the
    /// `filename`) when the file cannot be read, and ValueError naming the file and the key for
    /// invalid TOML, unknown or missing keys and values out of range.
    #[staticmethod]
    fn from_toml(path: PathBuf) -> PyResult<Self> {
        let origin = path.display().to_string();
        let text = read_text(&path, "spec file")?;
        Self::from_config(config::spec_from_toml_str(&text, &origin), origin)
    }

    /// A screw from the text of a TOML spec; `origin` names it in error messages.
    #[staticmethod]
    #[pyo3(signature = (text, origin = "<string>"))]
    fn from_toml_str(text: &str, origin: &str) -> PyResult<Self> {
        Self::from_config(config::spec_from_toml_str(text, origin), origin.to_string())
    }

    /// A new screw with spec values changed, as editing the spec's TOML text and loading it
    /// would give it: `screw.replace(friction_coefficient=0.05, preload_n=3000.0)` or
    /// `screw.replace({"friction.coefficient": 0.05})`.
    ///
    /// Names are the spec file's keys (`to_toml` lists them), values in their units (mm, deg,
    /// GPa, rpm, ...): the dotted key (`"friction.coefficient"`, in the dict), the dotted key with
    /// underscores (`friction_coefficient`) or, where no other table has it, the key alone
    /// (`pitch_diameter_mm`, `preload_n`; `coefficient` is in `[friction]` only, so it works too).
    /// A dotted key may also add a key the text leaves out (`"lubricant.inlet_distance_ratio"`,
    /// a table of `[extensions]`); `None` removes an optional key. An unknown name raises
    /// ValueError naming it with the closest known names; the values are checked as loading the
    /// TOML checks them (the same messages). Values not changed keep their exact SI values (as a
    /// pickle does), so `replace()` with nothing changed computes bit for bit what this screw does.
    #[pyo3(signature = (changes = None, **kwargs))]
    fn replace(
        &self,
        py: Python<'_>,
        changes: Option<&Bound<'_, PyDict>>,
        kwargs: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Self> {
        let old_text = config::spec_to_toml(self.spec());
        let mut table: toml::Table = old_text.parse().map_err(value_error)?;
        let mut paths = Vec::new();
        toml_leaves(&table, "", &mut paths);
        // The text writes only the half-widths of `[uncertainty]` that differ from their
        // defaults; every one is a key to change.
        for input in &UNCERTAIN_INPUTS {
            if !paths.iter().any(|p| p == input.field) {
                paths.push(input.field.to_string());
            }
        }
        let names = replace_names(&paths);
        let mut given: Vec<(String, Bound<'_, PyAny>)> = Vec::new();
        for dict in [changes, kwargs].into_iter().flatten() {
            for (k, v) in dict.iter() {
                let name: String = k.extract().map_err(|_| {
                    value_error(format!("invalid change: {} (valid: a spec key as text)", numbers_shown(&k)))
                })?;
                given.push((name, v));
            }
        }
        let mut changed = Vec::new();
        for (name, value) in &given {
            // A known name, or a dotted key under a table the text has (the loader judges it).
            let path = match names.iter().find(|(n, _)| n == name) {
                Some((_, path)) => path.clone(),
                None if name.contains('.') && table_at(&mut table.clone(), name, false).is_some() => name.clone(),
                None if name.starts_with("extensions.") && name.matches('.').count() == 2 => name.clone(),
                None => {
                    let known: Vec<&str> = names.iter().map(|(n, _)| n.as_str()).collect();
                    let close = py.import("difflib")?.call_method1("get_close_matches", (name, known, 3, 0.6))?;
                    let close: Vec<String> = close.extract()?;
                    let hint = if close.is_empty() {
                        "see Screw.to_toml() for the keys".to_string()
                    } else {
                        format!("did you mean {}?", close.join(", "))
                    };
                    return Err(value_error(format!("unknown spec key: {name:?} ({hint})")));
                }
            };
            if changed.contains(&path) {
                return Err(value_error(format!("spec key {path} given twice (as {name:?} and another name)")));
            }
            let (at, key) = table_at(&mut table, &path, true)
                .ok_or_else(|| value_error(format!("unknown spec key: {name:?} ({path} is no table's key)")))?;
            if value.is_none() {
                at.remove(key);
            } else {
                let v = py_to_toml(name, value, at.get(key))?;
                at.insert(key.to_string(), v);
            }
            changed.push(path);
        }
        // A grade given for the oil stands for both viscosities (the text of a spec written with a
        // grade has them instead): they go, unless given too (the loader then refuses the three).
        const VISCOSITIES: [&str; 2] = ["lubricant.viscosity_40c_mm2_s", "lubricant.viscosity_100c_mm2_s"];
        let grade_given = given.iter().zip(&changed).any(|((_, v), p)| p == "lubricant.iso_vg" && !v.is_none());
        if grade_given && !changed.iter().any(|p| VISCOSITIES.contains(&p.as_str())) {
            for path in VISCOSITIES {
                if let Some((at, key)) = table_at(&mut table, path, false) {
                    at.remove(key);
                }
            }
        }
        let text = toml::to_string(&table).map_err(value_error)?;
        let origin = self.origin.clone();
        let mut spec = match config::spec_from_toml_str(&text, &origin) {
            Ok(spec) => spec,
            // The line and column are of the edited text, which nobody sees: the message alone.
            Err(ConfigError::Parse { message, .. }) => return Err(value_error(format!("{origin}: {message}"))),
            Err(e) => return Err(value_error(format!("{origin}: {e}"))),
        };
        // Exactness: each SI value the text gives through a unit conversion that the change left
        // as the unchanged text reads it keeps this screw's own value (see `EXACT`).
        let read_back = config::spec_from_toml_str(&old_text, &origin).map_err(value_error)?;
        let (mut old, mut back) = (*self.spec(), read_back);
        for (_, at) in EXACT {
            if let (Some(new), Some(b), Some(o)) = (at(&mut spec), at(&mut back), at(&mut old))
                && new.to_bits() == b.to_bits()
            {
                *new = *o;
            }
        }
        Self::new(&spec, origin)
    }

    /// The spec as TOML text (units in the key names); `Screw.from_toml_str` reads it back.
    fn to_toml(&self) -> String {
        config::spec_to_toml(self.spec())
    }

    /// Drive (drag) torque in N m at preload `preload_n` (N), speed `speed_rpm` (rpm, negative
    /// for reverse rotation) and external axial load `axial_load_n` (N); `None` takes the spec's
    /// operating value (DKFZD4012: 100 rpm, 0 N).
    ///
    /// Floats give a float. Arrays (numpy integer or float arrays, lists of numbers) are
    /// broadcast together and give an array of that shape, computed in Rust on every core with
    /// the GIL released. With `start="canonical"` (the default) every point is its canonical
    /// state, the model's cold solve: the same bits as the scalar call and as `ballscrew
    /// torque`, on any number of threads and whatever the other points. `start="warm"` runs the
    /// control-loop evaluator band by band of speed, each point warm-started from a near one:
    /// tens of times faster on large batches, within 1e-8 of the canonical torque except where
    /// a ball has two steady states (docs/real-time.md, "Batches on the evaluator"); a scalar
    /// call is always canonical. Where the model's torque does not depend on the magnitude of a
    /// speed above the standstill speed, points that differ only in it are solved once. Every
    /// point is checked first:
    /// NaN, infinities and values out of range raise ValueError naming the argument and the
    /// index; so does a broadcast shape of more than 1e8 points, and anything that is not a real
    /// number: bools, complex numbers, datetimes and timedeltas, texts, None, and numpy masked
    /// arrays (numpy would ignore the mask: pass `.filled(value)` or drop the masked points).
    /// Ctrl-C stops a batch within a fraction of a second (KeyboardInterrupt). With
    /// `errors="nan"` a point the model cannot evaluate (beyond the static load capacity, or
    /// without a quasi-static state) gives NaN and the others are computed; one
    /// `ballscrew.EvaluationWarning` says how many and why the first failed. Bad arguments raise
    /// either way.
    #[pyo3(signature = (preload_n, speed_rpm = None, axial_load_n = None, *, errors = "raise", start = "canonical"))]
    fn torque<'py>(
        &self,
        py: Python<'py>,
        preload_n: &Bound<'py, PyAny>,
        speed_rpm: Option<&Bound<'py, PyAny>>,
        axial_load_n: Option<&Bound<'py, PyAny>>,
        errors: &str,
        start: &str,
    ) -> PyResult<Bound<'py, PyAny>> {
        let errors = parse_errors(errors)?;
        let start = match start {
            "canonical" => Start::Independent,
            "warm" => Start::Warm,
            other => {
                return Err(value_error(format!("invalid start: {other:?} (valid: \"canonical\" or \"warm\")")));
            }
        };
        let args = Args { preload_n: Some(preload_n), speed_rpm, axial_load_n };
        match points::points(&args, &self.spec().operating)? {
            Points::One(op) => {
                let t = match (self.torque_core(py, &op), errors) {
                    (Ok(t), _) => t,
                    (Err(e), Errors::Nan) => {
                        warn_failures(py, 1, 1, "point", 0, &format!("{e} {}", describe(&op)))?;
                        f64::NAN
                    }
                    (Err(e), Errors::Raise) => return Err(core_error(&e, &describe(&op))),
                };
                warn_quasi_static(py, self.spec(), [op])?;
                Ok(PyFloat::new(py, t).into_any())
            }
            Points::Many { shape, ops } => {
                let model = self.model;
                let out = interrupt::detach(py, |watch| {
                    let ev = if start == Start::Warm { self.evaluator(ops.len()) } else { None };
                    Batch::new(ops.len()).stop(watch).errors(errors).start(start).torques(&model, ev, &ops, None)
                })?
                .map_err(|e| batch_error(&e, &ops, &shape))?;
                let out = report_failures(py, out, "point", |i, e| {
                    format!("{e} {} (index {} of the operating points)", describe(&ops[i]), index_text(i, &shape))
                })?;
                warn_quasi_static(py, self.spec(), ops.iter().copied())?;
                Ok(PyArray1::from_vec(py, out).reshape(shape)?.into_any())
            }
        }
    }

    /// Everything the command line's `ballscrew torque` reports for one operating point, as a
    /// dict with its JSON keys in its order (units in the keys): `speed_rpm`, `preload_n`,
    /// `axial_load_n`; the drive torque `torque_nm` and its two parts, the friction
    /// `drag_torque_nm` and the load torque `load_torque_nm` = F_a L / (2 pi) (they add up to
    /// it); the torque by every route (`torque_energy_nm`, `torque_moment_nm`,
    /// `torque_eq27_nm`); the dissipation torque `dissipation_torque_nm` and its shares by
    /// mechanism (`creep_torque_nm`, `rolling_resistance_torque_nm`, `hysteresis_torque_nm`,
    /// `ball_ball_torque_nm`, `return_torque_nm`, which add up to it); `seal_torque_nm`; the
    /// catalog estimate and
    /// band (`catalog_nm`, `catalog_low_nm`, `catalog_high_nm`) and `ratio`, the drag torque
    /// over the catalog's; `iterations` and `max_residual`; under an axial load the
    /// `forward_efficiency` (F_a L / (2 pi T) with the drive moving the load),
    /// `backdrive_efficiency` (the torque the load produces at the screw over F_a L / (2 pi); 0
    /// when self-locking) and that torque `backdrive_torque_nm`: NaN without an axial load or
    /// at standstill. Cold start.
    #[pyo3(signature = (preload_n = None, speed_rpm = None, axial_load_n = None))]
    fn summary<'py>(
        &self,
        py: Python<'py>,
        preload_n: Option<&Bound<'py, PyAny>>,
        speed_rpm: Option<&Bound<'py, PyAny>>,
        axial_load_n: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let op = self.one_point(&Args { preload_n, speed_rpm, axial_load_n })?;
        let model = self.model;
        let row = py
            .detach(|| sweep_row(&SweepPoint { op, model: &model }))
            .map_err(|e| core_error(e.error(), &describe(&op)))?;
        let d = PyDict::new(py);
        records::fill(&d, POINT, &row.summary)?;
        records::fill(&d, EFFICIENCY, &row.efficiency)?;
        warn_quasi_static(py, self.spec(), [op])?;
        Ok(d)
    }

    /// The command line's sweep: one row per value of the swept quantity, the preload
    /// (`ballscrew sweep`), the speed (`--speed-rpm A..B`), the axial load (`--axial-load-n A..B`)
    /// or the oil temperature at the contacts (`--oil-temperature-c A..B`), each point solved cold
    /// (its canonical state) as the command line does, so the numbers are the command line's to
    /// the bit.
    ///
    /// Each of `preload_n` (N), `speed_rpm`, `axial_load_n` (N) and `oil_temperature_c` (the oil
    /// temperature at the contacts in degrees C, the spec's `lubricant.temperature_c`;
    /// lubricated model only) is one float (default the spec's) or a 1-d array-like of at most
    /// 100000 values to sweep (the command line's range `A..B` and its step, as the values).
    /// One quantity at a time, as on the command line; when none is an array the preload is
    /// swept (default 500 to 3000 N in steps of 100 N, the command line's default).
    /// Returns the columns of `ballscrew sweep --format csv`: the swept quantity (`preload_n`,
    /// `speed_rpm`, `axial_load_n` or `oil_temperature_c`), the operating point held
    /// (`preload_n`, `speed_rpm`, `axial_load_n` and, lubricated, `oil_temperature_c`, less the
    /// swept one), then `torque_nm`, `drag_torque_nm`, `load_torque_nm`,
    /// `torque_energy_nm`, `torque_moment_nm`, `torque_eq27_nm`, `catalog_nm`,
    /// `catalog_low_nm`, `catalog_high_nm`, `ratio` (of the drag torque), `iterations`,
    /// `max_residual`, `forward_efficiency`, `backdrive_efficiency`, `backdrive_torque_nm`
    /// (NaN without an axial load): a pandas DataFrame when pandas is installed (`frame=None`)
    /// or asked for (`frame=True`), else a dict of numpy arrays. Numbers are checked as in
    /// `torque`; `oil_temperature_c` under the dry model, or outside [-30, 200] degrees C, raises
    /// ValueError naming it. With `errors="nan"` a point the model cannot evaluate gives a row of
    /// NaN but its operating point (`iterations` then float) and the others are computed (one
    /// `ballscrew.EvaluationWarning`). Ctrl-C stops the sweep between two points.
    ///
    /// `band=True` (or a pair `(low, high)` of quantiles, default 0.05 and 0.95) adds the band
    /// of the drag torque at each row after the other columns, `drag_torque_low_nm`,
    /// `drag_torque_median_nm` and `drag_torque_high_nm` (N m; `ballscrew sweep --band`'s
    /// columns): each row's `Screw.band`, to the bit, from `samples` samples (default 128) of
    /// the spec's `[uncertainty]` by the seed `seed` (default 0); NaN at rows the model could
    /// not evaluate under `errors="nan"` (a sample that fails raises either way). `samples` or
    /// `seed` without a band raise ValueError naming them.
    #[pyo3(signature = (preload_n = None, speed_rpm = None, axial_load_n = None, *, oil_temperature_c = None, frame = None,
        errors = "raise", band = None, samples = None, seed = None))]
    #[allow(clippy::too_many_arguments)]
    fn sweep<'py>(
        &self,
        py: Python<'py>,
        preload_n: Option<&Bound<'py, PyAny>>,
        speed_rpm: Option<&Bound<'py, PyAny>>,
        axial_load_n: Option<&Bound<'py, PyAny>>,
        oil_temperature_c: Option<&Bound<'py, PyAny>>,
        frame: Option<bool>,
        errors: &str,
        band: Option<&Bound<'py, PyAny>>,
        samples: Option<&Bound<'py, PyAny>>,
        seed: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let errors = parse_errors(errors)?;
        let band_settings = band::sweep_settings(band, samples, seed)?;
        let given = |obj: Option<&Bound<'py, PyAny>>| obj.filter(|o| !o.is_none()).cloned();
        let (preload, speed, axial, temperature) =
            (given(preload_n), given(speed_rpm), given(axial_load_n), given(oil_temperature_c));
        // Each quantity is one number or a 1-d array to sweep; every one is read (and refused
        // when it is not real numbers) before the sweep is chosen.
        let mut arrays = Vec::new();
        for (name, obj) in SWEPT.iter().map(|q| q.key).zip([&preload, &speed, &axial, &temperature]) {
            if let Some(o) = obj
                && !reals(name, o, NUMBERS)?.shape().is_empty()
            {
                arrays.push(name);
            }
        }
        if arrays.len() > 1 {
            return Err(value_error(format!(
                "one quantity at a time: {} are {} arrays (give the {} a single value, as `ballscrew sweep`)",
                and_list(&arrays),
                if arrays.len() == 2 { "both" } else { "all" },
                if arrays.len() == 2 { "other" } else { "others" },
            )));
        }
        // The swept quantity: the one given as an array, else the preload.
        let key = arrays.first().copied().unwrap_or(SWEPT_PRELOAD.key);
        let (rows, failed, models) = if key == SWEPT_OIL_TEMPERATURE.key {
            let t = reals(key, temperature.as_ref().ok_or_else(|| value_error("no oil_temperature_c"))?, NUMBERS)?;
            let (shape, temps) = (t.shape().to_vec(), t.view().iter().copied().collect::<Vec<f64>>());
            self.sweep_oil_temperature(py, &shape, temps, preload.as_ref(), &speed, &axial, errors)?
        } else {
            // The preload, the speed or the axial load (the preload when nothing is an
            // array: the given one, else the command line's default preloads).
            let model = match &temperature {
                Some(t) => self.model_at(real_number(SWEPT_OIL_TEMPERATURE.key, t)?, "")?,
                None => self.model,
            };
            let preloads = match preload {
                Some(p) => Some(p),
                None if key == SWEPT_PRELOAD.key => Some(PyArray1::from_vec(py, default_sweep_preloads_n()).into_any()),
                None => None,
            };
            let args = Args { preload_n: preloads.as_ref(), speed_rpm: speed.as_ref(), axial_load_n: axial.as_ref() };
            let (shape, ops) = match points::points(&args, &self.spec().operating)? {
                Points::One(op) => (vec![1], vec![op]),
                Points::Many { shape, ops } => (shape, ops),
            };
            let what = match key {
                "speed_rpm" => "speeds",
                "axial_load_n" => "axial loads",
                _ => "preloads",
            };
            check_sweep_shape(key, what, &shape, ops.len())?;
            let points: Vec<SweepPoint<'_>> = ops.iter().map(|&op| SweepPoint { op, model: &model }).collect();
            let results = interrupt::detach(py, |watch| {
                sweep(&points, threads_for(points.len()), watch, errors, &mut |_, _| {})
            })?
            .map_err(|e| batch_error(&e.into(), &ops, &shape))?;
            let (rows, failed) = sweep_rows(py, results, &points, |i, e| {
                format!("{e} {} (index {} of the operating points)", describe(&ops[i]), index_text(i, &shape))
            })?;
            (rows, failed, vec![model])
        };
        // One warning over the rows' points where the quasi-static model does not hold, as the
        // command line's.
        warn_quasi_static(py, self.spec(), rows.iter().map(|r| r.summary.operating))?;
        // Every row names its whole operating point (the CLI's order: the swept quantity, then
        // the preload, speed, axial load and oil temperature held), so sweeps can be stacked.
        let lead = swept_quantity(key)?;
        let d = PyDict::new(py);
        for q in core::iter::once(lead).chain(held(lead, self.spec().model.lubrication)) {
            d.set_item(q.key, column(py, q.get, &rows, |r| r, &[])?)?;
        }
        for q in SWEEP {
            d.set_item(q.key, column(py, q.get, &rows, |r| &r.summary, &failed)?)?;
        }
        for q in EFFICIENCY {
            d.set_item(q.key, column(py, q.get, &rows, |r| &r.efficiency, &failed)?)?;
        }
        if let Some(settings) = band_settings {
            let bands = self.sweep_band(py, &rows, &failed, &models, &settings)?;
            for q in BAND {
                d.set_item(q.key, column(py, q.get, &bands, |b| b, &failed)?)?;
            }
        }
        match band::pandas(py, frame)? {
            Some(pd) => pd.getattr("DataFrame")?.call1((d,)),
            None => Ok(d.into_any()),
        }
    }

    /// The band of the drag torque (N m) that the spread of the spec's uncertain inputs gives,
    /// at one operating point or at each point of arrays (broadcast as in `torque`; `None`: the
    /// spec's operating value).
    ///
    /// The spec's `[uncertainty]` table gives each input's half-width: the oil's viscosity
    /// (default +-10 %, ISO 3448), pressure-viscosity coefficient (+-25 %), temperature at the
    /// contacts (+-5 K), ball and raceway roughness (+-30 %, +-50 %), boundary friction
    /// (+-0.05), full-film traction (+-0.015) and the preload (+-30 %, the preload torque class
    /// of ISO 3408-3); each default with its source in `docs/spec-reference.md`, 0 pins an
    /// input (`Screw.replace({"uncertainty.preload_relative": 0.1})` changes one). Each input is
    /// uniform over its spread; `samples` (default 128, 8 to 65536) scrambled Sobol samples of
    /// them, by the seed `seed` (default 0, a whole number below 2^32), go through the model at
    /// each point, and the band is the pair of `quantiles` (default `(0.05, 0.95)`) and the
    /// median of the samples' drag torques (numpy's default quantile). The same arguments give
    /// the same band to the bit, on any number of threads, and a point's band does not depend
    /// on the other points.
    ///
    /// Returns a dict: `drag_torque_nm` (the nominal drag torque, `summary`'s), then
    /// `drag_torque_low_nm`, `drag_torque_median_nm` and `drag_torque_high_nm`: floats for one
    /// point, numpy arrays of the broadcast shape for arrays. Computed in Rust over every core
    /// with the GIL released; Ctrl-C stops it (KeyboardInterrupt). A bad quantile pair, sample
    /// size or seed, or a half-width whose spread leaves its input's valid range at a point
    /// (naming `uncertainty.<key>`), raises ValueError; a sample the model cannot evaluate
    /// raises as a failing `torque` does (`ConvergenceError`, a ValueError), naming the sample
    /// and the point; a band too large for the memory raises MemoryError.
    #[pyo3(signature = (preload_n = None, speed_rpm = None, axial_load_n = None, *, quantiles = None, samples = None,
        seed = None),
        text_signature = "(self, preload_n=None, speed_rpm=None, axial_load_n=None, *, quantiles=(0.05, 0.95), samples=128, seed=0)")]
    #[allow(clippy::too_many_arguments)]
    fn band<'py>(
        &self,
        py: Python<'py>,
        preload_n: Option<&Bound<'py, PyAny>>,
        speed_rpm: Option<&Bound<'py, PyAny>>,
        axial_load_n: Option<&Bound<'py, PyAny>>,
        quantiles: Option<&Bound<'py, PyAny>>,
        samples: Option<&Bound<'py, PyAny>>,
        seed: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let settings = band::settings(quantiles, samples, seed)?;
        let args = Args { preload_n, speed_rpm, axial_load_n };
        let (shape, ops) = match points::points(&args, &self.spec().operating)? {
            Points::One(op) => (None, vec![op]),
            Points::Many { shape, ops } => (Some(shape), ops),
        };
        band::check_room(ops.len(), settings.samples)?;
        let model = self.model;
        let mut points = room_for(ops.len())?;
        points.extend(ops.iter().map(|&op| SweepPoint { op, model: &model }));
        let bands = interrupt::detach(py, |watch| -> Result<Vec<Band>, Box<BandError>> {
            let batch = Batch::new(points.len().max(settings.samples as usize)).stop(watch);
            uncertainty::band(&batch, &points, &settings).map_err(Box::new)
        })?
        .map_err(|e| {
            band::band_error(&e, |i| match &shape {
                Some(shape) => format!(
                    "{} (index {} of the operating points)",
                    ops.get(i).map(describe).unwrap_or_default(),
                    index_text(i, shape)
                ),
                None => ops.first().map(describe).unwrap_or_default(),
            })
        })?;
        warn_quasi_static(py, self.spec(), ops.iter().copied())?;
        let drag = by_key(POINT, "drag_torque_nm").ok_or_else(|| value_error("no drag_torque_nm quantity"))?;
        let d = PyDict::new(py);
        let put = |key: &str, values: Vec<f64>| -> PyResult<()> {
            match &shape {
                None => d.set_item(key, values.first().copied().unwrap_or(f64::NAN)),
                Some(shape) => d.set_item(key, PyArray1::from_vec(py, values).reshape(shape.clone())?),
            }
        };
        // The nominal drag torque: the band's own, `summary`'s to the bit.
        put(drag.key, bands.iter().map(|b| b.nominal_nm).collect())?;
        for q in BAND {
            put(q.key, bands.iter().map(|b| band::number((q.get)(b))).collect())?;
        }
        Ok(d)
    }

    /// What drives the band of the drag torque at one operating point (`None`: the spec's
    /// operating value): one row per uncertain input the model reads and the spec's
    /// `[uncertainty]` spreads (half-width above 0; see `band`), largest swing first.
    ///
    /// Columns: `input` (its short name), `key` (its half-width's spec key,
    /// `uncertainty.<key>`), `half_width` and `half_width_unit` (`share`: of the value; `1`: a
    /// friction coefficient's absolute spread; `K`), `low_end_nm` and `high_end_nm` (the drag
    /// torque with that input at the low and the high end of its spread, the others nominal),
    /// `swing_nm` (their difference, what a tornado chart draws), `first_order` and `total` (its
    /// first-order and total Sobol indices: the share of the band's variance it causes alone,
    /// and with its interactions; Saltelli et al. 2010, Jansen's estimator for the total, from
    /// `samples` base samples, default 128, and `samples (k + 2)` model evaluations for `k`
    /// inputs, by the seed `seed`, default 0).
    ///
    /// A pandas DataFrame when pandas is installed (`frame=None`) or asked for (`frame=True`),
    /// else a dict of the columns (numpy arrays; `input`, `key` and `half_width_unit` lists of
    /// texts). The nominal drag torque (N m, `summary`'s) and the variance of the drag torque
    /// over the samples (N^2 m^2) are in the table's `attrs`, `attrs["drag_torque_nm"]` and
    /// `attrs["variance_nm2"]`: the DataFrame's own `attrs`, or the dict's (a `dict` subclass
    /// with an `attrs` attribute). Errors as in `band`. Computed in Rust over every core with
    /// the GIL released; Ctrl-C stops it.
    #[pyo3(signature = (preload_n = None, speed_rpm = None, axial_load_n = None, *, samples = None, seed = None,
        frame = None),
        text_signature = "(self, preload_n=None, speed_rpm=None, axial_load_n=None, *, samples=128, seed=0, frame=None)")]
    #[allow(clippy::too_many_arguments)]
    fn sensitivity<'py>(
        &self,
        py: Python<'py>,
        preload_n: Option<&Bound<'py, PyAny>>,
        speed_rpm: Option<&Bound<'py, PyAny>>,
        axial_load_n: Option<&Bound<'py, PyAny>>,
        samples: Option<&Bound<'py, PyAny>>,
        seed: Option<&Bound<'py, PyAny>>,
        frame: Option<bool>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let settings = band::settings(None, samples, seed)?;
        let op = self.one_point(&Args { preload_n, speed_rpm, axial_load_n })?;
        band::check_room(UNCERTAIN_INPUTS.len() + 2, settings.samples)?;
        let model = self.model;
        let point = SweepPoint { op, model: &model };
        let s = interrupt::detach(py, |watch| {
            let batch = Batch::new(settings.samples as usize).stop(watch);
            uncertainty::sensitivity(&batch, &point, &settings).map_err(Box::new)
        })?
        .map_err(|e| band::band_error(&e, |_| describe(&op)))?;
        warn_quasi_static(py, self.spec(), [op])?;
        let columns = PyDict::new(py);
        for q in SENSITIVITY {
            columns.set_item(q.key, band::column(py, q.get, &s.inputs)?)?;
        }
        let drag = by_key(POINT, "drag_torque_nm").ok_or_else(|| value_error("no drag_torque_nm quantity"))?;
        let attrs = PyDict::new(py);
        attrs.set_item(drag.key, s.nominal_nm)?;
        attrs.set_item("variance_nm2", s.variance_nm2)?;
        band::table(py, columns, attrs, frame)
    }

    /// The same screw with the oil at `oil_temperature_c` (degrees C) at the contacts: the spec's
    /// `lubricant.temperature_c` changed, as `ballscrew sweep --oil-temperature-c` sets it for
    /// each point; `torque`, `summary`, `inspect` and `sweep` of the new screw run at that
    /// temperature. Lubricated model only: under `lubrication = "dry"` (no oil), and outside
    /// [-30, 200] degrees C, ValueError naming `oil_temperature_c`.
    fn with_oil_temperature(&self, oil_temperature_c: &Bound<'_, PyAny>) -> PyResult<Self> {
        let t = real_number("oil_temperature_c", oil_temperature_c)?;
        let model = self.model_at(t, "")?;
        Ok(Self { model, origin: self.origin.clone(), evaluator: OnceLock::new() })
    }

    /// The per-contact breakdown of one operating point, as `ballscrew inspect --format csv`
    /// has it: a list of dicts, one per contact (nut, screw, ball-ball) of the ball standing for
    /// each nut's circle, with the ball's columns (`nut`, `circle`, ..., `omega_b_per_screw`)
    /// then the contact's (`contact`, `normal_load_n`, ..., `friction_bound_n`,
    /// `friction_coefficient`, `film_central_um`, `film_minimum_um`, `lambda`,
    /// `rolling_resistance_ehl_n`, `rolling_resistance_hysteresis_n`, `dissipation_per_ball_nm`,
    /// `torque_share_nm` and its parts `creep_torque_share_nm`, `rolling_torque_share_nm`,
    /// `hysteresis_torque_share_nm`). Cold start.
    #[pyo3(signature = (preload_n = None, speed_rpm = None, axial_load_n = None))]
    fn inspect<'py>(
        &self,
        py: Python<'py>,
        preload_n: Option<&Bound<'py, PyAny>>,
        speed_rpm: Option<&Bound<'py, PyAny>>,
        axial_load_n: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyList>> {
        let op = self.one_point(&Args { preload_n, speed_rpm, axial_load_n })?;
        let model = self.model;
        let ev =
            py.detach(|| model.evaluate(&op, &mut SolverState::new())).map_err(|e| core_error(&e, &describe(&op)))?;
        let rows = PyList::empty(py);
        for nut in ev.balls.iter().take(ev.nuts.min(MAX_NUTS)) {
            for ball in nut.iter().take(ev.circles) {
                for c in &ball.contacts {
                    let d = PyDict::new(py);
                    records::fill(&d, BALL_ID, ball)?;
                    records::fill(&d, BALL, ball)?;
                    records::fill(&d, CONTACT_ID, c)?;
                    records::fill(&d, CONTACT, c)?;
                    rows.append(d)?;
                }
            }
        }
        warn_quasi_static(py, self.spec(), [op])?;
        Ok(rows)
    }

    /// The screw a pickle holds: `toml` (a spec's text), `origin`, and `exact`, the spec values
    /// of the text in SI as they were (see `__reduce__`).
    #[classmethod]
    fn _from_state(_cls: &Bound<'_, PyType>, toml: &str, origin: &str, exact: &Bound<'_, PyDict>) -> PyResult<Self> {
        Self::new(&spec_from_state(toml, origin, exact)?, origin.to_string())
    }

    /// Pickling (and `copy.copy`, `copy.deepcopy`): the spec as TOML text, its origin, and the
    /// spec values the text gives in other units in SI as they are, so that the copy computes
    /// the same torques bit for bit (a `Screw` holds no state beyond its spec: every answer is
    /// solved cold).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let this = slf.get();
        Ok((slf.get_type().getattr("_from_state")?, spec_state(py, this.spec(), &this.origin)?))
    }

    /// Where the spec came from: a file name, `<string>` or the built-in spec.
    #[getter]
    fn origin(&self) -> &str {
        &self.origin
    }

    /// Pitch diameter d_m (ball-centre helix diameter), m.
    #[getter]
    fn pitch_diameter_m(&self) -> f64 {
        self.spec().geometry.pitch_diameter_m
    }

    /// Lead L (axial advance per screw revolution), m.
    #[getter]
    fn lead_m(&self) -> f64 {
        self.spec().geometry.lead_m
    }

    /// Ball diameter D_w, m.
    #[getter]
    fn ball_diameter_m(&self) -> f64 {
        self.spec().geometry.ball_diameter_m
    }

    /// Conformity of the screw groove f_s (groove radius / ball diameter).
    #[getter]
    fn conformity_screw(&self) -> f64 {
        self.spec().geometry.conformity_screw
    }

    /// Conformity of the nut groove f_N (groove radius / ball diameter).
    #[getter]
    fn conformity_nut(&self) -> f64 {
        self.spec().geometry.conformity_nut
    }

    /// Nominal contact angle beta, degrees.
    #[getter]
    fn contact_angle_deg(&self) -> f64 {
        self.spec().geometry.contact_angle_rad.to_degrees()
    }

    /// Helix (lead) angle alpha = atan(L / (pi d_m)), degrees.
    #[getter]
    fn helix_angle_deg(&self) -> f64 {
        self.model.helix_angle_rad().to_degrees()
    }

    /// Number of nuts: 2 for a double nut, 1 for every single-nut arrangement.
    #[getter]
    fn nuts(&self) -> u32 {
        self.spec().geometry.nuts
    }

    /// How the nut is preloaded (`geometry.preload`): "double-nut", "offset-lead",
    /// "oversize-ball" (four-point contact) or "none".
    #[getter]
    fn preload_arrangement(&self) -> &'static str {
        self.spec().geometry.preload.name()
    }

    /// Load-carrying circles (turns) per nut.
    #[getter]
    fn circles_per_nut(&self) -> u32 {
        self.spec().geometry.circles_per_nut
    }

    /// Balls per circle.
    #[getter]
    fn balls_per_circle(&self) -> u32 {
        self.spec().geometry.balls_per_circle
    }

    /// Young's modulus E of balls and raceways, Pa.
    #[getter]
    fn youngs_modulus_pa(&self) -> f64 {
        self.spec().material.youngs_modulus_pa
    }

    /// Poisson's ratio nu.
    #[getter]
    fn poisson_ratio(&self) -> f64 {
        self.spec().material.poisson_ratio
    }

    /// Coulomb friction coefficient f of every contact under `lubrication == "dry"`; under
    /// `"ehl"` each raceway contact's coefficient comes from its film (`inspect`'s
    /// `friction_coefficient`).
    #[getter]
    fn friction_coefficient(&self) -> f64 {
        self.spec().friction.coefficient
    }

    /// Factor (0, 1] on Kalker's creep coefficients (1: dry contact; below 1: lubricated).
    #[getter]
    fn creep_reduction(&self) -> f64 {
        self.spec().friction.creep_reduction
    }

    /// Drag torque of each nut's seals, N m (`friction.seal_torque_per_nut_nm`; reported as
    /// `seal_torque_nm` in `summary`).
    #[getter]
    fn seal_torque_per_nut_nm(&self) -> f64 {
        self.spec().friction.seal_torque_per_nut_nm
    }

    /// Normal load between adjacent balls Q_m, N, where the spec sets it
    /// (`friction.ball_ball_load_n`); `None`: the loads follow from the ball train.
    #[getter]
    fn ball_ball_load_n(&self) -> Option<f64> {
        self.spec().friction.ball_ball_load_n
    }

    /// Standstill speed, rpm: below it the creep forces fade to zero at standstill.
    #[getter]
    fn standstill_speed_rpm(&self) -> f64 {
        rad_s_to_rpm(self.spec().friction.standstill_speed_rad_s)
    }

    /// The spec's operating speed (the default of `speed_rpm`), rpm.
    #[getter]
    fn default_speed_rpm(&self) -> f64 {
        rad_s_to_rpm(self.spec().operating.speed_rad_s)
    }

    /// The spec's preload (the default of `preload_n` in `summary` and `inspect`), N.
    #[getter]
    fn default_preload_n(&self) -> f64 {
        self.spec().operating.preload_n
    }

    /// The spec's external axial load (the default of `axial_load_n`), N.
    #[getter]
    fn default_axial_load_n(&self) -> f64 {
        self.spec().operating.axial_load_n
    }

    /// Load sharing over circles: "geometric", "paper-literal" or "uniform".
    #[getter]
    fn load_distribution(&self) -> &'static str {
        self.spec().model.load_distribution.name()
    }

    /// Whether the raceway contacts are lubricated: "ehl" (an elastohydrodynamic film of the
    /// spec's `lubricant`, the default) or "dry" (the paper's dry contacts).
    #[getter]
    fn lubrication(&self) -> &'static str {
        self.spec().model.lubrication.name()
    }

    /// The spec's `[lubricant]` table as a dict, keyed and in the units of a spec file (as
    /// `to_toml` writes it: both viscosities, not the grade): `viscosity_40c_mm2_s`,
    /// `viscosity_100c_mm2_s`, `density_15c_kg_m3`, ..., `temperature_c` (the oil temperature
    /// at the contacts), ..., `inlet_distance_ratio` (absent: fully flooded). Read by the model
    /// only under `lubrication == "ehl"`.
    #[getter]
    fn lubricant<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let text = config::spec_to_toml(self.spec());
        let table: toml::Table = text.parse().map_err(value_error)?;
        let d = PyDict::new(py);
        if let Some(toml::Value::Table(lubricant)) = table.get("lubricant") {
            for (key, value) in lubricant {
                d.set_item(key, toml_to_py(py, value)?)?;
            }
        }
        Ok(d)
    }

    /// The oil temperature at the contacts (`lubricant.temperature_c`, the default of
    /// `oil_temperature_c`), degrees C; `None` under `lubrication == "dry"` (no oil).
    #[getter]
    fn oil_temperature_c(&self) -> Option<f64> {
        (self.spec().model.lubrication == Lubrication::Ehl).then_some(self.spec().lubricant.temperature_c)
    }

    /// Creep coefficients: "kalker-table" or "paper-fit".
    #[getter]
    fn creep_coefficients(&self) -> &'static str {
        self.spec().model.creep_coefficients.name()
    }

    /// The torque reported as the torque: "energy" or "paper-eq27".
    #[getter]
    fn torque_route(&self) -> &'static str {
        self.spec().model.torque.name()
    }

    /// Whether Heathcote slip is included.
    #[getter]
    fn heathcote(&self) -> bool {
        self.spec().model.heathcote
    }

    /// Spin moment at the raceway contacts: "combined" or "separate".
    #[getter]
    fn spin_moment(&self) -> &'static str {
        self.spec().model.spin_moment.name()
    }

    /// Contact theory of the raceway contacts: "linear-saturated" or "fastsim".
    #[getter]
    fn contact_theory(&self) -> &'static str {
        self.spec().model.contact_theory.name()
    }

    /// FASTSIM elements per axis of the contact ellipse (with `contact_theory == "fastsim"`).
    #[getter]
    fn fastsim_grid(&self) -> u32 {
        self.spec().model.fastsim_grid
    }

    fn __repr__(&self) -> String {
        let spec = self.spec();
        let g = &spec.geometry;
        let lubrication = match spec.model.lubrication {
            Lubrication::Ehl => format!(
                "lubrication ehl (oil at {} C at the contacts, {} mm^2/s at 40 C)",
                Shown(spec.lubricant.temperature_c),
                Shown(m2_s_to_mm2_s(spec.lubricant.viscosity_40c_m2_s))
            ),
            Lubrication::Dry => "lubrication dry".to_string(),
        };
        format!(
            "<ballscrew.Screw from {}: d_m {} mm, L {} mm, D_w {} mm, preload {}, {} nut(s) x {} circles x {} balls, {lubrication}>",
            self.origin,
            g.pitch_diameter_m * 1e3,
            g.lead_m * 1e3,
            g.ball_diameter_m * 1e3,
            g.preload.name(),
            g.nuts,
            g.circles_per_nut,
            g.balls_per_circle
        )
    }
}

/// Drag torque of the built-in DKFZD4012 screw at `preload_n` (N) and `speed_rpm` (rpm; `None`:
/// 100), no axial load, N m; each call starts cold. `Screw.dkfzd4012().torque(...)` does the
/// same for arrays and any axial load. Anything but a real number raises ValueError naming the
/// argument.
#[pyfunction]
#[pyo3(signature = (preload_n, speed_rpm = None), text_signature = "(preload_n, speed_rpm=100.0)")]
pub fn dkfzd4012_torque_nm(
    py: Python<'_>,
    preload_n: &Bound<'_, PyAny>,
    speed_rpm: Option<&Bound<'_, PyAny>>,
) -> PyResult<f64> {
    let preload_n = real_number("preload_n", preload_n)?;
    let speed_rpm = speed_rpm.map_or(Ok(100.0), |s| real_number("speed_rpm", s))?;
    let op = points::operating_point(speed_rpm, preload_n, 0.0).map_err(value_error)?;
    py.detach(|| Model::new(&ScrewSpec::dkfzd4012()).and_then(|m| m.torque(&op, &mut SolverState::new())))
        .map_err(|e| core_error(&e, &describe(&op)))
}
