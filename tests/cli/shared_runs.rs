//! Runs that several tests check, made once per test run: the first test
//! that asks runs the command into the test run's own scratch folder
//! (`CARGO_TARGET_TMPDIR`), any asking meanwhile waits for that run, the
//! rest read it. Each test still checks its own claims on the run's
//! terminal and files; only the repeated command is gone (CI's time on
//! 2 cores: the guide wants under 20 minutes).

use super::*;
use std::sync::OnceLock;

/// An empty folder `name` in the test run's scratch folder, a previous
/// run's outputs removed (the commands below refuse or keep nothing
/// stale then).
fn fresh(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    if dir.exists() {
        fs::remove_dir_all(&dir).unwrap();
    }
    fs::create_dir_all(&dir).unwrap();
    dir
}

/// `identify <Hoosier cornering file> --model mf61 --template
/// fsae190_50R10.tir --out h.tir`, run in [`TemplateFit::dir`].
pub(crate) struct TemplateFit {
    /// What the terminal said, stdout.
    pub(crate) stdout: String,
    /// Its warnings, stderr.
    pub(crate) stderr: String,
    /// The folder the run was made in: `h.tir` and its report.
    pub(crate) dir: PathBuf,
}

/// The public Hoosier cornering file fitted by `mf61` from the public
/// FSAE template `fsae190_50R10.tir` (about 15 s of both cores: two tests
/// read it); `None` where [`shared_data`] skips `test`. The run must
/// succeed.
pub(crate) fn hoosier_on_fsae190(test: &str) -> Option<&'static TemplateFit> {
    static FIT: OnceLock<TemplateFit> = OnceLock::new();
    let data = shared_data(test, "tyre_ttc_hoosier_43075/cornering.csv")?;
    let template = shared_data(test, "tir_public/fsae190_50R10.tir")?;
    Some(FIT.get_or_init(|| {
        let dir = fresh("hoosier_fsae190");
        let o = run_in(
            &dir,
            &[
                "identify",
                data.to_str().unwrap(),
                "--model",
                "mf61",
                "--template",
                template.to_str().unwrap(),
                "--out",
                "h.tir",
            ],
        );
        assert!(o.status.success(), "{}", stderr(&o));
        TemplateFit {
            stdout: String::from_utf8_lossy(&o.stdout).into_owned(),
            stderr: stderr(&o),
            dir,
        }
    }))
}

/// A diagnosis: what the terminal said, `diagnosis.json`, and the folder
/// it was written to (`gap_map.png`, `report.html`).
pub(crate) struct Diagnosed {
    /// stdout.
    pub(crate) said: String,
    /// `diagnosis.json`.
    pub(crate) d: serde_json::Value,
    /// The `--out` folder.
    pub(crate) out: PathBuf,
}

/// `synth --effects sensor_delay --seed 1` with its vehicle file's yaw
/// inertia 3500 kg·m² for the car's 2315, diagnosed (about 20 s of both
/// cores: three tests read it, in `trips_s90_diag` and `trips_s91_diag`).
pub(crate) fn yaw_inertia_3500_beside_a_delay() -> &'static Diagnosed {
    static DIAGNOSED: OnceLock<Diagnosed> = OnceLock::new();
    DIAGNOSED.get_or_init(|| {
        let dir = fresh("yaw_inertia_3500_beside_a_delay");
        let c = trips_s90_diag::edited_campaign(&dir, "yaw_inertia = 2315", "yaw_inertia = 3500");
        let out = dir.join("out");
        let (said, d) = diagnose_to(&c, &out);
        Diagnosed { said, d, out }
    })
}

/// `identify rig <args> --out out`: the terminal (stdout), the run made
/// once per argument list and its files copied to `out` (the tyre file,
/// `*.report.json`, the figure), its stdout naming them there. A swarm
/// fit of one level of the Hoosier file (UniTire, about 10 s of a core)
/// was run by four tests alike. The run must succeed.
pub(crate) fn identified(rig: &Path, args: &[&str], out: &Path) -> String {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static MADE: crate::memo::Memo<Vec<String>, (PathBuf, String)> = crate::memo::Memo::new();
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let ext = out.extension().and_then(|e| e.to_str()).unwrap_or("toml");
    let mut key = vec![rig.display().to_string(), ext.to_string()];
    key.extend(args.iter().map(|a| a.to_string()));
    let (made, said) = MADE.get(key, || {
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let dir = fresh(&format!("identified-{n}"));
        let made = dir.join(format!("fit.{ext}"));
        let mut all = vec!["identify", rig.to_str().unwrap()];
        all.extend_from_slice(args);
        all.extend_from_slice(&["--out", made.to_str().unwrap()]);
        let o = run(&all);
        assert!(o.status.success(), "{}", stderr(&o));
        (made, String::from_utf8_lossy(&o.stdout).into_owned())
    });
    // Every file of the run (fit.toml, fit.report.json, fit.png) under
    // `out`'s stem.
    let (from, to) = (made.with_extension(""), out.with_extension(""));
    for f in fs::read_dir(made.parent().unwrap()).unwrap() {
        let name = f.unwrap().file_name().into_string().unwrap();
        if let Some(rest) = name.strip_prefix("fit.") {
            let target = format!("{}.{rest}", to.display());
            fs::copy(made.parent().unwrap().join(&name), target).unwrap();
        }
    }
    said.replace(&from.display().to_string(), &to.display().to_string())
}
