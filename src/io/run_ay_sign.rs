//! Whether a measured run's `ay` is logged in the sign ISO 8855 gives it,
//! told by its own speed and yaw rate.
//!
//! **Why.** `ay` is positive to the left and `yaw_rate` positive turning
//! left (ISO 8855, `FORMATS.md`): a car turning left is pushed to the left,
//! so its accelerometer reads `a_y = u·r + d(u·β)/dt + s·g·sin θ + b_ay`
//! (the bank's term with the share `s` the car feels of the logged bank,
//! `run_bank.rs`). An accelerometer mounted the other way round, or a
//! logger with its y axis to the right, writes every `ay` negated; the size
//! and unit checks pass it, and the diagnosis then fits the opposed phase
//! as the model's error (a compliance on its bound, a bank of −90°).
//!
//! **Rule.** Over the run's turning 0.5 s means ([`stretches`],
//! [`Stretch::turning`], as the slope check of `run_slope.rs`), `ay` is
//! regressed through the origin on the kinematic lateral acceleration: `u·r
//! + d(u·β)/dt`, and with a `bank` column also that plus `g·sin θ` (θ as
//!   read, in radians), the proving ground's two definitions of the logged
//!   bank (felt as logged with `bank_profile`, not felt without: its flat
//!   control). The fit with the higher R² is judged (the other reading of
//!   the bank is the wrong one: on an oval's banked turns the two differ by
//!   3.4 m/s²). A slope within [`REVERSED`], the negation of the SI band
//!   [`SI_RANGE`], with R² at least [`MIN_R2`] says `ay` and `u·r` oppose;
//!   where the steer turns with the yaw rate over those means (Σ δ·u·r >
//!   0), `ay` is the one reversed, and the run is refused at the `ay`
//!   column of the first sample of the turning mean whose regressor is
//!   largest (the clearest), with the slope. (A steer turning with `ay`,
//!   against the yaw rate, points at the yaw rate or the steer: the
//!   campaign's steer check names that.) A run in ISO signs fits near +1
//!   (0.6–1.6 with an unmeasured bank or the body's roll), so the bands
//!   are 1.2 apart.
//!
//! Not judged: fewer than [`MIN_BINS`] turning means, or an R² below
//! [`MIN_R2`] (left to the diagnosis, as the slope check leaves them).
//!
//! Units: SI, rad.

use super::columns::Columns;
use super::run_slope::{fit, stretches, Lateral, Stretch, MIN_BINS, MIN_R2, SI_RANGE};
use crate::constants::G;
use crate::error::{AyReversed, InputError, UnitSlip};
use std::path::Path;

/// The slopes of `ay` on the kinematic lateral acceleration that say `ay`
/// is logged in the other sign: [`SI_RANGE`] negated.
pub const REVERSED: (f64, f64) = (-SI_RANGE.1, -SI_RANGE.0);

/// The fit of `ay` on `u·r + d(u·β)/dt` plus `share` times `g·sin θ`
/// over the turning means `bins`: slope and R².
fn fit_with(bins: &[&Stretch], share: f64) -> (f64, f64) {
    fit(bins
        .iter()
        .map(|s| (s.speed_yaw + s.v_dot + share * s.bank_term, s.ay)))
}

/// The refusal of a run whose `ay` fits its kinematics with a slope in
/// [`REVERSED`] (the rule above), None where it is not judged or fits in
/// ISO signs.
pub(super) fn ay_reversed(c: &Lateral) -> Option<(usize, AyReversed)> {
    let all = stretches(c);
    let bins: Vec<&Stretch> = all
        .iter()
        .filter(|s| s.turning() && (s.speed_yaw + s.v_dot + s.bank_term + s.ay).is_finite())
        .collect();
    if bins.len() < MIN_BINS {
        return None;
    }
    // Without a bank column its term is 0 and one fit is all.
    let shares: &[f64] = if c.bank.is_some() {
        &[1.0, 0.0]
    } else {
        &[1.0]
    };
    let ((slope, r2), share) = shares
        .iter()
        .map(|&s| (fit_with(&bins, s), s))
        .max_by(|a, b| a.0 .1.total_cmp(&b.0 .1))?;
    if r2 < MIN_R2 || !(REVERSED.0..=REVERSED.1).contains(&slope) {
        return None;
    }
    // `ay` or the yaw rate: the one the steer turns against. A yaw rate
    // against the steer (and with `ay`) is the campaign's steer check's to
    // name ("the yaw rate turns against the steer").
    if bins.iter().map(|s| s.steer * s.speed_yaw).sum::<f64>() <= 0.0 {
        return None;
    }
    // The clearest mean: the largest regressor.
    let regressor = |s: &Stretch| s.speed_yaw + s.v_dot + share * s.bank_term;
    let clearest = bins
        .iter()
        .max_by(|a, b| regressor(a).abs().total_cmp(&regressor(b).abs()))?;
    let row = clearest.first;
    let bank_term = c.bank.map_or(0.0, |b| share * G * b[row].sin());
    let slip = AyReversed {
        value: c.ay[row],
        expected: c.speed[row] * c.yaw_rate[row] + bank_term,
        slope,
        r2,
        bins: bins.len(),
        with_beta: c.beta.is_some(),
        with_bank: c.bank.map(|_| share == 1.0),
        range: SI_RANGE,
    };
    Some((row, slip))
}

/// Refuses a run whose `ay` is logged in the other sign ([`ay_reversed`]).
pub(super) fn check_ay_sign(path: &Path, cols: &Columns, c: &Lateral) -> Result<(), InputError> {
    match ay_reversed(c) {
        Some((row, slip)) => Err(cols.error_at(path, row, "ay", UnitSlip::from(slip).into())),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A run at 20 m/s weaving with r = 0.2·sin(t) rad/s, `ay` = k·u·r,
    /// on a bank of `bank` rad in the turns that the car feels with
    /// `felt` of it; 10 Hz.
    fn run(k: f64, bank: f64, felt: f64) -> [Vec<f64>; 5] {
        let t: Vec<f64> = (0..600).map(|i| i as f64 * 0.1).collect();
        let u = vec![20.0; t.len()];
        let r: Vec<f64> = t.iter().map(|t| 0.2 * t.sin()).collect();
        let b: Vec<f64> = r
            .iter()
            .map(|r| -bank * (r.abs() > 0.05) as u8 as f64)
            .collect();
        let ay: Vec<f64> = r
            .iter()
            .zip(&b)
            .map(|(r, b)| k * (20.0 * r + felt * crate::constants::G * b.sin()))
            .collect();
        [t, u, r, ay, b]
    }

    fn judged(k: f64, bank: f64, felt: f64, logged: bool) -> Option<AyReversed> {
        judged_yaw(k, 1.0, bank, felt, logged)
    }

    /// [`judged`] with the yaw rate logged times `yaw` (the steer follows
    /// the car's own).
    fn judged_yaw(k: f64, yaw: f64, bank: f64, felt: f64, logged: bool) -> Option<AyReversed> {
        let [t, u, r, ay, b] = run(k, bank, felt);
        let steer: Vec<f64> = r.iter().map(|r| 0.15 * r).collect();
        let r: Vec<f64> = r.iter().map(|r| yaw * r).collect();
        let c = Lateral {
            t: &t,
            speed: &u,
            steer: &steer,
            yaw_rate: &r,
            ay: &ay,
            beta: None,
            bank: logged.then_some(&b[..]),
            means: Default::default(),
        };
        ay_reversed(&c).map(|(_, s)| s)
    }

    #[test]
    fn a_negated_ay_is_named_with_its_slope_whether_the_bank_acts_or_not() {
        for (bank, felt, logged) in [(0.0, 0.0, false), (0.35, 1.0, true), (0.35, 0.0, true)] {
            let s = judged(-1.0, bank, felt, logged).expect("refused");
            assert!((s.slope + 1.0).abs() < 1e-9, "{s:?}");
            assert_eq!(s.with_bank, logged.then_some(felt == 1.0));
        }
    }

    #[test]
    fn an_ay_in_iso_signs_passes_on_a_bank_felt_or_not() {
        for (bank, felt, logged) in [(0.0, 0.0, false), (0.35, 1.0, true), (0.35, 0.0, true)] {
            assert_eq!(judged(1.0, bank, felt, logged), None);
        }
    }

    #[test]
    fn a_yaw_rate_against_the_steer_and_ay_is_not_blamed_on_ay() {
        assert_eq!(judged_yaw(1.0, -1.0, 0.0, 0.0, false), None);
        assert!(judged_yaw(-1.0, 1.0, 0.0, 0.0, false).is_some());
    }
}
