"""governor = "planned" from Python (docs/pet-erg.md, section 16.2): attiguard.run of a planned
scenario, its trajectory re-checked here in numpy (cones and torque bound at every row), and the
refusals of the mode at their keys."""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np
import pytest

import attiguard as ag

REPO = Path(__file__).resolve().parents[2]
EXAMPLE = REPO / "examples" / "pet_erg_slew170_planned.toml"


def test_a_planned_run_converges_within_1p3_the_bang_bang_time_keeping_every_constraint():
    result = ag.run(EXAMPLE)
    s = result.summary
    assert s["governor"] == "planned"
    assert s["outcome"] == "converged"
    assert s["convergence_time_over_bang_bang"] <= 1.3
    assert s["planned"]["inadmissible_samples"] == 0
    # Every row re-checked: the cones from the quaternions, ‖τ‖ from the torques.
    scenario = tomllib.loads(EXAMPLE.read_text())
    tau_max = scenario["control"]["tau_max"]
    q = np.column_stack([result["q_w"], result["q_x"], result["q_y"], result["q_z"]])
    tau = np.column_stack([result["tau_x"], result["tau_y"], result["tau_z"]])
    assert np.all(np.linalg.norm(tau, axis=1) <= tau_max)
    for cone in scenario["cones"]:
        a_b = np.asarray(cone["axis_b"], float)
        d_i = np.asarray(cone["direction_i"], float)
        d_i /= np.linalg.norm(d_i)
        cos_angle = np.array([d_i @ ag.quat_to_rotation(qi) @ a_b for qi in q])
        limit = np.cos(np.radians(cone["half_angle_deg"]))
        if cone["type"] == "keep_out":
            assert np.all(cos_angle <= limit)
        else:
            assert np.all(cos_angle >= limit)
    # The clock: σ from 0 to the plan's duration, ṡ in [0, 1].
    assert result["s"][0] == 0.0
    assert result["s"][-1] == pytest.approx(s["planned"]["plan"]["duration"])
    assert np.all((result["s_dot"] >= 0.0) & (result["s_dot"] <= 1.0))


def test_the_planned_mode_refuses_the_pet_erg_table_at_its_key(tmp_path):
    text = EXAMPLE.read_text() + "\n[erg]\nkappa = 1.0\n"
    path = tmp_path / "with_erg.toml"
    path.write_text(text)
    with pytest.raises(ag.InputError, match=r"with_erg\.toml:\d+:\d+: erg: .*planned"):
        ag.run(path)


def test_a_moving_start_is_a_start_off_the_plan_that_the_clock_waits_out(tmp_path):
    # The plan starts at rest at R_0; the body turns at 0.005 rad/s: the clock waits at ṡ = 0
    # (the hold damps the rate) until the level fits a moving clock, then flies the plan; the
    # gains derived soft enough that the hold brakes the start without saturating.
    text = EXAMPLE.read_text().replace("omega_b = [0.0, 0.0, 0.0]", "omega_b = [0.0, 0.0, -0.005]")
    path = tmp_path / "moving.toml"
    path.write_text(text)
    s = ag.run(path).summary
    assert s["outcome"] == "converged"
    assert s["constraints_satisfied"]
    assert s["planned"]["time_held"] > 0.0
    assert s["planned"]["limited_by_initial_rate"]
    assert s["planned"]["saturated_commands"] == 0


def test_the_planned_mode_refuses_a_schedule_at_its_key(tmp_path):
    text = EXAMPLE.read_text().replace(
        "attitude = { axis = [0.0, 0.0, 1.0], angle_deg = 170.0 }",
        "schedule = [{ t = 0.0, attitude = { axis = [0.0, 0.0, 1.0], angle_deg = 10.0 } },"
        " { t = 50.0, attitude = { axis = [0.0, 0.0, 1.0], angle_deg = 170.0 } }]")
    path = tmp_path / "schedule.toml"
    path.write_text(text)
    with pytest.raises(ag.InputError, match=r"schedule\.toml:\d+:\d+: desired\.schedule: .*planned.*one rest-to-rest slew"):
        ag.run(path)


def _flight_loop_scenario(tmp_path: Path) -> Path:
    """The example in the flight loop at 10 Hz, one row per control instant, no imperfections."""
    text = EXAMPLE.read_text()
    text = text.replace("tau_max = 0.5                          # N m\n",
                        "tau_max = 0.5                          # N m\ncontrol_period = 0.1\n")
    text = text.replace("output_interval = 0.5", "output_interval = 0.1")
    path = tmp_path / "planned_10hz.toml"
    path.write_text(text)
    return path


def _replay(gov, cli, **step_keywords):
    """Steps `gov` from t = 0 through the rows of a CLI run (each row a control instant, its state
    the measurement); returns the worst |tau - tau_cli|/tau_max and |sigma - s_cli|/T_p."""
    gov.reset(0.0)
    worst_tau = worst_sigma = 0.0
    for i, t in enumerate(cli["t"]):
        q = np.array([cli["q_w"][i], cli["q_x"][i], cli["q_y"][i], cli["q_z"][i]])
        omega = np.array([cli["omega_x"][i], cli["omega_y"][i], cli["omega_z"][i]])
        out = gov.step(t, ag.quat_to_rotation(q), omega, **step_keywords)
        tau = np.array([cli["tau_x"][i], cli["tau_y"][i], cli["tau_z"][i]])
        worst_tau = max(worst_tau, float(np.max(np.abs(out.tau_b - tau))) / gov.tau_max)
        worst_sigma = max(worst_sigma, abs(out.sigma - cli["s"][i]) / gov.plan_duration)
    return worst_tau, worst_sigma


def test_a_user_loop_stepping_the_planned_governor_reproduces_the_cli_to_1e_12(tmp_path):
    # The CLI's flight loop at 10 Hz commands at each control instant what PlannedGovernor.step
    # returns for the state there: replayed row by row in a Python loop, the same torques and
    # clock to 1e-12.
    path = _flight_loop_scenario(tmp_path)
    cli = ag.run(path)
    assert cli.summary["outcome"] == "converged"
    gov = ag.PlannedGovernor.from_scenario(str(path))
    assert gov.plan_duration == pytest.approx(cli.summary["planned"]["plan"]["duration"], rel=1e-12)
    assert gov.k_R == cli.summary["planned"]["k_R"]
    worst_tau, worst_sigma = _replay(gov, cli)
    print(f"replay of {len(cli['t'])} control instants: worst |tau - tau_cli|/tau_max {worst_tau:.3g}, "
          f"worst |sigma - s_cli|/T_p {worst_sigma:.3g}")
    assert worst_tau <= 1e-12
    assert worst_sigma <= 1e-12


def test_a_user_loop_stepping_the_robust_planned_governor_reproduces_the_cli_to_1e_12(tmp_path):
    # Robust margins (docs/pet-erg.md, section 16.3): the same replay on the robust example's 50 Hz
    # flight loop without sensor errors (the measurement is the trajectory's state), so the clock's
    # wait, jump to the design's rate and coast are the CLI's.
    text = (REPO / "examples" / "pet_erg_slew170_planned_robust.toml").read_text()
    start = text.index("[imperfections]")
    text = text[:start] + text[text.index("[simulation]"):]
    text = text.replace("output_interval = 0.5", "output_interval = 0.02")
    path = tmp_path / "planned_robust.toml"
    path.write_text(text)
    cli = ag.run(path)
    assert cli.summary["outcome"] == "converged"
    robust = cli.summary["planned"]["robust"]
    assert robust["errors_within_bounds"]
    gov = ag.PlannedGovernor.from_scenario(str(path))
    assert gov.robust
    assert gov.robust_rate == robust["rate"]
    worst_tau, worst_sigma = _replay(gov, cli, wheel_momentum_b=np.zeros(3))
    assert worst_tau <= 1e-12
    assert worst_sigma <= 1e-12


def test_the_planned_governor_refuses_what_the_cli_refuses(tmp_path):
    with pytest.raises(ag.InputError, match=r'pet_erg_slew170\.toml:\d+:\d+: governor: .*needs governor = "planned"'):
        ag.PlannedGovernor.from_scenario(str(REPO / "examples" / "pet_erg_slew170.toml"))
    gov = ag.PlannedGovernor.from_scenario(str(EXAMPLE))
    with pytest.raises(ag.InputError, match=r"reset\(t0\) before"):
        gov.step(0.0, np.eye(3), np.zeros(3))
    gov.reset(0.0)
    gov.step(1.0, np.eye(3), np.zeros(3))
    with pytest.raises(ag.InputError, match="time went backwards"):
        gov.step(0.5, np.eye(3), np.zeros(3))
    with pytest.raises(ag.InputError, match=r"step\(\): R"):
        gov.step(2.0, 2.0 * np.eye(3), np.zeros(3))
    with pytest.raises(ag.InputError, match=r"step\(\): omega_b"):
        gov.step(2.0, np.eye(3), np.array([np.nan, 0.0, 0.0]))


def test_a_control_period_longer_than_a_tenth_of_the_plan_is_refused_at_its_key(tmp_path):
    text = EXAMPLE.read_text().replace("tau_max = 0.5                          # N m\n",
                                       "tau_max = 0.5                          # N m\ncontrol_period = 40.0\n")
    path = tmp_path / "slow_loop.toml"
    path.write_text(text)
    with pytest.raises(ag.InputError,
                       match=r"slow_loop\.toml:\d+:\d+: control\.control_period: 40 s leaves 1 control instants"):
        ag.run(path)
    with pytest.raises(ag.InputError, match=r"control\.control_period"):
        ag.check(path)


def test_a_run_shorter_than_its_plan_says_so(tmp_path):
    text = EXAMPLE.read_text().replace("duration = 150.0", "duration = 20.0")
    path = tmp_path / "short.toml"
    path.write_text(text)
    s = ag.run(path).summary
    assert s["outcome"] == "not_converged_by_end"
    assert "duration is shorter than the plan" in s["outcome_reason"]
    assert s["constraints_satisfied"]
