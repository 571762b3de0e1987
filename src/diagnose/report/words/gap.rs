//! Where the gap lies, in words: a channel's held-out RMS against its
//! noise floor, the parts of the data it is wrong and right in, and a
//! steady offset the RMS does not single out. RMS values and offsets in the
//! channel's unit (rad/s, m/s², rad).

use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::outcome::{
    above_noise, CombinedGap, GapFinding, OffInRight, SIGNIFICANT_NOISE_FLOORS,
};
use crate::diagnose::report::parts::Window;
use crate::diagnose::report::values::SteadyOffset;
use crate::diagnose::report::Part;

/// Parts listed, or "nowhere".
fn listed(v: Vec<String>) -> String {
    if v.is_empty() {
        "nowhere".to_string()
    } else {
        v.join(", ")
    }
}

/// A channel's finding ([`GapFinding::Channel`]) as the terminal and the
/// page say it; any other finding gives an empty text.
pub(super) fn channel(f: &GapFinding) -> String {
    let GapFinding::Channel {
        channel,
        rms,
        noise_floor,
        significant_runs,
        significant_in,
        within_in,
        runs,
        wrong,
        right,
        off_in_right,
        offset,
        combined,
    } = f
    else {
        return String::new();
    };
    let before = right_before_input(right, off_in_right);
    let said = offset.map_or(String::new(), |o| steady_offset(&o, *channel, before));
    let which = if *significant_runs == significant_in.len() {
        runs_named(*channel, *noise_floor, (significant_in, within_in), *runs)
    } else {
        String::new()
    };
    let head = format!(
                "{}: RMS {rms:.4} {} (noise floor {noise_floor:.4}); significant in {significant_runs} of {runs} runs{which}",
                channel.name(),
                channel.unit(),
            );
    let parts = |v: &[(Part, f64)]| {
        listed(
            v.iter()
                .map(|(p, rms)| format!("{p} ({rms:.3} {})", channel.unit()))
                .collect(),
        )
    };
    let place = if above_noise(*rms, *noise_floor) || *significant_runs > 0 {
        let wrong = if wrong.is_empty() && *significant_runs > 0 {
            "no part over all runs".to_string()
        } else {
            parts(wrong)
        };
        let right = right
            .iter()
            .map(|p| right_but(*p, off_in_right, *noise_floor));
        format!(
            "{head}; wrong in: {wrong}; right in: {}",
            listed(right.collect())
        )
    } else if let Some(c) = combined {
        within_combined(
            &head,
            *rms / *noise_floor,
            c,
            (!wrong.is_empty()).then(|| parts(wrong)),
        )
    } else if wrong.is_empty() {
        // A gap within noise has no place: listing the parts it is
        // "right in" would read as a finding.
        format!("{head}: within noise in every part, so no place where the base model is wrong")
    } else {
        // Named, but not as where the model is wrong: a part of a channel
        // within noise in every run is too little of the runs to place a
        // gap, and "no place where it is wrong" beside it would contradict
        // the part's own number.
        let (one, verb) = if wrong.len() == 1 {
            ("one part", "reads")
        } else {
            ("some parts", "read")
        };
        format!(
            "{head}: within noise over the runs and in every run; {one}, {}, {verb} above {SIGNIFICANT_NOISE_FLOORS} noise floors: too little of the runs to say the base model is wrong there",
            parts(wrong)
        )
    };
    place + &said
}

/// Whether the channel is right before the input for every run, not
/// pooled only (`right`, and no run of `off` off there): a run off there
/// has a zero offset of its own.
fn right_before_input(right: &[Part], off: &[OffInRight]) -> bool {
    let before = Part::Window(Window::BeforeInput);
    right.contains(&before) && !off.iter().any(|o| o.part == before)
}

/// A part the pooled RMS calls right, with the runs above three noise
/// floors in it (`off`, largest first) said beside it: "before the input
/// (but a.csv is 6.5 noise floors off there)". At most [`NAMED_RUNS`]
/// are named, the rest counted.
fn right_but(part: Part, off: &[OffInRight], noise_floor: f64) -> String {
    let runs: Vec<&OffInRight> = off.iter().filter(|o| o.part == part).collect();
    if runs.is_empty() {
        return part.label();
    }
    let floors = |o: &OffInRight| crate::format::fixed(o.rms / noise_floor, 1);
    let mut each: Vec<String> = runs
        .iter()
        .take(NAMED_RUNS)
        .enumerate()
        .map(|(i, o)| match i {
            0 => format!("{} is {}", o.run, floors(o)),
            _ => format!("{} {}", o.run, floors(o)),
        })
        .collect();
    if runs.len() > NAMED_RUNS {
        let rest = crate::format::plural(runs.len() - NAMED_RUNS, "other run", "other runs");
        each.push(format!("{rest} more than {SIGNIFICANT_NOISE_FLOORS}"));
    }
    let last = each.pop().unwrap_or_default();
    let named = match each.is_empty() {
        true => last,
        false => format!("{} and {last}", each.join(", ")),
    };
    format!("{} (but {named} noise floors off there)", part.label())
}

/// A channel within noise alone, over the runs and in every run, under a
/// significant combined gap `c` (`head`: the channel's RMS and runs;
/// `floors`: its RMS in noise floors; `wrong`: its parts above the floors,
/// listed, if any). The per-channel table calls it "not significant
/// alone", so it is no gap of its own: where other channels are
/// significant alone the combined gap lies in them; where none is, the
/// channels together carry it, spread thinly, and the numbers say so.
fn within_combined(head: &str, floors: f64, c: &CombinedGap, wrong: Option<String>) -> String {
    let floors = crate::format::fixed(floors, 1);
    let alone = format!("{head}: within noise alone ({floors} noise floors over the runs, below the {SIGNIFICANT_NOISE_FLOORS} a channel, run or part needs alone), so no gap of its own");
    let only = wrong.map_or(String::new(), |w| {
        format!("; above {SIGNIFICANT_NOISE_FLOORS} noise floors only in {w}, too little of the runs to say the base model is wrong there")
    });
    if c.significant_alone.is_empty() {
        format!(
            "{alone}{only}; no channel is significant alone over all runs, but the channels together are (held-out error {:.3} against a noise level of {:.3}): a gap spread thinly over the channels and runs, not in one place (the frequency bands and offsets below say more)",
            c.heldout_error, c.noise_level
        )
    } else {
        let names: Vec<&str> = c.significant_alone.iter().map(|ch| ch.name()).collect();
        format!(
            "{alone}{only}; the significant gap lies in {}",
            names.join(" and ")
        )
    }
}

/// The clause of a channel's steady offset `o`, after its place. Where
/// the channel is right before the input (`before`: its RMS there within
/// three floors) and the offset beyond three floors, the offset comes with
/// the input and is no sensor's: a sensor's zero offset would have made
/// that window wrong too ("right in: before the input" beside "a sensor
/// offset" read as both).
fn steady_offset(o: &SteadyOffset, channel: Channel, before: bool) -> String {
    let cause = if before && o.floors > SIGNIFICANT_NOISE_FLOORS {
        "a bias of the model's response that the RMS does not single out, after the input only (before it the channel is right, where a sensor's zero offset would show too), not a sensor offset"
    } else {
        "a sensor offset or a bias of the model that the RMS does not single out"
    };
    format!(
        "; a steady offset: mean residual {} {} over the runs, of that sign in {} of {} runs ({} noise floors, {:.0} % of the mean square), {cause}",
        crate::format::signed(o.mean, 4),
        channel.unit(),
        o.same_sign,
        o.runs,
        crate::format::fixed(o.floors, 1),
        100.0 * o.share
    )
}

/// A run's name and its held-out RMS of a channel (its unit).
type RunRms = (String, f64);

/// Where a channel's gap is significant in some runs and not all, at most
/// this many runs are named in a line; beyond, the largest are and the
/// rest are counted.
pub(super) const NAMED_RUNS: usize = 3;

/// The runs a channel's gap is significant in (`significant`, with their
/// held-out RMS) where some of the `runs` are and not all, each with its
/// RMS in noise floors: a gap in one run that no part over all runs
/// isolates ("wrong in: nowhere") is otherwise lost, and "significant in 4
/// of 8 runs" leaves the user to find which. Up to [`NAMED_RUNS`] + 1 are
/// named in the campaign's order; where the runs within noise (`within`)
/// are fewer and at most [`NAMED_RUNS`], and every one of the `runs`
/// measures the channel, those instead ("all but …"); else the
/// [`NAMED_RUNS`] largest and a count of the rest. Empty where none or
/// every run is significant. The `runs` are those that measure the
/// channel (a campaign run without a beta column is not one of beta's:
/// "significant in 0 of 8 runs" was said of beta measured in 7, round 51).
fn runs_named(
    channel: Channel,
    noise_floor: f64,
    (significant, within): (&[RunRms], &[RunRms]),
    runs: usize,
) -> String {
    let each = |v: &[RunRms]| -> String {
        let named: Vec<String> = v
            .iter()
            .map(|(run, rms)| {
                let floors = crate::format::fixed(rms / noise_floor, 1);
                format!("{run}: {rms:.4} {}, {floors} noise floors", channel.unit())
            })
            .collect();
        named.join("; ")
    };
    let k = significant.len();
    if k == 0 || k == runs {
        return String::new();
    }
    let measured_by_all = k + within.len() == runs;
    if measured_by_all && within.len() < k && within.len() <= NAMED_RUNS {
        return format!(" (all but {}; {OVER_ALL})", each(within));
    }
    if k <= NAMED_RUNS + 1 {
        return format!(" ({}; {OVER_ALL})", each(significant));
    }
    let mut largest = significant.to_vec();
    largest.sort_by(|a, b| b.1.total_cmp(&a.1));
    largest.truncate(NAMED_RUNS);
    format!(
        " (largest: {}; and {} more; {OVER_ALL})",
        each(&largest),
        k - NAMED_RUNS
    )
}

/// Which samples the runs' figures are read over: all of each run's, not
/// the held-out ones the verdict's before → after block judges a run left
/// on ([`super::left_in::runs_left`]), so that one run's two figures (3.2
/// here, 3.1 → 3.1 there) are not read as one contradicting the other.
const OVER_ALL: &str = "RMS over all of each run's samples";

/// The terminal's lines for the frequency bands whose yaw-rate response is
/// off ([`GapFinding::Band`], one per run and band in the report): a band
/// off in one run is said of that run; one off in several runs once, with
/// the runs counted of `runs` and the range of its gain and phase errors
/// (each run's stays in `diagnosis.json` and on the page).
pub fn band_lines(findings: &[GapFinding], runs: usize) -> Vec<String> {
    // Per band (Hz): each run's name, gain error (dB), phase error (°).
    type Runs<'a> = Vec<(&'a str, f64, f64)>;
    let mut bands: Vec<((f64, f64), Runs)> = Vec::new();
    for f in findings {
        if let GapFinding::Band {
            run,
            f_low,
            f_high,
            gain_error_db,
            phase_error_deg,
        } = f
        {
            let entry = (run.as_str(), *gain_error_db, *phase_error_deg);
            match bands.iter_mut().find(|(b, _)| *b == (*f_low, *f_high)) {
                Some((_, v)) => v.push(entry),
                None => bands.push(((*f_low, *f_high), vec![entry])),
            }
        }
    }
    bands.sort_by(|a, b| a.0 .0.total_cmp(&b.0 .0));
    let range = |v: &[(&str, f64, f64)], pick: fn(&(&str, f64, f64)) -> f64, d: usize| {
        let lo = v.iter().map(pick).fold(f64::INFINITY, f64::min);
        let hi = v.iter().map(pick).fold(f64::NEG_INFINITY, f64::max);
        format!(
            "{} to {}",
            crate::format::signed(lo, d),
            crate::format::signed(hi, d)
        )
    };
    bands
        .into_iter()
        .map(|((lo, hi), v)| match v.as_slice() {
            [(run, gain, phase)] => format!(
                "{run}: yaw-rate response {lo:.2}–{hi:.2} Hz off by {} dB, {}° (simulated against measured: + the model leads){}",
                crate::format::signed(*gain, 1),
                crate::format::signed(*phase, 0),
                unit_hint(*gain)
            ),
            _ => format!(
                "yaw-rate response {lo:.2}–{hi:.2} Hz off in {} of {runs} runs: {} dB, {}° (simulated against measured: + the model leads; each run's in diagnosis.json){}",
                v.len(),
                range(&v, |e| e.1, 1),
                range(&v, |e| e.2, 0),
                unit_hint(v.iter().map(|e| e.1).fold(0.0, |a: f64, g| if g.abs() > a.abs() { g } else { a }))
            ),
        })
        .collect()
}

/// "; <hint>" where a band's gain error is a degree-to-radian ratio
/// ([`crate::diagnose::unit_ratio`]), else nothing.
pub(super) fn unit_hint(gain_error_db: f64) -> String {
    crate::diagnose::unit_ratio::degree_ratio_hint(gain_error_db)
        .map_or(String::new(), |h| format!("; {h}"))
}

/// The steady offsets a channel's dominance was judged without
/// ([`GapFinding::Dominant`]'s `less_offsets`) and its share with them
/// counted, said together: " with ay's steady offset aside (94 % with
/// it)"; nothing without an offset.
pub(super) fn offsets_aside(channels: &[Channel], with_offsets_percent: f64) -> String {
    if channels.is_empty() {
        return String::new();
    }
    let (named, pronoun) = crate::diagnose::report::shares::offsets_named(channels);
    format!(" with {named} aside ({with_offsets_percent:.0} % with {pronoun})")
}
