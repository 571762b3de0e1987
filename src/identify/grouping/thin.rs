//! Thinning of one condition's samples along its slip axis into fit
//! points: the samples that fall into one slip bin (`alpha_bin` for slip
//! angle, `kappa_bin` for slip ratio) are averaged, a bin with one sample
//! keeps it, so no slip point is ever lost; up and down sweeps through the
//! same bin average their hysteresis. A bin below the resolution of the
//! data's doubles thins nothing ([`resolved_bin`]).
//! Units: N, N·m, rad, Pa, m/s; slip ratio dimensionless.

use crate::identify::data::{RigData, RigPoint, SlipAxis};

/// The slip and force columns of the sweep along `axis`, and the aligning
/// moment (cornering only).
pub(super) struct SweepColumns<'a> {
    axis: SlipAxis,
    pub(super) slip: &'a [f64],
    force: &'a [f64],
    mz: Option<&'a [f64]>,
}

impl<'a> SweepColumns<'a> {
    pub(super) fn of(d: &'a RigData, axis: SlipAxis) -> Option<Self> {
        Some(match axis {
            SlipAxis::Angle => Self {
                axis,
                slip: &d.alpha,
                force: &d.fy,
                mz: d.mz.as_deref(),
            },
            SlipAxis::Ratio => {
                let (kappa, fx) = d.longitudinal.as_ref()?;
                Self {
                    axis,
                    slip: kappa,
                    force: fx,
                    mz: None,
                }
            }
        })
    }
}

/// The largest bin number a slip's bin may reach for the bins to be
/// resolved: 2⁵², beyond which a double's integers are its values.
const RESOLVED_BINS: f64 = 4_503_599_627_370_496.0;

/// The bin the samples are thinned by for a bin `asked` on the slips
/// `slip`, and whether `asked` is below their resolution. A bin so fine
/// that a slip's bin number passes 2⁵² is below the resolution of the
/// data's doubles: every sample is a bin of its own there, and the numbers
/// would saturate an integer and merge the curve into a few points. It
/// keeps every sample (bin 0).
pub(super) fn resolved_bin(asked: f64, slip: &[f64]) -> (f64, bool) {
    let below_resolution = asked > 0.0 && slip.iter().any(|v| (v / asked).abs() >= RESOLVED_BINS);
    (if below_resolution { 0.0 } else { asked }, below_resolution)
}

/// The fit points of the samples `idx` on the sweep `s`: the mean of the
/// samples in each slip bin of width `bin` (each sample its own point when
/// `bin` is 0). A bin with one sample keeps it as it is.
pub(super) fn thin(
    d: &RigData,
    s: &SweepColumns,
    idx: &[usize],
    bin: f64,
    default_speed: f64,
) -> Vec<RigPoint> {
    let speed = |i: usize| d.speed.as_ref().map_or(default_speed, |v| v[i]);
    let mz = |i: usize| s.mz.map_or(f64::NAN, |m| m[i]);
    // A sample's values in a fixed order (slip, load, camber, speed, force,
    // moment) so that a bin's means are sums over the same samples in
    // recording order.
    let values = |i: usize| [s.slip[i], d.fz[i], d.camber[i], speed(i), s.force[i], mz(i)];
    let point = |[slip, fz, camber, speed, force, mz]: [f64; 6]| match s.axis {
        SlipAxis::Angle => RigPoint::lateral(slip, fz, camber, speed, force, mz),
        SlipAxis::Ratio => RigPoint::longitudinal(slip, fz, camber, speed, force),
    };
    if bin <= 0.0 {
        return idx.iter().map(|&i| point(values(i))).collect();
    }
    let mut bins: std::collections::BTreeMap<i64, ([f64; 6], usize)> = Default::default();
    for &i in idx {
        let e = bins
            .entry((s.slip[i] / bin).round() as i64)
            .or_insert(([0.0; 6], 0));
        for (acc, v) in e.0.iter_mut().zip(values(i)) {
            *acc += v;
        }
        e.1 += 1;
    }
    bins.into_values()
        .map(|(sum, n)| point(sum.map(|v| v / n as f64)))
        .collect()
}
