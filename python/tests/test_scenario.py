"""Scenarios from keywords: the same result as the scenario file, the same
checks, errors that name the keyword and its value."""

import pickle

import numpy as np
import pytest

import handling

# scenarios/sedan_step.toml as keywords.
VEHICLE = dict(
    mass=1530.0, yaw_inertia=2315.0, a=1.11, b=1.67, track_front=1.55, track_rear=1.55, cg_height=0.55
)
STEP = dict(kind="step_steer", speed=22.2222, steer=0.0174533, start=1.0, rise_time=0.1, end=6.0)


def sedan_step(root, **changes):
    kw = dict(
        vehicle=VEHICLE,
        tyres=(root / "tyres" / "gim_sedan_front.toml", root / "tyres" / "gim_sedan_rear.toml"),
        manoeuvre=STEP,
        name="sedan_step",
    )
    kw.update(changes)
    return kw


def same_run(a, b):
    # Simulations compare without their histories, which compare here.
    ha, hb = a.history, b.history
    assert a == b and a.to_dict().keys() == b.to_dict().keys()
    assert list(ha) == list(hb)
    for c in ha:
        assert np.array_equal(ha[c], hb[c]), c


def test_keywords_give_the_scenario_files_result_exactly(root):
    from_file = handling.simulate(root / "scenarios" / "sedan_step.toml", pandas=False)
    same_run(from_file, handling.simulate(**sedan_step(root), pandas=False))
    # A Vehicle, Tyre objects and a Scenario give it too.
    front = handling.Tyre.load(root / "tyres" / "gim_sedan_front.toml")
    rear = handling.Tyre.load(root / "tyres" / "gim_sedan_rear.toml")
    sc = handling.Scenario(
        **sedan_step(root, vehicle=handling.Vehicle(**VEHICLE), tyres={"front": front, "rear": rear})
    )
    assert sc.tyres == (front, rear) and sc.vehicle.mass == 1530.0 and sc.name == "sedan_step"
    from_file = handling.simulate(root / "scenarios" / "sedan_step.toml", pandas=False)
    same_run(from_file, handling.simulate(sc, pandas=False))


def test_keywords_with_every_table_equal_the_file(root, tmp_path):
    # The GB/T 6323 PAC89 scenario: road, model and simulation tables and a
    # step amplitude from the lateral acceleration.
    text = (root / "scenarios" / "step_gbt6323_pac89.toml").read_text()
    p = tmp_path / "pac89.toml"
    p.write_text(text.replace('"../tyres/', f'"{(root / "tyres").as_posix()}/'))
    kw = dict(
        vehicle=VEHICLE,
        tyres=root / "tyres" / "pac89_adams_example.toml",
        road={"friction": 1.0},
        model={"kinematics": "exact", "load_transfer": True},
        manoeuvre=dict(kind="step-steer", speed=22.2222, lateral_acceleration=2.0, start=1.0, rise_time=0.1, end=6.0),
        integrator={"step": 0.001},
        name="step_gbt6323_pac89",
    )
    same_run(handling.simulate(p, pandas=False), handling.simulate(**kw, pandas=False))
    # `metrics` takes the same keywords (and a Scenario): the run's metrics.
    m = handling.simulate(p, pandas=False).metrics
    assert handling.metrics(**kw) == m
    assert handling.metrics(handling.Scenario(**kw)) == m
    # Its windows go into the scenario's [metrics] table.
    with_table = handling.simulate(**kw, metrics={"steady_window": 0.5}, pandas=False).metrics
    assert handling.metrics(**kw, steady_window=0.5) == with_table != m


def test_written_scenario_runs_on_the_cli_path_to_the_same_result(root, tmp_path):
    sc = handling.Scenario(**sedan_step(root, tyres=handling.Tyre.load(root / "tyres" / "gim.toml")))
    # A folder that does not exist yet is created.
    path = sc.write(tmp_path / "new" / "folder")
    assert (tmp_path / "new" / "folder" / "front_tyre.toml").is_file()
    assert open(path).read() == sc.to_toml()
    same_run(handling.simulate(path, pandas=False), handling.simulate(sc, pandas=False))


@pytest.mark.parametrize(
    "changes, key, value",
    [
        (dict(vehicle=dict(VEHICLE, mass=-1530.0)), "vehicle.mass", -1530.0),
        (dict(vehicle=dict(VEHICLE, mas=1530.0)), "vehicle.mas", 1530.0),
        (dict(vehicle=dict(VEHICLE, mass="heavy")), "vehicle.mass", "heavy"),
        (dict(manoeuvre=dict(STEP, speed=0.0)), "manoeuvre.speed", 0.0),
        (dict(manoeuvre=dict(STEP, rise_time=0.3)), "manoeuvre.rise_time", 0.3),
        (dict(manoeuvre=dict(STEP, kind="jump")), "manoeuvre.kind", "jump"),
        (dict(integrator={"method": "rk4", "rtol": 1e-6}), "simulation.rtol", 1e-6),
        (dict(road={"friction": -0.5}), "road.friction", -0.5),
        (dict(model={"effects": {"relaxation_length": -0.1}}), "model.effects.relaxation_length", -0.1),
    ],
)
def test_a_bad_keyword_is_an_input_error_naming_key_and_value(root, changes, key, value):
    with pytest.raises(handling.InputError) as e:
        handling.simulate(**sedan_step(root, **changes))
    assert e.value.key == key and e.value.value == value and e.value.kind == "input"
    assert f"`{key}` = {value!r}" in str(e.value)
    # The reason is the reader's own, without the key and value again.
    assert f"`{key}`" not in e.value.reason
    assert e.value.path is None and e.value.line is None
    # The same keywords are refused by Scenario and metrics alike.
    with pytest.raises(handling.InputError, match=key.replace(".", r"\.")):
        handling.Scenario(**sedan_step(root, **changes))
    with pytest.raises(handling.InputError, match=key.replace(".", r"\.")):
        handling.metrics(**sedan_step(root, **changes))


def test_a_missing_table_or_tyre_file_is_named(root, tmp_path):
    with pytest.raises(handling.InputError, match=r"the table `\[manoeuvre\]` is missing"):
        handling.simulate(vehicle=VEHICLE, tyres=root / "tyres" / "gim.toml")
    with pytest.raises(handling.InputError) as e:
        handling.simulate(**sedan_step(root, tyres=tmp_path / "none.toml"))
    assert e.value.path == str(tmp_path / "none.toml")
    with pytest.raises(TypeError):
        handling.simulate(root / "scenarios" / "sedan_step.toml", vehicle=VEHICLE)


def test_vehicle_checks_pickles_and_loads(root):
    v = handling.Vehicle(**VEHICLE)
    assert v.mass == 1530.0 and v.wheelbase == pytest.approx(2.78)
    assert pickle.loads(pickle.dumps(v)) == v
    assert handling.Vehicle.load(root / "scenarios" / "sedan_step.toml") == v
    assert handling.Vehicle.from_dict(v.to_dict()) == v
    with pytest.raises(handling.InputError) as e:
        handling.Vehicle(**dict(VEHICLE, cg_height=-0.1))
    assert e.value.key == "cg_height" and e.value.value == -0.1
    with pytest.raises(handling.InputError) as e:
        handling.Vehicle(**dict(VEHICLE, b=1.67), wheelbase=3.0)
    assert e.value.key == "wheelbase" and e.value.value == 3.0


def test_scenario_pickles_whole_and_compares_by_value(root):
    sc = handling.Scenario(**sedan_step(root))
    again = pickle.loads(pickle.dumps(sc))
    assert again == sc and again.to_toml() == sc.to_toml()
    same_run(handling.simulate(sc, pandas=False), handling.simulate(again, pandas=False))
    other = sc.replace(manoeuvre=dict(STEP, speed=20.0))
    assert other != sc and other.name == "sedan_step"


def test_metrics_of_a_non_step_manoeuvre_is_refused(root):
    sine = dict(kind="sine", speed=20.0, amplitude=0.02, frequency=0.5, start=1.0, end=4.0)
    with pytest.raises(handling.OptionsError, match="not a step steer"):
        handling.metrics(**sedan_step(root, manoeuvre=sine))
