#!/usr/bin/env python3
"""Fails when the Python plots or the browser viewer read a CSV column the program does not write.

Usage: check_output_columns.py --cli PATH/attiguard   exit 0 when every column name the readers
                                                      name is written by the program, 1 (one
                                                      line per unknown name) otherwise
       check_output_columns.py --self-test            checks the reference scanner

The column names of trajectory.csv, runs.csv and the reach CSVs are defined once, by the C++
writers (src/attiguard/sim/*_run.cpp, app/reach_run.cpp, campaign/runs_file.cpp): this test
takes them from the files the program writes for every example of examples/ (`attiguard run`,
`attiguard reach` for two of the reach examples, and a 3-run `attiguard campaign` for the campaign examples), so it checks the
readers against the one definition rather than against a second list (docs/conventions.md,
"Outputs"). The readers scanned are python/package/attiguard/**/*.py and viewer/src/*.js; a
reference is a string literal argument of column(…), columns_of(…), col(…), has(…), a literal
tested with `in run.columns` or indexed as columns["…"], and an f-string such as f"tau_{c}",
whose fixed prefix must begin some column. Names built at run time from other variables (e.g.
the viewer's `${prefix}_w`) are not checked here; the viewer's browser test loads real outputs.
"""
import argparse
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
READERS = [("python/package/attiguard", "*.py"), ("viewer/src", "*.js")]
CAMPAIGN_RUNS = "3"
# Of the reach examples (seconds each) two suffice: the reach CSVs have the same columns in all.
REACH_EXAMPLES = ("conreach_paper", "conreach_hold_partitioned")

CALL = re.compile(r"\b(?:column|columns_of|col|has)\(([^()]*)\)")
LITERAL = re.compile(r"""(f?)(["'])([A-Za-z0-9_{}]+)\2""")
MEMBERSHIP = re.compile(r"""(f?)(["'])([A-Za-z0-9_{}]+)\2\s+(?:not\s+)?in\s+\w+\.columns\b""")
INDEX = re.compile(r"""\bcolumns\[(f?)(["'])([A-Za-z0-9_{}]+)\2\]""")


def references(text):
    """(line, name, is_prefix) of every column named in a reader's source text."""
    found = []
    for lineno, line in enumerate(text.splitlines(), 1):
        literals = []
        for m in CALL.finditer(line):
            literals += LITERAL.findall(m.group(1))
        literals += MEMBERSHIP.findall(line) + INDEX.findall(line)
        for f, _, name in literals:
            if f and "{" in name:
                prefix = name.split("{", 1)[0]
                if prefix:
                    found.append((lineno, prefix, True))
            elif "{" not in name:
                found.append((lineno, name, False))
    return found


def written_columns(cli):
    """Every column of every CSV the program writes for the examples."""
    columns = set()
    with tempfile.TemporaryDirectory() as scratch:
        for k, example in enumerate(sorted((ROOT / "examples").glob("*.toml"))):
            text = example.read_text()
            out = pathlib.Path(scratch) / f"{k}"
            if re.search(r'^kind\s*=\s*"reach"', text, re.M):
                if example.stem not in REACH_EXAMPLES:
                    continue
                cmd = [cli, "reach", str(example), "--out", str(out)]
            elif re.search(r"^\[dispersions\]", text, re.M):
                cmd = [cli, "campaign", str(example), "--runs", CAMPAIGN_RUNS, "--out", str(out)]
            else:
                cmd = [cli, "run", str(example), "--out", str(out)]
            r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
            if r.returncode not in (0, 4):
                raise SystemExit(f"check_output_columns: {' '.join(cmd)} exited {r.returncode}: "
                                 f"{r.stderr.strip()}")
            for csv in out.rglob("*.csv"):
                with open(csv, encoding="utf-8") as f:
                    header = f.readline()
                    while header.startswith("#"):
                        header = f.readline()
                columns.update(c.strip() for c in header.strip().split(","))
    return columns


def unknown_references(columns):
    bad, count = [], 0
    for top, pattern in READERS:
        for path in sorted((ROOT / top).rglob(pattern)):
            for line, name, is_prefix in references(path.read_text(encoding="utf-8")):
                count += 1
                ok = any(c.startswith(name) for c in columns) if is_prefix else name in columns
                if not ok:
                    kind = "no column starts with" if is_prefix else "no CSV has the column"
                    bad.append(f"{path.relative_to(ROOT)}:{line}: {kind} {name!r}")
    return bad, count


def self_test():
    text = ('a = run.column("t")\nb = run.columns_of("q_w", "q_x")\n'
            'c = run.column(f"tau_{c}")\nif "gamma_g" in run.columns: pass\n'
            "d = s.col('r_x'); e = s.has('tau_norm')\nf = run.columns[\"violation\"]\n"
            "g = run.column(name)\n")
    found = [(n, p) for _, n, p in references(text)]
    expected = [("t", False), ("q_w", False), ("q_x", False), ("tau_", True),
                ("gamma_g", False), ("r_x", False), ("tau_norm", False), ("violation", False)]
    if found != expected:
        print(f"check_output_columns self-test: found {found}, expected {expected}")
        return 1
    print("check_output_columns self-test: ok")
    return 0


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cli")
    ap.add_argument("--self-test", action="store_true")
    a = ap.parse_args(argv[1:])
    if a.self_test:
        return self_test()
    if not a.cli:
        ap.error("--cli PATH is required")
    columns = written_columns(a.cli)
    bad, count = unknown_references(columns)
    for line in bad:
        print(line)
    print(f"check_output_columns: {len(columns)} columns written, {count} references read, "
          f"{len(bad)} unknown")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
