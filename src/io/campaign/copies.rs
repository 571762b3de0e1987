//! Runs a campaign selects twice under two names: a file copied
//! (`run_2.csv` saved again as `run_2_copy.csv`, byte for byte or with
//! other line endings or number formats). Held out, the copy is scored on
//! the very samples its twin was fitted on, so a candidate's held-out gain
//! is its in-sample gain again: evidence counted twice. A copy is refused
//! at its `[runs]` entry, as the same file listed twice is
//! ([`super::runs`]). Runs are compared as read (every column, the path
//! aside), each file read once: the bytes are not compared, so a copy
//! saved with CRLF line endings or `20.0` for `20` is the copy it is.

use crate::measured::MeasuredRun;

/// Whether two runs as read hold the same samples: every column equal,
/// whatever their files' bytes (the path aside). Written out field by
/// field, so that a column added to [`MeasuredRun`] must be added here.
pub(super) fn same_samples(a: &MeasuredRun, b: &MeasuredRun) -> bool {
    let MeasuredRun {
        path: _,
        t,
        speed,
        steer,
        yaw_rate,
        ay,
        beta,
        roll,
        bank,
        ax,
        masked,
        clock,
    } = a;
    // The times first: runs of other lengths or rates differ there.
    *t == b.t
        && *steer == b.steer
        && *yaw_rate == b.yaw_rate
        && *speed == b.speed
        && *ay == b.ay
        && *beta == b.beta
        && *roll == b.roll
        && *bank == b.bank
        && *ax == b.ax
        && *masked == b.masked
        // A wall clock rebased: two runs logged at other times are no copy.
        && *clock == b.clock
}

/// The earlier run of `read` whose samples `run` repeats, if any.
pub(super) fn copied_from(read: &[MeasuredRun], run: &MeasuredRun) -> Option<usize> {
    read.iter().position(|r| same_samples(r, run))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(steer: f64) -> MeasuredRun {
        MeasuredRun::new(
            "a.csv",
            vec![0.0, 0.01],
            vec![20.0; 2],
            vec![steer; 2],
            vec![0.0; 2],
        )
    }

    #[test]
    fn a_copy_is_found_under_another_name_and_a_run_differing_by_one_sample_is_not() {
        let (a, b) = (run(0.01), run(0.02));
        let copy = MeasuredRun {
            path: "c.csv".into(),
            ..a.clone()
        };
        assert_eq!(copied_from(&[a.clone(), b.clone()], &copy), Some(0));
        assert_eq!(copied_from(std::slice::from_ref(&b), &copy), None);
        let with_ay = MeasuredRun {
            ay: Some(vec![0.0; 2]),
            ..copy
        };
        assert_eq!(copied_from(&[a, b], &with_ay), None);
    }
}
