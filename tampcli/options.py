"""What the options of every stage share: the error a bad value raises, and
the one place a command line reads a default from.

Each stage's options are a frozen dataclass checked when built; its field
defaults are the only copy of each default, so a command's flags take theirs
from `default_of` rather than repeating a literal.
"""

from __future__ import annotations

import dataclasses
import math


class OptionError(ValueError):
    """A bad option value; `field` names the dataclass field, so a command line
    can name its own flag for it."""

    def __init__(self, field: str, message: str):
        super().__init__(f"{field} {message}")
        self.field = field
        self.message = message


def default_of(options_type: type, field: str):
    """The default of `field` of the options dataclass `options_type`."""
    for f in dataclasses.fields(options_type):
        if f.name == field:
            if f.default is dataclasses.MISSING:
                raise TypeError(f"{options_type.__name__}.{field} has no plain default")
            return f.default
    raise TypeError(f"{options_type.__name__} has no field {field!r}")


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
