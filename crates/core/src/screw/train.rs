//! The ball train of a circuit: the loads between neighbouring balls.
//!
//! In a circuit the balls follow each other round the loaded turn and back through the return;
//! they cannot orbit at different mean speeds. The loaded balls push the return's balls
//! against its resistance ([`crate::input::circulation`]): the chain force is zero at the one
//! gap the train's clearance leaves open (behind the first loaded ball) and grows along the
//! loaded balls to the resistance `R` where the return begins. Where the free orbit rates of
//! a circuit's balls differ (circles of one circuit carrying different loads), the faster push
//! the slower as well: their chain is [`chain_of_pushes`] of the balls' pushes, and what sets
//! the pushes (every ball at one orbit rate) is [`crate::screw::circuit`]'s balance.
//!
//! # The chain force
//!
//! Walking along the travel from the contact behind the first loaded ball, the chain force after
//! ball `j` is `C_j = c - S_j`, `S_j` the sum of the pushes up to `j` (the push of a ball: the
//! load of its contact behind less that of its contact ahead; the return's balls each needing
//! `R / n_r`), `S` back to zero after the return. The gap is where `S` is largest: `c = max S`,
//! so every `C >= 0` and one contact carries none. With one state for all the loaded balls of a
//! circuit (one loaded turn, no ramp) each is pushed by `P = -R / n`, and `C_j = j R / n`: a
//! ball, representing all of them, carries the mean loads `R (n + 1) / (2 n)` ahead and
//! `R (n - 1) / (2 n)` behind (the torque is linear in them at a given state).
//!
//! # Friction at the contacts
//!
//! Neighbouring balls turn the same way, so at their contact the surfaces slide past each other
//! at about `2 r_b omega_R`, with zero entrainment speed: no film forms, and the friction is the
//! lubricant's boundary value (dry: the spec's coefficient), [`crate::screw::model::Model::ball_ball_mu`].
//! The two contacts between a loaded ball and a ball of the return carry the chain force but no
//! friction: the return's ball turns freely and rolls on its neighbour. So every contact whose
//! friction a ball's balance carries is carried by both its balls (as action and reaction),
//! and the energy balance of the screw equals the moment about its axis.
//!
//! # The return's share
//!
//! The chain delivers to the return the power `R v cos(chi)`, `v` the balls' speed along the
//! helix and `chi` the angle between the helix and the chord between neighbouring centres, along
//! which the balls push each other: the return path's share of the drag torque.

use crate::ball::setup::BallSetup;
use crate::input::MAX_CIRCLES_PER_NUT;
use crate::input::circulation::MAX_LOAD_RAMP_BALLS;

/// Most segments (balls of one state, in the order of travel) of a chain: a nut's circles and
/// the balls of a load ramp at each end ([`crate::input::circulation`]).
pub const MAX_SEGMENTS: usize = MAX_CIRCLES_PER_NUT + 2 * MAX_LOAD_RAMP_BALLS as usize;

/// The loads of one segment's ball.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SegmentLoads {
    /// Push forwards (N): the contact behind less the contact ahead.
    pub push_n: f64,
    /// Mean load of the contact ahead of each ball of the segment, N.
    pub ahead_n: f64,
    /// Mean load of the contact behind each ball of the segment, N.
    pub behind_n: f64,
    /// Mean load of the contacts ahead whose friction the balls carry, N: the contact between
    /// the last loaded ball and the return's first carries none.
    pub ahead_friction_n: f64,
    /// Mean load of the contacts behind whose friction the balls carry, N (none at the contact
    /// with the return's last ball).
    pub behind_friction_n: f64,
}

/// The chain of a circuit: each segment's loads and the chain force along it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Chain {
    /// Each segment's loads.
    pub loads: [SegmentLoads; MAX_SEGMENTS],
    /// The chain force at the contact behind each segment's first ball, and (at index
    /// `segments`) behind the return's first ball, N.
    pub entry_n: [f64; MAX_SEGMENTS + 1],
    /// Largest chain force along the circuit, N.
    pub max_n: f64,
    /// Segments.
    pub segments: usize,
}

/// The chain whose segments of `balls` balls each push forwards by `pushes` (N; the return's
/// balls take the rest): the loads of every contact, the gap where the running sum of the
/// pushes is largest (the module's documentation).
pub fn chain_of_pushes(balls: &[f64], pushes: &[f64]) -> Chain {
    chain_with_gap(balls, pushes, None)
}

/// The segment at whose entry the running sum of `pushes` (on segments of `balls` balls) is
/// largest: where [`chain_of_pushes`] opens the gap.
pub fn gap_of_pushes(balls: &[f64], pushes: &[f64]) -> usize {
    let n = balls.len().min(pushes.len()).min(MAX_SEGMENTS);
    let (mut sum, mut highest, mut gap) = (0.0, 0.0, 0);
    for i in 0..n {
        if sum > highest {
            (highest, gap) = (sum, i);
        }
        sum += balls[i] * pushes[i];
    }
    gap
}

/// [`chain_of_pushes`] with the gap at the entry of segment `gap` when given: the chain force
/// is then linear in the pushes, and a load may come out negative where the gap given is not
/// where the running sum is largest (what a solve with the gap held uses between its checks).
pub fn chain_with_gap(balls: &[f64], pushes: &[f64], gap: Option<usize>) -> Chain {
    let n = balls.len().min(pushes.len()).min(MAX_SEGMENTS);
    let clip = |v: f64| if gap.is_some() { v } else { v.max(0.0) };
    let mut out = Chain { segments: n, ..Chain::default() };
    if n == 0 {
        return out;
    }
    // The running sum of the pushes at each segment's entry; its largest value (the return
    // brings it back to zero) sets the gap.
    let mut entry = [0.0; MAX_SEGMENTS + 1];
    let mut sum = 0.0;
    let mut highest: f64 = 0.0;
    for i in 0..n {
        entry[i] = sum;
        sum += balls[i] * pushes[i];
        highest = highest.max(sum);
    }
    entry[n] = sum;
    if let Some(g) = gap {
        highest = entry[g.min(n)];
    }
    let mut max: f64 = 0.0;
    for (i, &e) in entry.iter().enumerate().take(n + 1) {
        // Rounding may leave a load a few ulps below zero at the gap.
        out.entry_n[i] = clip(highest - e);
        max = max.max(out.entry_n[i]);
    }
    for i in 0..n {
        let ahead = clip(highest - (entry[i] + 0.5 * (balls[i] + 1.0) * pushes[i]));
        let behind = clip(ahead + pushes[i]);
        // The contacts with the return's balls carry no friction: the loaded train's first
        // ball's contact behind, its last ball's contact ahead.
        let ahead_friction = if i == n - 1 { clip(ahead - out.entry_n[n] / balls[i]) } else { ahead };
        let behind_friction = if i == 0 { clip(behind - out.entry_n[0] / balls[i]) } else { behind };
        out.loads[i] = SegmentLoads {
            push_n: pushes[i],
            ahead_n: ahead,
            behind_n: behind,
            ahead_friction_n: ahead_friction,
            behind_friction_n: behind_friction,
        };
    }
    out.max_n = max;
    out
}

/// The train of a circuit of one loaded turn of `balls` balls in one state pushing a return of
/// resistance `resistance_n` (N).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Circuit {
    /// Balls in the loaded turn.
    pub balls: f64,
    /// The return's resistance, N (with the standstill factor).
    pub resistance_n: f64,
    /// Each loaded ball's (mean) loads.
    pub loads: SegmentLoads,
    /// Cosine of the angle between the helix and the chord between neighbouring centres.
    pub chord_cos: f64,
}

impl Circuit {
    /// The circuit of `balls` loaded balls, neighbours `spacing_rad` apart on a helix of pitch
    /// radius `rm_m` (m) and lead per radian `lead_per_rad_m` (m), pushing a return of
    /// resistance `resistance_n` (N).
    pub fn new(balls: f64, resistance_n: f64, spacing_rad: f64, rm_m: f64, lead_per_rad_m: f64) -> Self {
        let chain = chain_of_pushes(&[balls], &[-resistance_n / balls]);
        let (s, h) = (spacing_rad, lead_per_rad_m);
        let across = 2.0 * rm_m * libm::sin(0.5 * s);
        let chord = libm::sqrt(across * across + h * h * s * s);
        let chord_cos = (rm_m * rm_m * libm::sin(s) + h * h * s) / (chord * libm::sqrt(rm_m * rm_m + h * h));
        Self { balls, resistance_n, loads: chain.loads[0], chord_cos }
    }

    /// Whether any contact carries load.
    pub fn is_loaded(&self) -> bool {
        self.resistance_n > 0.0
    }

    /// The loads (normal at +spacing, at -spacing; their friction's loads) of a ball travelling
    /// towards +theta (`forwards`) or -theta.
    pub fn plus_minus(&self, forwards: bool) -> ((f64, f64), (f64, f64)) {
        let l = &self.loads;
        let ahead = (l.ahead_n, l.ahead_friction_n);
        let behind = (l.behind_n, l.behind_friction_n);
        if forwards { (ahead, behind) } else { (behind, ahead) }
    }

    /// Sets the ball-ball loads of `setup` to this circuit's, for a ball travelling towards
    /// +theta (`forwards`) or -theta.
    pub fn apply(&self, setup: &mut BallSetup, forwards: bool) {
        let ((plus, plus_f), (minus, minus_f)) = self.plus_minus(forwards);
        setup.ball_ball_plus_n = plus;
        setup.ball_ball_minus_n = minus;
        setup.ball_ball_plus_friction_n = plus_f;
        setup.ball_ball_minus_friction_n = minus_f;
    }

    /// The return's share of the dissipation per unit screw speed (N m) at the balls' orbit rate
    /// `orbit` (rad per rad of the screw) on a helix of pitch radius `rm_m` and lead per radian
    /// `lead_per_rad_m` (m): `R v cos(chi) / omega`, positive.
    pub fn return_dissipation_per_speed(&self, orbit: f64, rm_m: f64, lead_per_rad_m: f64) -> f64 {
        let path = libm::sqrt(rm_m * rm_m + lead_per_rad_m * lead_per_rad_m);
        self.resistance_n * self.chord_cos * libm::fabs(orbit) * path
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// No resistance: no load anywhere.
    #[test]
    fn a_circuit_without_resistance_carries_no_load() {
        let c = Circuit::new(19.0, 0.0, 0.3, 0.02, 0.002);
        assert_eq!(c.loads, SegmentLoads::default());
        assert!(!c.is_loaded());
    }

    /// One state shares the resistance evenly: the chain force rises from zero at the gap
    /// (behind the first loaded ball) to R where the return begins; the mean loads are
    /// R (n + 1) / (2 n) ahead and R (n - 1) / (2 n) behind; the contacts with the return carry
    /// no friction; every load >= 0.
    #[test]
    fn one_state_pushes_the_return() {
        let r = 0.019;
        let c = chain_of_pushes(&[19.0], &[-r / 19.0]);
        assert_eq!(c.entry_n[0], 0.0);
        assert!((c.entry_n[1] - r).abs() < 1e-15);
        let l = c.loads[0];
        assert!((l.push_n + 0.001).abs() < 1e-15);
        assert!((l.ahead_n - r * 20.0 / 38.0).abs() < 1e-15);
        assert!((l.behind_n - r * 18.0 / 38.0).abs() < 1e-15);
        assert!((l.ahead_friction_n - r * 18.0 / 38.0).abs() < 1e-15);
        assert!((l.behind_friction_n - r * 18.0 / 38.0).abs() < 1e-15);
        // The contacts whose friction the balls carry appear once ahead and once behind.
        assert!((l.ahead_friction_n - l.behind_friction_n).abs() < 1e-15);
    }

    /// Segments that push each other: the pushes balance against the return, every load is
    /// >= 0, one contact (the gap) carries none, the largest force where the pushes turn.
    #[test]
    fn the_chain_force_follows_the_pushes() {
        let c = chain_of_pushes(&[19.0, 19.0, 19.0], &[-0.1, 0.02, 0.07]);
        let least = c.entry_n[..4].iter().fold(f64::INFINITY, |m, &e| m.min(e));
        assert_eq!(least, 0.0);
        // The running sum: 0, -1.9, -1.52, -0.19; its largest value 0 at the first entry.
        assert!((c.max_n - 1.9).abs() < 1e-12);
        for l in &c.loads[..3] {
            assert!(l.ahead_n >= 0.0 && l.behind_n >= 0.0 && l.ahead_friction_n >= 0.0);
            assert!((l.behind_n - l.ahead_n - l.push_n).abs() < 1e-12);
        }
    }

    /// The chord's cosine: 1 for neighbours that touch on a straight line, cos(s / 2) on a
    /// flat circle.
    #[test]
    fn the_chord_lies_at_half_the_spacing_on_a_circle() {
        let c = Circuit::new(19.0, 0.01, 0.3, 0.02, 0.0);
        assert!((c.chord_cos - libm::cos(0.15)).abs() < 1e-15);
        let c = Circuit::new(19.0, 0.01, 1e-9, 0.02, 0.002);
        assert!((c.chord_cos - 1.0).abs() < 1e-9);
    }
}
