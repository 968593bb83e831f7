//! Errors of the command line and their exit codes.

use ballscrew_batch::sweep::SweepError;
use ballscrew_core::Error;
use core::fmt;

/// What went wrong, and so which exit code.
#[derive(Debug, Clone, PartialEq)]
pub enum CliError {
    /// Bad input: a flag's value, a spec file (exit code 2).
    Input(String),
    /// The model failed on valid input, e.g. a solve did not converge (exit code 1).
    Eval(String),
    /// The output could not be written (exit code 1).
    Output(String),
}

impl CliError {
    /// 2 for input errors (as clap's usage errors), 1 otherwise.
    pub fn exit_code(&self) -> u8 {
        match self {
            CliError::Input(_) => 2,
            CliError::Eval(_) | CliError::Output(_) => 1,
        }
    }

    /// An evaluation error of the core, with where it happened.
    pub fn eval(context: &str, e: &Error) -> Self {
        match e {
            Error::Input(_) | Error::Unsupported { .. } => CliError::Input(format!("{context}: {e}")),
            _ => CliError::Eval(format!("{context}: {e}")),
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CliError::Input(m) | CliError::Eval(m) | CliError::Output(m) => f.write_str(m),
        }
    }
}

impl core::error::Error for CliError {}

/// A range flag refused (`ballscrew_batch::sweep`): an input error, its message as it is.
impl From<SweepError> for CliError {
    fn from(e: SweepError) -> Self {
        CliError::Input(e.to_string())
    }
}

/// `text` with every control character escaped as Rust writes it (`\n`, `\u{1b}`), so that a
/// message quoting a file name, a spec key or a CSV header cannot move the cursor, recolour or
/// clear the terminal. Escaping twice changes nothing more.
pub fn printable(text: &str) -> String {
    text.chars().map(|c| if c.is_control() { c.escape_default().to_string() } else { c.to_string() }).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_characters_are_escaped_once() {
        let raw = "key \u{1b}[31mred\u{7}\ttab\nline \u{9b}c é";
        let once = printable(raw);
        assert_eq!(once, "key \\u{1b}[31mred\\u{7}\\ttab\\nline \\u{9b}c é");
        assert_eq!(printable(&once), once);
    }
}
