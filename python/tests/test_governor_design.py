"""Governor(...) from plain values (docs/python.md, "Governor"; docs/pet-erg.md, sections 12-13):
the robust governor with reaction wheels built without a scenario file by governor::design is the
governor `attiguard run` flies on the nominal case of examples/pet_erg_robust_campaign.toml
(without its [dispersions]): the same design figures as the run's summary, the same Γ and V
along the run's trajectory, and the same steps as Governor.from_scenario of that file."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import attiguard as ag

REPO = Path(__file__).resolve().parents[2]
EXAMPLE = REPO / "examples" / "pet_erg_robust_campaign.toml"
PYRAMID = [[0.577382, 0.577382, 0.577288], [-0.577382, 0.577382, 0.577288],
           [-0.577382, -0.577382, 0.577288], [0.577382, -0.577382, 0.577288]]
ATTITUDE_BIAS = [0.0002, -0.0002, 0.0001]


def nominal_case_text() -> str:
    text = EXAMPLE.read_text()
    return text[: text.index("[dispersions]")]


def plain_governor(**changes) -> ag.Governor:
    """The governor of the example from its values, written out (no file)."""
    J = np.array([[120.0, 5.0, -3.0], [5.0, 90.0, 2.0], [-3.0, 2.0, 150.0]])
    cones = [ag.keep_out_cone([1.0, 0.0, 0.0], [0.49, 0.85, 0.17], half_angle_deg=40.0,
                              delta_offset=0.002, zeta_offset=0.05, repulsive_gain=0.1),
             ag.keep_out_cone([1.0, 0.0, 0.0], [-0.81, 0.47, -0.34], half_angle_deg=15.0,
                              delta_offset=0.002, zeta_offset=0.05, repulsive_gain=0.1),
             ag.keep_in_cone([0.0, 0.0, 1.0], [0.0, 0.0, 1.0], half_angle_deg=60.0)]
    args = dict(kp=0.5, kd=6.0, tau_max=1.0, cones=cones, mode="pet", kappa=20.0, Ts=1.0,
                control_period=0.1,
                wheels=[{"axis_b": a, "torque_max": 0.1, "momentum_max": 6.0} for a in PYRAMID],
                margins="robust", disturbance_bound=0.003, attitude_bias_bound=0.0215,
                attitude_noise=0.0002, rate_bias_bound=math.hypot(0.00001, 0.0, -0.00001),
                rate_noise=0.00002, delay_periods=1, torque_quantum=0.001,
                robust_reference_step=0.002)
    args.update(changes)
    return ag.Governor(J, **args)


@pytest.fixture(scope="module")
def nominal_run():
    return ag.run(tomllib.loads(nominal_case_text()))


def test_the_design_figures_are_the_runs(nominal_run):
    s = nominal_run.summary
    gov = plain_governor()
    assert s["margins"] == "robust"
    assert gov.gamma_d == s["gamma_d"]
    assert gov.gamma(np.eye(3)) == s["gamma_initial"]
    omega0 = np.array([0.001, -0.001, 0.0005])
    assert gov.level(np.eye(3), omega0, np.eye(3)) == s["V_initial"]
    R_d = ag.expm(np.array([0.0, 0.0, 120.0 * math.pi / 180.0]))
    assert gov.evaluate(np.eye(3), omega0, np.eye(3), R_d, True).gamma_g == s["gamma_g_initial"]
    robust = gov.robust
    for key in ("epsilon", "delta", "gamma_min", "torque_error", "command_error", "measurement_margin",
                "max_reference_step"):
        assert robust[key] == s["robust"][key], key
    d = gov.design
    assert d["tau_max_reduced"] == s["robust"]["tau_max_reduced"]
    assert d["wheel_gamma_d_reduced"] == s["robust"]["wheel_gamma_d_reduced"]
    assert d["wheel_gamma_d"] == s["wheel_gamma_d"]
    assert d["wheel_binding"] == s["wheel_binding"]
    assert d["bounded_step"] is True
    assert d["tau_max"] == d["tau_max_reduced"] < 1.0
    assert d["polytope_gamma_d"] == d["wheel_gamma_d_reduced"] < d["wheel_gamma_d"]
    # the cones it enforces are tightened by the attitude bias bound; the run reports the true ones
    for enforced, true in zip(gov.cones, s["cones"]):
        assert enforced.theta_c == pytest.approx(true["theta_c_deg"] * math.pi / 180.0 - 0.0215, abs=1e-12)


def test_gamma_and_v_along_the_flown_trajectory_are_the_runs(nominal_run):
    gov = plain_governor()
    r = nominal_run
    bias = ag.expm(np.array(ATTITUDE_BIAS))  # the run's level is of the attitude seen through it
    assert len(r["t"]) == 301
    for k in range(len(r["t"])):
        R = ag.quat_to_rotation([r["q_w"][k], r["q_x"][k], r["q_y"][k], r["q_z"][k]])
        R_g = ag.quat_to_rotation([r["qg_w"][k], r["qg_x"][k], r["qg_y"][k], r["qg_z"][k]])
        omega = np.array([r["omega_x"][k], r["omega_y"][k], r["omega_z"][k]])
        assert gov.gamma(R_g) == pytest.approx(r["gamma"][k], rel=1e-9, abs=1e-15), k
        assert gov.lyapunov(R @ bias, omega, R_g) == pytest.approx(r["V"][k], rel=1e-8, abs=1e-14), k
    assert r.summary["constraints_satisfied"] is True
    assert r.summary["outcome"] == "converged"


def test_it_steps_as_the_governor_of_the_file(tmp_path):
    path = tmp_path / "robust.toml"
    path.write_text(nominal_case_text())
    plain, filed = plain_governor(), ag.Governor.from_scenario(str(path))
    assert plain.design == filed.design and plain.robust == filed.robust
    J = np.array([[120.0, 5.0, -3.0], [5.0, 90.0, 2.0], [-3.0, 2.0, 150.0]])
    body = ag.RigidBody(J)
    R_d = ag.expm(np.array([0.0, 0.0, 120.0 * math.pi / 180.0]))
    R, omega = np.eye(3), np.array([0.001, -0.001, 0.0005])
    plain.reset(0.0, R)
    filed.reset(0.0, R)
    moved = 0.0
    for k in range(3000):  # 300 s of the 10 Hz loop, the torque applied directly
        a = plain.step(0.1 * k, R, omega, R_d)
        b = filed.step(0.1 * k, R, omega, R_d)
        assert np.array_equal(a.tau_b, b.tau_b) and np.array_equal(a.R_g, b.R_g) and a.gamma == b.gamma, k
        assert a.min_margin > 0.0 and a.W <= a.gamma and np.linalg.norm(a.tau_b) <= 1.0
        for _ in range(10):
            omega = omega + 0.01 * body.angular_acceleration(omega, a.tau_b)
            R = R @ ag.expm(0.01 * omega)
        moved = ag.distance(np.eye(3), a.R_g)
    assert moved > 0.5  # the reference travelled towards R_d


def test_plain_values_are_checked_and_the_design_refusals_named():
    with pytest.raises(ValueError, match=r"Governor\(\): \"wheels\[1\]\.torque_max\": must be > 0"):
        plain_governor(wheels=[{"axis_b": PYRAMID[0], "torque_max": 0.1, "momentum_max": 6.0},
                               {"axis_b": PYRAMID[1], "torque_max": -0.1, "momentum_max": 6.0}])
    with pytest.raises(ValueError, match=r"wheels\[0\]: unknown key 'spin'"):
        plain_governor(wheels=[{"axis_b": PYRAMID[0], "torque_max": 0.1, "momentum_max": 6.0, "spin": 1}])
    with pytest.raises(ValueError, match="margins: must be"):
        plain_governor(margins="robustly")
    with pytest.raises(ValueError, match="no admissible set with robust margins: Gamma_min = "):
        plain_governor(disturbance_bound=0.03)
    with pytest.raises(ValueError, match="robust margins are for the flight loop"):
        plain_governor(control_period=0.0, wheels=[])
    with pytest.raises(ValueError, match="reaction wheels act in the flight loop"):
        plain_governor(control_period=0.0)
    nominal = plain_governor(margins="nominal")
    assert nominal.robust is None and nominal.design["tau_max_reduced"] == 0.0
    assert nominal.design["tau_max"] == 1.0 and nominal.design["wheel_binding"] in range(4)


def test_a_reference_step_without_the_delay_is_refused_as_in_a_scenario():
    # Issue 49: robust_reference_step caps the lag of a delayed command only; the scenario reader
    # refuses it at its key with delay_periods = 0, and so does Governor(...).
    with pytest.raises(ag.InputError, match=r"robust_reference_step: only used with delay_periods = 1"):
        plain_governor(delay_periods=0)
    plain_governor(delay_periods=0, robust_reference_step=0.0)  # without the cap: accepted
