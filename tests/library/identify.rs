//! `identify` chooses its fit from the tyre model's registry entry
//! ([`Identification`]), never from the model's name: every staged fit
//! `identify` offers fits and writes the Magic Formula version its entry
//! names, and the two-stage PAC89 identification runs beside the swarm
//! fit of the model whose entry asks for it, and of no other.

use crate::root;
use handling::io::tir::{load_tir, read_tir_text};
use handling::jobs::identify::{self, IdentifyModel, IdentifyReport, Options, StartArg};
use handling::tyre::mf::{MfInput, MfVersion};
use handling::tyre::{Identification, ModelName, Pac89, SlipState, Tyre, TyreModel};
use std::fs;
use std::path::Path;

/// The public MF 6.2 file: its vertical keys (`Q_FCY2`, `Q_CAM1..3`,
/// `Q_FYS1..3`) make its loaded radius differ from a 6.1's.
const MF62: &str = "tests/fixtures/tir/MagicFormula62_Parameters.tir";

/// Options of a fit of `data` by `model` into `out`.
fn options(data: &Path, model: IdentifyModel, out: &Path) -> Options {
    Options {
        data: data.to_path_buf(),
        model,
        seed: 1,
        out: Some(out.to_path_buf()),
        load: None,
        pressure: None,
        camber: None,
        local: Default::default(),
        alpha_bin_deg: 0.0,
        kappa_bin: 0.0,
        start: StartArg::Template,
        template: Some(root().join(MF62)),
        max_iterations: Some(50),
        hold: Vec::new(),
    }
}

/// A cambered point where MF 6.1's and 6.2's loaded radii differ.
const POINT: MfInput = MfInput {
    fz: 5000.0,
    kappa: 0.0,
    alpha: 0.05,
    camber: 0.06,
    speed: 16.6,
    pressure: None,
};

#[test]
fn every_staged_fit_writes_and_evaluates_the_version_its_registry_entry_names() {
    let truth = load_tir(&root().join(MF62)).unwrap();
    assert_eq!(truth.version, MfVersion::Mf62);
    // Pure lateral rig data of the 6.2 file, noiseless, at two cambers.
    let dir = tempfile::tempdir().unwrap();
    let mut csv = String::from("fz,alpha,camber,speed,fy\n");
    for fz in [3000.0, 5000.0, 7000.0] {
        for camber in [0.0, 0.06] {
            for i in -12..=12 {
                let alpha = f64::from(i).to_radians();
                let p = MfInput {
                    fz,
                    alpha,
                    camber,
                    ..POINT
                };
                csv += &format!("{fz},{alpha},{camber},16.6,{}\n", truth.evaluate(&p).fy);
            }
        }
    }
    let data = dir.path().join("rig.csv");
    fs::write(&data, csv).unwrap();
    // The truth's loaded radius under each version: what a file written
    // as that version must give (none for a 5.2, which has no vertical
    // model).
    let radius_as = |version: MfVersion| {
        let mut t = truth.clone();
        t.version = version;
        t.loaded_radius(&POINT)
    };
    let gap = (radius_as(MfVersion::Mf62).unwrap() - radius_as(MfVersion::Mf61).unwrap()).abs();
    assert!(gap > 1e-5, "6.1 and 6.2 radii {gap} m apart");
    let staged: Vec<_> = IdentifyModel::all()
        .into_iter()
        .filter_map(|m| match m {
            IdentifyModel::Staged(model, fit) => Some((m, model, fit)),
            IdentifyModel::Swarm(_) => None,
        })
        .collect();
    let versions: Vec<MfVersion> = staged.iter().map(|s| s.2.version).collect();
    assert!(
        versions.contains(&MfVersion::Mf61) && versions.contains(&MfVersion::Mf62),
        "{versions:?}"
    );
    for (model, name, fit) in staged {
        // The entry of the model lists this fit.
        let Identification::Staged(fits) = name.identification() else {
            panic!("{name}: {:?}", name.identification());
        };
        assert!(fits.contains(&fit), "{fit:?}");
        let out = dir.path().join(format!("{}.tir", fit.name));
        let IdentifyReport::Staged(job) = identify::run(&options(&data, model, &out)).unwrap()
        else {
            panic!("{model}: not a staged fit");
        };
        assert_eq!(job.report.version, fit.version, "{model}");
        let written = read_tir_text("written", &job.tir).unwrap();
        assert_eq!(written.version, fit.version, "{model}");
        assert_eq!(
            job.tir
                .lines()
                .find(|l| l.trim_start().starts_with("FITTYP"))
                .and_then(|l| l.split('=').nth(1))
                .and_then(|v| v.split_whitespace().next()),
            Some(fit.version.fittyp().to_string().as_str()),
            "{model}"
        );
        // The fit reproduces the data (it starts at the truth), and the
        // file evaluates with its version's equations: the loaded radius
        // is the truth's under that version, not the other's.
        let sigma = job.sigma_pooled.sigma_percent;
        assert!(sigma < 1e-3, "{model}: σ {sigma} %");
        let (r, want) = (written.loaded_radius(&POINT), radius_as(fit.version));
        let agree = match (r, want) {
            (Some(r), Some(want)) => (r - want).abs() < 0.01 * gap,
            (r, want) => r == want,
        };
        assert!(
            agree,
            "{model}: loaded radius {r:?} m, its version's {want:?} m"
        );
    }
}

#[test]
fn the_two_stage_pac89_fit_runs_where_the_registry_entry_asks_for_it() {
    let with_two_stage: Vec<ModelName> = handling::tyre::models()
        .iter()
        .filter(|e| e.identification() == Identification::SwarmAndTwoStage)
        .map(|e| e.name())
        .collect();
    assert_eq!(with_two_stage, [ModelName::Pac89]);
    // Rig data of the Adams PAC89 tyre at Zhang & Li's loads.
    let t = Tyre::Pac89(Pac89::adams_example());
    let mut csv = String::from("alpha,fz,fy\n");
    for fz in [2800.0, 5700.0, 8600.0] {
        for i in -20..=20 {
            let a = (0.6 * f64::from(i)).to_radians();
            csv += &format!("{a},{fz},{}\n", t.forces(&SlipState::lateral(a, fz)).fy);
        }
    }
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("rig.csv");
    fs::write(&data, csv).unwrap();
    for model in handling::tyre::swarm_models() {
        let out = dir.path().join(format!("{model}.toml"));
        let o = Options {
            start: StartArg::Data,
            template: None,
            ..options(&data, IdentifyModel::Swarm(model), &out)
        };
        let IdentifyReport::Swarm(r) = identify::run(&o).unwrap() else {
            panic!("{model}: not a swarm fit");
        };
        let asked = model.identification() == Identification::SwarmAndTwoStage;
        assert_eq!(r.two_stage.is_some(), asked, "{model}");
        assert_eq!(r.written.is_some(), asked, "{model}");
    }
}
