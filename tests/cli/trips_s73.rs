//! What a fresh-eyes check found after stop 72, run as a user runs the
//! tool.

use super::*;
use std::fs;

/// A linear tyre's `cornering_stiffness = 1000` (a car tyre's 1000 N/deg
/// typed as N/rad) was simulated: 0.22 N/rad per N of the sedan's wheel
/// load, a yaw rate overshooting by 165 % and a warning of a car "losing
/// grip" on a tyre that has no grip limit. The linear tyre has no load of
/// its own, so its stiffness is taken per unit of the static wheel load
/// of the axle it is fitted to, in `simulate` and in a campaign, and
/// refused at its key in the tyre file with the value converted; the
/// repository's own linear tyre (57296 N/rad) still runs.
#[test]
fn a_linear_tyres_stiffness_in_n_per_degree_is_refused_at_the_cars_wheel_load() {
    let n_per_deg = "model = \"linear\"\ncornering_stiffness = 1000\n";
    let dir = scenario(VEHICLE, n_per_deg, STEP);
    let e = simulate_err(dir.path());
    // The sedan: 1530 kg, a = 1.11, b = 1.67: 4506.65 N on each front wheel.
    let at = "tyre.toml:2:23: `cornering_stiffness` = 1000: over the tyre's static load on each wheel of its axle (from the vehicle's mass, a and b) = 4506.65 N that is 0.222 N/rad per N";
    assert!(e.contains(at), "{e}");
    assert!(
        e.contains("1000 N/deg is 57296 N/rad, 12.7 N/rad per N"),
        "{e}"
    );
    let dir = scenario(
        VEHICLE,
        &fs::read_to_string(root().join("tyres/linear.toml")).unwrap(),
        STEP,
    );
    let o = simulate_in(dir.path());
    assert!(o.status.success(), "{}", stderr(&o));

    // A campaign's one tyre file is checked at the heavier wheel (the
    // front's 4506.65 N), its front and rear files each at its own axle.
    let campaign = format!("{VEHICLE}\n[tyres]\nfile = \"tyre.toml\"\n");
    let dir = scratch(&[("vehicle.toml", &campaign), ("tyre.toml", n_per_deg)]);
    let e = fails_cleanly("diagnose", dir.path(), dir.path());
    assert!(e.contains("= 4506.65 N that is 0.222 N/rad per N"), "{e}");
    let rear_light = "model = \"linear\"\ncornering_stiffness = 4000\n";
    let campaign = format!("{VEHICLE}\n[tyres]\nfront = \"f.toml\"\nrear = \"r.toml\"\n");
    let dir = scratch(&[
        ("vehicle.toml", &campaign),
        (
            "f.toml",
            "model = \"linear\"\ncornering_stiffness = 60000\n",
        ),
        ("r.toml", rear_light),
    ]);
    let e = fails_cleanly("diagnose", dir.path(), dir.path());
    // The rear wheels carry 1530·9.80665·1.11/2.78/2 = 2995.44 N.
    assert!(
        e.contains("r.toml:2:23: `cornering_stiffness` = 4000: over the tyre's static load on each wheel of its axle (from the vehicle's mass, a and b) = 2995.44 N that is 1.34 N/rad per N"),
        "{e}"
    );
}

/// `tyre-eval` warned "1 of 1 points outside the ranges of the rig data
/// the tyre was fitted to" of a load 0.5 N and a slip angle 0.03° past the
/// data's ends, naming neither the range nor the point. A point past an
/// end by at most 1 % of the range's span is within the data (counted
/// apart in the report); one past it is warned of range by range, with
/// the farthest value, its share of the span and the first point's line.
#[test]
fn a_point_a_hair_past_the_fitted_ranges_is_not_an_extrapolation() {
    let tyre = format!("{GIM}[fitted_ranges]\nfz = [2000.0, 6000.0]\nalpha = [-0.2, 0.2]\n");
    let points = "fz,kappa,alpha,camber,speed\n\
                  6000.5,0,0.2005,0,20\n\
                  1960,0,-0.2039,0,20\n\
                  6041,0,0.1,0,20\n\
                  6500,0,0.1,0,20\n";
    let dir = scratch(&[("t.toml", &tyre), ("p.csv", points)]);
    let o = tyre_eval_in(dir.path(), "t.toml");
    assert!(o.status.success(), "{}", stderr(&o));
    let e = stderr(&o);
    let above = "warning: 2 of 4 points above the rig data's fz = 6000 N the tyre was fitted to (its [fitted_ranges]: 2000 to 6000 N): evaluated by extrapolation, the farthest at 6500 N, 12.5 % of the range's span past its end; the first at line 4, fz = 6041 N";
    assert!(e.contains(above), "{e}");
    // The 40 N and 0.0039 rad past the lower ends (1 % of the spans, 40 N
    // and 0.004 rad) are within the data; nothing else is warned of.
    assert_eq!(e.matches("the tyre was fitted to").count(), 1, "{e}");
}

/// A rig file of four loads whose lightest one's curve is half as high as
/// the load law the others follow (friction 1.4 at 2–6 kN, 0.7 at 1 kN).
fn rig_with_an_odd_load() -> String {
    let mut s = String::from("fz,alpha,fy\n");
    for fz in [1000.0, 2000.0, 4000.0, 6000.0] {
        let mu = if fz < 1500.0 { 0.7 } else { 1.4 };
        for k in -10..=10 {
            let alpha = 0.02 * f64::from(k);
            let fy = fz * mu * (1.4 * (12.0 * alpha).atan()).sin();
            s += &format!("{fz},{alpha},{fy:.3}\n");
        }
    }
    s
}

/// The Hoosier file's PAC89 fit printed σ 12.0 % at 534 N beside 1.1–2.2 %
/// at the other loads, and σ 2.5 % over all points, without a word. A
/// condition whose σ passes three times the median condition's (and 5 %)
/// is warned of, on the terminal and in the written file's header.
#[test]
fn a_condition_the_fit_misses_beside_others_it_follows_is_warned_of() {
    let dir = scratch(&[("rig.csv", &rig_with_an_odd_load())]);
    let out = dir.path().join("g.toml");
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "magic-simple",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    let w = "warning: the lateral force misses one condition at Fz 1000 N, camber 0.00° (σ ";
    assert!(said.contains(w), "{said}");
    assert!(
        said.contains("more than 3 times the median condition's σ"),
        "{said}"
    );
    let file = fs::read_to_string(&out).unwrap();
    assert!(
        file.contains("# warning: the lateral force misses one condition at Fz 1000 N"),
        "{file}"
    );
    // The same loads on one law: nothing said.
    let dir = scratch(&[("rig.csv", &super::trips_identify::rig(1.0))]);
    let o = run(&[
        "identify",
        dir.path().join("rig.csv").to_str().unwrap(),
        "--model",
        "magic-simple",
        "--out",
        dir.path().join("g.toml").to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        !String::from_utf8_lossy(&o.stdout).contains("misses"),
        "{}",
        String::from_utf8_lossy(&o.stdout)
    );
}

/// On linear tyres (no friction limit) a yaw rate overshooting by more
/// than 100 % was said to be "a car losing and regaining grip or
/// spinning": they have no grip to lose.
#[test]
fn an_overshoot_on_tyres_without_a_friction_limit_is_no_spin() {
    let soft = "model = \"linear\"\ncornering_stiffness = 7000\n";
    let fast = STEP.replace("speed = 22.2222", "speed = 40.0");
    let dir = scenario(VEHICLE, soft, &fast);
    let o = simulate_in(dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("yaw-rate overshoot           136.9"),
        "{said}"
    );
    assert!(
        said.contains("% on tyres with no friction limit (linear): no grip to lose, no spin, but a lightly damped linear response"),
        "{said}"
    );
    assert!(!said.contains("spinning"), "{said}");
}

/// The Hoosier file's `mz` multiplied by 1000 (N·mm) was fitted to a tyre
/// whose trail is 25 m, written without a word, and `tyre-eval` then gave
/// 34,578 N·m beside 1,338 N of force. A moment beyond 0.5 m times its
/// load is refused at its row, N·mm named; the same file in N·m is read.
#[test]
fn an_aligning_moment_in_newton_millimetres_is_refused_at_its_row() {
    let in_nm = super::trips_identify::rig(1.0);
    let mut in_nmm = String::from("fz,alpha,fy,mz\n");
    // The 2 kN sweep: at 6 kN a moment in N·mm passes 1e5, refused as
    // beyond any rig's whatever the load.
    for line in in_nm.lines().skip(1).filter(|l| l.starts_with("2000,")) {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        in_nmm += &format!("{},{},{},{}\n", v[0], v[1], v[2], 1000.0 * v[3]);
    }
    let dir = scratch(&[("rig.csv", &in_nmm)]);
    let out = dir.path().join("t.toml");
    let o = super::trips_identify::identify_with(dir.path(), "pac89", &[], &out);
    let e = refused(&o, &out);
    // The first row: 2000 N at -0.2 rad, mz -39.9 N·m.
    assert!(
        e.contains(
            "rig.csv:2:4: column `mz`: -39885.7 N·m at fz 2000 N is 18.9932 m times the load"
        ),
        "{e}"
    );
    assert!(
        e.contains("is the column in N·mm? divide it by 1000"),
        "{e}"
    );
    let dir = scratch(&[("rig.csv", &in_nm)]);
    let o =
        super::trips_identify::identify_with(dir.path(), "gim", &[], &dir.path().join("t.toml"));
    assert!(o.status.success(), "{}", stderr(&o));
}

/// `tyre-eval` of a linear tyre at `cornering_stiffness = 1000` (N/deg
/// typed) gave 50 N at 4 kN silently, where `simulate` refuses it; a
/// simplified Magic Formula with `b = 0.1745` (10 per radian typed per
/// degree, B·C·D = 0.23 per unit load) ran in both. The linear tyre is
/// checked at the points' median load, the simplified Magic Formula by
/// its own B·C·D wherever it is read.
#[test]
fn tyre_eval_refuses_a_stiffness_per_degree_as_simulate_does() {
    let points =
        "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n2000,0,0.05,0,16.7\n6000,0,0.05,0,16.7\n";
    let linear = "model = \"linear\"\ncornering_stiffness = 1000.0\n";
    let simple = "model = \"magic-simple\"\nb = 0.1745\nc = 1.3\n";
    let dir = scratch(&[("l.toml", linear), ("m.toml", simple), ("p.csv", points)]);
    let e = refused(
        &tyre_eval_in(dir.path(), "l.toml"),
        &dir.path().join("e.csv"),
    );
    assert!(
        e.contains("l.toml:2:23: `cornering_stiffness` = 1000: over the tyre's median load of the points evaluated = 4000 N that is 0.250 N/rad per N"),
        "{e}"
    );
    let e = refused(
        &tyre_eval_in(dir.path(), "m.toml"),
        &dir.path().join("e.csv"),
    );
    assert!(
        e.contains("m.toml:2:5: `b` = 0.1745: must be greater than 1.15385: the model's cornering stiffness per unit load is B·C·D = 0.227 1/rad"),
        "{e}"
    );
    assert!(e.contains("is it per degree? multiply it by 57.3"), "{e}");
    let dir = scenario(VEHICLE, simple, STEP);
    assert!(simulate_err(dir.path()).contains("`b` = 0.1745: must be greater than 1.15385"));
    // The repository's own tyres are read.
    for tyre in ["linear.toml", "magic_simple.toml"] {
        let dir = scratch(&[("p.csv", points)]);
        let o = tyre_eval_in(
            dir.path(),
            root().join("tyres").join(tyre).to_str().unwrap(),
        );
        assert!(o.status.success(), "{tyre}: {}", stderr(&o));
    }
}

/// The MF 6.1 sample with `FZMAX = 18` (kN typed) evaluated a 4000 N
/// point at 18 N, saying only that it lay above FZMAX. A `FZMAX` below
/// any tyre's largest load (100 N) is refused at its line; one below
/// FNOMIN alone is not (a staged fit from a template keeps its FNOMIN).
#[test]
fn a_tir_whose_fzmax_is_in_kilonewtons_is_refused_at_its_line() {
    let text = fs::read_to_string(root().join("tests/fixtures/tir/MagicFormula61_Parameters.tir"))
        .unwrap();
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n";
    let mut line_no = 0;
    let with = |value: &str, line_no: &mut usize| -> String {
        text.lines()
            .enumerate()
            .map(|(i, l)| match l.split_whitespace().next() {
                Some("FZMAX") => {
                    *line_no = i + 1;
                    format!("FZMAX = {value}\n")
                }
                _ => format!("{l}\n"),
            })
            .collect()
    };
    let eval = |tir: &str| {
        let dir = scratch(&[("t.tir", tir), ("p.csv", points)]);
        let o = tyre_eval_in(dir.path(), "t.tir");
        (o, dir)
    };
    let (o, dir) = eval(&with("18", &mut line_no));
    let e = refused(&o, &dir.path().join("e.csv"));
    let said = format!("t.tir:{line_no}:9: `FZMAX`: 18 must be greater than 100: no tyre's largest load is below 100 N (a bicycle's), and this file's nominal load is FNOMIN = 6752 N: loads are in N after the file's [UNITS]: is FZMAX in kN? multiply it by 1000");
    assert!(e.contains(&said), "{said}\n{e}");
    let (o, _dir) = eval(&with("2000", &mut line_no));
    assert!(o.status.success(), "{}", stderr(&o));
}

/// A Gim tyre evaluated past full sliding (α 0.3 and −0.5 rad at 4 kN)
/// gives `mz` = 0 by its brush model, and `tyre-eval` said "the tyre has
/// no aligning moment; its mz is not a prediction" of a tyre that gives
/// 37.9 N·m at 0.05 rad. Zeros the tyre gives some of at small slip are
/// its prediction; a file with no moment at all is still said.
#[test]
fn a_gim_tyres_zero_moment_past_full_sliding_is_its_prediction_not_a_missing_output() {
    let slide = "fz,kappa,alpha,camber,speed\n4000,0,0.3,0,16.7\n4000,0,-0.5,0,16.7\n";
    let dir = scratch(&[("p.csv", slide)]);
    let gim = root().join("tyres/gim.toml");
    let o = tyre_eval_in(dir.path(), gim.to_str().unwrap());
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("no aligning moment"), "{}", stderr(&o));
    let written = fs::read_to_string(dir.path().join("e.csv")).unwrap();
    assert!(
        written.contains("4000,0,0.3,0,16.7,0,4000,0\n"),
        "{written}"
    );
    // A linear tyre with no trail gives none anywhere: said.
    let lin = "model = \"linear\"\ncornering_stiffness = 60000\n";
    let dir = scratch(&[("p.csv", slide), ("l.toml", lin)]);
    let o = tyre_eval_in(dir.path(), "l.toml");
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("mz = 0: the tyre has no aligning moment"),
        "{}",
        stderr(&o)
    );
}

/// A synthetic 60 km/h step with its steer multiplied by 15 (a
/// steering-wheel angle) was measured as a 17.8° road-wheel step of yaw
/// gain 0.387 1/s without a word, where `diagnose` refuses the same run:
/// `metrics` does not know the car, and at its longest wheelbase (5 m)
/// the ratio, 0.12, passed the 0.1 that refuses a run. The step's steady
/// gain below 0.15 of a neutral 5 m car's is now warned of; the run as
/// logged is not.
#[test]
fn metrics_warns_of_a_steady_gain_no_car_has_as_a_steering_wheel_angle() {
    let dir = tempfile::tempdir().unwrap();
    let campaign = synth_campaign(dir.path(), "c", &["--seed", "1"]);
    let run = campaign.join("runs/step_060kph_2ms2.csv");
    let text = fs::read_to_string(&run).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let steer = header.split(',').position(|c| c == "steer").unwrap();
    let mut wheel = format!("{header}\n");
    for l in lines {
        let mut cells: Vec<String> = l.split(',').map(str::to_string).collect();
        cells[steer] = format!("{}", 15.0 * cells[steer].parse::<f64>().unwrap());
        wheel += &(cells.join(",") + "\n");
    }
    let x15 = dir.path().join("x15.csv");
    fs::write(&x15, wheel).unwrap();
    let said = |p: &Path| {
        let o = run_metrics(p);
        assert!(o.status.success(), "{}", stderr(&o));
        String::from_utf8_lossy(&o.stdout).into_owned() + &stderr(&o)
    };
    let w = said(&x15);
    // Round 50: in `diagnose`'s words and figure (`trips_s114_metrics50.rs`).
    assert!(
        w.contains("warning: the yaw rate is far smaller than a neutral car's for the steer even with l = 5 m, longer than any car's wheelbase (8.6× smaller, steady r·l/(u·δ) = 0.116: the yaw-rate gain 0.3870 1/s at 16.7 m/s;"),
        "{w}"
    );
    assert!(
        w.contains("or a steering-wheel angle (divide by the steering ratio)?"),
        "{w}"
    );
    assert!(!said(&run).contains("far smaller than a neutral car's"));
}

fn run_metrics(p: &Path) -> Output {
    run(&["metrics", p.to_str().unwrap()])
}

/// A second look (helper-76): the steering-wheel warning fired on a
/// linear car of 5°/g understeer at 160 km/h (ratio 0.24) and a
/// ploughing car at its limit; a simplified Magic Formula's `d = 100`
/// gave 227 kN at 4 kN; a rig's slip ratio in percent was fitted.
#[test]
fn a_second_look_at_the_gain_warning_the_peak_friction_and_a_slip_ratio_in_percent() {
    // The understeering linear car, simulated then measured.
    let front = "model = \"linear\"\ncornering_stiffness = 36000\n";
    let rear = "model = \"linear\"\ncornering_stiffness = 80000\n";
    let step = "[manoeuvre]\nkind = \"step-steer\"\nspeed = 44.4\nsteer = 0.01\n";
    let sc = format!("{VEHICLE}\n[tyres]\nfront = \"f.toml\"\nrear = \"r.toml\"\n\n{step}");
    let dir = scratch(&[("scenario.toml", &sc), ("f.toml", front), ("r.toml", rear)]);
    let out = dir.path().join("out");
    let o = simulate_in(dir.path());
    assert!(o.status.success(), "{}", stderr(&o));
    let o = run_metrics(&out.join("history.csv"));
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout).into_owned() + &stderr(&o);
    assert!(!said.contains("steering-wheel angle"), "{said}");

    // D, the peak friction, past any road's.
    let d100 = "model = \"magic-simple\"\nb = 10\nc = 1.3\nd = 100\n";
    let dir = scratch(&[
        ("m.toml", d100),
        ("p.csv", "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n"),
    ]);
    let o = tyre_eval_in(dir.path(), "m.toml");
    let e = refused(&o, &dir.path().join("e.csv"));
    assert!(e.contains("m.toml:4:5: `d` = 100"), "{e}");

    // A longitudinal rig file in percent of slip.
    let mut rig = String::from("fz,kappa,fx\n");
    for fz in [2000.0, 4000.0] {
        for k in -10..=10 {
            let kappa = 0.02 * f64::from(k);
            let fx = fz * (1.6 * (14.0 * kappa).atan()).sin();
            rig += &format!("{fz},{},{fx:.2}\n", 100.0 * kappa);
        }
    }
    let dir = scratch(&[("rig.csv", &rig)]);
    let out = dir.path().join("t.toml");
    let o = super::trips_identify::identify_with(dir.path(), "pac89", &[], &out);
    let e = refused(&o, &out);
    assert!(
        e.contains("rig.csv:2:2: column `kappa`: -20 is beyond ±1")
            && e.contains("is the column in percent? divide it by 100"),
        "{e}"
    );
}

/// Runs `tyre-eval tyre p.csv --out e.csv` in `dir`.
fn tyre_eval_in(dir: &Path, tyre: &str) -> Output {
    bin()
        .args(["tyre-eval", tyre, "p.csv", "--out", "e.csv"])
        .current_dir(dir)
        .output()
        .unwrap()
}

/// Runs `simulate dir/scenario.toml --out dir/out`.
fn simulate_in(dir: &Path) -> Output {
    let scenario = dir.join("scenario.toml");
    let out = dir.join("out");
    run(&[
        "simulate",
        scenario.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
}
