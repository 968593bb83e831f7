//! A preload sweep of the DKFZD4012 ball screw at 100 rpm: the model's drag torque from 500 N
//! to 3000 N, each point warm-started from the one before it (a stateful loop, as a simulation
//! steps; the command line's `sweep` solves each point cold, its canonical state, which agrees
//! with this loop to the solver's tolerance here), with the catalog estimate beside it.
//!
//! ```text
//! cargo run --release -p ballscrew-core --example sweep
//! ```

use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{Model, OperatingPoint, ScrewSpec, SolverState};

fn main() -> Result<(), ballscrew_core::Error> {
    let model = Model::new(&ScrewSpec::dkfzd4012())?;
    let mut state = SolverState::new();
    println!("DKFZD4012, speed 100 rpm, axial load 0 N");
    for step in 1..=6 {
        let preload_n = 500.0 * f64::from(step);
        let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(100.0), preload_n, axial_load_n: 0.0 };
        let s = model.summary(&op, &mut state)?;
        println!("preload {preload_n} N: drag {:.6} N m, catalog {:.6} N m", s.drag_torque_nm(), s.catalog_nm);
    }
    Ok(())
}
