//! What [`super::ParamReason::SlowSteer`] says, boxed: a sine or sweep
//! whose frequency is so low against its run that the steer never leaves
//! straight running (0.0001 Hz over 10 s steered 1.1e-4 rad, silently),
//! or reaches a few percent of its amplitude (0.001 Hz over 10 s: 6 %, a
//! slow ramp), with the share reached and the least frequency that
//! reaches the share asked.

use super::{angle, compared};
use crate::error::Num;
use crate::format::{fixed, rounded, rounded_up, significant};
use std::f64::consts::{FRAC_PI_2, PI};
use std::fmt;

/// The waveform of a [`SlowSteer`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Waveform {
    /// A sine of `frequency`.
    Sine,
    /// A linear sweep from `f_start` to `f_end`.
    Sweep,
}

/// A sine or sweep whose steer, within its run, stays below the smallest
/// step the metrics take as one, or below [`SlowSteer::min_share`] of its
/// amplitude (0.001 Hz over 10 s steered 0.0063 rad of 0.1 rad: a slow
/// ramp, not the sine the file asks for). Hz, s, rad.
#[derive(Debug, Clone, PartialEq)]
pub struct SlowSteer {
    /// Sine or sweep.
    pub waveform: Waveform,
    /// The frequency at `start` (a sine's only one), Hz.
    pub f_start: f64,
    /// The frequency at `end`, Hz.
    pub f_end: f64,
    /// Where the steer starts, s.
    pub start: f64,
    /// Where the run ends, s.
    pub end: f64,
    /// The steer amplitude, rad.
    pub amplitude: f64,
    /// The largest |steer| within the run, rad.
    pub reached: f64,
    /// The least steer a manoeuvre must reach, rad.
    pub min: f64,
    /// The least share of its amplitude a sine or sweep must reach within
    /// its run (0.1: below it the steer is a slow ramp).
    pub min_share: f64,
}

impl SlowSteer {
    /// The share of its amplitude the steer must reach: the stated share,
    /// or more where that share of the amplitude is below `min`.
    fn needed(&self) -> f64 {
        self.min_share.max(self.min / self.amplitude.abs()).min(1.0)
    }

    /// The phase (rad) the run must turn through to reach the needed
    /// share: `asin(share)`, a sine's phase at its largest steer.
    fn needed_phase(&self) -> f64 {
        self.needed().asin()
    }
}

/// The words of the least frequency: a sine's, or a sweep's sum of its
/// ends (its phase at the end is `π(f_start + f_end)·T`), reaching the
/// phase `phase` within a run of `run` s.
fn least(waveform: Waveform, phase: f64, run: f64) -> String {
    match waveform {
        Waveform::Sine => format!(
            "`frequency` ≥ {} Hz",
            rounded_up(phase / (2.0 * PI * run), 2)
        ),
        Waveform::Sweep => format!(
            "`f_start` + `f_end` ≥ {} Hz",
            rounded_up(phase / (PI * run), 2)
        ),
    }
}

impl fmt::Display for SlowSteer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let run = self.end - self.start;
        // The mean frequency: a linear sweep's phase at its end is a sine's
        // of it; the steer reaches its amplitude once the phase passes a
        // quarter turn.
        let mean = 0.5 * (self.f_start + self.f_end);
        let what = match self.waveform {
            Waveform::Sine => format!("a sine of `frequency` = {} Hz", Num(self.f_start)),
            Waveform::Sweep => format!(
                "a sweep from `f_start` = {} Hz to `f_end` = {} Hz (a mean of {} Hz)",
                Num(self.f_start),
                Num(self.f_end),
                rounded(mean, 3)
            ),
        };
        let amplitude = self.amplitude.abs();
        let share = self.reached / amplitude;
        let why = if self.reached < self.min {
            let (reached, min) = compared(self.reached, self.min);
            format!("{reached}, {}, less than the {min} a manoeuvre must steer, so the car would run straight, with no response to show", of_amplitude(significant(100.0 * share, 2), self.amplitude))
        } else {
            format!(
                "{}, {}, less than the {} % a {} must reach to be one: the steer is a slow ramp, not the waveform asked for",
                angle(self.reached),
                of_amplitude(below(share, self.min_share), self.amplitude),
                rounded(100.0 * self.min_share, 3),
                match self.waveform {
                    Waveform::Sine => "sine",
                    Waveform::Sweep => "sweep",
                }
            )
        };
        write!(
            f,
            "{what} has a period of {} s against a run of {} s (`start` = {} s to `end` = {} s): within it the steer reaches only {why}; {} reaches {} % of it, and the steer reaches its amplitude once a quarter period fits in the run ({}): is the frequency in Hz?",
            rounded(1.0 / mean, 3),
            Num(run),
            Num(self.start),
            Num(self.end),
            least(self.waveform, self.needed_phase(), run),
            rounded(100.0 * self.needed(), 3),
            least(self.waveform, FRAC_PI_2, run),
        )
    }
}

/// "6.3 % of its `amplitude` = 0.1 rad (5.73°)": a share (in percent,
/// as written) with the amplitude as the file writes it (its key's value,
/// not re-rounded).
fn of_amplitude(share: String, amplitude: f64) -> String {
    format!(
        "{share} % of its `amplitude` = {} rad ({}°)",
        Num(amplitude),
        fixed(amplitude.to_degrees(), 2)
    )
}

/// `share`, below `limit` (shares of one), in percent with the digits
/// that show it below: 0.09999 of an amplitude was said as "10.0 %, less
/// than the 10 %"; now "9.999 %".
fn below(share: f64, limit: f64) -> String {
    let digits = (2..=8).find(|&d| {
        significant(100.0 * share, d)
            .parse::<f64>()
            .is_ok_and(|s| s < 100.0 * limit)
    });
    significant(100.0 * share, digits.unwrap_or(8))
}
