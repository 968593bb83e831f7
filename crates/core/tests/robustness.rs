//! No input panics: random specs and operating points (valid or not) give a value or an error.

use ballscrew_core::input::{
    BALL_DIAMETER_RANGE_M, CONFORMITY_RANGE, LEAD_RANGE_M, MAX_BALL_BALL_LOAD_N, MAX_STANDSTILL_SPEED_RAD_S,
    PITCH_DIAMETER_RANGE_M, YOUNGS_MODULUS_RANGE_PA,
};
use ballscrew_core::{Error, Model, OperatingPoint, Preload, ScrewSpec, SolverState};

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
        // At least 0.5 mm (the smallest valid ball) at the smallest pitch diameter drawn.
        geo.ball_diameter_m = geo.pitch_diameter_m * g.range(0.0625, 0.25);
        geo.conformity_screw = g.range(0.505, 0.58);
        geo.conformity_nut = g.range(0.505, 0.58);
        geo.contact_angle_rad = g.range(30.0, 60.0).to_radians();
        geo.circles_per_nut = 1 + (g.unit() * 5.0) as u32;
        geo.balls_per_circle = 5 + (g.unit() * 20.0) as u32;
        // Every arrangement: a double nut, or one nut with oversize balls, a lead offset (its
        // circles made even) or no preload.
        geo.preload = Preload::ALL[((g.unit() * 4.0) as usize).min(3)];
        geo.nuts = geo.preload.nuts();
        if geo.preload == Preload::OffsetLead {
            geo.circles_per_nut = 2 * geo.circles_per_nut.div_ceil(2);
        }
        s.friction.coefficient = g.range(0.002, 0.15);
        let op = OperatingPoint {
            speed_rad_s: g.range(-300.0, 300.0),
            preload_n: if s.geometry.preload == Preload::None { 0.0 } else { g.range(0.0, 5000.0) },
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

/// Screws at the ends of the spec's valid ranges are set up and evaluate to a finite, positive
/// torque at preloads suited to their size: the ranges hold no value the model cannot handle.
#[test]
fn screws_at_the_ends_of_the_valid_ranges_evaluate() {
    // A miniature screw: smallest lead and ball, 4 mm pitch diameter.
    let mut mini = ScrewSpec::dkfzd4012();
    mini.geometry.pitch_diameter_m = 4.0e-3;
    mini.geometry.lead_m = LEAD_RANGE_M.0;
    mini.geometry.ball_diameter_m = BALL_DIAMETER_RANGE_M.0;
    mini.geometry.circles_per_nut = 3;
    mini.geometry.balls_per_circle = 20;
    // A heavy screw: largest pitch diameter, lead and ball.
    let mut heavy = ScrewSpec::dkfzd4012();
    heavy.geometry.pitch_diameter_m = PITCH_DIAMETER_RANGE_M.1;
    heavy.geometry.lead_m = LEAD_RANGE_M.1;
    heavy.geometry.ball_diameter_m = BALL_DIAMETER_RANGE_M.1;
    heavy.geometry.balls_per_circle = 15;
    let mut cases = Vec::new();
    for e in [YOUNGS_MODULUS_RANGE_PA.0, YOUNGS_MODULUS_RANGE_PA.1] {
        for f in [CONFORMITY_RANGE.0, CONFORMITY_RANGE.1] {
            let mut s = mini;
            s.material.youngs_modulus_pa = e;
            (s.geometry.conformity_screw, s.geometry.conformity_nut) = (f, f);
            cases.push((s, [20.0, 2000.0]));
        }
        let mut s = heavy;
        s.material.youngs_modulus_pa = e;
        cases.push((s, [20.0e3, 200.0e3]));
    }
    // The tightest grooves on DKFZD4012 converge up to 1 MN (closer to 0.5 they do not; their
    // conformal contacts keep the peak pressure within the static load capacity).
    let mut tight = ScrewSpec::dkfzd4012();
    (tight.geometry.conformity_screw, tight.geometry.conformity_nut) = (CONFORMITY_RANGE.0, CONFORMITY_RANGE.0);
    cases.push((tight, [2000.0, 1.0e6]));
    let mut steep = mini;
    steep.geometry.lead_m = LEAD_RANGE_M.1;
    cases.push((steep, [20.0, 200.0]));
    let mut jammed = heavy;
    jammed.friction.ball_ball_load_n = Some(MAX_BALL_BALL_LOAD_N);
    // Dry, at f = 0.03 between the balls: at the lubricant's boundary friction (0.15) a ball
    // this light against 1000 N at each neighbour has no steady state (its raceways cannot
    // carry the ball-ball friction's moment), and the model says so.
    jammed.model.lubrication = ballscrew_core::Lubrication::Dry;
    jammed.friction.standstill_speed_rad_s = MAX_STANDSTILL_SPEED_RAD_S;
    // The softest material keeps 200 kN within the static load capacity of these balls.
    jammed.material.youngs_modulus_pa = YOUNGS_MODULUS_RANGE_PA.0;
    cases.push((jammed, [200.0e3, 200.0e3]));
    // The lower preload of every case evaluates; the higher one evaluates or, when the most
    // loaded ball's Hertz peak pressure exceeds `MAX_PEAK_PRESSURE_PA`, is refused as beyond the
    // screw's static load capacity.
    for (spec, preloads) in cases {
        let model = Model::new(&spec).unwrap_or_else(|e| panic!("{e}: {spec:?}"));
        for (i, preload_n) in preloads.into_iter().enumerate() {
            let op = OperatingPoint { preload_n, ..spec.operating };
            match model.torque(&op, &mut SolverState::new()) {
                Ok(t) => assert!(t.is_finite() && t > 0.0, "{t} at {preload_n} N: {spec:?}"),
                Err(e @ Error::Input(_)) if i == 1 && format!("{e}").contains("static load capacity") => {}
                Err(e) => panic!("{e}: {preload_n} N, {spec:?}"),
            }
        }
    }
}

/// Conditions out of their ranges (a NaN or infinite temperature, position or running time, a
/// negative time) are an input error naming the field, from the model and the evaluator alike,
/// with every extension term on; the ends of the ranges evaluate. (A NaN temperature gave NaN
/// through the thermal term, an infinite one zeroed that term.)
#[test]
fn conditions_out_of_range_are_errors_naming_the_field() {
    use ballscrew_core::input::extensions::{
        CONDITION_TEMPERATURE_RANGE_C, Conditions, Extensions, POSITION_RANGE_M, RacewayWaviness, TIME_RANGE_H,
        ThermalViscosity, ViscousDrag,
    };
    use ballscrew_core::{EvalState, Evaluator};
    let mut spec = ScrewSpec::dkfzd4012();
    let drag = ViscousDrag { torque_nm: 0.01, exponent: 0.7, reference_speed_rad_s: 100.0 };
    spec.extensions = Extensions {
        thermal_viscosity: Some(ThermalViscosity {
            drag,
            viscosity_coefficient_per_k: 0.03,
            reference_temperature_c: 40.0,
        }),
        raceway_waviness: Some(RacewayWaviness { harmonic: 2, amplitude_nm: 0.005, phase_rad: 0.5 }),
        ..Extensions::NONE
    };
    let model = Model::new(&spec).unwrap();
    let ev = Evaluator::<f64>::new(&model).unwrap();
    let op = spec.operating;
    let base = Conditions::default();
    let bad = [
        ("temperature_c", Conditions { temperature_c: Some(f64::NAN), ..base }),
        ("temperature_c", Conditions { temperature_c: Some(f64::INFINITY), ..base }),
        ("temperature_c", Conditions { temperature_c: Some(CONDITION_TEMPERATURE_RANGE_C.1 + 1.0), ..base }),
        ("position_m", Conditions { position_m: f64::INFINITY, ..base }),
        ("position_m", Conditions { position_m: POSITION_RANGE_M.0 * 1.5, ..base }),
        ("time_h", Conditions { time_h: -1.0, ..base }),
        ("time_h", Conditions { time_h: f64::NAN, ..base }),
    ];
    for (field, cond) in bad {
        let m = model.torque_at(&op, &cond, &mut SolverState::new());
        let e = ev.torque_at_nm(&op, &cond, &mut EvalState::new());
        for r in [m, e] {
            assert!(matches!(&r, Err(Error::Input(i)) if i.field == field), "{cond:?}: {r:?}");
        }
    }
    let ends = Conditions {
        position_m: POSITION_RANGE_M.1,
        temperature_c: Some(CONDITION_TEMPERATURE_RANGE_C.0),
        time_h: TIME_RANGE_H.1,
    };
    let m = model.torque_at(&op, &ends, &mut SolverState::new()).unwrap();
    let e = ev.torque_at_nm(&op, &ends, &mut EvalState::new()).unwrap();
    assert!(m.is_finite() && (m - e).abs() <= 1e-8 * m.abs(), "{m} {e}");
}
