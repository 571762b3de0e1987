//! A verdict's words on axles that another tyre class's ranges hold
//! ([`ClassMismatch`]): the campaign's `[tyres] class` to check, in place of
//! "outside the library". Cornering coefficients in 1/rad.

use crate::diagnose::effects::{joined, EffectKind};
use crate::diagnose::report::narrowed::{Narrowed, OffsetMatch};
use crate::diagnose::report::tyre_class::ClassMismatch;
use crate::diagnose::report::CalibrationSource;
use crate::format::rounded;

/// The clause naming the class whose ranges hold the axles.
pub fn class_mismatch(c: &ClassMismatch) -> String {
    format!(
        "{}: the stated tyre class, not a model-form error outside the library, is what to check first",
        placed(c)
    )
}

/// The warning under an explained verdict whose axles another class's
/// ranges hold: the class to check, the effects fitted beside axles the
/// stated class's prior pulled.
pub fn class_to_check(c: &ClassMismatch) -> String {
    format!(
        "{}: check the stated tyre class, whose prior pulled the axles the effects were fitted beside",
        placed(c)
    )
}

/// Whose axles lie where: outside the stated class's prior, inside the
/// classes that hold them.
fn placed(c: &ClassMismatch) -> String {
    let whose = if c.effects.is_empty() {
        "the base model's axles".to_string()
    } else {
        format!(
            "the axles fitted with {}{}",
            joined(&c.effects, "+"),
            c.reduction_percent.map_or(String::new(), |r| format!(
                " (which removes {r:.1} % of the gap)"
            ))
        )
    };
    let range = |r: [f64; 2]| format!("{}–{} 1/rad", rounded(r[0], 3), rounded(r[1], 3));
    let names: Vec<&str> = c.holding.iter().map(|k| k.name()).collect();
    format!(
        "{whose}, front {} and rear {} 1/rad, lie outside the prior of `[tyres] class = \"{}\"` (cornering coefficient {}) but inside the ranges of {} (nearest: {}, {})",
        rounded(c.cornering[0], 3),
        rounded(c.cornering[1], 3),
        c.stated.name(),
        range(c.stated_cornering),
        names.join(", "),
        names[0],
        range(c.holding_cornering),
    )
}

/// How a sentence blaming a model-form error outside the library ends.
pub(super) const OUTSIDE: &str = " — a model-form error outside the library";
/// How a sentence refusing the library's best ends.
pub(super) const NO_VERDICT: &str = " — no verdict from the library";

/// The clause of a verdict on candidates a campaign narrowed: which
/// were tried, how many of the library's were not, and how to try them;
/// where the gap's steady offsets match the offsets the runs measured,
/// the untried `sensor_bias` to add ([`offsets_point_at_bias`]).
pub(super) fn untried(n: &Narrowed) -> String {
    format!(
        " — no verdict on the library: only the campaign's `[diagnose] effects` were tried ({}), and {} of the library's {} effects were not: leave `effects` out under [diagnose] to try them all{}",
        joined(&n.tried, ", "),
        n.untried.len(),
        n.tried.len() + n.untried.len(),
        offsets_point_at_bias(&n.offsets),
    )
}

/// The clause naming `sensor_bias` to add where the gap's steady offsets
/// match the offsets the standstills or straights measured (a sensor
/// offset reads as a residual of the opposite sign); empty without one.
pub fn offsets_point_at_bias(offsets: &[OffsetMatch]) -> String {
    if offsets.is_empty() {
        return String::new();
    }
    let each: Vec<String> = offsets
        .iter()
        .map(|o| {
            let u = o.channel.unit();
            let on = match o.measured_on {
                CalibrationSource::Standstills => "standstills",
                CalibrationSource::Straights => "straights",
            };
            format!(
                "the {c} gap's steady offset {} ± {} {u} matches the {on}' {c} offset {} ± {} {u}",
                rounded(o.residual, 3),
                rounded(o.residual_std_error, 2),
                rounded(o.measured, 3),
                rounded(o.measured_std_error, 2),
                c = o.channel.name(),
            )
        })
        .collect();
    format!(
        "; {} (a sensor's offset reads as a residual of the opposite sign): add {} to [diagnose] effects",
        each.join(", and "),
        EffectKind::SensorBias.name()
    )
}

/// An outside-the-library sentence `s` of a campaign that narrowed its
/// candidates to `n`: none of the campaign's candidates, not none of the
/// library's, explains the gap, and the ending says what was not tried in
/// place of blaming a model-form error outside the library.
pub(super) fn narrowed(s: String, n: &Narrowed) -> String {
    let s = s
        .replacen(
            "that no candidate effect explains",
            "that none of the campaign's candidate effects explains",
            1,
        )
        .replacen(
            "for which no candidate effect is accepted",
            "for which none of the campaign's candidate effects is accepted",
            1,
        );
    let cut = s.trim_end_matches(OUTSIDE).trim_end_matches(NO_VERDICT);
    let tail = untried(n);
    if cut.len() < s.len() {
        format!("{cut}{tail}")
    } else {
        // Ended by the tyre class to check: the narrowing after it.
        format!("{cut};{}", tail.trim_start_matches(" —"))
    }
}

/// An outside-the-library sentence `s`, its ending replaced by the class
/// to check where another tyre class's ranges hold the axles.
pub(super) fn with_class(s: String, c: Option<&ClassMismatch>) -> String {
    match c {
        Some(c) => format!(
            "{}; {}",
            s.trim_end_matches(OUTSIDE).trim_end_matches(NO_VERDICT),
            class_mismatch(c)
        ),
        None => s,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::campaign::prior::TyreClass;
    use crate::diagnose::effects::EffectKind;

    #[test]
    fn axles_another_class_holds_point_at_the_class_not_at_the_library() {
        let c = ClassMismatch {
            stated: TyreClass::Truck,
            stated_cornering: [4.0, 10.0],
            holding: vec![TyreClass::Road, TyreClass::RacingSlick],
            holding_cornering: [8.0, 35.0],
            effects: vec![EffectKind::AccelerometerPosition],
            reduction_percent: Some(91.23),
            cornering: [14.105, 19.898],
        };
        let s = with_class(
            format!("a gap that no candidate effect explains: the best, x, removes 10.0 % of it (acceptance needs 30 %){OUTSIDE}"),
            Some(&c),
        );
        assert_eq!(
            s,
            "a gap that no candidate effect explains: the best, x, removes 10.0 % of it (acceptance needs 30 %); the axles fitted with accelerometer_position (which removes 91.2 % of the gap), front 14.1 and rear 19.9 1/rad, lie outside the prior of `[tyres] class = \"truck\"` (cornering coefficient 4–10 1/rad) but inside the ranges of road, racing_slick (nearest: road, 8–35 1/rad): the stated tyre class, not a model-form error outside the library, is what to check first"
        );
        // Without a class that holds them, the sentence is left as it was.
        let alone = format!("a gap{NO_VERDICT}");
        assert_eq!(with_class(alone.clone(), None), alone);
    }

    #[test]
    fn a_campaign_that_named_its_candidates_is_no_verdict_on_the_library() {
        let n = Narrowed::of(Some(&[EffectKind::RoadBank])).unwrap();
        let s = narrowed(
            format!("a gap that no candidate effect explains: the best, road_bank, removes none of it (acceptance needs 30 %){OUTSIDE}"),
            &n,
        );
        let library = EffectKind::ALL.len();
        assert_eq!(
            s,
            format!("a gap that none of the campaign's candidate effects explains: the best, road_bank, removes none of it (acceptance needs 30 %) — no verdict on the library: only the campaign's `[diagnose] effects` were tried (road_bank), and {} of the library's {library} effects were not: leave `effects` out under [diagnose] to try them all", library - 1)
        );
        assert!(!s.contains("outside the library"), "{s}");
        // A refused best: its ending, too, says what was not tried.
        let s = narrowed(
            format!("a gap for which no candidate effect is accepted: the best, road_bank, removes 40 % of it{NO_VERDICT}"),
            &n,
        );
        assert!(
            s.starts_with("a gap for which none of the campaign's candidate effects is accepted"),
            "{s}"
        );
        assert!(
            s.ends_with("to try them all") && !s.contains(NO_VERDICT),
            "{s}"
        );
    }

    #[test]
    fn a_narrowed_verdict_whose_gap_offsets_match_the_standstills_names_sensor_bias() {
        use crate::diagnose::model::channels::Channel;
        let mut n = Narrowed::of(Some(&[EffectKind::SensorDelay])).unwrap();
        n.offsets = vec![OffsetMatch {
            channel: Channel::Ay,
            residual: -0.1917,
            residual_std_error: 0.0072,
            measured: 0.2028,
            measured_std_error: 0.0018,
            measured_on: CalibrationSource::Standstills,
        }];
        let s = untried(&n);
        assert!(
            s.ends_with("to try them all; the ay gap's steady offset -0.192 ± 0.0072 m/s² matches the standstills' ay offset 0.203 ± 0.0018 m/s² (a sensor's offset reads as a residual of the opposite sign): add sensor_bias to [diagnose] effects"),
            "{s}"
        );
        n.offsets.clear();
        assert!(untried(&n).ends_with("to try them all"));
    }
}
