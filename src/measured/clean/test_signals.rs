//! Test signals shared by the cleaning tests: seeded Gaussian noise and a
//! synthetic run (a slow steer sine and its noisy yaw rate, SI units).

pub(super) use crate::identify::data::white_noise as gauss_noise;
use crate::measured::MeasuredRun;

pub(super) fn no_slow(n: usize) -> Vec<bool> {
    vec![false; n]
}

pub(super) fn run(n: usize, dt: f64, speed: impl Fn(f64) -> f64) -> MeasuredRun {
    let t: Vec<f64> = (0..n).map(|i| i as f64 * dt).collect();
    let noise = gauss_noise(n, 0.002, 11);
    let speed = t.iter().map(|&x| speed(x)).collect();
    let steer = t.iter().map(|&x| 0.02 * (0.5 * x).sin()).collect();
    let yaw_rate = t
        .iter()
        .zip(&noise)
        .map(|(&x, e)| 0.2 * (0.5 * x).sin() + e)
        .collect();
    MeasuredRun::new("r.csv", t, speed, steer, yaw_rate)
}
