//! A verdict's words on axles that another tyre class's ranges hold
//! ([`ClassMismatch`]): the campaign's `[tyres] class` to check, in place of
//! "outside the library". Cornering coefficients in 1/rad.

use crate::diagnose::effects::joined;
use crate::diagnose::report::narrowed::Narrowed;
use crate::diagnose::report::tyre_class::ClassMismatch;
use crate::format::rounded;

/// The clause naming the class whose ranges hold the axles.
pub fn class_mismatch(c: &ClassMismatch) -> String {
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
        "{whose}, front {} and rear {} 1/rad, lie outside the prior of `[tyres] class = \"{}\"` (cornering coefficient {}) but inside the ranges of {} (nearest: {}, {}): the stated tyre class, not a model-form error outside the library, is what to check first",
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
/// were tried, how many of the library's were not, and how to try them.
pub(super) fn untried(n: &Narrowed) -> String {
    format!(
        " — no verdict on the library: only the campaign's `[diagnose] effects` were tried ({}), and {} of the library's {} effects were not: leave `effects` out under [diagnose] to try them all",
        joined(&n.tried, ", "),
        n.untried.len(),
        n.tried.len() + n.untried.len(),
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
}
