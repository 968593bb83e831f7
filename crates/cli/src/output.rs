//! The one place output is written: stdout, or a file replaced atomically.

use crate::error::CliError;
use std::io::{self, Write as _};
use std::path::{Component, Path, PathBuf};

/// A file written beside the report: the flag that named it, its path and its text.
#[derive(Debug, Clone, PartialEq)]
pub struct SideFile {
    /// The flag, as in messages (`--plot`, `--report`, ...).
    pub flag: &'static str,
    /// Where it goes.
    pub path: PathBuf,
    /// Its text.
    pub text: String,
}

/// What a command produced: its text (for stdout or `--out`), the directories its side files
/// need (created if missing) and the side files.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Output {
    /// The report, if any.
    pub text: Option<String>,
    /// Directories to create before the side files are written.
    pub dirs: Vec<PathBuf>,
    /// Files written beside the report.
    pub files: Vec<SideFile>,
}

impl From<String> for Output {
    fn from(text: String) -> Self {
        Self { text: Some(text), ..Self::default() }
    }
}

impl Output {
    /// A plotting command's result: its text (for stdout or `--out`), if any, and a plot for its
    /// own file (`--plot`: the path and the SVG text), if any.
    pub fn with_plot(text: Option<String>, plot: Option<(PathBuf, String)>) -> Self {
        let files = plot.into_iter().map(|(path, text)| SideFile { flag: "--plot", path, text }).collect();
        Self { text, dirs: Vec::new(), files }
    }
}

impl Output {
    /// Writes the side files, then the text to `out` (or stdout); each file atomically.
    /// Nothing is written when two of them, or one of them and `out`, name the same file.
    pub fn write(&self, out: Option<&Path>) -> Result<(), CliError> {
        self.check_distinct(out)?;
        for dir in &self.dirs {
            std::fs::create_dir_all(dir)
                .map_err(|e| CliError::Output(format!("{}: cannot create directory: {e}", dir.display())))?;
        }
        for f in &self.files {
            to_file(&f.text, &f.path)?;
        }
        match &self.text {
            Some(text) => emit(text, out),
            None => Ok(()),
        }
    }

    /// An input error naming both flags and both paths when two files coincide.
    fn check_distinct(&self, out: Option<&Path>) -> Result<(), CliError> {
        let all: Vec<(&str, &Path)> =
            self.files.iter().map(|f| (f.flag, f.path.as_path())).chain(out.map(|p| ("--out", p))).collect();
        for (i, (flag_a, a)) in all.iter().enumerate() {
            if let Some((flag_b, b)) = all[i + 1..].iter().find(|(_, b)| same_file(a, b)) {
                return Err(CliError::Input(format!(
                    "{flag_a} and {flag_b} name the same file: {} and {}",
                    a.display(),
                    b.display()
                )));
            }
        }
        Ok(())
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
/// the directory): the canonical directory and the file name are compared, or, for a directory
/// not made yet, the absolute paths with `.` and `..` resolved as written.
fn same_file(a: &Path, b: &Path) -> bool {
    file_key(a) == file_key(b)
}

/// The path [`same_file`] compares.
fn file_key(p: &Path) -> PathBuf {
    let canonical = || Some(std::fs::canonicalize(parent_dir(p)).ok()?.join(p.file_name()?));
    canonical().unwrap_or_else(|| {
        let mut key = PathBuf::new();
        for c in std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf()).components() {
            match c {
                Component::ParentDir => {
                    key.pop();
                }
                Component::CurDir => {}
                c => key.push(c),
            }
        }
        key
    })
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
        let r = Output::with_plot(Some("text".into()), Some((dotted, "<svg/>".into())));
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
    fn side_files_naming_one_file_are_refused_before_anything_is_written() {
        let dir = tempfile::tempdir().unwrap();
        let new_dir = dir.path().join("plots");
        let side = |flag, path: PathBuf| SideFile { flag, path, text: flag.to_string() };
        let out = Output {
            text: Some("text".into()),
            dirs: vec![new_dir.clone()],
            files: vec![
                side("--plots", new_dir.join("a.svg")),
                side("--report", new_dir.join("..").join("plots").join(".").join("a.svg")),
            ],
        };
        let e = out.write(None).unwrap_err();
        assert_eq!(e.exit_code(), 2);
        assert_eq!(
            e.to_string(),
            format!(
                "--plots and --report name the same file: {} and {}",
                out.files[0].path.display(),
                out.files[1].path.display()
            )
        );
        assert!(!new_dir.exists(), "no directory made");
        // Distinct files: the directory is made and every file written.
        let report = dir.path().join("r.json");
        let out = Output { files: vec![out.files[0].clone(), side("--report", report.clone())], ..out };
        let e = out.write(Some(&report)).unwrap_err();
        assert!(e.to_string().starts_with("--report and --out name the same file"), "{e}");
        let text_out = dir.path().join("out.txt");
        out.write(Some(&text_out)).unwrap();
        assert_eq!(std::fs::read_to_string(new_dir.join("a.svg")).unwrap(), "--plots");
        assert_eq!(std::fs::read_to_string(&report).unwrap(), "--report");
        assert_eq!(std::fs::read_to_string(&text_out).unwrap(), "text");
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
