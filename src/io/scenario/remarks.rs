//! What `simulate` says of a scenario as it reads it
//! ([`ScenarioRemark`]): a replayed run's `bank` column that does not act
//! (the scenario giving no `bank_profile_scale`: the road is flat, as in
//! `diagnose`'s base model) or a scale with no bank column to act on, an
//! `ax` column its speed says is in g or reversed, and a `[metrics]` table under a manoeuvre with no step-steer
//! metrics, which the run sets aside (said with its line).

use crate::error::ScenarioRemark;
use crate::io::toml_file::TomlSource;
use crate::io::MeasuredRun;
use crate::manoeuvre::Manoeuvre;
use crate::measured::ax_agreement::AxAgreement;

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

/// A replay of `run`: a `bank` column the scenario `src` gives no
/// `bank_profile_scale` for is said and left out (the base model drives a
/// flat road, as `diagnose`'s base does: whether the car felt the logged
/// bank, and how much of it, is its `bank_profile` effect's to fit); a
/// `bank_profile_scale` given for a run with no `bank` column acts on
/// nothing, and is said.
pub(super) fn bank_remark(src: &TomlSource, run: &MeasuredRun) -> Option<ScenarioRemark> {
    let given = src.key_span(BANK_SCALE_KEY);
    let Some(bank) = run.bank.as_ref() else {
        let span = given?;
        let (line, _) = crate::io::toml_file::line_col(&src.text, span.start);
        return Some(ScenarioRemark::BankScaleWithoutBank {
            line,
            kind: "replay",
        });
    };
    if given.is_some() {
        return None;
    }
    let range = bank
        .iter()
        .fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], &b| {
            [lo.min(b), hi.max(b)]
        });
    Some(ScenarioRemark::BankNotApplied { range })
}

/// A replayed run's `ax` that its speed says is in g or reversed
/// ([`AxAgreement`]).
pub(super) fn ax_remark(run: &MeasuredRun) -> Option<ScenarioRemark> {
    let agreement = AxAgreement::of(&run.t, &run.speed, run.ax.as_deref()?)?;
    agreement.reading()?;
    Some(ScenarioRemark::AxAgainstSpeed {
        slope: agreement.slope,
        correlation: agreement.correlation,
        windows: agreement.windows,
    })
}

/// A `bank_profile_scale` in `src` under a manoeuvre of `kind` that
/// replays no run: there is no logged bank for it to scale.
pub(super) fn bank_scale_unused(src: &TomlSource, kind: &'static str) -> Option<ScenarioRemark> {
    let span = src.key_span(BANK_SCALE_KEY)?;
    let (line, _) = crate::io::toml_file::line_col(&src.text, span.start);
    Some(ScenarioRemark::BankScaleWithoutBank { line, kind })
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

/// What is said of manoeuvre `m` as the file writes it (`spec`): a
/// `[metrics]` table it does not read, and a `bank_profile_scale` where it
/// replays no run (`replayed` false).
pub(super) fn of_manoeuvre(
    src: &TomlSource,
    spec: &super::ManoeuvreSpec,
    m: &Manoeuvre,
    replayed: bool,
) -> Vec<ScenarioRemark> {
    let kind = kind_name(spec);
    let mut said: Vec<ScenarioRemark> = metrics_unused(src, m, kind).into_iter().collect();
    if !replayed {
        said.extend(bank_scale_unused(src, kind));
    }
    said
}
