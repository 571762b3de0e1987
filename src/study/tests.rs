use super::inverse::{best_on_curve, distance, golden_section, solve_rear, Map};
use super::*;
use crate::manoeuvre::StepSteer;
use crate::sim::Method;
use crate::tyre::{Gim, Tyre, TyreModel};
use crate::vehicle::Vehicle;
use std::sync::atomic::AtomicUsize;

const DEG: f64 = 180.0 / std::f64::consts::PI;

fn study() -> Study {
    Study {
        model: VehicleModel::new(
            Vehicle::compact_sedan(),
            Tyre::Gim(Gim::new(500.0 * DEG, 0.16, 1.0)),
            Tyre::Gim(Gim::new(540.0 * DEG, 0.16, 1.0)),
        ),
        manoeuvre: Manoeuvre::StepSteer(StepSteer {
            speed: 22.2222,
            amplitude: 1f64.to_radians(),
            trim: 0.0,
            start: 0.5,
            rise_time: 0.1,
            end: 4.5,
        }),
        integrator: Integrator {
            step: 2e-3,
            friction: 1.0,
            method: Method::Rk4,
        },
        metrics: MetricSettings::default(),
    }
}

#[test]
fn more_rear_stiffness_means_more_understeer() {
    let st = study();
    let gains: Vec<f64> = [300.0, 400.0, 500.0, 600.0, 700.0]
        .iter()
        .map(|kr| {
            st.evaluate(500.0 * DEG, kr * DEG)
                .metrics
                .unwrap()
                .yaw_rate_gain
        })
        .collect();
    assert!(gains.windows(2).all(|w| w[1] < w[0]), "{gains:?}");
    // And more front stiffness, less understeer: a larger gain.
    let front: Vec<f64> = [300.0, 500.0, 700.0]
        .iter()
        .map(|kf| {
            st.evaluate(kf * DEG, 540.0 * DEG)
                .metrics
                .unwrap()
                .yaw_rate_gain
        })
        .collect();
    assert!(front.windows(2).all(|w| w[1] > w[0]), "{front:?}");
}

#[test]
fn scaled_tyres_have_the_asked_stiffness() {
    let st = study();
    let m = st.model_for(321.0 * DEG, 654.0 * DEG);
    let (sf, sr) = m.vehicle.static_axle_loads();
    assert!((m.front.cornering_stiffness(0.5 * sf) / DEG - 321.0).abs() < 1e-6);
    assert!((m.rear.cornering_stiffness(0.5 * sr) / DEG - 654.0).abs() < 1e-6);
}

#[test]
fn inverse_answers_resimulate_to_the_target() {
    let st = study();
    let front: Vec<f64> = (0..8).map(|i| (300.0 + 50.0 * i as f64) * DEG).collect();
    let rear: Vec<f64> = (0..8).map(|i| (320.0 + 50.0 * i as f64) * DEG).collect();
    let pairs: Vec<(f64, f64)> = front
        .iter()
        .flat_map(|&f| rear.iter().map(move |&r| (f, r)))
        .collect();
    let map = Map {
        front: front.clone(),
        rear,
        samples: st.evaluate_all(&pairs, &AtomicUsize::new(0)),
    };
    let target = 0.13;
    let curve = map.iso_curve(Metric::Er, target);
    assert!(curve.len() >= 5, "{curve:?}");
    // Every curve point is an interpolation: re-simulated it is near the target.
    for p in curve.iter().step_by(3) {
        let e = st.er(p.0, p.1);
        assert!((e - target).abs() < 0.01 * target, "{p:?}: {e}");
    }
    // The solved rear stiffness meets the target to the solver's tolerance.
    let kr = solve_rear(&st, Metric::Er, 450.0 * DEG, 500.0 * DEG, (target, 1e-7)).unwrap();
    assert!((st.er(450.0 * DEG, kr) - target).abs() <= 1e-7);
    // The refined best point is on the curve and no farther from the
    // reference than any interpolated curve point.
    let reference = (500.0 * DEG, 540.0 * DEG);
    let best = best_on_curve(
        &st,
        Metric::Er,
        &curve,
        map.bounds(),
        reference,
        (target, 100.0 * DEG),
    )
    .unwrap();
    let (kf, kr, e) = (best.k_front, best.k_rear, best.value);
    assert!((e - target).abs() <= 1e-6 * target);
    let best_curve = curve
        .iter()
        .map(|p| distance(*p, reference))
        .fold(f64::INFINITY, f64::min);
    assert!(
        distance((kf, kr), reference) <= best_curve + 1e-3,
        "{} vs {best_curve}",
        distance((kf, kr), reference)
    );
}

#[test]
fn metric_names_are_the_table_columns_and_unknown_names_are_refused() {
    assert_eq!(METRICS[0], "er");
    assert_eq!(METRICS[9], "tb");
    for m in Metric::ALL {
        assert_eq!(m.name().parse::<Metric>().unwrap(), m);
        assert_eq!(serde_json::to_value(m).unwrap(), m.name());
    }
    let e = "err".parse::<Metric>().unwrap_err().to_string();
    assert!(
        e.contains("unknown metric `err`") && e.contains("yaw_rate_gain"),
        "{e}"
    );
    assert_eq!(
        "N/deg".parse::<StiffnessUnit>().unwrap().to_si(),
        180.0 / std::f64::consts::PI
    );
    assert!("N/mm".parse::<StiffnessUnit>().is_err());
}

/// `Study::evaluate_in` checks each value as a study file's values are
/// checked, before simulating any: the compact sedan's front tyre carries
/// about 4.5 kN, so 20,000 N/deg (a value in N/rad) is 254 times its load
/// per rad, and the refusal names the argument and says the N/deg value.
#[test]
fn evaluate_in_refuses_what_the_study_file_refuses_naming_the_argument() {
    let st = study();
    let refused = |pairs: &[(f64, f64)]| {
        st.evaluate_in(pairs, StiffnessUnit::NPerDeg)
            .expect_err("refused")
    };
    for (x, why) in [
        (f64::NAN, crate::error::ParamReason::NotFinite),
        (f64::INFINITY, crate::error::ParamReason::NotFinite),
        (-500.0, crate::error::ParamReason::StiffnessNotPositive),
        (0.0, crate::error::ParamReason::StiffnessNotPositive),
    ] {
        let e = refused(&[(x, 540.0)]);
        assert_eq!(e.key, "front_n_per_deg", "{e}");
        assert_eq!(e.reason, why, "{e}");
    }
    let e = refused(&[(500.0, 540.0), (20000.0, 540.0)]).to_string();
    assert!(
        e.starts_with("`front_n_per_deg[1]` = 20000: 20000 N/deg per tyre is 1145916 N/rad, 254 times the front tyre's static load"),
        "{e}"
    );
    assert!(
        e.ends_with("is the value in N/rad? give it as `front_n_per_rad` = 20000, or as `front_n_per_deg[1]` = 349.1"),
        "{e}"
    );
    // No tyre's in either unit: the range a tyre of that load has.
    let e = refused(&[(500.0, 1e-300)]).to_string();
    assert!(e.starts_with("`rear_n_per_deg` = 1e-300"), "{e}");
    assert!(
        e.contains("nor is it one in N/rad: the rear tyre's lies within"),
        "{e}"
    );
    // In N/rad, the same values as the file's reader converts them.
    let s = st
        .evaluate_in(&[(500.0 * DEG, 540.0 * DEG)], StiffnessUnit::NPerRad)
        .unwrap();
    let d = st
        .evaluate_in(&[(500.0, 540.0)], StiffnessUnit::NPerDeg)
        .unwrap();
    assert_eq!(s, d);
    assert_eq!(s[0], st.evaluate(500.0 * DEG, 540.0 * DEG));
}

/// A sliding combination is reported as `study.csv` reports it: its
/// response and note, and no metrics (its Er is no handling number).
#[test]
fn a_sliding_combination_is_reported_without_metrics() {
    let st = study();
    let mut slides = st.evaluate(500.0 * DEG, 540.0 * DEG);
    slides.metrics = slides.metrics.map(|mut m| {
        m.beta_steady = Some(-0.6);
        m
    });
    let r = slides.reported();
    assert_eq!(r.response, "sliding");
    assert!(r.metrics.is_none() && r.note.unwrap().contains("slides past its grip"));
    let fine = st.evaluate(500.0 * DEG, 540.0 * DEG).reported();
    assert_eq!(fine.response, "handling");
    assert!(fine.metrics.is_some());
}

/// The golden-section search of the inverse evaluates its cost once per
/// iteration (two to start, none after the last narrowing: 26 for 25
/// iterations, where evaluating both interior points afresh took 50), and
/// narrows the interval exactly as that search does: the same ends, to
/// rounding, around the closed-form minimum of a parabola.
#[test]
fn the_golden_section_search_reuses_its_interior_point() {
    let minimum = 0.3141;
    let cost = |x: f64| (x - minimum) * (x - minimum);
    let calls = std::cell::Cell::new(0usize);
    let (mut lo, mut hi) = (-1.0, 2.0);
    golden_section(&mut lo, &mut hi, |x| {
        calls.set(calls.get() + 1);
        cost(x)
    });
    assert_eq!(calls.get(), 26);
    // The search as it was: both interior points evaluated every iteration.
    let (mut lo0, mut hi0) = (-1.0_f64, 2.0_f64);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..25 {
        let (m1, m2) = (hi0 - g * (hi0 - lo0), lo0 + g * (hi0 - lo0));
        if cost(m1) < cost(m2) {
            hi0 = m2;
        } else {
            lo0 = m1;
        }
    }
    assert!(
        (lo - lo0).abs() < 1e-12 && (hi - hi0).abs() < 1e-12,
        "{lo} {hi} vs {lo0} {hi0}"
    );
    // 0.618^25 of the width 3 around the minimum.
    assert!(lo <= minimum && minimum <= hi, "{lo} {hi}");
    assert!(hi - lo < 3.0 * g.powi(25) * (1.0 + 1e-9), "{}", hi - lo);
}

/// A combination listed twice (an RBF pair on the map's grid) is
/// simulated once and its sample given at both places, the one a
/// simulation of it gives; the progress counts every listing.
#[test]
fn a_combination_listed_twice_is_simulated_once_and_given_twice() {
    let st = study();
    let (a, b) = ((500.0 * DEG, 540.0 * DEG), (400.0 * DEG, 560.0 * DEG));
    let pairs = [a, b, a, a];
    assert_eq!(first_of_each(&pairs), (vec![0, 1], vec![0, 1, 0, 0]));
    let progress = AtomicUsize::new(0);
    let samples = st.evaluate_all(&pairs, &progress);
    assert_eq!(progress.load(std::sync::atomic::Ordering::Relaxed), 4);
    assert_eq!(samples.len(), 4);
    // Compared as printed: a metric a step lacks is NaN, unequal to itself.
    let text = |s: &Sample| format!("{s:?}");
    assert_eq!(text(&samples[0]), text(&st.evaluate(a.0, a.1)));
    assert_eq!(text(&samples[1]), text(&st.evaluate(b.0, b.1)));
    assert_eq!(text(&samples[2]), text(&samples[0]));
    assert_eq!(text(&samples[3]), text(&samples[0]));
    assert_ne!(text(&samples[1]), text(&samples[0]));
}
