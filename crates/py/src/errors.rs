//! The core's errors as Python exceptions.
//!
//! Invalid specs and inputs raise `ValueError` with the core's message (the field, the value and
//! the valid range); a ball balance that does not converge raises `ballscrew.ConvergenceError`,
//! a subclass of `ValueError` (the inputs have no quasi-static state the model can find).

use ballscrew_core::Error;
use pyo3::PyErr;
use pyo3::exceptions::PyValueError;

pyo3::create_exception!(
    ballscrew,
    ConvergenceError,
    PyValueError,
    "The ball balance did not converge at an operating point (a ValueError: the inputs have no \
     quasi-static state the model can find, e.g. balls that skid)."
);

/// A `ValueError` with `message`.
pub fn value_error(message: impl core::fmt::Display) -> PyErr {
    PyValueError::new_err(message.to_string())
}

/// The core's error, with `context` (e.g. where in a batch) appended when not empty.
pub fn core_error(e: &Error, context: &str) -> PyErr {
    let text = if context.is_empty() { e.to_string() } else { format!("{e} {context}") };
    match e {
        Error::NoConvergence { .. } => ConvergenceError::new_err(text),
        Error::Input(_) | Error::Unsupported { .. } => PyValueError::new_err(text),
    }
}
