"""scripts/reach_truth.py measure (issue 47, "proved where it is true"): the JSON it writes for
one short corpus loop, and a constructed violating copy of it classified "violates".

Reduced counts (--samples 24 --boundary 12 --starts 2 --maxfev 15) keep it to a few seconds;
the full measurement is in docs/reach.md, "Truth of the corpus".
"""

from __future__ import annotations

import json
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
from scipy.spatial.transform import Rotation

REPO_DIR = Path(__file__).resolve().parents[2]
SCRIPT = REPO_DIR / "scripts" / "reach_truth.py"
LOOP = REPO_DIR / "tests" / "data" / "reach" / "corpus" / "loop_01_pd.toml"  # T = 2 s, keep-out


def _initial_angle_deg(text: str) -> float:
    """Angle between R0 axis_b and direction_i at the centre of the initial set of the file."""
    att = re.search(r"^attitude = \{ axis = \[([^\]]*)\], angle_deg = ([^ ]*) \}", text, re.M)
    axis = np.array([float(x) for x in att.group(1).split(",")])
    r0 = Rotation.from_rotvec(math.radians(float(att.group(2))) * axis / np.linalg.norm(axis))
    ab = np.array([float(x) for x in re.search(r"^axis_b = \[([^\]]*)\]", text, re.M)
                   .group(1).split(",")])
    di = np.array([float(x) for x in re.search(r"^direction_i = \[([^\]]*)\]", text, re.M)
                   .group(1).split(",")])
    p = r0.apply(ab / np.linalg.norm(ab))
    di /= np.linalg.norm(di)
    return math.degrees(math.atan2(np.linalg.norm(np.cross(p, di)), p @ di))


def test_measure_fields_and_a_violating_copy(tmp_path: Path) -> None:
    text = LOOP.read_text()
    (tmp_path / "loop_01_pd.toml").write_text(text)
    # the same loop with the keep-out half-angle 5 deg beyond the centre's initial angle: the
    # centre of the initial set is inside the avoided cone at t = 0
    half = _initial_angle_deg(text) + 5.0
    bad = re.sub(r"^half_angle_deg = .*$", "half_angle_deg = %.6f" % half, text, flags=re.M)
    bad = bad.replace('name = "loop_01_pd"', 'name = "loop_01_violated"')
    (tmp_path / "loop_01_violated.toml").write_text(bad)
    out = tmp_path / "truth.json"
    subprocess.run([sys.executable, str(SCRIPT), "measure", "--dir", str(tmp_path), "--out",
                    str(out), "--samples", "24", "--boundary", "12", "--starts", "2",
                    "--maxfev", "15"], check=True, capture_output=True, text=True, timeout=60)
    doc = json.loads(out.read_text())
    assert doc["settings"]["samples_uniform"] == 24 and doc["settings"]["starts"] == 2
    loops = {r["name"]: r for r in doc["loops"]}
    assert set(loops) == {"loop_01_pd", "loop_01_violated"}

    good = loops["loop_01_pd"]
    assert good["samples"] == 1 + 24 + 12
    assert good["cls"] in ("roomy", "tight")  # its cone has a 10-40 % margin by construction
    (f,) = good["functionals"]
    for key in ("name", "kind", "bound", "worst_margin", "margin_pct", "sampling_worst_margin",
                "time", "eta", "domega", "R0_rotvec", "omega0", "ascent_evaluations"):
        assert key in f
    assert f["kind"] == "keep_out" and f["bound"] == 23.5
    assert 0.0 <= f["time"] <= 2.0
    assert f["worst_margin"] <= f["sampling_worst_margin"]  # the ascent never reports worse
    assert math.isclose(f["margin_pct"], 100.0 * f["worst_margin"] / f["bound"])
    assert f["eta_norm_over_a"] <= 1.0 + 1e-12 and f["domega_norm_over_b"] <= 1.0 + 1e-12
    assert good["worst_margin_pct"] == f["margin_pct"]

    viol = loops["loop_01_violated"]
    assert viol["cls"] == "violates"
    (fv,) = viol["functionals"]
    assert math.isclose(fv["bound"], half, rel_tol=1e-9)
    assert fv["worst_margin"] <= -5.0 + 1e-6  # at least the centre's 5 deg at t = 0
    assert fv["worst_margin"] < 0.0 and viol["worst_margin_pct"] < 0.0
