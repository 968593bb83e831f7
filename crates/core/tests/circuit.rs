//! The balance of circuits of several loaded turns (`screw/circuit.rs`): one orbit rate for
//! every ball of a circuit, the pushes and the chain force from it.

use ballscrew_core::input::LoadDistribution;
use ballscrew_core::input::circulation::Return;
use ballscrew_core::{Error, Evaluator, Model, OperatingPoint, ScrewSpec, SolverState};

fn rpm(r: f64) -> f64 {
    r * core::f64::consts::PI / 30.0
}

fn point(speed_rpm: f64, preload_n: f64) -> OperatingPoint {
    OperatingPoint { speed_rad_s: rpm(speed_rpm), preload_n, axial_load_n: 0.0 }
}

/// DKFZD4012 with an external return: each nut's four circles in one circuit.
fn external(turns: u32) -> ScrewSpec {
    let mut spec = ScrewSpec::dkfzd4012();
    spec.circulation.kind = Return::External;
    spec.circulation.turns_per_circuit = Some(turns);
    spec
}

/// An ideal circuit (equal loads on every circle, no resistance in the return): the balls orbit
/// alike with nothing between them, so no contact between balls carries load and the torque is
/// that of the same screw without the train, to 1e-9.
#[test]
fn an_ideal_circuit_carries_no_load_between_balls() {
    let mut ideal = external(4);
    ideal.model.load_distribution = LoadDistribution::Uniform;
    ideal.circulation.return_friction = Some(0.0);
    let mut without = ideal;
    without.friction.ball_ball_load_n = Some(0.0);
    for (speed, preload) in [(10.0, 500.0), (100.0, 2000.0), (1000.0, 3000.0)] {
        let op = point(speed, preload);
        let a = Model::new(&ideal).unwrap().summary(&op, &mut SolverState::new()).unwrap();
        let b = Model::new(&without).unwrap().summary(&op, &mut SolverState::new()).unwrap();
        assert!(
            (a.torque_nm - b.torque_nm).abs() <= 1e-9 * b.torque_nm,
            "{speed} rpm: {} {}",
            a.torque_nm,
            b.torque_nm
        );
        assert_eq!(a.ball_ball_torque_nm, 0.0);
        let e = Model::new(&ideal).unwrap().evaluate(&op, &mut SolverState::new()).unwrap();
        for nut in 0..e.nuts {
            for ball in &e.balls[nut][..e.circles] {
                assert_eq!(ball.contacts[2].normal_load_n, 0.0);
            }
        }
    }
}

/// The circles of one circuit carry different loads (the geometric distribution), so their
/// free orbit rates differ: in the balanced circuit every ball orbits at one rate (to 1e-10),
/// every load between balls is >= 0, and the ball-ball share grows with the preload (the
/// mismatch of the free orbit rates grows with it).
#[test]
fn one_orbit_rate_per_circuit_and_loads_that_grow_with_the_preload() {
    let model = Model::new(&external(4)).unwrap();
    let mut last = 0.0;
    for preload in [500.0, 1000.0, 2000.0, 3000.0] {
        let e = model.evaluate(&point(100.0, preload), &mut SolverState::new()).unwrap();
        for nut in 0..e.nuts {
            let balls = &e.balls[nut][..e.circles];
            let orbit = balls[0].orbit_ratio;
            for b in balls {
                assert!(
                    (b.orbit_ratio - orbit).abs() <= 1e-10 * orbit,
                    "{preload} N nut {nut}: {} {orbit}",
                    b.orbit_ratio
                );
                assert!(b.contacts[2].normal_load_n >= 0.0);
            }
        }
        let share = e.summary.ball_ball_torque_nm;
        assert!(share > last, "{preload} N: ball-ball share {share} after {last}");
        last = share;
    }
}

/// The energy route (dissipation) and the moment route (moments on the screw) agree. Within a
/// circle both balls of a contact are in one state, as in a circuit of one turn; where two
/// circles meet, each ball sees its neighbour in its own state, which leaves a difference of
/// order 1e-6 of the torque (measured up to 6e-6 on DKFZD4012 at 10-1000 rpm).
#[test]
fn energy_route_and_moment_route_agree() {
    let model = Model::new(&external(4)).unwrap();
    for (speed, preload) in [(10.0, 500.0), (100.0, 2000.0), (100.0, 3000.0), (-100.0, 2000.0), (1000.0, 2000.0)] {
        let s = model.summary(&point(speed, preload), &mut SolverState::new()).unwrap();
        let d = (s.torque_energy_nm - s.torque_moment_nm).abs() / s.torque_energy_nm.abs();
        assert!(d < 2e-5, "{speed} rpm {preload} N: {d:e}");
    }
}

/// The drag reverses with the rotation and passes through zero at standstill. Its magnitude is
/// not exactly the same both ways, unlike a circuit of one turn (antisymmetric to 1e-14): the
/// balls travel the circuit the other way round, so the heaviest circle, first behind the gap
/// one way, is last before the return the other, and the chain differs (measured 2.5e-6 of the
/// torque at 10 rpm and 9.8e-6 at 100 rpm on DKFZD4012 at 2000 N).
#[test]
fn the_drag_reverses_with_the_rotation() {
    let model = Model::new(&external(4)).unwrap();
    for speed in [10.0, 100.0] {
        let f = model.torque(&point(speed, 2000.0), &mut SolverState::new()).unwrap();
        let b = model.torque(&point(-speed, 2000.0), &mut SolverState::new()).unwrap();
        assert!(f > 0.0 && b < 0.0);
        assert!((f + b).abs() <= 5e-5 * f, "{speed} rpm: {f} {b}");
    }
    let still = model.torque(&point(0.0, 2000.0), &mut SolverState::new()).unwrap();
    assert_eq!(still, 0.0);
    let slow = model.torque(&point(1e-4, 2000.0), &mut SolverState::new()).unwrap();
    assert!(slow > 0.0 && slow < 0.01 * model.torque(&point(100.0, 2000.0), &mut SolverState::new()).unwrap());
}

/// A warm solve (from the last point's circuit) lands on the cold solve's state.
#[test]
fn warm_and_cold_agree() {
    let model = Model::new(&external(4)).unwrap();
    let mut warm = SolverState::new();
    for speed in [10.0, 20.0, 50.0, 100.0, 200.0] {
        let w = model.torque(&point(speed, 2000.0), &mut warm).unwrap();
        let c = model.torque(&point(speed, 2000.0), &mut SolverState::new()).unwrap();
        assert!((w - c).abs() <= 1e-9 * c, "{speed} rpm: warm {w}, cold {c}");
    }
}

/// The ball-ball contact's friction is the lubricant's boundary value: the ball-ball share
/// scales with it (the loads between balls move little).
#[test]
fn the_ball_ball_friction_is_the_boundary_value() {
    let op = point(100.0, 2000.0);
    let share = |mu: f64| {
        let mut spec = external(4);
        spec.lubricant.boundary_friction = mu;
        Model::new(&spec).unwrap().summary(&op, &mut SolverState::new()).unwrap().ball_ball_torque_nm
    };
    let (a, b) = (share(0.10), share(0.15));
    assert!(b > a * 1.2 && b < a * 1.8, "{a} {b}");
}

/// The control-loop evaluator does not solve a circuit of several turns: it says so, naming
/// the key, and the model does.
#[test]
fn the_evaluator_leaves_circuits_to_the_model() {
    let model = Model::new(&external(4)).unwrap();
    match Evaluator::<f64>::new(&model) {
        Err(Error::Unsupported { field, .. }) => assert_eq!(field, "circulation.turns_per_circuit"),
        other => panic!("{other:?}"),
    }
    let mut two = external(2);
    two.friction.ball_ball_load_n = Some(0.0);
    assert!(Evaluator::<f64>::new(&Model::new(&two).unwrap()).is_ok(), "an explicit load bypasses the train");
}

/// Oversize-ball nuts (four-point balls) and FASTSIM contacts: refused, naming the key.
#[test]
fn circuits_the_model_does_not_solve_are_refused() {
    let mut spec = ballscrew_core::ScrewSpec::dkfzd4012();
    spec.model.contact_theory = ballscrew_core::input::ContactTheory::Fastsim;
    spec.circulation.kind = Return::External;
    match Model::new(&spec) {
        Err(Error::Unsupported { field, .. }) => assert_eq!(field, "circulation.turns_per_circuit"),
        other => panic!("{other:?}"),
    }
}

/// Where no steady state of the train is found (DKFZD4012 with one circuit per nut at 3000 rpm:
/// the gap of the train switches back and forth between two places, neither of which
/// balances; docs/model-notes.md, "The ball train"), the answer is an error naming the circuit,
/// never a number.
#[test]
fn a_train_without_a_steady_state_is_an_error() {
    let model = Model::new(&external(4)).unwrap();
    match model.torque(&point(3000.0, 2000.0), &mut SolverState::new()) {
        Err(e @ Error::NoSteadyTrain { circles: (0, 3), .. }) => {
            let text = e.to_string();
            assert!(text.starts_with("the ball train of the circuit of nut "), "{text}");
            assert!(text.contains("circles 1-4"), "{text}");
        }
        other => panic!("{other:?}"),
    }
}
