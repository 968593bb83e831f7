//! Evaluation of many operating points over the machine's cores: the library crate
//! `ballscrew-batch`, whose [`Stop`] the Python side answers on Ctrl-C ([`crate::interrupt`]).

pub use ballscrew_batch::*;
