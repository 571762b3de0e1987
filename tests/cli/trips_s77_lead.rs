//! What a new user tripped on, mended: a schedule's braking reaches the
//! longitudinal effects.

use super::*;

/// A sedan scenario braking from 25 to 15 m/s over 1.2–4 s in a steady
/// turn, with the longitudinal load transfer `share` (scenario text).
fn braking_schedule(share: f64) -> String {
    let tyres = root().join("tyres");
    format!(
        r#"name = "brake"
[vehicle]
mass = 1530.0
yaw_inertia = 2315.0
a = 1.11
b = 1.67
track_front = 1.55
track_rear = 1.55
cg_height = 0.55
[tyres]
front = "{}"
rear = "{}"
[model.effects]
longitudinal_load_transfer = {share}
[manoeuvre]
kind = "schedule"
t = [0.0, 1.0, 1.2, 4.0, 6.0]
steer = [0.0, 0.0, 0.03, 0.03, 0.03]
speed = [25.0, 25.0, 25.0, 15.0, 15.0]
"#,
        tyres.join("gim_sedan_front.toml").display(),
        tyres.join("gim_sedan_rear.toml").display()
    )
}

/// The history's row at time `t` as (column, value) pairs.
fn row_at(history: &Path, t: f64) -> Vec<(String, f64)> {
    let text = fs::read_to_string(history).unwrap();
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    let row = lines
        .map(|l| {
            l.split(',')
                .map(|v| v.parse::<f64>().unwrap())
                .collect::<Vec<_>>()
        })
        .min_by(|a, b| (a[0] - t).abs().total_cmp(&(b[0] - t).abs()))
        .unwrap();
    header.into_iter().zip(row).collect()
}

/// A schedule's speed is linear between its breakpoints, five of them
/// over 6 s here: the adaptive integrator read a smoothed derivative of
/// them, a window holding one breakpoint, so du/dt was zero and the load
/// transfer of a 3.6 m/s² braking never reached the axles (the same rows
/// with the effect at 0 and at 1).
#[test]
fn a_schedules_braking_transfers_load_to_the_front_axle() {
    let dir = tempfile::tempdir().unwrap();
    let mut front = Vec::new();
    for share in [0.0, 1.0] {
        let name = format!("s{share}.toml");
        fs::write(dir.path().join(&name), braking_schedule(share)).unwrap();
        let out = format!("out{share}");
        let o = run_in(dir.path(), &["simulate", &name, "--out", &out]);
        assert!(o.status.success(), "{}", stderr(&o));
        let row = row_at(&dir.path().join(&out).join("history.csv"), 2.0);
        let get = |k: &str| row.iter().find(|(c, _)| c == k).unwrap().1;
        front.push(get("fz_fl") + get("fz_fr"));
    }
    // m·ax·h/l: 1530 kg × (10/2.8) m/s² × 0.55 m / 2.78 m = 1081 N.
    let rigid = 1530.0 * (10.0 / 2.8) * 0.55 / 2.78;
    let moved = front[1] - front[0];
    assert!(
        (moved - rigid).abs() < 0.01 * rigid,
        "front axle load {:.1} N with the effect, {:.1} N without: moved {moved:.1} N, rigid transfer {rigid:.1} N",
        front[1],
        front[0]
    );
}

/// `effects = ["bank_profile"]` on runs with no `bank` channel left no
/// candidate, and the diagnosis still ran the base and called the gap
/// "outside the library: no candidate was scored" (fresh-eyes round 5).
#[test]
fn a_campaign_whose_named_candidates_no_run_can_show_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let camp = synth_campaign(dir.path(), "camp", &["--seed", "1"]);
    let path = camp.join("vehicle.toml");
    let text = fs::read_to_string(&path).unwrap();
    let named = text.replace(
        "[diagnose]\n",
        "[diagnose]\neffects = [\"bank_profile\", \"longitudinal_load_transfer\"]\n",
    );
    assert_ne!(named, text);
    fs::write(&path, named).unwrap();
    let o = run(&[
        "diagnose",
        camp.to_str().unwrap(),
        "--out",
        dir.path().join("d").to_str().unwrap(),
    ]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains(&format!("{}: none of the candidate effects its `[diagnose] effects` names can show in its runs: bank_profile: no run has a bank channel; longitudinal_load_transfer: no run has a longitudinal acceleration above 0.5 m/s²", camp.display())),
        "{e}"
    );
    assert!(!dir.path().join("d").join("diagnosis.json").exists());
}

/// `run` of `camp` with its `steer` column mapped by `f`.
fn edit_steer(camp: &Path, run: &str, f: impl Fn(f64) -> f64) {
    let path = camp.join("runs").join(run);
    let text = fs::read_to_string(&path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let col = header.split(',').position(|c| c == "steer").unwrap();
    let mut out = format!("{header}\n");
    for l in lines {
        let mut cells: Vec<String> = l.split(',').map(String::from).collect();
        cells[col] = format!("{}", f(cells[col].parse::<f64>().unwrap()));
        out.push_str(&cells.join(","));
        out.push('\n');
    }
    fs::write(&path, out).unwrap();
}

/// The ISO 7401 step at 100 km/h and 2 m/s² steers 0.008 rad: below the
/// 0.01 rad from which a run's steer was judged against its yaw rate, so
/// its steer negated (another sign convention) or divided by 57 was
/// diagnosed as physics, "outside the library" (fresh-eyes round 5).
#[test]
fn a_gentle_steps_steer_in_another_sign_or_unit_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    for (name, f, says) in [
        (
            "flip",
            (|d: f64| -d) as fn(f64) -> f64,
            "the yaw rate turns against the steer",
        ),
        (
            "div57",
            |d: f64| d / 57.3,
            "× a neutral car's for this steer",
        ),
    ] {
        let camp = synth_campaign(dir.path(), name, &["--seed", "1"]);
        edit_steer(&camp, "step_100kph_2ms2.csv", f);
        let o = run(&[
            "diagnose",
            camp.to_str().unwrap(),
            "--out",
            dir.path().join(format!("d{name}")).to_str().unwrap(),
        ]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{name}: {e}");
        assert!(
            e.contains("step_100kph_2ms2.csv") && e.contains(says),
            "{name}: {e}"
        );
    }
}

/// A steer logged as 0 throughout while the yaw rate steps to 0.12 rad/s
/// was replayed straight and diagnosed, where a dead yaw rate is refused
/// (fresh-eyes round 5).
#[test]
fn a_dead_steer_under_a_turning_car_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let camp = synth_campaign(dir.path(), "camp", &["--seed", "1"]);
    edit_steer(&camp, "step_060kph_2ms2.csv", |_| 0.0);
    let o = run(&[
        "diagnose",
        camp.to_str().unwrap(),
        "--out",
        dir.path().join("d").to_str().unwrap(),
    ]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains("step_060kph_2ms2.csv")
            && e.contains("channel `steer` holds one value (0) over the whole run while the yaw rate turns the car")
            && e.contains("a replay of it drives straight"),
        "{e}"
    );
}

/// Effect values no car has ran without a word: down-force of 5000 N per
/// (m/s)² put 1.24 MN on a wheel, a roll gradient of 4 (4°/g typed in rad
/// per m/s²) rolled the body 915°, a load-transfer share of 5 passed
/// (fresh-eyes round 5). Each is refused at its line with the plausible
/// range and the unit.
#[test]
fn effect_values_no_car_has_are_refused_at_their_key() {
    let dir = tempfile::tempdir().unwrap();
    let base = braking_schedule(1.0);
    for (name, from, to, key, says) in [
        (
            "aero",
            "longitudinal_load_transfer = 1\n",
            "aero_load = [5000.0, 5000.0]\n",
            "aero_load[0]",
            "Formula 1",
        ),
        (
            "roll",
            "longitudinal_load_transfer = 1\n",
            "roll_steer = [0.1, 0.0]\n[model.effects.roll]\ngradient = 4.0\n",
            "gradient",
            "4°/g is 0.0071",
        ),
        (
            "share",
            "longitudinal_load_transfer = 1\n",
            "longitudinal_load_transfer = 5.0\n",
            "longitudinal_load_transfer",
            "rigid body's transfer",
        ),
    ] {
        let text = base.replace(from, to);
        assert_ne!(text, base, "{name}");
        let file = format!("{name}.toml");
        fs::write(dir.path().join(&file), &text).unwrap();
        let o = run_in(dir.path(), &["simulate", &file, "--out", name]);
        let e = stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{name}: {e}");
        let line = text
            .lines()
            .position(|l| l.starts_with(key.split('[').next().unwrap()))
            .unwrap()
            + 1;
        assert!(
            e.contains(&format!("{file}:{line}:")) && e.contains(key) && e.contains(says),
            "{name}: line {line}: {e}"
        );
    }
}

/// FORMATS.md: the `[vehicle]` table "accepts these keys (more are
/// allowed, e.g. roll stiffness, steering ratio)". A vehicle file with a
/// roll stiffness was refused as `unknown field` by `simulate` and
/// `diagnose` (fresh-eyes round 5). Such a key is set aside and said, with
/// its line; a slip of a key the tool reads is still refused with the key
/// meant.
#[test]
fn a_vehicle_key_formats_allows_is_set_aside_and_said_and_a_slip_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let text = braking_schedule(1.0).replace(
        "cg_height = 0.55\n",
        "cg_height = 0.55\nroll_stiffness = 80000.0\ndriver = \"test\"\n",
    );
    fs::write(dir.path().join("extra.toml"), &text).unwrap();
    let o = run_in(dir.path(), &["simulate", "extra.toml", "--out", "extra"]);
    let (out, e) = (String::from_utf8_lossy(&o.stdout).to_string(), stderr(&o));
    assert!(o.status.success(), "{e}");
    let said = format!("{out}{e}");
    for (key, line) in [("roll_stiffness", 10), ("driver", 11)] {
        assert!(
            said.contains(&format!("extra.toml:{line}: [vehicle] `{key}` is no key this tool reads (FORMATS.md allows more): set aside, not used")),
            "{said}"
        );
    }
    // A campaign says it among its notes.
    let camp = synth_campaign(dir.path(), "camp", &["--seed", "1"]);
    let path = camp.join("vehicle.toml");
    let v = fs::read_to_string(&path).unwrap();
    let v = v
        .replace(
            "cg_height = 0.55\n",
            "cg_height = 0.55\nroll_stiffness = 80000.0\n",
        )
        .replace("[diagnose]\n", "[diagnose]\neffects = [\"sensor_delay\"]\n");
    fs::write(&path, &v).unwrap();
    let line = v
        .lines()
        .position(|l| l.starts_with("roll_stiffness"))
        .unwrap()
        + 1;
    let o = run(&[
        "diagnose",
        camp.to_str().unwrap(),
        "--out",
        dir.path().join("d").to_str().unwrap(),
    ]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    let json = fs::read_to_string(dir.path().join("d").join("diagnosis.json")).unwrap();
    assert!(
        json.contains(&format!(
            "vehicle.toml:{line}: [vehicle] `roll_stiffness` is no key this tool reads"
        )),
        "{json}"
    );
    // A slip stays an error at its line, with the key meant.
    let slip = braking_schedule(1.0).replace("cg_height = 0.55\n", "cg_heigth = 0.55\n");
    fs::write(dir.path().join("slip.toml"), &slip).unwrap();
    let o = run_in(dir.path(), &["simulate", "slip.toml", "--out", "slip"]);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains("slip.toml:9:") && e.contains("cg_heigth") && e.contains("cg_height"),
        "{e}"
    );
}

/// `[metrics] filter_hz = 3` in a step-steer scenario moved E_r from 0.0495
/// to 0.0393 s without a word, where `metrics` on the same history warns
/// that the filter measures itself (fresh-eyes round 5).
#[test]
fn simulate_warns_of_a_low_pass_slow_enough_to_measure_itself() {
    let dir = tempfile::tempdir().unwrap();
    let scenario = fs::read_to_string(root().join("scenarios/step_gbt6323_pac89.toml"))
        .unwrap()
        .replace(
            "\"../tyres/pac89_adams_example.toml\"",
            &format!(
                "\"{}\"",
                root().join("tyres/pac89_adams_example.toml").display()
            ),
        );
    for (hz, warned) in [(3.0, true), (20.0, false)] {
        let file = format!("f{hz}.toml");
        fs::write(
            dir.path().join(&file),
            format!("{scenario}\n[metrics]\nfilter_hz = {hz:.1}\n"),
        )
        .unwrap();
        let o = run_in(dir.path(), &["simulate", &file, "--out", &format!("o{hz}")]);
        let said = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
        assert!(o.status.success(), "{said}");
        let says = said.contains(&format!("the low-pass at {hz} Hz rises (10–90 %) in"));
        assert_eq!(says, warned, "{hz} Hz: {said}");
    }
}

/// A campaign on a truck's `.tir` (FNOMIN 30 kN under a 1530 kg sedan)
/// was diagnosed as "outside the library" without the word `simulate`
/// says of the same file (fresh-eyes round 5): the campaign's notes now
/// say it.
#[test]
fn a_campaign_on_a_tyre_for_another_class_of_vehicle_says_so() {
    let test = "a_campaign_on_a_tyre_for_another_class_of_vehicle_says_so";
    let Some(tir) = shared_data(test, "tir_public/Truck_430_50R38.tir") else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let camp = synth_campaign(dir.path(), "camp", &["--seed", "1"]);
    let path = camp.join("vehicle.toml");
    let v = fs::read_to_string(&path).unwrap();
    let given = v
        .replace(
            "rig = \"tyre_rig.csv\"\nmodel = \"pac89\"\n",
            &format!("file = \"{}\"\n", tir.display()),
        )
        .replace("[diagnose]\n", "[diagnose]\neffects = [\"sensor_delay\"]\n");
    assert!(given.contains("Truck_430"), "{given}");
    fs::write(&path, given).unwrap();
    let out = dir.path().join("d");
    let o = run(&[
        "diagnose",
        camp.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let e = stderr(&o);
    assert!(o.status.success(), "{e}");
    let json = fs::read_to_string(out.join("diagnosis.json")).unwrap();
    assert!(
        json.contains("the front tyres' .tir: its wheels carry 4507 N each standing still, 0.15 times the file's FNOMIN = 30000 N")
            && json.contains("the rear tyres' .tir: its wheels carry 2995 N")
            && json.contains("a tyre for another class of vehicle"),
        "{json}"
    );
}
