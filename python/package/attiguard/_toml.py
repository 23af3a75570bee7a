"""A dict -> TOML text writer for scenario dicts (the inverse of tomllib.loads for the values
scenarios use): tables, arrays of tables, strings, booleans, ints, floats, arrays.

attiguard.to_toml(dict) writes a dict scenario as a scenario file's text (to save it, or to run
it with the CLI); attiguard.run(dict) does not go through it: the dict goes to the C++ core value
by value.
"""

from __future__ import annotations

import json
import math
from typing import Any, Mapping


class TomlValueError(ValueError):
    """A value a TOML scenario cannot hold (None, NaN, an unsupported type)."""


def _is_table(v: Any) -> bool:
    return isinstance(v, Mapping)


def _is_table_array(v: Any) -> bool:
    return isinstance(v, (list, tuple)) and len(v) > 0 and all(_is_table(x) for x in v)


def _key(k: Any) -> str:
    k = str(k)
    if k and all(c.isalnum() or c in "_-" for c in k):
        return k
    return json.dumps(k)


def _value(v: Any, where: str) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"  # rejected by the C++ reader with a message naming the key
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)  # JSON basic-string escapes are valid TOML escapes
    if hasattr(v, "tolist"):  # numpy arrays and scalars
        return _value(v.tolist(), where)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_value(x, where) for x in v) + "]"
    if _is_table(v):
        return "{ " + ", ".join(f"{_key(k)} = {_value(x, where + '.' + str(k))}" for k, x in v.items()) + " }"
    raise TomlValueError(f"{where}: a scenario value cannot be {type(v).__name__}")


def _table(out: list[str], table: Mapping, path: list[str]) -> None:
    # Plain key/values first, then sub-tables and arrays of tables (TOML's ordering rule).
    for k, v in table.items():
        if not _is_table(v) and not _is_table_array(v):
            out.append(f"{_key(k)} = {_value(v, '.'.join(path + [str(k)]))}")
    for k, v in table.items():
        sub = path + [_key(k)]
        if _is_table(v):
            out.append("")
            out.append(f"[{'.'.join(sub)}]")
            _table(out, v, sub)
        elif _is_table_array(v):
            for item in v:
                out.append("")
                out.append(f"[[{'.'.join(sub)}]]")
                _table(out, item, sub)


def dumps(scenario: Mapping) -> str:
    """TOML text of a scenario dict."""
    if not _is_table(scenario):
        raise TomlValueError(f"a scenario must be a dict, got {type(scenario).__name__}")
    out: list[str] = []
    _table(out, scenario, [])
    return "\n".join(out) + "\n"
