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
