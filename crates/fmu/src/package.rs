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
    /// The archive could not be written.
    Archive(String),
}

impl core::fmt::Display for PackageError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            PackageError::Spec(m) | PackageError::Library(m) => f.write_str(m),
            PackageError::Archive(m) => write!(f, "cannot write the FMU archive: {m}"),
        }
    }
}

impl core::error::Error for PackageError {}

/// Checks that `library` is a 64-bit x86-64 ELF shared object (the one platform packaged).
fn check_library(library: &[u8]) -> Result<(), PackageError> {
    let elf = library.len() > 20 && library.starts_with(b"\x7fELF") && library[4] == 2 && library[5] == 1;
    let machine = if elf { u16::from_le_bytes([library[18], library[19]]) } else { 0 };
    // e_type 3: shared object; e_machine 62: x86-64.
    let shared = elf && u16::from_le_bytes([library[16], library[17]]) == 3;
    if elf && shared && machine == 62 {
        Ok(())
    } else {
        Err(PackageError::Library(format!(
            "the FMU's library is not an x86-64 ELF shared object ({} bytes): FMUs are packaged for {PLATFORM} (linux x86_64) only",
            library.len()
        )))
    }
}

/// The FMU (zip archive bytes) of the spec in TOML text `spec_text` (named `origin` in
/// messages), named `model_name`, with the shared library `library` (the bytes of
/// [`LIBRARY_FILE`]). The spec is validated first, as the FMU will at instantiation.
pub fn fmu_archive(spec_text: &str, origin: &str, model_name: &str, library: &[u8]) -> Result<Vec<u8>, PackageError> {
    let spec = spec_from_toml_str(spec_text, origin).map_err(|e| match e {
        ConfigError::Parse { .. } | ConfigError::Io { .. } => PackageError::Spec(e.to_string()),
        _ => PackageError::Spec(format!("{origin}: {e}")),
    })?;
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
}
