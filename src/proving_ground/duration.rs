//! The total duration an analogue programme's runs may be lengthened to
//! (`synth --duration`, [`analogue_duration`]): a whole number of seconds
//! (each run is lengthened in proportion and rounded to whole seconds, the
//! last taking what is left, so a total of 370.5 s made a last run of
//! 115.5 s), at least the programme's own total and at most
//! [`MAX_DURATION`]. Checked by the library, so every caller (the command
//! line, Python) is refused alike: a NaN from Python panicked in the track
//! ("ends after 107 s, before the run's NaN s"), an infinity or 1e9 s
//! aborted the process on a failed allocation of gigabytes.

use super::{analogue_duration, Programme};
use crate::error::{Error, OptionsError};

/// The longest total duration of an analogue's runs, s: an hour of
/// logging, about ten times either analogue's own (370 s, 300 s). Each
/// run is simulated at the truth's 2 ms step and held in memory: 3600 s
/// of `sedan-winding` took 5.3 s CPU, 173 MB at its peak and 45 MB of
/// files (session 101, `/usr/bin/time -v handling synth --programme
/// sedan-winding --duration 3600`), so memory grows about 48 kB a second.
pub const MAX_DURATION: f64 = 3600.0;

/// Refuses a total duration of `given` s that `programme` cannot drive: a
/// programme whose runs are fixed, a duration shorter than its own runs,
/// beyond [`MAX_DURATION`], no number, or no whole number of seconds.
pub fn check_duration(programme: Programme, given: f64) -> Result<(), Error> {
    let Some(own) = analogue_duration(programme) else {
        let takes = Programme::ALL
            .iter()
            .filter_map(|&p| analogue_duration(p).map(|d| (p.name(), d)))
            .collect();
        return Err(OptionsError::DurationNotTaken {
            given,
            programme: programme.name(),
            takes,
        }
        .into());
    };
    if !given.is_finite() || given > MAX_DURATION {
        return Err(OptionsError::DurationTooLong {
            given,
            programme: programme.name(),
            own,
            most: MAX_DURATION,
        }
        .into());
    }
    if given < own {
        return Err(OptionsError::DurationTooShort {
            given,
            programme: programme.name(),
            own,
        }
        .into());
    }
    if given.fract() != 0.0 {
        return Err(OptionsError::DurationNotWhole { given }.into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refusal(p: Programme, d: f64) -> String {
        check_duration(p, d).unwrap_err().to_string()
    }

    #[test]
    fn no_number_and_beyond_an_hour_are_refused_with_the_limit() {
        let p = Programme::SedanWinding;
        for d in [f64::NAN, f64::INFINITY, 1e9, 3600.5] {
            let e = refusal(p, d);
            assert!(e.contains("at most 3600 s together"), "{d}: {e}");
            assert!(e.contains("from 370 to 3600"), "{d}: {e}");
        }
        assert!(refusal(p, f64::NAN).starts_with("--duration NaN: no number of seconds"));
        assert!(check_duration(p, 3600.0).is_ok());
        assert!(check_duration(Programme::RacingRearSteer, 300.0).is_ok());
    }

    #[test]
    fn a_duration_of_a_fraction_of_a_second_is_refused_with_the_whole_ones_beside_it() {
        let e = refusal(Programme::SedanWinding, 370.5);
        assert!(
            e.contains("--duration 370.5: the runs are lengthened to whole seconds"),
            "{e}"
        );
        assert!(e.ends_with("give 370 or 371"), "{e}");
    }
}
