"""Makes the packages importable when pytest runs from anywhere.

python/ holds attiguard_plot. The `attiguard` package (bindings) is built by CMake into
BUILD/python/attiguard; BUILD is $ATTIGUARD_BUILD_DIR when set, else build/ at the repository
root (scripts/build.sh).
"""

import os
import sys
from pathlib import Path

PYTHON_DIR = Path(__file__).resolve().parent.parent
REPO_DIR = PYTHON_DIR.parent
BUILD_DIR = Path(os.environ.get("ATTIGUARD_BUILD_DIR", REPO_DIR / "build")).resolve()

for entry in (BUILD_DIR / "python", PYTHON_DIR):
    if str(entry) not in sys.path:
        sys.path.insert(0, str(entry))
# The build directory's package wins over any other attiguard on sys.path (e.g. a .pth file).
sys.path.remove(str(BUILD_DIR / "python"))
sys.path.insert(0, str(BUILD_DIR / "python"))
