//! Time of a whole diagnosis (calibration, every candidate in 5-fold cross-validation, report):
//! a 384-row synthetic dataset with a hidden preload loss (7 candidates evaluated), and the
//! 30-row XJTU degradation data (one candidate).

use ballscrew_config::spec_from_toml_str;
use ballscrew_core::ScrewSpec;
use ballscrew_core::input::extensions::{Extensions, PreloadLoss};
use ballscrew_diagnose::data::{Column, Dataset};
use ballscrew_diagnose::diagnose;
use core::hint::black_box;
use criterion::{Criterion, criterion_group, criterion_main};

#[path = "../tests/synth/mod.rs"]
mod synth;

fn bench(c: &mut Criterion) {
    let ext = Extensions { preload_loss: Some(PreloadLoss { loss_per_1000_h: 0.35 }), ..Extensions::NONE };
    let data = Dataset::from_csv(&synth::generate(15, ext, false).csv, &[]).unwrap();
    let spec = ScrewSpec::dkfzd4012();
    let xjtu_map = [(Column::TimeH, "hours".to_string()), (Column::TorqueNm, "upper_screw_torque_Nm".to_string())];
    let xjtu = Dataset::from_csv(include_str!("../tests/data/xjtu-ball-screw/friction_torque.csv"), &xjtu_map).unwrap();
    let xjtu_spec = spec_from_toml_str(include_str!("../configs/xjtu-32x8.toml"), "xjtu-32x8.toml").unwrap();
    let mut g = c.benchmark_group("diagnose");
    g.sample_size(10);
    g.bench_function("synthetic_384_rows", |b| b.iter(|| diagnose(black_box(&spec), black_box(&data)).unwrap()));
    g.bench_function("xjtu_30_rows", |b| b.iter(|| diagnose(black_box(&xjtu_spec), black_box(&xjtu)).unwrap()));
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
