//! Where the gap lies, in words: a channel's held-out RMS against its
//! noise floor, the parts of the data it is wrong and right in, and a
//! steady offset the RMS does not single out. RMS values and offsets in the
//! channel's unit (rad/s, m/s², rad).

use crate::diagnose::report::outcome::{above_noise, GapFinding, SIGNIFICANT_NOISE_FLOORS};
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
        runs,
        wrong,
        right,
        offset,
    } = f
    else {
        return String::new();
    };
    let said = offset.map_or(String::new(), |o| {
                format!(
                    "; a steady offset: mean residual {} {} over the runs, of that sign in {} of {} runs ({} noise floors, {:.0} % of the mean square), a sensor offset or a bias of the model that the RMS does not single out",
                    crate::format::signed(o.mean, 4),
                    channel.unit(),
                    o.same_sign,
                    o.runs,
                    crate::format::fixed(o.floors, 1),
                    100.0 * o.share
                )
            });
    let head = format!(
                "{}: RMS {rms:.4} {} (noise floor {noise_floor:.4}); significant in {significant_runs} of {runs} runs",
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
        format!(
            "{head}; wrong in: {}; right in: {}",
            parts(wrong),
            listed(right.iter().map(|p| p.label()).collect()),
        )
    } else if wrong.is_empty() {
        // A gap within noise has no place: listing the parts it is
        // "right in" would read as a finding.
        format!("{head}: within noise in every part, so no place where the base model is wrong")
    } else {
        format!(
                    "{head}: within noise over the runs, so no place where the base model is wrong; above {SIGNIFICANT_NOISE_FLOORS} noise floors only in {}",
                    parts(wrong)
                )
    };
    place + &said
}
