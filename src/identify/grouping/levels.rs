//! Levels of a grouping variable of rig data (load, camber, pressure): the
//! values a rig held, found from the gaps between the sorted samples and
//! split at density valleys so that ramps between levels do not join them,
//! and only at valleys that separate levels, not inside one level's
//! scatter (`own_scale.rs`; the method is described in [`super`]). Units:
//! the variable's own (N, rad, Pa).

use super::own_scale::{median, split_own_scale};
pub use crate::error::Variable;
use serde::Serialize;

/// A level of a grouping variable.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Level {
    /// Smallest value in it.
    pub lo: f64,
    /// Largest value in it.
    pub hi: f64,
    /// Median of its samples: the level's nominal value (a condition's is
    /// of the samples fitted there, `fitted.rs`).
    pub nominal: f64,
    /// Samples in it.
    pub samples: usize,
}

impl Level {
    /// Whether `v` lies in the level's range of samples.
    pub fn holds(&self, v: f64) -> bool {
        v >= self.lo && v <= self.hi
    }
}

/// The levels of one variable and what did not belong to any.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Levels {
    /// The variable.
    pub variable: Variable,
    /// Gap that separates two levels (the threshold used), in the
    /// variable's unit.
    pub separation: f64,
    /// Noise of the variable estimated from consecutive samples.
    pub noise: f64,
    /// The levels, ascending.
    pub levels: Vec<Level>,
    /// Samples between levels (ramps, isolated values), dropped.
    pub transition_samples: usize,
}

impl Levels {
    /// The level holding `v`.
    pub(super) fn find(&self, v: f64) -> Option<usize> {
        self.levels.iter().position(|l| l.holds(v))
    }
    /// The level a requested value selects: the one whose band (its range
    /// widened by the separation) holds it, nearest nominal first.
    pub(super) fn select(&self, want: f64) -> Option<usize> {
        (0..self.levels.len())
            .filter(|&k| {
                let l = &self.levels[k];
                want >= l.lo - self.separation && want <= l.hi + self.separation
            })
            .min_by(|a, b| {
                (self.levels[*a].nominal - want)
                    .abs()
                    .total_cmp(&(self.levels[*b].nominal - want).abs())
            })
    }

    /// The request `want` read in another unit people write the variable
    /// in ([`crate::error::unit_slips`]), where it then selects a level;
    /// `None` for a request inside the span of the levels: one between two
    /// of them (3°, in rad, between levels at 1.6° and 3.2°) is in the
    /// right unit and merely has no level, and its conversion (3° read as
    /// 3 rad, or as 0.05° near a level at 0) would point the wrong way.
    pub(super) fn unit_slip(&self, want: f64) -> Option<crate::error::LevelSlip> {
        let (lo, hi) = (self.levels.first()?.lo, self.levels.last()?.hi);
        if (lo - self.separation..=hi + self.separation).contains(&want) {
            return None;
        }
        let slips = crate::error::unit_slips(self.variable);
        let (small, large) = (lo.abs().min(hi.abs()), lo.abs().max(hi.abs()));
        let selecting = slips.iter().find_map(|&(unit, factor)| {
            // A value typed in a smaller unit (degrees for rad) reads
            // larger than the levels, one in a larger unit (kN for N)
            // smaller: a request the other way is no slip of that unit (a
            // camber of −0.0279 rad, the sign slipped, is not −0.0279°).
            let slipped = if factor < 1.0 {
                want.abs() > large
            } else {
                want.abs() < small
            };
            if !slipped {
                return None;
            }
            let meant = want * factor;
            let k = self.select(meant)?;
            Some(crate::error::LevelSlip {
                meant,
                unit,
                level: Some(self.levels[k].nominal),
            })
        });
        // A request no test has in SI: its likeliest unit, though it
        // selects no level (`--camber 2`: 2°, between levels); so is a
        // camber past 20° on a file whose levels all lie within 20°
        // (`--camber 0.5`, 28.6°, beside levels at 0° to 3.2°); a pressure
        // in the first unit that makes it a pneumatic tyre's, as
        // `tyre-eval` reads a point's (2.6 is 2.6 bar, not 2.6 kPa).
        let [least, most] = crate::error::INFLATION_PRESSURES;
        let inflated = |&(_, f): &(&str, f64)| (least..=most).contains(&(want * f));
        let (unit, factor) = match self.variable {
            Variable::Pressure => slips.iter().copied().find(inflated),
            _ => None,
        }
        .unwrap_or(slips[0]);
        let steep =
            self.variable == Variable::Camber && want.abs() > FAR_CAMBER && large < FAR_CAMBER;
        selecting.or_else(|| {
            (self.variable.implausible(want) || steep).then_some(crate::error::LevelSlip {
                meant: want * factor,
                unit,
                level: None,
            })
        })
    }

    /// The nominal of the level a value measured from this variable's
    /// samples (a mean of thinned rows) belongs to ([`Levels::select`]),
    /// or the value itself outside every band: what the terminal names
    /// that level, so that a figure or a line on the fit names it alike.
    pub fn named(&self, v: f64) -> f64 {
        self.nominal_of(v).unwrap_or(v)
    }

    /// The nominal of the level whose band holds `v` ([`Levels::select`]),
    /// `None` outside every band.
    pub fn nominal_of(&self, v: f64) -> Option<f64> {
        self.select(v).map(|k| self.levels[k].nominal)
    }
}

/// The fewest samples at one value that make a level.
pub const LEVEL_SAMPLES: usize = 3;

/// A camber past which a request, on a file whose levels all lie within
/// it, reads as degrees typed for rad, rad (20°): car and truck rigs test
/// within ±10° (the Hoosier file 0° to 3.2°), while a motorcycle file
/// whose levels reach past it takes such a request as it is.
const FAR_CAMBER: f64 = 0.35;

/// The groups of values of one variable too few to be a level (fewer than
/// [`LEVEL_SAMPLES`] apart from the rest), each as its range (lo, hi):
/// their samples are among [`Levels::transition_samples`], and two rows
/// at one load are no ramp between levels but too few for one.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TooFew(Vec<(f64, f64)>);

impl TooFew {
    /// Whether `v` lies in one of the groups.
    pub fn holds(&self, v: f64) -> bool {
        self.0.iter().any(|&(lo, hi)| v >= lo && v <= hi)
    }
}

/// The levels of `values` (in recording order) of `variable`; `resolution`
/// is the smallest separation that counts as a different level.
pub fn levels(variable: Variable, values: &[f64], resolution: f64) -> Levels {
    levels_and_too_few(variable, values, resolution).0
}

/// [`levels`], with the groups of values too few to be a level.
pub fn levels_and_too_few(variable: Variable, values: &[f64], resolution: f64) -> (Levels, TooFew) {
    let mut diffs: Vec<f64> = values.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    diffs.sort_by(f64::total_cmp);
    // For Gaussian noise, |x_{i+1} − x_i| has median 0.6745·√2·σ.
    let in_order = if diffs.is_empty() {
        0.0
    } else {
        median(&diffs) / (0.6745 * std::f64::consts::SQRT_2)
    };
    let mut sorted: Vec<f64> = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    // Rows not recorded level by level (a table flattened slip angle by slip
    // angle, shuffled rows) make neighbours differ by whole level steps: the
    // spread inside groups split at `resolution` bounds the noise then.
    let noise = in_order.min(spread_within(&sorted, resolution));
    let separation = resolution.max(6.0 * noise);
    let mut out = Levels {
        variable,
        separation,
        noise,
        levels: Vec::new(),
        transition_samples: 0,
    };
    let mut too_few = TooFew::default();
    let mut start = 0;
    for i in 1..=sorted.len() {
        if i == sorted.len() || sorted[i] - sorted[i - 1] > separation {
            let mut into = Found {
                levels: &mut out,
                too_few: &mut too_few,
            };
            split_valleys(&sorted[start..i], separation, resolution, &mut into);
            start = i;
        }
    }
    (out, too_few)
}

/// Where [`split_valleys`] records what it finds.
struct Found<'a> {
    levels: &'a mut Levels,
    too_few: &'a mut TooFew,
}

/// Robust deviation (1.4826·MAD) of the values about the median of their
/// group, the sorted values split wherever consecutive ones are more than
/// `resolution` apart.
fn spread_within(sorted: &[f64], resolution: f64) -> f64 {
    let mut dev = Vec::with_capacity(sorted.len());
    let mut start = 0;
    for i in 1..=sorted.len() {
        if i == sorted.len() || sorted[i] - sorted[i - 1] > resolution {
            let m = median(&sorted[start..i]);
            dev.extend(sorted[start..i].iter().map(|v| (v - m).abs()));
            start = i;
        }
    }
    if dev.is_empty() {
        return 0.0;
    }
    dev.sort_by(f64::total_cmp);
    1.4826 * median(&dev)
}

/// Splits one gap-separated group at density valleys and records its levels.
fn split_valleys(group: &[f64], separation: f64, resolution: f64, out: &mut Found) {
    let (lo, hi) = (group[0], group[group.len() - 1]);
    if hi - lo <= 8.0 * separation {
        push_own_scale(group, resolution, out);
        return;
    }
    let nb = ((hi - lo) / separation).ceil() as usize;
    let bin = |v: f64| (((v - lo) / separation) as usize).min(nb - 1);
    let mut counts = vec![0usize; nb];
    for &v in group {
        counts[bin(v)] += 1;
    }
    let keep = (group.len() / 100).max(3);
    let mut i = 0;
    while i < group.len() {
        if counts[bin(group[i])] < keep {
            out.levels.transition_samples += 1;
            i += 1;
            continue;
        }
        let mut j = i;
        while j < group.len() && counts[bin(group[j])] >= keep {
            j += 1;
        }
        // Bins a separation wide see no valley narrower than one: the
        // part is looked at on its own scale too (the Hoosier file kept
        // every 8th row from its 4th split its lightest load off here and
        // kept the other four as one).
        push_own_scale(&group[i..j], resolution, out);
        i = j;
    }
}

/// Records the levels of `part` split on its own scale
/// ([`split_own_scale`]): a rig's load varies with slip along a sweep by
/// ±150 N, and a file keeping every fourth row makes consecutive samples
/// differ by that much, so the noise read from them (53 N for the Hoosier
/// file, 16 N at full rate) sets a separation that joins its five loads
/// 560 N apart into one group. A part of fewer than three samples is ramp
/// or isolated samples, counted as transitions.
fn push_own_scale(part: &[f64], resolution: f64, out: &mut Found) {
    let ranges = split_own_scale(part, resolution, out.levels.noise);
    let kept: usize = ranges.iter().map(|r| r.len()).sum();
    out.levels.transition_samples += part.len() - kept;
    for r in ranges {
        let level = &part[r];
        if level.len() < LEVEL_SAMPLES {
            out.levels.transition_samples += level.len();
            out.too_few.0.push((level[0], level[level.len() - 1]));
        } else {
            out.levels.levels.push(Level {
                lo: level[0],
                hi: level[level.len() - 1],
                nominal: median(level),
                samples: level.len(),
            });
        }
    }
}

#[cfg(test)]
#[path = "levels_noise_tests.rs"]
mod noise_tests;

#[cfg(test)]
mod tests {
    use crate::identify::grouping::levels::*;

    fn nominals(l: &Levels) -> Vec<f64> {
        l.levels.iter().map(|q| q.nominal).collect()
    }

    #[test]
    fn exact_levels_one_sample_per_slip_point_are_each_a_level() {
        let v: Vec<f64> = [2800.0, 5700.0, 8600.0]
            .iter()
            .flat_map(|f| std::iter::repeat_n(*f, 85))
            .collect();
        let l = levels(Variable::Load, &v, 10.0);
        assert_eq!(nominals(&l), vec![2800.0, 5700.0, 8600.0]);
        assert_eq!(l.transition_samples, 0);
    }

    #[test]
    fn levels_interleaved_row_by_row_stay_apart() {
        // The papers' table flattened one slip angle at a time: every row
        // changes load, so neighbours differ by whole level steps.
        let v: Vec<f64> = (0..85).flat_map(|_| [2800.0, 5700.0, 8600.0]).collect();
        let l = levels(Variable::Load, &v, 10.0);
        assert_eq!(nominals(&l), vec![2800.0, 5700.0, 8600.0]);
        assert_eq!(l.noise, 0.0);
    }

    #[test]
    fn close_noisy_levels_stay_apart_and_a_small_one_is_kept() {
        // Bicycle-tyre loads 50 N apart, ±3 N noise, and a fourth level with
        // 0.5 % of the samples.
        let mut rng = 1u64;
        let mut noise = || {
            rng = rng
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((rng >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 6.0
        };
        let mut v = Vec::new();
        for (f, n) in [(340.0, 1000), (390.0, 1000), (440.0, 1000), (490.0, 15)] {
            v.extend((0..n).map(|_| f + noise()));
        }
        let l = levels(Variable::Load, &v, 10.0);
        let got = nominals(&l);
        assert_eq!(got.len(), 4, "{got:?}");
        for (g, want) in got.iter().zip([340.0, 390.0, 440.0, 490.0]) {
            assert!((g - want).abs() < 1.0, "{got:?}");
        }
        assert_eq!(l.levels[3].samples, 15);
    }

    #[test]
    fn a_ramp_between_two_levels_is_a_transition_not_a_bridge() {
        // Two wandering levels (±150 N) joined by 40-sample ramps in
        // recording order.
        let mut v = Vec::new();
        for k in 0..3000 {
            v.push(1000.0 + 150.0 * (k as f64 * 0.01).sin());
        }
        for k in 0..40 {
            v.push(1150.0 + (2100.0 - 1150.0) * k as f64 / 40.0);
        }
        for k in 0..3000 {
            v.push(2200.0 + 150.0 * (k as f64 * 0.013).cos());
        }
        let l = levels(Variable::Load, &v, 10.0);
        assert_eq!(l.levels.len(), 2, "{:?}", l.levels);
        assert!((l.levels[0].nominal - 1000.0).abs() < 20.0);
        assert!((l.levels[1].nominal - 2200.0).abs() < 20.0);
        assert!(l.transition_samples > 0 && l.transition_samples <= 40);
        let accounted: usize =
            l.levels.iter().map(|q| q.samples).sum::<usize>() + l.transition_samples;
        assert_eq!(accounted, v.len());
    }

    /// A rig's sweep: five loads 560 N apart, each carried through slip
    /// sweeps that move it ±150 N (consecutive samples about 16 N apart, as
    /// on the Hoosier file), 40-sample ramps between them; then the same
    /// file keeping every 2nd to 16th row. Every rate finds the five loads
    /// (keeping every 4th merged them into one: its consecutive samples,
    /// about 60 N apart, read as noise).
    #[test]
    fn a_sweep_kept_every_few_rows_still_finds_its_loads() {
        let mut rng = 7u64;
        let mut noise = || {
            rng = rng
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((rng >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 20.0
        };
        let loads = [534.0, 1095.0, 1656.0, 2193.0, 2751.0];
        let mut v = Vec::new();
        for (k, f) in loads.iter().enumerate() {
            for i in 0..6000 {
                let sweep = (i as f64 * 0.15).sin();
                v.push(f + 150.0 * (sweep.abs() - std::f64::consts::FRAC_1_SQRT_2) + noise());
            }
            if let Some(next) = loads.get(k + 1) {
                v.extend((0..40).map(|i| f + (next - f) * f64::from(i) / 40.0));
            }
        }
        // From every row the thinning may start at: which rows are kept
        // decided it (every 8th from the 4th merged four loads).
        let thinned = [1, 2, 4, 8, 16]
            .into_iter()
            .flat_map(|every| (0..every).map(move |from| (every, from)));
        for (every, from) in thinned {
            let kept: Vec<f64> = v.iter().skip(from).step_by(every).copied().collect();
            let l = levels(Variable::Load, &kept, 10.0);
            let got = nominals(&l);
            let at = format!("every {every} from {from}: {got:?}");
            assert_eq!(got.len(), 5, "{at}");
            for (g, want) in got.iter().zip(loads) {
                assert!((g - want).abs() < 15.0, "{at}");
            }
            let accounted: usize =
                l.levels.iter().map(|q| q.samples).sum::<usize>() + l.transition_samples;
            assert_eq!(accounted, kept.len());
            // The ramps and the sparse tails of the levels, no more.
            assert!(
                l.transition_samples * 50 < kept.len(),
                "{at}: {}",
                l.transition_samples
            );
        }
    }

    /// A camber held at one level and logged in steps of 0.01°: the empty
    /// bins between its steps are narrower than the 0.1° resolution, so it
    /// stays one level (split on its own scale it read as −0.01° and 0.00°,
    /// or 1.58°, 1.59° and 1.60°); two levels 0.3° apart are two.
    #[test]
    fn a_quantised_level_is_not_split_at_its_steps() {
        let step = 0.01f64.to_radians();
        let one: Vec<f64> = (0..3000)
            .map(|i| step * f64::from([-2, -1, -1, 0, 0, 0, 0, 1, 1, 2][i % 10]))
            .collect();
        let l = levels(Variable::Camber, &one, 0.1f64.to_radians());
        assert_eq!(l.levels.len(), 1, "{:?}", l.levels);
        assert_eq!(l.transition_samples, 0);
        let two: Vec<f64> = (0..3000)
            .map(|i| one[i] + if i % 2 == 0 { 0.0 } else { 0.3f64.to_radians() })
            .collect();
        let l = levels(Variable::Camber, &two, 0.1f64.to_radians());
        assert_eq!(l.levels.len(), 2, "{:?}", l.levels);
    }
}
