//! A campaign run's logged `ax` checked against its speed's change in unit
//! and sign ([`AxAgreement`], the check a `simulate` replay makes): the
//! diagnosis drives its longitudinal effects (braking, throttle) and load
//! transfer by it, and an `ax` in g or positive rearward would be fitted
//! as a car that pitches and brakes 10× or backwards. Said once per run.

use crate::measured::ax_agreement::{AxAgreement, AxReading};
use crate::measured::MeasuredRun;

/// The note of run `run` whose `ax` its speed reads in g or reversed;
/// `None` where it agrees, or the run has no `ax` or too few windows whose
/// speed changes to tell.
pub(super) fn ax_note(run: &MeasuredRun) -> Option<String> {
    let a = AxAgreement::of(&run.t, &run.speed, run.ax.as_deref()?)?;
    let (says, fix) = match a.reading()? {
        AxReading::InG => ("reads in g, not m/s²", "multiply the column by 9.81"),
        AxReading::Reversed => (
            "is positive rearward, not forward (ISO 8855)",
            "change its sign",
        ),
    };
    Some(format!(
        "{}: `ax` {says}: over its {} one-second windows whose speed changes by more than 0.5 m/s, the change of speed is {} × the integral of `ax` (1 where they agree; correlation {}); the diagnosis takes `ax` as m/s² forward for its longitudinal effects and load transfer: {fix}",
        run.path.display(),
        a.windows,
        crate::format::fixed(a.slope, 2),
        crate::format::fixed(a.correlation, 2),
    ))
}
