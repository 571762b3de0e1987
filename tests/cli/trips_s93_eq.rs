//! Session 93, `eq`: an unstable car on linear tyres called "sliding" by
//! `study`, the critical speed `equilibria` did not report, arrowheads on
//! the phase portrait, and a Gim fit to unsaturated data.

use super::*;

/// The bundled coarse study (Wang & Liang's sedan: m 1530 kg, a 1.11 m,
/// b 1.67 m) on linear tyres, at `speed` m/s, the map alone.
fn linear_study(speed: f64) -> String {
    let text = fs::read_to_string(root().join("scenarios/sedan_study_coarse.toml"))
        .unwrap()
        .replace("../tyres/gim_sedan_front.toml", "tyre.toml")
        .replace("../tyres/gim_sedan_rear.toml", "tyre.toml")
        .replace("speed = 22.2222", &format!("speed = {speed}"));
    let map_only = text.split("[rbf]").next().unwrap();
    assert!(map_only.contains(&format!("speed = {speed}")), "{map_only}");
    assert_eq!(map_only.matches("\"tyre.toml\"").count(), 2, "{map_only}");
    map_only.to_string()
}

/// Critical speed √(−l/K) of the sedan with per-tyre stiffness `kf`, `kr`
/// (N/rad), K = (m/l)(b/Cf − a/Cr) with Cf, Cr the axles' (Genta 1997);
/// None where it does not oversteer.
fn critical_speed(kf: f64, kr: f64) -> Option<f64> {
    let (m, a, b) = (1530.0, 1.11, 1.67);
    let l = a + b;
    let k = m / l * (b / (2.0 * kf) - a / (2.0 * kr));
    (k < 0.0).then(|| (-l / k).sqrt())
}

/// On linear tyres there is no grip to slide past: the map points that
/// oversteer past their critical speed are unstable — exactly the
/// closed form's points, each with its critical speed — and none is
/// called sliding.
#[test]
fn a_linear_study_calls_the_points_past_the_critical_speed_unstable_not_sliding() {
    let speed = 30.0;
    let dir = scratch(&[("study.toml", &linear_study(speed))]);
    linear_tyre(dir.path());
    let o = run_in(dir.path(), &["study", "study.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    let out = dir.path().join("out");
    let csv = fs::read_to_string(out.join("study.csv")).unwrap();
    let (mut expected, mut unstable) = (0, 0);
    for row in csv.lines().skip(1) {
        let cells: Vec<&str> = row.splitn(5, ',').collect();
        let (kf, kr): (f64, f64) = (cells[2].parse().unwrap(), cells[3].parse().unwrap());
        let past = critical_speed(kf, kr).filter(|&u| speed > u);
        assert!(
            !row.contains("sliding") && !without_temp_names(row).contains("grip"),
            "{row}"
        );
        if let Some(u) = past {
            expected += 1;
            assert!(row.contains(",unstable,"), "{row}");
            let note =
                format!("at {speed:.2} m/s, past its critical speed sqrt(-l/K) = {u:.2} m/s");
            assert!(row.contains(&note), "{row} lacks {note}");
        }
        unstable += usize::from(row.contains(",unstable,"));
    }
    assert!(
        expected >= 5,
        "the map should hold points past u_crit: {expected}"
    );
    assert_eq!(unstable, expected, "{csv}");
    let summary = read_json(&out.join("summary.json"));
    assert_eq!(summary["unstable"], expected, "{summary}");
    assert_eq!(summary["sliding"], 0, "{summary}");
    assert!(!without_temp_names(&said).contains("slide"), "{said}");
    assert!(
        said.contains(&format!(
            "{expected} are unstable: they oversteer (K < 0) past their critical speed"
        )),
        "{said}"
    );
}

/// A speed sweep of an oversteering car on linear tyres (front 60, rear
/// 30 kN/rad per wheel) at zero steer: its straight running goes from
/// stable node to saddle at √(−l/K) = 33.198 m/s, with one equilibrium all
/// along. The crossing is located and reported — the terminal, the CSV and
/// summary.json — within 0.1 % of the closed form.
#[test]
fn an_equilibria_speed_sweep_reports_the_critical_speed_of_the_closed_form() {
    let sweep = format!(
        "name = \"lin_speed\"\n{VEHICLE}[tyres]\nfront = \"front.toml\"\nrear = \"rear.toml\"\n\
         [model]\nkinematics = \"small-angle\"\nload_transfer = false\n\
         [sweep]\nsteer = 0.0\nfriction = 1.0\nspeed = {{ from = 20.0, to = 45.0, step = 5.0 }}\n[pso]\nseed = 1\n"
    );
    let dir = scratch(&[
        ("sweep.toml", &sweep),
        (
            "front.toml",
            "model = \"linear\"\ncornering_stiffness = 60000.0\n",
        ),
        (
            "rear.toml",
            "model = \"linear\"\ncornering_stiffness = 30000.0\n",
        ),
    ]);
    let o = run_in(dir.path(), &["equilibria", "sweep.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    let (m, a, b): (f64, f64, f64) = (1530.0, 1.11, 1.67);
    let l = a + b;
    let k = m / l * (b / 120_000.0 - a / 60_000.0);
    let closed = (-l / k).sqrt();
    assert!((closed - 33.198).abs() < 1e-3, "{closed}");
    let out = dir.path().join("out");
    let summary = read_json(&out.join("summary.json"));
    let found: Vec<&serde_json::Value> = summary["bifurcations"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|b| b["kind"] == "zero-eigenvalue" && b["axis"] == "speed")
        .collect();
    assert_eq!(found.len(), 1, "{summary}");
    let u = found[0]["at"]["speed"].as_f64().unwrap();
    assert!((u - closed).abs() < 1e-3 * closed, "{u} against {closed}");
    assert_eq!(
        found[0]["kinds"],
        serde_json::json!(["stable-node", "saddle"])
    );
    let c = summary["critical_speed_closed_form"].as_f64().unwrap();
    assert!((c - closed).abs() < 1e-9 * closed, "{c}");
    let csv = fs::read_to_string(out.join("bifurcations.csv")).unwrap();
    let row = csv
        .lines()
        .find(|r| r.starts_with("zero-eigenvalue,speed,"))
        .expect(&csv);
    let speed: f64 = row.split(',').nth(4).unwrap().parse().unwrap();
    assert!((speed - closed).abs() < 1e-3 * closed, "{row}");
    assert!(
        said.contains(&format!("critical speed {closed:.4} m/s ({:.2} km/h): an eigenvalue crosses zero, stable-node below, saddle above", 3.6 * closed)),
        "{said}"
    );
}
