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
