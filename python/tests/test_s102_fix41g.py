"""Round 41's leftovers in the Python API: ``run_shard`` with a shard
index beyond its count (or 0) raised a plain ValueError where the book says
every error is a ``HandlingError`` subclass, and named neither number as
an attribute."""

import pytest

import handling


@pytest.mark.parametrize("index,count", [(4, 3), (0, 3), (2, 1)])
def test_a_shard_index_outside_its_count_is_an_options_error_naming_both(root, tmp_path, index, count):
    sweep = root / "scenarios" / "equilibria_steer.toml"
    with pytest.raises(handling.OptionsError) as e:
        handling.run_shard("equilibria", sweep, index, count, out=tmp_path)
    assert isinstance(e.value, handling.HandlingError)
    assert f"shard {index}/{count}" in str(e.value)
    assert "1 ≤ K ≤ N" in str(e.value)
    assert (e.value.index, e.value.count) == (index, count)
    assert e.value.kind == "options"
    assert not list(tmp_path.iterdir())


def test_an_unknown_job_is_still_an_options_error_before_the_shard_is_read(root, tmp_path):
    sweep = root / "scenarios" / "equilibria_steer.toml"
    with pytest.raises(handling.OptionsError) as e:
        handling.run_shard("studies", sweep, 1, 2, out=tmp_path)
    assert e.value.name == "studies" and "unknown job `studies`" in str(e.value)
