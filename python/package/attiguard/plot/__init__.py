"""attiguard.plot: PNG plots of the results of ``attiguard run``.

Usage (the ``attiguard run ... --plot`` option runs exactly this)::

    /usr/bin/python3 -m attiguard.plot KIND DIR

reads DIR/trajectory.csv and DIR/summary.json written by ``attiguard run`` for a scenario of kind
KIND and writes PNG files into DIR, printing the path of each on stdout, one per line.

The subpackage needs numpy and matplotlib but not the compiled extension attiguard._core: the
CLI runs it from the source tree with ``PYTHONPATH=python/package`` (docs/conventions.md).

Use Debian's interpreter ``/usr/bin/python3``: it is the one that sees ``python3-matplotlib``
and ``python3-numpy`` (a pyenv ``python3`` on PATH usually does not).

Exit status:
    0   plots written;
    2   usage error, unknown scenario kind, or missing/unreadable result files;
    69  numpy or matplotlib is not installed for this interpreter
        (EX_UNAVAILABLE; the one line on stderr says which and how to install it);
    1   unexpected error (Python traceback).
Every failure prints one line on stderr starting with ``attiguard.plot: ``.

To add plots for a new scenario kind, write a module ``KIND.py`` with a function
``plot(run: common.Run) -> list[pathlib.Path]`` and add it to :func:`plotters`.
"""

from __future__ import annotations

EXIT_OK = 0
EXIT_USAGE = 2
EXIT_DEPENDENCY_MISSING = 69


class PlotInputError(Exception):
    """The arguments or the result files cannot be plotted (exit status 2)."""


def plotters():
    """The registry: scenario kind -> function(run) -> list of written paths.

    Imported lazily so that ``import attiguard.plot`` works without matplotlib.
    """
    from . import campaign, mission, pet_erg, plan, reach, rigid_body, tune, waypoint

    return {
        "rigid_body": rigid_body.plot,
        "pet_erg": pet_erg.plot,
        "reach": reach.plot,
        "waypoint": waypoint.plot,
        "campaign": campaign.plot,
        "mission": mission.plot,
        "tune": tune.plot,
        "plan": plan.plot,
    }
