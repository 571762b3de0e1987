//! A step sized for a steady lateral acceleration that the run misses
//! ([`super::checks::asked_ay_missed`]), told apart: a run that ends
//! before the car settles, still approaching the steady state its steer
//! was solved from, from one that settles on another branch or slides
//! away. The solved steady state's stability is the 2-DOF linearisation's
//! there (the equilibria's eigenvalues, [`crate::equilibria`]); the
//! approach is read on the run, channel by channel (lateral acceleration,
//! yaw rate, sideslip), each gap from the solved value a share of its
//! step: the time constant from the gap's last two peaks after the step's
//! rise (a focus's oscillation), or, with fewer (a node's monotone
//! approach), from the largest gaps of the last two windows of the
//! linearisation's time constant. Where every gap shrinks with a time
//! constant shorter than the record after the step, the car is
//! approaching: carried on at those rates, each gap is within [`WITHIN`]
//! of its step from a time said, and an `end` that leaves the steady
//! window after that is said too; where they shrink slower, the run
//! cannot tell yet. Round 42: the sedan stepped for 8.5 m/s², ended at
//! 6 s, was said to reach "not the one" steady state (an unstable one, or
//! a slide); run to 20 s it settles at 8.5000 m/s².
//!
//! Units: m/s², s, rad, 1/s.

use super::checks::{ANOTHER_STATE, ASKED_AY_MISS};
use crate::equilibria::stability::Stability;
use crate::equilibria::{lagged, Condition};
use crate::io::Scenario;
use crate::manoeuvre::Manoeuvre;
use crate::metrics::{Ceiling, StepMetrics};
use crate::sim::TimeHistory;
use std::f64::consts::PI;

/// The steady state the step's steer was solved from: its lateral
/// acceleration (m/s², as the history's `ay` reads it), yaw rate (rad/s)
/// and sideslip (rad), and its stability.
#[derive(Debug, Clone, Copy)]
struct Solved {
    state: [f64; 3],
    stability: Stability,
}

/// The solved steady state of scenario `sc`'s step asked for `asked`
/// (m/s², the change from straight running), as the scenario solved it.
fn solved(sc: &Scenario, asked: f64) -> Option<Solved> {
    let Manoeuvre::StepSteer(s) = &sc.manoeuvre else {
        return None;
    };
    let (model, friction) = (&sc.model, sc.integrator.friction);
    let ay = model.bank_acceleration() + asked;
    let ss = model
        .steady_state_for_lateral_acceleration(s.speed, friction, ay)
        .ok()?;
    let c = Condition {
        steer: ss.steer,
        friction,
        speed: s.speed,
    };
    Some(Solved {
        state: [ss.ay, ss.yaw_rate, ss.beta],
        stability: lagged::classify(model, &c, [ss.beta, ss.yaw_rate]),
    })
}

/// The names of the channels of [`Solved::state`].
const CHANNELS: [&str; 3] = ["lateral acceleration", "yaw rate", "sideslip"];

/// How one channel approaches its solved value, its gap a share of its
/// step: the gap's last peak (time s, gap) and the time constant (s) from
/// its last two peaks, or, where the gap has no two (a node's monotone
/// approach), from the largest gaps of the last two windows of `w` s.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Approach {
    at: f64,
    gap: f64,
    tau: f64,
}

/// The largest gap of `g` (time s, gap) in `lo < t ≤ hi`.
fn largest(g: &[(f64, f64)], lo: f64, hi: f64) -> Option<(f64, f64)> {
    g.iter()
        .filter(|p| p.0 > lo && p.0 <= hi)
        .copied()
        .fold(None, |m: Option<(f64, f64)>, p| match m {
            Some(m) if m.1 >= p.1 => Some(m),
            _ => Some(p),
        })
}

/// [`Approach`] of channel `x` (times `t`) to `target` from its value at
/// the run's start, over the rows after `from` (s).
fn approach(t: &[f64], x: &[f64], target: f64, from: f64, w: f64) -> Option<Approach> {
    let step = (target - x.first()?).abs();
    let g: Vec<(f64, f64)> = t
        .iter()
        .zip(x)
        .filter(|(t, _)| **t > from)
        .map(|(t, v)| (*t, (v - target).abs() / step))
        .collect();
    let peaks: Vec<(f64, f64)> = (1..g.len().saturating_sub(1))
        .filter(|&k| g[k].1 > g[k - 1].1 && g[k].1 >= g[k + 1].1)
        .map(|k| g[k])
        .collect();
    let (a, b) = match peaks.len() {
        n if n >= 2 => (peaks[n - 2], peaks[n - 1]),
        _ => {
            let end = g.last()?.0;
            (
                largest(&g, end - 2.0 * w, end - w)?,
                largest(&g, end - w, end)?,
            )
        }
    };
    let tau = (b.0 - a.0) / (a.1 / b.1).ln();
    (step > 0.0 && tau.is_finite()).then_some(Approach {
        at: b.0,
        gap: b.1,
        tau,
    })
}

/// The window of [`approach`]'s fallback: half the linearisation's
/// period for a focus, its slow time constant for a node, at most half of
/// `record` (s).
fn window(s: &Stability, record: f64) -> f64 {
    let (re, im) = s.eigenvalues[0];
    let w = match im != 0.0 {
        true => PI / im.abs(),
        false => 1.0 / re.abs(),
    };
    w.min(0.5 * record)
}

/// Eigenvalues in words: "−0.55 ± 1.55i 1/s" or "−0.31 and −4.2 1/s".
fn eigen_words(s: &Stability) -> String {
    let [(r0, i0), (r1, _)] = s.eigenvalues;
    let n = |v: f64| crate::format::rounded(v, 3);
    match i0 != 0.0 {
        true => format!("{} ± {}i 1/s", n(r0), n(i0.abs())),
        false => format!("{} and {} 1/s", n(r0), n(r1)),
    }
}

/// The asked-ay warning of a step sized for `asked` (m/s²) with metrics
/// `m`: where the run has not settled but approaches a stable solved
/// steady state, every channel's gap from it falling with a time constant
/// shorter than the record after the step, that it ends before the car
/// settles ([`ends_before`]), and where they shrink slower than the run
/// can measure, that it cannot tell yet, each in place of
/// [`ANOTHER_STATE`]; elsewhere the words of
/// [`super::checks::asked_ay_missed`] (another branch, or a slide), with
/// the solved steady state's stability.
pub(super) fn asked_ay_words(
    sc: &Scenario,
    h: &TimeHistory,
    asked: f64,
    m: &StepMetrics,
    ceiling: Option<&Ceiling>,
) -> Option<String> {
    let missed = super::checks::asked_ay_missed(asked, m, ceiling)?;
    let (Some(x), Manoeuvre::StepSteer(s)) = (solved(sc, asked), &sc.manoeuvre) else {
        return Some(missed);
    };
    let kind = x.stability.kind;
    let state = format!(
        "the solved steady state is a {} (eigenvalues {})",
        kind.name().replace('-', " "),
        eigen_words(&x.stability)
    );
    let from = s.start + s.rise_time;
    let record = h.t.last()? - from;
    let w = window(&x.stability, record);
    let channels = [&h.ay, &h.yaw_rate, &h.beta];
    let each: Option<Vec<Approach>> = (0..3)
        .map(|c| approach(&h.t, channels[c], x.state[c], from, w))
        .collect();
    let shrinking = each
        .filter(|a| a.iter().all(|a| a.tau > 0.0))
        .filter(|_| kind.is_stable() && !m.settled);
    // The metrics' words up to why the run misses (its mean, its trend)
    // stand; why is what the run shows.
    let head = missed.find(ANOTHER_STATE).map(|i| &missed[..i]);
    Some(match (shrinking, head) {
        (Some(a), Some(head)) if a.iter().all(|a| a.tau < record) => {
            format!("{head}{}", ends_before(sc, h, (&x, &state), &a))
        }
        (Some(a), Some(head)) => {
            let tau = a.iter().map(|a| a.tau).fold(0.0, f64::max);
            format!(
                "{head}the run cannot yet tell whether the car settles at the steady state its steer was solved from: {state}, and the run's gaps from it shrink, but with time constants up to τ ≈ {} s, longer than the {} s it runs after the step (a longer `end` shows where it goes)",
                crate::format::significant(tau, 2),
                crate::format::fixed(record, 2)
            )
        }
        _ => format!("{missed}; {state}"),
    })
}

/// The share of each channel's step its gap must be within for the run to
/// be read as settled: half the 2 % a steady window may spread by
/// ([`ASKED_AY_MISS`]), a window's spread being at most twice the gap.
const WITHIN: f64 = 0.5 * ASKED_AY_MISS;

/// Why the run misses its asked ay where it ends before the car settles:
/// where its ay is at the end against the solved `x`, the slowest channel's approach of
/// `a` (its time constant), and when, carried on at its own rate, every
/// channel's gap is within [`WITHIN`] of its step: the `end` that leaves
/// the steady window after that.
fn ends_before(
    sc: &Scenario,
    h: &TimeHistory,
    (x, state): (&Solved, &str),
    a: &[Approach],
) -> String {
    let last = h.len() - 1;
    let (t, ay) = (h.t[last], h.ay[last]);
    let within = a
        .iter()
        .map(|a| a.at + a.tau * (a.gap / WITHIN).ln().max(0.0))
        .fold(t, f64::max);
    let end = (within + sc.metrics.steady_window).ceil();
    let slow = (0..a.len())
        .max_by(|&i, &j| a[i].tau.total_cmp(&a[j].tau))
        .unwrap_or(0);
    let rising = last > 0 && ay.abs() > h.ay[last - 1].abs();
    let f2 = |v: f64| crate::format::fixed(v, 2);
    format!(
        "the run ends before the car settles, still approaching the steady state its steer was solved from: at t = {} s its lateral acceleration is {} m/s², {} % of the solved {} m/s², still {}; {state}, and the gaps of the run's lateral acceleration, yaw rate and sideslip from it fall with time constants up to τ ≈ {} s (the {}'s, whose gap peaks last at {} % of its step at t = {} s); carried on, each is within {} % of its step from about t = {} s: run to `end` ≥ {} s (the {} s steady window after that) to read the steady state; the metrics describe a run still moving",
        f2(t),
        f2(ay),
        crate::format::fixed(100.0 * ay / x.state[0], 1),
        crate::format::rounded(x.state[0], 4),
        match rising {
            true => "rising",
            false => "falling",
        },
        crate::format::significant(a[slow].tau, 2),
        CHANNELS[slow],
        crate::format::fixed(100.0 * a[slow].gap, 1),
        f2(a[slow].at),
        crate::format::fixed(100.0 * WITHIN, 0),
        crate::format::fixed(within, 1),
        end,
        crate::error::Num(sc.metrics.steady_window)
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::equilibria::stability::Kind;

    fn stability(kind: Kind, eigenvalues: [(f64, f64); 2]) -> Stability {
        Stability {
            kind,
            eigenvalues,
            trace: 0.0,
            determinant: 0.0,
        }
    }

    /// A focus's window is half its period, a node's its slow time
    /// constant, each held to half the record.
    #[test]
    fn the_window_holds_one_peak_of_a_focus() {
        let focus = stability(Kind::StableFocus, [(-0.5, 1.0), (-0.5, -1.0)]);
        assert!((window(&focus, 100.0) - PI).abs() < 1e-12);
        assert!((window(&focus, 4.0) - 2.0).abs() < 1e-12);
        let node = stability(Kind::StableNode, [(-0.25, 0.0), (-4.0, 0.0)]);
        assert!((window(&node, 100.0) - 4.0).abs() < 1e-12);
        assert_eq!(eigen_words(&node), "-0.25 and -4 1/s");
    }

    /// A gap decaying as e^(−t/τ) gives τ back from its two windows; a
    /// decaying oscillation from its last two peaks.
    #[test]
    fn a_decaying_gap_gives_its_time_constant() {
        let t: Vec<f64> = (0..=6000).map(|i| i as f64 * 1e-3).collect();
        let node: Vec<f64> = t.iter().map(|t| 8.5 - 8.5 * (-t / 1.8).exp()).collect();
        let a = approach(&t, &node, 8.5, 1.0, 2.0).unwrap();
        assert!((a.tau - 1.8).abs() < 1e-3, "{a:?}");
        let focus: Vec<f64> = t
            .iter()
            .map(|t| 8.5 - 8.5 * (-t / 1.8).exp() * (1.5 * t).cos())
            .collect();
        let a = approach(&t, &focus, 8.5, 1.0, 2.0).unwrap();
        // Peaks of |e^(−t/τ)·cos ωt| lie before those of the cosine, each
        // by atan(1/(ωτ))/ω: their ratio is e^(π/(ωτ)).
        assert!((a.tau - 1.8).abs() < 1e-3, "{a:?}");
        let shift = (1.0 / (1.5 * 1.8_f64)).atan() / 1.5;
        assert!((a.at - (2.0 * PI / 1.5 - shift)).abs() < 2e-3, "{a:?}");
    }
}
