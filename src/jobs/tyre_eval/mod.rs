//! `tyre-eval` as one job: a tyre file (.tir or .toml) and a CSV of points
//! (`fz, kappa, alpha, camber, speed` and optionally `pressure`; SI, rad,
//! Pa) in; the same points with `fx, fy, mz` (and `mx, my` for the Magic
//! Formula, and its loaded radius `rl`, m, for a 6.1/6.2 file with a
//! vertical model: on every row, the free radius at zero or negative load)
//! out. A point at zero load has its wheel off the road: no force, for
//! every model, and those points counted; a negative load is refused at
//! its cell (a file whose every load is negative as a rig logged in SAE's
//! axes: `physical.rs`, as `identify` says it). A load the vertical
//! model carries at no loaded radius above 0 (limit checks off, a 100 kN
//! load on an FSAE tyre) is refused at its row: MFeval's closed form gives
//! a radius of 0 or below there. A Magic Formula tyre is evaluated in one of MFeval's modes
//! (`useMode`, default 121: limit checks on, `α*` on); with the limit
//! checks on, the points outside the file's ranges are counted (their
//! load, slip, camber and pressure are evaluated at the ranges' ends, as
//! MFeval does; the speed has no range in a `.tir`).
//!
//! A point no tyre is evaluated at is refused, by file, line, column and
//! value, before anything is evaluated ([`PHYSICAL`]): a load beyond
//! ±1 MN, a slip ratio beyond ±10 (a wheel spinning at eleven times the
//! road speed), a slip angle beyond ±90° or a camber beyond ±45° (said as degrees where
//! it reads as an angle in degrees, and a camber column whose every tilt is
//! steeper than 20° asked as degrees), a speed beyond 300 m/s, a pressure above 5 MPa; and a negative speed: the points
//! speak ISO 8855, whose slip angle within ±90° is a wheel rolling
//! forwards, so the speed is its size (a Magic Formula's own sign of the
//! speed, which flips its `fy` and `my`, stays inside its model), and a
//! pressure of a few Pa, written in kPa, bar or psi (`pressure.rs`); a
//! slip-angle column written in degrees, told by one rule with the
//! camber's (`other_unit.rs`: round numbers of degrees, reaching where no
//! rig sweeps, without the small slips of a sweep in radians), unless the
//! header states radians (`alpha [rad]`); and a
//! column beside an input stating its own unit (`sa_deg`) that disagrees
//! with it on a row (`beside.rs`). A
//! model that still gives a non-finite force or moment at a point is
//! refused at that point: the output never holds a non-finite value.
//!
//! What the evaluation cannot stand behind is said, not dropped: an input
//! column the model does not read (`unread.rs`: a Gim tyre's camber), and
//! the points beyond the ranges of the rig data a TOML tyre was fitted to
//! (its `[fitted_ranges]`, which `identify` writes: `fitted.rs`), evaluated by
//! extrapolation, or else beyond the loads its model is meant for
//! (`model_loads.rs`), and a slip stiffness that changes sign inside the loads
//! evaluated (`stiffness.rs`: the public `FSAE_Defaults.tir`'s at 1625 N),
//! and (`checks.rs`) a tyre with no longitudinal force evaluated at a slip
//! ratio, a Magic Formula file with no overturning or rolling resistance
//! coefficients, and a Magic Formula `my` at a speed past its speed terms'
//! reach; (`friction.rs`) a resultant `√(fx² + fy²)` beyond the tyre's
//! friction and a model that does not couple `fx` and `fy` at combined
//! slip (UniTire, PAC89); (`standstill.rs`) a Magic Formula `mz` at zero
//! speed, its residual torque alone; (`radius.rs`) a loaded radius above
//! the free radius at the point's speed, with what drives it; (`past_fzmax.rs`)
//! a loaded radius past `FZMAX`, the deflection there held (MFeval's).
//! A load past the one that pushes a Magic Formula tyre onto its rim is
//! refused at its row in every mode (`bottoming.rs`).

mod at_points;
mod beside;
mod bottoming;
pub use at_points::{refused_points, slip_past_lock, PointRefused};
pub use slip_ratio::SlipPastLock;
mod camber;
mod checks;
mod columns;
mod evaluate;
pub use evaluate::run;
mod fitted;
pub use fitted::{one_level, past_end};
mod file_checks;
pub(crate) use file_checks::of_text;
pub use file_checks::FileChecks;
mod friction;
pub(crate) use friction::peak_of;
mod light_load;
mod meant;
mod measured;
mod model_loads;
mod not_carried;
mod opposed;
mod order;
mod other_unit;
mod past_fzmax;
mod physical;
mod points;
mod pressure;
mod radius;
mod ranges;
pub use ranges::{mf_inputs, ranges_left, CamberHint, FirstAt, RangeLeft};
mod reads;
pub use reads::{read_ranges, reads, Reads};
mod rolling;
mod slip_ratio;
mod standstill;
mod stiffness;
pub(crate) use stiffness::sign_changes;
mod unfitted_lateral;
mod unread;
mod zero_slip;

pub use camber::{SteepCamber, STEEP_CAMBER};
pub(crate) use checks::gives_none;
pub use checks::{BeyondMySpeed, Output, ZeroOutput, MY_RESOLUTION, MY_SPEED_TERMS};
pub use friction::{BeyondFriction, Uncoupled, FRICTION_TOLERANCE};
pub use light_load::{LightLoad, LIGHT_LOAD_SHARE};
pub use measured::MeasuredDifference;
pub use model_loads::LoadsLeft;
pub use physical::PHYSICAL;
pub use standstill::{AtRest, StandstillMz, STANDSTILL};
pub use stiffness::{AgainstSlip, SignChange};
pub use unread::Unread;

use crate::error::Error;
use crate::io::fitted_ranges::FittedRanges;
use crate::report::write_columns;
use crate::tyre::mf::{MfInput, TyreSide};
use crate::tyre::Tyre;
use serde::Serialize;
use std::path::PathBuf;

/// The report of `tyre-eval`: the points with their forces and moments.
#[derive(Debug, Clone, Serialize)]
pub struct TyreEvalReport {
    /// The points file.
    pub points: String,
    /// Points evaluated.
    pub count: usize,
    /// The tyre model.
    pub model: &'static str,
    /// MFeval's `useMode` the Magic Formula was evaluated in (`None` for
    /// other models).
    pub mode: Option<u32>,
    /// A Magic Formula file's `TYRESIDE` (`None` for other models).
    pub tyre_side: Option<TyreSide>,
    /// Whether the file (`TYRESIDE = 'RIGHT'`) was mirrored into a left
    /// tyre: its equations evaluated at −`alpha`, −`camber` and `fy`, `mz`,
    /// `mx` negated (`tyre::mf`'s module docs). MFeval applies no
    /// `TYRESIDE`: its outputs for such a file are the unmirrored ones.
    pub mirrored: bool,
    /// Points outside the `.tir` file's ranges of load, slip, camber or
    /// pressure, evaluated at the ranges' ends (limit checks on; 0
    /// otherwise); a point only below `FZMIN` is not among them.
    pub clamped: usize,
    /// Points outside no range but `FZMIN`'s, with the limit checks on:
    /// their forces evaluated at the load given, not at `FZMIN`.
    pub below_fzmin: usize,
    /// The ranges those points leave, each with its count and first point.
    pub ranges_left: Vec<ranges::RangeLeft>,
    /// The points outside the loads a TOML tyre's model is meant for, by
    /// side (`model_loads.rs`).
    pub loads_left: Vec<LoadsLeft>,
    /// Points a linear tyre is not meant for (`meant.rs`): a slip angle
    /// beyond its line's reach, a load its stiffness is no road tyre's at.
    pub not_meant: Vec<meant::NotMeant>,
    /// Points whose loaded radius exceeds the free radius at their speed,
    /// by what drives it (`radius.rs`).
    pub radius_above_free: Vec<radius::RadiusAboveFree>,
    /// Points past `FZMAX`, the limit checks on, whose loaded radius
    /// holds the deflection at `FZMAX` (`past_fzmax.rs`).
    pub radius_past_fzmax: Option<past_fzmax::RadiusPastFzmax>,
    /// Points at a positive load below a Magic Formula file's floor (its
    /// `FZMIN`, else a share of `FNOMIN`) that the ranges do not say.
    pub light_load: Option<LightLoad>,
    /// The points at a camber steeper than any car tyre's measured range,
    /// of a model that states no camber range.
    pub steep_camber: Option<SteepCamber>,
    /// Points at zero or negative load: the wheel off the road, no force
    /// (and the loaded radius `rl`, where written, the free radius).
    pub off_road: usize,
    /// The forces and moments the tyre gives none of where a tyre that
    /// has them gives some (`fx` at a slip ratio, a Magic Formula's `mx`,
    /// `my`).
    pub zero_outputs: Vec<ZeroOutput>,
    /// Points faster than a Magic Formula `my`'s speed terms reach.
    pub beyond_my_speed: Option<BeyondMySpeed>,
    /// Points whose Magic Formula `my` is beyond any tyre's rolling
    /// resistance at a speed its speed terms carry (`rolling.rs`).
    pub rolling_beyond: Option<rolling::RollingBeyond>,
    /// Points at a slip ratio beyond ±1, of a model that reads it.
    pub slip_past_lock: Option<slip_ratio::SlipPastLock>,
    /// Points whose `√(fx² + fy²)` exceeds the tyre's `μ·Fz` by more than
    /// [`FRICTION_TOLERANCE`].
    pub beyond_friction: Option<BeyondFriction>,
    /// Points at zero slip ratio whose `|fx|` exceeds a free-rolling
    /// tyre's by far ([`zero_slip::ZERO_SLIP_SHARE`] of `fz`).
    pub fx_at_zero_slip: Option<zero_slip::FxAtZeroSlip>,
    /// Points at combined slip of a model that does not couple `fx` and
    /// `fy` (each its pure-slip force).
    pub uncoupled: Option<Uncoupled>,
    /// Points at rest, where some are at a slip ratio or angle ≠ 0.
    pub at_rest: Option<AtRest>,
    /// Points at zero speed whose Magic Formula `mz` lacks the pneumatic
    /// trail's term.
    pub standstill_mz: Option<StandstillMz>,
    /// The input columns the model does not read, set at some points.
    pub unread: Vec<Unread>,
    /// The points file's columns `tyre-eval` neither reads nor writes
    /// (not carried to the output).
    pub not_written: Vec<String>,
    /// The ranges of the rig data a TOML tyre was fitted to (its
    /// `[fitted_ranges]`; `None`: the file states none).
    pub fitted_ranges: Option<FittedRanges>,
    /// The points beyond those ranges, evaluated by extrapolation, range
    /// by range (`fitted.rs`).
    pub beyond_fitted: fitted::BeyondFitted,
    /// Points given a lateral force by a tyre fitted to longitudinal data
    /// only (`unfitted_lateral.rs`).
    pub unfitted_lateral: Option<unfitted_lateral::UnfittedLateral>,
    /// A `.tir`'s longitudinal slip stiffness negative inside its own
    /// load range, found when the file is read, whatever the points.
    #[serde(skip)]
    pub longitudinal_turn: Option<crate::io::tir::LongitudinalTurn>,
    /// The slip stiffnesses that change sign inside the loads evaluated
    /// (the points' loads, where `longitudinal_turn` says the file's).
    #[serde(skip)]
    pub sign_changes: Vec<SignChange>,
    /// Points whose slip stiffness at their own conditions is negative.
    pub against_slip: Vec<AgainstSlip>,
    /// Points whose `fy` or `fx` opposes its slip inside the ranges.
    pub opposed: Vec<opposed::Opposed>,
    /// A `.tir`'s pure-curve peak |F|/Fz above any tyre's on a road or
    /// rig (`tyre::mf::WARN_FRICTION`), said as a warning.
    #[serde(skip)]
    pub peak_friction: Option<crate::tyre::mf::PeakFriction>,
    /// The measured outputs the points file carries, kept in the output
    /// beside the model's (`measured.rs`), each against the model's.
    pub measured: Vec<MeasuredDifference>,
    /// The line naming the measured columns kept and the model's names.
    #[serde(skip)]
    pub kept: Option<String>,
    /// Output columns, named, in file order.
    #[serde(skip)]
    pub columns: Vec<(&'static str, Vec<f64>)>,
    /// The output file.
    #[serde(skip)]
    pub out: PathBuf,
}

/// What a Magic Formula tyre adds to the evaluation: its mode, its points
/// outside the file's ranges, and its loaded radius at every point (where
/// it has a vertical model), with the points whose load it carries at no
/// radius, and those whose radius exceeds the free radius at their speed.
/// All empty for another model.
#[derive(Default)]
struct MfExtras {
    mode: Option<u32>,
    clamped: usize,
    below_fzmin: usize,
    ranges_left: Vec<ranges::RangeLeft>,
    loaded_radius: Option<Vec<f64>>,
    not_carried: Vec<not_carried::NotCarriedAt>,
    blown: Vec<not_carried::BlownAt>,
    bottomed: Vec<not_carried::BottomedAt>,
    radius_above_free: Vec<radius::RadiusAboveFree>,
    radius_past_fzmax: Option<past_fzmax::RadiusPastFzmax>,
}

impl MfExtras {
    /// Refuses the points whose load the vertical model does not carry,
    /// blows the loaded radius past the free radius or pushes the tyre
    /// onto its rim, at their rows of the points file `points` (`file`).
    fn refuse(&self, points: &std::path::Path, file: &crate::io::Columns) -> Result<(), Error> {
        let refused = (&self.blown[..], &self.bottomed[..]);
        not_carried::refuse_not_carried(points, file, &self.not_carried, refused)
    }
}

/// The [`MfExtras`] of `tyre` (its file's `rim`, `bottoming.rs`) at the
/// points `p`.
fn magic_formula_extras(
    (tyre, rim): (&Tyre, Option<crate::error::RimFrom>),
    p: &unread::Points,
    lines: &[usize],
) -> MfExtras {
    let Tyre::MagicFormula(t) = tyre else {
        return MfExtras::default();
    };
    let inputs = mf_inputs(p.columns, p.pressure);
    // MFeval holds a point to every range's end but `FZMIN`'s, below
    // which the forces are taken at the load given: such a point is not
    // said as evaluated at the ranges' ends.
    let only_below_fzmin = |q: &MfInput| {
        let left = t.ranges_left(q);
        !left.is_empty()
            && left
                .iter()
                .all(|(r, x)| r.column == "fz" && r.lo.is_some_and(|lo| *x < lo))
    };
    let below_fzmin = inputs.iter().filter(|q| only_below_fzmin(q)).count();
    let clamped = inputs.iter().filter(|q| t.is_clamped(q)).count() - below_fzmin;
    let mut not_carried = Vec::new();
    // The loaded radius, on every row, where the file has a vertical
    // model (6.1, 6.2): the free radius off the road.
    let loaded_radius: Option<Vec<f64>> = t.has_vertical_model().then(|| {
        let rl = inputs.iter().map(|q| t.loaded_radius_or_not_carried(q));
        rl.enumerate()
            .map(|(i, r)| match r {
                Some(Ok(r)) => r,
                Some(Err(n)) => {
                    not_carried.push((i, n, not_carried::pressure_to_blame(t, &inputs[i])));
                    f64::NAN
                }
                None => f64::NAN,
            })
            .collect()
    });
    let radius_above_free = loaded_radius
        .as_deref()
        .map_or_else(Vec::new, |rl| radius::above_free(t, rl, &inputs, lines));
    let blown = loaded_radius
        .as_deref()
        .map_or_else(Vec::new, |rl| radius::blown_by_load(t, rl, &inputs));
    let radius_past_fzmax = loaded_radius
        .as_deref()
        .and_then(|rl| past_fzmax::past_fzmax(t, rl, &inputs, lines));
    MfExtras {
        mode: Some(t.mode().use_mode()),
        clamped,
        below_fzmin,
        ranges_left: ranges::ranges_left(t, &inputs, lines),
        loaded_radius,
        not_carried,
        blown,
        bottomed: bottoming::past_rim(t, rim, &inputs),
        radius_above_free,
        radius_past_fzmax,
    }
}

impl TyreEvalReport {
    /// What the evaluation cannot stand behind: the columns the model does
    /// not read, and the points beyond the ranges the tyre was fitted to.
    pub fn warnings(&self) -> Vec<String> {
        let mut out: Vec<String> = self.unread.iter().map(|u| u.line(self.model)).collect();
        out.extend(self.unfitted_lateral.iter().map(|u| u.line(self.count)));
        out.extend(self.peak_friction.iter().map(|p| p.to_string()));
        out.extend(unread::not_written_line(&self.not_written));
        out.extend(self.longitudinal_turn.iter().map(|t| t.to_string()));
        out.extend(self.sign_changes.iter().map(SignChange::line));
        out.extend(self.against_slip.iter().map(|a| a.line(self.count)));
        out.extend(self.opposed.iter().map(|o| o.line(self.count)));
        out.extend(self.zero_outputs.iter().map(|z| z.line(self.count)));
        out.extend(self.beyond_my_speed.iter().map(|b| b.line(self.count)));
        out.extend(self.rolling_beyond.iter().map(|r| r.line(self.count)));
        out.extend(self.slip_past_lock.iter().map(|k| k.line(self.count)));
        out.extend(self.fx_at_zero_slip.iter().map(|z| z.line(self.count)));
        out.extend(
            self.uncoupled
                .iter()
                .map(|u| u.line(self.count, self.model)),
        );
        let uncoupled = self.uncoupled.is_some();
        out.extend(
            self.beyond_friction
                .iter()
                .map(|b| b.line(self.count, uncoupled)),
        );
        out.extend(self.at_rest.iter().map(|a| a.line(self.count)));
        out.extend(self.standstill_mz.iter().map(StandstillMz::line));
        out.extend(self.ranges_left.iter().map(|r| r.line(self.count)));
        out.extend(
            self.loads_left
                .iter()
                .map(|l| l.line(self.count, self.model)),
        );
        out.extend(self.not_meant.iter().map(|m| m.line(self.count)));
        out.extend(self.light_load.iter().map(|l| l.line(self.count)));
        out.extend(self.radius_above_free.iter().map(|r| r.line(self.count)));
        out.extend(self.radius_past_fzmax.iter().map(|r| r.line(self.count)));
        out.extend(
            self.steep_camber
                .iter()
                .map(|c| c.line(self.model, self.count)),
        );
        out.extend(self.beyond_fitted.ranges.iter().map(|f| f.line(self.count)));
        out
    }

    /// The model's column of `name` as written: `fy_model` beside a
    /// measured `fy`'s kept columns (`measured.rs`), else `name`.
    fn model_column(&self, name: &'static str) -> &'static str {
        match self.kept {
            Some(_) => measured::model_name(name),
            None => name,
        }
    }

    /// The measured columns kept and each against the model's, said
    /// before the closing line.
    pub fn measured_lines(&self) -> Vec<String> {
        let mut out: Vec<String> = self.kept.iter().cloned().collect();
        out.extend(self.measured.iter().map(MeasuredDifference::line));
        out
    }

    /// Writes the output CSV.
    pub fn write(&self) -> Result<(), Error> {
        let cols: Vec<(&str, &[f64])> = self.columns.iter().map(|(n, v)| (*n, &v[..])).collect();
        // Every digit, the shortest text that reads back the same `f64`:
        // this file is what the model is checked against MFeval with, to
        // 1e-12 of the loaded radius (rounded, it would fail that check).
        write_columns(&self.out, &cols)
    }

    /// The points held at the file's ranges' ends, said in the closing
    /// line. MFeval takes the rolling resistance at the load given, not
    /// the one saturated to FZMAX, and the loaded radius's free radius
    /// there too: said, or a 40 kN point's `my` or `rl` reads as one
    /// evaluated at the file's range.
    fn held_at_ends(&self) -> String {
        if self.clamped == 0 {
            return String::new();
        }
        let column = |k: &'static str| {
            let k = self.model_column(k);
            self.columns.iter().any(|(n, _)| *n == k).then_some(k)
        };
        // MFeval's `rl` keeps the load given in its free radius only: the
        // deflection is the one at the load held (`past_fzmax.rs`).
        let given: Vec<String> = [
            column("my").map(|k| format!("`{k}` at the load given")),
            column("rl").map(|k| {
                format!("`{k}` the free radius at the load given less the deflection at the load held within FZMAX")
            }),
        ]
        .into_iter()
        .flatten()
        .collect();
        format!(
            "; {} of them outside the file's ranges of load, slip, camber or pressure, evaluated at the ranges' ends{}",
            self.clamped,
            match given.is_empty() {
                false => format!(" ({}, as MFeval does)", given.join(", and ")),
                true => String::new(),
            }
        )
    }

    /// The points below `FZMIN` only, said in the closing line as the
    /// ranges' warning says them: at the load given, not at the range's end.
    fn at_load_given(&self) -> String {
        match self.below_fzmin {
            0 => String::new(),
            n => format!("; {n} of them below FZMIN only, their forces evaluated at the load given (MFeval does not raise a load to FZMIN)"),
        }
    }

    /// A right-side file's mirroring, said in the closing line: a hand
    /// evaluation of the file's equations (or MFeval's, which applies no
    /// `TYRESIDE`) gives the opposite `fy` at zero slip.
    fn mirrored_clause(&self) -> &'static str {
        match self.mirrored {
            true => "; the file's TYRESIDE is 'RIGHT': evaluated mirrored into a left tyre, as every tyre here (its equations at −alpha and −camber, with fy, mz and mx negated; MFeval applies no TYRESIDE)",
            false => "",
        }
    }

    /// The closing line (with the mode and the points evaluated at the
    /// file's limits, for a Magic Formula).
    pub fn wrote(&self) -> String {
        let mode = match self.mode {
            Some(m) => format!(
                " in MFeval mode {m}{}{}{}",
                self.held_at_ends(),
                self.at_load_given(),
                self.mirrored_clause()
            ),
            None => String::new(),
        };
        let rl = self.model_column("rl");
        let rl = match self.columns.iter().any(|(n, _)| *n == rl) {
            true => format!(", `{rl}` the free radius"),
            false => String::new(),
        };
        let off_road = match self.off_road {
            0 => String::new(),
            n => format!(
                "; {} at fz ≤ 0 (off the road): no force{rl}",
                crate::format::plural(n, "point", "points")
            ),
        };
        format!(
            "{} of {} ({} tyre) evaluated{mode}{off_road}; wrote {}",
            crate::format::plural(self.count, "point", "points"),
            self.points,
            self.model,
            self.out.display()
        )
    }
}
