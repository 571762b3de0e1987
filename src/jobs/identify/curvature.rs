//! Whether a fitted Magic Formula's curvatures stay at or below 1 over the
//! data it was fitted to. The fit bounds `PEY1` and `PEX1` by 1, but the
//! curvature is a combination — `Ey = (PEY1 + PEY2·dfz)·(1 + PEY5·γ*² −
//! (PEY3 + PEY4·γ*)·sgn αy)·LEY`, `Ex = (PEX1 + PEX2·dfz + PEX3·dfz²)·(1 −
//! PEX4·sgn κ)·LEX` — and can exceed 1 at a load or camber of the data
//! while each coefficient lies within its bound. The formula with its
//! limit checks on (MFeval's `useLimitsCheck`, `tyre-eval`'s default mode
//! 121) clips it at 1 and reproduces the fit; without them (mode 221) the
//! force departs from the data. The excess is said, not hidden, with the
//! slip beyond which the file's force, without the checks, changes sign
//! where the fit's does not: the Hoosier file's `Ey` reaches 4.89 at 3.2°
//! camber, and its lateral force reverses there inside the data's slip
//! angles. The fit is not constrained to `E ≤ 1`: on that file the
//! constraint (tried as penalty rows) cost a quarter of the lateral σ,
//! 1.76 → 2.2 %, and made the stage's optimum depend on its start; the
//! clipped curvature is the formula's own with the checks on (Pacejka
//! 2012, eq. 4.E24, `Ey ≤ 1`).
//!
//! PAC89 (Adams numbering, `E = a6·Fz + a7`, Fz in kN) has no limit check:
//! above 1 its lateral force falls past the peak and changes sign at a
//! slip angle where `φ = B·x·(1 − E) + E·atan(B·x)` returns to zero — the
//! Hoosier file's fit reaches E 1.24 and reverses near 40°, outside the
//! data's 9.7° but inside a simulation's reach. The angle is said.

use super::ranges::Span;
use crate::format::readable;
use crate::identify::mf_staged::Stage;
use crate::tyre::mf::{MagicFormula, MfInput, TyreSide};
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
/// fitted ranges, and what the file's force does there without the limit
/// checks.
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
    /// The sign of the slip there (+1 or −1), in the frame of the points
    /// `tyre-eval` reads (the crate's: a left tyre's file frame negated).
    pub slip_sign: f64,
    /// The smallest |slip| (slip angle in rad, or slip ratio) beyond which
    /// the force, evaluated without the limit checks (mode 221), has the
    /// opposite sign to the fit's (with them), over the places where the
    /// curvature exceeds 1; `None` where it keeps it (to 90°, or a slip
    /// ratio of 1).
    pub reverses_beyond: Option<f64>,
    /// The place of that reversal: load (N), camber (rad), slip sign, all
    /// in the frame of the points `tyre-eval` reads.
    pub reverses_at: Option<(f64, f64, f64)>,
    /// The pressure of that reversal (Pa; `None` without a pressure
    /// span): the scan runs at the data's pressures, as the file's own
    /// `INFLPRES` may lie outside them, where the limit checks clip the
    /// pressure and the force without them differs at every slip.
    pub reverses_at_pressure: Option<f64>,
    /// The first reversal on the other slip sign, where there is one
    /// too: slip, then load (N), camber (rad), slip sign. The warning named
    /// only the earlier side, and mode 221 showed the Hoosier fit's force
    /// turning on both (5.76° positive, between 6° and 7° negative).
    pub reverses_also: Option<(f64, (f64, f64, f64))>,
    /// The largest |slip| of that kind the data reach.
    pub data_slip: f64,
}

impl CurvatureExcess {
    /// A slip of this curvature's kind in words (`6.31°`, `0.35`).
    fn slip_text(&self, x: f64) -> String {
        match self.curvature {
            Curvature::Ey => format!("{}°", readable(x.to_degrees(), 3)),
            Curvature::Ex => readable(x, 3),
        }
    }

    /// The warning, one line.
    pub fn line(&self) -> String {
        let (name, symbol) = match self.curvature {
            Curvature::Ey => ("lateral", "|alpha|"),
            Curvature::Ex => ("longitudinal", "|kappa|"),
        };
        let without = match self.reverses_beyond.zip(self.reverses_at) {
            Some((x, (fz, camber, sign))) => format!(
                "with the checks off (mode 221) its {name} force changes sign beyond {symbol} = {} at fz {} N, camber {}°{}, {} {} ({} the data's {}), while with them it keeps its sign (signs as tyre-eval's points give them)",
                self.slip_text(x),
                readable(fz, 4),
                readable(camber.to_degrees(), 3),
                self.reverses_at_pressure
                    .map_or(String::new(), |p| format!(", pressure {} Pa", readable(p, 4))),
                if sign > 0.0 { "positive" } else { "negative" },
                self.curvature.slip(),
                if x <= self.data_slip { "inside" } else { "outside" },
                self.slip_text(self.data_slip),
            ),
            None => "with the checks off (mode 221) its force departs from the fit".into(),
        };
        let also = self
            .reverses_also
            .map_or(String::new(), |(x, (fz, camber, sign))| {
                format!(
                "; on the {} {} too, beyond {symbol} = {} at fz {} N, camber {}° ({} the data's)",
                if sign > 0.0 { "positive" } else { "negative" },
                self.curvature.slip(),
                self.slip_text(x),
                readable(fz, 4),
                readable(camber.to_degrees(), 3),
                if x <= self.data_slip { "inside" } else { "outside" },
            )
            });
        format!(
            "curvature {} reaches {} above 1 over the fitted data (at fz {} N, camber {}°, {} {}): the file relies on a limit check clipping E at 1 (MFeval's useLimitsCheck; tyre-eval's mode 121, the default); {without}{also}",
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

/// The ends of a span and the vertex `v` where it lies inside; `none`
/// without a span.
fn ends_and(s: Option<(f64, f64)>, none: f64, v: Option<f64>) -> Vec<f64> {
    let (lo, hi) = s.unwrap_or((none, none));
    let mut out = vec![lo, hi];
    out.extend(v.filter(|v| (lo.min(hi)..=lo.max(hi)).contains(v)));
    out
}

/// A place a curvature is evaluated at: slip sign, load (N), camber (rad),
/// in the crate's frame (that of `tyre-eval`'s points).
type Place = (f64, f64, f64);

/// The curvatures of `t` above 1 over `spans`, the fitted stages' (`Ey`
/// where the pure lateral stage was fitted, `Ex` where the longitudinal).
/// `Ey` is linear in the load and quadratic in `γ* = sin γ`, `Ex`
/// quadratic in the load: the largest value over the ranges lies at an
/// end or at the vertex, which are the places evaluated (exactly, where a
/// grid would miss a vertex between its points).
pub(crate) fn curvature_excess(
    t: &MagicFormula,
    spans: &[Span],
    fitted: &[Stage],
) -> Vec<CurvatureExcess> {
    let c = &t.coefficients;
    let fz0 = c.FNOMIN * c.LFZO;
    let range = |name: &str| span(spans, name).map(|s| (s.lo, s.hi));
    // A left tyre's slip angle is the crate's negated; a right tyre's
    // camber likewise.
    let alpha_flip = if t.side == TyreSide::Left { -1.0 } else { 1.0 };
    let camber_flip = if t.side == TyreSide::Right { -1.0 } else { 1.0 };
    let signs = |name: &str, flip: f64| -> Vec<f64> {
        let s = range(name);
        [1.0, -1.0]
            .into_iter()
            .filter(|&g| s.is_some_and(|(lo, hi)| (flip * lo * g).max(flip * hi * g) > 0.0))
            .collect()
    };
    let gs_range =
        range("camber").map(|(lo, hi)| ((camber_flip * lo).sin(), (camber_flip * hi).sin()));
    // The reversal is scanned at the data's pressures (their ends and the
    // nominal between): `None`, the file's INFLPRES, may lie outside them.
    let pressures: Vec<Option<f64>> = match range("pressure") {
        Some((lo, hi)) => ends_and(Some((lo, hi)), lo, Some(c.NOMPRES))
            .into_iter()
            .map(Some)
            .collect(),
        None => vec![None],
    };
    let mut out = Vec::new();
    if fitted.contains(&Stage::PureFy) {
        let mut places: Vec<(f64, Place)> = Vec::new();
        for s in signs("alpha", alpha_flip) {
            let vertex = (c.PEY5 != 0.0).then(|| c.PEY4 * s / (2.0 * c.PEY5));
            for &fz in &ends_and(range("fz"), c.FNOMIN, None) {
                for gs in ends_and(gs_range, 0.0, vertex) {
                    let dfz = (fz - fz0) / fz0;
                    let e = (c.PEY1 + c.PEY2 * dfz)
                        * c.LEY
                        * (1.0 + c.PEY5 * gs * gs - (c.PEY3 + c.PEY4 * gs) * s);
                    places.push((e, (alpha_flip * s, fz, camber_flip * gs.asin())));
                }
            }
        }
        out.extend(excess(t, Curvature::Ey, places, range("alpha"), &pressures));
    }
    if fitted.contains(&Stage::PureFx) {
        let camber = range("camber").map_or(0.0, |r| r.0);
        let dfz = range("fz").map(|(lo, hi)| ((lo - fz0) / fz0, (hi - fz0) / fz0));
        let vertex = (c.PEX3 != 0.0).then(|| -c.PEX2 / (2.0 * c.PEX3));
        let mut places: Vec<(f64, Place)> = Vec::new();
        for s in signs("kappa", 1.0) {
            for d in ends_and(dfz, (c.FNOMIN - fz0) / fz0, vertex) {
                let e = (c.PEX1 + c.PEX2 * d + c.PEX3 * d * d) * (1.0 - c.PEX4 * s) * c.LEX;
                places.push((e, (s, fz0 * (1.0 + d), camber)));
            }
        }
        out.extend(excess(t, Curvature::Ex, places, range("kappa"), &pressures));
    }
    out
}

/// The largest of `places` (curvature, place) above 1, with where the
/// force there reverses without the limit checks; `slips` the data's range
/// of the curvature's slip (crate convention).
fn excess(
    t: &MagicFormula,
    curvature: Curvature,
    places: Vec<(f64, Place)>,
    slips: Option<(f64, f64)>,
    pressures: &[Option<f64>],
) -> Option<CurvatureExcess> {
    let above: Vec<(f64, Place)> = places.into_iter().filter(|p| p.0 > 1.0 + 1e-9).collect();
    let (largest, (s, fz, camber)) = *above.iter().max_by(|a, b| a.0.total_cmp(&b.0))?;
    // The earliest reversal may be where the curvature is not largest
    // (the other slip sign, where the force's shifts differ), and at any
    // of the data's pressures.
    let reversals: Vec<(f64, Place, Option<f64>)> = above
        .iter()
        .flat_map(|(_, at)| pressures.iter().map(move |p| (*at, *p)))
        .filter_map(|(at, p)| reversal(t, curvature, at, p).map(|x| (x, at, p)))
        .collect();
    let earliest = |side: Option<f64>| {
        reversals
            .iter()
            .filter(|r| side.is_none_or(|s| r.1 .0 == s))
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .copied()
    };
    let first = earliest(None);
    let also = first
        .and_then(|f| earliest(Some(-f.1 .0)))
        .map(|(x, (s, fz, camber), _)| (x, (fz, camber, s)));
    Some(CurvatureExcess {
        curvature,
        largest,
        fz,
        camber,
        slip_sign: s,
        reverses_beyond: first.map(|f| f.0),
        reverses_at: first.map(|(_, (s, fz, camber), _)| (fz, camber, s)),
        reverses_at_pressure: first.and_then(|f| f.2),
        reverses_also: also,
        data_slip: slips.map_or(0.0, |(lo, hi)| lo.abs().max(hi.abs())),
    })
}

/// The smallest |slip| at `place` and `pressure` past which the pure force of `t`
/// without the limit checks has the opposite sign to the force with them
/// (the fit's), by a scan (quarter degrees to 90°; slip ratio steps of
/// 0.0025 to 1) and bisection; `None` where it keeps the sign.
fn reversal(
    t: &MagicFormula,
    curvature: Curvature,
    (s, fz, camber): Place,
    pressure: Option<f64>,
) -> Option<f64> {
    let mut free = t.clone();
    free.options.limit_checks = false;
    let force = |tyre: &MagicFormula, x: f64| {
        let slip = s * x;
        let (kappa, alpha) = match curvature {
            Curvature::Ey => (0.0, slip),
            Curvature::Ex => (slip, 0.0),
        };
        let o = tyre.evaluate(&MfInput {
            fz,
            kappa,
            alpha,
            camber,
            speed: t.coefficients.LONGVL,
            pressure,
        });
        match curvature {
            Curvature::Ey => o.fy,
            Curvature::Ex => o.fx,
        }
    };
    let opposite = |x: f64| force(&free, x) * force(t, x) < 0.0;
    let (step, end) = match curvature {
        Curvature::Ey => (0.25f64.to_radians(), std::f64::consts::FRAC_PI_2),
        Curvature::Ex => (0.0025, 1.0),
    };
    let (mut lo, mut hi) = (step, step);
    while !opposite(hi) {
        lo = hi;
        hi += step;
        if hi > end {
            return None;
        }
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if opposite(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(0.5 * (lo + hi))
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

    /// `Ey` concave in the camber (`PEY5 < 0`) peaks between the camber
    /// ends, at `γ* = PEY4·s/(2·PEY5)`: found there exactly (a grid of the
    /// range would step over it), and a curvature a thousandth above 1
    /// turns the force, if at all, only past 80° (where it is near zero).
    #[test]
    fn a_curvature_above_one_only_at_its_camber_vertex_is_found_there() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/tir");
        let mut t = crate::io::tir::load_tir(&dir.join("MagicFormula61_Parameters.tir")).unwrap();
        let c = &mut t.coefficients;
        (c.PEY1, c.PEY2, c.PEY3, c.PEY4, c.PEY5, c.LEY) = (1.0, 0.0, 0.0, 0.5, -60.0, 1.0);
        let mut at = spans((2000.0, 6000.0), 0.2);
        at.push(Span {
            name: "camber",
            unit: "rad",
            lo: -0.05,
            hi: 0.06,
        });
        let e = curvature_excess(&t, &at, &[Stage::PureFy]);
        assert_eq!(e.len(), 1, "{e:?}");
        // 1 + PEY4²/(4·|PEY5|) at |γ*| = 1/240.
        assert!((e[0].largest - (1.0 + 0.25 / 240.0)).abs() < 1e-12, "{e:?}");
        assert!(
            (e[0].camber.abs() - (1.0f64 / 240.0).asin()).abs() < 1e-12,
            "{e:?}"
        );
        assert!(
            e[0].reverses_beyond.is_none_or(|x| x > 80f64.to_radians()),
            "{e:?}"
        );
        // At the ends alone it is below 1: nothing said without the vertex.
        t.coefficients.PEY1 = 0.99;
        assert!(curvature_excess(&t, &at, &[Stage::PureFy]).is_empty());
    }

    fn magic(c: &crate::tyre::pac89::CurveCoefficients, x: f64) -> f64 {
        magic_formula(c.b, c.c, c.d, c.e, x + c.sh) + c.sv
    }
}
