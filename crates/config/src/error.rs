//! Why a spec was rejected ([`ConfigError`]), and the rewording that puts every error on the
//! file's terms: serde's parse errors with the line and column (in characters) of the offending
//! text and the table or key it sits on; the core's range errors, which name SI fields, with the
//! TOML key, the value as written and the range in the key's unit (from the table of keys,
//! [`crate::keys`]).

use crate::file_format::RawSpec;
use crate::keys::KEYS;
use ballscrew_core::error::{Error, InputError, Invalid};
use ballscrew_core::input::geometry::max_balls_per_circle;
use ballscrew_core::input::{Preload, ScrewSpec};
use core::fmt;
use core::ops::Range;

/// Why a TOML spec was rejected.
#[derive(Debug, Clone, PartialEq)]
pub enum ConfigError {
    /// The text is not valid TOML or does not have the spec's shape (unknown or missing key,
    /// wrong type, unknown option name).
    Parse {
        /// Where the text came from (a file name).
        origin: String,
        /// 1-based line of the offending text.
        line: usize,
        /// 1-based column (in characters).
        column: usize,
        /// What is wrong.
        message: String,
    },
    /// A value is out of its valid range.
    Invalid {
        /// The TOML key, e.g. `geometry.pitch_diameter_mm`.
        field: String,
        /// The value, in the key's unit.
        value: f64,
        /// The valid range, in words.
        valid: String,
    },
    /// A key that goes with another (the two viscosities) is missing.
    Missing {
        /// The TOML key, e.g. `lubricant.viscosity_100c_mm2_s`.
        field: String,
        /// What may be given, in words.
        valid: String,
    },
    /// The spec passed validation but the model could not be set up.
    Model(Error),
    /// The file could not be read.
    Io {
        /// The path as given.
        path: String,
        /// The operating system's message.
        message: String,
    },
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Keys, file names and the parser's quotes of the text are the user's: their control
        // characters are escaped (`\u{1b}`) so that a message cannot drive the terminal.
        let text = match self {
            ConfigError::Parse { origin, line, column, message } => format!("{origin}:{line}:{column}: {message}"),
            ConfigError::Invalid { field, value, valid } => Invalid { field, value: *value, valid }.to_string(),
            ConfigError::Missing { field, valid } => format!("missing {field} (valid: {valid})"),
            ConfigError::Model(e) => format!("{e}"),
            ConfigError::Io { path, message } => format!("{path}: {message}"),
        };
        text.chars()
            .try_for_each(|c| if c.is_control() { write!(f, "{}", c.escape_default()) } else { write!(f, "{c}") })
    }
}

impl core::error::Error for ConfigError {}

// ---------------------------------------------------------------------------------------------
// The core's errors -> TOML keys.

/// Restates the core's error on the file's terms: TOML key, the value as written, its range
/// (with the ends that depend on other keys worked out for `spec`).
pub(crate) fn invalid(raw: &RawSpec, spec: &ScrewSpec, e: &InputError) -> ConfigError {
    if e.field == "geometry.balls_per_circle" {
        let most = max_balls_per_circle(&spec.geometry);
        return ConfigError::Invalid {
            field: e.field.to_string(),
            value: raw.geometry.balls_per_circle.0,
            valid: format!(
                "[1, {most}] (as many as fit one turn of the helix with this pitch diameter, lead and ball)"
            ),
        };
    }
    // A grade stands for both viscosities: their errors are the grade's.
    if let (Some(grade), true) = (raw.lubricant.iso_vg, e.field.starts_with("lubricant.viscosity_")) {
        return ConfigError::Invalid {
            field: "lubricant.iso_vg".to_string(),
            value: grade,
            valid: format!("a grade whose oil has {} in {}", &e.field["lubricant.".len()..], e.valid),
        };
    }
    match KEYS.iter().find(|k| k.core == Some(e.field)) {
        Some(k) => ConfigError::Invalid {
            field: k.full(),
            value: k.value.map_or(e.value, |value| value(raw)),
            valid: k.restated_valid().unwrap_or_else(|| e.valid.to_string()),
        },
        None => ConfigError::Invalid { field: e.field.to_string(), value: e.value, valid: e.valid.to_string() },
    }
}

// ---------------------------------------------------------------------------------------------
// Parse errors: byte offset -> line:column, with the key or table the error sits on.

/// 1-based line and column (in characters) of a byte offset.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let offset = floor_char_boundary(text, offset);
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (line, text[line_start..offset].chars().count() + 1)
}

fn floor_char_boundary(text: &str, offset: usize) -> usize {
    let mut i = offset.min(text.len());
    while !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// The line holding a byte offset.
fn line_at(text: &str, offset: usize) -> &str {
    let offset = floor_char_boundary(text, offset);
    let start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let end = text[offset..].find('\n').map_or(text.len(), |i| offset + i);
    &text[start..end]
}

/// The table name of a header line (`[geometry]` -> `geometry`), if the line is one.
pub(crate) fn header_name(line: &str) -> Option<&str> {
    let t = line.trim_start();
    if !t.starts_with('[') {
        return None;
    }
    let inner = t.trim_start_matches('[');
    let end = inner.find(']')?;
    Some(inner[..end].trim())
}

/// The table of the last header before a byte offset (`None`: the root table).
fn table_at(text: &str, offset: usize) -> Option<&str> {
    let offset = floor_char_boundary(text, offset);
    text[..offset].lines().rev().find_map(header_name)
}

/// The key of a `key = value` line.
pub(crate) fn key_of(line: &str) -> Option<&str> {
    let (k, _) = line.split_once('=')?;
    let k = k.trim();
    (!k.is_empty() && !k.starts_with('#')).then_some(k)
}

/// Rewords serde's message with the table and key its span points at: a span on a table header
/// is that table (a missing key, or an unknown table); an empty span is the root table (a
/// missing table); a span on a `key = value` line is that key.
fn reword(text: &str, span: &Range<usize>, message: &str) -> String {
    let missing = message.strip_prefix("missing field `").map(|r| r.trim_end_matches('`'));
    if span.is_empty() {
        return match missing {
            Some(table) => format!("missing table `[{table}]`"),
            None => message.to_string(),
        };
    }
    let line = line_at(text, span.start);
    if let Some(table) = header_name(line) {
        if let Some(key) = missing {
            return format!("missing key `{table}.{key}`");
        }
        if let Some(rest) = message.strip_prefix("unknown field") {
            return format!("unknown table `[{table}]`{}", rest.trim_start_matches(|c| c != ','));
        }
        return format!("[{table}]: {message}");
    }
    let Some(key) = key_of(line) else { return message.to_string() };
    let table = table_at(text, span.start);
    match (table, message.split_once(", expected")) {
        (Some(table), Some((head, tail))) if message.starts_with("unknown field") => {
            format!("{head} in [{table}], expected{tail}")
        }
        (_, _) if message.starts_with("unknown field") => message.to_string(),
        (Some(table), _) => format!("{table}.{key}: {message}"),
        (None, _) => format!("{key}: {message}"),
    }
}

/// Names serde's Rust types in words: a real-valued key expects "a number" (whole-number keys
/// say "a whole number" themselves, [`Count`](crate::file_format::Count)).
fn plain_types(message: &str) -> String {
    message.replace(", expected f64", ", expected a number")
}

/// The error for a preloaded nut whose spec leaves out `operating.preload_n` (or the whole
/// `[operating]` table): a missing key, at the `[operating]` header (or the file's start). Only
/// a nut without preload has a default preload (0 N); any other's is its own.
pub(crate) fn missing_preload(text: &str, origin: &str, raw: &RawSpec) -> Option<ConfigError> {
    if raw.operating.preload_n.is_some() {
        return None;
    }
    let nuts = raw.geometry.nuts.0;
    let arrangement = match raw.geometry.preload {
        Some(p) => p,
        None if nuts == 1.0 => return None,
        None if nuts == 2.0 => Preload::DoubleNut,
        // Not 1 or 2 nuts: the core's range error on `geometry.nuts` says so.
        None => return None,
    };
    if arrangement == Preload::None {
        return None;
    }
    let at = text.lines().position(|l| header_name(l) == Some("operating")).map_or(1, |i| i + 1);
    Some(ConfigError::Parse {
        origin: origin.to_string(),
        line: at,
        column: 1,
        message: format!(
            "missing key `operating.preload_n`: a nut preloaded by geometry.preload = \"{}\" needs its preload \
             in N (the maker's catalog gives it); only geometry.preload = \"none\" defaults to 0 N",
            arrangement.name()
        ),
    })
}

pub(crate) fn parse_error(text: &str, origin: &str, e: &toml::de::Error) -> ConfigError {
    let span = e.span().unwrap_or(0..0);
    let (line, column) = line_column(text, span.start);
    let message = reword(text, &span, &plain_types(e.message()));
    ConfigError::Parse { origin: origin.to_string(), line, column, message }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_column_counts_characters() {
        let text = "a = 1\nb = \"\u{e9}\u{e9}\" x\n";
        let off = text.find(" x").unwrap() + 1;
        assert_eq!(line_column(text, off), (2, 10));
        assert_eq!(line_column(text, 0), (1, 1));
        assert_eq!(line_column(text, text.len() + 5), (3, 1));
    }
}
