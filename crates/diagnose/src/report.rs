//! The diagnosis report: its fields, its JSON form (`--report report.json`, and what Python
//! returns) and its text form (stdout).

use super::data::Column;
use super::residual::Dependence;
use super::select::{self, Trial};
use super::terms::Effect;
use crate::outcome::{BandNarrowing, Calibrated, Finding, LevelFinding, Metrics, Reading, Series};
use crate::text::{sig, torque_text};
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
    /// The data's level against the model, and what carries it.
    pub level: LevelFinding,
    /// Why the model's level is off (a level factor kept that no physical value of the level
    /// parameters carries), when it is.
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
    /// The calibrated, extended spec (its `[uncertainty]`: the fit's spread of the inputs it
    /// calibrated, [`crate::calibrated_uncertainty`]).
    pub extended_spec: ScrewSpec,
    /// How much the data narrowed the band of the drag torque at the data's median point.
    pub band_narrowing: BandNarrowing,
}

fn metrics_json(m: &Metrics) -> Value {
    json!({
        "bias_nm": finite(m.bias_nm),
        "bias_forward_nm": finite(m.bias_forward_nm),
        "bias_reverse_nm": finite(m.bias_reverse_nm),
        "rmse_nm": m.rmse_nm,
        "heldout_rmse_nm": finite(m.heldout_rmse_nm),
        "level_ratio": finite(m.level_ratio),
        "level_ratio_interval": [finite(m.level_ratio_interval.0), finite(m.level_ratio_interval.1)],
    })
}

/// A number for JSON: `null` when not finite.
fn finite(v: f64) -> Value {
    if v.is_finite() { json!(v) } else { Value::Null }
}

fn range_text((lo, hi): (f64, f64)) -> String {
    format!("{}-{}", sig(lo), sig(hi))
}

fn reading_text(r: &Reading) -> String {
    let range = r.range.map_or(String::new(), |g| {
        let side = if r.physical() { "within" } else { "outside" };
        format!(", {side} its physical range {}", range_text(g))
    });
    format!("{} {} -> {}{range}", r.name.replace('_', " "), sig(r.spec), sig(r.value))
}

impl LevelFinding {
    /// Why a kept factor is not carried physically: a reading out of its range, or readings in
    /// range whose model does not reproduce the factor's drag.
    fn not_carried(&self) -> String {
        let readings = self.readings.iter().map(reading_text).collect::<Vec<_>>().join(", ");
        if self.readings.iter().all(Reading::physical) {
            format!(
                "the oil's friction coefficients times that factor stay within their ranges ({readings}) but the model \
                 there does not reproduce the factor's drag ({} RMS apart)",
                torque_text(self.reading_rms_nm)
            )
        } else {
            format!("no physical value of the oil's friction carries that ({readings})")
        }
    }

    /// The level in one sentence (the verdict's reason when the model's level is off).
    pub fn sentence(&self) -> String {
        let spec = format!(
            "measured over the spec model's drag {} (95 % interval {})",
            sig(self.spec_ratio),
            range_text(self.spec_ratio_interval)
        );
        let readings = self.readings.iter().map(reading_text).collect::<Vec<_>>().join(", ");
        match self.factor {
            None if !self.differs => format!("the data are at the spec model's level: {spec}"),
            None => format!(
                "the data's level differs from the spec model's ({spec}) and the calibration carries it: {readings}"
            ),
            Some((k, lo, hi)) if self.absorbed => format!(
                "the data are {} times the calibrated model's drag (level factor, 95 % interval {}; {spec}); the \
                 oil's friction coefficients times that factor carry it within their physical ranges: {readings}",
                sig(k),
                range_text((lo, hi))
            ),
            Some((k, lo, hi)) => {
                let (side, times) = if k >= 1.0 { ("below", k) } else { ("above", 1.0 / k) };
                format!(
                    "calibrated within its physical ranges, the model is {} times {side} this screw (level factor {}, \
                     95 % interval {}; {spec}): {}",
                    sig(times),
                    sig(k),
                    range_text((lo, hi)),
                    self.not_carried()
                )
            }
        }
    }
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

    /// The calibrated level in a few words: the level parameter and the level factor when kept
    /// (the figures' labels, the verdict).
    pub fn calibrated_label(&self) -> String {
        let mut label = match self.full_film_traction() {
            Some((_, _, mu)) => format!("full-film traction {}", sig(mu)),
            None => format!("f {}", sig(self.extended_friction_coefficient)),
        };
        if let Some(c) = self.calibration.iter().find(|c| c.name == "boundary_friction") {
            label.push_str(&format!(", boundary friction {}", sig(c.extended)));
        }
        if self.creep_reduction != self.spec_creep_reduction {
            label.push_str(&format!(", creep reduction {}", sig(self.creep_reduction)));
        }
        if let Some((k, _, _)) = self.level.factor {
            label.push_str(&format!(", level factor {}", sig(k)));
        }
        label
    }

    fn found(&self) -> String {
        if self.findings.is_empty() {
            format!(
                "no missing effect found: the level-calibrated model ({}) explains the data to a held-out RMSE of {}",
                self.calibrated_label(),
                torque_text(self.baseline.heldout_rmse_nm)
            )
        } else {
            format!(
                "missing effect(s): {}; held-out RMSE {} -> {} ({:.0} % less)",
                self.effects().join(", "),
                torque_text(self.baseline.heldout_rmse_nm),
                torque_text(self.extended.heldout_rmse_nm),
                100.0 * self.gain
            )
        }
    }

    /// Whether the physical calibration (no level factor) changed the model materially: its RMSE
    /// at least [`select::MIN_CUT`] below the spec model's.
    fn calibration_moved(&self) -> bool {
        self.level.factor.is_none() && self.baseline.rmse_nm <= (1.0 - select::MIN_CUT) * self.spec_model.rmse_nm
    }

    /// The report's first paragraph, for a person: what was found about the level and beyond
    /// it, how sure, and what to check on the machine.
    pub fn summary(&self) -> String {
        let mut out = Vec::new();
        let l = &self.level;
        let readings = l.readings.iter().map(reading_text).collect::<Vec<_>>().join(", ");
        let everywhere = if self.distinct_points > 1 { " at every operating point of the data" } else { "" };
        match l.factor {
            None if !l.differs && !self.calibration_moved() => out.push(format!(
                "The screw's drag is at the level of the spec's model: measured over modelled {} (95 % interval {}).",
                sig(l.spec_ratio),
                range_text(l.spec_ratio_interval)
            )),
            None => out.push(format!(
                "The screw's drag is {} times the spec model's (95 % interval {}), and the model's own parameters \
                 carry the difference within their physical ranges ({readings}; RMSE {} -> {}), so check the spec: \
                 the oil (grade, temperature, friction) and the preload against the values the calibration found.",
                sig(l.spec_ratio),
                range_text(l.spec_ratio_interval),
                torque_text(self.spec_model.rmse_nm),
                torque_text(self.baseline.rmse_nm)
            )),
            Some((k, lo, hi)) if l.absorbed => out.push(format!(
                "The screw's drag is {} times the calibrated model's{everywhere} (level factor, 95 % interval {}; the \
                 spec's model: {} times): a level, not a missing effect. The oil's friction coefficients times that \
                 factor stay physical and reproduce it to {} ({readings}), so check the spec: the oil (grade, \
                 temperature), the preload, the circuit.",
                sig(k),
                range_text((lo, hi)),
                sig(l.spec_ratio),
                torque_text(l.reading_rms_nm)
            )),
            Some((k, lo, hi)) => {
                let (side, times) = if k >= 1.0 { ("below", k) } else { ("above", 1.0 / k) };
                out.push(format!(
                    "Calibrated within its physical ranges, the model is {} times {side} this screw{everywhere} \
                     (level factor {}, 95 % interval {}; the spec's model: measured over modelled {}), and {}. Check \
                     the spec (oil grade and temperature, preload, circuit); if it is right, the factor is the model's \
                     known gap to real screws, not a missing effect.",
                    sig(times),
                    sig(k),
                    range_text((lo, hi)),
                    sig(l.spec_ratio),
                    l.not_carried()
                ));
            }
        }
        if self.findings.is_empty() {
            let best = self.steps.first().and_then(|t| select::best(t));
            out.push(match best {
                Some(t) => format!(
                    "No effect beyond the level explains the data on rows the fit never saw: the best candidate, {}, \
                     cuts the held-out error by {:.0} % where {:.0} % is needed.",
                    t.effect.name(),
                    (100.0 * t.heldout_gain()).round() + 0.0,
                    100.0 * select::MIN_CUT
                ),
                None => "None of the candidate effects can be evaluated on these data (see Candidates).".to_string(),
            });
        } else {
            for f in &self.findings {
                let main = f.effect.main_parameter();
                let value = f.parameters.iter().find(|(k, _)| *k == main).map_or(f64::NAN, |p| p.1);
                out.push(format!(
                    "Beyond the level the data show {}, {main} = {}, which cuts the error on rows the fit never saw \
                     by {:.0} %: {}.",
                    f.effect.meaning(),
                    sig(value),
                    100.0 * (1.0 - f.heldout_after_nm / f.heldout_before_nm),
                    f.effect.action()
                ));
            }
        }
        let drag = self.series.measured.iter().map(|m| m.abs()).sum::<f64>() / self.rows.max(1) as f64;
        out.push(format!(
            "The {} model's error on rows its fit never saw is {} ({:.1} % of the mean measured torque).",
            if self.findings.is_empty() { "level-calibrated" } else { "extended" },
            torque_text(self.extended.heldout_rmse_nm),
            100.0 * self.extended.heldout_rmse_nm / drag
        ));
        if !self.remaining.is_empty() {
            out.push(format!(
                "Structure no candidate explains is left {}.",
                self.remaining.iter().map(|r| r.split(':').next().unwrap_or(r)).collect::<Vec<_>>().join(", ")
            ));
        }
        out.join(" ")
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
                    "first_step_heldout_gain": first.map(|t| t.heldout_gain()),
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
                        .map(|t| {
                            json!({"effect": t.effect.name(), "heldout_rmse_nm": t.heldout_rmse_nm,
                                        "heldout_rmse_before_nm": t.heldout_before_nm, "heldout_gain": t.heldout_gain(),
                                        "delta_bic": t.delta_bic})
                        })
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
                    "standard_error": finite(c.standard_error),
                    "standard_error_note": c.standard_error_note,
                })
            })
            .collect();
        let mu = self.full_film_traction();
        let l = &self.level;
        let boundary = self.calibration.iter().find(|c| c.name == "boundary_friction");
        let level = json!({
            "spec_ratio": finite(l.spec_ratio),
            "spec_ratio_interval": [finite(l.spec_ratio_interval.0), finite(l.spec_ratio_interval.1)],
            "differs": l.differs,
            "factor": l.factor.map(|f| f.0),
            "factor_interval": l.factor.map(|f| [f.1, f.2]),
            "factor_trial": {"heldout_rmse_without_nm": l.trial.0, "heldout_rmse_with_nm": l.trial.1, "delta_bic": l.trial.2},
            "readings": l.readings.iter().map(|r| json!({
                "name": r.name, "spec_field": r.spec_field, "spec": r.spec, "value": r.value,
                "physical_range": r.range.map(|g| [g.0, g.1]), "within_physical_range": r.physical(),
            })).collect::<Vec<_>>(),
            "absorbed": l.absorbed,
            "reading_rms_nm": finite(l.reading_rms_nm),
            "sentence": l.sentence(),
        });
        json!({
            "summary": self.summary(),
            "level": level,
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
                           "bias_nm": finite(self.spec_model.bias_nm), "rmse_nm": self.spec_model.rmse_nm,
                           "metrics": metrics_json(&self.spec_model)},
            "baseline": {
                "friction_coefficient": self.friction_coefficient,
                "creep_reduction": self.creep_reduction,
                "spec_friction_coefficient": self.spec_friction_coefficient,
                "spec_creep_reduction": self.spec_creep_reduction,
                "full_film_traction": mu.map(|m| m.1),
                "spec_full_film_traction": mu.map(|m| m.0),
                "boundary_friction": boundary.map(|c| c.calibrated),
                "level_factor": self.calibration.iter().find(|c| c.name == "level_factor").map(|c| c.calibrated),
                "bias_nm": finite(self.baseline.bias_nm),
                "rmse_nm": self.baseline.rmse_nm,
                "heldout_rmse_nm": self.baseline.heldout_rmse_nm,
                "metrics": metrics_json(&self.baseline),
            },
            "residuals": residuals,
            "candidates": candidates,
            "steps": steps,
            "findings": findings,
            "extended": {"friction_coefficient": self.extended_friction_coefficient, "creep_reduction": self.creep_reduction,
                         "full_film_traction": mu.map(|m| m.2),
                         "boundary_friction": boundary.map(|c| c.extended),
                         "level_factor": self.level.factor.map(|f| f.0),
                         "metrics": metrics_json(&self.extended), "heldout_rmse_nm": self.extended.heldout_rmse_nm},
            "gain": {"heldout_rmse_cut": self.gain,
                     "heldout_rmse_before_nm": self.baseline.heldout_rmse_nm,
                     "heldout_rmse_after_nm": self.extended.heldout_rmse_nm},
            "remaining_structure": self.remaining,
            "band_narrowing": self.band_json(),
            "position_periodogram": pg,
            "verdict": self.verdict(),
        })
    }

    fn band_json(&self) -> Value {
        let b = &self.band_narrowing;
        json!({
            "point": {"speed_rpm": b.speed_rpm, "preload_n": b.preload_n, "axial_load_n": b.axial_load_n},
            "quantiles": [ballscrew_batch::uncertainty::DEFAULT_QUANTILES.0, ballscrew_batch::uncertainty::DEFAULT_QUANTILES.1],
            "samples": ballscrew_batch::uncertainty::DEFAULT_SAMPLES,
            "seed": ballscrew_batch::uncertainty::DEFAULT_SEED,
            "spec_band": [finite(b.spec_band.0), finite(b.spec_band.2)],
            "spec_median": finite(b.spec_band.1),
            "calibrated_band": [finite(b.calibrated_band.0), finite(b.calibrated_band.2)],
            "calibrated_median": finite(b.calibrated_band.1),
            "width_ratio": finite(b.width_ratio()),
            "relative_width_ratio": finite(b.relative_width_ratio()),
            "calibrated_half_widths": Value::Object(
                self.calibration
                    .iter()
                    .filter_map(|c| {
                        let (i, _) = c.uncertain_input()?;
                        let key = ballscrew_core::input::UNCERTAIN_INPUTS[i].key;
                        Some((key.to_string(), json!(self.extended_spec.uncertainty.half_widths[i])))
                    })
                    .collect::<Map<String, Value>>()
            ),
            "note": b.note,
        })
    }

    /// The band line of the text report.
    pub fn band_text(&self) -> String {
        let b = &self.band_narrowing;
        let band = |v: (f64, f64, f64)| format!("{}-{} N m (median {})", sig(v.0), sig(v.2), sig(v.1));
        let mut t = format!(
            "Band of the drag torque (5-95 %, {} samples, seed {}) at the data's median point ({} rpm, preload {} N, \
             axial load {} N): input spec {}, calibrated spec {}; width ratio {} (of the widths over the medians {})",
            ballscrew_batch::uncertainty::DEFAULT_SAMPLES,
            ballscrew_batch::uncertainty::DEFAULT_SEED,
            sig(b.speed_rpm),
            sig(b.preload_n),
            sig(b.axial_load_n),
            band(b.spec_band),
            band(b.calibrated_band),
            sig(b.width_ratio()),
            sig(b.relative_width_ratio())
        );
        if let Some(n) = &b.note {
            t.push_str(&format!(" ({n})"));
        }
        t
    }

    /// The report as text for people: the summary paragraph first, then the evidence.
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
        line(wrap(&self.summary(), 100));
        line(String::new());
        line(format!("Calibration of the level (spec -> fitted; {} contacts):", self.lubrication.name()));
        for c in &self.calibration {
            let physical = c.physical_range.map_or("none stated".to_string(), range_text);
            let values = if c.extended != c.calibrated {
                format!("{} -> {} (extended model {})", sig(c.spec), sig(c.calibrated), sig(c.extended))
            } else {
                format!("{} -> {}", sig(c.spec), sig(c.calibrated))
            };
            let error = match c.standard_error_note {
                None => format!("standard error {}", sig(c.standard_error)),
                Some(why) => format!("standard error n/a ({why})"),
            };
            line(format!(
                "  {:<22} {values}; fit bounds {}, physical range {physical}; {error}",
                c.name,
                range_text(c.fit_bounds)
            ));
        }
        if self.full_film_traction().is_some() {
            line(format!(
                "  friction coefficient f {} (not fitted: no effect on lubricated raceway contacts)",
                sig(self.spec_friction_coefficient)
            ));
        }
        let (without, with, dbic) = self.level.trial;
        line(format!(
            "  level factor's trial: held-out RMSE {} without, {} with it, BIC {:+.0}: {}",
            torque_text(without),
            torque_text(with),
            dbic,
            if self.level.factor.is_some() { "kept" } else { "not kept" }
        ));
        line(format!("  level: {}", self.level.sentence()));
        line(format!("  {}", self.band_text()));
        line(String::new());
        line("Against the data (bias = model - measured along the motion; level = measured / model drag):".into());
        for (name, m) in
            [("spec model", &self.spec_model), ("calibrated", &self.baseline), ("extended", &self.extended)]
        {
            line(format!("  {name:<11} {}", metrics_text(m)));
        }
        line(String::new());
        line("What the calibrated model gets wrong (residual = model - measured, times the sign of the speed):".into());
        for d in &self.residuals {
            line(format!("  {}", d.sentence));
        }
        line(String::new());
        line("Candidates (held-out gain against the level-calibrated model at the first step):".into());
        for (e, why) in &self.candidates {
            match why {
                Some(r) => line(format!("  {:<20} not evaluated: {r}", e.name())),
                None => {
                    let t = self.steps.first().and_then(|st| st.iter().find(|t| t.effect == *e));
                    line(format!(
                        "  {:<20} first step: held-out RMSE {}, gain {}, BIC {}",
                        e.name(),
                        t.map_or("-".into(), |t| torque_text(t.heldout_rmse_nm)),
                        t.map_or("-".into(), |t| format!("{:.1} %", 100.0 * t.heldout_gain())),
                        t.map_or("-".into(), |t| format!("{:+.0}", t.delta_bic))
                    ))
                }
            }
        }
        line(String::new());
        line(format!("Selection rule: {}.", select::rule(self.folds)));
        line(String::new());
        if self.findings.is_empty() {
            line("Findings beyond the level: none.".into());
        } else {
            line("Findings beyond the level (in order of selection):".into());
            for (i, f) in self.findings.iter().enumerate() {
                let p: Vec<String> =
                    f.parameters.iter().map(|(k, v)| format!("{k} = {}", parameter_text(*v))).collect();
                line(format!("  {}. {} ({})", i + 1, f.effect.name(), p.join(", ")));
                line(format!("     {}", f.evidence));
                line(format!("     what to check: {}", f.effect.action()));
            }
        }
        line(String::new());
        line(format!(
            "Extended model: {}, RMSE {}, held-out RMSE {}; gain {:.0} % of the held-out RMSE",
            self.calibrated_label(),
            torque_text(self.extended.rmse_nm),
            torque_text(self.extended.heldout_rmse_nm),
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

/// One model's metrics on a line, numbers short with their units.
fn metrics_text(m: &Metrics) -> String {
    let bias = |v: f64| if v.is_finite() { torque_text(v) } else { "-".into() };
    let heldout = if m.heldout_rmse_nm.is_finite() {
        format!(", held-out RMSE {}", torque_text(m.heldout_rmse_nm))
    } else {
        String::new()
    };
    format!(
        "bias {} (forward {}, reverse {}), RMSE {}{heldout}, level {} ({})",
        bias(m.bias_nm),
        bias(m.bias_forward_nm),
        bias(m.bias_reverse_nm),
        torque_text(m.rmse_nm),
        sig(m.level_ratio),
        range_text(m.level_ratio_interval)
    )
}

/// `text` broken into lines of at most `width` characters at spaces.
fn wrap(text: &str, width: usize) -> String {
    let mut out = String::new();
    let mut len = 0;
    for w in text.split(' ') {
        if len > 0 && len + 1 + w.len() > width {
            out.push('\n');
            len = 0;
        } else if len > 0 {
            out.push(' ');
            len += 1;
        }
        out.push_str(w);
        len += w.len();
    }
    out
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
