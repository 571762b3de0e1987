//! Units written in CSV headers, as real loggers and rigs write them
//! (`alpha [deg]`, `speed [km/h]`, `yaw_rate [deg/s]`): each reader
//! recognises the column and its unit, accepts the SI unit it reads the
//! column in, and refuses another with the conversion, or with the one key
//! that reader takes degrees by (where "Rename it" would have kept the
//! degrees and read them as radians). Also: a run's unit refusals name
//! only the reading command's key, a tyre file's written pressure range
//! past any tyre's is refused at its key, and `--pressure` is said back
//! in Pa as typed.

use super::trips_s90_met::tester_step;
use super::trips_s95_real::campaign;
use super::{linear_tyre, replay_of, run, shared_data, stderr, without_temp_names};
use std::fs;
use std::path::Path;

/// A run log of `rows` samples at 100 Hz and 20 m/s, steer `steer(t)` rad
/// and the yaw rate a neutral 2.78 m car gives, written under `header`
/// with the steer scaled by `steer_scale` and the yaw rate by `r_scale`.
fn run_log(header: &str, steer_scale: f64, r_scale: f64) -> String {
    let mut s = format!("{header}\n");
    for i in 0..400 {
        let t = f64::from(i) * 0.01;
        let steer = if t < 1.0 { 0.0 } else { 0.02 };
        let r = 20.0 * steer / 2.78;
        s += &format!("{t:.2},20,{},{}\n", steer * steer_scale, r * r_scale);
    }
    s
}

/// `history` with its header's names replaced by `names` (old, new).
fn renamed(history: &Path, names: &[(&str, &str)], to: &Path) {
    let text = fs::read_to_string(history).unwrap();
    let (head, rows) = text.split_once('\n').unwrap();
    let head: Vec<String> = head
        .split(',')
        .map(|h| {
            let h = h.trim();
            names
                .iter()
                .find(|(old, _)| *old == h)
                .map_or(h.to_string(), |(_, new)| new.to_string())
        })
        .collect();
    fs::write(to, format!("{}\n{rows}", head.join(","))).unwrap();
}

/// The step metrics compared between readings of one run.
const COMPARED: [&str; 5] = [
    "steer_step",
    "yaw_rate_gain",
    "yaw_rate_response_time",
    "yaw_rate_overshoot",
    "ay_response_time",
];

/// `metrics --json` of `csv` with `args`: the [`COMPARED`] metrics.
fn metrics_of(csv: &Path, args: &[&str]) -> Result<Vec<f64>, String> {
    let mut all = vec!["metrics", csv.to_str().unwrap(), "--json"];
    all.extend(args);
    let o = run(&all);
    if !o.status.success() {
        return Err(stderr(&o));
    }
    let j: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    Ok(COMPARED
        .iter()
        .map(|k| j[k].as_f64().unwrap_or_else(|| panic!("{k}: {j}")))
        .collect())
}

#[test]
fn a_run_header_in_si_units_is_read_and_one_in_degrees_is_told_to_declare_them_to_metrics() {
    let dir = tempfile::tempdir().unwrap();
    let history = tester_step(dir.path(), 0.1, "");
    let bare = metrics_of(&history, &[]).unwrap();
    // The SI units stated: read as the bare names, the same metrics.
    let si = dir.path().join("si.csv");
    let stated = [
        ("t", "t [s]"),
        ("speed", "speed (m/s)"),
        ("steer", "steer_rad"),
        ("yaw_rate", "yaw_rate [rad/s]"),
        ("ay", "ay [m/s²]"),
    ];
    renamed(&history, &stated, &si);
    assert_eq!(metrics_of(&si, &[]).unwrap(), bare);
    // The steer in degrees under `steer [deg]`: the header is refused with
    // `metrics`' own key; the column renamed and declared reads the same.
    let text = fs::read_to_string(&history).unwrap();
    let head = text.lines().next().unwrap();
    let k = head.split(',').position(|h| h == "steer").unwrap();
    let degrees = |header: &str| {
        let mut s = String::new();
        for (n, line) in text.lines().enumerate() {
            let mut cells: Vec<String> = line.split(',').map(str::to_string).collect();
            if n == 0 {
                cells[k] = header.to_string();
            } else {
                let v: f64 = cells[k].parse().unwrap();
                cells[k] = format!("{}", v.to_degrees());
            }
            s += &(cells.join(",") + "\n");
        }
        s
    };
    let deg = dir.path().join("deg.csv");
    fs::write(&deg, degrees("steer [deg]")).unwrap();
    let said = metrics_of(&deg, &[]).unwrap_err();
    assert!(said.contains("deg.csv:1:"), "{said}");
    assert!(
        said.contains("column `steer [deg]` is `steer` in deg"),
        "{said}"
    );
    assert!(said.contains("`--degrees steer` to `metrics`"), "{said}");
    assert!(said.contains("× π/180 = 0.0174533"), "{said}");
    assert!(!said.contains("Rename it"), "{said}");
    assert!(
        !said.contains("[runs]") && !said.contains("[manoeuvre]"),
        "{said}"
    );
    fs::write(&deg, degrees("steer")).unwrap();
    let declared = metrics_of(&deg, &["--degrees", "steer"]).unwrap();
    for (k, (a, b)) in COMPARED.iter().zip(declared.iter().zip(&bare)) {
        assert!((a / b - 1.0).abs() < 1e-6, "{k}: {a} against {b}");
    }
}

#[test]
fn a_rig_header_with_its_units_is_told_each_conversion_by_identify() {
    let dir = tempfile::tempdir().unwrap();
    let rig = dir.path().join("units_deg.csv");
    let mut s = String::from(
        "t [s],fz [N],alpha [deg],camber [deg],fy [N],mz [Nm],pressure [kPa],speed [km/h],fx [kN]\n",
    );
    for i in 0..40 {
        let a = f64::from(i) * 0.25 - 5.0;
        s += &format!(
            "{},1657.8,{a},0,{},-6.6,83.83,40.25,0\n",
            f64::from(i) * 0.01,
            -300.0 * a
        );
    }
    fs::write(&rig, s).unwrap();
    let o = run(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "linear",
        "--out",
        dir.path().join("t.toml").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let said = stderr(&o);
    for (column, factor) in [
        ("alpha [deg]", "× π/180 = 0.0174533"),
        ("camber [deg]", "× π/180 = 0.0174533"),
        ("pressure [kPa]", "× 1000"),
        ("speed [km/h]", "÷ 3.6"),
        ("fx [kN]", "× 1000"),
    ] {
        let line = said
            .lines()
            .find(|l| l.contains(&format!("column `{column}`")))
            .unwrap_or_else(|| panic!("{column} not said: {said}"));
        assert!(line.contains(factor), "{line}");
        let name = column.split(' ').next().unwrap();
        assert!(
            line.contains(&format!("name the column `{name}`")),
            "{line}"
        );
    }
    // The units it reads them in are taken as stated.
    for si in ["`t [s]`", "`fz [N]`", "`fy [N]`", "`mz [Nm]`"] {
        assert!(!said.contains(si), "{si}: {said}");
    }
    assert!(
        !said.contains("Rename it") && !said.contains("did you mean"),
        "{said}"
    );
    assert!(!dir.path().join("t.toml").exists());
}

#[test]
fn a_points_file_with_loads_in_kn_in_its_header_is_told_to_convert_them_by_tyre_eval() {
    let dir = tempfile::tempdir().unwrap();
    linear_tyre(dir.path());
    let points = dir.path().join("pts.csv");
    fs::write(
        &points,
        "fz [kN],kappa [-],alpha (deg),camber [rad],speed [m/s]\n4,0,2,0,20\n",
    )
    .unwrap();
    let out = dir.path().join("out.csv");
    let o = run(&[
        "tyre-eval",
        dir.path().join("tyre.toml").to_str().unwrap(),
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let said = stderr(&o);
    assert!(
        said.contains("pts.csv:1:1: column `fz [kN]` is `fz` in kN"),
        "{said}"
    );
    assert!(said.contains("(× 1000)"), "{said}");
    assert!(
        said.contains("pts.csv:1:3: column `alpha (deg)` is `alpha` in deg"),
        "{said}"
    );
    assert!(
        !said.contains("`kappa [-]`") && !said.contains("`speed [m/s]`"),
        "{said}"
    );
    assert!(!out.exists());
    // In the units it reads, the same header is read.
    fs::write(
        &points,
        "fz [N],kappa [-],alpha (rad),camber [rad],speed [m/s]\n4000,0,0.0349,0,20\n",
    )
    .unwrap();
    let o = run(&[
        "tyre-eval",
        dir.path().join("tyre.toml").to_str().unwrap(),
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let written = fs::read_to_string(&out).unwrap();
    assert!(written.lines().count() == 2, "{written}");
}

#[test]
fn a_campaign_run_with_its_steer_in_degrees_in_the_header_is_told_the_runs_key() {
    let dir = tempfile::tempdir().unwrap();
    let log = run_log("t,speed,steer [deg],yaw_rate", 57.29578, 1.0);
    let c = campaign(dir.path(), "\"sensor_bias\"", &[("a.csv".into(), log)]);
    let o = run(&[
        "diagnose",
        c.to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let said = without_temp_names(&stderr(&o));
    assert!(
        said.contains("column `steer [deg]` is `steer` in deg"),
        "{said}"
    );
    assert!(
        said.contains("`degrees = [\"steer\"]` under [runs]"),
        "{said}"
    );
    assert!(
        !said.contains("--degrees") && !said.contains("[manoeuvre]"),
        "{said}"
    );
}

#[test]
fn a_replay_run_with_its_yaw_rate_in_deg_per_s_in_the_header_is_told_the_manoeuvre_key() {
    let dir = tempfile::tempdir().unwrap();
    linear_tyre(dir.path());
    let log = run_log("t,speed,steer,yaw_rate [deg/s]", 1.0, 57.29578);
    let sc = replay_of(dir.path(), &log);
    let o = run(&[
        "simulate",
        sc.to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let said = without_temp_names(&stderr(&o));
    assert!(
        said.contains("column `yaw_rate [deg/s]` is `yaw_rate` in deg/s"),
        "{said}"
    );
    assert!(
        said.contains("`degrees = [\"yaw_rate\"]` under [manoeuvre]"),
        "{said}"
    );
    assert!(
        !said.contains("--degrees") && !said.contains("[runs]"),
        "{said}"
    );
}

/// The run reader's own unit refusals (a steer beyond 90°, a yaw rate
/// beyond any car's) name the key of the command that read the run only:
/// `metrics` its option, a campaign its `[runs]`.
#[test]
fn a_run_s_angles_in_degrees_are_declared_by_the_reading_command_s_key_only() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("r.csv");
    fs::write(
        &csv,
        run_log("t,speed,steer,yaw_rate", 1.0, 57.29578 * 20.0),
    )
    .unwrap();
    let said = metrics_of(&csv, &[]).unwrap_err();
    assert!(said.contains("column `yaw_rate`"), "{said}");
    assert!(
        said.contains("declare it so: `--degrees yaw_rate` to `metrics`"),
        "{said}"
    );
    assert!(
        !said.contains("[runs]") && !said.contains("[manoeuvre]"),
        "{said}"
    );
    let log = run_log("t,speed,steer,yaw_rate", 57.29578 * 100.0, 1.0);
    let c = campaign(dir.path(), "\"sensor_bias\"", &[("a.csv".into(), log)]);
    let o = run(&[
        "diagnose",
        c.to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let said = without_temp_names(&stderr(&o));
    assert!(said.contains("column `steer`"), "{said}");
    assert!(
        said.contains("declare it so: `degrees = [\"steer\"]` under [runs]"),
        "{said}"
    );
    assert!(
        !said.contains("--degrees") && !said.contains("[manoeuvre]"),
        "{said}"
    );
}

#[test]
fn a_tyre_file_s_written_pressure_range_past_any_tyre_s_is_refused_at_its_key() {
    let dir = tempfile::tempdir().unwrap();
    let tyre = dir.path().join("tyre.toml");
    fs::write(
        &tyre,
        "model = \"linear\"\ncornering_stiffness = 60000.0\n\n[fitted_ranges]\nfz = [500.0, 3000.0]\npressure = [82000000.0, 84000000.0]\n",
    )
    .unwrap();
    let points = dir.path().join("pts.csv");
    fs::write(&points, "fz,kappa,alpha,camber,speed\n2000,0,0.01,0,20\n").unwrap();
    let out = dir.path().join("out.csv");
    let o = run(&[
        "tyre-eval",
        tyre.to_str().unwrap(),
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success(), "{}", stderr(&o));
    let said = stderr(&o);
    assert!(said.contains("tyre.toml:6:"), "{said}");
    assert!(
        said.contains("`fitted_ranges.pressure[0]` = 82000000"),
        "{said}"
    );
    assert!(said.contains("5 MPa"), "{said}");
    assert!(!out.exists());
}

#[test]
fn a_pressure_asked_for_in_pa_is_said_back_in_pa_with_its_kpa() {
    let test = "a_pressure_asked_for_in_pa_is_said_back_in_pa_with_its_kpa";
    let Some(data) = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("t.toml");
    let o = run(&[
        "identify",
        data.to_str().unwrap(),
        "--model",
        "linear",
        "--pressure",
        "83400",
        "--load",
        "1656",
        "--camber",
        "0",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("pressure 83400 Pa (83.4 kPa) asked for: the 83.4 kPa level selected"),
        "{said}"
    );
}
