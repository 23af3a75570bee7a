#!/usr/bin/env python3
"""Reproduces Fig. 4 of the PET-ERG paper (Lyapunov function V against the thresholds Γ_d, Γ_g
and Γ, with the hold intervals of the trigger (5) shaded) from Python, with the `attiguard`
package (docs/python.md), and prints the figures of merit of the run.

Usage (from the repository root, after `bash scripts/build.sh`; or with a venv's python after
`pip install .`, docs/python.md "Installing"):
    PYTHONPATH=build/python /usr/bin/python3 examples/python_pet_erg_figure.py [OUT_DIR]  # default out/python
Writes OUT_DIR/pet_erg_fig4_lyapunov.png.
"""

from __future__ import annotations

import sys
import tomllib
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import attiguard  # noqa: E402

REPO = Path(__file__).resolve().parent.parent


def main() -> int:
    out_dir = Path(sys.argv[1]) if len(sys.argv) > 1 else REPO / "out" / "python"
    out_dir.mkdir(parents=True, exist_ok=True)

    # The paper's Sec. V scenario, as a dict: the same file `attiguard run` reads.
    scenario = tomllib.loads((REPO / "examples" / "pet_erg_paper.toml").read_text())
    scenario["simulation"]["duration"] = 30.0
    result = attiguard.run(scenario)
    t, s = result["t"], result.summary

    fig, ax = plt.subplots(figsize=(7.0, 3.6), dpi=120)
    held = result["trigger"] < 0.5
    edges = np.flatnonzero(np.diff(np.r_[0, held.astype(int), 0]))
    for start, stop in zip(edges[0::2], edges[1::2]):
        ax.axvspan(t[start], t[min(stop, len(t) - 1)], color="0.9", lw=0)
    ax.plot(t, result["V"], label="V(R, ω, R_g)")
    ax.plot(t, result["gamma"], label="Γ(R_g)")
    ax.plot(t, result["gamma_g"], "--", label="Γ_g(R_g)")
    ax.plot(t, result["gamma_d"], ":", label="Γ_d")
    ax.set_yscale("log")
    ax.set_xlabel("t [s]")
    ax.set_title("PET-ERG paper, Fig. 4 (grey: R_g held, trigger (5) false)")
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    path = out_dir / "pet_erg_fig4_lyapunov.png"
    fig.savefig(path)

    print(f"min pointing margin {s['min_pointing_margin']:.4f} (>= 0), "
          f"max |tau| {s['max_torque_norm']:.4f} N m (tau_max 2.5), "
          f"Gamma_d {s['gamma_d']:.4f}")
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
