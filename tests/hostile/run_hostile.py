#!/usr/bin/env python3
"""The hostile-input suite of the command line (docs/errors.md, "Hostile inputs").

Each case of a cases_*.toml file next to this script is one `attiguard` command run in a fresh
temporary directory, with a 20 s timeout and a 1 GiB address-space limit. A case passes when

- the exit code is one of the case's `exit` (and always one of 0, 2, 3, 4: docs/errors.md; an
  interrupted command ends with 3);
- with exit 2 or 3, stderr holds exactly one line that starts with `attiguard: error: `, and that
  line contains every string of the case's `where` (FILE:LINE:COL, the key or the flag); with
  exit 4 (a verdict: cannot prove, nothing found) at most one; with exit 0 none;
- no file the command wrote (.partial files included) holds a NaN or an infinity: CSV cells,
  JSON and TOML values, the data lines of an AEM, the lines of a .txt;
- no stale file: with `prefill = true` the output folder `out/` starts with the outputs of every
  command (made once per invocation of this script, dated 2000-01-01); afterwards each of them
  is rewritten or removed (.partial files and the names of the case's `keep` excepted).

Case keys: name, fault, cmd (attiguard's arguments), exit (list), where (list), files (name →
text written into the case's directory), copy (name → repository path copied in), prefill,
keep (names under out/ that the command reads and may leave as they were), signal =
{ after_s = S, sig = "TERM" } (the signal is sent once a .partial file appears under out/, or
after S seconds, whichever comes first), env (name → value), exe (a repository path run instead
of attiguard: the self-test's stand-in that misbehaves on purpose), timeout_s (a shorter
timeout than the suite's 20 s), needs_memory_limit (the case is about the 1 GiB limit, e.g. threads
the system refuses: skipped under --sanitized, which runs without it).

Usage: run_hostile.py [--attiguard PATH] [--keep-dirs] [--sanitized] [--expect-failures] CASES.toml ...
Exits 0 when every case passes, 1 otherwise, printing one line per case. --sanitized (a build
with ASan, which reserves terabytes of shadow memory): no address-space limit and three times
the timeout. --expect-failures (the runner's self-test, selftest_cases.toml): exits 0 only when
every case fails.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
TIMEOUT_S = 20.0
ADDRESS_SPACE = 1 << 30
ALLOWED_EXITS = {0, 2, 3, 4}
PREFILL_TIMEOUT_S = 900.0  # each command of the prefill (a sanitized reach takes a minute)
PREFILL_TIME = 946684800  # 2000-01-01T00:00:00Z: the date of every prefilled file
CHECKED_SUFFIXES = {".csv", ".json", ".toml", ".aem", ".txt"}
NONFINITE_TOKEN = re.compile(r"(?<![A-Za-z_])[-+]?(nan|inf|infinity)(?![A-Za-z_])", re.IGNORECASE)


SANITIZED = False
# The sanitized build's work divisor of the long tests (kSanitizedWorkDivisor of
# tests/sanitizer_build.hpp): its prefill's reach takes 1/16 of the example's soundness samples.
SANITIZED_WORK_DIVISOR = 16


def limit_resources() -> None:
    """In the child: the 1 GiB address-space limit of every case (none under ASan)."""
    if not SANITIZED:
        resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_SPACE, ADDRESS_SPACE))


def any_partial(folder: Path) -> bool:
    """Whether FOLDER holds a .partial file; the command may be removing files meanwhile."""
    try:
        return folder.is_dir() and any(p.name.endswith(".partial") for p in folder.rglob("*"))
    except OSError:  # a folder removed while it was listed
        return False


def run_attiguard(exe: Path, args: list[str], cwd: Path, env: dict[str, str] | None = None,
                  sig: dict | None = None,
                  timeout_s: float | None = None) -> tuple[int | None, str, str, float]:
    """Runs attiguard ARGS in CWD; returns (exit code or None on timeout, stdout, stderr, seconds)."""
    timeout_s = TIMEOUT_S if timeout_s is None else timeout_s
    full_env = dict(os.environ)
    full_env.update(env or {})
    start = time.monotonic()
    proc = subprocess.Popen([str(exe), *args], cwd=cwd, env=full_env, stdin=subprocess.DEVNULL,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            errors="replace", preexec_fn=limit_resources)
    if sig is not None:
        deadline = start + float(sig.get("after_s", 1.0))
        out_dir = cwd / "out"
        while proc.poll() is None and time.monotonic() < deadline:
            if any_partial(out_dir):
                break
            time.sleep(0.01)
        if proc.poll() is None:
            proc.send_signal(getattr(signal, "SIG" + sig.get("sig", "TERM")))
    try:
        out, err = proc.communicate(timeout=max(0.0, timeout_s - (time.monotonic() - start)))
    except subprocess.TimeoutExpired:
        proc.kill()
        out, err = proc.communicate()
        return None, out, err, time.monotonic() - start
    return proc.returncode, out, err, time.monotonic() - start


def make_prefill(exe: Path, work: Path) -> Path:
    """A folder holding the outputs of every command (one run of each into its own folder, then
    the union), every file dated PREFILL_TIME. Raises RuntimeError when a command fails."""
    ex = REPO / "examples"
    reach_example = ex / "conreach_paper.toml"
    if SANITIZED:  # the same files from 1/SANITIZED_WORK_DIVISOR of its soundness samples
        reach_example = work / "conreach_paper.toml"
        text = (ex / "conreach_paper.toml").read_text()
        found = re.search(r"\nsamples = (\d+)\n", text)
        if found is None:
            raise RuntimeError("prefill: examples/conreach_paper.toml has no [soundness] samples")
        fewer = max(100, int(found.group(1)) // SANITIZED_WORK_DIVISOR)
        reach_example.write_text(text[:found.start(1)] + str(fewer) + text[found.end(1):])
    commands = [
        ("pet", ["run", str(ex / "pet_erg_paper.toml"), "--out", "pet", "--plot"]),
        ("pet", ["view", "pet"]),
        ("pet", ["export-aem", "pet"]),
        ("way", ["run", str(ex / "waypoint_paper.toml"), "--out", "way"]),
        ("reach", ["reach", str(reach_example), "--out", "reach"]),
        ("camp", ["campaign", str(ex / "pet_erg_campaign.toml"), "--runs", "2", "--out", "camp",
                  "--plot"]),
        ("camp", ["campaign", str(ex / "pet_erg_campaign.toml"), "--runs", "2", "--out", "camp",
                  "--replay", "1", "--view", "--aem"]),
        ("tune", ["tune", str(ex / "pet_erg_paper.toml"), "--budget", "4", "--out", "tune"]),
    ]
    for _, args in commands:  # set-up, not a case: the suite's timeout does not apply
        code, _, err, _ = run_attiguard(exe, args, work, timeout_s=PREFILL_TIMEOUT_S)
        if code not in (0, 4):
            raise RuntimeError(f"prefill: attiguard {' '.join(args)} exited {code}: {err.strip()}")
    union = work / "prefill"
    union.mkdir()
    plots: list[str] = []
    for folder in dict.fromkeys(name for name, _ in commands):
        shutil.copytree(work / folder, union, dirs_exist_ok=True)
        listed = work / folder / "plots.txt"
        if listed.is_file():
            plots += listed.read_text().splitlines()
    if plots:  # one plots.txt listing every folder's figures, as successive runs would leave
        (union / "plots.txt").write_text("\n".join(dict.fromkeys(plots)) + "\n")
    for p in union.rglob("*"):
        os.utime(p, (PREFILL_TIME, PREFILL_TIME))
    return union


def nonfinite_in(path: Path) -> str | None:
    """A description of the first NaN or infinity in PATH, or None."""
    text = path.read_text(errors="replace")
    suffix = path.suffix if path.suffix != ".partial" else Path(path.stem).suffix
    if suffix == ".json":
        def bad(token: str) -> float:
            raise ValueError(token)
        try:
            json.loads(text, parse_constant=bad)
        except ValueError as e:
            if text.strip() and not isinstance(e, json.JSONDecodeError):
                return f"JSON constant {e}"
        return None
    if suffix == ".toml":
        try:
            doc = tomllib.loads(text)
        except tomllib.TOMLDecodeError:
            doc = None
        if doc is not None:
            stack = [doc]
            while stack:
                v = stack.pop()
                if isinstance(v, dict):
                    stack.extend(v.values())
                elif isinstance(v, list):
                    stack.extend(v)
                elif isinstance(v, float) and not math.isfinite(v):
                    return f"TOML value {v}"
            return None
    if suffix == ".csv":
        for row in csv.reader(text.splitlines()):
            for cell in row:
                if NONFINITE_TOKEN.fullmatch(cell.strip()):
                    return f"CSV cell {cell!r}"
        return None
    for line in text.splitlines():
        if line.startswith("COMMENT"):
            continue
        m = NONFINITE_TOKEN.search(line)
        if m:
            return f"token {m.group(0)!r} in line {line[:80]!r}"
    return None


def check_case(case: dict, exe: Path, prefill: Path | None, base: Path) -> list[str]:
    """Runs one case; returns its failures (empty when it passes)."""
    problems: list[str] = []
    if SANITIZED and case.get("needs_memory_limit"):
        case["_skipped"] = True
        return []
    cwd = Path(tempfile.mkdtemp(prefix=case["name"] + "-", dir=base))
    for name, text in case.get("files", {}).items():
        (cwd / name).parent.mkdir(parents=True, exist_ok=True)
        (cwd / name).write_text(text)
    for name, rel in case.get("copy", {}).items():
        (cwd / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(REPO / rel, cwd / name)
    inputs = {p for p in cwd.rglob("*")}
    if case.get("prefill"):
        shutil.copytree(prefill, cwd / "out")
        for p in (cwd / "out").rglob("*"):
            os.utime(p, (PREFILL_TIME, PREFILL_TIME))
    case_exe = REPO / case["exe"] if "exe" in case else exe
    timeout = min(TIMEOUT_S, float(case.get("timeout_s", TIMEOUT_S)))
    code, _, err, seconds = run_attiguard(case_exe, [str(a) for a in case["cmd"]], cwd,
                                          case.get("env"), case.get("signal"), timeout)
    if code is None:
        return [f"no end within {timeout:g} s"]
    if code not in ALLOWED_EXITS:
        problems.append(f"exit code {code} is not 0, 2, 3 or 4")
    if code not in case["exit"]:
        problems.append(f"exit code {code}, expected {case['exit']}")
    error_lines = [l for l in err.splitlines() if l.startswith("attiguard: error: ")]
    if code in (2, 3):
        if len(error_lines) != 1:
            problems.append(f"{len(error_lines)} error lines on stderr: {err.strip()[:300]!r}")
        for w in case.get("where", []):
            if error_lines and w not in error_lines[0]:
                problems.append(f"error line lacks {w!r}: {error_lines[0]!r}")
    elif code == 4:
        if len(error_lines) > 1:
            problems.append(f"{len(error_lines)} error lines on stderr: {err.strip()[:300]!r}")
    elif error_lines:
        problems.append(f"exit {code} with an error line: {error_lines[0]!r}")
    if any(l.startswith("internal error") or "internal error" in l for l in error_lines):
        problems.append("internal error")
    keep = set(case.get("keep", []))
    for p in sorted(cwd.rglob("*")):
        if not p.is_file() or p in inputs:
            continue
        rel = p.relative_to(cwd)
        stale = p.stat().st_mtime == PREFILL_TIME
        if stale and not p.name.endswith(".partial") and str(rel.relative_to("out")) not in keep:
            problems.append(f"stale file {rel}")
        if not stale and p.suffix in CHECKED_SUFFIXES | {".partial"}:
            found = nonfinite_in(p)
            if found:
                problems.append(f"{rel}: {found}")
    case["_seconds"] = seconds
    return problems


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--attiguard", type=Path, default=REPO / "build/src/attiguard")
    parser.add_argument("--keep-dirs", action="store_true", help="keep the case directories")
    parser.add_argument("--sanitized", action="store_true",
                        help="an ASan build: no address-space limit, 3x the timeout")
    parser.add_argument("--expect-failures", action="store_true",
                        help="self-test: pass only when every case fails")
    parser.add_argument("cases", type=Path, nargs="+")
    args = parser.parse_args()
    global SANITIZED, TIMEOUT_S
    if args.sanitized:
        SANITIZED, TIMEOUT_S = True, 3 * TIMEOUT_S
    exe = args.attiguard.resolve()
    cases: list[dict] = []
    for f in args.cases:
        with open(f, "rb") as fh:
            doc = tomllib.load(fh)
        for c in doc.get("case", []):
            for key in ("name", "cmd", "exit"):
                if key not in c:
                    print(f"{f}: a case without `{key}`: {c.get('name', '?')}")
                    return 1
            cases.append(c)
    names = [c["name"] for c in cases]
    if len(set(names)) != len(names):
        print("duplicate case names: " + ", ".join(sorted({n for n in names if names.count(n) > 1})))
        return 1
    base = Path(tempfile.mkdtemp(prefix="hostile-"))
    failed = 0
    try:
        prefill = make_prefill(exe, base) if any(c.get("prefill") for c in cases) else None
        for c in cases:
            problems = check_case(c, exe, prefill, base)
            status = "skip" if c.get("_skipped") else "ok  " if not problems else "FAIL"
            failed += bool(problems)
            print(f"{status} {c['name']} ({c.get('_seconds', 0.0):.2f} s)"
                  + "".join(f"\n       {p}" for p in problems))
    finally:
        if not args.keep_dirs:
            shutil.rmtree(base, ignore_errors=True)
        else:
            print(f"case directories kept in {base}")
    skipped = sum(1 for c in cases if c.get("_skipped"))
    print(f"{len(cases) - failed - skipped} of {len(cases)} cases pass"
          + (f" ({skipped} skipped: they need the 1 GiB limit)" if skipped else ""))
    if args.expect_failures:
        return 0 if failed == len(cases) and cases else 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
