"""Acceptance of the `mission` kind (docs/mission.md) through the Python package: the constrained
example completes every waypoint with min pointing margin >= 0 and ||tau|| <= tau_max at every
logged sample, while its unconstrained twin points the star tracker into the Sun."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import attiguard as ag

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "mission_sun_constrained.toml"


def test_constrained_mission_keeps_cone_and_torque_twin_violates():
    res = ag.run(EXAMPLE)
    s = res.summary
    assert res.kind == "mission"
    tau_max = s["tau_max"]
    con, unc = s["constrained"], s["unconstrained"]
    assert con["completed"] and con["waypoints_reached"] == 2
    assert con["min_pointing_margin"] >= 0.0
    assert con["max_torque_norm"] <= tau_max and con["torque_violations"] == 0
    assert np.all(res["min_margin"] >= 0.0)
    assert np.all(res["tau_norm"] <= tau_max)
    assert all(w["reached"] for w in s["waypoints"])
    assert unc["governor"] == "none" and unc["min_pointing_margin"] < 0.0
    assert not unc["pointing_constraints_satisfied"] and not unc["constraints_satisfied"]
    assert s["time_cost"] == con["total_time"] - unc["total_time"]


def test_twin_is_the_scenario_with_governor_none():
    import tomllib

    sc = tomllib.loads(EXAMPLE.read_text())
    sc["governor"] = "none"
    s = ag.run(sc).summary
    assert s["governor"] == "none" and s["min_pointing_margin"] < 0.0
    assert s["unconstrained"]["min_pointing_margin"] == s["min_pointing_margin"]
    assert s["constrained"]["min_pointing_margin"] >= 0.0


PLANNED = EXAMPLE.with_name("mission_sun_constrained_planned.toml")


def test_planned_mission_plans_each_slew_and_costs_less_than_the_pet_erg():
    """governor = "planned" (docs/mission.md, "Planned slews"): the four slews planned, every
    logged sample within the cone and tau_max, and a smaller constraint cost than the PET-ERG's
    against the same unconstrained twin."""
    res = ag.run(PLANNED)
    s = res.summary
    assert s["governor"] == "planned" and s["completed"] and s["constraints_satisfied"]
    assert [sl["mode"] for sl in s["slews"]] == ["align", "flip", "align", "flip"]
    assert all(sl["planned"] and sl["convergence_time_over_plan"] <= 1.3 for sl in s["slews"])
    assert np.all(res["min_margin"] >= 0.0)
    assert np.all(res["tau_norm"] <= s["tau_max"])
    assert set(np.unique(res["slew"])) == {-1.0, 0.0, 1.0, 2.0, 3.0}
    pet = ag.run(EXAMPLE).summary
    assert s["unconstrained"]["total_time"] == pet["unconstrained"]["total_time"]
    assert s["time_cost"] < pet["time_cost"]
