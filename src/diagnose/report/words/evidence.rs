//! What the runs show beside a verdict's fit, in words ([`Evidence`]): a
//! fitted sensor offset against the measured one (in the channel's unit),
//! axles the effects made a tyre again, and what the verdict was chosen
//! over — a look-alike pressed on its search range, or one that leaves a
//! parameter idle where a simpler candidate does about as well (held-out
//! errors J dimensionless, reductions in percent).

use super::{no_tyre_list, parameter, std_error, value};
use crate::diagnose::effects::joined;
use crate::diagnose::report::outcome::{
    CalibrationSource, Evidence, MassAlike, PairsFallback, Parsimony, Searched, ThroughBank,
};

/// What the runs show beside a verdict's fit, in one line.
pub fn evidence(e: &Evidence) -> String {
    match e {
        Evidence::Calibration {
            channel,
            fitted,
            fitted_std_error,
            fitted_fold_std_error,
            measured,
            measured_on,
            measured_std_error,
            through_bank,
            agrees,
        } => {
            let unit = channel.unit();
            // The fold scatter the agreement was judged on, where the
            // report says the standard error does not cover it.
            let folds = fitted_fold_std_error.map_or_else(String::new, |j| {
                format!(
                    " (judged on the fold refits' scatter ± {}, which the standard error does not cover)",
                    std_error(j)
                )
            });
            format!(
                "{}: the {} offset fitted, {fitted:.4} ± {} {unit}{folds}, {} the {}' {measured:.4} ± {} {unit}{}",
                if *agrees { "confirmed" } else { "not confirmed" },
                channel.name(),
                std_error(*fitted_std_error),
                if *agrees { "agrees with" } else { "differs from" },
                match measured_on {
                    CalibrationSource::Standstills => "standstills",
                    CalibrationSource::Straights => "straights",
                },
                std_error(*measured_std_error),
                through_bank.as_ref().map_or_else(String::new, |t| through(t, unit)),
            )
        }
        Evidence::AxlesRestored { no_tyre } => format!(
            "axles restored: the base model alone is no tyre ({}); fitted with the verdict's effects the axles are a tyre, so the effects account for what bent them (the reductions are measured against the base alone)",
            no_tyre_list(no_tyre)
        ),
        Evidence::LookalikePressed {
            effects,
            reduction_percent,
            pressed,
            pressed_ranges,
            verdict_inside,
        } => {
            let at: Vec<String> = pressed.iter().map(super::parameters::on_bound).collect();
            let ranges: Vec<String> = pressed_ranges.iter().map(|r| range(r.unit, r.range)).collect();
            let ranges = if ranges.is_empty() {
                String::new()
            } else {
                format!(" ({})", ranges.join(", "))
            };
            format!(
                "chosen over a look-alike pressed on its search range: {}, which removes {reduction_percent:.1} %, but only with {} at the end of the range searched{ranges}; an effect that explains the gap only at the end of its plausible range stands in for something else, where the verdict, within the confounding window of it, explains the gap from inside its ranges{}",
                joined(effects, "+"),
                at.join(", "),
                inside(verdict_inside, pressed_ranges)
            )
        }
        Evidence::ChosenForParsimony(c) => parsimony(c),
        Evidence::PairsFallback(f) => fallback(f),
        Evidence::MassAlike(m) => mass_alike(m),
    }
}

/// A range searched, `low–high unit`.
fn range(unit: &str, (low, high): (f64, f64)) -> String {
    let unit = if unit == "-" { "" } else { unit };
    format!("{}–{} {unit}", value(low), value(high))
        .trim_end()
        .to_string()
}

/// The verdict's parameters in a pressed one's unit, each with its range
/// searched, and where several share it, their sum against the pressed
/// range's end: a steer path whose delay and lag add up to the 0.3 s a
/// sensor delay is pressed on holds that total inside its ranges, which
/// a sensor's delay does not.
fn inside(verdict: &[Searched], pressed: &[Searched]) -> String {
    if verdict.is_empty() {
        return String::new();
    }
    let each: Vec<String> = verdict
        .iter()
        .map(|v| {
            let unit = if v.unit == "-" { "" } else { v.unit };
            format!(
                "{} = {} {unit} (range {})",
                v.name,
                value(v.value),
                range(v.unit, v.range)
            )
        })
        .collect();
    let unit = verdict[0].unit;
    let sum = (verdict.len() > 1 && verdict.iter().all(|v| v.unit == unit))
        .then(|| verdict.iter().map(|v| v.value).sum::<f64>());
    let end = pressed.iter().find(|p| p.unit == unit).map(|p| p.range.1);
    let total = match (sum, end) {
        (Some(t), Some(e)) => format!(
            "; their sum, {} {unit}, is {} the end of the look-alike's range ({} {unit}) but inside what the verdict's reach together ({} {unit}): the ranges say what each effect plausibly is, and the size that presses the look-alike is plausible for the verdict's",
            value(t),
            if t >= 0.9 * e { "near" } else { "below" },
            value(e),
            value(verdict.iter().map(|v| v.range.1).sum::<f64>()),
        ),
        _ => String::new(),
    };
    format!(": {}{total}", each.join(", "))
}

/// A verdict reached from a pair of the best singles in sample, where the
/// greedy search stopped with no verdict: on its start alone (no effect
/// added removed the acceptance share of what it leaves) or on a set
/// refused as a whole.
fn fallback(f: &PairsFallback) -> String {
    let (start, t) = (f.start.name(), f.threshold_percent);
    let ended = if f.ended == [f.start] {
        format!("{start} removes {:.1} % alone, and no effect added to it removed {t:.0} % of what it leaves", f.start_reduction_percent)
    } else {
        format!(
            "it ended on {}, which removes {:.1} %, refused",
            joined(&f.ended, "+"),
            f.ended_reduction_percent
        )
    };
    let passed = f.passed_over.map_or_else(String::new, |e| {
        format!(
            ", passing over {}, the best single on held-out runs",
            e.name()
        )
    });
    format!(
        "reached by the pairs fallback, not the greedy search: the greedy search from the best single on held-out runs, {start} ({:.1} %), stopped with no verdict ({ended}; a verdict must remove {t:.0} % and lower the BIC); the pair {} ({:.1} %) came from the pairs of the best singles in sample ({}){passed}, and the verdict is the set the search from that pair reached",
        f.start_reduction_percent,
        joined(&f.pair, "+"),
        f.pair_reduction_percent,
        joined(&f.paired_from, ", "),
    )
}

/// How the standstills' offset was read through the verdict's fitted bank.
fn through(t: &ThroughBank, unit: &str) -> String {
    let logged = match t.logged_bank {
        Some(b) => format!("through the logged bank ({b:.4} rad there)"),
        None => "on a flat road (no bank column)".to_string(),
    };
    format!(
        " read through the bank the verdict fits ({:.4} ± {} rad where they stood: the offset was fitted with it, and its ± includes g·cos θ times the bank's); read {logged} they give {:.4} {unit}",
        t.bank, std_error(t.bank_std_error), t.as_logged
    )
}

/// A yaw inertia in the verdict, and the mass that fits the runs the same.
fn mass_alike(m: &MassAlike) -> String {
    let s = m.scale;
    format!(
        "the yaw inertia or the mass: yaw_inertia.scale = {s:.3} makes the car's yaw inertia {:.0} × {s:.3} = {:.0} kg·m², and a vehicle.mass of {:.0} / {s:.3} = {:.0} kg in place of the file's {:.0} kg would look the same in the runs: with the axles' cornering stiffness about proportional to their loads, a wrong mass scales the loads and with them the axle forces, which the lateral balance cancels and the yaw balance does not, so the runs cannot tell it from a wrong yaw inertia; check vehicle.mass (weigh the car) as well as vehicle.yaw_inertia",
        m.yaw_inertia, m.yaw_inertia_fitted, m.mass, m.mass_alike, m.mass,
    )
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
