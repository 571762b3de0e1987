//! What `design` prints: the limits, each set's ranked manoeuvres with
//! their expected separation, whether each is worth driving and the runs
//! the diagnosis needs, what the diagnosis advises and where it ranks, and
//! each measured run against its prediction. Separations in noise floors.

use super::DesignReport;
use crate::design::{DiagnosisReads, Measured, Recommendation, SameRun, Scored, SetDesign, Worth};
use crate::format::readable;

/// The share of a manoeuvre below which a driven run is said to be a
/// part of it (a logger's last samples aside).
const PARTIAL: f64 = 0.98;

impl DesignReport {
    /// What the design found, in lines.
    pub fn summary(&self) -> Vec<String> {
        let mut out = vec![self.limits_line()];
        if !self.design.left_out_by_limits.is_empty() {
            out.push(format!(
                "  the limits leave out {} of the family: {}",
                self.design.left_out_by_limits.len(),
                self.design.left_out_by_limits.join(", ")
            ));
        }
        for set in &self.design.sets {
            out.extend(set_lines(set, self.design.family));
        }
        for m in &self.measured {
            out.extend(measured_lines(m));
        }
        if !self.stale.is_empty() {
            out.push(format!(
                "removed {} scenario file{} of an earlier design from {} (design.json lists them)",
                self.stale.len(),
                if self.stale.len() == 1 { "" } else { "s" },
                self.out_dir.join("scenarios").display()
            ));
        }
        out.push(format!("wrote {}", self.out_dir.display()));
        out
    }

    /// The limits the manoeuvres keep to and the family's size.
    fn limits_line(&self) -> String {
        let l = &self.design.limits;
        format!(
            "limits: {:.1}–{:.1} m/s, |ay| ≤ {} m/s² ({} % of the {:.2} reached), steer rate ≤ {:.2} rad/s, |ax| ≤ {:.1} m/s²; {} manoeuvres in the family",
            l.speed.0,
            l.speed.1,
            fixed_or_digits(l.ay_max(), 2),
            fixed_or_digits(100.0 * l.ay_share, 0),
            l.ay_reached,
            l.steer_rate,
            l.ax,
            self.design.family
        )
    }
}

/// One set's lines: the campaign's separation and its calibration, each
/// ranked manoeuvre, the recommendation, the diagnosis's advice and what
/// was left out (of a family of `family` manoeuvres).
fn set_lines(set: &SetDesign, family: usize) -> Vec<String> {
    let mut out = vec![format!(
        "{}: {}{}",
        set.members.join(" / "),
        separation_words(set),
        calibration_words(set)
    )];
    for (k, s) in set.ranked.iter().enumerate() {
        out.push(ranked_line(k, s));
    }
    out.extend(recommendation_line(set));
    out.extend(advised_line(set, family - set.excluded.len()));
    if !set.excluded.is_empty() {
        out.push(format!(
            "  left out: {} beyond the limits or diverged (design.json lists them)",
            set.excluded.len()
        ));
    }
    out
}

/// What D of the campaign's runs measures, and why those runs did not
/// tell the pair apart where the diagnosis says they do not: D sums the
/// fitted models' squared differences over every sample, the diagnosis's
/// held-out errors average the residuals over them, so a pair can differ
/// by D ≫ 1 and leave gaps within the confounding window.
fn separation_words(set: &SetDesign) -> String {
    let d = set.campaign_separation;
    let n = set.campaign_samples.max(1) as f64;
    let what = format!(
        "the two fitted models' replays of the campaign's runs differ by D = {d:.1} noise floors (the root of their squared differences summed over the runs' {} samples: {} of a floor a sample, RMS)",
        set.campaign_samples,
        readable(d / n.sqrt(), 2)
    );
    let why = match set.reads {
        DiagnosisReads::Confounded => "; yet the diagnosis calls them confounded: it weighs each one's held-out error, an average over the samples, and the gaps the two leave lie within its confounding window, so these runs do not tell them apart",
        DiagnosisReads::NoGap => "; the diagnosis finds no significant gap with these runs: they need neither, and do not tell one from the other",
        DiagnosisReads::Other => "",
    };
    format!("{what}{why}")
}

/// How the campaign's own runs calibrate a set's uncertainties, in words
/// after its separation.
fn calibration_words(set: &SetDesign) -> String {
    let cal = &set.calibration;
    let mut measured = match cal.runs {
        0 => "; none by a tenth of a noise floor, so none measures the predictions' scatter".into(),
        n if cal.inflation <= 1.0 => format!(
            "; the {n} that separate them by a tenth of a noise floor or more measure it within the noise's scatter, so the uncertainties below are the noise's"
        ),
        n => format!(
            "; the {n} that separate them by a tenth of a noise floor or more measure it with {:.1} times the noise's scatter, which widens the uncertainties below",
            cal.inflation
        ),
    };
    // The scatter holds a model-form error only along the differences the
    // campaign's runs show (`Calibration`).
    // A gap is said as the diagnosis reads it: above the noise only beyond
    // its threshold; below, what J exceeds J_n by is still bounded.
    let gap = &cal.reference;
    if gap.model_form() {
        let said = if gap.significant() {
            format!(
                "{} leaves a gap above the noise (held-out error {:.3} against a noise level of {:.3}), a model-form error",
                set.members[0], gap.heldout_error, gap.noise_level
            )
        } else {
            format!(
                "{} leaves no significant gap (held-out error {:.3}, within {} × the noise level {:.3}, as the diagnosis reads it), but what it leaves above the noise level may be model-form error, which",
                set.members[0],
                gap.heldout_error,
                crate::diagnose::rules::SIGNIFICANT,
                gap.noise_level
            )
        };
        measured += &format!(
            "; {said} this scatter holds only along the differences these runs show, so each uncertainty below adds the most it can move a driven run ({} of the noise's variance a sample, over the run's samples)",
            crate::format::readable(gap.excess(), 2)
        );
    }
    measured
}

/// The `k`-th (from 0) ranked manoeuvre: its separation, expectation,
/// worth and the runs the diagnosis needs.
fn ranked_line(k: usize, s: &Scored) -> String {
    let expected = match (s.expected, s.uncertainty) {
        (Some(e), Some(u)) if e < 0.0 => format!(
            "; a driven run is expected to measure {e:.1} ± {u:.1} (below 0: the noise of the start the replays take costs the reference more than its look-alike, favouring the look-alike on average)"
        ),
        (Some(e), Some(u)) => {
            format!("; a driven run is expected to measure {e:.1} ± {u:.1}")
        }
        _ => String::new(),
    };
    let enough = match s.repetitions {
        Some(0) => String::new(),
        Some(k) => format!(
            "; the diagnosis tells them apart after {k} such run{}",
            if k == 1 { "" } else { "s" }
        ),
        None if s.expected.is_some() => format!(
            "; more than {} such runs before the diagnosis tells them apart",
            crate::design::MAX_REPETITIONS
        ),
        None => String::new(),
    };
    format!(
        "  {}. {} — D = {:.1}{expected}{}{enough}: {}",
        k + 1,
        s.name,
        s.separation,
        worth_words(s),
        s.description
    )
}

/// A run driven after the design: its separation against the prediction,
/// and warnings where it is part of the manoeuvre or lacks channels.
fn measured_lines(m: &Measured) -> Vec<String> {
    let mut out = vec![format!(
        "measured: {} separates them by {:.1} noise floors and favours {}",
        m.run, m.separation, m.favours
    )];
    out.push(match &m.predicted {
        Some(p) => format!(
            "  predicted for {}: {:.1} ± {:.1}, measured {} σ from it{}",
            p.manoeuvre,
            p.expected,
            p.uncertainty,
            // Signed, and never "-0.0" for what rounds to zero.
            crate::format::signed(p.deviation, 1),
            if p.steer_difference > 0.1f64.to_radians() {
                format!("; its steer departs from the design by up to {:.2}°: not driven as designed", p.steer_difference.to_degrees())
            } else {
                String::new()
            }
        ),
        None => "  no prediction to compare: the family has no manoeuvre of this run's file name".into(),
    });
    if let Some(f) = &m.fitted_on {
        let how = match f.by {
            SameRun::Path => "the same file",
            SameRun::Content => "byte for byte the same",
        };
        out.push(format!(
            "  warning: this run is the campaign's own {} ({how}): the candidates were fitted to it, so its separation is no new evidence between them; drive a new run",
            f.run
        ));
    }
    if let Some(excess) = m.misfit() {
        out.push(format!(
            "  warning: both candidates miss the run by far more than they differ: the better, {}, is {:.1} noise floors RMS off it ({excess:.1} noise floors above the noise over its {} residuals, against a separation of {:.1}): the separation is misfit, not evidence between them",
            m.favours,
            m.best_rms(),
            m.residuals,
            m.separation.abs()
        ));
    }
    if let Some(p) = &m.predicted {
        if p.coverage < PARTIAL {
            out.push(format!(
                "  warning: the run covers {:.0} % of the manoeuvre's length: its separation is that of a part, the prediction that of the whole",
                100.0 * p.coverage
            ));
        }
        if !p.missing_channels.is_empty() {
            let names: Vec<&str> = p.missing_channels.iter().map(|c| c.name()).collect();
            out.push(format!(
                "  warning: the run does not log {}, which the prediction counts: its separation lacks their part",
                names.join(", ")
            ));
        }
    }
    out
}

/// Whether a manoeuvre is recommended, in words after its expectation;
/// one recommended within [`crate::design::FIRM_SIGMAS`] of its uncertainty is said to be
/// weak, with its ratio and the chance one run misleads.
fn worth_words(s: &Scored) -> String {
    if let Some(w) = s.weak() {
        return format!("; {}", w.words());
    }
    match s.worth {
        Some(Worth::Separates) => "; recommended",
        Some(Worth::WithinUncertainty) => {
            "; not recommended: within its own uncertainty, one run may show no separation or favour the wrong candidate"
        }
        Some(Worth::BelowCampaign) => {
            "; not recommended: it adds less than the D of the campaign's runs, which did not tell them apart"
        }
        Some(Worth::AlreadyToldApart) => {
            "; not needed: the diagnosis already tells them apart, no run is needed to separate them"
        }
        None => "",
    }
    .to_string()
}

/// `v` with `decimals` decimals where they show it, else with its first
/// three significant digits (0.000815, not 0.00).
fn fixed_or_digits(v: f64, decimals: usize) -> String {
    if v >= 10f64.powi(-(decimals as i32)) {
        format!("{v:.decimals$}")
    } else {
        readable(v, 3)
    }
}

/// The set's recommendation when none of its best is worth driving.
fn recommendation_line(set: &SetDesign) -> Option<String> {
    if set.recommendation == Recommendation::AlreadyToldApart {
        return Some(
            "  none needs driving: the diagnosis already tells them apart (drive one only to confirm it)".into(),
        );
    }
    let Recommendation::NoneWorthDriving {
        best_expected: e,
        best_uncertainty: u,
        campaign_separates_more,
    } = set.recommendation
    else {
        return None;
    };
    let n = set.ranked.len();
    if n == 0 || !(e.is_finite() && u.is_finite()) {
        return Some(
            "  no manoeuvre of the family fits within the limits (each is left out beyond them): none to drive; widen --ay-share or --max-ax".into(),
        );
    }
    Some(if campaign_separates_more {
        below_campaign_words(set, e, u)
    } else {
        format!(
            "  none is worth driving to separate them: each one's expected separation lies within its own uncertainty (at most {e:.1} ± {u:.1})"
        )
    })
}

/// The recommendation when each of the best is expected to add less than
/// the D of the campaign's runs (the best at most `e ± u`): those runs did
/// not tell the pair apart, so a test is still needed; the best and the
/// diagnosis's advice are what to drive, not "nothing".
fn below_campaign_words(set: &SetDesign, e: f64, u: f64) -> String {
    let best = set.ranked.first().map_or("", |s| s.name.as_str());
    let head = format!(
        "  no single run of these is expected to tell them apart (at most {e:.1} ± {u:.1}, less than the D = {:.1} of the campaign's runs",
        set.campaign_separation
    );
    match set.reads {
        DiagnosisReads::NoGap => format!(
            "{head}, with which the diagnosis finds no gap): the runs need neither; to tell them apart all the same, drive the test the diagnosis advises (below) and the best of these, {best}, and diagnose again with those runs"
        ),
        _ => format!(
            "{head}, which left them confounded): they are still to be told apart, so a test is still needed: drive the test the diagnosis advises (below) and the best of these, {best}, and diagnose again with those runs (the diagnosis, not one run, tells them apart)"
        ),
    }
}

/// What the diagnosis advises to separate the set's effects, and where
/// the family's manoeuvres of that test rank among the `ranked` within
/// the limits.
fn advised_line(set: &SetDesign, ranked: usize) -> Option<String> {
    use crate::design::Missing;
    if set.advised.is_empty() {
        return None;
    }
    let parts: Vec<String> = set
        .advised
        .iter()
        .map(|a| {
            let what = match (&a.missing, &a.best) {
                (Some(Missing::StraightBothWays), _) => {
                    "a straight run both ways, which the family, driven one way, does not make".into()
                }
                (Some(Missing::BankedCorner), _) => {
                    "a banked corner at two speeds, which the family, driven on a flat road, does not make".into()
                }
                (None, Some(b)) => format!(
                    "{} (the best, {}, ranks {} of {ranked}, D = {:.1})",
                    kinds_words(&a.kinds),
                    b.name,
                    b.rank,
                    b.separation
                ),
                (None, None) => format!(
                    "{} (every one of the family's left out beyond the limits)",
                    kinds_words(&a.kinds)
                ),
            };
            format!("{} by {what}", a.effect)
        })
        .collect();
    Some(format!(
        "  the diagnosis advises to separate {}",
        parts.join("; ")
    ))
}

/// The family's kinds of an advised test, in words.
fn kinds_words(kinds: &[crate::design::Kind]) -> String {
    use crate::design::Kind::*;
    let words: Vec<&str> = kinds
        .iter()
        .map(|k| match k {
            Step => "steps",
            Ramp => "a ramp",
            Sweep => "sweeps",
            LaneChange => "lane changes",
            SpeedChange => "a speed change on a straight",
            BrakeInTurn => "steady turns then braking",
            AccelerateInTurn => "steady turns then accelerating",
            ConstantRadius => "a constant-radius turn",
        })
        .collect();
    words.join(" or ")
}
