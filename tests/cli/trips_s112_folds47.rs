//! `diagnose` names the run whose fold moves a parameter (session 112,
//! tester round 47). A synth campaign with a 50 ms sensor delay, one run's
//! yaw rate and ay then logged 0.15 s later still (a logger with its own
//! delay): the runs disagree on the delay beyond their noise, and the
//! report said only that. Now each parameter carries its fold refits one
//! by one in `diagnosis.json` (the runs each leaves out, its value,
//! converged or not), and the terminal and the page name the fold that
//! stands apart — beyond 3× the other folds' spread — and its run as the
//! one to check.

use super::*;

/// The run given its own logger delay.
const LATE_RUN: &str = "step_100kph_6ms2.csv";

/// Samples of the extra delay: 0.15 s at synth's 100 Hz.
const LATE_SAMPLES: usize = 15;

/// The campaign `synth --effects sensor_delay --seed 1` writes into
/// `dir/name`, narrowed to the delay and a relaxation length (the book's
/// diagnose example). Also `trips_s113_floors48`'s.
pub(super) fn delay_campaign(dir: &Path, name: &str) -> PathBuf {
    let c = synth_campaign(dir, name, &["--effects", "sensor_delay", "--seed", "1"]);
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    assert!(text.trim_end().ends_with("seed = 1"), "{text}");
    let narrowed = "effects = [\"sensor_delay\", \"relaxation_length\"]\n";
    fs::write(&v, format!("{}\n{narrowed}", text.trim_end())).unwrap();
    c
}

/// Delays `columns` of the run file `path` by `n` samples: each row reads
/// the value `n` rows earlier, the first `n` rows the first value (the
/// logger held its first reading).
fn delay_columns(path: &Path, columns: &[&str], n: usize) {
    let text = fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let rows: Vec<Vec<String>> = lines
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    let at: Vec<usize> = columns
        .iter()
        .map(|c| head.iter().position(|h| h == c).unwrap())
        .collect();
    let mut out = head.join(",") + "\n";
    for (i, row) in rows.iter().enumerate() {
        let mut row = row.clone();
        for &c in &at {
            row[c].clone_from(&rows[i.saturating_sub(n)][c]);
        }
        out += &(row.join(",") + "\n");
    }
    fs::write(path, out).unwrap();
}

/// The grouped jackknife of `values`, as the report computes it.
fn jackknife(values: &[f64]) -> f64 {
    let k = values.len() as f64;
    let mean = values.iter().sum::<f64>() / k;
    let ss: f64 = values.iter().map(|v| (v - mean).powi(2)).sum();
    ((k - 1.0) / k * ss).sqrt()
}

#[test]
fn the_fold_that_leaves_out_a_late_logged_run_names_that_run() {
    let dir = tempfile::tempdir().unwrap();
    let clean = delay_campaign(dir.path(), "clean");
    let late = delay_campaign(dir.path(), "late");
    delay_columns(
        &late.join("runs").join(LATE_RUN),
        &["yaw_rate", "ay"],
        LATE_SAMPLES,
    );
    let both = diagnosed_together(&[clean.clone(), late.clone()]);
    let (stdout, d) = &both[1];
    let row = ranked(d, "sensor_delay");
    let p = &row["parameters"][0];
    assert_eq!(p["name"], "sensor_delay.delay", "{p}");
    // One refit per fold, each leaving out one of the eight runs, all
    // converged.
    let refits = p["fold_refits"].as_array().unwrap();
    assert_eq!(refits.len(), 8, "{p}");
    assert_eq!(row["folds"].as_u64(), Some(8), "{row}");
    let mut left_out: Vec<String> = refits
        .iter()
        .map(|f| {
            assert_eq!(f["converged"], true, "{f}");
            let runs = f["left_out"].as_array().unwrap();
            assert_eq!(runs.len(), 1, "{f}");
            runs[0].as_str().unwrap().to_string()
        })
        .collect();
    left_out.sort();
    let mut files: Vec<String> = fs::read_dir(late.join("runs"))
        .unwrap()
        .map(|e| e.unwrap().path().display().to_string())
        .collect();
    files.sort();
    let names = |v: &[String]| -> Vec<String> {
        v.iter()
            .map(|s| {
                Path::new(s)
                    .file_name()
                    .unwrap()
                    .to_string_lossy()
                    .into_owned()
            })
            .collect()
    };
    assert_eq!(names(&left_out), names(&files));
    // The report's fold spread is the jackknife of these values.
    let values: Vec<f64> = refits
        .iter()
        .map(|f| f["value"].as_f64().unwrap())
        .collect();
    let j = p["fold_std_error"].as_f64().unwrap();
    assert!((jackknife(&values) - j).abs() < 1e-12 * j.max(1e-12), "{p}");
    // The sweep carries most of what determines the delay (one fold's
    // noise carries the rest); without it the steps follow the late run:
    // that fold stands beyond 3× the others' spread by the test's own
    // count, and the late run's own fold moves most the other way, to
    // synth's 50 ms, nearer than the all-run fit the late run pulls.
    assert!(p["fold_noise_dof"].as_f64().unwrap() < 2.0, "{p}");
    let fold_of = |run: &str| {
        (refits.iter())
            .position(|f| f["left_out"][0].as_str().unwrap().ends_with(run))
            .unwrap()
    };
    let (sweep, late_fold) = (fold_of("sweep_080kph.csv"), fold_of(LATE_RUN));
    let others: Vec<f64> = (0..8).filter(|&i| i != sweep).map(|i| values[i]).collect();
    let mean = others.iter().sum::<f64>() / 7.0;
    let apart = (values[sweep] - mean).abs() / jackknife(&others);
    assert!(apart > 3.0, "{apart} of the others' spread: {values:?}");
    let all = p["value"].as_f64().unwrap();
    let side = (values[sweep] - all).signum();
    let most = (0..8)
        .filter(|&i| i != sweep)
        .max_by(|&a, &b| (side * (all - values[a])).total_cmp(&(side * (all - values[b]))))
        .unwrap();
    assert_eq!(most, late_fold, "{values:?}");
    assert!(
        (values[late_fold] - 0.05).abs() < (all - 0.05).abs(),
        "{values:?} against {all}"
    );
    // The terminal names both runs, with the others' range.
    let line = stdout
        .lines()
        .find(|l| l.trim_start().starts_with("sensor_delay "))
        .unwrap();
    assert!(
        line.contains("the runs disagree beyond their noise"),
        "{line}"
    );
    let lo = others.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = others.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let name = |i: usize| refits[i]["left_out"][0].as_str().unwrap().to_string();
    let said = format!(
        "; the fold leaving out {} refits it to {:.4} s, the other 7 folds to {lo:.4}–{hi:.4} s, beyond 3× their spread: check that run (its own logger, its own set-up) and {} (its fold {:.4} s)",
        name(sweep),
        values[sweep],
        name(late_fold),
        values[late_fold],
    );
    assert!(line.contains(&said), "{line}\nwants: {said}");
    // The page says the same.
    let page = fs::read_to_string(late.join("out").join("report.html")).unwrap();
    assert!(page.contains(&escaped(&said)), "{said}");
    // Without the late run the delay's folds agree within their noise: no
    // run named on its row.
    let (clean_out, _) = &both[0];
    let clean_line = (clean_out.lines())
        .find(|l| l.trim_start().starts_with("sensor_delay "))
        .unwrap();
    assert!(!clean_line.contains("to check"), "{clean_line}");
    assert!(!clean_line.contains("check that run"), "{clean_line}");
}
