//! Tests of the step steer's applicability warnings (`applicability.rs`).

use super::*;

/// Metrics of a well-behaved step: 0.5° sideslip, 12 % overshoot.
pub(crate) fn moderate() -> StepMetrics {
    StepMetrics {
        steer_step: 0.02,
        time_zero: 1.0,
        yaw_rate_response_time: 0.15,
        yaw_rate_peak_time: Some(0.3),
        yaw_rate_overshoot: Some(12.0),
        ay_response_time: Some(0.2),
        ay_response_time_below: None,
        yaw_rate_gain: 0.3,
        yaw_rate_steady: 0.006,
        ay_steady: Some(2.0),
        beta_steady: Some(-0.5_f64.to_radians()),
        tb: Some(0.15),
        yaw_rate_total_variance: 0.2,
        ay_total_variance: Some(0.2),
        er: Some(0.3),
        settled: true,
        settling: Default::default(),
        yaw_rate_noise: 0.0,
        ay_noise: Some(0.0),
        yaw_rate_peak_threshold: 1.0,
        yaw_rate_filter_ringing: 0.0,
        filter_hz: None,
        yaw_rate_peak_time_spread: None,
        yaw_rate_peak_found_share: None,
        yaw_rate_peak_stray_share: None,
        yaw_rate_overshoot_spread: None,
        yaw_rate_overshoot_noise_bias: None,
        yaw_rate_response_time_spread: None,
        ay_response_time_spread: None,
        yaw_rate_gain_spread: None,
        yaw_rate_peak_unmeasured: false,
        steer_logged_late: None,
        yaw_rate_window_moving: false,
        ay_window_moving: false,
        beta_window_moving: false,
        total_variance_window_cut: None,
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
        yaw_rate_overshoot: Some(503.6),
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
        yaw_rate_overshoot: Some(SPIN_OVERSHOOT),
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
        yaw_rate_overshoot: Some(229.0),
        ..moderate()
    };
    let said = |e: Option<Overshoot>| applicability_with_grip(&ringing, Some(80.0), None, e);
    // The tyres at a third of their grip, or the car within 2.2° of
    // sideslip: no spin.
    let w = said(Some(Overshoot::GripUsed {
        share: 0.35,
        sideslip: Some(0.2),
    }));
    assert!(
        w[0].contains("using no more than 35 % of their grip: no spin"),
        "{w:?}"
    );
    // Past the linear part but never sliding (the sedan at 45 m/s: axles
    // at 65 % of their grip, 5.2° of sideslip): no spin either.
    let w = said(Some(Overshoot::GripUsed {
        share: 0.65,
        sideslip: Some(5.2_f64.to_radians()),
    }));
    assert!(
        w[0].contains(
            "using no more than 65 % of their grip and the sideslip within ±5.2° throughout"
        ),
        "{w:?}"
    );
    assert!(!w[0].contains("spinning"), "{w:?}");
    let w = said(Some(Overshoot::NoGripLimit));
    assert!(
        w[0].contains("on tyres with no friction limit (linear): no grip to lose, no spin"),
        "{w:?}"
    );
    assert!(!w[0].contains("spinning"), "{w:?}");
    let w = said(Some(Overshoot::Sideslip(2.2_f64.to_radians())));
    assert!(
        w[0].contains("with the sideslip within ±2.2° throughout"),
        "{w:?}"
    );
    assert!(!w[0].contains("spinning"), "{w:?}");
    // At the limits themselves (half the grip is used, 10° is a
    // slide's least) and beyond, or with nothing to judge by: a spin.
    for e in [
        Some(Overshoot::GripUsed {
            share: KINEMATIC_GRIP,
            sideslip: Some(SLIDING_SIDESLIP + 1e-9),
        }),
        // An axle at its own tyres' peak: the sideslip tells nothing.
        Some(Overshoot::GripUsed {
            share: 0.65,
            sideslip: None,
        }),
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
    assert!(
        applicability_with_grip(&moderate(), Some(80.0), None, Some(Overshoot::NoSideslip))
            .is_empty()
    );
}

/// A measured step braked from 18.6 m/s at its yaw-rate peak to 7.27 m/s
/// over its steady window (the tester's 20 → 2 m/s schedule): a neutral
/// car's steady yaw rate is 2.56 times as large at the peak's speed, more
/// than the 2.02 the 102 % overshoot puts the peak at, so the overshoot
/// is the speed's change, not a lightly damped response. A speed falling
/// by less than the overshoot leaves the judgement by the sideslip.
#[test]
fn an_overshoot_the_falling_speed_accounts_for_is_said_as_the_speeds_change() {
    let braked = StepMetrics {
        yaw_rate_overshoot: Some(102.14),
        ..moderate()
    };
    let beta = Some(1.6_f64.to_radians());
    let w = applicability_measured(&braked, Some(13.6), beta, Some((18.6, 7.27)));
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].starts_with("the yaw rate overshoots its steady value by 102 %, but the speed falls from 18.6 m/s at the peak to 7.27 m/s over the steady window: a neutral car's steady yaw rate, u·δ/l, is 2.56 times as large at the peak's speed, no less than the 2.02 times"),
        "{w:?}"
    );
    assert!(!w[0].contains("damped response"), "{w:?}");
    // 20 → 12 m/s, a ratio of 1.67: short of 2.02, judged as before.
    let w = applicability_measured(&braked, Some(16.0), beta, Some((20.0, 12.0)));
    assert!(
        w[0].contains("no spin, but a lightly damped response"),
        "{w:?}"
    );
    // A rising speed lowers the peak against the steady value: as before.
    let w = applicability_measured(&braked, Some(16.0), beta, Some((10.0, 25.0)));
    assert!(
        w[0].contains("no spin, but a lightly damped response"),
        "{w:?}"
    );
    assert!(speed_explains(102.14, 18.6, 7.27) && !speed_explains(102.14, 20.0, 12.0));
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

/// A noise-free record's noise of exactly 0 was printed `0.00 %`, as if
/// rounded: it is said as none measured, and a tiny noise carries its
/// digits.
#[test]
fn a_yaw_rate_noise_of_zero_is_said_as_none_and_a_tiny_one_with_its_digits() {
    let none = moderate().yaw_rate_noise_text();
    assert_eq!(
        none,
        "0 % of the step (none measured: at least half of its successive samples are equal)"
    );
    let tiny = StepMetrics {
        yaw_rate_noise: 5.4e-9,
        ..moderate()
    };
    assert_eq!(tiny.yaw_rate_noise_text(), "5.4e-7 % of the step");
    let some = StepMetrics {
        yaw_rate_noise: 0.0123,
        ..moderate()
    };
    assert_eq!(some.yaw_rate_noise_text(), "1.23 % of the step");
}

/// A response leading the steer: a measured run's at speed is blamed on
/// its channels' alignment, a simulation's (one clock, its tyres known)
/// on the tyres' force falling past its peak, a crawl's on its geometry.
#[test]
fn a_leading_response_is_blamed_on_the_logger_only_where_there_is_one() {
    let leading = StepMetrics {
        yaw_rate_response_time: -0.008,
        ..moderate()
    };
    let measured = applicability_measured(&leading, Some(22.2), Some(0.01), None).join("\n");
    assert!(measured.contains("response time -0.0080 s"), "{measured}");
    assert!(measured.contains("not aligned in time"), "{measured}");
    for simulated in [
        applicability_with_grip(&leading, Some(22.2), Some(Grip::Tyres(9.8)), None),
        applicability_with_grip(&leading, Some(22.2), None, Some(Overshoot::NoGripLimit)),
    ] {
        let said = simulated.join("\n");
        assert!(
            said.contains("in a simulation, whose channels share one clock"),
            "{said}"
        );
        assert!(
            said.contains("check their curve with `tyre-eval`"),
            "{said}"
        );
        assert!(!said.contains("aligned"), "{said}");
    }
    let crawl = applicability_with_grip(&leading, Some(2.0), Some(Grip::Tyres(9.8)), None);
    let said = crawl.join("\n");
    assert!(
        said.contains("a response that leads the steer is a crawl's geometry, not"),
        "{said}"
    );
}

/// A sideslip of 10.04° read "10.0°, beyond 10°", an overshoot of
/// 100.4 % "100 %" beside "more than twice the steady value": each is
/// printed with the digits that tell it from the limit it is said against.
#[test]
fn a_value_beyond_a_limit_never_prints_as_the_limit() {
    assert_eq!(degrees_apart(10.04_f64.to_radians()), "10.04");
    assert_eq!(degrees_apart(-10.04_f64.to_radians()), "-10.04");
    assert_eq!(degrees_apart(17.8_f64.to_radians()), "17.8");
    let w = overshoot_words(100.4, None, None);
    assert!(
        w.starts_with(
            "the yaw rate overshoots its steady value by 100.4 %: a peak more than twice"
        ),
        "{w}"
    );
    let w = overshoot_words(140.0, None, None);
    assert!(
        w.starts_with("the yaw rate overshoots its steady value by 140 %:"),
        "{w}"
    );
}

/// A response time below 0 is a lead only beyond [`LEAD_SPREADS`] of its
/// spread from the run's noise: −0.029 s with ±0.096 s (the 0.0003 rad
/// step's gyro noise) is the noise's and says nothing; −0.05 s with
/// ±0.015 s (3.3 spreads) is said; without a spread (a noise-free run) any
/// time below 0 is said, as before.
#[test]
fn a_lead_within_its_noise_is_not_said_and_one_beyond_it_is() {
    let leading = |t: f64, spread: Option<f64>| {
        let m = StepMetrics {
            yaw_rate_response_time: t,
            yaw_rate_response_time_spread: spread,
            ..moderate()
        };
        applicability(&m, Some(22.2))
            .iter()
            .any(|w| w.contains("the yaw rate reaches 90 % of its step"))
    };
    assert!(!leading(-0.029, Some(0.096)));
    assert!(!leading(-0.045, Some(0.015)));
    assert!(leading(-0.05, Some(0.015)));
    assert!(leading(-0.029, None));
    // The ay's lead is judged by the ay's spread, not the yaw rate's.
    let ay = |spread: f64| StepMetrics {
        ay_response_time: Some(-0.05),
        ay_response_time_spread: Some(spread),
        yaw_rate_response_time_spread: Some(1.0),
        ..moderate()
    };
    let said = |m: &StepMetrics| {
        applicability(m, Some(22.2))
            .iter()
            .any(|w| w.contains("the lateral acceleration reaches 90 %"))
    };
    assert!(!said(&ay(0.042)) && said(&ay(0.01)));
}
