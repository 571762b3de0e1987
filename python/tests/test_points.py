"""`Tyre.forces` and `Tyre.cornering_stiffness` check their points as
`tyre-eval` checks a points file (the library's own checks): each point
the CLI refuses raises `PointError` naming the argument, index and value;
slip ratios beyond ±1 warn as the CLI warns. Round 28's findings."""

import warnings

import numpy as np
import pytest

import handling


@pytest.fixture
def mf(root):
    return handling.Tyre.load(root / "tests" / "fixtures" / "tir" / "MagicFormula61_Parameters.tir")


@pytest.mark.parametrize(
    "kw, argument, index, value",
    [
        (dict(fz=float("nan"), alpha=0.05), "fz", 0, None),
        (dict(fz=4000.0, alpha=[0.01, np.nan]), "alpha", 1, None),
        # 3 rad: beyond ±90°, and 3° in radians: the CLI asks for degrees.
        (dict(fz=4000.0, alpha=3.0), "alpha", 0, 3.0),
        (dict(fz=4000.0, alpha=0.05, speed=-16.7), "speed", 0, -16.7),
        (dict(fz=4000.0, alpha=0.05, pressure=2.2), "pressure", 0, 2.2),
        (dict(fz=4000.0, kappa=[0.0, 0.1, 12.0]), "kappa", 2, 12.0),
        # Loads in kN (4 for 4 kN).
        (dict(fz=[4.0, 5.0], alpha=0.05), "fz", 0, 4.0),
        (dict(fz=[-4000.0, -3000.0], alpha=0.05), "fz", 0, -4000.0),
    ],
)
def test_forces_refuse_each_point_the_cli_refuses_by_argument_and_index(mf, kw, argument, index, value):
    with pytest.raises(handling.PointError) as e:
        mf.forces(**kw)
    err = e.value
    assert isinstance(err, handling.HandlingError)
    assert (err.argument, err.index) == (argument, index), str(err)
    if value is None:
        assert not np.isfinite(err.value) and err.problem is None
    else:
        assert err.value == value and err.problem is not None
    assert f"{argument}[{index}]: " in str(err) and err.reason in str(err)
    assert err.refused[0] == (argument, index, err.value) or value is None


def test_forces_refuse_one_pressure_in_bar_among_pressures_in_pa_at_its_index(mf):
    # The median (2.3e5 Pa) is a tyre's, so the array passes as a whole;
    # its third value, 2.4 bar, is refused at its index as tyre-eval
    # refuses that cell of a points file (it was evaluated at 2.4 Pa).
    with pytest.raises(handling.PointError) as e:
        mf.forces(fz=4000.0, alpha=0.05, pressure=[2.2e5, 2.3e5, 2.4])
    err = e.value
    assert (err.argument, err.index, err.value) == ("pressure", 2, 2.4), str(err)
    assert err.refused == [("pressure", 2, 2.4)]
    assert err.problem is not None and "bar" in err.reason
    assert "pressure[2]: " in str(err) and "1 point refused" in str(err)
    # Cells in two units: each refused at its own index.
    with pytest.raises(handling.PointError) as e:
        mf.forces(fz=4000.0, alpha=0.05, pressure=[2.2e5, 2.2, 220.0])
    assert [(a, i) for a, i, _ in e.value.refused] == [("pressure", 1), ("pressure", 2)]
    f = mf.forces(fz=4000.0, alpha=0.05, pressure=[2.2e5, 2.3e5, 2.4e5])
    assert np.all(np.isfinite(f["fy"]))


def test_forces_name_every_refused_point_in_index_order(mf):
    with pytest.raises(handling.PointError) as e:
        mf.forces(fz=[4000.0, 4000.0, np.inf], alpha=[3.0, 0.0, 0.0], speed=[10.0, -5.0, 10.0])
    refused = [(a, i) for a, i, _ in e.value.refused]
    assert refused == [("alpha", 0), ("speed", 1), ("fz", 2)]
    assert "3 points refused" in str(e.value)


def test_forces_warn_of_slip_ratios_beyond_one_as_the_cli_does(mf):
    with pytest.warns(UserWarning, match=r"1 of 2 points at a slip ratio beyond ±1 \(the first at index 1, kappa = 7"):
        f = mf.forces(fz=4000.0, kappa=[0.1, 7.0])
    assert np.all(np.isfinite(f["fx"]))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mf.forces(fz=4000.0, kappa=[0.1, -1.0, 1.0])


def test_cornering_stiffness_refuses_a_load_the_cli_refuses(mf):
    for fz in (float("nan"), float("inf"), 2e6):
        with pytest.raises(handling.PointError) as e:
            mf.cornering_stiffness(fz)
        assert (e.value.argument, e.value.index) == ("fz", 0)
    with pytest.raises(handling.PointError) as e:
        mf.cornering_stiffness(np.array([4000.0, np.nan]))
    assert (e.value.argument, e.value.index) == ("fz", 1)
    assert mf.cornering_stiffness(4000.0) > 0.0


def test_forces_at_good_points_are_unchanged_by_the_checks(mf):
    alpha = np.radians([-5.0, 0.0, 2.0])
    f = mf.forces(fz=4000.0, alpha=alpha, speed=16.7)
    assert np.all(np.isfinite(f["fy"])) and f["fy"][0] * f["fy"][2] < 0


def test_identification_has_the_headline_sigma_of_its_dict(root, tmp_path):
    t = handling.Tyre.load(root / "tyres" / "gim.toml")
    fz = np.repeat([2000.0, 4000.0, 6000.0], 41)
    a = np.tile(np.radians(np.linspace(-12, 12, 41)), 3)
    fy = t.forces(fz, 0.0, a)["fy"]
    p = tmp_path / "rig.csv"
    np.savetxt(p, np.column_stack([fz, a, fy]), delimiter=",", header="fz,alpha,fy", comments="", fmt="%.17g")
    r = handling.identify(p, "gim", seed=1)
    assert r.sigma_percent == r.to_dict()["sigma_percent"] and 0.0 <= r.sigma_percent < 1.0
    # A staged Magic Formula fit's headline is its pooled σ.
    staged = handling.Identification.from_dict({"sigma_pooled": {"sigma_percent": 3.01}})
    assert staged.sigma_percent == 3.01


def test_point_error_is_exported_and_options_error_in_the_book(root):
    assert "PointError" in handling.__all__ and issubclass(handling.PointError, handling.HandlingError)
    book = (root / "docs" / "src" / "python.md").read_text()
    first_list = book.split("- Errors are")[1].split("\n- ")[0]
    for name in ("OptionsError", "PointError", "FitError", "OutputError"):
        assert name in first_list, name
