//! A run's residuals by a replay that can stop inside the run
//! ([`Prepared::residuals_watched`]): a fit's evaluation that is only used
//! when its cost is below a bound (a search point, a trial step) scores
//! the replay every [`CHUNK`] seconds while it integrates, and stops it as
//! soon as the cost of the residuals scored so far, with what the
//! evaluation's other runs have shown, is above that bound.
//!
//! The integration is the whole run's, watched
//! ([`crate::sim::Integrator::replay_watched`]: the same steps, the same
//! state carried, nothing restarted at a look), so a replay that is not
//! stopped is the whole replay to the bit; its residuals are then written
//! from the whole history as [`Prepared::observe_reusing`] writes them, and
//! it is cached as that one is. A stopped replay is not cached.
//!
//! A chunk scores only the residuals that the rest of the run cannot
//! change ([`Scorer`]): the sensors ([`crate::vehicle::Sensors::seen`])
//! read a row's neighbours (the yaw acceleration by central differences),
//! a delay `d` reads `d` seconds back (a negative one reads ahead), and a
//! residual time is interpolated between two rows. A residual is scored
//! once the history reaches [`MARGIN_ROWS`] rows past the time it reads
//! last, from rows starting [`MARGIN_ROWS`] before the time it reads
//! first: its value is then the whole replay's to the bit (the same
//! arithmetic on the same rows; the interpolator's bracket does not depend
//! on where its nodes start). The scored residuals' cost is thus a part of
//! the run's own, up to the rounding of a sum taken in another order. A
//! delay that is not finite is not chunked: the replay runs whole. Units:
//! SI, rad.

use super::{Prepared, ReplayCache, SharedReplays};
use crate::diagnose::model::channels::Channel;
use crate::diagnose::model::Augmented;
use crate::sim::{Integrator, TimeHistory};

/// How much of a run a replay integrates between two looks, s: about a
/// thousandth of the sedan's 200 s runs' cost each (a look scores its
/// chunk's residuals and takes a lock), so a replay goes on at most this
/// far past the point that shows it above its bound.
pub(crate) const CHUNK: f64 = 0.5;

/// Rows of history a scored residual keeps from both ends of what is
/// integrated, beyond its delay: the yaw acceleration's central difference
/// (one row each way), the delay's and the residual time's interpolation
/// (one row each way each), and the grid times' rounding.
const MARGIN_ROWS: f64 = 6.0;

/// What became of a watched replay ([`Prepared::residuals_watched`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Replayed {
    /// Whether the run's residuals were written whole (else it was stopped).
    pub(crate) complete: bool,
    /// Rows of history integrated (0 where a cached replay was read).
    pub(crate) rows: usize,
}

impl Prepared {
    /// The run's scaled residuals at `model` into `out` (as
    /// [`Prepared::write_residuals`] writes those of
    /// [`Prepared::observe_reusing`], through the same caches), unless
    /// `watch`, told the cost `½·Σ r²` of the residuals scored so far
    /// after every [`CHUNK`] of the replay, returns false: the replay then
    /// stops there (`out` partly written, nothing cached). Without a
    /// `watch` the replay runs whole.
    pub(crate) fn residuals_watched(
        &self,
        model: &Augmented,
        (cache, shared): (&ReplayCache, Option<(&SharedReplays, usize)>),
        scales: &[f64; 3],
        out: &mut [f64],
        watch: Option<&mut dyn FnMut(f64) -> bool>,
    ) -> Replayed {
        let start = self.start_of(model);
        if let Some(observed) = self.observe_cached(model, start, cache, shared) {
            self.write_residuals(&observed, scales, out);
            return Replayed {
                complete: true,
                rows: 0,
            };
        }
        let drive = self.drive_for(model);
        let x0 = model.initial_state(&drive, start.0, start.1);
        let integrator = Integrator {
            friction: model.friction,
            ..Integrator::default()
        };
        let delay = model.effects().sensors.delay;
        let mut whole = |_: f64| true;
        let (every, watch) = match watch {
            Some(w) if delay.is_finite() => (((CHUNK / drive.step).round() as usize).max(1), w),
            _ => (0, &mut whole as &mut dyn FnMut(f64) -> bool),
        };
        let mut scorer = Scorer::new(self, model, scales, drive.step);
        let (history, rows) =
            integrator.replay_watched(&model.model, &drive, x0, self.load_tolerance, every, |h| {
                watch(scorer.score(h, out))
            });
        let Some(history) = history else {
            return Replayed {
                complete: false,
                rows,
            };
        };
        let observed = self.seen(model, &history, &self.times);
        self.write_residuals(&observed, scales, out);
        cache.store(model, start, history);
        Replayed {
            complete: true,
            rows,
        }
    }
}

/// Scores a replay's residuals chunk by chunk while it runs, each once the
/// rest of the run can no longer change it (the module's rule).
pub(crate) struct Scorer<'a> {
    run: &'a Prepared,
    model: &'a Augmented,
    scales: &'a [f64; 3],
    /// The first residual time not scored yet.
    next: usize,
    /// How far a residual reads back and ahead of its time, s: the
    /// sensors' delay where positive, its opposite where negative, and
    /// [`MARGIN_ROWS`] rows either way.
    behind: f64,
    ahead: f64,
    /// `½·Σ r²` of the residuals scored.
    cost: f64,
}

impl<'a> Scorer<'a> {
    /// A scorer of `model`'s replay of `run` on a grid of step `step`, s.
    pub(crate) fn new(
        run: &'a Prepared,
        model: &'a Augmented,
        scales: &'a [f64; 3],
        step: f64,
    ) -> Self {
        let delay = model.effects().sensors.delay;
        let margin = MARGIN_ROWS * step;
        Self {
            run,
            model,
            scales,
            next: 0,
            behind: delay.max(0.0) + margin,
            ahead: (-delay).max(0.0) + margin,
            cost: 0.0,
        }
    }

    /// Scores the residuals that history `h` (the replay's first rows)
    /// settles and that were not scored yet, writing them into `out` where
    /// [`Prepared::write_residuals`] writes them; returns the cost of all
    /// those scored so far.
    pub(crate) fn score(&mut self, h: &TimeHistory, out: &mut [f64]) -> f64 {
        let times = &self.run.times;
        let Some(&last) = h.t.last() else {
            return self.cost;
        };
        let end = times.partition_point(|&s| s <= last - self.ahead);
        if end <= self.next {
            return self.cost;
        }
        let first = times[self.next] - self.behind;
        let from = h.t.partition_point(|&s| s < first).saturating_sub(1);
        let rows = from..h.len();
        let sensors = &self.model.effects().sensors;
        let ax = self.run.ax_for(sensors, &h.t[rows.clone()]);
        let at = &times[self.next..end];
        let seen = self.model.seen_rows(h, rows, &ax, at);
        let n = times.len();
        for (k, (c, measured)) in self.run.measured.iter().enumerate() {
            let sim = &seen[channel_slot(*c)];
            let s = self.scales[c.index()];
            for (j, y) in (self.next..end).zip(sim) {
                let r = super::scaled(*y, measured[j], s);
                out[k * n + j] = r;
                self.cost += 0.5 * r * r;
            }
        }
        self.next = end;
        self.cost
    }
}

/// Where [`crate::diagnose::model::Augmented::seen_rows`] puts channel `c`.
fn channel_slot(c: Channel) -> usize {
    match c {
        Channel::YawRate => 0,
        Channel::Ay => 1,
        Channel::Beta => 2,
    }
}

#[cfg(test)]
#[path = "chunked_tests.rs"]
mod tests;
