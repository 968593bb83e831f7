//! Operating points from Python arguments: real numbers or arrays of them (as
//! [`crate::numbers`] reads them: bools, complex numbers, datetimes, texts, `None` and masked
//! arrays are refused), broadcast together by numpy's rules.
//!
//! Speeds arrive in rpm and are checked as `speed_rpm`; preloads and axial loads in N. Every
//! point is validated by the core before anything is evaluated, so a NaN, an infinity or a value
//! out of range anywhere in a batch raises `ValueError` naming the argument, the value, the valid
//! range and the point's index, and nothing is computed.

use crate::errors::room_for;
use crate::errors::value_error;
use crate::numbers::{self, NUMBERS, index_text, tuple_text};
use ballscrew_core::input::{rad_s_to_rpm, rpm_to_rad_s};
use ballscrew_core::{InputError, OperatingPoint};
use numpy::ndarray::{ArrayViewD, IxDyn};
use pyo3::prelude::*;

/// Most operating points of one call (1e8: about 5 GB of inputs, results and work space, and
/// hours of evaluation); a larger broadcast shape raises `ValueError` before anything is
/// allocated, and an allocation that fails below it raises `MemoryError`, so no shape can abort
/// the interpreter.
pub const MAX_POINTS: usize = 100_000_000;

/// The three operating-point arguments as given (`None`: the spec's default).
#[derive(Debug, Clone, Copy)]
pub struct Args<'a, 'py> {
    /// `preload_n`.
    pub preload_n: Option<&'a Bound<'py, PyAny>>,
    /// `speed_rpm`.
    pub speed_rpm: Option<&'a Bound<'py, PyAny>>,
    /// `axial_load_n`.
    pub axial_load_n: Option<&'a Bound<'py, PyAny>>,
}

/// One point, or many in a shape.
#[derive(Debug, Clone, PartialEq)]
pub enum Points {
    /// Every argument was a scalar (or a 0-d array).
    One(OperatingPoint),
    /// The broadcast shape and its points in C order.
    Many {
        /// numpy shape of the result.
        shape: Vec<usize>,
        /// The points, flattened in C order.
        ops: Vec<OperatingPoint>,
    },
}

/// The operating point of (speed in rpm, preload in N, axial load in N), validated by the core;
/// an error names the Python argument (`speed_rpm`, not the core's `speed_rad_s`) and the value
/// as given.
pub fn operating_point(speed_rpm: f64, preload_n: f64, axial_load_n: f64) -> Result<OperatingPoint, InputError> {
    let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(speed_rpm), preload_n, axial_load_n };
    op.validate().map_err(|e| {
        if e.field == "speed_rad_s" { InputError { field: "speed_rpm", value: speed_rpm, ..e } } else { e }
    })?;
    Ok(op)
}

/// The broadcast shape of `shapes` by numpy's rules, or `None` when they do not broadcast.
pub fn broadcast_shape(shapes: &[&[usize]]) -> Option<Vec<usize>> {
    let ndim = shapes.iter().map(|s| s.len()).max().unwrap_or(0);
    let mut out = vec![1; ndim];
    for s in shapes {
        for (k, &n) in s.iter().rev().enumerate() {
            let o = &mut out[ndim - 1 - k];
            if *o == 1 {
                *o = n;
            } else if n != 1 && n != *o {
                return None;
            }
        }
    }
    Some(out)
}

/// The number of points of `shape`, when it is at most [`MAX_POINTS`].
pub fn point_count(shape: &[usize]) -> Option<usize> {
    shape.iter().try_fold(1usize, |n, &d| n.checked_mul(d)).filter(|&n| n <= MAX_POINTS)
}

/// The points of `args` over the spec's `defaults`, validated.
pub fn points(args: &Args<'_, '_>, defaults: &OperatingPoint) -> PyResult<Points> {
    let named = [
        ("preload_n", args.preload_n, defaults.preload_n),
        ("speed_rpm", args.speed_rpm, rad_s_to_rpm(defaults.speed_rad_s)),
        ("axial_load_n", args.axial_load_n, defaults.axial_load_n),
    ];
    // Fast path: three plain numbers.
    let mut values = [0.0; 3];
    let mut all_plain = true;
    for (v, (name, obj, default)) in values.iter_mut().zip(named) {
        match obj {
            None => *v = default,
            Some(o) => match numbers::plain_number(name, o, NUMBERS) {
                Some(x) => *v = x?,
                None => all_plain = false,
            },
        }
    }
    if all_plain {
        return operating_point(values[1], values[0], values[2]).map(Points::One).map_err(value_error);
    }
    let mut arrays = Vec::new();
    for (name, obj, _) in named {
        arrays.push(obj.map(|o| numbers::reals(name, o, NUMBERS)).transpose()?);
    }
    let shapes: Vec<&[usize]> = arrays.iter().flatten().map(|a| a.shape()).collect();
    let shape = broadcast_shape(&shapes).ok_or_else(|| {
        let list: Vec<String> = named
            .iter()
            .zip(&arrays)
            .filter_map(|((name, _, _), a)| a.as_ref().map(|a| format!("{name} {}", tuple_text(a.shape()))))
            .collect();
        value_error(format!("shapes do not broadcast together: {}", list.join(", ")))
    })?;
    let views: Vec<Option<ArrayViewD<'_, f64>>> = arrays.iter().map(|a| a.as_ref().map(|a| a.view())).collect();
    let n = point_count(&shape).ok_or_else(|| {
        value_error(format!(
            "invalid operating points: broadcast shape {} (valid: at most {MAX_POINTS} points)",
            tuple_text(&shape)
        ))
    })?;
    let mut columns: Vec<Vec<f64>> = Vec::with_capacity(3);
    for ((_, _, default), view) in named.iter().zip(&views) {
        let mut column = room_for(n)?;
        match view {
            None => column.resize(n, *default),
            Some(v) => column.extend(
                v.broadcast(IxDyn(&shape)).ok_or_else(|| value_error("shapes do not broadcast together"))?.iter(),
            ),
        }
        columns.push(column);
    }
    let mut ops = room_for(n)?;
    for i in 0..n {
        let op = operating_point(columns[1][i], columns[0][i], columns[2][i]).map_err(|e| {
            let (index, shape) = (index_text(i, &shape), tuple_text(&shape));
            value_error(format!("{e} at index {index} of the operating points (shape {shape})"))
        })?;
        ops.push(op);
    }
    if shape.is_empty() {
        return Ok(Points::One(ops[0]));
    }
    Ok(Points::Many { shape, ops })
}

/// Exactly one point of `args` over `defaults` (scalars); arrays raise `ValueError`.
pub fn one_point(args: &Args<'_, '_>, defaults: &OperatingPoint) -> PyResult<OperatingPoint> {
    match points(args, defaults)? {
        Points::One(op) => Ok(op),
        Points::Many { shape, .. } => Err(value_error(format!(
            "one operating point expected (scalars), got arrays of shape {}",
            tuple_text(&shape)
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_broadcast_by_numpys_rules() {
        assert_eq!(broadcast_shape(&[&[3], &[], &[1]]), Some(vec![3]));
        assert_eq!(broadcast_shape(&[&[4, 1], &[3]]), Some(vec![4, 3]));
        assert_eq!(broadcast_shape(&[&[2, 1, 5], &[3, 1]]), Some(vec![2, 3, 5]));
        assert_eq!(broadcast_shape(&[&[0], &[1]]), Some(vec![0]));
        assert_eq!(broadcast_shape(&[&[3], &[4]]), None);
        assert_eq!(broadcast_shape(&[&[2, 3], &[3, 2]]), None);
        assert_eq!(broadcast_shape(&[]), Some(vec![]));
    }

    #[test]
    fn point_counts_are_capped_without_overflow() {
        assert_eq!(point_count(&[]), Some(1));
        assert_eq!(point_count(&[2, 3]), Some(6));
        assert_eq!(point_count(&[0, usize::MAX]), Some(0));
        assert_eq!(point_count(&[MAX_POINTS]), Some(MAX_POINTS));
        assert_eq!(point_count(&[MAX_POINTS, 2]), None);
        assert_eq!(point_count(&[1 << 40, 1 << 40]), None);
    }

    #[test]
    fn speed_errors_name_the_rpm_argument_and_its_value() {
        let e = operating_point(1e9, 100.0, 0.0).unwrap_err();
        assert_eq!(e.to_string(), "invalid speed_rpm: 1e9 (valid: finite, |speed| <= 30000 rpm)");
        let e = operating_point(100.0, f64::NAN, 0.0).unwrap_err();
        assert!(e.to_string().starts_with("invalid preload_n: NaN (valid: "), "{e}");
        assert_eq!(operating_point(100.0, 1.0, 0.0).unwrap().speed_rad_s, rpm_to_rad_s(100.0));
    }
}
