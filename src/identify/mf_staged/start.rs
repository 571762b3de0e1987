//! Start values: the base tyre (template or a bare one sized from the
//! rows), the levels in a stage's rows, and the estimates of friction,
//! slip stiffness and trail per load level with their load laws fitted by
//! least squares (`--start data`).

use super::params::Stage;
use super::{MfRow, Settings, PURE_TOL};
use crate::identify::grouping::{levels, Variable};
use crate::tyre::mf::{MagicFormula, MfCoefficients, MfOptions, TyreSide};

fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Whether `t` writes its cornering stiffness on the other branch:
/// `Kyα = PKY1·Fz0'·…·sin(PKY4·atan x)` is odd in `PKY1` and `PKY4`
/// together, so `PKY1 = 27.42`, `PKY4 = −3.268` (MFeval's 6.1 and 6.2
/// samples) and `PKY1 = −27.42`, `PKY4 = 3.268` are one tyre. The fit keeps
/// `PKY4` within 0.1 to 5 ([`super::params::physical_bounds`]); a start
/// or a held value from the other branch has the stiffness's sign wrong
/// (a start σ of 192 % on data made from that very file).
pub(super) fn other_stiffness_branch(t: &MagicFormula) -> bool {
    t.coefficients.PKY4 < 0.0
}

/// A template's value of `name` as the fit reads it: `PKY1` and `PKY4`
/// on the branch the fit keeps ([`other_stiffness_branch`]).
pub(super) fn template_value(t: &MagicFormula, name: &str) -> Option<f64> {
    let v = t.coefficients.get(name)?;
    let flip = other_stiffness_branch(t) && (name == "PKY1" || name == "PKY4");
    Some(if flip { -v } else { v })
}

/// The template, or a bare tyre sized from the rows.
pub(super) fn base_tyre(rows: &[MfRow], s: &Settings) -> MagicFormula {
    let mut t = s.template.clone().unwrap_or_else(|| {
        let mut c = MfCoefficients {
            FNOMIN: (median(rows.iter().map(|r| r.fz).collect()) / 10.0).round() * 10.0,
            ..MfCoefficients::default()
        };
        let p = median(rows.iter().filter_map(|r| r.pressure).collect());
        if p.is_finite() {
            c.NOMPRES = (p / 100.0).round() * 100.0;
        }
        // To 0.1 m/s, as FNOMIN and NOMPRES are rounded: a rig's median
        // speed to sixteen digits (11.169666666666668) is noise, not a
        // reference; divided (not multiplied by 0.1) so that it prints as
        // 11.2, and never 0, which LONGVL divides by.
        let v = median(rows.iter().map(|r| r.speed).collect());
        if v.is_finite() && v > 0.0 {
            c.LONGVL = ((v * 10.0).round() / 10.0).max(0.1);
        }
        MagicFormula {
            version: s.version,
            side: TyreSide::Left,
            options: MfOptions::default(),
            limits: Default::default(),
            coefficients: c,
        }
    });
    t.version = s.version;
    if other_stiffness_branch(&t) {
        for name in ["PKY1", "PKY4"] {
            let v = template_value(&t, name).unwrap_or(0.0);
            t.coefficients.set(name, v);
        }
    }
    t
}

/// Counts of load, camber and pressure levels in rows.
pub(super) fn level_counts(rows: &[&MfRow]) -> [usize; 3] {
    let fz: Vec<f64> = rows.iter().map(|r| r.fz).collect();
    let ga: Vec<f64> = rows.iter().map(|r| r.camber).collect();
    let p: Vec<f64> = rows.iter().filter_map(|r| r.pressure).collect();
    [
        levels(Variable::Load, &fz, 10.0).levels.len().max(1),
        levels(Variable::Camber, &ga, 0.1f64.to_radians())
            .levels
            .len()
            .max(1),
        if p.len() == rows.len() && !p.is_empty() {
            levels(Variable::Pressure, &p, 1000.0).levels.len().max(1)
        } else {
            1
        },
    ]
}

/// Rows grouped by load level (nominal loads ascending), at the camber
/// closest to zero and the pressure closest to nominal.
fn by_load<'a>(rows: &[&'a MfRow], nompres: f64) -> Vec<(f64, Vec<&'a MfRow>)> {
    let gmin = rows
        .iter()
        .map(|r| r.camber.abs())
        .fold(f64::INFINITY, f64::min);
    let pbest = rows
        .iter()
        .filter_map(|r| r.pressure)
        .min_by(|a, b| (a - nompres).abs().total_cmp(&(b - nompres).abs()));
    let sel: Vec<&MfRow> = rows
        .iter()
        .copied()
        .filter(|r| (r.camber.abs() - gmin).abs() < 0.05f64.to_radians())
        .filter(|r| match (pbest, r.pressure) {
            (Some(pb), Some(p)) => (p - pb).abs() < 3000.0,
            _ => true,
        })
        .collect();
    let fz: Vec<f64> = sel.iter().map(|r| r.fz).collect();
    let lv = levels(Variable::Load, &fz, 10.0);
    let mut out: Vec<(f64, Vec<&MfRow>)> =
        lv.levels.iter().map(|l| (l.nominal, Vec::new())).collect();
    for r in sel {
        if let Some(k) = (0..out.len()).min_by(|a, b| {
            (out[*a].0 - r.fz)
                .abs()
                .total_cmp(&(out[*b].0 - r.fz).abs())
        }) {
            out[k].1.push(r);
        }
    }
    out.retain(|(_, v)| v.len() >= 3);
    out
}

/// Least-squares slope of `y` on `x` (with intercept) over the points whose
/// `|x|` is within `range`, or the four smallest `|x|` if fewer than three.
fn slope(pts: &[(f64, f64)], range: f64) -> Option<f64> {
    let mut p: Vec<(f64, f64)> = pts.iter().copied().filter(|q| q.0.abs() <= range).collect();
    if p.len() < 3 {
        let mut all = pts.to_vec();
        all.sort_by(|a, b| a.0.abs().total_cmp(&b.0.abs()));
        p = all.into_iter().take(4).collect();
    }
    let n = p.len() as f64;
    let (mx, my) = (
        p.iter().map(|q| q.0).sum::<f64>() / n,
        p.iter().map(|q| q.1).sum::<f64>() / n,
    );
    let sxx: f64 = p.iter().map(|q| (q.0 - mx).powi(2)).sum();
    let sxy: f64 = p.iter().map(|q| (q.0 - mx) * (q.1 - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx).filter(|s| s.is_finite())
}

/// `y ≈ a + b·x` by least squares (`b = 0` from one point).
fn line(pts: &[(f64, f64)]) -> (f64, f64) {
    let n = pts.len() as f64;
    let (mx, my) = (
        pts.iter().map(|q| q.0).sum::<f64>() / n,
        pts.iter().map(|q| q.1).sum::<f64>() / n,
    );
    let sxx: f64 = pts.iter().map(|q| (q.0 - mx).powi(2)).sum();
    let sxy: f64 = pts.iter().map(|q| (q.0 - mx) * (q.1 - my)).sum();
    if pts.len() < 2 || sxx <= 0.0 {
        (my, 0.0)
    } else {
        let b = sxy / sxx;
        (my - b * mx, b)
    }
}

/// `PKY1`, `PKY2` of `Kyα(Fz) = PKY1·Fz0·sin(PKY4·atan(Fz/(PKY2·Fz0)))`
/// from the slip stiffnesses `stiff` (load, N/rad) measured per load (ISO-W:
/// negative for a positive crate slope): `PKY2` on a grid, `PKY1` by least
/// squares for each; (−20, 2) without stiffnesses.
fn cornering_stiffness_law(stiff: &[(f64, f64)], fz0: f64, pky4: f64) -> (f64, f64) {
    let mut best = (f64::INFINITY, -20.0, 2.0);
    if !stiff.is_empty() {
        for i in 0..=150 {
            let pky2 = 0.5 + 0.05 * i as f64;
            let shape: Vec<f64> = stiff
                .iter()
                .map(|(fz, _)| fz0 * (pky4 * (fz / (pky2 * fz0)).atan()).sin())
                .collect();
            let num: f64 = stiff.iter().zip(&shape).map(|(s, h)| -s.1 * h).sum();
            let den: f64 = shape.iter().map(|h| h * h).sum();
            let pky1 = num / den;
            let err: f64 = stiff
                .iter()
                .zip(&shape)
                .map(|(s, h)| ((pky1 * h + s.1) / s.1).powi(2))
                .sum();
            if err < best.0 {
                best = (err, pky1, pky2);
            }
        }
    }
    (best.1, best.2)
}

/// `RBY1` estimated from the combined rows. With `Cyκ = 1`, `Eyκ = 0` and
/// no offsets the weighting is `Gyκ = Fy/Fy0 = cos(atan(Byκ·κ))`, so
/// `Byκ = sqrt(1/G² − 1)/|κ|`, and `RBY1 = Byκ / cos(atan(rby2·α))` at the
/// start's `RBY2`; `Fy0` is `base` (the pure `Fy` just fitted) at κ = 0.
/// The median over the rows whose pure force is at least a third of the
/// largest (where the ratio means something) and `0 < G < 1`; `None`
/// without such rows. A fixed start (10) can leave the fit in a local
/// minimum when the truth is far from it (MFeval's 6.1 file has 26).
fn lateral_weight_stiffness(base: &MagicFormula, rows: &[&MfRow], rby2: f64) -> Option<f64> {
    let pairs: Vec<(&MfRow, f64)> = rows
        .iter()
        .filter(|r| r.alpha.abs() > PURE_TOL && r.kappa.abs() > PURE_TOL)
        .map(|r| {
            let pure = MfRow { kappa: 0.0, ..**r };
            (*r, base.evaluate(&pure.input()).fy)
        })
        .collect();
    let largest = pairs.iter().map(|(_, f)| f.abs()).fold(0.0, f64::max);
    let b: Vec<f64> = pairs
        .iter()
        .filter(|(_, f0)| f0.abs() >= largest / 3.0)
        .filter_map(|(r, f0)| {
            let g = r.fy / f0;
            (g > 0.0 && g < 1.0).then(|| {
                (1.0 / (g * g) - 1.0).sqrt() / r.kappa.abs() / (rby2 * r.alpha).atan().cos()
            })
        })
        .collect();
    let m = median(b);
    m.is_finite().then_some(m)
}

/// Start values estimated from a stage's rows (only names it sets).
pub(super) fn data_start(
    stage: Stage,
    base: &MagicFormula,
    rows: &[&MfRow],
) -> Vec<(&'static str, f64)> {
    let c = &base.coefficients;
    match stage {
        Stage::PureFx | Stage::PureFy => pure_force_start(stage, c, &by_load(rows, c.NOMPRES)),
        Stage::PureMz => aligning_start(c, &by_load(rows, c.NOMPRES)),
        Stage::CombinedFx => vec![("RBX1", 10.0), ("RBX2", 8.0), ("RCX1", 1.0), ("REX1", 0.0)],
        Stage::CombinedMz => Vec::new(),
        // Off zero, where the products' gradients vanish: a unit sine
        // amplitude over a gentle load cosine and a small force slope.
        Stage::Mx => vec![
            ("QSX4", 1.0),
            ("QSX5", 0.5),
            ("QSX6", 1.0),
            ("QSX7", 0.5),
            ("QSX8", 1.0),
            ("QSX9", 0.1),
            ("QSX10", 0.1),
            ("QSX11", 1.0),
        ],
        // The load power multiplies the polynomial: QSY1 starts at a
        // typical rolling-resistance coefficient, not at 0.
        Stage::My => vec![("QSY1", 0.01)],
        Stage::CombinedFy => {
            let rby1 = lateral_weight_stiffness(base, rows, 8.0).unwrap_or(10.0);
            vec![
                ("RBY1", rby1),
                ("RBY2", 8.0),
                ("RCY1", 1.0),
                ("REY1", 0.0),
                ("RVY4", 50.0),
                ("RVY5", 2.0),
                ("RVY6", 10.0),
            ]
        }
    }
}

/// The pure lateral (`stage` PureFy) or longitudinal force's start from
/// the rows grouped by load (`groups`): the peak friction's and the slip
/// stiffness's lines in the load increment `dfz`.
fn pure_force_start(
    stage: Stage,
    c: &MfCoefficients,
    groups: &[(f64, Vec<&MfRow>)],
) -> Vec<(&'static str, f64)> {
    let fz0 = c.FNOMIN * c.LFZO;
    let dfz = |fz: f64| (fz - fz0) / fz0;
    let lat = stage == Stage::PureFy;
    let slip = |r: &MfRow| if lat { r.alpha } else { r.kappa };
    let force = |r: &MfRow| if lat { r.fy } else { r.fx };
    let mut mu = Vec::new();
    let mut stiff = Vec::new();
    for (fz, g) in groups {
        let peak = g.iter().map(|r| force(r).abs()).fold(0.0, f64::max);
        mu.push((dfz(*fz), peak / fz));
        let pts: Vec<(f64, f64)> = g.iter().map(|r| (slip(r), force(r))).collect();
        let range = if lat { 1.5f64.to_radians() } else { 0.02 };
        if let Some(k) = slope(&pts, range).filter(|k| *k > 0.0) {
            stiff.push((*fz, k));
        }
    }
    let (d1, d2) = if mu.is_empty() { (1.0, 0.0) } else { line(&mu) };
    let mut out: Vec<(&'static str, f64)> = Vec::new();
    if lat {
        out.extend([("PCY1", 1.3), ("PDY1", d1), ("PDY2", d2), ("PEY1", 0.0)]);
        let (pky1, pky2) = cornering_stiffness_law(&stiff, fz0, c.PKY4);
        out.extend([("PKY1", pky1), ("PKY2", pky2)]);
    } else {
        let kx: Vec<(f64, f64)> = stiff.iter().map(|(fz, k)| (dfz(*fz), k / fz)).collect();
        let (k1, k2) = if kx.is_empty() {
            (20.0, 0.0)
        } else {
            line(&kx)
        };
        out.extend([
            ("PCX1", 1.65),
            ("PDX1", d1),
            ("PDX2", d2),
            ("PEX1", 0.0),
            ("PKX1", k1),
            ("PKX2", k2),
        ]);
    }
    out
}

/// The aligning moment's start from the rows grouped by load (`groups`):
/// the pneumatic trail near zero slip, the slope of mz over fy; with
/// Dt = Fz·(R0/Fz0)·(QDZ1 + QDZ2·dfz) (the trail at α = 0).
fn aligning_start(c: &MfCoefficients, groups: &[(f64, Vec<&MfRow>)]) -> Vec<(&'static str, f64)> {
    let fz0 = c.FNOMIN * c.LFZO;
    let dfz = |fz: f64| (fz - fz0) / fz0;
    let r0 = c.UNLOADED_RADIUS;
    let trail: Vec<(f64, f64)> = groups
        .iter()
        .filter_map(|(fz, g)| {
            let pts: Vec<(f64, f64)> = g
                .iter()
                .filter(|r| r.alpha.abs() <= 2f64.to_radians())
                .map(|r| (r.fy, r.mz))
                .collect();
            let t = slope(&pts, f64::INFINITY)?;
            Some((dfz(*fz), t * fz0 / (r0 * fz)))
        })
        .collect();
    let (q1, q2) = if trail.is_empty() {
        (0.1, 0.0)
    } else {
        line(&trail)
    };
    // QBZ10 must start off zero: at Br = 0 the residual torque's
    // cos(atan(Br·αr)) has no slope in Br.
    vec![
        ("QBZ1", 10.0),
        ("QBZ10", 1.0),
        ("QCZ1", 1.2),
        ("QDZ1", q1),
        ("QDZ2", q2),
        ("QEZ1", 0.0),
    ]
}
