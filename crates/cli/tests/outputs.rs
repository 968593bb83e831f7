//! Where output goes and what is refused before anything is evaluated, through the built binary.
//! Each rule of the guide's "Bad input and limits" (docs/limits.md) has its test here or is named there
//! with its file:
//!
//! | rule | test |
//! |---|---|
//! | `--out -` is standard output | [`out_dash_is_stdout`] |
//! | a regular file is replaced atomically, a link to it kept | [`a_regular_file_is_replaced_and_a_link_to_it_kept`] |
//! | a character device is written, never replaced | [`dev_null_is_written_not_replaced`] |
//! | a FIFO is written, never replaced | [`a_fifo_is_written_through_not_replaced`] |
//! | an open descriptor is written, appending | [`dev_stdout_is_this_process_stdout`] |
//! | a directory is refused, naming flag and path | [`a_directory_is_refused_naming_flag_and_path`] |
//! | a `--plot` not named `.svg` is refused before the work | `a_plot_not_named_svg_is_refused_before_any_work` (`tests/figures.rs`) |
//! | a socket is refused | [`a_socket_is_refused`] |
//! | `--plots` must be a directory or makeable | [`plots_must_be_a_directory_or_makeable`] |
//! | paths are checked before the sweep, the map, the diagnosis | [`bad_outputs_are_refused_before_the_work`] |
//! | the files of a run: all or none | [`an_unwritable_side_file_writes_nothing_at_all`], [`a_failing_stream_leaves_no_side_file`] |
//! | a signal removes the temporaries | [`a_signal_while_writing_removes_the_temporaries`] |
//! | `diagnose --format csv` is refused before the data is read | [`diagnose_csv_is_refused_before_the_data_is_read`] |
//! | a map grid too long to tabulate is refused | [`a_map_grid_too_long_to_tabulate_is_refused_at_once`] |
//! | control characters in messages are escaped | [`control_characters_in_messages_are_escaped`] |
//! | an undefined number: JSON `null`, CSV empty, table `n/a` | [`an_undefined_ratio_is_null_empty_or_na`] |
//! | progress is drawn on stderr only when it is a terminal; a CSV sweep to stdout is streamed, the same text | [`no_progress_off_a_terminal_and_a_streamed_sweep_is_the_same_csv`] |
//!
//! No test measures time: a refusal that must come before the work is run with a timeout as a
//! guard only (the work it stands before would take far longer).

mod common;

use common::{XJTU_UPPER, ballscrew, fails, ok};
use core::time::Duration;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Instant;

/// The names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut n: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    n.sort();
    n
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Runs `ballscrew` and waits at most `guard` for it (then kills it and fails): for refusals
/// that must come before long work. Returns the exit code and stderr.
fn within(guard: Duration, args: &[&str]) -> (Option<i32>, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ballscrew"))
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            let mut e = String::new();
            std::io::Read::read_to_string(child.stderr.as_mut().unwrap(), &mut e).unwrap();
            return (status.code(), e);
        }
        if start.elapsed() > guard {
            let _ = child.kill();
            panic!("{args:?} still running after {guard:?}: the refusal did not come before the work");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// A FIFO at `path` by `mkfifo`; false when there is no `mkfifo`.
fn mkfifo(path: &Path) -> bool {
    Command::new("mkfifo").arg(path).status().is_ok_and(|s| s.success())
}

#[test]
fn out_dash_is_stdout() {
    let plain = ok(&["torque", "--format", "csv"]);
    assert_eq!(ok(&["torque", "--format", "csv", "--out", "-"]), plain);
    // With --plot, creep-curves prints its data only when asked for them by --out; `-` asks.
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("c.svg");
    let text = ok(&["creep-curves", "--points", "2", "--format", "csv", "--plot", s(&svg), "--out", "-"]);
    assert_eq!(text.lines().count(), 1 + 4 * 3 * 2);
    assert!(svg.exists());
}

#[cfg(unix)]
#[test]
fn a_regular_file_is_replaced_and_a_link_to_it_kept() {
    let dir = tempfile::tempdir().unwrap();
    let real = dir.path().join("real.csv");
    std::fs::write(&real, "old\n").unwrap();
    let link = dir.path().join("link.csv");
    std::os::unix::fs::symlink("real.csv", &link).unwrap();
    assert!(ok(&["torque", "--format", "csv", "--out", s(&link)]).is_empty());
    assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "the link is kept");
    assert_eq!(std::fs::read_to_string(&real).unwrap(), ok(&["torque", "--format", "csv"]));
    assert_eq!(names(dir.path()), ["link.csv", "real.csv"], "no temporary left");
}

#[cfg(unix)]
#[test]
fn dev_null_is_written_not_replaced() {
    use std::os::unix::fs::FileTypeExt as _;
    let null = Path::new("/dev/null");
    if !null.exists() {
        return;
    }
    assert!(ok(&["torque", "--out", "/dev/null"]).is_empty());
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("x.svg");
    assert!(ok(&["contact", "--plot", "/dev/null", "--out", s(&svg)]).is_empty());
    assert!(std::fs::read_to_string(&svg).unwrap().contains("FASTSIM"), "the report went to --out");
    assert!(std::fs::metadata(null).unwrap().file_type().is_char_device(), "/dev/null is still a device");
    assert_eq!(names(dir.path()), ["x.svg"]);
}

#[cfg(unix)]
#[test]
fn a_fifo_is_written_through_not_replaced() {
    use std::os::unix::fs::FileTypeExt as _;
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("pipe");
    if !mkfifo(&fifo) {
        eprintln!("no mkfifo here: the FIFO is not tested");
        return;
    }
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap())
    };
    assert!(ok(&["torque", "--format", "csv", "--out", s(&fifo)]).is_empty());
    assert_eq!(reader.join().unwrap(), ok(&["torque", "--format", "csv"]));
    assert!(std::fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo(), "still a FIFO");
    assert_eq!(names(dir.path()), ["pipe"]);
}

/// `/dev/stdout` is this process's standard output, whatever it is: here a file opened for
/// appending keeps what it held.
#[cfg(target_os = "linux")]
#[test]
fn dev_stdout_is_this_process_stdout() {
    let dir = tempfile::tempdir().unwrap();
    let log = dir.path().join("log.txt");
    std::fs::write(&log, "before\n").unwrap();
    let append = std::fs::OpenOptions::new().append(true).open(&log).unwrap();
    let status = Command::new(env!("CARGO_BIN_EXE_ballscrew"))
        .args(["torque", "--format", "csv", "--out", "/dev/stdout"])
        .stdout(Stdio::from(append))
        .status()
        .unwrap();
    assert!(status.success());
    let text = std::fs::read_to_string(&log).unwrap();
    assert_eq!(text, format!("before\n{}", ok(&["torque", "--format", "csv"])));
    assert_eq!(names(dir.path()), ["log.txt"], "no temporary, nothing replaced");
}

#[test]
fn a_directory_is_refused_naming_flag_and_path() {
    let dir = tempfile::tempdir().unwrap();
    let d = s(dir.path());
    let e = fails(&["torque", "--out", d], 1);
    assert_eq!(e.trim_end(), format!("error: --out {d}: is a directory (give a file name)"));
    let e = fails(&["contact", "--plot", d], 1);
    assert!(e.starts_with(&format!("error: --plot {d}: is a directory")), "{e}");
    let e = fails(&[&XJTU_UPPER[..], &["--report", d]].concat(), 1);
    assert!(e.starts_with(&format!("error: --report {d}: is a directory")), "{e}");
    assert!(names(dir.path()).is_empty());
}

#[cfg(unix)]
#[test]
fn a_socket_is_refused() {
    use std::os::unix::fs::FileTypeExt as _;
    let dir = tempfile::tempdir().unwrap();
    let sock = dir.path().join("sock");
    let _listener = std::os::unix::net::UnixListener::bind(&sock).unwrap();
    let e = fails(&["torque", "--out", s(&sock)], 1);
    assert_eq!(e.trim_end(), format!("error: --out {}: is a socket, which cannot be opened for writing", s(&sock)));
    assert!(std::fs::symlink_metadata(&sock).unwrap().file_type().is_socket(), "still a socket");
}

#[test]
fn plots_must_be_a_directory_or_makeable() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("file.txt");
    std::fs::write(&file, "x").unwrap();
    let e = fails(&[&XJTU_UPPER[..], &["--plots", s(&file)]].concat(), 1);
    assert_eq!(e.trim_end(), format!("error: --plots {}: not a directory", s(&file)));
    let under = file.join("sub").join("plots");
    let e = fails(&[&XJTU_UPPER[..], &["--plots", s(&under)]].concat(), 1);
    assert!(e.contains(&format!("cannot make the directory: {} is not a directory", s(&file))), "{e}");
    assert_eq!(names(dir.path()), ["file.txt"]);
    // Missing directories are made, the figures written.
    let deep = dir.path().join("a").join("b");
    ok(&[&XJTU_UPPER[..], &["--plots", s(&deep)]].concat());
    assert!(deep.join("measured_vs_model.svg").exists());
}

/// Output paths are checked before the work: a sweep of 100000 preloads, a map of 2000 x 40
/// points and a diagnosis would each take seconds to minutes; the refusals come first.
#[test]
fn bad_outputs_are_refused_before_the_work() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("missing").join("x.csv");
    let guard = Duration::from_secs(60);
    let (code, e) = within(guard, &["sweep", "--preload", "0..99999", "--step", "1", "--out", s(&missing)]);
    assert_eq!(code, Some(1), "{e}");
    assert!(e.starts_with(&format!("error: --out {}: cannot write output: no directory", s(&missing))), "{e}");
    let (code, e) = within(
        guard,
        &["map", "--preload-points", "2000", "--speed-points", "40", "--format", "c", "--out", s(dir.path())],
    );
    assert_eq!(code, Some(1), "{e}");
    assert!(e.contains("is a directory"), "{e}");
    let (code, e) = within(guard, &[&XJTU_UPPER[..], &["--out-spec", s(&missing)]].concat());
    assert_eq!(code, Some(1), "{e}");
    assert!(e.starts_with("error: --out-spec "), "{e}");
    assert!(names(dir.path()).is_empty());
}

/// A run whose last file cannot be written writes nothing at all: not the report, not the
/// figures, not their directory, not the text, no temporary. The unwritable place is a path
/// under a regular file (unwritable for root too); where permission bits apply, a read-only
/// directory is tried as well.
#[test]
fn an_unwritable_side_file_writes_nothing_at_all() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("file.txt");
    std::fs::write(&file, "x").unwrap();
    let (report, plots, out) = (dir.path().join("r.json"), dir.path().join("plots"), dir.path().join("out.txt"));
    let run = |bad: &Path| {
        let args =
            [&XJTU_UPPER[..], &["--report", s(&report), "--plots", s(&plots), "--out", s(&out), "--out-spec", s(bad)]]
                .concat();
        fails(&args, 1)
    };
    let e = run(&file.join("sub").join("s.toml"));
    assert!(e.starts_with("error: --out-spec "), "{e}");
    assert_eq!(names(dir.path()), ["file.txt"]);

    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        let ro = dir.path().join("ro");
        std::fs::create_dir(&ro).unwrap();
        std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).unwrap();
        let bits_apply = std::fs::write(ro.join("probe"), "x").is_err();
        if bits_apply {
            let e = run(&ro.join("s.toml"));
            assert!(e.starts_with("error: --out-spec ") && e.contains("cannot write in"), "{e}");
            assert_eq!(names(dir.path()), ["file.txt", "ro"]);
            assert!(names(&ro).is_empty());
        } else {
            eprintln!("permission bits do not stop this user (root): the read-only directory is not tried");
        }
        std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o755)).unwrap();
    }
}

/// A stream that fails (`/dev/full`: no space) is written before the files are renamed into
/// place: the plot of the run is not left behind.
#[cfg(target_os = "linux")]
#[test]
fn a_failing_stream_leaves_no_side_file() {
    if !Path::new("/dev/full").exists() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let svg = dir.path().join("x.svg");
    let e = fails(&["contact", "--plot", s(&svg), "--out", "/dev/full"], 1);
    assert!(e.starts_with("error: --out /dev/full: cannot write: "), "{e}");
    assert!(names(dir.path()).is_empty(), "no plot, no temporary");
}

/// SIGTERM and SIGINT while the files are written: the plot's temporary is made, then the run
/// waits for a reader of its `--out` FIFO; the signal removes the temporary, exit code 130.
#[cfg(unix)]
#[test]
fn a_signal_while_writing_removes_the_temporaries() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("pipe");
    if !mkfifo(&fifo) || Command::new("kill").arg("-l").output().is_err() {
        eprintln!("no mkfifo or kill here: signals are not tested");
        return;
    }
    for signal in ["-TERM", "-INT"] {
        let svg = dir.path().join("x.svg");
        let mut child = Command::new(env!("CARGO_BIN_EXE_ballscrew"))
            .args(["contact", "--plot", s(&svg), "--out", s(&fifo)])
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let start = Instant::now();
        // The plot's temporary, written (the probe files of the checks before are empty).
        let staged = || {
            names(dir.path()).iter().any(|n| {
                n.starts_with(".ballscrew-")
                    && n.ends_with(".tmp")
                    && std::fs::metadata(dir.path().join(n)).is_ok_and(|m| m.len() > 0)
            })
        };
        while !staged() {
            assert!(child.try_wait().unwrap().is_none(), "the run ended before writing");
            assert!(start.elapsed() < Duration::from_secs(60), "no temporary made");
            std::thread::sleep(Duration::from_millis(10));
        }
        assert!(Command::new("kill").args([signal, &child.id().to_string()]).status().unwrap().success());
        let out = child.wait_with_output().unwrap();
        assert_eq!(out.status.code(), Some(130), "{signal}");
        assert!(String::from_utf8_lossy(&out.stderr).contains("error: interrupted"));
        assert_eq!(names(dir.path()), ["pipe"], "{signal}: no temporary, no plot");
    }
}

/// A file-size limit (`ulimit -f`, SIGXFSZ) reached while the files are written: a write error
/// naming the file, exit code 1, and no temporary left (before, the signal ended the process
/// and left the sweep's temporary behind).
#[cfg(unix)]
#[test]
fn a_file_size_limit_is_a_write_error_and_leaves_no_temporary() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("sweep.csv");
    // One block of 512 bytes (POSIX sh) or 1 KiB (bash): the sweep's CSV is longer.
    let script = format!("ulimit -f 1 && exec \"$0\" sweep --format csv --out '{}'", s(&csv));
    let out = Command::new("sh").args(["-c", &script, env!("CARGO_BIN_EXE_ballscrew")]).output().unwrap();
    let e = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{e}");
    assert!(e.contains("sweep.csv") && e.contains("File too large"), "{e}");
    assert!(names(dir.path()).is_empty(), "left: {:?}", names(dir.path()));
}

#[test]
fn diagnose_csv_is_refused_before_the_data_is_read() {
    let e = fails(&["diagnose", "--data", "/no/such/data.csv", "--format", "csv"], 2);
    assert!(e.starts_with("error: invalid value 'csv' for '--format <FORMAT>'"), "{e}");
    assert!(e.contains("[possible values: table, json]"), "{e}");
    let (code, e) = within(Duration::from_secs(60), &[&XJTU_UPPER[..], &["--format", "csv"]].concat());
    assert_eq!(code, Some(2), "{e}");
}

#[test]
fn a_map_grid_too_long_to_tabulate_is_refused_at_once() {
    let (code, e) = within(Duration::from_secs(60), &["map", "--preload-points", "10000", "--speed-points", "10000"]);
    assert_eq!(code, Some(2), "{e}");
    assert!(
        e.starts_with("error: invalid grid: 10000 preloads x 10000 speeds need 399990000 model evaluations"),
        "{e}"
    );
    assert!(e.contains("estimated 111 h") && e.contains("the limit is 60 s"), "{e}");
}

#[test]
fn control_characters_in_messages_are_escaped() {
    let dir = tempfile::tempdir().unwrap();
    let builtin = include_str!("../../../configs/dkfzd4012.toml");
    let spec = dir.path().join("spec.toml");
    std::fs::write(&spec, format!("\"bad\\u001b[2Jkey\" = 1\n{builtin}")).unwrap();
    let e = fails(&["torque", "--spec", s(&spec)], 2);
    assert!(e.contains("unknown field `bad\\u{1b}[2Jkey`"), "{e}");
    let data = dir.path().join("d.csv");
    std::fs::write(&data, "preload_n,\u{1b}[31mred\n1000,1\n").unwrap();
    let o = ballscrew(&["predict", "--data", s(&data)]);
    let warning = String::from_utf8(o.stderr).unwrap();
    assert!(warning.contains("unknown column(s) ignored: `\\u{1b}[31mred`"), "{warning}");
    let e = fails(&["diagnose", "--data", s(&data), "--column", "torque_nm=zz"], 2);
    assert!(e.contains("(columns: `preload_n`, `\\u{1b}[31mred`)"), "{e}");
    let bell = dir.path().join("no\u{7}dir").join("x.csv");
    let e = fails(&["torque", "--out", s(&bell)], 1);
    assert!(e.contains("no\\u{7}dir"), "{e}");
    for text in [&e, &warning] {
        assert!(!text.contains(['\u{1b}', '\u{7}']), "raw control characters: {text:?}");
    }
}

/// At preload 0 the catalog torque is 0 and the ratio to it undefined.
#[test]
fn an_undefined_ratio_is_null_empty_or_na() {
    let csv = ok(&["sweep", "--preload", "0", "--format", "csv"]);
    let lines: Vec<&str> = csv.lines().collect();
    let i = lines[0].split(',').position(|k| k == "ratio").unwrap();
    assert_eq!(lines[1].split(',').nth(i), Some(""), "{csv}");
    let v: serde_json::Value = serde_json::from_str(&ok(&["sweep", "--preload", "0", "--format", "json"])).unwrap();
    assert!(v["rows"][0]["ratio"].is_null());
    let table = ok(&["torque", "--preload-n", "0"]);
    let row = table.lines().find(|l| l.starts_with("drag torque / catalog")).unwrap();
    assert!(row.contains("n/a"), "{row}");
    let csv = ok(&["torque", "--preload-n", "0", "--format", "csv"]);
    assert!(!csv.contains("NaN") && !csv.contains("inf"), "{csv}");
    let json = ok(&["torque", "--preload-n", "0", "--format", "json"]);
    assert!(json.contains("\"ratio\": null"), "{json}");
}

#[test]
fn no_progress_off_a_terminal_and_a_streamed_sweep_is_the_same_csv() {
    let dir = tempfile::tempdir().unwrap();
    let ops = dir.path().join("ops.csv");
    std::fs::write(&ops, "preload_n,speed_rpm\n1000,100\n2000,-300\n").unwrap();
    let file = dir.path().join("sweep.csv");
    // stderr is a pipe here: every command that shows progress on a terminal writes nothing there.
    let sweep = ["sweep", "--preload-n", "500..1500", "--step", "500", "--format", "csv"];
    for args in [&sweep[..], &["predict", "--data", s(&ops)], &["map"], &XJTU_UPPER[..]] {
        let out = ballscrew(args);
        assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
        assert_eq!(String::from_utf8_lossy(&out.stderr), "", "{args:?}");
    }
    // Streamed row by row to stdout, and written whole to a file: the same text.
    let streamed = ok(&sweep);
    ok(&[&sweep[..], &["--out", s(&file)]].concat());
    assert_eq!(streamed, std::fs::read_to_string(&file).unwrap());
    assert_eq!(streamed.lines().count(), 4, "{streamed}");
}
