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
        write!(f, "invalid {}: {} (valid: {})", self.field, self.value, self.valid)
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
        /// Scaled residual (max norm) where the solve stopped.
        residual: f64,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Input(e) => e.fmt(f),
            Error::NoConvergence { nut, circle, iterations, residual } => write!(
                f,
                "ball balance did not converge (nut {}, circle {}): residual {:.3e} after {} iterations",
                nut + 1,
                circle + 1,
                residual,
                iterations
            ),
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
