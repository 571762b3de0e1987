//! The long log's rows, one generator for the reliability test (which
//! writes them to a CSV file and runs the tool on it) and the bench
//! `measured` (which cleans and measures them in memory): a run at 25 Hz,
//! 20 m/s with a 0.02 rad step steer at 10 s, a 60 s standstill every
//! 30 min, stop-and-go traffic across the minimum speed (a piece every ten
//! samples), a 2 s gap every hour, and every 997th sample a glitch (a zero
//! read of yaw rate, a spike in ay, or a held steer), on noise from a
//! fixed-seed generator. SI units and radians, ISO 8855 signs.

/// Calls `row` with (t s, speed m/s, steer rad, yaw rate rad/s, ay m/s²,
/// beta rad) for each of the `n` rows, in order.
pub fn long_log_rows(n: usize, mut row: impl FnMut([f64; 6])) {
    let mut x: u64 = 0x2545_F491_4F6C_DD1D;
    let mut noise = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let mut held = 0.0;
    for i in 0..n {
        // Two seconds missing every hour (90 000 samples).
        let t = (i + 50 * (i / 90_000)) as f64 / 25.0;
        let stopped = t > 600.0 && t % 1800.0 < 60.0;
        // Stop-and-go across min_speed for 2 min of every 30: a piece
        // every 10 samples.
        let traffic = t > 600.0 && (t % 1800.0 - 100.0).abs() < 60.0;
        let speed = match (stopped, traffic) {
            (true, _) => 0.0,
            (_, true) if i % 20 < 10 => 4.0,
            (_, true) => 6.0,
            _ => 20.0 + 0.05 * noise(),
        };
        let steer = if t < 10.0 {
            0.0
        } else {
            0.02 * (1.0 - (-(t - 10.0) / 0.05).exp())
        };
        let r = if stopped {
            0.0
        } else {
            speed * steer / 2.78 * (1.0 - (-(t - 10.0).max(0.0) / 0.15).exp())
        };
        let (mut steer, mut r, mut ay) = (
            steer + 1e-4 * noise(),
            r + 1e-3 * noise(),
            speed * r + 0.02 * noise(),
        );
        match (i % 997 == 500, i / 997 % 3) {
            (true, 0) => r = 0.0,
            (true, 1) => ay += 5.0,
            (true, _) => held = steer,
            _ => {}
        }
        if i % 997 > 500 && i % 997 < 508 && i / 997 % 3 == 2 {
            steer = held;
        }
        row([t, speed, steer, r, ay, -0.1 * steer]);
    }
}
