//! The columns of a schedule manoeuvre (`[manoeuvre]` `t`, `steer`,
//! `speed`) as a [`super::ParamReason`] names them: s, rad, m/s.

/// A column of a schedule manoeuvre; it displays as its key under
/// `[manoeuvre]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ScheduleColumn {
    /// The breakpoint times.
    T,
    /// The steers.
    Steer,
    /// The speeds.
    Speed,
}

impl std::fmt::Display for ScheduleColumn {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            ScheduleColumn::T => "t",
            ScheduleColumn::Steer => "steer",
            ScheduleColumn::Speed => "speed",
        })
    }
}
