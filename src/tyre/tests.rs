//! Published invariants of each tyre model.

use super::*;
use approx::assert_relative_eq;

pub(crate) fn all_models() -> Vec<Tyre> {
    vec![
        Tyre::Gim(Gim::new(60_000.0, 0.18, 1.0)),
        Tyre::MagicSimple(MagicSimple::new(10.0, 1.3)),
        Tyre::Unitire(example_unitire()),
        Tyre::Pac89(Pac89::adams_example()),
        Tyre::Linear(Linear::new(60_000.0)),
    ]
}

pub(crate) fn example_unitire() -> UniTire {
    UniTire {
        rated_load: 5700.0,
        lateral: UniTireLateral {
            p: [0.3, 1.2, 14.0, -2.0, 0.2, 1.1, 8.0, 0.8, 0.4, 5.0],
        },
        longitudinal: Some(UniTireLateral {
            p: [0.2, 1.0, 18.0, -1.5, 0.1, 1.15, 9.0, 0.75, 0.5, 4.0],
        }),
        aligning: Some(unitire::UniTireAligning {
            c: [0.035, 0.004, 0.0, 0.01, 0.0, 0.0, 1.2, 10.0, 0.3, 10.0],
        }),
    }
}

/// Brush model with a parabolic pressure distribution integrated numerically:
/// an independent reference for the Gim closed form.
fn brush_numeric(k: f64, l: f64, mu: f64, fz: f64, alpha: f64) -> (f64, f64) {
    let a = 0.5 * l;
    let cp = k / (2.0 * a * a);
    let n = 200_000;
    let dx = 2.0 * a / n as f64;
    let (mut fy, mut mz) = (0.0, 0.0);
    let t = alpha.tan();
    for i in 0..n {
        let x = a - (i as f64 + 0.5) * dx;
        let q = 0.75 * fz / a * (1.0 - (x / a).powi(2));
        let elastic = cp * (a - x) * t;
        let f = elastic.abs().min(mu * q) * t.signum();
        fy += f * dx;
        mz -= x * f * dx;
    }
    (fy, mz)
}

#[test]
fn gim_matches_numerically_integrated_brush_model() {
    let (k, l, mu, fz) = (60_000.0, 0.18, 0.9, 4000.0);
    let g = Gim::new(k, l, mu);
    for deg in [-12.0, -3.0, -0.5, 0.2, 1.0, 2.5, 4.0, 6.0, 9.0, 20.0] {
        let alpha = f64::to_radians(deg);
        let f = g.forces(&SlipState::lateral(alpha, fz));
        let (fy, mz) = brush_numeric(k, l, mu, fz, alpha);
        assert_relative_eq!(f.fy, fy, max_relative = 1e-6, epsilon = 1e-6);
        assert_relative_eq!(f.mz, mz, max_relative = 1e-4, epsilon = 1e-3);
    }
}

#[test]
fn gim_brush_closed_form_limits() {
    let (k, l, mu, fz) = (60_000.0, 0.2, 1.0, 4000.0);
    let g = Gim::new(k, l, mu);
    // Full sliding from tan α = 3μFz/K on: Fy = μFz, Mz = 0.
    let a_sl = (3.0 * mu * fz / k).atan();
    let f = g.forces(&SlipState::lateral(a_sl * 1.0001, fz));
    assert_relative_eq!(f.fy, mu * fz, max_relative = 1e-12);
    assert_eq!(f.mz, 0.0);
    let f = g.forces(&SlipState::lateral(a_sl * 0.99, fz));
    assert!(f.fy < mu * fz && f.mz > 0.0);
    // Fy = μFz(1 − ln³) at an intermediate slip.
    let alpha = 0.5 * a_sl;
    let ln = 1.0 - k * alpha.tan() / (3.0 * mu * fz);
    assert_relative_eq!(
        g.lateral_force(&SlipState::lateral(alpha, fz)),
        mu * fz * (1.0 - ln.powi(3)),
        max_relative = 1e-14
    );
    // Small-slip pneumatic trail l/6.
    let f = g.forces(&SlipState::lateral(1e-6, fz));
    assert_relative_eq!(f.mz / f.fy, l / 6.0, max_relative = 1e-5);
}

#[test]
fn gim_friction_decay_lowers_sliding_force_only() {
    let mut g = Gim::new(60_000.0, 0.18, 1.0);
    let s = SlipState::lateral(0.3, 4000.0);
    let full = g.lateral_force(&s);
    g.friction_decay = 0.5;
    assert!(g.lateral_force(&s) < full);
    assert_relative_eq!(g.cornering_stiffness(4000.0), 60_000.0);
    let numeric = <Gim as TyreModel>::cornering_stiffness(&g, 4000.0);
    assert_relative_eq!(numeric, 60_000.0, max_relative = 1e-6);
}

#[test]
fn unitire_taylor_series_at_zero() {
    for e in [-0.3, 0.0, 0.5, 0.9] {
        for phi in [1e-3, 3e-3, 1e-2] {
            let series = phi + (e - 0.5) * phi * phi + (e - 0.5f64).powi(2) * phi.powi(3);
            let err = (unitire::dimensionless_force(phi, e) - series).abs();
            // The remainder is O(φ⁴): bounded by a modest constant times φ⁴.
            assert!(err < 2.0 * phi.powi(4), "E={e} φ={phi} err={err}");
        }
    }
}

#[test]
fn unitire_rises_monotonically_to_one() {
    for e in [-0.2, 0.0, 0.5, 1.0] {
        let mut prev = 0.0;
        for i in 1..4000 {
            let phi = i as f64 * 0.005;
            let f = unitire::dimensionless_force(phi, e);
            // Strictly rising until F̄ is within rounding of 1.
            assert!(f > prev || 1.0 - f < 1e-13, "E={e} not monotone at φ={phi}");
            assert!(f <= 1.0);
            prev = f;
        }
        assert_relative_eq!(prev, 1.0, epsilon = 1e-12);
    }
}

#[test]
fn unitire_slope_at_zero_is_k() {
    let u = example_unitire();
    for fz in [2800.0, 5700.0, 8600.0] {
        let k = u.lateral.stiffness(fz, fz / u.rated_load);
        let numeric = (u.lateral_force(&SlipState::lateral(1e-7, fz))
            - u.lateral_force(&SlipState::lateral(-1e-7, fz)))
            / 2e-7;
        assert_relative_eq!(numeric, k, max_relative = 1e-6);
        assert_relative_eq!(u.cornering_stiffness(fz), k);
    }
}

#[test]
fn unitire_friction_law_starts_at_mu0_and_tends_to_mus() {
    let u = example_unitire();
    let fzn = 1.0;
    let mu0 = u.lateral.p[5] * (-fzn / u.lateral.p[6]).exp();
    assert_relative_eq!(u.lateral.friction(fzn, 0.0), mu0, max_relative = 1e-15);
    assert_relative_eq!(
        u.lateral.friction(fzn, 1e4),
        u.lateral.p[7] * mu0,
        max_relative = 1e-3
    );
}

/// Reference values of the Adams PAC89 example set at Fz = 4 kN, zero camber,
/// computed from the raw equations (the published example).
#[test]
fn pac89_adams_example_reference_values() {
    let p = Pac89::adams_example();
    let fz = 4000.0;
    for (deg, fy, mz) in [
        (1.0, 1733.2, -40.04),
        (5.0, 4268.1, -24.16),
        (10.0, 4455.8, 1.14),
    ] {
        let f = p.forces(&SlipState::lateral(f64::to_radians(deg), fz));
        assert!((f.fy - fy).abs() < 0.1, "Fy({deg}°) = {}", f.fy);
        // The crate returns the moment with the sign of fy at small slip:
        // the negated raw value.
        assert!((-f.mz - mz).abs() < 0.01, "Mz({deg}°) = {}", -f.mz);
    }
    for (pct, fx) in [(5.0, 3599.3), (10.0, 5361.7), (20.0, 5730.5)] {
        let f = p.forces(&SlipState::longitudinal(pct / 100.0, fz));
        assert!((f.fx - fx).abs() < 0.1, "Fx({pct}%) = {}", f.fx);
    }
}

#[test]
fn pac89_refuses_1987_numbering() {
    let mut p = Pac89::adams_example();
    p.form = Pac89Form::Pacejka1987;
    let e = p.validate().unwrap_err();
    assert_eq!(e.key, "form");
    assert_eq!(e.reason, crate::error::ParamReason::Pac89PaperNumbering);
    assert!(e.to_string().contains("1987"), "{e}");
}

#[test]
fn odd_symmetry_without_offsets() {
    let mut pac = Pac89::adams_example();
    // Remove every offset (Sh, Sv) so the model becomes odd.
    for i in [8, 9, 10, 11, 12, 13] {
        pac.a[i] = 0.0;
    }
    let mut models = all_models();
    models[3] = Tyre::Pac89(pac);
    for t in &models {
        for deg in [0.1, 1.0, 4.0, 8.0, 15.0, 45.0, 89.0] {
            for fz in [500.0, 4000.0, 9000.0] {
                let a = f64::to_radians(deg);
                let p = t.forces(&SlipState::lateral(a, fz));
                let m = t.forces(&SlipState::lateral(-a, fz));
                assert_relative_eq!(p.fy, -m.fy, max_relative = 1e-12, epsilon = 1e-9);
                assert!(p.fy > 0.0, "{}: fy({deg}°) = {}", t.model_name(), p.fy);
                if t.model_name() != "pac89" {
                    assert_relative_eq!(p.mz, -m.mz, max_relative = 1e-12, epsilon = 1e-9);
                }
            }
        }
    }
}

#[test]
fn aligning_moment_has_sign_of_fy_at_small_slip() {
    for t in all_models() {
        let f = t.forces(&SlipState::lateral(f64::to_radians(1.0), 4000.0));
        if f.mz != 0.0 {
            assert!(f.mz * f.fy > 0.0, "{}", t.model_name());
        }
    }
}

#[test]
fn no_nan_at_the_edges_of_the_input_range() {
    for t in all_models() {
        // A subnormal load (5e-324) and the smallest normal one: θ = K/(3μFz)
        // is infinite there, and must not meet a zero slip as ∞·0.
        for fz in [
            -100.0,
            0.0,
            5e-324,
            f64::MIN_POSITIVE,
            1e-9,
            1.0,
            4000.0,
            20_000.0,
        ] {
            for alpha in [
                -std::f64::consts::FRAC_PI_2,
                -1.0,
                0.0,
                1e-12,
                0.5,
                std::f64::consts::FRAC_PI_2,
            ] {
                for kappa in [-1.0, 0.0, 0.1, 1.0] {
                    for speed in [0.0, 30.0] {
                        let s = SlipState {
                            alpha,
                            kappa,
                            fz,
                            camber: 0.05,
                            mu_scale: 0.8,
                            speed,
                        };
                        let f = t.forces(&s);
                        assert!(
                            f.fx.is_finite() && f.fy.is_finite() && f.mz.is_finite(),
                            "{} at {s:?}: {f:?}",
                            t.model_name()
                        );
                        if fz <= 0.0 {
                            assert_eq!(f, TyreForces::default());
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn numeric_cornering_stiffness_matches_closed_forms() {
    let fz = 4000.0;
    let expect = [
        ("gim", 60_000.0),
        ("magic-simple", 10.0 * 1.3 * fz),
        ("linear", 60_000.0),
    ];
    for t in all_models() {
        let numeric = {
            let s = |a| SlipState::lateral(a, fz);
            (t.lateral_force(&s(1e-8)) - t.lateral_force(&s(-1e-8))) / 2e-8
        };
        assert_relative_eq!(t.cornering_stiffness(fz), numeric, max_relative = 1e-6);
        if let Some((_, k)) = expect.iter().find(|(n, _)| *n == t.model_name()) {
            assert_relative_eq!(numeric, *k, max_relative = 1e-6);
        }
    }
    // PAC89: BCD per degree at 4 kN, times 180/π.
    let p = Pac89::adams_example();
    let bcd = 3036.0 * (2.0 * (4.0f64 / 12.8).atan()).sin();
    let curve = p.lateral_curve(4.0, 0.0);
    assert_relative_eq!(curve.b * curve.c * curve.d, bcd, max_relative = 1e-12);
}

#[test]
fn road_friction_scales_the_peak() {
    for t in all_models() {
        if t.model_name() == "linear" {
            continue;
        }
        let full = t.peak_lateral_force(4000.0, 1.0);
        let half = t.peak_lateral_force(4000.0, 0.5);
        assert_relative_eq!(half / full, 0.5, max_relative = 0.02);
    }
}

#[test]
fn with_cornering_stiffness_hits_the_target() {
    for t in all_models() {
        let target = 1.37 * t.cornering_stiffness(3500.0);
        let s = t.with_cornering_stiffness(target, 3500.0);
        assert_relative_eq!(s.cornering_stiffness(3500.0), target, max_relative = 1e-6);
    }
}

#[test]
fn tyre_files_parse_by_model_name() {
    let t: Tyre =
        toml::from_str("model = \"gim\"\ncornering_stiffness = 50000.0\ncontact_length = 0.2\n")
            .unwrap();
    assert_eq!(t.model_name(), "gim");
    let e = toml::from_str::<Tyre>("model = \"gym\"\n").unwrap_err();
    assert!(e.to_string().contains("gym"), "{e}");
    let e =
        toml::from_str::<Tyre>("model = \"gim\"\ncornering_stifness = 5.0\ncontact_length = 0.2\n")
            .unwrap_err();
    assert!(e.to_string().contains("cornering_stifness"), "{e}");
}

/// The contract every model with a start tyre keeps (`tyre/mod.rs`, "Adding
/// a model"): its name and file round-trip, a valid start inside its search
/// box, parameter blocks whose names, values, bounds and freedoms agree in
/// length and survive a set, a canonical form that changes no force, and a
/// cornering stiffness that scales.
#[test]
fn every_model_keeps_the_model_contract() {
    let fitted = swarm_models();
    assert!(fitted.len() >= 5, "{fitted:?}");
    for name in fitted {
        let t = name.start_tyre(4000.0).unwrap();
        assert_eq!(t.model(), name);
        assert_eq!(t.model_name().parse::<ModelName>(), Ok(name));
        let text = toml::to_string(&t).unwrap();
        assert_eq!(toml::from_str::<Tyre>(&text).unwrap(), t, "{name}");
        t.validate().unwrap();
        let (p, b) = (t.parameters(), t.bounds());
        assert_eq!(t.parameter_names().len(), p.len(), "{name}");
        assert_eq!(b.len(), p.len(), "{name}");
        for (loads, cambers) in [(1, 1), (3, 1), (4, 3)] {
            assert_eq!(t.lateral_free(loads, cambers).len(), p.len(), "{name}");
        }
        for (v, (lo, hi)) in p.iter().zip(&b) {
            assert!(lo <= v && v <= hi, "{name}: start {v} outside ({lo}, {hi})");
        }
        assert!(t.loads_needed() >= 1);
        let mut u = t.clone();
        let (a, l) = (t.aligning_parameters(), t.longitudinal_parameters());
        assert_eq!(t.aligning_names().len(), a.len(), "{name}");
        assert_eq!(t.aligning_bounds().len(), a.len(), "{name}");
        assert_eq!(t.aligning_free(2).len(), a.len(), "{name}");
        assert_eq!(t.longitudinal_names().len(), l.len(), "{name}");
        assert_eq!(t.longitudinal_bounds().len(), l.len(), "{name}");
        assert_eq!(t.longitudinal_free().len(), l.len(), "{name}");
        u.set_aligning_parameters(&a);
        u.set_longitudinal_parameters(&l);
        u.set_parameters(&p);
        assert_eq!(u.aligning_parameters(), a, "{name}");
        assert_eq!(u.longitudinal_parameters(), l, "{name}");
        assert_eq!(u.parameters(), p, "{name}");
        let c = u.canonical();
        assert_eq!(c.canonical(), c, "{name}");
        for deg in [-8.0, 0.5, 3.0] {
            let s = SlipState::lateral(f64::to_radians(deg), 4000.0);
            assert_relative_eq!(c.forces(&s).fy, u.forces(&s).fy, max_relative = 1e-12);
        }
        let target = 1.37 * t.cornering_stiffness(4000.0);
        let s = t.with_cornering_stiffness(target, 4000.0);
        assert_relative_eq!(s.cornering_stiffness(4000.0), target, max_relative = 1e-6);
        assert_eq!(
            t.forces(&SlipState::lateral(0.1, 0.0)),
            TyreForces::default()
        );
    }
    let e = "magic-formula"
        .parse::<ModelName>()
        .map(|m| m.start_tyre(4000.0));
    assert_eq!(e, Ok(None));
}

/// The registry's lists agree with each other and with the serde of a tyre
/// file: every name is parsed back, is the `model` key its start tyre
/// writes, has its constant, and an unknown name is refused with the list.
#[test]
fn the_registry_derives_every_list() {
    let names: Vec<&str> = model_names().iter().map(|n| n.as_str()).collect();
    assert_eq!(
        &names[..6],
        [
            "gim",
            "magic-simple",
            "unitire",
            "pac89",
            "linear",
            "magic-formula"
        ]
    );
    let consts = [
        ModelName::Gim,
        ModelName::MagicSimple,
        ModelName::Unitire,
        ModelName::Pac89,
        ModelName::Linear,
        ModelName::MagicFormula,
    ];
    assert_eq!(&model_names()[..6], consts);
    for (n, e) in model_names().iter().zip(models()) {
        assert_eq!(n.as_str().parse::<ModelName>(), Ok(*n));
        assert_eq!(e.name(), *n);
        let swarm = e.identification().by_swarm();
        assert_eq!(swarm, swarm_models().contains(n), "{n}");
        assert_eq!(swarm, n.start_tyre(3000.0).is_some(), "{n}");
    }
    assert_eq!(&swarm_models()[..5], &consts[..5]);
    let e = "brush".parse::<ModelName>().unwrap_err().to_string();
    assert!(e.contains("unknown tyre model `brush`"), "{e}");
    assert!(
        e.contains("gim, magic-simple, unitire, pac89, linear, magic-formula"),
        "{e}"
    );
    let e = toml::from_str::<Tyre>("model = \"brush\"\n").unwrap_err();
    assert_eq!(e.span(), Some(8..15), "the error points at the name");
    assert!(
        e.message()
            .starts_with("unknown variant `brush`, expected one of `gim`, `magic-simple`"),
        "{e}"
    );
    let e = toml::from_str::<Tyre>("cornering_stiffness = 1.0\n").unwrap_err();
    assert_eq!(e.message(), "missing field `model`");
}

/// A tyre file written and read back, as TOML and as JSON (with its unset
/// optional tables as `null`), is the same tyre; the `model` key comes
/// first, then the model's fields in their order.
#[test]
fn tyre_files_round_trip_through_the_registry() {
    let u = ModelName::Unitire.start_tyre(4000.0).unwrap();
    let text = toml::to_string(&u).unwrap();
    assert!(
        text.starts_with("model = \"unitire\"\nrated_load = 4000.0\n"),
        "{text}"
    );
    assert_eq!(toml::from_str::<Tyre>(&text).unwrap(), u);
    let json = serde_json::to_string(&u).unwrap();
    assert!(json.contains("\"aligning\":null"), "{json}");
    assert_eq!(serde_json::from_str::<Tyre>(&json).unwrap(), u);
    let nan = Tyre::Linear(Linear::new(f64::NAN));
    let back: Tyre = toml::from_str(&toml::to_string(&nan).unwrap()).unwrap();
    assert!(matches!(back, Tyre::Linear(l) if l.cornering_stiffness.is_nan()));
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// Every model gives finite forces anywhere in its input range, zero
        /// force at zero or negative load, and (without offsets) odd symmetry.
        #[test]
        fn finite_and_odd(alpha in -1.5f64..1.5, fz in -1000.0f64..20_000.0, mu in 0.05f64..2.0, speed in 0.0f64..60.0) {
            for t in all_models() {
                let s = SlipState { alpha, kappa: 0.0, fz, camber: 0.0, mu_scale: mu, speed };
                let f = t.forces(&s);
                prop_assert!(f.fx.is_finite() && f.fy.is_finite() && f.mz.is_finite());
                if fz <= 0.0 {
                    prop_assert_eq!(f, TyreForces::default());
                }
                if t.model_name() != "pac89" {
                    let m = t.forces(&SlipState { alpha: -alpha, ..s });
                    prop_assert!((f.fy + m.fy).abs() <= 1e-9 * f.fy.abs().max(1.0));
                }
            }
        }
    }
}
