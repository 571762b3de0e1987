//! The physical ranges of the numbers a scenario's `[model.effects]`
//! gives (roll camber, relaxation length, cornering-stiffness scale, roll
//! steer, the body's roll frequency and damping), as
//! [`super::Limit::Effect`] says them: `roll_camber = [500, 0]` ran away
//! (gigabytes of memory, no output), a relaxation length of 5e6 m and a
//! scale of 1e6 on a tyre's stiffness ran without a word. The ranges hold
//! every car's with room (the diagnosis searches narrower ones,
//! `crate::diagnose::effects`). Units as the keys': rad, m, Hz.

use thiserror::Error;

/// Which effect's range a value left.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Error)]
pub enum EffectLimit {
    /// The share of a replayed run's measured bank the road has.
    #[error("the share of a logged bank the road has lies in 0 to 2 (1: as measured, 0: a flat road; the diagnosis searches -0.5 to 2): beyond, the log's bank is not that road's (a wrong unit or sign: is the `bank` column in degrees?)")]
    BankProfileScale,
    /// Camber thrust per wheel load per rad of roll.
    #[error("camber thrust beyond ±10 of the wheel load per rad of body roll is no car's (a tyre's camber stiffness is about 1 per rad of camber, and a wheel cambers by about its body's roll); the diagnosis searches ±8")]
    RollCamber,
    /// A relaxation length, m.
    #[error(
        "a relaxation length beyond 3 m is no tyre's (a car tyre's is 0.2–1 m); the key is in m"
    )]
    RelaxationLength,
    /// A scale on an axle's cornering stiffness.
    #[error("a scale on an axle's cornering stiffness outside 0.2 to 5 is another tyre, not the same one scaled (the diagnosis searches 0.4 to 2)")]
    CorneringStiffnessScale,
    /// Axle steer per rad of roll.
    #[error("roll steer beyond ±1 rad of axle steer per rad of body roll is no suspension's (a car's is a few tenths at most)")]
    RollSteer,
    /// The body's roll natural frequency, Hz.
    #[error("a body's roll natural frequency is 1–3 Hz (a racing car's up to about 5 Hz): above 10 Hz it is no body's, and only multiplies the integration steps (is the value in rad/s?)")]
    RollFrequency,
    /// The body's roll damping ratio.
    #[error("a body's roll damping ratio is 0.2–1: above 5 it is no car's damper")]
    RollDamping,
}
