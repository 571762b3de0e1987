//! A measured sideslip that moves against the base model's: logged in the
//! other sign convention (`diagnose::base::beta_sign`). Fitted, it leaves a
//! gap no effect explains, β carrying most of it; refused, it names the
//! runs, each with its correlation, and asks for the column negated.

use crate::format::plural;

/// Runs whose `beta` correlates negatively with the base model's β.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("`beta` moves against the base model's sideslip: their correlation is {correlation:.2} over the {samples} samples of the {} with a sideslip that swings; {} against it (correlation over samples): {}; in FORMATS.md's ISO 8855 signs a measured sideslip follows the model's in sign whatever its tyres (positive in a slow left turn, negative in a fast one): noise and a wrong size weaken the correlation towards 0, they do not reverse it; is `beta` in another sign convention? negate it", plural(self.judged, "run", "runs"), plural(self.against.len(), "run", "runs"), self.against.iter().map(|(run, k, n)| format!("{run} ({k:.2} over {n})")).collect::<Vec<_>>().join(", "))]
pub struct BetaAgainstModel {
    /// The correlation pooled over the runs judged.
    pub correlation: f64,
    /// The samples it is taken over.
    pub samples: usize,
    /// Each run against (a negative correlation), its correlation and the samples it is taken over.
    pub against: Vec<(String, f64, usize)>,
    /// The runs judged (a `beta` channel and a swing of the model's β).
    pub judged: usize,
}
