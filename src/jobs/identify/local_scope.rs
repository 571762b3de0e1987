//! What `--local` chose in a swarm fit, said where the fit written was
//! polished otherwise. `--local` picks the polish of each channel's swarm
//! (Levenberg–Marquardt, Zhang & Li's 2017 Gauss–Newton, or none: the
//! swarm's best as it is); PAC89's two-stage identification (Zhang et al.
//! 2021) ends in its own Levenberg–Marquardt joint polish, part of that
//! method, and a parameter held as not determined by the data has the
//! rest refitted from the optimum by a polish, Levenberg–Marquardt under
//! `--local none` (`identify/undetermined.rs`). On the Hoosier file at
//! 83.4 kPa and 0°, `--local none`, `gn` and `lm` all wrote σ 2.525 % for
//! the lateral force, the two-stage result, without a word of why.

use super::choices::Polish;
use super::two_stage::Written;
use super::SwarmReport;
use crate::format::readable;
use crate::identify::{Fit, HeldFor};

/// The note saying which of the fits written `--local` did not polish
/// (`None`: `--local lm`, or it polished every one).
pub(crate) fn local_note(r: &SwarmReport) -> Option<String> {
    let local = r.options.local;
    if local == Polish::Lm {
        return None;
    }
    let mut said = Vec::new();
    if r.written == Some(Written::TwoStage) {
        let direct = r.two_stage.as_ref().map(|t| t.direct_sigma_percent);
        said.push(format!(
            "the lateral force written is PAC89's two-stage result, which ends in the Levenberg–Marquardt joint polish of its method (Zhang et al. 2021) whatever --local says; --local {} applied to the direct fit{}, which that result beat",
            local.as_str(),
            // With the digits the written line compares them with.
            direct.map_or(String::new(), |s| format!(" (σ {} % free)", readable(s, 6)))
        ));
    }
    let refitted: Vec<&str> = [Some(&r.fit), r.aligning.as_ref(), r.longitudinal.as_ref()]
        .into_iter()
        .flatten()
        .filter(|f| local == Polish::None && holds_undetermined(f))
        .map(|f| f.channel.quantity())
        .collect();
    if !refitted.is_empty() {
        said.push(format!(
            "the {} held what the data do not determine and refitted the rest from the optimum by Levenberg–Marquardt, as --local none has no polish to refit with",
            refitted.join(" and the ")
        ));
    }
    (!said.is_empty()).then(|| format!("--local {}: {}", local.as_str(), said.join("; ")))
}

/// Whether `f` holds a parameter because the data do not determine it.
fn holds_undetermined(f: &Fit) -> bool {
    f.parameters
        .iter()
        .any(|p| matches!(p.held, Some(HeldFor::Undetermined { .. })))
}
