//! Progress on stderr for the commands that can run for seconds (`diagnose`, `sweep`, `map`,
//! `predict`): a bar redrawn in place when stderr is a terminal, nothing at all otherwise (a
//! pipe, a file, a test, CI), so that what those read is only the warnings and errors. The
//! counts come from the library crates (their progress callbacks); this module only draws them.

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal as _;

/// A progress bar on stderr, or nothing when stderr is not a terminal. Cleared when dropped, so
/// that a warning or an error after it starts on a clean line.
#[derive(Debug)]
pub struct Bar(Option<ProgressBar>);

impl Bar {
    /// A bar of `total` steps labelled `what` (the command), drawn when stderr is a terminal.
    pub fn new(what: &str, total: usize) -> Self {
        Self::shown_if(std::io::stderr().is_terminal(), what, total)
    }

    /// A bar drawn only when `terminal`.
    fn shown_if(terminal: bool, what: &str, total: usize) -> Self {
        if !terminal {
            return Self(None);
        }
        let bar = ProgressBar::new(total as u64);
        let style = ProgressStyle::with_template("{prefix} [{bar:30}] {pos}/{len} {msg} ({elapsed}, {eta} left)")
            .map(|s| s.progress_chars("=> "));
        if let Ok(style) = style {
            bar.set_style(style);
        }
        bar.set_prefix(what.to_string());
        Self(Some(bar))
    }

    /// `done` of `total` steps.
    pub fn set(&self, done: usize, total: usize) {
        if let Some(b) = &self.0 {
            b.set_length(total as u64);
            b.set_position(done as u64);
        }
    }

    /// One more step done.
    pub fn step(&self) {
        if let Some(b) = &self.0 {
            b.inc(1);
        }
    }

    /// Runs `f` with the bar taken off the terminal (a line written to stdout meanwhile does not
    /// tear it).
    pub fn suspend<R>(&self, f: impl FnOnce() -> R) -> R {
        match &self.0 {
            Some(b) => b.suspend(f),
            None => f(),
        }
    }
}

/// A batch of the library crates ([`ballscrew_batch`]) steps the bar after each point; it never
/// stops one.
impl ballscrew_batch::Stop for Bar {
    fn stop(&self) -> bool {
        false
    }

    fn done(&self) {
        self.step();
    }
}

impl Drop for Bar {
    fn drop(&mut self) {
        if let Some(b) = &self.0 {
            b.finish_and_clear();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nothing_is_drawn_off_a_terminal() {
        let bar = Bar::shown_if(false, "sweep", 10);
        assert!(bar.0.is_none());
        bar.set(3, 10);
        bar.step();
        assert_eq!(bar.suspend(|| 7), 7);
        assert!(Bar::shown_if(true, "sweep", 10).0.is_some());
    }
}
