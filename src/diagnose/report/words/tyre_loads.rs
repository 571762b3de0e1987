//! The words of a base tyre used at static wheel loads beyond the range it
//! was fitted at ([`crate::diagnose::report::Note::TyreLoadsShort`]),
//! whichever way the tyre was given: fitted to the campaign's rig data
//! (the rig's loads), a TOML tyre file (its `[fitted_ranges] fz`, as
//! `identify` writes it) or a `.tir` (its `FZMIN`–`FZMAX`). One sentence per source, each with the ratio of
//! the car's load to the end it passes, so that a reader weighs the
//! verdict that follows. Units: N.

use crate::diagnose::report::outcome::{LoadRangeOf, TyreAxles};

/// The range `[lo, hi]` in words: `414–2887 N`, and a `.tir`'s range with
/// one end stated as `up to 2887 N` (no `FZMIN`: 0) or `from 414 N` (no
/// `FZMAX`: unbounded).
fn span([lo, hi]: [f64; 2]) -> String {
    match (lo > 0.0, hi.is_finite()) {
        (true, true) => format!("{lo:.0}–{hi:.0} N"),
        (false, true) => format!("up to {hi:.0} N"),
        (true, false) => format!("from {lo:.0} N"),
        (false, false) => "any load".to_string(),
    }
}

/// The car's loads `[lo, hi]`: one value where both are the same (a file
/// on one axle), else the range.
fn car_span([lo, hi]: [f64; 2]) -> String {
    match format!("{lo:.0}") == format!("{hi:.0}") {
        true => format!("{lo:.0} N"),
        false => format!("{lo:.0}–{hi:.0} N"),
    }
}

/// How far the car's loads `car` leave `loads`: the ratio to the end they
/// leave farther (an end not stated, 0 or unbounded, is never left), and
/// whether it is the upper.
fn beyond(loads: [f64; 2], car: [f64; 2]) -> (f64, bool) {
    let over = car[1] / loads[1];
    let under = loads[0] / car[0];
    match over >= under {
        true => (over, true),
        false => (car[0] / loads[0], false),
    }
}

/// What a gap may then be, said of every source: a steady residual too,
/// which the before → after block reads as a sensor's zero offset (the
/// Hoosier tyre's force at zero slip, +13 N per wheel at the sedan's
/// front load and +122 N at its rear, fitted −76 N at 1500 N, turned the
/// sedan's straight running into a yaw rate read as one).
const MAY_BE: &str = "so a gap may be the tyre's rather than an unmodelled effect's, a steady one included (its force at zero slip at those loads is no fit either, and a run reads it as a sensor's zero offset)";

/// What would tell the two apart, `what` said as its subject: a clause
/// of the note's one sentence after a `;`, where it had stood as a second
/// parenthesis straight after [`MAY_BE`]'s, "…offset) (a tyre fitted …
/// closes it)" (round 51).
fn settles(what: &str) -> String {
    format!("{what} would tell the two apart")
}

/// The words of [`crate::diagnose::report::Note::TyreLoadsShort`] of
/// `of`, its `loads` and `car`.
pub(super) fn note(of: &LoadRangeOf, loads: [f64; 2], car: [f64; 2]) -> String {
    let (ratio, above) = beyond(loads, car);
    let end = if above { "largest" } else { "least" };
    let is = |axles: TyreAxles| match axles {
        TyreAxles::Both => "are",
        TyreAxles::Front | TyreAxles::Rear => "is",
    };
    match of {
        LoadRangeOf::Rig => format!(
            "the rig data's wheel loads span {} and the car's static wheel loads are {} ({ratio:.2}× the rig's {end}): the base tyre fitted to them is extrapolated to the car's loads, {MAY_BE}; {}",
            span(loads),
            car_span(car),
            settles("rig data at the car's loads, or tyre files under [tyres],"),
        ),
        LoadRangeOf::Fitted { file, axles } => format!(
            "the tyre file {file} was fitted to rig data at wheel loads of {} (its [fitted_ranges] fz) and {} {} {} ({ratio:.2}× the fitted {end}): the tyre is extrapolated to the car's loads, {MAY_BE}; {}",
            span(loads),
            axles.wheels(),
            is(*axles),
            car_span(car),
            settles("a tyre fitted at the car's loads"),
        ),
        LoadRangeOf::Tir {
            file,
            axles,
            limit_checks,
        } => {
            let (key, held) = match (above, limit_checks) {
                (true, true) => ("FZMAX", "its forces are held at FZMAX's there (the limit checks of its mode, 1xx), not grown with the load"),
                (true, false) => ("FZMAX", "its formulae are extrapolated there (its mode's limit checks off, 2xx)"),
                (false, _) => ("FZMIN", "its forces are evaluated at the load given there, past the file's range (MFeval holds no load at FZMIN)"),
            };
            format!(
                "the tyre file {file} states the loads it holds as FZMIN–FZMAX, {}, and {} {} {} ({ratio:.2}× its {key}): {held}, {MAY_BE}; {}",
                span(loads),
                axles.wheels(),
                is(*axles),
                car_span(car),
                settles("a tyre file whose range holds the car's loads"),
            )
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fitted(car: [f64; 2], axles: TyreAxles) -> String {
        let of = LoadRangeOf::Fitted {
            file: "hoo.toml".to_string(),
            axles,
        };
        note(&of, [414.2, 2887.4], car)
    }

    #[test]
    fn the_ratio_is_to_the_end_the_car_passes() {
        // 4507 / 2887.4 = 1.5609; 300 / 414.2 = 0.7243.
        let above = fitted([2995.0, 4507.0], TyreAxles::Both);
        assert!(above.contains("wheel loads of 414–2887 N (its [fitted_ranges] fz) and the car's static wheel loads are 2995–4507 N (1.56× the fitted largest)"), "{above}");
        let below = fitted([300.0, 300.0], TyreAxles::Front);
        assert!(
            below.contains("the car's static front wheel load is 300 N (0.72× the fitted least)"),
            "{below}"
        );
    }

    #[test]
    fn a_tir_with_one_end_is_said_by_that_end() {
        assert_eq!(span([0.0, 2859.1]), "up to 2859 N");
        assert_eq!(span([414.2, f64::INFINITY]), "from 414 N");
        assert_eq!(span([414.2, 2859.1]), "414–2859 N");
        let of = LoadRangeOf::Tir {
            file: "small.tir".to_string(),
            axles: TyreAxles::Both,
            limit_checks: true,
        };
        let w = note(&of, [0.0, 2859.1], [2995.0, 4507.0]);
        assert!(w.contains("FZMIN–FZMAX, up to 2859 N, and the car's static wheel loads are 2995–4507 N (1.58× its FZMAX): its forces are held at FZMAX's there"), "{w}");
    }

    /// Each source's note is one sentence: what would settle it follows
    /// the last parenthesis after a `;`, never as a second one straight
    /// after it (round 51: "…offset) (a tyre fitted … closes it)").
    #[test]
    fn each_note_ends_in_one_clause_not_a_second_parenthesis() {
        let tir = LoadRangeOf::Tir {
            file: "small.tir".to_string(),
            axles: TyreAxles::Rear,
            limit_checks: false,
        };
        let ends = [
            (LoadRangeOf::Rig, "; rig data at the car's loads, or tyre files under [tyres], would tell the two apart"),
            (
                LoadRangeOf::Fitted {
                    file: "hoo.toml".to_string(),
                    axles: TyreAxles::Both,
                },
                "; a tyre fitted at the car's loads would tell the two apart",
            ),
            (tir, "; a tyre file whose range holds the car's loads would tell the two apart"),
        ];
        for (of, end) in ends {
            let w = note(&of, [414.2, 2887.4], [2995.0, 4507.0]);
            assert!(w.ends_with(&format!("a sensor's zero offset){end}")), "{w}");
            assert!(!w.contains(") ("), "{w}");
        }
    }
}
