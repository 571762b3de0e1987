//! Tyre rig data (`FORMATS.md`): reading, grouping of continuous sweeps into
//! test conditions (nominal load, camber, pressure) and thinning.
//!
//! Real rig data is continuous sweeps with transitions between conditions.
//! Each grouping variable is histogrammed; bins holding at least 1 % of the
//! samples are kept, adjacent kept bins merge into a level, the level's
//! nominal value is the median of its samples, and samples in transitions
//! (outside every level) are dropped. Thinning averages the samples of each
//! condition in slip-angle bins (default 0.25°), which also averages the
//! hysteresis of up and down sweeps. Units: N, rad, Pa, m/s.

use crate::error::InputError;
use crate::io::read_columns;
use std::path::Path;

/// Rig samples.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RigData {
    /// Vertical load, N.
    pub fz: Vec<f64>,
    /// Slip angle, rad.
    pub alpha: Vec<f64>,
    /// Lateral force, N.
    pub fy: Vec<f64>,
    /// Aligning moment, N·m (if measured).
    pub mz: Option<Vec<f64>>,
    /// Camber, rad (0 when absent).
    pub camber: Vec<f64>,
    /// Inflation pressure, Pa (if measured).
    pub pressure: Option<Vec<f64>>,
    /// Rig speed, m/s (if measured).
    pub speed: Option<Vec<f64>>,
    /// Longitudinal slip ratio and force (if a longitudinal test).
    pub longitudinal: Option<(Vec<f64>, Vec<f64>)>,
}

impl RigData {
    /// Number of samples.
    pub fn len(&self) -> usize {
        self.fz.len()
    }
    /// True without samples.
    pub fn is_empty(&self) -> bool {
        self.fz.is_empty()
    }
}

/// Reads rig data: lateral (`alpha`, `fy`) and/or longitudinal (`kappa`,
/// `fx`) sweeps; a file with neither pair is refused.
pub fn read_rig(path: &Path) -> Result<RigData, InputError> {
    let mut c = read_columns(
        path,
        &["fz"],
        &[
            "alpha", "fy", "mz", "camber", "pressure", "speed", "kappa", "fx",
        ],
    )?;
    let fz = c.take("fz");
    for (i, v) in fz.iter().enumerate() {
        if *v < 0.0 {
            return Err(c.error_at(
                path,
                i,
                "fz",
                format!("column `fz`: {v} N is negative (loads are positive in FORMATS.md)"),
            ));
        }
    }
    let n = fz.len();
    let lateral = match (c.take_optional("alpha"), c.take_optional("fy")) {
        (Some(a), Some(f)) => Some((a, f)),
        _ => None,
    };
    let longitudinal = match (c.take_optional("kappa"), c.take_optional("fx")) {
        (Some(k), Some(f)) => Some((k, f)),
        _ => None,
    };
    if lateral.is_none() && longitudinal.is_none() {
        return Err(InputError::File {
            path: path.to_path_buf(),
            message: "no lateral data (columns `alpha` and `fy`) and no longitudinal data (`kappa` and `fx`)".into(),
        });
    }
    let (alpha, fy) = lateral.unwrap_or_else(|| (vec![0.0; n], vec![f64::NAN; n]));
    Ok(RigData {
        camber: c.take_optional("camber").unwrap_or_else(|| vec![0.0; n]),
        mz: c.take_optional("mz"),
        pressure: c.take_optional("pressure"),
        speed: c.take_optional("speed"),
        longitudinal,
        fz,
        alpha,
        fy,
    })
}

/// Reads rig data and refuses a file without lateral data.
pub fn read_lateral(path: &Path) -> Result<RigData, InputError> {
    let d = read_rig(path)?;
    if d.fy.iter().all(|v| v.is_nan()) {
        return Err(InputError::File {
            path: path.to_path_buf(),
            message: "no lateral data: a lateral fit needs the columns `alpha` and `fy`".into(),
        });
    }
    Ok(d)
}

impl RigData {
    /// Whether lateral force was measured.
    pub fn has_lateral(&self) -> bool {
        self.fy.iter().any(|v| v.is_finite())
    }

    /// The longitudinal sweeps as rig data whose slip column holds κ and
    /// force column Fx, so the same grouping and thinning apply.
    pub fn longitudinal_view(&self) -> Option<RigData> {
        let (k, fx) = self.longitudinal.as_ref()?;
        Some(RigData {
            alpha: k.clone(),
            fy: fx.clone(),
            mz: None,
            longitudinal: None,
            ..self.clone()
        })
    }
}

/// A level of a grouping variable: [lo, hi] and its nominal value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Level {
    /// Lower edge.
    pub lo: f64,
    /// Upper edge.
    pub hi: f64,
    /// Median of the samples in it.
    pub nominal: f64,
}

/// Levels of `values` from a histogram of bin width `bin`.
pub fn levels(values: &[f64], bin: f64) -> Vec<Level> {
    let (min, max) = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    if !min.is_finite() {
        return Vec::new();
    }
    let nb = (((max - min) / bin).floor() as usize + 1).min(100_000);
    let mut counts = vec![0usize; nb];
    for v in values {
        counts[(((v - min) / bin) as usize).min(nb - 1)] += 1;
    }
    let keep = (values.len() / 100).max(1);
    let mut out = Vec::new();
    let mut i = 0;
    while i < nb {
        if counts[i] < keep {
            i += 1;
            continue;
        }
        let mut j = i;
        while j + 1 < nb && counts[j + 1] >= keep {
            j += 1;
        }
        let (lo, hi) = (min + i as f64 * bin, min + (j + 1) as f64 * bin);
        let mut inside: Vec<f64> = values
            .iter()
            .copied()
            .filter(|v| *v >= lo && *v <= hi)
            .collect();
        inside.sort_by(f64::total_cmp);
        out.push(Level {
            lo,
            hi,
            nominal: inside[inside.len() / 2],
        });
        i = j + 1;
    }
    out
}

/// One fit point: slip angle (rad), load (N), camber (rad), speed (m/s),
/// lateral force (N), aligning moment (N·m, NaN when not measured).
pub type Point = [f64; 6];

/// One test condition and the points of it used in the fit.
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    /// Nominal load, N.
    pub fz: f64,
    /// Nominal camber, rad.
    pub camber: f64,
    /// Nominal pressure, Pa (if measured).
    pub pressure: Option<f64>,
    /// Raw samples in it.
    pub samples: usize,
    /// Fit points (thinned).
    pub points: Vec<Point>,
}

/// Grouping and thinning settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grouping {
    /// Load histogram bin, N.
    pub load_bin: f64,
    /// Camber histogram bin, rad.
    pub camber_bin: f64,
    /// Pressure histogram bin, Pa.
    pub pressure_bin: f64,
    /// Slip-angle bin for thinning, rad (0: no thinning).
    pub alpha_bin: f64,
    /// Keep only this pressure level (nearest nominal), Pa.
    pub pressure: Option<f64>,
    /// Keep only this camber level (nearest nominal), rad.
    pub camber: Option<f64>,
    /// Speed when the data has none, m/s.
    pub default_speed: f64,
}

impl Default for Grouping {
    fn default() -> Self {
        Self {
            load_bin: 100.0,
            camber_bin: 0.25f64.to_radians(),
            pressure_bin: 2000.0,
            alpha_bin: 0.25f64.to_radians(),
            pressure: None,
            camber: None,
            default_speed: 10.0,
        }
    }
}

fn nearest(levels: &[Level], want: Option<f64>) -> Option<usize> {
    let w = want?;
    (0..levels.len()).min_by(|a, b| {
        (levels[*a].nominal - w)
            .abs()
            .total_cmp(&(levels[*b].nominal - w).abs())
    })
}

fn find(levels: &[Level], v: f64) -> Option<usize> {
    levels.iter().position(|l| v >= l.lo && v <= l.hi)
}

/// Groups the samples into conditions and thins each.
pub fn group(d: &RigData, g: &Grouping) -> Vec<Condition> {
    let loads = levels(&d.fz, g.load_bin);
    let cambers = levels(&d.camber, g.camber_bin);
    let pressures = d.pressure.as_ref().map(|p| levels(p, g.pressure_bin));
    let want_p = pressures.as_ref().and_then(|p| nearest(p, g.pressure));
    let want_c = nearest(&cambers, g.camber);
    let mut out: Vec<(usize, usize, Option<usize>, Vec<usize>)> = Vec::new();
    for i in 0..d.len() {
        let (Some(l), Some(c)) = (find(&loads, d.fz[i]), find(&cambers, d.camber[i])) else {
            continue;
        };
        let p = match (&pressures, &d.pressure) {
            (Some(levels), Some(p)) => match find(levels, p[i]) {
                Some(k) => Some(k),
                None => continue,
            },
            _ => None,
        };
        if want_c.is_some_and(|w| w != c) || (want_p.is_some() && p != want_p) {
            continue;
        }
        match out.iter_mut().find(|e| e.0 == l && e.1 == c && e.2 == p) {
            Some(e) => e.3.push(i),
            None => out.push((l, c, p, vec![i])),
        }
    }
    out.sort_by_key(|a| (a.2, a.1, a.0));
    out.into_iter()
        .map(|(l, c, p, idx)| {
            let speed = |i: usize| d.speed.as_ref().map_or(g.default_speed, |s| s[i]);
            let mz = |i: usize| d.mz.as_ref().map_or(f64::NAN, |m| m[i]);
            let point = |i: usize| [d.alpha[i], d.fz[i], d.camber[i], speed(i), d.fy[i], mz(i)];
            let points: Vec<Point> = if g.alpha_bin > 0.0 {
                let mut bins: std::collections::BTreeMap<i64, (Point, usize)> = Default::default();
                for &i in &idx {
                    let e = bins
                        .entry((d.alpha[i] / g.alpha_bin).round() as i64)
                        .or_insert(([0.0; 6], 0));
                    for (acc, v) in e.0.iter_mut().zip(point(i)) {
                        *acc += v;
                    }
                    e.1 += 1;
                }
                bins.into_values()
                    .filter(|(_, n)| *n >= 3)
                    .map(|(s, n)| s.map(|v| v / n as f64))
                    .collect()
            } else {
                idx.iter().map(|&i| point(i)).collect()
            };
            Condition {
                fz: loads[l].nominal,
                camber: cambers[c].nominal,
                pressure: p.and_then(|k| pressures.as_ref().map(|ps| ps[k].nominal)),
                samples: idx.len(),
                points,
            }
        })
        .collect()
}

/// Seed 000's test points generated from a known tyre: loads 2800 / 5700 /
/// 8600 N, slip angles 0 … ±12.0321° in 0.2865° steps (85 per load), camber
/// 0, 10 m/s, with multiplicative Gaussian noise of relative size `noise`
/// (seeded) on the lateral force and the aligning moment. Returns the
/// conditions and the lateral-force noise's own σ (%), the floor a fit
/// cannot beat on average.
pub fn seed000_conditions(
    truth: &crate::tyre::Tyre,
    noise: f64,
    seed: u64,
) -> (Vec<Condition>, f64) {
    use crate::tyre::{SlipState, TyreModel};
    use rand::SeedableRng;
    // Separate streams for Fy and Mz noise, so adding one channel does not
    // change the other's draws.
    let mut rng_fy = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let mut rng_mz = rand_chacha::ChaCha8Rng::seed_from_u64(seed ^ 0x9E37_79B9_7F4A_7C15);
    let (mut e2, mut y2) = (0.0, 0.0);
    let conditions = [2800.0, 5700.0, 8600.0]
        .iter()
        .map(|&fz| {
            let points: Vec<Point> = (-42..=42)
                .map(|i| {
                    let alpha = (0.2865 * i as f64).to_radians();
                    let f = truth.forces(&SlipState {
                        speed: 10.0,
                        ..SlipState::lateral(alpha, fz)
                    });
                    let noisy = f.fy * (1.0 + noise * gauss(&mut rng_fy));
                    let noisy_mz = f.mz * (1.0 + noise * gauss(&mut rng_mz));
                    e2 += (noisy - f.fy) * (noisy - f.fy);
                    y2 += noisy * noisy;
                    [alpha, fz, 0.0, 10.0, noisy, noisy_mz]
                })
                .collect();
            Condition {
                fz,
                camber: 0.0,
                pressure: None,
                samples: points.len(),
                points,
            }
        })
        .collect();
    (conditions, 100.0 * (e2 / y2).sqrt())
}

/// A standard normal draw (Box–Muller) from a seeded stream.
pub fn gauss(rng: &mut rand_chacha::ChaCha8Rng) -> f64 {
    use rand::RngExt;
    let (u1, u2): (f64, f64) = (rng.random::<f64>().max(1e-300), rng.random());
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}
