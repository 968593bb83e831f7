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
        write!(f, "invalid {}: {} (valid: {})", self.field, Shown(self.value), self.valid)
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

/// A short text on the stack (for [`Short`]); writing beyond its room is an error.
struct Text {
    bytes: [u8; 32],
    len: usize,
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
        write!(f, "{} {} (physical: {})", self.quantity, Shown(self.value), self.valid)
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
    extern crate std;
    use super::*;
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
        assert_eq!(format!("{e}"), "invalid preload_n: 1e300 (valid: finite, [0, 1e7] N)");
    }
}
