//! The axles identified from the runs in words: the no-tyre reasons, the
//! prior and its friction rule, where the base model's tyres come from.
//! Cornering coefficients in 1/rad (per unit load), peak friction
//! dimensionless, peak slip angles in degrees as tyre engineers read them.

use crate::diagnose::base::identify::{
    AxleIdentification, AxleLimit, AxleValue, NoTyre, PEAK_SLIP_MIN, SHAPE,
};
use crate::diagnose::base::prior::{PriorReport, Tempering};
use crate::diagnose::base::TyreSource;
use crate::diagnose::campaign::prior::Z95;
use crate::diagnose::report::BaseReport;

/// Reasons axles are no tyre, joined by "; ".
pub fn no_tyre_list(reasons: &[NoTyre]) -> String {
    reasons.iter().map(no_tyre).collect::<Vec<_>>().join("; ")
}

/// One reason axles are no tyre.
pub fn no_tyre(r: &NoTyre) -> String {
    match r {
        NoTyre::Limit { parameter, limit } => limit_meaning(*limit, parameter),
        NoTyre::EarlyPeak {
            axle,
            peak_slip,
            coefficient_over_friction,
        } => format!(
            "the {} axle peaks at {:.2}° of slip (cornering coefficient over peak friction {:.0} 1/rad; no tyre peaks before {:.0}°): the data pull it to saturate early",
            axle.name(),
            peak_slip.to_degrees(),
            coefficient_over_friction,
            PEAK_SLIP_MIN.to_degrees()
        ),
        NoTyre::OutsidePrior {
            parameter,
            value,
            range,
            z,
        } => format!(
            "the {parameter} {value:.3} lies {:.1} standard deviations {} the prior's range {:.2}–{:.2} (no tyre of the stated class): the data pull the axles to stand in for what the model lacks",
            z.abs(),
            if *z > 0.0 { "above the centre of" } else { "below the centre of" },
            range[0],
            range[1]
        ),
    }
}

/// What an axle characteristic on a limit means, and which way the data
/// pull, for the characteristic named `name`.
pub fn limit_meaning(limit: AxleLimit, name: &str) -> String {
    match limit {
        AxleLimit::NoForce => format!(
            "{name} at its physical limit 0.4 1/rad (an axle without cornering force; no tyre is that soft): the data pull it lower"
        ),
        AxleLimit::Rigid => format!(
            "{name} at its physical limit 4,000 1/rad (a rigid axle that never slips; no tyre is that stiff): the data pull it higher"
        ),
        AxleLimit::NoGrip => format!(
            "{name} at its physical limit 0.11 (a road without grip): the data pull it lower"
        ),
        AxleLimit::Linear => format!(
            "{name} at the top of its range (9): a tyre that never saturates on these runs, which stay in its linear range and do not identify it"
        ),
    }
}

/// The axles identified from the runs in one line.
pub fn axles_line(id: &AxleIdentification) -> String {
    let values = axle_values(&id.parameters);
    let mut s = format!(
        "axle characteristics identified from the runs (simplified Magic Formula, C = {SHAPE}; cornering coefficient = cornering stiffness per unit load; best of {} starts from a grid; refitted with every candidate): {}",
        id.starts,
        values.join(", ")
    );
    if let Some((a, b, rho)) = &id.largest_correlation {
        s.push_str(&format!("; largest correlation {a} / {b} {rho:+.2}"));
    }
    if let Some(p) = &id.prior {
        s.push_str(&format!("; {}", prior_line(p)));
    }
    if id.degenerate() {
        s.push_str(&format!("; no tyre: {}", no_tyre_list(&id.no_tyre)));
    }
    s
}

/// Each axle characteristic in words: its value with its standard error,
/// the limit it stands on, or that it is held.
pub fn axle_values(parameters: &[AxleValue]) -> Vec<String> {
    parameters
        .iter()
        .map(|v| {
            let digits = if v.unit == "-" { 3 } else { 1 };
            // A dimensionless value (peak friction) is written without a
            // unit, not with "-" ("1.129 ± 0.122 -;").
            let unit = match v.unit {
                "-" => String::new(),
                u => format!(" {u}"),
            };
            if v.held {
                return format!(
                    "{} {:.digits$} (held at the prior's centre, the geometric mean of its range)",
                    v.name, v.value
                );
            }
            match v.limit {
                Some(l) => limit_meaning(l, v.name).replacen(
                    v.name,
                    &format!("{} {:.digits$}", v.name, v.value),
                    1,
                ),
                // To the standard error's precision: "9.8 ± 0.0378"
                // rounded the value coarser than its own uncertainty.
                None if v.std_error.is_finite() => format!(
                    "{} {} ± {}{unit}",
                    v.name,
                    crate::format::beside_error(v.value, v.std_error, digits),
                    super::std_error(v.std_error),
                ),
                None => format!("{} {:.digits$}{unit} (not pinned)", v.name, v.value),
            }
        })
        .collect()
}

/// Standard deviations (in `ln x`) from the prior's centre beyond which a
/// fitted axle characteristic within the 95 % range is said to lie near
/// its edge: the outer quarter of each half of the range (1.5 of 1.96 σ),
/// where the prior, not the runs alone, may have put it.
pub const NEAR_EDGE: f64 = 1.5;

/// The prior the axles were fitted against, the friction rule, and where
/// the axles lie on it.
pub fn prior_line(p: &PriorReport) -> String {
    let a = &p.prior;
    let stated: Vec<&str> = ["cornering coefficient", "peak friction"]
        .into_iter()
        .zip(a.stated)
        .filter_map(|(n, s)| s.then_some(n))
        .collect();
    let class = format!(
        "{} tyres{}",
        a.class.name().replace('_', " "),
        if stated.is_empty() {
            String::new()
        } else {
            format!(" ({} stated)", stated.join(" and "))
        }
    );
    let rule = &p.friction_rule;
    let friction = if rule.free {
        format!(
            "peak friction fitted: the runs reach |ay| {:.1} m/s² (99.5th percentile), at least {:.1} m/s² (0.8 of the lowest grip)",
            rule.ay, rule.threshold
        )
    } else {
        format!(
            "peak friction held at {:.2} (the geometric mean of its range): the runs reach |ay| {:.1} m/s² (99.5th percentile), below {:.1} m/s² (0.8 of the lowest grip), so they do not show it",
            rule.value, rule.ay, rule.threshold
        )
    };
    let names = ["front", "rear", "peak friction"];
    // A held friction is where the prior put it: only fitted ones are
    // placed on it. One within the range but near its end is said so: at
    // −1.95 σ "within it" read as agreement where the prior held it back.
    let fitted = p
        .against
        .iter()
        .zip(names)
        .take(if rule.free { 3 } else { 2 });
    let outside: Vec<String> = fitted
        .filter(|(x, _)| !x.within || x.z.abs() >= NEAR_EDGE)
        .map(|(x, n)| {
            let place = if x.within {
                "lies near its edge"
            } else {
                "is outside it"
            };
            format!(
                "{n} {:.3} {place} ({:+.2} σ; the range ends at ±{Z95:.2} σ)",
                x.value, x.z
            )
        })
        .collect();
    format!(
        "prior {class}: cornering coefficient {:.0}–{:.0} 1/rad, peak friction {:.2}–{:.2} (95 % ranges); {friction}; {}; {}",
        a.cornering[0],
        a.cornering[1],
        a.friction[0],
        a.friction[1],
        tempering(&p.tempering),
        if outside.is_empty() {
            format!("the axles lie within it, inside ±{NEAR_EDGE} σ of its centre")
        } else {
            outside.join(", ")
        }
    )
}

/// How the runs weighed against the prior, in a clause.
pub fn tempering(t: &Tempering) -> String {
    if t.prior_weight <= 1.0 {
        return "the runs weigh as independent samples at their noise floors".into();
    }
    format!(
        "the runs weigh as {:.0} independent samples ({} residuals correlated over {:.1} samples) at {:.2} noise floors, so the prior's rows count ×{:.1}",
        t.effective_samples,
        t.samples,
        t.correlation_samples,
        t.residual_variance.sqrt(),
        t.prior_weight
    )
}

/// Where the base model's tyres come from, in one line.
pub fn tyre_source(b: &BaseReport) -> String {
    match (&b.source, &b.axles) {
        (TyreSource::Given, _) => "given tyre files".into(),
        (
            TyreSource::Rig {
                model,
                path,
                sigma_percent,
            },
            _,
        ) => format!(
            "{model} fitted to the rig data {} (σ {sigma_percent:.2} % of the force)",
            path.display()
        ),
        (TyreSource::FromRuns, Some(id)) => format!("no tyre data: {}", axles_line(id)),
        (TyreSource::FromRuns, None) => "no tyre data".into(),
    }
}
