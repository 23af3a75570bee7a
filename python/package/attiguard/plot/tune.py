"""Trade-off plot of `attiguard tune` (docs/pet-erg.md, section "Tuning").

Reads DIR/tune.json and writes ``tune_tradeoff.png``: one panel per tuned key, the convergence
time of every evaluated point against that key's value (log axis); admissible points (converged,
every constraint kept) in blue, converged points with a violation in red, the best point as a
star; points that did not converge are marked at the top of the panel.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from matplotlib.figure import Figure

from . import PlotInputError
from .common import DPI, FIGSIZE


@dataclass
class TuneRun:
    dir: Path
    data: dict


def load(directory: Path) -> TuneRun:
    path = Path(directory) / "tune.json"
    try:
        data = json.loads(path.read_text())
    except OSError as e:
        raise PlotInputError(f"{path}: cannot read ({e.strerror})") from None
    except json.JSONDecodeError as e:
        raise PlotInputError(f"{path}: not JSON ({e})") from None
    if not isinstance(data.get("points"), list) or not isinstance(data.get("parameters"), list):
        raise PlotInputError(f"{path}: no 'points' or 'parameters'")
    return TuneRun(Path(directory), data)


def plot(run: TuneRun) -> list[Path]:
    keys = [p["key"] for p in run.data["parameters"]]
    points = run.data["points"]
    times = [p["convergence_time"] for p in points if p.get("convergence_time") is not None]
    top = 1.1 * max(times) if times else 1.0
    fig = Figure(figsize=(FIGSIZE[0], FIGSIZE[1] * 0.6 * len(keys) + 1.0), dpi=DPI)
    axes = fig.subplots(len(keys), 1, squeeze=False)[:, 0]
    best = run.data.get("best")
    for ax, key in zip(axes, keys):
        for colour, label, select in (
            ("tab:blue", "converged, constraints kept", lambda p: p["admissible"]),
            ("tab:red", "converged with a violation",
             lambda p: not p["admissible"] and p.get("convergence_time") is not None),
        ):
            xs = [p["values"][key] for p in points if select(p)]
            ys = [p["convergence_time"] for p in points if select(p)]
            ax.scatter(xs, ys, s=12, color=colour, label=label)
        xs = [p["values"][key] for p in points if p.get("convergence_time") is None]
        ax.scatter(xs, [top] * len(xs), s=12, marker="x", color="0.5", label="not converged / rejected")
        if best:
            ax.scatter([best["values"][key]], [best["convergence_time"]], s=120, marker="*",
                       color="gold", edgecolor="k", zorder=5, label="best")
        ax.set_xscale("log")
        ax.set_xlabel(key)
        ax.set_ylabel("convergence time [s]")
        ax.grid(True, which="both", alpha=0.4)
    bb = run.data.get("eigenaxis_bang_bang_time")
    if bb:
        for ax in axes:
            ax.axhline(4.0 * bb, color="k", linestyle="--", linewidth=0.8, label="4 x bang-bang time")
    axes[0].legend(fontsize="small")
    axes[0].set_title(f"attiguard tune: {run.data.get('evaluated')} points, "
                      f"{run.data.get('admissible')} admissible")
    path = run.dir / "tune_tradeoff.png"
    fig.tight_layout()
    fig.savefig(path)
    return [path]


plot.load = load  # type: ignore[attr-defined]  # __main__ loads tune.json, not trajectory.csv
