//! The one rule for a listed sweep axis, shared by `equilibria`'s
//! `[sweep]` axes and `study`'s stiffness axes: an axis is a set of
//! values, given once each, in increasing order. Each job traces its axes
//! from one value to the next (bifurcations located between neighbours, a
//! study's target curve drawn through neighbouring map points), so an
//! unsorted list repeated bifurcations with their stability reversed and
//! drew a crossing target curve: it is refused at the value, never sorted
//! behind the user's back.

/// Why a listed axis is refused.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Disorder {
    /// Index `at` repeats an earlier value.
    Repeated {
        /// Index of the repeat.
        at: usize,
    },
    /// Index `at` lies below the value before it.
    Descending {
        /// Index of the value.
        at: usize,
        /// The value before it.
        before: f64,
    },
}

/// The first thing wrong with `v` as an axis: a repeated value (looked for
/// first, over the whole list, sorted once — an axis may hold a million
/// values) else the first value below its predecessor.
pub(crate) fn disorder(v: &[f64]) -> Option<Disorder> {
    let mut order: Vec<usize> = (0..v.len()).collect();
    order.sort_by(|&a, &b| v[a].total_cmp(&v[b]).then(a.cmp(&b)));
    let repeat = order
        .windows(2)
        .filter(|w| v[w[0]] == v[w[1]])
        .map(|w| w[1])
        .min();
    if let Some(at) = repeat {
        return Some(Disorder::Repeated { at });
    }
    v.windows(2)
        .position(|w| w[1] < w[0])
        .map(|i| Disorder::Descending {
            at: i + 1,
            before: v[i],
        })
}

/// The `i`-th value of the range from `from` by `step`, rounded to the
/// decimals `from` and `step` are written with (up to 12): 0.1 + 2·0.1 is
/// 0.30000000000000004 in binary, and was written so to equilibria.csv.
pub(crate) fn range_value(from: f64, step: f64, i: usize) -> f64 {
    let x = from + i as f64 * step;
    let decimals = |v: f64| {
        (0..=12).find(|&d| {
            let p = 10f64.powi(d);
            ((v * p).round() / p - v).abs() <= 1e-15 * v.abs()
        })
    };
    match (decimals(from), decimals(step)) {
        (Some(a), Some(b)) => {
            let p = 10f64.powi(a.max(b));
            (x * p).round() / p
        }
        _ => x,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_repeat_is_found_before_a_descent_and_a_sorted_axis_passes() {
        assert_eq!(disorder(&[0.0, 0.02, 0.04]), None);
        assert_eq!(
            disorder(&[0.1, 0.0, 0.1]),
            Some(Disorder::Repeated { at: 2 })
        );
        assert_eq!(
            disorder(&[80.0, 20.0, 50.0]),
            Some(Disorder::Descending {
                at: 1,
                before: 80.0
            })
        );
    }

    #[test]
    fn a_range_value_keeps_the_decimals_it_is_written_with() {
        assert_eq!(range_value(0.1, 0.1, 2), 0.3);
        assert_eq!(range_value(0.0, 0.01, 7), 0.07);
        assert_eq!(range_value(220.0, 100.0, 3), 520.0);
        // A step of no short decimal form is left as computed.
        let third = 1.0 / 3.0;
        assert_eq!(range_value(0.0, third, 2), 2.0 * third);
    }
}
