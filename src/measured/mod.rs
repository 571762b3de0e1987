//! Measured vehicle runs as the jobs take them (`FORMATS.md`): the run
//! ([`MeasuredRun`]: t, speed, steer, yaw_rate required; ay, beta, roll,
//! bank, ax optional), the sensor offsets its standstills and straights show
//! ([`calibration`], on the raw run), its cleaning ([`clean`]: standstills,
//! crawling and logger glitches found, repaired, masked and reported) and its
//! longitudinal acceleration ([`derivative`]: `ax`, else the speed's
//! smoothed derivative) and its clock ([`clock`]: a wall clock rebased
//! to the run's first sample, a wrap told from a new recording). SI units,
//! radians, ISO 8855 signs. `io` reads files into these; nothing here reads
//! a file.

pub mod ax_agreement;
pub mod calibration;
pub mod clean;
pub mod clock;
pub(crate) mod derivative;
pub(crate) mod road;
mod road_apart;
mod road_scale;
mod road_words;

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
    /// The log's clock at its first sample, s, where the reader rebased
    /// `t` to that sample (a wall clock, [`clock::rebase`]).
    pub clock: Option<f64>,
}

/// A response channel of a run that holds one value throughout: a dead or
/// unplugged sensor (a logger writing zeros). Its noise floor is zero, so
/// `diagnose` would take any gap to it as infinitely significant, and its
/// step is none, so `metrics` would read a yaw rate that does not move as a
/// unit error and a sideslip that does not as 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeadChannel {
    /// The column.
    pub channel: &'static str,
    /// The one value it holds (in the run's units after reading).
    pub value: f64,
    /// Whether the format requires the column (`yaw_rate`), else it is
    /// optional (`ay`, `beta`).
    pub required: bool,
}

impl DeadChannel {
    /// The refusal of a run with this dead channel.
    pub fn problem(&self) -> crate::error::InputProblem {
        crate::error::InputProblem::DeadChannel {
            channel: self.channel,
            value: self.value,
            required: self.required,
        }
    }
}

impl MeasuredRun {
    /// A run of the required channels only (the optional ones absent, no
    /// sample masked): the one way to build a run; the `with_*` methods add
    /// the optional channels.
    pub fn new(
        path: impl Into<PathBuf>,
        t: Vec<f64>,
        speed: Vec<f64>,
        steer: Vec<f64>,
        yaw_rate: Vec<f64>,
    ) -> Self {
        MeasuredRun {
            path: path.into(),
            t,
            speed,
            steer,
            yaw_rate,
            ay: None,
            beta: None,
            roll: None,
            bank: None,
            ax: None,
            masked: Vec::new(),
            clock: None,
        }
    }

    /// The run with lateral acceleration `ay` (m/s²; a `Vec` or an `Option`).
    pub fn with_ay(self, ay: impl Into<Option<Vec<f64>>>) -> Self {
        MeasuredRun {
            ay: ay.into(),
            ..self
        }
    }

    /// The run with sideslip `beta` (rad; a `Vec` or an `Option`).
    pub fn with_beta(self, beta: impl Into<Option<Vec<f64>>>) -> Self {
        MeasuredRun {
            beta: beta.into(),
            ..self
        }
    }

    /// The run with body roll `roll` (rad; a `Vec` or an `Option`).
    pub fn with_roll(self, roll: impl Into<Option<Vec<f64>>>) -> Self {
        MeasuredRun {
            roll: roll.into(),
            ..self
        }
    }

    /// The run with road bank `bank` (rad; a `Vec` or an `Option`).
    pub fn with_bank(self, bank: impl Into<Option<Vec<f64>>>) -> Self {
        MeasuredRun {
            bank: bank.into(),
            ..self
        }
    }

    /// The run with longitudinal acceleration `ax` (m/s²; a `Vec` or an
    /// `Option`).
    pub fn with_ax(self, ax: impl Into<Option<Vec<f64>>>) -> Self {
        MeasuredRun {
            ax: ax.into(),
            ..self
        }
    }

    /// The response channels (yaw rate, `ay`, `beta`) that hold one finite
    /// value over the whole run (samples that are not numbers aside), in
    /// that order: the one rule of a dead channel, for every job.
    pub fn dead_channels(&self) -> Vec<DeadChannel> {
        let channels = [
            ("yaw_rate", Some(&self.yaw_rate), true),
            ("ay", self.ay.as_ref(), false),
            ("beta", self.beta.as_ref(), false),
        ];
        channels
            .into_iter()
            .filter_map(|(channel, values, required)| {
                one_value(values?).map(|value| DeadChannel {
                    channel,
                    value,
                    required,
                })
            })
            .collect()
    }
}

/// The one finite value `v` holds throughout (samples that are not numbers
/// aside), if it holds one: the rule of [`MeasuredRun::dead_channels`].
pub fn one_value(v: &[f64]) -> Option<f64> {
    let mut finite = v.iter().copied().filter(|x| x.is_finite());
    let first = finite.next()?;
    finite.all(|x| x == first).then_some(first)
}
