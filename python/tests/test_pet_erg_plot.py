"""Plots of scenario kind `pet_erg` (PET-ERG paper, Figs. 2-5) on a synthetic run, and of a
planned run (governor = "planned", docs/pet-erg.md 16.2) written by the built CLI."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

from attiguard.plot import EXIT_OK, EXIT_USAGE, pet_erg
from attiguard.plot.__main__ import main
from attiguard.plot.common import load_run

from conftest import package_parent

REPO = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("ATTIGUARD_BUILD_DIR", REPO / "build")).resolve()

PET_ERG_PNGS = ["pet_erg_sphere.png", "pet_erg_errors.png", "pet_erg_lyapunov.png",
                "pet_erg_torque.png", "pet_erg_margins.png"]
# A planned run adds the plan clock's figure (sigma and s_dot against t) after the torque.
PLANNED_PNGS = ["pet_erg_sphere.png", "pet_erg_errors.png", "pet_erg_lyapunov.png",
                "pet_erg_torque.png", "pet_erg_progress.png", "pet_erg_margins.png"]

# A CubeSat's 90 deg slew about z whose +x axis must go around a Sun cone on its eigenaxis path:
# planned at set-up and flown at 20 Hz under the progress governor against a sinusoidal
# disturbance of 10 % tau_max, which slows the clock (min s_dot about 0.91, a few choices
# inadmissible). Under 1 s.
PLANNED_SCENARIO = """\
kind = "pet_erg"
name = "small_planned"
governor = "planned"

[body]
inertia = [[0.05, 0.0, 0.0], [0.0, 0.06, 0.0], [0.0, 0.0, 0.04]]

[initial]
attitude = { matrix = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] }
omega_b = [0.0, 0.0, 0.0]

[desired]
attitude = { axis = [0.0, 0.0, 1.0], angle_deg = 90.0 }

[control]
tau_max = 0.01
control_period = 0.05

[[cones]]
type = "keep_out"
axis_b = [1.0, 0.0, 0.0]
direction_i = [0.70710678, 0.70710678, 0.0]
half_angle_deg = 20.0

[imperfections]
disturbance = "sinusoidal"
disturbance_bound = 0.001
disturbance_period = 4.0
disturbance_axis_b = [0.3, 0.2, 1.0]

[simulation]
duration = 20.0
output_interval = 0.1
"""


def write_pet_erg_run(directory: Path, cones: int = 2, drop: str | None = None) -> Path:
    """A slew about y written like `attiguard run` writes a pet_erg scenario."""
    directory.mkdir(parents=True)
    t = np.linspace(0.0, 10.0, 201)
    angle = 0.5 * np.pi * (1.0 - np.exp(-t))
    q = np.column_stack([np.cos(angle / 2), 0 * t, np.sin(angle / 2), 0 * t])
    qd = np.tile([np.cos(np.pi / 4), 0.0, np.sin(np.pi / 4), 0.0], (len(t), 1))
    cols = {"t": t}
    for i, c in enumerate("wxyz"):
        cols[f"q_{c}"] = q[:, i]
        cols[f"qg_{c}"] = q[:, i]
        cols[f"qd_{c}"] = qd[:, i]
    for c in "xyz":
        cols[f"omega_{c}"] = np.exp(-t) * (c == "y")
        cols[f"tau_{c}"] = -np.exp(-t) * (c == "y")
    cols["tau_norm"] = np.exp(-t)
    cols["V"] = 0.3 * np.exp(-t)
    cols["gamma_d"] = np.full_like(t, 0.54)
    if cones:  # attiguard writes gamma_g only with cones (+inf without one)
        cols["gamma_g"] = 0.7 + 0.0 * t
    cols["gamma"] = np.minimum(cols["gamma_d"], cols.get("gamma_g", np.inf))
    cols["trigger"] = (t > 2.0).astype(float)
    cols["attitude_error"] = 1.0 - np.cos(0.5 * np.pi - angle)
    cols["reference_error"] = cols["attitude_error"]
    for i in range(cones):
        cols[f"margin_{i}"] = 0.1 + 0.01 * i + 0 * t
    if drop:
        cols.pop(drop)
    names = list(cols)
    with (directory / "trajectory.csv").open("w") as f:
        f.write(",".join(names) + "\n")
        for k in range(len(t)):
            f.write(",".join(repr(float(cols[n][k])) for n in names) + "\n")
    summary = {"kind": "pet_erg", "name": "synthetic", "governor": "pet", "tau_max": 2.5,
               "cones": [{"axis_b": [0, 0, 1], "direction_i": [-0.79, 0.06, -0.61],
                          "theta_c_deg": 160.0},
                         {"axis_b": [1, 0, 0], "direction_i": [0.0, 0.0, 1.0],
                          "theta_c_deg": 150.0}][:cones]}
    (directory / "summary.json").write_text(json.dumps(summary))
    return directory


def test_pet_erg_writes_every_png(tmp_path, capsys):
    run = write_pet_erg_run(tmp_path / "run")
    assert main(["pet_erg", str(run)]) == EXIT_OK
    printed = capsys.readouterr().out.split()
    assert [Path(p).name for p in printed] == PET_ERG_PNGS
    for name in PET_ERG_PNGS:
        assert (run / name).stat().st_size > 1000


def test_pet_erg_without_cones(tmp_path):
    run = write_pet_erg_run(tmp_path / "run", cones=0)
    assert "gamma_g" not in (run / "trajectory.csv").read_text().splitlines()[0].split(",")
    assert main(["pet_erg", str(run)]) == EXIT_OK


def test_pet_erg_missing_column_exits_2(tmp_path, capsys):
    run = write_pet_erg_run(tmp_path / "run", drop="gamma_d")
    assert main(["pet_erg", str(run)]) == EXIT_USAGE
    assert "gamma_d" in capsys.readouterr().err


@pytest.fixture(scope="module")
def planned_run(tmp_path_factory) -> Path:
    """`attiguard run SCENARIO --out DIR --plot` of PLANNED_SCENARIO with the built CLI, its plots
    made by the attiguard.plot under test (ATTIGUARD_PYTHON_DIR)."""
    cli = BUILD / "src" / "attiguard"
    if not cli.is_file():
        pytest.skip(f"no CLI at {cli}")
    work = tmp_path_factory.mktemp("planned")
    scenario = work / "small_planned.toml"
    scenario.write_text(PLANNED_SCENARIO)
    env = dict(os.environ, ATTIGUARD_PYTHON_DIR=str(package_parent()))
    proc = subprocess.run([str(cli), "run", str(scenario), "--out", str(work / "run"), "--plot"],
                          capture_output=True, text=True, env=env, cwd=work)
    assert proc.returncode == 0, proc.stderr
    for name in PLANNED_PNGS:
        assert f"run/{name}" in proc.stdout, proc.stdout
    return work / "run"


def test_planned_run_writes_every_png_with_the_clock_figure(planned_run, capsys):
    header = (planned_run / "trajectory.csv").read_text().splitlines()[0].split(",")
    assert {"s", "s_dot", "torque_bound", "admissible", "gamma_g"} <= set(header)
    assert not {"gamma_d", "gamma", "trigger"} & set(header)
    assert json.loads((planned_run / "summary.json").read_text())["governor"] == "planned"
    for name in PLANNED_PNGS:
        assert (planned_run / name).stat().st_size > 1000
    # Again through `python3 -m attiguard.plot`: the same figures, in this order.
    assert main(["pet_erg", str(planned_run)]) == EXIT_OK
    printed = capsys.readouterr().out.split()
    assert [Path(p).name for p in printed] == PLANNED_PNGS


def test_planned_figures_show_the_plan_the_clock_and_the_torque_bound(planned_run, monkeypatch):
    """The figures' content, caught before saving: the plan's clock panel (sigma and s_dot), the
    torque against tau_max and torque_bound, V without Gamma_d / Gamma, labels naming the plan."""
    figures = {}

    def keep(fig, run, filename):
        figures[filename] = fig
        return run.dir / filename

    monkeypatch.setattr(pet_erg, "save", keep)
    run = load_run(planned_run)
    pet_erg.plot(run)
    assert sorted(figures) == sorted(PLANNED_PNGS)

    def labels(name):
        return [line.get_label() for ax in figures[name].axes for line in ax.get_lines()]

    def texts(name):
        return " ".join(ax.get_title() + " " + ax.get_ylabel() + " " + ax.get_xlabel()
                        for ax in figures[name].axes)

    clock = figures["pet_erg_progress.png"].axes
    assert len(clock) == 2
    assert "σ" in clock[0].get_ylabel() and "ṡ" in clock[1].get_ylabel()
    assert "σ (plan clock)" in labels("pet_erg_progress.png")
    assert "ṡ" in labels("pet_erg_progress.png")
    sigma_line = next(line for line in clock[0].get_lines() if line.get_label() == "σ (plan clock)")
    assert np.allclose(sigma_line.get_ydata(), run.column("s"))
    t_p = run.summary["planned"]["plan"]["duration"]
    assert any(line.get_label().startswith("T_p") and np.allclose(line.get_ydata(), t_p)
               for line in clock[0].get_lines())
    # The rate's panel: s_dot, and red spans where a choice of s_dot was inadmissible (the
    # clock braked; this run has some at the time of writing).
    rate_line = next(line for line in clock[1].get_lines() if line.get_label() == "ṡ")
    assert np.allclose(rate_line.get_ydata(), run.column("s_dot"))
    shaded = any(patch.get_label().startswith("choice of ṡ inadmissible")
                 for patch in clock[1].patches)
    assert shaded == bool(np.any(run.column("admissible") < 0.5))

    torque = labels("pet_erg_torque.png")
    assert "τ_max" in torque
    assert any(label.startswith("torque bound") for label in torque)
    assert not any(label.startswith("Γ_d") or label.startswith("Γ =") for label in
                   labels("pet_erg_lyapunov.png"))
    assert "Γ_g over the plan ahead" in labels("pet_erg_lyapunov.png")
    assert "plan R_p(σ)" in texts("pet_erg_errors.png")
    assert any("R_p(σ) a_b" in label for label in labels("pet_erg_sphere.png"))
    assert not any(label == "R_g a_b" for label in labels("pet_erg_sphere.png"))
    assert "margin" in texts("pet_erg_margins.png")


def test_planned_run_without_gamma_g(planned_run, tmp_path):
    """Without cones the run writes no gamma_g: the figures are written all the same."""
    run = tmp_path / "run"
    run.mkdir()
    rows = [line.split(",") for line in (planned_run / "trajectory.csv").read_text().splitlines()]
    k = rows[0].index("gamma_g")
    (run / "trajectory.csv").write_text("\n".join(",".join(r[:k] + r[k + 1:]) for r in rows) + "\n")
    (run / "summary.json").write_text((planned_run / "summary.json").read_text())
    assert main(["pet_erg", str(run)]) == EXIT_OK
    for name in PLANNED_PNGS:
        assert (run / name).stat().st_size > 1000


def test_pet_runs_have_no_clock_figure(tmp_path):
    run = write_pet_erg_run(tmp_path / "run")
    assert main(["pet_erg", str(run)]) == EXIT_OK
    assert not (run / "pet_erg_progress.png").exists()
