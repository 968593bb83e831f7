//! The evaluator's start table: per flank, balls solved in f64 over a geometric grid of ball
//! loads (ratio [`TABLE_RATIO`] from [`TABLE_FIRST_LOAD_N`]), each with its solution, its slope in
//! the logarithm of the load and the inverse of the balance's Jacobian; how it is solved
//! ([`fill_table`]: by the model's continuation, then entry from entry), carried to another
//! screw speed ([`Evaluator::with_table_speed`]) and read (a cold start: cubic Hermite in log
//! load, [`Evaluator::table_start`]).

use super::linear::{Matrix, convert, convert_matrix, invert, times};
use crate::ball::balance::{self, Constants, Load};
use crate::ball::setup::{self, N, Unknowns};
use crate::ball::solve::{self};
use crate::real::Real;
use crate::screw::model::Model;

/// Ball load (N) below which the evaluator hands the whole point to the model
/// ([`Model::torque_at`] from a fresh state), so that both give the same torque or the same
/// error. Light balls make the balance nearly degenerate (both raceway contacts in full slip,
/// docs/model.md, "Light balls"): there the model's continuation decides whether a physical state is
/// found at all (on DKFZD4012 it is not below about 2 N of preload, 0.04 N per ball), and a
/// start from the evaluator's table or memory could land on a state the model does not reach.
/// 0.5 N is 25 N of preload on DKFZD4012, above the balls of 0.03-0.2 N whose solutions are
/// ill-determined.
pub const LIGHT_BALL_N: f64 = 0.5;

/// Ball load of the first entry of the start table, N.
pub const TABLE_FIRST_LOAD_N: f64 = 1e-2;
/// Ratio of the ball loads of adjacent entries of the start table.
pub const TABLE_RATIO: f64 = 1.25;
/// Entries of the start table per flank: 1e-2 N to about 2e6 N.
pub const TABLE_LEN: usize = 86;
/// Largest ratio of screw speeds over which an entry of the start table is solved again in one
/// Newton solve from its solution at the other speed ([`Evaluator::with_table_speed_for`](super::Evaluator::with_table_speed_for)): that of
/// a batch's bands of speed, whose tables are each solved from the band's before.
pub const CARRY_SPEED_RATIO: f64 = 1.1;
/// Most Newton solves along the speed for one entry (1.1^16 = 4.6: beyond that the steps are
/// longer, and an entry whose start does not converge is left out, as a table start then takes
/// the nearest solved one).
pub(super) const MAX_CARRY_STEPS: f64 = 16.0;
/// Entries of an evaluator's start table, a range of indices per flank
/// ([`Evaluator::table_entries`](super::Evaluator::table_entries), [`Evaluator::with_table_speed_for`](super::Evaluator::with_table_speed_for)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct TableEntries {
    /// First and last index, per flank (`None`: none).
    pub(super) ranges: [Option<(usize, usize)>; 2],
}

impl TableEntries {
    /// Every entry.
    pub const ALL: Self = Self { ranges: [Some((0, TABLE_LEN - 1)); 2] };

    pub(super) fn add(&mut self, fi: usize, first: usize, last: usize) {
        self.ranges[fi] = Some(match self.ranges[fi] {
            Some((a, b)) => (a.min(first), b.max(last)),
            None => (first, last),
        });
    }

    /// The entries of both.
    pub fn join(&self, other: &Self) -> Self {
        let mut out = *self;
        for (fi, r) in other.ranges.iter().enumerate() {
            if let &Some((a, b)) = r {
                out.add(fi, a, b);
            }
        }
        out
    }
}

/// One entry of the start table: a ball solved at the entry's load, turning forwards.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Entry<F: Real> {
    pub(super) x: [F; N],
    /// d x / d ln(load) times ln([`TABLE_RATIO`]): the change over one entry, to first order.
    pub(super) slope: [F; N],
    /// Inverse of the Jacobian of the balance (scaled residual) at the entry.
    pub(super) inverse: Matrix<F>,
    /// The screw speed whose films the entry's ball carries, rad/s.
    pub(super) speed_rad_s: f64,
}

/// The table entry `i` of flank `flank` from its solution `x` (f64): the inverse Jacobian, and
/// the slope d x / d ln(load) = -J^-1 d r / d ln(load) (the residual's derivative at fixed x by
/// central differences).
pub(super) fn entry<F: Real>(model: &Model, flank: f64, speed_rad_s: f64, i: usize, x: &Unknowns) -> Option<Entry<F>> {
    let p = table_load_n(i);
    let setup = table_setup(model, p, flank, speed_rad_s);
    let j = solve::balance_jacobian(&setup, x);
    let inverse = invert(&j)?;
    let c = Constants::new(&setup, 0.0);
    let eps = 1e-6;
    let r = |q: f64| balance::evaluate(&c, x, &Load { axial_load_n: q, direction: 1.0, factor: 1.0 }).residual;
    let (up, down) = (r(p * libm::exp(eps)), r(p * libm::exp(-eps)));
    let dr: Unknowns = core::array::from_fn(|k| (up[k] - down[k]) / (2.0 * eps));
    let dx = times(&inverse, &dr);
    let h = libm::log(TABLE_RATIO);
    Some(Entry {
        x: convert(x),
        slope: core::array::from_fn(|k| F::of(-dx[k] * h)),
        inverse: convert_matrix(&inverse),
        speed_rad_s,
    })
}

/// The setup of a table ball of load `load_n` (N) on `flank`: with lubricated contacts, their
/// films at the spec's operating speed (the table is a start, and the balls' friction changes
/// with the speed: a start near it converges in a few steps where a dry ball's, whose friction
/// coefficient may be a fifth of the lubricated one, does not).
pub(super) fn table_setup(model: &Model, load_n: f64, flank: f64, speed_rad_s: f64) -> setup::BallSetup {
    model.ball_setup_at(load_n, flank, speed_rad_s, 1.0).0
}

/// The speed of a table's films for screw speed `speed_rad_s`: its magnitude, at least the
/// standstill speed, rad/s.
pub(super) fn table_speed_rad_s(model: &Model, speed_rad_s: f64) -> f64 {
    libm::fabs(speed_rad_s).max(model.spec().friction.standstill_speed_rad_s)
}

/// Ball load of table entry `i`, N.
pub(super) fn table_load_n(i: usize) -> f64 {
    TABLE_FIRST_LOAD_N * libm::pow(TABLE_RATIO, i as f64)
}

/// Table entry `i` of flank `flank` at screw speed `speed_rad_s` solved from its neighbour's
/// solution `next` (and `after`, the neighbour's own neighbour on the same side): Newton's method
/// from the line through the two (equally spaced in log load), else the model's solve from
/// `next` (with its fallbacks).
pub(super) fn solve_from_neighbours(
    model: &Model,
    flank: f64,
    speed_rad_s: f64,
    i: usize,
    next: &Unknowns,
    after: Option<&Unknowns>,
) -> Option<Unknowns> {
    let setup = table_setup(model, table_load_n(i), flank, speed_rad_s);
    let ahead = after.map(|b| -> Unknowns { core::array::from_fn(|j| 2.0 * next[j] - b[j]) });
    let quick = ahead.and_then(|mut y| {
        let (_, residual) = solve::solve_full(&setup, &mut y, 1.0, 1.0);
        (residual <= setup::TOLERANCE).then_some(y)
    });
    quick.or_else(|| {
        let (y, rep) = solve::solve(&setup, Some(next), 1.0, 1.0);
        (rep.residual <= setup::TOLERANCE).then_some(y)
    })
}

/// Solves the table of one flank: the entry nearest 10 N cold (continuation), then outwards
/// entry by entry, each from its neighbour, from the entry below [`LIGHT_BALL_N`] to the one
/// above the static capacity.
pub(super) fn fill_table(
    model: &Model,
    flank: f64,
    speed_rad_s: f64,
    table: &mut [Unknowns; TABLE_LEN],
    ok: &mut [bool; TABLE_LEN],
) {
    let load = table_load_n;
    let centre = (libm::log(10.0 / TABLE_FIRST_LOAD_N) / libm::log(TABLE_RATIO)) as usize;
    let solve = |i: usize, from: Option<&Unknowns>| {
        let setup = table_setup(model, load(i), flank, speed_rad_s);
        solve::solve(&setup, from, 1.0, 1.0)
    };
    let (x, rep) = solve(centre, None);
    if !(rep.residual <= setup::TOLERANCE) {
        return;
    }
    table[centre] = x;
    ok[centre] = true;
    for dir in [1_isize, -1] {
        let (mut last, mut before) = (x, None::<Unknowns>);
        let mut i = centre as isize + dir;
        // From the lightest to the heaviest entry a table start reads: the evaluator hands
        // lighter balls to the model, and refuses a ball above the static capacity (as the
        // model does); the balances beyond, nearly degenerate or hugely overloaded, are the
        // costliest to solve.
        let read = |i: usize| {
            load(i) * TABLE_RATIO >= LIGHT_BALL_N && model.check_static_capacity(load(i) / TABLE_RATIO).is_ok()
        };
        while (0..TABLE_LEN as isize).contains(&i) && read(i as usize) {
            let Some(y) = solve_from_neighbours(model, flank, speed_rad_s, i as usize, &last, before.as_ref()) else {
                break;
            };
            table[i as usize] = y;
            ok[i as usize] = true;
            (before, last) = (Some(last), y);
            i += dir;
        }
    }
}

/// The start table of an [`Evaluator`]: per flank (index 0 for +1, 1 for -1), [`TABLE_LEN`]
/// balls solved turning forwards at the loads of [`table_load_n`], with the films of one screw
/// speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct StartTable<F: Real> {
    /// The entries, per flank.
    pub(super) entries: [[Entry<F>; TABLE_LEN]; 2],
    /// Whether each entry is solved.
    pub(super) ok: [[bool; TABLE_LEN]; 2],
    /// 1 / ln([`TABLE_RATIO`]).
    per_log_ratio: f64,
    /// Screw speed whose films the entries' balls carry, rad/s ([`table_speed_rad_s`]).
    pub(super) speed_rad_s: f64,
}

impl<F: Real> StartTable<F> {
    /// A table of no solved entry whose balls are to carry the films of `speed_rad_s` (rad/s).
    pub(super) fn empty(speed_rad_s: f64) -> Self {
        let empty = Entry { x: [F::zero(); N], slope: [F::zero(); N], inverse: [[F::zero(); N]; N], speed_rad_s: 0.0 };
        Self {
            entries: [[empty; TABLE_LEN]; 2],
            ok: [[false; TABLE_LEN]; 2],
            per_log_ratio: 1.0 / libm::log(TABLE_RATIO),
            speed_rad_s,
        }
    }

    /// Solves the table: per flank the entry nearest 10 N cold (continuation), then outwards
    /// entry by entry, each from its neighbour.
    pub(super) fn fill(&mut self, model: &Model) {
        for (k, flank) in [1.0, -1.0].into_iter().enumerate() {
            let mut solved = [[0.0; N]; TABLE_LEN];
            self.ok[k] = [false; TABLE_LEN];
            fill_table(model, flank, self.speed_rad_s, &mut solved, &mut self.ok[k]);
            for i in 0..TABLE_LEN {
                if !self.ok[k][i] {
                    continue;
                }
                match entry(model, flank, self.speed_rad_s, i, &solved[i]) {
                    Some(e) => self.entries[k][i] = e,
                    None => self.ok[k][i] = false,
                }
            }
        }
    }

    /// Solves the entries `entries` of this evaluator's table (its model, its table speed), and
    /// one more on either side of each range (for a start between entries), from `from`'s
    /// entries: each by Newton's method from `from`'s entry of the same load (along the speed
    /// in steps of at most [`CARRY_SPEED_RATIO`] from the speed that entry was last solved at),
    /// else from the last entry solved here (the next lighter ball that solved), else from
    /// `from`'s next lighter entry (the same way along the speed); then, downwards, an entry
    /// that none of these solved from the next heavier entry solved here ([`fill_table`]'s
    /// step, with the model's solve as its fallback). Entries lighter
    /// than [`LIGHT_BALL_N`] over [`TABLE_RATIO`] are left out (the evaluator hands such balls
    /// to the model), and so is an entry that does not solve. The other entries stay as they
    /// are. Whether every entry solved.
    pub(super) fn carry(&mut self, model: &Model, from: &Self, entries: &TableEntries) -> bool {
        let speed = self.speed_rad_s;
        let mut all = true;
        for (k, flank) in [1.0, -1.0].into_iter().enumerate() {
            let Some((first, last)) = entries.ranges[k] else { continue };
            let (lo, hi) = (first.saturating_sub(1), (last + 1).min(TABLE_LEN - 1));
            let mut failed = [false; TABLE_LEN];
            let mut below = None;
            for i in lo..=hi {
                // An entry keeps its last solution (at its speed) when a carry fails: still a
                // start. Speed 0: never solved (light, or beyond the span the table was built
                // for, [`fill_table`]), left out as it is.
                let kept = |j: usize| {
                    let e = &from.entries[k][j];
                    (e.speed_rad_s > 0.0).then_some((e.x, e.speed_rad_s))
                };
                if from.ok[k][i] && from.entries[k][i].speed_rad_s == speed {
                    // Solved at this speed already: kept, and the next entry's start.
                    below = kept(i);
                    continue;
                }
                self.ok[k][i] = false;
                if table_load_n(i) * TABLE_RATIO < LIGHT_BALL_N || kept(i).is_none() {
                    continue;
                }
                let lighter = if i > 0 { kept(i - 1) } else { None };
                let solved = [kept(i), below, lighter].into_iter().flatten().find_map(|(start, from_speed)| {
                    let mut x: Unknowns = core::array::from_fn(|j| start[j].to_f64());
                    // Along the speed in steps of at most CARRY_SPEED_RATIO (at most
                    // MAX_CARRY_STEPS of them): an entry left as it was while the bands passed
                    // it is a start of a far speed.
                    let ratio = speed / from_speed;
                    let steps = libm::ceil(libm::fabs(libm::log(ratio)) / libm::log(CARRY_SPEED_RATIO))
                        .clamp(1.0, MAX_CARRY_STEPS);
                    for j in 1..=(steps as u32) {
                        let at = from_speed * libm::pow(ratio, f64::from(j) / steps);
                        let setup = table_setup(model, table_load_n(i), flank, at);
                        let (_, residual) = solve::solve_full(&setup, &mut x, 1.0, 1.0);
                        if !(residual <= setup::TOLERANCE) {
                            return None;
                        }
                    }
                    entry(model, flank, speed, i, &x)
                });
                if let Some(e) = solved {
                    self.entries[k][i] = e;
                    self.ok[k][i] = true;
                    below = Some((e.x, speed));
                } else {
                    failed[i] = true;
                }
            }
            // Downwards, each entry that did not carry from the next heavier one solved here,
            // as the table is first solved ([`fill_table`]). Along the speed an entry's steps
            // can end where its branch of steady states ends (docs/model-notes.md item 24), and
            // then every lighter entry lacked a start: carried from 100 to 1745 rpm,
            // DKFZD4012's entries of 0.44-6.5 N on one flank, whose balls each took the
            // model's continuation (2000 random points at 1700-1800 rpm: 1.5 ms a point,
            // against 41 us with them).
            for i in (lo..hi).rev() {
                if !failed[i] || !self.ok[k][i + 1] {
                    continue;
                }
                let heavier = |j: usize| {
                    (j < TABLE_LEN && self.ok[k][j] && self.entries[k][j].speed_rad_s == speed)
                        .then(|| -> Unknowns { core::array::from_fn(|c| self.entries[k][j].x[c].to_f64()) })
                };
                let Some(next) = heavier(i + 1) else { continue };
                if let Some(e) = solve_from_neighbours(model, flank, speed, i, &next, heavier(i + 2).as_ref())
                    .and_then(|x| entry(model, flank, speed, i, &x))
                {
                    self.entries[k][i] = e;
                    self.ok[k][i] = true;
                    failed[i] = false;
                }
            }
            all &= !failed.contains(&true);
        }
        all
    }

    /// Where the load `load_n` (N) lies in the start table: the index of its entry, fractional
    /// between entries (negative below the first).
    pub(super) fn position(&self, load_n: f64) -> f64 {
        libm::log(load_n / TABLE_FIRST_LOAD_N) * self.per_log_ratio
    }

    /// The start for a ball of load `load_n` (N) on flank `fi`, turning forwards at factor 1,
    /// from the table, with its inverse Jacobian: the solution interpolated in log load (cubic
    /// Hermite through the two entries around the load) and the inverse Jacobian (written to
    /// `inverse`, where given) linearly; else the nearest solved entry.
    pub(super) fn start(&self, fi: usize, load_n: F, inverse: Option<&mut Matrix<F>>) -> Option<[F; N]> {
        let pos = self.position(load_n.to_f64());
        let ok = &self.ok[fi];
        let t = &self.entries[fi];
        if pos >= 0.0 && pos < (TABLE_LEN - 1) as f64 {
            let i = pos as usize;
            if ok[i] && ok[i + 1] {
                let w = F::of(pos - i as f64);
                let (a, b) = (&t[i], &t[i + 1]);
                let (w2, w3) = (w * w, w * w * w);
                let (two, three) = (F::of(2.0), F::of(3.0));
                let h00 = two * w3 - three * w2 + F::one();
                let h10 = w3 - two * w2 + w;
                let h01 = three * w2 - two * w3;
                let h11 = w3 - w2;
                let x = core::array::from_fn(|j| h00 * a.x[j] + h10 * a.slope[j] + h01 * b.x[j] + h11 * b.slope[j]);
                let v = F::one() - w;
                for (r, row) in inverse.into_iter().flatten().enumerate() {
                    for (c, m) in row.iter_mut().enumerate() {
                        *m = v * a.inverse[r][c] + w * b.inverse[r][c];
                    }
                }
                return Some(x);
            }
        }
        let near = (libm::round(pos.max(0.0)) as usize).min(TABLE_LEN - 1);
        let nearest =
            if ok[near] { near } else { (0..TABLE_LEN).filter(|&i| ok[i]).min_by_key(|&i| i.abs_diff(near))? };
        if let Some(inverse) = inverse {
            *inverse = t[nearest].inverse;
        }
        Some(t[nearest].x)
    }
    /// The two solved entries of flank `fi`'s table around the load `load_n` (N), nearest first,
    /// each as its solution and inverse Jacobian.
    #[allow(clippy::type_complexity)]
    pub(super) fn neighbours(&self, fi: usize, load_n: F) -> [Option<([F; N], Matrix<F>)>; 2] {
        let pos = self.position(load_n.to_f64());
        if !(pos >= 0.0 && pos < (TABLE_LEN - 1) as f64) {
            return [None, None];
        }
        let i = pos as usize;
        let (near, far) = if pos - i as f64 <= 0.5 { (i, i + 1) } else { (i + 1, i) };
        let entry = |k: usize| self.ok[fi][k].then(|| (self.entries[fi][k].x, self.entries[fi][k].inverse));
        [entry(near), entry(far)]
    }
}
