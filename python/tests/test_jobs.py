import json

import numpy as np
import pytest

import handling
from conftest import coarse_study


def test_simulate_returns_arrays_and_the_cli_metrics(root, tmp_path):
    r = handling.simulate(root / "scenarios" / "sedan_step.toml", out=tmp_path, pandas=False)
    h = r.history
    for c in ("t", "steer", "speed", "beta", "yaw_rate", "ay", "fz_fl"):
        assert isinstance(h[c], np.ndarray) and h[c].dtype == np.float64
        assert len(h[c]) == len(h["t"])
    assert h["t"][-1] == pytest.approx(6.0)
    m = r.metrics
    assert isinstance(m, handling.StepMetrics)
    written = json.loads((tmp_path / "metrics.json").read_text())
    for k, v in m.to_dict().items():
        assert written[k] == v, k
    assert (tmp_path / "response.png").exists()
    csv = np.genfromtxt(tmp_path / "history.csv", delimiter=",", names=True)
    assert list(csv.dtype.names) == list(h)
    # history.csv carries nine significant digits (an integration to 1e-9):
    # each value to within half a unit of its ninth.
    for c in h:
        assert np.allclose(csv[c], h[c], rtol=1e-8, atol=0), c
    # README example: 16.90 % overshoot, 3.7096 1/s gain.
    assert m.yaw_rate_overshoot == pytest.approx(16.90, abs=0.01)
    assert m.yaw_rate_gain == pytest.approx(3.7096, abs=1e-4)


def test_simulate_dataframe_when_pandas_present(root):
    pd = pytest.importorskip("pandas")
    r = handling.simulate(root / "scenarios" / "sedan_step.toml")
    assert isinstance(r.history, pd.DataFrame)


def test_min_overshoot_decides_whether_a_flat_maximum_is_a_peak(root, tmp_path):
    # The bundled UniTire step overshoots by about 0.1 %: no peak by default
    # (1 %), a peak with its TB when any maximum counts, simulated or measured.
    sc = handling.Scenario.load(root / "scenarios" / "step_gbt6323_unitire.toml")
    default = handling.metrics(sc)
    assert default.yaw_rate_peak_time is None and default.tb is None
    assert default.yaw_rate_peak_threshold == 1.0
    anything = handling.metrics(sc, min_overshoot=0)
    assert 0.05 < anything.yaw_rate_overshoot < 0.5 and anything.tb > 0.1
    h = handling.simulate(sc, out=tmp_path / "sim", pandas=False)
    run = tmp_path / "sim" / "history.csv"
    assert handling.metrics(run).metrics.yaw_rate_peak_time is None
    rows = handling.metrics(run, filter_hz=0, min_overshoot=0).metrics
    assert rows.yaw_rate_peak_time == pytest.approx(anything.yaw_rate_peak_time, abs=0.01)
    assert h.metrics == default


def test_metrics_of_a_measured_run(root, tmp_path):
    h = handling.simulate(root / "scenarios" / "sedan_step.toml", pandas=False).history
    cols = ["t", "steer", "speed", "yaw_rate", "ay"]
    rows = np.column_stack([h[c] for c in cols])[::10]
    p = tmp_path / "run.csv"
    np.savetxt(p, rows, delimiter=",", header=",".join(cols), comments="", fmt="%.17g")
    r = handling.metrics(p)
    assert r.metrics.yaw_rate_gain == pytest.approx(3.71, rel=0.02)
    assert "cleaning" in r.to_dict() and r.cleaning == r.to_dict()["cleaning"]


def test_scenario_error_is_located(root, tmp_path):
    text = (root / "scenarios" / "sedan_step.toml").read_text()
    text = text.replace("mass = 1530.0", "mass = -1530.0").replace('"../tyres/', f'"{root}/tyres/')
    p = tmp_path / "bad.toml"
    p.write_text(text)
    with pytest.raises(handling.InputError) as e:
        handling.simulate(p)
    assert e.value.path == str(p) and e.value.line == text.splitlines().index("mass = -1530.0") + 1
    assert "mass" in str(e.value)


def test_equilibria_report_is_summary_json(root, tmp_path):
    r = handling.equilibria(root / "scenarios" / "equilibria_steer.toml", out=tmp_path)
    written = json.loads((tmp_path / "summary.json").read_text())
    assert r.summary.to_dict() == written
    assert r.summary.agreement_percent == 100.0 and r.summary.conditions == written["conditions"]


def test_study_shards_on_three_merge_to_the_unsharded_run(tmp_path):
    p = coarse_study(tmp_path)
    whole = handling.study(p, out=tmp_path / "whole")
    assert len(whole.samples) == 12
    for k in (1, 2, 3):
        handling.run_shard("study", p, k, 3, out=tmp_path / "shards")
    merged = handling.merge(sorted((tmp_path / "shards").glob("shard-*-of-3.json")), out=tmp_path / "merged")
    assert merged["summary"] == whole.summary
    for f in ("study.csv", "summary.json"):
        assert (tmp_path / "merged" / f).read_bytes() == (tmp_path / "whole" / f).read_bytes()
    with pytest.raises(handling.OptionsError):
        handling.run_shard("study", p, 4, 3)


def test_study_object_evaluates_the_map(tmp_path):
    p = coarse_study(tmp_path)
    st = handling.Study.load(p)
    grid = st.grid()
    samples = st.evaluate(front_n_per_rad=[g[0] for g in grid], rear_n_per_rad=[g[1] for g in grid])
    assert samples == handling.study(p).samples


def test_identify_gim_recovers_its_tyre(root, tmp_path):
    t = handling.Tyre.load(root / "tyres" / "gim.toml")
    fz = np.repeat([2000.0, 4000.0, 6000.0], 41)
    a = np.tile(np.radians(np.linspace(-12, 12, 41)), 3)
    fy = t.forces(fz, 0.0, a)["fy"]
    p = tmp_path / "rig.csv"
    np.savetxt(p, np.column_stack([fz, a, fy]), delimiter=",", header="fz,alpha,fy", comments="", fmt="%.17g")
    r = handling.identify(p, "gim", seed=1, out=tmp_path / "fit.toml")
    assert isinstance(r.tyre, handling.Tyre) and r.tyre.model == "gim"
    assert (tmp_path / "fit.toml").exists()
    fit = r.tyre.forces(fz, 0.0, a)["fy"]
    assert np.max(np.abs(fit - fy)) < 0.01 * np.max(np.abs(fy))
    with pytest.raises(handling.OptionsError) as e:
        handling.identify(p, "pac2002")
    assert e.value.kind == "options" and e.value.what == "tyre model"
    assert e.value.name == "pac2002" and "gim" in e.value.known
    assert isinstance(e.value, handling.HandlingError)


def test_identify_holds_a_parameter_at_the_value_given(root, tmp_path):
    t = handling.Tyre.load(root / "tyres" / "gim.toml")
    fz = np.repeat([2000.0, 4000.0, 6000.0], 41)
    a = np.tile(np.radians(np.linspace(-12, 12, 41)), 3)
    fy = t.forces(fz, 0.0, a)["fy"]
    p = tmp_path / "rig.csv"
    np.savetxt(p, np.column_stack([fz, a, fy]), delimiter=",", header="fz,alpha,fy", comments="", fmt="%.17g")
    free = handling.identify(p, "pac89", seed=1).to_dict()
    a1 = next(q for q in free["parameters"] if q["name"] == "a1")
    # Fitted, or held at the model's start value by the rule that holds
    # what the data do not determine: never at the value given below.
    why = (a1.get("held") or {}).get("why")
    assert a1["value"] != -20.0 and (a1["free"] or why == "undetermined"), a1
    held = handling.identify(p, "pac89", seed=1, hold={"a1": -20.0}).to_dict()
    a1 = next(q for q in held["parameters"] if q["name"] == "a1")
    assert (a1["value"], a1["free"]) == (-20.0, False)
    assert "two_stage" not in held
    with pytest.raises(handling.OptionsError) as e:
        handling.identify(p, "pac89", hold={"A1": 1.0})
    assert (e.value.name, e.value.what) == ("A1", "pac89 parameter")
    assert "a1" in e.value.known and "did you mean `a1`" in str(e.value)


def test_pac89_on_one_load_is_a_fit_error_naming_the_data(root, tmp_path):
    t = handling.Tyre.load(root / "tyres" / "gim.toml")
    a = np.radians(np.linspace(-12, 12, 41))
    fz = np.full_like(a, 4000.0)
    fy = t.forces(fz, 0.0, a)["fy"]
    p = tmp_path / "one_load.csv"
    np.savetxt(p, np.column_stack([fz, a, fy]), delimiter=",", header="fz,alpha,fy", comments="", fmt="%.17g")
    with pytest.raises(handling.FitError) as e:
        handling.identify(p, "pac89", seed=1)
    assert e.value.kind == "fit" and e.value.path == str(p)


def test_a_text_cell_in_rig_data_is_an_input_error_naming_column_and_cell(tmp_path):
    p = tmp_path / "rig.csv"
    p.write_text("fz,alpha,fy\n4000,0.01,-900\n4000,abc,-1800\n")
    with pytest.raises(handling.InputError) as e:
        handling.identify(p, "gim", seed=1)
    assert (e.value.path, e.value.line, e.value.column) == (str(p), 3, 2)
    assert (e.value.key, e.value.value) == ("alpha", "abc")


def test_diagnose_missing_campaign_is_input_error(tmp_path):
    with pytest.raises(handling.InputError) as e:
        handling.diagnose(tmp_path / "nothing")
    assert e.value.kind == "input" and str(tmp_path / "nothing") in e.value.path


def test_synth_writes_a_campaign(tmp_path):
    r = handling.synth(tmp_path / "c", ["relaxation_length"], seed=3)
    assert r["runs"] > 0 and (tmp_path / "c" / "vehicle.toml").exists()


def test_synth_drives_the_oval_with_ax_and_bank_channels(tmp_path):
    r = handling.synth(tmp_path / "o", ["bank_profile"], seed=2, programme="oval")
    assert r["programme"] == "oval" and r["runs"] == 3
    header = (tmp_path / "o" / "runs" / "oval_stop_on_banking.csv").read_text().splitlines()[0]
    assert header == "t,speed,steer,yaw_rate,ay,ax,bank"
    with pytest.raises(handling.OptionsError, match="unknown programme `ovals`") as e:
        handling.synth(tmp_path / "x", [], programme="ovals")
    assert e.value.what == "programme" and e.value.name == "ovals" and "oval" in e.value.known
    with pytest.raises(handling.OutputError) as e:
        handling.synth(tmp_path / "o", [], seed=2, programme="oval")
    assert e.value.kind == "output" and e.value.path == str(tmp_path / "o")


def test_design_separates_the_delays_a_diagnosis_confounds_and_drives_its_best(tmp_path):
    handling.synth(tmp_path / "c", ["sensor_delay"], seed=1)
    v = tmp_path / "c" / "vehicle.toml"
    v.write_text(v.read_text() + 'effects = ["sensor_delay", "steer_path"]\n')
    d = handling.diagnose(tmp_path / "c", out=tmp_path / "d")
    assert d.to_dict()["confounded"][0]["effects"] == ["sensor_delay", "steer_path"]
    r = handling.design(tmp_path / "d")
    best = r["sets"][0]["ranked"][0]
    assert best["kind"] in ("brake_in_turn", "accelerate_in_turn", "constant_radius")
    assert best["separation"] > 1.5 * r["sets"][0]["campaign_separation"]
    scenario = tmp_path / "d" / "design" / "scenarios" / (best["name"] + ".toml")
    s = handling.synth(tmp_path / "c2", ["sensor_delay"], seed=1, drive=[scenario])
    assert s["runs"] == 9 and s["driven"] == 1
    m = handling.design(
        tmp_path / "d", measured=[tmp_path / "c2" / "runs" / (best["name"] + ".csv")], out=tmp_path / "m"
    )
    assert m["measured"][0]["favours"] in ("sensor_delay", "steer_path")
    with pytest.raises(handling.DiagnosisError, match="did not fit `yaw_inertia`"):
        handling.design(tmp_path / "d", effects=["sensor_delay", "yaw_inertia"], out=tmp_path / "x")
    # Options no design can honour are refused by the library, as on the
    # command line (max_ax=0 once replayed an empty schedule and panicked).
    with pytest.raises(handling.ParamError, match=r"`max_ax` = 0: must lie in \(0, 15\]"):
        handling.design(tmp_path / "d", max_ax=0.0, out=tmp_path / "y")
    with pytest.raises(handling.ParamError, match="`top` = 0"):
        handling.design(tmp_path / "d", top=0, out=tmp_path / "y")


def test_a_unit_slip_is_an_input_error_naming_its_column_and_value(tmp_path):
    # One load written in kN among loads in N, and a pressure column all
    # in kPa: typed as unit slips, whose column and value the exception
    # carries as any other input error's.
    rows = ["fz,alpha,fy,pressure"]
    for i in range(41):
        a = -0.1 + 0.005 * i
        fz = "2.5" if i == 20 else "2500"
        rows.append(f"{fz},{a:.4f},{60000.0 * a:.2f},220000")
    p = tmp_path / "rig.csv"
    p.write_text("\n".join(rows) + "\n")
    with pytest.raises(handling.InputError) as e:
        handling.identify(p, "linear", seed=1)
    assert (e.value.path, e.value.line, e.value.column) == (str(p), 22, 1)
    assert (e.value.key, e.value.value) == ("fz", 2.5)
    assert e.value.problem is not None and "kN" in e.value.reason
    p.write_text("\n".join(r.replace(",220000", ",220") for r in rows).replace("2.5,", "2500,") + "\n")
    with pytest.raises(handling.InputError) as e:
        handling.identify(p, "linear", seed=1)
    assert (e.value.key, e.value.value) == ("pressure", 220.0)
    assert "220000 Pa" in e.value.reason
