//! What the report already holds about a channel whose gap a verdict
//! leaves or makes larger ([`ChannelCause`]), in the words of a verdict's
//! warning: the file whose sideslip moves against the base model's (the
//! note above), the run carrying most of the gap left, the base model's
//! steady offset (where the gap lies, above). RMS values and offsets in
//! the channel's unit; shares in percent.

use crate::diagnose::model::channels::Channel;
use crate::diagnose::report::outcome::ChannelCause;
use crate::measured::clean::source_file;

/// The causes said in one clause, `None` without any. A run carrying most
/// of the gap that is a file the note names (or a piece of it) is said
/// with that file, not again.
pub(super) fn pointed(causes: &[ChannelCause], channel: Channel, floor: f64) -> Option<String> {
    let unit = channel.unit();
    let mut said: Vec<(Option<&str>, String)> = Vec::new();
    for c in causes {
        match c {
            ChannelCause::BetaAgainst { file, correlation } => said.push((
                Some(file.as_str()),
                format!("{file}'s beta moves against the base model's (correlation {correlation:.2}, the note above)"),
            )),
            ChannelCause::RunCarries {
                run,
                share_percent,
                rms,
                scale_apart,
            } => {
                // A gyro's scale error in that run holds its gap.
                let scale = scale_apart.map_or(String::new(), |a| {
                    format!("; {}", crate::measured::road::scale_in_run(&a))
                });
                let carries = format!(
                    "{share_percent:.0} % of this channel's gap above noise left (RMS {rms:.4} {unit}, {} noise floors){scale}",
                    crate::format::fixed(rms / floor, 1)
                );
                let file = source_file(std::path::Path::new(run));
                match said.iter_mut().find(|(f, _)| *f == Some(file.as_str())) {
                    Some((_, s)) if *run == file => s.push_str(&format!(", and it carries {carries}")),
                    Some((_, s)) => s.push_str(&format!(", and its piece {run} carries {carries}")),
                    None => said.push((None, format!("{run} carries {carries}"))),
                }
            }
            ChannelCause::SteadyOffset(o) => said.push((
                None,
                format!(
                    "the base model's steady offset in it, mean residual {} {unit} over the runs ({} noise floors, where the gap lies above)",
                    crate::format::signed(o.mean, 4),
                    crate::format::fixed(o.floors, 1)
                ),
            )),
        }
    }
    let each: Vec<String> = said.into_iter().map(|(_, s)| s).collect();
    (!each.is_empty()).then(|| each.join("; "))
}
