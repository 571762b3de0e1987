"""A cornering-stiffness map (Wang & Liang) on a Dask cluster.

Each task simulates a slice of the (front, rear) stiffness grid of a study
file through the package; the pickled `handling.Study` travels to the
workers (as its file path: the workers must see the files). The result is
checked against the single-process map, value for value.

    python python/examples/dask_stiffness_map.py [study.toml] [tasks]

Default: scenarios/sedan_study.toml (26 x 26 combinations) in 16 tasks on a
LocalCluster of 2 worker processes; point `Client` at a real scheduler
(`Client("tcp://scheduler:8786")`) to use a cluster.
"""

import pathlib
import sys
import time

from distributed import Client, LocalCluster

import handling

ROOT = pathlib.Path(__file__).resolve().parents[2]


def evaluate(study, pairs):
    return study.evaluate(front_n_per_rad=[p[0] for p in pairs], rear_n_per_rad=[p[1] for p in pairs])


def main() -> None:
    path = sys.argv[1] if len(sys.argv) > 1 else ROOT / "scenarios" / "sedan_study.toml"
    tasks = int(sys.argv[2]) if len(sys.argv) > 2 else 16
    study = handling.Study.load(path)
    grid = study.grid()
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster, Client(
        cluster
    ) as client:
        t0 = time.perf_counter()
        parts = client.gather(client.map(evaluate, [study] * tasks, [grid[i::tasks] for i in range(tasks)]))
        t_dask = time.perf_counter() - t0
    on_dask = {(s.k_front, s.k_rear): s for part in parts for s in part}
    t0 = time.perf_counter()
    local = study.evaluate(front_n_per_rad=[g[0] for g in grid], rear_n_per_rad=[g[1] for g in grid])
    t_local = time.perf_counter() - t0
    assert all(on_dask[(s.k_front, s.k_rear)] == s for s in local) and len(on_dask) == len(local)
    er = [s.metrics.er for s in local if s.metrics]
    print(f"{len(grid)} combinations: Dask {t_dask:.2f} s, one process {t_local:.2f} s; identical")
    print(f"Er from {min(er):.4f} to {max(er):.4f} s")


if __name__ == "__main__":
    main()
