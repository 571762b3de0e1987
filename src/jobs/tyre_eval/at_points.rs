//! `tyre-eval`'s checks of its points, made of arrays rather than of a
//! points file, for a caller that evaluates a tyre at points it holds (the
//! Python `Tyre.forces`): the same rules as the CLI's, by the same
//! functions — a value that is no finite number, one outside its physical
//! range or an angle that reads in degrees, a negative speed, a file of
//! negative loads (`physical.rs`), a pressure at or below 0 or not in
//! Pa (the whole array by its median, or one value among pressures in Pa:
//! `pressure.rs`), loads in kN — each said at its argument and
//! index; and the warning the CLI gives of slip ratios beyond ±1
//! (`slip_ratio.rs`). Units: SI, rad, Pa, as `tyre-eval`'s points file.

use super::slip_ratio::{self, SlipPastLock};
use super::{physical, pressure};
use crate::error::InputProblem;
use crate::io::rig::load_in_kn;
use crate::tyre::Tyre;

/// One refused value: the argument (`fz`, `kappa`, `alpha`, `camber`,
/// `speed`, `pressure`), its index (0-based), the value and why.
#[derive(Debug)]
pub struct PointRefused {
    /// The argument's name, as the points file's column.
    pub argument: &'static str,
    /// The index within it, 0-based.
    pub index: usize,
    /// The value given.
    pub value: f64,
    /// Why it is refused; `None`: it is NaN or infinite.
    pub problem: Option<InputProblem>,
}

impl std::fmt::Display for PointRefused {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}[{}]: ", self.argument, self.index)?;
        match &self.problem {
            Some(p) => write!(f, "{p}"),
            None => write!(f, "{} is not a finite value", self.value),
        }
    }
}

/// Every value of the points `inputs` (fz, kappa, alpha, camber, speed,
/// each as long as the first) and `pressure` (empty: the tyre's own) that
/// `tyre-eval` refuses for `tyre`, in index order then argument order.
pub fn refused_points(tyre: &Tyre, inputs: [&[f64]; 5], pressure: &[f64]) -> Vec<PointRefused> {
    const NAMES: [&str; 6] = ["fz", "kappa", "alpha", "camber", "speed", "pressure"];
    let given = inputs
        .into_iter()
        .chain((!pressure.is_empty()).then_some(pressure));
    let mut refused: Vec<(usize, usize, PointRefused)> = Vec::new();
    for (k, values) in given.enumerate() {
        let argument = NAMES[k];
        let at = |index: usize, problem: Option<InputProblem>| {
            let value = values[index];
            (
                index,
                k,
                PointRefused {
                    argument,
                    index,
                    value,
                    problem,
                },
            )
        };
        let non_finite = (0..values.len()).filter(|&i| !values[i].is_finite());
        refused.extend(non_finite.map(|i| at(i, None)));
        let physical = physical::not_physical(argument, values, false).into_iter();
        // A pressure at or below 0 is said as such, as the CLI says it.
        let physical = physical.filter(|(i, _)| argument != "pressure" || values[*i] > 0.0);
        refused.extend(physical.map(|(i, p)| at(i, Some(p))));
        if argument == "pressure" {
            let low = (0..values.len()).filter(|&i| values[i].is_finite() && values[i] <= 0.0);
            let said = |i: usize| InputProblem::NonPositivePressure { value: values[i] };
            refused.extend(low.map(|i| at(i, Some(said(i)))));
            // The points file's rule: a column in kPa, bar or psi once,
            // by its median; a cell so written among pressures in Pa
            // (2.4 beside 2.2e5 and 2.3e5) at its own index.
            let known = pressure::tyre_pressures(tyre, None);
            let slips = pressure::not_in_pa(values, known).into_iter();
            refused.extend(slips.map(|(i, slip)| at(i, Some(slip.into()))));
        }
        if argument == "fz" {
            if let Some((i, slip)) = load_in_kn(values, |fz| fz > 0.0) {
                refused.push(at(i, Some(slip.into())));
            }
        }
    }
    refused.sort_by_key(|(i, k, _)| (*i, *k));
    refused.into_iter().map(|(_, _, r)| r).collect()
}

/// The slip ratios of `kappa` beyond ±1, as `tyre-eval` warns of them,
/// the first's index (0-based) in place of its line; `None` without one.
pub fn slip_past_lock(kappa: &[f64]) -> Option<SlipPastLock> {
    let indices: Vec<usize> = (0..kappa.len()).collect();
    slip_ratio::past_lock(kappa, &indices)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tester's points (NaN, 3 rad, a negative speed, 2.2 bar) are
    /// each refused at their argument and index, in index order.
    #[test]
    fn each_point_the_cli_refuses_is_refused_at_its_argument_and_index() {
        let tyre = Tyre::Linear(crate::tyre::Linear::new(80e3));
        let fz = [4000.0, f64::NAN, 4000.0, 4000.0];
        let zero = [0.0; 4];
        let alpha = [0.0, 0.0, 3.0, 0.0];
        let speed = [16.7, 16.7, 16.7, -16.7];
        let r = refused_points(&tyre, [&fz, &zero, &alpha, &zero, &speed], &[]);
        let at: Vec<_> = r.iter().map(|r| (r.argument, r.index)).collect();
        assert_eq!(at, [("fz", 1), ("alpha", 2), ("speed", 3)], "{r:?}");
        assert!(r[0].problem.is_none());
        let said = r[2].to_string();
        assert!(
            said.starts_with("speed[3]: ") && said.contains("-16.7 m/s is negative"),
            "{said}"
        );
        // 2.2 bar at every point: the column's median is not in Pa.
        let p = [2.2; 4];
        let ok = [4000.0; 4];
        let r = refused_points(&tyre, [&ok, &zero, &zero, &zero, &[16.7; 4]], &p);
        assert_eq!(r.len(), 1, "{r:?}");
        assert_eq!(
            (r[0].argument, r[0].index, r[0].value),
            ("pressure", 0, 2.2)
        );
        assert!(refused_points(&tyre, [&ok, &zero, &zero, &zero, &[16.7; 4]], &[]).is_empty());
    }

    /// One pressure in bar among pressures in Pa passes the median rule
    /// (the median, 2.3e5 Pa, is a tyre's): it is refused at its own
    /// index, as the points file refuses its cell, with the bar reading
    /// that lands it among the tyre's pressures; the Pa ones pass.
    #[test]
    fn a_pressure_in_bar_among_pressures_in_pa_is_refused_at_its_index() {
        let tyre = Tyre::Linear(crate::tyre::Linear::new(80e3));
        let ok = [4000.0; 3];
        let zero = [0.0; 3];
        let speed = [16.7; 3];
        let inputs = [&ok[..], &zero, &zero, &zero, &speed];
        let r = refused_points(&tyre, inputs, &[2.2e5, 2.3e5, 2.4]);
        let at: Vec<_> = r.iter().map(|r| (r.argument, r.index, r.value)).collect();
        assert_eq!(at, [("pressure", 2, 2.4)], "{r:?}");
        let said = r[0].to_string();
        assert!(
            said.starts_with("pressure[2]: ") && said.contains("bar"),
            "{said}"
        );
        // Bar and kPa in one array: each cell said in its own unit.
        let r = refused_points(&tyre, inputs, &[2.2e5, 2.2, 220.0]);
        let at: Vec<_> = r.iter().map(|r| (r.index, r.value)).collect();
        assert_eq!(at, [(1, 2.2), (2, 220.0)], "{r:?}");
        assert!(refused_points(&tyre, inputs, &[2.2e5, 2.3e5, 2.4e5]).is_empty());
    }
}
