//! `equilibria`: sweep the steering equilibria and write CSV, JSON and PNGs.

use anyhow::Result;
use handling::equilibria::plots;
use handling::equilibria::sweep::{self, SweepResult};
use handling::equilibria::{exact, FoundBy};
use handling::io::sweep::load_sweep;
use handling::report::progress::Progress;
use handling::report::{refuse_overwrite, write_bytes, write_json};
use serde_json::json;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

fn equilibria_csv(r: &SweepResult) -> String {
    let mut s = String::from(
        "steer,friction,speed,beta,yaw_rate,kind,eig1_re,eig1_im,eig2_re,eig2_im,residual,found_by,in_box,alpha_rear\n",
    );
    for p in &r.points {
        for f in &p.found {
            let e = &f.equilibrium;
            let ev = e.stability.eigenvalues;
            let by = match f.found_by {
                FoundBy::Both => "both",
                FoundBy::Exact => "exact",
                FoundBy::Pso => "pso",
            };
            let _ = writeln!(
                s,
                "{},{},{},{},{},{},{},{},{},{},{:e},{},{},{}",
                p.condition.steer,
                p.condition.friction,
                p.condition.speed,
                e.beta,
                e.yaw_rate,
                e.stability.kind.name(),
                ev[0].0,
                ev[0].1,
                ev[1].0,
                ev[1].1,
                e.residual,
                by,
                f.in_box,
                e.alpha_rear
            );
        }
    }
    s
}

fn bifurcations_csv(r: &SweepResult) -> String {
    let mut s = String::from(
        "kind,axis,steer,friction,speed,beta,yaw_rate,residual,criterion,kind_a,kind_b,verified\n",
    );
    for b in &r.bifurcations {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{:e},{:e},{},{},{}",
            b.kind.name(),
            b.axis.name(),
            b.at.steer,
            b.at.friction,
            b.at.speed,
            b.beta,
            b.yaw_rate,
            b.residual,
            b.criterion,
            b.kinds[0].name(),
            b.kinds[1].name(),
            b.verified
        );
    }
    s
}

/// `handling equilibria`.
pub fn equilibria(path: &Path, out: Option<&Path>) -> Result<()> {
    let sw = load_sweep(path)?;
    let out_dir = out.map_or_else(|| PathBuf::from("out").join(&sw.name), Path::to_path_buf);
    let n = sw.grid.len();
    println!(
        "{}: {} conditions ({} steer × {} friction × {} speed), tyres {} / {}, {} kinematics, load transfer {}",
        sw.name,
        n,
        sw.grid.steer.len(),
        sw.grid.friction.len(),
        sw.grid.speed.len(),
        sw.model.front.model_name(),
        sw.model.rear.model_name(),
        match sw.model.options.kinematics {
            handling::vehicle::Kinematics::Exact => "exact",
            handling::vehicle::Kinematics::SmallAngle => "small-angle",
        },
        sw.model.options.load_transfer
    );
    println!(
        "  box |β| ≤ {:.3} rad, |r| ≤ {:.3} rad/s; PSO seed {}, {} particles × {} iterations, fitness {:?}",
        sw.search_box.beta_max, sw.search_box.yaw_rate_max, sw.pso.seed, sw.pso.particles, sw.pso.iterations, sw.pso.fitness
    );
    let t0 = Instant::now();
    let res = {
        let progress = Progress::start("equilibria", n);
        sweep::run(
            &sw.model,
            &sw.grid,
            &sw.search_box,
            &sw.pso,
            sw.report.bifurcations,
            progress.counter(),
        )
    };
    let seconds = t0.elapsed().as_secs_f64();
    let agree = res.agreeing();
    let max_res = res
        .points
        .iter()
        .flat_map(|p| &p.found)
        .map(|f| f.equilibrium.residual)
        .fold(0.0, f64::max);
    let mut counts = std::collections::BTreeMap::new();
    for p in &res.points {
        let k = p.found.iter().filter(|f| f.in_box).count();
        *counts.entry(k).or_insert(0usize) += 1;
    }
    let with_continua = res.points.iter().filter(|p| !p.continua.is_empty()).count();
    if with_continua > 0 {
        println!(
            "  {with_continua} conditions have a continuum of equilibria (both axles sliding at constant force: \
             the tyres' sliding force does not fall with slip); see continua.csv"
        );
    }
    println!("  PSO and exact agree at {agree}/{n} conditions ({:.1} %); largest residual {max_res:.1e}; {seconds:.2} s", 100.0 * agree as f64 / n as f64);
    for (k, c) in &counts {
        println!("  {c} conditions with {k} equilibria in the box");
    }
    for b in &res.bifurcations {
        println!(
            "  {:?} along {} at steer {:.6} rad, friction {:.4}, speed {:.3} m/s: β {:.4} rad, r {:.4} rad/s, {} + {}, residual {:.1e}, criterion {:.1e}, {}",
            b.kind,
            b.axis.name(),
            b.at.steer,
            b.at.friction,
            b.at.speed,
            b.beta,
            b.yaw_rate,
            b.kinds[0].name(),
            b.kinds[1].name(),
            b.residual,
            b.criterion,
            if b.verified { "verified" } else { "NOT verified" }
        );
    }
    let files = [
        "equilibria.csv",
        "bifurcations.csv",
        "summary.json",
        "continua.csv",
    ]
    .map(|f| out_dir.join(f));
    for f in &files {
        refuse_overwrite(f, &sw.inputs)?;
    }
    write_bytes(&files[0], equilibria_csv(&res).as_bytes())?;
    write_bytes(&files[1], bifurcations_csv(&res).as_bytes())?;
    let mut cont = String::from("steer,friction,speed,alpha_rear_from,alpha_rear_to,beta_from,beta_to,yaw_rate_from,yaw_rate_to\n");
    for p in &res.points {
        for k in &p.continua {
            let c = p.condition;
            let _ = writeln!(
                cont,
                "{},{},{},{},{},{},{},{},{}",
                c.steer,
                c.friction,
                c.speed,
                k.alpha_rear.0,
                k.alpha_rear.1,
                k.beta.0,
                k.beta.1,
                k.yaw_rate.0,
                k.yaw_rate.1
            );
        }
    }
    write_bytes(&files[3], cont.as_bytes())?;
    write_json(
        &files[2],
        &json!({
            "sweep": sw.name,
            "conditions": n,
            "agreeing": agree,
            "agreement_percent": 100.0 * agree as f64 / n as f64,
            "max_residual": max_res,
            "seed": sw.pso.seed,
            "pso": sw.pso,
            "box": sw.search_box,
            "pso_evaluations": res.points.iter().map(|p| p.pso_evaluations).sum::<usize>(),
            "seconds": seconds,
            "equilibria_in_box_histogram": counts,
            "conditions_with_continua": with_continua,
            "bifurcations": res.bifurcations,
        }),
    )?;
    if sw.report.plots {
        for axis in sw.grid.varying() {
            plots::branch_diagram(
                &res,
                axis,
                &sw.search_box,
                &out_dir.join(format!("branches_{}.png", axis.name())),
            )?;
        }
        let v = sw.grid.varying();
        if v.len() >= 2 {
            plots::stability_map(
                &res,
                v[0],
                v[1],
                &sw.search_box,
                &out_dir.join("stability_map.png"),
            )?;
        }
        for (k, c) in sw.portraits.iter().enumerate() {
            let eqs = exact::solve(&sw.model, c);
            plots::phase_portrait(
                &sw.model,
                c,
                &sw.search_box,
                &eqs,
                &out_dir.join(format!("phase_portrait_{k}.png")),
            )?;
        }
    }
    println!("wrote {}", out_dir.display());
    Ok(())
}
