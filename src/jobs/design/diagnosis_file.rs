//! `diagnosis.json` as `design` reads it: the base tyres, the channels'
//! noise floors and scales, every candidate's fitted values (the ranking
//! and the combinations), the confounded and screened sets, the campaign
//! it diagnosed and its runs. Units as the diagnosis wrote them (SI, rad).

use crate::design::{Fitted, FittedCandidate, FittedValue, ScreenedOut};
use crate::diagnose::effects::EffectKind;
use crate::diagnose::Channel;
use crate::error::{Error, InputError, InputProblem};
use crate::tyre::Tyre;
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// `diagnosis.json` as the design reads it.
#[derive(Deserialize)]
struct DiagnosisFile {
    source: PathBuf,
    #[serde(default)]
    source_absolute: Option<PathBuf>,
    #[serde(default)]
    runs: Vec<PathBuf>,
    base: BaseFile,
    gap: GapFile,
    ranking: Vec<CandidateFile>,
    combinations: Vec<CandidateFile>,
    confounded: Vec<ConfoundedFile>,
    #[serde(default)]
    screened: Vec<ScreenedFile>,
    #[serde(default)]
    verdict: Option<VerdictFile>,
}

/// The verdict's candidates fitted far from off on a gap within noise.
#[derive(Deserialize)]
struct VerdictFile {
    #[serde(default)]
    far_from_off: Option<FarFile>,
    #[serde(default)]
    kind: Option<VerdictKind>,
}

/// The verdict's kind, as far as the design asks: whether it found no
/// significant gap (said when nothing was cross-validated).
#[derive(Deserialize, PartialEq)]
#[serde(rename_all = "snake_case")]
enum VerdictKind {
    NoSignificantGap,
    #[serde(other)]
    Other,
}

#[derive(Deserialize)]
struct FarFile {
    effects: Vec<String>,
    #[serde(default)]
    also: Vec<ConfoundedFile>,
}

#[derive(Deserialize)]
struct ScreenedFile {
    effects: Vec<String>,
    #[serde(default)]
    extends: Vec<String>,
    insample_reduction_percent: f64,
    threshold_percent: f64,
    margin_percent: f64,
}

#[derive(Deserialize)]
struct BaseFile {
    front: Tyre,
    rear: Tyre,
}

#[derive(Deserialize)]
struct GapFile {
    noise: Vec<NoiseFile>,
    noise_level: f64,
}

#[derive(Deserialize)]
struct NoiseFile {
    channel: String,
    noise_floor: f64,
    scale: f64,
    /// Absent from diagnoses older than session 96: the floor stands in.
    #[serde(default)]
    scatter: Option<f64>,
}

#[derive(Deserialize)]
struct CandidateFile {
    effects: Vec<String>,
    heldout_error_after: f64,
    parameters: Vec<ParameterFile>,
    axles: Option<Vec<AxleFile>>,
}

#[derive(Deserialize)]
struct ParameterFile {
    name: String,
    value: f64,
    std_error: Option<f64>,
    at_bound: bool,
    determined: bool,
}

#[derive(Deserialize)]
struct AxleFile {
    name: String,
    value: f64,
    std_error: Option<f64>,
    limit: Option<serde_json::Value>,
    held: bool,
}

#[derive(Deserialize)]
struct ConfoundedFile {
    effects: Vec<String>,
}

fn kinds(path: &Path, names: &[String]) -> Result<Vec<EffectKind>, Error> {
    names
        .iter()
        .map(|n| {
            EffectKind::from_name(n).ok_or_else(|| {
                InputError::problem(
                    path,
                    InputProblem::Json {
                        detail: format!("`{n}` is no effect of this release"),
                    },
                )
                .into()
            })
        })
        .collect()
}

fn candidate(path: &Path, c: &CandidateFile) -> Result<FittedCandidate, Error> {
    let nan = |se: Option<f64>| se.unwrap_or(f64::NAN);
    Ok(FittedCandidate {
        effects: kinds(path, &c.effects)?,
        parameters: c
            .parameters
            .iter()
            .map(|p| {
                FittedValue::new(
                    &p.name,
                    p.value,
                    nan(p.std_error),
                    p.determined && !p.at_bound,
                )
            })
            .collect(),
        axles: c.axles.as_ref().map(|a| {
            a.iter()
                .map(|x| {
                    let free = x.limit.as_ref().is_none_or(|l| l.is_null()) && !x.held;
                    FittedValue::new(&x.name, x.value, nan(x.std_error), free)
                })
                .collect()
        }),
        heldout_error: c.heldout_error_after,
    })
}

/// What a diagnosis says of its campaign.
pub struct Diagnosed {
    /// The campaign it read (a file or folder, as named then).
    pub source: PathBuf,
    /// The same made absolute when it was written (older diagnoses have
    /// none).
    pub source_absolute: Option<PathBuf>,
    /// The runs it diagnosed, as named then.
    pub runs: Vec<PathBuf>,
}

/// Reads what the design needs of the diagnosis in `dir`, and which
/// campaign and runs it diagnosed.
pub fn read_diagnosis(dir: &Path) -> Result<(Fitted, Diagnosed), Error> {
    let path = dir.join("diagnosis.json");
    let text = std::fs::read_to_string(&path).map_err(|source| InputError::Io {
        path: path.clone(),
        source,
    })?;
    let f: DiagnosisFile = serde_json::from_str(&text).map_err(|e| {
        InputError::problem_at(
            &path,
            e.line(),
            e.column(),
            InputProblem::Json {
                detail: e.to_string(),
            },
        )
    })?;
    let mut noise_floors = [0.0; 3];
    let mut scales = [1.0; 3];
    let mut start_noise = [0.0; 3];
    for n in &f.gap.noise {
        if let Some(c) = Channel::ALL.into_iter().find(|c| c.name() == n.channel) {
            noise_floors[c.index()] = n.noise_floor;
            scales[c.index()] = n.scale;
            start_noise[c.index()] = Fitted::start_noise_of(n.noise_floor, n.scatter);
        }
    }
    let fitted = Fitted {
        front: f.base.front,
        rear: f.base.rear,
        noise_floors,
        start_noise,
        scales,
        noise_level: f.gap.noise_level,
        candidates: f
            .ranking
            .iter()
            .chain(&f.combinations)
            .map(|c| candidate(&path, c))
            .collect::<Result<_, _>>()?,
        confounded: f
            .confounded
            .iter()
            .map(|c| kinds(&path, &c.effects))
            .collect::<Result<_, _>>()?,
        screened: f
            .screened
            .iter()
            .map(|s| {
                Ok(ScreenedOut {
                    effects: kinds(&path, &s.effects)?,
                    extends: kinds(&path, &s.extends)?,
                    insample_reduction_percent: s.insample_reduction_percent,
                    screen_percent: s.threshold_percent - s.margin_percent,
                })
            })
            .collect::<Result<_, Error>>()?,
        no_gap: f
            .verdict
            .as_ref()
            .is_some_and(|v| v.kind == Some(VerdictKind::NoSignificantGap)),
        noted: match f.verdict.and_then(|v| v.far_from_off) {
            Some(far) => std::iter::once(&far.effects)
                .chain(far.also.iter().map(|a| &a.effects))
                .map(|e| kinds(&path, e))
                .collect::<Result<_, _>>()?,
            None => Vec::new(),
        },
    };
    Ok((
        fitted,
        Diagnosed {
            source: f.source,
            source_absolute: f.source_absolute,
            runs: f.runs,
        },
    ))
}
