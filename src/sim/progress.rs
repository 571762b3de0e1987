//! How far a simulation has got, for a progress line on the terminal
//! ([`crate::report::progress`] draws it): the time the integrator last
//! evaluated the model at, counted in output rows from the run's start.

use std::sync::atomic::{AtomicUsize, Ordering};

/// A counter of rows reached: `offset` plus the rows from `t0` to the
/// time evaluated, a row every `step` s.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Counted<'a> {
    counter: &'a AtomicUsize,
    t0: f64,
    step: f64,
    offset: usize,
}

impl<'a> Counted<'a> {
    pub(crate) fn new(counter: &'a AtomicUsize, t0: f64, step: f64, offset: usize) -> Self {
        Self {
            counter,
            t0,
            step,
            offset,
        }
    }

    /// The model evaluated at time `t`, s: a plain store (a rejected step
    /// may go back a little; the line shows where the run is, not a
    /// maximum).
    pub(crate) fn at(&self, t: f64) {
        let rows = ((t - self.t0) / self.step).max(0.0) as usize;
        self.counter.store(self.offset + rows, Ordering::Relaxed);
    }
}
