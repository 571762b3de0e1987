//! What a fresh user tripped on: files of the wrong kind and hints that
//! sent the user to the wrong place: a tyre rig CSV given as a run (its
//! `fy` answered "did you mean `ay`?"), a run given as rig data (`ax` as
//! `fx`), a scenario given to `metrics`, `identify` or `tyre-eval`, a
//! folder, a campaign, a sweep or a study given to `simulate`, a tyre file
//! or rig data given to `diagnose`; a campaign's `[model.effects]` sent to
//! `[tyres]`, a scenario's `[tyres] model` taken for `mode`; and a
//! campaign's `degrees = ["bank"]` refused at the run file's 1:1.

use super::*;

/// A tyre rig file's header and two rows (the TTC layout of FORMATS.md).
const RIG: &str = "t,fz,alpha,camber,fy,mz,pressure,speed\n0.00,2750.3,0.0,0.0,-72.08,-7.908,83170,11.178\n0.01,2788.6,-0.000531,0.0,-101.11,-9.936,82970,11.175\n";

/// A measured run's header and two rows (a racing log's layout).
const LOG: &str = "t,speed,steer,yaw_rate,beta,ax,roll\n0.00,5.0592,0.0,-0.005437,0.007263,1.1107,0.02\n0.04,5.1702,0.000581,-0.005888,0.009413,1.1337,0.02\n";

/// The error of `args` (the binary must fail).
fn error_of(args: &[&str]) -> String {
    let o = run(args);
    assert!(!o.status.success(), "expected failure: {args:?}");
    stderr(&o)
}

/// A rig CSV replayed as a run, measured by `metrics`: "this is a tyre
/// rig file", not `fy` → `ay`.
#[test]
fn rig_data_given_as_a_run_is_named_as_rig_data() {
    let dir = scratch(&[("cornering.csv", RIG)]);
    let rig = dir.path().join("cornering.csv");
    let rig_s = rig.to_str().unwrap();
    let said = "cornering.csv: this is a tyre rig file (columns t, fz, alpha, camber, fy, mz, pressure, speed), not a vehicle run (a CSV with `t`, `speed`, `steer`, `yaw_rate`): `handling identify` reads it (fits a tyre to it), and a campaign takes it as `[tyres] rig`";
    let e = error_of(&["metrics", rig_s]);
    assert!(e.contains(said), "{e}");
    assert!(!e.contains("did you mean `ay`"), "{e}");
    let sc = format!(
        "{VEHICLE}\n[tyres]\nfront = \"{}\"\n\n[manoeuvre]\nkind = \"replay\"\nrun = \"{rig_s}\"\n",
        root().join("tyres/gim.toml").display()
    );
    fs::write(dir.path().join("replay.toml"), sc).unwrap();
    let e = fails_cleanly("simulate", &dir.path().join("replay.toml"), dir.path());
    assert!(e.contains(said), "{e}");
}

/// A run given to `identify`, to `tyre-eval` as its points, and as a
/// campaign's rig: "this is a measured vehicle run", not `ax` → `fx`.
#[test]
fn a_run_given_as_tyre_data_is_named_as_a_run() {
    let dir = scratch(&[("log.csv", LOG)]);
    let log = dir.path().join("log.csv");
    let log_s = log.to_str().unwrap();
    let said = "log.csv: this is a measured vehicle run (columns t, speed, steer, yaw_rate, beta, ax, roll), not tyre data (a CSV with `fz` and `alpha` or `kappa`): `handling metrics` measures it; a campaign lists it under [runs], and a scenario replays it (`[manoeuvre] kind = \"replay\"`)";
    let out = dir.path().join("out");
    let out_s = out.to_str().unwrap();
    let e = error_of(&["identify", log_s, "--model", "pac89", "--out", out_s]);
    assert!(e.contains(said), "{e}");
    assert!(!e.contains("did you mean `fx`"), "{e}");
    let gim = root().join("tyres/gim.toml");
    let e = error_of(&["tyre-eval", gim.to_str().unwrap(), log_s, "--out", out_s]);
    assert!(e.contains(said), "{e}");
    let camp = format!("{VEHICLE}\n[tyres]\nrig = \"log.csv\"\nmodel = \"pac89\"\n\n[runs]\nfiles = [\"log.csv\"]\n");
    fs::write(dir.path().join("c.toml"), camp).unwrap();
    let e = fails_cleanly("diagnose", &dir.path().join("c.toml"), dir.path());
    assert!(e.contains(said), "{e}");
}

/// A scenario given to `metrics`, `identify` and `tyre-eval`: one
/// sentence naming it, not "missing required column `t` (the header has:
/// name = …)" per column.
#[test]
fn a_scenario_given_as_a_csv_is_named_as_a_scenario() {
    let dir = tempfile::tempdir().unwrap();
    let sc = root().join("scenarios/sedan_step.toml");
    let sc = sc.to_str().unwrap();
    let out = dir.path().join("out");
    let out = out.to_str().unwrap();
    let gim = root().join("tyres/gim.toml");
    for (args, wanted) in [
        (
            vec!["metrics", sc],
            "a vehicle run (a CSV with `t`, `speed`, `steer`, `yaw_rate`)",
        ),
        (
            vec!["identify", sc, "--model", "pac89", "--out", out],
            "tyre data (a CSV with `fz` and `alpha` or `kappa`)",
        ),
        (
            vec!["tyre-eval", gim.to_str().unwrap(), sc, "--out", out],
            "tyre data (a CSV with `fz` and `alpha` or `kappa`)",
        ),
    ] {
        let e = error_of(&args);
        let said = format!("sedan_step.toml: this is a scenario (a TOML file with [manoeuvre]), not {wanted}: `handling simulate` runs it");
        assert!(e.contains(&said), "{args:?}: {e}");
        assert!(!e.contains("missing required column"), "{e}");
    }
}

/// A folder given to `simulate` or `metrics` ("Is a directory"), a
/// campaign folder to `simulate`.
#[test]
fn a_folder_is_named_as_a_folder() {
    let dir = scratch(&[("vehicle.toml", VEHICLE)]);
    let scenarios = root().join("scenarios");
    let e = fails_cleanly("simulate", &scenarios, dir.path());
    assert!(
        e.contains("scenarios: the file is a folder, not a scenario: give one of its files"),
        "{e}"
    );
    let e = error_of(&["metrics", scenarios.to_str().unwrap()]);
    assert!(e.contains("scenarios: this is a folder, not a vehicle run (a CSV with `t`, `speed`, `steer`, `yaw_rate`): give one of its files"), "{e}");
    assert!(!e.contains("Is a directory"), "{e}");
    let e = fails_cleanly("simulate", dir.path(), dir.path());
    assert!(e.contains("the file is a campaign folder (vehicle.toml and runs/*.csv), not a scenario: `handling diagnose` reads it"), "{e}");
}

/// A campaign, a sweep and a study given to `simulate`: named, with the
/// command that reads each, not "unknown field `rig`" or "`sweep`".
#[test]
fn a_campaign_sweep_or_study_given_to_simulate_is_named() {
    let dir = tempfile::tempdir().unwrap();
    for (file, said) in [
        ("campaigns/synthetic.toml", "synthetic.toml: the file is a campaign (a TOML file with [runs] or [diagnose]), not a scenario: `handling diagnose` reads it"),
        ("scenarios/equilibria_steer.toml", "equilibria_steer.toml: the file is an equilibrium sweep (a TOML file with [sweep]), not a scenario: `handling equilibria` reads it"),
        ("scenarios/sedan_study.toml", "sedan_study.toml: the file is a stiffness study (a TOML file with [stiffness]), not a scenario: `handling study` reads it"),
    ] {
        let e = fails_cleanly("simulate", &root().join(file), dir.path());
        assert!(e.contains(said), "{e}");
        assert!(!e.contains("unknown field"), "{e}");
    }
}

/// A tyre file and a rig CSV given to `diagnose`: named as what they are,
/// the rig's advice no longer "[runs] files".
#[test]
fn a_tyre_file_or_rig_data_given_to_diagnose_is_named() {
    let dir = scratch(&[("cornering.csv", RIG)]);
    let e = fails_cleanly("diagnose", &root().join("tyres/gim.toml"), dir.path());
    assert!(e.contains("gim.toml: this is a tyre file (`model = \"gim\"`), not a campaign: `handling tyre-eval` reads it, and a scenario or campaign names it under [tyres]"), "{e}");
    let e = fails_cleanly("diagnose", &dir.path().join("cornering.csv"), dir.path());
    assert!(e.contains("cornering.csv: this is a tyre rig file (a CSV with `fz` and `alpha` or `kappa`), not a campaign: give it as the campaign's `[tyres] rig = \"<this file>\"` (or as tyre_rig.csv in a campaign folder); `handling identify` fits a tyre to it"), "{e}");
    assert!(!e.contains("[runs] files"), "{e}");
}

/// A campaign's `[model.effects]` was sent "in [tyres]" (whose `model`
/// is a name); a scenario's `[tyres] model` was answered "did you mean
/// `mode`?".
#[test]
fn table_hints_know_the_kind_of_file() {
    let dir = scratch(&[("log.csv", LOG)]);
    let camp = format!("{VEHICLE}\n[runs]\nfiles = [\"log.csv\"]\n\n[diagnose]\nseed = 1\n\n[model.effects]\nsensor_delay = 0.05\n");
    fs::write(dir.path().join("c.toml"), camp).unwrap();
    let e = fails_cleanly("diagnose", &dir.path().join("c.toml"), dir.path());
    assert!(e.contains("c.toml:16:2: `model`: unknown field `model` (a campaign has no [model] table, which is a scenario's: `handling diagnose` builds its base model from [vehicle], [tyres] and [roll], and the effects it tries are named in `[diagnose] effects = [\"…\"]`, their sizes fitted to the runs)"), "{e}");
    assert!(!e.contains("it belongs in [tyres]"), "{e}");
    let sc =
        bundled_scenario("sedan_step.toml").replace("[tyres]\n", "[tyres]\nmodel = \"pac89\"\n");
    fs::write(dir.path().join("s.toml"), sc).unwrap();
    let e = fails_cleanly("simulate", &dir.path().join("s.toml"), dir.path());
    assert!(e.contains("`tyres.model`: unknown field `model` (a scenario's tyre model is its tyre file's: `[tyres] front = \"<tyre file>\"` (and `rear`), whose own `model = \"…\"` names it, or a .tir file; `mode` is a .tir's MFeval useMode, and `model` with `rig` is a campaign's)"), "{e}");
    assert!(!e.contains("did you mean `mode`"), "{e}");
}

/// `degrees = ["roll", "bank"]` for logs without a bank was refused at
/// the run file's 1:1: now at the key's element, with the angle columns
/// the runs have and every value the key takes.
#[test]
fn a_degrees_column_no_run_has_is_refused_at_the_key() {
    // The second run a sample longer: a copy of a run is refused.
    let dir = scratch(&[("a.csv", LOG), ("b.csv", &one_sample_longer(LOG))]);
    let camp = format!(
        "{VEHICLE}\n[runs]\nfiles = [\"a.csv\", \"b.csv\"]\ndegrees = [\"roll\", \"bank\"]\n"
    );
    fs::write(dir.path().join("c.toml"), camp).unwrap();
    let e = fails_cleanly("diagnose", &dir.path().join("c.toml"), dir.path());
    assert!(e.contains("c.toml:12:20: `bank` is declared in degrees, and none of the 2 run files has it: the angle columns the runs have are steer, yaw_rate, beta, roll (`degrees` takes steer, yaw_rate, beta, roll, bank); leave `bank` out"), "{e}");
}
