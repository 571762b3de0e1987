//! What the runs show beside a verdict's fit, in words ([`Evidence`]): a
//! fitted sensor offset against the measured one (in the channel's unit),
//! axles the effects made a tyre again, and what the verdict was chosen
//! over — a look-alike pressed on its search range, or one that leaves a
//! parameter idle where a simpler candidate does about as well (held-out
//! errors J dimensionless, reductions in percent).

use super::{no_tyre_list, parameter, std_error};
use crate::diagnose::effects::joined;
use crate::diagnose::report::outcome::{CalibrationSource, Evidence, Parsimony};

/// What the runs show beside a verdict's fit, in one line.
pub fn evidence(e: &Evidence) -> String {
    match e {
        Evidence::Calibration {
            channel,
            fitted,
            fitted_std_error,
            measured,
            measured_on,
            measured_std_error,
            agrees,
        } => format!(
            "{}: the {} offset fitted, {fitted:.4} ± {} {unit}, {} the {}' {measured:.4} ± {} {unit}",
            if *agrees { "confirmed" } else { "not confirmed" },
            channel.name(),
            std_error(*fitted_std_error),
            if *agrees { "agrees with" } else { "differs from" },
            match measured_on {
                CalibrationSource::Standstills => "standstills",
                CalibrationSource::Straights => "straights",
            },
            std_error(*measured_std_error),
            unit = channel.unit(),
        ),
        Evidence::AxlesRestored { no_tyre } => format!(
            "axles restored: the base model alone is no tyre ({}); fitted with the verdict's effects the axles are a tyre, so the effects account for what bent them (the reductions are measured against the base alone)",
            no_tyre_list(no_tyre)
        ),
        Evidence::LookalikePressed {
            effects,
            reduction_percent,
            pressed,
        } => {
            let at: Vec<String> = pressed.iter().map(super::parameters::on_bound).collect();
            format!(
                "chosen over a look-alike pressed on its search range: {}, which removes {reduction_percent:.1} %, but only with {} at the end of the range searched; an effect that explains the gap only at the end of its plausible range stands in for something else, where the verdict, within the confounding window of it, explains the gap from inside its ranges",
                joined(effects, "+"),
                at.join(", ")
            )
        }
        Evidence::ChosenForParsimony(c) => parsimony(c),
    }
}

/// The verdict (or the set its search started from or extended) taken for
/// parsimony over a look-alike that leaves a parameter idle, with the
/// numbers of the rule.
fn parsimony(c: &Parsimony) -> String {
    let idle: Vec<String> = c.idle.iter().map(parameter).collect();
    let (j, n, jn) = (c.heldout_error, c.window_noise_levels, c.noise_level);
    format!(
        "chosen for parsimony over a look-alike that removes more: {} removes {:.1} % (held-out error {j:.3}) with {}, but leaves {} idle (off, or not told from off); {} removes {:.1} % with {}, within {n} noise levels of it (held-out error {:.3} ≤ {j:.3} + {n} × {jn:.3} = {:.3}), and within that window the candidate with the fewest parameters is taken, an idle one counted (a candidate that matches only with a parameter idle is the simpler one's look-alike with a parameter more): a tie the runs do not break, settled by the rule, not evidence against the other",
        joined(&c.effects, "+"),
        c.reduction_percent,
        free(c.free_parameters),
        if idle.is_empty() { "a parameter".to_string() } else { idle.join(", ") },
        joined(&c.taken, "+"),
        c.taken_reduction_percent,
        free(c.taken_free_parameters),
        c.taken_heldout_error,
        j + n * jn,
    )
}

/// `n parameters`, in the singular for one: a candidate's, its idle ones
/// counted (fitted to their off value or held there, they are still the
/// candidate's, and what makes it the look-alike of a simpler one).
fn free(n: usize) -> String {
    format!("{n} parameter{}", if n == 1 { "" } else { "s" })
}
