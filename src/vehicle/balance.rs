//! The lateral force balance of one evaluation of the right-hand side
//! ([`super::VehicleModel::rates`]): the axles' tyres at their slip angles
//! on the wheel loads of a lateral acceleration, and the load-transfer
//! loop that finds that acceleration (`ay = Y(ay)/m`, [`super::loads`]),
//! with a compliant front axle's slip solved at every load. The effects it
//! reads (compliance, stiffness scales, roll camber, combined slip, the
//! road friction) come from [`super::ModelScalars`]. In a dual scalar
//! ([`crate::scalar`]) both implicit solves run in plain numbers and are
//! differentiated at their roots. Units: SI, rad; ISO 8855 signs.

use super::loads::{solve_load_transfer, LoadSplit};
use super::scalar::{off, ModelScalars, Scalar};
use super::wheels::{AxleTyres, FRONT, REAR};
use super::{Inputs, Kinematics, LoadTransferSeed, VehicleModel, MIN_SPEED};

/// What the load-transfer loop carries out of its last evaluation.
#[derive(Debug, Clone, Copy)]
pub(crate) struct AxleSolution<T> {
    pub(crate) alpha_front: T,
    pub(crate) fy_front: T,
    pub(crate) fy_rear: T,
    pub(crate) projection: T,
    pub(crate) fz: [T; 4],
}

impl<T: Scalar> AxleSolution<T> {
    /// [`Scalar::eliminate`] of every value.
    fn eliminate(self, k: usize, x: T) -> Self {
        Self {
            alpha_front: self.alpha_front.eliminate(k, x),
            fy_front: self.fy_front.eliminate(k, x),
            fy_rear: self.fy_rear.eliminate(k, x),
            projection: self.projection.eliminate(k, x),
            fz: self.fz.map(|f| f.eliminate(k, x)),
        }
    }
}

/// An axle's tyre at a slip angle. A tyre whose force is proportional to
/// its load ([`AxleTyres::per_load`]) is evaluated here once for both
/// wheels and every load the load-transfer loop tries.
#[derive(Debug, Clone, Copy)]
struct AtSlip<T> {
    axle: usize,
    alpha: T,
    per_load: Option<T>,
}

/// What every tyre evaluation of one right-hand side shares: road friction
/// scale and speed.
#[derive(Debug, Clone, Copy)]
struct Road<T> {
    mu: T,
    speed: f64,
}

impl<T: Scalar> AtSlip<T> {
    fn new(tyres: &impl AxleTyres<T>, axle: usize, alpha: T, road: Road<T>) -> Self {
        Self {
            axle,
            alpha,
            per_load: tyres.per_load(axle, alpha, road.mu, road.speed),
        }
    }

    /// A wheel's lateral force at load `fz`.
    // Inlined, always (as `axle`, `front` and `Balance::eval`): the
    // load-transfer loop calls them for every load it tries (about twice a
    // right-hand side with per-load tyres), a per-load tyre's force is then
    // two products, and the calls, left out of line by the compiler, took a
    // sixth of the Putnam campaign's replays (profiled, session 96).
    // Inlining changes no operation: the same numbers.
    #[inline(always)]
    fn wheel(&self, tyres: &impl AxleTyres<T>, fz: T, road: Road<T>) -> T {
        match self.per_load {
            Some(k) if fz > 0.0 => k * fz,
            Some(_) => T::from(0.0),
            None => tyres.wheel(self.axle, self.alpha, fz, road.mu, road.speed),
        }
    }

    /// A wheel's lateral force with a longitudinal force `fx` taken from its
    /// friction circle: `Fy0·√(1 − (Fx/(μ·Fz))²)`, zero once `fx` uses all
    /// of it.
    fn combined(&self, tyres: &impl AxleTyres<T>, fz: T, fx: T, road: Road<T>) -> T {
        let fy0 = self.wheel(tyres, fz, road);
        if off(fx) || off(fy0) {
            return fy0;
        }
        let ratio = fx / (tyres.friction_coefficient(self.axle, fz, road.mu) * fz);
        let left = T::from(1.0) - ratio * ratio;
        if left.re() > 0.0 {
            fy0 * left.sqrt()
        } else {
            fy0 * 0.0
        }
    }

    /// Axle force on wheel loads `fz`, plus camber thrust `thrust` per
    /// unit load (roll camber); with a longitudinal force `fx` per wheel
    /// (combined slip), each wheel's force reduced on its friction circle.
    #[inline(always)]
    fn axle(
        &self,
        tyres: &impl AxleTyres<T>,
        fz: [T; 2],
        thrust: T,
        fx: Option<T>,
        road: Road<T>,
    ) -> T {
        let y = match fx {
            None => self.wheel(tyres, fz[0], road) + self.wheel(tyres, fz[1], road),
            Some(fx) => {
                self.combined(tyres, fz[0], fx, road) + self.combined(tyres, fz[1], fx, road)
            }
        };
        with_thrust(y, fz, thrust)
    }
}

/// An axle's force `y` of its wheels plus camber thrust `thrust` per unit
/// of its loads `fz`.
#[inline(always)]
fn with_thrust<T: Scalar>(y: T, fz: [T; 2], thrust: T) -> T {
    if off(thrust) {
        y
    } else {
        y + thrust * (fz[0] + fz[1])
    }
}

/// The lateral force balance the load-transfer loop solves, with
/// everything that does not depend on the loads evaluated once.
#[derive(Debug, Clone, Copy)]
pub(super) struct Balance<T> {
    split: LoadSplit<T>,
    /// The front tyre at its fixed slip angle (None: a compliant front,
    /// whose slip depends on its force).
    front_at: Option<AtSlip<T>>,
    rear_at: AtSlip<T>,
    alpha_front: T,
    kin_front: T,
    compliance: T,
    steer: T,
    scale_front: T,
    thrust: [T; 2],
    fx: Option<[T; 2]>,
    fixed_projection: T,
    inv_mass: f64,
    road: Road<T>,
    exact_kinematics: bool,
    pub(super) transfer: bool,
    directions: [usize; 2],
}

impl<T: Scalar> Balance<T> {
    /// The values without their derivatives (the tyres' per-load factors
    /// too: their value parts, not evaluated again).
    fn re(&self) -> Balance<f64> {
        let re2 = |x: [T; 2]| [x[0].re(), x[1].re()];
        let road = Road {
            mu: self.road.mu.re(),
            speed: self.road.speed,
        };
        let at = |a: &AtSlip<T>| AtSlip {
            axle: a.axle,
            alpha: a.alpha.re(),
            per_load: a.per_load.map(|k| k.re()),
        };
        Balance {
            split: self.split.re(),
            front_at: self.front_at.as_ref().map(at),
            rear_at: at(&self.rear_at),
            alpha_front: self.alpha_front.re(),
            kin_front: self.kin_front.re(),
            compliance: self.compliance.re(),
            steer: self.steer.re(),
            scale_front: self.scale_front.re(),
            thrust: re2(self.thrust),
            fx: self.fx.map(re2),
            fixed_projection: self.fixed_projection.re(),
            inv_mass: self.inv_mass,
            road,
            exact_kinematics: self.exact_kinematics,
            transfer: self.transfer,
            directions: self.directions,
        }
    }

    /// The front axle's force with a compliant steer at slip angle `a`.
    fn front_force(&self, tyres: &impl AxleTyres<T>, a: T, fz: [T; 2]) -> T {
        let at = AtSlip::new(tyres, FRONT, self.scale_front * a, self.road);
        let fx = self.fx.map(|f| f[0]);
        at.axle(tyres, fz, self.thrust[0], fx, self.road)
    }

    /// The plain balance a compliant front's slip is solved in when `T`
    /// carries derivatives (None otherwise).
    pub(super) fn plain_if_compliant(&self) -> Option<Balance<f64>> {
        (!T::PLAIN && self.front_at.is_none()).then(|| self.re())
    }

    /// The front slip angle and axle force on wheel loads `fz`; `re` the
    /// plain balance a compliant front's slip is solved in when `T` carries
    /// derivatives.
    #[inline(always)]
    fn front(&self, tyres: &impl AxleTyres<T>, re: Option<&Balance<f64>>, fz: [T; 2]) -> (T, T) {
        if let Some(at) = &self.front_at {
            let fx = self.fx.map(|f| f[0]);
            return (
                self.alpha_front,
                at.axle(tyres, fz, self.thrust[0], fx, self.road),
            );
        }
        let (kin, c) = (self.kin_front, self.compliance);
        let Some(re) = re else {
            return compliant_slip(kin, c, |a: T| self.front_force(tyres, a, fz));
        };
        // The slip solved in plain numbers, then differentiated at its
        // root: `α − α_kin + c·Fyf(α) = 0`.
        let plain = tyres.plain();
        let fz_re = [fz[0].re(), fz[1].re()];
        let (root, _) = compliant_slip(re.kin_front, re.compliance, |a: f64| {
            re.front_force(&plain, a, fz_re)
        });
        let k = self.directions[1];
        let a = T::variable(root, k);
        let f = self.front_force(tyres, a, fz);
        let alpha = T::implicit(a, a - kin + c * f, k);
        (alpha, f.eliminate(k, alpha))
    }

    /// Both axles' forces on the wheel loads `fz` when both slip angles are
    /// fixed and each wheel's force is its tyre's at its load (no
    /// longitudinal force, no force per unit load): the four wheels in one
    /// call ([`AxleTyres::wheels`]), summed as [`AtSlip::axle`] sums them.
    /// None otherwise.
    #[inline]
    fn both_axles(&self, tyres: &impl AxleTyres<T>, fz: [T; 4]) -> Option<(T, T)> {
        let (front, rear) = (self.front_at.as_ref()?, &self.rear_at);
        if self.fx.is_some() || front.per_load.is_some() || rear.per_load.is_some() {
            return None;
        }
        let (mu, speed) = (self.road.mu, self.road.speed);
        let w = tyres.wheels([front.alpha, rear.alpha], fz, mu, speed);
        Some((
            with_thrust(w[0] + w[1], [fz[0], fz[1]], self.thrust[0]),
            with_thrust(w[2] + w[3], [fz[2], fz[3]], self.thrust[1]),
        ))
    }

    /// `Y(ay)/m` and the axles at lateral acceleration `ay`.
    #[inline(always)]
    pub(super) fn eval(
        &self,
        tyres: &impl AxleTyres<T>,
        re: Option<&Balance<f64>>,
        ay: T,
    ) -> (T, AxleSolution<T>) {
        let fz = self.split.at(ay);
        let (alpha_front, fy_front, fy_rear) = match self.both_axles(tyres, fz) {
            Some((front, rear)) => (self.alpha_front, front, rear),
            None => {
                let (alpha, front) = self.front(tyres, re, [fz[0], fz[1]]);
                let fx = self.fx.map(|f| f[1]);
                let rear = self
                    .rear_at
                    .axle(tyres, [fz[2], fz[3]], self.thrust[1], fx, self.road);
                (alpha, front, rear)
            }
        };
        self.at_forces(alpha_front, fy_front, fy_rear, fz)
    }

    /// `Y/m` and the axles of axle forces `fy_front`, `fy_rear` (N) on
    /// wheel loads `fz` with the front at slip angle `alpha_front`.
    #[inline(always)]
    fn at_forces(
        &self,
        alpha_front: T,
        fy_front: T,
        fy_rear: T,
        fz: [T; 4],
    ) -> (T, AxleSolution<T>) {
        let projection = if off(self.compliance) {
            self.fixed_projection
        } else {
            projection(
                self.exact_kinematics,
                self.steer - self.compliance * fy_front,
            )
        };
        (
            (fy_front * projection + fy_rear) * self.inv_mass,
            AxleSolution {
                alpha_front,
                fy_front,
                fy_rear,
                projection,
                fz,
            },
        )
    }

    /// The load-transfer loop solved from `seed` to `tolerance`: the
    /// tyres' `Y/m`, the axles there and the evaluations made. In dual
    /// numbers the loop runs in plain numbers and one evaluation at its
    /// root, the lateral acceleration seeded in its direction, gives the
    /// root's derivatives ([`Scalar::implicit`]).
    pub(super) fn solve(
        &self,
        tyres: &impl AxleTyres<T>,
        seed: &mut LoadTransferSeed,
        tolerance: f64,
    ) -> (T, AxleSolution<T>, u32) {
        if T::PLAIN {
            if let Some(solved) = self.solve_newton(tyres, seed, tolerance) {
                return solved;
            }
            let (_, y, s, n) = solve_load_transfer(self.transfer, seed, tolerance, |ay| {
                let (y, s) = self.eval(tyres, None, T::from(ay));
                (y.re(), s)
            });
            return (T::from(y), s, n);
        }
        let plain = tyres.plain();
        let re = self.re();
        let (root, _, _, n) = solve_load_transfer(self.transfer, seed, tolerance, |ay| {
            re.eval(&plain, None, ay)
        });
        if !self.transfer {
            let (y, s) = self.eval(tyres, Some(&re), T::from(0.0));
            return (y, s, n);
        }
        let k = self.directions[0];
        let ay = T::variable(root, k);
        let (y, s) = self.eval(tyres, Some(&re), ay);
        let ay = T::implicit(ay, ay - y, k);
        (y.eliminate(k, ay), s.eliminate(k, ay), n)
    }
}

impl<T: Scalar> Balance<T> {
    /// The load-transfer loop by Newton's method on `g(ay) = ay − Y(ay)/m`
    /// where the tyres give their forces' derivatives in load (PAC89) and
    /// the balance is the four wheels' alone (both slip angles fixed, no
    /// longitudinal force, no steering compliance, load transfer on); None
    /// otherwise, and where the seed's prediction lifts a wheel off. Each
    /// pass of the four tyres gives `Y`, `Y'` and `Y''`; the iterate ends
    /// when `|g| ≤ tolerance·(1 + |ay|)` as [`solve_load_transfer`] ends,
    /// or when the forces' second-order Taylor expansion to the Newton step
    /// `Δ` satisfies that test at `ay + Δ` and its second-order term
    /// `|Y''|·Δ²/2` is itself within the tolerance: the neglected third
    /// order is then smaller than the tolerance by a further factor of about
    /// `|Δ|` over the load scale on which a tyre's curve bends (kN, several
    /// m/s² of ay), and the returned forces and loads are those at
    /// `ay + Δ` to well within the loop's tolerance. A step steer's solves
    /// mostly end after one pass instead of two (tested against the
    /// converged root in `vehicle::tests`). An iterate that lifts a wheel
    /// off hands over to the secant loop from there. In plain numbers only
    /// (the values of `T`), reading the balance in place: a plain copy of it
    /// (`Balance::re`) stalled the loop on store forwarding (profiled).
    fn solve_newton(
        &self,
        tyres: &impl AxleTyres<T>,
        seed: &mut LoadTransferSeed,
        tolerance: f64,
    ) -> Option<(T, AxleSolution<T>, u32)> {
        let (front, rear) = (self.front_at.as_ref()?, &self.rear_at);
        let fixed = self.fx.is_none() && front.per_load.is_none() && rear.per_load.is_none();
        if !(self.transfer && fixed && off(self.compliance)) {
            return None;
        }
        let (plain, split) = (tyres.plain(), self.split.re());
        let mu = self.road.mu.re();
        let alpha = [front.alpha.re(), rear.alpha.re()];
        let p = self.fixed_projection.re();
        let weight = [p, p, 1.0, 1.0];
        let (mut x, mut slope, mut evals) = (seed.predict(), seed.slope, 0);
        while let Some(k) = split.slopes(x) {
            let fz = split.at(x);
            let [f, f1, f2] = plain.wheels_in_load(alpha, fz, mu)?;
            evals += 1;
            let (y, s) = self.wheel_sums(f, fz);
            let g = x - y.re();
            // As the secant loop: a NaN ends it too.
            if g.abs() <= tolerance * (1.0 + x.abs()) || g.is_nan() || evals >= 60 {
                seed.slope = slope;
                return Some((y, s, evals));
            }
            let dy: f64 = (0..4).map(|i| weight[i] * f1[i] * k[i]).sum::<f64>() * self.inv_mass;
            let ddy: f64 =
                (0..4).map(|i| weight[i] * f2[i] * k[i] * k[i]).sum::<f64>() * self.inv_mass;
            let exact = 1.0 - dy;
            // g' = 1 − Y'/m stays near 1; beyond, a fixed-point step.
            slope = if (0.1..10.0).contains(&exact) {
                exact
            } else {
                1.0
            };
            let step = -g / slope;
            let next = x + step;
            if slope == exact && split.slopes(next) == Some(k) {
                let taylor: [f64; 4] = std::array::from_fn(|i| {
                    let dz = k[i] * step;
                    f[i] + (f1[i] + 0.5 * f2[i] * dz) * dz
                });
                let (y, s) = self.wheel_sums(taylor, split.at(next));
                let within = tolerance * (1.0 + next.abs());
                if (next - y.re()).abs() <= within && 0.5 * ddy.abs() * step * step <= within {
                    seed.slope = slope;
                    return Some((y, s, evals));
                }
            }
            x = next;
        }
        if evals == 0 {
            return None;
        }
        // A wheel lifts off at `x`: the secant loop from there, the seed's
        // history left as it was.
        let history = seed.ay;
        (seed.ay, seed.slope) = ([x; 3], slope);
        let (_, y, s, n) = solve_load_transfer(true, seed, tolerance, |ay| {
            let (y, s) = self.eval(tyres, None, T::from(ay));
            (y.re(), s)
        });
        seed.ay = history;
        Some((T::from(y), s, evals + n))
    }

    /// `Y/m` and the axles of the four wheels' forces `w` (FL, FR, RL, RR)
    /// on loads `fz`, summed as [`Balance::both_axles`] sums them.
    #[inline]
    fn wheel_sums(&self, w: [f64; 4], fz: [f64; 4]) -> (T, AxleSolution<T>) {
        let (w, fz) = (w.map(T::from), fz.map(T::from));
        let front = with_thrust(w[0] + w[1], [fz[0], fz[1]], self.thrust[0]);
        let rear = with_thrust(w[2] + w[3], [fz[2], fz[3]], self.thrust[1]);
        self.at_forces(self.alpha_front, front, rear, fz)
    }
}

/// cos δ of the force projection (1 in the small-angle form).
pub(super) fn projection<T: Scalar>(exact: bool, steer: T) -> T {
    if exact {
        steer.cos()
    } else {
        T::from(1.0)
    }
}

impl VehicleModel {
    /// The force balance of one right-hand side at road-wheel steer `steer`
    /// (`cos_steer` its projection, [`projection`]) and roll `phi`, with the
    /// front's lag state, its kinematic slip angle and the rear slip angle.
    pub(super) fn balance<T: Scalar>(
        &self,
        sc: &ModelScalars<T>,
        tyres: &impl AxleTyres<T>,
        inp: &Inputs,
        (steer, cos_steer, phi): (T, T, T),
        [lag_front, kin_front, alpha_rear]: [T; 3],
    ) -> Balance<T> {
        let e = &sc.effects;
        let lagged = e.lagged();
        let compliance = e.steering_compliance;
        let [scale_front, scale_rear] = e.cornering_stiffness_scale;
        let road = Road {
            mu: sc.friction,
            speed: inp.speed,
        };
        let u = inp.speed.max(MIN_SPEED);
        // The slip angles the load-transfer loop holds fixed (all but a
        // compliant front's), with their tyres evaluated once.
        let alpha_front = if lagged { lag_front } else { kin_front };
        let front_at = (lagged || off(compliance))
            .then(|| AtSlip::new(tyres, FRONT, scale_front * alpha_front, road));
        let exact_kinematics = self.options.kinematics == Kinematics::Exact;
        Balance {
            split: self.load_split_of(sc, u, inp.ax, inp.bank),
            front_at,
            rear_at: AtSlip::new(tyres, REAR, scale_rear * alpha_rear, road),
            alpha_front,
            kin_front,
            compliance,
            steer,
            scale_front,
            thrust: e.roll_camber.map(|k| k * phi),
            fx: sc.wheel_forces(self.vehicle.mass, inp.ax),
            // Without compliance the wheel's steer, hence the projection,
            // does not depend on the force: one cosine per evaluation.
            fixed_projection: cos_steer,
            inv_mass: sc.loads.inv_mass,
            road,
            exact_kinematics,
            transfer: self.options.load_transfer,
            directions: sc.directions,
        }
    }
}

/// The front slip angle and force with steering compliance `c`:
/// `α = α_kin − c·Fyf(α)`, solved by a secant (Fyf grows with α, so the
/// root is unique).
fn compliant_slip<T: Scalar>(kin: T, c: T, force: impl Fn(T) -> T) -> (T, T) {
    let g = |a: T| {
        let f = force(a);
        (a - kin + c * f, f)
    };
    // g(kin) = c·Fyf(kin): the first iterate's force is also the first
    // residual's.
    let f0 = force(kin);
    let (mut a0, mut a1, mut g0) = (kin, kin - c * f0, c * f0);
    let (mut g1, mut f1) = g(a1);
    for _ in 0..30 {
        if g1.abs() < 1e-13 || g1 == g0 {
            break;
        }
        let a2 = a1 - g1 * (a1 - a0) / (g1 - g0);
        let (g2, f2) = g(a2);
        (a0, g0, a1, g1, f1) = (a1, g1, a2, g2, f2);
    }
    (a1, f1)
}

#[cfg(test)]
mod tests {
    use super::super::{Inputs, Kinematics, Vehicle, VehicleModel, LOAD_TOLERANCE};
    use super::*;
    use crate::tyre::{Pac89, Tyre};

    /// The Newton solve with its Taylor ending (PAC89 axles, lateral load
    /// transfer) against the root solved to 1e-14, over sideslip, yaw rate
    /// and steer up to lifting the inner wheels off and seeds from exact to
    /// 0.3 m/s² away: the lateral acceleration within the loop's tolerance
    /// `1e-9·(1 + |ay|)`, each axle's force within 1e-9 of itself, and a
    /// seed within 1e-4 m/s² (an adaptive step's prediction in a step
    /// steer, mostly) ending after one pass of the tyres where the old
    /// secant loop took two (a Taylor ending without the first-order term
    /// would be off by `F'·ΔFz`, about 0.03 N a wheel at 1e-4 m/s²: four
    /// orders above the tolerance). A high centre of gravity lifts the
    /// inner wheels off in the hardest states.
    #[test]
    fn the_newton_solve_ends_on_the_converged_root() {
        let mut m = VehicleModel::new(
            Vehicle::compact_sedan(),
            Tyre::Pac89(Pac89::adams_example()),
            Tyre::Pac89(Pac89::adams_example()),
        );
        m.options.kinematics = Kinematics::Exact;
        m.options.load_transfer = true;
        m.vehicle.cg_height = 1.2;
        let (mut one_pass, mut near, mut lifted) = (0, 0, 0);
        for steer in [0.0, 0.012, 0.05] {
            for beta in [-0.03, -0.005, 0.0, 0.02] {
                for r in [-0.6, -0.1, 0.0, 0.15, 0.4, 0.9] {
                    let inp = Inputs::steady(steer, 22.2, 1.0);
                    let x = [beta, r, 0.0, 0.0, 0.0, 0.0];
                    let mut fresh = LoadTransferSeed::default();
                    let (_, exact) = m.rates(&x, &inp, &mut fresh, 1e-14);
                    let split = m.load_split(22.2);
                    lifted += usize::from(split.slopes(exact.ay).is_none());
                    for off in [0.0, 1e-7, -1e-5, 1e-4, -1e-2, 0.3] {
                        let mut seed = LoadTransferSeed {
                            ay: [exact.ay + off; 3],
                            slope: 1.0,
                        };
                        let (_, o) = m.rates(&x, &inp, &mut seed, LOAD_TOLERANCE);
                        let within = LOAD_TOLERANCE * (1.0 + exact.ay.abs());
                        assert!((o.ay - exact.ay).abs() <= within, "{x:?} {off}: {o:?}");
                        for (f, g) in [(o.fy_front, exact.fy_front), (o.fy_rear, exact.fy_rear)] {
                            assert!((f - g).abs() <= 1e-9 * g.abs().max(1.0), "{f} vs {g}");
                        }
                        if off.abs() <= 1e-4 && split.slopes(exact.ay).is_some() {
                            near += 1;
                            one_pass += usize::from(o.load_iterations == 1);
                        }
                    }
                }
            }
        }
        assert!(lifted > 0, "some states lift an inner wheel off");
        assert!(
            one_pass * 10 >= near * 9,
            "{one_pass} of {near} in one pass"
        );
    }
}
