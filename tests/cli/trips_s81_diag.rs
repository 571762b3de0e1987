//! What a fresh user tripped on in `diagnose` (session 81), run as a user
//! runs the tool: a sideslip in the other sign convention diagnosed as
//! "outside the library"; a `min_speed` that removed every run answered
//! with a `segment` hint; one run's steer in degrees answered with
//! `degrees = ["steer"]`, which converts every run.

use super::*;

/// A synthetic handling campaign (rig data, 8 runs at 100 Hz) with
/// `effects` on, in `dir/c`, its candidates narrowed to `sensor_bias`
/// (synth's vehicle.toml ends in its [diagnose] table).
fn campaign(dir: &Path, effects: &str) -> PathBuf {
    let c = synth_campaign(dir, "c", &["--effects", effects, "--seed", "1"]);
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    fs::write(&v, format!("{text}effects = [\"sensor_bias\"]\n")).unwrap();
    c
}

/// Rewrites column `name` of every run of campaign folder `c` whose file
/// name passes `which` by `f`.
pub(crate) fn rewrite(c: &Path, name: &str, which: &dyn Fn(&str) -> bool, f: &dyn Fn(f64) -> f64) {
    for e in fs::read_dir(c.join("runs")).unwrap() {
        let p = e.unwrap().path();
        if !which(&p.file_name().unwrap().to_string_lossy()) {
            continue;
        }
        let text = fs::read_to_string(&p).unwrap();
        let mut lines = text.lines();
        let head = lines.next().unwrap();
        let k = head.split(',').position(|h| h == name).unwrap();
        let mut out = format!("{head}\n");
        for l in lines {
            let mut cells: Vec<String> = l.split(',').map(str::to_string).collect();
            cells[k] = format!("{}", f(cells[k].parse().unwrap()));
            out.push_str(&cells.join(","));
            out.push('\n');
        }
        fs::write(&p, out).unwrap();
    }
}

/// `diagnose c` refused, without outputs: its stderr.
fn refused_campaign(dir: &Path, c: &Path) -> String {
    let out = dir.join("out");
    let o = run(&[
        "diagnose",
        c.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    refused(&o, &out)
}

/// A sideslip negated in every run was fitted: the verdict said "outside
/// the library", beta carrying 88 % of the error. It moves against the
/// base model's β (correlation −0.99 on the ramp): refused, "negate it".
#[test]
fn a_negated_sideslip_is_refused_with_its_correlation() {
    let dir = tempfile::tempdir().unwrap();
    let c = campaign(dir.path(), "sensor_delay");
    rewrite(&c, "beta", &|_| true, &|v| -v);
    let e = refused_campaign(dir.path(), &c);
    assert!(
        e.contains("`beta` moves against the base model's sideslip: their correlation"),
        "{e}"
    );
    assert!(e.contains("their correlation is -0.97 over the 6007 samples of the 7 runs with a sideslip that swings; 7 runs against it"), "{e}");
    assert!(e.contains("ramp_080kph.csv (-0.99 over 901)"), "{e}");
    assert!(
        e.contains("is `beta` in another sign convention? negate it"),
        "{e}"
    );
}

/// The same campaign with its sideslip as logged is diagnosed.
#[test]
fn a_sideslip_in_iso_signs_is_diagnosed() {
    let dir = tempfile::tempdir().unwrap();
    let c = campaign(dir.path(), "sensor_delay");
    let (stdout, _) = diagnose(&c);
    assert!(stdout.contains("verdict:"), "{stdout}");
}

/// `min_speed = 50` above every run's top speed was answered "0 runs …
/// set [runs] segment": the key is named at its line, with each run's top
/// speed and a value that keeps them all.
#[test]
fn a_min_speed_above_every_run_is_named_with_the_top_speeds() {
    let dir = tempfile::tempdir().unwrap();
    let c = campaign(dir.path(), "none");
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    fs::write(&v, format!("{text}min_speed = 50\n")).unwrap();
    let line = text.lines().count() + 1;
    let e = refused_campaign(dir.path(), &c);
    assert!(
        e.contains(&format!(
            "vehicle.toml:{line}:13: `diagnose.min_speed` = 50: must lie in [0, "
        )) && e.contains("it removes every run: no sample of theirs reaches it"),
        "{e}"
    );
    assert!(e.contains("step_040kph_3ms2.csv 11.1 m/s"), "{e}");
    assert!(e.contains("step_120kph_4ms2.csv 33.3 m/s"), "{e}");
    assert!(e.contains("write `min_speed = 5` under [diagnose]"), "{e}");
    assert!(!e.contains("segment"), "{e}");
}

/// One run of a folder campaign logs its steer in degrees: the hint was
/// `degrees = ["steer"]`, which converts every run's. The runs are named,
/// and the key said to apply to all.
#[test]
fn one_run_in_degrees_is_named_and_the_key_said_to_convert_all() {
    let dir = tempfile::tempdir().unwrap();
    let c = campaign(dir.path(), "none");
    let deg = |n: &str| n.starts_with("step_100kph");
    rewrite(&c, "steer", &deg, &|v| v.to_degrees());
    let e = refused_campaign(dir.path(), &c);
    assert!(
        e.contains(
            "the yaw rate is far smaller than a neutral car's for the steer in 2 of the 8 runs:"
        ),
        "{e}"
    );
    assert!(e.contains("step_100kph_2ms2.csv (62× smaller"), "{e}");
    assert!(e.contains("step_100kph_6ms2.csv (65× smaller"), "{e}");
    assert!(
        e.contains("5 read in radians by their held steer against their yaw rate, as they should")
            && e.contains("`degrees = [\"steer\"]` under [runs] would convert every run's steer, those in radians too"),
        "{e}"
    );
    assert!(
        e.contains("convert the steer of these runs to radians in their files"),
        "{e}"
    );
}

/// On a campaign without effects every candidate is "not significant",
/// yet steering_compliance's value said "the runs disagree beyond their
/// noise"; and the page counted "1 candidate effects".
#[test]
fn a_gap_within_noise_claims_no_disagreement_and_counts_agree() {
    let dir = tempfile::tempdir().unwrap();
    let (stdout, _, page) = narrowed(dir.path(), "none", "\"steering_compliance\"");
    assert!(stdout.contains("1 candidate effect, seed 1"), "{stdout}");
    assert!(page.contains("1 candidate effect, 8 folds"), "{page}");
    assert!(stdout.contains("not significant"), "{stdout}");
    assert!(!stdout.contains("beyond their noise"), "{stdout}");
    assert!(!page.contains("beyond their noise"));
    assert!(
        stdout.contains("± 1e-5 rad/kN (4.934e-8 rad/N) (the fold refits' spread, 3× the asymptotic ± 2.89e-6: the asymptotic error understates its uncertainty, of a value fitted where the effect removes nothing significant)"),
        "{stdout}"
    );
}

/// Rig data given as a scenario's `[tyres] front` or a campaign's
/// `[tyres] file` was answered with the TOML reader's "expected `.`, `=`"
/// at the CSV's header: named at the key, with the command that fits a
/// tyre from it.
#[test]
fn rig_data_given_as_a_tyre_file_is_named_at_its_key() {
    let dir = tempfile::tempdir().unwrap();
    let c = campaign(dir.path(), "none");
    fs::rename(c.join("tyre_rig.csv"), c.join("rig.csv")).unwrap();
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    let text = text.replace(
        "rig = \"tyre_rig.csv\"\nmodel = \"pac89\"",
        "file = \"rig.csv\"",
    );
    fs::write(&v, &text).unwrap();
    let line = text
        .lines()
        .position(|l| l == "file = \"rig.csv\"")
        .unwrap()
        + 1;
    let e = refused_campaign(dir.path(), &c);
    let said = "`tyres.file` = \"rig.csv\": this is a tyre rig file (a CSV with `fz` and `alpha` or `kappa`), not a tyre file (a Magic Formula .tir, or a TOML tyre with `model = \"…\"` that `handling identify` writes): `handling identify rig.csv --model pac89` fits a tyre from it, then give the written tyre here";
    assert!(e.contains(&format!("vehicle.toml:{line}:8: {said}; or give the rig data itself as `[tyres] rig = \"rig.csv\"`")), "{e}");
    assert!(!e.contains("expected `.`"), "{e}");
    // A scenario's: the bundled step with rig data for its front tyre.
    let sc: String = bundled_scenario("sedan_step.toml")
        .lines()
        .map(|l| match l.starts_with("front = ") {
            true => "front = \"rig.csv\"\n".to_string(),
            false => format!("{l}\n"),
        })
        .collect();
    let s = dir.path().join("s");
    fs::create_dir(&s).unwrap();
    fs::write(s.join("scenario.toml"), &sc).unwrap();
    fs::copy(c.join("rig.csv"), s.join("rig.csv")).unwrap();
    let line = sc.lines().position(|l| l == "front = \"rig.csv\"").unwrap() + 1;
    let e = simulate_err(&s);
    let said = said.replace("tyres.file", "tyres.front");
    assert!(
        e.contains(&format!("scenario.toml:{line}:9: {said}\n")),
        "{e}"
    );
}

/// `merge` of a fleet's shards whose every campaign failed exited 0 (only
/// `diagnose --batch` checked): it fails after writing the table, with
/// the count, as the batch does.
#[test]
fn a_merge_that_diagnosed_nothing_fails_with_the_count() {
    let dir = tempfile::tempdir().unwrap();
    let batch = dir.path().join("batch");
    fs::create_dir_all(&batch).unwrap();
    // Two campaigns whose runs do not exist.
    for name in ["a", "b"] {
        let sedan = "[vehicle]\nmass = 1530\nyaw_inertia = 2315\na = 1.11\nb = 1.67\ntrack_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n";
        let text = format!("{sedan}[runs]\ndir = \"nowhere\"\n");
        fs::write(batch.join(format!("{name}.toml")), text).unwrap();
    }
    let shards = dir.path().join("shards");
    for k in ["1/2", "2/2"] {
        let o = run(&[
            "diagnose",
            "--batch",
            batch.to_str().unwrap(),
            "--shard",
            k,
            "--out",
            shards.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let out = dir.path().join("merged");
    let files: Vec<String> = (1..=2)
        .map(|k| {
            shards
                .join(format!("shard-{k}-of-2.json"))
                .display()
                .to_string()
        })
        .collect();
    let o = run(&[
        "merge",
        &files[0],
        &files[1],
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success(), "a merge that diagnosed nothing failed");
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("fleet: 0 of 2 campaigns diagnosed, 2 failed (each one's reason below)"),
        "{said}"
    );
    let table = out.join("fleet.csv");
    let e = stderr(&o);
    assert!(
        e.contains(&format!("{}: none of its 2 campaigns could be diagnosed (each one's reason is listed above and in {}): no fleet to compare", out.display(), table.display())),
        "{e}"
    );
    assert!(table.is_file());
}

/// A run's `ax` written in g was read as m/s² by `diagnose` in silence
/// (only a `simulate` replay checked it against the speed's change): a
/// note names the run, with the slope of the speed's change on `∫ax dt`.
#[test]
fn an_ax_in_g_is_said_per_run() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(dir.path(), "c", &["--programme", "oval", "--seed", "1"]);
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    fs::write(&v, format!("{text}effects = [\"sensor_bias\"]\n")).unwrap();
    let mut names: Vec<String> = fs::read_dir(c.join("runs"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    let first = names[0].clone();
    rewrite(&c, "ax", &|n| n == first, &|v| v / 9.81);
    let (stdout, _) = diagnose(&c);
    let notes: Vec<&str> = stdout
        .lines()
        .filter(|l| l.contains("`ax` reads in g"))
        .collect();
    assert_eq!(notes.len(), 1, "{stdout}");
    assert!(notes[0].starts_with("  note: "), "{stdout}");
    assert!(
        notes[0].contains(&format!(
            "runs/{first}: `ax` reads in g, not m/s²: over its "
        )),
        "{stdout}"
    );
    assert!(notes[0].contains("the diagnosis takes `ax` as m/s² forward for its longitudinal effects and load transfer: multiply the column by 9.81"), "{stdout}");
}
