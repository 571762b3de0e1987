//! Which options of `identify` each fit reads: one table ([`FitOption::taken_by`]),
//! by which an option the model's fit would not read is refused, naming
//! it and why, as `--pressure` for the staged Magic Formula fit always was.
//! A `--template`, `--start` or `--max-iterations` given to a Gim fit, a
//! `--seed`, `--local` or `--bin-kappa` given to the staged fit, were
//! dropped without a word, and the user took the fit for one they shaped.
//! `--bin-deg` and `--hold` are read by every fit.

use super::IdentifyModel;
use crate::error::{Error, OptionsError};

/// An option of `identify` that only some fits read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FitOption {
    /// `--seed`: the swarm's.
    Seed,
    /// `--load`: one load level selected.
    Load,
    /// `--pressure`: one pressure level selected.
    Pressure,
    /// `--camber`: one camber level selected.
    Camber,
    /// `--local`: the polish after the swarm.
    Local,
    /// `--bin-kappa`: the slip-ratio bins of a swarm fit's thinning.
    BinKappa,
    /// `--start`: where the staged fit starts.
    Start,
    /// `--template`: the staged fit's `.tir` template.
    Template,
    /// `--max-iterations`: the staged fit's iterations per step.
    MaxIterations,
}

impl FitOption {
    /// The option as the command line spells it, without its dashes.
    pub fn flag(self) -> &'static str {
        match self {
            FitOption::Seed => "seed",
            FitOption::Load => "load",
            FitOption::Pressure => "pressure",
            FitOption::Camber => "camber",
            FitOption::Local => "local",
            FitOption::BinKappa => "bin-kappa",
            FitOption::Start => "start",
            FitOption::Template => "template",
            FitOption::MaxIterations => "max-iterations",
        }
    }

    /// Whether the fit of `model` reads the option: the swarm fits read
    /// the seed, the level selections, the polish and the slip-ratio bins;
    /// the staged Magic Formula fit its start, template and iterations.
    pub fn taken_by(self, model: IdentifyModel) -> bool {
        let swarm = model.swarm_model().is_some();
        match self {
            FitOption::Seed
            | FitOption::Load
            | FitOption::Pressure
            | FitOption::Camber
            | FitOption::Local
            | FitOption::BinKappa => swarm,
            FitOption::Start | FitOption::Template | FitOption::MaxIterations => !swarm,
        }
    }

    /// Why a fit that does not read the option does not.
    fn why_not(self) -> &'static str {
        match self {
            FitOption::Seed => "the staged Magic Formula fit runs Levenberg–Marquardt from its start (--start), no swarm, so it has no seed",
            FitOption::Local => "the staged Magic Formula fit is Levenberg–Marquardt throughout (Wei et al. 2010); --local chooses the polish after a swarm fit's swarm",
            FitOption::BinKappa => "the staged Magic Formula fit thins the slip angle only (--bin-deg), and fits every slip ratio",
            FitOption::Start | FitOption::Template | FitOption::MaxIterations => "only the staged Magic Formula fit (--model mf61, mf62) reads it; this model is fitted by a swarm and a local polish (--seed, --local)",
            // Said by their own error (`OptionsError::LevelSelectionNotTaken`).
            FitOption::Load | FitOption::Pressure | FitOption::Camber => "",
        }
    }
}

/// Refuses the first option of `given` the fit of `model` does not read,
/// in the order given.
pub fn check_given(model: IdentifyModel, given: &[FitOption]) -> Result<(), Error> {
    let Some(&option) = given.iter().find(|o| !o.taken_by(model)) else {
        return Ok(());
    };
    let flag = option.flag();
    Err(match option {
        FitOption::Load | FitOption::Pressure | FitOption::Camber => {
            OptionsError::LevelSelectionNotTaken {
                option: flag,
                model: model.to_string(),
            }
        }
        _ => OptionsError::OptionNotTaken {
            option: flag,
            model: model.to_string(),
            why: option.why_not(),
        },
    }
    .into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_fit_takes_its_own_options_and_refuses_the_others_by_name() {
        let gim: IdentifyModel = "gim".parse().unwrap();
        let mf = IdentifyModel::Mf61;
        assert!(check_given(gim, &[FitOption::Seed, FitOption::Local]).is_ok());
        assert!(check_given(mf, &[FitOption::Start, FitOption::Template]).is_ok());
        let e = check_given(gim, &[FitOption::Seed, FitOption::Template])
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with(
                "--template is not taken by --model gim: only the staged Magic Formula fit"
            ),
            "{e}"
        );
        let e = check_given(mf, &[FitOption::BinKappa])
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("--bin-kappa is not taken by --model mf61: "),
            "{e}"
        );
        let e = check_given(mf, &[FitOption::Pressure])
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("--pressure is not taken by --model mf61: "),
            "{e}"
        );
    }
}
