//! The manoeuvres a campaign lacks, and which of them separates two
//! fitted candidates most: the advice of a confounded set on a base with
//! no friction limit ([`crate::diagnose::report::separating`]).
//!
//! A campaign's run is read as a manoeuvre of the family's kinds from its
//! inputs alone: a speed change above [`MIN_SPEED_CHANGE`] makes it a
//! straight speed change (no steer), braking or accelerating in a turn;
//! at constant speed, a steer that crosses back over half its amplitude
//! four times or more is a sweep, once to three times a lane change
//! (steer to the other side), else a step when
//! it rises from 10 to 90 % of its peak within [`STEP_RISE`], a ramp
//! otherwise. A designed manoeuvre the campaign already has (its kind at
//! a speed within [`SAME_SPEED`] of one of the campaign's of that kind)
//! is never advised. The others are logged as the campaign logs,
//! replayed with both candidates as fitted ([`super::separation`]) and
//! kept within the lateral limit as the design keeps them.
//!
//! Units: SI (m/s, rad, s); separations in noise floors.

use super::family::{
    family_and_left_out, Designed, Kind, Limits, DEFAULT_AX, DEFAULT_AY_SHARE, MIN_SPEED_CHANGE,
};
use super::separation::{separation, Logging};
use super::{campaign_separation, Fitted, SetContext, Worth};
use crate::diagnose::campaign::Campaign;
use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::Observed;
use crate::diagnose::pipeline::observed_channel;
use crate::diagnose::report::separating::{LackingRun, NoLimit, PairRun, SeparatingRuns};
use crate::diagnose::{Channel, Prepared};
use crate::measured::MeasuredRun;
use rayon::prelude::*;

/// The longest 10–90 % rise of a steer step, s (a ramp takes longer).
pub const STEP_RISE: f64 = 1.5;

/// Two runs of one kind within this share of speed of each other are the
/// same manoeuvre for the advice.
pub const SAME_SPEED: f64 = 0.1;

/// A steer below this (rad of road wheel, 0.2°) is driving straight.
const STRAIGHT: f64 = 0.0035;

/// The kind and mean speed (m/s) of a campaign's run, read from its
/// inputs; None for a run that holds a straight line at constant speed.
pub fn kind_of(run: &MeasuredRun) -> Option<(Kind, f64)> {
    let n = run.t.len();
    if n < 3 {
        return None;
    }
    let speed = run.speed.iter().sum::<f64>() / n as f64;
    // The straight lead-in's steer is the trim the manoeuvre starts from.
    let lead = run
        .t
        .iter()
        .take_while(|&&x| x - run.t[0] < 0.5)
        .count()
        .max(1);
    let trim = run.steer[..lead].iter().sum::<f64>() / lead as f64;
    let s: Vec<f64> = run.steer.iter().map(|x| x - trim).collect();
    let peak = s.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    let (lo, hi) = run
        .speed
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &u| {
            (a.min(u), b.max(u))
        });
    if hi - lo > MIN_SPEED_CHANGE {
        // A turn's steer is held from the start: measured from zero.
        let turn = run.steer.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        let falls = run.speed[n - 1] < run.speed[0];
        let kind = match (turn < STRAIGHT, falls) {
            (true, _) => Kind::SpeedChange,
            (false, true) => Kind::BrakeInTurn,
            (false, false) => Kind::AccelerateInTurn,
        };
        return Some((kind, speed));
    }
    if peak < STRAIGHT {
        return None;
    }
    // Crossings with hysteresis: back over half the amplitude each time.
    let mut crossings = 0;
    let mut side = 0.0;
    for &x in &s {
        if x.abs() > 0.5 * peak && x.signum() != side {
            crossings += usize::from(side != 0.0);
            side = x.signum();
        }
    }
    let first = |share: f64| s.iter().position(|x| x.abs() >= share * peak);
    let rise = match (first(0.1), first(0.9)) {
        (Some(a), Some(b)) => run.t[b] - run.t[a],
        _ => f64::INFINITY,
    };
    let kind = match crossings {
        4.. => Kind::Sweep,
        1.. => Kind::LaneChange,
        _ if rise <= STEP_RISE => Kind::Step,
        _ => Kind::Ramp,
    };
    Some((kind, speed))
}

/// The kind in words, plural.
pub fn kind_words(k: Kind) -> &'static str {
    match k {
        Kind::Step => "steer steps",
        Kind::Ramp => "steer ramps",
        Kind::Sweep => "steer sweeps",
        Kind::LaneChange => "lane changes",
        Kind::SpeedChange => "speed changes on a straight",
        Kind::BrakeInTurn => "runs braking in a turn",
        Kind::AccelerateInTurn | Kind::ConstantRadius => "runs accelerating in a turn",
    }
}

/// The kind a campaign's run is read as for a designed one: a
/// constant-radius turn at rising speed reads as accelerating in a turn.
fn as_read(k: Kind) -> Kind {
    match k {
        Kind::ConstantRadius => Kind::AccelerateInTurn,
        k => k,
    }
}

/// The speed a designed manoeuvre is driven at: its mean over its span.
fn designed_speed(d: &Designed) -> f64 {
    let (t0, t1) = (d.manoeuvre.start_time(), d.manoeuvre.end_time());
    let n = 50;
    (0..=n)
        .map(|i| d.manoeuvre.speed(t0 + (t1 - t0) * i as f64 / n as f64))
        .sum::<f64>()
        / (n + 1) as f64
}

/// The speeds of `runs` (kinds read) of kind `k`, sorted.
fn speeds_of(runs: &[(Kind, f64)], k: Kind) -> Vec<f64> {
    let mut v: Vec<f64> = runs
        .iter()
        .filter(|(x, _)| *x == as_read(k))
        .map(|r| r.1)
        .collect();
    v.sort_by(f64::total_cmp);
    v
}

/// Whether the campaign (its runs' kinds `runs`) has `d` already.
fn has(runs: &[(Kind, f64)], d: &Designed) -> bool {
    let u = designed_speed(d);
    speeds_of(runs, d.kind)
        .iter()
        .any(|&v| (v - u).abs() <= SAME_SPEED * u.max(v))
}

/// Per channel, the part of D and the largest |difference|.
fn channel_parts(a: &Observed, b: &Observed, floors: &[f64; 3], log: &Logging) -> [(f64, f64); 3] {
    Channel::ALL.map(|c| {
        let sigma = floors[c.index()];
        if !log.channels[c.index()] || sigma <= 0.0 {
            return (0.0, 0.0);
        }
        let (mut s, mut peak) = (0.0, 0.0_f64);
        for (x, y) in observed_channel(a, c).iter().zip(observed_channel(b, c)) {
            s += ((y - x) / sigma).powi(2);
            peak = peak.max((y - x).abs());
        }
        (s.sqrt(), peak)
    })
}

/// What separates `reference` from `other` among `lacking`, or None when
/// either candidate is not among those fitted.
fn pair(
    c: &Campaign,
    fitted: &Fitted,
    (reference, other): (EffectKind, EffectKind),
    lacking: &[&Designed],
    limits: &Limits,
    runs: &[(Kind, f64)],
) -> Option<PairRun> {
    let base = fitted.base(c);
    let members = [
        fitted.candidate(&[reference])?.clone(),
        fitted.candidate(&[other])?.clone(),
    ];
    let a = members[0].model(&base)?;
    let b = members[1].model(&base)?;
    let log = Logging::of(c);
    let floors = &fitted.noise_floors;
    let scored: Vec<(f64, &Designed, Observed, Observed)> = lacking
        .par_iter()
        .filter_map(|d| {
            let logged = log.run(&d.name, &d.manoeuvre);
            let run = Prepared::new(&logged, c.settings.step, c.settings.sample_rate);
            let (oa, ob) = (run.observe(&a), run.observe(&b));
            // Within the lateral limit as the design keeps it (a's ay).
            let peak = observed_channel(&oa, Channel::Ay)
                .iter()
                .fold(0.0_f64, |m, x| m.max(x.abs()));
            let within = !log.channels[Channel::Ay.index()] || peak <= 1.1 * limits.ay_max();
            let sep = separation(&oa, &ob, floors, &log);
            (within && sep.is_finite()).then_some((sep, *d, oa, ob))
        })
        .collect();
    let best = scored.iter().max_by(|x, y| x.0.total_cmp(&y.0));
    let largest = best.map_or(f64::NAN, |b| b.0);
    let best = best.filter(|b| b.0 > 1.0).map(|(sep, d, oa, ob)| {
        let cx = SetContext {
            c,
            fitted,
            base: &base,
            members: &members,
            models: vec![a.clone(), b.clone()],
            labels: members.iter().map(|m| m.label()).collect(),
            limits,
            logging: &log,
            runs: &super::separation::campaign_prepared(c),
        };
        let (expected, uncertainty, campaign_separation, worth) = assess(&cx, d);
        let parts = channel_parts(oa, ob, floors, &log);
        let ch = Channel::ALL
            .into_iter()
            .max_by(|x, y| parts[x.index()].0.total_cmp(&parts[y.index()].0))
            .unwrap_or(Channel::YawRate);
        let mut run = LackingRun {
            name: d.name.clone(),
            description: d.description.clone(),
            separation: *sep,
            channel: ch,
            channel_separation: parts[ch.index()].0,
            peak_difference: parts[ch.index()].1,
            noise_floor: floors[ch.index()],
            kind: kind_words(d.kind).to_string(),
            speed: designed_speed(d),
            campaign_speeds: speeds_of(runs, d.kind),
            expected,
            uncertainty,
            campaign_separation,
            worth,
            weak: None,
        };
        run.weak = run.weak_of();
        run
    });
    Some(PairRun {
        reference,
        other,
        best,
        largest,
        replayed: scored.len(),
    })
}

/// The separation a driven run of `d` is expected to measure, its
/// uncertainty, the campaign's own separation and the run's worth, by the
/// rule `handling design` completes its best with, so the diagnosis never
/// advises a run the design calls not worth driving.
fn assess(cx: &SetContext, d: &Designed) -> (f64, f64, f64, Worth) {
    let (campaign, calibration) = campaign_separation(cx);
    match cx.score(d) {
        Ok((mut s, _)) => {
            cx.complete(&mut s, &calibration, campaign);
            let worth = s.worth.unwrap_or(Worth::WithinUncertainty);
            let nan = f64::NAN;
            (
                s.expected.unwrap_or(nan),
                s.uncertainty.unwrap_or(nan),
                campaign,
                worth,
            )
        }
        Err(_) => (f64::NAN, f64::NAN, campaign, Worth::WithinUncertainty),
    }
}

/// The separating runs of confounded set `effects` (the reference first)
/// of campaign `c` as `fitted`, on a base without a limit (`no_limit`):
/// per look-alike, the manoeuvre of the design's family (at its default
/// limits) the campaign lacks whose predicted responses differ most.
pub fn separating_runs(
    c: &Campaign,
    fitted: &Fitted,
    effects: &[EffectKind],
    no_limit: NoLimit,
) -> SeparatingRuns {
    let limits = Limits::of(&c.runs, c.settings.min_speed, DEFAULT_AY_SHARE, DEFAULT_AX);
    let (family, _) = family_and_left_out(&fitted.base(c), &limits);
    let runs: Vec<(Kind, f64)> = c.runs.iter().filter_map(kind_of).collect();
    let lacking: Vec<&Designed> = family.iter().filter(|d| !has(&runs, d)).collect();
    let pairs = match effects.split_first() {
        Some((&r, others)) => others
            .iter()
            .filter_map(|&o| pair(c, fitted, (r, o), &lacking, &limits, &runs))
            .collect(),
        None => Vec::new(),
    };
    SeparatingRuns { no_limit, pairs }
}

/// On a base with no friction limit, each confounded set of `d` given its
/// separating runs (the signatures' tests at the limit separate nothing
/// there); nothing elsewhere.
pub fn fill(c: &Campaign, d: &mut crate::diagnose::Diagnosis) {
    let Some(no_limit) = NoLimit::of(&d.base) else {
        return;
    };
    let fitted = Fitted::of(d);
    for set in &mut d.confounded {
        set.separating_runs = Some(separating_runs(c, &fitted, &set.effects, no_limit));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// A run of 10 s at 100 Hz with steer `steer(t)` and speed `speed(t)`.
    fn run(steer: impl Fn(f64) -> f64, speed: impl Fn(f64) -> f64) -> MeasuredRun {
        let t: Vec<f64> = (0..1000).map(|i| i as f64 * 0.01).collect();
        let n = t.len();
        let speed = t.iter().map(|&x| speed(x)).collect();
        // A logger's steer noise, ±0.02°, alternating.
        let steer = t
            .iter()
            .enumerate()
            .map(|(i, &x)| steer(x) + 3.5e-4 * if i % 2 == 0 { 1.0 } else { -1.0 })
            .collect();
        MeasuredRun::new("r.csv", t, speed, steer, vec![0.0; n])
    }

    /// Each kind read from its inputs: a step rising in 0.4 s, a ramp
    /// over 8 s, a sweep, a double lane change, braking in a turn, a
    /// straight speed change; a straight at constant speed is none.
    #[test]
    fn a_campaigns_runs_are_read_as_the_familys_kinds() {
        let u = |_: f64| 22.2;
        let step = |t: f64| 0.05 * ((t - 1.0) / 0.4).clamp(0.0, 1.0);
        let ramp = |t: f64| 0.05 * ((t - 1.0) / 8.0).clamp(0.0, 1.0);
        let sweep = |t: f64| {
            if t < 1.0 {
                0.0
            } else {
                0.02 * (2.0 * PI * 0.8 * (t - 1.0)).sin()
            }
        };
        let lane = |t: f64| {
            if (1.0..4.0).contains(&t) {
                0.03 * (2.0 * PI * (t - 1.0) / 3.0).sin()
            } else {
                0.0
            }
        };
        let brake = |t: f64| 25.0 - 1.0 * t;
        let cases: [(MeasuredRun, Option<Kind>); 6] = [
            (run(step, u), Some(Kind::Step)),
            (run(ramp, u), Some(Kind::Ramp)),
            (run(sweep, u), Some(Kind::Sweep)),
            (run(lane, u), Some(Kind::LaneChange)),
            (run(|_| 0.03, brake), Some(Kind::BrakeInTurn)),
            (run(|_| 0.0, u), None),
        ];
        for (r, want) in &cases {
            assert_eq!(kind_of(r).map(|k| k.0), *want);
        }
        assert_eq!(
            kind_of(&run(|_| 0.0, brake)).map(|k| k.0),
            Some(Kind::SpeedChange)
        );
        let (_, speed) = kind_of(&cases[0].0).unwrap();
        assert!((speed - 22.2).abs() < 1e-9, "{speed}");
    }

    /// A designed run is the campaign's when a run of its kind is within
    /// 10 % of its speed, not when only another kind is.
    #[test]
    fn a_designed_run_is_the_campaigns_only_at_its_kind_and_speed() {
        let d =
            |kind: Kind, u: f64| Designed {
                name: "d".into(),
                kind,
                description: String::new(),
                manoeuvre: crate::manoeuvre::Manoeuvre::Replay(
                    crate::manoeuvre::Replay::of_inputs(vec![0.0, 5.0], vec![0.0, 0.0], vec![u, u]),
                ),
            };
        let runs = [(Kind::Sweep, 22.2), (Kind::Step, 11.1), (Kind::Step, 33.3)];
        assert!(has(&runs, &d(Kind::Sweep, 22.2)));
        assert!(has(&runs, &d(Kind::Sweep, 24.0)));
        assert!(!has(&runs, &d(Kind::Sweep, 11.1)));
        assert!(!has(&runs, &d(Kind::Step, 22.2)));
        assert!(!has(&runs, &d(Kind::Ramp, 22.2)));
        assert_eq!(speeds_of(&runs, Kind::Step), [11.1, 33.3]);
    }
}
