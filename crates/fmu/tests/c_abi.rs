//! The FMU's C ABI called as an importer calls it: statuses, logged messages, null pointers
//! and bad value references (an error, never a crash), and the outputs against the core's
//! evaluator driven the same way.
//!
//! The logger here is a fixed-argument function `(env, name, status, category, message)` called
//! through FMI's variadic logger type: on x86-64 System V (the platform the FMU is built for) a
//! call with no variadic argument passes the fixed ones as a fixed-argument call does. The FMU
//! passes its message as the format with every `%` doubled, and no further argument.
#![cfg(all(target_arch = "x86_64", target_os = "linux"))]
#![allow(unsafe_code, reason = "the test calls the FMU's C functions")]
#![expect(clippy::std_instead_of_core, reason = "a std test program")]

use ballscrew_config::DKFZD4012_TOML;
use ballscrew_core::{EvalState, Evaluator, Model, OperatingPoint, SolverState};
use ballscrew_fmu::ffi::{self, Fmi2CallbackFunctions, Fmi2CallbackLogger, Fmi2Component, status_kind};
use ballscrew_fmu::instance::Status;
use ballscrew_fmu::model_description::guid;
use ballscrew_fmu::variables::{AXIAL_LOAD_N, DRAG_TORQUE_NM, PRELOAD_N, SPEED_RAD_S, TORQUE_NM};
use std::cell::RefCell;
extern crate alloc;
use alloc::ffi::CString;
use std::ffi::{CStr, c_char, c_int, c_void};
use std::ptr::{null, null_mut};

type Log = RefCell<Vec<(c_int, String)>>;

/// The logger's type without the variadic part.
type Fixed = unsafe extern "C" fn(*mut c_void, *const c_char, c_int, *const c_char, *const c_char);

/// Records `(status, message)` into the `Log` that `env` points at.
unsafe extern "C" fn record(
    env: *mut c_void,
    _name: *const c_char,
    status: c_int,
    _category: *const c_char,
    format: *const c_char,
) {
    // SAFETY: `env` is the `Log` of the test that instantiated; the strings are C strings.
    unsafe {
        let log = &*env.cast::<Log>();
        let text = CStr::from_ptr(format).to_string_lossy().replace("%%", "%");
        log.borrow_mut().push((status, text));
    }
}

fn callbacks(log: &Log) -> Fmi2CallbackFunctions {
    let fixed: Fixed = record;
    // SAFETY: see the module's documentation (x86-64 System V passes both alike).
    let logger = unsafe { std::mem::transmute::<Fixed, Fmi2CallbackLogger>(fixed) };
    Fmi2CallbackFunctions {
        logger: Some(logger),
        allocate_memory: None,
        free_memory: None,
        step_finished: None,
        component_environment: std::ptr::from_ref(log).cast_mut().cast(),
    }
}

/// A resources folder holding `spec` as `spec.toml`, and its `file://` URI.
fn resources(spec: &str) -> (tempfile::TempDir, CString) {
    let dir = tempfile::Builder::new().prefix("fmu res ").tempdir().unwrap();
    std::fs::write(dir.path().join("spec.toml"), spec).unwrap();
    let path = dir.path().to_str().unwrap().replace(' ', "%20");
    (dir, CString::new(format!("file://{path}/")).unwrap())
}

fn instantiate(spec: &str, guid_text: &str, log: &Log) -> Fmi2Component {
    let (_dir, uri) = resources(spec);
    let guid_c = CString::new(guid_text).unwrap();
    let cb = callbacks(log);
    // SAFETY: valid C strings and callbacks that outlive the call (the spec is read in it).
    unsafe { ffi::fmi2Instantiate(c"screw".as_ptr(), 1, guid_c.as_ptr(), uri.as_ptr(), &cb, 0, 0) }
}

fn errors(log: &Log) -> Vec<String> {
    log.borrow().iter().filter(|(s, _)| *s == Status::Error as c_int).map(|(_, m)| m.clone()).collect()
}

#[test]
fn platform_and_version() {
    assert_eq!(unsafe { CStr::from_ptr(ffi::fmi2GetTypesPlatform()) }, c"default");
    assert_eq!(unsafe { CStr::from_ptr(ffi::fmi2GetVersion()) }, c"2.0");
}

#[test]
fn null_component_is_an_error_everywhere() {
    let c = null_mut();
    let mut x = 0.0;
    let vr = 0u32;
    // SAFETY: a null component is what is tested; the other pointers are valid.
    unsafe {
        assert_eq!(ffi::fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), Status::Error);
        assert_eq!(ffi::fmi2EnterInitializationMode(c), Status::Error);
        assert_eq!(ffi::fmi2ExitInitializationMode(c), Status::Error);
        assert_eq!(ffi::fmi2DoStep(c, 0.0, 1e-3, 1), Status::Error);
        assert_eq!(ffi::fmi2GetReal(c, &vr, 1, &mut x), Status::Error);
        assert_eq!(ffi::fmi2SetReal(c, &vr, 1, &x), Status::Error);
        assert_eq!(ffi::fmi2Terminate(c), Status::Error);
        assert_eq!(ffi::fmi2Reset(c), Status::Error);
        assert_eq!(ffi::fmi2SetDebugLogging(c, 1, 0, null()), Status::Error);
        assert_eq!(ffi::fmi2GetRealStatus(c, status_kind::LAST_SUCCESSFUL_TIME, &mut x), Status::Error);
        ffi::fmi2FreeInstance(c);
    }
}

#[test]
fn instantiation_failures_return_null_and_log() {
    let log = Log::default();
    // No callbacks at all: null, nothing to log to.
    let (_dir, uri) = resources(DKFZD4012_TOML);
    let g = CString::new(guid(DKFZD4012_TOML)).unwrap();
    // SAFETY: valid strings; null callbacks is what is tested.
    let c = unsafe { ffi::fmi2Instantiate(c"x".as_ptr(), 1, g.as_ptr(), uri.as_ptr(), null(), 0, 0) };
    assert!(c.is_null());
    // Model exchange is not offered.
    let cb = callbacks(&log);
    // SAFETY: valid strings and callbacks.
    let c = unsafe { ffi::fmi2Instantiate(c"x".as_ptr(), 0, g.as_ptr(), uri.as_ptr(), &cb, 0, 0) };
    assert!(c.is_null());
    assert!(errors(&log).last().unwrap().contains("co-simulation only"), "{log:?}");
    // No resources location, or a folder without the spec.
    // SAFETY: valid strings and callbacks; the null location is what is tested.
    let c = unsafe { ffi::fmi2Instantiate(c"x".as_ptr(), 1, g.as_ptr(), null(), &cb, 0, 0) };
    assert!(c.is_null());
    assert!(errors(&log).last().unwrap().contains("fmuResourceLocation is a null pointer"), "{log:?}");
    // SAFETY: valid strings and callbacks.
    let c =
        unsafe { ffi::fmi2Instantiate(c"x".as_ptr(), 1, g.as_ptr(), c"file:///nonexistent/dir".as_ptr(), &cb, 0, 0) };
    assert!(c.is_null());
    assert!(errors(&log).last().unwrap().contains("cannot read the FMU's spec /nonexistent/dir/spec.toml"), "{log:?}");
    // A message quoting a '%' arrives whole (doubled in the format, undoubled by printf).
    // SAFETY: valid strings and callbacks.
    let c = unsafe { ffi::fmi2Instantiate(c"x".as_ptr(), 1, g.as_ptr(), c"file:///a%2".as_ptr(), &cb, 0, 0) };
    assert!(c.is_null());
    assert!(errors(&log).last().unwrap().contains("\"file:///a%2\": invalid %-escape"), "{log:?}");
}

#[test]
fn a_bad_spec_is_an_error_with_the_core_message() {
    let log = Log::default();
    let bad = DKFZD4012_TOML.replace("preload_n = ", "preload_n = -");
    let c = instantiate(&bad, &guid(&bad), &log);
    assert!(c.is_null());
    let e = errors(&log);
    assert_eq!(e.len(), 1, "{log:?}");
    assert!(e[0].contains("resources/spec.toml") && e[0].contains("invalid operating.preload_n: -2 kN"), "{e:?}");
}

#[test]
fn a_changed_spec_is_a_warning() {
    let log = Log::default();
    let c = instantiate(DKFZD4012_TOML, "{00000000-0000-0000-0000-000000000000}", &log);
    assert!(!c.is_null());
    assert!(log.borrow().iter().any(|(s, m)| *s == Status::Warning as c_int && m.contains("fmuGUID")), "{log:?}");
    // SAFETY: `c` is live and freed once.
    unsafe { ffi::fmi2FreeInstance(c) };
}

#[test]
fn bad_calls_on_an_instance_are_errors_with_messages() {
    let log = Log::default();
    let c = instantiate(DKFZD4012_TOML, &guid(DKFZD4012_TOML), &log);
    assert!(!c.is_null(), "{log:?}");
    let mut x = [0.0f64; 2];
    let mut i = [0 as c_int; 1];
    // SAFETY: `c` is live; the pointers are valid or null where that is what is tested.
    unsafe {
        assert_eq!(ffi::fmi2SetReal(c, &42, 1, &1.0), Status::Error);
        assert!(errors(&log).last().unwrap().contains("value reference 42"), "{log:?}");
        assert_eq!(ffi::fmi2SetReal(c, null(), 1, &1.0), Status::Error);
        assert!(errors(&log).last().unwrap().contains("vr is a null pointer"), "{log:?}");
        assert_eq!(ffi::fmi2GetReal(c, &SPEED_RAD_S, 1, null_mut()), Status::Error);
        assert!(errors(&log).last().unwrap().contains("value is a null pointer"), "{log:?}");
        assert_eq!(ffi::fmi2SetReal(c, &SPEED_RAD_S, 1, &f64::NAN), Status::Error);
        assert!(errors(&log).last().unwrap().contains("invalid speed_rad_s: NaN"), "{log:?}");
        assert_eq!(ffi::fmi2SetReal(c, &TORQUE_NM, 1, &1.0), Status::Error);
        // Outputs exist from initialization on; steps from step mode on.
        assert_eq!(ffi::fmi2GetReal(c, &TORQUE_NM, 1, x.as_mut_ptr()), Status::Error);
        assert_eq!(ffi::fmi2DoStep(c, 0.0, 1e-3, 1), Status::Error);
        // No variables of the other types; an empty request is fine.
        assert_eq!(ffi::fmi2GetInteger(c, &0, 1, i.as_mut_ptr()), Status::Error);
        assert!(errors(&log).last().unwrap().contains("no Integer variable"), "{log:?}");
        assert_eq!(ffi::fmi2GetInteger(c, null(), 0, null_mut()), Status::Ok);
        assert_eq!(ffi::fmi2SetBoolean(c, &0, 1, i.as_ptr()), Status::Error);
        assert_eq!(ffi::fmi2GetString(c, &0, 1, null_mut()), Status::Error);
        // What the FMU does not offer.
        let mut state = null_mut();
        assert_eq!(ffi::fmi2GetFMUstate(c, &mut state), Status::Error);
        assert!(errors(&log).last().unwrap().contains("canGetAndSetFMUstate = false"), "{log:?}");
        assert_eq!(ffi::fmi2SetFMUstate(c, state), Status::Error);
        assert_eq!(ffi::fmi2FreeFMUstate(c, &mut state), Status::Error);
        let mut size = 0usize;
        assert_eq!(ffi::fmi2SerializedFMUstateSize(c, state, &mut size), Status::Error);
        assert_eq!(ffi::fmi2SerializeFMUstate(c, state, null_mut(), 0), Status::Error);
        assert_eq!(ffi::fmi2DeSerializeFMUstate(c, null(), 0, &mut state), Status::Error);
        assert_eq!(ffi::fmi2GetDirectionalDerivative(c, null(), 0, null(), 0, null(), null_mut()), Status::Error);
        assert_eq!(ffi::fmi2SetRealInputDerivatives(c, null(), 0, null(), null()), Status::Error);
        assert_eq!(ffi::fmi2GetRealOutputDerivatives(c, null(), 0, null(), null_mut()), Status::Error);
        assert_eq!(ffi::fmi2CancelStep(c), Status::Error);
        assert_eq!(ffi::fmi2GetStatus(c, status_kind::DO_STEP_STATUS, i.as_mut_ptr()), Status::Discard);
        assert_eq!(ffi::fmi2GetStringStatus(c, status_kind::PENDING_STATUS, null_mut()), Status::Discard);
        assert_eq!(ffi::fmi2SetDebugLogging(c, 1, 1, &c"logNothing".as_ptr()), Status::Error);
        assert_eq!(ffi::fmi2SetDebugLogging(c, 1, 1, &c"logAll".as_ptr()), Status::Ok);
        ffi::fmi2FreeInstance(c);
    }
}

/// Drives the instance `c` from its instantiation through the inputs `speeds` (rad/s) and
/// `loads` (axial, N), the preload set first when given: the first point before initialization
/// ends, each next one followed by a step of 1 ms; after each, `check(k, speed, load, [torque,
/// drag])` with the outputs `torque_nm` and `drag_torque_nm`. Returns the time reached, s.
///
/// # Safety
/// `c` must be a live instance, just instantiated.
unsafe fn drive(
    c: Fmi2Component,
    log: &Log,
    preload: Option<f64>,
    speeds: &[f64],
    loads: &[f64],
    mut check: impl FnMut(usize, f64, f64, [f64; 2]),
) -> f64 {
    let mut time = 0.0;
    let mut out = [0.0; 2];
    // SAFETY: `c` is live (the caller's contract); every pointer is valid for its count.
    unsafe {
        assert_eq!(ffi::fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0), Status::Ok);
        assert_eq!(ffi::fmi2EnterInitializationMode(c), Status::Ok);
        if let Some(p) = preload {
            assert_eq!(ffi::fmi2SetReal(c, &PRELOAD_N, 1, &p), Status::Ok);
        }
        for (k, (&w, &f)) in speeds.iter().zip(loads).enumerate() {
            let vr = [SPEED_RAD_S, AXIAL_LOAD_N];
            assert_eq!(ffi::fmi2SetReal(c, vr.as_ptr(), 2, [w, f].as_ptr()), Status::Ok);
            if k == 0 {
                assert_eq!(ffi::fmi2ExitInitializationMode(c), Status::Ok, "{log:?}");
            } else {
                assert_eq!(ffi::fmi2DoStep(c, time, 1e-3, 1), Status::Ok, "{log:?}");
                time += 1e-3;
            }
            let vr = [TORQUE_NM, DRAG_TORQUE_NM];
            assert_eq!(ffi::fmi2GetReal(c, vr.as_ptr(), 2, out.as_mut_ptr()), Status::Ok);
            check(k, w, f, out);
        }
    }
    time
}

#[test]
fn outputs_are_the_evaluators_over_a_profile() {
    let log = Log::default();
    let c = instantiate(DKFZD4012_TOML, &guid(DKFZD4012_TOML), &log);
    assert!(!c.is_null(), "{log:?}");
    let spec = ballscrew_config::builtin_spec().unwrap();
    let evaluator = Evaluator::<f64>::new(&Model::new(&spec).unwrap()).unwrap();
    let mut state = EvalState::new();
    let preload = 1500.0;
    // Reversals and standstill, under a changing axial load.
    let speeds = [0.0, 20.0, 80.0, 80.0, 0.0, -0.01, -60.0, -60.0, 0.0, 0.0, 35.0];
    let loads = [0.0, 100.0, 300.0, 300.0, 0.0, -200.0, -200.0, 50.0, 0.0, 0.0, 400.0];
    let mut out = [0.0; 2];
    // SAFETY: `c` is live; every pointer is valid for its count.
    unsafe {
        let time = drive(c, &log, Some(preload), &speeds, &loads, |k, w, f, [torque, drag]| {
            let want = evaluator
                .torque_nm(&OperatingPoint { speed_rad_s: w, preload_n: preload, axial_load_n: f }, &mut state)
                .unwrap();
            assert_eq!(torque, want, "point {k}");
            assert!((torque - drag - f * spec.geometry.lead_m / (2.0 * std::f64::consts::PI)).abs() < 1e-15);
        });
        let mut t = 0.0;
        assert_eq!(ffi::fmi2GetRealStatus(c, status_kind::LAST_SUCCESSFUL_TIME, &mut t), Status::Ok);
        assert!((t - time).abs() < 1e-15);
        let mut terminated = 1;
        assert_eq!(ffi::fmi2GetBooleanStatus(c, status_kind::TERMINATED, &mut terminated), Status::Ok);
        assert_eq!(terminated, 0);
        // A point beyond the static capacity: an error with the core's message, no number.
        assert_eq!(ffi::fmi2SetReal(c, &AXIAL_LOAD_N, 1, &9.0e6), Status::Ok);
        assert_eq!(ffi::fmi2DoStep(c, time, 1e-3, 1), Status::Error);
        assert!(errors(&log).last().unwrap().contains("no torque at"), "{log:?}");
        assert_eq!(ffi::fmi2GetReal(c, &TORQUE_NM, 1, out.as_mut_ptr()), Status::Error);
        assert_eq!(ffi::fmi2Terminate(c), Status::Ok);
        assert_eq!(ffi::fmi2Reset(c), Status::Ok);
        ffi::fmi2FreeInstance(c);
    }
}

/// A spec the control-loop evaluator does not take (an oversize-ball screw's four-point
/// balls; DKFZD4012 with FASTSIM contacts) instantiates, says so in its model description,
/// and runs on the model's own solve: its outputs over a profile with reversals
/// and standstill are `Model::torque` warm-started the same way, to the last bit.
#[test]
fn a_spec_the_evaluator_does_not_take_runs_on_the_models_solve() {
    let fastsim = DKFZD4012_TOML.replace(r#"contact_theory = "linear-saturated""#, r#"contact_theory = "fastsim""#);
    assert_ne!(fastsim, DKFZD4012_TOML);
    for text in [include_str!("../../../configs/single-nut-16x5.toml"), fastsim.as_str()] {
        on_the_models_solve(text);
    }
}

fn on_the_models_solve(text: &str) {
    let spec = ballscrew_config::spec_from_toml_str(text, "spec").unwrap();
    let model = Model::new(&spec).unwrap();
    assert!(Evaluator::<f64>::new(&model).is_err(), "the evaluator does not take it");
    let xml = ballscrew_fmu::model_description::model_description(&spec, text, "m");
    assert!(xml.contains("(the model's solve, f64)"), "{xml}");
    let log = Log::default();
    let c = instantiate(text, &guid(text), &log);
    assert!(!c.is_null(), "{log:?}");
    let mut state = SolverState::new();
    let preload = spec.operating.preload_n;
    let speeds = [100.0, 100.0, 20.0, 0.0, -0.01, -50.0, 0.0, 60.0];
    let loads = [0.0, 150.0, 300.0, 0.0, -100.0, -300.0, 0.0, 200.0];
    // SAFETY: `c` is live; every pointer is valid for its count.
    unsafe {
        drive(c, &log, None, &speeds, &loads, |k, w, f, [torque, drag]| {
            let op = OperatingPoint { speed_rad_s: w, preload_n: preload, axial_load_n: f };
            let want = model.torque(&op, &mut state).unwrap();
            assert_eq!(torque, want, "point {k}");
            assert!(torque.is_finite() && (w == 0.0 || drag * w > 0.0), "point {k}: drag {drag} against {w}");
        });
        assert_eq!(ffi::fmi2Terminate(c), Status::Ok);
        ffi::fmi2FreeInstance(c);
    }
}
