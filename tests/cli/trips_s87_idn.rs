//! What a fresh user still tripped on in `identify`: a fit
//! with a parameter held that ended below the same fit with it free, a
//! linear window said to leave out "where the force saturates" on data
//! that never saturate, and rig `fy` and `mz` columns exchanged asked
//! about as an `mz` in N·mm.

use super::*;

/// Rig rows of the bundled UniTire at four loads, ±0.2 rad, with 1.3 %
/// multiplicative noise on `fy` and `mz` from a fixed generator (a
/// Box–Muller pair of a 64-bit LCG), written by `tyre-eval` in `dir`.
fn noisy_unitire(dir: &Path) -> PathBuf {
    let mut points = String::from("fz,kappa,alpha,camber,speed\n");
    for fz in [2500, 4000, 5500, 7000] {
        for i in -60..=60 {
            points += &format!("{fz},0,{},0,20\n", f64::from(i) * 0.2 / 60.0);
        }
    }
    fs::write(dir.join("pts.csv"), points).unwrap();
    let tyre = root().join("tyres/unitire.toml");
    let o = run_in(
        dir,
        &[
            "tyre-eval",
            tyre.to_str().unwrap(),
            "pts.csv",
            "--out",
            "clean.csv",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let clean = fs::read_to_string(dir.join("clean.csv")).unwrap();
    let mut state: u64 = 6;
    let mut uniform = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    };
    let mut gauss = || {
        let (u, v) = (uniform(), uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    };
    let mut rig = String::from("fz,alpha,camber,fy,mz\n");
    for line in clean.lines().skip(1) {
        // fz, kappa, alpha, camber, speed, fx, fy, mz
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        let fy = v[6] * (1.0 + 0.013 * gauss());
        let mz = v[7] * (1.0 + 0.013 * gauss());
        rig += &format!("{},{},{},{fy:.3},{mz:.4}\n", v[0], v[2], v[3]);
    }
    let path = dir.join("rig.csv");
    fs::write(&path, rig).unwrap();
    path
}

/// Each fit of `report` (the first channel, the aligning moment) that
/// held a parameter: its σ held and its σ free.
fn held_and_free(report: &serde_json::Value) -> Vec<(f64, f64)> {
    [report, &report["aligning"]]
        .into_iter()
        .filter_map(|f| {
            Some((
                f["sigma_percent"].as_f64()?,
                f["free_sigma_percent"].as_f64()?,
            ))
        })
        .collect()
}

/// UniTire's aligning moment with `c3` held ended at a lower σ than with
/// it free (1.314 % against 1.335 %): the free fit, here the swarm's best
/// unpolished under `--local none`, had stopped short. A fit with one
/// more free parameter can never be worse: the free fit is restarted from
/// the held fit's optimum, and its σ is at most the held one's.
#[test]
fn a_free_fit_never_ends_above_the_same_fit_with_a_parameter_held() {
    let dir = tempfile::tempdir().unwrap();
    let rig = noisy_unitire(dir.path());
    let out = dir.path().join("u.toml");
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "unitire",
        "--local",
        "none",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report = read_json(&dir.path().join("u.report.json"));
    let said = String::from_utf8_lossy(&o.stdout).into_owned();
    let fits = held_and_free(&report);
    assert!(!fits.is_empty(), "nothing held\n{said}");
    for (held, free) in fits {
        assert!(free <= held, "σ {free} % free above {held} % held\n{said}");
    }
    // The swarm's start had stopped above the held fit: restarted.
    let aligning = &report["aligning"];
    let swarm = aligning["free_swarm_sigma_percent"].as_f64().unwrap();
    let sigma = aligning["sigma_percent"].as_f64().unwrap();
    assert!(sigma < swarm, "{sigma} against the swarm start's {swarm}");
    assert!(said.contains("restarted from the"), "{said}");
}

/// On the public Hoosier file at 97.1 kPa and 0° camber, `--model
/// unitire` said "lateral force: p2 held …: σ 4.799 % held against
/// 5.589 % fitted free": the Levenberg–Marquardt polish had left the
/// swarm's best where it was. Restarted from the held optimum, the free
/// fit reaches below the held one, and the fit written below 4.799 %.
#[test]
fn the_hoosier_unitire_fit_restarts_its_free_fit_from_the_held_optimum() {
    let test = "the_hoosier_unitire_fit_restarts_its_free_fit_from_the_held_optimum";
    let Some(rig) = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("u.toml");
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "unitire",
        "--pressure",
        "97100",
        "--camber",
        "0",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report = read_json(&dir.path().join("u.report.json"));
    let said = String::from_utf8_lossy(&o.stdout).into_owned();
    for (held, free) in held_and_free(&report) {
        assert!(free <= held, "σ {free} % free above {held} % held\n{said}");
    }
    let swarm = report["free_swarm_sigma_percent"].as_f64().unwrap();
    assert!((swarm - 5.589).abs() < 0.001, "{swarm}\n{said}");
    let sigma = report["sigma_percent"].as_f64().unwrap();
    assert!(sigma < 4.79, "{sigma}\n{said}");
}

/// Rig rows of the bundled linear tyre (57 296 N/rad, no saturation) at
/// four loads, ±0.2 rad, as `tyre-eval` writes them, in `dir`.
fn linear_rig(dir: &Path) -> PathBuf {
    let mut points = String::from("fz,kappa,alpha,camber,speed\n");
    for fz in [2500, 4000, 5500, 7000] {
        for i in -60..=60 {
            points += &format!("{fz},0,{},0,20\n", f64::from(i) * 0.2 / 60.0);
        }
    }
    fs::write(dir.join("lin_pts.csv"), points).unwrap();
    let tyre = root().join("tyres/linear.toml");
    let o = run_in(
        dir,
        &[
            "tyre-eval",
            tyre.to_str().unwrap(),
            "lin_pts.csv",
            "--out",
            "lin.csv",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    dir.join("lin.csv")
}

/// `identify --model linear` on the rows of a linear tyre said its window
/// left 312 points out "where the force saturates", of a force that never
/// does. The points beyond the window follow its line here, so the window
/// is not needed: every point is fitted, and the line says why.
#[test]
fn a_linear_fit_of_a_force_that_never_saturates_fits_every_point() {
    let dir = tempfile::tempdir().unwrap();
    let rig = linear_rig(dir.path());
    let out = dir.path().join("lin_fit.toml");
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "linear",
        "--load",
        "4000",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(!said.contains("saturates"), "{said}");
    assert!(said.contains("  linear window: not needed: in the 1 condition judged the points beyond |alpha| = 2 deg follow the line through those within it"), "{said}");
    assert!(said.contains("all 93 points are fitted\n"), "{said}");
    let report = read_json(&dir.path().join("lin_fit.report.json"));
    let w = &report["linear_window"];
    assert_eq!(w["points_left_out"], 0, "{w}");
    assert_eq!(w["points_fitted"], 93, "{w}");
    assert_eq!(w["beyond"]["beyond_window"], "follow_line", "{w}");
    let tyre: toml::Value = toml::from_str(&fs::read_to_string(&out).unwrap()).unwrap();
    let c = tyre["cornering_stiffness"].as_float().unwrap();
    assert!((c / 57296.0 - 1.0).abs() < 1e-6, "{c}");
    // The range written is the data's, ±0.2 rad, not the window's ±2°.
    let text = fs::read_to_string(&out).unwrap();
    assert!(text.contains("alpha = [-0.2, 0.2]"), "{text}");
}

/// The same fit on a tyre that saturates (the bundled UniTire's rows)
/// keeps its window, and says by how much the points beyond depart.
#[test]
fn a_linear_fit_of_a_saturating_force_keeps_its_window_and_says_the_departure() {
    let dir = tempfile::tempdir().unwrap();
    let rig = noisy_unitire(dir.path());
    let out = dir.path().join("lin_fit.toml");
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "linear",
        "--load",
        "4000",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(said.contains("  linear window: fitted to |alpha| <= 2 deg only (17 points; 76 points with larger |alpha| left out, where the force saturates: in 1 of the 1 condition judged they depart from the window's line by up to "), "{said}");
    let report = read_json(&dir.path().join("lin_fit.report.json"));
    let w = &report["linear_window"];
    assert_eq!(w["beyond"]["beyond_window"], "saturates", "{w}");
    assert!(
        w["beyond"]["departure_percent"].as_f64().unwrap() > 20.0,
        "{w}"
    );
}

/// `noisy_unitire`'s rows with their header rewritten by `header`, as
/// `name` in `dir`.
fn with_header(dir: &Path, name: &str, header: &str, scale_mz: f64) -> PathBuf {
    let rig = fs::read_to_string(noisy_unitire(dir)).unwrap();
    let mut text = format!("{header}\n");
    for line in rig.lines().skip(1) {
        let mut v: Vec<String> = line.split(',').map(String::from).collect();
        // In N·mm the heaviest loads' moments pass the reader's 1e5 N·m.
        if scale_mz > 1.0 && v[0].parse::<f64>().unwrap() > 5000.0 {
            continue;
        }
        let mz: f64 = v[4].parse().unwrap();
        v[4] = format!("{}", mz * scale_mz);
        text += &(v.join(",") + "\n");
    }
    let path = dir.join(name);
    fs::write(&path, text).unwrap();
    path
}

/// A rig file whose `fy` and `mz` columns were exchanged was asked "is the
/// column in N·mm? divide it by 1000", which would have fitted a force as
/// a moment. The `mz` column holds forces of the load's size and `fy`
/// values a trail's share of them: said as swapped, both columns named,
/// at the file's line and column; a moment in N·mm is still asked so.
#[test]
fn rig_fy_and_mz_columns_exchanged_are_said_swapped_not_in_n_mm() {
    let dir = tempfile::tempdir().unwrap();
    let swapped = with_header(dir.path(), "swapped.csv", "fz,alpha,camber,mz,fy", 1.0);
    let out = dir.path().join("s.toml");
    let e = refused(&identify_to(&swapped, "unitire", &out), &out);
    assert!(!e.contains("N·mm? divide"), "{e}");
    assert!(e.contains("swapped.csv:"), "{e}");
    assert!(e.contains(":4: column `mz`: "), "{e}");
    assert!(e.contains("times the load, a lateral force's size, and the `fy` column (column 5) beside it holds values "), "{e}");
    assert!(
        e.contains("the columns `fy` and `mz` look swapped: exchange their names in the header"),
        "{e}"
    );
    let trail: f64 = e
        .split("a pneumatic trail of ")
        .nth(1)
        .and_then(|t| t.split(" mm").next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("{e}"));
    assert!((5.0..=60.0).contains(&trail), "{trail}: {e}");
    // The same rows with `mz` in N·mm: still asked about N·mm.
    let mm = with_header(dir.path(), "mm.csv", "fz,alpha,camber,fy,mz", 1000.0);
    let out = dir.path().join("m.toml");
    let e = refused(&identify_to(&mm, "unitire", &out), &out);
    assert!(
        e.contains("is the column in N·mm? divide it by 1000"),
        "{e}"
    );
    assert!(!e.contains("swapped"), "{e}");
}
