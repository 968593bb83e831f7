//! `ballscrew fmu`: an FMI 2.0 co-simulation FMU of the spec (`ballscrew_fmu::package`), with
//! the FMU's shared library found beside this executable (the same cargo target directory),
//! at `--library FILE`, or at `$BALLSCREW_FMU_LIBRARY`.

use crate::error::CliError;
use crate::output::Output;
use crate::spec_and_flags;
use ballscrew_fmu::package::{LIBRARY_FILE, fmu_archive};
use std::path::{Path, PathBuf};

/// The environment variable naming the FMU's shared library.
pub const LIBRARY_ENV: &str = "BALLSCREW_FMU_LIBRARY";

/// Flags of `ballscrew fmu`.
#[derive(Debug, Clone, clap::Args)]
pub struct FmuArgs {
    /// The FMU's shared library (libballscrew_fmu.so) [default: $BALLSCREW_FMU_LIBRARY, else
    /// beside this executable]
    #[arg(long, value_name = "FILE")]
    pub library: Option<PathBuf>,
    /// The FMU's model name [default: the spec file's name without extension, "DKFZD4012" for
    /// the built-in spec]
    #[arg(long, value_name = "NAME")]
    pub model_name: Option<String>,
}

/// The shared library: `--library`, else `$BALLSCREW_FMU_LIBRARY`, else [`LIBRARY_FILE`]
/// beside this executable; an input error naming where it looked and how to build it.
fn library_path(args: &FmuArgs) -> Result<PathBuf, CliError> {
    if let Some(p) = &args.library {
        return Ok(p.clone());
    }
    if let Some(p) = std::env::var_os(LIBRARY_ENV).filter(|p| !p.is_empty()) {
        return Ok(PathBuf::from(p));
    }
    let exe = std::env::current_exe()
        .map_err(|e| CliError::Input(format!("cannot locate this executable to find {LIBRARY_FILE} beside it: {e}")))?;
    let beside = exe.parent().unwrap_or(Path::new(".")).join(LIBRARY_FILE);
    if beside.is_file() {
        Ok(beside)
    } else {
        Err(CliError::Input(format!(
            "no FMU library {}: build it with `cargo build --release -p ballscrew-fmu` (into the target \
             directory of this executable), or name it with --library FILE or {LIBRARY_ENV}",
            beside.display()
        )))
    }
}

/// The FMU of the spec at `spec` (or the built-in one) as the bytes to write; `--out` is needed
/// (an archive is not for a terminal; `--out -` writes it to stdout).
pub fn run(spec: Option<&Path>, out: Option<&Path>, args: &FmuArgs) -> Result<Output, CliError> {
    if out.is_none() {
        return Err(CliError::Input(
            "ballscrew fmu writes a zip archive: give --out FILE.fmu (or --out - for stdout)".into(),
        ));
    }
    let (text, origin) = spec_and_flags::load_spec_text(spec)?;
    let name = match (&args.model_name, spec) {
        (Some(n), _) => n.clone(),
        (None, Some(p)) => p.file_stem().map_or_else(|| "ballscrew".into(), |s| s.to_string_lossy().into_owned()),
        (None, None) => "DKFZD4012".into(),
    };
    let path = library_path(args)?;
    let library = std::fs::read(&path)
        .map_err(|e| CliError::Input(format!("cannot read the FMU library {}: {e}", path.display())))?;
    let bytes = fmu_archive(&text, &origin, &name, &library).map_err(|e| match e {
        ballscrew_fmu::package::PackageError::Archive(_) => CliError::Output(e.to_string()),
        _ => CliError::Input(e.to_string()),
    })?;
    Ok(Output::binary(bytes))
}
