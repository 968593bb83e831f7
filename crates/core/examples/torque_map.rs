//! A torque map for firmware as the core provides it: the DKFZD4012 model tabulated over
//! preload and speed (f32 values, both directions, a geometric speed axis), its largest
//! interpolation error against the model as the tabulation states it, and the map then read
//! back the way firmware holds it, a grid and a borrowed slice of f32 (no allocation, no_std),
//! looked up off the grid's nodes and compared with the model.
//!
//! ```text
//! cargo run --release -p ballscrew-core --example torque_map
//! ```

use ballscrew_core::input::{rad_s_to_rpm, rpm_to_rad_s};
use ballscrew_core::realtime::map::{self, MapGrid, TorqueMap};
use ballscrew_core::{Model, OperatingPoint, ScrewSpec, SolverState};

fn main() -> Result<(), Box<dyn core::error::Error>> {
    let model = Model::new(&ScrewSpec::dkfzd4012())?;
    let omega0 = model.spec().friction.standstill_speed_rad_s;
    // 6 preloads from 500 N to 3000 N; 32 speeds from a tenth of the standstill speed to
    // 3000 rpm, geometrically spaced (the lubricated torque changes over decades of speed).
    let grid = MapGrid::geometric((500.0, 3000.0, 6), (omega0 / 10.0, rpm_to_rad_s(3000.0), 32), omega0);
    let tabulated = map::tabulate(&model, &grid, 0.0)?;
    println!(
        "grid: {} preloads from {} to {} N, {} speeds from {:.3} to {:.0} rpm (geometric), both directions",
        grid.preload_points,
        grid.preload_min_n,
        grid.preload_max_n(),
        grid.speed_points,
        rad_s_to_rpm(f64::from(grid.speed_min_rad_s)),
        rad_s_to_rpm(f64::from(grid.speed_max_rad_s()))
    );
    println!("values: {} f32 ({} bytes)", tabulated.values.len(), 4 * tabulated.values.len());
    println!(
        "largest interpolation error: {:.4} % at {:.0} N, {:.4} rpm ({} points checked)",
        100.0 * tabulated.max_relative_error,
        tabulated.worst_point.0,
        rad_s_to_rpm(tabulated.worst_point.1),
        tabulated.checked_points
    );

    // What firmware holds: the grid and the values in flash.
    let flashed: &[f32] = &tabulated.values;
    let firmware = TorqueMap::new(grid, flashed)?;
    let mut state = SolverState::new();
    for speed_rpm in [150.0, -150.0, 2.0] {
        let (preload_n, speed_rad_s) = (1750.0, rpm_to_rad_s(speed_rpm));
        let looked_up = firmware.torque_nm(preload_n as f32, speed_rad_s as f32);
        let op = OperatingPoint { speed_rad_s, preload_n, axial_load_n: 0.0 };
        let modelled = model.torque(&op, &mut state)?;
        println!("map at {preload_n} N, {speed_rpm} rpm: {looked_up:.6} N m (model {modelled:.6} N m)");
    }
    Ok(())
}
