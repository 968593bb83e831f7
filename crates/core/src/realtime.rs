//! Evaluation for a control loop: the torque of [`Model`] in `f64` or `f32`, with no allocation,
//! warm-started from the previous call and cold-started from a table of solved balls.
//!
//! [`Evaluator`] is built once from a model. It keeps, per flank, the load-independent factors
//! of the balance ([`balance::Constants`]) and a table of solved balls over a geometric grid of
//! ball loads (ratio [`TABLE_RATIO`], from [`TABLE_FIRST_LOAD_N`]), found in f64 by the model's
//! continuation (MODEL-NOTES item 11), so a cold start is a Newton solve from the table,
//! interpolated in the logarithm of the load (cubic, Catmull-Rom), and lands on the branch the
//! continuation selects. [`EvalState`] carries each ball's last two solutions (a secant start in
//! load) and the last Jacobian (Broyden's method carries it on); a ball whose load has jumped by
//! more than 1 % since its last solve starts from the table instead.
//!
//! Each call then solves every circle's ball in the chosen float type with the lean balance
//! ([`balance::evaluate`], Eqs. 3-24) to the tolerance [`Evaluator::tolerance`], and sums the
//! torque (Eqs. 25-27 by the model's route, MODEL-NOTES item 9). What stays in f64: the table
//! (at build), the split of the preload between the nuts (a scalar root), the extension terms
//! of the spec, and the model's own continuation where a solve from the table fails (a load
//! outside the table, or a ball that does not converge from it).

use crate::balance::{self, Constants, Load, Outcome};
use crate::creep::standstill_factor;
use crate::error::Error;
use crate::extensions::Conditions;
use crate::kinematics::{self, JacobianStep, MIN_SOLVE_FACTOR, N, Unknowns};
use crate::load;
use crate::real::Real;
use crate::spec::{ContactTheory, MAX_CIRCLES_PER_NUT, MAX_NUTS, OperatingPoint, TorqueRoute};
use crate::torque::Model;

/// Ball load of the first entry of the start table, N.
pub const TABLE_FIRST_LOAD_N: f64 = 1e-2;
/// Ratio of the ball loads of adjacent entries of the start table.
pub const TABLE_RATIO: f64 = 1.5;
/// Entries of the start table per flank: 1e-2 N to about 2e6 N.
pub const TABLE_LEN: usize = 48;
/// Relative change of a ball's load above which a warm start gives way to the table.
const JUMP: f64 = 0.01;
/// Newton iterations of one solve in the evaluator.
const MAX_ITERATIONS: u32 = 40;

/// A model ready for the control loop in float type `F`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Evaluator<F: Real> {
    model: Model,
    /// Per flank: index 0 for +1, 1 for -1.
    constants: [Constants<F>; 2],
    table: [[Unknowns; TABLE_LEN]; 2],
    /// The Jacobian of the balance at each table entry (f64 finite differences).
    table_jacobian: [[[[F; N]; N]; TABLE_LEN]; 2],
    table_ok: [[bool; TABLE_LEN]; 2],
    fractions: [F; MAX_CIRCLES_PER_NUT],
    weights: [F; MAX_CIRCLES_PER_NUT],
    nuts: usize,
    circles: usize,
    balls_per_circle: F,
    tolerance: F,
    step: JacobianStep,
}

/// Warm-start memory of an [`Evaluator`]: each ball's last two solutions and its Jacobian.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EvalState<F: Real> {
    balls: [[BallMemory<F>; MAX_CIRCLES_PER_NUT]; MAX_NUTS],
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct BallMemory<F: Real> {
    /// Number of stored solutions (0, 1 or 2).
    stored: u8,
    x: [F; N],
    load_n: F,
    previous: [F; N],
    previous_load_n: F,
    jacobian: Option<[[F; N]; N]>,
}

impl<F: Real> BallMemory<F> {
    const EMPTY: Self = Self {
        stored: 0,
        x: [F::ZERO; N],
        load_n: F::ZERO,
        previous: [F::ZERO; N],
        previous_load_n: F::ZERO,
        jacobian: None,
    };
}

impl<F: Real> Default for EvalState<F> {
    fn default() -> Self {
        Self::new()
    }
}

impl<F: Real> EvalState<F> {
    /// An empty state: the next call starts every ball from the table.
    pub const fn new() -> Self {
        Self { balls: [[BallMemory::EMPTY; MAX_CIRCLES_PER_NUT]; MAX_NUTS] }
    }

    /// Forgets every stored solution.
    pub fn reset(&mut self) {
        *self = Self::new();
    }
}

fn convert<F: Real>(x: &Unknowns) -> [F; N] {
    core::array::from_fn(|i| F::of(x[i]))
}

impl<F: Real> Evaluator<F> {
    /// Prepares `model` for the control loop: the constants of both flanks and the start table
    /// (about 100 ball solves in f64). The linear-saturated contact theory only: FASTSIM is an
    /// analysis option.
    pub fn new(model: &Model) -> Result<Self, Error> {
        let spec = model.spec();
        if spec.model.contact_theory != ContactTheory::LinearSaturated {
            return Err(Error::Unsupported {
                field: "model.contact_theory",
                value: spec.model.contact_theory.name(),
                valid: "linear-saturated, for the real-time evaluator",
            });
        }
        let g = &spec.geometry;
        let shares = load::circle_shares(g.circles_per_nut, spec.model.load_distribution);
        let approach = model.ball_ball_approach_m();
        let mut table = [[[0.0; N]; TABLE_LEN]; 2];
        let mut table_ok = [[false; TABLE_LEN]; 2];
        let mut table_jacobian = [[[[F::zero(); N]; N]; TABLE_LEN]; 2];
        for (k, flank) in [1.0, -1.0].into_iter().enumerate() {
            fill_table(model, flank, &mut table[k], &mut table_ok[k]);
            for i in 0..TABLE_LEN {
                if table_ok[k][i] {
                    let setup = model.ball_setup_for(table_load_n(i), flank);
                    let j = kinematics::balance_jacobian(&setup, &table[k][i]);
                    table_jacobian[k][i] = core::array::from_fn(|r| core::array::from_fn(|c| F::of(j[r][c])));
                }
            }
        }
        let setup = |flank: f64| Constants::new(&model.ball_setup_for(1.0, flank), approach);
        let js = kinematics::jacobian_step(&model.ball_setup_for(1.0, 1.0));
        let floor = F::JACOBIAN_STEP.to_f64();
        Ok(Self {
            model: *model,
            constants: [setup(1.0), setup(-1.0)],
            table,
            table_jacobian,
            table_ok,
            fractions: core::array::from_fn(|i| F::of(shares.load_fraction[i])),
            weights: core::array::from_fn(|i| F::of(shares.weight[i])),
            nuts: g.nuts as usize,
            circles: g.circles_per_nut as usize,
            balls_per_circle: F::of(f64::from(g.balls_per_circle)),
            tolerance: F::TOLERANCE,
            step: JacobianStep { far: js.far.max(floor), near: js.near.max(floor), near_below: js.near_below },
        })
    }

    /// The same evaluator with the tolerance `tolerance` on the residual (max norm of the
    /// imbalances over the nominal normal load Q, see [`weights`]). Below about
    /// [`Real::TOLERANCE`] a solve in f32 meets the rounding noise of the residual and falls back
    /// to the model's continuation.
    pub fn with_tolerance(mut self, tolerance: F) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// The tolerance on the residual (see [`Evaluator::with_tolerance`]).
    pub fn tolerance(&self) -> F {
        self.tolerance
    }

    /// The model this evaluator was built from.
    pub fn model(&self) -> &Model {
        &self.model
    }

    /// The start for a ball of load `load_n` (N) on flank `fi` from the table: interpolated in
    /// log load (cubic through the four entries around it, linear between the two where an
    /// outer one is missing), else the nearest solved entry; with the Jacobian of the nearest
    /// entry.
    fn table_start(&self, fi: usize, load_n: f64) -> Option<([F; N], &[[F; N]; N])> {
        let pos = libm::log(load_n / TABLE_FIRST_LOAD_N) / libm::log(TABLE_RATIO);
        let ok = &self.table_ok[fi];
        let t = &self.table[fi];
        let near = (libm::round(pos.max(0.0)) as usize).min(TABLE_LEN - 1);
        let nearest =
            if ok[near] { near } else { (0..TABLE_LEN).filter(|&i| ok[i]).min_by_key(|&i| i.abs_diff(near))? };
        let jacobian = &self.table_jacobian[fi][nearest];
        if pos >= 0.0 && pos < (TABLE_LEN - 1) as f64 {
            let i = pos as usize;
            if ok[i] && ok[i + 1] {
                let w = pos - i as f64;
                // Catmull-Rom (cubic) where both outer neighbours are solved, else linear.
                if i >= 1 && i + 2 < TABLE_LEN && ok[i - 1] && ok[i + 2] {
                    let (w2, w3) = (w * w, w * w * w);
                    let c = [
                        -0.5 * w3 + w2 - 0.5 * w,
                        1.5 * w3 - 2.5 * w2 + 1.0,
                        -1.5 * w3 + 2.0 * w2 + 0.5 * w,
                        0.5 * w3 - 0.5 * w2,
                    ];
                    return Some((
                        core::array::from_fn(|j| {
                            F::of(c[0] * t[i - 1][j] + c[1] * t[i][j] + c[2] * t[i + 1][j] + c[3] * t[i + 2][j])
                        }),
                        jacobian,
                    ));
                }
                return Some((core::array::from_fn(|j| F::of(t[i][j] + w * (t[i + 1][j] - t[i][j]))), jacobian));
            }
        }
        Some((convert(&t[nearest]), jacobian))
    }

    /// The drive torque (N m) at screw speed `speed_rad_s` (rad/s), preload `preload_n` (N) and
    /// axial load `axial_load_n` (N), by the model's torque route with the spec's extension
    /// terms at their default conditions.
    pub fn torque_nm(
        &self,
        speed_rad_s: F,
        preload_n: F,
        axial_load_n: F,
        state: &mut EvalState<F>,
    ) -> Result<F, Error> {
        self.torque_at_nm(speed_rad_s, preload_n, axial_load_n, &Conditions::default(), state)
    }

    /// [`Evaluator::torque_nm`] under `cond` (position, temperature, running time).
    pub fn torque_at_nm(
        &self,
        speed_rad_s: F,
        preload_n: F,
        axial_load_n: F,
        cond: &Conditions,
        state: &mut EvalState<F>,
    ) -> Result<F, Error> {
        let op = OperatingPoint {
            speed_rad_s: speed_rad_s.to_f64(),
            preload_n: preload_n.to_f64(),
            axial_load_n: axial_load_n.to_f64(),
        };
        op.validate()?;
        let ext = &self.model.spec().extensions;
        if ext.is_empty() {
            let (torque, _) = self.creep_torque(&op, speed_rad_s, state)?;
            return Ok(torque);
        }
        let eff = ext.effective_operating(&op, cond);
        let (torque, axial) = self.creep_torque(&eff, F::of(eff.speed_rad_s), state)?;
        Ok(F::of(self.model.with_extensions_nm(torque.to_f64(), axial.to_f64(), &eff, &op, cond)))
    }

    /// The creep model's torque and its axial term F_a L / (2 pi), N m.
    fn creep_torque(&self, op: &OperatingPoint, speed: F, state: &mut EvalState<F>) -> Result<(F, F), Error> {
        let spec = self.model.spec();
        let loads = load::nut_loads(op.preload_n, op.axial_load_n, spec.geometry.nuts);
        let factor = standstill_factor(op.speed_rad_s, spec.friction.standstill_speed_rad_s);
        let direction = if speed < F::zero() { -F::one() } else { F::one() };
        let z = self.balls_per_circle;
        let mut sum = F::zero();
        for (nut, &(nut_load, flank)) in loads.iter().enumerate().take(self.nuts) {
            let nut_load = F::of(nut_load);
            for circle in 0..self.circles {
                let p = nut_load * self.fractions[circle] / z;
                let memory = &mut state.balls[nut][circle];
                if !(p > F::zero()) {
                    memory.stored = 0;
                    continue;
                }
                let load = Load { axial_load_n: p, direction, factor: F::of(factor) };
                let o = self.solve_ball(flank, &load, memory).ok_or(Error::NoConvergence {
                    nut,
                    circle,
                    iterations: MAX_ITERATIONS,
                    residual: f64::INFINITY,
                })?;
                let wz = self.weights[circle] * z;
                sum += wz
                    * match spec.model.torque {
                        TorqueRoute::Energy => o.dissipation_per_speed,
                        TorqueRoute::PaperEq27 => direction * o.eq27_nm,
                    };
            }
        }
        let axial = F::of(self.model.axial_term_nm(&loads.map(|(l, _)| l), op));
        Ok((axial + sum, axial))
    }

    /// Solves one ball: from its memory (secant start, then its last solution), else from the
    /// table, else by the model's continuation in f64. Returns the ball evaluated at its
    /// solution (at the standstill factor of `load`), or `None` when nothing converges.
    fn solve_ball(&self, flank: f64, load: &Load<F>, memory: &mut BallMemory<F>) -> Option<Outcome<F>> {
        let fi = balance::flank_index(flank);
        let c = &self.constants[fi];
        let fk = load.factor.max(F::of(MIN_SOLVE_FACTOR));
        let at = Load { factor: fk, ..*load };
        let p = load.axial_load_n;
        // In f32 the table's Jacobian stands in for finite differences.
        let early = if F::FINITE_DIFFERENCES { None } else { self.table_start(fi, p.to_f64()) };
        let fresh = early.map(|(_, j)| j);
        let mut solved = None;
        // A jump in load (more than JUMP of the last solved load) starts from the table, whose
        // cubic interpolation is the better predictor there.
        let jump = memory.stored >= 1 && (p - memory.load_n).abs() > F::of(JUMP) * memory.load_n;
        if jump {
            memory.stored = 0;
        }
        if memory.stored >= 1 {
            let mut jacobian = memory.jacobian;
            if memory.stored == 2 {
                let m = &*memory;
                let start = kinematics::secant_start(&m.x, m.load_n, &m.previous, m.previous_load_n, p);
                solved = start.and_then(|start| self.newton(c, &at, start, &mut jacobian, fresh));
            }
            if solved.is_none() {
                solved = self.newton(c, &at, memory.x, &mut jacobian, fresh);
            }
            memory.jacobian = jacobian;
        }
        if solved.is_none() {
            let mut jacobian = None;
            let table = if early.is_some() { early } else { self.table_start(fi, p.to_f64()) };
            solved = table
                .and_then(|(start, j)| {
                    jacobian = Some(*j);
                    self.newton(c, &at, start, &mut jacobian, fresh)
                })
                .or_else(|| self.continuation(flank, &at, c));
            memory.jacobian = jacobian;
            memory.stored = 0;
        }
        let (x, outcome) = solved?;
        if memory.stored >= 1 {
            memory.previous = memory.x;
            memory.previous_load_n = memory.load_n;
            memory.stored = 2;
        } else {
            memory.stored = 1;
        }
        memory.x = x;
        memory.load_n = p;
        if load.factor >= fk {
            return Some(outcome);
        }
        Some(balance::evaluate(c, &kinematics::scale_to_factor(&x, load.factor), load))
    }

    /// Newton's method on the lean balance from `start`; the solution and the ball evaluated
    /// there.
    fn newton(
        &self,
        c: &Constants<F>,
        load: &Load<F>,
        start: [F; N],
        jacobian: &mut Option<[[F; N]; N]>,
        fresh: Option<&[[F; N]; N]>,
    ) -> Option<([F; N], Outcome<F>)> {
        let mut x = start;
        let mut last: Option<([F; N], Outcome<F>)> = None;
        let (_, res) = kinematics::newton(
            &mut x,
            |xx| {
                let o = balance::evaluate(c, xx, load);
                last = Some((*xx, o));
                o.residual
            },
            &weights(c.mu()),
            self.tolerance,
            MAX_ITERATIONS,
            self.step,
            jacobian,
            fresh,
        );
        if !(res <= self.tolerance) {
            *jacobian = None;
            return None;
        }
        match last {
            Some((y, o)) if y == x => Some((x, o)),
            _ => Some((x, balance::evaluate(c, &x, load))),
        }
    }

    /// The model's own solve in f64 (continuation), where the table gives no start that
    /// converges.
    fn continuation(&self, flank: f64, load: &Load<F>, c: &Constants<F>) -> Option<([F; N], Outcome<F>)> {
        let setup = self.model.ball_setup_for(load.axial_load_n.to_f64(), flank);
        let speed = load.direction.to_f64();
        let (x, rep) = kinematics::solve(&setup, None, speed, load.factor.to_f64());
        if !(rep.residual <= kinematics::TOLERANCE.max(self.tolerance.to_f64())) {
            return None;
        }
        let mut y = convert(&x);
        let mut none = None;
        // Polish in F (the f64 solution rounded may sit just above the tolerance).
        self.newton(c, load, y, &mut none, None).or_else(|| {
            y = convert(&x);
            Some((y, balance::evaluate(c, &y, load)))
        })
    }
}

/// Weights of the residual's equations in the convergence test: every equation relative to
/// the nominal load Q. The friction-borne ones (force along t, the three moments) are scaled by
/// f Q in [`balance`] (which keeps Newton's steps well conditioned) and are weighted by f here.
/// Their rounding noise is that of the creep forces, whose stiffness amplifies the rounding of
/// the creepages (about 5e-4 of f Q in f32), while the normal-load equations carry the torque:
/// one tolerance on loads then serves both float types.
fn weights<F: Real>(mu: F) -> [F; N] {
    [mu, F::one(), F::one(), mu, mu, mu, F::one()]
}

/// Ball load of table entry `i`, N.
fn table_load_n(i: usize) -> f64 {
    TABLE_FIRST_LOAD_N * libm::pow(TABLE_RATIO, i as f64)
}

/// Solves the table of one flank: the entry nearest 10 N cold (continuation), then outwards
/// entry by entry, each from its neighbour.
fn fill_table(model: &Model, flank: f64, table: &mut [Unknowns; TABLE_LEN], ok: &mut [bool; TABLE_LEN]) {
    let load = table_load_n;
    let centre = (libm::log(10.0 / TABLE_FIRST_LOAD_N) / libm::log(TABLE_RATIO)) as usize;
    let solve = |i: usize, from: Option<&Unknowns>| {
        let setup = model.ball_setup_for(load(i), flank);
        kinematics::solve(&setup, from, 1.0, 1.0)
    };
    let (x, rep) = solve(centre, None);
    if !(rep.residual <= kinematics::TOLERANCE) {
        return;
    }
    table[centre] = x;
    ok[centre] = true;
    for dir in [1_isize, -1] {
        let mut last = x;
        let mut i = centre as isize + dir;
        while (0..TABLE_LEN as isize).contains(&i) {
            let (y, rep) = solve(i as usize, Some(&last));
            if !(rep.residual <= kinematics::TOLERANCE) {
                break;
            }
            table[i as usize] = y;
            ok[i as usize] = true;
            last = y;
            i += dir;
        }
    }
}
