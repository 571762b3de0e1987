//! Where a step steer's metrics describe something other than the
//! handling response GB/T 6323 and ISO 7401 define them for, said as
//! warnings beside the table rather than left for the reader to notice:
//! a car sliding past its grip, a response that more than doubles its
//! steady value, a step at a crawl.
//!
//! The limits are the project's reading of what the standards test:
//! ISO 7401 (2011) runs its step at 80 km/h to a lateral acceleration of
//! 4 m/s², in the range where the sideslip stays within a few degrees;
//! a steady sideslip beyond [`SLIDING_SIDESLIP`] is a slide, a yaw-rate
//! overshoot beyond [`SPIN_OVERSHOOT`] a car losing and regaining grip,
//! and below [`CRAWL_SPEED`] the yaw rate follows the steer's geometry
//! (`r ≈ u·δ/l`) with no dynamics for the times to measure. A sideslip is
//! a slide only where the tyres are near their grip: at a crawl a large
//! steer turns the car about a point near the line of its rear axle, and
//! its sideslip (`β ≈ b·δ/l`) passes 10° with the tyres barely loaded
//! ([`KINEMATIC_GRIP`]). Units: rad, m/s and % as in [`StepMetrics`].
//!
//! A schedule is held to what a car on the road can drive
//! ([`schedule_applicability`]): the 2-DOF model takes the speed as an
//! input, so a change faster than the road's `μ·g` would run unchecked;
//! its steer to what a steering system can do, a road-wheel rate within
//! [`STEER_RATE`]; and a run that starts with its steer already applied
//! starts with an instant step from straight running.

use super::StepMetrics;

/// The change of speed over a measured step, as a share of its median
/// speed, beyond which the metrics mix speeds: the standards hold the
/// test speed constant, and a steady yaw-rate gain (`u/(l + K·u²)`)
/// moves by about as much as the speed does.
pub const VARYING_SPEED: f64 = 0.1;
/// The steady sideslip beyond which the car is sliding, rad (10°).
pub const SLIDING_SIDESLIP: f64 = 10.0 * std::f64::consts::PI / 180.0;
/// The share of the tyres' grip below which a sideslip beyond
/// [`SLIDING_SIDESLIP`] is no slide. In a steady turn each axle's lateral
/// force over its load is `ay/g`, so `|ay|/(μ·g)` is the grip the tyres
/// use; at under half of it every tyre curve is still short of its peak,
/// its slip angle a few degrees, and the rest of the sideslip is the
/// turn's geometry (`b·r/u`, which only a crawl makes large).
pub const KINEMATIC_GRIP: f64 = 0.5;
/// The grip a measured run's crawl is judged against, m/s² (0.3 g): below
/// any paved road's, wet or dry (only snow and ice are below it), so that
/// a crawl using under [`KINEMATIC_GRIP`] of it uses under that share of
/// any such road's. No channel of a run measures its tyres' grip.
pub const PAVED_ROAD_GRIP: f64 = 0.3 * crate::constants::G;

/// What a sideslip is judged against: the tyres' own grip (`μ·g` of the
/// lower axle at static load, m/s²), or, for a measured run,
/// [`PAVED_ROAD_GRIP`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Grip {
    /// The tyres' grip on this road, m/s².
    Tyres(f64),
    /// A paved road's least ([`PAVED_ROAD_GRIP`]).
    PavedRoad,
}

impl Grip {
    /// The grip, m/s².
    pub fn accel(self) -> f64 {
        match self {
            Grip::Tyres(g) => g,
            Grip::PavedRoad => PAVED_ROAD_GRIP,
        }
    }

    /// Whose grip, in a sentence: "their grip" or the road's.
    fn words(self) -> &'static str {
        match self {
            Grip::Tyres(_) => "their grip",
            Grip::PavedRoad => {
                "the grip of any paved road, wet or dry (0.3 g; the run does not measure its tyres')"
            }
        }
    }
}

/// The yaw-rate overshoot beyond which the response is no handling
/// response, %: the peak more than twice the steady value.
pub const SPIN_OVERSHOOT: f64 = 100.0;
/// The speed below which a step steer measures no dynamics, m/s
/// (18 km/h).
pub const CRAWL_SPEED: f64 = 5.0;
/// The fastest road-wheel steer rate a schedule is taken to mean, rad/s:
/// steering robots drive the handwheel at up to about 3,000°/s (ESC's
/// sine with dwell needs about 1,200°/s), about 3.5 rad/s at the road
/// wheels over a 15:1 ratio; 5 rad/s leaves room for a quick rack.
pub const STEER_RATE: f64 = 5.0;

/// The warnings on metrics `m` of a step steer at `speed` (m/s, where
/// known): one sentence each, empty where the metrics are what the
/// standards mean. A measured run's grip is not known:
/// [`applicability_with_grip`] for a run whose tyres are.
pub fn applicability(m: &StepMetrics, speed: Option<f64>) -> Vec<String> {
    applicability_with_grip(m, speed, None, None)
}

/// [`applicability`] of a measured run, whose grip no channel gives: at a
/// crawl (below [`CRAWL_SPEED`]) a sideslip beyond 10° is judged against
/// [`Grip::PavedRoad`], and said so; faster, a sideslip beyond 10° is a
/// slide on any road. A yaw-rate overshoot beyond [`SPIN_OVERSHOOT`] is
/// judged by the largest |β| of the run (`largest_sideslip`, rad, where it
/// logs `beta`): a spinning car's sideslip grows past a slide's.
pub fn applicability_measured(
    m: &StepMetrics,
    speed: Option<f64>,
    largest_sideslip: Option<f64>,
) -> Vec<String> {
    let crawl = speed.is_some_and(|u| u.abs() < CRAWL_SPEED);
    let evidence = Some(largest_sideslip.map_or(Overshoot::NoSideslip, Overshoot::Sideslip));
    applicability_with_grip(m, speed, crawl.then_some(Grip::PavedRoad), evidence)
}

/// What tells a yaw-rate overshoot beyond [`SPIN_OVERSHOOT`] from a spin.
/// A 2-DOF car's yaw damping falls as 1/u while its stiffness (from the
/// tyres) does not: at high speed a step rings, with every tyre on the
/// linear part of its curve and the car nowhere near sliding.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Overshoot {
    /// The most of its grip either axle used anywhere in the run (a
    /// simulation's, whose tyres are known): below [`KINEMATIC_GRIP`] no
    /// tyre passed the linear part of its curve.
    GripUsed(f64),
    /// The largest |β| of a measured run, rad: within
    /// [`SLIDING_SIDESLIP`] the car never slid, so it did not spin.
    Sideslip(f64),
    /// A measured run without `beta`: nothing tells the two apart.
    NoSideslip,
}

/// [`applicability`] for tyres that grip to `grip` on this road (`μ·g`,
/// m/s², the lower axle's peak at static load, road friction included):
/// a sideslip beyond 10° with the tyres at under [`KINEMATIC_GRIP`] of it
/// is said as the kinematic turn it is ([`kinematic_turn`]), not a slide;
/// and a yaw-rate overshoot beyond [`SPIN_OVERSHOOT`] where the run shows
/// no slide (`overshoot`: no axle used more than [`KINEMATIC_GRIP`] of its
/// grip anywhere in it, or its sideslip stayed within [`SLIDING_SIDESLIP`])
/// as the lightly damped response it is, not a spin.
pub fn applicability_with_grip(
    m: &StepMetrics,
    speed: Option<f64>,
    grip: Option<Grip>,
    overshoot: Option<Overshoot>,
) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(u) = speed.filter(|u| u.abs() < CRAWL_SPEED) {
        out.push(format!(
            "the step is at {:.2} m/s, below {CRAWL_SPEED} m/s (18 km/h): at a crawl the yaw rate follows the steer's geometry, and neither the response times nor the total variances (E_r, E_ay, Er: the lags of a geometric turn) measure handling (ISO 7401 steps at 80 km/h, as Wang & Liang's validation of Er does)",
            u.abs()
        ));
    }
    for (name, time) in [
        ("yaw rate", Some(m.yaw_rate_response_time)),
        ("lateral acceleration", m.ay_response_time),
    ] {
        if let Some(t) = time.filter(|t| *t <= 0.0) {
            out.push(format!(
                "the {name} reaches 90 % of its step {} s before the steer reaches half of its own (response time {} s): a response that leads the steer is a crawl's geometry or a record whose channels are not aligned in time, not the lag GB/T 6323 and ISO 7401 measure",
                crate::format::significant(-t, 2),
                crate::format::significant(t, 2)
            ));
        }
    }
    if let Some(beta) = m.beta_steady.filter(|b| b.abs() > SLIDING_SIDESLIP) {
        // In the steady turn both axles use |ay|/(μ·g) of their grip.
        let share = grip
            .zip(m.ay_steady)
            .map(|(g, ay)| (ay.abs() / g.accel(), g));
        out.push(match (share.filter(|s| s.0 < KINEMATIC_GRIP), speed) {
            (Some((share, g)), Some(u)) => format!(
                "the steady sideslip is {:.1}°, beyond 10°, {}",
                beta.to_degrees(),
                kinematic_turn(share, g.words(), u, m.steer_step)
            ),
            _ => format!(
                "the steady sideslip is {:.1}°, beyond 10°: the car is sliding, past its grip, and the step-steer metrics, defined for a handling response below the limit, do not apply (a smaller steer step measures the handling)",
                beta.to_degrees()
            ),
        });
    }
    if m.yaw_rate_overshoot > SPIN_OVERSHOOT {
        out.push(overshoot_words(m.yaw_rate_overshoot, speed, overshoot));
    }
    out
}

/// The warning on a yaw-rate overshoot of `percent` beyond
/// [`SPIN_OVERSHOOT`] at `speed` (m/s), judged by `evidence`.
fn overshoot_words(percent: f64, speed: Option<f64>, evidence: Option<Overshoot>) -> String {
    let at = speed.map_or_else(String::new, |u| format!(", here {:.1} m/s", u.abs()));
    let ringing =
        "the metrics still describe it, a response far from the standards' well-damped steps";
    let spin = format!("the yaw rate overshoots its steady value by {percent:.0} %: a peak more than twice the steady value is a car losing and regaining grip or spinning, not the handling response the metrics describe");
    match evidence {
        Some(Overshoot::GripUsed(share)) if share < KINEMATIC_GRIP => format!(
            "the yaw rate overshoots its steady value by {percent:.0} % with the tyres using no more than {:.0} % of their grip: no spin, but a lightly damped linear response (the yaw damping falls with speed{at}); {ringing}",
            100.0 * share
        ),
        Some(Overshoot::Sideslip(beta)) if beta <= SLIDING_SIDESLIP => format!(
            "the yaw rate overshoots its steady value by {percent:.0} % with the sideslip within ±{:.1}° throughout, short of the 10° of a sliding car: no spin, but a lightly damped response (the yaw damping falls with speed{at}); {ringing}",
            beta.to_degrees()
        ),
        Some(Overshoot::NoSideslip) => format!(
            "{spin}; or, at speed, a lightly damped response that never left the tyres' linear range: the run has no `beta` to tell them apart"
        ),
        _ => spin,
    }
}

/// Why a sideslip beyond 10° is no slide, where the tyres use `share`
/// (below [`KINEMATIC_GRIP`]) of the grip `whose` names at `speed` (m/s) and
/// road-wheel steer `steer` (rad): the end of a sentence that names the
/// sideslip. A slow car's sideslip is the geometry of its turn, so what
/// limits the turn is the steer, and the lock beside it says how close.
pub(crate) fn kinematic_turn(share: f64, whose: &str, speed: f64, steer: f64) -> String {
    format!(
        "but no slide: the tyres use no more than {:.0} % of {whose}, and at {:.2} m/s the {:.1}° steer (a car's lock is about 35–40° at the road wheels) turns the car about a point near the line of its rear axle, where the sideslip is the turn's geometry (β ≈ b·δ/l), not the tyres sliding: the response is kinematic, limited by the steer, not by grip",
        100.0 * share,
        speed.abs(),
        steer.to_degrees()
    )
}

/// The warning on a measured step whose speeds, sorted, are `sorted`
/// (m/s): where its 5th and 95th percentiles lie further apart than
/// [`VARYING_SPEED`] of the median (percentiles, so that a noise spike
/// is no change of speed); `rising` says which way it went (its last
/// tenth against its first).
pub fn varying_speed(sorted: &[f64], rising: bool) -> Option<String> {
    let at = |q: f64| crate::measured::clean::quantile(sorted, q);
    let (lo, median, hi) = (at(0.05)?, at(0.5)?, at(0.95)?);
    ((hi - lo) > VARYING_SPEED * median.abs()).then(|| {
        format!(
            "the speed {} over the measured piece, between {lo:.2} and {hi:.2} m/s (5th to 95th percentile; {:.0} % of its median {median:.2} m/s): GB/T 6323 and ISO 7401 hold the speed constant, and the metrics here mix the responses of several speeds",
            if rising { "rises" } else { "falls" },
            100.0 * (hi - lo) / median.abs()
        )
    })
}

/// The pieces of `x` given at breakpoints `t` (linear between) that
/// change faster than `limit`: the steepest (its rate and the times it
/// runs between), how many there are and how long they last in all.
fn steeper_than(t: &[f64], x: &[f64], limit: f64) -> Option<Steep> {
    let over: Vec<(f64, f64, f64)> = t
        .windows(2)
        .zip(x.windows(2))
        .map(|(t, x)| ((x[1] - x[0]) / (t[1] - t[0]), t[0], t[1]))
        .filter(|p| p.0.abs() > limit)
        .collect();
    let &(rate, t0, t1) = over.iter().max_by(|a, b| a.0.abs().total_cmp(&b.0.abs()))?;
    Some(Steep {
        rate,
        t0,
        t1,
        pieces: over.len(),
        time: over.iter().map(|p| p.2 - p.1).sum(),
    })
}

/// The pieces of a schedule steeper than a limit ([`steeper_than`]).
struct Steep {
    /// The steepest piece's rate, unit of `x` per s.
    rate: f64,
    /// Its start, s.
    t0: f64,
    /// Its end, s.
    t1: f64,
    /// How many pieces exceed the limit.
    pieces: usize,
    /// Their time in all, s.
    time: f64,
}

impl Steep {
    /// `from t = 1 s to 1.01 s`, and for several pieces how many and how
    /// long in all.
    fn when(&self) -> String {
        let (t0, t1) = (self.t0, self.t1);
        if self.pieces == 1 {
            format!("from t = {t0} s to {t1} s")
        } else {
            format!(
                "from t = {t0} s to {t1} s (the steepest of {} pieces beyond the limit, {:.2} s in all)",
                self.pieces, self.time
            )
        }
    }
}

/// The warning on a step steer of `amplitude` (rad) that rises in
/// `rise_time` (s, 0–100 %) faster than [`STEER_RATE`]: at 0 an instant
/// step, an infinite steer rate. None where a steering system drives it.
pub fn step_rate_applicability(amplitude: f64, rise_time: f64) -> Option<String> {
    let rate = amplitude.abs() / rise_time;
    if rate <= STEER_RATE {
        return None;
    }
    let how = if rise_time <= 0.0 {
        "rise_time = 0: an instant step, an infinite steer rate".to_string()
    } else {
        format!(
            "the step of {:.3} rad rises in {} s, {:.1} rad/s ({:.0}°/s at the road wheels)",
            amplitude.abs(),
            rise_time,
            rate,
            rate.to_degrees()
        )
    };
    Some(format!(
        "{how}, faster than a steering system turns the wheels (up to about {STEER_RATE} rad/s; a steering robot's 3,000°/s at the handwheel is about 3.5 rad/s; GB/T 6323 and ISO 7401 time a step of 0.1–0.2 s): the response times measure an input no driver or robot can give"
    ))
}

/// The warnings on a schedule (`t`, `steer`, `speed` at breakpoints,
/// linear between) for a car whose tyres on this road grip to `mu`: its
/// speed's ([`speed_schedule`]), a steer rate above [`STEER_RATE`], and a
/// first steer other than 0 (the run starts from straight running).
pub fn schedule_applicability(t: &[f64], steer: &[f64], speed: &[f64], mu: f64) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(steep) = steeper_than(t, steer, STEER_RATE) {
        let rate = steep.rate;
        out.push(format!(
            "the steer changes at {:.1} rad/s ({:.0}°/s at the road wheels) {}, faster than a steering system turns the wheels (up to about {STEER_RATE} rad/s; a steering robot's 3,000°/s at the handwheel is about 3.5 rad/s): the run shows a step no driver or robot can steer",
            rate.abs(),
            rate.abs().to_degrees(),
            steep.when()
        ));
    }
    if let (Some(&d0), Some(&t0)) = (steer.first(), t.first()) {
        if d0 != 0.0 {
            out.push(format!(
                "the schedule starts with steer = {d0} rad at t = {t0} s, but the run starts from straight running (no yaw rate, no sideslip): it opens with an instant steer step; start the steer at 0 and ramp it"
            ));
        }
    }
    out.extend(speed_schedule(t, speed, mu));
    out
}

/// The warnings on a speed schedule (`t`, `speed` at breakpoints, linear
/// between) for a car whose tyres on this road grip to `mu` (the peak
/// friction coefficient at static load, road friction scale included): a
/// speed change faster than `μ·g` (the 2-DOF model takes the speed as
/// given, so nothing stops it), and the time spent below [`CRAWL_SPEED`].
/// Empty where the schedule is one the car can drive.
fn speed_schedule(t: &[f64], speed: &[f64], mu: f64) -> Vec<String> {
    let mut out = Vec::new();
    let grip = mu * crate::constants::G;
    if let Some(steep) = steeper_than(t, speed, grip) {
        let rate = steep.rate;
        out.push(format!(
            "the speed {} at {:.1} m/s² ({:.1} g) {}, more than the tyres' grip on this road gives (μ·g = {grip:.1} m/s²): the 2-DOF model takes the speed as given, so the run goes where tyres on this road could not take the car",
            if rate < 0.0 { "falls" } else { "rises" },
            rate.abs(),
            rate.abs() / crate::constants::G,
            steep.when()
        ));
    }
    // Time below the crawl speed, on the piecewise linear speed.
    let crawl: f64 = t
        .windows(2)
        .zip(speed.windows(2))
        .map(|(t, u)| {
            let (lo, hi) = (u[0].abs().min(u[1].abs()), u[0].abs().max(u[1].abs()));
            let share = if hi < CRAWL_SPEED {
                1.0
            } else if lo >= CRAWL_SPEED {
                0.0
            } else {
                (CRAWL_SPEED - lo) / (hi - lo)
            };
            share * (t[1] - t[0])
        })
        .sum();
    if crawl > 0.0 {
        out.push(format!(
            "the schedule spends {crawl:.1} s below {CRAWL_SPEED} m/s (18 km/h): at a crawl the yaw rate follows the steer's geometry, with no handling dynamics to show"
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Metrics of a well-behaved step: 0.5° sideslip, 12 % overshoot.
    fn moderate() -> StepMetrics {
        StepMetrics {
            steer_step: 0.02,
            time_zero: 1.0,
            yaw_rate_response_time: 0.15,
            yaw_rate_peak_time: Some(0.3),
            yaw_rate_overshoot: 12.0,
            ay_response_time: Some(0.2),
            yaw_rate_gain: 0.3,
            yaw_rate_steady: 0.006,
            ay_steady: Some(2.0),
            beta_steady: Some(-0.5_f64.to_radians()),
            tb: Some(0.15),
            yaw_rate_total_variance: 0.2,
            ay_total_variance: Some(0.2),
            er: Some(0.3),
            settled: true,
            yaw_rate_noise: 0.0,
            yaw_rate_peak_threshold: 1.0,
            filter_hz: None,
        }
    }

    #[test]
    fn a_step_below_the_limit_at_test_speed_gets_no_warning() {
        assert!(applicability(&moderate(), Some(22.2)).is_empty());
        assert!(applicability(&moderate(), None).is_empty());
    }

    #[test]
    fn a_slide_a_spin_and_a_crawl_are_each_said() {
        let sliding = StepMetrics {
            beta_steady: Some(-18.8_f64.to_radians()),
            ..moderate()
        };
        let w = applicability(&sliding, Some(22.2));
        assert_eq!(w.len(), 1);
        assert!(
            w[0].starts_with("the steady sideslip is -18.8°, beyond 10°"),
            "{w:?}"
        );
        let spinning = StepMetrics {
            yaw_rate_overshoot: 503.6,
            ..moderate()
        };
        let w = applicability(&spinning, Some(22.2));
        assert!(
            w[0].contains("overshoots its steady value by 504 %"),
            "{w:?}"
        );
        let w = applicability(&moderate(), Some(0.5));
        assert!(
            w[0].starts_with("the step is at 0.50 m/s, below 5 m/s"),
            "{w:?}"
        );
        // The limits themselves pass: 10° and 100 % are still a response.
        let edge = StepMetrics {
            beta_steady: Some(SLIDING_SIDESLIP),
            yaw_rate_overshoot: SPIN_OVERSHOOT,
            ..moderate()
        };
        assert!(applicability(&edge, Some(CRAWL_SPEED)).is_empty());
    }

    #[test]
    fn a_step_faster_than_any_steering_is_said_and_an_instant_one_named() {
        // The bundled 1° step in 0.1 s, and a 17° one: a steering drives them.
        assert_eq!(step_rate_applicability(0.0174533, 0.1), None);
        assert_eq!(step_rate_applicability(0.3, 0.1), None);
        let w = step_rate_applicability(0.7, 0.1).unwrap();
        assert!(w.starts_with("the step of 0.700 rad rises in 0.1 s, 7.0 rad/s (401°/s at the road wheels), faster than a steering system"), "{w}");
        let w = step_rate_applicability(0.0174533, 0.0).unwrap();
        assert!(
            w.starts_with("rise_time = 0: an instant step, an infinite steer rate, faster"),
            "{w}"
        );
    }

    #[test]
    fn an_overshoot_beyond_a_spins_is_judged_by_the_grip_used_or_the_sideslip() {
        let ringing = StepMetrics {
            yaw_rate_overshoot: 229.0,
            ..moderate()
        };
        let said = |e: Option<Overshoot>| applicability_with_grip(&ringing, Some(80.0), None, e);
        // The tyres at a third of their grip, or the car within 2.2° of
        // sideslip: no spin.
        let w = said(Some(Overshoot::GripUsed(0.35)));
        assert!(
            w[0].contains("using no more than 35 % of their grip: no spin"),
            "{w:?}"
        );
        let w = said(Some(Overshoot::Sideslip(2.2_f64.to_radians())));
        assert!(
            w[0].contains("with the sideslip within ±2.2° throughout"),
            "{w:?}"
        );
        assert!(!w[0].contains("spinning"), "{w:?}");
        // At the limits themselves (half the grip is used, 10° is a
        // slide's least) and beyond, or with nothing to judge by: a spin.
        for e in [
            Some(Overshoot::GripUsed(KINEMATIC_GRIP)),
            Some(Overshoot::Sideslip(SLIDING_SIDESLIP + 1e-9)),
            None,
        ] {
            let w = said(e);
            assert!(
                w[0].ends_with("not the handling response the metrics describe"),
                "{e:?}: {w:?}"
            );
        }
        // A measured run without `beta`: both readings are said.
        let w = said(Some(Overshoot::NoSideslip));
        assert!(
            w[0].contains("spinning") && w[0].contains("no `beta` to tell them apart"),
            "{w:?}"
        );
        // An overshoot within a response's is no warning whatever the evidence.
        assert!(applicability_with_grip(
            &moderate(),
            Some(80.0),
            None,
            Some(Overshoot::NoSideslip)
        )
        .is_empty());
    }

    #[test]
    fn a_sideslip_with_the_tyres_far_below_their_grip_is_said_as_a_kinematic_turn() {
        // 17.8° at 2 m/s after a 28.6° step, 0.78 m/s² steady.
        let slow = StepMetrics {
            steer_step: 0.5,
            beta_steady: Some(17.8_f64.to_radians()),
            ay_steady: Some(0.78),
            ..moderate()
        };
        let w = applicability_with_grip(&slow, Some(2.0), Some(Grip::Tyres(9.8)), None);
        assert!(
            w[1].starts_with("the steady sideslip is 17.8°, beyond 10°, but no slide: the tyres use no more than 8 % of their grip, and at 2.00 m/s the 28.6° steer"),
            "{w:?}"
        );
        // At half the grip and above, or with the grip unknown: a slide.
        for grip in [Some(1.56), None] {
            let w = applicability_with_grip(&slow, Some(2.0), grip.map(Grip::Tyres), None);
            assert!(w[1].contains("the car is sliding, past its grip"), "{w:?}");
        }
    }

    #[test]
    fn a_schedule_braking_past_the_roads_grip_or_crawling_is_said() {
        // 40 → 1 m/s in 0.5 s: 78 m/s², 8 g; then 6.5 s at 1 m/s plus the
        // last 0.064 s of the drop below 5 m/s.
        let (t, u) = ([0.0, 1.0, 1.5, 8.0], [40.0, 40.0, 1.0, 1.0]);
        let w = speed_schedule(&t, &u, 1.0);
        assert_eq!(w.len(), 2, "{w:?}");
        assert!(
            w[0].starts_with("the speed falls at 78.0 m/s² (8.0 g) from t = 1 s to 1.5 s, more than the tyres' grip on this road gives (μ·g = 9.8 m/s²)"),
            "{w:?}"
        );
        let crawl = 6.5 + 0.5 * 4.0 / 39.0;
        assert!(
            w[1].starts_with(&format!("the schedule spends {crawl:.1} s below 5 m/s")),
            "{w:?}"
        );
        // At μ·g and above the crawl speed: nothing to say.
        let g = crate::constants::G;
        assert!(speed_schedule(&[0.0, 1.0], &[20.0, 20.0 - g], 1.0).is_empty());
        // Two hard brakings and a launch: all three counted, the steepest
        // named.
        let (t, u) = (
            [0.0, 1.0, 2.0, 3.0, 3.5, 4.0],
            [40.0, 20.0, 20.0, 40.0, 10.0, 10.0],
        );
        let w = speed_schedule(&t, &u, 1.0);
        assert!(
            w[0].starts_with("the speed falls at 60.0 m/s² (6.1 g) from t = 3 s to 3.5 s (the steepest of 3 pieces beyond the limit, 2.50 s in all), more than"),
            "{w:?}"
        );
        // On ice the same 0.5 g braking is past the grip.
        let w = speed_schedule(&[0.0, 1.0], &[20.0, 20.0 - 0.5 * g], 0.3);
        assert!(
            w[0].starts_with("the speed falls at 4.9 m/s² (0.5 g)"),
            "{w:?}"
        );
    }

    #[test]
    fn a_measured_step_at_varying_speed_is_said_and_a_noise_spike_is_not() {
        // 20 → 25 m/s over the piece: 24 % of the median.
        let rising: Vec<f64> = (0..=100).map(|i| 20.0 + 0.05 * f64::from(i)).collect();
        let w = varying_speed(&rising, true).expect("a 24 % change is said");
        assert!(
            w.starts_with("the speed rises over the measured piece, between 20.25 and 24.75 m/s (5th to 95th percentile; 20 % of its median 22.50 m/s)"),
            "{w}"
        );
        assert!(varying_speed(&rising, false)
            .unwrap()
            .starts_with("the speed falls over"));
        // Constant 20 m/s with two samples of 40 (a spike): nothing.
        let mut spiky = vec![20.0; 100];
        spiky.extend([40.0, 40.0]);
        assert_eq!(varying_speed(&spiky, true), None);
        // 8.6 % is within the limit.
        let slow: Vec<f64> = (0..=100).map(|i| 20.0 + 0.02 * f64::from(i)).collect();
        assert_eq!(varying_speed(&slow, true), None);
        assert_eq!(varying_speed(&[], true), None);
    }

    #[test]
    fn a_steer_faster_than_a_steering_system_or_applied_at_the_start_is_said() {
        // 0 → 0.5 rad in 1 ms: 500 rad/s.
        let (t, u) = ([0.0, 1.0, 1.001, 3.0], [30.0; 4]);
        let w = schedule_applicability(&t, &[0.0, 0.0, 0.5, 0.5], &u, 1.0);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(
            w[0].starts_with("the steer changes at 500.0 rad/s (28648°/s at the road wheels) from t = 1 s to 1.001 s"),
            "{w:?}"
        );
        // Just within the limit: nothing to say.
        let edge = [
            0.0,
            0.0,
            0.99 * STEER_RATE * 0.001,
            0.99 * STEER_RATE * 0.001,
        ];
        assert!(schedule_applicability(&t, &edge, &u, 1.0).is_empty());
        // A first steer other than 0: an instant step at the start.
        let w = schedule_applicability(&[0.5, 3.0], &[0.1, 0.1], &[30.0, 30.0], 1.0);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(
            w[0].starts_with("the schedule starts with steer = 0.1 rad at t = 0.5 s, but the run starts from straight running"),
            "{w:?}"
        );
    }
}
