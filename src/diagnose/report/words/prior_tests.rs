//! The prior line's words: where the identified axles lie on the prior.

use super::*;

#[test]
fn an_axle_within_the_prior_but_near_its_edge_is_said_to_lie_there() {
    use crate::diagnose::base::prior::{AgainstPrior, FrictionRule, PriorReport, Tempering};
    use crate::diagnose::campaign::prior::{AxlePrior, TyreClass};
    let prior = AxlePrior::of(TyreClass::RacingSlick);
    let report = |front: f64| PriorReport {
        prior,
        // The runs reach 6 m/s², below 0.8 of the lowest grip: the peak
        // friction is held at the centre, not placed on the prior.
        friction_rule: FrictionRule::new(&prior, 6.0),
        against: [
            AgainstPrior::new(front, prior.cornering),
            AgainstPrior::new(24.5, prior.cornering),
            AgainstPrior::new(AxlePrior::centre(prior.friction), prior.friction),
        ],
        tempering: Tempering::NONE,
    };
    // Putnam's front, 12.0 on the racing slicks' 12–50 1/rad: z = −1.96,
    // "within" by a hair; 24.5 is at the centre.
    let edge = prior_line(&report(12.05));
    assert!(
        edge.contains("front 12.050 lies near its edge (-1.9"),
        "{edge}"
    );
    assert!(!edge.contains("rear"), "{edge}");
    assert!(!edge.contains("lie within it"), "{edge}");
    let outside = prior_line(&report(11.0));
    assert!(
        outside.contains("front 11.000 is outside it (-2."),
        "{outside}"
    );
    let centre = prior_line(&report(24.0));
    assert!(
        centre.ends_with("the axles lie within it, inside ±1.5 σ of its centre"),
        "{centre}"
    );
    assert!(
        centre.contains("peak friction held at 1.47 (the geometric mean of its range)"),
        "{centre}"
    );
}
