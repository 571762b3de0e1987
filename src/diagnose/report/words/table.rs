//! The held-out table's words: what the verdict's effects did to a
//! channel's gap ([`ChannelChange`], one rule for the terminal, the page
//! and the warnings), a candidate's reduction of the combined error, and
//! RMS values as the terminal and the page print them. RMS values and
//! floors in the channel's unit; shares in percent of the gap above noise.

use crate::diagnose::report::outcome::{ChannelChange, SIGNIFICANT_NOISE_FLOORS, WORSENED};
use crate::diagnose::report::{Reduction, Shrinkage};

/// A channel's held-out gap within noise before and after the verdict's
/// effects ([`crate::diagnose::report::Shrinkage::change`]): no share of
/// it is said, but how many noise floors it was and is, so that a channel
/// the verdict brought from 2.5 floors to 1 does not read as untouched
/// beside a significant combined error.
pub fn within_noise(s: &Shrinkage) -> String {
    let floors = |rms: f64| crate::format::fixed(rms / s.noise_floor, 1);
    format!(
        "not significant alone ({} → {} noise floors; a channel alone needs {SIGNIFICANT_NOISE_FLOORS})",
        floors(s.before),
        floors(s.after)
    )
}

/// A channel's held-out gap above noise that the verdict's effects moved
/// by no more than the scatter of held-out scores
/// ([`ChannelChange::Unchanged`]): as for a gap within noise, no share
/// is said (RMS 0.0061 → 0.0062 on a 0.0020 floor read "−1 % of the gap
/// above noise removed" in round 38), but how many noise floors it was and is.
pub fn unchanged(before: f64, after: f64, noise_floor: f64) -> String {
    let floors = |rms: f64| crate::format::fixed(rms / noise_floor, 1);
    format!(
        "unchanged within the scatter of held-out scores ({} → {} noise floors; a change needs more than {WORSENED} % of the gap above noise)",
        floors(before),
        floors(after)
    )
}

/// How the per-channel table's "not significant" differs from the
/// verdict's: each channel alone against its noise floors, the verdict on
/// the channels together (the combined error against the noise level), so
/// channels each within noise can carry a significant gap together.
pub fn channels_alone() -> String {
    format!("Each channel is judged alone against {SIGNIFICANT_NOISE_FLOORS} noise floors; the verdict's share is of the combined error of all channels, so channels each within noise can together carry a significant gap.")
}

/// A candidate's reduction of the combined error ([`Reduction`]), the
/// number to one decimal (%), or why none is given.
pub fn reduction(r: Reduction) -> String {
    match r {
        Reduction::WithinNoise => "not significant".into(),
        Reduction::Percent(p) => crate::format::fixed(p, 1),
    }
}

/// One channel before and after the verdict's effects on held-out runs
/// (all samples), as the terminal lists it.
pub fn channel_change(s: &Shrinkage) -> String {
    let what = match s.change() {
        ChannelChange::WithinNoise => within_noise(s),
        ChannelChange::Unchanged(_) => unchanged(s.before, s.after, s.noise_floor),
        ChannelChange::Changed(p) => format!("{p:.0} % of the gap above noise removed"),
        ChannelChange::Worsened(p) => added(p, s.before, s.after, s.noise_floor),
    };
    format!(
        "{:<9} {} → {} (noise floor {}): {what}",
        s.channel.name(),
        rms(s.before),
        rms(s.after),
        rms(s.noise_floor)
    )
}

/// A worsening's share of the gap above noise added (`percent`), or where
/// there was no gap above noise before (an RMS `before` at or below its
/// floor, an infinite share) that it made one, in noise floors: not "0 %"
/// or "inf %".
pub fn added(percent: f64, before: f64, after: f64, noise_floor: f64) -> String {
    if percent.is_finite() {
        format!("{percent:.0} % of the gap above noise added")
    } else {
        let floors = |rms: f64| crate::format::fixed(rms / noise_floor, 1);
        format!(
            "a gap above noise where there was none ({} → {} noise floors)",
            floors(before),
            floors(after)
        )
    }
}

/// An RMS or a noise floor as the terminal and the page print it: four
/// decimals where they show two significant digits, else two significant
/// digits (0.0032 rad/s, 0.00021 rad), one text for one number.
pub fn rms(v: f64) -> String {
    crate::format::decimals_or_digits(v, 4, 2)
}
