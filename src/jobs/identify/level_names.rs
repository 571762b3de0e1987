//! The one name of each level of load, camber and pressure in every
//! output of `identify`: the terminal's grouping and condition lines, the
//! notes, the figures' titles and keys, the file's header. A level is
//! named by the median of every sample of it in the file
//! ([`Level::nominal`](crate::identify::grouping::Level)), spelt by
//! [`Variable::display`]: on the Hoosier cornering file 534, 1095, 1656,
//! 2193 and 2751 N. A condition's own value (the median of the samples
//! fitted there, which the tyre file's reference load is, 1640 N for the
//! 1656 N level at 0° and 83.4 kPa) or a mean of thinned rows (1601 N) is
//! a value inside a level, not another name of it: a line naming 1640 N
//! and a title naming 1656 N read as two loads. A value outside every
//! level (or without a grouping) is named as itself.
//! Units: the variable's own (N, rad, Pa).

use crate::identify::grouping::{Levels, Variable};

/// The levels that name values: one grouping's, or the lateral and the
/// longitudinal data's.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct LevelNames<'a> {
    groupings: [&'a [Levels]; 2],
}

impl<'a> LevelNames<'a> {
    /// The names of `levels` (a grouping's), and of `more` where a value
    /// lies in none of those (the longitudinal data's grouping).
    pub(crate) fn of(levels: &'a [Levels], more: &'a [Levels]) -> Self {
        Self {
            groupings: [levels, more],
        }
    }

    /// The nominal of the level of `variable` that `v` belongs to, or `v`
    /// itself outside every level.
    pub(crate) fn nominal(&self, variable: Variable, v: f64) -> f64 {
        self.groupings
            .iter()
            .flat_map(|g| g.iter())
            .filter(|l| l.variable == variable)
            .find_map(|l| l.nominal_of(v))
            .unwrap_or(v)
    }

    /// `v` of `variable` named by its level.
    pub(crate) fn name(&self, variable: Variable, v: f64) -> String {
        variable.display(self.nominal(variable, v))
    }

    /// A load's level's name.
    pub(crate) fn load(&self, fz: f64) -> String {
        self.name(Variable::Load, fz)
    }

    /// A camber's level's name.
    pub(crate) fn camber(&self, camber: f64) -> String {
        self.name(Variable::Camber, camber)
    }

    /// A pressure's level's name.
    pub(crate) fn pressure(&self, pressure: f64) -> String {
        self.name(Variable::Pressure, pressure)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::identify::grouping::levels;

    #[test]
    fn a_value_of_a_level_is_labelled_with_its_nominal_as_the_terminal_prints_it() {
        // The TTC file's lightest load: raw samples about 534 N whose
        // thinned rows average 532 N; and its 69.7 kPa pressure.
        let fz: Vec<f64> = (0..40).map(|i| 530.0 + 0.2 * f64::from(i)).collect();
        let loads = levels(Variable::Load, &[fz, vec![2751.0; 40]].concat(), 10.0);
        let p = levels(Variable::Pressure, &[69_650.0, 69_700.0, 69_750.0], 1000.0);
        let named = [loads.clone(), p];
        let level_label =
            |named: &[Levels], variable, v| LevelNames::of(named, &[]).name(variable, v);
        let terminal = Variable::Load.display(loads.levels[0].nominal);
        assert_eq!(terminal, "534 N");
        assert_eq!(level_label(&named, Variable::Load, 532.2), terminal);
        assert_eq!(level_label(&named, Variable::Load, 2754.0), "2751 N");
        assert_eq!(
            level_label(&named, Variable::Pressure, 69_712.0),
            "69.7 kPa"
        );
        // Outside every level, or without the grouping, the value itself.
        assert_eq!(level_label(&named, Variable::Load, 1500.0), "1500 N");
        assert_eq!(
            level_label(&[], Variable::Camber, 1.59f64.to_radians()),
            "1.59°"
        );
    }

    #[test]
    fn a_value_inside_a_level_is_named_by_the_median_of_all_its_samples() {
        let fz: Vec<f64> = (0..41).map(|i| 1500.0 + 7.5 * f64::from(i)).collect();
        let loads = [levels(Variable::Load, &fz, 10.0)];
        let names = LevelNames::of(&loads, &[]);
        assert_eq!(names.load(1640.0), "1650 N");
        assert_eq!(names.load(1601.3), "1650 N");
        assert_eq!(names.load(4000.0), "4000 N");
        assert_eq!(LevelNames::default().camber(0.0), "0.00°");
    }
}
