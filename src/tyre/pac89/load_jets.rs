//! PAC89's lateral force of a car's four wheels with its first and second
//! derivatives in the wheel load, `∂Fy/∂Fz` (N/N) and `∂²Fy/∂Fz²` (1/N),
//! for the vehicle's load-transfer solve: a Newton step on the lateral
//! acceleration takes the first, and the second tells whether a Taylor
//! expansion of the forces to that step is within the solve's tolerance
//! (`crate::vehicle`'s load-transfer loop). Differentiated by hand through
//! the lateral equations of the parent module (Bakker, Nyborg & Pacejka
//! 1989, Adams numbering, Fz in kN inside): with `f` the load in kN,
//! `D = a1·f² + a2·f`, `BCD = a3·q(f/a4)·(1 − a5·|γ|)` with
//! `q(z) = 2z/(1 + z²)`, `B = BCD/(C·D)`, `E = a6·f + a7`,
//! `Sh = a8·γ + a9·f + a10`, `Sv = a11·f·γ + a12·f + a13`, and the chain rule
//! through `atan` and `sin`. The values are the lanes' to the bit (the same
//! [`super::lanes::Stages`]); a lane off the ground or without friction has
//! zero force and derivatives.

use super::lanes::{each, force, select, stages};
use super::Pac89;
use crate::tyre::{kernels, SlipState, Tyre};

/// Lateral forces of four wheels (N) with their first (N/N) and second
/// (1/N) derivatives in each wheel's own load.
pub(crate) type LoadJets = [[f64; 4]; 3];

impl Tyre {
    /// [`LoadJets`] of a car's four wheels, the first two on this tyre and
    /// the last two on `rear`, at the axles' slip angles `alpha` (front,
    /// rear), the loads `fz` and friction scale `mu`, no camber: Some when
    /// both are PAC89 (in SIMD lanes, AVX2 at run time), None for any other
    /// model.
    #[inline]
    pub(crate) fn lateral_forces_in_load(
        &self,
        rear: &Tyre,
        alpha: [f64; 2],
        fz: [f64; 4],
        mu: f64,
    ) -> Option<LoadJets> {
        match (self, rear) {
            (Tyre::Pac89(f), Tyre::Pac89(r)) => Some(Pac89::axle_jets(f, r, alpha, fz, mu)),
            _ => None,
        }
    }
}

impl Pac89 {
    /// [`LoadJets`] of wheel `i` on `tyres[i]` at `s[i]`.
    #[cfg(test)]
    pub(crate) fn load_jets(tyres: [&Pac89; 4], s: &[SlipState; 4]) -> LoadJets {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2, checked on the line above.
            return unsafe { jets_avx2(tyres, s) };
        }
        jets(tyres, s)
    }

    /// [`LoadJets`] of a car's four wheels (FL, FR on `front`, RL, RR on
    /// `rear`) at the axles' slip angles `alpha`, the loads `fz` and
    /// friction scale `mu`, no camber: [`Pac89::load_jets`] of those wheels
    /// to the bit, with the inputs handed to the AVX2 kernel (a call of its
    /// own: the caller is not compiled for AVX2) in registers. An array of
    /// slip states handed over in memory, written a field at a time, made
    /// the kernel's wider loads of it wait for the stores to retire (no
    /// store forwarding; profiled: a stall on every right-hand side).
    #[inline]
    pub(crate) fn axle_jets(
        front: &Pac89,
        rear: &Pac89,
        alpha: [f64; 2],
        fz: [f64; 4],
        mu: f64,
    ) -> LoadJets {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            let ([af, ar], [f0, f1, f2, f3]) = (alpha, fz);
            // SAFETY: the CPU has AVX2, checked on the line above.
            return unsafe { axle_jets_avx2(front, rear, af, ar, f0, f1, f2, f3, mu) };
        }
        axle_jets_of(front, rear, alpha, fz, mu)
    }
}

/// [`jets`] compiled with AVX2.
#[cfg(all(test, target_arch = "x86_64"))]
#[target_feature(enable = "avx2")]
fn jets_avx2(tyres: [&Pac89; 4], s: &[SlipState; 4]) -> LoadJets {
    jets(tyres, s)
}

/// [`axle_jets_of`] compiled with AVX2, every number an argument of its own
/// (in a register, not in memory).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[allow(clippy::too_many_arguments)]
fn axle_jets_avx2(
    front: &Pac89,
    rear: &Pac89,
    af: f64,
    ar: f64,
    f0: f64,
    f1: f64,
    f2: f64,
    f3: f64,
    mu: f64,
) -> LoadJets {
    axle_jets_of(front, rear, [af, ar], [f0, f1, f2, f3], mu)
}

/// [`jets`] of the four wheels of [`Pac89::axle_jets`].
#[inline(always)]
fn axle_jets_of(front: &Pac89, rear: &Pac89, alpha: [f64; 2], fz: [f64; 4], mu: f64) -> LoadJets {
    let s: [SlipState; 4] = std::array::from_fn(|i| SlipState {
        alpha: alpha[i / 2],
        kappa: 0.0,
        fz: fz[i],
        camber: 0.0,
        mu_scale: mu,
        speed: 0.0,
    });
    jets([front, front, rear, rear], &s)
}

/// `(u, u', u'')` of `atan` at `x` with `x'`, `x''` (`atan x` given).
#[inline(always)]
fn atan_jet(x: f64, x1: f64, x2: f64) -> (f64, f64) {
    let p = 1.0 / (1.0 + x * x);
    (x1 * p, x2 * p - 2.0 * x * x1 * x1 * p * p)
}

/// Force and derivatives in load, lane by lane (kN inside, N at the
/// interface: `∂/∂Fz = ∂/∂f / 1000`); the derivatives with five divisions a
/// lane, reciprocals taken once.
#[inline(always)]
fn jets(tyres: [&Pac89; 4], s: &[SlipState; 4]) -> LoadJets {
    let st = stages(tyres, s);
    let a = &st.a;
    let c = a[0];
    // sin and cos of C·atan(φ) in one call of twice the lanes.
    let arg: [f64; 4] = each(|i| c[i] * st.outer[i]);
    let sc = kernels::sin_cos::<8>(each(|k| arg[k % 4]), std::array::from_fn(|k| k >= 4));
    let mut out = [[0.0; 4]; 3];
    for i in 0..4 {
        let (sine, cosine) = (sc[i], sc[i + 4]);
        out[0][i] = force(&st, sine, i);
        let (f, mu, d, b, z) = (st.f[i], st.mu[i], st.d[i], st.b[i], st.z[i]);
        let (d1, d2) = (2.0 * a[1][i] * f + a[2][i], 2.0 * a[1][i]);
        // q(z) = 2z/(1 + z²): q' = 2(1 − z²)/(1 + z²)², q'' = 4z(z² − 3)/(1 + z²)³,
        // z = f/a4; one division for both (a division costs a dozen products).
        let w = 1.0 + z * z;
        let r = 1.0 / (w * a[4][i]);
        let q1 = 2.0 * (1.0 - z * z) * r * r * a[4][i];
        let q2 = 4.0 * z * (z * z - 3.0) * r * r * r * a[4][i];
        let k = a[3][i] * st.bcd_camber[i];
        let (bcd1, bcd2) = (k * q1, k * q2);
        // BCD = B·C·D differentiated twice; B is held at zero where C·D vanishes.
        // Selected, not branched (as `stages`' B): the same bits.
        let inv_cd = select(st.small[i], 0.0, 1.0 / st.cd_safe[i]);
        let b1 = (bcd1 - b * c[i] * d1) * inv_cd;
        let b2 = (bcd2 - 2.0 * b1 * c[i] * d1 - b * c[i] * d2) * inv_cd;
        let x = s[i].alpha.to_degrees() + st.sh[i];
        let (sh1, inv_mu) = (a[9][i], 1.0 / mu);
        let bx1 = (b1 * x + b * sh1) * inv_mu;
        let bx2 = (b2 * x + 2.0 * b1 * sh1) * inv_mu;
        let (in1, in2) = atan_jet(st.bx[i], bx1, bx2);
        let (u, u1, u2) = (st.bx[i] - st.inner[i], bx1 - in1, bx2 - in2);
        let (e, e1) = (st.e[i], a[6][i]);
        let phi1 = bx1 - e1 * u - e * u1;
        let phi2 = bx2 - 2.0 * e1 * u1 - e * u2;
        let (o1, o2) = atan_jet(st.phi[i], phi1, phi2);
        let s1 = cosine * c[i] * o1;
        let s2 = cosine * c[i] * o2 - sine * c[i] * c[i] * o1 * o1;
        let sv1 = a[11][i] * st.g[i] + a[12][i];
        // Selected, not skipped: a lane off the ground (at no load and
        // μ = 1 in its stages) is computed and discarded, so every lane is
        // stored whole; a skipped lane made the stores masked, which the
        // caller's loads of them cannot be forwarded from (profiled: a
        // stall on every right-hand side).
        let on = st.on[i];
        out[1][i] = if on {
            mu * (d1 * sine + d * s1 + sv1) * 1e-3
        } else {
            0.0
        };
        out[2][i] = if on {
            mu * (d2 * sine + 2.0 * d1 * s1 + d * s2) * 1e-6
        } else {
            0.0
        };
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tyre::TyreModel;

    /// Against central differences of the one-wheel force (steps of 1 N
    /// and 10 N for the second derivative, whose truncation is then far
    /// below the tolerance) over slip angles through the peak into sliding,
    /// loads from 0.5 to 9 kN, two cambers and three friction scales, each
    /// lane another wheel and the rear another tyre; the values are the
    /// lanes' to the bit, and a wheel off the ground has none.
    #[test]
    fn load_derivatives_are_the_forces_slopes() {
        let front = Pac89::adams_example();
        let mut rear = Pac89::adams_example();
        rear.a[3] *= 1.3;
        rear.a[9] = 0.02;
        rear.a[13] = -8.0;
        let pair = [&front, &front, &rear, &rear];
        let mut n = 0;
        for alpha_deg in [-25.0, -6.0, -1.0, 0.0, 0.3, 2.0, 4.5, 12.0] {
            for fz in [500.0, 1500.0, 3000.0, 4500.0, 6500.0, 9000.0] {
                for (camber, mu) in [(0.0, 1.0), (0.05, 0.7), (-0.03, 1.2)] {
                    let wheel = |k: usize| SlipState {
                        alpha: f64::to_radians(alpha_deg) * (1.0 - 0.2 * k as f64),
                        fz: fz * (1.0 + 0.15 * k as f64),
                        camber,
                        mu_scale: mu,
                        ..SlipState::lateral(0.0, 0.0)
                    };
                    let s: [SlipState; 4] = std::array::from_fn(wheel);
                    let j = Pac89::load_jets(pair, &s);
                    assert_eq!(j[0], Pac89::lateral_forces_lanes(pair, &s));
                    for k in 0..4 {
                        let at = |dz: f64| {
                            pair[k].lateral_force(&SlipState {
                                fz: s[k].fz + dz,
                                ..s[k]
                            })
                        };
                        let d1 = (at(1.0) - at(-1.0)) / 2.0;
                        let d2 = (at(10.0) - 2.0 * at(0.0) + at(-10.0)) / 100.0;
                        let e1 = (j[1][k] - d1).abs();
                        let e2 = (j[2][k] - d2).abs();
                        assert!(
                            e1 <= 1e-6 * (1.0 + d1.abs()),
                            "{:?}: {} vs {d1}",
                            s[k],
                            j[1][k]
                        );
                        assert!(
                            e2 <= 2e-8 + 1e-3 * d2.abs(),
                            "{:?}: {} vs {d2}",
                            s[k],
                            j[2][k]
                        );
                        n += 1;
                    }
                }
            }
        }
        assert_eq!(n, 8 * 6 * 3 * 4);
        let off = [0.01, 0.01, 0.01, 0.01].map(|a| SlipState::lateral(a, -100.0));
        assert_eq!(Pac89::load_jets(pair, &off), [[0.0; 4]; 3]);
    }

    /// The axles' entry (the vehicle's: slip angles, loads and friction in
    /// registers) is the general one's to the bit, with wheels off the
    /// ground and without friction among them (whose selected zeros must
    /// not carry the discarded lanes' arithmetic).
    #[test]
    fn the_axles_jets_are_the_wheels_jets() {
        let front = Pac89::adams_example();
        let mut rear = Pac89::adams_example();
        rear.a[3] *= 1.3;
        rear.a[13] = -8.0;
        let mut n = 0;
        for alpha in [[0.0, 0.0], [0.02, -0.01], [-0.3, 0.25], [1.2, -1.5]] {
            for fz in [
                [3000.0, 4200.0, 2500.0, 3900.0],
                [-20.0, 7000.0, 0.0, 6000.0],
                [1e-9, 12_000.0, 800.0, -1.0],
            ] {
                for mu in [0.0, 0.7, 1.0, 1.2] {
                    let s: [SlipState; 4] = std::array::from_fn(|i| SlipState {
                        fz: fz[i],
                        mu_scale: mu,
                        ..SlipState::lateral(alpha[i / 2], 0.0)
                    });
                    let general = Pac89::load_jets([&front, &front, &rear, &rear], &s);
                    let axles = Pac89::axle_jets(&front, &rear, alpha, fz, mu);
                    for (g, a) in general.iter().flatten().zip(axles.iter().flatten()) {
                        assert_eq!(g.to_bits(), a.to_bits(), "{alpha:?} {fz:?} {mu}");
                    }
                    n += 1;
                }
            }
        }
        assert_eq!(n, 48);
    }
}
