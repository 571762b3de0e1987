//! What a fresh user tripped on (round 16) in `tyre-eval` and `identify`:
//! a camber column of small angles in degrees evaluated at a `.tir`'s
//! `CAMMAX` without a word on its unit, and the paper's σ printed beside
//! the fit's as if it were a target.

use super::*;

/// A camber column in degrees whose values stay under 20° read in radians
/// (0.5 and 0.3, meant as half a degree and 0.3°) passes the physical range
/// and was evaluated at the file's `CAMMAX` (0.105 rad = 6°) with only the
/// range's warning. Every camber other than 0 leaving the range while each,
/// read in degrees, lies inside it is now asked as degrees; a column in
/// radians with one camber inside the range (0.05 beside 0.5) is not, and
/// the same column given in radians (0.5° → 0.00873 rad) leaves no range.
#[test]
fn a_camber_column_of_small_degrees_outside_the_files_range_is_asked_as_degrees() {
    let tir = root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir");
    let asked = "every camber of the points other than 0 lies outside the range, and read in degrees every one lies inside it: angles are in radians (FORMATS.md); is the column in degrees?";
    let cases = [
        ("deg.csv", "0.5", "0.3", Some(true)),
        ("mixed.csv", "0.5", "0.05", Some(false)),
        ("rad.csv", "0.008727", "0.005236", None),
    ];
    let files: Vec<(String, String)> = cases
        .iter()
        .map(|(name, a, b, _)| {
            let body = format!(
                "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n4000,0,0.05,{a},16.7\n4000,0,0.05,{b},16.7\n"
            );
            (name.to_string(), body)
        })
        .collect();
    let refs: Vec<(&str, &str)> = files
        .iter()
        .map(|(n, b)| (n.as_str(), b.as_str()))
        .collect();
    let dir = scratch(&refs);
    for (name, _, _, expect) in cases {
        let out = dir.path().join(format!("{name}.out.csv"));
        let o = run_in(
            dir.path(),
            &[
                "tyre-eval",
                tir.to_str().unwrap(),
                name,
                "--out",
                out.to_str().unwrap(),
            ],
        );
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let err = stderr(&o);
        let camber_warning = err.lines().find(|l| l.contains("CAMMAX"));
        match expect {
            Some(degrees) => {
                let line = camber_warning.unwrap_or_else(|| panic!("{name}: {err}"));
                assert_eq!(line.contains(asked), degrees, "{name}: {line}");
            }
            None => assert!(camber_warning.is_none(), "{name}: {err}"),
        }
    }
}

/// `identify --model mf61` printed "(start 3.4 %; Wei et al. 2010: 1.20 %)"
/// beside each stage's σ, which a tester read as the σ to reach. The
/// paper's figure is said as what it is: what Wei et al. reached on their
/// own rig data.
#[test]
fn the_papers_sigma_is_said_as_theirs_on_their_data() {
    let dir = scratch(&[]);
    let rig = dir.path().join("rig.csv");
    mf61_evaluated(&root().join("docs/examples/mf_grid.csv"), &rig);
    let o = identify_to(&rig, "mf61", &dir.path().join("fit.tir"));
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    let stage = said
        .lines()
        .find(|l| l.trim_start().starts_with("pure Fy"))
        .unwrap_or_else(|| panic!("{said}"));
    assert!(
        stage.contains("; Wei et al. 2010 reached 1.20 % on their own rig data)"),
        "{stage}"
    );
    assert!(!said.contains("Wei et al. 2010: "), "{said}");
}

/// A campaign with two bad runs was refused at the first, and only after
/// mending it did the user learn of the second. Every run is now checked
/// before any is refused: a run cut to 0.58 s and one whose gyro logs 0
/// throughout are both said, in run order, with the count of runs; one bad
/// run alone is refused as before, in its own words.
#[test]
fn every_refused_run_of_a_campaign_is_said_at_once() {
    let dir = scratch(&[]);
    let camp = synth_campaign(
        dir.path(),
        "bad",
        &["--effects", "sensor_delay", "--seed", "1"],
    );
    let mut files: Vec<PathBuf> = fs::read_dir(camp.join("runs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    let short = fs::read_to_string(&files[0]).unwrap();
    let cut: String = short.lines().take(60).map(|l| format!("{l}\n")).collect();
    fs::write(&files[0], cut).unwrap();
    let refused = || fails_cleanly("diagnose", &camp, dir.path());
    let one = refused();
    assert!(
        one.contains("the run is 0.58 s long with 59 samples"),
        "{one}"
    );
    assert!(!one.contains("runs refused"), "{one}");
    let dead = fs::read_to_string(&files[2]).unwrap();
    let mut lines = dead.lines();
    let head = lines.next().unwrap();
    let yaw = head.split(',').position(|c| c == "yaw_rate").unwrap();
    let mut zeroed = format!("{head}\n");
    for l in lines {
        let mut cells: Vec<&str> = l.split(',').collect();
        cells[yaw] = "0";
        zeroed.push_str(&cells.join(","));
        zeroed.push('\n');
    }
    fs::write(&files[2], zeroed).unwrap();
    let both = refused();
    let listed: Vec<&str> = both.lines().collect();
    assert_eq!(
        listed[0], "error: 2 of 8 runs refused, in run order:",
        "{both}"
    );
    let name = |p: &PathBuf| p.file_name().unwrap().to_string_lossy().into_owned();
    assert!(
        listed[1].contains(&name(&files[0])) && listed[1].contains("0.58 s long"),
        "{both}"
    );
    assert!(
        listed[2].contains(&name(&files[2]))
            && listed[2].contains("channel `yaw_rate` holds one value (0)"),
        "{both}"
    );
}

/// A noise-free 7 Hz log whose sample lands on an instant step: the yaw
/// rate reads 0 at the step's own sample (it starts from 0), so its leading
/// zeros run one sample past the steer's change. They were masked as a
/// zero read and filled, and the yaw-rate gain read 0.796 for 5.604 with
/// no warning (fresh-eyes round 17). Zeros ending at the steer's change or
/// one sample after it are the straight running before the step.
#[test]
fn leading_zeros_through_the_steps_own_sample_are_no_zero_read() {
    let mut log = String::from("t,speed,steer,yaw_rate,ay,beta\n");
    for i in 0..43 {
        let t = 1.0 + f64::from(i - 7) / 7.0;
        let (steer, r) = match t >= 1.0 {
            true => (0.01, 0.056 * (1.0 - (-(t - 1.0) / 0.15).exp())),
            false => (0.0, 0.0),
        };
        log += &format!("{t:.6},25,{steer},{r:.9},{:.9},0\n", 25.0 * r);
    }
    let dir = scratch(&[("step.csv", &log)]);
    let o = run_in(dir.path(), &["metrics", "step.csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let all = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
    assert!(all.contains("glitches: 0 zero reads"), "{all}");
    let gain: f64 = all
        .lines()
        .find(|l| l.trim_start().starts_with("yaw-rate gain"))
        .and_then(|l| l.split_whitespace().nth(2))
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{all}"));
    // 0.056 (1 − e^(−5/0.15)) / 0.01 = 5.6 to 1e-14.
    assert!((gain - 5.6).abs() < 1e-3, "{gain}: {all}");
}
