//! The hot path allocates nothing: a counting global allocator (`allocation-counter`, linked
//! into this test binary only, the one that uses it) sees no allocation during 10,000
//! evaluations of DKFZD4012, kinematic solves included: warm-started evaluations over a grid of
//! preloads, speeds (both directions, through standstill) and axial loads, the full per-contact
//! breakdown every tenth call, and a cold start (fresh solver state, continuation) every 500th.
//! Likewise the contact-level reversal physics (`contact::presliding`) on caller buffers.

use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{Lubrication, Model, OperatingPoint, ScrewSpec, SolverState};

#[test]
fn the_counter_sees_an_allocation() {
    let info = allocation_counter::measure(|| {
        core::hint::black_box(vec![1.0_f64; 16]);
    });
    assert!(info.count_total >= 1, "the counting allocator must see a Vec's allocation");
}

#[test]
fn ten_thousand_evaluations_allocate_nothing() {
    let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
    let preloads = [500.0, 1000.0, 1700.0, 2000.0, 2600.0, 3000.0];
    let speeds_rpm = [100.0, 3000.0, 0.05, 0.0, -0.05, -100.0, -3000.0, 1.0];
    let axial_n = [0.0, 300.0, -300.0];
    let mut evaluations = 0;
    let mut cold = 0;
    let mut sum = 0.0;
    let info = allocation_counter::measure(|| {
        let mut state = SolverState::new();
        for k in 0..10_000_usize {
            if k % 500 == 0 {
                state = SolverState::new();
                cold += 1;
            }
            let op = OperatingPoint {
                preload_n: preloads[k % preloads.len()],
                speed_rad_s: rpm_to_rad_s(speeds_rpm[(k / 7) % speeds_rpm.len()]),
                axial_load_n: axial_n[(k / 11) % axial_n.len()],
            };
            sum += if k % 10 == 0 {
                model.evaluate(&op, &mut state).unwrap().summary.torque_nm
            } else {
                model.torque(&op, &mut state).unwrap()
            };
            evaluations += 1;
        }
    });
    assert!(sum.is_finite());
    assert_eq!((evaluations, cold), (10_000, 20));
    assert_eq!(info.count_total, 0, "{} allocations in {evaluations} evaluations", info.count_total);
}

/// The control-loop evaluator, in f64 and f32, lubricated (10,000 calls each) and dry (1,000)
/// over the same grid, a fresh state (table start) every 500th, nothing allocated.
#[test]
fn ten_thousand_real_time_evaluations_allocate_nothing() {
    // The dry model runs the same paths; a shorter run of it (the grid's cold solves at
    // standstill and at light loads make this test's minutes).
    for (lubrication, calls) in [(Lubrication::Ehl, 10_000), (Lubrication::Dry, 1_000)] {
        real_time_evaluations_allocate_nothing(lubrication, calls);
    }
}

/// `calls` calls of the evaluator in f64 and f32 each (every ball's first start in one pass of
/// the SIMD lanes, the rest ball by ball), through standstill, reversals and resets, on
/// `lubrication`.
fn real_time_evaluations_allocate_nothing(lubrication: Lubrication, calls: usize) {
    use ballscrew_core::{EvalState, Evaluator};
    let mut spec = ScrewSpec::dkfzd4012();
    spec.model.lubrication = lubrication;
    let model = Model::new(&spec).unwrap();
    let ev64 = Evaluator::<f64>::new(&model).unwrap();
    let ev32 = Evaluator::<f32>::new(&model).unwrap();
    let preloads = [500.0, 1000.0, 1700.0, 2000.0, 2600.0, 3000.0];
    let speeds_rpm = [100.0, 3000.0, 0.05, 0.0, -0.05, -100.0, -3000.0, 1.0];
    let axial_n = [0.0, 300.0, -300.0];
    let mut sum = 0.0;
    let info = allocation_counter::measure(|| {
        let mut s64 = EvalState::new();
        let mut s32 = EvalState::new();
        for k in 0..calls {
            if k % 500 == 0 {
                s64.reset();
                s32.reset();
            }
            let (p, w, a) = (
                preloads[k % preloads.len()],
                rpm_to_rad_s(speeds_rpm[(k / 7) % speeds_rpm.len()]),
                axial_n[(k / 11) % axial_n.len()],
            );
            sum += ev64.torque_nm(&OperatingPoint { speed_rad_s: w, preload_n: p, axial_load_n: a }, &mut s64).unwrap();
            sum += f64::from(
                ev32.torque_nm(
                    &OperatingPoint {
                        speed_rad_s: f64::from(w as f32),
                        preload_n: f64::from(p as f32),
                        axial_load_n: f64::from(a as f32),
                    },
                    &mut s32,
                )
                .unwrap(),
            );
        }
    });
    assert!(sum.is_finite());
    assert_eq!(info.count_total, 0, "{lubrication:?}: {} allocations in {} evaluations", info.count_total, 2 * calls);
}

/// The paths a batch adds allocate nothing: solving the evaluator's table again at other speeds
/// (`with_table_speed`, and `with_table_speed_for` the entries points start from, found by
/// `table_entries`: the bands of a batch), and evaluating with those tables through a drive
/// cycle in f64 and in f32, where a ball whose warm start fails takes a Jacobian in f64.
#[test]
fn batch_tables_and_drive_cycles_allocate_nothing() {
    use ballscrew_core::{EvalState, Evaluator};
    let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
    let ev64 = Evaluator::<f64>::new(&model).unwrap();
    let ev32 = Evaluator::<f32>::new(&model).unwrap();
    let mut sum = 0.0;
    let info = allocation_counter::measure(|| {
        let (mut t64, mut t32) = (ev64, ev32);
        for band in 1..=3 {
            let w = rpm_to_rad_s(100.0 * 1.1_f64.powi(band));
            t64 = t64.with_table_speed(w);
            t32 = t32.with_table_speed(w);
        }
        let cond = ballscrew_core::Conditions::default();
        let entries = t64.table_entries(
            &OperatingPoint { speed_rad_s: rpm_to_rad_s(200.0), preload_n: 2000.0, axial_load_n: 300.0 },
            &cond,
        );
        let entries = entries.join(&t64.table_entries(
            &OperatingPoint { speed_rad_s: rpm_to_rad_s(-250.0), preload_n: 1800.0, axial_load_n: -300.0 },
            &cond,
        ));
        t64 = t64.with_table_speed_for(rpm_to_rad_s(200.0), &entries);
        t32 = t32.with_table_speed_for(rpm_to_rad_s(200.0), &entries);
        let (mut s64, mut s32) = (EvalState::new(), EvalState::new());
        for k in 0..2000_u32 {
            let phase = 2.0 * core::f64::consts::PI * f64::from(k) / 2000.0;
            let w = rpm_to_rad_s(300.0 * (10.0 * phase).sin());
            let a = 400.0 * (7.0 * phase).sin();
            sum += t64
                .torque_nm(&OperatingPoint { speed_rad_s: w, preload_n: 2000.0, axial_load_n: a }, &mut s64)
                .unwrap();
            sum += f64::from(
                t32.torque_nm(
                    &OperatingPoint {
                        speed_rad_s: f64::from(w as f32),
                        preload_n: 2000.0,
                        axial_load_n: f64::from(a as f32),
                    },
                    &mut s32,
                )
                .unwrap(),
            );
        }
    });
    assert!(sum.is_finite());
    assert_eq!(info.count_total, 0, "{} allocations", info.count_total);
}

/// The reversal state model's steps allocate nothing (f64 and f32): a sinusoidal motion through
/// two reversals, stepped at 1e-5 rad, from a steady start.
#[test]
fn reversal_steps_allocate_nothing() {
    use ballscrew_core::{Evaluator, ReversalModel};
    let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
    let ev64 = Evaluator::<f64>::new(&model).unwrap();
    let ev32 = Evaluator::<f32>::new(&model).unwrap();
    let rm64 = ReversalModel::new(&ev64, 2000.0, 100.0).unwrap();
    let rm32 = ReversalModel::new(&ev32, 2000.0, 100.0).unwrap();
    let peak = rpm_to_rad_s(10.0);
    let mut sum = 0.0;
    let info = allocation_counter::measure(|| {
        let mut s64 = rm64.steady(peak).unwrap();
        let mut s32 = rm32.steady(peak as f32).unwrap();
        let (amplitude, dt) = (0.01, 1e-5 / peak);
        let mut prev = 0.0;
        for k in 1..=4000 {
            let theta = amplitude * (peak / amplitude * k as f64 * dt).sin();
            sum += rm64.step(theta - prev, dt, &mut s64).unwrap();
            sum += f64::from(rm32.step((theta - prev) as f32, dt as f32, &mut s32).unwrap());
            prev = theta;
        }
    });
    assert!(sum.is_finite());
    assert_eq!(info.count_total, 0, "{} allocations in 8,000 reversal steps", info.count_total);
}

/// The reversal physics of one contact (`contact::presliding`): the transient simplified theory
/// started both ways and stepped through reversals on a caller's buffer, the reversal slope, the
/// totals of a field and Dahl's element in f64 and f32.
#[test]
fn presliding_steps_allocate_nothing() {
    use ballscrew_core::contact::fastsim::{Element, FastsimInput, Grid, TractionBound};
    use ballscrew_core::contact::patch::{Contact, Creep};
    use ballscrew_core::contact::presliding::{Direction, Transient, dahl_step, field_totals, reversal_slope};
    let inp = FastsimInput {
        contact: Contact {
            semi_axis_rolling_m: 0.12e-3,
            semi_axis_lateral_m: 1.0e-3,
            normal_load_n: 200.0,
            shear_modulus_pa: 80.8e9,
            poisson_ratio: 0.3,
            friction_coefficient: 0.1,
        },
        creep: Creep { xi: 2e-4, eta: -1e-4, phi_per_m: 1.0, heathcote_per_m2: 100.0 },
        bound: TractionBound::Parabolic,
        grid: Grid::Strips,
    };
    let mut cells = [Element::default(); 24 * 24];
    let mut sum = 0.0;
    let mut steps = 0;
    let info = allocation_counter::measure(|| {
        let t = Transient::new(&inp, 24, 24).unwrap();
        let k = reversal_slope(&inp).unwrap();
        let ds = t.cell_length_m();
        sum += t.start_zero(&mut cells).unwrap().creepage_power_n;
        let mut z = 0.0_f64;
        let mut z32 = 0.0_f32;
        for direction in [Direction::Forward, Direction::Reversed, Direction::Forward] {
            sum += t.start_steady(direction, &mut cells).unwrap().creepage_power_n;
            for _ in 0..30 {
                let r = t.step(&mut cells, 0.7 * ds, direction.reversed()).unwrap();
                z = dahl_step(z, 1.0, 0.5 * k, -direction.sign() * ds).unwrap();
                z32 = dahl_step(z32, 1.0, 0.5 * k as f32, -direction.sign() as f32 * ds as f32).unwrap();
                sum += r.creepage_power_n + z + f64::from(z32);
                steps += 1;
            }
        }
        sum += field_totals(&inp, &cells).unwrap().dissipation_n;
    });
    assert!(sum.is_finite());
    assert_eq!(steps, 90);
    assert_eq!(info.count_total, 0, "{} allocations", info.count_total);
}
