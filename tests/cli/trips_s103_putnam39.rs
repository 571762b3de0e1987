//! The Putnam racing log's campaign (`campaigns/putnam.toml`) states its
//! sideslip's uncertainty: the log's `beta` is computed from the car's
//! state estimate, and its error is the estimator's slow drift, not the
//! white noise its scatter shows. Stated at the 0.005 rad the tool assumed
//! unstated, the fits weigh alike (the same base, verdict and reduction,
//! measured on the full library), while a run's mean sideslip inside that
//! uncertainty is no longer "a bias": 2 of the 46 run channels, where the
//! floor counted as white noise over every sample made 19.

use super::*;

#[test]
fn the_racing_log_s_stated_sideslip_counts_its_run_means_as_the_estimator_s_slow_error() {
    let test =
        "the_racing_log_s_stated_sideslip_counts_its_run_means_as_the_estimator_s_slow_error";
    let Some(log) = shared_data(test, "run_iac_putnam/putnam_run4_2.csv") else {
        return;
    };
    // The bundled campaign as it is, one candidate to keep the test short
    // (the base, and so the gap, do not depend on the candidates).
    let text = putnam_campaign(&log, "effects = [\"steer_path\"]\nmax_effects = 1");
    let dir = scratch(&[("putnam.toml", &text)]);
    let (stdout, d) = diagnose_to(&dir.path().join("putnam.toml"), &dir.path().join("out"));
    // The sideslip stated, at the estimated output's value; the gyro left
    // to its sensor floor (its scatter is below it), as before.
    let noise = &d["gap"]["noise"];
    assert_eq!(noise[0]["channel"], "yaw_rate", "{noise}");
    assert_eq!(noise[0]["source"], "sensor_floor", "{noise}");
    assert_eq!(noise[1]["channel"], "beta", "{noise}");
    assert_eq!(noise[1]["source"], "stated", "{noise}");
    assert_eq!(noise[1]["noise_floor"].as_f64().unwrap(), 0.005, "{noise}");
    assert_eq!(noise[1]["scale"].as_f64().unwrap(), 0.005, "{noise}");
    assert!(
        stdout.contains("beta 0.0050 rad (stated)"),
        "{}",
        without_temp_names(&stdout)
    );
    // Every run's sideslip counts its floor as the slow error it stands
    // for; few run means lie beyond it (2 measured; 19 counted white).
    let mut biased = 0;
    for run in d["gap"]["runs"].as_array().unwrap() {
        for c in run["channels"].as_array().unwrap() {
            if c["channel"] == "beta" {
                assert_eq!(c["bias_counting"], "slow", "{}", run["run"]);
            }
            biased += usize::from(c["bias_significant"] == true);
        }
    }
    assert!(biased <= 5, "{biased} run channels biased");
    // The statement does not move the weights: the base's axles stay a
    // slick's, the rear within twice the front.
    let axles = &d["base"]["axles"];
    for i in 0..2 {
        assert_eq!(axles["prior"]["against"][i]["within"], true, "{axles}");
    }
    let k = |i: usize| axles["parameters"][i]["value"].as_f64().unwrap();
    assert!((1.0..2.0).contains(&(k(1) / k(0))), "{axles}");
}
