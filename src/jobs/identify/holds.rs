//! The parameters held with `--hold` as `identify` reports them: each
//! with the value given (the tyre file's units) and whether a fit applied
//! it, and the terminal's lines that say so.

use super::Options;
use serde::Serialize;

/// A parameter held with `--hold`: its name, the value given (the tyre
/// file's units) and whether a fit it belongs to ran (a parameter of a
/// block the data do not fit, such as an aligning one without `mz`, is
/// not applied, and said so).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Held {
    /// The parameter, as the tyre file names it.
    pub name: String,
    /// The value given.
    pub value: f64,
    /// Whether a fit held it (false: no fit it belongs to ran).
    pub applied: bool,
}

/// The holds of `o`, each applied when `fitted` names it.
pub(crate) fn holds_of(o: &Options, fitted: &[String]) -> Vec<Held> {
    o.hold
        .iter()
        .map(|(name, value)| Held {
            name: name.clone(),
            value: *value,
            applied: fitted.contains(name),
        })
        .collect()
}

/// The terminal's lines of the holds: the parameters held, and those not
/// applied.
pub(crate) fn held_lines(held: &[Held]) -> Vec<String> {
    let applied: Vec<String> = held
        .iter()
        .filter(|h| h.applied)
        .map(|h| format!("{} = {}", h.name, h.value))
        .collect();
    let mut out = Vec::new();
    if !applied.is_empty() {
        out.push(format!(
            "  held with --hold (not fitted): {}",
            applied.join(", ")
        ));
    }
    out.extend(held.iter().filter(|h| !h.applied).map(|h| {
        format!(
            "  warning: --hold {}={}: not applied: no fit of its block ran on these data, and the file written does not hold it",
            h.name, h.value
        )
    }));
    out
}
