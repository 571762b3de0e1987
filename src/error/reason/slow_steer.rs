//! What [`super::ParamReason::SlowSteer`] says, boxed: a sine or sweep
//! whose frequency is so low against its run that the steer never leaves
//! straight running (0.0001 Hz over 10 s steered 1.1e-4 rad, silently).

use crate::error::Num;
use crate::format::{fixed, rounded, significant};
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
/// step the metrics take as one. Hz, s, rad.
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
}

/// An angle in rad with its degrees: "0.00011 rad (0.01°)".
fn angle(v: f64) -> String {
    format!("{} rad ({}°)", significant(v, 3), fixed(v.to_degrees(), 3))
}

impl fmt::Display for SlowSteer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let run = self.end - self.start;
        // The mean frequency: a linear sweep's phase at its end is a sine's
        // of it; the steer reaches its amplitude once the phase passes a
        // quarter turn.
        let mean = 0.5 * (self.f_start + self.f_end);
        let (what, least) = match self.waveform {
            Waveform::Sine => (
                format!("a sine of `frequency` = {} Hz", Num(self.f_start)),
                format!("`frequency` ≥ {} Hz", rounded(0.25 / run, 3)),
            ),
            Waveform::Sweep => (
                format!(
                    "a sweep from `f_start` = {} Hz to `f_end` = {} Hz (a mean of {} Hz)",
                    Num(self.f_start),
                    Num(self.f_end),
                    rounded(mean, 3)
                ),
                format!("`f_start` + `f_end` ≥ {} Hz", rounded(0.5 / run, 3)),
            ),
        };
        write!(
            f,
            "{what} has a period of {} s against a run of {} s (`start` = {} s to `end` = {} s): within it the steer reaches only {} of its `amplitude` = {}, less than the {} a manoeuvre must steer, so the car would run straight, with no response to show; the steer reaches its amplitude once a quarter period fits in the run ({least}): is the frequency in Hz?",
            rounded(1.0 / mean, 3),
            Num(run),
            Num(self.start),
            Num(self.end),
            angle(self.reached),
            angle(self.amplitude.abs()),
            angle(self.min)
        )
    }
}
