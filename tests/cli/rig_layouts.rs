//! Rig files in the layouts real rigs and papers produce: grouping and
//! thinning lose nothing silently, through `identify` and `diagnose`.

use super::*;
use handling::tyre::{Pac89, SlipState, Tyre, TyreModel};

fn truth() -> Tyre {
    Tyre::Pac89(Pac89::adams_example())
}

/// `header` then one line per row.
fn csv(header: &str, rows: &[Vec<f64>]) -> String {
    let mut s = format!("{header}\n");
    for r in rows {
        let cells: Vec<String> = r.iter().map(|v| format!("{v}")).collect();
        s += &cells.join(",");
        s.push('\n');
    }
    s
}

/// Runs `identify` on `file` in `dir` with `extra` flags; returns the
/// report and stdout, or panics with stderr.
pub(super) fn identify(
    dir: &Path,
    file: &str,
    model: &str,
    extra: &[&str],
) -> (serde_json::Value, String) {
    let out = dir.join("fit.toml");
    let data = dir.join(file);
    let mut args = vec![
        "identify",
        data.to_str().unwrap(),
        "--model",
        model,
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    let o = run(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let stdout = String::from_utf8_lossy(&o.stdout).into_owned();
    crate::identify::assert_tidy_output(&stdout);
    (read_json(&dir.join("fit.report.json")), stdout)
}

/// The nominal loads of a fit's report, ascending.
pub(super) fn load_nominals(report: &serde_json::Value) -> Vec<f64> {
    let loads = &report["grouping"]["levels"][0];
    assert_eq!(loads["variable"], "load");
    loads["levels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["nominal"].as_f64().unwrap())
        .collect()
}

fn lateral_rows(loads: &[f64], alphas: &[f64]) -> Vec<Vec<f64>> {
    let t = truth();
    loads
        .iter()
        .flat_map(|&fz| {
            alphas
                .iter()
                .map(|&a| vec![fz, a, t.lateral_force(&SlipState::lateral(a, fz))])
                .collect::<Vec<_>>()
        })
        .collect()
}

#[test]
fn the_papers_layout_one_sample_per_slip_angle_is_fitted_whole() {
    // Three loads × 85 slip angles 0.2865° apart, columns fz, alpha, fy only.
    let alphas: Vec<f64> = (-42..=42)
        .map(|i| (0.2865 * i as f64).to_radians())
        .collect();
    let rows = lateral_rows(&[2800.0, 5700.0, 8600.0], &alphas);
    let dir = scratch(&[("rig.csv", &csv("fz,alpha,fy", &rows))]);
    let (report, stdout) = identify(dir.path(), "rig.csv", "pac89", &[]);
    let g = &report["grouping"];
    assert_eq!(g["samples"], 255);
    assert_eq!(g["used"], 255, "{stdout}");
    assert_eq!(g["points"], 255);
    assert_eq!(g["dropped_in_transitions"], 0);
    assert!(stdout.contains("255 samples: 255 used"), "{stdout}");
    // Noise-free data of the model itself: a near-exact fit.
    assert!(report["sigma_percent"].as_f64().unwrap() < 0.5, "{report}");
}

#[test]
fn the_papers_table_flattened_slip_angle_by_slip_angle_keeps_its_loads() {
    // Rows ordered by slip angle, the three loads interleaved.
    let t = truth();
    let rows: Vec<Vec<f64>> = (-42..=42)
        .flat_map(|i| {
            let a = (0.2865 * i as f64).to_radians();
            [2800.0, 5700.0, 8600.0]
                .map(|fz| vec![fz, a, t.lateral_force(&SlipState::lateral(a, fz))])
        })
        .collect();
    let dir = scratch(&[("rig.csv", &csv("fz,alpha,fy", &rows))]);
    let (report, stdout) = identify(dir.path(), "rig.csv", "pac89", &[]);
    assert_eq!(report["curves"].as_array().unwrap().len(), 3, "{stdout}");
    assert_eq!(report["grouping"]["used"], 255);
}

#[test]
fn a_single_fine_sweep_loses_no_sample() {
    // 0.1° steps: 2–3 samples per 0.25° bin, all of them averaged in.
    let alphas: Vec<f64> = (-120..=120)
        .map(|i| (0.1 * i as f64).to_radians())
        .collect();
    let rows = lateral_rows(&[2000.0, 4000.0, 6000.0], &alphas);
    let dir = scratch(&[("rig.csv", &csv("fz,alpha,fy", &rows))]);
    let (report, _) = identify(dir.path(), "rig.csv", "pac89", &[]);
    let g = &report["grouping"];
    assert_eq!(g["used"], 723);
    // 24° of slip in 0.25° bins: 97 bins per load.
    assert_eq!(g["points"], 3 * 97, "{g}");
}

#[test]
fn up_and_down_sweeps_at_one_degree_average_their_hysteresis() {
    let up: Vec<f64> = (-12..=12).map(|i| (i as f64).to_radians()).collect();
    let t = truth();
    let mut rows = Vec::new();
    for fz in [2000.0, 4000.0, 6000.0] {
        // Down sweep reads 2 % high, up sweep 2 % low: the mean is the truth.
        for (k, sweep) in [up.clone(), up.iter().rev().copied().collect()]
            .iter()
            .enumerate()
        {
            for &a in sweep {
                let f = t.lateral_force(&SlipState::lateral(a, fz));
                rows.push(vec![fz, a, f * if k == 0 { 0.98 } else { 1.02 }]);
            }
        }
    }
    let dir = scratch(&[("rig.csv", &csv("fz,alpha,fy", &rows))]);
    let (report, _) = identify(dir.path(), "rig.csv", "pac89", &[]);
    let g = &report["grouping"];
    assert_eq!(g["used"], 150);
    assert_eq!(g["points"], 75);
    assert!(report["sigma_percent"].as_f64().unwrap() < 0.5, "{report}");
}

#[test]
fn a_discrete_slip_ratio_grid_is_binned_in_slip_ratio() {
    let t = truth();
    let t = &t;
    let rows: Vec<Vec<f64>> = [2000.0, 4000.0, 6000.0]
        .iter()
        .flat_map(|&fz| {
            (-20..=20).map(move |i| {
                let k = 0.01 * i as f64;
                vec![fz, k, t.forces(&SlipState::longitudinal(k, fz)).fx]
            })
        })
        .collect();
    let dir = scratch(&[("rig.csv", &csv("fz,kappa,fx", &rows))]);
    let (report, stdout) = identify(dir.path(), "rig.csv", "pac89", &[]);
    let g = &report["grouping"];
    assert_eq!(g["slip_axis"], "ratio");
    assert_eq!(g["points"], 123, "{stdout}");
    assert!(report["sigma_percent"].as_f64().unwrap() < 1.0, "{report}");
}

#[test]
fn close_bicycle_tyre_loads_stay_four_levels() {
    let alphas: Vec<f64> = (-30..=30).map(|i| (0.25 * i as f64).to_radians()).collect();
    let t = truth();
    let mut rows = Vec::new();
    for (k, fz) in [340.0, 390.0, 440.0, 490.0].iter().enumerate() {
        for (i, &a) in alphas.iter().enumerate() {
            // The load controller wanders ±2 N.
            let load = fz + 2.0 * ((i * 7 + k * 3) as f64).sin();
            rows.push(vec![load, a, t.lateral_force(&SlipState::lateral(a, load))]);
        }
    }
    let dir = scratch(&[("rig.csv", &csv("fz,alpha,fy", &rows))]);
    let (report, stdout) = identify(dir.path(), "rig.csv", "pac89", &[]);
    let nominal = load_nominals(&report);
    assert_eq!(nominal.len(), 4, "{stdout}");
    for (n, want) in nominal.iter().zip([340.0, 390.0, 440.0, 490.0]) {
        assert!((n - want).abs() < 2.0, "{nominal:?}");
    }
    assert_eq!(report["curves"].as_array().unwrap().len(), 4);
}

#[test]
fn a_small_fourth_load_is_kept_and_reported() {
    let many: Vec<f64> = (-200..=200)
        .map(|i| (0.05 * i as f64).to_radians())
        .collect();
    let few: Vec<f64> = (-4..=4).map(|i| (2.0 * i as f64).to_radians()).collect();
    let mut rows = lateral_rows(&[2000.0, 4000.0, 6000.0], &many);
    rows.extend(lateral_rows(&[8000.0], &few));
    assert!(
        9 * 100 < rows.len(),
        "the fourth load holds under 1 % of the samples"
    );
    let dir = scratch(&[("rig.csv", &csv("fz,alpha,fy", &rows))]);
    let (report, stdout) = identify(dir.path(), "rig.csv", "pac89", &[]);
    assert!(stdout.contains("8000 N (9)"), "{stdout}");
    let curves = report["curves"].as_array().unwrap();
    assert_eq!(curves.len(), 4);
    assert_eq!(report["grouping"]["used"], rows.len());
}

#[test]
fn selecting_a_pressure_or_camber_the_file_lacks_is_refused() {
    let alphas: Vec<f64> = (-10..=10).map(|i| (i as f64).to_radians()).collect();
    let rows = lateral_rows(&[2000.0, 4000.0, 6000.0], &alphas);
    let dir = scratch(&[("rig.csv", &csv("fz,alpha,fy", &rows))]);
    let data = dir.path().join("rig.csv");
    let out = dir.path().join("t.toml");
    for (flag, value, says) in [
        ("--pressure", "83000", "no `pressure` column"),
        ("--camber", "0.03", "no `camber` column"),
    ] {
        let o = run(&[
            "identify",
            data.to_str().unwrap(),
            "--model",
            "pac89",
            flag,
            value,
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(!o.status.success());
        assert!(stderr(&o).contains(says), "{}", stderr(&o));
        assert!(!out.exists());
    }
    // With a camber column, a value far from every level is refused, naming
    // the levels there are.
    let with_camber: Vec<Vec<f64>> = rows.iter().map(|r| vec![r[0], r[1], 0.0, r[2]]).collect();
    fs::write(&data, csv("fz,alpha,camber,fy", &with_camber)).unwrap();
    let o = run(&[
        "identify",
        data.to_str().unwrap(),
        "--model",
        "pac89",
        "--camber",
        "0.05",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("no camber level near") && e.contains("0.00°"),
        "{e}"
    );
}

#[test]
fn real_hoosier_rig_data_groups_as_before() {
    let Some(data) = shared_data(
        "real_hoosier_rig_data_groups_as_before",
        "tyre_ttc_hoosier_43075/cornering.csv",
    ) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("t.toml");
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
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let report = read_json(&dir.path().join("t.report.json"));
    let g = &report["grouping"];
    // Every sample accounted for; five loads, three cambers, three pressures.
    let total = g["used"].as_u64().unwrap()
        + g["dropped_in_transitions"].as_u64().unwrap()
        + g["not_selected"].as_u64().unwrap();
    assert_eq!(total, 59_965);
    let counts: Vec<usize> = g["levels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["levels"].as_array().unwrap().len())
        .collect();
    assert_eq!(counts, vec![5, 3, 3]);
    // The histogram grouping this replaced gave σ 2.511 % with the same
    // command (`identify cornering.csv --model pac89 --pressure 83000
    // --camber 0`, seed 1).
    let sigma = report["sigma_percent"].as_f64().unwrap();
    assert!((sigma - 2.511).abs() < 0.05, "σ {sigma}");
}

/// A synthetic campaign (relaxation length, seed 2) in `dir` whose rig
/// file's data rows are rewritten by `row` (row index, text; None drops it).
fn campaign_with_rig_rows(dir: &Path, row: impl Fn(usize, &str) -> Option<String>) -> PathBuf {
    let args = ["--effects", "relaxation_length", "--seed", "2"];
    let campaign = synth_campaign(dir, "c", &args);
    let rig = campaign.join("tyre_rig.csv");
    let text = fs::read_to_string(&rig).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    assert_eq!(header, "fz,alpha,fy");
    let mut out = format!("{header}\n");
    for (i, l) in lines.enumerate() {
        if let Some(r) = row(i, l) {
            out += &r;
            out.push('\n');
        }
    }
    fs::write(&rig, out).unwrap();
    campaign
}

#[test]
fn a_campaign_whose_rig_file_has_the_papers_layout_is_diagnosed() {
    let dir = tempfile::tempdir().unwrap();
    // Keep every sixth rig row: one sample per 0.3° of slip, as the papers
    // tabulate them.
    let campaign = campaign_with_rig_rows(dir.path(), |i, l| (i % 6 == 0).then(|| l.to_string()));
    let (_, d) = diagnose_campaign(&campaign);
    assert_eq!(
        verdict_of(&d),
        vec!["relaxation_length"],
        "{}",
        d["verdict"]
    );
}

#[test]
fn camber_zero_selects_a_file_without_camber_pooled_pressures_are_warned_about_and_degrees_refused()
{
    let alphas: Vec<f64> = (-10..=10).map(|i| (i as f64).to_radians()).collect();
    let rows = lateral_rows(&[2000.0, 4000.0, 6000.0], &alphas);
    let pressured: Vec<Vec<f64>> = [83_000.0, 97_000.0]
        .iter()
        .flat_map(|p| rows.iter().map(move |r| vec![r[0], r[1], r[2], *p]))
        .collect();
    let degrees: Vec<Vec<f64>> = rows
        .iter()
        .map(|r| vec![r[0], r[1].to_degrees(), r[2]])
        .collect();
    let dir = scratch(&[
        ("rig.csv", &csv("fz,alpha,fy", &rows)),
        ("pressures.csv", &csv("fz,alpha,fy,pressure", &pressured)),
        ("degrees.csv", &csv("fz,alpha,fy", &degrees)),
    ]);
    let identify = |file: &str, extra: &[&str]| {
        let out = dir.path().join(format!("{file}.toml"));
        let _ = fs::remove_file(out.with_extension("report.json"));
        let data = dir.path().join(file);
        let mut args = vec![
            "identify",
            data.to_str().unwrap(),
            "--model",
            "pac89",
            "--out",
            out.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        let _ = fs::remove_file(&out);
        let _ = fs::remove_file(out.with_extension("png"));
        run(&args)
    };
    // FORMATS.md: camber 0 when the column is absent.
    let o = identify("rig.csv", &["--camber", "0"]);
    assert!(o.status.success(), "{}", stderr(&o));
    // Two pressures into PAC89 (no pressure terms): fitted, with a warning
    // that names the way out; one pressure selected: no warning.
    let o = identify("pressures.csv", &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("2 pressures pooled into one pac89 fit"),
        "{}",
        stderr(&o)
    );
    let o = identify("pressures.csv", &["--pressure", "83000"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        !without_temp_names(&stderr(&o)).contains("pooled"),
        "{}",
        stderr(&o)
    );
    // Slip angles in degrees: refused at the first one past 90°, with its
    // line and column.
    let o = identify("degrees.csv", &[]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(
        e.contains("degrees.csv:") && e.contains("in degrees"),
        "{e}"
    );
    assert!(
        e.contains(":2:"),
        "line of the first slip past 90°, column 2: {e}"
    );
}

#[test]
fn a_camber_logged_a_hair_below_zero_prints_as_zero() {
    // Rigs log a zero camber as -1e-6 rad and the like: the level and every
    // curve print "0.00°", never "-0.00°".
    let alphas: Vec<f64> = (-42..=42)
        .map(|i| (0.2865 * i as f64).to_radians())
        .collect();
    let rows: Vec<Vec<f64>> = lateral_rows(&[2800.0, 5700.0, 8600.0], &alphas)
        .into_iter()
        .enumerate()
        .map(|(i, r)| vec![r[0], r[1], -1e-6 * (1 + i % 3) as f64, r[2]])
        .collect();
    let dir = scratch(&[("rig.csv", &csv("fz,alpha,camber,fy", &rows))]);
    let (_, stdout) = identify(dir.path(), "rig.csv", "pac89", &[]);
    assert!(stdout.contains("camber levels: 0.00° (255)"), "{stdout}");
    assert_eq!(
        stdout.matches(", camber  0.00°, ").count(),
        3,
        "one line per load: {stdout}"
    );
    assert!(!stdout.contains("-0.00"), "{stdout}");
}

#[test]
fn a_campaign_whose_rig_file_has_fy_reversed_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let campaign = campaign_with_rig_rows(dir.path(), |_, l| {
        let cells: Vec<f64> = l.split(',').map(|v| v.parse().unwrap()).collect();
        Some(format!("{},{},{}", cells[0], cells[1], -cells[2]))
    });
    let out = campaign.with_extension("out");
    let o = run(&[
        "diagnose",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(!out.join("diagnosis.json").exists());
    let e = stderr(&o);
    assert!(
        e.contains("tyre_rig.csv: column `fy` (column 3 of the header) has the wrong sign")
            && e.contains("slope against `alpha` is -")
            && e.contains("negate the `fy` column"),
        "{e}"
    );
}
