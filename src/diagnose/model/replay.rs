//! A measured run made ready for the many replays a fit makes ([`Prepared`]):
//! its inputs (steer, speed, and the `ax` and `bank` channels when logged)
//! sampled once onto the campaign's fixed step, the times at which
//! residuals are taken, and the measured channels at those times.
//!
//! A replay starts from the run's first measured state (sideslip, else 0,
//! and yaw rate) less the model's sensor offsets (its effects'
//! [`crate::vehicle::Sensors`]), and runs on the
//! campaign's fixed grid, smooth in the parameters: by classical RK4 while
//! the model being replayed is stable under it there, else by the linearly
//! implicit Rosenbrock-W method ROS34PW2 (Rang & Angermann 2005), stable at
//! any step ([`Prepared::drive_for`]). The residual of channel c at a
//! sample is `(simulated − measured)/s_c`, `s_c` the channel's scale.
//! Residuals are taken at a fixed rate (default 25 Hz) rather than at every
//! sample: neighbouring samples of a 100 Hz log say nearly the same thing.
//! Units: SI, rad.

use crate::diagnose::campaign::Campaign;
use crate::diagnose::model::channels::{Channel, ChannelErrors};
use crate::diagnose::model::{Augmented, Drive, FixedStep, Observed};
use crate::measured::MeasuredRun;
use crate::sim::TimeHistory;
use std::borrow::Cow;
use std::sync::{Arc, Mutex};

/// `h·ρ` up to which a replay runs by RK4, with `ρ` the model's fastest
/// rate ([`VehicleModel::fastest_rate`]): inside RK4's stability region
/// (−2.79 on the real axis, ±2.83 on the imaginary) with a margin for
/// what that estimate leaves out (load transfer, the slip's own
/// nonlinearity). Beyond it, ROS34PW2.
///
/// [`VehicleModel::fastest_rate`]: crate::vehicle::VehicleModel::fastest_rate
pub(crate) const STABLE_STEP: f64 = 2.0;

/// The measured inputs a run's replay grids are sampled from.
#[derive(Debug)]
struct ReplayInputs {
    t: Vec<f64>,
    steer: Vec<f64>,
    speed: Vec<f64>,
    ax: Option<Vec<f64>>,
    bank: Option<Vec<f64>>,
    /// Lowest and highest speed, m/s.
    speeds: (f64, f64),
}

/// A run made ready for repeated replays.
#[derive(Debug, Clone)]
pub struct Prepared {
    /// Name (the file).
    pub(crate) name: String,
    /// Its inputs at the RK4 stages of the campaign's step.
    pub(crate) drive: Drive,
    /// The same at the ROS34PW2 stages, sampled when a model first needs
    /// them ([`Prepared::drive_for`]).
    stiff: std::sync::Arc<std::sync::OnceLock<Drive>>,
    inputs: std::sync::Arc<ReplayInputs>,
    /// Times at which residuals are taken, s.
    pub(crate) times: Vec<f64>,
    /// Measured channels at those times.
    pub(crate) measured: Vec<(Channel, Vec<f64>)>,
    /// The longitudinal acceleration the replays read at the grid times
    /// ([`crate::diagnose::model::grid_ax`] of the RK4 drive): what a
    /// yawed accelerometer mixes into ay, one source for plain and dual
    /// replays alike.
    ax_grid: Arc<(Vec<f64>, Vec<f64>)>,
    /// Initial sideslip (measured, else 0) and yaw rate.
    pub(crate) start: (f64, f64),
    /// The time they are read at, s (the first residual's where the
    /// sideslip is measured).
    start_time: f64,
    /// Relative tolerance of the replays' load-transfer loop
    /// ([`crate::vehicle::LOAD_TOLERANCE`]; a check of derivatives against
    /// differences sets it at rounding).
    pub(crate) load_tolerance: f64,
}

/// The opening stretch of a run without a sideslip channel that is not
/// scored, s: its replay starts at a sideslip of 0 and settles within it
/// (the gap scan's first half-second window
/// leaves the same stretch out of every run).
pub const UNMEASURED_START: f64 = 0.5;

impl Prepared {
    /// Every run of campaign `c`, prepared with its `[diagnose]` step and
    /// residual rate.
    pub fn campaign_runs(c: &Campaign) -> Vec<Self> {
        let set = &c.settings;
        c.runs
            .iter()
            .map(|r| Self::new(r, set.step, set.sample_rate))
            .collect()
    }

    /// Prepares `run` for replays with step `step` and residuals taken
    /// at `rate` Hz (at the samples nearest to it).
    /// Masked samples (logger glitches in a response channel) are skipped:
    /// the next unmasked sample takes their place.
    pub fn new(run: &MeasuredRun, step: f64, rate: f64) -> Self {
        let mut masked = vec![false; run.t.len()];
        for &i in &run.masked {
            masked[i] = true;
        }
        let first = (0..run.t.len()).find(|&i| !masked[i]).unwrap_or(0);
        // Without a sideslip channel the replay starts at a sideslip of 0,
        // which a piece that starts in a turn does not have: its first
        // [`UNMEASURED_START`] s are the replay settling, not the model,
        // and are not scored (as the gap scan leaves them out).
        let scored_from = match run.beta {
            Some(_) => f64::NEG_INFINITY,
            None => run.t[first] + UNMEASURED_START,
        };
        let from = (first..run.t.len())
            .find(|&i| !masked[i] && run.t[i] >= scored_from - 1e-9)
            .unwrap_or(first);
        let mut idx = vec![from];
        for (i, (&t, &m)) in run.t.iter().zip(&masked).enumerate().skip(from + 1) {
            if !m && t - run.t[*idx.last().unwrap()] >= 1.0 / rate - 1e-9 {
                idx.push(i);
            }
        }
        let times: Vec<f64> = idx.iter().map(|&i| run.t[i]).collect();
        let measured = Channel::ALL
            .into_iter()
            .filter_map(|c| c.of(run).map(|v| (c, idx.iter().map(|&i| v[i]).collect())))
            .collect();
        let speeds = run
            .speed
            .iter()
            .fold((f64::INFINITY, 0.0_f64), |(lo, hi), &u| {
                (lo.min(u), hi.max(u))
            });
        let inputs = ReplayInputs {
            t: run.t.clone(),
            steer: run.steer.clone(),
            speed: run.speed.clone(),
            ax: run.ax.clone(),
            bank: run.bank.clone(),
            speeds,
        };
        let drive = inputs.drive(step, FixedStep::Rk4);
        Self {
            name: run.path.display().to_string(),
            ax_grid: Arc::new(super::grid_ax(&drive)),
            drive,
            stiff: Default::default(),
            inputs: std::sync::Arc::new(inputs),
            times,
            measured,
            start: (
                run.beta.as_ref().map_or(0.0, |b| b[first]),
                run.yaw_rate[first],
            ),
            start_time: run.t[first],
            load_tolerance: crate::vehicle::LOAD_TOLERANCE,
        }
    }

    /// The replay `model` needs on the campaign's step: by RK4 while
    /// `h·ρ ≤` `STABLE_STEP` at the run's lowest and highest speed, else
    /// by ROS34PW2, which is stable at any step. The step stays the
    /// campaign's: a stiff model (racing axles at a few m/s, a tyre lag of
    /// millimetres) costs a Jacobian every few steps, not a finer grid, and
    /// its fast modes, settled within a step, are followed quasi-statically.
    /// A model whose steer path is on gets a copy of that drive with the
    /// path's output for the run's logged steer ([`Augmented::steered`]);
    /// any other, the prepared drive itself.
    pub(crate) fn drive_for(&self, model: &Augmented) -> Cow<'_, Drive> {
        let (drive, t, steer) = self.unsteered_drive(model);
        model.steered(drive, t, steer)
    }

    /// The drive `model`'s replay runs on before its steer path (the
    /// method [`Prepared::drive_for`] picks), and the logged times and
    /// steer the path acts on.
    pub(crate) fn unsteered_drive(&self, model: &Augmented) -> (&Drive, &[f64], &[f64]) {
        let (vehicle, friction) = (&model.model, model.friction);
        let (lo, hi) = self.inputs.speeds;
        let rho = vehicle
            .fastest_rate(lo, friction)
            .max(vehicle.fastest_rate(hi, friction));
        let drive = if self.drive.step * rho <= STABLE_STEP {
            &self.drive
        } else {
            self.stiff
                .get_or_init(|| self.inputs.drive(self.drive.step, FixedStep::RosenbrockW))
        };
        (drive, &self.inputs.t, &self.inputs.steer)
    }

    /// The first measured state (sideslip, else 0, and yaw rate) and
    /// whether the sideslip is measured: a replay starts there less the
    /// model's sensor offsets ([`Prepared::replay`]).
    pub(crate) fn start_values(&self) -> ((f64, f64), bool) {
        let beta_measured = self.measured.iter().any(|(c, _)| *c == Channel::Beta);
        (self.start, beta_measured)
    }

    /// The run replayed by `model` from its first measured state less the
    /// model's sensor offsets, by the method [`Prepared::drive_for`] picks.
    pub(crate) fn replay(&self, model: &Augmented) -> TimeHistory {
        let (beta, yaw_rate) = self.start_of(model);
        model.simulate_from_to(&self.drive_for(model), beta, yaw_rate, self.load_tolerance)
    }

    /// Number of residuals of this run.
    pub(crate) fn count(&self) -> usize {
        self.measured.iter().map(|(_, v)| v.len()).sum()
    }

    /// Replays the run with `model` from its first measured state (less the
    /// model's sensor offsets) and returns what the sensors would read at
    /// the residual times.
    pub(crate) fn observe(&self, model: &Augmented) -> Observed {
        self.observe_at(model, &self.times)
    }

    /// [`Prepared::observe`] at times `t` of the replay's span, scored or
    /// not (a run's every sample: a designed run logged from a replay).
    pub(crate) fn observe_at(&self, model: &Augmented, t: &[f64]) -> Observed {
        self.seen(model, &self.replay(model), t)
    }

    /// What `model`'s sensors read of its replay `history` at times `t`.
    fn seen(&self, model: &Augmented, history: &TimeHistory, t: &[f64]) -> Observed {
        let ax = self.ax_for(&model.effects().sensors, &history.t);
        model.observe_with_ax(history, &ax, t)
    }

    /// The longitudinal acceleration at times `t` the replays read, m/s²,
    /// where `sensors` read it ([`crate::vehicle::Sensors::reads_ax`];
    /// else none).
    pub(crate) fn ax_for<T: crate::scalar::Scalar>(
        &self,
        sensors: &crate::vehicle::Sensors<T>,
        t: &[f64],
    ) -> Vec<f64> {
        if !sensors.reads_ax() {
            return Vec::new();
        }
        let (grid, ax) = &*self.ax_grid;
        let mut nodes = crate::manoeuvre::Interpolator::new(grid);
        t.iter().map(|&s| nodes.at(ax, s)).collect()
    }

    /// The replay's start (sideslip, yaw rate): the first measured state less
    /// the model's sensor offsets. A run without a sideslip channel starts
    /// at 0 whatever the sideslip offset: else the offset of a channel the
    /// run lacks would steer its start and be "fitted" from that.
    fn start_of(&self, model: &Augmented) -> (f64, f64) {
        let sensors = &model.effects().sensors;
        let beta_measured = self.measured.iter().any(|(c, _)| *c == Channel::Beta);
        let r = self.start.1 - sensors.yaw_rate_bias;
        (
            if beta_measured {
                self.start.0 - sensors.beta_bias - sensors.sideslip_offset(r, self.start_speed())
            } else {
                self.start.0
            },
            r,
        )
    }

    /// The time the replay starts at, s: the run's first unmasked sample
    /// (its residuals start [`UNMEASURED_START`] later without a sideslip
    /// channel).
    pub(crate) fn start_time(&self) -> f64 {
        self.start_time
    }

    /// The forward speed at the replay's start, m/s.
    pub(crate) fn start_speed(&self) -> f64 {
        crate::manoeuvre::interpolate(&self.inputs.t, &self.inputs.speed, self.start_time)
    }

    /// The forward speed at times `t`, m/s (the logged speed interpolated).
    pub(crate) fn speed_at(&self, t: &[f64]) -> Vec<f64> {
        t.iter()
            .map(|&x| crate::manoeuvre::interpolate(&self.inputs.t, &self.inputs.speed, x))
            .collect()
    }

    /// [`Prepared::observe`] through `cache`, the run's last replay and
    /// one kept ([`ReplayCache`]): a model that differs from one of theirs
    /// only in its sensors (a sensor delay, gain or accelerometer position,
    /// whose start state is the same) integrates the same history, so only
    /// the sensors are applied again.
    /// Where it finds none there, it looks in `shared` (if any): the
    /// replays of this run (its index `.1` in the campaign's runs) that
    /// every problem of a diagnosis on all runs shares ([`SharedReplays`]).
    pub(crate) fn observe_reusing(
        &self,
        model: &Augmented,
        cache: &ReplayCache,
        shared: Option<(&SharedReplays, usize)>,
    ) -> Observed {
        let start = self.start_of(model);
        if let Some(observed) = self.observe_cached(model, start, cache, shared) {
            return observed;
        }
        // Integrated without the lock: evaluations in parallel (a parallel
        // swarm) do not wait for each other, the last one stored wins.
        let history = self.replay(model);
        let observed = self.seen(model, &history, &self.times);
        cache.store(model, start, history);
        observed
    }

    /// What `model`'s sensors read of the replay from `start` that `cache`
    /// or else `shared` holds, if one does ([`Prepared::observe_reusing`]).
    fn observe_cached(
        &self,
        model: &Augmented,
        start: (f64, f64),
        cache: &ReplayCache,
        shared: Option<(&SharedReplays, usize)>,
    ) -> Option<Observed> {
        let l = [&cache.last, &cache.kept]
            .into_iter()
            .find_map(|slot| {
                let entry = slot.lock().unwrap_or_else(|e| e.into_inner());
                entry.as_ref().filter(|l| l.matches(model, start)).cloned()
            })
            .or_else(|| shared.and_then(|(s, i)| s.find(i, model, start)))?;
        let observed = self.seen(model, &l.history, &self.times);
        // The last slot holds the latest evaluation's replay, reused or
        // not: that is what [`ReplayCache::keep_last`] keeps.
        *cache.last.lock().unwrap_or_else(|e| e.into_inner()) = Some(l);
        Some(observed)
    }

    /// The scaled residuals of observed outputs `obs` into `out`.
    pub(crate) fn write_residuals(&self, obs: &Observed, scales: &[f64; 3], out: &mut [f64]) {
        let mut k = 0;
        for (c, m) in &self.measured {
            let sim = match c {
                Channel::YawRate => &obs.yaw_rate,
                Channel::Ay => &obs.ay,
                Channel::Beta => &obs.beta,
            };
            let s = scales[c.index()];
            for (y, x) in sim.iter().zip(m) {
                out[k] = scaled(*y, *x, s);
                k += 1;
            }
        }
    }

    /// Sum of squared unscaled residuals and sample count per channel.
    pub fn errors(&self, model: &Augmented) -> ChannelErrors {
        self.errors_of(&self.observe(model))
    }

    /// [`Prepared::errors`] of observed outputs `obs` (a replay already
    /// made).
    pub(crate) fn errors_of(&self, obs: &Observed) -> ChannelErrors {
        let mut r = vec![0.0; self.count()];
        self.write_residuals(obs, &[1.0; 3], &mut r);
        let mut e = ChannelErrors::default();
        let mut k = 0;
        for (c, v) in &self.measured {
            for _ in 0..v.len() {
                e.sum_sq[c.index()] += r[k] * r[k];
                e.count[c.index()] += 1;
                k += 1;
            }
        }
        e
    }
}

/// The residual of simulated `y` against measured `x` on scale `s`.
fn scaled(y: f64, x: f64, s: f64) -> f64 {
    // A diverged replay is a very bad fit, not a NaN for LM.
    if y.is_finite() {
        (y - x) / s
    } else {
        1e6
    }
}

impl ReplayInputs {
    /// The inputs on the grid of step `step`, sampled for `method`.
    fn drive(&self, step: f64, method: FixedStep) -> Drive {
        Drive::replay(&self.t, &self.steer, &self.speed, step, method).with_channels(
            &self.t,
            self.ax.as_deref(),
            self.bank.as_deref(),
        )
    }
}

/// A run's replay: the model (its sensors aside, the key), the start
/// state and the integrated history.
pub(crate) struct LastReplay {
    model: Augmented,
    start: (f64, f64),
    history: TimeHistory,
}

impl LastReplay {
    /// Whether `model` from `start` integrates this same history: the same
    /// start and the same dynamics (the sensors aside).
    fn matches(&self, model: &Augmented, start: (f64, f64)) -> bool {
        self.start == start && self.model.same_dynamics(model)
    }
}

/// Rows of replayed history (every run's together) that a
/// [`SharedReplays`] holds at most: about 170 MB at the 14 columns of a
/// [`TimeHistory`], some sixty replays of a 460 s log at 50 Hz, a score of
/// a 600 s one at 100 Hz. The oldest go first.
const SHARED_ROWS: usize = 1_500_000;

/// Replays of every run of a campaign that the problems of one diagnosis
/// on all runs share: a model the diagnosis replays in many fits (the
/// base, which every single's global stage starts from; a candidate's
/// optimum, which the sets that extend it start from; a global stage's
/// best, where its polish starts) is integrated once, not once per
/// problem. A replay is found by its model's dynamics and start state
/// ([`Prepared::observe_reusing`]), so what is read is what a replay would
/// integrate, bit for bit. Held until [`SHARED_ROWS`] is reached, the
/// oldest dropped first.
#[derive(Default)]
pub(crate) struct SharedReplays {
    /// Each shared set of replays, oldest first, and the rows they hold.
    sets: Mutex<(std::collections::VecDeque<SharedSet>, usize)>,
}

/// One shared set of replays: one slot per run, None where that run was
/// not replayed (or is shared already).
type SharedSet = Vec<Option<Arc<LastReplay>>>;

impl SharedReplays {
    /// Run `i`'s replay of `model` from `start`, if shared.
    fn find(&self, i: usize, model: &Augmented, start: (f64, f64)) -> Option<Arc<LastReplay>> {
        let sets = self.sets.lock().unwrap_or_else(|e| e.into_inner());
        sets.0
            .iter()
            .rev()
            .filter_map(|set| set.get(i).and_then(Option::as_ref))
            .find(|l| l.matches(model, start))
            .cloned()
    }

    /// Shares the last replays of `caches` (one per run, in the campaign's
    /// order), those already shared left out.
    pub(crate) fn share(&self, caches: &[ReplayCache]) {
        let mut set: SharedSet = caches
            .iter()
            .map(|c| c.last.lock().unwrap_or_else(|e| e.into_inner()).clone())
            .collect();
        let mut sets = self.sets.lock().unwrap_or_else(|e| e.into_inner());
        for (i, slot) in set.iter_mut().enumerate() {
            let known = slot.as_ref().is_some_and(|l| {
                sets.0
                    .iter()
                    .filter_map(|s| s.get(i).and_then(Option::as_ref))
                    .any(|k| Arc::ptr_eq(k, l) || k.matches(&l.model, l.start))
            });
            if known {
                *slot = None;
            }
        }
        let rows = rows_of(&set);
        if rows == 0 {
            return;
        }
        sets.0.push_back(set);
        sets.1 += rows;
        while sets.1 > SHARED_ROWS && sets.0.len() > 1 {
            if let Some(old) = sets.0.pop_front() {
                sets.1 -= rows_of(&old);
            }
        }
    }
}

/// Rows of history a shared set holds.
fn rows_of(set: &[Option<Arc<LastReplay>>]) -> usize {
    set.iter().flatten().map(|l| l.history.len()).sum()
}

/// A run's replays a problem may reuse: the last one made (or reused) and
/// one kept on request ([`ReplayCache::keep_last`]), so that a point a fit
/// comes back to (a search's best, where the polish starts; the polish's
/// optimum, where it is linearised) is not integrated again after other
/// points have been tried. Memory: two histories per run.
#[derive(Default)]
pub(crate) struct ReplayCache {
    last: Mutex<Option<Arc<LastReplay>>>,
    kept: Mutex<Option<Arc<LastReplay>>>,
}

impl ReplayCache {
    /// Stores `model`'s replay `history` from `start` as the last one.
    fn store(&self, model: &Augmented, start: (f64, f64), history: TimeHistory) {
        *self.last.lock().unwrap_or_else(|e| e.into_inner()) = Some(Arc::new(LastReplay {
            model: model.clone(),
            start,
            history,
        }));
    }

    /// Keeps the last replay.
    pub(crate) fn keep_last(&self) {
        let last = self.last.lock().unwrap_or_else(|e| e.into_inner()).clone();
        *self.kept.lock().unwrap_or_else(|e| e.into_inner()) = last;
    }
}

mod chunked;

#[cfg(test)]
pub(crate) mod tests;
