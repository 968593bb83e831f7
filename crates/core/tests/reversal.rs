//! The reversal (presliding) state model (`ballscrew_core::realtime::reversal`): at constant
//! speed it is the static model, a stepped reversal does not depend on the step, it is passive,
//! and it refuses what it cannot do. The lumped transient of one contact against transient
//! FASTSIM is checked in `crates/core/tests/presliding.rs`.

use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{EvalState, Evaluator, Model, ReversalModel, ScrewSpec, SolverState};

fn evaluator() -> Evaluator<f64> {
    Evaluator::new(&Model::new(&ScrewSpec::dkfzd4012()).unwrap()).unwrap()
}

/// At constant speed the state model's torque is the static model's, from a steady start and,
/// after enough rotation, from the relaxed state; forwards and backwards, with an axial load.
#[test]
fn constant_speed_gives_the_static_torque() {
    let ev = evaluator();
    let model = ev.model();
    for (preload, axial) in [(1000.0, 0.0), (3000.0, 0.0), (2000.0, 300.0)] {
        let rm = ReversalModel::new(&ev, preload, axial).unwrap();
        for rpm in [30.0, 100.0, 1000.0, -100.0, -3000.0] {
            let w = rpm_to_rad_s(rpm);
            let op = ballscrew_core::OperatingPoint { speed_rad_s: w, preload_n: preload, axial_load_n: axial };
            let stat = model.torque(&op, &mut SolverState::new()).unwrap();
            let dt = 1e-3;
            let mut st = rm.steady(w).unwrap();
            for _ in 0..20 {
                let t = rm.step(w * dt, dt, &mut st).unwrap();
                assert!((t - stat).abs() <= 1e-8 * stat.abs(), "{preload} N {axial} N {rpm} rpm: {t} vs {stat}");
            }
            // From rest: a few radians are thousands of relaxation angles.
            let mut st = rm.relaxed();
            let mut t = 0.0;
            for _ in 0..200 {
                t = rm.step(w * 0.01, 0.01, &mut st).unwrap();
            }
            assert!((t - stat).abs() <= 1e-8 * stat.abs(), "from rest {preload} N {rpm} rpm: {t} vs {stat}");
        }
    }
}

/// What the audit of the reversal model compares (`ReversalModel::steady_torque_at`) is the
/// torque its state settles on at a step's speed: the torque after steps at that speed, and the
/// canonical torque there within the evaluator's 1e-8; below the standstill speed it is taken
/// at the standstill speed, with the step's sign. An audit of every step at constant speed
/// finds no departure.
#[test]
fn the_audited_steady_torque_is_where_the_state_settles() {
    use ballscrew_core::realtime::audit::{Audit, F64_TOLERANCE};
    let ev = evaluator();
    let model = ev.model();
    let omega0 = model.spec().friction.standstill_speed_rad_s;
    let rm = ReversalModel::new(&ev, 2000.0, 300.0).unwrap();
    assert_eq!(rm.model(), model);
    for rpm in [30.0, -100.0, 2500.0, 1e-4, -1e-4] {
        let w = rpm_to_rad_s(rpm);
        let mut st = rm.steady(w).unwrap();
        let mut audit = Audit::new(1, F64_TOLERANCE).unwrap();
        let mut t = 0.0;
        for _ in 0..5 {
            t = rm.step(w * 1e-3, 1e-3, &mut st).unwrap();
            let speed = w * 1e-3 / 1e-3;
            assert!(audit.check_lazily(model, || rm.steady_torque_at(speed, &st).ok()).is_none());
        }
        let (op, steady) = rm.steady_torque_at(w, &st).unwrap();
        let at = w.abs().max(omega0).copysign(w);
        assert_eq!((op.speed_rad_s, op.preload_n, op.axial_load_n), (at, 2000.0, 300.0));
        let canonical = model.torque(&op, &mut SolverState::new()).unwrap();
        assert!((steady - canonical).abs() <= 1e-8 * canonical.abs(), "{rpm} rpm: {steady} vs {canonical}");
        if w.abs() >= omega0 {
            assert!((t - steady).abs() <= 1e-12 * steady.abs(), "{rpm} rpm: stepped {t} vs steady {steady}");
        }
        assert_eq!((audit.audited(), audit.departed()), (5, 0));
    }
}

/// The dry model (`lubrication = "dry"`) too: from rest the state settles on its
/// (speed-independent) torque, both directions.
#[test]
fn dry_model_at_constant_speed() {
    let mut spec = ScrewSpec::dkfzd4012();
    spec.model = ballscrew_core::ModelOptions::dry();
    let model = Model::new(&spec).unwrap();
    let ev = Evaluator::<f64>::new(&model).unwrap();
    let rm = ReversalModel::new(&ev, 2000.0, 0.0).unwrap();
    for rpm in [100.0, -100.0] {
        let w = rpm_to_rad_s(rpm);
        let op = ballscrew_core::OperatingPoint { speed_rad_s: w, preload_n: 2000.0, axial_load_n: 0.0 };
        let stat = model.torque(&op, &mut SolverState::new()).unwrap();
        let mut st = rm.relaxed();
        let mut t = 0.0;
        for _ in 0..100 {
            t = rm.step(w * 0.01, 0.01, &mut st).unwrap();
        }
        assert!((t - stat).abs() <= 1e-8 * stat.abs(), "{rpm} rpm: {t} vs {stat}");
    }
}

/// f32: the same within the evaluator's f32 tolerance (1e-4 of the torque).
#[test]
fn constant_speed_in_f32() {
    let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
    let ev = Evaluator::<f32>::new(&model).unwrap();
    let rm = ReversalModel::new(&ev, 2000.0, 0.0).unwrap();
    for rpm in [100.0, -1000.0] {
        let w = rpm_to_rad_s(rpm);
        let op = ballscrew_core::OperatingPoint { speed_rad_s: w, preload_n: 2000.0, axial_load_n: 0.0 };
        let stat = model.torque(&op, &mut SolverState::new()).unwrap();
        let mut st = rm.steady(w as f32).unwrap();
        let t = f64::from(rm.step((w * 1e-3) as f32, 1e-3, &mut st).unwrap());
        assert!((t - stat).abs() <= 1e-4 * stat.abs(), "{rpm} rpm: {t} vs {stat}");
    }
}

/// A sinusoidal motion through a reversal, `theta = A sin(Omega t)` from its zero crossing at
/// the peak speed to the next one, stepped in time so that the largest step turns the screw by
/// `h`: torques at the common times.
fn reversal(rm: &ReversalModel<f64>, h: f64, stride: usize) -> Vec<(f64, f64)> {
    let amplitude = 0.02; // rad: several relaxation angles (see the table of docs/real-time.md)
    let peak = rpm_to_rad_s(10.0);
    let omega = peak / amplitude;
    let dt = h / peak;
    let steps = (core::f64::consts::PI / omega / dt).round() as usize;
    let mut st = rm.steady(peak).unwrap();
    let mut out = Vec::new();
    let mut prev = 0.0;
    for k in 1..=steps {
        let theta = amplitude * (omega * k as f64 * dt).sin();
        let t = rm.step(theta - prev, dt, &mut st).unwrap();
        prev = theta;
        if k % stride == 0 {
            out.push((theta, t));
        }
    }
    out
}

/// The response converges as the step shrinks: a reversal stepped at 1e-4 and 1e-6 rad agrees
/// within 1 % of the steady torque at every common time (the Dahl step is exact for a constant
/// bound, so only the bound's dependence on speed sees the step).
#[test]
fn a_reversal_does_not_depend_on_the_step() {
    let ev = evaluator();
    for preload in [500.0, 3000.0] {
        let rm = ReversalModel::new(&ev, preload, 0.0).unwrap();
        let coarse = reversal(&rm, 1e-4, 1);
        let fine = reversal(&rm, 1e-6, 100);
        assert_eq!(coarse.len(), fine.len());
        let scale = coarse.iter().fold(0.0_f64, |m, &(_, t)| m.max(t.abs()));
        let worst = coarse.iter().zip(&fine).fold(0.0_f64, |m, (c, f)| m.max((c.1 - f.1).abs()));
        assert!(worst <= 0.01 * scale, "{preload} N: {worst:e} N m against {scale} N m");
        // The torque does change sign through the reversal, and ends at the backwards value.
        assert!(coarse[0].1 > 0.0 && coarse.last().unwrap().1 < 0.0);
    }
}

/// Passivity: from the relaxed state, the work `integral T dtheta` over any closed cycle of the
/// screw's rotation is non-negative (Dahl's law is dissipative); a small oscillation about a
/// point of steady motion draws a loop of positive area (hysteresis).
#[test]
fn closed_cycles_dissipate() {
    let ev = evaluator();
    let rm = ReversalModel::new(&ev, 2000.0, 0.0).unwrap();
    let mut seed = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for cycle in 0..20 {
        let mut st = rm.relaxed();
        // A random path of 2-6 legs that returns to its start.
        let legs = 2 + (next() * 5.0) as usize;
        let mut targets: Vec<f64> = (0..legs - 1).map(|_| (next() - 0.5) * 10f64.powf(-4.0 + 2.0 * next())).collect();
        targets.push(0.0);
        let (mut theta, mut torque, mut work) = (0.0_f64, 0.0_f64, 0.0_f64);
        let dt = 1e-3;
        for target in targets {
            // Each leg in 400 equal steps, the last landing on the target exactly.
            let start = theta;
            for k in 1..=400 {
                let to = if k == 400 { target } else { start + (target - start) * k as f64 / 400.0 };
                let d = to - theta;
                let t = rm.step(d, dt, &mut st).unwrap();
                work += 0.5 * (torque + t) * d;
                torque = t;
                theta = to;
            }
        }
        assert!(work >= -1e-12, "cycle {cycle}: work {work:e} J");
    }
    // Hysteresis: oscillate +-1 mrad about the steady forward state; each cycle's work > 0.
    let mut st = rm.steady(rpm_to_rad_s(1.0)).unwrap();
    let (mut theta, mut work) = (0.0_f64, 0.0_f64);
    let mut torque = rm.step(0.0, 1e-3, &mut st).unwrap();
    for k in 1..=4000 {
        let next = 1e-3 * (2.0 * core::f64::consts::PI * k as f64 / 1000.0).sin();
        let t = rm.step(next - theta, 1e-3, &mut st).unwrap();
        if k > 1000 {
            work += 0.5 * (torque + t) * (next - theta);
        }
        torque = t;
        theta = next;
    }
    assert!(work > 0.0, "three cycles of oscillation: {work:e} J");
}

/// Bad steps and specs are errors that name the field.
#[test]
fn bad_input_is_an_error() {
    let ev = evaluator();
    let rm = ReversalModel::new(&ev, 1000.0, 0.0).unwrap();
    let mut st = rm.relaxed();
    for (d, dt, field) in [
        (f64::NAN, 1e-3, "rotation_rad"),
        (1e-3, 0.0, "dt_s"),
        (1e300, 1e-300, "rotation_rad"),
        (1.0, 1e-6, "30000 rpm"),
    ] {
        let err = rm.step(d, dt, &mut st).unwrap_err().to_string();
        assert!(err.contains(field), "{err}");
    }
    assert!(rm.steady(0.0).unwrap_err().to_string().contains("speed_rad_s"));
    let err = ReversalModel::new(&ev, 1.0, 0.0).unwrap_err().to_string();
    assert!(err.contains("preload_n") && err.contains("0.5 N"), "{err}");
    // No load on any ball: no friction to reverse (the command line refused this after its
    // run, the Python object not at all).
    let err = ReversalModel::new(&ev, 0.0, 0.0).unwrap_err().to_string();
    assert!(err.contains("invalid preload_n: 0 N") && err.contains("no friction to reverse"), "{err}");
    // Without a preload but with an axial load, one nut carries it.
    assert!(ReversalModel::new(&ev, 0.0, 500.0).is_ok());
    let mut spec = ScrewSpec::dkfzd4012();
    spec.extensions.seal_drag = Some(ballscrew_core::input::extensions::SealDrag { torque_nm: 0.05 });
    let ev2 = Evaluator::<f64>::new(&Model::new(&spec).unwrap()).unwrap();
    let err = ReversalModel::new(&ev2, 1000.0, 0.0).unwrap_err().to_string();
    assert!(err.contains("extensions"), "{err}");
    let _ = EvalState::<f64>::new();
}

/// The screw angles (rad) after an instant reversal from `rpm` to `-rpm` (the steady state
/// forwards, then steps of 1e-7 rad backwards) at which the torque crosses zero and reaches
/// 90 % of its new steady value, and the steady torque forwards (N m).
fn reformation(rm: &ReversalModel<f64>, rpm: f64) -> (f64, f64, f64) {
    let w = rpm_to_rad_s(rpm);
    let mut st = rm.steady(w).unwrap();
    let forwards = rm.step(0.0, 1.0, &mut st).unwrap();
    let backwards = rm.steady(-w).unwrap().friction_nm();
    let h = 1e-7;
    let (mut theta, mut zero) = (0.0, f64::NAN);
    loop {
        let t = rm.step(-h, h / w, &mut st).unwrap();
        theta += h;
        if zero.is_nan() && t <= 0.0 {
            zero = theta;
        }
        if t <= 0.9 * backwards {
            return (zero, theta, forwards);
        }
        assert!(theta < 1.0, "no re-formation within a radian");
    }
}

/// The guide's table of the reversal on DKFZD4012 (docs/real-time.md) (lubricated and dry, 10 rpm), recomputed.
#[test]
fn readme_reversal_table() {
    let readme = include_str!("../../../docs/real-time.md");
    let start = readme.find("| preload | lubrication |").expect("the guide's reversal table");
    let rows: Vec<Vec<f64>> = readme[start..]
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            l.split('|')
                .map(str::trim)
                .filter(|c| !c.is_empty())
                .filter_map(|c| c.trim_end_matches(" N").parse::<f64>().ok())
                .collect()
        })
        .collect();
    assert_eq!(rows.len(), 8, "four preloads, both lubrication options");
    let lead_um = ScrewSpec::dkfzd4012().geometry.lead_m * 1e6;
    for (k, row) in rows.iter().enumerate() {
        let mut spec = ScrewSpec::dkfzd4012();
        if k >= 4 {
            spec.model = ballscrew_core::ModelOptions::dry();
        }
        let ev = Evaluator::<f64>::new(&Model::new(&spec).unwrap()).unwrap();
        let rm = ReversalModel::new(&ev, row[0], 0.0).unwrap();
        let (zero, ninety, torque) = reformation(&rm, 10.0);
        let computed = [
            row[0],
            torque,
            rm.stiffness_nm_per_rad(),
            zero * 1e6,
            ninety * 1e6,
            ninety * lead_um / (2.0 * core::f64::consts::PI),
        ];
        let decimals = [0, 4, 0, 1, 1, 2];
        for (i, (&printed, &value)) in row.iter().zip(&computed).enumerate() {
            let scale = 10f64.powi(decimals[i]);
            assert!(
                ((value * scale).round() - printed * scale).abs() < 0.5,
                "row {k} column {i}: docs/real-time.md {printed}, computed {value:.6}"
            );
        }
    }
}

/// Passivity under an axial load: one stiffness for both directions keeps Dahl's law passive
/// (with a stiffness per direction, a small out-and-back from rest returned work and a dither
/// pumped up a one-sided torque: 0.43 of the bound after 200 cycles at 1000 N and 3000 N
/// axial load). From rest, out and back and random closed paths do non-negative work, and a
/// zero-mean dither leaves a friction torque near zero.
#[test]
fn an_axial_load_keeps_it_passive() {
    let ev = evaluator();
    for (preload, axial) in [(2000.0, 300.0), (1000.0, 3000.0)] {
        let rm = ReversalModel::new(&ev, preload, axial).unwrap();
        let bound = rm.steady(rpm_to_rad_s(10.0)).unwrap().friction_nm().abs();
        // Out by 1e-5 rad and back, from rest.
        let mut st = rm.relaxed();
        let (mut work, mut torque) = (0.0, rm.step(0.0, 1e-3, &mut st).unwrap());
        let axial_nm = torque;
        for d in [1e-6; 10].into_iter().chain([-1e-6; 10]) {
            let t = rm.step(d, 1e-3, &mut st).unwrap();
            work += 0.5 * (torque + t - 2.0 * axial_nm) * d;
            torque = t;
        }
        assert!(work >= -1e-15, "{preload} N / {axial} N: out and back does {work:e} J");
        // A +-20 urad dither from rest, 200 cycles of 40 steps.
        let mut st = rm.relaxed();
        let mut prev = 0.0;
        let mut sum = 0.0;
        for k in 1..=8000 {
            let theta = 2e-5 * (core::f64::consts::TAU * k as f64 / 40.0).sin();
            sum += rm.step(theta - prev, 1e-4, &mut st).unwrap() - axial_nm;
            prev = theta;
        }
        let mean = sum / 8000.0;
        assert!(mean.abs() < 1e-3 * bound, "{preload} N / {axial} N: mean friction {mean:e} of {bound}");
    }
}

/// The ball-ball contacts (a load between neighbours, `friction.ball_ball_load_n`) hold a state
/// of their own: their Mindlin stiffness is far above the raceway contacts' (a light sliding
/// contact re-forms within micrometres), and summed into one state with the raceway contacts it
/// would make the whole circle re-form that fast. With 2 N between neighbours the drag still
/// reaches 90 % over about the raceway contacts' angle, and at constant speed it is the static
/// model.
#[test]
fn ball_ball_contacts_relax_on_their_own() {
    let mut spec = ScrewSpec::dkfzd4012();
    spec.friction.ball_ball_load_n = Some(2.0);
    let model = Model::new(&spec).unwrap();
    let ev = Evaluator::<f64>::new(&model).unwrap();
    let rm = ReversalModel::new(&ev, 2000.0, 0.0).unwrap();
    let plain = ReversalModel::new(&evaluator(), 2000.0, 0.0).unwrap();
    assert!(rm.stiffness_nm_per_rad() > 10.0 * plain.stiffness_nm_per_rad(), "Mindlin's term dominates the sum");
    let (zero, ninety, _) = reformation(&rm, 10.0);
    let (zero0, ninety0, _) = reformation(&plain, 10.0);
    // The ball-ball share flips within micrometres, so the torque crosses zero sooner; the rest
    // re-forms over the raceway contacts' angle (measured: zero crossing 0.038 against 0.193 mrad,
    // 90 % at 0.84 against 0.97 mrad).
    assert!(zero < zero0 && ninety > 0.5 * ninety0, "{zero:e} {ninety:e} against {zero0:e} {ninety0:e}");
    let w = rpm_to_rad_s(100.0);
    let op = ballscrew_core::OperatingPoint { speed_rad_s: w, preload_n: 2000.0, axial_load_n: 0.0 };
    let stat = model.torque(&op, &mut SolverState::new()).unwrap();
    let mut st = rm.steady(w).unwrap();
    let t = rm.step(w * 1e-3, 1e-3, &mut st).unwrap();
    assert!((t - stat).abs() <= 1e-8 * stat, "{t} vs {stat}");
}
