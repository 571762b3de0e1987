//! A sideslip logged in the other sign convention, found against the base
//! model before any candidate is fitted. The yaw rate's sign is judged
//! against the steer when the runs are read (`io::campaign::runs`); the
//! sideslip's has no such kinematic test: at the CG β = b·r/u − α_r turns
//! with the yaw rate at low speed and against it above the car's
//! "tangent speed", so its sign relation to r depends on the tyres. The
//! base model knows them: its replayed β follows the measured one (in a
//! turn at speed both negative for a left turn, ISO 8855) however wrong
//! its size. A measured β that moves against it over the runs — their
//! pooled correlation below [`AGAINST`] — is negated: fitted, it makes the gap
//! a sign slip that no effect explains ("outside the library", β carrying
//! most of the error). Units: SI, rad.
//!
//! Over the runs together the sideslip may move with the model and one
//! file's against it (a logger set up differently for one session): such a
//! file is named ([`FileAgainst`]), its pieces pooled (a piece of a long log
//! where the model misses a transient may reach −0.8 alone; a file's sign
//! convention is the same throughout), and refused where its correlation
//! is a sign slip's ([`SLIP`]): scored as logged, one run's negated β
//! carried 70 % of the gap and sank a right verdict. Every file that
//! slips is named in the one refusal, each with its correlation.

use crate::diagnose::campaign::Campaign;
use crate::diagnose::model::replay::Prepared;
use crate::diagnose::model::Augmented;
use crate::error::{BetaAgainstModel, FilesAgainst};
use crate::measured::clean::source_file;
use crate::measured::MeasuredRun;
use crate::stats::CentredSums;
use rayon::prelude::*;

/// Below this correlation of a run's measured sideslip with the base
/// model's, the run's `beta` is taken as negated: the threshold `metrics`
/// judges a β against the run's lateral kinematics by, one rule for both.
pub(crate) use crate::metrics::beta_sign::AGAINST;

/// The replayed sideslip must swing at least this much (centred RMS, rad)
/// over a run for its correlation to say anything: a straight run's β is
/// noise about an offset.
const SWING: f64 = 0.003;

/// The centred sums of run `run`'s measured β against `base`'s replayed β
/// over its scored samples, each centred on its own mean (an offset is no
/// sign); `None` without a `beta` channel or a swing of the replayed β.
fn sums(base: &Augmented, run: &MeasuredRun, step: f64) -> Option<CentredSums> {
    let beta = run.beta.as_ref()?;
    // The samples the gap scores: all but the masked (logger glitches).
    let mut keep = vec![true; run.t.len()];
    for &i in &run.masked {
        keep[i] = false;
    }
    let idx: Vec<usize> = (0..run.t.len()).filter(|&i| keep[i]).collect();
    if idx.len() < 10 {
        return None;
    }
    let history = Prepared::new(run, step, f64::INFINITY).replay(base);
    let sim: Vec<f64> = idx
        .iter()
        .map(|&i| crate::manoeuvre::interpolate(&history.t, &history.beta, run.t[i]))
        .collect();
    let measured: Vec<f64> = idx.iter().map(|&i| beta[i]).collect();
    let s = CentredSums::of(&sim, &measured);
    let swing = s.x_rms();
    (swing >= SWING && s.yy > 0.0 && swing.is_finite()).then_some(s)
}

/// A file whose measured β moves against the base model's (its runs'
/// pooled correlation below [`AGAINST`]) where the campaign's as a whole
/// does not.
#[derive(Debug, Clone, PartialEq)]
pub struct FileAgainst {
    /// The file.
    pub file: String,
    /// Its runs' pooled correlation with the base model's β.
    pub correlation: f64,
    /// The samples judged.
    pub samples: usize,
}

/// Refuses a campaign whose measured β moves against the base model's over
/// all its runs (their pooled correlation below [`AGAINST`]), naming each
/// run against with its own correlation. A single run against is no sign
/// slip (a real log's segment where the model misses a transient may
/// reach −0.8): a logger's convention is the same in every run of it.
/// Otherwise returns the files against it ([`FileAgainst`]), where the
/// runs come from more than one file.
pub(crate) fn check(c: &Campaign, base: &Augmented) -> Result<Vec<FileAgainst>, BetaAgainstModel> {
    let judged: Vec<(String, CentredSums)> = c
        .runs
        .par_iter()
        .filter_map(|r| sums(base, r, c.settings.step).map(|s| (r.path.display().to_string(), s)))
        .collect();
    let all = judged
        .iter()
        .fold(CentredSums::default(), |a, (_, s)| a.pooled(*s));
    let against = |file: Option<&str>| -> Vec<(String, f64, usize)> {
        judged
            .iter()
            .filter(|(run, _)| file.is_none_or(|f| source_file(std::path::Path::new(run)) == f))
            .filter_map(|(run, s)| Some((run.clone(), s.correlation()?, s.n)))
            .filter(|(_, k, _)| *k < 0.0)
            .collect()
    };
    let pooled = match all.correlation() {
        Some(k) if k < AGAINST => k,
        _ => {
            let files = files_against(&judged);
            // Every file that slips, in one refusal: named one at a time,
            // the user heard of the second only after fixing the first.
            let slips: Vec<&FileAgainst> = files.iter().filter(|f| is_slip(f)).collect();
            if slips.is_empty() {
                return Ok(files);
            }
            let names: Vec<&str> = slips.iter().map(|f| f.file.as_str()).collect();
            return Err(BetaAgainstModel {
                correlation: slips[0].correlation,
                samples: slips[0].samples,
                against: names.iter().flat_map(|f| against(Some(*f))).collect(),
                judged: judged.len(),
                files: Some(FilesAgainst {
                    files: slips
                        .iter()
                        .map(|f| (f.file.clone(), f.correlation, f.samples))
                        .collect(),
                    others: others_of(&judged, &names),
                }),
            });
        }
    };
    Err(BetaAgainstModel {
        correlation: pooled,
        samples: all.n,
        against: against(None),
        judged: judged.len(),
        files: None,
    })
}

/// Below this correlation, over at least [`SLIP_SAMPLES`] samples, one
/// file's β against the model while the others' move with it is a sign
/// slip, refused as the whole campaign's is: a stretch the model misses
/// weakens a correlation, it does not reverse a whole file's to −0.9
/// (the blind tester's run with β negated: −0.99 over 601 samples; the
/// Putnam log's worst segment, −0.84, is a piece of one file).
const SLIP: f64 = -0.9;

/// The samples a file's correlation must rest on to be a [`SLIP`].
const SLIP_SAMPLES: usize = 200;

/// Whether file `f`, against the others, is a sign slip.
fn is_slip(f: &FileAgainst) -> bool {
    f.correlation < SLIP && f.samples >= SLIP_SAMPLES
}

/// The pooled correlation of the runs from none of `files`.
fn others_of(judged: &[(String, CentredSums)], files: &[&str]) -> f64 {
    judged
        .iter()
        .filter(|(run, _)| !files.contains(&source_file(std::path::Path::new(run)).as_str()))
        .fold(CentredSums::default(), |a, (_, s)| a.pooled(*s))
        .correlation()
        .unwrap_or(f64::NAN)
}

/// The files whose runs' pooled β correlation is below [`AGAINST`], where
/// `judged` (per run: its file and sums) spans more than one file.
fn files_against(judged: &[(String, CentredSums)]) -> Vec<FileAgainst> {
    let mut files: Vec<(String, CentredSums)> = Vec::new();
    for (run, s) in judged {
        // A piece (`#2`) or a segment (`[22]`) is judged with its file.
        let file = source_file(std::path::Path::new(run));
        match files.iter_mut().find(|(f, _)| *f == file) {
            Some((_, sums)) => *sums = sums.pooled(*s),
            None => files.push((file, *s)),
        }
    }
    if files.len() < 2 {
        return Vec::new();
    }
    files
        .into_iter()
        .filter_map(|(file, s)| {
            let k = s.correlation()?;
            (k < AGAINST).then_some(FileAgainst {
                file,
                correlation: k,
                samples: s.n,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sums(k: f64) -> CentredSums {
        let x = [0.0, 1.0, 2.0, 3.0];
        let y: Vec<f64> = x.iter().map(|v| k * v).collect();
        CentredSums::of(&x, &y)
    }

    #[test]
    fn one_file_against_the_others_is_named_with_its_pieces_pooled() {
        let judged = vec![
            ("a.csv".to_string(), sums(1.0)),
            ("b.csv#1".to_string(), sums(-1.0)),
            ("b.csv#2[1]".to_string(), sums(-2.0)),
            ("c.csv".to_string(), sums(1.0)),
        ];
        let against = files_against(&judged);
        assert_eq!(against.len(), 1);
        assert_eq!(against[0].file, "b.csv");
        assert_eq!(against[0].samples, 8);
        // Pooled: Σxy = −5 − 10, Σxx = 5 + 5, Σyy = 5 + 20: −15/√250.
        assert!((against[0].correlation + 3.0 / 10f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn pieces_of_one_file_are_never_named_against_each_other() {
        // A long log's pieces: one against alone, the file as a whole with.
        let judged = vec![
            ("log.csv[1]".to_string(), sums(1.0)),
            ("log.csv[2]".to_string(), sums(1.0)),
            ("log.csv[3]".to_string(), sums(-1.0)),
        ];
        assert!(files_against(&judged).is_empty());
    }

    #[test]
    fn a_file_against_the_others_is_a_sign_slip_only_when_nearly_reversed_over_many_samples() {
        let f = |correlation, samples| FileAgainst {
            file: "b.csv".into(),
            correlation,
            samples,
        };
        assert!(is_slip(&f(-0.99, 601)));
        // A weaker reversal is a stretch the model misses: named, not refused.
        assert!(!is_slip(&f(-0.84, 5000)));
        // Too few samples to tell.
        assert!(!is_slip(&f(-0.99, 150)));
        let judged = vec![
            ("a.csv".to_string(), sums(1.0)),
            ("b.csv".to_string(), sums(-1.0)),
            ("c.csv".to_string(), sums(2.0)),
        ];
        // Pooled: Σxy = 5 + 10, Σxx = 5 + 5, Σyy = 5 + 20: 15/√250.
        assert!((others_of(&judged, &["b.csv"]) - 3.0 / 10f64.sqrt()).abs() < 1e-12);
        // Two files against: the others are the third alone (a perfect +1).
        assert!((others_of(&judged, &["a.csv", "b.csv"]) - 1.0).abs() < 1e-12);
    }
}
