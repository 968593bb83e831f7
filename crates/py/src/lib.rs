//! Python bindings of ballscrew: the module skeleton (the full API comes with the Python issue).
#![allow(missing_docs)]

/// The native module `ballscrew._ballscrew`.
#[pyo3::pymodule]
mod _ballscrew {
    use pyo3::prelude::*;

    /// Drag torque of the built-in DKFZD4012 screw at a preload (N) and speed (rpm), N m.
    #[pyfunction]
    #[pyo3(signature = (preload_n, speed_rpm = 100.0))]
    fn dkfzd4012_torque_nm(preload_n: f64, speed_rpm: f64) -> PyResult<f64> {
        use ballscrew_core::{Model, OperatingPoint, ScrewSpec, SolverState};
        let spec = ScrewSpec::dkfzd4012();
        let op =
            OperatingPoint { speed_rad_s: ballscrew_core::spec::rpm_to_rad_s(speed_rpm), preload_n, axial_load_n: 0.0 };
        let to_err = |e: ballscrew_core::Error| pyo3::exceptions::PyValueError::new_err(e.to_string());
        let model = Model::new(&spec).map_err(to_err)?;
        model.torque(&op, &mut SolverState::new()).map_err(to_err)
    }
}
