"""Tests of the plotting subpackage attiguard.plot on synthetic `attiguard run` outputs."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from conftest import package_parent

from attiguard.plot import EXIT_DEPENDENCY_MISSING, EXIT_OK, EXIT_USAGE
from attiguard.plot.__main__ import main


RIGID_BODY_COLUMNS = [
    "t", "q_w", "q_x", "q_y", "q_z", "omega_x", "omega_y", "omega_z", "tau_x", "tau_y", "tau_z",
    "attitude_error_rad", "phi", "energy", "V", "h_x", "h_y", "h_z",
]
RIGID_BODY_PNGS = ["attitude_error.png", "angular_velocity.png", "torque.png", "quaternion.png",
                   "energy_momentum.png"]


def write_rigid_body_run(directory: Path, law: str = "pd", columns=RIGID_BODY_COLUMNS) -> Path:
    """A damped slew about x written like `attiguard run` writes a rigid_body scenario."""
    directory.mkdir(parents=True, exist_ok=True)
    t = np.linspace(0.0, 10.0, 201)
    theta = (np.pi / 2) * np.exp(-0.5 * t)
    omega = np.gradient(theta, t)
    values = {
        "t": t, "q_w": np.cos(theta / 2), "q_x": np.sin(theta / 2), "q_y": 0 * t, "q_z": 0 * t,
        "omega_x": omega, "omega_y": 0 * t, "omega_z": 0 * t,
        "tau_x": -2.0 * theta - omega, "tau_y": 0 * t, "tau_z": 0 * t,
        "attitude_error_rad": np.abs(theta), "phi": 1 - np.cos(theta),
        "energy": 0.5 * omega**2, "V": 0.5 * omega**2 + 2 * (1 - np.cos(theta)),
        "h_x": omega, "h_y": 0 * t, "h_z": 0 * t,
    }
    table = np.column_stack([values[c] for c in columns])
    np.savetxt(directory / "trajectory.csv", table, delimiter=",", header=",".join(columns),
               comments="", fmt="%.17g")
    (directory / "summary.json").write_text(
        json.dumps({"kind": "rigid_body", "name": "synthetic slew", "law": law,
                    "wall_time_s": 0.01}))
    return directory


def test_rigid_body_writes_every_png(tmp_path, capsys):
    run = write_rigid_body_run(tmp_path / "run")
    assert main(["rigid_body", str(run)]) == EXIT_OK
    printed = capsys.readouterr().out.split()
    for png in RIGID_BODY_PNGS:
        path = run / png
        assert path.stat().st_size > 1000
        assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert str(path) in printed


def test_free_body_with_zero_error_at_start(tmp_path):
    # Non-PD laws measure the distance to the initial attitude, which is 0 at t = 0.
    run = write_rigid_body_run(tmp_path / "run", law="free")
    assert main(["rigid_body", str(run)]) == EXIT_OK
    assert (run / "attitude_error.png").exists()


def test_unknown_kind_exits_2_with_one_line(tmp_path, capsys):
    run = write_rigid_body_run(tmp_path / "run")
    assert main(["no_such_kind", str(run)]) == EXIT_USAGE
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert "no_such_kind" in err and "rigid_body" in err


def test_missing_trajectory_exits_2(tmp_path, capsys):
    assert main(["rigid_body", str(tmp_path)]) == EXIT_USAGE
    assert "trajectory.csv" in capsys.readouterr().err


def test_missing_column_exits_2(tmp_path, capsys):
    columns = [c for c in RIGID_BODY_COLUMNS if c != "energy"]
    run = write_rigid_body_run(tmp_path / "run", columns=columns)
    assert main(["rigid_body", str(run)]) == EXIT_USAGE
    assert "energy" in capsys.readouterr().err


def _module_env() -> dict[str, str]:
    env = dict(os.environ)
    env["PYTHONPATH"] = str(package_parent())
    return env


def test_module_entry_point(tmp_path):
    run = write_rigid_body_run(tmp_path / "run")
    r = subprocess.run([sys.executable, "-m", "attiguard.plot", "rigid_body", str(run)],
                       capture_output=True, text=True, env=_module_env(), check=False)
    assert r.returncode == EXIT_OK, r.stderr
    assert sorted(Path(p).name for p in r.stdout.split()) == sorted(RIGID_BODY_PNGS)


@pytest.mark.parametrize("blocked", ["matplotlib", "numpy"])
def test_missing_dependency_exits_69_with_one_line(tmp_path, blocked):
    run = write_rigid_body_run(tmp_path / "run")
    # sys.modules[name] = None makes `import name` raise ImportError, as if not installed.
    code = (f"import sys, runpy; sys.modules[{blocked!r}] = None; "
            f"sys.argv = ['attiguard.plot', 'rigid_body', {str(run)!r}]; "
            "runpy.run_module('attiguard.plot', run_name='__main__', alter_sys=True)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                       env=_module_env(), check=False)
    assert r.returncode == EXIT_DEPENDENCY_MISSING, r.stderr
    assert r.stderr.count("\n") == 1
    # matplotlib needs numpy, so blocking numpy reports both.
    assert blocked in r.stderr and "not installed" in r.stderr
    assert f"python3-{blocked}" in r.stderr
    assert not (run / "attitude_error.png").exists()


def test_plots_need_no_compiled_extension(tmp_path):
    # `attiguard run --plot` runs the plots from the source tree's python/package, which has no
    # _core: the package's files without the extension module must plot all the same.
    copy = tmp_path / "pkg" / "attiguard"
    shutil.copytree(package_parent() / "attiguard", copy,
                    ignore=shutil.ignore_patterns("_core*.so", "__pycache__"))
    assert not list(copy.glob("_core*.so"))
    run = write_rigid_body_run(tmp_path / "run")
    env = dict(os.environ, PYTHONPATH=str(copy.parent), PYTHONNOUSERSITE="1")
    r = subprocess.run([sys.executable, "-m", "attiguard.plot", "rigid_body", str(run)],
                       capture_output=True, text=True, env=env, cwd=tmp_path, check=False)
    assert r.returncode == EXIT_OK, r.stderr
    assert sorted(Path(p).name for p in r.stdout.split()) == sorted(RIGID_BODY_PNGS)
