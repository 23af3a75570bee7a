"""Plots of `attiguard campaign` (docs/campaigns.md).

Reads DIR/runs.csv and DIR/campaign.json and writes:

- ``campaign_histograms.png``: histograms, over the runs with status ok, of the margins and the
  main figures (min_pointing_margin, max_torque_norm, final_attitude_error, delta_v, ...: the
  first of a preferred list present in runs.csv, then other varying figures);
- ``campaign_scatter.png``: the first margin against each dispersed value (one panel per
  dispersed column, at most 12), violating runs in red;
- ``campaign_envelopes.png`` when the campaign retained time series (``[campaign] retain``,
  DIR/retained.h5, read with python3-h5py): per retained column, the min, 1 %, 50 %, 99 % and
  max envelopes against time (computed by attiguard, /envelopes/NAME) and the worst runs
  (/worst/NAME) highlighted.
"""

from __future__ import annotations

import csv
import json
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import PlotInputError
from .common import DPI

_PREFERRED = (
    "min_pointing_margin", "max_torque_norm", "final_attitude_error", "max_V_minus_Gamma",
    "total_delta_v", "delta_v", "total_time", "max_final_position_error", "final_omega_norm",
    "final_attitude_error_rad", "max_energy_drift_rel",
)
# Scatter y axis when a kind has no margin (waypoint): the mission's cost.
_SCATTER_FALLBACK = ("total_time", "total_delta_v", "max_final_position_error")
_MAX_PANELS = 12


@dataclass
class CampaignRun:
    """runs.csv as columns (floats, NaN where empty) and campaign.json."""

    dir: Path
    header: list[str]
    status: list[str]
    columns: dict[str, np.ndarray] = field(default_factory=dict)
    summary: dict = field(default_factory=dict)

    @property
    def name(self) -> str:
        """The scenario's name: campaign.json's `name` when present, else its file's stem."""
        if self.summary.get("name"):
            return str(self.summary["name"])
        return Path(str(self.summary.get("scenario") or self.dir.name)).stem


def _float(x: str) -> float:
    try:
        return float(x)
    except ValueError:
        return math.nan


def load(directory: Path) -> CampaignRun:
    directory = Path(directory)
    path = directory / "runs.csv"
    try:
        with path.open(newline="") as f:
            rows = list(csv.reader(f))
    except OSError as e:
        raise PlotInputError(f"{path}: cannot read ({e.strerror})") from None
    if len(rows) < 2:
        raise PlotInputError(f"{path}: no runs")
    header = rows[0]
    body = [r for r in rows[1:] if len(r) == len(header)]
    columns = {name: np.array([_float(r[i]) for r in body]) for i, name in enumerate(header)}
    summary = {}
    try:
        summary = json.loads((directory / "campaign.json").read_text())
    except (OSError, ValueError):
        pass
    return CampaignRun(directory, header, [r[header.index("status")] for r in body], columns,
                       summary)


def _figures(run: CampaignRun) -> list[str]:
    start = run.header.index("violation") + 1
    figures = [h for h in run.header[start:]]
    ok = np.array([s == "ok" for s in run.status])
    varying = [h for h in figures
               if np.isfinite(run.columns[h][ok]).any() and np.nanstd(run.columns[h][ok]) > 0]
    ordered = [h for h in _PREFERRED if h in varying]
    ordered += [h for h in varying if h not in ordered and "margin" in h]
    ordered += [h for h in varying if h not in ordered]
    return ordered[:_MAX_PANELS]


def _dispersed(run: CampaignRun) -> list[str]:
    start = run.header.index("reason") + 1
    stop = run.header.index("violation")
    # Every dispersed column that varies: one scatter panel each (no cap).
    return [h for h in run.header[start:stop] if np.nanstd(run.columns[h]) > 0]


def _grid(n: int):
    from matplotlib.figure import Figure

    cols = min(3, max(1, n))
    rows = max(1, math.ceil(n / cols))
    fig = Figure(figsize=(4.0 * cols, 3.0 * rows), dpi=DPI)
    axes = fig.subplots(rows, cols, squeeze=False).ravel()
    for ax in axes[n:]:
        ax.set_visible(False)
    return fig, axes


def histograms(run: CampaignRun) -> Path:
    ok = np.array([s == "ok" for s in run.status])
    names = _figures(run)
    fig, axes = _grid(max(1, len(names)))
    for ax, name in zip(axes, names):
        values = run.columns[name][ok]
        values = values[np.isfinite(values)]
        ax.hist(values, bins=40, color="tab:blue", alpha=0.8)
        if "margin" in name:
            ax.axvline(0.0, color="tab:red", lw=1.0)
        ax.set_xlabel(name)
        ax.set_ylabel("runs")
        ax.grid(True, alpha=0.4)
    fig.suptitle(f"{run.name}: {int(ok.sum())} runs ok, violations: "
                 f"{run.summary.get('violations', '?')}")
    path = run.dir / "campaign_histograms.png"
    fig.tight_layout()
    fig.savefig(path)
    return path


def scatter(run: CampaignRun) -> Path | None:
    from matplotlib.ticker import MaxNLocator
    ok = np.array([s == "ok" for s in run.status])
    figures = _figures(run)
    margins = ([f for f in figures if "margin" in f]
               or [f for f in _SCATTER_FALLBACK if f in figures] or figures)
    if not margins:
        return None
    margin = margins[0]
    params = _dispersed(run)
    fig, axes = _grid(max(1, len(params)))
    violation = run.columns["violation"] == 1.0
    for ax, p in zip(axes, params):
        ax.scatter(run.columns[p][ok & ~violation], run.columns[margin][ok & ~violation], s=3,
                   color="tab:blue", label="ok")
        if (ok & violation).any():
            ax.scatter(run.columns[p][ok & violation], run.columns[margin][ok & violation], s=6,
                       color="tab:red", label="violation")
        ax.set_xlabel(p)
        ax.set_ylabel(margin)
        ax.ticklabel_format(axis="x", useOffset=False)  # e.g. axis.x near 1: plain values
        ax.xaxis.set_major_locator(MaxNLocator(4))
        ax.grid(True, alpha=0.4)
    fig.suptitle(f"{run.name}: {margin} against the dispersed values")
    path = run.dir / "campaign_scatter.png"
    fig.tight_layout()
    fig.savefig(path)
    return path


def envelopes(run: CampaignRun) -> Path | None:
    """campaign_envelopes.png from DIR/retained.h5 (docs/campaigns.md, "Retained time series")."""
    path = run.dir / "retained.h5"
    if not path.is_file():
        return None
    try:
        import h5py
    except ImportError:
        import sys
        print(f"attiguard.plot: {path}: python3-h5py is not installed: no campaign_envelopes.png "
              "(apt-get install python3-h5py)", file=sys.stderr)
        return None
    with h5py.File(path, "r") as f:
        t = np.asarray(f["t"])
        if "envelopes" not in f:
            raise PlotInputError(f"{path}: no /envelopes (the campaign was interrupted: resume it)")
        names = list(f["envelopes"].keys())
        env = {n: np.asarray(f["envelopes"][n]) for n in names}
        worst = {n: [int(k) for k in np.asarray(f["worst"][n])] for n in names}
        worst_rows = {n: [np.asarray(f["series"][n][k, :]) for k in worst[n]] for n in names}
    fig, axes = _grid(max(1, len(names)))
    for ax, n in zip(axes, names):
        e = env[n]
        ax.fill_between(t, e[0], e[4], color="tab:blue", alpha=0.15, label="min – max")
        ax.fill_between(t, e[1], e[3], color="tab:blue", alpha=0.35, label="1 % – 99 %")
        ax.plot(t, e[2], color="black", lw=1.0, label="median")
        for k, row in zip(worst[n], worst_rows[n]):
            ax.plot(t, row, color="tab:red", lw=0.8, alpha=0.8)
        if worst[n]:
            ax.plot([], [], color="tab:red", lw=0.8,
                    label="worst runs " + ", ".join(str(k) for k in worst[n]))
        if "margin" in n:
            ax.axhline(0.0, color="tab:red", lw=0.6, ls="--")
        counts = e[5][np.isfinite(e[5])]
        ax.set_title(f"{n} (over {int(counts.min()) if counts.size else 0}"
                     f"–{int(counts.max()) if counts.size else 0} runs per t)", fontsize=9)
        ax.set_xlabel("t [s]")
        ax.set_ylabel(n)
        ax.grid(True, alpha=0.4)
        ax.legend(fontsize=7)
    fig.suptitle(f"{run.name}: percentile envelopes of the retained time series")
    out = run.dir / "campaign_envelopes.png"
    fig.tight_layout()
    fig.savefig(out)
    return out


def compare(runs: list[CampaignRun], figure: str, out: Path) -> Path:
    """Overlaid histograms of one figure of runs.csv for several campaigns of the same scenario
    with one setting changed, e.g. the robust / nominal pair of docs/pet-erg.md section 14: one
    colour per campaign, its ok runs and violations in the legend, the zero of a margin marked."""
    from matplotlib.figure import Figure

    if len(runs) < 2:
        raise PlotInputError("compare needs at least two campaign directories")
    series = []
    for run in runs:
        if figure not in run.columns:
            raise PlotInputError(f"{run.dir / 'runs.csv'}: no column '{figure}'")
        ok = np.array([s == "ok" for s in run.status])
        values = run.columns[figure][ok]
        series.append((run, values[np.isfinite(values)], int(ok.sum())))
    lo = min(float(v.min()) for _, v, _ in series if v.size)
    hi = max(float(v.max()) for _, v, _ in series if v.size)
    bins = np.linspace(lo, hi, 81) if hi > lo else 10
    fig = Figure(figsize=(8.0, 4.5), dpi=DPI)
    ax = fig.subplots()
    for run, values, ok in series:
        below = int((values < 0.0).sum()) if "margin" in figure else None
        label = f"{run.name}: {ok} runs ok, violations {run.summary.get('violations', '?')}"
        if below is not None:
            label += f", {figure} < 0 in {below}"
        ax.hist(values, bins=bins, alpha=0.6, label=label)
    if "margin" in figure:
        ax.axvline(0.0, color="tab:red", lw=1.0)
    ax.set_xlabel(figure)
    ax.set_ylabel("runs")
    ax.set_yscale("log")
    ax.grid(True, alpha=0.4)
    ax.legend(fontsize=8)
    fig.tight_layout()
    out = Path(out)
    fig.savefig(out)
    return out


def plot(run: CampaignRun) -> list[Path]:
    written = [histograms(run)]
    s = scatter(run)
    if s is not None:
        written.append(s)
    e = envelopes(run)
    if e is not None:
        written.append(e)
    return written


plot.load = load  # type: ignore[attr-defined]  # __main__ loads runs.csv, not trajectory.csv
