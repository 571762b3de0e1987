//! Where the gap lies, in tables and words: the base model's gap on each
//! run, held-out errors pooled per channel, window and regime before and
//! after the verdict's effects, and the findings of the report (worded in
//! [`super::words`]).
//! Units: each channel's own (rad/s, m/s², rad).

use crate::diagnose::model::channels::reduction;
use crate::diagnose::model::channels::Channel;
use crate::diagnose::model::replay::Prepared;
use crate::diagnose::model::{Augmented, Observed};
use crate::diagnose::report::gap::{channel_gap, regime_acceleration, run_gap, PartGap, Record};
use crate::diagnose::report::outcome::{above_noise, GapFinding};
use crate::diagnose::report::values::SteadyOffset;
use crate::diagnose::report::{Part, RunGap, Shrinkage};
use crate::manoeuvre::interpolate;
use crate::measured::MeasuredRun;

/// The base model's gap on one run, at the run's own samples (the base
/// model has no sensor effects: its history is what the sensors read),
/// each channel against its `trusted` noise floor.
pub(crate) fn base_run_gap(
    base: &Augmented,
    run: &MeasuredRun,
    step: f64,
    trusted: &[f64; 3],
) -> RunGap {
    let p = Prepared::new(run, step, f64::INFINITY);
    let history = p.replay(base);
    let idx = crate::diagnose::report::gap::scored_samples(run);
    let pick = |v: &[f64]| -> Vec<f64> { idx.iter().map(|&i| v[i]).collect() };
    let t = pick(&run.t);
    let yaw_rate: Vec<f64> = t
        .iter()
        .map(|&t| interpolate(&history.t, &history.yaw_rate, t))
        .collect();
    RunGap {
        run: run.path.display().to_string(),
        channels: run_gap(run, &history, trusted),
        bands: crate::diagnose::report::gap::band_gaps(
            &t,
            &pick(&run.steer),
            &pick(&run.yaw_rate),
            &yaw_rate,
        ),
    }
}

/// The high-frequency scatter of each channel a run measures (None where
/// it does not) and its RMS, on its scored samples, as the run's gap
/// estimates its noise floor ([`channel_gap`]): known before any model.
pub(crate) fn run_scatter(run: &MeasuredRun) -> [Option<(f64, f64)>; 3] {
    let idx = crate::diagnose::report::gap::scored_samples(run);
    let pick = |v: &[f64]| -> Vec<f64> { idx.iter().map(|&i| v[i]).collect() };
    let (t, steer) = (pick(&run.t), pick(&run.steer));
    let pre = &crate::diagnose::report::parts::window_samples(&t, &steer)[0].1;
    Channel::ALL.map(|c| {
        c.of(run).map(|v| {
            let v = pick(v);
            let rms = (v.iter().map(|x| x * x).sum::<f64>() / v.len().max(1) as f64).sqrt();
            (crate::diagnose::report::parts::scatter(pre, &v), rms)
        })
    })
}

/// Held-out RMS before/after pooled over runs per channel, window and regime.
pub(crate) fn parts_table(
    runs: &[MeasuredRun],
    prepared: &[Prepared],
    before: &[Observed],
    after: &[Observed],
    floors: &[f64; 3],
) -> Vec<Shrinkage> {
    // (channel, part) → (Σ before², Σ after², n)
    let mut acc: Vec<(Channel, Part, f64, f64, usize)> = Vec::new();
    for (i, p) in prepared.iter().enumerate() {
        let run = &runs[i];
        let at = |v: &[f64]| -> Vec<f64> {
            p.times.iter().map(|&t| interpolate(&run.t, v, t)).collect()
        };
        let steer = at(&run.steer);
        let speed = at(&run.speed);
        let ay = at(&regime_acceleration(run));
        let rec = Record {
            t: &p.times,
            steer: &steer,
            ay: &ay,
            speed: &speed,
        };
        for (ch, m) in &p.measured {
            let gb = channel_gap(*ch, &rec, m, observed_channel(&before[i], *ch));
            let ga = channel_gap(*ch, &rec, m, observed_channel(&after[i], *ch));
            let all_b = PartGap {
                name: Part::All,
                samples: m.len(),
                rms: gb.rms,
                bias: gb.bias,
            };
            let all_a = PartGap {
                rms: ga.rms,
                ..all_b.clone()
            };
            let pb = std::iter::once(&all_b)
                .chain(gb.windows.iter())
                .chain(gb.regimes.iter());
            let pa = std::iter::once(&all_a)
                .chain(ga.windows.iter())
                .chain(ga.regimes.iter());
            for (b, a) in pb.zip(pa) {
                let n = b.samples as f64;
                let part = b.name;
                match acc.iter_mut().find(|x| x.0 == *ch && x.1 == part) {
                    Some(x) => {
                        x.2 += b.rms * b.rms * n;
                        x.3 += a.rms * a.rms * n;
                        x.4 += b.samples;
                    }
                    None => acc.push((*ch, part, b.rms * b.rms * n, a.rms * a.rms * n, b.samples)),
                }
            }
        }
    }
    // Pooled in the order the runs showed them: listed in the parts' own.
    acc.sort_by(|a, b| {
        let key = |x: &(Channel, Part, f64, f64, usize)| (x.0.index(), x.1.order());
        let (ka, kb) = (key(a), key(b));
        ka.0.cmp(&kb.0)
            .then(ka.1 .0.cmp(&kb.1 .0))
            .then(ka.1 .1.total_cmp(&kb.1 .1))
    });
    acc.into_iter()
        .filter(|x| x.4 > 0)
        .map(|(ch, part, b2, a2, n)| {
            let (before, after) = ((b2 / n as f64).sqrt(), (a2 / n as f64).sqrt());
            let nf = floors[ch.index()];
            Shrinkage {
                channel: ch,
                part,
                samples: n,
                before,
                after,
                noise_floor: nf,
                reduction_percent: reduction(before, after, nf),
            }
        })
        .collect()
}

/// The gap's findings (the report words them): overall, per channel where
/// it is largest and where the model is right (parts of at least ten
/// samples, against three noise floors), and the frequency bands of a run
/// whose yaw-rate response is off by more than 1 dB or 10°.
pub(crate) fn gap_summary(
    runs: &[RunGap],
    parts: &[Shrinkage],
    significant: bool,
    j0: f64,
    jn: f64,
) -> Vec<GapFinding> {
    let mut out = vec![GapFinding::Overall {
        significant,
        heldout_error: j0,
        noise_level: jn,
    }];
    for ch in Channel::ALL {
        let rows: Vec<&Shrinkage> = parts.iter().filter(|p| p.channel == ch).collect();
        let Some(all) = rows.iter().find(|p| p.part == Part::All) else {
            continue;
        };
        let nf = all.noise_floor;
        let split = rows
            .iter()
            .filter(|p| p.part != Part::All && p.samples >= 10);
        let wrong: Vec<(Part, f64)> = split
            .clone()
            .filter(|p| above_noise(p.before, nf))
            .map(|p| (p.part, p.before))
            .collect();
        let right: Vec<Part> = split
            .filter(|p| !above_noise(p.before, nf))
            .map(|p| p.part)
            .collect();
        out.push(GapFinding::Channel {
            channel: ch,
            rms: all.before,
            noise_floor: nf,
            significant_runs: runs
                .iter()
                .filter(|r| r.channels.iter().any(|c| c.channel == ch && c.significant))
                .count(),
            runs: runs.len(),
            wrong,
            right,
            offset: SteadyOffset::of(
                &runs
                    .iter()
                    .flat_map(|r| r.channels.iter().filter(|c| c.channel == ch))
                    .map(|c| c.bias)
                    .collect::<Vec<_>>(),
                nf,
                all.before,
            ),
            combined_significant: significant,
        });
    }
    for r in runs {
        for b in &r.bands {
            if b.gain_error_db.abs() > 1.0 || b.phase_error_deg.abs() > 10.0 {
                out.push(GapFinding::Band {
                    run: r.run.clone(),
                    f_low: b.f_low,
                    f_high: b.f_high,
                    gain_error_db: b.gain_error_db,
                    phase_error_deg: b.phase_error_deg,
                });
            }
        }
    }
    out
}

/// A channel of an observation.
pub fn observed_channel(o: &Observed, c: Channel) -> &[f64] {
    match c {
        Channel::YawRate => &o.yaw_rate,
        Channel::Ay => &o.ay,
        Channel::Beta => &o.beta,
    }
}
