"""Plots of `attiguard plan` (the slew planner, docs/slew-planner.md).

Reads DIR/plan.csv and DIR/plan.json written by ``attiguard plan`` (src/attiguard/app/plan_run.hpp)
and writes ``plan.png``: the attitude's angle to the target and the body rate, the torque
against the torque limit and τ_max, and each cone's pointing margin a_cᵀRa_b − cos θ_c (≥ 0 kept).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from . import PlotInputError
from .common import Run, load_trajectory, new_figure, save, title


def load(directory: Path) -> Run:
    """DIR/plan.csv and DIR/plan.json as a Run."""
    directory = Path(directory)
    if not directory.is_dir():
        raise PlotInputError(f"{directory}: not a directory")
    path = directory / "plan.json"
    try:
        summary = json.loads(path.read_text())
    except (OSError, ValueError) as e:
        raise PlotInputError(f"{path}: cannot read ({e})") from None
    if not isinstance(summary, dict):
        raise PlotInputError(f"{path}: expected a JSON object")
    return Run(dir=directory, columns=load_trajectory(directory / "plan.csv"), summary=summary)


def _angle_to_target(run: Run) -> np.ndarray:
    """The rotation angle from each plan attitude to the last one [deg]."""
    q = run.columns_of("q_w", "q_x", "q_y", "q_z")
    q = q / np.linalg.norm(q, axis=1, keepdims=True)
    dots = np.abs(q @ q[-1])
    return np.degrees(2.0 * np.arccos(np.clip(dots, 0.0, 1.0)))


def plot(run: Run) -> list[Path]:
    t = run.column("t")
    s = run.summary
    fig, (ax1, ax2, ax3, ax4) = new_figure(4)
    ratio = s.get("ratio_to_bang_bang")
    what = f"planned slew, {t[-1]:.4g} s"
    if isinstance(ratio, (int, float)):
        what += f" = {ratio:.4g}x eigenaxis bang-bang"
    ax1.plot(t, _angle_to_target(run), color="k")
    ax1.set_ylabel("angle to target [deg]")
    ax1.set_title(title(run, what))
    for axis in "xyz":
        ax2.plot(t, run.column(f"omega_{axis}"), label=f"ω_{axis}")
    ax2.set_ylabel("ω_b [rad/s]")
    ax2.legend(loc="best")
    ax3.plot(t, run.column("tau_norm"), color="k", label="‖τ‖")
    limit = s.get("torque_limit")
    headroom = s.get("torque_headroom", 0.0)
    if isinstance(limit, (int, float)):
        ax3.axhline(limit * (1.0 - headroom), color="tab:orange", linestyle="--",
                    label="(1 − headroom) × torque limit")
        ax3.axhline(limit, color="tab:red", linestyle=":", label="torque limit")
    ax3.set_ylabel("‖τ‖ [N·m]")
    ax3.legend(loc="best")
    margins = sorted((c for c in run.columns if c.startswith("margin_")), key=lambda c: int(c[7:]))
    for name in margins:
        ax4.plot(t, run.column(name), label=f"cone {name[7:]}")
    ax4.axhline(0.0, color="tab:red", linestyle=":")
    ax4.set_ylabel("a_cᵀRa_b − cos θ_c")
    if margins:
        ax4.legend(loc="best")
    else:
        ax4.text(0.5, 0.5, "no cones", transform=ax4.transAxes, ha="center")
    return [save(fig, run, "plan.png")]


plot.load = load  # type: ignore[attr-defined]  # __main__ loads plan.csv, not trajectory.csv
