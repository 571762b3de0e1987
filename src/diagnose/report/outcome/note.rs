//! The notes on a diagnosis's inputs (the campaign reader's, the
//! candidates the runs cannot show, the replay method, the channel
//! uncertainties stated, a base tyre fitted to rig data of other loads or
//! pooled levels), typed; [`crate::diagnose::report::words::note`] says
//! them. Units: SI, as each field states.

use crate::diagnose::effects::EffectKind;
use crate::diagnose::model::channels::Channel;
use crate::error::Unseen;
use serde::Serialize;

/// A note on the inputs.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Note {
    /// A note of the campaign reader (a file it left out, a steer that
    /// looks too small), in its own words.
    Campaign {
        /// The note.
        text: String,
    },
    /// A given tyre file whose `FNOMIN` the car's static wheel loads lie
    /// far from (`simulate`'s words, `nominal_load`): a warning, carried
    /// into the verdict's warnings
    /// ([`crate::diagnose::report::outcome::VerdictWarning::TyresFarFromLoad`]).
    TyresFarFromLoad {
        /// The words, per axle.
        text: String,
    },
    /// An effect the runs cannot show, left out of the candidates.
    NotACandidate {
        /// The effect.
        effect: EffectKind,
        /// What the runs lack.
        lacks: Unseen,
    },
    /// Runs with a bank channel but neither sideslip nor ay, on axles
    /// identified from the runs: the bank shows only in the yaw rate.
    BankOnlyInYawRate {
        /// Such runs.
        runs: usize,
        /// All runs.
        of: usize,
    },
    /// Runs the base model is too stiff to replay by RK4 at the step,
    /// replayed by ROS34PW2.
    StiffReplay {
        /// The replay step, s.
        step: f64,
        /// Such runs.
        runs: usize,
        /// All runs.
        of: usize,
    },
    /// An uncertainty stated under `[channels]` for a channel no run
    /// measures: unused.
    UncertaintyUnused {
        /// The channel.
        channel: Channel,
    },
    /// An uncertainty stated under `[channels]` that the channel's own
    /// high-frequency scatter exceeds more than
    /// [`crate::diagnose::model::scale::SCATTER_EXCESS`] times: the
    /// channel is weighted past what its record shows.
    UncertaintyBelowScatter {
        /// The channel.
        channel: Channel,
        /// The stated uncertainty, the channel's unit.
        stated: f64,
        /// The scatter measured (median over runs), the channel's unit.
        scatter: f64,
        /// The scale the fits weigh the channel by, the channel's unit: the
        /// stated uncertainty, or a share of its RMS signal where that is
        /// larger ([`crate::diagnose::model::scale::SIGNAL_SHARE`]).
        weighted: f64,
    },
    /// An uncertainty stated under `[channels]` more than
    /// [`crate::diagnose::model::scale::STATED_EXCESS`] times what the
    /// channel shows of itself: a gap below it is insignificant by the
    /// statement.
    UncertaintyAboveOwn(crate::diagnose::model::scale::StatedExcess),
    /// Rig data whose wheel loads do not reach the car's static wheel
    /// loads: the base tyre fitted to them is extrapolated there.
    RigLoadsShort {
        /// The rig data's least and largest wheel load, N.
        rig: [f64; 2],
        /// The car's least and largest static wheel load, N.
        car: [f64; 2],
    },
    /// Levels of the rig data pooled into one fit of a model without
    /// terms for them: the base tyre is their blend.
    RigLevelsPooled {
        /// The variable whose levels are pooled.
        variable: crate::identify::grouping::Variable,
        /// How many levels.
        levels: usize,
        /// The model fitted.
        model: crate::tyre::ModelName,
    },
    /// Runs that turn harder than the campaign's vehicle or road allows
    /// any car ([`crate::diagnose::pipeline`]'s `limits`): a friction or a
    /// centre-of-gravity height the runs contradict.
    RunsBeyondVehicle {
        /// The limit passed.
        limit: VehicleLimit,
        /// The runs' 99th percentile of |u·r|, m/s².
        reached: f64,
        /// The limit as a lateral acceleration, m/s².
        threshold: f64,
    },
    /// A file whose measured sideslip moves against the base model's
    /// where the campaign's runs together move with it: a logger set up in
    /// the other sign convention for that file, or stretches the model
    /// misses.
    BetaAgainstInFile {
        /// The file.
        file: String,
        /// Its runs' pooled correlation with the base model's β.
        correlation: f64,
        /// Samples judged.
        samples: usize,
    },
}

/// A limit of the campaign's vehicle or road that its runs pass.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum VehicleLimit {
    /// The road's friction: no car turns beyond μ·g.
    Friction {
        /// The campaign's friction coefficient μ.
        friction: f64,
    },
    /// The static stability factor g·t/(2h): a rigid car's inner wheels
    /// lift beyond it.
    Rollover {
        /// The narrower track t, m.
        track: f64,
        /// The centre-of-gravity height h, m.
        cg_height: f64,
    },
}

impl Note {
    /// Whether the terminal and the page say it as a warning, not a note.
    pub fn is_warning(&self) -> bool {
        matches!(
            self,
            Note::TyresFarFromLoad { .. } | Note::RunsBeyondVehicle { .. }
        )
    }
}
