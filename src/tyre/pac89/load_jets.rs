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

use super::lanes::{each, force, stages};
use super::Pac89;
use crate::tyre::{kernels, SlipState, Tyre};

/// Lateral forces of four wheels (N) with their first (N/N) and second
/// (1/N) derivatives in each wheel's own load.
pub(crate) type LoadJets = [[f64; 4]; 3];

impl Tyre {
    /// [`LoadJets`] of a car's four wheels, the first two on this tyre and
    /// the last two on `rear`, at `s`: Some when both are PAC89 (in SIMD
    /// lanes, AVX2 at run time), None for any other model.
    pub(crate) fn lateral_forces_in_load(
        &self,
        rear: &Tyre,
        s: &[SlipState; 4],
    ) -> Option<LoadJets> {
        match (self, rear) {
            (Tyre::Pac89(f), Tyre::Pac89(r)) => Some(Pac89::load_jets([f, f, r, r], s)),
            _ => None,
        }
    }
}

impl Pac89 {
    /// [`LoadJets`] of wheel `i` on `tyres[i]` at `s[i]`.
    pub(crate) fn load_jets(tyres: [&Pac89; 4], s: &[SlipState; 4]) -> LoadJets {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2, checked on the line above.
            return unsafe { jets_avx2(tyres, s) };
        }
        jets(tyres, s)
    }
}

/// [`jets`] compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn jets_avx2(tyres: [&Pac89; 4], s: &[SlipState; 4]) -> LoadJets {
    jets(tyres, s)
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
        if !st.on[i] {
            continue;
        }
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
        let cd = c[i] * d;
        let inv_cd = if cd.abs() < 1e-12 { 0.0 } else { 1.0 / cd };
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
        out[1][i] = mu * (d1 * sine + d * s1 + sv1) * 1e-3;
        out[2][i] = mu * (d2 * sine + 2.0 * d1 * s1 + d * s2) * 1e-6;
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
}
