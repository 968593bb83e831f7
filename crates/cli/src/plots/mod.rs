//! The SVG figures of the command line, one file per command that draws (`--plot FILE.svg`,
//! `diagnose --plots DIR`), and what every figure shares ([`figure`]: the page, the axes,
//! numbers, the legend's place). Each figure is drawn from core types or the command line's
//! shared modules, never a command's, into a string: nothing here writes files, the caller hands
//! the text to `output`.

pub mod contact;
pub mod creep_curves;
pub mod diagnose;
pub mod figure;
pub mod inspect;
pub mod map;
pub mod reversal;
pub mod sensitivity;
pub mod sweep;
