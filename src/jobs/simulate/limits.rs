//! What no tyre gives, said by `simulate` of the run: an axle's slip angle
//! beyond [`SLIDING_SLIP`] (15°), past the peak of most road and racing
//! tyres' curves (3–10°), judged against the axle's own tyres' peak at
//! that row's wheel loads ([`super::own_peak`]) and said as a slide only
//! past it (a soft Gim tyre at 4.5 kN peaks at 25°), past "the peak of any
//! tyre's curve" only where no peak of its own is found; on a linear tyre
//! (whose `C_α·α` has no peak and never slides, but holds only at small
//! slip angles) as beyond its range of validity; and a
//! lateral acceleration beyond [`ANY_TYRE_AY`] g of the car's weight plus
//! its down-force (a racing slick on a dry road reaches about 1.5 g
//! without down-force), which a linear tyre gives at any steer. Slip
//! angles are printed as the history holds them, the largest and its
//! time: the small-angle model's `α = δ − β − a·r/u` of a spinning car
//! runs past a turn (34 rad, 1952°, at the end of an oversteering linear
//! car's run above its critical speed), and beyond a quarter turn it is
//! said as the model's number, no angle a tyre sees. A wrapped value
//! (180.0° said of that run) matched no column of `history.csv`.
//! Units: rad, m/s², N; printed in degrees and g.

use crate::constants::G;
use crate::io::Scenario;
use crate::sim::TimeHistory;
use std::f64::consts::{PI, TAU};

/// The axle slip angle beyond which the axle slides, rad (15°): past the
/// peak of road tyres (3–8°) and racing slicks (6–10°) alike.
pub(crate) const SLIDING_SLIP: f64 = 15.0 * PI / 180.0;

/// The most lateral acceleration any tyre gives, in g of the car's load
/// on the road (its weight plus down-force): a racing slick's friction on
/// a dry road is about 1.5–1.7, a road tyre's 0.9–1.1.
pub(super) const ANY_TYRE_AY: f64 = 1.5;

/// `a` (rad) wrapped to (−π, π].
pub(super) fn wrapped(a: f64) -> f64 {
    let w = a - TAU * ((a + PI) / TAU).floor();
    // `floor` puts an odd multiple of π at −π: the interval is open there.
    if w <= -PI {
        w + TAU
    } else {
        w
    }
}

/// A slip angle `a` (rad, as the history holds it) in words: degrees to
/// 0.1°; beyond a quarter turn with its radians too and said as the
/// small-angle model's number, which no tyre sees as an angle.
fn slip_words(a: f64) -> String {
    match a.abs() > PI / 2.0 {
        false => format!("{:.1}°", a.to_degrees()),
        true => format!(
            "{:.0}° ({} rad: the small-angle model's α = δ − β − a·r/u of a car turned past a quarter turn, no angle a tyre sees)",
            a.to_degrees(),
            crate::format::significant(a, 4)
        ),
    }
}

/// Each axle whose slip angle goes beyond [`SLIDING_SLIP`]: its largest
/// (as the history holds it), when, and from when, judged against its own
/// tyres' peak there and at the run's end ([`super::own_peak`]);
/// `friction` is each axle's peak friction coefficient, infinite for a
/// tyre with no limit (linear).
pub(super) fn axle_sliding(sc: &Scenario, h: &TimeHistory, friction: [f64; 2]) -> Vec<String> {
    [("front", &h.alpha_front), ("rear", &h.alpha_rear)]
        .into_iter()
        .zip(friction)
        .enumerate()
        .filter_map(|(n, ((axle, alpha), mu))| {
            let from = alpha.iter().position(|v| v.abs() > SLIDING_SLIP)?;
            let (i, a) = alpha
                .iter()
                .copied()
                .enumerate()
                .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))?;
            let reach = format!(
                "the {axle} axle's slip angle reaches {} at t = {:.2} s (beyond 15° from t = {:.2} s)",
                slip_words(a),
                h.t[i],
                h.t[from]
            );
            Some(match mu.is_finite() {
                true => own_curve(sc, h, (n, axle), &reach, i),
                false => format!(
                    "{reach}: its tyres are linear, with no peak, and never slide, but a linear tyre's force C_α·α holds at small slip angles only (a real tyre's peaks at 3–10°): the {axle} axle runs beyond the linear tyre's range of validity, and the response there is no car's"
                ),
            })
        })
        .collect()
}

/// An axle's largest slip `reach` (at row `i`) against its own tyres'
/// peak, and at the run's last row where that is another: "slides" only
/// where it is past that peak (or none is found).
fn own_curve(
    sc: &Scenario,
    h: &TimeHistory,
    (n, axle): (usize, &str),
    reach: &str,
    i: usize,
) -> String {
    let last = h.len() - 1;
    let (past, there) = super::own_peak::curve_words(sc, h, n, i);
    let end = (last != i).then(|| super::own_peak::curve_words(sc, h, n, last));
    let end_past = end.as_ref().is_some_and(|e| e.0);
    let alpha = [&h.alpha_front, &h.alpha_rear][n];
    let at_end = end.map_or_else(String::new, |(_, w)| {
        format!(
            "; at the end of the run (t = {:.2} s) it is at {}, {w}",
            h.t[last],
            slip_words(alpha[last])
        )
    });
    let verdict = match (past, end_past) {
        (false, false) => format!("the {axle} axle does not slide past its tyres' peak"),
        (true, false) if last != i => {
            format!("the {axle} axle slides there, and the response there is no handling response")
        }
        _ => format!("the {axle} axle slides, and the response is no handling response"),
    };
    format!("{reach}, {there}{at_end}: {verdict}")
}

/// The largest |ay| of the run where it is beyond [`ANY_TYRE_AY`] g of the
/// car's load on the road at that row (the history's four wheel loads,
/// down-force included), with the last row's: a steady lateral
/// acceleration no tyre gives.
pub(super) fn beyond_any_tyre(sc: &Scenario, h: &TimeHistory) -> Option<String> {
    let mass = sc.model.vehicle.mass;
    let limit = |k: usize| {
        let load: f64 = h.fz.iter().map(|w| w[k]).sum();
        ANY_TYRE_AY * load.max(mass * G) / mass
    };
    let (k, ay) =
        h.ay.iter()
            .enumerate()
            .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))?;
    (ay.abs() > limit(k)).then(|| {
        let last = h.len() - 1;
        format!(
            "the lateral acceleration reaches {} g ({} m/s²) at t = {:.2} s and is {} g at the end of the run (t = {:.2} s): beyond the {ANY_TYRE_AY} g any tyre gives (a racing slick on a dry road; a road tyre gives about 1 g), of the car's weight{}: the tyres are driven far past any tyre's grip, and the run describes no car",
            crate::format::fixed(ay.abs() / G, 2),
            crate::format::rounded(ay.abs(), 3),
            h.t[k],
            crate::format::fixed(h.ay[last].abs() / G, 2),
            h.t[last],
            match limit(k) > ANY_TYRE_AY * G * (1.0 + 1e-9) {
                true => " and its down-force",
                false => "",
            }
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn angles_wrap_into_the_half_open_turn() {
        let deg = |d: f64| d.to_radians();
        assert!((wrapped(deg(194.3)) - deg(-165.7)).abs() < 1e-12);
        assert!((wrapped(deg(-194.3)) - deg(165.7)).abs() < 1e-12);
        assert_eq!(wrapped(PI), PI);
        assert!((wrapped(-PI) - PI).abs() < 1e-12);
        assert!((wrapped(deg(28.3)) - deg(28.3)).abs() < 1e-15);
        assert!((wrapped(deg(540.0)) - PI).abs() < 1e-12);
    }

    #[test]
    fn a_slip_angle_past_a_quarter_turn_is_said_as_the_history_holds_it() {
        // The oversteering linear car at 35 m/s ends its run at 34.07 rad.
        let said = slip_words(34.066_583_8);
        assert!(said.starts_with("1952° (34.07 rad: "), "{said}");
        assert_eq!(slip_words(-0.5), "-28.6°");
    }
}
