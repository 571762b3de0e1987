"""Python parity (session 110): `EquilibriaSummary` had no `misses` field
(the Rust summary's conditions where the swarm fell short were only in
`to_dict()`), and the settling verdicts' `rising` went unsaid."""

import json

import handling

from conftest import ROOT


def _scenario(tmp_path, name, text):
    text = text.replace('"../tyres/', f'"{(ROOT / "tyres").as_posix()}/')
    p = tmp_path / name
    p.write_text(text)
    return p


def test_equilibria_summary_names_the_conditions_where_the_swarm_fell_short(tmp_path):
    # With 4 particles and 2 rounds the swarm misses equilibria (the CLI's
    # `trips_s109_eqstudy41`): each such condition is a typed field.
    text = (ROOT / "scenarios" / "equilibria_steer.toml").read_text()
    text = text.replace("[pso]\nseed = 1\n", "[pso]\nseed = 1\nparticles = 4\nrounds = 2\n")
    e = handling.equilibria(_scenario(tmp_path, "sweep.toml", text), out=tmp_path / "e")
    written = json.loads((tmp_path / "e" / "summary.json").read_text())
    s = e.summary
    assert s.misses == written["misses"] == s.to_dict()["misses"]
    assert s.conditions - s.agreeing >= 1
    apart = [m for m in s.misses if m["exact_only"] or m["pso_only"]]
    assert len(apart) == s.conditions - s.agreeing
    for m in s.misses:
        assert set(m) >= {"condition", "index_sum", "winding_number", "certificate"}
    # Where the two agree, no condition is named.
    full = handling.equilibria(ROOT / "scenarios" / "equilibria_steer.toml", out=tmp_path / "f")
    assert full.summary.agreeing == full.summary.conditions and full.summary.misses == []


def test_a_drifting_verdict_says_whether_its_trend_rises(tmp_path):
    # Round 40's `s_ay9.toml`: the sliding car's ay falls across its
    # steady window, a drifting verdict whose trend does not rise.
    text = (ROOT / "scenarios" / "sedan_step.toml").read_text()
    head = text[: text.index("[manoeuvre]")]
    step = (
        '[manoeuvre]\nkind = "step-steer"\nspeed = 22.2222\n'
        "lateral_acceleration = 9.0\nstart = 1.0\nrise_time = 0.1\nend = 6.0\n"
    )
    p = _scenario(tmp_path, "s_ay9.toml", head + step)
    r = handling.simulate(p, out=tmp_path / "s", pandas=False)
    ay = r.metrics.settling["ay"]
    assert ay["verdict"] == "drifting" and ay["rising"] is False
    written = json.loads((tmp_path / "s" / "metrics.json").read_text())
    assert written["settling"]["ay"] == ay
