"""A stiffness map and a tyre map on a Dask LocalCluster (2 worker
processes) through the package, equal to the single-process result."""

import numpy as np
import pytest

import handling
from conftest import coarse_study

distributed = pytest.importorskip("distributed")


def _evaluate(study, pairs):
    return study.evaluate(front_n_per_rad=[p[0] for p in pairs], rear_n_per_rad=[p[1] for p in pairs])


def _stiffness(tyre, fz):
    return tyre.cornering_stiffness(fz)


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    ) as cluster, distributed.Client(cluster) as c:
        yield c


def test_stiffness_map_on_dask_equals_single_process(tmp_path, client):
    p = coarse_study(tmp_path)
    study = handling.Study.load(p)
    grid = study.grid()
    chunks = [grid[i::4] for i in range(4)]
    futures = client.map(_evaluate, [study] * len(chunks), chunks, pure=False)
    parts = client.gather(futures)
    on_dask = {(s.k_front, s.k_rear): s for part in parts for s in part}
    local = handling.study(p).samples
    assert len(on_dask) == len(local) == 12
    for s in local:
        assert on_dask[(s.k_front, s.k_rear)] == s


def test_tyre_map_on_dask_equals_single_process(root, client):
    tyre = handling.Tyre.load(root / "tests" / "fixtures" / "tir" / "MagicFormula61_Parameters.tir")
    loads = list(np.linspace(1000.0, 8000.0, 8))
    on_dask = client.gather(client.map(_stiffness, [tyre] * len(loads), loads))
    assert on_dask == [tyre.cornering_stiffness(fz) for fz in loads]
    a = np.radians(np.linspace(-10, 10, 21))
    fut = client.submit(lambda t: t.forces(4000.0, 0.0, a)["fy"], tyre)
    assert np.array_equal(fut.result(), tyre.forces(4000.0, 0.0, a)["fy"])


def batch_of_campaigns(folder):
    """Three synthetic campaigns (the proving ground: one with a sensor
    bias, one with a tyre lag, one with neither), each diagnosed on two
    candidate effects only, so a diagnosis takes about 2 s."""
    paths = []
    for name, effects, seed in [("bias", ["sensor_bias"], 1), ("lag", ["relaxation_length"], 2), ("none", [], 3)]:
        c = folder / name
        handling.synth(c, effects, seed=seed)
        with open(c / "vehicle.toml", "a") as f:
            # synth's vehicle.toml ends in its [diagnose] table.
            f.write('effects = ["sensor_bias", "relaxation_length"]\n')
        paths.append(c)
    return paths


def test_a_batch_of_campaigns_on_dask_equals_single_process(tmp_path, client):
    paths = batch_of_campaigns(tmp_path)
    on_dask = client.gather(client.map(handling.diagnose, paths))
    local = [handling.diagnose(p) for p in paths]
    assert on_dask == local
    assert [d.verdict.effects for d in local] == [["sensor_bias"], ["relaxation_length"], []]
