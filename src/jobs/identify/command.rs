//! The command that reproduces a fit of `identify`: every option that
//! changes what is fitted (the model, the seed, the levels selected, the
//! polish, the thinning bins, a staged fit's start, template and
//! iteration cap, the holds), as the written file's header states it and
//! as `report.json` records it. Options that only name outputs (`--out`)
//! are left out; numbers are written as the shortest text that reads back
//! as the same value ([`exact`]), so the command fits the same data alike.

use super::Options;
use crate::format::exact;
use serde::Serialize;

/// A hold as recorded: the parameter and the value given.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RecordedHold {
    /// The parameter, as the tyre file names it.
    pub name: String,
    /// The value given, in the tyre file's units.
    pub value: f64,
}

/// The options of a fit that change it, as `report.json` records them
/// (`options`): those a model's fit does not read are left out.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RecordedOptions {
    /// The command line that reproduces the fit.
    pub command: String,
    /// `--model`.
    pub model: String,
    /// `--seed` (swarm fits).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// `--load`, N (swarm fits; null: every level pooled).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load: Option<Option<f64>>,
    /// `--pressure`, Pa (swarm fits; null: every level pooled).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pressure: Option<Option<f64>>,
    /// `--camber`, rad (swarm fits; null: every level pooled).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub camber: Option<Option<f64>>,
    /// `--local` (swarm fits).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub local: Option<&'static str>,
    /// `--bin-deg`.
    pub bin_deg: f64,
    /// `--bin-kappa` (swarm fits).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub bin_kappa: Option<f64>,
    /// `--start` (staged fits).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub start: Option<&'static str>,
    /// `--template` (staged fits; null: none).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub template: Option<Option<String>>,
    /// `--max-iterations` (staged fits).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_iterations: Option<usize>,
    /// `--hold`, in the order given.
    pub hold: Vec<RecordedHold>,
}

impl Options {
    /// The fit-changing options of `self`, with the command line.
    pub fn recorded(&self) -> RecordedOptions {
        let swarm = self.model.swarm_model().is_some();
        let staged = !swarm;
        RecordedOptions {
            command: self.command(),
            model: self.model.to_string(),
            seed: swarm.then_some(self.seed),
            load: swarm.then_some(self.load),
            pressure: swarm.then_some(self.pressure),
            camber: swarm.then_some(self.camber),
            local: swarm.then_some(self.local.as_str()),
            bin_deg: self.alpha_bin_deg,
            bin_kappa: swarm.then_some(self.kappa_bin),
            start: staged.then_some(self.start.as_str()),
            template: staged.then(|| self.template.as_ref().map(|t| t.display().to_string())),
            max_iterations: staged.then_some(
                self.max_iterations
                    .unwrap_or(crate::identify::mf_staged::LM_ITERATIONS),
            ),
            hold: self
                .hold
                .iter()
                .map(|(name, value)| RecordedHold {
                    name: name.clone(),
                    value: *value,
                })
                .collect(),
        }
    }

    /// `handling identify <data> --model … ` with every option that
    /// changes the fit of this model, defaults included (a default that
    /// changes later would otherwise change the fit the line names).
    pub fn command(&self) -> String {
        let mut words = vec![
            "handling identify".to_string(),
            quoted(&self.data.display().to_string()),
            format!("--model {}", self.model),
        ];
        if self.model.swarm_model().is_some() {
            words.push(format!("--seed {}", self.seed));
            if let Some(l) = self.load {
                words.push(format!("--load {}", exact(l)));
            }
            if let Some(p) = self.pressure {
                words.push(format!("--pressure {}", exact(p)));
            }
            if let Some(c) = self.camber {
                words.push(format!("--camber {}", exact(c)));
            }
            words.push(format!("--local {}", self.local.as_str()));
            words.push(format!("--bin-deg {}", exact(self.alpha_bin_deg)));
            words.push(format!("--bin-kappa {}", exact(self.kappa_bin)));
        } else {
            words.push(format!("--start {}", self.start.as_str()));
            if let Some(t) = &self.template {
                words.push(format!("--template {}", quoted(&t.display().to_string())));
            }
            // The default cap is left out: given, it would be honoured
            // where the default one continues a stage short of its optimum.
            if let Some(n) = self.max_iterations {
                words.push(format!("--max-iterations {n}"));
            }
            words.push(format!("--bin-deg {}", exact(self.alpha_bin_deg)));
        }
        words.extend(
            self.hold
                .iter()
                .map(|(n, v)| format!("--hold {n}={}", exact(*v))),
        );
        words.join(" ")
    }
}

/// A path as a shell reads it back: in single quotes when it holds a
/// character the shell would split or expand at.
fn quoted(s: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "/._-+,:@%".contains(c);
    if !s.is_empty() && s.chars().all(plain) {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', r"'\''"))
    }
}

#[cfg(test)]
mod tests {
    use super::quoted;

    #[test]
    fn a_path_the_shell_would_split_is_quoted() {
        assert_eq!(quoted("/data/rig.csv"), "/data/rig.csv");
        assert_eq!(quoted("my rig.csv"), "'my rig.csv'");
        assert_eq!(quoted("it's.csv"), r"'it'\''s.csv'");
    }
}
