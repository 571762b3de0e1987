//! A Magic Formula tyre fitted around a value given with `--hold` whose
//! slip stiffness (the force's slope at zero slip, N/rad or N per unit
//! slip ratio) changes sign inside the loads it was fitted on. A held
//! value is not fitted, so nothing the fit does can undo it: `PKY4 = −50`
//! turns `Kyα = PKY1·FNOMIN·sin(PKY4·atan(Fz/(PKY2·FNOMIN)))` over four
//! times between 2 and 6 kN on `car205_60R19.tir`'s forces, the pure Fy
//! stage still at σ 1.3 % (Pacejka 2012, §4.3.2: the sine's argument stays
//! within ±π for a stiffness of one sign). Refused, no file written, as a
//! fit whose force opposes its slip is refused elsewhere. Loads in N.

use crate::error::Num;
use crate::format::{plural, readable};

/// A coefficient held with `--hold`, in the tyre file's units.
#[derive(Debug, Clone, PartialEq)]
pub struct HeldValue {
    /// Its name (`PKY4`).
    pub name: String,
    /// The value given.
    pub value: f64,
    /// The box the fit searches for it, where it has one.
    pub search_box: Option<(f64, f64)>,
}

/// A held value's tyre whose slip stiffness turns over inside its loads.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", self.said())]
pub struct HeldTurn {
    /// The held coefficients of that stiffness.
    pub held: Vec<HeldValue>,
    /// `cornering` or `longitudinal slip`.
    pub stiffness: &'static str,
    /// The loads it first changes sign between.
    pub between: (f64, f64),
    /// How many times it changes sign over the loads.
    pub changes: usize,
    /// The loads fitted (the data's).
    pub loads: (f64, f64),
}

impl HeldTurn {
    fn said(&self) -> String {
        let n = |v: f64| readable(v, 4);
        let given: Vec<String> = self
            .held
            .iter()
            .map(|h| format!("--hold {}={}", h.name, Num(h.value)))
            .collect();
        let boxes: Vec<String> = self
            .held
            .iter()
            .filter_map(|h| {
                let (lo, hi) = h.search_box?;
                Some(format!("{} within {} to {}", h.name, Num(lo), Num(hi)))
            })
            .collect();
        let advice = match boxes.is_empty() {
            true => "a value that keeps it of one sign over the loads".to_string(),
            false => format!(
                "a value that keeps it of one sign over the loads (the fit's own box: {})",
                boxes.join(", ")
            ),
        };
        format!(
            "the tyre fitted with {} has a {} stiffness (the force's slope at zero slip) that changes sign {} over the data's loads, {} to {} N (first between {} and {} N): there its force opposes its slip, and a held value is not fitted, so the fit cannot undo it; no file is written: give {advice}, or leave it free",
            given.join(" "),
            self.stiffness,
            plural(self.changes, "time", "times"),
            n(self.loads.0),
            n(self.loads.1),
            n(self.between.0),
            n(self.between.1),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_held_turn_names_the_value_the_count_and_the_box() {
        let e = HeldTurn {
            held: vec![HeldValue {
                name: "PKY4".into(),
                value: -50.0,
                search_box: Some((0.1, 5.0)),
            }],
            stiffness: "cornering",
            between: (2063.0, 2125.0),
            changes: 4,
            loads: (2000.0, 6000.0),
        };
        let s = e.to_string();
        assert!(
            s.starts_with("the tyre fitted with --hold PKY4=-50 has a cornering stiffness"),
            "{s}"
        );
        assert!(s.contains("changes sign 4 times over the data's loads, 2000 to 6000 N (first between 2063 and 2125 N)"), "{s}");
        assert!(s.contains("no file is written"), "{s}");
        assert!(
            s.contains("(the fit's own box: PKY4 within 0.1 to 5)"),
            "{s}"
        );
    }
}
