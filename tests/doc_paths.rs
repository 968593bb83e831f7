//! Every path the documentation names exists: a link of a page of the README, the guide
//! (`docs/`), CHANGELOG.md or CONTRIBUTING.md, and a path in backquotes there or in a Rust doc
//! comment (`//!`, `///`) of the workspace's sources. A page moved or a file renamed fails here
//! with the page, the line and the path, where a reader would otherwise meet a dead end.
//!
//! What counts as a path: a link target that is not a web address or an anchor (resolved from
//! the page's own folder), and a backquoted word that starts with one of the repository's
//! top-level folders (`crates/`, `docs/`, `configs/`, `tests/`, `benches/`, `src/`) and holds no
//! placeholder (`*`, `<`, `{`, `...`). A backquoted path in a doc comment may also be relative to
//! the crate the comment is in (tests/realtime.rs of the core). A line that says its path is
//! another repository's (the word `repository` in it) names that repository's file. Files that a command of the
//! docs writes (`docs/figures/*.svg` are in the repository; an output like
//! `ballscrew_torque_map.h` starts with no folder) are not paths here.

use std::path::{Path, PathBuf};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");
const FOLDERS: [&str; 6] = ["crates/", "docs/", "configs/", "tests/", "benches/", "src/"];

/// Markdown pages: the root's and every one under `docs/`.
fn pages() -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> =
        ["README.md", "CHANGELOG.md", "CONTRIBUTING.md"].iter().map(|p| Path::new(ROOT).join(p)).collect();
    out.extend(files_under(&Path::new(ROOT).join("docs"), "md"));
    out.extend(files_under(&Path::new(ROOT).join("crates/py"), "md"));
    out
}

/// Files under `dir` with extension `ext`, leaving out build output and virtual environments.
fn files_under(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut dirs = vec![dir.to_path_buf()];
    while let Some(d) = dirs.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else { continue };
        for e in entries {
            let p = e.unwrap().path();
            let name = p.file_name().unwrap().to_string_lossy().to_string();
            if p.is_dir() {
                if !["target", ".venv", "venv", "node_modules", "__pycache__", "snapshots"].contains(&name.as_str())
                    && !name.starts_with('.')
                {
                    dirs.push(p);
                }
            } else if p.extension().is_some_and(|x| x == ext) {
                out.push(p);
            }
        }
    }
    out.sort();
    out
}

/// The backquoted words of `line` that look like repository paths.
fn backquoted_paths(line: &str) -> Vec<String> {
    line.split('`')
        .skip(1)
        .step_by(2)
        .filter(|w| FOLDERS.iter().any(|f| w.starts_with(f)))
        .filter(|w| !w.contains(['*', '<', '{', ' ', '$', '[', '=']) && !w.contains("..."))
        .map(|w| w.trim_end_matches([':', ',', '.', ')']).to_string())
        .collect()
}

/// The link targets of `line`: `](target)`, without an anchor.
fn link_targets(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(at) = rest.find("](") {
        rest = &rest[at + 2..];
        let Some(end) = rest.find(')') else { break };
        let target = rest[..end].split('#').next().unwrap_or("").trim();
        if !target.is_empty() && !target.contains("://") && !target.starts_with("mailto:") {
            out.push(target.to_string());
        }
        rest = &rest[end..];
    }
    out
}

#[test]
fn every_path_the_pages_name_exists() {
    let mut missing = Vec::new();
    let mut checked = 0;
    for page in pages() {
        let text = std::fs::read_to_string(&page).unwrap();
        let rel = page.strip_prefix(ROOT).unwrap().display().to_string();
        let mut fenced = false;
        for (n, line) in text.lines().enumerate() {
            if line.trim_start().starts_with("```") {
                fenced = !fenced;
                continue;
            }
            if fenced {
                continue;
            }
            for target in link_targets(line) {
                checked += 1;
                if !page.parent().unwrap().join(&target).exists() {
                    missing.push(format!("{rel}:{}: link {target}", n + 1));
                }
            }
            for path in backquoted_paths(line) {
                checked += 1;
                if !Path::new(ROOT).join(&path).exists() {
                    missing.push(format!("{rel}:{}: `{path}`", n + 1));
                }
            }
        }
    }
    assert!(checked > 100, "checked {checked}");
    assert!(missing.is_empty(), "paths the docs name that do not exist:\n{}", missing.join("\n"));
}

#[test]
fn every_path_a_doc_comment_names_exists() {
    let mut missing = Vec::new();
    let mut checked = 0;
    let mut sources = files_under(&Path::new(ROOT).join("crates"), "rs");
    sources.extend(files_under(&Path::new(ROOT).join("tests"), "rs"));
    sources.extend(files_under(&Path::new(ROOT).join("benches"), "rs"));
    sources.extend(files_under(&Path::new(ROOT).join("src"), "rs"));
    for file in sources {
        let rel = file.strip_prefix(ROOT).unwrap();
        // The crate the file is in: `crates/<name>`, else the root.
        let krate = match rel.components().next().map(|c| c.as_os_str().to_string_lossy().to_string()) {
            Some(c) if c == "crates" => Path::new(ROOT).join(rel.iter().take(2).collect::<PathBuf>()),
            _ => PathBuf::from(ROOT),
        };
        let text = std::fs::read_to_string(&file).unwrap();
        for (n, line) in text.lines().enumerate() {
            let t = line.trim_start();
            let Some(doc) = t.strip_prefix("//!").or_else(|| t.strip_prefix("///")) else { continue };
            if doc.contains("repository") {
                continue;
            }
            for path in backquoted_paths(doc) {
                checked += 1;
                if !Path::new(ROOT).join(&path).exists() && !krate.join(&path).exists() {
                    missing.push(format!("{}:{}: `{path}`", rel.display(), n + 1));
                }
            }
        }
    }
    assert!(checked > 50, "checked {checked}");
    assert!(missing.is_empty(), "paths doc comments name that do not exist:\n{}", missing.join("\n"));
}

/// Every page of the guide is a chapter of the book: `docs/SUMMARY.md` links it.
#[test]
fn every_page_of_the_guide_is_in_the_summary() {
    let docs = Path::new(ROOT).join("docs");
    let summary = std::fs::read_to_string(docs.join("SUMMARY.md")).unwrap();
    let linked = link_targets(&summary.replace('\n', " "));
    let orphans: Vec<String> = files_under(&docs, "md")
        .iter()
        .map(|p| p.strip_prefix(&docs).unwrap().display().to_string())
        .filter(|p| p != "SUMMARY.md" && !linked.contains(p))
        .collect();
    assert!(orphans.is_empty(), "pages of docs/ that docs/SUMMARY.md does not list: {orphans:?}");
}

#[test]
fn the_checker_finds_what_it_must() {
    assert_eq!(backquoted_paths("see `crates/core/src/lib.rs`, and `configs/*.toml`"), ["crates/core/src/lib.rs"]);
    assert_eq!(link_targets("[a](docs/x.md#y) and [b](https://example.org) [c](fleet.md)"), ["docs/x.md", "fleet.md"]);
}
