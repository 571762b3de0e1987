//! Whether a fitted Magic Formula's curvatures stay at or below 1 over the
//! data it was fitted to. The fit bounds `PEY1` and `PEX1` by 1, but the
//! curvature is a combination — `Ey = (PEY1 + PEY2·dfz)·(1 + PEY5·γ*² −
//! (PEY3 + PEY4·γ*)·sgn αy)·LEY`, `Ex = (PEX1 + PEX2·dfz + PEX3·dfz²)·(1 −
//! PEX4·sgn κ)·LEX` — and can exceed 1 at a load or camber of the data
//! while each coefficient lies within its bound. The formula with its
//! limit checks on (MFeval's `useLimitsCheck`, `tyre-eval`'s default mode
//! 121) clips it at 1 and reproduces the fit; without them (mode 221) the
//! force departs from the data. The excess is said, not hidden.
//!
//! PAC89 (Adams numbering, `E = a6·Fz + a7`, Fz in kN) has no limit check:
//! above 1 its lateral force falls past the peak and changes sign at a
//! slip angle where `φ = B·x·(1 − E) + E·atan(B·x)` returns to zero — the
//! Hoosier file's fit reaches E 1.24 and reverses near 40°, outside the
//! data's 9.7° but inside a simulation's reach. The angle is said.

use super::ranges::Span;
use crate::format::readable;
use crate::identify::mf_staged::Stage;
use crate::tyre::mf::{MagicFormula, TyreSide};
use crate::tyre::pac89::magic_formula;
use crate::tyre::Pac89;
use serde::Serialize;

/// Which of the Magic Formula's curvature factors: the file's names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Curvature {
    /// `Ey`, of the pure lateral force, over the slip angle.
    Ey,
    /// `Ex`, of the pure longitudinal force, over the slip ratio.
    Ex,
}

impl Curvature {
    /// Its name in the file and the literature.
    pub fn name(self) -> &'static str {
        match self {
            Curvature::Ey => "Ey",
            Curvature::Ex => "Ex",
        }
    }

    /// The slip it curves the force over, in words.
    fn slip(self) -> &'static str {
        match self {
            Curvature::Ey => "slip angle",
            Curvature::Ex => "slip ratio",
        }
    }
}

/// Where a curvature of the fitted tyre is largest above 1 within the
/// fitted ranges.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurvatureExcess {
    /// Which curvature.
    pub curvature: Curvature,
    /// Its largest value over the fitted ranges.
    pub largest: f64,
    /// The load there (N).
    pub fz: f64,
    /// The camber there (rad, the crate's convention).
    pub camber: f64,
    /// The sign of the slip there (+1 or −1, the file's frame).
    pub slip_sign: f64,
}

impl CurvatureExcess {
    /// The warning, one line.
    pub fn line(&self) -> String {
        format!(
            "curvature {} reaches {} above 1 over the fitted data (at fz {} N, camber {}°, {} {}): the file relies on a limit check clipping E at 1 (MFeval's useLimitsCheck; tyre-eval's mode 121, the default); with the checks off (mode 221) its force departs from the fit",
            self.curvature.name(),
            readable(self.largest, 3),
            readable(self.fz, 4),
            readable(self.camber.to_degrees(), 3),
            if self.slip_sign > 0.0 { "positive" } else { "negative" },
            self.curvature.slip(),
        )
    }
}

fn span<'a>(spans: &'a [Span], name: &str) -> Option<&'a Span> {
    spans.iter().find(|s| s.name == name)
}

/// Points of a span: its ends and 24 steps between (its one value when it
/// is one).
fn points(s: Option<&Span>, none: f64) -> Vec<f64> {
    match s {
        None => vec![none],
        Some(s) if s.lo >= s.hi => vec![s.lo],
        Some(s) => (0..=24)
            .map(|k| s.lo + (s.hi - s.lo) * k as f64 / 24.0)
            .collect(),
    }
}

/// The curvatures of `t` above 1 over `spans`, the fitted stages' (`Ey`
/// where the pure lateral stage was fitted, `Ex` where the longitudinal).
pub(crate) fn curvature_excess(
    t: &MagicFormula,
    spans: &[Span],
    fitted: &[Stage],
) -> Vec<CurvatureExcess> {
    let c = &t.coefficients;
    let fz0 = c.FNOMIN * c.LFZO;
    let loads = points(span(spans, "fz"), c.FNOMIN);
    let cambers = points(span(spans, "camber"), 0.0);
    // The slip signs the data reach, in the file's frame (a left tyre's
    // slip angle is the crate's negated).
    let signs = |name: &str, flip: f64| -> Vec<f64> {
        let s = span(spans, name);
        [1.0, -1.0]
            .into_iter()
            .filter(|&g| s.is_some_and(|s| (flip * s.lo * g).max(flip * s.hi * g) > 0.0))
            .collect()
    };
    let alpha_flip = if t.side == TyreSide::Left { -1.0 } else { 1.0 };
    let camber_flip = if t.side == TyreSide::Right { -1.0 } else { 1.0 };
    let mut out = Vec::new();
    let mut worst = |name: Curvature, e: &dyn Fn(f64, f64, f64) -> f64, slips: Vec<f64>| {
        let mut best: Option<CurvatureExcess> = None;
        for &fz in &loads {
            for &g in &cambers {
                for &s in &slips {
                    let v = e((fz - fz0) / fz0, (camber_flip * g).sin(), s);
                    if v > 1.0 + 1e-9 && best.as_ref().is_none_or(|b| v > b.largest) {
                        best = Some(CurvatureExcess {
                            curvature: name,
                            largest: v,
                            fz,
                            camber: g,
                            slip_sign: s,
                        });
                    }
                }
            }
        }
        out.extend(best);
    };
    if fitted.contains(&Stage::PureFy) {
        worst(
            Curvature::Ey,
            &|dfz, gs, s| {
                (c.PEY1 + c.PEY2 * dfz)
                    * c.LEY
                    * (1.0 + c.PEY5 * gs * gs - (c.PEY3 + c.PEY4 * gs) * s)
            },
            signs("alpha", alpha_flip),
        );
    }
    if fitted.contains(&Stage::PureFx) {
        worst(
            Curvature::Ex,
            &|dfz, _, s| (c.PEX1 + c.PEX2 * dfz + c.PEX3 * dfz * dfz) * (1.0 - c.PEX4 * s) * c.LEX,
            signs("kappa", 1.0),
        );
    }
    out
}

/// Where a fitted PAC89's lateral curvature `E` is largest above 1 over
/// the fitted loads, and the slip angle beyond which its lateral force
/// changes sign there.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Pac89Reversal {
    /// The largest `E` over the fitted loads.
    pub largest: f64,
    /// The load there (N).
    pub fz: f64,
    /// The slip angle beyond which the lateral force at that load and zero
    /// camber has the opposite sign to its slope (rad).
    pub reverses_beyond: f64,
    /// The largest |slip angle| of the data (rad).
    pub data_alpha: f64,
}

impl Pac89Reversal {
    /// The warning, one line.
    pub fn line(&self) -> String {
        format!(
            "curvature E = a6·Fz + a7 reaches {} above 1 over the fitted loads (at fz {} N): PAC89 has no limit check, so past its peak the lateral force falls through zero and changes sign beyond |alpha| = {}° at that load (the data reach {}°); do not drive the file past its data's slip angles, or hold E at 1 (`--hold a6=0 --hold a7=1`)",
            readable(self.largest, 3),
            readable(self.fz, 4),
            readable(self.reverses_beyond.to_degrees(), 3),
            readable(self.data_alpha.to_degrees(), 3),
        )
    }
}

/// The PAC89 reversal of `t` over `spans`' loads (none where `E ≤ 1`
/// throughout, without a load span, or where the force keeps its sign to
/// 90°).
pub(crate) fn pac89_reversal(t: &Pac89, spans: &[Span]) -> Option<Pac89Reversal> {
    let fz = span(spans, "fz")?;
    // E is linear in the load: largest at an end.
    let (e, at) = [fz.lo, fz.hi]
        .into_iter()
        .map(|f| (t.a[6] * f / 1000.0 + t.a[7], f))
        .fold(
            (f64::NEG_INFINITY, 0.0),
            |b, x| if x.0 > b.0 { x } else { b },
        );
    if e <= 1.0 + 1e-9 {
        return None;
    }
    let c = t.lateral_curve(at / 1000.0, 0.0);
    let force = |x_deg: f64| magic_formula(c.b, c.c, c.d, c.e, x_deg + c.sh) + c.sv;
    let reverses = [1.0, -1.0]
        .into_iter()
        .filter_map(|side| sign_change(&force, side))
        .fold(f64::INFINITY, f64::min);
    let data_alpha = span(spans, "alpha").map_or(0.0, |s| s.lo.abs().max(s.hi.abs()));
    reverses.is_finite().then(|| Pac89Reversal {
        largest: e,
        fz: at,
        reverses_beyond: reverses.to_radians(),
        data_alpha,
    })
}

/// The smallest |x| (degrees, on the side `side` of zero, within 90°)
/// past which `force` has the opposite sign to its sign at 1° on that
/// side, by a scan in quarter degrees and bisection.
fn sign_change(force: &dyn Fn(f64) -> f64, side: f64) -> Option<f64> {
    let sign = force(side).signum();
    let (mut lo, mut hi) = (1.0, 1.0);
    while force(side * hi).signum() == sign {
        lo = hi;
        hi += 0.25;
        if hi > 90.0 {
            return None;
        }
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if force(side * mid).signum() == sign {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spans(fz: (f64, f64), alpha: f64) -> Vec<Span> {
        vec![
            Span {
                name: "fz",
                unit: "N",
                lo: fz.0,
                hi: fz.1,
            },
            Span {
                name: "alpha",
                unit: "rad",
                lo: -alpha,
                hi: alpha,
            },
        ]
    }

    #[test]
    fn a_pac89_whose_e_exceeds_one_reverses_where_its_force_changes_sign() {
        let mut t = Pac89::adams_example();
        t.a[6] = 0.08;
        t.a[7] = 1.0;
        let r = pac89_reversal(&t, &spans((400.0, 3000.0), 0.17)).unwrap();
        assert!((r.largest - 1.24).abs() < 1e-12, "{}", r.largest);
        assert_eq!(r.fz, 3000.0);
        // The force at zero camber changes sign at the angle said:
        // positive just inside it, negative past (the Adams example's
        // shifts are positive, so the positive side reverses first).
        let c = t.lateral_curve(3.0, 0.0);
        let f = |alpha: f64| magic(&c, alpha.to_degrees());
        assert!(f(r.reverses_beyond * 0.999) > 0.0);
        assert!(f(r.reverses_beyond * 1.001) < 0.0);
        // Near the root of φ = B·x·(1 − E) + E·atan(B·x), which the
        // shifts move by little.
        let u = {
            let phi = |u: f64| u * (1.0 - r.largest) + r.largest * u.atan();
            let (mut lo, mut hi) = (1.0, 100.0);
            for _ in 0..100 {
                let m = 0.5 * (lo + hi);
                if phi(m) > 0.0 {
                    lo = m
                } else {
                    hi = m
                }
            }
            lo
        };
        let x0 = u / c.b;
        assert!(
            (r.reverses_beyond.to_degrees() - x0).abs() < 0.05 * x0,
            "{} vs {x0}",
            r.reverses_beyond.to_degrees()
        );
        assert!(r.line().contains("beyond |alpha|"), "{}", r.line());
    }

    #[test]
    fn a_pac89_whose_e_stays_at_or_below_one_is_not_flagged() {
        let mut t = Pac89::adams_example();
        t.a[6] = -0.02;
        t.a[7] = 1.0;
        assert_eq!(pac89_reversal(&t, &spans((400.0, 3000.0), 0.17)), None);
    }

    fn magic(c: &crate::tyre::pac89::CurveCoefficients, x: f64) -> f64 {
        magic_formula(c.b, c.c, c.d, c.e, x + c.sh) + c.sv
    }
}
