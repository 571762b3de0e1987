//! The settling verdicts' own tests: trends of known responses, verdicts
//! of known spreads, the words said of a limit known and unknown.

use super::*;

/// The means over [`TREND_PARTS`] parts of [0, 2] of `x(t)`, normalised
/// so that the last half's mean is 1 (as a steady window's is).
fn parts(x: impl Fn(f64) -> f64) -> [f64; TREND_PARTS] {
    let n = 400;
    let w = 2.0 / TREND_PARTS as f64;
    let raw: [f64; TREND_PARTS] = std::array::from_fn(|k| {
        (0..n)
            .map(|i| x(w * (k as f64 + (i as f64 + 0.5) / n as f64)))
            .sum::<f64>()
            / n as f64
    });
    let steady = raw[TREND_PARTS / 2..].iter().sum::<f64>() / (TREND_PARTS / 2) as f64;
    raw.map(|m| m / steady)
}

#[test]
fn a_geometric_approach_heads_to_its_limit() {
    // x = L − c·e^(−t/τ): the limit relative to the last window's mean.
    let (limit, c, tau) = (1.0, 0.3, 0.8);
    let x = |t: f64| limit - c * (-(t + 2.0) / tau).exp();
    let p = parts(x);
    let steady = {
        let n = 4000;
        (0..n)
            .map(|i| x(1.0 + (i as f64 + 0.5) / n as f64))
            .sum::<f64>()
            / n as f64
    };
    let trend = trend_of_parts(p, 0.0).unwrap();
    assert!(trend.converging);
    let expected = limit / steady - 1.0;
    assert!(
        (trend.heads - expected).abs() < 1e-3 * expected,
        "{} vs {expected}",
        trend.heads
    );
}

#[test]
fn ringing_that_turns_back_is_no_trend() {
    // A decaying oscillation of period 1.5 s: monotone over one window
    // at times, never over two.
    let x = |t: f64| 1.0 + 0.05 * (-t / 3.0).exp() * (2.0 * std::f64::consts::PI * t / 1.5).cos();
    for shift in [0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4] {
        assert_eq!(
            trend_of_parts(parts(|t| x(t + shift)), 0.0),
            None,
            "{shift}"
        );
    }
}

#[test]
fn a_change_within_the_noise_is_no_trend() {
    let p = parts(|t| 1.0 + 0.01 * t);
    // Each part moves by 0.01 · 2/12 of the step: within three deviations of 0.0006.
    assert_eq!(trend_of_parts(p, 0.0006), None);
    assert!(trend_of_parts(p, 0.0005).is_some());
}

#[test]
fn a_trend_that_does_not_slow_is_not_converging() {
    let trend = trend_of_parts(parts(|t| 1.0 + 0.05 * t * t), 0.0).unwrap();
    assert!(!trend.converging);
    assert!(trend.heads > 0.05, "{}", trend.heads);
}

#[test]
fn a_settled_spread_with_a_trend_beyond_the_drift_is_drifting() {
    let trend = Trend {
        heads: 0.089,
        converging: true,
        rising: true,
    };
    assert_eq!(
        Settling::of_spread(0.01, Some(trend), Inside::default()),
        Settling::Drifting {
            heads: 0.089,
            converging: true,
            rising: true,
        }
    );
    // Within the drift but beyond a tenth of a percent: approaching;
    // within that, settled.
    let small = Trend {
        heads: 0.5 * SETTLED_DRIFT,
        converging: true,
        rising: true,
    };
    assert_eq!(
        Settling::of_spread(0.01, Some(small), Inside::default()),
        Settling::Approaching {
            heads: 0.5 * SETTLED_DRIFT,
            rising: true
        }
    );
    let tiny = Trend {
        heads: 0.5 * APPROACH_SAID,
        ..small
    };
    assert_eq!(
        Settling::of_spread(0.01, Some(tiny), Inside::default()),
        Settling::Settled
    );
    assert_eq!(
        Settling::of_spread(0.03, Some(trend), Inside::default()),
        Settling::NotSettled { beyond: 0.03 }
    );
    let channels = ChannelSettling {
        yaw_rate: Settling::of_spread(0.01, Some(trend), Inside::default()),
        ay: Some(Settling::Settled),
        beta: None,
    };
    assert!(!channels.settled());
    assert_eq!(channels.only_converging(), Some(0.089));
}

/// A Gim car (μ = 1 on friction 1) whose lateral acceleration averages
/// 9.39 m/s² with a trend of 6.7 % of its step: rising, it would pass the
/// 9.807 m/s² its tyres give at 10.02 m/s² (round 40's words read so,
/// of a trend that in fact falls).
#[test]
fn a_trend_past_the_limit_climbs_toward_it_and_one_within_it_heads_there() {
    // Static axle loads of a 1530 kg car, a = 1.11, b = 1.67 m.
    let w = 1530.0 * crate::constants::G / 2.78;
    let limit = AyLimit::of_axles([1.0, 1.0], [w * 1.67, w * 1.11], 1530.0, 1.0);
    assert_eq!(limit.source, AyLimitSource::Tyres);
    assert!(
        (limit.value - crate::constants::G).abs() < 1e-12,
        "{limit:?}"
    );
    let ceiling = Ceiling {
        limit,
        ay_steady: 9.39,
    };
    // The room: (9.80665 − 9.39)/9.39 = 4.44 % of the step.
    assert!(
        (ceiling.room() - 0.4166 / 9.39).abs() < 1e-4,
        "{}",
        ceiling.room()
    );
    let drifting = |heads: f64, rising: bool| ChannelSettling {
        yaw_rate: Settling::Settled,
        ay: Some(Settling::Drifting {
            heads,
            converging: false,
            rising,
        }),
        beta: None,
    };
    let said = drifting(0.067, true)
        .not_settled_warning_within(1.0, Some(&ceiling))
        .unwrap();
    assert!(
        said.contains("the lateral acceleration is still drifting: the trend across its steady window climbs toward the 9.81 m/s² the tyres can give on this road (their peak lateral forces at static load over the mass), 4.4 % of its step above its window's mean (a line through the window would pass it, where no car on this road goes), more than 2 %"),
        "{said}"
    );
    assert!(!said.contains("6.7 %"), "{said}");
    // Within the room: where it heads, as before.
    let said = drifting(0.03, true)
        .not_settled_warning_within(1.0, Some(&ceiling))
        .unwrap();
    assert!(
        said.contains("the trend across its steady window heads 3.0 % of its step beyond its window's mean, more than 2 %"),
        "{said}"
    );
    // Falling back: back below, whatever the limit.
    let said = drifting(0.067, false)
        .not_settled_warning_within(1.0, Some(&ceiling))
        .unwrap();
    assert!(
        said.contains("heads 6.7 % of its step back below its window's mean"),
        "{said}"
    );
    // A measured record's: no limit known, said as the window's trend.
    let said = drifting(0.067, true).not_settled_warning(1.0).unwrap();
    assert!(
        said.contains("heads 6.7 % of its step beyond its window's mean (the window's trend carried on: the car's grip, which this record does not give, bounds where it ends)"),
        "{said}"
    );
    // The yaw rate's words are not bounded by the grip.
    let yaw = ChannelSettling {
        yaw_rate: Settling::Approaching {
            heads: 0.0015,
            rising: true,
        },
        ay: None,
        beta: None,
    };
    let said = yaw.approaching_warning(32.6189).unwrap();
    assert!(
        said.contains("the yaw rate still grows across its steady window, its trend heading 0.15 % of its step beyond the window's mean;"),
        "{said}"
    );
}

#[test]
fn tyres_with_no_limit_are_bounded_by_the_road() {
    let limit = AyLimit::of_axles([f64::INFINITY, 1.0], [8000.0, 7000.0], 1530.0, 0.5);
    assert_eq!(limit.source, AyLimitSource::Road);
    assert!((limit.value - 0.5 * crate::constants::G).abs() < 1e-12);
    assert_eq!(limit.to_string(), "the 4.90 m/s² (μ·g) this road can give");
    // A run past it already: the trend climbs on beyond it.
    let ceiling = Ceiling {
        limit,
        ay_steady: -6.0,
    };
    let s = ChannelSettling {
        yaw_rate: Settling::Settled,
        ay: Some(Settling::Approaching {
            heads: 0.01,
            rising: true,
        }),
        beta: None,
    };
    let said = s.approaching_warning_within(1.0, Some(&ceiling)).unwrap();
    assert!(
        said.contains("the lateral acceleration still grows across its steady window, its trend climbing on beyond the 4.90 m/s² (μ·g) this road can give, which the run already passes"),
        "{said}"
    );
}

/// Round 43: a yaw rate rising 10 %/s to the record's end spreads by only
/// 2.1 % of its step about the window's mean; read as "not settled, off by
/// up to about 2.1 %" its gain was 40 % above the car's. A ramp that does
/// not slow is drifting whatever its spread, and its warning bounds
/// nothing.
#[test]
fn a_ramp_spread_beyond_two_percent_is_drifting_and_bounds_no_gain() {
    let ramp = trend_of_parts(parts(|t| 1.0 + 0.1 * t), 0.0).unwrap();
    assert!(!ramp.converging && ramp.rising);
    let s = Settling::of_spread(0.021, Some(ramp), Inside::default());
    assert!(
        matches!(
            s,
            Settling::Drifting {
                converging: false,
                rising: true,
                ..
            }
        ),
        "{s:?}"
    );
    let channels = ChannelSettling {
        yaw_rate: s,
        ay: None,
        beta: None,
    };
    let w = channels.not_settled_warning(5.19).unwrap();
    assert!(w.contains("drifts without slowing"), "{w}");
    assert!(!w.contains("off by up to"), "{w}");
    // A spread without a one-way trend (a response ringing in its window)
    // stays a spread.
    assert_eq!(
        Settling::of_spread(0.021, None, Inside::default()),
        Settling::NotSettled { beyond: 0.021 }
    );
}

/// A geometric approach is read as slowing only where its slope falls by a
/// third or more across the two windows: a time constant of 3 s (three
/// windows) does, one of 30 s (q = 0.989 a third) is a drift the record
/// cannot tell from a ramp, and its limit is not extrapolated.
#[test]
fn an_approach_slower_than_the_windows_can_see_is_no_converging_trend() {
    let approach =
        |tau: f64| trend_of_parts(parts(|t| 1.0 - 0.3 * (-(t + 2.0) / tau).exp()), 0.0).unwrap();
    assert!(approach(3.0).converging);
    let slow = approach(30.0);
    assert!(!slow.converging && slow.rising, "{slow:?}");
}

/// A sideslip spreading beside a settled yaw rate and ay: the grip
/// limit is no explanation where the run knows its axles stay short
/// of their peak, a possibility where it does not know, and said as
/// the run's where an axle reaches its peak.
#[test]
fn the_grip_limit_is_said_only_as_far_as_the_run_knows_it() {
    let c = ChannelSettling {
        yaw_rate: Settling::Settled,
        ay: Some(Settling::Settled),
        beta: Some(Settling::NotSettled { beyond: 0.024 }),
    };
    let said = |a| c.not_settled_warning_known(2.4, None, a).unwrap();
    let below = said(AxlesGrip::BelowPeak);
    assert!(!below.contains("at its grip limit"), "{below}");
    assert!(below.contains("no slide at the grip limit"), "{below}");
    assert!(said(AxlesGrip::Unknown).contains("a possibility this record"));
    assert!(said(AxlesGrip::AtPeak).contains("an axle here reaches its tyres' peak"));
    // Where the yaw rate swings too, no grip words at all.
    let swinging = ChannelSettling {
        yaw_rate: Settling::Oscillating {
            amplitude: 0.04,
            period: 3.7,
            centre: -0.03,
            last: 5.25,
        },
        ..c
    };
    let w = swinging
        .not_settled_warning_known(2.434, None, AxlesGrip::Unknown)
        .unwrap();
    assert!(!w.contains("grip limit"), "{w}");
    assert!(
        w.contains("the oscillation's centre is about 2.361 1/s"),
        "{w}"
    );
}

/// A noise-free record whose spread passes (1.3 % of its step) but that
/// climbs across its window, its parts' means 4.5 % apart with a turn
/// inside (the sedan at 45 m/s, 0.05 rad): not settled, by the window's
/// range, as a measured record is judged ([`verdict`]); without the turn,
/// settled.
#[test]
fn a_simulated_window_that_turns_inside_is_unsettled_by_its_range() {
    let turning = Inside {
        peak: 0.025,
        range: 0.045,
    };
    assert_eq!(
        Settling::of_spread(0.013, None, turning),
        Settling::NotSettled { beyond: 0.045 }
    );
    assert_eq!(
        Settling::of_spread(0.013, None, Inside::default()),
        Settling::Settled
    );
    // A turn below the 2 % a settled response may move is no turn.
    let small = Inside {
        peak: 0.015,
        range: 0.03,
    };
    assert_eq!(Settling::of_spread(0.013, None, small), Settling::Settled);
}
