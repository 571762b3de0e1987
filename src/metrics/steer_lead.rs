//! A yaw rate that moves before the steer does: a timing error between a
//! measured record's channels, not the car. A car's yaw rate answers its
//! steer (through the front tyres' force): it can lag the steer, never
//! precede it. Where the yaw rate leaves its initial band before the
//! steer leaves its own, the steer was logged late against it (a logger
//! delay between channels): a sedan history whose steer column was
//! shifted 80 ms later read a response time of 0.1076 s for 0.1876 s and
//! Er 0.0595 s for 0.1251 s without a word, its yaw rate at 21 % of its
//! step while the steer still read its initial value exactly.
//!
//! Each channel's band is its pre-step noise: [`LEAD_NOISES`] noise
//! deviations of the raw (unfiltered: a zero-phase low-pass spreads a
//! sharp steer ahead of itself more than a gradual yaw rate), normalised
//! channel (as the lead of a 90 %
//! crossing is judged beyond 3 of its noise spreads in
//! `applicability.rs`), at least [`BAND_FLOOR`] of the step (a noise-free
//! record's band). The time a channel leaves it is the band's last
//! crossing before the channel rises through (the steer's 50 %, the yaw
//! rate's 90 % crossing), interpolated: noise that dips back into the band
//! only makes a response leave later, so noise alone reads no lead. The
//! lead is said where it exceeds two sample intervals (a crossing is
//! placed within one) and both bands lie within [`WIDEST_BAND`] of the
//! step (wider, the noise hides when either moved). Units: s; bands as
//! shares of each channel's step.

/// Noise deviations of its channel a band spans either side.
pub(super) const LEAD_NOISES: f64 = 3.0;

/// The narrowest band, a share of the step: a noise-free record's values
/// written to a few digits, and a filter's far tails, stay within it.
const BAND_FLOOR: f64 = 1e-3;

/// The widest band the lead is judged with, a share of the step: beyond
/// it the noise hides the first quarter of a channel's rise.
const WIDEST_BAND: f64 = 0.25;

/// The time (s) the normalised channel `v` (sampled at `t`) leaves its
/// band `band` for the last time before sample `until`: the band's
/// crossing between the last sample within it and the next, interpolated.
fn leaves(t: &[f64], v: &[f64], band: f64, until: usize) -> Option<f64> {
    let inside = (0..until.min(v.len()))
        .rev()
        .find(|&i| v[i].abs() <= band)?;
    let next = inside + 1;
    if next >= v.len() {
        return None;
    }
    let (a, b) = (v[inside], v[next]);
    let edge = band.copysign(b - a);
    let w = match b != a {
        true => ((edge - a) / (b - a)).clamp(0.0, 1.0),
        false => 0.0,
    };
    Some(t[inside] + w * (t[next] - t[inside]))
}

/// The first sample index at or after time `at`.
fn index_at(t: &[f64], at: f64) -> usize {
    t.iter().position(|&x| x >= at).unwrap_or(t.len())
}

/// How long (s) before the steer leaves its initial band the yaw rate
/// leaves its own: `steer` and `yaw_rate` normalised and filtered, with
/// their noise deviations (normalised, after the filter) `noises`, the
/// steer's 50 % crossing `t0` and the yaw rate's 90 % crossing `tr`.
/// None where the yaw rate leaves after the steer, within two sample
/// intervals `dt` of it, or where a band is too wide to tell.
pub(super) fn yaw_rate_leads(
    t: &[f64],
    (steer, yaw_rate): (&[f64], &[f64]),
    noises: (f64, f64),
    (t0, tr): (f64, f64),
    dt: f64,
) -> Option<f64> {
    let band = |noise: f64| (LEAD_NOISES * noise).max(BAND_FLOOR);
    let (band_d, band_r) = (band(noises.0), band(noises.1));
    if !(band_d <= WIDEST_BAND && band_r <= WIDEST_BAND) {
        return None;
    }
    let steer_leaves = leaves(t, steer, band_d, index_at(t, t0))?;
    let yaw_leaves = leaves(t, yaw_rate, band_r, index_at(t, tr))?;
    let lead = steer_leaves - yaw_leaves;
    (lead > 2.0 * dt).then_some(lead)
}

/// The warning of a yaw rate that leads the steer by `lead` (s).
pub(crate) fn said(lead: f64) -> String {
    let by = crate::format::readable(lead, 3);
    format!(
        "the yaw rate leaves its initial band ({LEAD_NOISES:.0} noise deviations, at least {} % of its step) {by} s before the steer leaves its own: a car's yaw rate answers its steer and never moves first, so the steer is logged late against it (a delay between the logger's channels), by that much or more (each band hides the start of its channel's move); the response times and the total variances (E_r, E_ay, Er), marked \"(steer misaligned)\", are read against the misaligned steer and are short by as much: shift the steer column earlier by the delay (about {by} s or more) and measure again, or let `diagnose` fit it (its `sensor_delay` effect)",
        100.0 * BAND_FLOOR
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit ramp from `from` over 0.08 s, and a response rising as
    /// `(t − start)²` scaled to reach 1 at `start + 0.2`, at 1 kHz.
    fn record(from: f64, start: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let t: Vec<f64> = (0..3000).map(|i| i as f64 * 0.001).collect();
        let steer = t.iter().map(|&x| ((x - from) / 0.08).clamp(0.0, 1.0));
        let r = t
            .iter()
            .map(|&x| (((x - start) / 0.2).clamp(0.0, 1.0)).powi(2));
        (t.clone(), steer.collect(), r.collect())
    }

    /// A yaw rate starting 80 ms before the steer reads a lead of 80 ms
    /// less the time its t² start takes to leave a 0.1 % band (0.2 s ·
    /// √0.001 = 6.3 ms); one starting 5 ms after the steer reads none.
    #[test]
    fn a_yaw_rate_moving_first_reads_its_lead_and_one_after_the_steer_none() {
        let (t, d, r) = record(1.08, 1.0);
        let t0 = 1.08 + 0.04;
        let tr = 1.0 + 0.2 * 0.9f64.sqrt();
        let lead = yaw_rate_leads(&t, (&d, &r), (0.0, 0.0), (t0, tr), 0.001).unwrap();
        let expected = 0.08 - 0.2 * 0.001f64.sqrt();
        assert!(
            (lead - expected).abs() < 0.0015,
            "{lead} against {expected}"
        );
        let (t, d, r) = record(1.0, 1.005);
        let tr = 1.005 + 0.2 * 0.9f64.sqrt();
        assert_eq!(
            yaw_rate_leads(&t, (&d, &r), (0.0, 0.0), (1.04, tr), 0.001),
            None
        );
    }

    /// A band wider than a quarter of the step is no judge: the lead is
    /// not read; a band of 3 noises of 5 % is still one.
    #[test]
    fn a_band_too_wide_reads_no_lead() {
        let (t, d, r) = record(1.08, 1.0);
        let tr = 1.0 + 0.2 * 0.9f64.sqrt();
        assert_eq!(
            yaw_rate_leads(&t, (&d, &r), (0.0, 0.09), (1.12, tr), 0.001),
            None
        );
        assert!(yaw_rate_leads(&t, (&d, &r), (0.0, 0.05), (1.12, tr), 0.001).is_some());
    }
}
