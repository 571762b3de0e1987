//! Why a parameter of a fit stands at a value it was not fitted to, as
//! the report and the terminal state it beside the value: given with
//! `--hold`, a term the data's levels cannot determine, one the model's
//! fit never frees, one the data did not determine when fitted
//! (`undetermined.rs`), or a constant of a written `.tir` that no
//! template gave.

use super::problem::Channel;
use super::spare::{held_at, lean_clause};
use crate::format::{exact, plural, readable};
use crate::tyre::Tyre;
use serde::Serialize;
use std::fmt;

/// What the swarm fits' stated value is, as a held line names it.
const START: &str = "the model's start value";

/// Where PAC89's start values come from: the only model whose terms the
/// camber levels free (`tyre/pac89.rs`).
const PAC89_START: &str =
    "PAC89's are the Adams/Tire documentation's example tyre's, whichever of its fits is written";

/// Why a value was held rather than fitted.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "why", rename_all = "kebab-case")]
pub enum HeldFor {
    /// The user gave it with `--hold`.
    Given,
    /// A term of the load, and the data have too few load levels.
    LoadLevels {
        /// Load levels in the data.
        have: usize,
    },
    /// A term of the camber, and the data have too few camber levels.
    CamberLevels {
        /// Camber levels in the data.
        have: usize,
    },
    /// The model's identification never frees it.
    ByDesign,
    /// PAC89's lateral curvature, held at or below its limit 1 where the
    /// free fit's reversed the force (`jobs/identify/curvature_hold.rs`).
    CurvatureLimit,
    /// Fitted free, the data did not determine it (its standard error
    /// reached its value and moved the channel by 1 % of its RMS, or it
    /// had none): held at the model's start value, or at the nearest value
    /// within two standard errors of the free fit where that lies beyond,
    /// and the rest refitted (`undetermined.rs`, `spare.rs`).
    Undetermined {
        /// Its value in the free fit.
        fitted: f64,
        /// Its standard error there (`None`: the Jacobian is singular
        /// along it).
        std_error: Option<f64>,
        /// One standard error's effect on the channel there, % of the
        /// channel's RMS (`None` without a standard error).
        effect_percent: Option<f64>,
        /// The model's start value, the value stated for it.
        stated: f64,
        /// The value held: `stated`, or the end of `fitted ± 2` standard
        /// errors nearest it where `stated` lies beyond (`spare.rs`).
        held_at: f64,
        /// How many standard errors `stated` lies from `fitted` (`None`
        /// without a standard error).
        standard_errors_away: Option<f64>,
    },
    /// A constant of a written `.tir`, set without a template.
    Constant {
        /// Where its value comes from.
        from: ConstantFrom,
    },
}

/// Where a `.tir` constant written without a template comes from.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ConstantFrom {
    /// The median load of the data (`FNOMIN`).
    MedianLoad,
    /// The median pressure of the data (`NOMPRES`).
    MedianPressure,
    /// No pressure column: 0, the pressure terms off (`NOMPRES`).
    NoPressure,
    /// The median rig speed (`LONGVL`).
    MedianSpeed,
    /// No speed column: the default speed (`LONGVL`).
    DefaultSpeed,
    /// The default radius: rig forces do not measure it (`UNLOADED_RADIUS`).
    DefaultRadius,
    /// The median pressure of the data, rounded to 100 Pa, in place of a
    /// template's `NOMPRES` outside the data's pressures (`NOMPRES`).
    OutsideData {
        /// The template's `NOMPRES`, Pa.
        template: f64,
        /// The data's lowest pressure, Pa.
        lo: f64,
        /// The data's highest pressure, Pa.
        hi: f64,
    },
    /// The median load of the data, rounded to 10 N, in place of a
    /// template's `FNOMIN` outside the data's loads (`FNOMIN`).
    LoadOutsideData {
        /// The template's `FNOMIN`, N.
        template: f64,
        /// The data's lowest load, N.
        lo: f64,
        /// The data's highest load, N.
        hi: f64,
    },
    /// The median pressure of the data, rounded to 100 Pa, where the
    /// template has no `NOMPRES` (0, its pressure terms off) and the data
    /// have a `pressure` column (`NOMPRES`).
    TemplateWithoutPressure,
    /// A template's size (`UNLOADED_RADIUS`, `WIDTH`, `VERTICAL_STIFFNESS`)
    /// kept: rig data do not measure it (`template_size.rs`).
    TemplateSize {
        /// Which size, and what it enters.
        field: super::template_size::SizeField,
        /// The template's `FNOMIN` before any recentring, N.
        template_fnomin: f64,
        /// The data's median load, N.
        data_load: f64,
    },
    /// A physical constant a fresh `.tir` states in place of 0
    /// (`INFLPRES`, `VERTICAL_STIFFNESS`, `WIDTH`, …: `tyre/mf/stated.rs`).
    Stated {
        /// Where its value comes from.
        from: crate::tyre::mf::stated::StatedFrom,
    },
    /// The median pressure of the data, rounded to 100 Pa, in place of a
    /// template's `INFLPRES` outside the data's pressures (`INFLPRES`).
    InflationOutsideData {
        /// The template's `INFLPRES`, Pa.
        template: f64,
        /// The data's lowest pressure, Pa.
        lo: f64,
        /// The data's highest pressure, Pa.
        hi: f64,
    },
}

impl fmt::Display for HeldFor {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            HeldFor::Given => f.write_str("given with --hold"),
            // Where the value comes from is said with it: PAC89's two fits
            // once held these at two values (the start's, and 0) in the
            // same words, whichever `--local` chose.
            HeldFor::LoadLevels { have } => write!(
                f,
                "load terms, which need more load levels than the data's {}: held at {START}s",
                plural(*have, "level", "levels")
            ),
            HeldFor::CamberLevels { have } => write!(
                f,
                "camber terms, which need more camber levels than the data's {}: held at {START}s ({PAC89_START}), so the file's response to camber is that tyre's, not one these data measured; give --hold with each to hold it elsewhere (0: no response to camber)",
                plural(*have, "level", "levels")
            ),
            HeldFor::ByDesign => f.write_str("not fitted by this model's identification"),
            HeldFor::CurvatureLimit => f.write_str(
                "the lateral curvature held at or below 1: fitted free, it rose above 1 and turned the lateral force around past its peak (see the note)",
            ),
            HeldFor::Undetermined {
                fitted,
                std_error: Some(se),
                effect_percent,
                stated,
                held_at: held,
                standard_errors_away,
            } => write!(
                f,
                "not determined by these data: fitted free it was {} ± {} (one standard error of it alone moves the fit by {:.1} % of the channel's RMS, which the other parameters' trade-off undoes), so it is {}, and the rest refitted",
                readable(*fitted, 4),
                readable(*se, 3),
                effect_percent.unwrap_or(f64::NAN),
                held_at(START, *stated, *held, *standard_errors_away)
            ),
            HeldFor::Undetermined {
                fitted,
                stated,
                held_at: held,
                ..
            } => write!(
                f,
                "not determined by these data: fitted free it was {} with no standard error (the fit is singular along it), so it is {} and the rest refitted",
                readable(*fitted, 4),
                held_at(START, *stated, *held, None)
            ),
            // (set in place of a template's, not for want of one)
            HeldFor::Constant {
                from:
                    from @ (ConstantFrom::OutsideData { .. }
                    | ConstantFrom::LoadOutsideData { .. }
                    | ConstantFrom::TemplateWithoutPressure
                    | ConstantFrom::TemplateSize { .. }
                    | ConstantFrom::InflationOutsideData { .. }),
            } => write!(f, "{from}"),
            HeldFor::Constant { from } => write!(f, "no --template: {from}"),
        }
    }
}

impl HeldFor {
    /// The reason as the held line of parameter `name` says it: its
    /// words, and for a value held off its stated one, the option that
    /// holds it where the user says (`spare.rs`).
    pub fn said(&self, name: &str) -> String {
        match self {
            HeldFor::Undetermined {
                stated,
                held_at,
                standard_errors_away,
                ..
            } => format!(
                "{self}{}",
                lean_clause(name, *stated, *held_at, *standard_errors_away)
            ),
            _ => self.to_string(),
        }
    }
}

impl fmt::Display for ConstantFrom {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let fixed = match self {
            ConstantFrom::MedianLoad => "the median load of the data, rounded to 10 N",
            ConstantFrom::MedianPressure => "the median pressure of the data, rounded to 100 Pa",
            ConstantFrom::NoPressure => "no `pressure` column, so 0 (the pressure terms off)",
            ConstantFrom::MedianSpeed => "the median rig speed of the data, read in m/s and rounded to 0.1 m/s (a `speed` column in km/h is read 3.6 times too fast: convert it to m/s)",
            ConstantFrom::DefaultSpeed => "no `speed` column, so the default",
            ConstantFrom::DefaultRadius => {
                "a default, as rig forces do not measure the radius (give --template with your tyre's)"
            }
            ConstantFrom::OutsideData { template, lo, hi } => {
                let (t, lo, hi) = (exact(*template), exact(*lo), exact(*hi));
                return write!(
                    f,
                    "the median pressure of the data, rounded to 100 Pa, in place of the \
                     template's {t} Pa, which lies outside the data's {lo} to {hi} Pa: the \
                     pressure terms are polynomials in dpi = (p − NOMPRES)/NOMPRES, and about \
                     the template's the fit would carry the peak friction in them, fitted at the \
                     data's dpi only and reaching {t} Pa by extrapolation (the blocks these data \
                     do not fit keep the template's coefficients, read about this pressure); to \
                     keep the template's, give --hold NOMPRES={t}"
                );
            }
            ConstantFrom::LoadOutsideData { template, lo, hi } => {
                let (t, lo, hi) = (exact(*template), exact(*lo), exact(*hi));
                return write!(
                    f,
                    "the median load of the data, rounded to 10 N, in place of the template's \
                     {t} N, which lies outside the data's {lo} to {hi} N: the load terms are \
                     polynomials in dfz = (Fz − FNOMIN)/FNOMIN, and about the template's every \
                     coefficient at nominal load (PDY1, PKY1) would be the data's laws carried \
                     to {t} N by extrapolation (the blocks these data do not fit keep the \
                     template's coefficients, read about this load); to keep the template's, \
                     give --hold FNOMIN={t}"
                );
            }
            ConstantFrom::TemplateWithoutPressure => {
                "the median pressure of the data, rounded to 100 Pa: the template has no \
                 NOMPRES (0 turns the pressure terms off, as MF 5.2 has none), and the data \
                 have a `pressure` column, which the pressure terms (PPX*, PPY*, PPZ*) are \
                 fitted to about it; to keep them off, give --hold NOMPRES=0"
            }
            ConstantFrom::TemplateSize {
                field,
                template_fnomin,
                data_load,
            } => {
                let said = super::template_size::kept_said(*field, *template_fnomin, *data_load);
                return f.write_str(&said);
            }
            ConstantFrom::Stated { from } => return write!(f, "{from}"),
            ConstantFrom::InflationOutsideData { template, lo, hi } => {
                let (t, lo, hi) = (exact(*template), exact(*lo), exact(*hi));
                return write!(
                    f,
                    "the median pressure of the data, rounded to 100 Pa, in place of the \
                     template's {t} Pa, which lies outside the data's {lo} to {hi} Pa: INFLPRES \
                     is the pressure a reader uses where the points give none, and the file \
                     would be evaluated there by extrapolation; to keep the template's, give \
                     --hold INFLPRES={t}"
                );
            }
        };
        f.write_str(fixed)
    }
}

/// Why each parameter of `channel` that `free` leaves out is held, for
/// data with `loads` load and `cambers` camber levels: a term freed with
/// more levels of one of them is held for want of those.
pub(super) fn held_reasons(
    start: &Tyre,
    channel: Channel,
    loads: usize,
    cambers: usize,
    free: &[bool],
) -> Vec<Option<HeldFor>> {
    // Many levels: what the data's own counts leave out is left out for
    // want of them.
    const MANY: usize = 1000;
    let more_loads = channel.free(start, MANY, cambers);
    let more_cambers = channel.free(start, loads, MANY);
    free.iter()
        .enumerate()
        .map(|(i, f)| {
            (!f).then(|| {
                if more_loads.get(i) == Some(&true) {
                    HeldFor::LoadLevels { have: loads }
                } else if more_cambers.get(i) == Some(&true) {
                    HeldFor::CamberLevels { have: cambers }
                } else {
                    HeldFor::ByDesign
                }
            })
        })
        .collect()
}

/// The block of `t` (any a fit fits) that has parameter `name`, and the
/// parameter's index in it.
fn place_of(t: &Tyre, name: &str) -> Option<(Channel, usize)> {
    [
        Channel::LateralForce,
        Channel::AligningMoment,
        Channel::LongitudinalForce,
    ]
    .into_iter()
    .find_map(|c| Some((c, c.names(t).iter().position(|n| n == name)?)))
}

/// The value of parameter `name` in tyre `t` (any block a fit fits), as
/// written: a held value is stated as the file holds it.
pub(crate) fn value_in(t: &Tyre, name: &str) -> Option<f64> {
    let (c, i) = place_of(t, name)?;
    c.parameters(t).get(i).copied()
}

/// The search box a fit keeps parameter `name` of `t` in (any block a
/// fit fits), in the tyre file's units; `None` when no block of `t` has it.
pub(crate) fn bounds_in(t: &Tyre, name: &str) -> Option<(f64, f64)> {
    let (c, i) = place_of(t, name)?;
    c.bounds(t).get(i).copied()
}

/// The parameters of `t`'s file that no channel's fit fits but that
/// `--hold` may set: a linear tyre's pneumatic trail, taken after its
/// lateral fit from `mz` (`jobs/identify/linear_window.rs`), or held at
/// the value given.
pub(crate) fn set_after_fits(t: &Tyre) -> &'static [&'static str] {
    match t {
        Tyre::Linear(_) => &[LINEAR_TRAIL],
        _ => &[],
    }
}

/// The linear tyre's pneumatic trail's name, as its file and `--hold`
/// give it.
pub(crate) const LINEAR_TRAIL: &str = "pneumatic_trail";

/// `t` with its parameter `name` (any block a fit fits, or one set after
/// the fits: [`set_after_fits`]) set to `v`; `None` when `t` has none.
pub(crate) fn with_value(t: &Tyre, name: &str, v: f64) -> Option<Tyre> {
    if let (Tyre::Linear(l), LINEAR_TRAIL) = (t, name) {
        let mut l = l.clone();
        l.pneumatic_trail = v;
        return Some(Tyre::Linear(l));
    }
    let (c, i) = place_of(t, name)?;
    let mut p = c.parameters(t);
    p[i] = v;
    let mut out = t.clone();
    c.set(&mut out, &p);
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// PAC89's aligning c9 on the Hoosier file, stated −1.3329 where the
    /// free fit gave −0.1947 ± 0.317: held at the end of the ±2 standard
    /// errors nearest the stated value, −0.828 (−0.8287 rounded towards the fit); its line says both values,
    /// how far the stated one lay and how to choose another; the report
    /// keeps them as numbers.
    #[test]
    fn an_undetermined_hold_says_the_value_held_and_the_stated_one() {
        use super::super::spare::{held_value, standard_errors_away};
        let (stated, fitted, se) = (-1.3329, -0.1947, Some(0.317));
        let held = HeldFor::Undetermined {
            fitted,
            std_error: se,
            effect_percent: Some(10.7),
            stated,
            held_at: held_value(stated, fitted, se, (-10.0, 10.0)),
            standard_errors_away: standard_errors_away(stated, fitted, se),
        };
        assert_eq!(
            held.said("c9"),
            "not determined by these data: fitted free it was -0.1947 ± 0.317 (one standard error of it alone moves the fit by 10.7 % of the channel's RMS, which the other parameters' trade-off undoes), so it is held at -0.828, the end of the free fit's ±2 standard errors nearest the model's start value -1.3329 (which lies 3.6 standard errors from the free fit, by its linearisation), and the rest refitted; to hold it at a value of your own, give --hold c9=VALUE"
        );
        let json = serde_json::to_value(held).unwrap();
        assert!(
            (json["standard_errors_away"].as_f64().unwrap() - 3.59).abs() < 0.01,
            "{json}"
        );
        assert_eq!(json["stated"].as_f64(), Some(-1.3329), "{json}");
        assert!(
            (json["held_at"].as_f64().unwrap() + 0.828).abs() < 1e-9,
            "{json}"
        );
        // Within two standard errors the stated value is held, and said so
        // without the option.
        let within = HeldFor::Undetermined {
            fitted: 0.9957,
            std_error: Some(24.4),
            effect_percent: Some(318.5),
            stated: 0.77394,
            held_at: 0.77394,
            standard_errors_away: standard_errors_away(0.77394, 0.9957, Some(24.4)),
        };
        assert!(
            within.said("a7").ends_with("so it is held at the model's start value 0.77394, 0.01 standard errors from the free fit (within the ±2 standard errors the data allow), and the rest refitted"),
            "{}",
            within.said("a7")
        );
        // Another reason is said as it was.
        let levels = HeldFor::CamberLevels { have: 1 };
        assert_eq!(levels.said("a5"), levels.to_string());
    }
}
