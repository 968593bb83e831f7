//! Held-out error and forward selection of the candidate terms.
//!
//! Folds: [`FOLDS`]-fold cross-validation; rows of one `repeat` group stay in one fold; the
//! assignment is a fixed pseudo-random shuffle, so a diagnosis is reproducible. In each fold the
//! whole structure (f and every term) is refitted on the other folds and predicts the held-out
//! rows; the held-out RMSE pools the held-out residuals of all folds.
//!
//! Selection rule: terms are added one at a time; at each step every remaining applicable
//! candidate is tried, and the one with the lowest held-out RMSE is kept only when it cuts the
//! current held-out RMSE by at least [`MIN_CUT`] and lowers the Bayesian information criterion
//! of the fit on all rows, `n ln(RSS / n) + p ln n`, by at least [`MIN_DELTA_BIC`] ("very strong"
//! evidence on the scale of Kass and Raftery, 1995). Between candidates whose held-out RMSE is
//! within [`TIE`] of the best, the one with fewer parameters wins.

use super::creep_cache::Watch;
use super::model::Structure;
use super::terms::Effect;

/// Folds of the cross-validation.
pub const FOLDS: usize = 5;
/// Smallest relative cut of the held-out RMSE for a term to be kept.
pub const MIN_CUT: f64 = 0.05;
/// Largest change of BIC for a term to be kept (negative: the criterion must fall).
pub const MIN_DELTA_BIC: f64 = -10.0;
/// Held-out RMSEs within this relative distance count as a tie (parsimony decides).
pub const TIE: f64 = 0.01;

/// The rule in words, for the report of a diagnosis with `folds` folds ([`FOLDS`], fewer when
/// the data has fewer `repeat` groups).
pub fn rule(folds: usize) -> String {
    format!(
        "forward selection: at each step the candidate with the lowest {folds}-fold held-out RMSE (folds grouped by \
         `repeat` when present; the level parameter, f or the full-film traction, and the level factor when kept, refitted in every fold) is kept only if it cuts the held-out RMSE of the level-calibrated model by at least {:.0} % \
         and lowers the BIC (n ln(RSS/n) + p ln n, all rows) by at least {:.0}; candidates within {:.0} % of the best \
         held-out RMSE count as tied and the one with fewer parameters wins (the creep reduction and the waviness \
         harmonic are chosen once on all rows, not per fold)",
        MIN_CUT * 100.0,
        -MIN_DELTA_BIC,
        TIE * 100.0
    )
}

/// splitmix64: a fixed, portable shuffle.
fn splitmix(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Fold of every row: groups (by `repeat`, or one group per row) shuffled and dealt round-robin.
pub fn folds(rows: usize, repeat: Option<&[f64]>) -> (Vec<usize>, usize) {
    let group: Vec<u64> = match repeat {
        Some(r) => r.iter().map(|v| v.to_bits()).collect(),
        None => (0..rows as u64).collect(),
    };
    let mut ids: Vec<u64> = group.clone();
    ids.sort_unstable();
    ids.dedup();
    let k = FOLDS.min(ids.len()).max(2);
    let mut state = 0x5EED_u64;
    for i in (1..ids.len()).rev() {
        let j = (splitmix(&mut state) % (i as u64 + 1)) as usize;
        ids.swap(i, j);
    }
    let fold_of = |g: u64| ids.iter().position(|&x| x == g).unwrap_or(0) % k;
    (group.iter().map(|&g| fold_of(g)).collect(), k)
}

/// Held-out RMSE of a structure and every held-out prediction (in row order).
pub fn heldout<W: Watch>(s: &Structure<'_, W>, fold: &[usize], k: usize, f_start: f64) -> (f64, Vec<f64>) {
    let mut predictions = Vec::new();
    for j in 0..k {
        // A cancelled diagnosis ends without this value (it reads the flag at its end).
        if s.physics.cancelled() {
            break;
        }
        predictions.extend(fold_predictions(s, fold, j, f_start));
    }
    heldout_rmse(s, predictions)
}

/// Fold `j`'s held-out predictions: the structure fitted on the rows of the other folds,
/// predicted at this fold's rows (row index, torque N m).
pub fn fold_predictions<W: Watch>(s: &Structure<'_, W>, fold: &[usize], j: usize, f_start: f64) -> Vec<(usize, f64)> {
    let n = fold.len();
    let train: Vec<usize> = (0..n).filter(|&i| fold[i] != j).collect();
    let test: Vec<usize> = (0..n).filter(|&i| fold[i] == j).collect();
    if test.is_empty() {
        return Vec::new();
    }
    let fit = s.fit(&train, f_start);
    test.iter().copied().zip(s.predict(&fit.x, &test)).collect()
}

/// Held-out RMSE of the held-out `predictions` (row index, torque N m; a row without one
/// counts as predicted 0) and every row's prediction (in row order).
pub fn heldout_rmse<W: Watch>(s: &Structure<'_, W>, predictions: Vec<(usize, f64)>) -> (f64, Vec<f64>) {
    let n = s.rows.torque.len();
    let mut pred = vec![0.0; n];
    for (i, p) in predictions {
        pred[i] = p;
    }
    let sse: f64 = (0..n).map(|i| (pred[i] - s.rows.torque[i]).powi(2)).sum();
    ((sse / n as f64).sqrt(), pred)
}

/// BIC of a fit with `p` parameters on `n` rows.
pub fn bic(rss: f64, n: usize, p: usize) -> f64 {
    let n = n as f64;
    n * (rss.max(1e-300) / n).ln() + p as f64 * n.ln()
}

/// One candidate tried at one step.
#[derive(Debug, Clone, PartialEq)]
pub struct Trial {
    /// The candidate.
    pub effect: Effect,
    /// Held-out RMSE with it, N m.
    pub heldout_rmse_nm: f64,
    /// Held-out RMSE of the model it was tried against (the level-calibrated model with the
    /// terms kept before), N m.
    pub heldout_before_nm: f64,
    /// Change of BIC on all rows.
    pub delta_bic: f64,
}

impl Trial {
    /// The share of the held-out RMSE it cuts (negative when it adds to it).
    pub fn heldout_gain(&self) -> f64 {
        1.0 - self.heldout_rmse_nm / self.heldout_before_nm
    }
}

/// Picks the best trial (lowest held-out RMSE, parsimony within [`TIE`]).
pub fn best(trials: &[Trial]) -> Option<&Trial> {
    let min = trials.iter().map(|t| t.heldout_rmse_nm).fold(f64::INFINITY, f64::min);
    trials.iter().filter(|t| t.heldout_rmse_nm <= min * (1.0 + TIE)).min_by(|a, b| {
        a.effect.parameters().cmp(&b.effect.parameters()).then(a.heldout_rmse_nm.total_cmp(&b.heldout_rmse_nm))
    })
}

/// Whether a trial passes the rule against the current held-out RMSE.
pub fn passes(t: &Trial, current_heldout: f64) -> bool {
    cuts(t.heldout_rmse_nm, t.delta_bic, current_heldout)
}

/// The rule on its numbers: a held-out RMSE `heldout` at least [`MIN_CUT`] below
/// `current_heldout`, and a BIC that falls by at least [`MIN_DELTA_BIC`] (the level factor's
/// test as well as every term's).
pub fn cuts(heldout: f64, delta_bic: f64, current_heldout: f64) -> bool {
    heldout <= (1.0 - MIN_CUT) * current_heldout && delta_bic <= MIN_DELTA_BIC
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rule states the folds of the diagnosis it describes.
    #[test]
    fn the_rule_states_the_folds_used() {
        assert!(rule(4).contains("lowest 4-fold held-out RMSE") && !rule(4).contains("5-fold"), "{}", rule(4));
        assert!(rule(FOLDS).contains(&format!("{FOLDS}-fold")));
    }

    #[test]
    fn folds_keep_repeat_groups_together_and_cover_every_fold() {
        let rep: Vec<f64> = (0..40).map(|i| (i / 4) as f64).collect();
        let (f, k) = folds(40, Some(&rep));
        assert_eq!(k, FOLDS);
        for g in 0..10 {
            let s = &f[g * 4..g * 4 + 4];
            assert!(s.iter().all(|&x| x == s[0]));
        }
        for j in 0..k {
            assert!(f.contains(&j));
        }
        assert_eq!(folds(40, Some(&rep)), (f, k), "reproducible");
    }

    #[test]
    fn ties_go_to_the_simpler_term_and_the_rule_needs_both_tests() {
        let t = |effect, h, b| Trial { effect, heldout_rmse_nm: h, heldout_before_nm: 1.0, delta_bic: b };
        let trials = [t(Effect::ThermalViscosity, 0.0100, -50.0), t(Effect::ViscousDrag, 0.01005, -48.0)];
        assert_eq!(best(&trials).unwrap().effect, Effect::ViscousDrag);
        assert!(passes(&t(Effect::SealDrag, 0.9, -11.0), 1.0));
        assert!(!passes(&t(Effect::SealDrag, 0.97, -50.0), 1.0));
        assert!(!passes(&t(Effect::SealDrag, 0.5, -5.0), 1.0));
    }
}
