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
            if same_file(plot, out) {
                return Err(CliError::Input(format!(
                    "--plot and --out name the same file: {} and {}",
                    plot.display(),
                    out.display()
                )));
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

/// Whether `a` and `b` name the same file, however written (`x`, `./x`, `dir/../x`, links to
/// the directory): the canonical directory and the file name are compared.
fn same_file(a: &Path, b: &Path) -> bool {
    let key = |p: &Path| {
        let dir = std::fs::canonicalize(parent_dir(p)).ok()?;
        Some(dir.join(p.file_name()?))
    };
    match (key(a), key(b)) {
        (Some(a), Some(b)) => a == b,
        _ => a == b,
    }
}

/// The directory `path` is in (`.` for a bare file name).
fn parent_dir(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
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
    let dir = parent_dir(path);
    if path.is_dir() {
        return Err(fail("cannot write output", &"is a directory"));
    }
    if !dir.is_dir() {
        return Err(fail("cannot write output", &format!("no directory {}", dir.display())));
    }
    // The temporary file is deleted when dropped, i.e. on every early return below. It is
    // created as an ordinary file would be (0666 less the umask), not owner-only.
    let mut builder = tempfile::Builder::new();
    builder.prefix(".ballscrew-").suffix(".tmp");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    let mut tmp = builder.tempfile_in(dir).map_err(|e| fail("cannot create a temporary file beside it", &e.kind()))?;
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

    #[cfg(unix)]
    #[test]
    fn output_file_has_the_permissions_of_an_ordinary_file() {
        use std::os::unix::fs::PermissionsExt as _;
        let dir = tempfile::tempdir().unwrap();
        let ordinary = dir.path().join("ordinary.txt");
        std::fs::write(&ordinary, "x").unwrap();
        let ours = dir.path().join("out.txt");
        emit("x", Some(&ours)).unwrap();
        let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode(&ours), mode(&ordinary));
    }

    #[test]
    fn plot_and_out_naming_one_file_in_two_ways_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let plain = dir.path().join("same.txt");
        let dotted = dir.path().join(".").join("sub").join("..").join("same.txt");
        std::fs::create_dir(dir.path().join("sub")).unwrap();
        let r = Rendered { text: Some("text".into()), plot: Some((dotted, "<svg/>".into())) };
        let e = r.write(Some(&plain)).unwrap_err();
        assert_eq!(e.exit_code(), 2);
        assert!(e.to_string().starts_with("--plot and --out name the same file"), "{e}");
        assert!(!plain.exists());
        let other = dir.path().join("other.txt");
        r.write(Some(&other)).unwrap();
        assert_eq!(std::fs::read_to_string(&other).unwrap(), "text");
        assert_eq!(std::fs::read_to_string(&plain).unwrap(), "<svg/>");
    }

    #[test]
    fn missing_directory_is_named() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no").join("out.csv");
        let e = emit("x", Some(&path)).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!("{}: cannot write output: no directory {}", path.display(), dir.path().join("no").display())
        );
    }
}
