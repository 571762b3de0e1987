//! The values `identify` held rather than fitted, as it reports them:
//! each with its value (the tyre file's units), why it was held (given
//! with `--hold`, too few levels in the data, a `.tir` constant without a
//! template) and, for a hold, whether a fit applied it; and the
//! terminal's lines that say so; and the check that a held value lies
//! within the limits the tyre reader applies to the file written.

use super::Options;
use crate::error::{Error, ParamError};
use crate::format::exact;
use crate::identify::{value_in, with_value, Fit, HeldFor};
use crate::tyre::mf::{MagicFormula, MfCoefficients, MfOptions, MfVersion, TyreSide};
use crate::tyre::{ModelName, Tyre};
use serde::Serialize;

/// `NAME=VALUE` of `--hold`, read for `model`: the error's example is a
/// parameter of that model (`a0=1.65` for pac89; a `.tir` coefficient,
/// `PKY4=2`, for mf61/mf62), not another model's (a pac89 fit once was
/// told "e.g. PKY4=2", a Magic Formula name it refuses).
pub fn parse_hold(s: &str, model: super::IdentifyModel) -> Result<(String, f64), Error> {
    s.split_once('=')
        .and_then(|(k, v)| Some((k.trim().to_string(), v.trim().parse::<f64>().ok()?)))
        .filter(|(k, _)| !k.is_empty())
        .ok_or_else(|| {
            crate::error::OptionsError::HoldSyntax {
                given: s.into(),
                example: hold_example(model),
            }
            .into()
        })
}

/// A `--hold` of `model` as an example: its first fitted parameter at its
/// start value at 4000 N, or `PKY4=2` for the staged Magic Formula fits.
pub(super) fn hold_example(model: super::IdentifyModel) -> String {
    let start = model
        .swarm_model()
        .and_then(|m| crate::identify::start_tyre_of(m, 4000.0).ok());
    let Some(t) = start else {
        return "PKY4=2".into();
    };
    let names = crate::identify::fitted_names(&t);
    match (
        names.first(),
        crate::tyre::Parameterised::parameters(&t).first(),
    ) {
        (Some(n), Some(v)) => format!("{n}={}", crate::format::readable(*v, 3)),
        _ => "PKY4=2".into(),
    }
}

/// A parameter held with `--hold`: its name, the value given (the tyre
/// file's units) and whether a fit it belongs to ran (a parameter of a
/// block the data do not fit, such as an aligning one without `mz`, is
/// not applied, and said so).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Held {
    /// The parameter, as the tyre file names it.
    pub name: String,
    /// The value given.
    pub value: f64,
    /// Whether a fit held it (false: no fit it belongs to ran).
    pub applied: bool,
    /// Why it was held.
    #[serde(flatten)]
    pub reason: HeldFor,
}

/// The holds of `o`, each applied when `fitted` names it.
pub(crate) fn holds_of(o: &Options, fitted: &[String]) -> Vec<Held> {
    o.hold
        .iter()
        .map(|(name, value)| Held {
            name: name.clone(),
            value: *value,
            applied: fitted.contains(name),
            reason: HeldFor::Given,
        })
        .collect()
}

/// The terminal's lines of the holds: the parameters held, and those not
/// applied.
pub(crate) fn held_lines(held: &[Held]) -> Vec<String> {
    let applied: Vec<String> = held
        .iter()
        .filter(|h| h.applied && h.reason == HeldFor::Given)
        .map(|h| format!("{} = {}", h.name, h.value))
        .collect();
    let mut out = Vec::new();
    if !applied.is_empty() {
        out.push(format!(
            "  held with --hold (not fitted): {}",
            applied.join(", ")
        ));
    }
    // The values held for another reason, one line per reason.
    out.extend(by_reason(held).into_iter().map(|l| format!("  held: {l}")));
    out.extend(held.iter().filter(|h| !h.applied).map(|h| {
        format!(
            "  warning: --hold {}={}: not applied: no fit of its block ran on these data, and the file written does not hold it",
            h.name, h.value
        )
    }));
    out
}

/// A held value as the terminal says it: `LONGVL` with its km/h too, so
/// that a rig's speed column in km/h (40 for a TTC rig's 40 km/h, read as
/// 40 m/s) shows as the 144 km/h it became.
fn value_text(h: &Held) -> String {
    match h.name.as_str() {
        "LONGVL" => format!(
            "{} m/s ({} km/h)",
            exact(h.value),
            crate::format::readable(h.value * 3.6, 3)
        ),
        _ => exact(h.value),
    }
}

/// The parameters of `fits` held for another reason than `--hold` (the
/// levels of the data, the model's design), at their value in `written`
/// (PAC89's two fits hold its camber terms at the start's alike); one that
/// another of the fits fitted (Gim's contact length, held by the lateral
/// fit and fitted to the aligning moment) is not held.
pub(crate) fn held_by_fits(fits: &[&Fit], written: &Tyre) -> Vec<Held> {
    let fitted = |name: &str| {
        fits.iter()
            .flat_map(|f| &f.parameters)
            .any(|p| p.free && p.name == name)
    };
    fits.iter()
        .flat_map(|f| &f.parameters)
        .filter(|p| !fitted(&p.name))
        .filter_map(|p| match p.held {
            Some(why) if why != HeldFor::Given => Some(Held {
                name: p.name.clone(),
                value: value_in(written, &p.name).unwrap_or(p.value),
                applied: true,
                reason: why,
            }),
            _ => None,
        })
        .collect()
}

/// The comment lines of a written file (`mark`: `#` for TOML, `$` for a
/// `.tir`) stating the values held for another reason than `--hold`, one
/// line per reason as the terminal says them.
pub(crate) fn held_file_lines(held: &[Held], mark: &str) -> String {
    by_reason(held)
        .into_iter()
        .map(|l| format!("{mark} held: {l}\n"))
        .collect()
}

/// The values `held` for another reason than `--hold`, one line per
/// reason: `NAME = value, …: why` (the terminal's and the file's alike).
fn by_reason(held: &[Held]) -> Vec<String> {
    let mut reasons: Vec<HeldFor> = Vec::new();
    for h in held.iter().filter(|h| h.reason != HeldFor::Given) {
        if !reasons.contains(&h.reason) {
            reasons.push(h.reason);
        }
    }
    reasons
        .into_iter()
        .map(|why| {
            let of: Vec<&Held> = held.iter().filter(|h| h.reason == why).collect();
            let values: Vec<String> = of
                .iter()
                .map(|h| format!("{} = {}", h.name, value_text(h)))
                .collect();
            // An undetermined parameter's reason is its own (its fitted
            // value), so `said` names the one parameter of its line.
            format!("{}: {}", values.join(", "), why.said(&of[0].name))
        })
        .collect()
}

/// The load the hold check's start tyre is made at, N (within every
/// reader's load limits).
pub(super) const CHECK_LOAD: f64 = 4000.0;

/// Refuses a value given with `--hold` that the tyre reader refuses (its
/// own checks, [`Tyre::validate`] and [`Tyre::check_sizes`], on a start
/// tyre holding it): the error names the parameter as `--hold` does, the
/// value and the reader's limit, before any data are read. `model` is `None` for the staged
/// Magic Formula fit (a `.tir` coefficient).
pub(crate) fn check_hold_values(
    model: Option<ModelName>,
    hold: &[(String, f64)],
) -> Result<(), Error> {
    let start = match model {
        Some(m) => super::start_tyre_of(m, CHECK_LOAD)?,
        None => Tyre::MagicFormula(Box::new(MagicFormula {
            version: MfVersion::Mf61,
            side: TyreSide::Left,
            options: MfOptions::default(),
            limits: Default::default(),
            coefficients: MfCoefficients::default(),
        })),
    };
    let reader = |t: &Tyre| t.validate().and_then(|()| t.check_sizes());
    // A start the reader refuses would blame the hold for it.
    if reader(&start).is_err() {
        return Ok(());
    }
    for (name, v) in hold {
        let held = match &start {
            Tyre::MagicFormula(mf) => {
                let mut mf = mf.clone();
                mf.coefficients.set(name, *v);
                Some(Tyre::MagicFormula(mf))
            }
            t => with_value(t, name, *v),
        };
        // At the parameter's name, as the other checks of a held value
        // (finite, within ±1e6) and the Python `key` give it.
        if let Some(Err(e)) = held.as_ref().map(reader) {
            return Err(ParamError {
                key: name.clone(),
                ..e
            }
            .into());
        }
    }
    Ok(())
}
