//! What a designed manoeuvre reaches, as the best model the design has
//! predicts it: the family's steers are sized on the base model
//! ([`super::family`]), which a diagnosis with a gap has shown wrong (a
//! step sized for 4.9 m/s² on the base reached 2.5 on the car and on the
//! verdict's fitted model). Each manoeuvre's words end with the peak |ay|
//! its set's reference (the verdict's effect of a confounded set) predicts
//! as fitted, and the base model's where the two differ by more than
//! [`DISAGREE`]; after a diagnosis that found no gap, the base model's.
//! A constant-radius turn is an open-loop steer schedule, not a path: its
//! words say what radius the reference drives it on.
//!
//! Units: m/s², m; ISO 8855 (a left turn has r > 0, ay > 0).

use super::family::Kind;
use super::separation::Logging;
use crate::diagnose::model::Observed;

/// The relative difference of the two models' peak |ay| beyond which the
/// words give both.
pub const DISAGREE: f64 = 0.1;

/// The predicted responses a manoeuvre's words are drawn from: the best
/// model's (its label, None: the base model) and the base model's, with
/// the lateral accelerations each reads (the logged ay, else u·r).
pub(crate) struct Predicted<'a> {
    /// The best model's label and its lateral acceleration, yaw rate.
    pub best: Option<(&'a str, Vec<f64>, &'a Observed)>,
    /// The base model's lateral acceleration.
    pub base_ay: Vec<f64>,
    /// Speed at the samples, m/s.
    pub speed: &'a [f64],
}

/// The lateral acceleration of `obs` as the campaign logs it: its `ay`
/// where the campaign logs one, else `u·r` at speeds `speed`, m/s².
pub(crate) fn lateral(obs: &Observed, speed: &[f64], logging: &Logging) -> Vec<f64> {
    if logging.channels[crate::diagnose::Channel::Ay.index()] {
        obs.ay.clone()
    } else {
        obs.yaw_rate.iter().zip(speed).map(|(r, u)| r * u).collect()
    }
}

/// The largest |ay| of `ay`, m/s².
pub(crate) fn peak(ay: &[f64]) -> f64 {
    ay.iter().fold(0.0, |m: f64, a| m.max(a.abs()))
}

/// The radius `u/|r|` the yaw rate `r` drives at speed `u` at the last
/// sample before the speed starts to rise and at the last, m (None where
/// the car does not turn there).
fn radii(obs: &Observed, speed: &[f64]) -> Option<(f64, f64)> {
    let first = speed.windows(2).position(|w| w[1] > w[0] + 1e-9)?;
    let last = speed.len().checked_sub(1)?;
    let radius = |k: usize| {
        let r = obs.yaw_rate.get(k)?.abs();
        (r > 1e-6).then(|| speed[k] / r)
    };
    Some((radius(first)?, radius(last)?))
}

/// The words after a manoeuvre of kind `kind`'s description: its
/// predicted peak |ay| (and the radius a constant-radius turn's steer
/// drives on the reference).
pub(crate) fn predicted_words(kind: Kind, p: &Predicted) -> String {
    let base = peak(&p.base_ay);
    let Some((label, ay, obs)) = &p.best else {
        return format!("; the base model predicts a peak |ay| of {base:.1} m/s²");
    };
    let best = peak(ay);
    let mut out = if (best - base).abs() > DISAGREE * base.abs().max(1e-9) {
        format!(
            "; {label} as fitted predicts a peak |ay| of {best:.1} m/s², the base model the steer was sized on {base:.1}: expect {best:.1}"
        )
    } else {
        format!(
            "; {label} as fitted predicts a peak |ay| of {best:.1} m/s² (the base model {base:.1}, within {:.0} %)",
            100.0 * DISAGREE
        )
    };
    if kind == Kind::ConstantRadius {
        if let Some((r0, r1)) = radii(obs, p.speed) {
            out += &format!(
                "; on {label} as fitted this steer drives a radius of {r0:.0} m growing to {r1:.0} m"
            );
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn observed(yaw_rate: Vec<f64>) -> Observed {
        let n = yaw_rate.len();
        Observed {
            yaw_rate,
            ay: vec![0.0; n],
            beta: vec![0.0; n],
            roll: vec![0.0; n],
        }
    }

    /// A step the base sizes for 4.9 m/s² that the fitted model reaches
    /// at 2.5 says both and which to expect; one within 10 % says the
    /// fitted model's and that the base agrees.
    #[test]
    fn a_fitted_model_that_reaches_less_than_the_base_is_said_with_both() {
        let obs = observed(vec![0.0, 0.1]);
        let speed = [30.0, 30.0];
        let far = Predicted {
            best: Some(("steering_compliance", vec![0.0, -2.54], &obs)),
            base_ay: vec![0.0, 4.92],
            speed: &speed,
        };
        assert_eq!(
            predicted_words(Kind::Step, &far),
            "; steering_compliance as fitted predicts a peak |ay| of 2.5 m/s², the base model the steer was sized on 4.9: expect 2.5"
        );
        let near = Predicted {
            best: Some(("steering_compliance", vec![0.0, 4.6], &obs)),
            ..far
        };
        assert_eq!(
            predicted_words(Kind::Step, &near),
            "; steering_compliance as fitted predicts a peak |ay| of 4.6 m/s² (the base model 4.9, within 10 %)"
        );
    }

    /// A constant-radius steer driven by a car whose yaw rate stays while
    /// its speed doubles: the radius u/r doubles, and the words say so.
    #[test]
    fn a_constant_radius_steer_says_the_radius_the_fitted_model_drives() {
        let obs = observed(vec![0.1, 0.1, 0.1]);
        let speed = [10.0, 10.0, 20.0];
        let p = Predicted {
            best: Some(("cornering_stiffness", vec![1.0, 1.0, 2.0], &obs)),
            base_ay: vec![1.0, 1.0, 2.0],
            speed: &speed,
        };
        let words = predicted_words(Kind::ConstantRadius, &p);
        assert!(
            words.ends_with("; on cornering_stiffness as fitted this steer drives a radius of 100 m growing to 200 m"),
            "{words}"
        );
    }
}
