//! Runs the built `ballscrew` binary.

mod common;

use common::{ballscrew, fails, ok_quiet as ok};
use serde_json::Value;
use std::path::{Path, PathBuf};

const BUILTIN: &str = include_str!("../../../configs/dkfzd4012.toml");

fn json(text: &str) -> Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("{e}: {text}"))
}

/// A spec file in `dir` from the built-in text with `from` replaced by `to`.
fn spec_file(dir: &Path, from: &str, to: &str) -> PathBuf {
    assert!(BUILTIN.contains(from), "{from}");
    let path = dir.join("spec.toml");
    std::fs::write(&path, BUILTIN.replacen(from, to, 1)).unwrap();
    path
}

/// Parses CSV of plain fields (no quoting) into a header and rows of numbers; an empty field
/// (an undefined number, n/a) is NaN.
fn csv_numbers(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(str::to_string).collect::<Vec<_>>();
    let number = |f: &str| if f.is_empty() { f64::NAN } else { f.parse().unwrap() };
    let rows: Vec<Vec<f64>> = lines.map(|l| l.split(',').map(number).collect()).collect();
    assert!(rows.iter().all(|r| r.len() == header.len()));
    (header, rows)
}

fn column(header: &[String], rows: &[Vec<f64>], key: &str) -> Vec<f64> {
    let i = header.iter().position(|h| h == key).unwrap_or_else(|| panic!("no column {key}"));
    rows.iter().map(|r| r[i]).collect()
}

#[test]
fn sweep_default_table_has_26_rising_rows() {
    let out = ok(&["sweep"]);
    let lines: Vec<&str> = out.lines().collect();
    assert!(lines[0].contains("DKFZD4012") && lines[0].contains("100 rpm"), "{}", lines[0]);
    assert!(out.contains("[N m]") && out.contains("[N]"), "units in the header");
    let rows: Vec<Vec<f64>> = lines
        .iter()
        .filter(|l| l.split_whitespace().next().is_some_and(|w| w.parse::<f64>().is_ok()))
        .map(|l| l.split_whitespace().map(|w| if w == "n/a" { f64::NAN } else { w.parse().unwrap() }).collect())
        .collect();
    assert_eq!(rows.len(), 26);
    assert_eq!((rows[0][0], rows[25][0]), (500.0, 3000.0));
    assert!(rows.windows(2).all(|w| w[1][1] > w[0][1]), "torque rises with preload");
    assert!(lines.last().unwrap().contains("catalog band"), "{}", lines.last().unwrap());
}

#[test]
fn sweep_csv_parses_and_matches_catalog() {
    let (header, rows) = csv_numbers(&ok(&["sweep", "--format", "csv"]));
    // The swept preload, then the operating point held (every row names its whole point).
    assert_eq!(header[..5], ["preload_n", "speed_rpm", "axial_load_n", "oil_temperature_c", "torque_nm"]);
    assert_eq!(rows.len(), 26);
    assert!(rows.iter().all(|r| r[1..4] == [100.0, 0.0, 40.0]), "the spec's speed, axial load and oil");
    let catalog = column(&header, &rows, "catalog_nm");
    // docs/reference/catalog_drag_torque.csv: 500 N -> 0.1545 N m, 3000 N -> 0.9271 N m.
    assert!((catalog[0] - 0.1545).abs() < 5e-5 && (catalog[25] - 0.9271).abs() < 5e-5);
    let (low, high) = (column(&header, &rows, "catalog_low_nm"), column(&header, &rows, "catalog_high_nm"));
    assert!(low.iter().zip(&high).zip(&catalog).all(|((l, h), c)| l < c && c < h));
    let torque = column(&header, &rows, "torque_nm");
    let ratio = column(&header, &rows, "ratio");
    assert!(torque.iter().zip(&catalog).zip(&ratio).all(|((t, c), r)| (t / c - r).abs() < 1e-12));
}

#[test]
fn sweep_json_parses_with_full_precision() {
    let v = json(&ok(&["sweep", "--format", "json", "--preload", "1000..2000", "--step", "250"]));
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 5);
    assert_eq!(v["command"], "sweep");
    assert_eq!(v["torque_route"], "energy");
    let (header, csv_rows) =
        csv_numbers(&ok(&["sweep", "--format", "csv", "--preload", "1000..2000", "--step", "250"]));
    let csv_torque = column(&header, &csv_rows, "torque_nm");
    for (row, t) in rows.iter().zip(&csv_torque) {
        // Same digits in both formats: nothing lost to formatting.
        assert_eq!(row["torque_nm"].as_f64().unwrap(), *t);
        assert!(row["iterations"].as_u64().unwrap() > 0);
    }
}

/// `--preload-n` and `--step-n` (units in the flag, as everywhere else) are the same flags as
/// `--preload` and `--step`.
#[test]
fn sweep_flags_with_units_are_aliases() {
    let short = ok(&["sweep", "--preload", "500..1500", "--step", "500", "--format", "csv"]);
    let with_units = ok(&["sweep", "--preload-n", "500..1500", "--step-n", "500", "--format", "csv"]);
    assert_eq!(short, with_units);
    assert_eq!(short.lines().count(), 4, "{short}");
    assert!(fails(&["sweep", "--step-n", "0"], 2).contains("invalid --step-n: 0 N"));
}

#[test]
fn sweep_single_value_and_uneven_step() {
    let (_, rows) = csv_numbers(&ok(&["sweep", "--preload", "1500", "--format", "csv"]));
    assert_eq!(rows.len(), 1);
    let (header, rows) = csv_numbers(&ok(&["sweep", "--preload", "500..800", "--step", "200", "--format", "csv"]));
    assert_eq!(column(&header, &rows, "preload_n"), [500.0, 700.0, 800.0]);
}

#[test]
fn torque_reports_every_route() {
    let v = json(&ok(&["torque", "--format", "json"]));
    for key in
        ["torque_nm", "torque_energy_nm", "torque_moment_nm", "torque_eq27_nm", "catalog_nm", "dissipation_torque_nm"]
    {
        assert!(v[key].as_f64().is_some_and(f64::is_finite), "{key}: {v}");
    }
    assert_eq!(v["preload_n"], 2000.0);
    assert!((v["speed_rpm"].as_f64().unwrap() - 100.0).abs() < 1e-9);
    let t = v["torque_nm"].as_f64().unwrap();
    assert!(t > 0.0);
    let table = ok(&["torque"]);
    assert!(table.contains("Eq. 27") && table.contains("catalog estimate"), "{table}");
}

#[test]
fn negative_speed_gives_negative_torque() {
    let torque = |speed: &str| {
        let v = json(&ok(&["torque", "--format", "json", "--speed-rpm", speed]));
        v["torque_nm"].as_f64().unwrap()
    };
    let (fwd, rev) = (torque("100"), torque("-100"));
    assert!(fwd > 0.0 && rev < 0.0, "{fwd} {rev}");
    assert!((fwd + rev).abs() < 1e-9 * fwd, "{fwd} {rev}");
}

#[test]
fn inspect_json_has_2_nuts_4_circles_3_contacts() {
    let v = json(&ok(&["inspect", "--format", "json"]));
    let nuts = v["nuts"].as_array().unwrap();
    assert_eq!(nuts.len(), 2);
    for nut in nuts {
        let circles = nut["circles"].as_array().unwrap();
        assert_eq!(circles.len(), 4);
        for c in circles {
            let contacts = c["contacts"].as_array().unwrap();
            let kinds: Vec<&str> = contacts.iter().map(|k| k["contact"].as_str().unwrap()).collect();
            assert_eq!(kinds, ["nut", "screw", "ball-ball"]);
            assert!(c["residual"].as_f64().unwrap() < 1e-9);
            assert!(contacts[0]["normal_load_n"].as_f64().unwrap() > 0.0);
            assert!(contacts[0]["peak_pressure_mpa"].as_f64().unwrap() > 100.0);
        }
    }
    // The shares of all contacts and the return path's add up to the dissipation torque.
    let shares: f64 = nuts
        .iter()
        .flat_map(|n| n["circles"].as_array().unwrap())
        .flat_map(|c| c["contacts"].as_array().unwrap())
        .map(|k| k["torque_share_nm"].as_f64().unwrap())
        .sum::<f64>()
        + v["torque"]["return_torque_nm"].as_f64().unwrap();
    let d = v["torque"]["dissipation_torque_nm"].as_f64().unwrap();
    assert!((shares - d).abs() < 1e-9 * d.abs(), "{shares} vs {d}");
}

#[test]
fn inspect_csv_has_a_row_per_contact_and_table_groups() {
    let text = ok(&["inspect", "--format", "csv"]);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 1 + 2 * 4 * 3);
    let header: Vec<&str> = lines[0].split(',').collect();
    assert!(header.starts_with(&["nut", "circle"]) && header.contains(&"contact"));
    assert!(lines[1..].iter().all(|l| l.split(',').count() == header.len()));
    let table = ok(&["inspect"]);
    assert!(table.contains("nut 2, circle 4") && table.contains("torque summary"));
    for unit in ["MPa", "um", "mm", "1/m", "deg"] {
        assert!(table.contains(unit), "{unit}");
    }
}

#[test]
fn out_writes_file_and_failure_leaves_none() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("sweep.csv");
    let p = path.to_str().unwrap();
    let printed = ok(&["sweep", "--format", "csv", "--out", p]);
    assert!(printed.is_empty());
    let (_, rows) = csv_numbers(&std::fs::read_to_string(&path).unwrap());
    assert_eq!(rows.len(), 26);

    let bad_spec = spec_file(dir.path(), "lead_mm = 12.0", "lead_mm = -12.0");
    let failed = dir.path().join("failed.csv");
    fails(&["sweep", "--spec", bad_spec.to_str().unwrap(), "--out", failed.to_str().unwrap()], 2);
    fails(&["sweep", "--speed-rpm", "nan", "--out", failed.to_str().unwrap()], 2);
    assert!(!failed.exists());
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names.len(), 2, "no temporary files left: {names:?}");
}

#[test]
fn spec_file_unknown_key_names_key_and_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = spec_file(dir.path(), "pitch_diameter_mm = 40.0", "pitch_mm = 40.0");
    let line = BUILTIN.lines().position(|l| l.starts_with("pitch_diameter_mm")).unwrap() + 1;
    let e = fails(&["torque", "--spec", path.to_str().unwrap()], 2);
    assert!(e.contains(&format!("spec.toml:{line}:1: unknown field `pitch_mm`")), "{e}");
}

#[test]
fn spec_file_errors() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("missing.toml");
    let e = fails(&["torque", "--spec", missing.to_str().unwrap()], 2);
    assert!(e.contains("missing.toml"), "{e}");
    let path = spec_file(dir.path(), "conformity_nut = 0.52", "conformity_nut = 0.5");
    let e = fails(&["sweep", "--spec", path.to_str().unwrap()], 2);
    assert!(e.contains("geometry.conformity_nut: 0.5 (valid: [0.501, 0.6])"), "{e}");
    let path = spec_file(dir.path(), "contact_angle_deg = 45.0", "contact_angle_deg = 90");
    let e = fails(&["inspect", "--spec", path.to_str().unwrap()], 2);
    assert!(e.contains("geometry.contact_angle_deg: 90 (valid: [20, 70])"), "{e}");
}

#[test]
fn spec_file_drives_the_model() {
    let dir = tempfile::tempdir().unwrap();
    let path = spec_file(dir.path(), "preload_n = 2000.0", "preload_n = 1000.0");
    let v = json(&ok(&["torque", "--format", "json", "--spec", path.to_str().unwrap()]));
    assert_eq!(v["preload_n"], 1000.0);
    assert!(v["spec"].as_str().unwrap().ends_with("spec.toml"));
    let path = spec_file(dir.path(), "torque = \"energy\"", "torque = \"paper-eq27\"");
    let v = json(&ok(&["torque", "--format", "json", "--spec", path.to_str().unwrap()]));
    assert_eq!(v["torque_nm"], v["torque_eq27_nm"]);
    assert_eq!(v["torque_route"], "paper-eq27");
}

#[test]
fn invalid_flags_exit_2_naming_flag_value_and_range() {
    let cases: &[(&[&str], &str)] = &[
        (&["torque", "--speed-rpm", "nan"], "invalid --speed-rpm: NaN (valid: finite, |speed| <= 30000 rpm)"),
        (&["sweep", "--speed-rpm", "1e9"], "invalid --speed-rpm: 1e9 (valid:"),
        (&["inspect", "--preload-n", "-5"], "invalid --preload-n: -5 N (valid:"),
        (&["torque", "--axial-load-n", "inf"], "invalid --axial-load-n: inf (valid:"),
        // A flag is named as typed: its alias where one was typed.
        (&["sweep", "--preload", "3000..500"], "invalid --preload: 3000..500"),
        (&["sweep", "--preload-n", "3000..500"], "invalid --preload-n: 3000..500"),
        (&["sweep", "--preload", "-100..500"], "invalid --preload: -100 N (valid:"),
        (&["sweep", "--preload", "five"], "invalid --preload: five"),
        (&["sweep", "--step", "0"], "invalid --step: 0 N (valid: finite and > 0 N)"),
        (&["sweep", "--step=-10"], "invalid --step: -10 N"),
        (&["sweep", "--preload-step-n", "0"], "invalid --preload-step-n: 0 N"),
        (&["sweep", "--preload", "0..1e7", "--step", "1"], "more than"),
        (
            &["sweep", "--preload", "0..1", "--step", "1e-300"],
            "--preload 0..1 with --step 1e-300 gives more than 100000 points",
        ),
        (
            &["sweep", "--preload-n", "0..1", "--step-n", "1e-300"],
            "--preload-n 0..1 with --step-n 1e-300 gives more than",
        ),
        (&["map", "--preload", "5000000"], "invalid --preload: 5000000"),
        // The grid's own limits name the flag that sets them, not the core's field (map.speed_step).
        (&["map", "--speed-rpm", "1..1.0000001"], "invalid --speed-rpm: 1..1.0000001 (its grid's speed step is "),
        (&["map", "--speed-rpm", "1..1.0000001"], "; valid: >= 0.001 (ln of the ratio of neighbouring speeds"),
        (&["torque", "--preload-n", "1e300"], "invalid --preload-n: 1e300 N (valid: finite, [0 N, 10 MN])"),
        (&["sweep", "--preload", "1e300..1e301", "--step", "1e299"], "invalid --preload: 1e300 N (valid:"),
        (&["torque", "--axial-load-n", "-1e20"], "invalid --axial-load-n: -1e20 N (valid:"),
        (&["torque", "--speed-rpm", "fast"], "--speed-rpm"),
        (&["torque", "--format", "xml"], "--format"),
        (&["torque", "--no-such-flag"], "--no-such-flag"),
    ];
    for (args, message) in cases {
        let e = fails(args, 2);
        assert!(e.contains(message), "{args:?}: {e}");
    }
}

#[test]
fn global_options_go_before_or_after_the_subcommand() {
    let spec = concat!(env!("CARGO_MANIFEST_DIR"), "/../../configs/dkfzd4012.toml");
    let a = ok(&["--spec", spec, "--out", "-", "torque", "--format", "csv"]);
    let b = ok(&["torque", "--format", "csv", "--spec", spec, "--out", "-"]);
    assert_eq!(a, b);
    // `--format` is the subcommand's own: it offers what that subcommand writes.
    let e = fails(&["--format", "csv", "torque"], 2);
    assert!(e.contains("--format"), "{e}");
}

#[test]
fn help_and_version_succeed() {
    for cmd in [&["--help"][..], &["sweep", "--help"], &["--version"]] {
        let o = ballscrew(cmd);
        assert!(o.status.success());
    }
}

// ---- contact and creep-curves (FASTSIM) ----

fn num(v: &Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("no number {key} in {v}"))
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

/// A valid SVG document of `plotters`' SVG backend, with line work.
fn assert_svg(text: &str) {
    let head = text.trim_start();
    assert!(head.starts_with("<svg") || head.starts_with("<?xml"), "{}", &text[..text.len().min(200)]);
    assert!(text.trim_end().ends_with("</svg>"));
    assert!(text.contains("<line") || text.contains("<path") || text.contains("<polyline"), "no line work");
    assert!(text.contains("<text"), "text as SVG text elements");
}

#[test]
fn contact_from_screw_point_prints_forces() {
    let table = ok(&["contact"]);
    assert!(table.lines().next().unwrap().contains("nut contact of nut 1, circle 1"), "{table}");
    for label in ["force F_e (rolling)", "force F_f (lateral)", "spin moment M_z", "|F| / (mu Q)", "adhesion share"] {
        assert!(table.contains(label), "{label}: {table}");
    }
    assert!(table.contains("FASTSIM") && table.contains("Eq. 24"));

    for side in ["nut", "screw"] {
        let v = json(&ok(&["contact", "--format", "json", "--contact", side, "--nut", "2", "--circle", "3"]));
        assert_eq!(v["command"], "contact");
        assert_eq!(v["screw"]["contact"], side);
        assert_eq!((v["screw"]["nut"].as_u64(), v["screw"]["circle"].as_u64()), (Some(2), Some(3)));
        // The bound is the model contact's own coefficient (lubricated by default) times Q.
        let mu_q = num(&v["contact"], "friction_bound_n");
        assert!(rel(mu_q, num(&v["contact"], "friction_coefficient") * num(&v["contact"], "normal_load_n")) < 1e-12);
        assert!(v["friction_source"].as_str().unwrap().contains("model contact"), "{}", v["friction_source"]);
        for law in ["fastsim", "eq24"] {
            let f = &v[law];
            let mag = num(f, "force_e_n").hypot(num(f, "force_f_n"));
            assert!(mag > 0.0 && mag <= mu_q * (1.0 + 1e-9), "{law}: |F| {mag} vs mu Q {mu_q}");
            assert!((num(f, "force_ratio") - mag / mu_q).abs() < 1e-12);
            assert!(num(f, "dissipation_per_speed_n") >= 0.0);
        }
        let share = num(&v["fastsim"], "adhesion_share");
        assert!((0.0..=1.0).contains(&share), "{share}");
        let elements =
            v["fastsim"]["adhesion_elements"].as_u64().unwrap() + v["fastsim"]["slip_elements"].as_u64().unwrap();
        assert_eq!(elements, 40 * 40);
        // The creepages are the contact's: the model's xi is the centre-line xi plus the
        // Heathcote mean k_h b^2 / 5.
        let c = &v["creepages"];
        let b = num(&v["contact"], "semi_axis_lateral_mm");
        assert!(rel(num(c, "creep_heathcote"), num(c, "heathcote_per_mm2") * b * b / 5.0) < 1e-12);
        assert!((num(c, "creep_xi") - num(c, "creep_xi_centre") - num(c, "creep_heathcote")).abs() < 1e-15);
    }
}

#[test]
fn contact_eq24_forces_are_the_models() {
    // The Eq. 24 column rebuilds the model's contact from the reported ellipse and creepages:
    // it must give inspect's saturated forces of the same contact.
    let inspect = json(&ok(&["inspect", "--format", "json", "--preload-n", "1500"]));
    let circle = &inspect["nuts"][1]["circles"][0];
    for (k, side) in ["nut", "screw"].iter().enumerate() {
        let expected = &circle["contacts"][k];
        assert_eq!(expected["contact"], *side);
        let v = json(&ok(&["contact", "--format", "json", "--preload-n", "1500", "--nut", "2", "--contact", side]));
        let eq24 = &v["eq24"];
        for (mine, theirs) in
            [("force_e_n", "force_rolling_n"), ("force_f_n", "force_lateral_n"), ("spin_moment_nm", "spin_moment_nm")]
        {
            let (a, b) = (num(eq24, mine), num(expected, theirs));
            assert!((a - b).abs() <= 1e-9 * num(expected, "friction_bound_n"), "{side} {mine}: {a} vs {b}");
        }
        assert!(rel(num(&v["contact"], "normal_load_n"), num(expected, "normal_load_n")) < 1e-12);
        assert!(rel(num(&v["creepages"], "creep_xi"), num(expected, "creep_xi")) < 1e-9);
    }
}

#[test]
fn contact_eq24_applies_the_creep_reduction() {
    // A spec with friction.creep_reduction = 0.7 (as `diagnose --out-spec` writes): the model
    // multiplies Kalker's coefficients by it (torque::Model::new), so the Eq. 24 column must
    // too. On a contact given by the flags (no model evaluation, the same ellipse and
    // creepages under both specs) the linear forces of Eq. 23 are 0.7 times those at 1.
    let dir = tempfile::tempdir().unwrap();
    let reduced = spec_file(dir.path(), "[friction]\n", "[friction]\ncreep_reduction = 0.7\n");
    let reduced = reduced.to_str().unwrap();
    let flags = [
        "contact",
        "--format",
        "json",
        "--semi-axis-rolling-mm",
        "0.1",
        "--semi-axis-lateral-mm",
        "0.8",
        "--normal-load-n",
        "500",
        "--xi",
        "1e-5",
        "--eta",
        "-2e-5",
        "--phi-per-mm",
        "1e-4",
    ];
    let full = json(&ok(&flags));
    let cut = json(&ok(&[&flags[..], &["--spec", reduced]].concat()));
    for key in ["linear_force_e_n", "linear_force_f_n", "linear_spin_moment_nm"] {
        let (at_1, at_07) = (num(&full["eq24"], key), num(&cut["eq24"], key));
        assert!(at_1 != 0.0, "{key}");
        assert!(rel(at_07, 0.7 * at_1) < 1e-12, "{key}: {at_07} vs 0.7 x {at_1}");
    }
    // Deep in the linear range the saturated force follows (Eq. 24's blend is 1 - O(|F|/muQ)).
    let (at_1, at_07) = (num(&full["eq24"], "force_e_n"), num(&cut["eq24"], "force_e_n"));
    assert!(rel(at_07, 0.7 * at_1) < 0.05, "{at_07} vs 0.7 x {at_1}");

    // At a screw point the column is the model's own contact under the reduced spec.
    let inspect = json(&ok(&["inspect", "--format", "json", "--spec", reduced]));
    let circle = &inspect["nuts"][0]["circles"][0];
    for (k, side) in ["nut", "screw"].iter().enumerate() {
        let expected = &circle["contacts"][k];
        assert_eq!(expected["contact"], *side);
        let v = json(&ok(&["contact", "--format", "json", "--spec", reduced, "--contact", side]));
        for (mine, theirs) in [
            ("linear_force_e_n", "linear_force_rolling_n"),
            ("linear_force_f_n", "linear_force_lateral_n"),
            ("force_e_n", "force_rolling_n"),
            ("force_f_n", "force_lateral_n"),
            ("spin_moment_nm", "spin_moment_nm"),
        ] {
            let (a, b) = (num(&v["eq24"], mine), num(expected, theirs));
            assert!((a - b).abs() <= 1e-9 * num(expected, "friction_bound_n"), "{side} {mine}: {a} vs {b}");
        }
    }
}

#[test]
fn contact_friction_coefficient_is_the_model_contacts_and_says_so() {
    // Under EHL (the default) a screw contact's mu is the one the model found for that contact.
    let inspect = json(&ok(&["inspect", "--format", "json"]));
    let expected = &inspect["nuts"][0]["circles"][0]["contacts"][1];
    assert_eq!(expected["contact"], "screw");
    let v = json(&ok(&["contact", "--format", "json", "--contact", "screw"]));
    let mu = num(&v["contact"], "friction_coefficient");
    assert!(rel(mu, num(expected, "friction_coefficient")) < 1e-12, "{mu}");
    assert!(mu != 0.03, "the film's coefficient, not friction.coefficient: {mu}");
    assert!(v["friction_source"].as_str().unwrap().contains("ehl"), "{}", v["friction_source"]);
    assert!(ok(&["contact", "--contact", "screw"]).contains("friction coefficient mu: the model contact's (ehl)"));
    // Under dry it is friction.coefficient.
    let dir = tempfile::tempdir().unwrap();
    let dry = spec_file(dir.path(), "lubrication = \"ehl\"", "lubrication = \"dry\"");
    let v = json(&ok(&["contact", "--format", "json", "--spec", dry.to_str().unwrap()]));
    assert_eq!(num(&v["contact"], "friction_coefficient"), 0.03);
    assert!(v["friction_source"].as_str().unwrap().contains("dry"), "{}", v["friction_source"]);
    // A contact given by the flags alone has no film: the spec's friction.coefficient, stated.
    let flags = [
        "contact",
        "--semi-axis-rolling-mm",
        "0.1",
        "--semi-axis-lateral-mm",
        "0.8",
        "--normal-load-n",
        "500",
        "--xi",
        "1e-5",
    ];
    let v = json(&ok(&[&flags[..], &["--format", "json"]].concat()));
    assert_eq!(num(&v["contact"], "friction_coefficient"), 0.03);
    assert_eq!(v["friction_source"], "friction.coefficient of the spec");
    assert!(ok(&flags).contains("friction coefficient mu: friction.coefficient of the spec"));
    let v = json(&ok(&[&flags[..], &["--format", "json", "--friction", "0.08"]].concat()));
    assert_eq!((num(&v["contact"], "friction_coefficient"), v["friction_source"].as_str()), (0.08, Some("--friction")));
}

#[test]
fn inspect_reports_the_lubricated_contacts_and_the_torque_by_mechanism() {
    let v = json(&ok(&["inspect", "--format", "json"]));
    let contacts: Vec<&Value> = v["nuts"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|n| n["circles"].as_array().unwrap())
        .flat_map(|c| c["contacts"].as_array().unwrap())
        .collect();
    for k in &contacts {
        // Each contact's share is the sum of its mechanisms' shares.
        let parts =
            num(k, "creep_torque_share_nm") + num(k, "rolling_torque_share_nm") + num(k, "hysteresis_torque_share_nm");
        assert!((parts - num(k, "torque_share_nm")).abs() <= 1e-12 * num(k, "torque_share_nm").abs().max(1e-12));
        if k["contact"] != "ball-ball" {
            let (hc, hmin, lambda) = (num(k, "film_central_um"), num(k, "film_minimum_um"), num(k, "lambda"));
            assert!(hc > 0.0 && hmin > 0.0 && hmin < hc && lambda > 0.0, "{k}");
            let mu = num(k, "friction_coefficient");
            assert!(rel(num(k, "friction_bound_n"), mu * num(k, "normal_load_n")) < 1e-12, "{k}");
            assert!(num(k, "rolling_resistance_ehl_n") > 0.0 && num(k, "rolling_resistance_hysteresis_n") > 0.0);
        }
    }
    let t = &v["torque"];
    for key in [
        "creep_torque_nm",
        "rolling_resistance_torque_nm",
        "hysteresis_torque_nm",
        "ball_ball_torque_nm",
        "return_torque_nm",
        "seal_torque_nm",
    ] {
        assert!(num(t, key).is_finite(), "{key}");
    }
    assert!(num(t, "rolling_resistance_torque_nm") > 0.0 && num(t, "hysteresis_torque_nm") > 0.0);
    // The five dissipation shares add up to D/omega (the seals are outside it).
    let shares: f64 = [
        "creep_torque_nm",
        "rolling_resistance_torque_nm",
        "hysteresis_torque_nm",
        "ball_ball_torque_nm",
        "return_torque_nm",
    ]
    .iter()
    .map(|k| num(t, k))
    .sum();
    assert!(rel(shares, num(t, "dissipation_torque_nm")) < 1e-9, "{shares}");
    // CSV and text carry the same names and quantities.
    let csv = ok(&["inspect", "--format", "csv"]);
    let header = csv.lines().next().unwrap();
    for key in [
        "film_central_um",
        "film_minimum_um",
        "lambda",
        "friction_coefficient",
        "rolling_resistance_ehl_n",
        "rolling_resistance_hysteresis_n",
        "creep_torque_share_nm",
        "rolling_torque_share_nm",
        "hysteresis_torque_share_nm",
    ] {
        assert!(header.split(',').any(|h| h == key), "{key}: {header}");
    }
    let torque_csv = ok(&["torque", "--format", "csv"]);
    for key in [
        "creep_torque_nm",
        "rolling_resistance_torque_nm",
        "hysteresis_torque_nm",
        "ball_ball_torque_nm",
        "seal_torque_nm",
    ] {
        assert!(torque_csv.lines().next().unwrap().split(',').any(|h| h == key), "{key}");
    }
    let text = ok(&["inspect"]);
    for label in [
        "central film thickness h_c",
        "film parameter Lambda",
        "EHL rolling resistance",
        "of which elastic hysteresis",
        "seals (friction.seal_torque_per_nut_nm",
    ] {
        assert!(text.contains(label), "{label}");
    }
    // The dry model has no film.
    let dir = tempfile::tempdir().unwrap();
    let dry = spec_file(dir.path(), "lubrication = \"ehl\"", "lubrication = \"dry\"");
    let v = json(&ok(&["inspect", "--format", "json", "--spec", dry.to_str().unwrap()]));
    let k = &v["nuts"][0]["circles"][0]["contacts"][0];
    assert_eq!((num(k, "film_central_um"), num(k, "friction_coefficient")), (0.0, 0.03));
}

#[test]
fn sweep_of_speed_rises_and_names_its_column() {
    let (header, rows) =
        csv_numbers(&ok(&["sweep", "--speed-rpm", "300..3000", "--speed-step-rpm", "900", "--format", "csv"]));
    assert_eq!(header[..4], ["speed_rpm", "preload_n", "axial_load_n", "oil_temperature_c"]);
    assert_eq!(header.iter().filter(|h| *h == "speed_rpm").count(), 1);
    assert_eq!(column(&header, &rows, "preload_n"), [2000.0; 4]);
    let speeds = column(&header, &rows, "speed_rpm");
    // The speeds read back as given in rpm (not 1199.9999999999998).
    assert_eq!(speeds, [300.0, 1200.0, 2100.0, 3000.0]);
    let t = column(&header, &rows, "torque_nm");
    assert!(t.windows(2).all(|w| w[1] > w[0]), "{t:?}");
    let v = json(&ok(&["sweep", "--speed-rpm", "300..3000", "--speed-step-rpm", "900", "--format", "json"]));
    assert_eq!(v["swept"], "speed_rpm");
    assert_eq!(v["preload_n"], 2000.0);
    assert!(ok(&["sweep", "--speed-rpm", "300..3000", "--speed-step-rpm", "2700"]).contains("speed"));
}

#[test]
fn sweep_of_oil_temperature_falls() {
    let args = ["sweep", "--oil-temperature-c", "20..80", "--oil-temperature-step-c", "20", "--speed-rpm", "1000"];
    let (header, rows) = csv_numbers(&ok(&[&args[..], &["--format", "csv"]].concat()));
    assert_eq!(header[0], "oil_temperature_c");
    assert_eq!(column(&header, &rows, "oil_temperature_c"), [20.0, 40.0, 60.0, 80.0]);
    let t = column(&header, &rows, "torque_nm");
    assert!(t.windows(2).all(|w| w[1] < w[0]), "{t:?}");
    let v = json(&ok(&[&args[..], &["--format", "json"]].concat()));
    assert_eq!(v["swept"], "oil_temperature_c");
    assert!(rel(num(&v, "speed_rpm"), 1000.0) < 1e-12);
    // Out of the core's range: the flag is named.
    let e = fails(&["sweep", "--oil-temperature-c", "20..300", "--oil-temperature-step-c", "140"], 2);
    assert!(e.contains("invalid --oil-temperature-c: 300 (valid: [-30, 200]"), "{e}");
    // One quantity at a time.
    let e = fails(&["sweep", "--oil-temperature-c", "20..80", "--speed-rpm", "100..200"], 2);
    assert!(e.contains("--speed-rpm") && e.contains("--oil-temperature-c"), "{e}");
}

#[test]
fn sweep_of_oil_temperature_under_dry_is_an_error_naming_the_flag() {
    let dir = tempfile::tempdir().unwrap();
    let dry = spec_file(dir.path(), "lubrication = \"ehl\"", "lubrication = \"dry\"");
    let e = fails(&["sweep", "--spec", dry.to_str().unwrap(), "--oil-temperature-c", "20..80"], 2);
    assert!(e.contains("--oil-temperature-c") && e.contains("dry"), "{e}");
}

#[test]
fn contact_from_creepages_has_partial_slip() {
    // At the dry coefficient 0.03 (the model contact's own would be the film's under EHL).
    let v = json(&ok(&["contact", "--format", "json", "--xi", "2e-4", "--friction", "0.03"]));
    assert!(v["creepages"]["creep_eta"].as_f64() == Some(0.0) && v["creepages"]["heathcote_per_mm2"] == 0.0);
    let f = &v["fastsim"];
    let share = num(f, "adhesion_share");
    assert!(share > 0.0 && share < 1.0, "partial slip: {share}");
    assert!(num(f, "force_e_n") < 0.0, "force against the creepage");
    assert_eq!(num(f, "force_f_n"), 0.0);
    let ratio = num(f, "force_ratio");
    assert!(ratio > 0.3 && ratio < 1.0, "{ratio}");
    // Fully given contact: no model evaluation, the flags' values exactly.
    let v = json(&ok(&[
        "contact",
        "--format",
        "json",
        "--semi-axis-rolling-mm",
        "0.3",
        "--semi-axis-lateral-mm",
        "0.3",
        "--normal-load-n",
        "100",
        "--friction",
        "0.1",
        "--eta",
        "-1e-4",
        "--grid",
        "20",
    ]));
    assert!(v["screw"].is_null());
    assert_eq!(v["contact"]["a_over_b"], 1.0);
    assert_eq!(v["contact"]["friction_bound_n"], 10.0);
    assert!(num(&v["fastsim"], "force_f_n") > 0.0 && num(&v["eq24"], "force_f_n") > 0.0);
    let share = num(&v["fastsim"], "adhesion_share");
    assert!(share > 0.0 && share <= 1.0, "{share}");
    assert_eq!(v["fastsim"]["grid"], 20);
}

#[test]
fn contact_linear_limit_and_full_slip() {
    // Tiny creepage: all adhesion, FASTSIM on Kalker's linear theory (as Eq. 24 is there).
    let v = json(&ok(&["contact", "--format", "json", "--xi", "1e-8"]));
    assert_eq!(num(&v["fastsim"], "adhesion_share"), 1.0);
    let (fs, law) = (num(&v["fastsim"], "force_e_n"), num(&v["eq24"], "force_e_n"));
    assert!(rel(fs, law) < 0.01, "{fs} vs {law}");
    // Large creepage: full slip at mu Q, both bounds.
    for bound in ["parabolic", "elliptical"] {
        let v = json(&ok(&["contact", "--format", "json", "--eta", "0.5", "--bound", bound]));
        assert_eq!(num(&v["fastsim"], "adhesion_share"), 0.0);
        assert!((num(&v["fastsim"], "force_ratio") - 1.0).abs() < 2e-3);
        assert_eq!(v["fastsim"]["bound"], bound);
    }
}

#[test]
fn contact_csv_is_one_row_with_prefixed_columns() {
    let text = ok(&["contact", "--format", "csv", "--xi", "1e-4"]);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 2);
    let header: Vec<&str> = lines[0].split(',').collect();
    assert_eq!(lines[1].split(',').count(), header.len());
    for key in
        ["semi_axis_rolling_mm", "creep_xi_centre", "fastsim_force_e_n", "fastsim_adhesion_share", "eq24_force_e_n"]
    {
        assert!(header.contains(&key), "{key}");
    }
}

#[test]
fn contact_plot_writes_svg_and_failure_leaves_none() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("traction.svg");
    let p = path.to_str().unwrap();
    let printed = ok(&["contact", "--xi", "2e-4", "--plot", p]);
    assert!(printed.contains("adhesion share"), "the report still goes to stdout");
    let svg = std::fs::read_to_string(&path).unwrap();
    assert_svg(&svg);
    // Arrowheads (filled polygons) in the slip area, the ellipse outline, the axes in mm.
    assert!(svg.matches("<polygon").count() > 100, "arrows");
    assert!(svg.contains("y lateral, mm") && svg.contains("x along rolling, mm"));
    assert!(svg.contains("adhesion"));
    // No slip, no arrows.
    let still = dir.path().join("still.svg");
    ok(&["contact", "--xi", "0", "--plot", still.to_str().unwrap()]);
    assert!(!std::fs::read_to_string(&still).unwrap().contains("<polygon"));

    let failed = dir.path().join("failed.svg");
    let f = failed.to_str().unwrap();
    fails(&["contact", "--grid", "0", "--plot", f], 2);
    fails(&["contact", "--xi", "nan", "--plot", f], 2);
    fails(&["contact", "--contact", "ball", "--plot", f], 2);
    fails(&["creep-curves", "--points", "1", "--plot", f], 2);
    assert!(!failed.exists());
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names.len(), 2, "no temporary files left: {names:?}");
    // A plot that cannot be written is an output error.
    fails(&["contact", "--plot", dir.path().join("no/such/dir/x.svg").to_str().unwrap()], 1);
}

/// The rows of one curve of `creep-curves --format json`.
fn curve<'a>(v: &'a Value, parameter: &str, law: &str) -> &'a [Value] {
    v["curves"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["parameter"] == parameter && c["law"] == law)
        .unwrap_or_else(|| panic!("no curve {parameter} {law}"))["rows"]
        .as_array()
        .unwrap()
}

#[test]
fn creep_curves_json_saturate_towards_one() {
    let v = json(&ok(&["creep-curves", "--format", "json"]));
    assert_eq!(v["command"], "creep-curves");
    assert_eq!(v["curves"].as_array().unwrap().len(), 4 * 3);
    for law in ["fastsim-parabolic", "fastsim-elliptical", "eq24"] {
        let rows = curve(&v, "xi", law);
        assert_eq!(rows.len(), 41);
        let ratio: Vec<f64> = rows.iter().map(|r| num(r, "force_ratio")).collect();
        assert_eq!(ratio[0], 0.0);
        assert!(ratio.windows(2).all(|w| w[1] >= w[0] - 1e-12), "{law}: monotone in xi: {ratio:?}");
        let last = *ratio.last().unwrap();
        assert!(last > 0.97 && last <= 1.0 + 1e-9, "{law}: saturates towards 1: {last}");
        // The force opposes the creepage, along e only.
        assert!(rows.iter().all(|r| num(r, "force_e_n") <= 0.0 && num(r, "force_f_n") == 0.0));
    }
    // FASTSIM starts on Kalker's linear slope, as Eq. 24 does.
    let (fs, law) = (
        num(&curve(&v, "eta", "fastsim-parabolic")[1], "force_ratio"),
        num(&curve(&v, "eta", "eq24")[1], "force_ratio"),
    );
    assert!(rel(fs, law) < 0.02, "{fs} vs {law}");
    for c in v["curves"].as_array().unwrap() {
        for r in c["rows"].as_array().unwrap() {
            assert!(num(r, "force_ratio") <= 1.0 + 1e-9, "{c}");
        }
        let share_is_number = c["rows"][1]["adhesion_share"].is_number();
        assert_eq!(share_is_number, c["law"] != "eq24");
    }
    // One bound: FASTSIM with it and Eq. 24.
    let v = json(&ok(&["creep-curves", "--format", "json", "--bound", "elliptical", "--points", "5"]));
    let laws: Vec<&str> = v["curves"].as_array().unwrap().iter().map(|c| c["law"].as_str().unwrap()).collect();
    assert_eq!(laws.len(), 8);
    assert!(laws.iter().all(|l| *l == "fastsim-elliptical" || *l == "eq24"));
    assert_eq!(curve(&v, "kh_b2", "eq24").len(), 5);
}

#[test]
fn creep_curves_csv_and_table() {
    let text = ok(&["creep-curves", "--format", "csv", "--points", "3"]);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "parameter,law,value,force_e_n,force_f_n,spin_moment_nm,force_ratio,adhesion_share");
    assert_eq!(lines.len(), 1 + 4 * 3 * 3);
    let table = ok(&["creep-curves", "--points", "3"]);
    for label in ["longitudinal creepage xi", "lateral creepage eta", "spin phi c", "Heathcote k_h b^2", "Eq. 24"] {
        assert!(table.contains(label), "{label}: {table}");
    }
}

#[test]
fn creep_curves_plot_writes_svg() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("fig9.svg");
    let printed = ok(&["creep-curves", "--plot", path.to_str().unwrap()]);
    assert!(printed.is_empty(), "with --plot the data go to --out only");
    let svg = std::fs::read_to_string(&path).unwrap();
    assert_svg(&svg);
    for label in ["|F| / (μQ)", "FASTSIM, parabolic bound", "FASTSIM, elliptical bound", "Eq. 24", "ξ", "η", "φ c"]
    {
        assert!(svg.contains(label), "{label}");
    }
    let data = dir.path().join("fig9.csv");
    ok(&["creep-curves", "--format", "csv", "--plot", path.to_str().unwrap(), "--out", data.to_str().unwrap()]);
    assert_eq!(std::fs::read_to_string(&data).unwrap().lines().count(), 1 + 4 * 3 * 41);
}

#[test]
fn contact_and_creep_curves_bad_flags_exit_2() {
    let cases: &[(&[&str], &str)] = &[
        (&["contact", "--grid", "0"], "invalid --grid: 0 (valid: integer in [1, 400])"),
        (&["contact", "--grid", "401"], "invalid --grid: 401 (valid: integer in [1, 400])"),
        (&["creep-curves", "--grid", "-1"], "invalid --grid: -1 (valid:"),
        (&["contact", "--normal-load-n", "-5"], "invalid --normal-load-n: -5 N (valid: finite, [1 µN, 10 MN])"),
        // Tiny values that pass a "> 0" check but whose products leave double precision (the
        // forces came out NaN: exit 1 without naming a flag).
        (&["contact", "--normal-load-n", "1e-300"], "invalid --normal-load-n: 1e-300 N (valid: finite, [1 µN, 10 MN])"),
        (
            &["contact", "--semi-axis-rolling-mm", "1e-300"],
            "invalid --semi-axis-rolling-mm: 1e-303 m (valid: finite, [100 nm, 100 mm])",
        ),
        (&["creep-curves", "--semi-axis-lateral-mm", "1e-5"], "invalid --semi-axis-lateral-mm: 10 nm (valid:"),
        (&["contact", "--friction", "1e-300"], "invalid --friction: 1e-300 (valid: [1e-4, 1])"),
        // Huge values in exponent form, not as 301 digits.
        (&["contact", "--xi", "1e300"], "invalid --xi: 1e300 (valid: finite, |value| <= 1000)"),
        (&["creep-curves", "--span", "-1e200"], "invalid --span: -1e200 (valid:"),
        (&["contact", "--normal-load-n", "nan"], "invalid --normal-load-n: NaN (valid:"),
        (&["contact", "--semi-axis-rolling-mm", "0"], "invalid --semi-axis-rolling-mm: 0 m (valid:"),
        (&["contact", "--semi-axis-lateral-mm", "inf"], "invalid --semi-axis-lateral-mm: inf (valid:"),
        (&["contact", "--friction", "1.5"], "invalid --friction: 1.5 (valid: [1e-4, 1])"),
        (&["contact", "--xi", "nan"], "invalid --xi: NaN (valid: finite"),
        (&["contact", "--eta", "inf"], "invalid --eta: inf (valid:"),
        (&["contact", "--phi-per-mm", "1e9"], "invalid --phi-per-mm: 1e9 (valid:"),
        (&["contact", "--heathcote-per-mm2", "-nan"], "invalid --heathcote-per-mm2: NaN (valid:"),
        (&["contact", "--contact", "ball"], "'--contact <CONTACT>'"),
        (&["contact", "--bound", "round"], "'--bound <BOUND>'"),
        (&["contact", "--nut", "3"], "invalid --nut: 3 (valid: integer in [1, 2])"),
        (&["contact", "--nut", "0"], "invalid --nut: 0 (valid: integer in [1, 2])"),
        (&["creep-curves", "--circle", "5"], "invalid --circle: 5 (valid: integer in [1, 4])"),
        (&["contact", "--circle", "-1"], "invalid --circle: -1 (valid: integer in [1, 4])"),
        (&["contact", "--preload-n", "-1"], "invalid --preload-n: -1 N (valid:"),
        (&["creep-curves", "--speed-rpm", "nan"], "invalid --speed-rpm: NaN (valid:"),
        (&["creep-curves", "--points", "1"], "invalid --points: 1 (valid: integer in [2, 1000])"),
        (&["creep-curves", "--span", "0"], "invalid --span: 0 (valid: finite, (0, 1000])"),
        (&["creep-curves", "--span", "nan"], "invalid --span: NaN (valid:"),
        (&["creep-curves", "--xi", "0.1"], "--xi"),
        (&["contact", "--axial-load-n", "8000", "--nut", "2"], "carries no load"),
    ];
    for (args, message) in cases {
        let e = fails(args, 2);
        assert!(e.contains(message), "{args:?}: {e}");
    }
    let dir = tempfile::tempdir().unwrap();
    let same = dir.path().join("same.svg");
    let s = same.to_str().unwrap();
    let e = fails(&["creep-curves", "--plot", s, "--out", s], 2);
    assert!(e.contains("same file"), "{e}");
    assert!(!same.exists());
}

/// The counts (below, within, above) of the catalog band [0.5, 1.5] in a sweep's closing line.
fn band_counts(table: &str) -> (usize, usize, usize) {
    let line = table.lines().last().unwrap();
    let count = |word: &str| -> usize {
        let after = line.split(&format!("{word} at ")).nth(1).unwrap_or_else(|| panic!("{line}"));
        after.split(|c: char| !c.is_ascii_digit()).next().unwrap().parse().unwrap()
    };
    (count("below"), count("within"), count("above"))
}

#[test]
fn torque_reports_drag_and_load_beside_their_sum_and_the_efficiency() {
    let v = json(&ok(&["torque", "--preload-n", "500", "--axial-load-n", "3000", "--format", "json"]));
    let (torque, drag, load) = (num(&v, "torque_nm"), num(&v, "drag_torque_nm"), num(&v, "load_torque_nm"));
    assert!((drag + load - torque).abs() < 1e-12 * torque, "{v}");
    // F_a L / (2 pi) with the built-in 12 mm lead.
    assert!(rel(load, 3000.0 * 0.012 / (2.0 * core::f64::consts::PI)) < 1e-9, "{load}");
    assert_eq!(num(&v, "ratio"), drag / num(&v, "catalog_nm"));
    let (forward, backdrive) = (num(&v, "forward_efficiency"), num(&v, "backdrive_efficiency"));
    assert!(forward > 0.9 && forward < 1.0 && backdrive > 0.9 && backdrive < 1.0, "{v}");
    // The forward point is this one (positive speed against a positive load).
    assert!(rel(forward, load / torque) < 1e-12, "{forward} vs {}", load / torque);
    assert!(rel(num(&v, "backdrive_torque_nm"), backdrive * load) < 1e-12);
    // Without an axial load: no load torque, no efficiency (null, empty, n/a).
    let v = json(&ok(&["torque", "--format", "json"]));
    assert_eq!((num(&v, "load_torque_nm"), num(&v, "drag_torque_nm")), (0.0, num(&v, "torque_nm")));
    assert!(v["forward_efficiency"].is_null() && v["backdrive_efficiency"].is_null(), "{v}");
    let table = ok(&["torque"]);
    let row = table.lines().find(|l| l.starts_with("forward efficiency")).unwrap();
    assert!(row.contains("n/a"), "{row}");
    let (header, rows) = csv_numbers(&ok(&["torque", "--format", "csv"]));
    assert!(column(&header, &rows, "forward_efficiency")[0].is_nan());
    // At standstill the efficiency is not defined either.
    let v = json(&ok(&["torque", "--speed-rpm", "0", "--axial-load-n", "300", "--format", "json"]));
    assert!(v["forward_efficiency"].is_null(), "{v}");
}

#[test]
fn inspect_reports_drag_and_load_by_the_same_names() {
    let v = json(&ok(&["inspect", "--axial-load-n", "300", "--format", "json"]));
    let t = &v["torque"];
    assert!((num(t, "drag_torque_nm") + num(t, "load_torque_nm") - num(t, "torque_nm")).abs() < 1e-12);
    assert!(num(t, "load_torque_nm") > 0.0);
}

#[test]
fn the_catalog_verdict_under_an_axial_load_is_the_drags() {
    let args = ["sweep", "--preload", "500..3000", "--step", "500", "--axial-load-n", "300"];
    let (header, rows) = csv_numbers(&ok(&[&args[..], &["--format", "csv"]].concat()));
    let drag = column(&header, &rows, "drag_torque_nm");
    let load = column(&header, &rows, "load_torque_nm");
    let torque = column(&header, &rows, "torque_nm");
    let catalog = column(&header, &rows, "catalog_nm");
    let ratio = column(&header, &rows, "ratio");
    for i in 0..rows.len() {
        assert!((drag[i] + load[i] - torque[i]).abs() < 1e-12 * torque[i]);
        assert_eq!(ratio[i], drag[i] / catalog[i]);
    }
    // The verdict of the drag alone, counted here; the torque with its load torque would move
    // the light preloads up in the band.
    let verdict = |t: &[f64]| {
        let r: Vec<f64> = t.iter().zip(&catalog).map(|(t, c)| (t / c).abs()).collect();
        let below = r.iter().filter(|&&x| x < 0.5).count();
        let above = r.iter().filter(|&&x| x > 1.5).count();
        (below, r.len() - below - above, above)
    };
    assert_eq!(band_counts(&ok(&args)), verdict(&drag));
    assert_ne!(verdict(&drag), verdict(&torque), "the load torque would change the verdict here");
    // The efficiency columns: both defined under the load.
    assert!(column(&header, &rows, "forward_efficiency").iter().all(|e| *e > 0.0 && *e < 1.0));
}

#[test]
fn sweep_of_axial_load_names_its_column_and_reports_the_efficiency() {
    let args = ["sweep", "--axial-load-n", "-1000..1000", "--axial-load-step-n", "500", "--preload", "2000"];
    let (header, rows) = csv_numbers(&ok(&[&args[..], &["--format", "csv"]].concat()));
    assert_eq!(header[0], "axial_load_n");
    assert_eq!(column(&header, &rows, "axial_load_n"), [-1000.0, -500.0, 0.0, 500.0, 1000.0]);
    let load = column(&header, &rows, "load_torque_nm");
    assert!(load.windows(2).all(|w| w[1] > w[0]), "{load:?}");
    let forward = column(&header, &rows, "forward_efficiency");
    assert!(forward[2].is_nan(), "n/a without a load: {forward:?}");
    for i in [0, 1, 3, 4] {
        assert!(forward[i] > 0.0 && forward[i] < 1.0, "{forward:?}");
    }
    // The efficiency rises with the load as the preload's drag weighs less.
    assert!(forward[4] > forward[3] && forward[0] > forward[1], "{forward:?}");
    let v = json(&ok(&[&args[..], &["--format", "json"]].concat()));
    assert_eq!(v["swept"], "axial_load_n");
    assert!(v.get("axial_load_n").is_none(), "{v}");
    assert!(v["rows"][2]["backdrive_efficiency"].is_null());
    let table = ok(&args);
    assert!(table.contains("of 5 axial loads"), "{table}");
    // One vocabulary of errors: the flag and its text.
    let e = fails(&["sweep", "--axial-load-n", "1000..-1000"], 2);
    assert!(e.contains("invalid --axial-load-n: 1000..-1000"), "{e}");
    let e = fails(&["sweep", "--axial-load-n", "0..1000", "--axial-load-step-n", "0"], 2);
    assert!(e.contains("invalid --axial-load-step-n: 0 N"), "{e}");
    let e = fails(&["sweep", "--axial-load-n", "0..1000", "--speed-rpm", "1..2"], 2);
    assert!(e.contains("one quantity at a time"), "{e}");
    let e = fails(&["sweep", "--axial-load-n", "0..2e7"], 2);
    assert!(e.contains("--axial-load-n"), "{e}");
    let e = fails(&["sweep", "--axial-load-n", "abc"], 2);
    assert!(e.contains("invalid --axial-load-n: abc"), "{e}");
}

/// The quasi-static model leaves out the balls' inertia (`ballscrew_core::screw::inertia`):
/// where it is not small the result is printed with a warning on stderr, not refused; the
/// catalog's range (DKFZD4012 to 3000 rpm from 500 N) prints none.
#[test]
fn a_speed_beyond_the_quasi_static_model_is_warned_about() {
    for args in [&["torque"][..], &["torque", "--speed-rpm", "-3000", "--preload-n", "500"], &["sweep"]] {
        let o = ballscrew(args);
        assert!(o.status.success() && o.stderr.is_empty(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    }
    let o = ballscrew(&["torque", "--speed-rpm", "6000", "--preload-n", "500", "--format", "csv"]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success() && !o.stdout.is_empty(), "{e}");
    assert!(e.starts_with("warning: at speed 6000 rpm, preload 500 N") && e.contains("quasi-static"), "{e}");
    assert!(e.contains("gyroscopic moment is 42 %"), "{e}");
    let o = ballscrew(&["sweep", "--speed-rpm", "1000..6000", "--speed-step-rpm", "1000", "--preload-n", "500"]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success() && e.matches("warning:").count() == 1, "{e}");
    assert!(e.contains("at 2 of 6 points, the worst at speed 6000 rpm"), "{e}");
}

/// The warning's text is the core's `InertiaWarning` (Python's `QuasiStaticWarning` says the
/// same): the command line prints it after `warning: `, byte for byte, for one point, for a
/// sweep (the worst of its points) and for an unloaded screw.
#[test]
fn the_quasi_static_warning_is_the_cores_text() {
    use ballscrew_core::input::rpm_to_rad_s;
    use ballscrew_core::screw::inertia;
    use ballscrew_core::{Model, OperatingPoint, ScrewSpec};
    let spec = ScrewSpec::dkfzd4012();
    let helix = Model::new(&spec).map(|m| m.helix_angle_rad()).expect("built-in spec");
    let point =
        |rpm: f64, preload_n: f64| OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n, axial_load_n: 0.0 };
    let sweep: Vec<OperatingPoint> = (1..=6).map(|k| point(1000.0 * f64::from(k), 500.0)).collect();
    for (args, ops) in [
        (&["torque", "--speed-rpm", "6000", "--preload-n", "500", "--format", "csv"][..], vec![point(6000.0, 500.0)]),
        (&["sweep", "--speed-rpm", "1000..6000", "--speed-step-rpm", "1000", "--preload-n", "500"], sweep),
        (&["torque", "--speed-rpm", "-2000", "--preload-n", "0", "--format", "csv"], vec![point(-2000.0, 0.0)]),
    ] {
        let o = ballscrew(args);
        let w = inertia::check(&spec, helix, ops).expect("beyond the quasi-static model");
        assert_eq!(String::from_utf8_lossy(&o.stderr), format!("warning: {w}\n"), "{args:?}");
    }
}

/// A mistyped flag is an input error naming the flag meant (clap's suggestions).
#[test]
fn a_mistyped_flag_names_the_flag_meant() {
    for (args, typo, meant) in [
        (&["torque", "--preload-n", "2000", "--sped-rpm", "100"][..], "--sped-rpm", "--speed-rpm"),
        (&["sweep", "--axial-load", "100"][..], "--axial-load", "--axial-load-n"),
        (&["predict", "--data", "ops.csv", "--colum", "time_h=hours"][..], "--colum", "--column"),
    ] {
        let e = fails(args, 2);
        assert!(e.starts_with(&format!("error: unexpected argument '{typo}' found")), "{e}");
        assert!(e.contains(&format!("a similar argument exists: '{meant}'")), "{e}");
    }
}

/// `--oil-temperature-c` of the commands of one operating point: the name, meaning and range
/// check of `sweep`'s. Warmer oil thins the film and lowers the lubricated torque at speed; the
/// torque is the sweep's at that temperature; the spec's own temperature changes nothing.
#[test]
fn the_oil_temperature_of_one_point_is_the_sweeps() {
    let torque = |extra: &[&str]| -> Value {
        json(&ok(&[&["torque", "--speed-rpm", "1000", "--format", "json"][..], extra].concat()))
    };
    let spec = torque(&[]);
    let warm = torque(&["--oil-temperature-c", "60"]);
    assert_eq!(spec["oil_temperature_c"].as_f64(), Some(40.0), "{spec}");
    assert_eq!(warm["oil_temperature_c"].as_f64(), Some(60.0), "{warm}");
    let t = |v: &Value| v["torque_nm"].as_f64().unwrap();
    assert!(t(&warm) < 0.9 * t(&spec), "{} at 60 C, {} at 40 C", t(&warm), t(&spec));
    assert_eq!(t(&torque(&["--oil-temperature-c", "40"])), t(&spec));
    let sweep = json(&ok(&[
        "sweep",
        "--oil-temperature-c",
        "60..60",
        "--preload-n",
        "2000",
        "--speed-rpm",
        "1000",
        "--format",
        "json",
    ]));
    assert_eq!(sweep["rows"][0]["torque_nm"].as_f64(), Some(t(&warm)), "{sweep}");
    let inspect = json(&ok(&["inspect", "--speed-rpm", "1000", "--oil-temperature-c", "60", "--format", "json"]));
    assert_eq!(
        (inspect["oil_temperature_c"].as_f64(), inspect["torque"]["torque_nm"].as_f64()),
        (Some(60.0), Some(t(&warm)))
    );
    let table = ok(&["torque", "--oil-temperature-c", "60"]);
    assert!(table.lines().next().unwrap().contains(", oil 60 C;"), "{table}");

    // Out of range, not a number or under the dry model: refused naming the flag, as by sweep.
    let e = fails(&["torque", "--oil-temperature-c", "1000"], 2);
    assert!(e.starts_with("error: invalid --oil-temperature-c: 1000 (valid: "), "{e}");
    let swept = fails(&["sweep", "--oil-temperature-c", "1000"], 2);
    assert_eq!(e, swept);
    for sub in ["inspect", "contact", "creep-curves"] {
        assert_eq!(fails(&[sub, "--oil-temperature-c", "1000"], 2), e, "{sub}");
    }
    let e = fails(&["torque", "--oil-temperature-c", "NaN"], 2);
    assert!(e.starts_with("error: invalid --oil-temperature-c: NaN (valid: "), "{e}");
    let dry = fails(
        &[
            "torque",
            "--spec",
            &format!("{}/../../configs/dkfzd4012-dry.toml", env!("CARGO_MANIFEST_DIR")),
            "--oil-temperature-c",
            "60",
        ],
        2,
    );
    assert!(dry.starts_with("error: --oil-temperature-c needs the lubricated model"), "{dry}");
}

/// `sweep --errors nan`: a point the model cannot evaluate (DKFZD4012 with one circuit per nut
/// at 3000 rpm: no steady train) gives a row that keeps its operating point and is NaN (CSV:
/// empty; JSON: null, with the error; table: "failed") while the other rows are `torque`'s own
/// numbers, and one warning on stderr says how many rows failed and why the first did. The
/// default (`raise`) stops with the point's error, exit 1, nothing on stdout.
#[test]
fn sweep_with_errors_nan_keeps_the_other_rows() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spec_file(dir.path(), "return = \"internal\"", "return = \"external\"");
    let spec = spec.to_str().unwrap();
    let args = ["sweep", "--spec", spec, "--speed-rpm", "100..3000", "--speed-step-rpm", "1450", "--errors", "nan"];
    let o = ballscrew(&[&args[..], &["--format", "csv"]].concat());
    assert!(o.status.success());
    let stderr = String::from_utf8(o.stderr).unwrap();
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with("warning: 1 of 3 rows could not be evaluated and are NaN (--errors nan); the first, at screw speed 3000 rpm: the ball train of the circuit of nut 1"),
        "{stderr}"
    );
    let (header, rows) = csv_numbers(&String::from_utf8(o.stdout).unwrap());
    assert_eq!(column(&header, &rows, "speed_rpm"), [100.0, 1550.0, 3000.0]);
    assert_eq!(column(&header, &rows, "preload_n"), [2000.0; 3]);
    let torques = column(&header, &rows, "torque_nm");
    assert!(torques[2].is_nan() && column(&header, &rows, "iterations")[2].is_nan());
    for (i, rpm) in [(0, "100"), (1, "1550")] {
        let one = json(&ok(&["torque", "--spec", spec, "--speed-rpm", rpm, "--format", "json"]));
        assert_eq!(torques[i], one["torque_nm"].as_f64().unwrap(), "{rpm} rpm");
    }
    let o = ballscrew(&[&args[..], &["--format", "json"]].concat());
    let rows = json(&String::from_utf8(o.stdout).unwrap())["rows"].as_array().unwrap().clone();
    assert!(rows[2]["torque_nm"].is_null() && rows[2]["speed_rpm"] == 3000.0);
    assert!(rows[2]["error"].as_str().unwrap().starts_with("the ball train of the circuit of nut 1"));
    assert!(rows[0].get("error").is_none() && rows[0]["torque_nm"].is_f64());
    let table = String::from_utf8(ballscrew(&args).stdout).unwrap();
    let last = table.lines().find(|l| l.trim_start().starts_with("3000")).unwrap();
    assert!(last.split_whitespace().skip(1).all(|c| c == "failed"), "{last}");
    let e = fails(&args[..args.len() - 2], 1);
    assert!(e.contains("at screw speed 3000 rpm: the ball train"), "{e}");
    // Every row NaN: a figure is refused (nothing to plot), and an old file is left as it was.
    let svg = dir.path().join("all.svg");
    std::fs::write(&svg, "old").unwrap();
    let all = ["sweep", "--spec", spec, "--speed-rpm", "3000", "--errors", "nan", "--plot", svg.to_str().unwrap()];
    let o = ballscrew(&all);
    assert_eq!(o.status.code(), Some(1));
    assert!(o.stdout.is_empty() && std::fs::read_to_string(&svg).unwrap() == "old");
    assert!(String::from_utf8(o.stderr).unwrap().contains("error: --plot: no row of the sweep could be evaluated"));
}

/// `sweep --band --errors nan`: a band whose samples cannot all be evaluated (DKFZD4012 with one
/// circuit per nut and a lead deviation of -2.76 um at 500 N and 100 rpm: the oil's spread reaches
/// a train without a steady state) is NaN while the row's torque stands, said once on stderr;
/// without `--errors nan` the sweep stops there.
#[test]
fn sweep_band_with_errors_nan_gives_a_nan_band() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spec_file(dir.path(), "return = \"internal\"", "return = \"external\"\nlead_deviation_um = -2.76");
    let spec = spec.to_str().unwrap();
    let args = ["sweep", "--spec", spec, "--preload-n", "500", "--band", "--samples", "16", "--format", "csv"];
    let o = ballscrew(&[&args[..], &["--errors", "nan"]].concat());
    assert!(o.status.success());
    let stderr = String::from_utf8(o.stderr).unwrap();
    assert!(stderr.starts_with("warning: the band of 1 of 1 rows could not be evaluated and is NaN"), "{stderr}");
    let (header, rows) = csv_numbers(&String::from_utf8(o.stdout).unwrap());
    assert!(column(&header, &rows, "torque_nm")[0] > 0.0);
    assert!(column(&header, &rows, "drag_torque_low_nm")[0].is_nan());
    let e = fails(&args, 1);
    assert!(e.contains("band at preload F_p 500 N"), "{e}");
}
