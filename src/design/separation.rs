//! How far apart candidates' responses to a manoeuvre are, in units of
//! the campaign's noise, and how well that is known.
//!
//! A manoeuvre is logged as the campaign's runs are (their sample
//! interval, their channels) and replayed by the diagnosis's own replay
//! ([`Prepared`]) with each candidate as fitted. The separation of
//! candidates A and B is
//! `D = sqrt(Σ_c Σ_i ((y_B,c,i − y_A,c,i)/σ_c)²)` over the measured
//! channels c and the residual samples i, with σ_c the channel's noise
//! floor: on a run driven by a car that behaves as A, with white noise of
//! those floors, the difference of the two candidates' sums of squared
//! residuals `χ²_B − χ²_A` has mean `D²` and standard deviation `2D`, so
//! the measured separation `√(χ²_B − χ²_A)` is `D ± 1` (the noise's part of
//! the uncertainty). The parameters' part is the delta method over each
//! candidate's free values at their standard errors (central differences
//! of D at ±1 standard error), their correlations not known to
//! `diagnosis.json` and left out. A run of a car that behaves as neither
//! adds model-form error that neither part covers; the book's design
//! chapter measures how far that goes.
//!
//! Units: D is dimensionless (noise floors); SI, rad elsewhere.

use crate::diagnose::campaign::Campaign;
use crate::diagnose::model::{Augmented, Observed};
use crate::diagnose::pipeline::observed_channel;
use crate::diagnose::{Channel, Prepared};
use crate::manoeuvre::Manoeuvre;
use crate::measured::MeasuredRun;

/// What a campaign logs: the sample interval and which channels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Logging {
    /// Sample interval, s (the runs' median).
    pub interval: f64,
    /// Which response channels, by [`Channel`] index.
    pub channels: [bool; 3],
    /// Whether it logs `ax` (written as the speed's derivative).
    pub ax: bool,
    /// Whether it logs the bank (written as 0: a flat pad).
    pub bank: bool,
}

impl Logging {
    /// How campaign `c` logs its runs.
    pub fn of(c: &Campaign) -> Self {
        let mut dts: Vec<f64> = c
            .runs
            .iter()
            .flat_map(|r| r.t.windows(2).map(|w| w[1] - w[0]))
            .filter(|d| *d > 0.0)
            .collect();
        dts.sort_by(f64::total_cmp);
        let interval = dts.get(dts.len() / 2).copied().unwrap_or(0.01);
        Self {
            interval,
            channels: Channel::ALL.map(|ch| c.runs.iter().any(|r| ch.of(r).is_some())),
            ax: c.runs.iter().any(|r| r.ax.is_some()),
            bank: c.runs.iter().any(|r| r.bank.is_some()),
        }
    }

    /// Manoeuvre `m` as this logger records it, every response 0: the run
    /// a replay of it starts from straight running.
    pub fn run(&self, name: &str, m: &Manoeuvre) -> MeasuredRun {
        let (t0, t1) = (m.start_time(), m.end_time());
        let t: Vec<f64> = (0..)
            .map(|i| t0 + self.interval * i as f64)
            .take_while(|x| *x <= t1 + 1e-9)
            .collect();
        let zero = vec![0.0; t.len()];
        let on = |c: Channel| self.channels[c.index()].then(|| zero.clone());
        let speed = t.iter().map(|&x| m.speed(x)).collect();
        let steer = t.iter().map(|&x| m.steer(x)).collect();
        let ax = self
            .ax
            .then(|| t.iter().map(|&x| m.speed_rate(x)).collect::<Vec<f64>>());
        MeasuredRun::new(format!("{name}.csv"), t, speed, steer, zero.clone())
            .with_ay(on(Channel::Ay))
            .with_beta(on(Channel::Beta))
            .with_bank(self.bank.then(|| zero.clone()))
            .with_ax(ax)
    }
}

/// The separation D of two observations of the same run (NaN when either
/// diverged).
pub fn separation(a: &Observed, b: &Observed, floors: &[f64; 3], logging: &Logging) -> f64 {
    let mut s = 0.0;
    for c in Channel::ALL {
        let sigma = floors[c.index()];
        if !logging.channels[c.index()] || sigma <= 0.0 {
            continue;
        }
        for (x, y) in observed_channel(a, c).iter().zip(observed_channel(b, c)) {
            let d = (y - x) / sigma;
            s += d * d;
        }
    }
    if s.is_finite() {
        s.sqrt()
    } else {
        f64::NAN
    }
}

/// `run` made ready for replays (step `step`, residuals at `rate` Hz)
/// from its settled start ([`settled_start`]), not its first sample: how
/// a design replays every run, the campaign's as a driven one.
pub(crate) fn prepared(run: &MeasuredRun, step: f64, rate: f64) -> Prepared {
    let mut p = Prepared::new(run, step, rate);
    if let Some((start, _)) = settled_start(run) {
        p.start = start;
    }
    p
}

/// The campaign's runs made ready for replays from their settled starts
/// ([`prepared`]): one preparation for `design` and for the diagnosis's
/// advice on a lacking run, so both measure the same campaign separation.
pub(crate) fn campaign_prepared(c: &Campaign) -> Vec<Prepared> {
    let set = &c.settings;
    c.runs
        .iter()
        .map(|r| prepared(r, set.step, set.sample_rate))
        .collect()
}

/// The sum of squared residuals of `model` on `run` in units of the noise
/// floors, over the measured channels.
pub fn chi_square(run: &Prepared, model: &Augmented, floors: &[f64; 3]) -> f64 {
    chi_square_of(run, &run.observe(model), floors)
}

/// [`chi_square`] of a replay already made (`obs`, of `run`).
pub(crate) fn chi_square_of(run: &Prepared, obs: &Observed, floors: &[f64; 3]) -> f64 {
    let scales = floors.map(|f| if f > 0.0 { f } else { 1.0 });
    let mut r = vec![0.0; run.count()];
    run.write_residuals(obs, &scales, &mut r);
    r.iter().map(|x| x * x).sum()
}

/// The start of a run's replay, settled: the sideslip (0 where not
/// measured) and yaw rate over its opening stretch of held steer (within
/// [`SETTLED_STEER`] of its first value, at most [`super::family::LEAD`]
/// s, the family's straight lead-in; masked samples left out), and the
/// number of samples whose mean has the same noise. A replay from one
/// sample starts both candidates off by that sample's noise, and the
/// transient that follows weighs on `χ²_B − χ²_A` as much as the
/// manoeuvre (a delayed sensor holds it); the mean of `n` samples is off
/// by `1/√n` of it. Where a channel still moves across the stretch (a
/// piece cut from a turn it is still settling into: its least-squares
/// line departs from the mean at the first sample by more than
/// [`DRIFT_SIGMAS`] of its own standard error), that line's value at the
/// first sample is taken instead, whose noise is that of the mean of
/// `n(n+1)/(4n−2)` samples. None: no two samples to average.
pub fn settled_start(run: &MeasuredRun) -> Option<((f64, f64), usize)> {
    let (t0, d0) = (*run.t.first()?, *run.steer.first()?);
    let held = run
        .t
        .iter()
        .zip(&run.steer)
        .take_while(|(t, d)| {
            **t - t0 <= super::family::LEAD + 1e-9 && (**d - d0).abs() <= SETTLED_STEER
        })
        .count();
    let idx: Vec<usize> = (0..held).filter(|i| !run.masked.contains(i)).collect();
    if idx.len() < 2 {
        return None;
    }
    let t: Vec<f64> = idx.iter().map(|&i| run.t[i]).collect();
    let beta = run
        .beta
        .as_deref()
        .map(|b| start_of(&t, idx.iter().map(|&i| b[i])));
    let r = start_of(&t, idx.iter().map(|&i| run.yaw_rate[i]));
    let n = beta.map_or(r.1, |b| b.1.min(r.1));
    Some(((beta.map_or(0.0, |b| b.0), r.0), n))
}

/// Standard errors of its own by which a channel's least-squares line
/// over the opening stretch must depart from the stretch's mean, at the
/// first sample, for the line to be taken ([`settled_start`]): a channel
/// at rest departs by more than 3 in 0.3 % of runs.
pub const DRIFT_SIGMAS: f64 = 3.0;

/// A channel's value at the first of the times `t` ([`settled_start`]):
/// the mean of `x`, or its least-squares line's value there where that
/// departs from the mean by more than [`DRIFT_SIGMAS`] standard errors;
/// and the samples whose mean has the same noise.
fn start_of(t: &[f64], x: impl Iterator<Item = f64>) -> (f64, usize) {
    let x: Vec<f64> = x.collect();
    let n = x.len() as f64;
    let (tm, xm) = (t.iter().sum::<f64>() / n, x.iter().sum::<f64>() / n);
    let stt: f64 = t.iter().map(|v| (v - tm).powi(2)).sum();
    let slope = match stt > 0.0 {
        true => {
            t.iter()
                .zip(&x)
                .map(|(a, b)| (a - tm) * (b - xm))
                .sum::<f64>()
                / stt
        }
        false => 0.0,
    };
    let at_first = xm + slope * (t[0] - tm);
    // The line's residual variance; the departure at the first sample is
    // slope·(t0 − t̄), of standard error s·|t0 − t̄|/√Stt.
    let dof = (n - 2.0).max(1.0);
    let s2 = t
        .iter()
        .zip(&x)
        .map(|(a, b)| (b - xm - slope * (a - tm)).powi(2))
        .sum::<f64>()
        / dof;
    let se = (s2 / stt.max(f64::MIN_POSITIVE)).sqrt() * (t[0] - tm).abs();
    let k = x.len();
    if k > 2 && (at_first - xm).abs() > DRIFT_SIGMAS * se && se.is_finite() {
        (at_first, (k * (k + 1) / (4 * k - 2)).max(1))
    } else {
        (xm, k)
    }
}

/// How far the steer may move in the opening stretch a driven run's start
/// is settled over, rad (0.1°: a hand holding the wheel).
pub const SETTLED_STEER: f64 = 0.1 * std::f64::consts::PI / 180.0;

/// What the start of a driven run does to its measured separation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct StartTerms {
    /// `χ²_B − χ²_A` on the reference's own noise-free response (D²).
    pub(crate) d2: f64,
    /// Its expected change from the noise of the start.
    pub(crate) shift: f64,
    /// The variance that noise adds to it.
    pub(crate) variance: f64,
}

/// How the noise of a driven run's start moves `χ²_B − χ²_A`: a replay
/// starts from the measured start, so its noise starts both candidates off
/// the car's state, and a transient follows (a sideslip one noise floor off
/// is a lateral acceleration several floors off for a few tenths of a
/// second, and a delayed sensor holds it for its delay). Each start
/// channel the run measures is moved by ±`start_sd` (its standard
/// deviation, by channel index: one sample's noise, [`Fitted::start_noise`],
/// over √n for a start averaged over n samples — not the floor, which for
/// an estimated sideslip is ten times its noise) on the reference's own
/// noise-free response; the change `e(±)` is taken as quadratic in the
/// start's error `x` (in standard deviations, standard normal):
/// `e = b·x + a·x²` with `a = (e₊ + e₋)/2`, `b = (e₊ − e₋)/2`, so its mean
/// is `a` and its variance `b² + 2a²`, summed over the channels.
///
/// [`Fitted::start_noise`]: super::Fitted::start_noise
pub(crate) fn start_terms(
    template: &MeasuredRun,
    models: [&Augmented; 2],
    (floors, start_sd): (&[f64; 3], &[f64; 3]),
    (step, rate): (f64, f64),
) -> StartTerms {
    // At every sample: a run without a sideslip scores from later on.
    let clean = Prepared::new(template, step, 1e6).observe_at(models[0], &template.t);
    let mut car = template.clone();
    car.yaw_rate = clean.yaw_rate.clone();
    if car.ay.is_some() {
        car.ay = Some(clean.ay.clone());
    }
    if car.beta.is_some() {
        car.beta = Some(clean.beta.clone());
    }
    let diff = |r: &MeasuredRun| {
        let p = Prepared::new(r, step, rate);
        chi_square(&p, models[1], floors) - chi_square(&p, models[0], floors)
    };
    let base = diff(&car);
    // The replay starts at the first sample not masked.
    let first = (0..car.t.len())
        .find(|i| !car.masked.contains(i))
        .unwrap_or(0);
    let (mut shift, mut variance) = (0.0, 0.0);
    for ch in [Channel::YawRate, Channel::Beta] {
        let f = start_sd[ch.index()];
        if f <= 0.0 || (ch == Channel::Beta && car.beta.is_none()) {
            continue;
        }
        let moved = |sign: f64| {
            let mut r = car.clone();
            match ch {
                Channel::YawRate => r.yaw_rate[first] += sign * f,
                _ => r.beta.as_mut().expect("measured")[first] += sign * f,
            }
            diff(&r) - base
        };
        let (up, down) = (moved(1.0), moved(-1.0));
        let (a, b) = (0.5 * (up + down), 0.5 * (up - down));
        if a.is_finite() && b.is_finite() {
            shift += a;
            variance += b * b + 2.0 * a * a;
        }
    }
    StartTerms {
        d2: base,
        shift,
        variance,
    }
}

/// The parameters' part of the uncertainty of `D(a, b)`: for each free
/// value of each candidate, half the change of D between ±1 standard
/// error, added in quadrature. `a` and `b` are (candidate, its model's
/// values) pairs; `observe` replays a model on the run.
pub(crate) fn parameter_spread(
    members: [(&super::FittedCandidate, &Augmented); 2],
    base: &Augmented,
    observe: &(dyn Fn(&Augmented) -> Observed + Sync),
    floors: &[f64; 3],
    logging: &Logging,
) -> f64 {
    use rayon::prelude::*;
    let obs = members.map(|(_, m)| observe(m));
    let mut jobs = Vec::new();
    for (k, (cand, _)) in members.iter().enumerate() {
        for (i, v) in cand.values().enumerate() {
            if v.free {
                jobs.push((k, i, v.std_error));
            }
        }
    }
    let var: f64 = jobs
        .par_iter()
        .map(|&(k, i, se)| {
            let cand = members[k].0;
            let at = |sign: f64| -> f64 {
                let mut v: Vec<f64> = cand.values().map(|x| x.value).collect();
                v[i] += sign * se;
                let Some(m) = cand.model_with(base, &v) else {
                    return f64::NAN;
                };
                let moved = observe(&m);
                let other = &obs[1 - k];
                separation(&moved, other, floors, logging)
            };
            let half = 0.5 * (at(1.0) - at(-1.0));
            if half.is_finite() {
                half * half
            } else {
                0.0
            }
        })
        .sum();
    var.sqrt()
}
