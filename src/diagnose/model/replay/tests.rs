//! Prepared runs' replays: the test runs other modules' tests share
//! ([`sine_run`], [`sine_runs`]) and the inputs a replay reads.

use super::*;
use crate::manoeuvre::{Manoeuvre, SineSteer};
use crate::sim::Drive;

/// The sine steer `m` driven by `truth`, logged at 25 Hz for 8 s (yaw
/// rate and ay, no sideslip) as `run{k}.csv` and prepared for replays
/// at 10 ms.
pub(crate) fn sine_run(truth: &Augmented, k: usize, m: SineSteer) -> Prepared {
    let h = truth.simulate_from(&Drive::new(&Manoeuvre::Sine(m), 1e-3), 0.0, 0.0);
    let t: Vec<f64> = (0..200).map(|i| 0.04 * i as f64).collect();
    let at = |v: &[f64]| -> Vec<f64> {
        t.iter()
            .map(|&s| crate::manoeuvre::interpolate(&h.t, v, s))
            .collect()
    };
    let (speed, steer, yaw_rate, ay) = (at(&h.speed), at(&h.steer), at(&h.yaw_rate), at(&h.ay));
    let run = MeasuredRun::new(format!("run{k}.csv"), t, speed, steer, yaw_rate).with_ay(ay);
    Prepared::new(&run, 0.01, 25.0)
}

/// Sine steers of `truth` at 12, 20 and 28 m/s (0.03 rad at 0.4, 0.6
/// and 0.8 Hz for 7.5 s), 25 Hz, yaw rate and ay, noise-free.
pub(crate) fn sine_runs(truth: &Augmented) -> Vec<Prepared> {
    (0..3)
        .map(|k| {
            let m = SineSteer {
                speed: 12.0 + 8.0 * k as f64,
                amplitude: 0.03,
                frequency: 0.4 + 0.2 * k as f64,
                start: 0.5,
                end: 8.0,
            };
            sine_run(truth, k, m)
        })
        .collect()
}

/// A run of constant steer at `speed`, `ax` logged or not.
fn run(t: Vec<f64>, speed: Vec<f64>, ax: Option<Vec<f64>>) -> MeasuredRun {
    let n = t.len();
    MeasuredRun::new("r.csv", t, speed, vec![0.01; n], vec![0.0; n]).with_ax(ax)
}

use crate::identify::data::{rms, white_noise as noise};

// The acceleration a replay uses: the logged `ax`, else the speed's
// Savitzky–Golay derivative (`crate::measured::derivative`).
#[test]
fn a_noisy_constant_speed_without_ax_is_replayed_without_fake_acceleration() {
    // 30 s at 20 m/s logged at 100 Hz with 0.03 m/s of white noise.
    let t: Vec<f64> = (0..3001).map(|k| k as f64 * 0.01).collect();
    let speed: Vec<f64> = noise(t.len(), 0.03, 11).iter().map(|e| 20.0 + e).collect();
    // The raw difference of the speed: √2·0.03/0.01 ≈ 4.2 m/s² RMS.
    let raw: Vec<f64> = speed.windows(2).map(|u| (u[1] - u[0]) / 0.01).collect();
    assert!(rms(&raw) > 1.0, "{}", rms(&raw));
    let r = run(t, speed, None);
    for step in [0.01, 0.02] {
        let p = Prepared::new(&r, step, 25.0);
        let ax = p.drive.ax_samples();
        assert_eq!(ax.len(), 2 * p.drive.steps + 1);
        assert!(rms(&ax) < 0.2, "step {step}: {}", rms(&ax));
    }
    // With an ax channel, that is what the replay reads.
    let measured: Vec<f64> = (0..3001).map(|k| -1.0 - 1e-3 * k as f64).collect();
    let r = run(r.t.clone(), r.speed.clone(), Some(measured));
    let p = Prepared::new(&r, 0.01, 25.0);
    for (i, a) in p.drive.ax_samples().iter().enumerate() {
        assert!((a - (-1.0 - 0.5e-3 * i as f64)).abs() < 1e-9, "{i}: {a}");
    }
}

#[test]
fn a_speed_ramp_is_recovered_in_its_middle() {
    // 2 s at 10 m/s, 5 s speeding up at 2 m/s², 3 s at 20 m/s, at
    // 100 Hz; once exact, once with 0.03 m/s of noise.
    let t: Vec<f64> = (0..1001).map(|k| k as f64 * 0.01).collect();
    let clean: Vec<f64> = t
        .iter()
        .map(|&x| 10.0 + 2.0 * (x - 2.0).clamp(0.0, 5.0))
        .collect();
    let noisy: Vec<f64> = clean
        .iter()
        .zip(noise(t.len(), 0.03, 5))
        .map(|(u, e)| u + e)
        .collect();
    let middle = |p: &Prepared| -> Vec<f64> {
        let ax = p.drive.ax_samples();
        // Stage sample k is at k·h/2 = k·2.5 ms: 3.5–5.5 s.
        (1400..=2200).map(|k| ax[k]).collect()
    };
    let p = Prepared::new(&run(t.clone(), clean, None), 0.005, 25.0);
    for a in middle(&p) {
        assert!((a - 2.0).abs() < 0.02 * 2.0, "{a}");
    }
    // Zero before and after the ramp, half a window from its kinks
    // (before 1.75 s, after 7.25 s).
    let ax = p.drive.ax_samples();
    assert!(ax[..700].iter().all(|a| a.abs() < 1e-9));
    assert!(ax[2901..].iter().all(|a| a.abs() < 1e-9));
    let p = Prepared::new(&run(t, noisy, None), 0.005, 25.0);
    let m = middle(&p);
    let mean = m.iter().sum::<f64>() / m.len() as f64;
    assert!((mean - 2.0).abs() < 0.02 * 2.0, "{mean}");
    assert!(m.iter().all(|a| (a - 2.0).abs() < 0.2), "{m:?}");
}
