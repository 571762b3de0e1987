//! Sharded runs (`--shard K/N`, `handling merge`): the merged outputs equal
//! the unsharded run's byte for byte whatever N, and merges of incomplete,
//! repeated, mixed or stale shards are refused.

use super::*;

/// Runs `args`, expects success.
fn ok(args: &[&str]) {
    let o = run(args);
    assert!(o.status.success(), "{:?}: {}", args, stderr(&o));
}

/// The shard files of `dir`, named for shards 1..=n of n.
fn shard_files(dir: &Path, n: usize) -> Vec<String> {
    (1..=n)
        .map(|k| {
            dir.join(format!("shard-{k}-of-{n}.json"))
                .to_str()
                .unwrap()
                .to_string()
        })
        .collect()
}

/// Every file of `a` is in `b` with the same bytes, and `b` has no other.
fn same_outputs(a: &Path, b: &Path) {
    let names = |d: &Path| {
        let mut v: Vec<_> = fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        v.sort();
        v
    };
    assert_eq!(names(a), names(b));
    for n in names(a) {
        assert!(
            fs::read(a.join(&n)).unwrap() == fs::read(b.join(&n)).unwrap(),
            "{} differs",
            n.to_string_lossy()
        );
    }
}

/// `command input` unsharded, then in N = 1, 3, 7 shards merged: the same
/// outputs, byte for byte.
fn sharded_equals_unsharded(command: &str, input: &Path) {
    let dir = tempfile::tempdir().unwrap();
    let full = dir.path().join("full");
    ok(&[
        command,
        input.to_str().unwrap(),
        "--out",
        full.to_str().unwrap(),
    ]);
    for n in [1, 3, 7] {
        let shards = dir.path().join(format!("shards{n}"));
        // Shards run in any order.
        for k in (1..=n).rev() {
            ok(&[
                command,
                input.to_str().unwrap(),
                "--shard",
                &format!("{k}/{n}"),
                "--out",
                shards.to_str().unwrap(),
            ]);
        }
        let merged = dir.path().join(format!("merged{n}"));
        let files = shard_files(&shards, n);
        let mut args = vec!["merge"];
        args.extend(files.iter().map(String::as_str));
        args.extend(["--out", merged.to_str().unwrap()]);
        ok(&args);
        same_outputs(&full, &merged);
    }
}

#[test]
fn a_sharded_equilibrium_sweep_merges_to_the_unsharded_outputs() {
    // Nine lines of friction, a pitchfork along them, two phase portraits.
    sharded_equals_unsharded(
        "equilibria",
        &root().join("scenarios/equilibria_friction.toml"),
    );
}

#[test]
fn a_sharded_stiffness_study_merges_to_the_unsharded_outputs() {
    // The bundled study on a coarser map: map points and RBF pairs are
    // shared out in one list, the network and the inverse made at the merge.
    let text = fs::read_to_string(root().join("scenarios/sedan_study.toml"))
        .unwrap()
        .replace("step = 20.0 }", "step = 100.0 }")
        .replace("validation = [4, 14, 24, 34, 44]", "validation = [2, 8]")
        // RK4 at 4 ms: the shards must give the unsharded bytes at any step.
        .replace("step = 0.001", "step = 0.004")
        .replace("../tyres/", &format!("{}/tyres/", root().display()));
    let dir = scratch(&[("study.toml", &text)]);
    sharded_equals_unsharded("study", &dir.path().join("study.toml"));
}

#[test]
fn merges_of_missing_repeated_mixed_or_stale_shards_are_refused() {
    let text = fs::read_to_string(root().join("scenarios/equilibria_friction.toml"))
        .unwrap()
        .replace("../tyres/", &format!("{}/tyres/", root().display()));
    let dir = scratch(&[("sweep.toml", &text)]);
    let sweep = dir.path().join("sweep.toml");
    let shards = dir.path().join("shards");
    for s in ["1/3", "2/3", "3/3", "1/2"] {
        ok(&[
            "equilibria",
            sweep.to_str().unwrap(),
            "--shard",
            s,
            "--out",
            shards.to_str().unwrap(),
        ]);
    }
    let f = shard_files(&shards, 3);
    let merge = |files: &[&str]| {
        let out = dir.path().join("out");
        let mut args = vec!["merge"];
        args.extend(files);
        args.extend(["--out", out.to_str().unwrap()]);
        let o = run(&args);
        assert!(!o.status.success(), "{files:?} merged");
        assert!(!out.exists(), "a refused merge must not leave outputs");
        stderr(&o)
    };
    let e = merge(&[&f[0], &f[2]]);
    assert!(e.contains("shards 2/3 missing"), "{e}");
    let e = merge(&[&f[0], &f[1], &f[1], &f[2]]);
    assert!(e.contains("shard 2/3 given twice"), "{e}");
    let half = shards.join("shard-1-of-2.json");
    let e = merge(&[&f[0], &f[1], half.to_str().unwrap()]);
    assert!(
        e.contains("differs") && e.contains("shard-1-of-2.json"),
        "{e}"
    );
    fs::write(&sweep, text.replace("seed = 1", "seed = 2")).unwrap();
    let e = merge(&[&f[0], &f[1], &f[2]]);
    assert!(
        e.contains("sweep.toml") && e.contains("changed since"),
        "{e}"
    );
    for bad in ["0/3", "4/3", "2"] {
        let o = run(&["equilibria", sweep.to_str().unwrap(), "--shard", bad]);
        assert!(!o.status.success());
        assert!(stderr(&o).contains("expected K/N"), "{}", stderr(&o));
    }
}

/// Runs `args` in the working directory `cwd`, expects success.
fn ok_in(cwd: &Path, args: &[&str]) {
    let o = bin().args(args).current_dir(cwd).output().expect("runs");
    assert!(
        o.status.success(),
        "{args:?} in {}: {}",
        cwd.display(),
        stderr(&o)
    );
}

/// `merge` of shards 1..=n of `dir` into `out`, run from the repository root.
fn merge_shards(dir: &Path, n: usize, out: &Path) {
    let files = shard_files(dir, n);
    let mut args = vec!["merge"];
    args.extend(files.iter().map(String::as_str));
    args.extend(["--out", out.to_str().unwrap()]);
    ok(&args);
}

/// A campaign folder `dir/name` whose runs are step steers simulated on
/// Gim tyres (rows every 10 ms) at `speeds` (m/s) and whose model has a
/// linear tyre, asked about the sensor bias only; with `gap` the second run
/// loses rows 300 to 349 (a 0.5 s time gap the cleaning splits at).
fn simulated_campaign(dir: &Path, name: &str, speeds: &[f64], gap: bool) {
    let c = dir.join(name);
    fs::create_dir_all(c.join("runs")).unwrap();
    let sim = tempfile::tempdir().unwrap();
    for (i, speed) in speeds.iter().enumerate() {
        let sc = format!(
            "{VEHICLE}\n[tyres]\nfront = \"tyre.toml\"\n\n[manoeuvre]\nkind = \"step-steer\"\n\
             speed = {speed}\nsteer = 0.02\n\n[simulation]\nstep = 0.01\n"
        );
        fs::write(sim.path().join("scenario.toml"), sc).unwrap();
        fs::write(sim.path().join("tyre.toml"), GIM).unwrap();
        let out = sim.path().join(format!("run{i}"));
        ok_in(
            sim.path(),
            &["simulate", "scenario.toml", "--out", out.to_str().unwrap()],
        );
        let history = fs::read_to_string(out.join("history.csv")).unwrap();
        let rows: Vec<&str> = history
            .lines()
            .enumerate()
            .filter(|&(n, _)| !(gap && i == 1 && (301..351).contains(&n)))
            .map(|(_, l)| l)
            .collect();
        fs::write(c.join(format!("runs/r{i}.csv")), rows.join("\n") + "\n").unwrap();
    }
    fs::write(
        c.join("vehicle.toml"),
        format!(
            "{VEHICLE}\n[tyres]\nfile = \"tyre.toml\"\n\n[diagnose]\neffects = [\"sensor_bias\"]\n"
        ),
    )
    .unwrap();
    fs::write(
        c.join("tyre.toml"),
        "model = \"linear\"\ncornering_stiffness = 50000.0\n",
    )
    .unwrap();
}

/// The files under `dir`, relative to it, sorted.
fn files_under(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                todo.push(p);
            } else {
                out.push(p.strip_prefix(dir).unwrap().to_path_buf());
            }
        }
    }
    out.sort();
    out
}

#[test]
fn a_sharded_batch_diagnosis_merges_to_the_unsharded_fleet_from_any_directory() {
    // Three quick campaigns (one with a time gap in a run) and a folder
    // that is not a campaign; every run and shard works in `work` on the
    // relative folder `batch`, every merge from the repository root.
    let work = tempfile::tempdir().unwrap();
    let batch = work.path().join("batch");
    simulated_campaign(&batch, "a_slow", &[15.0, 20.0], false);
    simulated_campaign(&batch, "b_gap", &[20.0, 25.0], true);
    simulated_campaign(&batch, "c_fast", &[25.0, 30.0], false);
    fs::create_dir(batch.join("d_not_a_campaign")).unwrap();
    ok_in(
        work.path(),
        &["diagnose", "batch", "--batch", "--out", "full"],
    );
    let full = work.path().join("full");
    let fleet = read_json(&full.join("fleet.json"));
    let rows = fleet["campaigns"].as_array().unwrap();
    let names: Vec<&str> = rows
        .iter()
        .map(|r| r["campaign"].as_str().unwrap())
        .collect();
    // Every entry of the folder is a row, the broken one marked failed with
    // its reason; each campaign has its own diagnosis, the gap one fewer
    // runs replayed whole.
    assert_eq!(names, ["a_slow", "b_gap", "c_fast", "d_not_a_campaign"]);
    assert_eq!(rows[3]["failed"], true);
    let why = rows[3]["statement"].as_str().unwrap();
    assert!(why.contains("vehicle.toml"), "{why}");
    for (r, n) in rows.iter().zip(&names[..3]) {
        assert_eq!(r["failed"], false, "{r}");
        assert!(r["heldout_error_before"].as_f64().unwrap() > 0.0, "{r}");
        assert!(full.join(n).join("diagnosis.json").is_file(), "{n}");
    }
    assert_eq!(rows[0]["runs"], 2);
    assert_eq!(rows[1]["runs"], 3, "the gap splits a run in two");
    let csv = fs::read_to_string(full.join("fleet.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 4);
    for n in [1, 3, 7] {
        // Shards in any order; with N = 7, shards 5 to 7 own no campaign.
        let shards = format!("shards{n}");
        for k in (1..=n).rev() {
            ok_in(
                work.path(),
                &[
                    "diagnose",
                    "batch",
                    "--batch",
                    "--shard",
                    &format!("{k}/{n}"),
                    "--out",
                    &shards,
                ],
            );
        }
        let shards = work.path().join(shards);
        // Every N, 1 included (a job array of one), writes shard files
        // and merges from the root.
        let merged = work.path().join(format!("merged{n}"));
        merge_shards(&shards, n, &merged);
        assert_eq!(
            files_under(&merged),
            ["fleet.csv", "fleet.html", "fleet.json"].map(PathBuf::from)
        );
        crate::report_html::opens_in_a_browser(
            &merged.join("fleet.html"),
            &["fleet-table", "recurring-table"],
        );
        for f in ["fleet.csv", "fleet.json", "fleet.html"] {
            assert!(
                fs::read(full.join(f)).unwrap() == fs::read(merged.join(f)).unwrap(),
                "N = {n}: {f} differs"
            );
        }
        // The shards wrote each campaign's folder as the whole batch did.
        let written: Vec<PathBuf> = files_under(&shards)
            .into_iter()
            .filter(|p| !p.to_string_lossy().starts_with("shard-"))
            .collect();
        let expected: Vec<PathBuf> = files_under(&full)
            .into_iter()
            .filter(|p| !p.to_string_lossy().starts_with("fleet."))
            .collect();
        assert_eq!(written, expected, "N = {n}");
        for f in &expected {
            assert!(
                same_but_timing(&full.join(f), &shards.join(f)),
                "N = {n}: {} differs",
                f.display()
            );
        }
    }
}

/// Whether two output files are the same byte for byte, a
/// `diagnosis.json` but for its `timing` (the clock's, not the
/// diagnosis's).
fn same_but_timing(a: &Path, b: &Path) -> bool {
    let (x, y) = (fs::read(a).unwrap(), fs::read(b).unwrap());
    if a.file_name().is_some_and(|n| n == "diagnosis.json") {
        let parse = |v: &[u8]| {
            let mut d: serde_json::Value = serde_json::from_slice(v).unwrap();
            assert!(d["timing"]["wall_seconds"].as_f64().unwrap() > 0.0);
            d.as_object_mut().unwrap().remove("timing");
            d
        };
        return parse(&x) == parse(&y);
    }
    x == y
}

#[test]
fn shards_written_in_one_directory_merge_from_another() {
    // The sweep is named relative to the directory the shards run in; the
    // merge runs from elsewhere (the repository root) and must still find
    // it and its unchanged text.
    let text = fs::read_to_string(root().join("scenarios/equilibria_friction.toml"))
        .unwrap()
        .replace("../tyres/", &format!("{}/tyres/", root().display()));
    let dir = scratch(&[("sweep.toml", &text)]);
    ok_in(dir.path(), &["equilibria", "sweep.toml", "--out", "full"]);
    for k in 1..=3 {
        ok_in(
            dir.path(),
            &[
                "equilibria",
                "sweep.toml",
                "--shard",
                &format!("{k}/3"),
                "--out",
                "shards",
            ],
        );
    }
    let shard = read_json(&dir.path().join("shards/shard-2-of-3.json"));
    let input = PathBuf::from(shard["input"].as_str().unwrap());
    assert!(
        input.is_absolute() && input.ends_with("sweep.toml"),
        "{input:?}"
    );
    let merged = dir.path().join("merged");
    merge_shards(&dir.path().join("shards"), 3, &merged);
    same_outputs(&dir.path().join("full"), &merged);
}
