//! Measured vehicle runs as the jobs take them (`FORMATS.md`): the run
//! ([`MeasuredRun`]: t, speed, steer, yaw_rate required; ay, beta, roll,
//! bank, ax optional), the sensor offsets its standstills and straights show
//! ([`calibration`], on the raw run), its cleaning ([`clean`]: standstills,
//! crawling and logger glitches found, repaired, masked and reported) and its
//! longitudinal acceleration ([`derivative`]: `ax`, else the speed's
//! smoothed derivative). SI units,
//! radians, ISO 8855 signs. `io` reads files into these; nothing here reads
//! a file.

pub mod calibration;
pub mod clean;
pub(crate) mod derivative;
pub(crate) mod road;

use std::path::PathBuf;

/// One measured manoeuvre.
#[derive(Debug, Clone, PartialEq)]
pub struct MeasuredRun {
    /// The file it came from.
    pub path: PathBuf,
    /// Time, s, strictly increasing.
    pub t: Vec<f64>,
    /// Forward speed, m/s.
    pub speed: Vec<f64>,
    /// Front road-wheel steer, rad.
    pub steer: Vec<f64>,
    /// Yaw rate, rad/s.
    pub yaw_rate: Vec<f64>,
    /// Lateral acceleration, m/s².
    pub ay: Option<Vec<f64>>,
    /// Sideslip at the centre of gravity, rad.
    pub beta: Option<Vec<f64>>,
    /// Body roll relative to the road, rad (ISO: positive right side down).
    pub roll: Option<Vec<f64>>,
    /// Road bank under the car, rad (positive: the road's left edge higher).
    pub bank: Option<Vec<f64>>,
    /// Longitudinal acceleration, m/s².
    pub ax: Option<Vec<f64>>,
    /// Samples whose response channels (yaw rate, ay, beta) are left out of
    /// fits and scores (logger glitches, see [`clean`]), ascending.
    pub masked: Vec<usize>,
}
