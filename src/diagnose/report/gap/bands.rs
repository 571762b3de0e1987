//! The yaw-rate response's gain and phase error by frequency band, for a
//! run whose steer oscillates: `H = Σ Y·U*/Σ|U|²` over the DFT bins of a
//! band, measured against simulated, said only where the steer drives a
//! response above the noise ([`BAND_SNR`]; Bendat & Piersol 2010, ch. 9).
//! Units: Hz, 1/s, dB, degrees.

use super::mean;
use crate::manoeuvre::interpolate;
use serde::Serialize;

/// The yaw-rate response's gain and phase error in one frequency band.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BandGap {
    /// Lower edge, Hz.
    pub f_low: f64,
    /// Upper edge, Hz.
    pub f_high: f64,
    /// Measured yaw-rate gain |r/δ|, 1/s.
    pub gain_measured: f64,
    /// Simulated gain, 1/s.
    pub gain_simulated: f64,
    /// 20·log10(simulated/measured), dB.
    pub gain_error_db: f64,
    /// Phase of simulated relative to measured, degrees (negative: the
    /// model lags).
    pub phase_error_deg: f64,
}

/// Frequency bands of the sweep analysis, Hz.
const BANDS: [(f64, f64); 5] = [(0.1, 0.3), (0.3, 0.6), (0.6, 1.2), (1.2, 2.4), (2.4, 4.0)];

/// The least yaw-rate response the steer must drive in a band, in units of
/// the measured channel's noise in one DFT bin (`n·σ²`, σ its noise floor),
/// for the band's gain and phase to be said. The band's gain estimate
/// `Σ Y·U*/Σ|U|²` carries the noise as a complex error of relative size
/// `1/√S` at that ratio `S` (Bendat & Piersol 2010, ch. 9): at 300 the
/// gain's standard error is 4 % (0.35 dB) and the phase's 2.3°, so the
/// 1 dB and 10° a finding needs are three standard errors and more. A steer
/// at the noise level (round 29: white noise of 0.0002 rad on a straight)
/// drives less than one bin's noise and read "off by −7 dB, +100°".
pub const BAND_SNR: f64 = 300.0;

/// A run's band analysis: the bands said, and those left unsaid because the
/// steer drives no response above the noise there ([`BAND_SNR`]).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Bands {
    /// Bands with steer content and a response above the noise.
    pub found: Vec<BandGap>,
    /// Bands holding the steer's power share but no response above the
    /// noise: no statement is made of them.
    pub without_steer: usize,
}

/// Gain and phase errors of the yaw-rate response per frequency band, for a
/// run whose steer oscillates (at least six sign changes about its mean: a
/// sweep or a sine; a step has no band content worth splitting). Both
/// responses are estimated as `H = Σ Y·U*/Σ |U|²` over the DFT bins of the
/// band (the run resampled to its median interval, means removed); a band is
/// reported when it holds at least 5 % of the steer's power in 0.1–4 Hz.
/// No noise floor: every such band ([`band_gaps_above`] gates them).
#[cfg(test)]
pub fn band_gaps(t: &[f64], steer: &[f64], measured: &[f64], simulated: &[f64]) -> Vec<BandGap> {
    band_gaps_above(t, steer, measured, simulated, 0.0).found
}

/// [`band_gaps`], a band said only where the response the steer drives in
/// it (the larger of the measured and the simulated yaw rate's part
/// coherent with the steer, `|Σ Y·U*|²/Σ|U|²`) exceeds [`BAND_SNR`] times
/// the measured yaw rate's noise in one bin, `n·σ²` with σ `noise_floor`
/// (rad/s); the others are counted.
pub fn band_gaps_above(
    t: &[f64],
    steer: &[f64],
    measured: &[f64],
    simulated: &[f64],
    noise_floor: f64,
) -> Bands {
    let Some((bins, n)) = spectra(t, steer, measured, simulated) else {
        return Bands::default();
    };
    let power: f64 = bins.iter().map(|b| b.1 .0 * b.1 .0 + b.1 .1 * b.1 .1).sum();
    let mut out = Bands::default();
    for (lo, hi) in BANDS {
        let (uu, (mr, mi), (sr, si)) = cross_spectra(&bins, lo, hi);
        if power <= 0.0 || uu < 0.05 * power {
            continue;
        }
        let coherent = (mr * mr + mi * mi).max(sr * sr + si * si) / uu;
        if coherent <= BAND_SNR * n as f64 * noise_floor * noise_floor {
            out.without_steer += 1;
            continue;
        }
        let (gm, gs) = (mr.hypot(mi) / uu, sr.hypot(si) / uu);
        let phase = (si.atan2(sr) - mi.atan2(mr)).to_degrees();
        let phase = (phase + 540.0).rem_euclid(360.0) - 180.0;
        out.found.push(BandGap {
            f_low: lo,
            f_high: hi,
            gain_measured: gm,
            gain_simulated: gs,
            gain_error_db: 20.0 * (gs / gm).log10(),
            phase_error_deg: phase,
        });
    }
    out
}

/// (frequency, DFT of steer, of measured, of simulated) per bin.
type Bin = (f64, (f64, f64), (f64, f64), (f64, f64));

/// The DFT bins of 0.1–4 Hz (below 0.8 of the Nyquist frequency) of the
/// steer and both yaw rates, resampled to the median interval, means
/// removed, with the resampled count; None for a run under 32 samples or
/// whose steer crosses its mean fewer than six times (no band content).
fn spectra(
    t: &[f64],
    steer: &[f64],
    measured: &[f64],
    simulated: &[f64],
) -> Option<(Vec<Bin>, usize)> {
    let n0 = t.len();
    if n0 < 32 {
        return None;
    }
    let m0 = mean(steer);
    let crossings = steer
        .windows(2)
        .filter(|w| (w[0] - m0).signum() != (w[1] - m0).signum())
        .count();
    if crossings < 6 {
        return None;
    }
    let mut dts: Vec<f64> = t.windows(2).map(|w| w[1] - w[0]).collect();
    dts.sort_by(f64::total_cmp);
    let dt = dts[dts.len() / 2];
    let n = ((t[n0 - 1] - t[0]) / dt).floor() as usize + 1;
    let grid = |y: &[f64]| -> Vec<f64> {
        let v: Vec<f64> = (0..n)
            .map(|i| interpolate(t, y, t[0] + i as f64 * dt))
            .collect();
        let m = mean(&v);
        v.into_iter().map(|x| x - m).collect()
    };
    let (u, ym, ys) = (grid(steer), grid(measured), grid(simulated));
    let span = n as f64 * dt;
    let dft = |x: &[f64], f: f64| -> (f64, f64) {
        let w = std::f64::consts::TAU * f * dt;
        x.iter().enumerate().fold((0.0, 0.0), |(re, im), (i, v)| {
            let (s, c) = (w * i as f64).sin_cos();
            (re + v * c, im - v * s)
        })
    };
    let nyquist = 0.5 / dt;
    let bins = (1..)
        .map(|k| k as f64 / span)
        .take_while(|f| *f <= 4.0_f64.min(0.8 * nyquist))
        .filter(|f| *f >= 0.1)
        .map(|f| (f, dft(&u, f), dft(&ym, f), dft(&ys, f)))
        .collect();
    Some((bins, n))
}

/// Over the bins in `[lo, hi)`: the steer's power `Σ|U|²` and the measured
/// and simulated cross spectra `Σ Y·U*` (real, imaginary).
fn cross_spectra(bins: &[Bin], lo: f64, hi: f64) -> (f64, (f64, f64), (f64, f64)) {
    let (mut uu, mut mr, mut mi, mut sr, mut si) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for (f, (ur, ui), (yr, yi), (zr, zi)) in bins {
        if *f >= lo && *f < hi {
            uu += ur * ur + ui * ui;
            // Y·U*
            mr += yr * ur + yi * ui;
            mi += yi * ur - yr * ui;
            sr += zr * ur + zi * ui;
            si += zi * ur - zr * ui;
        }
    }
    (uu, (mr, mi), (sr, si))
}
