//! The one place output is written: stdout, or a file replaced atomically.

use crate::error::CliError;
use std::io::{self, Write as _};
use std::path::{Path, PathBuf};

/// What a command produced: its text (for stdout or `--out`) and a plot for its own file.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Rendered {
    /// The report, if any.
    pub text: Option<String>,
    /// A plot: its file and its SVG text.
    pub plot: Option<(PathBuf, String)>,
}

impl From<String> for Rendered {
    fn from(text: String) -> Self {
        Self { text: Some(text), plot: None }
    }
}

impl Rendered {
    /// Writes the plot to its file, then the text to `out` (or stdout); each file atomically.
    /// Nothing is written when the plot would overwrite `out`.
    pub fn write(&self, out: Option<&Path>) -> Result<(), CliError> {
        if let (Some((plot, _)), Some(out)) = (&self.plot, out) {
            if plot == out {
                return Err(CliError::Input(format!("--plot and --out name the same file: {}", plot.display())));
            }
        }
        if let Some((path, svg)) = &self.plot {
            to_file(svg, path)?;
        }
        match &self.text {
            Some(text) => emit(text, out),
            None => Ok(()),
        }
    }
}

/// Writes `text` to `out`, or to stdout when `out` is `None`.
///
/// A file is written to a temporary file in the same directory and renamed over `out` only once
/// complete; on any error the temporary file is removed and `out` is left as it was.
pub fn emit(text: &str, out: Option<&Path>) -> Result<(), CliError> {
    match out {
        None => to_stdout(text),
        Some(path) => to_file(text, path),
    }
}

fn to_stdout(text: &str) -> Result<(), CliError> {
    let mut stdout = io::stdout().lock();
    match stdout.write_all(text.as_bytes()).and_then(|()| stdout.flush()) {
        // A closed pipe (`ballscrew sweep | head`) is not an error of ours.
        Err(e) if e.kind() != io::ErrorKind::BrokenPipe => {
            Err(CliError::Output(format!("cannot write to stdout: {e}")))
        }
        _ => Ok(()),
    }
}

fn to_file(text: &str, path: &Path) -> Result<(), CliError> {
    let fail = |what: &str, e: &dyn core::fmt::Display| CliError::Output(format!("{}: {what}: {e}", path.display()));
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    if path.is_dir() {
        return Err(fail("cannot write output", &"is a directory"));
    }
    // The temporary file is deleted when dropped, i.e. on every early return below.
    let mut tmp = tempfile::Builder::new()
        .prefix(".ballscrew-")
        .suffix(".tmp")
        .tempfile_in(dir)
        .map_err(|e| fail("cannot create a temporary file beside it", &e))?;
    tmp.write_all(text.as_bytes()).and_then(|()| tmp.as_file().sync_all()).map_err(|e| fail("cannot write", &e))?;
    tmp.persist(path).map_err(|e| fail("cannot replace", &e.error))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_file_and_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.csv");
        emit("a,b\n", Some(&path)).unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "a,b\n");
        emit("c\n", Some(&path)).unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "c\n");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn missing_directory_is_an_error_without_output() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no/such/dir/out.csv");
        let e = emit("x", Some(&path)).unwrap_err();
        assert!(e.to_string().contains("out.csv"), "{e}");
        assert!(!path.exists());
        let e = emit("x", Some(dir.path())).unwrap_err();
        assert!(e.to_string().contains("directory"), "{e}");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
    }
}
