//! What a base tyre cannot carry to the car, said as notes beside the
//! diagnosis: static wheel loads beyond the loads the tyre was fitted at
//! (the rig data's, or those its file states: [`super::tyre_loads`]), and
//! levels of pressure, camber or load pooled into one fit of a model
//! without terms for them (the tyre is their blend). Either can leave a
//! gap that is the tyre's, not an unmodelled effect's, so the reader is
//! told before reading the verdict. `identify` warns of the pooling alike
//! and `simulate` counts the rows beyond a tyre's fitted ranges. Units: N.

use super::tyre_loads::{given_loads_short, loads_short};
use crate::diagnose::base::TyreSource;
use crate::diagnose::campaign::Campaign;
use crate::diagnose::report::outcome::LoadRangeOf;
use crate::diagnose::report::Note;
use crate::identify::grouping::{GroupingReport, Variable};
use crate::identify::pooled::Pooled;
use crate::tyre::ModelName;

/// The notes on the base tyre of `source`: given files judged by the load
/// ranges they state, a tyre fitted to the rig data whose grouping is
/// `grouping` by the rig's loads and the levels it pools.
pub(crate) fn rig_notes(
    c: &Campaign,
    source: &TyreSource,
    grouping: Option<&GroupingReport>,
) -> Vec<Note> {
    let (TyreSource::Rig { model, .. }, Some(g)) = (source, grouping) else {
        return given_loads_short(c);
    };
    let (front, rear) = c.vehicle.static_axle_loads();
    let car = [0.5 * front.min(rear), 0.5 * front.max(rear)];
    let mut notes: Vec<Note> = rig_loads(g)
        .and_then(|loads| loads_short(LoadRangeOf::Rig, loads, car))
        .into_iter()
        .collect();
    notes.extend(pooled(*model, g));
    notes
}

/// The rig data's least and largest wheel load, N, over its load levels.
fn rig_loads(g: &GroupingReport) -> Option<[f64; 2]> {
    let levels = g.levels.iter().find(|l| l.variable == Variable::Load)?;
    let lo = levels
        .levels
        .iter()
        .map(|l| l.lo)
        .fold(f64::INFINITY, f64::min);
    let hi = levels.levels.iter().map(|l| l.hi).fold(0.0, f64::max);
    (lo.is_finite() && hi > 0.0).then_some([lo, hi])
}

/// The levels `model` pools into its one fit.
fn pooled(model: ModelName, g: &GroupingReport) -> Vec<Note> {
    let Some(tyre0) = model.start_tyre(3000.0) else {
        return Vec::new();
    };
    let p = Pooled::of(&tyre0, g);
    [
        (Variable::Load, p.loads),
        (Variable::Pressure, p.pressures),
        (Variable::Camber, p.cambers),
    ]
    .into_iter()
    .filter(|(_, n)| *n > 1)
    .map(|(variable, levels)| Note::RigLevelsPooled {
        variable,
        levels,
        model,
    })
    .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::identify::grouping::{Level, Levels};

    fn grouping(loads: &[f64], pressures: usize) -> GroupingReport {
        let level = |v: f64| Level {
            lo: 0.97 * v,
            hi: 1.03 * v,
            nominal: v,
            samples: 100,
        };
        let levels = |variable, values: Vec<f64>| Levels {
            variable,
            separation: 100.0,
            noise: 1.0,
            levels: values.into_iter().map(level).collect(),
            transition_samples: 0,
        };
        let p: Vec<f64> = (0..pressures).map(|k| 80e3 + 10e3 * k as f64).collect();
        GroupingReport {
            samples: 1000,
            used: 1000,
            points: 1000,
            slip_axis: crate::identify::grouping::SlipAxis::Angle,
            slip_bin: 0.0,
            slip_bin_below_resolution: false,
            levels: vec![
                levels(Variable::Load, loads.to_vec()),
                levels(Variable::Pressure, p),
            ],
            dropped_in_transitions: 0,
            dropped_too_few: 0,
            not_selected: 0,
            selected: Vec::new(),
        }
    }

    #[test]
    fn a_car_heavier_than_the_rig_loads_is_said_extrapolated() {
        // A formula-student rig test (up to about 2900 N) under a sedan's
        // wheels (3000–4500 N static).
        let g = grouping(&[400.0, 1100.0, 1650.0, 2850.0], 1);
        let loads = rig_loads(&g).expect("a load range");
        assert_eq!(loads, [0.97 * 400.0, 1.03 * 2850.0]);
        let n = loads_short(LoadRangeOf::Rig, loads, [2995.0, 4507.0]).expect("a note");
        assert_eq!(
            n,
            Note::TyreLoadsShort {
                of: LoadRangeOf::Rig,
                loads: [0.97 * 400.0, 1.03 * 2850.0],
                car: [2995.0, 4507.0]
            }
        );
    }

    #[test]
    fn a_car_within_the_rig_loads_or_a_tenth_beyond_is_not() {
        let g = grouping(&[2000.0, 4000.0, 6000.0], 1);
        let loads = rig_loads(&g).expect("a load range");
        let short = |car| loads_short(LoadRangeOf::Rig, loads, car);
        assert_eq!(short([2995.0, 4507.0]), None);
        // 6180 N is the largest load measured: 1.09× it is within the slack.
        assert_eq!(short([2995.0, 6180.0 * 1.09]), None);
        assert!(short([2995.0, 6180.0 * 1.11]).is_some());
    }

    #[test]
    fn pressures_pooled_by_a_model_without_pressure_terms_are_noted() {
        let g = grouping(&[2000.0, 4000.0], 3);
        let notes = pooled(ModelName::Pac89, &g);
        assert_eq!(
            notes,
            vec![Note::RigLevelsPooled {
                variable: Variable::Pressure,
                levels: 3,
                model: ModelName::Pac89
            }]
        );
        assert!(pooled(ModelName::Pac89, &grouping(&[2000.0, 4000.0], 1)).is_empty());
    }
}
