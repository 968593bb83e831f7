//! One FMU instance in safe Rust: the spec's evaluator (`ballscrew_core::Evaluator`, f64) with
//! its warm state, the inputs, the outputs and FMI's life cycle (instantiated, initialization
//! mode, step mode, terminated). A spec the evaluator does not take (the four-point balls of an
//! oversize-ball nut, FASTSIM contacts) runs on the model's own solve instead, warm-started the
//! same way (`ballscrew_core::Model::torque` with its `SolverState`): the torques of
//! `ballscrew torque` at each point, at the model's cost (about 0.2 ms a warm step for a four-point
//! screw, against 10 to 20 us for the evaluator).
//!
//! The outputs are algebraic in the inputs (direct feedthrough): a set of an input or of the
//! preload marks them stale, and they are evaluated once when next needed: at the end of
//! initialization, at a step (`fmi2DoStep`), or when an output is read. Each evaluation is
//! warm-started from the one before, exactly as `Evaluator.series` of the Python module runs a
//! time series, so the FMU and a series over the same points give the same torques (on the
//! model's path, as `Model::torque` with one `SolverState` over the points). Nothing is
//! allocated on the way of a successful set, step or get; an error carries its message.
//!
//! The warm evaluations follow the screw's history and may sit on another steady state of the
//! balls than a stateless request reports (docs/model-notes.md item 24). The instance audits
//! its first evaluation and every [`AUDIT_EVERY`]-th after it (`ballscrew_core::realtime::audit`:
//! a cold solve of the model, compared); an evaluation that departs from the canonical state by
//! more than 1e-6 of the drag torque makes the call that evaluated it return `fmi2Warning`,
//! its message in the importer's log (the only allocation of a successful call).

use ballscrew_config::spec_from_toml_str;
use ballscrew_core::realtime::audit::{self, Audit};
use ballscrew_core::{Model, OperatingPoint, Shown, Stepper};
use core::f64::consts::PI;

use crate::variables::{self, AXIAL_LOAD_N, Causality, PRELOAD_N, SPEED_RAD_S};

/// FMI's status codes (`fmi2Status`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// All well.
    Ok = 0,
    /// Something to note; the results are usable.
    Warning = 1,
    /// The call was not carried out; the instance is usable.
    Discard = 2,
    /// The call failed.
    Error = 3,
    /// The instance is unusable.
    Fatal = 4,
    /// An asynchronous step is still running (never returned here).
    Pending = 5,
}

/// A failed call: its status and the message logged for it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Fault {
    /// The status returned.
    pub status: Status,
    /// What went wrong, for the importer's log.
    pub message: String,
}

impl Fault {
    /// An `fmi2Error` with `message`.
    pub fn error(message: impl Into<String>) -> Self {
        Self { status: Status::Error, message: message.into() }
    }

    /// An `fmi2Discard` with `message`.
    pub fn discard(message: impl Into<String>) -> Self {
        Self { status: Status::Discard, message: message.into() }
    }
}

/// Where an instance is in FMI's life cycle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// After `fmi2Instantiate` or `fmi2Reset`.
    Instantiated,
    /// Between `fmi2EnterInitializationMode` and `fmi2ExitInitializationMode`.
    Initialization,
    /// After `fmi2ExitInitializationMode`: steps.
    StepMode,
    /// After `fmi2Terminate`.
    Terminated,
}

impl Phase {
    fn name(self) -> &'static str {
        match self {
            Phase::Instantiated => "instantiated",
            Phase::Initialization => "initialization mode",
            Phase::StepMode => "step mode",
            Phase::Terminated => "terminated",
        }
    }
}

/// The outputs at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outputs {
    /// Drive torque, N m.
    pub torque_nm: f64,
    /// Drag torque, N m.
    pub drag_torque_nm: f64,
    /// Load torque, N m.
    pub load_torque_nm: f64,
    /// Dissipated power, W.
    pub dissipated_power_w: f64,
}

/// What the outputs hold.
#[derive(Debug, Clone, PartialEq)]
enum Computed {
    /// The outputs at the current inputs.
    Fresh(Outputs),
    /// An input or the preload was set since the last evaluation.
    Stale,
    /// The last evaluation failed: why.
    Failed(String),
}

/// How far, relative to the time reached (or 1 s), a step may start before that time: the
/// rounding of an importer that adds its step sizes up differently.
pub const TIME_TOLERANCE_REL: f64 = 1e-9;

/// Evaluations between two audited ones (the first is audited): a cold solve of the model,
/// about 0.5 ms, per 1000 warm evaluations of 10 to 20 us.
pub const AUDIT_EVERY: u32 = 1000;

/// One instance of the FMU.
pub struct Instance {
    /// What evaluates the torque, with its warm state.
    solver: Box<Stepper<f64>>,
    /// The audit of its evaluations against the canonical state.
    audit: Audit,
    /// A departure found by the last evaluation, for the importer's log.
    warning: Option<String>,
    /// The spec's operating point: the start values.
    start: OperatingPoint,
    /// Lead of the screw, m (for the load torque).
    lead_m: f64,
    /// The inputs and the preload as set.
    point: OperatingPoint,
    computed: Computed,
    phase: Phase,
    /// The communication point reached, s.
    time_s: f64,
}

impl Instance {
    /// An instance of the spec in TOML text `text` (named `origin` in messages): the spec
    /// parsed and validated, and the evaluator built (milliseconds; for a spec the evaluator does
    /// not take, the model readied: [`ballscrew_core::Evaluator::supports`]). The error is the message
    /// of the spec's parser or of the core.
    pub fn from_spec_text(text: &str, origin: &str) -> Result<Self, String> {
        let spec = spec_from_toml_str(text, origin).map_err(|e| match e {
            // Parse and I/O errors name the origin already.
            ballscrew_config::ConfigError::Parse { .. } | ballscrew_config::ConfigError::Io { .. } => e.to_string(),
            _ => format!("{origin}: {e}"),
        })?;
        let model = Model::new(&spec).map_err(|e| format!("{origin}: {e}"))?;
        // Four-point balls, FASTSIM: the model solves them ([`Stepper::new`]).
        let solver = Box::new(Stepper::new(&model).map_err(|e| format!("{origin}: {e}"))?);
        Ok(Self {
            solver,
            audit: Audit::new(AUDIT_EVERY, audit::F64_TOLERANCE).map_err(|e| e.to_string())?,
            warning: None,
            start: spec.operating,
            lead_m: spec.geometry.lead_m,
            point: spec.operating,
            computed: Computed::Stale,
            phase: Phase::Instantiated,
            time_s: 0.0,
        })
    }

    /// What evaluates the torque: "evaluator" (the control-loop evaluator) or "model" (the
    /// model's own solve, for a spec the evaluator does not take).
    pub fn solver_name(&self) -> &'static str {
        self.solver.name()
    }

    /// The instance with its evaluations audited every `every`-th (0: none; the first is
    /// audited), in place of [`AUDIT_EVERY`].
    pub fn audited_every(mut self, every: u32) -> Self {
        self.audit = Audit::new(every, self.audit.tolerance()).unwrap_or(self.audit);
        self
    }

    /// What the audit of the evaluations found so far.
    pub fn audit(&self) -> &Audit {
        &self.audit
    }

    /// The warning of the last call, if its evaluation departed from the canonical state (taken:
    /// the next call has none until it departs).
    pub fn take_warning(&mut self) -> Option<String> {
        self.warning.take()
    }

    /// Where the instance is in its life cycle.
    pub fn phase(&self) -> Phase {
        self.phase
    }

    /// The communication point reached, s (`fmi2LastSuccessfulTime`).
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// The current inputs and preload.
    pub fn point(&self) -> OperatingPoint {
        self.point
    }

    /// An error unless the instance is in one of `phases`.
    fn expect(&self, call: &str, phases: &[Phase]) -> Result<(), Fault> {
        if phases.contains(&self.phase) {
            Ok(())
        } else {
            Err(Fault::error(format!("{call} is not allowed when the instance is {}", self.phase.name())))
        }
    }

    /// `fmi2SetupExperiment`: the start time, s (finite).
    pub fn setup_experiment(&mut self, start_time_s: f64) -> Result<(), Fault> {
        self.expect("fmi2SetupExperiment", &[Phase::Instantiated])?;
        if !start_time_s.is_finite() {
            return Err(Fault::error(format!("invalid startTime: {} (valid: finite), s", Shown(start_time_s))));
        }
        self.time_s = start_time_s;
        Ok(())
    }

    /// `fmi2EnterInitializationMode`.
    pub fn enter_initialization(&mut self) -> Result<(), Fault> {
        self.expect("fmi2EnterInitializationMode", &[Phase::Instantiated])?;
        self.phase = Phase::Initialization;
        Ok(())
    }

    /// `fmi2ExitInitializationMode`: the outputs at the initial inputs.
    pub fn exit_initialization(&mut self) -> Result<(), Fault> {
        self.expect("fmi2ExitInitializationMode", &[Phase::Initialization])?;
        self.phase = Phase::StepMode;
        self.refresh().map(drop)
    }

    /// `fmi2DoStep` from `current_s` over `step_s` (s): the outputs at the inputs as set (held
    /// over the step), evaluated if an input or the preload was set since the last evaluation.
    pub fn do_step(&mut self, current_s: f64, step_s: f64) -> Result<(), Fault> {
        self.expect("fmi2DoStep", &[Phase::StepMode])?;
        if !current_s.is_finite() {
            return Err(Fault::error(format!(
                "invalid currentCommunicationPoint: {} (valid: finite), s",
                Shown(current_s)
            )));
        }
        if !(step_s >= 0.0) || !step_s.is_finite() {
            return Err(Fault::error(format!(
                "invalid communicationStepSize: {} (valid: finite, >= 0), s",
                Shown(step_s)
            )));
        }
        // The warm state is the screw's history: a step cannot start before the time reached
        // (this FMU cannot get or set its state to go back). Rounding of the importer's sum of
        // steps is let through.
        if current_s < self.time_s - TIME_TOLERANCE_REL * self.time_s.abs().max(1.0) {
            return Err(Fault::error(format!(
                "invalid currentCommunicationPoint: {} s, before the time reached, {} s (valid: from the time \
                 reached on; this FMU cannot go back in time: fmi2Reset starts again)",
                Shown(current_s),
                Shown(self.time_s)
            )));
        }
        self.refresh()?;
        self.time_s = current_s + step_s;
        Ok(())
    }

    /// `fmi2Terminate`.
    pub fn terminate(&mut self) -> Result<(), Fault> {
        self.expect("fmi2Terminate", &[Phase::StepMode, Phase::Initialization])?;
        self.phase = Phase::Terminated;
        Ok(())
    }

    /// `fmi2Reset`: back to the state after instantiation (start values, no warm state).
    pub fn reset(&mut self) {
        self.solver.reset();
        self.audit.reset();
        self.warning = None;
        self.point = self.start;
        self.computed = Computed::Stale;
        self.phase = Phase::Instantiated;
        self.time_s = 0.0;
    }

    /// Sets the variable of value reference `vr` to `value`: an input or the preload, checked
    /// (finite, within the core's range: the error names the variable, the value and the valid
    /// range). The outputs are then stale.
    pub fn set_real(&mut self, vr: u32, value: f64) -> Result<(), Fault> {
        let Some(var) = variables::variable(vr) else {
            return Err(unknown(vr));
        };
        if var.causality == Causality::Output {
            return Err(Fault::error(format!("{} (value reference {vr}) is an output: it cannot be set", var.name)));
        }
        if self.phase == Phase::Terminated {
            return Err(Fault::error(format!("cannot set {}: the instance is terminated", var.name)));
        }
        let mut point = self.point;
        match vr {
            SPEED_RAD_S => point.speed_rad_s = value,
            AXIAL_LOAD_N => point.axial_load_n = value,
            PRELOAD_N => point.preload_n = value,
            _ => return Err(unknown(vr)),
        }
        point.validate().map_err(|e| Fault::error(e.to_string()))?;
        self.point = point;
        self.computed = Computed::Stale;
        Ok(())
    }

    /// The value of the variable of value reference `vr`: an input or the preload as set, or an
    /// output (evaluated first if stale; an error if its evaluation failed, never a number).
    pub fn get_real(&mut self, vr: u32) -> Result<f64, Fault> {
        let Some(var) = variables::variable(vr) else {
            return Err(unknown(vr));
        };
        let outputs = match var.causality {
            Causality::Input | Causality::TunableParameter => {
                return Ok(match vr {
                    SPEED_RAD_S => self.point.speed_rad_s,
                    AXIAL_LOAD_N => self.point.axial_load_n,
                    _ => self.point.preload_n,
                });
            }
            Causality::Output => {
                if self.phase == Phase::Instantiated {
                    return Err(Fault::error(format!(
                        "{} is computed from initialization mode on (the instance is instantiated)",
                        var.name
                    )));
                }
                self.refresh()?
            }
        };
        Ok(match vr {
            variables::TORQUE_NM => outputs.torque_nm,
            variables::DRAG_TORQUE_NM => outputs.drag_torque_nm,
            variables::LOAD_TORQUE_NM => outputs.load_torque_nm,
            _ => outputs.dissipated_power_w,
        })
    }

    /// The outputs at the current point, evaluated if stale (warm-started from the last
    /// evaluation); the error of the last evaluation if it failed.
    fn refresh(&mut self) -> Result<Outputs, Fault> {
        match &self.computed {
            Computed::Fresh(o) => return Ok(*o),
            Computed::Failed(why) => return Err(Fault::error(why.clone())),
            Computed::Stale => {}
        }
        let p = self.point;
        let result = self.solver.torque_nm(&p);
        let outputs = result.map_err(|e| e.to_string()).and_then(|torque_nm| {
            // The load torque as the model sums it (`Summary::load_torque_nm`).
            let load_torque_nm = p.axial_load_n * self.lead_m / (2.0 * PI);
            let drag_torque_nm = torque_nm - load_torque_nm;
            let o = Outputs {
                torque_nm,
                drag_torque_nm,
                load_torque_nm,
                dissipated_power_w: drag_torque_nm * p.speed_rad_s,
            };
            let all = [o.torque_nm, o.drag_torque_nm, o.load_torque_nm, o.dissipated_power_w];
            if all.iter().all(|v| v.is_finite()) {
                Ok(o)
            } else {
                Err(format!("the evaluation gave a non-finite torque ({})", Shown(torque_nm)))
            }
        });
        match outputs {
            Ok(o) => {
                self.computed = Computed::Fresh(o);
                if let Some(d) = self.audit.check(self.solver.model(), &p, o.torque_nm) {
                    self.warning = Some(format!(
                        "the torque at speed_rad_s = {}, preload_n = {}, axial_load_n = {} departs from the canonical \
                         state (the model's cold solve, what `ballscrew torque` gives): {d}; the warm evaluation follows \
                         the screw's history and sits on another steady state of the balls ({} of {} audited evaluations \
                         so far)",
                        Shown(p.speed_rad_s),
                        Shown(p.preload_n),
                        Shown(p.axial_load_n),
                        self.audit.departed(),
                        self.audit.audited()
                    ));
                }
                Ok(o)
            }
            Err(why) => {
                let why = format!(
                    "no torque at speed_rad_s = {}, preload_n = {}, axial_load_n = {}: {why}",
                    Shown(p.speed_rad_s),
                    Shown(p.preload_n),
                    Shown(p.axial_load_n)
                );
                self.computed = Computed::Failed(why.clone());
                Err(Fault::error(why))
            }
        }
    }
}

/// The error of a value reference the FMU does not have.
fn unknown(vr: u32) -> Fault {
    Fault::error(format!("no Real variable with value reference {vr} (valid: 0 to {})", variables::VARIABLES.len() - 1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::variables::{DRAG_TORQUE_NM, LOAD_TORQUE_NM, TORQUE_NM};
    use ballscrew_config::DKFZD4012_TOML;

    fn started() -> Instance {
        let mut i = Instance::from_spec_text(DKFZD4012_TOML, "spec.toml").unwrap();
        i.enter_initialization().unwrap();
        i.exit_initialization().unwrap();
        i
    }

    #[test]
    fn outputs_follow_the_inputs_and_add_up() {
        let mut i = started();
        i.set_real(SPEED_RAD_S, 50.0).unwrap();
        i.set_real(AXIAL_LOAD_N, 300.0).unwrap();
        i.do_step(0.0, 1e-3).unwrap();
        let t = i.get_real(TORQUE_NM).unwrap();
        let d = i.get_real(DRAG_TORQUE_NM).unwrap();
        let l = i.get_real(LOAD_TORQUE_NM).unwrap();
        assert!(l > 0.0 && d > 0.0, "{t} {d} {l}");
        assert!((d + l - t).abs() <= 1e-15 * t.abs());
        assert_eq!(i.get_real(variables::DISSIPATED_POWER_W).unwrap(), d * 50.0);
        // Reversed: the drag turns with the rotation.
        i.set_real(SPEED_RAD_S, -50.0).unwrap();
        assert!(i.get_real(DRAG_TORQUE_NM).unwrap() < 0.0);
        assert!((i.time_s() - 1e-3).abs() < 1e-18);
    }

    #[test]
    fn an_evaluation_off_the_canonical_state_is_a_warning() {
        // The single nut 16 x 5 (the model's warm solve) at 200 N, 3550 N of axial load,
        // speeding up in reverse: at -100 rpm the warm solve sits on another steady state, about
        // 2 % of the drag torque from the cold solve.
        let text = include_str!("../../../configs/single-nut-16x5.toml");
        let mut i = Instance::from_spec_text(text, "spec.toml").unwrap().audited_every(1);
        i.set_real(PRELOAD_N, 200.0).unwrap();
        i.set_real(AXIAL_LOAD_N, 3550.0).unwrap();
        i.enter_initialization().unwrap();
        i.exit_initialization().unwrap();
        assert_eq!(i.take_warning(), None);
        let mut warnings = Vec::new();
        for (k, rpm) in [-10.0, -25.0, -50.0, -75.0, -100.0].into_iter().enumerate() {
            i.set_real(SPEED_RAD_S, ballscrew_core::input::rpm_to_rad_s(rpm)).unwrap();
            i.do_step(k as f64 * 1e-3, 1e-3).unwrap();
            warnings.extend(i.take_warning().map(|w| (rpm, w)));
        }
        assert_eq!(warnings.len(), 1, "{warnings:?}");
        let (rpm, w) = &warnings[0];
        assert_eq!(*rpm, -100.0);
        assert!(w.contains("departs from the canonical state") && w.contains("preload_n = 200"), "{w}");
        assert_eq!((i.audit().audited(), i.audit().departed()), (6, 1));
        assert!(i.audit().largest_departure() > 1e-3);
        i.reset();
        assert_eq!((i.audit().calls(), i.audit().departed()), (0, 0));
        // By default only the first evaluation of these six is audited: no warning.
        let mut quiet = Instance::from_spec_text(text, "spec.toml").unwrap();
        assert_eq!(quiet.audit().every(), AUDIT_EVERY);
        quiet.set_real(PRELOAD_N, 200.0).unwrap();
        quiet.set_real(AXIAL_LOAD_N, 3550.0).unwrap();
        quiet.enter_initialization().unwrap();
        quiet.exit_initialization().unwrap();
        for (k, rpm) in [-10.0, -25.0, -50.0, -75.0, -100.0].into_iter().enumerate() {
            quiet.set_real(SPEED_RAD_S, ballscrew_core::input::rpm_to_rad_s(rpm)).unwrap();
            quiet.do_step(k as f64 * 1e-3, 1e-3).unwrap();
            assert_eq!(quiet.take_warning(), None);
        }
        assert_eq!((quiet.audit().calls(), quiet.audit().audited()), (6, 1));
    }

    #[test]
    fn bad_values_are_refused_with_field_value_and_range() {
        let mut i = started();
        let before = i.point();
        let e = i.set_real(SPEED_RAD_S, f64::NAN).unwrap_err();
        assert_eq!(e.status, Status::Error);
        assert!(e.message.contains("speed_rad_s") && e.message.contains("NaN") && e.message.contains("valid"), "{e:?}");
        let e = i.set_real(PRELOAD_N, -1.0).unwrap_err();
        assert!(e.message.contains("preload_n") && e.message.contains("-1"), "{e:?}");
        assert_eq!(i.point(), before);
        assert!(i.set_real(TORQUE_NM, 1.0).unwrap_err().message.contains("is an output"));
        assert!(i.get_real(99).unwrap_err().message.contains("99"));
        assert!(i.do_step(0.0, -1.0).is_err());
        assert!(i.do_step(f64::INFINITY, 1.0).is_err());
    }

    #[test]
    fn a_step_may_not_start_before_the_time_reached() {
        let mut i = started();
        i.do_step(0.0, 0.1).unwrap();
        i.do_step(0.1, 0.1).unwrap();
        let reached = i.time_s();
        // An importer's own sum of the steps, a rounding away: taken.
        i.do_step(0.1 + 0.1 - 1e-15, 0.1).unwrap();
        let e = i.do_step(0.1, 0.1).unwrap_err();
        assert_eq!(e.status, Status::Error);
        assert!(
            e.message.contains("currentCommunicationPoint: 0.1 s") && e.message.contains("cannot go back"),
            "{e:?}"
        );
        assert!(i.time_s() > reached, "a refused step leaves the time as it was");
        // After a reset it starts again.
        i.reset();
        i.enter_initialization().unwrap();
        i.exit_initialization().unwrap();
        i.do_step(0.0, 0.1).unwrap();
    }

    #[test]
    fn a_failed_evaluation_gives_no_number() {
        let mut i = started();
        // Far beyond the static capacity of the DKFZD4012: the core refuses the point.
        i.set_real(AXIAL_LOAD_N, 9.0e6).unwrap();
        let e = i.do_step(0.0, 1e-3).unwrap_err();
        assert_eq!(e.status, Status::Error);
        assert!(e.message.contains("axial_load_n = 9000000"), "{e:?}");
        assert!(i.get_real(TORQUE_NM).is_err());
        // A valid point again: usable.
        i.set_real(AXIAL_LOAD_N, 0.0).unwrap();
        assert!(i.get_real(TORQUE_NM).unwrap().is_finite());
    }

    #[test]
    fn life_cycle_is_enforced() {
        let mut i = Instance::from_spec_text(DKFZD4012_TOML, "spec.toml").unwrap();
        assert!(i.do_step(0.0, 1e-3).is_err());
        assert!(i.get_real(TORQUE_NM).is_err());
        i.enter_initialization().unwrap();
        i.exit_initialization().unwrap();
        i.terminate().unwrap();
        assert!(i.do_step(0.0, 1e-3).is_err());
        i.reset();
        assert_eq!(i.phase(), Phase::Instantiated);
    }

    #[test]
    fn a_bad_spec_gives_the_message_naming_the_key() {
        let text = DKFZD4012_TOML.replace("preload_n = ", "preload_n = -");
        let e = Instance::from_spec_text(&text, "resources/spec.toml").err().unwrap();
        assert!(e.contains("preload_n"), "{e}");
    }
}
