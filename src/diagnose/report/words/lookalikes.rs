//! A verdict's look-alikes in words: each one's share and held-out gap
//! above noise beside those of what it stands in for, and the confounding
//! window they lie in with its terms (`1.5 × G + 0.25 × J_n = bound`), for
//! a single verdict ([`Lookalikes`]) and for a set's look-alikes fitted in
//! its place ([`InSet`]), and those set aside though in the window with
//! why ([`SetAside`]). Not "about as well": a look-alike that removes
//! 50 % against the verdict's 74 % can lie in the window. Gaps and held-out
//! errors are dimensionless, reductions in percent.

use crate::diagnose::effects::{joined, same_effects, EffectKind};
use crate::diagnose::report::outcome::CALIBRATION_AGREES;
use crate::diagnose::report::outcome::{
    Explained, InSet, Lookalike, Lookalikes, SetAside, StandstillBank, Window,
};
use crate::diagnose::report::Evidence;

/// A confounding window with its terms: `1.5 × 0.310 + 0.25 × 0.941 =
/// 0.700` (gaps above noise, dimensionless), so that a look-alike that
/// removes a visibly smaller share reads as what the rule holds it to.
pub fn window(w: &Window) -> String {
    format!(
        "{} × {:.3} + {} × {:.3} = {:.3}",
        crate::format::exact(w.gap_factor),
        w.gap,
        crate::format::exact(w.noise_factor),
        w.noise_level,
        w.bound
    )
}

/// The verdict sentence `head` of an effect `first` with look-alikes
/// alone ([`Lookalikes`]): each one's share and gap beside the share and
/// gap of the single the window is of, and the window, not "about as
/// well" (a look-alike may remove 50 % against the verdict's 74 % and
/// still lie in it). Those set aside ([`SetAside`]) are said with why,
/// not as confounded.
pub(super) fn alone(head: String, l: &Lookalikes, first: EffectKind) -> String {
    let each = |m: &Lookalike| {
        format!(
            "{} removes {:.1} % (gap above noise {:.3})",
            m.effect.name(),
            m.reduction_percent,
            m.gap
        )
    };
    let (alike, aside): (Vec<&Lookalike>, Vec<&Lookalike>) =
        l.members.iter().partition(|m| m.confounded());
    let against = format!(
        "against {}'s {:.1} % ({:.3}): within the confounding window of {}'s gap, {}",
        l.start.name(),
        l.start_reduction_percent,
        l.window.gap,
        l.start.name(),
        window(&l.window),
    );
    let mut out = head;
    if !alike.is_empty() {
        let it = if alike.len() == 1 { "it" } else { "them" };
        let each: Vec<String> = alike.iter().map(|m| each(m)).collect();
        out += &format!(
            "; but {} alone, {against}, so the runs do not tell {it} from {} (confounded)",
            each.join(", "),
            first.name()
        );
        for m in &alike {
            if let Some(b) = &m.standstills {
                out += &format!(
                    "; the standstills do not tell {} apart: {}",
                    m.effect.name(),
                    standstill_bank(b)
                );
            }
        }
    }
    for m in aside {
        let why = match (&m.set_aside, &m.standstills) {
            (Some(SetAside::StandstillsContradictBank), Some(b)) => format!(
                "the standstills contradict its bank: {}",
                standstill_bank(b)
            ),
            _ => String::new(),
        };
        out += &format!(
            "; {} alone, {against}, but {why}: set aside, not confounded",
            each(m)
        );
    }
    out
}

/// A bank-like look-alike's bank against the standstills, as a clause:
/// what they read, what its bank there would read (where the runs
/// determine it), and what the verdict's fit reads (m/s², banks in rad).
fn standstill_bank(b: &StandstillBank) -> String {
    let r = |v: f64| crate::format::rounded(v, 2);
    let logged = b
        .logged_bank
        .map_or(String::new(), |t| format!(", the logged bank {t:.4} rad"));
    let verdict = format!(
        "the verdict's fit {:.3} ± {} m/s² ({:.1})",
        b.verdict_predicted,
        r(b.verdict_predicted_std_error),
        b.verdict_standard_errors
    );
    let read = format!(
        "parked, they read {:.3} ± {} m/s²",
        b.measured,
        r(b.measured_std_error)
    );
    if !b.determined {
        return format!(
            "{read}; its bank there, {:.4} rad as fitted{logged}, is one of many the runs fit alike (its parameters not all determined), so no reading refutes it; {verdict}",
            b.bank
        );
    }
    format!(
        "{read}; its bank there, {:.4} rad{logged}, would read {:.3} ± {} m/s² ({:.1} standard errors off), {verdict}{}",
        b.bank,
        b.predicted,
        r(b.predicted_std_error),
        b.standard_errors,
        why_not(b)
    )
}

/// Why a determined reading sets nothing aside, where it does not.
fn why_not(b: &StandstillBank) -> &'static str {
    if !b.apart {
        ": the two predict alike"
    } else if b.standard_errors <= CALIBRATION_AGREES {
        ": its reading agrees"
    } else if b.verdict_standard_errors >= b.standard_errors {
        ": the verdict's reads as far off or further"
    } else {
        ""
    }
}

/// The verdict sentence `head` of a set `e` whose first effect `first`
/// (the single the set was grown from) has look-alikes fitted in the set
/// in its place ([`InSet`]): those whose gap lies in the set's window stay
/// confounded, the others the set tells apart; the window is said.
pub(super) fn in_set(head: String, e: &Explained, first: EffectKind) -> String {
    let (alike, apart): (Vec<&InSet>, Vec<&InSet>) = e.in_set.iter().partition(|s| s.confounded);
    let each = |v: &[&InSet]| {
        v.iter()
            .map(|s| {
                format!(
                    "{} removes {:.1} % (gap above noise {:.3})",
                    joined(&s.effects, "+"),
                    s.reduction_percent,
                    s.gap
                )
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    let names = |v: &[&InSet]| {
        let n: Vec<EffectKind> = v.iter().map(|s| s.effects[0]).collect();
        (joined(&n, ", "), n.len() == 1)
    };
    let set = joined(&e.effects, "+");
    let mut out = head;
    // The set took the place of a twin for parsimony: the single the set
    // was grown from is the twin's first effect, not its own.
    let grown = alike.iter().find(|s| {
        e.evidence.iter().any(
            |v| matches!(v, Evidence::ChosenForParsimony(p) if same_effects(&p.effects, &s.effects)),
        )
    });
    let whose = match grown {
        Some(g) => format!(
            "{} is the single the set was grown from, and {} took its place by the parsimony rule below",
            g.effects[0].name(),
            first.name()
        ),
        None => "the single the set was grown from".to_string(),
    };
    if let Some(w) = alike.first().map(|s| &s.window) {
        let (who, one) = names(&alike);
        out += &format!(
            "; but {who} in place of {} ({whose}): {}, against {set}'s {:.1} % ({:.3}): within the set's confounding window, {}, so the runs do not tell {} apart (confounded)",
            first.name(),
            each(&alike),
            e.reduction_percent,
            w.gap,
            window(w),
            if one { "the two" } else { "them" }
        );
    }
    if let Some(w) = apart.first().map(|s| &s.window) {
        let (who, one) = names(&apart);
        // The start said once: in the first clause that names it.
        let grown = match alike.is_empty() {
            true => " (the single the set was grown from)",
            false => "",
        };
        out += &format!(
            "; {who} alone {} in the confounding window of {} alone{grown}, but in its place in the set {}, against {set}'s {:.1} % ({:.3}): outside the set's confounding window, {}, so the set tells them apart",
            if one { "lies" } else { "lie" },
            first.name(),
            each(&apart),
            e.reduction_percent,
            w.gap,
            window(w)
        );
    }
    out
}
