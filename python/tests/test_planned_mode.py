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


def test_the_planned_mode_refuses_a_moving_start_at_its_key(tmp_path):
    text = EXAMPLE.read_text().replace("omega_b = [0.0, 0.0, 0.0]", "omega_b = [0.0, 0.0, 0.01]")
    path = tmp_path / "moving.toml"
    path.write_text(text)
    with pytest.raises(ag.InputError, match=r"moving\.toml:\d+:\d+: initial\.omega_b: .*rest"):
        ag.run(path)
