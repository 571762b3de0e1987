//! A fitted effect parameter in words: its value and unit with its
//! standard error, or the bound it stands on, or why it is held or not
//! determined. Values in the parameter's own unit (SI, rad; a steering
//! compliance in rad/kN with rad/N beside it); a dimensionless parameter
//! (unit `-`) is written without one. A value per radian of roll is said
//! at the roll gradient it holds at, with its product with that gradient,
//! what the runs determine (`per_roll.rs`).

use super::fold_words::apart;
use super::{std_error, value};
use crate::diagnose::effects::Bound;
use crate::diagnose::effects::PerRoll;
use crate::diagnose::report::{ParameterValue, PerLateralAcceleration, StdErrorBasis};

/// A parameter on the end of its search range, to four decimals: its
/// name, value and unit (a ratio's unit, `-`, not written).
pub(super) fn on_bound(p: &ParameterValue) -> String {
    let unit = match p.unit {
        "" | "-" => String::new(),
        unit => format!(" {unit}"),
    };
    // One near its bound, not on it, says how near.
    let near = p.near_search_bound().map_or(String::new(), |n| {
        let within = match n.by_std_error {
            true => format!("its standard error, {}{unit}", std_error(p.std_error)),
            false => "1 % of its range".to_string(),
        };
        let bound = crate::format::rounded(n.bound, 6);
        format!(" (its bound {bound}{unit} lies within {within})")
    });
    format!("{} = {:.4}{unit}{near}", p.name, p.value)
}

/// The parameters on their search bound in a verdict's warning: an
/// effect's own parameter there bounds the effect's size; the roll
/// dynamics (`roll.frequency`, `roll.damping`) are the body's roll mode
/// the roll effects act through, shared by them, not any effect's size,
/// and are said so. One sentence per kind, joined by `; `.
pub fn on_search_bound(parameters: &[ParameterValue]) -> String {
    let (roll, own): (Vec<&ParameterValue>, Vec<&ParameterValue>) =
        parameters.iter().partition(|p| p.name.starts_with("roll."));
    let said = |ps: &[&ParameterValue], reading: &str| {
        let each: Vec<String> = ps.iter().map(|p| on_bound(p)).collect();
        let one = ps.len() == 1;
        format!(
            "{} on {} search bound: the data would take {} further, so {reading}",
            each.join(", "),
            if one { "its" } else { "their" },
            if one { "it" } else { "them" },
        )
    };
    let mut parts = Vec::new();
    if !own.is_empty() {
        let values = if own.len() == 1 {
            "its value is"
        } else {
            "their values are"
        };
        parts.push(said(
            &own,
            &format!("{values} a bound on the effect's size, not a measurement of it"),
        ));
    }
    if !roll.is_empty() {
        let (it, is) = if roll.len() == 1 {
            ("it", "is")
        } else {
            ("they", "are")
        };
        parts.push(said(
            &roll,
            &format!("{it} {is} a bound on the body's roll mode, which the roll effects act through (not the effect's size): the effect's values are fitted through a roll mode at that limit, and the runs do not measure the mode"),
        ));
    }
    parts.join("; ")
}

/// A fitted parameter in words: its value, unit and standard error; or
/// the bound it stands on — a search bound (the data would take it
/// further) or a physical limit (a length, a share, a load that would be
/// negative beyond it); or, where the standard error is missing or larger
/// than the parameter's whole range, that the runs do not determine it;
/// or that it is held at its off value (no measured channel responds to
/// it, or fitted free the runs did not determine it). A steering
/// compliance, fitted in rad/kN, is given in rad/N too: the unit of
/// `steering_compliance` in a scenario's `[model.effects]`. A standard
/// error that the fold refits' jackknife exceeds several times over is said
/// to understate ([`ParameterValue::understated`]).
pub fn parameter(p: &ParameterValue) -> String {
    parameter_of(p, true)
}

/// A fitted parameter in words ([`parameter`]), of a candidate that
/// `removes` a share of a significant gap or not (a gap within noise): where it
/// does not, a fold scatter beyond the standard error is no disagreement of
/// the runs beyond their noise to claim (a no-effect campaign's candidates
/// fit noise), only a standard error that understates.
pub fn parameter_of(p: &ParameterValue, removes: bool) -> String {
    let traded = traded_of(p, removes);
    match &p.per_lateral_acceleration {
        Some(a) => format!("{traded}{}", at_roll_gradient(p, a)),
        None => traded,
    }
}

/// [`parameter_alone`] with what a pair that trades adds.
fn traded_of(p: &ParameterValue, removes: bool) -> String {
    let alone = parameter_alone(p, removes);
    let Some(t) = &p.traded else {
        return alone;
    };
    // A pair that trades: their sum is what the runs determine (a delay
    // and a lag: the steer path's equivalent delay).
    let unit = if p.unit == "-" { "" } else { p.unit };
    let what = if p.unit == "s" {
        "the equivalent delay, "
    } else {
        ""
    };
    let folds = t.sum_fold_std_error.map_or(String::new(), |j| {
        format!(
            "; the fold refits scatter the sum ± {} {unit}",
            std_error(j)
        )
    });
    format!(
        "{alone} (correlation {:+.2} with {}: the runs determine their sum, {what}{} ± {} {unit}, {}{folds})",
        t.correlation,
        t.with,
        value(t.sum),
        std_error(t.sum_std_error),
        if t.split_undetermined {
            "not how it splits between them"
        } else {
            "better than either"
        }
    )
}

/// What a value per radian of roll is said with: the stated roll gradient
/// it holds at, in °/g, and where (`[roll] gradient`, file:line), that it
/// scales inversely with it, and the product the runs determine, per m/s²
/// and per g, with its standard error where the value has one and stands
/// off its bounds (the gradient held).
fn at_roll_gradient(p: &ParameterValue, a: &PerLateralAcceleration) -> String {
    let k = &a.roll_gradient;
    let stated = match (&k.file, k.line) {
        (Some(file), Some(line)) => format!(
            "the stated roll gradient of {}°/g (`[roll] gradient` = {}, {}:{line})",
            crate::format::readable(k.degrees_per_g(), 3),
            crate::format::exact(k.gradient),
            file.display()
        ),
        _ => format!(
            "the default roll gradient of {}°/g (the campaign states no `[roll] gradient`)",
            crate::format::readable(k.degrees_per_g(), 3)
        ),
    };
    let logged = match k.runs_logging_roll {
        0 => "no run logs roll to measure it".to_string(),
        1 => "the one run's logged roll levels its ay and measures no gradient".to_string(),
        n => format!("the roll logged in {n} runs levels their ay and measures no gradient"),
    };
    let axle = p.name.rsplit('.').next().unwrap_or_default();
    let what = match a.quantity {
        PerRoll::Steer => format!("rad of {axle} steer per m/s² of ay"),
        PerRoll::CamberThrust => format!("N/N of {axle} camber thrust per m/s² of ay"),
    };
    let per_g = match a.quantity {
        PerRoll::Steer => "°/g",
        PerRoll::CamberThrust => " N/N per g",
    };
    let fitted = !p.unseen && p.held.is_none() && p.bound.is_none() && p.determined;
    let product = if fitted && a.std_error.is_finite() {
        format!(
            "{} ± {} {what} ({} ± {}{per_g})",
            value(a.value),
            std_error(a.std_error),
            crate::format::readable(a.per_g(a.value), 3),
            std_error(a.per_g(a.std_error)),
        )
    } else {
        format!(
            "{} {what} ({}{per_g})",
            value(a.value),
            crate::format::readable(a.per_g(a.value), 3)
        )
    };
    format!(
        " at {stated}, which the diagnosis holds ({logged}): the value scales inversely with that gradient, and the runs determine only its product with it, {product}"
    )
}

/// [`parameter_of`] without what a pair that trades adds.
fn parameter_alone(p: &ParameterValue, removes: bool) -> String {
    // A dimensionless parameter (unit `-`) is written without a unit.
    let unit = match p.unit {
        "rad/kN" => format!(" rad/kN ({} rad/N)", value(p.value * 1e-3)),
        "-" => String::new(),
        u => format!(" {u}"),
    };
    // A standard error in the parameter's own unit ([`std_error`]).
    let se = |x: f64| {
        let u = if p.unit == "-" { "" } else { p.unit };
        format!("{}{}{u}", std_error(x), if u.is_empty() { "" } else { " " })
    };
    let v = value(p.value);
    if p.unseen {
        return format!(
            "{} = {v}{unit} (held at its off value: no measured channel responds to it)",
            p.name
        );
    }
    if let Some(free) = p.held {
        // The roll dynamics' off value is the campaign's `[roll]`.
        let at = if p.name.starts_with("roll.") {
            "the campaign's value"
        } else {
            "its off value"
        };
        return format!(
            "{} = {v}{unit} (held at {at}: the runs do not determine it, fitted free its standard error {} exceeds its whole range)",
            p.name, se(free)
        );
    }
    let Some(bound) = p.bound else {
        return if p.determined {
            determined(p, removes, &v, &unit) + &apart(p, removes)
        } else if p.std_error.is_finite() {
            format!(
                "{} = {v}{unit} (not determined by the runs: its standard error {} exceeds its whole range)",
                p.name, se(p.std_error)
            )
        } else {
            // No standard error: the runs cannot see it (a channel they
            // lack, a parameter pinned by another).
            format!(
                "{} = {v}{unit} (no standard error: not determined by the runs)",
                p.name
            )
        };
    };
    let why = match bound {
        Bound::Search => "at its search bound: the data would take it further",
        // Every lower physical limit is 0 (a length, a delay, a share, a
        // down-force); the upper ones are a share's 1: a value on one is
        // within a hair of 0 or of 1.
        Bound::Physical if p.value < 0.5 => {
            "at its physical limit: any smaller value would be negative"
        }
        Bound::Physical => "at its physical limit: a share cannot exceed 1",
    };
    // On a physical limit the value is the limit, written as such: within
    // the limit's resolution no data tell it from the limit, and a lag of
    // 4e-5 s written `3.959e-5 s` beside another's `0.0000 s` read as two
    // different findings.
    let v = match (bound, p.effect_parameter.map(|q| q.bounds)) {
        (Bound::Physical, Some((lo, hi))) if p.value - lo < hi - p.value => value(lo),
        (Bound::Physical, Some((_, hi))) => value(hi),
        _ => v,
    };
    format!("{} = {v}{unit} ({why})", p.name)
}

/// A determined parameter `p` off its bounds, its value `v` written with
/// its `unit`: with its standard error, and where the fold refits scatter
/// beyond what the asymptotic error covers, by how much and what that says
/// (`removes`: the effect removes something significant).
fn determined(p: &ParameterValue, removes: bool, v: &str, unit: &str) -> String {
    let se = p.asymptotic_std_error;
    let spread = p.std_error_basis == StdErrorBasis::FoldSpread;
    // Never rounded coarser than the error it leads with.
    let led = match p.fold_std_error.filter(|_| p.understated()) {
        Some(_) if spread => p.std_error,
        _ => se,
    };
    let v = &crate::format::finer_than_error(v, p.value, led);
    let said = format!("{} = {v} ± {}{unit}", p.name, std_error(se));
    let yardstick = p.fold_yardstick();
    match p.fold_std_error.filter(|_| p.understated()) {
        // The verdict stands on the fold refits' spread: the words
        // lead with it, as the JSON's `std_error` does, and give
        // the asymptotic error in the parenthesis.
        Some(j) if spread && !removes => format!(
            "{} = {v} ± {}{unit} (the fold refits' spread, {:.0}× the asymptotic ± {}: the asymptotic error understates its uncertainty, of a value fitted where the effect removes nothing significant)",
            p.name,
            std_error(p.std_error),
            j / se,
            std_error(se)
        ),
        Some(j) if spread => format!(
            "{} = {v} ± {}{unit} (the fold refits' spread, {:.0}× the asymptotic ± {}{}: the runs disagree beyond their noise, which the asymptotic error does not cover)",
            p.name,
            std_error(p.std_error),
            j / se,
            std_error(se),
            if yardstick <= se {
                String::new()
            } else {
                format!(
                    " and {:.0}× the ± {} the runs' noise alone moves them by, leaving out a run that carries much of what determines it",
                    j / yardstick,
                    std_error(yardstick)
                )
            }
        ),
        // The runs of equal information: the standard error is
        // what their noise moves the folds by.
        Some(j) if !removes => format!(
            "{said} (the fold refits scatter ± {}, {:.0}× {}: the standard error understates its uncertainty, of a value fitted where the effect removes nothing significant)",
            std_error(j),
            j / yardstick,
            if yardstick <= se {
                "it".to_string()
            } else {
                format!("the ± {} the runs' noise alone moves them by", std_error(yardstick))
            }
        ),
        Some(j) if yardstick <= se => format!(
            "{said} (the fold refits scatter ± {}, {:.0}× it: the runs disagree beyond their noise, which the standard error does not cover)",
            std_error(j),
            j / se
        ),
        Some(j) => format!(
            "{said} (the fold refits scatter ± {}, {:.0}× the ± {} the runs' noise alone moves them by, leaving out a run that carries much of what determines it: the runs disagree beyond their noise, which the standard error does not cover)",
            std_error(j),
            j / yardstick,
            std_error(yardstick)
        ),
        // The model leaves a gap above noise and the refits scatter
        // beyond the asymptotic error, though not beyond chance:
        // the larger is the one reported.
        None if p.std_error_basis == StdErrorBasis::FoldSpread => format!(
            "{} = {v} ± {}{unit} (the fold refits' spread: its held-out error stays above the noise level, and its asymptotic ± {} covers the noise alone)",
            p.name,
            std_error(p.std_error),
            std_error(se)
        ),
        None => said,
    }
}
