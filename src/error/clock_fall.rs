//! How a run's time column fails to increase at a row (`FORMATS.md`: `t`
//! strictly increasing), said with what to do: a time repeated (a row
//! logged twice), a clock that falls back and resumes where a new
//! recording starts (split the file), or a counter that wraps (unwrap it:
//! add its period to the rows after the fall). Told apart by
//! `crate::measured::clock::fall_of`. Times in s.

use super::number::Num;
use std::fmt;

/// A logger's clock counter whose wrap a fall of the time may be: its
/// period is the counter's range.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Counter {
    /// A 16-bit counter of milliseconds: 65.536 s.
    Millis16,
    /// A 16-bit counter of 10 ms: 655.36 s.
    Centis16,
    /// A 32-bit counter of microseconds: 4294.967296 s.
    Micros32,
    /// A 32-bit counter of milliseconds: 4294967.296 s.
    Millis32,
    /// Seconds of the minute: 60 s.
    Minute,
    /// Seconds of the hour: 3600 s.
    Hour,
    /// Seconds of the day: 86400 s.
    Day,
}

impl Counter {
    /// Every counter, shortest period first.
    pub const ALL: [Counter; 7] = [
        Counter::Minute,
        Counter::Millis16,
        Counter::Centis16,
        Counter::Hour,
        Counter::Micros32,
        Counter::Day,
        Counter::Millis32,
    ];

    /// Its period, s.
    pub fn period(self) -> f64 {
        match self {
            Counter::Millis16 => 65.536,
            Counter::Centis16 => 655.36,
            Counter::Micros32 => 4294.967296,
            Counter::Millis32 => 4294967.296,
            Counter::Minute => 60.0,
            Counter::Hour => 3600.0,
            Counter::Day => 86400.0,
        }
    }

    /// What counts it, for the message.
    fn words(self) -> &'static str {
        match self {
            Counter::Millis16 => "a 16-bit millisecond counter's period (2^16 ms)",
            Counter::Centis16 => "a 16-bit counter of 10 ms's period (2^16 × 10 ms)",
            Counter::Micros32 => "a 32-bit microsecond counter's period (2^32 µs)",
            Counter::Millis32 => "a 32-bit millisecond counter's period (2^32 ms)",
            Counter::Minute => "a minute: a clock of the seconds of the minute",
            Counter::Hour => "an hour: a clock of the seconds of the hour",
            Counter::Day => "a day: a time of day in seconds",
        }
    }
}

/// How the time fails to increase at a row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ClockFall {
    /// The same time as the row before.
    Repeated,
    /// The clock goes back with the channels jumping: a new recording.
    Restart,
    /// The clock goes back by a counter's period, less one step: a wrap.
    Counter {
        /// The counter.
        counter: Counter,
        /// The step before the fall, s.
        step: f64,
    },
    /// The clock goes back, resumes its step and the channels run on
    /// across the fall: a wrap of a counter of period `period`.
    SameStep {
        /// What unwraps it: the time before the fall plus one step, less
        /// the time after it, s.
        period: f64,
        /// The step before and after the fall, s.
        step: f64,
    },
}

impl fmt::Display for ClockFall {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            ClockFall::Repeated => f.write_str(": a time repeated, a row logged twice?"),
            ClockFall::Restart => f.write_str(": the clock goes back, as where a logger starts a new recording in the same file; split the file at this line into two runs"),
            ClockFall::Counter { counter, step } => write!(
                f,
                ": the clock falls by {} s less its step of {} s, {}: it reads as a wrapped clock, not a new recording; unwrap it by adding {} s to the time of this row and of every row after it (and again at each later wrap)",
                counter.period(),
                Num(step),
                counter.words(),
                counter.period(),
            ),
            ClockFall::SameStep { period, step } => write!(
                f,
                ": the clock goes back and resumes its step of {} s with every channel running on across the fall: it reads as a wrapped clock (a counter of period {} s), not a new recording; unwrap it by adding {} s to the time of this row and of every row after it (if a new recording starts here instead, split the file at this line into two runs)",
                Num(step),
                Num(period),
                Num(period),
            ),
        }
    }
}
