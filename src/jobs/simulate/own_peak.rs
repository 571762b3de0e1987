//! Each axle judged against its own tyres' curve, not against the 15° any
//! tyre's peak lies below (the `SLIDING_SLIP` `simulate` said it by): the axle's
//! lateral force `Σ Fy(α, Fz_w)` over its two wheels at one row's wheel
//! loads (the road's friction scale and the row's speed, no camber and no
//! longitudinal slip, as the 2-DOF model evaluates them), scanned in slip
//! angle for the least slip at which it reaches its peak. A Gim tyre of
//! 500 N/deg at 4.5 kN peaks only at 25° (its full sliding, `tan α =
//! 3μFz/C_α`): a car on it at 19.8° of front slip was said to slide "past
//! the peak of any tyre's curve" with its front axle at 88 % of its own
//! (round 42). A brush tyre's curve is flat beyond its peak: the peak is
//! where the force first reaches its top, within [`TOP`] of it.
//!
//! Units: rad and N inside; degrees, kN and % in words. Slip angles as
//! `history.csv` holds them (ISO 8855), judged by magnitude; a peak is
//! said with the sign of the slip it is judged against (a −49.5° front
//! slip was said "past its tyres' peak at 38.0°", two signs for one side
//! of the curve).

use crate::io::Scenario;
use crate::metrics::applicability::{KINEMATIC_GRIP, SLIDING_SIDESLIP};
use crate::metrics::{AxlesGrip, StepMetrics};
use crate::sim::TimeHistory;
use crate::tyre::{SlipState, Tyre, TyreModel};
use std::f64::consts::FRAC_PI_2;

/// The largest slip angle scanned for a peak, rad (80°): a curve still
/// rising there has no peak the scan finds (a linear tyre's never has).
const SCAN_MAX: f64 = 80.0 * std::f64::consts::PI / 180.0;
/// The scan's step, rad (0.05°, as [`TyreModel::peak_lateral_force`]'s).
const SCAN_STEP: f64 = 0.05 * std::f64::consts::PI / 180.0;
/// The share of the peak force within which a flat top counts as reached:
/// a brush tyre's force `μFz·(1 − ln³)` is within it from `ln = 1e-4`, a
/// slip 4e-5 rad short of full sliding (at 1e-6 it was 0.2° short).
const TOP: f64 = 1e-12;
/// How far past its peak slip an axle must be to be past it, rad (0.1°,
/// the resolution the words print): a slip within it is at the peak.
const AT_PEAK: f64 = 0.1 * std::f64::consts::PI / 180.0;

/// An axle's peak at one row's wheel loads.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct AxlePeak {
    /// The least slip angle at which the axle's force reaches its peak, rad.
    pub slip: f64,
    /// The peak force, N.
    pub force: f64,
}

/// The force of `tyre`'s wheels at loads `fz` (N) and slip angle `alpha`
/// (rad, magnitude) on a road of friction scale `mu` at `speed` (m/s), N.
fn axle_force(tyre: &Tyre, fz: &[f64], alpha: f64, mu: f64, speed: f64) -> f64 {
    fz.iter()
        .map(|&fz| {
            tyre.lateral_force(&SlipState {
                alpha,
                kappa: 0.0,
                fz,
                camber: 0.0,
                mu_scale: mu,
                speed,
            })
            .abs()
        })
        .sum()
}

/// The peak of `tyre`'s wheels at loads `fz` (N): `None` where the force
/// still rises at [`SCAN_MAX`] (no limit, or one beyond any the scan
/// reaches) or is nowhere positive.
pub(super) fn axle_peak(tyre: &Tyre, fz: &[f64], mu: f64, speed: f64) -> Option<AxlePeak> {
    let f = |a: f64| axle_force(tyre, fz, a, mu, speed);
    let n = (SCAN_MAX / SCAN_STEP).round() as usize;
    let forces: Vec<f64> = (0..=n).map(|i| f(i as f64 * SCAN_STEP)).collect();
    let top = forces.iter().copied().fold(0.0, f64::max);
    let reach = top * (1.0 - TOP);
    let i = forces.iter().position(|&v| v >= reach)?;
    if top <= 0.0 || i == n || i == 0 {
        return None;
    }
    // The force first reaches the top between rows i − 1 and i: bisected.
    let (mut lo, mut hi) = ((i - 1) as f64 * SCAN_STEP, i as f64 * SCAN_STEP);
    for _ in 0..50 {
        let mid = 0.5 * (lo + hi);
        match f(mid) >= reach {
            true => hi = mid,
            false => lo = mid,
        }
    }
    Some(AxlePeak {
        slip: hi,
        force: top.max(f(hi)),
    })
}

/// Where an axle stands on its own curve at one row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum OnCurve {
    /// Short of its peak, or at it (within [`AT_PEAK`]).
    Short { peak: AxlePeak, share: f64 },
    /// Past its peak: the axle slides.
    Past { peak: AxlePeak, share: f64 },
    /// No peak found below [`SCAN_MAX`].
    NoPeak,
}

impl OnCurve {
    /// Whether the axle is past its own peak.
    pub(super) fn past(self) -> bool {
        matches!(self, OnCurve::Past { .. })
    }
}

/// Where axle `axle` (0 front, 1 rear) of scenario `sc` stands on its own
/// tyres' curve at row `k` of `h`, with its wheels' loads (N).
pub(super) fn on_curve(
    sc: &Scenario,
    h: &TimeHistory,
    axle: usize,
    k: usize,
) -> (OnCurve, [f64; 2]) {
    let (tyre, alpha) = match axle {
        0 => (&sc.model.front, h.alpha_front[k]),
        _ => (&sc.model.rear, h.alpha_rear[k]),
    };
    let loads = [h.fz[2 * axle][k], h.fz[2 * axle + 1][k]];
    let (mu, speed) = (sc.integrator.friction, h.speed[k]);
    let Some(peak) = axle_peak(tyre, &loads, mu, speed) else {
        return (OnCurve::NoPeak, loads);
    };
    let a = alpha.abs();
    let share = axle_force(tyre, &loads, a, mu, speed) / peak.force;
    let on = match a > peak.slip + AT_PEAK {
        true => OnCurve::Past { peak, share },
        false => OnCurve::Short { peak, share },
    };
    (on, loads)
}

/// The sign of axle `axle`'s slip angle at row `k` (1 at zero): a peak
/// slip (a magnitude) is said on the slip's side of the curve.
fn slip_sign(h: &TimeHistory, axle: usize, k: usize) -> f64 {
    match [h.alpha_front[k], h.alpha_rear[k]][axle] < 0.0 {
        true => -1.0,
        false => 1.0,
    }
}

/// [`on_curve`] in words: "88 % of its tyres' peak at 37.3° (9.02 kN at
/// that row's wheel loads, 1.74 and 7.28 kN)", with the lighter wheel
/// where it alone is past its own peak; peaks with the row's slip's sign.
pub(super) fn curve_words(sc: &Scenario, h: &TimeHistory, axle: usize, k: usize) -> (bool, String) {
    let (on, loads) = on_curve(sc, h, axle, k);
    let kn = |f: f64| crate::format::fixed(f / 1000.0, 2);
    let sign = slip_sign(h, axle, k);
    let at = |p: AxlePeak| {
        format!(
            "its tyres' peak at {:.1}° ({} kN at that row's wheel loads, {} and {} kN)",
            (sign * p.slip).to_degrees(),
            kn(p.force),
            kn(loads[0]),
            kn(loads[1])
        )
    };
    let said = match on {
        OnCurve::Past { peak, share } => format!(
            "past {}, where it gives {} % of that",
            at(peak),
            crate::format::fixed(100.0 * share, 0)
        ),
        OnCurve::Short { peak, share } => format!(
            "{} % of {}{}",
            crate::format::fixed(100.0 * share, 0),
            at(peak),
            lighter_wheel(sc, h, axle, k, loads)
        ),
        OnCurve::NoPeak => "past the peak of any tyre's curve (its own tyres' force at that row's wheel loads still rises at 80°: no peak of their own is found to judge it by)".into(),
    };
    (on.past() || on == OnCurve::NoPeak, said)
}

/// The lighter-loaded wheel of an axle short of its peak where that wheel
/// alone is past its own (a brush tyre's inner wheel slides from a slip
/// proportional to its load), in words; empty otherwise.
fn lighter_wheel(sc: &Scenario, h: &TimeHistory, axle: usize, k: usize, loads: [f64; 2]) -> String {
    let tyre = [&sc.model.front, &sc.model.rear][axle];
    let alpha = [h.alpha_front[k], h.alpha_rear[k]][axle];
    let light = loads[0].min(loads[1]);
    let mu = sc.integrator.friction;
    match axle_peak(tyre, &[light], mu, h.speed[k]) {
        Some(p) if alpha.abs() > p.slip + AT_PEAK => format!(
            ", though its lighter wheel ({} kN) is past its own peak at {:.1}°",
            crate::format::fixed(light / 1000.0, 2),
            (slip_sign(h, axle, k) * p.slip).to_degrees()
        ),
        _ => String::new(),
    }
}

/// Whether `axle` (0 front, 1 rear) is short of its own tyres' peak at
/// its largest slip and at the run's end: an axle that slid on the way (a
/// 0.3 rad step's front at 48° past its peak at 38°) leaves the car the
/// slide the metrics say.
fn short_of_peak(sc: &Scenario, h: &TimeHistory, axle: usize) -> bool {
    let Some(last) = h.len().checked_sub(1) else {
        return false;
    };
    let alpha = [&h.alpha_front, &h.alpha_rear][axle];
    let largest = (0..alpha.len()).max_by(|&i, &j| alpha[i].abs().total_cmp(&alpha[j].abs()));
    [Some(last), largest]
        .into_iter()
        .flatten()
        .all(|k| matches!(on_curve(sc, h, axle, k).0, OnCurve::Short { .. }))
}

/// What the run knows of its axles against their own tyres' peak, for
/// the settling words ([`AxlesGrip`]): both short of it
/// ([`short_of_peak`]), or one at it or past it; not known where a tyre
/// has no friction limit of its own (a linear tyre has no peak).
pub(super) fn axles_grip(sc: &Scenario, h: &TimeHistory) -> AxlesGrip {
    let mu = super::unlimited::static_friction(&sc.model, sc.integrator.friction);
    if !mu.iter().all(|m| m.is_finite() && *m > 0.0) {
        return AxlesGrip::Unknown;
    }
    match short_of_peak(sc, h, 0) && short_of_peak(sc, h, 1) {
        true => AxlesGrip::BelowPeak,
        false => AxlesGrip::AtPeak,
    }
}

/// A step's steady sideslip beyond
/// [`SLIDING_SIDESLIP`](crate::metrics::applicability::SLIDING_SIDESLIP)
/// (10°) with both axles short of their own tyres' peaks at the run's last
/// row and at their largest slip, and the tyres at [`KINEMATIC_GRIP`] of their grip `grip` (μ·g,
/// m/s²) or more, in words: no slide, where the metrics' own words say
/// "the car is sliding, past its grip" (round 42: a Gim car at −10.4°
/// with its axles at 88 and 9x % of their peaks). `None` where an axle is
/// past its peak or has none found, a spin, or a kinematic turn: the
/// metrics' words stand.
pub(super) fn steady_sideslip(
    sc: &Scenario,
    h: &TimeHistory,
    m: &StepMetrics,
    grip: Option<f64>,
) -> Option<String> {
    let beta = m
        .beta_steady
        .filter(|b| b.abs() > SLIDING_SIDESLIP && b.abs() <= FRAC_PI_2)?;
    let share = m.ay_steady?.abs() / grip?;
    let last = h.len().checked_sub(1)?;
    let short = |axle: usize| short_of_peak(sc, h, axle);
    if share < KINEMATIC_GRIP || !short(0) || !short(1) {
        return None;
    }
    let axle = |n: usize, name: &str| {
        let alpha = [h.alpha_front[last], h.alpha_rear[last]][n];
        format!(
            "the {name} at {:.1}°, {}",
            alpha.to_degrees(),
            curve_words(sc, h, n, last).1
        )
    };
    Some(format!(
        "the steady sideslip is {:.1}°, beyond 10°, but neither axle is past its own tyres' peak, at its largest slip or at the end of the run (t = {:.2} s): {}; {}: a large sideslip on tyres short of their peaks, not a slide; the car turns at {} % of its grip (a steady ay of {} m/s² against μ·g = {} m/s²), far beyond the 4 m/s² ISO 7401 steps to, so the step-steer metrics describe a car near its limit, not its handling (a smaller steer step measures the handling)",
        beta.to_degrees(),
        h.t[last],
        axle(0, "front"),
        axle(1, "rear"),
        crate::format::fixed(100.0 * share, 0),
        crate::format::fixed(m.ay_steady?.abs(), 2),
        crate::format::fixed(grip?, 2)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tyre::{Gim, Linear};

    /// A brush tyre with constant friction peaks where it slides fully,
    /// `tan α = 3μFz/C_α`, at `μFz` (Pacejka 2012, eq. 3.17).
    #[test]
    fn a_brush_tyres_peak_is_its_full_sliding_slip() {
        let tyre = Tyre::Gim(Gim::new(28_647.9, 0.16, 1.0));
        let p = axle_peak(&tyre, &[4506.65], 1.0, 22.2).unwrap();
        // Within [`TOP`] of the top from 1e-4 of the full-sliding tan α.
        let closed = (3.0 * 4506.65 / 28_647.9_f64).atan();
        assert!(
            p.slip <= closed && closed - p.slip < 1e-4,
            "{} {closed}",
            p.slip
        );
        assert!((p.force - 4506.65).abs() < 1e-6 * 4506.65, "{}", p.force);
        // Two wheels: the heavier one's full sliding, the sum of μFz.
        let p = axle_peak(&tyre, &[1736.0, 7280.0], 1.0, 22.2).unwrap();
        let closed = (3.0 * 7280.0 / 28_647.9_f64).atan();
        assert!(
            p.slip <= closed && closed - p.slip < 1e-4,
            "{} {closed}",
            p.slip
        );
        assert!((p.force - 9016.0).abs() < 1e-6 * 9016.0, "{}", p.force);
    }

    /// A linear tyre's force rises without a peak: none is found.
    #[test]
    fn a_linear_tyre_has_no_peak_to_find() {
        let tyre = Tyre::Linear(Linear::new(80_000.0));
        assert_eq!(axle_peak(&tyre, &[4000.0, 4000.0], 1.0, 20.0), None);
    }
}
