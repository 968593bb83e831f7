//! No input panics: random specs and operating points (valid or not) give a value or an error.

use ballscrew_core::{Error, Model, OperatingPoint, ScrewSpec, SolverState};

/// A small deterministic generator (64-bit LCG), so the test is repeatable.
struct Lcg(u64);
impl Lcg {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

#[test]
fn random_screws_evaluate_or_fail_cleanly() {
    let mut g = Lcg(0x5eed);
    let mut ok = 0;
    for _ in 0..120 {
        let mut s = ScrewSpec::dkfzd4012();
        let geo = &mut s.geometry;
        geo.pitch_diameter_m = g.range(0.008, 0.12);
        geo.lead_m = g.range(0.002, 0.04);
        geo.ball_diameter_m = geo.pitch_diameter_m * g.range(0.05, 0.25);
        geo.conformity_screw = g.range(0.505, 0.58);
        geo.conformity_nut = g.range(0.505, 0.58);
        geo.contact_angle_rad = g.range(30.0, 60.0).to_radians();
        geo.circles_per_nut = 1 + (g.unit() * 5.0) as u32;
        geo.balls_per_circle = 5 + (g.unit() * 20.0) as u32;
        geo.nuts = 1 + (g.unit() * 2.0) as u32;
        s.friction.coefficient = g.range(0.002, 0.15);
        let op = OperatingPoint {
            speed_rad_s: g.range(-300.0, 300.0),
            preload_n: g.range(0.0, 5000.0),
            axial_load_n: g.range(-3000.0, 3000.0),
        };
        let model = match Model::new(&s) {
            Ok(m) => m,
            Err(Error::Input(e)) => {
                assert!(!e.field.is_empty());
                continue;
            }
            Err(e) => panic!("unexpected {e}"),
        };
        match model.torque(&op, &mut SolverState::new()) {
            Ok(t) => {
                assert!(t.is_finite());
                ok += 1;
            }
            Err(e) => assert!(!format!("{e}").is_empty()),
        }
    }
    assert!(ok > 60, "most random screws evaluate: {ok}");
}

#[test]
fn non_finite_operating_points_are_rejected_by_name() {
    let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
    let base = ScrewSpec::dkfzd4012().operating;
    for (op, field) in [
        (OperatingPoint { speed_rad_s: f64::NAN, ..base }, "speed_rad_s"),
        (OperatingPoint { preload_n: f64::INFINITY, ..base }, "preload_n"),
        (OperatingPoint { axial_load_n: f64::NEG_INFINITY, ..base }, "axial_load_n"),
    ] {
        match model.torque(&op, &mut SolverState::new()) {
            Err(Error::Input(e)) => assert_eq!(e.field, field),
            other => panic!("{field}: {other:?}"),
        }
    }
}
