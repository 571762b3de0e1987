//! What a fresh-eyes user still tripped on, run as a user runs the tool:
//! `design` offering, on a road course, manoeuvres whose expected
//! separation lies within their own uncertainty and below the campaign's
//! as tests to drive, without a word on the test the diagnosis advised;
//! `identify` giving a σ to a channel it did not fit and `NaN %` to one
//! measured 0 throughout; `metrics` printing a noise of none as
//! `0.00 %`. Each test one finding.

use super::*;
use crate::trips_s62::rig;

/// The road course with a steering compliance withheld: the diagnosis
/// confounds it with a stiffness scale and the roll effects, and its runs
/// separate them by more than any manoeuvre of the family is expected to.
/// `design` ranked sweeps of `1.2 ± 2.5` as the tests to drive; it now
/// says each is not recommended, that none is worth driving because the
/// campaign already separates them by more, and where the steady turns
/// and steps the diagnosis advises rank.
#[test]
fn design_recommends_no_manoeuvre_within_its_uncertainty_and_ranks_the_diagnosiss_advice() {
    let dir = tempfile::tempdir().unwrap();
    let c = synth_campaign(
        dir.path(),
        "c",
        &[
            "--programme",
            "road-course",
            "--effects",
            "steering_compliance",
            "--seed",
            "1",
        ],
    );
    // The pair the full library confounds here, fitted alone: the design
    // reads only the candidates of the confounded set.
    let vehicle = c.join("vehicle.toml");
    let text = fs::read_to_string(&vehicle).unwrap();
    let pair = "effects = [\"steering_compliance\", \"cornering_stiffness\"]\n";
    fs::write(&vehicle, format!("{text}{pair}")).unwrap();
    let d = dir.path().join("d");
    let (_, diagnosis) = diagnose_to(&c, &d);
    let confounded = diagnosis["confounded"][0]["effects"].to_string();
    assert!(
        confounded.contains("steering_compliance") && confounded.contains("cornering_stiffness"),
        "{confounded}"
    );
    let o = run(&["design", d.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    let report = read_json(&d.join("design/design.json"));
    let set = &report["sets"][0];
    let campaign = set["campaign_separation"].as_f64().unwrap();
    for (k, s) in set["ranked"].as_array().unwrap().iter().enumerate() {
        let (e, u) = (
            s["expected"].as_f64().unwrap(),
            s["uncertainty"].as_f64().unwrap(),
        );
        assert!(e <= u || e < campaign, "{s}");
        assert_ne!(s["worth"], "separates", "{s}");
        let line = text
            .lines()
            .find(|l| l.starts_with(&format!("  {}. ", k + 1)))
            .unwrap();
        assert!(line.contains("; not recommended: "), "{line}");
    }
    assert_eq!(set["recommendation"]["kind"], "none_worth_driving", "{set}");
    assert_eq!(set["recommendation"]["campaign_separates_more"], true);
    let best_e = set["recommendation"]["best_expected"].as_f64().unwrap();
    let best_u = set["recommendation"]["best_uncertainty"].as_f64().unwrap();
    assert!(
        text.contains(&format!(
            "  no single run of these is expected to tell them apart (at most {best_e:.1} ± {best_u:.1}, less than the D = {campaign:.1} of the campaign's runs, which left them confounded): they are still to be told apart, so a test is still needed"
        )),
        "{text}"
    );
    // The diagnosis's advice (a ramp to the limit and a steer step; steps
    // at two speeds) is in the family and ranked.
    assert!(
        text.contains("  the diagnosis advises to separate steering_compliance by a ramp or steps (the best, "),
        "{text}"
    );
    assert!(
        text.contains("; cornering_stiffness by steps (the best, step_"),
        "{text}"
    );
    let advised = set["advised"].as_array().unwrap();
    assert!(
        advised.iter().all(|a| a["best"]["rank"].as_u64().is_some()),
        "{advised:?}"
    );
    // Nor does a scenario file offer them as separating.
    let name = set["ranked"][0]["name"].as_str().unwrap();
    let scenario = fs::read_to_string(d.join(format!("design/scenarios/{name}.toml"))).unwrap();
    assert!(scenario.contains("; not recommended: "), "{scenario}");
}

/// `identify --model mf61` printed `mx 100.000 %` in its pooled σ line for
/// an `mx` whose stage was skipped (a file without `kappa` and `fx`), and
/// `fx NaN %` for an `fx` column of zeros: a channel not fitted is said
/// so and left out of the pool, and no σ is `NaN`.
#[test]
fn identify_gives_no_sigma_to_a_channel_it_did_not_fit_and_no_nan_to_an_all_zero_one() {
    let lateral = rig("fz,alpha,fy,mz,mx", |fz, a, fy| {
        format!("{fz},{a},{fy:.3},{:.4},{:.4}", 0.02 * fy, -0.01 * fy)
    });
    let zero_fx = rig("fz,kappa,alpha,fx,fy,mz,mx", |fz, a, fy| {
        format!("{fz},0,{a},0,{fy:.3},{:.4},{:.4}", 0.02 * fy, -0.01 * fy)
    });
    let dir = scratch(&[("lateral.csv", &lateral), ("zero_fx.csv", &zero_fx)]);
    let pooled = |file: &str, out: &str| {
        let tir = dir.path().join(out);
        let o = identify_to(&dir.path().join(file), "mf61", &tir);
        assert!(o.status.success(), "{}", stderr(&o));
        let said = String::from_utf8_lossy(&o.stdout).into_owned();
        let line = said
            .lines()
            .find(|l| l.contains("σ pooled over all"))
            .unwrap()
            .to_string();
        let report = read_json(&tir.with_extension("report.json"));
        (line, report["sigma_pooled"].clone())
    };
    let (line, json) = pooled("lateral.csv", "a.tir");
    assert!(!line.contains("mx 100.000 %"), "{line}");
    assert!(
        line.contains("; mx not fitted (its stage was skipped): no σ, left out of the pool)"),
        "{line}"
    );
    let mx = &json["channels"][2];
    assert_eq!(
        (&mx["channel"], &mx["fitted"]),
        (&"mx".into(), &false.into())
    );
    assert!(mx["sigma_percent"].is_null(), "{json}");
    // The pool is fy's and mz's: well below the unfitted mx's 100 %.
    assert!(json["sigma_percent"].as_f64().unwrap() < 1.0, "{json}");
    let (line, _) = pooled("zero_fx.csv", "k.tir");
    assert!(!without_temp_names(&line).contains("NaN"), "{line}");
    assert!(
        line.contains("(fx not fitted (its stage was skipped): no σ, left out of the pool; fy "),
        "{line}"
    );
    assert!(line.contains("; mx 0.0"), "{line}");
}

/// `metrics` on a noise-free simulated step at 1 m/s printed
/// `yaw-rate noise 0.00 % of the step`, as if a value had been rounded
/// away: none measured is said so.
#[test]
fn metrics_says_a_noise_free_records_yaw_rate_noise_as_none_measured() {
    let text = bundled_scenario("step_gbt6323_gim.toml")
        .replace("speed = 22.2222", "speed = 1.0 #")
        .replace("lateral_acceleration = 2.0", "lateral_acceleration = 0.05");
    let dir = scratch(&[("scenario.toml", &text)]);
    let (ok, _, e) = crate::trips_simulate::simulated(dir.path());
    assert!(ok, "{e}");
    let (ok, said, e) = crate::trips_run_units::metrics(
        &dir.path().join("out/history.csv"),
        &["--min-speed", "0.5"],
    );
    assert!(ok, "{e}");
    assert!(!said.contains("0.00 % of the step"), "{said}");
    assert!(
        said.contains("yaw-rate noise 0 % of the step (none measured: at least half of its successive samples are equal)"),
        "{said}"
    );
}
