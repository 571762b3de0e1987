//! The conditions where the swarm's answer is short, named one by one:
//! where PSO and the exact solver disagree (an equilibrium in the box that
//! only one of them found) or where the equilibria the swarm found do not
//! certify themselves (their index sum, +1 per node or focus and −1 per
//! saddle, is not the winding number of the field around the box:
//! Poincaré–Hopf). "Agree at 9/11 conditions" alone said neither where nor
//! what. Units: rad, rad/s, m/s; ISO 8855 signs as `equilibria.csv`.

use crate::equilibria::sweep::{Certificate, SweepResult};
use crate::equilibria::{Condition, FoundBy, Kind};
use crate::format::{fixed, rounded};
use serde::Serialize;

/// Terminal lines past which the rest are left to `summary.json`.
const MOST_LINES: usize = 20;

/// An equilibrium one solver found and the other did not.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Spot {
    /// Sideslip, rad.
    pub beta: f64,
    /// Yaw rate, rad/s.
    pub yaw_rate: f64,
    /// Its kind.
    pub kind: Kind,
}

/// One condition where the swarm's answer is short.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConditionMiss {
    /// The condition.
    pub condition: Condition,
    /// Equilibria in the box the exact solver found and the swarm did not.
    pub exact_only: Vec<Spot>,
    /// Equilibria the swarm found and the exact solver did not.
    pub pso_only: Vec<Spot>,
    /// Sum of the indices of the equilibria the swarm found in the box.
    pub index_sum: i32,
    /// Winding number of the field around the box (None: see `certificate`).
    pub winding_number: Option<i32>,
    /// Whether the index sum certifies the swarm's equilibria.
    pub certificate: Certificate,
}

/// Every condition where PSO and the exact solver disagree or the index
/// sum falls short of the winding number, in the sweep's order; `certify`:
/// whether the search took the winding number (`[pso] certify`).
pub(super) fn misses(r: &SweepResult, certify: bool) -> Vec<ConditionMiss> {
    r.points
        .iter()
        .filter_map(|p| {
            let certificate = p.certificate(certify);
            if p.agree && certificate != Certificate::FallsShort {
                return None;
            }
            let spots = |by: FoundBy| {
                (p.found.iter())
                    .filter(|f| f.found_by == by && f.in_box)
                    .map(|f| Spot {
                        beta: f.equilibrium.beta,
                        yaw_rate: f.equilibrium.yaw_rate,
                        kind: f.equilibrium.stability.kind,
                    })
                    .collect()
            };
            Some(ConditionMiss {
                condition: p.condition,
                exact_only: spots(FoundBy::Exact),
                pso_only: spots(FoundBy::Pso),
                index_sum: p.index_sum,
                winding_number: p.winding,
                certificate,
            })
        })
        .collect()
}

/// The terminal's lines: a heading, then one line per condition (at most
/// [`MOST_LINES`], the rest counted and left to `summary.json`).
pub(super) fn lines(misses: &[ConditionMiss]) -> Vec<String> {
    if misses.is_empty() {
        return Vec::new();
    }
    let mut out = vec![format!(
        "  where the swarm fell short ({}; summary.json `misses`):",
        crate::format::plural(misses.len(), "condition", "conditions")
    )];
    out.extend(misses.iter().take(MOST_LINES).map(line));
    if misses.len() > MOST_LINES {
        out.push(format!(
            "    … and {} more in summary.json `misses`",
            misses.len() - MOST_LINES
        ));
    }
    out
}

/// One condition: where, which solver found what, and the certificate.
fn line(m: &ConditionMiss) -> String {
    let c = m.condition;
    let spots = |v: &[Spot]| {
        v.iter()
            .map(|s| {
                format!(
                    "a {} (β {} rad, r {} rad/s)",
                    s.kind.name(),
                    fixed(s.beta, 4),
                    fixed(s.yaw_rate, 4)
                )
            })
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut said = Vec::new();
    if !m.exact_only.is_empty() {
        said.push(format!(
            "the exact solver alone found {}",
            spots(&m.exact_only[..])
        ));
    }
    if !m.pso_only.is_empty() {
        said.push(format!("the swarm alone found {}", spots(&m.pso_only[..])));
    }
    said.push(certificate_words(m));
    format!(
        "    steer {} rad, friction {}, speed {} m/s: {}",
        rounded(c.steer, 6),
        rounded(c.friction, 6),
        rounded(c.speed, 6),
        said.join("; ")
    )
}

/// The certificate in words, with the numbers it compares.
fn certificate_words(m: &ConditionMiss) -> String {
    let sum = m.index_sum;
    match (m.certificate, m.winding_number) {
        (Certificate::Holds, _) => format!(
            "the swarm's index sum {sum} is the winding number (the indices it missed cancel)"
        ),
        (Certificate::FallsShort, Some(w)) => format!(
            "the swarm's index sum {sum} is not the winding number {w}: the certificate failed"
        ),
        (Certificate::FallsShort | Certificate::Undefined, _) => format!(
            "the swarm's index sum {sum}, no winding number (the field nearly vanishes on the box's edge): not certified"
        ),
        (Certificate::NotAsked, _) => {
            format!("the swarm's index sum {sum}, not certified (`certify = false`)")
        }
    }
}
