//! How the balls circulate: the return that closes each circuit, the loaded turns a circuit
//! holds and the return path's resistance. What the ball train ([`crate::screw::train`]) is
//! built from.
//!
//! # Returns (HIWIN ballscrews catalogue, "Nut configuration"; Steinmeyer, "Ball return")
//!
//! - `internal`: a deflector (return cap) in the nut lifts the balls over the screw's land into
//!   the previous groove: every circuit is one loaded turn ("the balls make only one revolution
//!   around the screw spindle").
//! - `external`: a return tube outside the nut, or a bore through the nut with end caps: the
//!   balls "traverse the whole circuit of the balltracks": a circuit holds several loaded turns.
//!
//! # Defaults, and what they assume
//!
//! - `turns_per_circuit`: 1 (internal); every circle of the nut (external).
//!
//! The train of a circuit of several loaded turns (whose circles carry different loads, so
//! that their balls' free orbit rates differ and the faster push the slower) is balanced as one
//! ([`crate::screw::circuit`]): by the model, for two-point balls with linear-saturated
//! contacts (not the real-time evaluator, nor the reversal model, which refuse it); at some
//! points it has no steady state, which is an error ([`crate::Error::NoSteadyTrain`]). A circle
//! too light to carry the train is left out of its circuit's balance, and a circuit left with
//! one loaded circle gets the train of one turn. Every ball of a circuit carries its circle's
//! load up to the return (no load ramp at a deflector or tube), and every ball of a circle the
//! same load (no diameter variation between balls), unless a load ramp is stated:
//! - `load_ramp_balls`: the balls at each end of a circuit's loaded zone (where the balls enter
//!   it from the return and leave it for the return) whose load ramps between zero at the
//!   return and the full load of their circle: ball `k` of `m`, counted from the return, carries
//!   `k / (m + 1)` of it (a linear ramp over `m + 1` ball spacings). 0, by default: every ball of
//!   the loaded zone carries its circle's load up to the return. The circle keeps its share of
//!   the nut's load, so its other balls carry more ([`crate::screw::model::Model`]). No standard
//!   or catalogue states the length of a ramp; a nut's drawing (the relief of the raceway at a
//!   deflector or tube) does. Each ball of a ramp is a segment of its circuit's balance
//!   ([`crate::screw::circuit`]), so a ramp is solved by the model (not the real-time
//!   evaluator, the reversal model, FASTSIM contacts or four-point balls, which refuse it).
//! - `lead_deviation_m` (the file's `lead_deviation_um`): the screw's lead deviation between a
//!   nut's first and last circle, which moves load between the nut's circles
//!   ([`crate::screw::load::shares_with_lead_deviation`]); 0, the nominal lead, by default.
//!   ISO 3408-3 allows a travel variation within 300 mm (v_300p) of 12, 23 and 52 um for
//!   tolerance classes 3, 5 and 7: a share of it in proportion to the length between the nut's
//!   first and last circle is an estimate of the misfit. Not with oversize balls; the real-time evaluator leaves it to the
//!   model.
//! - `spacer_balls`: a smaller spacer ball between each two load-carrying balls (false by
//!   default: the balls touch). Neighbouring load balls turn the same way, so their surfaces
//!   slide at their contact; a spacer turns the other way and rolls on both, as a ball of the
//!   return does on its neighbour: the contacts carry the chain force and no friction. The
//!   spacers carry no raceway load (`geometry.balls_per_circle` counts the load balls), and
//!   `return_balls` counts every ball of the return, spacers included.
//! - `return_balls`: the balls in the return path: 2 for an internal deflector (the crossover
//!   over the land is about two ball diameters long), for an external return the balls that fill
//!   a path of the circuit's loaded length (turns x lead) plus two bends of the pitch radius
//!   (each a quarter circle): an estimate of the path, not a measured one.
//! - `return_friction`: the wall friction of a ball in the return; absent, the full-film
//!   traction of the lubricant (lubricated model) or the spec's friction coefficient (dry
//!   model): a lightly loaded ball moving over an oil-wetted wall at the train's speed carries
//!   a film (unlike neighbouring balls, whose contact has no entrainment). With the boundary
//!   value instead (0.15) the return's pull at light preloads and high speeds exceeds what the
//!   balls' films can transmit (DKFZD4012 at 25 N, 2500 rpm): no steady state rolls it.
//!
//! The return's resistance on a circuit is `R = mu_w n_r m (g + v^2 / r_m)`: wall friction on
//! each return ball's weight (the axis taken horizontal, the whole weight on the wall) and on its
//! centripetal force in a bend of the pitch radius `r_m`, `m = rho_steel pi D_w^3 / 6` with
//! `rho_steel = 7.81e3 kg/m^3` (100Cr6 bearing steel, ISO 683-17), at the train's speed
//! `v = omega_c sqrt(r_m^2 + (L / 2 pi)^2)` with the orbit rate of pure rolling
//! `omega_c / omega = (1 - D_w cos(beta) / d_m) / 2`. The oil's drag on a ball in the tube
//! (Stokes, `3 pi eta D_w v`: 0.3 mN for VG 68 at 0.1 m/s) is left out: below the wall friction's
//! estimate at every speed of the default screw.

use crate::error::{InputError, check_range};
use crate::input::geometry::Geometry;

/// Most loaded turns per circuit: a nut's most circles (the spec's `MAX_CIRCLES_PER_NUT`).
pub const MAX_TURNS_PER_CIRCUIT: u32 = 16;
/// Most balls in a circuit's return path.
pub const MAX_RETURN_BALLS: u32 = 1000;
/// Valid loaded turns per circuit: [1, [`MAX_TURNS_PER_CIRCUIT`]].
pub const TURNS_PER_CIRCUIT_RANGE: (f64, f64) = (1.0, MAX_TURNS_PER_CIRCUIT as f64);
/// Valid balls in a return path: [0, [`MAX_RETURN_BALLS`]].
pub const RETURN_BALLS_RANGE: (f64, f64) = (0.0, MAX_RETURN_BALLS as f64);
/// Valid wall friction coefficients of a ball in the return: [0, 1].
pub const RETURN_FRICTION_RANGE: (f64, f64) = (0.0, 1.0);
/// Density of the balls' steel, kg/m^3 (100Cr6, ISO 683-17).
pub const BALL_DENSITY_KG_M3: f64 = 7.81e3;
/// Valid lead deviations over a nut's loaded length, m: [-100, 100] um (ISO 3408-3's widest
/// travel variation over 300 mm, class 10's 210 um, is about 30 um over a 40 mm nut).
pub const LEAD_DEVIATION_RANGE_M: (f64, f64) = (-100e-6, 100e-6);
/// Most balls of a load ramp at each end of a circuit's loaded zone.
pub const MAX_LOAD_RAMP_BALLS: u32 = 4;
/// Valid balls of a load ramp: [0, [`MAX_LOAD_RAMP_BALLS`]] (and fewer than half a circle's
/// balls, [`crate::screw::model::Model::new`]).
pub const LOAD_RAMP_BALLS_RANGE: (f64, f64) = (0.0, MAX_LOAD_RAMP_BALLS as f64);
/// Standard gravity, m/s^2.
pub const GRAVITY_M_S2: f64 = 9.80665;

/// The return that closes a circuit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize), serde(rename_all = "kebab-case"))]
pub enum Return {
    /// A deflector in the nut: one loaded turn per circuit.
    #[default]
    Internal,
    /// A tube outside the nut or a bore with end caps: several loaded turns per circuit.
    External,
}

impl Return {
    /// Both returns, in the order of the spec's documentation.
    pub const ALL: [Return; 2] = [Return::Internal, Return::External];

    /// The name in a spec file: `internal`, `external`.
    pub fn name(&self) -> &'static str {
        match self {
            Return::Internal => "internal",
            Return::External => "external",
        }
    }

    /// The return named `name` (see [`Return::name`]).
    pub fn from_name(name: &str) -> Option<Return> {
        Return::ALL.into_iter().find(|r| r.name() == name)
    }
}

/// How the balls circulate (the module's documentation). `None` fields take the defaults.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Circulation {
    /// The return.
    pub kind: Return,
    /// Loaded turns (circles) per circuit; `None`: 1 (internal), the nut's circles (external).
    pub turns_per_circuit: Option<u32>,
    /// Balls in a circuit's return path; `None`: the module's estimate.
    pub return_balls: Option<u32>,
    /// Wall friction coefficient of a ball in the return; `None`: the full-film traction (dry:
    /// the spec's coefficient).
    pub return_friction: Option<f64>,
    /// The screw's lead deviation between a nut's first and last circle, m: the axial misfit of
    /// its last circle against its first, which moves load between the circles
    /// ([`crate::screw::load::shares_with_lead_deviation`]); 0: the nominal lead. Positive: the
    /// circles away from a nut's most loaded one gain approach.
    pub lead_deviation_m: f64,
    /// Balls of the load ramp at each end of a circuit's loaded zone: ball `k` of `m`, counted
    /// from the return, carries `k / (m + 1)` of its circle's full load; 0: no ramp.
    pub load_ramp_balls: u32,
    /// Whether a smaller spacer ball sits between each two load-carrying balls: it turns the other
    /// way and rolls on both neighbours, so the contacts between balls carry the chain force but
    /// no friction ([`crate::screw::model::Model::ball_ball_mu`]); false: the balls touch.
    pub spacer_balls: bool,
}

impl Circulation {
    /// Loaded turns per circuit in a nut of `circles` circles (the last circuit of a nut takes
    /// what is left).
    pub fn turns(&self, circles: u32) -> u32 {
        match (self.kind, self.turns_per_circuit) {
            (_, Some(t)) => t.min(circles.max(1)),
            (Return::Internal, None) => 1,
            (Return::External, None) => circles.max(1),
        }
    }

    /// Balls in a circuit's return path of `turns` loaded turns (the module's default when not
    /// stated).
    pub fn return_balls_for(&self, g: &Geometry, turns: u32) -> u32 {
        self.return_balls.unwrap_or_else(|| match self.kind {
            Return::Internal => 2,
            Return::External => {
                let path = f64::from(turns) * g.lead_m + core::f64::consts::PI * 0.5 * g.pitch_diameter_m;
                libm::ceil(path / g.ball_diameter_m) as u32
            }
        })
    }

    /// Checks each field's range; the first one out of range is returned. (Whether the model
    /// solves the circuit is [`crate::screw::model::Model::new`]'s to say.)
    pub fn validate(&self) -> Result<(), InputError> {
        if let Some(t) = self.turns_per_circuit {
            let (lo, hi) = TURNS_PER_CIRCUIT_RANGE;
            check_range(
                "circulation.turns_per_circuit",
                f64::from(t),
                lo,
                false,
                hi,
                false,
                "an integer in [1, 16]: 1 for an internal return",
            )?;
        }
        if let Some(n) = self.return_balls {
            let (lo, hi) = RETURN_BALLS_RANGE;
            check_range("circulation.return_balls", f64::from(n), lo, false, hi, false, "an integer in [0, 1000]")?;
        }
        if let Some(mu) = self.return_friction {
            let (lo, hi) = RETURN_FRICTION_RANGE;
            check_range("circulation.return_friction", mu, lo, false, hi, false, "[0, 1]")?;
        }
        let (lo, hi) = LEAD_DEVIATION_RANGE_M;
        check_range("circulation.lead_deviation_m", self.lead_deviation_m, lo, false, hi, false, "[-1e-4, 1e-4] m")?;
        let (lo, hi) = LOAD_RAMP_BALLS_RANGE;
        check_range(
            "circulation.load_ramp_balls",
            f64::from(self.load_ramp_balls),
            lo,
            false,
            hi,
            false,
            "an integer in [0, 4]",
        )?;
        Ok(())
    }
}

/// The return path's resistance on one circuit of `return_balls` balls (N): the module's
/// `R = mu_w n_r m (g + v^2 / r_m)` at screw speed `speed_rad_s` (rad/s), wall friction
/// `wall_friction`.
pub fn return_resistance_n(g: &Geometry, return_balls: u32, wall_friction: f64, speed_rad_s: f64) -> f64 {
    let d = g.ball_diameter_m;
    let rm = 0.5 * g.pitch_diameter_m;
    let h = g.lead_m / (2.0 * core::f64::consts::PI);
    let mass = BALL_DENSITY_KG_M3 * core::f64::consts::PI * d * d * d / 6.0;
    let orbit = 0.5 * (1.0 - d * libm::cos(g.contact_angle_rad) / g.pitch_diameter_m);
    let v = libm::fabs(speed_rad_s) * orbit * libm::sqrt(rm * rm + h * h);
    wall_friction * f64::from(return_balls) * mass * (GRAVITY_M_S2 + v * v / rm)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::ScrewSpec;

    #[test]
    fn defaults_follow_the_return() {
        let g = ScrewSpec::dkfzd4012().geometry;
        let internal = Circulation::default();
        assert_eq!(internal.turns(4), 1);
        assert_eq!(internal.return_balls_for(&g, 1), 2);
        let external = Circulation { kind: Return::External, ..Circulation::default() };
        assert_eq!(external.turns(4), 4);
        // 4 x 12 mm + pi x 20 mm = 110.8 mm of path over 5.953 mm balls: 19 balls.
        assert_eq!(external.return_balls_for(&g, 4), 19);
        assert!(internal.validate().is_ok() && external.validate().is_ok());
    }

    #[test]
    fn out_of_range_names_the_field() {
        let cases: [(Circulation, &str); 7] = [
            (Circulation { turns_per_circuit: Some(0), ..Default::default() }, "circulation.turns_per_circuit"),
            (
                Circulation { kind: Return::External, turns_per_circuit: Some(17), ..Default::default() },
                "circulation.turns_per_circuit",
            ),
            (Circulation { return_balls: Some(1001), ..Default::default() }, "circulation.return_balls"),
            (Circulation { return_friction: Some(f64::NAN), ..Default::default() }, "circulation.return_friction"),
            (Circulation { lead_deviation_m: 1.01e-4, ..Default::default() }, "circulation.lead_deviation_m"),
            (Circulation { lead_deviation_m: f64::NAN, ..Default::default() }, "circulation.lead_deviation_m"),
            (Circulation { load_ramp_balls: 5, ..Default::default() }, "circulation.load_ramp_balls"),
        ];
        for (c, field) in cases {
            assert_eq!(c.validate().unwrap_err().field, field);
        }
    }

    #[test]
    fn return_resistance_is_the_weight_at_standstill_and_grows_with_the_square_of_speed() {
        let g = ScrewSpec::dkfzd4012().geometry;
        let mass = BALL_DENSITY_KG_M3 * core::f64::consts::PI * g.ball_diameter_m.powi(3) / 6.0;
        let still = return_resistance_n(&g, 2, 0.15, 0.0);
        assert!((still - 0.15 * 2.0 * mass * GRAVITY_M_S2).abs() < 1e-15);
        let r1 = return_resistance_n(&g, 2, 0.15, 100.0) - still;
        let r2 = return_resistance_n(&g, 2, 0.15, 200.0) - still;
        assert!((r2 / r1 - 4.0).abs() < 1e-12);
        assert_eq!(return_resistance_n(&g, 2, 0.0, 300.0), 0.0);
    }
}
