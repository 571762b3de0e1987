//! What a fresh user tripped on in `identify` and in campaign and scenario
//! files (round 12): a road without grip in a campaign asked whether it
//! was a speed, a per-axle array of three numbers (or a decimal comma's
//! four) run on its first two, the unfitted `mz` counted over the whole
//! file under a selection, a decay at its physical limit 0 called a
//! failed fit, a slip angle column in degrees fitted without a word, and
//! a staged fit's pooled σ led by rows no stage fits.

use super::*;

/// A campaign with a linear tyre, an empty runs folder and `road`.
fn campaign_with_road(road: &str) -> tempfile::TempDir {
    let text = format!(
        "name = \"c\"\n{VEHICLE}[tyres]\nfront = \"tyre.toml\"\n[runs]\ndir = \"runs\"\n[road]\n{road}\n"
    );
    let dir = scratch(&[("c.toml", &text)]);
    linear_tyre(dir.path());
    fs::create_dir(dir.path().join("runs")).unwrap();
    dir
}

/// `[road] friction = 0` in a campaign was asked "is it a speed or a
/// percentage?" (the range's top's hint); a scenario already said "must
/// be positive".
#[test]
fn a_campaign_road_without_grip_is_said_not_positive() {
    let dir = campaign_with_road("friction = 0");
    let e = fails_cleanly("diagnose", &dir.path().join("c.toml"), dir.path());
    assert!(
        e.contains("c.toml:15:12: `road.friction` = 0: must be positive"),
        "{e}"
    );
    assert!(!e.contains("a speed or a percentage"), "{e}");
}

/// `aero_load = [0.5, 0.6, 0.7]` ran as `[0.5, 0.6]`, and a decimal
/// comma's `[0,5, 0,6]` as `[0, 5]`: a per-axle key takes exactly two.
#[test]
fn a_per_axle_effect_of_other_than_two_numbers_is_refused_at_its_key() {
    for (value, found) in [("[0.5, 0.6, 0.7]", 3), ("[0,5, 0,6]", 4)] {
        let effects = format!("[model.effects]\naero_load = {value}\n\n{STEP}");
        let dir = scenario(VEHICLE, GIM, &effects);
        let e = simulate_err(dir.path());
        assert!(
            e.contains(&format!(
                "scenario.toml:14:13: `model.effects.aero_load`: invalid length {found}, expected an array of length 2 (front, rear); decimals take a point: [0,5, 0,6] is four numbers, [0.5, 0.6] two"
            )),
            "{value}: {e}"
        );
    }
    // Two are read as before.
    let dir = scenario(
        VEHICLE,
        GIM,
        &format!("[model.effects]\nroll_steer = [0.1, 0.0]\n\n{STEP}"),
    );
    let o = run_in(dir.path(), &["simulate", "scenario.toml", "--out", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// A magic-simple fit of the Hoosier file at one pressure and camber said
/// "59965 values of `mz` not fitted", the whole file's, though 7,494
/// rows were selected.
#[test]
fn the_unfitted_mz_is_counted_over_the_rows_selected() {
    let test = "the_unfitted_mz_is_counted_over_the_rows_selected";
    let Some(rig) = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv") else {
        return;
    };
    let dir = scratch(&[]);
    let out = dir.path().join("ms.toml");
    let said = succeeds(&[
        "identify",
        rig.to_str().unwrap(),
        "--model",
        "magic-simple",
        "--pressure",
        "83000",
        "--camber",
        "0",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(
        said.contains("59965 samples: 7494 used in conditions"),
        "{said}"
    );
    assert!(
        said.contains("the magic-simple model has no aligning moment: 7494 values of `mz` in the rows selected (of 59965 in the file) not fitted"),
        "{said}"
    );
}

/// Rig data `fz, alpha, fy` of `tyre` (a TOML tyre file's text), as
/// `tyre-eval` gives them at 2, 4 and 6 kN, |alpha| to 0.3 rad.
fn rig_of(dir: &Path, tyre: &str) -> PathBuf {
    fs::write(dir.join("truth.toml"), tyre).unwrap();
    let mut points = String::from("fz,kappa,alpha,camber,speed\n");
    for fz in [2000, 4000, 6000] {
        for i in -60..=60 {
            points += &format!("{fz},0,{:.4},0,10\n", f64::from(i) * 0.005);
        }
    }
    fs::write(dir.join("points.csv"), points).unwrap();
    let o = run_in(
        dir,
        &["tyre-eval", "truth.toml", "points.csv", "--out", "eval.csv"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let eval = fs::read_to_string(dir.join("eval.csv")).unwrap();
    let header: Vec<&str> = eval.lines().next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (fz, alpha, fy) = (col("fz"), col("alpha"), col("fy"));
    let mut rig = String::from("fz,alpha,fy\n");
    for line in eval.lines().skip(1) {
        let c: Vec<&str> = line.split(',').collect();
        rig += &format!("{},{},{}\n", c[fz], c[alpha], c[fy]);
    }
    let path = dir.join("rig.csv");
    fs::write(&path, rig).unwrap();
    path
}

/// A GIM fit of its own constant-friction, load-independent tyre put
/// `friction_decay` at 1.2e-17 and `load_exponent` at 3.5e-18, said "on
/// its search bound … not a fit" (0 is where no tyre goes below, and the
/// data do not pull it there), and wrote them `0.0000000000000000122…`.
#[test]
fn a_gim_decay_at_zero_on_exact_data_is_at_its_physical_limit_and_written_in_scientific() {
    let dir = scratch(&[]);
    let rig = rig_of(
        dir.path(),
        "model = \"gim\"\ncornering_stiffness = 80000.0\ncontact_length = 0.2\nfriction = 1.2\n",
    );
    let out = dir.path().join("fit.toml");
    let o = identify_to(&rig, "gim", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    assert!(
        said.contains("  friction_decay = 1.221e-17: at its physical limit 0 (a smaller decay is a friction that rises with slip): the data fit best there and do not pull it past; a fit, not a search stopped"),
        "{said}"
    );
    assert!(
        said.contains("  load_exponent = 3.532e-18: at its physical limit 0 (a smaller exponent is a stiffness that falls with load, infinite at none)"),
        "{said}"
    );
    assert!(!said.contains("search bound"), "{said}");
    let text = fs::read_to_string(&out).unwrap();
    assert!(
        text.contains("\nfriction_decay = 1.2209966040030408e-17\n"),
        "{text}"
    );
    assert!(
        text.contains("\nload_exponent = 3.531780870132351e-18\n"),
        "{text}"
    );
    assert!(!text.contains("0.0000000"), "{text}");
    // Not a warning: the report's parameters carry it as a note.
    let report = read_json(&out.with_extension("report.json"));
    let decay = report["parameters"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["name"] == "friction_decay")
        .unwrap();
    assert!(decay["warning"].is_null(), "{decay}");
    assert!(
        decay["note"]
            .as_str()
            .unwrap()
            .starts_with("at its physical limit 0"),
        "{decay}"
    );
}

/// A rig file `fz, alpha, fy` of a tyre of 20 N/rad per N of load: loads
/// 1 and 2 kN swept finely (0.01 steps), 3 and 4 kN coarsely (`coarse`
/// steps, none but 0 inside a linear fit's ±2° window); `alpha` written
/// in degrees when `degrees`.
fn two_sweeps(degrees: bool, coarse: f64) -> String {
    sweeps_of(degrees, coarse, |fz, alpha| 20.0 * fz * alpha)
}

/// [`two_sweeps`]' rows with the force `fy(fz, alpha)`.
fn sweeps_of(degrees: bool, coarse: f64, fy: impl Fn(f64, f64) -> f64) -> String {
    let mut s = String::from("fz,alpha,fy\n");
    for (fz, step, n) in [
        (1000.0, 0.01, 10),
        (2000.0, 0.01, 10),
        (3000.0, coarse, 2),
        (4000.0, coarse, 2),
    ] {
        for i in -n..=n {
            let written: f64 = f64::from(i) * step;
            let alpha = if degrees {
                written.to_radians()
            } else {
                written
            };
            s += &format!("{fz},{written:.4},{:.3}\n", fy(fz, alpha));
        }
    }
    s
}

/// Slip angles written in degrees (to ±1.5, inside the reader's ±90°)
/// were fitted by `--model linear` to 1000 N/rad, on its search bound,
/// without a word on the unit (`tyre-eval` later asked whether the
/// stiffness was in N/deg): refused, the column named and asked whether
/// it is in degrees.
#[test]
fn a_linear_fit_to_slip_angles_in_degrees_asks_whether_the_column_is_in_degrees() {
    let dir = scratch(&[("deg.csv", &two_sweeps(true, 0.75))]);
    let out = dir.path().join("fit.toml");
    let o = identify_to(&dir.path().join("deg.csv"), "linear", &out);
    let e = refused(&o, &out);
    assert!(
        // (Since session 88 the rig reader refuses the column, for every
        // model, before any fit: trips_s88_idn.)
        e.contains("deg.csv:53:2: column `alpha`: 1.5 here, the sweep's largest |alpha|, is 86° read in radians, beyond the ±0.35 rad (20°) a rig sweeps, and read in radians the slope of fy/fz against alpha over its 16 samples with |alpha| ≤ 0.035 is 0.349 1/rad (N/rad per N of load), below any tyre's 1.5 (a car tyre's is about 5–45); read in degrees the slope is 20.0 1/rad, a tyre's: angles are in radians (FORMATS.md); is the column in degrees? Convert it (multiply by 0.01745)"),
        "{e}"
    );
    // The same tyre in radians is fitted, its stiffness per unit load
    // a tyre's.
    let dir = scratch(&[("rad.csv", &two_sweeps(false, 0.05))]);
    let out = dir.path().join("fit.toml");
    let o = identify_to(&dir.path().join("rad.csv"), "linear", &out);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// Two of a file's four loads had no two points inside a linear fit's
/// window and vanished from the fit without a word: the window's line
/// counts them, with their loads.
#[test]
fn a_linear_fit_says_the_loads_its_window_leaves_without_points() {
    // A force that saturates (a linear one needs no window, trips_s87_idn).
    let saturating = sweeps_of(false, 0.05, |fz, alpha| fz * (20.0 * alpha).tanh());
    let dir = scratch(&[("rad.csv", &saturating)]);
    let out = dir.path().join("fit.toml");
    let o = identify_to(&dir.path().join("rad.csv"), "linear", &out);
    assert!(o.status.success(), "{}", stderr(&o));
    let said = String::from_utf8_lossy(&o.stdout);
    let line = "linear window: fitted to |alpha| <= 2 deg only (14 points; 38 points with larger |alpha| left out, where the force saturates: in 2 of the 2 conditions judged they depart from the window's line by up to 38 % RMS, beyond its noise; 2 conditions with fewer than two points in it left out, at Fz 3000, 4000 N)";
    assert!(said.contains(&format!("  {line}\n")), "{said}");
    let text = fs::read_to_string(&out).unwrap();
    assert!(text.contains(&format!("# {line}\n")), "{text}");
}
