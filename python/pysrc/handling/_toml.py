"""TOML text written from keyword arguments, one key per line, with the
keyword and value of every line: the library reads the text as it reads a
file (same parser, same checks), and an error it locates at a line is
turned back into the keyword that wrote that line."""

from __future__ import annotations

import json
import math
import os
import re
from typing import Any, List, Mapping, Optional, Tuple

import numpy as np

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(k: Any) -> str:
    if not isinstance(k, str):
        raise TypeError(f"keyword keys must be strings, not {type(k).__name__} ({k!r})")
    return k if _BARE.match(k) else _string(k)


def _string(s: str) -> str:
    # JSON's escapes (\", \\, \n, \t, \uXXXX for other control characters)
    # are TOML's; TOML also wants DEL escaped.
    return json.dumps(s, ensure_ascii=False).replace("\x7f", "\\u007f")


def value(v: Any) -> str:
    """A TOML value: numbers exactly (Python's shortest round-trip repr,
    which the TOML reader parses back to the same float), strings, paths,
    booleans, arrays and inline tables."""
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        x = float(v)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, os.PathLike):
        return _string(os.fspath(v))
    if isinstance(v, Mapping):
        return "{ " + ", ".join(f"{_key(k)} = {value(x)}" for k, x in v.items()) + " }"
    if isinstance(v, np.ndarray):
        v = v.tolist()
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(value(x) for x in v) + "]"
    raise TypeError(f"no TOML value for {type(v).__name__} ({v!r})")


class Document:
    """A TOML document built key by key; ``keys[i]`` is the (dotted
    keyword, value) that wrote line ``i + 1``."""

    def __init__(self) -> None:
        self.lines: List[str] = []
        self.keys: List[Tuple[Optional[str], Any]] = []

    def _line(self, text: str, key: Optional[str], v: Any) -> None:
        self.lines.append(text)
        self.keys.append((key, v))

    def entry(self, dotted: str, k: str, v: Any) -> None:
        """``k = v`` (``dotted``: the keyword's full name)."""
        try:
            self._line(f"{_key(k)} = {value(v)}", dotted, v)
        except TypeError as e:
            raise TypeError(f"keyword `{dotted}`: {e}") from None

    def table(self, path: List[str], d: Mapping[str, Any]) -> None:
        """The table ``[a.b]`` (``path`` ``["a", "b"]``) with ``d``'s
        entries, its sub-tables after them."""
        dotted = ".".join(path)
        self._line(f"[{'.'.join(_key(p) for p in path)}]", dotted, d)
        subs = []
        for k, v in d.items():
            if isinstance(v, Mapping):
                subs.append((k, v))
            else:
                self.entry(f"{dotted}.{k}", k, v)
        for k, v in subs:
            self.table(path + [k], v)

    def text(self) -> str:
        return "\n".join(self.lines) + "\n"

    def at(self, line: Optional[int]) -> Tuple[Optional[str], Any]:
        """The keyword and value of a 1-based line (None: none)."""
        if line is None or not 1 <= line <= len(self.keys):
            return None, None
        return self.keys[line - 1]
