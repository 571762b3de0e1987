//! The library's integration tests: jobs and analyses called as functions
//! of `handling`, without the binary, on the bundled files and on
//! campaigns the proving ground generates in memory. What a user sees of
//! the command line is tested in `tests/cli/`; the unit tests sit beside
//! their code in `src/`.

use handling::diagnose::effects::EffectKind;
use handling::diagnose::{diagnose, DiagnoseSettings, Diagnosis};
use handling::proving_ground::{generate, truth_values, Noise, SynthSpec};
use std::path::PathBuf;
use std::sync::Arc;

#[path = "../support/memo.rs"]
mod memo;

/// The repository root.
pub(crate) fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A proving-ground campaign with `truth` withheld on noise `seed`,
/// diagnosed (library API, default settings, the run's seed `seed`) with
/// screening on or off against every effect but `hidden`.
pub(crate) fn diagnosed_afresh(
    truth: &[EffectKind],
    seed: u64,
    screening: bool,
    hidden: &[EffectKind],
) -> Diagnosis {
    let s = generate(&SynthSpec {
        effects: truth.iter().map(|e| (*e, truth_values(*e))).collect(),
        seed,
        noise: Noise::default(),
        programme: Default::default(),
    });
    let settings = DiagnoseSettings {
        seed,
        screening,
        ..Default::default()
    };
    let candidates = EffectKind::ALL
        .into_iter()
        .filter(|e| !hidden.contains(e))
        .collect();
    diagnose(&s.campaign(candidates, settings), None).unwrap()
}

/// [`diagnosed_afresh`], once per test run for each distinct campaign and
/// settings: the tests that read the same diagnosis (a pair found
/// together, screening that leaves it as it is) share one, each taking
/// half a minute of both cores.
pub(crate) fn diagnosed(
    truth: &[EffectKind],
    seed: u64,
    screening: bool,
    hidden: &[EffectKind],
) -> Arc<Diagnosis> {
    type Key = (Vec<EffectKind>, u64, bool, Vec<EffectKind>);
    static MADE: memo::Memo<Key, Arc<Diagnosis>> = memo::Memo::new();
    let key = (truth.to_vec(), seed, screening, hidden.to_vec());
    MADE.get(key, || {
        Arc::new(diagnosed_afresh(truth, seed, screening, hidden))
    })
}

mod derivatives;
mod diagnose;
mod identify;
mod screening;
