//! What a new user tripped on in `identify` and `tyre-eval`, round 81,
//! run from files as a user runs the tool.

use super::*;

/// `synth`'s default campaign's rig file (`fz, alpha, fy`; slip angles to
/// ±12° = ±0.20943951 rad, loads 2500 to 7000 N, no `mz`).
fn synth_rig(dir: &Path) -> PathBuf {
    synth_campaign(dir, "camp", &[]).join("tyre_rig.csv")
}

/// A braking/driving sweep at three loads, `fz, kappa, fx` only.
fn longitudinal_rig() -> String {
    let mut s = String::from("fz,kappa,fx\n");
    for fz in [2000.0_f64, 4000.0, 6000.0] {
        for i in -60..=60 {
            let k = f64::from(i) * 0.0025;
            let d = 1.1 * fz * (1.0 - 0.05 * (fz - 4000.0) / 4000.0);
            let (b, c, e) = (12.0, 1.65, 0.3);
            let fx = d * (c * (b * k - e * (b * k - (b * k).atan())).atan()).sin();
            s += &format!("{fz},{k},{fx}\n");
        }
    }
    s
}

/// The value of `key` in a `.tir`.
fn tir_value(text: &str, key: &str) -> f64 {
    let line = text
        .lines()
        .find(|l| l.split_whitespace().next() == Some(key))
        .unwrap_or_else(|| panic!("no {key}"));
    line.split('=')
        .nth(1)
        .unwrap()
        .split('$')
        .next()
        .unwrap()
        .trim()
        .parse()
        .unwrap()
}

/// The mf61 file's `ALPMAX` was its bins' means' 0.2085668 rad, while the
/// samples reach 0.20943951 (`pac89` states the samples'): `tyre-eval` on
/// the file then held its own rig's extreme samples at ALPMIN/ALPMAX.
#[test]
fn an_mf61_file_states_the_slip_angles_its_samples_reach() {
    let dir = tempfile::tempdir().unwrap();
    let rig = synth_rig(dir.path());
    let tir = dir.path().join("s.tir");
    let o = identify_to(&rig, "mf61", &tir);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(&tir).unwrap();
    let max = tir_value(&text, "ALPMAX");
    assert!((max - 0.20943951023931956).abs() < 1e-12, "{max}");
    assert!(
        text.contains("alpha -0.2094 to 0.2094 rad"),
        "{}",
        text.lines().nth(1).unwrap()
    );
    let points = "fz,kappa,alpha,camber,speed\n2500,0,-0.20943951023931956,0,20\n7000,0,0.20943951023931956,0,20\n";
    fs::write(dir.path().join("p.csv"), points).unwrap();
    let o = run(&[
        "tyre-eval",
        tir.to_str().unwrap(),
        dir.path().join("p.csv").to_str().unwrap(),
        "--out",
        dir.path().join("f.csv").to_str().unwrap(),
    ]);
    let err = stderr(&o);
    assert!(o.status.success(), "{err}");
    assert!(
        !without_temp_names(&err).contains("ALPMIN")
            && !without_temp_names(&err).contains("ALPMAX"),
        "{err}"
    );
}

/// PAC89 fitted to a file without `mz`: the note says the aligning block
/// keeps the defaults' values, and the file carried no `c` array (an
/// aligning moment of 0). The defaults' array is written.
#[test]
fn pac89_without_mz_writes_the_aligning_defaults_its_note_names() {
    let dir = tempfile::tempdir().unwrap();
    let rig = synth_rig(dir.path());
    let out = dir.path().join("p.toml");
    let o = identify_to(&rig, "pac89", &out);
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(said.contains("no aligning moment data") && said.contains("the defaults' values"));
    let text = fs::read_to_string(&out).unwrap();
    let c = text
        .lines()
        .find(|l| l.starts_with("c = ["))
        .unwrap_or_else(|| panic!("no c array:\n{text}"));
    assert!(
        c.starts_with("c = [2.34, 1.495, 6.416654, -3.57403,"),
        "{c}"
    );
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n";
    fs::write(dir.path().join("q.csv"), points).unwrap();
    let o = run(&[
        "tyre-eval",
        out.to_str().unwrap(),
        dir.path().join("q.csv").to_str().unwrap(),
        "--out",
        dir.path().join("f.csv").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("mz = 0"), "{}", stderr(&o));
    let row = fs::read_to_string(dir.path().join("f.csv")).unwrap();
    let mz: f64 = row
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .nth(7)
        .unwrap()
        .parse()
        .unwrap();
    assert!(mz.abs() > 1.0, "{mz}");
}

/// A PAC89 fitted to longitudinal data only gave `tyre-eval` the
/// template's lateral force without a word (`simulate` warns): said once.
#[test]
fn tyre_eval_says_a_longitudinal_only_tyres_lateral_block_is_unfitted() {
    let points =
        "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n4000,0.05,0,0,20\n4000,0,-0.05,0,20\n";
    let dir = scratch(&[("long.csv", &longitudinal_rig()), ("p.csv", points)]);
    let tyre = dir.path().join("l.toml");
    let o = identify_to(&dir.path().join("long.csv"), "pac89", &tyre);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = run(&[
        "tyre-eval",
        tyre.to_str().unwrap(),
        dir.path().join("p.csv").to_str().unwrap(),
        "--out",
        dir.path().join("f.csv").to_str().unwrap(),
    ]);
    let err = stderr(&o);
    assert!(o.status.success(), "{err}");
    assert_eq!(err.matches("longitudinal data only").count(), 1, "{err}");
    assert!(
        err.contains("2 of 3 points at a slip angle or camber ≠ 0 (the first at line 2): the tyre was fitted to longitudinal data only (its `[fitted_ranges]` give a slip ratio of -0.1500 to 0.1500 and no slip angle), so its lateral block is unfitted"),
        "{err}"
    );
}

/// `tyre-eval --out x.tir` wrote a CSV under a .tir name.
#[test]
fn tyre_eval_refuses_an_out_that_is_no_csv() {
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n";
    let dir = scratch(&[("p.csv", points), ("t.toml", GIM)]);
    let out = dir.path().join("x.tir");
    let o = run(&[
        "tyre-eval",
        dir.path().join("t.toml").to_str().unwrap(),
        dir.path().join("p.csv").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(!out.exists());
    let err = stderr(&o);
    assert!(
        err.contains("x.tir: tyre-eval's forces are written as a .csv file, not .tir")
            && err.contains("name it ")
            && err.contains("x.csv"),
        "{err}"
    );
}

/// FSAE_Defaults.tir (Kxκ negative from 1625 N, FZMAX 2000 N): points at
/// κ = 0 were said to have "the force opposes the slip" where there is no
/// slip, and a point above FZMAX was said to be "at their own load".
#[test]
fn a_negative_slip_stiffness_is_said_of_points_with_slip_at_the_load_evaluated() {
    let Some(tir) = shared_data(
        "a_negative_slip_stiffness_is_said_of_points_with_slip_at_the_load_evaluated",
        "tir_public/FSAE_Defaults.tir",
    ) else {
        return;
    };
    let eval = |points: &str| {
        let dir = scratch(&[("p.csv", points)]);
        let o = run(&[
            "tyre-eval",
            tir.to_str().unwrap(),
            dir.path().join("p.csv").to_str().unwrap(),
            "--out",
            dir.path().join("f.csv").to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        stderr(&o)
    };
    let err = eval("fz,kappa,alpha,camber,speed\n1800,0,0.05,0,15\n3000,0,0.05,0,15\n");
    assert!(
        !err.contains("negative longitudinal slip stiffness at"),
        "{err}"
    );
    let err = eval("fz,kappa,alpha,camber,speed\n1800,0,0.05,0,15\n3000,0.05,0,0,15\n");
    assert!(
        err.contains("1 of 2 points has a negative longitudinal slip stiffness at its load (at the file's FZMAX = 2000 N where above it), camber, pressure and speed (the first at line 3: fz = 3000 N given, evaluated at 2000 N, camber = 0 rad)"),
        "{err}"
    );
}

/// Files of another kind given to `tyre-eval`: each named as what it is,
/// with the command that reads it (a campaign TOML said "missing field
/// model", a history "the order is `tyre-eval <tyre> <points>`", a folder
/// "Is a directory", a rig file as points its missing columns).
#[test]
fn tyre_eval_names_a_file_of_another_kind_with_its_command() {
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n";
    let history = "t,speed,steer,yaw_rate,fy_front,alpha_front\n0,20,0,0,0,0\n";
    let rig = "fz,alpha,fy\n4000,0.05,3000\n4000,-0.05,-3000\n";
    let dir = scratch(&[
        ("p.csv", points),
        ("history.csv", history),
        ("rig.csv", rig),
        ("t.toml", GIM),
    ]);
    let eval = |tyre: &Path, points: &Path| {
        let o = run(&[
            "tyre-eval",
            tyre.to_str().unwrap(),
            points.to_str().unwrap(),
            "--out",
            dir.path().join("f.csv").to_str().unwrap(),
        ]);
        assert!(!o.status.success());
        stderr(&o)
    };
    let p = dir.path().join("p.csv");
    let campaign = root().join("campaigns/delays.toml");
    let err = eval(&campaign, &p);
    assert!(
        err.contains("this is a campaign (a TOML file with [runs] or [diagnose]), not a tyre file")
            && err.contains("`handling diagnose` reads it"),
        "{err}"
    );
    let err = eval(&dir.path().join("history.csv"), &p);
    assert!(
        err.contains("this is a simulation history") && err.contains("not a tyre file"),
        "{err}"
    );
    assert!(!err.contains("the order is"), "{err}");
    let err = eval(&root().join("tyres"), &p);
    assert!(err.contains("this is a folder, not a tyre file"), "{err}");
    let err = eval(&dir.path().join("t.toml"), &dir.path().join("rig.csv"));
    assert!(
        err.contains("this is a tyre rig file (columns fz, alpha, fy), not the points `handling tyre-eval <tyre> <points>` evaluates")
            && err.contains("`handling identify` reads it"),
        "{err}"
    );
    assert!(!err.contains("missing required column"), "{err}");
}

/// `identify --camber 2` on a file without cambers: degrees given where
/// radians are taken, with no hint.
#[test]
fn identify_camber_in_degrees_on_a_file_without_cambers_gets_the_degrees_hint() {
    let dir = tempfile::tempdir().unwrap();
    let rig = synth_rig(dir.path());
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "gim",
        "--camber",
        "2",
        "--out",
        dir.path().join("g.toml").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("camber 114.59° was requested but the file has no `camber` column (its samples are at camber 0); the value is read in rad: did you mean 0.0349066 rad (2°)?"),
        "{err}"
    );
}

/// A load the MF 6.1 sample's vertical model carries at no radius (limit
/// checks off): the refusal quoted "-468848448 N" as what the tyre
/// carries, a negative force of its stiffness terms extrapolated.
#[test]
fn a_load_not_carried_is_not_said_against_a_negative_force() {
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let dir = scratch(&[(
        "p.csv",
        "fz,kappa,alpha,camber,speed\n4000,0,0,0,16\n1000000,0,0.05,0,20\n",
    )]);
    let o = run(&[
        "tyre-eval",
        tir.to_str().unwrap(),
        dir.path().join("p.csv").to_str().unwrap(),
        "--out",
        dir.path().join("f.csv").to_str().unwrap(),
        "--mode",
        "221",
    ]);
    let err = stderr(&o);
    assert!(!o.status.success(), "{err}");
    assert!(!err.contains("-468848448"), "{err}");
    assert!(
        err.contains("p.csv:3:1: fz = 1000000 N is more than the tyre's vertical model carries: no load at a deflection of its whole free radius"),
        "{err}"
    );
}

/// A rig of `fz, kappa, alpha, fx, fy` at three loads: combined-slip rows
/// (κ 0.005 to 0.1 at α ±0.05, 0.02), and, with `pure`, the pure sweeps at
/// α = 0 and κ = 0 beside them; no `mz`.
fn combined_rig(pure: bool) -> String {
    let mut s = String::from("fz,kappa,alpha,fx,fy\n");
    let row = |fz: f64, k: f64, a: f64| {
        let fx = fz * (1.6 * (12.0 * k).atan()).sin() * (5.0 * a).atan().cos();
        let fy = fz * (1.4 * (10.0 * a).atan()).sin() * (5.0 * k).atan().cos();
        format!("{fz},{k},{a},{fx},{fy}\n")
    };
    for fz in [2000.0, 4000.0, 6000.0] {
        for a in [0.02, 0.05, -0.05] {
            for i in 1..=20 {
                s += &row(fz, f64::from(i) * 0.005, a);
            }
        }
        if pure {
            for i in -40..=40 {
                s += &row(fz, f64::from(i) * 0.005, 0.0);
                s += &row(fz, 0.0, f64::from(i) * 0.005);
            }
        }
    }
    s
}

/// An mf61 fit of a file of combined rows only said "no stage could be
/// fitted" without a word of the rows set aside: counted.
#[test]
fn an_mf61_fit_of_combined_rows_only_counts_the_rows_set_aside() {
    let dir = scratch(&[("comb.csv", &combined_rig(false))]);
    let o = identify_to(
        &dir.path().join("comb.csv"),
        "mf61",
        &dir.path().join("c.tir"),
    );
    let err = stderr(&o);
    assert!(!o.status.success(), "{err}");
    assert!(err.contains("no stage could be fitted ("), "{err}");
    assert!(
        err.contains("): 180 of its 180 rows are of combined slip (both |κ| and |α| above 1e-3), set aside for the combined stages"),
        "{err}"
    );
}

/// A file with combined rows and no `mz`: the skipped combined Mz stage's
/// `$` line was headed "no combined-slip data".
#[test]
fn a_skipped_combined_mz_stage_beside_combined_rows_is_not_said_to_have_none() {
    let dir = scratch(&[("comb.csv", &combined_rig(true))]);
    let tir = dir.path().join("c.tir");
    let o = identify_to(&dir.path().join("comb.csv"), "mf61", &tir);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(&tir).unwrap();
    let line = text
        .lines()
        .find(|l| l.contains("the combined aligning moment (SSZ*) block is not fitted"))
        .unwrap_or_else(|| panic!("{text}"));
    assert!(
        line.starts_with("$ 180 combined-slip rows without the pure stage: the combined aligning moment (SSZ*) block is not fitted (it builds on the pure Mz stage, which was skipped)"),
        "{line}"
    );
}

/// `synth`'s rig with its `fy` in lbf (divided by 4.448222) against `fz`
/// in N: a Gim tyre of friction 0.26 was written without a word.
#[test]
fn rig_forces_in_lbf_are_warned_of_with_the_number_and_the_unit() {
    let dir = tempfile::tempdir().unwrap();
    let rig = fs::read_to_string(synth_rig(dir.path())).unwrap();
    let mut lbf = String::from("fz,alpha,fy\n");
    for line in rig.lines().skip(1) {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        lbf += &format!("{},{},{}\n", v[0], v[1], v[2] / 4.448222);
    }
    fs::write(dir.path().join("lbf.csv"), lbf).unwrap();
    let out = dir.path().join("g.toml");
    let o = identify_to(&dir.path().join("lbf.csv"), "gim", &out);
    let err = stderr(&o);
    assert!(o.status.success(), "{err}");
    let said = "column `fy`: its largest |fy|/fz is 0.242 (fy = 605.8 N at fz = 2500 N, alpha 9.80°), where a road tyre's peak is 0.6–1.8 over a sweep this far: is `fy` in lbf against `fz` in N (4.45× too small; 605.8 × 4.448 = 2695 N)?";
    assert!(err.contains(&format!("warning: {said}")), "{err}");
    assert!(fs::read_to_string(&out)
        .unwrap()
        .contains(&format!("# warning: {said}")));
    // The rig in N is not warned of.
    let o = identify_to(
        &synth_rig(&dir.path().join("n")),
        "gim",
        &dir.path().join("n.toml"),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        !without_temp_names(&stderr(&o)).contains("lbf"),
        "{}",
        stderr(&o)
    );
}
