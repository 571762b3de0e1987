//! What the settling words may claim of a sideslip that still moves while
//! the yaw rate and lateral acceleration have settled. A car at its grip
//! limit can hold them while the magnitude of its sideslip |β| grows, but
//! so can a sideslip that is only slower to settle: where the run knows
//! its axles stay short of their tyres' peak (`simulate`: round 48 said
//! "at its grip limit" of a run whose front axle it said, in the next
//! warning, reached 86 % of its tyres' peak and did not slide past it),
//! the grip limit is not suggested; where it does not know (a measured
//! record, whose tyres' grip is not in it), the slide is said as a
//! possibility, not as the explanation. One source for the words.

/// What a run knows of its axles against their tyres' peak.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AxlesGrip {
    /// Not known (a measured record).
    Unknown,
    /// Both axles stay short of their tyres' peak through the run (at
    /// their largest slip and at its end).
    BelowPeak,
    /// An axle reaches or passes its tyres' peak.
    AtPeak,
}

/// The clause after the channels that have not settled, where the
/// sideslip moves while the yaw rate and lateral acceleration hold.
pub(super) fn words(axles: AxlesGrip) -> &'static str {
    match axles {
        AxlesGrip::Unknown => "; the yaw rate and lateral acceleration have settled while the sideslip has not: a car at its grip limit can hold them while the magnitude of its sideslip |β| grows, a possibility this record, which does not give its tyres' grip, can neither confirm nor rule out (a sideslip slower to settle than they are reads alike)",
        AxlesGrip::BelowPeak => "; the yaw rate and lateral acceleration have settled while the sideslip has not, with both axles short of their tyres' peak: no slide at the grip limit, a sideslip slower to settle than they are",
        AxlesGrip::AtPeak => "; the yaw rate and lateral acceleration have settled while the sideslip has not: at its grip limit a car holds them while the magnitude of its sideslip |β| grows, and an axle here reaches its tyres' peak",
    }
}
