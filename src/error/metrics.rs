//! The step-steer metrics' errors (GB/T 6323 / ISO 7401 windows on a
//! record): why a record's metrics could not be computed. Durations in s,
//! steer in rad.

use super::number::Num;
use super::reason::{angle, compared, compared_like};
use crate::format::fixed;
use thiserror::Error;

/// The sentence of [`MetricsError::NoStep`] in plain terms: where the
/// steer stays, or how little it moves, against the step it needs.
fn no_step(initial: f64, steady: f64, min: f64, pre_window: f64) -> String {
    let change = steady - initial;
    // Wheels already turned at the first sample and held: a record cut
    // after its step (or a steady turn), whose straight running is gone.
    let turned = match initial.abs() >= min && change.abs() < min {
        true => format!(
            "; the wheels are already turned by {} in the initial window: a record that starts \
             during or after its step holds no straight running before it, and the metrics \
             measure a step from the steer held straight for `pre_window` = {} s before it: \
             start the record at least {} s before the steer moves",
            angle(initial),
            Num(pre_window),
            Num(pre_window)
        ),
        false => String::new(),
    };
    if !change.is_finite() {
        return "no steer step: the steer is not a number in the initial or steady window".into();
    }
    if change.abs() < 1e-9 {
        return format!(
            "no steer step: the steer stays at {} from the initial window to the steady one; \
             a step steer needs a change of at least {}{turned}",
            angle(initial),
            angle(min)
        );
    }
    // The change by its size (the sentence says from where to where), and
    // every angle of the sentence with the digits that set it apart from
    // the least step: the steady steer of a run from 0 is the change.
    let like = |v: f64| compared_like(v, change.abs(), min);
    let (from, to) = (like(initial), like(steady));
    let (change, min) = compared(change.abs(), min);
    format!(
        "no steer step: the steer goes from {from} in the initial window to {to} in the steady \
         one, a change of {change}, less than the {min} a step steer needs{turned}",
    )
}

/// The sentence of [`MetricsError::SteerPulse`]: the pulse by its size,
/// start and duration, and why a held step is what the metrics read.
fn pulse(initial: f64, size: f64, start: f64, duration: f64, steady: f64, window: f64) -> String {
    format!(
        "no steer step: the steer is a pulse, not a step: a pulse of {} from {}, from {} s for \
         {} s (times at half its size), back to {} in the steady window; the step-steer metrics \
         (GB/T 6323 / ISO 7401 step input) read the response to a steer held after its step (its \
         steady gains, and the times to reach 90 % of them), which a pulse never holds: hold the \
         steer after the step to the record's end, at least the last `steady_window` = {} s; a \
         pulse input is read for its frequency response, which these metrics do not compute",
        angle(size),
        angle(initial),
        fixed(start, 2),
        nonzero(duration, 2),
        angle(steady),
        Num(window)
    )
}

/// A length or time `v` (s) that is not zero to `decimals` decimals, and
/// more where those round it to zero: "a record 0.004 s longer", not
/// "0.00 s longer" ([`crate::format::fixed_apart`]).
fn nonzero(v: f64, decimals: usize) -> String {
    crate::format::fixed_apart(&[v], decimals).swap_remove(0)
}

/// Why the metrics could not be computed.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MetricsError {
    /// Channels of different lengths or too few samples.
    #[error("a step-steer record needs at least 10 samples with equal-length channels; it has {}", lengths.iter().map(|(c, n)| format!("{c} {n}")).collect::<Vec<_>>().join(", "))]
    Shape {
        /// Each channel given and its sample count.
        lengths: Vec<(&'static str, usize)>,
    },
    /// The record is too short for the windows.
    #[error("the record ({span:.3} s) is not longer than the initial and steady windows together (`pre_window` = {} s + `steady_window` = {} s)", Num(*pre_window), Num(*steady_window))]
    TooShort {
        /// The record's length, s.
        span: f64,
        /// The initial-value window, s.
        pre_window: f64,
        /// The steady-value window, s.
        steady_window: f64,
    },
    /// No steer step in the record: the steer's means in the initial and
    /// steady windows, rad, and the least change that is a step.
    #[error("{}", no_step(*initial, *steady, *min, *pre_window))]
    NoStep {
        /// Mean steer in the initial window, rad.
        initial: f64,
        /// Mean steer in the steady window, rad.
        steady: f64,
        /// The smallest change that counts as a step, rad.
        min: f64,
        /// The initial window, s: how long the steer must be held before
        /// the step.
        pre_window: f64,
    },
    /// No held step: the steer leaves its initial value by a step's worth
    /// and comes back before the steady window (a pulse). Rad, s.
    #[error("{}", pulse(*initial, *size, *start, *duration, *steady, *steady_window))]
    SteerPulse {
        /// Mean steer in the initial window, rad.
        initial: f64,
        /// The largest departure from it, signed, rad.
        size: f64,
        /// Where the steer first passes half of that, s.
        start: f64,
        /// How long it stays beyond half of it, s.
        duration: f64,
        /// Mean steer in the steady window, rad.
        steady: f64,
        /// The steady window, s.
        steady_window: f64,
    },
    /// The steer does not cross half its step after the initial window.
    #[error("the steer never crosses half its step between the initial and steady windows")]
    NoHalfStep,
    /// A response does not change.
    #[error("the {0} does not change between the initial and steady windows")]
    NoResponse(&'static str),
    /// A response never reaches 90 % of its steady value.
    #[error("the {0} never reaches 90 % of its steady-state value")]
    NoCrossing(&'static str),
    /// The response grows away from every steady value as exp(λ·t): an
    /// unstable car, with no steady state to measure.
    #[error("the {channel} diverges after the step: over {from:.2}–{to:.2} s it grows as exp(t/τ), its growth rate fitted from the log λ = {} 1/s (time constant τ = 1/λ = {} s, doubling every {} s), not towards a steady value: an unstable car (one that oversteers, above its critical speed √(−l/K)) has no steady state, so no steady-state gain, response times, peak, E_r, E_ay or Er are given; a step below the critical speed measures the car's handling", crate::format::significant(*rate, 3), crate::format::significant(1.0 / rate, 3), crate::format::significant(std::f64::consts::LN_2 / rate, 3))]
    Diverges {
        /// The channel that diverges.
        channel: &'static str,
        /// Its growth rate λ, 1/s.
        rate: f64,
        /// The stretch it was fitted on, s.
        from: f64,
        /// Its end, s.
        to: f64,
    },
    /// The steer leaves its initial value inside the initial window: the
    /// record starts too close to the step to read the initial values.
    #[error("the steer moves by more than 5 % of its step at {moved:.2} s, inside the initial window ({from:.2}–{to:.2} s) whose means are the initial values: the record starts too close to the step; a step-steer record needs the steer held for `pre_window` = {} s before the step; one of at most {} s ends before it moves", Num(to - from), super::hundredths_down(moved - from + 1e-11))]
    StepInInitialWindow {
        /// Where the steer first is 5 % of its step off its initial value, s.
        moved: f64,
        /// The initial window's start, s.
        from: f64,
        /// Its end, s.
        to: f64,
    },
    /// The steer moves within [`MIN_STRAIGHT`] of the record's first
    /// sample: the record starts during (or just before) the step, with no
    /// straight running to measure it from.
    #[error("the record starts during its step: the steer moves by more than 5 % of its step at {moved:.3} s, {} s after the record's first sample at {from:.3} s, so the record holds no steady straight running before the step (at least {} s is needed to read one); the metrics measure the step from the steer held for `pre_window` = {} s before it: start the record at least {} s before the steer moves (at {} s or earlier)", crate::format::rounded(moved - from, 3), Num(MIN_STRAIGHT), Num(*pre_window), Num(*pre_window), crate::format::rounded(moved - pre_window, 3))]
    StartsInStep {
        /// Where the steer first is 5 % of its step off its initial value, s.
        moved: f64,
        /// The record's first sample, s.
        from: f64,
        /// The initial window asked for, s.
        pre_window: f64,
    },
    /// A record whose steer is no step steer at all (a log of driving):
    /// it reverses more often than a step and its return do.
    #[error("no step steer in this record: the steer spans {}, from {} to {}, and reverses {reversals} times by more than {} (a quarter of that span, or eight times the sensor's noise), and holds within {} for at most {} s (from {} s); a step steer is a steer held, changed once quickly and held again (a step and its return reverse once): cut one such stretch out of the log to measure it", angle(hi - lo), angle(*lo), angle(*hi), angle(*swing), angle(*band), fixed(*longest, 2), fixed(*longest_from, 2))]
    NoStepSteer {
        /// The least steer, rad.
        lo: f64,
        /// The largest steer, rad.
        hi: f64,
        /// How many times the steer turns back by more than `swing`.
        reversals: usize,
        /// The least change a reversal counts, rad.
        swing: f64,
        /// The longest time the steer stays within `band`, s.
        longest: f64,
        /// Where that stretch starts, s.
        longest_from: f64,
        /// The width of a held steer, rad.
        band: f64,
    },
    /// A record too short for its steady window: the window, the record's
    /// last `--steady-window` seconds, starts before the steer has reached
    /// its step, so its means mix the step (and the time before it) in.
    #[error("the record is too short for its steady window: the step lies inside the steady window ({from:.2}–{to:.2} s, `--steady-window` = {} s) whose means are the steady values; the steer settles within 5 % of its held value only at {settles:.2} s, so {}; the record holds the step for {} s, and a {} s steady window needs it held to {} s at least (a record {} s longer)", Num(to - from), advice.words(to - settles, *to), nonzero(to - settles, 2), Num(to - from), fixed(settles + (to - from), 2), nonzero(settles - from, 2))]
    ShortForSteadyWindow {
        /// Which shorter window, if any, reads a settled response.
        advice: SteadyAdvice,
        /// From when on the steer stays within 5 % of its step of its held
        /// value, s.
        settles: f64,
        /// The steady window's start, s.
        from: f64,
        /// Its end (the record's), s.
        to: f64,
    },
    /// The steer still moves inside the steady window: the steady values
    /// would mix the step in (a window that reaches back over the step).
    #[error("the steer moves by more than 5 % of its step inside the steady window ({from:.2}–{to:.2} s, `--steady-window` = {} s) whose means are the steady values: {}; the steady values would mix the step in", Num(to - from), settles.map_or("it does not settle within 5 % of its held value before the record ends".to_string(), |t| format!("it settles within 5 % of its held value only at {t:.2} s, so a `--steady-window` of at most {} s starts after it", super::hundredths_down(to - t))))]
    StepInSteadyWindow {
        /// From when on the steer stays within 5 % of its step of its held
        /// value, s (none: not before the record's end).
        settles: Option<f64>,
        /// The steady window's start, s.
        from: f64,
        /// Its end, s.
        to: f64,
    },
    /// The steer leaves its step after reaching it: a sweep or a sine.
    #[error("the steer does not hold its step: after reaching 90 % of it at {reached:.2} s it is at {} % of it at {time:.2} s, where a step steer stays between {} % and {} %: a sweep or a sine is not measured as a step steer", crate::format::fixed_apart(&[100.0 * share, 100.0 * HELD_STEP.0, 100.0 * HELD_STEP.1], 0)[0], Num(100.0 * HELD_STEP.0), Num(100.0 * HELD_STEP.1))]
    SteerNotHeld {
        /// Where the steer first reaches 90 % of its step, s.
        reached: f64,
        /// The first time after it outside [`HELD_STEP`], s.
        time: f64,
        /// The steer there, as a share of the step.
        share: f64,
    },
    /// A steer that takes longer than a step may to rise: a ramp.
    #[error("the steer rises from 10 % to 90 % of its change in {} s, from {from:.2} s: a ramp steer, not a step (GB/T 6323 steps within 0.2 s, ISO 7401 within 0.15 s; a step taking more than {} s is refused), and the step-steer metrics measure nothing of it", crate::format::fixed_apart(&[*rise, *limit], 2)[0], Num(*limit))]
    SteerRamp {
        /// The 10–90 % rise, s.
        rise: f64,
        /// Where it reaches 10 %, s.
        from: f64,
        /// The longest rise taken as a step, s.
        limit: f64,
    },
    /// A steer held neither before its "step" nor after it.
    #[error("no step steer in this record: the steer moves inside the initial window (at {moved:.2} s) and does not hold its step after it (at {time:.2} s); a step steer is a steer held straight, stepped and held: cut one out of the log to measure it")]
    NeverHeld {
        /// Where the steer first moves inside the initial window, s.
        moved: f64,
        /// Where it first leaves the held step, s.
        time: f64,
    },
}

/// The least straight running before a step that the metrics read, s: in
/// less, the initial means stand on a handful of samples (10 at 100 Hz),
/// and a record that starts within it starts in the step.
pub const MIN_STRAIGHT: f64 = 0.1;

/// The band a step steer's normalised steer stays in once it has reached
/// 90 % of its step (a driver's hand wobbles by far less than half a step).
pub const HELD_STEP: (f64, f64) = (0.5, 1.5);

/// What a record too short for its steady window is advised
/// ([`MetricsError::ShortForSteadyWindow`]): a window that starts after the
/// steer settles is not enough, for the response may still be moving in
/// it (a linear car's record ending 0.6 s after its step, advised "at most
/// 0.58 s", read a yaw-rate gain 7 % low, not settled).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SteadyAdvice {
    /// Not tried: only the steer's bound is known.
    SteerOnly,
    /// The longest window tried, at most the steer's bound, whose response
    /// settles (every channel judged within 2 % of its step, and not still
    /// approaching it), s.
    Settled(f64),
    /// No window tried, from `shortest` s (the yaw rate's response time,
    /// or two sample intervals) to the steer's bound, reads a settled
    /// response: the record ends before its steady state.
    NoneSettles {
        /// The shortest window tried, s.
        shortest: f64,
    },
}

impl SteadyAdvice {
    /// The advice's words, the steer held for `held` s before the record
    /// ends at `end` s. The windows tried are lengths, each ending at the
    /// record's end: said with the starts they give (said as "none from
    /// 0.23 s to 0.87 s", they read as starts before the step).
    pub(crate) fn words(&self, held: f64, end: f64) -> String {
        let most = super::hundredths_down(held);
        match *self {
            Self::SteerOnly => {
                format!("a `--steady-window` of at most {most} s starts after it")
            }
            Self::Settled(w) => format!(
                "a `--steady-window` of at most {most} s starts after it, and one of {} s reads a settled response",
                super::hundredths_down(w)
            ),
            Self::NoneSettles { shortest } => format!(
                "a steady window must start after it, and no window {} s to {most} s long ending at the record's end (starting from {} s to {} s) reads a settled response (every channel within 2 % of its step and no longer approaching it): the record ends before the car reaches its steady state, and a gain read from it is no steady-state gain; record the step held longer",
                nonzero(shortest, 2),
                crate::format::fixed(end - (held * 100.0).floor().max(0.0) / 100.0, 2),
                crate::format::fixed(end - shortest, 2)
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A steer at 49.6 % of its step read "at 50 % of it, where a step
    /// steer stays between 50 % and 150 %"; a rise just past the limit
    /// read as the limit; a record a few milliseconds short "0.00 s
    /// longer".
    #[test]
    fn a_refusal_never_prints_its_value_as_the_bound_it_broke_or_as_zero() {
        let e = MetricsError::SteerNotHeld {
            reached: 1.1,
            time: 2.0,
            share: 0.496,
        };
        assert!(
            e.to_string().contains(
                "it is at 49.6 % of it at 2.00 s, where a step steer stays between 50 % and 150 %"
            ),
            "{e}"
        );
        let e = MetricsError::SteerRamp {
            rise: 0.5004,
            from: 1.0,
            limit: 0.5,
        };
        assert!(e.to_string().contains("in 0.5004 s, from 1.00 s"), "{e}");
        let e = MetricsError::ShortForSteadyWindow {
            advice: SteadyAdvice::SteerOnly,
            settles: 3.004,
            from: 3.0,
            to: 4.0,
        };
        assert!(e.to_string().ends_with("(a record 0.004 s longer)"), "{e}");
    }
}
