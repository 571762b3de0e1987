//! Fresh-eyes round 50 on tyres and rig data: a tyre file used far beyond
//! the loads it was fitted at is noted by `diagnose` as the same tyre
//! given as rig data is; a `.tir` fitted at one camber says so instead of
//! asking whether a correct camber is in degrees; a rig speed no rig runs
//! at (a column in mm/s) is refused, and so is such a `LONGVL`; a force at
//! zero load is said without an `inf` ratio.

use super::*;

/// The campaign of the sedan's handling programme (1530 kg: static wheel
/// loads 4507 N front, 2995 N rear) with its `[tyres]` table replaced by
/// `tyres` and its rig file removed; the files `(name, text)` written
/// beside it.
fn sedan_on(dir: &Path, name: &str, tyres: &str, files: &[(&str, &str)]) -> PathBuf {
    let c = synth_extended(
        dir,
        "handling",
        "sensor_delay",
        "1",
        "effects = [\"sensor_delay\"]\n",
    );
    let c2 = dir.join(name);
    fs::rename(&c, &c2).unwrap();
    fs::remove_file(c2.join("tyre_rig.csv")).unwrap();
    let v = c2.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    let rig = "[tyres]\nrig = \"tyre_rig.csv\"\nmodel = \"pac89\"\n";
    assert!(text.contains(rig), "{text}");
    fs::write(&v, text.replace(rig, tyres)).unwrap();
    for (file, body) in files {
        fs::write(c2.join(file), body).unwrap();
    }
    c2
}

/// The PAC89 example tyre with `[fitted_ranges] fz` = `fz` (none: `None`).
fn pac89_fitted(fz: Option<&str>) -> String {
    let tyre = fs::read_to_string(root().join("tyres/pac89_adams_example.toml")).unwrap();
    match fz {
        Some(fz) => format!("{tyre}\n[fitted_ranges]\nfz = {fz}\n"),
        None => tyre,
    }
}

/// The `tyre_loads_short` notes of a diagnosis.
fn loads_notes(d: &serde_json::Value) -> Vec<&serde_json::Value> {
    let details = d["note_details"].as_array().unwrap();
    details
        .iter()
        .filter(|n| n["kind"] == "tyre_loads_short")
        .collect()
}

/// A formula-student tyre's fitted range (414–2887 N, as `identify`
/// writes the Hoosier test's) under the sedan: `diagnose` printed only
/// `base model: given tyre files`, with `notes` empty, where the same tyre
/// given as rig data was noted. The note is on the terminal before the
/// verdict, in `notes` and on the page; a range that holds the car's loads
/// or a file that states none gets no note, and a `.tir` is judged by its
/// `FZMIN`–`FZMAX` on the axle it is on.
#[test]
fn a_tyre_file_fitted_below_the_cars_wheel_loads_is_noted_before_the_verdict() {
    let dir = tempfile::tempdir().unwrap();
    let narrow = pac89_fitted(Some("[414.2, 2887.4]"));
    let c = sedan_on(
        dir.path(),
        "narrow",
        "[tyres]\nfile = \"narrow.toml\"\n",
        &[("narrow.toml", narrow.as_str())],
    );
    let out = dir.path().join("narrow.out");
    let (stdout, d) = diagnose_to(&c, &out);
    let said = format!("note: the tyre file {} was fitted to rig data at wheel loads of 414–2887 N (its [fitted_ranges] fz) and the car's static wheel loads are 2995–4507 N (1.56× the fitted largest): the tyre is extrapolated to the car's loads, so a gap may be the tyre's rather than an unmodelled effect's, a steady one included (its force at zero slip at those loads is no fit either, and a run reads it as a sensor's zero offset)", c.join("narrow.toml").display());
    let lines: Vec<&str> = stdout.lines().collect();
    let at = |p: &str| lines.iter().position(|l| l.trim_start().starts_with(p));
    let note = at(&said).unwrap_or_else(|| panic!("{stdout}"));
    let verdict = at("verdict:").unwrap_or_else(|| panic!("{stdout}"));
    assert!(note < verdict, "{stdout}");
    // One sentence: what would settle it follows the last parenthesis
    // after a `;`, not as a second parenthesis straight after it.
    let line = lines[note].trim_start();
    assert!(
        line.ends_with("zero offset); a tyre fitted at the car's loads would tell the two apart"),
        "{line}"
    );
    assert!(!line.contains(") ("), "{line}");
    let notes = d["notes"].as_array().unwrap();
    assert!(
        notes
            .iter()
            .any(|n| n.as_str().unwrap().starts_with(&said["note: ".len()..])),
        "{notes:?}"
    );
    let tyre_notes = notes.iter().map(|n| n.as_str().unwrap());
    let mut tyre_notes = tyre_notes.filter(|n| n.starts_with("the tyre file "));
    assert!(tyre_notes.all(|n| !n.contains(") (")), "{notes:?}");
    let short = loads_notes(&d);
    assert_eq!(short.len(), 1, "{short:?}");
    assert_eq!(short[0]["of"]["kind"], "fitted");
    assert_eq!(short[0]["of"]["axles"], "both");
    assert_eq!(short[0]["loads"], serde_json::json!([414.2, 2887.4]));
    // The sedan's static wheel loads: 1530 kg on a = 1.11, b = 1.67 m.
    let g = 9.80665 * 1530.0 / 2.78 / 2.0;
    let car = &short[0]["car"];
    let near = |v: &serde_json::Value, x: f64| (v.as_f64().unwrap() - x).abs() < 1e-6 * x;
    assert!(near(&car[0], g * 1.11) && near(&car[1], g * 1.67), "{car}");
    let page = fs::read_to_string(out.join("report.html")).unwrap();
    assert!(
        page.contains(
            "(its [fitted_ranges] fz) and the car&#39;s static wheel loads are 2995–4507 N"
        ),
        "the note is not on the page"
    );
    assert!(
        page.contains(
            "zero offset); a tyre fitted at the car&#39;s loads would tell the two apart"
        ),
        "the note's end is not on the page"
    );

    // A `.tir` whose FZMAX the front's load passes, a range holding the
    // rear's load: the front alone is noted, by its FZMAX.
    let tir = fs::read_to_string(mf61_fixture()).unwrap().replace(
        "FZMAX                    =    18000",
        "FZMAX                    =    3000",
    );
    let wide = pac89_fitted(Some("[2000.0, 5000.0]"));
    let c = sedan_on(
        dir.path(),
        "axles",
        "[tyres]\nfront = \"narrow.tir\"\nrear = \"wide.toml\"\n",
        &[("wide.toml", wide.as_str()), ("narrow.tir", tir.as_str())],
    );
    let (stdout, d) = diagnose_to(&c, &dir.path().join("axles.out"));
    let short = loads_notes(&d);
    assert_eq!(short.len(), 1, "{short:?}");
    assert_eq!(short[0]["of"]["kind"], "tir");
    assert_eq!(short[0]["of"]["axles"], "front");
    assert!(stdout.contains(&format!("note: the tyre file {} states the loads it holds as FZMIN–FZMAX, up to 3000 N, and the car's static front wheel load is 4507 N (1.50× its FZMAX): its forces are held at FZMAX's there (the limit checks of its mode, 1xx), not grown with the load", c.join("narrow.tir").display())), "{stdout}");

    // A hand-written tyre states no range: judged against nothing.
    let bare = pac89_fitted(None);
    let c = sedan_on(
        dir.path(),
        "bare",
        "[tyres]\nfile = \"bare.toml\"\n",
        &[("bare.toml", bare.as_str())],
    );
    let (stdout, d) = diagnose_to(&c, &dir.path().join("bare.out"));
    assert!(loads_notes(&d).is_empty(), "{}", d["notes"]);
    assert!(!stdout.contains("wheel loads of"), "{stdout}");
}

/// The MF 6.1 fixture with `CAMMIN`/`CAMMAX` = `lo`/`hi` (rad).
fn mf61_cambers(lo: &str, hi: &str) -> String {
    fs::read_to_string(mf61_fixture())
        .unwrap()
        .replace(
            "CAMMIN                   =    -0.0873",
            &format!("CAMMIN = {lo}"),
        )
        .replace(
            "CAMMAX                   =    0.105",
            &format!("CAMMAX = {hi}"),
        )
}

/// A `.tir` fitted at camber 0 only (`identify` writes the rig rows'
/// −0.00036 to 0.00045 rad) asked of a point at a correct 0.02 rad "is the
/// column in degrees?" (0.02° lies inside that range). A range under 1°
/// is said as one camber, with no unit asked; points at its camber leave
/// no range.
#[test]
fn a_tir_fitted_at_one_camber_says_so_and_asks_no_unit() {
    let tir = mf61_cambers("-0.00036", "0.00045");
    let dir = scratch(&[
        ("one.tir", tir.as_str()),
        (
            "cam2.csv",
            "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n4000,0,0.05,0.02,16.7\n",
        ),
        (
            "flat.csv",
            "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n4000,0,0.08,0.0003,16.7\n",
        ),
    ]);
    let o = run_in(
        dir.path(),
        &["tyre-eval", "one.tir", "cam2.csv", "--out", "o.csv"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    let line = err
        .lines()
        .find(|l| l.contains("CAMMAX"))
        .unwrap_or_else(|| panic!("{err}"));
    assert!(line.contains("1 of 2 points above CAMMAX = 0.00036 rad, in the points' frame (the file's range -0.00045 to 0.00036): evaluated at that end; the first at line 3, camber = 0.02 rad given, evaluated at 0.00036 rad; the tyre was fitted at camber 0 only (CAMMIN to CAMMAX, -0.00045 to 0.00036 rad, a range under 1°): its camber terms describe no other camber, in any unit"), "{line}");
    assert!(!err.contains("is the column in degrees?"), "{err}");
    // The book's example points ask no unit of this file either.
    let book = root().join("docs/examples/tyre_points.csv");
    let o = run_in(
        dir.path(),
        &[
            "tyre-eval",
            "one.tir",
            book.to_str().unwrap(),
            "--out",
            "b.csv",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("the tyre was fitted at camber 0 only"),
        "{err}"
    );
    assert!(!err.contains("is the column in degrees?"), "{err}");
    // Points within the range: no camber warning at all.
    let o = run_in(
        dir.path(),
        &["tyre-eval", "one.tir", "flat.csv", "--out", "f.csv"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("CAMMAX"), "{}", stderr(&o));
}

/// A range one degree wide or more still asks a column of small degrees
/// (0.5 and 0.3, meant as degrees) about its unit; a range of 0.86° does
/// not, and says the one camber it is centred on where it holds no 0 (the
/// fixture is a right tyre: its cambers negated in the points' frame).
#[test]
fn the_degrees_question_needs_a_camber_range_of_a_degree() {
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n4000,0,0.05,0.5,16.7\n4000,0,0.05,0.3,16.7\n";
    // 1.15° wide (−0.01 to 0.01 rad) and 0.86° wide, off 0 (0.0275 to 0.0425 rad).
    let (wide, off) = (
        mf61_cambers("-0.01", "0.01"),
        mf61_cambers("0.0275", "0.0425"),
    );
    let dir = scratch(&[
        ("wide.tir", wide.as_str()),
        ("off.tir", off.as_str()),
        ("deg.csv", points),
    ]);
    let said = |tir: &str| {
        let o = run_in(dir.path(), &["tyre-eval", tir, "deg.csv", "--out", "o.csv"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let _ = fs::remove_file(dir.path().join("o.csv"));
        let err = stderr(&o);
        err.lines()
            .find(|l| l.contains("above CAMMAX"))
            .unwrap_or_else(|| panic!("{err}"))
            .to_string()
    };
    let wide = said("wide.tir");
    assert!(wide.contains("is the column in degrees?"), "{wide}");
    let off = said("off.tir");
    assert!(!off.contains("is the column in degrees?"), "{off}");
    assert!(
        off.contains("; the tyre was fitted at camber -0.035 rad (-2.01°) only (CAMMIN to CAMMAX, -0.0425 to -0.0275 rad, a range under 1°)"),
        "{off}"
    );
}

/// The book's grid evaluated by the MF 6.1 fixture, as a rig writes it,
/// with its `speed` column mapped by `f`: the rig file's path.
fn grid_rig_speed(dir: &Path, f: impl Fn(f64) -> f64) -> PathBuf {
    let rig = grid_rig(&mf61_fixture(), dir);
    map_column(&rig, "speed", f);
    rig
}

/// A rig file whose speed is in mm/s (16.7 m/s written 16700) was fitted
/// and its median written as `LONGVL = 16700` m/s (60120 km/h): it is
/// refused at its first row beyond 150 m/s, the limit `metrics` holds a
/// run's speed to, with the unit its median reads in; a speed in km/h of
/// a fast rig (200 km/h) is asked as such, and the same file in m/s fits.
#[test]
fn a_rig_speed_beyond_any_rigs_is_refused_at_its_first_row_with_its_unit() {
    let dir = tempfile::tempdir().unwrap();
    let rig = grid_rig_speed(dir.path(), |v| v * 1000.0);
    let head = fs::read_to_string(&rig).unwrap();
    let col = 1 + head
        .lines()
        .next()
        .unwrap()
        .split(',')
        .position(|c| c == "speed")
        .unwrap();
    let rows = head.lines().count() - 1;
    let out = dir.path().join("mm.toml");
    let err = refused(&identify_to(&rig, "linear", &out), &out);
    assert!(err.contains(&format!("grid_rig.csv:2:{col}: column `speed`: 16700 m/s is beyond 150 m/s (540 km/h), which no tyre rig or car runs at ({rows} rows of the file beyond it; the column's median is 16700): `speed` is the wheel's forward speed in m/s (FORMATS.md); is the column in mm/s? read so, its median is 16.7 m/s, a rig's speed: divide it by 1000")), "{err}");

    let dir = tempfile::tempdir().unwrap();
    let rig = grid_rig_speed(dir.path(), |_| 200.0);
    let out = dir.path().join("kmh.toml");
    let err = refused(&identify_to(&rig, "linear", &out), &out);
    assert!(
        err.contains("column `speed`: 200 m/s is beyond 150 m/s"),
        "{err}"
    );
    assert!(err.contains("is the column in km/h (or mph, ÷ 2.237)? read so, its median is 55.6 m/s, a rig's speed: divide it by 3.6"), "{err}");

    let dir = tempfile::tempdir().unwrap();
    let rig = grid_rig_speed(dir.path(), |v| v);
    let out = dir.path().join("ok.toml");
    let o = identify_to(&rig, "linear", &out);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// A `.tir` whose `LONGVL` no rig runs at (the 11169.9 a fit to a rig file
/// in mm/s wrote) was read silently by `tyre-eval`: refused at its line
/// with the limit; the fixture's 16.6 m/s and 150 m/s itself are read.
#[test]
fn a_tir_reference_speed_beyond_any_rigs_is_refused_at_its_line() {
    let fixture = fs::read_to_string(mf61_fixture()).unwrap();
    let was = "LONGVL                   =    16.6";
    assert!(fixture.contains(was));
    let line = 1 + fixture.lines().position(|l| l.starts_with(was)).unwrap();
    let points = "fz,kappa,alpha,camber,speed\n4000,0,0.05,0,16.7\n";
    let mm = fixture.replace(was, "LONGVL = 11169.9");
    let top = fixture.replace(was, "LONGVL = 150");
    let dir = scratch(&[
        ("mm.tir", mm.as_str()),
        ("top.tir", top.as_str()),
        ("p.csv", points),
    ]);
    let o = run_in(
        dir.path(),
        &["tyre-eval", "mm.tir", "p.csv", "--out", "mm.csv"],
    );
    let err = refused(&o, &dir.path().join("mm.csv"));
    assert!(err.contains(&format!("mm.tir:{line}")), "{err}");
    assert!(err.contains("LONGVL"), "{err}");
    assert!(err.contains("11169.9"), "{err}");
    assert!(err.contains("no tyre rig or car runs beyond 150 m/s (540 km/h), the limit a rig file's and a run's speed keep to: is it in km/h (÷ 3.6) or mm/s (÷ 1000)?"), "{err}");
    let o = run_in(
        dir.path(),
        &["tyre-eval", "top.tir", "p.csv", "--out", "t.csv"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
}

/// A rig row at zero load with a lateral force was said "-558.23 N at fz
/// 0 N is inf times the load": at zero load it is said as a force where a
/// tyre carries none, with no ratio; a light load keeps its ratio.
#[test]
fn a_rig_force_at_zero_load_is_said_without_a_ratio() {
    let dir = tempfile::tempdir().unwrap();
    let rig = grid_rig(&mf61_fixture(), dir.path());
    let text = fs::read_to_string(&rig).unwrap();
    let head: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let k = |name: &str| head.iter().position(|c| *c == name).unwrap();
    let (fz, fy, kappa) = (k("fz"), k("fy"), k("kappa"));
    // The pure-slip row with the largest |fy|: its load set to 0, and
    // another's to 1 N.
    let rows: Vec<Vec<String>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    let num = |r: &Vec<String>, i: usize| r[i].parse::<f64>().unwrap();
    let pure: Vec<usize> = (0..rows.len())
        .filter(|&i| num(&rows[i], kappa) == 0.0)
        .collect();
    let by_fy =
        |&a: &usize, &b: &usize| num(&rows[a], fy).abs().total_cmp(&num(&rows[b], fy).abs());
    let top = pure.iter().copied().max_by(by_fy).unwrap();
    assert!(num(&rows[top], fy) < 0.0, "{:?}", rows[top]);
    let mut zeroed = rows.clone();
    zeroed[top][fz] = "0".to_string();
    let write = |rows: &[Vec<String>], name: &str| {
        let body: Vec<String> = rows.iter().map(|r| r.join(",")).collect();
        written(
            dir.path(),
            name,
            &format!("{}\n{}\n", head.join(","), body.join("\n")),
        )
    };
    let zero = write(&zeroed, "zero.csv");
    let out = dir.path().join("zero.toml");
    let err = refused(&identify_to(&zero, "linear", &out), &out);
    // The force as the error writes it (6 significant digits) is not the
    // cell's text: the row is found by its place, the words after it.
    let at = format!("zero.csv:{}:{}: column `fy`: -", top + 2, fy + 1);
    let line = err
        .lines()
        .find(|l| l.contains(&at))
        .unwrap_or_else(|| panic!("{err}"));
    assert!(line.contains(" N at fz 0 N is a force at zero load, and a tyre carries none off the road: the wheel lifted off the rig's belt or drum (a row logged outside the test?), or is `fz` in another sign or unit? (the limit there is 5 × (fz + a twentieth of the file's median load"), "{line}");
    assert!(!err.contains("inf times"), "{err}");
    let mut light = rows;
    light[top][fz] = "1".to_string();
    let one = write(&light, "one.csv");
    let out = dir.path().join("one.toml");
    let err = refused(&identify_to(&one, "linear", &out), &out);
    let at = format!("one.csv:{}:{}: column `fy`: -", top + 2, fy + 1);
    let line = err
        .lines()
        .find(|l| l.contains(&at))
        .unwrap_or_else(|| panic!("{err}"));
    assert!(line.contains(" N at fz 1 N is "), "{line}");
    assert!(
        line.contains(" times the load, which no tyre grips at"),
        "{line}"
    );
}
