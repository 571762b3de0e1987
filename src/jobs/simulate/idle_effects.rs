//! Effects a scenario switches on that act on nothing in its run, warned
//! with their numbers: a `relaxation_length` above 0 but below
//! [`MIN_RELAXATION_LENGTH`] (1 mm, where the tyres' lag is switched off),
//! and the effects of the longitudinal acceleration
//! (`longitudinal_load_transfer`, `combined_slip`) under a manoeuvre whose
//! speed never changes and that logs no `ax`: they scale `ax`, which is 0
//! throughout; and an `aero_load` on an axle whose tyres are linear
//! (`Fy = C_α·α`, whatever the load) with no roll camber and no combined
//! slip on it, which read the load: the down-force changes no force.
//! Units: m, m/s², N.

use crate::io::Scenario;
use crate::manoeuvre::Manoeuvre;
use crate::tyre::Tyre;
use crate::vehicle::MIN_RELAXATION_LENGTH;

/// The warnings of this module for scenario `sc`.
pub(super) fn idle_effects(sc: &Scenario) -> Vec<String> {
    let e = &sc.model.options.effects;
    let mut said = Vec::new();
    if e.relaxation_length > 0.0 && e.relaxation_length < MIN_RELAXATION_LENGTH {
        said.push(format!(
            "`model.effects.relaxation_length` = {} m acts on nothing: below {} m (1 mm, 50 µs of lag at 20 m/s, far below what a run resolves) the tyres' lag is switched off, and the slip angles follow their kinematic values at once; give {} m or more for a lag (a car tyre's is a few tenths of a metre), or 0",
            crate::format::exact(e.relaxation_length),
            crate::format::exact(MIN_RELAXATION_LENGTH),
            crate::format::exact(MIN_RELAXATION_LENGTH)
        ));
    }
    said.extend(idle_aero(sc));
    let mut by_ax = Vec::new();
    if e.longitudinal_load_transfer != 0.0 {
        by_ax.push(format!(
            "`model.effects.longitudinal_load_transfer` = {}",
            crate::format::exact(e.longitudinal_load_transfer)
        ));
    }
    if e.combined_slip.is_some() {
        by_ax.push("`model.effects.combined_slip`".to_string());
    }
    if by_ax.is_empty() {
        return said;
    }
    if let Some(speed) = constant_speed(sc) {
        said.push(format!(
            "{} {} on nothing: {} with the longitudinal acceleration ax, and this run holds its speed at {} m/s throughout (ax = 0, and no `ax` is logged); drive a speed change (a replay or a schedule whose speed changes) for {} to act",
            by_ax.join(" and "),
            if by_ax.len() > 1 { "act" } else { "acts" },
            if by_ax.len() > 1 { "they act" } else { "it acts" },
            crate::format::significant(speed, 4),
            if by_ax.len() > 1 { "them" } else { "it" }
        ));
    }
    said
}

/// The run's speed, m/s, where it never changes and no `ax` is logged
/// (None: the speed changes, or a replay logs `ax`).
fn constant_speed(sc: &Scenario) -> Option<f64> {
    let m = &sc.manoeuvre;
    let first = m.speed(m.start_time());
    match m {
        Manoeuvre::Replay(r) => {
            let same = r.speed.iter().all(|&u| u == first);
            (r.ax.is_none() && same).then_some(first)
        }
        _ => Some(first),
    }
}

/// The part of an `aero_load` on axles with linear tyres (whose force
/// `C_α·α` does not depend on the load) with no roll camber there and no
/// combined slip (camber thrust and the friction circle read the load):
/// the down-force it adds there, said with the axles' numbers at the run's
/// starting speed. Said per axle: a down-force on a linear front acts on
/// nothing even where the rear's tyres read theirs.
fn idle_aero(sc: &Scenario) -> Option<String> {
    let e = &sc.model.options.effects;
    let k = e.aero_load;
    let tyres = [&sc.model.front, &sc.model.rear];
    let acts = |axle: usize| {
        !matches!(tyres[axle], Tyre::Linear(_))
            || e.roll_camber[axle] != 0.0
            || e.combined_slip.is_some()
    };
    let loaded: Vec<usize> = (0..2).filter(|&i| k[i] != 0.0 && !acts(i)).collect();
    if loaded.is_empty() {
        return None;
    }
    // Where the other axle's down-force does act, the warning names the
    // idle part only.
    let part = if (0..2).any(|i| k[i] != 0.0 && acts(i)) {
        format!(": its {} part", ["front", "rear"][loaded[0]])
    } else {
        String::new()
    };
    let m = &sc.manoeuvre;
    let u = m.speed(m.start_time());
    let axle = ["front", "rear"];
    let adds: Vec<String> = loaded
        .iter()
        .map(|&i| {
            let n = crate::format::rounded(k[i] * u * u, 4);
            format!("{n} N on the {} axle", axle[i])
        })
        .collect();
    Some(format!(
        "`model.effects.aero_load` = [{}, {}] N per (m/s)²{part} acts on nothing: it adds {} at {} m/s (k·u²), and the {} tyres are linear, whose force C_α·α does not depend on the load (nor does anything else here: no roll camber, no combined slip); give a tyre whose force grows with its load (gim, pac89, a .tir) for the down-force to act, or 0",
        crate::format::exact(k[0]),
        crate::format::exact(k[1]),
        adds.join(" and "),
        crate::format::rounded(u, 4),
        match loaded.as_slice() {
            [i] => axle[*i],
            _ => "front and rear",
        }
    ))
}
