//! The verdict's types: their rules.

use super::*;

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
    // Three noise floors is the line, on either side of the change.
    assert_eq!(
        row(0.0059, 0.0060, 0.002).change(),
        ChannelChange::WithinNoise
    );
    assert!(matches!(
        row(0.0059, 0.0061, 0.002).change(),
        ChannelChange::Changed(_)
    ));
}

#[test]
fn a_gap_above_noise_grown_by_more_than_ten_percent_is_a_worsening() {
    // Gap above noise sqrt(after² − nf²): from 4 to 4.4 noise floors
    // (+10 %) and to 4.41 (just over).
    let nf = 1.0;
    let rms = |g: f64| (g * g + nf * nf).sqrt();
    let at = |g_after: f64| row(rms(4.0), rms(g_after), nf).change();
    assert!(matches!(at(4.39), ChannelChange::Changed(p) if (p + 9.75).abs() < 1e-9));
    assert!(matches!(at(4.41), ChannelChange::Worsened(p) if (p - 10.25).abs() < 1e-9));
    // A channel within noise before and well above it after is worse.
    assert!(matches!(
        row(1.5, 5.0, 1.0).change(),
        ChannelChange::Worsened(_)
    ));
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
