"""Plots of `attiguard reach` (ConReach, contraction-reachability paper, Sec. 6, Fig. 1).

Reads DIR/reach.json, steps.csv, tube.csv, boundary.csv and samples.csv written by
``attiguard reach`` (src/attiguard/app/reach_run.hpp) and writes:

- ``reach_omega.png`` (Fig. 1a): sampled ω trajectories, the state-tube ω boxes and the search
  regions of the first and last steps (dashed; U_0 and U_6 in the paper's scenario) in ω space;
- ``reach_attitude.png`` (Fig. 1b): boundaries of the attitude balls B_Q(R_i, r_i) in the exp
  chart (points obtained by integrating (26) from the ellipsoid wᵀQw = r²) and the sampled
  attitude trajectories in the same chart;
- ``reach_radius.png``: r_i, the bi-invariant attitude enclosure r_i/√λ_min(Q_i) and c_i.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from . import PlotInputError
from .common import DPI, Run, load_trajectory, save, title


def _table(run: Run, name: str) -> dict[str, np.ndarray] | None:
    path = run.dir / name
    return load_trajectory(path) if path.exists() else None


def _reach_json(run: Run) -> dict:
    path = run.dir / "reach.json"
    try:
        return json.loads(path.read_text())
    except (OSError, ValueError) as e:
        raise PlotInputError(f"{path}: cannot read ({e})") from None


def _box_edges(lo, hi):
    """The 12 edges of a box as pairs of 3-vectors."""
    corners = np.array([[lo[0] if i & 1 == 0 else hi[0], lo[1] if i & 2 == 0 else hi[1],
                         lo[2] if i & 4 == 0 else hi[2]] for i in range(8)])
    edges = []
    for a in range(8):
        for b in range(a + 1, 8):
            if bin(a ^ b).count("1") == 1:
                edges.append((corners[a], corners[b]))
    return edges


def _figure_3d():
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7.0, 6.0), dpi=DPI)
    ax = fig.add_subplot(1, 1, 1, projection="3d")
    return fig, ax


def omega_plot(run: Run, summary: dict) -> Path:
    fig, ax = _figure_3d()
    tube = _table(run, "tube.csv")
    if tube is not None:
        cell0 = tube["cell"] == 0
        for k in np.nonzero(cell0)[0][::4]:
            lo = [tube[f"omega_lo_{a}"][k] for a in "xyz"]
            hi = [tube[f"omega_hi_{a}"][k] for a in "xyz"]
            for p, q in _box_edges(lo, hi):
                ax.plot(*zip(p, q), color="tab:blue", alpha=0.15, linewidth=0.6)
    steps = summary.get("steps", [])
    for idx, style in ((0, "k--"), (len(steps) - 1, "r--")):
        if 0 <= idx < len(steps) and "omega_box" in steps[idx]:
            box = steps[idx]["omega_box"]
            for n, (p, q) in enumerate(_box_edges(box["lower"], box["upper"])):
                ax.plot(*zip(p, q), style, linewidth=1.2,
                        label=f"search region of step {idx}" if n == 0 else None)
        if len(steps) == 1:
            break
    samples = _table(run, "samples.csv")
    if samples is not None:
        for s in np.unique(samples["sample"]):
            m = samples["sample"] == s
            ax.plot(samples["omega_x"][m], samples["omega_y"][m], samples["omega_z"][m], linewidth=0.8)
    ax.set_xlabel("ω_x [rad/s]")
    ax.set_ylabel("ω_y [rad/s]")
    ax.set_zlabel("ω_z [rad/s]")
    ax.set_title(title(run, "ω tube (boxes), first and last search regions (dashed), samples"))
    ax.legend(loc="upper left")
    return save(fig, run, "reach_omega.png")


def attitude_plot(run: Run, summary: dict) -> Path:
    fig, ax = _figure_3d()
    b = _table(run, "boundary.csv")
    if b is not None:
        m0 = b["cell"] == 0
        steps = np.unique(b["step"][m0])
        for s in steps[:: max(1, len(steps) // 10)]:
            m = m0 & (b["step"] == s)
            ax.scatter(b["r_x"][m], b["r_y"][m], b["r_z"][m], s=2, alpha=0.35, color="tab:blue")
    samples = _table(run, "samples.csv")
    if samples is not None:
        for s in np.unique(samples["sample"]):
            m = samples["sample"] == s
            ax.plot(samples["r_x"][m], samples["r_y"][m], samples["r_z"][m], linewidth=0.8)
    chart = summary.get("chart", 0)
    ax.set_xlabel("r_x [rad]")
    ax.set_ylabel("r_y [rad]")
    ax.set_zlabel("r_z [rad]")
    # chart = -1: no single chart holds every ball; each point is in the chart of boundary.csv's
    # `chart` column (docs/reach.md, "Representation"), the samples in chart 0.
    where = f"exp chart {chart}" if chart is not None and chart >= 0 else "each point's exp chart"
    ax.set_title(title(run, f"attitude ball boundaries in {where}, samples"))
    return save(fig, run, "reach_attitude.png")


def radius_plot(run: Run, summary: dict) -> Path:
    from .common import new_figure

    steps = summary.get("steps", [])
    if not steps:
        raise PlotInputError(f"{run.dir / 'reach.json'}: no steps")
    t = np.array([s["t_end"] for s in steps])
    fig, (ax1, ax2) = new_figure(2)
    ax1.plot(t, [s["r"] for s in steps], label="r_i (product metric)")
    ax1.plot(t, [s["attitude_radius"] for s in steps], label="r_i / √λ_min(Q_i) (attitude, rad)")
    ax1.set_ylabel("radius")
    ax1.legend(loc="best")
    ax1.set_title(title(run, "ConReach balls"))
    ax2.step(t, [s["c"] for s in steps], where="post", label="c_i")
    ax2.step(t, [s["c_identity"] for s in steps], where="post", linestyle="--", label="c with Q = P = I")
    ax2.set_ylabel("contraction rate [1/s]")
    ax2.legend(loc="best")
    return save(fig, run, "reach_radius.png")


def plot(run: Run) -> list[Path]:
    summary = _reach_json(run)
    return [omega_plot(run, summary), attitude_plot(run, summary), radius_plot(run, summary)]
