//! The engine of the guide's calculator page: the project's own spec parser, model and sweep,
//! built for `wasm32-unknown-unknown` and called by the page's script, with no server.
//!
//! One call, [`handle`]: a JSON request in, a JSON answer out. The calls ([`calls`]):
//!
//! - `start`: the shipped specs (and `ballscrew init`'s template, when the page's build gave it)
//!   to start from;
//! - `fields`: the keys a spec's TOML text holds, table by table, with their values and
//!   comments, for the page's form; or the parser's error;
//! - `set`: the TOML text with one key set to a value typed in the form, its comments and layout
//!   kept;
//! - `sweep`: the sweep `ballscrew sweep` runs for the same spec and flags (the same points,
//!   evaluated by the same function, [`ballscrew_batch::sweep::sweep`]), as the columns of the
//!   reported-quantities table ([`ballscrew_batch::quantities`]) and the catalog band's line.
//!
//! Errors are the messages the command line prints, with the key or flag they name, so that
//! the page shows them at that field. Nothing here is physics: every number comes from the
//! crates the command line calls.
//!
//! The module's exports ([`abi`]) move bytes only: the page writes the request's UTF-8 into a
//! buffer the module gives it, calls, and reads the answer back. A plain export of three
//! functions, where wasm-bindgen would add a generator whose version must match the library's
//! and a second script to ship; the page's loader is about thirty lines.
//!
//! ```
//! let answer = ballscrew_wasm::handle(r#"{"call": "sweep", "toml": null, "preload_n": "500..1000", "preload_step_n": 500}"#);
//! let v: serde_json::Value = serde_json::from_str(&answer).unwrap();
//! assert_eq!(v["ok"], true, "{answer}");
//! assert_eq!(v["rows"].as_array().unwrap().len(), 2);
//! assert_eq!(v["columns"][0]["key"], "preload_n");
//! ```

pub mod abi;
pub mod calls;

pub use calls::handle;
