//! `atan`, `sin` and `cos` over small arrays of independent arguments, for
//! the tyre models' hot paths: the slip part of one Magic Formula
//! evaluation needs about thirty of them, most independent of each other
//! (the curves of `Fx0`, `Fy0`, `Gxα`, `Gyκ`, …), and a vehicle's four
//! PAC89 wheels three each, independent across the wheels; the C library
//! evaluates them one call at a time. Written branch-free over arrays, they
//! compile to SIMD lanes (SSE2, the x86-64 baseline: two per instruction;
//! four where a caller is compiled for AVX2) and their polynomials are
//! evaluated by Estrin's scheme, so the chain of dependent stages of one
//! evaluation is shorter as well.
//!
//! Accuracy: within 1 ulp of the C library's (glibc, itself within 1 ulp
//! of the exact value) over the ranges tested in `mf/tests.rs` — relative error
//! below 3e-16, far inside the 1e-13 the model's agreement with MFeval
//! allows. Pure functions of their arguments: the same inputs give the same
//! bits whatever the lane, so a ratio of two equal curves is exactly 1.
//!
//! Method (standard; the coefficients are this crate's own Chebyshev
//! interpolants, computed in 60-digit arithmetic):
//! - `atan`: the argument is reduced to `|t| ≤ tan(π/8)` with
//!   `atan a = π/4 + atan((a − 1)/(a + 1))` or `π/2 + atan(−1/a)` (one
//!   division for every branch, selected by masks), then
//!   `atan t = t + t³·P(t²)`, `P` of degree 10.
//! - `sin`/`cos`: `x = q·π/2 + r`, `|r| ≤ π/4`, with `q` rounded by the
//!   1.5·2⁵² shift and `π/2` in three parts (Cody and Waite 1980), so `r`
//!   is exact to 1e-37 for `|x| ≤ 1e5`; `sin r = r + r³·S(r²)`,
//!   `cos r = 1 − r²/2 + r⁴·K(r²)` (the `1 − r²/2` compensated), `S`, `K`
//!   of degree 5; the quadrant of `q` (plus one for the cosine) picks and
//!   signs the result. Arguments beyond 1e5 or not finite go to the C
//!   library.

use std::f64::consts::{FRAC_2_PI, FRAC_PI_2, FRAC_PI_4};

/// `P(s)` of `atan t = t + t³·P(t²)` on `s ∈ [0, tan²(π/8)]`.
const ATAN: [f64; 11] = [
    -0.3333333333333333,
    0.1999999999999552,
    -0.14285714284666542,
    0.11111111015256361,
    -0.09090904578123903,
    0.07692183190826087,
    -0.06664511447381948,
    0.0585814891280221,
    -0.0508544973794026,
    0.03923165829558719,
    -0.01917688711906226,
];
/// `S(s)` of `sin r = r + r³·S(r²)` on `s ∈ [0, (π/4)²]`.
const SIN: [f64; 6] = [
    -0.16666666666666666,
    0.008333333333330948,
    -0.00019841269836758574,
    2.755731610255244e-06,
    -2.5051131845003624e-08,
    1.5918129294866608e-10,
];
/// `K(s)` of `cos r = 1 − r²/2 + r⁴·K(r²)` on `s ∈ [0, (π/4)²]`.
const COS: [f64; 6] = [
    0.041666666666666664,
    -0.0013888888888887398,
    2.480158729876569e-05,
    -2.7557317271729793e-07,
    2.08761462684032e-09,
    -1.1382632425521717e-11,
];
const TAN_PI_8: f64 = 0.41421356237309503;
const TAN_3PI_8: f64 = 2.414213562373095;
/// π/2 and π/4 as a double and the remainder.
const PI_2: (f64, f64) = (FRAC_PI_2, 6.123233995736766e-17);
const PI_4: (f64, f64) = (FRAC_PI_4, 3.061616997868383e-17);
/// π/2 in three parts, the first two of 33 bits: `q·part` is exact for
/// `|q| < 2²⁰`.
const PI_2_CW: [f64; 3] = [
    1.5707963267341256,
    6.077100506303966e-11,
    2.0222662487959506e-21,
];
/// Adding 1.5·2⁵² rounds to an integer, held in the low mantissa bits.
const SHIFT: f64 = 6755399441055744.0;
/// Largest `|x|` reduced here (the three-part reduction is exact below).
const TRIG_MAX: f64 = 1e5;

/// `x` where the mask `m` is all ones, `y` where it is zero.
#[inline(always)]
pub(crate) fn blend(m: u64, x: f64, y: f64) -> f64 {
    f64::from_bits((x.to_bits() & m) | (y.to_bits() & !m))
}

#[inline(always)]
pub(crate) fn mask(b: bool) -> u64 {
    0u64.wrapping_sub(b as u64)
}

/// `atan(n/d)` lane by lane for `d > 0` (`d = 1`: `atan n`, to the bit).
#[inline(always)]
pub(super) fn atan_ratio<const N: usize>(n: [f64; N], d: [f64; N]) -> [f64; N] {
    atan_ratio_lanes(n, d)
}

/// `atan x` lane by lane (as [`atan_ratio`]).
#[inline(always)]
pub(super) fn atan<const N: usize>(x: [f64; N]) -> [f64; N] {
    atan_ratio(x, [1.0; N])
}

/// `sin x` where `cos[i]` is false, `cos x` where it is true.
#[inline(always)]
pub(super) fn sin_cos<const N: usize>(x: [f64; N], cos: [bool; N]) -> [f64; N] {
    // Outside the reduction's range (never in the model's use): the C
    // library's, out of line so that the hot path has no call.
    if x.iter().any(|v| v.is_nan() || v.abs() > TRIG_MAX) {
        return sin_cos_libm(x, cos);
    }
    sin_cos_lanes(x, cos)
}

// Inlined into an evaluation rather than called: passing the lanes through
// memory to an out-of-line kernel (scalar stores, vector loads) stalls on
// store forwarding, and was measured slower despite 6 % fewer instructions.
#[inline(always)]
fn atan_ratio_lanes<const N: usize>(n: [f64; N], d: [f64; N]) -> [f64; N] {
    let mut o = [0.0; N];
    for i in 0..N {
        let (x, den) = (n[i], d[i]);
        let a = x.abs();
        let big = mask(a > TAN_3PI_8 * den);
        let mid = mask(a > TAN_PI_8 * den);
        let num = blend(big, -den, blend(mid, a - den, a));
        let den = blend(big, a, blend(mid, a + den, den));
        let hi = blend(big, PI_2.0, blend(mid, PI_4.0, 0.0));
        let lo = blend(big, PI_2.1, blend(mid, PI_4.1, 0.0));
        let t = num / den;
        let s = t * t;
        // Estrin's scheme: a shorter dependency chain than Horner's.
        let s2 = s * s;
        let s4 = s2 * s2;
        let s8 = s4 * s4;
        let q0 = ATAN[0] + ATAN[1] * s;
        let q1 = ATAN[2] + ATAN[3] * s;
        let q2 = ATAN[4] + ATAN[5] * s;
        let q3 = ATAN[6] + ATAN[7] * s;
        let q4 = ATAN[8] + ATAN[9] * s;
        let r0 = q0 + q1 * s2;
        let r1 = q2 + q3 * s2;
        let r2 = q4 + ATAN[10] * s2;
        let p = (r0 + r1 * s4) + r2 * s8;
        let r = hi + (t + (t * s * p + lo));
        o[i] = f64::from_bits(r.to_bits() | (x.to_bits() & (1 << 63)));
    }
    o
}

#[inline(always)]
fn sin_cos_lanes<const N: usize>(x: [f64; N], cos: [bool; N]) -> [f64; N] {
    let mut o = [0.0; N];
    for i in 0..N {
        let xi = x[i];
        let k = xi * FRAC_2_PI + SHIFT;
        // The quadrant in the low bits (two's complement modulo 4), one on
        // for the cosine: cos x = sin(x + π/2).
        let q = k.to_bits().wrapping_add(cos[i] as u64);
        let qf = k - SHIFT;
        let r = ((xi - qf * PI_2_CW[0]) - qf * PI_2_CW[1]) - qf * PI_2_CW[2];
        let s = r * r;
        let s2 = s * s;
        let ps =
            (SIN[0] + SIN[1] * s) + (SIN[2] + SIN[3] * s) * s2 + (SIN[4] + SIN[5] * s) * (s2 * s2);
        let pc =
            (COS[0] + COS[1] * s) + (COS[2] + COS[3] * s) * s2 + (COS[4] + COS[5] * s) * (s2 * s2);
        let sn = r + r * s * ps;
        // 1 − s/2 with its rounding error carried (as fdlibm's __kernel_cos).
        let hz = 0.5 * s;
        let w = 1.0 - hz;
        let cs = w + (((1.0 - w) - hz) + s2 * pc);
        let v = blend(mask(q & 1 == 1), cs, sn);
        o[i] = f64::from_bits(v.to_bits() ^ ((q & 2) << 62));
    }
    o
}

#[cold]
#[inline(never)]
fn sin_cos_libm<const N: usize>(x: [f64; N], cos: [bool; N]) -> [f64; N] {
    std::array::from_fn(|i| if cos[i] { x[i].cos() } else { x[i].sin() })
}
