//! User input: the spec (file or built-in), operating points from flags, the preload range.
//!
//! Every value is checked by the core's own validation; its errors are restated with the flag
//! the user typed and the value as typed.

use crate::error::CliError;
use ballscrew_config::{self as config, BUILTIN_ORIGIN, ConfigError, MAX_SWEEP_POINTS};
use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{InputError, OperatingPoint, ScrewSpec, Shown};
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
        Some((_, flag, Some(v))) => invalid(flag, &Shown(*v), e.valid),
        _ => CliError::Input(e.to_string()),
    }
}

/// The input error of a flag: `invalid FLAG: VALUE (valid: RANGE)`.
fn invalid(flag: &str, value: &dyn core::fmt::Display, valid: &str) -> CliError {
    CliError::Input(format!("invalid {flag}: {value} (valid: {valid})"))
}

/// `value` of the real flag `flag` when `ok`, else [`invalid`].
pub fn checked(flag: &str, value: f64, ok: bool, valid: &str) -> Result<f64, CliError> {
    if ok { Ok(value) } else { Err(invalid(flag, &Shown(value), valid)) }
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
        Err(invalid(flag, &value, &format!("integer in [{lo}, {hi}]")))
    }
}

/// A range `A..B` of finite numbers (with `single`, also one value `A`, read as `A..A`) for
/// which `ok(A, B)` holds; else `invalid FLAG: TEXT (valid: VALID)`.
pub fn range(
    flag: &str,
    text: &str,
    single: bool,
    ok: fn(f64, f64) -> bool,
    valid: &str,
) -> Result<(f64, f64), CliError> {
    let number = |s: &str| s.trim().parse::<f64>().ok().filter(|x| x.is_finite());
    let parsed = match text.split_once("..") {
        Some((a, b)) => number(a).zip(number(b)),
        None if single => number(text).map(|a| (a, a)),
        None => None,
    };
    match parsed {
        Some((a, b)) if ok(a, b) => Ok((a, b)),
        _ => Err(invalid(flag, &text, valid)),
    }
}

/// The preloads of `A..B` (both ends included, `step` apart; the last step may be shorter) or
/// of a single value `A`.
pub fn preload_points(text: &str, step: f64) -> Result<Vec<f64>, CliError> {
    let (lo, hi) = range("--preload-n", text, true, |a, b| a <= b, "A..B with A <= B, or a single value, in N")?;
    if !(step.is_finite() && step > 0.0) {
        return Err(invalid("--preload-step-n", &Shown(step), "finite and > 0 N"));
    }
    if config::steps_to_reach(lo, hi, step) + 1.0 > MAX_SWEEP_POINTS as f64 {
        return Err(CliError::Input(format!(
            "--preload {text} with --step {} gives more than {MAX_SWEEP_POINTS} points: use a larger step",
            Shown(step)
        )));
    }
    Ok(config::range_points(lo, hi, step))
}

/// The points of a sweep flag `flag` = `A..B` (both ends included, `step` apart; the last step
/// may be shorter), `step` given by `step_flag`; `unit` names the flags' unit in messages.
/// The values themselves are checked where they are used (operating point, spec).
pub fn sweep_points(flag: &str, text: &str, step_flag: &str, step: f64, unit: &str) -> Result<Vec<f64>, CliError> {
    let (lo, hi) = range(flag, text, false, |a, b| a <= b, &format!("A..B with A <= B, in {unit}"))?;
    if !(step.is_finite() && step > 0.0) {
        return Err(invalid(step_flag, &Shown(step), &format!("finite and > 0 {unit}")));
    }
    if config::steps_to_reach(lo, hi, step) + 1.0 > MAX_SWEEP_POINTS as f64 {
        return Err(CliError::Input(format!(
            "{flag} {text} with {step_flag} {} gives more than {MAX_SWEEP_POINTS} points: use a larger step",
            Shown(step)
        )));
    }
    Ok(config::range_points(lo, hi, step))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_range_has_26_points() {
        let p = preload_points("500..3000", 100.0).unwrap();
        assert_eq!(p.len(), 26);
        assert_eq!((p[0], p[1], p[25]), (500.0, 600.0, 3000.0));
    }

    #[test]
    fn uneven_range_keeps_both_ends() {
        assert_eq!(preload_points("0..250", 100.0).unwrap(), [0.0, 100.0, 200.0, 250.0]);
        assert_eq!(preload_points("1000", 100.0).unwrap(), [1000.0]);
        assert_eq!(preload_points("1000..1000", 100.0).unwrap(), [1000.0]);
        assert_eq!(preload_points("0.5..0.7", 0.1).unwrap().len(), 3);
    }

    #[test]
    fn bad_ranges_are_input_errors() {
        for (r, step, flag) in [
            ("3000..500", 100.0, "--preload-n"),
            ("abc", 100.0, "--preload-n"),
            ("1..nan", 100.0, "--preload-n"),
            ("500..3000", 0.0, "--preload-step-n"),
            ("500..3000", -5.0, "--preload-step-n"),
            ("500..3000", f64::NAN, "--preload-step-n"),
        ] {
            let e = preload_points(r, step).unwrap_err();
            assert_eq!(e.exit_code(), 2);
            assert!(e.to_string().starts_with(&format!("invalid {flag}: ")), "{e}");
        }
        assert!(preload_points("0..1e7", 1e-3).is_err());
    }

    #[test]
    fn ranges_parse_by_the_callers_rule() {
        let below = |a: f64, b: f64| a < b;
        assert_eq!(range("--x", " -1 .. 2.5", false, below, "V").unwrap(), (-1.0, 2.5));
        assert_eq!(range("--x", "7", true, |a, b| a <= b, "V").unwrap(), (7.0, 7.0));
        for text in ["7", "2..1", "1..1", "1..inf", "a..2", "1..2..3"] {
            let e = range("--x", text, false, below, "A..B with A < B").unwrap_err();
            assert_eq!(e.to_string(), format!("invalid --x: {text} (valid: A..B with A < B)"));
        }
    }

    #[test]
    fn flags_are_named_with_their_value_and_range() {
        let spec = ScrewSpec::dkfzd4012();
        let input =
            PointInput { speed_rpm: Some(1e9), preload_n: None, axial_load_n: None, preload_flag: "--preload-n" };
        let e = operating_point(&spec, &input).unwrap_err();
        assert_eq!(e.to_string(), "invalid --speed-rpm: 1000000000 (valid: finite, |speed| <= 30000 rpm)");
        let input =
            PointInput { speed_rpm: None, preload_n: Some(-1.0), axial_load_n: None, preload_flag: "--preload-n" };
        assert!(operating_point(&spec, &input).unwrap_err().to_string().starts_with("invalid --preload-n: -1 "));
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
