//! The longitudinal effects and the measured bank: load transfer from ax
//! against `m·ax·h/l`, combined slip against the friction circle in closed
//! form, the bank profile against the constant bank, each bit-identical when
//! off.

use super::*;

/// Inputs of straight running at `speed` with longitudinal acceleration
/// `ax` (and du/dt = ax).
fn accelerating(speed: f64, steer: f64, ax: f64) -> Inputs {
    Inputs {
        speed_rate: ax,
        ax,
        ..Inputs::steady(steer, speed, 1.0)
    }
}

#[test]
fn longitudinal_load_transfer_moves_m_ax_h_over_l_between_the_axles() {
    let mut m = nonlinear_model();
    let v = m.vehicle.clone();
    let (sf, sr) = v.static_axle_loads();
    let x = State::default();
    // Off, the longitudinal acceleration moves no load.
    let off = m.evaluate(&x, &accelerating(20.0, 0.0, -6.0)).fz;
    assert_eq!(off, m.evaluate(&x, &Inputs::steady(0.0, 20.0, 1.0)).fz);
    m.options.effects.longitudinal_load_transfer = 1.0;
    for ax in [-6.0, 3.0] {
        let fz = m.evaluate(&x, &accelerating(20.0, 0.0, ax)).fz;
        let d = v.mass * ax * v.cg_height / v.wheelbase();
        assert_relative_eq!(fz[0], 0.5 * (sf - d), max_relative = 1e-12);
        assert_relative_eq!(fz[1], 0.5 * (sf - d), max_relative = 1e-12);
        assert_relative_eq!(fz[2], 0.5 * (sr + d), max_relative = 1e-12);
        assert_relative_eq!(fz.iter().sum::<f64>(), sf + sr, max_relative = 1e-12);
    }
    // A deceleration beyond what the rear axle carries lifts it, no more.
    let fz = m.evaluate(&x, &accelerating(20.0, 0.0, -100.0)).fz;
    assert_eq!([fz[2], fz[3]], [0.0, 0.0]);
    assert_relative_eq!(fz[0] + fz[1], sf + sr, max_relative = 1e-12);
    // At ax = 0 the effect changes nothing, to the bit.
    let steady = Inputs::steady(0.05, 20.0, 1.0);
    let y = State {
        beta: 0.01,
        yaw_rate: 0.2,
    };
    assert_eq!(
        m.evaluate(&y, &steady),
        nonlinear_model().evaluate(&y, &steady)
    );
}

#[test]
fn a_measured_bank_acts_as_the_constant_bank() {
    let (mut constant, mut measured) = (nonlinear_model(), nonlinear_model());
    constant.options.effects.road_bank = 0.2;
    // Off by default: a measured profile reaches the model only when asked.
    let x0 = State::default();
    let banked = Inputs {
        bank: 0.2,
        ..Inputs::steady(0.0, 25.0, 1.0)
    };
    assert_eq!(
        measured.evaluate(&x0, &banked),
        measured.evaluate(&x0, &Inputs::steady(0.0, 25.0, 1.0))
    );
    measured.options.effects.bank_profile_scale = 1.0;
    let x = State {
        beta: 0.01,
        yaw_rate: 0.15,
    };
    let inp = Inputs::steady(0.04, 25.0, 1.0);
    let with_profile = Inputs { bank: 0.2, ..inp };
    assert_eq!(
        constant.evaluate(&x, &inp),
        measured.evaluate(&x, &with_profile)
    );
    // And the two add, the profile scaled.
    constant.options.effects.bank_profile_scale = 0.5;
    let both = Inputs { bank: -0.4, ..inp };
    assert_eq!(
        constant.evaluate(&x, &both).fz,
        measured.evaluate(&x, &inp).fz
    );
    assert_relative_eq!(
        constant.evaluate(&x, &both).beta_rate,
        measured.evaluate(&x, &inp).beta_rate,
        max_relative = 1e-12
    );
}

#[test]
fn combined_slip_takes_the_longitudinal_force_from_each_wheels_friction_circle() {
    use crate::tyre::MagicSimple;
    let tyre = Tyre::MagicSimple(MagicSimple {
        b: 10.0,
        c: 1.3,
        d: 1.0,
    });
    let mut m = VehicleModel::new(sedan(), tyre.clone(), tyre);
    let mass = m.vehicle.mass;
    let x = State {
        beta: 0.0,
        yaw_rate: 0.1,
    };
    let pure = m.evaluate(&x, &accelerating(20.0, 0.05, -4.0));
    let split = CombinedSlip {
        drive_front_share: 0.0,
        brake_front_share: 0.7,
        force_share: 1.0,
    };
    m.options.effects.combined_slip = Some(split);
    // Off the throttle and brakes the lateral forces are the pure ones.
    let coasting = Inputs::steady(0.05, 20.0, 1.0);
    assert_eq!(
        m.evaluate(&x, &coasting),
        nonlinear_free(&m).evaluate(&x, &coasting)
    );
    // Braking at 4 m/s²: each front wheel brakes with 0.7·m·4/2, each rear
    // wheel with 0.3·m·4/2, and keeps √(1 − (Fx/(D·Fz))²) of its force.
    let o = m.evaluate(&x, &accelerating(20.0, 0.05, -4.0));
    let keep = |fx: f64, fz: f64| (1.0 - (fx / fz).powi(2)).sqrt();
    let wheel = |alpha: f64, fz: f64| fz * (1.3 * (10.0 * alpha).atan()).sin();
    let (ff, fr) = (0.5 * 0.7 * mass * 4.0, 0.5 * 0.3 * mass * 4.0);
    let front = wheel(o.alpha_front, o.fz[0]) * keep(ff, o.fz[0])
        + wheel(o.alpha_front, o.fz[1]) * keep(ff, o.fz[1]);
    let rear = wheel(o.alpha_rear, o.fz[2]) * keep(fr, o.fz[2])
        + wheel(o.alpha_rear, o.fz[3]) * keep(fr, o.fz[3]);
    assert_relative_eq!(o.fy_front, front, max_relative = 1e-12);
    assert_relative_eq!(o.fy_rear, rear, max_relative = 1e-12);
    assert!(o.fy_front < pure.fy_front && o.fy_rear < pure.fy_rear);
    // Rear-wheel drive: accelerating takes force from the rear axle only.
    let o = m.evaluate(&x, &accelerating(20.0, 0.05, 2.0));
    let pure = nonlinear_free(&m).evaluate(&x, &accelerating(20.0, 0.05, 2.0));
    assert_eq!(o.fy_front, pure.fy_front);
    assert!(o.fy_rear < pure.fy_rear);
    // A braking force beyond the friction circle leaves no lateral force.
    let o = m.evaluate(&x, &accelerating(20.0, 0.05, -30.0));
    assert_eq!(o.fy_front, 0.0);
    // Half of m·ax through the tyres is the whole of half of it; none of
    // it is pure slip, to the bit, braking hard or not.
    let mut half = m.clone();
    half.options.effects.combined_slip = Some(CombinedSlip {
        force_share: 0.5,
        ..split
    });
    let o = half.evaluate(&x, &accelerating(20.0, 0.05, -4.0));
    let whole = m.evaluate(&x, &accelerating(20.0, 0.05, -2.0));
    assert_relative_eq!(o.fy_front, whole.fy_front, max_relative = 1e-12);
    assert_relative_eq!(o.fy_rear, whole.fy_rear, max_relative = 1e-12);
    let mut none = m.clone();
    none.options.effects.combined_slip = Some(CombinedSlip {
        force_share: 0.0,
        ..split
    });
    for ax in [-30.0, -4.0, 0.0, 2.0] {
        let inp = accelerating(20.0, 0.05, ax);
        assert_eq!(
            none.evaluate(&x, &inp),
            nonlinear_free(&m).evaluate(&x, &inp)
        );
    }
}

/// `m` without its combined slip.
fn nonlinear_free(m: &VehicleModel) -> VehicleModel {
    let mut free = m.clone();
    free.options.effects.combined_slip = None;
    free
}

#[test]
fn the_friction_circle_holds_each_models_pure_slip_curve() {
    use crate::tyre::{MagicSimple, TyreModel};
    let tyres = [
        Tyre::Gim(Gim::new(55_000.0, 0.18, 1.0)),
        Tyre::Pac89(Pac89::adams_example()),
        Tyre::MagicSimple(MagicSimple {
            b: 10.0,
            c: 1.3,
            d: 0.95,
        }),
        crate::tyre::ModelName::Unitire.start_tyre(4000.0).unwrap(),
    ];
    for t in &tyres {
        for fz in [2000.0, 4000.0, 6000.0] {
            let mu = t.friction_coefficient(fz, 0.9);
            let peak = t.peak_lateral_force(fz, 0.9);
            // The circle holds the curve and is not far outside it (PAC89's
            // vertical shift, Gim's and UniTire's sliding friction decay
            // make the peak a few per cent lower).
            assert!(
                peak <= mu * fz * (1.0 + 1e-9),
                "{t:?} {fz}: {peak} > {}",
                mu * fz
            );
            assert!(peak >= 0.85 * mu * fz, "{t:?} {fz}: {peak} ≪ {}", mu * fz);
        }
    }
    let d = Tyre::MagicSimple(MagicSimple {
        b: 10.0,
        c: 1.3,
        d: 0.95,
    });
    assert_relative_eq!(
        d.friction_coefficient(4000.0, 0.9) * 4000.0,
        d.peak_lateral_force(4000.0, 0.9),
        max_relative = 1e-9
    );
}
