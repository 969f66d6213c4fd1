"""The bindings' checks of what Python hands the library: every limit the CLI enforces on
the same setting (cli/options.c), and what C cannot see at all (a NUL ends a C string, so
"a.graph\\0junk" would reach the library as "a.graph"). A bad value raises
ValueRangeError (also a ValueError) naming the argument; a value of the wrong kind,
TypeError. Nothing here changes a value: it passes as given or it is refused."""
import numbers
import os
import re
from typing import Tuple

from ._errors import Diagnostic, ValueRangeError
from ._ssgraph import lib

SIZE_MAX = 16384              # --size WxH: each side 1..16384 (cli/options.c, take_size)
FRAMES_MAX = 1000000          # --frames 1..1000000
THREADS_MAX = 1024            # --threads 1..1024 (0 here: all cores, the library's default)
SEED_MAX = 2147483647         # --seed 0..2147483647
GUARD_MAX = lib.SSG_GUARD_MAX  # --guard 0..SSG_GUARD_MAX (core/ssgraph.h)
INT_MAX = 2147483647          # a C int (frame indices)


def refuse(code: str, message: str) -> ValueRangeError:
    return ValueRangeError(code, [Diagnostic(code, "", 0, 0, message)])


def integer(value, name: str, lo: int, hi: int) -> int:
    """An int (or numpy integer) lo..hi: a float, a bool or a string is refused rather than
    rounded (1.9 frames is not 1)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError("%s: expected an integer, got %r (%s)"
                        % (name, value, type(value).__name__))
    if not lo <= int(value) <= hi:
        raise refuse("SSG_E_RANGE", "%s: expected an integer %d..%d, got %d"
                     % (name, lo, hi, int(value)))
    return int(value)


def c_text(value, name: str) -> bytes:
    """A str as the C string the library reads (UTF-8), refusing a NUL inside it."""
    if not isinstance(value, str):
        raise TypeError("%s: expected a str, got %r (%s)" % (name, value, type(value).__name__))
    return no_nul(value.encode("utf-8", "surrogateescape"), name, value)


def c_path(value, name: str) -> bytes:
    """A path (str, bytes or os.PathLike) as the C string the library opens, refusing a NUL
    inside it (the library would open the part before it)."""
    try:
        raw = os.fsencode(value)
    except TypeError:
        raise TypeError("%s: expected a path (str, bytes or os.PathLike), got %r (%s)"
                        % (name, value, type(value).__name__)) from None
    return no_nul(raw, name, value)


def no_nul(raw: bytes, name: str, value) -> bytes:
    if b"\0" in raw:
        raise refuse("SSG_E_VALUE", "%s: %r holds a NUL character (C would read only the "
                     "part before it)" % (name, value))
    return raw


def size(value, name: str = "size") -> Tuple[int, int]:
    """(W, H) from "WxH" or a pair, each 1..SIZE_MAX as --size takes it."""
    if isinstance(value, str):
        m = re.fullmatch(r"([0-9]{1,9})[xX]([0-9]{1,9})", value)
        if not m:
            raise refuse("SSG_E_RANGE", "%s: expected \"WxH\" (as --size), got %r"
                         % (name, value))
        pair = (int(m.group(1)), int(m.group(2)))
    else:
        try:
            pair = tuple(value)
        except TypeError:
            raise TypeError("%s: expected (W, H) or \"WxH\", got %r" % (name, value)) from None
        if len(pair) != 2:
            raise refuse("SSG_E_RANGE", "%s: expected (W, H), got %r" % (name, value))
    return (integer(pair[0], name + " width", 1, SIZE_MAX),
            integer(pair[1], name + " height", 1, SIZE_MAX))
