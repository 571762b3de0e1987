"""The package's own surface: scenario files read as the CLI reads them,
studies that travel to any working directory, stiffness values whose unit
is named, and reports as typed objects."""

import dataclasses
import importlib.metadata
import json
import pickle

import numpy as np
import pytest

import handling
from conftest import coarse_study
from test_scenario import same_run


def test_scenario_load_runs_as_the_file(root, tmp_path, monkeypatch):
    path = root / "scenarios" / "sedan_step.toml"
    # Another working directory: the tyre files are read beside the
    # scenario file, as the CLI reads them.
    monkeypatch.chdir(tmp_path)
    sc = handling.Scenario.load(path)
    assert sc.name == "sedan_step"
    assert sc.tyres == (
        handling.Tyre.load(root / "tyres" / "gim_sedan_front.toml"),
        handling.Tyre.load(root / "tyres" / "gim_sedan_rear.toml"),
    )
    same_run(handling.simulate(path, pandas=False), handling.simulate(sc, pandas=False))
    again = pickle.loads(pickle.dumps(sc))
    assert again == sc
    # Written back, the CLI's reader runs it to the same result.
    same_run(handling.simulate(sc.write(tmp_path / "w"), pandas=False), handling.simulate(sc, pandas=False))


def test_scenario_load_names_its_file_when_the_file_does_not(root, tmp_path):
    text = (root / "scenarios" / "sedan_step.toml").read_text().replace('name = "sedan_step"\n', "")
    p = tmp_path / "unnamed_step.toml"
    p.write_text(text.replace('"../tyres/', f'"{(root / "tyres").as_posix()}/'))
    assert handling.Scenario.load(p).name == "unnamed_step"


def test_scenario_load_errors_are_the_readers(root, tmp_path):
    text = (root / "scenarios" / "sedan_step.toml").read_text()
    bad = text.replace("mass = 1530.0", "mass = -1530.0").replace('"../tyres/', f'"{root}/tyres/')
    p = tmp_path / "bad.toml"
    p.write_text(bad)
    with pytest.raises(handling.InputError) as e:
        handling.Scenario.load(p)
    assert (e.value.path, e.value.line) == (str(p), bad.splitlines().index("mass = -1530.0") + 1)
    with pytest.raises(handling.InputError) as e:
        handling.Scenario.load(tmp_path / "none.toml")
    assert e.value.path == str(tmp_path / "none.toml")


def test_scenario_given_a_path_points_to_load(root):
    for given in (str(root / "scenarios" / "sedan_step.toml"), root / "scenarios" / "sedan_step.toml"):
        with pytest.raises(TypeError, match=r"Scenario\.load\(path\)"):
            handling.Scenario(given)


def test_a_pickled_study_evaluates_in_another_working_directory(tmp_path, monkeypatch):
    p = coarse_study(tmp_path)
    monkeypatch.chdir(tmp_path)
    study = handling.Study.load(p.name)
    assert study.path == str(p)
    blob = pickle.dumps(study)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    again = pickle.loads(blob)
    assert again.path == str(p)
    pairs = dict(front_n_per_deg=[500.0], rear_n_per_deg=[500.0])
    assert again.evaluate(**pairs) == study.evaluate(**pairs)


def test_study_stiffness_in_n_per_deg_gives_the_cli_numbers(root, tmp_path):
    p = coarse_study(tmp_path)
    study = handling.Study.load(p)
    # sedan_step's Gim tyres are 500 / 540 N/deg: the study's vehicle and
    # step steer with those stiffnesses are that scenario.
    step = handling.simulate(root / "scenarios" / "sedan_step.toml", pandas=False).metrics
    (s,) = study.evaluate(front_n_per_deg=500.0, rear_n_per_deg=540.0)
    assert s.metrics.settled and step.settled
    assert s.metrics.er == pytest.approx(step.er, rel=1e-3)
    assert s.metrics.yaw_rate_gain == pytest.approx(step.yaw_rate_gain, rel=1e-3)
    assert s.k_front_n_per_deg == pytest.approx(500.0) and s.k_rear_n_per_deg == pytest.approx(540.0)
    # The same pair in N/rad is the same sample; a grid point of the CLI's
    # study (500 / 500 N/deg, converted by the study file's reader) is the
    # same sample bit for bit.
    k = 180.0 / np.pi
    assert study.evaluate(front_n_per_rad=500.0 * k, rear_n_per_rad=540.0 * k) == [s]
    cli = {(x.k_front, x.k_rear): x for x in handling.study(p).samples}
    (g,) = study.evaluate(front_n_per_deg=500.0, rear_n_per_deg=500.0)
    assert cli[(g.k_front, g.k_rear)] == g


def test_study_evaluate_refuses_an_unnamed_unit(tmp_path):
    study = handling.Study.load(coarse_study(tmp_path))
    with pytest.raises(TypeError, match="front_n_per_deg"):
        study.evaluate(500.0, 540.0)
    with pytest.raises(TypeError, match="front_n_per_deg and rear_n_per_deg"):
        study.evaluate(front_n_per_deg=500.0, rear_n_per_rad=30000.0)


def test_reports_are_typed_frozen_and_keep_their_json(root, tmp_path):
    r = handling.simulate(root / "scenarios" / "sedan_step.toml", out=tmp_path / "s", pandas=False)
    assert isinstance(r, handling.Simulation) and isinstance(r.metrics, handling.StepMetrics)
    assert r.scenario == "sedan_step" and r.tyres == ("gim", "gim")
    written = json.loads((tmp_path / "s" / "metrics.json").read_text())
    assert {k: written[k] for k in r.metrics.to_dict()} == r.metrics.to_dict()
    assert r.metrics.er == written["er"] and r.metrics.settled is True
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.metrics.er = 0.0  # type: ignore[misc]
    assert pickle.loads(pickle.dumps(r.metrics)) == r.metrics
    assert r.to_dict()["metrics"] == r.metrics.to_dict() and "history" in r.to_dict()

    e = handling.equilibria(root / "scenarios" / "equilibria_steer.toml", out=tmp_path / "e")
    assert isinstance(e.summary, handling.EquilibriaSummary)
    assert e.summary.to_dict() == json.loads((tmp_path / "e" / "summary.json").read_text())
    assert (e.summary.conditions, e.summary.agreeing) == (11, 11)


def test_diagnosis_is_typed_and_equals_its_json(tmp_path):
    c = tmp_path / "bias"
    handling.synth(c, ["sensor_bias"], seed=1)
    with open(c / "vehicle.toml", "a") as f:
        f.write('effects = ["sensor_bias", "relaxation_length"]\n')
    d = handling.diagnose(c, out=tmp_path / "d")
    assert isinstance(d, handling.Diagnosis) and isinstance(d.verdict, handling.Verdict)
    assert d.verdict.effects == ["sensor_bias"]
    assert d.derivatives == "differences"
    assert all(isinstance(x, handling.RankedEffect) for x in d.ranking)
    written = json.loads((tmp_path / "d" / "diagnosis.json").read_text())
    assert d.to_dict() == written
    assert d.verdict.statement == written["verdict"]["statement"]
    # The timing is reported and left out of equality (the clock's).
    assert d.timing["wall_seconds"] > 0 and d.timing["threads"] >= 1
    later = dict(written, timing=dict(written["timing"], wall_seconds=1e9))
    assert handling.Diagnosis.from_dict(later) == d
    other = dict(written, seed=written["seed"] + 1)
    assert handling.Diagnosis.from_dict(other) != d
    # The verdict is typed: its case, and the figures of that case.
    assert d.verdict.kind is handling.VerdictKind.EXPLAINED
    assert written["verdict"]["kind"] == "explained"
    assert d.verdict.heldout_error == written["gap"]["heldout_error"]
    assert d.verdict.noise_level == written["gap"]["noise_level"]
    best = next(x for x in d.ranking if x.effects == ["sensor_bias"])
    assert d.verdict.reduction_percent == best.reduction_percent
    assert d.verdict.heldout_error_after == best.heldout_error_after
    assert d.verdict.partial is (best.reduction_percent < 50.0)
    remains = any(w["kind"] == "gap_remains" for w in d.verdict.warning_details)
    assert d.verdict.extent == (
        "part" if d.verdict.partial else "most" if remains else "all"
    )
    assert d.verdict.refused is None and d.verdict.threshold is None
    assert len(d.verdict.warning_details) == len(d.verdict.warnings)
    assert {w["kind"] for w in d.verdict.warning_details} <= {
        "channel_worsened",
        "channel_left",
        "on_search_bound",
    }
    assert all(isinstance(x.warning_details, list) for x in d.ranking)
    assert len(d.note_details) == len(d.notes)
    assert [x.effect for x in d.ranking] == [x["effect"] for x in written["ranking"]]
    assert pickle.loads(pickle.dumps(d)) == d
    assert (d.campaign, d.runs, d.folds) == (written["campaign"], written["runs"], written["folds"])


def test_the_dask_extra_brings_distributed():
    # `pip install "./python[dask]"` must bring what the Dask examples import.
    reqs = [r.replace(" ", "").replace("'", '"') for r in importlib.metadata.requires("handling") or []]
    assert any(r.startswith("dask[distributed]") and 'extra=="dask"' in r for r in reqs), reqs


def test_verdict_kinds_are_the_librarys():
    # Python's cases are the library's, by name.
    assert [k.value for k in handling.VerdictKind] == handling._handling.verdict_kinds()


def test_a_verdict_without_effects_says_its_case_and_why(tmp_path):
    # No gap: the case and its threshold, no effects; a refused best
    # candidate comes back typed from the JSON a verdict outside the
    # library writes.
    c = tmp_path / "none"
    handling.synth(c, [], seed=4)
    with open(c / "vehicle.toml", "a") as f:
        f.write('effects = ["sensor_bias"]\n')
    d = handling.diagnose(c, out=tmp_path / "d")
    assert d.verdict.kind is handling.VerdictKind.NO_SIGNIFICANT_GAP
    assert d.verdict.effects == [] and d.verdict.parameters == []
    assert d.verdict.threshold == 1.3
    assert d.verdict.statement.startswith("no significant gap")
    outside = dict(
        d.to_dict()["verdict"],
        kind="outside_library",
        refused={
            "effects": ["sensor_bias"],
            "reduction_percent": 53.5,
            "why": [{"kind": "axles_no_tyre", "no_tyre": []}],
        },
        threshold_percent=30.0,
    )
    v = handling.Verdict.from_dict(outside)
    assert v.kind is handling.VerdictKind.OUTSIDE_LIBRARY
    assert isinstance(v.refused, handling.Refused)
    assert v.refused.reasons == ["axles_no_tyre"] and v.refused.reduction_percent == 53.5
    assert pickle.loads(pickle.dumps(v)) == v
