//! The screw specification (SI units throughout) and its validation.
//!
//! A [`ScrewSpec`] holds the geometry and material of Table 1 of Xu et al. (2015), the friction
//! data, a default operating point and the model options of `docs/model-notes.md`. [`ScrewSpec::validate`]
//! rejects every value outside its physical range with an [`InputError`] that names the field,
//! the value and the valid range; nothing downstream panics on a spec that passed it.

use crate::error::{InputError, check_range};
use crate::input::circulation::Circulation;
use crate::input::extensions::Extensions;
use crate::input::geometry::{
    BALL_DIAMETER_RANGE_M, CONFORMITY_RANGE, CONTACT_ANGLE_RANGE_DEG, Geometry, LEAD_RANGE_M, PITCH_DIAMETER_RANGE_M,
    Preload, max_balls_per_circle,
};
use crate::input::lubricant::Lubricant;
use crate::input::operating::{OperatingPoint, rpm_to_rad_s};
use crate::input::options::{FASTSIM_GRID_RANGE, ModelOptions};
use crate::input::uncertainty::{INPUTS, SpreadError, Uncertainty, index};
use core::f64::consts::PI;

/// Most circles (turns of balls) per nut the fixed-size evaluation holds.
pub const MAX_CIRCLES_PER_NUT: usize = 16;
/// Most nuts: a single nut or a preloaded double nut.
pub const MAX_NUTS: usize = 2;

// Physical ranges of the material and friction data.
/// Young's modulus, Pa: [1, 1000] GPa (polymers' upper end to beyond tungsten carbide).
pub const YOUNGS_MODULUS_RANGE_PA: (f64, f64) = (1.0e9, 1.0e12);
/// Largest normal load between adjacent balls, N.
pub const MAX_BALL_BALL_LOAD_N: f64 = 1000.0;
/// Largest seal torque per nut, N m.
pub const MAX_SEAL_TORQUE_NM: f64 = 100.0;
/// Largest standstill speed, rad/s (100 rpm).
pub const MAX_STANDSTILL_SPEED_RAD_S: f64 = 100.0 * 2.0 * PI / 60.0;
/// Nuts: a single nut or a double nut, `[1, MAX_NUTS]`.
pub const NUTS_RANGE: (f64, f64) = (1.0, MAX_NUTS as f64);
/// Circles (turns of balls) per nut: `[1, MAX_CIRCLES_PER_NUT]`.
pub const CIRCLES_PER_NUT_RANGE: (f64, f64) = (1.0, MAX_CIRCLES_PER_NUT as f64);
/// Fewest balls of a circle (the most are as many as fit one turn of the helix,
/// [`max_balls_per_circle`]).
pub const MIN_BALLS_PER_CIRCLE: f64 = 1.0;
/// Poisson's ratio: [0, 0.5].
pub const POISSON_RATIO_RANGE: (f64, f64) = (0.0, 0.5);
/// Friction coefficient: [0.005, 1]. Below 0.005 every raceway contact of a DKFZD4012-like
/// screw is in full slip and the ball's balance degenerates (no unique attitude).
pub const FRICTION_COEFFICIENT_RANGE: (f64, f64) = (0.005, 1.0);
/// Normal load between adjacent balls, N: [0, [`MAX_BALL_BALL_LOAD_N`]].
pub const BALL_BALL_LOAD_RANGE_N: (f64, f64) = (0.0, MAX_BALL_BALL_LOAD_N);
/// Standstill speed, rad/s: (0, [`MAX_STANDSTILL_SPEED_RAD_S`]] (the lower end open).
pub const STANDSTILL_SPEED_RANGE_RAD_S: (f64, f64) = (0.0, MAX_STANDSTILL_SPEED_RAD_S);
/// Reduction factor on Kalker's creep coefficients: (0, 1] (the lower end open).
pub const CREEP_REDUCTION_RANGE: (f64, f64) = (0.0, 1.0);
/// Seal torque per nut, N m: [0, [`MAX_SEAL_TORQUE_NM`]].
pub const SEAL_TORQUE_RANGE_NM: (f64, f64) = (0.0, MAX_SEAL_TORQUE_NM);

/// Elastic constants of balls and raceways (one steel for both).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Young's modulus E, Pa: [`YOUNGS_MODULUS_RANGE_PA`].
    pub youngs_modulus_pa: f64,
    /// Poisson's ratio nu.
    pub poisson_ratio: f64,
}

impl Material {
    /// Shear modulus G of this material, Pa ([`shear_modulus_pa`]).
    pub fn shear_modulus_pa(&self) -> f64 {
        shear_modulus_pa(self.youngs_modulus_pa, self.poisson_ratio)
    }
}

/// Shear modulus `G = E / (2 (1 + nu))` of an isotropic material, Pa, from Young's modulus
/// `youngs_modulus_pa` (Pa) and Poisson's ratio `poisson_ratio`. No validation: NaN in, NaN out.
pub fn shear_modulus_pa(youngs_modulus_pa: f64, poisson_ratio: f64) -> f64 {
    youngs_modulus_pa / (2.0 * (1.0 + poisson_ratio))
}

/// Friction data of the contacts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Friction {
    /// Coulomb friction coefficient f of every contact (Table 1: 0.03).
    pub coefficient: f64,
    /// Normal load between adjacent balls Q_m, N, at most [`MAX_BALL_BALL_LOAD_N`]: an explicit
    /// override, the same load at every ball-ball contact (the paper's reading, docs/model-notes.md
    /// item 10). `None` (the default): the loads follow from the ball train of the spec's
    /// circulation ([`crate::screw::train`]).
    pub ball_ball_load_n: Option<f64>,
    /// Standstill speed omega0 of the screw, rad/s (docs/model-notes.md item 13): below it the creep
    /// forces are scaled by x (2 - x), x = |omega| / omega0, fading to zero at standstill; above
    /// it the model is untouched.
    pub standstill_speed_rad_s: f64,
    /// Reduction factor kappa on Kalker's creep coefficients, (0, 1] (1: dry contact as in the
    /// paper). Lubricated rolling contacts show a lower initial creep slope than Kalker's dry
    /// theory; the coefficients C11, C22, C23, C33 are multiplied by this factor.
    pub creep_reduction: f64,
    /// Drag torque of each nut's seals (wipers), N m, against the motion with the standstill
    /// factor (default 0: a screw without seals, or one whose seal drag is measured apart), at
    /// most [`MAX_SEAL_TORQUE_NM`]. Reported as its own share.
    pub seal_torque_per_nut_nm: f64,
}

/// A complete screw specification in SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScrewSpec {
    /// Geometry.
    pub geometry: Geometry,
    /// Material.
    pub material: Material,
    /// Friction data.
    pub friction: Friction,
    /// Default operating point (Table 1's operating conditions for DKFZD4012).
    pub operating: OperatingPoint,
    /// Model options.
    pub model: ModelOptions,
    /// The oil at the raceway contacts (used when `model.lubrication` is
    /// [`Lubrication::Ehl`](crate::input::options::Lubrication::Ehl), checked under either
    /// model; default: ISO VG 68 mineral oil at 40 degrees C, [`Lubricant::default`]).
    pub lubricant: Lubricant,
    /// Terms beyond the paper's physics (seals, lubricant, waviness, wear, ...), all off by
    /// default; see [`crate::input::extensions`].
    pub extensions: Extensions,
    /// How the balls circulate (default: an internal return, one loaded turn per circuit, no
    /// load ramp); see [`crate::input::circulation`].
    pub circulation: Circulation,
    /// The spread of the inputs nobody measures on a given screw (default: each input's
    /// documented half-width); the model does not read it: a band of predictions samples it.
    /// See [`crate::input::uncertainty`].
    pub uncertainty: Uncertainty,
}

impl ScrewSpec {
    /// The DKFZD4012 screw of Table 1 of Xu et al. (2015), with the contact angle (45 deg) and
    /// the split of its 152 balls (2 nuts x 4 circles x 19 balls) of docs/model-notes.md item 14.
    pub fn dkfzd4012() -> Self {
        Self {
            geometry: Geometry {
                pitch_diameter_m: 40.0e-3,
                lead_m: 12.0e-3,
                ball_diameter_m: 5.953e-3,
                conformity_screw: 0.52,
                conformity_nut: 0.52,
                contact_angle_rad: 45.0_f64.to_radians(),
                nuts: 2,
                circles_per_nut: 4,
                balls_per_circle: 19,
                preload: Preload::DoubleNut,
            },
            material: Material { youngs_modulus_pa: 210.0e9, poisson_ratio: 0.3 },
            friction: Friction {
                coefficient: 0.03,
                ball_ball_load_n: None,
                standstill_speed_rad_s: rpm_to_rad_s(0.1),
                creep_reduction: 1.0,
                seal_torque_per_nut_nm: 0.0,
            },
            operating: OperatingPoint { speed_rad_s: rpm_to_rad_s(100.0), preload_n: 2000.0, axial_load_n: 0.0 },
            model: ModelOptions::default(),
            lubricant: Lubricant::default(),
            extensions: Extensions::NONE,
            circulation: Circulation::default(),
            uncertainty: Uncertainty::DEFAULT,
        }
    }

    /// The spec and the operating point `op` moved to one sample of the spread of
    /// [`ScrewSpec::uncertainty`]: input `i` at `u[i]` of its half-width (`u[i]` in [-1, 1]; 0:
    /// the nominal value). An input the model does not read is moved too (it changes nothing).
    pub fn spread_to(&self, u: &[f64; INPUTS], op: &OperatingPoint) -> (ScrewSpec, OperatingPoint) {
        let (mut spec, mut op) = (*self, *op);
        let at = |i: usize| self.uncertainty.offset(i, u[i]);
        let l = &mut spec.lubricant;
        l.viscosity_40c_m2_s *= at(index::VISCOSITY);
        l.viscosity_100c_m2_s *= at(index::VISCOSITY);
        l.pressure_viscosity_per_pa *= at(index::PRESSURE_VISCOSITY);
        l.temperature_c += at(index::TEMPERATURE);
        l.roughness_ball_rq_m *= at(index::ROUGHNESS_BALL);
        l.roughness_raceway_rq_m *= at(index::ROUGHNESS_RACEWAY);
        l.boundary_friction += at(index::BOUNDARY_FRICTION);
        l.full_film_traction += at(index::FULL_FILM_TRACTION);
        op.preload_n *= at(index::PRELOAD);
        spec.friction.coefficient *= at(index::FRICTION_COEFFICIENT);
        (spec, op)
    }

    /// Checks that the spec at `op` is valid, and that each input the spec's model reads, at
    /// both ends of its spread (the others nominal), leaves it valid: what a band needs before
    /// it samples. (Not part of [`ScrewSpec::validate`]: a spec whose oil sits at the end of its
    /// range stays valid; only its band is refused.) The first failure: the nominal point's own
    /// error, or the input, the end and the value out of range.
    pub fn check_spread(&self, op: &OperatingPoint) -> Result<(), SpreadError> {
        let at = |spec: &ScrewSpec, op: &OperatingPoint| -> Result<(), InputError> {
            op.validate()?;
            ScrewSpec { operating: *op, ..*spec }.validate()
        };
        self.uncertainty.validate().map_err(SpreadError::Nominal)?;
        at(self, op).map_err(SpreadError::Nominal)?;
        for input in self.uncertainty.active(self.model.lubrication) {
            for end in [-1.0, 1.0] {
                let mut u = [0.0; INPUTS];
                u[input] = end;
                let (s, o) = self.spread_to(&u, op);
                at(&s, &o).map_err(|error| SpreadError::End {
                    input,
                    half_width: self.uncertainty.half_widths[input],
                    end,
                    error,
                })?;
            }
        }
        Ok(())
    }

    /// Helix (lead) angle alpha = atan(L / (pi d_m)), rad.
    pub fn helix_angle_rad(&self) -> f64 {
        libm::atan(self.geometry.lead_m / (PI * self.geometry.pitch_diameter_m))
    }

    /// Checks every field; the first one out of range is returned.
    pub fn validate(&self) -> Result<(), InputError> {
        let g = &self.geometry;
        let (lo, hi) = PITCH_DIAMETER_RANGE_M;
        check_range("geometry.pitch_diameter_m", g.pitch_diameter_m, lo, false, hi, false, "[0.003, 0.3] m")?;
        let (lo, hi) = LEAD_RANGE_M;
        check_range("geometry.lead_m", g.lead_m, lo, false, hi, false, "[0.0005, 0.2] m")?;
        let (lo, hi) = BALL_DIAMETER_RANGE_M;
        let ball = "[0.0005, 0.05] m and below pitch diameter / 2";
        check_range("geometry.ball_diameter_m", g.ball_diameter_m, lo, false, hi, false, ball)?;
        check_range("geometry.ball_diameter_m", g.ball_diameter_m, 0.0, true, 0.5 * g.pitch_diameter_m, true, ball)?;
        let (lo, hi) = CONFORMITY_RANGE;
        check_range("geometry.conformity_screw", g.conformity_screw, lo, false, hi, false, "[0.501, 0.6]")?;
        check_range("geometry.conformity_nut", g.conformity_nut, lo, false, hi, false, "[0.501, 0.6]")?;
        let (lo, hi) = CONTACT_ANGLE_RANGE_DEG;
        check_range(
            "geometry.contact_angle_rad",
            g.contact_angle_rad,
            lo.to_radians(),
            false,
            hi.to_radians(),
            false,
            "[20, 70] degrees (ball-screw grooves)",
        )?;
        let (lo, hi) = NUTS_RANGE;
        check_range("geometry.nuts", g.nuts as f64, lo, false, hi, false, "1 or 2")?;
        check_arrangement(g)?;
        let (lo, hi) = CIRCLES_PER_NUT_RANGE;
        check_range("geometry.circles_per_nut", g.circles_per_nut as f64, lo, false, hi, false, "integer in [1, 16]")?;
        let max_balls = max_balls_per_circle(g);
        check_range(
            "geometry.balls_per_circle",
            g.balls_per_circle as f64,
            MIN_BALLS_PER_CIRCLE,
            false,
            max_balls as f64,
            false,
            "integer >= 1, and the balls of a circle must fit one turn of the helix",
        )?;
        let m = &self.material;
        let (lo, hi) = YOUNGS_MODULUS_RANGE_PA;
        check_range("material.youngs_modulus_pa", m.youngs_modulus_pa, lo, false, hi, false, "[1e9, 1e12] Pa")?;
        let (lo, hi) = POISSON_RATIO_RANGE;
        check_range("material.poisson_ratio", m.poisson_ratio, lo, false, hi, false, "[0, 0.5]")?;
        let f = &self.friction;
        // Below 0.005 every raceway contact of a DKFZD4012-like screw is in full slip and the
        // ball's balance degenerates (no unique attitude): the model has no answer there.
        let (lo, hi) = FRICTION_COEFFICIENT_RANGE;
        check_range("friction.coefficient", f.coefficient, lo, false, hi, false, "[0.005, 1]")?;
        if let Some(q) = f.ball_ball_load_n {
            let (lo, hi) = BALL_BALL_LOAD_RANGE_N;
            check_range("friction.ball_ball_load_n", q, lo, false, hi, false, "[0, 1000] N")?;
        }
        let (lo, hi) = STANDSTILL_SPEED_RANGE_RAD_S;
        check_range(
            "friction.standstill_speed_rad_s",
            f.standstill_speed_rad_s,
            lo,
            true,
            hi,
            false,
            "(0, 10.47] rad/s, i.e. (0, 100] rpm",
        )?;
        let (lo, hi) = CREEP_REDUCTION_RANGE;
        check_range("friction.creep_reduction", f.creep_reduction, lo, true, hi, false, "(0, 1]")?;
        let (lo, hi) = SEAL_TORQUE_RANGE_NM;
        check_range("friction.seal_torque_per_nut_nm", f.seal_torque_per_nut_nm, lo, false, hi, false, "[0, 100] N m")?;
        // Under the dry model too: a value out of range is an error wherever it is written, not
        // only once `lubrication = "ehl"` uses it.
        self.lubricant.validate()?;
        self.extensions.validate()?;
        self.circulation.validate()?;
        self.uncertainty.validate()?;
        let (lo, hi) = FASTSIM_GRID_RANGE;
        check_range("model.fastsim_grid", self.model.fastsim_grid as f64, lo, false, hi, false, "integer in [4, 200]")?;
        self.operating.validate()?;
        check_preload_for(g.preload, self.operating.preload_n)?;
        Ok(())
    }
}

/// Checks that the nut count and circles suit the preload arrangement `g.preload`.
fn check_arrangement(g: &Geometry) -> Result<(), InputError> {
    let nuts = g.preload.nuts();
    if g.nuts != nuts {
        return Err(InputError {
            field: "geometry.nuts",
            value: g.nuts as f64,
            valid: match g.preload {
                Preload::DoubleNut => "2 for a double nut (geometry.preload = \"double-nut\")",
                _ => "1 for a single nut (geometry.preload = \"offset-lead\", \"oversize-ball\" or \"none\")",
            },
        });
    }
    if g.preload == Preload::OffsetLead && (g.circles_per_nut < 2 || !g.circles_per_nut.is_multiple_of(2)) {
        return Err(InputError {
            field: "geometry.circles_per_nut",
            value: g.circles_per_nut as f64,
            valid: "an even number >= 2 for an offset-lead nut (half of the circles in each half)",
        });
    }
    Ok(())
}

/// Checks a preload `preload_n` (N) against the arrangement `preload`: a nut without preload
/// arrangement (`none`) takes none.
pub fn check_preload_for(preload: Preload, preload_n: f64) -> Result<(), InputError> {
    if preload == Preload::None && preload_n != 0.0 {
        return Err(InputError {
            field: "preload_n",
            value: preload_n,
            valid: "0 N for a single nut without preload (geometry.preload = \"none\"); a preloaded \
                    single nut is \"oversize-ball\" or \"offset-lead\"",
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::options::*;

    fn field_of(spec: &ScrewSpec) -> &'static str {
        spec.validate().unwrap_err().field
    }

    #[test]
    fn dkfzd4012_is_valid() {
        assert_eq!(ScrewSpec::dkfzd4012().validate(), Ok(()));
    }

    #[test]
    fn every_bad_field_is_named_with_its_value_and_range() {
        let d = ScrewSpec::dkfzd4012();
        type Case = (fn(&mut ScrewSpec), &'static str);
        let cases: [Case; 16] = [
            (|s| s.geometry.pitch_diameter_m = f64::NAN, "geometry.pitch_diameter_m"),
            (|s| s.geometry.lead_m = -0.012, "geometry.lead_m"),
            (|s| s.geometry.lead_m = 0.0, "geometry.lead_m"),
            (|s| s.geometry.ball_diameter_m = 0.03, "geometry.ball_diameter_m"),
            (|s| s.geometry.conformity_screw = 0.5, "geometry.conformity_screw"),
            (|s| s.geometry.conformity_nut = 0.49, "geometry.conformity_nut"),
            (|s| s.geometry.contact_angle_rad = core::f64::consts::FRAC_PI_2, "geometry.contact_angle_rad"),
            (|s| s.geometry.contact_angle_rad = 0.0, "geometry.contact_angle_rad"),
            (|s| s.geometry.nuts = 3, "geometry.nuts"),
            (|s| s.geometry.circles_per_nut = 0, "geometry.circles_per_nut"),
            (|s| s.geometry.balls_per_circle = 30, "geometry.balls_per_circle"),
            (|s| s.material.poisson_ratio = 0.6, "material.poisson_ratio"),
            (|s| s.material.youngs_modulus_pa = f64::INFINITY, "material.youngs_modulus_pa"),
            (|s| s.friction.coefficient = 0.001, "friction.coefficient"),
            (|s| s.friction.ball_ball_load_n = Some(-1.0), "friction.ball_ball_load_n"),
            (|s| s.operating.preload_n = -5.0, "preload_n"),
        ];
        for (set, field) in cases {
            let mut s = d;
            set(&mut s);
            let e = s.validate().unwrap_err();
            assert_eq!(e.field, field);
            let text = std::format!("{e}");
            assert!(text.contains(field) && text.contains("valid"), "{text}");
        }
        let mut s = d;
        s.operating.speed_rad_s = 1e9;
        assert_eq!(field_of(&s), "speed_rad_s");
        // 22 balls do not fit one turn of DKFZD4012's helix (about 21 do: docs/model-notes.md item 14).
        let mut s = d;
        s.geometry.balls_per_circle = 22;
        assert_eq!(field_of(&s), "geometry.balls_per_circle");
    }

    /// The `[lubricant]` table is checked whatever the model: under `lubrication = "dry"`,
    /// which leaves the oil out, an oil at 4000 degrees C was once accepted without a word.
    #[test]
    fn the_lubricant_is_checked_under_the_dry_model_too() {
        for lubrication in [Lubrication::Ehl, Lubrication::Dry] {
            let mut s = ScrewSpec::dkfzd4012();
            s.model.lubrication = lubrication;
            assert_eq!(s.validate(), Ok(()));
            s.lubricant.temperature_c = 4000.0;
            assert_eq!(field_of(&s), "lubricant.temperature_c", "{lubrication:?}");
            s.lubricant.temperature_c = 40.0;
            s.lubricant.boundary_friction = 15.0;
            assert_eq!(field_of(&s), "lubricant.boundary_friction", "{lubrication:?}");
        }
    }

    #[test]
    fn values_beyond_the_physical_ranges_are_input_errors() {
        // Each of these once passed validation and then ended in "did not converge" (or was
        // accepted): now the validation names the field and gives its range.
        let d = ScrewSpec::dkfzd4012();
        type Case = (fn(&mut ScrewSpec), &'static str, &'static str);
        let cases: [Case; 14] = [
            (|s| s.geometry.lead_m = 1e297, "geometry.lead_m", "[0.0005, 0.2] m"),
            (|s| s.geometry.lead_m = 0.4e-3, "geometry.lead_m", "[0.0005, 0.2] m"),
            (|s| s.geometry.ball_diameter_m = 1e-12, "geometry.ball_diameter_m", "[0.0005, 0.05] m"),
            (|s| s.geometry.ball_diameter_m = 0.4e-3, "geometry.ball_diameter_m", "[0.0005, 0.05] m"),
            (|s| s.material.youngs_modulus_pa = 1e-291, "material.youngs_modulus_pa", "[1e9, 1e12] Pa"),
            (|s| s.material.youngs_modulus_pa = 1.1e12, "material.youngs_modulus_pa", "[1e9, 1e12] Pa"),
            (|s| s.friction.ball_ball_load_n = Some(1e300), "friction.ball_ball_load_n", "[0, 1000] N"),
            (|s| s.friction.ball_ball_load_n = Some(1000.5), "friction.ball_ball_load_n", "[0, 1000] N"),
            (|s| s.geometry.conformity_nut = 0.5000001, "geometry.conformity_nut", "[0.501, 0.6]"),
            (|s| s.geometry.conformity_screw = 0.6001, "geometry.conformity_screw", "[0.501, 0.6]"),
            (|s| s.geometry.pitch_diameter_m = 1e6, "geometry.pitch_diameter_m", "[0.003, 0.3] m"),
            (|s| s.geometry.pitch_diameter_m = 2.9e-3, "geometry.pitch_diameter_m", "[0.003, 0.3] m"),
            (|s| s.friction.standstill_speed_rad_s = 1e300, "friction.standstill_speed_rad_s", "100] rpm"),
            (
                |s| s.friction.standstill_speed_rad_s = rpm_to_rad_s(100.1),
                "friction.standstill_speed_rad_s",
                "100] rpm",
            ),
        ];
        for (set, field, valid) in cases {
            let mut s = d;
            set(&mut s);
            let e = s.validate().unwrap_err();
            assert_eq!(e.field, field);
            assert!(e.valid.contains(valid), "{field}: {}", e.valid);
        }
        // The ends of every range are valid.
        let mut s = d;
        s.friction.ball_ball_load_n = Some(MAX_BALL_BALL_LOAD_N);
        // A circuit holds at most a nut's circles.
        assert_eq!(crate::input::circulation::MAX_TURNS_PER_CIRCUIT as usize, MAX_CIRCLES_PER_NUT);
        s.friction.standstill_speed_rad_s = MAX_STANDSTILL_SPEED_RAD_S;
        s.material.youngs_modulus_pa = YOUNGS_MODULUS_RANGE_PA.1;
        s.geometry.conformity_screw = CONFORMITY_RANGE.0;
        s.geometry.conformity_nut = CONFORMITY_RANGE.1;
        s.geometry.lead_m = LEAD_RANGE_M.1;
        s.geometry.pitch_diameter_m = PITCH_DIAMETER_RANGE_M.1;
        s.geometry.ball_diameter_m = BALL_DIAMETER_RANGE_M.1;
        assert_eq!(s.validate(), Ok(()));
    }

    #[test]
    fn paper_literal_options_differ_from_the_default_in_every_switch() {
        let d = ModelOptions::default();
        let p = ModelOptions::paper_literal();
        assert_ne!(d.load_distribution, p.load_distribution);
        assert_ne!(d.creep_coefficients, p.creep_coefficients);
        assert_ne!(d.torque, p.torque);
        assert_ne!(d.spin_moment, p.spin_moment);
    }

    #[test]
    fn shear_modulus_of_steel() {
        // Table 1's steel, E = 210 GPa and nu = 0.3: G = E / (2 (1 + nu)) = 80.77 GPa.
        let m = ScrewSpec::dkfzd4012().material;
        assert!((m.shear_modulus_pa() * 1e-9 - 80.769_230_769).abs() < 1e-8);
        assert_eq!(m.shear_modulus_pa(), shear_modulus_pa(210e9, 0.3));
        assert_eq!(shear_modulus_pa(100e9, 0.0), 50e9);
    }
}
