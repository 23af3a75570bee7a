"""Plots of scenario kind `pet_erg` (PET-ERG paper, Figs. 2-5) on a synthetic run."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from attiguard.plot import EXIT_OK, EXIT_USAGE
from attiguard.plot.__main__ import main

PET_ERG_PNGS = ["pet_erg_sphere.png", "pet_erg_errors.png", "pet_erg_lyapunov.png",
                "pet_erg_torque.png", "pet_erg_margins.png"]


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
