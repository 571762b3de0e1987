//! A measured sideslip that moves against the base model's: logged in the
//! other sign convention (`diagnose::base::beta_sign`). Fitted, it leaves a
//! gap no effect explains, β carrying most of it; refused, it names the
//! runs, each with its correlation, and asks for the column negated; where
//! the campaign as a whole moves with the model, it names every file whose
//! β moves against it, so that one rerun after negating them all passes
//! (naming one, the user heard of the next only after fixing the first).

use crate::format::plural;

/// Runs whose `beta` correlates negatively with the base model's β: all
/// of them pooled, or some files' while the other files' move with it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", self.said())]
pub struct BetaAgainstModel {
    /// The correlation pooled over the runs judged (unused where
    /// [`BetaAgainstModel::files`] is given: each file has its own).
    pub correlation: f64,
    /// The samples it is taken over.
    pub samples: usize,
    /// Each run against (a negative correlation), its correlation and the samples it is taken over.
    pub against: Vec<(String, f64, usize)>,
    /// The runs judged (a `beta` channel and a swing of the model's β).
    pub judged: usize,
    /// Where some files' β moves against the model and the other files'
    /// with it: those files and the other files' pooled correlation.
    pub files: Option<FilesAgainst>,
}

/// The files whose β moves against the base model's while the campaign's
/// other files' move with it.
#[derive(Debug, Clone, PartialEq)]
pub struct FilesAgainst {
    /// Each file, its runs' pooled correlation and the samples it is taken
    /// over, in the campaign's order.
    pub files: Vec<(String, f64, usize)>,
    /// The other files' pooled correlation.
    pub others: f64,
}

/// A correlation as the refusal prints it: two decimals, more where those
/// would round a small one to zero (`-0.004`, not `-0.00`, for a run
/// named as against).
fn k(v: f64) -> String {
    crate::format::fixed_apart(&[v], 2).swap_remove(0)
}

impl BetaAgainstModel {
    fn said(&self) -> String {
        let why = "in FORMATS.md's ISO 8855 signs a measured sideslip follows the model's in sign whatever its tyres (positive in a slow left turn, negative in a fast one): noise and a wrong size weaken the correlation towards 0, they do not reverse it";
        let runs = self
            .against
            .iter()
            .map(|(run, c, n)| format!("{run} ({} over {n})", k(*c)))
            .collect::<Vec<_>>()
            .join(", ");
        match &self.files {
            Some(FilesAgainst { files, others }) if files.len() == 1 => {
                let (file, c, n) = &files[0];
                format!(
                    "`beta` of {file} moves against the base model's sideslip: their correlation is {} over its {n} samples, while the other files' move with it ({}); {why}; a logger set up in the other sign convention for that file? negate its `beta` (or remove the column from it): scored as logged it leaves a gap no effect explains",
                    k(*c),
                    k(*others)
                )
            }
            Some(FilesAgainst { files, others }) => {
                let each = files
                    .iter()
                    .map(|(file, c, n)| format!("{file} ({} over {n} samples)", k(*c)))
                    .collect::<Vec<_>>()
                    .join(", ");
                format!(
                    "`beta` of {} moves against the base model's sideslip (correlation over samples): {each}, while the other files' move with it ({}); {why}; a logger set up in the other sign convention for those files? negate the `beta` of each (or remove the column from them): scored as logged they leave a gap no effect explains",
                    plural(files.len(), "file", "files"),
                    k(*others)
                )
            }
            None => format!(
                "`beta` moves against the base model's sideslip: their correlation is {} over the {} samples of the {} with a sideslip that swings; {} against it (correlation over samples): {runs}; {why}; is `beta` in another sign convention? negate it",
                k(self.correlation),
                self.samples,
                plural(self.judged, "run", "runs"),
                plural(self.against.len(), "run", "runs"),
            ),
        }
    }
}

/// Runs taken by the input checks beside runs they refused: their
/// `beta`'s sign is judged against the base model's sideslip
/// (`diagnose/base/beta_sign.rs`), fitted only once every run is taken, so
/// it has not been judged yet. Said in the refusal of the others
/// (fresh-eyes round 39: a yaw rate refused in one file, the user mended
/// it and only then heard of the other file's negated `beta`). The
/// sideslip has no kinematic sign test without the model (its sign
/// against the yaw rate changes with speed and tyres).
#[derive(Debug, Clone, PartialEq)]
pub struct BetaUnchecked {
    /// The other runs with a `beta` (their files), after the first, which
    /// the refusal is at.
    pub others: Vec<String>,
}

impl std::fmt::Display for BetaUnchecked {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (whose, is) = match self.others.len() {
            0 => (String::new(), "its sign is"),
            _ => (
                format!(" (and of {})", self.others.join(", ")),
                "their signs are",
            ),
        };
        write!(f, "taken, but its `beta`{whose} is not checked yet: {is} judged against the base model's sideslip, which is fitted only once every run is taken; mend the runs refused and rerun to have it checked (a `beta` in the other sign convention is refused then)")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two files logged in the other sign convention: both named in one
    /// refusal, each with its correlation (main named the first alone).
    #[test]
    fn every_file_against_the_model_is_named_in_one_refusal() {
        let e = BetaAgainstModel {
            correlation: f64::NAN,
            samples: 0,
            against: Vec::new(),
            judged: 4,
            files: Some(FilesAgainst {
                files: vec![("a.csv".into(), -0.99, 601), ("c.csv".into(), -0.97, 580)],
                others: 0.96,
            }),
        }
        .to_string();
        assert!(
            e.starts_with("`beta` of 2 files moves against the base model's sideslip (correlation over samples): a.csv (-0.99 over 601 samples), c.csv (-0.97 over 580 samples), while the other files' move with it (0.96)"),
            "{e}"
        );
        assert!(e.contains("negate the `beta` of each"), "{e}");
    }
}
