#!/usr/bin/env python3
"""The step steer's solver alone at rtol 1e-10, the crate against SciPy in
the same minutes: rounds of the crate's release `peer_jobs` binary (its
Dormand-Prince 5(4) and DOP853 rows) alternated with SciPy's RK45
(`scipy_peer.step_scipy`, median of 3), each round's times, ratios, load
average, right-hand sides and yaw-rate / sideslip errors against SciPy's
DOP853 reference at rtol 1e-12 (over the steady values, 10 ms grid).

On a loaded machine SciPy slows more than the crate: read the crate's two
pairs against each other, and quote SciPy's ratio only from a quiet run.

Usage: cargo build --release --example peer_jobs &&
       python3 peer/step_steer_rounds.py [rounds]   (needs numpy and scipy)
"""
import json
import os
import subprocess
import sys

import numpy as np

import scipy_peer as P

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main():
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    ts = np.round(np.arange(0.0, 10.0 + 1e-9, 0.01), 10)
    ref = P.step_reference(ts)
    r_ss, b_ss = abs(ref[-1, 2]), abs(ref[-1, 1])
    tight = P.step_scipy(ts, 1e-10, 1e-13)
    print(f"SciPy RK45 rtol 1e-10: {tight.nfev} evaluations, error r "
          f"{np.max(np.abs(tight.y[1] - ref[:, 2])) / r_ss:.1e}, beta "
          f"{np.max(np.abs(tight.y[0] - ref[:, 1])) / b_ss:.1e} of steady")
    binary = os.path.join(ROOT, "target/release/examples/peer_jobs")
    for _ in range(rounds):
        load = os.getloadavg()[0]
        crate = json.loads(subprocess.run([binary, "20"], capture_output=True, text=True,
                                          check=True).stdout)
        rows = {}
        for job in crate["step_steer_solver"]:
            if job["rtol"] != 1e-10:
                continue
            st = np.loadtxt(os.path.join(ROOT, job["file"]), delimiter=",", skiprows=1)
            rows[job["method"]] = (job["seconds"] * 1e3, job["evaluations"],
                                   np.max(np.abs(st[:, 1] - ref[:, 2])) / r_ss,
                                   np.max(np.abs(st[:, 2] - ref[:, 1])) / b_ss)
        t = P.median_seconds(3, lambda: P.step_scipy(ts, 1e-10, 1e-13)) * 1e3
        words = [f"load {load:.1f}", f"SciPy {t:.1f} ms"]
        for name, (ms, ev, er, eb) in rows.items():
            words.append(f"{name} {ms:.3f} ms ({t / ms:.0f}x, {ev} evaluations, "
                         f"error r {er:.1e}, beta {eb:.1e})")
        print(" | ".join(words), flush=True)


if __name__ == "__main__":
    sys.exit(main())
