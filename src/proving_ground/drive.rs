//! Designed manoeuvres driven on the proving ground: the truth of a
//! campaign (its programme, effects and noise seed) drives open-loop
//! manoeuvres given from outside — the scenario files `handling design`
//! writes — and logs them as the programme logs its own runs (its sample
//! rate and channels, its noise levels). The programme's own runs are not
//! touched: the noise of a driven run is drawn from its own generator,
//! seeded by the campaign's seed and the run's name, so adding a run to a
//! campaign leaves every other run bit for bit, and a run's noise does not
//! depend on which other runs are driven with it or in what order.
//!
//! Each run starts from straight running at the manoeuvre's first speed and
//! is logged from its first instant. A logged programme's `ax` is the
//! speed's derivative and its `bank` 0 (a flat pad), both with the
//! programme's noise. Units: SI, rad.

use super::driver::LOG_RATE;
use super::{
    estimator, with_noise, Programme, SynthSpec, Truth, TruthModels, AX_NOISE, BANK_NOISE,
    HANDLING_INTERVAL,
};
use crate::error::{ParamError, ParamReason};
use crate::manoeuvre::Manoeuvre;
use crate::measured::MeasuredRun;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// A manoeuvre to drive, with the name of the run it makes.
#[derive(Debug, Clone, PartialEq)]
pub struct DrivenRun {
    /// The run's name (its file is `<name>.csv`).
    pub name: String,
    /// What the driver does.
    pub manoeuvre: Manoeuvre,
}

/// The runs `truth` logs driving `runs` with the effects, noise and
/// programme of `spec`. An error for a programme whose driver is
/// closed-loop (the analogues of real logs) or one `truth` does not drive.
pub fn drive(
    spec: &SynthSpec,
    truth: Truth,
    runs: &[DrivenRun],
) -> Result<Vec<MeasuredRun>, ParamError> {
    let programme = spec.programme;
    if matches!(
        programme,
        Programme::SedanWinding | Programme::RacingRearSteer
    ) {
        return Err(ParamError::without_value(
            "programme",
            ParamReason::DriveProgramme {
                programme: programme.name().into(),
            },
        ));
    }
    let models = TruthModels::new(spec, truth)?;
    Ok(runs
        .iter()
        .map(|r| driven_run(&models, spec, truth, r))
        .collect())
}

/// The sample interval of `programme`'s logger, s.
fn interval(programme: Programme) -> f64 {
    if programme.logged() {
        1.0 / LOG_RATE
    } else {
        HANDLING_INTERVAL
    }
}

/// FNV-1a of `name`: a hash fixed across releases and platforms (std's
/// hasher is not), for the noise stream of a run by its name.
fn name_hash(name: &str) -> u64 {
    name.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// A driven run, logged with its own noise.
fn driven_run(models: &TruthModels, spec: &SynthSpec, truth: Truth, r: &DrivenRun) -> MeasuredRun {
    let m = &r.manoeuvre;
    let dt = interval(spec.programme);
    let (t0, t1) = (m.start_time(), m.end_time());
    let times: Vec<f64> = (0..)
        .map(|i| t0 + dt * i as f64)
        .take_while(|t| *t <= t1 + 1e-9)
        .collect();
    let (yaw_rate, ay, beta) = models.measure(truth, m, &times);
    // Its own stream: the campaign's runs drew theirs from the seed alone.
    let mut rng = ChaCha8Rng::seed_from_u64(spec.seed ^ DRIVEN_STREAM ^ name_hash(&r.name));
    let n = spec.noise;
    let p = spec.programme;
    let yaw_rate = with_noise(&yaw_rate, n.yaw_rate, &mut rng);
    let ay = with_noise(&ay, n.ay, &mut rng);
    let beta = match p {
        _ if !p.logs_beta() => None,
        Programme::SlowOvalEstimatedBeta => Some(estimator::estimated(&times, &beta, &mut rng)),
        _ => Some(with_noise(&beta, n.beta, &mut rng)),
    };
    // A replay's own `ax` and `bank` are what its car felt (the truth's
    // drive reads them): logged as the programme logs its channels.
    let replay = match m {
        Manoeuvre::Replay(r) => Some(r),
        _ => None,
    };
    let ax = p.logged().then(|| {
        let rate: Vec<f64> = times
            .iter()
            .map(|&t| {
                replay
                    .and_then(|r| r.ax_at(t))
                    .unwrap_or_else(|| m.speed_rate(t))
            })
            .collect();
        with_noise(&rate, AX_NOISE, &mut rng)
    });
    let bank = p.logs_bank().then(|| {
        let bank: Vec<f64> = times
            .iter()
            .map(|&t| replay.map_or(0.0, |r| r.bank_at(t)))
            .collect();
        with_noise(&bank, BANK_NOISE, &mut rng)
    });
    let speed = times.iter().map(|&t| m.speed(t)).collect();
    let steer = times.iter().map(|&t| m.steer(t)).collect();
    MeasuredRun::new(format!("{}.csv", r.name), times, speed, steer, yaw_rate)
        .with_ay(p.logs_ay().then_some(ay))
        .with_beta(beta)
        .with_bank(bank)
        .with_ax(ax)
}

/// What a driven run of `programme` leaves out of the replay `m` of the
/// scenario `path`: its `bank` where the programme logs none (its truth
/// then drives a flat road), its `ax` where the programme logs none.
pub fn dropped_channels(
    programme: Programme,
    path: &std::path::Path,
    m: &Manoeuvre,
) -> Vec<String> {
    let Manoeuvre::Replay(r) = m else {
        return Vec::new();
    };
    let mut said = Vec::new();
    if let Some(b) = r.bank.as_ref().filter(|_| !programme.logs_bank()) {
        let largest = b.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        said.push(format!(
            "{}: the replayed run's `bank` column (up to {} rad, {}°) is dropped: the {} programme logs no bank, and its truth does not drive on it; drive it with a programme that logs one (`--programme oval`, `road-course`, `slow-oval`) to keep it",
            path.display(),
            crate::format::significant(largest, 3),
            crate::format::fixed(largest.to_degrees(), 2),
            programme.name()
        ));
    }
    if r.ax.is_some() && !programme.logged() {
        said.push(format!(
            "{}: the replayed run's `ax` column is dropped: the {} programme logs no ax; drive it with a programme that logs one (`--programme oval`, `road-course`, `slow-oval`) to keep it",
            path.display(),
            programme.name()
        ));
    }
    said
}

/// Mixed into the seed of the driven runs' noise (a constant with many
/// bits set, so no driven run's stream is a programme run's).
const DRIVEN_STREAM: u64 = 0x9E37_79B9_7F4A_7C15;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::manoeuvre::StepSteer;
    use crate::proving_ground::Noise;

    fn spec(seed: u64) -> SynthSpec {
        SynthSpec {
            effects: vec![(
                crate::diagnose::effects::EffectKind::SensorDelay,
                vec![0.05],
            )],
            seed,
            noise: Noise::default(),
            programme: Programme::Handling,
        }
    }

    fn step() -> DrivenRun {
        DrivenRun {
            name: "step".into(),
            manoeuvre: Manoeuvre::StepSteer(StepSteer {
                speed: 20.0,
                amplitude: 0.02,
                trim: 0.0,
                start: 1.0,
                rise_time: 0.15,
                end: 4.0,
            }),
        }
    }

    #[test]
    fn a_driven_run_is_the_truth_plus_its_own_seeded_noise() {
        let s = spec(3);
        let runs = drive(&s, Truth::Augmented, &[step()]).unwrap();
        let r = &runs[0];
        assert_eq!(r.t.len(), 401);
        assert_eq!(r.t[0], 0.0);
        // The truth's delayed response: nothing before the step plus 50 ms.
        let quiet = r.yaw_rate[..100].iter().map(|x| x * x).sum::<f64>() / 100.0;
        assert!(quiet.sqrt() < 2.0 * 0.003, "{}", quiet.sqrt());
        assert!(r.yaw_rate[350] > 0.1, "{}", r.yaw_rate[350]);
        // Seeded: the same again, another seed another noise.
        assert_eq!(drive(&s, Truth::Augmented, &[step()]).unwrap()[0], *r);
        assert_ne!(
            drive(&spec(4), Truth::Augmented, &[step()]).unwrap()[0].yaw_rate,
            r.yaw_rate
        );
        // A second run of the same manoeuvre under another name draws
        // other noise; each run's noise is its own whatever the order.
        let other = DrivenRun {
            name: "step_again".into(),
            ..step()
        };
        let two = drive(&s, Truth::Augmented, &[step(), other.clone()]).unwrap();
        assert_eq!(two[0], *r);
        assert_ne!(two[1].yaw_rate, r.yaw_rate);
        let swapped = drive(&s, Truth::Augmented, &[other, step()]).unwrap();
        assert_eq!(swapped[1], *r);
        assert_eq!(swapped[0], two[1]);
    }

    #[test]
    fn an_analogue_drives_no_designed_manoeuvre() {
        let mut s = spec(1);
        s.effects.clear();
        s.programme = Programme::SedanWinding;
        let e = drive(&s, Truth::Augmented, &[step()]).unwrap_err();
        assert!(e.to_string().contains("closed-loop"), "{e}");
    }
}
