//! The one place output is written: standard output, a stream written directly (a device, a
//! FIFO, an open file descriptor such as `/dev/stdout`), or a file replaced atomically; the
//! files of one run all or none.
//!
//! What a path names decides how it is written (symbolic links followed):
//! - a regular file, or nothing yet: a temporary file beside it (`.ballscrew-<pid>-<n>.tmp`)
//!   renamed over it once complete; a link to it stays a link;
//! - a character or block device or a FIFO: opened and written, never replaced;
//! - an open file descriptor (`/dev/stdout`, `/dev/fd/N`, `/proc/self/fd/N`): written to that
//!   descriptor (appending);
//! - a directory or a socket: refused; `-` for `--out`: standard output.
//!
//! Before a command computes anything, [`check`] checks everything its flags name (distinct,
//! each directory there or makeable, each writable: a probe file made and removed there).
//! [`Output::write`] then checks again and writes in steps: makes the missing directories,
//! writes every file's temporary (synced), writes the streams, and renames every temporary over
//! its file under a lock the signal handler ([`abandon_and_exit`]) also takes. A failure before
//! the renames removes every temporary and every directory made; a failure in them puts back
//! the files already replaced. A stream cannot be taken back: it is written just before the
//! renames, so a failing stream leaves no file of the run.

use crate::error::CliError;
use core::sync::atomic::{AtomicU32, Ordering};
use std::fs::{self, File, OpenOptions};
use std::io::{self, Write as _};
use std::path::{Component, Path, PathBuf};
use std::sync::{Mutex, MutexGuard, PoisonError};

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

/// A directory the side files need, made if missing (`--plots DIR`).
#[derive(Debug, Clone, PartialEq)]
pub struct SideDir {
    /// The flag that named it.
    pub flag: &'static str,
    /// The directory.
    pub path: PathBuf,
}

/// What a command produced: its text (for stdout or `--out`), the directories its side files
/// need (made if missing) and the side files.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Output {
    /// The report, if any.
    pub text: Option<String>,
    /// A binary report (`ballscrew fmu`: a zip archive), written where `text` would be and in
    /// its place.
    pub bytes: Option<Vec<u8>>,
    /// Directories to make before the side files are written.
    pub dirs: Vec<SideDir>,
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
        Self { text, dirs: Vec::new(), files, bytes: None }
    }

    /// A binary report (for `--out` or stdout), nothing beside it.
    pub fn binary(bytes: Vec<u8>) -> Self {
        Self { bytes: Some(bytes), ..Self::default() }
    }
}

/// The files and directories a command's flags name, known before it runs (the figures inside
/// `--plots DIR` are named only once computed).
#[derive(Debug, Clone, Default)]
pub struct Named<'a> {
    /// `(flag, path)` of each side file.
    pub files: Vec<(&'static str, &'a Path)>,
    /// `(flag, path)` of each directory of side files.
    pub dirs: Vec<(&'static str, &'a Path)>,
}

/// `--out -`: standard output.
pub const STDOUT: &str = "-";

/// Checks everything the flags name before anything is computed: the files distinct (an input
/// error), and each path writable (an output error naming the flag and the path): not a
/// directory nor a socket, its directory there (or one of `named.dirs`), each directory
/// there or makeable, and a file can be made in it (a probe file made and removed).
pub fn check(out: Option<&Path>, named: &Named<'_>) -> Result<(), CliError> {
    let files: Vec<(&str, &Path)> = named.files.iter().copied().chain(out.map(|p| ("--out", p))).collect();
    check_distinct(&files)?;
    let new_dirs = check_dirs(&named.dirs, true)?;
    for (flag, path) in files {
        // A file in a directory still to be made: that directory's ancestor was probed.
        if let Sink::File(p) = resolve(flag, path, &new_dirs)?
            && let Some(dir) = p.parent().filter(|d| d.is_dir())
        {
            probe(flag, path, dir)?;
        }
    }
    Ok(())
}

/// Checks the path of a figure (`--plot`): the figures are SVG, so its name ends in `.svg` (any
/// case), unless it names a stream that exists (a device, a FIFO, an open descriptor such as
/// `/dev/stdout`), which has no name to mislead (a directory is left to [`check`]). Anything
/// else is an input error naming the flag, the value and what is valid, before any work.
pub fn check_svg(flag: &str, path: &Path) -> Result<(), CliError> {
    if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("svg")) {
        return Ok(());
    }
    // A stream, or a directory ([`check`] refuses it as such).
    if fs::metadata(path).is_ok_and(|m| !m.is_file()) {
        return Ok(());
    }
    Err(CliError::Input(format!(
        "invalid {flag}: {} (the figure is SVG: valid is a file name ending in .svg, or a device or FIFO such as \
         /dev/stdout)",
        path.display()
    )))
}

impl Output {
    /// Writes the side files and the text to `out` (or stdout): all or none (see the module).
    /// Nothing is written when two of them, or one of them and `out`, name the same file (an
    /// input error), or when any path is not writable (an output error).
    pub fn write(&self, out: Option<&Path>) -> Result<(), CliError> {
        let named: Vec<(&str, &Path)> =
            self.files.iter().map(|f| (f.flag, f.path.as_path())).chain(out.map(|p| ("--out", p))).collect();
        check_distinct(&named)?;
        let dirs: Vec<(&str, &Path)> = self.dirs.iter().map(|d| (d.flag, d.path.as_path())).collect();
        let new_dirs = check_dirs(&dirs, false)?;
        let mut jobs: Vec<(&str, &Path, Sink, &[u8])> = Vec::new();
        for f in &self.files {
            jobs.push((f.flag, &f.path, resolve(f.flag, &f.path, &new_dirs)?, f.text.as_bytes()));
        }
        if let Some(text) = self.bytes.as_deref().or(self.text.as_deref().map(str::as_bytes)) {
            match out {
                Some(path) => jobs.push(("--out", path, resolve("--out", path, &new_dirs)?, text)),
                None => jobs.push(("--out", Path::new(STDOUT), Sink::Stdout, text)),
            }
        }
        let mut run = Transaction::default();
        for (flag, path) in dirs {
            run.make_dir(flag, path)?;
        }
        for (flag, shown, sink, text) in &jobs {
            if let Sink::File(path) = sink {
                run.stage(flag, shown, path, text)?;
            }
        }
        for (flag, shown, sink, text) in &jobs {
            write_stream(flag, shown, sink, text)?;
        }
        run.commit()
    }
}

/// Where one output goes.
#[derive(Debug, Clone, PartialEq)]
enum Sink {
    /// Standard output (no `--out`, `--out -`, or this process's descriptor 1).
    Stdout,
    /// Standard error (this process's descriptor 2).
    Stderr,
    /// A regular file or none yet (links followed): replaced atomically.
    File(PathBuf),
    /// A device, a FIFO or another open descriptor: opened and written directly.
    Stream {
        /// The path to open.
        path: PathBuf,
        /// Append (an open descriptor: do not overwrite what it holds).
        append: bool,
    },
}

/// The output error `FLAG PATH: WHAT`.
fn fail(flag: &str, path: &Path, what: impl core::fmt::Display) -> CliError {
    CliError::Output(format!("{flag} {}: {what}", path.display()))
}

/// Most symbolic links followed for one path.
const MAX_LINKS: usize = 40;

/// What `path` (named by `flag`) is, links followed; errors name the flag and the path. A file
/// whose directory is missing is accepted when the directory lies in one of `new_dirs`
/// (absolute, normalized), made by this run.
fn resolve(flag: &str, path: &Path, new_dirs: &[PathBuf]) -> Result<Sink, CliError> {
    if flag == "--out" && path == Path::new(STDOUT) {
        return Ok(Sink::Stdout);
    }
    let err = |what: &dyn core::fmt::Display| fail(flag, path, what);
    if path.as_os_str().is_empty() {
        return Err(err(&"not a file name"));
    }
    let mut p = std::path::absolute(path).map_err(|e| err(&e))?;
    for hop in 0..MAX_LINKS {
        let Some(name) = p.file_name().map(ToOwned::to_owned) else {
            return Err(err(&"is a directory (give a file name)"));
        };
        let parent = p.parent().unwrap_or(Path::new("/"));
        // The directory as the user wrote it, until a link is followed.
        let shown = if hop == 0 { parent_dir(path) } else { parent };
        let dir = match fs::canonicalize(parent) {
            Ok(d) if d.is_dir() => d,
            Ok(_) => return Err(err(&format!("cannot write output: {} is not a directory", shown.display()))),
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                let lexical = normalize(&p);
                if new_dirs.iter().any(|d| lexical.starts_with(d)) {
                    return Ok(Sink::File(lexical));
                }
                return Err(err(&format!("cannot write output: no directory {}", shown.display())));
            }
            Err(e) => return Err(err(&format!("cannot write output: no directory {}: {e}", shown.display()))),
        };
        if let Some(sink) = descriptor(&dir, &name) {
            return Ok(sink);
        }
        let full = dir.join(&name);
        let meta = match fs::symlink_metadata(&full) {
            Ok(m) => m,
            Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(Sink::File(full)),
            Err(e) => return Err(err(&format!("cannot write output: {e}"))),
        };
        let kind = meta.file_type();
        if kind.is_symlink() {
            p = dir.join(fs::read_link(&full).map_err(|e| err(&format!("cannot follow the link: {e}")))?);
        } else if kind.is_file() {
            return Ok(Sink::File(full));
        } else if kind.is_dir() {
            return Err(err(&"is a directory (give a file name)"));
        } else if is_socket(&kind) {
            return Err(err(&"is a socket, which cannot be opened for writing"));
        } else {
            return Ok(Sink::Stream { path: full, append: false });
        }
    }
    Err(err(&"too many levels of symbolic links"))
}

#[cfg(unix)]
fn is_socket(kind: &fs::FileType) -> bool {
    use std::os::unix::fs::FileTypeExt as _;
    kind.is_socket()
}

#[cfg(not(unix))]
fn is_socket(_: &fs::FileType) -> bool {
    false
}

/// An open file descriptor: `name` in a `/proc/<pid>/fd` directory (what `/dev/stdout`,
/// `/dev/fd/N` and `/proc/self/fd/N` lead to on Linux). Its entries are links to what the
/// descriptor holds (a pipe, a terminal, a file), so they are written, not followed.
fn descriptor(dir: &Path, name: &std::ffi::OsStr) -> Option<Sink> {
    if !(dir.starts_with("/proc") && dir.file_name().is_some_and(|n| n == "fd")) {
        return None;
    }
    let own = dir == Path::new("/proc").join(std::process::id().to_string()).join("fd");
    match name.to_str() {
        Some("1") if own => Some(Sink::Stdout),
        Some("2") if own => Some(Sink::Stderr),
        _ => Some(Sink::Stream { path: dir.join(name), append: true }),
    }
}

/// Checks the directories of side files (each an existing directory, or makeable: its nearest
/// existing ancestor is a directory), with a probe file when `probe`; returns them absolute
/// and normalized.
fn check_dirs(dirs: &[(&str, &Path)], probe_them: bool) -> Result<Vec<PathBuf>, CliError> {
    let mut out = Vec::new();
    for &(flag, dir) in dirs {
        let existing = nearest_existing(dir);
        match fs::metadata(&existing) {
            Ok(m) if m.is_dir() => {}
            Ok(_) if existing == dir => return Err(fail(flag, dir, "not a directory")),
            Ok(_) => {
                return Err(fail(
                    flag,
                    dir,
                    format!("cannot make the directory: {} is not a directory", existing.display()),
                ));
            }
            Err(e) => return Err(fail(flag, dir, format!("cannot make the directory: {e}"))),
        }
        if probe_them {
            probe(flag, dir, &existing)?;
        }
        out.push(normalize(&std::path::absolute(dir).map_err(|e| fail(flag, dir, e))?));
    }
    Ok(out)
}

/// `dir` if it exists, else its nearest existing ancestor (`.` for a relative path with none).
fn nearest_existing(dir: &Path) -> PathBuf {
    let mut d = dir;
    loop {
        if fs::symlink_metadata(d).is_ok() {
            return d.to_path_buf();
        }
        match d.parent() {
            Some(p) if !p.as_os_str().is_empty() => d = p,
            Some(_) => return PathBuf::from("."),
            None => return d.to_path_buf(),
        }
    }
}

/// Whether a file can be made in `dir`: makes a temporary file there and removes it.
fn probe(flag: &str, path: &Path, dir: &Path) -> Result<(), CliError> {
    let (tmp, file) = new_temp(dir).map_err(|e| fail(flag, path, format!("cannot write in {}: {e}", dir.display())))?;
    drop(file);
    remove_temp(&tmp);
    Ok(())
}

/// An input error naming both flags and both paths when two files coincide.
fn check_distinct(all: &[(&str, &Path)]) -> Result<(), CliError> {
    let all: Vec<&(&str, &Path)> =
        all.iter().filter(|(flag, p)| !(*flag == "--out" && *p == Path::new(STDOUT))).collect();
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

/// Whether `a` and `b` name the same file, however written (`x`, `./x`, `dir/../x`, links): the
/// canonical paths of existing files, else the canonical directory and the file name, or, for
/// a directory not made yet, the absolute paths with `.` and `..` resolved as written.
fn same_file(a: &Path, b: &Path) -> bool {
    file_key(a) == file_key(b)
}

/// The path [`same_file`] compares.
fn file_key(p: &Path) -> PathBuf {
    let in_dir = || Some(fs::canonicalize(parent_dir(p)).ok()?.join(p.file_name()?));
    fs::canonicalize(p)
        .ok()
        .or_else(in_dir)
        .unwrap_or_else(|| normalize(&std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf())))
}

/// `p` with `.` and `..` resolved as written.
fn normalize(p: &Path) -> PathBuf {
    let mut key = PathBuf::new();
    for c in p.components() {
        match c {
            Component::ParentDir => {
                key.pop();
            }
            Component::CurDir => {}
            c => key.push(c),
        }
    }
    key
}

/// The directory `path` is in (`.` for a bare file name).
fn parent_dir(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

/// Writes `text` to stdout at once, as a command computes its rows (`sweep --format csv` to
/// stdout with no file beside it): a reader that stopped reading is no error, as in
/// [`Output::write`].
pub fn stream_stdout(text: &str) -> Result<(), CliError> {
    write_stream("--out", Path::new(STDOUT), &Sink::Stdout, text.as_bytes())
}

/// Writes a stream output (stdout, stderr, a device, a FIFO, a descriptor); files are staged.
fn write_stream(flag: &str, shown: &Path, sink: &Sink, text: &[u8]) -> Result<(), CliError> {
    let result = match sink {
        Sink::File(_) => return Ok(()),
        Sink::Stdout => {
            let mut s = io::stdout().lock();
            s.write_all(text).and_then(|()| s.flush())
        }
        Sink::Stderr => io::stderr().lock().write_all(text),
        Sink::Stream { path, append } => OpenOptions::new()
            .write(true)
            .append(*append)
            .open(path)
            .and_then(|mut f| f.write_all(text).and_then(|()| f.flush())),
    };
    match result {
        // A reader that stopped reading (`ballscrew sweep | head`) is not an error of ours.
        Err(e) if e.kind() != io::ErrorKind::BrokenPipe => Err(if *sink == Sink::Stdout {
            CliError::Output(format!("cannot write to stdout: {e}"))
        } else {
            fail(flag, shown, format!("cannot write: {e}"))
        }),
        _ => Ok(()),
    }
}

// ---------------------------------------------------------------------------------------------
// Temporary files, the directories made, and their removal on a signal.

/// First part of the name of every temporary file: `.ballscrew-<pid>-<n>.tmp`.
pub const TEMP_PREFIX: &str = ".ballscrew-";
/// Last part of the name of every temporary file.
pub const TEMP_SUFFIX: &str = ".tmp";

/// What this process has made and not yet handed over: temporary files and the directories made
/// for output. The lock is held while a temporary is made and while the temporaries are renamed,
/// so the signal handler sees either none of a run's final files or all of them.
struct Pending {
    files: Vec<PathBuf>,
    dirs: Vec<PathBuf>,
}

static PENDING: Mutex<Pending> = Mutex::new(Pending { files: Vec::new(), dirs: Vec::new() });
static SEQUENCE: AtomicU32 = AtomicU32::new(0);

fn pending() -> MutexGuard<'static, Pending> {
    PENDING.lock().unwrap_or_else(PoisonError::into_inner)
}

/// On SIGINT, SIGTERM or SIGHUP: removes every temporary file and every directory made for
/// output that this process has not handed over, tells so on stderr and exits with `code`. The
/// lock is kept to the end, so no rename happens after the removal.
pub fn abandon_and_exit(code: i32) -> ! {
    let mut p = pending();
    for f in p.files.drain(..) {
        let _ = fs::remove_file(f);
    }
    for d in p.dirs.drain(..).rev() {
        let _ = fs::remove_dir(d);
    }
    let _ = writeln!(io::stderr(), "error: interrupted; no output of this run left behind");
    std::process::exit(code)
}

/// A new empty file `.ballscrew-<pid>-<n>.tmp` in `dir`, registered for removal on a signal;
/// made with the permissions of an ordinary new file (0666 less the umask).
fn new_temp(dir: &Path) -> io::Result<(PathBuf, File)> {
    let mut p = pending();
    let mut tries = 0;
    loop {
        let n = SEQUENCE.fetch_add(1, Ordering::Relaxed);
        let path = dir.join(format!("{TEMP_PREFIX}{}-{n}{TEMP_SUFFIX}", std::process::id()));
        match OpenOptions::new().write(true).create_new(true).open(&path) {
            Ok(f) => {
                p.files.push(path.clone());
                return Ok((path, f));
            }
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists && tries < 1000 => tries += 1,
            Err(e) => return Err(e),
        }
    }
}

/// Removes a temporary file and its registration.
fn remove_temp(path: &Path) {
    let mut p = pending();
    let _ = fs::remove_file(path);
    p.files.retain(|f| f != path);
}

/// What a rename replaced.
enum Prior {
    /// No file was there.
    Nothing,
    /// A file, kept under this name (a hard link) until the run is complete.
    Kept(PathBuf),
    /// A file that could not be kept (no hard links here): left replaced on a failure.
    Lost,
}

/// The files of one run: staged temporaries and the directories made; undone when dropped
/// uncommitted.
#[derive(Default)]
struct Transaction {
    /// (temporary, final path, flag, path as named).
    staged: Vec<(PathBuf, PathBuf, String, PathBuf)>,
    /// Directories made, outermost first.
    dirs: Vec<PathBuf>,
    committed: bool,
}

impl Transaction {
    /// Makes `dir` and its missing ancestors, remembering each one made.
    fn make_dir(&mut self, flag: &str, dir: &Path) -> Result<(), CliError> {
        let mut missing = Vec::new();
        let mut d = dir;
        while fs::symlink_metadata(d).is_err() {
            missing.push(d.to_path_buf());
            match d.parent() {
                Some(p) if !p.as_os_str().is_empty() => d = p,
                _ => break,
            }
        }
        for m in missing.into_iter().rev() {
            let mut p = pending();
            match fs::create_dir(&m) {
                Ok(()) => {
                    p.dirs.push(m.clone());
                    self.dirs.push(m);
                }
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {}
                Err(e) => return Err(fail(flag, dir, format!("cannot make directory {}: {e}", m.display()))),
            }
        }
        Ok(())
    }

    /// Writes `text` to a synced temporary file beside `path`.
    fn stage(&mut self, flag: &str, shown: &Path, path: &Path, text: &[u8]) -> Result<(), CliError> {
        let dir = path.parent().unwrap_or(Path::new("/"));
        let (tmp, mut file) =
            new_temp(dir).map_err(|e| fail(flag, shown, format!("cannot make a temporary file beside it: {e}")))?;
        self.staged.push((tmp, path.to_path_buf(), flag.to_string(), shown.to_path_buf()));
        file.write_all(text).and_then(|()| file.sync_all()).map_err(|e| fail(flag, shown, format!("cannot write: {e}")))
    }

    /// Renames every temporary over its file; on a failure puts back what was replaced.
    fn commit(mut self) -> Result<(), CliError> {
        let mut p = pending();
        let mut done: Vec<(&Path, Prior)> = Vec::new();
        let mut failure = None;
        for (tmp, path, flag, shown) in &self.staged {
            let prior = keep(path);
            match fs::rename(tmp, path) {
                Ok(()) => done.push((path, prior)),
                Err(e) => {
                    if let Prior::Kept(k) = prior {
                        let _ = fs::remove_file(k);
                    }
                    failure = Some(fail(flag, shown, format!("cannot replace: {e}")));
                    break;
                }
            }
        }
        for (path, prior) in done {
            match (prior, failure.is_some()) {
                (Prior::Kept(k), false) => {
                    let _ = fs::remove_file(k);
                }
                (Prior::Kept(k), true) => {
                    let _ = fs::rename(k, path);
                }
                (Prior::Nothing, true) => {
                    let _ = fs::remove_file(path);
                }
                (Prior::Nothing | Prior::Lost, _) => {}
            }
        }
        if let Some(e) = failure {
            drop(p);
            return Err(e);
        }
        p.files.retain(|f| !self.staged.iter().any(|(t, ..)| t == f));
        p.dirs.retain(|d| !self.dirs.contains(d));
        self.committed = true;
        Ok(())
    }
}

/// Keeps the regular file at `path`, if any, under a temporary name (a hard link).
fn keep(path: &Path) -> Prior {
    if !fs::symlink_metadata(path).is_ok_and(|m| m.is_file()) {
        return Prior::Nothing;
    }
    let dir = path.parent().unwrap_or(Path::new("/"));
    for _ in 0..1000 {
        let n = SEQUENCE.fetch_add(1, Ordering::Relaxed);
        let k = dir.join(format!("{TEMP_PREFIX}{}-{n}{TEMP_SUFFIX}", std::process::id()));
        match fs::hard_link(path, &k) {
            Ok(()) => return Prior::Kept(k),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {}
            Err(_) => return Prior::Lost,
        }
    }
    Prior::Lost
}

impl Drop for Transaction {
    fn drop(&mut self) {
        if self.committed {
            return;
        }
        for (tmp, ..) in &self.staged {
            remove_temp(tmp);
        }
        let mut p = pending();
        for d in self.dirs.iter().rev() {
            let _ = fs::remove_dir(d);
            p.dirs.retain(|x| x != d);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Writes `text` to `out`, or to stdout when `out` is `None`.
    fn emit(text: &str, out: Option<&Path>) -> Result<(), CliError> {
        Output::from(text.to_string()).write(out)
    }

    #[test]
    fn binary_output_is_written_byte_for_byte_in_place_of_text() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.fmu");
        let bytes = vec![0x50, 0x4b, 0xff, 0x00, 0xfe];
        let out = Output { text: Some("not this".into()), ..Output::binary(bytes.clone()) };
        out.write(Some(&path)).unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), bytes);
    }

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
            dirs: vec![SideDir { flag: "--plots", path: new_dir.clone() }],
            files: vec![
                side("--plots", new_dir.join("a.svg")),
                side("--report", new_dir.join("..").join("plots").join(".").join("a.svg")),
            ],
            bytes: None,
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
            format!("--out {}: cannot write output: no directory {}", path.display(), dir.path().join("no").display())
        );
    }

    /// Every file of a run, or none: a side file that cannot be written leaves no other file,
    /// no temporary and no directory made.
    #[test]
    fn a_failing_file_leaves_no_file_of_the_run() {
        let dir = tempfile::tempdir().unwrap();
        let blocker = dir.path().join("file.txt");
        std::fs::write(&blocker, "x").unwrap();
        let side = |flag, path: PathBuf| SideFile { flag, path, text: flag.to_string() };
        let plots = dir.path().join("plots");
        let out = Output {
            text: Some("text".into()),
            dirs: vec![SideDir { flag: "--plots", path: plots.clone() }],
            files: vec![
                side("--plots", plots.join("a.svg")),
                side("--report", dir.path().join("r.json")),
                side("--out-spec", blocker.join("sub").join("s.toml")),
            ],
            bytes: None,
        };
        let e = out.write(Some(&dir.path().join("out.txt"))).unwrap_err();
        assert_eq!(e.exit_code(), 1);
        assert!(e.to_string().starts_with("--out-spec "), "{e}");
        let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(names, ["file.txt"], "nothing of the run");
    }

    /// A rename that fails puts back the files already replaced.
    #[test]
    fn a_failing_rename_puts_back_what_was_replaced() {
        let dir = tempfile::tempdir().unwrap();
        let first = dir.path().join("first.txt");
        std::fs::write(&first, "old").unwrap();
        let second = dir.path().join("second.txt");
        let mut run = Transaction::default();
        run.stage("--report", &first, &first, b"new").unwrap();
        run.stage("--out", &second, &second, b"new").unwrap();
        // The second target turns into a directory after staging: its rename fails.
        std::fs::create_dir(&second).unwrap();
        std::fs::write(second.join("inside"), "x").unwrap();
        let e = run.commit().unwrap_err();
        assert!(e.to_string().starts_with("--out "), "{e}");
        assert_eq!(std::fs::read_to_string(&first).unwrap(), "old");
        let mut names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name()).collect();
        names.sort();
        assert_eq!(names, ["first.txt", "second.txt"], "no temporary left");
    }

    #[test]
    fn paths_resolve_to_what_they_name() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("f.txt");
        assert_eq!(
            resolve("--out", &file, &[]).unwrap(),
            Sink::File(fs::canonicalize(dir.path()).unwrap().join("f.txt"))
        );
        assert_eq!(resolve("--out", Path::new("-"), &[]).unwrap(), Sink::Stdout);
        assert!(
            matches!(resolve("--plot", Path::new("-"), &[]).unwrap(), Sink::File(_)),
            "`-` is stdout for --out only"
        );
        let e = resolve("--out", dir.path(), &[]).unwrap_err();
        assert_eq!(e.to_string(), format!("--out {}: is a directory (give a file name)", dir.path().display()));
        #[cfg(unix)]
        {
            std::fs::write(&file, "x").unwrap();
            let link = dir.path().join("link.txt");
            std::os::unix::fs::symlink("f.txt", &link).unwrap();
            assert_eq!(resolve("--out", &link, &[]).unwrap(), Sink::File(fs::canonicalize(&file).unwrap()));
            assert!(matches!(
                resolve("--out", Path::new("/dev/null"), &[]).unwrap(),
                Sink::Stream { append: false, .. }
            ));
        }
        #[cfg(target_os = "linux")]
        {
            assert_eq!(resolve("--out", Path::new("/dev/stdout"), &[]).unwrap(), Sink::Stdout);
            assert_eq!(resolve("--out", Path::new("/proc/self/fd/2"), &[]).unwrap(), Sink::Stderr);
        }
    }
}
