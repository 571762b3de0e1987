//! Winding tracks for the closed-loop driver: a track as pieces
//! (straights, corners with clothoid entries and exits, stops where the car
//! stands still), its centre line sampled every [`DS`] metres (position,
//! heading, curvature), and the speed the driver drives along it in time.
//!
//! **Geometry.** A corner of radius R turning through the angle θ (positive
//! left) has a clothoid (curvature linear in distance) of length
//! `clamp(R/2, 6, 20)` m at each end, so the path's curvature is continuous
//! and a driver need not jerk the wheel; the constant-radius arc takes the
//! rest of the angle. The line is integrated from the curvature by the
//! midpoint rule on the [`DS`] grid.
//!
//! **Speed.** Every piece names the speed the driver wants on it (a
//! corner's over its clothoids too); the driver brakes into a slower piece
//! at no more than its braking level and accelerates out at no more than
//! its drive level (the classic forward–backward pass over the distance
//! grid, constant acceleration between grid points, so the speed is
//! piecewise linear in time). A run starts parked for a stated time; a
//! stop brakes to rest at its point and stands there for its dwell. The
//! driver's pedal work is not a step in acceleration: the speed is the
//! moving average of that profile over [`PEDAL_SMOOTHING`], whose
//! derivative (the longitudinal acceleration) ramps over that time and
//! which is zero wherever the profile stands still longer.
//!
//! Units: m, rad, s, m/s; ISO 8855 (x forward, y left, curvature and
//! heading positive to the left).

/// Spacing of the centre line's samples, m.
pub(super) const DS: f64 = 0.25;
/// Time over which the driver's pedal work blends one acceleration into
/// the next, s.
pub(super) const PEDAL_SMOOTHING: f64 = 0.6;

/// A piece of a track.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Piece {
    /// A straight of `length` m driven at `speed` m/s.
    Straight { length: f64, speed: f64 },
    /// A corner of `radius` m turning through `angle` rad (positive left),
    /// driven at `speed` m/s.
    Corner { radius: f64, angle: f64, speed: f64 },
    /// The car brakes to rest here and stands still for `dwell` s.
    Stop { dwell: f64 },
}

/// A straight of `length` m at `speed` m/s.
pub(super) const fn straight(length: f64, speed: f64) -> Piece {
    Piece::Straight { length, speed }
}

/// A corner of `radius` m through `degrees` (positive left) at `speed` m/s.
pub(super) fn corner(radius: f64, degrees: f64, speed: f64) -> Piece {
    Piece::Corner {
        radius,
        angle: degrees.to_radians(),
        speed,
    }
}

/// The clothoid length of a corner of radius `radius` turning through
/// `angle`, m: half the radius within 6–20 m, shortened so that the two
/// clothoids (each turning through half its length over the radius) take
/// at most the whole angle.
fn clothoid_length(radius: f64, angle: f64) -> f64 {
    (0.5 * radius).clamp(6.0, 20.0).min(radius * angle.abs())
}

/// A track's centre line on the [`DS`] grid and the speed wanted there.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Track {
    /// Position ahead, m.
    pub x: Vec<f64>,
    /// Position to the left, m.
    pub y: Vec<f64>,
    /// Heading, rad.
    pub heading: Vec<f64>,
    /// Curvature, 1/m (positive left).
    pub curvature: Vec<f64>,
    /// The speed the driver wants at each sample, m/s (0 at a stop).
    pub wanted: Vec<f64>,
    /// Stops: (sample index, dwell s).
    pub stops: Vec<(usize, f64)>,
}

impl Track {
    /// The track of `pieces`, starting at the origin heading along x.
    pub(super) fn new(pieces: &[Piece]) -> Self {
        let mut curvature = vec![0.0];
        let mut wanted = vec![0.0];
        let mut stops = Vec::new();
        for p in pieces {
            match *p {
                Piece::Straight { length, speed } => {
                    let n = (length / DS).round() as usize;
                    curvature.extend(std::iter::repeat_n(0.0, n));
                    wanted.extend(std::iter::repeat_n(speed, n));
                }
                Piece::Corner {
                    radius,
                    angle,
                    speed,
                } => {
                    let k = angle.signum() / radius;
                    let lt = clothoid_length(radius, angle);
                    let arc = (radius * angle.abs() - lt).max(0.0);
                    let (nt, na) = ((lt / DS).round() as usize, (arc / DS).round() as usize);
                    let ramp = |i: usize| k * (i as f64 + 0.5) / nt as f64;
                    curvature.extend((0..nt).map(ramp));
                    curvature.extend(std::iter::repeat_n(k, na));
                    curvature.extend((0..nt).rev().map(ramp));
                    wanted.extend(std::iter::repeat_n(speed, 2 * nt + na));
                }
                Piece::Stop { dwell } => {
                    stops.push((wanted.len() - 1, dwell));
                }
            }
        }
        let n = curvature.len();
        let (mut x, mut y, mut heading) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        for i in 1..n {
            let mid = heading[i - 1] + 0.5 * DS * curvature[i];
            heading[i] = heading[i - 1] + DS * curvature[i];
            x[i] = x[i - 1] + DS * mid.cos();
            y[i] = y[i - 1] + DS * mid.sin();
        }
        for &(i, _) in &stops {
            wanted[i] = 0.0;
        }
        Self {
            x,
            y,
            heading,
            curvature,
            wanted,
            stops,
        }
    }

    /// The speed along the track (per sample, m/s) from `start` m/s:
    /// at most the wanted speed, reached accelerating at no more than
    /// `drive` and braking at no more than `brake` (both m/s², positive).
    fn speed_profile(&self, start: f64, drive: f64, brake: f64) -> Vec<f64> {
        let mut v: Vec<f64> = self.wanted.clone();
        v[0] = start;
        for i in 1..v.len() {
            v[i] = v[i].min((v[i - 1] * v[i - 1] + 2.0 * drive * DS).sqrt());
        }
        for i in (0..v.len() - 1).rev() {
            v[i] = v[i].min((v[i + 1] * v[i + 1] + 2.0 * brake * DS).sqrt());
        }
        v
    }

    /// The driven speed sampled every `h` s for `duration` s: parked for
    /// `parked` s (or, with `start` > 0, rolling at `start` m/s from the
    /// first sample), then along the profile of [`Track::speed_profile`] with
    /// the stops' dwells, the pedal work smoothed over
    /// [`PEDAL_SMOOTHING`]; (speed m/s, its derivative m/s²). The track
    /// must be long enough for the duration (a panic says so otherwise).
    pub(super) fn drive(
        &self,
        start: f64,
        parked: f64,
        duration: f64,
        h: f64,
        drive: f64,
        brake: f64,
    ) -> (Vec<f64>, Vec<f64>) {
        let v = self.speed_profile(start, drive, brake);
        // Knots (t, v) of the piecewise-linear speed in time.
        let (mut kt, mut kv) = (vec![0.0], vec![start]);
        if parked > 0.0 {
            kt.push(parked);
            kv.push(start);
        }
        let mut stop = self.stops.iter().peekable();
        for i in 1..v.len() {
            let dt = 2.0 * DS / (v[i - 1] + v[i]);
            let t = kt[kt.len() - 1] + dt;
            kt.push(t);
            kv.push(v[i]);
            if let Some(&(_, dwell)) = stop.next_if(|s| s.0 == i) {
                kt.push(t + dwell);
                kv.push(0.0);
            }
        }
        let end = kt[kt.len() - 1];
        assert!(
            end >= duration + PEDAL_SMOOTHING,
            "the track ends after {end:.0} s, before the run's {duration} s"
        );
        // The speed at the fine grid, its running integral, and the moving
        // average over the pedal smoothing (exact for the linear pieces up
        // to the trapezoid rule at h).
        let n = (duration / h).round() as usize;
        let m = (0.5 * PEDAL_SMOOTHING / h).round() as usize;
        let raw: Vec<f64> = (0..=n + m)
            .map(|k| crate::manoeuvre::interpolate(&kt, &kv, k as f64 * h))
            .collect();
        let mut integral = vec![0.0; raw.len()];
        for k in 1..raw.len() {
            integral[k] = integral[k - 1] + 0.5 * h * (raw[k - 1] + raw[k]);
        }
        let speed: Vec<f64> = (0..=n)
            .map(|k| {
                let (lo, hi) = (k.saturating_sub(m), k + m);
                let s = (integral[hi] - integral[lo]) / ((hi - lo) as f64 * h);
                // Parked: 0, not the round-off of the integration.
                if s < 1e-9 {
                    0.0
                } else {
                    s
                }
            })
            .collect();
        let ax: Vec<f64> = (0..=n)
            .map(|k| {
                let (lo, hi) = (k.saturating_sub(m), k + m);
                (raw[hi] - raw[lo]) / ((hi - lo) as f64 * h)
            })
            .collect();
        (speed, ax)
    }

    /// The sample of the centre line nearest to (`x`, `y`), searched
    /// within 40 m of sample `from` (the last one found: the car moves
    /// little between two calls).
    pub(super) fn nearest(&self, from: usize, x: f64, y: f64) -> usize {
        let span = (40.0 / DS) as usize;
        let lo = from.saturating_sub(span / 4);
        let hi = (from + span).min(self.x.len() - 1);
        (lo..=hi)
            .min_by(|&i, &j| {
                let d = |k: usize| (self.x[k] - x).powi(2) + (self.y[k] - y).powi(2);
                d(i).total_cmp(&d(j))
            })
            .unwrap_or(from)
    }

    /// The sample `distance` m along the line from sample `i` (the last
    /// one at the end).
    pub(super) fn ahead(&self, i: usize, distance: f64) -> usize {
        (i + (distance / DS).round() as usize).min(self.x.len() - 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_corner_turns_through_its_angle_with_continuous_curvature() {
        let t = Track::new(&[
            straight(20.0, 10.0),
            corner(30.0, 90.0, 8.0),
            straight(20.0, 10.0),
        ]);
        let last = t.heading.len() - 1;
        assert!((t.heading[last] - 90f64.to_radians()).abs() < 0.01);
        // The curvature never jumps by more than one clothoid step.
        let step = (1.0 / 30.0) / (15.0 / DS);
        for w in t.curvature.windows(2) {
            assert!((w[1] - w[0]).abs() <= 1.01 * step, "{w:?}");
        }
        // Quarter circle of R = 30 m between clothoids of L = 15 m, plus
        // the straights: the tangent length of a symmetric clothoid curve
        // is (R + L²/24R)·tan(θ/2) + L/2 − L³/240R² = 37.8 m for θ = 90°,
        // so the exit is 57.8 m ahead and 57.8 m left.
        let (r, l) = (30.0f64, 15.0f64);
        let tangent = r + l * l / (24.0 * r) + l / 2.0 - l.powi(3) / (240.0 * r * r);
        assert!((t.x[last] - (20.0 + tangent)).abs() < 0.3, "{}", t.x[last]);
        assert!((t.y[last] - (tangent + 20.0)).abs() < 0.3, "{}", t.y[last]);
    }

    #[test]
    fn the_speed_respects_the_pedals_and_stands_still_at_stops() {
        let t = Track::new(&[
            straight(200.0, 15.0),
            Piece::Stop { dwell: 10.0 },
            straight(400.0, 15.0),
        ]);
        let h = 0.01;
        let (u, ax) = t.drive(0.0, 5.0, 60.0, h, 2.0, 3.0);
        // Parked for 5 s (less the smoothing's half width).
        assert!(u[..(4.6 / h) as usize].iter().all(|&v| v == 0.0));
        assert!(u.iter().all(|&v| (0.0..=15.0 + 1e-9).contains(&v)));
        assert!(ax.iter().all(|&a| (-3.0 - 1e-9..=2.0 + 1e-9).contains(&a)));
        // The stop: a stretch of at least 9 s standing still mid-run.
        let mut longest = 0;
        let mut run = 0;
        for &v in &u[(6.0 / h) as usize..] {
            run = if v == 0.0 { run + 1 } else { 0 };
            longest = longest.max(run);
        }
        assert!(longest as f64 * h > 9.0, "{}", longest as f64 * h);
        // The derivative is the speed's.
        for k in (600..u.len() - 1).step_by(97) {
            let d = (u[k + 1] - u[k - 1]) / (2.0 * h);
            assert!((d - ax[k]).abs() < 0.05, "{k}: {d} vs {}", ax[k]);
        }
    }
}
