"""Plots of scenario kind `rigid_body` (PET-ERG paper, eq. (1); PD law (3)).

trajectory.csv columns: t, q_w,q_x,q_y,q_z, omega_x,omega_y,omega_z, tau_x,tau_y,tau_z,
attitude_error_rad, phi, energy, h_x,h_y,h_z.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .common import Run, new_figure, positive_or_nan, save, title

AXES = ("x", "y", "z")


def _reference_label(run: Run) -> str:
    """What attitude_error_rad measures: the distance to the PD reference, or for the other
    laws to the initial attitude."""
    law = run.summary.get("law", run.summary.get("control_law"))
    if isinstance(law, str) and law != "pd":
        return "initial attitude"
    return "reference"


def attitude_error(run: Run) -> Path:
    t = run.column("t")
    d = run.column("attitude_error_rad")
    target = _reference_label(run)
    fig, (ax,) = new_figure()
    if np.any(d > 0.0):
        ax.semilogy(t, positive_or_nan(d), label=f"d(R, R_{target[:3]}) = ‖log(R_{target[:3]}ᵀ R)‖")
    else:  # identically zero: a log axis cannot show it
        ax.plot(t, d, label="d = 0")
    ax.set_ylabel("attitude error [rad]")
    ax.set_title(title(run, f"distance to the {target} (bi-invariant, log scale)"))
    ax.legend(loc="best")
    return save(fig, run, "attitude_error.png")


def _components(run: Run, prefix: str, ylabel: str, what: str, filename: str,
                norm_label: str | None = None) -> Path:
    t = run.column("t")
    v = run.columns_of(*(f"{prefix}_{a}" for a in AXES))
    fig, (ax,) = new_figure()
    for i, a in enumerate(AXES):
        ax.plot(t, v[:, i], label=f"{prefix}_{a}")
    if norm_label is not None:
        ax.plot(t, np.linalg.norm(v, axis=1), "k--", linewidth=1.0, label=norm_label)
    ax.set_ylabel(ylabel)
    ax.set_title(title(run, what))
    ax.legend(loc="best")
    return save(fig, run, filename)


def angular_velocity(run: Run) -> Path:
    return _components(run, "omega", "body angular velocity ω_b [rad/s]",
                       "angular velocity (body frame)", "angular_velocity.png", "‖ω‖")


def torque(run: Run) -> Path:
    return _components(run, "tau", "control torque τ_b [N·m]", "applied torque (body frame)",
                       "torque.png", "‖τ‖")


def quaternion(run: Run) -> Path:
    t = run.column("t")
    fig, (ax,) = new_figure()
    for c in ("w", "x", "y", "z"):
        ax.plot(t, run.column(f"q_{c}"), label=f"q_{c}")
    ax.set_ylabel("attitude quaternion q_ib [-]")
    ax.set_ylim(-1.05, 1.05)
    ax.set_title(title(run, "attitude quaternion (scalar-first, body → inertial)"))
    ax.legend(loc="best", ncol=4)
    return save(fig, run, "quaternion.png")


def energy_momentum(run: Run) -> Path:
    t = run.column("t")
    energy = run.column("energy")
    h_norm = np.linalg.norm(run.columns_of("h_x", "h_y", "h_z"), axis=1)
    fig, (ax_e, ax_h) = new_figure(rows=2)
    ax_e.plot(t, energy - energy[0], color="C0", label=f"E − E(0),  E(0) = {energy[0]:.6g} J")
    ax_e.set_ylabel("energy change [J]")
    ax_e.set_title(title(run, "kinetic energy and angular momentum drift"))
    ax_e.legend(loc="best")
    ax_h.plot(t, h_norm - h_norm[0], color="C1",
              label=f"‖h‖ − ‖h‖(0),  ‖h‖(0) = {h_norm[0]:.6g} N·m·s")
    ax_h.set_ylabel("‖h‖ change [N·m·s]")
    ax_h.legend(loc="best")
    return save(fig, run, "energy_momentum.png")


def plot(run: Run) -> list[Path]:
    """Every rigid_body figure; returns the paths written."""
    return [attitude_error(run), angular_velocity(run), torque(run), quaternion(run),
            energy_momentum(run)]
