//! The window a linear tyre is fitted in. A straight line through
//! saturated data is a secant, not the tyre's cornering stiffness (15.6
//! kN/rad through every row of one load of the Hoosier file against 33.8
//! kN/rad through those with |α| ≤ 2°, 37.6 kN/rad within 1°), so `--model linear` fits only the points of small slip angle,
//! |α| ≤ [`WINDOW_DEG`] — a rule of this program, chosen as the range
//! where a passenger-car or racing tyre's lateral force stays close to
//! its slope at zero slip — and says how many points it left out. Its
//! pneumatic trail is fitted on the same points when the data have `mz`
//! (`t_p` = the ratio of the slopes of Mz and Fy on α, as
//! [`crate::tyre::Linear`] writes `Mz = t_p·Fy`), or said held at 0.
//!
//! The window is cut only where the data leave their line: each
//! condition's points within it give a line `Fy = a + c·α` (least
//! squares, with an offset for ply steer and conicity) and its noise (the
//! residuals' standard deviation); the condition *saturates* where its
//! points beyond the window depart from that line by more than
//! [`NOISE_MULTIPLE`] times that noise and [`DEPARTURE_SHARE`] of the
//! line's force there (RMS over those points). Where no condition does
//! (data of a linear tyre, or a sweep that stays in the tyre's linear
//! range), the window is not needed, every point is fitted and the line
//! says so: "where the force saturates" was said of data that never do.
//! A condition with fewer than [`JUDGED_POINTS`] points in the window
//! cannot be judged; where none can, the window is kept and the line says
//! it was not judged.

use crate::identify::data::Condition;
use crate::tyre::Tyre;
use serde::Serialize;

/// The largest |α| a linear tyre is fitted to, degrees.
pub(crate) const WINDOW_DEG: f64 = 2.0;

/// The slip a file's digits resolve, rad: 2° written to six decimals in
/// rad (0.034907) lies 2e-5° past 2°, and the mean of a bin of samples
/// at ±2° lands a rounding error either side of it.
const SLIP_ROUNDING: f64 = 1e-6;

/// Whether a point of slip angle `slip` (rad) lies within the window, its
/// samples thinned in slip bins `bin` wide (rad; 0: not thinned): the
/// centre of its bin within ±[`WINDOW_DEG`], else its slip, to within
/// [`SLIP_ROUNDING`]. Symmetric about zero slip: a bin's mean lies
/// anywhere in the bin, and judged by it the bin at −2.0° was left out of
/// a symmetric sweep where the one at +2.0° was kept.
pub(crate) fn in_window(slip: f64, bin: f64) -> bool {
    // A bin below the resolution of the slips thinned nothing (`thin.rs`).
    let centre = Some((slip / bin).round() * bin)
        .filter(|c| bin > 0.0 && c.is_finite())
        .unwrap_or(slip);
    centre.abs() <= WINDOW_DEG.to_radians() + SLIP_ROUNDING
}

/// The window of a linear fit, as written to the report.
#[derive(Debug, Clone, Serialize)]
pub struct LinearWindow {
    /// The largest |α| fitted, degrees.
    pub max_abs_alpha_deg: f64,
    /// Points fitted (after thinning: rows with `--bin-deg 0`).
    pub points_fitted: usize,
    /// Points left out, with |α| above the window.
    pub points_left_out: usize,
    /// The pneumatic trail fitted in the window, m (`None`: no `mz`, held at
    /// 0, or given with `--hold`).
    pub pneumatic_trail: Option<f64>,
    /// The pneumatic trail given with `--hold pneumatic_trail=VALUE`, m,
    /// held there and not fitted (`None`: not given).
    pub trail_given: Option<f64>,
    /// The σ of the aligning moment `t_p·Fy` against the measured `mz`
    /// over the window's points with one, % (`None`: no `mz`), as the
    /// figure's aligning panel gives it.
    pub trail_sigma_percent: Option<f64>,
    /// The window's points with a measured `mz`.
    pub trail_points: usize,
    /// Where the trail given with `--hold` costs the aligning moment more
    /// than the hold guard lets a hold cost (the data refuse it; held all
    /// the same, as given): the trail they fit and its σ.
    pub trail_refused: Option<TrailRefused>,
    /// The loads of the conditions left with fewer than two points in the
    /// window, so not fitted, N.
    pub loads_left_out: Vec<f64>,
    /// Whether the points beyond the window depart from its line (module
    /// notes): the window cut, or not needed.
    pub beyond: Beyond,
    /// The largest |α| of the samples of the points fitted, degrees, the
    /// written `[fitted_ranges]`' (`None`: not known): past
    /// `max_abs_alpha_deg` by up to half a bin, as a bin within the window
    /// is judged by its centre and its samples spread about it.
    pub samples_reach_deg: Option<f64>,
}

/// A trail given with `--hold` that the window's `mz` refuses, judged as
/// the staged fit's guard judges a hold (`mf_staged::sigma_limit`): its σ
/// past what σ of the trail the data fit (Σα·Mz / Σα·Fy, [`trail`]) may
/// rise to, by 5 % of itself or 2.25 standard errors' worth over the
/// points less the one trail, the larger. A σ of 20 % (the large-σ
/// warning's bound, `notes.rs`) is no such test here: σ is the RMS of
/// `t_p·Fy − Mz` over the RMS of `Mz`, and `Mz = t_p·Fy` misses a real
/// tyre's aligning moment by a share of its own (13.2 % at the trail the
/// Hoosier file's 1656 N level fits, 0.0279 m), so a bound on σ alone
/// says the model form, not the hold; the guard compares the held trail
/// with the fitted one on the same points (15.2 % allowed there; 0.05 m
/// gives 79.8 %).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TrailRefused {
    /// The trail the points fit, m.
    pub fitted: f64,
    /// The aligning moment's σ at it, %.
    pub sigma_fitted_percent: f64,
    /// The most σ a hold may reach, %.
    pub sigma_limit_percent: f64,
    /// Which of the guard's two limits set it.
    pub limit: crate::identify::mf_staged::GuardLimit,
}

/// What the points beyond a linear fit's window do (module notes).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "beyond_window", rename_all = "snake_case")]
pub enum Beyond {
    /// Some condition's points depart from the window's line: the window
    /// is cut there.
    Saturates {
        /// The largest departure of a condition, RMS over its points
        /// beyond, % of the line's force there.
        departure_percent: f64,
        /// The conditions that depart, of those judged.
        conditions: usize,
        /// The conditions judged.
        judged: usize,
    },
    /// No condition's points depart: every point fitted.
    FollowLine {
        /// The largest departure of a condition, RMS over its points
        /// beyond, % of the line's force there.
        departure_percent: f64,
        /// The conditions judged.
        judged: usize,
    },
    /// No condition has enough points in the window to be judged: the
    /// window is kept.
    NotJudged,
    /// No point lies beyond the window.
    NoPointPast,
}

/// How many times a condition's noise within the window its points beyond
/// must depart from the window's line by to saturate: three standard
/// deviations, past what the noise and the line's own uncertainty
/// carried to larger slip give.
pub(crate) const NOISE_MULTIPLE: f64 = 3.0;

/// The share of the line's force (RMS over the points beyond) the points
/// beyond must depart by to saturate: 2 %, a tyre's force at twice its
/// linear range falls 10–30 % below its line (the Hoosier file's at 4°
/// by about 20 %); the rounding of a file's digits does not.
pub(crate) const DEPARTURE_SHARE: f64 = 0.02;

/// The least points within the window of a condition judged: a line and
/// its noise need three.
pub(crate) const JUDGED_POINTS: usize = 3;

impl LinearWindow {
    /// The lines said on the terminal (`mark` `" "`) and in the file's
    /// header (`mark` `"#"`).
    pub(crate) fn lines(&self, mark: &str) -> Vec<String> {
        let trail = match (self.trail_given, self.pneumatic_trail) {
            (Some(t), _) => format!(
                "{}{}",
                given_trail_words(t, self.trail_sigma_percent, self.trail_points),
                self.given_warning(t)
            ),
            (None, Some(t)) => format!(
                "pneumatic_trail = {t:.5} m fitted to mz on the same points (the ratio of the slopes of mz and fy on alpha): aligning moment σ {} % over {}{}",
                crate::format::fixed(self.trail_sigma_percent.unwrap_or(f64::NAN), 3),
                crate::format::plural(self.trail_points, "point", "points"),
                self.trail_warning()
            ),
            (None, None) => "pneumatic_trail held at 0 (no mz data)".into(),
        };
        let conditions = match self.loads_left_out.len() {
            0 => String::new(),
            n => format!(
                "; {} with fewer than two points in it left out, at Fz {} N",
                crate::format::plural(n, "condition", "conditions"),
                self.loads_left_out
                    .iter()
                    .map(|f| format!("{f:.0}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        };
        let window = match self.beyond {
            Beyond::FollowLine { departure_percent, judged } => format!(
                "{mark} linear window: not needed: in {} the points beyond |alpha| = {WINDOW_DEG} deg follow the line through those within it (they depart from it by at most {} % RMS, within {NOISE_MULTIPLE} times the noise or {} % of the force): the force does not saturate in these data, and all {} points are fitted",
                match judged { 1 => "the 1 condition judged".to_string(), n => format!("each of the {n} conditions judged") },
                crate::format::readable(departure_percent, 2),
                100.0 * DEPARTURE_SHARE,
                self.points_fitted
            ),
            Beyond::Saturates { departure_percent, conditions: n, judged } => format!(
                "{mark} linear window: fitted to |alpha| <= {} deg only ({}; {} with larger |alpha| left out, where the force saturates: in {n} of the {} judged they depart from the window's line by up to {} % RMS, beyond its noise{conditions}){}",
                self.max_abs_alpha_deg,
                crate::format::plural(self.points_fitted, "point", "points"),
                crate::format::plural(self.points_left_out, "point", "points"),
                crate::format::plural(judged, "condition", "conditions"),
                crate::format::readable(departure_percent, 2),
                self.reach()
            ),
            // Nothing left out: the window is not needed, said as where the
            // points beyond it follow the line (one file said "fitted to
            // |alpha| <= 2 deg only" binned and "not needed" unbinned).
            Beyond::NoPointPast if self.points_left_out == 0 && self.loads_left_out.is_empty() => format!(
                "{mark} linear window: not needed: no point lies beyond |alpha| = {WINDOW_DEG} deg, so all {} points are fitted",
                self.points_fitted
            ),
            Beyond::NotJudged | Beyond::NoPointPast => format!(
                "{mark} linear window: fitted to |alpha| <= {} deg only ({}; {} with larger |alpha| left out{}{conditions}){}",
                self.max_abs_alpha_deg,
                crate::format::plural(self.points_fitted, "point", "points"),
                crate::format::plural(self.points_left_out, "point", "points"),
                match self.beyond {
                    Beyond::NotJudged => format!(": no condition has {JUDGED_POINTS} points within the window to tell whether the force departs from its line beyond it"),
                    _ => String::new(),
                },
                self.reach()
            ),
        };
        vec![window, format!("{mark} {trail}")]
    }

    /// Where the samples of the points fitted reach past the window, the
    /// clause that says so: the window judges a slip bin by its centre
    /// (`in_window`), and its samples spread half a bin about it, so the
    /// written `[fitted_ranges]` reach past the window's |α| (2.11° on the
    /// Hoosier file, where the line said "<= 2 deg only" alone). Empty
    /// where they do not.
    fn reach(&self) -> String {
        match self.samples_reach_deg {
            Some(r) if r > self.max_abs_alpha_deg + SLIP_ROUNDING.to_degrees() => format!(
                "; a slip-angle bin is in the window by its centre, and the samples of those fitted reach |alpha| = {} deg, the [fitted_ranges] written",
                crate::format::fixed(r, 2)
            ),
            _ => String::new(),
        }
    }
}

/// `conditions` (thinned in slip bins `bin` wide, rad) kept to the window
/// ([`in_window`]; a condition left with fewer than two points dropped,
/// its load said: two of a file's loads vanished without a word), and the
/// window's account (no trail yet).
pub(crate) fn windowed(conditions: Vec<Condition>, bin: f64) -> (Vec<Condition>, LinearWindow) {
    let total: usize = conditions.iter().map(|c| c.points.len()).sum();
    let beyond = judged(&conditions, bin);
    if let Beyond::FollowLine { .. } = beyond {
        // The data never leave their line: every point is the line's.
        let reach = largest_slip(&conditions);
        let w = LinearWindow {
            max_abs_alpha_deg: reach.to_degrees(),
            points_fitted: total,
            points_left_out: 0,
            pneumatic_trail: None,
            trail_given: None,
            trail_sigma_percent: None,
            trail_points: 0,
            trail_refused: None,
            loads_left_out: Vec::new(),
            beyond,
            samples_reach_deg: None,
        };
        return (conditions, w);
    }
    let (kept, left): (Vec<Condition>, Vec<Condition>) = conditions
        .into_iter()
        .map(|mut c| {
            c.points.retain(|p| in_window(p.slip(), bin));
            c
        })
        .partition(|c| c.points.len() >= 2);
    let fitted: usize = kept.iter().map(|c| c.points.len()).sum();
    let w = LinearWindow {
        max_abs_alpha_deg: WINDOW_DEG,
        points_fitted: fitted,
        points_left_out: total - fitted,
        pneumatic_trail: None,
        trail_given: None,
        trail_sigma_percent: None,
        trail_points: 0,
        trail_refused: None,
        loads_left_out: left.iter().map(|c| c.fz).collect(),
        beyond,
        samples_reach_deg: None,
    };
    (kept, w)
}

/// Whether the points of `conditions` (thinned in bins `bin` wide)
/// beyond the window depart from their condition's line within it
/// (module notes).
fn judged(conditions: &[Condition], bin: f64) -> Beyond {
    let departures: Vec<(f64, bool)> = conditions
        .iter()
        .filter_map(|c| departure(c, bin))
        .collect();
    let beyond = conditions
        .iter()
        .flat_map(|c| &c.points)
        .any(|p| !in_window(p.slip(), bin));
    let largest = departures.iter().map(|d| d.0).fold(0.0, f64::max);
    let n = departures.iter().filter(|d| d.1).count();
    match (beyond, departures.len(), n) {
        (false, _, _) => Beyond::NoPointPast,
        (true, 0, _) => Beyond::NotJudged,
        (true, judged, 0) => Beyond::FollowLine {
            departure_percent: 100.0 * largest,
            judged,
        },
        (true, judged, conditions) => Beyond::Saturates {
            departure_percent: 100.0 * largest,
            conditions,
            judged,
        },
    }
}

/// The departure of condition `c`'s points (thinned in bins `bin` wide)
/// beyond the window from the line through its points within it, as a
/// share of the line's force there (RMS), and whether it saturates;
/// `None` where it has fewer than [`JUDGED_POINTS`] within or none beyond.
fn departure(c: &Condition, bin: f64) -> Option<(f64, bool)> {
    let pairs = |inside: bool| -> Vec<(f64, f64)> {
        c.points
            .iter()
            .filter(|p| in_window(p.slip(), bin) == inside && p.fy().is_finite())
            .map(|p| (p.slip(), p.fy()))
            .collect()
    };
    let (within, outside) = (pairs(true), pairs(false));
    if within.len() < JUDGED_POINTS || outside.is_empty() {
        return None;
    }
    let m = within.len() as f64;
    let (ma, mf) = within
        .iter()
        .fold((0.0, 0.0), |(a, f), (x, y)| (a + x / m, f + y / m));
    let (sxx, sxy) = within.iter().fold((0.0, 0.0), |(xx, xy), (x, y)| {
        (xx + (x - ma) * (x - ma), xy + (x - ma) * (y - mf))
    });
    if sxx <= 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    let line = |x: f64| mf + slope * (x - ma);
    let rss: f64 = within.iter().map(|(x, y)| (y - line(*x)).powi(2)).sum();
    let noise = (rss / (m - 2.0)).sqrt();
    let rms = |v: &mut dyn Iterator<Item = f64>| {
        let (s, n) = v.fold((0.0, 0.0), |(s, n), e| (s + e * e, n + 1.0));
        (s / n).sqrt()
    };
    let off = rms(&mut outside.iter().map(|(x, y)| y - line(*x)));
    let force = rms(&mut outside.iter().map(|(x, _)| line(*x)));
    let share = off / force.max(f64::MIN_POSITIVE);
    Some((
        share,
        off > NOISE_MULTIPLE * noise && share > DEPARTURE_SHARE,
    ))
}

/// The largest |α| of the points of `conditions`, rad (0 without points).
fn largest_slip(conditions: &[Condition]) -> f64 {
    conditions
        .iter()
        .flat_map(|c| &c.points)
        .map(|p| p.slip().abs())
        .fold(0.0, f64::max)
}

/// The smallest |α| of the points of `conditions`, rad (infinite
/// without points).
pub(crate) fn smallest_slip(conditions: &[Condition]) -> f64 {
    conditions
        .iter()
        .flat_map(|c| &c.points)
        .map(|p| p.slip().abs())
        .fold(f64::INFINITY, f64::min)
}

/// The pneumatic trail of the points of `conditions` with a measured
/// `mz`: Σα·Mz / Σα·Fy, the ratio of the least-squares slopes through
/// zero of Mz and Fy on α (m); `None` without such points.
pub(crate) fn trail(conditions: &[Condition]) -> Option<f64> {
    let (mut amz, mut afy) = (0.0, 0.0);
    for p in conditions.iter().flat_map(|c| &c.points) {
        if p.mz().is_finite() && p.fy().is_finite() {
            amz += p.slip() * p.mz();
            afy += p.slip() * p.fy();
        }
    }
    (afy != 0.0 && amz.is_finite()).then(|| amz / afy)
}

impl LinearWindow {
    /// Sets the trail fitted to `conditions` on `tyre` (0 without `mz`),
    /// or the trail `given` with `--hold`, with the σ of its aligning
    /// moment there and the points it has.
    pub(crate) fn fit_trail(
        &mut self,
        tyre: &mut Tyre,
        conditions: &[Condition],
        given: Option<f64>,
    ) {
        use crate::identify::{sigma_of, Channel};
        self.trail_given = given;
        self.pneumatic_trail = given.is_none().then(|| trail(conditions)).flatten();
        let set = given.or(self.pneumatic_trail);
        set_trail(tyre, set.unwrap_or(0.0));
        let points: Vec<_> = conditions
            .iter()
            .flat_map(|c| c.points.iter().cloned())
            .filter(|p| p.mz().is_finite())
            .collect();
        self.trail_points = points.len();
        self.trail_sigma_percent = set
            .filter(|_| !points.is_empty())
            .map(|_| sigma_of(Channel::AligningMoment, tyre, &points).0);
        self.trail_refused = match (given, self.trail_sigma_percent) {
            (Some(_), Some(held)) => refused_trail(tyre, conditions, &points, held),
            _ => None,
        };
    }

    /// The warning of a trail `t` given with `--hold`: the data's refusal
    /// ([`TrailRefused`], in the words the staged fit gives a refused
    /// hold's σ), else a σ past the large-σ bound, as a fitted trail's.
    fn given_warning(&self, t: f64) -> String {
        let (Some(r), Some(held)) = (self.trail_refused, self.trail_sigma_percent) else {
            return self.trail_warning();
        };
        format!(
            "; warning: the data refuse this hold: the trail they fit on the same points is {} m; held at {} m, σ rose from {:.3} % to {held:.3} %, past the {:.3} % a hold may reach ({}), so Mz = t_p·Fy at the trail held does not follow these data; it is held all the same, as given with --hold: hold a value you know, or leave it out to fit the trail",
            crate::format::fixed(r.fitted, 5),
            crate::format::exact(t),
            r.sigma_fitted_percent,
            r.sigma_limit_percent,
            r.limit.words(),
        )
    }

    /// The trail the window's `mz` judges: the one fitted to it, or the
    /// one given with `--hold` where there is `mz` (the figure draws it,
    /// and `mz` is not a column left unused).
    pub(crate) fn judged_trail(&self) -> Option<f64> {
        let given = self.trail_given.filter(|_| self.trail_points > 0);
        self.pneumatic_trail.or(given)
    }

    /// The warning a trail whose σ passes the swarm fits' bound adds, as
    /// theirs say it (`notes.rs`).
    fn trail_warning(&self) -> String {
        let large = super::notes::LARGE_SIGMA_PERCENT;
        match self.trail_sigma_percent {
            Some(s) if s > large => format!(
                "; warning: a σ above {large} % misses by more than a fifth of the measured values: Mz = t_p·Fy does not follow these data; do not rely on its aligning moment"
            ),
            _ => String::new(),
        }
    }
}

/// The words of a trail `t` (m) given with `--hold`: held, not fitted,
/// and judged against the `points` with a measured `mz` where there are
/// any (its σ there, %).
fn given_trail_words(t: f64, sigma: Option<f64>, points: usize) -> String {
    let judged = match sigma {
        Some(s) => format!(
            ": aligning moment σ {} % over {}",
            crate::format::fixed(s, 3),
            crate::format::plural(points, "point", "points")
        ),
        None => " (no mz data to judge it)".into(),
    };
    format!(
        "pneumatic_trail = {} m held as given with --hold, not fitted to mz{judged}",
        crate::format::exact(t)
    )
}

/// The refusal ([`TrailRefused`]) of a trail held on `tyre` at σ `held`
/// (%) over `points`, the window's with a measured `mz`: `None` where the
/// data fit no trail or the held one costs what a hold may.
fn refused_trail(
    tyre: &Tyre,
    conditions: &[Condition],
    points: &[crate::identify::data::Point],
    held: f64,
) -> Option<TrailRefused> {
    use crate::identify::{sigma_of, Channel};
    let fitted = trail(conditions)?;
    let mut free = tyre.clone();
    set_trail(&mut free, fitted);
    let sigma = sigma_of(Channel::AligningMoment, &free, points).0;
    // One parameter, the trail, fitted to the points.
    let dof = points.len().saturating_sub(1) as f64;
    let (most, limit) = crate::identify::mf_staged::sigma_limit(sigma, dof);
    (held > most).then_some(TrailRefused {
        fitted,
        sigma_fitted_percent: sigma,
        sigma_limit_percent: most,
        limit,
    })
}

/// Sets the trail of a linear `tyre` to `t`.
pub(crate) fn set_trail(tyre: &mut Tyre, t: f64) {
    if let Tyre::Linear(l) = tyre {
        l.pneumatic_trail = t;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The window line says how far its bins' samples reach where they
    /// pass ±2° (the Hoosier file's 2.11°), and nothing where they do not.
    #[test]
    fn a_window_line_says_how_far_its_bins_samples_reach() {
        let mut w = LinearWindow {
            max_abs_alpha_deg: WINDOW_DEG,
            points_fitted: 17,
            points_left_out: 62,
            pneumatic_trail: None,
            trail_given: None,
            trail_sigma_percent: None,
            trail_points: 0,
            trail_refused: None,
            loads_left_out: Vec::new(),
            beyond: Beyond::NotJudged,
            samples_reach_deg: Some(2.112),
        };
        let line = &w.lines(" ")[0];
        assert!(
            line.starts_with(
                "  linear window: fitted to |alpha| <= 2 deg only (17 points; 62 points"
            ),
            "{line}"
        );
        assert!(line.ends_with("; a slip-angle bin is in the window by its centre, and the samples of those fitted reach |alpha| = 2.11 deg, the [fitted_ranges] written"), "{line}");
        w.samples_reach_deg = Some(1.99);
        assert!(
            w.lines(" ")[0].ends_with("beyond it)"),
            "{}",
            w.lines(" ")[0]
        );
    }

    /// Symmetric about zero slip: the 0.25° bins at −2° and +2° both in
    /// wherever their means lie in them, the next ones out; unthinned, a
    /// file's rounding of ±2° in.
    #[test]
    fn the_window_keeps_the_bins_at_both_its_ends() {
        let bin = 0.25f64.to_radians();
        for deg in [2.0f64, -2.0, 2.0 + 1e-9, -2.0 - 1e-9, 2.1, -2.1, 1.9, 0.0] {
            assert!(in_window(deg.to_radians(), bin), "{deg}");
        }
        for deg in [2.13f64, -2.13, 2.25, -2.25] {
            assert!(!in_window(deg.to_radians(), bin), "{deg}");
        }
        for rad in [0.034907, -0.034907] {
            assert!(in_window(rad, 0.0), "{rad}");
        }
        assert!(!in_window(0.0352, 0.0));
        assert!(!in_window(-2.1f64.to_radians(), 0.0));
    }
}
