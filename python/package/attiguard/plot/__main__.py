"""Command line: ``python3 -m attiguard.plot KIND DIR`` (exit statuses: see __init__.py)."""

from __future__ import annotations

import argparse
import importlib
import sys
from pathlib import Path

from . import EXIT_DEPENDENCY_MISSING, EXIT_OK, EXIT_USAGE, PlotInputError

# Debian package that provides each third-party module.
_DEBIAN_PACKAGES = {"numpy": "python3-numpy", "matplotlib": "python3-matplotlib"}


def _error(message: str) -> None:
    print(f"attiguard.plot: {message}", file=sys.stderr)


def _missing_dependencies() -> list[str]:
    """Those of numpy and matplotlib that cannot be imported."""
    missing = []
    for module in _DEBIAN_PACKAGES:
        try:
            importlib.import_module(module)
        except ImportError:
            missing.append(module)
    return missing


def _missing_message(missing: list[str]) -> str:
    names = " and ".join(missing)
    verb = "is" if len(missing) == 1 else "are"
    install = "apt-get install " + " ".join(_DEBIAN_PACKAGES[m] for m in missing)
    if sys.executable.startswith("/usr/bin/"):
        return f"{names} {verb} not installed for {sys.executable} ({install})"
    return (f"{names} {verb} not installed for {sys.executable}, which is not Debian's "
            f"/usr/bin/python3 (use /usr/bin/python3 after: {install})")


def _compare(argv: list[str]) -> int:
    """``python3 -m attiguard.plot compare DIR DIR ... --figure NAME --out PNG``: overlaid
    histograms of one runs.csv figure of several campaigns (campaign.compare)."""
    parser = argparse.ArgumentParser(
        prog="python3 -m attiguard.plot compare",
        description="Overlaid histograms of one figure of several `attiguard campaign` directories.",
    )
    parser.add_argument("dirs", type=Path, nargs="+", help="campaign output directories")
    parser.add_argument("--figure", default="min_pointing_margin", help="a column of runs.csv")
    parser.add_argument("--out", type=Path, required=True, help="the PNG to write")
    args = parser.parse_args(argv)
    missing = _missing_dependencies()
    if missing:
        _error(_missing_message(missing))
        return EXIT_DEPENDENCY_MISSING
    from .campaign import compare, load

    try:
        print(compare([load(d) for d in args.dirs], args.figure, args.out))
    except PlotInputError as e:
        _error(f"error: {e}")
        return EXIT_USAGE
    return EXIT_OK


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv and argv[0] == "compare":
        return _compare(argv[1:])
    parser = argparse.ArgumentParser(
        prog="python3 -m attiguard.plot",
        description="Write PNG plots of an `attiguard run` output directory.",
    )
    parser.add_argument("kind", help="scenario kind, e.g. rigid_body")
    parser.add_argument("dir", type=Path, help="output directory of `attiguard run`")
    args = parser.parse_args(argv)

    missing = _missing_dependencies()
    if missing:
        _error(_missing_message(missing))
        return EXIT_DEPENDENCY_MISSING

    from . import plotters

    registry = plotters()
    plot = registry.get(args.kind)
    if plot is None:
        known = ", ".join(sorted(registry))
        _error(f"error: no plots for scenario kind '{args.kind}' (known kinds: {known})")
        return EXIT_USAGE

    from .common import load_run

    try:
        load = getattr(plot, "load", load_run)  # campaign: runs.csv, not trajectory.csv
        written = plot(load(args.dir))
    except PlotInputError as e:
        _error(f"error: {e}")
        return EXIT_USAGE
    for path in written:
        print(path)
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
