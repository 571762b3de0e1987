//! A template's nominal pressure outside the rig data's pressures. A fit
//! with `--template` keeps the template's `NOMPRES` (the public
//! `fsae190_50R10.tir`'s 220 kPa) while the validity ranges come from the
//! data (the Hoosier rig's 68–99 kPa): the Magic Formula's pressure terms
//! are polynomials in `dpi = (p − NOMPRES)/NOMPRES`, so the fit sees only
//! `dpi` of −0.69 to −0.55 and its terms reach the file's own nominal
//! pressure by extrapolation (`PPY3 = −25.9` there), which nothing in
//! the file says unless it is said here, with what to do.

use crate::format::{exact, readable};
use crate::identify::mf_staged::MfRow;
use crate::tyre::mf::{MagicFormula, MfCoefficients};

/// The warning of a fit from a template (`template`) whose written tyre
/// `t` keeps a `NOMPRES` outside the data's pressures (its `PRESMIN` to
/// `PRESMAX`, set from the data, else those of `rows`); `None` where
/// it lies inside, the rows give no pressure, or `NOMPRES` was given with
/// `--hold` (`hold`).
pub(super) fn nompres_outside(
    t: &MagicFormula,
    rows: &[MfRow],
    template: bool,
    hold: &[(String, f64)],
) -> Option<String> {
    if !template || hold.iter().any(|(n, _)| n == "NOMPRES") {
        return None;
    }
    let mut p: Vec<f64> = rows.iter().filter_map(|r| r.pressure).collect();
    p.retain(|v| v.is_finite());
    if p.is_empty() {
        // Rows without pressures: nothing to set NOMPRES to (and no
        // median to index).
        return None;
    }
    p.sort_by(f64::total_cmp);
    // The file's PRESMIN–PRESMAX (every sample of the levels fitted),
    // else the rows' own span.
    let (lo, hi) = match (t.limits.pressure_min, t.limits.pressure_max) {
        (Some(lo), Some(hi)) => (lo, hi),
        _ => (*p.first()?, *p.last()?),
    };
    let nominal = t.coefficients.NOMPRES;
    if nominal <= 0.0 || (lo..=hi).contains(&nominal) {
        return None;
    }
    // The median, rounded to 100 Pa as a fit without a template sets it.
    let median = (p[p.len() / 2] / 100.0).round() * 100.0;
    let dpi = |v: f64| readable((v - nominal) / nominal, 3);
    let largest = MfCoefficients::NAMES
        .iter()
        .filter(|n| n.starts_with("PP"))
        .filter_map(|n| t.coefficients.get(n).map(|v| (*n, v)))
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        .filter(|(_, v)| *v != 0.0)
        .map_or_else(String::new, |(n, v)| {
            format!(" (the largest, {n} = {})", readable(v, 4))
        });
    Some(format!(
        "the template's NOMPRES = {} Pa lies outside the data's pressures ({} to {} Pa): the pressure terms, polynomials in dpi = (p − NOMPRES)/NOMPRES, are fitted at dpi {} to {} only and reach the file's nominal pressure by extrapolation{largest}; set NOMPRES in the template to a pressure of the data (their median, {} Pa), or give --hold NOMPRES={}",
        exact(nominal),
        exact(lo),
        exact(hi),
        dpi(lo),
        dpi(hi),
        exact(median),
        exact(median),
    ))
}
