"""The package's version: the C library's SSG_VERSION (tests/test_python.sh checks both)."""
__version__ = "0.1.0"
