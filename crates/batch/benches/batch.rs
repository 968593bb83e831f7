//! Batches of DKFZD4012 torques by `ballscrew_batch::torques` on the machine's cores, each timed
//! whole, by both starts: `canonical/...` (`Start::Independent`: each point the model's cold
//! solve, its canonical state; the path of Python's `Screw.torque` on arrays and of `predict`)
//! and `warm/...` (`Start::Warm`: the control-loop evaluator band by band of speed, its build
//! and the bands' tables included; the path of the diagnosis's fits). Their ratio in one run is
//! the cost of the canonical rule (the dry model's canonical drive cycle left out: its cold
//! solves take seconds a batch):
//!
//! - `random_1000_1_1000rpm`: 1000 points of uniform random preload (500-3000 N), axial load
//!   (-500..500 N) and speed (1-1000 rpm, either direction), in random order;
//! - `random_1000_1_3000rpm`: the same up to 3000 rpm (above about 1300 rpm some ball loads
//!   take the model's continuation, see `ballscrew_batch::evaluated`);
//! - `drive_cycle_10000`: 10,000 points of a drive cycle in time order, as `predict` reads a
//!   measured log (2000 N falling to 1700 N, the speed 300 rpm +- 250 rpm over three periods,
//!   the axial load +-200 N over five);
//! - `evaluator_new`: building the control-loop evaluator (its start table) alone;
//!
//! each for the lubricated default (`batch_lubricated`) and the dry option (`batch_dry`); and the
//! band of the drag torque (`band`, `ballscrew_batch::uncertainty`, the default 128 samples of
//! the default `[uncertainty]`, over the machine's cores):
//!
//! - `point_100rpm`, `point_1000rpm`: DKFZD4012 at 2000 N (`ballscrew torque --band`);
//! - `sweep_26_100rpm`: the 26 preloads 500-3000 N of `ballscrew sweep --band` at 100 rpm;
//! - `sensitivity_100rpm`: the swings and Sobol indices at 2000 N, 100 rpm (`ballscrew
//!   sensitivity`: (k + 2) x 128 samples for k = 8 inputs).

use ballscrew_batch::sweep::SweepPoint;
use ballscrew_batch::uncertainty::{BandSettings, band, sensitivity};
use ballscrew_batch::{Batch, Errors, Start, threads_for};
use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{Evaluator, Lubrication, Model, OperatingPoint, ScrewSpec};
use core::hint::black_box;
use criterion::{Criterion, criterion_group, criterion_main};

fn random(n: usize, max_rpm: f64) -> Vec<OperatingPoint> {
    let mut s = 2015_u64;
    let mut rnd = move || {
        s = s.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        (s >> 11) as f64 / (1_u64 << 53) as f64
    };
    (0..n)
        .map(|_| {
            let rpm = (1.0 + (max_rpm - 1.0) * rnd()) * if rnd() < 0.5 { -1.0 } else { 1.0 };
            OperatingPoint {
                preload_n: 500.0 + 2500.0 * rnd(),
                speed_rad_s: rpm_to_rad_s(rpm),
                axial_load_n: -500.0 + 1000.0 * rnd(),
            }
        })
        .collect()
}

fn drive_cycle(n: usize) -> Vec<OperatingPoint> {
    (0..n)
        .map(|i| {
            let t = i as f64 / n as f64;
            let tau = 2.0 * core::f64::consts::PI;
            OperatingPoint {
                preload_n: 2000.0 - 300.0 * t,
                speed_rad_s: rpm_to_rad_s(300.0 + 250.0 * (tau * 3.0 * t).sin()),
                axial_load_n: 200.0 * (tau * 5.0 * t).sin(),
            }
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    for (name, lubrication) in [("batch_lubricated", Lubrication::Ehl), ("batch_dry", Lubrication::Dry)] {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.model.lubrication = lubrication;
        let model = Model::new(&spec).expect("built-in spec");
        let mut g = c.benchmark_group(name);
        g.sample_size(10);
        for (label, ops) in [
            ("random_1000_1_1000rpm", random(1000, 1000.0)),
            ("random_1000_1_3000rpm", random(1000, 3000.0)),
            ("drive_cycle_10000", drive_cycle(10_000)),
        ] {
            let threads = threads_for(ops.len());
            for (start_name, start) in [("canonical", Start::Independent), ("warm", Start::Warm)] {
                // The dry model's cold solve costs milliseconds: its canonical drive cycle would
                // take minutes of criterion's samples.
                if start == Start::Independent && lubrication == Lubrication::Dry && ops.len() > 1000 {
                    continue;
                }
                g.bench_function(format!("{start_name}/{label}"), |b| {
                    b.iter(|| {
                        Batch::new(0)
                            .threads(threads)
                            .errors(Errors::Raise)
                            .start(start)
                            .torques(&model, None, black_box(&ops), None)
                            .expect("evaluates")
                    })
                });
            }
        }
        g.bench_function("evaluator_new", |b| b.iter(|| Evaluator::<f64>::new(black_box(&model)).expect("builds")));
        g.finish();
    }
}

fn bench_band(c: &mut Criterion) {
    let model = Model::new(&ScrewSpec::dkfzd4012()).expect("built-in spec");
    let at = |rpm: f64, preload_n: f64| SweepPoint {
        op: OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n, axial_load_n: 0.0 },
        model: &model,
    };
    let settings = BandSettings::default();
    let batch = Batch::new(settings.samples as usize);
    let mut g = c.benchmark_group("band");
    g.sample_size(10);
    for (label, rpm) in [("point_100rpm", 100.0), ("point_1000rpm", 1000.0)] {
        let point = [at(rpm, 2000.0)];
        g.bench_function(label, |b| b.iter(|| band(&batch, black_box(&point), &settings).expect("evaluates")));
    }
    let sweep: Vec<SweepPoint> = (0..26).map(|k| at(100.0, 500.0 + 100.0 * f64::from(k))).collect();
    g.bench_function("sweep_26_100rpm", |b| b.iter(|| band(&batch, black_box(&sweep), &settings).expect("evaluates")));
    let point = at(100.0, 2000.0);
    g.bench_function("sensitivity_100rpm", |b| {
        b.iter(|| sensitivity(&batch, black_box(&point), &settings).expect("evaluates"))
    });
    g.finish();
}

criterion_group!(benches, bench, bench_band);
criterion_main!(benches);
