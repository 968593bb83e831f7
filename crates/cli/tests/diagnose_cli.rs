//! `ballscrew predict` and `ballscrew diagnose` through the built binary.

mod common;

use common::{XJTU_DATA, XJTU_UPPER, fails, ok, ok_quiet};
use serde_json::Value;
use std::path::Path;

const BUILTIN: &str = include_str!("../../../configs/dkfzd4012.toml");

fn torque_json(extra: &[&str]) -> f64 {
    let mut args = vec!["torque", "--format", "json"];
    args.extend_from_slice(extra);
    let v: Value = serde_json::from_str(&ok(&args)).unwrap();
    v["torque_nm"].as_f64().unwrap()
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

#[test]
fn predict_appends_the_model_torque_to_each_row() {
    let dir = tempfile::tempdir().unwrap();
    let ops = write(dir.path(), "ops.csv", "preload_n,speed_rpm,note\n2000,100,a\n1000,-300,b\n");
    let out = ok(&["predict", "--data", &ops]);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines[0], "preload_n,speed_rpm,note,model_torque_nm");
    let t: Vec<f64> = lines[1..].iter().map(|l| l.rsplit(',').next().unwrap().parse().unwrap()).collect();
    assert!((t[0] - torque_json(&["--preload-n", "2000", "--speed-rpm", "100"])).abs() < 1e-9);
    assert!((t[1] - torque_json(&["--preload-n", "1000", "--speed-rpm", "-300"])).abs() < 1e-9);
    assert!(lines[2].starts_with("1000,-300,b,"));
}

/// `predict --format json`: the report's head, the spec's values of the columns the file lacks,
/// and per row its line, the known columns read (mapped ones by their own names) and the same
/// torque as the CSV's.
#[test]
fn predict_writes_json_with_the_rows_read_and_the_model_torque() {
    let dir = tempfile::tempdir().unwrap();
    let ops = write(dir.path(), "ops.csv", "# points\nFp,speed_rpm,note\n2000,100,a\n1000,-300,b\n");
    let csv = ok(&["predict", "--data", &ops, "--column", "preload_n=Fp"]);
    let v: Value =
        serde_json::from_str(&ok(&["predict", "--data", &ops, "--column", "preload_n=Fp", "--format", "json"]))
            .unwrap();
    assert_eq!((v["command"].as_str(), v["torque_route"].as_str()), (Some("predict"), Some("energy")), "{v}");
    assert!(v["spec"].as_str().unwrap().contains("DKFZD4012"), "{v}");
    assert_eq!(v["data"].as_str(), Some(ops.as_str()));
    // The file gives the speed and the preload: the axial load alone is the spec's.
    assert_eq!((v.get("speed_rpm"), v.get("preload_n"), v["axial_load_n"].as_f64()), (None, None, Some(0.0)), "{v}");
    let rows = v["rows"].as_array().unwrap();
    let keys: Vec<&str> = rows[0].as_object().unwrap().keys().map(String::as_str).collect();
    assert_eq!(keys, ["row", "preload_n", "speed_rpm", "model_torque_nm"]);
    assert_eq!((rows[0]["row"].as_u64(), rows[1]["row"].as_u64()), (Some(3), Some(4)));
    assert_eq!((rows[1]["preload_n"].as_f64(), rows[1]["speed_rpm"].as_f64()), (Some(1000.0), Some(-300.0)));
    let json_torques: Vec<f64> = rows.iter().map(|r| r["model_torque_nm"].as_f64().unwrap()).collect();
    assert_eq!(json_torques, model_column(&csv, ','));
}

/// An unknown column close to a known one the file lacks is named with it, in the warning of a
/// data file and in the error of a `--column` mapping; the rows still take the spec's speed.
#[test]
fn an_unknown_column_suggests_the_known_one() {
    let dir = tempfile::tempdir().unwrap();
    let ops = write(dir.path(), "ops.csv", "preload_n,rpm\n2000,300\n");
    let o = common::ballscrew(&["predict", "--data", &ops]);
    assert!(o.status.success());
    let warning = String::from_utf8(o.stderr).unwrap();
    assert!(warning.contains("unknown column(s) ignored: `rpm`"), "{warning}");
    assert!(warning.trim_end().ends_with("; `rpm`: did you mean `speed_rpm`?"), "{warning}");
    let out = String::from_utf8(o.stdout).unwrap();
    let t: f64 = out.lines().nth(1).unwrap().rsplit(',').next().unwrap().parse().unwrap();
    assert!((t - torque_json(&["--preload-n", "2000"])).abs() < 1e-9, "{out}");
    // A column the file has is not suggested for another header.
    let both = write(dir.path(), "both.csv", "speed_rpm,rpm\n300,300\n");
    let o = common::ballscrew(&["predict", "--data", &both]);
    let warning = String::from_utf8(o.stderr).unwrap();
    assert!(warning.contains("ignored: `rpm`") && !warning.contains("did you mean"), "{warning}");
    let e = fails(&["predict", "--data", &ops, "--column", "speed=rpm"], 2);
    assert!(e.contains("unknown column \"speed\"") && e.trim_end().ends_with("did you mean `speed_rpm`?"), "{e}");
}

/// `predict` warns once on stderr, in the core's words, when rows reach speeds where the
/// balls' inertia is not small (as `torque` and `sweep` do); the torques are still written.
#[test]
fn predict_warns_about_rows_beyond_the_quasi_static_model() {
    use ballscrew_core::input::rpm_to_rad_s;
    use ballscrew_core::screw::inertia;
    use ballscrew_core::{OperatingPoint, ScrewSpec};
    let dir = tempfile::tempdir().unwrap();
    let ops = write(dir.path(), "ops.csv", "preload_n,speed_rpm\n2000,100\n500,6000\n500,-5000\n");
    let o = common::ballscrew(&["predict", "--data", &ops]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(String::from_utf8_lossy(&o.stdout).lines().count(), 4);
    let spec = ScrewSpec::dkfzd4012();
    let point =
        |preload_n: f64, rpm: f64| OperatingPoint { speed_rad_s: rpm_to_rad_s(rpm), preload_n, axial_load_n: 0.0 };
    let w = inertia::check(
        &spec,
        spec.helix_angle_rad(),
        [point(2000.0, 100.0), point(500.0, 6000.0), point(500.0, -5000.0)],
    )
    .expect("beyond the quasi-static model");
    let e = String::from_utf8_lossy(&o.stderr);
    assert_eq!(e, format!("warning: {w}\n"));
    assert!(e.contains("at 2 of 3 points, the worst at speed 6000 rpm"), "{e}");
    // Ordinary rows: nothing on stderr.
    let ops = write(dir.path(), "quiet.csv", "preload_n,speed_rpm\n2000,100\n500,3000\n");
    ok_quiet(&["predict", "--data", &ops]);
}

/// A `temperature_c` column under the lubricated model: `predict` says that the oil at the
/// contacts stays at the spec's temperature on every row (the column only reaches the
/// `thermal_viscosity` term), where it used to give the same torque for 20 and 80 degrees C
/// without a word; under the dry model, which has no oil, it says nothing.
#[test]
fn predict_says_the_temperature_column_is_not_the_oil_temperature() {
    let dir = tempfile::tempdir().unwrap();
    let ops = write(dir.path(), "t.csv", "preload_n,speed_rpm,temperature_c\n1500,300,20\n1500,300,80\n");
    let o = common::ballscrew(&["predict", "--data", &ops]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{e}");
    assert_eq!(
        e,
        format!(
            "warning: {ops}: column `temperature_c`: the lubricated model's oil at the contacts stays at the \
             spec's lubricant.temperature_c (40 degrees C) on every row; the column enters only the \
             thermal_viscosity term, which this spec does not have: here it changes nothing\n"
        )
    );
    let dry = concat!(env!("CARGO_MANIFEST_DIR"), "/../../configs/dkfzd4012-dry.toml");
    ok_quiet(&["predict", "--spec", dry, "--data", &ops]);
}

#[test]
fn torque_sweep_and_predict_honour_the_spec_extensions() {
    let dir = tempfile::tempdir().unwrap();
    let spec = write(dir.path(), "seal.toml", &format!("{BUILTIN}\n[extensions.seal_drag]\ntorque_nm = 0.02\n"));
    let plain = torque_json(&[]);
    let sealed = torque_json(&["--spec", &spec]);
    assert!((sealed - plain - 0.02).abs() < 1e-9, "{sealed} vs {plain}");
    let reverse = torque_json(&["--spec", &spec, "--speed-rpm", "-100"]);
    assert!((reverse + sealed).abs() < 1e-9, "against the motion: {reverse}");
    let sweep = ok(&["sweep", "--spec", &spec, "--preload", "2000", "--format", "csv"]);
    // The torque column (found by its name: the operating point's columns come first); the
    // efficiency columns are empty (n/a) without an axial load.
    let column = sweep.lines().next().unwrap().split(',').position(|k| k == "torque_nm").unwrap();
    let torque: f64 = sweep.lines().nth(1).unwrap().split(',').nth(column).unwrap().parse().unwrap();
    assert!((torque - sealed).abs() < 1e-9, "{sweep}");
    let ops = write(dir.path(), "ops.csv", "preload_n\n2000\n");
    let p = ok(&["predict", "--spec", &spec, "--data", &ops]);
    let t: f64 = p.lines().nth(1).unwrap().rsplit(',').next().unwrap().parse().unwrap();
    assert!((t - sealed).abs() < 1e-9);
}

#[test]
fn diagnose_xjtu_writes_report_figures_and_extended_spec() {
    let dir = tempfile::tempdir().unwrap();
    let report = dir.path().join("report.json");
    let plots = dir.path().join("plots");
    let ext = dir.path().join("extended.toml");
    let text = ok(&[
        &XJTU_UPPER[..],
        &["--report", report.to_str().unwrap(), "--plots", plots.to_str().unwrap()],
        &["--out-spec", ext.to_str().unwrap()],
    ]
    .concat());
    assert!(text.contains("missing effect(s): preload_loss"), "{text}");
    let v: Value = serde_json::from_str(&std::fs::read_to_string(&report).unwrap()).unwrap();
    for key in ["baseline", "findings", "extended", "gain", "selection_rule", "residuals", "remaining_structure"] {
        assert!(!v[key].is_null(), "{key} missing");
    }
    // The lubricated model (the default) is far below this screw's torque: the calibrated
    // full-film traction rises to the top of its physical range, a level factor carries the
    // rest, no physical value of the oil's friction does, and the report says the model's level
    // is off (its first paragraph first).
    assert_eq!(v["lubrication"], "ehl");
    assert_eq!(v["calibration"][0]["name"], "full_film_traction");
    let mu = v["baseline"]["full_film_traction"].as_f64().unwrap();
    assert!(mu > v["baseline"]["spec_full_film_traction"].as_f64().unwrap(), "{mu}");
    assert_eq!(v["calibration"][0]["within_physical_range"], true);
    // The traction sits on the top of its fit's range: no standard error, and the note; the
    // creep reduction is chosen on a grid. One operating point cannot tell the boundary
    // friction from the level factor: neither has one. So the calibrated spec keeps the input
    // spec's spread, and its band at the data's point is the input spec's scaled by the level.
    for c in v["calibration"].as_array().unwrap() {
        assert!(c["standard_error"].is_null() && c["standard_error_note"].is_string(), "{c}");
    }
    assert!(v["calibration"][0]["standard_error_note"].as_str().unwrap().starts_with("on a bound of its fit"));
    let band = &v["band_narrowing"];
    assert_eq!(band["point"]["preload_n"].as_f64(), Some(1500.0), "{band}");
    assert!(band["width_ratio"].as_f64().unwrap() > 1.0 && band["relative_width_ratio"].as_f64().unwrap() < 1.0);
    assert!(text.contains("Band of the drag torque (5-95 %, 128 samples, seed 0) at the data's median point"));
    assert!(v["level"]["factor"].as_f64().unwrap() > 2.0 && v["level"]["absorbed"] == false, "{}", v["level"]);
    assert!(v["model_level_off"].is_string() && v["verdict"].as_str().unwrap().starts_with("the model's level is off"));
    let summary = v["summary"].as_str().unwrap();
    assert!(
        summary.starts_with("Calibrated within its physical ranges, the model is ") && summary.contains("re-preload")
    );
    assert!(text.contains(&summary[..60]), "{text}");
    assert_eq!(v["findings"][0]["effect"], "preload_loss");
    assert!(v["findings"][0]["heldout_rmse_after_nm"].as_f64() < v["findings"][0]["heldout_rmse_before_nm"].as_f64());
    assert!(v["gain"]["heldout_rmse_cut"].as_f64().unwrap() >= 0.3);
    for f in ["measured_vs_model.svg", "residual_time_h.svg"] {
        assert!(std::fs::read_to_string(plots.join(f)).unwrap().starts_with("<svg"), "{f}");
    }
    // The extended spec loads and gives the worn screw a smaller torque than at the start.
    let spec_text = std::fs::read_to_string(&ext).unwrap();
    assert!(spec_text.contains("[extensions.preload_loss]"), "{spec_text}");
    let ops = write(dir.path(), "ops.csv", "time_h\n0\n1000\n");
    let p = ok(&["predict", "--spec", ext.to_str().unwrap(), "--data", &ops]);
    let t: Vec<f64> = p.lines().skip(1).map(|l| l.rsplit(',').next().unwrap().parse().unwrap()).collect();
    assert!(t[1] < 0.8 * t[0], "{p}");
    // The JSON on stdout is the same report.
    let j = ok(&[&XJTU_UPPER[..], &["--format", "json"]].concat());
    assert_eq!(serde_json::from_str::<Value>(&j).unwrap(), v);
}

#[test]
fn bad_data_is_an_input_error_naming_row_and_column_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let mut text = String::from("torque_nm,preload_n\n");
    for i in 0..10 {
        text.push_str(&format!("0.0{i},{}\n", 500 + 100 * i));
    }
    text.push_str("0.05,abc\n");
    let data = write(dir.path(), "m.csv", &text);
    let report = dir.path().join("r.json");
    let e = fails(&["diagnose", "--data", &data, "--report", report.to_str().unwrap()], 2);
    assert!(e.contains("row 12, column `preload_n`: not a number"), "{e}");
    assert!(!report.exists());
    let e = fails(&["diagnose", "--data", &data, "--column", "speed=rpm"], 2);
    assert!(e.contains("unknown column \"speed\""), "{e}");
    let e = fails(&["predict", "--data", &dir.path().join("none.csv").display().to_string()], 2);
    assert!(e.contains("cannot read data file"), "{e}");
}

#[test]
fn side_files_naming_one_file_are_refused_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let same = dir.path().join("same.json");
    let s = same.to_str().unwrap();
    let e = fails(&[&XJTU_UPPER[..], &["--report", s, "--out", s]].concat(), 2);
    assert_eq!(e.trim_end(), format!("error: --report and --out name the same file: {s} and {s}"));
    let plots = dir.path().join("plots");
    let in_plots = plots.join("measured_vs_model.svg");
    let e = fails(
        &[&XJTU_UPPER[..], &["--plots", plots.to_str().unwrap(), "--out-spec", in_plots.to_str().unwrap()]].concat(),
        2,
    );
    assert!(e.starts_with("error: --plots and --out-spec name the same file: "), "{e}");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0, "nothing written, no directory made");
}

/// The last field of each data line of `predict`'s output, split at `delimiter`.
fn model_column(out: &str, delimiter: char) -> Vec<f64> {
    out.lines().skip(1).map(|l| l.rsplit(delimiter).next().unwrap().parse().unwrap()).collect()
}

#[test]
fn predict_reads_spreadsheet_csv_bom_semicolons_tabs_crlf_and_quotes() {
    let dir = tempfile::tempdir().unwrap();
    let t2000 = torque_json(&["--preload-n", "2000", "--speed-rpm", "100"]);
    let t1000 = torque_json(&["--preload-n", "1000", "--speed-rpm", "-300"]);
    // A byte order mark, semicolons, CRLF: every column read (no warning), written back in `;`.
    let ops = write(dir.path(), "excel.csv", "\u{feff}preload_n;speed_rpm\r\n2000;100\r\n1000;-300\r\n");
    let out = ok_quiet(&["predict", "--data", &ops]);
    assert!(out.starts_with("preload_n;speed_rpm;model_torque_nm\n2000;100;"), "{out}");
    let t = model_column(&out, ';');
    assert!((t[0] - t2000).abs() < 1e-9 && (t[1] - t1000).abs() < 1e-9, "{out}");
    // The same with the delimiter given, and with tabs, found or given.
    assert_eq!(ok_quiet(&["predict", "--data", &ops, "--delimiter", "semicolon"]), out);
    let tabs = write(dir.path(), "tabs.tsv", "preload_n\tspeed_rpm\n2000\t100\n1000\t-300\n");
    let out_tab = ok_quiet(&["predict", "--data", &tabs]);
    assert_eq!(out_tab, out.replace(';', "\t"));
    assert_eq!(ok_quiet(&["predict", "--data", &tabs, "--delimiter", "tab"]), out_tab);
    // A quoted header name with a comma, taken by --column, and quoted numbers.
    let quoted = write(dir.path(), "quoted.csv", "\"preload, N\",speed_rpm\n\"2000\",\"100\"\n");
    let out = ok_quiet(&["predict", "--data", &quoted, "--column", "preload_n=preload, N"]);
    assert!(out.starts_with("\"preload, N\",speed_rpm,model_torque_nm\n2000,100,"), "{out}");
    assert!((model_column(&out, ',')[0] - t2000).abs() < 1e-9, "{out}");
}

/// `--column` naming one source for two columns fed only the first (the second silently took
/// the spec's value, exit 0); it is refused, as is one column mapped from two sources.
#[test]
fn a_column_mapping_that_reads_one_header_twice_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let ops = write(dir.path(), "ops.csv", "Fp,n\n1500,300\n");
    let e = fails(&["predict", "--data", &ops, "--column", "preload_n=Fp", "--column", "axial_load_n=Fp"], 2);
    assert!(
        e.starts_with(&format!(
            "error: {ops}: column mappings preload_n=Fp and axial_load_n=Fp take the column `Fp` for two quantities"
        )),
        "{e}"
    );
    let e = fails(&["predict", "--data", &ops, "--column", "preload_n=Fp", "--column", "preload_n=n"], 2);
    assert!(e.contains("column mappings preload_n=Fp and preload_n=n map `preload_n` from two columns"), "{e}");
    // Each mapped once, every value is the one given.
    let out = ok_quiet(&["predict", "--data", &ops, "--column", "preload_n=Fp", "--column", "speed_rpm=n"]);
    let t = torque_json(&["--preload-n", "1500", "--speed-rpm", "300"]);
    assert!((model_column(&out, ',')[0] - t).abs() < 1e-9, "{out}");
}

/// `predict` on its own output wrote a second `model_torque_nm` column (pandas reads the first,
/// the stale one); a data file with the column is refused.
#[test]
fn predict_refuses_data_that_already_has_the_model_column() {
    let dir = tempfile::tempdir().unwrap();
    let ops = write(dir.path(), "ops.csv", "preload_n,speed_rpm\n1500,300\n");
    let once = write(dir.path(), "once.csv", &ok_quiet(&["predict", "--data", &ops]));
    let e = fails(&["predict", "--data", &once], 2);
    assert!(
        e.starts_with(&format!(
            "error: {once}: the data already has a column `model_torque_nm` (line 1), the column predict adds"
        )),
        "{e}"
    );
}

#[test]
fn diagnose_gives_the_same_report_on_a_semicolon_copy_of_the_data() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(XJTU_DATA).unwrap();
    let excel = write(dir.path(), "xjtu.csv", &format!("\u{feff}{}", text.replace(',', ";").replace('\n', "\r\n")));
    let mut args = XJTU_UPPER.to_vec();
    args[4] = &excel;
    let found = ok(&[&args[..], &["--format", "json"]].concat());
    let given = ok(&[&args[..], &["--format", "json", "--delimiter", ";"]].concat());
    let original = ok(&[&XJTU_UPPER[..], &["--format", "json"]].concat());
    assert_eq!(found, original);
    assert_eq!(given, original);
    let e = fails(&[&args[..], &["--delimiter", "|"]].concat(), 2);
    assert!(e.contains("invalid delimiter \"|\" (valid: comma"), "{e}");
}

#[test]
fn data_file_errors_name_the_file_and_line_alike() {
    let dir = tempfile::tempdir().unwrap();
    // Every kind of error in the row on line 5 (after a comment and a blank line) names line 5:
    // a cell that is not a number, a value out of range, a decimal comma, a row of the wrong
    // length and a row the model cannot evaluate (1 N of preload under the paper's dry model,
    // no load between balls; the lubricated default, and the ball train's loads, balance it).
    let file =
        |name: &str, row: &str| write(dir.path(), name, &format!("# ops\n\npreload_n;speed_rpm\n2000;100\n{row}\n"));
    let paper = BUILTIN.replacen("lubrication = \"ehl\"", "lubrication = \"dry\"", 1);
    let dry = write(dir.path(), "dry.toml", &paper.replacen("[friction]\n", "[friction]\nball_ball_load_n = 0.0\n", 1));
    for (name, row, code, says) in [
        ("parse.csv", "abc;100", 2, "row 5, column `preload_n`: not a number: \"abc\""),
        ("range.csv", "-5;100", 2, "row 5, column `preload_n`: -5 N is out of range"),
        ("comma.csv", "1500,5;100", 2, "row 5, column `preload_n`: decimal comma in \"1500,5\""),
        ("short.csv", "1500", 2, "row 5: 1 cells, the header (line 3) has 2"),
        ("model.csv", "1;100", 1, "row 5: ball balance did not converge"),
    ] {
        let path = file(name, row);
        let e = fails(&["predict", "--spec", &dry, "--data", &path], code);
        assert!(e.starts_with(&format!("error: {path}: {says}")), "{e}");
    }
    // A comma file whose first row has a decimal comma: the delimiter is not guessed.
    let path = write(dir.path(), "unclear.csv", "preload_n,speed_rpm\n1500,5,100\n");
    let e = fails(&["predict", "--data", &path], 2);
    assert!(
        e.starts_with(&format!(
            "error: {path}: cannot tell the delimiter: at comma (`,`) the header (line 1) splits into 2 field(s) \
             but line 2 into 3"
        )),
        "{e}"
    );
    let e = fails(&["diagnose", "--data", &path], 2);
    assert!(e.contains("cannot tell the delimiter"), "{e}");
}

/// The guide's XJTU section (`docs/diagnosis.md`, between its markers) is what `ballscrew
/// diagnose --format json` prints for the two screws, rendered: no number in it is copied by
/// hand. `BALLSCREW_BLESS=1` rewrites the section from the command.
#[test]
fn the_guides_xjtu_section_is_the_commands_output() {
    let sig = ballscrew_diagnose::text::sig;
    let mut table = String::from(
        "| screw | spec model: measured / model drag (95 %) | spec model RMSE | full-film traction | boundary friction \
         | level factor (95 %) | held-out RMSE, level-calibrated | finding | held-out RMSE, extended | gain |\n\
         |---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut paragraphs = String::new();
    for screw in ["upper", "lower"] {
        let column = format!("torque_nm={screw}_screw_torque_Nm");
        let mut args = XJTU_UPPER.to_vec();
        args[8] = &column;
        args.extend(["--format", "json"]);
        let v: Value = serde_json::from_str(&ok(&args)).unwrap();
        let num = |v: &Value| sig(v.as_f64().unwrap());
        let l = &v["level"];
        let factor = match l["factor"].as_f64() {
            Some(k) => format!("{} ({}-{})", sig(k), num(&l["factor_interval"][0]), num(&l["factor_interval"][1])),
            None => "none".into(),
        };
        let findings: Vec<String> = v["findings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| {
                let main = f["main_parameter"].as_str().unwrap();
                format!("`{}`, {main} = {}", f["effect"].as_str().unwrap(), num(&f["parameters"][main]))
            })
            .collect();
        let torque = |v: &Value| format!("{} N m", num(v));
        table.push_str(&format!(
            "| {screw} | {} ({}-{}) | {} | {} | {} | {factor} | {} | {} | {} | {:.0} % |\n",
            num(&l["spec_ratio"]),
            num(&l["spec_ratio_interval"][0]),
            num(&l["spec_ratio_interval"][1]),
            torque(&v["spec_model"]["rmse_nm"]),
            num(&v["extended"]["full_film_traction"]),
            num(&v["extended"]["boundary_friction"]),
            torque(&v["baseline"]["heldout_rmse_nm"]),
            if findings.is_empty() { "none".into() } else { findings.join("; ") },
            torque(&v["extended"]["heldout_rmse_nm"]),
            100.0 * v["gain"]["heldout_rmse_cut"].as_f64().unwrap()
        ));
        paragraphs.push_str(&format!(
            "The {screw} screw, the report's first paragraph:\n\n> {}\n\n",
            v["summary"].as_str().unwrap()
        ));
        let b = &v["band_narrowing"];
        let errors: Vec<String> = v["calibration"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| match c["standard_error"].as_f64() {
                Some(se) => format!("{} {}", c["name"].as_str().unwrap(), sig(se)),
                None => format!("{} none", c["name"].as_str().unwrap()),
            })
            .collect();
        paragraphs.push_str(&format!(
            "Standard errors: {}. The band of the drag torque (5-95 %) at {} rpm and {} N: input spec {}-{} N m, \
             calibrated spec {}-{} N m, width ratio {} ({} of the widths over the medians).\n\n",
            errors.join(", "),
            num(&b["point"]["speed_rpm"]),
            num(&b["point"]["preload_n"]),
            num(&b["spec_band"][0]),
            num(&b["spec_band"][1]),
            num(&b["calibrated_band"][0]),
            num(&b["calibrated_band"][1]),
            num(&b["width_ratio"]),
            num(&b["relative_width_ratio"])
        ));
    }
    const BEGIN: &str = "<!-- begin generated: the XJTU diagnosis (crates/cli/tests/diagnose_cli.rs) -->\n";
    const END: &str = "<!-- end generated -->";
    let generated = format!("{BEGIN}{table}\n{paragraphs}{END}");
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/diagnosis.md");
    let page = std::fs::read_to_string(path).unwrap();
    let (a, b) = (page.find(BEGIN).expect("the begin marker"), page.find(END).expect("the end marker") + END.len());
    let fresh = format!("{}{generated}{}", &page[..a], &page[b..]);
    if std::env::var_os("BALLSCREW_BLESS").is_some() {
        std::fs::write(path, &fresh).unwrap();
        return;
    }
    assert!(
        page == fresh,
        "docs/diagnosis.md's XJTU section is stale: run this test with BALLSCREW_BLESS=1\n{generated}"
    );
}
