#!/usr/bin/env python3
"""Fails when a comment or a document names a repository path that does not exist.

Usage: check_repo_paths.py <repository root>     exit 0 when every named path exists, 1 (with
                                                 one line per bad reference) otherwise
       check_repo_paths.py --self-test           checks the checker on a scratch tree

Scanned: the text files (except this one) under src/, tests/, python/, bench/, docs/, examples/, scripts/, cmake/,
fuzz/, .ci/ and README.md, CMakeLists.txt. A reference is a token starting with one of those
top-level directories and a slash (e.g. `docs/<name>.md`), not preceded by a path character (so
`build/python/...`, `${DIR}/tests/...` and URLs are not references). Not checked, by design:
placeholders (a component like NAME or N, or `<...>`, `*`, `$` in the token) and names that say
they do not exist (`does_not_exist`, `nonexistent`, `no_such`). Brace lists expand:
`src/a/b.{hpp,cpp}` names two files. Trailing punctuation is not part of a path.
"""
import os
import re
import sys
import tempfile

PREFIXES = ("src", "tests", "python", "bench", "docs", "examples", "scripts", "cmake", "fuzz")
SCAN = PREFIXES + (".ci", "README.md", "CMakeLists.txt")
TEXT_SUFFIXES = (".cpp", ".hpp", ".h", ".in", ".py", ".pyi", ".md", ".toml", ".txt", ".cmake",
                 ".sh", ".json", ".cfg", ".ini", ".yml", ".yaml", ".html", ".js")
TEXT_NAMES = ("CMakeLists.txt", "run", "README.md")
SKIP_DIRS = {".git", "__pycache__", "node_modules", ".venv", ".mypy_cache", ".pytest_cache"}
SELF = "tests/docs/check_repo_paths.py"  # its examples are made up: not scanned

REFERENCE = re.compile(
    r"(?<![A-Za-z0-9_.~$/\\}){-])"           # not the tail of a longer path or a variable
    r"((?:%s)/(?:[A-Za-z0-9_.\-/]|\{[A-Za-z0-9_.,\-]*\})*)" % "|".join(PREFIXES))
PLACEHOLDER_NEXT = set("<*$?{[")
INTENDED_ABSENT = ("does_not_exist", "nonexistent", "no_such")


def scanned_files(root):
    """The text files to scan, as paths relative to root."""
    for top in SCAN:
        path = os.path.join(root, top)
        if os.path.isfile(path):
            yield top
            continue
        for dirpath, dirnames, filenames in os.walk(path):
            dirnames[:] = [d for d in dirnames if d not in SKIP_DIRS and not d.startswith("build")]
            for name in filenames:
                if name.endswith(TEXT_SUFFIXES) or name in TEXT_NAMES:
                    yield os.path.relpath(os.path.join(dirpath, name), root)


def expand_braces(token):
    """`a.{hpp,cpp}` -> [`a.hpp`, `a.cpp`] (recursively, every brace list)."""
    m = re.search(r"\{([^{}]*)\}", token)
    if not m:
        return [token]
    out = []
    for alt in m.group(1).split(","):
        out.extend(expand_braces(token[:m.start()] + alt + token[m.end():]))
    return out


def is_placeholder(path):
    """A component such as NAME, N or NAME.toml stands for any name."""
    for part in path.split("/"):
        stem = part.split(".")[0]
        if stem and re.fullmatch(r"[A-Z][A-Z0-9_]*", stem):
            return True
    return any(word in path for word in INTENDED_ABSENT)


def references(text):
    """(line number, path) of every checked repository path in text."""
    for m in REFERENCE.finditer(text):
        token = m.group(1)
        after = text[m.end():m.end() + 1]
        if after in PLACEHOLDER_NEXT or "..." in token:
            continue
        line = text.count("\n", 0, m.start()) + 1
        for path in expand_braces(token):
            path = path.rstrip(".,:;")
            if path.endswith("/"):
                path = path.rstrip("/")
            if path.count("/") == 0 or is_placeholder(path):
                continue
            yield line, path


def bad_references(root):
    """(file, line, path) of every named path that does not exist under root."""
    bad = []
    count = 0
    for rel in sorted(f for f in scanned_files(root) if f != SELF):
        try:
            with open(os.path.join(root, rel), encoding="utf-8") as f:
                text = f.read()
        except UnicodeDecodeError:
            continue
        for line, path in references(text):
            count += 1
            if not os.path.exists(os.path.join(root, path)):
                bad.append((rel, line, path))
    return bad, count


def self_test():
    """The checker finds a missing file, a missing brace alternative, and nothing else."""
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "src", "lie"))
        os.makedirs(os.path.join(root, "docs"))
        for name in ("src/lie/so3.hpp", "src/lie/so3.cpp", "docs/a.md"):
            open(os.path.join(root, name), "w").close()
        with open(os.path.join(root, "README.md"), "w") as f:
            f.write("See docs/a.md, src/lie/so3.{hpp,cpp} and src/lie/ and docs/gone.md.\n"
                    "Placeholders: docs/NAME.md, docs/<name>.md, src/*/x.cpp, docs/...\n"
                    "Not references: build/docs/x.md ${DIR}/docs/y.md https://h/src/z.cpp\n"
                    "Missing alternative: src/lie/so3.{hpp,ipp}; absent: docs/does_not_exist.md\n")
        bad, _ = bad_references(root)
        found = sorted((line, path) for _, line, path in bad)
        expected = [(1, "docs/gone.md"), (4, "src/lie/so3.ipp")]
        if found != expected:
            print(f"check_repo_paths self-test: found {found}, expected {expected}")
            return 1
        print("check_repo_paths self-test: ok")
        return 0


def main(argv):
    if len(argv) == 2 and argv[1] == "--self-test":
        return self_test()
    if len(argv) != 2 or not os.path.isdir(argv[1]):
        print("usage: check_repo_paths.py <repository root> | --self-test", file=sys.stderr)
        return 2
    bad, count = bad_references(argv[1])
    for rel, line, path in bad:
        print(f"{rel}:{line}: names {path}, which does not exist")
    print(f"check_repo_paths: {count} path references checked, {len(bad)} do not exist")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
