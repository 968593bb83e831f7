//! One vocabulary across the subcommands (docs/command-line.md, "One vocabulary"): the same flag for the same
//! quantity, its unit in its name, a value or an `A..B` range told apart the same way
//! everywhere, and `--format` offering per subcommand only what that subcommand writes. Read
//! from each subcommand's own `--help`, so a flag added under another name fails here.

mod common;

use common::{ballscrew, fails, ok_quiet as ok};

/// Every subcommand that reports on a spec: each takes `--spec`, `--out` and `--format`.
const SUBCOMMANDS: [&str; 10] =
    ["sweep", "torque", "sensitivity", "inspect", "contact", "creep-curves", "predict", "diagnose", "map", "reversal"];

/// The subcommands outside [`SUBCOMMANDS`], each with why it does not take all three shared flags.
const EXEMPT: [(&str, &str); 4] = [
    ("fmu", "writes one thing, an FMU archive of the spec: --spec and --out, no --format"),
    ("completions", "writes a shell's completion script of the command line itself: no spec, no --format"),
    ("man", "writes the manual of the command line itself: no spec; --format roff|markdown"),
    ("init", "writes a new spec from its flags, in the spec's one format (TOML): no --spec, no --format"),
];

/// The subcommands that take an operating point (or a range of one) from flags.
const POINT_COMMANDS: [&str; 8] =
    ["sweep", "torque", "sensitivity", "inspect", "contact", "creep-curves", "map", "reversal"];

/// The long flags of a subcommand's `--help` (canonical names, then aliases apart).
fn flags(subcommand: &str) -> (Vec<String>, Vec<String>) {
    let help = ok(&[subcommand, "--help"]);
    let mut names = Vec::new();
    let mut aliases = Vec::new();
    for line in help.lines() {
        let t = line.trim_start();
        if let Some(rest) = t.strip_prefix("--").or_else(|| t.strip_prefix("-h, --")) {
            names.push(format!("--{}", rest.split([' ', '<']).next().unwrap_or("")));
        }
        if let Some(list) = t.strip_prefix("[alias: ").or_else(|| t.strip_prefix("[aliases: ")) {
            aliases.extend(list.trim_end_matches(']').split(", ").map(str::to_string));
        }
    }
    (names, aliases)
}

/// The possible values of a subcommand's `--format`, from its `--help`.
fn formats(subcommand: &str) -> Vec<String> {
    let help = ok(&[subcommand, "--help"]);
    let after = help.split("--format <FORMAT>").nth(1).expect("a --format flag");
    let block = after.split("Possible values:").nth(1).expect("its possible values");
    block
        .lines()
        .map(str::trim)
        .take_while(|l| l.starts_with("- ") || l.is_empty())
        .filter_map(|l| l.strip_prefix("- ")?.split(':').next().map(str::to_string))
        .collect()
}

/// The subcommands `ballscrew --help` lists, clap's `help` left out.
fn listed_subcommands() -> Vec<String> {
    let help = ok(&["--help"]);
    let block = help.split("Commands:\n").nth(1).expect("a Commands: block");
    block
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .filter(|l| l.starts_with("  ") && !l.starts_with("   "))
        .filter_map(|l| l.split_whitespace().next().map(str::to_string))
        .filter(|n| n != "help")
        .collect()
}

/// A new subcommand is in [`SUBCOMMANDS`] (and so held to the shared flags) or exempt with a
/// reason.
#[test]
fn every_subcommand_is_held_to_the_shared_flags_or_exempt_by_name() {
    let listed = listed_subcommands();
    let known: Vec<&str> = SUBCOMMANDS.iter().copied().chain(EXEMPT.iter().map(|(name, _)| *name)).collect();
    for sub in &listed {
        assert!(known.contains(&sub.as_str()), "{sub}: add it to SUBCOMMANDS or to EXEMPT with a reason");
    }
    for sub in known {
        assert!(listed.iter().any(|l| l == sub), "{sub} is not a subcommand: {listed:?}");
    }
}

#[test]
fn every_subcommand_takes_the_shared_flags_under_the_same_names() {
    for sub in SUBCOMMANDS {
        let (names, _) = flags(sub);
        for shared in ["--spec", "--out", "--format"] {
            assert!(names.iter().any(|n| n == shared), "{sub}: {shared} missing in {names:?}");
        }
    }
    // `fmu` writes an FMU archive: the spec and the output, no format.
    let (names, _) = flags("fmu");
    assert!(names.iter().any(|n| n == "--spec") && names.iter().any(|n| n == "--out"), "fmu: {names:?}");
    assert!(!names.iter().any(|n| n == "--format"), "fmu has one output, an FMU archive: {names:?}");
    // `completions` and `man` describe the command line: they refuse --spec (it is global, so
    // their `--help` shows it) and write to --out.
    for sub in ["completions", "man"] {
        let (names, _) = flags(sub);
        assert!(names.iter().any(|n| n == "--out"), "{sub}: {names:?}");
    }
    assert!(!flags("completions").0.iter().any(|n| n == "--format"), "completions: the shell is its argument");
    // `init` writes a spec: --out, no --format; its preload is the preload's flag elsewhere.
    let (names, _) = flags("init");
    assert!(names.iter().any(|n| n == "--out") && !names.iter().any(|n| n == "--format"), "init: {names:?}");
    assert!(names.iter().any(|n| n == "--preload-n"), "init: {names:?}");
    for sub in POINT_COMMANDS {
        let (names, aliases) = flags(sub);
        for quantity in ["--preload-n", "--speed-rpm", "--axial-load-n"] {
            assert!(names.iter().any(|n| n == quantity), "{sub}: {quantity} missing in {names:?}");
        }
        // `--preload` (the README's first command) is the preload's alias everywhere.
        assert!(aliases.iter().any(|a| a == "--preload"), "{sub}: --preload alias missing in {aliases:?}");
    }
    for sub in ["predict", "diagnose"] {
        let (names, _) = flags(sub);
        for data in ["--data", "--delimiter", "--column"] {
            assert!(names.iter().any(|n| n == data), "{sub}: {data} missing");
        }
    }
}

/// A flag about a quantity carries the quantity's name and its unit: the value (`--preload-n`),
/// its step (`--preload-step-n`) and a count of points (`--preload-points`, no unit), nothing
/// else, in every subcommand.
#[test]
fn a_quantitys_flags_are_named_by_the_quantity_and_its_unit() {
    let allowed: [(&str, &[&str]); 4] = [
        ("--preload", &["--preload-n", "--preload-step-n", "--preload-points"]),
        ("--speed", &["--speed-rpm", "--speed-step-rpm", "--speed-points", "--speed-spacing"]),
        ("--axial-load", &["--axial-load-n", "--axial-load-step-n"]),
        ("--oil-temperature", &["--oil-temperature-c", "--oil-temperature-step-c"]),
    ];
    let mut seen = 0;
    for sub in SUBCOMMANDS {
        let (names, _) = flags(sub);
        for name in &names {
            for (prefix, valid) in allowed {
                if name.starts_with(prefix) {
                    seen += 1;
                    assert!(valid.contains(&name.as_str()), "{sub}: {name} (valid for {prefix}: {valid:?})");
                }
            }
        }
    }
    assert!(seen >= 25, "the flags were read: {seen}");
}

#[test]
fn format_offers_what_each_subcommand_writes() {
    for sub in ["sweep", "torque", "sensitivity", "inspect", "contact", "creep-curves", "reversal"] {
        assert_eq!(formats(sub), ["table", "csv", "json"], "{sub}");
    }
    assert_eq!(formats("map"), ["table", "c", "rust", "csv"]);
    assert_eq!(formats("diagnose"), ["table", "json"]);
    assert_eq!(formats("predict"), ["csv", "json"]);
    assert_eq!(formats("man"), ["roff", "markdown"]);
    // What is not offered is refused by name with what is.
    let e = fails(&["predict", "--format", "table"], 2);
    assert!(
        e.contains("invalid value 'table' for '--format <FORMAT>'") && e.contains("[possible values: csv, json]"),
        "{e}"
    );
    let e = fails(&["torque", "--format", "rust"], 2);
    assert!(e.contains("[possible values: table, csv, json]"), "{e}");
}

/// The alias and the name give the same result; a range where one value is taken is refused
/// naming the flag (a range is always `A..B`, a value a number).
#[test]
fn values_and_ranges_are_told_apart_the_same_way() {
    for sub in ["torque", "inspect"] {
        let a = ok(&[sub, "--preload", "1500", "--format", "json"]);
        let b = ok(&[sub, "--preload-n", "1500", "--format", "json"]);
        assert_eq!(a, b, "{sub}");
        let o = ballscrew(&[sub, "--preload-n", "500..1000"]);
        assert_eq!(o.status.code(), Some(2), "{sub}");
        assert!(String::from_utf8_lossy(&o.stderr).contains("--preload-n"), "{sub}");
    }
    let a = ok(&["sweep", "--preload", "500..1000", "--step", "500", "--format", "csv"]);
    let b = ok(&["sweep", "--preload-n", "500..1000", "--preload-step-n", "500", "--format", "csv"]);
    assert_eq!(a, b);
    // (A coarse map: its warning and description go to stderr; the CSV alone to stdout.)
    let map = |flag| {
        let o =
            ballscrew(&["map", flag, "500..1000", "--preload-points", "2", "--speed-points", "4", "--format", "csv"]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        o.stdout
    };
    assert_eq!(map("--preload"), map("--preload-n"));
}
