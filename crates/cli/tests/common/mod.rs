//! Running the built `ballscrew` binary, shared by the command-line test binaries.
#![allow(dead_code, reason = "each test binary uses its own subset")]

use std::process::{Command, Output};

/// `ballscrew init` with DKFZD4012's dimensions (Table 1; configs/dkfzd4012.toml): 2 nuts of 4
/// circles of 19 balls, 2000 N preload.
pub const INIT_DKFZD4012: [&str; 15] = [
    "init",
    "--pitch-diameter-mm",
    "40",
    "--lead-mm",
    "12",
    "--ball-diameter-mm",
    "5.953",
    "--nuts",
    "2",
    "--circles-per-nut",
    "4",
    "--balls-per-circle",
    "19",
    "--preload-n",
    "2000",
];

/// The spec of the XJTU test rig.
pub const XJTU_SPEC: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../configs/xjtu-32x8.toml");
/// The XJTU degradation data.
pub const XJTU_DATA: &str =
    concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/xjtu-ball-screw/friction_torque.csv");
/// `ballscrew diagnose` of the upper screw of the XJTU data.
pub const XJTU_UPPER: [&str; 9] = [
    "diagnose",
    "--spec",
    XJTU_SPEC,
    "--data",
    XJTU_DATA,
    "--column",
    "time_h=hours",
    "--column",
    "torque_nm=upper_screw_torque_Nm",
];

/// Runs `ballscrew` with `args`.
pub fn ballscrew(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ballscrew")).args(args).output().expect("the binary runs")
}

/// Runs and expects success; returns stdout.
pub fn ok(args: &[&str]) -> String {
    let o = ballscrew(args);
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8(o.stdout).unwrap()
}

/// Runs and expects success with nothing on stderr; returns stdout.
pub fn ok_quiet(args: &[&str]) -> String {
    let o = ballscrew(args);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{args:?}: {stderr}");
    assert!(stderr.is_empty(), "{stderr}");
    String::from_utf8(o.stdout).unwrap()
}

/// Runs and expects failure with exit code `code`, nothing on stdout and an `error: ` line
/// without a panic on stderr; returns stderr.
pub fn fails(args: &[&str], code: i32) -> String {
    let o = ballscrew(args);
    let stdout = String::from_utf8_lossy(&o.stdout);
    let e = String::from_utf8(o.stderr).unwrap();
    assert_eq!(o.status.code(), Some(code), "{args:?}: stdout {stdout} stderr {e}");
    assert!(o.stdout.is_empty(), "no output on failure: {stdout}");
    assert!(e.starts_with("error: "), "{e}");
    assert!(!e.contains("panicked"), "{e}");
    e
}
