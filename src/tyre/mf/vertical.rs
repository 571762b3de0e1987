//! The vertical side of a Magic Formula 6.1 / 6.2 tyre: the free-spinning
//! radius `RΩ`, the effective rolling radius `Re`, the vertical force from
//! the tyre's deflection and its inverse, the loaded radius `Rl` at a given
//! load (the `rl` output of `tyre-eval`).
//!
//! Source: Pacejka (2012) eqs. A3.1–A3.3 and the TNO MF-Tyre/MF-Swift 6.1
//! and 6.2 equation manuals (Besselink et al. 2010 for 6.1's pressure term),
//! as MFeval (M. Furlan) implements them (`calculateRe`,
//! `calculateRhoRl61`, `calculateFz62`):
//!
//! - `RΩ = R0·(Q_RE0 + Q_V1·(Ω·R0/V0)²)`, `Re = RΩ − (Fz0/Cz)·(DREFF·
//!   atan(BREFF·Fz/Fz0) + FREFF·Fz/Fz0)` with `Cz = VERTICAL_STIFFNESS·(1 +
//!   PFZ1·dpi)`, and the wheel speed `Ω = (1 + κ)·Vx/Re`, iterated from
//!   `Re = 0.965·R0` until it moves less than 1e-9 m.
//! - `Fz = (1 + Q_V2·(R0/V0)·|Ω| − (Q_FCX·Fx/Fz0)² − ((ρz/R0)^Q_FCY2·Q_FCY·
//!   (Fy − (Q_FYS1 + Q_FYS2·Rl/RΩ + Q_FYS3·(Rl/RΩ)²)·γ)/Fz0)²)·(1 +
//!   PFZ1·dpi)·(Q_FZ1·ρz/R0 + Q_FZ2·(ρz/R0)²)·Fz0`, with `Q_FZ1 =
//!   sqrt((Cz0·R0/Fz0)² − 4·Q_FZ2)` (`Cz0 = VERTICAL_STIFFNESS`), and (6.2)
//!   the deflection `ρz = max(ρzfr + ρzγ, 0)`: the free part `ρzfr =
//!   max(RΩ − Rl, 0)` and the camber part `ρzγ = (Q_CAM1·Rl + Q_CAM2·Rl²)²·
//!   γ²/((Q_CAM1·RΩ + Q_CAM2·RΩ²)²·γ²)·((1.075 − 0.5·ASPECT_RATIO)·WIDTH/8)·
//!   |tan γ| − Q_CAM3·ρzfr·|γ|` (0 at γ = 0). A 6.1 file has no camber and
//!   `Fy`-shift terms (`Q_CAM*`, `Q_FYS*`, `Q_FCY2` are 0): the same
//!   formula, and its inverse is MFeval's closed form for 6.1 (a quadratic
//!   in `ρz/R0`).
//! - `Rl` at a load: the root of `Fz(Rl) = Fz` below `RΩ`, where `Fz`
//!   falls as `Rl` rises, by bisection to 1e-13 m. (MFeval 6.2 searches
//!   it by `fminsearch` from 0.3 m, which on MFeval's 6.2 sample at a
//!   light load and camber can stop on a second root far above `RΩ`,
//!   where the camber part `ρzγ` grows with `Rl`: not a loaded radius.)
//!
//! Inputs as MFeval takes them: `Fx`, `Fy` the tyre's own forces at the
//! point in TNO's ISO-W frame (the camber is then in the same frame: a
//! mirrored right-side tyre gives the same `Fz` and `Rl`, all its terms
//! being even under the mirror), `γ` and the pressure after the limit
//! checks, the load, slip ratio and speed as given. Units: SI (m, N, rad).
//!
//! Past `FZMAX` with the limit checks on, MFeval takes the deflection at
//! the load held at `FZMAX` (6.1's `Fz_lowLimit`, 6.2's limited `Fz`) and
//! the free radius `RΩ` at the load given (`calculateRe` takes the
//! unlimited `Fz`): `Re` shrinks with the load, `Ω = Vx/Re` and `RΩ` grow,
//! and `Rl` rises with the load (0.30443 m at 10 kN, 0.30616 m at 400 kN on
//! the public `car205_60R19.tir` at 16.7 m/s; checked against MFeval's
//! June 2020 C++ build). Followed, for the file to stay comparable; the
//! caller says it (`jobs/tyre_eval/past_fzmax.rs`). No tyre deflects past
//! its rim: `rim_load.rs` gives the load at which this vertical force,
//! standing and free of force, reaches a deflection (the caller's bound:
//! the rim on the road, `jobs/tyre_eval/bottoming.rs`).

use super::MfCoefficients;

/// The vertical-force coefficients MF 6.2 has and 6.1 does not (MFeval's
/// `calculateRhoRl61` reads none of them).
pub const MF62_ONLY: [&str; 7] = [
    "Q_CAM1", "Q_CAM2", "Q_CAM3", "Q_FYS1", "Q_FYS2", "Q_FYS3", "Q_FCY2",
];

/// The rolling radii of a point: free-spinning `RΩ`, effective `Re`, and
/// the wheel's angular speed `Ω` (rad/s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Radii {
    /// Free-spinning radius `RΩ`, m.
    pub free: f64,
    /// Effective rolling radius `Re`, m.
    pub effective: f64,
    /// Wheel angular speed `Ω`, rad/s.
    pub omega: f64,
}

/// `RΩ`, `Re` and `Ω` at load `fz`, slip ratio `kappa`, forward speed
/// `speed` and relative pressure `dpi` (the fixed point of MFeval's
/// `calculateRe`).
pub fn radii(c: &MfCoefficients, fz: f64, kappa: f64, speed: f64, dpi: f64) -> Radii {
    let r0 = c.UNLOADED_RADIUS;
    let free = |omega: f64| r0 * (c.Q_RE0 + c.Q_V1 * (omega * r0 / c.LONGVL).powi(2));
    let cz = c.VERTICAL_STIFFNESS * (1.0 + c.PFZ1 * dpi);
    let n = fz / c.FNOMIN;
    let (mut re, mut re_old, mut omega) = (0.965 * r0, r0, 0.0);
    let mut r_free = free(0.0);
    // MFeval's loop (a contraction: |dRe/dRe_old| ≈ 2·Q_V1·(ΩR0/V0)² ≪ 1),
    // capped so that a degenerate file cannot hang it.
    for _ in 0..200 {
        if (re_old - re).abs() <= 1e-9 {
            break;
        }
        re_old = re;
        omega = (kappa * speed + speed) / re;
        r_free = free(omega);
        re = r_free - c.FNOMIN / cz * (c.DREFF * (c.BREFF * n).atan() + c.FREFF * n);
    }
    Radii {
        free: r_free,
        effective: re,
        omega,
    }
}

/// What the vertical force depends on besides the loaded radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VerticalState {
    /// Inclination angle (ISO-W, after the limit checks), rad.
    pub gamma: f64,
    /// `(p − NOMPRES)/NOMPRES`.
    pub dpi: f64,
    /// The radii at the point ([`radii`]).
    pub radii: Radii,
    /// Longitudinal force, N (ISO-W).
    pub fx: f64,
    /// Lateral force, N (ISO-W).
    pub fy: f64,
}

/// The vertical force (N) at loaded radius `rl` (m): MF 6.2's `Fz(Rl)`
/// (6.1's when the camber and `Fy`-shift terms are 0).
pub fn vertical_force(c: &MfCoefficients, s: &VerticalState, rl: f64) -> f64 {
    let (r0, fz0, g) = (c.UNLOADED_RADIUS, c.FNOMIN, s.gamma);
    let r_free = s.radii.free;
    let rho_free = (r_free - rl).max(0.0);
    let camber = {
        let at_rl = (c.Q_CAM1 * rl + c.Q_CAM2 * rl * rl) * g;
        let at_free = (c.Q_CAM1 * r_free + c.Q_CAM2 * r_free * r_free) * g;
        let v = at_rl * at_rl * ((1.075 - 0.5 * c.ASPECT_RATIO) * c.WIDTH / 8.0) * g.tan().abs()
            / (at_free * at_free)
            - c.Q_CAM3 * rho_free * g.abs();
        // 0/0 at γ = 0 (or without Q_CAM1, Q_CAM2): no camber part.
        if v.is_nan() {
            0.0
        } else {
            v
        }
    };
    let rho = (rho_free + camber).max(0.0);
    let q_fz1 = ((c.VERTICAL_STIFFNESS * r0 / fz0).powi(2) - 4.0 * c.Q_FZ2).sqrt();
    let x = rl / r_free;
    let fcx = c.Q_FCX * s.fx / fz0;
    let fcy = (rho / r0).powf(c.Q_FCY2)
        * (c.Q_FCY * (s.fy - (c.Q_FYS1 + c.Q_FYS2 * x + c.Q_FYS3 * x * x) * g) / fz0);
    let speed = 1.0 + c.Q_V2 * (r0 / c.LONGVL) * s.radii.omega.abs();
    (speed - fcx * fcx - fcy * fcy)
        * (1.0 + c.PFZ1 * s.dpi)
        * (q_fz1 * rho / r0 + c.Q_FZ2 * (rho / r0).powi(2))
        * fz0
}

/// A load the vertical model does not carry at any loaded radius above 0:
/// even a deflection of the whole free radius (the axle on the road) gives
/// less. MFeval's closed form returns a loaded radius of 0 or below there;
/// no tyre has one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NotCarried {
    /// The load asked for (after the limit checks), N.
    pub fz: f64,
    /// The most the model carries, at that deflection, N.
    pub most: f64,
    /// The free radius `RΩ` at the point, m.
    pub free: f64,
}

/// The loaded radius (m) at load `fz`: the root of [`vertical_force`] `=
/// fz` between `max(RΩ − R0, 0)` and `RΩ` (bisection to 1e-13 m); `RΩ` at
/// zero load; [`NotCarried`] where even the lower end does not carry `fz`
/// (a 100 kN load on an FSAE tyre with the limit checks off).
pub fn loaded_radius(c: &MfCoefficients, s: &VerticalState, fz: f64) -> Result<f64, NotCarried> {
    let (mut lo, mut hi) = ((s.radii.free - c.UNLOADED_RADIUS).max(0.0), s.radii.free);
    if fz <= 0.0 {
        return Ok(hi);
    }
    let most = vertical_force(c, s, lo);
    // A NaN force (a degenerate file) carries nothing either.
    if most <= fz || most.is_nan() {
        return Err(NotCarried {
            fz,
            most,
            free: s.radii.free,
        });
    }
    for _ in 0..200 {
        if hi - lo <= 1e-13 {
            break;
        }
        let mid = 0.5 * (lo + hi);
        if vertical_force(c, s, mid) > fz {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}
