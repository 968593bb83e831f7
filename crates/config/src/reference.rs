//! The spec reference, `docs/spec-reference.md`, rendered from the table of keys
//! ([`crate::keys::KEYS`]): the page's prose (what a spec file is, the format of the tables, the
//! notes of each TOML table) and one markdown table per TOML table with the columns
//! `key | unit | default | valid | meaning | source`. The crate's test `tests/spec_reference.rs`
//! requires the page to be this text and checks its rows against the parser.

use crate::keys::{KEYS, Key};

/// The page before the tables: what a spec file is, how the page is made and checked, the
/// format of the tables.
const INTRO: &str = r#"# Spec file reference

A spec file is TOML with the unit of every value in its key's name. This page lists every key of
every table: its unit, whether it is required (and its default when it is not), the values it
accepts and what it means. `configs/dkfzd4012.toml` is a complete example (and the built-in spec).

Unknown tables and keys are refused with their line and column; a value out of range is refused
with its key, the value and the valid range. The page is generated from the table of keys in
`crates/config` (`crates/config/src/keys.rs`, whose ranges are the core's range constants) and
checked against the parser by `crates/config/tests/spec_reference.rs`: the keys listed here are
exactly the keys the parser accepts, every range end and option is tried, and every default is
compared with what the parser fills in.

## Format of the tables

One table per TOML table, with the columns `key | unit | default | valid | meaning | source`:

- **unit**: the unit the key's name carries; `1` for a plain number, `count` for a whole number,
  `option` for a string from a list, `bool` for `true` or `false`.
- **default**: `required`; or the value taken when the key is left out, as a TOML value in
  backticks (with a note where it depends on other keys); or, without backticks, what leaving
  the key out means where no single value stands for it.
- **valid**: in backticks, `[a, b]` (closed ends), `(a, b]`, `[a, b)`, `(a, b)` (open ends) for
  numbers, `"a" | "b"` for the options, `true | false` for a flag; then, in words, any condition
  that ties the key to other keys. A range written with other keys at their built-in values says
  so.
- **source**: where the default or the range comes from, where one is cited (a standard, a
  paper, a catalog); empty where none.

A whole `[operating]`, `[model]`, `[lubricant]` or `[extensions.<name>]` table is optional
(`[operating]` only for a nut without preload, see below). An extension table,
when given, turns its term on; its keys marked `required` must then be given.

"#;

/// Each TOML table of the page in order: its name, the prose before its table of keys and the
/// prose after it (empty where none).
const TABLES: [(&str, &str, &str); 17] = [
    ("geometry", "", ""),
    ("material", "", ""),
    ("friction", "", ""),
    (
        "operating",
        "",
        r#"The preload has a default only where no preload is the arrangement: a preload is the screw's
own, set by its maker as a fraction of the screw's dynamic load rating, which the spec does not
hold, and a made-up value would silently give another screw's torque. A preloaded nut
(`"double-nut"`, `"offset-lead"`, `"oversize-ball"`, or two nuts without `preload`) that leaves
out `preload_n`, or the whole table, is refused as a missing key. The command line's
`--preload-n`, `--speed-rpm` and `--axial-load-n` override the table's values."#,
    ),
    ("model", "", ""),
    (
        "circulation",
        r#"How the balls circulate: what the ball train is built from (the guide's model notes, "The ball
train"). Every key is optional. The loaded balls of a circuit push the return's balls against
its resistance; the loads between neighbouring balls follow, and their sliding (at the
lubricant's boundary friction: no film forms at zero entrainment speed) and the return's
resistance are shares of the drag torque. Bypassed where `friction.ball_ball_load_n` is given."#,
        "",
    ),
    (
        "lubricant",
        r#"Read and checked under either model (`model.lubrication = "dry"` leaves the oil out of the
torque, but a value out of range is refused there too). Every key is optional; the defaults are
ISO VG 68 mineral oil at 40 degrees C. Give either `iso_vg` or both viscosities, not both."#,
        "",
    ),
    (
        "uncertainty",
        r#"How far each input nobody measures on a given screw may lie from the value the spec states: a
half-width, relative (a share of the value) or absolute (in the value's unit), with every value in
`nominal +- half-width` equally likely. 0 pins the input. The model does not read this table: a
band of predictions (`--band`, `ballscrew sensitivity`, Python's `Screw.band`) samples it (the
guide's chapter on uncertainty). Every key is optional; the defaults are the sources' below."#,
        "",
    ),
    ("extensions.seal_drag", r#"Seals and wipers: a constant torque against the motion."#, ""),
    (
        "extensions.viscous_drag",
        r#"Lubricant drag growing with speed: `c (|omega| / omega_ref)^n` against the motion."#,
        "",
    ),
    (
        "extensions.thermal_viscosity",
        r#"Viscous drag whose level follows the oil's viscosity with temperature,
`exp(-b (theta - theta_ref))`."#,
        "",
    ),
    ("extensions.raceway_waviness", r#"A torque periodic in the nut position: `A sin(2 pi h x / L + phi)`."#, ""),
    (
        "extensions.preload_loss",
        r#"Wear: the effective preload falls linearly with running time, `Fp max(0, 1 - r t / 1000 h)`."#,
        "",
    ),
    ("extensions.direction_asymmetry", r#"A different friction level in the reverse direction."#, ""),
    ("extensions.preload_law", r#"The friction part of the torque multiplied by `(Fp / Fp_ref)^e`."#, ""),
    (
        "extensions.axial_load_loss",
        r#"Torque growing with the external axial load beyond the model's: `k |F_a|` against the motion."#,
        "",
    ),
    (
        "extensions.level_factor",
        r#"The friction part of the torque times a constant in both directions: the level a diagnosis finds
when the data's drag is the model's times a factor that no physical value of the model's parameters
carries (`ballscrew diagnose --out-spec` writes it then)."#,
        "",
    ),
];

/// The whole page, `docs/spec-reference.md`, from the table of keys.
pub fn spec_reference() -> String {
    let sections: Vec<String> = TABLES
        .iter()
        .map(|(table, before, after)| {
            let mut s = format!("## `[{table}]`\n\n");
            if !before.is_empty() {
                s += &format!("{before}\n\n");
            }
            s += "| key | unit | default | valid | meaning | source |\n|---|---|---|---|---|---|\n";
            for key in KEYS.iter().filter(|k| k.table == *table) {
                s += &row(key);
            }
            if !after.is_empty() {
                s += &format!("\n{after}\n");
            }
            s
        })
        .collect();
    format!("{INTRO}{}", sections.join("\n"))
}

/// A key's line of its table; a `|` inside a cell is written `\|`.
fn row(k: &Key) -> String {
    let code = format!("`{}`", k.valid.code());
    let valid = if k.conditions.is_empty() { code } else { format!("{code} {}", k.conditions) };
    let key = format!("`{}`", k.key);
    let cells: [&str; 6] = [&key, k.unit, k.default, &valid, k.meaning, k.source];
    let cells: Vec<String> = cells.iter().map(|c| c.replace('|', "\\|")).collect();
    format!("| {} |\n", cells.join(" | "))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every key of the table is on the page, under a table of [`TABLES`].
    #[test]
    fn every_key_is_under_a_table_of_the_page() {
        for k in KEYS.iter() {
            assert!(TABLES.iter().any(|(t, _, _)| *t == k.table), "{}: no table {}", k.full(), k.table);
        }
        let page = spec_reference();
        assert_eq!(page.lines().filter(|l| l.starts_with("| `")).count(), KEYS.len());
    }
}
