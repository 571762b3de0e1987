//! The most lateral acceleration a simulated step can reach, which bounds
//! what `simulate` says of where a step's lateral acceleration heads
//! ([`crate::metrics::Ceiling`]): its tyres' peak lateral forces at static
//! load on the road's friction, over the mass; μ·g of the road where a
//! tyre has no limit of its own (a linear tyre's force grows without
//! one, the road's friction is all that bounds a car on it). A trend
//! through the steady window that would pass it is said to climb toward
//! it, never to arrive beyond it (round 40: "its trend heads 0.63 m/s²
//! beyond" a mean of 9.39 m/s² on a road giving 9.81 m/s²).
//!
//! Units: m/s², N, kg.

use crate::io::Scenario;
use crate::metrics::{AyLimit, Ceiling, StepMetrics};
use crate::sim::TimeHistory;

/// The ceiling of scenario `sc`'s lateral acceleration against its step's
/// steady change `ay_steady` (m/s²).
pub(super) fn ceiling(sc: &Scenario, ay_steady: f64) -> Ceiling {
    let mu = super::unlimited::static_friction(&sc.model, sc.integrator.friction);
    let (front, rear) = sc.model.vehicle.static_axle_loads();
    Ceiling {
        limit: AyLimit::of_axles(
            mu,
            [front, rear],
            sc.model.vehicle.mass,
            sc.integrator.friction,
        ),
        ay_steady,
    }
}

/// The metrics' settling warning ([`StepMetrics::settling_warning`]) with
/// the lateral acceleration's trend bounded by scenario `sc`'s ceiling,
/// and a sideslip moving beside a settled yaw rate and lateral
/// acceleration said against what the run `h` knows of its axles' peak
/// ([`crate::metrics::AxlesGrip`]).
pub(super) fn settling_warning(sc: &Scenario, h: &TimeHistory, m: &StepMetrics) -> Option<String> {
    let Some(ay) = m.ay_steady else {
        return m.settling_warning();
    };
    let c = ceiling(sc, ay);
    let said = match m.settled {
        true => m
            .settling
            .approaching_warning_within(m.yaw_rate_gain, Some(&c)),
        false => m.settling.not_settled_warning_known(
            m.yaw_rate_gain,
            Some(&c),
            super::own_peak::axles_grip(sc, h),
        ),
    };
    // Nothing of its own to say where the metrics have (a spread the
    // channels do not name): theirs.
    said.or_else(|| m.settling_warning())
}
