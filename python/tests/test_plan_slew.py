"""attiguard.plan_slew: the slew planner (docs/slew-planner.md) from Python, its arrays checked
against the closed form, the cones and the torque bound computed here in numpy, and its errors."""

from __future__ import annotations

import json
import math
import os
import subprocess
import threading
import time
import tomllib
from pathlib import Path

import numpy as np
import pytest

import attiguard as ag

REPO = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("ATTIGUARD_BUILD_DIR", REPO / "build")).resolve()
TAU_MAX = 0.1
HEADROOM = 0.05


def rot_x(angle: float) -> np.ndarray:
    return ag.expm([angle, 0.0, 0.0])


def rot_z(angle: float) -> np.ndarray:
    return ag.expm([0.0, 0.0, angle])


def closed_form(theta: float, j: float, tau: float) -> float:
    """Rest-to-rest eigenaxis bang-bang time of a symmetric body at the torque bound tau."""
    return 2.0 * math.sqrt(theta * j / tau)


def rotations_of(q: np.ndarray) -> np.ndarray:
    return np.array([ag.quat_to_rotation(qi) for qi in q])


@pytest.fixture(scope="module")
def free_slew() -> ag.PlannedSlew:
    return ag.plan_slew(0.5 * np.eye(3), np.eye(3), rot_z(math.pi / 2), TAU_MAX)


SUN = np.array([0.0, -1.0, 1.0]) / math.sqrt(2.0)  # halfway along +z's eigenaxis path


@pytest.fixture(scope="module")
def sun_slew() -> ag.PlannedSlew:
    cone = ag.keep_out_cone([0, 0, 1], SUN, half_angle_deg=20.0)
    return ag.plan_slew(0.5 * np.eye(3), np.eye(3), rot_x(math.pi / 2), TAU_MAX, [cone],
                        cone_margin_deg=1.0)


def test_symmetric_body_matches_the_closed_form(free_slew):
    p = free_slew
    expected = closed_form(math.pi / 2, 0.5, TAU_MAX * (1.0 - HEADROOM))
    assert p.duration == pytest.approx(expected, rel=5e-3)
    assert p.bang_bang_time == pytest.approx(closed_form(math.pi / 2, 0.5, TAU_MAX), rel=1e-9)
    assert p.ratio == pytest.approx(p.duration / p.bang_bang_time)
    assert p.ratio == pytest.approx(1.0 / math.sqrt(1.0 - HEADROOM), rel=5e-3)
    assert p.smallest_cone_margin_deg is None and p.smallest_margin_cone is None
    assert p.largest_torque_ratio <= 1.0 - HEADROOM + 1e-6
    assert p.solves >= 1 and p.iterations >= 1 and p.ways_tried >= 1
    assert p.intervals == len(p.t_nodes) - 1 and p.planning_seconds > 0.0
    assert isinstance(p.solver_status, str) and p.solver_status
    assert p.report["duration"] == p.duration and set(p.report) >= {"ratio", "solver_status"}


def test_samples_are_the_plan_at_points_per_interval(free_slew):
    p = free_slew
    n = p.intervals * 10 + 1
    assert p.t.shape == (n,) and p.q.shape == (n, 4) and p.R.shape == (n, 3, 3)
    assert p.omega_b.shape == (n, 3) and p.tau_b.shape == (n, 3) and p.omega_dot_b.shape == (n, 3)
    assert p.t[0] == 0.0 and p.t[-1] == pytest.approx(p.duration, rel=1e-12)
    assert np.all(np.diff(p.t) > 0.0)
    assert np.allclose(p.t[::10], p.t_nodes, rtol=1e-12, atol=1e-12)  # every 10th is a node
    assert np.allclose(np.linalg.norm(p.q, axis=1), 1.0, atol=1e-12)
    assert np.allclose(rotations_of(p.q), p.R, atol=1e-9)
    # The ends: at rest, at R_start and R_target (either sign of q).
    assert np.allclose(p.R[0], np.eye(3), atol=1e-6)
    assert np.allclose(p.R[-1], rot_z(math.pi / 2), atol=1e-6)
    assert np.allclose(p.omega_b[[0, -1]], 0.0, atol=1e-8)
    # The torque bound at every sample, and the slew is fast: it uses the torque.
    norms = np.linalg.norm(p.tau_b, axis=1)
    assert norms.max() <= TAU_MAX * (1.0 - HEADROOM) * (1.0 + 1e-6)
    assert norms.max() >= 0.99 * TAU_MAX * (1.0 - HEADROOM)
    # The rate about z peaks at mid-slew (bang-bang: accelerate, then brake).
    k = int(np.argmax(p.omega_b[:, 2]))
    assert p.t[k] == pytest.approx(0.5 * p.duration, rel=0.05)
    assert np.abs(p.omega_b[:, :2]).max() < 1e-6


def test_points_per_interval_and_intervals_are_honoured():
    p = ag.plan_slew(0.5 * np.eye(3), np.eye(3), rot_z(0.5), TAU_MAX, intervals=8,
                     points_per_interval=3)
    assert p.intervals == 8 and p.t.shape == (8 * 3 + 1,) and p.t_nodes.shape == (9,)
    assert p.duration == pytest.approx(closed_form(0.5, 0.5, TAU_MAX * (1 - HEADROOM)), rel=5e-3)


def test_keep_out_cone_on_the_eigenaxis_path_is_kept_everywhere(sun_slew):
    p = sun_slew
    # The body +z axis in the inertial frame at every sample, from R and from q.
    for R in (p.R, rotations_of(p.q)):
        z_i = R[:, :, 2]
        angle = np.degrees(np.arccos(np.clip(z_i @ SUN, -1.0, 1.0)))
        assert angle.min() >= 20.0 + 1.0 - 1e-3, f"the +z axis came {angle.min()} deg from the Sun"
    # It had to go round: slower than the unconstrained closed form, and the report says so.
    free = closed_form(math.pi / 2, 0.5, TAU_MAX * (1.0 - HEADROOM))
    assert p.duration > 1.005 * free
    assert p.ratio > 1.0 / math.sqrt(1.0 - HEADROOM)
    assert p.smallest_cone_margin_deg >= 1.0 - 1e-6 and p.smallest_margin_cone == 0
    assert np.linalg.norm(p.tau_b, axis=1).max() <= TAU_MAX * (1.0 - HEADROOM) * (1.0 + 1e-6)
    assert np.allclose(p.R[-1], rot_x(math.pi / 2), atol=1e-6)


def test_target_inside_a_keep_out_cone_is_a_verification_failure():
    cone = ag.keep_out_cone([0, 0, 1], [0, -1, 0], half_angle_deg=20.0)
    with pytest.raises(ag.VerificationFailure, match=r"no admissible path.*target.*cones\[0\]") as e:
        ag.plan_slew(0.5 * np.eye(3), np.eye(3), rot_x(math.pi / 2), TAU_MAX, [cone])
    assert e.value.exit_code == 4
    assert str(e.value).startswith("plan_slew(): ")


@pytest.mark.parametrize("change, match", [
    (dict(R_start=1.01 * np.eye(3)), r"plan_slew\(\): R_start: not a rotation matrix"),
    (dict(R_target=np.diag([1.0, 1.0, -1.0])), r"plan_slew\(\): R_target: not a rotation matrix: det = -1"),
    (dict(J=np.diag([0.5, math.nan, 0.5])), r"plan_slew\(\): J: .*non-finite"),
    (dict(J=np.diag([1.0, 1.0, 3.0])), r"plan_slew\(\): J: .*triangle"),
    (dict(tau_max=0.0), r"plan_slew\(\): tau_max: must be > 0"),
    (dict(tau_max=-1.0), r"plan_slew\(\): tau_max:"),
    (dict(tau_max=math.nan), r"plan_slew\(\): tau_max:"),
    (dict(torque_headroom=1.0), r"plan_slew\(\): torque_headroom: must be >= 0 and < 1"),
    (dict(cone_margin_deg=90.0), r"plan_slew\(\): cone_margin_deg: must be >= 0 and < 90"),
    (dict(intervals=2), r"plan_slew\(\): intervals:"),
    (dict(points_per_interval=0), r"plan_slew\(\): points_per_interval:"),
])
def test_malformed_arguments_raise_the_input_error(change, match):
    args = dict(J=0.5 * np.eye(3), R_start=np.eye(3), R_target=rot_z(1.0), tau_max=TAU_MAX)
    args.update(change)
    with pytest.raises(ag.InputError, match=match) as e:
        ag.plan_slew(**args)
    assert isinstance(e.value, ValueError) and e.value.exit_code == 2


def test_wrong_types_raise_type_error():
    with pytest.raises(TypeError, match="cones"):
        ag.plan_slew(0.5 * np.eye(3), np.eye(3), rot_z(1.0), TAU_MAX,
                     ag.keep_out_cone([0, 0, 1], [1, 0, 0], half_angle_deg=10.0))
    with pytest.raises(TypeError):
        ag.plan_slew(0.5 * np.eye(3), np.eye(3), rot_z(1.0), TAU_MAX, [None])
    with pytest.raises(TypeError, match="intervals"):
        ag.plan_slew(0.5 * np.eye(3), np.eye(3), rot_z(1.0), TAU_MAX, intervals=8.0)
    with pytest.raises(TypeError):
        ag.plan_slew(np.eye(2), np.eye(3), rot_z(1.0), TAU_MAX)


def test_the_gil_is_released_while_planning():
    """Another Python thread runs while the planner works: no pause of the main thread as long
    as the planning."""
    cone = ag.keep_out_cone([0, 0, 1], SUN, half_angle_deg=20.0)
    result: list[ag.PlannedSlew] = []
    worker = threading.Thread(target=lambda: result.append(ag.plan_slew(
        0.5 * np.eye(3), np.eye(3), rot_x(math.pi / 2), TAU_MAX, [cone], cone_margin_deg=1.0)))
    last, longest = time.perf_counter(), 0.0
    worker.start()
    while worker.is_alive():
        now = time.perf_counter()
        longest, last = max(longest, now - last), now
    worker.join()
    seconds = result[0].planning_seconds
    if seconds < 0.05:
        pytest.skip(f"planning took {seconds:.3f} s: too short to tell")
    assert longest < 0.5 * seconds, f"the main thread paused {longest:.3f} s of {seconds:.3f} s"


def test_arrays_agree_with_the_cli_plan_csv(tmp_path):
    """The same problem as `attiguard plan examples/pet_erg_slew170.toml` (three cones, products
    of inertia, 170 deg): the same plan, sample for sample (plan.csv, plan.json)."""
    cli = BUILD / "src" / "attiguard"
    if not cli.is_file():
        pytest.skip(f"no CLI at {cli}")
    path = REPO / "examples" / "pet_erg_slew170.toml"
    proc = subprocess.run([str(cli), "plan", str(path), "--out", str(tmp_path)],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    summary = json.loads((tmp_path / "plan.json").read_text())
    csv = np.genfromtxt(tmp_path / "plan.csv", delimiter=",", names=True)

    sc = tomllib.loads(path.read_text())
    make = {"keep_out": ag.keep_out_cone, "keep_in": ag.keep_in_cone}
    cones = [make[c["type"]](c["axis_b"], c["direction_i"], half_angle_deg=c["half_angle_deg"])
             for c in sc["cones"]]
    target = sc["desired"]["attitude"]
    R_target = ag.expm(np.radians(target["angle_deg"]) * np.array(target["axis"], dtype=float))
    p = ag.plan_slew(sc["body"]["inertia"], np.eye(3), R_target, summary["torque_limit"], cones)

    assert p.duration == pytest.approx(summary["duration"], rel=1e-6)
    assert p.intervals == summary["intervals"] and p.ways_tried == summary["ways_tried"]
    assert p.smallest_cone_margin_deg == pytest.approx(summary["smallest_cone_margin_deg"], abs=1e-4)
    assert p.smallest_margin_cone == summary["smallest_margin_cone"]
    assert p.largest_torque_ratio == pytest.approx(summary["largest_torque_ratio"], rel=1e-6)
    assert p.t.shape == csv["t"].shape
    assert np.allclose(p.t, csv["t"], rtol=1e-6, atol=1e-9)
    q_csv = np.column_stack([csv[c] for c in ("q_w", "q_x", "q_y", "q_z")])
    w_csv = np.column_stack([csv[c] for c in ("omega_x", "omega_y", "omega_z")])
    tau_csv = np.column_stack([csv[c] for c in ("tau_x", "tau_y", "tau_z")])
    assert np.allclose(p.q, q_csv, atol=1e-6)
    assert np.allclose(p.omega_b, w_csv, atol=1e-7)
    assert np.allclose(p.tau_b, tau_csv, atol=1e-6 * summary["torque_limit"])
