"""Plots of scenario kind `mission` (docs/mission.md): the pointing margin of the Sun cone and the
torque norm against tau_max over the whole mission, and the path with the thrust.

trajectory.csv columns: t, p_*, v_*, q_*, omega_*, tau_*, tau_norm, thrust, mode, waypoint,
qg_* (R_g), qd_* (R_d), trigger, min_margin. summary.json: tau_max, governor, unconstrained.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .common import Run, new_figure, save, title


def constraints(run: Run) -> Path:
    """Min pointing margin (2b) and ‖τ‖ against τ_max (2a) at every logged sample."""
    t = run.column("t")
    fig, axes = new_figure(2)
    axes[0].plot(t, run.column("min_margin"), label=f"governor = {run.summary.get('governor')}")
    axes[0].axhline(0.0, color="r", lw=0.8, label="cone boundary")
    unc = run.summary.get("unconstrained", {})
    if isinstance(unc, dict) and unc.get("min_pointing_margin") is not None:
        axes[0].axhline(unc["min_pointing_margin"], color="0.5", ls=":",
                        label="min margin of the unconstrained twin")
    axes[0].set_ylabel("a_cᵀRa_b − cos θ_c")
    axes[0].set_title(title(run, "pointing margin and torque"))
    axes[1].plot(t, run.column("tau_norm"), label="‖τ‖")
    if "tau_max" in run.summary:
        axes[1].axhline(float(run.summary["tau_max"]), color="r", lw=0.8, label="τ_max")
    axes[1].set_ylabel("‖τ‖ [N·m]")
    axes[1].set_xlabel("t [s]")
    for ax in axes:
        ax.legend(loc="best", fontsize="small")
    return save(fig, run, "mission_constraints.png")


def path(run: Run) -> Path:
    """Position components, thrust and mode over time."""
    t = run.column("t")
    fig, axes = new_figure(2)
    for a in "xyz":
        axes[0].plot(t, run.column(f"p_{a}"), label=f"p_{a}")
    axes[0].set_ylabel("p_i [m]")
    axes[0].set_title(title(run, "path and thrust"))
    axes[0].legend(loc="best", fontsize="small")
    axes[1].plot(t, run.column("thrust"), label="T [N]")
    axes[1].plot(t, np.asarray(run.column("mode")), label="mode (0 align … 6 done, 7 brake, 8 rct_transfer)")
    axes[1].set_xlabel("t [s]")
    axes[1].legend(loc="best", fontsize="small")
    return save(fig, run, "mission_path.png")


def plot(run: Run) -> list[Path]:
    return [constraints(run), path(run)]
