//! The closed-form equilibrium residual against the one right-hand side:
//! at random states, conditions and settings of every effect it takes, its
//! value is [`VehicleModel::rates`] with the load-transfer loop stopped at
//! the equilibrium's ay = u·r + g·sin θ, and its Jacobian that function's
//! central differences; each effect it leaves out
//! ([`Effects::beyond_equilibrium_residual`]) is named when on and moves the
//! right-hand side away from it.

use super::*;
use crate::tyre::MagicSimple;
use proptest::prelude::*;

/// (β̇, ṙ) of the one right-hand side with the wheel loads at the
/// equilibrium's lateral acceleration (an infinite tolerance stops the
/// load-transfer loop after its first evaluation, at the seed).
fn rhs_at_equilibrium_loads(m: &VehicleModel, x: [f64; 2], inp: &Inputs) -> [f64; 2] {
    let ay = inp.speed.max(MIN_SPEED) * x[1] + m.bank_acceleration();
    let mut seed = LoadTransferSeed {
        ay: [ay; 3],
        slope: 1.0,
    };
    let state = State {
        beta: x[0],
        yaw_rate: x[1],
    };
    let o = m.evaluate_to(&state, inp, &mut seed, f64::INFINITY);
    [o.beta_rate, o.yaw_acceleration]
}

fn closed_form(m: &VehicleModel, x: [f64; 2], inp: &Inputs) -> ([f64; 2], [[f64; 2]; 2]) {
    let state = State {
        beta: x[0],
        yaw_rate: x[1],
    };
    m.equilibrium_residual(&state, inp)
}

/// The sedan on PAC89 (closed-form tyre partials) or a simplified Magic
/// Formula (differenced tyre partials).
fn model(pac89: bool, exact: bool, load_transfer: bool, effects: Effects) -> VehicleModel {
    let tyre = if pac89 {
        Tyre::Pac89(Pac89::adams_example())
    } else {
        Tyre::MagicSimple(MagicSimple::new(10.0, 1.3))
    };
    let mut m = VehicleModel::new(sedan(), tyre.clone(), tyre);
    m.options = ModelOptions {
        kinematics: if exact {
            Kinematics::Exact
        } else {
            Kinematics::SmallAngle
        },
        load_transfer,
        effects,
    };
    m
}

prop_compose! {
    /// Every effect the closed form takes, each on or off at random.
    fn taken_effects()(
        aero in prop::array::uniform2(0.0f64..1.5),
        bank in -0.12f64..0.12,
        bank_profile_scale in 0.0f64..1.5,
        relaxation_length in prop_oneof![Just(0.0), 0.05f64..1.0],
        longitudinal in 0.0f64..1.0,
        shares in prop::option::of((0.0f64..1.0, 0.0f64..1.0, 0.0f64..1.5)),
        roll in (0.0f64..0.02, 0.5f64..3.0, 0.2f64..1.2),
    ) -> Effects {
        Effects {
            aero_load: aero,
            road_bank: bank,
            bank_profile_scale,
            relaxation_length,
            longitudinal_load_transfer: longitudinal,
            combined_slip: shares.map(|(d, b, s)| CombinedSlip {
                drive_front_share: d,
                brake_front_share: b,
                force_share: s,
            }),
            roll: RollModel {
                gradient: roll.0,
                frequency: roll.1,
                damping: roll.2,
            },
            ..Effects::default()
        }
    }
}

proptest! {
    #[test]
    fn the_closed_form_is_the_right_hand_side_at_the_equilibrium_loads(
        effects in taken_effects(),
        pac89 in any::<bool>(),
        exact in any::<bool>(),
        load_transfer in any::<bool>(),
        beta in -0.15f64..0.15,
        // Lateral accelerations u·r within ±6 m/s²: no wheel lifts, so the
        // loads are smooth in r and central differences hold.
        ay in -6.0f64..6.0,
        steer in -0.1f64..0.1,
        friction in 0.5f64..1.2,
        speed in 5.0f64..40.0,
    ) {
        let m = model(pac89, exact, load_transfer, effects);
        prop_assert!(effects.beyond_equilibrium_residual().is_empty());
        let inp = Inputs::steady(steer, speed, friction);
        let x = [beta, ay / speed];
        let (f, j) = closed_form(&m, x, &inp);
        let f_ref = rhs_at_equilibrium_loads(&m, x, &inp);
        for i in 0..2 {
            // The same function, summed in another order.
            prop_assert!(
                (f[i] - f_ref[i]).abs() <= 1e-12 * (1.0 + f_ref[i].abs()),
                "{:?} vs {:?}", f, f_ref
            );
        }
        for k in 0..2 {
            let h = 1e-6;
            let (mut xp, mut xm) = (x, x);
            xp[k] += h;
            xm[k] -= h;
            let (fp, fm) = (
                rhs_at_equilibrium_loads(&m, xp, &inp),
                rhs_at_equilibrium_loads(&m, xm, &inp),
            );
            for i in 0..2 {
                let fd = (fp[i] - fm[i]) / (2.0 * h);
                // Central differences are good to ~1e-8 relative here; the
                // simplified Magic Formula's own forward differences to ~1e-5.
                let tol = if pac89 { 1e-6 } else { 1e-4 };
                prop_assert!(
                    (j[i][k] - fd).abs() <= tol * (1.0 + fd.abs()),
                    "J[{}][{}] {} vs {}", i, k, j[i][k], fd
                );
            }
        }
    }
}

#[test]
fn each_effect_the_closed_form_leaves_out_is_named_and_moves_the_right_hand_side() {
    // An effect's key and how to switch it on.
    type Switch = (&'static str, fn(&mut Effects));
    let left_out: [Switch; 4] = [
        ("steering_compliance", |e| e.steering_compliance = 2e-6),
        ("roll_steer", |e| e.roll_steer = [0.1, -0.05]),
        ("roll_camber", |e| e.roll_camber = [0.1, 0.1]),
        ("cornering_stiffness_scale", |e| {
            e.cornering_stiffness_scale = [1.2, 0.9]
        }),
    ];
    let inp = Inputs::steady(0.04, 20.0, 1.0);
    let x = [0.01, 0.2];
    for (key, switch_on) in left_out {
        let mut effects = Effects::default();
        switch_on(&mut effects);
        assert_eq!(effects.beyond_equilibrium_residual(), vec![key]);
        let m = model(true, true, true, effects);
        let (f, _) = closed_form(&m, x, &inp);
        let f_ref = rhs_at_equilibrium_loads(&m, x, &inp);
        let gap = (0..2)
            .map(|i| (f[i] - f_ref[i]).abs() / (1.0 + f_ref[i].abs()))
            .fold(0.0, f64::max);
        assert!(
            gap > 1e-4,
            "{key}: the closed form is within {gap:e} of the right-hand side"
        );
    }
    // With none of them on, the two agree here too.
    let m = model(true, true, true, Effects::default());
    let (f, _) = closed_form(&m, x, &inp);
    let f_ref = rhs_at_equilibrium_loads(&m, x, &inp);
    assert!((0..2).all(|i| (f[i] - f_ref[i]).abs() <= 1e-12 * (1.0 + f_ref[i].abs())));
}
