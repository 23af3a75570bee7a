"""attiguard.run / check / reach: the `attiguard run`, `check` and `reach` commands from Python.

A scenario is a TOML file path (str or pathlib.Path) or a dict with the same structure as the
file (docs/scenario-format.md); a dict is written as TOML text (attiguard._toml.dumps) and
parsed by the same C++ reader as a file, so errors carry the same messages, with "<dict>" in
place of the file name.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any, Mapping, Union

from . import _core
from ._results import ReachResult, RunResult, balls_of, load_csv, load_json
from ._toml import dumps

Scenario = Union[str, os.PathLike, Mapping[str, Any]]

DICT_LABEL = "<dict>"


def _source(scenario: Scenario) -> tuple[str, bool, str]:
    """(source, is_text, label) for the C++ side."""
    if isinstance(scenario, Mapping):
        return dumps(scenario), True, DICT_LABEL
    if isinstance(scenario, (str, os.PathLike)):
        return os.fspath(scenario), False, os.fspath(scenario)
    raise TypeError(f"scenario must be a TOML file path or a dict, got {type(scenario).__name__}")


class _OutDir:
    """The output directory: the given one (kept), or a temporary one removed afterwards."""

    def __init__(self, out: str | os.PathLike | None):
        self.keep = out is not None
        self.path = Path(out) if out is not None else Path(tempfile.mkdtemp(prefix="attiguard-"))
        self.path.mkdir(parents=True, exist_ok=True)

    def __enter__(self) -> "_OutDir":
        return self

    def __exit__(self, *exc: object) -> None:
        if not self.keep:
            shutil.rmtree(self.path, ignore_errors=True)


def check(scenario: Scenario) -> str:
    """Parses and validates a scenario like `attiguard check`; returns its kind.
    Raises attiguard.InputError with the CLI's message when it is invalid."""
    source, is_text, label = _source(scenario)
    return _core._check(source, is_text, label)


def run(scenario: Scenario, out: str | os.PathLike | None = None) -> RunResult:
    """Runs a scenario like `attiguard run SCENARIO --out OUT` and returns a RunResult: the time
    series of trajectory.csv as numpy arrays (result.series, result["t"]) and summary.json as a
    dict (result.summary). Without `out` the files go to a temporary directory that is removed.
    Raises InputError (exit code 2), NumericalError (3) or VerificationFailure (4)."""
    source, is_text, label = _source(scenario)
    with _OutDir(out) as d:
        kind, summary_text = _core._run(source, is_text, label, str(d.path))
        summary = json.loads(summary_text)
        csv = d.path / "trajectory.csv"
        series = load_csv(csv) if csv.is_file() else {}
        return RunResult(kind=kind, summary=summary, series=series,
                         out_dir=d.path if d.keep else None)


def reach(scenario: Scenario, out: str | os.PathLike | None = None,
          raise_on_failure: bool = True) -> ReachResult:
    """ConReach on a `reach` scenario like `attiguard reach SCENARIO --out OUT` (docs/reach.md).
    Returns a ReachResult: reach.json as a dict, its verdict and the balls (per step: t, the
    radius r, the contraction rate c, the attitude radius, ...). When safety is requested and not
    proved, raises VerificationFailure (the CLI's exit code 4) unless raise_on_failure=False,
    in which case the result (verdict "unsafe" or "unknown") is returned."""
    source, is_text, label = _source(scenario)
    with _OutDir(out) as d:
        try:
            summary = json.loads(_core._reach(source, is_text, label, str(d.path)))
        except _core.VerificationFailure:
            written = d.path / "reach.json"
            if raise_on_failure or not written.is_file():
                raise
            summary = load_json(written)
        return ReachResult(summary=summary, balls=balls_of(summary),
                           out_dir=d.path if d.keep else None)
