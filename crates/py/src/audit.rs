//! The audit of a stateful Python object's warm answers against the canonical state
//! (`ballscrew_core::realtime::audit`), shared by `Evaluator` and `Reversal`: the
//! `audit_every` argument, the counts of one call, the `StateWarning` that says a call departed,
//! and the `audit` dict.

use crate::errors::{StateWarning, value_error};
use crate::numbers::index_text;
use crate::screw::describe;
use ballscrew_core::input::rad_s_to_rpm;
use ballscrew_core::realtime::audit::{Audit, Departure, F32_TOLERANCE, F64_TOLERANCE};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Points between two audited points by default (the first is audited): a cold solve per
/// 1000 warm points, 1.15 times the time of a lubricated drive cycle and 1.31 times a dry one
/// (docs/real-time.md, "Saying so").
pub const DEFAULT_AUDIT_EVERY: u32 = 1000;

/// The number of `audit_every` ([`DEFAULT_AUDIT_EVERY`] when not given): a whole number in
/// [0, 2^32 - 1]; else `ValueError` naming it.
pub fn audit_every(value: Option<&Bound<'_, PyAny>>) -> PyResult<u32> {
    let Some(v) = value else { return Ok(DEFAULT_AUDIT_EVERY) };
    v.extract::<u32>().map_err(|_| {
        let given = v.repr().map_or_else(|_| "?".to_string(), |r| r.to_string());
        value_error(format!(
            "invalid audit_every: {given} (valid: a whole number in [0, 4294967295]; 0 audits nothing)"
        ))
    })
}

/// The audit of an object computing in `precision` ("f64" or "f32", as `precision_name` gives
/// it) with the `audit_every` argument: its tolerance the precision's
/// ([`F64_TOLERANCE`], [`F32_TOLERANCE`]); `ValueError` naming `audit_every` when it is bad.
pub fn audit_of(precision: &str, audit_every: Option<&Bound<'_, PyAny>>) -> PyResult<Audit> {
    let tolerance = if precision == "f32" { F32_TOLERANCE } else { F64_TOLERANCE };
    Audit::new(self::audit_every(audit_every)?, tolerance).map_err(|e| value_error(e.to_string()))
}

/// The departures from the canonical state one call found: how many, the first (its flat
/// index among the call's points or steps), and the audit as it stood at the last (a copy
/// taken under the state's lock, so that the warning does not lock it again with the GIL held).
#[derive(Default)]
pub struct Departed {
    /// How many.
    pub count: usize,
    /// The first: its index and what it was.
    pub first: Option<(usize, Departure)>,
    /// The audit after the last departure.
    pub audit: Option<Audit>,
}

impl Departed {
    /// Notes the departure `d`, if any, of the call's item `index`, with the audit after it.
    pub fn note(&mut self, index: usize, d: Option<Departure>, audit: &Audit) {
        if let Some(d) = d {
            self.count += 1;
            self.first.get_or_insert((index, d));
            self.audit = Some(*audit);
        }
    }
}

/// Issues the [`StateWarning`] of a call's departures, if any: `what` names its items ("point",
/// "step"), `items` how many it had and `shape` their broadcast shape.
pub fn warn_departed(py: Python<'_>, departed: &Departed, what: &str, items: usize, shape: &[usize]) -> PyResult<()> {
    let (Some((index, d)), Some(audit)) = (departed.first, departed.audit) else { return Ok(()) };
    let at = if items > 1 { format!(" (index {} of the {what}s)", index_text(index, shape)) } else { String::new() };
    let text = format!(
        "{} audited {what}(s) of this call departed from the canonical state (the model's cold solve) by more than \
         {:e} of the drag torque: the first {}{at}: {d}; the warm solve follows its history and sits on another \
         steady state of the balls there ({} of {} audited so far)",
        departed.count,
        audit.tolerance(),
        describe(&d.op),
        audit.departed(),
        audit.audited(),
    );
    let warning = StateWarning::new_err(text).into_value(py);
    let w = warning.bind(py);
    w.setattr("count", departed.count)?;
    w.setattr("first_index", index)?;
    w.setattr("speed_rpm", rad_s_to_rpm(d.op.speed_rad_s))?;
    w.setattr("preload_n", d.op.preload_n)?;
    w.setattr("axial_load_n", d.op.axial_load_n)?;
    w.setattr("torque_nm", d.torque_nm)?;
    w.setattr("canonical_torque_nm", d.canonical_torque_nm)?;
    w.setattr("relative_departure", d.relative)?;
    py.import("warnings")?.call_method1("warn", (w, py.None(), 1))?;
    Ok(())
}

/// The `audit` property: the counts and the first departure, as a dict.
pub fn audit_dict<'py>(py: Python<'py>, a: &Audit) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("audit_every", a.every())?;
    d.set_item("tolerance", a.tolerance())?;
    d.set_item("calls", a.calls())?;
    d.set_item("audited", a.audited())?;
    d.set_item("departed", a.departed())?;
    d.set_item("largest_departure", a.largest_departure())?;
    let first = match a.first_departure() {
        None => py.None().into_bound(py),
        Some(f) => {
            let f_d = PyDict::new(py);
            f_d.set_item("preload_n", f.op.preload_n)?;
            f_d.set_item("speed_rpm", rad_s_to_rpm(f.op.speed_rad_s))?;
            f_d.set_item("axial_load_n", f.op.axial_load_n)?;
            f_d.set_item("torque_nm", f.torque_nm)?;
            f_d.set_item("canonical_torque_nm", f.canonical_torque_nm)?;
            f_d.set_item("relative_departure", f.relative)?;
            f_d.into_any()
        }
    };
    d.set_item("first_departure", first)?;
    Ok(d)
}
