//! How a measurement system sees the vehicle: the sensor effects among
//! the diagnosis's candidates. All zero is an ideal measurement.
//!
//! - `delay` (s): every channel reports its value `delay` seconds late;
//! - `yaw_rate_bias` (rad/s), `ay_bias` (m/s²), `beta_bias` (rad): constant
//!   offsets (a sideslip sensor's misalignment is one);
//! - `accelerometer_x` (m, positive ahead of the centre of gravity): the
//!   accelerometer also feels the yaw acceleration, `ay + x·ṙ`;
//! - `roll_gradient` (rad per m/s²): the body rolls by φ = k·ay (ISO 8855:
//!   positive φ puts the right side down, outward in a left turn) and a
//!   body-fixed accelerometer reads `ay·cos φ + g·sin φ`.
//!
//! Units: SI, rad.

use crate::manoeuvre::interpolate_of;
use crate::measured::MeasuredRun;
use crate::scalar::{off, Scalar};
use crate::sim::TimeHistory;
use crate::vehicle::G;
use serde::{Deserialize, Serialize};
use std::path::PathBuf;

/// Sensor effects.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Sensors {
    /// Reporting delay, s.
    pub delay: f64,
    /// Yaw-rate offset, rad/s.
    pub yaw_rate_bias: f64,
    /// Lateral-acceleration offset, m/s².
    pub ay_bias: f64,
    /// Sideslip offset, rad.
    pub beta_bias: f64,
    /// Accelerometer position ahead of the centre of gravity, m.
    pub accelerometer_x: f64,
    /// Body roll per unit lateral acceleration, rad per m/s².
    pub roll_gradient: f64,
}

/// Central-difference derivative of `y` over `t` (one-sided at the ends).
fn derivative<T: Scalar>(t: &[f64], y: &[T]) -> Vec<T> {
    let n = t.len();
    (0..n)
        .map(|i| {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(n - 1));
            if b > a {
                (y[b] - y[a]) / (t[b] - t[a])
            } else {
                T::from(0.0)
            }
        })
        .collect()
}

/// [`Sensors`] with their numbers in a scalar of [`crate::scalar`] (a fit's
/// dual numbers carry their derivatives).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorsOf<T> {
    /// Delay, s.
    pub delay: T,
    /// Yaw-rate offset, rad/s.
    pub yaw_rate_bias: T,
    /// Lateral-acceleration offset, m/s².
    pub ay_bias: T,
    /// Sideslip offset, rad.
    pub beta_bias: T,
    /// Accelerometer position ahead of the centre of gravity, m.
    pub accelerometer_x: T,
    /// Body roll per unit lateral acceleration, rad per m/s².
    pub roll_gradient: T,
}

impl Sensors {
    /// The same sensors in scalar `T`, as constants.
    pub(crate) fn of<T: Scalar>(&self) -> SensorsOf<T> {
        SensorsOf {
            delay: T::from(self.delay),
            yaw_rate_bias: T::from(self.yaw_rate_bias),
            ay_bias: T::from(self.ay_bias),
            beta_bias: T::from(self.beta_bias),
            accelerometer_x: T::from(self.accelerometer_x),
            roll_gradient: T::from(self.roll_gradient),
        }
    }

    /// What these sensors would record of a simulated history, as a measured
    /// run (steer and speed are taken as recorded without error).
    pub fn measure(&self, h: &TimeHistory) -> MeasuredRun {
        let [yaw_rate, ay, beta] = self.of::<f64>().seen(&h.t, &h.yaw_rate, &h.ay, &h.beta);
        MeasuredRun {
            path: PathBuf::from("(simulated)"),
            t: h.t.clone(),
            speed: h.speed.clone(),
            steer: h.steer.clone(),
            yaw_rate,
            ay: Some(ay),
            beta: Some(beta),
            roll: None,
            bank: None,
            ax: None,
            masked: Vec::new(),
        }
    }
}

impl<T: Scalar> SensorsOf<T> {
    /// What the sensors record of a response (yaw rate, `ay` and sideslip
    /// at times `t`), at the same times: (yaw rate, ay, sideslip).
    pub(crate) fn seen(&self, t: &[f64], yaw_rate: &[T], ay: &[T], beta: &[T]) -> [Vec<T>; 3] {
        let yaw_acc = derivative(t, yaw_rate);
        let ay_seen: Vec<T> = ay
            .iter()
            .zip(&yaw_acc)
            .map(|(&ay, &ra)| {
                let phi = self.roll_gradient * ay;
                ay * phi.cos() + phi.sin() * G + self.accelerometer_x * ra + self.ay_bias
            })
            .collect();
        let yaw_seen: Vec<T> = yaw_rate.iter().map(|&r| r + self.yaw_rate_bias).collect();
        let late = |y: &[T]| -> Vec<T> {
            if off(self.delay) {
                y.to_vec()
            } else {
                t.iter()
                    .map(|&s| interpolate_of(t, y, T::from(s) - self.delay))
                    .collect()
            }
        };
        let beta_seen = if off(self.beta_bias) {
            late(beta)
        } else {
            let b: Vec<T> = beta.iter().map(|&b| b + self.beta_bias).collect();
            late(&b)
        };
        [late(&yaw_seen), late(&ay_seen), beta_seen]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn history() -> TimeHistory {
        let t: Vec<f64> = (0..=1000).map(|i| i as f64 * 0.01).collect();
        let n = t.len();
        TimeHistory {
            yaw_rate: t.iter().map(|x| 0.2 * (1.5 * x).sin()).collect(),
            ay: t.iter().map(|x| 4.0 * (1.5 * x).sin()).collect(),
            beta: t.iter().map(|x| -0.01 * (1.5 * x).sin()).collect(),
            steer: vec![0.01; n],
            speed: vec![20.0; n],
            t,
            ..TimeHistory::default()
        }
    }

    #[test]
    fn ideal_sensors_record_the_history() {
        let h = history();
        let m = Sensors::default().measure(&h);
        assert_eq!(m.yaw_rate, h.yaw_rate);
        assert_eq!(m.ay.unwrap(), h.ay);
        assert_eq!(m.beta.unwrap(), h.beta);
    }

    #[test]
    fn each_sensor_effect_has_its_closed_form() {
        let h = history();
        let i = 400; // t = 4 s
        let t = h.t[i];
        let delayed = Sensors {
            delay: 0.1,
            ..Default::default()
        }
        .measure(&h);
        assert!((delayed.yaw_rate[i] - 0.2 * (1.5 * (t - 0.1)).sin()).abs() < 1e-4);
        let biased = Sensors {
            yaw_rate_bias: 0.01,
            ay_bias: -0.2,
            beta_bias: 0.003,
            ..Default::default()
        }
        .measure(&h);
        assert!((biased.beta.as_ref().unwrap()[i] - h.beta[i] - 0.003).abs() < 1e-15);
        assert!((biased.yaw_rate[i] - h.yaw_rate[i] - 0.01).abs() < 1e-15);
        assert!((biased.ay.unwrap()[i] - h.ay[i] + 0.2).abs() < 1e-12);
        let ahead = Sensors {
            accelerometer_x: 0.5,
            ..Default::default()
        }
        .measure(&h);
        let rdot = 0.3 * (1.5 * t).cos();
        assert!((ahead.ay.unwrap()[i] - h.ay[i] - 0.5 * rdot).abs() < 1e-4);
        let rolled = Sensors {
            roll_gradient: 0.01,
            ..Default::default()
        }
        .measure(&h);
        let phi = 0.01 * h.ay[i];
        assert!(
            (rolled.ay.as_ref().unwrap()[i] - (h.ay[i] * phi.cos() + G * phi.sin())).abs() < 1e-12
        );
        // Outward roll in a left turn (t = 1 s, ay > 0) reads more than the
        // true acceleration.
        let j = 100;
        assert!(h.ay[j] > 0.0 && rolled.ay.as_ref().unwrap()[j] > h.ay[j]);
    }
}
