//! The boxed payloads of [`super::ParamReason`]'s larger kinds and the
//! messages built from them (kept apart so the kinds' list stays short).

/// What [`ParamReason::UncertaintyBeyondSignal`] says, boxed: the channel's
/// RMS signal, its unit, a sensor's floor and ten times an estimated
/// output's uncertainty (the channel's unit).
#[derive(Debug, Clone, PartialEq)]
pub struct BeyondSignal {
    /// The channel's RMS signal over every run.
    pub signal: f64,
    /// The channel's unit.
    pub unit: &'static str,
    /// The floor of a sensor of its kind.
    pub floor: f64,
    /// Ten times an estimated output's uncertainty.
    pub estimated: f64,
}

/// What [`ParamReason::CorneringPerLoad`] says, boxed: the stiffness per
/// unit load, the load it is taken at and the least of any tyre.
#[derive(Debug, Clone, PartialEq)]
pub struct PerLoad {
    /// Stiffness over load, 1/rad.
    pub per_load: f64,
    /// The key of the load.
    pub load_key: &'static str,
    /// The load, N.
    pub load: f64,
    /// Whether the load is the model's default, which a file stating none
    /// is read at.
    pub default: bool,
    /// The least of any tyre, 1/rad.
    pub min: f64,
}

/// The message of [`ParamReason::CorneringPerLoad`]: the stiffness per
/// unit load at the load it is taken at, the floor with the tyres it lies
/// below, and the N/deg slip with the value given converted.
pub(super) fn cornering_per_load(r: &PerLoad) -> String {
    let given = r.per_load * r.load;
    format!(
        "over the tyre's {} = {} N{} that is {} N/rad per N (Cα/Fz), below any tyre's {} (a car tyre's is about 5–45 at its nominal load, a truck's or tractor's about 7, Pacejka's book tyre's 12.0 at 4 kN): the key is in N/rad, per wheel: is the value in N/deg? multiply it by 57.3 ({} N/deg is {} N/rad, {} N/rad per N)",
        r.load_key,
        crate::format::rounded(r.load, 6),
        match r.default {
            true => " (the model's default where a file states none)",
            false => "",
        },
        crate::format::readable(r.per_load, 3),
        crate::error::Num(r.min),
        crate::error::Num(given),
        crate::format::rounded(given.to_degrees(), 5),
        crate::format::readable(r.per_load.to_degrees(), 3)
    )
}
