//! Runs the built `ballscrew` binary.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const BUILTIN: &str = include_str!("../../../configs/dkfzd4012.toml");

fn ballscrew(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ballscrew")).args(args).output().expect("the binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).unwrap()
}

/// Runs and expects success; returns stdout.
fn ok(args: &[&str]) -> String {
    let o = ballscrew(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    assert!(stderr(&o).is_empty(), "{}", stderr(&o));
    stdout(&o)
}

/// Runs and expects failure with `code`; returns stderr.
fn fails(args: &[&str], code: i32) -> String {
    let o = ballscrew(args);
    assert_eq!(o.status.code(), Some(code), "{args:?}: stdout {} stderr {}", stdout(&o), stderr(&o));
    assert!(o.stdout.is_empty(), "no output on failure: {}", stdout(&o));
    let e = stderr(&o);
    assert!(e.starts_with("error: "), "{e}");
    assert!(!e.contains("panicked"), "{e}");
    e
}

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

/// Parses CSV of plain fields (no quoting) into a header and rows of numbers.
fn csv_numbers(text: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(str::to_string).collect::<Vec<_>>();
    let rows: Vec<Vec<f64>> = lines.map(|l| l.split(',').map(|f| f.parse().unwrap()).collect()).collect();
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
        .map(|l| l.split_whitespace().map(|w| w.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 26);
    assert_eq!((rows[0][0], rows[25][0]), (500.0, 3000.0));
    assert!(rows.windows(2).all(|w| w[1][1] > w[0][1]), "torque rises with preload");
    assert!(lines.last().unwrap().contains("catalog band"), "{}", lines.last().unwrap());
}

#[test]
fn sweep_csv_parses_and_matches_catalog() {
    let (header, rows) = csv_numbers(&ok(&["sweep", "--format", "csv"]));
    assert_eq!(header[..2], ["preload_n", "torque_nm"]);
    assert_eq!(rows.len(), 26);
    let catalog = column(&header, &rows, "catalog_nm");
    // reference/catalog_drag_torque.csv: 500 N -> 0.1545 N m, 3000 N -> 0.9271 N m.
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
    // The shares of all contacts add up to the dissipation torque.
    let shares: f64 = nuts
        .iter()
        .flat_map(|n| n["circles"].as_array().unwrap())
        .flat_map(|c| c["contacts"].as_array().unwrap())
        .map(|k| k["torque_share_nm"].as_f64().unwrap())
        .sum();
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
    assert!(e.contains("geometry.conformity_nut: 0.5 (valid: (0.5, 1.0])"), "{e}");
    let path = spec_file(dir.path(), "contact_angle_deg = 45.0", "contact_angle_deg = 90");
    let e = fails(&["inspect", "--spec", path.to_str().unwrap()], 2);
    assert!(e.contains("geometry.contact_angle_deg: 90 (valid: (0, 90))"), "{e}");
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
        (&["sweep", "--speed-rpm", "1e9"], "invalid --speed-rpm: 1000000000 (valid:"),
        (&["inspect", "--preload-n", "-5"], "invalid --preload-n: -5 (valid:"),
        (&["torque", "--axial-load-n", "inf"], "invalid --axial-load-n: inf (valid:"),
        (&["sweep", "--preload", "3000..500"], "invalid --preload: 3000..500"),
        (&["sweep", "--preload", "-100..500"], "invalid --preload: -100 (valid:"),
        (&["sweep", "--preload", "five"], "invalid --preload: five"),
        (&["sweep", "--step", "0"], "invalid --step: 0 (valid: finite and > 0 N)"),
        (&["sweep", "--step", "-10"], "invalid --step: -10"),
        (&["sweep", "--preload", "0..1e7", "--step", "1"], "more than"),
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
    let a = ok(&["--format", "csv", "torque"]);
    let b = ok(&["torque", "--format", "csv"]);
    assert_eq!(a, b);
}

#[test]
fn help_and_version_succeed() {
    for cmd in [&["--help"][..], &["sweep", "--help"], &["--version"]] {
        let o = ballscrew(cmd);
        assert!(o.status.success());
    }
}
