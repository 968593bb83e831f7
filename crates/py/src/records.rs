//! Reported values as Python objects: the table of reported quantities
//! ([`ballscrew_batch::quantities`], the one the command line renders as CSV and JSON) read into
//! dicts and arrays, so a table from Python and one from the command line (`ballscrew torque`,
//! `sweep`, `inspect`) line up column for column under the same keys, scaled the same. Units are
//! in the keys.

use ballscrew_batch::quantities::{Quantity, Value};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The value as a Python object.
pub fn to_py<'py>(py: Python<'py>, v: Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        Value::Num(x) => x.into_pyobject(py)?.into_any(),
        Value::Int(n) => n.into_pyobject(py)?.into_any(),
        Value::Text(s) => s.into_pyobject(py)?.into_any(),
    })
}

/// Adds every quantity of `quantities` of `item` to `dict`, under its key.
pub fn fill<T>(dict: &Bound<'_, PyDict>, quantities: &[Quantity<T>], item: &T) -> PyResult<()> {
    for q in quantities {
        dict.set_item(q.key, to_py(dict.py(), (q.get)(item))?)?;
    }
    Ok(())
}
