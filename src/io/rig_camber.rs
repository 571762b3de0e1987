//! The camber thrust of a rig file near zero slip: the least-squares slope
//! of `fy/fz` against `camber`, fitted beside the slip angle
//! (`fy/fz = a·alpha + b·camber + c`), per rad of camber. It tells a
//! reversed `alpha` from reversed `fy` and `mz` ([`crate::error::Reversal`]):
//! both fix the two slopes against `alpha`, but only one leaves the camber
//! thrust pointing toward the lean, as a tyre's does (ISO 8855: a positive
//! inclination leans the wheel's top to the right, −y, and the tyre pushes
//! that way; 12 of the 13 public `.tir` files give `dFy/dγ` of −0.46 to
//! −2.0 times the load per rad at zero slip). Dividing by the load makes
//! the slope one number over sweeps at several loads (the thrust and the
//! offsets grow with the load).
//!
//! Units: N, rad; the slope is dimensionless per rad.

use crate::error::CamberSlope;

/// The least spread of cambers (rad, 0.5°) over which a camber slope is
/// fitted: below it the slope is an offset's noise.
const MIN_CAMBER_SPREAD: f64 = 0.008_726_646_259_971_648;

/// Samples needed below and above the middle of the cambers' spread.
const SAMPLES_PER_SIDE: usize = 5;

/// The camber slope of the samples `near` (indices near zero slip) of
/// `(alpha, fy)` at loads `fz` and cambers `camber`; `None` where fewer
/// than [`SAMPLES_PER_SIDE`] samples lie on each side of the middle of a
/// spread of at least [`MIN_CAMBER_SPREAD`], or the two regressors are
/// one (camber changed only with the slip angle).
pub(super) fn camber_slope(
    near: &[usize],
    (alpha, fy): (&[f64], &[f64]),
    fz: &[f64],
    camber: &[f64],
) -> Option<CamberSlope> {
    let rows: Vec<[f64; 3]> = near
        .iter()
        .filter(|&&i| fz[i] > 0.0)
        .map(|&i| [alpha[i], camber[i], fy[i] / fz[i]])
        .filter(|r| r.iter().all(|v| v.is_finite()))
        .collect();
    let (lo, hi) = rows
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), r| {
            (a.min(r[1]), b.max(r[1]))
        });
    let middle = 0.5 * (lo + hi);
    let below = rows.iter().filter(|r| r[1] < middle).count();
    let above = rows.iter().filter(|r| r[1] > middle).count();
    if hi - lo < MIN_CAMBER_SPREAD || below < SAMPLES_PER_SIDE || above < SAMPLES_PER_SIDE {
        return None;
    }
    let m = rows.len() as f64;
    let mean = |k: usize| rows.iter().map(|r| r[k]).sum::<f64>() / m;
    let (ma, mg, my) = (mean(0), mean(1), mean(2));
    let sum = |f: &dyn Fn(&[f64; 3]) -> f64| rows.iter().map(f).sum::<f64>();
    let saa = sum(&|r| (r[0] - ma).powi(2));
    let sgg = sum(&|r| (r[1] - mg).powi(2));
    let sag = sum(&|r| (r[0] - ma) * (r[1] - mg));
    let say = sum(&|r| (r[0] - ma) * (r[2] - my));
    let sgy = sum(&|r| (r[1] - mg) * (r[2] - my));
    let det = saa * sgg - sag * sag;
    // Camber in step with the slip angle: the two slopes are not apart.
    if det.is_nan() || det <= 1e-12 * saa * sgg {
        return None;
    }
    let a = (sgg * say - sag * sgy) / det;
    let b = (saa * sgy - sag * say) / det;
    let rss = sum(&|r| (r[2] - my - a * (r[0] - ma) - b * (r[1] - mg)).powi(2));
    let variance = rss / (m - 3.0);
    Some(CamberSlope {
        per_load: b,
        standard_error: (variance * saa / det).sqrt(),
        samples: rows.len(),
        range: (lo, hi),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `fy/fz = 15·α − 0.9·γ + 0.02` sampled at cambers −2°, 0, 2° and
    /// slips ±2°, with an alternating noise of ±0.001.
    fn samples(noise: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>) {
        let (mut a, mut f, mut z, mut g) = (vec![], vec![], vec![], vec![]);
        for (j, gamma) in [-2.0_f64, 0.0, 2.0].into_iter().enumerate() {
            for k in -8..=8 {
                let (alpha, gamma) = ((0.25 * f64::from(k)).to_radians(), gamma.to_radians());
                let fz = 3000.0 + 1000.0 * j as f64;
                let wiggle = if (k + j as i32) % 2 == 0 {
                    noise
                } else {
                    -noise
                };
                a.push(alpha);
                g.push(gamma);
                z.push(fz);
                f.push(fz * (15.0 * alpha - 0.9 * gamma + 0.02 + wiggle));
            }
        }
        (a, f, z, g)
    }

    #[test]
    fn a_known_camber_thrust_is_recovered_beside_the_slip_angle() {
        let (a, f, z, g) = samples(0.0);
        let near: Vec<usize> = (0..a.len()).collect();
        let s = camber_slope(&near, (&a, &f), &z, &g).unwrap();
        assert!((s.per_load + 0.9).abs() < 1e-9, "{s:?}");
        assert_eq!(s.samples, 51);
        assert!((s.range.1.to_degrees() - 2.0).abs() < 1e-12);
        // With noise the slope keeps its sign, many standard errors away.
        let (a, f, z, g) = samples(0.001);
        let s = camber_slope(&near, (&a, &f), &z, &g).unwrap();
        assert!((s.per_load + 0.9).abs() < 0.05, "{s:?}");
        assert!(s.per_load < -10.0 * s.standard_error, "{s:?}");
    }

    #[test]
    fn one_camber_or_a_camber_tied_to_the_slip_angle_gives_no_slope() {
        let (a, f, z, _) = samples(0.0);
        let near: Vec<usize> = (0..a.len()).collect();
        assert!(camber_slope(&near, (&a, &f), &z, &vec![0.0; a.len()]).is_none());
        // Camber a multiple of the slip angle: no telling the two apart.
        let tied: Vec<f64> = a.iter().map(|x| 0.5 * x).collect();
        assert!(camber_slope(&near, (&a, &f), &z, &tied).is_none());
    }
}
