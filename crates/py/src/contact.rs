//! One rolling contact by FASTSIM (Kalker's simplified theory) over its Hertz ellipse, with its
//! traction field as numpy arrays: the core's contact analysis
//! ([`ballscrew_core::contact::analysis`]), parsed and rendered, in the units and ranges of
//! `ballscrew contact` ([`ballscrew_core::contact::limits`]).

use crate::errors::value_error;
use crate::numbers::{real_number, refusal, shown};
use ballscrew_core::contact::analysis::{Contact, Creep, elements_are_finite};
use ballscrew_core::contact::fastsim::{Element, TractionBound};
use ballscrew_core::contact::limits::{
    self, CREEPAGE, FRICTION, Limit, NORMAL_LOAD_N, POISSON_RATIO, SEMI_AXIS_MM, YOUNGS_MODULUS_GPA,
};
use ballscrew_core::input::shear_modulus_pa;
use ballscrew_core::{Invalid, Shown};
use numpy::{IntoPyArray, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict};

/// `value` of the argument `name` when `limit` holds it, else `ValueError` in the command line's
/// words (`invalid NAME: VALUE (valid: RANGE)`).
fn within(name: &str, value: f64, limit: &Limit) -> PyResult<f64> {
    if limit.contains(value) {
        Ok(value)
    } else {
        Err(value_error(Invalid { field: name, value, valid: limit.valid }.to_string()))
    }
}

/// One rolling contact by FASTSIM (Kalker's simplified theory) over its Hertz ellipse, in the
/// units and ranges of `ballscrew contact` (see [`ballscrew_core::contact::limits`]).
///
/// Semi-axes in mm (`semi_axis_rolling_mm` along the rolling direction, [1e-4, 100]), the normal
/// load in N ([1e-6, 1e7]), creepages `xi`, `eta` dimensionless, `phi_per_mm` in 1/mm,
/// `heathcote_per_mm2` the coefficient k_h of the extra longitudinal creepage k_h y^2 in 1/mm^2
/// (each |value| <= 1000), `friction` the coefficient mu ([1e-4, 1]), `youngs_modulus_gpa` in
/// GPa ([1, 1000]), `poisson_ratio` ([0, 0.5]); `grid` elements per axis (1..400), `bound`
/// "parabolic" or "elliptical". Returns a dict: the forces on the ball `force_e_n`,
/// `force_f_n`, `spin_moment_nm`, `dissipation_per_speed_n`, the element counts and the
/// adhesion share, and (grid x grid) numpy arrays, rows lateral, columns along rolling from the
/// trailing edge: `x_mm`, `y_mm`, `area_mm2`, `traction_x_mpa`, `traction_y_mpa`, `bound_mpa`
/// (MPa = N/mm^2: traction times area sums to N), `slip_x`, `slip_y`, `sliding` (bool).
#[pyfunction]
#[pyo3(signature = (semi_axis_rolling_mm, semi_axis_lateral_mm, normal_load_n, *, xi = None, eta = None,
    phi_per_mm = None, heathcote_per_mm2 = None, friction = None, youngs_modulus_gpa = None,
    poisson_ratio = None, grid = None, bound = "parabolic"),
    text_signature = "(semi_axis_rolling_mm, semi_axis_lateral_mm, normal_load_n, *, xi=0.0, eta=0.0, \
    phi_per_mm=0.0, heathcote_per_mm2=0.0, friction=0.03, youngs_modulus_gpa=210.0, poisson_ratio=0.3, grid=40, \
    bound='parabolic')")]
#[allow(clippy::too_many_arguments)]
pub fn contact<'py>(
    py: Python<'py>,
    semi_axis_rolling_mm: &Bound<'py, PyAny>,
    semi_axis_lateral_mm: &Bound<'py, PyAny>,
    normal_load_n: &Bound<'py, PyAny>,
    xi: Option<&Bound<'py, PyAny>>,
    eta: Option<&Bound<'py, PyAny>>,
    phi_per_mm: Option<&Bound<'py, PyAny>>,
    heathcote_per_mm2: Option<&Bound<'py, PyAny>>,
    friction: Option<&Bound<'py, PyAny>>,
    youngs_modulus_gpa: Option<&Bound<'py, PyAny>>,
    poisson_ratio: Option<&Bound<'py, PyAny>>,
    grid: Option<&Bound<'py, PyAny>>,
    bound: &str,
) -> PyResult<Bound<'py, PyDict>> {
    // Each number: a real number (as every number argument), then the command line's range.
    let value = |name: &str, obj: Option<&Bound<'py, PyAny>>, default: f64, limit: &Limit| match obj {
        Some(o) => within(name, real_number(name, o)?, limit),
        None => Ok(default),
    };
    let a_mm = value("semi_axis_rolling_mm", Some(semi_axis_rolling_mm), 0.0, &SEMI_AXIS_MM)?;
    let b_mm = value("semi_axis_lateral_mm", Some(semi_axis_lateral_mm), 0.0, &SEMI_AXIS_MM)?;
    let normal_load_n = value("normal_load_n", Some(normal_load_n), 0.0, &NORMAL_LOAD_N)?;
    let xi = value("xi", xi, 0.0, &CREEPAGE)?;
    let eta = value("eta", eta, 0.0, &CREEPAGE)?;
    let phi_per_mm = value("phi_per_mm", phi_per_mm, 0.0, &CREEPAGE)?;
    let heathcote_per_mm2 = value("heathcote_per_mm2", heathcote_per_mm2, 0.0, &CREEPAGE)?;
    let friction = value("friction", friction, 0.03, &FRICTION)?;
    let youngs_modulus_gpa = value("youngs_modulus_gpa", youngs_modulus_gpa, 210.0, &YOUNGS_MODULUS_GPA)?;
    let poisson_ratio = value("poisson_ratio", poisson_ratio, 0.3, &POISSON_RATIO)?;
    let grid_valid = format!("integer in [1, {}]", limits::MAX_GRID);
    let grid = match grid {
        None => 40,
        Some(g) => match g.extract::<i64>() {
            Ok(n) if !g.is_instance_of::<PyBool>() && (1..=limits::MAX_GRID).contains(&n) => n,
            _ => return Err(refusal("grid", &shown(g), &grid_valid)),
        },
    };
    let Some(bound) = TractionBound::parse(bound) else {
        return Err(value_error(format!("invalid bound: {bound:?} (valid: \"parabolic\" or \"elliptical\")")));
    };
    let (semi_axis_rolling_m, semi_axis_lateral_m) = (a_mm * 1e-3, b_mm * 1e-3);
    let (phi_per_m, heathcote_per_m2) = (phi_per_mm * 1e3, heathcote_per_mm2 * 1e6);
    let youngs_modulus_pa = youngs_modulus_gpa * 1e9;
    let friction_coefficient = friction;
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
            ("semi_axis_rolling_mm", a_mm),
            ("semi_axis_lateral_mm", b_mm),
            ("normal_load_n", normal_load_n),
            ("xi", xi),
            ("eta", eta),
            ("phi_per_mm", phi_per_mm),
            ("heathcote_per_mm2", heathcote_per_mm2),
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
    // mm, mm^2 and MPa (N/mm^2): the traction times the area is in N.
    let field = |f: fn(&Element) -> f64, scale: f64| -> PyResult<Bound<'py, PyAny>> {
        let v: Vec<f64> = elements.iter().map(|e| f(e) * scale).collect();
        Ok(v.into_pyarray(py).reshape([n, n])?.into_any())
    };
    d.set_item("x_mm", field(|e| e.x_m, 1e3)?)?;
    d.set_item("y_mm", field(|e| e.y_m, 1e3)?)?;
    d.set_item("area_mm2", field(|e| e.area_m2, 1e6)?)?;
    d.set_item("traction_x_mpa", field(|e| e.traction_x_pa, 1e-6)?)?;
    d.set_item("traction_y_mpa", field(|e| e.traction_y_pa, 1e-6)?)?;
    d.set_item("bound_mpa", field(|e| e.bound_pa, 1e-6)?)?;
    d.set_item("slip_x", field(|e| e.slip_x, 1.0)?)?;
    d.set_item("slip_y", field(|e| e.slip_y, 1.0)?)?;
    let sliding: Vec<bool> = elements.iter().map(|e| e.sliding).collect();
    d.set_item("sliding", sliding.into_pyarray(py).reshape([n, n])?)?;
    Ok(d)
}
