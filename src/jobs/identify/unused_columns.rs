//! Measured columns a swarm fit does not fit, said with their counts: a
//! magic-simple fit of the Hoosier rig file said nothing of its 59,965
//! values of `mz` (the model has no aligning moment), and a PAC89 fit of a
//! file with `mx` and `my` nothing of them (no swarm model fits the wheel
//! moments; the staged Magic Formula does), nor a Gim fit of a file with
//! pure longitudinal sweeps anything of their `fx` (Gim, the simple Magic
//! Formula and the linear tyre have no longitudinal force).

use super::SwarmReport;
use crate::error::Variable;
use crate::identify::data::RigData;
use crate::identify::grouping::Selected;
use crate::identify::Channel;

/// The finite values of the file's `mz`, `mx` and `my` (0: no column),
/// over the rows a selection (`--load`, `--pressure`, `--camber`) keeps
/// where one was asked for (`of_rows`: `total` is then the file's).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Measured {
    mz: usize,
    mx: usize,
    my: usize,
    /// The file's `mz` count where the counts are of a selection's rows.
    total_mz: Option<usize>,
    /// The `fx` of the pure longitudinal rows (of a selection's where
    /// one was asked for): said where no longitudinal force is fitted.
    /// Counted only where those rows (|alpha| ≤ 1e-3 rad) reach |kappa| ≥
    /// 0.01, a longitudinal sweep (`identify/pure.rs`): a cornering
    /// sweep's three rows at alpha −0.001, 0, 0.001 and kappa 0 were said
    /// as "3 values of `fx` in the pure longitudinal rows not fitted".
    pure_fx: usize,
}

impl Measured {
    /// The counts of `data` (the file's rows) and its wheel moments read
    /// beside (`mx`, `my`).
    pub(super) fn of(data: &RigData, moments: &[Option<Vec<f64>>; 2]) -> Self {
        let finite =
            |v: Option<&Vec<f64>>| v.map_or(0, |v| v.iter().filter(|x| x.is_finite()).count());
        Measured {
            mz: finite(data.mz.as_ref()),
            mx: finite(moments[0].as_ref()),
            my: finite(moments[1].as_ref()),
            total_mz: None,
            pure_fx: 0,
        }
    }

    /// With the finite `fx` of `view` (the pure longitudinal rows, `None`:
    /// no slip-ratio sweep) counted over the levels `selected`.
    pub(super) fn with_pure_fx(self, view: Option<&RigData>, selected: &[Selected]) -> Self {
        let pure_fx = view.map_or(0, |v| {
            let Some((_, fx)) = v.longitudinal.as_ref() else {
                return 0;
            };
            kept_rows(v, selected)
                .filter(|&i| fx[i].is_finite())
                .count()
        });
        Measured { pure_fx, ..self }
    }

    /// The same over the rows of `data` whose load, camber and pressure
    /// lie in the levels `selected` (each level's samples' range, as the
    /// grouping finds them); `self` when nothing was selected. A magic-
    /// simple fit of the Hoosier file at one pressure and camber said
    /// 59,965 values of `mz` not fitted, the whole file's, of 7,494 rows
    /// selected.
    pub(super) fn of_rows(
        self,
        data: &RigData,
        moments: &[Option<Vec<f64>>; 2],
        selected: &[Selected],
    ) -> Self {
        if selected.is_empty() {
            return self;
        }
        let rows: Vec<usize> = kept_rows(data, selected).collect();
        let finite = |v: Option<&Vec<f64>>| {
            v.map_or(0, |v| rows.iter().filter(|&&i| v[i].is_finite()).count())
        };
        Measured {
            mz: finite(data.mz.as_ref()),
            mx: finite(moments[0].as_ref()),
            my: finite(moments[1].as_ref()),
            total_mz: Some(self.mz),
            pure_fx: self.pure_fx,
        }
    }
}

/// The rows of `data` whose load, camber and pressure lie in the levels
/// `selected` (each level's samples' range); every row where none is.
fn kept_rows<'a>(data: &'a RigData, selected: &'a [Selected]) -> impl Iterator<Item = usize> + 'a {
    let value = move |v: Variable, i: usize| match v {
        Variable::Load => Some(data.fz[i]),
        Variable::Camber => Some(data.camber[i]),
        Variable::Pressure => data.pressure.as_ref().map(|p| p[i]),
    };
    (0..data.len()).filter(move |&i| {
        selected
            .iter()
            .all(|s| value(s.variable, i).is_some_and(|v| s.level.holds(v)))
    })
}

/// The notes on the measured columns `r`'s fits left out: `mz` where no
/// aligning moment was fitted (nor a linear tyre's trail taken from it),
/// the pure longitudinal rows' `fx` where no longitudinal force was,
/// `mx` and `my` always.
pub(super) fn unused_notes(r: &SwarmReport) -> Vec<String> {
    let m = r.measured;
    let model = &r.options.model;
    let trail = r.linear_window.as_ref().and_then(|w| w.judged_trail());
    // Alpha 0 throughout: `mz` is said with the lateral columns set aside.
    let mz_left = r.aligning.is_none() && trail.is_none() && r.flat_alpha.is_none();
    let no_aligning = r.tyre.aligning_names().is_empty();
    let mz_why = match no_aligning {
        true => format!("the {model} model has no aligning moment"),
        false => format!("the {model} fit's aligning moment was not fitted"),
    };
    let moments = format!("the {model} model has no wheel moments (the staged Magic Formula, --model mf61 or mf62, fits `mx` and `my`)");
    // A model with a longitudinal block says its `no longitudinal data`
    // line instead.
    let fx_left = r.fit.channel == Channel::LateralForce && r.tyre.longitudinal_names().is_empty();
    let fx_why = format!("the {model} model has no longitudinal force (pac89 and unitire fit `fx`, as do mf61 and mf62)");
    [
        (m.mz * usize::from(mz_left), "mz", mz_why),
        (m.pure_fx * usize::from(fx_left), "fx", fx_why),
        (m.mx, "mx", moments.clone()),
        (m.my, "my", moments),
    ]
    .into_iter()
    .filter(|(n, _, _)| *n > 0)
    .map(|(n, column, why)| {
        let of_file = match (column, m.total_mz) {
            ("mz", Some(total)) => format!(" in the rows selected (of {total} in the file)"),
            ("fx", Some(_)) => " in the pure longitudinal rows selected".to_string(),
            ("fx", None) => " in the pure longitudinal rows".to_string(),
            (_, Some(_)) => " in the rows selected".to_string(),
            _ => String::new(),
        };
        format!(
            "{why}: {} of `{column}`{of_file} not fitted",
            crate::format::plural(n, "value", "values")
        )
    })
    .collect()
}
