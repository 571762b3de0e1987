//! How far each measured channel of a set of runs is trusted, before any
//! model: the one rule that `diagnose` states as `channels trusted to:` and
//! that a `simulate` replay of one run uses for its noise floors, so that
//! the same run reads the same number of noise floors in both.
//!
//! Per channel: the median over the runs of its high-frequency scatter
//! (each run's as its gap estimates it: [`run_scatter`]), then the user's
//! stated uncertainty, the sensor type's floor or an estimated output's
//! ([`channel_scale`]). A channel's own scatter alone would trust a state
//! estimator's smooth output ten times a gyro. How the floor counts in the
//! gap's bias and window tests ([`floor_counting`]) also reads the median
//! over the runs of how white the channel's record is
//! ([`difference_correlation`]). Units: each channel's own
//! (rad/s, m/s², rad).

use crate::diagnose::campaign::StatedUncertainty;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::model::scale::{
    channel_scale, difference_correlation, floor_counting, reads_as_estimated, signal_rms,
    stated_excess, FloorCounting,
};
use crate::diagnose::report::summary::run_scatter;
use crate::diagnose::report::ChannelNoise;
use crate::measured::clean::median;
use crate::measured::MeasuredRun;
use rayon::prelude::*;

/// How far the channels of a set of runs are trusted.
#[derive(Debug, Clone, PartialEq)]
pub struct Trust {
    /// Each channel some run measures: its noise floor, scale and source.
    pub noise: Vec<ChannelNoise>,
    /// The fits' residual scales by channel index (1 where no run measures
    /// the channel: it has no residuals).
    pub scales: [f64; 3],
    /// The noise floors by channel index (0 where no run measures it).
    pub floors: [f64; 3],
    /// How each floor counts in the bias test, by channel index
    /// ([`floor_counting`]; white where no run measures the channel).
    pub countings: [FloorCounting; 3],
}

/// Each measured channel's lag-1 correlation of its first differences
/// over a run's scored samples ([`difference_correlation`]: −½ for a white
/// sensor's record, 0 for a smooth one's).
fn run_differences(run: &MeasuredRun) -> [Option<f64>; 3] {
    let idx = crate::diagnose::report::gap::scored_samples(run);
    Channel::ALL.map(|c| {
        c.of(run)
            .map(|v| difference_correlation(&idx.iter().map(|&i| v[i]).collect::<Vec<_>>()))
    })
}

/// How far each channel of `runs` is trusted, with the uncertainties the
/// user `stated` (module doc).
pub fn channel_trust(runs: &[MeasuredRun], stated: &StatedUncertainty) -> Trust {
    let per_run: Vec<[Option<(f64, f64)>; 3]> = runs.par_iter().map(run_scatter).collect();
    let differences: Vec<[Option<f64>; 3]> = runs.par_iter().map(run_differences).collect();
    let rms = signal_rms(runs);
    let mut scales = [1.0; 3];
    let mut floors = [0.0; 3];
    let mut countings = [FloorCounting::White; 3];
    let noise = Channel::ALL
        .into_iter()
        .filter_map(|ch| {
            let mut scatter: Vec<f64> = per_run
                .iter()
                .filter_map(|r| r[ch.index()].map(|x| x.0))
                .collect();
            (!scatter.is_empty()).then(|| {
                let runs = scatter.len();
                let each = scatter.clone();
                let scatter = median(&mut scatter);
                let side = reads_as_estimated(ch, scatter);
                let other_side = each
                    .iter()
                    .filter(|&&s| reads_as_estimated(ch, s) != side)
                    .count();
                let trust = channel_scale(ch, stated, scatter, rms[ch.index()]);
                scales[ch.index()] = trust.scale;
                floors[ch.index()] = trust.uncertainty;
                let mut smooth: Vec<f64> = differences
                    .iter()
                    .filter_map(|r| r[ch.index()])
                    .filter(|d| !d.is_nan())
                    .collect();
                let smooth = median(&mut smooth);
                countings[ch.index()] = floor_counting(ch, trust.source, scatter, smooth);
                ChannelNoise {
                    channel: ch,
                    unit: ch.unit(),
                    noise_floor: trust.uncertainty,
                    scale: trust.scale,
                    source: trust.source,
                    scatter: trust.scatter,
                    runs,
                    other_side,
                    stated_excess: stated_excess(ch, trust.source, trust.uncertainty, scatter),
                }
            })
        })
        .collect();
    Trust {
        noise,
        scales,
        floors,
        countings,
    }
}
