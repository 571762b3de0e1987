//! The input columns of `tyre-eval` a tyre's model does not read: a Gim
//! tyre has no camber, pressure or longitudinal slip terms, a linear tyre
//! reads only load and slip angle, and a points file that sets them is
//! evaluated as if it did not, which a user takes for a result unless it
//! is said. Found by behaviour, not by a list per model: the column is
//! changed at the points (slip ratio and camber to 0, pressure raised by
//! a quarter) and the model is unread in it when no output moves at any
//! of them. The speed is not probed: the points file must give it, and
//! only a sliding-speed friction law reads it. Nor is a Magic Formula
//! tyre: it has terms in every input, and past its file's ranges it holds
//! an input at the range's end (`tyre-eval` counts those points), where
//! a probe would take saturation for an input not read. Its pressure is
//! said unread by the file instead (as MFeval reads it, TNO MF 6.1): a
//! 5.2 file has no pressure terms, a 6.x file without `NOMPRES` has them
//! off (`dpi = 0`), and one whose every pressure coefficient
//! ([`MF_PRESSURE_TERMS`]) is 0 gives them no effect; a pressure column
//! evaluated at such a file was ignored without a word.

use crate::tyre::{PointForces, Tyre};
use serde::Serialize;

/// The camber below which a point counts as at zero for the warning,
/// rad (0.001 rad = 0.057°): a rig's zero-camber rows read ±0.0003 rad
/// of noise about it (the Hoosier 1656 N sweep), and a tyre not reading
/// camber gives them the force it gives at 0, so they are none to say.
pub const CAMBER_RESOLUTION: f64 = 1e-3;

/// The points the probe re-evaluates at most (the first ones where the
/// column is set): a model reads a column everywhere or nowhere.
const PROBED: usize = 256;

/// An input column the model does not read.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Unread {
    /// The column.
    pub column: &'static str,
    /// Points where it is set (non-zero; every point for a pressure),
    /// evaluated as if it were not.
    pub points: usize,
    /// Why a Magic Formula file does not read it, where known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub why: Option<MfNoPressure>,
}

/// Why a Magic Formula file does not respond to the pressure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MfNoPressure {
    /// A 5.2 file (`FITTYP` 5, 52, …): no pressure terms.
    Mf52,
    /// A 6.x file without a positive `NOMPRES`: its terms are off.
    NoNompres,
    /// A 6.x file whose every pressure coefficient is 0.
    TermsZero,
}

/// The coefficients of a 6.x file through which the pressure acts
/// (`dpi = (p − NOMPRES)/NOMPRES`; TNO MF 6.1): Fx, Fy, Mz, Mx, the
/// vertical stiffness and the rolling resistance's `(p/NOMPRES)^QSY8`.
pub const MF_PRESSURE_TERMS: [&str; 14] = [
    "PPX1", "PPX2", "PPX3", "PPX4", "PPY1", "PPY2", "PPY3", "PPY4", "PPY5", "PPZ1", "PPZ2",
    "PPMX1", "PFZ1", "QSY8",
];

/// Why the Magic Formula `t` does not respond to the pressure, or `None`.
pub(super) fn mf_no_pressure(t: &crate::tyre::MagicFormula) -> Option<MfNoPressure> {
    use crate::tyre::mf::MfVersion;
    let c = &t.coefficients;
    let zero = |k: &&str| c.get(k).is_none_or(|v| v == 0.0);
    if t.version == MfVersion::Mf52 {
        Some(MfNoPressure::Mf52)
    } else if c.NOMPRES <= 0.0 {
        Some(MfNoPressure::NoNompres)
    } else if MF_PRESSURE_TERMS.iter().all(zero) {
        Some(MfNoPressure::TermsZero)
    } else {
        None
    }
}

impl Unread {
    /// The sentence on the terminal, for `model`.
    pub fn line(&self, model: &str) -> String {
        let set = match self.column {
            "kappa" | "camber" => format!(
                "{} with {} ≠ 0, evaluated as at 0",
                crate::format::plural(self.points, "point", "points"),
                self.column
            ),
            _ => format!(
                "the {} given at {} ignored",
                self.column,
                crate::format::plural(self.points, "point", "points")
            ),
        };
        let why = match self.why {
            None => "its model does not read it, or its coefficients give it no effect",
            Some(MfNoPressure::Mf52) => "a Magic Formula 5.2 file has no pressure terms (FITTYP 5x)",
            Some(MfNoPressure::NoNompres) => "the file has no NOMPRES, without which its pressure terms are off (MFeval's dpi = 0)",
            Some(MfNoPressure::TermsZero) => "every one of its pressure coefficients (PPX1–4, PPY1–5, PPZ1–2, PPMX1, PFZ1, QSY8) is 0",
        };
        let zero = match self.column {
            "camber" => format!(
                "; a camber within ±{} rad counts as 0 here (a rig's noise about zero)",
                crate::error::Num(CAMBER_RESOLUTION)
            ),
            _ => String::new(),
        };
        format!(
            "this {model} tyre does not respond to `{}`: its forces and moments are the same at any value ({set}); {why}{zero}",
            self.column
        )
    }
}

/// The inputs of the points, by column (`fz, kappa, alpha, camber,
/// speed`), and the pressures (empty: none given).
pub(crate) struct Points<'a> {
    pub columns: [&'a [f64]; 5],
    pub pressure: &'a [f64],
}

/// A column probed: its name, its index (5: the pressure) and the value
/// it is changed to.
type Probe = (&'static str, usize, fn(f64) -> f64);

/// Whether `column` is among the columns the model does not read.
pub(crate) fn is_unread(unread: &[Unread], column: &str) -> bool {
    unread.iter().any(|u| u.column == column)
}

/// The columns of `p` that `tyre` does not read, given its outputs `f`
/// at them.
pub(crate) fn unread(tyre: &Tyre, p: &Points, f: &[PointForces]) -> Vec<Unread> {
    let [fz, kappa, alpha, camber, speed] = p.columns;
    if let Tyre::MagicFormula(t) = tyre {
        let points = (0..p.pressure.len()).filter(|&i| fz[i] > 0.0).count();
        return match mf_no_pressure(t) {
            Some(why) if points > 0 => vec![Unread {
                column: "pressure",
                points,
                why: Some(why),
            }],
            _ => Vec::new(),
        };
    }
    let probes: [Probe; 3] = [
        ("kappa", 1, |_| 0.0),
        ("camber", 3, |_| 0.0),
        ("pressure", 5, |v| 1.25 * v),
    ];
    let mut out = Vec::new();
    for (column, k, changed) in probes {
        let values = if k == 5 { p.pressure } else { p.columns[k] };
        // Slip ratio is set where non-zero, camber from its resolution
        // on; a pressure at every point that gives one.
        let least = if k == 3 { CAMBER_RESOLUTION } else { 0.0 };
        let set: Vec<usize> = (0..values.len())
            .filter(|&i| k == 5 || (values[i].abs() >= least && values[i] != 0.0))
            .filter(|&i| fz[i] > 0.0)
            .collect();
        if set.is_empty() {
            continue;
        }
        let idx = &set[..set.len().min(PROBED)];
        let pick = |c: &[f64]| idx.iter().map(|&i| c[i]).collect::<Vec<f64>>();
        let mut cols = [
            pick(fz),
            pick(kappa),
            pick(alpha),
            pick(camber),
            pick(speed),
        ];
        let mut pressure = if p.pressure.is_empty() {
            Vec::new()
        } else {
            pick(p.pressure)
        };
        let target = if k == 5 { &mut pressure } else { &mut cols[k] };
        target.iter_mut().for_each(|v| *v = changed(*v));
        let g = tyre.evaluate_points(&cols[0], &cols[1], &cols[2], &cols[3], &cols[4], &pressure);
        let same = idx
            .iter()
            .zip(&g)
            .all(|(&i, b)| f[i].fx == b.fx && f[i].fy == b.fy && f[i].mz == b.mz);
        if same {
            out.push(Unread {
                column,
                points: set.len(),
                why: None,
            });
        }
    }
    out
}

/// The warning of the points file's columns `tyre-eval` neither reads nor
/// writes (`not_written`), if any.
pub(crate) fn not_written_line(not_written: &[String]) -> Option<String> {
    if not_written.is_empty() {
        return None;
    }
    Some(format!(
        "the points file's column{} {} not carried to the output: tyre-eval reads fz, kappa, alpha, camber, speed and pressure and writes them with the tyre's outputs",
        if not_written.len() == 1 { "" } else { "s" },
        not_written
            .iter()
            .map(|c| format!("`{c}`"))
            .collect::<Vec<_>>()
            .join(", ")
            + if not_written.len() == 1 { " is" } else { " are" }
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tyre::Linear;

    fn probe(tyre: &Tyre) -> Vec<&'static str> {
        let fz = [3000.0, 4000.0];
        let kappa = [0.05, 0.0];
        let alpha = [0.05, -0.03];
        let camber = [0.02, 0.0];
        let speed = [20.0, 20.0];
        let pressure = [200e3, 200e3];
        let f = tyre.evaluate_points(&fz, &kappa, &alpha, &camber, &speed, &pressure);
        let p = Points {
            columns: [&fz, &kappa, &alpha, &camber, &speed],
            pressure: &pressure,
        };
        unread(tyre, &p, &f).iter().map(|u| u.column).collect()
    }

    #[test]
    fn a_linear_tyre_reads_neither_slip_ratio_camber_nor_pressure() {
        let t = Tyre::Linear(Linear {
            cornering_stiffness: 60e3,
            pneumatic_trail: 0.03,
        });
        assert_eq!(probe(&t), ["kappa", "camber", "pressure"]);
    }

    fn tyre_file(name: &str) -> Tyre {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        crate::io::load_tyre(&root.join("tyres").join(name)).unwrap()
    }

    #[test]
    fn pac89_reads_slip_ratio_and_camber_but_not_pressure() {
        assert_eq!(probe(&tyre_file("pac89_adams_example.toml")), ["pressure"]);
    }

    #[test]
    fn gim_reads_neither_slip_ratio_camber_nor_pressure() {
        // Gim's brush model is lateral: no slip ratio either.
        assert_eq!(
            probe(&tyre_file("gim.toml")),
            ["kappa", "camber", "pressure"]
        );
    }
}
