//! The module's exports: bytes in and out of [`crate::handle`], for the page's loader
//! (`docs/calculator/calculator.js`).
//!
//! The page asks [`request_buffer`] for room for its request's UTF-8 and writes it at the
//! address returned (the module's memory is the page's to write), calls [`call`], which answers
//! the request and returns the answer's length, and reads that many bytes at [`answer`]. Both
//! buffers belong to the module and live until the next call; the page copies the answer out.
//! No unsafe block: the exports are unmangled (`#[unsafe(no_mangle)]`, the reason this module
//! allows `unsafe_code`), and addresses go out as numbers only.

#![allow(unsafe_code)]

use std::sync::Mutex;

/// The request's bytes, written by the page.
static REQUEST: Mutex<Vec<u8>> = Mutex::new(Vec::new());
/// The last answer's bytes, read by the page.
static ANSWER: Mutex<Vec<u8>> = Mutex::new(Vec::new());

/// Room for a request of `len` bytes, zeroed; its address in the module's memory.
#[unsafe(no_mangle)]
pub extern "C" fn request_buffer(len: usize) -> usize {
    let mut r = REQUEST.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    r.clear();
    r.resize(len, 0);
    r.as_mut_ptr() as usize
}

/// Answers the request in the buffer ([`crate::handle`]; bytes that are not UTF-8 are replaced,
/// and the JSON parser refuses them); the answer's length in bytes.
#[unsafe(no_mangle)]
pub extern "C" fn call() -> usize {
    let request = REQUEST.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    let text = String::from_utf8_lossy(&request).into_owned();
    drop(request);
    let answer = crate::handle(&text);
    let mut a = ANSWER.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    *a = answer.into_bytes();
    a.len()
}

/// The address of the last answer.
#[unsafe(no_mangle)]
pub extern "C" fn answer() -> usize {
    ANSWER.lock().unwrap_or_else(std::sync::PoisonError::into_inner).as_ptr() as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bytes round trip as the page moves them (here, natively, through the statics).
    #[test]
    fn a_request_written_to_the_buffer_is_answered() {
        let request = br#"{"call": "start"}"#;
        request_buffer(request.len());
        REQUEST.lock().unwrap().copy_from_slice(request);
        let len = call();
        let a = ANSWER.lock().unwrap();
        assert_eq!(a.len(), len);
        assert!(a.starts_with(br#"{"ok":true"#), "{}", String::from_utf8_lossy(&a));
    }
}
