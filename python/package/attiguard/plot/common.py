"""Loading of `attiguard run` outputs and the figure conventions shared by every kind."""

from __future__ import annotations

import csv
import json
import math
from dataclasses import dataclass
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, never a window

import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from . import PlotInputError  # noqa: E402

FIGSIZE = (8.0, 4.5)  # inches
DPI = 120


@dataclass
class Run:
    """The results of one run: its directory, time series and summary."""

    dir: Path
    columns: dict[str, np.ndarray]  # trajectory.csv, one array per column
    summary: dict  # summary.json

    @property
    def name(self) -> str:
        """Scenario name for titles (summary.json `name`, else the directory name)."""
        name = self.summary.get("name")
        return name if isinstance(name, str) and name else self.dir.name

    def column(self, name: str) -> np.ndarray:
        try:
            return self.columns[name]
        except KeyError:
            raise PlotInputError(
                f"{self.dir / 'trajectory.csv'}: no column '{name}'"
            ) from None

    def columns_of(self, *names: str) -> np.ndarray:
        """Columns stacked as an array of shape (len(t), len(names))."""
        return np.column_stack([self.column(n) for n in names])


def load_trajectory(path: Path) -> dict[str, np.ndarray]:
    """Reads a CSV with a header row into {column name: float array}."""
    try:
        with path.open(newline="") as f:
            rows = list(csv.reader(f))
    except OSError as e:
        raise PlotInputError(f"{path}: cannot read ({e.strerror})") from None
    if not rows:
        raise PlotInputError(f"{path}: empty file (expected a header row)")
    header = [h.strip() for h in rows[0]]
    body = [r for r in rows[1:] if r]
    if not body:
        raise PlotInputError(f"{path}: no data rows")
    try:
        data = np.array([[float(x) for x in r] for r in body], dtype=float)
    except ValueError as e:
        raise PlotInputError(f"{path}: not a numeric table ({e})") from None
    if data.shape[1] != len(header):
        raise PlotInputError(f"{path}: {data.shape[1]} values per row but {len(header)} names")
    return {name: data[:, i] for i, name in enumerate(header)}


def load_summary(path: Path) -> dict:
    """Reads summary.json (an object); an absent file gives {}."""
    if not path.exists():
        return {}
    try:
        value = json.loads(path.read_text())
    except (OSError, ValueError) as e:
        raise PlotInputError(f"{path}: cannot read JSON ({e})") from None
    if not isinstance(value, dict):
        raise PlotInputError(f"{path}: expected a JSON object")
    return value


def load_run(directory: Path) -> Run:
    directory = Path(directory)
    if not directory.is_dir():
        raise PlotInputError(f"{directory}: not a directory")
    return Run(
        dir=directory,
        columns=load_trajectory(directory / "trajectory.csv"),
        summary=load_summary(directory / "summary.json"),
    )


def new_figure(rows: int = 1) -> tuple[Figure, list]:
    """A figure with `rows` stacked axes sharing the time axis."""
    fig = Figure(figsize=(FIGSIZE[0], FIGSIZE[1] * (1 + 0.6 * (rows - 1))), dpi=DPI)
    axes = fig.subplots(rows, 1, sharex=True, squeeze=False)[:, 0]
    for ax in axes:
        ax.grid(True, which="both", alpha=0.4)
    axes[-1].set_xlabel("time t [s]")
    return fig, list(axes)


def save(fig: Figure, run: Run, filename: str) -> Path:
    """Writes the figure as DIR/filename and returns that path."""
    path = run.dir / filename
    fig.tight_layout()
    fig.savefig(path)
    return path


def title(run: Run, what: str) -> str:
    return f"{run.name}: {what}"


def positive_or_nan(x: np.ndarray) -> np.ndarray:
    """x with non-positive entries replaced by NaN (gaps on a log axis)."""
    return np.where(x > 0.0, x, math.nan)
