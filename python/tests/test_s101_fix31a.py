"""Round 31's findings in the Python API: ``Study.evaluate`` took stiffness
values the study file refuses (NaN gave the unscaled car's answer, −500
N/deg a car with negative stiffness, 20,000 N/deg a car 254 times stiffer
than its load), and its samples carried full metrics for a sliding
combination where ``study.csv`` leaves the row empty; ``synth(duration=)``
panicked on NaN and aborted the interpreter on infinity; ``run_shard`` raised
a plain ValueError for an unknown job."""

import csv
import math

import numpy as np
import pytest

import handling


@pytest.fixture
def coarse(root):
    return handling.Study.load(root / "scenarios" / "sedan_study_coarse.toml")


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -500.0, 0.0, 20000.0, 1e-300])
def test_evaluate_refuses_what_the_study_file_refuses_naming_the_keyword(coarse, bad):
    with pytest.raises(handling.ParamError) as e:
        coarse.evaluate(front_n_per_deg=bad, rear_n_per_deg=540.0)
    assert e.value.key == "front_n_per_deg", str(e.value)
    assert e.value.value == bad or (math.isnan(bad) and math.isnan(e.value.value))
    assert str(e.value).startswith("`front_n_per_deg` = "), str(e.value)


def test_evaluate_says_a_value_in_the_other_unit_as_the_study_file_does(coarse):
    with pytest.raises(handling.ParamError) as e:
        coarse.evaluate(front_n_per_deg=20000.0, rear_n_per_deg=540.0)
    said = str(e.value)
    assert "20000 N/deg per tyre is 1145916 N/rad, 254 times the front tyre's static load" in said
    assert said.endswith("give it as `front_n_per_rad` = 20000, or as `front_n_per_deg` = 349.1"), said
    # The rear, in N/rad, among several pairs: the index of the one refused.
    k = 180.0 / np.pi
    with pytest.raises(handling.ParamError) as e:
        coarse.evaluate(front_n_per_rad=[500.0 * k, 500.0 * k], rear_n_per_rad=[540.0 * k, 540.0])
    assert e.value.key == "rear_n_per_rad[1]", str(e.value)
    assert "is the value in N/deg? give it as `rear_n_per_deg` = 540" in str(e.value)
    # Softer than any tyre in either unit: the range a tyre there has.
    with pytest.raises(handling.ParamError, match="nor is it one in N/rad: the rear tyre's lies within"):
        coarse.evaluate(front_n_per_deg=500.0, rear_n_per_deg=5.0)


def test_a_sliding_combination_has_the_csv_s_response_and_no_metrics(coarse, root, tmp_path):
    (slides, holds) = coarse.evaluate(front_n_per_deg=[500.0, 500.0], rear_n_per_deg=[220.0, 540.0])
    assert slides.response == "sliding" and slides.metrics is None, slides
    assert "slides past its grip" in slides.note
    assert holds.response == "handling" and holds.metrics is not None and holds.note is None
    # The map's Er over the handling responses is study.csv's: the Dask
    # example's range (`s.metrics.er for s if s.metrics`) is the CLI's.
    report = handling.study(root / "scenarios" / "sedan_study_coarse.toml", out=tmp_path / "st")
    rows = list(csv.DictReader(open(tmp_path / "st" / "study.csv")))
    grid = coarse.grid()
    samples = coarse.evaluate(front_n_per_rad=[g[0] for g in grid], rear_n_per_rad=[g[1] for g in grid])
    assert [s.response for s in samples] == [r["response"] for r in rows[: len(grid)]]
    assert any(s.response == "sliding" for s in samples)
    er = [s.metrics.er for s in samples if s.metrics]
    cli = [float(r["er"]) for r in rows[: len(grid)] if r["er"]]
    assert min(er) == pytest.approx(min(cli), rel=1e-6) and max(er) == pytest.approx(max(cli), rel=1e-6)
    # The study's own samples say the same.
    assert [s.response for s in report.samples[: len(grid)]] == [s.response for s in samples]
    assert all((s.metrics is None) == (s.response not in ("handling",)) for s in report.samples)


@pytest.mark.parametrize(
    "duration, said",
    [
        (float("nan"), "no number of seconds"),
        (float("inf"), "at most 3600 s together"),
        (1e9, "at most 3600 s together"),
        (300.5, "give 300 or 301"),
    ],
)
def test_synth_refuses_a_duration_it_cannot_drive_as_an_options_error(tmp_path, duration, said):
    with pytest.raises(handling.OptionsError, match=said):
        handling.synth(tmp_path / "s", programme="racing-rear-steer", duration=duration)
    assert not (tmp_path / "s").exists()


def test_run_shard_names_an_unknown_job_with_the_nearest(root, tmp_path):
    sweep = root / "scenarios" / "equilibria_steer.toml"
    with pytest.raises(handling.OptionsError) as e:
        handling.run_shard("equilibrium", sweep, 1, 3, out=tmp_path)
    assert isinstance(e.value, handling.HandlingError)
    assert "unknown job `equilibrium` (did you mean `equilibria`?): one of equilibria, study" in str(e.value)
    assert e.value.name == "equilibrium" and list(e.value.known) == ["equilibria", "study"]
