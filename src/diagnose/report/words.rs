//! The diagnosis in words: every sentence the terminal, `diagnosis.json`'s
//! strings (`verdict.statement`, `verdict.warnings`, `ranking[].warning`,
//! `notes`, `gap.summary`, `base.tyres`, `base.axles.degenerate`,
//! `confounded[].separating_test`), the page, the fleet table and Python
//! show is made here from the typed outcome ([`super::outcome`]); nothing
//! else words them, and no rule reads them.
//!
//! Values keep their units (SI, rad; slip angles of a peak in degrees, as
//! tyre engineers read them); J is dimensionless, reductions in percent.

mod axles;
mod causes;
mod class;
use class::{NO_VERDICT, OUTSIDE};
mod evidence;
mod fold_words;
mod gap;
mod left_in;
mod lookalikes;
mod parameters;
mod rank;
mod runs_left;
mod table;
mod trust;
mod tyre_loads;
mod warnings;
pub use crate::diagnose::report::shares::carries_line as channel_shares;
use crate::identify::grouping::Variable;
pub use axles::{
    axle_values, axles_line, limit_meaning, no_tyre, no_tyre_list, prior_line, tyre_source,
};
pub use evidence::evidence;
pub use gap::band_lines;
pub use left_in::runs_left;
pub use lookalikes::window;
use lookalikes::{alone, in_set};
pub use parameters::{parameter, parameter_of};
pub use rank::{rank_warning, rank_warnings};
pub use table::{added, channel_change, channels_alone, reduction, rms, unchanged, within_noise};
pub use trust::{
    assumed_floor, channel_change_judged, channel_trust, channels_trusted, channels_trusted_for,
    judged_apart, Reader,
};
pub use warnings::{effect_parameters_on_bound, verdict_warning};

use crate::diagnose::effects::{joined, EffectKind};
use crate::diagnose::report::outcome::{
    Extent, GapFinding, NotIdentifiable, Note, OutsideLibrary, Refusal, Refused, Verdict,
    SIGNIFICANT_GAP,
};
use crate::diagnose::report::Confounded;
use crate::format::signed;

impl Verdict {
    /// The verdict in one sentence ([`statement`]; written here, beside
    /// the other sentences, so that the types do not read their words).
    pub fn statement(&self) -> String {
        statement(self)
    }
}

/// The verdict in one sentence.
pub fn statement(v: &Verdict) -> String {
    match v {
        Verdict::Explained(e) => {
            let left: Vec<&str> = e.channels_left().iter().map(|c| c.name()).collect();
            let head = format!(
                "{} explains {}the gap{}: held-out error {:.3} → {:.3} (noise level {:.3}), {:.1} % of the gap above noise removed",
                joined(&e.effects, "+"),
                // "The gap" only where what is left is noise: 53 % said
                // as "explains the gap" above "the other 47 % is a
                // further cause" read as a contradiction.
                match e.extent() {
                    Extent::Part => "part of ",
                    Extent::Most => "most of ",
                    Extent::All => "",
                },
                if left.is_empty() {
                    String::new()
                } else {
                    format!(" but not its {} part", left.join(" and "))
                },
                e.heldout_error_before,
                e.heldout_error_after,
                e.noise_level,
                e.reduction_percent
            );
            let head = if e.partial() {
                partial_rest(head, e)
            } else {
                head
            };
            // A parameter on its search bound: the verdict names the
            // effect at its range's end, not a measurement of it.
            let head = head + &warnings::bound_clause(&e.warnings);
            match (&e.confounded_with, e.effects.first()) {
                (_, Some(first)) if !e.in_set.is_empty() => in_set(head, e, *first),
                (Some(l), Some(first)) => alone(head, l, *first),
                _ => head,
            }
        }
        Verdict::NoSignificantGap(n) => trust::no_gap(n),
        Verdict::NotIdentifiable(n) => not_identifiable(n),
        Verdict::OutsideLibrary(o) => outside(o),
    }
}

/// What a verdict that explains part of the gap leaves, after its head:
/// a rest no candidate explains, or, where the held-out error left is
/// within [`SIGNIFICANT_GAP`] of the noise level, a rest not shown to be a
/// gap at all (round 39: two runs, a delay recovered to 0.0492 s of 0.05,
/// "the other 55.6 % no candidate explains" at 1.26 × the noise level,
/// where the same rest after most of a gap would draw no warning).
fn partial_rest(head: String, e: &super::outcome::Explained) -> String {
    let rest = 100.0 - e.reduction_percent;
    let ratio = e.heldout_error_after / e.noise_level;
    if e.noise_level > 0.0 && ratio <= SIGNIFICANT_GAP {
        format!(
            "{head}; the other {rest:.1} % is not shown to be a gap: the held-out error left is {} × the noise level, within the {SIGNIFICANT_GAP} × a gap must exceed (more or longer runs would tell a further cause from noise)",
            crate::format::fixed(ratio, 2)
        )
    } else {
        format!("{head}; the other {rest:.1} % no candidate explains")
    }
}

fn not_identifiable(n: &NotIdentifiable) -> String {
    let closest = if let Some(c) = &n.tyre_class {
        class::class_mismatch(c)
    } else if let (true, Some(narrowed)) = (n.closest.is_empty(), &n.narrowed) {
        format!(
            "no candidate fitted with it makes the axles a tyre{}",
            class::untried(narrowed)
        )
    } else if n.closest.is_empty() {
        "no candidate fitted with it makes the axles a tyre: what bent them is outside the library"
            .to_string()
    } else {
        let each: Vec<String> = n
            .closest
            .iter()
            .map(|c| {
                format!(
                    "{} (removes {:.1} %)",
                    joined(&c.effects, "+"),
                    c.reduction_percent
                )
            })
            .collect();
        format!(
            "the candidates that make the axles a tyre, fitted jointly, come closest: {}",
            each.join(", ")
        )
    };
    // A stated road friction scales the grip the axles are identified
    // with: one off the truth bends them, and the user can check it.
    let road = n.road_friction.map_or(String::new(), |r| {
        format!(
            "; the campaign states `[road] friction = {}` (line {}), a scale on the grip that trades off with the axles' peak friction identified from the runs: a road friction off the truth bends them out of any tyre's range (check it, or leave it out for 1)",
            crate::format::exact(r.value),
            r.line
        )
    });
    format!(
        "the base model is not identifiable from these runs: {}; no candidate effect fitted with it gives axles that are a tyre and removes {:.0} % of the gap (held-out error {:.3}, noise level {:.3}), so there is no model-form verdict; {closest}{road}",
        no_tyre_list(&n.no_tyre),
        n.threshold_percent,
        n.heldout_error,
        n.noise_level
    )
}

/// What a share `percent` of the gap removed says: none where it rounds
/// to 0 or below (not "removes -0.0 %" or "removes -0.5 %"), with how
/// much larger it leaves the gap where it does.
fn removal(percent: f64) -> String {
    if percent >= 0.05 {
        format!("removes {percent:.1} % of it")
    } else if percent > -0.05 {
        "removes none of it".into()
    } else {
        format!(
            "removes none of it (it leaves the held-out gap {:.1} % larger)",
            -percent
        )
    }
}

/// A gap no candidate is accepted for. Where the best removes less than
/// the acceptance share and fails nothing else, no candidate explains it:
/// a model-form error outside the library, and the sentence adds any
/// other rule it fails. Where it removes enough but fails another rule,
/// the sentence says which, and never that nothing explains the gap.
fn outside(o: &OutsideLibrary) -> String {
    let s = class::with_class(outside_alone(o), o.tyre_class.as_ref());
    let s = match &o.narrowed {
        Some(n) => class::narrowed(s, n),
        None => s,
    };
    s + &runs_left::outside_bearing(o)
}

fn outside_alone(o: &OutsideLibrary) -> String {
    let gap = format!(
        "a gap (held-out error {:.3}, noise level {:.3})",
        o.heldout_error, o.noise_level
    );
    let Some(best) = &o.refused else {
        return format!(
            "{gap} that no candidate effect explains: no candidate was scored{OUTSIDE}"
        );
    };
    let name = joined(&best.effects, "+");
    if let [Refusal::BelowAcceptance { threshold_percent }] = best.why[..] {
        return format!(
            "{gap} that no candidate effect explains: the best, {name}, {} (acceptance needs {threshold_percent:.0} %){OUTSIDE}",
            removal(best.reduction_percent)
        );
    }
    // Below the share and failing more: the share once, then the rest
    // (not "removes 20 % (acceptance needs 30 %) but is refused: it
    // removes less than the 30 % acceptance needs; …").
    let below = |r: &Refusal| matches!(r, Refusal::BelowAcceptance { .. });
    if best.why.iter().any(below) {
        let rest: Vec<String> = best.why.iter().filter(|r| !below(r)).map(refusal).collect();
        return format!(
            "{gap} that no candidate effect explains: the best, {name}, {}, less than the {:.0} % acceptance needs, and besides {}{OUTSIDE}",
            removal(best.reduction_percent),
            o.threshold_percent,
            rest.join("; ")
        );
    }
    format!(
        "{gap} for which no candidate effect is accepted: the best, {name}, {} (acceptance needs {:.0} %) but is refused: {}{NO_VERDICT}",
        removal(best.reduction_percent),
        o.threshold_percent,
        refusals(best)
    )
}

/// Why a candidate is refused: its failed rules joined by "; ".
pub fn refusals(r: &Refused) -> String {
    let why: Vec<String> = r.why.iter().map(refusal).collect();
    if why.is_empty() {
        "not accepted by the search".into()
    } else {
        why.join("; ")
    }
}

/// One failed rule.
pub fn refusal(r: &Refusal) -> String {
    let other = |x: &Refused| {
        format!(
            "{}, which removes {:.1} % and is refused: {}",
            joined(&x.effects, "+"),
            x.reduction_percent,
            refusals(x)
        )
    };
    match r {
        Refusal::BelowAcceptance { threshold_percent } => {
            format!("it removes less than the {threshold_percent:.0} % acceptance needs")
        }
        Refusal::BicNotLower { delta_bic } => {
            format!(
                "its BIC is not lower than the base model's (ΔBIC {})",
                signed(*delta_bic, 0)
            )
        }
        Refusal::AxlesNoTyre { no_tyre } => format!(
            "fitted with it, the axles are no tyre ({})",
            no_tyre_list(no_tyre)
        ),
        Refusal::LeavesParameterIdle { simpler } => format!(
            "it leaves a parameter idle, and the simpler candidate that does as well was taken in its place: {}",
            other(simpler)
        ),
        Refusal::PressedOnSearchBound { inside } => format!(
            "a parameter of it is pressed on its search bound, and the look-alike inside its ranges was taken in its place: {}",
            other(inside)
        ),
        Refusal::SearchEndedOn { set } => {
            format!("the search from it ended on {}", other(set))
        }
    }
}

/// The verdict's warnings, one sentence each.
pub fn verdict_warnings(v: &Verdict) -> Vec<String> {
    match v {
        Verdict::Explained(e) => e.warnings.iter().map(verdict_warning).collect(),
        _ => Vec::new(),
    }
}

/// The note on a channel whose stated uncertainty `stated` lies below its
/// `scatter`: the weight the fits give it (`weighted`) and the floor its
/// gap is still judged against.
fn below_scatter(
    channel: crate::diagnose::model::channels::Channel,
    stated: f64,
    scatter: f64,
    weighted: f64,
) -> String {
    let u = channel.unit();
    // A scale floored by the signal's share is not what is stated:
    // the note must not say the weight it does not use.
    let weight = if weighted > stated * (1.0 + 1e-9) {
        format!(
                "it is weighted by {} {u} instead, {} % of the channel's RMS signal (the least any channel is weighted by)",
                crate::format::rounded(weighted, 2),
                crate::diagnose::model::scale::SIGNAL_SHARE * 100.0
            )
    } else {
        "it is weighted as stated and may dominate every fit".into()
    };
    // The weight is the fits'; the stated value still judges the
    // gap, and the note must not let the one read as the other.
    format!(
            "[channels] {} = {} {u}: the channel scatters by {} {u} from sample to sample, {} times what is stated; {weight}; its gap is judged against the stated {} {u} all the same, so its noise floors count {} times what its scatter would (state at least its scatter, or leave the key out for the tool's estimate)",
            channel.name(),
            crate::error::Num(stated),
            crate::format::rounded(scatter, 2),
            crate::format::rounded(scatter / stated, 2),
            crate::error::Num(stated),
            crate::format::rounded(scatter / stated, 2),
        )
}

/// A note on the inputs.
pub fn note(n: &Note) -> String {
    match n {
        Note::Campaign { text } | Note::TyresFarFromLoad { text } => text.clone(),
        Note::NotACandidate { effect, lacks } => {
            format!("{}: not a candidate: {lacks}", effect.name())
        }
        Note::RunsBeyondVehicle {
            limit,
            reached,
            threshold,
        } => beyond_vehicle(limit, *reached, *threshold),
        Note::BankOnlyInYawRate { runs, of } => format!(
            "bank_profile: {runs} of {of} runs have a bank channel but neither sideslip nor ay: there the bank shows only in the yaw rate, which the axles identified from the runs can take up; a sideslip or ay channel separates them"
        ),
        Note::UncertaintyUnused { channel } => format!(
            "[channels] {}: no run measures this channel, so its stated uncertainty is not used",
            channel.name()
        ),
        Note::UncertaintyAboveOwn(e) => trust::excess_note(e),
        Note::UncertaintyBelowScatter {
            channel,
            stated,
            scatter,
            weighted,
        } => below_scatter(*channel, *stated, *scatter, *weighted),
        Note::StiffReplay { step, runs, of } => format!(
            "replay method: the base model is too stiff for RK4 at the {step} s step on {runs} of {of} runs, replayed by the linearly implicit ROS34PW2 at that step"
        ),
        Note::TyreLoadsShort { of, loads, car } => tyre_loads::note(of, *loads, *car),
        Note::RigLevelsPooled {
            variable,
            levels,
            model,
        } => {
            let what = match variable {
                Variable::Load => "load",
                Variable::Camber => "camber",
                Variable::Pressure => "pressure",
            };
            format!(
                "{levels} {what} levels of the rig data pooled into one {model} fit, which has no {what} terms: the base tyre is their blend (rig data at the car's {what} alone would be the car's tyre)"
            )
        }
        Note::BetaAgainstInFile {
            file,
            correlation,
            samples,
        } => format!(
            "beta of {file} moves against the base model's (correlation {correlation:.2} over {samples} samples) while the other files' move with it: logged in the other sign convention in that file (ISO 8855: negative in a left turn at speed; `metrics` on the file says so where it has ay), or stretches the model misses; scored as logged"
        ),
    }
}

/// The heading of the findings on the gap: where it lies, or, when the
/// held-out error is within the noise level, that it has no place.
pub fn gap_heading(findings: &[GapFinding]) -> &'static str {
    if gap_within_noise(findings) {
        "the gap, within noise"
    } else {
        "where the gap lies"
    }
}

/// The overall finding says the gap is within noise.
fn gap_within_noise(findings: &[GapFinding]) -> bool {
    findings.iter().any(|f| {
        matches!(
            f,
            GapFinding::Overall {
                significant: false,
                ..
            }
        )
    })
}

/// What a candidate's standard errors leave out where the base model's
/// tyres come from rig data or files: those tyres are held, so a bias of
/// theirs moves every fitted value and is in no standard error. Said on
/// the terminal under the candidates' table and on the page under the
/// verdict's fitted values.
pub const TYRES_HELD: &str =
    "± a standard error with the base model's tyres held as they are: their own uncertainty is not in it";

/// In place of the candidates' table where every candidate was screened
/// out before cross-validation.
pub const NONE_CROSS_VALIDATED: &str =
    "none cross-validated: every candidate was screened out (below)";

/// Under the candidates' table: their ΔBIC (and, on a gap within noise,
/// their standard errors) count every sample as an independent one, but a
/// replay's residuals are correlated over many samples (a model's error is
/// smooth), so on thousands of samples a ΔBIC difference of hundreds
/// between two candidates reads as decisive where the held-out columns,
/// judged against the noise, do not tell them apart. On a gap within noise
/// the standard errors mislead the same way.
pub fn bic_caveat(findings: &[GapFinding]) -> &'static str {
    if gap_within_noise(findings) {
        "the gap is within noise: the ΔBIC and ± below count every sample as independent, and a replay's residuals are correlated over many samples, so on a gap within noise they look decisive where nothing is found; the held-out columns are the evidence"
    } else {
        "the ΔBIC below counts every sample as independent, and a replay's residuals are correlated over many samples, so a ΔBIC difference of hundreds between two candidates is no evidence between them; the held-out columns, against the noise, decide which the runs tell apart"
    }
}

/// A finding on where the gap lies.
pub fn finding(f: &GapFinding) -> String {
    match f {
        GapFinding::Overall {
            significant,
            heldout_error,
            noise_level,
        } => format!(
            "held-out error {heldout_error:.3} against a noise level of {noise_level:.3}: {}",
            if *significant {
                "the base model has a significant gap"
            } else {
                "no significant gap"
            }
        ),
        GapFinding::Channel { .. } => gap::channel(f),
        GapFinding::Band {
            run,
            f_low,
            f_high,
            gain_error_db,
            phase_error_deg,
        } => format!(
            "{run}: yaw-rate response {f_low:.2}–{f_high:.2} Hz off by {} dB, {}° (simulated against measured: + the model leads){}",
            signed(*gain_error_db, 1),
            signed(*phase_error_deg, 0),
            gap::unit_hint(*gain_error_db)
        ),
        GapFinding::Dominant {
            channel,
            share_percent,
            with_offsets_percent,
            less_offsets,
        } => format!(
            "{} carries {share_percent:.0} % of the base model's held-out J² (each channel over its noise floor){}: it decides every fit; where its floor is not what the channel can be trusted to, state it under [channels]",
            channel.name(),
            gap::offsets_aside(less_offsets, *with_offsets_percent)
        ),
        GapFinding::BandsWithoutSteer { bands, runs } => format!(
            "frequency bands: {} in {} without steer content: the steer there drives no yaw-rate response above {} × the gyro's noise in one frequency bin, so no gain or phase is said of them",
            crate::format::plural(*bands, "band", "bands"),
            crate::format::plural(*runs, "run", "runs"),
            crate::diagnose::report::gap::BAND_SNR
        ),
        GapFinding::WithoutAy { runs, of } => {
            format!("|ay| levels are u·r on the {runs} of {of} runs without an ay channel")
        }
    }
}

/// The experiment that separates confounded effects: each one's
/// signature.
pub fn separating_test(c: &Confounded) -> String {
    signatures(&c.effects)
}

/// Each effect's signature, as `name: signature` joined by "; ".
pub fn signatures(effects: &[EffectKind]) -> String {
    effects
        .iter()
        .map(|e| format!("{}: {}", e.name(), e.signature()))
        .collect::<Vec<_>>()
        .join("; ")
}

/// A fitted value: below 0.01 to four significant digits (a steering
/// compliance of 8.9e-5 rad/kN printed as 0.0001 would hide what was
/// fitted), else to four decimals; in the notation [`std_error`] writes
/// its standard error in (plain decimals from 1e-4, an exponent below).
pub fn value(v: f64) -> String {
    if v != 0.0 && v.abs() < 0.01 {
        crate::format::readable(v, 4)
    } else {
        // `+ 0.0` writes a negative zero as 0.0000, not -0.0000.
        format!("{:.4}", v + 0.0)
    }
}

/// A standard error (or a scatter said as one) as every sentence of the
/// diagnosis writes it: three significant digits, in plain decimals from
/// 1e-4 to below 1e6 and with an exponent beyond
/// ([`crate::format::readable`]), the notation [`value`] writes a value
/// in: `0.0496 ± 0.000224 s`, `± 0.00465` beside `± 0.0358`, never
/// `2.24e-4` in one sentence and `0.0358` in the next.
pub fn std_error(se: f64) -> String {
    crate::format::readable(se, 3)
}

/// The words of [`Note::RunsBeyondVehicle`]: the reach, the limit and the
/// key to check.
fn beyond_vehicle(
    limit: &crate::diagnose::report::VehicleLimit,
    reached: f64,
    threshold: f64,
) -> String {
    use crate::diagnose::report::VehicleLimit;
    use crate::format::significant;
    let g = crate::constants::G;
    let head = format!(
        "the runs turn at up to {} m/s² ({} g; 99th percentile of |speed × yaw_rate|, less a logged bank's g·|sin θ|)",
        significant(reached, 3),
        significant(reached / g, 2)
    );
    match limit {
        VehicleLimit::Friction { friction } => format!(
            "{head}, {}× what the campaign's friction {} lets any car turn at (μ·g = {} m/s²): the base model cannot follow them, and the gap it leaves is the friction's, not an unmodelled effect's; is `friction` right?",
            significant(reached / threshold, 2),
            crate::format::rounded(*friction, 3),
            significant(threshold, 3)
        ),
        VehicleLimit::Rollover { track, cg_height } => format!(
            "{head}, beyond the car's static stability factor g·t/(2h) = {} m/s² ({} g; track {} m, cg_height {} m), where a car's inner wheels lift: these runs stayed on four wheels, so `cg_height` or the track is likely wrong (a road car's factor is 1.0–1.5 g)",
            significant(threshold, 3),
            significant(threshold / g, 2),
            crate::format::rounded(*track, 3),
            crate::format::rounded(*cg_height, 3)
        ),
    }
}

#[cfg(test)]
mod band_tests;
#[cfg(test)]
mod cause_tests;
#[cfg(test)]
mod evidence_tests;
#[cfg(test)]
mod lookalike_tests;
#[cfg(test)]
mod parameter_tests;
#[cfg(test)]
mod prior_tests;
#[cfg(test)]
mod small_tests;
#[cfg(test)]
mod tests;
