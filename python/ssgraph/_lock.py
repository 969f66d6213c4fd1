"""One lock for the whole library. Every call that loads, runs or changes a graph, or runs
a node, holds it; cffi releases the GIL during each C call, so other Python threads (a
plot, a UI, a second sweep preparing its arrays) go on while a run computes. The library
is not documented as safe for two runs at once (a graph is not thread-safe, and every run
already spreads its rows over all cores through OpenMP), so runs from several threads take
turns: correct results, no speed-up (docs/python.md, "Threads")."""
import contextlib
import threading

_LOCK = threading.RLock()


@contextlib.contextmanager
def locked():
    with _LOCK:
        yield
