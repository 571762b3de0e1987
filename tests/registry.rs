//! A tyre model added from outside the crate, the way a new model is added:
//! a type implementing the model traits plus one registration. The toy is a
//! linear tyre `Fy = C·α` (no friction limit), so every job has a closed
//! form to meet: `simulate`'s steady yaw-rate gain is the linear bicycle
//! model's `u/(l + K·u²)` with `K = m/l·(b/C_f − a/C_r)` (axle stiffnesses,
//! two wheels each; Wong, *Theory of Ground Vehicles*, ch. 5), `identify`
//! recovers the stiffness that generated its rig data, and `tyre-eval`
//! returns `C·α`.

use handling::error::ParamError;
use handling::io::load_tyre;
use handling::jobs::identify::{self, IdentifyModel, IdentifyReport, Options, Polish, StartArg};
use handling::jobs::{simulate, tyre_eval};
use handling::tyre::{
    model_names, register, swarm_models, Model, ModelName, ModelParameters, Parameterised,
    SlipState, Tyre, TyreForces, TyreModel,
};
use serde::{Deserialize, Serialize};
use std::fs;
use std::path::Path;

/// The toy: a linear tyre of stiffness `stiffness` (N/rad per wheel).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct ToyLinear {
    stiffness: f64,
}

impl TyreModel for ToyLinear {
    fn forces(&self, s: &SlipState) -> TyreForces {
        let fy = if s.fz > 0.0 {
            self.stiffness * s.alpha
        } else {
            0.0
        };
        TyreForces {
            fx: 0.0,
            fy,
            mz: 0.0,
        }
    }
    /// Linear: no friction limit.
    fn friction_coefficient(&self, _fz: f64, _mu_scale: f64) -> f64 {
        f64::INFINITY
    }
}

impl Parameterised for ToyLinear {
    fn parameter_names(&self) -> Vec<&'static str> {
        vec!["stiffness"]
    }
    fn parameters(&self) -> Vec<f64> {
        vec![self.stiffness]
    }
    fn set_parameters(&mut self, p: &[f64]) {
        self.stiffness = p[0];
    }
    fn bounds(&self) -> Vec<(f64, f64)> {
        vec![(1e3, 5e5)]
    }
}

impl ModelParameters for ToyLinear {
    fn validate(&self) -> Result<(), ParamError> {
        ParamError::positive("stiffness", self.stiffness)
    }
    fn scale_cornering_stiffness(&mut self, k: f64) {
        self.stiffness *= k;
    }
}

impl Model for ToyLinear {
    const NAME: &'static str = "toy-linear";
    fn start(_fz: f64) -> Option<Self> {
        Some(ToyLinear {
            stiffness: 50_000.0,
        })
    }
}

/// The one registration (every test makes it; a second is no change).
fn toy() -> ModelName {
    register::<ToyLinear>().unwrap()
}

fn write(dir: &Path, name: &str, text: &str) -> std::path::PathBuf {
    let p = dir.join(name);
    fs::write(&p, text).unwrap();
    p
}

/// The registry's lists know the toy, in its place after the crate's
/// models; its name is parsed; a different model under a taken name is
/// refused.
#[test]
fn the_registered_toy_is_in_every_list() {
    let name = toy();
    assert_eq!(name.as_str(), "toy-linear");
    assert_eq!(toy(), name);
    let builtin = [
        ModelName::Gim,
        ModelName::MagicSimple,
        ModelName::Unitire,
        ModelName::Pac89,
        ModelName::Linear,
        ModelName::MagicFormula,
    ];
    assert_eq!(model_names()[..6], builtin);
    assert_eq!(model_names()[6..], [name]);
    assert!(swarm_models().contains(&name));
    assert_eq!("toy-linear".parse::<ModelName>(), Ok(name));
    assert_eq!(
        IdentifyModel::names(),
        [
            "gim",
            "magic-simple",
            "unitire",
            "pac89",
            "linear",
            "mf61",
            "mf62",
            "toy-linear"
        ]
    );
    let all = IdentifyModel::all();
    assert!(all.contains(&IdentifyModel::Mf61) && all.contains(&IdentifyModel::Mf62));
    assert_eq!(all[7], IdentifyModel::Swarm(name));
    let e = "brush".parse::<IdentifyModel>().unwrap_err().to_string();
    assert!(e.contains("toy-linear") && e.contains("mf62"), "{e}");

    /// A second model that claims the built-in linear tyre's name.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    struct Impostor(ToyLinear);
    impl TyreModel for Impostor {
        fn forces(&self, s: &SlipState) -> TyreForces {
            self.0.forces(s)
        }
    }
    impl Parameterised for Impostor {
        fn parameter_names(&self) -> Vec<&'static str> {
            self.0.parameter_names()
        }
        fn parameters(&self) -> Vec<f64> {
            self.0.parameters()
        }
        fn set_parameters(&mut self, p: &[f64]) {
            self.0.set_parameters(p)
        }
        fn bounds(&self) -> Vec<(f64, f64)> {
            self.0.bounds()
        }
    }
    impl ModelParameters for Impostor {
        fn validate(&self) -> Result<(), ParamError> {
            self.0.validate()
        }
        fn scale_cornering_stiffness(&mut self, k: f64) {
            self.0.scale_cornering_stiffness(k)
        }
    }
    impl Model for Impostor {
        const NAME: &'static str = "linear";
        fn start(_fz: f64) -> Option<Self> {
            None
        }
    }
    let e = register::<Impostor>().unwrap_err().to_string();
    assert!(e.contains("already registered as `linear`"), "{e}");
}

/// `tyre-eval` of a toy tyre file: `Fy = C·α` at every point, nothing at
/// zero load; the file's `model` key is read through the registry.
#[test]
fn tyre_eval_of_the_toy_is_its_closed_form() {
    toy();
    let dir = tempfile::tempdir().unwrap();
    let tyre = write(
        dir.path(),
        "toy.toml",
        "model = \"toy-linear\"\nstiffness = 61000.0\n",
    );
    let mut points = String::from("fz,kappa,alpha,camber,speed\n");
    let alphas = [-0.1, -0.02, 0.0, 0.013, 0.2];
    for a in alphas {
        points.push_str(&format!("4000,0,{a},0,20\n"));
    }
    points.push_str("0,0,0.05,0,20\n");
    let points = write(dir.path(), "points.csv", &points);
    let r = tyre_eval::run(&tyre, &points, &dir.path().join("forces.csv"), None).unwrap();
    assert_eq!(r.model, "toy-linear");
    assert_eq!(r.count, 6);
    let fy = &r.columns.iter().find(|(n, _)| *n == "fy").unwrap().1;
    for (f, a) in fy.iter().zip(alphas) {
        assert_eq!(*f, 61_000.0 * a);
    }
    assert_eq!(fy[5], 0.0);
    r.write().unwrap();
    assert!(dir.path().join("forces.csv").is_file());
}

const VEHICLE: &str = "[vehicle]
mass = 1530.0
yaw_inertia = 2315.0
a = 1.11
b = 1.67
track_front = 1.55
track_rear = 1.55
cg_height = 0.55
";

/// The steady yaw-rate gain of a step steer at 80 km/h of a car on the
/// toy: `simulate`'s metric, which the bicycle model's closed form and the
/// same car on the crate's own linear tyre give too.
fn step_gain(dir: &Path, front: &str, rear: &str) -> (f64, [&'static str; 2]) {
    write(dir, "front.toml", front);
    write(dir, "rear.toml", rear);
    let sc = write(
        dir,
        "scenario.toml",
        &format!(
            "name = \"toy\"\n{VEHICLE}\n[tyres]\nfront = \"front.toml\"\nrear = \"rear.toml\"\n\n\
             [manoeuvre]\nkind = \"step-steer\"\nspeed = 22.2222\nsteer = 0.0087266\n\
             start = 1.0\nrise_time = 0.1\nend = 8.0\n"
        ),
    );
    let r = simulate::run(&sc, Some(&dir.join("out"))).unwrap();
    (r.metrics.unwrap().yaw_rate_gain, r.tyres)
}

#[test]
fn simulate_on_the_toy_gives_the_linear_bicycle_gain() {
    toy();
    let (cf, cr) = (55_000.0, 62_000.0);
    let dir = tempfile::tempdir().unwrap();
    let (gain, tyres) = step_gain(
        dir.path(),
        &format!("model = \"toy-linear\"\nstiffness = {cf}\n"),
        &format!("model = \"toy-linear\"\nstiffness = {cr}\n"),
    );
    assert_eq!(tyres, ["toy-linear", "toy-linear"]);
    let (m, a, b, u) = (1530.0, 1.11, 1.67, 22.2222);
    let l: f64 = a + b;
    let k = m / l * (b / (2.0 * cf) - a / (2.0 * cr));
    let closed = u / (l + k * u * u);
    assert!(
        (gain / closed - 1.0).abs() < 1e-3,
        "gain {gain} /s, bicycle model {closed} /s"
    );
    let other = tempfile::tempdir().unwrap();
    let (linear, _) = step_gain(
        other.path(),
        &format!("model = \"linear\"\ncornering_stiffness = {cf}\n"),
        &format!("model = \"linear\"\ncornering_stiffness = {cr}\n"),
    );
    assert!((gain / linear - 1.0).abs() < 1e-9, "{gain} vs {linear}");
}

/// `identify --model toy-linear` on rig data the toy generated (three
/// loads, ±0.1 rad) recovers its stiffness, writes a tyre file that reads
/// back as the same toy, and reports a zero residual.
#[test]
fn identify_recovers_the_toys_stiffness() {
    toy();
    let truth = 73_400.0;
    let mut csv = String::from("fz,alpha,fy\n");
    for fz in [2000.0, 4000.0, 6000.0] {
        for i in 0..=40 {
            let a = 0.005 * (i as f64 - 20.0);
            csv.push_str(&format!("{fz},{a},{}\n", truth * a));
        }
    }
    let dir = tempfile::tempdir().unwrap();
    let data = write(dir.path(), "rig.csv", &csv);
    let out = dir.path().join("toy.toml");
    let r = identify::run(&Options {
        data,
        model: "toy-linear".parse().unwrap(),
        seed: 3,
        out: Some(out.clone()),
        load: None,
        pressure: None,
        camber: None,
        local: Polish::Lm,
        alpha_bin_deg: 0.0,
        kappa_bin: 0.0,
        start: StartArg::Data,
        template: None,
        max_iterations: None,
        hold: Vec::new(),
    })
    .unwrap();
    let IdentifyReport::Swarm(s) = &r else {
        panic!("a swarm fit")
    };
    let fitted = match &s.tyre {
        Tyre::Registered(t) => t.downcast_ref::<ToyLinear>().unwrap().stiffness,
        other => panic!("not the toy: {other:?}"),
    };
    assert!((fitted / truth - 1.0).abs() < 1e-9, "{fitted}");
    assert!(s.fit.sigma_percent < 1e-6, "{}", s.fit.sigma_percent);
    assert_eq!(s.fit.model, "toy-linear");
    r.write().unwrap();
    assert_eq!(load_tyre(&out).unwrap(), s.tyre);
}
