//! `docs/spec-reference.md` is the page rendered from the table of keys
//! ([`ballscrew_config::spec_reference`]; `BALLSCREW_BLESS=1` rewrites it), and it is checked
//! against the parser: its tables list exactly the keys the parser accepts, each range end and
//! option is tried, each default is compared with what the parser fills in and each required key
//! is required. The table's ranges are the core's constants, so these checks tie the table to
//! the core's validation.
//!
//! The page's format (described on the page): one markdown table per TOML table under a heading
//! `` ## `[table]` ``, with the columns `key | unit | default | valid | meaning | source`. The
//! default cell is `required`, a TOML value in backticks, or words (an optional key without a
//! single default). The valid cell starts with a code span: `[a, b]`, `(a, b]`, `[a, b)`,
//! `(a, b)` for numbers (`count` keys step by 1), `"a" | "b"` or `true | false` for the allowed
//! values.
//!
//! Some ranges depend on other keys (ball diameter below half the pitch diameter, nuts against
//! the preload arrangement, the two viscosities); [`context`] sets those other keys to values
//! under which the documented range is the key's own.

use ballscrew_config::{ConfigError, DKFZD4012_TOML, spec_from_toml_str, spec_reference, spec_to_toml};
use ballscrew_core::input::extensions::{
    AxialLoadLoss, DirectionAsymmetry, Extensions, LevelFactor, PreloadLaw, PreloadLoss, RacewayWaviness, SealDrag,
    ThermalViscosity, ViscousDrag,
};
use ballscrew_core::input::{Circulation, Return, ScrewSpec};
extern crate alloc;
use alloc::collections::BTreeSet;

/// The page in the repository.
const PAGE_PATH: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/spec-reference.md");
const ORIGIN: &str = "spec-reference";

/// Keys that are read but never written (`spec_to_toml` writes the viscosities instead).
const INPUT_ONLY_KEYS: [&str; 1] = ["lubricant.iso_vg"];

/// Relative distance of a value "just inside" or "just outside" a range end (at least this much
/// in absolute terms).
const STEP_REL: f64 = 1e-6;

#[derive(Debug, Clone, PartialEq)]
enum Valid {
    Range {
        lo: f64,
        lo_open: bool,
        hi: f64,
        hi_open: bool,
    },
    /// TOML literals, e.g. `"geometric"`, `true`.
    Options(Vec<String>),
}

#[derive(Debug, Clone)]
struct Row {
    table: String,
    key: String,
    unit: String,
    /// `None`: required.
    default: Option<DefaultCell>,
    valid: Valid,
}

#[derive(Debug, Clone, PartialEq)]
enum DefaultCell {
    /// A TOML literal.
    Value(String),
    /// Words: optional, without a single default value.
    Words,
}

impl Row {
    fn full(&self) -> String {
        format!("{}.{}", self.table, self.key)
    }
    fn is_count(&self) -> bool {
        self.unit == "count"
    }
    /// A valid value of the key (the lower end of its range, or the first option).
    fn probe(&self) -> String {
        match &self.valid {
            Valid::Range { lo, lo_open, .. } => {
                let v = if *lo_open { lo + step(*lo) } else { *lo };
                self.literal(v)
            }
            Valid::Options(o) => o[0].clone(),
        }
    }
    fn literal(&self, v: f64) -> String {
        if self.is_count() { format!("{}", v as i64) } else { format!("{v:?}") }
    }
}

fn step(end: f64) -> f64 {
    STEP_REL * end.abs().max(1.0)
}

/// The first code span of a cell.
fn code_span(cell: &str) -> Option<&str> {
    let start = cell.find('`')? + 1;
    let len = cell[start..].find('`')?;
    Some(&cell[start..start + len])
}

/// The cells of a table row, split at unescaped `|` (`\|` is a `|` inside a cell).
fn cells(line: &str) -> Vec<String> {
    let inner = line.trim().trim_start_matches('|').trim_end_matches('|');
    let mut out = vec![String::new()];
    let mut chars = inner.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                chars.next();
                out.last_mut().unwrap().push('|');
            }
            '|' => out.push(String::new()),
            _ => out.last_mut().unwrap().push(c),
        }
    }
    out.into_iter().map(|c| c.trim().to_string()).collect()
}

fn parse_valid(cell: &str, what: &str) -> Valid {
    let code = code_span(cell).unwrap_or_else(|| panic!("{what}: no code span in the valid cell: {cell}"));
    let first = code.chars().next().unwrap_or(' ');
    if first == '[' || first == '(' {
        let last = code.chars().last().unwrap();
        assert!(last == ']' || last == ')', "{what}: range not closed: {code}");
        let (lo, hi) = code[1..code.len() - 1].split_once(',').unwrap_or_else(|| panic!("{what}: {code}"));
        let num = |s: &str| s.trim().parse::<f64>().unwrap_or_else(|_| panic!("{what}: not a number: {s}"));
        let (lo, hi) = (num(lo), num(hi));
        assert!(lo < hi, "{what}: empty range {code}");
        Valid::Range { lo, lo_open: first == '(', hi, hi_open: last == ')' }
    } else {
        let options: Vec<String> = code.split('|').map(|o| o.trim().to_string()).collect();
        for o in &options {
            let ok = (o.len() >= 2 && o.starts_with('"') && o.ends_with('"')) || o == "true" || o == "false";
            assert!(ok, "{what}: not an option: {o}");
        }
        Valid::Options(options)
    }
}

/// Every row of every table of the page (as rendered: the page in the repository is this text,
/// [`the_page_is_the_rendered_table_of_keys`]).
fn rows() -> Vec<Row> {
    let mut table: Option<String> = None;
    let mut out = Vec::new();
    for line in spec_reference().lines() {
        if let Some(h) = line.strip_prefix("## ") {
            table = code_span(h).and_then(|c| c.strip_prefix('[')).and_then(|c| c.strip_suffix(']')).map(String::from);
            continue;
        }
        let Some(t) = &table else { continue };
        if !line.starts_with("| `") {
            continue;
        }
        let c = cells(line);
        assert_eq!(c.len(), 6, "six columns: {line}");
        let key = code_span(&c[0]).unwrap_or_else(|| panic!("key in backticks: {line}")).to_string();
        let what = format!("{t}.{key}");
        let default = if c[2] == "required" {
            None
        } else {
            Some(match code_span(&c[2]) {
                Some(v) if c[2].starts_with('`') => DefaultCell::Value(v.to_string()),
                _ => DefaultCell::Words,
            })
        };
        out.push(Row { table: t.clone(), key, unit: c[1].clone(), default, valid: parse_valid(&c[3], &what) });
    }
    assert!(out.len() > 50, "the page's tables were read: {} rows", out.len());
    out
}

/// The key of a `key = value` line.
fn key_of(line: &str) -> Option<&str> {
    let t = line.trim();
    if t.starts_with('#') || t.starts_with('[') {
        return None;
    }
    Some(t.split_once('=')?.0.trim())
}

fn header_of(line: &str) -> Option<&str> {
    line.trim().strip_prefix('[')?.split_once(']').map(|(t, _)| t.trim())
}

/// The built-in spec with each `(table.key, value)` set: `Some` replaces the key's line (or adds
/// it under its table's header, adding the table at the end if the file has none), `None`
/// removes it.
fn spec_with(sets: &[(String, Option<String>)]) -> String {
    let mut lines: Vec<String> = DKFZD4012_TOML.lines().map(String::from).collect();
    for (full, value) in sets {
        let (table, key) = full.rsplit_once('.').unwrap();
        let header = lines.iter().position(|l| header_of(l) == Some(table));
        let header = match header {
            Some(h) => h,
            None => {
                lines.push(format!("[{table}]"));
                lines.len() - 1
            }
        };
        let end =
            lines[header + 1..].iter().position(|l| header_of(l).is_some()).map_or(lines.len(), |i| header + 1 + i);
        let at = (header + 1..end).find(|&i| key_of(&lines[i]) == Some(key));
        match (at, value) {
            (Some(i), Some(v)) => lines[i] = format!("{key} = {v}"),
            (Some(i), None) => {
                lines.remove(i);
            }
            (None, Some(v)) => lines.insert(header + 1, format!("{key} = {v}")),
            (None, None) => {}
        }
    }
    lines.join("\n") + "\n"
}

fn set(full: &str, value: &str) -> (String, Option<String>) {
    (full.to_string(), Some(value.to_string()))
}

fn unset(full: &str) -> (String, Option<String>) {
    (full.to_string(), None)
}

/// The other keys a key's documented range or option `value` needs: in an extension table the
/// table's other required keys (at valid values); for the keys whose valid values depend on
/// others, those others.
fn context(rows: &[Row], row: &Row, value: &str) -> Vec<(String, Option<String>)> {
    let mut out = Vec::new();
    if row.table.starts_with("extensions.") {
        for r in rows.iter().filter(|r| r.table == row.table && r.key != row.key && r.default.is_none()) {
            out.push(set(&r.full(), &r.probe()));
        }
    }
    match row.full().as_str() {
        // Below half the pitch diameter at every documented pitch diameter.
        "geometry.pitch_diameter_mm" => out.push(set("geometry.ball_diameter_mm", "0.5")),
        // 50 mm balls need a pitch diameter above 100 mm; a circle of them holds fewer than 19.
        "geometry.ball_diameter_mm" => {
            out.push(set("geometry.pitch_diameter_mm", "300.0"));
            out.push(set("geometry.balls_per_circle", "1"));
        }
        // The arrangement follows the nuts (absent `preload`), and a nut without preload
        // takes no preload.
        "geometry.nuts" => {
            out.push(unset("geometry.preload"));
            out.push(set("operating.preload_n", "0.0"));
        }
        "geometry.preload" if value != "\"double-nut\"" => {
            out.push(set("geometry.nuts", "1"));
            out.push(set("operating.preload_n", "0.0"));
        }
        // The preload's default (0 N) is a nut's without preload; a preloaded nut needs its own.
        "operating.preload_n" if value == "0.0" => {
            out.push(set("geometry.nuts", "1"));
            out.push(set("geometry.preload", "\"none\""));
        }
        "lubricant.viscosity_40c_mm2_s" => {
            out.push(unset("lubricant.iso_vg"));
            out.push(set("lubricant.viscosity_100c_mm2_s", "2.0"));
        }
        "lubricant.viscosity_100c_mm2_s" => {
            out.push(unset("lubricant.iso_vg"));
            out.push(set("lubricant.viscosity_40c_mm2_s", "5000.0"));
        }
        _ => {}
    }
    out
}

/// The built-in spec with `row`'s key at `value` (a TOML literal), in the key's context.
fn text_with(rows: &[Row], row: &Row, value: &str) -> String {
    let mut sets = context(rows, row, value);
    sets.push(set(&row.full(), value));
    spec_with(&sets)
}

fn accepted(rows: &[Row], row: &Row, value: &str) -> ScrewSpec {
    let text = text_with(rows, row, value);
    spec_from_toml_str(&text, ORIGIN).unwrap_or_else(|e| panic!("{} = {value} refused: {e}\n{text}", row.full()))
}

fn refused(rows: &[Row], row: &Row, value: &str) -> ConfigError {
    let text = text_with(rows, row, value);
    match spec_from_toml_str(&text, ORIGIN) {
        Ok(_) => panic!("{} = {value} accepted\n{text}", row.full()),
        Err(e) => e,
    }
}

/// Every `table.key` of a TOML text.
fn keys_of(text: &str) -> BTreeSet<String> {
    let mut table = String::new();
    let mut out = BTreeSet::new();
    for l in text.lines() {
        if let Some(t) = header_of(l) {
            table = t.to_string();
        } else if let Some(k) = key_of(l) {
            out.insert(format!("{table}.{k}"));
        }
    }
    out
}

/// A spec with every optional table and term on: what `spec_to_toml` writes of it is every key
/// the file format has (but the input-only ones).
fn spec_with_everything() -> ScrewSpec {
    let mut spec = ScrewSpec::dkfzd4012();
    let drag = ViscousDrag { torque_nm: 0.01, exponent: 0.7, reference_speed_rad_s: 100.0 };
    spec.extensions = Extensions {
        seal_drag: Some(SealDrag { torque_nm: 0.02 }),
        viscous_drag: Some(drag),
        thermal_viscosity: Some(ThermalViscosity {
            drag,
            viscosity_coefficient_per_k: 0.03,
            reference_temperature_c: 40.0,
        }),
        raceway_waviness: Some(RacewayWaviness { harmonic: 2, amplitude_nm: 0.005, phase_rad: 0.5 }),
        preload_loss: Some(PreloadLoss { loss_per_1000_h: 0.3 }),
        direction_asymmetry: Some(DirectionAsymmetry { reverse_factor: 1.2 }),
        preload_law: Some(PreloadLaw { exponent: -0.2, reference_preload_n: 1500.0 }),
        axial_load_loss: Some(AxialLoadLoss { torque_per_n_nm: 3e-4 }),
        level_factor: Some(LevelFactor { factor: 1.3 }),
    };
    spec.lubricant.inlet_distance_ratio = Some(5.0);
    spec.friction.ball_ball_load_n = Some(1.0);
    spec.circulation = Circulation {
        kind: Return::External,
        turns_per_circuit: Some(1),
        return_balls: Some(3),
        return_friction: Some(0.02),
        lead_deviation_m: 2e-6,
        load_ramp_balls: 2,
        spacer_balls: true,
    };
    // Every half-width off its default, so that each is written.
    spec.uncertainty.half_widths = spec.uncertainty.half_widths.map(|h| h + 0.01);
    spec
}

#[test]
fn the_page_is_the_rendered_table_of_keys() {
    let generated = spec_reference();
    if std::env::var_os("BALLSCREW_BLESS").is_some() {
        std::fs::write(PAGE_PATH, &generated).unwrap();
        return;
    }
    let page = std::fs::read_to_string(PAGE_PATH).unwrap_or_default();
    assert!(
        page == generated,
        "docs/spec-reference.md is stale: regenerate it with\n  \
         BALLSCREW_BLESS=1 cargo test --release -p ballscrew-config --test spec_reference"
    );
}

#[test]
fn documented_keys_are_the_keys_the_parser_accepts() {
    let rows = rows();
    let documented: BTreeSet<String> = rows.iter().map(Row::full).collect();
    assert_eq!(documented.len(), rows.len(), "no key is documented twice");
    let spec = spec_with_everything();
    let text = spec_to_toml(&spec);
    // The written spec reads back: its keys are accepted keys.
    spec_from_toml_str(&text, ORIGIN).unwrap_or_else(|e| panic!("{e}\n{text}"));
    let mut written = keys_of(&text);
    written.extend(INPUT_ONLY_KEYS.iter().map(|k| k.to_string()));
    let undocumented: Vec<_> = written.difference(&documented).collect();
    let unknown: Vec<_> = documented.difference(&written).collect();
    assert!(undocumented.is_empty() && unknown.is_empty(), "undocumented: {undocumented:?}; not accepted: {unknown:?}");
}

#[test]
fn every_documented_key_is_accepted_and_its_misspelling_refused() {
    let rows = rows();
    for row in &rows {
        accepted(&rows, row, &row.probe());
        let mut sets = context(&rows, row, &row.probe());
        let typo = format!("{}_x", row.full());
        sets.push(set(&typo, &row.probe()));
        match spec_from_toml_str(&spec_with(&sets), ORIGIN) {
            Err(ConfigError::Parse { message, .. }) => {
                assert!(message.contains(&format!("unknown field `{}_x`", row.key)), "{typo}: {message}")
            }
            other => panic!("{typo}: expected an unknown-key error, got {other:?}"),
        }
    }
}

/// The range an error message states: its first `[a, b]`, `(a, b]`, `[a, b)` or `(a, b)`, or
/// a count's `a or b`, the numbers as written (a message that states no range, or another one,
/// fails the comparison with the page).
fn message_range(valid: &str) -> Option<Valid> {
    if let Some((lo, hi)) = valid.split_once(" or ")
        && let (Ok(lo), Ok(hi)) = (lo.trim().parse::<u32>(), hi.trim().parse::<u32>())
    {
        return Some(Valid::Range { lo: lo.into(), lo_open: false, hi: hi.into(), hi_open: false });
    }
    let start = valid.find(['[', '('])?;
    let len = valid[start..].find([']', ')'])?;
    let code = &valid[start..=start + len];
    let (lo, hi) = code[1..code.len() - 1].split_once(',')?;
    Some(Valid::Range {
        lo: lo.trim().parse().ok()?,
        lo_open: code.starts_with('('),
        hi: hi.trim().parse().ok()?,
        hi_open: code.ends_with(')'),
    })
}

/// Each end of each documented range: a value at it (inside it, for an open end) is accepted,
/// a value just outside is refused naming the key, and the error states the page's range.
#[test]
fn every_range_end_is_where_the_parser_puts_it() {
    let rows = rows();
    let mut ends = 0;
    let mut wrong = Vec::new();
    for row in &rows {
        let Valid::Range { lo, lo_open, hi, hi_open } = row.valid else { continue };
        // (end, open, direction towards the outside)
        for (end, open, out) in [(lo, lo_open, -1.0), (hi, hi_open, 1.0)] {
            let d = if row.is_count() {
                assert!(!open && end.fract() == 0.0, "{}: a count's range has whole, closed ends", row.full());
                1.0
            } else {
                step(end)
            };
            if open {
                accepted(&rows, row, &row.literal(end - out * d));
                refused(&rows, row, &row.literal(end));
            } else {
                accepted(&rows, row, &row.literal(end));
            }
            let outside = row.literal(end + out * d);
            match refused(&rows, row, &outside) {
                ConfigError::Invalid { field, valid, .. } => {
                    assert_eq!(field, row.full(), "{} = {outside}", row.full());
                    if message_range(&valid) != Some(row.valid.clone()) {
                        wrong.push(format!("{} = {outside}: `{valid}`", row.full()));
                    }
                }
                e => panic!("{} = {outside}: expected an invalid-value error, got {e:?}", row.full()),
            }
            ends += 1;
        }
    }
    assert!(wrong.is_empty(), "errors whose range is not the page's:\n{}", wrong.join("\n"));
    assert!(ends > 80, "{ends} range ends");
}

#[test]
fn every_option_is_accepted_and_no_other() {
    let rows = rows();
    for row in &rows {
        let Valid::Options(options) = &row.valid else { continue };
        for o in options {
            accepted(&rows, row, o);
        }
        // A name not listed (for a flag: the word as a string).
        let other = if options[0].starts_with('"') { "\"not-an-option\"" } else { "\"true\"" };
        match refused(&rows, row, other) {
            ConfigError::Parse { message, .. } => assert!(message.contains(&row.full()), "{}: {message}", row.full()),
            e => panic!("{} = {other}: expected a parse error, got {e:?}", row.full()),
        }
    }
}

#[test]
fn every_default_is_what_the_parser_fills_in() {
    let rows = rows();
    let mut defaults = 0;
    for row in &rows {
        let Some(DefaultCell::Value(value)) = &row.default else { continue };
        let given = accepted(&rows, row, value);
        let mut sets = context(&rows, row, value);
        sets.push(unset(&row.full()));
        let text = spec_with(&sets);
        let left_out =
            spec_from_toml_str(&text, ORIGIN).unwrap_or_else(|e| panic!("{} left out: {e}\n{text}", row.full()));
        assert_eq!(left_out, given, "{}: the documented default {value}", row.full());
        defaults += 1;
    }
    assert!(defaults > 25, "{defaults} defaults");
}

#[test]
fn every_required_key_is_required() {
    let rows = rows();
    for row in rows.iter().filter(|r| r.default.is_none()) {
        let mut sets = context(&rows, row, &row.probe());
        sets.push(unset(&row.full()));
        let text = spec_with(&sets);
        // The table must exist for its key to be missing from it.
        let text = if row.table.starts_with("extensions.") && !text.contains(&format!("[{}]", row.table)) {
            format!("{text}[{}]\n", row.table)
        } else {
            text
        };
        match spec_from_toml_str(&text, ORIGIN) {
            Err(ConfigError::Parse { message, .. }) => {
                assert!(message.contains(&format!("missing key `{}`", row.full())), "{}: {message}", row.full())
            }
            other => panic!("{} left out: expected a missing-key error, got {other:?}\n{text}", row.full()),
        }
    }
}

#[test]
fn units_follow_the_key_names() {
    // Longest suffix first.
    let units: [(&str, &str); 17] = [
        ("_kg_m3_k", "kg/(m^3 K)"),
        ("_per_kn_nm", "N m per kN"),
        ("_w_m_k", "W/(m K)"),
        ("_per_gpa", "1/GPa"),
        ("_per_k", "1/K"),
        ("_k", "K"),
        ("_mm2_s", "mm^2/s"),
        ("_kg_m3", "kg/m^3"),
        ("_gpa", "GPa"),
        ("_deg", "deg"),
        ("_rpm", "rpm"),
        ("_um", "um"),
        ("_mm", "mm"),
        ("_nm", "N m"),
        ("_n", "N"),
        ("temperature_c", "degrees C"),
        ("_h", "1"),
    ];
    for row in rows() {
        match units.iter().find(|(suffix, _)| row.key.ends_with(suffix)) {
            Some((_, unit)) => assert_eq!(row.unit, *unit, "{}", row.full()),
            None => assert!(
                ["1", "count", "option", "bool", "mm^2/s"].contains(&row.unit.as_str()),
                "{}: {}",
                row.full(),
                row.unit
            ),
        }
    }
}
