#!/usr/bin/env python3
"""An independent linear replay of the Putnam racing log (no code shared with the crate).

What `campaigns/putnam.toml`'s base model is checked against: a linear 2-DOF
bicycle model (ISO 8855: x forward, y left, yaw rate positive to the left) with
two free axle cornering coefficients, replayed over the log's 20 s pieces, each
started from the measured state, and fitted by least squares on yaw rate and
sideslip scaled by the uncertainties each channel is trusted to.

    m (dv/dt + u r) = Fyf + Fyr,    Iz dr/dt = a Fyf - b Fyr
    Fyf = kf (m g b / L) (delta - (v + a r)/u),   Fyr = kr (m g a / L) (-(v - b r)/u)

kf, kr: cornering stiffness per unit static axle load (1/rad), as the crate
reports its axles. Speed u and steer delta are the log's, linear between
samples; v starts at u tan(beta), r at the logged yaw rate. Integration: the
trapezoidal rule (A-stable), `--sub` steps per 40 ms sample; a check with
scipy's LSODA at rtol 1e-8 gave the same fit to 0.01 1/rad. Units: SI, rad.

Vehicle (the campaign's, from the source): m 790 kg, Iz 1000 kg m^2,
a 1.248 m, b 1.7328 m.

Usage: python3 peer/putnam_replay.py [--sr 0.003] [--sb 0.005] [--min-speed 0]
       [--segment 20] [--delay 0] [--lag 0] [--no-beta] [--at-rest] [--log PATH]   (needs numpy and scipy)
"""
import argparse
import os

import numpy as np
from scipy.optimize import least_squares

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LOG = os.path.join(ROOT, "..", "shared", "data", "run_iac_putnam", "putnam_run4_2.csv")
M, IZ, A, B, G = 790.0, 1000.0, 1.248, 1.7328, 9.80665
L = A + B


def arguments():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--sr", type=float, default=0.003, help="yaw rate trusted to, rad/s")
    p.add_argument("--sb", type=float, default=0.005, help="sideslip trusted to, rad")
    p.add_argument("--segment", type=float, default=20.0, help="piece length, s")
    p.add_argument("--min-speed", type=float, default=0.0, help="slower samples not scored, m/s")
    p.add_argument("--delay", type=float, default=0.0, help="steer dead time, s")
    p.add_argument("--lag", type=float, default=0.0, help="steer first-order lag, s")
    p.add_argument("--no-beta", action="store_true", help="fit the yaw rate alone")
    p.add_argument("--at-rest", action="store_true", help="start each piece at v = r = 0")
    p.add_argument("--sub", type=int, default=4, help="integration steps per sample")
    p.add_argument("--log", default=LOG)
    return p.parse_args()


def steer_path(t, steer, delay, lag):
    """The logged steer delayed by `delay` and lagged by a first-order `lag` (s)."""
    if delay > 0:
        steer = np.interp(t - delay, t, steer, left=steer[0])
    if lag > 0:
        out = np.empty_like(steer)
        out[0] = steer[0]
        for i in range(1, len(steer)):
            w = (t[i] - t[i - 1]) / (lag + t[i] - t[i - 1])
            out[i] = out[i - 1] + w * (steer[i] - out[i - 1])
        steer = out
    return steer


def pieces(t, segment):
    """Index ranges of the pieces; a tail shorter than 2 s joins the last."""
    edges = [0]
    while True:
        j = int(np.searchsorted(t, t[edges[-1]] + segment - 1e-9))
        if j >= len(t) or t[-1] - t[j] < 2.0:
            edges.append(len(t))
            return list(zip(edges[:-1], edges[1:]))
        edges.append(j)


def padded(x, ranges, width):
    out = np.empty((len(ranges), width))
    for i, (s, e) in enumerate(ranges):
        out[i, : e - s] = x[s:e]
        out[i, e - s :] = x[e - 1]
    return out


def replayer(log, args):
    """The residual function of (ln kf, ln kr): every piece replayed at once."""
    t, u, r_m, b_m = log["t"], log["speed"], log["yaw_rate"], log["beta"]
    d = steer_path(t, log["steer"], args.delay, args.lag)
    ranges = pieces(t, args.segment)
    width = max(e - s for s, e in ranges)
    keep = np.zeros((len(ranges), width), bool)
    for i, (s, e) in enumerate(ranges):
        keep[i, : e - s] = True
    U, D, R, BETA, T = (padded(x, ranges, width) for x in (u, d, r_m, b_m, t))
    keep &= U >= args.min_speed
    H = np.diff(T, axis=1)
    H[H <= 0] = 1.0  # padding: any step, never scored

    def residuals(z):
        cf = np.exp(z[0]) * M * G * B / L
        cr = np.exp(z[1]) * M * G * A / L

        def matrix(uu):
            return (-(cf + cr) / (M * uu), -(A * cf - B * cr) / (M * uu) - uu,
                    -(A * cf - B * cr) / (IZ * uu), -(A * A * cf + B * B * cr) / (IZ * uu),
                    cf / M, A * cf / IZ)

        v, r = U[:, 0] * np.tan(BETA[:, 0]), R[:, 0].copy()
        if args.at_rest:
            v, r = np.zeros_like(v), np.zeros_like(r)
        V, Y = np.empty_like(U), np.empty_like(U)
        V[:, 0], Y[:, 0] = v, r
        n = args.sub
        for k in range(width - 1):
            h = H[:, k] / n
            for q in range(n):
                w0, w1 = q / n, (q + 1) / n
                u0, u1 = (U[:, k] + w * (U[:, k + 1] - U[:, k]) for w in (w0, w1))
                d0, d1 = (D[:, k] + w * (D[:, k + 1] - D[:, k]) for w in (w0, w1))
                a11, a12, a21, a22, b1, b2 = matrix(u0)
                c11, c12, c21, c22, e1, e2 = matrix(u1)
                f1 = v + 0.5 * h * (a11 * v + a12 * r + b1 * d0 + e1 * d1)
                f2 = r + 0.5 * h * (a21 * v + a22 * r + b2 * d0 + e2 * d1)
                m11, m12 = 1 - 0.5 * h * c11, -0.5 * h * c12
                m21, m22 = -0.5 * h * c21, 1 - 0.5 * h * c22
                det = m11 * m22 - m12 * m21
                v, r = (m22 * f1 - m12 * f2) / det, (m11 * f2 - m21 * f1) / det
            V[:, k + 1], Y[:, k + 1] = v, r
        out = [((Y - R) / args.sr)[keep]]
        if not args.no_beta:
            out.append(((np.arctan(V / U) - BETA) / args.sb)[keep])
        return np.concatenate(out)

    return residuals, len(ranges)


def main():
    args = arguments()
    log = np.genfromtxt(args.log, delimiter=",", names=True)
    residuals, n = replayer(log, args)
    best = None
    for start in ([15.0, 25.0], [30.0, 60.0], [8.0, 10.0]):
        fit = least_squares(residuals, np.log(start), diff_step=1e-4)
        if best is None or fit.cost < best.cost:
            best = fit
    kf, kr = np.exp(best.x)
    rms = np.sqrt(np.mean(best.fun ** 2))
    print(f"{n} pieces of {args.segment:g} s; yaw rate trusted to {args.sr:g} rad/s, "
          f"sideslip {'not fitted' if args.no_beta else f'{args.sb:g} rad'}; "
          f"steer delay {args.delay:g} s, lag {args.lag:g} s; scored from {args.min_speed:g} m/s")
    print(f"front {kf:.2f} 1/rad, rear {kr:.2f} 1/rad (rear/front {kr / kf:.2f}); "
          f"RMS scaled residual {rms:.3f}")


if __name__ == "__main__":
    main()
