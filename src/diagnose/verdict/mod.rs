//! How the verdict is chosen: every candidate fitted on all runs and
//! scored on held-out runs (`score`: the folds, the held-out gap above
//! noise and an effect's reduction of it) against the base model's scores
//! (`baseline`), the singles and the greedy additions' sets screened
//! before their cross-validation (`screening`), and the search for the set of
//! effects that explains the gap (`search`, and `pairs` where it reaches no verdict), the rules all three apply as
//! pure functions (`rules`, with their thresholds; `twins` lets them read the
//! verdict's set against its look-alikes in its first effect's place), and the verdict's case
//! from what the search found (`conclude`).
//! Units: SI, rad; held-out errors J dimensionless.

pub(crate) mod baseline;
pub(crate) mod calibration;
pub(crate) mod candidate;
pub(crate) mod class;
pub(crate) mod conclude;
pub(crate) mod pairs;
pub(crate) mod restricted;
pub mod rules;
pub(crate) mod score;
pub(crate) mod screening;
pub(crate) mod search;
pub(crate) mod standstills;
pub(crate) mod twins;
