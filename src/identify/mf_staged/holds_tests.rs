//! Tests of `holds.rs`: the book defaults, the held lines' words.

use super::*;
use crate::identify::mf_staged::book_defaults::PACEJKA_BOOK;
use crate::identify::mf_staged::Stage;

/// Every coefficient a stage fits has its book default, and the
/// values are the book's (spot checks against the file).
#[test]
fn every_fitted_coefficient_has_a_book_default() {
    for st in Stage::ALL {
        for (name, _) in st.parameters() {
            assert!(pacejka_book_default(name).is_some(), "{name}");
        }
    }
    assert_eq!(PACEJKA_BOOK.len(), 124);
    assert_eq!(pacejka_book_default("PKY4"), Some(2.0));
    assert_eq!(pacejka_book_default("PKY1"), Some(-15.0));
    assert_eq!(pacejka_book_default("QBZ5"), Some(0.0));
    let h = Holding {
        given: vec![("PKY4".into(), 1.5)],
        template_keys: vec!["QBZ4".into()],
    };
    assert_eq!(h.given("PKY4"), Some(1.5));
    assert_eq!(h.stated("QBZ4", Some(2.1)), (2.1, HoldSource::Template));
    assert_eq!(h.stated("QBZ5", Some(1.0)), (0.0, HoldSource::PacejkaBook));
}

/// Each coefficient held by design gives its own reason, none the
/// other's.
#[test]
fn a_coefficient_held_by_design_gives_its_own_reason() {
    let why = |name| held_reason(name, HELD, [3, 3, 3]).unwrap().to_string();
    assert!(why("QBZ9").contains("QBZ10·By·Cy") && !why("QBZ9").contains("rolling"));
    for name in ["QSY3", "QSY4"] {
        assert!(why(name).contains("rolling resistance's speed terms"));
        assert!(!why(name).contains("QBZ10"));
    }
}

#[test]
fn a_hold_reason_reads_as_a_sentence() {
    let levels = HoldReason::Levels {
        need: [2, 1, 3],
        have: [1, 2, 1],
    };
    assert_eq!(
        levels.to_string(),
        "needs 2 load levels, the data have 1, needs 3 pressure levels, the data have 1"
    );
    let rule = HoldReason::NotIdentifiable {
        fitted: 0.100662,
        std_error: Some(2.049),
        effect_percent: 715.1,
        source: HoldSource::PacejkaBook,
        stated: 0.0,
        held_at: 0.0,
        standard_errors_away: Some(0.049),
        at_bound: None,
        sigma_held_free: None,
        hold_order: None,
    };
    assert_eq!(rule.to_string(), "not identifiable from these data when fitted (0.10066 ± 2.049; one standard error of it alone moves the fit by 715.1 % of the channel's RMS, which the other parameters' trade-off undoes): held at the Pacejka 2012 book default 0, 0.05 standard errors from the free fit (within the ±2 standard errors the data allow)");
    // PKY4 of the Hoosier fit at 0.10014 of its box 0.1..5: said at
    // its bound, without the standard error's effect (723 %).
    assert_eq!(near_bound(0.10014, (0.1, 5.0)), Some((0.1, (0.1, 5.0))));
    assert_eq!(near_bound(0.2, (0.1, 5.0)), None);
    let at = HoldReason::NotIdentifiable {
        fitted: 0.10014,
        std_error: Some(2.06),
        effect_percent: 722.7,
        source: HoldSource::PacejkaBook,
        stated: 2.0,
        held_at: 2.0,
        standard_errors_away: Some(0.9),
        at_bound: near_bound(0.10014, (0.1, 5.0)),
        sigma_held_free: None,
        hold_order: None,
    };
    assert_eq!(at.to_string(), "stopped at its lower bound 0.1 when fitted (0.10014; its physical box 0.1 to 5): the best fit to these data lies outside the physical box, so they give it no physical value, and a standard error taken at the bound means nothing: held at the Pacejka 2012 book default 2");
}

/// A stated value more than two standard errors from the fitted one
/// is not held: the end of the ±2 nearest it is, and the line says both
/// values, how far the stated one lay and the option that holds
/// another; within two, the stated value is held and the line is the
/// reason alone.
#[test]
fn a_held_line_says_the_value_held_and_the_stated_one() {
    use crate::identify::spare::{held_value, standard_errors_away};
    let rule = |stated: f64| {
        let (fitted, se) = (0.0009574, Some(0.002192));
        HoldReason::NotIdentifiable {
            fitted,
            std_error: se,
            effect_percent: 9.2,
            source: HoldSource::Template,
            stated,
            held_at: held_value(stated, fitted, se, (-1.0, 1.0)),
            standard_errors_away: standard_errors_away(stated, fitted, se),
            at_bound: None,
            sigma_held_free: None,
            hold_order: None,
        }
    };
    let far = rule(0.084).said("QDZ1");
    assert!(far.ends_with("held at 0.00534, the end of the free fit's ±2 standard errors nearest the template's value 0.084 (which lies 37.9 standard errors from the free fit: held there first, with the rest refitted, it raised the cost past what a hold may, so the data reject it); to hold it at a value of your own, give --hold QDZ1=VALUE"), "{far}");
    let near = rule(0.004);
    assert_eq!(near.said("QDZ1"), near.to_string());
    assert!(near.to_string().ends_with("held at the template's value 0.004, 1.4 standard errors from the free fit (within the ±2 standard errors the data allow)"), "{near}");
    assert_eq!(HoldReason::Given.said("PKY4"), "given with --hold");
}

/// A hold that lowers σ says the free fit stopped short; one that raises
/// it, or moves no printed digit, says nothing more (MFeval's grid held
/// QSX6 at σ 0.355 % against 0.404 % free, unsaid, before the guard
/// refused its costly neighbour's hold).
#[test]
fn a_hold_that_lowers_sigma_says_the_free_fit_stopped_short() {
    assert!(held_below_free(0.355, 0.404).contains("had stopped short of its optimum"));
    assert_eq!(held_below_free(0.404, 0.355), "");
    assert_eq!(held_below_free(0.3550000001, 0.3550000002), "");
}

/// A round's σ held and free print with the digits that tell them apart,
/// alike where they agree to a millionth (the car205 grid's QBZ2 read
/// "σ 1.245514 % held against 1.245514 % free", six decimals for two
/// numbers it could not tell apart), and say which of the stage's holds
/// the round was.
#[test]
fn a_rounds_sigma_is_told_apart_or_alike_and_numbered() {
    let same = held_free([1.245514429528859, 1.2455142525422576], Some([1, 1]));
    assert_eq!(
        same,
        "; σ 1.246 % held against 1.246 % free (in the round of the stage's hold 1 of 1, in the order they were made)"
    );
    let apart = held_free([1.24561, 1.24589], Some([2, 3]));
    assert!(
        apart.starts_with(
            "; σ 1.2456 % held against 1.2459 % free (in the round of the stage's hold 2 of 3"
        ),
        "{apart}"
    );
    let lower = held_free([0.355, 0.404], None);
    assert!(
        lower.starts_with("; σ 0.355 % held against 0.404 % free: lower held"),
        "{lower}"
    );
}
