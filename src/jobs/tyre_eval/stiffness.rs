//! A slip stiffness that changes sign inside the loads a points file
//! evaluates: a `.tir` whose `PKX1 + PKX2·dfz` crosses 0 within its load
//! range (the public `FSAE_Defaults.tir` at 1625 N) gives a longitudinal
//! force against its slip above that load, and `tyre-eval` writes it like
//! any other. Found by behaviour, for any model: the force's slope at zero
//! slip (a central difference of ±[`SLIP`]) at loads across the points'
//! range, and a change of its sign between two of them. A Magic Formula
//! tyre with its limit checks on evaluates its forces at no load above its
//! file's `FZMAX`: the loads probed, and the range the warning names, stop
//! there (the points' 5000 N on `FSAE_Defaults.tir`, whose `FZMAX` is
//! 2000 N, are evaluated at 2000 N).

use super::unread::Points;
use crate::tyre::{SlipState, Tyre};
use serde::Serialize;

/// The slip (ratio and angle, rad) of the central difference.
const SLIP: f64 = 1e-4;

/// Loads the slope is read at across the points' range.
const LOADS: usize = 65;

/// A stiffness whose sign changes between two loads.
#[derive(Debug, Clone, PartialEq)]
pub struct SignChange {
    /// `longitudinal slip` or `cornering`.
    pub stiffness: &'static str,
    /// The loads it first changes sign between, N.
    pub between: (f64, f64),
    /// How many times it changes sign over the loads probed (a held
    /// `PKY4 = −50` turns `sin(PKY4·atan(…))` over four times in 2–6 kN).
    pub changes: usize,
    /// The range of loads evaluated, N (after the limit checks).
    pub loads: (f64, f64),
    /// The largest load of the points, where the limit checks evaluate it
    /// at a lower one (the file's `FZMAX`), N.
    pub held_from: Option<f64>,
}

impl SignChange {
    /// The sentence on the terminal.
    pub fn line(&self) -> String {
        let n = |f: f64| format!("{f:.0}");
        let held = match self.held_from {
            Some(f) => format!(
                ", the points' loads up to {} N held at the file's FZMAX",
                n(f)
            ),
            None => String::new(),
        };
        let times = match self.changes {
            1 => String::new(),
            n => format!(" {n} times, first"),
        };
        format!(
            "the {} stiffness (the force's slope at zero slip) changes sign{times} between fz = {} N and {} N, inside the loads evaluated ({} to {} N{held}): on one side of it the tyre's force opposes its slip; check the file's load coefficients (a .tir's PKX1 + PKX2·dfz, PKY1…)",
            self.stiffness,
            n(self.between.0),
            n(self.between.1),
            n(self.loads.0),
            n(self.loads.1)
        )
    }
}

/// Points whose slip stiffness, at their own load, camber, pressure and
/// speed, is negative: there the force opposes the slip (ISO 8855:
/// `fx ≈ +C_κ·κ`, `fy ≈ +C_α·α`). What [`sign_changes`] finds along the
/// load at nominal conditions, counted at the points' own: a `.tir`'s
/// pressure coefficients can turn the cornering stiffness over inside its
/// own `PRESMIN`–`PRESMAX` (the public `car205_60R19.tir` above about
/// 500 kPa), and a load held at `FZMAX` past a sign change keeps it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AgainstSlip {
    /// `longitudinal slip` or `cornering`.
    pub stiffness: &'static str,
    /// Points at a positive load where it is negative.
    pub points: usize,
    /// The first of them, by its line in the points file (1-based, as
    /// every other warning of `tyre-eval` names a point), and its load (N),
    /// camber (rad) and pressure (Pa; 0 where the points give none).
    pub first: (usize, [f64; 3]),
    /// The file's `FZMAX` (N), where some of the points lie above it and
    /// the limit checks evaluate them there, not at their own load.
    pub held_at_fz_max: Option<f64>,
}

impl AgainstSlip {
    /// The sentence on the terminal.
    pub fn line(&self, count: usize) -> String {
        let (line, [fz, camber, pressure]) = self.first;
        let n = |v: f64| crate::format::readable(v, 4);
        let at_pressure = if pressure > 0.0 {
            format!(", pressure = {} Pa", n(pressure))
        } else {
            String::new()
        };
        // A load above FZMAX is evaluated at FZMAX, not at its own.
        let (load, fz_text) = match self.held_at_fz_max {
            Some(m) => (
                format!("load (at the file's FZMAX = {} N where above it)", n(m)),
                match fz > m {
                    true => format!("{} N given, evaluated at {} N", n(fz), n(m)),
                    false => format!("{} N", n(fz)),
                },
            ),
            None => ("own load".to_string(), format!("{} N", n(fz))),
        };
        format!(
            "{} of {} {} a negative {} stiffness at {} {load}, camber, pressure and speed (the first at line {line}: fz = {fz_text}, camber = {} rad{at_pressure}): there the force opposes the slip (ISO 8855: a positive slip gives a positive force), and the values written there are what the file's coefficients give where they describe no tyre (inside the file's ranges or not)",
            self.points,
            crate::format::plural(count, "point", "points"),
            if self.points == 1 { "has" } else { "have" },
            self.stiffness,
            if self.points == 1 { "its" } else { "their" },
            n(camber),
        )
    }
}

/// The points of `p` (at file lines `lines`) whose slip stiffnesses are
/// negative ([`AgainstSlip`]), by a central difference of ±[`SLIP`] at each
/// point's own conditions; a stiffness within 1e-6 of the largest found is
/// no sign (a model without that force).
pub(crate) fn against_slip(tyre: &Tyre, p: &Points, lines: &[usize]) -> Vec<AgainstSlip> {
    let [fz, kappa, alpha, camber, speed] = p.columns;
    // The load the forces are evaluated at: a Magic Formula tyre with its
    // limit checks on holds a load above FZMAX there.
    let fz_max = match tyre {
        Tyre::MagicFormula(t) if t.options.limit_checks => t.limits.fz_max,
        _ => None,
    };
    let n = fz.len();
    let zero = vec![0.0; n];
    let at = |s: f64| vec![s; n];
    let eval = |kappa: &[f64], alpha: &[f64]| {
        tyre.evaluate_points(fz, kappa, alpha, camber, speed, p.pressure)
    };
    let slopes = |plus: Vec<f64>, minus: Vec<f64>| -> Vec<f64> {
        plus.iter()
            .zip(&minus)
            .map(|(a, b)| (a - b) / (2.0 * SLIP))
            .collect()
    };
    let kx = slopes(
        eval(&at(SLIP), &zero).iter().map(|f| f.fx).collect(),
        eval(&at(-SLIP), &zero).iter().map(|f| f.fx).collect(),
    );
    let ky = slopes(
        eval(&zero, &at(SLIP)).iter().map(|f| f.fy).collect(),
        eval(&zero, &at(-SLIP)).iter().map(|f| f.fy).collect(),
    );
    // A point at zero slip of the kind has no slip for the force to
    // oppose (FSAE_Defaults.tir's points at kappa = 0 above 1625 N).
    [("longitudinal slip", kx, kappa), ("cornering", ky, alpha)]
        .into_iter()
        .filter_map(|(stiffness, k, slip)| {
            let scale = k
                .iter()
                .filter(|v| v.is_finite())
                .fold(0.0_f64, |m, v| m.max(v.abs()));
            let against: Vec<usize> = (0..n)
                .filter(|&i| fz[i] > 0.0 && slip[i] != 0.0 && k[i] < -1e-6 * scale)
                .collect();
            let held_at_fz_max = fz_max.filter(|m| against.iter().any(|&i| fz[i] > *m));
            let &i = against.first()?;
            let pressure = p.pressure.get(i).copied().unwrap_or(0.0);
            Some(AgainstSlip {
                stiffness,
                points: against.len(),
                first: (
                    lines.get(i).copied().unwrap_or(i + 2),
                    [fz[i], camber[i], pressure],
                ),
                held_at_fz_max,
            })
        })
        .collect()
}

/// The stiffnesses of `tyre` that change sign over the positive loads of
/// `fz`.
pub(crate) fn sign_changes(tyre: &Tyre, fz: &[f64]) -> Vec<SignChange> {
    let (lo, hi) = fz
        .iter()
        .filter(|f| **f > 0.0 && f.is_finite())
        .fold((f64::INFINITY, 0.0_f64), |(lo, hi), &f| {
            (lo.min(f), hi.max(f))
        });
    // The load the forces are evaluated at: a Magic Formula tyre with its
    // limit checks on holds a load above FZMAX there.
    let fz_max = match tyre {
        Tyre::MagicFormula(t) if t.options.limit_checks => t.limits.fz_max,
        _ => None,
    };
    let (hi, held_from) = match fz_max {
        Some(m) if hi > m => (m, Some(hi)),
        _ => (hi, None),
    };
    if lo >= hi {
        return Vec::new();
    }
    let loads: Vec<f64> = (0..LOADS)
        .map(|k| lo + (hi - lo) * k as f64 / (LOADS - 1) as f64)
        .collect();
    let slope = |fz: f64, longitudinal: bool| {
        let at = |s: f64| {
            let mut p = SlipState::lateral(0.0, fz);
            if longitudinal {
                p.kappa = s;
                tyre.point_forces(&p, None).fx
            } else {
                p.alpha = s;
                tyre.point_forces(&p, None).fy
            }
        };
        (at(SLIP) - at(-SLIP)) / (2.0 * SLIP)
    };
    [("longitudinal slip", true), ("cornering", false)]
        .into_iter()
        .filter_map(|(stiffness, longitudinal)| {
            let k: Vec<f64> = loads.iter().map(|&f| slope(f, longitudinal)).collect();
            // A model without the force (a lateral-only Gim) has none.
            let scale = k.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let tiny = 1e-6 * scale;
            // Between the last load of one sign and the first of the
            // other (a load where it is 0 lies between them).
            let signed: Vec<usize> = (0..LOADS).filter(|&i| k[i].abs() > tiny).collect();
            let flips: Vec<&[usize]> = signed
                .windows(2)
                .filter(|w| k[w[0]].signum() != k[w[1]].signum())
                .collect();
            let w = flips.first()?;
            Some(SignChange {
                stiffness,
                between: (loads[w[0]], loads[w[1]]),
                changes: flips.len(),
                loads: (lo, hi),
                held_from,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tir(name: &str) -> Tyre {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        crate::io::load_tyre(&root.join("tests/fixtures/tir").join(name)).unwrap()
    }

    #[test]
    fn a_tyre_whose_stiffnesses_keep_their_sign_gives_nothing() {
        let t = tir("MagicFormula61_Parameters.tir");
        assert!(sign_changes(&t, &[1000.0, 8000.0]).is_empty());
    }

    #[test]
    fn a_slip_stiffness_crossing_zero_is_found_between_two_loads() {
        // The MF 6.1 file (FNOMIN 6752 N, PKX1 32.9102) with PKX2 set so
        // that PKX1 + PKX2·dfz = 0 at dfz = 0.25, at 1.25·FNOMIN = 8440 N,
        // as FSAE_Defaults.tir's does at 1625 N.
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let text =
            std::fs::read_to_string(root.join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
                .unwrap();
        let text = text
            .replace(
                "PKX2                     =    12.7911",
                "PKX2                     =    -131.6408",
            )
            .replace(
                "PKX3                     =    -0.11254",
                "PKX3                     =    0",
            );
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("crossing.tir");
        assert!(
            text.contains("-131.6408")
                && text.contains("=    0       $Exponent in slip stiffness Kfx"),
            "the file changed"
        );
        std::fs::write(&path, text).unwrap();
        let t = crate::io::load_tyre(&path).unwrap();
        let cross = 6752.0 * 1.25;
        let found = sign_changes(&t, &[0.5 * cross, 1.5 * cross]);
        assert_eq!(found.len(), 1, "{found:?}");
        let s = &found[0];
        assert_eq!(s.stiffness, "longitudinal slip");
        assert_eq!(s.changes, 1);
        assert!(!s.line().contains("times"), "{}", s.line());
        assert!(
            s.between.0 <= cross && cross <= s.between.1,
            "{s:?} against {cross}"
        );
        // Evaluated on one side of it only: nothing to say.
        assert!(sign_changes(&t, &[0.5 * cross, 0.9 * cross]).is_empty());
    }
}
