//! A fingerprint of the project's torques: the bits of every torque of a fixed sample of calls
//! (the model, its summary, the control-loop evaluator cold and warm in f64 and f32, the warm
//! stepper, the reversal model and the batch on one and two threads), over dry and lubricated
//! specs, every preload arrangement and a spec with extension terms, hashed per path.
//!
//! A change meant to keep behaviour bit for bit (a refactor) prints the same lines before and
//! after: run it on both commits and compare.
//!
//! ```text
//! cargo run --release -p ballscrew-batch --example torque_fingerprint
//! ```

use ballscrew_batch::{Batch, Errors, Start};
use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{
    Conditions, Error, Evaluator, Lubrication, Model, OperatingPoint, Preload, ReversalModel, ReversalState, ScrewSpec,
    SolverState, Stepper,
};

/// FNV-1a over 64-bit words, with a count of what went in.
#[derive(Default)]
struct Hash {
    value: u64,
    calls: usize,
}

impl Hash {
    fn word(&mut self, w: u64) {
        if self.calls == 0 && self.value == 0 {
            self.value = 0xcbf2_9ce4_8422_2325;
        }
        for b in w.to_le_bytes() {
            self.value ^= u64::from(b);
            self.value = self.value.wrapping_mul(0x0100_0000_01b3);
        }
    }

    fn text(&mut self, s: &str) {
        for chunk in s.as_bytes().chunks(8) {
            let mut b = [0u8; 8];
            b[..chunk.len()].copy_from_slice(chunk);
            self.word(u64::from_le_bytes(b));
        }
    }

    /// One call's result: the torque's bits, or the error's text.
    fn result(&mut self, r: Result<f64, Error>) {
        match r {
            Ok(t) => self.word(t.to_bits()),
            Err(e) => self.text(&e.to_string()),
        }
        self.calls += 1;
    }
}

fn op(speed_rpm: f64, preload_n: f64, axial_load_n: f64) -> OperatingPoint {
    OperatingPoint { speed_rad_s: rpm_to_rad_s(speed_rpm), preload_n, axial_load_n }
}

/// A 16 x 5 screw with 3.175 mm balls, 3 circles of 15 balls a nut, arranged by `preload`.
fn screw_16x5(preload: Preload, lubrication: Lubrication) -> ScrewSpec {
    let mut s = ScrewSpec::dkfzd4012();
    let g = &mut s.geometry;
    g.pitch_diameter_m = 16e-3;
    g.lead_m = 5e-3;
    g.ball_diameter_m = 3.175e-3;
    g.balls_per_circle = 15;
    g.preload = preload;
    g.nuts = preload.nuts();
    g.circles_per_nut = if preload == Preload::OffsetLead { 6 } else { 3 };
    s.model.lubrication = lubrication;
    s.operating = if preload == Preload::None { op(1000.0, 0.0, 300.0) } else { op(1000.0, 200.0, 0.0) };
    s
}

fn spec_file(name: &str) -> ScrewSpec {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs").join(name);
    ballscrew_config::spec_from_toml_file(&path).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// The specs of the sample, with a name and the scale of their preloads (N).
fn specs() -> Vec<(String, ScrewSpec, f64)> {
    let mut out = Vec::new();
    let mut dry = ScrewSpec::dkfzd4012();
    dry.model.lubrication = Lubrication::Dry;
    out.push(("dkfzd4012 lubricated".to_string(), ScrewSpec::dkfzd4012(), 2000.0));
    out.push(("dkfzd4012 dry".to_string(), dry, 2000.0));
    for preload in Preload::ALL {
        for lubrication in [Lubrication::Ehl, Lubrication::Dry] {
            let name = format!("16x5 {} {lubrication:?}", preload.name());
            let scale = if preload == Preload::None { 0.0 } else { 300.0 };
            out.push((name, screw_16x5(preload, lubrication), scale));
        }
    }
    out.push(("xjtu-32x8".to_string(), spec_file("xjtu-32x8.toml"), 1500.0));
    out.push(("single-nut-16x5".to_string(), spec_file("single-nut-16x5.toml"), 0.0));
    let mut extended = spec_file("dkfzd4012.toml");
    let text = format!(
        "{}\n[extensions.seal_drag]\ntorque_nm = 0.02\n[extensions.preload_loss]\nloss_per_1000_h = 0.3\n\
         [extensions.thermal_viscosity]\ntorque_nm = 0.01\nexponent = 0.5\nviscosity_coefficient_per_k = 0.03\n\
         reference_temperature_c = 40.0\n[extensions.level_factor]\nfactor = 1.7\n",
        ballscrew_config::spec_to_toml(&extended)
    );
    extended = ballscrew_config::spec_from_toml_str(&text, "extended").expect("extended spec");
    out.push(("dkfzd4012 extended".to_string(), extended, 2000.0));
    let mut fastsim = ScrewSpec::dkfzd4012();
    fastsim.model.contact_theory = ballscrew_core::input::ContactTheory::Fastsim;
    fastsim.model.fastsim_grid = 8;
    out.push(("dkfzd4012 fastsim".to_string(), fastsim, -1.0));
    out
}

/// The operating points of a spec: speeds both ways, preloads around `scale`, axial loads.
fn points(scale: f64) -> Vec<OperatingPoint> {
    if scale < 0.0 {
        // FASTSIM: the model's own solve only, seconds a point: a few points.
        return vec![op(100.0, 2000.0, 0.0), op(-30.0, 1000.0, 300.0), op(1500.0, 3000.0, -500.0)];
    }
    let speeds = [-3000.0, -100.0, -1.0, 0.05, 2.0, 30.0, 100.0, 420.0, 1500.0, 3000.0];
    let preloads: Vec<f64> =
        if scale == 0.0 { vec![0.0] } else { [0.3, 0.7, 1.0, 1.6].iter().map(|f| f * scale).collect() };
    let axial = if scale == 0.0 { vec![50.0, 300.0, -800.0, 1500.0] } else { vec![0.0, 0.2 * scale, -0.5 * scale] };
    let mut out = Vec::new();
    for &s in &speeds {
        for &p in &preloads {
            for &a in &axial {
                out.push(op(s, p, a));
            }
        }
    }
    out
}

fn conditions(n: usize) -> Vec<Conditions> {
    (0..n)
        .map(|i| Conditions {
            position_m: 0.01 * i as f64,
            temperature_c: Some(25.0 + (i % 7) as f64 * 4.0),
            time_h: 30.0 * (i % 5) as f64,
        })
        .collect()
}

fn evaluator_path<F: ballscrew_core::real::Real>(
    model: &Model,
    ops: &[OperatingPoint],
    conds: &[Conditions],
    h: &mut Hash,
) {
    let Ok(ev) = Evaluator::<F>::new(model) else { return };
    let mut warm = ballscrew_core::EvalState::new();
    for (o, c) in ops.iter().zip(conds) {
        let r = ev.torque_at_nm(o, c, &mut warm);
        h.result(r.map(|t| t.to_f64()));
        let mut cold = ballscrew_core::EvalState::new();
        let r = ev.torque_nm(o, &mut cold);
        h.result(r.map(|t| t.to_f64()));
    }
}

fn main() {
    let mut paths: Vec<(&str, Hash)> = [
        "model",
        "summary",
        "evaluator f64",
        "evaluator f32",
        "warm stepper",
        "reversal",
        "batch 1 thread",
        "batch 2 threads",
        "batch with conditions",
    ]
    .into_iter()
    .map(|n| (n, Hash::default()))
    .collect();
    for (name, spec, scale) in specs() {
        let model = Model::new(&spec).unwrap_or_else(|e| panic!("{name}: {e}"));
        let ops = points(scale);
        let conds = conditions(ops.len());
        {
            let h = &mut paths[0].1;
            let mut state = SolverState::new();
            for (o, c) in ops.iter().zip(&conds) {
                h.result(model.torque(o, &mut SolverState::new()));
                h.result(model.torque_at(o, c, &mut state));
            }
        }
        {
            let h = &mut paths[1].1;
            for o in &ops {
                match model.summary(o, &mut SolverState::new()) {
                    Ok(s) => {
                        h.result(Ok(s.torque_nm));
                        h.result(Ok(s.axial_term_nm));
                    }
                    Err(e) => h.result(Err(e)),
                }
            }
        }
        evaluator_path::<f64>(&model, &ops, &conds, &mut paths[2].1);
        evaluator_path::<f32>(&model, &ops, &conds, &mut paths[3].1);
        {
            let h = &mut paths[4].1;
            let mut stepper = Stepper::<f64>::new(&model).expect("a warm stepper");
            for o in &ops {
                h.result(stepper.torque_nm(o));
            }
            if let Ok(mut stepper) = Stepper::<f32>::evaluator(&model) {
                for o in &ops {
                    h.result(stepper.torque_nm(o));
                }
            }
        }
        if spec.extensions.is_empty()
            && let Ok(ev) = Evaluator::<f64>::new(&model)
            && scale > 0.0
        {
            let h = &mut paths[5].1;
            match ReversalModel::new(&ev, scale, 0.0) {
                Ok(rm) => {
                    let mut state: ReversalState<f64> = rm.relaxed();
                    for k in 0..400 {
                        let rotation = 2e-3 * (k as f64 * 0.05).sin();
                        h.result(rm.step(rotation, 1e-3, &mut state));
                    }
                }
                Err(e) => h.result(Err(e)),
            }
        }
        for (i, threads) in [(6, 1), (7, 2)] {
            let r = Batch::new(0)
                .start(Start::Warm)
                .threads(threads)
                .errors(Errors::Nan)
                .torques(&model, None, &ops, None)
                .expect("a batch");
            for t in r {
                paths[i].1.result(t);
            }
        }
        let r = Batch::new(0)
            .start(Start::Warm)
            .threads(2)
            .errors(Errors::Nan)
            .torques(&model, None, &ops, Some(&conds))
            .expect("a batch");
        for t in r {
            paths[8].1.result(t);
        }
        eprintln!("{name}: {} points", ops.len());
    }
    let mut all = Hash::default();
    for (name, h) in &paths {
        println!("{name:<22} {:>6} calls  {:016x}", h.calls, h.value);
        all.word(h.value);
        all.calls += h.calls;
    }
    println!("{:<22} {:>6} calls  {:016x}", "all", all.calls, all.value);
}
