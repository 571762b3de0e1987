//! A campaign's vehicle or road that its own runs contradict: runs turning
//! harder than the stated friction lets any car (|u·r| beyond μ·g), or than
//! the car can on four wheels (beyond its static stability factor
//! g·t/(2h); Gillespie 1992, ch. 9). A friction of 0.05 typed for 0.5, or
//! a centre of gravity in the wrong unit, would otherwise be diagnosed as
//! a gap of the runs. Judged on the 99th percentile of |u·r| over all runs
//! (a logger's spike is no turn), u·r being the lateral acceleration of
//! steady turning that every run carries, less what a logged bank gives
//! (ISO 8855; m/s², m/s, rad/s, rad).

use crate::diagnose::campaign::{BaseTyres, Campaign};
use crate::diagnose::report::{Note, VehicleLimit};
use crate::measured::clean::quantile;

/// How far beyond μ·g the runs' |u·r| may go before the friction is
/// contradicted: downforce (not in the base model), a banked road and the
/// sideslip rate move a car's u·r past μ·g by tens of per cent, not more.
const FRICTION_SLACK: f64 = 1.5;

/// How far beyond the static stability factor the runs' |u·r| may go:
/// suspension compliance and a banked road carry a car a tenth past it.
const ROLLOVER_SLACK: f64 = 1.1;

/// The share of samples the reach is judged at (the 99th percentile).
const REACH_QUANTILE: f64 = 0.99;

/// The notes on a vehicle or road the runs of `c` contradict.
pub(crate) fn contradicted(c: &Campaign) -> Vec<Note> {
    let g = crate::constants::G;
    let mut turning: Vec<f64> = c.runs.iter().flat_map(|r| demand(r, g)).collect();
    turning.sort_by(f64::total_cmp);
    let Some(reached) = quantile(&turning, REACH_QUANTILE) else {
        return Vec::new();
    };
    let mut notes = Vec::new();
    if friction_limits(c) && reached > FRICTION_SLACK * c.friction * g {
        notes.push(Note::RunsBeyondVehicle {
            limit: VehicleLimit::Friction {
                friction: c.friction,
            },
            reached,
            threshold: c.friction * g,
        });
    }
    let v = &c.vehicle;
    let rollover = crate::error::Rollover::of(v.track_front, v.track_rear, v.cg_height);
    if reached > ROLLOVER_SLACK * rollover.threshold {
        notes.push(Note::RunsBeyondVehicle {
            limit: VehicleLimit::Rollover {
                track: rollover.track,
                cg_height: v.cg_height,
            },
            reached,
            threshold: rollover.threshold,
        });
    }
    notes
}

/// The lateral acceleration the road asks of a run's tyres at each sample,
/// |u·r| less what a bank gives, g·|sin θ| (m/s²): on a banked oval the
/// bank carries part of u·r, so a run there is not judged against μ·g by
/// its whole u·r (the generous sign: the bank taken as helping).
fn demand(run: &crate::measured::MeasuredRun, g: f64) -> Vec<f64> {
    let bank = |i: usize| run.bank.as_ref().and_then(|b| b.get(i)).copied();
    run.speed
        .iter()
        .zip(&run.yaw_rate)
        .enumerate()
        .map(|(i, (u, r))| (u * r).abs() - bank(i).map_or(0.0, |b| g * b.sin().abs()))
        .filter(|v| v.is_finite())
        .map(|v| v.max(0.0))
        .collect()
}

/// Whether the campaign's base tyres have a friction limit the road's
/// friction scales: linear tyres and axles identified from the runs have
/// none, so the stated friction acts on nothing.
fn friction_limits(c: &Campaign) -> bool {
    !matches!(c.tyres, BaseTyres::FromRuns) && !c.tyres.linear()
}
