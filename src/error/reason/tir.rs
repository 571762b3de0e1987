//! The texts of the `.tir` reader's refusals ([`Limit::TyrePressure`],
//! [`ParamReason::TirDeclaredUnit`], [`ParamReason::MfPureCurve`]) and the
//! boxed values they are built from, apart from the other reasons so that
//! `reason.rs` stays readable.

use super::{Limit, ParamReason};

impl Limit {
    /// The units a pressure written as Pa is likely in, and their Pa.
    pub(crate) const PRESSURE_UNITS: [(&'static str, f64); 4] = [
        ("kPa", 1e3),
        ("bar", 1e5),
        ("psi", 6_894.757_293_168),
        ("MPa", 1e6),
    ];
}

/// The message of [`Limit::TyrePressure`]: the tyres' pressures, and the
/// unit the value is likely in with it converted.
pub(super) fn tyre_pressure(given: f64, unit: Option<u8>, nominal: bool, apart: bool) -> String {
    let (key, other) = match nominal {
        true => ("NOMPRES", "INFLPRES"),
        false => ("INFLPRES", "NOMPRES"),
    };
    let mut s = format!("a tyre's inflation pressure is 10 kPa to 2 MPa (a kart's about 60 kPa, a car's 200–300 kPa, a track bicycle's up to 1.4 MPa); {key} is in Pa after the file's [UNITS]");
    match unit.and_then(|u| Limit::PRESSURE_UNITS.get(u as usize)) {
        Some((name, pa)) => {
            s += &format!(
                ": is it in {name}? ({} {name} is {} Pa)",
                crate::error::Num(given),
                crate::format::rounded(given * pa, 6)
            );
            if apart {
                s += &format!(
                    "; the file's {other} is about {} times it: the two are in different units",
                    crate::format::rounded(*pa, 4)
                );
            }
        }
        None => s += ": check the value and the file's [UNITS] PRESSURE",
    }
    s
}

/// The message of [`Limit::UnloadedRadius`]: a radius too large is read
/// as millimetres, centimetres or inches written as metres, or a digit
/// slipped (3.1 m for 0.31); one too small as metres read under a smaller
/// `[UNITS] LENGTH` (or divided twice), or a digit slipped (0.031 m): of
/// the readings that land it on a tyre's, the hint gives the one nearest
/// a car tyre's 0.3 m (logarithmically), with the value converted.
pub(super) fn unloaded_radius(given: f64) -> String {
    use crate::format::{exact, rounded};
    let head = "a tyre's unloaded radius is 0.05–2 m (a kart's about 0.13 m, a car's about 0.3 m), in m after the file's [UNITS] LENGTH";
    // `tyre::sizes::UNLOADED_RADIUS` (a lower layer may not import it).
    let (lo, hi) = (0.05, 2.0);
    let lands = |v: f64| v > lo && v <= hi;
    // (reading, factor to the radius it gives): `None` is a digit.
    let readings: &[(Option<&str>, f64)] = match given > hi {
        true => &[
            (Some("millimetres"), 1e-3),
            (Some("centimetres"), 1e-2),
            (Some("inches"), 0.0254),
            (None, 0.1),
        ],
        false => &[(Some("millimetres"), 1e3), (None, 10.0)],
    };
    let best = readings
        .iter()
        .filter(|(_, f)| given > 0.0 && lands(given * f))
        .min_by(|a, b| {
            let off = |f: f64| (given * f / 0.3).ln().abs();
            off(a.1).total_cmp(&off(b.1))
        });
    let (large, v) = (given > hi, exact(given));
    match best {
        Some((None, f)) => format!(
            "{head}: too {} for any tyre: is a digit slipped? {} m is a tyre's radius",
            if large { "large" } else { "small" },
            rounded(given * f, 4)
        ),
        Some((Some(unit), f)) if large => format!(
            "{head}: too large for metres: is it in {unit}, written with LENGTH = 'meter'? ({v} {unit} is {} m)",
            rounded(given * f, 4)
        ),
        Some((Some(_), f)) => format!(
            "{head}: too small: {v} m is {} mm; as metres it would be {} m, a tyre's: is a value in metres read under LENGTH = 'mm' (or converted to metres twice)?",
            rounded(given * f, 4),
            rounded(given * f, 4)
        ),
        None if large => format!("{head}: too large for any tyre in metres, millimetres or inches, or with a digit slipped: check the value"),
        None => format!("{head}: check the value and the file's [UNITS] LENGTH"),
    }
}

/// What [`ParamReason::TirLoadOffNominal`] says, boxed.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadOffNominal {
    /// The value as the file writes it.
    pub written: f64,
    /// The force unit it is read in (`N`, `kN`, …: the file's `[UNITS]`
    /// FORCE, `N` where it gives none).
    pub unit: &'static str,
    /// That unit in N.
    pub factor: f64,
    /// `FNOMIN` as written, same unit.
    pub fnomin: f64,
    /// The value over `FNOMIN`.
    pub ratio: f64,
    /// The shares of `FNOMIN` a tyre's load range lies within.
    pub range: (f64, f64),
    /// The key is `FZMAX` (else `FZMIN`).
    pub max: bool,
}

impl ParamReason {
    /// [`ParamReason::TirLoadOffNominal`] of the value `written` in `unit`
    /// (`factor` N), beside `FNOMIN` `fnomin` (same unit), `ratio` times
    /// it, outside the shares `range` of it a tyre's load range lies in.
    pub(crate) fn tir_load_off_nominal(
        written: f64,
        (unit, factor): (&'static str, f64),
        (fnomin, ratio): (f64, f64),
        (range, max): ((f64, f64), bool),
    ) -> Self {
        ParamReason::TirLoadOffNominal(Box::new(LoadOffNominal {
            written,
            unit,
            factor,
            fnomin,
            ratio,
            range,
            max,
        }))
    }
}

/// The message of [`ParamReason::TirLoadOffNominal`]: the value, the
/// declared unit, the factor off `FNOMIN`, and the unit it is likely in.
pub(super) fn load_off_nominal(d: &LoadOffNominal) -> String {
    use crate::format::{exact, rounded};
    let (lo, hi) = d.range;
    let head = format!(
        "is {} {} as the file's [UNITS] FORCE reads it, {} times its FNOMIN = {} {}: a tyre's validity range of loads lies within {lo} to {hi} times its nominal load (published files: FZMAX 2–3 times FNOMIN)",
        exact(d.written),
        d.unit,
        rounded(d.ratio, 3),
        exact(d.fnomin),
        d.unit,
    );
    // The reading of the value as written that makes it the load range's
    // end it is: FZMAX at or above FNOMIN, FZMIN at or below it, nearest
    // the published files' share (FZMAX 2.5 times FNOMIN, FZMIN a 40th):
    // another force unit, or a digit slipped in the file's own.
    let units = [
        ("N", 1.0),
        ("kN", 1e3),
        ("lbf", 4.448_221_615_260_5),
        ("kgf", 9.806_65),
    ];
    let (band, aim) = match d.max {
        true => ((1.0, hi), 2.5),
        false => ((lo, 1.0), 0.025),
    };
    let likely = units
        .into_iter()
        .filter(|(_, f)| *f != d.factor)
        .map(|(u, f)| (Some(u), f / d.factor))
        .chain([(None, 10.0), (None, 0.1)])
        .map(|(u, f)| (u, f, d.ratio * f))
        .filter(|(_, _, r)| *r >= band.0 && *r <= band.1)
        .min_by(|a, b| (a.2 / aim).ln().abs().total_cmp(&(b.2 / aim).ln().abs()));
    match likely {
        Some((Some(u), f, r)) => format!(
            "{head}: is it written in {u}? ({} {u} is {} {}, {} times FNOMIN)",
            exact(d.written),
            rounded(d.written * f, 4),
            d.unit,
            rounded(r, 3)
        ),
        Some((None, f, r)) => format!(
            "{head}: is a digit slipped? {} {} would be {} times FNOMIN",
            rounded(d.written * f, 4),
            d.unit,
            rounded(r, 3)
        ),
        None => format!("{head}: check the value and FNOMIN"),
    }
}

/// What [`ParamReason::TirDeclaredUnit`] says, boxed.
#[derive(Debug, Clone, PartialEq)]
pub struct DeclaredUnit {
    /// The value as the file writes it.
    pub written: f64,
    /// The line of the `[UNITS]` key that declares the unit.
    pub line: usize,
    /// That key (`FORCE`, `LENGTH`, `PRESSURE`).
    pub key: &'static str,
    /// The unit it declares (`kN`, `mm`).
    pub unit: &'static str,
    /// The range of any tyre, SI, `(lo, hi]`.
    pub range: (f64, f64),
    /// How the value's unit follows from the declared one.
    pub how: DeclaredHow,
}

/// How a value's unit follows from a declared one ([`DeclaredUnit::how`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeclaredHow {
    /// The key's SI unit (`N`, `m`, `Pa`, `N/m`).
    pub si: &'static str,
    /// What stands before and after the declared unit in the value's
    /// (`("", "/m")` for kN/m, `("N/", "²")` for N/mm²), or nothing.
    pub around: (&'static str, &'static str),
    /// The value's unit in SI.
    pub factor: f64,
    /// A pressure read in `FORCE/LENGTH²`: the file has no `PRESSURE` line.
    pub no_pressure_line: bool,
}

impl ParamReason {
    /// [`ParamReason::TirDeclaredUnit`] of the value `written` read in the
    /// `unit` that `[UNITS]` key `key` declares at `line`.
    pub(crate) fn tir_declared_unit(
        written: f64,
        line: usize,
        (key, unit): (&'static str, &'static str),
        range: (f64, f64),
        how: DeclaredHow,
    ) -> Self {
        ParamReason::TirDeclaredUnit(Box::new(DeclaredUnit {
            written,
            line,
            key,
            unit,
            range,
            how,
        }))
    }
}

/// The message of [`ParamReason::TirDeclaredUnit`]: the declaration that
/// makes the value no tyre's, and the value as written, a tyre's in SI.
pub(super) fn declared_unit(d: &DeclaredUnit) -> String {
    let word = match d.key {
        "FORCE" => "'newton'",
        "LENGTH" => "'meter'",
        _ => "'pascal'",
    };
    let h = d.how;
    let si = h.si;
    let (lo, hi) = d.range;
    let range = match (hi.is_finite(), lo == -hi) {
        (true, true) => format!("±{}", crate::format::readable(hi, 3)),
        (true, false) => format!("({}, {}]", crate::error::Num(lo), crate::error::Num(hi)),
        (false, _) => format!("above {}", crate::error::Num(lo)),
    };
    // A unit built on the declared one says its factor (kN/m is 1000 N/m).
    let unit = match h.around {
        ("", "") => d.unit.to_string(),
        (before, after) => format!(
            "{before}{}{after} ({} {si} each)",
            d.unit,
            crate::format::rounded(h.factor, 6)
        ),
    };
    let (declares, fix) = match h.no_pressure_line {
        true => (
            " with no PRESSURE line (pressures are then read in FORCE/LENGTH²)".to_string(),
            "add PRESSURE = 'pascal' to [UNITS] (it reads them as written)".to_string(),
        ),
        false => (
            String::new(),
            format!(
                "are the file's values in {si}, and line {} the slip? ({} = {word} reads them as written)",
                d.line, d.key
            ),
        ),
    };
    format!(
        "is the {} written here read in {unit}, as the file's [UNITS] {} at line {} declares{declares}: outside any tyre's {range} {si}; read in {si}, as written, it is a tyre's: {fix}",
        crate::error::Num(d.written),
        d.key,
        d.line,
    )
}

/// What is wrong with a `.tir` file's pure-slip curve ([`PureCurve::fault`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CurveFault {
    /// Its peak |F|/Fz lies beyond any tyre's.
    Peak,
    /// It turns against its slip.
    Reversal,
    /// It is the same at every slip: a shape factor C of about 0 makes
    /// `sin(C·atan(B·x))` vanish, leaving the shifts' constant force.
    Flat,
}

/// What [`ParamReason::MfPureCurve`] says, boxed: where a `.tir` file's
/// pure-slip curve goes beyond any tyre's.
#[derive(Debug, Clone, PartialEq)]
pub struct PureCurve {
    /// The lateral force over the slip angle (else the longitudinal over
    /// the slip ratio).
    pub lateral: bool,
    /// The coefficient named (the error's key).
    pub key: &'static str,
    /// |F|/Fz at the point for a peak, else the force there, N.
    pub at: f64,
    /// What is wrong with the curve.
    pub fault: CurveFault,
    /// The load, N.
    pub load: f64,
    /// The slip angle (rad) or ratio.
    pub slip: f64,
    /// The shape factor C (`PCY1·LCY`, `PCX1·LCX`).
    pub shape: f64,
    /// The speed evaluated at (`LONGVL`), m/s.
    pub speed: f64,
}

/// The message of [`ParamReason::MfPureCurve`].
pub(super) fn pure_curve(p: &PureCurve) -> String {
    use crate::format::{readable, rounded};
    let (f, a, slip, axis) = match p.lateral {
        true => (
            "Fy",
            'Y',
            format!(
                "α = {} rad ({}°)",
                readable(p.slip, 3),
                readable(p.slip.to_degrees(), 3)
            ),
            "lateral",
        ),
        false => (
            "Fx",
            'X',
            format!("κ = {}", readable(p.slip, 3)),
            "longitudinal",
        ),
    };
    let head = format!(
        "the file's pure {axis} force (at zero {}, no camber, LONGVL = {} m/s)",
        if p.lateral {
            "slip ratio"
        } else {
            "slip angle"
        },
        rounded(p.speed, 4)
    );
    let at = format!("at Fz = {} N and {slip}", rounded(p.load, 5));
    if p.fault == CurveFault::Flat {
        return format!(
            "makes {head} the same at every {}: {f} = {} N {at} as at any other (the shifts' force alone), where a tyre's rises with its slip (its stiffness): the shape factor C = PC{a}1·LC{a} = {} makes sin(C·atan(B·x)) about 0 at every slip (a tyre's C is about 1.1–1.9): check {}",
            if p.lateral { "slip angle" } else { "slip ratio" },
            readable(p.at, 4),
            readable(p.shape, 4),
            p.key
        );
    }
    if p.fault == CurveFault::Peak {
        let why = match p.key {
            k if k.starts_with("LMU") => format!("{k} scales the peak friction (1 as fitted)"),
            k if k.ends_with('2') => format!("{k} is the peak friction's change with load"),
            k => format!("{k} is the peak friction μ{} at FNOMIN (a road or racing tyre's is about 0.8–1.8; some published defaults reach 3)", a.to_ascii_lowercase()),
        };
        return format!(
            "makes {head} reach |{f}|/Fz = {} {at}, beyond the friction 5 no tyre reaches (racing slicks about 1.8; a TOML tyre's limit): {why}: check it",
            readable(p.at, 3)
        );
    }
    let why = match p.shape > 2.0 {
        true => format!(
            "the shape factor C = PC{a}1·LC{a} = {} lies above 2, past which a Magic Formula's force turns around after its peak (a tyre's C is about 1.1–1.9)",
            readable(p.shape, 4)
        ),
        false => format!(
            "the shape factor C = PC{a}1·LC{a} = {} does not turn it (C ≤ 2): the curvature (PE{a}1…) or the shifts (PH{a}…, PV{a}…) do; check {}",
            readable(p.shape, 4),
            p.key
        ),
    };
    format!(
        "turns {head} against its slip: {f} = {} N {at}, where smaller slips of that sign give a force of the other sign: {why}",
        readable(p.at, 3)
    )
}

impl ParamReason {
    /// [`ParamReason::MfPureCurve`]: the `lateral` (else longitudinal)
    /// curve, the coefficient `key` named, what is wrong (`fault`) `at`
    /// the point (|F|/Fz of a peak, else the force), the point's load and
    /// slip, the shape factor C and the speed.
    pub(crate) fn mf_pure_curve(
        (lateral, key): (bool, &'static str),
        (at, fault): (f64, CurveFault),
        (load, slip): (f64, f64),
        (shape, speed): (f64, f64),
    ) -> Self {
        ParamReason::MfPureCurve(Box::new(PureCurve {
            lateral,
            key,
            at,
            fault,
            load,
            slip,
            shape,
            speed,
        }))
    }
}
