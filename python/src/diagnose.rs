//! The sim-to-real workflow from Python: `diagnose` a campaign, `synth`
//! a campaign on the virtual proving ground, `design` the next test, and
//! the verdict kinds a diagnosis names; reports as JSON.

use crate::errors::py_err;
use crate::{detached, json, run_job};
use handling::error::Error;
use handling::jobs;
use handling::jobs::synth::{truth_named, EffectName};
use pyo3::prelude::*;
use std::path::PathBuf;

/// The sim-to-real gap of a campaign (file or folder); report JSON
/// (`diagnosis.json`'s content).
#[pyfunction]
#[pyo3(signature = (campaign, out=None))]
pub(crate) fn diagnose(
    py: Python<'_>,
    campaign: PathBuf,
    out: Option<PathBuf>,
) -> PyResult<String> {
    let r = run_job(
        py,
        out.is_some(),
        || jobs::diagnose::run(&campaign, out.as_deref()),
        |r| r.write(),
    )?;
    json(&r)
}

/// The cases a diagnosis's verdict can be (`verdict.kind` in
/// `diagnosis.json`), as the library names them.
#[pyfunction]
pub(crate) fn verdict_kinds() -> Vec<&'static str> {
    handling::diagnose::VerdictKind::ALL
        .iter()
        .map(|k| k.name())
        .collect()
}

/// The virtual proving ground: writes a campaign folder `out` measured on
/// a truth model with the named effects on, driving `programme`
/// (`handling`, `oval` or `road-course`); report JSON.
#[pyfunction]
#[pyo3(signature = (out, effects=Vec::new(), seed=1, truth="augmented", programme="handling", drive=Vec::new(), duration=None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn synth(
    py: Python<'_>,
    out: PathBuf,
    effects: Vec<String>,
    seed: u64,
    truth: &str,
    programme: &str,
    drive: Vec<PathBuf>,
    duration: Option<f64>,
) -> PyResult<String> {
    let programme = programme.parse().map_err(py_err)?;
    let effects = effects
        .iter()
        .map(|e| e.parse::<EffectName>())
        .collect::<Result<Vec<_>, _>>()
        .map_err(py_err)?;
    let truth = truth_named(truth).map_err(py_err)?;
    let r = detached(py, || {
        let mut r = jobs::synth::run(&effects, seed, truth, programme, duration, &out)?;
        r.drive(&drive)?;
        r.write()?;
        Ok(r)
    })?;
    json(&r)
}

/// The next test to drive for the diagnosis in folder `diagnosis`
/// (`handling design`): `effects` names the candidates to separate (the
/// reference first, `a+b` a combination; default the confounded sets);
/// runs `measured` driven afterwards are measured against the first set.
/// Writes the outputs to `out` (default `<diagnosis>/design`); report JSON.
#[pyfunction]
#[pyo3(signature = (diagnosis, campaign=None, effects=Vec::new(), ay_share=0.8, max_ax=3.0, top=3, measured=Vec::new(), out=None))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn design(
    py: Python<'_>,
    diagnosis: PathBuf,
    campaign: Option<PathBuf>,
    effects: Vec<String>,
    ay_share: f64,
    max_ax: f64,
    top: usize,
    measured: Vec<PathBuf>,
    out: Option<PathBuf>,
) -> PyResult<String> {
    let set = effects
        .iter()
        .map(|c| {
            c.split('+')
                .map(|n| {
                    n.trim().parse::<EffectName>().and_then(|e| {
                        e.0.ok_or_else(|| {
                            handling::error::OptionsError::UnknownName {
                                what: handling::error::NameKind::Effect,
                                given: n.trim().to_string(),
                                known: handling::diagnose::effects::EffectKind::ALL
                                    .iter()
                                    .map(|k| k.name())
                                    .collect(),
                            }
                            .into()
                        })
                    })
                })
                .collect::<Result<Vec<_>, Error>>()
        })
        .collect::<Result<Vec<_>, _>>()
        .map_err(py_err)?;
    let request = handling::design::DesignRequest {
        sets: (!set.is_empty()).then(|| vec![set]),
        ay_share,
        ax: max_ax,
        top,
        ..Default::default()
    };
    let r = detached(py, || {
        let r = jobs::design::run(
            &diagnosis,
            campaign.as_deref(),
            &request,
            &measured,
            out.as_deref(),
        )?;
        r.write()?;
        Ok(r)
    })?;
    json(&r)
}
