//! The workspace's own suite: the tests and benchmarks that span crates (`tests/`, `benches/`),
//! and the Rust code blocks of the README and the guide (`docs/`), which compile and run here
//! as doc tests (`cargo test --doc -p ballscrew-suite`), so that none of them can go stale.
//! Lines of a block that start with `# ` are run but not shown (rustdoc and mdBook both hide
//! them).

/// The README's Rust blocks.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct Readme;

/// The guide's chapter on real time.
#[cfg(doctest)]
#[doc = include_str!("../docs/real-time.md")]
pub struct RealTime;
