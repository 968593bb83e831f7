//! # ballscrew-fmu
//!
//! The ball screw's friction torque as an FMI 2.0 co-simulation FMU (Functional Mock-up Unit):
//! the shared library a simulator loads (the C functions of [`ffi`]) and the packaging of an FMU
//! archive around it ([`package`]), which `ballscrew fmu` calls.
//!
//! FMI 2.0 rather than 3.0: it is the version every common importer runs (Simulink, OpenModelica,
//! Dymola, FMPy), and co-simulation because the torque is an algebraic function of the inputs
//! with the solver's warm start as its only memory: the FMU needs no integrator of the host.
//!
//! The modules:
//! - [`variables`]: the FMU's variables (names, value references, units, causality);
//! - [`instance`]: one instance's state and its FMI life cycle in safe Rust: the spec, the
//!   control-loop evaluator (`ballscrew_core::Evaluator`, f64; the model's own solve for a spec
//!   the evaluator does not take) and its warm state, the inputs and the outputs;
//! - [`resource`]: the path of the FMU's resources from the `file:` URI the importer passes;
//! - [`model_description`]: `modelDescription.xml` of a spec;
//! - [`package`]: the FMU archive (zip) of a spec and the shared library;
//! - [`ffi`]: the exported `fmi2*` functions (C ABI), which check every pointer, catch every
//!   panic and log every error through the importer's logger.

pub mod ffi;
pub mod instance;
pub mod model_description;
pub mod package;
pub mod resource;
pub mod variables;
