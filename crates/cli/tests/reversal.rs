//! `ballscrew reversal` through the built binary: the friction state model stepped through a
//! sinusoidal reversal against the static model, its summary, its plot and its refusals.
//!
//! All but one run take steps of 1e-5 rad (a tenth of the time of the default 1e-6 rad; the
//! core's own test holds the two within 1 %).

mod common;

use common::{fails, ok_quiet as ok};
use serde_json::Value;
use std::path::Path;

const BUILTIN: &str = include_str!("../../../configs/dkfzd4012.toml");
/// Steps of the quicker runs, rad.
const STEP: [&str; 2] = ["--step-rad", "1e-5"];

/// `reversal` with `args` after the quicker step.
fn quick(args: &[&str]) -> Vec<String> {
    ["reversal", STEP[0], STEP[1]].iter().chain(args).map(|s| (*s).to_string()).collect()
}

fn run_ok(args: &[String]) -> String {
    ok(&args.iter().map(String::as_str).collect::<Vec<_>>())
}

fn json(text: &str) -> Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("{e}: {text}"))
}

fn num(v: &Value, key: &str) -> f64 {
    v[key].as_f64().unwrap_or_else(|| panic!("no number {key} in {v}"))
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(1e-300)
}

/// A `# key = value` line of the CSV: key and value.
type Pair = (String, String);

/// CSV with `#` lines first: the summary (`# key = value`), the header, the rows of numbers.
fn csv(text: &str) -> (Vec<Pair>, Vec<String>, Vec<Vec<f64>>) {
    let mut summary = Vec::new();
    let mut lines = text.lines().peekable();
    while let Some(line) = lines.next_if(|l| l.starts_with('#')) {
        if let Some((k, v)) = line.trim_start_matches("# ").split_once(" = ") {
            summary.push((k.to_string(), v.to_string()));
        }
    }
    let header: Vec<String> = lines.next().unwrap().split(',').map(str::to_string).collect();
    let rows: Vec<Vec<f64>> = lines.map(|l| l.split(',').map(|f| f.parse().unwrap()).collect()).collect();
    assert!(rows.iter().all(|r| r.len() == header.len()));
    (summary, header, rows)
}

/// The value of a `# key = value` line.
fn summary_value<'a>(summary: &'a [Pair], key: &str) -> &'a str {
    summary.iter().find(|(k, _)| k == key).unwrap_or_else(|| panic!("no summary line {key}")).1.as_str()
}

fn column(header: &[String], rows: &[Vec<f64>], key: &str) -> Vec<f64> {
    let i = header.iter().position(|h| h == key).unwrap_or_else(|| panic!("no column {key}"));
    rows.iter().map(|r| r[i]).collect()
}

/// The row keys every format shares.
const COLUMNS: [&str; 5] = ["time_s", "angle_rad", "speed_rpm", "torque_nm", "static_torque_nm"];
/// The summary keys.
const SUMMARY: [&str; 11] = [
    "preload_n",
    "axial_load_n",
    "speed_rpm",
    "amplitude_rad",
    "stiffness_nm_per_rad",
    "steady_torque_before_nm",
    "steady_torque_after_nm",
    "zero_crossing_angle_rad",
    "zero_crossing_travel_um",
    "reformed_90_angle_rad",
    "reformed_90_travel_um",
];

/// With no flags at all: the built-in spec, 10 rpm, 1e-6 rad steps, at most 400 rows, every
/// summary line and both columns of torque.
#[test]
fn reversal_runs_with_no_flags() {
    let out = ok(&["reversal"]);
    let first = out.lines().next().unwrap();
    assert!(first.starts_with("ballscrew reversal: built-in DKFZD4012"), "{first}");
    assert!(first.contains("peak speed 10 rpm") && first.contains("preload 2000 N"), "{first}");
    for label in [
        "Dahl stiffness sigma",
        "steady torque before the reversal",
        "steady torque after the reversal",
        "screw angle from the turning point to the torque's zero crossing",
        "screw angle from the turning point to 90 % of the new steady torque",
        "nut travel (angle x lead / 2 pi)",
        "N m/rad",
        "1.0000e-6",
    ] {
        assert!(out.contains(label), "{label}: {out}");
    }
    let heads = out.lines().find(|l| l.trim_start().starts_with("time") && l.contains("angle")).unwrap();
    assert!(heads.contains("speed") && heads.contains("torque") && heads.contains("static"), "{heads}");
    let rows = out
        .lines()
        .skip_while(|l| !l.trim_start().starts_with("---"))
        .skip(1)
        .skip_while(|l| !l.trim_start().starts_with("---"))
        .skip(1)
        .count();
    assert!(rows > 300 && rows <= 400, "{rows} rows");
}

/// CSV and JSON carry the same summary and rows to the last digit; the rows run from the start
/// (time 0, angle 0, the peak speed) to the next zero crossing, the first and last included.
#[test]
fn csv_and_json_agree_and_cover_the_reversal() {
    let (summary, header, rows) = csv(&run_ok(&quick(&["--format", "csv"])));
    assert_eq!(header, COLUMNS);
    let v = json(&run_ok(&quick(&["--format", "json"])));
    assert_eq!(v["command"], "reversal");
    assert_eq!(v["precision"], "f64");
    for key in SUMMARY {
        let text = summary_value(&summary, key);
        assert_eq!(text.parse::<f64>().unwrap(), num(&v, key), "{key}");
    }
    let list = v["rows"].as_array().unwrap();
    assert_eq!(list.len(), rows.len());
    for (row, csv_row) in list.iter().zip(&rows) {
        for (key, x) in COLUMNS.iter().zip(csv_row) {
            assert_eq!(num(row, key), *x, "{key}");
        }
    }
    let angle = column(&header, &rows, "angle_rad");
    let speed = column(&header, &rows, "speed_rpm");
    assert_eq!((angle[0], *angle.last().unwrap()), (0.0, 0.0));
    assert_eq!(speed[0], num(&v, "speed_rpm"));
    let top = angle.iter().copied().fold(0.0, f64::max);
    assert!(top <= num(&v, "amplitude_rad") && top > 0.99 * num(&v, "amplitude_rad"), "{top}");
    // --rows: at most that many, the first and the last kept: the same samples of the state
    // model (the static model's warm start, which depends on the rows evaluated before, moves
    // its torque within the evaluator's tolerance only).
    let (_, _, few) = csv(&run_ok(&quick(&["--format", "csv", "--rows", "7"])));
    assert!(few.len() <= 7 && few.len() >= 5, "{}", few.len());
    for (a, b) in [(&few[0], &rows[0]), (few.last().unwrap(), rows.last().unwrap())] {
        assert_eq!(a[..4], b[..4]);
        assert!((a[4] - b[4]).abs() <= 1e-9 * b[4].abs(), "{} vs {}", a[4], b[4]);
    }
}

/// Through the reversal the torque changes sign, the static model at once, the state model
/// over a rotation: it crosses zero after the turning point, before it reaches 90 % of its new
/// steady value, both within the amplitude; the travels are the angles times lead / 2 pi.
#[test]
fn the_torque_reforms_after_the_turning_point() {
    let v = json(&run_ok(&quick(&["--format", "json"])));
    let (zero, reformed) = (num(&v, "zero_crossing_angle_rad"), num(&v, "reformed_90_angle_rad"));
    assert!(zero > 0.0 && zero < reformed && reformed < num(&v, "amplitude_rad"), "{zero} {reformed}");
    let lead_m = 12e-3;
    for (angle, travel) in [(zero, "zero_crossing_travel_um"), (reformed, "reformed_90_travel_um")] {
        assert!(rel(num(&v, travel), angle * lead_m / core::f64::consts::TAU * 1e6) < 1e-12, "{travel}");
    }
    let (before, after) = (num(&v, "steady_torque_before_nm"), num(&v, "steady_torque_after_nm"));
    assert!(before > 0.0 && after < 0.0, "{before} {after}");
    assert!(num(&v, "stiffness_nm_per_rad") > 0.0);
    let rows = v["rows"].as_array().unwrap();
    let torque: Vec<f64> = rows.iter().map(|r| num(r, "torque_nm")).collect();
    assert_eq!(torque[0], before);
    assert!(*torque.last().unwrap() < 0.0);
    assert!(rows.iter().any(|r| num(r, "torque_nm") > 0.0 && num(r, "speed_rpm") < 0.0));
    // Where the static model has already reversed, the state model has not: the difference.
    assert!(
        rows.iter().any(|r| num(r, "speed_rpm") < 0.0 && num(r, "static_torque_nm") < 0.0 && num(r, "torque_nm") > 0.0),
        "no row between the two reversals"
    );
    // Starting backwards: the mirror image (the model is symmetric without an axial load).
    let back = json(&run_ok(&quick(&["--format", "json", "--speed-rpm", "-10"])));
    assert!(num(&back, "steady_torque_before_nm") < 0.0 && num(&back, "steady_torque_after_nm") > 0.0);
    for key in ["zero_crossing_angle_rad", "reformed_90_angle_rad"] {
        assert!(rel(num(&back, key), num(&v, key)) < 1e-6, "{key}: {} vs {}", num(&back, key), num(&v, key));
    }
    // f32: the same within the evaluator's single-precision tolerance.
    let single = json(&run_ok(&quick(&["--format", "json", "--precision", "f32"])));
    assert_eq!(single["precision"], "f32");
    for key in ["zero_crossing_angle_rad", "reformed_90_angle_rad", "steady_torque_before_nm"] {
        assert!(rel(num(&single, key), num(&v, key)) < 1e-3, "{key}: {} vs {}", num(&single, key), num(&v, key));
    }
}

/// The static column is `ballscrew torque` at the row's speed, preload and axial load; with an
/// axial load the re-formation is measured on the torque less the axial term (the load torque,
/// `torque`'s `load_torque_nm`).
#[test]
fn static_torque_is_the_torque_command_at_the_same_point() {
    let point = ["--preload-n", "1500", "--axial-load-n", "300"];
    let v = json(&run_ok(&quick(&[&["--format", "json"][..], &point].concat())));
    assert_eq!((num(&v, "preload_n"), num(&v, "axial_load_n")), (1500.0, 300.0));
    let rows = v["rows"].as_array().unwrap();
    let scale = num(&v, "steady_torque_before_nm").abs();
    // The start, the slowest row (in the static model's fade) and the end.
    let slowest = rows.iter().min_by(|a, b| num(a, "speed_rpm").abs().total_cmp(&num(b, "speed_rpm").abs())).unwrap();
    for row in [&rows[0], slowest, rows.last().unwrap()] {
        let speed = format!("--speed-rpm={}", num(row, "speed_rpm"));
        let t = json(&ok(&[&["torque", "--format", "json", &speed][..], &point].concat()));
        let (mine, theirs) = (num(row, "static_torque_nm"), num(&t, "torque_nm"));
        assert!((mine - theirs).abs() <= 1e-8 * scale, "{speed}: {mine} vs {theirs}");
        assert_eq!(num(&v, "load_torque_nm"), num(&t, "load_torque_nm"));
    }
    assert!(num(slowest, "speed_rpm").abs() < 0.1, "a row in the fade: {slowest}");
    let axial = num(&v, "load_torque_nm");
    assert!(axial > 0.0);
    let (before, after) = (num(&v, "steady_torque_before_nm") - axial, num(&v, "steady_torque_after_nm") - axial);
    assert!(before > 0.0 && after < 0.0, "{before} {after}");
    let (zero, reformed) = (num(&v, "zero_crossing_angle_rad"), num(&v, "reformed_90_angle_rad"));
    assert!(zero > 0.0 && zero < reformed, "{zero} {reformed}");
}

/// `--plot`: an SVG with both panels, the data to `--out`; the same run that fails writes
/// neither.
#[test]
fn plot_writes_both_panels() {
    let dir = tempfile::tempdir().unwrap();
    let svg_path = dir.path().join("reversal.svg");
    let data = dir.path().join("reversal.csv");
    let args = quick(&["--format", "csv", "--plot", svg_path.to_str().unwrap(), "--out", data.to_str().unwrap()]);
    assert!(run_ok(&args).is_empty());
    let svg = std::fs::read_to_string(&svg_path).unwrap();
    let head = svg.trim_start();
    assert!(head.starts_with("<svg") || head.starts_with("<?xml"), "{}", &svg[..svg.len().min(200)]);
    assert!(svg.trim_end().ends_with("</svg>"));
    for title in [
        "(a) Torque through a reversal against the screw angle",
        "(b) Hysteresis loop of a small oscillation about standstill",
        "state model",
        "static model",
        "screw angle θ, rad",
        "drive torque, N m",
    ] {
        assert!(svg.contains(title), "{title}");
    }
    let (summary, _, rows) = csv(&std::fs::read_to_string(&data).unwrap());
    assert!(!rows.is_empty() && summary_value(&summary, "zero_crossing_angle_rad").parse::<f64>().is_ok());
    // A bad flag: nothing written, not even the plot.
    let failed = dir.path().join("failed.svg");
    fails(&["reversal", "--amplitude-rad", "0", "--plot", failed.to_str().unwrap()], 2);
    assert!(!failed.exists());
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2, "no temporary files left");
}

fn with_extensions(dir: &Path) -> String {
    let path = dir.join("spec.toml");
    std::fs::write(&path, format!("{BUILTIN}\n[extensions.seal_drag]\ntorque_nm = 0.02\n")).unwrap();
    path.to_str().unwrap().to_string()
}

/// Every bad flag is refused with exit code 2 before anything is evaluated, naming the flag,
/// the value and the valid range; so are a spec with extension terms and a preload too light
/// for the model; nothing is written.
#[test]
fn bad_flags_are_named_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let spec = with_extensions(dir.path());
    let cases: &[(&[&str], &str)] = &[
        (&["--amplitude-rad", "0"], "invalid --amplitude-rad: 0 (valid: finite, [1e-6, 100] rad)"),
        (&["--amplitude-rad", "nan"], "invalid --amplitude-rad: NaN (valid:"),
        (&["--amplitude-rad", "-0.01"], "invalid --amplitude-rad: -0.01 (valid:"),
        (&["--amplitude-rad", "1e3"], "invalid --amplitude-rad: 1000 (valid:"),
        (&["--step-rad", "0"], "invalid --step-rad: 0 (valid: finite, [--amplitude-rad / 1e5, --amplitude-rad / 10]"),
        (&["--step-rad", "1e-9"], "invalid --step-rad: 1e-9 (valid:"),
        (&["--step-rad", "0.01"], "= [1e-7, 0.001] rad)"),
        (&["--amplitude-rad", "0.003", "--step-rad", "1"], "= [3e-8, 0.0003] rad)"),
        (&["--step-rad", "inf"], "invalid --step-rad: inf (valid:"),
        (&["--speed-rpm", "0"], "invalid --speed-rpm: 0 (valid: finite, nonzero, |speed| <= 30000 rpm)"),
        (&["--speed-rpm", "nan"], "invalid --speed-rpm: NaN (valid:"),
        (&["--speed-rpm", "1e9"], "invalid --speed-rpm: 1e9 (valid:"),
        (&["--rows", "1"], "invalid --rows: 1 (valid: integer in [2, 100000])"),
        (&["--rows", "100001"], "invalid --rows: 100001 (valid: integer in [2, 100000])"),
        (&["--preload-n", "-5"], "invalid --preload-n: -5 N (valid:"),
        (&["--axial-load-n", "inf"], "invalid --axial-load-n: inf (valid:"),
        (&["--preload-n", "1"], "invalid --preload-n: 1 N (valid: every loaded ball above 0.5 N"),
        (&["--preload-n", "0"], "invalid --preload-n: 0 N (valid: a load on the balls (a preload, or an axial load)"),
        (&["--precision", "f16"], "'--precision <PRECISION>'"),
        (&["--spec", &spec], "invalid extensions: extension terms (valid: none, for the reversal model)"),
        (&["--format", "c"], "invalid value 'c' for '--format <FORMAT>'"),
    ];
    for (flags, message) in cases {
        let out = dir.path().join("out.txt");
        let plot = dir.path().join("plot.svg");
        let args =
            [&["reversal"][..], flags, &["--out", out.to_str().unwrap(), "--plot", plot.to_str().unwrap()]].concat();
        let e = fails(&args, 2);
        assert!(e.contains(message), "{flags:?}: {e}");
        assert!(!out.exists() && !plot.exists(), "{flags:?}: a file was written");
    }
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1, "only the spec: no temporary files left");
}

/// A peak speed below the standstill speed (0.1 rpm): the steady torques of the summary and the
/// first row are the state model's running torque, not the static model's faded one, so the
/// 90 % angle is read against the model's own new value.
#[test]
fn below_the_standstill_speed_the_summary_is_the_state_models() {
    let v = json(&run_ok(&quick(&["--format", "json", "--speed-rpm", "0.05", "--amplitude-rad", "0.005"])));
    let rows = v["rows"].as_array().unwrap();
    let (first, last) = (&rows[0], rows.last().unwrap());
    let before = num(&v, "steady_torque_before_nm");
    assert_eq!(num(first, "torque_nm"), before);
    assert!(num(first, "static_torque_nm") < 0.9 * before, "the static model fades here");
    // The state ends near its steady value after the reversal (within the re-formation's tail).
    let after = num(&v, "steady_torque_after_nm");
    assert!(rel(num(last, "torque_nm"), after) < 0.01, "{} {after}", num(last, "torque_nm"));
}

/// 30000 rpm, the documented top of the speed range, runs in f32 as in f64 (on the dry model:
/// the lubricated one refuses it for the oil's thermal loading in both): the speed is rounded to
/// the f32 inside the range, not to the nearest f32 above it, which was refused as beyond
/// 30000 rpm.
#[test]
fn the_top_of_the_speed_range_runs_in_f32() {
    for speed in ["30000", "-30000"] {
        let run = |precision: &str| {
            json(&run_ok(&quick(&[
                "--spec",
                concat!(env!("CARGO_MANIFEST_DIR"), "/../../configs/dkfzd4012-dry.toml"),
                "--format",
                "json",
                "--speed-rpm",
                speed,
                "--precision",
                precision,
            ])))
        };
        let (v32, v64) = (run("f32"), run("f64"));
        assert_eq!(v32["precision"], "f32");
        for key in ["steady_torque_before_nm", "steady_torque_after_nm"] {
            assert!(rel(num(&v32, key), num(&v64, key)) < 1e-4, "{speed} rpm {key}: {v32} vs {v64}");
        }
    }
}
