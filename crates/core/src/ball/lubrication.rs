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
//! `no_std`, no allocation.

use crate::ball::setup::{BallSetup, ContactFriction, RacewaySetup};
use crate::contact::ehl::{self, EhlContact, EhlInput, FilmConstants, SpeedLoadPowers};
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
    let hz = rs.shape.contact(q);
    let input = EhlInput {
        load_n: q,
        radius_rolling_m: rs.rolling_radius_m,
        semi_axis_rolling_m: hz.semi_axis_rolling_m,
        semi_axis_lateral_m: hz.semi_axis_lateral_m,
        peak_pressure_pa: hz.peak_pressure_pa,
        effective_modulus_pa: rs.shape.effective_modulus_pa(),
        rolling_speed_m_s: speed_m_s,
        slide_to_roll: 0.0,
    };
    ehl::analyse_with(&input, constants, powers, lubricant, oil)
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
    ContactFriction {
        mu: c.friction_coefficient,
        rolling_resistance_ehl_n: c.rolling_resistance_ehl_n,
        rolling_resistance_hysteresis_n: factor * c.rolling_resistance_hysteresis_n,
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
}
