"""The Python call's overhead over the Rust call: 1,000 simulations of a
10 s step steer (scenarios/sedan_step.toml run to 10 s), once as a loop of
`jobs::simulate::run` inside Rust, once as a Python loop of
`handling.simulate` (report parsed into a dict, the history copied into
numpy arrays). Best of three rounds each, interleaved.

    python python/examples/overhead.py [N]
"""

import pathlib
import sys
import tempfile
import time

import handling
from handling import _handling

ROOT = pathlib.Path(__file__).resolve().parents[2]


def scenario(tmp: pathlib.Path) -> pathlib.Path:
    text = (ROOT / "scenarios" / "sedan_step.toml").read_text()
    text = text.replace('"../tyres/', f'"{(ROOT / "tyres").as_posix()}/')
    text = text.replace("end = 6.0", "end = 10.0")
    assert "end = 10.0" in text
    p = tmp / "step_10s.toml"
    p.write_text(text)
    return p


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    with tempfile.TemporaryDirectory() as d:
        p = scenario(pathlib.Path(d))
        r = handling.simulate(p, pandas=False)
        rows = len(r.history["t"])
        rust, python = [], []
        for _ in range(3):
            rust.append(_handling._bench_simulate(str(p), n))
            t0 = time.perf_counter()
            for _ in range(n):
                handling.simulate(p, pandas=False)
            python.append(time.perf_counter() - t0)
    best_r, best_p = min(rust), min(python)
    print(f"{n} simulations of a 10 s step steer ({rows} rows, {r['integration'].split(':')[0]})")
    print(f"  Rust loop   (jobs::simulate::run)  {best_r:.3f} s  ({1e3 * best_r / n:.3f} ms each)")
    print(f"  Python loop (handling.simulate)    {best_p:.3f} s  ({1e3 * best_p / n:.3f} ms each)")
    print(f"  overhead {100 * (best_p - best_r) / best_r:.2f} %")


if __name__ == "__main__":
    main()
