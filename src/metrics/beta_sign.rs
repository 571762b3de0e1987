//! A sideslip logged in the other sign convention, found from the run's
//! own lateral channels. On a flat road a body-fixed accelerometer reads
//! `a_y = u·(β̇ + r)` (ISO 8855, small β, steady speed), so the sideslip's
//! rate is `β̇ = a_y/u − r`: a measured β whose rate moves against it —
//! their correlation over the run below [`AGAINST`] — turns the other way
//! from the car, and its steady sideslip reads with the wrong sign (at
//! speed a left turn's β is negative). As the diagnosis refuses a sideslip
//! that moves against its base model's (a sensor's noise and a wrong size
//! weaken a correlation towards 0, never reverse it), the metrics say so.
//! Both rates are smoothed over [`HALF_WIDTH`] each side (β̇ by the
//! difference across the window, `a_y/u − r` by its mean there), masked
//! samples and crawls left out. Units: SI, rad.

use crate::measured::MeasuredRun;
use crate::stats::CentredSums;

/// Below this correlation of β̇ with `a_y/u − r` the sideslip is taken as
/// logged in the other sign convention; the diagnosis takes a β against
/// its base model's by the same threshold. A real sideslip sensor or
/// estimator follows the car in sign (the shape of a step, a ramp or a
/// turn is the car's): noise and a wrong size only weaken the
/// correlation towards 0, never reverse it.
pub(crate) const AGAINST: f64 = -0.5;

/// Half the window the rates are smoothed over, s.
const HALF_WIDTH: f64 = 0.05;

/// Least swing of `a_y/u − r` from its mean, rad/s, for the correlation
/// to say anything: a straight run's is noise about the sensors' offsets
/// (0.05 m/s² of `a_y` noise at 22 m/s, smoothed, about 0.0002 rad/s); a
/// 1° step at 80 km/h swings it by 0.019 rad/s.
const SWING: f64 = 0.005;

/// Slowest sample judged, m/s: `a_y/u` grows without bound at a crawl.
const MIN_SPEED: f64 = 5.0;

/// Widest half window tried, s: a step's sideslip transient lasts a few
/// tenths of a second, and a window much wider than it averages it away.
const WIDEST: f64 = 0.8;

/// Fewest independent windows (the run's usable samples over the window's
/// width) a correlation must rest on: with fewer, chance alone reaches
/// ±0.5.
const MIN_WINDOWS: f64 = 12.0;

/// Fisher's z a correlation must reach to be judged: below it the run
/// cannot tell a sideslip with the car from one against it.
const MIN_Z: f64 = 3.0;

/// β̇ (by the difference across `2w` samples) and the mean of `a_y/u − r`
/// there, at every sample whose window is usable.
fn rates(
    run: &MeasuredRun,
    ay: &[f64],
    beta: &[f64],
    w: usize,
    usable: &[bool],
) -> Vec<(f64, f64)> {
    let (t, n) = (&run.t, run.t.len());
    (w..n.saturating_sub(w))
        .filter(|&i| usable[i - w..=i + w].iter().all(|&u| u))
        .map(|i| {
            let rate = (beta[i + w] - beta[i - w]) / (t[i + w] - t[i - w]);
            let kin = (i - w..=i + w)
                .map(|k| ay[k] / run.speed[k] - run.yaw_rate[k])
                .sum::<f64>()
                / (2 * w + 1) as f64;
            (rate, kin)
        })
        .filter(|(a, b)| a.is_finite() && b.is_finite())
        .collect()
}

/// The correlation of β̇ with `a_y/u − r` over `run` (`None` without `ay`
/// or `beta`, or without a swing of the kinematic rate at the narrowest
/// window). β̇ by a difference across the window carries β's own noise
/// σ_β as `σ_β·√2/(2w·dt)`: at 0.05 s a 0.001 rad scatter at 100 Hz is
/// 0.014 rad/s, the size of a step's sideslip rate, and a negated β
/// correlated at −0.3, unseen. Both sides integrate over the same window
/// (β(t+w) − β(t−w) = ∫(a_y/u − r) dt at any width), so the window is
/// widened, doubling up to [`WIDEST`] while at least [`MIN_WINDOWS`]
/// independent windows remain, and the correlation taken where it is
/// most significant (Fisher's z on the independent windows; below
/// [`MIN_Z`], `None`).
fn correlation(run: &MeasuredRun) -> Option<f64> {
    let (ay, beta) = (run.ay.as_ref()?, run.beta.as_ref()?);
    let n = run.t.len();
    let mut usable = vec![true; n];
    run.masked.iter().for_each(|&i| usable[i] = false);
    (0..n).for_each(|i| usable[i] &= run.speed[i] >= MIN_SPEED);
    let dt = crate::measured::clean::median_interval(&run.t);
    let narrowest = ((HALF_WIDTH / dt).round() as usize).max(1);
    let widest = ((WIDEST / dt).round() as usize).max(narrowest);
    let mut best: Option<(f64, f64)> = None;
    let mut w = narrowest;
    while w <= widest {
        let pairs = rates(run, ay, beta, w, &usable);
        let windows = pairs.len() as f64 / (2 * w) as f64;
        if pairs.len() < 10 || (w > narrowest && windows < MIN_WINDOWS) {
            break;
        }
        let (rates, kinematic): (Vec<f64>, Vec<f64>) = pairs.into_iter().unzip();
        if w == narrowest {
            let my = kinematic.iter().sum::<f64>() / kinematic.len() as f64;
            let swing = kinematic.iter().fold(0.0_f64, |a, y| a.max((y - my).abs()));
            if swing < SWING {
                return None;
            }
        }
        if let Some(k) = CentredSums::of(&rates, &kinematic).correlation() {
            let z = k.clamp(-0.999_999, 0.999_999).atanh() * (windows - 3.0).max(1.0).sqrt();
            if best.is_none_or(|(_, bz)| z.abs() > bz.abs()) {
                best = Some((k, z));
            }
        }
        w *= 2;
    }
    best.filter(|(_, z)| z.abs() >= MIN_Z).map(|(k, _)| k)
}

/// The warning of a run whose sideslip turns against its lateral
/// kinematics, with the correlation.
pub(crate) fn against_kinematics(run: &MeasuredRun) -> Option<String> {
    let k = correlation(run)?;
    (k < AGAINST).then(|| {
        // -0.5004 is not "-0.50" beside "below -0.5".
        let k = crate::format::fixed_apart(&[k, AGAINST], 2).swap_remove(0);
        format!(
            "the sideslip turns against the car: its rate correlates at {k} with ay/u − r (β̇ = ay/u − r on a flat road, ISO 8855; below {AGAINST} it is taken as reversed, as the diagnosis refuses a β against its model's): `beta` is logged in the other sign convention (FORMATS.md: at speed a left turn's β is negative)? Negate the column; the steady sideslip and the metrics read from β carry the wrong sign"
        )
    })
}
