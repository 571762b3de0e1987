import pickle

import numpy as np
import pytest

import handling


def test_load_toml_and_vectorised_forces_equal_pointwise(root):
    t = handling.Tyre.load(root / "tyres" / "pac89_adams_example.toml")
    assert t.model == "pac89"
    fz = np.linspace(1000.0, 6000.0, 6)[:, None]
    alpha = np.radians(np.linspace(-12.0, 12.0, 9))
    f = t.forces(fz, 0.0, alpha, 0.0, 20.0)
    assert set(f) == {"fx", "fy", "mz"}
    assert f["fy"].shape == (6, 9)
    for i in (0, 3, 5):
        for j in (0, 4, 8):
            one = t.forces(float(fz[i, 0]), 0.0, float(alpha[j]), 0.0, 20.0)
            assert one["fy"].shape == ()
            assert one["fy"] == f["fy"][i, j]
    # Sign convention: positive slip angle, positive lateral force.
    assert np.all(f["fy"][:, alpha > 0] > 0)
    k = t.cornering_stiffness(4000.0)
    assert k > 0
    assert np.allclose(t.cornering_stiffness(np.array([4000.0, 4000.0])), k)


def test_tir_has_wheel_moments_and_reads_pressure(root):
    t = handling.Tyre.load(root / "tests" / "fixtures" / "tir" / "MagicFormula62_Parameters.tir")
    assert t.model == "magic-formula"
    f = t.forces(4000.0, 0.01, 0.05, 0.0, 16.7)
    assert {"mx", "my"} <= set(f)
    lo = t.forces(4000.0, 0.0, 0.05, 0.0, 16.7, pressure=1.8e5)["fy"]
    hi = t.forces(4000.0, 0.0, 0.05, 0.0, 16.7, pressure=2.6e5)["fy"]
    assert lo != hi


@pytest.mark.parametrize(
    "name", ["gim.toml", "unitire.toml", "magic_simple.toml", "linear.toml", "pac89_adams_example.toml"]
)
def test_pickle_round_trip_is_exact(root, name):
    t = handling.Tyre.load(root / "tyres" / name)
    u = pickle.loads(pickle.dumps(t))
    assert u == t
    a = np.radians(np.linspace(-15, 15, 31))
    assert np.array_equal(t.forces(3500.0, 0.0, a)["fy"], u.forces(3500.0, 0.0, a)["fy"])


def test_input_error_carries_file_and_line(root, tmp_path):
    text = (root / "tyres" / "gim.toml").read_text()
    lines = text.splitlines()
    i = next(n for n, l in enumerate(lines) if l.startswith("friction ="))
    lines[i] = "friction = -1.0"
    p = tmp_path / "bad.toml"
    p.write_text("\n".join(lines) + "\n")
    with pytest.raises(handling.InputError) as e:
        handling.Tyre.load(p)
    assert e.value.path == str(p)
    assert e.value.line == i + 1
    assert isinstance(e.value.column, int)
    assert "friction" in str(e.value)
    assert isinstance(e.value, handling.HandlingError)


def test_missing_file_is_input_error(tmp_path):
    with pytest.raises(handling.InputError) as e:
        handling.Tyre.load(tmp_path / "nope.toml")
    assert e.value.path.endswith("nope.toml")
    assert e.value.line is None


def test_param_error_carries_key_and_value(root):
    import json

    t = handling.Tyre.load(root / "tyres" / "linear.toml")
    d = json.loads(t.to_json())
    key = next(k for k, v in d.items() if isinstance(v, float) and v > 0)
    d[key] = -1.0
    with pytest.raises(handling.ParamError) as e:
        handling.Tyre.from_json(json.dumps(d))
    assert key in e.value.key
    assert e.value.value == -1.0
    assert e.value.reason


@pytest.mark.parametrize(
    "name", ["tyres/pac89_adams_example.toml", "tyres/unitire.toml", "tests/fixtures/tir/MagicFormula61_Parameters.tir"]
)
def test_cornering_stiffness_on_arrays_equals_the_scalar_calls(root, name):
    t = handling.Tyre.load(root / name)
    fz = np.linspace(500.0, 8000.0, 12).reshape(3, 4)
    k = t.cornering_stiffness(fz)
    assert isinstance(k, np.ndarray) and k.dtype == np.float64 and k.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            assert k[i, j] == t.cornering_stiffness(float(fz[i, j]))
    # Strided and list input, numpy and Python scalars, empty arrays.
    assert np.array_equal(t.cornering_stiffness(fz.T), k.T)
    assert np.array_equal(t.cornering_stiffness(list(fz[0])), k[0])
    s = t.cornering_stiffness(np.float64(4000.0))
    assert isinstance(s, float) and s == t.cornering_stiffness(4000)
    assert t.cornering_stiffness(np.empty((0, 2))).shape == (0, 2)
    # Stiffness grows with load over this range for these tyres.
    assert np.all(np.diff(k.ravel()) > 0)
