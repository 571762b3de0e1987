//! The load at which a Magic Formula 6.1/6.2 file's vertical model
//! deflects the tyre by a given amount, standing (`Ω` = 0), free of force
//! (`Fx`, `Fy` = 0) and camber: its vertical force ([`super::vertical`],
//! MFeval's `calculateFz62`) at the loaded radius `R0 − ρ`, which reduces
//! to `(1 + PFZ1·dpi)·(Q_FZ1·ρz/R0 + Q_FZ2·(ρz/R0)²)·Fz0` with `ρz = RΩ −
//! R0 + ρ` (`RΩ = Q_RE0·R0` standing) (TNO
//! MF-Tyre 6.1/6.2; Besselink et al. 2010). `tyre-eval` takes it at the
//! deflection that puts the rim on the road as the most load a tyre
//! carries (`jobs/tyre_eval/bottoming.rs`). Units: N, m, Pa.

use super::vertical::{self, Radii, VerticalState};
use super::MagicFormula;

impl MagicFormula {
    /// The load (N) at which the vertical model puts the loaded radius
    /// `deflection` (m) below `UNLOADED_RADIUS`, standing, free of force
    /// and camber, at the
    /// pressure `pressure` as the vertical model takes it (after the limit
    /// checks; `None`: the file's); `None` without a vertical model or
    /// where the force there is not a positive load.
    pub fn static_load_at(&self, deflection: f64, pressure: Option<f64>) -> Option<f64> {
        if !self.has_vertical_model() {
            return None;
        }
        let c = &self.coefficients;
        let checked = self.checked(c.FNOMIN, 0.0, self.pressure(pressure));
        let free = vertical::radii(c, 0.0, 0.0, 0.0, 0.0).free;
        let state = VerticalState {
            gamma: 0.0,
            dpi: (checked.p - c.NOMPRES) / c.NOMPRES,
            radii: Radii {
                free,
                effective: free,
                omega: 0.0,
            },
            fx: 0.0,
            fy: 0.0,
        };
        let load = vertical::vertical_force(c, &state, c.UNLOADED_RADIUS - deflection);
        (load.is_finite() && load > 0.0).then_some(load)
    }
}
