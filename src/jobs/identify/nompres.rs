//! A template's nominal pressure outside the rig data's pressures. The
//! public `fsae190_50R10.tir` has `NOMPRES` = 220 kPa while the Hoosier
//! rig ran at 68–99 kPa: the Magic Formula's pressure terms are
//! polynomials in `dpi = (p − NOMPRES)/NOMPRES`, so a fit that keeps the
//! template's sees only `dpi` of −0.69 to −0.55, and every coefficient
//! "at nominal pressure" (`PDY1`, `PKY1`) is a value 120 kPa beyond the
//! data, reached by extrapolation. The fit then put the peak friction in
//! the pressure terms (`PPY3 = −25.9`, `PDY1` on its lower bound 0.05)
//! and the pooled `σ` suffered. A tyre engineer fits about the data's own
//! pressure, as a fit without a template sets it: so `NOMPRES` is set to
//! the data's median (stated, with the template's value and how to keep
//! it), unless `--hold NOMPRES=…` says otherwise.

use crate::identify::mf_staged::MfRow;
use crate::identify::{ConstantFrom, HeldFor};
use crate::tyre::mf::MagicFormula;

/// The `NOMPRES` a fit from `template` (its limits already the data's)
/// uses in place of the template's where that lies outside the data's
/// pressures (the template's `PRESMIN` to `PRESMAX`, set from the data,
/// else the rows' span): the rows' median rounded to 100 Pa, as a fit
/// without a template sets it, held and said as such. `None` where it
/// lies inside, the rows give no pressure, or `NOMPRES` is given with
/// `--hold` (`hold`).
pub(super) fn recentred(
    template: Option<&MagicFormula>,
    rows: &[MfRow],
    hold: &[(String, f64)],
) -> Option<super::holds::Held> {
    let t = template?;
    if hold.iter().any(|(n, _)| n == "NOMPRES") {
        return None;
    }
    let mut p: Vec<f64> = rows.iter().filter_map(|r| r.pressure).collect();
    p.retain(|v| v.is_finite() && *v > 0.0);
    if p.is_empty() {
        // Rows without pressures: nothing to set NOMPRES to (and no
        // median to index).
        return None;
    }
    p.sort_by(f64::total_cmp);
    let (lo, hi) = match (t.limits.pressure_min, t.limits.pressure_max) {
        (Some(lo), Some(hi)) => (lo, hi),
        _ => (p[0], p[p.len() - 1]),
    };
    let nominal = t.coefficients.NOMPRES;
    // (A template with no NOMPRES, 0, has its pressure terms off.)
    if nominal <= 0.0 || (lo..=hi).contains(&nominal) {
        return None;
    }
    let median = (p[p.len() / 2] / 100.0).round() * 100.0;
    Some(super::holds::Held {
        name: "NOMPRES".into(),
        value: median,
        applied: true,
        reason: HeldFor::Constant {
            from: ConstantFrom::OutsideData {
                template: nominal,
                lo,
                hi,
            },
        },
    })
}
