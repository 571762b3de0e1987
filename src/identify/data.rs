//! Tyre rig data (`docs/FORMATS.md`): reading and checking a rig file, and
//! test points generated from a known tyre at the identification papers'
//! conditions. Grouping into test conditions is in [`super::grouping`].
//! Units: N, rad, Pa, m/s.

use crate::error::InputError;
use crate::io::read_columns;
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};
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
    /// Whether the file has a `camber` column.
    pub camber_measured: bool,
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
    let camber = c.take_optional("camber");
    // Angles in degrees are the commonest slip of a hand-made file: a slip
    // angle past ±90° or a camber past ±45° is not a tyre test in radians.
    let angles = [
        ("alpha", lateral.as_ref().map(|l| &l.0), FRAC_PI_2),
        ("camber", camber.as_ref(), FRAC_PI_4),
    ];
    for (name, values, limit) in angles {
        let Some(values) = values else { continue };
        if let Some(i) = values.iter().position(|v| v.abs() > limit) {
            return Err(c.error_at(
                path,
                i,
                name,
                format!(
                    "column `{name}`: {} rad is beyond ±{:.0}°: angles are in radians (FORMATS.md); is the column in degrees?",
                    values[i],
                    limit.to_degrees()
                ),
            ));
        }
    }
    let (alpha, fy) = lateral.unwrap_or_else(|| (vec![0.0; n], vec![f64::NAN; n]));
    Ok(RigData {
        camber_measured: camber.is_some(),
        camber: camber.unwrap_or_else(|| vec![0.0; n]),
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

/// One fit point: slip angle (rad), load (N), camber (rad), speed (m/s),
/// lateral force (N), aligning moment (N·m, NaN when not measured).
pub type Point = [f64; 6];

pub use super::grouping::Condition;

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
