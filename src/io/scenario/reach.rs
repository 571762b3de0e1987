//! How far a manoeuvre steers the road wheels within its run, checked
//! against what a road wheel can do and what the metrics take as a steer:
//! a ramp's reach by its `end`, and the largest |steer| a sine or sweep
//! reaches before the run ends (a sine of 0.0001 Hz over 10 s steered
//! 1.1e-4 rad of its 0.0175 rad and ran straight without a word), and
//! against its own amplitude (0.001 Hz over 10 s reached 6 % of it).
//! Rad, s, Hz.

use super::super::limits::{road_wheel_steer, MAX_ROAD_WHEEL_STEER};
use crate::error::{ParamError, ParamReason, SlowSteer, Waveform};
use crate::manoeuvre::{RampSteer, SineSteer, SweepSteer};
use crate::metrics::MIN_STEP;
use std::f64::consts::{FRAC_PI_2, PI};

/// The steer a ramp reaches by its `end`, within ±[`MAX_ROAD_WHEEL_STEER`],
/// refused at `rate` naming that steer: the rate itself may be sound and
/// the run too long. Degrees are suggested only for a rate that passes the
/// limit within a second, which no ramp in rad/s of a road wheel does.
pub(super) fn ramp_reach(r: &RampSteer) -> Result<(), ParamError> {
    let reached = r.rate * (r.end - r.start);
    if road_wheel_steer("rate", reached).is_ok() {
        return Ok(());
    }
    Err(ParamError::new(
        "rate",
        r.rate,
        ParamReason::RampReach {
            reached,
            end: r.end,
            in_degrees: r.rate.abs() > MAX_ROAD_WHEEL_STEER,
        },
    ))
}

/// A manoeuvre that steers the road wheels by at most `reached`, rad,
/// refused at `key` (written as `v`) below the smallest step the metrics
/// take as one: a sine of amplitude 0 or a ramp of rate 0 ran as straight
/// running without a word, answering nothing the file asked.
pub(super) fn steers(key: &str, v: f64, reached: f64) -> Result<(), ParamError> {
    if reached.abs() >= MIN_STEP {
        return Ok(());
    }
    let reason = ParamReason::NoSteer {
        reached: reached.abs(),
        min: MIN_STEP,
    };
    Err(ParamError::new(key, v, reason))
}

/// The largest |steer| of amplitude `amplitude` whose phase turns
/// steadily from 0 to `phase` (rad) over the run: the amplitude once the
/// phase passes a quarter turn, else the steer at the run's end (it rises
/// over the whole first quarter).
fn largest_steer(amplitude: f64, phase: f64) -> f64 {
    match phase >= FRAC_PI_2 {
        true => amplitude.abs(),
        false => (amplitude * phase.sin()).abs(),
    }
}

/// The least share of its amplitude a sine or sweep must reach within its
/// run. A run that holds less than a tenth of a quarter period (0.0016 Hz
/// over 10 s) steers a slow ramp: 0.001 Hz over 10 s reached 6 % of its
/// 0.1 rad and ran without a word, a frequency most likely written in
/// mHz or a period for a frequency.
pub(crate) const MIN_REACH_SHARE: f64 = 0.1;

/// [`SlowSteer`] at `key` (written as `v`) where the largest steer within
/// the run is below [`MIN_STEP`] while the amplitude is not (an amplitude
/// below it is [`steers`]'s to refuse), or below [`MIN_REACH_SHARE`] of
/// the amplitude.
fn slow(key: &str, v: f64, s: SlowSteer) -> Result<(), ParamError> {
    if s.reached >= MIN_STEP && s.reached >= MIN_REACH_SHARE * s.amplitude.abs() {
        return Ok(());
    }
    Err(ParamError::new(key, v, ParamReason::SlowSteer(Box::new(s))))
}

/// A sine whose steer within its run (from `start` to `end`) stays below
/// [`MIN_STEP`]: its frequency too low for the run (a period of 10,000 s
/// against 10 s), refused at `frequency`.
pub(super) fn sine_reach(s: &SineSteer) -> Result<(), ParamError> {
    let phase = 2.0 * PI * s.frequency * (s.end - s.start);
    slow(
        "frequency",
        s.frequency,
        SlowSteer {
            waveform: Waveform::Sine,
            f_start: s.frequency,
            f_end: s.frequency,
            start: s.start,
            end: s.end,
            amplitude: s.amplitude,
            reached: largest_steer(s.amplitude, phase),
            min: MIN_STEP,
            min_share: MIN_REACH_SHARE,
        },
    )
}

/// A sweep whose steer within its run stays below [`MIN_STEP`], refused at
/// `key`, the key of its higher frequency: its phase at the end,
/// `2π(f_start·T + (f_end − f_start)·T/2) = π(f_start + f_end)·T`, short
/// of a quarter turn by far.
pub(super) fn sweep_reach(s: &SweepSteer, key: &str) -> Result<(), ParamError> {
    let phase = PI * (s.f_start + s.f_end) * (s.end - s.start);
    let v = if key == "f_start" { s.f_start } else { s.f_end };
    slow(
        key,
        v,
        SlowSteer {
            waveform: Waveform::Sweep,
            f_start: s.f_start,
            f_end: s.f_end,
            start: s.start,
            end: s.end,
            amplitude: s.amplitude,
            reached: largest_steer(s.amplitude, phase),
            min: MIN_STEP,
            min_share: MIN_REACH_SHARE,
        },
    )
}
