//! Benchmarks of one full evaluation of DKFZD4012 (kinematic solve of every circle's ball and
//! the torque) and of the 26-point preload sweep.
//!
//! - `cold`: a fresh [`SolverState`] each time, so every circle's ball is solved from pure
//!   rolling by continuation (what the first call of a simulation costs);
//! - `warm_nearby`: the state left by the previous call, which was at a nearby operating point:
//!   the calls alternate between 2000 N / 100 rpm / no axial load and 2010 N / 101 rpm / 10 N
//!   axial load (what a control loop sees from step to step, and more: the preload and the
//!   axial load both move, so every circle's Newton solve has real work to do);
//!   Since the state keeps each ball's last two solutions for a secant start, a call that
//!   returns to the point before last starts from nearly its solution: `warm_ramp` is the
//!   figure for a point that keeps moving;
//! - `warm_ramp`: a control loop's load history: the preload runs up and down between 1900 and
//!   2100 N in steps of 1 N per call, the axial load between 0 and 50 N in steps of 0.25 N and
//!   the speed between 100 and 150 rpm (so no call repeats an earlier point; the
//!   secant start extrapolates from the two calls before);
//! - `warm_same`: the state left by a call at the very same point (a loop at constant load; the
//!   Newton solve stops after one residual per circle);
//! - `sweep_26`: 500..3000 N in steps of 100 N at 100 rpm, from a fresh state, warm-started
//!   point to point as `ballscrew sweep` does;
//! - `map_lookup`: one lookup in the torque map of `ballscrew map`'s default grid (11 preloads
//!   x 4 speed magnitudes, both directions), at points cycling over 1024 preloads and speeds
//!   through standstill and both directions;
//! - `realtime_f64_*`, `realtime_f32_*`: the control-loop evaluator
//!   ([`ballscrew_core::Evaluator`]) in f64 and f32: `cold` (a fresh state, every ball from
//!   the start table), `warm_ramp`, `warm_same` and the 26-point sweep, as above, and
//!   `warm_speed_ramp`: the speed alone between 100 and 150 rpm by 0.25 rpm a call at 2000 N
//!   (an axis accelerating at constant load; with lubricated contacts the balls' friction
//!   follows the speed through the films); the groups
//!   `..._dry_...` run the same on the dry model (`lubrication = "dry"`), the figures before
//!   the lubricant, for the ratio in one run;
//! - `reversal_f64_*`, `reversal_f32_*`: one step of the reversal state model
//!   ([`ballscrew_core::ReversalModel`], 2000 N): `sinusoid` steps a sinusoidal motion of
//!   0.01 rad amplitude and 10 rpm peak speed through its reversals at 1e-5 rad per step (the
//!   speed, and so every ball's bound, changes each step); `constant_speed` steps at 100 rpm;
//! - `arrangements_16x5_*`: the single-nut 16 x 5 screw of `configs/single-nut-16x5.toml` at
//!   200 N and 1000 rpm with oversize balls (four-point contact, [`ballscrew_core::ball::four_point`])
//!   and as the double nut of the same balls: `cold` and `warm_ramp` (the preload between 190
//!   and 210 N, the axial load between 0 and 50 N), for their ratio in one run;
//! - `circuit_dkfzd4012_external_2000n_100rpm`: DKFZD4012 with an external return (each nut's
//!   four circles in one circuit, whose ball train the model balances as one,
//!   `screw/circuit.rs`, from the cold start whatever the state holds): `cold`, for the ratio to
//!   `dkfzd4012_2000n_100rpm` (the internal return) in one run;
//! - `fastsim_*`: the model with FASTSIM at every raceway contact (`contact_theory =
//!   "fastsim"`, 20 x 20 elements), `warm_same` and `warm_ramp` as above, lubricated and dry;
//! - `balance_lanes_f64`, `balance_lanes_f32`: the balance of DKFZD4012's eight balls (each
//!   circle's, both nuts, 2000 N, 100 rpm, lubricated, at their solutions) evaluated
//!   `one_by_one` ([`ballscrew_core::ball::balance::evaluate`] in f64 or f32) against `in_lanes`
//!   (the same in `Real::Wide`, four f64 or eight f32 balls a pass: their states and loads
//!   gathered and the outcomes taken back lane by lane each time, their constants gathered
//!   once, as the evaluator keeps each flank's: what it does for every ball's first start),
//!   the same numbers to the bit.

use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{ContactTheory, Lubrication, Model, OperatingPoint, Preload, ScrewSpec, SolverState};
use core::hint::black_box;
use criterion::{Criterion, criterion_group, criterion_main};

fn point(preload_n: f64, speed_rpm: f64, axial_load_n: f64) -> OperatingPoint {
    OperatingPoint { speed_rad_s: rpm_to_rad_s(speed_rpm), preload_n, axial_load_n }
}

/// A triangle wave of period `period` calls: 0, 1, ..., period / 2, ..., 1, 0, 1, ...
fn triangle(k: u32, period: u32) -> f64 {
    let (k, half) = (k % period, period / 2);
    f64::from(if k < half { k } else { period - k })
}

/// Call `k` of `warm_ramp`: the preload between 1900 and 2100 N, the speed between 100 and
/// 150 rpm and the axial load between 0 and 50 N, each along the same triangle (see the module
/// docs).
fn ramp_point(k: u32) -> OperatingPoint {
    let t = triangle(k, 400);
    point(1900.0 + t, 100.0 + 0.25 * t, 0.25 * t)
}

fn evaluation(c: &mut Criterion) {
    let model = Model::new(&ScrewSpec::dkfzd4012()).expect("built-in spec");
    let a = point(2000.0, 100.0, 0.0);
    let b = point(2010.0, 101.0, 10.0);
    let mut g = c.benchmark_group("dkfzd4012_2000n_100rpm");
    g.bench_function("cold", |bench| {
        bench.iter(|| {
            let mut state = SolverState::new();
            model.torque(black_box(&a), &mut state).expect("converges")
        })
    });
    let mut state = SolverState::new();
    model.torque(&a, &mut state).expect("converges");
    let mut flip = false;
    g.bench_function("warm_nearby", |bench| {
        bench.iter(|| {
            flip = !flip;
            let op = if flip { &b } else { &a };
            model.torque(black_box(op), &mut state).expect("converges")
        })
    });
    let mut k = 0_u32;
    g.bench_function("warm_ramp", |bench| {
        bench.iter(|| {
            k = k.wrapping_add(1);
            model.torque(black_box(&ramp_point(k)), &mut state).expect("converges")
        })
    });
    model.torque(&a, &mut state).expect("converges");
    g.bench_function("warm_same", |bench| bench.iter(|| model.torque(black_box(&a), &mut state).expect("converges")));
    g.finish();
}

fn sweep(c: &mut Criterion) {
    let model = Model::new(&ScrewSpec::dkfzd4012()).expect("built-in spec");
    let ops: Vec<OperatingPoint> = (0..26).map(|k| point(500.0 + 100.0 * f64::from(k), 100.0, 0.0)).collect();
    c.bench_function("sweep_26_points_500_3000n", |bench| {
        bench.iter(|| {
            let mut state = SolverState::new();
            let mut sum = 0.0;
            for op in &ops {
                sum += model.torque(black_box(op), &mut state).expect("converges");
            }
            sum
        })
    });
}

fn map_lookup(c: &mut Criterion) {
    use ballscrew_core::realtime::map::{MapGrid, tabulate};
    let spec = ScrewSpec::dkfzd4012();
    let model = Model::new(&spec).expect("built-in spec");
    let grid =
        MapGrid::spanning((500.0, 3000.0, 11), (0.0, rpm_to_rad_s(3000.0), 4), spec.friction.standstill_speed_rad_s);
    let table = tabulate(&model, &grid, 0.0).expect("tabulates");
    let map = table.map();
    let points: Vec<(f32, f32)> = (0..1024)
        .map(|k| {
            let x = k as f32 / 1024.0;
            (
                400.0 + 2700.0 * x,
                rpm_to_rad_s(f64::from(3200.0 * (2.0 * x - 1.0) * (1.0 - 0.999 * (k % 3) as f32))) as f32,
            )
        })
        .collect();
    let mut k = 0;
    c.bench_function("map_lookup", |bench| {
        bench.iter(|| {
            k = (k + 1) & 1023;
            let (p, w) = points[k];
            map.torque_nm(black_box(p), black_box(w))
        })
    });
}

/// The control-loop evaluator (`ballscrew_core::realtime::evaluator`) in f64 and f32, on the same
/// workloads: `cold` (fresh state: every ball from the start table), `warm_ramp`, `warm_same`
/// and the 26-point sweep from a fresh state.
fn realtime<F: ballscrew_core::real::Real>(c: &mut Criterion, name: &str, lubrication: Lubrication) {
    use ballscrew_core::{EvalState, Evaluator};
    let mut spec = ScrewSpec::dkfzd4012();
    spec.model.lubrication = lubrication;
    let model = Model::new(&spec).expect("built-in spec");
    let ev = Evaluator::<F>::new(&model).expect("linear-saturated");
    let w = rpm_to_rad_s(100.0);
    let p = 2000.0;
    let zero = 0.0;
    let mut g = c.benchmark_group(name);
    g.bench_function("cold", |bench| {
        bench.iter(|| {
            let mut state = EvalState::new();
            ev.torque_nm(
                &OperatingPoint { speed_rad_s: black_box(w), preload_n: black_box(p), axial_load_n: zero },
                &mut state,
            )
            .expect("converges")
        })
    });
    let mut state = EvalState::new();
    let mut k = 0_u32;
    g.bench_function("warm_ramp", |bench| {
        bench.iter(|| {
            k = k.wrapping_add(1);
            let op = ramp_point(k);
            let (pk, wk, ak) = (op.preload_n, op.speed_rad_s, op.axial_load_n);
            ev.torque_nm(
                &OperatingPoint { speed_rad_s: black_box(wk), preload_n: black_box(pk), axial_load_n: ak },
                &mut state,
            )
            .expect("converges")
        })
    });
    let mut k = 0_u32;
    g.bench_function("warm_speed_ramp", |bench| {
        bench.iter(|| {
            k = k.wrapping_add(1);
            let wk = rpm_to_rad_s(100.0 + 0.25 * triangle(k, 400));
            ev.torque_nm(
                &OperatingPoint { speed_rad_s: black_box(wk), preload_n: black_box(p), axial_load_n: zero },
                &mut state,
            )
            .expect("converges")
        })
    });
    ev.torque_nm(&OperatingPoint { speed_rad_s: w, preload_n: p, axial_load_n: zero }, &mut state).expect("converges");
    g.bench_function("warm_same", |bench| {
        bench.iter(|| {
            ev.torque_nm(
                &OperatingPoint { speed_rad_s: black_box(w), preload_n: black_box(p), axial_load_n: zero },
                &mut state,
            )
            .expect("converges")
        })
    });
    let preloads: Vec<f64> = (0..26).map(|k| 500.0 + 100.0 * f64::from(k)).collect();
    g.bench_function("sweep_26_points_500_3000n", |bench| {
        bench.iter(|| {
            let mut state = EvalState::new();
            let mut sum = F::zero();
            for &pk in &preloads {
                sum += ev
                    .torque_nm(
                        &OperatingPoint { speed_rad_s: w, preload_n: black_box(pk), axial_load_n: zero },
                        &mut state,
                    )
                    .expect("converges");
            }
            sum
        })
    });
    g.finish();
}

fn realtime_f64(c: &mut Criterion) {
    realtime::<f64>(c, "realtime_f64_dkfzd4012_2000n_100rpm", Lubrication::Ehl);
    realtime::<f64>(c, "realtime_f64_dry_dkfzd4012_2000n_100rpm", Lubrication::Dry);
}

fn realtime_f32(c: &mut Criterion) {
    realtime::<f32>(c, "realtime_f32_dkfzd4012_2000n_100rpm", Lubrication::Ehl);
    realtime::<f32>(c, "realtime_f32_dry_dkfzd4012_2000n_100rpm", Lubrication::Dry);
}

/// One step of the reversal state model in float type `F` (see the module documentation).
fn reversal<F: ballscrew_core::real::Real>(c: &mut Criterion, name: &str) {
    use ballscrew_core::{Evaluator, ReversalModel};
    let model = Model::new(&ScrewSpec::dkfzd4012()).expect("built-in spec");
    let ev = Evaluator::<F>::new(&model).expect("linear-saturated");
    let rm = ReversalModel::new(&ev, 2000.0, 0.0).expect("reversal model");
    let peak = rpm_to_rad_s(10.0);
    let (amplitude, dt) = (0.01, 1e-5 / peak);
    let mut g = c.benchmark_group(name);
    let mut state = rm.steady(F::of(peak)).expect("steady");
    let (mut k, mut prev) = (0_u64, 0.0);
    g.bench_function("sinusoid", |bench| {
        bench.iter(|| {
            k += 1;
            let theta = amplitude * (peak / amplitude * k as f64 * dt).sin();
            let d = theta - prev;
            prev = theta;
            rm.step(black_box(F::of(d)), F::of(dt), &mut state).expect("converges")
        })
    });
    let w = rpm_to_rad_s(100.0);
    let mut state = rm.steady(F::of(w)).expect("steady");
    g.bench_function("constant_speed", |bench| {
        bench.iter(|| rm.step(black_box(F::of(w * 1e-4)), F::of(1e-4), &mut state).expect("converges"))
    });
    g.finish();
}

fn reversal_steps(c: &mut Criterion) {
    reversal::<f64>(c, "reversal_f64_dkfzd4012_2000n");
    reversal::<f32>(c, "reversal_f32_dkfzd4012_2000n");
}

/// The single-nut 16 x 5 screw with oversize balls and as a double nut (see the module docs).
fn arrangements(c: &mut Criterion) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/configs/single-nut-16x5.toml");
    let four = ballscrew_config::spec_from_toml_file(std::path::Path::new(path)).expect("the 16 x 5 spec");
    let mut double = four;
    double.geometry.preload = Preload::DoubleNut;
    double.geometry.nuts = 2;
    for (name, spec) in [("arrangements_16x5_oversize_ball", four), ("arrangements_16x5_double_nut", double)] {
        let model = Model::new(&spec).expect("valid");
        let a = point(200.0, 1000.0, 0.0);
        let mut g = c.benchmark_group(name);
        g.bench_function("cold", |bench| {
            bench.iter(|| model.torque(black_box(&a), &mut SolverState::new()).expect("converges"))
        });
        let mut state = SolverState::new();
        let mut k = 0_u32;
        g.bench_function("warm_ramp", |bench| {
            bench.iter(|| {
                k = k.wrapping_add(1);
                let t = triangle(k, 80);
                let op = point(190.0 + 0.5 * t, 1000.0, 1.25 * t);
                model.torque(black_box(&op), &mut state).expect("converges")
            })
        });
        g.finish();
    }
}

/// DKFZD4012 with an external return: the train of a circuit of four loaded turns (see the
/// module docs).
fn circuit(c: &mut Criterion) {
    let mut spec = ScrewSpec::dkfzd4012();
    spec.circulation.kind = ballscrew_core::input::circulation::Return::External;
    let model = Model::new(&spec).expect("valid");
    let a = point(2000.0, 100.0, 0.0);
    let mut g = c.benchmark_group("circuit_dkfzd4012_external_2000n_100rpm");
    g.bench_function("cold", |bench| {
        bench.iter(|| model.torque(black_box(&a), &mut SolverState::new()).expect("converges"))
    });
    g.finish();
}

/// The whole screw with FASTSIM at every raceway contact (`contact_theory = "fastsim"`, the
/// default 20 x 20 grid), lubricated and dry: `warm_same` and `warm_ramp` as above.
fn fastsim(c: &mut Criterion) {
    for (name, lubrication) in
        [("fastsim_dkfzd4012_2000n_100rpm", Lubrication::Ehl), ("fastsim_dry_dkfzd4012_2000n_100rpm", Lubrication::Dry)]
    {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.model.contact_theory = ContactTheory::Fastsim;
        spec.model.lubrication = lubrication;
        let model = Model::new(&spec).expect("valid");
        let a = point(2000.0, 100.0, 0.0);
        let mut state = SolverState::new();
        model.torque(&a, &mut state).expect("converges");
        let mut g = c.benchmark_group(name);
        g.bench_function("warm_same", |bench| {
            bench.iter(|| model.torque(black_box(&a), &mut state).expect("converges"))
        });
        let mut k = 0_u32;
        g.bench_function("warm_ramp", |bench| {
            bench.iter(|| {
                k = k.wrapping_add(1);
                model.torque(black_box(&ramp_point(k)), &mut state).expect("converges")
            })
        });
        g.finish();
    }
}

/// The balance of eight balls one by one and in lanes, in float type `F` (module docs).
fn balance_lanes<F: ballscrew_core::real::Real>(c: &mut Criterion, name: &str) {
    use ballscrew_core::ball::balance::{Constants, Load, evaluate, gather_states};
    use ballscrew_core::ball::solve;
    use ballscrew_core::real::Lanes;
    let model = Model::new(&ScrewSpec::dkfzd4012()).expect("built-in spec");
    let w = rpm_to_rad_s(100.0);
    let shares = [1.0, 2.0 / 3.0, 4.0 / 9.0, 8.0 / 27.0];
    let per_ball = 2000.0 / shares.iter().sum::<f64>() / 19.0;
    let mut constants = Vec::new();
    let mut states = Vec::new();
    let mut loads = Vec::new();
    for flank in [1.0, -1.0] {
        for share in shares {
            let p = per_ball * share;
            let (setup, _) = model.ball_setup_at(p, flank, w, 1.0);
            let (x, _) = solve::solve(&setup, None, 1.0, 1.0);
            constants.push(Constants::<F>::new(&setup, model.ball_ball_approach_m()));
            states.push(x.map(F::of));
            loads.push(Load { axial_load_n: F::of(p), direction: F::of(1.0), factor: F::of(1.0) });
        }
    }
    let lanes = <F::Wide as Lanes>::LANES;
    let mut g = c.benchmark_group(name);
    g.bench_function("one_by_one", |bench| {
        bench.iter(|| {
            let mut sum = F::of(0.0);
            for i in 0..constants.len() {
                sum += evaluate(black_box(&constants[i]), black_box(&states[i]), &loads[i]).dissipation_per_speed;
            }
            sum
        })
    });
    // The constants of each group of lanes, gathered once (as the evaluator keeps each flank's).
    let groups: Vec<(usize, usize, Constants<F::Wide>)> = (0..constants.len())
        .step_by(lanes)
        .map(|first| {
            let last = (first + lanes).min(constants.len());
            let refs: Vec<&Constants<F>> = constants[first..last].iter().collect();
            (first, last, Constants::<F::Wide>::gather(&refs))
        })
        .collect();
    g.bench_function("in_lanes", |bench| {
        bench.iter(|| {
            let mut sum = F::of(0.0);
            for (first, last, c) in &groups {
                let x = gather_states::<F::Wide>(black_box(&states[*first..*last]));
                let o = evaluate(black_box(c), &x, &Load::gather(&loads[*first..*last]));
                for lane in 0..last - first {
                    sum += o.lane(lane).dissipation_per_speed;
                }
            }
            sum
        })
    });
    g.finish();
}

fn balance_lanes_f64_f32(c: &mut Criterion) {
    balance_lanes::<f64>(c, "balance_lanes_f64");
    balance_lanes::<f32>(c, "balance_lanes_f32");
}

criterion_group!(
    benches,
    evaluation,
    circuit,
    sweep,
    map_lookup,
    realtime_f64,
    realtime_f32,
    reversal_steps,
    arrangements,
    fastsim,
    balance_lanes_f64_f32
);
criterion_main!(benches);
