#!/usr/bin/env python3
"""Every example's figures, captured once and compared on every test run (docs/architecture.md,
"Behaviour kept").

Each example of examples/*.toml is run through the `attiguard` program (`attiguard run` for the
simulation kinds, `attiguard reach` for kind reach) into a scratch directory; every figure of its
summary.json (reach.json for kind reach) is flattened to a key path ("cones[0].delta") and
compared with the committed figures in tests/data/example_figures/<example>.json. Numbers must
agree to 1e-12 relative (absolute floor 1e-300 for zeros), booleans, strings and nulls exactly, and
the exit code exactly; a campaign example (with [dispersions]) is compared through the summary
of its dispersed run REPLAY_RUN (`attiguard campaign FILE --replay K`); a figure missing from either side is a failure. Machine-dependent fields
(wall times, thread counts, output paths) are left out (MACHINE_DEPENDENT below).

Compare also checks the stdout of the command: exactly one line that starts with "outcome: "
(docs/conventions.md, "Outcome line"), followed by "Wrote:" and the paths written. For a
campaign example it also runs a small campaign (CAMPAIGN_RUNS runs), and for a pet_erg example a
small `attiguard tune` (TUNE_BUDGET points), and checks their stdout the same way.

Capture (rewrites the committed figures; run it only when a change of the figures is intended,
e.g. after a change to ConReach's bounds, and commit the result):

    scripts/capture_example_figures.sh                 # every example
    scripts/capture_example_figures.sh conreach_pd     # just these examples

Compare (what the CTest tests ExampleFigures.<example> run):

    /usr/bin/python3 scripts/example_figures.py compare --cli build/src/attiguard --example NAME
"""

from __future__ import annotations

import argparse
import json
import math
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"
FIGURES = ROOT / "tests" / "data" / "example_figures"

# Keys whose values depend on the machine or the run, not on the numerics.
MACHINE_DEPENDENT = {"wall_time_s", "threads", "ranks", "out_dir", "path"}

# Campaign examples (with [dispersions]) are compared through `attiguard campaign --replay K`:
# the summary of their dispersed run K.
REPLAY_RUN = 1

# The small campaign and tune whose stdout compare checks.
CAMPAIGN_RUNS = 3
TUNE_BUDGET = 4

REL_TOL = 1e-12
ABS_FLOOR = 1e-300


def example_kind(path: pathlib.Path) -> str:
    for line in path.read_text().splitlines():
        stripped = line.strip()
        if stripped.startswith("kind") and "=" in stripped:
            return stripped.split("=", 1)[1].strip().strip('"')
    raise SystemExit(f"{path}: no top-level kind")


def is_campaign(path: pathlib.Path) -> bool:
    return any(line.strip() == "[dispersions]" for line in path.read_text().splitlines())


def examples() -> list[pathlib.Path]:
    return sorted(EXAMPLES.glob("*.toml"))


def flatten(value, prefix: str, out: dict) -> None:
    if isinstance(value, dict):
        for key, item in value.items():
            if key in MACHINE_DEPENDENT:
                continue
            flatten(item, f"{prefix}.{key}" if prefix else key, out)
    elif isinstance(value, list):
        for i, item in enumerate(value):
            flatten(item, f"{prefix}[{i}]", out)
    else:
        out[prefix] = value


def outcome_problems(command: str, stdout: str) -> list[str]:
    """What is wrong with a command's stdout: one "outcome: " line, then "Wrote:" (empty: fine)."""
    lines = stdout.splitlines()
    at = [i for i, line in enumerate(lines) if line.startswith("outcome: ")]
    if len(at) != 1:
        return [f"{command}: {len(at)} 'outcome: ' lines on stdout (expected 1):\n{stdout}"]
    i = at[0]
    if i + 1 >= len(lines) or lines[i + 1] != "Wrote:" or i + 2 >= len(lines):
        return [f"{command}: the outcome line is not followed by 'Wrote:' and paths:\n{stdout}"]
    return []


def side_commands(example: pathlib.Path, tmp: str) -> list[list[str]]:
    """The campaign and tune runs of an example whose stdout compare checks besides its own."""
    if is_campaign(example):
        return [["campaign", str(example), "--runs", str(CAMPAIGN_RUNS), "--threads", "2",
                 "--out", tmp]]
    if example_kind(example) == "pet_erg":
        return [["tune", str(example), "--budget", str(TUNE_BUDGET), "--threads", "2", "--no-plot",
                 "--out", tmp]]
    return []


def run_example(cli: str, example: pathlib.Path) -> dict:
    """Runs one example; returns {"exit_code": N, "figures": {path: value}, "stdout": text}."""
    kind = example_kind(example)
    with tempfile.TemporaryDirectory(prefix="attiguard_figures_") as tmp:
        out = pathlib.Path(tmp)
        if kind == "reach":
            args, summary_file = ["reach", str(example), "--out", tmp], out / "reach.json"
        elif is_campaign(example):  # run REPLAY_RUN of the campaign: a dispersed scenario
            args = ["campaign", str(example), "--replay", str(REPLAY_RUN), "--out", tmp]
            summary_file = out / f"run_{REPLAY_RUN}" / "summary.json"
        else:
            args, summary_file = ["run", str(example), "--out", tmp], out / "summary.json"
        proc = subprocess.run([cli, *args], cwd=ROOT, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True, check=False)
        if not summary_file.is_file():
            raise SystemExit(f"{example.name}: exit {proc.returncode}, no {summary_file.name}; "
                             f"stderr: {proc.stderr.strip()}")
        figures: dict = {}
        flatten(json.loads(summary_file.read_text()), "", figures)
    return {"exit_code": proc.returncode, "figures": figures, "stdout": proc.stdout,
            "command": " ".join(args[:2])}


def same(expected, got) -> bool:
    if isinstance(expected, bool) or isinstance(got, bool) or expected is None or got is None:
        return expected is got or expected == got and type(expected) is type(got)
    if isinstance(expected, (int, float)) and isinstance(got, (int, float)):
        if math.isnan(expected) or math.isnan(got):
            return math.isnan(expected) and math.isnan(got)
        return abs(expected - got) <= max(REL_TOL * max(abs(expected), abs(got)), ABS_FLOOR)
    return expected == got


def compare(cli: str, name: str) -> int:
    example = EXAMPLES / f"{name}.toml"
    reference = json.loads((FIGURES / f"{name}.json").read_text())
    result = run_example(cli, example)
    problems = []
    if result["exit_code"] != reference["exit_code"]:
        problems.append(f"exit code {result['exit_code']} != {reference['exit_code']}")
    expected, got = reference["figures"], result["figures"]
    for key in sorted(set(expected) - set(got)):
        problems.append(f"missing figure {key} (expected {expected[key]!r})")
    for key in sorted(set(got) - set(expected)):
        problems.append(f"extra figure {key} = {got[key]!r}")
    for key in sorted(set(expected) & set(got)):
        if not same(expected[key], got[key]):
            problems.append(f"{key}: {got[key]!r} != expected {expected[key]!r}")
    problems += outcome_problems(result["command"], result["stdout"])
    with tempfile.TemporaryDirectory(prefix="attiguard_outcome_") as tmp:
        for args in side_commands(example, tmp):
            proc = subprocess.run([cli, *args], cwd=ROOT, stdout=subprocess.PIPE,
                                  stderr=subprocess.PIPE, text=True, check=False)
            problems += outcome_problems(" ".join(args[:2]) + f" (exit {proc.returncode})",
                                         proc.stdout)
    for p in problems:
        print(f"{name}: {p}")
    print(f"{name}: {len(expected)} figures, {len(problems)} differences")
    return 1 if problems else 0


def capture(cli: str, names: list[str]) -> int:
    FIGURES.mkdir(parents=True, exist_ok=True)
    chosen = [EXAMPLES / f"{n}.toml" for n in names] if names else examples()
    for example in chosen:
        result = run_example(cli, example)
        result = {"exit_code": result["exit_code"], "figures": result["figures"]}
        (FIGURES / f"{example.stem}.json").write_text(json.dumps(result, indent=1, sort_keys=True)
                                                     + "\n")
        print(f"{example.stem}: {len(result['figures'])} figures, exit {result['exit_code']}")
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=["capture", "compare", "list"])
    parser.add_argument("--cli", default=str(ROOT / "build" / "src" / "attiguard"))
    parser.add_argument("--example", action="append", default=[])
    args = parser.parse_args()
    if args.mode == "list":
        print("\n".join(e.stem for e in examples()))
        return 0
    if args.mode == "capture":
        return capture(args.cli, args.example)
    status = 0
    for name in args.example or [e.stem for e in examples()]:
        status |= compare(args.cli, name)
    return status


if __name__ == "__main__":
    sys.exit(main())
