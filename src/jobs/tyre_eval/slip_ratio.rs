//! Slip ratios past a locked wheel's or a wheel spun to twice the road
//! speed, counted and said: `tyre-eval` evaluates slip ratios up to ±10
//! (`physical.rs`: a wheel spinning up from rest reaches them), but below
//! −1 the wheel turns backwards while the car rolls forwards and above 1
//! it spins at more than twice the road speed, where no braking or
//! traction test goes (rigs sweep to about ±0.3). A column of them is most
//! likely in percent (5 for 5 %), and the tyre's forces there are the
//! saturated tail of its curve, so a user reading them as 5 % slip reads
//! the wrong numbers without a word. Slip ratio κ = (ω·R − V)/V,
//! dimensionless (ISO 8855, positive driving).

use crate::error::Num;
use crate::format::plural;
use serde::Serialize;

/// The points at |κ| > 1.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SlipPastLock {
    /// Points past ±1.
    pub points: usize,
    /// The first one's line in the points file (1-based).
    pub first_line: usize,
    /// Its slip ratio.
    pub first_value: f64,
    /// The slip ratio farthest from 0 among them.
    pub farthest: f64,
}

/// The points of slip ratio `kappa` (at file lines `lines`) beyond ±1;
/// `None` where there are none.
pub(super) fn past_lock(kappa: &[f64], lines: &[usize]) -> Option<SlipPastLock> {
    let past: Vec<usize> = (0..kappa.len()).filter(|&i| kappa[i].abs() > 1.0).collect();
    let &first = past.first()?;
    let farthest = past
        .iter()
        .map(|&i| kappa[i])
        .max_by(|a, b| a.abs().total_cmp(&b.abs()))?;
    Some(SlipPastLock {
        points: past.len(),
        first_line: lines[first],
        first_value: kappa[first],
        farthest,
    })
}

impl SlipPastLock {
    /// The warning, of `count` points.
    pub fn line(&self, count: usize) -> String {
        format!(
            "{} of {count} at a slip ratio beyond ±1 (the first at line {}, κ = {}; the farthest {}): below −1 the wheel turns backwards while the car rolls forwards, above 1 it spins at more than twice the road speed, where no braking or traction test goes (rigs sweep to about ±0.3) and the forces are the saturated tail of the curve: `kappa` is a fraction (FORMATS.md); is the column in percent? divide it by 100",
            plural(self.points, "point", "points"),
            self.first_line,
            Num(self.first_value),
            Num(self.farthest)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slip_ratios_past_a_locked_wheel_are_counted_with_the_first_and_farthest() {
        let kappa = [0.0, 0.05, 5.0, -3.0, 10.0, -1.0, 1.0];
        let lines: Vec<usize> = (2..9).collect();
        let p = past_lock(&kappa, &lines).unwrap();
        assert_eq!((p.points, p.first_line), (3, 4));
        assert_eq!((p.first_value, p.farthest), (5.0, 10.0));
        let said = p.line(7);
        assert!(said.starts_with("3 points of 7 at a slip ratio beyond ±1 (the first at line 4, κ = 5; the farthest 10)"), "{said}");
        // ±1 itself (a locked wheel, one spinning at twice the speed) is a
        // state a test can reach.
        assert_eq!(past_lock(&[-1.0, 1.0, 0.3], &[2, 3, 4]), None);
    }
}
