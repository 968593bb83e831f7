//! `ballscrew init`: the spec it writes reads back through `ballscrew torque --spec`, gives the
//! shipped spec's torque for the shipped screw's dimensions, marks every value given or
//! assumed, and a value the parser refuses is refused naming its flag, with nothing written.

mod common;

// `ok_warned`: success with a warning on stderr allowed.
use common::{INIT_DKFZD4012, ballscrew, fails, ok as ok_warned, ok_quiet as ok};
use std::path::Path;

/// DKFZD4012's dimensions (Table 1): 2 nuts of 4 circles of 19 balls, 2000 N preload.
const DKFZD4012: [&str; 15] = common::INIT_DKFZD4012;

const SHIPPED: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../configs/dkfzd4012.toml");

/// `ballscrew torque --spec spec --format json`, parsed.
fn torque(spec: &Path) -> serde_json::Value {
    serde_json::from_str(&ok(&["torque", "--spec", spec.to_str().unwrap(), "--format", "json"])).unwrap()
}

/// `init args --out dir/name`: the path written.
fn init_to(dir: &Path, name: &str, args: &[&str]) -> std::path::PathBuf {
    let path = dir.join(name);
    let mut all: Vec<&str> = args.to_vec();
    all.extend(["--out", path.to_str().unwrap()]);
    assert_eq!(ok(&all), "", "the spec goes to --out");
    path
}

/// The shipped screw's dimensions give the shipped spec's torques at its default point: the
/// shipped file's other values (material, grooves, friction, circulation, oil) are what `init`
/// assumes.
#[test]
fn dkfzd4012_dimensions_give_the_shipped_specs_torque() {
    let dir = tempfile::tempdir().unwrap();
    let written = init_to(dir.path(), "dkfzd4012.toml", &DKFZD4012);
    let (ours, shipped) = (torque(&written), torque(Path::new(SHIPPED)));
    for key in
        ["speed_rpm", "preload_n", "axial_load_n", "torque_nm", "drag_torque_nm", "torque_moment_nm", "catalog_nm"]
    {
        let (a, b) = (ours[key].as_f64().unwrap(), shipped[key].as_f64().unwrap());
        assert!((a - b).abs() <= 1e-12 * b.abs().max(1.0), "{key}: {a} vs {b}");
    }
    assert!(ours["torque_nm"].as_f64().unwrap() > 0.0);
}

/// Every key line is marked `# given` (the flags given) or `# assumed: why` (the others).
#[test]
fn every_value_is_marked_given_or_assumed() {
    let text = ok(&DKFZD4012);
    let mut given = Vec::new();
    for line in text.lines().filter(|l| !l.starts_with('#') && l.contains(" = ")) {
        let key = line.split(" = ").next().unwrap().trim();
        let note = line.split_once('#').map(|(_, n)| n.trim()).unwrap_or_else(|| panic!("no note: {line}"));
        if note == "given" {
            given.push(key);
        } else {
            assert!(note.starts_with("assumed: ") && note.len() > "assumed: ".len() + 5, "{line}");
        }
    }
    assert_eq!(
        given,
        [
            "pitch_diameter_mm",
            "lead_mm",
            "ball_diameter_mm",
            "nuts",
            "circles_per_nut",
            "balls_per_circle",
            "preload_n"
        ]
    );
    // The three dimensions alone: everything else assumed, a nut without preload, and as many
    // balls as fit a turn less two for the deflector.
    let dimensions = &DKFZD4012[..7];
    let text = ok(dimensions);
    assert!(text.contains("preload = \"none\""), "{text}");
    let balls = text.lines().find(|l| l.starts_with("balls_per_circle = ")).unwrap();
    assert!(
        balls.starts_with("balls_per_circle = 19 ") && balls.contains("assumed: 21 fit one turn, less 2"),
        "{balls}"
    );
    let external = ok(&[dimensions, &["--return", "external"]].concat());
    assert!(external.contains("balls_per_circle = 20 ") && external.contains("return = \"external\""), "{external}");
    assert!(external.contains("turns_per_circuit = 4 "), "{external}");
    // Oversize balls: one turn per circuit (several are solved for two-point balls only), and
    // the spec reads back.
    let oversize =
        ok(&[dimensions, &["--return", "external", "--preload-arrangement", "oversize-ball", "--preload-n", "200"]]
            .concat());
    assert!(oversize.contains("turns_per_circuit = 1 "), "{oversize}");
}

/// What `init` writes with the dimensions alone is a spec `ballscrew torque --spec` reads, at
/// the default point of a nut without preload.
#[test]
fn output_round_trips_through_torque() {
    let dir = tempfile::tempdir().unwrap();
    let args = ["init", "--pitch-diameter-mm", "16", "--lead-mm", "5", "--ball-diameter-mm", "3.175"];
    let written = init_to(dir.path(), "small.toml", &args);
    // (No ball carries a load at 0 N preload and 0 N axial load: a warning says so.)
    let t: serde_json::Value =
        serde_json::from_str(&ok_warned(&["torque", "--spec", written.to_str().unwrap(), "--format", "json"])).unwrap();
    assert_eq!((t["speed_rpm"].as_f64(), t["preload_n"].as_f64()), (Some(100.0), Some(0.0)));
    // Under an axial load the balls carry it and the torque is positive.
    let loaded = ok(&["torque", "--spec", written.to_str().unwrap(), "--axial-load-n", "500", "--format", "json"]);
    let loaded: serde_json::Value = serde_json::from_str(&loaded).unwrap();
    assert!(loaded["drag_torque_nm"].as_f64().unwrap() > 0.0, "{loaded}");
    // Stdout and --out write the same text.
    assert_eq!(std::fs::read_to_string(&written).unwrap(), ok(&args));
}

/// A ball larger than half the pitch diameter is refused naming the flag and the value;
/// nothing is written.
#[test]
fn a_bad_value_is_refused_naming_the_flag() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("bad.toml");
    let e = fails(
        &[
            "init",
            "--pitch-diameter-mm",
            "40",
            "--lead-mm",
            "12",
            "--ball-diameter-mm",
            "25",
            "--out",
            out.to_str().unwrap(),
        ],
        2,
    );
    assert!(e.contains("invalid --ball-diameter-mm: 25") && e.contains("pitch diameter / 2"), "{e}");
    assert!(!out.exists(), "nothing written");
    // DKFZD4012's three dimensions (the shared flags' first seven words) with a bad contact angle.
    let e = fails(&[&INIT_DKFZD4012[..7], &["--contact-angle-deg", "80"][..]].concat(), 2);
    assert!(e.contains("invalid --contact-angle-deg: 80 (valid: [20, 70]"), "{e}");
    let e = fails(&["init", "--pitch-diameter-mm", "40", "--lead-mm", "nan", "--ball-diameter-mm", "5.953"], 2);
    assert!(e.contains("--lead-mm"), "{e}");
    let e = fails(&["init", "--pitch-diameter-mm", "-40", "--lead-mm", "12", "--ball-diameter-mm", "5.953"], 2);
    assert!(e.contains("invalid --pitch-diameter-mm: -40 mm (valid: [3 mm, 300 mm]"), "{e}");
    let e = fails(
        &["init", "--pitch-diameter-mm", "40", "--lead-mm", "12", "--ball-diameter-mm", "5.953", "--nuts", "3"],
        2,
    );
    assert!(e.contains("invalid --nuts: 3 (valid: 1 or 2)"), "{e}");
    let e = fails(&DKFZD4012[..13], 2);
    assert!(e.contains("--preload-n is needed") && e.contains("double-nut"), "{e}");
    let e = fails(
        &["--spec", SHIPPED, "init", "--pitch-diameter-mm", "40", "--lead-mm", "12", "--ball-diameter-mm", "5.953"],
        2,
    );
    assert!(e.contains("reads no spec"), "{e}");
}

/// An existing file is not replaced without --force.
#[test]
fn an_existing_file_is_replaced_only_with_force() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("spec.toml");
    std::fs::write(&out, "mine\n").unwrap();
    let mut args: Vec<&str> = DKFZD4012.to_vec();
    args.extend(["--out", out.to_str().unwrap()]);
    let e = fails(&args, 2);
    assert!(e.contains("exists") && e.contains("--force"), "{e}");
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "mine\n");
    args.push("--force");
    let o = ballscrew(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), ok(&DKFZD4012));
}
