//! `diagnose` (the sim-to-real gap of a campaign) and `synth` (the virtual
//! proving ground that writes campaigns with known effects).

use anyhow::Result;
use clap::Args;
use handling::jobs::diagnose;
use handling::jobs::fleet::{self, BatchOutcome};
use handling::jobs::shard::Shard;
use handling::jobs::synth::{self, truth_named, EffectName};
use handling::proving_ground::{Programme, Truth, MAX_DURATION};
use std::path::PathBuf;
use std::str::FromStr;

/// `handling diagnose`'s arguments.
#[derive(Args)]
pub struct DiagnoseArgs {
    /// Campaign file or folder (with --batch: a folder of campaigns).
    campaign: PathBuf,
    /// Output folder (default: out/<campaign name>).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Diagnose every campaign of the folder (its sub-folders and .toml
    /// files) into <out>/<campaign>/, with a fleet table (fleet.csv,
    /// fleet.json).
    #[arg(long)]
    batch: bool,
    /// With --batch: only shard K of N of the campaigns (name order, index
    /// mod N = K − 1); `handling merge` writes the fleet table.
    #[arg(long, value_name = "K/N", value_parser = super::equilibria::parse_shard, requires = "batch")]
    shard: Option<Shard>,
}

/// `handling diagnose`.
pub fn diagnose(a: DiagnoseArgs) -> Result<()> {
    if a.batch {
        let (reports, outcome) = fleet::run_batch(&a.campaign, a.out.as_deref(), a.shard)?;
        for r in &reports {
            super::print(&r.summary());
        }
        match outcome {
            BatchOutcome::Fleet(f) => {
                super::print(&f.summary());
                let [csv, json, html] = f.outputs();
                say!(
                    "wrote {}, {}, {}",
                    csv.display(),
                    json.display(),
                    html.display()
                );
                if let Some(e) = f.all_failed(&a.campaign) {
                    return Err(e.into());
                }
            }
            BatchOutcome::Shard(s) => super::print(&s.summary()),
        }
        return Ok(());
    }
    let r = diagnose::run(&a.campaign, a.out.as_deref())?;
    r.write()?;
    super::print(&r.summary());
    let f = r.outputs();
    say!(
        "diagnosed in {}; wrote {}, {}, {}, {}, {}",
        r.time_spent(),
        f[0].display(),
        f[1].display(),
        f[2].display(),
        f[4].display(),
        f[3].display()
    );
    Ok(())
}

/// `handling synth`'s arguments.
#[derive(Args)]
pub struct SynthArgs {
    /// Effects to switch on, comma-separated (`none` for none).
    #[arg(long, value_delimiter = ',', default_value = "none", value_parser = EffectName::from_str)]
    effects: Vec<EffectName>,
    /// Noise seed (a whole number of 0 or more).
    #[arg(long, default_value_t = 1, allow_hyphen_values = true, value_parser = super::whole_number)]
    seed: u64,
    /// The model that plays the car: `augmented` (the diagnosis's own
    /// model) or `four-wheel` (an independent four-wheel model with roll
    /// and its own tyre).
    #[arg(long, default_value = "augmented", value_parser = truth_named)]
    truth: Truth,
    /// What the driver does: `handling` (steps, a ramp and a sweep at
    /// constant speed, 100 Hz), `oval` (a 20° banked oval with braking,
    /// throttle and a standstill on the banking, 25 Hz, ax and bank
    /// channels), `road-course` (trail braking, cambered corners, 25 Hz),
    /// `slow-oval` (a light racing car at 5–21 m/s on a 20° banked
    /// oval with a standstill, 25 Hz, ax, beta and bank, no ay, no rig
    /// data, 20 s pieces), `slow-oval-no-beta` and
    /// `slow-oval-estimated-beta` (the same without beta, or with a beta
    /// as a state estimator gives it), or the analogues of real logs:
    /// `sedan-winding` (a 2.3 t sedan driven by hand on a winding track,
    /// 100 Hz, with a logger's offsets) and `racing-rear-steer` (the
    /// Putnam log's car on a road course, its rear steering with roll).
    #[arg(long, default_value = "handling", value_parser = Programme::from_str)]
    programme: Programme,
    /// The runs' total duration, s, for the analogues (`sedan-winding`,
    /// 370 s by default; `racing-rear-steer`, 300 s): a whole number of
    /// seconds from the programme's own to 3600, each run lengthened in
    /// proportion, to whole seconds, its driver lapping its track more often.
    #[arg(long, value_name = "SECONDS", allow_hyphen_values = true, value_parser = seconds)]
    duration: Option<f64>,
    /// Campaign folder to create.
    #[arg(long)]
    out: PathBuf,
    /// Scenario files (`handling design` writes them) whose manoeuvres the
    /// truth drives as further runs, named after the files: repeat it, or
    /// separate the files with commas, as `--effects` takes its names.
    #[arg(long, value_delimiter = ',')]
    drive: Vec<PathBuf>,
}

/// `handling synth`: writes a campaign folder generated with the effects.
pub fn synth(a: SynthArgs) -> Result<()> {
    let mut r = synth::run(&a.effects, a.seed, a.truth, a.programme, a.duration, &a.out)?;
    r.drive(&a.drive)?;
    r.write()?;
    for n in &r.notes {
        say!("note: {n}");
    }
    say!("{}", r.wrote());
    Ok(())
}

/// A duration in seconds: a finite number above 0. The refusal names the
/// value given and what is wrong with it (clap quotes the text before it,
/// but "expected a number of seconds above 0" alone left a user of `nan`
/// or `1e400`, read as infinite, guessing).
fn seconds(s: &str) -> Result<f64, String> {
    let wrong = match s.parse::<f64>() {
        Ok(d) if d.is_finite() && d > 0.0 => return Ok(d),
        Ok(d) if d.is_nan() => format!("`{s}` is no number of seconds"),
        Ok(d) if d.is_infinite() => format!("`{s}` is read as {d} s, no duration"),
        Ok(_) => format!("`{s}` s is not above 0"),
        Err(_) => format!("`{s}` is not a number"),
    };
    Err(format!(
        "{wrong}: expected a number of seconds above 0 (a whole number from the \
         programme's own to {MAX_DURATION})"
    ))
}
