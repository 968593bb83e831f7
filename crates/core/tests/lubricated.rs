//! The lubricated model (`lubrication = "ehl"`, the default; docs/model-notes.md item 22) over
//! the whole screw: the balance still closes with the rolling resistance in it, and the torque
//! follows speed, viscosity and oil temperature the way lubricated ball screws do. The contact
//! laws themselves (films, mixed friction, rolling resistance against SKF's bearing figure) are
//! tested beside their code in `crates/core/src/contact/ehl.rs`.

use ballscrew_core::ball::lubrication;
use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{Lubricant, Lubrication, Model, OperatingPoint, ScrewSpec, SolverState, Summary};

fn op(preload_n: f64, speed_rpm: f64, axial_load_n: f64) -> OperatingPoint {
    OperatingPoint { preload_n, speed_rad_s: rpm_to_rad_s(speed_rpm), axial_load_n }
}

fn summary(spec: &ScrewSpec, preload_n: f64, speed_rpm: f64) -> Summary {
    Model::new(spec).unwrap().summary(&op(preload_n, speed_rpm, 0.0), &mut SolverState::new()).unwrap()
}

fn torque(spec: &ScrewSpec, preload_n: f64, speed_rpm: f64) -> f64 {
    summary(spec, preload_n, speed_rpm).torque_nm
}

/// The default is lubricated, and the dry option is the paper's model.
#[test]
fn default_is_lubricated_and_depends_on_the_speed() {
    let spec = ScrewSpec::dkfzd4012();
    assert_eq!(spec.model.lubrication, Lubrication::Ehl);
    assert!(Model::new(&spec).unwrap().torque_depends_on_speed_magnitude());
    let mut dry = spec;
    dry.model.lubrication = Lubrication::Dry;
    // The return's resistance grows with the square of the speed (the centrifugal force in its
    // bends): with the ball train, the dry model's torque depends on the speed too.
    assert!(Model::new(&dry).unwrap().torque_depends_on_speed_magnitude());
    let (d1, d2) = (torque(&dry, 2000.0, 100.0), torque(&dry, 2000.0, 1000.0));
    assert!(d2 > d1, "{d1} vs {d2}");
    // The paper's model (the loads between balls set, here none) does not.
    dry.friction.ball_ball_load_n = Some(0.0);
    assert!(!Model::new(&dry).unwrap().torque_depends_on_speed_magnitude());
    let (d1, d2) = (torque(&dry, 2000.0, 100.0), torque(&dry, 2000.0, 1000.0));
    assert!((d1 - d2).abs() <= 1e-9 * d1, "{d1} vs {d2}");
    let (l1, l2) = (torque(&spec, 2000.0, 100.0), torque(&spec, 2000.0, 1000.0));
    assert!(l2 > 1.2 * l1, "{l1} vs {l2}");
    // A bad oil is named under either model, though the dry one leaves the oil out.
    let mut bad = spec;
    bad.lubricant.temperature_c = 500.0;
    let e = bad.validate().unwrap_err();
    assert_eq!(e.field, "lubricant.temperature_c");
    bad.model.lubrication = Lubrication::Dry;
    assert_eq!(bad.validate().unwrap_err().field, "lubricant.temperature_c");
}

/// docs/model-notes.md item 9 with the rolling resistance in the balance: the moment about the
/// screw axis of everything the balls exert on the screw equals F_a L / (2 pi) + D / omega
/// within 1e-6 relative, at light and heavy preloads, slow and fast, both directions, with an
/// axial load, a ball-ball load (0.5 N at the boundary friction) and seals.
#[test]
fn energy_route_equals_moment_route_with_the_lubricant() {
    let mut spec = ScrewSpec::dkfzd4012();
    let mut with_extras = spec;
    with_extras.friction.ball_ball_load_n = Some(0.5);
    with_extras.friction.seal_torque_per_nut_nm = 0.03;
    for s in [&mut spec, &mut with_extras] {
        let model = Model::new(s).unwrap();
        for &(fp, fa) in &[(500.0, 0.0), (2000.0, 700.0), (3000.0, -300.0)] {
            for rpm in [10.0, -300.0, 3000.0, -3000.0] {
                let ev = model.evaluate(&op(fp, rpm, fa), &mut SolverState::new()).unwrap();
                let (e, m) = (ev.summary.torque_energy_nm, ev.summary.torque_moment_nm);
                assert!((e - m).abs() <= 1e-6 * e.abs(), "{fp} N {fa} N {rpm} rpm: {e} vs {m}");
                // The shares add up to the dissipation torque, and the rolling resistance has one.
                let sm = &ev.summary;
                let sum = sm.creep_torque_nm
                    + sm.rolling_resistance_torque_nm
                    + sm.hysteresis_torque_nm
                    + sm.ball_ball_torque_nm
                    + sm.return_torque_nm;
                assert!((sum - sm.dissipation_torque_nm).abs() <= 1e-12 * sm.dissipation_torque_nm.abs());
                assert!(sm.rolling_resistance_torque_nm * rpm.signum() > 0.0);
                assert!(sm.hysteresis_torque_nm * rpm.signum() > 0.0);
                // The lean form (torque alone) gives the report form's torque.
                let lean = model.torque(&op(fp, rpm, fa), &mut SolverState::new()).unwrap();
                assert!((lean - ev.summary.torque_nm).abs() <= 1e-9 * lean.abs(), "{lean} vs {}", ev.summary.torque_nm);
            }
        }
    }
}

/// Each raceway contact reports its film, film parameter, friction coefficient and rolling
/// resistance; the friction coefficient lies between the full-film and the boundary value and
/// falls as the film grows with speed.
#[test]
fn contacts_report_their_film_and_friction() {
    let spec = ScrewSpec::dkfzd4012();
    let model = Model::new(&spec).unwrap();
    let l = spec.lubricant;
    let mut last_mu = f64::INFINITY;
    let mut last_film = 0.0;
    for rpm in [10.0, 100.0, 1000.0, 3000.0] {
        let ev = model.evaluate(&op(2000.0, rpm, 0.0), &mut SolverState::new()).unwrap();
        let c = &ev.balls[0][0].contacts[1];
        assert!(c.film_central_m > last_film && c.film_minimum_m < c.film_central_m, "{rpm}: {c:?}");
        assert!(c.friction_coefficient < last_mu, "{rpm}: {}", c.friction_coefficient);
        assert!(c.friction_coefficient > l.full_film_traction && c.friction_coefficient < l.boundary_friction);
        assert!(c.lambda > 0.0 && c.rolling_resistance_ehl_n > 0.0 && c.rolling_resistance_hysteresis_n > 0.0);
        let parts = c.creep_torque_share_nm + c.rolling_torque_share_nm + c.hysteresis_torque_share_nm;
        assert!((parts - c.torque_share_nm).abs() <= 1e-12 * c.torque_share_nm.abs().max(1e-12));
        last_mu = c.friction_coefficient;
        last_film = c.film_central_m;
    }
}

/// The entrainment speed of the films (the rolling ball's, `lubrication::rolling_entrainment_m`)
/// is the solved ball's rolling speed within 2 % (the solved ball slips a little, its axis is
/// tilted and the helix's lead moves the contacts).
#[test]
fn film_speed_is_the_solved_balls_rolling_speed() {
    let spec = ScrewSpec::dkfzd4012();
    let model = Model::new(&spec).unwrap();
    let rpm = 1000.0;
    let ev = model.evaluate(&op(2000.0, rpm, 0.0), &mut SolverState::new()).unwrap();
    let u = lubrication::rolling_entrainment_m(&model.ball_setup_for(10.0, 1.0)) * rpm_to_rad_s(rpm);
    for c in &ev.balls[0][0].contacts[..2] {
        assert!((c.rolling_speed_m_s / u - 1.0).abs() < 0.02, "{} vs {u}", c.rolling_speed_m_s);
    }
}

/// Above the mixed-friction minimum the torque rises with speed, and between 300 and 3000 rpm it
/// grows as a power of the speed between 0.3 and 0.8: where published loss laws of lubricated
/// rolling elements put it (Palmgren's viscous moment M0 ~ (nu n)^(2/3), Harris & Kotzalas,
/// *Rolling Bearing Analysis*, 5th ed., ch. on friction; SKF's rolling frictional moment
/// M_rr ~ (nu n)^0.6, SKF catalogue "The SKF model for calculating the frictional moment").
#[test]
fn torque_rises_with_speed_as_a_power_law_of_lubricated_rolling() {
    let spec = ScrewSpec::dkfzd4012();
    let model = Model::new(&spec).unwrap();
    for fp in [500.0, 1000.0, 2000.0, 3000.0] {
        let mut state = SolverState::new();
        let t: Vec<f64> =
            [300.0, 1000.0, 3000.0].iter().map(|&rpm| model.torque(&op(fp, rpm, 0.0), &mut state).unwrap()).collect();
        assert!(t[0] < t[1] && t[1] < t[2], "{fp} N: {t:?}");
        let exponent = (t[2] / t[0]).ln() / 10f64.ln();
        assert!((0.3..=0.8).contains(&exponent), "{fp} N: exponent {exponent}");
    }
}

/// A thicker oil gives more torque at speed, a warmer oil less (Walther's law thins it).
#[test]
fn torque_rises_with_viscosity_and_falls_with_oil_temperature() {
    let base = ScrewSpec::dkfzd4012();
    let with_oil = |lubricant: Lubricant| {
        let mut s = base;
        s.lubricant = lubricant;
        torque(&s, 2000.0, 1000.0)
    };
    let by_grade: Vec<f64> = [32.0, 68.0, 220.0].iter().map(|&vg| with_oil(Lubricant::iso_vg(vg))).collect();
    assert!(by_grade[0] < by_grade[1] && by_grade[1] < by_grade[2], "{by_grade:?}");
    let by_temperature: Vec<f64> =
        [20.0, 40.0, 80.0].iter().map(|&t| with_oil(Lubricant::default().at_temperature(t))).collect();
    assert!(by_temperature[0] > by_temperature[1] && by_temperature[1] > by_temperature[2], "{by_temperature:?}");
}

/// The seals add their torque per nut against the motion, in every route, as their own share.
#[test]
fn seals_add_their_torque_per_nut() {
    let base = ScrewSpec::dkfzd4012();
    let mut sealed = base;
    sealed.friction.seal_torque_per_nut_nm = 0.04;
    for rpm in [500.0, -500.0] {
        let (a, b) = (summary(&base, 2000.0, rpm), summary(&sealed, 2000.0, rpm));
        let expected = 2.0 * 0.04 * rpm.signum();
        assert!((b.seal_torque_nm - expected).abs() < 1e-15);
        assert!((b.torque_nm - a.torque_nm - expected).abs() < 1e-12, "{} vs {}", b.torque_nm, a.torque_nm);
        assert!((b.torque_moment_nm - a.torque_moment_nm - expected).abs() < 1e-9);
    }
    // At standstill there is no seal drag (the standstill factor).
    assert_eq!(summary(&sealed, 2000.0, 0.0).seal_torque_nm, 0.0);
}

/// Through standstill the lubricated torque is finite, turns with the rotation, is zero at rest
/// and continuous: between speeds 1e-3 rpm apart within 1 rpm of standstill it changes by no
/// more than the standstill factor's steepest slope 2 / omega0 times the step times the largest
/// torque there, plus 1e-3 of it for the film's own change over the step.
#[test]
fn lubricated_torque_passes_standstill_continuously() {
    let spec = ScrewSpec::dkfzd4012();
    let model = Model::new(&spec).unwrap();
    let omega0_rpm = spec.friction.standstill_speed_rad_s * 60.0 / (2.0 * core::f64::consts::PI);
    let mut state = SolverState::new();
    let speeds: Vec<f64> = (-1000..=1000).map(|k| f64::from(k) * 1e-3).collect();
    let torques: Vec<f64> =
        speeds.iter().map(|&rpm| model.torque(&op(2000.0, rpm, 0.0), &mut state).unwrap()).collect();
    let largest = torques.iter().fold(0.0_f64, |m, t| m.max(t.abs()));
    assert!(largest > 0.1, "{largest}");
    for (i, (&rpm, &t)) in speeds.iter().zip(&torques).enumerate() {
        assert!(t.is_finite() && t * rpm >= 0.0, "{rpm} rpm: {t}");
        if rpm == 0.0 {
            assert_eq!(t, 0.0);
        }
        if i > 0 {
            let bound = 2.0 / omega0_rpm * 1e-3 * largest + 1e-3 * largest;
            assert!((t - torques[i - 1]).abs() <= bound, "jump at {rpm} rpm: {} -> {t}", torques[i - 1]);
        }
    }
}
