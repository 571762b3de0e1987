//! The verdict's types: their rules.

use super::*;
use crate::diagnose::report::Shrinkage;

fn row(before: f64, after: f64, noise_floor: f64) -> Shrinkage {
    Shrinkage {
        channel: Channel::Beta,
        part: Part::All,
        samples: 100,
        before,
        after,
        noise_floor,
        reduction_percent: crate::diagnose::model::channels::reduction(before, after, noise_floor),
        mean_level: None,
        runs: Vec::new(),
    }
}

#[test]
fn a_change_within_noise_is_no_worsening() {
    // The blind campaign's sideslip: 0.0021 → 0.0022 rad on a floor of
    // 0.0020 adds 43 % to a gap that is noise: within noise.
    let r = row(0.0021, 0.0022, 0.0020);
    assert!(r.reduction_percent < -40.0, "{}", r.reduction_percent);
    assert_eq!(r.change(), ChannelChange::WithinNoise);
    // Three noise floors is the line, on either side of the change; a
    // change across it of 3.8 % of the gap is within the scatter of
    // held-out scores: unchanged, not a removal or a worsening.
    assert_eq!(
        row(0.0059, 0.0060, 0.002).change(),
        ChannelChange::WithinNoise
    );
    assert!(matches!(
        row(0.0059, 0.0061, 0.002).change(),
        ChannelChange::Unchanged(p) if (-4.0..-3.5).contains(&p)
    ));
}

/// Round 38: RMS 0.0061 → 0.0062 on a 0.0020 floor read "−1 % of the gap
/// above noise removed". A change of the gap above noise within
/// [`WORSENED`] either way is unchanged, at the same line a worsening
/// starts: a gap above noise sqrt(rms² − nf²) from 4 noise floors to
/// 3.61 (9.75 % removed) or 4.39 (9.75 % added) is unchanged, to 3.59
/// (10.25 % removed) a change.
#[test]
fn a_change_within_the_scatter_of_held_out_scores_is_no_change() {
    let r = row(0.0061, 0.0062, 0.0020);
    let p = r.reduction_percent;
    assert!((-2.0..-1.5).contains(&p), "{p}");
    assert_eq!(r.change(), ChannelChange::Unchanged(p));
    let nf = 1.0;
    let rms = |g: f64| (g * g + nf * nf).sqrt();
    let at = |g_after: f64| row(rms(4.0), rms(g_after), nf).change();
    assert!(matches!(at(3.61), ChannelChange::Unchanged(p) if (p - 9.75).abs() < 1e-9));
    assert!(matches!(at(4.39), ChannelChange::Unchanged(p) if (p + 9.75).abs() < 1e-9));
    assert!(matches!(at(3.59), ChannelChange::Changed(p) if (p - 10.25).abs() < 1e-9));
    // The warning's channel says it by the same rule.
    let left = ChannelLeft {
        channel: Channel::Beta,
        before: 0.0061,
        after: 0.0062,
        noise_floor: 0.0020,
        removed_percent: p,
        acceptance_percent: 30.0,
        causes: Vec::new(),
    };
    assert_eq!(left.change(), r.change());
}

#[test]
fn a_gap_above_noise_grown_by_more_than_ten_percent_is_a_worsening() {
    // Gap above noise sqrt(after² − nf²): from 4 to 4.4 noise floors
    // (+10 %) and to 4.41 (just over).
    let nf = 1.0;
    let rms = |g: f64| (g * g + nf * nf).sqrt();
    let at = |g_after: f64| row(rms(4.0), rms(g_after), nf).change();
    assert!(matches!(at(4.39), ChannelChange::Unchanged(p) if (p + 9.75).abs() < 1e-9));
    assert!(matches!(at(4.41), ChannelChange::Worsened(p) if (p - 10.25).abs() < 1e-9));
    // A channel within noise before and well above it after is worse.
    assert!(matches!(
        row(1.5, 5.0, 1.0).change(),
        ChannelChange::Worsened(_)
    ));
    // From an RMS below its floor (no gap above noise, the share defined
    // as 0) to one above noise: a worsening by no finite share, not
    // "unchanged" and not "0 %".
    let from_none = row(0.0018, 0.0080, 0.0020);
    assert_eq!(from_none.reduction_percent, 0.0);
    assert_eq!(from_none.change(), ChannelChange::Worsened(f64::INFINITY));
    // A reduction is a change, whatever its size.
    assert!(matches!(
        row(5.0, 1.0, 1.0).change(),
        ChannelChange::Changed(p) if p == 100.0
    ));
}

#[test]
fn an_accepted_set_explains_part_of_the_gap_below_half_of_it() {
    let e = |reduction_percent| Explained {
        effects: vec![EffectKind::SensorDelay],
        parameters: Vec::new(),
        heldout_error_before: 3.0,
        heldout_error_after: 2.0,
        noise_level: 1.0,
        reduction_percent,
        warnings: Vec::new(),
        evidence: Vec::new(),
        confounded_with: None,
        in_set: Vec::new(),
    };
    assert!(e(49.9).partial());
    assert!(!e(50.0).partial());
}
