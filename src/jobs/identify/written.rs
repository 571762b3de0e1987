//! The TOML tyre file a swarm fit writes: its header (the command that
//! repeats the fit, its σ, the values held), the tyre, and the check that
//! the tyre reader takes the text as it will be written — the reader's own
//! parse, [`Tyre::validate`] and [`Tyre::check_sizes`], so that `identify`
//! never writes a file that `tyre-eval` or `simulate` refuse.

use super::holds::held_file_lines;
use super::ranges;
use super::SwarmReport;
use crate::error::{Error, FitError, OutputError, ParamError};
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
        Err(e) => Err(FitError::InData {
            data: r.options.data.clone(),
            channel: Some(if r.options.hold.is_empty() {
                REFUSED
            } else {
                REFUSED_HOLDING
            }),
            source: Box::new(Error::Param(e)),
        }
        .into()),
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
