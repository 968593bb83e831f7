//! A reversal transient: the DKFZD4012 at 2000 N preload oscillating as a circular
//! interpolation's axis does at its quadrant change (amplitude 0.01 rad, peak 10 rpm), stepped
//! through the reversal by the state model of `realtime::reversal` (Dahl's law per circle of
//! balls, the evaluator's steady torque as its bound): the friction does not flip at once but
//! re-forms over a small rotation of the screw.
//!
//! ```text
//! cargo run --release -p ballscrew-core --example reversal
//! ```

use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::realtime::reversal::{Reformation, SineMotion};
use ballscrew_core::{Evaluator, Model, ReversalModel, ScrewSpec};

fn main() -> Result<(), ballscrew_core::Error> {
    let model = Model::new(&ScrewSpec::dkfzd4012())?;
    let evaluator = Evaluator::<f64>::new(&model)?;
    let reversal = ReversalModel::new(&evaluator, 2000.0, 0.0)?;
    let peak = rpm_to_rad_s(10.0);
    let motion = SineMotion::new(0.01, peak, 1e-5)?;
    // Running steadily forward at the peak speed, then through the turning point and back.
    let before_nm = reversal.steady(peak)?.friction_nm();
    let after_nm = reversal.steady(-peak)?.friction_nm();
    let mut reformation = Reformation::new(after_nm, 0.9)?;
    let mut state = reversal.steady(peak)?;
    let n = motion.steps_per_period();
    for k in 1..=n / 2 {
        let torque_nm = reversal.step(motion.rotation_rad(k), motion.dt_s(), &mut state)?;
        if k >= n / 4 {
            let from_turning_point_rad = motion.amplitude_rad() - motion.angle_rad(k);
            reformation.record(from_turning_point_rad, torque_nm - reversal.axial_term_nm());
        }
    }
    let lead_um = model.spec().geometry.lead_m * 1e6;
    let travel_um = |angle_rad: f64| angle_rad / core::f64::consts::TAU * lead_um;
    let zero = reformation.zero_crossing_rad().unwrap_or(f64::NAN);
    let reformed = reformation.reformed_rad().unwrap_or(f64::NAN);
    println!("DKFZD4012, preload 2000 N, {} steps of {:.3e} s through the reversal", n / 2, motion.dt_s());
    println!("stiffness from rest: {:.1} N m/rad", reversal.stiffness_nm_per_rad());
    println!("steady friction before: {before_nm:.6} N m");
    println!("steady friction after: {after_nm:.6} N m");
    println!("zero crossing after the turning point: {zero:.4e} rad ({:.4} um of travel)", travel_um(zero));
    println!("90 % re-formed after the turning point: {reformed:.4e} rad ({:.4} um of travel)", travel_um(reformed));
    println!("friction at the end: {:.6} N m", state.friction_nm());
    Ok(())
}
