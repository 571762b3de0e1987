//! The coefficients without which a `.tir` describes no force: the peak
//! and shape coefficients every published Magic Formula file carries (all
//! thirteen public files here, MF 5.2 to 6.2), looked for so that a file
//! cut short or with such a key misspelt is refused, not evaluated with
//! their defaults.

use super::TirDocument;
use crate::error::{InputError, InputProblem};
use crate::tyre::mf::{MfCoefficients, MfLimits};

impl TirDocument {
    /// Ok when the file has the peak and shape coefficients every published
    /// Magic Formula file carries (all thirteen public files here, MF 5.2 to
    /// 6.2) for each force it describes, for all three where it describes
    /// the longitudinal force (listed first, so a file without the later
    /// ones was cut short), and (`any`) describes one: a file cut short, or
    /// one with such a key misspelt, would otherwise evaluate with their
    /// defaults (a force of the wrong sign, or none).
    pub(super) fn core_coefficients(&self, any: bool) -> Result<(), InputError> {
        // (the channel's letters in a coefficient name: `P?Y…`, its core)
        const CORE: [(char, char, &[&str]); 3] = [
            ('P', 'X', &["PCX1", "PDX1", "PKX1"]),
            ('P', 'Y', &["PCY1", "PDY1", "PKY1"]),
            ('Q', 'Z', &["QBZ1", "QDZ1"]),
        ];
        let of = |key: &str, (first, third): (char, char)| {
            let c: Vec<char> = key.chars().collect();
            c.len() >= 4 && c[0] == first && c[2] == third
        };
        let described: Vec<_> = CORE
            .iter()
            .filter(|(f, t, _)| self.entries().any(|(_, e)| of(&e.key, (*f, *t))))
            .collect();
        // A published file lists the longitudinal coefficients first, then
        // the lateral, then the aligning ones: one that describes the
        // longitudinal force describes all three, and lacking a later one
        // it was cut short. A file of the lateral force alone (and its
        // moment) is a partial file as fitting tools write them.
        let longitudinal = described.iter().any(|c| c.1 == 'X');
        let mut missing: Vec<&'static str> = if (described.is_empty() && any) || longitudinal {
            CORE.iter().flat_map(|c| c.2.iter().copied()).collect()
        } else {
            described.iter().flat_map(|c| c.2.iter().copied()).collect()
        };
        missing.retain(|k| self.get(k).is_none());
        if missing.is_empty() {
            return Ok(());
        }
        let near = missing
            .iter()
            .flat_map(|&k| {
                self.entries()
                    .filter(move |(_, e)| {
                        // A key the model reads is no misspelling; one of
                        // another section is another quantity (`PCFY1`).
                        let known = MfCoefficients::default().get(&e.key).is_some()
                            || MfLimits::KEYS.contains(&e.key.as_str());
                        let section = match &k[..2] {
                            "QB" | "QD" => "ALIGNING_COEFFICIENTS",
                            _ if k.ends_with("X1") => "LONGITUDINAL_COEFFICIENTS",
                            _ => "LATERAL_COEFFICIENTS",
                        };
                        !known
                            && e.section == section
                            && crate::format::edit_distance(&e.key, k) <= 1
                    })
                    .map(move |(line, e)| (k, line, e.key.clone()))
            })
            .collect();
        Err(InputError::problem(
            &self.path,
            InputProblem::TirCoefficientsMissing {
                missing,
                near,
                lines: self.lines.len(),
            },
        ))
    }
}
