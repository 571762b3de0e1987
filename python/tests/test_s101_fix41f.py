"""What a user trips on in the Python package: a `mode=` no integer code
holds (negative, or past 2**32 - 1) raised Python's `OverflowError`; and
`metrics`' judgement of a hole in a log beside the yaw-rate peak (one
missing row keeps the peak within the noise, a hole that can hide it
withholds it with its bound, a hole that cuts the step says to fill it),
measured through `handling.metrics` as a user calls it."""

import numpy as np
import pytest

import handling

TIR = ("tests", "fixtures", "tir", "MagicFormula61_Parameters.tir")

# tyre-eval's words for a code of other than three digits, which name the
# digits allowed.
CODES = "MFeval's useMode: hundreds 1 (limit checks on) or 2 (off)"


@pytest.mark.parametrize("mode", [-5, -121, 2**32, 2**70])
def test_a_mode_no_code_holds_is_refused_naming_it_and_the_codes(root, mode):
    t = handling.Tyre.load(root.joinpath(*TIR))
    with pytest.raises(handling.OptionsError) as e:
        t.forces(fz=4000.0, alpha=0.05, mode=mode)
    msg = str(e.value)
    assert msg.startswith(f"`mode=`: mode {mode} is not a three-digit code ({CODES}"), msg
    assert e.value.kind == "options"
    assert not isinstance(e.value, OverflowError)
    # As a code of two digits is refused.
    with pytest.raises(handling.OptionsError) as two:
        t.forces(fz=4000.0, alpha=0.05, mode=99)
    assert str(two.value) == msg.replace(f"mode {mode} ", "mode 99 ", 1)


LINEAR = 'model = "linear"\ncornering_stiffness = 57296.0\npneumatic_trail = 0.03\n'

# A linear car's 0.01 rad step steer at 25 m/s, 1 ms steps: tests/cli's
# `tester_step`, whose yaw rate peaks at 1.39 s.
STEP = """name = "lin"
[vehicle]
mass = 1530.0
yaw_inertia = 2315.0
a = 1.11
b = 1.67
track_front = 1.55
track_rear = 1.55
cg_height = 0.55
[tyres]
front = "linear.toml"
[model]
kinematics = "small-angle"
load_transfer = false
[manoeuvre]
kind = "step-steer"
speed = 25.0
steer = 0.01
start = 1.0
rise_time = 0.1
end = 9.0
[simulation]
step = 0.001
"""


@pytest.fixture
def logged(tmp_path):
    """`(name, missing, sigma) -> path`: the step logged at 100 Hz, the
    rows whose time in ms `missing` holds left out, the yaw rate with a
    noise of `sigma` rad/s drawn once per row (a log with rows left out
    has the same noise on the rows it keeps)."""
    (tmp_path / "linear.toml").write_text(LINEAR)
    (tmp_path / "lin.toml").write_text(STEP)
    h = handling.simulate(tmp_path / "lin.toml", pandas=False).history
    ms = np.rint(np.asarray(h["t"]) * 1000).astype(int)
    noise = np.random.default_rng(6323).uniform(-0.5, 0.5, ms.size) * np.sqrt(12)

    def write(name, missing, sigma):
        keep = (ms % 10 == 0) & ~missing(ms)
        cols = ["t", "speed", "steer", "yaw_rate", "ay", "beta"]
        data = {c: np.asarray(h[c]) for c in cols}
        data["yaw_rate"] = data["yaw_rate"] + sigma * noise
        rows = np.column_stack([data[c] for c in cols])[keep]
        p = tmp_path / name
        np.savetxt(p, rows, delimiter=",", header=",".join(cols), comments="", fmt="%.17g")
        return p

    return write


def _said(r):
    return "\n".join(r.to_dict()["warnings"])


def test_one_missing_row_beside_the_yaw_rate_peak_keeps_the_peak(logged):
    # Noise of 1.4 % of the step (0.0008 rad/s): the straight line across
    # a 0.02 s hole misses the yaw rate by |r''|·L²/8, about 0.01 % of it.
    intact = handling.metrics(logged("intact.csv", lambda ms: ms < 0, 0.0008))
    tp, os = intact.metrics.yaw_rate_peak_time, intact.metrics.yaw_rate_overshoot
    assert tp is not None and os is not None, _said(intact)
    for name, missing in [
        ("at_peak.csv", lambda ms: ms == 1390),
        ("before.csv", lambda ms: ms == 1330),
        ("one_in_seven.csv", lambda ms: ms % 70 == 30),
    ]:
        r = handling.metrics(logged(name, missing, 0.0008))
        m = r.metrics
        assert m.yaw_rate_peak_time is not None, f"{name}: {_said(r)}"
        assert abs(m.yaw_rate_peak_time - tp) <= 0.02, (name, m.yaw_rate_peak_time, tp)
        assert abs(m.yaw_rate_overshoot - os) <= 0.5, (name, m.yaw_rate_overshoot, os)
        assert "does not measure the peak" not in _said(r), _said(r)


def test_a_hole_that_can_hide_the_peak_withholds_it_with_its_bound(logged):
    # Four rows at the peak of a log without noise: the line across can
    # miss the top by more than the noise.
    r = handling.metrics(logged("four.csv", lambda ms: (ms >= 1365) & (ms <= 1405), 0.0))
    said = _said(r)
    assert r.metrics.yaw_rate_peak_time is None and r.metrics.yaw_rate_overshoot is None
    assert "|r''|·L²/8" in said and "the log does not measure the peak there" in said, said


def test_a_hole_that_cuts_the_step_says_to_fill_it(logged):
    # Rows 1.24-1.28 s missing, 0.19 s after the steer moved: the piece
    # after the gap starts turned.
    p = logged("gap5.csv", lambda ms: (ms >= 1235) & (ms <= 1285), 0.0)
    with pytest.raises(handling.InputError) as e:
        handling.metrics(p)
    msg = str(e.value)
    assert e.value.path == str(p)
    assert "no rows 1.230–1.290 s, 5 samples missing" in msg, msg
    assert "fill the hole in the file" in msg and "start the record" not in msg, msg
