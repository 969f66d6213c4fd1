"""Builds the package's one compiled module, ssgraph._ssgraph, with cffi from build_ffi.py
(pyproject.toml has the rest). Everything else is plain Python."""
import importlib.util
import sys

# `pip install --no-build-isolation` builds with the interpreter's own setuptools, wheel and
# cffi (docs/python.md: Debian's, nothing downloaded). A Python without them (a pyenv or
# conda build first on PATH) failed with "invalid command 'bdist_wheel'" and no hint (issue
# 46): name what is missing and the two ways out.
MISSING = [m for m in ("wheel", "cffi") if importlib.util.find_spec(m) is None]
if MISSING:
    sys.exit("ssgraph: building the Python package needs %s, which %s (%s) lacks. Use "
             "Debian's Python: /usr/bin/python3 -m venv --system-site-packages .venv, after "
             "bash tools/install-deps.sh --test (python3-wheel, python3-cffi); or install them "
             "into this Python (pip install %s) and drop --no-build-isolation"
             % (" and ".join(MISSING), sys.executable, sys.version.split()[0],
                " ".join(MISSING)))

from setuptools import setup  # noqa: E402

setup(cffi_modules=["build_ffi.py:ffibuilder"])
