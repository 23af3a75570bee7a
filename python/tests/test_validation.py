"""Property test: every public callable of `attiguard` validates its arguments like the CLI
(docs/python.md, "Validation").

The callables are found by introspection (the module's __all__, each class's constructor and
its own public methods), so a new one is covered: test_every_public_callable_has_a_spec fails
until SPECS below describes its arguments (or EXEMPT says why it takes none worth checking).
For each callable, each argument is replaced in turn by hostile values of its kind — NaN, ±inf
at every position, non-rotations, non-unit quaternions, zero axes, non-positive gains and
steps, wrong shapes, wrong types, cyclic and over-deep dicts — deterministic ones plus random
ones (stdlib `random`, seeded; ATTIGUARD_VALIDATION_SEED overrides the seed, _TRIALS the
count). Every such call must raise ValueError or TypeError. Valid random arguments must return
results without NaN or inf. Each callable's sweep runs in a child interpreter (limited to
1 GiB of address space and a timeout), so a crash or a runaway allocation is a test failure,
not a dead test run.
"""

from __future__ import annotations

import inspect
import json
import math
import os
import random
import subprocess
import sys
import tomllib
from pathlib import Path
from typing import Any, Callable, Iterator

import pytest

REPO = Path(__file__).resolve().parents[2]
SEED = int(os.environ.get("ATTIGUARD_VALIDATION_SEED", "27"))
TRIALS = int(os.environ.get("ATTIGUARD_VALIDATION_TRIALS", "40"))
CHILD_TIMEOUT_S = 300
CHILD_ADDRESS_SPACE = 1 << 30

NAN, INF = math.nan, math.inf
WRONG_TYPES: list[Any] = ["abc", None, {"a": 1}, object()]


# ---- valid values and hostile values of each argument kind --------------------------------------

def _np():
    import numpy as np

    return np


def random_rotation(rng: random.Random):
    import attiguard as ag

    w = [rng.gauss(0.0, 1.0) for _ in range(3)]
    return ag.expm(w)


def random_unit_quat(rng: random.Random) -> list[float]:
    q = [rng.gauss(0.0, 1.0) for _ in range(4)]
    n = math.sqrt(sum(x * x for x in q)) or 1.0
    return [x / n for x in q]


def random_vec3(rng: random.Random, scale: float = 1.0) -> list[float]:
    return [rng.uniform(-scale, scale) for _ in range(3)]


def _with_bad_entry(value, bad: float, index: int):
    np = _np()
    a = np.array(value, dtype=float)
    a.flat[index % a.size] = bad
    return a


def non_finite(value, rng: random.Random) -> Iterator[Any]:
    """value with NaN, +inf, -inf at every position (and one random extra)."""
    size = _np().array(value, dtype=float).size
    for bad in (NAN, INF, -INF):
        for i in range(size):
            yield _with_bad_entry(value, bad, i)
    yield _with_bad_entry(value, rng.choice((NAN, INF, -INF)), rng.randrange(size))


def wrong_shapes(value) -> Iterator[Any]:
    np = _np()
    a = np.array(value, dtype=float)
    if a.ndim == 1:
        yield a[:-1]
        yield np.append(a, 1.0)
        yield np.eye(3)
    else:
        yield a[:2, :2]
        yield np.hstack([a, np.ones((3, 1))])
        yield a[0]
    yield ["x"] * a.size                         # strings (numeric strings numpy converts, as asarray)
    yield 1.0


def hostile_vec3(rng, base):
    yield from non_finite(base, rng)
    yield from wrong_shapes(base)
    yield from WRONG_TYPES


def hostile_optional_vec3(rng, base):
    """An optional 3-vector: None leaves it out, every other hostile value is refused."""
    yield from (x for x in hostile_vec3(rng, base) if x is not None)


def hostile_matrix(rng, base):
    yield from non_finite(base, rng)
    yield from wrong_shapes(base)
    yield from WRONG_TYPES


def hostile_rotation(rng, base):
    np = _np()
    R = np.array(base, dtype=float)
    yield from hostile_matrix(rng, R)
    yield 2.0 * R                                # lyapunov(2I, 0, I) used to give -7.5
    yield R * (1.0 + 1e-6)                      # just outside the 1e-9 tolerance
    yield -R                                    # a reflection (det -1)
    yield np.zeros((3, 3))
    yield np.array([[rng.gauss(0, 1) for _ in range(3)] for _ in range(3)])
    E = R.copy()
    E[rng.randrange(3), rng.randrange(3)] += 1e-3
    yield E


def hostile_quat(rng, base):
    np = _np()
    q = np.array(base, dtype=float)
    yield from non_finite(q, rng)
    yield from wrong_shapes(q)
    yield from WRONG_TYPES
    yield np.zeros(4)
    yield 2.0 * q
    yield q * (1.0 + 1e-6)
    yield q * rng.uniform(0.0, 0.99)


def hostile_axis(rng, base):
    yield from hostile_vec3(rng, base)
    yield [0.0, 0.0, 0.0]


def hostile_skew(rng, base):
    np = _np()
    yield from hostile_matrix(rng, base)
    yield np.eye(3)
    yield np.array(base) + np.diag([1e-3, 0.0, 0.0])


def hostile_inertia(rng, base):
    np = _np()
    yield from hostile_matrix(rng, base)
    yield np.diag([1.0, 1.0, 3.0])              # triangle inequality
    yield np.diag([1.0, -2.0, 3.0])
    yield np.zeros((3, 3))
    yield np.array([[1.0, 0.5, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.5]])  # not symmetric


def _hostile_number(rng, lower_bad: list[float]):
    yield NAN
    yield INF
    yield -INF
    yield from lower_bad
    yield -rng.uniform(1e-300, 1e300)
    yield "1.0"
    yield None
    yield [1.0]


def hostile_positive(rng, base):
    yield from _hostile_number(rng, [0.0, -0.0, -1.0])


def hostile_nonnegative(rng, base):
    yield from _hostile_number(rng, [-1.0, -1e-300])


def hostile_real(rng, base):
    yield NAN
    yield INF
    yield -INF
    yield "1.0"
    yield None
    yield [1.0]


def hostile_angle(rng, base):
    yield from hostile_real(rng, base)
    yield 1e300
    yield -1e7


def hostile_bool(rng, base):
    yield "abc"
    yield None
    yield [True]
    yield 1.5


def hostile_str(rng, base):
    yield 5
    yield None
    yield ["pet"]
    yield "no_such_mode"


def hostile_cones(rng, base):
    yield 5
    yield "abc"
    yield [None]
    yield [5.0]
    yield None


def hostile_wheels(rng, base):
    good = {"axis_b": [1.0, 0.0, 0.0], "torque_max": 0.1, "momentum_max": 1.0}
    yield 5
    yield "abc"
    yield [None]
    yield [5.0]
    yield None
    yield [dict(good, axis_b=[0.0, 0.0, 0.0])]
    yield [dict(good, axis_b=[NAN, 0.0, 0.0])]
    yield [dict(good, axis_b=[1.0, 2.0])]
    yield [dict(good, axis_b="x")]
    yield [dict(good, torque_max=-1.0)]
    yield [dict(good, torque_max=INF)]
    yield [dict(good, momentum_max=0.0)]
    yield [dict(good, momentum_max="1.0")]
    yield [dict(good, momentum=2.0)]
    yield [dict(good, momentum=NAN)]
    yield [dict(good, spin=1.0)]
    yield [{"axis_b": [1.0, 0.0, 0.0], "torque_max": 0.1}]


def hostile_delay(rng, base):
    yield -1
    yield 2
    yield 0.5
    yield "1"
    yield None


def hostile_waypoints(rng, base):
    yield "abc"
    yield [[NAN, 0.0, 0.0]]
    yield [[0.0, INF, 0.0], [1.0, 2.0, 3.0]]
    yield [[1.0, 2.0]]
    yield [None]
    yield 5


def hostile_path(rng, base):
    yield 5
    yield None
    yield str(REPO / "no_such_dir" / "no_such_file.toml")
    yield str(REPO / "examples")                # a directory
    yield ["x.toml"]


def hostile_headroom(rng, base):
    yield from hostile_nonnegative(rng, base)
    yield 1.0
    yield 1.5


def hostile_margin_deg(rng, base):
    yield from hostile_nonnegative(rng, base)
    yield 90.0
    yield 1e3


def hostile_intervals(rng, base):
    yield -1
    yield 2
    yield 2001
    yield 8.0
    yield "8"
    yield None
    yield 10 ** 40


def hostile_points(rng, base):
    yield 0
    yield -1
    yield 1001
    yield 2.0
    yield "2"
    yield None


def hostile_out(rng, base):
    yield 5
    yield ["out"]
    yield {"out": 1}


def _small_scenario() -> dict:
    sc = tomllib.loads((REPO / "examples" / "rigid_body_free.toml").read_text())
    sc["simulation"]["duration"] = 0.1
    return sc


def _nan_scenarios(rng) -> Iterator[dict]:
    """The small scenario with NaN / inf at every numeric leaf in turn."""
    def leaves(d, path=()):
        for k, v in d.items():
            if isinstance(v, dict):
                yield from leaves(v, path + (k,))
            elif isinstance(v, (int, float)) and not isinstance(v, bool):
                yield path + (k,), None
            elif isinstance(v, list) and v and all(isinstance(x, (int, float)) for x in v):
                for i in range(len(v)):
                    yield path + (k,), i

    base = _small_scenario()
    for path, index in leaves(base):
        sc = json.loads(json.dumps(base))
        table = sc
        for k in path[:-1]:
            table = table[k]
        bad = rng.choice((NAN, INF, -INF))
        if index is None:
            table[path[-1]] = bad
        else:
            table[path[-1]][index] = bad
        yield sc


def hostile_scenario(rng, base):
    yield 5
    yield None
    yield [1, 2]
    yield str(REPO / "no_such_file.toml")
    cyclic: dict = {"kind": "rigid_body"}
    cyclic["body"] = cyclic
    yield cyclic
    wide: dict = {"kind": "rigid_body"}
    wide["a"] = [wide, wide]
    yield wide
    deep: dict = {}
    for _ in range(200_000):                    # used to overflow the C++ stack
        deep = {"a": deep}
    yield deep
    shared: list = [0.0]
    for _ in range(60):                         # a 2^60-leaf tree sharing its sub-lists
        shared = [shared, shared]
    yield {"kind": "rigid_body", "s": shared}
    yield {"kind": "rigid_body", "n": 10 ** 40}
    yield {"kind": "rigid_body", "n": None}
    yield {"kind": "rigid_body", "n": object()}
    yield from _nan_scenarios(rng)


# ---- the specification of every public callable -------------------------------------------------
# A spec: (factory, arguments). factory() returns the callable bound to a fresh object (for a
# method) or the function itself; arguments: name -> (valid-value generator, hostile generator,
# passed by keyword?). `check_output`: whether valid calls are made and their results checked
# (False for the scenario runs: they are covered by their own tests).

OMIT = object()  # the valid value of an optional argument that is left out


def hostile_second_angle(rng, base):
    """The other of two exclusive arguments (half_angle_deg / half_angle_rad): given too."""
    yield 1.0
    yield from (x for x in hostile_positive(rng, base) if x is not None)  # None: left out


class Arg:
    def __init__(self, valid: Callable[[random.Random], Any], hostile: Callable, keyword: bool = False):
        self.valid, self.hostile, self.keyword = valid, hostile, keyword


def _J(rng=None):
    return _np().diag([1.0, 2.0, 3.0])


def _rot(rng):
    return random_rotation(rng)


def _vec(rng):
    return random_vec3(rng)


def _quat(rng):
    return random_unit_quat(rng)


def _pos(lo=0.1, hi=10.0):
    return lambda rng: rng.uniform(lo, hi)


def _const(v):
    return lambda rng: v


def _governor():
    import attiguard as ag

    cone = ag.keep_in_cone([0, 0, 1], [-0.791, 0.061, -0.609], half_angle_deg=160.0)
    return ag.Governor(_J(), kp=5.0, kd=1.0, tau_max=2.5, cones=[cone], Ts=0.5)


def _reset_governor():
    g = _governor()
    g.reset(0.0, _np().eye(3))
    return g


_PLANNED_TEXT = '''kind = "pet_erg"
name = "validation_planned"
governor = "planned"
[body]
inertia = [1.0, 2.0, 3.0]
[desired]
attitude = { axis = [0.0, 0.0, 1.0], angle_deg = 60.0 }
[control]
tau_max = 1.0
[plan]
intervals = 8
[simulation]
duration = 10.0
output_interval = 1.0
'''
_PLANNED_PATH: list[str] = []


def _planned_path() -> str:
    """A small planned scenario (a 60 deg slew, no cone, 8 intervals: planned in milliseconds)."""
    if not _PLANNED_PATH:
        import tempfile

        d = tempfile.mkdtemp(prefix="attiguard_validation_")
        path = Path(d) / "planned.toml"
        path.write_text(_PLANNED_TEXT)
        _PLANNED_PATH.append(str(path))
    return _PLANNED_PATH[0]


def _reset_planned():
    import attiguard as ag

    g = ag.PlannedGovernor.from_scenario(_planned_path())
    g.reset(0.0)
    return g


def _cone():
    import attiguard as ag

    return ag.keep_in_cone([0, 0, 1], [0, 0, 1], half_angle_deg=40.0)


def _mission():
    import attiguard as ag

    return ag.Mission([[100.0, 0.0, 0.0]])


def _fn(name):
    def factory():
        import attiguard as ag

        return getattr(ag, name)
    return factory


def _method(make, name):
    return lambda: getattr(make(), name)


def _ctor(name):
    return _fn(name)


ROT = lambda: Arg(_rot, hostile_rotation)
VEC = lambda: Arg(_vec, hostile_vec3)
QUAT = lambda: Arg(_quat, hostile_quat)
SCEN = lambda: Arg(_const(None), hostile_scenario)

SPECS: dict[str, tuple[Callable[[], Callable], dict[str, Arg], bool]] = {
    "hat": (_fn("hat"), {"x": VEC()}, True),
    "vee": (_fn("vee"), {"X": Arg(lambda rng: _skew(rng), hostile_skew)}, True),
    "expm": (_fn("expm"), {"w": Arg(lambda rng: random_vec3(rng, 10.0), hostile_vec3)}, True),
    "logm": (_fn("logm"), {"R": ROT()}, True),
    "distance": (_fn("distance"), {"R1": ROT(), "R2": ROT()}, True),
    "phi": (_fn("phi"), {"R": ROT()}, True),
    "project_to_so3": (_fn("project_to_so3"),
                       {"M": Arg(lambda rng: _np().eye(3) + 0.1 * _np().array(
                           [[rng.uniform(-1, 1) for _ in range(3)] for _ in range(3)]),
                           lambda rng, base: (x for x in list(hostile_matrix(rng, base))
                                              + [_np().zeros((3, 3))]))}, True),
    "is_rotation": (_fn("is_rotation"),
                    {"M": Arg(_rot, hostile_matrix), "tol": Arg(_pos(1e-12, 1e-3), hostile_nonnegative)}, True),
    "quat_to_rotation": (_fn("quat_to_rotation"), {"q": QUAT()}, True),
    "rotation_to_quat": (_fn("rotation_to_quat"), {"R": ROT()}, True),
    "quat_multiply": (_fn("quat_multiply"), {"p": QUAT(), "q": QUAT()}, True),
    "quat_conjugate": (_fn("quat_conjugate"), {"q": QUAT()}, True),
    "quat_from_axis_angle": (_fn("quat_from_axis_angle"),
                             {"axis": Arg(_vec, hostile_axis),
                              "angle": Arg(lambda rng: rng.uniform(-10, 10), hostile_angle)}, True),
    "keep_in_cone": (_fn("keep_in_cone"),
                     {"axis_b": Arg(_const([0.0, 0.0, 1.0]), hostile_axis),
                      "direction_i": Arg(_const([0.0, 1.0, 0.0]), hostile_axis),
                      "half_angle_rad": Arg(_const(OMIT), hostile_second_angle, True),
                     "half_angle_deg": Arg(lambda rng: rng.uniform(30, 170), hostile_positive, True),
                      "delta_offset": Arg(_pos(0.01, 0.1), hostile_nonnegative, True),
                      "zeta_offset": Arg(_pos(0.01, 0.1), hostile_nonnegative, True),
                      "repulsive_gain": Arg(_pos(0.5, 2.0), hostile_positive, True)}, True),
    "keep_out_cone": (_fn("keep_out_cone"),
                      {"axis_b": Arg(_const([0.0, 0.0, 1.0]), hostile_axis),
                       "direction_i": Arg(_const([0.0, 1.0, 0.0]), hostile_axis),
                       "half_angle_deg": Arg(_const(OMIT), hostile_second_angle, True),
                     "half_angle_rad": Arg(lambda rng: rng.uniform(0.1, 2.5), hostile_nonnegative, True),  # 0: the CLI's rule
                       "delta_offset": Arg(_pos(0.01, 0.1), hostile_nonnegative, True),
                       "zeta_offset": Arg(_pos(0.01, 0.1), hostile_nonnegative, True),
                       "repulsive_gain": Arg(_pos(0.5, 2.0), hostile_positive, True)}, True),
    "pd_torque": (_fn("pd_torque"),
                  {"R": ROT(), "omega_b": VEC(), "R_g": ROT(),
                   "kp": Arg(_pos(), hostile_positive), "kd": Arg(_pos(), hostile_positive)}, True),
    "RigidBody.__init__": (_ctor("RigidBody"), {"J": Arg(_J, hostile_inertia)}, True),
    "RigidBody.angular_acceleration": (_method(lambda: _fn("RigidBody")()(_J()), "angular_acceleration"),
                                       {"omega_b": VEC(), "tau_b": VEC()}, True),
    "RigidBody.kinetic_energy": (_method(lambda: _fn("RigidBody")()(_J()), "kinetic_energy"),
                                 {"omega_b": VEC()}, True),
    "Cone.margin": (_method(_cone, "margin"), {"R": ROT()}, True),
    "Governor.__init__": (_ctor("Governor"),
                          {"J": Arg(_J, hostile_inertia),
                           "kp": Arg(_const(5.0), hostile_positive, True),
                           "kd": Arg(_const(1.0), hostile_positive, True),
                           "tau_max": Arg(_const(2.5), hostile_positive, True),
                           "cones": Arg(lambda rng: [_cone()], hostile_cones, True),
                           "mode": Arg(_const("pet"), hostile_str, True),
                           "kappa": Arg(_const(1.0), hostile_positive, True),
                           "c_gamma": Arg(_const(3.0), hostile_positive, True),
                           "Ts": Arg(_const(0.5), hostile_positive, True),
                           "epsilon": Arg(_const(1e-3), hostile_positive, True),
                           "epsilon_gamma": Arg(_const(0.1), hostile_positive, True),
                           "control_period": Arg(_const(0.0), hostile_nonnegative, True),
                           "wheels": Arg(_const([]), hostile_wheels, True),
                           "margins": Arg(_const("nominal"), hostile_str, True),
                           "disturbance_bound": Arg(_const(0.0), hostile_nonnegative, True),
                           "attitude_bias_bound": Arg(_const(0.0), hostile_nonnegative, True),
                           "attitude_noise": Arg(_const(0.0), hostile_nonnegative, True),
                           "rate_bias_bound": Arg(_const(0.0), hostile_nonnegative, True),
                           "rate_noise": Arg(_const(0.0), hostile_nonnegative, True),
                           "delay_periods": Arg(_const(0), hostile_delay, True),
                           "torque_quantum": Arg(_const(0.0), hostile_nonnegative, True),
                           "robust_reference_step": Arg(_const(0.0), hostile_nonnegative, True)}, True),
    "Governor.from_scenario": (_method(lambda: _fn("Governor")(), "from_scenario"),
                               {"path": Arg(_const(str(REPO / "examples" / "pet_erg_paper.toml")),
                                            hostile_path)}, True),
    "PlannedGovernor.from_scenario": (_method(lambda: _fn("PlannedGovernor")(), "from_scenario"),
                                      {"path": Arg(lambda rng: _planned_path(), hostile_path)}, True),
    "PlannedGovernor.reset": (_method(lambda: _fn("PlannedGovernor")().from_scenario(_planned_path()), "reset"),
                              {"t0": Arg(lambda rng: rng.uniform(-10, 10), hostile_real)}, True),
    "PlannedGovernor.step": (_method(_reset_planned, "step"),
                             {"t": Arg(lambda rng: rng.uniform(0.0, 10.0), hostile_real), "R": ROT(),
                              "omega_b": VEC(),
                              "wheel_momentum_b": Arg(_vec, hostile_optional_vec3, True)}, True),
    "Governor.reset": (_method(_governor, "reset"),
                       {"t0": Arg(lambda rng: rng.uniform(-10, 10), hostile_real), "R_g0": ROT()}, True),
    "Governor.step": (_method(_reset_governor, "step"),
                      {"t": Arg(lambda rng: rng.uniform(0.0, 10.0), hostile_real), "R": ROT(),
                       "omega_b": VEC(), "R_d": ROT()}, True),
    "Governor.evaluate": (_method(_reset_governor, "evaluate"),
                          {"R": ROT(), "omega_b": VEC(), "R_g": ROT(), "R_d": ROT(),
                           "flag": Arg(lambda rng: rng.random() < 0.5, hostile_bool)}, True),
    "Governor.lyapunov": (_method(_reset_governor, "lyapunov"),
                          {"R": ROT(), "omega_b": VEC(), "R_g": ROT()}, True),
    "Governor.level": (_method(_reset_governor, "level"),
                       {"R": ROT(), "omega_b": VEC(), "R_g": ROT()}, True),
    "Governor.trigger_condition": (_method(_reset_governor, "trigger_condition"),
                                   {"R": ROT(), "omega_b": VEC(), "R_g": ROT()}, True),
    "Governor.gamma": (_method(_reset_governor, "gamma"), {"R_g": ROT()}, True),
    "QuaternionPid.__init__": (_ctor("QuaternionPid"),
                               {"kp": Arg(_pos(), hostile_nonnegative), "ki": Arg(_pos(), hostile_nonnegative),
                                "kd": Arg(_pos(), hostile_nonnegative)}, True),
    "QuaternionPid.step": (_method(lambda: _fn("QuaternionPid")()(), "step"),
                           {"q_ib": QUAT(), "omega_b": VEC(), "q_id": QUAT(), "omega_d_d": VEC(),
                            "dt": Arg(_pos(1e-3, 1.0), hostile_positive)}, True),
    "QuaternionPid.reset": (_method(lambda: _fn("QuaternionPid")()(), "reset"), {}, True),
    "Mission.__init__": (_ctor("Mission"),
                         {"waypoints": Arg(lambda rng: [random_vec3(rng, 1e3)], hostile_waypoints),
                          "mass": Arg(_pos(1, 1e3), hostile_positive, True),
                          "t_max": Arg(_pos(1, 50), hostile_positive, True),
                          "f_max": Arg(_pos(0.1, 1), hostile_positive, True),
                          "cruise_speed": Arg(_pos(1, 100), hostile_positive, True),
                          "pointing_tolerance": Arg(_pos(1e-7, 1e-3), hostile_positive, True),
                          "kp": Arg(_pos(), hostile_nonnegative, True),
                          "ki": Arg(_pos(), hostile_nonnegative, True),
                          "kd": Arg(_pos(), hostile_nonnegative, True)}, True),
    "Mission.step": (_method(_mission, "step"),
                     {"R": ROT(), "omega_b": VEC(), "p_i": Arg(lambda rng: random_vec3(rng, 1e3), hostile_vec3),
                      "v_i": VEC(), "dt": Arg(_pos(1e-3, 1.0), hostile_positive)}, True),
    "run": (_fn("run"), {"scenario": SCEN(), "out": Arg(_const(None), hostile_out)}, False),
    "check": (_fn("check"), {"scenario": SCEN()}, False),
    "predict": (_fn("predict"), {"scenario": SCEN()}, False),
    "reach": (_fn("reach"), {"scenario": SCEN(), "out": Arg(_const(None), hostile_out),
                             "raise_on_failure": Arg(_const(True), hostile_bool)}, False),
    "plan_slew": (_fn("plan_slew"),
                  {"J": Arg(_J, hostile_inertia), "R_start": ROT(), "R_target": ROT(),
                   "tau_max": Arg(_pos(0.5, 5.0), hostile_positive),
                   "cones": Arg(_const([]), hostile_cones),
                   "torque_headroom": Arg(_pos(0.0, 0.5), hostile_headroom, True),
                   "cone_margin_deg": Arg(_pos(0.0, 10.0), hostile_margin_deg, True),
                   "intervals": Arg(_const(0), hostile_intervals, True),
                   "points_per_interval": Arg(lambda rng: rng.randint(1, 5), hostile_points, True)}, True),
    "to_toml": (_fn("to_toml"), {"scenario": Arg(lambda rng: _small_scenario(), hostile_scenario)}, True),
}

# Public callables without arguments to check, and why.
EXEMPT = {
    "Error.__init__": "exception class",
    "InputError.__init__": "exception class",
    "NumericalError.__init__": "exception class",
    "VerificationFailure.__init__": "exception class",
    "RunResult.__init__": "a record of run()'s results (a dataclass holding what run() returns)",
    "ReachResult.__init__": "a record of reach()'s results (a dataclass holding what reach() returns)",
    "PlannedSlew.__init__": "a record of plan_slew()'s results (a dataclass holding what plan_slew() returns)",
}


def _skew(rng):
    import attiguard as ag

    return ag.hat(random_vec3(rng))


# ---- introspection --------------------------------------------------------------------------------

def _has_constructor(cls: type) -> bool:
    init = vars(cls).get("__init__")
    if init is None:
        return False
    doc = getattr(init, "__doc__", "") or ""
    return "No constructor defined" not in doc and "Initialize self" not in doc


def public_callables() -> set[str]:
    """Every public function, constructor and (own, non-property) method of attiguard."""
    import attiguard as ag

    names: set[str] = set()
    for name in ag.__all__:
        obj = getattr(ag, name)
        if inspect.isclass(obj):
            if issubclass(obj, BaseException):
                names.add(f"{name}.__init__")
                continue
            if _has_constructor(obj):
                names.add(f"{name}.__init__")
            for attr, member in vars(obj).items():
                if attr.startswith("_") or isinstance(member, property):
                    continue
                if isinstance(member, (staticmethod, classmethod)) or callable(member):
                    names.add(f"{name}.{attr}")
        elif callable(obj):
            names.add(name)
    return names


# ---- one callable's sweep (in a child interpreter) ------------------------------------------------

def _finite(value: Any) -> bool:
    np = _np()
    if value is None or isinstance(value, (bool, str)):
        return True
    if isinstance(value, (int, float)):
        return math.isfinite(value)
    if isinstance(value, np.ndarray):
        return value.dtype.kind not in "fc" or bool(np.all(np.isfinite(value)))
    if isinstance(value, (list, tuple)):
        return all(_finite(v) for v in value)
    if isinstance(value, dict):
        return all(_finite(v) for v in value.values())
    if type(value).__module__.startswith("attiguard"):  # GovernorOutput, Cone, ...
        return all(_finite(getattr(value, a)) for a in dir(value)
                   if not a.startswith("_") and not callable(getattr(value, a)))
    return True


def _call(name: str, factory, args: dict[str, Arg], values: dict[str, Any]):
    fn = factory()
    pos = [values[a] for a, spec in args.items() if not spec.keyword]
    kw = {a: values[a] for a, spec in args.items() if spec.keyword and values[a] is not OMIT}
    return fn(*pos, **kw)


def sweep(name: str) -> list[str]:
    """Failures of one callable: hostile arguments that did not raise ValueError/TypeError, or
    valid ones that raised or returned NaN/inf."""
    import attiguard as ag

    factory, args, check_output = SPECS[name]
    rng = random.Random(f"{SEED}:{name}")
    failures: list[str] = []
    expected = (ValueError, TypeError)

    def valid() -> dict[str, Any]:
        return {a: spec.valid(rng) for a, spec in args.items()}

    if check_output:
        for _ in range(TRIALS):
            values = valid()
            try:
                out = _call(name, factory, args, values)
            except Exception as e:  # noqa: BLE001 — a valid call must work
                failures.append(f"{name}: valid arguments raised {type(e).__name__}: {e}")
                break
            if not _finite(out):
                failures.append(f"{name}: valid arguments {values!r} gave a non-finite result {out!r}")
                break

    for arg, spec in args.items():
        for trial in range(max(1, TRIALS // 20)):
            base = valid()
            hostile = list(spec.hostile(rng, base[arg]))
            for bad in hostile:
                values = dict(base)
                values[arg] = bad
                try:
                    out = _call(name, factory, args, values)
                except expected as e:
                    if isinstance(e, ag.InputError) and not str(e):
                        failures.append(f"{name}({arg}={bad!r:.80}): empty message")
                    continue
                except Exception as e:  # noqa: BLE001
                    failures.append(f"{name}({arg}={bad!r:.80}): {type(e).__name__} instead of "
                                    f"ValueError/TypeError: {e}")
                    continue
                failures.append(f"{name}({arg}={bad!r:.80}): no exception, returned {out!r:.120}")
    return failures


def _limit_child() -> None:
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (CHILD_ADDRESS_SPACE, CHILD_ADDRESS_SPACE))


def run_sweep_in_child(name: str) -> tuple[int, str, str]:
    from conftest import package_parent

    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(package_parent()), str(Path(__file__).parent)])
    env["OPENBLAS_NUM_THREADS"] = "1"
    env["OMP_NUM_THREADS"] = "1"
    p = subprocess.run([sys.executable, __file__, name], env=env, capture_output=True, text=True,
                       timeout=CHILD_TIMEOUT_S, preexec_fn=_limit_child, cwd=str(REPO))
    return p.returncode, p.stdout, p.stderr


# ---- the tests -------------------------------------------------------------------------------------

def test_every_public_callable_has_a_spec():
    found = public_callables()
    missing = sorted(found - set(SPECS) - set(EXEMPT))
    stale = sorted((set(SPECS) | set(EXEMPT)) - found)
    assert not missing, f"public callables without an argument specification in SPECS: {missing}"
    assert not stale, f"SPECS/EXEMPT name callables attiguard does not have: {stale}"


def test_every_argument_has_a_spec():
    """Each spec names exactly the callable's parameters (pybind11's signature line)."""
    import attiguard as ag

    for name, (factory, args, _) in SPECS.items():
        fn = factory()
        if inspect.isclass(fn):
            fn = fn.__init__
        doc = (fn.__doc__ or "").splitlines()
        if not doc or "(" not in doc[0] or name in ("run", "check", "predict", "reach", "to_toml"):
            params = [p for p in inspect.signature(fn).parameters]
        else:  # "name(self: X, a: T, *, b: T = …) -> R"
            inside = doc[0][doc[0].index("(") + 1: doc[0].rindex(")")]
            params = [p.split(":")[0].strip() for p in _split_top(inside)]
            params = [p for p in params if p not in ("self", "*", "")]
        assert set(params) == set(args), f"{name}: parameters {params}, spec {sorted(args)}"
    assert ag  # the module under test was importable


def _split_top(text: str) -> list[str]:
    parts, depth, cur = [], 0, ""
    for c in text:
        if c in "[(":
            depth += 1
        elif c in "])":
            depth -= 1
        if c == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += c
    parts.append(cur)
    return parts


@pytest.mark.parametrize("name", sorted(SPECS))
def test_hostile_arguments_raise(name):
    code, out, err = run_sweep_in_child(name)
    assert code in (0, 1), (f"{name}: the child interpreter died (exit code {code}; a negative "
                            f"code is a signal): {err[-2000:]}")
    failures = json.loads(out.strip().splitlines()[-1]) if out.strip() else [err[-2000:]]
    assert not failures, "\n".join(failures[:30])


def test_the_sweep_can_fail():
    """The sweep reports a hostile value that is accepted: a spec whose hostile values are
    valid ones must fail."""
    SPECS["_probe"] = (_fn("phi"), {"R": Arg(_rot, lambda rng, base: iter([base]))}, True)
    try:
        failures = sweep("_probe")
    finally:
        del SPECS["_probe"]
    assert failures and "no exception" in failures[0]


if __name__ == "__main__":  # the child: one callable's sweep, failures as JSON on the last line
    result = sweep(sys.argv[1])
    print(json.dumps(result))
    sys.exit(1 if result else 0)
