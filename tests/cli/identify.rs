//! Tyre identification from rig files.

use super::*;

fn rig_csv(rows: &[(f64, f64, f64)]) -> String {
    let mut s = String::from("fz,alpha,fy\n");
    for (fz, a, fy) in rows {
        s.push_str(&format!("{fz},{a},{fy}\n"));
    }
    s
}

#[test]
fn identify_refuses_bad_rig_data_clearly() {
    // No lateral columns.
    let dir = scratch(&[("rig.csv", "fz,kappa,fx\n4000,0.01,500\n")]);
    let e = stderr(&run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "gim",
    ]));
    assert!(
        e.contains("rig.csv")
            && e.contains("no lateral data")
            && e.contains("no longitudinal force"),
        "{e}"
    );
    // Neither lateral nor longitudinal columns.
    let dir2 = scratch(&[("rig.csv", "fz,speed\n4000,10\n")]);
    let e = stderr(&run(&[
        "identify",
        dir2.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "pac89",
    ]));
    assert!(
        e.contains("no lateral data") && e.contains("no longitudinal data"),
        "{e}"
    );
    // Unknown model.
    let e = stderr(&run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "pac2002",
    ]));
    assert!(e.contains("unknown tyre model `pac2002`"), "{e}");
    // A NaN cell.
    let dir = scratch(&[("rig.csv", "fz,alpha,fy\n4000,0.01,500\n4000,NaN,600\n")]);
    let e = stderr(&run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "gim",
    ]));
    assert!(e.contains("rig.csv:3:2") && e.contains("alpha"), "{e}");
    // A single load for a load-dependent model.
    let rows: Vec<(f64, f64, f64)> = (0..40)
        .map(|i| {
            (
                4000.0,
                0.005 * (i as f64 - 20.0),
                60_000.0 * 0.005 * (i as f64 - 20.0),
            )
        })
        .collect();
    let dir = scratch(&[("rig.csv", &rig_csv(&rows))]);
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "pac89",
        "--out",
        dir.path().join("t.toml").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("at least 3 loads"), "{}", stderr(&o));
    assert!(!dir.path().join("t.toml").exists());
}

#[test]
fn an_identified_tyre_file_loads_and_simulates() {
    let rows: Vec<(f64, f64, f64)> = [2000.0, 4000.0, 6000.0]
        .iter()
        .flat_map(|&fz| {
            (0..41).map(move |i| {
                let a = 0.005 * (i as f64 - 20.0);
                (fz, a, fz * (1.3 * (10.0 * a).atan()).sin())
            })
        })
        .collect();
    let dir = scratch(&[("rig.csv", &rig_csv(&rows))]);
    let tyre = dir.path().join("fitted.toml");
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "magic-simple",
        "--seed",
        "3",
        "--out",
        tyre.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report: serde_json::Value = read_json(&dir.path().join("fitted.report.json"));
    assert_eq!(report["seed"], 3);
    assert!(report["sigma_percent"].as_f64().unwrap() < 1e-6, "{report}");
    for key in ["model", "curves", "parameters", "evaluations", "seconds"] {
        assert!(report.get(key).is_some(), "{key}");
    }
    assert_eq!(report["curves"].as_array().unwrap().len(), 3);
    // The fitted file is a tyre file like any other.
    let sc = format!("{VEHICLE}\n[tyres]\nfront = \"fitted.toml\"\n\n{STEP}");
    fs::write(dir.path().join("scenario.toml"), sc).unwrap();
    let o = run(&[
        "simulate",
        dir.path().join("scenario.toml").to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn real_hoosier_rig_data_fits_within_a_few_percent() {
    let data = root().join("../shared/data/tyre_ttc_hoosier_43075/cornering.csv");
    if !data.exists() {
        skipped("real_hoosier_rig_data_fits_within_a_few_percent", &data);
        return;
    }
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "identify",
        data.to_str().unwrap(),
        "--model",
        "pac89",
        "--pressure",
        "83000",
        "--camber",
        "0",
        "--out",
        out.path().join("pac89.toml").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report: serde_json::Value = read_json(&out.path().join("pac89.report.json"));
    let sigma = report["sigma_percent"].as_f64().unwrap();
    assert!(sigma < 3.0, "σ {sigma} %");
    assert_eq!(
        report["curves"].as_array().unwrap().len(),
        5,
        "five loads at one pressure and camber"
    );
}

#[test]
fn identify_fits_longitudinal_only_rig_data() {
    // Fx of the Adams PAC89 example at three loads (kN inside the model):
    // D·sin(C·atan(B·x − E·(B·x − atan(B·x)))), x = 100·κ + Sh.
    let b = [
        1.67272, -9.46, 1490.0, 30.0, 176.0, 0.0886, 0.00402, -0.0615, 0.20, 0.0299, -0.176,
    ];
    let mut s = String::from("fz,kappa,fx\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        let z: f64 = fz / 1000.0;
        let c = b[0];
        let d = b[1] * z * z + b[2] * z;
        let bb = (b[3] * z * z + b[4] * z) * (-b[5] * z).exp() / (c * d);
        let e = b[6] * z * z + b[7] * z + b[8];
        for i in -25..=25 {
            let kappa = 0.01 * i as f64;
            let x = 100.0 * kappa + b[9] * z + b[10];
            let fx = d * (c * (bb * x - e * (bb * x - (bb * x).atan())).atan()).sin();
            s.push_str(&format!("{fz},{kappa},{fx}\n"));
        }
    }
    let dir = scratch(&[("rig.csv", &s)]);
    let out = dir.path().join("fx.toml");
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "pac89",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report: serde_json::Value = read_json(&dir.path().join("fx.report.json"));
    assert_eq!(report["channel"], "longitudinal-force");
    assert!(report["sigma_percent"].as_f64().unwrap() < 0.01, "{report}");
    assert!(fs::read_to_string(&out).unwrap().contains("b = ["));
}
