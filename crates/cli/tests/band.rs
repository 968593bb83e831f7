//! The band of the drag torque on the command line: `torque --band`, `sweep --band` and
//! `sensitivity` give one band for one question (the same to the bit for the same point,
//! sample and seed), a pinned spec gives the nominal drag torque, and bad flags and spreads are
//! refused naming the flag or the spec key.

mod common;

use common::{fails, ok, ok_quiet};
use serde_json::Value;

const BAND_KEYS: [&str; 3] = ["drag_torque_low_nm", "drag_torque_median_nm", "drag_torque_high_nm"];

fn json(args: &[&str]) -> Value {
    serde_json::from_str(&ok_quiet(args)).unwrap()
}

/// The band's three numbers of a JSON object.
fn band_of(v: &Value) -> [f64; 3] {
    BAND_KEYS.map(|k| v[k].as_f64().unwrap_or_else(|| panic!("{k} in {v}")))
}

/// The text of every `<text>` element of an SVG, its quote unescaped.
fn texts(svg: &str) -> Vec<String> {
    svg.split("<text")
        .skip(1)
        .filter_map(|t| Some(t[t.find('>')? + 1..t.find("</text>")?].trim().replace("&apos;", "'")))
        .collect()
}

/// A copy of DKFZD4012's spec with `[uncertainty]` text appended, in a temporary directory.
fn spec_with(uncertainty: &str) -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../../configs/dkfzd4012.toml");
    // The shipped file's own `[uncertainty]` (the defaults, its last table) replaced.
    let text = std::fs::read_to_string(root).unwrap();
    let text = text.split("\n[uncertainty]\n").next().unwrap();
    let path = dir.path().join("spec.toml");
    std::fs::write(&path, format!("{text}\n[uncertainty]\n{uncertainty}\n")).unwrap();
    let path = path.to_str().unwrap().to_string();
    (dir, path)
}

#[test]
fn one_point_has_one_band_on_every_path() {
    let point = ["--preload-n", "1500", "--speed-rpm", "300"];
    let torque =
        json(&[&["torque", "--band", "--samples", "64", "--seed", "3", "--format", "json"][..], &point].concat());
    let sensitivity =
        json(&[&["sensitivity", "--samples", "64", "--seed", "3", "--format", "json"][..], &point].concat());
    let sweep = json(&[
        "sweep",
        "--preload-n",
        "500..2500",
        "--step",
        "500",
        "--speed-rpm",
        "300",
        "--band",
        "--samples",
        "64",
        "--seed",
        "3",
        "--format",
        "json",
    ]);
    let row = sweep["rows"].as_array().unwrap().iter().find(|r| r["preload_n"] == 1500.0).unwrap();
    assert_eq!(band_of(&torque), band_of(&sensitivity));
    assert_eq!(band_of(&torque), band_of(row));
    assert_eq!(torque["drag_torque_nm"], sensitivity["drag_torque_nm"]);
    assert_eq!(torque["band"], serde_json::json!({"quantiles": [0.05, 0.95], "samples": 64, "seed": 3}));
    let [low, median, high] = band_of(&torque);
    let nominal = torque["drag_torque_nm"].as_f64().unwrap();
    assert!(low < nominal && nominal < high && low < median && median < high, "{low} {median} {high} {nominal}");
    // CSV carries the same numbers, to the bit, after the other columns.
    let csv = ok(&[&["torque", "--band", "--samples", "64", "--seed", "3", "--format", "csv"][..], &point].concat());
    let (head, values) = csv.trim_end().split_once('\n').unwrap();
    let heads: Vec<&str> = head.split(',').collect();
    let values: Vec<&str> = values.split(',').collect();
    assert_eq!(heads[heads.len() - 3..], BAND_KEYS);
    for (k, want) in BAND_KEYS.iter().zip(band_of(&torque)) {
        let got: f64 = values[heads.iter().position(|h| h == k).unwrap()].parse().unwrap();
        assert_eq!(got, want, "{k}");
    }
}

#[test]
fn a_decimal_percentile_is_the_quantile_it_writes() {
    // 12.3 % is the double nearest 0.123 (Python's literal), not 12.3 / 100 rounded twice.
    let v = json(&["torque", "--band", "12.3,87.7", "--samples", "8", "--format", "json"]);
    assert_eq!(v["band"]["quantiles"], serde_json::json!([0.123, 0.877]));
    for bad in ["1e1,90", "5,", ",95", "5,95,99", "nan,95", "5,100.5"] {
        let e = fails(&["torque", "--band", bad], 2);
        assert!(e.starts_with(&format!("error: invalid --band: {bad} (valid: ")), "{bad}: {e}");
    }
}

#[test]
fn the_band_of_a_pinned_spec_is_the_drag_torque() {
    let pinned: String = ballscrew_core::input::UNCERTAIN_INPUTS.iter().map(|u| format!("{} = 0.0\n", u.key)).collect();
    let (_dir, spec) = spec_with(&pinned);
    let v = json(&["torque", "--spec", &spec, "--band", "--format", "json"]);
    let drag = v["drag_torque_nm"].as_f64().unwrap();
    assert_eq!(band_of(&v), [drag; 3]);
    let s = json(&["sensitivity", "--spec", &spec, "--format", "json"]);
    assert_eq!(s["inputs"], serde_json::json!([]));
    let table = ok(&["sensitivity", "--spec", &spec]);
    assert!(table.contains("every input is pinned"), "{table}");
}

#[test]
fn the_sensitivity_ranks_the_inputs_by_swing_and_draws_them() {
    let dir = tempfile::tempdir().unwrap();
    let plot = dir.path().join("tornado.svg");
    let v = json(&["sensitivity", "--samples", "32", "--format", "json", "--plot", plot.to_str().unwrap()]);
    let inputs = v["inputs"].as_array().unwrap();
    // DKFZD4012 under the lubricated model reads every input but the dry model's coefficient.
    assert_eq!(inputs.len(), ballscrew_core::input::INPUTS - 1);
    let swings: Vec<f64> = inputs.iter().map(|i| i["swing_nm"].as_f64().unwrap()).collect();
    assert!(swings.windows(2).all(|w| w[0] >= w[1]), "{swings:?}");
    for i in inputs {
        let (lo, hi) = (i["low_end_nm"].as_f64().unwrap(), i["high_end_nm"].as_f64().unwrap());
        assert_eq!(i["swing_nm"].as_f64().unwrap(), (hi - lo).abs());
        assert!(i["key"].as_str().unwrap().starts_with("uncertainty."), "{i}");
    }
    let svg = std::fs::read_to_string(&plot).unwrap();
    // One bar a side per input, its name on the axis with its spread.
    let texts = texts(&svg);
    for i in inputs {
        let name = i["input"].as_str().unwrap();
        assert!(texts.iter().any(|t| t.starts_with(&format!("{name} ±"))), "{name} is named with its spread");
    }
    assert!(texts.iter().any(|t| t == "preload ±30 %"), "a relative spread in per cent: {texts:?}");
    assert!(texts.iter().any(|t| t == "band of the whole sample"), "{texts:?}");
}

#[test]
fn the_sweep_plot_shades_the_band() {
    let dir = tempfile::tempdir().unwrap();
    let plot = dir.path().join("sweep.svg");
    ok(&[
        "sweep",
        "--preload-n",
        "500..1500",
        "--step",
        "500",
        "--band",
        "--samples",
        "16",
        "--plot",
        plot.to_str().unwrap(),
    ]);
    let texts = texts(&std::fs::read_to_string(&plot).unwrap());
    let legend = "model's band of the drag torque, 5-95 %, 16 samples, seed 0";
    assert!(texts.iter().any(|t| t == legend), "the legend names the band: {texts:?}");
}

#[test]
fn bad_band_flags_are_refused_naming_the_flag() {
    for (args, want) in [
        (&["torque", "--samples", "64"][..], "error: --samples needs --band"),
        (&["sweep", "--seed", "2"], "error: --seed needs --band"),
        (&["torque", "--band", "5,150"], "error: invalid --band: 5,150 (valid: two percentiles"),
        (&["torque", "--band", "95,5"], "error: invalid --band: 95,5"),
        (&["torque", "--band", "x"], "error: invalid --band: x"),
        (&["torque", "--band", "--samples", "4"], "error: invalid --samples: 4 (valid: a whole number in [8, 65536])"),
        (&["sensitivity", "--samples", "70000"], "error: invalid --samples: 70000"),
        (&["sensitivity", "--seed", "-1"], "error: invalid --seed: -1"),
    ] {
        let e = fails(args, 2);
        assert!(e.starts_with(want), "{args:?}: {e}");
    }
}

#[test]
fn a_spread_that_leaves_its_keys_range_is_refused_naming_the_key() {
    // 40 C +- 75 K: the half-width's own range ([0, 50] K) refuses it when the spec is read.
    let (_dir, spec) = spec_with("temperature_k = 75.0");
    let e = fails(&["torque", "--spec", &spec], 2);
    assert!(e.contains("uncertainty.temperature_k: 75"), "{e}");
    // -28 C +- 5 K: a valid spec, whose band would sample oil below -30 C.
    let (_dir, spec) = spec_with("");
    let text = std::fs::read_to_string(&spec).unwrap().replace("temperature_c = 40.0", "temperature_c = -28.0");
    std::fs::write(&spec, text).unwrap();
    ok(&["torque", "--spec", &spec, "--speed-rpm", "1"]);
    let e = fails(&["torque", "--spec", &spec, "--speed-rpm", "1", "--band"], 2);
    assert!(e.contains("invalid uncertainty.temperature_k: 5 (valid: a half-width that keeps"), "{e}");
}
