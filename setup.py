"""setuptools glue of pyproject.toml: builds the extension module attiguard._core with the
project's CMake build (docs/python.md, "Installing").

The wheel's version is CMakeLists.txt's project(VERSION), the one source of truth (CMake writes
the same number into attiguard/_version.py). build_ext configures CMake in build-pip/ at the
repository root (or $ATTIGUARD_PIP_BUILD_DIR) with the interpreter running this build, tests and
benchmarks off and ccache when it is installed, builds only the target attiguard_python and
copies _core and _version.py into the wheel. build-pip/ sits at the depth of build/, so that with
ccache's base_dir the compile commands of the two builds are the same and the objects of
scripts/build.sh's build are reused. setuptools' own files go to build-pip/setuptools/.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def cmake_project_version() -> str:
    """VERSION of project(attiguard ...) in CMakeLists.txt."""
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(\s*attiguard\s+VERSION\s+([0-9][0-9.]*)", text)
    if match is None:
        raise RuntimeError("setup.py: no `project(attiguard VERSION x.y.z` in CMakeLists.txt")
    return match.group(1)


def _setuptools_dir() -> str:
    """build-pip/setuptools (created): setuptools' build and egg-info, out of the source tree."""
    path = ROOT / "build-pip" / "setuptools"
    path.mkdir(parents=True, exist_ok=True)
    return os.path.relpath(path)


class CMakeExtension(Extension):
    """An extension built by the CMake target `target`, not by setuptools' compiler."""

    def __init__(self, name: str, target: str) -> None:
        super().__init__(name, sources=[])
        self.target = target


class CMakeBuild(build_ext):
    """build_ext that runs the CMake build of the repository for each CMakeExtension."""

    def build_extension(self, ext: Extension) -> None:
        if not isinstance(ext, CMakeExtension):
            super().build_extension(ext)
            return
        build_dir = Path(os.environ.get("ATTIGUARD_PIP_BUILD_DIR", ROOT / "build-pip")).resolve()
        self._configure(build_dir)
        if not (build_dir / "python" / "attiguard").is_dir():
            raise RuntimeError(
                "setup.py: CMake did not configure the Python package (see its message above: "
                "pybind11-dev or python3-dev missing, or ATTIGUARD_BUILD_PYTHON/SANITIZE set)")
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        self._run(["cmake", "--build", str(build_dir), "--target", ext.target,
                   "--parallel", jobs])

        package_dir = build_dir / "python" / "attiguard"
        built = sorted(package_dir.glob("_core.*.so")) or sorted(package_dir.glob("_core*.so"))
        if not built:
            raise RuntimeError(f"setup.py: the CMake build wrote no _core*.so into {package_dir}")
        destination = Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], destination)
        shutil.copyfile(package_dir / "_version.py", destination.parent / "_version.py")

    def _configure(self, build_dir: Path) -> None:
        args = [
            "cmake", "-S", str(ROOT), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython3_EXECUTABLE={sys.executable}",
            "-DATTIGUARD_BUILD_PYTHON=ON",
            "-DATTIGUARD_BUILD_TESTS=OFF",
            "-DATTIGUARD_BUILD_BENCH=OFF",
        ]
        # The generator of scripts/build.sh (Ninja when installed), so that the compile commands
        # and with them ccache's keys are those of build/ (a new build-pip/ has no cache).
        if shutil.which("ninja") and not (build_dir / "CMakeCache.txt").exists():
            args += ["-G", "Ninja"]
        if shutil.which("ccache"):
            args.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        args += os.environ.get("ATTIGUARD_CMAKE_ARGS", "").split()
        self._run(args)

    @staticmethod
    def _run(command: list[str]) -> None:
        print("setup.py:", " ".join(command), flush=True)
        # ccache's base_dir (unless the caller set one): paths below the repository become
        # relative, so this build's compile commands equal scripts/build.sh's (which sets the same).
        env = dict(os.environ)
        env.setdefault("CCACHE_BASEDIR", str(ROOT))
        subprocess.run(command, check=True, env=env)


setup(
    version=cmake_project_version(),
    package_dir={"": "python/package"},
    packages=["attiguard", "attiguard.plot"],
    package_data={"attiguard": ["py.typed", "_core.pyi"]},
    include_package_data=False,
    ext_modules=[CMakeExtension("attiguard._core", target="attiguard_python")],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build-pip/setuptools"},
             "egg_info": {"egg_base": _setuptools_dir()}},
)
