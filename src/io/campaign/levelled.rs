//! A campaign's logged body roll put to use: every replayed piece whose run
//! logs `roll` has its `ay` levelled by it before any fit or estimate
//! ([`crate::measured::calibration::roll`]: a body-fixed accelerometer
//! reads `g·sin φ` of gravity in roll, known from the log, not fitted), the
//! roll sensor's own offset measured at the raw runs' standstills and
//! removed first; and the note that says so, with the numbers. Units: rad,
//! m/s².

use crate::error::Unseen;
use crate::format::{fixed, readable};
use crate::measured::calibration::roll::{gravity_term, levelled, roll_offset, RollOffset};
use crate::measured::clean::quantile;
use crate::measured::MeasuredRun;

/// The pieces `runs` (cut from the raw runs `raw`) with `ay` levelled by
/// their logged roll, and the note on it (None where no run logs roll;
/// `declared`: the roll was declared in degrees under `[runs]`).
pub(super) fn level_by_roll(
    raw: &[MeasuredRun],
    runs: Vec<MeasuredRun>,
    declared: bool,
) -> (Vec<MeasuredRun>, Option<String>) {
    let with = raw.iter().filter(|r| r.roll.is_some()).count();
    if with == 0 {
        return (runs, None);
    }
    let offset = roll_offset(raw);
    let phi0 = offset.map_or(0.0, |o| o.mean);
    let mut terms: Vec<f64> = runs
        .iter()
        .filter(|r| r.ay.is_some())
        .filter_map(|r| r.roll.as_ref())
        .flat_map(|roll| gravity_term(roll, phi0))
        .map(f64::abs)
        .collect();
    terms.sort_by(f64::total_cmp);
    // Candidate or not by the pipeline's one rule, on the same pieces.
    let with_ay = runs.iter().filter(|r| r.ay.is_some());
    let unseen = Unseen::accelerometer_roll(
        with_ay.clone().count(),
        with_ay.filter(|r| r.roll.is_some()).count(),
    );
    let runs = runs.into_iter().map(|r| levelled(r, phi0)).collect();
    let largest = quantile(&terms, 0.995);
    let note = note(with, raw.len(), declared, offset, (largest, unseen));
    (runs, Some(note))
}

/// The words: what was levelled, by what, how much, and what the roll is
/// not used for.
fn note(
    with: usize,
    of: usize,
    declared: bool,
    offset: Option<RollOffset>,
    (largest, unseen): (Option<f64>, Option<Unseen>),
) -> String {
    let unit = match declared {
        true => ", converted from the degrees `degrees` under [runs] declares",
        false => "",
    };
    let runs = if of == 1 { "run" } else { "runs" };
    let offset = match offset {
        Some(o) => format!(
            "the logged roll less its own offset, {} ± {} rad, its mean at {} ({} s) where a body does not roll",
            readable(o.mean, 3),
            readable(o.std_error, 2),
            crate::format::plural(o.spans, "standstill", "standstills"),
            fixed(o.seconds, 0)
        ),
        None => "the roll as logged (no standstill to measure its own offset)".to_string(),
    };
    let size = largest.map_or(String::new(), |g| {
        format!(
            "; g·sin φ reaches {} m/s² (99.5th percentile of the replayed samples)",
            fixed(g, 3)
        )
    });
    let rest = match (unseen, of - with) {
        (Some(_), _) => "accelerometer_roll is no candidate".to_string(),
        (None, 0) => "accelerometer_roll is a candidate for the pieces with ay and no roll".into(),
        (None, n) => format!(
            "{n} {} without roll keep their ay as logged, for accelerometer_roll to fit",
            if n == 1 { "run" } else { "runs" }
        ),
    };
    // A log without ay has nothing for the roll to level (round 41: the
    // Putnam log's note said ay was levelled).
    if unseen == Some(Unseen::NoAyChannel) {
        return format!(
            "roll: logged in {with} of {of} {runs}{unit}, but no run logs ay, the one channel it levels: {rest} (it moves ay alone); the roll itself is not scored: the gap is the yaw rate's and beta's"
        );
    }
    format!(
        "roll: logged in {with} of {of} {runs}{unit}: ay levelled by it before every fit and the bank's estimate, (ay − g·sin φ)/cos φ with φ {offset} (a body-fixed accelerometer rolled by φ reads g·sin φ of gravity: known from the log, not fitted){size}; {rest}; the roll itself is not scored: the gap is the yaw rate's, ay's and beta's"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_note_says_what_levels_ay_and_what_the_roll_is_not() {
        let o = RollOffset {
            mean: 0.0021,
            std_error: 0.00004,
            spans: 3,
            seconds: 25.2,
        };
        let n = note(
            2,
            2,
            false,
            Some(o),
            (Some(0.5861), Some(Unseen::RollLogged)),
        );
        assert!(n.starts_with("roll: logged in 2 of 2 runs: ay levelled by it before every fit and the bank's estimate, (ay − g·sin φ)/cos φ with φ the logged roll less its own offset, 0.00210 ± 4e-5 rad, its mean at 3 standstills (25 s)"), "{n}");
        assert!(n.contains("g·sin φ reaches 0.586 m/s²"), "{n}");
        assert!(n.contains("; accelerometer_roll is no candidate;"), "{n}");
        let n = note(1, 3, true, None, (None, None));
        assert!(
            n.contains("logged in 1 of 3 runs, converted from the degrees"),
            "{n}"
        );
        assert!(n.contains("φ the roll as logged (no standstill"), "{n}");
        assert!(
            n.contains("2 runs without roll keep their ay as logged"),
            "{n}"
        );
        assert!(!n.contains("reaches"), "{n}");
        // No ay to level: not said levelled, and no candidate.
        let n = note(1, 1, true, None, (None, Some(Unseen::NoAyChannel)));
        assert!(
            n.contains(
                "but no run logs ay, the one channel it levels: accelerometer_roll is no candidate"
            ),
            "{n}"
        );
        assert!(!n.contains("ay levelled by it"), "{n}");
    }
}
