//! A replay watched in chunks against the whole replay: the same history
//! to the bit by either method, and the residuals each chunk scores the
//! whole replay's to the bit, under sensors that read back (a delay),
//! ahead (a negative delay), a neighbour (an accelerometer ahead, whose
//! yaw acceleration is a central difference) and the logged `ax` (a
//! yawed mount).

use super::super::tests::sine_run;
use super::*;
use crate::diagnose::model::FixedStep;
use crate::manoeuvre::{Manoeuvre, SineSteer};
use crate::measured::MeasuredRun;
use crate::sim::Drive;
use crate::tyre::{Pac89, Tyre};
use crate::vehicle::{Sensors, Vehicle, VehicleModel};

/// The compact sedan on PAC89 tyres, with `sensors`.
fn car(sensors: Sensors) -> Augmented {
    let pac89 = Tyre::Pac89(Pac89::adams_example());
    let mut m = VehicleModel::new(Vehicle::compact_sedan(), pac89.clone(), pac89);
    m.options.effects.sensors = sensors;
    Augmented::new(m, 1.0)
}

/// A 12 s sine steer at 18 m/s of the ideal-sensor car, logged at 50 Hz
/// with all three channels (the sideslip too) and prepared at 10 ms with
/// residuals at 25 Hz.
fn logged_run() -> Prepared {
    let truth = car(Sensors::default());
    let m = SineSteer {
        speed: 18.0,
        amplitude: 0.03,
        frequency: 0.5,
        start: 0.5,
        end: 12.0,
    };
    let h = truth.simulate_from(&Drive::new(&Manoeuvre::Sine(m), 1e-3), 0.0, 0.0);
    let t: Vec<f64> = (0..600).map(|i| 0.02 * i as f64).collect();
    let at = |v: &[f64]| -> Vec<f64> {
        t.iter()
            .map(|&s| crate::manoeuvre::interpolate(&h.t, v, s))
            .collect()
    };
    let run = MeasuredRun::new(
        "logged.csv",
        t.clone(),
        at(&h.speed),
        at(&h.steer),
        at(&h.yaw_rate),
    )
    .with_ay(at(&h.ay))
    .with_beta(at(&h.beta));
    Prepared::new(&run, 0.01, 25.0)
}

/// Every column of two histories, to the bit.
fn assert_same_history(a: &TimeHistory, b: &TimeHistory) {
    let columns = |h: &TimeHistory| -> Vec<Vec<u64>> {
        let mut c = vec![
            &h.t,
            &h.speed,
            &h.beta,
            &h.yaw_rate,
            &h.ay,
            &h.roll,
            &h.fy_front,
        ];
        c.extend(h.fz.iter());
        c.iter()
            .map(|v| v.iter().map(|x| x.to_bits()).collect())
            .collect()
    };
    assert_eq!(columns(a), columns(b));
    assert_eq!(a.load_evaluations, b.load_evaluations);
}

#[test]
fn a_watched_replay_is_the_whole_replay_to_the_bit_by_either_method() {
    let run = logged_run();
    let model = car(Sensors::default());
    let integrator = Integrator::default();
    for method in [FixedStep::Rk4, FixedStep::RosenbrockW] {
        let drive = run.inputs.drive(run.drive.step, method);
        let x0 = model.initial_state(&drive, 0.0, run.start.1);
        let whole = integrator.replay_to(&model.model, &drive, x0, run.load_tolerance);
        let mut looks = Vec::new();
        let (watched, rows) =
            integrator.replay_watched(&model.model, &drive, x0, run.load_tolerance, 37, |h| {
                looks.push(h.len());
                true
            });
        let watched = watched.expect("never stopped");
        assert_same_history(&watched, &whole);
        assert_eq!(rows, whole.len());
        // A look after every 37 rows, none after the last.
        let want: Vec<usize> = (1..)
            .map(|k| 37 * k)
            .take_while(|&n| n < whole.len())
            .collect();
        assert_eq!(looks, want, "{method:?}");
        // Stopped at the fifth look: its first 185 rows, nothing returned.
        let mut seen = 0;
        let (stopped, rows) =
            integrator.replay_watched(&model.model, &drive, x0, run.load_tolerance, 37, |h| {
                seen = h.len();
                h.len() < 185
            });
        assert!(stopped.is_none());
        assert_eq!((rows, seen), (185, 185), "{method:?}");
    }
}

/// The sensors the chunks are checked under: ideal; delays back and
/// ahead; an accelerometer ahead with a sideslip offset; a yawed mount
/// (which reads the run's `ax`) with a roll gradient.
fn sensor_cases() -> Vec<Sensors> {
    vec![
        Sensors::default(),
        Sensors {
            delay: 0.083,
            ..Default::default()
        },
        Sensors {
            delay: -0.061,
            yaw_rate_bias: 0.002,
            ..Default::default()
        },
        Sensors {
            accelerometer_x: 0.7,
            beta_bias: 0.004,
            delay: 0.02,
            ..Default::default()
        },
        Sensors {
            mount_yaw: 0.03,
            roll_gradient: 0.004,
            ..Default::default()
        },
    ]
}

#[test]
fn each_chunk_scores_the_whole_replays_residuals_to_the_bit() {
    let run = logged_run();
    let scales = [2e-3, 5e-2, 1e-3];
    for sensors in sensor_cases() {
        let model = car(sensors);
        let mut whole = vec![0.0; run.count()];
        run.write_residuals(&run.observe(&model), &scales, &mut whole);
        // The chunks' residuals alone: NaN where none was scored.
        let mut chunked = vec![f64::NAN; run.count()];
        let mut costs = Vec::new();
        let mut watch = |c: f64| {
            costs.push(c);
            true
        };
        let drive = run.drive_for(&model);
        let mut scorer = Scorer::new(&run, &model, &scales, drive.step);
        let start = run.start_of(&model);
        let x0 = model.initial_state(&drive, start.0, start.1);
        let (h, _) = Integrator::default().replay_watched(
            &model.model,
            &drive,
            x0,
            run.load_tolerance,
            50,
            |h| watch(scorer.score(h, &mut chunked)),
        );
        assert_same_history(&h.expect("whole"), &run.replay(&model));
        let n = run.times.len();
        let scored: Vec<usize> = (0..run.count()).filter(|&k| !chunked[k].is_nan()).collect();
        // Every channel scored alike, from the first time on, to within a
        // second of the run's end (the last chunk, the margin and the
        // delay; 12 s, 300 times).
        let per_channel = scored.len() / 3;
        assert_eq!(scored.len(), 3 * per_channel, "{sensors:?}");
        assert!(
            per_channel + 25 > n && per_channel < n,
            "{sensors:?}: {per_channel} of {n}"
        );
        for &k in &scored {
            assert_eq!(
                chunked[k].to_bits(),
                whole[k].to_bits(),
                "{sensors:?}: residual {k}"
            );
            assert!(k % n < per_channel);
        }
        // The cost told after each chunk grows to that of what was scored,
        // below the whole's.
        assert!(costs.windows(2).all(|c| c[0] <= c[1]), "{sensors:?}");
        let part = 0.5 * scored.iter().map(|&k| whole[k] * whole[k]).sum::<f64>();
        let all = 0.5 * whole.iter().map(|e| e * e).sum::<f64>();
        let last = *costs.last().unwrap();
        assert!((last - part).abs() <= 1e-12 * part, "{last} against {part}");
        assert!(last < all, "{sensors:?}");
        assert_cached_whole(&run, &model, &scales, &whole);
    }
}

/// `model`'s residuals of `run` through a fresh cache, watched but never
/// stopped: `whole`'s to the bit, every row integrated; again, read from
/// the cache without a row.
fn assert_cached_whole(run: &Prepared, model: &Augmented, scales: &[f64; 3], whole: &[f64]) {
    let cache = ReplayCache::default();
    let mut out = vec![0.0; run.count()];
    let mut never = |_: f64| true;
    let done = run.residuals_watched(model, (&cache, None), scales, &mut out, Some(&mut never));
    let rows = run.drive.steps + 1;
    assert_eq!(
        done,
        Replayed {
            complete: true,
            rows
        }
    );
    assert_eq!(
        out.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
        whole.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
    );
    let again = run.residuals_watched(model, (&cache, None), scales, &mut out, Some(&mut never));
    assert_eq!(
        again,
        Replayed {
            complete: true,
            rows: 0
        }
    );
}

#[test]
fn a_stopped_replay_is_not_cached() {
    let m = SineSteer {
        speed: 20.0,
        amplitude: 0.03,
        frequency: 0.6,
        start: 0.5,
        end: 8.0,
    };
    let run = sine_run(&car(Sensors::default()), 0, m);
    let model = car(Sensors {
        delay: 0.05,
        ..Default::default()
    });
    let (cache, scales) = (ReplayCache::default(), [2e-3, 5e-2, 1e-3]);
    let mut out = vec![0.0; run.count()];
    let mut looks = 0;
    let mut stop = |_: f64| {
        looks += 1;
        looks < 3
    };
    let done = run.residuals_watched(&model, (&cache, None), &scales, &mut out, Some(&mut stop));
    // Stopped at the third look, 0.5 s apart: 150 of the 797 rows (8 s
    // logged, the last sample at 7.96 s), and integrated again in full.
    assert_eq!(
        done,
        Replayed {
            complete: false,
            rows: 150
        }
    );
    let whole = run.residuals_watched(&model, (&cache, None), &scales, &mut out, None);
    assert_eq!(
        whole,
        Replayed {
            complete: true,
            rows: 797
        }
    );
}
