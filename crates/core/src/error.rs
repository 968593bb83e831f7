//! Errors of the core: every invalid input names the field, the value given and the valid range.

use core::fmt;

/// An input outside its valid range: which field, what value, what is allowed.
///
/// `field` is the name a user sees in a spec file or on the command line (with its unit),
/// e.g. `geometry.conformity_screw` or `preload_n`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InputError {
    /// The field's name, as written in a spec file or an argument list.
    pub field: &'static str,
    /// The value that was given (in the unit of the field's name).
    pub value: f64,
    /// The valid range, in words (e.g. `"(0.5, 1.0]"` or `"finite and > 0"`).
    pub valid: &'static str,
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        Invalid { field: self.field, value: self.value, valid: self.valid }.fmt(f)
    }
}

/// An invalid value in words: `invalid {field}: {value} (valid: {valid})`, the value and the
/// valid range's bounds in short form ([`Measured`], [`ValidRange`]). Every range error of the
/// crates is written by this one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Invalid<'a> {
    /// The field's name (a spec key, an argument or a flag), its unit at its end.
    pub field: &'a str,
    /// The value given, in the unit of the field's name.
    pub value: f64,
    /// The valid range, in words.
    pub valid: &'a str,
}

impl fmt::Display for Invalid<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let value = Measured { value: self.value, field: self.field, valid: self.valid };
        write!(f, "invalid {}: {value} (valid: {})", self.field, ValidRange(self.valid))
    }
}

/// A value in a message on a valid range, short: 3 significant digits with the SI prefix of
/// the unit its field's name ends in (`material.youngs_modulus_pa` 6910094107.248013: `6.91
/// GPa`; `_m` 2.1e-8: `21 nm`; `_mm` 0.5: `500 µm`), 4 significant digits and no unit for
/// dimensionless values and units without prefixes (rpm, degrees C, mm2/s: the name says the
/// unit), whole numbers below 1e9 as they are. Never rounded onto or across a number of the
/// valid range: a value just outside a bound gets the digits that show it outside (`1.0000001`,
/// not `1`, against `(0, 1]`). `NaN`, `inf`, `-inf` as such.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measured<'a> {
    /// The value, in the unit of the field's name.
    pub value: f64,
    /// The field's name (`_m`, `_mm`, `_um`, `_pa`, `_gpa`, `_n`, `_nm` for N m, `_m_s`, `_s` at
    /// its end give the unit; `-` counts as `_`, for flags).
    pub field: &'a str,
    /// The valid range in words: the value shown does not round onto or across its numbers.
    pub valid: &'a str,
}

impl fmt::Display for Measured<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.value;
        if !v.is_finite() {
            return write!(f, "{v}");
        }
        let unit = unit_of_field(self.field);
        let (symbol, first) = match unit {
            Some((s, _)) => (Some(s), 3),
            None => (None, 4),
        };
        // Whole dimensionless numbers (counts, rpm, degrees) as they are.
        if symbol.is_none() && v == libm::trunc(v) && libm::fabs(v) < 1e9 {
            return write!(f, "{}", v + 0.0);
        }
        // The fewest digits from `first` on that do not show the value on a bound's side.
        let mut digits = first;
        while digits < 17 && rounds_past_a_bound(v, rounded(v, digits), self.valid) {
            digits += 1;
        }
        match unit {
            Some((s, power)) => write_prefixed(f, v, power, digits, s),
            None => write_plain(f, v, digits),
        }
    }
}

/// The valid range as messages show it: each interval `[a, b] U` of a unit that takes a prefix
/// (m, mm, Pa, GPa, N, N m, ...) with both ends in short form (`[0.003, 0.3] m`: `[3 mm, 300
/// mm]`; `[1e9, 1e12] Pa`: `[1 GPa, 1 TPa]`), exact; the rest of the words as written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ValidRange<'a>(pub &'a str);

impl fmt::Display for ValidRange<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut rest = self.0;
        while let Some(at) = rest.find(['[', '(']) {
            f.write_str(&rest[..at])?;
            rest = &rest[at..];
            match interval(rest) {
                Some(i) => {
                    f.write_str(&rest[..1])?;
                    write_prefixed(f, i.lo, i.power, exact_digits(i.lo), i.symbol)?;
                    f.write_str(", ")?;
                    write_prefixed(f, i.hi, i.power, exact_digits(i.hi), i.symbol)?;
                    f.write_str(i.close)?;
                    rest = &rest[i.len..];
                }
                None => {
                    f.write_str(&rest[..1])?;
                    rest = &rest[1..];
                }
            }
        }
        f.write_str(rest)
    }
}

/// Units of field names: the suffix, the unit a prefix goes on and the factor to it. Suffixes
/// of units that take no prefix come first (`_mm2_s` is no time); a unit after `_per`
/// (`_per_m`, `_per_gpa`) is no unit of the value.
const FIELD_UNITS: [(&str, Option<(&str, i32)>); 13] = [
    ("_mm2_s", None),
    ("_m2_s", None),
    ("_rad_s", None),
    ("_m_s", Some(("m/s", 0))),
    ("_nm", Some(("N m", 0))),
    ("_gpa", Some(("Pa", 9))),
    ("_mpa", Some(("Pa", 6))),
    ("_pa", Some(("Pa", 0))),
    ("_mm", Some(("m", -3))),
    ("_um", Some(("m", -6))),
    ("_m", Some(("m", 0))),
    ("_n", Some(("N", 0))),
    ("_s", Some(("s", 0))),
];

/// Units as valid ranges write them after an interval: the unit a prefix goes on and the factor.
const TEXT_UNITS: [(&str, &str, i32); 14] = [
    ("N m", "N m", 0),
    ("m/s", "m/s", 0),
    ("mm", "m", -3),
    ("um", "m", -6),
    ("µm", "m", -6),
    ("nm", "m", -9),
    ("m", "m", 0),
    ("GPa", "Pa", 9),
    ("MPa", "Pa", 6),
    ("kPa", "Pa", 3),
    ("Pa", "Pa", 0),
    ("kN", "N", 3),
    ("N", "N", 0),
    ("s", "s", 0),
];

/// The unit of a field's name (see [`FIELD_UNITS`]); `None`: dimensionless or no prefix.
fn unit_of_field(field: &str) -> Option<(&'static str, i32)> {
    let name = field.as_bytes();
    // `-` stands for `_` (flags: `--preload-n`).
    let ends_with = |end: &[u8]| {
        name.len() > end.len()
            && name[name.len() - end.len()..].iter().zip(end).all(|(&a, &b)| a == b || (a == b'-' && b == b'_'))
    };
    let (suffix, unit) = FIELD_UNITS.iter().find(|(suffix, _)| ends_with(suffix.as_bytes()))?;
    let before = &name[..name.len() - suffix.len()];
    let per = before.len() >= 4
        && before[before.len() - 4..].iter().zip(b"_per").all(|(&a, &b)| a == b || (a == b'-' && b == b'_'));
    if per { None } else { *unit }
}

/// An interval of a valid range with a unit that takes a prefix (see [`interval`]).
struct Interval<'a> {
    /// Its ends, in the unit written.
    lo: f64,
    hi: f64,
    /// The closing bracket.
    close: &'a str,
    /// The unit a prefix goes on, and the power of ten from the unit written to it.
    symbol: &'static str,
    power: i32,
    /// Its length in bytes, the unit included.
    len: usize,
}

/// The interval at the start of `text`: `[a, b] U` or with `(`/`)`, U a unit of [`TEXT_UNITS`]
/// ending at a word's end.
fn interval(text: &str) -> Option<Interval<'_>> {
    let close = text.find([']', ')'])?;
    let (lo, hi) = text[1..close].split_once(", ")?;
    let (lo, hi) = (lo.parse::<f64>().ok()?, hi.parse::<f64>().ok()?);
    if !(lo.is_finite() && hi.is_finite()) {
        return None;
    }
    let after = text[close + 1..].strip_prefix(' ')?;
    let (written, symbol, power) = TEXT_UNITS.iter().find(|(s, _, _)| {
        // The whole unit: it ends the text, a phrase or a clause (not `N m per kN`, `mm^2/s`).
        after.strip_prefix(s).is_some_and(|r| {
            r.is_empty() || r.starts_with([',', ')', ';']) || r.starts_with(" and ") || r.starts_with(" (")
        })
    })?;
    Some(Interval { lo, hi, close: &text[close..close + 1], symbol, power: *power, len: close + 2 + written.len() })
}

/// Whether `shown`, the value rounded, is on or across the other side of a number of `valid`
/// from `value` (each number also taken at a power of 1000 apart: the range may be written in
/// another prefix of the unit).
fn rounds_past_a_bound(value: f64, shown: f64, valid: &str) -> bool {
    if shown == value {
        return false;
    }
    numbers(valid).any(|n| {
        (-4..=4).any(|k| {
            let b = n * libm::pow(1e3, k as f64);
            (value > b && shown <= b) || (value < b && shown >= b)
        })
    })
}

/// The numbers of a text (`[0.5, 50] mm and below pitch diameter / 2`: 0.5, 50, 2).
fn numbers(text: &str) -> impl Iterator<Item = f64> + '_ {
    text.split(|c: char| !(c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '-' | '+')))
        .filter_map(|w| w.parse::<f64>().ok())
}

/// `x` rounded to `digits` significant digits (decimal rounding, as printed).
fn rounded(x: f64, digits: usize) -> f64 {
    let mut text = Text { bytes: [0; 32], len: 0 };
    match fmt::write(&mut text, format_args!("{:.*e}", digits.saturating_sub(1), x)) {
        Ok(()) => text.as_str().parse().unwrap_or(x),
        Err(_) => x,
    }
}

/// The fewest significant digits that give `x` exactly (at most 17).
fn exact_digits(x: f64) -> usize {
    (1..17).find(|&d| rounded(x, d) == x).unwrap_or(17)
}

/// `x` times 10^`power` in the base unit `symbol` (`x` in mm: `power` -3, `symbol` m; the
/// power added to the exponent of the text, so no product overflows or rounds) with `digits`
/// significant digits and the SI prefix that puts 1 to 999 before it (femto to tera; the
/// exponent form beyond); 0 without a prefix.
fn write_prefixed(f: &mut fmt::Formatter<'_>, x: f64, power: i32, digits: usize, symbol: &str) -> fmt::Result {
    const PREFIXES: [&str; 10] = ["f", "p", "n", "µ", "m", "", "k", "M", "G", "T"];
    if x == 0.0 || !x.is_finite() {
        return write!(f, "{} {symbol}", x + 0.0);
    }
    let mut text = Text { bytes: [0; 32], len: 0 };
    fmt::write(&mut text, format_args!("{:.*e}", digits.saturating_sub(1), x))?;
    let (mantissa, exponent) = text.as_str().split_once('e').ok_or(fmt::Error)?;
    let exponent = exponent.parse::<i32>().map_err(|_| fmt::Error)? + power;
    let k = exponent.div_euclid(3);
    match PREFIXES.get((k + 5) as usize).filter(|_| k >= -5) {
        Some(prefix) => {
            write_digits(f, mantissa, exponent - 3 * k)?;
            write!(f, " {prefix}{symbol}")
        }
        // Beyond tera and below femto: the exponent form in the base unit.
        None => {
            write_digits(f, mantissa, 0)?;
            write!(f, "e{exponent} {symbol}")
        }
    }
}

/// `x` with `digits` significant digits: fixed point from 1e-3 to 1e6, else `1.235e7`.
fn write_plain(f: &mut fmt::Formatter<'_>, x: f64, digits: usize) -> fmt::Result {
    if x == 0.0 {
        return f.write_str("0");
    }
    let mut text = Text { bytes: [0; 32], len: 0 };
    fmt::write(&mut text, format_args!("{:.*e}", digits.saturating_sub(1), x))?;
    let (mantissa, exponent) = text.as_str().split_once('e').ok_or(fmt::Error)?;
    let exponent: i32 = exponent.parse().map_err(|_| fmt::Error)?;
    if (-3..6).contains(&exponent) {
        write_digits(f, mantissa, exponent)
    } else {
        write_digits(f, mantissa, 0)?;
        write!(f, "e{exponent}")
    }
}

/// The mantissa `-d.ddd` of an exponent form times 10^`shift`, in fixed point without trailing
/// zeros (`6.91`, 0: `6.91`; `2.10`, 1: `21`; `5.00`, -1: `0.5`).
fn write_digits(f: &mut fmt::Formatter<'_>, mantissa: &str, shift: i32) -> fmt::Result {
    let (sign, mantissa) = match mantissa.strip_prefix('-') {
        Some(m) => ("-", m),
        None => ("", mantissa),
    };
    let mut d = [b'0'; 24];
    let mut n = 0;
    for b in mantissa.bytes().filter(u8::is_ascii_digit) {
        if let Some(slot) = d.get_mut(n) {
            *slot = b;
            n += 1;
        }
    }
    while n > 1 && d[n - 1] == b'0' {
        n -= 1;
    }
    let digits = core::str::from_utf8(&d[..n.max(1)]).map_err(|_| fmt::Error)?;
    // Digits before the point.
    let point = 1 + shift;
    f.write_str(sign)?;
    if point <= 0 {
        f.write_str("0.")?;
        for _ in 0..-point {
            f.write_str("0")?;
        }
        f.write_str(digits)
    } else if point as usize >= digits.len() {
        f.write_str(digits)?;
        for _ in digits.len()..point as usize {
            f.write_str("0")?;
        }
        Ok(())
    } else {
        let (whole, fraction) = digits.split_at(point as usize);
        write!(f, "{whole}.{fraction}")
    }
}

/// A number as an error message shows it: as typed for ordinary magnitudes (`2000`, `0.52`,
/// `1000000000`), in exponent form for very large or very small ones (`1e300`, not 301 digits;
/// `1e-300`, not 300 zeros).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shown(pub f64);

impl fmt::Display for Shown {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let m = libm::fabs(self.0);
        if m.is_finite() && m != 0.0 && !(1e-6..1e15).contains(&m) {
            write!(f, "{:e}", self.0)
        } else {
            write!(f, "{}", self.0)
        }
    }
}

/// A number as reports show it (the command line's tables): 6 significant digits, whole
/// numbers below 1e9 as integers, others in fixed point between 1e-3 and 1e6 and in exponent
/// form outside; `n/a` when not finite; -0 as 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Significant(pub f64);

impl fmt::Display for Significant {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // -0 shows as 0: the sign of a zero says nothing a reader can use.
        let x = self.0 + 0.0;
        let a = libm::fabs(x);
        if x - libm::trunc(x) == 0.0 && a < 1e9 {
            write!(f, "{x:.0}")
        } else if !x.is_finite() {
            f.write_str("n/a")
        } else if (1e-3..1e6).contains(&a) {
            let decimals = (5 - libm::floor(libm::log10(a)) as i32).max(0) as usize;
            write!(f, "{x:.decimals$}")
        } else {
            write!(f, "{x:.4e}")
        }
    }
}

/// A number for running text: [`Significant`] without trailing zeros (`100`, `0.5`, `1.25e7`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Short(pub f64);

impl fmt::Display for Short {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // No allocation: the text of `Significant` (at most about 14 bytes) on the stack.
        let mut text = Text { bytes: [0; 32], len: 0 };
        fmt::write(&mut text, format_args!("{}", Significant(self.0)))?;
        let s = core::str::from_utf8(&text.bytes[..text.len]).map_err(|_| fmt::Error)?;
        if s.contains('.') && !s.contains('e') {
            f.write_str(s.trim_end_matches('0').trim_end_matches('.'))
        } else {
            f.write_str(s)
        }
    }
}

/// A short text on the stack (for [`Short`] and [`Measured`]); writing beyond its room is an
/// error.
struct Text {
    bytes: [u8; 32],
    len: usize,
}

impl Text {
    /// The text written so far.
    fn as_str(&self) -> &str {
        core::str::from_utf8(&self.bytes[..self.len]).unwrap_or("")
    }
}

impl fmt::Write for Text {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        let end = self.len + s.len();
        self.bytes.get_mut(self.len..end).ok_or(fmt::Error)?.copy_from_slice(s.as_bytes());
        self.len = end;
        Ok(())
    }
}

/// A solved ball state outside the bounds of a physical one (see
/// `ball::setup::check_state`): which quantity, its value, the physical range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unphysical {
    /// The quantity, in words (e.g. `orbit ratio`).
    pub quantity: &'static str,
    /// Its value in the state.
    pub value: f64,
    /// The range a physical state keeps it in, in words.
    pub valid: &'static str,
}

impl fmt::Display for Unphysical {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let value = Measured { value: self.value, field: self.quantity, valid: self.valid };
        write!(f, "{} {value} (physical: {})", self.quantity, ValidRange(self.valid))
    }
}

/// What can go wrong when the model is evaluated.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Error {
    /// A spec field or an operating-point input is out of its valid range.
    Input(InputError),
    /// The ball's quasi-static balance did not converge.
    NoConvergence {
        /// Which ball: nut index (0-based).
        nut: usize,
        /// Which ball: circle index within the nut (0-based, 0 = first circle).
        circle: usize,
        /// Newton iterations spent.
        iterations: u32,
        /// Scaled residual (max norm) where the solve stopped (infinite when every state it
        /// reached was rejected as not physical).
        residual: f64,
        /// Why the last state reached was rejected, when it balanced but was not physical.
        unphysical: Option<Unphysical>,
    },
    /// The ball train of a circuit of several loaded turns has no steady state found at this
    /// point: no state in which its balls all orbit at one rate with one gap in the train
    /// ([`crate::screw::circuit`]).
    NoSteadyTrain {
        /// Which circuit: nut index (0-based).
        nut: usize,
        /// Its first and last circle (0-based, as in [`Error::NoConvergence`]).
        circles: (usize, usize),
        /// Newton iterations spent.
        iterations: u32,
        /// Scaled residual (max norm) of the last step tried (small where the steps balance but
        /// the gap does not settle).
        residual: f64,
    },
    /// A model option that this evaluation does not support.
    Unsupported {
        /// The spec field, as in a spec file (e.g. `model.contact_theory`).
        field: &'static str,
        /// Its value, as in a spec file.
        value: &'static str,
        /// What is supported.
        valid: &'static str,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Input(e) => e.fmt(f),
            Error::NoConvergence { nut, circle, iterations, residual, unphysical: None } => write!(
                f,
                "ball balance did not converge (nut {}, circle {}): residual {:.3e} after {} iterations",
                nut + 1,
                circle + 1,
                residual,
                iterations
            ),
            Error::NoConvergence { nut, circle, iterations, unphysical: Some(u), .. } => write!(
                f,
                "ball balance did not converge (nut {}, circle {}): no physical state after {} iterations, \
                 the last one reached has {}",
                nut + 1,
                circle + 1,
                iterations,
                u
            ),
            Error::NoSteadyTrain { nut, circles, iterations, .. } => write!(
                f,
                "the ball train of the circuit of nut {}, circles {}-{}, has no steady state found here: no state in \
                 which its balls all orbit at one rate with one gap in the train ({} iterations; docs/model-notes.md, \
                 \"The ball train\", says where such circuits solve)",
                nut + 1,
                circles.0 + 1,
                circles.1 + 1,
                iterations
            ),
            Error::Unsupported { field, value, valid } => write!(f, "invalid {field}: {value} (valid: {valid})"),
        }
    }
}

impl From<InputError> for Error {
    fn from(e: InputError) -> Self {
        Error::Input(e)
    }
}

impl core::error::Error for InputError {}
impl core::error::Error for Error {}

/// Checks that `value` is finite and inside `(lo, hi)` with the given openness.
///
/// `valid` is the text shown to the user.
pub(crate) fn check_range(
    field: &'static str,
    value: f64,
    lo: f64,
    lo_open: bool,
    hi: f64,
    hi_open: bool,
    valid: &'static str,
) -> Result<f64, InputError> {
    let err = InputError { field, value, valid };
    if !value.is_finite() {
        return Err(err);
    }
    let above = if lo_open { value > lo } else { value >= lo };
    let below = if hi_open { value < hi } else { value <= hi };
    if above && below { Ok(value) } else { Err(err) }
}

#[cfg(test)]
mod tests {
    extern crate alloc;
    extern crate std;
    use super::*;
    use alloc::string::String;
    use std::format;

    #[test]
    fn numbers_in_reports_have_six_significant_digits() {
        let sig = |v: f64| format!("{}", Significant(v));
        let short = |v: f64| format!("{}", Short(v));
        assert_eq!((sig(100.0), short(100.0)), ("100".into(), "100".into()));
        assert_eq!((sig(-0.0), sig(f64::NAN), sig(f64::INFINITY)), ("0".into(), "n/a".into(), "n/a".into()));
        assert_eq!((sig(0.5), short(0.5)), ("0.500000".into(), "0.5".into()));
        assert_eq!((sig(123.456_789), short(2.5e-3)), ("123.457".into(), "0.0025".into()));
        assert_eq!((sig(1.25e-7), short(1.25e-7)), ("1.2500e-7".into(), "1.2500e-7".into()));
        assert_eq!((sig(2.5e9), short(-1234567.5)), ("2.5000e9".into(), "-1.2346e6".into()));
        assert_eq!(short(-f64::MAX), "-1.7977e308");
    }

    #[test]
    fn numbers_in_messages_stay_short() {
        let shown = |v: f64| format!("{}", Shown(v));
        assert_eq!(shown(2000.0), "2000");
        assert_eq!(shown(-0.52), "-0.52");
        assert_eq!(shown(1e9), "1000000000");
        assert_eq!(shown(0.0), "0");
        assert_eq!(shown(1e300), "1e300");
        assert_eq!(shown(-1e-300), "-1e-300");
        assert_eq!(shown(5e-324), "5e-324");
        assert_eq!(shown(f64::NAN), "NaN");
        assert_eq!(shown(f64::NEG_INFINITY), "-inf");
        let e = InputError { field: "preload_n", value: 1e300, valid: "finite, [0, 1e7] N" };
        assert_eq!(format!("{e}"), "invalid preload_n: 1e300 N (valid: finite, [0 N, 10 MN])");
    }

    fn measured(field: &str, value: f64, valid: &str) -> String {
        format!("{}", Measured { value, field, valid })
    }

    #[test]
    fn values_in_range_errors_have_three_digits_and_their_units_prefix() {
        assert_eq!(measured("material.youngs_modulus_pa", 6910094107.248013, ""), "6.91 GPa");
        assert_eq!(measured("position_m", 2.1e-8, ""), "21 nm");
        assert_eq!(measured("geometry.ball_diameter_mm", 0.5, ""), "500 µm");
        assert_eq!(measured("geometry.ball_diameter_m", 0.0005, ""), "500 µm");
        assert_eq!(measured("geometry.lead_mm", 12345.0, ""), "12.3 m");
        assert_eq!(measured("preload_n", 2000.0, ""), "2 kN");
        assert_eq!(measured("--axial-load-n", -1234.5, ""), "-1.23 kN");
        assert_eq!(measured("extensions.seal_drag.torque_nm", 0.000123456, ""), "123 µN m");
        assert_eq!(measured("sliding_speed_m_s", 0.25, ""), "250 mm/s");
        assert_eq!(measured("dt_s", 1e-3, ""), "1 ms");
        assert_eq!(measured("preload_n", 0.0, ""), "0 N");
        // Beyond the prefixes (femto to tera): the exponent form.
        assert_eq!(measured("preload_n", 1e300, ""), "1e300 N");
        assert_eq!(measured("position_m", -2.5e-20, ""), "-2.5e-20 m");
        // A value in a prefixed unit beyond f64 in the base unit, without overflow.
        assert_eq!(measured("youngs_modulus_gpa", 1e300, "[1, 1000] GPa"), "1e309 Pa");
        assert_eq!(measured("youngs_modulus_gpa", -1e300, ""), "-1e309 Pa");
        assert_eq!(measured("lead_mm", f64::MAX, ""), "1.8e305 m");
        assert_eq!(
            (measured("preload_n", f64::NAN, ""), measured("x_m", f64::NEG_INFINITY, "")),
            ("NaN".into(), "-inf".into())
        );
    }

    #[test]
    fn dimensionless_values_and_units_without_prefixes_have_four_digits() {
        assert_eq!(measured("geometry.conformity_screw", 0.523456, ""), "0.5235");
        assert_eq!(measured("speed_rpm", 1e9, ""), "1e9");
        assert_eq!(measured("speed_rpm", 31000.0, ""), "31000");
        assert_eq!(measured("speed_rpm", 31234.5678, ""), "31230");
        assert_eq!(measured("lubricant.viscosity_40c_mm2_s", 0.012345, ""), "0.01235");
        assert_eq!(measured("hertz.curvature_sum_per_m", 1.5e-7, ""), "1.5e-7");
        assert_eq!(measured("lubricant.pressure_viscosity_per_gpa", 500.0, ""), "500");
        assert_eq!(measured("--phi-per-mm", -2000.6, ""), "-2001");
        assert_eq!(measured("friction.seal_torque_per_nut_nm", 0.02, ""), "20 mN m");
        assert_eq!(measured("geometry.balls_per_circle", 150.0, ""), "150");
        assert_eq!(measured("x", 5e-324, ""), "4.941e-324");
    }

    #[test]
    fn a_value_outside_is_never_shown_on_a_bound() {
        // Three digits would show 1, 0.501, 0.6, 10 MN, 1 GPa: inside the range.
        assert_eq!(measured("friction.creep_reduction", 1.0000001, "(0, 1]"), "1.0000001");
        assert_eq!(measured("geometry.conformity_screw", 0.50096, "[0.501, 0.6]"), "0.50096");
        assert_eq!(measured("geometry.conformity_screw", 0.60004, "[0.501, 0.6]"), "0.60004");
        assert_eq!(measured("preload_n", 10_000_000.5, "finite, [0, 1e7] N"), "10.0000005 MN");
        assert_eq!(measured("material.youngs_modulus_pa", 999_999_000.0, "[1e9, 1e12] Pa"), "999.999 MPa");
        // A range in another prefix of the unit.
        assert_eq!(measured("material.youngs_modulus_pa", 1.0000001e9, "[1, 1000] GPa"), "1.0000001 GPa");
        // Nor across a bound of more digits than shown.
        assert_eq!(measured("x", 0.501241, "[0.3, 0.50124]"), "0.501241");
        assert_eq!(measured("x", 0.50124, "[0.50125, 0.6]"), "0.5012");
        // Far from the bounds, short.
        assert_eq!(measured("friction.creep_reduction", 1.5, "(0, 1]"), "1.5");
        assert_eq!(measured("geometry.conformity_screw", 0.61234, "[0.501, 0.6]"), "0.6123");
        // On a bound exactly (an open end): the bound.
        assert_eq!(measured("friction.creep_reduction", 0.0, "(0, 1]"), "0");
    }

    #[test]
    fn ranges_show_their_ends_with_the_units_prefix() {
        let range = |text: &str| format!("{}", ValidRange(text));
        assert_eq!(range("[0.003, 0.3] m"), "[3 mm, 300 mm]");
        assert_eq!(range("[1e9, 1e12] Pa"), "[1 GPa, 1 TPa]");
        assert_eq!(range("finite, [0, 1e7] N"), "finite, [0 N, 10 MN]");
        assert_eq!(range("[0.5, 50] mm and below pitch diameter / 2"), "[500 µm, 50 mm] and below pitch diameter / 2");
        assert_eq!(range("[0, 5e-6] m"), "[0 m, 5 µm]");
        assert_eq!(range("[0, 1e4] N m"), "[0 N m, 10 kN m]");
        assert_eq!(range("[0.0005, 0.2] m"), "[500 µm, 200 mm]");
        assert_eq!(range("[1, 1e7] N (the ball's)"), "[1 N, 10 MN] (the ball's)");
        // No unit, or one without prefixes: as written.
        for text in [
            "(0, 1]",
            "[-30, 200] degrees C",
            "[0, 1000] N m per kN",
            "[0, 1] N m per N",
            "[2, 500] mm^2/s and below",
            "finite, |speed| <= 30000 rpm",
            "[1, 1e6] (or absent)",
            "a (b) [c",
            "(0, inf) m",
        ] {
            assert_eq!(range(text), text);
        }
        let e = Invalid { field: "material.youngs_modulus_pa", value: 6910094107.248013, valid: "[1e9, 1e12] Pa" };
        assert_eq!(format!("{e}"), "invalid material.youngs_modulus_pa: 6.91 GPa (valid: [1 GPa, 1 TPa])");
    }
}
