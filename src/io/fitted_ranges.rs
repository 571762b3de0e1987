//! The `[fitted_ranges]` table of a TOML tyre file: the ranges of the rig
//! data its parameters were fitted to (`identify` writes it), so that
//! `tyre-eval` can count the points it evaluates beyond them. A `.tir`
//! states its own validity ranges (`FZMIN`…`PRESMAX`); the TOML models
//! have none, and a Gim or PAC89 tyre evaluated at three times the loads
//! it was fitted to extrapolates a curve no data constrained.
//!
//! Keys (each optional, `[low, high]` in SI units, the crate's sign
//! convention): `fz` (N), `alpha` (rad), `kappa` (-), `camber` (rad),
//! `pressure` (Pa). The table is not part of the tyre model: the tyre is
//! read from the file with the table's lines blanked (every other line
//! and column kept, so an error in the tyre is placed as before), and the
//! table from the file alone. A hand-written tyre without it is checked
//! against nothing.

use super::{param_error, TomlSource};
use crate::constants::MOST_PRESSURE;
use crate::error::{InputError, Limit, ParamError, ParamReason};
use crate::format::readable;
use serde::{Deserialize, Serialize};

/// The table's name in a TOML tyre file.
pub const TABLE: &str = "fitted_ranges";

/// The significant digits a written range keeps: a rig's load or slip
/// angle is not measured to more (17 wrote `0.2085668456133224` rad).
pub const RANGE_DIGITS: usize = 6;

/// `[lo, hi]` rounded outward to `digits` significant digits: the range
/// written still holds every point of the data it was read from.
fn outward([lo, hi]: [f64; 2], digits: usize) -> [f64; 2] {
    let round = |v: f64, up: bool| {
        if v == 0.0 || !v.is_finite() {
            return v;
        }
        // By a power of ten that is exact (10^k, k ≥ 0) both ways, so the
        // result is the double nearest its decimal text.
        let e = digits as i32 - 1 - v.abs().log10().floor() as i32;
        let p = 10f64.powi(e.abs());
        let (x, back): (f64, &dyn Fn(f64) -> f64) = if e >= 0 {
            (v * p, &|r| r / p)
        } else {
            (v / p, &|r| r * p)
        };
        // A value already at `digits` digits (2500) stays as it is.
        let snapped = x.round();
        let r = if (x - snapped).abs() <= 1e-9 * x.abs() {
            snapped
        } else if up {
            x.ceil()
        } else {
            x.floor()
        };
        back(r)
    };
    [round(lo, false), round(hi, true)]
}

/// The ranges of the data a tyre was fitted to, each `[low, high]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FittedRanges {
    /// Vertical load, N.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fz: Option<[f64; 2]>,
    /// Slip angle, rad.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha: Option<[f64; 2]>,
    /// Slip ratio.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kappa: Option<[f64; 2]>,
    /// Camber, rad.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub camber: Option<[f64; 2]>,
    /// Inflation pressure, Pa.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pressure: Option<[f64; 2]>,
}

impl FittedRanges {
    /// Every range rounded outward to `digits` significant digits.
    pub fn rounded_outward(&self, digits: usize) -> Self {
        let o = |r: Option<[f64; 2]>| r.map(|r| outward(r, digits));
        FittedRanges {
            fz: o(self.fz),
            alpha: o(self.alpha),
            kappa: o(self.kappa),
            camber: o(self.camber),
            pressure: o(self.pressure),
        }
    }
}

/// The share of a range's span a value may lie past either end and still
/// be read as within it: a rig holds its load and slip angle to about 1 %
/// of their sweep (a load logged 0.5 N, a slip angle 0.03° past the data's
/// end is a point of the data, not an extrapolation).
pub const SLACK: f64 = 0.01;

/// Whether `v` lies past `[lo, hi]` by more than `share` of its span
/// (a range open at one end, a `.tir`'s without `FZMIN`, has no slack):
/// `Some(true)` below, `Some(false)` above, `None` within.
pub fn past_by([lo, hi]: [f64; 2], v: f64, share: f64) -> Option<bool> {
    let span = hi - lo;
    let slack = if span.is_finite() { share * span } else { 0.0 };
    match (v < lo - slack, v > hi + slack) {
        (true, _) => Some(true),
        (_, true) => Some(false),
        _ => None,
    }
}

/// A range a point leaves ([`FittedRanges::left`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RangeLeft {
    /// The key (`fz`, `alpha`, `kappa`, `camber`, `pressure`).
    pub key: &'static str,
    /// Its unit (N, rad, Pa; empty for the slip ratio).
    pub unit: &'static str,
    /// The range, `[low, high]`.
    pub range: [f64; 2],
    /// The point's value.
    pub value: f64,
    /// It lies below the range (else above).
    pub below: bool,
}

/// One point's inputs, as the ranges read them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RangePoint {
    /// Load, N.
    pub fz: f64,
    /// Slip angle, rad.
    pub alpha: f64,
    /// Slip ratio.
    pub kappa: f64,
    /// Camber, rad.
    pub camber: f64,
    /// Pressure, Pa (`None`: not given, not checked).
    pub pressure: Option<f64>,
}

/// `range` written as a TOML file reads it: the table's half of a tyre
/// file, parsed alone.
#[derive(Deserialize)]
struct TableOnly {
    #[serde(default)]
    fitted_ranges: Option<FittedRanges>,
}

impl FittedRanges {
    /// The ranges with their names and units, in key order.
    fn named(&self) -> [(&'static str, &'static str, Option<[f64; 2]>); 5] {
        [
            ("fz", "N", self.fz),
            ("alpha", "rad", self.alpha),
            ("kappa", "", self.kappa),
            ("camber", "rad", self.camber),
            ("pressure", "Pa", self.pressure),
        ]
    }

    /// Whether `p` lies outside a range by more than `share` of its span
    /// (a load at or below 0, off the road, is never counted: no tyre
    /// model gives a force there): [`SLACK`] for the ranges of rig data,
    /// 0 for a `.tir`'s validity ranges, at whose ends the model clamps.
    pub fn outside(&self, p: &RangePoint, share: f64) -> bool {
        !self.left_by(p, share).is_empty()
    }

    /// The ranges `p` lies past by more than [`SLACK`] of their span, in
    /// key order: the key, its unit, the range, the value and whether it
    /// lies below (else above). None for a load at or below 0.
    pub fn left(&self, p: &RangePoint) -> Vec<RangeLeft> {
        self.left_by(p, SLACK)
    }

    /// [`Self::left`] with `share` of a span as the slack.
    pub fn left_by(&self, p: &RangePoint, share: f64) -> Vec<RangeLeft> {
        if p.fz <= 0.0 {
            return Vec::new();
        }
        let values = [
            Some(p.fz),
            Some(p.alpha),
            Some(p.kappa),
            Some(p.camber),
            p.pressure,
        ];
        self.named()
            .into_iter()
            .zip(values)
            .filter_map(|((key, unit, range), value)| {
                let (range, value) = (range?, value?);
                let below = past_by(range, value, share)?;
                Some(RangeLeft {
                    key,
                    unit,
                    range,
                    value,
                    below,
                })
            })
            .collect()
    }

    /// `fz 474 to 2768 N, alpha -0.1693 to 0.1692 rad, …`.
    pub fn text(&self) -> String {
        let parts: Vec<String> = self
            .named()
            .iter()
            .filter_map(|(name, unit, r)| {
                let [lo, hi] = (*r)?;
                let unit = if unit.is_empty() {
                    String::new()
                } else {
                    format!(" {unit}")
                };
                Some(format!(
                    "{name} {} to {}{unit}",
                    readable(lo, 4),
                    readable(hi, 4)
                ))
            })
            .collect();
        parts.join(", ")
    }

    /// Ok when every range is finite with its upper end not below its
    /// lower (`[4000, 4000]`: data at one load).
    fn check(&self) -> Result<(), ParamError> {
        for (name, _, r) in self.named() {
            let Some([lo, hi]) = r else { continue };
            ParamError::finite(&format!("{name}[0]"), lo)?;
            ParamError::finite(&format!("{name}[1]"), hi)?;
            if hi < lo {
                let reason = ParamReason::RangeReversed { lo };
                return Err(ParamError::new(&format!("{name}[1]"), hi, reason));
            }
            // No range today's `identify` writes: its rig data are refused
            // above the limit (`rig_rows.rs`), so the file's range would
            // let a point at an impossible pressure read as fitted.
            if name == "pressure" {
                for (k, v) in [lo, hi].into_iter().enumerate() {
                    let why = Limit::WrittenPressure;
                    ParamError::in_range(&format!("pressure[{k}]"), v, 0.0, MOST_PRESSURE, why)?;
                }
            }
        }
        Ok(())
    }
}

/// The tyre's part of a TOML tyre file `src` (the `[fitted_ranges]`
/// table's lines blanked, every other byte where it was) and the table,
/// checked. A file without the table is returned as it is.
pub(crate) fn split(src: &TomlSource) -> Result<(TomlSource, Option<FittedRanges>), InputError> {
    let Some((start, end)) = table_bytes(&src.text) else {
        return Ok((src.clone(), None));
    };
    let ranges = src.parse::<TableOnly>()?.fitted_ranges;
    if let Some(r) = &ranges {
        r.check().map_err(|e| param_error(src, Some(TABLE), e))?;
    }
    let mut text = src.text.clone();
    let blank: String = text[start..end]
        .chars()
        .map(|c| if c == '\n' { '\n' } else { ' ' })
        .collect();
    text.replace_range(start..end, &blank);
    let tyre = TomlSource {
        path: src.path.clone(),
        text,
    };
    Ok((tyre, ranges))
}

/// The bytes of the `[fitted_ranges]` table in `text`: from its header's
/// line to the next table header (a line that opens with `[`) or the end.
fn table_bytes(text: &str) -> Option<(usize, usize)> {
    let mut offset = 0;
    let mut start = None;
    for line in text.split_inclusive('\n') {
        let t = line.trim_start();
        let header = t.starts_with('[');
        match start {
            None if header && table_name(t) == Some(TABLE) => start = Some(offset),
            Some(s) if header => return Some((s, offset)),
            _ => {}
        }
        offset += line.len();
    }
    start.map(|s| (s, text.len()))
}

/// The name of the table a header line `[name] # …` opens.
fn table_name(line: &str) -> Option<&str> {
    let inner = line.strip_prefix('[')?;
    let name = inner.split(']').next()?;
    Some(name.trim())
}

/// The table as `identify` writes it at the end of a TOML tyre file.
pub(crate) fn table_text(r: &FittedRanges) -> String {
    let body = toml::to_string(&r.rounded_outward(RANGE_DIGITS)).unwrap_or_default();
    format!("\n# The ranges of the rig data fitted (SI units, rad): `tyre-eval` counts the points beyond them.\n[{TABLE}]\n{body}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    fn source(text: &str) -> TomlSource {
        TomlSource {
            path: PathBuf::from("t.toml"),
            text: text.into(),
        }
    }

    #[test]
    fn a_written_range_keeps_six_digits_and_still_holds_its_data() {
        assert_eq!(
            outward([-0.2085668456133224, 0.2085668456133224], 6),
            [-0.208567, 0.208567]
        );
        assert_eq!(outward([2500.0, 7000.0], 6), [2500.0, 7000.0]);
        assert_eq!(
            outward([405.29999999999995, 1234567.8], 6),
            [405.3, 1234570.0]
        );
        let r = FittedRanges {
            alpha: Some([-0.2085668456133224, 0.2085668456133224]),
            ..FittedRanges::default()
        };
        assert!(table_text(&r).contains("alpha = [-0.208567, 0.208567]"));
    }

    #[test]
    fn the_table_is_read_and_blanked_keeping_every_other_line_in_place() {
        let text = "model = \"gim\"\n[fitted_ranges]\nfz = [500.0, 3000.0]\nalpha = [-0.2, 0.2]\n[other]\nx = 1\n";
        let (tyre, r) = split(&source(text)).unwrap();
        let r = r.unwrap();
        assert_eq!(
            (r.fz, r.alpha, r.kappa),
            (Some([500.0, 3000.0]), Some([-0.2, 0.2]), None)
        );
        assert_eq!(tyre.text.len(), text.len());
        assert_eq!(tyre.text.lines().count(), text.lines().count());
        assert!(tyre.text.starts_with("model = \"gim\"\n"));
        assert!(tyre.text.ends_with("[other]\nx = 1\n"));
        assert!(!tyre.text.contains("fitted_ranges") && !tyre.text.contains("500"));
    }

    #[test]
    fn a_point_outside_any_range_is_counted_and_one_off_the_road_is_not() {
        let r = FittedRanges {
            fz: Some([500.0, 3000.0]),
            alpha: Some([-0.2, 0.2]),
            pressure: Some([80e3, 100e3]),
            ..Default::default()
        };
        let p = RangePoint {
            fz: 2000.0,
            alpha: 0.1,
            kappa: 0.5,
            camber: 0.1,
            pressure: None,
        };
        // kappa and camber have no range: not checked.
        assert!(!r.outside(&p, SLACK));
        // Past an end by at most 1 % of the span: within the data.
        assert!(!r.outside(&RangePoint { fz: 3025.0, ..p }, SLACK));
        assert!(r.outside(&RangePoint { fz: 3025.0, ..p }, 0.0));
        assert!(r.outside(&RangePoint { fz: 3026.0, ..p }, SLACK));
        assert!(!r.outside(&RangePoint { alpha: -0.204, ..p }, SLACK));
        assert!(r.outside(&RangePoint { alpha: -0.21, ..p }, SLACK));
        let left = r.left(&RangePoint {
            alpha: -0.21,
            pressure: Some(120e3),
            ..p
        });
        let keys: Vec<_> = left.iter().map(|l| (l.key, l.value, l.below)).collect();
        assert_eq!(keys, [("alpha", -0.21, true), ("pressure", 120e3, false)]);
        assert!(r.outside(
            &RangePoint {
                pressure: Some(120e3),
                ..p
            },
            SLACK
        ));
        assert!(!r.outside(&RangePoint { fz: 0.0, ..p }, 0.0));
        assert_eq!(
            r.text(),
            "fz 500.0 to 3000 N, alpha -0.2000 to 0.2000 rad, pressure 80000 to 100000 Pa"
        );
    }

    #[test]
    fn a_reversed_range_is_refused_at_its_key() {
        let text = "model = \"gim\"\n[fitted_ranges]\nfz = [3000.0, 500.0]\n";
        let e = split(&source(text)).unwrap_err().to_string();
        assert!(e.starts_with("t.toml:3:"), "{e}");
        assert!(
            e.contains("`fitted_ranges.fz[1]` = 500: must lie above the range's lower end, 3000"),
            "{e}"
        );
        let text = "model = \"gim\"\n[fitted_ranges]\nspeed = [1.0, 2.0]\n";
        assert!(split(&source(text)).is_err());
    }
}
