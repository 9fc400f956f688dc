"""Errors that reach the user: bad input (exit 2) with a precise location.

An InputError knows the file, line and column it is about and, when it can,
the offending source line, so the CLI can print `path:line:col: message`, the
line and a caret. Everything that is the user's fault is an InputError; any
other exception is a bug (exit 70).

The options of a stage (frozen dataclasses) are checked when built with
`require_int` / `require_number` and raise OptionError, a ValueError naming
the field: from a library caller it is a bug, and a command that built the
options from its flags turns it into a UsageError naming the flag.
"""

from __future__ import annotations

import enum
import math


class ExitCode(enum.IntEnum):
    OK = 0
    NO_SOLUTION = 1  # proved unsolvable, or a limit was reached; or a plan is invalid
    BAD_INPUT = 2
    INTERNAL = 70


class InputError(Exception):
    """Bad input: a file, or a command-line usage, the user must fix."""

    kind = "input"

    def __init__(
        self,
        message: str,
        path: str | None = None,
        line: int | None = None,
        column: int | None = None,
        source_line: str | None = None,
        expected: tuple[str, ...] = (),
        key: str | None = None,
    ):
        super().__init__(message)
        self.message = message
        self.path = path
        self.line = line
        self.column = column
        self.source_line = source_line
        self.expected = expected
        self.key = key

    def location(self) -> str:
        parts = [self.path or "<input>"]
        if self.line is not None:
            parts.append(str(self.line))
            if self.column is not None:
                parts.append(str(self.column))
        return ":".join(parts)

    def render(self) -> str:
        """The full user-facing text: location, message, source line, caret."""
        head = f"{self.location()}: "
        if self.key:
            head += f"{self.key}: "
        text = head + self.message
        if self.expected:
            text += "\n  expected: " + ", ".join(self.expected)
        if self.source_line is not None:
            src = self.source_line.rstrip("\n").expandtabs(1)
            text += "\n  " + src
            if self.column is not None:
                text += "\n  " + " " * max(self.column - 1, 0) + "^"
        return text

    def to_json(self) -> dict:
        return {
            "kind": self.kind,
            "message": self.message,
            "path": self.path,
            "line": self.line,
            "column": self.column,
            "key": self.key,
            "expected": list(self.expected),
        }


class PDDLSyntaxError(InputError):
    kind = "syntax"


class PDDLSemanticError(InputError):
    kind = "semantic"


class UnsupportedFeatureError(InputError):
    kind = "unsupported"


class SceneError(InputError):
    kind = "scene"


class SolutionFileError(InputError):
    kind = "solution"


class UsageError(InputError):
    kind = "usage"


def source_line_at(text: str, line: int | None) -> str | None:
    """The 1-based `line` of `text`, or None when out of range.

    Lines end at "\n" only, as the lexers count them (str.splitlines would
    also split at form feeds and other separators, and show the wrong line);
    an empty file has one empty line, so an error in it still shows a caret.
    """
    if line is None or line < 1:
        return None
    lines = text.split("\n")
    if line > len(lines):
        return None
    return lines[line - 1].removesuffix("\r")


class OptionError(ValueError):
    """A bad option value; `field` names the dataclass field, so a command line
    can name its own flag for it."""

    def __init__(self, field: str, message: str):
        super().__init__(f"{field} {message}")
        self.field = field
        self.message = message


def require_int(value, field: str, least: int) -> None:
    if isinstance(value, bool) or not isinstance(value, int) or value < least:
        raise OptionError(field, f"must be an integer >= {least}, got {value!r}")


def require_number(value, field: str, *, positive: bool = False, unit: str = "",
                   finite: bool = True) -> None:
    """A number, > 0 with `positive`, else >= 0; infinity only without `finite`
    (a time limit of inf is no limit), never NaN."""
    ok = isinstance(value, (int, float)) and not isinstance(value, bool) and \
        not math.isnan(value) and (not finite or math.isfinite(value)) and \
        (value > 0 if positive else value >= 0)
    if not ok:
        bound = "> 0" if positive else ">= 0"
        raise OptionError(field, f"must be a number {bound}{f' ({unit})' if unit else ''}, "
                          f"got {value!r}")
