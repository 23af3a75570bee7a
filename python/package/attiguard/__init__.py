"""attiguard: geometric spacecraft guidance and control with safety guarantees, from Python.

    import attiguard
    result = attiguard.run("examples/pet_erg_paper.toml")       # or a dict scenario
    result["t"], result["tau_norm"], result.summary["min_pointing_margin"]

See docs/python.md. The C++ core is the extension module attiguard._core, built by CMake into
build/python/attiguard next to these files (scripts/build.sh makes Debian's /usr/bin/python3
find it).
"""

from __future__ import annotations

try:
    from . import _core
except ImportError as _e:  # the Python files are copied at configure time, _core at build time
    raise ImportError(
        f"attiguard: the compiled extension attiguard._core is missing or unloadable next to "
        f"{__file__} (the build of this checkout is unfinished or failed): run "
        f"`bash scripts/build.sh` in that checkout. Cause: {_e}") from _e
from ._api import check, reach, run
from ._core import (Cone, Error, Governor, GovernorOutput, InputError, Mission, NumericalError,
                    QuaternionPid, RigidBody, VerificationFailure, distance, expm, hat,
                    is_rotation, keep_in_cone, keep_out_cone, logm, pd_torque, phi,
                    project_to_so3, quat_conjugate, quat_from_axis_angle, quat_multiply,
                    quat_to_rotation, rotation_to_quat, vee)
from ._results import ReachResult, RunResult
from ._toml import dumps as to_toml

__all__ = [
    "Cone", "Error", "Governor", "GovernorOutput", "InputError", "Mission", "NumericalError",
    "QuaternionPid", "ReachResult", "RigidBody", "RunResult", "VerificationFailure", "check",
    "distance", "expm", "hat", "is_rotation", "keep_in_cone", "keep_out_cone", "logm",
    "pd_torque", "phi", "project_to_so3", "quat_conjugate", "quat_from_axis_angle",
    "quat_multiply", "quat_to_rotation", "reach", "rotation_to_quat", "run", "to_toml", "vee",
]
