use ballscrew_batch::{Errors, Never, torques};
use ballscrew_core::{Lubrication, Model, OperatingPoint, ScrewSpec, SolverState};
use std::time::Instant;
#[test]
fn measure() {
    let mut s = 7u64;
    let mut rnd = move || {
        s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    let ops: Vec<OperatingPoint> = (0..2000)
        .map(|_| {
            let rpm = (1.0 + 2999.0 * rnd()) * if rnd() < 0.5 { -1.0 } else { 1.0 };
            OperatingPoint {
                preload_n: 500.0 + 2500.0 * rnd(),
                speed_rad_s: rpm * core::f64::consts::PI / 30.0,
                axial_load_n: -500.0 + 1000.0 * rnd(),
            }
        })
        .collect();
    for lub in [Lubrication::Ehl] {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.model.lubrication = lub;
        let model = Model::new(&spec).unwrap();
        let t = Instant::now();
        let got = torques(&model, None, &ops, None, 2, &Never, Errors::Raise).unwrap();
        let tb = t.elapsed();
        let want: Vec<f64> = ops.iter().map(|o| model.torque(o, &mut SolverState::new()).unwrap()).collect();
        let mut rels: Vec<(f64, usize)> =
            got.iter().zip(&want).enumerate().map(|(i, (g, w))| (((g.as_ref().unwrap() - w) / w).abs(), i)).collect();
        rels.sort_by(|a, b| a.0.total_cmp(&b.0));
        let bad: Vec<_> = rels.iter().filter(|r| r.0 > 1e-8).collect();
        println!(
            "{lub:?}: batch {tb:?} ({:?}/pt); max rel {:e}; above 1e-8: {}",
            tb / 2000,
            rels.last().unwrap().0,
            bad.len()
        );
        for &&(r, i) in bad.iter().rev().take(5) {
            println!("   {r:e} at {:?} rpm {:.0}", ops[i], ops[i].speed_rad_s * 30.0 / core::f64::consts::PI);
        }
    }
}
