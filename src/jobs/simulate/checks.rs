//! What `simulate` says beside its outputs where the run is not what the
//! scenario's words suggest, for every manoeuvre (the step steer's metrics
//! have their own, [`crate::metrics::applicability`]):
//!
//! - **straight running that needs a steer** ([`super::straight`]): on
//!   tyres that make force at zero slip or on a banked road.
//! - **a slide**: a sideslip beyond
//!   [`SLIDING_SIDESLIP`](crate::metrics::applicability::SLIDING_SIDESLIP)
//!   (10°) anywhere in a ramp, sine, sweep or schedule, where the tyres
//!   use at least [`KINEMATIC_GRIP`] of their grip (below it the sideslip
//!   is a slow car's turn, said as such); and in any
//!   manoeuvre an axle's slip angle beyond
//!   [`SLIDING_SLIP`](super::limits::SLIDING_SLIP) (15°), past the
//!   peak of any road or racing tyre's curve (3–10°): a front axle
//!   ploughing on with the body barely turned, which the sideslip misses.
//! - **a car on two wheels**: both wheels of one side off the ground at
//!   once, a rollover the 2-DOF model does not follow.
//! - **a steer no steering system makes**: a ramp's rate, a sine's or a
//!   sweep's peak rate (`2π·f·A`) beyond
//!   [`STEER_RATE`](crate::metrics::applicability::STEER_RATE).
//! - **tyres beyond the data they were fitted to**: the rows whose wheel
//!   loads or axle slip angles leave a tyre file's `[fitted_ranges]`
//!   (each wheel at zero slip ratio and camber, as the 2-DOF model
//!   evaluates it), counted per axle; and likewise the rows beyond a
//!   `.tir`'s own ranges (`FZMIN`/`FZMAX`, `ALPMIN`/`ALPMAX`,
//!   `CAMMIN`/`CAMMAX`, `KPUMIN`/`KPUMAX`, and `PRESMIN`/`PRESMAX`
//!   against the file's own `INFLPRES` (else `NOMPRES`), which its wheels
//!   run at: a scenario states no pressure), where the Magic Formula holds
//!   each input at its range's end (MFeval's limit checks) or, with them
//!   off, extrapolates. A range with one end given is said as `≥ X` or
//!   `≤ X`.
//!
//! - **a `.tir` whose pure curves peak beyond any tyre's** (|F|/Fz above
//!   2.5), as `tyre-eval` says it, and one whose `FNOMIN` is far from the
//!   car's wheel loads ([`super::nominal_load`]).
//!
//! Units: rad, rad/s, N, s; printed in degrees where a driver reads them.

use super::limits::wrapped;
use crate::io::fitted_ranges::{past_by, FittedRanges, RangePoint, SLACK};
use crate::io::Scenario;
use crate::manoeuvre::Manoeuvre;
use crate::metrics::applicability::{kinematic_turn, KINEMATIC_GRIP, SLIDING_SIDESLIP, STEER_RATE};
use crate::metrics::{Ceiling, Settling, StepMetrics};
use crate::sim::TimeHistory;
use crate::tyre::mf::{MagicFormula, TyreSide};
use crate::tyre::Tyre;
use std::f64::consts::TAU;

/// What `simulate` says: notes (facts of the run) and warnings (where the
/// run is not what its words suggest).
#[derive(Debug, Default)]
pub(super) struct Said {
    pub notes: Vec<String>,
    pub warnings: Vec<String>,
}

/// Everything this module says about scenario `sc` and its history `h`.
pub(super) fn checks(sc: &Scenario, h: &TimeHistory) -> Said {
    let mut said = Said::default();
    said.notes.extend(sc.unread.iter().map(|u| u.note()));
    said.notes
        .extend(sc.kmh_speed.as_ref().map(|k| k.to_string()));
    for r in &sc.remarks {
        match r.is_note() {
            true => said.notes.push(r.to_string()),
            false => said.warnings.push(r.to_string()),
        }
    }
    said.warnings.extend(sc.model.vehicle.unlikely());
    match super::straight::straight_running(sc) {
        Some(super::straight::Straight::Note(n)) => said.notes.push(n),
        Some(super::straight::Straight::Warning(w)) => said.warnings.push(w),
        None => {}
    }
    said.warnings.extend(super::idle_effects::idle_effects(sc));
    if !matches!(sc.manoeuvre, Manoeuvre::StepSteer(_)) {
        said.warnings.extend(sliding(h, axle_friction(sc)));
    } else if let Some(mu) = axle_friction(sc) {
        said.warnings
            .extend(steady_at_limit(h, mu, sc.integrator.friction));
    }
    said.warnings
        .extend(super::limits::axle_sliding(sc, h, static_friction(sc)));
    said.warnings.extend(super::limits::beyond_any_tyre(sc, h));
    said.warnings.extend(on_two_wheels(h));
    said.warnings.extend(steer_rate(&sc.manoeuvre));
    said.warnings.extend(tir_friction(sc));
    said.warnings.extend(super::unlimited::run_beyond_road(
        &sc.model,
        sc.integrator.friction,
        &h.ay,
    ));
    let [front, rear] = super::nominal_load::far_from_nominal(sc);
    said.warnings.extend(per_axle_tir(front, rear));
    said.warnings.extend(variance_window(sc));
    let tyres = [&sc.model.front, &sc.model.rear];
    for (axle, ranges) in sc.fitted_ranges.iter().enumerate() {
        if let Some(r) = ranges {
            // Only the ranges of inputs the model reads, as tyre-eval
            // judges them (a linear tyre's load, a Gim tyre's camber).
            let r = crate::jobs::tyre_eval::read_ranges(tyres[axle], r);
            said.warnings
                .extend(beyond_fitted(axle, &r, RangeSource::Fitted, h));
        }
    }
    for (axle, tyre) in tyres.into_iter().enumerate() {
        if let Tyre::MagicFormula(t) = tyre {
            let source = RangeSource::Tir {
                held: t.options.limit_checks,
                pressure: t.own_pressure(),
            };
            said.warnings
                .extend(beyond_fitted(axle, &tir_ranges(t), source, h));
        }
    }
    said
}

/// A `.tir` whose pure curves peak above
/// [`WARN_FRICTION`](crate::tyre::mf::WARN_FRICTION) (2.5), warned as
/// `tyre-eval` warns of it: `simulate` ran the public `FSAE_Defaults.tir`
/// (3.37 at 250 N) without a word. One line for both axles where they
/// share the file's peak.
fn tir_friction(sc: &Scenario) -> Vec<String> {
    tir_friction_of([&sc.model.front, &sc.model.rear])
}

/// [`tir_friction`] of a front and a rear tyre (a campaign's given files).
pub(crate) fn tir_friction_of(tyres: [&Tyre; 2]) -> Vec<String> {
    let [front, rear] = tyres.map(|t| crate::jobs::tyre_eval::peak_of(t).map(|p| p.to_string()));
    per_axle_tir(front, rear)
}

/// What is said of each axle's `.tir` (`None`: nothing), one line for both
/// where they say the same.
pub(crate) fn per_axle_tir(front: Option<String>, rear: Option<String>) -> Vec<String> {
    match (front, rear) {
        (Some(f), Some(r)) if f == r => vec![format!("the front and rear tyres' .tir: {f}")],
        (f, r) => [("front", f), ("rear", r)]
            .into_iter()
            .filter_map(|(axle, p)| p.map(|p| format!("the {axle} tyres' .tir: {p}")))
            .collect(),
    }
}

/// Share of the asked steady lateral acceleration by which a step sized
/// for it may settle elsewhere unsaid: the steady window's own scatter
/// and the metrics' averaging stay far inside it.
pub(super) const ASKED_AY_MISS: f64 = 0.02;

/// Why a step misses its asked ay, where its run does not show it nearing
/// the state solved for ([`super::approach`] says where it does).
pub(super) const ANOTHER_STATE: &str = "the steady state its steer was solved from is not the one the step reaches (an unstable one past an axle's peak, where the car settles on another, or a slide)";

/// A step steer sized for a steady lateral acceleration `asked` (m/s²)
/// whose run ends beyond [`ASKED_AY_MISS`] of it (the metrics' steady
/// change, `m.ay_steady`): the steady state its steer was solved from is
/// not the one the step reaches (past an axle's peak it is unstable and
/// the car settles on another branch, or slides on). A run whose steady
/// window has not settled ([`StepMetrics::settled`]) settles nowhere yet:
/// its window's mean is said as that, with where its trend heads where the
/// metrics know it ([`trend_heads`]), never as where "the run settles".
pub(super) fn asked_ay_missed(
    asked: f64,
    m: &StepMetrics,
    ceiling: Option<&Ceiling>,
) -> Option<String> {
    let reached = m.ay_steady?;
    let miss = (reached - asked) / asked.abs().max(1e-12);
    if miss.abs() <= ASKED_AY_MISS {
        return None;
    }
    let why = ANOTHER_STATE;
    let (asked_text, reached_text, miss_text) = (
        crate::format::exact(asked),
        crate::format::fixed(reached, 2),
        crate::format::signed(100.0 * miss, 0),
    );
    if m.settled {
        return Some(format!(
            "the step was sized for a steady lateral acceleration of {asked_text} m/s² (`lateral_acceleration`), but the run settles at {reached_text} m/s² ({miss_text} %): {why}; the metrics describe the run, not {asked_text} m/s²"
        ));
    }
    let moving = match trend_heads(m, reached, ceiling) {
        Some(h) => format!("still moving: its trend {h}"),
        None => "still moving at the end of the run".into(),
    };
    Some(format!(
        "the step was sized for a steady lateral acceleration of {asked_text} m/s² (`lateral_acceleration`), but the run has not settled: its lateral acceleration averages {reached_text} m/s² ({miss_text} %) over the steady window and is {moving}, so it reaches no steady state within the run; {why}; the metrics describe a run still moving, not a steady turn at {asked_text} m/s² (a longer `end` shows where it goes)"
    ))
}

/// Where the lateral acceleration's trend heads from its steady window's
/// mean `reached` (m/s²), where the metrics measured one, in words: a
/// trend is a line through the window, and where carrying it on would
/// pass the `ceiling` (the most |ay| this car reaches on this road) it is
/// said to climb toward it, with the room left, not where the line goes.
fn trend_heads(m: &StepMetrics, reached: f64, ceiling: Option<&Ceiling>) -> Option<String> {
    let (heads, rising) = match m.settling.ay? {
        Settling::Drifting { heads, rising, .. } | Settling::Approaching { heads, rising } => {
            (heads, rising)
        }
        _ => return None,
    };
    let by = heads * reached.abs();
    let by_text = crate::format::fixed(by, 2);
    let passes = |c: &&Ceiling| rising && reached.abs() + by > c.limit.value;
    let Some(c) = ceiling.filter(passes) else {
        let toward = if rising { "beyond" } else { "back below" };
        return Some(format!("heads {by_text} m/s² {toward} that mean"));
    };
    let room = c.limit.value - reached.abs();
    Some(match room > 0.0 {
        true => format!(
            "climbs toward {}, {} m/s² above that mean (carried on, a line through the window would pass it, where no car on this road goes)",
            c.limit,
            crate::format::fixed(room, 2)
        ),
        false => format!("climbs on beyond {}, which the run already passes", c.limit),
    })
}

/// Where `x` goes beyond `limit` in magnitude: its largest value, the
/// row of it and the first row beyond.
fn largest_beyond(x: &[f64], limit: f64) -> Option<(f64, usize, usize)> {
    let from = x.iter().position(|v| v.abs() > limit)?;
    let (i, v) = x
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))?;
    Some((*v, i, from))
}

/// The peak friction coefficient of the front and rear tyres at static
/// load on this road (friction scale included); infinite for a tyre with
/// no limit (linear).
fn static_friction(sc: &Scenario) -> [f64; 2] {
    super::unlimited::static_friction(&sc.model, sc.integrator.friction)
}

/// [`static_friction`] where both tyres have one.
pub(super) fn axle_friction(sc: &Scenario) -> Option<[f64; 2]> {
    let [f, r] = static_friction(sc);
    (f.is_finite() && r.is_finite() && f > 0.0 && r > 0.0).then_some([f, r])
}

/// Whether neither axle's tyre has a friction limit (linear tyres): a
/// yaw rate that overshoots on them is no car losing grip.
pub(super) fn gripless(sc: &Scenario) -> bool {
    static_friction(sc) == [f64::INFINITY; 2]
}

/// The share of its grip the busier axle uses at row `k`: its lateral
/// force over its peak (`μ` of [`axle_friction`] times its load).
fn grip_used(h: &TimeHistory, mu: [f64; 2], k: usize) -> f64 {
    let front = h.fy_front[k].abs() / (mu[0] * (h.fz[0][k] + h.fz[1][k]));
    let rear = h.fy_rear[k].abs() / (mu[1] * (h.fz[2][k] + h.fz[3][k]));
    front.max(rear)
}

/// The most of its grip the busier axle uses at any row ([`grip_used`];
/// rows with an axle off the ground left out).
pub(super) fn peak_grip_used(h: &TimeHistory, mu: [f64; 2]) -> f64 {
    (0..h.len())
        .map(|k| grip_used(h, mu, k))
        .filter(|s| s.is_finite())
        .fold(0.0, f64::max)
}

/// A slide: the largest sideslip, where beyond [`SLIDING_SIDESLIP`]; where
/// the tyres of `mu` ([`axle_friction`]) use under [`KINEMATIC_GRIP`] of
/// their grip at every such row, a kinematic turn instead.
fn sliding(h: &TimeHistory, mu: Option<[f64; 2]>) -> Option<String> {
    let (beta, i, from) = largest_beyond(&h.beta, SLIDING_SIDESLIP)?;
    let share = mu.map(|mu| {
        (0..h.len())
            .filter(|&k| h.beta[k].abs() > SLIDING_SIDESLIP)
            .map(|k| grip_used(h, mu, k))
            .fold(0.0, f64::max)
    });
    if let Some(share) = share.filter(|s| *s < KINEMATIC_GRIP) {
        return Some(format!(
            "the sideslip reaches {:.1}° at t = {:.2} s (beyond 10° from t = {:.2} s), {}",
            beta.to_degrees(),
            h.t[i],
            h.t[from],
            kinematic_turn(share, "their grip", h.speed[i], h.steer[i])
        ));
    }
    Some(format!(
        "the sideslip reaches {:.1}° at t = {:.2} s (beyond 10° from t = {:.2} s): the car slides past its grip, where a 2-DOF model with the tyres' steady curves no longer says how a car behaves",
        beta.to_degrees(),
        h.t[i],
        h.t[from]
    ))
}

/// The share of its grip the busier axle may use at the end of a step
/// steer before its steady state is the friction limit: within 5 % the
/// tyres are on the flat top of their curves.
pub(super) const AT_LIMIT: f64 = 0.95;

/// A step steer whose busier axle uses at least [`AT_LIMIT`] of its grip
/// (tyres of `mu`, [`axle_friction`], on a road of friction `road`) at
/// its last row: the steady values are the limit's (ay ≈ μg), and the
/// response times and Er of a car that cannot turn further read as good
/// handling (a road friction of 1e-9 gave an Er better than the car's).
fn steady_at_limit(h: &TimeHistory, mu: [f64; 2], road: f64) -> Option<String> {
    let k = h.len().checked_sub(1)?;
    let used = grip_used(h, mu, k);
    (used.is_finite() && used >= AT_LIMIT).then(|| {
        format!(
            "at the end of the step the busier axle uses {} % of its grip (ay {} m/s² at the last row, t = {} s, on a road of friction {}; the metrics' steady ay is the mean of the steady window): the car turns at its friction limit, so the response times, the yaw-rate gain and Er describe that limit, not the car's handling; a smaller step, or a road with more grip, measures handling",
            crate::format::fixed(100.0 * used, 0),
            crate::format::rounded(h.ay[k].abs(), 3),
            crate::format::rounded(h.t[k], 3),
            crate::error::Num(road)
        )
    })
}

/// Both wheels of one side off the ground at the same row: the first such
/// row.
fn on_two_wheels(h: &TimeHistory) -> Option<String> {
    let off = |w: usize, k: usize| h.fz[w][k] <= 0.0;
    let k = (0..h.len()).find(|&k| (off(0, k) && off(2, k)) || (off(1, k) && off(3, k)))?;
    let side = if off(0, k) { "left" } else { "right" };
    Some(format!(
        "both {side} wheels are off the ground at t = {:.2} s: the car is on two wheels, rolling over, which a model without a roll-over degree of freedom does not follow; the run past it, and its metrics, describe no car",
        h.t[k]
    ))
}

/// A step's total-variance window running past the record's end: the
/// metrics take the variances over what was recorded (as `metrics` says
/// for a measured run).
fn variance_window(sc: &Scenario) -> Option<String> {
    let Manoeuvre::StepSteer(s) = &sc.manoeuvre else {
        return None;
    };
    let w = sc.metrics.variance_window;
    (s.start + w > s.end).then(|| {
        format!(
            "the total-variance window, `variance_window` = {} s, is longer than the record after the step ({:.2} s, from the step at t = {} s to `end` = {} s): the variances are over what was recorded; lengthen `end` or shorten the window",
            crate::error::Num(w),
            s.end - s.start,
            crate::error::Num(s.start),
            crate::error::Num(s.end)
        )
    })
}

/// The input's fastest road-wheel steer rate, where beyond [`STEER_RATE`].
fn steer_rate(m: &Manoeuvre) -> Option<String> {
    let (rate, what) = match m {
        Manoeuvre::RampSteer(r) => (r.rate.abs(), "the ramp's rate".to_string()),
        Manoeuvre::Sine(s) => (
            TAU * s.frequency * s.amplitude.abs(),
            format!("the sine's peak rate (2π·{} Hz·amplitude)", s.frequency),
        ),
        Manoeuvre::Sweep(s) => {
            let f = s.f_start.max(s.f_end);
            (
                TAU * f * s.amplitude.abs(),
                format!("the sweep's peak rate at {f} Hz (2π·f·amplitude)"),
            )
        }
        // A step's rise is checked against ISO 7401's timing, a
        // schedule's pieces by `schedule_applicability`.
        Manoeuvre::StepSteer(_) | Manoeuvre::Replay(_) => return None,
    };
    (rate > STEER_RATE).then(|| {
        format!(
            "{what} is {rate:.1} rad/s ({:.0}°/s at the road wheels), faster than a steering system turns the wheels (up to about {STEER_RATE} rad/s; a steering robot's 3,000°/s at the handwheel is about 3.5 rad/s): no driver or robot can steer this input",
            rate.to_degrees()
        )
    })
}

/// Where a tyre's ranges come from, for what the model does beyond them.
#[derive(Debug, Clone, Copy)]
enum RangeSource {
    /// A TOML tyre's `[fitted_ranges]`: its model extrapolates.
    Fitted,
    /// A `.tir`'s own validity ranges: the Magic Formula holds each input
    /// at its range's end where the limit checks are on (`held`), and
    /// extrapolates where they are off. Its wheels run at the file's own
    /// `pressure` (Pa, and the key that gives it; a scenario states none),
    /// `None` where no pressure moves the model.
    Tir {
        held: bool,
        pressure: Option<(f64, &'static str)>,
    },
}

impl RangeSource {
    /// What the ranges are and how the model evaluates beyond them, in
    /// words.
    fn words(self) -> (&'static str, &'static str) {
        match self {
            RangeSource::Fitted => (
                "the ranges of the rig data they were fitted to",
                "their [fitted_ranges]; each wheel at zero slip ratio and camber, as the 2-DOF model evaluates it), evaluated by extrapolation",
            ),
            RangeSource::Tir { held: true, .. } => (
                "their .tir's validity ranges",
                "its *_RANGE sections; each wheel at zero slip ratio and camber, as the 2-DOF model evaluates it), evaluated at the ranges' ends, a load below FZMIN excepted (MFeval's limit checks: the force stays that of the range's end, however far beyond; a load below FZMIN is not raised to it, its force is evaluated at the load given)",
            ),
            RangeSource::Tir { held: false, .. } => (
                "their .tir's validity ranges",
                "its *_RANGE sections; each wheel at zero slip ratio and camber, as the 2-DOF model evaluates it), evaluated by extrapolation (the limit checks are off)",
            ),
        }
    }

    /// The inflation pressure the wheels run at, where it is checked.
    fn pressure(self) -> Option<(f64, &'static str)> {
        match self {
            RangeSource::Fitted => None,
            RangeSource::Tir { pressure, .. } => pressure,
        }
    }
}

/// A `.tir`'s validity ranges in the crate's convention (the file states
/// slip and camber in its own frame: a left-side file's slip angle is the
/// crate's negated, a right-side file's camber is), a missing bound
/// unbounded ([`ranges_text`] says such a range as `≥ X` or `≤ X`).
fn tir_ranges(t: &MagicFormula) -> FittedRanges {
    let l = &t.limits;
    let range = |lo: Option<f64>, hi: Option<f64>| {
        (lo.is_some() || hi.is_some())
            .then(|| [lo.unwrap_or(f64::NEG_INFINITY), hi.unwrap_or(f64::INFINITY)])
    };
    let negated = |r: Option<[f64; 2]>| r.map(|[lo, hi]| [-hi, -lo]);
    let alpha = range(l.alpha_min, l.alpha_max);
    let camber = range(l.camber_min, l.camber_max);
    let right = t.side == TyreSide::Right;
    FittedRanges {
        fz: range(l.fz_min, l.fz_max),
        alpha: if right { alpha } else { negated(alpha) },
        kappa: range(l.kappa_min, l.kappa_max),
        camber: if right { negated(camber) } else { camber },
        pressure: range(l.pressure_min, l.pressure_max),
    }
}

/// The ranges of `r` in words, as [`FittedRanges::text`] gives them
/// (`fz 0 to 2000 N, alpha -0.2000 to 0.2000 rad`), a range with one end
/// (a `.tir` that gives `FZMAX` and no `FZMIN`) as `fz ≤ 2000 N` or
/// `fz ≥ 100 N`, not with an `inf` end.
fn ranges_text(r: &FittedRanges) -> String {
    let named = [
        ("fz", " N", r.fz),
        ("alpha", " rad", r.alpha),
        ("kappa", "", r.kappa),
        ("camber", " rad", r.camber),
        ("pressure", " Pa", r.pressure),
    ];
    let n = |v: f64| crate::format::readable(v, 4);
    let parts: Vec<String> = named
        .into_iter()
        .filter_map(|(name, unit, range)| {
            let [lo, hi] = range?;
            Some(match (lo.is_finite(), hi.is_finite()) {
                (true, true) if n(lo) == n(hi) => format!("{name} {}{unit} only", n(lo)),
                (true, true) => format!("{name} {} to {}{unit}", n(lo), n(hi)),
                (true, false) => format!("{name} ≥ {}{unit}", n(lo)),
                (false, true) => format!("{name} ≤ {}{unit}", n(hi)),
                (false, false) => return None,
            })
        })
        .collect();
    parts.join(", ")
}

/// The simulation's constant inputs (no slip ratio, no camber, the file's
/// pressure) past the ranges `r` with `share` of slack, in words. Apart from
/// [`beyond_fitted`] so that it reads on a screen.
fn constants_past(r: &FittedRanges, share: f64, pressure: Option<(f64, &str)>) -> Vec<String> {
    let mut out = Vec::new();
    // A constant input past its range, by the rule tyre-eval says its
    // points by: a one-level range by its distance, a sweep by its span.
    let past = |key: &str, range: Option<[f64; 2]>, v: f64, unit: &str| {
        let range = range.filter(|r| past_by(*r, v, share).is_some())?;
        let level = crate::jobs::tyre_eval::one_level(key, range).then(|| {
            let mid = crate::format::readable(0.5 * (range[0] + range[1]), 4);
            format!(", one level of the data at {mid}{unit}")
        });
        Some(format!(
            "{}{}",
            crate::jobs::tyre_eval::past_end(key, range, v, unit),
            level.unwrap_or_default()
        ))
    };
    out.extend(past("kappa", r.kappa, 0.0, "").map(|w| format!("a slip ratio of 0 ({w})")));
    out.extend(past("camber", r.camber, 0.0, " rad").map(|w| format!("a camber of 0 rad ({w})")));
    if let Some((p, key)) = pressure {
        out.extend(past("pressure", r.pressure, p, " Pa").map(|w| {
            format!(
                "a pressure of {} Pa (the file's {key}), {w}",
                crate::format::readable(p, 4)
            )
        }));
    }
    out
}

/// The rows whose wheels leave the ranges `r` of the tyre of `axle` (0
/// front, 1 rear), from `source`: counted, with the extremes reached.
fn beyond_fitted(
    axle: usize,
    r: &FittedRanges,
    source: RangeSource,
    h: &TimeHistory,
) -> Option<String> {
    let (name, wheels, alpha) = if axle == 0 {
        ("front", [&h.fz[0], &h.fz[1]], &h.alpha_front)
    } else {
        ("rear", [&h.fz[2], &h.fz[3]], &h.alpha_rear)
    };
    let pressure = source.pressure();
    // Rig data's ends are read with their scatter; a `.tir`'s are where
    // the model clamps.
    let share = match source {
        RangeSource::Fitted => SLACK,
        RangeSource::Tir { .. } => 0.0,
    };
    let point = |fz: f64, alpha: f64| RangePoint {
        fz,
        alpha,
        kappa: 0.0,
        camber: 0.0,
        pressure: pressure.map(|p| p.0),
    };
    let rows: Vec<usize> = (0..h.len())
        .filter(|&i| {
            wheels
                .iter()
                .any(|fz| r.outside(&point(fz[i], wrapped(alpha[i])), share))
        })
        .collect();
    if rows.is_empty() {
        return None;
    }
    // What left the ranges: the extent of the values beyond their own
    // range, over the rows outside.
    let out_of =
        |range: Option<[f64; 2]>, v: f64| range.is_some_and(|r| past_by(r, v, share).is_some());
    let extent = |x: &mut dyn Iterator<Item = f64>| {
        x.fold(None, |e: Option<(f64, f64)>, v| {
            Some(e.map_or((v, v), |(lo, hi)| (lo.min(v), hi.max(v))))
        })
    };
    let mut what = Vec::new();
    let loads = rows.iter().flat_map(|&i| wheels.iter().map(move |w| w[i]));
    if let Some((lo, hi)) = extent(&mut loads.filter(|&v| v > 0.0 && out_of(r.fz, v))) {
        what.push(match format!("{lo:.0}") == format!("{hi:.0}") {
            true => format!("a wheel load of {lo:.0} N"),
            false => format!("wheel loads {lo:.0} to {hi:.0} N"),
        });
    }
    if let Some((lo, hi)) = extent(
        &mut rows
            .iter()
            .map(|&i| wrapped(alpha[i]))
            .filter(|&v| out_of(r.alpha, v)),
    ) {
        what.push(match format!("{lo:.4}") == format!("{hi:.4}") {
            true => format!("a slip angle of {lo:.4} rad ({:.2}°)", lo.to_degrees()),
            false => format!(
                "slip angles {lo:.4} to {hi:.4} rad ({:.2}° to {:.2}°)",
                lo.to_degrees(),
                hi.to_degrees()
            ),
        });
    }
    what.extend(constants_past(r, share, pressure));
    let (ranges, evaluated) = source.words();
    Some(format!(
        "{} of {} rows take the {name} tyres outside {ranges} ({}; {evaluated}: there, {}",
        rows.len(),
        h.len(),
        ranges_text(r),
        what.join(", ")
    ))
}
