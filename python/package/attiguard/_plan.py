"""attiguard.plan_slew: the slew planner of `attiguard plan` (docs/slew-planner.md) from Python,
the plan returned as numpy arrays (PlannedSlew)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import _core

_Array = NDArray[np.float64]


@dataclass
class PlannedSlew:
    """The result of attiguard.plan_slew (docs/slew-planner.md, "The plan as a trajectory").

    Samples (n = intervals * points_per_interval + 1, both ends of each interval, as plan.csv of
    `attiguard plan`): `t` (n,) [s], `q` (n, 4) q_ib scalar first, `R` (n, 3, 3) body to inertial,
    `omega_b` (n, 3) [rad/s], `omega_dot_b` (n, 3) [rad/s^2], `tau_b` (n, 3) the control torque
    [N m]. Nodes of the transcription: `t_nodes` (N+1,), `q_nodes` (N+1, 4), `omega_b_nodes`,
    `tau_b_nodes` (N+1, 3).

    Report (plan.json's figures): `duration` [s]; `bang_bang_time` the eigenaxis rest-to-rest
    bang-bang time at the full tau_max [s]; `ratio` = duration / bang_bang_time;
    `smallest_cone_margin_deg` the dense check's smallest cone margin in DEGREES (None without
    cones), with `smallest_margin_cone` and `smallest_margin_time` [s]; `largest_torque_ratio`
    max |tau| / tau_max and `largest_torque_time` [s]; `largest_attitude_deviation` [rad] (the
    plan's dynamic consistency); `intervals`, `path_waypoints`, `ways_tried`,
    `roadmap_attitudes`, `solves`, `iterations`, `solver_status` (IPOPT's), `planning_seconds`.
    `report` holds these as a dict.
    """

    t: _Array = field(repr=False)
    q: _Array = field(repr=False)
    R: _Array = field(repr=False)
    omega_b: _Array = field(repr=False)
    omega_dot_b: _Array = field(repr=False)
    tau_b: _Array = field(repr=False)
    t_nodes: _Array = field(repr=False)
    q_nodes: _Array = field(repr=False)
    omega_b_nodes: _Array = field(repr=False)
    tau_b_nodes: _Array = field(repr=False)
    duration: float
    bang_bang_time: float
    ratio: float
    smallest_cone_margin_deg: float | None
    smallest_margin_cone: int | None
    smallest_margin_time: float | None
    largest_torque_ratio: float
    largest_torque_time: float
    largest_attitude_deviation: float
    intervals: int
    path_waypoints: int
    ways_tried: int
    roadmap_attitudes: int
    solves: int
    iterations: int
    solver_status: str
    planning_seconds: float

    @property
    def report(self) -> dict[str, Any]:
        """The report's figures as a dict (the names above; plan.json's content)."""
        return {name: getattr(self, name) for name in _REPORT_FIELDS}


_REPORT_FIELDS = (
    "duration", "bang_bang_time", "ratio", "smallest_cone_margin_deg", "smallest_margin_cone",
    "smallest_margin_time", "largest_torque_ratio", "largest_torque_time",
    "largest_attitude_deviation", "intervals", "path_waypoints", "ways_tried",
    "roadmap_attitudes", "solves", "iterations", "solver_status", "planning_seconds",
)


def plan_slew(J: ArrayLike, R_start: ArrayLike, R_target: ArrayLike, tau_max: float,
              cones: Sequence[_core.Cone] = (), *, torque_headroom: float = 0.05,
              cone_margin_deg: float = 0.0, intervals: int = 0,
              points_per_interval: int = 10) -> PlannedSlew:
    """Plans a near time-optimal rest-to-rest slew that keeps every cone and the torque bound.

    The planner of `attiguard plan` (docs/slew-planner.md): from R_start to R_target (rotation
    matrices body to inertial, at rest at both ends) for the inertia J [kg m^2], with
    |tau|_2 <= (1 - torque_headroom) tau_max [N m], keeping every cone (attiguard.keep_in_cone /
    keep_out_cone) with cone_margin_deg DEGREES to spare (the [plan] keys torque_headroom,
    cone_margin_deg and intervals of a scenario file; intervals 0: derived). The plan is sampled
    at points_per_interval points per interval (both ends included), as plan.csv. The GIL is
    released while planning (milliseconds to seconds).

    Raises attiguard.InputError (a ValueError) for a malformed argument (J not symmetric positive
    definite or not physical, a rotation that is not one, NaN, tau_max <= 0, ...), naming it;
    attiguard.VerificationFailure (exit code 4) when there is no admissible path (the start or
    target breaks a cone or its margin, or the cones close every way), with the reason;
    attiguard.NumericalError when the solver fails.
    """
    if isinstance(cones, _core.Cone):
        raise TypeError("plan_slew(): cones: expected a sequence of Cone, got one Cone (write [cone])")
    if isinstance(cones, (str, bytes)) or not isinstance(cones, Sequence):
        raise TypeError(f"plan_slew(): cones: expected a sequence of Cone, got {type(cones).__name__}")
    for name, value in (("torque_headroom", torque_headroom), ("cone_margin_deg", cone_margin_deg),
                        ("tau_max", tau_max)):
        if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
            raise TypeError(f"plan_slew(): {name}: must be a number, got {type(value).__name__}")
    for name, value in (("intervals", intervals), ("points_per_interval", points_per_interval)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
            raise TypeError(f"plan_slew(): {name}: must be an integer, got {type(value).__name__}")
    out = _core._plan_slew(J, R_start, R_target, float(tau_max), list(cones),
                           float(torque_headroom), float(cone_margin_deg), int(intervals),
                           int(points_per_interval))
    report = out.pop("report")
    return PlannedSlew(**out, **report)
