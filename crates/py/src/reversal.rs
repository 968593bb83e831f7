//! `ballscrew.Reversal`: the friction torque through reversals (presliding) for a servo
//! simulation that steps the screw's rotation: the core's reversal state model
//! (`ballscrew_core::ReversalModel`, a Dahl friction state per circle of balls) in f64 or f32,
//! at one preload and axial load, with its state.
//!
//! - `step`: one step of rotation (rad) over a time step (s), the drive torque (N m) at its end;
//! - `series`: arrays of steps broadcast together and stepped in order (flattened C order), with
//!   the GIL released;
//! - `reset`: the relaxed state (no friction stored), or the steady state of a speed in rpm;
//! - `audit`: what the audit found: every `audit_every`-th step's steady torque (the torque its
//!   state settles on at the step's speed) is compared with the canonical state there
//!   (`ballscrew_core::realtime::audit`), a step that departs raising a `StateWarning`.
//!
//! Both `step` and `series` check their inputs with [`checked`] and run the same loop over the
//! same state (`Stepper::run`), so a series equals the scalar steps taken in its order, bit for
//! bit. Every step of a series is checked before the first is taken. Ctrl-C stops a series
//! between two steps (`KeyboardInterrupt`, [`crate::interrupt`]); the state keeps the steps
//! taken. The state sits behind a `Mutex` locked only with the GIL released, so the class stays
//! `frozen` and may be shared between threads (calls on one model take turns).

use crate::audit::{self, Departed, warn_departed};
use crate::batch::{BatchError, Never, Stop};
use crate::errors::room_for;
use crate::errors::{core_error, value_error};
use crate::evaluator::{Precision, precision_name};
use crate::interrupt;
use crate::numbers::{self, NUMBERS, index_text, real_number, refusal, tuple_text};
use crate::points::{MAX_POINTS, broadcast_shape, operating_point, point_count};
use crate::screw::{Screw, batch_error};
use ballscrew_core::input::{MAX_SPEED_RAD_S, rad_s_to_rpm, rpm_to_rad_s};
use ballscrew_core::real::Real;
use ballscrew_core::realtime::audit::Audit;
use ballscrew_core::{Error, EvalState, Evaluator, Model, ReversalModel, ReversalState, ScrewSpec, Shown};
use numpy::ndarray::IxDyn;
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use std::sync::{Mutex, MutexGuard};

use ballscrew_core::realtime::reversal::check_step as checked;

/// A state as pickled: the friction torques and the evaluator's memory (exact in f64).
type Saved = (Vec<f64>, Vec<f64>);

/// The reversal model in float type `F` and its state.
struct Stepper<F: Real> {
    model: ReversalModel<F>,
    /// The state and the audit of its steady torques (one lock: a step steps and audits).
    state: Mutex<(ReversalState<F>, Audit)>,
}

impl<F: Real + Send + Sync> Stepper<F> {
    /// The reversal model of `model` at `preload_n` and `axial_load_n` (N), relaxed, on the heap
    /// (it holds an evaluator: tens of kB).
    fn boxed(model: &Model, preload_n: f64, axial_load_n: f64, audit: Audit) -> Result<Box<Self>, Error> {
        let evaluator = Evaluator::<F>::new(model)?;
        let model = ReversalModel::new(&evaluator, preload_n, axial_load_n)?;
        Ok(Box::new(Self { state: Mutex::new((model.relaxed(), audit)), model }))
    }

    /// The state and the audit (a poisoned lock only means a panic elsewhere; both are plain
    /// data).
    fn locked(&self) -> MutexGuard<'_, (ReversalState<F>, Audit)> {
        self.state.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// The audit so far.
    fn audit(&self) -> Audit {
        self.locked().1
    }

    /// The drive torque (N m) after each of `steps` (checked by [`checked`]) into `out`, in
    /// order from the stored state, which keeps the last step taken, until `stop` says to stop
    /// (`Err(BatchError::Stopped)`); the first step that fails as a [`BatchError::Point`]. Each
    /// step that turns is counted by the audit, which compares every so many steps' steady
    /// torque with the canonical one: `departed` counts this call's departures.
    fn run(
        &self,
        steps: &[(F, F)],
        out: &mut [f64],
        stop: &dyn Stop,
        departed: &mut Departed,
    ) -> Result<(), BatchError> {
        let mut guard = self.locked();
        let (state, audit) = &mut *guard;
        let model = *self.model.model();
        for (index, (&(rotation, dt), t)) in steps.iter().zip(out.iter_mut()).enumerate() {
            if stop.stop() {
                return Err(BatchError::Stopped);
            }
            *t = self.model.step(rotation, dt, state).map_err(|error| BatchError::Point { index, error })?.to_f64();
            if rotation != F::zero() {
                let speed = rotation.to_f64() / dt.to_f64();
                let steady = || self.model.steady_torque_at(speed, state).ok().map(|(op, t)| (op, t.to_f64()));
                let d = audit.check_lazily(&model, steady);
                departed.note(index, d, audit);
            }
        }
        Ok(())
    }

    /// The relaxed state (`None`) or the steady state at `speed_rad_s` (rad/s, nonzero in `F`);
    /// on an error the state stays as it was.
    fn reset(&self, speed_rad_s: Option<f64>) -> Result<(), Error> {
        let new = match speed_rad_s {
            None => self.model.relaxed(),
            // Within the speed range: 30000 rpm, its top, is the f32 below it in f32.
            Some(w) => self.model.steady(F::of_within(w, -MAX_SPEED_RAD_S, MAX_SPEED_RAD_S))?,
        };
        let mut guard = self.locked();
        guard.0 = new;
        guard.1.reset();
        Ok(())
    }

    fn friction_nm(&self) -> f64 {
        self.locked().0.friction_nm().to_f64()
    }

    /// The friction torques of the state (`ReversalState::friction_values`) and the
    /// evaluator's memory it carries (`EvalState::values`), exact in f64.
    fn saved(&self) -> Saved {
        let guard = self.locked();
        let state = &guard.0;
        (state.friction_values().map(Real::to_f64).collect(), state.evaluator_state().values().collect())
    }

    /// Sets the state's friction torques (`ReversalModel::with_friction`) and the evaluator's
    /// memory (cold when `None`); on an error the state stays as it was.
    fn restore(&self, friction: &[f64], evaluator: Option<&[f64]>) -> Result<(), Error> {
        let values: Vec<F> = friction.iter().map(|&v| F::of(v)).collect();
        let mut state = self.model.with_friction(&values)?;
        if let Some(memory) = evaluator {
            state.set_evaluator_state(EvalState::from_values(memory)?);
        }
        self.locked().0 = state;
        Ok(())
    }

    fn stiffness_nm_per_rad(&self) -> f64 {
        self.model.stiffness_nm_per_rad().to_f64()
    }

    /// The steps of `rotation_rad` and `dt_s` (broadcast, C order), every one checked before any
    /// is taken, then taken in order with the GIL released (Ctrl-C stops between two).
    fn series(&self, py: Python<'_>, rotation_rad: &[f64], dt_s: &[f64], shape: &[usize]) -> PyResult<Vec<f64>> {
        let mut steps = room_for(rotation_rad.len())?;
        for (i, (&r, &d)) in rotation_rad.iter().zip(dt_s).enumerate() {
            steps.push(checked::<F>(r, d).map_err(|e| {
                value_error(format!("{e} at index {} of the steps (shape {})", index_text(i, shape), tuple_text(shape)))
            })?);
        }
        let mut out = room_for(steps.len())?;
        out.resize(steps.len(), 0.0);
        let mut departed = Departed::default();
        interrupt::detach(py, |watch| self.run(&steps, &mut out, watch, &mut departed))?.map_err(|e| match e {
            BatchError::Point { index, error } => {
                let at = describe(rotation_rad[index], dt_s[index]);
                core_error(&error, &format!("{at} (index {} of the steps)", index_text(index, shape)))
            }
            other => batch_error(&other, &[], shape),
        })?;
        warn_departed(py, &departed, "step", steps.len(), shape)?;
        Ok(out)
    }

    /// One step, with the GIL released.
    fn step(&self, py: Python<'_>, rotation_rad: f64, dt_s: f64) -> PyResult<f64> {
        let step = checked::<F>(rotation_rad, dt_s).map_err(value_error)?;
        let mut out = [0.0];
        let mut departed = Departed::default();
        py.detach(|| self.run(&[step], &mut out, &Never, &mut departed)).map_err(|e| match e {
            BatchError::Point { error, .. } => core_error(&error, &describe(rotation_rad, dt_s)),
            other => batch_error(&other, &[], &[]),
        })?;
        warn_departed(py, &departed, "step", 1, &[])?;
        Ok(out[0])
    }
}

/// `at rotation_rad 0.001, dt_s 1e-4` (numbers in short form).
fn describe(rotation_rad: f64, dt_s: f64) -> String {
    format!("at rotation_rad {}, dt_s {}", Shown(rotation_rad), Shown(dt_s))
}

/// The model in the precision asked for.
type Steppers = Precision<Box<Stepper<f64>>, Box<Stepper<f32>>>;

/// Runs `$body` with `$s` bound to the stepper, whatever its precision.
macro_rules! with_stepper {
    ($inner:expr, $s:ident => $body:expr) => {
        match $inner {
            Precision::F64($s) => $body,
            Precision::F32($s) => $body,
        }
    };
}

/// The drive torque through reversals, for a servo simulation that steps the screw's rotation:
/// a friction state per circle of balls that re-forms over the small rotation after a reversal
/// (presliding, Dahl's law; the quadrant glitch of friction feed-forward), whose steady state at
/// a constant speed above the standstill speed is the static model's torque (`Screw.torque`,
/// within 1e-8 in f64 and 1e-4 in f32).
///
/// `Reversal(screw, preload_n=None, axial_load_n=None, precision="f64")`: the model of `screw`
/// at preload `preload_n` (N) and external axial load `axial_load_n` (N), `None` taking the
/// spec's operating value; `precision` "f64" or "f32". Building one takes a fraction of a second
/// (the evaluator's start table and two evaluations of the model for the stiffness, at the
/// spec's operating speed). It starts relaxed (no friction stored). Rotations are in rad (the
/// screw's angle), time steps in s, speeds in rpm, loads in N, torques in N m. Specs with
/// extension terms or `model.contact_theory = "fastsim"` are refused (ValueError naming the
/// field). Invalid inputs raise ValueError with the argument, the value and the valid range; a
/// balance without solution raises `ballscrew.ConvergenceError`.
#[pyclass(frozen, module = "ballscrew")]
pub struct Reversal {
    inner: Steppers,
    preload_n: f64,
    axial_load_n: f64,
    /// The screw's spec and origin (for pickling).
    spec: ScrewSpec,
    origin: String,
}

#[pymethods]
impl Reversal {
    /// The reversal model of `screw` at `preload_n` and `axial_load_n` (N; `None`: the spec's
    /// operating value) in `precision` ("f64", the default, or "f32"), relaxed.
    #[new]
    #[pyo3(
        signature = (screw, preload_n = None, axial_load_n = None, precision = None, *, audit_every = None),
        text_signature = "(screw, preload_n=None, axial_load_n=None, precision='f64', *, audit_every=1000)"
    )]
    fn new(
        py: Python<'_>,
        screw: &Bound<'_, Screw>,
        preload_n: Option<&Bound<'_, PyAny>>,
        axial_load_n: Option<&Bound<'_, PyAny>>,
        precision: Option<&Bound<'_, PyAny>>,
        audit_every: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let model = *screw.get().model();
        let origin = screw.get().origin_text().to_string();
        let defaults = model.spec().operating;
        let preload_n = preload_n.map_or(Ok(defaults.preload_n), |p| real_number("preload_n", p))?;
        let axial_load_n = axial_load_n.map_or(Ok(defaults.axial_load_n), |a| real_number("axial_load_n", a))?;
        let name = precision_name(precision)?;
        let audit = audit::audit_of(name, audit_every)?;
        // The loads' ranges before the heavy part (the core checks them again).
        operating_point(rad_s_to_rpm(defaults.speed_rad_s), preload_n, axial_load_n).map_err(value_error)?;
        let built = match name {
            "f32" => py.detach(|| Stepper::boxed(&model, preload_n, axial_load_n, audit).map(Precision::F32)),
            _ => py.detach(|| Stepper::boxed(&model, preload_n, axial_load_n, audit).map(Precision::F64)),
        };
        let context =
            format!("(reversal model at preload_n {}, axial_load_n {})", Shown(preload_n), Shown(axial_load_n));
        let inner = built.map_err(|e| match e {
            Error::NoConvergence { .. } | Error::NoSteadyTrain { .. } => core_error(&e, &context),
            _ => core_error(&e, ""),
        })?;
        Ok(Self { inner, preload_n, axial_load_n, spec: *model.spec(), origin })
    }

    /// Turns the screw by `rotation_rad` (rad, signed: negative backwards) over the time step
    /// `dt_s` (s, > 0) and returns the drive torque in N m at the step's end: the circles'
    /// friction torques, the axial load's torque and the seals. The step's speed
    /// `rotation_rad / dt_s` sets each circle's steady friction (the model's torque-speed curve);
    /// a step of zero rotation keeps the friction stored. Floats only (`series` takes arrays).
    #[pyo3(signature = (rotation_rad, dt_s))]
    fn step(&self, py: Python<'_>, rotation_rad: &Bound<'_, PyAny>, dt_s: &Bound<'_, PyAny>) -> PyResult<f64> {
        let (rotation, dt) = (real_number("rotation_rad", rotation_rad)?, real_number("dt_s", dt_s)?);
        with_stepper!(&self.inner, s => s.step(py, rotation, dt))
    }

    /// Drive torque in N m after each of a series of steps: `rotation_rad` (rad per step) and
    /// `dt_s` (s per step) are broadcast together (numpy's rules) and the steps taken in order,
    /// flattened in C order, from the model's state, which keeps the last (as a drive's history
    /// does). The result is a float64 array of the broadcast shape, equal bit for bit to calling
    /// `step` step by step in the same order. Every step is checked first (ValueError naming
    /// the argument, the value, the valid range and the index; anything that is not a real
    /// number names the argument); the GIL is released while the steps are taken. A step
    /// without solution raises `ConvergenceError` naming its index, the state keeping the steps
    /// before it. Ctrl-C stops the series between two steps (KeyboardInterrupt), the state
    /// keeping the steps taken.
    #[pyo3(signature = (rotation_rad, dt_s))]
    fn series<'py>(
        &self,
        py: Python<'py>,
        rotation_rad: &Bound<'py, PyAny>,
        dt_s: &Bound<'py, PyAny>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (shape, rotation, dt) = broadcast_steps(rotation_rad, dt_s)?;
        let out = with_stepper!(&self.inner, s => s.series(py, &rotation, &dt, &shape))?;
        Ok(PyArray1::from_vec(py, out).reshape(shape)?.into_any())
    }

    /// Sets the state: `speed_rpm=None` (the default) the relaxed state, no friction stored (the
    /// screw at rest after assembly); a speed in rpm (nonzero, negative for reverse rotation)
    /// the steady state of the screw running at that speed. On an error the state is kept.
    #[pyo3(signature = (speed_rpm = None))]
    fn reset(&self, py: Python<'_>, speed_rpm: Option<&Bound<'_, PyAny>>) -> PyResult<()> {
        let speed = match speed_rpm {
            None => None,
            Some(obj) => {
                let rpm = real_number("speed_rpm", obj)?;
                operating_point(rpm, self.preload_n, self.axial_load_n).map_err(value_error)?;
                let w = rpm_to_rad_s(rpm);
                let (zero, valid) = match self.inner {
                    Precision::F64(_) => (w == 0.0, "nonzero, |speed| <= 30000 rpm; None for the relaxed state"),
                    Precision::F32(_) => (
                        f64::from(w as f32) == 0.0,
                        "nonzero (|speed| at least 1.4e-44 rpm in f32), |speed| <= 30000 rpm; None for the relaxed state",
                    ),
                };
                if zero {
                    let shown = ballscrew_core::Measured { value: rpm, field: "speed_rpm", valid }.to_string();
                    return Err(refusal("speed_rpm", &shown, valid));
                }
                Some((rpm, w))
            }
        };
        py.detach(|| with_stepper!(&self.inner, s => s.reset(speed.map(|(_, w)| w)))).map_err(|e| {
            core_error(&e, &speed.map_or_else(String::new, |(rpm, _)| format!("at speed_rpm {}", Shown(rpm))))
        })
    }

    /// The float type the model computes in: "f64" or "f32".
    #[getter]
    fn precision(&self) -> &'static str {
        self.inner.name()
    }

    /// What the audit found since the model was built or reset: the first turning step and
    /// every `audit_every`-th after it compare the steady torque the state settles on at the
    /// step's speed (at least the standstill speed) with the canonical torque there; a dict of
    /// `audit_every`, `tolerance` (relative to the drag torque: 1e-6 in f64, 5e-4 in f32),
    /// `calls` (steps that turn), `audited`, `departed`, `largest_departure` and
    /// `first_departure` (None, or a dict of the point, `torque_nm`, `canonical_torque_nm` and
    /// `relative_departure`).
    #[getter]
    fn audit<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let a = py.detach(|| with_stepper!(&self.inner, s => s.audit()));
        audit::audit_dict(py, &a)
    }

    /// The preload the model was built at, N.
    #[getter]
    fn preload_n(&self) -> f64 {
        self.preload_n
    }

    /// The external axial load the model was built at, N.
    #[getter]
    fn axial_load_n(&self) -> f64 {
        self.axial_load_n
    }

    /// Dahl's stiffness summed over the circles and mechanisms, N m/rad: the initial slope of the
    /// friction torque against the screw's angle turning from the relaxed state (either way);
    /// after a reversal from steady running the slope starts near twice it (exactly twice where
    /// each state's steady friction is the same both ways). From the contacts at the spec's
    /// operating speed, the mean of the two directions.
    #[getter]
    fn stiffness_nm_per_rad(&self) -> f64 {
        with_stepper!(&self.inner, s => s.stiffness_nm_per_rad())
    }

    /// The friction torque the state holds now (all circles), N m, signed as the drive torque:
    /// without the axial load's torque and the seals (0 when relaxed).
    #[getter]
    fn friction_nm(&self, py: Python<'_>) -> f64 {
        py.detach(|| with_stepper!(&self.inner, s => s.friction_nm()))
    }

    /// Pickling (and `copy.copy`, `copy.deepcopy`): the screw (its spec, see `Screw`), the
    /// preload, the axial load and the precision, and the state: the friction torques it holds
    /// and the evaluator's warm-start memory, so that the copy continues bit for bit as the
    /// original.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>, Saved)> {
        let py = slf.py();
        let this = slf.get();
        let screw = Bound::new(py, Screw::of_spec(&this.spec, this.origin.clone())?)?;
        let args = PyTuple::new(
            py,
            [
                screw.into_any(),
                this.preload_n.into_pyobject(py)?.into_any(),
                this.axial_load_n.into_pyobject(py)?.into_any(),
                this.precision().into_pyobject(py)?.into_any(),
            ],
        )?;
        let saved = py.detach(|| with_stepper!(&this.inner, s => s.saved()));
        let kwargs = PyDict::new(py);
        kwargs.set_item("audit_every", py.detach(|| with_stepper!(&this.inner, s => s.audit())).every())?;
        // `functools.partial` carries the keyword argument.
        let partial = py.import("functools")?.getattr("partial")?.call((slf.get_type(),), Some(&kwargs))?;
        Ok((partial, args, saved))
    }

    /// Sets a pickle's state (see `__reduce__`): the model's friction values and the evaluator's
    /// memory, so that the copy continues bit for bit as the original; ValueError unless they
    /// fit the model.
    fn __setstate__(&self, py: Python<'_>, state: &Bound<'_, PyAny>) -> PyResult<()> {
        let (friction, memory): (Vec<f64>, Vec<f64>) =
            state.extract().map_err(|_| value_error("invalid pickled Reversal: state"))?;
        py.detach(|| with_stepper!(&self.inner, s => s.restore(&friction, Some(&memory))))
            .map_err(|e| value_error(format!("invalid pickled Reversal: {e}")))
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        format!(
            "<ballscrew.Reversal in {} at preload_n {}, axial_load_n {}; friction_nm {}>",
            self.precision(),
            Shown(self.preload_n),
            Shown(self.axial_load_n),
            Shown(self.friction_nm(py))
        )
    }
}

/// `rotation_rad` and `dt_s` as real numbers broadcast together: the shape and both in C order.
fn broadcast_steps(
    rotation_rad: &Bound<'_, PyAny>,
    dt_s: &Bound<'_, PyAny>,
) -> PyResult<(Vec<usize>, Vec<f64>, Vec<f64>)> {
    // Fast path: two plain numbers.
    if let (Some(r), Some(d)) =
        (numbers::plain_number("rotation_rad", rotation_rad, NUMBERS), numbers::plain_number("dt_s", dt_s, NUMBERS))
    {
        return Ok((Vec::new(), vec![r?], vec![d?]));
    }
    let named = [
        ("rotation_rad", numbers::reals("rotation_rad", rotation_rad, NUMBERS)?),
        ("dt_s", numbers::reals("dt_s", dt_s, NUMBERS)?),
    ];
    let shape = broadcast_shape(&[named[0].1.shape(), named[1].1.shape()]).ok_or_else(|| {
        let list: Vec<String> = named.iter().map(|(name, a)| format!("{name} {}", tuple_text(a.shape()))).collect();
        value_error(format!("shapes do not broadcast together: {}", list.join(", ")))
    })?;
    let n = point_count(&shape).ok_or_else(|| {
        value_error(format!(
            "invalid steps: broadcast shape {} (valid: at most {MAX_POINTS} steps)",
            tuple_text(&shape)
        ))
    })?;
    let mut columns = Vec::with_capacity(2);
    for (_, values) in &named {
        let mut column = room_for(n)?;
        let view = values.view();
        column.extend(
            view.broadcast(IxDyn(&shape)).ok_or_else(|| value_error("shapes do not broadcast together"))?.iter(),
        );
        columns.push(column);
    }
    let dt = columns.pop().unwrap_or_default();
    let rotation = columns.pop().unwrap_or_default();
    Ok((shape, rotation, dt))
}
