"""A batch of campaigns diagnosed on a Dask cluster.

Each task diagnoses one campaign folder (`handling.diagnose`, the sim-to-real
gap and the effects that explain it); the result is checked against the
single-process diagnoses, report for report. The workers must see the
campaign folders (a shared file system on a real cluster).

    python python/examples/dask_diagnose_batch.py [batch_folder]

With a folder of campaigns (folders or `.toml` files), diagnoses those
(each with its own `[diagnose]` settings); a campaign that cannot be read
or diagnosed is listed as FAILED with its error and the others go on, as
`handling diagnose <folder> --batch` lists it in its fleet table. Without one, writes six synthetic campaigns first
(`handling.synth`: the proving ground, two with a sensor bias, two with a
tyre lag, two with neither), each asked about those two candidate effects,
into a temporary folder; on a LocalCluster of 2 worker processes. Point
`Client` at a real scheduler (`Client("tcp://scheduler:8786")`) to use a
cluster. The CLI's equivalent is `handling diagnose <folder> --batch`,
sharded with `--shard K/N` and `handling merge`.
"""

import pathlib
import sys
import tempfile
import time

from distributed import Client, LocalCluster

import handling

EFFECTS = [["sensor_bias"], ["relaxation_length"], []]


def synthetic_batch(folder: pathlib.Path) -> None:
    for i in range(6):
        effects = EFFECTS[i % 3]
        c = folder / f"c{i}_{'+'.join(effects) or 'none'}"
        handling.synth(c, effects, seed=i + 1)
        with open(c / "vehicle.toml", "a") as f:
            # synth's vehicle.toml ends in its [diagnose] table.
            f.write('effects = ["sensor_bias", "relaxation_length"]\n')


def diagnosed(campaign: pathlib.Path):
    """The diagnosis of one campaign and None, or None and the error that
    stopped it: one broken campaign must not end the batch."""
    try:
        return handling.diagnose(campaign), None
    except handling.HandlingError as e:
        return None, str(e)


def main() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        folder = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(tmp)
        if len(sys.argv) <= 1:
            synthetic_batch(folder)
        campaigns = sorted(p for p in folder.iterdir() if p.is_dir() or p.suffix == ".toml")
        with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster, Client(
            cluster
        ) as client:
            t0 = time.perf_counter()
            on_dask = client.gather(client.map(diagnosed, campaigns))
            t_dask = time.perf_counter() - t0
        t0 = time.perf_counter()
        local = [diagnosed(c) for c in campaigns]
        t_local = time.perf_counter() - t0
        assert on_dask == local
        for c, (d, error) in zip(campaigns, local):
            print(f"{c.name}: FAILED: {error}" if d is None else f"{c.name}: {d.verdict.statement}")
        failed = sum(d is None for d, _ in local)
        said = f", {failed} failed" if failed else ""
        print(f"{len(campaigns)} campaigns{said}: Dask {t_dask:.2f} s, one process {t_local:.2f} s; identical")


if __name__ == "__main__":
    main()
