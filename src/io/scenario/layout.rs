//! A scenario file's layout, checked before its tables are deserialised:
//! a file of another kind given as a scenario (a run or rig CSV, a `.tir`,
//! a tyre TOML, a JSON report, a binary file), named as what it is instead
//! of the TOML parser's first complaint; `[simulation]` and `[integrator]`
//! both written (one table under two names: serde's "duplicate field" at
//! line 1 named neither); and the names of `diagnose`'s effects in
//! `[model.effects]`: those of the measurement (sensors, the steer path),
//! which a scenario of the car alone has no place for, and those a
//! scenario sets under another key (`[road] friction`, `[vehicle]
//! yaw_inertia`, …), pointed there.

use crate::diagnose::effects::EffectKind;
use crate::error::{FileKind, InputError, InputProblem, ScenarioProblem};
use crate::io::toml_file::TomlSource;
use std::path::Path;

/// `diagnose`'s effects of the measurement, not of the car (named from
/// the effect library, so a renamed effect cannot leave this list behind).
pub(crate) const MEASUREMENT: [EffectKind; 7] = [
    EffectKind::SensorDelay,
    EffectKind::SensorBias,
    EffectKind::AccelerometerRoll,
    EffectKind::AccelerometerPosition,
    EffectKind::SteerPath,
    EffectKind::SteeringRatio,
    EffectKind::MountYaw,
];

/// `diagnose`'s effects whose numbers a scenario gives under another key.
const ELSEWHERE: [(EffectKind, &str); 5] = [
    (EffectKind::CorneringStiffness, "`[model.effects] cornering_stiffness_scale = [front, rear]` (a scale on each axle's slip)"),
    (EffectKind::BankProfile, "`[model.effects] bank_profile_scale` (the share of a replayed run's measured `bank`) and `road_bank` (a constant bank, rad)"),
    (EffectKind::RoadFriction, FRICTION),
    (EffectKind::YawInertia, "`[vehicle] yaw_inertia` (kg·m²)"),
    (EffectKind::LoadTransferDistribution, "`[vehicle] load_transfer_front_share` (the front axle's share of the lateral load transfer)"),
];

/// Where a scenario sets the road's friction (also the answer to
/// `road_friction`'s parameter name, `friction_scale`, written as a key).
const FRICTION: &str = "`[road] friction` (a scale on the tyres' own friction)";

/// Where `key` of `[model.effects]` belongs when it names one of
/// `diagnose`'s effects a scenario takes elsewhere.
fn elsewhere(key: &str) -> Option<&'static str> {
    if key == "friction_scale" {
        return Some(FRICTION);
    }
    ELSEWHERE
        .iter()
        .find(|(e, _)| e.name() == key)
        .map(|(_, home)| *home)
}

/// The layout checks of a scenario's text `src`.
pub(super) fn check(src: &TomlSource) -> Result<(), InputError> {
    let Ok(doc) = toml_edit::ImDocument::parse(src.text.as_str()) else {
        return Ok(());
    };
    integration_tables(src, doc.as_table())?;
    effect_keys(src, doc.as_table())
}

/// `[simulation]` and `[integrator]` both: refused at the later one.
fn integration_tables(src: &TomlSource, root: &toml_edit::Table) -> Result<(), InputError> {
    let names = ["simulation", "integrator"];
    let mut at: Vec<(usize, &'static str)> = names
        .iter()
        .filter(|n| root.contains_key(n))
        .filter_map(|&n| Some((src.key_span(n)?.start, n)))
        .collect();
    if at.len() < 2 {
        return Ok(());
    }
    at.sort();
    let line = crate::io::toml_file::line_col(&src.text, at[0].0).0;
    let problem = ScenarioProblem::TwoIntegrationTables {
        first: (at[0].1, line),
        second: at[1].1,
    };
    let span = src.key_span(at[1].1);
    Err(src.located(span, InputProblem::Scenario(Box::new(problem))))
}

/// A `diagnose` effect's name among `[model.effects]`' keys.
fn effect_keys(src: &TomlSource, root: &toml_edit::Table) -> Result<(), InputError> {
    let Some(effects) = root
        .get("model")
        .and_then(|m| m.as_table_like())
        .and_then(|m| m.get("effects"))
        .and_then(|e| e.as_table_like())
    else {
        return Ok(());
    };
    for (key, _) in effects.iter() {
        let problem = if MEASUREMENT.iter().any(|e| e.name() == key) {
            ScenarioProblem::MeasurementEffect { key: key.into() }
        } else if let Some(home) = elsewhere(key) {
            ScenarioProblem::EffectElsewhere {
                key: key.into(),
                home,
            }
        } else {
            continue;
        };
        let span = src.key_span(&format!("model.effects.{key}"));
        return Err(src.located(span, InputProblem::Scenario(Box::new(problem))));
    }
    Ok(())
}

/// The error for the file at `path` when it is of another kind than a
/// scenario; None for a file that may be one (its own error stands).
pub(super) fn other_kind(path: &Path) -> Option<InputError> {
    let kind = crate::io::file_kind::recognise(path).filter(|k| *k != FileKind::Scenario)?;
    let problem = InputProblem::Scenario(Box::new(ScenarioProblem::NotAScenario(kind)));
    Some(InputError::problem(path, problem))
}
