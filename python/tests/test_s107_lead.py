"""A rig file whose header writes a unit after a column (`fz [kN]`, as rigs
and loggers write them) is refused at that header cell; before, the Python
exception carried the path, line and column but no `key`, where every
other refusal of a column names it."""

import pytest

import handling


def test_a_unit_in_a_header_is_keyed_by_the_column_it_names(tmp_path):
    rows = ["fz [kN],alpha,fy,pressure"]
    for i in range(41):
        a = -0.1 + 0.005 * i
        rows.append(f"2.5,{a:.4f},{60000.0 * a:.2f},220000")
    p = tmp_path / "rig.csv"
    p.write_text("\n".join(rows) + "\n")
    with pytest.raises(handling.InputError) as e:
        handling.identify(p, "linear", seed=1)
    assert (e.value.path, e.value.line, e.value.column) == (str(p), 1, 1)
    assert (e.value.key, e.value.value) == ("fz", None)
    assert "kN" in e.value.reason and "× 1000" in e.value.reason
