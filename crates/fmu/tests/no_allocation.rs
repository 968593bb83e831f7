//! A step of the FMU allocates nothing: `fmi2SetReal`, `fmi2DoStep` and `fmi2GetReal` through a
//! profile with reversals and standstill, counted by a counting global allocator (this test
//! binary only). Instantiation allocates (the instance, the evaluator's table), as FMI allows.
//! The profile's 2000 steps hold audited evaluations (`ballscrew_fmu::instance::AUDIT_EVERY`:
//! the first is at initialization, then every 1000th): their cold solves allocate nothing
//! either (a departure's log message would, and none departs here).
#![allow(unsafe_code, reason = "the test calls the FMU's C functions")]

use ballscrew_config::DKFZD4012_TOML;
use ballscrew_fmu::ffi::{self, Fmi2CallbackFunctions};
use ballscrew_fmu::instance::Status;
use ballscrew_fmu::model_description::guid;
use ballscrew_fmu::variables::{AXIAL_LOAD_N, DISSIPATED_POWER_W, SPEED_RAD_S, TORQUE_NM};
extern crate alloc;
use alloc::ffi::CString;

// The measured steps hold at least one audited evaluation.
const _: () = assert!(ballscrew_fmu::instance::AUDIT_EVERY < 2000);

#[test]
fn the_counter_sees_allocations() {
    let info = allocation_counter::measure(|| {
        core::hint::black_box(vec![1.0_f64; 16]);
    });
    assert!(info.count_total >= 1);
}

/// The evaluator's steps (DKFZD4012) and the model's (an oversize-ball screw and DKFZD4012
/// with FASTSIM contacts, which the evaluator does not take).
#[test]
fn steps_allocate_nothing() {
    steps_of(DKFZD4012_TOML);
    steps_of(include_str!("../../../configs/single-nut-16x5.toml"));
    steps_of(&fastsim_spec());
}

/// DKFZD4012 with FASTSIM at every raceway contact.
fn fastsim_spec() -> String {
    let text = DKFZD4012_TOML.replace(r#"contact_theory = "linear-saturated""#, r#"contact_theory = "fastsim""#);
    assert_ne!(text, DKFZD4012_TOML, "the built-in spec names its contact theory");
    text
}

fn steps_of(text: &str) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("spec.toml"), text).unwrap();
    let uri = CString::new(format!("file://{}", dir.path().display())).unwrap();
    let g = CString::new(guid(text)).unwrap();
    let cb = Fmi2CallbackFunctions {
        logger: None,
        allocate_memory: None,
        free_memory: None,
        step_finished: None,
        component_environment: core::ptr::null_mut(),
    };
    // SAFETY: valid C strings and callbacks for the call.
    let c = unsafe { ffi::fmi2Instantiate(c"s".as_ptr(), 1, g.as_ptr(), uri.as_ptr(), &cb, 0, 0) };
    assert!(!c.is_null());
    // SAFETY: `c` is live.
    unsafe {
        assert_eq!(ffi::fmi2EnterInitializationMode(c), Status::Ok);
        assert_eq!(ffi::fmi2ExitInitializationMode(c), Status::Ok);
    }
    let mut torques = Vec::with_capacity(2000);
    let info = allocation_counter::measure(|| {
        let mut time = 0.0;
        for k in 0..2000_u32 {
            // Up, down through zero, a standstill, up again; a changing axial load.
            let phase = f64::from(k % 500) / 500.0;
            let speed =
                if (0.6..0.7).contains(&phase) { 0.0 } else { 80.0 * (2.0 * core::f64::consts::PI * phase).cos() };
            let load = 300.0 * (f64::from(k) / 300.0).sin();
            let refs = [SPEED_RAD_S, AXIAL_LOAD_N];
            let mut out = [0.0; 2];
            // SAFETY: `c` is live; every pointer is valid for its count.
            unsafe {
                assert_eq!(ffi::fmi2SetReal(c, refs.as_ptr(), 2, [speed, load].as_ptr()), Status::Ok);
                assert_eq!(ffi::fmi2DoStep(c, time, 1e-3, 1), Status::Ok);
                let outs = [TORQUE_NM, DISSIPATED_POWER_W];
                assert_eq!(ffi::fmi2GetReal(c, outs.as_ptr(), 2, out.as_mut_ptr()), Status::Ok);
            }
            time += 1e-3;
            if torques.len() < torques.capacity() {
                torques.push(out[0]);
            }
        }
    });
    assert_eq!(info.count_total, 0, "{info:?}");
    assert_eq!(torques.len(), 2000);
    assert!(torques.iter().all(|t| t.is_finite()));
    assert!(torques.iter().any(|&t| t > 0.0) && torques.iter().any(|&t| t < 0.0));
    // SAFETY: `c` is live and freed once.
    unsafe { ffi::fmi2FreeInstance(c) };
}
