//! A verdict's warnings in words ([`VerdictWarning`]): a channel the
//! effects leave worse or leave, parameters on their search bound, and a
//! rest of the gap that is itself significant. RMS values in the channel's
//! unit; shares in percent of the gap above noise.

use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::outcome::VerdictWarning;

/// A channel's held-out RMS before and after the verdict's effects, in its
/// unit: `RMS 0.0247 → 0.0216 rad/s`.
fn rms_change(channel: Channel, before: f64, after: f64) -> String {
    format!("RMS {before:.4} → {after:.4} {}", channel.unit())
}

/// One warning on the verdict.
pub fn verdict_warning(w: &VerdictWarning) -> String {
    match w {
        VerdictWarning::ChannelWorsened(c) => format!(
            "it leaves the {} gap larger on held-out runs: {} (noise floor {:.4}), {:.0} % of the gap above noise added; the combined error falls through the other channels (check this channel's sensor and whether the effect's physics can make it worse)",
            c.channel.name(),
            rms_change(c.channel, c.before, c.after),
            c.noise_floor,
            c.added_percent
        ),
        VerdictWarning::ChannelLeft(c) => format!(
            "it leaves the {} gap: {} on held-out runs (noise floor {:.4}), {:.0} % of the gap above noise removed, less than the {:.0} % the verdict needs of the whole; the combined error falls through the other channels, so this channel's gap has another cause (a model-form error the candidates do not hold, or this channel's sensor)",
            c.channel.name(),
            rms_change(c.channel, c.before, c.after),
            c.noise_floor,
            c.removed_percent,
            c.acceptance_percent
        ),
        VerdictWarning::OnSearchBound { parameters } => {
            super::parameters::on_search_bound(parameters)
        }
        VerdictWarning::TyresFarFromLoad { front, rear } => {
            let each: Vec<String> = [("front", front), ("rear", rear)]
                .into_iter()
                .filter_map(|(axle, share)| {
                    share.map(|x| format!("{axle} {} × FNOMIN", crate::format::fixed(x, 2)))
                })
                .collect();
            format!(
                "the base tyres are used far from their load range ({} a wheel standing still): a tyre file of another class of vehicle, so the effects fitted may stand in for the tyres' misfit, not for the car",
                each.join(", ")
            )
        }
        VerdictWarning::GapRemains {
            heldout_error_after,
            noise_level,
            threshold,
            left_percent,
        } => format!(
            "what it leaves is still a gap: held-out error {heldout_error_after:.3}, above {threshold} × the noise level {noise_level:.3}, so the other {left_percent:.1} % of the gap is a further cause (an effect outside the library, or the base model's own form), not noise"
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::effects::Bound;

    /// A ratio (unit `-`) is said without a unit, not "1.5000 -".
    #[test]
    fn a_ratio_on_its_search_bound_is_said_without_a_unit() {
        let ratio = super::super::tests::fitted("roll.damping", "-", 1.5, Some(Bound::Search));
        let w = verdict_warning(&VerdictWarning::OnSearchBound {
            parameters: vec![ratio],
        });
        assert!(
            w.starts_with("roll.damping = 1.5000 on its search bound"),
            "{w}"
        );
    }

    /// The roll mode on its bound is no bound on the effect's size; an
    /// effect's own parameter beside it is, each said in its own words.
    #[test]
    fn the_roll_mode_on_its_bound_is_not_called_the_effects_size() {
        let fitted = super::super::tests::fitted;
        let frequency = fitted("roll.frequency", "Hz", 4.0, Some(Bound::Search));
        let w = verdict_warning(&VerdictWarning::OnSearchBound {
            parameters: vec![frequency.clone()],
        });
        assert!(w.starts_with("roll.frequency = 4.0000 Hz on its search bound: the data would take it further, so it is a bound on the body's roll mode"), "{w}");
        assert!(!w.contains("a bound on the effect's size"), "{w}");
        let steer = fitted("roll_steer.rear", "rad/rad", -0.5, Some(Bound::Search));
        let w = verdict_warning(&VerdictWarning::OnSearchBound {
            parameters: vec![frequency, steer],
        });
        assert!(w.starts_with("roll_steer.rear = -0.5000 rad/rad on its search bound: the data would take it further, so its value is a bound on the effect's size, not a measurement of it; roll.frequency = 4.0000 Hz on its search bound"), "{w}");
    }
}
