//! `tyre-eval`: forces and moments of a tyre file at the points of a CSV.

use anyhow::Result;
use clap::Args;
use handling::jobs::tyre_eval;
use std::path::PathBuf;

/// `handling tyre-eval`'s arguments.
#[derive(Args)]
pub struct TyreEvalArgs {
    /// Tyre file.
    tyre: PathBuf,
    /// Points file (CSV).
    points: PathBuf,
    /// Output CSV.
    #[arg(long)]
    out: PathBuf,
    /// MFeval's useMode for a Magic Formula tyre: hundreds 1 = limit checks
    /// on, 2 = off; tens 1 = α* off, 2 = on; units 1 = no turn slip (turn
    /// slip is not modelled). Default 121.
    #[arg(long, value_name = "NNN", allow_hyphen_values = true, value_parser = mode_code)]
    mode: Option<u32>,
}

/// `--mode`'s value: digits, or the refusal listing the modes, one a
/// line (`--mode abc` read "invalid digit found in string", `--mode -1`
/// "unexpected argument"). The digits' own meaning is checked by the
/// library, which names the digit refused.
fn mode_code(s: &str) -> Result<u32, String> {
    if !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit()) {
        if let Ok(code) = s.parse() {
            return Ok(code);
        }
    }
    let modes: Vec<String> = handling::tyre::mf::MfMode::CODES
        .iter()
        .map(|(code, what)| format!("  {code}: {what}"))
        .collect();
    Err(format!(
        "--mode takes one of MFeval's useMode codes, three digits (hundreds: limit checks 1 on, 2 off; tens: α* 1 off, 2 on; units: 1, no turn slip):\n{}",
        modes.join("\n")
    ))
}

/// `handling tyre-eval`.
pub fn tyre_eval(a: TyreEvalArgs) -> Result<()> {
    let r = tyre_eval::run(&a.tyre, &a.points, &a.out, a.mode)?;
    for w in r.warnings() {
        eprintln!("warning: {w}");
    }
    r.write()?;
    for line in r.measured_lines() {
        say!("{line}");
    }
    say!("{}", r.wrote());
    Ok(())
}
