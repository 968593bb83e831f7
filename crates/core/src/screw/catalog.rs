//! The manufacturers' catalog estimate of preload drag torque, for comparison with the model:
//! T = K Fp L / (2 pi) with K = 0.05 / sqrt(tan alpha) (docs/reference/catalog_drag_torque.csv),
//! quoted with a tolerance band of roughly +-30-50 %.

use crate::input::Geometry;
use core::f64::consts::PI;

/// The catalog's preload-torque coefficient K = 0.05 / sqrt(tan alpha).
pub fn preload_torque_coefficient(g: &Geometry) -> f64 {
    0.05 / libm::sqrt(g.lead_m / (PI * g.pitch_diameter_m))
}

/// Catalog estimate of the preload drag torque, N m, for preload `preload_n` (N).
pub fn drag_torque_nm(g: &Geometry, preload_n: f64) -> f64 {
    preload_torque_coefficient(g) * preload_n * g.lead_m / (2.0 * PI)
}

/// Relative half-width of the band manufacturers quote around the estimate (the wider, 50 %).
pub const BAND_RELATIVE: f64 = 0.5;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::ScrewSpec;

    #[test]
    fn matches_reference_catalog_table() {
        // docs/reference/catalog_drag_torque.csv: K = 0.1618; 500 N -> 0.1545, 2000 N -> 0.6180,
        // 3000 N -> 0.9271 N m.
        let g = ScrewSpec::dkfzd4012().geometry;
        assert!((preload_torque_coefficient(&g) - 0.1618).abs() < 5e-5);
        for &(fp, t) in &[(500.0, 0.1545), (2000.0, 0.6180), (3000.0, 0.9271)] {
            assert!((drag_torque_nm(&g, fp) - t).abs() < 5e-5, "{fp}");
        }
    }
}
