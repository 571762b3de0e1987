//! A template's nominal load and pressure outside the rig data's. The
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
//!
//! The load terms are polynomials in `dfz = (Fz − FNOMIN)/FNOMIN` alike:
//! the truck template's `FNOMIN` = 30 kN on car data at 2–6 kN left the
//! fit's `PKY1` a cornering stiffness at 30 kN, 0.99 N/rad per N, which
//! the readers refuse; the FSAE template's 6 kN on the Hoosier file's
//! 0.4–2.9 kN made `PDY1` the friction law extrapolated to 6 kN. So
//! `FNOMIN` more than a quarter outside the data's loads is set to their
//! median (rounded to 10 N, as without a template), unless `--hold
//! FNOMIN=…` says otherwise.
//!
//! A template without `NOMPRES` (an MF 5.2 file: 0, the pressure terms
//! off) on data with a `pressure` column gets the data's median too, or
//! a fit version with pressure terms would leave every `PP*` unmoved and
//! blame the data; `--hold NOMPRES=0` keeps them off. An `INFLPRES` (the
//! pressure a reader uses where the points give none) outside the data's
//! pressures is set to that median too, or the file would be evaluated
//! by default at a pressure it was not fitted at (and was: the curvature
//! warning's reversal scan, `curvature.rs`, ran at the FSAE template's
//! 220 kPa).

use crate::identify::mf_staged::MfRow;
use crate::identify::{ConstantFrom, HeldFor};
use crate::tyre::mf::{MagicFormula, MfVersion};

/// How far past the data's loads (a factor) a template's `FNOMIN` is
/// kept.
const LOAD_REACH: f64 = 1.25;

/// The median of the finite positive values of `v` (sorted here),
/// `None` when none.
pub(super) fn median(mut v: Vec<f64>) -> Option<f64> {
    v.retain(|x| x.is_finite() && *x > 0.0);
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied()
}

/// A held constant set in place of the template's.
fn held(name: &str, value: f64, from: ConstantFrom) -> super::holds::Held {
    super::holds::Held {
        name: name.into(),
        value,
        applied: true,
        reason: HeldFor::Constant { from },
    }
}

/// The constants a fit from `template` (its limits already the data's)
/// uses in place of the template's (module notes): `FNOMIN` outside the
/// data's loads, `NOMPRES` outside their pressures or absent while the
/// rows have pressures, and then an `INFLPRES` outside them; each the
/// rows' median rounded (10 N, 100 Pa), as a fit without a template sets
/// it, held and said as such. None of a constant given with `--hold`
/// (`hold`). `version` is the fit's (an MF 5.2 fit has no pressure
/// terms to switch on).
pub(super) fn recentred(
    version: MfVersion,
    template: Option<&MagicFormula>,
    rows: &[MfRow],
    hold: &[(String, f64)],
) -> Vec<super::holds::Held> {
    let Some(t) = template else {
        return Vec::new();
    };
    let given = |name: &str| hold.iter().any(|(n, _)| n == name);
    let mut out = Vec::new();
    let loads: Vec<f64> = rows.iter().map(|r| r.fz).collect();
    if let (Some(m), false) = (median(loads.clone()), given("FNOMIN")) {
        let (lo, hi) = span(t.limits.fz_min, t.limits.fz_max, &loads);
        let nominal = t.coefficients.FNOMIN;
        // A quarter past the ends is kept: MFeval's sample file (6752 N)
        // on data to 6000 N reads its coefficients about a load the laws
        // barely extrapolate to; the truck's 30 kN on 2–6 kN does not.
        if !(lo / LOAD_REACH..=hi * LOAD_REACH).contains(&nominal) {
            let from = ConstantFrom::LoadOutsideData {
                template: nominal,
                lo,
                hi,
            };
            out.push(held("FNOMIN", (m / 10.0).round() * 10.0, from));
        }
    }
    let p: Vec<f64> = rows.iter().filter_map(|r| r.pressure).collect();
    // Rows without pressures: nothing to set NOMPRES to.
    let Some(m) = median(p.clone()) else {
        return out;
    };
    let median = (m / 100.0).round() * 100.0;
    let (lo, hi) = span(t.limits.pressure_min, t.limits.pressure_max, &p);
    let outside = |v: f64| v > 0.0 && !(lo..=hi).contains(&v);
    let c = &t.coefficients;
    let nompres = if given("NOMPRES") {
        None
    } else if c.NOMPRES <= 0.0 && version != MfVersion::Mf52 {
        Some(ConstantFrom::TemplateWithoutPressure)
    } else if outside(c.NOMPRES) {
        Some(ConstantFrom::OutsideData {
            template: c.NOMPRES,
            lo,
            hi,
        })
    } else {
        None
    };
    if let Some(from) = nompres {
        out.push(held("NOMPRES", median, from));
    }
    if outside(c.INFLPRES) && !given("INFLPRES") {
        let from = ConstantFrom::InflationOutsideData {
            template: c.INFLPRES,
            lo,
            hi,
        };
        out.push(held("INFLPRES", median, from));
    }
    out
}

/// The limits `lo`–`hi` where both are set (the data's, `ranges.rs`),
/// else the span of `values`.
fn span(lo: Option<f64>, hi: Option<f64>, values: &[f64]) -> (f64, f64) {
    match (lo, hi) {
        (Some(lo), Some(hi)) => (lo, hi),
        _ => values
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
                (a.min(v), b.max(v))
            }),
    }
}

/// The `.tir` constants a fit without a template sets (`FNOMIN`,
/// `UNLOADED_RADIUS`, `NOMPRES`, `LONGVL`), each with where its value
/// comes from; one given with `--hold` is said as such; then those the
/// fresh file states in place of a 0 (`tyre/mf/stated.rs`: `INFLPRES`,
/// `VERTICAL_STIFFNESS`, `WIDTH`, `ASPECT_RATIO`, and `NOMPRES` without
/// pressure data), as it writes them.
pub(super) fn constants_held(
    t: &MagicFormula,
    data: &crate::identify::data::RigData,
    o: &super::Options,
) -> Vec<super::holds::Held> {
    let c = &t.coefficients;
    let pressure = match data.pressure {
        Some(_) => ConstantFrom::MedianPressure,
        None => ConstantFrom::NoPressure,
    };
    let speed = match data.speed {
        Some(_) => ConstantFrom::MedianSpeed,
        None => ConstantFrom::DefaultSpeed,
    };
    let mut out = [
        ("FNOMIN", c.FNOMIN, ConstantFrom::MedianLoad),
        (
            "UNLOADED_RADIUS",
            c.UNLOADED_RADIUS,
            ConstantFrom::DefaultRadius,
        ),
        ("NOMPRES", c.NOMPRES, pressure),
        ("LONGVL", c.LONGVL, speed),
    ]
    .into_iter()
    .filter(|(name, ..)| !o.hold.iter().any(|(h, _)| h == name))
    .map(|(name, value, from)| held(name, value, from))
    .collect::<Vec<_>>();
    let stated = crate::tyre::mf::stated::stated(t);
    // A stated NOMPRES replaces the 0 said above.
    out.retain(|h| !stated.iter().any(|s| s.key == h.name));
    out.extend(stated.into_iter().map(|s| {
        let from = ConstantFrom::Stated { from: s.from };
        held(s.key, s.value, from)
    }));
    out
}
