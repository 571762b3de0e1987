//! A PAC89 fit of the public Hoosier cornering file with its three
//! pressures pooled (`identify --model pac89`, the layout a user hands
//! it): the polish drifted along a direction the data do not see and
//! wrote `a0` = 0.0068, `a1` = 1046, `a2` = 211161 past their boxes
//! (1–2, ±400, 200–5000), and its lateral curvature above 1 made the force
//! change sign at a slip angle no one was told of.

use super::*;

/// The numbers of the TOML array `key = [...]` in `text`.
fn array(text: &str, key: &str) -> Vec<f64> {
    let line = text
        .lines()
        .find(|l| l.starts_with(&format!("{key} = [")))
        .unwrap_or_else(|| panic!("no {key}: {text}"));
    line[line.find('[').unwrap() + 1..line.rfind(']').unwrap()]
        .split(',')
        .map(|v| v.trim().parse().unwrap())
        .collect()
}

/// `fy` of the tyre file at `fz` for each slip angle (rad), by `tyre-eval`.
fn fy_at(dir: &Path, tyre: &Path, fz: f64, alphas: &[f64]) -> Vec<f64> {
    let points = dir.join("points.csv");
    let rows: String = alphas
        .iter()
        .map(|a| format!("{fz},0,{a},0,11\n"))
        .collect();
    fs::write(&points, format!("fz,kappa,alpha,camber,speed\n{rows}")).unwrap();
    let out = dir.join("forces.csv");
    succeeds(&[
        "tyre-eval",
        tyre.to_str().unwrap(),
        points.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let mut r = csv::Reader::from_path(&out).unwrap();
    let col = r.headers().unwrap().iter().position(|h| h == "fy").unwrap();
    r.records()
        .map(|row| row.unwrap()[col].parse().unwrap())
        .collect()
}

#[test]
fn a_pac89_fit_keeps_what_the_data_do_not_see_in_its_box_and_says_where_its_force_reverses() {
    let Some(data) = shared_data(
        "a_pac89_fit_keeps_what_the_data_do_not_see_in_its_box_and_says_where_its_force_reverses",
        "tyre_ttc_hoosier_43075/cornering.csv",
    ) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let tyre = dir.path().join("hoosier_pac89.toml");
    let text = succeeds(&[
        "identify",
        data.to_str().unwrap(),
        "--model",
        "pac89",
        "--seed",
        "1",
        "--out",
        tyre.to_str().unwrap(),
    ]);
    let a = array(&fs::read_to_string(&tyre).unwrap(), "a");
    for (i, (lo, hi)) in [(1.0, 2.0), (-400.0, 400.0), (200.0, 5000.0)]
        .into_iter()
        .enumerate()
    {
        assert!(
            (lo..=hi).contains(&a[i]),
            "a{i} = {} outside {lo} to {hi}",
            a[i]
        );
    }
    assert!(!text.contains("drifted past its search bound"), "{text}");
    // The σ of the bounded fit: within a hundredth of a percent of the
    // drifted one's 5.837 %.
    let sigma: f64 = text
        .split("  σ ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .unwrap()
        .parse()
        .unwrap();
    assert!((5.83..5.86).contains(&sigma), "σ {sigma}\n{text}");
    // Its curvature exceeds 1 at the largest load: the angle said is where
    // `tyre-eval` finds the lateral force change sign.
    let warned = text
        .lines()
        .find(|l| l.contains("warning: curvature E = a6·Fz + a7 reaches"))
        .unwrap_or_else(|| panic!("no reversal warning: {text}"));
    let fz: f64 = warned
        .split("(at fz ")
        .nth(1)
        .unwrap()
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let deg: f64 = warned
        .split("beyond |alpha| = ")
        .nth(1)
        .unwrap()
        .split('°')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!((2900.0..2950.0).contains(&fz), "{warned}");
    assert!((20.0..60.0).contains(&deg), "{warned}");
    let inside = deg.to_radians() * 0.99;
    let past = deg.to_radians() * 1.01;
    let fy = fy_at(dir.path(), &tyre, fz, &[inside, past, -inside, -past]);
    let changed = |a: f64, b: f64| a.signum() != b.signum();
    assert!(
        changed(fy[0], fy[1]) || changed(fy[2], fy[3]),
        "no sign change around ±{deg}°: {fy:?}"
    );
}
