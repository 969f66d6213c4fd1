"""Builds the package's one compiled module, ssgraph._ssgraph, with cffi from build_ffi.py
(pyproject.toml has the rest). Everything else is plain Python."""
from setuptools import setup

setup(cffi_modules=["build_ffi.py:ffibuilder"])
