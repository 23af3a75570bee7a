"""The type stub attiguard/_core.pyi against the compiled module attiguard._core.

The stub must name exactly what the module exports (module-level names, and each class's own
methods and properties, __init__ included), with the same parameter names and the same
parameters having defaults as pybind11's signature line (the first line of each docstring).
With mypy installed (python3-mypy), mypy.stubtest checks the stub too, and mypy sees the real
signatures through py.typed (a wrong call is a type error).
"""

from __future__ import annotations

import ast
import importlib.util
import inspect
import os
import re
import subprocess
import sys
import types
from pathlib import Path

import pytest

import attiguard
from attiguard import _core

PACKAGE = Path(attiguard.__file__).resolve().parent
STUB = PACKAGE / "_core.pyi"
HAVE_MYPY = importlib.util.find_spec("mypy") is not None


# ---- the stub, parsed ---------------------------------------------------------------------------

def _stub_tree(path: Path) -> ast.Module:
    return ast.parse(path.read_text(), filename=str(path))


def _is_property(node: ast.FunctionDef) -> bool:
    return any(isinstance(d, ast.Name) and d.id == "property" for d in node.decorator_list)


def _params(node: ast.FunctionDef) -> list[tuple[str, bool]]:
    """(name, has default) of each parameter but self."""
    args = node.args.posonlyargs + node.args.args
    defaults = [False] * (len(args) - len(node.args.defaults)) + [True] * len(node.args.defaults)
    out = [(a.arg, d) for a, d in zip(args, defaults)]
    if node.args.kwonlyargs:  # pybind11's signature line shows the bare "*" too
        out.append(("*", False))
    out += [(a.arg, d is not None) for a, d in zip(node.args.kwonlyargs, node.args.kw_defaults)]
    return out[1:] if out and out[0][0] == "self" else out


def _stub_module_names(path: Path = STUB) -> dict[str, ast.AST]:
    names: dict[str, ast.AST] = {}
    for node in _stub_tree(path).body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names[node.name] = node
    return {n: v for n, v in names.items() if not n.startswith("__")}


def _stub_class_members(cls: ast.ClassDef) -> dict[str, ast.AST]:
    members: dict[str, ast.AST] = {}
    for node in cls.body:
        if isinstance(node, ast.FunctionDef):
            members[node.name] = node
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            members[node.target.id] = node
    return members


# ---- the compiled module, introspected ----------------------------------------------------------

def _runtime_module_names() -> dict[str, object]:
    return {n: getattr(_core, n) for n in dir(_core) if not n.startswith("__")}


def _has_constructor(cls: type) -> bool:
    """Whether the bindings give the class a constructor (py::init): pybind11 copies the slot
    wrapper of its base's __init__ (which raises "No constructor defined") into every class."""
    init = vars(cls).get("__init__")
    return init is not None and not isinstance(init, types.WrapperDescriptorType)


def _runtime_class_members(cls: type) -> dict[str, object]:
    """The class's own public members, and __init__ when the bindings define a constructor."""
    members = {n: v for n, v in vars(cls).items() if not n.startswith("_")}
    if _has_constructor(cls):
        members["__init__"] = vars(cls)["__init__"]
    return members


def _split_top_level(text: str) -> list[str]:
    """Splits `a: T[1, 2], b: U = 3` at the commas outside brackets and quotes."""
    parts, depth, quote, start = [], 0, "", 0
    for i, ch in enumerate(text):
        if quote:
            quote = "" if ch == quote else quote
        elif ch in "'\"":
            quote = ch
        elif ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    if text[start:].strip():
        parts.append(text[start:])
    return [p.strip() for p in parts]


def _runtime_params(obj: object, name: str) -> list[tuple[str, bool]]:
    """(name, has default) of each parameter but self, from pybind11's signature line."""
    doc = inspect.getdoc(obj) or ""
    first = doc.splitlines()[0] if doc else ""
    match = re.match(rf"{re.escape(name)}\((.*)\)\s*->", first)
    assert match, f"{name}: no pybind11 signature line in its docstring: {first!r}"
    params = []
    for part in _split_top_level(match.group(1)):
        pname = part.split(":", 1)[0].strip()
        params.append((pname, " = " in part))
    return params[1:] if params and params[0][0] == "self" else params


# ---- the tests ----------------------------------------------------------------------------------

def test_stub_and_marker_are_shipped_next_to_the_module():
    assert STUB.is_file()
    assert (PACKAGE / "py.typed").is_file()


def test_stub_names_exactly_the_module_exports():
    stub, runtime = set(_stub_module_names()), set(_runtime_module_names())
    assert sorted(runtime - stub) == [], "exported by _core but missing from _core.pyi"
    assert sorted(stub - runtime) == [], "declared in _core.pyi but not exported by _core"


@pytest.mark.parametrize("name", sorted(n for n, v in _runtime_module_names().items()
                                        if isinstance(v, type)))
def test_stub_class_names_exactly_the_class_members(name):
    stub_cls = _stub_module_names()[name]
    assert isinstance(stub_cls, ast.ClassDef), f"{name} is a class in _core, not in the stub"
    runtime_cls = getattr(_core, name)
    stub, runtime = _stub_class_members(stub_cls), _runtime_class_members(runtime_cls)
    assert sorted(set(runtime) - set(stub)) == [], f"{name}: members missing from the stub"
    assert sorted(set(stub) - set(runtime)) == [], f"{name}: stub members _core does not have"
    for member, node in stub.items():
        value = vars(runtime_cls)[member]
        if isinstance(value, staticmethod):  # e.g. Governor.from_scenario
            value = value.__func__
        if isinstance(node, ast.FunctionDef) and _is_property(node):
            assert isinstance(value, property), f"{name}.{member} is not a property"
        elif isinstance(node, ast.FunctionDef):
            assert callable(value), f"{name}.{member} is not a method"
            assert _params(node) == _runtime_params(value, member), f"{name}.{member}"
        else:
            assert not callable(value), f"{name}.{member} is callable, the stub says data"


@pytest.mark.parametrize("name", sorted(n for n, v in _runtime_module_names().items()
                                        if not isinstance(v, type)))
def test_stub_function_parameters_match(name):
    node = _stub_module_names()[name]
    assert isinstance(node, ast.FunctionDef), f"{name} is a function in _core, not in the stub"
    assert _params(node) == _runtime_params(getattr(_core, name), name)


def test_the_comparison_catches_a_renamed_function_and_parameter(tmp_path):
    # The tests above fail when the stub drifts: shown on a stub with one function renamed and
    # one parameter renamed.
    edited = tmp_path / "_core.pyi"
    edited.write_text(STUB.read_text().replace("def phi(", "def phi_renamed(")
                      .replace("def hat(x:", "def hat(v:"))
    stub, runtime = set(_stub_module_names(edited)), set(_runtime_module_names())
    assert runtime - stub == {"phi"} and stub - runtime == {"phi_renamed"}
    hat = _stub_module_names(edited)["hat"]
    assert isinstance(hat, ast.FunctionDef)
    assert _params(hat) != _runtime_params(_core.hat, "hat")


def _mypy_env() -> dict[str, str]:
    # mypy finds attiguard where this interpreter does (the build tree or site-packages).
    return dict(os.environ, MYPYPATH="", PYTHONPATH=str(PACKAGE.parent))


def _pybind11_artifacts() -> list[str]:
    """What stubtest reports on any pybind11 class and a stub cannot express: the metaclass
    pybind11_type, and the inherited __init__ (raising "No constructor defined") of a class
    the bindings give no constructor."""
    entries = []
    for name, value in _runtime_module_names().items():
        if isinstance(value, type) and type(value).__name__ == "pybind11_type":
            entries.append(f"attiguard._core.{name}")
            if not _has_constructor(value):
                entries.append(f"attiguard._core.{name}.__init__")
    return entries


@pytest.mark.skipif(not HAVE_MYPY, reason="mypy is not installed (apt-get install python3-mypy)")
def test_mypy_stubtest_accepts_the_stub(tmp_path):
    allowlist = tmp_path / "allowlist.txt"
    allowlist.write_text("\n".join(_pybind11_artifacts()) + "\n")
    r = subprocess.run([sys.executable, "-m", "mypy.stubtest", "attiguard._core",
                        "--allowlist", str(allowlist)],
                       capture_output=True, text=True, env=_mypy_env(), cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr


@pytest.mark.skipif(not HAVE_MYPY, reason="mypy is not installed (apt-get install python3-mypy)")
def test_mypy_sees_the_real_signatures(tmp_path):
    (tmp_path / "good.py").write_text(
        "import numpy as np\nimport attiguard\n"
        "R = attiguard.expm([0.0, 0.0, 1.0])\n"
        "d: float = attiguard.distance(R, np.eye(3))\n"
        "gov = attiguard.Governor(np.eye(3), kp=5.0, kd=1.0, tau_max=2.5)\n"
        "m: float = gov.step(0.0, R, np.zeros(3), R).min_margin\n"
        "result: attiguard.RunResult = attiguard.run('x.toml')\n")
    (tmp_path / "bad.py").write_text(
        "import attiguard\nattiguard.Governor([[1.0]], kp='five', kd=1.0, tau_max=1.0)\n"
        "x: str = attiguard.phi([[1.0]])\n")
    (tmp_path / "mypy.ini").write_text("[mypy]\n")
    r = subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", "--follow-imports=silent",
                        "--config-file", "mypy.ini", "good.py", "bad.py"],
                       capture_output=True, text=True, env=_mypy_env(), cwd=tmp_path)
    errors = [line for line in r.stdout.splitlines() if ": error:" in line]
    assert r.returncode == 1, r.stdout + r.stderr
    assert [e.split(":")[0:2] for e in errors] == [["bad.py", "2"], ["bad.py", "3"]], r.stdout
    assert 'Argument "kp" to "Governor" has incompatible type "str"' in errors[0]
    assert "Incompatible types in assignment" in errors[1]
