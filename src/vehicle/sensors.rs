//! How a measurement system sees the vehicle ([`Sensors`]): the sensor
//! effects among the diagnosis's candidates, part of the vehicle model's
//! [`super::Effects`]. They act on the response the model computes, not
//! on its dynamics. All zero is an ideal measurement.
//!
//! - `delay` (s): every channel reports its value `delay` seconds late;
//! - `yaw_rate_bias` (rad/s), `ay_bias` (m/s²), `beta_bias` (rad): constant
//!   offsets (a sideslip sensor's misalignment is one);
//! - `accelerometer_x` (m, positive ahead of the centre of gravity): the
//!   inertial unit's position. Its accelerometer also feels the yaw
//!   acceleration, `ay + x·ṙ`, and a sideslip it measures (a GNSS/INS or
//!   optical sensor at the unit) is the velocity angle there,
//!   `β + x·r/u` (the lateral velocity at x is `v + x·r`; small angles);
//! - `beta_at` (m ahead of the centre of gravity, or None): where a
//!   campaign states that the sideslip is measured by a sensor of its own
//!   (`[sensors] beta_x`), its point: the sideslip is `β + x·r/u` there,
//!   whatever the accelerometer's position (None: at the inertial unit);
//! - `roll_gradient` (rad per m/s²): the body rolls by φ = k·ay (ISO 8855:
//!   positive φ puts the right side down, outward in a left turn) and a
//!   body-fixed accelerometer reads `ay·cos φ + g·sin φ`;
//! - `mount_yaw` (rad): the inertial unit turned by ψₘ in its mount about
//!   the body's z axis (ISO 8855: z up, ψₘ > 0 turns the unit's x axis to
//!   the left, counter-clockwise seen from above). The unit's y axis is
//!   then (−sin ψₘ, cos ψₘ) in body axes, so its accelerometer reads the
//!   body's specific force (ax, ay) as `ay_m = ay·cos ψₘ − ax·sin ψₘ`: a
//!   unit turned left reads braking (ax < 0) as a left acceleration. The
//!   ax it mixes in is the run's longitudinal acceleration as the model
//!   reads it (a logged `ax` channel, else the speed's derivative), which
//!   the same unit logs as `ax·cos ψₘ + ay·sin ψₘ`: taking it for the
//!   body's leaves `ay·sin²ψₘ`, 0.1 % of ay at 2°. The gyro's yaw rate is
//!   a rate about z, which a turn about z leaves as it is; a sideslip the
//!   unit measures in its own axes is off by −ψₘ, a constant, which the
//!   sideslip offset `beta_bias` carries (not this term).
//!
//! The numbers may be dual numbers ([`crate::scalar`]): what the sensors
//! record then carries their derivatives. Units: SI, rad.

use crate::constants::G;
use crate::manoeuvre::Interpolator;
use crate::scalar::{off, Scalar};

/// Sensor effects, in a scalar of [`crate::scalar`] (`f64` by default).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Sensors<T = f64> {
    /// Reporting delay, s.
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
    /// The inertial unit's yaw in its mount, rad (ISO 8855: positive
    /// turns its x axis to the left).
    pub mount_yaw: T,
    /// The sideslip's own measurement point ahead of the centre of
    /// gravity, m, where stated (None: at the inertial unit,
    /// `accelerometer_x`). Stated, never fitted: a plain number.
    pub beta_at: Option<f64>,
}

impl<T: Copy> Sensors<T> {
    /// Every number mapped by `f` (a lift into dual numbers, their values).
    pub fn map<U>(&self, f: impl Fn(T) -> U) -> Sensors<U> {
        Sensors {
            delay: f(self.delay),
            yaw_rate_bias: f(self.yaw_rate_bias),
            ay_bias: f(self.ay_bias),
            beta_bias: f(self.beta_bias),
            accelerometer_x: f(self.accelerometer_x),
            roll_gradient: f(self.roll_gradient),
            mount_yaw: f(self.mount_yaw),
            beta_at: self.beta_at,
        }
    }
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

/// The lowest speed a sideslip away from the centre of gravity is taken
/// at, m/s: below it `x·r/u` has no meaning (the replays start above the
/// campaign's minimum speed, 5 m/s by default).
const SIDESLIP_MIN_SPEED: f64 = 1.0;

impl<T: Scalar> Sensors<T> {
    /// Whether the body's roll enters the accelerometer: not where the
    /// roll gradient is +0 in plain numbers, whose `ay·cos φ + g·sin φ` is
    /// `ay` to the bit (a −0 gradient or a dual one, whose derivative
    /// parts would move, takes the general path).
    fn rolls(&self) -> bool {
        !(T::PLAIN && self.roll_gradient.re().to_bits() == 0)
    }

    /// What a sideslip measured at the inertial unit adds to the centre of
    /// gravity's at yaw rate `r` and speed `u`: `x·r/u`.
    pub fn sideslip_offset(&self, r: T, u: f64) -> T {
        let x = self.beta_at.map_or(self.accelerometer_x, T::from);
        x * r / u.max(SIDESLIP_MIN_SPEED)
    }

    /// Whether the accelerometer reads the longitudinal acceleration (its
    /// mount is yawed): only then does [`Sensors::seen`] read its `ax`.
    pub fn reads_ax(&self) -> bool {
        !off(self.mount_yaw)
    }

    /// What the sensors record of a response (yaw rate, `ay` and sideslip
    /// at times `t`, at forward speeds `speed` and longitudinal
    /// accelerations `ax`), at the same times: (yaw rate, ay, sideslip).
    /// `ax` is read only where [`Sensors::reads_ax`] (it may be empty
    /// otherwise).
    ///
    /// # Panics
    /// When the mount is yawed and `ax` is not one value per time.
    pub fn seen(
        &self,
        t: &[f64],
        speed: &[f64],
        ax: &[f64],
        yaw_rate: &[T],
        ay: &[T],
        beta: &[T],
    ) -> [Vec<T>; 3] {
        let yaw_acc = derivative(t, yaw_rate);
        let flat = !self.rolls();
        let mut ay_seen: Vec<T> = ay
            .iter()
            .zip(&yaw_acc)
            .map(|(&ay, &ra)| {
                // φ = +0·ay is a zero of ay's sign: `ay·cos φ + g·sin φ` is
                // a finite ay to the bit (signed zeros too), without a sine
                // and a cosine a sample (a profiled twentieth of a sedan
                // log's diagnosis); an infinite one gives NaN, as it did.
                let tilted = if flat && ay.re().is_finite() {
                    ay
                } else {
                    let phi = self.roll_gradient * ay;
                    ay * phi.cos() + phi.sin() * G
                };
                tilted + self.accelerometer_x * ra
            })
            .collect();
        if self.reads_ax() {
            assert_eq!(ax.len(), t.len(), "one ax per time");
            let (sin, cos) = (self.mount_yaw.sin(), self.mount_yaw.cos());
            for (a, &x) in ay_seen.iter_mut().zip(ax) {
                *a = *a * cos - sin * x;
            }
        }
        for a in &mut ay_seen {
            *a += self.ay_bias;
        }
        let yaw_seen: Vec<T> = yaw_rate.iter().map(|&r| r + self.yaw_rate_bias).collect();
        // Without a delay a channel is handed on as it is, not copied.
        let late = |y: Vec<T>| -> Vec<T> {
            if off(self.delay) {
                y
            } else {
                let mut nodes = Interpolator::new(t);
                t.iter()
                    .map(|&s| nodes.at(&y, T::from(s) - self.delay))
                    .collect()
            }
        };
        let at_cg = self.beta_at.map_or(off(self.accelerometer_x), |x| x == 0.0);
        let beta_seen = if off(self.beta_bias) && at_cg {
            late(beta.to_vec())
        } else {
            let b: Vec<T> = beta
                .iter()
                .zip(yaw_rate)
                .zip(speed)
                .map(|((&b, &r), &u)| b + self.sideslip_offset(r, u) + self.beta_bias)
                .collect();
            late(b)
        };
        [late(yaw_seen), late(ay_seen), beta_seen]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 10 s at 100 Hz of a 1.5 rad/s sine: (t, yaw rate, ay, sideslip).
    fn history() -> [Vec<f64>; 4] {
        let t: Vec<f64> = (0..=1000).map(|i| i as f64 * 0.01).collect();
        let wave = |a: f64| t.iter().map(|x| a * (1.5 * x).sin()).collect::<Vec<_>>();
        let (r, ay, beta) = (wave(0.2), wave(4.0), wave(-0.01));
        [t, r, ay, beta]
    }

    fn measure(s: &Sensors) -> [Vec<f64>; 3] {
        let [t, r, ay, beta] = history();
        let u = vec![20.0; t.len()];
        // Braking at 3 m/s² through the sine.
        let ax = vec![-3.0; t.len()];
        s.seen(&t, &u, &ax, &r, &ay, &beta)
    }

    #[test]
    fn ideal_sensors_record_the_history() {
        let [_, r, ay, beta] = history();
        assert_eq!(measure(&Sensors::default()), [r, ay, beta]);
    }

    #[test]
    fn each_sensor_effect_has_its_closed_form() {
        let [time, r, ay, beta] = history();
        let i = 400; // t = 4 s
        let t = time[i];
        let delayed = measure(&Sensors {
            delay: 0.1,
            ..Default::default()
        });
        assert!((delayed[0][i] - 0.2 * (1.5 * (t - 0.1)).sin()).abs() < 1e-4);
        let biased = measure(&Sensors {
            yaw_rate_bias: 0.01,
            ay_bias: -0.2,
            beta_bias: 0.003,
            ..Default::default()
        });
        assert!((biased[2][i] - beta[i] - 0.003).abs() < 1e-15);
        assert!((biased[0][i] - r[i] - 0.01).abs() < 1e-15);
        assert!((biased[1][i] - ay[i] + 0.2).abs() < 1e-12);
        let ahead = measure(&Sensors {
            accelerometer_x: 0.5,
            ..Default::default()
        });
        let rdot = 0.3 * (1.5 * t).cos();
        assert!((ahead[1][i] - ay[i] - 0.5 * rdot).abs() < 1e-4);
        // The unit's sideslip: the velocity angle 0.5 m ahead, at 20 m/s.
        assert!((ahead[2][i] - beta[i] - 0.5 * r[i] / 20.0).abs() < 1e-15);
        assert_eq!(ahead[0], r);
        // A sideslip sensor of its own 1.5 m ahead: the sideslip is taken
        // there, the accelerometer's ay still 0.5 m ahead.
        let apart = measure(&Sensors {
            accelerometer_x: 0.5,
            beta_at: Some(1.5),
            ..Default::default()
        });
        assert!((apart[2][i] - beta[i] - 1.5 * r[i] / 20.0).abs() < 1e-15);
        assert_eq!(apart[1], ahead[1]);
        let rolled = measure(&Sensors {
            roll_gradient: 0.01,
            ..Default::default()
        });
        let phi = 0.01 * ay[i];
        assert!((rolled[1][i] - (ay[i] * phi.cos() + G * phi.sin())).abs() < 1e-12);
        // Outward roll in a left turn (t = 1 s, ay > 0) reads more than the
        // true acceleration.
        let j = 100;
        assert!(ay[j] > 0.0 && rolled[1][j] > ay[j]);
    }

    // A zero roll gradient skips the tilt's sine and cosine
    // (`Sensors::rolls`): the record must be the tilt formula's to the bit,
    // signed zeros and a diverged (infinite, NaN) ay included.
    #[test]
    fn a_zero_roll_gradient_reads_the_tilt_formula_to_the_bit() {
        let t: Vec<f64> = (0..8).map(|i| i as f64 * 0.01).collect();
        let u = vec![20.0; t.len()];
        let r = vec![0.1, -0.2, 0.0, 0.3, 0.05, -0.1, 0.2, 0.0];
        let ay = vec![
            4.0,
            -0.0,
            0.0,
            -7.5e-300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            1e-3,
        ];
        for x in [0.0, 0.7] {
            let s = Sensors {
                accelerometer_x: x,
                ..Default::default()
            };
            let [_, seen, _] = s.seen(&t, &u, &[], &r, &ay, &r);
            let ra = derivative(&t, &r);
            for i in 0..t.len() {
                let phi = 0.0 * ay[i];
                // The default bias, +0, added after as `seen` adds it.
                let want = ay[i] * phi.cos() + phi.sin() * G + x * ra[i] + 0.0;
                // A NaN's sign bit is the compiler's (a product folded at
                // compile time is a positive NaN, x86 gives a negative one
                // at run time): NaN as NaN, every other value to the bit.
                if want.is_nan() {
                    assert!(seen[i].is_nan(), "{i}: x {x}");
                } else {
                    assert_eq!(seen[i].to_bits(), want.to_bits(), "{i}: x {x}");
                }
            }
        }
    }

    #[test]
    fn a_unit_yawed_in_its_mount_reads_part_of_ax_as_ay() {
        let [_, r, ay, beta] = history();
        // Turned 2° to the left: its y axis leans back, so braking (ax =
        // −3 m/s²) reads 3·sin 2° = 0.105 m/s² to the left, on top of
        // ay·cos 2°, with the bias added after.
        let psi = 2f64.to_radians();
        let yawed = measure(&Sensors {
            mount_yaw: psi,
            ay_bias: 0.1,
            ..Default::default()
        });
        for i in [0, 123, 400, 777] {
            let want = ay[i] * psi.cos() + 3.0 * psi.sin() + 0.1;
            assert!((yawed[1][i] - want).abs() < 1e-12, "{i}");
        }
        // At 0 the ax is not read (none given, the same record).
        let t: Vec<f64> = (0..=1000).map(|i| i as f64 * 0.01).collect();
        let u = vec![20.0; t.len()];
        let plain = Sensors::default().seen(&t, &u, &[], &r, &ay, &beta);
        assert_eq!(plain, [r.clone(), ay.clone(), beta.clone()]);
        // A turn about z leaves the gyro and the sideslip as they are.
        assert_eq!(yawed[0], r);
        assert_eq!(yawed[2], beta);
        // The opposite turn reads braking to the right: the sign is odd.
        let right = measure(&Sensors {
            mount_yaw: -psi,
            ..Default::default()
        });
        assert!((right[1][400] - (ay[400] * psi.cos() - 3.0 * psi.sin())).abs() < 1e-12);
    }
}
