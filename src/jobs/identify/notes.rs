//! What a swarm fit of `identify` tells its user beside the numbers, on
//! the terminal and in the written file's header alike: a parameter one
//! fit held and a later one fitted (Gim's contact length, fitted to the
//! aligning moment), and a channel the model does not follow (an aligning
//! moment's σ above [`LARGE_SIGMA_PERCENT`]), and a block of the model
//! no fit ran on for want of its columns (a longitudinal-only rig file
//! fitted with PAC89 or UniTire keeps the defaults' lateral coefficients),
//! in the words of the Magic Formula's `no longitudinal data` line; and
//! the warnings on the fit's inputs (levels pooled into a model without
//! terms for them) and on its parameters (not identified, past a bound);
//! and, for a channel whose parameters the data did not all determine,
//! which were held and its σ before and after (`identify/undetermined.rs`).

use super::level_names::LevelNames;
use super::SwarmReport;
use crate::format::{fixed, readable};
use crate::identify::mf_staged::MIN_POINTS_PER_PARAMETER;
use crate::identify::{Channel, Fit, HeldFor, ParameterReport};
use crate::jobs::tyre_eval::{gives_none, Output};
use serde::Serialize;

/// The σ of a fitted channel above which the model is said not to follow
/// the data, %: a fit that misses by a fifth of the measured values.
pub(crate) const LARGE_SIGMA_PERCENT: f64 = 20.0;

/// A line of what the fit tells: a plain statement, or a warning.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Note {
    /// The text, without a mark.
    pub text: String,
    /// A warning (said `warning:`).
    pub warning: bool,
}

impl Note {
    pub(crate) fn said(text: String) -> Self {
        Note {
            text,
            warning: false,
        }
    }
    pub(crate) fn warned(text: String) -> Self {
        Note {
            text,
            warning: true,
        }
    }

    /// The note as a line after `mark` (`  ` on the terminal, `#` in a
    /// TOML file).
    pub(crate) fn line(&self, mark: &str) -> String {
        let w = if self.warning { "warning: " } else { "" };
        format!("{mark} {w}{}", self.text)
    }
}

/// The notes of a fit's later channel `f` (the aligning moment, the
/// longitudinal force): each parameter the first fit held by design that
/// `f` fitted, with its value and standard error, and a warning when `f`'s
/// σ is large.
pub(crate) fn later_fit_notes(r: &SwarmReport, f: &Fit) -> Vec<Note> {
    let quantity = f.channel.quantity();
    let mut notes: Vec<Note> = f
        .parameters
        .iter()
        .filter(|p| p.free && held_by_design(&r.fit, &p.name))
        .map(|p| {
            let se = p.std_error.map_or("no standard error".into(), |s| {
                format!("standard error {}", readable(s, 2))
            });
            Note::said(format!(
                "{} = {} ({se}): fitted to the {quantity} (σ {} %), not to the {}",
                p.name,
                readable(p.value, 4),
                fixed(f.sigma_percent, 1),
                r.fit.channel.quantity()
            ))
        })
        .collect();
    if f.channel == Channel::AligningMoment {
        let length = super::contact_length::size_warning(&r.tyre, f.sigma_percent);
        notes.extend(length.map(Note::warned));
    }
    notes.extend(sigma_notes(f, &r.level_names()));
    notes
}

/// The warning of a fit whose σ passes [`LARGE_SIGMA_PERCENT`]; one at
/// 100 % or more is worse than no force at all (a sign the data flip, or a
/// model that cannot take their shape), and said so.
pub(crate) fn large_sigma(f: &Fit) -> Option<Note> {
    let quantity = f.channel.quantity();
    let worse = match f.sigma_percent >= 100.0 {
        true => ": it misses by more than a zero force would (is the column's sign the tyre's, as FORMATS.md fixes it?)",
        false => "",
    };
    (f.sigma_percent > LARGE_SIGMA_PERCENT).then(|| {
        Note::warned(format!(
            "the {quantity}'s σ is {} %: the {} model's {quantity} does not follow these data (a σ above {LARGE_SIGMA_PERCENT} % misses by more than a fifth of the measured values){worse}; do not rely on its {quantity}",
            fixed(f.sigma_percent, 1),
            f.model
        ))
    })
}

/// How many times the median condition's σ a condition's must pass to be
/// said: the Hoosier file's PAC89 fit gives 1.1–2.2 % at four loads and
/// 12.0 % at the lightest.
pub(crate) const OUTLYING_RATIO: f64 = 3.0;

/// The least σ of a condition said as outlying, %: below it, a curve is
/// followed well whatever its neighbours do.
pub(crate) const OUTLYING_FLOOR_PERCENT: f64 = 5.0;

/// The warning of a fit of three or more conditions whose σ at some
/// passes [`OUTLYING_RATIO`] times the median condition's and
/// [`OUTLYING_FLOOR_PERCENT`]: the model's laws of load, camber and
/// pressure do not carry its curve to them, which the σ over all points
/// (weighted to the heavy loads' large forces) hides.
pub(crate) fn outlying_conditions(f: &Fit, names: &LevelNames) -> Option<Note> {
    if f.curves.len() < 3 {
        return None;
    }
    let mut sigmas: Vec<f64> = f.curves.iter().map(|c| c.sigma_percent).collect();
    sigmas.sort_by(f64::total_cmp);
    let n = sigmas.len();
    let median = 0.5 * (sigmas[(n - 1) / 2] + sigmas[n / 2]);
    let limit = (OUTLYING_RATIO * median).max(OUTLYING_FLOOR_PERCENT);
    let out: Vec<String> = f
        .curves
        .iter()
        .filter(|c| c.sigma_percent > limit)
        .map(|c| {
            let pressure = c.pressure.map_or(String::new(), |p| {
                format!(", pressure {}", names.pressure(p))
            });
            format!(
                "Fz {}, camber {}{pressure} (σ {} %)",
                names.load(c.fz),
                names.camber(c.camber),
                fixed(c.sigma_percent, 1)
            )
        })
        .collect();
    (!out.is_empty()).then(|| {
        Note::warned(format!(
            "the {} misses {} at {}: more than {OUTLYING_RATIO} times the median condition's σ, {} % over the {n} conditions; {} (the σ over all points, weighted to the large forces, hides it): see its panel in the figure before relying on the tyre near {}",
            f.channel.quantity(),
            if out.len() == 1 { "one condition" } else { "conditions" },
            out.join("; "),
            fixed(median, 2),
            not_carried(f),
            if out.len() == 1 { "it" } else { "them" }
        ))
    })
}

/// Why a model misses a condition, by the laws it has: those of load,
/// camber and pressure that move its forces (found by behaviour, as the
/// pooled-levels warning finds them) do not carry its curve there; a
/// model with none (a linear tyre's `C·α`) has one curve for every
/// condition, and is not said to have laws it lacks.
fn not_carried(f: &Fit) -> String {
    let forces = |fz: f64, camber: f64, pressure: f64| {
        let p = f
            .tyre
            .evaluate_points(&[fz], &[0.02], &[0.02], &[camber], &[10.0], &[pressure]);
        (p[0].fx, p[0].fy, p[0].mz)
    };
    let base = forces(2000.0, 0.0, 2e5);
    let laws: Vec<&str> = [
        ("load", forces(4000.0, 0.0, 2e5)),
        ("camber", forces(2000.0, 0.05, 2e5)),
        ("pressure", forces(2000.0, 0.0, 2.5e5)),
    ]
    .into_iter()
    .filter(|(_, moved)| *moved != base)
    .map(|(law, _)| law)
    .collect();
    let model = f.model;
    match laws.as_slice() {
        [] => format!("the {model} model has no law of load, camber or pressure (one curve for every condition): it cannot follow them"),
        [one] => format!("the {model} model's law of {one} does not carry its curve there"),
        [first @ .., last] => format!(
            "the {model} model's laws of {} and {last} do not carry its curve there",
            first.join(", ")
        ),
    }
}

/// The warnings on a fitted channel's σ: as a whole
/// ([`large_sigma`]), and condition by condition
/// ([`outlying_conditions`]).
pub(crate) fn sigma_notes(f: &Fit, names: &LevelNames) -> Vec<Note> {
    large_sigma(f)
        .into_iter()
        .chain(outlying_conditions(f, names))
        .collect()
}

/// Whether `fit` holds its parameter `name` by the model's design.
fn held_by_design(fit: &Fit, name: &str) -> bool {
    fit.parameters
        .iter()
        .any(|p| p.name == name && p.held == Some(HeldFor::ByDesign))
}

/// The blocks of the written tyre no fit ran on, for want of their
/// columns in the data: each says its coefficients are the model's
/// defaults (its start values at the data's median load), not fitted.
pub(crate) fn unfitted_notes(r: &SwarmReport) -> Vec<Note> {
    use crate::identify::Channel;
    let lateral = r.fit.channel == Channel::LateralForce;
    // Columns there without a sweep: an `fx` at kappa 0 beside a
    // cornering test.
    let no_kappa_sweep = match r.set_aside.kappa_reach {
        Some(reach) => format!(
            "no longitudinal-slip sweep: |kappa| reaches {} on the rows at alpha = 0, below the {} a sweep must reach",
            readable(reach, 3),
            crate::identify::pure::MIN_KAPPA_SWEEP
        ),
        None => match r.set_aside.missing_column {
            Some(column) => format!(
                "no `{column}` column in the data (its `{}` alone is no longitudinal test)",
                if column == "kappa" { "fx" } else { "kappa" }
            ),
            None => "no kappa/fx columns in the data".into(),
        },
    };
    let blocks: [(&str, &str, &str, bool); 3] = [
        (
            "lateral",
            "lateral force",
            match r.flat_alpha {
                // Columns there, set aside: alpha 0 throughout.
                Some(_) => "alpha is 0 throughout",
                None => "no alpha/fy columns in the data",
            },
            !lateral,
        ),
        (
            "aligning moment",
            "aligning moment",
            match r.flat_alpha {
                Some(_) => "alpha is 0 throughout",
                None => "no mz columns in the data",
            },
            r.aligning.is_none() && !r.tyre.aligning_names().is_empty(),
        ),
        (
            "longitudinal",
            "longitudinal force",
            &no_kappa_sweep,
            lateral && r.longitudinal.is_none() && !r.tyre.longitudinal_names().is_empty(),
        ),
    ];
    let unused = super::unused_columns::unused_notes(r);
    blocks
        .into_iter()
        .filter(|b| b.3)
        .map(|(data, quantity, columns, _)| {
            // Found by evaluating the written tyre, by `tyre-eval`'s rule
            // ([`gives_none`]): a model whose start values leave the
            // block at zero gives no force at all.
            let what = if data == "longitudinal" && gives_none(&r.tyre, Output::Fx).is_some() {
                format!(
                    "the written file's longitudinal force is 0 at any slip ratio (the {} model's longitudinal coefficients start at zero): fit rig data with kappa and fx for one",
                    r.options.model
                )
            } else {
                format!(
                    "the defaults' values (the {} model's start values at the data's median load)",
                    r.options.model
                )
            };
            Note::said(format!(
                "no {data} data: the file's {quantity} coefficients are not fitted ({columns}): {what}"
            ))
        })
        .chain(unused.into_iter().map(Note::said))
        .collect()
}

/// The note of a fit that held parameters the data do not determine:
/// which, where (the model's start values, or for a start value the data
/// reject the nearest value they allow), and its σ with them held against
/// fitted free.
pub(crate) fn undetermined_note(f: &Fit) -> Option<Note> {
    let Some(free) = f.free_sigma_percent else {
        // A restart that left nothing to hold: the fit written is the
        // free one, polished from the held fit's optimum.
        return f.free_swarm_sigma_percent.map(|swarm| {
            Note::said(format!(
                "{}: σ {} % fitted free, restarted from the optimum of the fit with what the data seemed not to determine held, which had beaten the free fit from the swarm's start (σ {} %); from there the data determine every parameter, and none is held",
                f.channel.quantity(),
                fixed(f.sigma_percent, 3),
                fixed(swarm, 3)
            ))
        });
    };
    let held: Vec<(&str, bool)> = f
        .parameters
        .iter()
        .filter_map(|p| match p.held {
            Some(HeldFor::Undetermined {
                stated, held_at, ..
            }) => Some((p, held_at != stated)),
            _ => None,
        })
        // Inside its own block a parameter goes without the block's
        // prefix (UniTire's `aligning.c3` is `c3` after "aligning
        // moment:"); the held lines keep the name --hold takes.
        .map(|(p, moved)| {
            let name = p.name.rsplit_once('.').map_or(p.name.as_str(), |(_, n)| n);
            (name, moved)
        })
        .collect();
    let names: Vec<&str> = held.iter().map(|h| h.0).collect();
    let one = names.len() == 1;
    let at = if held.iter().any(|h| h.1) {
        format!(
            "held at the model's start {} or, where the data reject {}, the nearest value they allow",
            if one { "value" } else { "values" },
            if one { "it" } else { "one" },
        )
    } else {
        format!(
            "held at the model's start {}",
            if one { "value" } else { "values" }
        )
    };
    // Where the held fit had beaten the free fit from the swarm's start,
    // the free fit was restarted from the held optimum: both said.
    let restart = f.free_swarm_sigma_percent.map_or(String::new(), |swarm| {
        let (swarm, held, _) = crate::format::distinct(swarm, f.sigma_percent, 3, 6);
        format!(
            " (restarted from the held fit's optimum: from the swarm's start the free fit had stopped at {swarm} %, above the held fit's {held} %)"
        )
    });
    // Two equal numbers read as a misprint: a hold that costs nothing to
    // the digits shown is said so.
    let (held, free) = (fixed(f.sigma_percent, 3), fixed(free, 3));
    let sigma = if held == free {
        format!("σ {held} % held, as fitted free (to 0.001 %)")
    } else {
        format!("σ {held} % held against {free} % fitted free")
    };
    Some(Note::said(format!(
        "{}: {} {at}, as the data do not determine {} (the held lines say how far): {sigma}{restart}",
        f.channel.quantity(),
        names.join(", "),
        if one { "it" } else { "them" },
    )))
}

/// Every note of `r`, in the order the terminal gives them.
pub(crate) fn notes(r: &SwarmReport) -> Vec<Note> {
    let fits = [Some(&r.fit), r.aligning.as_ref(), r.longitudinal.as_ref()];
    fits.into_iter()
        .flatten()
        .filter_map(undetermined_note)
        .chain(
            [r.aligning.as_ref(), r.longitudinal.as_ref()]
                .into_iter()
                .flatten()
                .flat_map(|f| later_fit_notes(r, f)),
        )
        .chain(sigma_notes(&r.fit, &r.level_names()))
        .chain(super::condition_values::own_values_note(r).map(Note::said))
        .chain(super::local_scope::local_note(r).map(Note::said))
        .chain(r.lifted.map(|l| Note::said(l.line())))
        .chain(r.at_rest.iter().map(|l| Note::said(l.clone())))
        .chain(unfitted_notes(r))
        .chain(r.curvature_held.as_ref().map(|x| Note::said(x.line())))
        .chain(r.pac89_reversal.map(|x| Note::warned(x.line())))
        .collect()
}

/// The warning on one fitted parameter, with its value, or else its
/// note ([`ParameterReport::note`]), said.
pub(crate) fn parameter_warning(p: &ParameterReport) -> Option<Note> {
    let value = crate::format::rounded(p.value, 4);
    match (p.warning.as_deref(), p.note.as_deref()) {
        (Some(w), _) => Some(Note::warned(format!("{} = {value}: {w}", p.name))),
        (None, Some(n)) => Some(Note::said(format!("{} = {value}: {n}", p.name))),
        (None, None) => None,
    }
}

impl SwarmReport {
    /// Warnings on the fit's inputs: levels pooled into a model without
    /// terms for them (a load, pressure or camber not selected).
    pub(crate) fn input_warnings(&self) -> Vec<String> {
        let o = &self.options;
        let pooled = [
            ("loads", "load", o.load, self.loads_pooled),
            ("pressures", "pressure", o.pressure, self.pressures_pooled),
            ("cambers", "camber", o.camber, self.cambers_pooled),
        ];
        // The lateral columns set aside first: what was fitted at all;
        // then the rows of combined slip.
        let combined = self.set_aside.combined_line(&o.model.to_string());
        let flat = self
            .small_forces
            .iter()
            .cloned()
            .chain(self.flat_alpha.iter().cloned())
            .chain(combined)
            .chain(coverage_warning(self))
            .chain(block_coverage_warnings(self));
        flat.chain(pooled
            .into_iter()
            .filter(|(_, _, selected, n)| selected.is_none() && *n > 1)
            .map(|(levels, option, _, n)| {
                format!(
                    "{n} {levels} pooled into one {} fit, which has no {option} terms: select one with --{option}",
                    o.model
                )
            }))
            .collect()
    }

    /// The warnings of the whole fit, as the file's header gives them:
    /// its inputs', then each channel's parameters'.
    pub(crate) fn warning_notes(&self) -> Vec<Note> {
        let inputs = self.input_warnings().into_iter().map(Note::warned);
        let fits = [
            Some(&self.fit),
            self.aligning.as_ref(),
            self.longitudinal.as_ref(),
        ];
        // A value given with --hold is said as held (the header's `held:`
        // lines), not warned of, as the terminal does.
        let hold = &self.options.hold;
        let params = fits.into_iter().flatten().flat_map(|f| &f.parameters);
        inputs
            .chain(
                params
                    .filter(|p| !held_as_given(p, hold))
                    .filter_map(parameter_warning),
            )
            .collect()
    }
}

/// Whether `p` is held at the value given for it with `--hold` (`hold`):
/// said as held, on the terminal and in the header alike, never warned of.
pub(crate) fn held_as_given(p: &ParameterReport, hold: &[(String, f64)]) -> bool {
    !p.free && hold.iter().any(|(h, _)| *h == p.name)
}

/// The slip angle a cornering sweep must reach, rad (4°), for a model
/// with a force peak to be fitted beyond its slope: a car tyre's lateral
/// force peaks at 4–8°, and below it friction and curvature are only
/// extrapolated. A linear tyre, fitted to its window, is not judged.
pub(crate) const MIN_PEAK_ALPHA: f64 = 0.0698;

/// The "N points for M free parameters" of a fit `f` with fewer than
/// [`MIN_POINTS_PER_PARAMETER`] points per free parameter.
fn too_few(f: &Fit) -> Option<String> {
    let points: usize = f.curves.iter().map(|c| c.points).sum();
    let free = f.parameters.iter().filter(|p| p.free).count();
    (points < MIN_POINTS_PER_PARAMETER * free).then(|| {
        format!(
            "{} for {} free parameters, fewer than the {MIN_POINTS_PER_PARAMETER} per parameter a fit needs to rest on the data rather than match them",
            crate::format::plural(points, "point", "points"),
            free
        )
    })
}

/// The warnings of the fits after the first (the aligning moment's, the
/// longitudinal force's) on too few points: a PAC89 longitudinal block of
/// 11 parameters was fitted to 18 points without a word.
fn block_coverage_warnings(r: &SwarmReport) -> Vec<String> {
    [&r.aligning, &r.longitudinal]
        .into_iter()
        .flatten()
        .filter_map(|f| {
            too_few(f).map(|few| {
                format!(
                    "the data are too few for the {} fit: {few}; do not rely on the tyre beyond the points",
                    f.channel.quantity()
                )
            })
        })
        .collect()
}

/// The warning of a first fit on too few or too narrow data: fewer than
/// [`MIN_POINTS_PER_PARAMETER`] points per free parameter, or (a
/// cornering fit of a model with a peak) slip angles within
/// [`MIN_PEAK_ALPHA`].
fn coverage_warning(r: &SwarmReport) -> Option<String> {
    let f = &r.fit;
    let mut said: Vec<String> = too_few(f).into_iter().collect();
    let reach = r.sample_slips[0].map(|(lo, hi)| lo.abs().max(hi.abs()));
    let linear = r.linear_window.is_some();
    if let (Some(reach), false) = (reach, linear) {
        if reach < MIN_PEAK_ALPHA {
            said.push(format!(
                "|alpha| reaches {} rad ({}°) only, below the {MIN_PEAK_ALPHA} rad (4°) past which a tyre's lateral force peaks: its friction and curvature are extrapolated, not fitted",
                crate::format::rounded(reach, 3),
                crate::format::rounded(reach.to_degrees(), 3)
            ));
        }
    }
    (!said.is_empty()).then(|| {
        format!(
            "the data are too few or too narrow for the {} fit: {}; do not rely on the tyre beyond the points",
            f.channel.quantity(),
            said.join("; ")
        )
    })
}
