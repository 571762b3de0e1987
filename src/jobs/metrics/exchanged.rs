//! A `beta` column that is the steer, and a `steer` column that is a
//! response: the two exchanged in a log. Read as logged, the yaw rate
//! answers before the "steer" moves (a negative response time) and the
//! gain comes out of any sign (−22.9 1/s on a round-19 file whose true
//! gain is +5.4). Where, in addition, `beta`'s own step read as a steer
//! gives a response a car could have — the yaw rate reaching 90 % of its
//! step after `beta` reaches half of its own, and a steady r/(u·δ) of a
//! car (1/(l·(1 + K·u²)), Milliken & Milliken 1995, ch. 5: 0.05 to
//! 1.5 1/m for wheelbases of 1.5 to 5 m and understeer or oversteer
//! within a factor of 4 of neutral) — the columns are said to look
//! exchanged.
//!
//! Units: rad, rad/s, m/s, s; the ratio r/(u·δ) in 1/m.

use crate::measured::MeasuredRun;

/// The band of a car's steady r/(u·δ), 1/m.
const CAR_RATIO: (f64, f64) = (0.05, 1.5);

/// The longest lag, s, from a steer's half step to the yaw rate's 90 %
/// a car shows (GB/T 6323's response times are 0.1 to 0.5 s).
const LONGEST_LAG: f64 = 1.0;

/// The mean of `x` over the first and the last tenth of the record.
fn ends(x: &[f64]) -> (f64, f64) {
    let n = (x.len() / 10).max(1);
    let mean = |s: &[f64]| s.iter().sum::<f64>() / s.len() as f64;
    (mean(&x[..n]), mean(&x[x.len() - n..]))
}

/// The first time `x` passes `share` of its step from its start level
/// `a` to its end level `b` ([`ends`]).
fn crossing(t: &[f64], x: &[f64], (a, b): (f64, f64), share: f64) -> Option<f64> {
    let level = a + share * (b - a);
    let k = x
        .iter()
        .position(|&v| (v - level) * (b - a).signum() >= 0.0)?;
    Some(t[k])
}

/// The warning where the run's `beta` reads as its steer and its `steer`
/// does not (`response_time`: the yaw-rate response time read with the
/// logged steer, s).
pub(super) fn exchanged(run: &MeasuredRun, response_time: f64) -> Option<String> {
    let beta = run.beta.as_ref()?;
    if run.t.len() < 20 {
        return None;
    }
    let ((r0, r1), (b0, b1)) = (ends(&run.yaw_rate), ends(beta));
    let (s0, s1) = ends(&run.steer);
    let (dr, db, ds) = (r1 - r0, b1 - b0, s1 - s0);
    let u = run.speed.iter().sum::<f64>() / run.speed.len() as f64;
    let ratio = dr / (u * db);
    let steer_ratio = dr / (u * ds);
    let steer_no_car = response_time < 0.0 || !(0.0..=CAR_RATIO.1).contains(&steer_ratio);
    if !steer_no_car || db.abs() <= ds.abs() {
        return None;
    }
    let lag =
        crossing(&run.t, &run.yaw_rate, (r0, r1), 0.9)? - crossing(&run.t, beta, (b0, b1), 0.5)?;
    let car = (CAR_RATIO.0..=CAR_RATIO.1).contains(&ratio);
    (car && lag > 0.0 && lag <= LONGEST_LAG).then(|| {
        format!(
            "`steer` and `beta` look exchanged: `steer` steps by {ds:.4} rad, and the yaw rate answers it {}, while `beta` steps by {:.4} rad and the yaw rate follows it {lag:.3} s later with r/(u·β) = {ratio:.3} 1/m, a car's steady yaw response to a steer (0.05 to 1.5 1/m); if `beta` is the steer, exchange the two columns' names",
            if response_time < 0.0 {
                "before it moves".to_string()
            } else {
                format!("with r/(u·δ) = {steer_ratio:.3} 1/m, no car's")
            },
            db
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A step at 1 s, ramped over 0.1 s, of `size`, its response delayed
    /// by `lag` s.
    fn step(t: &[f64], size: f64, lag: f64) -> Vec<f64> {
        t.iter()
            .map(|&t| size * ((t - 1.0 - lag) / 0.1).clamp(0.0, 1.0))
            .collect()
    }

    fn run(steer: Vec<f64>, yaw_rate: Vec<f64>, beta: Vec<f64>, t: Vec<f64>) -> MeasuredRun {
        let n = t.len();
        MeasuredRun::new("run.csv", t, vec![22.2; n], steer, yaw_rate).with_beta(beta)
    }

    #[test]
    fn a_steer_logged_as_beta_is_said_to_look_exchanged() {
        let t: Vec<f64> = (0..800).map(|k| k as f64 * 0.01).collect();
        // The true steer 0.01 rad, the yaw rate 0.054 rad/s 0.15 s later,
        // the sideslip −0.002 rad: logged with steer and beta exchanged.
        let (steer, r, beta) = (
            step(&t, 0.01, 0.0),
            step(&t, 0.054, 0.15),
            step(&t, -0.002, 0.15),
        );
        let swapped = run(beta.clone(), r.clone(), steer.clone(), t.clone());
        let w = exchanged(&swapped, -0.13).unwrap();
        assert!(w.contains("the yaw rate answers it before it moves"), "{w}");
        assert!(w.contains("r/(u·β) = 0.243 1/m"), "{w}");
        // The yaw rate at 90 % (1.24 s) after the steer at half (1.05 s).
        assert!(w.contains("follows it 0.190 s later"), "{w}");
        // As logged right: the response time is positive, nothing said.
        let right = run(steer, r, beta, t);
        assert_eq!(exchanged(&right, 0.2), None);
        // A misaligned log whose beta is a sideslip: its r/(u·β) (−1.2
        // 1/m) is no car's steer response, nothing said.
        assert_eq!(exchanged(&right, -0.1), None);
    }
}
