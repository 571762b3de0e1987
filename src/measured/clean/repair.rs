//! The repair of a driving channel's glitches (steer, speed): linear
//! interpolation in time across them, so that a replay is not kicked.
//! Units: those of the channel; times in s.

/// Interpolates `x` linearly in `t` across the flagged samples (held at the
/// nearest good value at an end).
pub(super) fn repair(t: &[f64], x: &mut [f64], bad: &[bool]) {
    let n = x.len();
    let mut i = 0;
    while i < n {
        if !bad[i] {
            i += 1;
            continue;
        }
        let mut j = i;
        while j < n && bad[j] {
            j += 1;
        }
        let left = i.checked_sub(1);
        let right = (j < n).then_some(j);
        for k in i..j {
            x[k] = match (left, right) {
                (Some(l), Some(r)) => x[l] + (x[r] - x[l]) * (t[k] - t[l]) / (t[r] - t[l]),
                (Some(l), None) => x[l],
                (None, Some(r)) => x[r],
                (None, None) => x[k],
            };
        }
        i = j;
    }
}
