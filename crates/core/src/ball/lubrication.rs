//! The lubricated raceway contacts of one ball: the EHL film of each contact
//! ([`crate::contact::ehl`]) at the ball's nominal normal load and rolling speed, and what it
//! sets in the ball's balance (docs/model-notes.md item 22):
//!
//! - the bound of Eq. (24) is the mixed-lubrication friction coefficient of the contact,
//!   `mu = phi mu_bl + (1 - phi) mu_EHL`, `phi = exp(-B Lambda^C)`;
//! - a rolling resistance, the EHL (Fujiwara) force times the thermal and starvation factors
//!   plus the elastic hysteresis force (Johnson), acts on the ball through its centre along the
//!   entrainment velocity of the contact. Pressure acts normal to the ball's surface, so the
//!   resultant of the film's pressure passes through the ball centre; the raceway carries the
//!   equal and opposite force on the same line. Its power is that force times the speed of the
//!   ball centre over the raceway, which the ball's balance counts with the creep forces'
//!   (so the energy and the moment route still agree);
//! - the hysteresis force, speed-independent, takes the standstill factor of the creep forces
//!   (docs/model-notes.md item 13); the EHL force vanishes with the speed by itself.
//!
//! The film is evaluated once per solve, not in every Newton step: at the nominal normal load
//! `Q = P / (sin(beta) cos(alpha))` and at the entrainment speed of the ball rolling without
//! slip, `u = |omega| (r_m^2 - (r_b cos(beta))^2) / (2 r_m cos(alpha))`. The balance departs
//! from both by a few per cent (the film goes as `Q^-0.067 u^0.67`), and the rolling ball's
//! slide-to-roll ratio is 0 in the thermal factor.
//!
//! What the film laws take from a raceway contact's Hertz shape and the oil, unchanged by load
//! and speed, is computed once, when the model builds the raceway's setup ([`film_constants`],
//! [`crate::ball::setup::RacewaySetup::film`]); what they take from the load and the speed,
//! once per ball for both its contacts, which carry the same load at the same speed
//! ([`ehl::SpeedLoadPowers`]; the module documentation of [`crate::contact::ehl`]).
//!
//! [`BallFilms`] gives the control-loop evaluator the same friction, to the bit, for the many
//! balls of one call: what the speed sets once per call ([`FilmSpeed`]), per ball only what
//! its load sets (one logarithm and cube root of the load, two powers, and per contact the
//! central film's friction; not the minimum film and the groups of the report).
//! `no_std`, no allocation.

use crate::ball::setup::{BallSetup, ContactFriction, RacewaySetup};
use crate::contact::ehl::{self, EhlContact, EhlInput, FilmConstants, FilmFriction, SpeedLoadPowers, SpeedPowers};
use crate::contact::hertz::{self, HertzContact};
use crate::input::lubricant::{Lubricant, OilState};

/// Entrainment speed `(u_ball + u_raceway) / 2` relative to the contact per unit screw speed of
/// a ball rolling without slip, m/rad: `(r_m^2 - (r_b cos(beta))^2) / (2 r_m cos(alpha))`, the
/// same at both contacts. The orbit turns at `(1 - r_b cos(beta) / r_m) / 2` of the screw's
/// speed, so the nut moves under its contact (radius `r_m + r_b cos(beta)`) at that rate and
/// the screw under its own (`r_m - r_b cos(beta)`) at the rest; along the helix over
/// `cos(alpha)`.
pub fn rolling_entrainment_m(s: &BallSetup) -> f64 {
    let c = s.rb_m * libm::cos(s.contact_angle_rad);
    (s.rm_m * s.rm_m - c * c) / (2.0 * s.rm_m * libm::cos(s.helix_angle_rad))
}

/// The two raceway contacts' films of one ball.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LubricatedContacts {
    /// Screw contact.
    pub screw: EhlContact,
    /// Nut contact.
    pub nut: EhlContact,
    /// Entrainment speed of both contacts, m/s.
    pub rolling_speed_m_s: f64,
}

/// The constants of the film laws of raceway contact `rs` with oil `oil`
/// ([`ehl::FilmConstants`]): the ellipticity is its Hertz shape's, the same at every load.
pub fn film_constants(rs: &RacewaySetup, oil: &OilState) -> FilmConstants {
    let unit = rs.shape.contact(1.0);
    let ellipticity = unit.semi_axis_lateral_m / unit.semi_axis_rolling_m;
    FilmConstants::new(rs.rolling_radius_m, rs.shape.effective_modulus_pa(), ellipticity, oil)
}

/// The film of raceway contact `rs` of ball `s` carrying the normal load `load_n` (N) at screw
/// speed `speed_rad_s` (its sign is ignored): a contact whose load is not the ball's nominal
/// one (a four-point ball's, [`crate::ball::four_point`]).
pub fn contact_film(
    s: &BallSetup,
    rs: &RacewaySetup,
    lubricant: &Lubricant,
    oil: &OilState,
    speed_rad_s: f64,
    load_n: f64,
) -> EhlContact {
    let u = libm::fabs(speed_rad_s) * rolling_entrainment_m(s);
    let constants = constants_of(rs, oil);
    film_at(rs, &constants, &SpeedLoadPowers::new(u, load_n, &constants), lubricant, oil, u, load_n)
}

/// The film constants of raceway contact `rs` with oil `oil`: those it carries
/// ([`RacewaySetup::film`], the model's oil's) when they are `oil`'s, else computed here.
fn constants_of(rs: &RacewaySetup, oil: &OilState) -> FilmConstants {
    rs.film.filter(|f| f.is_for(oil)).unwrap_or_else(|| film_constants(rs, oil))
}

/// The film of raceway contact `rs` of film constants `constants` at entrainment speed
/// `speed_m_s` and load `q`, whose powers are `powers`.
fn film_at(
    rs: &RacewaySetup,
    constants: &FilmConstants,
    powers: &SpeedLoadPowers,
    lubricant: &Lubricant,
    oil: &OilState,
    speed_m_s: f64,
    q: f64,
) -> EhlContact {
    ehl::analyse_with(&input_at(rs, &rs.shape.contact(q), q, speed_m_s), constants, powers, lubricant, oil)
}

/// The input of the film laws at raceway contact `rs`, whose Hertz contact is `hz` at load `q`
/// (N), at entrainment speed `speed_m_s` (m/s) of a rolling ball.
fn input_at(rs: &RacewaySetup, hz: &HertzContact, q: f64, speed_m_s: f64) -> EhlInput {
    EhlInput {
        load_n: q,
        radius_rolling_m: rs.rolling_radius_m,
        semi_axis_rolling_m: hz.semi_axis_rolling_m,
        semi_axis_lateral_m: hz.semi_axis_lateral_m,
        peak_pressure_pa: hz.peak_pressure_pa,
        effective_modulus_pa: rs.shape.effective_modulus_pa(),
        rolling_speed_m_s: speed_m_s,
        slide_to_roll: 0.0,
    }
}

/// The films of the raceway contacts of ball `s` lubricated by `lubricant` (state `oil` at its
/// temperature) at screw speed `speed_rad_s` (its sign is ignored). Both contacts carry the
/// ball's nominal load at one entrainment speed, so the powers of speed and load are taken once.
pub fn films(s: &BallSetup, lubricant: &Lubricant, oil: &OilState, speed_rad_s: f64) -> LubricatedContacts {
    let u = libm::fabs(speed_rad_s) * rolling_entrainment_m(s);
    let q = s.nominal_load_n();
    let (screw, nut) = (constants_of(&s.screw, oil), constants_of(&s.nut, oil));
    let powers = SpeedLoadPowers::new(u, q, &screw);
    LubricatedContacts {
        screw: film_at(&s.screw, &screw, &powers, lubricant, oil, u, q),
        nut: film_at(&s.nut, &nut, &powers, lubricant, oil, u, q),
        rolling_speed_m_s: u,
    }
}

/// The friction a contact's film `c` sets in the balance, the hysteresis force scaled by the
/// standstill factor `factor`.
pub fn contact_friction(c: &EhlContact, factor: f64) -> ContactFriction {
    film_friction(
        &FilmFriction {
            friction_coefficient: c.friction_coefficient,
            rolling_resistance_ehl_n: c.rolling_resistance_ehl_n,
            rolling_resistance_hysteresis_n: c.rolling_resistance_hysteresis_n,
        },
        factor,
    )
}

/// The friction `f` of a film sets in the balance, the hysteresis force scaled by the
/// standstill factor `factor`.
fn film_friction(f: &FilmFriction, factor: f64) -> ContactFriction {
    ContactFriction {
        mu: f.friction_coefficient,
        rolling_resistance_ehl_n: f.rolling_resistance_ehl_n,
        rolling_resistance_hysteresis_n: factor * f.rolling_resistance_hysteresis_n,
    }
}

/// The friction of a ball's lubricated raceway contacts at any load and speed, as [`lubricate`]
/// sets it (the same numbers, to the bit), with what the ball's geometry and the oil fix
/// computed once (see the module's documentation). The same for both flanks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallFilms {
    /// Entrainment speed per unit screw speed, m/rad ([`rolling_entrainment_m`]).
    entrainment_m: f64,
    /// `sin(beta) cos(alpha)`: axial load over nominal normal load.
    axial_per_nominal: f64,
    screw: (RacewaySetup, FilmConstants),
    nut: (RacewaySetup, FilmConstants),
    lubricant: Lubricant,
}

/// What a screw speed sets in the films of every ball ([`BallFilms::speed`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmSpeed {
    /// Entrainment speed, m/s.
    speed_m_s: f64,
    powers: SpeedPowers,
}

impl BallFilms {
    /// The films of the balls of setup `s` (its load and flank are not read) lubricated by
    /// `lubricant` in state `oil`.
    pub fn new(s: &BallSetup, lubricant: &Lubricant, oil: &OilState) -> Self {
        Self {
            entrainment_m: rolling_entrainment_m(s),
            axial_per_nominal: s.axial_per_nominal(),
            screw: (s.screw, constants_of(&s.screw, oil)),
            nut: (s.nut, constants_of(&s.nut, oil)),
            lubricant: *lubricant,
        }
    }

    /// What screw speed `speed_rad_s` (its sign ignored) sets in every ball's films.
    pub fn speed(&self, speed_rad_s: f64) -> FilmSpeed {
        let u = libm::fabs(speed_rad_s) * self.entrainment_m;
        FilmSpeed { speed_m_s: u, powers: SpeedPowers::new(u, &self.screw.1) }
    }

    /// The friction of the (screw, nut) contacts of a ball carrying axial load `axial_load_n`
    /// (N) at the speed of `speed`, the hysteresis forces scaled by the standstill factor
    /// `factor`.
    pub fn friction(&self, speed: &FilmSpeed, axial_load_n: f64, factor: f64) -> (ContactFriction, ContactFriction) {
        let q = axial_load_n / self.axial_per_nominal;
        let powers = SpeedLoadPowers::at(&speed.powers, q);
        // Both contacts' Hertz ellipses from one cube root of the load.
        let positive = q > 0.0;
        let q13 = if positive { hertz::cbrt(q) } else { 0.0 };
        let one = |(rs, constants): &(RacewaySetup, FilmConstants)| {
            let hz = if positive { rs.shape.contact_at_cube_root(q13) } else { HertzContact::default() };
            let input = input_at(rs, &hz, q, speed.speed_m_s);
            film_friction(&ehl::balance_friction(&input, constants, &powers, &self.lubricant), factor)
        };
        (one(&self.screw), one(&self.nut))
    }
}

/// Sets in ball `s` the friction of its lubricated raceway contacts at screw speed
/// `speed_rad_s` with standstill factor `factor`; returns the films. The ball-ball contacts keep
/// `friction.coefficient` (a parameter, like their load).
pub fn lubricate(
    s: &mut BallSetup,
    lubricant: &Lubricant,
    oil: &OilState,
    speed_rad_s: f64,
    factor: f64,
) -> LubricatedContacts {
    let f = films(s, lubricant, oil, speed_rad_s);
    s.screw.friction = contact_friction(&f.screw, factor);
    s.nut.friction = contact_friction(&f.nut, factor);
    f
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Model, ScrewSpec};

    /// A ball's raceways carry the film constants of the model's oil; films of the same ball
    /// with another oil (the oil at 60 instead of 40 degrees C) are that oil's, as from
    /// raceways that carry none, and not the model's oil's.
    #[test]
    fn films_with_another_oil_do_not_take_the_carried_constants() {
        let mut spec = ScrewSpec::dkfzd4012();
        spec.lubricant.temperature_c = 40.0;
        let model = Model::new(&spec).unwrap();
        let s = model.ball_setup_for(250.0, 1.0);
        assert!(s.screw.film.is_some() && s.nut.film.is_some());
        let mut bare = s;
        (bare.screw.film, bare.nut.film) = (None, None);
        let mut warmer = spec.lubricant;
        warmer.temperature_c = 60.0;
        let (oil, oil60) = (spec.lubricant.state(), warmer.state());
        let w = 10.0;
        let carried = films(&s, &warmer, &oil60, w);
        assert_eq!(carried, films(&bare, &warmer, &oil60, w));
        assert_ne!(carried.screw.film_central_m, films(&s, &spec.lubricant, &oil, w).screw.film_central_m);
        assert_eq!(films(&s, &spec.lubricant, &oil, w), films(&bare, &spec.lubricant, &oil, w));
    }

    /// `BallFilms` sets the same friction as `lubricate`, to the bit: the default oil, and one
    /// starved, hot and with a thermal loading (every branch of the film laws), over loads from
    /// a light ball to the static capacity, both flanks, speeds through standstill and
    /// standstill factors.
    #[test]
    fn ball_films_are_lubricates_friction_to_the_bit() {
        let mut starved = ScrewSpec::dkfzd4012();
        starved.lubricant.inlet_distance_ratio = Some(3.0);
        starved.lubricant.temperature_c = 70.0;
        for spec in [ScrewSpec::dkfzd4012(), starved] {
            let model = Model::new(&spec).unwrap();
            let oil = model.oil().copied().unwrap();
            let films = BallFilms::new(&model.ball_setup_for(1.0, 1.0), &spec.lubricant, &oil);
            let mut compared = 0;
            for &speed in &[-300.0, -1e-3, 0.0, 2e-4, 0.7, 10.5, 104.7, 314.2] {
                let at = films.speed(speed);
                for &load in &[0.0, 0.02, 0.5, 3.3, 31.0, 250.0, 2222.2, 2.0e4] {
                    for flank in [1.0, -1.0] {
                        for factor in [1.0, 0.37] {
                            let mut s = model.ball_setup_for(load, flank);
                            lubricate(&mut s, &spec.lubricant, &oil, speed, factor);
                            let (screw, nut) = films.friction(&at, load, factor);
                            let bits = |c: &ContactFriction| {
                                [c.mu, c.rolling_resistance_ehl_n, c.rolling_resistance_hysteresis_n].map(f64::to_bits)
                            };
                            assert_eq!(
                                [bits(&screw), bits(&nut)],
                                [bits(&s.screw.friction), bits(&s.nut.friction)],
                                "{speed} rad/s, {load} N"
                            );
                            compared += 1;
                        }
                    }
                }
            }
            assert_eq!(compared, 256);
        }
    }
}
