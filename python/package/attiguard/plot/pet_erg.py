"""Plots of scenario kind `pet_erg`: the PET-ERG paper's Figs. 2-5.

trajectory.csv columns: t, q_w..q_z (R), omega_x..z, tau_x..z, tau_norm, qg_w..qg_z (R_g),
qd_w..qd_z (R_d), V, gamma_d, gamma_g (with cones only), gamma, trigger, attitude_error (phi(R_d^T R)),
reference_error (phi(R_d^T R_g)), margin_0.. (one per cone).
summary.json provides `cones` (axis_b, direction_i, theta_c_deg), `tau_max`, `governor`.

With `governor = "planned"` (docs/pet-erg.md, section 16.2) qg_w..qg_z is the plan's attitude
R_p(sigma), reference_error is phi(R_d^T R_p), V is the tracking law's, and s (sigma [s]), s_dot,
torque_bound [N m] and admissible replace gamma_d, gamma and trigger; summary.json adds the
object `planned` (plan.duration = T_p). Such a run gets the same figures with the plan in place
of the governor's reference, the torque bound on the torque figure, V against Gamma_g only, and
one more figure: the plan's clock sigma and its rate s_dot (pet_erg_progress.png).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from . import PlotInputError
from .common import FIGSIZE, DPI, Run, new_figure, positive_or_nan, save, title

from matplotlib.figure import Figure


def _rotations(q: np.ndarray) -> np.ndarray:
    """Rotation matrices (n, 3, 3) of scalar-first unit quaternions (n, 4), body -> inertial."""
    w, x, y, z = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    R = np.empty((q.shape[0], 3, 3))
    R[:, 0, 0] = 1 - 2 * (y * y + z * z)
    R[:, 0, 1] = 2 * (x * y - w * z)
    R[:, 0, 2] = 2 * (x * z + w * y)
    R[:, 1, 0] = 2 * (x * y + w * z)
    R[:, 1, 1] = 1 - 2 * (x * x + z * z)
    R[:, 1, 2] = 2 * (y * z - w * x)
    R[:, 2, 0] = 2 * (x * z - w * y)
    R[:, 2, 1] = 2 * (y * z + w * x)
    R[:, 2, 2] = 1 - 2 * (x * x + y * y)
    return R


def _planned(run: Run) -> bool:
    """Whether the run flew a planned slew (governor = "planned", docs/pet-erg.md 16.2)."""
    return run.summary.get("governor") == "planned"


def _plan_duration(run: Run) -> float | None:
    """T_p of summary.json's planned.plan.duration [s], or None."""
    planned = run.summary.get("planned")
    plan = planned.get("plan") if isinstance(planned, dict) else None
    duration = plan.get("duration") if isinstance(plan, dict) else None
    return float(duration) if isinstance(duration, (int, float)) else None


def _tau_max(run: Run) -> float | None:
    """tau_max of summary.json (planned runs: also planned.tau_max), or None."""
    tau_max = run.summary.get("tau_max")
    planned = run.summary.get("planned")
    if not isinstance(tau_max, (int, float)) and isinstance(planned, dict):
        tau_max = planned.get("tau_max")
    return float(tau_max) if isinstance(tau_max, (int, float)) else None


def _cones(run: Run) -> list[dict]:
    cones = run.summary.get("cones", [])
    if not isinstance(cones, list):
        raise PlotInputError(f"{run.dir / 'summary.json'}: 'cones' is not a list")
    return cones


def _circle(center: np.ndarray, angle: float, n: int = 200) -> np.ndarray:
    """Points (n, 3) of the circle on the unit sphere at angular radius `angle` around `center`."""
    c = center / np.linalg.norm(center)
    helper = np.array([1.0, 0.0, 0.0]) if abs(c[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(c, helper)
    u /= np.linalg.norm(u)
    v = np.cross(c, u)
    s = np.linspace(0.0, 2.0 * np.pi, n)
    return (np.cos(angle) * c[None, :]
            + np.sin(angle) * (np.cos(s)[:, None] * u[None, :] + np.sin(s)[:, None] * v[None, :]))


def _forbidden_cap(ax, a_c: np.ndarray, theta_c: float, color: str) -> None:
    """The forbidden region {x : a_c^T x < cos theta_c}: a cap of radius pi - theta_c around -a_c.

    The forbidden region of a narrow keep-in cone (theta_c < 90 deg) covers more than half the
    sphere: it gets its boundary and a faint fill only, so that it never hides the keep-out
    cones (small forbidden caps) drawn over it.
    """
    radius = np.pi - theta_c
    centre = -a_c / np.linalg.norm(a_c)
    wide = radius > np.pi / 2
    for frac, alpha in ((1.0, 0.35), (0.66, 0.25), (0.33, 0.2)):
        if wide and frac < 1.0:
            continue
        ring = _circle(centre, radius * frac)
        ax.plot(ring[:, 0], ring[:, 1], ring[:, 2], color=color, alpha=alpha + 0.3, linewidth=1.0)
    # Filled surface of the cap.
    r = np.linspace(0.0, radius, 12)
    s = np.linspace(0.0, 2.0 * np.pi, 48)
    helper = np.array([1.0, 0.0, 0.0]) if abs(centre[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(centre, helper)
    u /= np.linalg.norm(u)
    v = np.cross(centre, u)
    rr, ss = np.meshgrid(r, s)
    pts = (np.cos(rr)[..., None] * centre + np.sin(rr)[..., None]
           * (np.cos(ss)[..., None] * u + np.sin(ss)[..., None] * v))
    ax.plot_surface(pts[..., 0], pts[..., 1], pts[..., 2], color=color, alpha=0.06 if wide else 0.25,
                    linewidth=0)


def sphere(run: Run) -> Path:
    """The body axes of the cones on the unit sphere, the cones and the desired direction."""
    q = run.columns_of("q_w", "q_x", "q_y", "q_z")
    qg = run.columns_of("qg_w", "qg_x", "qg_y", "qg_z")
    qd = run.columns_of("qd_w", "qd_x", "qd_y", "qd_z")
    R, Rg, Rd = _rotations(q), _rotations(qg), _rotations(qd)
    cones = _cones(run)
    fig = Figure(figsize=(FIGSIZE[0], FIGSIZE[0] * 0.85), dpi=DPI)
    ax = fig.add_subplot(projection="3d")
    u = np.linspace(0, 2 * np.pi, 40)
    v = np.linspace(0, np.pi, 20)
    ax.plot_wireframe(np.outer(np.cos(u), np.sin(v)), np.outer(np.sin(u), np.sin(v)),
                      np.outer(np.ones_like(u), np.cos(v)), color="0.8", linewidth=0.3)
    axes_b = []
    for cone in cones:
        a_b = np.asarray(cone["axis_b"], dtype=float)
        if not any(np.allclose(a_b, b) for b in axes_b):
            axes_b.append(a_b)
    if not axes_b:
        axes_b = [np.array([0.0, 0.0, 1.0])]
    # Each forbidden region in the colour of the body axis it constrains (cyan with one axis,
    # as in the paper's Fig. 2).
    # Wide forbidden regions (narrow keep-in cones) first, faint: the small ones stay visible.
    for cone in sorted(cones, key=lambda c: float(c["theta_c_deg"])):
        a_b = np.asarray(cone["axis_b"], dtype=float)
        k = next(i for i, b in enumerate(axes_b) if np.allclose(a_b, b))
        _forbidden_cap(ax, np.asarray(cone["direction_i"], dtype=float),
                       np.radians(float(cone["theta_c_deg"])), "c" if len(axes_b) == 1 else f"C{k}")
    ref_label = "R_p(σ) a_b (plan at the governed clock)" if _planned(run) else "R_g a_b"
    for k, a_b in enumerate(axes_b):
        path = R @ a_b
        ref = Rg @ a_b
        des = Rd @ a_b
        col = f"C{k}"
        label = f"body axis {np.array2string(a_b, precision=2)}"
        ax.plot(path[:, 0], path[:, 1], path[:, 2], color=col, linewidth=2.0, label=f"R a_b, {label}")
        ax.plot(ref[:, 0], ref[:, 1], ref[:, 2], color=col, linestyle="--", linewidth=1.0,
                label=ref_label)
        ax.scatter(*path[0], color=col, marker="o", s=25)
        ax.scatter(*des[-1], color="m", marker="*", s=120,
                   label="desired R_d a_b" if k == 0 else None)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("x_i")
    ax.set_ylabel("y_i")
    ax.set_zlabel("z_i")
    ax.set_title(title(run, "body axes on the unit sphere; forbidden regions shaded"))
    ax.legend(loc="upper left", fontsize="small")
    return save(fig, run, "pet_erg_sphere.png")


def errors(run: Run) -> Path:
    """phi(R, R_d) and phi(R_g, R_d) (planned: phi(R_p(sigma), R_d)) on a log scale."""
    t = run.column("t")
    fig, (ax,) = new_figure()
    ax.semilogy(t, positive_or_nan(run.column("attitude_error")), label="φ(R, R_d)")
    if _planned(run):
        ax.semilogy(t, positive_or_nan(run.column("reference_error")), "--",
                    label="φ(R_p(σ), R_d): plan R_p(σ)")
        ax.set_title(title(run, "attitude error and the plan R_p(σ)'s distance to R_d "
                                "(log scale)"))
    else:
        ax.semilogy(t, positive_or_nan(run.column("reference_error")), "--", label="φ(R_g, R_d)")
        ax.set_title(title(run, "attitude and reference errors (log scale)"))
    ax.set_ylabel("attitude error φ [-]")
    ax.legend(loc="best")
    return save(fig, run, "pet_erg_errors.png")


def _shade_trigger(ax, t: np.ndarray, trigger: np.ndarray) -> None:
    """Blue where the reference updates (trigger set), red where it is held."""
    edges = np.flatnonzero(np.diff(trigger)) + 1
    starts = np.concatenate(([0], edges))
    ends = np.concatenate((edges, [len(t) - 1]))
    used = set()
    for a, b in zip(starts, ends):
        on = trigger[a] > 0.5
        label = ("reference updating" if on else "reference held")
        ax.axvspan(t[a], t[b], color="tab:blue" if on else "tab:red", alpha=0.12, linewidth=0,
                   label=None if label in used else label)
        used.add(label)


def _shade_inadmissible(ax, t: np.ndarray, admissible: np.ndarray) -> None:
    """Red where the last choice of s_dot met no threshold (admissible = 0)."""
    bad = admissible < 0.5
    if not np.any(bad):
        return
    edges = np.flatnonzero(np.diff(bad.astype(int))) + 1
    starts = np.concatenate(([0], edges))
    ends = np.concatenate((edges, [len(t) - 1]))
    first = True
    for a, b in zip(starts, ends):
        if bad[a]:
            ax.axvspan(t[a], t[b], color="tab:red", alpha=0.15, linewidth=0,
                       label="choice of ṡ inadmissible (clock braked)" if first else None)
            first = False


def _lyapunov_planned(run: Run) -> Path:
    """Planned runs: the tracking law's V against Gamma_g over the plan ahead (log scale)."""
    t = run.column("t")
    fig, (ax,) = new_figure()
    if "admissible" in run.columns:
        _shade_inadmissible(ax, t, run.column("admissible"))
    ax.semilogy(t, positive_or_nan(run.column("V")), color="k", linewidth=1.6,
                label="V of the tracking law (plan R_p(σ))")
    if "gamma_g" in run.columns and np.any(np.isfinite(run.column("gamma_g"))):
        ax.semilogy(t, positive_or_nan(run.column("gamma_g")), color="C2", linestyle="--",
                    label="Γ_g over the plan ahead")
    # V is round-off (1e-15 and below, or negative) once the body is on the plan or at rest:
    # the axis shows twelve decades below the largest value.
    top = np.nanmax(np.concatenate([positive_or_nan(line.get_ydata()) for line in ax.get_lines()]
                                   + [[np.nan]]))
    if np.isfinite(top):
        ax.set_ylim(top * 1e-12, top * 10.0)
    ax.set_ylabel("Lyapunov function and threshold")
    ax.set_title(title(run, "V of the tracking law and Γ_g (governor: planned)"))
    ax.legend(loc="best", fontsize="small")
    return save(fig, run, "pet_erg_lyapunov.png")


def lyapunov(run: Run) -> Path:
    """V with Gamma_d, Gamma_g and Gamma; held/updating intervals shaded."""
    if _planned(run):
        return _lyapunov_planned(run)
    t = run.column("t")
    fig, (ax,) = new_figure()
    if run.summary.get("governor") == "pet":
        _shade_trigger(ax, t, run.column("trigger"))
    ax.plot(t, run.column("V"), color="k", linewidth=1.6, label="V")
    ax.plot(t, run.column("gamma_d"), color="C1", linestyle=":", label="Γ_d")
    # gamma_g is written only with cones (without one Gamma_g = +inf).
    gamma_g = run.column("gamma_g") if "gamma_g" in run.columns else np.full_like(t, np.inf)
    if np.any(np.isfinite(gamma_g)):
        ax.plot(t, gamma_g, color="C2", linestyle="--", label="Γ_g(R_g)")
    ax.plot(t, run.column("gamma"), color="C3", linewidth=1.0, label="Γ = min{Γ_d, Γ_g, k_p(2−ε_Γ)}")
    top = np.nanmax(np.where(np.isfinite(gamma_g), gamma_g, np.nan)) if np.any(np.isfinite(gamma_g)) else 1.0
    ax.set_ylim(0.0, 1.1 * max(float(np.max(run.column("gamma"))), float(np.max(run.column("V"))),
                               min(float(top), 3.0 * float(np.max(run.column("gamma"))))))
    ax.set_ylabel("Lyapunov function and thresholds")
    ax.set_title(title(run, f"V and the safety thresholds (governor: {run.summary.get('governor', '?')})"))
    ax.legend(loc="best", fontsize="small")
    return save(fig, run, "pet_erg_lyapunov.png")


def torque(run: Run) -> Path:
    """‖τ‖ against τ_max, with the components."""
    t = run.column("t")
    fig, (ax,) = new_figure()
    for c in ("x", "y", "z"):
        ax.plot(t, run.column(f"tau_{c}"), linewidth=0.8, label=f"τ_{c}")
    ax.plot(t, run.column("tau_norm"), color="k", linewidth=1.6, label="‖τ‖")
    if _planned(run):
        tau_max = _tau_max(run)
        if tau_max is not None:
            ax.axhline(tau_max, color="r", linestyle="--", label="τ_max")
        if "torque_bound" in run.columns:
            ax.step(t, run.column("torque_bound"), where="post", color="C4", linestyle="-.",
                    linewidth=1.2, label="torque bound of the level set (last choice of ṡ)")
        ax.set_ylabel("control torque [N·m]")
        ax.set_title(title(run, "control torque, its limit and the governor's bound "
                                "(plan R_p(σ))"))
        ax.legend(loc="best", ncol=2, fontsize="small")
        return save(fig, run, "pet_erg_torque.png")
    tau_max = run.summary.get("tau_max")
    if isinstance(tau_max, (int, float)):
        ax.axhline(tau_max, color="r", linestyle="--", label="τ_max")
    ax.set_ylabel("control torque [N·m]")
    ax.set_title(title(run, "control torque and its limit"))
    ax.legend(loc="best", ncol=3)
    return save(fig, run, "pet_erg_torque.png")


def margins(run: Run) -> Path:
    """Margins a_c^T R a_b − cos θ_c of every cone (≥ 0 when the constraint holds)."""
    t = run.column("t")
    fig, (ax,) = new_figure()
    i = 0
    while f"margin_{i}" in run.columns:
        ax.plot(t, run.column(f"margin_{i}"), label=f"cone {i}")
        i += 1
    ax.axhline(0.0, color="r", linestyle="--", linewidth=1.0)
    ax.set_ylabel("pointing margin [-]")
    ax.set_title(title(run, "pointing-constraint margins (2b)"))
    if i:
        ax.legend(loc="best")
    return save(fig, run, "pet_erg_margins.png")


def progress(run: Run) -> Path:
    """Planned runs: the plan's clock sigma and its rate s_dot against t (where it slowed or
    held)."""
    t = run.column("t")
    sigma = run.column("s")
    rate = run.column("s_dot")
    fig, (ax_s, ax_r) = new_figure(2)
    admissible = run.column("admissible") if "admissible" in run.columns else None
    for ax in (ax_s, ax_r):
        if admissible is not None:
            _shade_inadmissible(ax, t, admissible)
    t_p = _plan_duration(run)
    ax_s.plot(t, sigma, color="k", linewidth=1.6, label="σ (plan clock)")
    ax_s.plot(t, np.minimum(t, t_p) if t_p is not None else t, color="0.5", linestyle=":",
              linewidth=1.0, label="σ at ṡ = 1 (the plan's own time)")
    if t_p is not None:
        ax_s.axhline(t_p, color="C2", linestyle="--", linewidth=1.0,
                     label=f"T_p = {t_p:.4g} s (plan's end)")
    ax_s.set_ylabel("plan clock σ [s]")
    ax_s.legend(loc="lower right", fontsize="small")
    ax_r.step(t, rate, where="post", color="C0", linewidth=1.4, label="ṡ")
    held = rate <= 0.0
    if t_p is not None:
        held &= sigma < t_p
    if np.any(held):
        ax_r.plot(t[held], rate[held], "o", color="tab:red", markersize=3,
                  label="clock held (ṡ = 0, σ < T_p)")
    ax_r.set_ylim(-0.05, 1.1)
    ax_r.set_ylabel("clock rate ṡ [-]")
    ax_r.legend(loc="lower right", fontsize="small")
    ax_s.set_title(title(run, "plan R_p(σ): governed clock σ and its rate ṡ"))
    return save(fig, run, "pet_erg_progress.png")


def plot(run: Run) -> list[Path]:
    """Every pet_erg figure (paper Figs. 2-5 and the margins); returns the paths written.

    A planned run (governor = "planned") also gets the plan clock's figure, after the torque."""
    if _planned(run):
        return [sphere(run), errors(run), lyapunov(run), torque(run), progress(run), margins(run)]
    return [sphere(run), errors(run), lyapunov(run), torque(run), margins(run)]
