//! Real numbers from Python arguments: the one conversion behind every number argument of the
//! module (operating points, a sweep's speed and axial load, the columns of `predict` and
//! `diagnose`).
//!
//! Accepted: Python ints and floats; numpy integer and floating scalars and arrays of any width
//! (int8 to uint64, float16 to longdouble); nested lists and tuples of those; anything else
//! numpy reads as integers or floats (e.g. a pandas Series); object arrays of real numbers
//! (`numbers.Real` or `decimal.Decimal`, e.g. `fractions.Fraction`).
//!
//! Refused with `ValueError` naming the argument (and the index of an element): bools (`True`
//! is not 1 N), complex numbers (numpy would drop the imaginary part), datetimes and timedeltas
//! (numpy's `datetime64` and `timedelta64`, Python's `datetime`: numpy would read a date as days
//! since 1970), texts (numpy would parse "2000"), `None`, numpy masked arrays (numpy would
//! ignore the mask: `.filled(value)` or dropping the masked points says what is meant), ints too
//! large for a float, and any other kind of value.

use crate::errors::value_error;
use numpy::ndarray::{ArrayD, ArrayViewD, IxDyn};
use numpy::{
    AllowTypeChange, PyArrayDescrMethods, PyArrayDyn, PyArrayLike, PyArrayMethods, PyUntypedArray,
    PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBool, PyBytes, PyComplex, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple, PyType};

/// What a number argument may be, as error messages say it.
pub const A_NUMBER: &str = "a real number";
/// What an argument taking numbers or arrays may be.
pub const NUMBERS: &str = "a real number or an array of real numbers";

/// Real numbers from one argument, as a float64 array (0-d for a number): numpy's own array when
/// numpy holds them as integers or floats (a copy only where a cast is needed), else converted
/// element by element.
#[derive(Debug)]
pub enum Reals<'py> {
    /// An integer or float array, as float64.
    Numpy(PyArrayLike<'py, f64, IxDyn, AllowTypeChange>),
    /// Numbers converted one by one (Python numbers, lists, object arrays).
    Owned(ArrayD<f64>),
}

impl Reals<'_> {
    /// The numbers.
    pub fn view(&self) -> ArrayViewD<'_, f64> {
        match self {
            Self::Numpy(a) => a.as_array(),
            Self::Owned(a) => a.view(),
        }
    }

    /// Their shape (`[]` for one number).
    pub fn shape(&self) -> &[usize] {
        match self {
            Self::Numpy(a) => a.shape(),
            Self::Owned(a) => a.shape(),
        }
    }
}

/// A shape or an index as Python writes a tuple: `()`, `(3,)`, `(2, 3)`.
pub fn tuple_text(items: &[usize]) -> String {
    let parts: Vec<String> = items.iter().map(|i| i.to_string()).collect();
    if parts.len() == 1 { format!("({},)", parts[0]) } else { format!("({})", parts.join(", ")) }
}

/// `(i, j, ...)`: the C-order multi-index of `flat` in `shape`.
pub fn index_text(flat: usize, shape: &[usize]) -> String {
    let mut rest = flat;
    let mut idx = vec![0; shape.len()];
    for (k, &n) in shape.iter().enumerate().rev() {
        if n > 0 {
            idx[k] = rest % n;
            rest /= n;
        }
    }
    tuple_text(&idx)
}

/// The value as an error message shows it: its `repr`, shortened when long; a huge int by its
/// number of digits.
pub fn shown(obj: &Bound<'_, PyAny>) -> String {
    const LONGEST: usize = 60;
    let text = obj.repr().map_or_else(|_| "?".to_string(), |r| r.to_string());
    if obj.is_instance_of::<PyInt>() && text.len() > LONGEST {
        return format!("an integer of {} digits", text.trim_start_matches('-').len());
    }
    if text.chars().count() > LONGEST {
        let head: String = text.chars().take(LONGEST - 3).collect();
        return format!("{head}...");
    }
    text
}

/// A Python float or int that is not a bool (numpy's float64 is a float): its value, or the
/// refusal of an int too large for a float; `None` for other objects.
fn plain(obj: &Bound<'_, PyAny>) -> Option<Result<f64, String>> {
    let int = obj.is_instance_of::<PyInt>() && !obj.is_instance_of::<PyBool>();
    if !(int || obj.is_instance_of::<PyFloat>()) {
        return None;
    }
    Some(obj.extract::<f64>().map_err(|_| format!("{} (too large for a float)", shown(obj))))
}

/// The types an element of an object array is checked against: refused although `numbers`
/// counts them as real numbers or numpy converts them to floats (bool, numpy's bool_,
/// datetime64, timedelta64), then accepted (`numbers.Real`, `decimal.Decimal`).
fn kinds(py: Python<'_>) -> PyResult<&(Py<PyTuple>, Py<PyTuple>)> {
    static KINDS: PyOnceLock<(Py<PyTuple>, Py<PyTuple>)> = PyOnceLock::new();
    KINDS.get_or_try_init(py, || {
        let np = py.import("numpy")?;
        // np.timedelta64 is registered as a numbers.Real (an integer subclass): refuse it first.
        let refused = PyTuple::new(
            py,
            [
                py.get_type::<PyBool>().into_any(),
                np.getattr("bool_")?,
                np.getattr("datetime64")?,
                np.getattr("timedelta64")?,
            ],
        )?;
        let accepted =
            PyTuple::new(py, [py.import("numbers")?.getattr("Real")?, py.import("decimal")?.getattr("Decimal")?])?;
        Ok((refused.unbind(), accepted.unbind()))
    })
}

/// One element of an object array (or a list) as a real number; the refusal text otherwise.
fn element(obj: &Bound<'_, PyAny>) -> PyResult<Result<f64, String>> {
    if let Some(x) = plain(obj) {
        return Ok(x);
    }
    // A 0-d array in a list (numpy keeps it whole in an object array): its value as Python has
    // it (a datetime64 gives a date, a bool_ a bool, and so on).
    if let Ok(a) = obj.cast::<PyUntypedArray>()
        && a.ndim() == 0
    {
        let item = obj.call_method0("item")?;
        if !item.is_instance_of::<PyUntypedArray>() {
            return element(&item).map(|x| x.map_err(|_| shown(obj)));
        }
    }
    let (refused, accepted) = kinds(obj.py())?;
    if !obj.is_instance(refused.bind(obj.py()))? && obj.is_instance(accepted.bind(obj.py()))? {
        return Ok(obj.extract::<f64>().map_err(|e| format!("{} ({e})", shown(obj))));
    }
    Ok(Err(shown(obj)))
}

/// The `ValueError` of argument `name` given as `given`, which may be `valid`.
pub fn refusal(name: &str, given: &str, valid: &str) -> PyErr {
    value_error(format!("invalid {name}: {given} (valid: {valid})"))
}

/// Whether `obj` is a numpy masked array.
fn masked(obj: &Bound<'_, PyAny>) -> PyResult<bool> {
    static MASKED: PyOnceLock<Py<PyType>> = PyOnceLock::new();
    obj.is_instance(MASKED.import(obj.py(), "numpy.ma", "MaskedArray")?)
}

/// The real numbers of argument `name` (see the module docs); errors say it may be `valid`.
pub fn reals<'py>(name: &str, obj: &Bound<'py, PyAny>, valid: &str) -> PyResult<Reals<'py>> {
    let py = obj.py();
    if let Some(x) = plain_number(name, obj, valid) {
        return x.map(|v| Reals::Owned(ArrayD::from_elem(IxDyn(&[]), v)));
    }
    let refuse = |given: String| refusal(name, &given, valid);
    if obj.is_none()
        || obj.is_instance_of::<PyBool>()
        || obj.is_instance_of::<PyComplex>()
        || obj.is_instance_of::<PyString>()
        || obj.is_instance_of::<PyBytes>()
    {
        return Err(refuse(shown(obj)));
    }
    if masked(obj)? {
        let valid = format!("{valid}; numpy would ignore the mask: pass .filled(value) or drop the masked points");
        return Err(refusal(name, "a masked array", &valid));
    }
    let array = if let Ok(a) = obj.cast::<PyUntypedArray>() {
        a.clone()
    } else {
        // Lists and tuples as objects, element by element: numpy would read [1000.0, True] as
        // [1000.0, 1.0].
        let kwargs = PyDict::new(py);
        if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
            kwargs.set_item("dtype", "object")?;
        }
        let asarray = py.import("numpy")?.getattr("asarray")?;
        let a = asarray.call((obj,), Some(&kwargs)).map_err(|e| refuse(format!("{} ({e})", shown(obj))))?;
        a.cast_into::<PyUntypedArray>().map_err(|e| refuse(format!("{} ({e})", shown(obj))))?
    };
    match array.dtype().kind() {
        b'f' | b'i' | b'u' => array.extract().map(Reals::Numpy).map_err(|e| refuse(format!("{} ({e})", shown(obj)))),
        b'O' => {
            let objects = array.cast::<PyArrayDyn<Py<PyAny>>>()?.readonly();
            let view = objects.as_array();
            let shape = view.shape().to_vec();
            let mut out = crate::errors::room_for(view.len())?;
            for (i, e) in view.iter().enumerate() {
                match element(e.bind(py))? {
                    Ok(x) => out.push(x),
                    Err(given) if shape.is_empty() => return Err(refuse(given)),
                    Err(given) => return Err(refuse(format!("{given} at index {}", index_text(i, &shape)))),
                }
            }
            ArrayD::from_shape_vec(IxDyn(&shape), out).map(Reals::Owned).map_err(value_error)
        }
        _ if array.ndim() == 0 => Err(refuse(shown(obj))),
        kind => {
            let what = match kind {
                b'b' => "bools",
                b'c' => "complex numbers",
                b'M' => "datetimes",
                b'm' => "timedeltas",
                b'U' | b'S' => "texts",
                _ => "values that are not numbers",
            };
            Err(refuse(format!("an array of {what} (dtype {})", array.dtype())))
        }
    }
}

/// Argument `name` when it is a Python float or int (not a bool): its value, or `ValueError`
/// saying it may be `valid` for an int too large for a float; `None` for other objects (the fast
/// path of one number, before [`reals`]).
pub fn plain_number(name: &str, obj: &Bound<'_, PyAny>, valid: &str) -> Option<PyResult<f64>> {
    plain(obj).map(|x| x.map_err(|given| refusal(name, &given, valid)))
}

/// Argument `name` as one real number (a 0-d array too); anything else, arrays included,
/// raises `ValueError` naming it.
pub fn real_number(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<f64> {
    let values = reals(name, obj, A_NUMBER)?;
    match values.view().first() {
        Some(&x) if values.shape().is_empty() => Ok(x),
        _ => Err(refusal(name, &shown(obj), A_NUMBER)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn indices_are_c_order() {
        assert_eq!(index_text(5, &[2, 3]), "(1, 2)");
        assert_eq!(index_text(7, &[10]), "(7,)");
        assert_eq!(index_text(0, &[]), "()");
        assert_eq!(tuple_text(&[2, 3]), "(2, 3)");
    }
}
