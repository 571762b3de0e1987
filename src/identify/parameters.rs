//! The per-parameter part of a fit's report: each parameter's value,
//! standard error and the warning a tyre engineer needs when the data do
//! not fix it (on or past its search bound, a standard error larger than
//! the value, or a direction of the fit the data leave undetermined).

use super::{Channel, ParameterReport, Spread};
use crate::format::{readable, rounded};
use crate::optim::bounded::LIMIT_RESOLUTION;
use crate::tyre::{Parameterised, Tyre};
use nalgebra::DMatrix;

/// The fraction of the channel's RMS one standard error must move it by
/// for the parameter to count as not determined (the staged fit's floor).
pub(super) const EFFECT_FLOOR: f64 = 0.01;

/// One report per parameter of `channel`: value, whether it was free, its
/// standard error and effect from `spread` (over the free ones, in order)
/// and a warning when it sits at a bound or the data cannot identify it.
pub(super) fn parameter_reports(
    start: &Tyre,
    tyre: &Tyre,
    channel: Channel,
    free: &[bool],
    spread: &Spread,
) -> Vec<ParameterReport> {
    let covariance = spread.covariance.as_ref();
    let all_bounds = channel.bounds(start);
    let values = channel.parameters(tyre);
    let traded = undetermined_names(start, channel, free, covariance);
    // Only the lateral block's vector carries the model's physical floors.
    let floors = match channel {
        Channel::LateralForce => start.physical_floors(),
        _ => Vec::new(),
    };
    let mut k = 0;
    let mut parameters = Vec::new();
    for (i, name) in channel.names(start).iter().enumerate() {
        let (lo, hi) = all_bounds[i];
        let mut rep = ParameterReport {
            name: name.to_string(),
            value: values[i],
            free: free[i],
            held: None,
            std_error: None,
            effect_percent: None,
            bounds: (lo, hi),
            warning: None,
            determination: None,
            note: None,
        };
        if free[i] {
            let se = covariance
                .map(|c| c[(k, k)])
                .filter(|v| v.is_finite())
                .map(|v| v.max(0.0).sqrt());
            rep.std_error = se;
            rep.effect_percent = se.map(|_| 100.0 * spread.effect[k]);
            let floor = floors.get(i).copied().flatten();
            match floor.filter(|_| on_floor(values[i], (lo, hi), spread.pull[k])) {
                Some(why) => rep.note = Some(at_floor(lo, why)),
                None => {
                    rep.warning = warning(name, values[i], (lo, hi), se, &traded);
                    // On its bound, its standard error means nothing: the
                    // bound's warning stands however little it moves the
                    // fit (unbinned, GIM's decay of 5.37e-18 on the Hoosier
                    // file was said free, binned on its bound).
                    if !on_search_bound(values[i], (lo, hi)) {
                        hardly_felt(&mut rep);
                    }
                }
            }
            k += 1;
        }
        parameters.push(rep);
    }
    parameters
}

/// Whether `v` in its box `(lo, hi)`, whose lower end is a physical
/// limit, stands on it as a fit: within [`LIMIT_RESOLUTION`] of it, and
/// the data's own step from it (`pull`, [`Spread::pull`]) not past it by
/// more (a GIM decay on rig data whose friction rises with slip is pulled
/// below 0: stopped there, still said as on its bound, not a fit).
fn on_floor(v: f64, (lo, hi): (f64, f64), pull: f64) -> bool {
    let near = LIMIT_RESOLUTION * (hi - lo);
    v >= lo && v - lo <= near && v + pull >= lo - near
}

/// The note on a parameter at its physical limit `lo`, `why` beyond it
/// is no tyre.
fn at_floor(lo: f64, why: &str) -> String {
    format!(
        "at its physical limit {} ({why}): the data fit best there and do not pull it past; a fit, not a search stopped",
        rounded(lo, 6)
    )
}

/// A warned parameter `rep` whose standard error passes its value but
/// moves the fit by under [`EFFECT_FLOOR`] of the channel's RMS: inside
/// its box, said as a note, not warned of (the rule that holds what the
/// data do not determine passes it by, `undetermined.rs`, and the staged
/// Magic Formula fit does not flag it either); past its box, the warning
/// stands with the effect added.
fn hardly_felt(rep: &mut ParameterReport) {
    let floor = 100.0 * EFFECT_FLOOR;
    let (Some(e), Some(s)) = (rep.effect_percent, rep.std_error) else {
        return;
    };
    if e >= floor || s <= rep.value.abs() {
        return;
    }
    let effect = format!(
        "one standard error of it alone moves the fit by only {} % of the channel's RMS (under the {floor} % that would have it held)",
        crate::format::decimals_or_digits(e, 1, 2)
    );
    let (lo, hi) = rep.bounds;
    match (rep.warning.take(), (lo..=hi).contains(&rep.value)) {
        (Some(_), true) => {
            rep.note = Some(format!(
                "its standard error {} is larger than its value, but {effect}: left free, as what it leaves unsettled the fit hardly shows",
                readable(s, 3)
            ));
        }
        (Some(w), false) => {
            rep.warning = Some(format!(
                "{w}, but {effect}: what it leaves unsettled the fit hardly shows"
            ));
        }
        (None, _) => {}
    }
}

/// The free parameters of `channel` that the covariance leaves without a
/// standard error (NaN on its diagonal: [`crate::optim::stats::covariance`] marks those
/// along a direction where JᵀJ is singular), in order.
fn undetermined_names(
    start: &Tyre,
    channel: Channel,
    free: &[bool],
    covariance: Option<&DMatrix<f64>>,
) -> Vec<String> {
    let Some(c) = covariance else {
        return Vec::new();
    };
    channel
        .names(start)
        .iter()
        .zip(free)
        .filter(|(_, f)| **f)
        .enumerate()
        .filter(|(k, _)| c[(*k, *k)].is_nan())
        .map(|(_, (n, _))| n.to_string())
        .collect()
}

/// Whether `v` stands on an end of its search box `(lo, hi)`: inside it
/// and within a millionth of its width of the end, a value the rounding
/// of the polish leaves there (GIM's `friction_decay` of 5.37e-18 in its
/// box 0 to 1) being the bound, as the rule that holds what the data do
/// not determine reads it (`undetermined.rs`).
pub(super) fn on_search_bound(v: f64, (lo, hi): (f64, f64)) -> bool {
    let near = 1e-6 * (hi - lo);
    (lo..=hi).contains(&v) && (v <= lo + near || v >= hi - near)
}

/// The warning on a free parameter `name` of value `v` in its search box
/// `(lo, hi)` with standard error `se`, `traded` naming the parameters
/// left without one ([`undetermined_names`]); `None` when the data fix it.
/// A value the data do not determine (no standard error, or one larger
/// than the value) is said to be so whether or not it lies past its box:
/// past it, the polish drifted there, the data did not take it there.
fn warning(
    name: &str,
    v: f64,
    (lo, hi): (f64, f64),
    se: Option<f64>,
    traded: &[String],
) -> Option<String> {
    let beyond = v < lo || v > hi;
    // Six significant digits: a box of `c ± (5|c| + 1)` printed exactly
    // read `-1.0160799999999999`.
    let bounds = format!("{} to {}", rounded(lo, 6), rounded(hi, 6));
    // On its bound, the value is where the box stopped the fit (the polish
    // stays in the box): said first, before its standard error, which a
    // bound makes meaningless.
    if on_search_bound(v, (lo, hi)) {
        return Some(format!(
            "on its search bound ({bounds}): the fit would take it beyond; the value is the bound, not a fit"
        ));
    }
    let drift = if beyond {
        format!("; the polish drifted past its search bound ({bounds})")
    } else {
        String::new()
    };
    match se {
        // The covariance marks the parameters along a direction where JᵀJ
        // is singular: the data fix only a combination of them, so a value
        // past the box is one of many that fit alike, not one the data ask
        // for.
        None if traded.len() > 1 => {
            let others: Vec<&str> = traded
                .iter()
                .filter(|n| n.as_str() != name)
                .map(String::as_str)
                .collect();
            Some(format!(
                "not identified by the data: it trades off with {} (the Jacobian at the fit is singular along a direction they share, so only a combination of them is determined and there is no standard error){drift}{}",
                others.join(", "),
                if beyond { " along that direction" } else { "" }
            ))
        }
        None => Some(format!(
            "not identified by the data: no standard error (the Jacobian at the fit is singular along it){drift}"
        )),
        Some(s) if !s.is_finite() || s > v.abs().max(1e-12) => Some(format!(
            "not identified by the data: its standard error {} is larger than its value{drift}",
            readable(s, 3)
        )),
        Some(_) if beyond => Some(format!(
            "beyond its search bound ({bounds}) after the polish: the data take it past the box"
        )),
        Some(_) => None,
    }
}

/// A fit of `tyre` (fitted to `problem`, `from`'s free parameters free)
/// carrying `from`'s holds: each parameter's value and standard error
/// from the Jacobian at `tyre` (reported against `start`'s bounds), those
/// `from` held held alike with their words, its σ, RMS and curves over
/// `conditions`; the rest (seed, work, swarm σ) `from`'s.
pub(super) fn fit_carrying_holds(
    tyre: Tyre,
    start: &Tyre,
    problem: &super::FitProblem,
    conditions: &[super::data::Condition],
    from: &super::Fit,
) -> super::Fit {
    let channel = problem.channel;
    let mask: Vec<bool> = from.parameters.iter().map(|p| p.free).collect();
    let all = channel.parameters(&tyre);
    let p: Vec<f64> = problem.free.iter().map(|&i| all[i]).collect();
    let spread = Spread::at(problem, &p);
    let mut parameters = parameter_reports(start, &tyre, channel, &mask, &spread);
    for (new, old) in parameters.iter_mut().zip(&from.parameters) {
        if !old.free {
            new.held = old.held;
            new.warning.clone_from(&old.warning);
        }
    }
    let (sigma_percent, rms) = super::sigma_of(channel, &tyre, &problem.points);
    super::Fit {
        curves: super::curves_of(channel, &tyre, conditions),
        parameters,
        sigma_percent,
        rms,
        covariance: spread.covariance,
        tyre,
        ..from.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parameters_without_standard_error_are_named_as_traded_not_data_driven() {
        // PAC89's TTC fit: a0 (C) 0.0068 with a1, a2 (D's load law) huge,
        // none with a standard error: only C·D is determined.
        let traded: Vec<String> = ["a0", "a1", "a2"].map(String::from).into();
        let w = warning("a0", 0.006819, (1.0, 2.0), None, &traded).unwrap();
        assert!(
            w.starts_with("not identified by the data: it trades off with a1, a2 ("),
            "{w}"
        );
        assert!(w.contains("there is no standard error"), "{w}");
        assert!(
            w.ends_with("past its search bound (1 to 2) along that direction"),
            "{w}"
        );
        assert!(!w.contains("the data take it past the box"), "{w}");
        // With a standard error, past the box is the data's doing.
        let w = warning("a0", 2.4, (1.0, 2.0), Some(0.01), &[]).unwrap();
        assert!(w.contains("the data take it past the box"), "{w}");
        // A standard error larger than the value: not the data's doing,
        // past the box or not (UniTire's aligning c8 of 3354.6, ± 8.9e6).
        let w = warning("c8", 3354.6, (0.1, 100.0), Some(8.9e6), &[]).unwrap();
        assert_eq!(
            w,
            "not identified by the data: its standard error 8.9e6 is larger than its value; the polish drifted past its search bound (0.1 to 100)"
        );
        let w = warning("a9", 0.0022, (-1.0, 1.0), Some(0.003), &[]).unwrap();
        assert_eq!(
            w,
            "not identified by the data: its standard error 0.00300 is larger than its value"
        );
        // No standard error, alone (UniTire's longitudinal p2 of 6473).
        let w = warning("p2", 6473.0, (0.1, 100.0), None, &[]).unwrap();
        assert!(
            w.starts_with("not identified by the data: no standard error"),
            "{w}"
        );
        assert!(w.ends_with("past its search bound (0.1 to 100)"), "{w}");
        // On its bound, that is said whatever its standard error.
        let w = warning("a0", 1.0, (1.0, 2.0), None, &traded).unwrap();
        assert!(w.starts_with("on its search bound (1 to 2)"), "{w}");
        // A PAC89 box of c ± (5|c| + 1) about c = 0.00402 printed
        // `-1.0160799999999999`: six digits.
        let (lo, hi) = (0.00402 - 5.0 * 0.00402 - 1.0, 0.00402 + 5.0 * 0.00402 + 1.0);
        let w = warning("b6", lo, (lo, hi), None, &[]).unwrap();
        assert!(
            w.starts_with("on its search bound (-1.01608 to 1.02412)"),
            "{w}"
        );
        // A well-determined value inside the box carries no warning.
        assert_eq!(warning("a3", 894.7, (-2e3, 2e3), Some(11.7), &[]), None);
    }

    /// A value within rounding of its bound is on it, whatever its
    /// standard error: GIM's `friction_decay` of 5.37e-18 ± 0.0884 on the
    /// Hoosier file unbinned, 0 binned.
    #[test]
    fn a_value_within_rounding_of_its_bound_is_on_it() {
        for v in [0.0, 5.37e-18, 9e-7] {
            assert!(on_search_bound(v, (0.0, 1.0)), "{v}");
            let w = warning("friction_decay", v, (0.0, 1.0), Some(0.0884), &[]).unwrap();
            assert!(w.starts_with("on its search bound (0 to 1)"), "{v}: {w}");
        }
        assert!(on_search_bound(1.0 - 1e-9, (0.0, 1.0)));
        // Past the box, or clear of its ends, it is not.
        assert!(!on_search_bound(-1e-3, (0.0, 1.0)));
        assert!(!on_search_bound(2e-6, (0.0, 1.0)));
    }
}
