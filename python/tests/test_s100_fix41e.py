"""`Tyre.forces` takes `tyre-eval`'s `--mode` (MFeval's useMode) as
`mode=`, with its choices, its default and its refusals in its words (the
spelling of the CLI's options as Python's keywords: test_spelling.py)."""

import warnings

import numpy as np
import pytest

import handling

TIR = ("tests", "fixtures", "tir", "MagicFormula61_Parameters.tir")

# `handling tyre-eval MagicFormula61_Parameters.tir points.csv --mode M`
# at fz = 4000 and 40000 N (FZMAX = 18000 N), alpha = 0.05 rad, speed
# 20 m/s: its fy column, as it wrote it.
CLI_FY = {
    121: (3355.328139353409, 8464.505446736965),
    111: (3353.858695645541, 8458.615043110167),
    221: (3355.328139353409, 207.86190723084246),
}


def _tir(root):
    return handling.Tyre.load(root.joinpath(*TIR))


def _fy(t, **kw):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        f = t.forces(fz=np.array([4000.0, 40000.0]), alpha=0.05, speed=20.0, **kw)
    return f["fy"], [str(x.message) for x in w if issubclass(x.category, UserWarning)]


@pytest.mark.parametrize("mode", sorted(CLI_FY))
def test_forces_in_a_mode_are_tyre_eval_s_in_that_mode(root, mode):
    fy, _ = _fy(_tir(root), mode=mode)
    assert fy == pytest.approx(CLI_FY[mode], rel=1e-12, abs=1e-9)


def test_forces_without_a_mode_are_tyre_eval_s_default_121(root):
    t = _tir(root)
    fy, said = _fy(t)
    assert np.array_equal(fy, _fy(t, mode=121)[0])
    assert any("evaluated at 18000 N" in s for s in said), said


def test_limit_checks_off_extrapolate_and_the_warning_says_so(root):
    t = _tir(root)
    fy, said = _fy(t, mode=221)
    above = [s for s in said if "above FZMAX = 18000 N" in s]
    assert above and "limit checks off, mode 2xx" in above[0], said
    assert "evaluated at 18000 N" not in above[0]
    # The tyre itself is unchanged: its next call is in its own mode.
    assert np.array_equal(_fy(t)[0], _fy(t, mode=121)[0])
    assert fy[1] != _fy(t)[0][1]


@pytest.mark.parametrize(
    "mode, words",
    [
        (122, "`mode=`: mode 122: turn slip (units digit 2) is not modelled; use 121"),
        (131, "`mode=`: mode 131: tens digit 3 is not 1 or 2"),
        (99, "`mode=`: mode 99 is not a three-digit code"),
        (1211, "`mode=`: mode 1211 is not a three-digit code"),
    ],
)
def test_a_mode_tyre_eval_refuses_is_refused_in_its_words(root, mode, words):
    with pytest.raises(handling.OptionsError) as e:
        _tir(root).forces(fz=4000.0, alpha=0.05, mode=mode)
    assert str(e.value).startswith(words), str(e.value)
    assert "--mode" not in str(e.value)
    assert e.value.kind == "options"


def test_a_mode_for_another_model_is_refused_as_tyre_eval_refuses_it(root):
    t = handling.Tyre.load(root / "tyres" / "gim.toml")
    with pytest.raises(handling.OptionsError) as e:
        t.forces(fz=4000.0, alpha=0.05, mode=121)
    msg = str(e.value)
    assert "a setting of the Magic Formula (.tir) tyres only" in msg, msg
    assert "drop `mode=`" in msg and "--mode" not in msg, msg
    # Without it the tyre is evaluated as before.
    assert t.forces(fz=4000.0, alpha=0.05)["fy"] > 0


@pytest.mark.parametrize("mode", [121.0, "121"])
def test_a_mode_that_is_not_an_integer_is_refused(root, mode):
    # As `tyre-eval --mode 121.0` is refused: an integer code only.
    with pytest.raises(TypeError, match="argument 'mode': .* cannot be interpreted as an integer"):
        _tir(root).forces(fz=4000.0, alpha=0.05, mode=mode)
