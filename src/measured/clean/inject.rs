//! Logger glitches injected into clean runs for tests and benchmarks, in
//! the form the detector reports them, so that detection can be checked
//! against a known truth. Units as the run's.

use super::glitches::scale;
use super::report::{Glitch, GlitchKind, RunChannel, Treatment};
use crate::measured::MeasuredRun;

/// Corrupts a clean run the way loggers do, for tests and benchmarks: in
/// each response channel one zero read, one isolated spike and one value
/// held for eight samples, and in the steer one spike, at seeded places in
/// the driven part of the run (away from its ends and from each other).
/// Returns what was injected, in the form the detector reports it.
pub fn inject_glitches(run: &mut MeasuredRun, seed: u64) -> Vec<Glitch> {
    use rand::{RngExt, SeedableRng};
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let n = run.t.len();
    let name = run.path.display().to_string();
    let mut taken = vec![false; n];
    let mut out = Vec::new();
    let margin = 10.min(n / 4);
    let plan: Vec<(RunChannel, GlitchKind)> =
        [RunChannel::YawRate, RunChannel::Ay, RunChannel::Beta]
            .into_iter()
            .flat_map(|c| {
                [GlitchKind::ZeroRead, GlitchKind::Spike, GlitchKind::Stuck].map(move |k| (c, k))
            })
            .chain(std::iter::once((RunChannel::Steer, GlitchKind::Spike)))
            .collect();
    for (ch, kind) in plan {
        let Some(x) = ch.of(run) else { continue };
        let tt = scale(x, &vec![false; x.len()]).threshold;
        let len = if kind == GlitchKind::Stuck { 8 } else { 1 };
        // A zero read needs a value far from 0 around it; any place will do
        // for the others.
        let mut pick = None;
        for _ in 0..2000 {
            let i = rng.random_range(margin..n - margin - len);
            let free = taken[i.saturating_sub(3)..(i + len + 3).min(n)]
                .iter()
                .all(|t| !t);
            let ok = match kind {
                GlitchKind::ZeroRead => (i - 2..i + 3).all(|k| x[k].abs() > 3.0 * tt),
                _ => true,
            };
            if free && ok {
                pick = Some(i);
                break;
            }
        }
        let Some(i) = pick else { continue };
        let Some(x) = ch.of_mut(run) else { continue };
        let value = match kind {
            GlitchKind::ZeroRead => 0.0,
            GlitchKind::Spike => {
                let sign = if rng.random_bool(0.5) { 1.0 } else { -1.0 };
                0.5 * (x[i - 1] + x[i + 1]) + sign * 3.0 * tt
            }
            _ => x[i],
        };
        for v in &mut x[i..i + len] {
            *v = value;
        }
        taken[i.saturating_sub(3)..(i + len + 3).min(n)]
            .iter_mut()
            .for_each(|t| *t = true);
        out.push(Glitch {
            run: name.clone(),
            t: run.t[i],
            channel: ch,
            kind,
            value,
            samples: len,
            treatment: Treatment::of(ch),
            dropped_with: None,
        });
    }
    out.sort_by(|a, b| a.t.total_cmp(&b.t));
    out
}

#[cfg(test)]
mod tests {
    use super::super::test_signals::run;
    use super::super::{clean_runs, treat_glitches, CleanSettings, CleaningReport};
    use super::*;

    #[test]
    fn injected_glitches_are_found_where_they_were_put() {
        let mut r = run(3000, 0.01, |_| 20.0);
        r.ay = Some(r.yaw_rate.iter().map(|v| 20.0 * v).collect());
        let injected = inject_glitches(&mut r, 42);
        assert_eq!(injected.len(), 7);
        let mut rep = CleaningReport::new(5.0);
        let mut r2 = r.clone();
        treat_glitches(&mut r2, 5.0, &mut rep);
        for g in &injected {
            assert!(
                rep.glitches
                    .iter()
                    .any(|f| f.channel == g.channel && f.kind == g.kind && f.t == g.t),
                "{g:?} not in {:?}",
                rep.glitches
            );
        }
        assert_eq!(rep.glitches.len(), injected.len(), "{:?}", rep.glitches);
    }

    #[test]
    fn glitches_injected_into_synthetic_runs_are_all_found_and_nothing_else() {
        use crate::diagnose::effects::EffectKind;
        use crate::proving_ground::{generate, truth_values, Noise, SynthSpec};
        for (seed, effects) in [
            (1, vec![]),
            (2, vec![EffectKind::SensorDelay]),
            (3, vec![EffectKind::RelaxationLength]),
            (
                4,
                vec![EffectKind::SensorBias, EffectKind::AccelerometerRoll],
            ),
            (5, vec![EffectKind::CorneringStiffness]),
            (6, vec![EffectKind::RoadBank]),
        ] {
            let s = generate(&SynthSpec {
                effects: effects.iter().map(|e| (*e, truth_values(*e))).collect(),
                seed,
                noise: Noise::default(),
                programme: Default::default(),
            });
            let mut injected = Vec::new();
            let mut runs = s.runs.clone();
            for (k, r) in runs.iter_mut().enumerate() {
                injected.extend(inject_glitches(r, seed * 100 + k as u64));
            }
            let (clean, rep) = clean_runs(runs, &CleanSettings::default());
            assert_eq!(clean.len(), s.runs.len());
            let key = |g: &Glitch| {
                (
                    g.run.clone(),
                    g.channel.name(),
                    g.kind.name(),
                    g.t.to_bits(),
                )
            };
            let mut found: Vec<_> = rep.glitches.iter().map(key).collect();
            let mut want: Vec<_> = injected.iter().map(key).collect();
            found.sort();
            want.sort();
            assert_eq!(found, want, "seed {seed}");
            // Spikes and holds always find a place; zero reads need a value far
            // from 0.
            assert!(injected.len() >= 7 * s.runs.len(), "{}", injected.len());
        }
    }
}
