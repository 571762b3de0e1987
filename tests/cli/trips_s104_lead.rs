//! Session 104, the lead's own findings: a down-force on one axle of
//! linear tyres while the other axle's tyres read their load.

use super::scenarios::simulate_to;
use super::{scratch, VEHICLE};

#[test]
fn aero_load_on_a_linear_axle_is_warned_of_even_where_the_other_axle_reads_its_load() {
    let lin = "model = \"linear\"\ncornering_stiffness = 57296.0\npneumatic_trail = 0.03\n";
    let gim =
        "model = \"gim\"\ncornering_stiffness = 28647.9\ncontact_length = 0.16\nfriction = 1.0\n";
    let manoeuvre = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 25.0\nsteer = 0.01\nstart = 1.0\nrise_time = 0.1\nend = 12.0\n";
    let sc = |tyres: &str, aero: &str| {
        format!("name = \"aero\"\n{VEHICLE}\n[tyres]\n{tyres}\n[model]\nkinematics = \"small-angle\"\nload_transfer = false\n[model.effects]\naero_load = {aero}\n{manoeuvre}")
    };
    let dir = scratch(&[
        ("lin.toml", lin),
        ("gim.toml", gim),
        (
            "gl.toml",
            &sc("front = \"gim.toml\"\nrear = \"lin.toml\"\n", "[0.5, 0.7]"),
        ),
        (
            "lg.toml",
            &sc("front = \"lin.toml\"\nrear = \"gim.toml\"\n", "[0.5, 0.7]"),
        ),
        (
            "gl_front.toml",
            &sc("front = \"gim.toml\"\nrear = \"lin.toml\"\n", "[0.5, 0.0]"),
        ),
    ]);
    // The rear's 0.7·25² = 437.5 N falls on linear tyres: idle, while the
    // front's 312.5 N loads Gim tyres, whose friction limit reads it.
    let said = simulate_to(&dir.path().join("gl.toml"), &dir.path().join("o_gl"));
    assert!(
        said.contains("warning: `model.effects.aero_load` = [0.5, 0.7] N per (m/s)²: its rear part acts on nothing: it adds 437.5 N on the rear axle at 25 m/s (k·u²), and the rear tyres are linear"),
        "{said}"
    );
    let said = simulate_to(&dir.path().join("lg.toml"), &dir.path().join("o_lg"));
    assert!(
        said.contains("warning: `model.effects.aero_load` = [0.5, 0.7] N per (m/s)²: its front part acts on nothing: it adds 312.5 N on the front axle at 25 m/s (k·u²), and the front tyres are linear"),
        "{said}"
    );
    // No down-force on the linear axle: nothing idle, nothing said.
    let said = simulate_to(&dir.path().join("gl_front.toml"), &dir.path().join("o_glf"));
    assert!(!said.contains("acts on nothing"), "{said}");
}

#[test]
fn a_reader_that_stops_early_leaves_no_lock_behind() {
    // `handling simulate … | head -1`: the job runs on after stdout's
    // reader has gone and releases its folder (it exited at the print,
    // and the next run took the lock over as a killed run's).
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("x");
    let mut child = super::bin()
        .args([
            "simulate",
            "scenarios/step_gbt6323_pac89.toml",
            "--out",
            out.to_str().unwrap(),
        ])
        .current_dir(super::root())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let o = child.wait_with_output().unwrap();
    assert!(o.status.success(), "{}", super::stderr(&o));
    assert!(out.join("history.csv").exists());
    assert!(!out.join(".handling.lock").exists());
    let again = super::run(&[
        "simulate",
        "scenarios/step_gbt6323_pac89.toml",
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = super::stderr(&again);
    assert!(again.status.success(), "{e}");
    assert!(!e.contains("no longer running"), "{e}");
}

#[test]
fn a_campaign_whose_candidates_are_all_screened_out_prints_no_empty_table() {
    let dir = tempfile::tempdir().unwrap();
    let none = super::synth_campaign(dir.path(), "none", &[]);
    let campaign = dir.path().join("nulls.toml");
    std::fs::write(
        &campaign,
        format!(
            "name = \"nulls\"\n[vehicle]\nmass = 1530.0\nyaw_inertia = 2315.0\na = 1.11\nb = 1.67\ntrack_front = 1.55\ntrack_rear = 1.55\ncg_height = 0.55\n[tyres]\nrig = \"{}\"\nmodel = \"pac89\"\n[runs]\ndir = \"{}\"\n[diagnose]\nseed = 1\neffects = [\"steer_path\", \"sensor_bias\"]\nparticles = 6\niterations = 4\n",
            none.join("tyre_rig.csv").display(),
            none.join("runs").display()
        ),
    )
    .unwrap();
    let out = dir.path().join("out");
    let (said, d) = super::diagnose_to(&campaign, &out);
    assert!(said.contains("verdict: no significant gap"), "{said}");
    assert_eq!(d["ranking"].as_array().map(Vec::len), Some(0), "{d}");
    // In place of a header without rows: one line, then the screened ones.
    assert!(
        said.contains("noise level 0.")
            && said.contains(
                "\n  none cross-validated: every candidate was screened out (below)\nscreened, not cross-validated"
            ),
        "{said}"
    );
    assert!(!said.contains("J after    held out"), "{said}");
    let page = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(
        page.contains("None cross-validated: every candidate was screened out (below)."),
        "{page}"
    );
    assert!(!page.contains("ranking-table"), "{page}");
}

#[test]
fn a_staged_fit_s_iteration_cap_is_refused_past_its_most_and_when_not_in_digits() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("q.tir");
    let rig = super::root().join("docs/examples/mf_grid.csv");
    let identify = |cap: &str| {
        super::run(&[
            "identify",
            rig.to_str().unwrap(),
            "--model",
            "mf61",
            "--max-iterations",
            cap,
            "--out",
            out.to_str().unwrap(),
        ])
    };
    // A billion ran silently for as long as a stage did not converge.
    let o = identify("1000000000");
    let e = super::stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("max_iterations") && e.contains("10000") && e.contains("no cap"),
        "{e}"
    );
    assert!(!out.exists());
    // `1e9` read "invalid digit found in string".
    let o = identify("1e9");
    let e = super::stderr(&o);
    assert!(!o.status.success(), "{e}");
    assert!(
        e.contains("expected a whole number written in digits (such as 300), not `1e9`"),
        "{e}"
    );
}
