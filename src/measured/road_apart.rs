//! A run's estimated road bank that the campaign's other runs do not show
//! ([`BankApart`], set over the campaign by `RoadGeometry::set_apart`), and
//! its words: on one run's kinematics (ISO 8855, `a_y − u·r = g·sin θ` on
//! flat-road 2-DOF terms) a steady bank θ, an `ay` offset `g·sin θ` and a
//! yaw-rate offset `−g·sin θ/u` read alike; over a run whose speed varies a
//! yaw-rate offset's apparent bank grows with the speed ([`BySpeed`]).
//! Round 39: +0.02 rad/s in one run's yaw rate on the synth's flat ground
//! was said as a bank of −2.0°. Units: rad, m/s², rad/s, m/s.

use serde::Serialize;

/// The estimated bank over a run's slower and faster halves (split at its
/// median speed), their median speeds (m/s) and banks (rad).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BySpeed {
    /// Median speed of the slower half, m/s.
    pub slow_speed: f64,
    /// Median estimated bank there, rad.
    pub slow_bank: f64,
    /// Median speed of the faster half, m/s.
    pub fast_speed: f64,
    /// Median estimated bank there, rad.
    pub fast_bank: f64,
}

impl BySpeed {
    /// Which the halves read as: a bank that scales with the speed (a
    /// yaw-rate offset's `−u·b_r/g`) or one that does not (a bank, an
    /// `ay` offset), by the nearer of the two in the log of the ratio.
    pub fn scales_with_speed(&self) -> bool {
        let banks = (self.fast_bank / self.slow_bank).abs().ln();
        let speeds = (self.fast_speed / self.slow_speed).ln();
        self.fast_bank * self.slow_bank > 0.0 && (banks - speeds).abs() < banks.abs()
    }
}

/// A run's estimated bank that the campaign's other runs do not show: on
/// one run's kinematics a steady bank θ, an `ay` offset `g·sin θ` and a
/// yaw-rate offset `−g·sin θ/u` read alike (`a_y − u·r = g·sin θ`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BankApart {
    /// The run's median estimated bank, rad.
    pub bank: f64,
    /// The median of the other runs' medians, rad.
    pub others: f64,
    /// The other runs.
    pub other_runs: usize,
    /// The `ay` offset that reads as it, m/s²: `g·sin(bank − others)`.
    pub ay_offset: f64,
    /// The yaw-rate offset that reads as it at the run's median speed,
    /// rad/s: `−ay_offset/u`.
    pub yaw_rate_offset: f64,
}

/// A bank estimate no other run shows ([`BankApart`]), in words: the three
/// things one run's `ay − u·r` reads alike, and what would tell them
/// apart, from the run's speeds (`by_speed`) where they vary. `speed`:
/// the run's median, m/s.
pub(crate) fn apart(a: &BankApart, speed: f64, by_speed: Option<BySpeed>) -> String {
    let deg = |x: f64| crate::format::fixed(x.to_degrees(), 1);
    let alike = format!(
        "; a steady {}° that the other {} runs do not show (their median {}°): a bank of {}°, an ay offset of {} m/s² or a yaw-rate offset of {} rad/s at its {} m/s read alike in one run's ay − u·r",
        deg(a.bank),
        a.other_runs,
        deg(a.others),
        deg(a.bank - a.others),
        crate::format::signed(a.ay_offset, 3),
        crate::format::signed(a.yaw_rate_offset, 4),
        crate::format::fixed(speed, 1)
    );
    let tell = match by_speed {
        None => "; at one speed the run cannot tell them apart: a yaw-rate offset's bank grows with the speed, a bank's and an ay offset's do not (the same ground at another speed tells it), and a standstill in the run shows a sensor's offset (the calibration's)".to_string(),
        Some(b) => {
            let read = format!(
                "over its speeds it reads {}° at {} m/s and {}° at {} m/s",
                deg(b.slow_bank),
                crate::format::fixed(b.slow_speed, 1),
                deg(b.fast_bank),
                crate::format::fixed(b.fast_speed, 1)
            );
            match b.scales_with_speed() {
                true => format!("; {read}, growing with the speed as a yaw-rate offset's does (a bank's and an ay offset's would not)"),
                false => format!("; {read}, not growing with the speed as a yaw-rate offset's would: a bank or an ay offset, which a standstill in the run tells apart (an offset reads there, a bank does not)"),
            }
        }
    };
    alike + &tell
}
