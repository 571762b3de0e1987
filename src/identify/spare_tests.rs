//! The rule of `spare.rs`: the held value, the guard, the stated value
//! tried first, and the words of a held line, on a straight line whose
//! least squares are known in closed form.

use super::*;
use crate::optim::bounded::BoundedLm;
use crate::optim::stats;
use nalgebra::DMatrix;

/// Within two standard errors of the free fit the stated value is
/// held; beyond, the end of the ±2 nearest it, clamped into bounds;
/// without a standard error, the stated value.
/// A value just past or short of the ±2 limit is not printed as
/// the limit: "2.04" outside, "1.96" within; others to one decimal.
#[test]
fn standard_errors_at_the_limit_keep_their_side_in_print() {
    assert_eq!(z_text(2.04), "2.04");
    assert_eq!(z_text(1.96), "1.96");
    assert_eq!(z_text(2.0004), "2.0004");
    assert_eq!(z_text(2.0), "2.0");
    assert_eq!(z_text(3.62), "3.6");
    // Not 0 where it is not: 0.04 standard errors is not "0.0".
    assert_eq!(z_text(0.04), "0.04");
    let line = held_at("the model's start value", 1.0, 1.0, Some(2.04));
    assert!(
        line.contains("which lies 2.04 standard errors from the free fit, outside the ±2"),
        "{line}"
    );
}

#[test]
fn a_held_value_is_the_stated_one_or_the_nearest_the_data_allow() {
    let wide = (-10.0, 10.0);
    // PAC89's lateral a7 on the Hoosier file: 0.009 standard errors.
    assert_eq!(held_value(0.77394, 0.9957, Some(24.4), wide), 0.77394);
    assert_eq!(held_value(3.0, 1.0, Some(1.0), wide), 3.0);
    // PAC89's aligning c9: stated −1.3329, free −0.1947 ± 0.317.
    // Its edge −0.8287, rounded towards the free fit to 0.001.
    assert_eq!(held_value(-1.3329, -0.1947, Some(0.317), wide), -0.828);
    // UniTire's aligning c9: stated 0.3, free 0.0002232 ± 0.00111, edge
    // 0.0024432.
    assert_eq!(held_value(0.3, 0.0002232, Some(0.00111), wide), 0.00244);
    // The edge past a bound is the bound.
    assert_eq!(held_value(5.0, 1.0, Some(1.0), (0.0, 2.5)), 2.5);
    assert_eq!(held_value(-5.0, 1.0, Some(1.0), (0.0, 2.5)), 0.0);
    // No standard error, or a useless one: the stated value.
    assert_eq!(held_value(3.0, 1.0, None, wide), 3.0);
    assert_eq!(held_value(3.0, 1.0, Some(0.0), wide), 3.0);
    assert_eq!(standard_errors_away(3.0, 1.0, Some(f64::NAN)), None);
}

/// The guard is what one parameter 2.25 standard errors off costs,
/// `½·2.25²·s²` with `s² = 2·cost/dof`, or σ rising by 5 %.
#[test]
fn the_guard_is_a_quarter_standard_error_past_the_edge_or_a_twentieth_of_sigma() {
    // cost 0.5 on 2 residuals, 1 free: s² = 1.
    assert!((guard(0.5, 2, 1) - 0.5 * 2.25 * 2.25).abs() < 1e-12);
    // cost 50 on 110 residuals, 10 free: s² = 1, but σ rising by 5 %
    // costs more, 50·(1.05² − 1).
    assert!((guard(50.0, 110, 10) - 5.125).abs() < 1e-9);
    // At least one degree of freedom.
    assert!((guard(1.0, 3, 5) - 2.0 * 0.5 * 2.25 * 2.25).abs() < 1e-12);
}

/// A straight line `a + b·x` through noisy points, with parameter
/// `held` (if any) held at its value.
struct Line {
    x: Vec<f64>,
    y: Vec<f64>,
    held: Option<(usize, f64)>,
}

impl Line {
    fn full(&self, p: &[f64]) -> [f64; 2] {
        match self.held {
            Some((0, v)) => [v, p[0]],
            Some((_, v)) => [p[0], v],
            None => [p[0], p[1]],
        }
    }
}

impl Residuals for Line {
    fn count(&self) -> usize {
        self.x.len()
    }
    fn residuals(&self, p: &[f64], out: &mut [f64]) {
        let [a, b] = self.full(p);
        for ((o, x), y) in out.iter_mut().zip(&self.x).zip(&self.y) {
            *o = a + b * x - y;
        }
    }
}

/// The line's free fit: its problem, optimum and standard errors.
fn line() -> (Line, Vec<f64>, Vec<Option<f64>>) {
    let x: Vec<f64> = (0..40).map(|i| f64::from(i) / 20.0).collect();
    let y = x
        .iter()
        .enumerate()
        .map(|(i, x)| 1.0 + 0.5 * x + 0.05 * (3.7 * i as f64).sin())
        .collect();
    let line = Line { x, y, held: None };
    // The least-squares line, in closed form.
    let n = line.count() as f64;
    let (mx, my) = (
        line.x.iter().sum::<f64>() / n,
        line.y.iter().sum::<f64>() / n,
    );
    let sxy: f64 = line
        .x
        .iter()
        .zip(&line.y)
        .map(|(x, y)| (x - mx) * (y - my))
        .sum();
    let sxx: f64 = line.x.iter().map(|x| (x - mx) * (x - mx)).sum();
    let b = sxy / sxx;
    let p = vec![my - b * mx, b];
    let j = DMatrix::from_fn(line.count(), 2, |i, c| if c == 0 { 1.0 } else { line.x[i] });
    let c = stats::covariance(&j, 2.0 * line.cost(&p)).unwrap();
    let se = vec![Some(c[(0, 0)].sqrt()), Some(c[(1, 1)].sqrt())];
    (line, p, se)
}

/// One round of holds on the line, each parameter's stated value
/// `stated`, within `bounds`; a parameter `known` false has no
/// standard error (as along a singular direction).
fn round(
    stated: [f64; 2],
    bounds: [(f64, f64); 2],
    known: [bool; 2],
    candidates: &[usize],
) -> Spared<Line> {
    round_tried(stated, bounds, known, candidates, false)
}

/// [`round`], the stated value tried first where `stated_first`.
fn round_tried(
    stated: [f64; 2],
    bounds: [(f64, f64); 2],
    known: [bool; 2],
    candidates: &[usize],
    stated_first: bool,
) -> Spared<Line> {
    let (line, p, se) = line();
    let se: Vec<Option<f64>> = se.iter().zip(known).map(|(s, k)| s.filter(|_| k)).collect();
    let fit = HoldFit {
        problem: &line,
        p: &p,
        std_errors: &se,
        bounds: &bounds,
        clamp_starts: true,
        tie: TieBreak::LeastDetermined,
        guarded: true,
        stated_first,
    };
    let ways = HoldWays {
        without: |k: usize, v: f64| Line {
            x: line.x.clone(),
            y: line.y.clone(),
            held: Some((k, v)),
        },
        stated: |k: usize| stated[k],
        compensating: |k: usize, dv: f64| {
            let mut d = vec![0.0; 2];
            d[k] = dv;
            d
        },
        refit: |sub: &Line, x: &[f64], b: &[(f64, f64)]| BoundedLm::default().minimize(sub, x, b),
    };
    spare(&fit, candidates, &ways)
}

/// A stated value far out is held at the edge of the ±2 standard
/// errors, which costs `2s²` on a line and passes the guard; the same
/// value clamped by a bound ten standard errors out costs `50s²` and
/// is refused, as is one held where stated for want of a standard
/// error, leaving the parameter free; one within the ±2 is held where
/// stated.
#[test]
fn a_hold_the_data_reject_is_refused_and_one_they_allow_kept() {
    let (line, p, se) = line();
    let (sa, sb) = (se[0].unwrap(), se[1].unwrap());
    let wide = [(-100.0, 100.0); 2];
    let s2 = 2.0 * line.cost(&p) / (line.count() - 2) as f64;
    let edge = round([p[0] - 100.0 * sa, 0.0], wide, [true; 2], &[0]);
    let kept = edge.kept.as_ref().expect("the edge hold is kept");
    // At the edge, rounded towards the fit by at most a hundredth of
    // a standard error: z in [1.99, 2], a rise of ½z²s².
    let inside = kept.value - (p[0] - 2.0 * sa);
    assert!((0.0..=0.01 * sa).contains(&inside), "{inside}");
    let rise = kept.cost - line.cost(&p);
    assert!((1.98..=2.0 + 1e-6).contains(&(rise / s2)), "{}", rise / s2);
    assert!(edge.refused.is_empty());
    // Clamped ten standard errors out: refused, and nothing kept.
    let narrow = [(p[0] + 10.0 * sa, 100.0), (-100.0, 100.0)];
    let clamped = round([100.0, 0.0], narrow, [true; 2], &[0]);
    assert!(clamped.kept.is_none() && clamped.refused == vec![0]);
    // Held where stated, far out, for want of a standard error:
    // refused; the slope, stated one standard error off, is held where
    // stated.
    let both = round([p[0] + 100.0 * sa, p[1] + sb], wide, [false, true], &[0, 1]);
    assert_eq!(both.refused, vec![0]);
    let kept = both.kept.expect("the slope's hold is kept");
    assert_eq!((kept.k, kept.value), (1, p[1] + sb));
}

/// Tried first, a stated value 2.1 standard errors off costs
/// `½·2.1²·s² ≈ 2.2s²`, within the guard (`2.53s²` on the line's 38
/// degrees of freedom): held where stated, where the edge rule held it
/// at the ±2 edge; one 3 standard errors off costs `4.5s²`, refused,
/// and held at the edge. The words say which.
#[test]
fn a_stated_value_the_guard_allows_is_held_where_stated_before_the_edge() {
    let (_, p, se) = line();
    let sa = se[0].unwrap();
    let wide = [(-100.0, 100.0); 2];
    let near = [p[0] - 2.1 * sa, 0.0];
    let edge = round_tried(near, wide, [true; 2], &[0], false)
        .kept
        .unwrap();
    assert!(edge.value > near[0], "{}", edge.value);
    let tried = round_tried(near, wide, [true; 2], &[0], true).kept.unwrap();
    assert_eq!(tried.value, near[0]);
    let far = [p[0] - 3.0 * sa, 0.0];
    let refused = round_tried(far, wide, [true; 2], &[0], true).kept.unwrap();
    assert!(
        (refused.value - (p[0] - 2.0 * sa)).abs() <= 0.01 * sa,
        "{}",
        refused.value
    );
    let line = held_at_tried("the template's value", 1.0, 1.0, Some(2.1));
    assert!(
        line.ends_with("it costs no more than the data allow (within the guard)"),
        "{line}"
    );
    let line = held_at_tried("the template's value", 1.0, 0.5, Some(3.0));
    assert!(
        line.contains(
            "held there first, with the rest refitted, it raised the cost past what a hold may"
        ),
        "{line}"
    );
}

/// A held line says the value held and the stated one, and the option
/// that holds another when they differ.
#[test]
fn a_held_line_says_the_value_held_and_the_stated_one() {
    let start = "the model's start value";
    let away = standard_errors_away(-1.3329, -0.1947, Some(0.317));
    assert!((away.unwrap() - 3.5905).abs() < 1e-3, "{away:?}");
    let held = held_value(-1.3329, -0.1947, Some(0.317), (-10.0, 10.0));
    assert_eq!(
        held_at(start, -1.3329, held, away),
        "held at -0.828, the end of the free fit's ±2 standard errors nearest the model's start value -1.3329 (which lies 3.6 standard errors from the free fit, by its linearisation)"
    );
    assert_eq!(
        lean_clause("c9", -1.3329, held, away),
        "; to hold it at a value of your own, give --hold c9=VALUE"
    );
    let away = standard_errors_away(0.0, 0.003344, Some(0.0107));
    assert_eq!(
        held_at(start, 0.0, 0.0, away),
        "held at the model's start value 0, 0.3 standard errors from the free fit (within the ±2 standard errors the data allow)"
    );
    assert_eq!(lean_clause("c6", 0.0, 0.0, away), "");
    assert_eq!(
        held_at(start, 10.0, 10.0, None),
        "held at the model's start value 10"
    );
    assert_eq!(lean_clause("c10", 10.0, 10.0, None), "");
}
