//! One rolling contact by FASTSIM (Kalker's simplified theory) over its Hertz ellipse, with its
//! traction field as numpy arrays: the core's contact analysis
//! ([`ballscrew_core::contact::analysis`]), parsed and rendered.

use crate::errors::value_error;
use ballscrew_core::Shown;
use ballscrew_core::contact::analysis::{Contact, Creep, elements_are_finite};
use ballscrew_core::contact::fastsim::{self, Element, TractionBound};
use ballscrew_core::input::shear_modulus_pa;
use numpy::{IntoPyArray, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// One rolling contact by FASTSIM (Kalker's simplified theory) over its Hertz ellipse.
///
/// Semi-axes in m (`semi_axis_rolling_m` along the rolling direction), load in N, creepages
/// dimensionless (`phi_per_m` in 1/m, `heathcote_per_m2` the coefficient k_h of the extra
/// longitudinal creepage k_h y^2), material in Pa. `grid` elements per axis (1..1000),
/// `bound` "parabolic" or "elliptical". Returns a dict: the forces on the ball `force_e_n`,
/// `force_f_n`, `spin_moment_nm`, `dissipation_per_speed_n`, the element counts and the
/// adhesion share, and (grid x grid) numpy arrays, rows lateral, columns along rolling from the
/// trailing edge: `x_m`, `y_m`, `area_m2`, `traction_x_pa`, `traction_y_pa`, `bound_pa`,
/// `slip_x`, `slip_y`, `sliding` (bool).
#[pyfunction]
#[pyo3(signature = (semi_axis_rolling_m, semi_axis_lateral_m, normal_load_n, *, xi = 0.0, eta = 0.0,
    phi_per_m = 0.0, heathcote_per_m2 = 0.0, friction_coefficient = 0.03, youngs_modulus_pa = 210e9,
    poisson_ratio = 0.3, grid = 40, bound = "parabolic"))]
#[allow(clippy::too_many_arguments)]
pub fn contact<'py>(
    py: Python<'py>,
    semi_axis_rolling_m: f64,
    semi_axis_lateral_m: f64,
    normal_load_n: f64,
    xi: f64,
    eta: f64,
    phi_per_m: f64,
    heathcote_per_m2: f64,
    friction_coefficient: f64,
    youngs_modulus_pa: f64,
    poisson_ratio: f64,
    grid: i64,
    bound: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let Some(bound) = TractionBound::parse(bound) else {
        return Err(value_error(format!("invalid bound: {bound:?} (valid: \"parabolic\" or \"elliptical\")")));
    };
    if !(1..=fastsim::MAX_GRID as i64).contains(&grid) {
        return Err(value_error(format!("invalid grid: {grid} (valid: integer in [1, {}])", fastsim::MAX_GRID)));
    }
    if !(youngs_modulus_pa.is_finite() && youngs_modulus_pa > 0.0) {
        return Err(value_error(format!("invalid youngs_modulus_pa: {youngs_modulus_pa} (valid: finite and > 0)")));
    }
    let contact = Contact {
        semi_axis_rolling_m,
        semi_axis_lateral_m,
        normal_load_n,
        shear_modulus_pa: shear_modulus_pa(youngs_modulus_pa, poisson_ratio),
        poisson_ratio,
        friction_coefficient,
    };
    let creep = Creep { xi, eta, phi_per_m, heathcote_per_m2 };
    let n = grid as usize;
    let (result, elements) = py
        .detach(|| {
            let mut elements = vec![Element::default(); n * n];
            contact.fastsim(&creep, bound, n, Some(&mut elements)).map(|f| (f.result, elements))
        })
        .map_err(value_error)?;
    // The totals as FASTSIM gives them (|F|/(mu Q) is not returned: mu Q may be 0 here).
    let totals = [result.force_e_n, result.force_f_n, result.spin_moment_nm, result.dissipation_per_speed_n];
    if !(totals.iter().all(|v| v.is_finite()) && elements_are_finite(&elements)) {
        // Values the core accepts one by one can still overflow together (e.g. a creepage of
        // 1e300 times the stiffness): refuse rather than hand back NaN or infinities.
        let given = [
            ("semi_axis_rolling_m", semi_axis_rolling_m),
            ("semi_axis_lateral_m", semi_axis_lateral_m),
            ("normal_load_n", normal_load_n),
            ("xi", xi),
            ("eta", eta),
            ("phi_per_m", phi_per_m),
            ("heathcote_per_m2", heathcote_per_m2),
        ]
        .map(|(name, v)| format!("{name} {}", Shown(v)))
        .join(", ");
        return Err(value_error(format!(
            "contact: the result is not finite for {given} (valid: values whose products stay within double precision)"
        )));
    }
    let d = PyDict::new(py);
    d.set_item("force_e_n", result.force_e_n)?;
    d.set_item("force_f_n", result.force_f_n)?;
    d.set_item("spin_moment_nm", result.spin_moment_nm)?;
    d.set_item("dissipation_per_speed_n", result.dissipation_per_speed_n)?;
    d.set_item("adhesion_elements", result.adhesion_elements)?;
    d.set_item("slip_elements", result.slip_elements)?;
    d.set_item("adhesion_share", result.adhesion_share())?;
    let field = |f: fn(&Element) -> f64| -> PyResult<Bound<'py, PyAny>> {
        let v: Vec<f64> = elements.iter().map(f).collect();
        Ok(v.into_pyarray(py).reshape([n, n])?.into_any())
    };
    d.set_item("x_m", field(|e| e.x_m)?)?;
    d.set_item("y_m", field(|e| e.y_m)?)?;
    d.set_item("area_m2", field(|e| e.area_m2)?)?;
    d.set_item("traction_x_pa", field(|e| e.traction_x_pa)?)?;
    d.set_item("traction_y_pa", field(|e| e.traction_y_pa)?)?;
    d.set_item("bound_pa", field(|e| e.bound_pa)?)?;
    d.set_item("slip_x", field(|e| e.slip_x)?)?;
    d.set_item("slip_y", field(|e| e.slip_y)?)?;
    let sliding: Vec<bool> = elements.iter().map(|e| e.sliding).collect();
    d.set_item("sliding", sliding.into_pyarray(py).reshape([n, n])?)?;
    Ok(d)
}
