//! A measured sideslip that moves against the base model's: logged in the
//! other sign convention (`diagnose::base::beta_sign`). Fitted, it leaves a
//! gap no effect explains, β carrying most of it; refused, it names the
//! runs, each with its correlation, and asks for the column negated.

use crate::format::plural;

/// Runs whose `beta` correlates negatively with the base model's β: all
/// of them pooled, or one file's while the other files' move with it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}", self.said())]
pub struct BetaAgainstModel {
    /// The correlation pooled over the runs judged (of the one file, where
    /// [`BetaAgainstModel::others`] is given).
    pub correlation: f64,
    /// The samples it is taken over.
    pub samples: usize,
    /// Each run against (a negative correlation), its correlation and the samples it is taken over.
    pub against: Vec<(String, f64, usize)>,
    /// The runs judged (a `beta` channel and a swing of the model's β).
    pub judged: usize,
    /// Where one file's β moves against the model and the other files'
    /// with it: that file and the other files' pooled correlation.
    pub others: Option<(String, f64)>,
}

impl BetaAgainstModel {
    fn said(&self) -> String {
        let why = "in FORMATS.md's ISO 8855 signs a measured sideslip follows the model's in sign whatever its tyres (positive in a slow left turn, negative in a fast one): noise and a wrong size weaken the correlation towards 0, they do not reverse it";
        let runs = self
            .against
            .iter()
            .map(|(run, k, n)| format!("{run} ({k:.2} over {n})"))
            .collect::<Vec<_>>()
            .join(", ");
        match &self.others {
            Some((file, others)) => format!(
                "`beta` of {file} moves against the base model's sideslip: their correlation is {:.2} over its {} samples, while the other files' move with it ({others:.2}); {why}; a logger set up in the other sign convention for that file? negate its `beta` (or remove the column from it): scored as logged it leaves a gap no effect explains",
                self.correlation, self.samples
            ),
            None => format!(
                "`beta` moves against the base model's sideslip: their correlation is {:.2} over the {} samples of the {} with a sideslip that swings; {} against it (correlation over samples): {runs}; {why}; is `beta` in another sign convention? negate it",
                self.correlation,
                self.samples,
                plural(self.judged, "run", "runs"),
                plural(self.against.len(), "run", "runs"),
            ),
        }
    }
}
