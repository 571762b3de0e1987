//! `tyre-eval`: forces and moments of a tyre file at the points of a CSV.

use anyhow::Result;
use handling::io::{load_tyre, read_columns};
use handling::report::{refuse_overwrite, write_columns};
use std::path::Path;

/// Reads the tyre and the points, evaluates, writes the output CSV.
pub fn tyre_eval(tyre_path: &Path, points: &Path, out: &Path) -> Result<()> {
    refuse_overwrite(out, &[tyre_path.to_path_buf(), points.to_path_buf()])?;
    let tyre = load_tyre(tyre_path)?;
    let mut c = read_columns(
        points,
        &["fz", "kappa", "alpha", "camber", "speed"],
        &["pressure"],
    )?;
    let pressure = c.take_optional("pressure");
    if let Some(p) = &pressure {
        if let Some(i) = p.iter().position(|v| *v <= 0.0) {
            return Err(c
                .error_at(
                    points,
                    i,
                    "pressure",
                    format!("column `pressure`: {} Pa is not a positive pressure", p[i]),
                )
                .into());
        }
    }
    let (fz, kappa, alpha, camber, speed) = (
        c.take("fz"),
        c.take("kappa"),
        c.take("alpha"),
        c.take("camber"),
        c.take("speed"),
    );
    let p = pressure.clone().unwrap_or_default();
    let f = tyre.evaluate_points(&fz, &kappa, &alpha, &camber, &speed, &p);
    let col = |g: fn(&handling::tyre::PointForces) -> f64| f.iter().map(g).collect::<Vec<_>>();
    let (fx, fy, mz) = (col(|x| x.fx), col(|x| x.fy), col(|x| x.mz));
    let mx = col(|x| x.mx.unwrap_or(f64::NAN));
    let my = col(|x| x.my.unwrap_or(f64::NAN));
    let mut cols: Vec<(&str, &[f64])> = vec![
        ("fz", &fz),
        ("kappa", &kappa),
        ("alpha", &alpha),
        ("camber", &camber),
        ("speed", &speed),
    ];
    if let Some(p) = &pressure {
        cols.push(("pressure", p));
    }
    cols.extend([("fx", &fx[..]), ("fy", &fy[..]), ("mz", &mz[..])]);
    if tyre.has_wheel_moments() {
        cols.extend([("mx", &mx[..]), ("my", &my[..])]);
    }
    write_columns(out, &cols)?;
    println!(
        "{} points of {} ({} tyre) evaluated; wrote {}",
        fz.len(),
        points.display(),
        tyre.model_name(),
        out.display()
    );
    Ok(())
}
