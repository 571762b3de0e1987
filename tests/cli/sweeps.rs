//! Equilibrium sweeps and the cornering-stiffness study from their bundled files.

use super::*;

#[test]
fn equilibria_sweep_writes_tables_and_figures() {
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "equilibria",
        "scenarios/equilibria_steer.toml",
        "--out",
        out.path().to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(stdout.contains("agree at 11/11 conditions"), "{stdout}");
    let csv = fs::read_to_string(out.path().join("equilibria.csv")).unwrap();
    assert!(csv.starts_with("steer,friction,speed,beta,yaw_rate,kind,"));
    assert!(csv.lines().count() > 11);
    let bif = fs::read_to_string(out.path().join("bifurcations.csv")).unwrap();
    assert!(
        bif.lines().nth(1).unwrap().starts_with("pitchfork,steer,"),
        "{bif}"
    );
    for png in [
        "branches_steer.png",
        "phase_portrait_0.png",
        "phase_portrait_1.png",
    ] {
        assert!(
            fs::metadata(out.path().join(png)).unwrap().len() > 10_000,
            "{png}"
        );
    }
    let s: serde_json::Value = read_json(&out.path().join("summary.json"));
    assert_eq!(s["seed"], 1);
    assert_eq!(s["agreeing"], 11);
}

#[test]
fn sweep_with_an_unknown_unit_is_refused() {
    let text = fs::read_to_string(root().join("scenarios/equilibria_steer.toml")).unwrap();
    let text = text
        .replace("unit = \"km/h\"", "unit = \"mph\"")
        .replace("../tyres/", &format!("{}/tyres/", root().display()));
    let dir = scratch(&[("sweep.toml", &text)]);
    let o = run(&[
        "equilibria",
        dir.path().join("sweep.toml").to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("sweep.toml:") && e.contains("mph") && e.contains("sweep.speed"),
        "{e}"
    );
    assert!(!dir.path().join("out").exists());
}

#[test]
fn wang_liang_study_writes_map_rbf_and_inverse() {
    let out = tempfile::tempdir().unwrap();
    let o = run(&[
        "study",
        "scenarios/sedan_study.toml",
        "--out",
        out.path().to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.contains("676 map combinations + 51 RBF pairs"),
        "{stdout}"
    );
    let csv = fs::read_to_string(out.path().join("study.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 676 + 51);
    let rbf: serde_json::Value = read_json(&out.path().join("rbf.json"));
    assert_eq!(rbf["training_pairs"], 46);
    assert_eq!(rbf["validation"].as_array().unwrap().len(), 5);
    let inv: serde_json::Value = read_json(&out.path().join("inverse.json"));
    for t in inv["targets"].as_array().unwrap() {
        let target = t["target"].as_f64().unwrap();
        let er = t["best"]["resimulated"].as_f64().unwrap();
        assert!((er - target).abs() <= 1e-5 * target, "{er} vs {target}");
    }
    assert!(fs::metadata(out.path().join("maps.png")).unwrap().len() > 10_000);
}

#[test]
fn a_sweep_refuses_an_effect_the_equilibrium_analysis_does_not_model() {
    // Roll steer moves every equilibrium, and the equilibrium residual does
    // not model it: a sweep with it is refused at its key, not solved wrong.
    let text = fs::read_to_string(root().join("scenarios/equilibria_steer.toml")).unwrap();
    let text = text
        .replace(
            "\n[model]\n",
            "\n[model]\neffects = { roll_steer = [-0.1, 0.0] }\n",
        )
        .replace("../tyres/", &format!("{}/tyres/", root().display()));
    let dir = scratch(&[("sweep.toml", &text)]);
    let o = run(&[
        "equilibria",
        dir.path().join("sweep.toml").to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("sweep.toml:") && e.contains("model.effects.roll_steer"),
        "{e}"
    );
    assert!(!dir.path().join("out").exists());
}
