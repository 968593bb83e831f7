//! `ballscrew map`: the generated Rust source compiles (it is included below) and its stated
//! interpolation error is true; the checked-in source is what the command writes; the C header
//! compiles and its lookup agrees with the core's; the CSV reads back; bad flags are named.

mod common;

use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::realtime::map::{GEOMETRIC_EXPONENT, MapGrid, Spacing, TorqueMap};
use ballscrew_core::{Model, OperatingPoint, ScrewSpec, SolverState};
use common::{ballscrew, ok};
use std::process::Command;

/// The map of the dry DKFZD4012 as `ballscrew map` writes it (the command is in the file's
/// first line): `configs/dkfzd4012-dry.toml`, whose torque does not depend on the speed's
/// magnitude, on a uniform speed axis of four points.
mod dry {
    include!("fixtures/dkfzd4012_torque_map.rs");
}

/// The default map of the built-in, lubricated DKFZD4012 (`ballscrew map` with no flags; the
/// command is in the file's first line): a geometric speed axis.
mod lubricated {
    include!("fixtures/dkfzd4012_lubricated_torque_map.rs");
}

/// A checked-in map: its text, its constants and the spec it maps.
struct Fixture {
    name: &'static str,
    text: &'static str,
    grid: MapGrid,
    values: &'static [f32],
    axial_load_n: f64,
    max_relative_error: f64,
    max_absolute_error_nm: f64,
    spec: fn() -> ScrewSpec,
}

const FIXTURES: [Fixture; 2] = [
    Fixture {
        name: "dkfzd4012_torque_map.rs",
        text: include_str!("fixtures/dkfzd4012_torque_map.rs"),
        grid: dry::TORQUE_MAP_GRID,
        values: &dry::TORQUE_MAP_VALUES,
        axial_load_n: dry::TORQUE_MAP_AXIAL_LOAD_N,
        max_relative_error: dry::TORQUE_MAP_MAX_RELATIVE_ERROR,
        max_absolute_error_nm: dry::TORQUE_MAP_MAX_ABSOLUTE_ERROR_NM,
        spec: dry_spec,
    },
    Fixture {
        name: "dkfzd4012_lubricated_torque_map.rs",
        text: include_str!("fixtures/dkfzd4012_lubricated_torque_map.rs"),
        grid: lubricated::TORQUE_MAP_GRID,
        values: &lubricated::TORQUE_MAP_VALUES,
        axial_load_n: lubricated::TORQUE_MAP_AXIAL_LOAD_N,
        max_relative_error: lubricated::TORQUE_MAP_MAX_RELATIVE_ERROR,
        max_absolute_error_nm: lubricated::TORQUE_MAP_MAX_ABSOLUTE_ERROR_NM,
        spec: lubricated_spec,
    },
];

impl Fixture {
    fn map(&self) -> TorqueMap<'static> {
        TorqueMap::new(self.grid, self.values).expect("the generated map is valid")
    }

    /// The `ballscrew map ...` command in the fixture's first line, as arguments (its spec
    /// path made absolute).
    fn command(&self) -> Vec<String> {
        let first = self.text.lines().next().unwrap();
        let cmd = first.split('`').nth(1).expect("command in backticks");
        cmd.split_whitespace()
            .skip(1)
            .map(|a| if a.starts_with("configs/") { format!("{ROOT}{a}") } else { a.to_string() })
            .collect()
    }

    /// The command with another --format, and more arguments.
    fn command_as(&self, format: &str, more: &[String]) -> Vec<String> {
        let mut args = self.command();
        *args.last_mut().unwrap() = format.into();
        args.extend_from_slice(more);
        args
    }

    fn hint(&self) -> String {
        format!("regenerate crates/cli/tests/fixtures/{} with the command in its first line", self.name)
    }
}

/// The workspace root, which the fixtures' spec paths are relative to.
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../");

fn dry_spec() -> ScrewSpec {
    ballscrew_config::spec_from_toml_str(
        include_str!("../../../configs/dkfzd4012-dry.toml"),
        "configs/dkfzd4012-dry.toml",
    )
    .unwrap()
}

/// The built-in spec (`configs/dkfzd4012.toml`).
fn lubricated_spec() -> ScrewSpec {
    ballscrew_config::spec_from_toml_str(include_str!("../../../configs/dkfzd4012.toml"), "configs/dkfzd4012.toml")
        .unwrap()
}

fn model_torque(model: &Model, state: &mut SolverState, preload_n: f64, speed_rad_s: f64) -> f64 {
    model.torque(&OperatingPoint { speed_rad_s, preload_n, axial_load_n: 0.0 }, state).unwrap()
}

/// Speed node `k` of the grid as the tabulation evaluates the model at it (the lookup's node,
/// in f32), rad/s.
fn speed_node(g: &MapGrid, k: u32) -> f64 {
    f64::from(g.speed_rad_s(k))
}

/// The middle of speed cell `k` in the coordinate the lookup interpolates in (the speed, or
/// on a geometric axis its power `GEOMETRIC_EXPONENT`), rad/s.
fn speed_midpoint(g: &MapGrid, k: u32) -> f64 {
    let (a, b) = (speed_node(g, k), speed_node(g, k + 1));
    match g.speed_spacing {
        Spacing::Uniform => 0.5 * (a + b),
        Spacing::Geometric => {
            let q = f64::from(GEOMETRIC_EXPONENT);
            (0.5 * (a.powf(q) + b.powf(q))).powf(1.0 / q)
        }
    }
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

/// The checked-in sources are what the command writes: the same text, the same grid, and the
/// same numbers up to the last bits of the model's arithmetic (values within 2e-7 relative,
/// the stated error within 1e-4 of itself).
#[test]
fn checked_in_rust_sources_are_what_the_command_writes() {
    for f in &FIXTURES {
        let args = f.command();
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let text = ok(&args).replace(ROOT, "");
        let hint = f.hint();
        assert_eq!(skeleton(&text), skeleton(f.text), "{hint}");
        let grid_lines = |t: &str| {
            t.lines()
                .filter(|l| l.contains("_n:") || l.contains("_s:") || l.contains("points:") || l.contains("speed_"))
                .filter(|l| l.starts_with("    "))
                .map(str::to_string)
                .collect::<Vec<_>>()
        };
        assert_eq!(grid_lines(&text), grid_lines(f.text), "{hint}");
        for name in ["TORQUE_MAP_MAX_RELATIVE_ERROR", "TORQUE_MAP_MAX_ABSOLUTE_ERROR_NM"] {
            let (a, b) = (constant(&text, name), constant(f.text, name));
            assert!((a - b).abs() <= 1e-4 * b.abs(), "{name}: {a} vs {b}: {hint}");
        }
        let start = text.find("TORQUE_MAP_VALUES: [f32;").unwrap();
        let body = &text[text[start..].find('=').unwrap() + start..];
        let values: Vec<f32> = body
            .split(|c: char| c == ',' || c == '[' || c == ']' || c.is_whitespace() || c == '=' || c == ';')
            .filter(|t| !t.is_empty())
            .map(|t| t.parse().unwrap())
            .collect();
        assert_eq!(values.len(), f.values.len());
        for (a, b) in values.iter().zip(f.values) {
            assert!((a - b).abs() <= 2e-7 * b.abs(), "{a} vs {b}: {hint}");
        }
    }
}

/// The lubricated fixture is the default map: `ballscrew map` with no flags has its grid and
/// its stated error.
#[test]
fn the_lubricated_fixture_is_the_default_map() {
    let f = &FIXTURES[1];
    assert_eq!(f.grid.speed_spacing, Spacing::Geometric);
    let default = ok(&["map", "--format", "rust"]);
    let grid_of = |t: &str| t.lines().skip(1).take(2).map(str::to_string).collect::<Vec<_>>();
    assert_eq!(grid_of(&default), grid_of(f.text), "{}", f.hint());
    let (a, b) = (constant(&default, "TORQUE_MAP_MAX_RELATIVE_ERROR"), f.max_relative_error);
    assert!((a - b).abs() <= 1e-4 * b, "{a} vs {b}");
}

/// The stated error is the largest error at the check points (every cell's midpoint in both
/// directions, and the middle of the standstill band or of the span below a geometric axis's
/// first node), and it is within the 0.5 % a firmware map aims at; the nodes reproduce the
/// model.
#[test]
fn stated_interpolation_error_is_true_and_within_half_a_percent() {
    for f in &FIXTURES {
        let map = f.map();
        let g = f.grid;
        let model = Model::new(&(f.spec)()).unwrap();
        let mut state = SolverState::new();
        let omega0 = f64::from(g.standstill_speed_rad_s);
        let band = match g.speed_spacing {
            Spacing::Uniform => omega0,
            Spacing::Geometric => omega0.min(speed_node(&g, 0)),
        };
        assert_eq!(f.axial_load_n, 0.0);
        let mut worst: f64 = 0.0;
        let mut worst_abs: f64 = 0.0;
        let mut check = |p: f64, w: f64| {
            let t = model_torque(&model, &mut state, p, w);
            let m = f64::from(map.torque_nm(p as f32, w as f32));
            worst = worst.max((m - t).abs() / t.abs());
            worst_abs = worst_abs.max((m - t).abs());
        };
        for i in 0..g.preload_points - 1 {
            let p = 0.5 * (f64::from(g.preload_n(i)) + f64::from(g.preload_n(i + 1)));
            for sign in [1.0, -1.0] {
                for k in 0..g.speed_points - 1 {
                    check(p, sign * speed_midpoint(&g, k));
                }
                check(p, sign * 0.5 * band);
            }
        }
        let name = f.name;
        assert!(worst <= f.max_relative_error * (1.0 + 1e-9), "{name}: {worst} above the stated error");
        assert!(worst >= f.max_relative_error * (1.0 - 1e-9), "{name}: {worst} below the stated error");
        assert!((worst_abs - f.max_absolute_error_nm).abs() <= 1e-9 * worst_abs, "{name}: {worst_abs} N m");
        assert!(worst < 5e-3, "{name}: target 0.5 %: {worst}");
        // The nodes reproduce the model (f32 storage), the grid's corners included.
        let mut nodes = vec![(3000.0, -speed_node(&g, g.speed_points - 1))];
        if g.speed_spacing == Spacing::Geometric {
            for k in (0..g.speed_points).step_by(3) {
                let p = f64::from(g.preload_n(k % g.preload_points));
                nodes.push((p, speed_node(&g, k)));
                nodes.push((p, -speed_node(&g, k)));
            }
        } else {
            let rpm = [(500.0, 100.0), (2000.0, 1000.0), (1250.0, -2000.0)];
            nodes.extend(rpm.map(|(p, w)| (p, rpm_to_rad_s(w))));
        }
        for (p, w) in nodes {
            let t = model_torque(&model, &mut state, p, w);
            let m = f64::from(map.torque_nm(p as f32, w as f32));
            assert!((m - t).abs() <= 2e-6 * t.abs(), "{name}: {p} N {w} rad/s: map {m} model {t}");
        }
    }
}

/// The CSV map is what a CSV reader takes with no options (`pandas.read_csv(path)`): its
/// first line is the header, every row has its five fields, no comment lines; the values read
/// back to the map's. The description goes to `FILE.about.txt` beside `--out FILE.csv`, or to
/// stderr when the CSV goes to stdout.
#[test]
fn csv_reads_back_to_the_same_values() {
    for f in &FIXTURES {
        let args = f.command_as("csv", &[]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let run = ballscrew(&args);
        assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
        let text = String::from_utf8(run.stdout).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some("sheet,preload_n,speed_rad_s,speed_rpm,torque_nm"));
        let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
        assert!(rows.iter().all(|r| r.len() == 5 && !r[0].starts_with('#')), "{}", f.name);
        let values: Vec<f32> = rows.iter().map(|r| r[4].parse().unwrap()).collect();
        assert_eq!(values, f.values);
        let stderr = String::from_utf8(run.stderr).unwrap();
        let about = stderr.lines().find(|l| l.starts_with("Drive torque map of"));
        assert!(about.is_some(), "{}: the description on stderr: {stderr}", f.name);
        let spacing = format!("in {} points ({}", f.grid.speed_points, f.grid.speed_spacing.name());
        assert!(stderr.contains(&spacing), "{}", f.name);
        // The forward rows of the first preload carry the node speeds.
        let forward: Vec<f32> = rows.iter().filter(|r| r[0] == "forward").map(|r| r[2].parse().unwrap()).collect();
        for k in 0..f.grid.speed_points {
            assert_eq!(forward[k as usize], f.grid.speed_rad_s(k), "{}: node {k}", f.name);
        }
        // With --out, the same CSV in the file and the description beside it.
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("torque_map.csv");
        let args = f.command_as("csv", &["--out".into(), path.display().to_string()]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        assert!(ok(&args).is_empty());
        assert_eq!(std::fs::read_to_string(&path).unwrap(), text);
        let about = std::fs::read_to_string(dir.path().join("torque_map.about.txt")).unwrap();
        assert!(about.starts_with("Drive torque map of") && about.contains(&spacing), "{about}");
    }
}

/// Compiles the generated headers with the system C compiler (C99, pedantic, every conversion
/// and float-promotion warning an error: a firmware build's strictest usual flags) into a
/// program that prints the lookup and the in-grid indicator at many points, and compares both
/// with the core's (`TorqueMap::torque_nm`, `TorqueMap::in_grid`); every macro is used in a
/// `float` context, so a double literal among them would fail.
#[test]
fn c_header_compiles_and_its_lookup_equals_the_cores() {
    if Command::new("cc").arg("--version").output().is_err() {
        eprintln!("no C compiler (cc) on this machine: the C header is not compiled here");
        return;
    }
    for f in &FIXTURES {
        let dir = tempfile::tempdir().unwrap();
        let header = dir.path().join("ballscrew_torque_map.h");
        let args = f.command_as("c", &["--out".into(), header.display().to_string()]);
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        assert!(ok(&args).is_empty());
        // Preloads past both ends of the grid, speeds past +-3000 rpm, through standstill, and
        // over the decades of a geometric axis (its nodes included).
        let g = f.grid;
        let points: Vec<(f32, f32)> = (0..400)
            .map(|k| (300.0 + 7.3 * k as f32, -340.0 + 1.7 * k as f32))
            .chain((0..=40).map(|k| (1700.0 + 10.0 * k as f32, -0.012 + 6e-4 * k as f32)))
            .chain(
                (0..=300)
                    .map(|k| (480.0 + 9.0 * k as f32, 1e-4 * 1.06_f32.powi(k) * if k % 2 == 0 { 1.0 } else { -1.0 })),
            )
            .chain((0..g.speed_points).map(|k| (g.preload_n(k % g.preload_points), g.speed_rad_s(k))))
            .chain([(1000.0, 0.0), (1000.0, -0.0), (1000.0, 1e-45), (1000.0, f32::MAX), (1000.0, -f32::MAX)])
            .collect();
        let calls: String = points
            .iter()
            .map(|(p, w)| {
                format!(
                    "    printf(\"%.9g %d\\n\", (double)ballscrew_torque_map_nm({p:?}f, {w:e}f), \
                     ballscrew_torque_map_in_grid({p:?}f, {w:e}f));\n"
                )
            })
            .collect();
        let macros = "PRELOAD_MIN_N PRELOAD_STEP_N PRELOAD_MAX_N SPEED_MIN_RAD_S SPEED_MAX_RAD_S \
                      STANDSTILL_SPEED_RAD_S AXIAL_LOAD_N MAX_RELATIVE_ERROR MAX_ABSOLUTE_ERROR_NM";
        let uses: String = macros
            .split_whitespace()
            .map(|m| format!("    float m_{m} = BALLSCREW_TORQUE_MAP_{m};\n    (void)m_{m};\n"))
            .collect();
        let main = format!(
            "#include <stdio.h>\n#include \"ballscrew_torque_map.h\"\nint main(void)\n{{\n{uses}{calls}    return 0;\n}}\n"
        );
        let src = dir.path().join("main.c");
        std::fs::write(&src, main).unwrap();
        let exe = dir.path().join("lookup");
        let cc = Command::new("cc")
            .args(["-std=c99", "-Wall", "-Wextra", "-Wconversion", "-Wdouble-promotion", "-Werror", "-pedantic"])
            .args(["-O2", "-ffp-contract=off", "-o"])
            .arg(&exe)
            .arg(&src)
            .output()
            .unwrap();
        assert!(cc.status.success(), "{}: cc: {}", f.name, String::from_utf8_lossy(&cc.stderr));
        let out = Command::new(&exe).output().unwrap();
        let text = String::from_utf8(out.stdout).unwrap();
        let map = f.map();
        let c_values: Vec<(f32, bool)> = text
            .lines()
            .map(|l| {
                let (v, inside) = l.split_once(' ').unwrap();
                (v.parse().unwrap(), inside == "1")
            })
            .collect();
        assert_eq!(c_values.len(), points.len());
        let (mut inside, mut outside) = (0, 0);
        for ((p, w), (c, c_inside)) in points.iter().zip(c_values) {
            let r = map.torque_nm(*p, *w);
            // The same f32 operations in the same order (no contraction into FMA): equal bits.
            assert_eq!(c.to_bits(), r.to_bits(), "{}: {p} N {w} rad/s: C {c} Rust {r}", f.name);
            assert_eq!(c_inside, map.in_grid(*p, *w), "{}: in grid at {p} N {w} rad/s", f.name);
            if c_inside { inside += 1 } else { outside += 1 }
        }
        // The points cross the grid's edges: both answers occur.
        assert!(inside > 100 && outside > 100, "{}: {inside} inside, {outside} outside", f.name);
    }
}

/// A geometric map of the dry model (whose torque does not depend on the speed's magnitude)
/// is as good as its uniform one.
#[test]
fn a_geometric_map_of_the_dry_model_works() {
    let spec = format!("{ROOT}configs/dkfzd4012-dry.toml");
    let text = ok(&["--spec", &spec, "map", "--speed-spacing", "geometric", "--speed-points", "12"]);
    assert!(text.contains("speed magnitude 0.01..") && text.contains(" rpm x 12 points"), "{text}");
    let line = text.lines().find(|l| l.starts_with("largest interpolation error")).unwrap();
    let percent: f64 = line.split_whitespace().nth(6).unwrap().parse().unwrap();
    assert!(percent < 0.5, "{line}");
}

#[test]
fn bad_flags_are_named() {
    for (args, needle) in [
        // Each flag named as typed: an alias where one was typed.
        (&["map", "--preload", "3000..500"][..], "invalid --preload: 3000..500"),
        (&["map", "--preload-n", "3000..500"][..], "invalid --preload-n: 3000..500"),
        (&["map", "--preload", "-5..500"][..], "invalid --preload: -5"),
        (&["map", "--preload-points", "1"][..], "invalid --preload-points: 1"),
        (&["map", "--speed-points", "100000"][..], "invalid --speed-points: 100000"),
        (&["map", "--preload-step", "0"][..], "invalid --preload-step: 0"),
        (&["map", "--speed-rpm", "40000..50000"][..], "invalid --speed-rpm: 40000"),
        (&["map", "--speed-rpm", "-100..100", "--speed-step-rpm", "nan"][..], "invalid --speed-step-rpm: NaN"),
        (&["map", "--format", "json"][..], "invalid value 'json' for '--format <FORMAT>'"),
        (&["map", "--speed-spacing", "log"][..], "invalid value 'log' for '--speed-spacing <SPACING>'"),
        (&["map", "--speed-spacing", "geometric", "--speed-step-rpm", "100"][..], "invalid --speed-step-rpm: 100"),
        (&["map", "--speed-rpm", "0..0.001"][..], "invalid --speed-rpm: 0..0.001 with --speed-spacing geometric"),
        (&["sweep", "--format", "c"][..], "[possible values: table, csv, json]"),
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
    // 3000 N and 3000 rpm are reached by the last step (f32 grid: its last node the f32 below
    // 3100 rpm, not the nearest one above it).
    assert!(text.contains("grid: preload 500..3200 N x 10 points, speed magnitude 100..3099.9998"), "{text}");
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

/// The last speed node of a map of 0..3000 rpm is not above 3000 rpm, on the default
/// geometric axis and on a uniform one (before, f32's nearest value put it at 314.15927 rad/s,
/// 3000.0002 rpm on the geometric axis), and a map up to 30000 rpm, the top of the speed range,
/// is built (its last node was above the range, where the model refuses the point).
#[test]
fn the_last_node_is_not_above_the_range_asked_for() {
    let dry = concat!(env!("CARGO_MANIFEST_DIR"), "/../../configs/dkfzd4012-dry.toml");
    let cases: [(&[&str], f64); 3] = [
        (&["--preload-points", "2", "--speed-points", "4"], 3000.0),
        (&["--preload-points", "2", "--speed-points", "4", "--speed-spacing", "uniform"], 3000.0),
        (
            &[
                "--spec",
                dry,
                "--preload-points",
                "2",
                "--speed-points",
                "3",
                "--speed-spacing",
                "uniform",
                "--speed-rpm",
                "0..30000",
            ],
            30000.0,
        ),
    ];
    for (flags, top_rpm) in cases {
        let args = [&["map", "--format", "csv"][..], flags].concat();
        let text = ok(&args);
        let mut forward = 0;
        for line in text.lines().filter(|l| l.starts_with("forward,") || l.starts_with("reverse,")) {
            let fields: Vec<&str> = line.split(',').collect();
            let w = f64::from(fields[2].parse::<f32>().unwrap());
            assert!(w.abs() <= rpm_to_rad_s(top_rpm), "{flags:?}: {line}");
            forward += usize::from(line.starts_with("forward,") && w.abs() >= rpm_to_rad_s(top_rpm) * (1.0 - 1e-5));
        }
        assert_eq!(forward, 2, "{flags:?}: a last node at each preload, near the top: {text}");
    }
}

/// A map's nodes are stateless answers: each is the canonical state of its point (the model's
/// cold solve, what `ballscrew torque` gives), rounded to `f32`, whatever node was solved
/// before it (docs/real-time.md, "One question, one answer"). The built-in lubricated
/// DKFZD4012 on a geometric axis to 3000 rpm, whose top cells cross the speeds where a ball has
/// two steady states (docs/model-notes.md item 24), the dry model on a uniform axis, and the
/// single nut 16 x 5 at 3550 N of axial load, where a row of speeds solved each from the node
/// before ended on another state, 0.1 % from the cold solve (2.6772 against 2.6800 N m at
/// 200 N, -100 rpm); both directions and the standstill row.
#[test]
fn a_maps_nodes_are_each_points_canonical_torque() {
    let dry = spec("dkfzd4012-dry.toml", include_str!("../../../configs/dkfzd4012-dry.toml"));
    let single = spec("single-nut-16x5.toml", include_str!("../../../configs/single-nut-16x5.toml"));
    for (spec, spacing, (p_lo, p_hi), top_rpm, axial) in [
        (ScrewSpec::dkfzd4012(), Spacing::Geometric, (600.0, 2900.0), 3000.0, 150.0),
        (dry, Spacing::Uniform, (600.0, 2900.0), 3000.0, 150.0),
        (single, Spacing::Uniform, (100.0, 300.0), 200.0, 3550.0),
    ] {
        let model = Model::new(&spec).unwrap();
        let omega0 = model.spec().friction.standstill_speed_rad_s;
        let top = rpm_to_rad_s(top_rpm);
        let g = match spacing {
            Spacing::Geometric => MapGrid::geometric((p_lo, p_hi, 3), (0.1 * omega0, top, 12), omega0),
            Spacing::Uniform => MapGrid::spanning((p_lo, p_hi, 3), (0.0, top, 5), omega0),
        };
        let t = ballscrew_core::realtime::map::tabulate(&model, &g, axial).unwrap();
        let cold = |p: f64, w: f64| {
            let op = OperatingPoint { speed_rad_s: w, preload_n: p, axial_load_n: axial };
            model.torque(&op, &mut SolverState::new()).unwrap()
        };
        let (np, ns) = (g.preload_points, g.speed_points);
        let mut checked = 0;
        for p in 0..np {
            let preload = f64::from(g.preload_n(p));
            assert_eq!(
                t.values[p as usize].to_bits(),
                (cold(preload, 0.0) as f32).to_bits(),
                "standstill at {preload} N"
            );
            for (d, direction) in [1.0, -1.0].into_iter().enumerate() {
                for s in 0..ns {
                    let w = f64::from(g.speed_rad_s(s));
                    // Nodes below omega0 hold a blend's inverse (the module docs); the others the torque.
                    if w < omega0 {
                        continue;
                    }
                    let k = np as usize + d * (np * ns) as usize + (p * ns + s) as usize;
                    let (got, want) = (t.values[k], cold(preload, direction * w) as f32);
                    assert_eq!(
                        got.to_bits(),
                        want.to_bits(),
                        "{preload} N, {} rad/s: {got} against {want}",
                        direction * w
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked >= 12, "{checked}");
    }
}

/// A shipped spec by its file name and text.
fn spec(name: &str, text: &str) -> ScrewSpec {
    ballscrew_config::spec_from_toml_str(text, name).unwrap()
}
