//! `separation.png` measured on what it draws: every candidate in a look
//! of its own, named in the key, the same in every panel; the steer and
//! the speed each on an axis of its own range.

use super::*;
use crate::diagnose::model::Observed;
use crate::report::plot::Axes;

/// A sweep of ±0.43° at 21 m/s, predicted for a reference and four
/// look-alikes (the road course's confounded set of four and more).
fn prediction(members: usize) -> Prediction {
    let times: Vec<f64> = (0..200).map(|i| 0.05 * i as f64).collect();
    let steer: Vec<f64> = times
        .iter()
        .map(|t| 0.43f64.to_radians() * (2.0 * t).sin())
        .collect();
    let response = |k: usize| Observed {
        yaw_rate: steer.iter().map(|d| (2.0 + 0.01 * k as f64) * d).collect(),
        ay: steer.iter().map(|d| (40.0 + 0.1 * k as f64) * d).collect(),
        beta: steer.iter().map(|d| (0.1 + 0.001 * k as f64) * d).collect(),
        roll: vec![0.0; steer.len()],
    };
    Prediction {
        name: "sweep_075kph".into(),
        speed: vec![20.9; times.len()],
        members: (0..members)
            .map(|k| (format!("candidate_{k}"), response(k)))
            .collect(),
        steer,
        times,
    }
}

/// Two look-alikes were drawn alike (dotted, one colour per channel, in
/// the difference panel; the fourth member's dotted line as the third's):
/// now every member has a colour of its own, the same in every panel,
/// and a key entry naming it.
#[test]
fn every_candidate_is_drawn_in_a_look_of_its_own_and_named_in_the_key() {
    for n in [2, 5, 9, 24] {
        let looks: Vec<_> = (0..n).map(member_look).collect();
        for (k, a) in looks.iter().enumerate() {
            assert!(!looks[..k].contains(a), "member {k} of {n}: {looks:?}");
        }
    }
    let p = prediction(5);
    let panels = prediction_panels(&p, &[true, true, true], &[0.01, 0.05, 0.002], 1.2);
    // Three channels, the difference, the steer, the speed.
    assert_eq!(panels.len(), 6);
    for panel in &panels[..3] {
        let colours: Vec<usize> = panel.series.iter().map(|s| s.color).collect();
        let labels: Vec<&str> = panel.series.iter().map(|s| s.label.as_str()).collect();
        assert_eq!(
            labels,
            (0..5).map(|k| format!("candidate_{k}")).collect::<Vec<_>>(),
            "{}",
            panel.title
        );
        for (k, c) in colours.iter().enumerate() {
            assert!(!colours[..k].contains(c), "{}: {colours:?}", panel.title);
            assert_eq!(*c, member_look(k).0);
        }
    }
    // The difference panel: each look-alike in its colour, a style per
    // channel, no two series alike, each named.
    let diff = &panels[3];
    let looks: Vec<(usize, Style)> = diff
        .series
        .iter()
        .filter(|s| !s.label.is_empty() && s.label != "±1 noise floor")
        .map(|s| (s.color, s.style))
        .collect();
    assert_eq!(looks.len(), 4 * 3);
    for (k, a) in looks.iter().enumerate() {
        assert!(!looks[..k].contains(a), "{looks:?}");
    }
    for s in diff
        .series
        .iter()
        .filter(|s| s.label.starts_with("candidate_"))
    {
        let k: usize = s.label["candidate_".len()..]
            .split(':')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        assert_eq!(s.color, member_look(k).0, "{}", s.label);
    }
}

/// A ±0.43° steer was drawn on the speed's 0–21 axis: the steer and the
/// speed now have panels of their own, each axis spanning its data.
#[test]
fn the_steer_and_the_speed_each_have_an_axis_of_their_own_range() {
    let p = prediction(2);
    let panels = prediction_panels(&p, &[true, true, false], &[0.01, 0.05, 0.0], 27.0);
    let steer = panels.iter().find(|q| q.y_label == "steer, °").unwrap();
    let speed = panels.iter().find(|q| q.y_label == "speed, m/s").unwrap();
    assert_eq!(steer.series.len(), 1);
    assert_eq!(speed.series.len(), 1);
    let Axes { y, .. } = steer.axes();
    // The steer's ±0.43° fills its axis: the axis spans no more than
    // twice the data's range.
    assert!(y.0 < -0.42 && y.1 > 0.42, "{y:?}");
    assert!(y.1 - y.0 < 2.0 * 0.86, "{y:?}");
    let Axes { y, .. } = speed.axes();
    assert!(y.0 <= 20.9 && y.1 >= 20.9 && y.0 > 15.0, "{y:?}");
}

/// The steer and speed panels were drawn in the first two candidates'
/// colours (blue, red): an input read as a candidate's response. They are
/// drawn in black, a colour no candidate has.
#[test]
fn the_steer_and_speed_are_drawn_in_a_colour_no_candidate_has() {
    let p = prediction(24);
    let panels = prediction_panels(&p, &[true, true, true], &[0.01, 0.05, 0.002], 1.2);
    let candidates: Vec<usize> = (0..24).map(|k| member_look(k).0).collect();
    for panel in &panels[4..] {
        for s in &panel.series {
            assert_eq!(s.color, crate::report::plot::INK, "{}", panel.title);
            assert!(!candidates.contains(&s.color), "{}", panel.title);
        }
    }
}
