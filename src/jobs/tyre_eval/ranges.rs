//! The points outside a `.tir` file's ranges, range by range: which range
//! each leaves (load, slip ratio, slip angle, camber, pressure), how many
//! points leave it, its ends and the first such point's line and value. A
//! count over all ranges alone left a user to find which one the points
//! left. Each range in the points' frame (a left-side file's slip angle
//! range negated); units N, rad, Pa. With the limit checks off (mode 2xx)
//! the points are evaluated at the values given, and the ranges they leave
//! are said as extrapolated past. Each end is said apart: a point
//! beyond one is evaluated at that end, except a load below `FZMIN`, which
//! MFeval (as TNO's MF-Tyre) does not saturate: its forces are evaluated at
//! the load given, only the pneumatic trail at `FZMIN` and the rolling and
//! overturning moments scaled down below it; a 6.x file with `QSY7 = 0`
//! has a rolling resistance that does not depend on the load (TNO eq. A48:
//! `My ∝ (Fz/Fz0)^QSY7`; the public `Truck_430_50R38.tir` gives −201.93 N·m
//! from 1 N to 60 kN), which the words say with its value instead.

use crate::format::{plural, rounded};
use crate::tyre::mf::{InputRange, MfInput, MfVersion};
use crate::tyre::MagicFormula;
use serde::Serialize;

/// A range some points leave.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RangeLeft {
    /// The range, in the points' frame.
    pub range: InputRange,
    /// Points outside it.
    pub points: usize,
    /// The first such point's line in the points file (1-based).
    pub first_line: usize,
    /// Its value there, as given (the pressure the file's `INFLPRES`, else
    /// `NOMPRES`, where the points give none).
    pub first_value: f64,
    /// The points leave it below its lower end (else above its upper).
    pub below: bool,
    /// The limit checks were off (mode 2xx): the points were evaluated at
    /// the values given, past the range, not at its end.
    pub as_given: bool,
    /// Below `FZMIN` of a file whose rolling resistance does not depend on
    /// the load (`QSY7 = 0`): its `my` at the first such point, N·m.
    pub load_free_my: Option<f64>,
    /// What the camber range says of the points leaving it
    /// ([`CamberHint`]; `None` for any other range).
    pub camber_hint: CamberHint,
}

/// The least span of a camber range, rad (1°), that a column read in
/// degrees is asked of: a file fitted at one camber (`identify` writes the
/// rig rows' range, −0.00036 to 0.00045 rad for the Hoosier test at 0°)
/// holds every camber of a column in degrees inside it read as degrees
/// (0.02° = 0.00035 rad), and a correct 0.02 rad was asked as degrees.
pub const DEGREES_HINT_SPAN: f64 = std::f64::consts::PI / 180.0;

/// What a camber range some points leave says of them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum CamberHint {
    /// Nothing beyond the range's words.
    None,
    /// A range spanning at least [`DEGREES_HINT_SPAN`] that every tilted
    /// point leaves far, each of which read in degrees lies inside it: the
    /// column reads as degrees (0.5 meant as 0.5° is 28.6° in radians,
    /// where `physical.rs` asks only past 20°).
    Degrees,
    /// A range narrower than [`DEGREES_HINT_SPAN`]: the tyre was fitted at
    /// one camber, its middle (rad), and no unit makes a point another.
    OneLevel {
        /// The camber the tyre was fitted at, rad (0 where the range holds 0).
        camber: f64,
    },
}

impl CamberHint {
    /// The hint of `range` (a camber range of `tyre`) that the points
    /// `inputs` leave.
    fn of(tyre: &MagicFormula, range: &InputRange, inputs: &[MfInput]) -> Self {
        if range.column != "camber" {
            return CamberHint::None;
        }
        match (range.lo, range.hi) {
            (Some(lo), Some(hi)) if hi - lo < DEGREES_HINT_SPAN => CamberHint::OneLevel {
                camber: if lo <= 0.0 && hi >= 0.0 {
                    0.0
                } else {
                    0.5 * (lo + hi)
                },
            },
            _ if camber_reads_as_degrees(tyre, inputs) => CamberHint::Degrees,
            _ => CamberHint::None,
        }
    }

    /// Its words after those of `range`, the camber range it is of.
    fn said(self, range: &InputRange) -> String {
        match self {
            CamberHint::None => String::new(),
            CamberHint::Degrees => "; every camber of the points other than 0 lies outside the range, and read in degrees every one lies inside it: angles are in radians (FORMATS.md); is the column in degrees?".to_string(),
            CamberHint::OneLevel { camber } => {
                let at = match camber == 0.0 {
                    true => "0".to_string(),
                    false => format!(
                        "{} rad ({}°)",
                        rounded(camber, 4),
                        rounded(camber.to_degrees(), 3)
                    ),
                };
                let end = |v: Option<f64>| v.map_or(String::new(), |v| rounded(v, 4));
                format!(
                    "; the tyre was fitted at camber {at} only ({} to {}, {} to {} rad, a range under 1°): its camber terms describe no other camber, in any unit",
                    range.keys[0],
                    range.keys[1],
                    end(range.lo),
                    end(range.hi),
                )
            }
        }
    }
}

/// The Magic Formula inputs of the point columns `[fz, kappa, alpha,
/// camber, speed]` (equal lengths) and `pressure` (one per point, or empty
/// for the tyre's own): N, rad, m/s, Pa.
pub fn mf_inputs(columns: [&[f64]; 5], pressure: &[f64]) -> Vec<MfInput> {
    let [fz, kappa, alpha, camber, speed] = columns;
    (0..fz.len())
        .map(|i| MfInput {
            fz: fz[i],
            kappa: kappa[i],
            alpha: alpha[i],
            camber: camber[i],
            speed: speed[i],
            pressure: pressure.get(i).copied(),
        })
        .collect()
}

/// Where a range's first point is said to be: a points file's line
/// (`tyre-eval`), or an index into the arrays given (Python).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FirstAt {
    /// The points file's line.
    Line,
    /// The index into the arrays given.
    Index,
}

/// The ranges of `tyre` the points `inputs` (at file lines `lines`) leave,
/// in [`MagicFormula::file_ranges`]'s order: with the limit checks on, the
/// ends the points were held to; off, the ranges they were evaluated
/// beyond as given (a 100 kN point of an 18 kN file is said either way).
pub fn ranges_left(tyre: &MagicFormula, inputs: &[MfInput], lines: &[usize]) -> Vec<RangeLeft> {
    let as_given = !tyre.mode().limit_checks;
    let mut out: Vec<RangeLeft> = Vec::new();
    for (i, q) in inputs.iter().enumerate() {
        for (range, value) in tyre.file_ranges_left(q) {
            let below = range.lo.is_some_and(|lo| value < lo);
            let same = |r: &&mut RangeLeft| r.range.keys == range.keys && r.below == below;
            match out.iter_mut().find(same) {
                Some(r) => r.points += 1,
                None => out.push(RangeLeft {
                    range,
                    points: 1,
                    first_line: lines.get(i).copied().unwrap_or(0),
                    first_value: value,
                    below,
                    as_given,
                    load_free_my: (below && range.column == "fz")
                        .then(|| load_free_my(tyre, q))
                        .flatten(),
                    camber_hint: CamberHint::of(tyre, &range, inputs),
                }),
            }
        }
    }
    let all = tyre.file_ranges();
    let order = |r: &RangeLeft| all.iter().position(|a| a.keys == r.range.keys);
    out.sort_by_key(|r| (order(r), !r.below));
    out
}

/// Whether every point of `inputs` at a camber other than 0 leaves the
/// file's camber range (at least [`DEGREES_HINT_SPAN`] wide) far (at least twice the size of the end it
/// passes) and each, read in degrees, lies inside it: a column of small
/// cambers in degrees (0.3, 0.5, 2) evaluated at `CAMMAX` without a word
/// on its unit otherwise. A camber just past an end (3.22° given as
/// 0.0561996 rad against `CAMMAX` = 0.05619) is no unit slip: degrees
/// read as radians are 57 times their size, so a column in degrees whose
/// values lie inside the range in degrees lies up to 57 times past it.
fn camber_reads_as_degrees(tyre: &MagicFormula, inputs: &[MfInput]) -> bool {
    let leaves = |q: &MfInput| {
        let camber = |(r, _): &(InputRange, f64)| r.column == "camber";
        tyre.file_ranges_left(q).iter().any(camber)
    };
    let leaves_far = |q: &MfInput| {
        tyre.file_ranges_left(q).iter().any(|(r, v)| {
            let end = if r.hi.is_some_and(|hi| *v > hi) {
                r.hi
            } else {
                r.lo
            };
            r.column == "camber" && end.is_some_and(|e| v.abs() >= 2.0 * e.abs())
        })
    };
    let mut tilted = inputs.iter().filter(|q| q.camber != 0.0).peekable();
    tilted.peek().is_some()
        && tilted.all(|q| {
            let degrees = MfInput {
                camber: q.camber.to_radians(),
                ..*q
            };
            leaves_far(q) && !leaves(&degrees)
        })
}

/// What a Magic Formula evaluates below `FZMIN`.
const BELOW_FZMIN: &str = "fx and fy evaluated at the load given (MFeval saturates the load only at FZMAX), the pneumatic trail at FZMIN and";

/// The rolling resistance of `tyre` at `q` where it does not depend on
/// the load: a 6.x file's `(Fz/Fz0)^QSY7` with `QSY7 = 0` (a 5.2 file's
/// `My` is proportional to the load whatever its `QSY7`).
fn load_free_my(tyre: &MagicFormula, q: &MfInput) -> Option<f64> {
    let c = &tyre.coefficients;
    (tyre.version != MfVersion::Mf52 && c.QSY7 == 0.0).then(|| tyre.evaluate(q).my)
}

impl RangeLeft {
    /// What the points below `FZMIN` were evaluated at: the rolling
    /// resistance said with its value where it does not depend on the load.
    fn below_fzmin(&self) -> String {
        match self.load_free_my {
            Some(my) => format!(
                "{BELOW_FZMIN} the overturning moment scaled down below it; this file's rolling resistance does not depend on the load (QSY7 = 0): my = {} N·m at the first of them, the same at any load",
                rounded(my, 6)
            ),
            None => format!("{BELOW_FZMIN} the rolling and overturning moments scaled down below it"),
        }
    }

    /// The range in words, of `count` points, the first at its file line.
    pub fn line(&self, count: usize) -> String {
        self.said(count, FirstAt::Line)
    }

    /// The range in words, of `count` points, the first where `at` says.
    pub fn said(&self, count: usize, at: FirstAt) -> String {
        let r = &self.range;
        let unit = match r.unit {
            "" => String::new(),
            u => format!(" {u}"),
        };
        let end = |v: Option<f64>| v.map_or("unbounded".to_string(), |v| rounded(v, 4));
        let (side, key, bound) = match self.below {
            true => ("below", r.keys[0], r.lo),
            false => ("above", r.keys[1], r.hi),
        };
        // The value given, and the one evaluated where it is the end's (a
        // 2 MPa pressure is evaluated at PRESMAX): both said.
        let (evaluated, given) = match (r.column, self.below) {
            _ if self.as_given => (
                "evaluated at the value given, past the range (the limit checks off, mode 2xx): an extrapolation of the file".to_string(),
                String::new(),
            ),
            ("fz", true) => (self.below_fzmin(), String::new()),
            _ => ("evaluated at that end".to_string(), format!(" given, evaluated at {}{unit}", end(bound))),
        };
        let degrees = self.camber_hint.said(r);
        format!(
            "{} of {} {side} {key} = {}{unit}{} (the file's range {} to {}): {evaluated}; the first at {} {}, {} = {}{unit}{given}{degrees}",
            self.points,
            plural(count, "point", "points"),
            end(bound),
            match r.column {
                "alpha" | "camber" => ", in the points' frame",
                _ => "",
            },
            end(r.lo),
            end(r.hi),
            match at {
                FirstAt::Line => "line",
                FirstAt::Index => "index",
            },
            self.first_line,
            r.column,
            rounded(self.first_value, 6)
        )
    }
}
