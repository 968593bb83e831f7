//! `ballscrew fmu`: the archive written all or none, a missing or wrong library and a bad spec
//! refused with a message saying what to do, nothing written then.

mod common;

use common::{fails, ok_quiet};
use std::io::Read as _;
use std::path::Path;

/// The smallest file the packaging takes for a library: an ELF64 x86-64 shared-object header.
fn fake_library(dir: &Path) -> std::path::PathBuf {
    let mut b = vec![0u8; 64];
    b[..4].copy_from_slice(b"\x7fELF");
    b[4] = 2;
    b[5] = 1;
    b[16] = 3;
    b[18] = 62;
    let path = dir.join("lib.so");
    std::fs::write(&path, b).unwrap();
    path
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn writes_the_fmu_of_the_spec() {
    let dir = tempfile::tempdir().unwrap();
    let lib = fake_library(dir.path());
    let out = dir.path().join("screw.fmu");
    let spec = concat!(env!("CARGO_MANIFEST_DIR"), "/../../configs/single-nut-16x5.toml");
    ok_quiet(&["fmu", "--spec", spec, "--library", s(&lib), "--out", s(&out)]);
    let mut zip = zip::ZipArchive::new(std::fs::File::open(&out).unwrap()).unwrap();
    let mut text = String::new();
    zip.by_name("resources/spec.toml").unwrap().read_to_string(&mut text).unwrap();
    assert_eq!(text, std::fs::read_to_string(spec).unwrap());
    let mut xml = String::new();
    zip.by_name("modelDescription.xml").unwrap().read_to_string(&mut xml).unwrap();
    assert!(xml.contains(r#"modelName="single-nut-16x5""#), "{xml}");
    let mut so = Vec::new();
    zip.by_name("binaries/linux64/ballscrew.so").unwrap().read_to_end(&mut so).unwrap();
    assert_eq!(so, std::fs::read(&lib).unwrap());
}

#[test]
fn refusals_name_what_to_do_and_write_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let lib = fake_library(dir.path());
    let out = dir.path().join("x.fmu");
    let e = fails(&["fmu", "--library", s(&lib)], 2);
    assert!(e.contains("--out FILE.fmu"), "{e}");
    let e = fails(&["fmu", "--library", s(&dir.path().join("none.so")), "--out", s(&out)], 2);
    assert!(e.contains("cannot read the FMU library") && e.contains("none.so"), "{e}");
    let spec = dir.path().join("bad.toml");
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../configs/dkfzd4012.toml")).unwrap();
    std::fs::write(&spec, text.replace("pitch_diameter_mm = 40.0", "pitch_diameter_mm = -40.0")).unwrap();
    let e = fails(&["fmu", "--spec", s(&spec), "--library", s(&lib), "--out", s(&out)], 2);
    assert!(e.contains("bad.toml") && e.contains("invalid geometry.pitch_diameter_mm: -40 mm"), "{e}");
    let e = fails(&["fmu", "--library", s(&spec), "--out", s(&out)], 2);
    assert!(e.contains("not an x86-64 ELF shared object"), "{e}");
    let e = fails(&["fmu", "--library", s(&lib), "--format", "json", "--out", s(&out)], 2);
    assert!(e.contains("--format"), "{e}");
    // This command's own executable, a position-independent executable (an ELF "shared object"
    // too), is not the FMU's library.
    let e = fails(&["fmu", "--library", env!("CARGO_BIN_EXE_ballscrew"), "--out", s(&out)], 2);
    assert!(e.contains("is an executable, not a shared library"), "{e}");
    // A model name that XML cannot carry.
    let e = fails(&["fmu", "--library", s(&lib), "--model-name", "screw\u{1}", "--out", s(&out)], 2);
    assert!(e.contains("invalid model name \"screw\\u{1}\"") && e.contains("control characters"), "{e}");
    assert!(!out.exists());
}
