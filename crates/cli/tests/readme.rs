//! The README's and the guide's command-line examples cannot go stale. Over every page (the
//! README, CONTRIBUTING.md and every Markdown page under `docs/`):
//!
//! - every `ballscrew` command of a `sh` block (but synopses with `[optional]` parts) runs and
//!   succeeds, in a directory where `configs/` and `tests/` are the repository's (the pages'
//!   relative paths); a `cp` line runs too, so a page can copy a shipped spec and use it;
//! - a figure such a command draws into `docs/figures/` is the repository's, byte for byte;
//! - every `text` block shown as a command's output (the paragraph before it opens with the
//!   command in backquotes) is that command's output to the byte;
//! - the README's table "Where the prediction stands" is what `ballscrew torque` prints, row by
//!   row, and its measured column is the XJTU data's first row.
//!
//! The Python blocks are run by `crates/py/tests/test_readme.py`, the Rust blocks are the root
//! package's doc tests (`src/lib.rs`), the paths the pages name are checked by
//! `tests/doc_paths.rs`.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

/// Every page: (path relative to the repository, text).
fn pages() -> Vec<(String, String)> {
    let mut out = Vec::new();
    for name in ["README.md", "CONTRIBUTING.md"] {
        out.push((name.to_string(), std::fs::read_to_string(Path::new(ROOT).join(name)).expect(name)));
    }
    let mut dirs = vec![PathBuf::from("docs")];
    while let Some(dir) = dirs.pop() {
        let mut entries: Vec<_> =
            std::fs::read_dir(Path::new(ROOT).join(&dir)).unwrap().map(|e| e.unwrap().path()).collect();
        entries.sort();
        for path in entries {
            let rel = dir.join(path.file_name().unwrap());
            if path.is_dir() {
                dirs.push(rel);
            } else if path.extension().is_some_and(|e| e == "md") {
                out.push((rel.display().to_string(), std::fs::read_to_string(&path).unwrap()));
            }
        }
    }
    out
}

/// A fenced block: its language, its body (dedented as far as its fence) and the paragraph
/// before it.
struct Block {
    lang: String,
    body: String,
    before: String,
}

/// The fenced blocks of `text`, fences indented or not (a block inside a list item).
fn blocks(text: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut open: Option<(usize, Block)> = None;
    let mut paragraph: Vec<&str> = Vec::new();
    let mut last = String::new();
    for line in text.lines() {
        let trimmed = line.trim_start();
        let indent = line.len() - trimmed.len();
        match (&mut open, trimmed.strip_prefix("```")) {
            (None, Some(lang)) => {
                let before = if paragraph.is_empty() { last.clone() } else { paragraph.join("\n") };
                open = Some((indent, Block { lang: lang.trim().to_string(), body: String::new(), before }));
            }
            (Some(_), Some(_)) => {
                out.extend(open.take().map(|(_, b)| b));
                paragraph.clear();
                last.clear();
            }
            (Some((ind, block)), None) => {
                block.body.push_str(line.get(*ind..).unwrap_or(line.trim_start()));
                block.body.push('\n');
            }
            (None, None) if line.trim().is_empty() => {
                if !paragraph.is_empty() {
                    last = paragraph.join("\n");
                    paragraph.clear();
                }
            }
            (None, None) => paragraph.push(line),
        }
    }
    out
}

/// The command lines of a `sh` block: continuation lines joined, comments cut.
fn command_lines(body: &str) -> Vec<String> {
    let joined = body.replace("\\\n", " ");
    joined.lines().map(|l| l.split(" #").next().unwrap_or("").trim().to_string()).filter(|l| !l.is_empty()).collect()
}

/// Splits a command line into words (the pages' lines have no quoting).
fn words(line: &str) -> Vec<String> {
    line.split_whitespace().map(str::to_string).collect()
}

/// What a page's command line is, for this test.
enum Line {
    /// `ballscrew` with these arguments.
    Ballscrew(Vec<String>),
    /// `cp` with these arguments.
    Copy(Vec<String>),
}

/// What to run for a command line, or why it is not run here.
fn classify(line: &str) -> Result<Line, &'static str> {
    let w = words(line);
    let args: Vec<String> = match w.first().map(String::as_str) {
        Some("ballscrew") | Some("target/release/ballscrew") => w[1..].to_vec(),
        Some("cargo") if line.starts_with("cargo run --release -p ballscrew-cli --") => {
            w.iter().skip_while(|x| *x != "--").skip(1).cloned().collect()
        }
        Some("cp") => return Ok(Line::Copy(w[1..].to_vec())),
        Some("cargo") => return Err("a cargo build, bench, install or test (the suite runs those itself)"),
        Some("pip") | Some("python") | Some("bash") | Some("make") | Some("rustup") => {
            return Err("not the command line (the suite's own steps or Python)");
        }
        _ => return Err("not a command"),
    };
    if line.contains('[') || line.contains('<') {
        return Err("a synopsis with optional parts");
    }
    if args.first().map(String::as_str) == Some("fmu") {
        return Err("the FMU: built and simulated by crates/py/tests/test_fmu.py");
    }
    Ok(Line::Ballscrew(args))
}

/// A directory to run in, where `configs` and `tests` are the repository's (the pages'
/// relative paths) and outputs land in a temporary place.
fn workdir() -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    for name in ["configs", "tests"] {
        std::os::unix::fs::symlink(Path::new(ROOT).join(name), dir.path().join(name)).unwrap();
    }
    std::fs::create_dir(dir.path().join("docs")).unwrap();
    std::fs::create_dir(dir.path().join("docs").join("figures")).unwrap();
    let path = dir.path().to_path_buf();
    (dir, path)
}

#[test]
fn every_output_block_is_the_commands_output() {
    let mut checked = Vec::new();
    for (page, text) in pages() {
        for block in blocks(&text) {
            if block.lang != "text" {
                continue;
            }
            let Some(command) = block.before.strip_prefix('`').and_then(|s| s.split('`').next()) else {
                continue;
            };
            let Ok(Line::Ballscrew(args)) = classify(command) else { continue };
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            let out = common::ok(&args);
            assert_eq!(block.body, out, "{page}: the output shown under `{command}` is stale: regenerate it");
            checked.push(page.clone());
        }
    }
    assert!(checked.iter().any(|p| p == "README.md"), "the README's Example is checked: {checked:?}");
    assert!(checked.len() >= 2, "{checked:?}");
}

#[test]
fn every_command_of_every_page_runs() {
    let mut ran = 0;
    let mut skipped = Vec::new();
    let mut pages_with_commands = 0;
    for (page, text) in pages() {
        let (_dir, cwd) = workdir();
        let mut ran_here = 0;
        for block in blocks(&text) {
            if block.lang != "sh" {
                continue;
            }
            for line in command_lines(&block.body) {
                let o = match classify(&line) {
                    Ok(Line::Ballscrew(args)) => {
                        Command::new(env!("CARGO_BIN_EXE_ballscrew")).args(&args).current_dir(&cwd).output().unwrap()
                    }
                    Ok(Line::Copy(args)) => Command::new("cp").args(&args).current_dir(&cwd).output().unwrap(),
                    Err(why) => {
                        skipped.push(format!("{page}: {line}: {why}"));
                        continue;
                    }
                };
                assert!(o.status.success(), "{page}: `{line}` failed: {}", String::from_utf8_lossy(&o.stderr));
                ran_here += 1;
            }
        }
        // A figure a page's command draws into `docs/figures/` is the repository's figure.
        for entry in std::fs::read_dir(cwd.join("docs/figures")).unwrap() {
            let made = entry.unwrap().path();
            let kept = Path::new(ROOT).join("docs/figures").join(made.file_name().unwrap());
            assert!(
                std::fs::read(&kept).ok() == std::fs::read(&made).ok(),
                "{page}: {} is stale or missing: run the page's command from the repository's root",
                kept.display()
            );
        }
        if page == "README.md" {
            // The run command of "Set up", init and the two commands of one's own screw.
            assert!(ran_here >= 4, "README: ran {ran_here}; skipped: {skipped:#?}");
            assert!(cwd.join("my_screw.toml").exists(), "the README's init wrote its spec");
        }
        if page == "docs/real-time.md" {
            assert!(cwd.join("ballscrew_torque_map.h").exists(), "the map command wrote its header");
        }
        pages_with_commands += usize::from(ran_here > 0);
        ran += ran_here;
    }
    assert!(pages_with_commands >= 4 && ran >= 10, "ran {ran} on {pages_with_commands} pages; skipped: {skipped:#?}");
}

/// `value` rounds to `printed`, given with `decimals` decimals.
fn rounds_to(value: f64, printed: &str) -> bool {
    let decimals = printed.split('.').nth(1).map_or(0, str::len) as i32;
    let p: f64 = printed.parse().unwrap_or_else(|_| panic!("a number: {printed}"));
    (value - p).abs() <= 0.5 * 10f64.powi(-decimals) * (1.0 + 1e-9)
}

/// The first number of a cell (`2000 N`, `0.1811 N m`, `0.40 and 0.52 N m`), and all of them.
fn numbers(cell: &str) -> Vec<&str> {
    cell.split_whitespace().filter(|w| w.parse::<f64>().is_ok()).collect()
}

#[test]
fn the_standing_table_is_what_torque_prints() {
    let (_, readme) = pages().into_iter().next().unwrap();
    let at = readme.find("## Where the prediction stands").expect("the section");
    let rows: Vec<Vec<&str>> = readme[at..]
        .lines()
        .skip_while(|l| !l.starts_with('|'))
        .take_while(|l| l.starts_with('|'))
        .skip(2)
        .map(|l| l.trim_matches('|').split('|').map(str::trim).collect())
        .collect();
    assert!(rows.len() >= 5, "{rows:?}");
    let first_data_row: Vec<f64> = {
        let text = std::fs::read_to_string(common::XJTU_DATA).unwrap();
        text.lines().nth(1).unwrap().split(',').map(|x| x.parse().unwrap()).collect()
    };
    for row in rows {
        let [screw, preload, speed, model, catalog, ratio, measured] = row[..] else { panic!("7 cells: {row:?}") };
        let spec = screw.split('`').nth(1).expect("the spec in backquotes");
        let (preload, speed) = (numbers(preload)[0], numbers(speed)[0]);
        let out = common::ok(&[
            "--spec",
            &format!("{ROOT}/{spec}"),
            "torque",
            "--preload-n",
            preload,
            "--speed-rpm",
            speed,
            "--format",
            "json",
        ]);
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        let get = |k: &str| v[k].as_f64().unwrap();
        for (printed, key) in [(model, "drag_torque_nm"), (catalog, "catalog_nm"), (ratio, "ratio")] {
            let printed = numbers(printed)[0];
            assert!(
                rounds_to(get(key), printed),
                "{spec} {preload} N {speed} rpm: {key} {} printed {printed}",
                get(key)
            );
        }
        if !measured.is_empty() {
            assert!(spec.contains("xjtu"), "measured data of the XJTU screws only");
            let m = numbers(measured);
            assert_eq!(m.len(), 2, "upper and lower screw");
            assert!(rounds_to(first_data_row[1], m[0]) && rounds_to(first_data_row[2], m[1]), "{m:?}");
        }
    }
}
