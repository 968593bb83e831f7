//! The band of the drag torque from Python (`Screw.band`, `Screw.sweep(band=...)`,
//! `Screw.sensitivity`): the band's settings read from the arguments, the band's errors as
//! Python exceptions, and its values as columns under the keys of the table of reported
//! quantities (`BAND`, `SENSITIVITY`).
//!
//! Errors: a setting out of range (the quantiles, the sample size) and a spread that leaves its
//! input's range (naming `uncertainty.<key>`) raise `ValueError` with the Rust message; a sample
//! or nominal point the model cannot evaluate raises what a failing `torque` raises
//! (`ConvergenceError` or `ValueError`); a band too large for the memory raises `MemoryError`.

use crate::batch::BatchError;
use crate::errors::{core_error_text, room_for, value_error};
use crate::numbers::{real_number, shown};
use ballscrew_batch::quantities::Value;
use ballscrew_batch::uncertainty::{
    BandError, BandSettings, DEFAULT_QUANTILES, DEFAULT_SAMPLES, DEFAULT_SEED, QUANTILES_VALID, SAMPLES_VALID,
    SettingError,
};
use numpy::PyArray1;
use pyo3::exceptions::{PyImportError, PyKeyboardInterrupt, PyMemoryError, PyRuntimeError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyList, PyModule, PyString};

/// Valid seeds, for messages.
const SEED_VALID: &str = "a whole number in [0, 4294967295]";

/// The message of a band setting out of range, as the Rust side words it.
fn setting_error(setting: &'static str, value: String, valid: &'static str) -> PyErr {
    value_error(BandError::Setting(SettingError { setting, value, valid }))
}

/// A whole number (a Python or numpy integer, not a bool), or `None` for anything else.
fn whole_number(obj: &Bound<'_, PyAny>) -> Option<i128> {
    if obj.is_instance_of::<PyBool>() {
        return None;
    }
    obj.extract::<i128>().ok()
}

/// The sample size `samples` (default [`DEFAULT_SAMPLES`]): a whole number in [8, 65536].
fn samples(obj: Option<&Bound<'_, PyAny>>) -> PyResult<u32> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(DEFAULT_SAMPLES);
    };
    match whole_number(obj) {
        Some(n) => u32::try_from(n).map_err(|_| setting_error("samples", n.to_string(), SAMPLES_VALID)),
        None => Err(setting_error("samples", shown(obj), SAMPLES_VALID)),
    }
}

/// The seed `seed` (default [`DEFAULT_SEED`]): a whole number in [0, 2^32 - 1].
fn seed(obj: Option<&Bound<'_, PyAny>>) -> PyResult<u32> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(DEFAULT_SEED);
    };
    match whole_number(obj) {
        Some(n) => u32::try_from(n).map_err(|_| setting_error("seed", n.to_string(), SEED_VALID)),
        None => Err(setting_error("seed", shown(obj), SEED_VALID)),
    }
}

/// The band's quantiles `quantiles` (default [`DEFAULT_QUANTILES`]): a pair of real numbers.
fn quantiles(obj: Option<&Bound<'_, PyAny>>) -> PyResult<(f64, f64)> {
    let Some(obj) = obj.filter(|o| !o.is_none()) else {
        return Ok(DEFAULT_QUANTILES);
    };
    let refused = || setting_error("quantiles", shown(obj), QUANTILES_VALID);
    if obj.is_instance_of::<PyString>() || obj.len().ok() != Some(2) {
        return Err(refused());
    }
    let (lo, hi) = (obj.get_item(0).map_err(|_| refused())?, obj.get_item(1).map_err(|_| refused())?);
    Ok((real_number("quantiles", &lo)?, real_number("quantiles", &hi)?))
}

/// The band's settings from the arguments `quantiles`, `samples` and `seed` (`None`: the
/// defaults, 0.05 and 0.95, 128 and 0), checked.
pub fn settings(
    quantiles_arg: Option<&Bound<'_, PyAny>>,
    samples_arg: Option<&Bound<'_, PyAny>>,
    seed_arg: Option<&Bound<'_, PyAny>>,
) -> PyResult<BandSettings> {
    let settings =
        BandSettings { samples: samples(samples_arg)?, seed: seed(seed_arg)?, quantiles: quantiles(quantiles_arg)? };
    settings.validate().map_err(|e| value_error(BandError::Setting(e)))?;
    Ok(settings)
}

/// The settings of `sweep`'s `band` (`None` or `False`: no band; `True`: the default quantiles;
/// a pair: the quantiles) with its `samples` and `seed`; these given without a band raise
/// `ValueError` naming them.
pub fn sweep_settings(
    band: Option<&Bound<'_, PyAny>>,
    samples_arg: Option<&Bound<'_, PyAny>>,
    seed_arg: Option<&Bound<'_, PyAny>>,
) -> PyResult<Option<BandSettings>> {
    let band = band.filter(|b| !b.is_none());
    let wanted = match band {
        None => false,
        Some(b) if b.is_instance_of::<PyBool>() => b.extract::<bool>()?,
        Some(_) => true,
    };
    if !wanted {
        let given: Vec<&str> = [("samples", samples_arg), ("seed", seed_arg)]
            .into_iter()
            .filter(|(_, a)| a.is_some_and(|a| !a.is_none()))
            .map(|(name, _)| name)
            .collect();
        if !given.is_empty() {
            let verb = if given.len() == 1 { "is" } else { "are" };
            return Err(value_error(format!(
                "{} {verb} given without band (they set the band's sample: add band=True, or band=(low, high) quantiles)",
                given.join(" and ")
            )));
        }
        return Ok(None);
    }
    let quantiles_arg = band.filter(|b| !b.is_instance_of::<PyBool>());
    settings(quantiles_arg, samples_arg, seed_arg).map(Some)
}

/// `MemoryError` unless there is room for what a band of `samples` samples at `points` points
/// holds at once (asked for, not touched): the drag torques of one chunk of points
/// ([`ballscrew_batch::uncertainty::BAND_CHUNK_POINTS`]) by the samples, and the band's three
/// numbers at every point. A band too large fails before it starts; the command line's band
/// holds the same.
pub fn check_room(points: usize, samples: u32) -> PyResult<()> {
    let chunk = points.min(ballscrew_batch::uncertainty::BAND_CHUNK_POINTS);
    let n =
        chunk.checked_mul(samples as usize).and_then(|d| d.checked_add(points.checked_mul(3)?)).ok_or_else(|| {
            PyMemoryError::new_err(format!("not enough memory for the band of {points} points by {samples} samples"))
        })?;
    room_for::<f64>(n).map(drop)
}

/// The band's error as a Python exception; `describe(point)` names the point at that index.
/// (The callers box the error where they pass it on: it is large.)
pub fn band_error(e: &BandError, describe: impl Fn(usize) -> String) -> PyErr {
    match e {
        BandError::Setting(_) | BandError::Input(_) | BandError::Spread(_) => value_error(e),
        BandError::Nominal { point, error } => core_error_text(error, format!("{error} {}", describe(*point))),
        BandError::Sample { point, error, .. } | BandError::End { point, error, .. } => {
            core_error_text(error, format!("{e} {}", describe(*point)))
        }
        BandError::Batch(BatchError::Point { index, error }) => {
            core_error_text(error, format!("{error} {}", describe(*index)))
        }
        BandError::Batch(BatchError::OutOfMemory { .. }) => PyMemoryError::new_err(e.to_string()),
        // Ctrl-C comes as the signal handler's own exception (`interrupt::detach`); this is for a
        // stop without it.
        BandError::Batch(BatchError::Stopped) => PyKeyboardInterrupt::new_err("the band was interrupted"),
        BandError::Batch(BatchError::Internal(_)) => PyRuntimeError::new_err(e.to_string()),
    }
}

/// One column of `items`: a list of texts when the values are names, else a float array.
pub fn column<'py, T>(py: Python<'py>, get: fn(&T) -> Value, items: &[T]) -> PyResult<Bound<'py, PyAny>> {
    let values: Vec<Value> = items.iter().map(get).collect();
    if !values.is_empty() && values.iter().all(|v| matches!(v, Value::Text(_))) {
        let texts: Vec<&str> = values.iter().map(|v| if let Value::Text(t) = v { *t } else { "" }).collect();
        return Ok(PyList::new(py, texts)?.into_any());
    }
    Ok(PyArray1::from_vec(py, values.iter().map(|v| number(*v)).collect()).into_any())
}

/// A value as a float (NaN for a name).
pub fn number(v: Value) -> f64 {
    match v {
        Value::Num(x) => x,
        Value::Int(n) => n as f64,
        Value::Text(_) => f64::NAN,
    }
}

/// pandas when a table is to be a DataFrame: `frame=True` (imported, or its ImportError),
/// `frame=None` (when installed), `frame=False` (never).
pub fn pandas(py: Python<'_>, frame: Option<bool>) -> PyResult<Option<Bound<'_, PyModule>>> {
    match frame {
        Some(false) => Ok(None),
        Some(true) => py.import("pandas").map(Some),
        None => match py.import("pandas") {
            Ok(m) => Ok(Some(m)),
            Err(e) if e.is_instance_of::<PyImportError>(py) => Ok(None),
            Err(e) => Err(e),
        },
    }
}

/// The table `columns` with the values `attrs` that belong to the whole table: a pandas
/// DataFrame with them in its `attrs` ([`pandas`] decides), else a `dict` of the columns whose
/// `attrs` attribute holds them (`ballscrew._columns.Columns`).
pub fn table<'py>(
    py: Python<'py>,
    columns: Bound<'py, PyDict>,
    attrs: Bound<'py, PyDict>,
    frame: Option<bool>,
) -> PyResult<Bound<'py, PyAny>> {
    match pandas(py, frame)? {
        Some(pd) => {
            let df = pd.getattr("DataFrame")?.call1((columns,))?;
            df.getattr("attrs")?.call_method1("update", (attrs,))?;
            Ok(df)
        }
        None => py.import("ballscrew._columns")?.getattr("Columns")?.call1((columns, attrs)),
    }
}
