//! One run per output: `equilibria`, `identify` and the fleet table of a
//! `diagnose --batch` refuse outputs another live run holds (a lock held
//! by PID 1, which is always running), naming the holder and the lock file,
//! and write nothing. (`simulate`, `study` and `diagnose` are held to the
//! same in [`crate::kill`], with two real runs at once.)

use crate::{fs, inputs, root, Path};
use std::process::{Command, Output};

fn handling(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_handling"))
        .current_dir(root())
        .args(args)
        .output()
        .unwrap()
}

/// Runs `args` with `lock` (inside the output folder `out`) held by PID 1
/// and checks the refusal; the folder keeps only the lock.
fn refused_while_held(args: &[&str], out: &Path, lock: &str) {
    fs::create_dir_all(out).unwrap();
    let file = out.join(lock);
    fs::write(&file, "1\n").unwrap();
    let o = handling(args);
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success(), "not refused: {args:?}");
    assert!(
        e.contains("another run (process 1)") && e.contains(&file.display().to_string()),
        "{args:?}: {e}"
    );
    let left: Vec<String> = fs::read_dir(out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(left, [lock], "{args:?} wrote into a held folder");
}

#[test]
fn equilibria_refuses_a_held_folder() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let sweep = root().join("scenarios/equilibria_steer.toml");
    let args = [
        "equilibria",
        sweep.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    refused_while_held(&args, &out, ".handling.lock");
}

#[test]
fn identify_refuses_outputs_held_by_another_fit() {
    let dir = tempfile::tempdir().unwrap();
    let rig = dir.path().join("rig.csv");
    fs::write(&rig, inputs::rig_csv()).unwrap();
    let out = dir.path().join("out");
    let fitted = out.join("fit.toml");
    let args = [
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "gim",
        "--out",
        fitted.to_str().unwrap(),
    ];
    refused_while_held(&args, &out, ".fit.handling.lock");
}

#[test]
fn a_fleet_table_held_by_another_batch_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let batch = dir.path().join("campaigns");
    fs::create_dir_all(&batch).unwrap();
    let text = inputs::campaign(&batch);
    fs::write(batch.join("one.toml"), text).unwrap();
    let out = dir.path().join("out");
    let args = [
        "diagnose",
        batch.to_str().unwrap(),
        "--batch",
        "--out",
        out.to_str().unwrap(),
    ];
    refused_while_held(&args, &out, ".fleet.handling.lock");
}
