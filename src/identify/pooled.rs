//! The levels of load, pressure and camber a rig file holds that one fit
//! of a model without terms for them pools into a single parameter set:
//! their differences blur into the fit. `identify` warns of them; a
//! diagnosis whose base tyre is fitted to rig data notes them. Units: the
//! levels are counted, the probe loads in N and slip in rad.

use crate::identify::data::Condition;
use crate::identify::grouping::{GroupingReport, Variable};
use crate::tyre::{SlipState, Tyre};

/// The levels pooled by a model without terms for them (0: not pooled,
/// or the model has them).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pooled {
    /// Load levels pooled by a model whose force does not change with load.
    pub loads: usize,
    /// Pressure levels (no model fitted by a swarm has pressure terms).
    pub pressures: usize,
    /// Camber levels pooled by a model without camber terms.
    pub cambers: usize,
}

impl Pooled {
    /// The levels of `report` that `tyre0` (the model's start) pools.
    pub fn of(tyre0: &Tyre, report: &GroupingReport) -> Self {
        let levels_of = |v: Variable| {
            report
                .levels
                .iter()
                .find(|l| l.variable == v)
                .map_or(0, |l| l.levels.len())
        };
        // A model whose lateral fit frees nothing more with more cambers
        // has no camber terms.
        let many = 1000;
        let camber_terms = tyre0.lateral_free(many, many) != tyre0.lateral_free(many, 1);
        // A model whose force is the same at two loads (a linear tyre's
        // C·α) has no load terms.
        let at = |fz| tyre0.point_forces(&SlipState::lateral(0.02, fz), None).fy;
        Pooled {
            pressures: levels_of(Variable::Pressure),
            cambers: if camber_terms {
                0
            } else {
                levels_of(Variable::Camber)
            },
            loads: if at(1000.0) == at(3000.0) {
                levels_of(Variable::Load)
            } else {
                0
            },
        }
    }

    /// These counts over the levels `conditions` (the fit's, after a
    /// selection) hold, not the file's: a camber that exists only at a
    /// pressure not selected is not pooled into the fit. A count already
    /// 0 (the model has the terms) stays 0.
    pub fn among(self, conditions: &[Condition]) -> Self {
        // The grouping's level tolerances: 10 N, 0.1°, 1 kPa.
        let count = |n: usize, v: Vec<f64>, tol: f64| {
            if n == 0 {
                return 0;
            }
            let mut v = v;
            v.sort_by(f64::total_cmp);
            v.windows(2).filter(|w| w[1] - w[0] > tol).count() + usize::from(!v.is_empty())
        };
        let c = conditions;
        Pooled {
            loads: count(self.loads, c.iter().map(|c| c.fz).collect(), 10.0),
            cambers: count(
                self.cambers,
                c.iter().map(|c| c.camber).collect(),
                0.1f64.to_radians(),
            ),
            pressures: count(
                self.pressures,
                c.iter().filter_map(|c| c.pressure).collect(),
                1000.0,
            ),
        }
    }
}
