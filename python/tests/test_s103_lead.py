"""Python errors that were plain ValueErrors: a merge of no shard file, a
study evaluated on stiffness arrays of unequal length and an unknown start
of the staged fit are the package's own errors, with their attributes; the
angle columns ``metrics`` reads in degrees are the library's one list."""

import pytest

import handling


def test_a_merge_of_no_shard_file_is_an_options_error():
    with pytest.raises(handling.OptionsError) as e:
        handling.merge([])
    assert e.value.kind == "options"
    assert "no shard files" in str(e.value)


def test_unequal_stiffness_arrays_are_an_options_error_naming_both_keywords(root):
    study = handling.Study.load(root / "scenarios" / "sedan_study_coarse.toml")
    with pytest.raises(handling.OptionsError) as e:
        study.evaluate(front_n_per_deg=[400.0, 500.0, 600.0], rear_n_per_deg=[500.0, 600.0])
    said = str(e.value)
    assert "`front_n_per_deg` has shape (3,) and `rear_n_per_deg` (2,)" in said, said
    assert e.value.name == "rear_n_per_deg"
    # Broadcasting a scalar against an array is no contradiction.
    assert len(study.evaluate(front_n_per_deg=[400.0, 500.0], rear_n_per_deg=500.0)) == 2


def test_metrics_reads_in_degrees_the_librarys_angle_columns(tmp_path):
    assert list(handling._handling.METRICS_ANGLES) == ["steer", "yaw_rate", "beta", "roll"]
    run = tmp_path / "run.csv"
    run.write_text("time,speed,steer,yaw_rate\n0,20,0,0\n")
    with pytest.raises(handling.OptionsError) as e:
        handling.metrics(run, degrees=["bank"])
    assert e.value.known == ["steer", "yaw_rate", "beta", "roll"]
    assert e.value.name == "bank"


def test_an_unknown_start_of_the_staged_fit_is_an_options_error(tmp_path):
    # The start is checked before the data are read.
    with pytest.raises(handling.OptionsError) as e:
        handling.identify(tmp_path / "rig.csv", "mf61", start="nowhere")
    assert "nowhere" in str(e.value)
