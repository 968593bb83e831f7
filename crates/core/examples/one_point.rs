//! The drag torque of the DKFZD4012 ball screw (Table 1 of Xu et al. 2015, the core's built-in
//! spec) at one preload and speed, from the model: the drag torque, the two routes it is
//! computed by (energy and moment, which agree), its shares and the catalog estimate.
//!
//! ```text
//! cargo run --release -p ballscrew-core --example one_point
//! ```

use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{Model, OperatingPoint, ScrewSpec, SolverState};

fn main() -> Result<(), ballscrew_core::Error> {
    let model = Model::new(&ScrewSpec::dkfzd4012())?;
    let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(100.0), preload_n: 2000.0, axial_load_n: 0.0 };
    let s = model.summary(&op, &mut SolverState::new())?;
    println!("DKFZD4012 at {op}");
    println!("drag torque: {:.6} N m", s.drag_torque_nm());
    println!("energy route: {:.6} N m", s.torque_energy_nm);
    println!("moment route: {:.6} N m", s.torque_moment_nm);
    println!("creep and sliding: {:.6} N m", s.creep_torque_nm);
    println!("rolling resistance: {:.6} N m", s.rolling_resistance_torque_nm);
    println!("hysteresis: {:.6} N m", s.hysteresis_torque_nm);
    println!("ball-ball contacts: {:.6} N m", s.ball_ball_torque_nm);
    println!("return path: {:.6} N m", s.return_torque_nm);
    println!("catalog estimate: {:.6} N m", s.catalog_nm);
    Ok(())
}
