//! What separates confounded effects on a base model with no friction
//! limit, as the design's replays measure it.
//!
//! Each effect's signature names the test that shows it (a ramp steer to
//! the limit, steps at two speeds, …). On a base whose tyres are linear
//! (`Fy = C·α`, no friction limit: Pacejka 2012, §1.3) or whose identified
//! peak friction was held at its prior (the runs never approach the
//! limit), nothing saturates in the base's replays, so a test "to the
//! limit" separates nothing there; and a signature may name runs the
//! campaign already has. Instead the fitted candidates are replayed on the
//! manoeuvres of the design's family the campaign has not driven
//! (`crate::design`, filled in by the `diagnose` job), and the one whose
//! predicted responses differ most is named, with the channel where they
//! differ most. It is advised only where `handling design` would
//! recommend it ([`super::worth::worth`]: the separation a driven run is
//! expected to measure lies beyond its uncertainty and is at least the
//! campaign's own); else the words say why it is not worth driving. One
//! recommended within 2 of its own uncertainty is said to be weak, in the
//! design's words ([`super::worth::weak`]: Putnam's sweep, 277.9 ± 268.9,
//! was advised as if one run would measure it), and counts as no firm run:
//! the remedy (runs nearer the limit, tyres with a limit) is said beside
//! it. A run the design calls already told apart ([`Worth::AlreadyToldApart`]:
//! its evidence model finds the campaign's runs enough) is judged here by
//! its expected separation alone, as the diagnosis that calls the pair
//! confounded has not told them apart: it was advised whatever its
//! uncertainty.
//!
//! Units: separations D in noise floors (`crate::design::separation`);
//! speeds m/s; a channel's difference in its own unit (rad/s, m/s², rad).

use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::worth::{weak, worth, Weak, Worth};
use crate::diagnose::report::BaseReport;
use crate::tyre::TyreModel;
use serde::Serialize;

/// Why the base model has no friction limit the runs' replays reach.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum NoLimit {
    /// Its tyres (given files) are linear.
    LinearTyres,
    /// Its axles were identified from runs that never approach the limit:
    /// the peak friction was held at its prior's value.
    FrictionHeld,
}

impl NoLimit {
    /// Why `base` has no friction limit, or None where it has one.
    pub fn of(base: &BaseReport) -> Option<Self> {
        // Any load: a linear tyre's friction coefficient is infinite at all.
        let unlimited = |t: &crate::tyre::Tyre| t.friction_coefficient(4000.0, 1.0).is_infinite();
        if unlimited(&base.front) || unlimited(&base.rear) {
            return Some(Self::LinearTyres);
        }
        let held = base
            .axles
            .as_ref()
            .is_some_and(|a| a.parameters.iter().any(|p| p.held));
        held.then_some(Self::FrictionHeld)
    }

    /// In words, as a reason.
    pub fn words(self) -> &'static str {
        match self {
            Self::LinearTyres => {
                "the base model's tyres are linear, with no friction limit, so a test at the limit separates nothing on it"
            }
            Self::FrictionHeld => {
                "the base model's peak friction is held at its prior (the runs never approach the limit), so what a test at the limit shows is not known on it"
            }
        }
    }
}

/// The manoeuvre the campaign lacks that separates two candidates most.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LackingRun {
    /// Its name (`handling design` writes a scenario file of it).
    pub name: String,
    /// What the driver does.
    pub description: String,
    /// The separation D of the two candidates' predicted responses.
    pub separation: f64,
    /// The channel whose part of D is largest.
    pub channel: Channel,
    /// That channel's part of D (its own sum of squares, rooted).
    pub channel_separation: f64,
    /// The largest |difference| of the two predictions in that channel,
    /// its unit.
    pub peak_difference: f64,
    /// Its noise floor, its unit.
    pub noise_floor: f64,
    /// The manoeuvre's kind in words, plural ("sweeps").
    pub kind: String,
    /// The speed it is driven at, m/s.
    pub speed: f64,
    /// The speeds of the campaign's runs of that kind, m/s (empty: the
    /// campaign has none of that kind).
    pub campaign_speeds: Vec<f64>,
    /// The separation a driven run of it is expected to measure, and its
    /// uncertainty (1 σ), as `handling design` completes its best (NaN:
    /// not computed).
    pub expected: f64,
    /// The uncertainty of `expected`.
    pub uncertainty: f64,
    /// D of the two candidates over the campaign's own runs.
    pub campaign_separation: f64,
    /// Whether a driven run is worth it, by `handling design`'s rule
    /// ([`crate::diagnose::report::worth::worth`]).
    pub worth: Worth,
    /// Where the words recommend it but weakly (within 2 of its own
    /// uncertainty, [`weak`]): its ratio and the chance one run misleads;
    /// `None` otherwise. Set once from [`LackingRun::weak_of`]; the words
    /// read it, so the terminal and the JSON say the same.
    pub weak: Option<Weak>,
}

impl LackingRun {
    /// What [`LackingRun::weak`] holds: weak where the run's words
    /// recommend it ([`judged`]) within 2 of its own uncertainty.
    pub fn weak_of(&self) -> Option<Weak> {
        (judged(self) == Worth::Separates)
            .then(|| weak(Worth::Separates, self.expected, self.uncertainty))
            .flatten()
    }
}

/// What separates the reference from one look-alike.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairRun {
    /// The reference (the verdict's effect).
    pub reference: EffectKind,
    /// The look-alike.
    pub other: EffectKind,
    /// The best manoeuvre the campaign lacks, when it separates them by
    /// more than a noise floor.
    pub best: Option<LackingRun>,
    /// The largest separation of any manoeuvre the campaign lacks (NaN:
    /// none replayed).
    pub largest: f64,
    /// Manoeuvres of the family replayed (those the campaign lacks,
    /// within the limits).
    pub replayed: usize,
}

/// The separating runs of a confounded set on a base without a limit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SeparatingRuns {
    /// Why the signatures' tests do not apply.
    pub no_limit: NoLimit,
    /// One per look-alike.
    pub pairs: Vec<PairRun>,
}

fn kmh(speeds: &[f64]) -> String {
    let v: Vec<String> = speeds.iter().map(|u| format!("{:.0}", u * 3.6)).collect();
    format!("{} km/h", v.join(", "))
}

/// One pair's advice, in words.
fn pair_words(p: &PairRun) -> String {
    let (a, b) = (p.reference.name(), p.other.name());
    let Some(r) = &p.best else {
        let largest = if p.largest.is_finite() {
            format!("at most D = {:.1}", p.largest)
        } else {
            "none could be replayed".to_string()
        };
        return format!(
            "{a} from {b}: none of the {} separates them by a noise floor ({largest}): on this base model they predict the same responses",
            p.replayed
        );
    };
    let has = if r.campaign_speeds.is_empty() {
        format!("the campaign has no {}", r.kind)
    } else {
        // Mean speeds on both sides, the rule's: a braking run named by
        // its entry speed (`brake_in_turn_043kph`) averages less.
        format!(
            "its mean speed {}, the campaign's {} at mean speeds of {}",
            kmh(&[r.speed]),
            r.kind,
            kmh(&r.campaign_speeds)
        )
    };
    let unit = r.channel.unit();
    let run = format!(
        "{} ({}; {has}): their predicted responses differ by D = {:.1} noise floors, most in {} (D = {:.1} of it; up to {} {unit} apart, its noise floor {} {unit})",
        r.description,
        r.name,
        r.separation,
        r.channel.name(),
        r.channel_separation,
        crate::format::readable(r.peak_difference, 3),
        crate::format::readable(r.noise_floor, 3),
    );
    let measured = format!(
        "a driven run is expected to measure {:.1} ± {:.1}",
        r.expected, r.uncertainty
    );
    match judged(r) {
        Worth::Separates => match r.weak {
            Some(w) => format!("{a} from {b}: {run}; {measured}; {}", w.words()),
            None => format!("{a} from {b}: {run}; {measured}"),
        },
        Worth::WithinUncertainty => format!(
            "{a} from {b}: none of the {} is worth driving to separate them; the best, {run}, but {measured}: within its own uncertainty, one run may show no separation or favour the wrong candidate",
            p.replayed
        ),
        // (`judged` gives no AlreadyToldApart.)
        Worth::BelowCampaign | Worth::AlreadyToldApart => format!(
            "{a} from {b}: none of the {} is worth driving to separate them; the best, {run}, but {measured}, less than the campaign's own runs separate them by (D = {:.1})",
            p.replayed, r.campaign_separation
        ),
    }
}

/// The worth `r`'s words follow: the design's, except that a run it calls
/// already told apart is judged by its expected separation, its
/// uncertainty and the campaign's own separation ([`worth`]) — the
/// diagnosis advising it calls the pair confounded.
fn judged(r: &LackingRun) -> Worth {
    match r.worth {
        Worth::AlreadyToldApart => worth(r.expected, r.uncertainty, r.campaign_separation),
        w => w,
    }
}

/// Whether pair `p` has a manoeuvre firmly worth driving: recommended,
/// and not weakly ([`weak`]).
fn has_run(p: &PairRun) -> bool {
    p.best
        .as_ref()
        .is_some_and(|r| judged(r) == Worth::Separates && r.weak.is_none())
}

impl SeparatingRuns {
    /// The advice, in words: why the signatures do not apply, then each
    /// pair's run.
    pub fn words(&self) -> String {
        let pairs: Vec<String> = self.pairs.iter().map(pair_words).collect();
        let remedy = if !self.pairs.iter().all(has_run) {
            match self.no_limit {
                NoLimit::LinearTyres => "; tyres with a friction limit (rig data) give the base the saturation a test at the limit needs",
                NoLimit::FrictionHeld => "; runs nearer the limit let the diagnosis identify the peak friction a test at the limit needs",
            }
        } else {
            ""
        };
        format!(
            "{}; the candidates as fitted, replayed on the manoeuvres of the design's family the campaign has not driven (a kind at a speed it has no run of), predict: {}{remedy}",
            self.no_limit.words(),
            pairs.join("; ")
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pair(worth: Worth) -> PairRun {
        let mut p = PairRun {
            reference: EffectKind::RollSteer,
            other: EffectKind::CorneringStiffness,
            best: Some(LackingRun {
                name: "brake_in_turn_043kph_2.9ms2".into(),
                description: "a steady turn at 43 km/h, braking".into(),
                separation: 39.4,
                channel: Channel::YawRate,
                channel_separation: 33.0,
                peak_difference: 0.0103,
                noise_floor: 0.003,
                kind: "runs braking in a turn".into(),
                speed: 9.6,
                campaign_speeds: vec![11.49, 13.07],
                expected: 39.4,
                uncertainty: 10.5,
                campaign_separation: 63.0,
                worth,
                weak: None,
            }),
            largest: 39.4,
            replayed: 12,
        };
        let r = p.best.as_mut().unwrap();
        r.weak = r.weak_of();
        p
    }

    /// The advice follows the design's worth: a run worth driving is
    /// advised with what a driven run is expected to measure; one within
    /// its uncertainty or below the campaign's own separation is named
    /// as the best but not worth driving, with the reason; the speeds
    /// compared are means on both sides.
    #[test]
    fn the_advice_words_follow_the_runs_worth() {
        let said = pair_words(&pair(Worth::Separates));
        assert!(
            said.ends_with("; a driven run is expected to measure 39.4 ± 10.5"),
            "{said}"
        );
        assert!(!said.contains("none of"), "{said}");
        assert!(
            said.contains("its mean speed 35 km/h, the campaign's runs braking in a turn at mean speeds of 41, 47 km/h"),
            "{said}"
        );
        let within = pair_words(&pair(Worth::WithinUncertainty));
        assert!(
            within.starts_with("roll_steer from cornering_stiffness: none of the 12 is worth driving to separate them; the best, "),
            "{within}"
        );
        assert!(within.ends_with("within its own uncertainty, one run may show no separation or favour the wrong candidate"), "{within}");
        let below = pair_words(&pair(Worth::BelowCampaign));
        assert!(
            below.ends_with("less than the campaign's own runs separate them by (D = 63.0)"),
            "{below}"
        );
        let runs = |w| SeparatingRuns {
            no_limit: NoLimit::LinearTyres,
            pairs: vec![pair(w)],
        };
        let remedy = "tyres with a friction limit (rig data)";
        assert!(!runs(Worth::Separates).words().contains(remedy));
        assert!(runs(Worth::BelowCampaign).words().contains(remedy));
    }

    /// `pair(worth)` expected to measure `expected ± uncertainty`.
    fn expecting(worth: Worth, expected: f64, uncertainty: f64) -> PairRun {
        let mut p = pair(worth);
        let r = p.best.as_mut().unwrap();
        (r.expected, r.uncertainty) = (expected, uncertainty);
        r.weak = r.weak_of();
        p
    }

    /// Putnam's sweep, recommended at 277.9 ± 268.9, is advised as the
    /// design words it, weak, with the chance one run measures nothing
    /// (Φ(−1.03) = 15 %), and is no firm run: the remedy is said too. A run
    /// the design calls already told apart is judged by its numbers: at
    /// 3.1 ± 9.5 not worth driving (it was advised as the one to drive).
    #[test]
    fn a_weak_run_is_said_weak_and_one_told_apart_is_judged_by_its_numbers() {
        let putnam = expecting(Worth::Separates, 277.9, 268.9);
        let said = pair_words(&putnam);
        assert!(
            said.ends_with("; a driven run is expected to measure 277.9 ± 268.9; weak: expected at 1.03 times its own uncertainty, below 2, so one run lands at or below 0 (no separation, or the wrong candidate favoured) with a chance of 15 % on a normal spread: it separates them as a series, not in one run"),
            "{said}"
        );
        let runs = SeparatingRuns {
            no_limit: NoLimit::FrictionHeld,
            pairs: vec![putnam],
        };
        assert!(
            runs.words().ends_with("not in one run; runs nearer the limit let the diagnosis identify the peak friction a test at the limit needs"),
            "{}",
            runs.words()
        );
        // The firm 39.4 ± 10.5 (3.75 σ) is not weak.
        assert!(!pair_words(&pair(Worth::Separates)).contains("weak"));
        let told = pair_words(&expecting(Worth::AlreadyToldApart, 3.1, 9.5));
        assert!(
            told.contains("none of the 12 is worth driving")
                && told.ends_with("within its own uncertainty, one run may show no separation or favour the wrong candidate"),
            "{told}"
        );
        // 39.4 ± 10.5 against the campaign's 63.0: below it.
        let told = pair_words(&pair(Worth::AlreadyToldApart));
        assert!(told.ends_with("(D = 63.0)"), "{told}");
    }

    /// The JSON's `weak` is what the words say: Putnam's sweep carries its
    /// 1.03 and 15 %; a firm run, one not worth driving and one told apart
    /// that its numbers put within its uncertainty carry none.
    #[test]
    fn the_json_says_weak_where_the_words_do() {
        let run = |p: PairRun| serde_json::to_value(p.best.unwrap()).unwrap();
        let putnam = run(expecting(Worth::Separates, 277.9, 268.9));
        let sigmas = putnam["weak"]["sigmas"].as_f64().unwrap();
        let wrong = putnam["weak"]["wrong"].as_f64().unwrap();
        assert!((sigmas - 277.9 / 268.9).abs() < 1e-12, "{putnam}");
        assert!((wrong - 0.1507).abs() < 5e-4, "{putnam}");
        assert!(run(pair(Worth::Separates))["weak"].is_null());
        assert!(run(expecting(Worth::WithinUncertainty, 3.1, 9.5))["weak"].is_null());
        assert!(run(expecting(Worth::AlreadyToldApart, 3.1, 9.5))["weak"].is_null());
    }
}
