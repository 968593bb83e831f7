//! The exported functions of FMI 2.0 for co-simulation (`fmi2Functions.h`), C ABI.
//!
//! Every function checks its pointers (a null component or array is an `fmi2Error`, never a
//! dereference), runs its body under `catch_unwind` (a panic becomes an `fmi2Error`, never an
//! unwind into C), and logs every error through the importer's logger (errors and warnings
//! always, other messages with debug logging on; the message is the logger's format, every
//! `%` doubled, with no further argument). The instance lives in a `Box` from
//! `fmi2Instantiate` to `fmi2FreeInstance`; the logger's message is the only allocation of a
//! failing call, and a successful set, step or get allocates nothing but the message of an
//! evaluation that departs from the canonical state (`fmi2Warning`, the audit of
//! `crate::instance`).
//!
//! What the FMU does not do (its `modelDescription.xml` says so) returns `fmi2Error` with a
//! logged message: FMU states (`canGetAndSetFMUstate = false`), directional derivatives,
//! input and output derivatives, asynchronous steps, and Integer, Boolean and String variables
//! (it has none).
#![allow(unsafe_code)]
#![allow(non_snake_case, reason = "the names of FMI 2.0's C functions")]

use crate::instance::{Fault, Instance, Status};
use crate::model_description::guid;
use crate::resource::{SPEC_FILE, path_of_uri};
use core::ffi::{CStr, c_char, c_int, c_uint, c_void};
use core::panic::AssertUnwindSafe;
extern crate alloc;
use alloc::ffi::CString;
use std::panic::catch_unwind;

/// `fmi2Component`: the instance, as the importer holds it.
pub type Fmi2Component = *mut c_void;
/// `fmi2ComponentEnvironment`: the importer's pointer, handed back to its logger.
pub type Fmi2ComponentEnvironment = *mut c_void;
/// `fmi2FMUstate` (unsupported).
pub type Fmi2FmuState = *mut c_void;
/// `fmi2ValueReference`.
pub type Fmi2ValueReference = c_uint;
/// `fmi2Real`.
pub type Fmi2Real = f64;
/// `fmi2Integer`.
pub type Fmi2Integer = c_int;
/// `fmi2Boolean`: 0 false, else true.
pub type Fmi2Boolean = c_int;
/// `fmi2String`.
pub type Fmi2String = *const c_char;
/// `fmi2Byte`.
pub type Fmi2Byte = c_char;

/// `fmi2CallbackLogger`: `(componentEnvironment, instanceName, status, category, message, ...)`,
/// `message` a printf format.
pub type Fmi2CallbackLogger =
    unsafe extern "C" fn(Fmi2ComponentEnvironment, Fmi2String, c_int, Fmi2String, Fmi2String, ...);

/// `fmi2CallbackFunctions`.
#[repr(C)]
pub struct Fmi2CallbackFunctions {
    /// The logger (may be null: nothing is logged).
    pub logger: Option<Fmi2CallbackLogger>,
    /// `allocateMemory` (unused: `canNotUseMemoryManagementFunctions = true`).
    pub allocate_memory: Option<unsafe extern "C" fn(usize, usize) -> *mut c_void>,
    /// `freeMemory` (unused).
    pub free_memory: Option<unsafe extern "C" fn(*mut c_void)>,
    /// `stepFinished` (unused: steps are synchronous).
    pub step_finished: Option<unsafe extern "C" fn(Fmi2ComponentEnvironment, c_int)>,
    /// Handed back to the logger.
    pub component_environment: Fmi2ComponentEnvironment,
}

/// `fmi2CoSimulation` of `fmi2Type`.
const FMI2_CO_SIMULATION: c_int = 1;
/// `fmi2StatusKind`'s values.
const FMI2_DO_STEP_STATUS: c_int = 0;
const FMI2_PENDING_STATUS: c_int = 1;
const FMI2_LAST_SUCCESSFUL_TIME: c_int = 2;
const FMI2_TERMINATED: c_int = 3;

/// The importer's logger and how to call it.
#[derive(Clone)]
struct Logger {
    logger: Option<Fmi2CallbackLogger>,
    environment: Fmi2ComponentEnvironment,
    instance_name: CString,
    debug: bool,
}

impl Logger {
    /// Logs `message` at `status`: always for warnings and worse, else with debug logging on.
    fn log(&self, status: Status, message: &str) {
        let Some(logger) = self.logger else { return };
        if status == Status::Ok && !self.debug {
            return;
        }
        let category: &CStr = match status {
            Status::Ok | Status::Pending => c"logAll",
            Status::Warning => c"logStatusWarning",
            Status::Discard => c"logStatusDiscard",
            Status::Error | Status::Fatal => c"logStatusError",
        };
        // The message is the format itself, every '%' doubled: importers that format it
        // (printf) show it as written, and those that take it as text (FMPy) show it whole.
        let format = CString::new(message.replace('\0', "\\0").replace('%', "%%")).unwrap_or_default();
        // SAFETY: `logger` is the importer's `fmi2CallbackLogger`, called as FMI defines it: the
        // environment it gave and NUL-terminated strings that live through the call; the format
        // has no conversion (every '%' is doubled), so no variadic argument is read.
        unsafe {
            logger(self.environment, self.instance_name.as_ptr(), status as c_int, category.as_ptr(), format.as_ptr());
        }
    }
}

/// What `fmi2Component` points at.
struct Slave {
    logger: Logger,
    instance: Instance,
}

/// The text of a panic's payload.
fn panic_text(payload: &(dyn core::any::Any + Send)) -> &str {
    payload
        .downcast_ref::<&str>()
        .copied()
        .or_else(|| payload.downcast_ref::<String>().map(String::as_str))
        .unwrap_or("?")
}

/// Runs `body` on the instance behind `c` (`call` names the function in messages): an
/// `fmi2Error` for a null `c`; a failure's message logged and its status returned; an
/// evaluation that departed from the canonical state logged and `fmi2Warning` returned
/// ([`Instance::take_warning`]); a panic caught, logged and returned as `fmi2Error`.
///
/// # Safety
/// `c` is null or a component from [`fmi2Instantiate`] not yet freed, used by one thread at a
/// time (FMI's rule).
unsafe fn with_slave(c: Fmi2Component, call: &str, body: impl FnOnce(&mut Slave) -> Result<(), Fault>) -> Status {
    if c.is_null() {
        return Status::Error;
    }
    // SAFETY: by the caller's contract `c` is a live `Box<Slave>` from `fmi2Instantiate`, not
    // shared with another thread during the call.
    let slave = unsafe { &mut *c.cast::<Slave>() };
    match catch_unwind(AssertUnwindSafe(|| body(slave))) {
        // An evaluation that departed from the canonical state: usable, and said.
        Ok(Ok(())) => match slave.instance.take_warning() {
            Some(w) => {
                slave.logger.log(Status::Warning, &format!("{call}: {w}"));
                Status::Warning
            }
            None => Status::Ok,
        },
        Ok(Err(fault)) => {
            // A departure found before the call failed (a get whose later reference is bad) is
            // said with this call, not carried to the next.
            if let Some(w) = slave.instance.take_warning() {
                slave.logger.log(Status::Warning, &format!("{call}: {w}"));
            }
            slave.logger.log(fault.status, &format!("{call}: {}", fault.message));
            fault.status
        }
        Err(payload) => {
            slave.logger.log(Status::Error, &format!("{call}: internal error: {}", panic_text(payload.as_ref())));
            Status::Error
        }
    }
}

/// The `n` values at `ptr` (`what` names the argument): empty for `n == 0`, an error for a null
/// `ptr` with `n > 0` or a length beyond memory.
///
/// # Safety
/// `ptr` is null or points at `n` initialized values that outlive the returned slice.
unsafe fn slice<'a, T>(ptr: *const T, n: usize, what: &str) -> Result<&'a [T], Fault> {
    if n == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() {
        return Err(Fault::error(format!("{what} is a null pointer with {n} entries")));
    }
    if n > isize::MAX as usize / size_of::<T>().max(1) {
        return Err(Fault::error(format!("{what}: {n} entries is beyond memory")));
    }
    // SAFETY: non-null, and by the caller's contract `n` values live there.
    Ok(unsafe { core::slice::from_raw_parts(ptr, n) })
}

/// [`slice`] for an array the function writes.
///
/// # Safety
/// `ptr` is null or points at room for `n` values, not aliased during the returned borrow.
unsafe fn slice_mut<'a, T>(ptr: *mut T, n: usize, what: &str) -> Result<&'a mut [T], Fault> {
    if n == 0 {
        return Ok(&mut []);
    }
    if ptr.is_null() {
        return Err(Fault::error(format!("{what} is a null pointer with {n} entries")));
    }
    if n > isize::MAX as usize / size_of::<T>().max(1) {
        return Err(Fault::error(format!("{what}: {n} entries is beyond memory")));
    }
    // SAFETY: non-null, and by the caller's contract there is room for `n` values there.
    Ok(unsafe { core::slice::from_raw_parts_mut(ptr, n) })
}

/// The text of the C string `s` (`what` names it): an error for null or not UTF-8.
///
/// # Safety
/// `s` is null or a NUL-terminated string.
unsafe fn text<'a>(s: Fmi2String, what: &str) -> Result<&'a str, String> {
    if s.is_null() {
        return Err(format!("{what} is a null pointer"));
    }
    // SAFETY: non-null and NUL-terminated by the caller's contract.
    unsafe { CStr::from_ptr(s) }.to_str().map_err(|_| format!("{what} is not UTF-8"))
}

/// `fmi2GetTypesPlatform`: `"default"`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetTypesPlatform() -> *const c_char {
    c"default".as_ptr()
}

/// `fmi2GetVersion`: `"2.0"`.
#[unsafe(no_mangle)]
pub extern "C" fn fmi2GetVersion() -> *const c_char {
    c"2.0".as_ptr()
}

/// `fmi2SetDebugLogging`: debug messages on or off; the categories are those of
/// `modelDescription.xml` (an unknown one is an error).
///
/// # Safety
/// `c` as for every function (null or live); `categories` null or `n_categories` C strings.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetDebugLogging(
    c: Fmi2Component,
    logging_on: Fmi2Boolean,
    n_categories: usize,
    categories: *const Fmi2String,
) -> Status {
    let body = |s: &mut Slave| {
        // SAFETY: `categories` holds `n_categories` strings by the caller's contract.
        let names = unsafe { slice(categories, n_categories, "categories") }?;
        for &name in names {
            // SAFETY: each entry is a C string by the caller's contract.
            let name = unsafe { text(name, "a category") }.map_err(Fault::error)?;
            if !["logStatusWarning", "logStatusDiscard", "logStatusError", "logAll"].contains(&name) {
                return Err(Fault::error(format!(
                    "unknown log category {name:?} (valid: logStatusWarning, logStatusDiscard, logStatusError, logAll)"
                )));
            }
        }
        s.logger.debug = logging_on != 0;
        Ok(())
    };
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2SetDebugLogging", body) }
}

/// `fmi2Instantiate`: reads `resources/spec.toml` from `fmu_resource_location` (a `file:`
/// URI), builds the evaluator (or readies the model, for a spec the evaluator does not take)
/// and returns the instance; null on any error, logged through the
/// logger with `fmi2Error` (the spec parser's or the core's message).
///
/// # Safety
/// The strings are null or NUL-terminated; `functions` is null or a valid
/// `fmi2CallbackFunctions` whose logger, if any, stays callable while the instance lives.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Instantiate(
    instance_name: Fmi2String,
    fmu_type: c_int,
    fmu_guid: Fmi2String,
    fmu_resource_location: Fmi2String,
    functions: *const Fmi2CallbackFunctions,
    _visible: Fmi2Boolean,
    logging_on: Fmi2Boolean,
) -> Fmi2Component {
    if functions.is_null() {
        return core::ptr::null_mut();
    }
    // SAFETY: non-null and a valid struct by the caller's contract; its fields are copied.
    let (logger, environment) = unsafe { ((*functions).logger, (*functions).component_environment) };
    // SAFETY: `instance_name` is null or a C string by the caller's contract.
    let name = unsafe { text(instance_name, "instanceName") }.unwrap_or("ballscrew");
    let instance_name = CString::new(name).unwrap_or_default();
    let logger = Logger { logger, environment, instance_name, debug: logging_on != 0 };
    let made = catch_unwind(AssertUnwindSafe(|| -> Result<(Box<Slave>, Option<String>), String> {
        if fmu_type != FMI2_CO_SIMULATION {
            return Err(format!("fmuType {fmu_type}: this FMU is for co-simulation only (fmi2CoSimulation = 1)"));
        }
        // SAFETY: null or a C string by the caller's contract.
        let location = unsafe { text(fmu_resource_location, "fmuResourceLocation") }?;
        let path = path_of_uri(location)?.join(SPEC_FILE);
        let spec_text = std::fs::read_to_string(&path)
            .map_err(|e| format!("cannot read the FMU's spec {}: {e}", path.display()))?;
        let instance = Instance::from_spec_text(&spec_text, &format!("resources/{SPEC_FILE}"))?;
        // SAFETY: null or a C string by the caller's contract.
        let given = unsafe { text(fmu_guid, "fmuGUID") }?;
        let warning = (given != guid(&spec_text)).then(|| {
            format!(
                "fmuGUID {given} is not that of resources/{SPEC_FILE} ({}): the spec was changed after packaging, \
                 so the start values of modelDescription.xml may not be the spec's",
                guid(&spec_text)
            )
        });
        Ok((Box::new(Slave { logger: logger.clone(), instance }), warning))
    }));
    match made {
        Ok(Ok((slave, warning))) => {
            let built = match slave.instance.solver_name() {
                "evaluator" => "evaluator built",
                _ => "the model ready (the control-loop evaluator does not take this spec)",
            };
            slave.logger.log(Status::Ok, &format!("fmi2Instantiate: resources/spec.toml read, {built}"));
            if let Some(w) = warning {
                slave.logger.log(Status::Warning, &format!("fmi2Instantiate: {w}"));
            }
            Box::into_raw(slave).cast()
        }
        Ok(Err(message)) => {
            logger.log(Status::Error, &format!("fmi2Instantiate: {message}"));
            core::ptr::null_mut()
        }
        Err(payload) => {
            logger.log(Status::Error, &format!("fmi2Instantiate: internal error: {}", panic_text(payload.as_ref())));
            core::ptr::null_mut()
        }
    }
}

/// `fmi2FreeInstance`: frees the instance (null: nothing).
///
/// # Safety
/// `c` is null or a component from [`fmi2Instantiate`] not yet freed; it is not used after.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeInstance(c: Fmi2Component) {
    if c.is_null() {
        return;
    }
    // SAFETY: `c` came from `Box::into_raw` in `fmi2Instantiate` and is freed once.
    let slave = unsafe { Box::from_raw(c.cast::<Slave>()) };
    // Dropping plain data cannot panic; caught all the same so nothing unwinds into C.
    let _ = catch_unwind(AssertUnwindSafe(move || drop(slave)));
}

/// `fmi2SetupExperiment`: the start time (tolerance and stop time are not used: the evaluator,
/// or the model, solves to its own tolerance at every point).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetupExperiment(
    c: Fmi2Component,
    _tolerance_defined: Fmi2Boolean,
    _tolerance: Fmi2Real,
    start_time: Fmi2Real,
    _stop_time_defined: Fmi2Boolean,
    _stop_time: Fmi2Real,
) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2SetupExperiment", |s| s.instance.setup_experiment(start_time)) }
}

/// `fmi2EnterInitializationMode`.
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2EnterInitializationMode(c: Fmi2Component) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2EnterInitializationMode", |s| s.instance.enter_initialization()) }
}

/// `fmi2ExitInitializationMode`: the outputs at the initial inputs are evaluated.
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2ExitInitializationMode(c: Fmi2Component) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2ExitInitializationMode", |s| s.instance.exit_initialization()) }
}

/// `fmi2Terminate`.
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Terminate(c: Fmi2Component) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2Terminate", |s| s.instance.terminate()) }
}

/// `fmi2Reset`: back to the state after instantiation.
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2Reset(c: Fmi2Component) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe {
        with_slave(c, "fmi2Reset", |s| {
            s.instance.reset();
            Ok(())
        })
    }
}

/// `fmi2GetReal`: the values of `vr` into `value`, in order; the first failure stops.
///
/// # Safety
/// `c` is null or a live component; `vr` and `value` null or `nvr` entries each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetReal(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *mut Fmi2Real,
) -> Status {
    let body = |s: &mut Slave| {
        // SAFETY: `nvr` entries each by the caller's contract.
        let (refs, values) = unsafe { (slice(vr, nvr, "vr")?, slice_mut(value, nvr, "value")?) };
        for (&r, v) in refs.iter().zip(values.iter_mut()) {
            *v = s.instance.get_real(r)?;
        }
        Ok(())
    };
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2GetReal", body) }
}

/// `fmi2SetReal`: sets the inputs and the preload of `vr` to `value`, in order; the first
/// invalid value (non-finite or out of range: the message names the variable, the value and
/// the valid range) stops, and is not set.
///
/// # Safety
/// `c` is null or a live component; `vr` and `value` null or `nvr` entries each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetReal(
    c: Fmi2Component,
    vr: *const Fmi2ValueReference,
    nvr: usize,
    value: *const Fmi2Real,
) -> Status {
    let body = |s: &mut Slave| {
        // SAFETY: `nvr` entries each by the caller's contract.
        let (refs, values) = unsafe { (slice(vr, nvr, "vr")?, slice(value, nvr, "value")?) };
        for (&r, &v) in refs.iter().zip(values) {
            s.instance.set_real(r, v)?;
        }
        Ok(())
    };
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2SetReal", body) }
}

/// The error of a typed get or set on value references the FMU does not have of that type.
///
/// # Safety
/// `vr` is null or `nvr` entries.
unsafe fn no_variables(vr: *const Fmi2ValueReference, nvr: usize, kind: &str) -> Result<(), Fault> {
    // SAFETY: the caller's contract, passed on.
    let refs = unsafe { slice(vr, nvr, "vr") }?;
    match refs.first() {
        None => Ok(()),
        Some(r) => {
            Err(Fault::error(format!("no {kind} variable with value reference {r}: the FMU has Real variables only")))
        }
    }
}

macro_rules! no_typed_access {
    ($(#[$doc:meta] $name:ident($ptr:ty), $kind:literal;)*) => {$(
        #[$doc]
        ///
        /// # Safety
        /// `c` is null or a live component; `vr` null or `nvr` entries.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn $name(c: Fmi2Component, vr: *const Fmi2ValueReference, nvr: usize, _value: $ptr) -> Status {
            // SAFETY: the caller's contract, passed on.
            unsafe { with_slave(c, stringify!($name), |_| no_variables(vr, nvr, $kind)) }
        }
    )*};
}

no_typed_access! {
    /// `fmi2GetInteger`: the FMU has no Integer variable (an error for any value reference).
    fmi2GetInteger(*mut Fmi2Integer), "Integer";
    /// `fmi2SetInteger`: the FMU has no Integer variable (an error for any value reference).
    fmi2SetInteger(*const Fmi2Integer), "Integer";
    /// `fmi2GetBoolean`: the FMU has no Boolean variable (an error for any value reference).
    fmi2GetBoolean(*mut Fmi2Boolean), "Boolean";
    /// `fmi2SetBoolean`: the FMU has no Boolean variable (an error for any value reference).
    fmi2SetBoolean(*const Fmi2Boolean), "Boolean";
    /// `fmi2GetString`: the FMU has no String variable (an error for any value reference).
    fmi2GetString(*mut Fmi2String), "String";
    /// `fmi2SetString`: the FMU has no String variable (an error for any value reference).
    fmi2SetString(*const Fmi2String), "String";
}

/// The error of a capability the FMU does not have.
fn unsupported(what: &str) -> Result<(), Fault> {
    Err(Fault::error(format!("not supported: {what}")))
}

/// `fmi2GetFMUstate`: not supported (`canGetAndSetFMUstate = false`).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetFMUstate(c: Fmi2Component, _state: *mut Fmi2FmuState) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2GetFMUstate", |_| unsupported("FMU states (canGetAndSetFMUstate = false)")) }
}

/// `fmi2SetFMUstate`: not supported (`canGetAndSetFMUstate = false`).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetFMUstate(c: Fmi2Component, _state: Fmi2FmuState) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2SetFMUstate", |_| unsupported("FMU states (canGetAndSetFMUstate = false)")) }
}

/// `fmi2FreeFMUstate`: not supported (`canGetAndSetFMUstate = false`).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2FreeFMUstate(c: Fmi2Component, _state: *mut Fmi2FmuState) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2FreeFMUstate", |_| unsupported("FMU states (canGetAndSetFMUstate = false)")) }
}

/// `fmi2SerializedFMUstateSize`: not supported (`canSerializeFMUstate = false`).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializedFMUstateSize(
    c: Fmi2Component,
    _state: Fmi2FmuState,
    _size: *mut usize,
) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe {
        with_slave(c, "fmi2SerializedFMUstateSize", |_| {
            unsupported("serialized FMU states (canSerializeFMUstate = false)")
        })
    }
}

/// `fmi2SerializeFMUstate`: not supported (`canSerializeFMUstate = false`).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SerializeFMUstate(
    c: Fmi2Component,
    _state: Fmi2FmuState,
    _bytes: *mut Fmi2Byte,
    _size: usize,
) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe {
        with_slave(c, "fmi2SerializeFMUstate", |_| unsupported("serialized FMU states (canSerializeFMUstate = false)"))
    }
}

/// `fmi2DeSerializeFMUstate`: not supported (`canSerializeFMUstate = false`).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DeSerializeFMUstate(
    c: Fmi2Component,
    _bytes: *const Fmi2Byte,
    _size: usize,
    _state: *mut Fmi2FmuState,
) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe {
        with_slave(c, "fmi2DeSerializeFMUstate", |_| {
            unsupported("serialized FMU states (canSerializeFMUstate = false)")
        })
    }
}

/// `fmi2GetDirectionalDerivative`: not supported (`providesDirectionalDerivative = false`).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetDirectionalDerivative(
    c: Fmi2Component,
    _unknowns: *const Fmi2ValueReference,
    _n_unknowns: usize,
    _knowns: *const Fmi2ValueReference,
    _n_knowns: usize,
    _dv_known: *const Fmi2Real,
    _dv_unknown: *mut Fmi2Real,
) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe {
        with_slave(c, "fmi2GetDirectionalDerivative", |_| {
            unsupported("directional derivatives (providesDirectionalDerivative = false)")
        })
    }
}

/// `fmi2SetRealInputDerivatives`: not supported (`canInterpolateInputs = false`).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2SetRealInputDerivatives(
    c: Fmi2Component,
    _vr: *const Fmi2ValueReference,
    _nvr: usize,
    _order: *const Fmi2Integer,
    _value: *const Fmi2Real,
) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe {
        with_slave(c, "fmi2SetRealInputDerivatives", |_| {
            unsupported("input derivatives (canInterpolateInputs = false: inputs are held over a step)")
        })
    }
}

/// `fmi2GetRealOutputDerivatives`: not supported (`maxOutputDerivativeOrder = 0`).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealOutputDerivatives(
    c: Fmi2Component,
    _vr: *const Fmi2ValueReference,
    _nvr: usize,
    _order: *const Fmi2Integer,
    _value: *mut Fmi2Real,
) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe {
        with_slave(c, "fmi2GetRealOutputDerivatives", |_| {
            unsupported("output derivatives (maxOutputDerivativeOrder = 0)")
        })
    }
}

/// `fmi2DoStep`: the outputs at the inputs as set, held over the step from
/// `current_communication_point` over `communication_step_size` (s); an `fmi2Error` with the
/// core's message where the point has no solution (the outputs then give no number until a
/// valid point is set).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2DoStep(
    c: Fmi2Component,
    current_communication_point: Fmi2Real,
    communication_step_size: Fmi2Real,
    _no_set_fmu_state_prior: Fmi2Boolean,
) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2DoStep", |s| s.instance.do_step(current_communication_point, communication_step_size)) }
}

/// `fmi2CancelStep`: an error (steps are synchronous: there is never one to cancel).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2CancelStep(c: Fmi2Component) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2CancelStep", |_| unsupported("cancelling a step (steps are synchronous)")) }
}

/// The `fmi2Discard` of a status kind the function does not report.
fn no_status(kind: c_int) -> Result<(), Fault> {
    Err(Fault::discard(format!("status kind {kind} is not reported here (steps are synchronous)")))
}

/// `fmi2GetStatus`: `fmi2Discard` (steps are synchronous: no step status to ask for).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStatus(c: Fmi2Component, kind: c_int, _value: *mut c_int) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2GetStatus", |_| no_status(kind)) }
}

/// `fmi2GetRealStatus`: `fmi2LastSuccessfulTime`, the communication point reached (s).
///
/// # Safety
/// `c` is null or a live component; `value` null or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetRealStatus(c: Fmi2Component, kind: c_int, value: *mut Fmi2Real) -> Status {
    let body = |s: &mut Slave| {
        if kind != FMI2_LAST_SUCCESSFUL_TIME {
            return no_status(kind);
        }
        // SAFETY: one writable value by the caller's contract.
        let out = unsafe { slice_mut(value, 1, "value") }?;
        out[0] = s.instance.time_s();
        Ok(())
    };
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2GetRealStatus", body) }
}

/// `fmi2GetIntegerStatus`: `fmi2Discard` (no Integer status kind is defined).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetIntegerStatus(c: Fmi2Component, kind: c_int, _value: *mut Fmi2Integer) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2GetIntegerStatus", |_| no_status(kind)) }
}

/// `fmi2GetBooleanStatus`: `fmi2Terminated`, always false (the FMU never ends a simulation).
///
/// # Safety
/// `c` is null or a live component; `value` null or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetBooleanStatus(c: Fmi2Component, kind: c_int, value: *mut Fmi2Boolean) -> Status {
    let body = |_: &mut Slave| {
        if kind != FMI2_TERMINATED {
            return no_status(kind);
        }
        // SAFETY: one writable value by the caller's contract.
        let out = unsafe { slice_mut(value, 1, "value") }?;
        out[0] = 0;
        Ok(())
    };
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2GetBooleanStatus", body) }
}

/// `fmi2GetStringStatus`: `fmi2Discard` (no pending step to describe).
///
/// # Safety
/// `c` is null or a live component.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn fmi2GetStringStatus(c: Fmi2Component, kind: c_int, _value: *mut Fmi2String) -> Status {
    // SAFETY: the caller's contract, passed on.
    unsafe { with_slave(c, "fmi2GetStringStatus", |_| no_status(kind)) }
}

/// The status kinds, named for the tests of the C ABI.
pub mod status_kind {
    /// `fmi2DoStepStatus`.
    pub const DO_STEP_STATUS: core::ffi::c_int = super::FMI2_DO_STEP_STATUS;
    /// `fmi2PendingStatus`.
    pub const PENDING_STATUS: core::ffi::c_int = super::FMI2_PENDING_STATUS;
    /// `fmi2LastSuccessfulTime`.
    pub const LAST_SUCCESSFUL_TIME: core::ffi::c_int = super::FMI2_LAST_SUCCESSFUL_TIME;
    /// `fmi2Terminated`.
    pub const TERMINATED: core::ffi::c_int = super::FMI2_TERMINATED;
}
