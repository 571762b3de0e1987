"""Round 29's findings in the Python API: `Tyre.forces` clipped
at a `.tir` file's ranges without a word where `tyre-eval` warns; `metrics`
had no `degrees` while its errors told a Python user to type
`metrics --degrees steer`; a run without a step steer raises the CLI's
class of error (`InputError`, the file holds no step)."""

import warnings

import numpy as np
import pytest

import handling


def test_forces_beyond_a_tir_file_s_ranges_warn_in_tyre_eval_s_words(root):
    # FZMAX = 18000 N, ALPMAX = 0.96 rad: 40 kN is evaluated at 18 kN.
    t = handling.Tyre.load(root / "tests" / "fixtures" / "tir" / "MagicFormula61_Parameters.tir")
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        at = t.forces(fz=np.array([4000.0, 40000.0]), alpha=0.05)
    said = [str(x.message) for x in w if issubclass(x.category, UserWarning)]
    above = [s for s in said if "above FZMAX = 18000 N" in s]
    assert above, said
    assert "1 of 2 points" in above[0] and "the first at index 1, fz = 40000 N" in above[0], above
    assert "evaluated at 18000 N" in above[0]
    # What it warns of is what it did: the forces at FZMAX.
    clipped = t.forces(fz=18000.0, alpha=0.05)
    assert at["fy"][1] == pytest.approx(float(clipped["fy"]))
    # Inside every range: no warning.
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        t.forces(fz=4000.0, alpha=0.05)
    assert not [x for x in w if "FZMAX" in str(x.message)]


def test_metrics_reads_a_steer_in_degrees_and_names_unknown_columns(root, tmp_path):
    h = handling.simulate(root / "scenarios" / "sedan_step.toml", pandas=False).history
    cols = ["t", "steer", "speed", "yaw_rate", "ay"]
    rows = np.column_stack([h[c] for c in cols])[::10]
    radians = tmp_path / "rad.csv"
    np.savetxt(radians, rows, delimiter=",", header=",".join(cols), comments="", fmt="%.17g")
    rows[:, 1] = np.degrees(rows[:, 1])
    degrees = tmp_path / "deg.csv"
    np.savetxt(degrees, rows, delimiter=",", header=",".join(cols), comments="", fmt="%.17g")
    # Read in radians the steer in degrees is refused, in Python's words.
    with pytest.raises(handling.HandlingError) as e:
        handling.metrics(degrees)
    assert "--degrees" not in str(e.value), str(e.value)
    m = handling.metrics(degrees, degrees=["steer"]).metrics
    assert m.yaw_rate_gain == pytest.approx(handling.metrics(radians).metrics.yaw_rate_gain, rel=1e-6)
    with pytest.raises(handling.OptionsError) as e:
        handling.metrics(degrees, degrees=["bank"])
    assert e.value.name == "bank" and e.value.known == ["steer", "yaw_rate", "beta", "roll"]


def test_a_run_without_a_step_is_the_cli_s_input_error(tmp_path):
    t = np.arange(0.0, 10.0, 0.01)
    rows = np.column_stack([t, 0.02 * np.sin(2 * np.pi * 0.5 * t), 20.0 + 0 * t, 0.1 * np.sin(2 * np.pi * 0.5 * t), 2.0 * np.sin(2 * np.pi * 0.5 * t)])
    p = tmp_path / "sine.csv"
    np.savetxt(p, rows, delimiter=",", header="t,steer,speed,yaw_rate,ay", comments="", fmt="%.9g")
    with pytest.raises(handling.InputError) as e:
        handling.metrics(p)
    assert e.value.kind == "input" and "no step steer" in str(e.value)
