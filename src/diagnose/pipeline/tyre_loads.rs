//! Whether the base tyre is used at loads it was not fitted at: the car's
//! static wheel loads against the tyre's load range, one rule whichever
//! way the tyre is given ([`loads_short`]). The range is the rig data's
//! wheel loads where the tyre is fitted to the campaign's rig data, a TOML
//! tyre file's `[fitted_ranges] fz` (`identify` writes it) or a `.tir`'s
//! `FZMIN`–`FZMAX`; a file that states none (a hand-written TOML tyre, a
//! `.tir` without either key) is judged against nothing and gets no note.
//! The note stands before the verdict: a formula-student tyre (fitted at
//! 414–2887 N) under a 1530 kg sedan (2995–4507 N) gave a verdict with no
//! word of it when given as a file, where the same tyre given as rig data
//! was noted (round 50). Units: N.

use crate::diagnose::campaign::{BaseTyres, Campaign, TyreFile};
use crate::diagnose::report::outcome::{LoadRangeOf, TyreAxles};
use crate::diagnose::report::Note;
use crate::tyre::Tyre;

/// How far beyond a tyre's load range a static wheel load may lie before
/// the tyre is said to be used outside it: a level's spread and a tyre's
/// smooth load law carry a tenth beyond the data without a change of
/// shape.
pub(crate) const LOAD_SLACK: f64 = 1.1;

/// The note where the car's static wheel loads `car` (least, largest, N)
/// leave the tyre's load range `loads` (N; a lower end of 0 or an upper
/// end unbounded is no end) by more than [`LOAD_SLACK`].
pub(crate) fn loads_short(of: LoadRangeOf, loads: [f64; 2], car: [f64; 2]) -> Option<Note> {
    let [lo, hi] = loads;
    let above = hi.is_finite() && car[1] > hi * LOAD_SLACK;
    let below = lo > 0.0 && car[0] * LOAD_SLACK < lo;
    (above || below).then_some(Note::TyreLoadsShort { of, loads, car })
}

/// The load range a given tyre file states: a TOML tyre's
/// `[fitted_ranges] fz`, a `.tir`'s `FZMIN`–`FZMAX` (0 where it has no
/// `FZMIN`, unbounded where it has no `FZMAX`), with where it comes from.
fn file_loads(tyre: &Tyre, file: &TyreFile, axles: TyreAxles) -> Option<(LoadRangeOf, [f64; 2])> {
    let name = file.path.display().to_string();
    if let Tyre::MagicFormula(t) = tyre {
        let l = &t.limits;
        let range = [l.fz_min.unwrap_or(0.0), l.fz_max.unwrap_or(f64::INFINITY)];
        let of = LoadRangeOf::Tir {
            file: name,
            axles,
            limit_checks: t.mode().limit_checks,
        };
        return (l.fz_min.is_some() || l.fz_max.is_some()).then_some((of, range));
    }
    let fz = file.fitted_loads?;
    Some((LoadRangeOf::Fitted { file: name, axles }, fz))
}

/// The notes of the campaign's given tyre files whose stated load ranges
/// the car's static wheel loads leave: one per file (a file on both axles
/// is judged at both axles' loads).
pub(crate) fn given_loads_short(c: &Campaign) -> Vec<Note> {
    let BaseTyres::Given(f, r, files) = &c.tyres else {
        return Vec::new();
    };
    let (front, rear) = c.vehicle.static_axle_loads();
    let (front, rear) = (0.5 * front, 0.5 * rear);
    let [ff, rf] = &**files;
    let on = if ff.path == rf.path {
        vec![(
            &**f,
            ff,
            TyreAxles::Both,
            [front.min(rear), front.max(rear)],
        )]
    } else {
        vec![
            (&**f, ff, TyreAxles::Front, [front, front]),
            (&**r, rf, TyreAxles::Rear, [rear, rear]),
        ]
    };
    on.into_iter()
        .filter_map(|(tyre, file, axles, car)| {
            let (of, loads) = file_loads(tyre, file, axles)?;
            loads_short(of, loads, car)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loads_a_tenth_beyond_either_end_are_noted_and_within_it_not() {
        let of = || LoadRangeOf::Rig;
        let range = [2000.0, 6000.0];
        assert_eq!(loads_short(of(), range, [2995.0, 4507.0]), None);
        assert_eq!(loads_short(of(), range, [2995.0, 6000.0 * 1.09]), None);
        assert!(loads_short(of(), range, [2995.0, 6000.0 * 1.11]).is_some());
        assert_eq!(loads_short(of(), range, [2000.0 / 1.09, 4000.0]), None);
        assert!(loads_short(of(), range, [2000.0 / 1.11, 4000.0]).is_some());
    }

    #[test]
    fn an_end_not_stated_is_no_end() {
        let of = || LoadRangeOf::Rig;
        // A `.tir` with FZMAX alone: any light load is within it.
        assert_eq!(loads_short(of(), [0.0, 6000.0], [10.0, 4507.0]), None);
        // With FZMIN alone: any heavy load is.
        assert_eq!(
            loads_short(of(), [1000.0, f64::INFINITY], [2995.0, 9e9]),
            None
        );
        assert!(loads_short(of(), [4000.0, f64::INFINITY], [2995.0, 9e9]).is_some());
    }
}
