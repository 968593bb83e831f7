//! The numbers the guide prints, checked against the model: the tables of "How the prediction
//! compares with the catalog" (`docs/prediction.md`: DKFZD4012 lubricated at 10-3000 rpm, and dry
//! at 100 rpm with each model option changed on its own) and the FASTSIM table of "Inside the
//! contact" (`docs/fastsim.md`), and the figures of their sentences. Each value must round to the
//! digits printed (within half a unit of the last digit), and the page must print it, so the
//! guide cannot drift from the model unnoticed: a change of the model that moves a printed number
//! fails here, and the page is then updated with it.

use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{
    ContactTheory, CreepCoefficientSource, LoadDistribution, Lubrication, Model, ModelOptions, OperatingPoint,
    ScrewSpec, SolverState, SpinMoment, Summary, TorqueRoute,
};

/// The preloads of the README's table, N.
const PRELOADS_N: [f64; 4] = [500.0, 1000.0, 2000.0, 3000.0];

/// The summary of DKFZD4012 with `options` at `preload_n`, 100 rpm, no axial load.
fn summary(options: ModelOptions, preload_n: f64) -> Summary {
    summary_at(options, preload_n, 100.0)
}

/// The summary of DKFZD4012 with `options` at `preload_n` and `speed_rpm`, no axial load.
fn summary_at(options: ModelOptions, preload_n: f64, speed_rpm: f64) -> Summary {
    let mut spec = ScrewSpec::dkfzd4012();
    spec.model = options;
    if options.lubrication == Lubrication::Dry {
        // The README's dry rows are the paper's model: no load between balls (as
        // configs/dkfzd4012-dry.toml), no ball train.
        spec.friction.ball_ball_load_n = Some(0.0);
    }
    let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(speed_rpm), preload_n, axial_load_n: 0.0 };
    Model::new(&spec).unwrap().summary(&op, &mut SolverState::new()).unwrap()
}

/// `value` rounds to `printed`, which has `decimals` decimals.
fn rounds_to(value: f64, printed: f64, decimals: i32) -> bool {
    (value - printed).abs() <= 0.5 * 10f64.powi(-decimals) * (1.0 + 1e-9)
}

/// The shipped spec of the XJTU screw (`configs/xjtu-32x8.toml`).
fn xjtu_spec() -> ScrewSpec {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/xjtu-32x8.toml");
    ballscrew_config::spec_from_toml_str(&std::fs::read_to_string(path).unwrap(), "xjtu-32x8.toml").unwrap()
}

/// The text of a page of the guide.
fn page(name: &str) -> String {
    std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs").join(name)).unwrap()
}

/// `page` prints `cells` as consecutive cells of a table row.
fn assert_row(page_name: &str, cells: &[String]) {
    let row = format!("| {} |", cells.join(" | "));
    // Bold cells (`**0.0118**`) print the same number.
    assert!(page(page_name).replace("**", "").contains(&row), "docs/{page_name} does not print the row `{row}`");
}

fn check_row(label: &str, options: ModelOptions, printed: [f64; 4], decimals: i32, get: fn(&Summary) -> f64) {
    let cells: Vec<String> = printed.iter().map(|p| format!("{p:.*}", decimals as usize)).collect();
    assert_row("prediction.md", &cells);
    for (&fp, &p) in PRELOADS_N.iter().zip(&printed) {
        let v = get(&summary(options, fp));
        assert!(rounds_to(v, p, decimals), "README row `{label}` at {fp} N prints {p}, the model gives {v}");
    }
}

#[test]
fn readme_catalog_comparison_table() {
    // The paper's dry contacts (`lubrication = "dry"`): these are the numbers the model gave
    // before the lubricant, so this table is also the test that the dry option reproduces them.
    let d = ModelOptions::dry();
    let torque = |s: &Summary| s.torque_nm;
    check_row("default (decided reading)", d, [0.0118, 0.0238, 0.0480, 0.0730], 4, torque);
    let eq27 = ModelOptions { torque: TorqueRoute::PaperEq27, ..d };
    check_row("torque = paper-eq27", eq27, [0.2183, 0.4080, 0.7446, 1.0457], 4, torque);
    let literal = ModelOptions { load_distribution: LoadDistribution::PaperLiteral, ..d };
    check_row("load_distribution = paper-literal", literal, [0.0071, 0.0143, 0.0288, 0.0436], 4, torque);
    let uniform = ModelOptions { load_distribution: LoadDistribution::Uniform, ..d };
    check_row("load_distribution = uniform", uniform, [0.0118, 0.0237, 0.0478, 0.0725], 4, torque);
    let fit = ModelOptions { creep_coefficients: CreepCoefficientSource::PaperFit, ..d };
    check_row("creep_coefficients = paper-fit", fit, [0.0119, 0.0240, 0.0486, 0.0740], 4, torque);
    let no_heathcote = ModelOptions { heathcote: false, ..d };
    check_row("heathcote = false", no_heathcote, [0.0118, 0.0238, 0.0481, 0.0731], 4, torque);
    let separate = ModelOptions { spin_moment: SpinMoment::Separate, ..d };
    check_row("spin_moment = separate", separate, [0.0150, 0.0315, 0.0668, 0.1042], 4, torque);
    assert_eq!(ModelOptions::paper_literal().lubrication, d.lubrication);
    let all = ModelOptions::paper_literal();
    check_row("all paper-literal options", all, [0.1526, 0.3052, 0.6102, 0.9152], 4, torque);
    check_row("all paper-literal options, energy route", all, [0.0089, 0.0188, 0.0397, 0.0619], 4, |s| {
        s.torque_energy_nm
    });
    check_row("catalog estimate", d, [0.1545, 0.3090, 0.6180, 0.9271], 4, |s| s.catalog_nm);
}

/// The lubricated table: DKFZD4012 with the default oil at 10-3000 rpm, torque and its ratio to
/// the catalog estimate, and the claims of the text beside it.
#[test]
fn readme_lubricated_table() {
    let d = ModelOptions::default();
    let printed: [(f64, [(f64, f64); 4]); 4] = [
        (500.0, [(0.0580, 0.38), (0.0596, 0.39), (0.1565, 1.01), (0.3053, 1.98)]),
        (1000.0, [(0.1147, 0.37), (0.1012, 0.33), (0.2149, 0.70), (0.4078, 1.32)]),
        (2000.0, [(0.2315, 0.37), (0.1811, 0.29), (0.3017, 0.49), (0.5507, 0.89)]),
        (3000.0, [(0.3522, 0.38), (0.2606, 0.28), (0.3731, 0.40), (0.6614, 0.71)]),
    ];
    for (fp, row) in printed {
        let mut cells = vec![format!("{fp} N")];
        cells.extend(row.iter().map(|(t, ratio)| format!("{t:.4} ({ratio:.2})")));
        assert_row("prediction.md", &cells);
        for (rpm, (t, ratio)) in [10.0, 100.0, 1000.0, 3000.0].into_iter().zip(row) {
            let s = summary_at(d, fp, rpm);
            assert!(rounds_to(s.torque_nm, t, 4), "{fp} N {rpm} rpm: README {t}, model {}", s.torque_nm);
            assert!(rounds_to(s.catalog_ratio(), ratio, 2), "{fp} N {rpm} rpm: ratio {}", s.catalog_ratio());
        }
        // "90 % of it at 3000 rpm and 2000 N"; "hysteresis under 1 %".
        let s = summary_at(d, fp, 3000.0);
        if fp == 2000.0 {
            let share = s.rolling_resistance_torque_nm / s.torque_nm;
            assert!(rounds_to(share, 0.90, 2), "{share}");
        }
        assert!(s.hysteresis_torque_nm < 0.01 * s.torque_nm);
    }
}

#[test]
fn readme_fastsim_table_and_its_claims() {
    let linear = ModelOptions::dry();
    let fastsim = ModelOptions { contact_theory: ContactTheory::Fastsim, ..linear };
    for (fp, printed_linear, printed_fastsim) in
        [(500.0, 0.01184, 0.01217), (2000.0, 0.04803, 0.05017), (3000.0, 0.07298, 0.07651)]
    {
        let cells: Vec<String> = [0.01184, 0.04803, 0.07298].iter().map(|v| format!("{v:.5}")).collect();
        assert_row("fastsim.md", &cells[..]);
        let cells: Vec<String> = [0.01217, 0.05017, 0.07651].iter().map(|v| format!("{v:.5}")).collect();
        assert_row("fastsim.md", &cells[..]);
        let l = summary(linear, fp).torque_nm;
        let f = summary(fastsim, fp).torque_nm;
        assert!(rounds_to(l, printed_linear, 5), "{fp} N: linear-saturated {l}, README {printed_linear}");
        assert!(rounds_to(f, printed_fastsim, 5), "{fp} N: FASTSIM {f}, README {printed_fastsim}");
        // "FASTSIM lies 3-5 % above the saturated linear theory"
        let above = f / l - 1.0;
        assert!((0.025..0.055).contains(&above), "{fp} N: FASTSIM {:.2} % above", 100.0 * above);
        // "(grid 40 changes it by under 0.1 %)"
        let fine = summary(ModelOptions { fastsim_grid: 40, ..fastsim }, fp).torque_nm;
        assert!((fine / f - 1.0).abs() < 1e-3, "{fp} N: grid 40 {fine} vs grid 20 {f}");
    }
}

/// The ball train's figures in docs/prediction.md and the model notes ("The ball train"): on DKFZD4012
/// (internal return, the default wall friction) it adds under 0.3 % to the drag at 10-100 rpm
/// and 1.1-2.0 % at 3000 rpm over 500-2000 N, against the same screw without load between
/// balls; the return's resistance is 0.5 mN at rest and at 100 rpm, 21 mN at 3000 rpm.
#[test]
fn readme_ball_train_figures() {
    let drag = |spec: &ScrewSpec, fp: f64, rpm: f64| {
        let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: fp, axial_load_n: 0.0 };
        Model::new(spec).unwrap().summary(&op, &mut SolverState::new()).unwrap().torque_nm
    };
    let train = ScrewSpec::dkfzd4012();
    let mut none = train;
    none.friction.ball_ball_load_n = Some(0.0);
    for fp in [500.0, 2000.0] {
        for rpm in [10.0, 100.0, 3000.0] {
            let added = drag(&train, fp, rpm) / drag(&none, fp, rpm) - 1.0;
            let (lo, hi) = if rpm < 1000.0 { (0.0, 0.003) } else { (0.0105, 0.0205) };
            assert!(added > lo && added < hi, "{fp} N {rpm} rpm: {added}");
        }
    }
    let g = &train.geometry;
    let r = |rpm: f64| ballscrew_core::input::circulation::return_resistance_n(g, 2, 0.03, rpm_to_rad_s(rpm));
    assert!(rounds_to(r(0.0) * 1e3, 0.5, 1) && rounds_to(r(100.0) * 1e3, 0.5, 1), "{} {}", r(0.0), r(100.0));
    assert!(rounds_to(r(3000.0) * 1e3, 21.0, 0), "{}", r(3000.0));
    let text = page("prediction.md").split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        text.contains("under 0.3 % at 10-100 rpm and 1.1-2.0 % at 3000 rpm"),
        "docs/prediction.md's train sentence"
    );
}

/// The oil-temperature sentence of docs/prediction.md: from 40 to 60 C the drag of DKFZD4012 falls 27-39 % at
/// 1000-3000 rpm over 500-3000 N, and changes by -6 to +14 % at 10-100 rpm, rising at 10 rpm and
/// at the heavier preloads.
#[test]
fn readme_oil_temperature_sentence() {
    let drag = |temperature_c: f64, fp: f64, rpm: f64| {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.lubricant.temperature_c = temperature_c;
        let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: fp, axial_load_n: 0.0 };
        Model::new(&spec).unwrap().summary(&op, &mut SolverState::new()).unwrap().torque_nm
    };
    let (mut fast, mut slow) = ((f64::INFINITY, f64::NEG_INFINITY), (f64::INFINITY, f64::NEG_INFINITY));
    for fp in [500.0, 1000.0, 2000.0, 3000.0] {
        for rpm in [10.0, 100.0, 1000.0, 3000.0] {
            let change = drag(60.0, fp, rpm) / drag(40.0, fp, rpm) - 1.0;
            let range = if rpm >= 1000.0 { &mut fast } else { &mut slow };
            *range = (range.0.min(change), range.1.max(change));
            if rpm == 10.0 || fp >= 2000.0 && rpm == 100.0 {
                assert!(change > 0.0, "{fp} N {rpm} rpm: {change}");
            }
        }
    }
    assert!(rounds_to(-100.0 * fast.1, 27.0, 0) && rounds_to(-100.0 * fast.0, 39.0, 0), "{fast:?}");
    assert!(rounds_to(100.0 * slow.0, -6.0, 0) && rounds_to(100.0 * slow.1, 14.0, 0), "{slow:?}");
    let text = page("prediction.md").split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        text.contains("falls 27-39 % at 1000-3000 rpm") && text.contains("by -6 to +14 %"),
        "docs/prediction.md's sentence"
    );
}

/// The table and sentences of "Circuits of several loaded turns" (docs/prediction.md):
/// DKFZD4012 with an external return at 10-3000 rpm and 500-3000 N, each cell's drag and ratio
/// to the catalog (or no steady state of the train); 0.40-0.52 of the catalog at 10-100 rpm
/// against the internal return's 0.28-0.39; the ball-ball share 18-36 % at 100 rpm, rising with
/// the preload from 1000 N up; 4-9 % added at 1000 rpm; the XJTU screw's 0.1339 N m.
#[test]
fn several_turns_per_circuit_table_and_sentences() {
    use ballscrew_core::Error;
    use ballscrew_core::input::circulation::Return;
    let op = |fp: f64, rpm: f64| OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: fp, axial_load_n: 0.0 };
    let internal = Model::new(&ScrewSpec::dkfzd4012()).unwrap();
    let mut spec = ScrewSpec::dkfzd4012();
    spec.circulation.kind = Return::External;
    let external = Model::new(&spec).unwrap();
    let (mut ratio_lo, mut ratio_hi) = (f64::INFINITY, 0.0_f64);
    let (mut internal_lo, mut internal_hi) = (f64::INFINITY, 0.0_f64);
    let (mut share_lo, mut share_hi, mut last_share) = (f64::INFINITY, 0.0_f64, 0.0);
    let (mut added_lo, mut added_hi) = (f64::INFINITY, 0.0_f64);
    for fp in PRELOADS_N {
        let mut cells = vec![format!("{fp:.0} N")];
        for rpm in [10.0, 100.0, 1000.0, 3000.0] {
            let base = internal.summary(&op(fp, rpm), &mut SolverState::new()).unwrap();
            match external.summary(&op(fp, rpm), &mut SolverState::new()) {
                Ok(s) => {
                    let ratio = s.torque_nm / s.catalog_nm;
                    cells.push(format!("{:.4} ({:.2})", s.torque_nm, ratio));
                    if rpm <= 100.0 {
                        (ratio_lo, ratio_hi) = (ratio_lo.min(ratio), ratio_hi.max(ratio));
                        let r = base.torque_nm / base.catalog_nm;
                        (internal_lo, internal_hi) = (internal_lo.min(r), internal_hi.max(r));
                    }
                    if rpm == 100.0 {
                        let share = s.ball_ball_torque_nm / s.torque_nm;
                        assert!(fp <= 1000.0 || share > last_share, "{fp} N: the share {share} does not rise");
                        last_share = share;
                        (share_lo, share_hi) = (share_lo.min(share), share_hi.max(share));
                    }
                    if rpm == 1000.0 {
                        let added = s.torque_nm / base.torque_nm - 1.0;
                        (added_lo, added_hi) = (added_lo.min(added), added_hi.max(added));
                    }
                }
                Err(Error::NoSteadyTrain { .. }) => cells.push("no steady state".into()),
                Err(e) => panic!("{fp} N {rpm} rpm: {e}"),
            }
        }
        assert_row("prediction.md", &cells);
    }
    assert!(rounds_to(ratio_lo, 0.40, 2) && rounds_to(ratio_hi, 0.52, 2), "{ratio_lo} {ratio_hi}");
    assert!(rounds_to(internal_lo, 0.28, 2) && rounds_to(internal_hi, 0.39, 2), "{internal_lo} {internal_hi}");
    assert!(rounds_to(share_lo * 100.0, 18.0, 0) && rounds_to(share_hi * 100.0, 36.0, 0), "{share_lo} {share_hi}");
    assert!(rounds_to(added_lo * 100.0, 4.0, 0) && rounds_to(added_hi * 100.0, 9.0, 0), "{added_lo} {added_hi}");
    let mut xjtu = xjtu_spec();
    xjtu.circulation.kind = Return::External;
    let x = Model::new(&xjtu).unwrap().summary(&op(1500.0, 300.0), &mut SolverState::new()).unwrap();
    assert!(rounds_to(x.torque_nm, 0.1339, 4), "{}", x.torque_nm);
    let text = page("prediction.md").split_whitespace().collect::<Vec<_>>().join(" ");
    for claim in [
        "the train lifts the drag to 0.40-0.52 of the catalog there",
        "internal return's 0.28-0.39 at 10-100 rpm",
        "carry 18-36 % of the drag at 100 rpm",
        "the train adds 4-9 %",
        "gives 0.1339 N m at its measured point",
    ] {
        assert!(text.contains(claim), "docs/prediction.md: `{claim}`");
    }
}

/// The table and sentences of "A stated lead deviation" (docs/prediction.md): DKFZD4012 at
/// 100 rpm with the internal and the external return, without a deviation and with ISO 3408-3
/// class 5's 23 um over 300 mm in proportion to its 36 mm of loaded length (2.76 um) either
/// way; the XJTU screw at its measured point with 23 um x 16 / 300 (1.23 um).
#[test]
fn lead_deviation_table_and_sentences() {
    use ballscrew_core::Error;
    use ballscrew_core::input::circulation::Return;
    let op = |fp: f64, rpm: f64| OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: fp, axial_load_n: 0.0 };
    let deviation_m = 23e-6 * 36.0 / 300.0;
    let model = |kind: Return, d: f64| {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.circulation.kind = kind;
        spec.circulation.lead_deviation_m = d;
        Model::new(&spec).unwrap()
    };
    let models: Vec<Model> = [Return::Internal, Return::External]
        .into_iter()
        .flat_map(|kind| [0.0, deviation_m, -deviation_m].map(|d| model(kind, d)))
        .collect();
    // The largest rise and fall against the same return without a deviation.
    let (mut rise, mut fall) = (0.0_f64, 0.0_f64);
    for fp in PRELOADS_N {
        let mut cells = vec![format!("{fp:.0} N")];
        let mut base = f64::NAN;
        for (k, m) in models.iter().enumerate() {
            match m.summary(&op(fp, 100.0), &mut SolverState::new()) {
                Ok(s) => {
                    cells.push(format!("{:.4} ({:.2})", s.torque_nm, s.torque_nm / s.catalog_nm));
                    if k % 3 == 0 {
                        base = s.torque_nm;
                    } else {
                        (rise, fall) = (rise.max(s.torque_nm / base - 1.0), fall.max(1.0 - s.torque_nm / base));
                    }
                }
                Err(Error::NoSteadyTrain { .. }) => cells.push("no steady state".into()),
                Err(e) => panic!("{fp} N: {e}"),
            }
        }
        assert_row("prediction.md", &cells);
    }
    let xjtu = xjtu_spec();
    let at = |kind: Return, d: f64| {
        let mut spec = xjtu;
        spec.circulation.kind = kind;
        spec.circulation.lead_deviation_m = d;
        Model::new(&spec).unwrap().summary(&op(1500.0, 300.0), &mut SolverState::new()).unwrap().torque_nm
    };
    let d = 23e-6 * 16.0 / 300.0;
    let (ext, int) =
        ([at(Return::External, d), at(Return::External, -d)], [at(Return::Internal, -d), at(Return::Internal, d)]);
    let (ext_lo, ext_hi) = (ext[0].min(ext[1]), ext[0].max(ext[1]));
    let (int_lo, int_hi) = (int[0].min(int[1]), int[0].max(int[1]));
    assert!(rounds_to(ext_lo, 0.1295, 4) && rounds_to(ext_hi, 0.1332, 4), "{ext:?}");
    assert!(rounds_to(int_lo, 0.1009, 4) && rounds_to(int_hi, 0.1019, 4), "{int:?}");
    assert!(rounds_to(at(Return::Internal, 0.0), 0.1016, 4));
    rise = rise.max(int_hi / at(Return::Internal, 0.0) - 1.0).max(ext_hi / at(Return::External, 0.0) - 1.0);
    assert!(rise > 0.0 && rise < 0.003, "{rise}");
    assert!(rounds_to(fall * 100.0, 21.0, 0), "{fall}");
    let text = page("prediction.md").split_whitespace().collect::<Vec<_>>().join(" ");
    for claim in [
        "the length between DKFZD4012's first and last circle (3 leads, 36 mm) that is 2.76 um",
        "raises the drag by at most 0.3 % here (and at the XJTU point below) and lowers it by up to 21 %",
        "gives 0.1295 and 0.1332 N m with the external return (0.1339 without) and 0.1009 and 0.1019 N m with the internal one (0.1016)",
    ] {
        assert!(text.contains(claim), "docs/prediction.md: `{claim}`");
    }
}

/// docs/prediction.md, "A stated load ramp": the table of DKFZD4012 with ramps of 0, 2 and 4
/// balls at 10 and 100 rpm, the rises it states, and the XJTU screw at its measured point.
#[test]
fn load_ramp_table_and_sentences() {
    use ballscrew_core::Error;
    use ballscrew_core::input::circulation::Return;
    let op = |fp: f64, rpm: f64| OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n: fp, axial_load_n: 0.0 };
    let model = |balls: u32| {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.circulation.load_ramp_balls = balls;
        Model::new(&spec).unwrap()
    };
    let models = [model(0), model(2), model(4)];
    // The smallest and largest rise against no ramp, at 10 and at 100 rpm.
    let mut rises = [(f64::INFINITY, 0.0_f64); 2];
    for fp in PRELOADS_N {
        let mut cells = vec![format!("{fp:.0} N")];
        for (k, rpm) in [10.0, 100.0].into_iter().enumerate() {
            let mut base = f64::NAN;
            for (j, m) in models.iter().enumerate() {
                match m.summary(&op(fp, rpm), &mut SolverState::new()) {
                    Ok(s) => {
                        cells.push(format!("{:.4} ({:.2})", s.torque_nm, s.torque_nm / s.catalog_nm));
                        if j == 0 {
                            base = s.torque_nm;
                        } else {
                            let r = s.torque_nm / base - 1.0;
                            rises[k] = (rises[k].0.min(r), rises[k].1.max(r));
                        }
                    }
                    Err(Error::NoSteadyTrain { .. }) => cells.push("no steady state".into()),
                    Err(e) => panic!("{fp} N, {rpm} rpm: {e}"),
                }
            }
        }
        assert_row("prediction.md", &cells);
    }
    // "The more the heavier the preload": at 10 rpm each ramp's rise at 3000 N above its rise
    // at 500 N.
    for m in &models[1..] {
        let rise = |fp: f64| {
            let t = |m: &Model| m.summary(&op(fp, 10.0), &mut SolverState::new()).unwrap().torque_nm;
            t(m) / t(&models[0]) - 1.0
        };
        assert!(rise(3000.0) > rise(500.0));
    }
    let pct = |r: (f64, f64)| (format!("{:.0}", r.0 * 100.0), format!("{:.0}", r.1 * 100.0));
    let (a, b) = (pct(rises[0]), pct(rises[1]));
    let rise = format!("raises the drag by {}-{} % at 10 rpm and by {}-{} % at 100 rpm", a.0, a.1, b.0, b.1);
    for fp in PRELOADS_N {
        for m in &models[1..] {
            for rpm in [1000.0, 3000.0] {
                assert!(matches!(m.summary(&op(fp, rpm), &mut SolverState::new()), Err(Error::NoSteadyTrain { .. })));
            }
        }
    }
    let xjtu = xjtu_spec();
    let at = |kind: Return, balls: u32| {
        let mut spec = xjtu;
        spec.circulation.kind = kind;
        spec.circulation.load_ramp_balls = balls;
        Model::new(&spec).unwrap().summary(&op(1500.0, 300.0), &mut SolverState::new()).map(|s| s.torque_nm)
    };
    assert!(rounds_to(at(Return::Internal, 0).unwrap(), 0.1016, 4));
    assert!(rounds_to(at(Return::Internal, 3).unwrap(), 0.1167, 4));
    for balls in [1, 2, 4] {
        assert!(matches!(at(Return::Internal, balls), Err(Error::NoSteadyTrain { .. })), "{balls}");
    }
    let ext: Vec<f64> = (1..=4).map(|b| at(Return::External, b).unwrap()).collect();
    let (lo, hi) = ext.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), &t| (lo.min(t), hi.max(t)));
    assert!(rounds_to(lo, 0.1365, 4) && rounds_to(hi, 0.1368, 4), "{ext:?}");
    assert!(rounds_to(at(Return::External, 0).unwrap(), 0.1339, 4));
    let text = page("prediction.md").split_whitespace().collect::<Vec<_>>().join(" ");
    for claim in [
        rise.as_str(),
        "At 1000 rpm and above none of these points has a steady train.",
        "gives 0.1167 N m with a ramp of 3 balls and the internal return (0.1016 without; with 1, 2 or 4 balls no steady train there) and 0.1365-0.1368 N m with 1 to 4 balls and the external return (0.1339 without)",
    ] {
        assert!(text.contains(claim), "docs/prediction.md: `{claim}`");
    }
}
