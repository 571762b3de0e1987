//! A verdict's warnings in words ([`VerdictWarning`]): a channel the
//! effects leave worse or leave, parameters on their search bound, and a
//! rest of the gap that is itself significant. RMS values in the channel's
//! unit; shares in percent of the gap above noise.

use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::outcome::{CarriedBy, ChannelChange, ChannelLeft, VerdictWarning};
use crate::diagnose::report::ParameterValue;

/// A channel's held-out RMS before and after the verdict's effects, in its
/// unit: `RMS 0.0247 → 0.0216 rad/s`.
fn rms_change(channel: Channel, before: f64, after: f64) -> String {
    format!("RMS {before:.4} → {after:.4} {}", channel.unit())
}

/// A channel whose gap the verdict's effects leave ([`ChannelLeft`]):
/// its change said by the rule the table and the page say it by (a change
/// within the scatter of held-out scores is no removal), and its other
/// cause pointed to where the report holds evidence of one
/// ([`ChannelLeft::causes`]), else named in general.
fn channel_left(c: &ChannelLeft) -> String {
    let change = match c.change() {
        ChannelChange::Unchanged(_) => format!(
            "{}, where the verdict needs {:.0} % of the whole",
            super::unchanged(c.before, c.after, c.noise_floor),
            c.acceptance_percent
        ),
        _ => format!(
            "{:.0} % of the gap above noise removed, less than the {:.0} % the verdict needs of the whole",
            c.removed_percent, c.acceptance_percent
        ),
    };
    let cause = super::causes::pointed(&c.causes, c.channel, c.noise_floor).unwrap_or_else(|| {
        "(a model-form error the candidates do not hold, or this channel's sensor)".into()
    });
    format!(
        "it leaves the {} gap: {} on held-out runs (noise floor {:.4}), {change}; the combined error falls through the other channels, so this channel's gap has another cause{}{cause}",
        c.channel.name(),
        rms_change(c.channel, c.before, c.after),
        c.noise_floor,
        if c.causes.is_empty() { " " } else { ": " }
    )
}

/// One warning on the verdict.
pub fn verdict_warning(w: &VerdictWarning) -> String {
    match w {
        VerdictWarning::ChannelWorsened(c) => format!(
            "it leaves the {} gap larger on held-out runs: {} (noise floor {:.4}), {}; the combined error falls through the other channels (check this channel's sensor{} and whether the effect's physics can make it worse)",
            c.channel.name(),
            rms_change(c.channel, c.before, c.after),
            c.noise_floor,
            super::added(c.added_percent, c.before, c.after, c.noise_floor),
            super::causes::pointed(&c.causes, c.channel, c.noise_floor)
                .map_or(String::new(), |p| format!(": {p};"))
        ),
        VerdictWarning::ChannelLeft(c) => channel_left(c),
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
        VerdictWarning::TyreClass(c) => super::class::class_to_check(c),
        VerdictWarning::GapRemains {
            heldout_error_after,
            noise_level,
            threshold,
            left_percent,
            carried_by,
            runs_carrying,
        } => {
            let head = format!("what it leaves is still a gap: held-out error {heldout_error_after:.3}, above {threshold} × the noise level {noise_level:.3}, so the other {left_percent:.1} % of the gap is a further cause");
            let runs = runs_carrying.as_ref();
            let named = runs.filter(|r| !r.carried_by.is_empty());
            match (carried_by, named, runs) {
                (Some(c), Some(r), _) => {
                    let said = carried(c);
                    let r = super::runs_left::without_scales_said(r, &said);
                    format!("{head}, not noise: {said}; over all channels {}", super::runs_left::held_by(&r))
                }
                (Some(c), None, _) => format!("{head}, not noise: {}", carried(c)),
                (None, Some(r), _) => format!("{head}, not noise: {}; {}", super::runs_left::held_by(r), super::runs_left::look_first(r)),
                (None, None, Some(r)) => format!("{head} (an effect outside the library, or the base model's own form), not noise: {}", super::runs_left::spread(r)),
                (None, None, None) => format!("{head} (an effect outside the library, or the base model's own form), not noise"),
            }
        }
    }
}

/// Where the further cause of what a verdict leaves lies: the channel
/// that carries most of it, and either the warning on it above that names
/// what the report holds about it or the causes in general.
fn carried(c: &CarriedBy) -> String {
    let name = c.channel.name();
    let share = format!("{name} carries {:.0} % of what it leaves", c.share_percent);
    if c.causes_named {
        format!("{share}, and the warning on {name} above says what the report holds about it")
    } else if let Some(p) = super::causes::pointed(&c.causes, c.channel, c.noise_floor) {
        format!("{share}: {p}")
    } else {
        format!("{share} (an effect outside the library, the base model's own form, or {name}'s sensor)")
    }
}

/// The effect parameters on or near their search bound in a verdict's
/// warnings ([`VerdictWarning::OnSearchBound`]); the roll mode's
/// (`roll.frequency`, `roll.damping`) are no effect's size and left out.
pub fn effect_parameters_on_bound(warnings: &[VerdictWarning]) -> Vec<&ParameterValue> {
    warnings
        .iter()
        .filter_map(|w| match w {
            VerdictWarning::OnSearchBound { parameters } => Some(parameters),
            _ => None,
        })
        .flatten()
        .filter(|p| !p.name.starts_with("roll."))
        .collect()
}

/// The clause of a verdict's statement where a parameter of its effects
/// stands on or near its search bound (`warnings`): the verdict then names
/// an effect pressed against the end of the range the library allows it,
/// not a measurement of that effect's physics; the warning below says the
/// same of the parameter. Empty otherwise.
pub(super) fn bound_clause(warnings: &[VerdictWarning]) -> String {
    let own = effect_parameters_on_bound(warnings);
    if own.is_empty() {
        return String::new();
    }
    let each: Vec<String> = own.iter().map(|p| super::parameters::on_bound(p)).collect();
    let mut effects: Vec<&str> = own
        .iter()
        .map(|p| p.name.split('.').next().unwrap_or(&p.name))
        .collect();
    effects.dedup();
    let effects = effects.join(" and ");
    let all_on = own.iter().all(|p| p.at_bound);
    let (on, its, it) = match (own.len(), all_on) {
        (1, true) => ("on", "its", "it"),
        (1, false) => ("near", "its", "it"),
        (_, true) => ("on", "their", "them"),
        (_, false) => ("on or near", "their", "them"),
    };
    format!(
        "; {} {on} {its} search bound, so the verdict is not a measurement of {effects}: the runs would take {it} beyond the range the library allows, and the cause may be {effects} beyond that range, or a different effect that {effects} at {its} limit imitates",
        each.join(", ")
    )
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

    /// A verdict whose parameter sits on or near its search bound says in
    /// its own sentence that it measures no effect there (round 35: the
    /// Putnam log's narrowed verdict, a delay on its 0.3 s bound, said only
    /// in a warning); the roll mode on its bound is no effect's and not
    /// named; nothing on a bound, nothing said.
    #[test]
    fn a_parameter_on_its_search_bound_is_said_in_the_verdicts_sentence() {
        use crate::diagnose::effects::{EffectKind, Group};
        let fitted = super::super::tests::fitted;
        let on = |ps: Vec<ParameterValue>| {
            bound_clause(&[VerdictWarning::OnSearchBound { parameters: ps }])
        };
        let delay = fitted("sensor_delay.delay", "s", 0.3, Some(Bound::Search));
        let roll = fitted("roll.frequency", "Hz", 4.0, Some(Bound::Search));
        assert_eq!(
            on(vec![delay, roll.clone()]),
            "; sensor_delay.delay = 0.3000 s on its search bound, so the verdict is not a measurement of sensor_delay: the runs would take it beyond the range the library allows, and the cause may be sensor_delay beyond that range, or a different effect that sensor_delay at its limit imitates"
        );
        assert_eq!(on(vec![roll]), "");
        assert_eq!(bound_clause(&[]), "");
        let q = &EffectKind::SensorDelay.parameters()[0];
        let near = ParameterValue::of(Group::Effect(EffectKind::SensorDelay), q, 0.2991, 0.0165);
        assert!(
            on(vec![near]).starts_with("; sensor_delay.delay = 0.2991 s (its bound 0.3 s lies within its standard error, 0.0165 s) near its search bound, so the verdict is not a measurement of sensor_delay"),
        );
    }
}
