"""Plots of scenario kind `waypoint` (waypoint paper, Figs. 2-6).

trajectory.csv columns: t, p_x..p_z, v_x..v_z, q_w..q_z, omega_x..omega_z, tau_x..tau_z, thrust,
rct_1..rct_6, mode, waypoint. summary.json: `legs[k].position` gives the waypoints.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .common import FIGSIZE, DPI, Run, new_figure, save, title

AXES = ("x", "y", "z")


def _waypoints(run: Run) -> np.ndarray:
    legs = run.summary.get("legs", [])
    pts = [leg.get("position") for leg in legs if isinstance(leg, dict)]
    pts = [p for p in pts if isinstance(p, list) and len(p) == 3]
    return np.array(pts, dtype=float).reshape(-1, 3)


def _rotate_x(q: np.ndarray) -> np.ndarray:
    """First column of R(q) (body x axis in inertial axes), q scalar-first, one row per sample."""
    w, x, y, z = q.T
    return np.column_stack([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)])


def path_3d(run: Run) -> Path:
    """3-D path with the thrust direction x_b."""
    from matplotlib.figure import Figure

    p = run.columns_of("p_x", "p_y", "p_z")
    q = run.columns_of("q_w", "q_x", "q_y", "q_z")
    fig = Figure(figsize=(FIGSIZE[0], FIGSIZE[0] * 0.8), dpi=DPI)
    ax = fig.add_subplot(projection="3d")
    ax.plot(p[:, 0], p[:, 1], p[:, 2], "b-", linewidth=1.0, label="path")
    wp = _waypoints(run)
    if len(wp):
        ax.scatter(wp[:, 0], wp[:, 1], wp[:, 2], c="k", marker="o", label="waypoints")
    span = float(np.ptp(np.vstack([p, wp]) if len(wp) else p, axis=0).max()) or 1.0
    idx = np.linspace(0, len(p) - 1, min(40, len(p))).astype(int)
    xb = _rotate_x(q[idx]) * 0.06 * span
    ax.quiver(p[idx, 0], p[idx, 1], p[idx, 2], xb[:, 0], xb[:, 1], xb[:, 2], color="r",
              label="thrust direction x_b")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    ax.set_title(title(run, "path and thrust direction"))
    ax.legend(loc="best")
    return save(fig, run, "path_3d.png")


def thrusters(run: Run) -> Path:
    """main thruster and the six RCT."""
    t = run.column("t")
    fig, axes = new_figure(7)
    axes[0].step(t, run.column("thrust"), where="post", color="r")
    axes[0].set_ylabel("T [N]")
    axes[0].set_title(title(run, "thruster firings"))
    for j in range(6):
        axes[j + 1].step(t, run.column(f"rct_{j + 1}"), where="post")
        axes[j + 1].set_ylabel(f"f_{j + 1} [N]")
    return save(fig, run, "thrusters.png")


def speed(run: Run) -> Path:
    """speed and velocity components."""
    t = run.column("t")
    v = run.columns_of("v_x", "v_y", "v_z")
    fig, (ax,) = new_figure()
    for i, a in enumerate(AXES):
        ax.plot(t, v[:, i], label=f"v_{a}")
    ax.plot(t, np.linalg.norm(v, axis=1), "k--", linewidth=1.0, label="‖v‖")
    ax.set_ylabel("velocity [m/s]")
    ax.set_title(title(run, "velocity"))
    ax.legend(loc="best")
    return save(fig, run, "velocity.png")


def position_error(run: Run) -> Path:
    """position error to the active waypoint (log scale) and the mode."""
    t = run.column("t")
    p = run.columns_of("p_x", "p_y", "p_z")
    k = run.column("waypoint").astype(int)
    wp = _waypoints(run)
    fig, (ax, axm) = new_figure(2)
    if len(wp):
        active = np.clip(k, 0, len(wp) - 1)
        e = np.linalg.norm(wp[active] - p, axis=1)
        ax.semilogy(t, np.where(e > 0, e, np.nan), label="‖e‖ to the active waypoint")
        ax.legend(loc="best")
    ax.set_ylabel("position error [m]")
    ax.set_title(title(run, "position error"))
    names = run.summary.get("mode_names") or ["align", "accelerate", "coast", "flip",
                                              "decelerate", "fine", "done", "brake", "rct_transfer"]
    axm.step(t, run.column("mode"), where="post")
    axm.set_yticks(range(len(names)))
    axm.set_yticklabels(names)
    axm.set_ylabel("mode")
    return save(fig, run, "position_error.png")


def attitude(run: Run) -> Path:
    """quaternion, angular velocity and torque."""
    t = run.column("t")
    fig, axes = new_figure(3)
    for name in ("q_w", "q_x", "q_y", "q_z"):
        axes[0].plot(t, run.column(name), label=name)
    axes[0].set_ylabel("q_ib")
    axes[0].set_title(title(run, "attitude dynamics"))
    for a in AXES:
        axes[1].plot(t, run.column(f"omega_{a}"), label=f"ω_{a}")
        axes[2].plot(t, run.column(f"tau_{a}"), label=f"τ_{a}")
    axes[1].set_ylabel("ω_b [rad/s]")
    axes[2].set_ylabel("τ_b [N·m]")
    for ax in axes:
        ax.legend(loc="best", fontsize="small")
    return save(fig, run, "attitude.png")


def plot(run: Run) -> list[Path]:
    return [path_3d(run), thrusters(run), speed(run), position_error(run), attitude(run)]
