//! Whether a fitted Magic Formula's curvatures stay at or below 1 over the
//! data it was fitted to. The fit bounds `PEY1` and `PEX1` by 1, but the
//! curvature is a combination — `Ey = (PEY1 + PEY2·dfz)·(1 + PEY5·γ*² −
//! (PEY3 + PEY4·γ*)·sgn αy)·LEY`, `Ex = (PEX1 + PEX2·dfz + PEX3·dfz²)·(1 −
//! PEX4·sgn κ)·LEX` — and can exceed 1 at a load or camber of the data
//! while each coefficient lies within its bound. The formula with its
//! limit checks on (MFeval's `useLimitsCheck`, `tyre-eval`'s default mode
//! 121) clips it at 1 and reproduces the fit; without them (mode 221) the
//! force departs from the data. The excess is said, not hidden.

use super::ranges::Span;
use crate::format::readable;
use crate::identify::mf_staged::Stage;
use crate::tyre::mf::{MagicFormula, TyreSide};
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
