"""Chooses which `attiguard` package the tests import (docs/python.md, "Tests").

- By default, the package of a CMake build: BUILD/python/attiguard (the extension _core, the
  copied pure-Python files and attiguard.plot), BUILD being $ATTIGUARD_BUILD_DIR when set, else
  build/ at the repository root (scripts/build.sh). It is put first on sys.path, ahead of any
  other attiguard.
- With ATTIGUARD_TEST_INSTALLED=1, the installed package (scripts/test_python_install.sh:
  `pip install .` into a venv): sys.path is left alone, and the session stops at once if the
  attiguard it imports is not in the interpreter's site-packages (i.e. is not the installed
  one, e.g. python/package found through the current directory).
"""

from __future__ import annotations

import os
import sys
import sysconfig
from pathlib import Path

import pytest

REPO_DIR = Path(__file__).resolve().parents[2]
BUILD_DIR = Path(os.environ.get("ATTIGUARD_BUILD_DIR", REPO_DIR / "build")).resolve()
INSTALLED = os.environ.get("ATTIGUARD_TEST_INSTALLED") == "1"

if not INSTALLED:
    build_python = str(BUILD_DIR / "python")
    while build_python in sys.path:
        sys.path.remove(build_python)
    sys.path.insert(0, build_python)


def package_parent() -> Path:
    """The directory holding the attiguard package under test (for a child's PYTHONPATH)."""
    import attiguard

    return Path(attiguard.__file__).resolve().parent.parent


def pytest_configure(config: pytest.Config) -> None:
    try:
        import attiguard
    except ImportError as e:
        raise pytest.UsageError(f"cannot import attiguard: {e}") from e

    where = Path(attiguard.__file__).resolve()
    site = {Path(sysconfig.get_paths()[k]).resolve() for k in ("purelib", "platlib")}
    if INSTALLED and not any(where.is_relative_to(s) for s in site):
        raise pytest.UsageError(
            f"ATTIGUARD_TEST_INSTALLED=1 but attiguard is imported from {where}, not from the "
            f"site-packages of {sys.executable}: run pytest from outside the source tree")
    if not INSTALLED and not where.is_relative_to(BUILD_DIR):
        raise pytest.UsageError(
            f"attiguard is imported from {where}, not from the build {BUILD_DIR}/python "
            f"(build it first: bash scripts/build.sh, or set ATTIGUARD_BUILD_DIR)")
