//! Session 115, `roll51`: round 51's roll steer fitted through a roll
//! gradient the campaign assumes, run as the tester ran it (`handling synth
//! --truth four-wheel --effects roll_steer --seed 2`, then `handling
//! diagnose`; the candidates narrowed to roll_steer to keep it short). The
//! truth steers -0.12 / 0.05 rad per rad of roll at 6°/g; the campaign
//! states 3°/g, so the per-radian values come out twice the truth's, and
//! the report must say they hold at the stated gradient and give what the
//! runs determine: their product with it, steer per m/s² (and °/g).

use super::*;

/// A number written after `key` in the truth's comment of `text` (the
/// truth is withheld from the diagnosis, not from the test).
fn after(text: &str, key: &str) -> f64 {
    let rest = &text[text.find(key).unwrap_or_else(|| panic!("{key}: {text}")) + key.len()..];
    let end = rest
        .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
        .unwrap();
    rest[..end].parse().unwrap()
}

#[test]
fn a_roll_steer_is_said_at_the_stated_roll_gradient_with_the_product_the_runs_determine() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "--truth",
        "four-wheel",
        "--effects",
        "roll_steer",
        "--seed",
        "2",
    ];
    let c = synth_campaign(dir.path(), "fw2", &args);
    let v = c.join("vehicle.toml");
    let text = fs::read_to_string(&v).unwrap();
    // synth's vehicle.toml ends in its [diagnose] table.
    fs::write(&v, format!("{text}effects = [\"roll_steer\"]\n")).unwrap();
    // The truth (6°/g, [-0.12, 0.05]) and the campaign's stated gradient.
    let truth_gradient = after(&text, "roll gradient ").to_radians() / 9.80665;
    let listed = text.split("roll_steer = [").nth(1).unwrap();
    let truth: Vec<f64> = listed[..listed.find(']').unwrap()]
        .split(',')
        .map(|x| x.trim().parse().unwrap())
        .collect();
    assert_eq!(truth, [-0.12, 0.05]);
    let stated = after(&text, "\ngradient = ");
    let line = 1 + text[..text.find("\ngradient = ").unwrap() + 1]
        .matches('\n')
        .count();
    // The two gradients differ twofold: what the per-radian values carry.
    assert!(
        (truth_gradient / stated - 2.0).abs() < 0.01,
        "{truth_gradient} {stated}"
    );

    let out = dir.path().join("out");
    let (said, d) = diagnose_to(&c, &out);
    assert_eq!(verdict_of(&d), ["roll_steer"], "{said}");
    let p = |name: &str| -> serde_json::Value {
        let ps = d["verdict"]["parameters"].as_array().unwrap();
        ps.iter().find(|p| p["name"] == name).unwrap().clone()
    };
    let mut products = Vec::new();
    for (axle, truth) in ["front", "rear"].into_iter().zip(truth.iter().copied()) {
        let q = p(&format!("roll_steer.{axle}"));
        let a = &q["per_lateral_acceleration"];
        let (value, se) = (
            q["value"].as_f64().unwrap(),
            q["std_error"].as_f64().unwrap(),
        );
        let k = &a["roll_gradient"];
        assert_eq!(k["gradient"].as_f64().unwrap(), stated, "{q}");
        assert_eq!(k["line"], line, "{q}");
        assert!(k["file"].as_str().unwrap().ends_with("vehicle.toml"), "{q}");
        assert_eq!(k["runs_logging_roll"], 0, "{q}");
        assert_eq!(
            (a["quantity"].as_str(), a["unit"].as_str()),
            (Some("steer"), Some("rad/(m/s²)"))
        );
        let product = a["value"].as_f64().unwrap();
        assert!(
            (product - value * stated).abs() <= 1e-12 * product.abs(),
            "{q}"
        );
        assert!((a["std_error"].as_f64().unwrap() - se * stated).abs() <= 1e-12 * se * stated);
        // The per-radian value is about twice the truth's (the gradient
        // half the truth's); the product is the truth's: the front within
        // 8 %, the rear, a third the size, within 15 % (the four-wheel
        // truth's roll is not the 2-DOF model's).
        let want = truth * truth_gradient;
        let tolerance = if axle == "front" { 0.08 } else { 0.15 };
        assert!(
            (product / want - 1.0).abs() < tolerance,
            "{axle}: {product} against {want}"
        );
        products.push(product);
    }
    // Their difference, the roll steer's share of the understeer gradient,
    // within 3 % of the truth's.
    let want = (truth[0] - truth[1]) * truth_gradient;
    let got = products[0] - products[1];
    assert!((got / want - 1.0).abs() < 0.03, "{got} against {want}");

    // The words, in the terminal and on the page: the stated gradient in
    // °/g with its file and line, that the value scales inversely with it,
    // and the product per m/s² and in °/g.
    let row = said
        .lines()
        .find(|l| l.trim_start().starts_with("roll_steer "))
        .unwrap();
    let where_ = format!(
        "at the stated roll gradient of 3.00°/g (`[roll] gradient` = {stated}, {}:{line})",
        v.display()
    );
    for part in [
        where_.as_str(),
        "the value scales inversely with that gradient, and the runs determine only its product with it, ",
        "rad of front steer per m/s² of ay (-0.7",
        "rad of rear steer per m/s² of ay (0.2",
    ] {
        assert!(row.contains(part), "{part:?} in {row}");
    }
    let page = fs::read_to_string(out.join("report.html")).unwrap();
    assert!(page.contains("the value scales inversely with that gradient"));
}
