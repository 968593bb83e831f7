//! A load ramp at the ends of a circuit's loaded zone (`circulation.load_ramp_balls`): the
//! ramp's balls carry less than their circle's full load, so their free orbit rates differ from
//! the full balls', and the train carries the mismatch (`screw/model.rs`, `screw/circuit.rs`).

use ballscrew_core::input::Preload;
use ballscrew_core::input::circulation::Return;
use ballscrew_core::{Error, Evaluation, Evaluator, Model, OperatingPoint, ScrewSpec, SolverState};

fn point(speed_rpm: f64, preload_n: f64) -> OperatingPoint {
    OperatingPoint { speed_rad_s: speed_rpm * core::f64::consts::PI / 30.0, preload_n, axial_load_n: 0.0 }
}

/// DKFZD4012 (an internal return: a circuit of one turn per circle) with a ramp of `balls`.
fn ramp(balls: u32) -> ScrewSpec {
    let mut spec = ScrewSpec::dkfzd4012();
    spec.circulation.load_ramp_balls = balls;
    spec
}

fn evaluate(spec: &ScrewSpec, op: &OperatingPoint) -> Result<Evaluation, Error> {
    Model::new(spec)?.evaluate(op, &mut SolverState::new())
}

/// The largest chain force at a circle's ends (N), after checking what every ramp must keep:
/// each nut's circles carry its load between their full balls and their ramps' (a ramp of m
/// balls carrying m / 2 full balls' load), and no load between balls is negative.
fn largest_chain_n(e: &Evaluation, nut_load_n: f64, z: u32) -> f64 {
    let mut chain: f64 = 0.0;
    for nut in 0..e.nuts {
        let balls = &e.balls[nut][..e.circles];
        let carried: f64 =
            balls.iter().map(|b| b.axial_load_n * (f64::from(b.balls) + 0.5 * f64::from(b.ramp_balls))).sum();
        assert!((carried - nut_load_n).abs() <= 1e-9 * nut_load_n, "nut {nut}: {carried}");
        for b in balls {
            assert_eq!(b.balls + b.ramp_balls, z);
            assert!(b.contacts[2].normal_load_n >= 0.0 && b.chain_in_n >= 0.0 && b.chain_out_n >= 0.0);
            chain = chain.max(b.chain_in_n).max(b.chain_out_n);
        }
    }
    chain
}

/// A ramp's balls carry less than the full balls, so their free orbit rates differ and the
/// train carries the mismatch: on DKFZD4012 at 10 rpm and 2000 N the largest chain force at a
/// circle's ends grows with the ramp (0.0005 N without one, from the return alone; 0.107,
/// 0.158, 0.209 and 0.255 N with 1 to 4 balls), and with it the ball-ball share and the drag
/// (0.2315 to 0.2575 N m); the full balls carry more (43.7 to 55.4 N on the first circle);
/// each nut's circles still carry its load, no load between balls is negative, the energy
/// route equals the moment route to the 2e-5 of a circuit whose segments differ (the model
/// notes, "The ball train"), and a ramp of none is the spec without one, to the bit.
#[test]
fn the_train_carries_a_ramps_mismatch_and_it_grows_with_the_ramp() {
    let z = ScrewSpec::dkfzd4012().geometry.balls_per_circle;
    let op = point(10.0, 2000.0);
    let mut last: Option<(f64, f64, f64)> = None;
    let mut chains = [0.0; 5];
    for m in 0..=4 {
        let e = evaluate(&ramp(m), &op).unwrap();
        let chain = largest_chain_n(&e, 2000.0, z);
        let s = e.summary;
        let d = (s.torque_energy_nm - s.torque_moment_nm).abs() / s.torque_energy_nm;
        assert!(d < if m == 0 { 1e-9 } else { 2e-5 }, "{m} balls: routes {d:e}");
        let now = (chain, s.ball_ball_torque_nm, s.torque_nm);
        if let Some(before) = last {
            assert!(now.0 > before.0 && now.1 > before.1 && now.2 > before.2, "{m} balls: {now:?} after {before:?}");
        }
        last = Some(now);
        chains[m as usize] = chain;
        // The full balls: the circle's balls less its two ramps' (a circuit of one turn).
        assert_eq!(e.balls[0][0].balls, z - 2 * m);
    }
    let near = |x: f64, want: f64| (x - want).abs() <= 0.005 * want;
    for (got, want) in chains.iter().zip([0.0005, 0.107, 0.158, 0.209, 0.255]) {
        assert!((got - want).abs() < 0.1 * want.min(0.005), "{chains:?}");
    }
    let (none, four) = (evaluate(&ramp(0), &op).unwrap(), evaluate(&ramp(4), &op).unwrap());
    assert!(near(none.balls[0][0].axial_load_n, 43.72) && near(four.balls[0][0].axial_load_n, 55.38));
    assert!((none.summary.torque_nm - 0.2315).abs() < 5e-5 && (four.summary.torque_nm - 0.2575).abs() < 5e-5);
    let plain = Model::new(&ScrewSpec::dkfzd4012()).unwrap().torque(&op, &mut SolverState::new()).unwrap();
    assert_eq!(none.summary.torque_nm.to_bits(), plain.to_bits());
}

/// The drag reverses with the rotation (the ramps at both ends mirror each other): the moment
/// route to rounding, the energy route to the 2e-5 of its count of each ball's contacts; and
/// it fades through standstill to none at rest, where the ramp's balls are solved alone (every
/// friction force is zero whatever the loads between balls).
#[test]
fn a_ramps_drag_reverses_with_the_rotation_and_fades_at_standstill() {
    let model = Model::new(&ramp(3)).unwrap();
    let summary = |rpm: f64| model.summary(&point(rpm, 2000.0), &mut SolverState::new()).unwrap();
    for rpm in [10.0, 0.01] {
        let (f, b) = (summary(rpm), summary(-rpm));
        assert!((f.torque_moment_nm + b.torque_moment_nm).abs() <= 1e-9 * f.torque_moment_nm, "{rpm}: {f:?} {b:?}");
        assert!((f.torque_energy_nm + b.torque_energy_nm).abs() <= 3e-5 * f.torque_energy_nm, "{rpm}");
        assert!(f.ball_ball_torque_nm > 0.0 && b.ball_ball_torque_nm < 0.0);
    }
    let rest = summary(0.0);
    assert_eq!(rest.drag_torque_nm(), 0.0);
    assert!(summary(0.01).torque_nm < summary(10.0).torque_nm);
}

/// A ramp with a stated load between balls (`friction.ball_ball_load_n`, which bypasses the
/// train): every ball, a ramp's too, carries the stated load; the ramp moves the circle's load
/// onto its full balls, which changes the drag. What does not take a ramp says so, naming the
/// key: the real-time evaluator, an oversize-ball nut, FASTSIM contacts with the train, a ramp
/// that leaves a circle of one turn no full ball.
#[test]
fn a_ramp_with_a_stated_load_between_balls_and_where_it_is_refused() {
    let op = point(100.0, 2000.0);
    let mut stated = ramp(2);
    stated.friction.ball_ball_load_n = Some(1.0);
    let mut without = stated;
    without.circulation.load_ramp_balls = 0;
    let a = evaluate(&stated, &op).unwrap();
    let b = evaluate(&without, &op).unwrap();
    assert!(a.summary.torque_nm != b.summary.torque_nm);
    largest_chain_n(&a, 2000.0, stated.geometry.balls_per_circle);
    assert_eq!(a.balls[0][0].contacts[2].normal_load_n, 1.0);
    let refused = |spec: &ScrewSpec| match Model::new(spec).and_then(|m| Evaluator::<f64>::new(&m).map(|_| ())) {
        Err(Error::Unsupported { field, .. }) => assert_eq!(field, "circulation.load_ramp_balls"),
        Err(Error::Input(e)) => assert_eq!(e.field, "circulation.load_ramp_balls"),
        other => panic!("{other:?}"),
    };
    refused(&ramp(2));
    refused(&stated);
    let mut oversize = ramp(2);
    oversize.geometry.nuts = 1;
    oversize.geometry.preload = Preload::OversizeBall;
    refused(&oversize);
    let mut fastsim = ramp(2);
    fastsim.model.contact_theory = ballscrew_core::input::ContactTheory::Fastsim;
    refused(&fastsim);
    let mut few = ramp(4);
    few.geometry.balls_per_circle = 8;
    refused(&few);
    few.geometry.balls_per_circle = 9;
    Model::new(&few).unwrap();
}

/// A circuit of several turns (an external return): the entering ramp's balls ahead of its first
/// circle, the leaving ramp's behind its last; the end circles lose the ramps' balls, the
/// middle ones keep theirs, and the train carries more than without the ramp.
#[test]
fn a_circuit_of_several_turns_has_its_ramps_at_its_ends() {
    let mut spec = ramp(2);
    spec.circulation.kind = Return::External;
    let op = point(10.0, 2000.0);
    let z = spec.geometry.balls_per_circle;
    let e = evaluate(&spec, &op).unwrap();
    let full: Vec<u32> = e.balls[0][..e.circles].iter().map(|b| b.balls).collect();
    assert_eq!(full, [z - 2, z, z, z - 2]);
    let chain = largest_chain_n(&e, 2000.0, z);
    spec.circulation.load_ramp_balls = 0;
    let plain = evaluate(&spec, &op).unwrap();
    assert!(chain > largest_chain_n(&plain, 2000.0, z));
    let s = e.summary;
    assert!((s.torque_energy_nm - s.torque_moment_nm).abs() <= 2e-5 * s.torque_energy_nm);
}

/// The free orbit ratios the model notes give ("The load ramp"): a ball of DKFZD4012 alone at
/// a third of the full load of the first circle with a ramp of 2 (48.87 N at 2000 N) orbits
/// slower than at the full load, at 100 rpm (0.44352 against 0.44443) and at 1000 rpm (0.44623
/// against 0.44661).
#[test]
fn a_light_ball_orbits_slower_when_free() {
    use ballscrew_core::ball::solve;
    let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
    let full = evaluate(&ramp(2), &point(10.0, 2000.0)).unwrap().balls[0][0].axial_load_n;
    assert!((full - 48.87).abs() < 0.005, "{full}");
    let free = |rpm: f64, load_n: f64| {
        let w = rpm * core::f64::consts::PI / 30.0;
        let (setup, _) = model.ball_setup_at(load_n, 1.0, w, 1.0);
        solve::solve(&setup, None, w, 1.0).0[3]
    };
    for (rpm, light, heavy) in [(100.0, 0.44352, 0.44443), (1000.0, 0.44623, 0.44661)] {
        let (a, b) = (free(rpm, full / 3.0), free(rpm, full));
        assert!((a - light).abs() < 5e-6 && (b - heavy).abs() < 5e-6, "{rpm}: {a} {b}");
    }
}

/// The ramp's balls are in the totals, each once: with a stated load between balls (no train)
/// each ramp ball is a ball alone at k / (m + 1) of its circle's full load, so the dissipation
/// torque is rebuilt here from the report's contact shares (the full balls), the return's share
/// and each ramp ball solved alone (`ball::solve`, `ball::report`) to 1e-9; the same rebuild
/// without the ramp balls falls short by their share.
#[test]
fn the_ramps_balls_are_in_the_totals_once() {
    use ballscrew_core::ball::{report, solve};
    let mut spec = ramp(2);
    spec.friction.ball_ball_load_n = Some(0.5);
    let model = Model::new(&spec).unwrap();
    let op = point(100.0, 2000.0);
    let e = model.evaluate(&op, &mut SolverState::new()).unwrap();
    let m = spec.circulation.load_ramp_balls;
    let (mut full, mut ramps) = (e.summary.return_torque_nm, 0.0);
    for b in e.balls.iter().take(e.nuts).flat_map(|n| n.iter().take(e.circles)) {
        full += b.contacts.iter().map(|c| c.torque_share_nm).sum::<f64>();
        for _ in 0..b.ramp_balls / m {
            for k in 1..=m {
                let p = b.axial_load_n * f64::from(k) / f64::from(m + 1);
                let (setup, _) = model.ball_setup_at(p, b.flank, op.speed_rad_s, 1.0);
                let (x, rep) = solve::solve(&setup, None, op.speed_rad_s, 1.0);
                assert!(rep.residual < 1e-9);
                let st = report::ball_state(&setup, &x, op.speed_rad_s, 1.0);
                let per_ball =
                    st.screw.dissipation_per_speed + st.nut.dissipation_per_speed + st.ball_ball.dissipation_per_speed;
                ramps += b.weight * per_ball;
            }
        }
    }
    let d = e.summary.dissipation_torque_nm;
    assert!(ramps > 0.02 * d, "{ramps} of {d}");
    assert!((full + ramps - d).abs() <= 1e-9 * d, "{full} + {ramps} against {d}");
}
