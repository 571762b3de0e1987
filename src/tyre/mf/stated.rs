//! The physical constants a fresh `.tir` (one written without a template)
//! states where the fit leaves them 0, so that any Magic Formula reader
//! evaluates a physical tyre: MFeval and ADAMS divide by `NOMPRES` (`dpi =
//! (p − NOMPRES)/NOMPRES`) and by `VERTICAL_STIFFNESS` (`Re = RΩ −
//! FNOMIN/Cz·(…)`, `Q_FZ1 = Cz·R0/FNOMIN`), evaluate a point without a
//! pressure at `INFLPRES` (0: a flat tyre, `dpi = −1`), and take `WIDTH`
//! and `ASPECT_RATIO` as the tyre's section (0: no tyre). Rig forces
//! measure none of these: each value stated here says where it comes
//! from, and `identify` lists it among the held values (terminal and
//! report).
//!
//! Sources: the thirteen public `.tir` files (shared data, `tir_public`):
//! `FNOMIN/VERTICAL_STIFFNESS` is 19–21 mm in eleven of them (5 mm in
//! `FSAE_Defaults`, 30 mm in `Truck_430_50R38`); `WIDTH/UNLOADED_RADIUS`
//! 0.41–0.82, median 0.61; `ASPECT_RATIO` 0.4–0.9, median 0.6; `INFLPRES`
//! 220 kPa in 8 of the 12 that give one. Units: SI (Pa, N/m, m).

use super::{MagicFormula, MfVersion};
use serde::Serialize;
use std::fmt;

/// The deflection at `FNOMIN` a stated vertical stiffness gives, m.
pub const NOMINAL_DEFLECTION: f64 = 0.020;
/// A stated section width per unit of the unloaded radius.
pub const WIDTH_PER_RADIUS: f64 = 0.61;
/// A stated aspect ratio (section height over width).
pub const ASPECT_RATIO: f64 = 0.6;
/// A stated nominal pressure where the data have none, Pa.
pub const PRESSURE: f64 = 220_000.0;

/// Why a constant of a fresh `.tir` has the value stated for it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum StatedFrom {
    /// `INFLPRES` set to `NOMPRES` (the data's pressure, unless held).
    InflationAtNominal,
    /// `NOMPRES` (and `INFLPRES`) stated where the data have no pressure
    /// and the pressure terms are all 0.
    PressureWithoutData,
    /// `VERTICAL_STIFFNESS` = `FNOMIN` / [`NOMINAL_DEFLECTION`].
    DeflectionAtNominal,
    /// `WIDTH` = [`WIDTH_PER_RADIUS`] · `UNLOADED_RADIUS`, to the mm.
    WidthOfRadius,
    /// `ASPECT_RATIO` = [`ASPECT_RATIO`].
    MedianAspectRatio,
}

/// A constant stated for a fresh `.tir`: its key, value (SI) and why.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stated {
    /// The `.tir` key.
    pub key: &'static str,
    /// The value written, SI.
    pub value: f64,
    /// Where it comes from.
    pub from: StatedFrom,
}

/// Whether every pressure term of `t` is 0 (none fitted nor held), so
/// that its forces are the same at any pressure.
fn pressure_terms_off(t: &MagicFormula) -> bool {
    super::MfCoefficients::NAMES
        .iter()
        .filter(|k| k.starts_with("PP") || **k == "PFZ1")
        .all(|k| t.coefficients.get(k) == Some(0.0))
}

/// The constants of `t` a fresh file states in place of its 0s (module
/// notes), in file order; none where `t` has them.
pub fn stated(t: &MagicFormula) -> Vec<Stated> {
    let c = &t.coefficients;
    let mut out = Vec::new();
    let mut put = |key, value, from| out.push(Stated { key, value, from });
    // MF 5.2 has no pressure terms: its readers take no pressure.
    let pressure = t.version != MfVersion::Mf52;
    if pressure && c.NOMPRES <= 0.0 && pressure_terms_off(t) {
        put("NOMPRES", PRESSURE, StatedFrom::PressureWithoutData);
        if c.INFLPRES <= 0.0 {
            put("INFLPRES", PRESSURE, StatedFrom::PressureWithoutData);
        }
    } else if c.NOMPRES > 0.0 && c.INFLPRES <= 0.0 {
        put("INFLPRES", c.NOMPRES, StatedFrom::InflationAtNominal);
    }
    if c.WIDTH <= 0.0 && c.UNLOADED_RADIUS > 0.0 {
        let width = (WIDTH_PER_RADIUS * c.UNLOADED_RADIUS * 1000.0).round() / 1000.0;
        put("WIDTH", width, StatedFrom::WidthOfRadius);
    }
    if c.ASPECT_RATIO <= 0.0 {
        put("ASPECT_RATIO", ASPECT_RATIO, StatedFrom::MedianAspectRatio);
    }
    if c.VERTICAL_STIFFNESS <= 0.0 && c.FNOMIN > 0.0 {
        let cz = c.FNOMIN / NOMINAL_DEFLECTION;
        put("VERTICAL_STIFFNESS", cz, StatedFrom::DeflectionAtNominal);
    }
    out
}

/// `t` with the constants [`stated`] gives in place of its 0s.
pub fn with_stated(t: &MagicFormula) -> MagicFormula {
    let mut out = t.clone();
    for s in stated(t) {
        out.coefficients.set(s.key, s.value);
    }
    out
}

impl fmt::Display for StatedFrom {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StatedFrom::InflationAtNominal => f.write_str(
                "NOMPRES's (the data's pressure, unless held): the pressure a reader evaluates a point without one at; 0 would be a flat tyre to MFeval and ADAMS (dpi = (p − NOMPRES)/NOMPRES = −1)",
            ),
            StatedFrom::PressureWithoutData => write!(
                f,
                "no `pressure` column, so a stated {} kPa (INFLPRES of 8 of the 12 public .tir files that give one): no pressure term is fitted, so the forces are the same at any pressure, and readers divide by NOMPRES (dpi = (p − NOMPRES)/NOMPRES), which 0 would divide by zero; give --hold NOMPRES=… with your tyre's",
                PRESSURE / 1000.0
            ),
            StatedFrom::DeflectionAtNominal => write!(
                f,
                "rig forces do not measure the vertical stiffness (a loaded radius would), so FNOMIN over a stated {} mm of deflection at FNOMIN, as 11 of the 13 public .tir files have (19 to 21 mm; 5 to 30 mm in all); it sets the loaded and rolling radii, not the forces, and readers divide by it (Re = RΩ − FNOMIN/Cz·…); give --hold VERTICAL_STIFFNESS=… with your tyre's",
                NOMINAL_DEFLECTION * 1000.0
            ),
            StatedFrom::WidthOfRadius => write!(
                f,
                "rig forces do not measure the section, so {WIDTH_PER_RADIUS} times UNLOADED_RADIUS, the median of the 13 public .tir files (0.41 to 0.82); no force depends on it here"
            ),
            StatedFrom::MedianAspectRatio => f.write_str(
                "the median of the 13 public .tir files (0.4 to 0.9); no force depends on it here",
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tyre::mf::{MfCoefficients, MfOptions, TyreSide};

    fn bare(version: MfVersion, nompres: f64) -> MagicFormula {
        MagicFormula {
            version,
            side: TyreSide::Left,
            options: MfOptions::default(),
            limits: Default::default(),
            coefficients: MfCoefficients {
                FNOMIN: 1640.0,
                NOMPRES: nompres,
                ..MfCoefficients::default()
            },
        }
    }

    #[test]
    fn a_fresh_files_zero_sizes_are_stated_and_its_own_values_kept() {
        let t = with_stated(&bare(MfVersion::Mf62, 83_400.0));
        let c = &t.coefficients;
        assert_eq!(c.INFLPRES, 83_400.0);
        assert_eq!(c.NOMPRES, 83_400.0);
        // 20 mm at FNOMIN: Fz = Cz·ρ at FNOMIN.
        assert!((c.FNOMIN / c.VERTICAL_STIFFNESS - 0.020).abs() < 1e-15);
        assert_eq!((c.WIDTH, c.ASPECT_RATIO), (0.183, 0.6));
        assert!(stated(&t).is_empty());
        // No pressure data: a stated pressure, for 6.x only.
        let none = with_stated(&bare(MfVersion::Mf61, 0.0)).coefficients;
        assert_eq!((none.NOMPRES, none.INFLPRES), (PRESSURE, PRESSURE));
        let mf52 = with_stated(&bare(MfVersion::Mf52, 0.0)).coefficients;
        assert_eq!((mf52.NOMPRES, mf52.INFLPRES), (0.0, 0.0));
        // A pressure term held away from 0: the pressure is no longer
        // immaterial, and not stated.
        let mut held = bare(MfVersion::Mf62, 0.0);
        held.coefficients.PPY1 = 0.5;
        assert!(stated(&held).iter().all(|s| s.key != "NOMPRES"));
    }
}
