"""An error's message as Python says it (python/src/spelling.rs): the
library's messages name the command line's options, which a Python user
does not type; raised from Python they name the keyword instead. Only the
spelling of options changes; numbers and every other word stay.

These were the extension crate's own Rust unit test, which CI built a
second time, linked to libpython (`cargo test --manifest-path
python/Cargo.toml`): checked here through the built extension instead,
the same messages and the same expected words."""

import pytest

import handling

CASES = [
    # A quoted command: its option as a keyword, `degrees` as a list.
    (
        'a column in degrees is declared so: `metrics --degrees steer`, or `degrees = ["steer"]` under a campaign\'s [runs]',
        'a column in degrees is declared so: `degrees=["steer"]`, or `degrees = ["steer"]` under a campaign\'s [runs]',
    ),
    # Bare options outside quotes.
    (
        "fit a model that takes one load (gim), or, where --load selected it, drop --load",
        "fit a model that takes one load (gim), or, where `load=` selected it, drop `load=`",
    ),
    # Either value, each quoted.
    ("`identify --model mf61|mf62`", '`model="mf61"|"mf62"`'),
    # A number as it is; a flag alone as its keyword's name.
    ("`--camber 2` and `--hold`", "`camber=2` and `hold`"),
    # Not options: a range, a dash in words.
    ("from -1 to 2 -- nothing", "from -1 to 2 -- nothing"),
]


@pytest.mark.parametrize("message, said", CASES)
def test_options_are_spelt_as_keywords(message, said):
    assert handling._handling._pythonic(message) == said
