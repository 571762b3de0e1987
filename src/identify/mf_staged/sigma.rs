//! The fit's one overall figure: σ pooled over every raw sample of the rig
//! file and every measured channel, `σ = sqrt(Σe²/ΣF²)·100 %` with the sums
//! over all channels together (Zhang & Li (2017)'s definition, as the
//! stages use per channel), beside each channel's own σ and RMS. Raw
//! samples, not the thinned rows the stages fit: the figure does not depend
//! on the binning. A channel no stage fitted (an `mx` column whose stage
//! was skipped) is listed as not fitted, with no σ, and left out of the
//! pooled sums. A fitted channel's σ is over the samples its fitted
//! stages take ([`Stage::takes`]): a sample under longitudinal slip is a
//! combined stage's, and with that stage skipped its `mz` is no fit's
//! (exact MF 6.1 pure sweeps fitted back gave `mz` σ 92.2 % over them,
//! 0.089 % over the pure lateral rows fitted); such samples are counted
//! and named as left out ([`LeftOut`]). A channel measured 0 throughout has no relative error,
//! said in words. Units: N and N·m as measured (the pooled sum is then led
//! by the forces, as the published figures it is compared with).

use super::{MfRow, Stage};
use crate::identify::data::RigData;
use crate::tyre::mf::MagicFormula;
use serde::Serialize;

/// σ and RMS of one channel over the raw samples that measured it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChannelSigma {
    /// `fx`, `fy`, `mz`, `mx` or `my`.
    pub channel: &'static str,
    /// Samples with the channel measured.
    pub samples: usize,
    /// Whether a stage fitted it (else it has no σ and is not pooled).
    pub fitted: bool,
    /// `sqrt(Σe²/ΣF²)·100 %` (None: not fitted, or measured 0 throughout,
    /// where no error is relative to anything).
    pub sigma_percent: Option<f64>,
    /// RMS error, N or N·m.
    pub rms: f64,
    /// The samples measuring the channel that no fitted stage of it takes
    /// (not in its σ nor in the pool); `None` when there are none or the
    /// channel was not fitted.
    pub left_out: Option<LeftOut>,
}

/// Samples of a fitted channel that no fitted stage of it takes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LeftOut {
    /// How many.
    pub samples: usize,
    /// The stages of the channel, not fitted, that would take them
    /// (`combined Mz`); empty when none would.
    pub stages: Vec<&'static str>,
    /// The samples by their slip content (a combined stage takes the pure
    /// longitudinal rows too: they are named as what they are).
    pub slips: Vec<(RowSlip, usize)>,
}

/// A row's slip content, within [`super::PURE_TOL`] of zero.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RowSlip {
    /// α ≠ 0, κ = 0.
    PureLateral,
    /// α = 0, κ ≠ 0.
    PureLongitudinal,
    /// α ≠ 0 and κ ≠ 0.
    Combined,
    /// α = 0 and κ = 0.
    Zero,
}

impl RowSlip {
    /// The slip content of row `r`.
    fn of(r: &MfRow) -> RowSlip {
        let a = r.alpha.abs() > super::PURE_TOL;
        let k = r.kappa.abs() > super::PURE_TOL;
        match (a, k) {
            (true, false) => RowSlip::PureLateral,
            (false, true) => RowSlip::PureLongitudinal,
            (true, true) => RowSlip::Combined,
            (false, false) => RowSlip::Zero,
        }
    }

    /// A name people read.
    fn label(self) -> &'static str {
        match self {
            RowSlip::PureLateral => "pure lateral slip (κ = 0)",
            RowSlip::PureLongitudinal => "pure longitudinal slip (α = 0)",
            RowSlip::Combined => "combined slip (α and κ ≠ 0)",
            RowSlip::Zero => "zero slip",
        }
    }
}

impl LeftOut {
    /// `, 120 samples left out (rows of pure longitudinal slip (α = 0),
    /// the combined Mz stage's, not fitted)`.
    fn text(&self) -> String {
        let rows = match &self.slips[..] {
            [(slip, _)] => format!("rows of {}", slip.label()),
            slips => {
                let each: Vec<String> = slips
                    .iter()
                    .map(|(slip, n)| format!("{n} of {}", slip.label()))
                    .collect();
                format!("rows: {}", each.join(", "))
            }
        };
        let whose = if self.stages.is_empty() {
            format!("{rows}, which no stage of the channel takes")
        } else {
            format!(
                "{rows}, the {} stage's, not fitted",
                self.stages.join(" and ")
            )
        };
        format!(
            ", {} left out ({whose})",
            crate::format::plural(self.samples, "sample", "samples")
        )
    }
}

/// The pooled σ over every raw sample and measured channel.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PooledSigma {
    /// Raw samples in the file.
    pub samples: usize,
    /// `sqrt(Σ_channels Σe² / Σ_channels ΣF²)·100 %` over the fitted
    /// channels (NaN when they measured 0 throughout).
    pub sigma_percent: f64,
    /// Each measured channel's own σ, the ones not fitted included.
    pub channels: Vec<ChannelSigma>,
}

impl PooledSigma {
    /// One line: the pooled figure and the channels it pools; a channel
    /// not fitted, or measured 0 throughout, said so in words.
    pub fn line(&self) -> String {
        let parts: Vec<String> = self.channels.iter().map(ChannelSigma::part).collect();
        let pooled = if self.sigma_percent.is_finite() {
            format!("{:.3} %", self.sigma_percent)
        } else {
            "no relative error (the fitted channels measured 0 throughout)".into()
        };
        // Samples some channel's fitted stages do not take are named at
        // that channel: the pool is not over all of them then.
        let over = if self.channels.iter().any(|c| c.left_out.is_some()) {
            format!(
                "the {} raw samples' rows the fitted stages take",
                self.samples
            )
        } else {
            format!("all {} raw samples", self.samples)
        };
        format!("σ pooled over {over}: {pooled} ({})", parts.join("; "))
    }
}

impl ChannelSigma {
    /// The channel's part of [`PooledSigma::line`].
    fn part(&self) -> String {
        let rms = rms_text(self.rms, channel_unit(self.channel));
        let left = self.left_out.as_ref().map_or(String::new(), LeftOut::text);
        match (self.fitted, self.sigma_percent) {
            (true, None) if self.samples == 0 => format!(
                "{} not in the pool: every sample of it left out{left}",
                self.channel
            ),
            (false, _) => format!(
                "{} not fitted (its stage was skipped): no σ, left out of the pool",
                self.channel
            ),
            (true, Some(s)) => format!("{} {s:.3} %, RMS error {rms}{left}", self.channel),
            (true, None) => format!(
                "{} measured 0 throughout: no relative error, RMS error {rms}{left}",
                self.channel
            ),
        }
    }
}

/// The unit of a channel: N for the forces, N·m for the moments.
pub fn channel_unit(channel: &str) -> &'static str {
    if channel.starts_with('f') {
        "N"
    } else {
        "N·m"
    }
}

/// An RMS error as read on the terminal: two decimals, or two significant
/// digits below 0.1 (a fit to noise-free data leaves 1e-11 N, which two
/// decimals would show as a suspicious 0.00).
pub fn rms_text(rms: f64, unit: &str) -> String {
    format!("{} {unit}", crate::format::decimals_or_digits(rms, 2, 2))
}

/// Every sample of the rig file as a row (no thinning), with the wheel
/// moments `moments` (`mx`, `my`) when measured.
pub fn raw_rows(d: &RigData, moments: &[Option<Vec<f64>>; 2], default_speed: f64) -> Vec<MfRow> {
    let opt = |v: &Option<Vec<f64>>, i: usize| v.as_ref().map_or(f64::NAN, |m| m[i]);
    (0..d.len())
        .map(|i| MfRow {
            fz: d.fz[i],
            kappa: d.longitudinal.as_ref().map_or(0.0, |(k, _)| k[i]),
            alpha: d.alpha[i],
            camber: d.camber[i],
            speed: d.speed.as_ref().map_or(default_speed, |s| s[i]),
            pressure: d.pressure.as_ref().map(|p| p[i]),
            fx: d.longitudinal.as_ref().map_or(f64::NAN, |(_, f)| f[i]),
            fy: d.fy[i],
            mz: opt(&d.mz, i),
            mx: opt(&moments[0], i),
            my: opt(&moments[1], i),
        })
        .collect()
}

/// The index in [`pooled_sigma`]'s channels of the channel `stage` fits.
fn channel_of(stage: Stage) -> usize {
    match stage {
        Stage::PureFx | Stage::CombinedFx => 0,
        Stage::PureFy | Stage::CombinedFy => 1,
        Stage::PureMz | Stage::CombinedMz => 2,
        Stage::Mx => 3,
        Stage::My => 4,
    }
}

/// The pooled σ of `tyre` over `rows` (each channel where measured), the
/// sums over the channels the stages `fitted` fit, each over the rows its
/// fitted stages take (the others counted as left out).
pub fn pooled_sigma(tyre: &MagicFormula, rows: &[MfRow], fitted: &[Stage]) -> PooledSigma {
    const NAMES: [&str; 5] = ["fx", "fy", "mz", "mx", "my"];
    let (mut e2, mut y2, mut n) = ([0.0f64; 5], [0.0f64; 5], [0usize; 5]);
    let mut left = [0usize; 5];
    let is_fitted = |k: usize| fitted.iter().any(|&s| channel_of(s) == k);
    // The stages of each channel not fitted that take a row left out.
    let mut whose: [Vec<&'static str>; 5] = Default::default();
    let mut slips: [Vec<(RowSlip, usize)>; 5] = Default::default();
    for r in rows {
        let o = tyre.evaluate(&r.input());
        let pairs = [
            (o.fx, r.fx),
            (o.fy, r.fy),
            (o.mz, r.mz),
            (o.mx, r.mx),
            (o.my, r.my),
        ];
        for (k, (model, measured)) in pairs.into_iter().enumerate() {
            if !measured.is_finite() {
                continue;
            }
            let taken = fitted.iter().any(|&s| channel_of(s) == k && s.takes(r));
            if is_fitted(k) && !taken {
                left[k] += 1;
                let slip = RowSlip::of(r);
                match slips[k].iter_mut().find(|(s, _)| *s == slip) {
                    Some((_, n)) => *n += 1,
                    None => slips[k].push((slip, 1)),
                }
                let takers = Stage::ALL
                    .into_iter()
                    .filter(|&s| channel_of(s) == k && !fitted.contains(&s) && s.takes(r));
                for s in takers {
                    if !whose[k].contains(&s.label()) {
                        whose[k].push(s.label());
                    }
                }
                continue;
            }
            let e = model - measured;
            e2[k] += e * e;
            y2[k] += measured * measured;
            n[k] += 1;
        }
    }
    let channels: Vec<ChannelSigma> = (0..5)
        .filter(|&k| n[k] + left[k] > 0)
        .map(|k| ChannelSigma {
            channel: NAMES[k],
            samples: n[k],
            fitted: is_fitted(k),
            sigma_percent: Some(100.0 * (e2[k] / y2[k]).sqrt())
                .filter(|s| is_fitted(k) && s.is_finite()),
            rms: if n[k] > 0 {
                (e2[k] / n[k] as f64).sqrt()
            } else {
                f64::NAN
            },
            left_out: (left[k] > 0).then(|| LeftOut {
                samples: left[k],
                stages: whose[k].clone(),
                slips: slips[k].clone(),
            }),
        })
        .collect();
    let pooled = |v: &[f64; 5]| (0..5).filter(|&k| is_fitted(k)).map(|k| v[k]).sum::<f64>();
    PooledSigma {
        samples: rows.len(),
        sigma_percent: 100.0 * (pooled(&e2) / pooled(&y2)).sqrt(),
        channels,
    }
}

/// The largest difference of `fx`, `fy`, `mz` between `tyre` and `back`
/// (the tyre read back from its written `.tir`) over `rows`, relative to the
/// largest magnitude of each channel (0 when the file reproduces the tyre).
pub fn round_trip_difference(tyre: &MagicFormula, back: &MagicFormula, rows: &[MfRow]) -> f64 {
    let mut worst: f64 = 0.0;
    let mut scale = [1e-9f64; 3];
    let mut diff = [0.0f64; 3];
    for r in rows {
        let (a, b) = (tyre.evaluate(&r.input()), back.evaluate(&r.input()));
        for (k, (x, y)) in [(a.fx, b.fx), (a.fy, b.fy), (a.mz, b.mz)]
            .iter()
            .enumerate()
        {
            scale[k] = scale[k].max(x.abs());
            diff[k] = diff[k].max((x - y).abs());
        }
    }
    for k in 0..3 {
        worst = worst.max(diff[k] / scale[k]);
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tyre::mf::{MfCoefficients, MfOptions, MfVersion, TyreSide};

    /// Two channels: the pooled σ is the square root of the summed squared
    /// errors over the summed squares, not the mean of the channels' σ.
    #[test]
    fn pooled_sigma_sums_errors_and_squares_over_channels() {
        let mut c = MfCoefficients::default();
        for (k, v) in [("PCY1", 1.3), ("PDY1", 1.0), ("PKY1", -15.0), ("PKY2", 1.7)] {
            c.set(k, v);
        }
        let t = MagicFormula {
            version: MfVersion::Mf61,
            side: TyreSide::Left,
            options: MfOptions::default(),
            limits: Default::default(),
            coefficients: c,
        };
        let row = |alpha: f64, dfy: f64, mz: f64| {
            let mut r = MfRow {
                fz: 4000.0,
                kappa: 0.0,
                alpha,
                camber: 0.0,
                speed: 16.7,
                pressure: None,
                fx: f64::NAN,
                fy: 0.0,
                mz,
                mx: f64::NAN,
                my: f64::NAN,
            };
            r.fy = t.evaluate(&r.input()).fy + dfy;
            r
        };
        // fy off by 30 N at one of two rows; mz model 0 vs measured 3 and 4.
        let rows = [row(0.05, 30.0, 3.0), row(0.1, 0.0, 4.0)];
        let s = pooled_sigma(&t, &rows, &[Stage::PureFy, Stage::PureMz]);
        let fy2: f64 = rows.iter().map(|r| r.fy * r.fy).sum();
        let want = 100.0 * ((900.0 + 25.0) / (fy2 + 25.0)).sqrt();
        assert!(
            (s.sigma_percent - want).abs() < 1e-9,
            "{} {want}",
            s.sigma_percent
        );
        assert_eq!(s.channels.len(), 2);
        assert!((s.channels[1].sigma_percent.unwrap() - 100.0).abs() < 1e-9);
        assert!((s.channels[0].rms - (900.0f64 / 2.0).sqrt()).abs() < 1e-9);
        let line = s.line();
        assert!(line.contains("%, RMS error 21.21 N; "), "{line}");
        assert!(line.contains("mz 100.000 %, RMS error 3.54 N·m"), "{line}");
    }

    /// An `mx` measured but not fitted (its stage skipped) gets no σ and
    /// is not pooled; an `fx` measured 0 throughout has no relative error,
    /// said in words, never `NaN %`.
    #[test]
    fn a_channel_not_fitted_gets_no_sigma_and_an_all_zero_one_no_nan() {
        let t = MagicFormula {
            version: MfVersion::Mf61,
            side: TyreSide::Left,
            options: MfOptions::default(),
            limits: Default::default(),
            coefficients: MfCoefficients::default(),
        };
        // Slip angles within the pure tolerance: the pure Fx stage takes
        // the rows' `fx` (it takes no row at a slip angle).
        let rows: Vec<MfRow> = [0.0002, 0.0005, 0.0009]
            .iter()
            .map(|&alpha| MfRow {
                fz: 4000.0,
                kappa: 0.0,
                alpha,
                camber: 0.0,
                speed: 16.7,
                pressure: None,
                fx: 0.0,
                fy: 3000.0 * alpha,
                mz: 10.0,
                mx: 40.0,
                my: f64::NAN,
            })
            .collect();
        let fitted = [Stage::PureFx, Stage::PureFy, Stage::PureMz];
        let s = pooled_sigma(&t, &rows, &fitted);
        let only = pooled_sigma(&t, &rows, &fitted[1..]);
        let mx = s.channels.iter().find(|c| c.channel == "mx").unwrap();
        assert!(!mx.fitted && mx.sigma_percent.is_none(), "{mx:?}");
        let fx = s.channels.iter().find(|c| c.channel == "fx").unwrap();
        assert!(fx.fitted && fx.sigma_percent.is_none(), "{fx:?}");
        // mx left out of the pool: the pool is fy's and mz's alone (fx
        // adds no square).
        let (fy, mz) = (&s.channels[1], &s.channels[2]);
        let e2 = |c: &ChannelSigma| c.rms * c.rms * c.samples as f64;
        let y2: f64 = rows.iter().map(|r| r.fy * r.fy + r.mz * r.mz).sum();
        let want = 100.0 * ((e2(fy) + e2(mz) + e2(fx)) / y2).sqrt();
        assert!((s.sigma_percent - want).abs() < 1e-9 * want, "{s:?}");
        let line = s.line();
        assert!(!line.contains("NaN") && !line.contains("mx 100"), "{line}");
        assert!(
            line.contains("mx not fitted (its stage was skipped): no σ, left out of the pool"),
            "{line}"
        );
        assert!(
            line.contains("fx measured 0 throughout: no relative error, RMS error"),
            "{line}"
        );
        assert!(only.line().contains("fx not fitted"), "{}", only.line());
    }

    #[test]
    fn a_tiny_rms_error_is_shown_in_scientific_notation_with_its_unit() {
        assert_eq!(rms_text(7.925e-12, "N"), "7.9e-12 N");
        assert_eq!(rms_text(0.0, "N·m"), "0.00 N·m");
        assert_eq!(rms_text(41.254, channel_unit("fy")), "41.25 N");
        assert_eq!(rms_text(0.0102, channel_unit("mz")), "0.010 N·m");
    }
}
