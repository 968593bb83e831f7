//! Ctrl-C during long evaluations.
//!
//! Python runs its signal handlers (Ctrl-C: `KeyboardInterrupt`) only between bytecodes on the
//! main thread, so a call that computes for minutes with the GIL released would see Ctrl-C only
//! when it returns. [`detach`] runs the work with the GIL released and hands it a [`Watch`]: the
//! work asks it before each point whether to stop ([`Stop::stop`]). On the thread that called
//! [`detach`], the watch re-attaches to Python every [`INTERVAL`] to run the signal handlers
//! (`Python::check_signals`); when one raises, the watch keeps the exception and says stop from
//! then on, to every thread; [`detach`] then returns the exception instead of the work's result.
//! On other threads the watch only reads that flag.

use crate::batch::Stop;
use core::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use core::time::Duration;
use pyo3::prelude::*;
use std::sync::Mutex;
use std::thread::ThreadId;
use std::time::Instant;

/// Time between two signal checks on the calling thread (a check takes the GIL for
/// microseconds, or up to Python's switch interval, 5 ms, when another thread holds it).
pub const INTERVAL: Duration = Duration::from_millis(50);

/// Whether a signal handler has raised during the work, checked on the calling thread.
#[derive(Debug)]
pub struct Watch {
    /// The thread that released the GIL (the only one that checks for signals).
    caller: ThreadId,
    start: Instant,
    /// Nanoseconds after `start` of the next check.
    next_check_ns: AtomicU64,
    stop: AtomicBool,
    /// The exception of the signal handler that raised.
    raised: Mutex<Option<PyErr>>,
}

impl Watch {
    fn new() -> Self {
        Self {
            caller: std::thread::current().id(),
            start: Instant::now(),
            next_check_ns: AtomicU64::new(INTERVAL.as_nanos() as u64),
            stop: AtomicBool::new(false),
            raised: Mutex::new(None),
        }
    }

    /// The exception a signal handler raised, if one did.
    fn into_raised(self) -> Option<PyErr> {
        self.raised.into_inner().unwrap_or_else(std::sync::PoisonError::into_inner)
    }
}

impl Stop for Watch {
    /// Whether a signal handler has raised; on the calling thread, runs the handlers first when
    /// [`INTERVAL`] has passed since the last check.
    fn stop(&self) -> bool {
        if self.stop.load(Ordering::Relaxed) {
            return true;
        }
        let now_ns = self.start.elapsed().as_nanos() as u64;
        if now_ns < self.next_check_ns.load(Ordering::Relaxed) || std::thread::current().id() != self.caller {
            return false;
        }
        self.next_check_ns.store(now_ns + INTERVAL.as_nanos() as u64, Ordering::Relaxed);
        match Python::attach(|py| py.check_signals()) {
            Ok(()) => false,
            Err(e) => {
                *self.raised.lock().unwrap_or_else(std::sync::PoisonError::into_inner) = Some(e);
                self.stop.store(true, Ordering::Relaxed);
                true
            }
        }
    }
}

/// `work` with the GIL released and a [`Watch`] to ask between points: its result, or the
/// exception a signal handler raised meanwhile (`KeyboardInterrupt` for Ctrl-C), whatever the
/// work returned after it stopped.
pub fn detach<T, F>(py: Python<'_>, work: F) -> PyResult<T>
where
    T: Send,
    F: Send + FnOnce(&Watch) -> T,
{
    let watch = Watch::new();
    let out = py.detach(|| work(&watch));
    match watch.into_raised() {
        Some(e) => Err(e),
        None => Ok(out),
    }
}
