//! The Magic Formula 6.1/6.2 from .tir files through the CLI.

use super::*;

/// A symmetric MF 6.1 lateral tyre in millimetres and kilonewtons, in the
/// layout TNO tools write: header, units, model, sections, `$` comments.
fn symmetric_tir(side: &str, extra: &str) -> String {
    format!(
        "[MDI_HEADER]\nFILE_TYPE = 'tir'\nFILE_VERSION = 3.0\n$------units\n[UNITS]\n\
         LENGTH = 'mm'\nFORCE = 'kN'\nANGLE = 'radians'\nMASS = 'kg'\nTIME = 'second'\n\
         [MODEL]\nFITTYP = 61 $ MF 6.1\nTYRESIDE = '{side}'\nLONGVL = 16700\nVXLOW = 1000\n\
         [DIMENSION]\nUNLOADED_RADIUS = 313.0 ! free radius\n[VERTICAL]\nFNOMIN = 4.0\n\
         [SHAPE]\n{{radial width}}\n 1.0 0.0\n 1.1 0.2\n[LATERAL_COEFFICIENTS]\n\
         PCY1 = 1.3\nPDY1 = 1.1\nPKY1 = -15.0\nPKY2 = 1.7\nPEY1 = -0.5\n{extra}"
    )
}

/// The pure-slip lateral force of `symmetric_tir` in closed form (Pacejka
/// 2012 eq. 4.E19–4.E30 with every other coefficient zero), in the crate's
/// sign convention: positive slip angle, positive force.
fn closed_form_fy(fz: f64, alpha: f64) -> f64 {
    let fz0 = 4000.0;
    let kya = -15.0 * fz0 * (2.0 * (fz / (1.7 * fz0)).atan()).sin();
    let (c, d, e) = (1.3, 1.1 * fz, -0.5);
    let b = kya / (c * d + 1e-6);
    let x = (-alpha).tan();
    d * (c * (b * x - e * (b * x - (b * x).atan())).atan()).sin()
}

fn points(rows: &[(f64, f64, f64, f64)]) -> String {
    let mut s = String::from("fz,kappa,alpha,camber,speed\n");
    for (fz, k, a, g) in rows {
        s.push_str(&format!("{fz},{k},{a},{g},20\n"));
    }
    s
}

/// Runs `handling tyre-eval tyre points --out out`.
fn tyre_eval(tyre: &Path, points: &Path, out: &Path) -> Output {
    run(&[
        "tyre-eval",
        tyre.to_str().unwrap(),
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
}

#[test]
fn tyre_eval_matches_the_closed_form_and_converts_units() {
    let alphas = [-0.4, -0.1, -0.01, 0.0, 0.003, 0.05, 0.2, 0.6];
    let rows: Vec<_> = [2000.0, 4000.0, 6500.0]
        .iter()
        .flat_map(|fz| alphas.iter().map(move |a| (*fz, 0.0, *a, 0.0)))
        .collect();
    let dir = scratch(&[
        ("tyre.tir", &symmetric_tir("LEFT", "")),
        ("points.csv", &points(&rows)),
    ]);
    let out = dir.path().join("forces.csv");
    let o = tyre_eval(
        &dir.path().join("tyre.tir"),
        &dir.path().join("points.csv"),
        &out,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let (head, got) = numeric_csv(&out);
    assert_eq!(
        head,
        ["fz", "kappa", "alpha", "camber", "speed", "fx", "fy", "mz", "mx", "my"]
    );
    assert_eq!(got.len(), rows.len());
    for (r, g) in rows.iter().zip(&got) {
        let want = closed_form_fy(r.0, r.2);
        let fy = g[column(&head, "fy")];
        assert!(
            (fy - want).abs() <= 1e-9 * want.abs() + 1e-9,
            "fz {} alpha {}: {fy} vs {want}",
            r.0,
            r.2
        );
        // Odd symmetry of a symmetric tyre, and the sign convention.
        assert!(r.2 == 0.0 || fy.signum() == r.2.signum());
    }
}

#[test]
fn right_side_file_is_the_mirror_image() {
    let extra = "PHY1 = 0.004\nPVY1 = 0.03\nPVY3 = 0.2\nPKY6 = -0.9\nQSX1 = 0.01\n\
                 QBZ1 = 10\nQCZ1 = 1.2\nQDZ1 = 0.1\n";
    let rows = [
        (4000.0, 0.0, 0.05, 0.03),
        (3000.0, 0.05, -0.1, -0.02),
        (5000.0, -0.1, 0.2, 0.0),
    ];
    let mirrored: Vec<_> = rows.iter().map(|r| (r.0, r.1, -r.2, -r.3)).collect();
    let dir = scratch(&[
        ("left.tir", &symmetric_tir("LEFT", extra)),
        ("right.tir", &symmetric_tir("RIGHT", extra)),
        ("p.csv", &points(&rows)),
        ("m.csv", &points(&mirrored)),
    ]);
    let eval = |tyre: &str, pts: &str| {
        let out = dir.path().join(format!("{tyre}-{pts}.out"));
        let o = tyre_eval(&dir.path().join(tyre), &dir.path().join(pts), &out);
        assert!(o.status.success(), "{}", stderr(&o));
        numeric_csv(&out)
    };
    let (head, left) = eval("left.tir", "p.csv");
    let (_, right) = eval("right.tir", "m.csv");
    for (l, r) in left.iter().zip(&right) {
        for (name, sign) in [
            ("fx", 1.0),
            ("fy", -1.0),
            ("mz", -1.0),
            ("mx", -1.0),
            ("my", 1.0),
        ] {
            let i = column(&head, name);
            assert!(
                (l[i] - sign * r[i]).abs() <= 1e-9 * l[i].abs().max(1.0),
                "{name}: {} vs {}",
                l[i],
                r[i]
            );
        }
        assert!(left.iter().any(|l| l[column(&head, "fy")].abs() > 100.0));
    }
}

#[test]
fn public_tir_files_load_and_combined_force_stays_below_pure() {
    for v in [
        "MagicFormula52_Parameters",
        "MagicFormula61_Parameters",
        "MagicFormula62_Parameters",
        "chrono_Sedan_Pac02Tire",
        "chrono_HMMWV_Pac02Tire",
        "chrono_mf_185_80R14",
    ] {
        let tir = root().join(format!("tests/fixtures/tir/{v}.tir"));
        let mut rows = Vec::new();
        for fz in [2000.0, 4000.0, 6000.0] {
            for a in [0.08, 0.15, 0.3] {
                rows.push((fz, 0.0, a, 0.0));
                rows.push((fz, 0.15, a, 0.0));
                rows.push((fz, -0.15, a, 0.0));
            }
        }
        let dir = scratch(&[("p.csv", &points(&rows))]);
        let out = dir.path().join("f.csv");
        let o = tyre_eval(&tir, &dir.path().join("p.csv"), &out);
        assert!(o.status.success(), "{v}: {}", stderr(&o));
        let (head, got) = numeric_csv(&out);
        // Beyond small slip angles (where the κ-induced shift SVyκ may add
        // a few newtons), slip in the other direction only takes force away
        // (or none: Chrono's Sedan file has no lateral combined-slip
        // coefficients, so its weight Gyκ is 1).
        let fy = column(&head, "fy");
        for chunk in got.chunks(3) {
            let pure = chunk[0][fy].abs();
            assert!(pure > 50.0, "{v}: no lateral force {pure}");
            for c in &chunk[1..] {
                assert!(c[fy].abs() <= pure, "{v}: combined {} > pure {pure}", c[fy]);
            }
        }
    }
}

/// A public file of a Magic Formula the model does not implement (Chrono's
/// FED-Alpha tyre, `FITTYP = 5`, MF-Tyre 5.0) is refused with its file,
/// line, column and key rather than evaluated as another version.
#[test]
fn unsupported_fittyp_of_a_public_file_is_refused_with_file_line_and_key() {
    let tir = root().join("tests/fixtures/tir/chrono_335_65R22_5_G275MSA_60psi.tir");
    let dir = scratch(&[("p.csv", "fz,kappa,alpha,camber,speed\n20000,0,0.1,0,20\n")]);
    let out = dir.path().join("f.csv");
    let o = tyre_eval(&tir, &dir.path().join("p.csv"), &out);
    assert!(!o.status.success());
    assert!(!out.exists());
    let e = stderr(&o);
    assert!(
        e.contains("chrono_335_65R22_5_G275MSA_60psi.tir:55:")
            && e.contains("FITTYP")
            && e.contains('5'),
        "{e}"
    );
}

#[test]
fn broken_tir_and_points_name_file_line_and_key() {
    let bad_value = symmetric_tir("LEFT", "").replace("PDY1 = 1.1", "PDY1 = 1,1");
    let bad_fittyp = symmetric_tir("LEFT", "").replace("FITTYP = 61", "FITTYP = 5");
    let dir = scratch(&[
        ("value.tir", &bad_value),
        ("fittyp.tir", &bad_fittyp),
        ("good.tir", &symmetric_tir("LEFT", "")),
        ("p.csv", "fz,kappa,alpha,camber,speed\n4000,0,0.1,0,20\n"),
        (
            "bad.csv",
            "speed,fz,kappa,alpha,camber\n20,4000,0,0.1,0\n20,4000,0,abc,0\n",
        ),
    ]);
    let eval = |tyre: &str, pts: &str| {
        let o = tyre_eval(
            &dir.path().join(tyre),
            &dir.path().join(pts),
            &dir.path().join("out.csv"),
        );
        assert!(!o.status.success());
        assert!(!dir.path().join("out.csv").exists());
        stderr(&o)
    };
    let e = eval("value.tir", "p.csv");
    assert!(
        e.contains("value.tir:26:8:") && e.contains("PDY1") && e.contains("1,1"),
        "{e}"
    );
    let e = eval("fittyp.tir", "p.csv");
    assert!(e.contains("fittyp.tir:12:") && e.contains("FITTYP"), "{e}");
    let e = eval("good.tir", "bad.csv");
    assert!(
        e.contains("bad.csv:3:4") && e.contains("alpha") && e.contains("abc"),
        "{e}"
    );
}

#[test]
fn scenario_with_a_tir_tyre_simulates() {
    let tir = fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap();
    let sc = format!("{VEHICLE}\n[tyres]\nfront = \"tyre.tir\"\n\n{STEP}");
    let dir = scratch(&[("scenario.toml", &sc), ("tyre.tir", &tir)]);
    let out = dir.path().join("out");
    let o = run(&[
        "simulate",
        dir.path().join("scenario.toml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let m = read_json(&out.join("metrics.json"));
    let gain = m["yaw_rate_gain"].as_f64().unwrap();
    // The linear bicycle-model gain u/(l + K·u²) bounds an understeering
    // car's gain from above (neutral steer, K = 0: 22.2/2.78 = 8 /s per rad);
    // a car with any grip has a positive gain.
    assert!(gain > 1.0 && gain < 8.0, "{m}");
}

/// Reference rows of an independent implementation: (fz, kappa, alpha_iso,
/// camber_iso, speed, pressure, fx, fy, mz, mx, my), ISO-W, unmirrored.
fn reference(name: &str) -> Vec<Vec<f64>> {
    let text =
        fs::read_to_string(root().join(format!("tests/fixtures/tir/reference_mfeval_{name}.csv")))
            .unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect()
}

/// Every force and moment, with and without camber, combined slip, two
/// pressures (one for 5.2/PAC2002), against MFeval's numbers
/// (tests/fixtures/tir/README.md): MFeval's three sample files and three of
/// Chrono's PAC2002 files (no `FITTYP`: read as 5.2).
#[test]
fn tyre_eval_agrees_with_mfeval_on_public_files() {
    // (.tir file, reference, FNOMIN, rows, TYRESIDE = RIGHT)
    for (tir, v, fnomin, n, right) in [
        ("MagicFormula61_Parameters", "mf61", 6752.0, 1638, true),
        ("MagicFormula62_Parameters", "mf62", 6752.0, 1638, true),
        // QSY7 = 0 (derived from the 6.1 file): a 6.x My without load power.
        (
            "MagicFormula61_QSY7_zero",
            "mf61_qsy7_zero",
            6752.0,
            1638,
            true,
        ),
        ("MagicFormula52_Parameters", "mf52", 9416.6, 819, false),
        ("chrono_Sedan_Pac02Tire", "chrono_sedan", 4850.0, 819, false),
        (
            "chrono_HMMWV_Pac02Tire",
            "chrono_hmmwv",
            35000.0,
            819,
            false,
        ),
        ("chrono_mf_185_80R14", "chrono_microbus", 3800.0, 819, false),
    ] {
        let rows = reference(v);
        assert_eq!(rows.len(), n);
        // The crate presents a left tyre (module docs of tyre::mf): a
        // left-side file is evaluated at α_ISO = −α, γ_ISO = γ, with
        // fy = Fy, mz = −Mz, mx = Mx; a right-side file mirrored at
        // α_ISO = α, γ_ISO = −γ, with fy = −Fy, mz = Mz, mx = −Mx.
        let (sa, sg) = if right { (1.0, -1.0) } else { (-1.0, 1.0) };
        let mut pts = String::from("fz,kappa,alpha,camber,speed,pressure\n");
        for r in &rows {
            pts.push_str(&format!(
                "{},{},{},{},{},{}\n",
                r[0],
                r[1],
                sa * r[2],
                sg * r[3],
                r[4],
                r[5]
            ));
        }
        let dir = scratch(&[("points.csv", &pts)]);
        let out = dir.path().join("forces.csv");
        let tir = root().join(format!("tests/fixtures/tir/{tir}.tir"));
        let o = tyre_eval(&tir, &dir.path().join("points.csv"), &out);
        assert!(o.status.success(), "{}", stderr(&o));
        let (head, got) = numeric_csv(&out);
        let mirror = if right { -1.0 } else { 1.0 };
        let mut cambered_mz = 0;
        for (r, g) in rows.iter().zip(&got) {
            for (name, i, sign) in [
                ("fx", 6, 1.0),
                ("fy", 7, mirror),
                ("mz", 8, -mirror),
                ("mx", 9, mirror),
                ("my", 10, 1.0),
            ] {
                let (want, have) = (sign * r[i], g[column(&head, name)]);
                assert!(
                    (have - want).abs() <= 1e-6 * want.abs() + 1e-6 * fnomin,
                    "{v} {name} at {r:?}: {have} vs {want}"
                );
            }
            if r[3] != 0.0 && r[8].abs() > 10.0 {
                cambered_mz += 1;
            }
        }
        // The camber rows carry aligning moments worth checking.
        assert!(cambered_mz > n / 3, "{v}: {cambered_mz}");
    }
}

/// MFeval's four modes without turn slip (useMode 121, 111, 221, 211) on a
/// grid that reaches past each file's `[*_LIMITS]` ranges (load above
/// `FZMAX` and below `FZMIN`, slip ratio, slip angle, inclination and
/// pressure outside theirs; κ past −1, where `My` turns with the wheel):
/// `tyre-eval --mode` equals MFeval's numbers to 1e-6 of FNOMIN (forces)
/// and of FNOMIN·R0 (moments). The modes give different numbers on this
/// grid, so a mode read wrongly fails.
#[test]
fn tyre_eval_modes_agree_with_mfeval_past_the_limits() {
    // (.tir file, reference, FNOMIN, UNLOADED_RADIUS, rows per mode, right)
    for (tir, v, fnomin, r0, n, right) in [
        (
            "MagicFormula61_Parameters",
            "mf61",
            6752.0,
            0.3943,
            384,
            true,
        ),
        (
            "MagicFormula62_Parameters",
            "mf62",
            6752.0,
            0.3943,
            384,
            true,
        ),
        (
            "MagicFormula61_QSY7_zero",
            "mf61_qsy7_zero",
            6752.0,
            0.3943,
            384,
            true,
        ),
        ("MagicFormula52_Parameters", "mf52", 9416.6, 0.4, 192, false),
        (
            "chrono_Sedan_Pac02Tire",
            "chrono_sedan",
            4850.0,
            0.344,
            192,
            false,
        ),
        (
            "chrono_HMMWV_Pac02Tire",
            "chrono_hmmwv",
            35000.0,
            0.4699,
            192,
            false,
        ),
        (
            "chrono_mf_185_80R14",
            "chrono_microbus",
            3800.0,
            0.376,
            192,
            false,
        ),
    ] {
        let rows = reference(&format!("modes_{v}"));
        let (sa, sg, mirror) = if right {
            (1.0, -1.0, -1.0)
        } else {
            (-1.0, 1.0, 1.0)
        };
        let mut by_mode = Vec::new();
        for mode in [121.0, 111.0, 221.0, 211.0] {
            let sel: Vec<_> = rows.iter().filter(|r| r[6] == mode).collect();
            assert_eq!(sel.len(), n, "{v} {mode}");
            let mut pts = String::from("fz,kappa,alpha,camber,speed,pressure\n");
            for r in &sel {
                let (a, g) = (sa * r[2], sg * r[3]);
                pts.push_str(&format!("{},{},{a},{g},{},{}\n", r[0], r[1], r[4], r[5]));
            }
            let dir = scratch(&[("points.csv", &pts)]);
            let out = dir.path().join("forces.csv");
            let tir_path = root().join(format!("tests/fixtures/tir/{tir}.tir"));
            let o = run(&[
                "tyre-eval",
                tir_path.to_str().unwrap(),
                dir.path().join("points.csv").to_str().unwrap(),
                "--out",
                out.to_str().unwrap(),
                "--mode",
                &format!("{mode}"),
            ]);
            assert!(o.status.success(), "{}", stderr(&o));
            // Limit checks on: the points evaluated at the limits are
            // counted, once for the batch; off: none is.
            let said = String::from_utf8_lossy(&o.stdout).to_string();
            assert!(said.contains(&format!("MFeval mode {mode}")), "{said}");
            assert_eq!(
                said.contains("outside the file's ranges"),
                mode < 200.0,
                "{said}"
            );
            let (head, got) = numeric_csv(&out);
            for (r, g) in sel.iter().zip(&got) {
                for (name, i, sign, scale) in [
                    ("fx", 7, 1.0, fnomin),
                    ("fy", 8, mirror, fnomin),
                    ("mz", 9, -mirror, fnomin * r0),
                    ("mx", 10, mirror, fnomin * r0),
                    ("my", 11, 1.0, fnomin * r0),
                ] {
                    let (want, have) = (sign * r[i], g[column(&head, name)]);
                    assert!(
                        (have - want).abs() <= 1e-6 * scale,
                        "{v} mode {mode} {name} at {r:?}: {have} vs {want}"
                    );
                }
            }
            by_mode.push(got);
        }
        // The limit checks and α* each move some point's fy by > 1 N
        // (columns: the six inputs, then fx, fy, …).
        let fy = 7;
        let moved = |a: usize, b: usize| {
            by_mode[a]
                .iter()
                .zip(&by_mode[b])
                .filter(|(x, y)| (x[fy] - y[fy]).abs() > 1.0)
                .count()
        };
        assert!(moved(0, 2) > 0 && moved(0, 1) > 0, "{v}");
    }
}

#[test]
fn a_turn_slip_mode_or_a_mode_on_another_model_is_refused_by_name() {
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let dir = scratch(&[
        ("p.csv", "fz,kappa,alpha,camber,speed\n4000,0,0.1,0,20\n"),
        (
            "linear.toml",
            "model = \"linear\"\ncornering_stiffness = 80000\n",
        ),
    ]);
    let out = dir.path().join("f.csv");
    let eval = |tyre: &Path, mode: &str| {
        let o = run(&[
            "tyre-eval",
            tyre.to_str().unwrap(),
            dir.path().join("p.csv").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--mode",
            mode,
        ]);
        assert!(!o.status.success());
        assert!(!out.exists());
        stderr(&o)
    };
    let e = eval(&tir, "122");
    assert!(
        e.contains("--mode") && e.contains("turn slip") && e.contains("121"),
        "{e}"
    );
    let e = eval(&tir, "131");
    assert!(e.contains("tens digit 3"), "{e}");
    let e = eval(&dir.path().join("linear.toml"), "121");
    assert!(e.contains("Magic Formula") && e.contains("linear"), "{e}");
}

/// The `[tyres]` table's `mode` reaches the .tir tyres of a scenario: a
/// turn-slip mode is refused with the file, line and key; 221 runs.
#[test]
fn scenario_tyre_mode_key_is_read_and_checked() {
    let tir = fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap();
    let sc =
        |mode: u32| format!("{VEHICLE}\n[tyres]\nfront = \"tyre.tir\"\nmode = {mode}\n\n{STEP}");
    let dir = scratch(&[
        ("bad.toml", &sc(122)),
        ("off.toml", &sc(221)),
        ("tyre.tir", &tir),
    ]);
    let sim = |name: &str| {
        run(&[
            "simulate",
            dir.path().join(name).to_str().unwrap(),
            "--out",
            dir.path().join(format!("{name}.out")).to_str().unwrap(),
        ])
    };
    let o = sim("bad.toml");
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("bad.toml:") && e.contains("tyres.mode") && e.contains("turn slip"),
        "{e}"
    );
    let o = sim("off.toml");
    assert!(o.status.success(), "{}", stderr(&o));
}
