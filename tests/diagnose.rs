//! The diagnosis finds effects hidden in measured-like data.
//!
//! A seeded generator (`synth/mod.rs`) builds datasets from the project's own model (the
//! default, lubricated one unless a test says dry) with its level parameter (full-film traction,
//! or f for the dry model) and creep reduction moved within realistic bounds (so that
//! calibration has work to do), one hidden effect and 3 % noise. The diagnosis runs with the
//! spec the data were generated from (before the draws). For every effect the diagnosis must
//! name it first, recover its main parameter within the tolerance stated beside it and cut the
//! held-out RMSE by at least 30 %; noise alone must give no finding; two effects must give
//! both; data far above the model's level must be reported as a model whose level is off.

use ballscrew_core::input::extensions::*;
use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{Lubrication, Model, ModelOptions, ScrewSpec, SolverState};
use ballscrew_diagnose::data::Dataset;
use ballscrew_diagnose::{Report, diagnose};

#[path = "synth/mod.rs"]
mod synth;

use synth::{Synthetic, generate, generate_from, generate_scaled};

fn run(data: &Synthetic) -> Report {
    run_with(&ScrewSpec::dkfzd4012(), data)
}

fn run_with(spec: &ScrewSpec, data: &Synthetic) -> Report {
    let d = Dataset::from_csv(&data.csv, &[]).expect("generated data parse");
    diagnose(spec, &d).expect("diagnosis")
}

fn dry() -> ScrewSpec {
    let mut spec = ScrewSpec::dkfzd4012();
    spec.model = ModelOptions::dry();
    spec
}

/// The level parameter of the extended model: the full-film traction (lubricated model) or f.
fn extended_level(r: &Report) -> f64 {
    match r.lubrication {
        Lubrication::Ehl => r.full_film_traction().expect("lubricated calibration").2,
        Lubrication::Dry => r.extended_friction_coefficient,
    }
}

fn param(r: &Report, name: &str) -> f64 {
    r.findings[0].parameters.iter().find(|(k, _)| *k == name).map(|p| p.1).unwrap_or(f64::NAN)
}

/// Names `effect` first, its main parameter `name` within `tol` (absolute) of `truth`, and a
/// held-out cut of at least 30 %; returns the report.
fn check(seed: u64, ext: Extensions, axial: bool, effect: &str, name: &str, truth: f64, tol: f64) -> Report {
    check_with(&ScrewSpec::dkfzd4012(), seed, ext, axial, effect, name, truth, tol)
}

/// [`check`] with data generated from and diagnosed against `spec`.
#[allow(clippy::too_many_arguments)]
fn check_with(
    spec: &ScrewSpec,
    seed: u64,
    ext: Extensions,
    axial: bool,
    effect: &str,
    name: &str,
    truth: f64,
    tol: f64,
) -> Report {
    let data = generate_from(*spec, seed, ext, axial);
    let r = run_with(spec, &data);
    let text = r.to_text();
    assert_eq!(r.findings.first().map(|f| f.effect.name()), Some(effect), "{text}");
    let got = param(&r, name);
    assert!((got - truth).abs() <= tol, "{effect}.{name}: {got} vs {truth} +- {tol}\n{text}");
    assert!(r.gain >= 0.30, "gain {}\n{text}", r.gain);
    // The calibrated level is physical.
    assert!(r.level_off.is_none(), "{text}");
    if effect == "preload_law" {
        // Under the lubricated model the traction's share of the torque changes with the
        // preload, so a preload-law exponent and the traction level trade off against each
        // other on these data (seed 17: traction 0.023 for a true 0.033, with the exponent
        // within its tolerance): the level is not identifiable next to this term.
        return r;
    }
    // Calibration moved the level parameter from the spec's 0.03 toward the truth (within 25 %),
    // and found it physical.
    let level = extended_level(&r);
    assert!((level / data.true_level - 1.0).abs() < 0.25, "level {level} vs {}\n{text}", data.true_level);
    r
}

const NONE: Extensions = Extensions::NONE;

/// The lubricated model's torque on this design is about 7 times the dry model's (mean |torque|
/// 0.27 against 0.039 N m for seed 11): hidden torques given in N m are scaled by it, so that
/// each is the same share of the torque (and of the 3 % noise) as in the dry model's tests.
const S: f64 = 7.0;

#[test]
fn seal_drag_is_found() {
    // Tolerance: 15 % of the drag torque.
    let e = Extensions { seal_drag: Some(SealDrag { torque_nm: S * 0.015 }), ..NONE };
    check(11, e, false, "seal_drag", "torque_nm", S * 0.015, 0.15 * S * 0.015);
}

#[test]
fn seal_drag_is_found_by_the_dry_model() {
    // The dry model's calibration fits f, as before the lubricant; tolerance as above.
    let e = Extensions { seal_drag: Some(SealDrag { torque_nm: 0.015 }), ..NONE };
    let r = check_with(&dry(), 11, e, false, "seal_drag", "torque_nm", 0.015, 0.15 * 0.015);
    assert_eq!(r.calibration[0].name, "friction_coefficient");
    assert_eq!(r.full_film_traction(), None);
    assert_eq!(r.extended_spec.friction.coefficient, r.extended_friction_coefficient);
}

#[test]
fn viscous_drag_is_found() {
    // The data carry the lubricated model's own speed dependence (film, mixed friction,
    // rolling resistance) and, beyond it, a drag |w|^0.8 that the diagnosis must name.
    // Tolerance: the speed exponent within 0.15.
    let v = ViscousDrag { torque_nm: S * 0.02, exponent: 0.8, reference_speed_rad_s: rpm_to_rad_s(1000.0) };
    check(12, Extensions { viscous_drag: Some(v), ..NONE }, false, "viscous_drag", "exponent", 0.8, 0.15);
}

#[test]
fn thermal_viscosity_is_found() {
    // Tolerance: the viscosity-temperature coefficient within 25 %.
    let t = ThermalViscosity {
        drag: ViscousDrag { torque_nm: S * 0.025, exponent: 0.8, reference_speed_rad_s: rpm_to_rad_s(1000.0) },
        viscosity_coefficient_per_k: 0.03,
        reference_temperature_c: 40.0,
    };
    let e = Extensions { thermal_viscosity: Some(t), ..NONE };
    check(13, e, false, "thermal_viscosity", "viscosity_coefficient_per_k", 0.03, 0.25 * 0.03);
}

#[test]
fn raceway_waviness_is_found_with_its_harmonic() {
    // Tolerance: amplitude within 20 %, harmonic exact.
    let w = RacewayWaviness { harmonic: 2, amplitude_nm: S * 0.008, phase_rad: 0.7 };
    let e = Extensions { raceway_waviness: Some(w), ..NONE };
    let r = check(14, e, false, "raceway_waviness", "amplitude_nm", S * 0.008, 0.2 * S * 0.008);
    assert_eq!(param(&r, "harmonic"), 2.0);
}

#[test]
fn direction_asymmetry_is_found() {
    // Tolerance: the reverse factor within 0.08.
    let e = Extensions { direction_asymmetry: Some(DirectionAsymmetry { reverse_factor: 1.35 }), ..NONE };
    check(16, e, false, "direction_asymmetry", "reverse_factor", 1.35, 0.08);
}

#[test]
fn preload_law_is_found() {
    // Tolerance: the exponent within 0.1.
    let e = Extensions { preload_law: Some(PreloadLaw { exponent: -0.35, reference_preload_n: 1750.0 }), ..NONE };
    check(17, e, false, "preload_law", "exponent", -0.35, 0.1);
}

#[test]
fn axial_load_loss_is_found() {
    // Tolerance: 30 % of the extra torque per kN.
    // (Not scaled by S: 0.3 N m per kN is already several times the torque at 1 kN.)
    let e = Extensions { axial_load_loss: Some(AxialLoadLoss { torque_per_n_nm: 0.3e-3 }), ..NONE };
    check(18, e, true, "axial_load_loss", "torque_per_kn_nm", 0.3, 0.3 * 0.3);
}

#[test]
fn noise_alone_gives_no_finding() {
    for seed in [21, 22] {
        let r = run(&generate(seed, NONE, false));
        assert!(r.findings.is_empty(), "{}", r.to_text());
        assert!(r.level_off.is_none() && r.warnings.is_empty(), "{}", r.to_text());
        assert!(r.verdict().starts_with("no missing effect found"), "{}", r.verdict());
    }
}

/// Data that reach speeds where the balls' inertia is not small (here one row at 6000 rpm and
/// 500 N, where the gyroscopic moment of the most loaded ball is 42 % of its friction's) are
/// diagnosed with a warning that says so in the core's words: the model's torque there is an
/// extrapolation of the quasi-static balance (the noise-only data above, up to 3000 rpm, give
/// no warning).
#[test]
fn data_beyond_the_quasi_static_model_are_warned_about() {
    let mut data = generate(21, NONE, false);
    let first = data.csv.lines().nth(1).expect("a data row").to_string();
    let mut cells: Vec<&str> = first.split(',').collect();
    (cells[1], cells[2]) = ("500", "6000");
    data.csv.push_str(&(cells.join(",") + "\n"));
    let r = run(&data);
    let spec = ScrewSpec::dkfzd4012();
    let d = Dataset::from_csv(&data.csv, &[]).unwrap();
    let rows = ballscrew_diagnose::model::Rows::new(&d, &spec.operating);
    let w = ballscrew_core::screw::inertia::check(&spec, spec.helix_angle_rad(), rows.op.iter().copied())
        .expect("beyond the quasi-static model");
    assert_eq!(r.warnings, vec![format!("the data's operating points: {w}")], "{}", r.to_text());
    assert!(
        r.warnings[0].contains("at 1 of ") && r.warnings[0].contains("speed 6000 rpm, preload 500 N"),
        "{:?}",
        r.warnings
    );
    assert!(r.to_text().contains(&r.warnings[0]), "{}", r.to_text());
}

#[test]
fn two_effects_give_both() {
    let e = Extensions {
        seal_drag: Some(SealDrag { torque_nm: S * 0.015 }),
        raceway_waviness: Some(RacewayWaviness { harmonic: 1, amplitude_nm: S * 0.008, phase_rad: -1.0 }),
        ..NONE
    };
    let r = run(&generate(31, e, false));
    let mut names = r.effects();
    names.sort_unstable();
    assert_eq!(names, vec!["raceway_waviness", "seal_drag"], "{}", r.to_text());
    assert!(r.gain >= 0.30, "{}", r.to_text());
}

/// A preload loss is found, and the extended spec reproduces the extended prediction (one
/// diagnosis for both: the lubricated model's evaluations dominate the test time).
#[test]
fn preload_loss_is_found_and_the_extended_spec_reproduces_the_extended_prediction() {
    // Tolerance: the loss rate within 20 %.
    let e = Extensions { preload_loss: Some(PreloadLoss { loss_per_1000_h: 0.35 }), ..NONE };
    let r = check(15, e, false, "preload_loss", "loss_per_1000_h", 0.35, 0.2 * 0.35);
    // The spec written by `diagnose --out-spec` predicts, through the core's own torque, what
    // the diagnosis reported. The diagnosis interpolates the model in the level (full-film
    // traction) and takes the friction at the worn preload from a table in preload: agreement
    // within 0.1 % of each torque where the preload is the nominal one (running time 0: the
    // level interpolation alone), within 0.5 % elsewhere (the lubricated friction bends with
    // the preload between the table's ratios: 0.41 % at most on these data).
    let data = generate(15, e, false);
    // The calibrated traction is where the lubricated model reads it; f is untouched.
    assert_eq!(r.extended_spec.lubricant.full_film_traction, extended_level(&r));
    assert_eq!(r.extended_spec.friction.coefficient, ScrewSpec::dkfzd4012().friction.coefficient);
    let model = Model::new(&r.extended_spec).unwrap();
    let d = Dataset::from_csv(&data.csv, &[]).unwrap();
    let rows = ballscrew_diagnose::model::Rows::new(&d, &r.extended_spec.operating);
    let mut state = SolverState::new();
    for i in (0..r.rows).step_by(7) {
        let t = model.torque_at(&rows.op[i], &rows.cond[i], &mut state).unwrap();
        let tol = if rows.cond[i].time_h == 0.0 { 1e-3 } else { 5e-3 };
        assert!((t - r.series.extended[i]).abs() < tol * t.abs(), "row {i}: {t} vs {}", r.series.extended[i]);
    }
}

/// The XJTU degradation data (upper screw): torque against running time at one operating point.
#[test]
fn xjtu_upper_screw_loses_preload() {
    let text = include_str!("data/xjtu-ball-screw/friction_torque.csv");
    let map = [
        (ballscrew_diagnose::data::Column::TimeH, "hours".to_string()),
        (ballscrew_diagnose::data::Column::TorqueNm, "upper_screw_torque_Nm".to_string()),
    ];
    let d = Dataset::from_csv(text, &map).unwrap();
    assert!(d.warnings[0].contains("lower_screw_torque_Nm"));
    let spec =
        ballscrew_config::spec_from_toml_str(include_str!("../configs/xjtu-32x8.toml"), "xjtu-32x8.toml").unwrap();
    let r = diagnose(&spec, &d).unwrap();
    let text = r.to_text();
    assert_eq!(r.effects(), vec!["preload_loss"], "{text}");
    // The torque falls from about 0.39 to 0.25 N m over 1015 h: about 0.35 of the preload per
    // 1000 h on a torque nearly proportional to the preload.
    let loss = param(&r, "loss_per_1000_h");
    assert!((0.25..0.45).contains(&loss), "{loss}\n{text}");
    assert!(r.gain >= 0.30, "{text}");
}

/// A local defect (extra drag of 0.012 N m, times [`S`], on the last 150 mm of a 400 mm stroke) is no term of
/// the library: a term may take its mean (a seal drag does), but no term explains it, the gain
/// stays small, and the structure left along the position is reported.
#[test]
fn an_unknown_effect_is_reported_as_remaining_structure() {
    let data = generate(41, NONE, false);
    let mut lines = data.csv.lines();
    let mut csv = format!("{}\n", lines.next().unwrap());
    for l in lines {
        let mut v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
        // Columns: torque_nm, preload_n, speed_rpm, position_mm, ...
        if v[3] > 250.0 {
            v[0] += S * 0.012 * v[2].signum();
        }
        csv.push_str(&v.iter().map(f64::to_string).collect::<Vec<_>>().join(","));
        csv.push('\n');
    }
    let r = run(&Synthetic { csv, true_level: data.true_level });
    let text = r.to_text();
    assert!(r.remaining.iter().any(|s| s.contains("position_mm")), "{text}");
    assert!(r.gain < 0.3, "{text}");
}

/// Degenerate data end in a result or an error, never a panic.
#[test]
fn degenerate_data_give_errors_or_results_not_panics() {
    let spec = ScrewSpec::dkfzd4012();
    let rows = |f: &dyn Fn(usize) -> String| (0..12).map(f).collect::<Vec<_>>().join("\n");
    // Zero preload everywhere: the model has no friction to calibrate.
    let zero = format!("torque_nm,preload_n\n{}\n", rows(&|_| "0.05,0".into()));
    let e = diagnose(&spec, &Dataset::from_csv(&zero, &[]).unwrap()).unwrap_err();
    assert!(e.to_string().contains("no friction"), "{e}");
    // A measured torque of zero everywhere: calibration goes to its lower bound, no finding; the
    // lubricated model's offset (boundary friction, rolling resistance) stays, so its level is
    // off.
    let flat = format!("torque_nm,preload_n,speed_rpm\n{}\n", rows(&|i| format!("0,{},{}", 500 + 250 * (i % 4), 100)));
    let r = diagnose(&spec, &Dataset::from_csv(&flat, &[]).unwrap()).unwrap();
    let (_, mu, _) = r.full_film_traction().unwrap();
    assert!(mu >= ballscrew_diagnose::creep_cache::MU_EHL_MIN && r.findings.is_empty(), "{}", r.to_text());
    assert!(r.level_off.is_some(), "{}", r.to_text());
    let r = diagnose(&dry(), &Dataset::from_csv(&flat, &[]).unwrap()).unwrap();
    assert!(r.friction_coefficient >= 0.005 && r.findings.is_empty(), "{}", r.to_text());
    // Standstill only: the model's friction is zero there (standstill factor), nothing to calibrate.
    let still = format!("torque_nm,preload_n,speed_rpm\n{}\n", rows(&|i| format!("0.01,{},{}", 1000 + 100 * i, 0.0)));
    let e = diagnose(&spec, &Dataset::from_csv(&still, &[]).unwrap()).unwrap_err();
    assert!(e.to_string().contains("no friction"), "{e}");
}

/// Data at ten times the lubricated model's level: the full-film traction stays within its
/// physical range (the fit's bounds), a level factor of about 10 is kept, the oil's friction
/// coefficients times it leave their ranges, and the report says that the model's level is off
/// rather than offering a traction as the oil's. (Before the level factor, the traction itself
/// was fitted out of its range here; it no longer can be.)
#[test]
fn data_far_above_the_lubricated_model_are_a_level_finding() {
    let data = generate(51, NONE, false);
    let mut lines = data.csv.lines();
    let mut csv = format!("{}\n", lines.next().unwrap());
    for l in lines {
        let mut v: Vec<&str> = l.split(',').collect();
        let t = 10.0 * v[0].parse::<f64>().unwrap();
        let t = t.to_string();
        v[0] = &t;
        csv.push_str(&v.join(","));
        csv.push('\n');
    }
    let r = run(&Synthetic { csv, true_level: 10.0 * data.true_level });
    let text = r.to_text();
    let (lo, hi) = ballscrew_diagnose::creep_cache::FULL_FILM_TRACTION_RANGE;
    let (_, mu, _) = r.full_film_traction().unwrap();
    assert!((lo..=hi).contains(&mu), "{mu}\n{text}");
    let (k, k_lo, k_hi) = r.level.factor.expect("a level factor");
    assert!(k_lo < k && k < k_hi && (7.0..14.0).contains(&k), "{k} [{k_lo}, {k_hi}]\n{text}");
    assert!(!r.level.absorbed && r.level.readings.iter().any(|g| !g.physical()), "{text}");
    assert!(r.findings.is_empty(), "{text}");
    assert!(r.verdict().starts_with("the model's level is off"), "{}", r.verdict());
    assert!(r.summary().starts_with("Calibrated within its physical ranges, the model is "), "{}", r.summary());
    let json = r.to_json();
    assert_eq!(json["calibration"][0]["name"], "full_film_traction");
    assert_eq!(json["calibration"][0]["within_physical_range"], true);
    assert_eq!(json["level"]["absorbed"], false);
    assert_eq!(json["level"]["factor"].as_f64(), Some(k));
    assert_eq!(json["baseline"]["full_film_traction"].as_f64(), Some(mu));
    // The extended spec carries the factor: it predicts what the report predicts.
    assert_eq!(r.extended_spec.extensions.level_factor.map(|l| l.factor), Some(k));
}

/// A screw whose drag is the model's times a constant (x0.6, x1.12, x2 of the spec's own
/// model, both directions, 10-2500 rpm, 6 preloads, 3 % noise) gets a finding of level with its
/// factor, and no named term: the level is what the data show, not seals or viscous drag.
#[test]
fn a_pure_level_change_is_a_level_finding_and_no_term() {
    for (seed, factor) in [(61, 0.6), (62, 1.12), (63, 2.0)] {
        let data = generate_scaled(ScrewSpec::dkfzd4012(), seed, NONE, false, false, factor);
        let r = run(&data);
        let text = r.to_text();
        assert!(r.findings.is_empty(), "x{factor}: a named term\n{text}");
        let l = &r.level;
        // The data's level against the spec's model: the factor, within its interval.
        assert!(l.differs, "x{factor}\n{text}");
        assert!((l.spec_ratio / factor - 1.0).abs() < 0.02, "x{factor}: ratio {}\n{text}", l.spec_ratio);
        let (lo, hi) = l.spec_ratio_interval;
        assert!(lo < factor && factor < hi, "x{factor}: [{lo}, {hi}]\n{text}");
        // The full-film traction alone cannot scale the slow rows (boundary friction carries
        // them), so the level factor is kept, and it is the factor.
        let (k, k_lo, k_hi) = l.factor.unwrap_or_else(|| panic!("x{factor}: no level factor\n{text}"));
        assert!((k / factor - 1.0).abs() < 0.05 && k_lo < k && k < k_hi, "x{factor}: {k}\n{text}");
        // The first paragraph says it in words: a level (with the factor), what to check, and
        // no candidate's name as a finding.
        let summary = r.summary();
        let first = summary.split(". ").next().unwrap();
        let k_text = ballscrew_diagnose::text::sig(if k >= 1.0 { k } else { 1.0 / k });
        assert!(first.contains(&k_text), "x{factor}: {summary}");
        assert!(summary.contains("check the spec") || summary.contains("Check the spec"), "x{factor}: {summary}");
        assert!(summary.contains("No effect beyond the level"), "x{factor}: {summary}");
        if l.absorbed {
            assert!(first.contains("a level, not a missing effect"), "x{factor}: {summary}");
            assert!(r.level_off.is_none() && l.readings.iter().all(|g| g.physical()), "{text}");
        } else {
            let side = if factor > 1.0 { "below" } else { "above" };
            assert!(first.contains(&format!("the model is {k_text} times {side} this screw")), "{summary}");
            assert!(r.verdict().starts_with("the model's level is off"), "{}", r.verdict());
        }
        // Twice the model: the oil's boundary friction would have to be 0.3, beyond its range.
        if factor == 2.0 {
            assert!(!l.absorbed, "{text}");
        }
        // The spec model's bias is signed with the motion: the same sign in both directions.
        let m = &r.spec_model;
        let want = if factor > 1.0 { -1.0 } else { 1.0 };
        assert!(m.bias_forward_nm * want > 0.0 && m.bias_reverse_nm * want > 0.0, "{m:?}");
    }
}

/// Model and data differ in level and in one named effect: both are found, the effect's size
/// within 20 % of the truth.
#[test]
fn a_level_change_with_a_seal_drag_gives_both() {
    let seal = S * 0.015;
    let e = Extensions { seal_drag: Some(SealDrag { torque_nm: seal }), ..NONE };
    let data = generate_scaled(ScrewSpec::dkfzd4012(), 64, e, false, false, 1.5);
    let r = run(&data);
    let text = r.to_text();
    assert_eq!(r.effects(), vec!["seal_drag"], "{text}");
    let got = param(&r, "torque_nm");
    assert!((got / seal - 1.0).abs() < 0.2, "seal {got} vs {seal}\n{text}");
    let (k, _, _) = r.level.factor.expect("a level factor");
    assert!((k / 1.5 - 1.0).abs() < 0.1, "{k}\n{text}");
    let summary = r.summary();
    assert!(summary.contains("seals and wipers"), "{summary}");
}

/// The bias of data run in both directions: model minus measured along the motion, so a model
/// below the screw shows as a negative bias in both directions and in the whole, never as a
/// cancellation near zero; each direction's bias equals its own mean.
#[test]
fn the_bias_is_signed_with_the_motion_in_both_directions() {
    let data = generate_scaled(ScrewSpec::dkfzd4012(), 65, NONE, false, false, 1.3);
    let r = run(&data);
    let s = &r.series;
    let speed = &s.columns.iter().find(|(c, _)| c.name() == "speed_rpm").unwrap().1;
    let mean = |keep: &dyn Fn(f64) -> bool| {
        let v: Vec<f64> = (0..r.rows)
            .filter(|&i| keep(speed[i]))
            .map(|i| (s.spec_model[i] - s.measured[i]) * speed[i].signum())
            .collect();
        v.iter().sum::<f64>() / v.len() as f64
    };
    let m = &r.spec_model;
    assert!((m.bias_nm - mean(&|_| true)).abs() < 1e-12 && (m.bias_forward_nm - mean(&|v| v > 0.0)).abs() < 1e-12);
    assert!((m.bias_reverse_nm - mean(&|v| v < 0.0)).abs() < 1e-12);
    // A model 1/1.3 of the screw: about 23 % of the mean |torque| below it, in each direction.
    let drag = s.measured.iter().map(|v| v.abs()).sum::<f64>() / r.rows as f64;
    for b in [m.bias_nm, m.bias_forward_nm, m.bias_reverse_nm] {
        assert!(b < -0.15 * drag, "{b} vs mean drag {drag}\n{}", r.to_text());
    }
    // The signed mean of model minus measured, the former bias, cancels between directions.
    let signed = (0..r.rows).map(|i| s.spec_model[i] - s.measured[i]).sum::<f64>() / r.rows as f64;
    assert!(signed.abs() < 0.2 * m.bias_nm.abs(), "{signed} vs {}", m.bias_nm);
}

/// A worn screw at 0.7 of the model's level (preloads 312-2900 N, 20-1800 rpm, both
/// directions, a preload loss of 0.3 per 1000 h over 1200 h): the fit's trials reach levels and
/// worn preloads the model may not solve, which are infeasible trials, not the end of the
/// diagnosis; the loss is found.
#[test]
fn a_preload_loss_at_a_lower_level_is_diagnosed_without_aborting() {
    let spec = ScrewSpec::dkfzd4012();
    let mut worn = spec;
    worn.extensions.preload_loss = Some(PreloadLoss { loss_per_1000_h: 0.3 });
    let model = Model::new(&worn).unwrap();
    let mut rng = synth::Rng(66);
    let mut csv = String::from("torque_nm,preload_n,speed_rpm,time_h,repeat\n");
    for (g, hours) in [0.0, 240.0, 480.0, 720.0, 960.0, 1200.0].into_iter().enumerate() {
        for preload in [312.0, 900.0, 1500.0, 2200.0, 2900.0] {
            for rpm in [20.0, -20.0, 400.0, -400.0, 1000.0, -1000.0, 1800.0, -1800.0] {
                let op = ballscrew_core::OperatingPoint {
                    speed_rad_s: rpm_to_rad_s(rpm),
                    preload_n: preload,
                    axial_load_n: 0.0,
                };
                let cond = ballscrew_core::Conditions { time_h: hours, ..Default::default() };
                let t = 0.7 * model.torque_at(&op, &cond, &mut SolverState::new()).unwrap();
                let t = t + synth::NOISE * t.abs() * rng.normal();
                csv.push_str(&format!("{t},{preload},{rpm},{hours},{g}\n"));
            }
        }
    }
    let r = diagnose(&spec, &Dataset::from_csv(&csv, &[]).unwrap()).expect("a diagnosis, not an abort");
    let text = r.to_text();
    assert_eq!(r.effects(), vec!["preload_loss"], "{text}");
    let loss = param(&r, "loss_per_1000_h");
    assert!((loss / 0.3 - 1.0).abs() < 0.2, "{loss}\n{text}");
    assert!((r.level.spec_ratio - 0.7).abs() < 0.15, "{}\n{text}", r.level.spec_ratio);
    assert!(r.summary().contains("re-preload it or replace it"), "{}", r.summary());
}

/// A screw whose oil has another boundary friction than the spec says (0.18 or 0.12 for the
/// spec's 0.15, both within the physical range 0.1-0.2) drags more at low speed and about the
/// same at high speed: no level factor and no named term explain that better than the
/// calibration, which finds the boundary friction itself (within 0.01) and says so first. (With
/// the full-film traction alone calibrated, these data were diagnosed as a seal drag with a
/// preload law, and as a viscous drag with a preload law.)
#[test]
fn another_boundary_friction_is_calibrated_not_named() {
    for (seed, mu_b) in [(71, 0.18), (72, 0.12)] {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.lubricant.boundary_friction = mu_b;
        let r = run(&generate_scaled(spec, seed, NONE, false, false, 1.0));
        let text = r.to_text();
        assert!(r.findings.is_empty() && r.level.factor.is_none() && r.level_off.is_none(), "{mu_b}: {text}");
        let c = r.calibration.iter().find(|c| c.name == "boundary_friction").expect("calibrated");
        assert!((c.extended - mu_b).abs() < 0.01, "{mu_b}: {}\n{text}", c.extended);
        assert_eq!(r.extended_spec.lubricant.boundary_friction, c.extended);
        let summary = r.summary();
        let reading = format!("boundary friction 0.15 -> {}", ballscrew_diagnose::text::sig(c.extended));
        assert!(summary.starts_with("The screw's drag is ") && summary.contains(&reading), "{summary}");
        assert!(summary.contains("No effect beyond the level"), "{summary}");
    }
}

/// The calibrated full-film traction and boundary friction (first), the level factor: each's
/// `Calibrated` row.
fn calibrated<'r>(r: &'r Report, name: &str) -> &'r ballscrew_diagnose::Calibrated {
    r.calibration.iter().find(|c| c.name == name).unwrap_or_else(|| panic!("{name} calibrated"))
}

/// Data from the spec's own model with a full-film traction of 0.036 and a boundary friction of
/// 0.13 (the spec says 0.03 and 0.15), no hidden term, Gaussian noise of `noise` times each
/// torque, diagnosed against `spec`.
fn known_levels(spec: &ScrewSpec, seed: u64, noise: f64) -> Report {
    let mut truth = ScrewSpec::dkfzd4012();
    truth.lubricant.full_film_traction = TRACTION;
    truth.lubricant.boundary_friction = BOUNDARY;
    run_with(spec, &synth::generate_noisy(truth, seed, NONE, false, false, 1.0, noise))
}

/// See [`known_levels`].
const TRACTION: f64 = 0.036;
/// See [`known_levels`].
const BOUNDARY: f64 = 0.13;

/// The calibration's standard errors are those of the linearised least-squares fit at its
/// optimum: covariance `s^2 (J^T J)^-1`, `s^2 = RSS / (m - p)`, `J` the Jacobian of the
/// residuals (Seber & Wild, *Nonlinear Regression*, 1989, section 2.1; Press et al.,
/// *Numerical Recipes*, 3rd ed., 15.5-15.6), carried from the `ln` the fit works in to the
/// parameters by the delta method. On data of known full-film traction and boundary friction
/// ([`known_levels`], 384 rows, 3 % noise):
/// - the calibrated value +- its half-width `sqrt(3) se` contains the true value on at least
///   five of six seeds for each parameter (a normal estimate lies within 1.73 standard errors
///   92 % of the time). Measured: every seed but one for the traction, every seed for the
///   boundary friction; seed 31's traction is 4.1 standard errors off (0.0344 for 0.036), the
///   others within 1.5. (The noise is 3 % of each torque, not of one size on every row as the
///   formula takes: a heteroscedasticity-consistent "sandwich" estimate of the traction's error
///   is about 1.4 times this one on these data.)
/// - a quarter of the noise (the same normals) gives a quarter of the error (measured: 4.000;
///   asserted within 3.5-4.5): the residuals at the optimum scale with the noise, the Jacobian
///   does not.
/// - the calibrated spec carries that spread in its `[uncertainty]`, the other inputs the
///   input spec's.
#[test]
fn the_calibrations_standard_errors_contain_the_truth_and_scale_with_the_noise() {
    use ballscrew_core::input::uncertainty::index;
    let spec = ScrewSpec::dkfzd4012();
    let mut misses = [0, 0];
    for seed in [31, 33, 34, 35, 36, 37] {
        let r = known_levels(&spec, seed, synth::NOISE);
        let text = r.to_text();
        for (k, (name, value)) in [("full_film_traction", TRACTION), ("boundary_friction", BOUNDARY)].iter().enumerate()
        {
            let c = calibrated(&r, name);
            assert!(c.standard_error > 0.0 && c.standard_error_note.is_none(), "{name}: {c:?}\n{text}");
            assert!(text.contains(&format!("standard error {}", ballscrew_diagnose::text::sig(c.standard_error))));
            if (c.extended - value).abs() > c.half_width() {
                misses[k] += 1;
            }
        }
        let u = &r.extended_spec.uncertainty;
        assert_eq!(u.half_widths[index::FULL_FILM_TRACTION], calibrated(&r, "full_film_traction").half_width());
        assert_eq!(u.half_widths[index::BOUNDARY_FRICTION], calibrated(&r, "boundary_friction").half_width());
        for i in [index::PRELOAD, index::VISCOSITY, index::ROUGHNESS_RACEWAY] {
            assert_eq!(u.half_widths[i], spec.uncertainty.half_widths[i]);
        }
        let json = r.to_json();
        assert_eq!(
            json["calibration"][0]["standard_error"].as_f64(),
            Some(calibrated(&r, "full_film_traction").standard_error)
        );
        assert!(json["band_narrowing"]["width_ratio"].as_f64().is_some(), "{}", json["band_narrowing"]);
    }
    assert!(misses[0] <= 1 && misses[1] <= 1, "misses of six seeds: {misses:?}");
    // A quarter of the noise.
    let (loud, quiet) = (known_levels(&spec, 33, synth::NOISE), known_levels(&spec, 33, synth::NOISE / 4.0));
    for name in ["full_film_traction", "boundary_friction"] {
        let ratio = calibrated(&loud, name).standard_error / calibrated(&quiet, name).standard_error;
        assert!((3.5..4.5).contains(&ratio), "{name}: ratio of the standard errors {ratio}");
    }
}

/// The band of the drag torque at the data's median point, from the input spec's
/// `[uncertainty]` and from the calibrated spec's: with only the full-film traction and the
/// boundary friction spread (their default half-widths 0.015 and 0.05, every other input
/// pinned) the calibrated spec's band is a small part of the input spec's; with every default
/// spread, it is about as wide (the preload's +-30 %, the viscosity's, the roughnesses' spread
/// the band, and the data narrow none of them).
#[test]
fn the_calibrated_specs_band_is_narrower_than_the_input_specs() {
    use ballscrew_core::input::Uncertainty;
    use ballscrew_core::input::uncertainty::index;
    let mut spec = ScrewSpec::dkfzd4012();
    spec.uncertainty = Uncertainty::PINNED;
    for i in [index::FULL_FILM_TRACTION, index::BOUNDARY_FRICTION] {
        spec.uncertainty.half_widths[i] = Uncertainty::DEFAULT.half_widths[i];
    }
    let r = known_levels(&spec, 33, synth::NOISE);
    let b = &r.band_narrowing;
    let text = r.to_text();
    assert!(b.note.is_none() && b.width_ratio() < 0.2, "{b:?}\n{text}");
    assert!(b.spec_band.0 < b.spec_band.2 && b.calibrated_band.0 < b.calibrated_band.2, "{b:?}");
    assert_eq!((b.preload_n, b.speed_rpm, b.axial_load_n), (2000.0, 1000.0, 0.0));
    assert!(
        text.contains("Band of the drag torque (5-95 %, 128 samples, seed 0) at the data's median point"),
        "{text}"
    );
    let json = r.to_json();
    assert_eq!(json["band_narrowing"]["width_ratio"].as_f64(), Some(b.width_ratio()));
    assert_eq!(json["band_narrowing"]["spec_band"][0].as_f64(), Some(b.spec_band.0));
    // Every default spread: about as wide, a little narrower relative to its median.
    let r = known_levels(&ScrewSpec::dkfzd4012(), 33, synth::NOISE);
    let b = &r.band_narrowing;
    assert!((0.95..1.05).contains(&b.width_ratio()) && b.relative_width_ratio() < 1.0, "{b:?}");
}

/// A level beyond the full-film traction's physical range (data from a traction of 0.1, above
/// the fit's bound 0.08; a level factor of 1.05 and two terms take the rest) pins the
/// calibrated traction on its bound: it gets no standard error (NaN) and the note that the
/// fit's curvature there is not that of a quadratic minimum, and the calibrated spec keeps the
/// input spec's spread of it. The parameters off their bounds keep theirs (held there, the
/// bound parameter's errors are conditional on it).
#[test]
fn a_parameter_on_a_bound_of_its_fit_has_no_standard_error() {
    let mut truth = ScrewSpec::dkfzd4012();
    truth.lubricant.full_film_traction = 0.1;
    let r = run(&synth::generate_noisy(truth, 32, NONE, false, false, 1.0, 0.03));
    let text = r.to_text();
    let c = calibrated(&r, "full_film_traction");
    assert!((c.extended / c.fit_bounds.1 - 1.0).abs() < 1e-9, "{text}");
    assert!(c.standard_error.is_nan() && c.standard_error_note == Some(ballscrew_diagnose::model::ON_A_BOUND), "{c:?}");
    assert!(text.contains("standard error n/a (on a bound of its fit"), "{text}");
    assert!(r.to_json()["calibration"][0]["standard_error"].is_null());
    use ballscrew_core::input::uncertainty::index;
    let spread = |s: &ScrewSpec| s.uncertainty.half_widths[index::FULL_FILM_TRACTION];
    assert_eq!(spread(&r.extended_spec), spread(&ScrewSpec::dkfzd4012()));
    assert!(calibrated(&r, "boundary_friction").standard_error > 0.0, "{text}");
    // The creep reduction, chosen on a grid, has none either.
    assert!(calibrated(&r, "creep_reduction").standard_error.is_nan());
}
