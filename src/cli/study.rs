//! `study`: cornering stiffness against handling (Wang & Liang).

use anyhow::{bail, Result};
use handling::io::study::load_study;
use handling::report::plot::{Figure, Panel, Series, Style};
use handling::report::progress::Progress;
use handling::report::{refuse_overwrite, write_bytes, write_json};
use handling::study::inverse::{best_on_curve, distance, Map};
use handling::study::rbf::Rbf;
use handling::study::{metric, Sample, Study, METRICS};
use serde_json::{json, Value};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

fn table(samples: &[Sample], unit: &str, k: f64) -> String {
    let u = unit.replace('/', "_per_");
    let mut s = format!(
        "k_front_{u},k_rear_{u},k_front,k_rear,{}\n",
        METRICS.join(",")
    );
    for x in samples {
        let _ = write!(
            s,
            "{},{},{},{}",
            x.k_front / k,
            x.k_rear / k,
            x.k_front,
            x.k_rear
        );
        for m in METRICS {
            let _ = write!(s, ",{}", x.metrics.map_or(f64::NAN, |v| metric(&v, m)));
        }
        s.push('\n');
    }
    s
}

fn heat_maps(
    map: &Map,
    unit: &str,
    k: f64,
    curves: &[(f64, Vec<(f64, f64)>)],
    path: &Path,
) -> Result<()> {
    let names = [
        ("er", "Er [s]"),
        ("yaw_rate_total_variance", "E_r [s]"),
        ("ay_total_variance", "E_ay [s]"),
        ("yaw_rate_response_time", "yaw-rate response time [s]"),
        ("yaw_rate_overshoot", "yaw-rate overshoot [%]"),
        ("tb", "TB [s·deg]"),
    ];
    let step = |v: &[f64]| {
        v.windows(2)
            .map(|w| (w[1] - w[0]) / k)
            .fold(f64::INFINITY, f64::min)
    };
    let (dx, dy) = (step(&map.front), step(&map.rear));
    let mut panels = Vec::new();
    for (name, label) in names {
        let (mut x, mut y, mut v) = (Vec::new(), Vec::new(), Vec::new());
        for (i, kf) in map.front.iter().enumerate() {
            for (j, kr) in map.rear.iter().enumerate() {
                x.push(kf / k);
                y.push(kr / k);
                v.push(map.value(name, i, j));
            }
        }
        let finite: Vec<f64> = v.iter().copied().filter(|a| a.is_finite()).collect();
        let lo = finite.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let mut heat = Series::line("", &x, &y, 0).styled(Style::Heat(dx, dy, lo, hi));
        heat.values = Some(v);
        let mut series = vec![heat];
        if name == "er" {
            for (target, c) in curves {
                let (cx, cy): (Vec<f64>, Vec<f64>) = c.iter().map(|p| (p.0 / k, p.1 / k)).unzip();
                series.push(
                    Series::line(&format!("Er = {target}"), &cx, &cy, 1).styled(Style::Points(2)),
                );
            }
        }
        panels.push(Panel {
            title: format!("{label}: {lo:.4} (dark) … {hi:.4} (yellow)"),
            x_label: format!("front k1 [{unit}]"),
            y_label: format!("rear k2 [{unit}]"),
            series,
            ..Panel::default()
        });
    }
    Figure {
        panels,
        columns: 2,
        width: 1400,
        row_height: 520,
    }
    .save(path)
}

/// `handling study`.
pub fn study(path: &Path, out: Option<&Path>) -> Result<()> {
    let input = load_study(path)?;
    let sc = &input.scenario;
    let out_dir = out.map_or_else(|| PathBuf::from("out").join(&sc.name), Path::to_path_buf);
    let files = [
        "study.csv",
        "maps.png",
        "rbf.json",
        "rbf.png",
        "inverse.json",
        "summary.json",
    ]
    .map(|f| out_dir.join(f));
    for f in &files {
        refuse_overwrite(f, &sc.inputs)?;
    }
    let st = Study {
        model: sc.model.clone(),
        manoeuvre: sc.manoeuvre.clone(),
        integrator: sc.integrator,
        metrics: sc.metrics,
    };
    let (k, unit) = (input.unit_to_si, input.unit.as_str());
    let grid: Vec<(f64, f64)> = input
        .front
        .iter()
        .flat_map(|&f| input.rear.iter().map(move |&r| (f, r)))
        .collect();
    let rbf_pairs = input
        .rbf
        .as_ref()
        .map(|r| r.pairs.clone())
        .unwrap_or_default();
    let all: Vec<(f64, f64)> = grid.iter().chain(&rbf_pairs).copied().collect();
    if all.is_empty() {
        bail!(
            "{}: nothing to simulate: give a [stiffness] map or [rbf] pairs",
            path.display()
        );
    }
    println!(
        "{}: {} map combinations + {} RBF pairs, tyres {} / {}, step steer",
        sc.name,
        grid.len(),
        rbf_pairs.len(),
        sc.model.front.model_name(),
        sc.model.rear.model_name()
    );
    let t0 = Instant::now();
    let samples = {
        let p = Progress::start("study", all.len());
        st.evaluate_all(&all, p.counter())
    };
    let seconds = t0.elapsed().as_secs_f64();
    println!("  simulated {} combinations in {seconds:.2} s", all.len());
    let (map_samples, pair_samples) = samples.split_at(grid.len());
    let mut report = json!({ "study": sc.name, "unit": unit, "seconds": seconds });
    write_bytes(&files[0], table(&samples, unit, k).as_bytes())?;
    let map = Map {
        front: input.front.clone(),
        rear: input.rear.clone(),
        samples: map_samples.to_vec(),
    };
    // The RBF network of Wang & Liang: Er → (k1, k2), trained on all pairs but
    // the validation ones, checked by re-simulating its answers.
    let mut rbf_net = None;
    if let Some(rbf) = &input.rbf {
        let (spread, validation) = (&rbf.spread, &rbf.validation);
        let er: Vec<f64> = pair_samples
            .iter()
            .map(|s| s.metrics.and_then(|m| m.er).unwrap_or(f64::NAN))
            .collect();
        let train: Vec<usize> = (0..pair_samples.len())
            .filter(|i| !validation.contains(i) && er[*i].is_finite())
            .collect();
        let net = Rbf::train(
            &train.iter().map(|&i| er[i]).collect::<Vec<_>>(),
            &train
                .iter()
                .map(|&i| vec![pair_samples[i].k_front, pair_samples[i].k_rear])
                .collect::<Vec<_>>(),
            *spread,
        );
        let fit_err = train
            .iter()
            .map(|&i| {
                let p = net.predict(er[i]);
                ((p[0] - pair_samples[i].k_front) / k)
                    .abs()
                    .max(((p[1] - pair_samples[i].k_rear) / k).abs())
            })
            .fold(0.0, f64::max);
        println!(
            "  RBF (spread {spread} s): trained on {} pairs, condition number {:.2e}, largest training misfit {fit_err:.3} {unit}",
            train.len(),
            net.condition
        );
        println!("  validation (Wang & Liang, table 3): Er target → predicted k1, k2 [{unit}] → Er re-simulated, error");
        let mut rows = Vec::new();
        for &i in validation {
            let p = net.predict(er[i]);
            let er_sim = st.er(p[0], p[1]);
            let err = 100.0 * (er_sim - er[i]) / er[i];
            println!(
                "    Er {:.5} ({:.0}, {:.0}) → ({:.1}, {:.1}) → Er {er_sim:.5}, {err:+.2} %",
                er[i],
                pair_samples[i].k_front / k,
                pair_samples[i].k_rear / k,
                p[0] / k,
                p[1] / k
            );
            rows.push(json!({
                "er_target": er[i], "k_front_true": pair_samples[i].k_front / k, "k_rear_true": pair_samples[i].k_rear / k,
                "k_front_predicted": p[0] / k, "k_rear_predicted": p[1] / k, "er_resimulated": er_sim, "error_percent": err,
            }));
        }
        write_json(
            &files[2],
            &json!({ "spread": spread, "training_pairs": train.len(), "condition_number": net.condition,
                     "largest_training_misfit": fit_err, "validation": rows, "unit": unit }),
        )?;
        let offsets: Vec<f64> = {
            let mut o: Vec<f64> = pair_samples
                .iter()
                .map(|s| ((s.k_rear - s.k_front) / k).round())
                .collect();
            o.dedup();
            o
        };
        let series = offsets
            .iter()
            .enumerate()
            .map(|(c, off)| {
                let (x, y): (Vec<f64>, Vec<f64>) = pair_samples
                    .iter()
                    .zip(&er)
                    .filter(|(s, _)| ((s.k_rear - s.k_front) / k).round() == *off)
                    .map(|(s, e)| (s.k_front / k, *e))
                    .unzip();
                Series::line(&format!("k2 = k1 + {off} {unit}"), &x, &y, c)
            })
            .collect();
        Figure::stack(vec![Panel {
            title: "Wang & Liang pairs: Er against front stiffness".into(),
            x_label: format!("front k1 [{unit}]"),
            y_label: "Er [s]".into(),
            series,
            ..Panel::default()
        }])
        .save(&files[3])?;
        rbf_net = Some(net);
    }
    let mut curves = Vec::new();
    if let Some(inv) = &input.inverse {
        let reference = &inv.reference;
        let mut out = Vec::new();
        for (name, value, tol) in &inv.targets {
            let mut all = vec![(name.clone(), *value, *tol)];
            all.extend(inv.constraints.iter().cloned());
            let region = map.region(&all);
            println!(
                "  {name} = {value} ± {tol}: {} map points meet it and every constraint",
                region.len()
            );
            out.push(json!({ "metric": name, "target": value, "tolerance": tol,
                             "region": region.iter().map(|p| [p.0 / k, p.1 / k]).collect::<Vec<_>>() }));
            if name != "er" {
                continue;
            }
            let curve = map.iso_curve(name, *value);
            let span = 2.0 * (input.front[1] - input.front[0]);
            let best = best_on_curve(&st, &curve, *reference, *value, span);
            let rbf_answer = rbf_net.as_ref().map(|net| {
                let p = net.predict(*value);
                let e = st.er(p[0], p[1]);
                json!({ "k_front": p[0] / k, "k_rear": p[1] / k, "er_resimulated": e,
                        "error_percent": 100.0 * (e - value) / value, "distance_to_reference": distance((p[0], p[1]), *reference) })
            });
            match best {
                Some((kf, kr, e)) => println!(
                    "  Er = {value}: a curve of {} map points; closest to ({:.0}, {:.0}) {unit}: ({:.1}, {:.1}) with Er {e:.6} (re-simulated), distance {:.3}",
                    curve.len(),
                    reference.0 / k,
                    reference.1 / k,
                    kf / k,
                    kr / k,
                    distance((kf, kr), *reference)
                ),
                None => println!("  Er = {value}: not reached on the map"),
            }
            if let Some(r) = &rbf_answer {
                println!(
                    "    RBF answer: ({:.1}, {:.1}) {unit}, Er {:.6} re-simulated ({:+.2} %), distance {:.3}",
                    r["k_front"].as_f64().unwrap_or(f64::NAN),
                    r["k_rear"].as_f64().unwrap_or(f64::NAN),
                    r["er_resimulated"].as_f64().unwrap_or(f64::NAN),
                    r["error_percent"].as_f64().unwrap_or(f64::NAN),
                    r["distance_to_reference"].as_f64().unwrap_or(f64::NAN)
                );
            }
            let last = out.last_mut().expect("pushed above");
            last["curve"] = json!(curve.iter().map(|p| [p.0 / k, p.1 / k]).collect::<Vec<_>>());
            last["best"] = json!(best.map(|(kf, kr, e)| json!({ "k_front": kf / k, "k_rear": kr / k, "er_resimulated": e,
                                                                 "distance_to_reference": distance((kf, kr), *reference) })));
            last["rbf"] = rbf_answer.unwrap_or(Value::Null);
            curves.push((*value, curve));
        }
        write_json(
            &files[4],
            &json!({ "unit": unit, "reference": [reference.0 / k, reference.1 / k], "targets": out }),
        )?;
    }
    if map.front.len() >= 2 && map.rear.len() >= 2 {
        heat_maps(&map, unit, k, &curves, &files[1])?;
    }
    report["combinations"] = json!(all.len());
    report["without_steady_state"] = json!(samples.iter().filter(|s| s.metrics.is_none()).count());
    write_json(&files[5], &report)?;
    println!("wrote {}", out_dir.display());
    Ok(())
}
