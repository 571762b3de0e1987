"""A keyword of ``identify`` the model's fit does not read is refused, as
the command line refuses its flag (one table, ``identify/taken.rs``): a
``seed`` given to the staged Magic Formula fit, or a ``template`` to a
swarm fit, was dropped without a word."""

import pytest

import handling


@pytest.mark.parametrize(
    "model, keyword, value",
    [
        ("mf61", "seed", 3),
        ("mf61", "local", "nm"),
        ("mf62", "bin_kappa", 0.01),
        ("gim", "max_iterations", 20),
        ("pac89", "start", "paper"),
    ],
)
def test_a_keyword_the_models_fit_does_not_read_is_refused_by_name(tmp_path, model, keyword, value):
    # Refused before the data are read: the file need not exist.
    with pytest.raises(handling.OptionsError) as e:
        handling.identify(tmp_path / "rig.csv", model, **{keyword: value})
    said = str(e.value)
    # Said in the keywords' spelling, as the package's other errors are.
    assert said.startswith(f"`{keyword}=` is not taken by `model=` {model}: "), said
    assert said.endswith(f"drop `{keyword}=`"), said


def test_a_level_selection_the_staged_fit_does_not_make_is_refused(tmp_path):
    with pytest.raises(handling.OptionsError) as e:
        handling.identify(tmp_path / "rig.csv", "mf61", pressure=2.0e5)
    assert str(e.value).startswith("`pressure=` is not taken by `model=` mf61: "), str(e.value)


def test_keywords_left_at_their_defaults_are_not_refused(tmp_path):
    # Past the option check, the missing file is what is said.
    for model in ["mf61", "gim"]:
        with pytest.raises(handling.HandlingError) as e:
            handling.identify(tmp_path / "rig.csv", model)
        assert "not taken" not in str(e.value), str(e.value)
        assert "rig.csv" in str(e.value), str(e.value)
