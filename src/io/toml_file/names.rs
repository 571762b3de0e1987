//! An unknown name answered: serde's `unknown variant` or `unknown field`
//! with the nearest known name suggested (a manoeuvre's `kind =
//! "step_stear"`), a key of another manoeuvre kind's table by the key that
//! holds its quantity here (a sine's `steer`: `amplitude`), and a run
//! column that is no angle where an angle column is asked (`degrees =
//! ["speed"]`) as no angle, not as a slip of `steer`.

use super::home;
use crate::io::AngleColumn;

/// serde's `unknown variant `x`, expected one of `a`, `b`` (or `unknown
/// field`: a misspelt key) with the nearest
/// known name suggested after the unknown one, as every other unknown name
/// is answered (a manoeuvre's `kind = "step_stear"`); other messages, and
/// ones that already suggest, unchanged.
pub(super) fn suggest_variant(message: &str) -> String {
    let parse = |what: &str| {
        let rest = message.strip_prefix(&format!("unknown {what} `"))?;
        let (given, rest) = rest.split_once('`')?;
        let known = home::listed(rest.strip_prefix(", expected ")?);
        let clause = Some(what)
            .filter(|w| *w == "field")
            .and_then(|_| same_quantity(given, &known))
            .or_else(|| not_an_angle(what, given, &known))
            .unwrap_or_else(|| crate::format::did_you_mean(given, &known));
        (!clause.is_empty()).then(|| format!("unknown {what} `{given}`{clause}{rest}"))
    };
    parse("variant")
        .or_else(|| parse("field"))
        .unwrap_or_else(|| message.to_string())
}

/// Keys the manoeuvre kinds (`scenario.rs`) give one quantity under
/// different names: the steer is a step steer's `steer`, a sine's or a
/// sweep's `amplitude`, a ramp's `rate`; the frequency is a sine's
/// `frequency`, a sweep's `f_start` and `f_end`. Spelling alone answers a
/// sine's `steer` with `speed`.
const SAME_QUANTITY: &[&[&str]] = &[
    &["steer", "amplitude", "rate"],
    &["frequency", "f_start", "f_end"],
];

/// The known keys that hold what the unknown key `given` holds in another
/// kind of table, as a clause (` (did you mean `amplitude`?)`).
fn same_quantity(given: &str, known: &[&str]) -> Option<String> {
    let group = SAME_QUANTITY.iter().find(|g| g.contains(&given))?;
    let names: Vec<String> = known
        .iter()
        .filter(|k| group.contains(k))
        .map(|k| format!("`{k}`"))
        .collect();
    (!names.is_empty()).then(|| format!(" (did you mean {}?)", names.join(" or ")))
}

/// ` (`speed` is no angle: …)` where the names `known` are the angle
/// columns' and `given` is a run column that is no angle.
fn not_an_angle(what: &str, given: &str, known: &[&str]) -> Option<String> {
    let angles = AngleColumn::ALL.map(AngleColumn::name);
    (what == "variant" && known == angles)
        .then(|| AngleColumn::not_an_angle(given))
        .flatten()
        .map(|why| format!(" ({why})"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_run_column_that_is_no_angle_is_not_offered_an_angles_name() {
        let message =
            "unknown variant `speed`, expected one of `steer`, `yaw_rate`, `beta`, `roll`, `bank`";
        let said = suggest_variant(message);
        assert!(said.starts_with("unknown variant `speed` (`speed` is no angle: a run's forward speed is in m/s, never in degrees), expected one of `steer`"), "{said}");
        // A slip of an angle's name is still answered with it.
        let said = suggest_variant(&message.replace("`speed`,", "`stear`,"));
        assert!(said.contains("(did you mean `steer`?)"), "{said}");
    }
}
