//! The README's command-line examples cannot go stale: the output shown under "Example" is the
//! command's output to the byte, and every `ballscrew` command of a `sh` block (but synopses
//! with `[optional]` parts) runs and succeeds. The Python examples are run by
//! `crates/py/tests/test_readme.py`.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

fn readme() -> String {
    std::fs::read_to_string(Path::new(ROOT).join("README.md")).expect("README.md")
}

/// The fenced blocks of `text` with their language: (language, body).
fn blocks(text: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut open: Option<(String, String)> = None;
    for line in text.lines() {
        match (&mut open, line.strip_prefix("```")) {
            (None, Some(lang)) => open = Some((lang.trim().to_string(), String::new())),
            (Some(_), Some(_)) => out.extend(open.take()),
            (Some((_, body)), None) => {
                body.push_str(line);
                body.push('\n');
            }
            (None, None) => {}
        }
    }
    out
}

/// The command lines of a `sh` block: continuation lines joined, comments cut.
fn command_lines(body: &str) -> Vec<String> {
    let joined = body.replace("\\\n", " ");
    joined.lines().map(|l| l.split(" #").next().unwrap_or("").trim().to_string()).filter(|l| !l.is_empty()).collect()
}

/// Splits a command line into words (the README's lines have no quoting).
fn words(line: &str) -> Vec<String> {
    line.split_whitespace().map(str::to_string).collect()
}

/// The arguments of `ballscrew` in a README command line, or why it is not run here.
fn ballscrew_args(line: &str) -> Result<Vec<String>, &'static str> {
    let w = words(line);
    let args: Vec<String> = match w.first().map(String::as_str) {
        Some("ballscrew") | Some("target/release/ballscrew") => w[1..].to_vec(),
        Some("cargo") if line.starts_with("cargo run --release -p ballscrew-cli --") => {
            w.iter().skip_while(|x| *x != "--").skip(1).cloned().collect()
        }
        Some("cargo") => return Err("a cargo build, bench or test (the suite runs those itself)"),
        Some("pip") | Some("python") | Some("bash") => return Err("not the command line"),
        _ => return Err("not a command"),
    };
    if line.contains('[') {
        return Err("a synopsis with optional parts");
    }
    if args.first().map(String::as_str) == Some("fmu") {
        return Err("the FMU: built and simulated by crates/py/tests/test_fmu.py");
    }
    Ok(args)
}

/// A directory to run in, where `configs` and `tests` are the repository's (the README's
/// relative paths) and outputs land in a temporary place.
fn workdir() -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    for name in ["configs", "tests"] {
        std::os::unix::fs::symlink(Path::new(ROOT).join(name), dir.path().join(name)).unwrap();
    }
    let path = dir.path().to_path_buf();
    (dir, path)
}

#[test]
fn the_example_output_is_the_commands_output() {
    let text = readme();
    let at = text.find("## Example").expect("an Example section");
    let section = &text[at..];
    let command = section.lines().nth(2).expect("its command line");
    let command = command.split('`').nth(1).expect("the command in backquotes");
    let (lang, shown) = blocks(section).into_iter().next().expect("its output block");
    assert_eq!(lang, "text");
    let args = ballscrew_args(command).expect("a ballscrew command");
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = common::ok(&args);
    assert_eq!(shown, out, "README's Example block is stale: regenerate it with `{command}`");
}

#[test]
fn every_readme_command_runs() {
    let (_dir, cwd) = workdir();
    let mut ran = 0;
    let mut skipped = Vec::new();
    for (lang, body) in blocks(&readme()) {
        if lang != "sh" {
            continue;
        }
        for line in command_lines(&body) {
            match ballscrew_args(&line) {
                Ok(args) => {
                    let o =
                        Command::new(env!("CARGO_BIN_EXE_ballscrew")).args(&args).current_dir(&cwd).output().unwrap();
                    assert!(o.status.success(), "README: `{line}` failed: {}", String::from_utf8_lossy(&o.stderr));
                    ran += 1;
                }
                Err(why) => skipped.push(format!("{line}: {why}")),
            }
        }
    }
    // The run command of "Set up", the map, the diagnosis of the XJTU data at the least.
    assert!(ran >= 3, "ran {ran}; skipped: {skipped:#?}");
    assert!(cwd.join("ballscrew_torque_map.h").exists(), "the map command wrote its header");
}
