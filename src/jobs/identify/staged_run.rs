//! The run of `identify --model mf61|mf62` ([`run_staged`]): the rig data
//! read and prepared as Wei et al.'s (2010) stages take them, the fit
//! ([`crate::identify::mf_staged`]), and the .tir written from it (a
//! template's constants and layout kept), its header saying what the fit
//! held, skipped and warned of, read back and checked to reproduce the
//! fitted forces. Each step is a function of its own; the report and its
//! lines are in `staged.rs`.

use super::ranges::Span;
use super::staged::{stage_lines, unfitted_blocks, StagedJob};
use super::{Options, StartArg};
use crate::error::{Error, FitError, OptionsError};
use crate::format::exact;
use crate::identify::mf_staged::{
    self, Holding, PooledSigma, Prepared, Stage, StagedReport, StartScheme,
};
use crate::io::tir::TirDocument;
use crate::report::{refuse_overwrites, OutputLock};
use crate::tyre::mf::{MagicFormula, MfCoefficients};
use crate::tyre::StagedFit;

/// Runs the staged fit of `o`, version `fit` of its model's (from the
/// model's registry entry: `mf61` fits and writes an MF 6.1, `mf62` an
/// MF 6.2).
pub(super) fn run_staged(o: &Options, fit: StagedFit) -> Result<StagedJob, Error> {
    let out = o.output_path();
    let lock = claimed_outputs(o, &out)?;
    let (template, template_tyre) = super::template::read_given(o.template.as_deref())?;
    let template_warning = template_curve_warning(template.as_ref(), template_tyre.as_ref());
    // A lifted wheel's samples are no test condition (`identify/lifted.rs`).
    let (data, moments, lifted) = super::read_lifted(o)?;
    // Nor is a sample at rest (`standstill.rs`); forces far too small for
    // their loads are warned of as for every model (`force_scale.rs`).
    let (data, moments, at_rest) = super::standstill::without_rest(data, moments);
    super::flat_alpha::refuse_flat_lateral(&data, &o.data)?;
    let input_warnings = super::force_scale::small_forces(&data);
    let default_speed = template_tyre
        .as_ref()
        .map_or(16.7, |t| t.coefficients.LONGVL);
    let bin = o.alpha_bin_deg.to_radians();
    let prepared = mf_staged::prepare(&o.data, &data, &moments, bin, default_speed)?;
    let spans = data_spans(&prepared, &data);
    let template_tyre = template_tyre.map(|mut t| {
        t.limits = super::ranges::mf_limits(&spans, t.side, t.limits);
        t
    });
    // Template constants off the data replaced (`nompres.rs`), sizes kept (`template_size.rs`).
    let (rows, version) = (&prepared.rows, fit.version);
    let recentred = super::nompres::recentred(version, template_tyre.as_ref(), rows, &o.hold);
    let kept = super::template_size::kept(template_tyre.as_ref(), rows, &o.hold);
    let settings = settings_of(o, fit, template_tyre, template.as_ref(), &recentred)?;
    let id = mf_staged::identify(&prepared.rows, &settings)
        .map_err(|e| FitError::in_data(&o.data, None, e.into()))?;
    let fitted = fitted_stages(&id.report);
    let raw = mf_staged::raw_rows(&data, &moments, default_speed);
    let sigma_pooled = mf_staged::pooled_sigma(&id.tyre, &raw, &fitted);
    crate::tyre::ModelParameters::check_sizes(&id.tyre)
        .map_err(|source| FitError::BeyondAnyTyre { source })?;
    let held = held_values(o, (recentred, kept), &id.tyre, &data);
    let mut written = id.tyre.clone();
    written.limits = super::ranges::mf_limits(&spans, written.side, written.limits);
    let mut unfitted: Vec<String> = lifted.iter().map(|l| l.line()).collect();
    unfitted.extend(at_rest.map(|r| r.line()));
    unfitted.extend(not_fitted(&settings, &id.report, &written, &prepared.rows));
    let named = thinned_levels(&prepared);
    let curvature_above_one = super::curvature::curvature_excess(&written, &spans, &fitted);
    // A fitted curve beyond any tyre's is written, marked, not refused: a
    // long fit is not lost, and the readers refuse the file with the
    // same numbers.
    let pure_curve_warning: Vec<String> = template_warning
        .into_iter()
        .chain(pure_curve_warning(&written, &o.hold, &id.report))
        .collect();
    let head = file_head(o, &spans, &unfitted, &held)
        + &stage_comments(&id.report, named, &sigma_pooled)
        + &warning_comments(&curvature_above_one, &input_warnings, &pure_curve_warning);
    // The file's own checks, as `tyre-eval` makes them of it.
    let body = crate::io::tir::tir_text(&written, template.as_ref())?;
    let (tir, file_warnings) = super::written_checks::with_file_checks(&out, &head, &body);
    super::written_checks::refuse_paper_turn(o.start, &out, &tir, &fitted)?;
    super::written_checks::refuse_held_turn(&o.hold, &written)?;
    let back = read_back_difference(&tir, &id.tyre, &prepared)?;
    let figures =
        super::staged_figure::stage_figures(&id.tyre, &fitted, &prepared.rows, named, &out);
    Ok(StagedJob {
        held,
        report: id.report,
        data: o.data.display().to_string(),
        recorded: o.recorded(),
        rows: prepared.account,
        sigma_pooled,
        round_trip_relative_difference: back,
        curvature_above_one,
        pure_curve_warning,
        file_warnings,
        input_warnings,
        figures,
        not_from_this_fit: super::staged::not_from_this_fit(&out),
        tir,
        unfitted,
        options: o.clone(),
        lock,
    })
}

/// The outputs of the fit (the .tir `out`, its report and figures) refused
/// where they would overwrite an input (the data, the template), then
/// held for this run.
fn claimed_outputs(o: &Options, out: &std::path::Path) -> Result<OutputLock, Error> {
    let mut inputs = vec![o.data.clone()];
    inputs.extend(o.template.clone());
    let mut outputs = vec![out.to_path_buf(), out.with_extension("report.json")];
    outputs.extend(
        crate::identify::mf_staged::Stage::ALL
            .iter()
            .map(|&st| super::staged_figure::stage_png(out, st)),
    );
    refuse_overwrites(&outputs, &inputs)?;
    super::output_lock(o)
}

/// The warning of a template whose curves are no tyre's, or `None`.
/// A template's curves are judged as a tyre's, and warned of: the fit
/// sets the coefficients it starts from (a block no stage fits is
/// written as the template has it, and said again in the file).
fn template_curve_warning(
    template: Option<&TirDocument>,
    tyre: Option<&MagicFormula>,
) -> Option<String> {
    template
        .zip(tyre)
        .and_then(|(d, t)| d.curve_refusal(t))
        .map(|e| {
            format!("the template's curves are no tyre's: {e}; its coefficients only start the fit")
        })
}

/// The rows' ranges as the fit's and the file's validity ranges: a
/// template's own (a pressure range of 200–400 kPa) would saturate data
/// outside them in the fit, and the file would extrapolate past the
/// data silently. Widened to the levels the thinning reached and to the
/// samples' own slips.
fn data_spans(prepared: &Prepared, data: &crate::identify::data::RigData) -> Vec<Span> {
    let spans = super::ranges::row_spans(&prepared.rows);
    let spans = match &prepared.account.thinning {
        Some(g) => super::ranges::widened_to_reached_levels(spans, &g.levels),
        None => spans,
    };
    super::ranges::widened_to_sample_slips(spans, data)
}

/// The fit's settings from the options `o`: the version `fit`, the start
/// scheme, the template tyre (its limits the data's), and what is held:
/// the values given with `--hold` and the constants `recentred` to the
/// data, then the keys the template file gives.
fn settings_of(
    o: &Options,
    fit: StagedFit,
    template_tyre: Option<MagicFormula>,
    template: Option<&TirDocument>,
    recentred: &[super::holds::Held],
) -> Result<mf_staged::Settings, Error> {
    let mut given = o.hold.clone();
    given.extend(recentred.iter().map(|h| (h.name.clone(), h.value)));
    Ok(mf_staged::Settings {
        version: fit.version,
        start: match o.start {
            StartArg::Data => StartScheme::Data,
            StartArg::Paper => StartScheme::Paper,
            StartArg::Template if o.template.is_none() => {
                return Err(OptionsError::TemplateMissing.into())
            }
            StartArg::Template => StartScheme::Template,
        },
        template: template_tyre,
        max_iterations: o.max_iterations.unwrap_or(mf_staged::LM_ITERATIONS),
        cap_given: o.max_iterations.is_some(),
        holding: Holding {
            given,
            // The coefficients the template file gives: a parameter the
            // data do not determine is held at the template's value then.
            template_keys: template.map_or(Vec::new(), |d| {
                MfCoefficients::NAMES
                    .iter()
                    .filter(|k| d.get(k).is_some())
                    .map(|k| k.to_string())
                    .collect()
            }),
        },
    })
}

/// The values held (written at their value, not fitted): those given
/// with `--hold`, the template's constants `recentred` to the data and
/// its sizes `kept` (`template_size.rs`), and without a template the
/// constants the data set for the fitted `tyre`.
fn held_values(
    o: &Options,
    (recentred, kept): (Vec<super::holds::Held>, Vec<super::holds::Held>),
    tyre: &MagicFormula,
    data: &crate::identify::data::RigData,
) -> Vec<super::holds::Held> {
    let mut held = super::holds::holds_of(o, &given_names(o));
    held.extend(recentred);
    held.extend(kept);
    if o.template.is_none() {
        held.extend(super::nompres::constants_held(tyre, data, o));
    }
    held
}

/// The lines on what the fit did not fit from these data: a template's
/// lateral stiffness on its negative branch, and each block written
/// without data ([`unfitted_blocks`], told how many of the `rows` are
/// of combined slip).
fn not_fitted(
    settings: &mf_staged::Settings,
    report: &StagedReport,
    written: &MagicFormula,
    rows: &[mf_staged::MfRow],
) -> Vec<String> {
    let combined = rows.iter().filter(|r| is_combined(r)).count();
    let mut out: Vec<String> = settings
        .template
        .as_ref()
        .and_then(super::written_checks::stiffness_branch_note)
        .into_iter()
        .collect();
    // The version written, if not the template's, said first.
    let version = settings.template.as_ref();
    let version = version.and_then(|t| super::template_version::change_line(t, settings.version));
    out.splice(0..0, version);
    let template = settings.template.is_some();
    out.extend(unfitted_blocks(report, template, written, combined));
    out
}

/// The comment lines that open the written file: the command and what
/// it held ([`held_comment`]), the data's ranges, what was not fitted
/// (`unfitted`), and the values `held`.
fn file_head(
    o: &Options,
    spans: &[Span],
    unfitted: &[String],
    held: &[super::holds::Held],
) -> String {
    held_comment(o)
        + &super::ranges::tir_comment(spans, o.template.is_some())
        + &unfitted
            .iter()
            .map(|l| format!("$ {l}\n"))
            .collect::<String>()
        + &super::holds::held_file_lines(held, "$")
}

/// The levels the thinning named (none without thinning), which name
/// the loads in the stages' lines and the figure.
fn thinned_levels(prepared: &Prepared) -> &[crate::identify::grouping::Levels] {
    prepared
        .account
        .thinning
        .as_ref()
        .map_or(&[][..], |g| g.levels.as_slice())
}

/// The stages of `report` that ran (not skipped).
fn fitted_stages(report: &StagedReport) -> Vec<Stage> {
    report
        .stages
        .iter()
        .filter(|s| s.skipped.is_none())
        .map(|s| s.stage)
        .collect()
}

/// The terminal's record of each stage and the pooled σ as `$` comment
/// lines, so that the file says what its fit left undetermined or
/// unconverged (without the seconds: a refit writes the same file).
fn stage_comments(
    report: &StagedReport,
    named: &[crate::identify::grouping::Levels],
    sigma_pooled: &PooledSigma,
) -> String {
    stage_lines(report, named, false)
        .iter()
        .chain(std::iter::once(&sigma_pooled.line()))
        .map(|l| format!("$ {}\n", l.trim_start()))
        .collect()
}

/// The `$ warning:` comment lines of the written file: the curvatures
/// above 1, the warnings on the data read, and the pure curves beyond
/// any tyre's, in that order.
fn warning_comments(
    curvature_above_one: &[super::curvature::CurvatureExcess],
    input_warnings: &[String],
    pure_curve_warning: &[String],
) -> String {
    let curvature: String = curvature_above_one
        .iter()
        .map(|e| format!("$ warning: {}\n", e.line()))
        .collect();
    curvature
        + &input_warnings
            .iter()
            .map(|w| format!("$ warning: {w}\n"))
            .collect::<String>()
        + &pure_curve_warning
            .iter()
            .map(|w| format!("$ warning: {w}\n"))
            .collect::<String>()
}

/// The written .tir text `tir` read back: its largest relative force
/// difference from the fitted `tyre` over the rows, refused above 1e-9
/// (the file would not be the fit).
fn read_back_difference(tir: &str, tyre: &MagicFormula, prepared: &Prepared) -> Result<f64, Error> {
    let read_back = TirDocument::parse(std::path::Path::new("<written .tir>"), tir)?.template()?;
    let back = mf_staged::round_trip_difference(tyre, &read_back, &prepared.rows);
    if back > 1e-9 {
        return Err(FitError::RoundTrip { difference: back }.into());
    }
    Ok(back)
}

/// The warning of a fitted tyre whose pure curves (of the forces it has:
/// `PDY1`, `PDX1` not 0) go beyond any tyre's, with the numbers, or `None`.
/// The coefficient named is said as what it is (`report`): fitted, held
/// by its stage, given with `--hold`, or kept from the template or the
/// defaults where no stage fitted its block.
fn pure_curve_warning(
    t: &MagicFormula,
    hold: &[(String, f64)],
    report: &StagedReport,
) -> Option<String> {
    let c = &t.coefficients;
    // The cornering stiffness per unit load at FNOMIN is judged after the
    // curves, as the readers judge it: a fit outside 1.5–100 1/rad is
    // written and warned of, not refused, as a curve beyond any tyre's is
    // (a long fit is not lost, the data or their units may be what to
    // fix, and the file shows what the fit found); every reader refuses
    // the file with the same numbers, so nothing runs on it unseen.
    let e = t
        .check_pure_curves(c.PDY1 != 0.0, c.PDX1 != 0.0)
        .err()
        .or_else(|| crate::io::tir::cornering_per_load(t))?;
    let given = hold.iter().any(|(k, _)| *k == e.key);
    let parameter = report
        .stages
        .iter()
        .filter(|s| s.skipped.is_none())
        .flat_map(|s| &s.parameters)
        .find(|p| p.name == e.key);
    let (what, remedy) = match parameter {
        _ if given => ("held", "hold it at a tyre's value, or fit it"),
        Some(p) if p.free => ("fitted", "refit with --hold, or check the data"),
        Some(_) => (
            "held",
            "hold it at a tyre's value with --hold, or check the data",
        ),
        None if report.template => (
            "template's (no stage fitted it)",
            "give a template whose block is a tyre's, or data that fit it",
        ),
        None => (
            "default (no stage fitted it)",
            "give --template with a tyre's coefficients, or data that fit it",
        ),
    };
    Some(format!(
        "the {what} `{}` = {}: {}; the file is written as {}, but tyre-eval and simulate refuse it: {remedy}",
        e.key,
        exact(c.get(&e.key).unwrap_or(f64::NAN)),
        e.reason,
        if given || parameter.is_some() { "fitted" } else { "it stands" },
    ))
}

/// The comment lines that open a written .tir: the command that repeats
/// the fit (every option that changes it) and each coefficient held at
/// the value given, not fitted. A `$` line is a comment wherever it
/// stands.
fn held_comment(o: &Options) -> String {
    let mut s = format!("$ identified by `{}`\n", o.command());
    for (n, v) in &o.hold {
        s += &format!(
            "$ held: {n} = {}: given with --hold, not fitted (SI units)\n",
            exact(*v)
        );
    }
    s
}

/// A row of combined slip: both |κ| and |α| above 1e-3, as the combined
/// stages take them.
fn is_combined(r: &mf_staged::MfRow) -> bool {
    r.kappa.abs() > 1e-3 && r.alpha.abs() > 1e-3
}

/// The names given with `--hold`: a given value is set before the stages
/// and written whether or not a stage that fits it ran, so every hold is
/// applied.
fn given_names(o: &Options) -> Vec<String> {
    o.hold.iter().map(|(n, _)| n.clone()).collect()
}
