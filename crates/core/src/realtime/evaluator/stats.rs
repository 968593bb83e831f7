//! What the evaluator counts of its own work, for its tests: the residuals Broyden's method
//! evaluates (per thread), and per ball the solves that gave up the warm start for Newton's
//! method or the continuation and the warm starts retried with a fresh Jacobian. Outside test
//! builds every count is a no-op and [`Stats`] has no size: the hot path carries no counter.

/// A ball's counts (in its memory, [`super::memory::BallMemory`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(super) struct Stats {
    /// Solves that gave up the warm start for Newton's method or the continuation.
    #[cfg(test)]
    pub(super) fallbacks: u32,
    /// Warm starts retried with a fresh Jacobian.
    #[cfg(test)]
    pub(super) refreshes: u32,
}

impl Stats {
    /// No counts.
    pub(super) const ZERO: Self = Self {
        #[cfg(test)]
        fallbacks: 0,
        #[cfg(test)]
        refreshes: 0,
    };

    /// Counts a solve that gave up its start for Newton's method or the continuation.
    #[inline(always)]
    pub(super) fn fallback(&mut self) {
        #[cfg(test)]
        {
            self.fallbacks += 1;
        }
    }

    /// Counts a warm start retried with a fresh Jacobian.
    #[inline(always)]
    pub(super) fn refresh(&mut self) {
        #[cfg(test)]
        {
            self.refreshes += 1;
        }
    }
}

/// Counts one residual evaluated for Broyden's method on this thread.
#[inline(always)]
pub(super) fn residual() {
    #[cfg(test)]
    RESIDUALS.with(|n| n.set(n.get() + 1));
}

#[cfg(test)]
std::thread_local! {
    /// Residuals evaluated for Broyden's method on this thread (every test has its own).
    pub(super) static RESIDUALS: core::cell::Cell<u64> = const { core::cell::Cell::new(0) };
}
