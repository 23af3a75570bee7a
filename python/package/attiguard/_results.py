"""The results of attiguard.run() and attiguard.reach(): numpy arrays and dicts."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np


@dataclass
class RunResult:
    """Outputs of attiguard.run(): the time series (trajectory.csv, one numpy array per column),
    the summary dict (summary.json) and the scenario kind. result["t"] is result.series["t"]."""

    kind: str
    summary: dict[str, Any]
    series: dict[str, np.ndarray] = field(repr=False)
    out_dir: Path | None = None

    def __getitem__(self, column: str) -> np.ndarray:
        return self.series[column]

    @property
    def columns(self) -> list[str]:
        return list(self.series)


@dataclass
class ReachResult:
    """Outputs of attiguard.reach(): the summary dict (reach.json), its verdict, and the balls
    (one entry per step of reach.json's `steps`, numeric fields stacked as numpy arrays:
    t, r, c, attitude_radius, ...)."""

    summary: dict[str, Any]
    balls: dict[str, np.ndarray] = field(repr=False)
    out_dir: Path | None = None

    @property
    def verdict(self) -> str:
        return str(self.summary.get("verdict", ""))


def balls_of(summary: dict[str, Any]) -> dict[str, np.ndarray]:
    steps = summary.get("steps", [])
    if not steps:
        return {}
    out: dict[str, np.ndarray] = {}
    for key, value in steps[0].items():
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            out[key] = np.array([float(s[key]) for s in steps])
        elif isinstance(value, list):
            try:
                out[key] = np.array([s[key] for s in steps], dtype=float)
            except (TypeError, ValueError):
                pass
    return out


def load_json(path: Path) -> dict[str, Any]:
    return json.loads(Path(path).read_text())
