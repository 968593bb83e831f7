//! `ballscrew.Evaluator`: the core's control-loop evaluator (`ballscrew_core::Evaluator`) in
//! f64 or f32, with its warm-start state, evaluated from Python.
//!
//! - `torque`: one operating point (floats), warm-started from the previous call;
//! - `series`: arrays broadcast together and evaluated in order (flattened C order) as a time
//!   series, each point warm-started from the one before, with the GIL released;
//! - `reset`: forget the warm state;
//! - `audit`: what the audit of the warm answers against the canonical state found
//!   (`ballscrew_core::realtime::audit`): every `audit_every`-th call is solved cold too, and a
//!   call that departs raises a `StateWarning`.
//!
//! A spec the control-loop evaluator does not take (the four-point balls of an oversize-ball
//! nut, FASTSIM contacts: `ballscrew_core::Evaluator::supports`) runs in f64 on the model's own
//! solve instead (`Model::torque` with its `SolverState`, warm-started the same way, as the FMU
//! does): the torques of `Screw.torque`, at the model's cost. f32 needs the evaluator and is
//! refused for such a spec, naming the option.
//!
//! Both entry points run the same loop over the same state (`Loop::run`), so a series equals
//! the scalar calls made in its order, bit for bit. Ctrl-C stops a series between two points
//! (`KeyboardInterrupt`, [`crate::interrupt`]); the state keeps the last point evaluated. The state sits behind a `Mutex`, so the class
//! stays `frozen` and may be shared between threads (calls on one evaluator take turns).

use crate::audit::{self, Departed, warn_departed};
use crate::batch::{BatchError, Errors, Never, Stop};
use crate::errors::room_for;
use crate::errors::{core_error, parse_errors, report_failures, value_error, warn_quasi_static};
use crate::interrupt;
use crate::numbers::index_text;
use crate::points::{self, Args, Points};
use crate::screw::{Screw, batch_error, describe};
use ballscrew_core::real::Real;
use ballscrew_core::realtime::audit::Audit;
use ballscrew_core::{Error, Evaluator as CoreEvaluator, OperatingPoint, ScrewSpec, Stepper};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyFloat, PyTuple};
use std::sync::Mutex;

/// The precisions an evaluator computes in, as `precision` names them.
const PRECISIONS: &str = "\"f64\", \"f32\"";

/// The float type `precision` names ("f64" when not given): "f64" or "f32"; anything else raises
/// `ValueError` naming the argument and its value.
pub(crate) fn precision_name(precision: Option<&Bound<'_, PyAny>>) -> PyResult<&'static str> {
    let name = precision.map_or(Some("f64".to_string()), |p| p.extract::<String>().ok());
    match name.as_deref() {
        Some("f64") => Ok("f64"),
        Some("f32") => Ok("f32"),
        _ => {
            let given = precision.and_then(|p| p.repr().ok()).map_or_else(|| "?".to_string(), |r| r.to_string());
            Err(value_error(format!("invalid precision: {given} (valid: {PRECISIONS})")))
        }
    }
}

/// What evaluates the torques in float type `F`, with its warm state (the core's
/// [`Stepper`]), and what it is.
struct Loop<F: Real> {
    /// The stepper and its audit (one lock: a call steps and audits together).
    solver: Mutex<(Stepper<F>, Audit)>,
    /// "evaluator" or "model".
    name: &'static str,
    /// The solve's tolerance.
    tolerance: f64,
}

impl<F: Real> Loop<F> {
    /// `solver` on the heap (tens of kB), audited by `audit`.
    fn boxed(solver: Stepper<F>, audit: Audit) -> Box<Self> {
        let (name, tolerance) = (solver.name(), solver.tolerance());
        Box::new(Self { solver: Mutex::new((solver, audit)), name, tolerance })
    }

    /// The torque (N m) of each point of `ops` into `out`, in order, each warm-started from the
    /// one before (the first from the stored state, which keeps the last), until `stop` says to
    /// stop (`Err(BatchError::Stopped)`); under [`Errors::Raise`] the first point that fails as
    /// a [`BatchError::Point`], under [`Errors::Nan`] each failing point's error in its slot (the
    /// next point warm-starts from what the failure left). Each torque is counted by the audit,
    /// which solves every so many cold and compares: `departed` counts this call's departures
    /// and keeps the first (its index, what it was).
    fn run(
        &self,
        ops: &[OperatingPoint],
        out: &mut [Result<f64, Error>],
        stop: &dyn Stop,
        errors: Errors,
        departed: &mut Departed,
    ) -> Result<(), BatchError> {
        // A poisoned lock only means a panic elsewhere; the state is plain data.
        let mut guard = self.solver.lock().unwrap_or_else(|p| p.into_inner());
        let (solver, audit) = &mut *guard;
        for (index, (op, t)) in ops.iter().zip(out.iter_mut()).enumerate() {
            if stop.stop() {
                return Err(BatchError::Stopped);
            }
            *t = solver.torque_nm(op);
            match (&*t, errors) {
                (Err(error), Errors::Raise) => return Err(BatchError::Point { index, error: *error }),
                (Ok(torque_nm), _) => {
                    let d = audit.check(solver.model(), op, *torque_nm);
                    departed.note(index, d, audit);
                }
                (Err(_), Errors::Nan) => {}
            }
        }
        Ok(())
    }

    fn reset(&self) {
        let mut guard = self.solver.lock().unwrap_or_else(|p| p.into_inner());
        guard.0.reset();
        guard.1.reset();
    }

    /// The audit so far.
    fn audit(&self) -> Audit {
        self.solver.lock().unwrap_or_else(|p| p.into_inner()).1
    }
}

/// A value in the precision asked for: the evaluator here, the reversal model in
/// [`crate::reversal`].
pub(crate) enum Precision<T64, T32> {
    F64(T64),
    F32(T32),
}

impl<T64, T32> Precision<T64, T32> {
    /// The float type, as `precision` names it: "f64" or "f32".
    pub(crate) fn name(&self) -> &'static str {
        match self {
            Precision::F64(_) => "f64",
            Precision::F32(_) => "f32",
        }
    }
}

/// The model's drive torque for a control loop or a drive simulation: the core's real-time
/// evaluator, in f64 (within 1e-8 of `Screw.torque`, but where a ball has two steady states) or
/// f32 (within 1e-4), about microseconds a
/// point, each call warm-started from the previous calls on the same evaluator.
///
/// `Evaluator(screw, precision="f64")`, `precision` "f64" or "f32". Building one takes a few
/// milliseconds (a start table of solved balls). Speeds are in rpm, loads in N, torques in N m. Specs
/// with `model.contact_theory = "fastsim"` or `geometry.preload = "oversize-ball"`, which the
/// evaluator does not take, run on the model's own solve in f64 (`solver == "model"`: the
/// torques of `Screw.torque`, at the model's cost: about 0.2 ms a warm point of a four-point
/// screw); in f32 they are refused (ValueError
/// naming the key). Invalid inputs raise
/// ValueError with the argument, the value and the valid range; a balance without solution
/// raises `ballscrew.ConvergenceError`.
#[pyclass(frozen, module = "ballscrew")]
pub struct Evaluator {
    inner: Precision<Box<Loop<f64>>, Box<Loop<f32>>>,
    /// The spec's operating point: the defaults of `speed_rpm` and `axial_load_n`.
    defaults: OperatingPoint,
    /// The screw's spec and origin (for pickling).
    spec: ScrewSpec,
    origin: String,
}

impl Evaluator {
    /// Torques of `ops` in order from the stored state (see [`Loop::run`]).
    fn run(
        &self,
        ops: &[OperatingPoint],
        out: &mut [Result<f64, Error>],
        stop: &dyn Stop,
        errors: Errors,
        departed: &mut Departed,
    ) -> Result<(), BatchError> {
        match &self.inner {
            Precision::F64(l) => l.run(ops, out, stop, errors, departed),
            Precision::F32(l) => l.run(ops, out, stop, errors, departed),
        }
    }

    /// The audit so far.
    fn audit_so_far(&self) -> Audit {
        match &self.inner {
            Precision::F64(l) => l.audit(),
            Precision::F32(l) => l.audit(),
        }
    }
}

#[pymethods]
impl Evaluator {
    /// An evaluator of `screw`'s model in `precision` ("f64", the default, or "f32").
    #[new]
    #[pyo3(
        signature = (screw, precision = None, *, audit_every = None),
        text_signature = "(screw, precision='f64', *, audit_every=1000)"
    )]
    fn new(
        py: Python<'_>,
        screw: &Bound<'_, Screw>,
        precision: Option<&Bound<'_, PyAny>>,
        audit_every: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let model = *screw.get().model();
        let name = precision_name(precision)?;
        let audit = audit::audit_of(name, audit_every)?;
        let built = match (CoreEvaluator::<f64>::supports(model.spec()), name) {
            (Ok(()), "f32") => py.detach(|| Stepper::evaluator(&model).map(|s| Precision::F32(Loop::boxed(s, audit)))),
            // The model solves what the evaluator does not take, in f64 only.
            (Err(e), "f32") => {
                return Err(value_error(format!(
                    "precision \"f32\" needs the control-loop evaluator, which does not take this spec: {e}; \
                     precision \"f64\" evaluates it on the model's own solve"
                )));
            }
            // The evaluator where it takes the spec, else the model's own solve.
            _ => py.detach(|| Stepper::new(&model).map(|s| Precision::F64(Loop::boxed(s, audit)))),
        };
        let inner = built.map_err(|e| core_error(&e, ""))?;
        let origin = screw.get().origin_text().to_string();
        Ok(Self { inner, defaults: model.spec().operating, spec: *model.spec(), origin })
    }

    /// Drive (drag) torque in N m at preload `preload_n` (N), speed `speed_rpm` (rpm, negative
    /// for reverse rotation) and external axial load `axial_load_n` (N); `None` takes the spec's
    /// operating value. Floats only (`series` takes arrays). Warm-started from the previous
    /// `torque` or `series` point on this evaluator.
    #[pyo3(signature = (preload_n, speed_rpm = None, axial_load_n = None))]
    fn torque<'py>(
        &self,
        py: Python<'py>,
        preload_n: &Bound<'py, PyAny>,
        speed_rpm: Option<&Bound<'py, PyAny>>,
        axial_load_n: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<f64> {
        let op = points::one_point(&Args { preload_n: Some(preload_n), speed_rpm, axial_load_n }, &self.defaults)?;
        let mut out = [Ok(0.0)];
        let mut departed = Departed::default();
        py.detach(|| self.run(&[op], &mut out, &Never, Errors::Raise, &mut departed)).map_err(|e| match e {
            BatchError::Point { error, .. } => core_error(&error, &describe(&op)),
            other => batch_error(&other, &[op], &[]),
        })?;
        let [t] = out;
        let t = t.map_err(|e| core_error(&e, &describe(&op)))?;
        warn_quasi_static(py, &self.spec, [op])?;
        warn_departed(py, &departed, "point", 1, &[])?;
        Ok(t)
    }

    /// Drive torque in N m over a time series: `preload_n` (N), `speed_rpm` (rpm) and
    /// `axial_load_n` (N) are broadcast together (numpy's rules; `None`: the spec's value) and
    /// the points evaluated in order, flattened in C order, each warm-started from the one
    /// before, the first from the evaluator's state, which keeps the last (as a drive's history
    /// does). The result is a float64 array of the broadcast shape (a float when every argument
    /// is a number or a 0-d array, as from `Screw.torque`), equal to calling `torque` point by
    /// point in the same order. Every point is checked first (ValueError naming the
    /// argument, the value, the valid range and the index; anything that is not a real number,
    /// as for `Screw.torque`, names the argument); the GIL is released while the points are
    /// evaluated. A point without solution raises `ConvergenceError` naming its index; the
    /// evaluator stays usable, warm from the points before it (and from the balls of the
    /// failing point that did solve; `reset` for a clean start). Ctrl-C stops the series
    /// between two points (KeyboardInterrupt), the evaluator warm from the last one evaluated.
    /// With `errors="nan"` a point without solution gives NaN instead and the series goes on
    /// (an `EvaluationWarning` says how many and why the first failed); bad arguments still
    /// raise.
    #[pyo3(signature = (preload_n, speed_rpm = None, axial_load_n = None, *, errors = "raise"))]
    fn series<'py>(
        &self,
        py: Python<'py>,
        preload_n: &Bound<'py, PyAny>,
        speed_rpm: Option<&Bound<'py, PyAny>>,
        axial_load_n: Option<&Bound<'py, PyAny>>,
        errors: &str,
    ) -> PyResult<Bound<'py, PyAny>> {
        let errors = parse_errors(errors)?;
        let args = Args { preload_n: Some(preload_n), speed_rpm, axial_load_n };
        let (shape, ops) = match points::points(&args, &self.defaults)? {
            Points::One(op) => (Vec::new(), vec![op]),
            Points::Many { shape, ops } => (shape, ops),
        };
        let mut out = room_for(ops.len())?;
        out.resize(ops.len(), Ok(0.0));
        let mut departed = Departed::default();
        interrupt::detach(py, |watch| self.run(&ops, &mut out, watch, errors, &mut departed))?
            .map_err(|e| batch_error(&e, &ops, &shape))?;
        let out = report_failures(py, out, "point", |i, e| {
            format!("{e} {} (index {} of the operating points)", describe(&ops[i]), index_text(i, &shape))
        })?;
        warn_quasi_static(py, &self.spec, ops.iter().copied())?;
        warn_departed(py, &departed, "point", ops.len(), &shape)?;
        // Numbers (or 0-d arrays) only: a float, as from `Screw.torque`.
        if let (true, [t]) = (shape.is_empty(), out.as_slice()) {
            return Ok(PyFloat::new(py, *t).into_any());
        }
        Ok(PyArray1::from_vec(py, out).reshape(shape)?.into_any())
    }

    /// Forgets the warm state: the next point starts cold (from the evaluator's table; on the
    /// model's solve, by its continuation). The audit's counts start again.
    fn reset(&self) {
        match &self.inner {
            Precision::F64(l) => l.reset(),
            Precision::F32(l) => l.reset(),
        }
    }

    /// What the audit of the warm answers found since the evaluator was built or reset: a dict
    /// of `audit_every`, `tolerance` (relative to the drag torque: 1e-6 in f64, 5e-4 in f32),
    /// `calls`, `audited` (solved cold too and compared), `departed` (audited calls whose torque
    /// departed from the canonical state by more than the tolerance), `largest_departure`
    /// (relative) and `first_departure` (None, or a dict of the point, `torque_nm`,
    /// `canonical_torque_nm` and `relative_departure`).
    #[getter]
    fn audit<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        // The state's lock is taken with the GIL released (a series holding it asks for the GIL).
        let a = py.detach(|| self.audit_so_far());
        audit::audit_dict(py, &a)
    }

    /// The float type the evaluator computes in: "f64" or "f32".
    #[getter]
    fn precision(&self) -> &'static str {
        self.inner.name()
    }

    /// Tolerance of the ball balance's solve on the residual (max norm of the force and moment
    /// imbalances over the nominal normal load, dimensionless): 1e-9 in f64, 1e-5 in f32; the
    /// model's 1e-12 where it solves (`solver == "model"`).
    #[getter]
    fn tolerance(&self) -> f64 {
        match &self.inner {
            Precision::F64(l) => l.tolerance,
            Precision::F32(l) => l.tolerance,
        }
    }

    /// What evaluates the torques: "evaluator" (the control-loop evaluator) or "model" (the
    /// model's own solve, in f64, for a spec the evaluator does not take: oversize-ball nuts,
    /// FASTSIM contacts).
    #[getter]
    fn solver(&self) -> &'static str {
        match &self.inner {
            Precision::F64(l) => l.name,
            Precision::F32(l) => l.name,
        }
    }

    /// Pickling (and `copy.copy`, `copy.deepcopy`): the screw (its spec, see `Screw`) and the
    /// precision. The warm state is not carried: the copy starts cold, as after `reset` (its
    /// torques agree with the original's to the solver's tolerance, and bit for bit with a new or
    /// reset evaluator's).
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let (py, this) = (slf.py(), slf.get());
        let screw = Bound::new(py, Screw::of_spec(&this.spec, this.origin.clone())?)?.into_any();
        let args = PyTuple::new(py, [screw, this.precision().into_pyobject(py)?.into_any()])?;
        let kwargs = PyDict::new(py);
        kwargs.set_item("audit_every", py.detach(|| this.audit_so_far()).every())?;
        // `functools.partial` carries the keyword argument.
        let partial = py.import("functools")?.getattr("partial")?.call((slf.get_type(),), Some(&kwargs))?;
        Ok((partial, args))
    }

    fn __repr__(&self) -> String {
        format!(
            "<ballscrew.Evaluator in {} on the {}, tolerance {:e}>",
            self.precision(),
            self.solver(),
            self.tolerance()
        )
    }
}
