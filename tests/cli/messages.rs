//! What a new user reads: numbers without float noise, user words instead
//! of internal names, normalised paths, the same checks and spellings
//! across commands.

use super::*;

/// A step-steer scenario whose `[manoeuvre]` table is `manoeuvre`.
fn step_scenario(manoeuvre: &str) -> tempfile::TempDir {
    scenario(VEHICLE, GIM, &format!("[manoeuvre]\n{manoeuvre}"))
}

#[test]
fn a_range_shows_clean_bounds_and_a_guarded_zero_as_closed() {
    let dir = step_scenario(
        "kind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\nrise_time = 0.3\n",
    );
    let e = simulate_err(dir.path());
    assert!(
        e.contains("`manoeuvre.rise_time` = 0.3: must lie in [0, 0.1875]:"),
        "{e}"
    );
    assert!(
        !e.contains("0.18749999") && !e.contains("0.000000000001"),
        "{e}"
    );
}

#[test]
fn a_manoeuvre_kind_is_read_with_underscores_as_with_hyphens() {
    for kind in ["step-steer", "step_steer"] {
        let dir = step_scenario(&format!(
            "kind = \"{kind}\"\nspeed = 22.2222\nsteer = 0.0174533\n"
        ));
        let out = dir.path().join("out");
        let o = run(&[
            "simulate",
            dir.path().join("scenario.toml").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{kind}: {}", stderr(&o));
    }
}

#[test]
fn shard_and_equilibria_summaries_speak_the_users_words() {
    let dir = tempfile::tempdir().unwrap();
    let sweep = root().join("scenarios/equilibria_friction.toml");
    let out = dir.path().join("f");
    let o = run(&[
        "equilibria",
        sweep.to_str().unwrap(),
        "--shard",
        "1/3",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.starts_with("shard 1/3 of the equilibria job: 3 of 9 grid lines → "),
        "{said}"
    );
    assert!(
        !said.contains("Equilibria") && !without_temp_names(&said).contains("units"),
        "{said}"
    );
    let o = run(&[
        "equilibria",
        sweep.to_str().unwrap(),
        "--out",
        dir.path().join("whole").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    // One condition, singular; the fitness and bifurcation by their file names.
    assert!(
        said.contains("  1 condition with 2 equilibria in the box"),
        "{said}"
    );
    assert!(said.contains("fitness newton-step"), "{said}");
    assert!(said.contains("  pitchfork along friction at"), "{said}");
    assert!(
        !said.contains("NewtonStep") && !said.contains("Pitchfork"),
        "{said}"
    );
}

#[test]
fn the_staged_fit_names_its_start_as_the_command_line_does() {
    let dir = tempfile::tempdir().unwrap();
    let mut points = String::from("fz,kappa,alpha,camber,speed\n");
    for fz in [2000, 4000, 6000] {
        for i in -10..=10 {
            points += &format!("{fz},0,{},0,16.7\n", f64::from(i) * 0.02);
        }
    }
    let (p, rig) = (dir.path().join("p.csv"), dir.path().join("rig.csv"));
    fs::write(&p, points).unwrap();
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let o = run(&[
        "tyre-eval",
        tir.to_str().unwrap(),
        p.to_str().unwrap(),
        "--out",
        rig.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "mf61",
        "--out",
        dir.path().join("fit.tir").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(said.contains("; model mf61, start data\n"), "{said}");
}

#[test]
fn a_useful_refusal_of_a_mode_names_every_bad_digit() {
    let dir = scratch(&[("p.csv", "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n")]);
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let out = dir.path().join("o.csv");
    let o = run(&[
        "tyre-eval",
        tir.to_str().unwrap(),
        dir.path().join("p.csv").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--mode",
        "999",
    ]);
    let e = refused(&o, &out);
    assert!(
        e.contains("mode 999: hundreds digit 9 is not 1 or 2, tens digit 9 is not 1 or 2, units digit 9 is not 1 ("),
        "{e}"
    );
}

#[test]
fn an_empty_cell_is_called_empty_at_its_line_and_column() {
    let dir = scratch(&[("p.csv", "fz,kappa,alpha,camber,speed\n4000,,0.05,0,20\n")]);
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let out = dir.path().join("o.csv");
    let o = run(&[
        "tyre-eval",
        tir.to_str().unwrap(),
        dir.path().join("p.csv").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = refused(&o, &out);
    assert!(
        e.contains("p.csv:2:2: column `kappa`: empty cell: a number is needed"),
        "{e}"
    );
    assert!(!e.contains("``"), "{e}");
}

/// A campaign file in `dir/campaigns` whose runs are `runs`.
fn campaign_listing(dir: &Path, runs: &str) -> PathBuf {
    fs::create_dir_all(dir.join("campaigns")).unwrap();
    let file = dir.join("campaigns/c.toml");
    fs::write(&file, format!("{VEHICLE}\n[runs]\nfiles = [{runs}]\n")).unwrap();
    file
}

#[test]
fn a_path_relative_to_a_campaign_is_shown_normalised() {
    let dir = tempfile::tempdir().unwrap();
    let file = campaign_listing(dir.path(), "\"../data/./absent.csv\"");
    let e = fails_cleanly("diagnose", &file, dir.path());
    let expected = dir.path().join("data").join("absent.csv");
    assert!(
        e.contains(&format!(
            "names {}, which does not exist",
            expected.display()
        )),
        "{e}"
    );
    assert!(!e.contains("campaigns/..") && !e.contains("/./"), "{e}");
}

#[test]
fn a_broken_campaign_in_a_batch_reads_as_it_does_alone() {
    let dir = tempfile::tempdir().unwrap();
    let fleet = dir.path().join("fleet");
    fs::create_dir(&fleet).unwrap();
    let broken = fleet.join("broken.toml");
    fs::write(&broken, "[vehicle]\nmass = 1530.0\nyaw_inertia = \n").unwrap();
    let alone = fails_cleanly("diagnose", &broken, dir.path());
    let message = format!(
        "{}:3:15: `vehicle.yaw_inertia`: invalid string; expected",
        broken.display()
    );
    assert!(alone.contains(&message), "{alone}");
    let o = run(&[
        "diagnose",
        "--batch",
        fleet.to_str().unwrap(),
        "--out",
        dir.path().join("batch").to_str().unwrap(),
    ]);
    let said = String::from_utf8_lossy(&o.stdout);
    let line = said
        .lines()
        .find(|l| l.contains("broken.toml") && l.contains("FAILED"))
        .unwrap_or_else(|| panic!("{said}"));
    // The whole message on the campaign's line, as alone.
    assert!(line.contains(&message), "{said}");
    let row = alone.trim().trim_start_matches("error: ");
    assert!(line.ends_with(row), "{line}\n{row}");
}

/// `history.csv` of the bundled sedan step with its steer written in
/// degrees, in `dir`.
fn steer_in_degrees(dir: &Path) -> PathBuf {
    let sim = dir.join("sim");
    super::scenarios::simulate_to(&root().join("scenarios/sedan_step.toml"), &sim);
    let text = fs::read_to_string(sim.join("history.csv")).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let steer = header.split(',').position(|c| c == "steer").unwrap();
    let mut out = format!("{header}\n");
    for l in lines {
        let cells: Vec<String> = l
            .split(',')
            .enumerate()
            .map(|(i, c)| match i == steer {
                true => c.parse::<f64>().unwrap().to_degrees().to_string(),
                false => c.to_string(),
            })
            .collect();
        out += &(cells.join(",") + "\n");
    }
    written(dir, "degrees.csv", &out)
}

#[test]
fn metrics_refuses_a_steer_in_degrees_as_the_diagnosis_judges_it() {
    let dir = tempfile::tempdir().unwrap();
    let run_file = steer_in_degrees(dir.path());
    let o = run(&["metrics", run_file.to_str().unwrap(), "--filter-hz", "0"]);
    assert!(
        !o.status.success(),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
    let e = stderr(&o);
    assert!(
        e.contains("degrees.csv: the yaw rate is ")
            && e.contains("× smaller than a neutral car's for this steer")
            && e.contains("with l = 5 m, longer than any car's wheelbase")
            && e.contains("is `steer` in degrees (57×) or a steering-wheel angle"),
        "{e}"
    );
    // The same run in radians is measured.
    let o = run(&[
        "metrics",
        dir.path().join("sim/history.csv").to_str().unwrap(),
        "--filter-hz",
        "0",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn the_study_table_shows_the_stiffness_grid_as_written() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("study");
    let o = run(&[
        "study",
        root()
            .join("scenarios/sedan_study_coarse.toml")
            .to_str()
            .unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = fs::read_to_string(out.join("study.csv")).unwrap();
    let mut pairs: Vec<(String, String)> = text
        .lines()
        .skip(1)
        .map(|l| {
            let mut c = l.split(',');
            (c.next().unwrap().into(), c.next().unwrap().into())
        })
        .collect();
    pairs.dedup();
    // The map's 200…700 by 100 and the RBF pairs' front + 20 and + 40 N/deg.
    for (front, rear) in &pairs {
        for v in [front, rear] {
            let x: f64 = v.parse().unwrap();
            assert!(x.fract() == 0.0 && *v == format!("{x}"), "{v} in {text}");
        }
    }
    assert!(pairs.contains(&("200".into(), "240".into())), "{pairs:?}");
    assert!(pairs.contains(&("700".into(), "720".into())), "{pairs:?}");
}

#[test]
fn a_column_or_tir_key_given_twice_is_refused_not_dropped() {
    let dir = scratch(&[(
        "p.csv",
        "fz,kappa,alpha,camber,speed,kappa\n4000,0,0.05,0,20,0.1\n",
    )]);
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let tyre_eval = |tir: &Path, out: &Path| {
        run(&[
            "tyre-eval",
            tir.to_str().unwrap(),
            dir.path().join("p.csv").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ])
    };
    let out = dir.path().join("o.csv");
    let e = refused(&tyre_eval(&tir, &out), &out);
    assert!(
        e.contains("p.csv:1:6: `kappa` appears twice (also column 2)"),
        "{e}"
    );
    // A .tir whose FNOMIN is given twice with two values.
    let text = fs::read_to_string(&tir).unwrap();
    let line = text
        .lines()
        .position(|l| l.trim_start().starts_with("FNOMIN"))
        .unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    lines.insert(line + 1, "FNOMIN = 9999".into());
    let twice = dir.path().join("twice.tir");
    fs::write(&twice, lines.join("\n")).unwrap();
    fs::write(
        dir.path().join("p.csv"),
        "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,20\n",
    )
    .unwrap();
    let e = refused(&tyre_eval(&twice, &out), &out);
    assert!(
        e.contains(&format!(
            "twice.tir:{}:1: `FNOMIN` appears twice (also line {})",
            line + 2,
            line + 1
        )),
        "{e}"
    );
}

#[test]
fn a_steering_compliance_in_rad_per_kn_is_refused_not_integrated() {
    let dir = scenario(
        VEHICLE,
        GIM,
        "[model.effects]\nsteering_compliance = 0.003\n\n[manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0174533\n",
    );
    let e = simulate_err(dir.path());
    assert!(
        e.contains("`model.effects.steering_compliance` = 0.003: must lie in [0, 0.0001]")
            && e.contains("0.003 rad/kN, the diagnosis's unit, is 3e-6 rad/N"),
        "{e}"
    );
}
