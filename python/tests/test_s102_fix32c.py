"""What a user trips on in the Python package: `EquilibriaSummary` had no
`critical_speed_closed_form`, `box` nor `pso` attribute, though
`.to_dict()` (summary.json) holds each; an oversteering car's critical
speed could be read only from the dict."""

import math

import handling

LINEAR = 'model = "linear"\ncornering_stiffness = 57296.0\npneumatic_trail = 0.03\n'

# The round's eq_over.toml: the sedan with a and b swapped (oversteer).
EQ_OVER = """name = "eq_over"
[vehicle]
mass = 1530.0
yaw_inertia = 2315.0
a = 1.67
b = 1.11
track_front = 1.55
track_rear = 1.55
cg_height = 0.55
[tyres]
front = "lin.toml"
[model]
kinematics = "small-angle"
load_transfer = false
[sweep]
steer = { values = [0.5, 1.0, 2.0], unit = "deg" }
friction = 1.0
speed = { from = 20.0, to = 44.0, step = 4.0 }
[pso]
seed = 1
"""


def test_equilibria_summary_has_the_critical_speed_box_and_pso_as_attributes(tmp_path):
    (tmp_path / "lin.toml").write_text(LINEAR)
    (tmp_path / "eq_over.toml").write_text(EQ_OVER)
    e = handling.equilibria(tmp_path / "eq_over.toml")
    s = e.summary
    d = s.to_dict()
    # sqrt(-l/K), K = m/l (b/Cf - a/Cr), Cf = Cr = 2 x 57296 N/rad.
    m, a, b, c = 1530.0, 1.67, 1.11, 2 * 57296.0
    l = a + b
    k = m / l * (b / c - a / c)
    assert math.isclose(s.critical_speed_closed_form, math.sqrt(-l / k), rel_tol=1e-12)
    assert s.critical_speed_closed_form == d["critical_speed_closed_form"]
    assert s.box == d["box"] and s.box["beta_max"] == 0.6
    assert s.pso == d["pso"] and s.pso["seed"] == 1


def test_an_understeering_car_has_no_critical_speed(root):
    e = handling.equilibria(root / "scenarios" / "equilibria_steer.toml")
    assert e.summary.critical_speed_closed_form is None
    assert set(e.summary.box) == {"beta_max", "yaw_rate_max"}
