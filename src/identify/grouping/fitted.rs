//! The nominal load, camber and pressure of a condition: the median of the
//! samples fitted at its level, not of every sample of the level in the
//! file. A level selected with `--load` holds the samples of every camber
//! and pressure in the file; those fitted are only its part at the camber
//! and pressure selected (on the Hoosier file, the 1656 N level's 1249
//! samples at 0° and 83.4 kPa have a median of 1640 N). The tyre file's
//! reference load is this nominal, so the same samples give the same
//! tyre, read from the whole file or from a file of them alone. The
//! conditions at one level still share its nominal: a model's count of
//! load levels is of levels, not of conditions.
//! Units: the variable's own (N, rad, Pa).

use super::own_scale::median;
use super::RigData;

/// A condition's (load, camber, pressure) level indices; no pressure
/// index in a file without the column.
pub(super) type Key = (usize, usize, Option<usize>);

/// The nominals of the levels, by level index, from the samples fitted.
pub(super) struct Nominals {
    load: Vec<f64>,
    camber: Vec<f64>,
    pressure: Vec<f64>,
}

impl Nominals {
    /// The medians of `d`'s load, camber and pressure over the samples of
    /// `groups` (each condition's key and sample indices) at each level.
    pub(super) fn of(d: &RigData, groups: &[(Key, Vec<usize>)]) -> Self {
        let of = |values: &[f64], level: fn(&Key) -> Option<usize>| {
            let count = groups
                .iter()
                .filter_map(|g| level(&g.0))
                .max()
                .map_or(0, |k| k + 1);
            (0..count)
                .map(|k| {
                    let mut v: Vec<f64> = groups
                        .iter()
                        .filter(|g| level(&g.0) == Some(k))
                        .flat_map(|g| g.1.iter().map(|&i| values[i]))
                        .collect();
                    v.sort_by(f64::total_cmp);
                    // A level no condition holds is never asked for.
                    if v.is_empty() {
                        f64::NAN
                    } else {
                        median(&v)
                    }
                })
                .collect()
        };
        Self {
            load: of(&d.fz, |k| Some(k.0)),
            camber: of(&d.camber, |k| Some(k.1)),
            pressure: d
                .pressure
                .as_ref()
                .map_or_else(Vec::new, |p| of(p, |k| k.2)),
        }
    }

    /// The nominal load, camber and pressure of the condition at `key`.
    pub(super) fn at(&self, key: Key) -> (f64, f64, Option<f64>) {
        let (l, c, p) = key;
        (
            self.load[l],
            self.camber[c],
            p.and_then(|k| self.pressure.get(k).copied()),
        )
    }
}
