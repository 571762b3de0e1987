//! The notes on a diagnosis's inputs (the campaign reader's, the
//! candidates the runs cannot show, the replay method, the channel
//! uncertainties stated, a base tyre used beyond the loads it was fitted
//! at, a base tyre fitted to rig data of pooled levels), typed; [`crate::diagnose::report::words::note`] says
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
    /// A base tyre whose load range (the rig data's it is fitted to, or
    /// the one its file states) the car's static wheel loads leave: the
    /// tyre is used at loads it was not fitted at
    /// (`crate::diagnose::pipeline`'s `tyre_loads`).
    TyreLoadsShort {
        /// Where the range comes from.
        of: LoadRangeOf,
        /// The range's least and largest load, N (a `.tir` without `FZMIN`
        /// 0, without `FZMAX` unbounded, written `null`).
        loads: [f64; 2],
        /// The car's least and largest static wheel load on the axles the
        /// tyre is on, N.
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

/// Where a base tyre's load range comes from ([`Note::TyreLoadsShort`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum LoadRangeOf {
    /// The wheel loads of the rig data the tyre is fitted to.
    Rig,
    /// A TOML tyre file's `[fitted_ranges] fz` (`identify` writes it).
    Fitted {
        /// The file, as the campaign names it.
        file: String,
        /// The axles it is on.
        axles: TyreAxles,
    },
    /// A `.tir`'s `FZMIN`–`FZMAX`.
    Tir {
        /// The file, as the campaign names it.
        file: String,
        /// The axles it is on.
        axles: TyreAxles,
        /// Its mode's limit checks (1xx) are on: a load beyond `FZMAX` is
        /// evaluated at `FZMAX`, not extrapolated.
        limit_checks: bool,
    },
}

/// The axles a given tyre file is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TyreAxles {
    /// Both (`[tyres] file`, or one file as `front` and `rear`).
    Both,
    /// The front (`[tyres] front`).
    Front,
    /// The rear (`[tyres] rear`).
    Rear,
}

impl TyreAxles {
    /// Its words: the car's static wheel loads of `both`, of the `front`
    /// wheels, of the `rear` wheels.
    pub fn wheels(self) -> &'static str {
        match self {
            TyreAxles::Both => "the car's static wheel loads",
            TyreAxles::Front => "the car's static front wheel load",
            TyreAxles::Rear => "the car's static rear wheel load",
        }
    }
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
