#!/usr/bin/env python3
"""Writes OUT/index.md, the page a newcomer opens first after `bash scripts/main.sh`: one section
per result folder of OUT (in the order given), with what it is, the command that made it, its
headline figures from summary.json / reach.json and links to its plots.

Usage: /usr/bin/python3 scripts/results_index.py OUT ENTRY... where ENTRY is
DIR|TITLE|COMMAND|DOC (DIR relative to OUT; DOC a path relative to the repository root).
Standard library only.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

# Headline figures, in order, when present in the summary.
KEYS = [
    "verdict", "governor", "completed", "min_pointing_margin", "max_torque_norm", "tau_max",
    "gamma_d", "first_pointing_violation_time", "final_attitude_error", "total_time",
    "total_delta_v", "first_failure_time", "cells", "sdp_solves", "wall_time_s",
]


def fmt(v: object) -> str:
    if isinstance(v, float):
        return f"{v:.6g}"
    return json.dumps(v) if not isinstance(v, str) else v


def section(out: Path, entry: str) -> list[str]:
    dir_name, title, command, doc = (entry.split("|") + ["", "", ""])[:4]
    d = out / dir_name
    lines = [f"## {title}", ""]
    if not d.is_dir():
        return lines + [f"*Not produced* (`{command}` did not run).", ""]
    lines += [f"Command: `{command}`" + (f" — documentation: [{doc}](../{doc})" if doc else ""), ""]
    summary = {}
    for name in ("summary.json", "reach.json"):
        if (d / name).is_file():
            summary = json.loads((d / name).read_text())
            lines.append(f"Summary: [{dir_name}/{name}]({dir_name}/{name})")
            break
    rows = [(k, summary[k]) for k in KEYS if k in summary and not isinstance(summary[k], (dict, list))]
    if rows:
        lines += ["", "| figure | value |", "| --- | --- |"]
        lines += [f"| `{k}` | {fmt(v)} |" for k, v in rows]
    pngs = sorted(d.glob("*.png"))
    if pngs:
        lines.append("")
        for p in pngs:
            lines.append(f"![{p.stem}]({dir_name}/{p.name})")
    lines.append("")
    return lines


def main(argv: list[str]) -> int:
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    out = Path(argv[1])
    lines = [
        "# attiguard results",
        "",
        "Written by `bash scripts/main.sh`. Each section is one run: what it shows, the command",
        "that reproduces it, its headline figures and its plots. Time series are in each folder's",
        "`trajectory.csv`; units are SI (docs/conventions.md).",
        "",
    ]
    for entry in argv[2:]:
        lines += section(out, entry)
    (out / "index.md").write_text("\n".join(lines))
    print(f"results_index.py: wrote {out / 'index.md'}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
