//! The FMU's resources folder from the `fmuResourceLocation` an importer passes to
//! `fmi2Instantiate`: a `file:` URI (`file:///dir/resources`, `file:/dir/resources`,
//! `file://localhost/dir/resources`), percent-encoded (`%20` for a space); a plain absolute
//! path is taken as it is, as some importers pass one.

use std::path::PathBuf;

/// The name of the spec inside the resources folder.
pub const SPEC_FILE: &str = "spec.toml";

/// The local path of the `file:` URI `uri`; an error names the URI and what is wrong.
pub fn path_of_uri(uri: &str) -> Result<PathBuf, String> {
    let encoded = if let Some(rest) = uri.strip_prefix("file://") {
        if rest.starts_with('/') {
            rest
        } else if let Some(local) = rest.strip_prefix("localhost") {
            local
        } else {
            return Err(format!("fmuResourceLocation {uri:?}: a file URI on another host is not readable"));
        }
    } else if let Some(rest) = uri.strip_prefix("file:") {
        rest
    } else if uri.starts_with('/') {
        uri
    } else {
        return Err(format!("fmuResourceLocation {uri:?}: not a file: URI (valid: file:///path/resources)"));
    };
    if !encoded.starts_with('/') {
        return Err(format!("fmuResourceLocation {uri:?}: not an absolute path"));
    }
    let bytes = percent_decode(encoded).ok_or_else(|| format!("fmuResourceLocation {uri:?}: invalid %-escape"))?;
    path_from_bytes(bytes)
}

/// `text` with every `%XX` replaced by its byte; `None` for a `%` without two hex digits.
fn percent_decode(text: &str) -> Option<Vec<u8>> {
    let b = text.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%' {
            let hex = b.get(i + 1..i + 3)?;
            let s = core::str::from_utf8(hex).ok()?;
            out.push(u8::from_str_radix(s, 16).ok()?);
            i += 3;
        } else {
            out.push(b[i]);
            i += 1;
        }
    }
    Some(out)
}

#[cfg(unix)]
fn path_from_bytes(bytes: Vec<u8>) -> Result<PathBuf, String> {
    use std::os::unix::ffi::OsStringExt as _;
    Ok(PathBuf::from(std::ffi::OsString::from_vec(bytes)))
}

#[cfg(not(unix))]
fn path_from_bytes(bytes: Vec<u8>) -> Result<PathBuf, String> {
    String::from_utf8(bytes).map(PathBuf::from).map_err(|_| "fmuResourceLocation: not UTF-8".to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_file_uri_form() {
        let want = PathBuf::from("/tmp/my fmu/resources");
        assert_eq!(path_of_uri("file:///tmp/my%20fmu/resources").unwrap(), want);
        assert_eq!(path_of_uri("file:/tmp/my%20fmu/resources").unwrap(), want);
        assert_eq!(path_of_uri("file://localhost/tmp/my%20fmu/resources").unwrap(), want);
        assert_eq!(path_of_uri("/tmp/my fmu/resources").unwrap(), want);
        assert_eq!(path_of_uri("file:///a/%C3%A9/").unwrap(), PathBuf::from("/a/é/"));
    }

    #[test]
    fn bad_uris_are_refused_by_name() {
        for bad in ["file://server/share", "http://x/y", "file:relative", "file:///a%2", "file:///a%zz", "rel/ative"] {
            let e = path_of_uri(bad).unwrap_err();
            assert!(e.contains(bad), "{bad}: {e}");
        }
    }
}
