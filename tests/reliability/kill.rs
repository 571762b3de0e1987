//! Outputs that survive a kill: `simulate`, `study` and `diagnose` are
//! SIGKILLed at seeded random moments (`HANDLING_KILL_MOMENTS`, default 10
//! per command) while writing into a folder that holds a complete earlier
//! run (or into a fresh one); every output is then absent or complete
//! (JSON and TOML parse, a CSV parses with the reference's rows, a PNG ends
//! with its IEND chunk), never truncated, and a rerun succeeds, taking the
//! killed run's lock over. Two runs into one folder at once: the second is
//! refused, the first completes.
//!
//! A seeded moment may fall after a run has ended (runs are faster or
//! slower than the reference run that set the span), so the first moment
//! of each command is not a time but an event: the run has taken the
//! folder (its lock names its process), and so is certainly at work. A run
//! counts as killed when its exit status says SIGKILL ended it; the count
//! is asserted, at least that first kill per command, and every other run
//! must have ended by itself, successfully.

use crate::{env_count, fs, inputs, root, Path, PathBuf};
use std::os::unix::process::ExitStatusExt;
use std::process::{Child, Command, ExitStatus, Output, Stdio};
use std::time::{Duration, Instant};

fn handling() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_handling"));
    c.current_dir(root());
    c
}

fn run(args: &[String]) -> Output {
    handling().args(args).output().unwrap()
}

/// A job: its arguments without `--out`, and its inputs' folder.
struct Job {
    name: &'static str,
    args: Vec<String>,
    _inputs: tempfile::TempDir,
}

fn jobs() -> Vec<Job> {
    let s = |p: &Path| p.to_str().unwrap().to_string();
    let sim = tempfile::tempdir().unwrap();
    let study_dir = tempfile::tempdir().unwrap();
    // The bundled study on a 3 × 3 map (no network): quick to run.
    let text = fs::read_to_string(root().join("scenarios/sedan_study.toml")).unwrap();
    let text = text[..text.find("[rbf]").unwrap()]
        .replace("../tyres/", &format!("{}/tyres/", root().display()))
        .replace(
            "from = 200.0, to = 700.0, step = 20.0",
            "from = 400.0, to = 600.0, step = 100.0",
        )
        .replace(
            "from = 220.0, to = 720.0, step = 20.0",
            "from = 420.0, to = 620.0, step = 100.0",
        );
    let study = study_dir.path().join("study.toml");
    fs::write(&study, text).unwrap();
    let camp_dir = tempfile::tempdir().unwrap();
    let campaign = camp_dir.path().join("campaign.toml");
    let small = "effects = [\"sensor_delay\", \"cornering_stiffness\"]\nmax_effects = 1\nparticles = 8\niterations = 5\n";
    fs::write(&campaign, inputs::campaign(camp_dir.path()) + small).unwrap();
    vec![
        Job {
            name: "simulate",
            args: vec![
                "simulate".into(),
                s(&root().join("scenarios/sedan_step.toml")),
            ],
            _inputs: sim,
        },
        Job {
            name: "study",
            args: vec!["study".into(), s(&study)],
            _inputs: study_dir,
        },
        Job {
            name: "diagnose",
            args: vec!["diagnose".into(), s(&campaign)],
            _inputs: camp_dir,
        },
    ]
}

fn with_out(args: &[String], out: &Path) -> Vec<String> {
    let mut a = args.to_vec();
    a.extend(["--out".into(), out.to_str().unwrap().into()]);
    a
}

/// The PNG trailer: the IEND chunk (length 0, type, CRC).
const IEND: [u8; 12] = [0, 0, 0, 0, b'I', b'E', b'N', b'D', 0xAE, 0x42, 0x60, 0x82];

/// Checks that every visible file of `dir` is complete; `reference` holds
/// the complete run's files.
fn complete(dir: &Path, reference: &Path) -> Result<usize, String> {
    let mut n = 0;
    for e in fs::read_dir(dir).map_err(|e| e.to_string())? {
        let p = e.unwrap().path();
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        if name.starts_with('.') {
            // The lock and the temporary files of a killed run.
            continue;
        }
        let bytes = fs::read(&p).unwrap();
        let fail = |why: String| Err(format!("{}: {why} ({} bytes)", p.display(), bytes.len()));
        let ok = match p.extension().and_then(|x| x.to_str()) {
            Some("json") => serde_json::from_slice::<serde_json::Value>(&bytes)
                .map(drop)
                .map_err(|e| e.to_string()),
            Some("toml") => std::str::from_utf8(&bytes)
                .map_err(|e| e.to_string())
                .and_then(|t| {
                    t.parse::<toml::Table>()
                        .map(drop)
                        .map_err(|e| e.to_string())
                }),
            Some("png") if bytes.ends_with(&IEND) => Ok(()),
            Some("png") => Err("no IEND chunk at the end".into()),
            Some("csv") if fs::read(reference.join(&name)).ok() == Some(bytes.clone()) => Ok(()),
            Some("csv") => Err("differs from the complete run's".into()),
            // A page is complete when its document closes.
            Some("html") if bytes.trim_ascii_end().ends_with(b"</html>") => Ok(()),
            Some("html") => Err("the document does not close".into()),
            _ => Err("an unexpected file".into()),
        };
        if let Err(why) = ok {
            return fail(why);
        }
        n += 1;
    }
    Ok(n)
}

/// A seeded generator of kill moments (SplitMix64).
fn moments(seed: u64, n: usize, span: Duration) -> Vec<Duration> {
    let mut x = seed;
    (0..n)
        .map(|_| {
            x = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = x;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            let u = (z ^ (z >> 31)) as f64 / u64::MAX as f64;
            span.mul_f64(u)
        })
        .collect()
}

/// Waits until `child` holds output folder `out` (its lock file names its
/// process id): from then on it is at work on that folder until it
/// releases the lock at its very end.
fn holds_the_folder(child: &mut Child, out: &Path, name: &str) {
    let lock = out.join(".handling.lock");
    let me = child.id().to_string();
    let t0 = Instant::now();
    loop {
        let held = fs::read_to_string(&lock).is_ok_and(|t| t.trim() == me);
        if held {
            return;
        }
        if let Some(status) = child.try_wait().unwrap() {
            panic!("{name}: the run ended ({status}) before its lock was seen");
        }
        assert!(
            t0.elapsed() < Duration::from_secs(120),
            "{name}: the run did not take its folder in 120 s"
        );
        std::thread::sleep(Duration::from_micros(200));
    }
}

/// SIGKILLs `child` (a run that has ended already is not touched) and
/// returns how it ended.
fn kill(child: &mut Child) -> ExitStatus {
    // An error means the child was reaped already; its status follows.
    child.kill().unwrap_or(());
    child.wait().unwrap()
}

/// True when SIGKILL ended the run (nothing but this test sends it).
fn killed(status: ExitStatus) -> bool {
    status.signal() == Some(9)
}

#[test]
fn outputs_survive_a_kill_at_any_moment() {
    let n = env_count("HANDLING_KILL_MOMENTS", 10) as usize;
    let scratch = tempfile::tempdir().unwrap();
    for (j, job) in jobs().iter().enumerate() {
        let reference = scratch.path().join(format!("{}-reference", job.name));
        let t0 = Instant::now();
        let o = run(&with_out(&job.args, &reference));
        assert!(
            o.status.success(),
            "{}: {}",
            job.name,
            String::from_utf8_lossy(&o.stderr)
        );
        let span = t0.elapsed().mul_f64(1.2);
        let files = complete(&reference, &reference).unwrap();
        let out = scratch.path().join(job.name);
        let (mut kills, mut ended) = (0, 0);
        for (i, at) in moments(j as u64 + 1, n, span).into_iter().enumerate() {
            // Odd moments write over a complete earlier run.
            if i % 2 == 1 && !out.join(".handling.lock").exists() {
                let o = run(&with_out(&job.args, &out));
                assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
            }
            let spawned = Instant::now();
            let mut child = handling()
                .args(with_out(&job.args, &out))
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .spawn()
                .unwrap();
            let at = if i == 0 {
                holds_the_folder(&mut child, &out, job.name);
                spawned.elapsed()
            } else {
                std::thread::sleep(at);
                at
            };
            let status = kill(&mut child);
            if killed(status) {
                kills += 1;
            } else {
                assert!(
                    status.success(),
                    "{} at {at:?}: the run ended by itself but failed: {status}",
                    job.name
                );
                ended += 1;
            }
            assert!(
                i != 0 || killed(status),
                "{}: the run holding the folder was not killed: {status}",
                job.name
            );
            if out.exists() {
                if let Err(e) = complete(&out, &reference) {
                    panic!("{} killed at {at:?}: {e}", job.name);
                }
            }
        }
        assert!(kills >= 1, "{}: no run was killed", job.name);
        assert_eq!(kills + ended, n, "{}", job.name);
        let o = run(&with_out(&job.args, &out));
        assert!(
            o.status.success(),
            "rerun of {}: {}",
            job.name,
            String::from_utf8_lossy(&o.stderr)
        );
        assert_eq!(complete(&out, &reference).unwrap(), files, "{}", job.name);
        let hidden: Vec<PathBuf> = fs::read_dir(&out)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.file_name().unwrap().to_string_lossy().starts_with('.'))
            .collect();
        assert!(hidden.is_empty(), "{}: left behind {hidden:?}", job.name);
        eprintln!("{}: {kills} of {n} runs killed before they ended, {ended} ended by themselves (span {span:?}); every file complete; rerun fine", job.name);
    }
}

#[test]
fn two_runs_into_one_folder_are_refused() {
    let scratch = tempfile::tempdir().unwrap();
    // The bundled study on a 21 × 21 map: seconds of work, long enough for
    // a second run to start while the first holds the folder.
    let text = fs::read_to_string(root().join("scenarios/sedan_study.toml")).unwrap();
    let text = text[..text.find("[rbf]").unwrap()]
        .replace("../tyres/", &format!("{}/tyres/", root().display()))
        .replace("step = 20.0", "step = 25.0");
    let study = scratch.path().join("study.toml");
    fs::write(&study, text).unwrap();
    let args = vec!["study".to_string(), study.to_str().unwrap().into()];
    let out = scratch.path().join("out");
    let lock = out.join(".handling.lock");
    let first = handling()
        .args(with_out(&args, &out))
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let t0 = Instant::now();
    while !lock.exists() && t0.elapsed() < Duration::from_secs(20) {
        std::thread::sleep(Duration::from_millis(1));
    }
    let second = run(&with_out(&args, &out));
    let pid = first.id();
    let first = first.wait_with_output().unwrap();
    assert!(
        first.status.success(),
        "{}",
        String::from_utf8_lossy(&first.stderr)
    );
    assert!(!second.status.success(), "the second run was not refused");
    let e = String::from_utf8_lossy(&second.stderr);
    assert!(
        e.contains(&format!("another run (process {pid})")) && e.contains(".handling.lock"),
        "{e}"
    );
    assert!(!lock.exists(), "the first run released its lock");
    assert_eq!(complete(&out, &out).unwrap(), 3);
    // A stale lock (a process that is gone) is taken over with a note.
    fs::write(&lock, "4194400\n").unwrap();
    let o = run(&with_out(&args, &out));
    assert!(o.status.success());
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("no longer running") && e.contains("taking the folder over"),
        "{e}"
    );
    assert!(!lock.exists());
}

#[test]
fn a_truncated_output_is_seen() {
    let scratch = tempfile::tempdir().unwrap();
    let (a, b) = (scratch.path().join("a"), scratch.path().join("b"));
    fs::create_dir_all(&a).unwrap();
    fs::create_dir_all(&b).unwrap();
    fs::write(a.join("x.json"), "{\"a\": [1, 2]}").unwrap();
    fs::write(a.join("x.png"), [&b"\x89PNG"[..], &IEND].concat()).unwrap();
    fs::write(a.join("x.csv"), "t,x\n0,1\n").unwrap();
    assert_eq!(complete(&a, &a), Ok(3));
    for (name, half) in [
        ("x.json", "{\"a\": [1,"),
        ("x.png", "\u{89}PNG\0\0"),
        ("x.csv", "t,x\n0,"),
    ] {
        fs::write(b.join(name), half).unwrap();
        assert!(complete(&b, &a).is_err(), "{name}");
        fs::remove_file(b.join(name)).unwrap();
    }
}
