//! The steer path between the logged steer and the road wheels
//! ([`SteerPath`]): a steering ratio's error (a gain and a cubic term, the
//! diagnosis's `steering_ratio`), then an actuator's dead time and
//! first-order lag (its `steer_path`), part of the vehicle model's
//! [`super::Effects`]. It is linear in the input, so it is no state of the
//! model: a replay whose path is on runs the path's exact output for the
//! logged (piecewise-linear) steer at its stage times; off, the road
//! wheels follow the logged steer as it is. Its numbers may be dual
//! numbers ([`crate::scalar`]): the output then carries their derivatives.
//! Units: s, rad.

use crate::manoeuvre::Interpolator;
use crate::scalar::{off, Scalar};

/// The steer path between the logged steer δ and the road wheels:
/// δ_wheel(t) = lag_τ(ρ(t − delay)), with ρ = g·(δ + k₃·δ³) the steer
/// through the steering ratio's error (each logged sample shaped, the
/// shaped samples joined piecewise-linearly) and lag_τ a first-order lag
/// of time constant `lag` (dy/dt = (u − y)/τ). The logged steer is the
/// piecewise-linear signal through its samples, held at its first sample
/// before the start (and at its last after the end), and the lag starts
/// settled on that first sample. Its numbers may be dual numbers
/// ([`crate::scalar`]): the output then carries their derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteerPath<T = f64> {
    /// Dead time, s (≥ 0).
    pub delay: T,
    /// Time constant of the first-order lag, s (≥ 0; 0: none).
    pub lag: T,
    /// The steering ratio's error as a factor g on the logged steer (> 0;
    /// 1: the ratio the logger used is the car's).
    pub gain: T,
    /// The ratio's nonlinearity k₃, rad⁻² of logged steer (0: a constant
    /// ratio; > 0: quicker off centre, as a variable-ratio rack).
    pub cubic: T,
}

impl Default for SteerPath {
    /// The road wheels follow the logged steer as it is.
    fn default() -> Self {
        Self {
            delay: 0.0,
            lag: 0.0,
            gain: 1.0,
            cubic: 0.0,
        }
    }
}

impl<T: Copy> SteerPath<T> {
    /// Both numbers mapped by `f` (a lift into dual numbers, their values).
    pub fn map<U>(&self, f: impl Fn(T) -> U) -> SteerPath<U> {
        SteerPath {
            delay: f(self.delay),
            lag: f(self.lag),
            gain: f(self.gain),
            cubic: f(self.cubic),
        }
    }
}

impl<T: Scalar> SteerPath<T> {
    /// Whether the road wheels follow the logged steer as it is.
    pub fn is_off(&self) -> bool {
        off(self.delay) && off(self.lag) && off(self.gain - 1.0) && off(self.cubic)
    }

    /// The road-wheel steer ρ = g·(δ + k₃·δ³) the ratio gives for the
    /// logged steer `delta`, before the delay and the lag.
    pub fn shaped(&self, delta: f64) -> T {
        self.gain * (self.cubic * delta.powi(3) + delta)
    }

    /// The road-wheel steer at times `at` (in any order) of the steer
    /// logged at increasing times `t` (repeated times allowed: a jump). The
    /// delay interpolates the samples at `at − delay`; the lag is the exact
    /// discretisation of the first-order lag driven by the delayed
    /// piecewise-linear input, stepped from one break point or output time
    /// to the next (the delayed input is linear between them), so the
    /// output is exact to round-off at every time asked for, whatever the
    /// spacing. Without a lag, a lag being differentiated at zero adds its
    /// one-sided derivative `−τ·δ̇` (value unchanged).
    pub fn apply(&self, t: &[f64], steer: &[f64], at: &[f64]) -> Vec<T> {
        assert_eq!(t.len(), steer.len(), "one steer per time");
        assert!(!t.is_empty(), "a steer path needs samples");
        let delay = self.delay;
        // The ratio first: the shaped samples are the delay's and the
        // lag's input (their values alone for the lag's slope below).
        let logged: Vec<T> = steer.iter().map(|&v| self.shaped(v)).collect();
        let values: Vec<f64> = logged.iter().map(|v| v.re()).collect();
        if self.lag.re() <= 0.0 {
            let mut nodes = Interpolator::new(t);
            return at
                .iter()
                .map(|&s| {
                    let y = nodes.at(&logged, T::from(s) - delay);
                    if self.lag.is_constant() {
                        y
                    } else {
                        y - self.lag * slope_below(t, &values, s - delay.re())
                    }
                })
                .collect();
        }
        let tau = self.lag;
        let one = T::from(1.0);
        // One exact step of h of the lag from y with the input linear from
        // u0 to u1: y·a + (1 − a)·u0 + (u1 − u0)·(1 − (1 − a)/x), with
        // x = h/τ and a = e^(−x).
        let advance = |y: T, u0: T, u1: T, h: T| -> T {
            let x = h / tau;
            if x.re() <= 0.0 {
                // A step of no length whose ends move with the parameters
                // (an output time on a delayed break point): the lag's
                // first-order change, zero in value.
                return if x.is_constant() { y } else { y + (u0 - y) * x };
            }
            let one_minus_a = -(-x).exp_m1();
            let a = one - one_minus_a;
            // 1 − (1 − a)/x: in dual numbers by its series for a short
            // step, whose quotient of two small numbers would lose the
            // derivative to rounding (the value is the same to rounding).
            let ramp = if T::PLAIN || x.re() > 1e-3 {
                one - one_minus_a / x
            } else {
                x * (one - x * (one - x * 0.25) * (1.0 / 3.0)) * 0.5
            };
            a * y + one_minus_a * u0 + (u1 - u0) * ramp
        };
        let mut order: Vec<usize> = (0..at.len()).collect();
        order.sort_by(|&i, &j| at[i].total_cmp(&at[j]));
        let node = |j: usize| delay + t[j];
        let mut out = vec![T::from(0.0); at.len()];
        // The state: time, input and output there; the next break point.
        let (mut s, mut u, mut y) = (node(0), logged[0], logged[0]);
        let mut j = 1;
        // An output time on a break point whose time moves with the delay
        // still steps (by nothing in value) to carry its derivative.
        let ahead = |q: f64, s: T| q > s.re() || (q == s.re() && !s.is_constant());
        for i in order {
            let q = at[i];
            if ahead(q, s) {
                while j < t.len() && node(j).re() <= q {
                    y = advance(y, u, logged[j], node(j) - s);
                    (s, u) = (node(j), logged[j]);
                    j += 1;
                }
                if ahead(q, s) {
                    let uq = if j < t.len() {
                        let w = (T::from(q) - delay - t[j - 1]) / (t[j] - t[j - 1]);
                        logged[j - 1] + w * (logged[j] - logged[j - 1])
                    } else {
                        u
                    };
                    y = advance(y, u, uq, T::from(q) - s);
                    (s, u) = (T::from(q), uq);
                }
            }
            out[i] = y;
        }
        out
    }
}

/// The slope of the piecewise-linear signal (`t`, `y`) just below time `x`
/// (0 outside it and across a jump).
fn slope_below(t: &[f64], y: &[f64], x: f64) -> f64 {
    let k = t.partition_point(|v| *v < x);
    if k == 0 || k >= t.len() || t[k] <= t[k - 1] {
        0.0
    } else {
        (y[k] - y[k - 1]) / (t[k] - t[k - 1])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::manoeuvre::interpolate;

    #[test]
    fn a_pure_steer_delay_shifts_a_ramp() {
        // A ramp from t = 1 s at 0.1 rad/s, sampled at 25 Hz, delayed 0.13 s
        // (not a multiple of the sampling interval).
        let t: Vec<f64> = (0..200).map(|i| 0.04 * i as f64).collect();
        let ramp = |t: f64| 0.1 * (t - 1.0).max(0.0);
        let steer: Vec<f64> = t.iter().map(|&t| ramp(t)).collect();
        let path = SteerPath {
            delay: 0.13,
            lag: 0.0,
            ..SteerPath::default()
        };
        let at: Vec<f64> = (0..1000).map(|i| 0.0077 * i as f64).collect();
        let out = path.apply(&t, &steer, &at);
        for (&s, &y) in at.iter().zip(&out) {
            let expected = if s - 0.13 >= *t.last().unwrap() {
                *steer.last().unwrap()
            } else {
                ramp(s - 0.13)
            };
            // Before the ramp's corner is delayed past a sample the
            // interpolation between samples sees the corner: exact elsewhere.
            let near_corner = (s - 1.13).abs() < 0.04;
            if !near_corner {
                assert!((y - expected).abs() < 1e-12, "t {s}: {y} vs {expected}");
            }
        }
        // The first sample is held before the start.
        let early = path.apply(&[0.0, 1.0], &[0.2, 0.3], &[-1.0, 0.0, 0.1, 0.13]);
        assert_eq!(early, vec![0.2, 0.2, 0.2, 0.2]);
        // The same with the lag: off, and every time order.
        let off = SteerPath::<f64>::default().apply(&t, &steer, &at);
        assert_eq!(
            off,
            at.iter()
                .map(|&s| interpolate(&t, &steer, s))
                .collect::<Vec<_>>()
        );
        let mut rev = at.clone();
        rev.reverse();
        let lagged = SteerPath {
            delay: 0.13,
            lag: 0.2,
            ..SteerPath::default()
        };
        let mut back = lagged.apply(&t, &steer, &rev);
        back.reverse();
        assert_eq!(back, lagged.apply(&t, &steer, &at));
    }

    #[test]
    fn the_steer_lag_of_a_step_is_one_minus_an_exponential() {
        // A unit step 1e-14 s wide, then samples every millisecond: the lag's
        // output at the samples is 1 − exp(−t/τ) (the ramp's width moves it
        // by about 1e-14/(2τ)).
        let tau = 0.15;
        let mut t = vec![-1e-14];
        t.extend((0..2000).map(|i| 1e-3 * i as f64));
        let mut steer = vec![1.0; t.len()];
        steer[0] = 0.0;
        let path = SteerPath {
            delay: 0.0,
            lag: tau,
            ..SteerPath::default()
        };
        let out = path.apply(&t, &steer, &t);
        assert_eq!(out[0], 0.0);
        for (&s, &y) in t.iter().zip(&out).skip(1) {
            let expected = 1.0 - (-s / tau).exp();
            assert!((y - expected).abs() < 1e-12, "t {s}: {y} vs {expected}");
        }
        // Delayed by 0.2 s, the same curve 0.2 s later, between the samples
        // too.
        let delayed = SteerPath {
            delay: 0.2,
            lag: tau,
            ..SteerPath::default()
        };
        let at: Vec<f64> = (0..700).map(|i| 0.2 + 0.00237 * i as f64).collect();
        for (&s, &y) in at.iter().zip(&delayed.apply(&t, &steer, &at)) {
            let expected = 1.0 - (-(s - 0.2) / tau).exp();
            assert!((y - expected).abs() < 1e-12, "t {s}: {y} vs {expected}");
        }
    }
}
