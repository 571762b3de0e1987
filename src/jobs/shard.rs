//! Sharding a job over machines (a Slurm or HTCondor job array): shard K of
//! N solves the units of work `u` with `u mod N = K − 1` (lines of an
//! equilibrium grid, points of a stiffness map) and writes them to
//! `shard-K-of-N.json`; `handling merge` reads the N shard files and writes
//! the outputs of the unsharded run, byte for byte. Every unit is solved as
//! in the unsharded run (its seeds do not depend on the shard), so the
//! result does not depend on N.
//!
//! A shard file keeps a copy of the text of every input the job read, under
//! its absolute path (so the merge runs from any working directory); the
//! merge refuses shards of different runs and inputs that changed since.

use crate::error::{Error, InputError, OptionsError, ShardField};
use crate::report::write_json;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// Shard `index` (1-based) of `count`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Shard {
    /// K, from 1 to N.
    pub index: usize,
    /// N.
    pub count: usize,
}

impl Shard {
    /// Shard `index` of `count`, checked: 1 ≤ K ≤ N.
    pub fn new(index: usize, count: usize) -> Result<Self, Error> {
        if index == 0 || index > count {
            return Err(OptionsError::ShardOutOfRange { index, count }.into());
        }
        Ok(Self { index, count })
    }

    /// Whether unit `unit` (0-based) is this shard's.
    pub fn owns(&self, unit: usize) -> bool {
        unit % self.count == self.index - 1
    }

    /// This shard's units among `units`.
    pub fn units(&self, units: usize) -> Vec<usize> {
        (0..units).filter(|&u| self.owns(u)).collect()
    }

    /// The shard file's name in an output folder.
    pub fn file_name(&self) -> String {
        format!("shard-{}-of-{}.json", self.index, self.count)
    }
}

impl std::fmt::Display for Shard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl std::str::FromStr for Shard {
    type Err = Error;
    /// `K/N` with 1 ≤ K ≤ N.
    fn from_str(s: &str) -> Result<Self, Error> {
        let bad = || {
            Error::Options(OptionsError::ShardText {
                given: s.to_string(),
            })
        };
        let (k, n) = s.split_once('/').ok_or_else(bad)?;
        let (index, count): (usize, usize) = (
            k.trim().parse().map_err(|_| bad())?,
            n.trim().parse().map_err(|_| bad())?,
        );
        Self::new(index, count).map_err(|_| bad())
    }
}

/// The job a shard file belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ShardJob {
    /// `equilibria`: lines of the grid.
    Equilibria,
    /// `study`: points of the stiffness map and RBF pairs.
    Study,
    /// `diagnose --batch`: campaigns of a folder.
    Diagnose,
}

/// A job that shards the units of one input file, by the name its command
/// has: what a caller names to run one shard (Python's `run_shard`); a
/// batch of campaigns shards through `diagnose --batch`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileJob {
    /// `equilibria`: a sweep's lines.
    Equilibria,
    /// `study`: a study's combinations.
    Study,
}

impl FileJob {
    /// Every such job.
    pub const ALL: [FileJob; 2] = [FileJob::Equilibria, FileJob::Study];

    /// Its command's name.
    pub const fn name(self) -> &'static str {
        match self {
            FileJob::Equilibria => "equilibria",
            FileJob::Study => "study",
        }
    }
}

impl std::str::FromStr for FileJob {
    type Err = Error;
    /// The job named `s`; an unknown name is refused with the known ones
    /// and the nearest ("did you mean `equilibria`?").
    fn from_str(s: &str) -> Result<Self, Error> {
        crate::error::named(&Self::ALL, FileJob::name, crate::error::NameKind::Job, s)
            .map_err(Error::from)
    }
}

/// An input of the run as the shard read it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct InputCopy {
    /// Its path as the job read it (absolute in a written shard file).
    pub path: PathBuf,
    /// Its text.
    pub text: String,
}

/// What a shard file holds: the run it belongs to and its units' results.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct ShardFile<T> {
    /// The job.
    pub job: ShardJob,
    /// Which shard.
    pub shard: Shard,
    /// The job's main input (a sweep or study file, a batch's folder;
    /// absolute in a written shard file).
    pub input: PathBuf,
    /// Every input read, with its text.
    pub inputs: Vec<InputCopy>,
    /// Units of work of the whole run.
    pub units: usize,
    /// This shard's units (0-based), in order.
    pub owned: Vec<usize>,
    /// Their results, in the same order.
    pub results: Vec<T>,
}

/// The report of one shard's run: what it solved and where it wrote it.
#[derive(Debug, Clone, Serialize)]
pub struct ShardReport {
    /// The job.
    pub job: ShardJob,
    /// Which shard.
    pub shard: Shard,
    /// Units of work of the whole run.
    pub units: usize,
    /// This shard's units.
    pub owned: usize,
    /// Conditions (points) solved by this shard.
    pub conditions: usize,
    /// The shard file.
    pub path: PathBuf,
}

impl ShardJob {
    /// The job as the command line names it.
    pub fn command(self) -> &'static str {
        match self {
            ShardJob::Equilibria => "equilibria",
            ShardJob::Study => "study",
            ShardJob::Diagnose => "diagnose --batch",
        }
    }

    /// `n` of its units of work, in words: grid lines, combinations,
    /// campaigns.
    pub fn units(self, n: usize) -> String {
        let (one, many) = match self {
            ShardJob::Equilibria => ("grid line", "grid lines"),
            ShardJob::Study => ("combination", "combinations"),
            ShardJob::Diagnose => ("campaign", "campaigns"),
        };
        plural(n, one, many)
    }
}

pub use crate::format::plural;

impl ShardReport {
    /// The report in lines of text.
    pub fn summary(&self) -> Vec<String> {
        // A unit of the equilibria is a line of conditions; the other
        // jobs' units are one each.
        let conditions = if self.conditions == self.owned {
            String::new()
        } else {
            format!(" ({})", plural(self.conditions, "condition", "conditions"))
        };
        vec![format!(
            "shard {} of the {} job: {} of {}{conditions} → {}; merge the {} with `handling merge`",
            self.shard,
            self.job.command(),
            self.owned,
            self.job.units(self.units),
            self.path.display(),
            plural(self.shard.count, "shard file", "shard files"),
        )]
    }
}

/// Copies of the inputs' texts.
pub(crate) fn input_copies(inputs: &[PathBuf]) -> Result<Vec<InputCopy>, Error> {
    inputs
        .iter()
        .map(|p| {
            let text = std::fs::read_to_string(p).map_err(|source| InputError::Io {
                path: p.clone(),
                source,
            })?;
            Ok(InputCopy {
                path: p.clone(),
                text,
            })
        })
        .collect()
}

/// `p` made absolute against the working directory (not resolving links);
/// as given if the working directory cannot be read.
fn absolute(p: &Path) -> PathBuf {
    std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf())
}

/// Writes a shard file (atomically), its input paths made absolute: the
/// merge reads the inputs again, and may run in another directory than
/// the shards (a job array's tasks and its merge job need not share one).
pub(crate) fn write_shard<T: Serialize>(path: &Path, file: &ShardFile<T>) -> Result<(), Error> {
    /// [`ShardFile`]'s fields, in its order, the results borrowed.
    #[derive(Serialize)]
    struct Written<'a, T> {
        job: ShardJob,
        shard: Shard,
        input: PathBuf,
        inputs: Vec<InputCopy>,
        units: usize,
        owned: &'a [usize],
        results: &'a [T],
    }
    let inputs = file
        .inputs
        .iter()
        .map(|c| InputCopy {
            path: absolute(&c.path),
            text: c.text.clone(),
        })
        .collect();
    write_json(
        path,
        &Written {
            job: file.job,
            shard: file.shard,
            input: absolute(&file.input),
            inputs,
            units: file.units,
            owned: &file.owned,
            results: &file.results,
        },
    )
}

/// Which job a shard file belongs to, read from the file.
pub fn shard_job(path: &Path) -> Result<ShardJob, Error> {
    #[derive(Deserialize)]
    struct Head {
        job: ShardJob,
    }
    let head: Head = read_json(path)?;
    Ok(head.job)
}

fn read_json<T: DeserializeOwned>(path: &Path) -> Result<T, Error> {
    let text = std::fs::read_to_string(path).map_err(|source| InputError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    serde_json::from_str(&text).map_err(|e| {
        InputError::problem_at(
            path,
            e.line(),
            e.column(),
            crate::error::InputProblem::NotAShard {
                detail: e.to_string(),
            },
        )
        .into()
    })
}

/// The shard files of one run, read ([`read_shards`]).
pub(crate) struct Shards<T> {
    /// The job's input file (or batch folder).
    pub input: PathBuf,
    /// Its units of work.
    pub units: usize,
    /// Every unit's result, in unit order.
    pub results: Vec<T>,
    /// Files given that are byte for byte another one given (a copy under
    /// another name): read once, each with the one it repeats.
    pub identical: Copies,
}

/// Files that copy another file given, each with the one it repeats.
pub(crate) type Copies = Vec<(PathBuf, PathBuf)>;

impl<T> Shards<T> {
    /// The note on the shard files read once, where there are any:
    /// "2 shard files identical to others given: counted once: a = b, c = b".
    pub fn note(&self) -> Option<String> {
        (!self.identical.is_empty()).then(|| {
            let pairs: Vec<String> = self
                .identical
                .iter()
                .map(|(copy, first)| format!("{} = {}", copy.display(), first.display()))
                .collect();
            format!(
                "{} identical, byte for byte, to {} given before: counted once: {}",
                plural(self.identical.len(), "shard file", "shard files"),
                match self.identical.len() {
                    1 => "another",
                    _ => "others",
                },
                pairs.join(", ")
            )
        })
    }
}

/// A 64-bit FNV-1a digest of `bytes` (Fowler, Noll & Vo): equal for equal
/// bytes, so that a file given twice under two names (a copied shard, a
/// copied runs folder) is read once. Not a cryptographic hash: it tells
/// copies apart from files that differ, not from a forgery.
pub(crate) fn digest(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h: u64, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

/// `paths` without the files whose bytes repeat an earlier, other file's
/// (a copy), and each left out with the earlier one.
fn distinct_files(paths: &[PathBuf]) -> Result<(Vec<PathBuf>, Copies), Error> {
    let mut kept: Vec<(u64, Vec<u8>, PathBuf)> = Vec::new();
    let mut identical = Vec::new();
    for p in paths {
        let bytes = std::fs::read(p).map_err(|source| InputError::Io {
            path: p.clone(),
            source,
        })?;
        let d = digest(&bytes);
        // The digest finds the candidate, the bytes decide; one file named
        // twice is no copy, and is refused as a shard given twice.
        let same_file = |q: &PathBuf| q.canonicalize().ok() == p.canonicalize().ok();
        match kept
            .iter()
            .find(|(k, b, q)| *k == d && *b == bytes && !same_file(q))
        {
            Some((_, _, first)) => identical.push((p.clone(), first.clone())),
            None => kept.push((d, bytes, p.clone())),
        }
    }
    Ok((kept.into_iter().map(|k| k.2).collect(), identical))
}

/// Refuses a merge whose input files changed since the shards read them
/// (a folder's copy is its listing, which the job checks itself). Apart
/// from [`read_shards`] so that it reads on a screen.
fn inputs_unchanged(inputs: &[InputCopy]) -> Result<(), Error> {
    for c in inputs.iter().filter(|c| !c.path.is_dir()) {
        let now = std::fs::read_to_string(&c.path).unwrap_or_default();
        if now != c.text {
            return Err(OptionsError::InputChanged {
                path: c.path.clone(),
            }
            .into());
        }
    }
    Ok(())
}

/// Reads the shard files of one run: all of one job, one input, one N,
/// every shard exactly once (a file byte for byte another one given is
/// read once, and said: [`Shards::note`]), and inputs unchanged since.
pub(crate) fn read_shards<T: DeserializeOwned>(
    job: ShardJob,
    given: &[PathBuf],
) -> Result<Shards<T>, Error> {
    let (paths, identical) = distinct_files(given)?;
    let paths = &paths[..];
    let files: Vec<ShardFile<T>> = paths
        .iter()
        .map(|p| read_json(p))
        .collect::<Result<_, _>>()?;
    let Some(first) = files.first() else {
        return Err(OptionsError::NoShards.into());
    };
    let count = first.shard.count;
    let mut seen = vec![false; count];
    for (f, p) in files.iter().zip(paths) {
        let differ = |field: ShardField| {
            Error::Options(OptionsError::ShardsDiffer {
                path: p.clone(),
                first: paths[0].clone(),
                field,
            })
        };
        if f.job != job {
            return Err(differ(ShardField::Job));
        }
        if f.input != first.input || f.inputs != first.inputs {
            return Err(differ(ShardField::Input));
        }
        if f.shard.count != count || f.units != first.units {
            return Err(differ(ShardField::Count));
        }
        if f.owned != f.shard.units(f.units) || f.results.len() != f.owned.len() {
            return Err(OptionsError::ShardUnits {
                path: p.clone(),
                index: f.shard.index,
                count: f.shard.count,
            }
            .into());
        }
        if std::mem::replace(&mut seen[f.shard.index - 1], true) {
            return Err(OptionsError::ShardTwice {
                path: p.clone(),
                index: f.shard.index,
                count: f.shard.count,
            }
            .into());
        }
    }
    let missing: Vec<usize> = (1..=count).filter(|k| !seen[k - 1]).collect();
    if !missing.is_empty() {
        return Err(OptionsError::ShardsMissing { missing, count }.into());
    }
    inputs_unchanged(&first.inputs)?;
    let (input, units) = (first.input.clone(), first.units);
    let mut slots: Vec<Option<T>> = (0..units).map(|_| None).collect();
    for f in files {
        for (u, r) in f.owned.into_iter().zip(f.results) {
            slots[u] = Some(r);
        }
    }
    let results = slots
        .into_iter()
        .map(|r| r.expect("every unit is owned by exactly one shard"))
        .collect();
    Ok(Shards {
        input,
        units,
        results,
        identical,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_job_name_one_letter_off_is_refused_with_the_nearest() {
        assert_eq!("study".parse::<FileJob>().unwrap(), FileJob::Study);
        let e = "equilibrium".parse::<FileJob>().unwrap_err().to_string();
        assert_eq!(
            e,
            "unknown job `equilibrium` (did you mean `equilibria`?): one of equilibria, study"
        );
    }

    /// FNV-1a's published values (Fowler, Noll & Vo's test vectors).
    #[test]
    fn the_digest_is_fnv1a() {
        assert_eq!(digest(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(digest(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(digest(b"foobar"), 0x8594_4171_f739_67e8);
    }

    #[test]
    fn shards_partition_the_units_and_parse_from_k_over_n() {
        for n in [1, 3, 7] {
            let mut all: Vec<usize> = (1..=n)
                .flat_map(|k| Shard { index: k, count: n }.units(20))
                .collect();
            all.sort();
            assert_eq!(all, (0..20).collect::<Vec<_>>());
        }
        assert_eq!(
            "3/7".parse::<Shard>().unwrap(),
            Shard { index: 3, count: 7 }
        );
        for bad in ["0/3", "4/3", "3", "a/b", "1/0"] {
            let e = bad.parse::<Shard>().unwrap_err().to_string();
            assert!(e.contains("expected K/N"), "{bad}: {e}");
        }
    }
}
