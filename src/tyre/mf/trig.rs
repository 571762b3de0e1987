//! `atan`, `sin` and `cos` for the Magic Formula's inner loop, to double
//! precision without the C library's rounding-mode switches.
//!
//! Why: one combined-slip evaluation makes about 25 `atan`, 8 `sin` and 6
//! `cos` calls, and glibc's versions (2.36, `__atan_fma`, `__sin_fma`) set
//! and restore the SSE rounding mode (`ldmxcsr`) on every call, which
//! stalls the floating-point pipeline; under callgrind they are three
//! quarters of the evaluation's instructions. These are the Cephes
//! algorithms (S. L. Moshier, *Methods and Programs for Mathematical
//! Functions*, 1989; Cephes Math Library 2.8, `atan.c`, `sin.c`): `atan`
//! reduces to `|x| ≤ 0.66` by `atan x = π/4 + atan((x−1)/(x+1))` or
//! `π/2 − atan(1/x)` and evaluates a (4,5) rational function; `sin` and
//! `cos` reduce by multiples of π/4 (three-part Cody–Waite constants) and
//! evaluate degree-6 polynomials. Cephes quotes a relative error below
//! 2.2e-16 (`atan`, IEEE, ±10) and 2.2e-16 (`sin`/`cos`, ±2³⁰). The unit
//! tests below check them against the standard library to 1e-15 relative
//! (absolute near the zeros of `sin`/`cos`). Arguments beyond ±2²⁰ (never
//! reached by the formulae's bounded angles) and non-finite ones go to the
//! standard library.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

const ATAN_P: [f64; 5] = [
    -8.750_608_600_031_904e-1,
    -1.615_753_718_733_365e1,
    -7.500_855_792_314_705e1,
    -1.228_866_684_490_136_2e2,
    -6.485_021_904_942_025e1,
];
const ATAN_Q: [f64; 5] = [
    2.485_846_490_142_306_3e1,
    1.650_270_098_316_988_6e2,
    4.328_810_604_912_903e2,
    4.853_903_996_359_137e2,
    1.945_506_571_482_614e2,
];
/// tan(3π/8).
const T3P8: f64 = 2.414_213_562_373_095;
/// The low part of π/2 (π/2 − FRAC_PI_2).
const MOREBITS: f64 = 6.123_233_995_736_766e-17;

/// Arc tangent, |error| ≤ 2.2e-16 relative.
#[inline]
pub fn atan(x: f64) -> f64 {
    let a = x.abs();
    if !a.is_finite() {
        return x.atan();
    }
    let (base, r, low) = if a > T3P8 {
        (FRAC_PI_2, -1.0 / a, MOREBITS)
    } else if a <= 0.66 {
        (0.0, a, 0.0)
    } else {
        (FRAC_PI_4, (a - 1.0) / (a + 1.0), 0.5 * MOREBITS)
    };
    let z = r * r;
    let p = (((ATAN_P[0] * z + ATAN_P[1]) * z + ATAN_P[2]) * z + ATAN_P[3]) * z + ATAN_P[4];
    let q = ((((z + ATAN_Q[0]) * z + ATAN_Q[1]) * z + ATAN_Q[2]) * z + ATAN_Q[3]) * z + ATAN_Q[4];
    let y = base + (r * (z * p / q) + r + low);
    if x.is_sign_negative() {
        -y
    } else {
        y
    }
}

/// The functions above as methods, so the formulae read as before.
pub(super) trait Trig {
    fn fatan(self) -> f64;
    fn fsin(self) -> f64;
    fn fcos(self) -> f64;
}

impl Trig for f64 {
    #[inline]
    fn fatan(self) -> f64 {
        atan(self)
    }
    #[inline]
    fn fsin(self) -> f64 {
        sin(self)
    }
    #[inline]
    fn fcos(self) -> f64 {
        cos(self)
    }
}

const SIN_C: [f64; 6] = [
    1.589_623_015_765_465_7e-10,
    -2.505_074_776_285_780_7e-8,
    2.755_731_362_138_572_5e-6,
    -1.984_126_982_958_954e-4,
    8.333_333_333_322_118e-3,
    -1.666_666_666_666_663e-1,
];
const COS_C: [f64; 6] = [
    -1.135_853_652_138_768_2e-11,
    2.087_570_084_197_473e-9,
    -2.755_731_417_929_674e-7,
    2.480_158_728_885_170_5e-5,
    -1.388_888_888_887_305_6e-3,
    4.166_666_666_666_659e-2,
];
const DP1: f64 = 7.853_981_256_484_985e-1;
const DP2: f64 = 3.774_894_707_930_798e-8;
const DP3: f64 = 2.695_151_429_079_059_5e-15;
/// Beyond this the reduction loses digits; the standard library takes over.
const LIMIT: f64 = 1_048_576.0;

#[inline]
fn poly(z: f64, c: &[f64; 6]) -> f64 {
    ((((c[0] * z + c[1]) * z + c[2]) * z + c[3]) * z + c[4]) * z + c[5]
}

/// `|x|` reduced to `[−π/4, π/4]`: the octant `j` (0..=3, even) and the
/// remainder, the sign flipped when `j` was above 3.
#[inline]
fn reduce(a: f64) -> (u32, f64, bool) {
    // `a` is below LIMIT and not negative: truncation is the floor, and a
    // conversion, where `floor` would be a library call without SSE4.1.
    let mut j = (a / FRAC_PI_4) as u64;
    let mut y = j as f64;
    if j & 1 == 1 {
        j += 1;
        y += 1.0;
    }
    let mut j = (j & 7) as u32;
    let flip = j > 3;
    if flip {
        j -= 4;
    }
    (j, ((a - y * DP1) - y * DP2) - y * DP3, flip)
}

#[inline]
fn sin_poly(z: f64) -> f64 {
    let zz = z * z;
    z + z * zz * poly(zz, &SIN_C)
}

#[inline]
fn cos_poly(z: f64) -> f64 {
    let zz = z * z;
    1.0 - 0.5 * zz + zz * zz * poly(zz, &COS_C)
}

/// Sine, |error| ≤ 2.2e-16 relative (absolute near its zeros).
#[inline]
pub fn sin(x: f64) -> f64 {
    let a = x.abs();
    if a.is_nan() || a >= LIMIT {
        return x.sin();
    }
    let (j, z, flip) = reduce(a);
    let r = if j == 2 { cos_poly(z) } else { sin_poly(z) };
    if flip != (x < 0.0) {
        -r
    } else {
        r
    }
}

/// Cosine, |error| ≤ 2.2e-16 relative (absolute near its zeros).
#[inline]
pub fn cos(x: f64) -> f64 {
    let a = x.abs();
    if a.is_nan() || a >= LIMIT {
        return x.cos();
    }
    let (j, z, flip) = reduce(a);
    let r = if j == 2 { sin_poly(z) } else { cos_poly(z) };
    if flip != (j > 1) {
        -r
    } else {
        r
    }
}

#[cfg(test)]
mod tests {
    /// Relative error, absolute where the value is below 1 (the zeros of
    /// `sin` and `cos` have no relative accuracy to speak of).
    fn err(a: f64, b: f64) -> f64 {
        (a - b).abs() / a.abs().max(1.0)
    }

    #[test]
    fn atan_agrees_with_the_standard_library() {
        let mut worst: f64 = 0.0;
        for i in -200_000..=200_000 {
            let t = i as f64 * 1e-5;
            // Dense near 0, out to ±8e15 through the cube.
            for x in [t, t * t * t * 1e3, 1.0 / (t + 1e-9)] {
                let (a, b) = (x.atan(), super::atan(x));
                worst = worst.max((a - b).abs() / a.abs().max(f64::MIN_POSITIVE));
            }
        }
        assert!(worst < 1e-15, "atan: worst relative error {worst:e}");
        assert!(super::atan(f64::INFINITY) == std::f64::consts::FRAC_PI_2);
        assert!(super::atan(f64::NAN).is_nan());
        assert_eq!(super::atan(-0.0).to_bits(), (-0.0f64).to_bits());
    }

    #[test]
    fn sin_and_cos_agree_with_the_standard_library() {
        let mut worst: f64 = 0.0;
        for i in -400_000..=400_000 {
            let x = i as f64 * 2.5e-4 * (1.0 + (i % 7) as f64 * 0.013);
            worst = worst.max(err(x.sin(), super::sin(x)));
            worst = worst.max(err(x.cos(), super::cos(x)));
        }
        assert!(worst < 1e-15, "sin/cos: worst error {worst:e}");
        for x in [1e-300, -1e-8, 3e6, f64::NAN, f64::INFINITY] {
            let (s, c) = (super::sin(x), super::cos(x));
            assert!(
                s.to_bits() == x.sin().to_bits() || err(x.sin(), s) < 1e-15,
                "{x}"
            );
            assert!(
                c.to_bits() == x.cos().to_bits() || err(x.cos(), c) < 1e-15,
                "{x}"
            );
        }
    }
}
