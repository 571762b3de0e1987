//! Session 94, `eq`: the pitchfork of straight running on the simplified
//! Magic Formula, branches continued through a fold, and words of
//! `study`, `equilibria` and `design` on inputs outside their range.

use super::*;

/// The oversteering sedan of the fresh-eyes round (m 1530 kg, a 1.11 m,
/// b 1.67 m) on the simplified Magic Formula Fy = D·μ·Fz·sin(C·atan(B·α)),
/// front B = 10, rear B = 6, C = 1.3, D = 1, small-angle, no load
/// transfer, μ = 0.8, swept in speed at δ = 0.
fn ms_os(speeds: &str) -> tempfile::TempDir {
    let sweep = format!(
        "name = \"ms_os\"\n{VEHICLE}[tyres]\nfront = \"front.toml\"\nrear = \"rear.toml\"\n\
         [model]\nkinematics = \"small-angle\"\nload_transfer = false\n\
         [sweep]\nsteer = 0.0\nfriction = 0.8\nspeed = {speeds}\n[pso]\nseed = 1\n"
    );
    scratch(&[
        ("sweep.toml", &sweep),
        (
            "front.toml",
            "model = \"magic-simple\"\nb = 10.0\nc = 1.3\nd = 1.0\n",
        ),
        (
            "rear.toml",
            "model = \"magic-simple\"\nb = 6.0\nc = 1.3\nd = 1.0\n",
        ),
    ])
}

/// Straight running of that car loses stability at the critical speed
/// √(−l/K), K = (m/l)(b/Cf − a/Cr) with each axle's stiffness at zero
/// slip B·C·D·μ times its static load (Genta 1997): there the two saddles
/// beside (0, 0) merge with it and five equilibria become three. The
/// symmetric (pitchfork) bifurcation at δ = 0 is found, at (0, 0), and its
/// speed is the closed form's within 0.1 %, in the CSV, summary.json and
/// the terminal's critical-speed line.
#[test]
fn the_pitchfork_of_straight_running_on_the_magic_formula_is_at_the_closed_form_speed() {
    let dir = ms_os("{ from = 10.0, to = 40.0, step = 1.0 }");
    let o = run_in(dir.path(), &["equilibria", "sweep.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    let (m, a, b, mu, g): (f64, f64, f64, f64, f64) = (1530.0, 1.11, 1.67, 0.8, 9.80665);
    let l = a + b;
    let (ff, fr) = (m * g * b / l, m * g * a / l);
    let (cf, cr) = (10.0 * 1.3 * mu * ff, 6.0 * 1.3 * mu * fr);
    let k = m / l * (b / cf - a / cr);
    let closed = (-l / k).sqrt();
    assert!((closed - 20.6227).abs() < 1e-3, "{closed}");
    let out = dir.path().join("out");
    let csv = fs::read_to_string(out.join("bifurcations.csv")).unwrap();
    let rows: Vec<&str> = csv
        .lines()
        .filter(|r| r.starts_with("pitchfork,speed,"))
        .collect();
    assert_eq!(rows.len(), 1, "{csv}");
    let cells: Vec<&str> = rows[0].split(',').collect();
    let num = |i: usize| cells[i].parse::<f64>().unwrap();
    assert!(
        (num(4) - closed).abs() < 1e-3 * closed,
        "{} against {closed}",
        rows[0]
    );
    assert!(num(5).abs() < 1e-9 && num(6).abs() < 1e-9, "{}", rows[0]);
    assert_eq!(cells[11], "true", "{}", rows[0]);
    let summary = read_json(&out.join("summary.json"));
    let found: Vec<&serde_json::Value> = summary["bifurcations"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|b| b["kind"] == "pitchfork")
        .collect();
    assert_eq!(found.len(), 1, "{summary}");
    // Below the critical speed: a stable node and the two saddles beside it.
    let eq = fs::read_to_string(out.join("equilibria.csv")).unwrap();
    let at = |u: &str| {
        eq.lines()
            .filter(|r| r.split(',').nth(2) == Some(u))
            .count()
    };
    assert_eq!((at("20"), at("21")), (5, 3), "{eq}");
    assert!(
        said.contains(&format!(
            "critical speed {closed:.4} m/s ({:.2} km/h): straight running changes stability",
            3.6 * closed
        )),
        "{said}"
    );
    assert!(
        said.contains(&format!("closed form sqrt(-l/K) from the tyres' cornering stiffness at zero slip {closed:.4} m/s")),
        "{said}"
    );
}

/// Just below that critical speed the two saddles beside straight running
/// lie within one scan cell of (0, 0), where symmetry puts a root on a scan
/// sample: the exact solver finds them too (it missed them, and the swarm
/// alone reported them), so both solvers agree on all five.
#[test]
fn the_exact_solver_finds_the_saddles_beside_straight_running_near_the_pitchfork() {
    let dir = ms_os("{ values = [20.5, 20.6, 20.62] }");
    let o = run_in(dir.path(), &["equilibria", "sweep.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let eq = fs::read_to_string(dir.path().join("out/equilibria.csv")).unwrap();
    for u in ["20.5", "20.6", "20.62"] {
        let rows: Vec<&str> = eq
            .lines()
            .filter(|r| r.split(',').nth(2) == Some(u))
            .collect();
        assert_eq!(rows.len(), 5, "{eq}");
        assert!(rows.iter().all(|r| r.contains(",both,")), "{eq}");
    }
    let summary = read_json(&dir.path().join("out/summary.json"));
    assert_eq!(summary["agreeing"], 3, "{summary}");
}

/// Li, Jia & Zhao's steer sweep (the sedan on the simplified Magic Formula,
/// B = 10, exact kinematics, μ = 0.8, 70 km/h): between δ = 0.04 and
/// 0.06 rad the saddle and the unstable focus beside it meet at a fold,
/// while the straight-running node goes on to a stable focus. The drawn
/// branches (`branches_steer.csv`, the segments of the PNG) follow that:
/// the fold's two segments come from one saddle and one non-saddle and end
/// at the fold's state in bifurcations.csv, neither is linked past it, no
/// link joins a saddle to a node or focus (no eigenvalue crosses zero in
/// this sweep), and the stable branch from (0, 0) runs unbroken to the
/// last steer. (The nearest-neighbour matching linked the saddle to the
/// stable focus past the fold and joined the stable node to the fold.)
#[test]
fn the_branch_diagram_joins_the_fold_to_the_two_branches_that_meet_there() {
    let sweep = format!(
        "name = \"eq_exact\"\n{VEHICLE}[tyres]\nfront = \"front.toml\"\n\
         [model]\nkinematics = \"exact\"\nload_transfer = false\n\
         [sweep]\nsteer = {{ from = 0.0, to = 0.2, step = 0.02 }}\nfriction = 0.8\n\
         speed = {{ values = [70.0], unit = \"km/h\" }}\n[pso]\nseed = 1\n"
    );
    let dir = scratch(&[
        ("sweep.toml", &sweep),
        (
            "front.toml",
            "model = \"magic-simple\"\nb = 10.0\nc = 1.3\nd = 1.0\n",
        ),
    ]);
    let o = run_in(dir.path(), &["equilibria", "sweep.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = dir.path().join("out");
    let bif = fs::read_to_string(out.join("bifurcations.csv")).unwrap();
    let fold: Vec<&str> = bif
        .lines()
        .filter(|r| r.starts_with("fold,steer,"))
        .collect();
    assert_eq!(fold.len(), 1, "{bif}");
    let f: Vec<f64> = fold[0]
        .split(',')
        .skip(4)
        .take(3)
        .map(|v| v.parse().unwrap())
        .collect();
    let fold_steer: f64 = fold[0].split(',').nth(2).unwrap().parse().unwrap();
    assert!(fold_steer > 0.04 && fold_steer < 0.06, "{bif}");
    let csv = fs::read_to_string(out.join("branches_steer.csv")).expect("branches_steer.csv");
    let rows: Vec<Vec<&str>> = csv
        .lines()
        .skip(1)
        .map(|r| r.split(',').collect())
        .collect();
    let num = |r: &Vec<&str>, i: usize| r[i].parse::<f64>().unwrap();
    let saddle = |k: &str| k == "saddle";
    let ends: Vec<&Vec<&str>> = rows.iter().filter(|r| r[7] == "fold").collect();
    assert_eq!(ends.len(), 2, "{csv}");
    assert_ne!(saddle(ends[0][3]), saddle(ends[1][3]), "{csv}");
    for e in &ends {
        assert!((num(e, 4) - fold_steer).abs() < 1e-12, "{csv}");
        assert!(
            (num(e, 5) - f[1]).abs() < 1e-12 && (num(e, 6) - f[2]).abs() < 1e-12,
            "{csv}"
        );
        let past = rows
            .iter()
            .any(|r| r[7] != "fold" && r[0] == e[0] && r[1] == e[1] && num(r, 4) > fold_steer);
        assert!(!past, "{csv}: a fold end is linked past the fold");
    }
    let links: Vec<&Vec<&str>> = rows.iter().filter(|r| r[7] != "fold").collect();
    for l in &links {
        assert_eq!(saddle(l[3]), saddle(l[7]), "{csv}: {l:?}");
    }
    // Follow the branch from straight running to the last steer.
    let (mut steer, mut beta) = ("0".to_string(), "0".to_string());
    let mut steps = 0;
    while let Some(l) = links.iter().find(|l| l[0] == steer && l[1] == beta) {
        assert!(!saddle(l[7]), "{csv}");
        (steer, beta) = (l[4].to_string(), l[5].to_string());
        steps += 1;
    }
    assert_eq!((steps, steer.as_str()), (10, "0.2"), "{csv}");
}

/// The bundled coarse study with its Er target set to `target`, the tyres
/// named by absolute path.
pub(crate) fn study_with(target: &str, reference: &str) -> tempfile::TempDir {
    let tyres = root().join("tyres");
    let text = fs::read_to_string(root().join("scenarios/sedan_study_coarse.toml"))
        .unwrap()
        .replace("../tyres", &tyres.display().to_string())
        .replace("value = 0.13,", &format!("value = {target},"))
        .replace("front = 500.0, rear", &format!("front = {reference}, rear"));
    assert!(text.contains(&format!("value = {target},")), "{text}");
    assert!(
        text.contains(&format!("front = {reference}, rear")),
        "{text}"
    );
    scratch(&[("study.toml", &text)])
}

/// Er = 0.5 s lies outside the Er of the network's training pairs: its
/// answer is said to be an extrapolation, with the trained range, and the
/// re-simulation that has no Er is said in words, never "NaN" (it read
/// "Er NaN re-simulated (NaN %)"). A negative Er target and a negative
/// reference stiffness are refused at their keys, with line and column.
#[test]
fn study_says_when_the_rbf_extrapolates_and_refuses_negative_targets_and_stiffness() {
    let dir = study_with("0.5", "500.0");
    let o = run_in(dir.path(), &["study", "study.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    let line = said
        .lines()
        .find(|l| l.contains("RBF answer"))
        .expect(&said);
    assert!(!without_temp_names(line).contains("NaN"), "{line}");
    assert!(
        line.contains("an extrapolation: Er 0.5 lies outside the Er "),
        "{line}"
    );
    let inv = fs::read_to_string(dir.path().join("out/inverse.json")).unwrap();
    assert!(!without_temp_names(&inv).contains("NaN"), "{inv}");
    let dir = study_with("-0.5", "500.0");
    let o = run_in(dir.path(), &["study", "study.toml", "--out", "out"]);
    assert!(!o.status.success());
    assert!(
        stderr(&o)
            .contains("study.toml:44:37: `inverse.targets[0].value` = -0.5: must be positive"),
        "{}",
        stderr(&o)
    );
    let dir = study_with("0.13", "-9.4");
    let o = run_in(dir.path(), &["study", "study.toml", "--out", "out"]);
    assert!(!o.status.success());
    let err = stderr(&o);
    assert!(
        err.contains("`inverse.reference.front` = -9.4: must be positive"),
        "{err}"
    );
    assert!(!err.contains("give it in N/deg as -"), "{err}");
}
