//! Through standstill and reversals the torque is finite, bounded and continuous: a sweep of
//! the screw speed from -3000 to 3000 rpm in fine steps (docs/model-notes.md items 12 and 13).
//!
//! Continuity on a discrete sweep: between neighbouring speeds the torque may change by no more
//! than the steepest the model allows, the standstill factor's slope 2 / omega0 (its largest,
//! at zero speed) times the step times the running torque, plus a tolerance of 1e-9 of the
//! running torque. Above the standstill speed the dry model's torque does not depend on the
//! speed at all: these checks run on the dry model (`lubrication = "dry"`); the lubricated
//! model's passage through standstill is checked in `crates/core/tests/lubricated.rs`.

use ballscrew_core::input::{rad_s_to_rpm, rpm_to_rad_s};
use ballscrew_core::{Lubrication, Model, OperatingPoint, ScrewSpec, SolverState};

/// DKFZD4012 with the paper's dry contacts.
fn dry() -> ScrewSpec {
    let mut s = ScrewSpec::dkfzd4012();
    s.model.lubrication = Lubrication::Dry;
    // The paper's dry model: no load between balls (no ball train).
    s.friction.ball_ball_load_n = Some(0.0);
    s
}

/// Speeds from -3000 to 3000 rpm: 1 rpm apart, 1e-3 rpm apart within 1 rpm of standstill
/// (the standstill speed of DKFZD4012's spec is 0.1 rpm), sorted, zero included.
pub fn sweep_speeds_rpm() -> Vec<f64> {
    let mut v: Vec<f64> = (-3000..=3000).filter(|k: &i32| k.abs() > 1).map(f64::from).collect();
    v.extend((-1000..=1000).map(|k| f64::from(k) * 1e-3));
    v.sort_by(f64::total_cmp);
    v
}

/// Checks the sweep `torque_of` over [`sweep_speeds_rpm`] against the running torque `full` and
/// the standstill speed `omega0_rpm`; returns the largest step between neighbours over its bound.
pub fn check_sweep(mut torque_of: impl FnMut(f64) -> f64, full: f64, omega0_rpm: f64) -> f64 {
    let speeds = sweep_speeds_rpm();
    let mut worst: f64 = 0.0;
    let mut prev: Option<(f64, f64)> = None;
    for &rpm in &speeds {
        let t = torque_of(rpm);
        assert!(t.is_finite(), "{rpm} rpm: {t}");
        assert!(t.abs() <= full * (1.0 + 1e-6), "{rpm} rpm: |{t}| above the running torque {full}");
        assert!(t * rpm >= 0.0, "{rpm} rpm: torque {t} against the rotation");
        if let Some((r0, t0)) = prev {
            let bound = 2.0 / omega0_rpm * (rpm - r0) * full + 1e-9 * full;
            worst = worst.max((t - t0).abs() / bound);
            assert!((t - t0).abs() <= bound, "jump between {r0} and {rpm} rpm: {t0} -> {t}");
        }
        prev = Some((rpm, t));
    }
    worst
}

#[test]
fn model_torque_is_continuous_and_bounded_from_minus_to_plus_3000_rpm() {
    let spec = dry();
    let model = Model::new(&spec).unwrap();
    let op = |rpm: f64| OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: 2000.0, axial_load_n: 0.0 };
    let full = model.torque(&op(100.0), &mut SolverState::new()).unwrap();
    let omega0_rpm = rad_s_to_rpm(spec.friction.standstill_speed_rad_s);
    let mut state = SolverState::new();
    let mut at = Vec::new();
    let worst = check_sweep(
        |rpm| {
            let t = model.torque(&op(rpm), &mut state).unwrap();
            at.push((rpm, t));
            t
        },
        full,
        omega0_rpm,
    );
    // The bound is met with room, and it is not vacuous: the steepest step near standstill uses
    // a good part of it.
    assert!(worst > 0.5 && worst <= 1.0, "largest step over its bound: {worst}");
    // Above the standstill speed the torque is the running torque, with the sign of rotation.
    for &(rpm, t) in &at {
        if rpm.abs() >= omega0_rpm {
            assert!((t.abs() - full).abs() <= 1e-9 * full, "{rpm} rpm: {t} vs {full}");
        }
    }
    assert!(at.iter().any(|&(rpm, t)| rpm == 0.0 && t == 0.0), "no torque at standstill");
}

#[test]
fn map_torque_is_continuous_and_bounded_from_minus_to_plus_3000_rpm() {
    use ballscrew_core::realtime::map::{MapGrid, tabulate};
    let spec = dry();
    let model = Model::new(&spec).unwrap();
    let omega0 = spec.friction.standstill_speed_rad_s;
    let grid =
        MapGrid::spanning((500.0, 3000.0, 11), (0.0, rpm_to_rad_s(3000.0), 4), spec.friction.standstill_speed_rad_s);
    let table = tabulate(&model, &grid, 0.0).unwrap();
    let map = table.map();
    for preload_n in [500.0_f32, 1234.5, 2000.0, 3000.0] {
        let op =
            OperatingPoint { speed_rad_s: rpm_to_rad_s(100.0), preload_n: f64::from(preload_n), axial_load_n: 0.0 };
        let full = model.torque(&op, &mut SolverState::new()).unwrap();
        // The map's running torque is within its stated error of the model's; its own f32
        // rounding adds a step tolerance of 1e-6 of the running torque.
        let running = f64::from(map.torque_nm(preload_n, rpm_to_rad_s(100.0) as f32));
        assert!((running - full).abs() <= table.max_relative_error * full);
        let worst = check_sweep(
            |rpm| f64::from(map.torque_nm(preload_n, rpm_to_rad_s(rpm) as f32)),
            running * (1.0 + 1e-6),
            rad_s_to_rpm(omega0) * (1.0 - 1e-6),
        );
        assert!(worst > 0.5 && worst <= 1.0, "{preload_n} N: largest step over its bound {worst}");
        assert_eq!(map.torque_nm(preload_n, 0.0), 0.0, "no torque at standstill");
    }
}

#[test]
fn map_progress_counts_every_evaluation_one_by_one() {
    use ballscrew_core::realtime::map::{MapGrid, evaluations, tabulate, tabulate_with_progress};
    let spec = dry();
    let model = Model::new(&spec).unwrap();
    let grid =
        MapGrid::spanning((500.0, 3000.0, 11), (0.0, rpm_to_rad_s(3000.0), 4), spec.friction.standstill_speed_rad_s);
    let mut seen = Vec::new();
    let with = tabulate_with_progress(&model, &grid, 0.0, &mut |done, total| seen.push((done, total))).unwrap();
    // 11 standstill values, 2 x 44 sheet values, 10 cells x 2 directions x 4 checks.
    assert_eq!(evaluations(11, 4), 179);
    let expected: Vec<(usize, usize)> = (1..=179).map(|d| (d, 179)).collect();
    assert_eq!(seen, expected);
    assert_eq!(with, tabulate(&model, &grid, 0.0).unwrap());
}
