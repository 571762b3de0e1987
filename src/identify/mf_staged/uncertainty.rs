//! How well a stage's rows determine its free parameters at the optimum:
//! standard errors `cov = s²·(JᵀJ)⁻¹` with `s² = Σe²/(m−n)`, on the
//! column-scaled Jacobian (SVD, pseudo-inverse), each parameter's effect
//! on the channel (one standard error, alone, as a fraction of the
//! channel's RMS over the rows), the condition number and the parameters
//! of the weakest direction; and the rule that calls a parameter not
//! identifiable ([`identifiability_warning`]).

use super::problem::{unbounded, StageProblem};
use crate::identify::determined::effect_words;
use crate::optim::local::Residuals;

/// The uncertainty of a stage's free parameters at a point.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Uncertainty {
    /// Standard error of each free parameter (`None`: the data do not
    /// move it, or no covariance).
    pub(super) std_error: Vec<Option<f64>>,
    /// One standard error's effect on the channel, alone, as a fraction of
    /// its RMS over the rows (`se·‖∂F/∂p‖/‖F‖`).
    pub(super) effect: Vec<f64>,
    /// Condition number of the column-scaled Jacobian.
    pub(super) condition: f64,
    /// The warning of a near-singular Jacobian (condition number above
    /// 1e8), naming the parameters of its weakest direction.
    pub(super) near_singular: Option<String>,
    /// `(JᵀJ)⁺` of the column-scaled Jacobian, and the columns' norms.
    scaled_cov: Option<nalgebra::DMatrix<f64>>,
    norms: Vec<f64>,
    /// The decrease of the cost ½·Σe² an undamped Gauss–Newton step from
    /// the point predicts, `½·gᵀ(JᵀJ)⁺g` with `g = Jᵀe`: what is left to
    /// gain there, to first order.
    pub(super) remaining: f64,
    /// The residual variance `s² = Σe²/(m−n)`.
    pub(super) s2: f64,
}

impl Uncertainty {
    /// The change of every free parameter that best keeps the fit when
    /// parameter `k` moves by `dv`: to first order the others' regression
    /// on it, `Σ_jk/Σ_kk·dv` (`dv` itself for `k`), so that a parameter
    /// held away from its fitted value starts the refit with the rest
    /// moved along the direction they trade on (`QBZ4·γ` against
    /// `QBZ5·|γ|` on cambers of one sign); only `dv` where there is no
    /// covariance.
    pub(super) fn compensating(&self, k: usize, dv: f64) -> Vec<f64> {
        let n = self.norms.len();
        let mut d = vec![0.0; n];
        d[k] = dv;
        let Some(c) = &self.scaled_cov else {
            return d;
        };
        let ckk = c[(k, k)];
        if !(ckk > 0.0 && self.norms[k] > 0.0) {
            return d;
        }
        for (j, dj) in d.iter_mut().enumerate() {
            if j != k && self.norms[j] > 0.0 {
                *dj = c[(j, k)] * self.norms[k] / (ckk * self.norms[j]) * dv;
            }
        }
        d
    }

    /// Whether the point is at the optimum to the precision the holds are
    /// judged with: a Gauss–Newton step would lower the cost by less than
    /// a tenth of the half residual variance that tells two holds apart
    /// (`holds.rs`). A stage stopped on its iteration cap there (its
    /// relative decrease per iteration still above 1e-12) has converged
    /// for every purpose the report serves; one that is not, has not.
    pub(super) fn at_optimum(&self) -> bool {
        self.remaining < 0.05 * self.s2
    }

    /// The free parameter whose estimate is most correlated with `k`'s,
    /// with the correlation `Σ_jk/sqrt(Σ_jj·Σ_kk)` (the columns' scaling
    /// cancels), where its magnitude reaches `least`.
    pub(super) fn partner(&self, k: usize, least: f64) -> Option<(usize, f64)> {
        let c = self.scaled_cov.as_ref()?;
        let seen = |j: usize| self.norms[j] > 0.0 && c[(j, j)] > 0.0;
        if !seen(k) {
            return None;
        }
        (0..self.norms.len())
            .filter(|&j| j != k && seen(j))
            .map(|j| (j, c[(j, k)] / (c[(j, j)] * c[(k, k)]).sqrt()))
            .filter(|(_, r)| r.is_finite() && r.abs() >= least)
            .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
    }

    /// Whether free parameter `k`, at `value`, is not identifiable.
    pub(super) fn flagged(&self, k: usize, value: f64) -> bool {
        match self.std_error[k] {
            None => true,
            Some(se) => identifiability_warning(value, se, self.effect[k]).is_some(),
        }
    }

    /// The warning of free parameter `k` at `value`, if any.
    pub(super) fn warning(&self, k: usize, value: f64) -> Option<String> {
        match self.std_error[k] {
            None => Some("no sensitivity: the data do not move it".into()),
            Some(s) => identifiability_warning(value, s, self.effect[k]),
        }
    }
}

/// The uncertainty of `problem`'s free parameters at `p`.
pub(super) fn uncertainty(problem: &StageProblem, p: &[f64]) -> Uncertainty {
    let mut res = vec![0.0; problem.count()];
    problem.residuals(p, &mut res);
    let j = problem.jacobian(p, &res, &unbounded(p.len()));
    let (m, nf) = (problem.count(), p.len());
    let s2 = res.iter().map(|e| e * e).sum::<f64>() / (m - nf).max(1) as f64;
    let norms: Vec<f64> = (0..nf).map(|k| j.column(k).norm()).collect();
    let mut js = j.clone();
    for (k, nk) in norms.iter().enumerate() {
        if *nk > 0.0 {
            js.column_mut(k).scale_mut(1.0 / nk);
        }
    }
    // The measured channel's norm over the rows: the scale of a
    // parameter's effect (see `identifiability_warning`).
    let y_norm = problem
        .rows
        .iter()
        .map(|r| problem.stage.measured(r).powi(2))
        .sum::<f64>()
        .sqrt()
        .max(f64::MIN_POSITIVE);
    let svd = js.clone().svd(false, true);
    let sv = &svd.singular_values;
    let (smax, smin) = (sv.max(), sv.min());
    let condition = if smin > 0.0 {
        smax / smin
    } else {
        f64::INFINITY
    };
    let jtj = js.transpose() * &js;
    let cov = jtj.pseudo_inverse(1e-14).ok();
    let g = js.transpose() * nalgebra::DVector::from_column_slice(&res);
    let remaining = cov
        .as_ref()
        .map_or(f64::INFINITY, |c| 0.5 * (g.transpose() * c * &g)[(0, 0)]);
    let near_singular = (condition > 1e8).then(|| {
        // The weakest direction: the right singular vector of the smallest
        // singular value names the parameters that trade off.
        let mut weak = String::new();
        if let Some(vt) = &svd.v_t {
            let kmin = (0..sv.len())
                .min_by(|a, b| sv[*a].total_cmp(&sv[*b]))
                .unwrap_or(0);
            let row = vt.row(kmin);
            let mut w: Vec<(usize, f64)> = row.iter().map(|v| v.abs()).enumerate().collect();
            w.sort_by(|a, b| b.1.total_cmp(&a.1));
            weak = w
                .iter()
                .take(3)
                .filter(|x| x.1 > 0.2)
                .map(|x| problem.names[x.0])
                .collect::<Vec<_>>()
                .join(", ");
        }
        singular_text(problem, &norms, condition, &weak)
    });
    let std_error: Vec<Option<f64>> = (0..nf)
        .map(|k| {
            cov.as_ref()
                .and_then(|c| (norms[k] > 0.0).then(|| (s2 * c[(k, k)]).max(0.0).sqrt() / norms[k]))
        })
        .collect();
    let effect = (0..nf)
        .map(|k| std_error[k].map_or(0.0, |s| s * norms[k] / y_norm))
        .collect();
    Uncertainty {
        std_error,
        effect,
        condition,
        near_singular,
        scaled_cov: cov,
        norms,
        remaining,
        s2,
    }
}

/// The warning of a near-singular Jacobian. A parameter whose column is 0
/// (no effect on any row: `PCY1` with `PKY1` held at 0) makes it singular,
/// its condition number infinite; a number that is no number is never
/// printed (it read "condition number inf"): the columns are named.
fn singular_text(problem: &StageProblem, norms: &[f64], condition: f64, weak: &str) -> String {
    let dead: Vec<&str> = norms
        .iter()
        .zip(&problem.names)
        .filter(|(n, _)| **n == 0.0)
        .map(|(_, k)| *k)
        .collect();
    if !dead.is_empty() {
        format!(
            "singular Jacobian (a parameter has no effect on these rows: {}): the data do not determine it",
            dead.join(", ")
        )
    } else if !condition.is_finite() {
        format!("singular Jacobian: the data do not separate {weak} at all")
    } else {
        format!(
            "near-singular Jacobian (condition number {}): the data barely separate {weak}",
            crate::format::readable(condition, 3)
        )
    }
}

/// One standard error, alone, moving the stage's channel by less than this
/// fraction of its RMS is an uncertainty too small to matter.
pub(super) const EFFECT_FLOOR: f64 = 0.01;

/// The identifiability warning of a fitted parameter, or `None`.
///
/// The rule: a parameter is *not identifiable* when its standard error `se`
/// reaches its magnitude **and** one standard error of it, alone, moves
/// the stage's channel by at least [`EFFECT_FLOOR`] (1 %) of its RMS
/// (`effect = se·‖∂F/∂p‖/‖F‖`, over the stage's rows). The magnitude alone
/// is no scale for a parameter whose true value is zero (`SSZ*` of a file
/// without them: estimate 1e-7, standard error 1e-6, and the data pin the
/// moment to 1e-5 of its RMS): that parameter is identified, as zero. The
/// effect is the parameter's natural scale taken from the data: the change
/// of it that matters is the one that moves the fitted curve. It is large
/// where the data trade the parameter against others (a large variance
/// inflation: `RVY1` against `RVY4` where `cos(atan(RVY4·α))` is in its
/// 1/α regime) or barely see it, which is what the warning is for.
pub(super) fn identifiability_warning(value: f64, se: f64, effect: f64) -> Option<String> {
    if !se.is_finite() {
        return Some("not identifiable from these data (no finite standard error)".into());
    }
    (se >= value.abs() && effect >= EFFECT_FLOOR).then(|| {
        format!(
            "not identifiable from these data (standard error {} ≥ |value|; one standard error moves the fit by {})",
            crate::format::readable(se, 4),
            effect_words(100.0 * effect)
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A zero parameter pinned by the data is identified (as zero); one
    /// whose uncertainty spans its value and moves the fit is not; a
    /// well-determined large one is identified.
    #[test]
    fn a_parameter_identified_as_zero_is_not_flagged() {
        // SSZ1 of a file without it: 1e-7 ± 1e-6, moving Mz by 3e-5 of its RMS.
        assert_eq!(identifiability_warning(1e-7, 1e-6, 3e-5), None);
        // RVY4 in its 1/α regime: 72 ± 163, one SE moves Fy by 4 %.
        let w = identifiability_warning(72.0, 163.0, 0.04).unwrap();
        assert!(w.contains("moves the fit by 4.0 %"), "{w}");
        // Just below the effect floor, and a value larger than its SE.
        assert_eq!(identifiability_warning(0.0, 1.0, 0.0099), None);
        assert_eq!(identifiability_warning(-2.0, 1.9, 0.5), None);
        assert!(identifiability_warning(1.0, 1.0, EFFECT_FLOOR).is_some());
        assert!(identifiability_warning(1.0, f64::INFINITY, 0.0).is_some());
        // RHY1 under --start paper: 152.1 ± 30427, 5505749.1 % in digits.
        let w = identifiability_warning(152.1, 30427.0, 55057.491).unwrap();
        assert!(
            w.ends_with("moves the fit by more than 10 times the channel's RMS)"),
            "{w}"
        );
        let w = identifiability_warning(1.0, 2.0, 9.99).unwrap();
        assert!(w.contains("by 999.0 % of the channel's RMS"), "{w}");
    }
}
