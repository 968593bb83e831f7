use ballscrew_batch::Batch;
use ballscrew_batch::sweep::SweepPoint;
use ballscrew_batch::uncertainty::{BandSettings, band};
use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{Model, OperatingPoint, ScrewSpec};
fn main() {
    let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
    for rpm in [100.0, 1000.0] {
        let p = [SweepPoint {
            op: OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: 2000.0, axial_load_n: 0.0 },
            model: &model,
        }];
        let reference = band(&Batch::new(2), &p, &BandSettings { samples: 8192, ..Default::default() }).unwrap()[0];
        let width = reference.high_nm - reference.low_nm;
        println!(
            "{rpm} rpm reference (8192): {:.5} {:.5} {:.5} width {:.5}",
            reference.low_nm, reference.median_nm, reference.high_nm, width
        );
        for n in [16u32, 32, 64, 128, 256, 512] {
            let mut worst: f64 = 0.0;
            let mut sq = 0.0;
            let seeds = 16;
            for seed in 0..seeds {
                let b = band(&Batch::new(2), &p, &BandSettings { samples: n, seed, ..Default::default() }).unwrap()[0];
                let e = (b.low_nm - reference.low_nm).abs().max((b.high_nm - reference.high_nm).abs()) / width;
                worst = worst.max(e);
                sq += e * e;
            }
            println!("  n {n:5}: rms {:.3} worst {:.3} of the width (16 seeds)", (sq / seeds as f64).sqrt(), worst);
        }
    }
}
