//! The parts of a run a gap is pooled over ([`Part`]): the time windows
//! from the start of its input and the regimes (bands of |ay| and of speed),
//! with the samples that fall in each. Times in s, |ay| in m/s², speed in m/s.

use serde::Serialize;

/// A run's part is judged on its own only with at least this many
/// samples: fewer say nothing of a part (the gap summary's parts and runs
/// off in a part, and the runs a verdict leaves, by one rule).
pub(crate) const LEAST_PART_SAMPLES: usize = 10;

/// A time window of a run, from the start of its input.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Window {
    /// Before the input starts.
    BeforeInput,
    /// The input's first 0.5 s.
    FirstHalfSecond,
    /// 0.5–2 s after the input starts.
    HalfToTwoSeconds,
    /// Later than 2 s.
    Later,
}

impl Window {
    /// Every window, in time order.
    pub const ALL: [Window; 4] = [
        Window::BeforeInput,
        Window::FirstHalfSecond,
        Window::HalfToTwoSeconds,
        Window::Later,
    ];

    /// Its name in reports.
    pub fn label(self) -> &'static str {
        match self {
            Window::BeforeInput => "before the input",
            Window::FirstHalfSecond => "first 0.5 s of the input",
            Window::HalfToTwoSeconds => "0.5–2 s after the input",
            Window::Later => "later",
        }
    }

    /// Its place in time order: the window's centre, s after the input
    /// starts (the open ends half a second before and a second after). The
    /// gap map draws a window at its samples' mean time instead
    /// ([`Levels::mean`]).
    pub fn centre(self) -> f64 {
        match self {
            Window::BeforeInput => -0.5,
            Window::FirstHalfSecond => 0.25,
            Window::HalfToTwoSeconds => 1.25,
            Window::Later => 3.0,
        }
    }
}

/// The axis of the gap map a part lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PartAxis {
    /// Time after the input starts, s.
    Time,
    /// Lateral-acceleration level |ay|, m/s².
    Ay,
    /// Speed, m/s.
    Speed,
}

impl PartAxis {
    /// Every axis, in the gap map's order.
    pub const ALL: [PartAxis; 3] = [PartAxis::Time, PartAxis::Ay, PartAxis::Speed];
}

/// A part of the data a gap is pooled over: everything, a time window or a
/// regime (a band of |ay| or of speed, `lo` included, `hi` excluded).
/// Serialised as its label.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Part {
    /// All samples.
    All,
    /// A time window.
    Window(Window),
    /// Samples with `lo ≤ |ay| < hi`, m/s².
    Ay {
        /// Lower edge.
        lo: f64,
        /// Upper edge (may be infinite).
        hi: f64,
    },
    /// Samples with `lo ≤ speed < hi`, m/s.
    Speed {
        /// Lower edge.
        lo: f64,
        /// Upper edge.
        hi: f64,
    },
}

impl Part {
    /// Its label in reports: `all`, the window's name, `|ay| 2–4 m/s²`,
    /// `speed 20–30 m/s`, and an open band `|ay| ≥ 8 m/s²` (not `8–inf`).
    pub fn label(&self) -> String {
        let band = |lo: f64, hi: f64| {
            if hi.is_finite() {
                format!("{lo}–{hi}")
            } else {
                format!("≥ {lo}")
            }
        };
        match self {
            Part::All => "all".into(),
            Part::Window(w) => w.label().into(),
            Part::Ay { lo, hi } => format!("|ay| {} m/s²", band(*lo, *hi)),
            Part::Speed { lo, hi } => format!("speed {} m/s", band(*lo, *hi)),
        }
    }

    /// Its place in a report's lists: all, the windows in time, the |ay|
    /// bands, then the speed bands, each by its lower edge (a campaign
    /// pools runs whose bands appear in any order).
    pub fn order(&self) -> (u8, f64) {
        match *self {
            Part::All => (0, 0.0),
            Part::Window(w) => (1, w.centre()),
            Part::Ay { lo, .. } => (2, lo),
            Part::Speed { lo, .. } => (3, lo),
        }
    }

    /// The axis of the gap map it lies on; `None` for [`Part::All`].
    pub fn axis(&self) -> Option<PartAxis> {
        match self {
            Part::All => None,
            Part::Window(_) => Some(PartAxis::Time),
            Part::Ay { .. } => Some(PartAxis::Ay),
            Part::Speed { .. } => Some(PartAxis::Speed),
        }
    }
}

/// Where a record's samples lie on each axis of the gap map: their time
/// after the input starts (s), their |ay| (m/s²) and their speed (m/s). A
/// part is drawn at its samples' mean level ([`Levels::mean`]), not at its
/// band's centre: runs at 12 and at 18 m/s share the band 10–20 m/s, and
/// the map must show where in it the gap grows.
#[derive(Debug, Clone, Copy)]
pub struct Levels<'a> {
    t: &'a [f64],
    /// When the input starts, s ([`input_start`]; the record's end where
    /// there is none, as [`window_samples`] splits it).
    start: f64,
    ay: &'a [f64],
    speed: &'a [f64],
}

impl<'a> Levels<'a> {
    /// The levels of a record: sample times, steer (for the input's start),
    /// the lateral acceleration the regimes read and the speed.
    pub fn new(t: &'a [f64], steer: &[f64], ay: &'a [f64], speed: &'a [f64]) -> Self {
        let start = input_start(t, steer).unwrap_or(t[t.len() - 1]);
        Self {
            t,
            start,
            ay,
            speed,
        }
    }

    /// Sample `i`'s level on `axis`.
    pub fn at(&self, axis: PartAxis, i: usize) -> f64 {
        match axis {
            PartAxis::Time => self.t[i] - self.start,
            PartAxis::Ay => self.ay[i].abs(),
            PartAxis::Speed => self.speed[i],
        }
    }

    /// The mean level of samples `idx` on `part`'s axis; `None` for
    /// [`Part::All`] or no samples.
    pub fn mean(&self, part: Part, idx: &[usize]) -> Option<f64> {
        let axis = part.axis()?;
        (!idx.is_empty())
            .then(|| idx.iter().map(|&i| self.at(axis, i)).sum::<f64>() / idx.len() as f64)
    }
}

impl std::fmt::Display for Part {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.label())
    }
}

impl Serialize for Part {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.label())
    }
}

fn std_dev(v: &[f64]) -> f64 {
    let m = v.iter().sum::<f64>() / v.len().max(1) as f64;
    (v.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / v.len().max(1) as f64).sqrt()
}

/// How a channel's high-frequency scatter was estimated ([`scatter_by`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Scatter {
    /// The standard deviation over the window before the input.
    BeforeInput,
    /// The robust second differences: the window before the input holds
    /// motion.
    SecondDifferences,
    /// The robust second differences: no window before the input.
    NoWindow,
    /// The first differences over √2 (an upper bound): too few samples,
    /// or a channel whose second differences are mostly zero.
    FirstDifferences,
}

/// A window before the input whose standard deviation exceeds this multiple
/// of the robust second-difference scatter holds motion, not only noise.
pub(crate) const MOTION: f64 = 1.5;

/// A measured channel's high-frequency scatter: the standard deviation over
/// the samples `pre` before the input (ten or more), else the robust
/// scatter of its second differences ([`second_difference_scatter`]).
pub(crate) fn scatter(pre: &[usize], measured: &[f64]) -> f64 {
    scatter_by(pre, measured).0
}

/// [`scatter`] and how it was estimated. A window before the input is
/// quiet in a step-steer programme, but a hand-driven log starts by pulling
/// away and turning out of the pits: where its standard deviation exceeds
/// [`MOTION`] times the robust scatter of the second differences
/// ([`second_difference_scatter`]), the window holds motion and the second
/// differences are the scatter.
pub(crate) fn scatter_by(pre: &[usize], measured: &[f64]) -> (f64, Scatter) {
    if pre.len() >= 10 {
        let before = std_dev(&pre.iter().map(|&i| measured[i]).collect::<Vec<_>>());
        let robust = second_difference_scatter(measured);
        return if before > MOTION * robust {
            (robust, Scatter::SecondDifferences)
        } else {
            (before, Scatter::BeforeInput)
        };
    }
    // Without a window, the second differences: the first differences'
    // deviation over √2 holds a smooth run's own motion (a segment of a
    // slow lap read 0.0052 rad/s of yaw "noise", 0.0030 of it its turns).
    let robust = second_difference_scatter(measured);
    if robust > 0.0 {
        return (robust, Scatter::NoWindow);
    }
    let d: Vec<f64> = measured.windows(2).map(|w| w[1] - w[0]).collect();
    (std_dev(&d) / 2f64.sqrt(), Scatter::FirstDifferences)
}

/// The standard deviation of white noise on `x` from its second
/// differences, robustly: `1.4826·MAD(Δ²x)/√6` (white noise of variance σ²
/// has second differences of variance 6σ², and 1.4826·MAD estimates a
/// Gaussian's standard deviation). A signal sampled fast against its
/// bandwidth barely moves its second differences, and the median absolute
/// deviation ignores the spikes and the fast stretches that do (Hampel
/// 1974). NaN on fewer than three samples.
pub(crate) fn second_difference_scatter(x: &[f64]) -> f64 {
    if x.len() < 3 {
        return f64::NAN;
    }
    let mut d: Vec<f64> = x.windows(3).map(|w| w[2] - 2.0 * w[1] + w[0]).collect();
    let median = crate::measured::clean::midpoint_median;
    let m = median(&mut d);
    let mut dev: Vec<f64> = d.iter().map(|v| (v - m).abs()).collect();
    1.4826 * median(&mut dev) / 6f64.sqrt()
}

/// Shortest time the steer must hold its initial value before an input
/// for the run's time windows to be read as times after that input, s:
/// the initial window a step's metrics take their initial values over
/// ([`crate::metrics::MetricSettings`]'s default `pre_window`). A run
/// that starts in the middle of its driving (a piece of a lap, an oval's
/// steady turn with its corrections) has no input to time from: its
/// samples are pooled by regime only.
pub const STEADY_BEFORE_INPUT: f64 = 0.5;

/// When the input starts: where the steer first leaves its initial value
/// by more than 5 % of its largest excursion (and 1 mrad); None where it
/// never does.
fn input_start(t: &[f64], steer: &[f64]) -> Option<f64> {
    let d0 = steer[0];
    let excursion = steer.iter().map(|d| (d - d0).abs()).fold(0.0, f64::max);
    let threshold = (0.05 * excursion).max(1e-3);
    steer
        .iter()
        .position(|d| (d - d0).abs() > threshold)
        .map(|i| t[i])
}

/// Whether the run has an input its time windows can be timed from: the
/// steer held at its initial value for [`STEADY_BEFORE_INPUT`], then left.
pub fn timed_from_an_input(t: &[f64], steer: &[f64]) -> bool {
    input_start(t, steer).is_some_and(|s| s - t[0] >= STEADY_BEFORE_INPUT)
}

/// The samples of each time window ([`Window::ALL`], in order): before the
/// input, its first 0.5 s, 0.5–2 s, the rest ([`input_start`]; without an
/// input every sample is before it). Only a run
/// [`timed_from_an_input`] reads them as times after an input; the window
/// before it serves any run's noise floor.
pub fn window_samples(t: &[f64], steer: &[f64]) -> Vec<(Part, Vec<usize>)> {
    let start = input_start(t, steer).unwrap_or(t[t.len() - 1]);
    let bounds = [
        (f64::NEG_INFINITY, start),
        (start, start + 0.5),
        (start + 0.5, start + 2.0),
        (start + 2.0, f64::INFINITY),
    ];
    Window::ALL
        .into_iter()
        .zip(bounds)
        .map(|(w, (lo, hi))| {
            let idx = (0..t.len()).filter(|&i| t[i] >= lo && t[i] < hi).collect();
            (Part::Window(w), idx)
        })
        .collect()
}

/// The samples of each regime that has any: |ay| in bands of 2 m/s² (the
/// last open), then speed in bands of 10 m/s up to the largest speed.
pub fn regime_samples(ay: &[f64], speed: &[f64]) -> Vec<(Part, Vec<usize>)> {
    let n = ay.len();
    let mut out = Vec::new();
    for (lo, hi) in [
        (0.0, 2.0),
        (2.0, 4.0),
        (4.0, 6.0),
        (6.0, 8.0),
        (8.0, f64::INFINITY),
    ] {
        let idx: Vec<usize> = (0..n)
            .filter(|&i| ay[i].abs() >= lo && ay[i].abs() < hi)
            .collect();
        if !idx.is_empty() {
            out.push((Part::Ay { lo, hi }, idx));
        }
    }
    let vmax = speed.iter().copied().fold(0.0, f64::max);
    let mut lo = 0.0;
    while lo <= vmax {
        let hi = lo + 10.0;
        let idx: Vec<usize> = (0..n)
            .filter(|&i| speed[i] >= lo && speed[i] < hi)
            .collect();
        if !idx.is_empty() {
            out.push((Part::Speed { lo, hi }, idx));
        }
        lo += 10.0;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_record_splits_into_every_window_and_band_with_their_labels() {
        // A record that visits every window, every |ay| band and three
        // speed bands.
        let t: Vec<f64> = (0..1200).map(|i| 0.01 * i as f64).collect();
        let steer: Vec<f64> = t
            .iter()
            .map(|&t| if t < 1.0 { 0.0 } else { 0.02 })
            .collect();
        let ay = t.clone();
        let speed: Vec<f64> = t.iter().map(|&t| 5.0 + 2.0 * t).collect();
        let windows = window_samples(&t, &steer);
        let regimes = regime_samples(&ay, &speed);
        let parts: Vec<Part> = windows.iter().chain(&regimes).map(|p| p.0).collect();
        assert_eq!(parts.len(), 4 + 5 + 3);
        assert_eq!(parts[0], Part::Window(Window::BeforeInput));
        // The input starts at 1 s: 100 samples before it, 50 in its first
        // half second, 150 from 0.5 to 2 s, the rest later.
        let counts: Vec<usize> = windows.iter().map(|w| w.1.len()).collect();
        assert_eq!(counts, [100, 50, 150, 900]);
        assert_eq!(
            parts[8],
            Part::Ay {
                lo: 8.0,
                hi: f64::INFINITY
            }
        );
        assert_eq!(parts[8].axis(), Some(PartAxis::Ay));
        // Each part's mean level on its axis: the speed band 0–10 m/s
        // holds t < 2.5 s, speeds 5–9.98 m/s, mean 7.49, not the band's
        // centre 5;
        // the |ay| band ≥ 8 holds |ay| 8–11.99, mean 9.995; the window
        // before the input its times 1 s before to 0.01 s before it.
        let levels = Levels::new(&t, &steer, &ay, &speed);
        let level =
            |k: usize| levels.mean(parts[k], &windows.iter().chain(&regimes).nth(k).unwrap().1);
        assert!((level(9).unwrap() - 7.49).abs() < 1e-9, "{:?}", level(9));
        assert!((level(8).unwrap() - 9.995).abs() < 1e-9, "{:?}", level(8));
        assert!((level(0).unwrap() + 0.505).abs() < 1e-9, "{:?}", level(0));
        assert_eq!(levels.mean(Part::All, &[0, 1]), None);
        assert_eq!(parts[8].label(), "|ay| ≥ 8 m/s²");
        assert_eq!(parts[9], Part::Speed { lo: 0.0, hi: 10.0 });
        assert_eq!(parts[9].label(), "speed 0–10 m/s");
        assert_eq!(parts[4].label(), "|ay| 0–2 m/s²");
        assert_eq!(parts[1].label(), "first 0.5 s of the input");
        // Every sample is in exactly one window, one |ay| band and one speed
        // band.
        let total = |v: &[(Part, Vec<usize>)]| v.iter().map(|p| p.1.len()).sum::<usize>();
        assert_eq!(total(&windows), t.len());
        assert_eq!(total(&regimes), 2 * t.len());
    }

    /// A record of `n` samples at 100 Hz: white Gaussian noise of standard
    /// deviation `sigma` on `signal(t)`.
    fn record(n: usize, sigma: f64, signal: impl Fn(f64) -> f64) -> Vec<f64> {
        use rand::SeedableRng;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        (0..n)
            .map(|i| signal(0.01 * i as f64) + sigma * crate::identify::data::gauss(&mut rng))
            .collect()
    }

    #[test]
    fn the_robust_second_differences_measure_white_noise_on_a_smooth_signal() {
        // 0.002 of noise on a 0.3 amplitude, 0.5 Hz yaw rate: within 3 %.
        let sine = |t: f64| 0.3 * (std::f64::consts::TAU * 0.5 * t).sin();
        let x = record(10_000, 0.002, sine);
        let s = second_difference_scatter(&x);
        assert!((s / 0.002 - 1.0).abs() < 0.03, "{s}");
        // One spike in a hundred samples moves it by little; the standard
        // deviation of the first differences by a factor of more than 3.
        let mut spiked = x.clone();
        for v in spiked.iter_mut().step_by(100) {
            *v += 0.1;
        }
        let s = second_difference_scatter(&spiked);
        assert!((s / 0.002 - 1.0).abs() < 0.06, "{s}");
        assert!(second_difference_scatter(&[1.0, 2.0]).is_nan());
    }

    #[test]
    fn a_window_before_the_input_that_holds_motion_gives_way_to_the_second_differences() {
        let pre: Vec<usize> = (0..500).collect();
        // Quiet before the input: its standard deviation, as before.
        let quiet = record(2000, 0.002, |t| if t < 5.0 { 0.0 } else { 0.2 });
        let (s, how) = scatter_by(&pre, &quiet);
        assert_eq!(how, Scatter::BeforeInput);
        assert!((s / 0.002 - 1.0).abs() < 0.1, "{s}");
        // Pulling away and turning out of the pits before the steer input:
        // a 0.01 rad/s, 0.3 Hz wander that the standard deviation takes for
        // noise (0.0073), and the second differences do not.
        let moving = record(2000, 0.002, |t| {
            0.01 * (std::f64::consts::TAU * 0.3 * t).sin()
        });
        let before = std_dev(&moving[..500]);
        assert!(before > 3.0 * 0.002, "{before}");
        let (s, how) = scatter_by(&pre, &moving);
        assert_eq!(how, Scatter::SecondDifferences);
        assert!((s / 0.002 - 1.0).abs() < 0.06, "{s}");
        // Without a window before the input: the second differences too,
        // which the wander does not move (the first differences' deviation
        // over √2 holds some of it).
        let (s, how) = scatter_by(&[], &moving);
        assert_eq!(how, Scatter::NoWindow);
        assert!((s / 0.002 - 1.0).abs() < 0.06, "{s}");
        assert_eq!(scatter_by(&[], &[1.0, 2.0]).1, Scatter::FirstDifferences);
    }

    #[test]
    fn parts_are_listed_windows_then_ay_then_speed_each_by_its_lower_edge() {
        let mut parts = [
            Part::Speed { lo: 20.0, hi: 30.0 },
            Part::Ay { lo: 2.0, hi: 4.0 },
            Part::Speed { lo: 10.0, hi: 20.0 },
            Part::Window(Window::Later),
            Part::All,
            Part::Ay { lo: 0.0, hi: 2.0 },
            Part::Window(Window::BeforeInput),
        ];
        parts.sort_by(|a, b| {
            let (ka, kb) = (a.order(), b.order());
            ka.0.cmp(&kb.0).then(ka.1.total_cmp(&kb.1))
        });
        let labels: Vec<String> = parts.iter().map(Part::label).collect();
        assert_eq!(
            labels,
            [
                "all",
                Window::BeforeInput.label(),
                Window::Later.label(),
                "|ay| 0–2 m/s²",
                "|ay| 2–4 m/s²",
                "speed 10–20 m/s",
                "speed 20–30 m/s"
            ]
        );
    }
}
