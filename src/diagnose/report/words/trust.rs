//! How far each measured channel is trusted, in words: the number, where
//! it comes from (stated, scatter, a sensor type's floor, an estimated
//! output's) and, where the reading that chose between a sensor and an
//! estimated output lies near its line, that it does (the rule:
//! [`crate::diagnose::model::scale`]). Units: each channel's own.

use super::{rms, std_error, value};
use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::scale::{near_the_line, smooth_line, StatedExcess};
use crate::diagnose::report::outcome::AssumedFloor;
use crate::diagnose::report::{ChannelNoise, FarFromOff, NoSignificantGap, ScaleSource, Shrinkage};

/// Who reads the channels' trust, for what a user can do where a
/// channel's reading lies near the line between a sensor and an
/// estimated output.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reader {
    /// A diagnosis: its campaign file states an uncertainty under
    /// `[channels]`.
    Diagnosis,
    /// A replay (`simulate` with a measured run): no file states one, so
    /// the words give the floor the other reading would take.
    Replay,
}

/// How far every measured channel is trusted, in one line.
pub fn channels_trusted(noise: &[ChannelNoise]) -> String {
    channels_trusted_for(noise, Reader::Diagnosis)
}

/// [`channels_trusted`], its advice for `reader`.
pub fn channels_trusted_for(noise: &[ChannelNoise], reader: Reader) -> String {
    let each: Vec<String> = noise.iter().map(|n| trust_for(n, reader)).collect();
    format!("channels trusted to: {}", each.join("; "))
}

/// How far a channel is trusted, and why, each number with its unit and
/// in digits that show it ([`rms`]: a stated 1e-6 rad is not "0.0000").
pub fn channel_trust(n: &ChannelNoise) -> String {
    trust_for(n, Reader::Diagnosis)
}

/// [`channel_trust`], its advice for `reader`.
fn trust_for(n: &ChannelNoise, reader: Reader) -> String {
    let u = n.unit;
    let why = match n.source {
        ScaleSource::Stated => match &n.stated_excess {
            Some(e) => format!("stated; {}", stated_excess(e)),
            None => "stated".to_string(),
        },
        ScaleSource::Scatter => "its scatter".to_string(),
        ScaleSource::SensorFloor => format!(
            "its sensor type's floor; scatter {} {u}{}",
            rms(n.scatter),
            quiet_sensor(n)
        ),
        ScaleSource::Estimated => format!(
            "an estimated output's: its scatter {} {u} is below any sensor's",
            rms(n.scatter)
        ),
    };
    let near = near_the_line(n.channel, n.source, n.scatter, n.other_side)
        .map(|share| near_line(n, share, reader))
        .unwrap_or_default();
    format!(
        "{} {} {u} ({why}{near}){}",
        n.channel.name(),
        rms(n.noise_floor),
        judged_apart(n).map_or_else(String::new, |j| format!(", {j}"))
    )
}

/// Where a channel's stated uncertainty lies below its own scatter, what
/// judges its gap and what weighs it in the fits, which then differ: the
/// gap is judged against the stated floor (its noise floors, every
/// significance), the fits weigh the channel by their scale, at least
/// [`crate::diagnose::model::scale::SIGNAL_SHARE`] of its RMS signal. None
/// for a channel trusted to its stated value at or above its scatter, or
/// to what the tool measured. Said where the floor is shown (the trust
/// line, the before → after rows), so that the note's "weighted by …
/// instead" is not read as the floor.
pub fn judged_apart(n: &ChannelNoise) -> Option<String> {
    let apart = |a: f64, b: f64| a > b * (1.0 + 1e-9);
    if n.source != ScaleSource::Stated || !apart(n.scatter, n.noise_floor) {
        return None;
    }
    let u = n.unit;
    let weighed = if apart(n.scale, n.noise_floor) {
        format!("the fits weigh it by {} {u}", rms(n.scale))
    } else {
        "the fits weigh it by that too".to_string()
    };
    Some(format!(
        "below its scatter {} {u}: its gap is judged against the stated {} {u}, {weighed}",
        rms(n.scatter),
        rms(n.noise_floor)
    ))
}

/// Why a sensor channel quieter than a sideslip would be read as an
/// estimated output is trusted to its sensor type's floor
/// ([`crate::diagnose::model::scale::smooth_line`]); empty otherwise.
fn quiet_sensor(n: &ChannelNoise) -> &'static str {
    use crate::diagnose::model::channels::Channel;
    use crate::diagnose::model::scale::{SENSOR_FLOOR, SMOOTH_SHARE};
    if n.scatter >= SMOOTH_SHARE * SENSOR_FLOOR[n.channel.index()] {
        return "";
    }
    match n.channel {
        Channel::YawRate => ", a quiet gyro's (a yaw rate is measured, not an estimator's output)",
        Channel::Ay => ", a quiet accelerometer's (ay is measured, not an estimator's output)",
        Channel::Beta => "",
    }
}

/// What a user should know of a channel whose trust hangs on a reading
/// near the line between a sensor and an estimated output: which way it
/// went, how near, and how to settle it.
fn near_line(n: &ChannelNoise, share: f64, reader: Reader) -> String {
    use crate::diagnose::model::scale::{ESTIMATED, SENSOR_FLOOR};
    let i = n.channel.index();
    // The other reading's floor: a sensor's type floor (its scatter, below
    // the line, is under it), or an estimated output's uncertainty.
    let (this, other, other_floor) = if n.source == ScaleSource::Estimated {
        (
            "an estimated output",
            "a sensor",
            SENSOR_FLOOR[i].max(n.scatter),
        )
    } else {
        ("a sensor", "an estimated output", ESTIMATED[i])
    };
    let settle = match reader {
        Reader::Diagnosis => "where you know which it is, state its uncertainty under [channels]".to_string(),
        Reader::Replay => format!(
            "where you know it is {other}, read its gap against {other}'s floor, {} {u}, in place of {} {u} (`diagnose` takes it stated under a campaign's [channels])",
            rms(other_floor),
            rms(n.noise_floor),
            u = n.unit,
        ),
    };
    let runs = if n.other_side > 0 {
        format!(
            "; {} of its {} runs read alone fall on the side of {other}",
            n.other_side, n.runs
        )
    } else {
        String::new()
    };
    format!(
        "; near the line between a sensor and an estimated output: its scatter is {} of its sensor type's floor, the line at {}{runs}; read as {this}, a shorter or calmer stretch may read it as {other}: {settle}",
        crate::format::rounded(share, 2),
        smooth_line(n.channel),
    )
}

/// A stated uncertainty far above what its channel shows
/// ([`StatedExcess`]): how far, and what follows.
pub fn stated_excess(e: &StatedExcess) -> String {
    let u = e.channel.unit();
    let own = if e.estimated {
        format!(
            "an estimated output's uncertainty, {} {u} (its scatter is below any sensor's)",
            rms(e.own)
        )
    } else {
        format!("the channel's own scatter, {} {u}", rms(e.own))
    };
    format!(
        "{:.0}× {own}: a gap below it is called insignificant only because of the statement",
        e.times
    )
}

/// The note of an uncertainty stated far above what its channel shows.
pub fn excess_note(e: &StatedExcess) -> String {
    format!(
        "[channels] {} = {} {}: the stated uncertainty is {}",
        e.channel.name(),
        crate::error::Num(e.stated),
        e.channel.unit(),
        stated_excess(e)
    )
}

/// An assumed floor the verdict rests on ([`AssumedFloor`]) in words:
/// what the channel is trusted to and why, and what its own scatter would
/// make of its RMS.
pub fn assumed_floor(a: &AssumedFloor) -> String {
    let (name, u) = (a.channel.name(), a.channel.unit());
    // A channel without scatter has no ratio to give: any RMS is a gap.
    if a.scatter == 0.0 {
        return format!(
            "this rests on an assumed floor: {name} is read as an estimated output and trusted to {} {u}, an estimated output's uncertainty, not one stated; with {name} trusted to its scatter, 0 {u} (noise-free), its RMS {} {u} would be a gap at any number of noise floors (where {name} is a sensor, state `[channels] {name} = …` in the campaign)",
            rms(a.floor),
            rms(a.rms),
        );
    }
    format!(
        "this rests on an assumed floor: {name} is read as an estimated output and trusted to {} {u}, an estimated output's uncertainty, not one stated; with {name} trusted to its scatter, {} {u}, its RMS {} {u} would be {} noise floors, a gap (where {name} is a sensor, state `[channels] {name} = …` in the campaign)",
        rms(a.floor),
        rms(a.scatter),
        rms(a.rms),
        crate::format::fixed(a.rms / a.scatter, 0),
    )
}

/// A verdict of no significant gap, with the stated uncertainties it
/// rests on ([`StatedExcess`]).
pub fn no_gap(n: &NoSignificantGap) -> String {
    let mut v = format!(
        "no significant gap: held-out error {:.3} is within {} × the noise level {:.3}",
        n.heldout_error, n.threshold, n.noise_level
    );
    for e in &n.resting_on {
        v += &format!(
            "; this rests on the uncertainty stated under [channels] for {}, {} {}, {}",
            e.channel.name(),
            rms(e.stated),
            e.channel.unit(),
            stated_excess(e)
        );
    }
    for a in &n.assumed {
        v += "; ";
        v += &assumed_floor(a);
    }
    if let Some(f) = &n.far_from_off {
        v += &far_from_off(f, n.threshold);
    }
    v
}

/// What a candidate fitted far from off on a gap within noise found (the
/// best on held-out runs of those that do, and the others that do too),
/// why the rule does not take it, and what would decide it.
fn far_from_off(f: &FarFromOff, threshold: f64) -> String {
    let p = &f.parameter;
    let unit = if p.unit == "-" { "" } else { p.unit };
    let sp = if unit.is_empty() { "" } else { " " };
    let names = |e: &[EffectKind]| e.iter().map(|k| k.name()).collect::<Vec<_>>().join("+");
    let mut kinds: Vec<EffectKind> = f.effects.clone();
    for k in f.also.iter().flat_map(|a| &a.effects) {
        if !kinds.contains(k) {
            kinds.push(*k);
        }
    }
    let signatures: Vec<String> = kinds
        .iter()
        .map(|e| format!("{}: {}", e.name(), e.signature()))
        .collect();
    let also = if f.also.is_empty() {
        String::new()
    } else {
        let others: Vec<String> = f
            .also
            .iter()
            .map(|a| {
                format!(
                    "{} ({:.0} standard errors from off, held-out error {:.3})",
                    names(&a.effects),
                    a.standard_errors,
                    a.heldout_error_after
                )
            })
            .collect();
        format!(
            "; {} fit{} that far from off too and the held-out runs do not tell {} from {}",
            others.join(", "),
            if f.also.len() == 1 { "s" } else { "" },
            if f.also.len() == 1 { "it" } else { "them" },
            names(&f.effects)
        )
    };
    format!(
        "; but {} fits {} = {} ± {}{sp}{unit}, {:.0} standard errors from its off value {}{sp}{unit}, and lowers the held-out error to {:.3}, the most of the candidates that fit that far from off{also}: the rule weighs a candidate only where the gap exceeds {threshold} × the noise level, so it is not accepted; what it fits lies in too little of the runs to lift the gap above that, and more or longer runs that show it ({}) would decide it",
        names(&f.effects),
        p.name,
        value(p.value),
        std_error(p.std_error),
        f.standard_errors,
        crate::format::exact(f.off),
        f.heldout_error_after,
        signatures.join("; ")
    )
}

/// [`super::channel_change`] with, where the channel's stated floor lies below
/// its scatter ([`super::judged_apart`]: the fits weigh it by another
/// value), that said beside the floor: one value judges significance,
/// and the row names it.
pub fn channel_change_judged(s: &Shrinkage, noise: &[ChannelNoise]) -> String {
    let line = super::channel_change(s);
    let judged = noise
        .iter()
        .find(|n| n.channel == s.channel)
        .and_then(judged_apart);
    match judged {
        Some(j) => {
            let floor = format!("(noise floor {})", rms(s.noise_floor));
            let said = format!("(noise floor {}, stated, {j})", rms(s.noise_floor));
            line.replacen(&floor, &said, 1)
        }
        None => line,
    }
}
