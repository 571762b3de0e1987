//! What `simulate` says of a scenario as it reads it
//! ([`ScenarioRemark`]): a replayed run's `bank` column applied as the
//! road it was driven on (the scenario giving no `bank_profile_scale`, the
//! measured bank at scale 1, as `diagnose`'s bank-profile effect means
//! it), and a `[metrics]` table under a manoeuvre with no step-steer
//! metrics, which the run sets aside (said with its line).

use crate::error::ScenarioRemark;
use crate::io::toml_file::TomlSource;
use crate::io::MeasuredRun;
use crate::manoeuvre::Manoeuvre;
use crate::vehicle::VehicleModel;

/// The `kind` of a manoeuvre as a scenario writes it.
pub(super) fn kind_name(spec: &super::ManoeuvreSpec) -> &'static str {
    use super::ManoeuvreSpec as S;
    match spec {
        S::StepSteer(_) => "step-steer",
        S::RampSteer(_) => "ramp-steer",
        S::Sine(_) => "sine",
        S::Sweep(_) => "sweep",
        S::Replay(_) => "replay",
        S::Schedule(_) => "schedule",
    }
}

/// The key that scales a measured bank profile.
const BANK_SCALE_KEY: &str = "model.effects.bank_profile_scale";

/// A replay of `run` on `model`: where the run logs a `bank` and the
/// scenario `src` gives no `bank_profile_scale`, the road is the run's
/// bank as measured (scale 1), said as a note.
pub(super) fn apply_bank(
    src: &TomlSource,
    run: &MeasuredRun,
    model: &mut VehicleModel,
) -> Option<ScenarioRemark> {
    let bank = run.bank.as_ref()?;
    if src.key_span(BANK_SCALE_KEY).is_some() {
        return None;
    }
    model.options.effects.bank_profile_scale = 1.0;
    let range = bank
        .iter()
        .fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], &b| {
            [lo.min(b), hi.max(b)]
        });
    Some(ScenarioRemark::BankApplied { range })
}

/// A `[metrics]` table in `src` that manoeuvre `m` does not read: only a
/// step steer has the metrics its windows and filter set.
pub(super) fn metrics_unused(
    src: &TomlSource,
    m: &Manoeuvre,
    kind: &'static str,
) -> Option<ScenarioRemark> {
    if matches!(m, Manoeuvre::StepSteer(_)) {
        return None;
    }
    let span = src.key_span("metrics")?;
    let (line, _) = crate::io::toml_file::line_col(&src.text, span.start);
    Some(ScenarioRemark::MetricsUnused { line, kind })
}
