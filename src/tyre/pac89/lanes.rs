//! PAC89's lateral force of several wheels at once, for the vehicle's
//! right-hand side: a car's four wheels ([`super::TyreModel::lateral_forces`])
//! in four lanes, each lane its own tyre's coefficients, load, slip angle,
//! camber and friction scale. The arithmetic is that of the one-wheel
//! [`super::TyreModel::lateral_force`] (the parent module's equations,
//! Bakker, Nyborg & Pacejka 1989, in the Adams numbering; kN and degrees
//! inside, N and rad at the interface) with its three `atan`, `atan`, `sin`
//! taken from the crate's branch-free array kernels ([`crate::tyre::kernels`])
//! instead of the C library: one call per stage for the four wheels, which
//! the compiler turns into SIMD lanes, and `B·x/μ` in one division where
//! the one-wheel method takes three (the divisions of the load's chain are
//! what a right-hand side waits on). The kernels are within 1 ulp of the C
//! library's, so a wheel's force is within a few ulp of the one-wheel method's
//! (tested below over slip, load, camber and friction); a lane's result
//! depends on its own inputs only, whatever the other lanes hold.

use super::Pac89;
use crate::tyre::kernels;
use crate::tyre::SlipState;

impl Pac89 {
    /// The lateral forces (N) of four wheels, wheel `i` on `tyres[i]` at
    /// `s[i]`; compiled for AVX2 (four lanes per instruction instead of
    /// SSE2's two) when the CPU has it. No FMA either way (Rust does not
    /// contract `a·b + c`): the same bits on both paths.
    pub(crate) fn lateral_forces_lanes(tyres: [&Pac89; 4], s: &[SlipState; 4]) -> [f64; 4] {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2, checked on the line above.
            return unsafe { lanes_avx2(tyres, s) };
        }
        lanes(tyres, s)
    }
}

/// [`lanes`] compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn lanes_avx2(tyres: [&Pac89; 4], s: &[SlipState; 4]) -> [f64; 4] {
    lanes(tyres, s)
}

/// An array of `N` lanes, lane `i` the value of `f(i)`.
#[inline(always)]
pub(super) fn each<const N: usize>(f: impl FnMut(usize) -> f64) -> [f64; N] {
    std::array::from_fn(f)
}

/// What a lane's lateral force is made of, up to the outer `atan`: the
/// coefficients (`a[k][i]`, coefficient k of lane i), the lane's load in kN
/// (`f`), friction scale, camber in degrees, the curve's D, B, E, Sh, Sv,
/// `B·x/μ` and the two arctangents. Shared by [`lanes`] and the load
/// derivatives (`load_jets.rs`), so both hold the same values to the bit.
pub(super) struct Stages<const N: usize> {
    pub(super) a: [[f64; N]; 14],
    pub(super) on: [bool; N],
    /// Where C·D vanishes (B is zero there).
    pub(super) small: [bool; N],
    /// C·D where it does not vanish, 1 where it does: a divisor that never
    /// is zero, its quotient discarded there.
    pub(super) cd_safe: [f64; N],
    pub(super) f: [f64; N],
    pub(super) mu: [f64; N],
    pub(super) g: [f64; N],
    pub(super) d: [f64; N],
    pub(super) z: [f64; N],
    pub(super) bcd_camber: [f64; N],
    pub(super) b: [f64; N],
    pub(super) e: [f64; N],
    pub(super) sh: [f64; N],
    pub(super) sv: [f64; N],
    pub(super) bx: [f64; N],
    pub(super) inner: [f64; N],
    pub(super) phi: [f64; N],
    pub(super) outer: [f64; N],
}

/// The lanes' [`Stages`]: the one-wheel method's equations
/// (`lateral_curve_of` and `Pac89::scaled`), its operations but for `z`
/// (taken from the load in N) and `B·x/μ` (one division where it takes
/// three), so the lanes differ from it by the kernels' last bits and a few
/// ulp of `B·x`; `x/1` and `x·1` are `x` to the bit, so μ = 1 needs no
/// branch of its own. Written as whole-array steps without
/// branches (a load-less lane selects, it does not jump), so the compiler
/// keeps the lanes in vector registers from the coefficients on.
#[inline(always)]
pub(super) fn stages<const N: usize>(tyres: [&Pac89; N], s: &[SlipState; N]) -> Stages<N> {
    let a: [[f64; N]; 14] = std::array::from_fn(|k| std::array::from_fn(|i| tyres[i].a[k]));
    let on: [bool; N] =
        std::array::from_fn(|i| (s[i].fz > 0.0 || s[i].fz.is_nan()) && s[i].mu_scale > 0.0);
    // A lane that gives zero is evaluated at no load and μ = 1 (its value
    // is discarded), so no NaN sends the whole array to the kernels'
    // out-of-range path.
    let f: [f64; N] = each(|i| load(s, on, i) / 1000.0);
    let mu: [f64; N] = each(|i| if on[i] { s[i].mu_scale } else { 1.0 });
    let g: [f64; N] = each(|i| s[i].camber.to_degrees());
    let c = a[0];
    let d: [f64; N] = each(|i| a[1][i] * f[i] * f[i] + a[2][i] * f[i]);
    // z = f/a4 from the load in N directly: beside `f`, not after it.
    let z: [f64; N] = each(|i| load(s, on, i) / (a[4][i] * 1000.0));
    let bcd_camber: [f64; N] = each(|i| -(a[5][i] * g[i].abs()) + 1.0);
    let w: [f64; N] = each(|i| z[i] * z[i] + 1.0);
    let cd: [f64; N] = each(|i| c[i] * d[i]);
    // Where C·D vanishes B is zero (`stiffness_factor`). The divisions
    // below are by `cd_safe`, C·D where it does not vanish and 1 where it
    // does (a quotient then discarded), and the zero is selected by a bit
    // mask: with a branch per lane the compiler took the divisions out of
    // the vector lanes, twelve scalar divisions each behind a branch
    // (profiled, session 113). The same quotients, so the same bits.
    let small: [bool; N] = std::array::from_fn(|i| cd[i].abs() < 1e-12);
    let cd_safe: [f64; N] = each(|i| select(small[i], 1.0, cd[i]));
    // B = BCD/(C·D): read by the load derivatives only.
    let b: [f64; N] = each(|i| {
        let bcd = a[3][i] * (z[i] * 2.0 / w[i]) * bcd_camber[i];
        select(small[i], 0.0, bcd / cd_safe[i])
    });
    let e: [f64; N] = each(|i| a[6][i] * f[i] + a[7][i]);
    let sh: [f64; N] = each(|i| a[8][i] * g[i] + a[9][i] * f[i] + a[10][i]);
    let sv: [f64; N] = each(|i| a[11][i] * f[i] * g[i] + a[12][i] * f[i] + a[13][i]);
    // B/μ = a3·2z·(1 − a5·|γ|) / ((1 + z²)·C·D·μ) in one division where
    // the one-wheel method takes three (BCD's q(z), B, B/μ): the load's
    // chain of dependent divisions to B·x is what a right-hand side waits
    // on (profiled); a few ulp of B·x apart from the one-wheel method's.
    let bx: [f64; N] = each(|i| {
        let num = a[3][i] * (z[i] * 2.0) * bcd_camber[i];
        let b_mu = select(small[i], 0.0, num / (w[i] * cd_safe[i] * mu[i]));
        b_mu * (s[i].alpha.to_degrees() + sh[i])
    });
    let inner = kernels::atan(bx);
    let phi: [f64; N] = each(|i| bx[i] - e[i] * (bx[i] - inner[i]));
    let outer = kernels::atan(phi);
    Stages {
        a,
        on,
        small,
        cd_safe,
        f,
        mu,
        g,
        d,
        z,
        bcd_camber,
        b,
        e,
        sh,
        sv,
        bx,
        inner,
        phi,
        outer,
    }
}

/// `x` where `m`, `y` elsewhere, by a bit mask, not a branch (so that a
/// lane's choice keeps the arithmetic around it in vector lanes).
#[inline(always)]
pub(super) fn select(m: bool, x: f64, y: f64) -> f64 {
    kernels::blend(kernels::mask(m), x, y)
}

/// Lane `i`'s load in N, zero where it gives no force (`on[i]` false).
#[inline(always)]
fn load<const N: usize>(s: &[SlipState; N], on: [bool; N], i: usize) -> f64 {
    if on[i] {
        s[i].fz
    } else {
        0.0
    }
}

/// The lateral force of each lane: `Y = D·sin(C·atan(B·x − E·(B·x −
/// atan(B·x)))) + Sv` with the curve at the lane's load and camber and the
/// road's friction scale on D, B and Sv, zero off the ground (`Fz ≤ 0`) or
/// without friction (`μ ≤ 0`), from its [`Stages`].
#[inline(always)]
fn lanes<const N: usize>(tyres: [&Pac89; N], s: &[SlipState; N]) -> [f64; N] {
    let st = stages(tyres, s);
    let c = st.a[0];
    let sine = kernels::sin_cos(each(|i| c[i] * st.outer[i]), [false; N]);
    each(|i| force(&st, sine[i], i))
}

/// Lane `i`'s force of its [`Stages`] `st` and `sin(C·atan(…))` `sine`.
#[inline(always)]
pub(super) fn force<const N: usize>(st: &Stages<N>, sine: f64, i: usize) -> f64 {
    if st.on[i] {
        st.d[i] * st.mu[i] * sine + st.sv[i] * st.mu[i]
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tyre::pac89::lateral_curve_of;
    use crate::tyre::{Tyre, TyreModel};

    /// Distance in units in the last place between two finite numbers of
    /// one sign (or both zero).
    fn ulps(a: f64, b: f64) -> u64 {
        if a == b {
            return 0;
        }
        assert_eq!(a.is_sign_negative(), b.is_sign_negative(), "{a} vs {b}");
        a.to_bits().abs_diff(b.to_bits())
    }

    /// The set evaluation against the one-wheel method over slip angles
    /// from −90° to 90° (zero, the peak and deep sliding), loads from off
    /// the ground through zero to 12 kN, two cambers, four friction scales
    /// (none, less, the file's, more), each lane a different wheel and the
    /// rear on another tyre: within 4 ulp of the curve's size `(|D| +
    /// |Sv|)·μ`. Not of the force itself: `sin` near its zero and the sum
    /// `D·sin(…) + Sv` near a zero crossing amplify the kernels' last bit
    /// (measured: at most 6 ulp of the force away from its zeros).
    #[test]
    fn the_four_wheel_evaluation_is_the_one_wheel_one() {
        let front = Pac89::adams_example();
        let mut rear = Pac89::adams_example();
        rear.a[3] *= 1.3;
        rear.a[10] = -0.004;
        rear.a[13] = -8.0;
        let pair = [&front, &front, &rear, &rear];
        let (mut worst, mut worst_of_force, mut n) = (0.0_f64, 0, 0);
        let alphas = (-180..=180).map(|i| (0.5 * f64::from(i)).to_radians());
        for alpha in alphas {
            for fz in [-50.0, 0.0, 1e-9, 120.0, 2500.0, 4000.0, 6100.0, 12_000.0] {
                for camber in [0.0, 3f64.to_radians()] {
                    for mu in [0.0, 0.6, 1.0, 1.15] {
                        let wheel = |k: usize| SlipState {
                            alpha: alpha * (1.0 - 0.3 * k as f64),
                            fz: fz * (1.0 + 0.1 * k as f64),
                            camber,
                            mu_scale: mu,
                            ..SlipState::lateral(0.0, 0.0)
                        };
                        let s = [wheel(0), wheel(1), wheel(2), wheel(3)];
                        let set = Pac89::lateral_forces_lanes(pair, &s);
                        let lanes_sse2 = lanes(pair, &s);
                        for k in 0..4 {
                            assert_eq!(set[k].to_bits(), lanes_sse2[k].to_bits(), "{:?}", s[k]);
                            let one = pair[k].lateral_force(&s[k]);
                            if s[k].fz <= 0.0 || mu <= 0.0 {
                                assert_eq!(set[k].to_bits(), 0f64.to_bits(), "{:?}", s[k]);
                                assert_eq!(one, 0.0);
                                continue;
                            }
                            let (fz, camber) = (s[k].fz / 1000.0, s[k].camber.to_degrees());
                            let curve = lateral_curve_of(&pair[k].a, fz, camber);
                            let size = (curve.d.abs() + curve.sv.abs()) * mu;
                            let d = (set[k] - one).abs() / (size * f64::EPSILON);
                            assert!(d <= 4.0, "{d} ulp: {} vs {one} at {:?}", set[k], s[k]);
                            worst = worst.max(d);
                            if one.abs() > 0.1 * size {
                                worst_of_force = worst_of_force.max(ulps(set[k], one));
                            }
                            n += 1;
                        }
                    }
                }
            }
        }
        assert!(n > 15_000, "{n} wheels compared");
        eprintln!(
            "worst {worst:.2} ulp of the curve's size, {worst_of_force} of the force, {n} wheels"
        );
    }

    /// Through the tyre: one call of two PAC89 tyres is the lanes'; a pair
    /// of different models is a one-wheel call each, to the bit.
    #[test]
    fn a_tyre_pair_dispatches_the_set_or_each_wheel() {
        let (front, rear) = (Pac89::adams_example(), Pac89::adams_example());
        let s = [0.02, -0.05, 0.1, 0.0].map(|a| SlipState::lateral(a, 3500.0));
        let pac = Tyre::Pac89(front.clone());
        let set = pac.lateral_forces(&Tyre::Pac89(rear.clone()), &s);
        assert_eq!(
            set,
            Pac89::lateral_forces_lanes([&front, &front, &rear, &rear], &s)
        );
        let other = Tyre::Linear(crate::tyre::Linear::new(60_000.0));
        let mixed = pac.lateral_forces(&other, &s);
        for k in 0..4 {
            let t = if k < 2 { &pac } else { &other };
            assert_eq!(mixed[k].to_bits(), t.lateral_force(&s[k]).to_bits());
        }
    }
}
