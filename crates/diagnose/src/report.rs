//! The diagnosis report: its fields, its JSON form (`--report report.json`, and what Python
//! returns) and its text form (stdout).

use super::data::Column;
use super::residual::Dependence;
use super::select::{self, Trial};
use super::terms::Effect;
use crate::outcome::{Calibrated, Finding, Metrics, Series};
use ballscrew_core::input::{Lubrication, ScrewSpec};
use serde_json::{Map, Value, json};

/// Residual amplitude (N m) per harmonic of the lead.
pub type Periodogram = Vec<(u32, f64)>;

/// Everything a diagnosis found.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// Data rows.
    pub rows: usize,
    /// Columns present.
    pub columns: Vec<Column>,
    /// Warnings about the data, and about calibrated values out of their physical range.
    pub warnings: Vec<String>,
    /// Distinct (preload, axial load, direction) points the model was evaluated at.
    pub distinct_points: usize,
    /// Folds of the cross-validation.
    pub folds: usize,
    /// The spec's friction coefficient (of the dry contacts).
    pub spec_friction_coefficient: f64,
    /// The spec's creep reduction.
    pub spec_creep_reduction: f64,
    /// Calibrated friction coefficient (no extension); under `lubrication = "ehl"` the spec's,
    /// not fitted (it does not act on the raceway contacts: see `calibration`).
    pub friction_coefficient: f64,
    /// Calibrated creep reduction.
    pub creep_reduction: f64,
    /// The spec's model as it stands (no held-out value: nothing is fitted).
    pub spec_model: Metrics,
    /// The calibrated model.
    pub baseline: Metrics,
    /// The calibrated model's residual against each operating column.
    pub residuals: Vec<Dependence>,
    /// Every candidate; `Some(reason)` when the data cannot show it.
    pub candidates: Vec<(Effect, Option<String>)>,
    /// The candidates tried at each step of the selection.
    pub steps: Vec<Vec<Trial>>,
    /// Terms kept, in order of selection.
    pub findings: Vec<Finding>,
    /// The extended model (calibrated + findings).
    pub extended: Metrics,
    /// Friction coefficient of the extended model.
    pub extended_friction_coefficient: f64,
    /// The model's contacts: lubricated (the level is the lubricant's full-film traction) or
    /// dry (the level is f).
    pub lubrication: Lubrication,
    /// The fitted physical parameters (the level parameter, then the creep reduction), with
    /// their fit bounds and physical ranges.
    pub calibration: Vec<Calibrated>,
    /// Why the lubricated model's level is off (its calibrated level parameter out of its
    /// physical range or on a bound of the fit), when it is.
    pub level_off: Option<String>,
    /// Relative cut of the held-out RMSE, extended against calibrated.
    pub gain: f64,
    /// Structure left in the extended model's residual.
    pub remaining: Vec<String>,
    /// Residual amplitude (N m) at harmonics of the lead along the position: (calibrated,
    /// extended), when the position is present.
    pub periodogram: Option<(Periodogram, Periodogram)>,
    /// Per-row predictions (for figures; not in the JSON).
    pub series: Series,
    /// The calibrated, extended spec.
    pub extended_spec: ScrewSpec,
}

fn metrics_json(m: &Metrics) -> Value {
    json!({"bias_nm": m.bias_nm, "rmse_nm": m.rmse_nm, "heldout_rmse_nm": m.heldout_rmse_nm})
}

fn pairs(p: &[(&'static str, f64)]) -> Value {
    Value::Object(p.iter().map(|(k, v)| ((*k).to_string(), json!(v))).collect::<Map<String, Value>>())
}

impl Report {
    /// The names of the findings, in order.
    pub fn effects(&self) -> Vec<&'static str> {
        self.findings.iter().map(|f| f.effect.name()).collect()
    }

    /// The calibrated full-film traction (`lubrication = "ehl"`): (spec, calibrated, extended).
    pub fn full_film_traction(&self) -> Option<(f64, f64, f64)> {
        self.calibration.iter().find(|c| c.name == "full_film_traction").map(|c| (c.spec, c.calibrated, c.extended))
    }

    /// One line: what was found.
    pub fn verdict(&self) -> String {
        let found = self.found();
        match &self.level_off {
            Some(why) => format!("the model's level is off ({why}); {found}"),
            None => found,
        }
    }

    fn found(&self) -> String {
        let level = match self.full_film_traction() {
            Some((_, mu, _)) => format!("full-film traction = {mu:.4}"),
            None => format!("f = {:.4}", self.friction_coefficient),
        };
        if self.findings.is_empty() {
            format!(
                "no missing effect found: the calibrated model ({level}) explains the data to a held-out RMSE of {:.4e} N m",
                self.baseline.heldout_rmse_nm
            )
        } else {
            format!(
                "missing effect(s): {}; held-out RMSE {:.4e} -> {:.4e} N m ({:.1} % less)",
                self.effects().join(", "),
                self.baseline.heldout_rmse_nm,
                self.extended.heldout_rmse_nm,
                100.0 * self.gain
            )
        }
    }

    /// The report as JSON.
    pub fn to_json(&self) -> Value {
        let findings: Vec<Value> = self
            .findings
            .iter()
            .map(|f| {
                json!({
                    "effect": f.effect.name(),
                    "main_parameter": f.effect.main_parameter(),
                    "parameters": pairs(&f.parameters),
                    "heldout_rmse_before_nm": f.heldout_before_nm,
                    "heldout_rmse_after_nm": f.heldout_after_nm,
                    "delta_bic": f.delta_bic,
                    "evidence": f.evidence,
                })
            })
            .collect();
        let residuals: Vec<Value> = self
            .residuals
            .iter()
            .map(|d| {
                json!({
                    "column": d.column.name(),
                    "correlation": d.correlation,
                    "slope_nm_per_unit": d.slope_nm_per_unit,
                    "serial_correlation": d.serial_correlation,
                    "bins": d.bins.iter().map(|b| json!({"from": b.0, "to": b.1, "mean_residual_nm": b.2, "rows": b.3})).collect::<Vec<_>>(),
                    "sentence": d.sentence,
                })
            })
            .collect();
        let candidates: Vec<Value> = self
            .candidates
            .iter()
            .map(|(e, why)| {
                let first = self.steps.first().and_then(|s| s.iter().find(|t| t.effect == *e));
                json!({
                    "effect": e.name(),
                    "evaluated": why.is_none(),
                    "reason": why,
                    "first_step_heldout_rmse_nm": first.map(|t| t.heldout_rmse_nm),
                    "first_step_delta_bic": first.map(|t| t.delta_bic),
                })
            })
            .collect();
        let steps: Vec<Value> = self
            .steps
            .iter()
            .map(|s| {
                Value::Array(
                    s.iter()
                        .map(|t| json!({"effect": t.effect.name(), "heldout_rmse_nm": t.heldout_rmse_nm, "delta_bic": t.delta_bic}))
                        .collect(),
                )
            })
            .collect();
        let pg = self.periodogram.as_ref().map(|(b, e)| {
            json!({
                "harmonic": b.iter().map(|p| p.0).collect::<Vec<_>>(),
                "baseline_amplitude_nm": b.iter().map(|p| p.1).collect::<Vec<_>>(),
                "extended_amplitude_nm": e.iter().map(|p| p.1).collect::<Vec<_>>(),
            })
        });
        let calibration: Vec<Value> = self
            .calibration
            .iter()
            .map(|c| {
                json!({
                    "name": c.name,
                    "spec_field": c.spec_field,
                    "spec": c.spec,
                    "calibrated": c.calibrated,
                    "extended": c.extended,
                    "fit_bounds": [c.fit_bounds.0, c.fit_bounds.1],
                    "physical_range": c.physical_range.map(|r| [r.0, r.1]),
                    "within_physical_range": c.physical_range.map(|(lo, hi)| (lo..=hi).contains(&c.extended)),
                })
            })
            .collect();
        let mu = self.full_film_traction();
        json!({
            "rows": self.rows,
            "lubrication": self.lubrication.name(),
            "calibration": calibration,
            "model_level_off": self.level_off,
            "columns": self.columns.iter().map(|c| c.name()).collect::<Vec<_>>(),
            "warnings": self.warnings,
            "distinct_operating_points": self.distinct_points,
            "folds": self.folds,
            "selection_rule": select::rule(self.folds),
            "spec_model": {"friction_coefficient": self.spec_friction_coefficient, "creep_reduction": self.spec_creep_reduction,
                           "full_film_traction": mu.map(|m| m.0),
                           "bias_nm": self.spec_model.bias_nm, "rmse_nm": self.spec_model.rmse_nm},
            "baseline": {
                "friction_coefficient": self.friction_coefficient,
                "creep_reduction": self.creep_reduction,
                "spec_friction_coefficient": self.spec_friction_coefficient,
                "spec_creep_reduction": self.spec_creep_reduction,
                "full_film_traction": mu.map(|m| m.1),
                "spec_full_film_traction": mu.map(|m| m.0),
                "bias_nm": self.baseline.bias_nm,
                "rmse_nm": self.baseline.rmse_nm,
                "heldout_rmse_nm": self.baseline.heldout_rmse_nm,
            },
            "residuals": residuals,
            "candidates": candidates,
            "steps": steps,
            "findings": findings,
            "extended": {"friction_coefficient": self.extended_friction_coefficient, "creep_reduction": self.creep_reduction,
                         "full_film_traction": mu.map(|m| m.2),
                         "metrics": metrics_json(&self.extended), "heldout_rmse_nm": self.extended.heldout_rmse_nm},
            "gain": {"heldout_rmse_cut": self.gain,
                     "heldout_rmse_before_nm": self.baseline.heldout_rmse_nm,
                     "heldout_rmse_after_nm": self.extended.heldout_rmse_nm},
            "remaining_structure": self.remaining,
            "position_periodogram": pg,
            "verdict": self.verdict(),
        })
    }

    /// The report as text for people.
    pub fn to_text(&self) -> String {
        let mut s = String::new();
        let mut line = |t: String| {
            s.push_str(&t);
            s.push('\n');
        };
        line(format!(
            "ballscrew diagnose: {} rows, columns {}; {} distinct operating point{}, {}-fold cross-validation",
            self.rows,
            self.columns.iter().map(|c| c.name()).collect::<Vec<_>>().join(", "),
            self.distinct_points,
            if self.distinct_points == 1 { "" } else { "s" },
            self.folds
        ));
        for w in &self.warnings {
            line(format!("warning: {w}"));
        }
        line(String::new());
        line(format!("Calibration (spec -> fitted; {} contacts):", self.lubrication.name()));
        match self.full_film_traction() {
            Some((spec, mu, _)) => {
                line(format!("  full-film traction       {spec:.4} -> {mu:.4}"));
                line(format!(
                    "  friction coefficient f   {:.4} (not fitted: no effect on lubricated raceway contacts)",
                    self.spec_friction_coefficient
                ));
            }
            None => line(format!(
                "  friction coefficient f   {:.4} -> {:.4}",
                self.spec_friction_coefficient, self.friction_coefficient
            )),
        }
        line(format!("  creep reduction kappa    {:.3} -> {:.3}", self.spec_creep_reduction, self.creep_reduction));
        for c in &self.calibration {
            let physical = c.physical_range.map_or("none stated".to_string(), |(lo, hi)| format!("[{lo}, {hi}]"));
            line(format!(
                "  {:<24} fit bounds [{:.4}, {:.4}], physical range {physical}",
                c.name, c.fit_bounds.0, c.fit_bounds.1
            ));
        }
        line(format!(
            "  spec model:  bias {:+.4e} N m, RMSE {:.4e} N m",
            self.spec_model.bias_nm, self.spec_model.rmse_nm
        ));
        line(format!(
            "  calibrated:  bias {:+.4e} N m, RMSE {:.4e} N m, held-out RMSE {:.4e} N m",
            self.baseline.bias_nm, self.baseline.rmse_nm, self.baseline.heldout_rmse_nm
        ));
        line(String::new());
        line("What the calibrated model gets wrong (residual = model - measured, times the sign of the speed):".into());
        for d in &self.residuals {
            line(format!("  {}", d.sentence));
        }
        line(String::new());
        line("Candidates:".into());
        for (e, why) in &self.candidates {
            match why {
                Some(r) => line(format!("  {:<20} not evaluated: {r}", e.name())),
                None => {
                    let t = self.steps.first().and_then(|st| st.iter().find(|t| t.effect == *e));
                    line(format!(
                        "  {:<20} first step: held-out RMSE {}, BIC {}",
                        e.name(),
                        t.map_or("-".into(), |t| format!("{:.4e} N m", t.heldout_rmse_nm)),
                        t.map_or("-".into(), |t| format!("{:+.1}", t.delta_bic))
                    ))
                }
            }
        }
        line(String::new());
        line(format!("Selection rule: {}.", select::rule(self.folds)));
        line(String::new());
        if self.findings.is_empty() {
            line("Findings: none.".into());
        } else {
            line("Findings (in order of selection):".into());
            for (i, f) in self.findings.iter().enumerate() {
                let p: Vec<String> =
                    f.parameters.iter().map(|(k, v)| format!("{k} = {}", parameter_text(*v))).collect();
                line(format!("  {}. {} ({})", i + 1, f.effect.name(), p.join(", ")));
                line(format!("     {}", f.evidence));
            }
        }
        line(String::new());
        let level = match self.full_film_traction() {
            Some((_, _, mu)) => format!("full-film traction = {mu:.4}"),
            None => format!("f = {:.4}", self.extended_friction_coefficient),
        };
        line(format!(
            "Extended model: {level}, RMSE {:.4e} N m, held-out RMSE {:.4e} N m; gain {:.1} % of the held-out RMSE",
            self.extended.rmse_nm,
            self.extended.heldout_rmse_nm,
            100.0 * self.gain
        ));
        if self.remaining.is_empty() {
            line("Remaining structure: none found along any column.".into());
        } else {
            for r in &self.remaining {
                line(format!("Remaining structure {r}."));
            }
        }
        line(String::new());
        line(self.verdict());
        s
    }
}

/// A fitted parameter as text: a whole number (a harmonic's order) as one (`2`, not `2.0000`),
/// others to four decimals.
fn parameter_text(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e9 { format!("{v:.0}") } else { format!("{v:.4}") }
}

#[cfg(test)]
mod text_tests {
    use super::parameter_text;

    #[test]
    fn whole_parameters_show_as_whole_numbers() {
        assert_eq!(parameter_text(2.0), "2");
        assert_eq!(parameter_text(0.123456), "0.1235");
        assert_eq!(parameter_text(-3.0), "-3");
    }
}
