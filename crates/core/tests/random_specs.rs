//! No silent wrong answers from valid input: random valid specs reach no degenerate state (every
//! accepted ball state is physical, every torque finite) and one answer per point (the torque
//! alone and the full evaluation, both cold: the canonical state), with an internal return and
//! with an external one (circuits of several loaded turns, whose train may have no steady
//! state: `NoSteadyTrain`, an error like the convergence error), the stateful paths (the
//! model's warm solve, the evaluator) leave the canonical state on few of them, every end of
//! every validated range gives a finite torque or the convergence error, the reported
//! degenerate point errs cold and warm, and below 2 N of preload the model and the evaluator
//! agree.

use ballscrew_core::input::extensions::{
    AxialLoadLoss, DirectionAsymmetry, Extensions, LevelFactor, MIN_LAW_REFERENCE_PRELOAD_N, MIN_REFERENCE_SPEED_RAD_S,
    PreloadLaw, PreloadLoss, RacewayWaviness, SealDrag, ThermalViscosity, ViscousDrag,
};
use ballscrew_core::input::geometry::max_balls_per_circle;
use ballscrew_core::input::operating::MAX_SPEED_RAD_S;
use ballscrew_core::input::{
    BALL_DIAMETER_RANGE_M, CONFORMITY_RANGE, CONTACT_ANGLE_RANGE_DEG, LEAD_RANGE_M, MAX_BALL_BALL_LOAD_N,
    MAX_STANDSTILL_SPEED_RAD_S, PITCH_DIAMETER_RANGE_M, YOUNGS_MODULUS_RANGE_PA, rpm_to_rad_s,
};
use ballscrew_core::screw::load;
use ballscrew_core::screw::model::{LIGHT_BALL_SHARE, MAX_PEAK_PRESSURE_PA, MAX_THERMAL_LOADING};
use ballscrew_core::{
    BallReport, Conditions, ContactTheory, Error, EvalState, Evaluator, Model, OperatingPoint, ScrewSpec, SolverState,
};

/// splitmix64: a small deterministic generator, so the sample is repeatable.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        self.range(lo.ln(), hi.ln()).exp()
    }
}

fn random_spec(r: &mut Rng) -> Option<ScrewSpec> {
    let mut s = ScrewSpec::dkfzd4012();
    let g = &mut s.geometry;
    g.pitch_diameter_m = r.log(3e-3, 0.3);
    g.lead_m = r.log(0.5e-3, 0.2);
    g.ball_diameter_m = r.log(0.5e-3, (50e-3f64).min(0.5 * g.pitch_diameter_m));
    g.conformity_screw = r.range(0.501, 0.6);
    g.conformity_nut = r.range(0.501, 0.6);
    g.contact_angle_rad = r.range(CONTACT_ANGLE_RANGE_DEG.0, CONTACT_ANGLE_RANGE_DEG.1).to_radians();
    g.nuts = 1 + (r.unit() * 2.0) as u32;
    g.circles_per_nut = 1 + (r.unit() * 16.0) as u32;
    let most = max_balls_per_circle(g);
    g.balls_per_circle = 1 + (r.unit() * most as f64) as u32;
    s.friction.coefficient = r.log(0.005, 1.0);
    g.preload = ballscrew_core::Preload::default_for_nuts(g.nuts);
    let preload = if r.unit() < 0.05 || g.preload == ballscrew_core::Preload::None { 0.0 } else { r.log(0.1, 1e7) };
    let axial = if r.unit() < 0.3 { 0.0 } else { (if r.unit() < 0.5 { -1.0 } else { 1.0 }) * r.log(0.1, 1e7) };
    let speed = if r.unit() < 0.5 { 1.0 } else { -1.0 } * r.log(1.0, 3000.0);
    s.operating = OperatingPoint { speed_rad_s: rpm_to_rad_s(speed), preload_n: preload, axial_load_n: axial };
    s.validate().ok().map(|_| s)
}

/// The bounds of a physical state (`ballscrew_core::ball::setup`), restated here from the
/// physics so that the test does not lean on the check it tests: the rolling ball's orbit ratio
/// (1 - D_w cos(beta) / d_m) / 2 and spin (that orbit times r_m / (r_b cos(alpha))), the nominal
/// load P / (sin(beta) cos(alpha)); a state within (0, 10] of the orbit, [0.01, 100] of the spin,
/// (0, 10] of the nominal load, dissipating power (the degenerate state of the report had every
/// creep force zero and dissipated nothing).
fn physical_ball(spec: &ScrewSpec, model: &Model, b: &BallReport, speed_rad_s: f64) -> Result<(), String> {
    let g = &spec.geometry;
    let (rm, rb, beta, alpha) =
        (0.5 * g.pitch_diameter_m, 0.5 * g.ball_diameter_m, g.contact_angle_rad, model.helix_angle_rad());
    let orbit = 0.5 * (1.0 - g.ball_diameter_m * beta.cos() / g.pitch_diameter_m);
    let spin = orbit * rm / (rb * alpha.cos());
    let nominal = b.axial_load_n / (beta.sin() * alpha.cos());
    let o = b.orbit_ratio / orbit;
    let w = b.spin_ratio / spin;
    let (qa, qb) = (b.contacts[0].normal_load_n / nominal, b.contacts[1].normal_load_n / nominal);
    let dissipation: f64 = b.contacts.iter().map(|c| c.dissipation_per_ball_nm).sum::<f64>() * speed_rad_s.signum();
    let ok = o > 0.0
        && o <= 10.0 * (1.0 + 1e-12)
        && (0.01 * (1.0 - 1e-12)..=100.0 * (1.0 + 1e-12)).contains(&w)
        && qa > 0.0
        && qa <= 10.0 * (1.0 + 1e-12)
        && qb > 0.0
        && qb <= 10.0 * (1.0 + 1e-12)
        && dissipation > 0.0;
    if ok { Ok(()) } else { Err(format!("orbit {o:e}, spin {w:e}, loads {qa:e} {qb:e}, dissipation {dissipation:e}")) }
}

/// Counts of one sample.
#[derive(Default, Debug)]
struct Tally {
    specs: usize,
    evaluated: usize,
    errors: usize,
    /// Of `errors`, the ball train's (`NoSteadyTrain`).
    trains: usize,
    refused: usize,
    balls: usize,
    bad: Vec<String>,
}

/// Whether `e` is the refusal of a point beyond the screw's static load capacity (the most
/// loaded ball's Hertz peak pressure above `MAX_PEAK_PRESSURE_PA`).
fn beyond_capacity(e: &Error) -> bool {
    matches!(e, Error::Input(i) if i.field.starts_with("peak Hertz pressure") && i.value > MAX_PEAK_PRESSURE_PA)
}

/// The refusal of an oil too viscous for the speed ([`MAX_THERMAL_LOADING`]).
fn beyond_thermal_loading(e: &Error) -> bool {
    matches!(e, Error::Input(i) if i.field.starts_with("thermal loading") && i.value > MAX_THERMAL_LOADING)
}

/// `count` valid specs drawn by `spec_of` from `seed`, each solved cold with the full breakdown
/// and again for its torque alone: what is physical, finite and one answer, tallied.
fn check_sample_of(seed: u64, count: usize, spec_of: fn(&mut Rng) -> Option<ScrewSpec>) -> Tally {
    let mut r = Rng(seed);
    let mut t = Tally::default();
    while t.specs < count {
        let Some(spec) = spec_of(&mut r) else { continue };
        t.specs += 1;
        let model = Model::new(&spec).unwrap();
        let op = spec.operating;
        let evaluated = model.evaluate(&op, &mut SolverState::new());
        // One question, one answer: the torque alone (`torque`, Python, the canonical batch)
        // is the full evaluation's (`inspect`) to the bit, or the same error.
        let torque = model.torque(&op, &mut SolverState::new());
        match (&evaluated, &torque) {
            (Ok(e), Ok(alone)) if e.summary.torque_nm.to_bits() == alone.to_bits() => {}
            (Err(a), Err(b)) if format!("{a:?}") == format!("{b:?}") => {}
            _ => t.bad.push(format!(
                "evaluate {:?} against torque {torque:?} at {spec:?}",
                evaluated.as_ref().map(|e| e.summary.torque_nm)
            )),
        }
        match evaluated {
            Ok(e) => {
                t.evaluated += 1;
                if !e.summary.torque_nm.is_finite() {
                    t.bad.push(format!("torque {} at {spec:?}", e.summary.torque_nm));
                }
                for b in e.balls.iter().take(e.nuts).flat_map(|n| n.iter().take(e.circles)) {
                    if b.axial_load_n > 0.0 {
                        t.balls += 1;
                        if let Err(why) = physical_ball(&spec, &model, b, op.speed_rad_s) {
                            t.bad.push(format!("{why} at {spec:?}"));
                        }
                    }
                }
            }
            Err(Error::NoConvergence { .. }) => t.errors += 1,
            Err(Error::NoSteadyTrain { .. }) => {
                t.errors += 1;
                t.trains += 1;
            }
            Err(e) if beyond_capacity(&e) || beyond_thermal_loading(&e) => t.refused += 1,
            Err(e) => t.bad.push(format!("{e} at {spec:?}")),
        }
    }
    t
}

/// 20,000 random valid specs (seeded; every value across its validated range: pitch diameter,
/// lead, ball size, conformities, contact angle, friction coefficient, nuts, circles, balls,
/// preload and axial load log-uniform up to 1e7 N, speed 1-3000 rpm either way), each solved
/// cold with the full breakdown: every accepted ball is physical by bounds restated here
/// ([`physical_ball`]) and every torque finite; whatever is not accepted is the convergence
/// error. Each is solved cold a second time for its torque alone: the canonical state, the
/// same bits (or the same error) as the full evaluation. Two threads; about 4 minutes in
/// `--release` on a 2-core machine.
#[test]
fn random_specs_reach_no_degenerate_state() {
    let n = 20_000;
    let t = on_two_threads(0x5eed, n, random_spec);
    println!(
        "{} specs, {} evaluated ({} balls), {} beyond the static load capacity or the thermal loading, the rest did \
         not converge",
        t.specs, t.evaluated, t.balls, t.refused
    );
    assert!(t.bad.is_empty(), "{} not physical, e.g. {}", t.bad.len(), t.bad[0]);
    assert_eq!(t.specs, n);
    assert!(t.evaluated > (n - t.refused) / 2, "most specs within the static load capacity evaluate: {}", t.evaluated);
}

/// [`check_sample_of`] over `n` specs on two threads (seeds `seed` and `seed + 1`), the tallies
/// summed.
fn on_two_threads(seed: u64, n: usize, spec_of: fn(&mut Rng) -> Option<ScrewSpec>) -> Tally {
    let tallies: Vec<Tally> = std::thread::scope(|s| {
        let h: Vec<_> = (0..2u64).map(|k| s.spawn(move || check_sample_of(seed + k, n / 2, spec_of))).collect();
        h.into_iter().map(|h| h.join().unwrap()).collect()
    });
    let mut sum = Tally::default();
    for t in tallies {
        sum.specs += t.specs;
        sum.evaluated += t.evaluated;
        sum.errors += t.errors;
        sum.trains += t.trains;
        sum.refused += t.refused;
        sum.balls += t.balls;
        sum.bad.extend(t.bad);
    }
    sum
}

/// A point solved cold (fresh state) and warm (after the point 3 % lighter in preload and axial
/// load): both the same torque to 1e-6 relative, or both the convergence error.
fn cold_and_warm(model: &Model, op: &OperatingPoint) -> Option<String> {
    let near = OperatingPoint { preload_n: op.preload_n * 0.97, axial_load_n: op.axial_load_n * 0.97, ..*op };
    let cold = model.torque(op, &mut SolverState::new());
    let mut st = SolverState::new();
    let _ = model.torque(&near, &mut st);
    let warm = model.torque(op, &mut st);
    match (cold, warm) {
        (Ok(a), Ok(b)) if (a - b).abs() <= 1e-6 * a.abs().max(b.abs()) => None,
        (Err(_), Err(_)) => None,
        (a, b) => Some(format!("cold {a:?}, warm {b:?}")),
    }
}

/// What sets a spec apart: its contact angle (degrees), the Hertz peak pressure of its most
/// loaded ball at the nominal load (GPa, the larger of the two raceway contacts) and whether
/// any ball is light (below `LIGHT_BALL_SHARE` of the heaviest ball's load).
fn features(model: &Model, op: &OperatingPoint) -> (f64, f64, bool) {
    let spec = model.spec();
    let g = &spec.geometry;
    let loads = load::nut_loads(op.preload_n, op.axial_load_n, g.nuts);
    let shares = load::circle_shares(g.circles_per_nut, spec.model.load_distribution);
    let z = f64::from(g.balls_per_circle);
    let (nuts, circles) = (g.nuts as usize, g.circles_per_nut as usize);
    let p_max = load::heaviest_ball_load_n(&loads, nuts, &shares, circles, z);
    let light = loads.iter().take(nuts).any(|&(l, _)| {
        shares.load_fraction.iter().take(circles).any(|&f| {
            let p = l * f / z;
            p > 0.0 && p < LIGHT_BALL_SHARE * p_max
        })
    });
    let q = p_max / (g.contact_angle_rad.sin() * model.helix_angle_rad().cos());
    let (a, b) = model.hertz_shapes();
    let peak = a.contact(q).peak_pressure_pa.max(b.contact(q).peak_pressure_pa);
    (g.contact_angle_rad.to_degrees(), peak * 1e-9, light)
}

/// The model's warm solve is a stateful path: it follows its history, as a real screw does, and
/// may stay on another steady state of a ball's balance than the canonical one (the cold
/// continuation's, which every stateless request reports; docs/model-notes.md item 24). How
/// often, on random valid specs: measured on this sample of 2,000 (lubricated default, contact
/// angle 20-70 degrees, points above `MAX_PEAK_PRESSURE_PA` refused), 16 disagree. In 14 both
/// converge to residuals below 1e-12 and are physical, 5e-6 to 1e-2 relative apart (median
/// 6e-5): the balls that differ take the forced lateral slip at the other raceway (slip at the
/// nut and rolling at the screw, or the reverse) or turn their spin the other way. In 2 the
/// cold solve ends in the convergence error (residual 2e-4 and 1.3e-3) where the warm one
/// converges. Before the contact-angle limit and the static-capacity refusal: 59 of 2,000
/// disagreed. The test holds the rate (at most 1.5 %): more is a change of the solver to look
/// at.
#[test]
fn warm_solves_leave_the_canonical_state_on_few_random_specs() {
    let mut r = Rng(0xc01d);
    let mut specs = 0;
    let mut bad = Vec::new();
    while specs < 2000 {
        let Some(spec) = random_spec(&mut r) else { continue };
        specs += 1;
        let model = Model::new(&spec).unwrap();
        if let Some(d) = cold_and_warm(&model, &spec.operating) {
            let (angle, peak, light) = features(&model, &spec.operating);
            println!("DISAGREE angle {angle:.1} deg, peak {peak:.3e} GPa, light {light}: {d}");
            bad.push(format!("{d} at {spec:?}"));
        }
    }
    println!("{} of {specs} disagree", bad.len());
    assert!(bad.len() * 1000 <= 15 * specs, "{} of {specs} disagree, e.g. {}", bad.len(), bad[0]);
}

/// The control-loop evaluator is a stateful path too (the FMU's, `Reversal`'s, the diagnosis's
/// fits): even from a fresh state it starts each ball from its table of solutions in load, not
/// by the model's continuation in the creep stiffness, so where a ball's balance has two steady
/// states it may land on the other one (docs/model-notes.md item 24). Measured on this sample
/// of 500: 299 agree within 1e-8, 195 give an error on both paths (beyond the static load
/// capacity or not converged), 6 disagree by 1e-6 to 0.15 relative, all at heavy loads (2 to
/// 600 kN) and four of them at low speed (0.1 to 1.2 rad/s). In the worst (0.15: 141 kN of
/// preload at 0.12 rad/s) the model itself reaches the evaluator's torque warm from 0.8 times
/// the load. The test holds the rate (at most 3 %).
#[test]
fn the_evaluator_leaves_the_canonical_state_on_few_random_specs() {
    let mut r = Rng(0xe7a1);
    let (mut specs, mut agree, mut both_err) = (0, 0, 0);
    let mut bad = Vec::new();
    while specs < 500 {
        let Some(spec) = random_spec(&mut r) else { continue };
        specs += 1;
        let model = Model::new(&spec).unwrap();
        let op = spec.operating;
        let m = model.torque(&op, &mut SolverState::new());
        let ev = Evaluator::<f64>::new(&model).unwrap();
        let e = ev.torque_nm(&op, &mut EvalState::new());
        match (&m, &e) {
            (Ok(a), Ok(b)) if (a - b).abs() <= 1e-8 * a.abs().max(b.abs()) => agree += 1,
            (Err(_), Err(_)) => both_err += 1,
            _ => bad.push(format!("model {m:?}, evaluator {e:?} at {spec:?}")),
        }
    }
    println!("{agree} agree, {both_err} err on both paths, {} disagree", bad.len());
    assert!(bad.len() * 100 <= 3 * specs, "{} of {specs} disagree, e.g. {}", bad.len(), bad[0]);
}

/// The reported case: DKFZD4012 with conformities 0.501 (screw) and 0.6 (nut) at 600 kN, cold
/// and warm from 450 kN, once gave 0 N m (a state with an orbit ratio of -6.7e162) and 13.27 N m.
/// Its most loaded ball's Hertz peak pressure is far above `MAX_PEAK_PRESSURE_PA` (beyond the
/// screw's static load capacity): the model (cold and warm) and the evaluator refuse the point.
#[test]
fn the_reported_degenerate_point_is_an_error_cold_and_warm() {
    let mut spec = ScrewSpec::dkfzd4012();
    spec.geometry.conformity_screw = 0.501;
    spec.geometry.conformity_nut = 0.6;
    let model = Model::new(&spec).unwrap();
    let op = OperatingPoint { preload_n: 600e3, ..spec.operating };
    let cold = model.torque(&op, &mut SolverState::new());
    assert!(matches!(&cold, Err(e) if beyond_capacity(e)), "{cold:?}");
    let mut st = SolverState::new();
    for p in [450e3, 500e3, 550e3, 600e3] {
        let _ = model.torque(&OperatingPoint { preload_n: p, ..op }, &mut st);
    }
    let warm = model.torque(&op, &mut st);
    assert!(matches!(&warm, Err(e) if beyond_capacity(e)), "{warm:?}");
    let ev = Evaluator::<f64>::new(&model).unwrap();
    let r = ev.torque_nm(
        &OperatingPoint { speed_rad_s: op.speed_rad_s, preload_n: op.preload_n, axial_load_n: 0.0 },
        &mut EvalState::new(),
    );
    assert!(matches!(&r, Err(e) if beyond_capacity(e)), "{r:?}");
    let e = format!("{}", cold.unwrap_err());
    assert!(e.contains("static load capacity") && e.contains("ISO 76"), "{e}");
}

/// Below 2 N of preload on DKFZD4012 (0.04 N per ball and less) the model and the evaluator
/// (f64 and f32) give the same torque or the same error: the evaluator hands points with balls
/// below `LIGHT_BALL_N` to the model.
#[test]
fn model_and_evaluator_agree_below_2_n() {
    let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
    let e64 = Evaluator::<f64>::new(&model).unwrap();
    let e32 = Evaluator::<f32>::new(&model).unwrap();
    let (mut s64, mut s32) = (EvalState::new(), EvalState::new());
    let w = rpm_to_rad_s(100.0);
    for p in [0.0, 1e-300, 1e-6, 1e-3, 0.05, 0.3, 1.0, 1.5, 1.9, 1.99, 2.0, 2.5] {
        for axial in [0.0, 0.3 * p] {
            let m = model
                .torque(&OperatingPoint { speed_rad_s: w, preload_n: p, axial_load_n: axial }, &mut SolverState::new());
            let a = e64.torque_nm(&OperatingPoint { speed_rad_s: w, preload_n: p, axial_load_n: axial }, &mut s64);
            let p32 = OperatingPoint {
                speed_rad_s: f64::from(w as f32),
                preload_n: f64::from(p as f32),
                axial_load_n: f64::from(axial as f32),
            };
            let m32 = model.torque(&p32, &mut SolverState::new());
            let b = e32
                .torque_nm(
                    &OperatingPoint {
                        speed_rad_s: f64::from(w as f32),
                        preload_n: f64::from(p as f32),
                        axial_load_n: f64::from(axial as f32),
                    },
                    &mut s32,
                )
                .map(f64::from);
            for (m, r, tol) in [(&m, &a, 1e-8), (&m32, &b, 1e-4)] {
                match (m, r) {
                    (Ok(x), Ok(y)) => assert!((x - y).abs() <= tol * x.abs(), "{p} N: {x} vs {y}"),
                    (Err(x), Err(y)) => assert_eq!(format!("{x}"), format!("{y}"), "{p} N"),
                    (x, y) => panic!("{p} N, {axial} N: model {x:?}, evaluator {y:?}"),
                }
            }
        }
    }
}

/// The next float above `v` (the lower end of a range open there).
fn above(v: f64) -> f64 {
    if v == 0.0 { f64::from_bits(1) } else { f64::from_bits(v.to_bits() + 1) }
}

/// The next float below positive `v` (the upper end of a range open there).
fn below(v: f64) -> f64 {
    f64::from_bits(v.to_bits() - 1)
}

/// Every extension term on, at ordinary values.
fn all_terms(s: &mut ScrewSpec) {
    s.extensions = Extensions {
        seal_drag: Some(SealDrag { torque_nm: 0.02 }),
        viscous_drag: Some(ViscousDrag { torque_nm: 0.01, exponent: 0.7, reference_speed_rad_s: 100.0 }),
        thermal_viscosity: Some(ThermalViscosity {
            drag: ViscousDrag { torque_nm: 0.01, exponent: 0.7, reference_speed_rad_s: 50.0 },
            viscosity_coefficient_per_k: 0.02,
            reference_temperature_c: 40.0,
        }),
        raceway_waviness: Some(RacewayWaviness { harmonic: 2, amplitude_nm: 0.01, phase_rad: 0.3 }),
        preload_loss: Some(PreloadLoss { loss_per_1000_h: 0.3 }),
        direction_asymmetry: Some(DirectionAsymmetry { reverse_factor: 1.2 }),
        preload_law: Some(PreloadLaw { exponent: -0.2, reference_preload_n: 1500.0 }),
        axial_load_loss: Some(AxialLoadLoss { torque_per_n_nm: 1e-5 }),
        level_factor: Some(LevelFactor { factor: 1.5 }),
    };
}

type Case = (&'static str, fn(&mut ScrewSpec));

/// One spec per end of every range `ScrewSpec::validate` checks (`check_range` in
/// `crates/core/src/input/*.rs`), DKFZD4012 otherwise (with what the end needs to stay valid,
/// e.g. a smaller ball on the smallest pitch diameter); an open end is taken at the next float
/// inside it.
fn range_ends() -> Vec<Case> {
    vec![
        ("geometry.pitch_diameter_m low", |s| {
            s.geometry.pitch_diameter_m = PITCH_DIAMETER_RANGE_M.0;
            s.geometry.ball_diameter_m = 1e-3;
            s.geometry.lead_m = 1e-3;
            s.operating.preload_n = 20.0;
        }),
        ("geometry.pitch_diameter_m high", |s| {
            s.geometry.pitch_diameter_m = PITCH_DIAMETER_RANGE_M.1;
        }),
        ("geometry.lead_m low", |s| {
            s.geometry.lead_m = LEAD_RANGE_M.0;
        }),
        ("geometry.lead_m high", |s| {
            s.geometry.lead_m = LEAD_RANGE_M.1;
            s.geometry.balls_per_circle = 5;
        }),
        ("geometry.ball_diameter_m low", |s| {
            s.geometry.ball_diameter_m = BALL_DIAMETER_RANGE_M.0;
            s.operating.preload_n = 200.0;
        }),
        ("geometry.ball_diameter_m high", |s| {
            s.geometry.ball_diameter_m = BALL_DIAMETER_RANGE_M.1;
            s.geometry.pitch_diameter_m = 0.3;
            s.geometry.balls_per_circle = 15;
            s.operating.preload_n = 2e5;
        }),
        ("geometry.ball_diameter_m below half the pitch diameter", |s| {
            s.geometry.ball_diameter_m = below(0.5 * s.geometry.pitch_diameter_m);
            s.geometry.balls_per_circle = 3;
            s.operating.preload_n = 2e5;
        }),
        ("geometry.conformity_screw low", |s| {
            s.geometry.conformity_screw = CONFORMITY_RANGE.0;
        }),
        ("geometry.conformity_screw high", |s| {
            s.geometry.conformity_screw = CONFORMITY_RANGE.1;
        }),
        ("geometry.conformity_nut low", |s| {
            s.geometry.conformity_nut = CONFORMITY_RANGE.0;
        }),
        ("geometry.conformity_nut high", |s| {
            s.geometry.conformity_nut = CONFORMITY_RANGE.1;
        }),
        ("geometry.contact_angle_rad low", |s| {
            s.geometry.contact_angle_rad = CONTACT_ANGLE_RANGE_DEG.0.to_radians();
        }),
        ("geometry.contact_angle_rad high", |s| {
            s.geometry.contact_angle_rad = CONTACT_ANGLE_RANGE_DEG.1.to_radians();
        }),
        ("geometry.nuts low", |s| {
            s.geometry.nuts = 1;
            s.geometry.preload = ballscrew_core::Preload::None;
            s.operating.preload_n = 0.0;
            s.operating.axial_load_n = 2000.0;
        }),
        ("geometry.nuts high", |s| {
            s.geometry.nuts = 2;
        }),
        ("geometry.circles_per_nut low", |s| {
            s.geometry.circles_per_nut = 1;
        }),
        ("geometry.circles_per_nut high", |s| {
            s.geometry.circles_per_nut = 16;
        }),
        ("geometry.balls_per_circle low", |s| {
            s.geometry.balls_per_circle = 1;
        }),
        ("geometry.balls_per_circle high", |s| {
            s.geometry.balls_per_circle = max_balls_per_circle(&s.geometry);
        }),
        ("material.youngs_modulus_pa low", |s| {
            s.material.youngs_modulus_pa = YOUNGS_MODULUS_RANGE_PA.0;
        }),
        ("material.youngs_modulus_pa high", |s| {
            s.material.youngs_modulus_pa = YOUNGS_MODULUS_RANGE_PA.1;
        }),
        ("material.poisson_ratio low", |s| {
            s.material.poisson_ratio = 0.0;
        }),
        ("material.poisson_ratio high", |s| {
            s.material.poisson_ratio = 0.5;
        }),
        ("friction.coefficient low", |s| {
            s.friction.coefficient = 0.005;
        }),
        ("friction.coefficient high", |s| {
            s.friction.coefficient = 1.0;
        }),
        ("friction.ball_ball_load_n low", |s| {
            s.friction.ball_ball_load_n = Some(0.0);
        }),
        ("friction.ball_ball_load_n high", |s| {
            s.friction.ball_ball_load_n = Some(MAX_BALL_BALL_LOAD_N);
        }),
        ("friction.standstill_speed_rad_s low", |s| {
            s.friction.standstill_speed_rad_s = above(0.0);
        }),
        ("friction.standstill_speed_rad_s high", |s| {
            s.friction.standstill_speed_rad_s = MAX_STANDSTILL_SPEED_RAD_S;
        }),
        ("friction.creep_reduction low", |s| {
            s.friction.creep_reduction = above(0.0);
        }),
        ("friction.creep_reduction high", |s| {
            s.friction.creep_reduction = 1.0;
        }),
        ("model.fastsim_grid low", |s| {
            s.model.contact_theory = ContactTheory::Fastsim;
            s.model.fastsim_grid = 4;
        }),
        ("model.fastsim_grid high", |s| {
            s.model.contact_theory = ContactTheory::Fastsim;
            s.model.fastsim_grid = 200;
        }),
        ("speed_rad_s low", |s| {
            s.operating.speed_rad_s = -MAX_SPEED_RAD_S;
        }),
        ("speed_rad_s high", |s| {
            s.operating.speed_rad_s = MAX_SPEED_RAD_S;
        }),
        ("preload_n low", |s| {
            s.operating.preload_n = 0.0;
        }),
        ("preload_n high", |s| {
            s.operating.preload_n = 1e7;
        }),
        ("axial_load_n low", |s| {
            s.operating.axial_load_n = -1e7;
        }),
        ("axial_load_n high", |s| {
            s.operating.axial_load_n = 1e7;
        }),
        ("extensions.seal_drag.torque_nm low", |s| {
            all_terms(s);
            s.extensions.seal_drag = Some(SealDrag { torque_nm: 0.0 });
        }),
        ("extensions.seal_drag.torque_nm high", |s| {
            all_terms(s);
            s.extensions.seal_drag = Some(SealDrag { torque_nm: 1e4 });
        }),
        ("extensions.viscous_drag.torque_nm low", |s| {
            all_terms(s);
            let v = s.extensions.viscous_drag.as_mut().unwrap();
            v.torque_nm = 0.0;
        }),
        ("extensions.viscous_drag.torque_nm high", |s| {
            all_terms(s);
            let v = s.extensions.viscous_drag.as_mut().unwrap();
            v.torque_nm = 1e4;
        }),
        ("extensions.viscous_drag.exponent low", |s| {
            all_terms(s);
            let v = s.extensions.viscous_drag.as_mut().unwrap();
            v.exponent = 0.05;
            s.operating.speed_rad_s = MAX_SPEED_RAD_S;
        }),
        ("extensions.viscous_drag.exponent high", |s| {
            all_terms(s);
            let v = s.extensions.viscous_drag.as_mut().unwrap();
            v.exponent = 3.0;
            s.operating.speed_rad_s = MAX_SPEED_RAD_S;
        }),
        ("extensions.viscous_drag.reference_speed_rad_s low", |s| {
            all_terms(s);
            let v = s.extensions.viscous_drag.as_mut().unwrap();
            v.reference_speed_rad_s = MIN_REFERENCE_SPEED_RAD_S;
            s.operating.speed_rad_s = MAX_SPEED_RAD_S;
        }),
        ("extensions.viscous_drag.reference_speed_rad_s high", |s| {
            all_terms(s);
            let v = s.extensions.viscous_drag.as_mut().unwrap();
            v.reference_speed_rad_s = 1e4;
            s.operating.speed_rad_s = MAX_SPEED_RAD_S;
        }),
        ("extensions.thermal_viscosity.torque_nm low", |s| {
            all_terms(s);
            let v = &mut s.extensions.thermal_viscosity.as_mut().unwrap().drag;
            v.torque_nm = 0.0;
        }),
        ("extensions.thermal_viscosity.torque_nm high", |s| {
            all_terms(s);
            let v = &mut s.extensions.thermal_viscosity.as_mut().unwrap().drag;
            v.torque_nm = 1e4;
        }),
        ("extensions.thermal_viscosity.exponent low", |s| {
            all_terms(s);
            let v = &mut s.extensions.thermal_viscosity.as_mut().unwrap().drag;
            v.exponent = 0.05;
            s.operating.speed_rad_s = MAX_SPEED_RAD_S;
        }),
        ("extensions.thermal_viscosity.exponent high", |s| {
            all_terms(s);
            let v = &mut s.extensions.thermal_viscosity.as_mut().unwrap().drag;
            v.exponent = 3.0;
            s.operating.speed_rad_s = MAX_SPEED_RAD_S;
        }),
        ("extensions.thermal_viscosity.reference_speed_rad_s low", |s| {
            all_terms(s);
            let v = &mut s.extensions.thermal_viscosity.as_mut().unwrap().drag;
            v.reference_speed_rad_s = MIN_REFERENCE_SPEED_RAD_S;
            s.operating.speed_rad_s = MAX_SPEED_RAD_S;
        }),
        ("extensions.thermal_viscosity.reference_speed_rad_s high", |s| {
            all_terms(s);
            let v = &mut s.extensions.thermal_viscosity.as_mut().unwrap().drag;
            v.reference_speed_rad_s = 1e4;
            s.operating.speed_rad_s = MAX_SPEED_RAD_S;
        }),
        ("extensions.thermal_viscosity.viscosity_coefficient_per_k low", |s| {
            all_terms(s);
            s.extensions.thermal_viscosity.as_mut().unwrap().viscosity_coefficient_per_k = 0.0;
        }),
        ("extensions.thermal_viscosity.viscosity_coefficient_per_k high", |s| {
            all_terms(s);
            s.extensions.thermal_viscosity.as_mut().unwrap().viscosity_coefficient_per_k = 0.2;
        }),
        ("extensions.thermal_viscosity.reference_temperature_c low", |s| {
            all_terms(s);
            s.extensions.thermal_viscosity.as_mut().unwrap().reference_temperature_c = -100.0;
        }),
        ("extensions.thermal_viscosity.reference_temperature_c high", |s| {
            all_terms(s);
            s.extensions.thermal_viscosity.as_mut().unwrap().reference_temperature_c = 300.0;
        }),
        ("extensions.raceway_waviness.harmonic low", |s| {
            all_terms(s);
            s.extensions.raceway_waviness.as_mut().unwrap().harmonic = 1;
        }),
        ("extensions.raceway_waviness.harmonic high", |s| {
            all_terms(s);
            s.extensions.raceway_waviness.as_mut().unwrap().harmonic = 64;
        }),
        ("extensions.raceway_waviness.amplitude_nm low", |s| {
            all_terms(s);
            s.extensions.raceway_waviness.as_mut().unwrap().amplitude_nm = 0.0;
        }),
        ("extensions.raceway_waviness.amplitude_nm high", |s| {
            all_terms(s);
            s.extensions.raceway_waviness.as_mut().unwrap().amplitude_nm = 1e4;
        }),
        ("extensions.raceway_waviness.phase_rad low", |s| {
            all_terms(s);
            s.extensions.raceway_waviness.as_mut().unwrap().phase_rad = -1e3;
        }),
        ("extensions.raceway_waviness.phase_rad high", |s| {
            all_terms(s);
            s.extensions.raceway_waviness.as_mut().unwrap().phase_rad = 1e3;
        }),
        ("extensions.preload_loss.loss_per_1000_h low", |s| {
            all_terms(s);
            s.extensions.preload_loss.as_mut().unwrap().loss_per_1000_h = 0.0;
        }),
        ("extensions.preload_loss.loss_per_1000_h high", |s| {
            all_terms(s);
            s.extensions.preload_loss.as_mut().unwrap().loss_per_1000_h = 10.0;
        }),
        ("extensions.level_factor.factor low", |s| {
            all_terms(s);
            s.extensions.level_factor.as_mut().unwrap().factor = 0.01;
        }),
        ("extensions.level_factor.factor high", |s| {
            all_terms(s);
            s.extensions.level_factor.as_mut().unwrap().factor = 100.0;
        }),
        ("extensions.direction_asymmetry.reverse_factor low", |s| {
            all_terms(s);
            s.extensions.direction_asymmetry.as_mut().unwrap().reverse_factor = 0.1;
            s.operating.speed_rad_s = -s.operating.speed_rad_s;
        }),
        ("extensions.direction_asymmetry.reverse_factor high", |s| {
            all_terms(s);
            s.extensions.direction_asymmetry.as_mut().unwrap().reverse_factor = 10.0;
            s.operating.speed_rad_s = -s.operating.speed_rad_s;
        }),
        ("extensions.preload_law.exponent low", |s| {
            all_terms(s);
            s.extensions.preload_law.as_mut().unwrap().exponent = -1.0;
            s.operating.preload_n = if true { 0.0 } else { 1e7 };
        }),
        ("extensions.preload_law.exponent high", |s| {
            all_terms(s);
            s.extensions.preload_law.as_mut().unwrap().exponent = 1.0;
            s.operating.preload_n = if false { 0.0 } else { 1e7 };
        }),
        ("extensions.preload_law.reference_preload_n low", |s| {
            all_terms(s);
            s.extensions.preload_law.as_mut().unwrap().reference_preload_n = MIN_LAW_REFERENCE_PRELOAD_N;
            s.operating.preload_n = if true { 0.0 } else { 1e7 };
        }),
        ("extensions.preload_law.reference_preload_n high", |s| {
            all_terms(s);
            s.extensions.preload_law.as_mut().unwrap().reference_preload_n = 1e7;
            s.operating.preload_n = if false { 0.0 } else { 1e7 };
        }),
        ("extensions.axial_load_loss.torque_per_n_nm low", |s| {
            all_terms(s);
            s.extensions.axial_load_loss.as_mut().unwrap().torque_per_n_nm = 0.0;
            s.operating.axial_load_n = 1e7;
        }),
        ("extensions.axial_load_loss.torque_per_n_nm high", |s| {
            all_terms(s);
            s.extensions.axial_load_loss.as_mut().unwrap().torque_per_n_nm = 1.0;
            s.operating.axial_load_n = 1e7;
        }),
    ]
}

/// Every end of every validated range, in a full torque evaluation (the model, and the f64
/// evaluator where it serves the spec, with extension terms under extreme conditions too): a
/// finite torque or an error that names the ball and why, never an infinity or NaN.
#[test]
fn every_range_end_gives_a_finite_torque_or_an_error() {
    let conditions = [
        Conditions::default(),
        Conditions { position_m: 1e3, temperature_c: Some(-100.0), time_h: 1e5 },
        Conditions { position_m: -1e3, temperature_c: Some(300.0), time_h: 0.0 },
    ];
    let mut finite = 0;
    for (name, set) in range_ends() {
        let mut s = ScrewSpec::dkfzd4012();
        set(&mut s);
        // As many balls as fit one turn, at most the spec's.
        s.geometry.balls_per_circle = s.geometry.balls_per_circle.min(max_balls_per_circle(&s.geometry));
        s.validate().unwrap_or_else(|e| panic!("{name}: not valid: {e}"));
        let model = Model::new(&s).unwrap();
        let evaluator = Evaluator::<f64>::new(&model).ok();
        let op = s.operating;
        for cond in &conditions {
            let results = [
                model.torque_at(&op, cond, &mut SolverState::new()),
                model.summary_at(&op, cond, &mut SolverState::new()).map(|x| x.torque_nm),
                evaluator.as_ref().map_or(Ok(0.0), |e| e.torque_at_nm(&op, cond, &mut EvalState::new())),
            ];
            for r in results {
                match r {
                    Ok(t) => {
                        assert!(t.is_finite(), "{name}: {t} under {cond:?}");
                        finite += 1;
                    }
                    Err(e @ Error::NoConvergence { .. }) => assert!(format!("{e}").contains("did not converge")),
                    Err(e) if beyond_capacity(&e) => assert!(format!("{e}").contains("static load capacity")),
                    Err(e) if beyond_thermal_loading(&e) => assert!(format!("{e}").contains("too viscous")),
                    Err(e) => panic!("{name}: {e}"),
                }
            }
        }
    }
    assert!(finite > 100, "most ends evaluate: {finite}");
}

/// A random spec ([`random_spec`]) whose balls circulate through an external return: each
/// circuit of 1 to all of a nut's circles (a drawn `turns_per_circuit`), so that the ball
/// train of several loaded turns is balanced as one.
fn random_circuit_spec(r: &mut Rng) -> Option<ScrewSpec> {
    let mut s = random_spec(r)?;
    s.circulation.kind = ballscrew_core::input::circulation::Return::External;
    let circles = s.geometry.circles_per_nut;
    s.circulation.turns_per_circuit = Some(1 + (r.unit() * f64::from(circles)) as u32);
    // A spec the model refuses at construction (oversize balls in a circuit of several turns,
    // named by its message) is not drawn.
    s.validate().ok()?;
    Model::new(&s).ok().map(|_| s)
}

/// `n` random specs of `spec_of` checked on two threads ([`on_two_threads`]): every one drawn,
/// none in a state that is not physical; the counts printed (`what`: what the specs have).
fn trains_of(seed: u64, n: usize, spec_of: fn(&mut Rng) -> Option<ScrewSpec>, what: &str) -> Tally {
    let t = on_two_threads(seed, n, spec_of);
    println!(
        "{} specs {what}, {} evaluated, {} refused, {} without a steady state ({} of them the train's)",
        t.specs, t.evaluated, t.refused, t.errors, t.trains
    );
    assert!(t.bad.is_empty(), "{} not physical, e.g. {}", t.bad.len(), t.bad[0]);
    assert_eq!(t.specs, n);
    t
}

/// 400 random valid specs with an external return ([`random_circuit_spec`]): every accepted
/// ball physical, every torque finite, the torque alone the full evaluation's to the bit (or
/// the same error); what is not accepted is the convergence error or the train's
/// (`NoSteadyTrain`). Two threads.
#[test]
fn random_circuits_reach_no_degenerate_state() {
    let n = 400;
    let t = trains_of(0xc1c, n, random_circuit_spec, "with circuits");
    assert!(t.evaluated > (n - t.refused) / 2, "most specs within the static load capacity evaluate: {}", t.evaluated);
    // The counts docs/model-notes.md ("The ball train", where no steady state is found) states.
    assert_eq!((t.evaluated, t.refused, t.errors - t.trains, t.trains), (155, 135, 32, 78));
}

/// A random spec ([`random_spec`]) with a load ramp of 1 to 4 balls (fewer than half its balls
/// per circle), its return internal or external (every circle of a nut in one circuit); a spec
/// the model refuses at construction (oversize balls, FASTSIM contacts with the train, by their
/// messages) is not drawn.
fn random_ramp_spec(r: &mut Rng) -> Option<ScrewSpec> {
    let mut s = random_spec(r)?;
    if r.unit() < 0.5 {
        s.circulation.kind = ballscrew_core::input::circulation::Return::External;
    }
    let most = ((s.geometry.balls_per_circle.saturating_sub(1)) / 2).min(4);
    if most == 0 {
        return None;
    }
    s.circulation.load_ramp_balls = 1 + (r.unit() * f64::from(most)) as u32 % most;
    s.validate().ok()?;
    Model::new(&s).ok().map(|_| s)
}

/// 200 random valid specs with a load ramp ([`random_ramp_spec`]): every accepted ball physical,
/// every torque finite, the torque alone the full evaluation's to the bit (or the same error);
/// what is not accepted is the convergence error or the train's (`NoSteadyTrain`). Two threads.
#[test]
fn random_ramps_reach_no_degenerate_state() {
    let t = trains_of(0x4a3b, 200, random_ramp_spec, "with a ramp");
    // The counts docs/model-notes.md ("The load ramp", where it is solved) states.
    assert_eq!((t.evaluated, t.refused, t.errors - t.trains, t.trains), (62, 75, 14, 49));
}
