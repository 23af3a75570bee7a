"""attiguard: geometric spacecraft guidance and control with safety guarantees, from Python.

    import attiguard
    result = attiguard.run("examples/pet_erg_paper.toml")       # or a dict scenario
    result["t"], result["tau_norm"], result.summary["min_pointing_margin"]

See docs/python.md. The C++ core is the extension module attiguard._core (typed in _core.pyi);
`pip install .` builds it (docs/python.md, "Installing"), and a CMake build puts it in
build/python/attiguard next to these files.

The public names are loaded on first use (PEP 562): `import attiguard` and the plotting
subpackage `attiguard.plot` (what `attiguard run --plot` runs) work without the compiled
extension, e.g. from the source directory python/package; the first use of a name that needs
_core without it raises an ImportError saying how to build it.
"""

import importlib as _importlib
import typing as _typing

if _typing.TYPE_CHECKING:  # what mypy and IDEs see; at run time __getattr__ below loads these
    from ._api import check, predict, reach, run
    from ._plan import PlannedSlew, plan_slew
    from ._core import (Cone, Error, Governor, GovernorOutput, InputError, Mission,
                        NumericalError, PlannedGovernor, PlannedStep, QuaternionPid, RigidBody, VerificationFailure, distance,
                        expm, hat, is_rotation, keep_in_cone, keep_out_cone, logm, pd_torque,
                        phi, project_to_so3, quat_conjugate, quat_from_axis_angle,
                        quat_multiply, quat_to_rotation, rotation_to_quat, vee)
    from ._results import ReachResult, RunResult
    from ._toml import dumps as to_toml
    from ._version import __version__

# Public name -> (submodule, attribute). One table: __all__, __dir__ and __getattr__ use it.
_CORE_NAMES = (
    "Cone", "Error", "Governor", "GovernorOutput", "InputError", "Mission", "NumericalError",
    "PlannedGovernor", "PlannedStep", "QuaternionPid", "RigidBody", "VerificationFailure", "distance", "expm", "hat",
    "is_rotation", "keep_in_cone", "keep_out_cone", "logm", "pd_torque", "phi",
    "project_to_so3", "quat_conjugate", "quat_from_axis_angle", "quat_multiply",
    "quat_to_rotation", "rotation_to_quat", "vee",
)
_EXPORTS: dict[str, tuple[str, str]] = {
    **{name: ("_core", name) for name in _CORE_NAMES},
    "check": ("_api", "check"),
    "plan_slew": ("_plan", "plan_slew"),
    "PlannedSlew": ("_plan", "PlannedSlew"),
    "predict": ("_api", "predict"),
    "reach": ("_api", "reach"),
    "run": ("_api", "run"),
    "ReachResult": ("_results", "ReachResult"),
    "RunResult": ("_results", "RunResult"),
    "to_toml": ("_toml", "dumps"),
}

__all__ = sorted(_EXPORTS)


def _core_module() -> _typing.Any:
    """attiguard._core, or an ImportError that says what is missing and how to build it."""
    try:
        return _importlib.import_module("._core", __name__)
    except ImportError as e:
        raise ImportError(
            f"attiguard: the compiled extension attiguard._core is missing or unloadable next to "
            f"{__file__} (a source directory, or a build of this checkout that is unfinished or "
            f"failed): `pip install .` (docs/python.md) or run `bash scripts/build.sh` and use "
            f"build/python. Cause: {e}") from e


def _version() -> str:
    """The CMake project version, written by the build into attiguard/_version.py."""
    try:
        return str(_importlib.import_module("._version", __name__).__version__)
    except ImportError:
        # An AttributeError, so that getattr(attiguard, "__version__", None) stays None here.
        raise AttributeError(
            f"attiguard.__version__: {__file__} is a source directory without a build "
            f"(the version is written by CMake into attiguard/_version.py)") from None


def __getattr__(name: str) -> _typing.Any:
    if name == "__version__":
        value: _typing.Any = _version()
    elif name in _EXPORTS:
        module_name, attribute = _EXPORTS[name]
        _core_module()  # the clear message, before _api's own `from . import _core` fails
        value = getattr(_importlib.import_module("." + module_name, __name__), attribute)
    else:
        raise AttributeError(f"module 'attiguard' has no attribute '{name}'")
    globals()[name] = value  # loaded once
    return value


def __dir__() -> list[str]:
    public = {name for name in globals() if not name.startswith("_")}  # e.g. plot, once imported
    return sorted(public | set(__all__) | {"__version__"})
