//! The real-time evaluator in f32, stepped as a servo drive steps it: a 1 kHz loop over a
//! sinusoidal speed profile through both directions (1500 rpm peak, 2 s period, DKFZD4012 at
//! 2000 N preload), one warm-started call a step, nothing allocated in the loop (counted by a
//! counting allocator), the f32 torques then checked against the same evaluator in f64.
//!
//! ```text
//! cargo run --release -p ballscrew-core --example control_loop_f32
//! ```

use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{EvalState, Evaluator, Model, OperatingPoint, ScrewSpec};
use std::time::Instant;

/// Steps of the loop: one period at 1 kHz.
const STEPS: usize = 2000;
/// The loop's time step, s.
const DT_S: f64 = 1e-3;
/// The profile's period, s.
const PERIOD_S: f64 = 2.0;
/// The profile's peak speed, rpm.
const PEAK_RPM: f64 = 1500.0;

/// The operating point of step `k`.
fn point(k: usize) -> OperatingPoint {
    let t = k as f64 * DT_S;
    let speed_rpm = PEAK_RPM * (core::f64::consts::TAU * t / PERIOD_S).sin();
    OperatingPoint { speed_rad_s: rpm_to_rad_s(speed_rpm), preload_n: 2000.0, axial_load_n: 0.0 }
}

fn main() -> Result<(), ballscrew_core::Error> {
    let model = Model::new(&ScrewSpec::dkfzd4012())?;
    // Built once, before the loop (about 100 ball solves in f64).
    let evaluator = Evaluator::<f32>::new(&model)?;
    let mut state = EvalState::<f32>::new();
    let mut torques_nm = [0.0_f32; STEPS];
    let mut failed = None;
    let start = Instant::now();
    let allocations = allocation_counter::measure(|| {
        for (k, torque) in torques_nm.iter_mut().enumerate() {
            match evaluator.torque_nm(&point(k), &mut state) {
                Ok(t) => *torque = t,
                Err(e) => {
                    failed = Some(e);
                    break;
                }
            }
        }
    });
    let elapsed = start.elapsed();
    if let Some(e) = failed {
        return Err(e);
    }

    let reference = Evaluator::<f64>::new(&model)?;
    let mut reference_state = EvalState::<f64>::new();
    let mut largest_nm = 0.0_f64;
    let mut largest_difference_nm = 0.0_f64;
    for (k, &t) in torques_nm.iter().enumerate() {
        let t64 = reference.torque_nm(&point(k), &mut reference_state)?;
        largest_nm = largest_nm.max(f64::from(t).abs());
        largest_difference_nm = largest_difference_nm.max((f64::from(t) - t64).abs());
    }
    println!("DKFZD4012, preload 2000 N, speed {PEAK_RPM} rpm sin(2 pi t / {PERIOD_S} s), {STEPS} steps of 1 ms");
    println!("f32 torque at step 500 (+1500 rpm): {:.6} N m", torques_nm[500]);
    println!("f32 torque at step 1500 (-1500 rpm): {:.6} N m", torques_nm[1500]);
    println!("largest f32 torque magnitude: {largest_nm:.6} N m");
    println!("largest f32 - f64 difference: {largest_difference_nm:.3e} N m");
    println!("allocations in the loop: {}", allocations.count_total);
    println!("time per step: {:.1} us", elapsed.as_secs_f64() / STEPS as f64 * 1e6);
    Ok(())
}
