//! Where a fitted stage's error lies: in the outer tenth of the slip its
//! rows sweep, and from one load level to another. A stage's σ over all
//! its rows can be led by a few of them — on a continuous rig sweep the
//! aligning moment at the sweep's ends, where the slip turns back before
//! the moment has settled (the Hoosier file: 62 % of the pure `Mz` stage's
//! squared error in the outer tenth of |α|), and at the lowest load, where
//! the moment is a few N·m and the rig's noise is not smaller — which the
//! Magic Formula's steady-state terms do not model. The report says so
//! with the σ within the inner nine tenths, so a σ above the literature's
//! (Wei et al. 2010: 4.82 % on pure `Mz`) is read with what limits it.
//! Units: the slip as the stage's rows carry it (rad, or slip ratio).

use super::{MfRow, Stage};
use crate::tyre::mf::MagicFormula;
use serde::Serialize;

/// The outer band: rows with |slip| beyond this share of the largest.
const OUTER: f64 = 0.9;

/// The σ below which a stage's fit is at round-off and no line places its
/// error, %: a millionth of a percent, ten thousand times below a rig's
/// noise (0.01 % and more); a noise-free file's fit reads 1e-14 %.
pub const ROUND_OFF_PERCENT: f64 = 1e-6;

/// Loads within this of each other are one level, N.
const LOAD_GAP: f64 = 200.0;

/// σ of one load level of a stage's rows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoadSigma {
    /// The level's mean load, N.
    pub fz: f64,
    /// Rows at it.
    pub rows: usize,
    /// σ over them, %.
    pub sigma_percent: f64,
}

/// Where a stage's squared error lies.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ErrorSpread {
    /// The slip the stage's rows sweep: `alpha` or `kappa`.
    pub slip: &'static str,
    /// The outer band starts at this |slip| (rad, or slip ratio).
    pub outer_from: f64,
    /// Rows in the outer band.
    pub outer_rows: usize,
    /// Share of the stage's rows in it, %.
    pub outer_rows_percent: f64,
    /// Share of the stage's squared error in it, %.
    pub outer_error_percent: f64,
    /// σ over the rows within the band's edge, %.
    pub sigma_inner_percent: f64,
    /// σ per load level, in increasing load.
    pub by_load: Vec<LoadSigma>,
}

impl ErrorSpread {
    /// Whether the outer band holds at least twice its share of the rows
    /// of the squared error: the stage's σ is then led by the sweeps' ends.
    pub fn outer_leads(&self) -> bool {
        self.outer_error_percent >= 2.0 * self.outer_rows_percent
    }

    /// Whether every load level's σ is below [`ROUND_OFF_PERCENT`] (a
    /// stage without levels: its σ within the band's edge).
    pub fn at_round_off(&self) -> bool {
        let top = self
            .by_load
            .iter()
            .map(|l| l.sigma_percent)
            .fold(f64::NAN, f64::max);
        let top = if top.is_nan() {
            self.sigma_inner_percent
        } else {
            top
        };
        top < ROUND_OFF_PERCENT
    }

    /// One line on where the error lies, or `None` when it is spread
    /// evenly (neither the sweeps' ends nor a load level lead it).
    pub fn line(&self) -> Option<String> {
        self.line_naming(&|fz| crate::identify::grouping::Variable::Load.display(fz))
    }

    /// [`ErrorSpread::line`] with each load level spelt by `load` (the
    /// terminal's name of the level, `jobs/identify/level_names.rs`).
    pub fn line_naming(&self, load: &dyn Fn(f64) -> String) -> Option<String> {
        // A fit at round-off has no error to place: its shares and
        // ratios are of noise in the last digits.
        if self.at_round_off() {
            return None;
        }
        let by = |a: &&LoadSigma, b: &&LoadSigma| a.sigma_percent.total_cmp(&b.sigma_percent);
        let (lo, hi) = (
            self.by_load.iter().min_by(by),
            self.by_load.iter().max_by(by),
        );
        let loads = match (lo, hi) {
            (Some(lo), Some(hi)) if hi.sigma_percent >= 2.0 * lo.sigma_percent => Some(format!(
                "by load, σ {} % at {} to {} % at {}",
                // Two digits where one decimal shows none (a noise-free
                // fit's 0.012 %, not 0.0 %).
                crate::format::decimals_or_digits(lo.sigma_percent, 1, 2),
                load(lo.fz),
                crate::format::decimals_or_digits(hi.sigma_percent, 1, 2),
                load(hi.fz)
            )),
            _ => None,
        };
        let (symbol, edge) = match self.slip {
            "alpha" => ("α", format!("{:.1}°", self.outer_from.to_degrees())),
            _ => ("κ", format!("{:.1} %", 100.0 * self.outer_from)),
        };
        let outer = self.outer_leads().then(|| {
            format!(
                "{:.0} % of the squared error at |{symbol}| > {edge} (the outer tenth of the sweeps, {:.0} % of the rows); σ {:.2} % within |{symbol}| ≤ {edge}",
                self.outer_error_percent, self.outer_rows_percent, self.sigma_inner_percent
            )
        });
        match (outer, loads) {
            (None, None) => None,
            (Some(o), None) => Some(o),
            (None, Some(l)) => Some(l),
            (Some(o), Some(l)) => Some(format!("{o}; {l}")),
        }
    }
}

/// The slip stage `st`'s rows sweep: the slip angle for the pure lateral
/// force and aligning moment and the overturning moment, the slip ratio
/// for the others (the slip-ratio sweeps of a drive/brake test).
pub fn sweeps_slip_angle(st: Stage) -> bool {
    matches!(st, Stage::PureFy | Stage::PureMz | Stage::Mx)
}

/// Where the squared error of `tyre`'s stage `st` over `rows` lies.
pub(super) fn error_spread(st: Stage, tyre: &MagicFormula, rows: &[&MfRow]) -> ErrorSpread {
    let angle = sweeps_slip_angle(st);
    let slip = |r: &MfRow| if angle { r.alpha } else { r.kappa }.abs();
    let edge = OUTER * rows.iter().map(|r| slip(r)).fold(0.0, f64::max);
    let e2: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| {
            (
                (st.model(tyre, r) - st.measured(r)).powi(2),
                st.measured(r).powi(2),
            )
        })
        .collect();
    let (mut inner, mut total, mut outer_e2, mut outer_rows) = ((0.0, 0.0), 0.0, 0.0, 0);
    for (r, (e, y)) in rows.iter().zip(&e2) {
        total += e;
        if slip(r) > edge {
            outer_e2 += e;
            outer_rows += 1;
        } else {
            inner.0 += e;
            inner.1 += y;
        }
    }
    let mut loads: Vec<(f64, Vec<usize>)> = Vec::new();
    let mut order: Vec<usize> = (0..rows.len()).collect();
    order.sort_by(|&a, &b| rows[a].fz.total_cmp(&rows[b].fz));
    for i in order {
        match loads.last_mut() {
            Some((last, members)) if rows[i].fz - *last <= LOAD_GAP => {
                *last = rows[i].fz;
                members.push(i);
            }
            _ => loads.push((rows[i].fz, vec![i])),
        }
    }
    let by_load = loads
        .iter()
        .map(|(_, m)| {
            let (e, y) = m
                .iter()
                .fold((0.0, 0.0), |(a, b), &i| (a + e2[i].0, b + e2[i].1));
            LoadSigma {
                fz: m.iter().map(|&i| rows[i].fz).sum::<f64>() / m.len() as f64,
                rows: m.len(),
                sigma_percent: 100.0 * (e / y).sqrt(),
            }
        })
        .collect();
    let n = rows.len().max(1) as f64;
    ErrorSpread {
        slip: if angle { "alpha" } else { "kappa" },
        outer_from: edge,
        outer_rows,
        outer_rows_percent: 100.0 * outer_rows as f64 / n,
        outer_error_percent: 100.0 * outer_e2 / total.max(f64::MIN_POSITIVE),
        sigma_inner_percent: 100.0 * (inner.0 / inner.1).sqrt(),
        by_load,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spread(outer_error: f64, loads: &[(f64, f64)]) -> ErrorSpread {
        ErrorSpread {
            slip: "alpha",
            outer_from: 8.8f64.to_radians(),
            outer_rows: 436,
            outer_rows_percent: 12.3,
            outer_error_percent: outer_error,
            sigma_inner_percent: 6.34,
            by_load: loads
                .iter()
                .map(|&(fz, s)| LoadSigma {
                    fz,
                    rows: 700,
                    sigma_percent: s,
                })
                .collect(),
        }
    }

    #[test]
    fn the_line_names_what_leads_the_error_and_nothing_when_it_is_even() {
        let led = spread(61.9, &[(534.0, 32.0), (1656.0, 7.7), (2751.0, 4.2)]);
        assert_eq!(led.line().unwrap(), "62 % of the squared error at |α| > 8.8° (the outer tenth of the sweeps, 12 % of the rows); σ 6.34 % within |α| ≤ 8.8°; by load, σ 4.2 % at 2751 N to 32.0 % at 534 N");
        let even = spread(13.0, &[(2000.0, 1.5), (4000.0, 1.2)]);
        assert_eq!(even.line(), None);
    }

    /// Rows whose error is all at the sweeps' ends: the band holds all of
    /// it, and σ within is zero.
    #[test]
    fn an_error_at_the_sweeps_ends_is_found_there() {
        let t = crate::io::tir::read_tir_text(
            "MagicFormula61_Parameters.tir",
            include_str!("../../../tests/fixtures/tir/MagicFormula61_Parameters.tir"),
        )
        .unwrap();
        let rows: Vec<MfRow> = (-20..=20)
            .map(|i| {
                let mut r = MfRow {
                    fz: 4000.0,
                    kappa: 0.0,
                    alpha: (0.5 * f64::from(i)).to_radians(),
                    camber: 0.0,
                    speed: 16.7,
                    pressure: None,
                    fx: f64::NAN,
                    fy: 0.0,
                    mz: f64::NAN,
                    mx: f64::NAN,
                    my: f64::NAN,
                };
                r.fy = Stage::PureFy.model(&t, &r) + if i32::abs(i) >= 19 { 100.0 } else { 0.0 };
                r
            })
            .collect();
        let refs: Vec<&MfRow> = rows.iter().collect();
        let s = error_spread(Stage::PureFy, &t, &refs);
        assert_eq!((s.slip, s.outer_rows), ("alpha", 4));
        assert!((s.outer_error_percent - 100.0).abs() < 1e-9);
        assert!(s.sigma_inner_percent < 1e-9);
        assert!(s.outer_leads());
        assert_eq!(s.by_load.len(), 1);
    }
}
