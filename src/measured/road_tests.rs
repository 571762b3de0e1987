//! The road's bank and grade estimates of [`super`] on runs whose
//! readings are exact: a steady turn on a bank and a grade, offsets, a
//! unit slip, masked samples, a step steer with and without its sideslip.

use super::*;

#[test]
fn an_angle_that_rounds_to_zero_is_said_without_a_sign() {
    assert_eq!(deg(-1e-5), "0.0");
    assert_eq!(deg(-0.01), "-0.6");
    assert_eq!(deg(0.1), "5.7");
}

/// A steady left turn (u = 25 m/s, r = 0.2 rad/s) whose road banks from
/// 0 to −10° and back (left edge lower), on a 3 % uphill grade while the
/// car speeds up at 1 m/s²: what the accelerometers of a car that
/// neither rolls nor pitches read, exactly.
fn run() -> (MeasuredRun, Vec<f64>) {
    let n = 1001;
    let t: Vec<f64> = (0..n).map(|k| k as f64 * 0.01).collect();
    let bank: Vec<f64> = t
        .iter()
        .map(|&t| -10f64.to_radians() * (std::f64::consts::PI * t / 10.0).sin())
        .collect();
    let grade = 0.03f64.atan();
    let speed: Vec<f64> = t.iter().map(|&t| 25.0 + t).collect();
    let r = 0.2;
    let ay: Vec<f64> = (0..n).map(|k| speed[k] * r + G * bank[k].sin()).collect();
    let ax = vec![1.0 + G * grade.sin(); n];
    (
        MeasuredRun::new("turn.csv", t, speed, vec![0.02; n], vec![r; n])
            .with_ay(ay)
            .with_ax(ax),
        bank,
    )
}

#[test]
fn the_bank_and_grade_of_exact_readings_come_back() {
    let (r, bank) = run();
    let est = bank_estimate(&r, r.ay.as_ref().unwrap(), SensorOffsets::default());
    // The 1 s average of a 10 s half-sine differs from it by at most
    // its curvature over the window, (π/10)²·(0.5²/6)·10° ≈ 0.041°,
    // plus the sine's curvature (the average is taken of sin θ).
    // Within half a window of the ends the average is one-sided.
    for k in 50..r.t.len() - 50 {
        assert!(
            (est[k] - bank[k]).abs() < 0.045f64.to_radians(),
            "t {}: {} vs {}",
            r.t[k],
            est[k].to_degrees(),
            bank[k].to_degrees()
        );
    }
    let g = RoadGeometry::of("turn", &r, SensorOffsets::default(), 0.0);
    let b = g.bank.unwrap();
    assert_eq!(b.source, AngleSource::LateralKinematics);
    assert!((b.min.to_degrees() + 10.0).abs() < 0.05, "{b:?}");
    let gr = g.grade.unwrap();
    assert_eq!(gr.source, AngleSource::LongitudinalKinematics);
    for x in [gr.mean, gr.min, gr.max, gr.p05, gr.median, gr.p95] {
        assert!((x - 0.03f64.atan()).abs() < 1e-9, "{gr:?}");
    }
    let line = g.line().unwrap();
    assert!(
        line.contains("bank estimated from ay − u·r -9.9° to "),
        "{line}"
    );
    assert!(
        line.contains("grade estimated from ax − du/dt 1.7° to 1.7° (5–95 %; median 1.7°)"),
        "{line}"
    );
    assert!(!line.contains("steeper than"), "{line}");
    // A 12 % grade read from ax: beyond a road's, said to be likely
    // something else.
    let mut steep = r.clone();
    steep.ax = Some(vec![1.0 + G * 0.12f64.atan().sin(); steep.t.len()]);
    let line = RoadGeometry::of("turn", &steep, SensorOffsets::default(), 0.0)
        .line()
        .unwrap();
    assert!(
        line.contains("grade estimated from ax − du/dt 6.8° to 6.8° (5–95 %; median 6.8°) (steeper than a 10 % grade: more likely what ax and du/dt disagree on besides the grade"),
        "{line}"
    );
    // The bank's 5th percentile of a half-sine to −10°: −10°·cos(0.05·π/2).
    let p05 = (-10f64 * (0.05 * std::f64::consts::FRAC_PI_2).cos()).to_radians();
    assert!((b.p05 - p05).abs() < 0.05f64.to_radians(), "{b:?}");
}

/// A flat road read by an accelerometer mounted with an offset of
#[test] // A speed in km/h reads as a bank past any road's.
fn a_bank_past_any_road_is_warned_of_as_a_unit_slip() {
    let (mut r, _) = run();
    r.speed.iter_mut().for_each(|u| *u *= 3.6);
    let line = RoadGeometry::of("kmh", &r, SensorOffsets::default(), 0.0).line();
    let line = line.unwrap();
    assert!(line.starts_with("kmh: bank estimated from ay − u·r -90.0°"));
    assert!(line.contains("(warning: steeper than any road's 35°: more likely a unit"));
}

/// −0.6 m/s² and a gyro reading 0.005 rad/s high: −3.6° of bank
/// without the offsets, none with them.
#[test]
fn the_offsets_the_calibration_measured_are_no_bank() {
    let (mut r, bank) = run();
    let (b_ay, b_r) = (-0.6, 0.005);
    let ay: Vec<f64> = (0..r.t.len())
        .map(|k| r.ay.as_ref().unwrap()[k] - G * bank[k].sin() + b_ay)
        .collect();
    r.ay = Some(ay);
    r.yaw_rate.iter_mut().for_each(|x| *x += b_r);
    let g = RoadGeometry::of("flat", &r, SensorOffsets::default(), 0.0);
    let median = g.bank.unwrap().median.to_degrees();
    let unseen = ((b_ay - 25.0 * b_r) / G).asin().to_degrees();
    assert!((median - unseen).abs() < 0.35, "{median} vs {unseen}");
    assert!(median < -3.0, "{median}");
    let offsets = SensorOffsets {
        ay: b_ay,
        yaw_rate: b_r,
        beta: 0.0,
    };
    let g = RoadGeometry::of("flat", &r, offsets, 0.0);
    let b = g.bank.unwrap();
    for x in [b.p05, b.median, b.p95] {
        assert!(x.to_degrees().abs() < 1e-9, "{b:?}");
    }
    let line = g.line().unwrap();
    assert!(
        line.contains("bank estimated from ay − u·r less the offsets the calibration measured (ay -0.600 m/s², yaw rate 0.0050 rad/s) 0.0° to 0.0°"),
        "{line}"
    );
    // A measured bank is taken as logged: no offset is said removed.
    r.bank = Some(bank);
    assert_eq!(
        RoadGeometry::of("flat", &r, offsets, 0.0).offsets_removed,
        None
    );
}

#[test]
fn a_bank_column_is_reported_as_measured_and_masked_samples_are_left_out() {
    let (mut r, bank) = run();
    r.bank = Some(bank);
    let g = RoadGeometry::of("turn", &r, SensorOffsets::default(), 0.0);
    assert_eq!(g.bank.unwrap().source, AngleSource::Measured);
    // A 0.5 s glitch of ay at 9 g, masked: the estimate does not see it.
    let (mut r, _) = run();
    let ay = r.ay.as_mut().unwrap();
    for a in &mut ay[400..450] {
        *a = 90.0;
    }
    r.masked = (400..450).collect();
    let est = bank_estimate(&r, r.ay.as_ref().unwrap(), SensorOffsets::default());
    assert!(
        est.iter().all(|b| b.is_finite() && b.abs() < 0.2),
        "no glitch in it"
    );
    // Without ay and bank, no bank; without ax, no grade.
    let (mut r, _) = run();
    (r.ay, r.ax) = (None, None);
    let g = RoadGeometry::of("turn", &r, SensorOffsets::default(), 0.0);
    assert!(g.bank.is_none() && g.grade.is_none() && g.line().is_none());
}

/// A 2° step steer at 80 km/h on a flat road: the sideslip settles to
/// −0.02 rad with a 0.3 s lag and the accelerometer reads `u·r + v̇`.
/// With `beta` the estimate finds the flat road; without, `v̇` reads as
/// bank at the step and the line says why.
#[test]
fn a_step_on_a_flat_road_is_no_bank_when_the_run_has_its_sideslip() {
    let n = 601;
    let u = 22.2;
    let t: Vec<f64> = (0..n).map(|k| k as f64 * 0.01).collect();
    let lag = |t: f64| {
        if t < 2.0 {
            0.0
        } else {
            1.0 - (-(t - 2.0) / 0.3).exp()
        }
    };
    let beta: Vec<f64> = t.iter().map(|&t| -0.02 * lag(t)).collect();
    let r: Vec<f64> = t.iter().map(|&t| 0.2 * lag(t)).collect();
    let ay: Vec<f64> = (0..n)
        .map(|k| {
            let v_dot = -0.02 * u * (-(t[k] - 2.0) / 0.3).exp() / 0.3;
            u * r[k]
                + if t[k] < 2.0 {
                    0.0
                } else {
                    v_dot / beta_cos(beta[k])
                }
        })
        .collect();
    let mut run = MeasuredRun::new("step.csv", t, vec![u; n], vec![0.0; n], r)
        .with_ay(ay)
        .with_beta(beta);
    let with = RoadGeometry::of("step", &run, SensorOffsets::default(), 0.0);
    let b = with.bank.unwrap();
    assert_eq!(b.source, AngleSource::LateralKinematicsWithSideslip);
    // Central differences of a 0.3 s lag at 100 Hz: within 0.05°.
    for x in [b.min, b.max] {
        assert!(x.to_degrees().abs() < 0.05, "{b:?}");
    }
    assert!(with
        .line()
        .unwrap()
        .contains("bank estimated from ay − u·r − d(u·β)/dt"));
    run.beta = None;
    let without = RoadGeometry::of("step", &run, SensorOffsets::default(), 0.0);
    let b = without.bank.unwrap();
    assert_eq!(b.source, AngleSource::LateralKinematics);
    // The 1 s average of v̇ over the step: −0.02·22.2/1 s = −0.44 m/s²,
    // −2.6° at its largest.
    assert!(b.min.to_degrees() < -2.0, "{b:?}");
    assert!(without
        .line()
        .unwrap()
        .contains("no beta column: the sideslip's rate v̇ is left out"));
    // A masked sample's neighbours take no difference across it.
    run.beta = with_beta(&run);
    run.masked = vec![300];
    let est = bank_estimate(&run, run.ay.as_ref().unwrap(), SensorOffsets::default());
    assert!(est
        .iter()
        .all(|x| x.is_finite() && x.to_degrees().abs() < 0.05));
}

/// `v = u·tan β`: the lateral velocity's rate is `u·β̇/cos²β` at a
/// steady speed; the factor the readings carry.
fn beta_cos(beta: f64) -> f64 {
    beta.cos().powi(2)
}

fn with_beta(run: &MeasuredRun) -> Option<Vec<f64>> {
    let lag = |t: f64| {
        if t < 2.0 {
            0.0
        } else {
            1.0 - (-(t - 2.0) / 0.3).exp()
        }
    };
    Some(run.t.iter().map(|&t| -0.02 * lag(t)).collect())
}

/// A straight on flat ground at `speed(t)` m/s for 20 s (100 Hz), its
/// yaw rate reading `yaw_offset` rad/s and its ay `ay_offset` m/s²
/// besides, no sideslip column.
fn straight(
    name: &str,
    speed: impl Fn(f64) -> f64,
    yaw_offset: f64,
    ay_offset: f64,
) -> RoadGeometry {
    let n = 2001;
    let t: Vec<f64> = (0..n).map(|k| k as f64 * 0.01).collect();
    let u: Vec<f64> = t.iter().map(|&t| speed(t)).collect();
    let run =
        MeasuredRun::new(name, t, u, vec![0.0; n], vec![yaw_offset; n]).with_ay(vec![ay_offset; n]);
    RoadGeometry::of(name, &run, SensorOffsets::default(), 0.0)
}

/// Round 39: one run's yaw rate +0.02 rad/s on flat ground read as a bank
/// of −2.0°. Of three runs at 16.67 m/s, the one with the offset is set
/// apart, its bank `asin(−u·0.02/g)`, its ay offset `−u·0.02` and its
/// yaw-rate offset 0.02 given back exactly; the two others are not, nor
/// any of two runs alone (no "others" to differ from).
#[test]
fn a_bank_no_other_run_shows_is_set_apart_with_the_offsets_it_reads_as() {
    let u = 60.0 / 3.6;
    let roads = RoadGeometry::set_apart(vec![
        straight("a", |_| u, 0.0, 0.0),
        straight("b", |_| u, 0.02, 0.0),
        straight("c", |_| u, 0.0, 0.0),
    ]);
    assert_eq!((roads[0].apart, roads[2].apart), (None, None));
    let a = roads[1].apart.unwrap();
    assert!((a.bank - (-u * 0.02 / G).asin()).abs() < 1e-12, "{a:?}");
    assert!((a.ay_offset + u * 0.02).abs() < 1e-12, "{a:?}");
    assert!((a.yaw_rate_offset - 0.02).abs() < 1e-12, "{a:?}");
    assert_eq!((a.others, a.other_runs), (0.0, 2));
    // At one speed: no halves to tell a yaw-rate offset by.
    assert_eq!(roads[1].by_speed, None);
    let line = roads[1].line().unwrap();
    assert!(line.contains("a steady -1.9° that the other 2 runs do not show (their median 0.0°): a bank of -1.9°, an ay offset of -0.333 m/s² or a yaw-rate offset of +0.0200 rad/s at its 16.7 m/s read alike in one run's ay − u·r; at one speed the run cannot tell them apart"), "{line}");
    // 0.4° off (an ay offset of 0.068 m/s²): within APART_BANK, not apart.
    let small = 9.81 * 0.4f64.to_radians().sin();
    let roads = RoadGeometry::set_apart(vec![
        straight("a", |_| u, 0.0, 0.0),
        straight("b", |_| u, 0.0, small),
        straight("c", |_| u, 0.0, 0.0),
    ]);
    assert_eq!(roads[1].apart, None);
    let two = RoadGeometry::set_apart(vec![
        straight("a", |_| u, 0.0, 0.0),
        straight("b", |_| u, 0.02, 0.0),
    ]);
    assert_eq!((two[0].apart, two[1].apart), (None, None));
}

/// Over a run whose speed rises from 10 to 30 m/s a yaw-rate offset's
/// apparent bank grows with the speed (`−u·b_r/g`), an ay offset's does
/// not: the halves tell them apart, and the line says which.
#[test]
fn a_run_over_speeds_tells_a_yaw_rate_offset_from_an_ay_offset() {
    let rising = |t: f64| 10.0 + t;
    let flat = |_| 20.0;
    let yaw = RoadGeometry::set_apart(vec![
        straight("a", flat, 0.0, 0.0),
        straight("b", rising, 0.02, 0.0),
        straight("c", flat, 0.0, 0.0),
    ]);
    let b = yaw[1].by_speed.unwrap();
    assert!(b.fast_speed > 1.5 * b.slow_speed, "{b:?}");
    assert!(b.scales_with_speed(), "{b:?}");
    assert!(yaw[1]
        .line()
        .unwrap()
        .contains("growing with the speed as a yaw-rate offset's does"));
    let ay = RoadGeometry::set_apart(vec![
        straight("a", flat, 0.0, 0.0),
        straight("b", rising, 0.0, 0.3),
        straight("c", flat, 0.0, 0.0),
    ]);
    let b = ay[1].by_speed.unwrap();
    assert!(!b.scales_with_speed(), "{b:?}");
    assert!((ay[1].apart.unwrap().ay_offset - 0.3).abs() < 1e-9);
    assert!(ay[1].line().unwrap().contains(
        "not growing with the speed as a yaw-rate offset's would: a bank or an ay offset"
    ));
}

/// A straight then a left turn at 25 m/s (2 s, then 8 s at 0.16 rad/s,
/// 100 Hz) on flat ground, its gyro reading `scale` times the yaw rate, and
/// the road banked `turn_bank` rad (left edge higher) in the turn only.
fn turn(name: &str, scale: f64, turn_bank: f64) -> RoadGeometry {
    let n = 1001;
    let t: Vec<f64> = (0..n).map(|k| k as f64 * 0.01).collect();
    let r: Vec<f64> = t
        .iter()
        .map(|&t| if t < 2.0 { 0.0 } else { 0.16 })
        .collect();
    let bank: Vec<f64> = r
        .iter()
        .map(|r| if *r > 0.0 { turn_bank } else { 0.0 })
        .collect();
    let ay: Vec<f64> = (0..n).map(|k| 25.0 * r[k] + G * bank[k].sin()).collect();
    let gyro: Vec<f64> = r.iter().map(|r| scale * r).collect();
    let run = MeasuredRun::new(name, t, vec![25.0; n], vec![0.01; n], gyro).with_ay(ay);
    RoadGeometry::of(name, &run, SensorOffsets::default(), 0.0)
}

/// Round 40: one run's yaw rate ×1.15 read as a bank of −2.2° to −0.1°.
/// Of four exact runs the scaled one is set apart with its scale given
/// back exactly, and its line says it is the gyro's (or the
/// accelerometer's) scale, not a bank, naming what reads alike at one
/// speed: the same turn banked `asin(4·(1/1.15 − 1)/g)` under a true gyro
/// reads the same scale. The other runs read ×1, and none is set apart.
#[test]
fn a_yaw_rate_scale_no_other_run_shares_is_set_apart() {
    let roads = RoadGeometry::set_apart(vec![
        turn("a", 1.0, 0.0),
        turn("b", 1.15, 0.0),
        turn("c", 1.0, 0.0),
        turn("d", 1.0, 0.0),
    ]);
    for g in [&roads[0], &roads[2], &roads[3]] {
        assert_eq!(g.scale_apart, None);
        assert!((g.yaw_scale.unwrap().scale - 1.0).abs() < 1e-9, "{g:?}");
    }
    let a = roads[1].scale_apart.unwrap();
    assert!(
        (a.scale - 1.15).abs() < 1e-9 && (a.factor - 1.15).abs() < 1e-9,
        "{a:?}"
    );
    assert_eq!((a.other_runs, roads[1].apart), (3, None));
    let line = roads[1].line().unwrap();
    assert!(line.contains("; its yaw rate reads ×1.150 ± 0.000 of what ay/u says, the other 3 runs' ×1.000 (their median): a scale error of ×1.150 of the gyro (or of ×0.870 of the accelerometer), not a bank; only a road banked in step with the turning under this run alone (as a banked oval's turns) reads alike at one speed"), "{line}");
    let banked = turn("e", 1.0, (4.0 * (1.0 / 1.15 - 1.0) / G).asin());
    let k = banked.yaw_scale.unwrap().scale;
    assert!((k - 1.15).abs() < 1e-9, "{k}");
}
