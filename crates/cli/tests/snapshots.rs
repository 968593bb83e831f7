//! Snapshots of the command line's outputs: what `ballscrew` prints for the shipped specs, kept in
//! reviewed files so that a change of output, wanted or not, shows as a diff. They guard
//! refactors that must not change a digit.
//!
//! What is kept, for the built-in spec (no `--spec`) and for every `configs/*.toml`:
//! `torque`, `inspect` and a short `sweep` (preload 500..1500 N in steps of 500 N) as table, CSV
//! and JSON; `map` on a coarse grid (3 preloads, 4 speeds) as its report and as CSV (the built-in
//! spec also as the C header and the Rust source). `predict` is kept for the XJTU spec on its
//! data (`tests/data/xjtu-ball-screw`), the only data file of the repository. A file holds the
//! command's standard output and, when the command writes one, its standard error (warnings, a
//! CSV map's description) after a `---- stderr ----` line. Files: `tests/snapshots/`, named
//! `<spec>__<command>_<format>.snap` (`builtin` or the spec file's stem); each file's
//! `description` is the command line that made it.
//!
//! The binary runs in the workspace root and is given the specs and the data by relative paths,
//! so the outputs name `configs/...` as a user's would and no machine path enters a snapshot
//! (one that did would show as `[ROOT]`).
//!
//! Deterministic on any machine: `torque` and `inspect` solve one point, `sweep` warm-starts its
//! points in order on one thread, `map` tabulates on one thread. `predict` (`ballscrew-batch`)
//! shares its rows out over the machine's cores in contiguous warm-started chunks, and on rows of
//! different operating points the last digits depend on the number of threads (seen between one
//! and two); the command line has no flag or variable to pin it. The XJTU data's rows all run at
//! the spec's one operating point, where a cold and a warm solve agree to the last digit, so its
//! prediction is the same on any number of cores. Every command here gave the same bytes twice,
//! on one core (`taskset -c 0`) and on two, and in the dev and release profiles. Add no
//! `predict` of varying points without pinning the threads first.
//!
//! An intended change of output: run
//!
//! ```sh
//! INSTA_UPDATE=always cargo test -p ballscrew-cli --test snapshots
//! git diff crates/cli/tests/snapshots
//! ```
//!
//! read the diff and commit the snapshots with the change. With `cargo-insta` installed,
//! `cargo insta test -p ballscrew-cli --test snapshots --review` (or `cargo insta review` after a
//! failing `cargo test`) shows each change and accepts or rejects it. A plain failing `cargo test`
//! leaves the new output beside the old as `<name>.snap.new` (not to be committed); under
//! `CI=true` insta writes nothing and a differing or missing snapshot fails the test. A new
//! snapshot is written by its first run with `INSTA_UPDATE=always`.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

/// The workspace root, where the binary runs.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").canonicalize().expect("the workspace root")
}

/// The short sweep: three preloads.
const SWEEP: [&str; 5] = ["sweep", "--preload-n", "500..1500", "--preload-step-n", "500"];
/// The coarse map: 3 preloads by 4 speed magnitudes.
const MAP: [&str; 5] = ["map", "--preload-points", "3", "--speed-points", "4"];
/// The XJTU data with its columns named.
const PREDICT: [&str; 7] = [
    "predict",
    "--data",
    "tests/data/xjtu-ball-screw/friction_torque.csv",
    "--column",
    "time_h=hours",
    "--column",
    "torque_nm=upper_screw_torque_Nm",
];

/// The arguments of `command` (a subcommand, or one of the lists above by its subcommand).
fn command_args(command: &str) -> &'static [&'static str] {
    match command {
        "torque" => &["torque"],
        "inspect" => &["inspect"],
        "sweep" => &SWEEP,
        "map" => &MAP,
        "predict" => &PREDICT,
        other => panic!("no snapshot command {other}"),
    }
}

/// Runs `ballscrew args` in the workspace root and expects success: its standard output, then
/// its standard error (if any) after a marker line, with the workspace root's path as `[ROOT]`.
fn run(args: &[&str]) -> String {
    let root = root();
    let o =
        Command::new(env!("CARGO_BIN_EXE_ballscrew")).args(args).current_dir(&root).output().expect("the binary runs");
    let stdout = String::from_utf8(o.stdout).expect("UTF-8 on stdout");
    let stderr = String::from_utf8(o.stderr).expect("UTF-8 on stderr");
    assert!(o.status.success(), "ballscrew {}: {stderr}", args.join(" "));
    let mut text = stdout;
    if !stderr.is_empty() {
        text.push_str("---- stderr ----\n");
        text.push_str(&stderr);
    }
    text.replace(root.to_str().expect("a UTF-8 path"), "[ROOT]")
}

/// Checks the snapshot of `command` (see [`command_args`]) in `format` for `spec` (a path
/// relative to the workspace root; `None`: the built-in spec).
fn check(spec: Option<&str>, command: &str, format: &str) {
    let mut args: Vec<&str> = Vec::new();
    if let Some(spec) = spec {
        args.extend(["--spec", spec]);
    }
    args.extend(command_args(command));
    args.extend(["--format", format]);
    let spec_name = spec.map_or("builtin", |s| Path::new(s).file_stem().and_then(|s| s.to_str()).expect("a spec name"));
    let mut settings = insta::Settings::clone_current();
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    settings.set_description(format!("ballscrew {}", args.join(" ")));
    settings.bind(|| insta::assert_snapshot!(format!("{spec_name}__{command}_{format}"), run(&args)));
}

/// A module of tests for one spec: `$spec` is the value of `--spec` (`None`: the built-in), then
/// one test per command and format.
macro_rules! spec_snapshots {
    ($module:ident, $spec:expr $(, $test:ident: $command:literal $format:literal)* $(,)?) => {
        mod $module {
            $(
                #[test]
                fn $test() {
                    super::check($spec, $command, $format);
                }
            )*
        }
    };
}

/// The tests every spec has.
macro_rules! every_spec {
    ($($module:ident, $spec:expr $(, $test:ident: $command:literal $format:literal)*;)*) => {
        $(
            spec_snapshots!(
                $module,
                $spec,
                torque_table: "torque" "table",
                torque_csv: "torque" "csv",
                torque_json: "torque" "json",
                inspect_table: "inspect" "table",
                inspect_csv: "inspect" "csv",
                inspect_json: "inspect" "json",
                sweep_table: "sweep" "table",
                sweep_csv: "sweep" "csv",
                sweep_json: "sweep" "json",
                map_table: "map" "table",
                map_csv: "map" "csv",
                $($test: $command $format,)*
            );
        )*
    };
}

every_spec! {
    builtin, None, map_c: "map" "c", map_rust: "map" "rust";
    dkfzd4012, Some("configs/dkfzd4012.toml");
    dkfzd4012_dry, Some("configs/dkfzd4012-dry.toml");
    single_nut_16x5, Some("configs/single-nut-16x5.toml");
    xjtu_32x8, Some("configs/xjtu-32x8.toml"), predict_csv: "predict" "csv", predict_json: "predict" "json";
}

/// Every shipped spec has its tests above: a spec added to `configs/` fails here until it has.
#[test]
fn every_shipped_spec_is_snapshotted() {
    let mut specs: Vec<String> = std::fs::read_dir(root().join("configs"))
        .expect("configs/")
        .map(|e| e.expect("an entry").file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".toml"))
        .collect();
    specs.sort();
    assert_eq!(specs, ["dkfzd4012-dry.toml", "dkfzd4012.toml", "single-nut-16x5.toml", "xjtu-32x8.toml"]);
}

/// The spec `ballscrew init` writes: DKFZD4012's dimensions (Table 1) with its preload, and the
/// three dimensions alone (every other value assumed).
#[test]
fn init_writes_the_commented_spec() {
    for (name, args) in
        [("init__dkfzd4012", &init_args::DKFZD4012[..]), ("init__dimensions_only", &init_args::DIMENSIONS[..])]
    {
        let mut settings = insta::Settings::clone_current();
        settings.set_prepend_module_to_snapshot(false);
        settings.set_omit_expression(true);
        settings.set_description(format!("ballscrew {}", args.join(" ")));
        settings.bind(|| insta::assert_snapshot!(name, run(args)));
    }
}

/// The flags of the `init` snapshots.
mod init_args {
    /// DKFZD4012 (Table 1): 2 nuts of 4 circles of 19 balls, 2000 N preload.
    pub const DKFZD4012: [&str; 15] = super::common::INIT_DKFZD4012;
    /// The three dimensions the command needs.
    pub const DIMENSIONS: [&str; 7] =
        ["init", "--pitch-diameter-mm", "16", "--lead-mm", "5", "--ball-diameter-mm", "3.175"];
}
