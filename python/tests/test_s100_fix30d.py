"""Round 30's findings in the Python API: one effect name given as a string
was split into its letters (``unknown effect `s```), and so was a single
path given to ``drive`` or ``measured``; a number written as a string with
a decimal comma (``mass="1530,0"``) was refused as "invalid type" where the
command line names the decimal comma."""

import json

import pytest

import handling


def test_a_string_of_effects_is_read_as_the_command_line_s_comma_list(tmp_path):
    one = handling.synth(tmp_path / "one", effects="sensor_delay")
    assert one["name"] == "sensor_delay" and one["runs"] > 0, one
    # The truth the campaign states is the effect named, not its letters.
    assert "sensor_delay" in (tmp_path / "one" / "vehicle.toml").read_text()
    two = handling.synth(tmp_path / "two", effects="sensor_delay, relaxation_length")
    assert two["name"] == handling.synth(
        tmp_path / "three", effects=["sensor_delay", "relaxation_length"]
    )["name"]
    with pytest.raises(ValueError, match="empty name between its commas"):
        handling.synth(tmp_path / "four", effects="sensor_delay,,relaxation_length")
    with pytest.raises(TypeError, match=r"each name is a string, not int \(3\)"):
        handling.synth(tmp_path / "five", effects=["sensor_delay", 3])


def test_a_single_path_to_drive_is_one_path_not_its_letters(tmp_path):
    # A path that does not exist is named whole: before, its first letter.
    with pytest.raises(handling.InputError) as e:
        handling.synth(tmp_path / "c", drive=str(tmp_path / "missing.toml"))
    assert "missing.toml" in str(e.value), str(e.value)


def test_a_string_with_a_decimal_comma_is_named_as_one():
    with pytest.raises(handling.InputError) as e:
        handling.Vehicle(
            mass="1530,0",
            yaw_inertia=2315.0,
            a=1.2,
            b=1.4,
            track_front=1.5,
            track_rear=1.5,
            cg_height=0.5,
        )
    assert e.value.key == "mass" and e.value.value == "1530,0"
    assert "decimal comma" in str(e.value) and "write 1530.0" in str(e.value), str(e.value)
    # A string that is no number keeps the reader's words.
    with pytest.raises(handling.InputError) as e:
        handling.Vehicle(
            mass="heavy",
            yaw_inertia=2315.0,
            a=1.2,
            b=1.4,
            track_front=1.5,
            track_rear=1.5,
            cg_height=0.5,
        )
    assert "decimal comma" not in str(e.value) and "invalid type" in str(e.value)


@pytest.mark.parametrize(
    "kw, said",
    [
        # A load in kN: said of the loads given, not of a file's column.
        (dict(fz=4.0), "among loads whose median is 4 N"),
        (dict(fz=[-4000.0, -3000.0]), "every load given is"),
        (dict(fz=4000.0, alpha=3.0), "is `alpha` in degrees?"),
        (dict(fz=4000.0, speed=-20.0), "-20 m/s is negative"),
        (dict(fz=4000.0, kappa=12.0), "12 lies outside -10 to 10, where a tyre is evaluated"),
        (dict(fz=4000.0, pressure=2.2), "`pressure` is in Pa"),
    ],
)
def test_a_refused_point_is_said_of_the_arrays_given_not_of_a_file(root, kw, said):
    t = handling.Tyre.load(root / "tests" / "fixtures" / "tir" / "MagicFormula61_Parameters.tir")
    with pytest.raises(handling.PointError) as e:
        t.forces(**kw)
    words = str(e.value)
    assert said in words and said in e.value.reason, words
    # The tyre-eval words name a column, a file and FORMATS.md.
    for cli in ("column", "a file whose", "FORMATS.md"):
        assert cli not in e.value.reason, words


def test_synth_takes_the_command_lines_duration(tmp_path):
    # `handling synth --duration` lengthens an analogue programme's runs
    # to the total asked (racing-rear-steer: 300 s by default); a
    # programme of fixed runs refuses it, naming those that take one.
    handling.synth(tmp_path / "s", programme="racing-rear-steer", seed=1, duration=320)
    header = (tmp_path / "s" / "vehicle.toml").read_text().splitlines()[0]
    assert "--duration 320" in header, header
    total = 0.0
    for run in sorted((tmp_path / "s" / "runs").glob("*.csv")):
        times = [float(line.split(",")[0]) for line in run.read_text().splitlines()[1:] if line]
        total += times[-1] - times[0]
    assert abs(total - 320.0) < 1e-9, total
    with pytest.raises(handling.OptionsError, match="sedan-winding"):
        handling.synth(tmp_path / "h", programme="handling", duration=600)
