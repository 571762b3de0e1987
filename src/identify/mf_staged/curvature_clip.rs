//! A curvature parameter held by the Magic Formula's bound `E ≤ 1`, not
//! for want of data. The formula clips each curvature factor at 1
//! (`Ex`, `Ey`, `Et`, the combined weights' `Exα` and `Eyκ`; MFeval's
//! limit checks, `tyre/mf/mode.rs`): where a fit leaves the factor at or
//! above 1 at every row it shapes, the force there no longer depends on
//! the factor's coefficients, their Jacobian columns are 0, and the
//! stage's words were those of a parameter the data do not determine
//! (`--start paper` on the noise-free `car205_60R19.tir` grid: `PEY1`
//! "not determined by the data" where the paper's unbounded LM had taken
//! `Ey` to 1 at every load and camber). The parameter is then held where
//! the fit left it (any value keeping the factor at 1 over the rows fits
//! alike), with its own typed reason ([`AtClip`]): the factor, and the
//! loads and cambers of the rows where it reaches 1.
//!
//! The test is exact: the stage's exact Jacobian column of the parameter
//! is 0 with the limit checks on, and not 0 with them off (the only
//! difference the checks make to a curvature coefficient's derivative is
//! the clip; their input saturation moves the point, never zeroes it).
//! The rows where the clip binds are those whose entry is 0 with the
//! checks on and not with them off. Units: N, rad.

use super::problem::StageProblem;
use crate::optim::local::Residuals;
use serde::Serialize;

/// A curvature factor of the Magic Formula that it clips at 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum CurvatureFactor {
    /// Pure longitudinal `Ex` (`PEX1..4`).
    Ex,
    /// Pure lateral `Ey` (`PEY1..5`).
    Ey,
    /// The pneumatic trail's `Et` (`QEZ1..5`).
    Et,
    /// The combined `Fx` weight's `Exα` (`REX1`, `REX2`).
    ExAlpha,
    /// The combined `Fy` weight's `Eyκ` (`REY1`, `REY2`).
    EyKappa,
}

impl CurvatureFactor {
    /// The factor coefficient `name` enters, if it is a curvature one.
    pub fn of(name: &str) -> Option<Self> {
        let family = name.get(..3)?;
        Some(match family {
            "PEX" => CurvatureFactor::Ex,
            "PEY" => CurvatureFactor::Ey,
            "QEZ" => CurvatureFactor::Et,
            "REX" => CurvatureFactor::ExAlpha,
            "REY" => CurvatureFactor::EyKappa,
            _ => return None,
        })
    }

    /// The force it shapes.
    pub fn force(self) -> &'static str {
        match self {
            CurvatureFactor::Ex | CurvatureFactor::ExAlpha => "Fx",
            CurvatureFactor::Ey | CurvatureFactor::EyKappa => "Fy",
            CurvatureFactor::Et => "Mz",
        }
    }

    /// Its symbol.
    pub fn symbol(self) -> &'static str {
        match self {
            CurvatureFactor::Ex => "Ex",
            CurvatureFactor::Ey => "Ey",
            CurvatureFactor::Et => "Et",
            CurvatureFactor::ExAlpha => "Exα",
            CurvatureFactor::EyKappa => "Eyκ",
        }
    }
}

/// Where a curvature factor reaches its clip at 1 over a stage's rows.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AtClip {
    /// The factor.
    pub factor: CurvatureFactor,
    /// Rows where the clip binds (every row the factor shapes).
    pub rows: usize,
    /// The stage's rows.
    pub of: usize,
    /// The least and largest load of those rows, N.
    pub fz: [f64; 2],
    /// The least and largest inclination of those rows, rad.
    pub camber: [f64; 2],
}

impl AtClip {
    /// The words of a parameter held by it.
    pub fn said(&self) -> String {
        let e = self.factor.symbol();
        // `2000 to 6000 N`, `0.00° to 2.01°`; one value once.
        let span = |[lo, hi]: [f64; 2], text: &dyn Fn(f64) -> String, unit: &str| {
            if text(lo) == text(hi) {
                format!("{}{unit}", text(lo))
            } else {
                format!("{} to {}{unit}", text(lo), text(hi))
            }
        };
        let load = span(self.fz, &|v| crate::format::fixed(v, 0), " N");
        let camber = span(self.camber, &|v| format!("{:.2}°", v.to_degrees()), "");
        format!(
            "held by the Magic Formula's bound {e} ≤ 1, not for want of data: where the fit left it, {e} reaches 1 at every one of the {} rows it shapes (of the stage's {}; Fz {load}, camber {camber}) and is clipped there, so {} does not depend on it; held there, as any value keeping {e} at 1 over these rows fits alike",
            self.rows,
            self.of,
            self.factor.force(),
        )
    }
}

/// Where free parameter `k` of `problem` at `p` is held by its curvature
/// factor's clip at 1 (module notes), or `None`: not a curvature
/// coefficient, a column that is not 0, or one that is 0 unclipped too.
pub(super) fn at_clip(problem: &StageProblem, p: &[f64], k: usize) -> Option<AtClip> {
    let factor = CurvatureFactor::of(problem.names[k])?;
    let column = |checks: bool| {
        let mut t = problem.tyre(p);
        let mut mode = t.mode();
        mode.limit_checks = checks;
        t.set_mode(mode);
        let q = StageProblem::new(
            t,
            problem.stage,
            problem.names.clone(),
            problem.rows.clone(),
            problem.derivatives,
        );
        let mut r = vec![0.0; q.count()];
        q.residuals(p, &mut r);
        let bounds = super::problem::unbounded(p.len());
        q.jacobian(p, &r, &bounds)
            .column(k)
            .iter()
            .copied()
            .collect::<Vec<f64>>()
    };
    let (clipped, free) = (column(true), column(false));
    if clipped.iter().any(|d| *d != 0.0) {
        return None;
    }
    let binds: Vec<usize> = (0..free.len()).filter(|&i| free[i] != 0.0).collect();
    if binds.is_empty() {
        return None;
    }
    let span = |f: &dyn Fn(usize) -> f64| {
        binds
            .iter()
            .fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], &i| {
                [lo.min(f(i)), hi.max(f(i))]
            })
    };
    Some(AtClip {
        factor,
        rows: binds.len(),
        of: problem.rows.len(),
        fz: span(&|i| problem.rows[i].fz),
        camber: span(&|i| problem.rows[i].camber),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::identify::mf_staged::params::Stage;
    use crate::identify::mf_staged::problem::Derivatives;
    use crate::identify::mf_staged::MfRow;
    use crate::io::tir::load_tir;
    use std::path::Path;

    /// Pure lateral rows at two loads and two cambers, α ±0.02 and ±0.15.
    fn rows() -> Vec<MfRow> {
        let mut out = Vec::new();
        for fz in [3000.0, 6000.0] {
            for camber in [0.0, 0.03] {
                for alpha in [-0.15, -0.02, 0.02, 0.15] {
                    out.push(MfRow {
                        fz,
                        kappa: 0.0,
                        alpha,
                        camber,
                        speed: 16.7,
                        pressure: None,
                        fx: f64::NAN,
                        fy: 0.0,
                        mz: f64::NAN,
                        mx: f64::NAN,
                        my: f64::NAN,
                    });
                }
            }
        }
        out
    }

    /// `PEY1` of the public MF 6.1 file's pure Fy stage (`PEY1..4`
    /// free) with `Ey` set by `pey1` (the rest 0: `Ey = PEY1·LEY`).
    fn clip_of(pey1: f64) -> Option<AtClip> {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/tir");
        let mut t = load_tir(&dir.join("MagicFormula61_Parameters.tir")).unwrap();
        for (k, v) in [
            ("PEY2", 0.0),
            ("PEY3", 0.0),
            ("PEY4", 0.0),
            ("PEY5", 0.0),
            ("LEY", 1.0),
        ] {
            t.coefficients.set(k, v);
        }
        let rows = rows();
        let names = vec!["PEY1", "PEY2", "PEY3", "PEY4"];
        let problem = StageProblem::new(
            t,
            Stage::PureFy,
            names,
            rows.iter().collect(),
            Derivatives::Exact,
        );
        at_clip(&problem, &[pey1, 0.0, 0.0, 0.0], 0)
    }

    #[test]
    fn a_curvature_at_its_clip_over_every_row_is_held_by_it() {
        // Ey = 1.4 at every row: clipped to 1 everywhere, Fy flat in PEY1.
        let clip = clip_of(1.4).expect("held by the clip");
        assert_eq!(clip.factor, CurvatureFactor::Ey);
        assert_eq!((clip.rows, clip.of), (16, 16));
        assert_eq!(clip.fz, [3000.0, 6000.0]);
        assert_eq!(clip.camber, [0.0, 0.03]);
        assert!(clip.said().contains("Ey ≤ 1"), "{}", clip.said());
        assert!(
            clip.said()
                .contains("Fz 3000 to 6000 N, camber 0.00° to 1.72°"),
            "{}",
            clip.said()
        );
        // Ey = −0.5: inside the clip, PEY1 moves Fy: determined, not held.
        assert_eq!(clip_of(-0.5), None);
    }

    #[test]
    fn the_curvature_coefficients_are_named_by_their_factor() {
        assert_eq!(CurvatureFactor::of("PEY1"), Some(CurvatureFactor::Ey));
        assert_eq!(CurvatureFactor::of("PEY5"), Some(CurvatureFactor::Ey));
        assert_eq!(CurvatureFactor::of("QEZ3"), Some(CurvatureFactor::Et));
        assert_eq!(CurvatureFactor::of("REX2"), Some(CurvatureFactor::ExAlpha));
        assert_eq!(CurvatureFactor::of("PKY1"), None);
        assert_eq!(CurvatureFactor::of("PE"), None);
    }
}
