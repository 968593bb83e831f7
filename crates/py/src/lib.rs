//! Python bindings of ballscrew (module `ballscrew`, native part `ballscrew._ballscrew`).
//!
//! - [`screw`]: the `Screw` class (a validated spec and its model): torque over numpy arrays,
//!   preload sweeps, the per-contact breakdown, read access to the spec.
//! - [`evaluator`]: the `Evaluator` class (the core's control-loop evaluator in f64 or f32):
//!   warm-started single points and in-order time series.
//! - [`reversal`]: the `Reversal` class (the core's reversal state model in f64 or f32): the
//!   drive torque through reversals (presliding) stepped with the screw's rotation.
//! - [`band`]: the band of the drag torque (`Screw.band`, `Screw.sweep(band=...)`,
//!   `Screw.sensitivity`): its settings, errors and columns.
//! - [`batch`]: evaluation of many operating points over the machine's cores (no Python).
//! - [`interrupt`]: Ctrl-C during long evaluations (signal checks with the GIL released).
//! - [`numbers`]: real numbers from Python arguments, the one conversion of every number
//!   argument (bools, complex numbers, datetimes, texts, `None`, masked arrays refused).
//! - [`points`]: numpy arguments to broadcast operating points.
//! - [`records`]: reported values as Python objects, read from the table of reported quantities
//!   that the command line renders (`ballscrew_batch::quantities`).
//! - [`contact`]: one rolling contact by FASTSIM, with its traction field as numpy arrays.
//! - [`errors`]: the core's errors as Python exceptions (`ValueError` with the core's message).
//!
//! Each Python-facing item lives in its own file and is exported by one `#[pymodule_export]`
//! line below. A new item needs its `pub mod` line, its export line and its entry in the type
//! stub `python/ballscrew/_ballscrew.pyi` (a test checks that the stub covers the module);
//! `ballscrew/__init__.py` re-exports every public name of the native module by itself, and
//! `__version__` (the crate's version) by name.

extern crate alloc;

pub mod audit;
pub mod band;
pub mod batch;
pub mod contact;
pub mod diagnose;
pub mod errors;
pub mod evaluator;
pub mod interrupt;
pub mod numbers;
pub mod points;
pub mod records;
pub mod reversal;
pub mod screw;

/// Friction (drag) torque of preloaded ball screws: the native part of the `ballscrew` package.
#[pyo3::pymodule]
mod _ballscrew {
    #[pymodule_export]
    use crate::contact::contact;
    #[pymodule_export]
    use crate::diagnose::{diagnose, predict};
    #[pymodule_export]
    use crate::errors::ConvergenceError;
    #[pymodule_export]
    use crate::errors::EvaluationWarning;
    #[pymodule_export]
    use crate::errors::QuasiStaticWarning;
    #[pymodule_export]
    use crate::errors::StateWarning;
    #[pymodule_export]
    use crate::evaluator::Evaluator;
    #[pymodule_export]
    use crate::reversal::Reversal;
    #[pymodule_export]
    use crate::screw::Screw;
    #[pymodule_export]
    use crate::screw::dkfzd4012_torque_nm;

    use pyo3::prelude::*;

    /// `__version__`: the crate's version, the one the wheel carries (maturin takes the
    /// package's version from `Cargo.toml`).
    #[pymodule_init]
    fn init(m: &Bound<'_, PyModule>) -> PyResult<()> {
        m.add("__version__", env!("CARGO_PKG_VERSION"))
    }
}
