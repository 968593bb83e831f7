//! The FMU archive: a zip of `modelDescription.xml`, the shared library of this crate as
//! `binaries/linux64/ballscrew.so`, and the spec as `resources/spec.toml` (read at
//! instantiation), all deflated, with fixed timestamps (the same inputs give the same bytes).

use crate::model_description::model_description;
use crate::resource::SPEC_FILE;
use crate::variables::MODEL_IDENTIFIER;
use ballscrew_config::{ConfigError, spec_from_toml_str};
use std::io::{Cursor, Write as _};
use zip::CompressionMethod;
use zip::write::{SimpleFileOptions, ZipWriter};

/// The file name of the shared library cargo builds from this crate (linux).
pub const LIBRARY_FILE: &str = "libballscrew_fmu.so";

/// FMI 2.0's name of the platform the library is built for.
pub const PLATFORM: &str = "linux64";

/// Why an FMU could not be packaged.
#[derive(Debug, Clone, PartialEq)]
pub enum PackageError {
    /// The spec is invalid: the parser's or the core's message.
    Spec(String),
    /// The shared library is not one for [`PLATFORM`].
    Library(String),
    /// The model name cannot be written into `modelDescription.xml`.
    ModelName(String),
    /// The archive could not be written.
    Archive(String),
}

impl core::fmt::Display for PackageError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            PackageError::Spec(m) | PackageError::Library(m) | PackageError::ModelName(m) => f.write_str(m),
            PackageError::Archive(m) => write!(f, "cannot write the FMU archive: {m}"),
        }
    }
}

impl core::error::Error for PackageError {}

/// Checks that `library` is a 64-bit x86-64 ELF shared object (the one platform packaged), and
/// not an executable: a position-independent executable is an ELF "shared object" too, but it
/// names a program interpreter (a `PT_INTERP` program header), which a library does not.
fn check_library(library: &[u8]) -> Result<(), PackageError> {
    let u16_at = |at: usize| library.get(at..at + 2).map_or(0, |b| u16::from_le_bytes([b[0], b[1]]));
    let elf = library.len() >= 64 && library.starts_with(b"\x7fELF") && library[4] == 2 && library[5] == 1;
    // e_type 3: shared object; e_machine 62: x86-64.
    if !(elf && u16_at(16) == 3 && u16_at(18) == 62) {
        return Err(PackageError::Library(format!(
            "the FMU's library is not an x86-64 ELF shared object ({} bytes): FMUs are packaged for {PLATFORM} (linux x86_64) only",
            library.len()
        )));
    }
    if program_headers(library).any(|p_type| p_type == PT_INTERP) {
        return Err(PackageError::Library(format!(
            "the FMU's library is an executable, not a shared library: give {LIBRARY_FILE} (cargo build --release -p ballscrew-fmu)"
        )));
    }
    Ok(())
}

/// ELF's program header type of the program interpreter (executables only).
const PT_INTERP: u32 = 3;

/// The types (`p_type`) of the program headers of the ELF64 little-endian file `elf`, those that
/// lie inside it.
fn program_headers(elf: &[u8]) -> impl Iterator<Item = u32> + '_ {
    let word = |at: usize, n: usize| {
        elf.get(at..at + n).map_or(0, |b| b.iter().rev().fold(0u64, |v, &x| v << 8 | u64::from(x)))
    };
    let (offset, size, count) = (word(32, 8), word(54, 2), word(56, 2));
    (0..count).filter_map(move |i| {
        let at = usize::try_from(offset.checked_add(i.checked_mul(size)?)?).ok()?;
        u32::try_from(word(at, 4)).ok().filter(|_| elf.len() >= at + 4)
    })
}

/// Checks that `name` can stand as the FMU's `modelName`: not empty, no control characters
/// (XML 1.0 cannot carry most of them, and an importer shows the name as it is).
fn check_model_name(name: &str) -> Result<(), PackageError> {
    if name.trim().is_empty() || name.chars().any(char::is_control) {
        return Err(PackageError::ModelName(format!(
            "invalid model name {name:?} (--model-name, else the spec file's name): it needs a visible character and no control characters"
        )));
    }
    Ok(())
}

/// The FMU (zip archive bytes) of the spec in TOML text `spec_text` (named `origin` in
/// messages), named `model_name`, with the shared library `library` (the bytes of
/// [`LIBRARY_FILE`]). The spec is validated first, as the FMU will at instantiation.
pub fn fmu_archive(spec_text: &str, origin: &str, model_name: &str, library: &[u8]) -> Result<Vec<u8>, PackageError> {
    let spec = spec_from_toml_str(spec_text, origin).map_err(|e| match e {
        ConfigError::Parse { .. } | ConfigError::Io { .. } => PackageError::Spec(e.to_string()),
        _ => PackageError::Spec(format!("{origin}: {e}")),
    })?;
    check_model_name(model_name)?;
    check_library(library)?;
    let xml = model_description(&spec, spec_text, model_name);
    let archive = |e: &dyn core::fmt::Display| PackageError::Archive(e.to_string());
    let mut zip = ZipWriter::new(Cursor::new(Vec::new()));
    let file = SimpleFileOptions::default().compression_method(CompressionMethod::Deflated).unix_permissions(0o644);
    let entries: [(String, &[u8], SimpleFileOptions); 3] = [
        ("modelDescription.xml".into(), xml.as_bytes(), file),
        (format!("binaries/{PLATFORM}/{MODEL_IDENTIFIER}.so"), library, file.unix_permissions(0o755)),
        (format!("resources/{SPEC_FILE}"), spec_text.as_bytes(), file),
    ];
    for (name, bytes, options) in entries {
        zip.start_file(name, options).map_err(|e| archive(&e))?;
        zip.write_all(bytes).map_err(|e| archive(&e))?;
    }
    Ok(zip.finish().map_err(|e| archive(&e))?.into_inner())
}

#[cfg(test)]
mod tests {
    use super::*;
    use ballscrew_config::DKFZD4012_TOML;
    use std::io::Read as _;

    /// The smallest header [`check_library`] takes: ELF64, little-endian, shared, x86-64.
    fn fake_library() -> Vec<u8> {
        let mut b = vec![0u8; 64];
        b[..4].copy_from_slice(b"\x7fELF");
        b[4] = 2;
        b[5] = 1;
        b[16] = 3;
        b[18] = 62;
        b
    }

    #[test]
    fn archive_holds_the_three_files() {
        let lib = fake_library();
        let bytes = fmu_archive(DKFZD4012_TOML, "built-in", "dkfzd4012", &lib).unwrap();
        let mut zip = zip::ZipArchive::new(Cursor::new(bytes.clone())).unwrap();
        let mut names: Vec<String> = zip.file_names().map(String::from).collect();
        names.sort();
        assert_eq!(names, ["binaries/linux64/ballscrew.so", "modelDescription.xml", "resources/spec.toml"]);
        let mut spec = String::new();
        zip.by_name("resources/spec.toml").unwrap().read_to_string(&mut spec).unwrap();
        assert_eq!(spec, DKFZD4012_TOML);
        let mut so = Vec::new();
        zip.by_name("binaries/linux64/ballscrew.so").unwrap().read_to_end(&mut so).unwrap();
        assert_eq!(so, lib);
        // The same inputs, the same bytes.
        assert_eq!(bytes, fmu_archive(DKFZD4012_TOML, "built-in", "dkfzd4012", &lib).unwrap());
    }

    #[test]
    fn bad_spec_and_bad_library_are_refused() {
        let text = DKFZD4012_TOML.replace("preload_n = ", "preload_n = -");
        let e = fmu_archive(&text, "my.toml", "m", &fake_library()).unwrap_err();
        assert!(matches!(&e, PackageError::Spec(m) if m.contains("my.toml") && m.contains("preload_n")), "{e}");
        let e = fmu_archive(DKFZD4012_TOML, "my.toml", "m", b"#!/bin/sh\n").unwrap_err();
        assert!(matches!(e, PackageError::Library(_)), "{e}");
    }

    /// [`fake_library`] with program headers of the types `types` after the ELF header.
    fn with_program_headers(types: &[u32]) -> Vec<u8> {
        let mut b = fake_library();
        b[32..40].copy_from_slice(&64u64.to_le_bytes());
        b[54..56].copy_from_slice(&56u16.to_le_bytes());
        b[56..58].copy_from_slice(&u16::try_from(types.len()).unwrap().to_le_bytes());
        for t in types {
            let mut header = vec![0u8; 56];
            header[..4].copy_from_slice(&t.to_le_bytes());
            b.extend(header);
        }
        b
    }

    #[test]
    fn an_executable_is_refused_as_the_library() {
        // PT_PHDR, PT_INTERP, PT_LOAD: a position-independent executable's first headers.
        let e = fmu_archive(DKFZD4012_TOML, "built-in", "m", &with_program_headers(&[6, 3, 1])).unwrap_err();
        assert!(matches!(&e, PackageError::Library(m) if m.contains("executable")), "{e}");
        // PT_LOAD, PT_DYNAMIC: a shared library's.
        assert!(fmu_archive(DKFZD4012_TOML, "built-in", "m", &with_program_headers(&[1, 1, 2])).is_ok());
        // Headers said to lie beyond the file's end are not read.
        let mut cut = with_program_headers(&[3]);
        cut.truncate(66);
        assert!(fmu_archive(DKFZD4012_TOML, "built-in", "m", &cut).is_ok());
    }

    #[test]
    fn a_model_name_with_control_characters_or_nothing_visible_is_refused() {
        for name in ["a\u{1}b", "tab\there", "line\n", "\u{7f}", "\u{85}", "", "   "] {
            let e = fmu_archive(DKFZD4012_TOML, "built-in", name, &fake_library()).unwrap_err();
            assert!(matches!(&e, PackageError::ModelName(m) if m.contains("model name")), "{name:?}: {e}");
        }
        for name in ["DKFZD4012", "a<b & c", "Kugelgewindetrieb Ø40"] {
            assert!(fmu_archive(DKFZD4012_TOML, "built-in", name, &fake_library()).is_ok(), "{name:?}");
        }
    }
}
