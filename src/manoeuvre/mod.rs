//! Open-loop manoeuvres: front road-wheel steer δ(t) and forward speed u(t).
//!
//! Step steer as GB/T 6323-2014 and ISO 7401:2011 define it (a ramp from 0 to
//! the amplitude in `rise_time`, time zero of the metrics at 50 % of the
//! steer input), ramp steer, sine, linear frequency sweep and the replay of a
//! measured run (linear interpolation of its steer and speed).
//! Units: s, rad, m/s, Hz. Positive steer turns left.

use crate::scalar::Scalar;
use serde::{Deserialize, Serialize};

fn default_start() -> f64 {
    1.0
}

/// Step steer: δ rises linearly from 0 to `amplitude` between `start` and
/// `start + rise_time`, at constant speed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StepSteer {
    /// Forward speed, m/s.
    pub speed: f64,
    /// Steer step, rad (added to `trim`).
    pub amplitude: f64,
    /// Steer held before the step, rad: the straight-running steer of a
    /// vehicle whose tyres have offsets (0 for symmetric tyres).
    #[serde(default)]
    pub trim: f64,
    /// Time the steer starts to move, s.
    pub start: f64,
    /// 0–100 % rise time of the steer, s (GB/T 6323: ≤ 0.2 s).
    pub rise_time: f64,
    /// End of the run, s.
    pub end: f64,
}

/// Ramp steer at constant speed: δ = rate·(t − start) after `start`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RampSteer {
    /// Forward speed, m/s.
    pub speed: f64,
    /// Steer rate, rad/s.
    pub rate: f64,
    /// Time the ramp starts, s. Default 1 s.
    #[serde(default = "default_start")]
    pub start: f64,
    /// End of the run, s.
    pub end: f64,
}

/// Sine steer at constant speed from `start` on.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SineSteer {
    /// Forward speed, m/s.
    pub speed: f64,
    /// Steer amplitude, rad.
    pub amplitude: f64,
    /// Frequency, Hz.
    pub frequency: f64,
    /// Time the sine starts (at zero phase), s. Default 1 s.
    #[serde(default = "default_start")]
    pub start: f64,
    /// End of the run, s.
    pub end: f64,
}

/// Linear frequency sweep (chirp) at constant speed from `start` to `end`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepSteer {
    /// Forward speed, m/s.
    pub speed: f64,
    /// Steer amplitude, rad.
    pub amplitude: f64,
    /// Frequency at `start`, Hz.
    pub f_start: f64,
    /// Frequency at `end`, Hz.
    pub f_end: f64,
    /// Start of the sweep, s. Default 1 s.
    #[serde(default = "default_start")]
    pub start: f64,
    /// End of the sweep and of the run, s.
    pub end: f64,
}

/// A measured run's steer and speed, replayed by linear interpolation,
/// with its longitudinal acceleration and road bank where it logs them.
#[derive(Debug, Clone, PartialEq)]
pub struct Replay {
    /// Sample times, s, strictly increasing.
    pub t: Vec<f64>,
    /// Steer, rad.
    pub steer: Vec<f64>,
    /// Speed, m/s.
    pub speed: Vec<f64>,
    /// Measured longitudinal acceleration, m/s² (None: the speed's
    /// smoothed derivative stands in, as in `diagnose`'s replays).
    pub ax: Option<Vec<f64>>,
    /// Measured road bank, rad, positive with the road's left edge higher
    /// (None: a flat road, or the scenario's constant `road_bank`).
    pub bank: Option<Vec<f64>>,
}

impl Replay {
    /// Steer and speed at times `t`, with no measured acceleration or bank
    /// (a schedule, a designed manoeuvre).
    pub fn of_inputs(t: Vec<f64>, steer: Vec<f64>, speed: Vec<f64>) -> Self {
        Self {
            t,
            steer,
            speed,
            ax: None,
            bank: None,
        }
    }

    /// The measured longitudinal acceleration at `t`, m/s², where logged.
    pub(crate) fn ax_at(&self, t: f64) -> Option<f64> {
        self.ax.as_ref().map(|ax| self.interp(ax, t))
    }

    /// The measured road bank at `t`, rad (0 where not logged).
    pub(crate) fn bank_at(&self, t: f64) -> f64 {
        self.bank.as_ref().map_or(0.0, |b| self.interp(b, t))
    }

    /// Index `i` with `t[i] ≤ t < t[i+1]`, clamped to the ends.
    fn segment(&self, t: f64) -> usize {
        let n = self.t.len();
        match self.t.partition_point(|&x| x <= t) {
            0 => 0,
            k if k >= n => n - 2,
            k => k - 1,
        }
    }
    fn interp(&self, y: &[f64], t: f64) -> f64 {
        interpolate(&self.t, y, t)
    }
}

/// Linear interpolation of (xs, ys) at x, xs increasing, clamped to the
/// ends (the replay of a run and the comparison with one both use it).
pub(crate) fn interpolate(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    interpolate_of(xs, ys, x)
}

/// [`interpolate`] in a scalar of the `num-dual` crate: the values `ys` and
/// the abscissa `x` may carry derivatives (a delay being fitted moves `x`).
/// At a node, an `x` that carries a derivative takes the slope of the
/// segment below it: the one a growing delay moves into, whose one-sided
/// derivative a fit pressed onto a zero delay needs.
pub(crate) fn interpolate_of<T: Scalar>(xs: &[f64], ys: &[T], x: T) -> T {
    let k = xs.partition_point(|v| *v <= x.re());
    interpolate_below(xs, ys, x, k)
}

/// [`interpolate_of`] at many abscissae in turn, each found from the last
/// one's segment (a replay's sample times, a delayed copy of them): forward
/// a few nodes at a time, by bisection beyond that or backwards. The
/// values are [`interpolate_of`]'s to the bit.
pub(crate) struct Interpolator<'a> {
    xs: &'a [f64],
    /// The count of nodes at or below the last abscissa.
    k: usize,
}

/// Nodes an [`Interpolator`] steps over one by one before it bisects.
const WALK: usize = 8;

impl<'a> Interpolator<'a> {
    /// An interpolator over the increasing nodes `xs`.
    pub(crate) fn new(xs: &'a [f64]) -> Self {
        Self { xs, k: 0 }
    }

    /// The value of `ys` at `x` ([`interpolate_of`]).
    pub(crate) fn at<T: Scalar>(&mut self, ys: &[T], x: T) -> T {
        let (xs, at) = (self.xs, x.re());
        let mut k = self.k;
        if k > 0 && xs[k - 1] > at {
            k = xs.partition_point(|v| *v <= at);
        } else {
            let mut walked = 0;
            while k < xs.len() && xs[k] <= at {
                k += 1;
                walked += 1;
                if walked == WALK {
                    k += xs[k..].partition_point(|v| *v <= at);
                    break;
                }
            }
        }
        self.k = k;
        interpolate_below(xs, ys, x, k)
    }
}

/// [`interpolate_of`] given `k`, the count of nodes at or below `x`.
fn interpolate_below<T: Scalar>(xs: &[f64], ys: &[T], x: T, k: usize) -> T {
    let at = x.re();
    let mut k = k;
    if k == 0 {
        return ys[0];
    }
    if xs[k - 1] == at && !x.is_constant() {
        if k < 2 {
            // Below the first node the signal is held: no slope.
            return ys[0];
        }
        k -= 1;
    } else if k >= xs.len() {
        return ys[ys.len() - 1];
    }
    let (x0, x1) = (xs[k - 1], xs[k]);
    let w = if x1 > x0 {
        (x - x0) / (x1 - x0)
    } else {
        T::from(0.0)
    };
    ys[k - 1] + w * (ys[k] - ys[k - 1])
}

/// Any manoeuvre.
#[derive(Debug, Clone, PartialEq)]
pub enum Manoeuvre {
    /// Step steer.
    StepSteer(StepSteer),
    /// Ramp steer.
    RampSteer(RampSteer),
    /// Sine steer.
    Sine(SineSteer),
    /// Frequency sweep.
    Sweep(SweepSteer),
    /// Replay of a measured run.
    Replay(Replay),
}

impl Manoeuvre {
    /// Front road-wheel steer at `t`, rad.
    pub fn steer(&self, t: f64) -> f64 {
        use std::f64::consts::TAU;
        match self {
            Manoeuvre::StepSteer(s) => {
                // Right-continuous at `start`, so an ideal step (rise time 0)
                // acts from the first integration stage at `start` on.
                let ramp = if t < s.start {
                    0.0
                } else if s.rise_time <= 0.0 || t >= s.start + s.rise_time {
                    1.0
                } else {
                    (t - s.start) / s.rise_time
                };
                s.trim + s.amplitude * ramp
            }
            Manoeuvre::RampSteer(r) => r.rate * (t - r.start).max(0.0),
            Manoeuvre::Sine(s) => {
                if t <= s.start {
                    0.0
                } else {
                    s.amplitude * (TAU * s.frequency * (t - s.start)).sin()
                }
            }
            Manoeuvre::Sweep(s) => {
                // Closed at `end`: the history's last row, at `end`, is the
                // sweep's, not a straight wheel after it.
                if t <= s.start || t > s.end {
                    return 0.0;
                }
                let tau = t - s.start;
                let k = (s.f_end - s.f_start) / (s.end - s.start);
                s.amplitude * (TAU * (s.f_start * tau + 0.5 * k * tau * tau)).sin()
            }
            Manoeuvre::Replay(r) => r.interp(&r.steer, t),
        }
    }

    /// Forward speed at `t`, m/s.
    pub fn speed(&self, t: f64) -> f64 {
        match self {
            Manoeuvre::StepSteer(s) => s.speed,
            Manoeuvre::RampSteer(s) => s.speed,
            Manoeuvre::Sine(s) => s.speed,
            Manoeuvre::Sweep(s) => s.speed,
            Manoeuvre::Replay(r) => r.interp(&r.speed, t),
        }
    }

    /// du/dt at `t`, m/s² (the slope of the current segment for a replay).
    pub(crate) fn speed_rate(&self, t: f64) -> f64 {
        match self {
            Manoeuvre::Replay(r) if r.t.len() > 1 => {
                let i = r.segment(t);
                (r.speed[i + 1] - r.speed[i]) / (r.t[i + 1] - r.t[i])
            }
            _ => 0.0,
        }
    }

    /// First time of the run, s.
    pub(crate) fn start_time(&self) -> f64 {
        match self {
            Manoeuvre::Replay(r) => r.t[0],
            _ => 0.0,
        }
    }

    /// Last time of the run, s.
    pub(crate) fn end_time(&self) -> f64 {
        match self {
            Manoeuvre::StepSteer(s) => s.end,
            Manoeuvre::RampSteer(s) => s.end,
            Manoeuvre::Sine(s) => s.end,
            Manoeuvre::Sweep(s) => s.end,
            Manoeuvre::Replay(r) => *r.t.last().expect("a replay has samples"),
        }
    }

    /// Times where the steer or speed input has a kink or a jump (ramp
    /// ends, the start of a sine, every sample of a replay): an adaptive
    /// integrator restarts there instead of stepping across.
    pub(crate) fn breakpoints(&self) -> Vec<f64> {
        match self {
            Manoeuvre::StepSteer(s) => vec![s.start, s.start + s.rise_time.max(0.0)],
            Manoeuvre::RampSteer(r) => vec![r.start],
            Manoeuvre::Sine(s) => vec![s.start],
            Manoeuvre::Sweep(s) => vec![s.start, s.end],
            Manoeuvre::Replay(r) => r.t.clone(),
        }
    }

    /// The same manoeuvre with the steer mirrored (δ → −δ).
    pub fn mirrored(&self) -> Manoeuvre {
        let mut m = self.clone();
        match &mut m {
            Manoeuvre::StepSteer(s) => {
                s.amplitude = -s.amplitude;
                s.trim = -s.trim;
            }
            Manoeuvre::RampSteer(s) => s.rate = -s.rate,
            Manoeuvre::Sine(s) => s.amplitude = -s.amplitude,
            Manoeuvre::Sweep(s) => s.amplitude = -s.amplitude,
            Manoeuvre::Replay(r) => r.steer.iter_mut().for_each(|d| *d = -*d),
        }
        m
    }
}

#[cfg(test)]
mod tests {
    use super::{interpolate_of, Interpolator};

    #[test]
    fn the_interpolator_gives_interpolate_of_to_the_bit_in_any_order() {
        // Nodes with a repeated time (a jump), abscissae below, on, between
        // and beyond them, forwards by small and large strides and back.
        let xs: [f64; 12] = [0.0, 0.1, 0.2, 0.2, 0.35, 0.5, 0.6, 0.8, 1.0, 1.1, 1.3, 1.5];
        let ys: Vec<f64> = xs
            .iter()
            .enumerate()
            .map(|(i, x)| (x * 7.0).sin() + i as f64)
            .collect();
        let mut at: Vec<f64> = (-3..170).map(|i| i as f64 * 0.01).collect();
        at.extend([0.2, 0.05, 1.45, 0.0, 2.0, 0.2, 0.199, 1.3]);
        let mut nodes = Interpolator::new(&xs);
        for &x in &at {
            let (a, b) = (nodes.at(&ys, x), interpolate_of(&xs, &ys, x));
            assert_eq!(a.to_bits(), b.to_bits(), "at {x}: {a} against {b}");
        }
    }

    use super::*;

    #[test]
    fn step_steer_reaches_half_amplitude_at_mid_rise() {
        let m = Manoeuvre::StepSteer(StepSteer {
            speed: 20.0,
            amplitude: 0.02,
            trim: 0.0,
            start: 1.0,
            rise_time: 0.2,
            end: 5.0,
        });
        assert_eq!(m.steer(0.5), 0.0);
        assert!((m.steer(1.1) - 0.01).abs() < 1e-15);
        assert_eq!(m.steer(2.0), 0.02);
        assert_eq!(m.mirrored().steer(2.0), -0.02);
    }

    #[test]
    fn replay_interpolates_and_differentiates_speed() {
        let m = Manoeuvre::Replay(Replay::of_inputs(
            vec![0.0, 1.0, 3.0],
            vec![0.0, 0.1, 0.3],
            vec![10.0, 12.0, 12.0],
        ));
        assert!((m.steer(2.0) - 0.2).abs() < 1e-15);
        assert_eq!(m.steer(-1.0), 0.0);
        assert!((m.speed(0.5) - 11.0).abs() < 1e-15);
        assert_eq!(m.speed_rate(0.5), 2.0);
        assert_eq!(m.speed_rate(2.5), 0.0);
        assert_eq!(m.steer(10.0), 0.3);
        assert_eq!(m.end_time(), 3.0);
    }

    #[test]
    fn sweep_frequency_rises_linearly() {
        let s = SweepSteer {
            speed: 20.0,
            amplitude: 1.0,
            f_start: 0.0,
            f_end: 2.0,
            start: 0.0,
            end: 10.0,
        };
        let m = Manoeuvre::Sweep(s);
        // Phase 2π·(0.1·τ²): zero crossings at τ = sqrt(k/0.2)·... at τ = √10.
        let tz = (10.0f64).sqrt();
        assert!(m.steer(tz).abs() < 1e-12);
    }
}
