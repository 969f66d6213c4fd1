"""Errors: a library diagnostic becomes a Python exception carrying its file, line, column
and message; the bindings' own checks (dtype, shape, contiguity) raise TypeError or
ValueError before anything reaches the library."""
from dataclasses import dataclass
from typing import List, Optional

from ._ssgraph import ffi, lib


@dataclass(frozen=True)
class Diagnostic:
    """One message of the library: where (file, 1-based line and column; 0 = no place)
    and what, with the error code's symbolic name ("SSG_E_RANGE")."""
    code: str
    file: str
    line: int
    column: int
    message: str

    def __str__(self) -> str:
        place = self.file
        if self.line:
            place += ":%d:%d" % (self.line, self.column)
        return "%s: %s" % (place, self.message) if place else self.message


class Error(Exception):
    """A call into ssgraph failed. `code` is the error's symbolic name ("SSG_E_RANGE"),
    `diagnostics` every message the call reported (the first is also `file`, `line`,
    `column` and `message`), `warnings` the warnings beside them."""

    def __init__(self, code: str, diagnostics: List[Diagnostic],
                 warnings: Optional[List[Diagnostic]] = None):
        self.code = code
        self.diagnostics = diagnostics
        self.warnings = warnings or []
        first = diagnostics[0] if diagnostics else Diagnostic(code, "", 0, 0, code)
        self.file, self.line, self.column = first.file, first.line, first.column
        self.message = first.message
        super().__init__(str(first))

    def __str__(self) -> str:
        return "\n".join(str(d) for d in self.diagnostics) or self.code


class UnknownNameError(Error, KeyError):
    """A node, port, parameter or name the graph or the registry does not have."""


class ValueRangeError(Error, ValueError):
    """A value of the wrong type, out of its range, or an image of the wrong size or
    channel count."""


_KINDS = {
    "SSG_E_UNKNOWN_NODE": UnknownNameError, "SSG_E_UNKNOWN_PORT": UnknownNameError,
    "SSG_E_UNKNOWN_PARAM": UnknownNameError, "SSG_E_UNKNOWN_NAME": UnknownNameError,
    "SSG_E_RANGE": ValueRangeError, "SSG_E_VALUE": ValueRangeError,
    "SSG_E_TYPE": ValueRangeError, "SSG_E_SIZE": ValueRangeError,
    "SSG_E_CHANNELS": ValueRangeError,
}


def _string(chars) -> str:
    return ffi.string(chars).decode("utf-8", "replace")


def _diagnostic(d) -> Diagnostic:
    return Diagnostic(_string(lib.ssg_err_name(d.code)), _string(d.file), d.line, d.column,
                      _string(d.message))


def new_diags():
    """A zeroed struct ssg_diags for one call."""
    return ffi.new("struct ssg_diags *")


def warnings_of(diags) -> List[Diagnostic]:
    return [_diagnostic(diags.warnings[i]) for i in range(diags.warning_count)]


def raise_for(err: int, diags, what: str = "") -> None:
    """Raises the Error of a failed call (err != SSG_OK) with its diagnostics; a failure
    that reported none still names its code and `what` was being done."""
    if err == lib.SSG_OK:
        return
    code = _string(lib.ssg_err_name(err))
    found = [_diagnostic(diags.items[i]) for i in range(diags.count)]
    if not found:
        found = [Diagnostic(code, "", 0, 0, "%s%s" % (what + ": " if what else "",
                                                       _string(lib.ssg_err_text(err))))]
    raise _KINDS.get(code, Error)(code, found, warnings_of(diags))
