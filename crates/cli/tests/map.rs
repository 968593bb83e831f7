//! `ballscrew map`: the generated Rust source compiles (it is included below) and its stated
//! interpolation error is true; the checked-in source is what the command writes; the C header
//! compiles and its lookup agrees with the core's; the CSV reads back; bad flags are named.

mod common;

use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::realtime::map::TorqueMap;
use ballscrew_core::{Model, OperatingPoint, ScrewSpec, SolverState};
use common::{ballscrew, ok};
use std::process::Command;

/// The map of DKFZD4012 as `ballscrew map` writes it (the command is in the file's first line).
mod generated {
    include!("fixtures/dkfzd4012_torque_map.rs");
}
use generated::{
    TORQUE_MAP_AXIAL_LOAD_N, TORQUE_MAP_GRID, TORQUE_MAP_MAX_ABSOLUTE_ERROR_NM, TORQUE_MAP_MAX_RELATIVE_ERROR,
    TORQUE_MAP_VALUES,
};

const FIXTURE: &str = include_str!("fixtures/dkfzd4012_torque_map.rs");

fn fixture_map() -> TorqueMap<'static> {
    TorqueMap::new(TORQUE_MAP_GRID, &TORQUE_MAP_VALUES).expect("the generated map is valid")
}

/// The workspace root, which the fixture's spec path is relative to.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../");

/// The `ballscrew map ...` command in the fixture's first line, as arguments (its spec path
/// made absolute). The fixture maps the dry model (`configs/dkfzd4012-dry.toml`), whose torque
/// does not depend on the speed's magnitude: four speed points meet the half percent there. The
/// lubricated default's speed trend needs a finer speed axis than a uniform grid gives.
fn fixture_command() -> Vec<String> {
    let first = FIXTURE.lines().next().unwrap();
    let cmd = first.split('`').nth(1).expect("command in backticks");
    cmd.split_whitespace()
        .skip(1)
        .map(|a| if a.starts_with("configs/") { format!("{ROOT}{a}") } else { a.to_string() })
        .collect()
}

/// The spec the fixture maps.
fn fixture_spec() -> ScrewSpec {
    ballscrew_config::spec_from_toml_str(
        include_str!("../../../configs/dkfzd4012-dry.toml"),
        "configs/dkfzd4012-dry.toml",
    )
    .unwrap()
}

fn model_torque(model: &Model, state: &mut SolverState, preload_n: f64, speed_rad_s: f64) -> f64 {
    model.torque(&OperatingPoint { speed_rad_s, preload_n, axial_load_n: 0.0 }, state).unwrap()
}

/// The text with every number (sign included) replaced by `#`: what must not change when the
/// model's last digits do (they may even move the worst point to the other direction).
fn skeleton(text: &str) -> String {
    let mut out = String::new();
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        let signed = c == '-' && chars.peek().is_some_and(char::is_ascii_digit);
        if c.is_ascii_digit() || signed {
            while chars.peek().is_some_and(|d| d.is_ascii_digit() || ".eE+-".contains(*d)) {
                chars.next();
            }
            out.push('#');
        } else {
            out.push(c);
        }
    }
    out
}

/// The value of `pub const NAME: f64 = VALUE;` in a generated Rust source.
fn constant(text: &str, name: &str) -> f64 {
    let line = text.lines().find(|l| l.starts_with(&format!("pub const {name}: f64 = "))).unwrap();
    line.rsplit(' ').next().unwrap().trim_end_matches(';').parse().unwrap()
}

/// The checked-in source is what the command writes: the same text, the same grid, and the
/// same numbers up to the last bits of the model's arithmetic (values within 2e-7 relative,
/// the stated error within 1e-4 of itself).
#[test]
fn checked_in_rust_source_is_what_the_command_writes() {
    let args = fixture_command();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let text = ok(&args).replace(ROOT, "");
    let hint = "regenerate crates/cli/tests/fixtures/dkfzd4012_torque_map.rs with the command in its first line";
    assert_eq!(skeleton(&text), skeleton(FIXTURE), "{hint}");
    let grid_lines = |t: &str| {
        t.lines()
            .filter(|l| l.contains("_n:") || l.contains("_s:") || l.contains("points:"))
            .map(str::to_string)
            .collect::<Vec<_>>()
    };
    assert_eq!(grid_lines(&text), grid_lines(FIXTURE), "{hint}");
    for name in ["TORQUE_MAP_MAX_RELATIVE_ERROR", "TORQUE_MAP_MAX_ABSOLUTE_ERROR_NM"] {
        let (a, b) = (constant(&text, name), constant(FIXTURE, name));
        assert!((a - b).abs() <= 1e-4 * b.abs(), "{name}: {a} vs {b}: {hint}");
    }
    let start = text.find("TORQUE_MAP_VALUES: [f32;").unwrap();
    let body = &text[text[start..].find('=').unwrap() + start..];
    let values: Vec<f32> = body
        .split(|c: char| c == ',' || c == '[' || c == ']' || c.is_whitespace() || c == '=' || c == ';')
        .filter(|t| !t.is_empty())
        .map(|t| t.parse().unwrap())
        .collect();
    assert_eq!(values.len(), TORQUE_MAP_VALUES.len());
    for (a, b) in values.iter().zip(TORQUE_MAP_VALUES) {
        assert!((a - b).abs() <= 2e-7 * b.abs(), "{a} vs {b}: {hint}");
    }
}

#[test]
fn stated_interpolation_error_is_true_and_within_half_a_percent() {
    let map = fixture_map();
    let g = TORQUE_MAP_GRID;
    let model = Model::new(&fixture_spec()).unwrap();
    let mut state = SolverState::new();
    let omega0 = f64::from(g.standstill_speed_rad_s);
    assert_eq!(TORQUE_MAP_AXIAL_LOAD_N, 0.0);
    let mut worst: f64 = 0.0;
    let mut worst_abs: f64 = 0.0;
    let mut check = |p: f64, w: f64| {
        let t = model_torque(&model, &mut state, p, w);
        let m = f64::from(map.torque_nm(p as f32, w as f32));
        worst = worst.max((m - t).abs() / t.abs());
        worst_abs = worst_abs.max((m - t).abs());
    };
    for i in 0..g.preload_points - 1 {
        let p = f64::from(g.preload_min_n) + f64::from(g.preload_step_n) * (f64::from(i) + 0.5);
        for sign in [1.0, -1.0] {
            for k in 0..g.speed_points - 1 {
                check(p, sign * (f64::from(g.speed_min_rad_s) + f64::from(g.speed_step_rad_s) * (f64::from(k) + 0.5)));
            }
            check(p, sign * 0.5 * omega0);
        }
    }
    assert!(worst <= TORQUE_MAP_MAX_RELATIVE_ERROR * (1.0 + 1e-9), "{worst} above the stated error");
    assert!(worst >= TORQUE_MAP_MAX_RELATIVE_ERROR * (1.0 - 1e-9), "{worst} below the stated error");
    assert!((worst_abs - TORQUE_MAP_MAX_ABSOLUTE_ERROR_NM).abs() <= 1e-9 * worst_abs, "{worst_abs} N m");
    assert!(worst < 5e-3, "target 0.5 %: {worst}");
    // The nodes reproduce the model (f32 storage), the grid's corners included.
    for (p, rpm) in [(500.0, 100.0), (3000.0, -3000.0), (2000.0, 1000.0), (1250.0, -2000.0)] {
        let w = rpm_to_rad_s(rpm);
        let t = model_torque(&model, &mut state, p, w);
        let m = f64::from(map.torque_nm(p as f32, w as f32));
        assert!((m - t).abs() <= 1e-6 * t.abs(), "{p} N {rpm} rpm: map {m} model {t}");
    }
}

#[test]
fn csv_reads_back_to_the_same_values() {
    let mut args = fixture_command();
    *args.last_mut().unwrap() = "csv".into();
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let text = ok(&args);
    let mut lines = text.lines().skip_while(|l| l.starts_with('#'));
    assert_eq!(lines.next(), Some("sheet,preload_n,speed_rad_s,speed_rpm,torque_nm"));
    let values: Vec<f32> = lines.map(|l| l.rsplit(',').next().unwrap().parse().unwrap()).collect();
    assert_eq!(values, TORQUE_MAP_VALUES);
    assert!(text.lines().next().unwrap().starts_with("# Drive torque map of"));
}

/// Compiles the generated header with the system C compiler (warnings as errors, C99, pedantic)
/// into a program that prints the lookup at many points, and compares with the core's lookup.
#[test]
fn c_header_compiles_and_its_lookup_equals_the_cores() {
    if Command::new("cc").arg("--version").output().is_err() {
        eprintln!("no C compiler (cc) on this machine: the C header is not compiled here");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let header = dir.path().join("ballscrew_torque_map.h");
    let mut args = fixture_command();
    *args.last_mut().unwrap() = "c".into();
    args.push("--out".into());
    args.push(header.display().to_string());
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    assert!(ok(&args).is_empty());
    // Preloads past both ends of the grid, speeds past +-3000 rpm, and through standstill.
    let points: Vec<(f32, f32)> = (0..400)
        .map(|k| (300.0 + 7.3 * k as f32, -340.0 + 1.7 * k as f32))
        .chain((0..=40).map(|k| (1700.0 + 10.0 * k as f32, -0.012 + 6e-4 * k as f32)))
        .collect();
    let calls: String = points
        .iter()
        .map(|(p, w)| format!("    printf(\"%.9g\\n\", (double)ballscrew_torque_map_nm({p:?}f, {w:?}f));\n"))
        .collect();
    let main = format!(
        "#include <stdio.h>\n#include \"ballscrew_torque_map.h\"\nint main(void)\n{{\n{calls}    return 0;\n}}\n"
    );
    let src = dir.path().join("main.c");
    std::fs::write(&src, main).unwrap();
    let exe = dir.path().join("lookup");
    let cc = Command::new("cc")
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-O2", "-ffp-contract=off", "-o"])
        .arg(&exe)
        .arg(&src)
        .output()
        .unwrap();
    assert!(cc.status.success(), "cc: {}", String::from_utf8_lossy(&cc.stderr));
    let out = Command::new(&exe).output().unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    let map = fixture_map();
    let c_values: Vec<f32> = text.lines().map(|l| l.parse().unwrap()).collect();
    assert_eq!(c_values.len(), points.len());
    for ((p, w), c) in points.iter().zip(c_values) {
        let r = map.torque_nm(*p, *w);
        // The same f32 operations in the same order (no contraction into FMA): equal bits.
        assert_eq!(c.to_bits(), r.to_bits(), "{p} N {w} rad/s: C {c} Rust {r}");
    }
}

#[test]
fn bad_flags_are_named() {
    for (args, needle) in [
        (&["map", "--preload", "3000..500"][..], "invalid --preload: 3000..500"),
        (&["map", "--preload", "-5..500"][..], "invalid --preload: -5"),
        (&["map", "--preload-points", "1"][..], "invalid --preload-points: 1"),
        (&["map", "--speed-points", "100000"][..], "invalid --speed-points: 100000"),
        (&["map", "--preload-step", "0"][..], "invalid --preload-step: 0"),
        (&["map", "--speed-rpm", "40000..50000"][..], "invalid --speed-rpm: 40000"),
        (&["map", "--speed-rpm", "-100..100", "--speed-step-rpm", "nan"][..], "invalid --speed-step-rpm: NaN"),
        (&["map", "--format", "json"][..], "invalid --format: json"),
        (&["sweep", "--format", "c"][..], "invalid --format: c and rust are for `ballscrew map`"),
    ] {
        let o = ballscrew(args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(o.stdout.is_empty());
        let e = String::from_utf8(o.stderr).unwrap();
        assert!(e.starts_with("error: ") && e.contains(needle), "{args:?}: {e}");
    }
}

#[test]
fn steps_give_a_grid_that_reaches_the_end_of_the_range() {
    let text = ok(&[
        "map",
        "--preload",
        "500..3000",
        "--preload-step",
        "300",
        "--speed-rpm",
        "100..3000",
        "--speed-step-rpm",
        "1000",
    ]);
    // 3000 N and 3000 rpm are reached by the last step (f32 grid: 3100 rpm to 7 digits).
    assert!(text.contains("grid: preload 500..3200 N x 10 points, speed magnitude 100..3100"), "{text}");
    assert!(text.contains(" rpm x 4 points"), "{text}");
}

#[test]
fn out_file_is_written_whole() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("map.h");
    ok(&[
        "map",
        "--preload",
        "1000..2000",
        "--preload-points",
        "3",
        "--speed-points",
        "2",
        "--format",
        "c",
        "--out",
        out.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.starts_with("/*") && text.trim_end().ends_with("#endif /* BALLSCREW_TORQUE_MAP_H */"));
    assert!(text.contains("#define BALLSCREW_TORQUE_MAP_LEN (15)"));
    // A failing map leaves the file as it was.
    let o = ballscrew(&["map", "--preload", "2000..1000", "--out", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), text);
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1, "no temporary left");
}
