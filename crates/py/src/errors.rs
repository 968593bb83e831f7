//! The core's errors as Python exceptions.
//!
//! Invalid specs and inputs raise `ValueError` with the core's message (the field, the value and
//! the valid range); a ball balance that does not converge, or a ball train without a steady
//! state, raises `ballscrew.ConvergenceError`, a subclass of `ValueError` (the inputs have no
//! quasi-static state the model can find). A file
//! that cannot be read raises Python's own `OSError` subclass (`FileNotFoundError`,
//! `IsADirectoryError`, `PermissionError`) with its `filename` ([`read_text`]).

use crate::batch::Errors;
use ballscrew_core::input::rad_s_to_rpm;
use ballscrew_core::screw::inertia;
use ballscrew_core::{Error, OperatingPoint, ScrewSpec};
use pyo3::exceptions::{
    PyFileNotFoundError, PyIsADirectoryError, PyOSError, PyPermissionError, PyRuntimeWarning, PyUserWarning,
    PyValueError,
};
use pyo3::prelude::*;
use std::path::Path;

pyo3::create_exception!(
    ballscrew,
    ConvergenceError,
    PyValueError,
    "The ball balance did not converge at an operating point, or the ball train of a circuit of \
     several loaded turns has no steady state found there (a ValueError: the inputs have no \
     quasi-static state the model can find, e.g. balls that skid)."
);

/// A `ValueError` with `message`.
pub fn value_error(message: impl core::fmt::Display) -> PyErr {
    PyValueError::new_err(message.to_string())
}

/// The core's error, with `context` (e.g. where in a batch) appended when not empty.
pub fn core_error(e: &Error, context: &str) -> PyErr {
    let text = if context.is_empty() { e.to_string() } else { format!("{e} {context}") };
    core_error_text(e, text)
}

/// The exception class of the core's error `e` (as [`core_error`]) with the message `text`.
pub fn core_error_text(e: &Error, text: String) -> PyErr {
    match e {
        Error::NoConvergence { .. } | Error::NoSteadyTrain { .. } => ConvergenceError::new_err(text),
        Error::Input(_) | Error::Unsupported { .. } => PyValueError::new_err(text),
    }
}

/// The text of the file at `path` (`what` says which, e.g. "spec file"), or the standard Python
/// exception of the operating system's error: `FileNotFoundError`, `IsADirectoryError`,
/// `PermissionError`, else `OSError`, each with its `errno`, `strerror` (`cannot read WHAT:
/// REASON`) and `filename`; a file that is not UTF-8 text raises `ValueError` naming it.
pub fn read_text(path: &Path, what: &str) -> PyResult<String> {
    std::fs::read_to_string(path).map_err(|e| io_error(&e, path, what))
}

/// The Python exception of the I/O error `e` on `path` (see [`read_text`]).
pub fn io_error(e: &std::io::Error, path: &Path, what: &str) -> PyErr {
    use std::io::ErrorKind;
    let name = path.display().to_string();
    if e.kind() == ErrorKind::InvalidData {
        return value_error(format!("{name}: cannot read {what}: not UTF-8 text ({e})"));
    }
    // The operating system's words without Rust's " (os error N)".
    let reason = e.to_string();
    let reason = reason.split(" (os error").next().unwrap_or(&reason).to_string();
    let args = (e.raw_os_error().unwrap_or(0), format!("cannot read {what}: {reason}"), name);
    match e.kind() {
        ErrorKind::NotFound => PyFileNotFoundError::new_err(args),
        ErrorKind::IsADirectory => PyIsADirectoryError::new_err(args),
        ErrorKind::PermissionDenied => PyPermissionError::new_err(args),
        _ => PyOSError::new_err(args),
    }
}

pyo3::create_exception!(
    ballscrew,
    EvaluationWarning,
    PyRuntimeWarning,
    "Points of a batch or sweep run with errors=\"nan\" that the model could not evaluate and that \
     came out NaN. Attributes: `count` (how many), `total` (of how many points), `first_index` \
     (the first one's flat index in C order) and `first_error` (why it failed)."
);

pyo3::create_exception!(
    ballscrew,
    StateWarning,
    PyRuntimeWarning,
    "Audited points of an `Evaluator` call whose warm torque departed from the canonical state (the \
     model's cold solve, what `Screw.torque` gives) by more than the audit's tolerance: the evaluator \
     follows its history and sits on another steady state of the balls. Attributes: `count` (this \
     call's departures), `first_index`, `speed_rpm`, `preload_n`, `axial_load_n`, `torque_nm`, \
     `canonical_torque_nm` and `relative_departure` (of the first)."
);

/// The policy `errors` names: "raise" or "nan"; else `ValueError` naming the argument.
pub fn parse_errors(errors: &str) -> PyResult<Errors> {
    match errors {
        "raise" => Ok(Errors::Raise),
        "nan" => Ok(Errors::Nan),
        other => Err(value_error(format!("invalid errors: {other:?} (valid: \"raise\" or \"nan\")"))),
    }
}

/// The values of a batch run under [`Errors`], each failed point NaN; when any failed, an
/// [`EvaluationWarning`] saying how many `what`s of how many, and the first one's reason as
/// `describe(index, error)` gives it.
pub fn report_failures<T: Into<f64>>(
    py: Python<'_>,
    results: Vec<Result<T, Error>>,
    what: &str,
    describe: impl Fn(usize, &Error) -> String,
) -> PyResult<Vec<f64>> {
    let total = results.len();
    let mut first = None;
    let mut count = 0usize;
    // Reserved at once: memory that runs out is a MemoryError, not an abort.
    let mut values = room_for(total)?;
    for (i, r) in results.into_iter().enumerate() {
        values.push(match r {
            Ok(v) => v.into(),
            Err(e) => {
                count += 1;
                first.get_or_insert((i, e));
                f64::NAN
            }
        });
    }
    if let Some((index, error)) = first {
        warn_failures(py, count, total, what, index, &describe(index, &error))?;
    }
    Ok(values)
}

/// Issues the [`EvaluationWarning`] of [`report_failures`]: `count` of `total` `what`s NaN, the
/// first at flat `index` for `reason`.
pub fn warn_failures(
    py: Python<'_>,
    count: usize,
    total: usize,
    what: &str,
    index: usize,
    reason: &str,
) -> PyResult<()> {
    let plural = if total == 1 { "" } else { "s" };
    let text = format!(
        "{count} of {total} {what}{plural} could not be evaluated and gave NaN (errors=\"nan\"); the first: {reason}"
    );
    let warning = EvaluationWarning::new_err(text).into_value(py);
    let w = warning.bind(py);
    w.setattr("count", count)?;
    w.setattr("total", total)?;
    w.setattr("first_index", index)?;
    w.setattr("first_error", reason)?;
    py.import("warnings")?.call_method1("warn", (w, py.None(), 1))?;
    Ok(())
}

pyo3::create_exception!(
    ballscrew,
    QuasiStaticWarning,
    PyUserWarning,
    "Operating points where the balls' inertia, which the quasi-static model leaves out (their \
     centrifugal force, their gyroscopic moment), is more than a quarter of what the contacts carry: \
     the torque there is an extrapolation (the command line prints the same warning). Attributes: \
     `count` (how many points), `total` (of how many), and the worst point's `speed_rpm`, \
     `preload_n` and `axial_load_n`."
);

/// Issues one [`QuasiStaticWarning`] when the balls' inertia is not small at any of `ops` (the
/// operating points of one call of `spec`'s model), naming the worst point and how many: the
/// core's `InertiaWarning`, the command line's text. `stacklevel` 1: the caller's line.
pub fn warn_quasi_static(
    py: Python<'_>,
    spec: &ScrewSpec,
    ops: impl IntoIterator<Item = OperatingPoint>,
) -> PyResult<()> {
    let Some(w) = inertia::check(spec, spec.helix_angle_rad(), ops) else {
        return Ok(());
    };
    let warning = QuasiStaticWarning::new_err(w.to_string()).into_value(py);
    let bound = warning.bind(py);
    bound.setattr("count", w.beyond)?;
    bound.setattr("total", w.total)?;
    bound.setattr("speed_rpm", rad_s_to_rpm(w.point.speed_rad_s))?;
    bound.setattr("preload_n", w.point.preload_n)?;
    bound.setattr("axial_load_n", w.point.axial_load_n)?;
    py.import("warnings")?.call_method1("warn", (bound, py.None(), 1))?;
    Ok(())
}

/// An empty vector with room for `n` items, or `MemoryError`.
pub fn room_for<T>(n: usize) -> PyResult<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(n)
        .map_err(|_| pyo3::exceptions::PyMemoryError::new_err(format!("not enough memory for {n} values")))?;
    Ok(v)
}
