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
    """A value a TOML scenario cannot hold (None, NaN, ±inf, an unsupported type, a cycle, a nesting
    deeper than MAX_DEPTH)."""


# The limits of a scenario dict, as attiguard.run(dict) (python/src/bind_run.cpp; docs/python.md,
# "Validation"): tables and arrays nested at most this deep, and no value containing itself.
MAX_DEPTH = 64
# At most this many tables and arrays in all (a tree sharing its sub-lists, x = [x0, x0] nested,
# is refused instead of being written out 2^depth times).
MAX_CONTAINERS = 1_000_000


class _Open(list):
    """The tables/arrays being written (innermost last) and how many were entered in all."""
    entered = 0


def _enter(v: Any, where: str, open_: list) -> None:
    """The depth and cycle check on entering the table or array v at `where`."""
    open_.entered += 1
    if open_.entered > MAX_CONTAINERS:
        raise TomlValueError(f"{where or 'scenario'}: more than {MAX_CONTAINERS} tables/arrays: "
                             f"beyond the limit of a scenario dict (docs/python.md, \"Validation\")")
    if len(open_) >= MAX_DEPTH:
        raise TomlValueError(f"{where or 'scenario'}: nested deeper than {MAX_DEPTH} tables/arrays: "
                             f"beyond the limit of a scenario dict (docs/python.md, \"Validation\")")
    for obj, at in open_:
        if obj is v:
            target = f"its enclosing value {at}" if at else "the scenario dict itself"
            raise TomlValueError(f"{where}: refers back to {target} (a cycle): a scenario is a "
                                 f"tree of tables and arrays")


def _is_table(v: Any) -> bool:
    return isinstance(v, Mapping)


def _is_table_array(v: Any) -> bool:
    return isinstance(v, (list, tuple)) and len(v) > 0 and all(_is_table(x) for x in v)


def _key(k: Any) -> str:
    k = str(k)
    if k and all(c.isalnum() or c in "_-" for c in k):
        return k
    return json.dumps(k)


def _value(v: Any, where: str, open_: list) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        if not -2**63 <= v < 2**63:  # TOML integers are 64-bit
            raise TomlValueError(f"{where}: integer {str(v)[:40]} is beyond the 64-bit range of a scenario integer")
        return str(v)
    if isinstance(v, float):
        if not math.isfinite(v):  # a scenario file refuses nan and inf: say so here, by key
            raise TomlValueError(f"{where}: must be finite, got {v!r} (a scenario value cannot be nan or inf)")
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)  # JSON basic-string escapes are valid TOML escapes
    if hasattr(v, "tolist"):  # numpy arrays and scalars
        return _value(v.tolist(), where, open_)
    if isinstance(v, (list, tuple)) or _is_table(v):
        _enter(v, where, open_)
        open_.append((v, where))
        if _is_table(v):
            text = "{ " + ", ".join(f"{_key(k)} = {_value(x, where + '.' + str(k), open_)}"
                                    for k, x in v.items()) + " }"
        else:
            text = "[" + ", ".join(_value(x, f"{where}[{i}]", open_) for i, x in enumerate(v)) + "]"
        open_.pop()
        return text
    raise TomlValueError(f"{where}: a scenario value cannot be {type(v).__name__}")


def _table(out: list[str], table: Mapping, path: list[str], open_: list) -> None:
    where = ".".join(path)
    _enter(table, where, open_)
    open_.append((table, where))
    # Plain key/values first, then sub-tables and arrays of tables (TOML's ordering rule).
    for k, v in table.items():
        if not _is_table(v) and not _is_table_array(v):
            out.append(f"{_key(k)} = {_value(v, '.'.join(path + [str(k)]), open_)}")
    for k, v in table.items():
        sub = path + [_key(k)]
        if _is_table(v):
            out.append("")
            out.append(f"[{'.'.join(sub)}]")
            _table(out, v, sub, open_)
        elif _is_table_array(v):
            _enter(v, ".".join(sub), open_)
            open_.append((v, ".".join(sub)))
            for item in v:
                out.append("")
                out.append(f"[[{'.'.join(sub)}]]")
                _table(out, item, sub, open_)
            open_.pop()
    open_.pop()


def dumps(scenario: Mapping) -> str:
    """TOML text of a scenario dict."""
    if not _is_table(scenario):
        raise TomlValueError(f"a scenario must be a dict, got {type(scenario).__name__}")
    out: list[str] = []
    _table(out, scenario, [], _Open())
    return "\n".join(out) + "\n"
