//! The slip-dependent part of the Magic Formula at one point, from a
//! [`Prelude`] of its load, pressure and camber: pure and combined `Fx` and
//! `Fy`, `Mz`, `Mx` and `My` in TNO's ISO-W frame (what is modelled, the
//! sources and the choices are in the parent module's notes). SI and
//! radians; `α` here is TNO's.

use super::formulae::{cos_atan, sgn, LateralAtLoad, Prelude, EPS_V};
use super::{AlphaStar, MagicFormula, MfOutput, MfVersion};
use crate::tyre::kernels;
use std::f64::consts::PI;

impl MagicFormula {
    /// The slip-dependent part at one point from a prelude (ISO-W).
    ///
    /// Cost: the transcendental functions (about 35 `atan`, `sin`, `cos`
    /// here, 12 more in the prelude) were 70 % of an evaluation as C
    /// library calls, one at a time. They are now evaluated in array passes
    /// of [`kernels`] (see [`Self::slip`]). Inlined scalar Cephes
    /// `atan`/`sin`/`cos` had been tried before: 10 % fewer instructions but
    /// slower on the clock than glibc's — the gain is in the lanes, not in
    /// the polynomials.
    #[inline]
    pub(super) fn forces_iso(&self, l: &Prelude, kappa: f64, alpha: f64, speed: f64) -> MfOutput {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2, checked on the line above.
            return unsafe { self.forces_iso_avx2(l, kappa, alpha, speed) };
        }
        self.forces_iso_lanes(l, kappa, alpha, speed)
    }

    /// [`Self::forces_iso`] compiled with AVX2: four lanes per instruction
    /// instead of SSE2's two. No FMA (Rust never contracts `a·b + c`), so
    /// the result is the same to the bit.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn forces_iso_avx2(&self, l: &Prelude, kappa: f64, alpha: f64, speed: f64) -> MfOutput {
        self.forces_iso_lanes(l, kappa, alpha, speed)
    }

    /// The prelude and the slip part at one point (ISO-W): one evaluation.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn evaluate_iso(
        &self,
        fz: f64,
        gamma: f64,
        p: f64,
        mu_scale: f64,
        kappa: f64,
        alpha: f64,
        speed: f64,
    ) -> MfOutput {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU has AVX2, checked on the line above.
            return unsafe { self.evaluate_iso_avx2(fz, gamma, p, mu_scale, kappa, alpha, speed) };
        }
        let pre = self.prelude(fz, gamma, p, mu_scale, 1.0);
        self.forces_iso_lanes(&pre, kappa, alpha, speed)
    }

    /// [`Self::evaluate_iso`] compiled with AVX2 (as [`Self::forces_iso_avx2`]).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    #[allow(clippy::too_many_arguments)]
    fn evaluate_iso_avx2(
        &self,
        fz: f64,
        gamma: f64,
        p: f64,
        mu_scale: f64,
        kappa: f64,
        alpha: f64,
        speed: f64,
    ) -> MfOutput {
        let pre = self.prelude(fz, gamma, p, mu_scale, 1.0);
        self.forces_iso_lanes(&pre, kappa, alpha, speed)
    }

    #[inline(always)]
    fn forces_iso_lanes(&self, l: &Prelude, kappa: f64, alpha: f64, speed: f64) -> MfOutput {
        let c = &self.coefficients;
        let vx = speed;
        let my_reversal = Self::rolling_direction(kappa, vx, c.VXLOW);
        let (kappa, alpha) = self.checked_slip(kappa, alpha);
        let sgn_vx = sgn(vx);
        let low = if vx.abs() < c.VXLOW {
            vx.abs() / c.VXLOW
        } else {
            1.0
        };
        // tan α = sin α/cos α inside ±90°; beyond, sin α/|cos α| keeps the
        // slip's direction.
        let [sin_a, cos_a, ..] =
            kernels::sin_cos([alpha, alpha, 0.0, 0.0], [false, true, false, false]);
        let tan_a = if alpha.abs() < 0.5 * PI {
            sin_a / cos_a
        } else {
            sin_a / cos_a.abs().max(1e-12)
        };
        let astar = match self.options.alpha_star {
            AlphaStar::Tan => tan_a * sgn_vx,
            AlphaStar::Angle => alpha * sgn_vx,
        };
        let own;
        let l = if c.LMUV == 0.0 {
            l
        } else {
            // λ*_μ depends on the slip speed: the prelude is this point's
            // (rebuilt out of line, this path is rare).
            let vs = vx.abs() * (kappa * kappa + astar * astar).sqrt();
            let speed_factor = 1.0 / (1.0 + c.LMUV * vs / c.LONGVL);
            if speed_factor == 1.0 {
                l
            } else {
                own = self.prelude_out_of_line(l.fz, l.gamma, l.p, l.mu_scale, speed_factor);
                &own
            }
        };
        let point = SlipPoint {
            kappa,
            astar,
            tan_a,
            vx,
            sgn_vx,
            low,
            my_low: low * my_reversal,
        };
        self.slip(l, &point)
    }

    /// The rolling resistance's factor for the wheel's direction of
    /// rotation at slip ratio `kappa` (as given, before any limit check)
    /// and speed `vx` (MFeval's `calculateMy`): 1 while the wheel turns
    /// forward, −1 once it spins backward (`κ < −1 − VXLOW/|Vx|`, roughly),
    /// a quarter sine between, over the slip ratios within `VXLOW/|Vx|` of
    /// `κ = −1`; 0 at `Vx = 0`.
    #[inline(always)]
    pub(super) fn rolling_direction(kappa: f64, vx: f64, vxlow: f64) -> f64 {
        if vx == 0.0 {
            return 0.0;
        }
        let high = vxlow / vx.abs() - 1.0;
        let low = -1.0 - vxlow - high;
        if kappa > high {
            1.0
        } else if kappa >= low {
            (0.5 * PI * (kappa + 1.0) / (high + 1.0)).sin()
        } else {
            -1.0
        }
    }

    /// [`Self::prelude`] as a call (for [`super::MfAtLoad`] and the
    /// slip-speed friction path), not inlined into every caller.
    #[inline(never)]
    pub(super) fn prelude_out_of_line(
        &self,
        fz: f64,
        gamma: f64,
        p: f64,
        mu_scale: f64,
        speed_factor: f64,
    ) -> Prelude {
        self.prelude(fz, gamma, p, mu_scale, speed_factor)
    }

    /// The shifts and curvature of the pure lateral force at `α*` with the
    /// low-speed fade: `(αy, Ey, SHy, SVy)`.
    #[inline(always)]
    fn lateral_input(&self, f: &LateralAtLoad, astar: f64, low: f64) -> (f64, f64, f64, f64) {
        let (shy, svy) = if low == 1.0 {
            (f.shy, f.svy)
        } else if self.version == MfVersion::Mf52 {
            (f.shy, f.svy * low)
        } else {
            let svyg = f.svyg * low;
            (f.shy0 + (f.kyg_gs - svyg) / f.kya_g, f.svy * low)
        };
        let ay = astar + shy;
        let ey = self.clip_e(f.ey0 * (f.ey_a - f.ey_b * sgn(ay)));
        (ay, ey, shy, svy)
    }

    /// The slip part. Every Magic Formula curve `sin/cos(C·atan(B·x −
    /// E·(B·x − atan(B·x))))` of the point — pure `Fx0`, `Fy0` (and at zero
    /// camber), the numerators and denominators of `Gxα` and `Gyκ`, the
    /// trail — and the other angles are set up first and evaluated together
    /// in a few array passes of [`kernels`], one per stage of their
    /// dependency chain. Where the old scalar code skipped a call because
    /// its result was known (a weight of exactly 1 at zero slip of the other
    /// kind, `SVyκ = 0` at `κ = 0`, `E = 0`) the lanes give the same result
    /// exactly: equal inputs, equal bits.
    ///
    /// The stages are separate functions, all `#[inline(always)]`: one
    /// body in the hot loop, as before the split.
    #[inline(always)]
    fn slip(&self, l: &Prelude, s: &SlipPoint) -> MfOutput {
        let set = self.curve_inputs(l, s);
        let inner = self.inner_angles(l, s, &set);
        let outer = self.outer_angles(l, &inner);
        let forces = self.combined_forces(l, s, &set, &outer.curves, inner.a_rvy);
        let (mz, mx) = self.aligning_and_overturning(l, s, &forces, outer.y_t, inner.ar_eq);
        let my = self.rolling_resistance(l, s, forces.fx);
        MfOutput {
            fx: forces.fx,
            fy: forces.fy,
            mz,
            mx,
            my,
        }
    }

    /// Set-up: the shifted slips and curvatures of pure longitudinal, pure
    /// lateral at the point's camber and at zero camber (6.x `Mz`), the
    /// combined-slip weights' slopes, the trail's and residual torque's
    /// angles.
    #[inline(always)]
    fn curve_inputs(&self, l: &Prelude, s: &SlipPoint) -> CurveInputs {
        let c = &self.coefficients;
        let (kappa, astar, low) = (s.kappa, s.astar, s.low);
        let kx = kappa + l.shx;
        let ex = self.clip_e(l.ex_load * (1.0 - c.PEX4 * sgn(kx)) * c.LEX);
        let (ay, ey, shy, svy) = self.lateral_input(&l.lat, astar, low);
        let (ay0, ey0, _, svy0) = self.lateral_input(&l.flat, astar, low);
        let bxa = l.rbx * cos_atan(c.RBX2 * kappa) * c.LXAL;
        let byk = l.rby * cos_atan(c.RBY2 * (astar - c.RBY3)) * c.LYKA;
        let at = astar + l.sht;
        let ar = astar + shy + svy / l.lat.kya_g;
        CurveInputs {
            kx,
            ex,
            ay,
            ey,
            svy,
            ay0,
            ey0,
            svy0,
            bxa,
            byk,
            at,
            ar,
        }
    }

    /// Stages 1 and 2: sin and cos of the trail's and the residual torque's
    /// angles (their tangents), then the inner atan of every curve,
    /// atan(RVY6·κ), Et's atan and the equivalent angles.
    #[inline(always)]
    fn inner_angles(&self, l: &Prelude, s: &SlipPoint, set: &CurveInputs) -> InnerAngles {
        let c = &self.coefficients;
        let (kappa, astar) = (s.kappa, s.astar);
        let (at, ar) = (set.at, set.ar);
        let [s_at, c_at, s_ar, c_ar] =
            kernels::sin_cos([at, at, ar, ar], [false, true, false, true]);
        // TNO (A54/A55): the equivalent angles combine tangents,
        // atan(√(tan² a + k²))·sgn a = atan(√(sin² a + k²·cos² a)/|cos a|)·sgn a;
        // without longitudinal slip that is a itself inside ±90°.
        let k2 = l.kratio2 * kappa * kappa;
        let eq = |s: f64, co: f64| ((s * s + k2 * co * co).sqrt(), co.abs());
        let ((n_at, d_at), (n_ar, d_ar)) = (eq(s_at, c_at), eq(s_ar, c_ar));

        let bx = [
            l.bx * set.kx,
            l.lat.by * set.ay,
            l.flat.by * set.ay0,
            set.bxa * (astar + c.RHX1),
            set.bxa * c.RHX1,
            set.byk * (kappa + l.shyk),
            set.byk * l.shyk,
        ];
        let e = [set.ex, set.ey, set.ey0, l.exa, l.exa, l.eyk, l.eyk];
        let [i0, i1, i2, i3, i4, i5, i6, a_rvy, a_et, eq_t, eq_r, _] = kernels::atan_ratio(
            [
                bx[0],
                bx[1],
                bx[2],
                bx[3],
                bx[4],
                bx[5],
                bx[6],
                c.RVY6 * kappa,
                l.btct * at,
                n_at,
                n_ar,
                0.0,
            ],
            [1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, d_at, d_ar, 1.0],
        );
        let equivalent = |a: f64, q: f64| {
            if k2 == 0.0 && a.abs() < 0.5 * PI {
                a
            } else {
                q * sgn(a)
            }
        };
        InnerAngles {
            bx,
            e,
            inner: [i0, i1, i2, i3, i4, i5, i6],
            a_rvy,
            a_et,
            at_eq: equivalent(at, eq_t),
            ar_eq: equivalent(ar, eq_r),
        }
    }

    /// Stage 3: the outer atan of every curve, `B·x − E·(B·x − atan(B·x))`
    /// under it, and the trail's inner atan with its curvature `Et`.
    #[inline(always)]
    fn outer_angles(&self, l: &Prelude, a: &InnerAngles) -> OuterAngles {
        let (bx, e, inner) = (&a.bx, &a.e, &a.inner);
        let y: [f64; 7] = std::array::from_fn(|k| bx[k] - e[k] * (bx[k] - inner[k]));
        let bt_at = l.bt * a.at_eq;
        let [o0, o1, o2, o3, o4, o5, o6, i_t] =
            kernels::atan([y[0], y[1], y[2], y[3], y[4], y[5], y[6], bt_at]);
        let et = self.clip_e(l.et_load * (1.0 + l.et_gamma * a.a_et));
        OuterAngles {
            curves: [o0, o1, o2, o3, o4, o5, o6],
            y_t: bt_at - et * (bt_at - i_t),
        }
    }

    /// Stage 4: the pure-slip curves (sin of C·θ) and the combined-slip
    /// weights (cos of C·θ), the sine of `SVyκ`; from them `Fx`, `Fy` and
    /// the lateral force the trail multiplies.
    #[inline(always)]
    fn combined_forces(
        &self,
        l: &Prelude,
        s: &SlipPoint,
        set: &CurveInputs,
        o: &[f64; 7],
        a_rvy: f64,
    ) -> CombinedForces {
        let c = &self.coefficients;
        let (cxa, cyk) = (c.RCX1, c.RCY1);
        let [f_x, f_y, f_y0, gx_n, gx_d, gy_n, gy_d, s_rvy] = kernels::sin_cos(
            [
                l.cx * o[0],
                l.lat.cy * o[1],
                l.flat.cy * o[2],
                cxa * o[3],
                cxa * o[4],
                cyk * o[5],
                cyk * o[6],
                c.RVY5 * a_rvy,
            ],
            [false, false, false, true, true, true, true, false],
        );

        let fx0 = l.dx * f_x + l.svx * s.low;
        let fy0 = l.lat.dy * f_y + set.svy;
        let fy0_flat = l.flat.dy * f_y0 + set.svy0;
        // Combined slip: weighting functions (exactly 1 at zero slip of the
        // other kind: numerator and denominator are then the same number).
        let fx = gx_n / gx_d * fx0;
        // `svyk_per_mu`: SVyκ per unit μy (eqs. 4.E66/4.E67), so that the
        // 5.2 aligning moment can take it at the zero-camber μy as MFeval
        // does.
        let svyk_per_mu = l.svyk_load * cos_atan(c.RVY4 * s.astar) * s_rvy * c.LVYKA * s.low;
        let gyk = gy_n / gy_d;
        let fy = gyk * fy0 + l.lat.muy * svyk_per_mu;
        // The lateral force the trail multiplies: TNO 6.1's `Fy'` (eq.
        // 4.E74: the combined force at zero camber), and MFeval's 5.2 form
        // `Fy − SVyκ` with SVyκ at the zero-camber μy.
        let fy_trail = if self.version == MfVersion::Mf52 {
            fy - l.mu0 * svyk_per_mu
        } else {
            gyk * fy0_flat
        };
        CombinedForces { fx, fy, fy_trail }
    }

    /// Stages 5 and 6 and the two moments they feed: the trail's outer
    /// atan and cosine beside the overturning moment's atan and sine (they
    /// need `Fy`), and `cos α*`; `(Mz, Mx)`.
    #[inline(always)]
    fn aligning_and_overturning(
        &self,
        l: &Prelude,
        s: &SlipPoint,
        f: &CombinedForces,
        y_t: f64,
        ar_eq: f64,
    ) -> (f64, f64) {
        let c = &self.coefficients;
        let (vx, sgn_vx, fx, fy) = (s.vx, s.sgn_vx, f.fx, f.fy);
        // Aligning moment. cos'α = Vcx/(Vc + εV) (Pacejka 2012 eq. 4.E6)
        // with Vsy = tan α·|Vx| in either α* mode (MFeval); TNO scales the
        // trail by λ_Fz0 as well.
        let vsy = vx.abs() * s.tan_a;
        let cos_a = vx / ((vx * vx + vsy * vsy).sqrt() + EPS_V);
        let fz0 = c.FNOMIN;
        let [o_t, a_mx, ..] = kernels::atan([y_t, c.QSX9 * fy / fz0, 0.0, 0.0]);
        let [cos_t, sin_mx, cos_astar, _] = kernels::sin_cos(
            [c.QCZ1 * o_t, c.QSX7 * l.gamma + c.QSX8 * a_mx, s.astar, 0.0],
            [true, false, true, false],
        );
        let t = l.dt * sgn_vx * cos_t * cos_a * c.LFZO;
        // The residual torque ends in cos α* (MFeval); eq. 4.E75: no cos'α
        // again in Mzr.
        let mzr = l.dr * sgn_vx * cos_astar * cos_atan(l.br * ar_eq);
        // TNO (A56): Fy/Fz0 with the unscaled Fz0 and γ itself.
        let r0 = c.UNLOADED_RADIUS;
        let arm = r0 * (c.SSZ1 + c.SSZ2 * (fy / fz0) + l.s_gamma) * c.LS;
        let mz = -t * f.fy_trail + mzr + arm * fx;

        // Overturning moment (TNO 6.1; 5.2 files leave the 6.1 terms at 0).
        let mixed = if l.mx_mixed == 0.0 {
            0.0
        } else {
            l.mx_mixed * sin_mx
        };
        let mx = l.mx_scale * (l.mx_const + c.QSX3 * fy / fz0 + mixed + l.mx_load_camber)
            + (fy * l.mx_fy + l.mx_gamma);
        (mz, mx)
    }

    /// Rolling-resistance moment `My` (TNO 6.1 form; 5.2 without the
    /// powers) at longitudinal force `fx`.
    #[inline(always)]
    fn rolling_resistance(&self, l: &Prelude, s: &SlipPoint, fx: f64) -> f64 {
        let c = &self.coefficients;
        let fz0 = c.FNOMIN;
        let vr = s.vx / c.LONGVL;
        let vr2 = vr * vr;
        let poly =
            c.QSY1 + c.QSY2 * fx / fz0 + c.QSY3 * vr.abs() + c.QSY4 * (vr2 * vr2) + l.my_gamma;
        l.my_scale * poly * l.my_powers * s.sgn_vx * s.my_low
    }
}

/// One point's slip as the slip part takes it: `κ` and `α*` after the limit
/// checks, `tan α`, the speed `Vx` and its sign, the low-speed fade of the
/// vertical shifts and that of `My` (with the rolling direction).
struct SlipPoint {
    kappa: f64,
    astar: f64,
    tan_a: f64,
    vx: f64,
    sgn_vx: f64,
    low: f64,
    my_low: f64,
}

/// The curves' shifted slips and curvatures and the moments' angles,
/// before any transcendental function (see [`MagicFormula::curve_inputs`]).
struct CurveInputs {
    kx: f64,
    ex: f64,
    ay: f64,
    ey: f64,
    svy: f64,
    ay0: f64,
    ey0: f64,
    svy0: f64,
    bxa: f64,
    byk: f64,
    at: f64,
    ar: f64,
}

/// The seven curves' `B·x`, `E` and `atan(B·x)` (pure `Fx0`, `Fy0`, `Fy0`
/// at zero camber, `Gxα`'s and `Gyκ`'s numerators and denominators), with
/// `atan(RVY6·κ)`, Et's atan and the equivalent angles of trail and
/// residual torque.
struct InnerAngles {
    bx: [f64; 7],
    e: [f64; 7],
    inner: [f64; 7],
    a_rvy: f64,
    a_et: f64,
    at_eq: f64,
    ar_eq: f64,
}

/// The seven curves' outer atans and the trail's `Bt·x − Et·(Bt·x −
/// atan(Bt·x))`.
struct OuterAngles {
    curves: [f64; 7],
    y_t: f64,
}

/// The combined-slip forces and the lateral force the trail multiplies.
struct CombinedForces {
    fx: f64,
    fy: f64,
    fy_trail: f64,
}
