//! The balls of one call in groups of the SIMD lanes ([`crate::real::Real::Wide`]): each ball
//! prepared with its friction, load and first start ([`Evaluator::prepare`]), the balance at
//! every ball's first start evaluated in one pass of the lanes, then each ball solved and its
//! circle's torque summed ([`Evaluator::solve_group`]).

use super::api::{Evaluator, MAX_ITERATIONS};
use super::memory::{BallMemory, EvalState};
use super::stats;
use crate::ball::balance::{self, Constants, Load, Outcome};
use crate::ball::lubrication::FilmSpeed;
use crate::ball::setup::{ContactFriction, MIN_SOLVE_FACTOR, N};
use crate::ball::solve::{self};
use crate::contact::creep::standstill_factor;
use crate::error::Error;
use crate::input::geometry;
use crate::input::{MAX_CIRCLES_PER_NUT, MAX_NUTS, OperatingPoint, TorqueRoute};
use crate::real::{Lanes, Real};
use crate::screw::model::{Model, accepted_residual, carries_train};
use crate::screw::train::Circuit;

/// Per nut and circle, a circle's friction torque by mechanism ([`MECHANISMS`]), N m.
pub(crate) type Groups<F> = [[[F; MECHANISMS]; MAX_CIRCLES_PER_NUT]; MAX_NUTS];

/// The mechanisms of a circle's friction torque, in the order of [`Groups`]: the raceway
/// contacts' creep and sliding, their rolling resistance (EHL and hysteresis), the ball-ball
/// contacts.
pub(crate) const MECHANISMS: usize = 3;

/// What builds a ball's constants in f64 for f32's checks ([`Evaluator::settle_in_f64`],
/// [`Evaluator::broyden_refreshed`]), which most solves do not reach: a copy of the model's
/// constants with the films' friction, built for every ball, cost about a tenth of an f32 warm
/// call lubricated and a sixth dry.
#[derive(Clone, Copy)]
pub(super) struct Wide<'a> {
    pub(super) model: &'a Model,
    pub(super) flank: f64,
    /// The raceway contacts' friction (screw, nut) with lubricated contacts, `None` dry.
    pub(super) friction: Option<(ContactFriction, ContactFriction)>,
    /// The ball-ball contacts' loads of the call's train ([`Ball::train`]).
    pub(super) train: Option<Circuit>,
}

impl Wide<'_> {
    /// The constants in f64.
    pub(super) fn constants(&self) -> Constants<f64> {
        let c = match &self.friction {
            Some((screw, nut)) => self.model.lean_with(self.flank, screw, nut),
            None => self.model.lean_dry(self.flank),
        };
        with_train(c, &self.train)
    }
}

/// `c` with the ball-ball loads of the train `train` (solved turning forwards), if any.
pub(super) fn with_train<V: Lanes>(c: Constants<V>, train: &Option<Circuit>) -> Constants<V> {
    match train {
        Some(t) => {
            let ((plus, plus_f), (minus, minus_f)) = t.plus_minus(true);
            c.with_ball_ball_loads((plus, minus, plus_f, minus_f))
        }
        None => c,
    }
}

/// The most balls whose first evaluations share one pass of the lanes (f32's eight).
pub(super) const MAX_GROUP: usize = 8;

/// A ball of one call, ready for its solve ([`Evaluator::prepare`], [`Evaluator::solve_ball`]).
pub(super) struct Ball<F: Real> {
    pub(super) nut: usize,
    pub(super) circle: usize,
    /// Flank index as solved (turning forwards).
    pub(super) fi: usize,
    /// The ball's axial load, N.
    pub(super) p: F,
    /// The residual the model accepts for this ball ([`accepted_residual`]).
    pub(super) accept: f64,
    /// The raceway contacts' friction (screw, nut) from the films, with lubricated contacts.
    pub(super) friction: Option<(ContactFriction, ContactFriction)>,
    /// The ball's load turning forwards at the solve's standstill factor.
    pub(super) load: Load<F>,
    /// The call's standstill factor.
    pub(super) factor: F,
    /// The call's screw speed, rad/s.
    pub(super) speed_rad_s: f64,
    pub(super) first: First<F>,
    /// The ball evaluated at its first start, where the lanes did ([`Evaluator::solve_group`]).
    pub(super) evaluated: Option<Outcome<F>>,
    /// The ball train of the call: the loads between neighbouring balls and the return's
    /// resistance ([`Model::circuit`]); `None` where no contact carries load.
    pub(super) train: Option<Circuit>,
}

impl<F: Real> Ball<F> {
    /// The first start, if there is one.
    pub(super) fn start(&self) -> Option<[F; N]> {
        match self.first {
            First::Warm(x) | First::Table(x) => Some(x),
            First::None => None,
        }
    }
}

/// Where a ball's solve starts first.
#[derive(Clone, Copy)]
pub(super) enum First<F: Real> {
    /// Extrapolated from the ball's memory (with the remembered inverse Jacobian).
    Warm([F; N]),
    /// Interpolated in the table (with the table's inverse Jacobian, taken when it is solved).
    Table([F; N]),
    /// No start: no memory, no solved table entry.
    None,
}

impl<F: Real> Evaluator<F> {
    /// A ball of load `p` (N) on flank `fi` of nut `nut`, circle `circle`, ready for its solve
    /// ([`Evaluator::solve_ball`]): its constants and load, and its first start, from its
    /// `memory` where that gives one, else from the table. Reads `memory` only.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn prepare(
        &self,
        nut: usize,
        circle: usize,
        fi: usize,
        p: F,
        p_max: f64,
        film_speed: Option<&FilmSpeed>,
        factor: F,
        op: &OperatingPoint,
        memory: &BallMemory<F>,
        train: Option<Circuit>,
    ) -> Ball<F> {
        let friction = self.friction_at(p, film_speed, factor);
        let fk = factor.max(F::of(MIN_SOLVE_FACTOR));
        let speed = self.start_speed(op.speed_rad_s);
        let first = match memory.start(p, speed, fk) {
            Some(x) => First::Warm(x),
            None => match self.table.start(fi, p, None) {
                Some(x) => First::Table(solve::scale_friction_terms(&x, fk)),
                None => First::None,
            },
        };
        Ball {
            nut,
            circle,
            fi,
            p,
            accept: accepted_residual(p.to_f64(), p_max),
            friction,
            load: Load { axial_load_n: p, direction: F::one(), factor: fk },
            factor,
            speed_rad_s: op.speed_rad_s,
            first,
            evaluated: None,
            train: train.filter(|_| carries_train(p.to_f64(), p_max)),
        }
    }

    /// The friction of the (screw, nut) contacts of a ball of load `p` (N) at the films' speed
    /// `film_speed` ([`Evaluator::film_speed`]) with standstill factor `factor`, with
    /// lubricated contacts ([`BallFilms`]: the model's, to the bit, the films evaluated once
    /// per ball and call); `None` dry.
    pub(super) fn friction_at(
        &self,
        p: F,
        film_speed: Option<&FilmSpeed>,
        factor: F,
    ) -> Option<(ContactFriction, ContactFriction)> {
        let (films, speed) = (self.films.as_ref()?, film_speed?);
        Some(films.friction(speed, p.to_f64(), factor.to_f64()))
    }

    /// The constants of a ball on flank `fi` with the contacts' friction `friction`
    /// ([`Evaluator::friction_at`]; dry, the evaluator's own).
    pub(super) fn constants_with(
        &self,
        fi: usize,
        friction: &Option<(ContactFriction, ContactFriction)>,
    ) -> Constants<F> {
        match friction {
            Some((screw, nut)) => self.constants[fi].with_friction(screw, nut),
            None => self.constants[fi],
        }
    }

    /// The constants of `ball`, and in f32 what builds them in f64 (for the Jacobian of a
    /// refreshed start and the check of a solution, [`Evaluator::settle_in_f64`]; built only
    /// where one needs them, [`Wide`]).
    pub(super) fn ball_constants(&self, ball: &Ball<F>) -> (Constants<F>, Option<Wide<'_>>) {
        let flank = if ball.fi == 0 { 1.0 } else { -1.0 };
        let wide = (!F::FINITE_DIFFERENCES).then_some(Wide {
            model: &self.model,
            flank,
            friction: ball.friction,
            train: ball.train,
        });
        (with_train(self.constants_with(ball.fi, &ball.friction), &ball.train), wide)
    }

    /// Solves the balls of `group` (in order, each with its memory in `state`) and adds each
    /// circle's torque to `sum` (and its mechanisms to `groups`): the balance at every ball's
    /// first start evaluated in one pass of the lanes ([`Real::Wide`]: one ball a lane, each
    /// lane the single ball's result to the bit), then each ball's solve from there. Empties
    /// `group`; the first ball that finds no solution is the error.
    pub(super) fn solve_group(
        &self,
        group: &mut [Option<Ball<F>>],
        state: &mut EvalState<F>,
        direction: F,
        groups: &mut Option<&mut Groups<F>>,
        sum: &mut F,
    ) -> Result<(), Error> {
        let mut which = [0; MAX_GROUP];
        let mut k = 0;
        for (i, ball) in group.iter().enumerate() {
            if ball.as_ref().and_then(Ball::start).is_some() {
                which[k] = i;
                k += 1;
            }
        }
        if k > 1 {
            let mut constants = [&self.constants[0]; MAX_GROUP];
            let dry = ContactFriction::dry(0.0);
            let mut frictions = [(&dry, &dry); MAX_GROUP];
            let mut starts = [[F::zero(); N]; MAX_GROUP];
            let mut loads = [Load { axial_load_n: F::zero(), direction: F::zero(), factor: F::zero() }; MAX_GROUP];
            for (lane, &i) in which[..k].iter().enumerate() {
                if let Some(ball) = group[i].as_ref() {
                    constants[lane] = &self.constants[ball.fi];
                    if let Some((screw, nut)) = &ball.friction {
                        frictions[lane] = (screw, nut);
                    }
                    (starts[lane], loads[lane]) = (ball.start().unwrap_or_default(), ball.load);
                }
            }
            // Every lane on one flank (a nut's circles): that flank's constants in lanes; else
            // gathered lane by lane. With lubricated contacts, each ball's films' friction.
            let fi = group[which[0]].as_ref().map_or(0, |b| b.fi);
            let one_flank = which[..k].iter().all(|&i| group[i].as_ref().is_some_and(|b| b.fi == fi));
            let gathered;
            let c = if one_flank {
                &self.wide[fi]
            } else {
                gathered = Constants::<F::Wide>::gather(&constants[..k]);
                &gathered
            };
            let lubricated;
            let c = if self.films.is_some() {
                let screw: [&ContactFriction; MAX_GROUP] = core::array::from_fn(|i| frictions[i].0);
                let nut: [&ContactFriction; MAX_GROUP] = core::array::from_fn(|i| frictions[i].1);
                lubricated = c.with_frictions(&screw[..k], &nut[..k]);
                &lubricated
            } else {
                c
            };
            let trained;
            let c = match group[which[0]].as_ref().and_then(|b| b.train) {
                // Every ball of a call carries the same train.
                Some(t) => {
                    trained = with_train(*c, &Some(t));
                    &trained
                }
                None => c,
            };
            let loads = Load::gather(&loads[..k]);
            let first = balance::evaluate(c, &balance::gather_states::<F::Wide>(&starts[..k]), &loads);
            for (lane, &i) in which[..k].iter().enumerate() {
                if let Some(ball) = group[i].as_mut() {
                    // A residual of the ball's solve, counted as where it evaluates one itself.
                    stats::residual();
                    ball.evaluated = Some(first.lane(lane));
                }
            }
        }
        let spec = self.model.spec();
        let z = self.balls_per_circle;
        for ball in group.iter().flatten() {
            let (nut, circle) = (ball.nut, ball.circle);
            let memory = &mut state.balls[ball.fi][circle];
            let o = self.solve_ball(ball, memory).ok_or(Error::NoConvergence {
                nut,
                circle,
                iterations: MAX_ITERATIONS,
                residual: f64::INFINITY,
                unphysical: None,
            })?;
            let wz = self.weights[circle] * z;
            // The return's share of the circle's circuit: its resistance moved at the balls'
            // speed (in f64, as the model sums it).
            // Eq. (27) as printed has no such term (as the model's).
            let returned = ball.train.filter(|_| spec.model.torque == TorqueRoute::Energy).map_or(F::zero(), |t| {
                let g = &spec.geometry;
                let (rm, h) = (0.5 * g.pitch_diameter_m, geometry::lead_per_rad(g));
                self.weights[circle] * F::of(t.return_dissipation_per_speed(o.orbit.to_f64(), rm, h))
            });
            let circle_nm = wz
                * direction
                * match spec.model.torque {
                    TorqueRoute::Energy => o.dissipation_per_speed,
                    TorqueRoute::PaperEq27 => o.eq27_nm,
                }
                + direction * returned;
            if let Some(g) = groups.as_deref_mut() {
                g[nut][circle] = match spec.model.torque {
                    TorqueRoute::Energy => {
                        let (rolling, ball_ball) = (o.rolling_dissipation_per_speed, o.ball_ball_dissipation_per_speed);
                        let creep = o.dissipation_per_speed - rolling - ball_ball;
                        let mut m = [creep, rolling, ball_ball].map(|d| wz * direction * d);
                        m[2] += direction * returned;
                        m
                    }
                    TorqueRoute::PaperEq27 => [circle_nm, F::zero(), F::zero()],
                };
            }
            *sum += circle_nm;
        }
        Ok(())
    }

    /// The speed a lubricated ball's warm start follows (the screw speed's magnitude, rad/s; 0
    /// dry, whose solutions do not depend on it).
    pub(super) fn start_speed(&self, speed_rad_s: f64) -> F {
        if self.model.oil().is_some() { F::of(libm::fabs(speed_rad_s)) } else { F::zero() }
    }

    /// What screw speed `speed_rad_s` sets in the films of every ball of a call (lubricated
    /// contacts; `None` dry).
    pub(super) fn film_speed(&self, speed_rad_s: f64) -> Option<FilmSpeed> {
        self.films.as_ref().map(|f| f.speed(speed_rad_s))
    }

    /// The creep model's torque (with the axial term and the seals, as the model sums them) and
    /// its axial term F_a L / (2 pi), N m; `None` when a loaded ball is lighter than
    /// [`LIGHT_BALL_N`] (the model answers there). `groups`, when given, receives each circle's
    /// friction torque (all its balls, signed as the torque) by mechanism, N m, per nut and
    /// circle (0 for a circle without load; by the paper's Eq. (27) route all of it is counted
    /// as creep).
    pub(crate) fn creep_torque(
        &self,
        op: &OperatingPoint,
        speed: F,
        state: &mut EvalState<F>,
        mut groups: Option<&mut Groups<F>>,
    ) -> Result<Option<(F, F)>, Error> {
        if let Some(g) = groups.as_deref_mut() {
            *g = [[[F::zero(); MECHANISMS]; MAX_CIRCLES_PER_NUT]; MAX_NUTS];
        }
        let spec = self.model.spec();
        let (loads, p_max) = self.ball_loads(op)?;
        if self.has_light_ball(&loads) {
            return Ok(None);
        }
        let factor = F::of(standstill_factor(op.speed_rad_s, spec.friction.standstill_speed_rad_s));
        let backwards = speed < F::zero();
        let direction = if backwards { -F::one() } else { F::one() };
        let z = self.balls_per_circle;
        let film_speed = self.film_speed(op.speed_rad_s);
        // The train's loads at the call's speed, with the standstill factor in f64 (as the
        // model's).
        let train =
            self.model.circuit(op.speed_rad_s, standstill_factor(op.speed_rad_s, spec.friction.standstill_speed_rad_s));
        let mut sum = F::zero();
        // The balls of the call in groups of the lanes (`Real::Wide`): each group's first
        // evaluations in one pass, then each ball's solve, in the balls' order.
        let lanes = <F::Wide as Lanes>::LANES.min(MAX_GROUP);
        let mut group: [Option<Ball<F>>; MAX_GROUP] = core::array::from_fn(|_| None);
        let mut count = 0;
        for (nut, &(nut_load, flank)) in loads.iter().enumerate().take(self.nuts) {
            // Solved turning forwards on the mirrored flank (see the module's documentation).
            let fi = balance::flank_index(if backwards { -flank } else { flank });
            let nut_load = F::of(nut_load);
            for circle in 0..self.circles {
                // A ball whose memory a ball of the group still has to use waits for the group.
                let taken = group[..count].iter().flatten().any(|b| b.fi == fi && b.circle == circle);
                if count == lanes || taken {
                    self.solve_group(&mut group[..count], state, direction, &mut groups, &mut sum)?;
                    count = 0;
                }
                let p = nut_load * self.fractions[circle] / z;
                if !(p > F::zero()) {
                    state.balls[fi][circle].stored = 0;
                    continue;
                }
                let memory = &state.balls[fi][circle];
                group[count] =
                    Some(self.prepare(nut, circle, fi, p, p_max, film_speed.as_ref(), factor, op, memory, train));
                count += 1;
            }
        }
        self.solve_group(&mut group[..count], state, direction, &mut groups, &mut sum)?;
        let axial = F::of(self.model.axial_term_nm(op));
        let seals = F::of(self.model.seal_torque_nm(op.speed_rad_s));
        Ok(Some((axial + sum + seals, axial)))
    }
}
