//! One run per output folder: a lock file, `.handling.lock`, created in the
//! folder with `create_new` (atomic: of two runs, one creates it and the
//! other is refused) and holding the process id of the run that owns it.
//! The lock is released (the file removed, and the folders the lock created
//! removed again if they are still empty) when the last copy of the
//! [`OutputLock`] is dropped, so a failed run leaves nothing behind.
//!
//! A run that was killed leaves its lock behind; the next run finds the
//! process gone (on Linux, `/proc/<pid>` absent or a zombie), takes the lock
//! over with a note on stderr. Whenever a run takes a folder, it removes
//! the hidden files that runs no longer running left there (temporary
//! outputs `.<name>.partial-<pid>.<ext>`, see [`super::write_atomic`], and
//! locks moved aside in a take-over), named by a lock or not: a run killed
//! in the middle of a take-over leaves a dead run's files that no lock
//! names any more.
//! A lock naming a running process that started after the lock was
//! written is taken over too: that process is not the run that wrote it,
//! but another program given the dead run's id (ids are reused: after a
//! restart, or in a container). Where process ids cannot be checked, a
//! lock is taken as live and the message says which file to remove.
//!
//! A lock that names no process — empty, text that is no process id or
//! bytes that are not text (a disk that filled as it was written, an
//! editor's save), each said as such in the note — is taken over
//! once it is older than [`NAMELESS_AGE`]: a live run writes its id within
//! microseconds of creating the file, so a nameless lock that old is no
//! live run's. A younger one is refused as busy, the message saying when
//! it will be taken over.

use crate::error::{Error, OutputError, WriteStep};
use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Name of the lock file inside an output folder.
pub const LOCK_FILE: &str = ".handling.lock";

/// Age, s, after which a lock file that names no process is taken over.
pub const NAMELESS_AGE: f64 = 10.0;

/// Age of `file` since it was last written, s (0 when unknown).
fn age(file: &Path) -> f64 {
    fs::metadata(file)
        .and_then(|m| m.modified())
        .ok()
        .and_then(|t| t.elapsed().ok())
        .map_or(0.0, |d| d.as_secs_f64())
}

/// The process id a lock's bytes name: a decimal number, blanks around
/// it allowed, above 0 (0 is the kernel's scheduler, never a run: a lock
/// holding it names no process).
fn process_named(bytes: &[u8]) -> Option<u32> {
    let pid: u32 = std::str::from_utf8(bytes).ok()?.trim().parse().ok()?;
    (pid > 0).then_some(pid)
}

/// What a lock that names no process holds, as its take-over note says:
/// nothing (or blanks), text, or bytes that are no text (a disk that
/// filled, a crashed editor).
fn nameless(bytes: &[u8]) -> String {
    match std::str::from_utf8(bytes) {
        Ok("") => "is empty".into(),
        Ok(t) if t.trim().is_empty() => format!(
            "holds only blanks ({})",
            crate::format::plural(t.chars().count(), "character", "characters")
        ),
        Ok(t) => format!(
            "names no process ({})",
            crate::format::plural(t.trim().chars().count(), "character", "characters")
        ),
        Err(_) => format!(
            "names no process ({} that are not text)",
            crate::format::plural(bytes.len(), "byte", "bytes")
        ),
    }
}

/// A held output folder (cheap to clone: copies share the one lock).
#[derive(Debug, Clone, Default)]
pub struct OutputLock {
    /// Released when the last copy drops; none for a report not made by a
    /// run (a default).
    _held: Option<Arc<Held>>,
}

#[derive(Debug)]
struct Held {
    file: PathBuf,
    /// Folders the lock created, deepest first.
    created: Vec<PathBuf>,
    /// False when this process already held the lock (a second job of the
    /// same process into the same folder): the first holder removes it.
    owner: bool,
}

impl Drop for Held {
    fn drop(&mut self) {
        if self.owner {
            let _ = fs::remove_file(&self.file);
        }
        for dir in &self.created {
            if fs::remove_dir(dir).is_err() {
                break;
            }
        }
    }
}

/// Whether process `pid` is running: `Some(false)` when it is gone or a
/// zombie, `None` when this system cannot tell.
fn alive(pid: u32) -> Option<bool> {
    let proc_root = Path::new("/proc");
    if !proc_root.join("self").exists() {
        return None;
    }
    let Ok(stat) = fs::read_to_string(proc_root.join(pid.to_string()).join("stat")) else {
        return Some(false);
    };
    // The state follows the parenthesised command name.
    let state = stat
        .rsplit(')')
        .next()
        .and_then(|s| s.trim().chars().next());
    Some(!matches!(state, Some('Z' | 'X')))
}

/// Clock ticks a second of the start times /proc gives (Linux's USER_HZ:
/// 100 on every architecture but Alpha, whatever the kernel's own tick).
const USER_HZ: f64 = 100.0;

/// How long process `pid` has been running, s, where /proc tells.
fn running_for(pid: u32) -> Option<f64> {
    let stat = fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    // Field 22, the start in ticks since boot, is the 20th after the
    // parenthesised command name (which may hold blanks).
    let start: f64 = stat
        .rsplit(')')
        .next()?
        .split_whitespace()
        .nth(19)?
        .parse()
        .ok()?;
    let uptime = fs::read_to_string("/proc/uptime").ok()?;
    let uptime: f64 = uptime.split_whitespace().next()?.parse().ok()?;
    Some(uptime - start / USER_HZ)
}

/// Seconds by which a process must have started after its lock was
/// written to be judged another program: the start and the file's time
/// come from two clocks, each read to 10 ms, the file's set when the id
/// was written, milliseconds after the run started.
const START_MARGIN: f64 = 2.0;

/// Why the lock `file`, which names process `pid`, is stale, or `None`
/// when that process may be the run that wrote it: gone (a killed run),
/// or running but started after the lock was written, so another program
/// that the system gave the dead run's id (after a restart, or in a
/// container whose first process takes the same small ids), which is no
/// run of this tool holding the folder.
fn stale_because(pid: u32, file: &Path) -> Option<String> {
    match alive(pid) {
        Some(false) => Some(format!(
            "was left by process {pid}, which is no longer running (killed?)"
        )),
        Some(true) => {
            let lock_age = age(file);
            let ran = running_for(pid)?;
            (ran + START_MARGIN < lock_age).then(|| {
                format!(
                    "was left by process {pid}, which is no longer running: process {pid} now is another program, started {:.0} s after the lock was written",
                    lock_age - ran
                )
            })
        }
        None => None,
    }
}

/// The folders `create_dir_all(dir)` is about to create, deepest first.
fn missing_folders(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut here = Some(dir);
    while let Some(p) = here.filter(|p| !p.as_os_str().is_empty() && !p.exists()) {
        out.push(p.to_path_buf());
        here = p.parent();
    }
    out
}

/// The process that left `name` behind, for the hidden files a run makes
/// in its folder and removes again: a temporary output
/// (`.<name>.partial-<pid>.<ext>`) or a lock moved aside in a take-over
/// (`.<lock>.stale-<pid>`). `None` for any other file.
fn leftover_of(name: &str) -> Option<u32> {
    if !name.starts_with('.') {
        return None;
    }
    let digits = |tail: &str| -> Option<u32> {
        let end = tail
            .find(|c: char| !c.is_ascii_digit())
            .unwrap_or(tail.len());
        tail[..end].parse().ok()
    };
    if let Some(at) = name.rfind(".partial-") {
        return digits(&name[at + ".partial-".len()..]);
    }
    let at = name.rfind(".stale-")?;
    let tail = &name[at + ".stale-".len()..];
    tail.bytes()
        .all(|b| b.is_ascii_digit())
        .then(|| digits(tail))?
}

/// Removes the hidden files that runs no longer running left in `dir`
/// (see [`leftover_of`]). Run once the lock is held, whoever held it
/// before: a run killed while it took a dead run's lock over leaves that
/// run's temporary files named by no lock, and they would stay for good
/// if only the files of the process a lock names were removed. A file
/// of a live process (another output's run in a shared folder) stays.
fn remove_leftovers(dir: &Path) {
    let me = std::process::id();
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        let Some(pid) = leftover_of(&name) else {
            continue;
        };
        if pid != me && alive(pid) == Some(false) {
            let _ = fs::remove_file(e.path());
        }
    }
}

impl OutputLock {
    /// Takes output folder `dir` (created if missing) for this run, or
    /// refuses when another live run holds it.
    pub fn acquire(dir: &Path) -> Result<Self, Error> {
        Self::acquire_file(dir, LOCK_FILE)
    }

    /// Takes the outputs named `<stem>.*` in folder `dir` for this run (a
    /// lock `.<stem>.handling.lock`): for a job whose outputs share a folder
    /// with other runs' (a fitted tyre file beside others), so that two runs
    /// writing the same files are refused and runs writing others are not.
    pub fn acquire_outputs(dir: &Path, stem: &str) -> Result<Self, Error> {
        Self::acquire_file(dir, &format!(".{stem}{LOCK_FILE}"))
    }

    fn acquire_file(dir: &Path, name: &str) -> Result<Self, Error> {
        let created = missing_folders(dir);
        fs::create_dir_all(dir).map_err(|source| OutputError::Io {
            path: dir.to_path_buf(),
            step: WriteStep::Create,
            source,
        })?;
        let file = dir.join(name);
        let me = std::process::id();
        // Two rounds: the second after a stale lock was removed.
        for _ in 0..2 {
            match fs::OpenOptions::new()
                .write(true)
                .create_new(true)
                .open(&file)
            {
                Ok(mut f) => {
                    f.write_all(format!("{me}\n").as_bytes())
                        .and_then(|()| f.sync_all())
                        .map_err(|source| OutputError::Io {
                            path: file.clone(),
                            step: WriteStep::Write,
                            source,
                        })?;
                    remove_leftovers(dir);
                    return Ok(Self::held(file, created, true));
                }
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {}
                Err(source) => {
                    return Err(OutputError::Io {
                        path: file,
                        step: WriteStep::Create,
                        source,
                    }
                    .into())
                }
            }
            // A folder reads as no bytes, which would be judged an empty
            // lock and moved aside for good: it is named for what it is.
            if file.is_dir() {
                return Err(OutputError::LockIsAFolder {
                    folder: dir.to_path_buf(),
                    lock: file,
                }
                .into());
            }
            let text = fs::read(&file).unwrap_or_default();
            let holder = process_named(&text);
            match holder {
                Some(pid) if pid == me => return Ok(Self::held(file, created, false)),
                Some(pid) => match stale_because(pid, &file) {
                    Some(why) => Self::take_over(dir, &file, &text, &why)?,
                    None => return Err(Self::busy(dir, &file, &format!("process {pid}"))),
                },
                None => {
                    // A lock being written this instant holds no number
                    // yet: look again before judging it.
                    std::thread::sleep(std::time::Duration::from_millis(50));
                    let again = fs::read(&file).unwrap_or_default();
                    if process_named(&again).is_some() {
                        continue;
                    }
                    let old = age(&file);
                    if old <= NAMELESS_AGE {
                        return Err(Self::busy(
                            dir,
                            &file,
                            &format!("an unknown process: the lock names none, and is taken over once it is {NAMELESS_AGE} s old"),
                        ));
                    }
                    let what = nameless(&again);
                    Self::take_over(dir, &file, &again, &format!("{what} and is {old:.0} s old"))?;
                }
            }
        }
        Err(Self::busy(dir, &file, "another run"))
    }

    fn held(file: PathBuf, created: Vec<PathBuf>, owner: bool) -> Self {
        Self {
            _held: Some(Arc::new(Held {
                file,
                created,
                owner,
            })),
        }
    }

    /// Removes the stale lock `file` whose content was `text` (why it is
    /// stale: `why`): renamed aside first (atomic), then checked to hold
    /// that content still before it is deleted, so that of two runs taking
    /// over at once only one does.
    fn take_over(dir: &Path, file: &Path, text: &[u8], why: &str) -> Result<(), Error> {
        let name = file
            .file_name()
            .map_or_else(|| LOCK_FILE.into(), |n| n.to_string_lossy().into_owned());
        let aside = dir.join(format!("{name}.stale-{}", std::process::id()));
        if fs::rename(file, &aside).is_err() {
            // Another run took it over first: the next round sees its lock.
            return Ok(());
        }
        let moved = fs::read(&aside).unwrap_or_default();
        if moved != text {
            // A live run's fresh lock was moved: give it back.
            let _ = fs::rename(&aside, file);
            return Err(Self::busy(dir, file, "another run"));
        }
        let _ = fs::remove_file(&aside);
        eprintln!("note: {} {why}; taking the folder over", file.display());
        Ok(())
    }

    fn busy(dir: &Path, file: &Path, holder: &str) -> Error {
        OutputError::Busy {
            folder: dir.to_path_buf(),
            holder: holder.to_string(),
            lock: file.to_path_buf(),
        }
        .into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_held_folder_is_refused_and_released_on_drop() {
        let root = tempfile::tempdir().unwrap();
        let dir = root.path().join("a/b");
        let lock = OutputLock::acquire(&dir).unwrap();
        assert!(dir.join(LOCK_FILE).exists());
        // The same process may take it again (a second job of one run).
        let again = OutputLock::acquire(&dir).unwrap();
        drop(again);
        assert!(dir.join(LOCK_FILE).exists(), "only the owner releases");
        drop(lock);
        assert!(!root.path().join("a").exists(), "created folders removed");
    }

    #[test]
    fn outputs_of_different_names_share_a_folder() {
        let dir = tempfile::tempdir().unwrap();
        fs::write(dir.path().join(".b.handling.lock"), "1\n").unwrap();
        let a = OutputLock::acquire_outputs(dir.path(), "a").unwrap();
        assert!(dir.path().join(".a.handling.lock").exists());
        let e = OutputLock::acquire_outputs(dir.path(), "b").unwrap_err();
        assert!(e.to_string().contains("another run (process 1)"), "{e}");
        drop(a);
        assert!(!dir.path().join(".a.handling.lock").exists());
    }

    #[test]
    fn a_live_foreign_lock_is_refused_and_a_dead_one_taken_over() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join(LOCK_FILE);
        // PID 1 is always running.
        fs::write(&file, "1\n").unwrap();
        let e = OutputLock::acquire(dir.path()).unwrap_err().to_string();
        assert!(
            e.contains("another run (process 1)") && e.contains(LOCK_FILE),
            "{e}"
        );
        // A PID above the kernel's maximum (2^22) is never running.
        let dead = 4_194_400;
        fs::write(&file, format!("{dead}\n")).unwrap();
        let partial = dir.path().join(format!(".x.csv.partial-{dead}.csv"));
        fs::write(&partial, "half").unwrap();
        let lock = OutputLock::acquire(dir.path()).unwrap();
        let held = fs::read_to_string(&file).unwrap();
        assert_eq!(held.trim(), std::process::id().to_string());
        assert!(!partial.exists(), "the dead run's temporary file removed");
        drop(lock);
        assert!(!file.exists());
        assert!(dir.path().exists(), "a folder that existed stays");
    }

    #[test]
    fn leftovers_of_dead_runs_are_removed_even_when_no_lock_names_them() {
        let dir = tempfile::tempdir().unwrap();
        let dead = 4_194_401;
        let me = std::process::id();
        let files = [
            (format!(".diagnosis.json.partial-{dead}.json"), false),
            (format!(".handling.lock.stale-{dead}"), false),
            // A live process's temporary file (PID 1 and this test).
            (".gaps.csv.partial-1.csv".to_string(), true),
            (format!(".x.png.partial-{me}.png"), true),
            // Not a run's leftover: a user's hidden file.
            (format!(".notes-{dead}"), true),
            (format!(".a.stale-{dead}x"), true),
        ];
        for (name, _) in &files {
            fs::write(dir.path().join(name), "x").unwrap();
        }
        assert_eq!(leftover_of(&files[0].0), Some(dead));
        assert_eq!(leftover_of(&files[1].0), Some(dead));
        assert_eq!(leftover_of("diagnosis.json"), None);
        let lock = OutputLock::acquire(dir.path()).unwrap();
        for (name, stays) in &files {
            assert_eq!(dir.path().join(name).exists(), *stays, "{name}");
        }
        drop(lock);
    }

    /// Sets the modification time of `file` to `seconds` ago.
    fn age_by(file: &Path, seconds: u64) {
        let then = std::time::SystemTime::now() - std::time::Duration::from_secs(seconds);
        fs::File::options()
            .write(true)
            .open(file)
            .unwrap()
            .set_modified(then)
            .unwrap();
    }

    #[test]
    fn a_nameless_lock_is_said_empty_only_when_it_holds_nothing() {
        assert_eq!(nameless(b""), "is empty");
        assert_eq!(nameless(b"   \n"), "holds only blanks (4 characters)");
        assert_eq!(nameless(b"garbage\n"), "names no process (7 characters)");
        assert_eq!(process_named(b"0\n"), None);
        assert_eq!(process_named(b" 42\n"), Some(42));
        assert_eq!(
            nameless(&[0xff, 0xfe]),
            "names no process (2 bytes that are not text)"
        );
    }

    #[test]
    fn a_lock_that_names_no_process_is_taken_over_once_old() {
        for text in ["", "\n", "garbage\n", "\u{0}\u{0}", "0\n"] {
            let dir = tempfile::tempdir().unwrap();
            let file = dir.path().join(LOCK_FILE);
            fs::write(&file, text).unwrap();
            // Fresh: it may be a run writing its id this instant.
            let e = OutputLock::acquire(dir.path()).unwrap_err().to_string();
            assert!(
                e.contains("taken over once it is 10 s old"),
                "{text:?}: {e}"
            );
            age_by(&file, 11);
            let lock = OutputLock::acquire(dir.path()).unwrap();
            let held = fs::read_to_string(&file).unwrap();
            assert_eq!(held.trim(), std::process::id().to_string(), "{text:?}");
            drop(lock);
            assert!(!file.exists());
        }
    }
}
