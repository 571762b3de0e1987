"""What a user trips on in the Python package: `handling.design` refusing
`top=0` or `ay_share=1.5` named the command line's `--top` and
`--ay-share` in the exception's `key` while its message named the Python
keyword; and the Dask batch example died on one broken campaign, where
the command-line batch it mirrors lists it as FAILED and goes on."""

import os
import pathlib
import subprocess
import sys

import pytest

import handling


@pytest.mark.parametrize(
    "kwargs, key, value",
    [({"top": 0}, "top", 0.0), ({"ay_share": 1.5}, "ay_share", 1.5), ({"max_ax": 0.0}, "max_ax", 0.0)],
)
def test_a_design_option_refused_is_keyed_by_its_python_keyword(tmp_path, kwargs, key, value):
    # The options are checked before the diagnosis is read.
    with pytest.raises(handling.ParamError) as e:
        handling.design(tmp_path / "no_diagnosis", **kwargs)
    assert e.value.key == key, (e.value.key, str(e.value))
    assert e.value.value == value
    assert f"`{key}`" in str(e.value), str(e.value)


def test_the_dask_batch_example_lists_a_broken_campaign_as_failed_and_goes_on(root, tmp_path):
    pytest.importorskip("distributed")
    batch = tmp_path / "batch"
    good = batch / "a_none"
    handling.synth(good, [], seed=3)
    with open(good / "vehicle.toml", "a") as f:
        f.write('effects = ["sensor_bias", "relaxation_length"]\n')
    (batch / "c_broken.toml").write_text('name = "broken"\n[vehicle]\nmass = 1530.0\n')
    example = root / "python" / "examples" / "dask_diagnose_batch.py"
    env = dict(os.environ)
    done = subprocess.run(
        [sys.executable, str(example), str(batch)], capture_output=True, text=True, env=env, timeout=600
    )
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert any(line.startswith("a_none: no significant gap") for line in lines), done.stdout
    broken = [line for line in lines if line.startswith("c_broken.toml: FAILED: ")]
    assert len(broken) == 1 and "yaw_inertia" in broken[0], done.stdout
    assert lines[-1].startswith("2 campaigns, 1 failed: Dask ") and lines[-1].endswith("; identical"), done.stdout
