//! Seeded synthetic measurements from the project's own model (shared by `tests/diagnose.rs`
//! and `benches/diagnose.rs`).
//!
//! The DKFZD4012 screw of Table 1 with its level parameter drawn from 0.02-0.045 (the
//! lubricant's full-film traction under the default lubricated model, the friction coefficient
//! f under `lubrication = "dry"`) and its creep reduction from 0.6-1, one hidden effect (a term of `ballscrew_core::input::extensions`,
//! evaluated by `Model::torque_at`), Gaussian noise of 3 % of each torque. Design: 8 repeat
//! groups (`repeat`), each a sweep of 6 preloads (500-3000 N) x 8 speeds (10-2500 rpm, both
//! directions) at random nut positions along a 400 mm stroke, every group at its own
//! temperature (15-65 degrees C) and running time (0-980 h); with `with_axial`, axial loads of
//! 0-1000 N. Each row's torque is the core's own route of `Model::torque_at` (the creep model at
//! the terms' effective operating point, then the terms), with the creep model solved once per
//! distinct effective operating point (checked against `Model::torque_at` on the first row).
//! splitmix64 and Box-Muller rather than the `rand` crate: the streams are fixed by
//! this file alone, and nothing else needs randomness.

extern crate alloc;

use alloc::collections::BTreeMap;
use ballscrew_core::contact::creep::{direction, standstill_factor};
use ballscrew_core::input::extensions::Extensions;
use ballscrew_core::input::rpm_to_rad_s;
use ballscrew_core::{Conditions, Lubrication, Model, OperatingPoint, ScrewSpec, SolverState};

/// splitmix64 with Box-Muller normals.
pub struct Rng(pub u64);

impl Rng {
    /// Next 64 random bits.
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.uniform()
    }

    /// Standard normal (Box-Muller).
    pub fn normal(&mut self) -> f64 {
        let u1 = self.uniform().max(1e-300);
        let u2 = self.uniform();
        (-2.0 * u1.ln()).sqrt() * (2.0 * core::f64::consts::PI * u2).cos()
    }
}

pub const PRELOADS: [f64; 6] = [500.0, 1000.0, 1500.0, 2000.0, 2500.0, 3000.0];
pub const SPEEDS: [f64; 8] = [10.0, -10.0, 300.0, -300.0, 1000.0, -1000.0, 2500.0, -2500.0];
pub const AXIAL: [f64; 4] = [0.0, 250.0, 500.0, 1000.0];
pub const GROUPS: usize = 8;
pub const NOISE: f64 = 0.03;

/// A generated dataset and the true level parameter.
pub struct Synthetic {
    /// The CSV text.
    pub csv: String,
    /// The true level parameter: the full-film traction (lubricated model) or the friction
    /// coefficient (dry model).
    #[allow(dead_code)] // read by the tests, not by the benchmark
    pub true_level: f64,
}

/// A dataset with the hidden terms `ext` from the default (lubricated) DKFZD4012 model.
pub fn generate(seed: u64, ext: Extensions, with_axial: bool) -> Synthetic {
    generate_from(ScrewSpec::dkfzd4012(), seed, ext, with_axial)
}

/// A dataset with the hidden terms `ext` from `spec` (its level parameter and creep reduction
/// drawn).
#[allow(dead_code)] // used by the tests, not by the benchmark
pub fn generate_from(spec: ScrewSpec, seed: u64, ext: Extensions, with_axial: bool) -> Synthetic {
    generate_scaled(spec, seed, ext, with_axial, true, 1.0)
}

#[allow(dead_code)] // used by the tests, not by the benchmark
/// A dataset with the hidden terms `ext` from `spec`, its creep model's drag (the torque less
/// the load torque) times `factor` before the terms act: with `draw`, its level parameter and
/// creep reduction drawn as [`generate_from`] draws them; without, `spec`'s own.
pub fn generate_scaled(
    spec: ScrewSpec,
    seed: u64,
    ext: Extensions,
    with_axial: bool,
    draw: bool,
    factor: f64,
) -> Synthetic {
    generate_noisy(spec, seed, ext, with_axial, draw, factor, NOISE)
}

#[allow(dead_code)] // used by the tests, not by the benchmark
/// [`generate_scaled`] with Gaussian noise of `noise` times each torque (instead of
/// [`NOISE`]): the same seed draws the same normals, so the noise of two datasets of one seed
/// differs by the ratio of their `noise` alone.
pub fn generate_noisy(
    mut spec: ScrewSpec,
    seed: u64,
    ext: Extensions,
    with_axial: bool,
    draw: bool,
    factor: f64,
    noise: f64,
) -> Synthetic {
    let mut rng = Rng(seed);
    if draw {
        let level = rng.range(0.02, 0.045);
        match spec.model.lubrication {
            Lubrication::Ehl => spec.lubricant.full_film_traction = level,
            Lubrication::Dry => spec.friction.coefficient = level,
        }
        spec.friction.creep_reduction = rng.range(0.6, 1.0);
    }
    let level = match spec.model.lubrication {
        Lubrication::Ehl => spec.lubricant.full_film_traction,
        Lubrication::Dry => spec.friction.coefficient,
    };
    spec.extensions = ext;
    let model = Model::new(&spec).expect("generator spec");
    let mut plain = spec;
    plain.extensions = Extensions::NONE;
    let plain = Model::new(&plain).expect("generator spec");
    let mut cache: BTreeMap<[u64; 3], (f64, f64)> = BTreeMap::new();
    let mut state = SolverState::new();
    let mut first = true;
    let mut csv = String::from("torque_nm,preload_n,speed_rpm,position_mm,temperature_c,time_h,repeat");
    csv.push_str(if with_axial { ",axial_load_n\n" } else { "\n" });
    for g in 0..GROUPS {
        let temperature = 15.0 + 50.0 * g as f64 / (GROUPS - 1) as f64 + rng.range(-2.0, 2.0);
        let time = 140.0 * g as f64;
        for &p in &PRELOADS {
            for &s in &SPEEDS {
                let axial = if with_axial { AXIAL[(rng.next() % 4) as usize] } else { 0.0 };
                let position = rng.range(0.0, 400.0);
                let op = OperatingPoint { speed_rad_s: rpm_to_rad_s(s), preload_n: p, axial_load_n: axial };
                let cond = Conditions { position_m: position / 1000.0, temperature_c: Some(temperature), time_h: time };
                let eff = ext.effective_operating(&op, &cond);
                let key = [eff.preload_n.to_bits(), eff.axial_load_n.to_bits(), eff.speed_rad_s.to_bits()];
                let (t, ax) = *cache.entry(key).or_insert_with(|| {
                    let s = plain.summary(&eff, &mut state).expect("generator point");
                    (s.axial_term_nm + factor * (s.torque_nm - s.axial_term_nm), s.axial_term_nm)
                });
                let motion =
                    direction(op.speed_rad_s) * standstill_factor(op.speed_rad_s, spec.friction.standstill_speed_rad_s);
                let t =
                    if ext.is_empty() { t } else { ext.torque_nm(t, ax, &eff, &cond, spec.geometry.lead_m, motion) };
                if first && factor == 1.0 {
                    let direct = model.torque_at(&op, &cond, &mut SolverState::new()).expect("generator point");
                    assert!((t - direct).abs() <= 1e-9 * direct.abs(), "generator route: {t} vs {direct}");
                    first = false;
                }
                let measured = t + noise * t.abs() * rng.normal();
                csv.push_str(&format!("{measured},{p},{s},{position},{temperature},{time},{g}"));
                csv.push_str(&if with_axial { format!(",{axial}\n") } else { "\n".into() });
            }
        }
    }
    Synthetic { csv, true_level: level }
}
