"""Tests of the Python package `attiguard` (the pybind11 bindings, docs/python.md)."""

from __future__ import annotations

import math
import os
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest

import attiguard as ag
from conftest import INSTALLED

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"
BUILD = Path(os.environ.get("ATTIGUARD_BUILD_DIR", REPO / "build")).resolve()


def load(name: str) -> dict:
    return tomllib.loads((EXAMPLES / name).read_text())


# ---- SO(3) / quaternion helpers ---------------------------------------------------------------

def test_exp_log_round_trip_and_hat_vee():
    w = np.array([0.3, -1.1, 0.7])
    R = ag.expm(w)
    assert ag.is_rotation(R)
    np.testing.assert_allclose(ag.logm(R), w, atol=1e-12)
    np.testing.assert_allclose(ag.hat(w) @ np.array([1.0, 2.0, 3.0]), np.cross(w, [1.0, 2.0, 3.0]))
    np.testing.assert_allclose(ag.vee(ag.hat(w)), w)
    assert ag.distance(np.eye(3), R) == pytest.approx(np.linalg.norm(w))
    assert ag.phi(R) == pytest.approx(1.0 - math.cos(np.linalg.norm(w)))


def test_quaternion_conventions_scalar_first_hamilton():
    q = ag.quat_from_axis_angle([0.0, 0.0, 1.0], math.pi / 2)
    np.testing.assert_allclose(q, [math.cos(math.pi / 4), 0, 0, math.sin(math.pi / 4)])
    R = ag.quat_to_rotation(q)
    np.testing.assert_allclose(R @ [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(R, ag.expm([0.0, 0.0, math.pi / 2]), atol=1e-15)
    qq = ag.quat_multiply(q, q)
    np.testing.assert_allclose(ag.quat_to_rotation(qq), ag.expm([0.0, 0.0, math.pi]), atol=1e-12)
    np.testing.assert_allclose(ag.rotation_to_quat(R), q, atol=1e-15)
    np.testing.assert_allclose(ag.quat_multiply(q, ag.quat_conjugate(q)), [1, 0, 0, 0], atol=1e-15)


# ---- run(): files and dicts -------------------------------------------------------------------

def short_pet_erg(duration: float = 10.0) -> dict:
    sc = load("pet_erg_paper.toml")
    sc["simulation"]["duration"] = duration
    sc["simulation"]["output_interval"] = 0.05
    return sc


def test_run_dict_returns_numpy_series_and_summary():
    res = ag.run(short_pet_erg())
    assert res.kind == "pet_erg"
    t = res["t"]
    assert isinstance(t, np.ndarray) and t[0] == 0.0 and t[-1] == pytest.approx(10.0)
    for col in ("q_w", "q_x", "q_y", "q_z", "omega_x", "tau_norm", "V", "gamma", "margin_0"):
        assert res[col].shape == t.shape
    s = res.summary
    assert s["min_pointing_margin"] >= 0.0
    assert s["max_torque_norm"] <= 2.5
    assert np.min(res["margin_0"]) >= 0.0
    assert "wall_time_s" in s


def test_run_path_matches_dict(tmp_path):
    sc = short_pet_erg(5.0)
    path = tmp_path / "short.toml"
    path.write_text(ag.to_toml(sc))
    a = ag.run(path, out=tmp_path / "out")
    b = ag.run(sc)
    assert (tmp_path / "out" / "summary.json").is_file()
    assert a.summary["min_pointing_margin"] == b.summary["min_pointing_margin"]
    np.testing.assert_array_equal(a["tau_norm"], b["tau_norm"])


def test_run_and_reach_into_an_existing_file_raise_the_input_error(tmp_path):
    # issue 49: out=<a file> used to raise FileExistsError, not the package's error type.
    taken = tmp_path / "taken"
    taken.write_text("not a directory\n")
    with pytest.raises(ag.InputError, match=r"^out: .*taken: cannot create output directory"):
        ag.run(short_pet_erg(1.0), out=taken)
    with pytest.raises(ag.InputError, match=r"^out: .*taken.*: cannot create output directory"):
        ag.run(short_pet_erg(1.0), out=taken / "below")
    sc = load("conreach_pd.toml")
    with pytest.raises(ag.InputError, match=r"^out: .*taken: cannot create output directory"):
        ag.reach(sc, out=taken)
    assert taken.read_text() == "not a directory\n"


def test_run_without_out_writes_no_file(monkeypatch):
    # run() fills the numpy arrays directly: no temporary directory, no CSV to read back.
    import tempfile

    def no_temporary_files(*args, **kwargs):
        raise AssertionError("run() created a temporary file or directory")

    for name in ("mkdtemp", "mkstemp", "TemporaryDirectory", "NamedTemporaryFile"):
        monkeypatch.setattr(tempfile, name, no_temporary_files)
    res = ag.run(short_pet_erg(2.0))
    assert res.out_dir is None
    assert res["t"][-1] == pytest.approx(2.0)
    assert res.summary["output_rows"] == len(res["t"])


def test_check_returns_kind():
    assert ag.check(EXAMPLES / "waypoint_paper.toml") == "waypoint"
    assert ag.check(load("rigid_body_pd.toml")) == "rigid_body"


def test_predict_gives_the_waypoint_prediction_and_refuses_other_kinds():
    p = ag.predict(EXAMPLES / "waypoint_paper.toml")
    assert len(p["legs"]) == 3
    assert p["time"] == pytest.approx(sum(leg["time"] for leg in p["legs"]))
    assert 0.9 * 3240.4 < p["time"] < 1.1 * 3240.4  # the flown mission (docs/waypoint.md)
    assert ag.run(EXAMPLES / "waypoint_paper.toml").summary["prediction"] == p
    with pytest.raises(ag.InputError) as info:
        ag.predict(load("rigid_body_pd.toml"))
    assert "kind" in str(info.value) and "waypoint" in str(info.value)


# ---- errors: same messages as the CLI ---------------------------------------------------------

def test_input_error_from_file_has_the_cli_message():
    bad = EXAMPLES / "bad" / "typo_key.toml"
    with pytest.raises(ag.InputError) as info:
        ag.run(bad)
    message = str(info.value)
    assert "kpp" in message and str(bad) in message
    assert info.value.exit_code == 2 and isinstance(info.value, ag.Error)
    cli = BUILD / "src" / "attiguard"
    if cli.is_file():
        proc = subprocess.run([str(cli), "check", str(bad)], capture_output=True, text=True)
        assert proc.returncode == 2
        assert proc.stderr.strip() == f"attiguard: error: {message}"


def test_input_error_from_dict_names_the_key():
    sc = short_pet_erg()
    sc["control"]["tau_max"] = -1.0
    with pytest.raises(ag.InputError, match=r"<dict>.*tau_max"):
        ag.run(sc)
    with pytest.raises(ag.InputError, match="nan"):
        ag.check({**short_pet_erg(), "erg": {**short_pet_erg()["erg"], "kappa": float("nan")}})
    with pytest.raises(TypeError):
        ag.run(42)


# ---- step-able objects: close the loop in Python ----------------------------------------------

def test_governor_closed_loop_in_python_keeps_the_constraints():
    J = np.diag([1.0, 2.0, 3.0])
    cone = ag.keep_in_cone([0, 0, 1], [-0.791, 0.061, -0.609], half_angle_deg=160.0)
    gov = ag.Governor(J, kp=5.0, kd=1.0, tau_max=2.5, cones=[cone], Ts=0.5)
    body = ag.RigidBody(J)
    R, w = np.eye(3), np.array([0.2, 0.3, 0.4])
    R_d = ag.expm([0.0, math.pi / 2, 0.0])
    gov.reset(0.0, R)
    dt, worst_margin, worst_tau, holds = 0.005, math.inf, 0.0, 0
    for k in range(int(20.0 / dt)):
        out = gov.step(k * dt, R, w, R_d)
        worst_margin = min(worst_margin, cone.margin(R))
        worst_tau = max(worst_tau, float(np.linalg.norm(out.tau_b)))
        holds += not out.trigger
        # semi-implicit Lie-Euler step of Ṙ = R ω̂, J ω̇ = Jω × ω + τ
        w = w + dt * body.angular_acceleration(w, out.tau_b)
        R = R @ ag.expm(dt * w)
    assert worst_margin >= 0.0
    assert worst_tau <= 2.5 + 1e-9
    assert holds > 0
    assert gov.gamma_d > 0.0
    assert ag.distance(gov.reference, R_d) < ag.distance(np.eye(3), R_d)


def test_mission_and_pid_step():
    m = ag.Mission([[100.0, 0.0, 0.0]])
    cmd = m.step(ag.expm([0.0, 0.0, 0.5]), np.zeros(3), np.zeros(3), np.zeros(3), 0.1)
    assert cmd["mode"] == "align" and cmd["thrust"] == 0.0
    np.testing.assert_allclose(cmd["R_d"] @ [1.0, 0.0, 0.0], [1.0, 0.0, 0.0], atol=1e-9)
    pid = ag.QuaternionPid(kp=20.0, ki=0.0, kd=20.0)
    tau = pid.step([1.0, 0.0, 0.0, 0.0], np.zeros(3), ag.quat_from_axis_angle([0, 0, 1], 0.2),
                   np.zeros(3), 0.1)
    assert tau[2] > 0.0


def test_governor_rejects_bad_parameters():
    J = np.diag([1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match=r"^Governor\(\): tau_max: must be > 0, got -1$"):
        ag.Governor(J, kp=5.0, kd=1.0, tau_max=-1.0)
    # the file reader's inertia check (shared C++ validation): triangle inequality
    with pytest.raises(ValueError, match=r"Governor\(\): J: principal moments 1, 1, 3 violate the triangle"):
        ag.Governor(np.diag([1.0, 1.0, 3.0]), kp=5.0, kd=1.0, tau_max=1.0)
    with pytest.raises(ValueError, match=r"Governor\(\): Ts: must be finite, got nan"):
        ag.Governor(J, kp=5.0, kd=1.0, tau_max=1.0, Ts=float("nan"))
    # kp, kd, tau_max are required, as in a scenario file (no silent defaults)
    with pytest.raises(TypeError):
        ag.Governor(J)  # type: ignore[call-arg]


def test_cones_take_explicit_units_and_the_file_checks():
    assert ag.keep_out_cone([0, 0, 1], [1, 0, 0], half_angle_deg=40.0).theta_c == pytest.approx(
        math.radians(140.0))
    assert ag.keep_in_cone([0, 0, 1], [1, 0, 0], half_angle_rad=0.5).theta_c == 0.5
    with pytest.raises(ValueError, match="half_angle_rad is in radians; for 40 degrees write half_angle_deg = 40"):
        ag.keep_out_cone([0, 0, 1], [1, 0, 0], half_angle_rad=40.0)
    with pytest.raises(ValueError, match=r"half_angle_deg: must be in \[0, 180\), got 200"):
        ag.keep_out_cone([0, 0, 1], [1, 0, 0], half_angle_deg=200.0)
    with pytest.raises(ValueError, match=r"direction_i: must be a non-zero direction"):
        ag.keep_in_cone([0, 0, 1], [0, 0, 0], half_angle_deg=30.0)
    with pytest.raises(ValueError, match="exactly one of half_angle_deg"):
        ag.keep_in_cone([0, 0, 1], [1, 0, 0])
    with pytest.raises(ValueError, match="not both"):
        ag.keep_in_cone([0, 0, 1], [1, 0, 0], half_angle_deg=30.0, half_angle_rad=0.5)


def test_governor_step_refuses_bad_state_naming_the_argument():
    gov = ag.Governor(np.diag([1.0, 2.0, 3.0]), kp=5.0, kd=1.0, tau_max=2.5)
    with pytest.raises(ValueError, match=r"Governor.step\(\): call reset\(t0, R_g0\) before the first step"):
        gov.step(0.0, np.eye(3), np.zeros(3), np.eye(3))
    gov.reset(0.0, np.eye(3))
    with pytest.raises(ValueError, match=r"Governor.step\(\): R: not a rotation matrix"):
        gov.step(0.0, 2.0 * np.eye(3), np.zeros(3), np.eye(3))
    with pytest.raises(ValueError, match=r"Governor.step\(\): omega_b\[0\]: must be finite, got nan"):
        gov.step(0.0, np.eye(3), np.array([np.nan, 0.0, 0.0]), np.eye(3))
    with pytest.raises(ValueError, match=r"Governor.step\(\): R_d: not a rotation matrix"):
        gov.step(0.0, np.eye(3), np.zeros(3), np.zeros((3, 3)))
    assert np.all(np.isfinite(gov.step(1.0, np.eye(3), np.zeros(3), np.eye(3)).tau_b))
    with pytest.raises(ValueError, match=r"t: time went backwards \(t = 0.5 s < 1 s of the previous call\)"):
        gov.step(0.5, np.eye(3), np.zeros(3), np.eye(3))


def test_mission_refuses_a_zero_mass():
    with pytest.raises(ValueError, match=r"^Mission\(\): mass: must be > 0, got 0$"):
        ag.Mission([[100.0, 0.0, 0.0]], mass=0.0)
    with pytest.raises(ValueError, match=r"Mission\(\): waypoints\[0\]\[0\]: must be finite"):
        ag.Mission([[math.nan, 0.0, 0.0]])


def test_mission_refuses_no_waypoints():
    # issue 49: Mission([]) was accepted and stepped as `done`.
    with pytest.raises(ag.InputError, match=r"^Mission\(\): waypoints: expected a non-empty list"):
        ag.Mission([])


# ---- reach(): the balls -----------------------------------------------------------------------

def test_reach_returns_the_balls():
    sc = load("conreach_pd.toml")
    sc["reach"]["steps"] = 5
    sc["reach"]["horizon"] = 0.5
    sc["soundness"]["samples"] = 50
    res = ag.reach(sc)
    assert res.verdict == "safe"
    assert len(res.balls["r"]) == 5
    assert np.all(res.balls["r"] > 0.0)


def test_missing_extension_module_gives_a_clear_import_error(tmp_path):
    # The pure-Python files without the compiled _core (the source tree, an unfinished build):
    # `import attiguard` works (attiguard.plot needs nothing more), and the first name that needs
    # _core raises an ImportError that says what is missing and how to build it.
    import shutil
    copy = tmp_path / "attiguard"
    shutil.copytree(Path(ag.__file__).parent, copy,
                    ignore=shutil.ignore_patterns("_core*.so", "__pycache__"))
    env = dict(os.environ, PYTHONPATH=str(tmp_path), PYTHONNOUSERSITE="1")
    code = ("import attiguard\n"
            "try:\n"
            "    attiguard.expm([0.0, 0.0, 1.0])\n"
            "except ImportError as e:\n"
            "    print(e)\n")
    r = subprocess.run([sys.executable, "-c", code], env=env, cwd=tmp_path,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert "attiguard._core is missing" in r.stdout
    assert "pip install ." in r.stdout and "scripts/build.sh" in r.stdout


def test_version_is_the_cmake_project_version():
    cmake = (REPO / "CMakeLists.txt").read_text()
    match = re.search(r"project\(\s*attiguard\s+VERSION\s+([0-9.]+)", cmake)
    assert match is not None
    assert ag.__version__ == match.group(1)
    if INSTALLED:  # pip's metadata (setup.py reads the same project(VERSION))
        from importlib.metadata import version
        assert version("attiguard") == ag.__version__


def test_public_names_resolve_and_are_listed():
    for name in ag.__all__:
        assert getattr(ag, name) is not None, name
    assert set(ag.__all__) <= set(dir(ag))
    with pytest.raises(AttributeError):
        ag.no_such_name  # noqa: B018


def test_governor_from_scenario_is_the_flight_loops_robust_governor(tmp_path):
    """Governor.from_scenario builds the governor of a pet_erg file as its flight loop does
    (docs/pet-erg.md, section 13): with margins = "robust" the level is W and Γ is Γ_W."""
    import pathlib
    import numpy as np
    import attiguard
    text = (pathlib.Path(__file__).resolve().parents[2] / "examples" / "pet_erg_robust_campaign.toml").read_text()
    path = tmp_path / "robust.toml"
    path.write_text(text[: text.index("[dispersions]")])
    gov = attiguard.Governor.from_scenario(str(path))
    robust = gov.robust
    assert robust is not None and robust["gamma_min"] > 0.0 and 0.0 < robust["delta"] < 1.0
    gov.reset(0.0, np.eye(3))
    R_d = attiguard.expm(np.array([0.0, 0.0, 120.0 * np.pi / 180.0]))
    R = attiguard.expm(np.array([0.01, 0.0, 0.0]))
    out = gov.step(0.0, R, np.array([1e-3, -1e-3, 5e-4]), R_d)
    assert out.W == gov.level(R, np.array([1e-3, -1e-3, 5e-4]), np.eye(3))
    assert out.W != out.V
    assert out.gamma == gov.gamma(np.eye(3))
    nominal = tmp_path / "nominal.toml"
    nominal.write_text(text[: text.index("[dispersions]")].replace('margins = "robust"', 'margins = "nominal"')
                       .replace("robust_reference_step", "# robust_reference_step"))
    assert attiguard.Governor.from_scenario(str(nominal)).robust is None
    bad = tmp_path / "bad.toml"
    bad.write_text(text[: text.index("[dispersions]")].replace("disturbance_bound = 0.003", "disturbance_bound = 0.03"))
    import pytest
    with pytest.raises(ValueError, match="control.margins: no admissible set with robust margins"):
        attiguard.Governor.from_scenario(str(bad))
