//! What a user tripped on in round 32 with `study`, `equilibria` and
//! `identify`, run as the user ran them, from files:
//! - `study` with a yaw-rate-gain target drew its traced curve nowhere
//!   (maps.png had six metrics; the target's was not among them);
//! - `equilibria` on an oversteering car said "0 equilibria in the box"
//!   with no reason, and its branch figure did not mark the critical
//!   speed summary.json held;
//! - `identify --model linear` on data within ±2.005° said "fitted to
//!   |alpha| <= 2 deg only (… 0 points … left out)" binned and "not needed"
//!   unbinned;
//! - `identify --model mf61` with an MF 6.2 template wrote `FITTYP = 61`
//!   without a word.

use super::trips_identify::stdout;
use super::*;
use crate::trips_s91_diag::png_pixels;
use handling::report::plot::palette;

/// The linear tyre of the round's inputs (57 296 N/rad per wheel, 3 cm
/// trail).
const LINEAR: &str = "model = \"linear\"\ncornering_stiffness = 57296.0\npneumatic_trail = 0.03\n";

/// The round's `study_lin.toml`: a 4 × 4 map and a yaw-rate-gain target.
fn study() -> String {
    let sedan = linear_sedan("lin.toml");
    format!(
        "name = \"study_lin\"
{sedan}[manoeuvre]
kind = \"step-steer\"
speed = 25.0
steer = 0.01
start = 1.0
rise_time = 0.1
end = 8.0
[stiffness]
unit = \"N/rad\"
front = {{ from = 40000.0, to = 100000.0, count = 4 }}
rear = {{ from = 40000.0, to = 100000.0, count = 4 }}
[inverse]
targets = [{{ metric = \"yaw_rate_gain\", value = 6.0, tolerance = 0.2 }}]
reference = {{ front = 57296.0, rear = 57296.0 }}
"
    )
}

/// Before: maps.png held Er, E_r, E_ay, the yaw-rate response time, the
/// overshoot and TB (3 rows of 2); the yaw_rate_gain = 6 curve ("a curve of
/// 6 map points") was drawn on none. Now every metric of study.csv has a
/// map (5 rows of 2, in its columns' order: yaw_rate_gain is the 8th, row
/// 4, right) and the target's curve, in the first target's colour, is
/// drawn on its metric's map and nowhere else.
#[test]
fn a_studys_target_curve_is_drawn_on_the_map_of_its_own_metric() {
    let dir = scratch(&[("study_lin.toml", &study()), ("lin.toml", LINEAR)]);
    let o = run_in(dir.path(), &["study", "study_lin.toml", "--out", "o"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("yaw_rate_gain = 6: a curve of 6 map points"),
        "{}",
        stdout(&o)
    );
    let head = fs::read_to_string(dir.path().join("o/study.csv")).unwrap();
    let metrics = head
        .lines()
        .next()
        .unwrap()
        .split(',')
        .skip(4)
        .take(10)
        .count();
    assert_eq!(metrics, 10, "{head}");
    let (rgb, w, h) = png_pixels(&dir.path().join("o/maps.png"));
    let c = palette(1);
    let curve: Vec<(usize, usize)> = rgb
        .chunks_exact(3)
        .enumerate()
        .filter(|(_, p)| *p == [c.0, c.1, c.2])
        .map(|(i, _)| (i % w, i / w))
        .collect();
    println!("{w}×{h} px, {} pixels of the curve's colour", curve.len());
    assert!(!curve.is_empty(), "the target's curve is drawn nowhere");
    // Two columns of panels, five rows: yaw_rate_gain's is row 3 (from 0),
    // column 1.
    let (pw, ph) = (w / 2, h / 5);
    let outside: Vec<&(usize, usize)> = curve
        .iter()
        .filter(|(x, y)| *x < pw || y / ph != 3)
        .collect();
    assert!(
        outside.is_empty(),
        "{} of {} pixels of the curve lie off the yaw-rate gain map (first {:?})",
        outside.len(),
        curve.len(),
        outside.first()
    );
}

/// The round's `eq_over.toml`: the sedan with a and b swapped
/// (oversteering), linear tyres, speeds 20 to 44 m/s.
fn eq_over() -> String {
    let sedan = rearward_sedan("lin.toml");
    format!(
        "name = \"eq_over\"
{sedan}[sweep]
steer = {{ values = [0.5, 1.0, 2.0], unit = \"deg\" }}
friction = 1.0
speed = {{ from = 20.0, to = 44.0, step = 4.0 }}
[pso]
seed = 1
"
    )
}

/// Before: "3 conditions with 0 equilibria in the box" and nothing else,
/// though summary.json held critical_speed_closed_form = 32.15 m/s; the
/// branch figure along speed jumped from stable to saddle between 100.8
/// and 129.6 km/h unmarked. Now the terminal gives the critical speed
/// √(−l/K) (checked here against the bicycle model's K = m/l·(b/Cf −
/// a/Cr)), says the empty conditions lie at 32 m/s beside it where the
/// linear trim's yaw rate u·δ/(l + K u²) leaves the box, and the branch
/// figure draws the critical speed as a line in its own colour.
#[test]
fn an_oversteering_cars_empty_box_is_explained_by_its_critical_speed() {
    let dir = scratch(&[("eq_over.toml", &eq_over()), ("lin.toml", LINEAR)]);
    let o = run_in(dir.path(), &["equilibria", "eq_over.toml", "--out", "o"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stdout(&o);
    let (m, a, b, c) = (1530.0_f64, 1.67_f64, 1.11_f64, 2.0 * 57296.0_f64);
    let l = a + b;
    let k = m / l * (b / c - a / c);
    let u_crit = (-l / k).sqrt();
    let line = format!(
        "  critical speed {u_crit:.4} m/s ({:.2} km/h), closed form sqrt(-l/K)",
        3.6 * u_crit
    );
    assert!(said.contains(&line), "no «{line}» in\n{said}");
    assert!(
        said.contains("3 conditions with 0 equilibria in the box"),
        "{said}"
    );
    // The linear trim at 32 m/s and 0.5° (the nearest the box) is far out:
    // r = u·δ/(l + K u²).
    let r = 32.0 * 0.5_f64.to_radians() / (l + k * 32.0 * 32.0);
    let why = format!(
        "the 3 conditions with no equilibrium in the box (speed 32 m/s, within {:.1} % of the critical speed {u_crit:.4} m/s)",
        100.0 * (32.0 - u_crit).abs() / u_crit
    );
    assert!(said.contains(&why), "no «{why}» in\n{said}");
    assert!(said.contains(&format!("r {r:.3} rad/s)")), "{r}: {said}");
    let summary = read_json(&dir.path().join("o/summary.json"));
    let closed = summary["critical_speed_closed_form"].as_f64().unwrap();
    assert!((closed / u_crit - 1.0).abs() < 1e-12, "{closed} {u_crit}");
    // The critical speed's line on the branch figure along speed.
    let (rgb, w, h) = png_pixels(&dir.path().join("o/branches_speed_steer_0.5deg.png"));
    let p = palette(4);
    let n = rgb
        .chunks_exact(3)
        .filter(|q| *q == [p.0, p.1, p.2])
        .count();
    println!("{w}×{h} px: {n} pixels of the critical speed's colour");
    assert!(n > 100, "{n} pixels: the critical speed is not drawn");
}

/// The round's rig/lin.csv: a linear tyre (59.9 kN/rad, 3 cm trail) at
/// 3 kN swept over ±0.035 rad (±2.005°) in 141 rows, with a small
/// deterministic scatter.
fn linear_rig() -> String {
    let mut s = String::from("t,fz,alpha,fy,mz\n");
    for i in 0..141 {
        let alpha = -0.035 + 0.0005 * f64::from(i);
        let wobble = (f64::from(i) * 1.7).sin();
        let fy = 59_900.0 * alpha + 3.0 * wobble;
        let fz = 3000.0 + 4.0 * (f64::from(i) * 0.9).cos();
        s += &format!(
            "{},{fz:.4},{alpha:.4},{fy:.4},{:.6}\n",
            0.01 * f64::from(i),
            0.03 * fy
        );
    }
    s
}

/// Before, on the same rows: binned (the default) "linear window: fitted
/// to |alpha| <= 2 deg only (17 points; 0 points with larger |alpha| left
/// out)", unbinned (`--bin-deg 0`) "linear window: not needed: … all 141
/// points are fitted". Nothing is left out in either: both now say the
/// window is not needed, with the points each fits (the thinned count,
/// as the line above it and the report give it).
#[test]
fn a_linear_fit_that_leaves_nothing_out_says_its_window_is_not_needed_binned_or_not() {
    let dir = scratch(&[("rig.csv", &linear_rig())]);
    for (args, name) in [(&[][..], "binned"), (&["--bin-deg", "0"][..], "rows")] {
        let out = dir.path().join(format!("{name}.toml"));
        let o = super::trips_identify::identify_with(dir.path(), "linear", args, &out);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let said = stdout(&o);
        let report = read_json(&dir.path().join(format!("{name}.report.json")));
        let w = &report["linear_window"];
        assert_eq!(w["points_left_out"], 0, "{name}: {w}");
        let fitted = w["points_fitted"].as_u64().unwrap();
        let thinned = format!("thinned to {fitted} points");
        assert!(said.contains(&thinned), "{name}: no «{thinned}» in\n{said}");
        let window = said
            .lines()
            .find(|l| l.contains("linear window:"))
            .unwrap_or_else(|| panic!("{name}: no window line in\n{said}"));
        assert!(
            window.starts_with("  linear window: not needed: "),
            "{name}: {window}"
        );
        assert!(
            window.ends_with(&format!("all {fitted} points are fitted")),
            "{name}: {window}"
        );
        assert!(!window.contains("left out"), "{name}: {window}");
        let file = fs::read_to_string(&out).unwrap();
        assert!(
            file.contains(&format!("# {}", window.trim_start())),
            "{name}: {file}"
        );
    }
}

/// Before: `identify --model mf61 --template car205_60R19.tir` (an MF 6.2
/// file, FITTYP = 62, with 6.2's vertical-stiffness terms Q_CAM1 = 85.19
/// …) wrote FITTYP = 61 and said nothing of the change. Now the terminal
/// and the file's header say the template's version, the one written, that
/// `--model mf62` keeps it, and the 6.2 terms a 6.1 file leaves unread;
/// `--model mf62` says nothing of a version.
#[test]
fn an_mf61_fit_of_an_mf62_template_says_the_version_changes_and_what_it_drops() {
    let test = "an_mf61_fit_of_an_mf62_template_says_the_version_changes_and_what_it_drops";
    let Some(template) = shared_data(test, "tir_public/car205_60R19.tir") else {
        return;
    };
    let t = template.display().to_string();
    let dir = scratch(&[("rig.csv", &super::trips_identify::rig(1.0))]);
    let out = dir.path().join("m.tir");
    let args = ["--template", t.as_str(), "--start", "data"];
    let o = super::trips_identify::identify_with(dir.path(), "mf61", &args, &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = stdout(&o);
    let file = fs::read_to_string(&out).unwrap();
    assert!(file.contains("FITTYP                   = 61"), "{file}");
    let line = "version: the template is MF 6.2 (FITTYP = 62), the written file MF 6.1 (FITTYP = 61) as --model asks (--model mf62 keeps the template's version)";
    assert!(said.contains(&format!("  {line}")), "{said}");
    assert!(file.contains(&format!("$ {line}")), "{file}");
    let dropped = "6.2's vertical-stiffness terms the template sets (Q_CAM1 = 85.19, Q_CAM2 = 257.4, Q_CAM3 = 0.5119, Q_FYS1 = -20496.4, Q_FYS2 = -60000, Q_FYS3 = 88211.7, Q_FCY2 = -0.4751) stay in the file unread";
    assert!(said.contains(dropped), "{said}");
    let out = dir.path().join("m2.tir");
    let o = super::trips_identify::identify_with(dir.path(), "mf62", &args, &out);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stdout(&o).contains("version: "), "{}", stdout(&o));
    let file = fs::read_to_string(&out).unwrap();
    assert!(file.contains("FITTYP                   = 62"), "{file}");
}
