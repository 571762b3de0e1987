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
//! ([`KINEMATIC_GRIP`]). Linear tyres have no grip to share: their
//! largest slip angles judge it instead ([`LINEAR_SLIP`]). Units: rad,
//! m/s and % as in [`StepMetrics`].
//!
//! A schedule is held to what a car on the road can drive
//! ([`schedule_applicability`]): the 2-DOF model takes the speed as an
//! input, so a change faster than the road's `μ·g` would run unchecked;
//! its steer to what a steering system can do, a road-wheel rate within
//! [`STEER_RATE`]; and a run that starts with its steer already applied
//! starts with an instant step from straight running.
//!
//! A response time at or below 0 is said as a lead only beyond
//! [`LEAD_SPREADS`] of its crossing's spread from the run's own noise
//! (`crossing_spread.rs`): a 0.0003 rad step under gyro noise of 1.7
//! times its steady yaw rate read −0.029 s where the noise moves it by
//! ±0.096 s.

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
/// Standard deviations of a response time's spread from noise beyond 0
/// (early) for a response to lead the steer: a response lags the steer, so
/// a time at or below 0 is a lead only where its noise would put it there
/// in under one draw in 740 (one-sided normal; the spread leans high).
/// Within it the time is the noise's, and `noise_spread.rs` says it with
/// its spread (a third of its size or more, past the twentieth said).
pub const LEAD_SPREADS: f64 = 3.0;
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
///
/// `speeds`: the speed at the yaw-rate peak and over the steady window
/// (m/s), where the run has a peak; a speed that falls between them by as
/// much as the overshoot explains it ([`speed_explains`]), and that is
/// said instead of a spin or a lightly damped response.
pub fn applicability_measured(
    m: &StepMetrics,
    speed: Option<f64>,
    largest_sideslip: Option<f64>,
    speeds: Option<(f64, f64)>,
) -> Vec<String> {
    let crawl = speed.is_some_and(|u| u.abs() < CRAWL_SPEED);
    let percent = m.yaw_rate_overshoot.unwrap_or(0.0);
    let evidence = Some(
        match speeds.filter(|&(peak, steady)| speed_explains(percent, peak, steady)) {
            Some((at_peak, steady)) => Overshoot::SpeedFalls { at_peak, steady },
            None => largest_sideslip.map_or(Overshoot::NoSideslip, Overshoot::Sideslip),
        },
    );
    applicability_with_grip(m, speed, crawl.then_some(Grip::PavedRoad), evidence)
}

/// What tells a yaw-rate overshoot beyond [`SPIN_OVERSHOOT`] from a spin.
/// A 2-DOF car's yaw damping falls as 1/u while its stiffness (from the
/// tyres) does not: at high speed a step rings, with every tyre on the
/// linear part of its curve and the car nowhere near sliding.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Overshoot {
    /// A simulation's, whose tyres are known: the most of its grip either
    /// axle used, `share` (below [`KINEMATIC_GRIP`] no tyre passed the
    /// linear part of its curve), and, where both axles stay short of their
    /// own tyres' peak, the largest |β|, `sideslip` (rad): within
    /// [`SLIDING_SIDESLIP`] no slide, so no spin (the sedan at 45 m/s,
    /// 0.05 rad: 111 % at 65 % of its grip and 5.2°, once called a spin).
    GripUsed {
        /// The most of its grip either axle used, a share.
        share: f64,
        /// The largest |β| in the run, rad, where no axle reaches its own
        /// tyres' peak (none where one does: it may have lost grip).
        sideslip: Option<f64>,
    },
    /// The largest |β| of a measured run, rad: within
    /// [`SLIDING_SIDESLIP`] the car never slid, so it did not spin.
    Sideslip(f64),
    /// A measured run without `beta`: nothing tells the two apart.
    NoSideslip,
    /// Tyres with no friction limit (linear ones): no grip to lose.
    NoGripLimit,
    /// Linear tyres whose axles' largest |slip angle| anywhere in the run
    /// is this, rad (front, rear): no grip to lose, and a sideslip beyond
    /// [`SLIDING_SIDESLIP`] is judged by them, not by itself (within
    /// [`LINEAR_SLIP`] it is the turn's geometry).
    LinearSlip([f64; 2]),
    /// A measured run whose speed falls from `at_peak` (m/s, at the
    /// yaw-rate peak) to `steady` (over the steady window) by more than
    /// the overshoot: the peak and the steady value are read at two
    /// speeds ([`speed_explains`]).
    SpeedFalls {
        /// The speed at the yaw-rate peak, m/s.
        at_peak: f64,
        /// The mean speed over the steady window, m/s.
        steady: f64,
    },
}

/// Whether a speed falling from `at_peak` to `steady` (m/s) between the
/// yaw-rate peak and the steady window accounts for an overshoot of
/// `percent`: a neutral car's steady yaw rate, `u·δ/l`, is `at_peak/steady`
/// times as large at the peak's speed as over the window, and where that
/// ratio reaches `1 + percent/100` the peak stands no higher above the
/// steady value than the speed's change alone puts it (an understeering
/// car's steady yaw rate falls less with the speed, so the ratio is the
/// most the speed can account for, below its characteristic speed).
pub fn speed_explains(percent: f64, at_peak: f64, steady: f64) -> bool {
    let ratio = at_peak.abs() / steady.abs();
    ratio.is_finite() && ratio >= 1.0 + percent / 100.0
}

/// The slip angle within which a linear tyre stands for a real one, rad
/// (3°): the least of the 3–10° at which real tyres' forces peak, so that
/// every road or racing tyre is still short of its peak there.
pub const LINEAR_SLIP: f64 = 3.0 * std::f64::consts::PI / 180.0;

/// Why the step-steer metrics do not apply to a steady sideslip `beta`
/// (rad) beyond 10°: the turn's geometry at a crawl or on little grip,
/// linear tyres past their range, or a slide. Apart from
/// [`applicability_with_grip`] so that it reads on a screen.
fn sliding_words(
    m: &StepMetrics,
    beta: f64,
    speed: Option<f64>,
    grip: Option<Grip>,
    overshoot: Option<Overshoot>,
) -> String {
    // In the steady turn both axles use |ay|/(μ·g) of their grip.
    let share = grip
        .zip(m.ay_steady)
        .map(|(g, ay)| (ay.abs() / g.accel(), g));
    let gripless = matches!(
        overshoot,
        Some(Overshoot::NoGripLimit | Overshoot::LinearSlip(_))
    );
    // Linear tyres are judged by their slip angles: a crawl's 10°
    // sideslip at 0.05° of slip is the turn's geometry (β ≈ b·δ/l),
    // and was said to take the tyres beyond their range.
    let linear_slip = match overshoot {
        Some(Overshoot::LinearSlip(slip)) => Some(slip),
        _ => None,
    };
    match (share.filter(|s| s.0 < KINEMATIC_GRIP), speed) {
        _ if linear_slip.is_some_and(|s| s[0].max(s[1]) <= LINEAR_SLIP)
            && speed.is_some() =>
        {
            let [front, rear] = linear_slip.unwrap_or_default();
            format!(
                "the steady sideslip is {}°, beyond 10°, {}",
                degrees_apart(beta),
                kinematic_turn_because(
                    &format!(
                        "the linear tyres' slip angles stay within {}° (front) and {}° (rear), short of the 3° where real tyres' forces begin to peak",
                        crate::format::significant(front.to_degrees(), 2),
                        crate::format::significant(rear.to_degrees(), 2)
                    ),
                    speed.unwrap_or_default(),
                    m.steer_step
                )
            )
        }
        // Linear tyres have no grip to slide past.
        _ if gripless => format!(
            "the steady sideslip is {}°, beyond 10°: on linear tyres, which have no peak and never slide, a turn this tight takes slip angles beyond a linear tyre's range of validity ({}a real tyre's force peaks at 3–10°), and the step-steer metrics describe no car (a smaller steer step measures the handling)",
            degrees_apart(beta),
            linear_slip.map_or_else(String::new, |s| format!(
                "the largest is {}°; ",
                crate::format::significant(s[0].max(s[1]).to_degrees(), 2)
            ))
        ),
        (Some((share, g)), Some(u)) => format!(
            "the steady sideslip is {}°, beyond 10°, {}",
            degrees_apart(beta),
            kinematic_turn(share, g.words(), u, m.steer_step)
        ),
        _ if beta.abs() > std::f64::consts::FRAC_PI_2 => format!(
            "the steady sideslip is {}°, past a quarter turn: the car has spun, and the step-steer metrics, defined for a handling response below the limit, do not apply (a smaller steer step measures the handling)",
            degrees_apart(beta)
        ),
        _ => format!(
            "the steady sideslip is {}°, beyond 10°: the car is sliding, past its grip, and the step-steer metrics, defined for a handling response below the limit, do not apply (a smaller steer step measures the handling)",
            degrees_apart(beta)
        ),
    }
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
            "the step is at {} m/s, below {CRAWL_SPEED} m/s (18 km/h): at a crawl the yaw rate follows the steer's geometry, and neither the response times nor the total variances (E_r, E_ay, Er: the lags of a geometric turn) measure handling (ISO 7401 steps at 80 km/h, as Wang & Liang's validation of Er does)",
            crate::format::fixed_apart(&[u.abs(), CRAWL_SPEED], 2)[0]
        ));
    }
    // A simulation's channels share one clock, and its tyres are known.
    let simulated = matches!(grip, Some(Grip::Tyres(_)))
        || matches!(
            overshoot,
            Some(Overshoot::GripUsed { .. } | Overshoot::NoGripLimit | Overshoot::LinearSlip(_))
        );
    for (name, time, spread) in [
        (
            "yaw rate",
            Some(m.yaw_rate_response_time),
            m.yaw_rate_response_time_spread,
        ),
        (
            "lateral acceleration",
            m.ay_response_time,
            m.ay_response_time_spread,
        ),
    ] {
        let beyond_noise = |t: f64| spread.is_none_or(|s| -t > LEAD_SPREADS * s);
        if let Some(t) = time.filter(|t| *t <= 0.0 && beyond_noise(*t)) {
            out.push(format!(
                "the {name} reaches 90 % of its step {} s before the steer reaches half of its own (response time {} s): {}, not the lag GB/T 6323 and ISO 7401 measure",
                crate::format::significant(-t, 2),
                crate::format::significant(t, 2),
                leading_cause(simulated, speed)
            ));
        }
    }
    if let Some(beta) = m.beta_steady.filter(|b| b.abs() > SLIDING_SIDESLIP) {
        out.push(sliding_words(m, beta, speed, grip, overshoot));
    }
    if let Some(percent) = m.yaw_rate_overshoot.filter(|p| *p > SPIN_OVERSHOOT) {
        out.push(overshoot_words(percent, speed, overshoot));
    }
    if m.overshoot_unresolved() {
        out.push(format!(
            "no yaw-rate overshoot is measured: the yaw rate scatters over the steady window so far that a maximum would have to stand {} % above the steady value to be told from it, beyond the {SPIN_OVERSHOOT:.0} % of a spin; the run cannot say whether it overshoots, and its peak time, overshoot and TB are left out",
            crate::format::rounded(m.yaw_rate_peak_threshold, 3)
        ));
    }
    out
}

/// Why a response leads the steer. A measured one: a crawl's geometry or
/// channels not aligned in time. A simulated one faster than a crawl has
/// one clock: its steady value lies far below its peak, the tyres' force
/// falling past its peak (a `.tir` whose `PCY1` was typed ten times over
/// turned its force around at 11° and was blamed on a logger).
fn leading_cause(simulated: bool, speed: Option<f64>) -> &'static str {
    let crawl = speed.is_some_and(|u| u.abs() < CRAWL_SPEED);
    match (simulated, crawl) {
        (_, true) => "a response that leads the steer is a crawl's geometry",
        (true, false) => "in a simulation, whose channels share one clock, a response that leads the steer settles far below its peak: the tyres' force falls past its peak within the step's slip (check their curve with `tyre-eval`), and the response time measures that fall",
        (false, false) => "a response that leads the steer is a crawl's geometry or a record whose channels are not aligned in time",
    }
}

/// A sideslip `beta` (rad) in degrees to one decimal, more where one
/// would round it onto the 10° of a sliding car or a quarter turn it is
/// said against ("10.0°, beyond 10°" for 10.04°).
fn degrees_apart(beta: f64) -> String {
    let limits = [10.0, -10.0, 90.0, -90.0];
    let mut all = vec![beta.to_degrees()];
    all.extend(limits);
    crate::format::fixed_apart(&all, 1).swap_remove(0)
}

/// The warning on a yaw-rate overshoot of `percent` beyond
/// [`SPIN_OVERSHOOT`] at `speed` (m/s), judged by `evidence`.
fn overshoot_words(percent: f64, speed: Option<f64>, evidence: Option<Overshoot>) -> String {
    let at = speed.map_or_else(String::new, |u| format!(", here {:.1} m/s", u.abs()));
    // 100.4 % is not "100 %" beside "more than twice the steady value".
    let said = crate::format::fixed_apart(&[percent, SPIN_OVERSHOOT], 0).swap_remove(0);
    let ringing =
        "the metrics still describe it, a response far from the standards' well-damped steps";
    let spin = format!("the yaw rate overshoots its steady value by {said} %: a peak more than twice the steady value is a car losing and regaining grip or spinning, not the handling response the metrics describe");
    match evidence {
        Some(Overshoot::GripUsed { share, .. }) if share < KINEMATIC_GRIP => format!(
            "the yaw rate overshoots its steady value by {said} % with the tyres using no more than {:.0} % of their grip: no spin, but a lightly damped linear response (the yaw damping falls with speed{at}); {ringing}",
            100.0 * share
        ),
        Some(Overshoot::GripUsed {
            share,
            sideslip: Some(sideslip),
        }) if sideslip <= SLIDING_SIDESLIP => format!(
            "the yaw rate overshoots its steady value by {said} % with the tyres using no more than {:.0} % of their grip and the sideslip within ±{}° throughout, short of the 10° of a sliding car: no spin, but a lightly damped response (the yaw damping falls with speed{at}); {ringing}",
            100.0 * share,
            degrees_apart(sideslip)
        ),
        Some(Overshoot::Sideslip(beta)) if beta <= SLIDING_SIDESLIP => format!(
            "the yaw rate overshoots its steady value by {said} % with the sideslip within ±{}° throughout, short of the 10° of a sliding car: no spin, but a lightly damped response (the yaw damping falls with speed{at}); {ringing}",
            degrees_apart(beta)
        ),
        Some(Overshoot::NoGripLimit | Overshoot::LinearSlip(_)) => format!(
            "the yaw rate overshoots its steady value by {said} % on tyres with no friction limit (linear): no grip to lose, no spin, but a lightly damped linear response (the yaw damping falls with speed{at}, and soft tyres lower it); {ringing}"
        ),
        Some(Overshoot::NoSideslip) => format!(
            "{spin}; or, at speed, a lightly damped response that never left the tyres' linear range: the run has no `beta` to tell them apart"
        ),
        Some(Overshoot::SpeedFalls { at_peak, steady }) => format!(
            "the yaw rate overshoots its steady value by {said} %, but the speed falls from {} m/s at the peak to {} m/s over the steady window: a neutral car's steady yaw rate, u·δ/l, is {} times as large at the peak's speed, no less than the {} times the peak stands above the steady value: the overshoot compares the yaw rate at two speeds and measures neither a spin nor the damping; hold the speed through the step to measure them (GB/T 6323 and ISO 7401 do)",
            crate::format::readable(at_peak.abs(), 3),
            crate::format::readable(steady.abs(), 3),
            crate::format::fixed(at_peak.abs() / steady.abs(), 2),
            crate::format::fixed(1.0 + percent / 100.0, 2)
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
    kinematic_turn_because(
        &format!(
            "the tyres use no more than {:.0} % of {whose}",
            100.0 * share
        ),
        speed,
        steer,
    )
}

/// [`kinematic_turn`] with its evidence `why` (the grip used, or a linear
/// tyre's slip angles) given in words.
fn kinematic_turn_because(why: &str, speed: f64, steer: f64) -> String {
    format!(
        "but no slide: {why}, and at {:.2} m/s the {:.1}° steer (a car's lock is about 35–40° at the road wheels) turns the car about a point near the line of its rear axle, where the sideslip is the turn's geometry (β ≈ b·δ/l), not the tyres sliding: the response is kinematic, limited by the steer, not by grip",
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

/// What a steer rate beyond [`STEER_RATE`] is beyond, its bracket left
/// open for the sentence's own reference.
fn beyond_steering() -> String {
    format!("faster than a steering system turns the wheels (up to about {STEER_RATE} rad/s; a steering robot's 3,000°/s at the handwheel is about 3.5 rad/s")
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
        "{how}, {}; GB/T 6323 and ISO 7401 time a step of 0.1–0.2 s): the response times measure an input no driver or robot can give",
        beyond_steering()
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
            "the steer changes at {:.1} rad/s ({:.0}°/s at the road wheels) {}, {}): the run shows a step no driver or robot can steer",
            rate.abs(),
            rate.abs().to_degrees(),
            steep.when(),
            beyond_steering()
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
#[path = "applicability_tests.rs"]
pub(crate) mod tests;
