//! A vehicle layout no car has, said by `simulate` before its numbers are
//! read: a centre of gravity within [`LEAST_AXLE_SHARE`] of the wheelbase
//! of an axle (the other axle then carries almost none of the weight),
//! and a radius of gyration `k = √(Iz/m)` outside [`GYRATION_SHARE`] of
//! the wheelbase. Both pass the input checks where they pass each other:
//! the dynamic index `Iz/(m·a·b)` of a car with `a` = 0.01 m and
//! `Iz` = 40 kg·m² is 0.94, a road car's, while its `k` is 0.16 m on a
//! 2.78 m wheelbase (found by a fresh user, run without a word).
//!
//! The bounds are the project's rules, wide of the cars they are drawn
//! from: road and racing cars carry about 35–65 % of their weight on each
//! axle, and their dynamic index `k²/(a·b)` is about 0.8–1.2 for road
//! cars and 0.6 for a racing car (Milliken & Milliken 1995, *Race Car
//! Vehicle Dynamics*), which with the centre of gravity between 40 and
//! 60 % of the wheelbase puts `k` at about 0.38–0.55 of it (a bus with
//! its overhangs, index 1.5, at about 0.6). Units: m, kg, kg·m²; printed
//! as shares of the wheelbase in %.

use crate::vehicle::Vehicle;

/// The least share of the weight an axle carries statically, and so the
/// least share of the wheelbase between the centre of gravity and the
/// other axle, below which the layout is said: 10 %.
pub(super) const LEAST_AXLE_SHARE: f64 = 0.10;

/// The radius of gyration's range as a share of the wheelbase, outside
/// which the yaw inertia is said: 0.3–0.7.
pub(super) const GYRATION_SHARE: (f64, f64) = (0.3, 0.7);

/// The warnings on `v`'s layout: one sentence each, none for a car's.
pub(super) fn layout_warnings(v: &Vehicle) -> Vec<String> {
    let l = v.a + v.b;
    let mut out = Vec::new();
    // The rear axle carries a/l of the weight, the front b/l: a CG near
    // one axle leaves the other unloaded.
    for (axle, near, far) in [("front", v.a, "rear"), ("rear", v.b, "front")] {
        let share = near / l;
        if share < LEAST_AXLE_SHARE {
            out.push(format!(
                "the centre of gravity is {} m from the {axle} axle, {} % of the {} m wheelbase: the {far} axle carries {} % of the weight at rest ({} N of {} N), where road and racing cars carry about 35–65 % on each axle (Milliken & Milliken 1995; the project warns below {:.0} %): an axle with almost no load has almost no grip, and the response is no car's; check `a` and `b` (m, from the centre of gravity to each axle)",
                crate::format::rounded(near, 3),
                crate::format::significant(100.0 * share, 2),
                crate::format::rounded(l, 3),
                crate::format::significant(100.0 * share, 2),
                crate::format::rounded(share * v.mass * crate::constants::G, 3),
                crate::format::rounded(v.mass * crate::constants::G, 3),
                100.0 * LEAST_AXLE_SHARE
            ));
        }
    }
    let k = (v.yaw_inertia / v.mass).sqrt();
    let share = k / l;
    if share < GYRATION_SHARE.0 || share > GYRATION_SHARE.1 {
        out.push(format!(
            "the radius of gyration √(yaw_inertia/mass) is {} m, {} % of the {} m wheelbase, outside the {:.0}–{:.0} % the project allows (cars lie at about 38–55 %: a dynamic index k²/(a·b) of 0.6–1.2, Milliken & Milliken 1995, with the centre of gravity between 40 and 60 % of the wheelbase): a yaw inertia of {} kg·m² would put it at half the wheelbase; check `yaw_inertia` and `mass` (kg·m², kg)",
            crate::format::rounded(k, 3),
            crate::format::significant(100.0 * share, 2),
            crate::format::rounded(l, 3),
            100.0 * GYRATION_SHARE.0,
            100.0 * GYRATION_SHARE.1,
            crate::format::rounded(v.mass * (0.5 * l).powi(2), 3)
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn car(a: f64, b: f64, yaw_inertia: f64) -> Vehicle {
        Vehicle {
            mass: 1530.0,
            yaw_inertia,
            a,
            b,
            track_front: 1.55,
            track_rear: 1.55,
            cg_height: 0.55,
            wheelbase: None,
            load_transfer_front_share: None,
            steering_ratio: None,
        }
    }

    #[test]
    fn the_bundled_sedan_is_said_nothing_of() {
        // k = √(2315/1530) = 1.23 m, 44 % of 2.78 m; 40/60 on the axles.
        assert!(layout_warnings(&car(1.11, 1.67, 2315.0)).is_empty());
    }

    #[test]
    fn a_centre_of_gravity_on_an_axle_and_a_point_mass_inertia_are_said() {
        // The user's car: a = 0.01 m of 2.78 m, k = √(40/1530) = 0.162 m.
        let w = layout_warnings(&car(0.01, 2.77, 40.0));
        assert_eq!(w.len(), 2, "{w:?}");
        assert!(
            w[0].starts_with("the centre of gravity is 0.01 m from the front axle, 0.36 % of the 2.78 m wheelbase: the rear axle carries 0.36 % of the weight"),
            "{}",
            w[0]
        );
        assert!(
            w[1].starts_with("the radius of gyration √(yaw_inertia/mass) is 0.162 m, 5.8 % of the 2.78 m wheelbase"),
            "{}",
            w[1]
        );
        // Mirrored: the rear axle named, the front unloaded.
        let w = layout_warnings(&car(2.77, 0.01, 2315.0));
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(
            w[0].contains("from the rear axle") && w[0].contains("the front axle carries 0.36 %")
        );
    }
}
