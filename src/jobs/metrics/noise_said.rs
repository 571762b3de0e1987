//! What the noise of the yaw rate and of `ay` adds to the total variances
//! `E_r`, `E_ay` and to `Er = e1·E_r + e2·E_ay`, said where it is a tenth
//! or more of what it adds to. White noise of deviation σ (after the
//! filter, a share of the channel's step) adds `W·σ²` to
//! `E_x = ∫(δ̂ − x̂)² dt` over a window `W`, in expectation, whatever its
//! correlation; a noise of a tenth of the step over 4 s adds 0.04 s, the
//! size of a car's `E_r`. One run scatters about it by as much (the noise
//! of the initial and steady means that normalise the response, and the
//! noise's product with the response error): the figure is a bias, not a
//! correction of the run. Times in s; noises as shares of the step.

use crate::metrics::StepMetrics;

/// The share of a total variance the noise must add to be said.
const SAID_SHARE: f64 = 0.1;

/// The noise `noise` (share of the step) adds to a total variance over
/// `window` s.
fn added(noise: f64, window: f64) -> f64 {
    window * noise.powi(2)
}

/// The estimate of the total variance `name` (`value` s) without the
/// noise's expected share `add`: none where that share passes the value
/// itself (this run's noise fell below its mean), since a total variance
/// is never negative ("E_ay − 1.65 = -0.00188 s is the estimate without
/// it" on a 0.01° step logged with noise of 62 % of its ay step).
fn without(name: &str, value: f64, add: f64) -> String {
    let rest = value - add;
    if rest > 0.0 {
        return format!(
            "{name} − {} = {} s is the estimate without it",
            crate::format::readable(add, 3),
            crate::format::readable(rest, 3)
        );
    }
    format!(
        "the noise's expected share, {} s, is all of {name} ({} s) or more, so the run gives no estimate of {name} without it (its own noise fell below the mean; one run cannot tell {name} from 0)",
        crate::format::readable(add, 3),
        crate::format::readable(value, 4)
    )
}

/// What e1 and e2 are, with their values: the terminal says them where
/// they weigh a noise's share into Er (the book defines them, the
/// terminal's "e2 times it for Er" did not, round 51).
fn weights((e1, e2): (f64, f64)) -> String {
    format!(
        "Er = e1·E_r + e2·E_ay, the total variances weighted by e1 = {} and e2 = {}",
        crate::error::Num(e1),
        crate::error::Num(e2)
    )
}

/// The warnings of the total variances of `m` a tenth or more of which
/// is noise over `window` s: `E_r`'s, `E_ay`'s, and Er's with what each
/// channel adds to it through its weight (`weights`, e1 and e2).
pub(super) fn noise_in_variance(m: &StepMetrics, window: f64, (e1, e2): (f64, f64)) -> Vec<String> {
    let mut said = Vec::new();
    let add_r = added(m.yaw_rate_noise, window);
    let e_r = m.yaw_rate_total_variance;
    if add_r > 0.0 && add_r >= SAID_SHARE * e_r {
        said.push(format!(
            "the yaw-rate noise ({}) adds about {} s to E_r ({} s) over its {} s window, on average (white noise adds its variance times the window; one run scatters about that by as much): E_r reads high by that much and Er by e1 times it ({}), {}; filter harder (--filter-hz) or log a quieter gyro",
            m.yaw_rate_noise_text(),
            crate::format::readable(add_r, 3),
            crate::format::readable(e_r, 4),
            crate::error::Num(window),
            weights((e1, e2)),
            without("E_r", e_r, add_r),
        ));
    }
    let (Some(noise_ay), Some(e_ay), Some(er)) = (m.ay_noise, m.ay_total_variance, m.er) else {
        return said;
    };
    let add_ay = added(noise_ay, window);
    if add_ay > 0.0 && add_ay >= SAID_SHARE * e_ay {
        said.push(format!(
            "the ay noise ({} % of its step) adds about {} s to E_ay ({} s) over its {} s window, on average (white noise adds its variance times the window; one run scatters about that by as much): E_ay reads high by that much and Er by e2 times it ({}), {}; filter harder (--filter-hz) or log a quieter accelerometer",
            crate::format::decimals_or_digits(100.0 * noise_ay, 2, 2),
            crate::format::readable(add_ay, 3),
            crate::format::readable(e_ay, 4),
            crate::error::Num(window),
            weights((e1, e2)),
            without("E_ay", e_ay, add_ay),
        ));
    }
    // Er's share: a tenth of Er implies a tenth of E_r or of E_ay, so
    // this line always follows one of the channels'.
    let (through_r, through_ay) = (e1 * add_r, e2 * add_ay);
    let add_er = through_r + through_ay;
    if add_er > 0.0 && add_er >= SAID_SHARE * er {
        said.push(format!(
            "the noise adds about {} s to Er ({} s) in all, {} s through E_r (e1 = {}) and {} s through E_ay (e2 = {}): {}",
            crate::format::readable(add_er, 3),
            crate::format::readable(er, 4),
            crate::format::readable(through_r, 3),
            crate::error::Num(e1),
            crate::format::readable(through_ay, 3),
            crate::error::Num(e2),
            without("Er", er, add_er),
        ));
    }
    said
}

#[cfg(test)]
mod tests {
    use super::{weights, without};

    #[test]
    fn the_weights_are_said_with_what_they_weigh() {
        assert_eq!(
            weights((1.0, 0.5)),
            "Er = e1·E_r + e2·E_ay, the total variances weighted by e1 = 1 and e2 = 0.5"
        );
    }

    #[test]
    fn a_noise_share_past_the_variance_gives_no_negative_estimate() {
        assert_eq!(
            without("E_r", 0.0613, 0.0197),
            "E_r − 0.0197 = 0.0416 s is the estimate without it"
        );
        let w = without("E_ay", 1.6953, 1.6972);
        assert!(
            w.starts_with("the noise's expected share, 1.70 s, is all of E_ay (1.695 s) or more"),
            "{w}"
        );
        assert!(!w.contains('-'), "{w}");
    }
}
