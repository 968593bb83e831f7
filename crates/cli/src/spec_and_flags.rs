//! The spec and the flags: the spec from its file or the built-in one, the operating point from
//! the point flags over the spec's, and the checks of a real or integer flag's value. (The range
//! flags, `A..B`, are read and checked by `ballscrew_batch::sweep`.)
//!
//! Every value is checked by the core's own validation; its errors are restated with the flag
//! the user typed and the value as typed.

use crate::error::CliError;
use ballscrew_config::{self as config, BUILTIN_ORIGIN, ConfigError};
use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{InputError, Invalid, OperatingPoint, ScrewSpec};
use std::path::Path;

/// A spec and where it came from.
#[derive(Debug, Clone)]
pub struct LoadedSpec {
    /// The spec (validated).
    pub spec: ScrewSpec,
    /// The file it came from, or [`BUILTIN_ORIGIN`].
    pub origin: String,
}

/// Loads `path`, or the built-in DKFZD4012 spec.
pub fn load_spec(path: Option<&Path>) -> Result<LoadedSpec, CliError> {
    let (result, origin) = match path {
        Some(p) => (config::spec_from_toml_file(p), p.display().to_string()),
        None => (config::builtin_spec(), BUILTIN_ORIGIN.to_string()),
    };
    match result {
        Ok(spec) => Ok(LoadedSpec { spec, origin }),
        // Parse and I/O errors carry the file name already.
        Err(e @ (ConfigError::Parse { .. } | ConfigError::Io { .. })) => Err(CliError::Input(e.to_string())),
        Err(e) => Err(CliError::Input(format!("{origin}: {e}"))),
    }
}

/// The TOML text of `path`, or of the built-in DKFZD4012 spec, and where it came from (not yet
/// validated: `ballscrew fmu` packages the text itself).
pub fn load_spec_text(path: Option<&Path>) -> Result<(String, String), CliError> {
    match path {
        Some(p) => std::fs::read_to_string(p)
            .map(|text| (text, p.display().to_string()))
            .map_err(|e| CliError::Input(format!("{}: cannot read spec file: {e}", p.display()))),
        None => Ok((config::DKFZD4012_TOML.to_string(), BUILTIN_ORIGIN.to_string())),
    }
}

/// Operating-point flags as typed (`None`: the spec's value).
#[derive(Debug, Clone, Copy)]
pub struct PointInput {
    /// `--speed-rpm`.
    pub speed_rpm: Option<f64>,
    /// The preload flag's value.
    pub preload_n: Option<f64>,
    /// `--axial-load-n`.
    pub axial_load_n: Option<f64>,
    /// The preload flag's name (`--preload-n` or `--preload`).
    pub preload_flag: &'static str,
}

/// The operating point of `input` over the spec's defaults, validated.
pub fn operating_point(spec: &ScrewSpec, input: &PointInput) -> Result<OperatingPoint, CliError> {
    let d = spec.operating;
    let op = OperatingPoint {
        speed_rad_s: input.speed_rpm.map_or(d.speed_rad_s, rpm_to_rad_s),
        preload_n: input.preload_n.unwrap_or(d.preload_n),
        axial_load_n: input.axial_load_n.unwrap_or(d.axial_load_n),
    };
    op.validate().map_err(|e| flag_error(&e, input))?;
    Ok(op)
}

/// The core's error on an operating-point field, restated with the flag and the typed value.
fn flag_error(e: &InputError, input: &PointInput) -> CliError {
    let flags = [
        ("speed_rad_s", "--speed-rpm", input.speed_rpm),
        ("preload_n", input.preload_flag, input.preload_n),
        ("axial_load_n", "--axial-load-n", input.axial_load_n),
    ];
    match flags.iter().find(|(field, _, _)| *field == e.field) {
        Some((_, flag, Some(v))) => invalid(flag, *v, e.valid),
        _ => CliError::Input(e.to_string()),
    }
}

/// The input error of a flag: `invalid FLAG: VALUE (valid: RANGE)` ([`Invalid`]: the value and
/// the range short, with their unit's prefix).
fn invalid(flag: &str, value: f64, valid: &str) -> CliError {
    CliError::Input(Invalid { field: flag, value, valid }.to_string())
}

/// `value` of the real flag `flag` when `ok`, else [`invalid`].
pub fn checked(flag: &str, value: f64, ok: bool, valid: &str) -> Result<f64, CliError> {
    if ok { Ok(value) } else { Err(invalid(flag, value, valid)) }
}

/// A real flag that must be finite and in `[lo, hi]`.
pub fn in_range(flag: &str, value: f64, lo: f64, hi: f64, valid: &str) -> Result<f64, CliError> {
    checked(flag, value, (lo..=hi).contains(&value), valid)
}

/// An integer flag in `[lo, hi]`, as an index type.
pub fn count(flag: &str, value: i64, lo: i64, hi: i64) -> Result<usize, CliError> {
    if (lo..=hi).contains(&value) {
        Ok(value as usize)
    } else {
        // A count as typed (no unit, every digit).
        Err(CliError::Input(format!("invalid {flag}: {value} (valid: integer in [{lo}, {hi}])")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flags_are_named_with_their_value_and_range() {
        let spec = ScrewSpec::dkfzd4012();
        let input =
            PointInput { speed_rpm: Some(1e9), preload_n: None, axial_load_n: None, preload_flag: "--preload-n" };
        let e = operating_point(&spec, &input).unwrap_err();
        assert_eq!(e.to_string(), "invalid --speed-rpm: 1e9 (valid: finite, |speed| <= 30000 rpm)");
        let input =
            PointInput { speed_rpm: None, preload_n: Some(-1.0), axial_load_n: None, preload_flag: "--preload-n" };
        assert!(operating_point(&spec, &input).unwrap_err().to_string().starts_with("invalid --preload-n: -1 N "));
        let input =
            PointInput { speed_rpm: None, preload_n: None, axial_load_n: Some(f64::NAN), preload_flag: "--preload-n" };
        assert!(operating_point(&spec, &input).unwrap_err().to_string().starts_with("invalid --axial-load-n: NaN "));
    }

    #[test]
    fn builtin_spec_loads() {
        let s = load_spec(None).unwrap();
        assert_eq!(s.spec, ScrewSpec::dkfzd4012());
        assert_eq!(s.origin, BUILTIN_ORIGIN);
    }
}
