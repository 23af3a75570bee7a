#!/usr/bin/env python3
"""Fails when a function in src/ is longer than the limit of docs/architecture.md ("Functions").

Usage: check_function_length.py <repository root> [--limit N]   exit 0 when no function
                                       definition under src/ spans more than N lines (default
                                       80, signature to closing brace), 1 listing the offenders
       check_function_length.py --self-test                     checks the checker

The definitions and their extents come from universal-ctags (`ctags --kinds-c++=f
--fields=+ne`), which scripts/setup.sh installs for the tests; a lambda counts towards the
function it is written in. Exit 2 when ctags is missing or is not universal-ctags.
"""
import os
import shutil
import subprocess
import sys
import tempfile

LIMIT = 80


def function_extents(root):
    """(length, file, line, name) of every C++ function definition under root/src."""
    ctags = shutil.which("ctags")
    if ctags is None:
        raise SystemExit("check_function_length: ctags not found (install universal-ctags)")
    out = subprocess.run([ctags, "--languages=C++", "--kinds-c++=f", "--fields=+ne", "-f", "-",
                          "-R", "src"], cwd=root, capture_output=True, text=True)
    if out.returncode != 0:
        print(out.stderr, file=sys.stderr)
        raise SystemExit("check_function_length: ctags failed (is it universal-ctags?)")
    found = []
    for row in out.stdout.splitlines():
        if row.startswith("!"):
            continue
        cols = row.split("\t")
        fields = dict(c.split(":", 1) for c in cols[3:] if ":" in c)
        if "line" not in fields or "end" not in fields:
            continue
        start, end = int(fields["line"]), int(fields["end"])
        found.append((end - start + 1, cols[1], start, cols[0]))
    return found


def offenders(root, limit):
    return sorted((f for f in function_extents(root) if f[0] > limit), reverse=True)


def self_test():
    """A 90-line function is reported, a 10-line one and a long comment are not."""
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "src"))
        body = "".join(f"  x += {i};\n" for i in range(87))
        with open(os.path.join(root, "src", "a.cpp"), "w") as f:
            f.write("// " + "comment\n// " * 100 + "\n")
            f.write("int long_one(int x) {\n" + body + "  return x;\n}\n")
            f.write("int short_one(int x) {\n  return x + 1;\n}\n")
        bad = offenders(root, LIMIT)
        names = [(n, length) for length, _, _, n in bad]
        if names != [("long_one", 90)]:
            print(f"check_function_length self-test: found {names}, expected [('long_one', 90)]")
            return 1
        print("check_function_length self-test: ok")
        return 0


def main(argv):
    if len(argv) == 2 and argv[1] == "--self-test":
        return self_test()
    limit = LIMIT
    if len(argv) == 4 and argv[2] == "--limit":
        limit = int(argv[3])
    elif len(argv) != 2:
        print("usage: check_function_length.py <repository root> [--limit N] | --self-test",
              file=sys.stderr)
        return 2
    everything = function_extents(argv[1])
    bad = [f for f in everything if f[0] > limit]
    for length, path, line, name in sorted(bad, reverse=True):
        print(f"{path}:{line}: {name} is {length} lines (limit {limit})")
    print(f"check_function_length: {len(everything)} functions, {len(bad)} over {limit} lines")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
