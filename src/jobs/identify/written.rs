//! The TOML tyre file a swarm fit writes: its header (the command that
//! repeats the fit, its σ, the values held), the tyre, and the check that
//! the tyre reader takes the text as it will be written — the reader's own
//! parse, [`Tyre::validate`] and [`Tyre::check_sizes`], so that `identify`
//! never writes a file that `tyre-eval` or `simulate` refuse.

use super::holds::held_file_lines;
use super::ranges;
use super::SwarmReport;
use crate::error::{range, Error, FitError, OutputError, ParamError, ParamReason};
use crate::io::{fitted_ranges, TomlSource};
use crate::tyre::Tyre;
use std::path::Path;

/// What the error says of a fitted tyre the reader refuses.
const REFUSED: &str =
    "the fitted tyre is not written, as the tyre readers (tyre-eval, simulate) would refuse it";

/// The same, of a fit with values held.
const REFUSED_HOLDING: &str = "the fitted tyre is not written, as the tyre readers (tyre-eval, simulate) would refuse it (the fit ran with the values given with --hold, which may have driven it there)";

/// The text of the tyre file of `r`, to be written at `path`, checked to
/// be read back: an error naming the parameter, its value and the limit
/// when the reader would refuse it.
pub(super) fn tyre_file_text(r: &SwarmReport, path: &Path) -> Result<String, Error> {
    let tyre = toml::to_string(&r.tyre).map_err(|e| OutputError::Tyre {
        path: path.to_path_buf(),
        source: e,
    })?;
    let tyre = tiny_in_scientific(&tyre);
    let header = format!(
        "# Identified by `{}`: sigma {:.3} %.\n",
        r.options.command(),
        r.fit.sigma_percent
    );
    let held = held_file_lines(&r.held, "#");
    let window = r.linear_window.iter().flat_map(|w| w.lines("#"));
    let selected = r
        .grouping
        .selected
        .iter()
        .map(|s| format!("# {}", s.line()));
    let notes: String = window
        .chain(selected)
        .chain(r.notes.iter().map(|n| n.line("#")))
        .map(|l| l + "\n")
        .collect();
    let spans = ranges::fitted_spans(r);
    let table = fitted_ranges::table_text(&ranges::fitted_ranges(&spans));
    let ranges = ranges::toml_line(&spans);
    let text = format!("{header}# {ranges}\n{held}{notes}{tyre}{table}");
    match read_back(path, &text)? {
        Ok(()) => Ok(text),
        Err(e) => Err(refused(r, e)),
    }
}

/// The error of a fitted tyre the reader refuses with `e`: the value said
/// as the fit's, the reader's limit without the words it gives a user's
/// key (a unit hint: "is the value in millimetres?" of a contact length
/// no user wrote), and the likely cause: the rig's forces far too small
/// for their loads where they are (`force_scale.rs`), said first.
fn refused(r: &SwarmReport, e: ParamError) -> Error {
    let limit = match e.reason {
        ParamReason::OutOfRange { lo, hi, .. } => format!("it must {}", range(lo, hi)),
        ref other => format!("it {other}"),
    };
    let cause = match r.small_forces.first() {
        Some(w) => format!("the likely cause: {w}"),
        None => "check that the data are in the units FORMATS.md gives (forces in N, moments in N·m, angles in rad), or hold the parameter at a value of your own with --hold NAME=VALUE".into(),
    };
    match e.value.number() {
        Some(value) => FitError::FittedRefused {
            data: r.options.data.clone(),
            key: e.key.clone(),
            value,
            limit,
            holding: !r.options.hold.is_empty(),
            cause,
        }
        .into(),
        None => FitError::InData {
            data: r.options.data.clone(),
            channel: Some(if r.options.hold.is_empty() {
                REFUSED
            } else {
                REFUSED_HOLDING
            }),
            source: Box::new(Error::Param(e)),
        }
        .into(),
    }
}

/// The reader's verdict on `text` as the tyre file `path`: the outer
/// error when it does not parse as a tyre, the inner one when a value is
/// beyond the reader's limits.
fn read_back(path: &Path, text: &str) -> Result<Result<(), ParamError>, Error> {
    let src = TomlSource {
        path: path.to_path_buf(),
        text: text.to_string(),
    };
    let (src, _) = fitted_ranges::split(&src)?;
    let tyre: Tyre = src.parse()?;
    Ok(tyre.validate().and_then(|()| tyre.check_sizes()))
}

/// Refuses fits whose σ or a parameter is not a finite number (data that
/// no model reproduces): no such value is written.
pub(super) fn finite_fits(r: &SwarmReport) -> Result<(), Error> {
    let fits = [Some(&r.fit), r.aligning.as_ref(), r.longitudinal.as_ref()];
    for f in fits.into_iter().flatten() {
        let sigma = (format!("{} σ", f.channel.quantity()), f.sigma_percent);
        let values = f.parameters.iter().map(|p| (p.name.clone(), p.value));
        if let Some((quantity, value)) = std::iter::once(sigma)
            .chain(values)
            .find(|(_, v)| !v.is_finite())
        {
            return Err(FitError::NonFiniteResult { quantity, value }.into());
        }
    }
    Ok(())
}

/// The smallest magnitude written in decimals; below it, in scientific
/// notation.
const SMALLEST_DECIMAL: f64 = 1e-6;

/// `text` (a tyre's `key = value` lines) with every value below
/// [`SMALLEST_DECIMAL`] but 0 written in scientific notation: the TOML
/// writer spells a float in decimals, and a GIM decay fitted to 2.7e-17
/// came out as `0.0000000000000000271`, read as a typing slip. The value
/// is the same double either way.
fn tiny_in_scientific(text: &str) -> String {
    text.lines()
        .map(|line| {
            let tiny = line.split_once(" = ").and_then(|(key, value)| {
                let v: f64 = value.parse().ok()?;
                (v != 0.0 && v.abs() < SMALLEST_DECIMAL).then(|| format!("{key} = {v:e}"))
            });
            tiny.unwrap_or_else(|| line.to_string()) + "\n"
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tiny_value_is_written_in_scientific_and_the_rest_as_they_were() {
        let text = "model = \"gim\"\nfriction_decay = 0.000000000000000012209966040030408\nfriction = 1.0\nload_exponent = 0.0\n";
        assert_eq!(
            tiny_in_scientific(text),
            "model = \"gim\"\nfriction_decay = 1.2209966040030408e-17\nfriction = 1.0\nload_exponent = 0.0\n"
        );
        let back: toml::Value = toml::from_str(&tiny_in_scientific(text)).unwrap();
        assert_eq!(
            back["friction_decay"].as_float(),
            Some(1.2209966040030408e-17)
        );
    }
}
