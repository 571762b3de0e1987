import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture
def root() -> pathlib.Path:
    """The repository root (scenarios/, tyres/, tests/fixtures/)."""
    return ROOT


def coarse_study(tmp_path: pathlib.Path) -> pathlib.Path:
    """scenarios/sedan_study.toml on a coarse 4 x 3 map, no RBF or inverse."""
    text = (ROOT / "scenarios" / "sedan_study.toml").read_text()
    head = text.split("[stiffness]")[0]
    head = head.replace('"../tyres/', f'"{(ROOT / "tyres").as_posix()}/')
    head = head.replace('name = "sedan_study"', 'name = "coarse_study"')
    body = (
        '[stiffness]\nunit = "N/deg"\n'
        "front = { from = 300.0, to = 600.0, step = 100.0 }\n"
        "rear = { from = 400.0, to = 600.0, step = 100.0 }\n"
    )
    p = tmp_path / "coarse_study.toml"
    p.write_text(head + body)
    return p
