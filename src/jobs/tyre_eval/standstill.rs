//! Points at rest (a speed below [`STANDSTILL`]), every one counted, and
//! those at a slip ratio or slip angle ≠ 0 said apart ([`AtRest`]): a slip
//! is a slip velocity over the speed (`κ = −Vsx/|Vx|`, `tan α =
//! −Vsy/|Vx|`), and a standing wheel has neither, so a slip at zero speed
//! is no physical state. A model evaluates it all the same, as the
//! steady-state force of a wheel rolling at that slip (the MF 6.1 sample at
//! 4 kN, κ = 0.05 and rest: fx = 4010 N), which is said with what was
//! evaluated, not left to read as a standing tyre's force.
//!
//! A Magic Formula aligning moment at zero speed, counted and said: the
//! pneumatic trail's term of `mz` is `−t·Fy` with `t ∝ cos'α =
//! Vcx/(Vc + εV)` (Pacejka 2012 eq. 4.E6a, `εV` = 1e-6 m/s, as MFeval
//! evaluates it), which is 0 at `Vcx` = 0: a standing tyre's `mz` is its
//! residual torque `Mzr` (and `s·Fx`) alone, a fraction of the moment the
//! same point has at any speed above [`STANDSTILL`], and often of the
//! opposite sign to it and to `fy` (MFeval's public MF 6.1 sample at 4 kN
//! and a slip angle of −0.05 rad: +0.21 N·m, −43 N·m at speed). This is
//! MFeval's formula, not a slip of this crate's (which matches MFeval to
//! rounding at speed): it is kept, and said, with how many points it
//! turned against their moment at speed (`VXLOW`, where the low-speed
//! fade of the shifts ends). (MFeval with its limit checks on, mode 1xx,
//! also fades the slips and the residual torque below `VXLOW`, to an `mz`
//! of about 0 at rest; this crate fades the shifts only, `mf/mod.rs`.)

use super::unread::Points;
use crate::tyre::{PointForces, Tyre};
use serde::Serialize;

/// The speed below which a point is at standstill for the trail, m/s:
/// there `εV` is more than 1 % of `Vc`, so `cos'α` is below 0.99 of
/// `cos α`.
pub const STANDSTILL: f64 = 1e-4;

/// The points at rest: a speed below [`STANDSTILL`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AtRest {
    /// Every point at rest.
    pub points: usize,
    /// Of them, those at a slip ratio or slip angle ≠ 0.
    pub with_slip: usize,
    /// The first of those: its line in the points file, `kappa`, `alpha`
    /// (rad), and the `fx` and `fy` evaluated there (N).
    pub first: (usize, [f64; 4]),
    /// A Magic Formula's `VXLOW`, m/s (`None` for another model).
    pub vxlow: Option<f64>,
}

impl AtRest {
    /// The sentence on the terminal, of `count` points.
    pub fn line(&self, count: usize) -> String {
        let n = |v: f64| crate::format::rounded(v, 4);
        let (line, [kappa, alpha, fx, fy]) = self.first;
        let faded = match self.vxlow {
            Some(v) => format!(
                ", its vertical shifts and `my` faded to 0 (linearly below VXLOW = {} m/s)",
                n(v)
            ),
            None => String::new(),
        };
        format!(
            "{} of {} at zero speed (below {STANDSTILL} m/s), {} of them at a slip ratio or slip angle ≠ 0 (the first at line {line}: kappa = {}, alpha = {} rad, evaluated to fx = {} N, fy = {} N): a slip at zero speed is not a physical state (κ = −Vsx/|Vx| and tan α = −Vsy/|Vx| are slip velocities over the speed, and a standing wheel has none); what was evaluated is the model's steady-state force of a wheel rolling at that slip{faded}, not a standing tyre's; give the wheel's speed, or a slip of 0 for a tyre at rest",
            self.points,
            crate::format::plural(count, "point", "points"),
            self.with_slip,
            n(kappa),
            n(alpha),
            n(fx),
            n(fy),
        )
    }
}

/// The points of `p` (outputs `f`, file lines `lines`) at rest, where one
/// is at a slip ratio or slip angle ≠ 0; `None` otherwise (a tyre standing
/// without slip is a physical state, and its forces are said elsewhere:
/// `zero_slip.rs`).
pub(crate) fn at_rest(
    tyre: &Tyre,
    p: &Points,
    f: &[PointForces],
    lines: &[usize],
) -> Option<AtRest> {
    let [_, kappa, alpha, _, speed] = p.columns;
    let resting: Vec<usize> = (0..f.len())
        .filter(|&i| speed[i].abs() < STANDSTILL)
        .collect();
    let slipping: Vec<usize> = resting
        .iter()
        .copied()
        .filter(|&i| kappa[i] != 0.0 || alpha[i] != 0.0)
        .collect();
    let &i = slipping.first()?;
    Some(AtRest {
        points: resting.len(),
        with_slip: slipping.len(),
        first: (
            lines.get(i).copied().unwrap_or(i + 2),
            [kappa[i], alpha[i], f[i].fx, f[i].fy],
        ),
        vxlow: match tyre {
            Tyre::MagicFormula(t) => Some(t.coefficients.VXLOW),
            _ => None,
        },
    })
}

/// Points at zero speed whose `mz` lacks the pneumatic trail's term.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StandstillMz {
    /// Points at a positive load, a slip angle ≠ 0 and a speed below
    /// [`STANDSTILL`].
    pub points: usize,
    /// Every point at a speed below [`STANDSTILL`], those among them.
    pub at_rest: usize,
    /// Of them, those whose `mz` has the opposite sign to the same
    /// point's at `VXLOW`.
    pub reversed: usize,
    /// The file's `VXLOW`, m/s.
    pub vxlow: f64,
    /// A reversed point's `mz` at zero speed and at `VXLOW`, N·m (the
    /// first), where one is.
    pub example: Option<[f64; 2]>,
}

impl StandstillMz {
    /// The sentence on the terminal.
    pub fn line(&self) -> String {
        let n = |v: f64| crate::format::readable(v, 3);
        let reversed = match self.example {
            Some([at_rest, moving]) => format!(
                ", of the opposite sign to the same point's at VXLOW = {} m/s at {} of them ({} N·m against {} N·m)",
                n(self.vxlow),
                self.reversed,
                n(at_rest),
                n(moving)
            ),
            None => String::new(),
        };
        format!(
            "{} of the {} at zero speed (below {STANDSTILL} m/s) {} a slip angle ≠ 0: mz there is the residual torque alone{reversed}, as MFeval's formula gives it (cos'α = Vx/(Vc + εV), Pacejka 2012 eq. 4.E6a with εV = 1e-6 m/s, is 0 at Vx = 0, so the pneumatic trail's term −t·fy drops); give the wheel's speed for the aligning moment of a rolling tyre",
            self.points,
            crate::format::plural(self.at_rest, "point", "points"),
            if self.points == 1 { "has" } else { "have" },
        )
    }
}

/// The points of `p` at zero speed where a Magic Formula `tyre` (outputs
/// `f`) gives `mz` without its trail; `None` for another model or no such
/// point.
pub(crate) fn standstill_mz(tyre: &Tyre, p: &Points, f: &[PointForces]) -> Option<StandstillMz> {
    let Tyre::MagicFormula(t) = tyre else {
        return None;
    };
    let [fz, kappa, alpha, camber, speed] = p.columns;
    let idx: Vec<usize> = (0..f.len())
        .filter(|&i| fz[i] > 0.0 && alpha[i] != 0.0 && speed[i].abs() < STANDSTILL)
        .collect();
    if idx.is_empty() {
        return None;
    }
    let vxlow = t.coefficients.VXLOW;
    let pick = |c: &[f64]| idx.iter().map(|&i| c[i]).collect::<Vec<f64>>();
    let pressure = match p.pressure.is_empty() {
        true => Vec::new(),
        false => pick(p.pressure),
    };
    let moving = tyre.evaluate_points(
        &pick(fz),
        &pick(kappa),
        &pick(alpha),
        &pick(camber),
        &vec![vxlow; idx.len()],
        &pressure,
    );
    let reversed: Vec<[f64; 2]> = idx
        .iter()
        .zip(&moving)
        .map(|(&i, m)| [f[i].mz, m.mz])
        .filter(|[a, b]| a * b < 0.0)
        .collect();
    Some(StandstillMz {
        points: idx.len(),
        at_rest: speed.iter().filter(|v| v.abs() < STANDSTILL).count(),
        reversed: reversed.len(),
        vxlow,
        example: reversed.first().copied(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_mf61_samples_mz_at_rest_is_its_residual_torque_against_its_moment_at_speed() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let tir = root.join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
        let t = crate::io::load_tyre(&tir).unwrap();
        let fz = [4000.0; 4];
        let kappa = [0.0; 4];
        let alpha = [0.05, -0.05, -0.05, 0.0];
        let camber = [0.0; 4];
        let speed = [0.0, 0.0, 20.0, 0.0];
        let f = t.evaluate_points(&fz, &kappa, &alpha, &camber, &speed, &[]);
        let p = Points {
            columns: [&fz, &kappa, &alpha, &camber, &speed],
            pressure: &[],
        };
        // At rest, a slip angle of -0.05 gives a positive mz; at speed
        // a negative one, with fy.
        assert!(f[1].mz > 0.0 && f[2].mz < -40.0 && f[1].fy < 0.0, "{f:?}");
        let s = standstill_mz(&t, &p, &f).unwrap();
        assert_eq!((s.points, s.at_rest, s.reversed), (2, 3, 1));
        // Every point at rest counted, those with a slip apart.
        let a = at_rest(&t, &p, &f, &[2, 3, 4, 5]).unwrap();
        assert_eq!((a.points, a.with_slip, a.first.0), (3, 2, 2));
        let [at_rest, moving] = s.example.unwrap();
        assert_eq!(at_rest, f[1].mz);
        assert!(moving < -40.0, "{moving}");
        // Another model has no such term.
        let gim = crate::io::load_tyre(&root.join("tyres/gim.toml")).unwrap();
        assert_eq!(standstill_mz(&gim, &p, &f), None);
    }
}
