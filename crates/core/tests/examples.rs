//! The examples (`crates/core/examples`) print what the library computes: each example's binary,
//! which `cargo test` builds into the profile's `examples` folder beside this test's `deps`, is
//! run, and every number it prints is compared with the same public calls made here (to half a
//! unit in the last printed digit), with what the numbers must satisfy besides.

use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::realtime::map::{self, MapGrid, TorqueMap};
use ballscrew_core::realtime::reversal::{Reformation, SineMotion};
use ballscrew_core::{EvalState, Evaluator, Model, OperatingPoint, ReversalModel, ScrewSpec, SolverState};
use std::path::PathBuf;
use std::process::Command;

/// The path of the example `name`'s binary: `<target>/<profile>/examples/<name>`, this test
/// binary being `<target>/<profile>/deps/examples-<hash>` (so it follows `CARGO_TARGET_DIR`
/// and the profile).
fn example_path(name: &str) -> PathBuf {
    let exe = std::env::current_exe().expect("the test binary's path");
    let profile = exe.parent().and_then(|deps| deps.parent()).expect("the test binary lies in <target>/<profile>/deps");
    profile.join("examples").join(format!("{name}{}", std::env::consts::EXE_SUFFIX))
}

/// Runs the example `name` and returns what it printed.
fn run(name: &str) -> String {
    let path = example_path(name);
    assert!(
        path.is_file(),
        "the example `{name}` is not built ({} is missing): `cargo test -p ballscrew-core` builds the \
         examples before it runs the tests, while `--test examples` alone does not; build them with \
         `cargo build -p ballscrew-core --examples` (with the same profile flag, e.g. --release)",
        path.display()
    );
    let source = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples").join(format!("{name}.rs"));
    let modified = |p: &PathBuf| std::fs::metadata(p).and_then(|m| m.modified()).ok();
    if let (Some(built), Some(edited)) = (modified(&path), modified(&source)) {
        assert!(
            built >= edited,
            "the example `{name}` was built before its source was last changed: rebuild it with \
             `cargo build -p ballscrew-core --examples` (with the same profile flag) or run the crate's \
             whole `cargo test`"
        );
    }
    let out = Command::new(&path).output().unwrap_or_else(|e| panic!("cannot run {}: {e}", path.display()));
    let stdout = String::from_utf8(out.stdout).expect("the example prints UTF-8");
    assert!(
        out.status.success(),
        "the example `{name}` failed ({}):\n{stdout}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    stdout
}

/// The line of `out` that starts with `label`.
fn line<'a>(out: &'a str, label: &str) -> &'a str {
    out.lines().find(|l| l.starts_with(label)).unwrap_or_else(|| panic!("no line starting `{label}` in:\n{out}"))
}

/// The numbers of the line that starts with `label`, after the label, in order (words around
/// them and the punctuation `,:()` stuck to them skipped).
fn numbers(out: &str, label: &str) -> Vec<f64> {
    line(out, label)[label.len()..]
        .split_whitespace()
        .filter_map(|w| w.trim_matches(|c| ",:()".contains(c)).parse().ok())
        .collect()
}

/// The first number after `label`.
fn value(out: &str, label: &str) -> f64 {
    *numbers(out, label).first().unwrap_or_else(|| panic!("no number on the line `{label}` in:\n{out}"))
}

/// `printed` is `computed` written with `decimals` decimals.
fn assert_printed(printed: f64, computed: f64, decimals: i32, what: &str) {
    let half_unit = 0.5 * 10f64.powi(-decimals) * (1.0 + 1e-9);
    assert!((printed - computed).abs() <= half_unit, "{what}: printed {printed}, computed {computed}");
}

/// `printed` is `computed` written in scientific notation with `digits` decimals of the mantissa.
fn assert_printed_sci(printed: f64, computed: f64, digits: i32, what: &str) {
    let half_unit = 0.5 * 10f64.powi(-digits) * computed.abs() * 10.0 * (1.0 + 1e-9);
    assert!((printed - computed).abs() <= half_unit, "{what}: printed {printed:e}, computed {computed:e}");
}

fn dkfzd4012() -> Model {
    Model::new(&ScrewSpec::dkfzd4012()).expect("the built-in spec")
}

#[test]
fn one_point_prints_the_models_summary() {
    let out = run("one_point");
    let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(100.0), preload_n: 2000.0, axial_load_n: 0.0 };
    let s = dkfzd4012().summary(&op, &mut SolverState::new()).unwrap();
    assert!(line(&out, "DKFZD4012 at").contains("speed 100 rpm, preload 2000 N, axial load 0 N"), "{out}");
    for (label, computed) in [
        ("drag torque", s.drag_torque_nm()),
        ("energy route", s.torque_energy_nm),
        ("moment route", s.torque_moment_nm),
        ("creep and sliding", s.creep_torque_nm),
        ("rolling resistance", s.rolling_resistance_torque_nm),
        ("hysteresis", s.hysteresis_torque_nm),
        ("ball-ball contacts", s.ball_ball_torque_nm),
        ("return path", s.return_torque_nm),
        ("catalog estimate", s.catalog_nm),
    ] {
        assert!(line(&out, label).ends_with(" N m"), "{label}: the unit in\n{out}");
        assert_printed(value(&out, label), computed, 6, label);
    }
    // The two routes agree, and the drag is the creep model's (no axial load, no seals).
    assert!((value(&out, "energy route") - value(&out, "moment route")).abs() <= 2e-6, "{out}");
    assert!(value(&out, "drag torque") > 0.0);
}

#[test]
fn sweep_prints_the_warm_started_preload_sweep() {
    let out = run("sweep");
    let model = dkfzd4012();
    let mut state = SolverState::new();
    let mut previous = 0.0;
    for step in 1..=6 {
        let preload_n = 500.0 * f64::from(step);
        let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(100.0), preload_n, axial_load_n: 0.0 };
        let s = model.summary(&op, &mut state).unwrap();
        let label = format!("preload {preload_n} N:");
        let printed = numbers(&out, &label);
        assert_eq!(printed.len(), 2, "{label} in\n{out}");
        assert_printed(printed[0], s.drag_torque_nm(), 6, &label);
        assert_printed(printed[1], s.catalog_nm, 6, &label);
        assert!(printed[0] > previous, "the drag grows with the preload:\n{out}");
        previous = printed[0];
    }
}

#[test]
fn control_loop_f32_prints_the_evaluators_torques_without_allocation() {
    let out = run("control_loop_f32");
    let model = dkfzd4012();
    let point = |k: usize| {
        let speed_rpm = 1500.0 * (core::f64::consts::TAU * k as f64 * 1e-3 / 2.0).sin();
        OperatingPoint { speed_rad_s: rpm_to_rad_s(speed_rpm), preload_n: 2000.0, axial_load_n: 0.0 }
    };
    let ev32 = Evaluator::<f32>::new(&model).unwrap();
    let ev64 = Evaluator::<f64>::new(&model).unwrap();
    let (mut s32, mut s64) = (EvalState::<f32>::new(), EvalState::<f64>::new());
    let (mut largest, mut difference) = (0.0_f64, 0.0_f64);
    let mut at = [0.0_f64; 2];
    for k in 0..2000 {
        let t32 = f64::from(ev32.torque_nm(&point(k), &mut s32).unwrap());
        let t64 = ev64.torque_nm(&point(k), &mut s64).unwrap();
        largest = largest.max(t32.abs());
        difference = difference.max((t32 - t64).abs());
        match k {
            500 => at[0] = t32,
            1500 => at[1] = t32,
            _ => {}
        }
    }
    assert_printed(value(&out, "f32 torque at step 500 (+1500 rpm)"), at[0], 6, "step 500");
    assert_printed(value(&out, "f32 torque at step 1500 (-1500 rpm)"), at[1], 6, "step 1500");
    assert_printed(value(&out, "largest f32 torque magnitude"), largest, 6, "largest");
    assert_printed_sci(value(&out, "largest f32 - f64 difference"), difference, 3, "f32 - f64");
    assert_eq!(value(&out, "allocations in the loop"), 0.0, "{out}");
    // The torque is odd in the speed, and f32 within 1e-4 of the largest torque of f64.
    assert!(at[0] > 0.0 && (at[0] + at[1]).abs() <= 1e-3 * at[0], "{out}");
    assert!(difference <= 1e-4 * largest, "{out}");
}

#[test]
fn torque_map_prints_the_tabulation_and_the_firmware_lookup() {
    let out = run("torque_map");
    let model = dkfzd4012();
    let omega0 = model.spec().friction.standstill_speed_rad_s;
    let grid = MapGrid::geometric((500.0, 3000.0, 6), (omega0 / 10.0, rpm_to_rad_s(3000.0), 32), omega0);
    let t = map::tabulate(&model, &grid, 0.0).unwrap();
    assert_eq!(value(&out, "values"), (6 * (1 + 2 * 32)) as f64, "{out}");
    let error = numbers(&out, "largest interpolation error");
    assert_printed(error[0], 100.0 * t.max_relative_error, 4, "largest error, %");
    assert_eq!(error[1], t.worst_point.0.round(), "worst preload");
    assert_eq!(error[3], t.checked_points as f64, "check points");
    let firmware = TorqueMap::new(grid, &t.values).unwrap();
    let mut state = SolverState::new();
    for speed_rpm in [150.0, -150.0, 2.0] {
        let label = format!("map at 1750 N, {speed_rpm} rpm:");
        let printed = numbers(&out, &label);
        let looked_up = f64::from(firmware.torque_nm(1750.0, rpm_to_rad_s(speed_rpm) as f32));
        let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(speed_rpm), preload_n: 1750.0, axial_load_n: 0.0 };
        let modelled = model.torque(&op, &mut state).unwrap();
        assert_printed(printed[0], looked_up, 6, &label);
        assert_printed(printed[1], modelled, 6, &label);
        // Off the nodes the map is within the error the tabulation states (at cell midpoints).
        assert!((looked_up - modelled).abs() <= 1.5 * t.max_relative_error * modelled.abs(), "{label}\n{out}");
    }
}

#[test]
fn reversal_prints_the_state_models_reformation() {
    let out = run("reversal");
    let model = dkfzd4012();
    let ev = Evaluator::<f64>::new(&model).unwrap();
    let rm = ReversalModel::new(&ev, 2000.0, 0.0).unwrap();
    let peak = rpm_to_rad_s(10.0);
    let motion = SineMotion::new(0.01, peak, 1e-5).unwrap();
    let before = rm.steady(peak).unwrap().friction_nm();
    let after = rm.steady(-peak).unwrap().friction_nm();
    let mut reformation = Reformation::new(after, 0.9).unwrap();
    let mut state = rm.steady(peak).unwrap();
    let n = motion.steps_per_period();
    for k in 1..=n / 2 {
        let torque = rm.step(motion.rotation_rad(k), motion.dt_s(), &mut state).unwrap();
        if k >= n / 4 {
            reformation.record(motion.amplitude_rad() - motion.angle_rad(k), torque - rm.axial_term_nm());
        }
    }
    let zero = reformation.zero_crossing_rad().expect("the friction crosses zero");
    let reformed = reformation.reformed_rad().expect("the friction re-forms");
    assert_printed(value(&out, "stiffness from rest"), rm.stiffness_nm_per_rad(), 1, "stiffness");
    assert_printed(value(&out, "steady friction before"), before, 6, "before");
    assert_printed(value(&out, "steady friction after"), after, 6, "after");
    assert_printed_sci(value(&out, "zero crossing after the turning point"), zero, 4, "zero crossing");
    assert_printed_sci(value(&out, "90 % re-formed after the turning point"), reformed, 4, "re-formed");
    assert_printed(value(&out, "friction at the end"), state.friction_nm(), 6, "end");
    // The friction flips sign and re-forms within the half period, the zero crossing first.
    assert!(before > 0.0 && after < 0.0 && zero > 0.0 && zero < reformed && reformed < 0.01, "{out}");
}
