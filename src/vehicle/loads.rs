//! Wheel loads and the load-transfer loop.
//!
//! Wheel loads (Wang & Liang eq. 4): static axle loads `m·g·b/l` and
//! `m·g·a/l` (times cos θ on a bank, plus aero load) split evenly, plus a
//! lateral transfer `ΔFz = χ·m·ay·h/d_f` (front) and `(1 − χ)·m·ay·h/d_r`
//! (rear) from the inner (left, for ay > 0) to the outer wheel, with χ = b/l
//! by default. A wheel whose load would go negative is off the ground. With
//! longitudinal load transfer ([`super::Effects::longitudinal_load_transfer`])
//! the axle loads move by `m·ax·h/l` first; a measured bank
//! ([`super::Inputs::bank`]) adds to the constant one, scaled. The share χ
//! is the effects' when they set one ([`super::Effects::transfer_share`]),
//! else the vehicle's; every effect is read through [`super::ModelScalars`].
//!
//! The loop: the loads depend on ay and ay on the forces, which depend on the
//! loads. It is solved by a secant iteration on `g(ay) = ay − Y(ay)/m`, not
//! lagged by a step; `g` is strictly increasing for any tyre whose force does
//! not grow faster with load than `m/(h/d)` allows, so the root is unique.
//! Tyres that give their forces' load derivatives (PAC89) are solved by
//! Newton's method instead (`balance.rs`, `Balance::solve_newton`), to the
//! same test. Units: SI.

use super::scalar::{off, ModelScalars, Scalar};
use super::VehicleModel;
use crate::constants::G;
use num_dual::DualNum;

/// Where the load-transfer solve starts: the last three solutions (the solve
/// starts from their quadratic extrapolation) and the last slope of
/// g(ay) = ay − Y(ay)/m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadTransferSeed {
    /// Last three solutions, newest first, m/s².
    pub ay: [f64; 3],
    /// dg/day estimate.
    pub slope: f64,
}

impl Default for LoadTransferSeed {
    fn default() -> Self {
        Self {
            ay: [0.0; 3],
            slope: 1.0,
        }
    }
}

impl LoadTransferSeed {
    pub(crate) fn predict(&self) -> f64 {
        let [a, b, c] = self.ay;
        3.0 * a - 3.0 * b + c
    }

    /// Records a solution.
    pub(crate) fn push(&mut self, ay: f64) {
        self.ay = [ay, self.ay[0], self.ay[1]];
    }
}

/// Static wheel loads (N) and lateral load transfer per unit ay (N per
/// m/s²), in the model's scalar.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LoadSplit<T = f64> {
    front: T,
    rear: T,
    kf: T,
    kr: T,
    /// Track ratio t_f / t_r: a transfer moment that the front axle cannot
    /// carry, expressed as rear transfer.
    front_to_rear: f64,
}

/// `x` held within `[lo, hi]` (compared by value; as `f64::clamp`).
fn clamp<T: Scalar>(x: T, lo: T, hi: T) -> T {
    if x < lo {
        lo
    } else if x > hi {
        hi
    } else {
        x
    }
}

/// `magnitude` (≥ 0) with the sign of `sign` (as `f64::copysign`).
fn copysign<T: Scalar>(magnitude: T, sign: T) -> T {
    if sign.re().is_sign_negative() {
        -magnitude
    } else {
        magnitude
    }
}

impl<T: Scalar> LoadSplit<T> {
    /// The values without their derivatives.
    pub(crate) fn re(&self) -> LoadSplit<f64> {
        LoadSplit {
            front: self.front.re(),
            rear: self.rear.re(),
            kf: self.kf.re(),
            kr: self.kr.re(),
            front_to_rear: self.front_to_rear,
        }
    }

    /// FL, FR, RL, RR at `ay`. The roll moment m·ay·h is shared between the
    /// axles by the transfer share; an axle whose inner wheel has lifted off
    /// carries no more than its whole load on the outer wheel, and the moment
    /// it cannot carry goes to the other axle (the body pivots on the outer
    /// wheels), so the four loads always add up to the axle loads (m·g·cos θ
    /// plus aero) until both inner wheels are off the ground (roll-over).
    #[inline]
    pub(crate) fn at(&self, ay: T) -> [T; 4] {
        let (mut df, mut dr) = (self.kf * ay, self.kr * ay);
        if df.abs() > self.front {
            dr += (df - copysign(self.front, df)) * self.front_to_rear;
            df = copysign(self.front, df);
        }
        if dr.abs() > self.rear {
            df += (dr - copysign(self.rear, dr)) / self.front_to_rear;
            df = clamp(df, -self.front, self.front);
            dr = copysign(self.rear, dr);
        }
        [
            self.front - df,
            self.front + df,
            self.rear - dr,
            self.rear + dr,
        ]
    }
}

impl LoadSplit<f64> {
    /// The wheel loads' slopes `dFz/day` (FL, FR, RL, RR; N per m/s²) at
    /// `ay` where no wheel has lifted off, so that [`LoadSplit::at`] is
    /// linear about it (strictly inside the lift-off bounds); None
    /// otherwise.
    pub(crate) fn slopes(&self, ay: f64) -> Option<[f64; 4]> {
        let (df, dr) = (self.kf * ay, self.kr * ay);
        (df.abs() < self.front && dr.abs() < self.rear)
            .then_some([-self.kf, self.kf, -self.kr, self.kr])
    }
}

/// Solves `ay = Y(ay)/m` by the secant method from `seed`'s prediction, with
/// the seed's slope as the first derivative estimate; `eval(ay)` returns
/// `Y(ay)/m` and what else it computed at those loads. Returns the last
/// iterate, its evaluation's `Y/m` and by-products and the number of
/// evaluations, and leaves
/// the slope in `seed` (the caller records the solution). Without load
/// transfer (`enabled` false) one evaluation at ay = 0.
pub(crate) fn solve_load_transfer<T>(
    enabled: bool,
    seed: &mut LoadTransferSeed,
    tolerance: f64,
    mut eval: impl FnMut(f64) -> (f64, T),
) -> (f64, f64, T, u32) {
    if !enabled {
        let (y, out) = eval(0.0);
        return (0.0, y, out, 0);
    }
    // The integrator keeps one seed per RK stage, so the prediction is a
    // quadratic extrapolation in time and a solve usually ends after one
    // evaluation of the four tyres.
    let mut x1 = seed.predict();
    let (mut y1, mut o1) = eval(x1);
    let mut g1 = x1 - y1;
    let mut slope = seed.slope;
    let mut evals = 1;
    while g1.abs() > tolerance * (1.0 + x1.abs()) && evals < 60 {
        let x2 = x1 - g1 / slope;
        let (y2, o2) = eval(x2);
        let g2 = x2 - y2;
        let s = (g2 - g1) / (x2 - x1);
        // g' = 1 − Y'/m stays near 1; a wild secant (wheel lift-off kinks
        // Y) falls back to the fixed-point slope 1.
        slope = if s.is_finite() && (0.1..10.0).contains(&s) {
            s
        } else {
            1.0
        };
        (x1, y1, o1, g1) = (x2, y2, o2, g2);
        evals += 1;
    }
    seed.slope = slope;
    (x1, y1, o1, evals)
}

/// The root `ay` of `g(ay) = ay − y(ay)` (solved in plain numbers, e.g. by
/// [`solve_load_transfer`]) with its derivatives with respect to the
/// variables a dual scalar `T` carries, by implicit differentiation:
/// `dAy/dθ = (∂y/∂θ)/(1 − ∂y/∂ay)`. `y_at_root` is `y` evaluated in `T` at
/// the plain root (its derivative part is `∂y/∂θ`), `slope` is `∂y/∂ay`
/// there (one evaluation in a scalar dual in ay). The derivative is that of
/// the exact root; the iterations' own tolerance moves the value, not the
/// derivative, by more than rounding.
pub fn implicit_root<T: DualNum<f64> + Copy>(ay: f64, y_at_root: T, slope: f64) -> T {
    let sensitivity = (y_at_root - y_at_root.re()) / (1.0 - slope);
    sensitivity + ay
}

impl VehicleModel {
    /// Static wheel loads and the load transferred per m/s² of lateral
    /// acceleration on each axle: computed once per derivative evaluation,
    /// not once per load-transfer iteration.
    pub(crate) fn load_split(&self, speed: f64) -> LoadSplit {
        self.load_split_at(speed, 0.0, 0.0)
    }

    /// [`VehicleModel::load_split`] at longitudinal acceleration `ax` and a
    /// measured bank `bank` ([`super::Effects::bank`]; both zero for a
    /// steady state).
    pub(crate) fn load_split_at(&self, speed: f64, ax: f64, bank: f64) -> LoadSplit {
        let friction = 1.0;
        self.load_split_of(&self.scalars(friction), speed, ax, bank)
    }

    /// [`VehicleModel::load_split_at`] with the model's numbers `sc` in a
    /// scalar.
    pub(crate) fn load_split_of<T: Scalar>(
        &self,
        sc: &ModelScalars<T>,
        speed: f64,
        ax: f64,
        bank: f64,
    ) -> LoadSplit<T> {
        let v = &self.vehicle;
        let (sf, sr) = sc.loads.static_axle;
        let (mut sf, mut sr) = (T::from(sf), T::from(sr));
        let e = &sc.effects;
        let bank = e.bank(bank);
        if !off(bank) {
            let c = bank.cos();
            sf *= c;
            sr *= c;
        }
        let [aero_f, aero_r] = e.aero_load;
        if !(off(aero_f) && off(aero_r)) {
            sf += aero_f * speed * speed;
            sr += aero_r * speed * speed;
        }
        if !off(e.longitudinal_load_transfer) && ax != 0.0 {
            // A wheelie or a stoppie at the most: no axle load below zero.
            let rigid = v.mass * ax * v.cg_height / v.wheelbase();
            let d = clamp(e.longitudinal_load_transfer * rigid, -sr, sf);
            sf -= d;
            sr += d;
        }
        let (kf, kr) = if self.options.load_transfer {
            sc.loads.transfer
        } else {
            (T::from(0.0), T::from(0.0))
        };
        LoadSplit {
            front: sf * 0.5,
            rear: sr * 0.5,
            kf,
            kr,
            front_to_rear: sc.loads.front_to_rear,
        }
    }

    /// Wheel loads (FL, FR, RL, RR) at lateral acceleration `ay` (the
    /// tyres' force over the mass) and standstill.
    pub fn wheel_loads(&self, ay: f64) -> [f64; 4] {
        self.load_split(0.0).at(ay)
    }

    /// Wheel loads at lateral acceleration `ay` and speed `speed` (aero).
    pub(crate) fn wheel_loads_at(&self, ay: f64, speed: f64) -> [f64; 4] {
        self.load_split(speed).at(ay)
    }

    /// g·sin θ of the road bank, m/s².
    pub(crate) fn bank_acceleration(&self) -> f64 {
        self.bank_acceleration_at(0.0)
    }

    /// g·sin θ of the road bank with a measured bank `bank` on top of the
    /// constant one ([`super::Effects::bank`]), m/s².
    pub(crate) fn bank_acceleration_at(&self, bank: f64) -> f64 {
        let bank = self.options.effects.bank(bank);
        // No sine in the hot loop of the base model.
        if bank == 0.0 {
            0.0
        } else {
            G * bank.sin()
        }
    }

    /// [`VehicleModel::bank_acceleration_at`] with the model's numbers `sc`
    /// in a scalar.
    pub(crate) fn bank_acceleration_of<T: Scalar>(&self, sc: &ModelScalars<T>, bank: f64) -> T {
        let bank = sc.effects.bank(bank);
        if off(bank) {
            T::from(0.0)
        } else {
            bank.sin() * G
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tyre::{Gim, LateralForceOf, Parameterised, SlipOf};
    use nalgebra::{Const, U1};
    use num_dual::{Dual64, DualSVec64};

    /// A car's Y(ay)/m on load-sensitive brush tyres (stiffness ∝ Fz^0.7)
    /// at fixed slip angles, the loads moving with ay; `p` the front and
    /// rear tyres' lateral parameters.
    fn y_over_m<T: DualNum<f64> + Copy>(tyre: &Gim, p: &[T], ay: T) -> T {
        let mut model = super::super::linear_bicycle();
        model.vehicle = super::super::Vehicle::compact_sedan();
        model.options.load_transfer = true;
        let split = model.load_split(20.0);
        let m = model.vehicle.mass;
        // The split is linear in ay below lift-off: its slope per m/s².
        let (at0, at1) = (split.at(0.0), split.at(1.0));
        let mut y = T::from(0.0);
        for (i, alpha) in [0.03, 0.03, 0.02, 0.02].into_iter().enumerate() {
            let fz = ay * (at1[i] - at0[i]) + at0[i];
            let q = if i < 2 { &p[..5] } else { &p[5..] };
            let s = SlipOf {
                alpha: T::from(alpha),
                fz,
                mu_scale: T::from(1.0),
                speed: 20.0,
            };
            y += tyre.lateral_force_of(q, &s) / m;
        }
        y
    }

    #[test]
    fn the_load_transfer_roots_derivatives_are_the_implicit_ones() {
        let tyre = Gim {
            load_exponent: 0.7,
            friction_decay: 0.2,
            ..Gim::new(40_000.0, 0.15, 1.0)
        };
        let p0: Vec<f64> = tyre
            .parameters()
            .into_iter()
            .chain(tyre.parameters())
            .collect();
        let root = |p: &[f64]| {
            let mut seed = LoadTransferSeed::default();
            let (_, _, ay, _) = solve_load_transfer(true, &mut seed, 1e-15, |ay| {
                let y = y_over_m(&tyre, p, ay);
                (y, ay)
            });
            ay
        };
        let ay = root(&p0);
        assert!(ay > 1.0, "a car cornering: {ay}");
        type D = DualSVec64<10>;
        let dual: Vec<D> = p0
            .iter()
            .enumerate()
            .map(|(k, &v)| D::from(v).derivative(k))
            .collect();
        let slope = y_over_m(
            &tyre,
            &p0.iter().map(|&v| Dual64::from(v)).collect::<Vec<_>>(),
            Dual64::from(ay).derivative(),
        )
        .eps;
        let lifted = implicit_root(ay, y_over_m(&tyre, &dual, D::from(ay)), slope);
        assert_eq!(lifted.re, ay);
        let grad = lifted.eps.unwrap_generic(Const::<10>, U1);
        let bounds: Vec<(f64, f64)> = tyre.bounds().into_iter().chain(tyre.bounds()).collect();
        for k in 0..10 {
            let h = 1e-3 * p0[k].abs().max(0.1 * (bounds[k].1 - bounds[k].0));
            let at = |m: f64| {
                let mut p = p0.clone();
                p[k] += m * h;
                root(&p)
            };
            let central = (8.0 * (at(1.0) - at(-1.0)) - (at(2.0) - at(-2.0))) / (12.0 * h);
            if grad[k] == 0.0 {
                assert_eq!(central, 0.0, "parameter {k}");
            } else {
                let e = (grad[k] - central).abs() / grad[k].abs();
                assert!(e < 1e-6, "parameter {k}: {} vs {central}", grad[k]);
            }
        }
    }
}
