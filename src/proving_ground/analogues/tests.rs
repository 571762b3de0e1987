//! Tests of the analogues: their drivers stay on the line, their built-in
//! effects, and runs lengthened to a duration.

use super::*;
use crate::proving_ground::programme::truth_vehicle;
use crate::proving_ground::truth::truth_tyre;
use crate::vehicle::VehicleModel;

/// The truth of `programme` without effects, its built-in ones in.
fn truth(programme: Programme) -> Augmented {
    let tyre = truth_tyre();
    let mut base = VehicleModel::new(truth_vehicle(programme), tyre.clone(), tyre);
    base.options.effects.aero_load = super::super::programme::truth_downforce(programme);
    let mut t = Augmented::new(base, 1.0);
    build_in(programme, &mut t, &[]);
    t
}

#[test]
fn the_drivers_keep_their_cars_on_the_line() {
    for (programme, plan, largest) in [
        // Within its lane (half of 3.5 m) by hand; the racing car on a
        // wider track.
        (Programme::SedanWinding, sedan_plan(2), 1.75),
        (Programme::RacingRearSteer, racing_plan(2), 2.5),
    ] {
        let t = truth(programme);
        for run in &plan.runs {
            let track = Track::new(&run.pieces);
            let (d, b) = plan.pedals;
            let (u, ax) = track.drive(run.start, run.parked, run.duration, STEP, d, b);
            let cl = drive(&t, &track, &plan.driver, &plan.steering, &u, &ax, STEP);
            assert!(
                cl.largest_offset < largest,
                "{}: {:.2} m off the line",
                run.name,
                cl.largest_offset
            );
            // The car went round: its yaw rate both ways.
            let r = &cl.history.yaw_rate;
            assert!(r.iter().any(|&x| x > 0.2) && r.iter().any(|&x| x < -0.2));
        }
    }
}

#[test]
fn a_lengthened_analogue_lasts_the_duration_asked_on_tracks_long_enough() {
    assert_eq!(analogue_duration(Programme::SedanWinding), Some(370.0));
    assert_eq!(analogue_duration(Programme::RacingRearSteer), Some(300.0));
    assert_eq!(analogue_duration(Programme::SlowOval), None);
    for programme in [Programme::SedanWinding, Programme::RacingRearSteer] {
        // Its own length asked: its own runs.
        let own = plan_lasting(programme, None).unwrap();
        let same = plan_lasting(programme, analogue_duration(programme)).unwrap();
        let durations = |p: &Plan| p.runs.iter().map(|r| r.duration).collect::<Vec<_>>();
        assert_eq!(durations(&same), durations(&own));
        for total in [600.0, 1234.0] {
            let plan = plan_lasting(programme, Some(total)).unwrap();
            let d = durations(&plan);
            assert_eq!(d.iter().sum::<f64>(), total, "{d:?}");
            // In proportion to the runs' own, to a second.
            for (r, o) in d.iter().zip(durations(&own)) {
                let share = o / analogue_duration(programme).unwrap();
                assert!((r - share * total).abs() <= 1.0, "{d:?}");
            }
            // Every run's track is long enough to drive (`Track::drive`
            // asserts it), at its own parked time and start.
            for run in &plan.runs {
                let (dr, br) = plan.pedals;
                let track = Track::new(&run.pieces);
                let (u, _) = track.drive(run.start, run.parked, run.duration, STEP, dr, br);
                assert_eq!(u.len(), (run.duration / STEP).round() as usize + 1);
            }
        }
    }
}

#[test]
fn the_racing_truth_steers_its_rear_with_roll_and_the_sedan_has_none() {
    let racing = truth(Programme::RacingRearSteer);
    assert_eq!(racing.effects().roll_steer, [0.0, REAR_ROLL_STEER]);
    assert_eq!(racing.effects().roll, RACING_ROLL);
    let mut asked = truth(Programme::SedanWinding);
    assert_eq!(asked.effects().roll_steer, [0.0; 2]);
    // Roll steer asked for replaces the built-in one.
    asked.effects_mut().roll_steer = [-0.1, 0.0];
    build_in(
        Programme::RacingRearSteer,
        &mut asked,
        &[EffectKind::RollSteer],
    );
    assert_eq!(asked.effects().roll_steer, [-0.1, 0.0]);
}
