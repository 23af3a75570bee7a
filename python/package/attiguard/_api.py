"""attiguard.run / check / reach: the `attiguard run`, `check` and `reach` commands from Python.

A scenario is a scenario file path (str or pathlib.Path) or a dict with the same structure as
the file (docs/scenario-format.md); a dict is handed to the C++ core value by value (no text,
no temporary file) and validated by the same readers as a file, so errors carry the same
messages, with "<dict>" in place of the file name. run() receives the time series straight into
numpy arrays (a row sink of the bindings); files are written only when `out` is given.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any, Mapping, Union

from . import _core
from ._results import ReachResult, RunResult, balls_of, load_json

Scenario = Union[str, os.PathLike, Mapping[str, Any]]

def _out_path(out: object) -> Union[str, os.PathLike, None]:
    """`out` as given when it is None or a path; TypeError naming it otherwise."""
    if out is None or isinstance(out, (str, os.PathLike)):
        return out
    raise TypeError(f"out must be a directory path or None, got {type(out).__name__}")


def _source(scenario: Scenario) -> Union[str, Mapping[str, Any]]:
    """The scenario for the C++ side: a path as str, or the dict itself."""
    if isinstance(scenario, Mapping):
        return scenario
    if isinstance(scenario, (str, os.PathLike)):
        return os.fspath(scenario)
    raise TypeError(f"scenario must be a scenario file path or a dict, got {type(scenario).__name__}")


def _make_out_dir(path: Path) -> None:
    """Creates the output directory PATH (and its parents), as the CLI's --out does
    (cli/output_dir.cpp): a file in its place, or a directory the system refuses, is the
    package's InputError naming `out` (docs/python.md, "Errors"), never a bare OSError."""
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise _core.InputError(f"out: {path}: cannot create output directory ({e.strerror or e})") from None
    if not path.is_dir():
        raise _core.InputError(f"out: {path}: cannot create output directory (a file of that name exists)")


class _OutDir:
    """The output directory: the given one (kept), or a temporary one removed afterwards."""

    def __init__(self, out: str | os.PathLike | None):
        self.keep = out is not None
        self.path = Path(out) if out is not None else Path(tempfile.mkdtemp(prefix="attiguard-"))
        _make_out_dir(self.path)

    def __enter__(self) -> "_OutDir":
        return self

    def __exit__(self, *exc: object) -> None:
        if not self.keep:
            shutil.rmtree(self.path, ignore_errors=True)


def check(scenario: Scenario) -> str:
    """Parses and validates a scenario like `attiguard check`; returns its kind.
    Raises attiguard.InputError with the CLI's message when it is invalid."""
    return _core._check(_source(scenario))


def predict(scenario: Scenario) -> dict[str, Any]:
    """The mission-time and delta-v prediction of a `waypoint` scenario, as `attiguard check`
    prints it and summary.json's `prediction` holds it (docs/waypoint.md, "Prediction"): a dict
    with `time` [s], `delta_v` [m/s] and `legs` (each `time`, `delta_v`, `turn_time`,
    `fine_time`, `peak_speed`, `rct_only`). Validates like `check`; raises InputError."""
    return dict(json.loads(_core._predict(_source(scenario))))


def run(scenario: Scenario, out: str | os.PathLike | None = None) -> RunResult:
    """Runs a scenario like `attiguard run SCENARIO --out OUT` and returns a RunResult: the time
    series (the columns of trajectory.csv) as numpy arrays (result.series, result["t"]) and the
    summary as a dict (result.summary). The arrays are filled by the simulator directly; with
    `out` the run also writes OUT/trajectory.csv and OUT/summary.json, without it nothing is
    written. Raises InputError (exit code 2), NumericalError (3) or VerificationFailure (4)."""
    out_dir = None
    _out_path(out)
    if out is not None:
        out_dir = Path(out)
        _make_out_dir(out_dir)
    kind, summary_text, series = _core._run(_source(scenario),
                                            None if out_dir is None else str(out_dir))
    return RunResult(kind=kind, summary=json.loads(summary_text), series=dict(series),
                     out_dir=out_dir)


def reach(scenario: Scenario, out: str | os.PathLike | None = None,
          raise_on_failure: bool = True) -> ReachResult:
    """ConReach on a `reach` scenario like `attiguard reach SCENARIO --out OUT` (docs/reach.md).
    Returns a ReachResult: reach.json as a dict, its verdict and the balls (per step: t, the
    radius r, the contraction rate c, the attitude radius, ...). When safety is requested and not
    proved, raises VerificationFailure (the CLI's exit code 4) unless raise_on_failure=False,
    in which case the result (verdict "unsafe" or "unknown") is returned."""
    if not isinstance(raise_on_failure, bool):
        raise TypeError(f"raise_on_failure must be True or False, got {type(raise_on_failure).__name__}")
    source = _source(scenario)
    with _OutDir(_out_path(out)) as d:
        try:
            summary = json.loads(_core._reach(source, str(d.path)))
        except _core.VerificationFailure:
            written = d.path / "reach.json"
            if raise_on_failure or not written.is_file():
                raise
            summary = load_json(written)
        return ReachResult(summary=summary, balls=balls_of(summary),
                           out_dir=d.path if d.keep else None)
