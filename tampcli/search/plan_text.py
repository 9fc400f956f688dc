"""IPC plan text -> steps, with the place of each step for error messages.

Accepted: one or more `(action arg ...)` groups (normally one a line), `;`
comments anywhere, an optional `; cost = N ...` comment, and the decorations
some planners add around a step (`0: (a x)` or `0.000: (a x) [1]`). Anything
else is a syntax error at its line and column.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from tampcli.errors import InputError, source_line_at


class PlanSyntaxError(InputError):
    kind = "plan-syntax"


@dataclass(frozen=True)
class PlanStep:
    action: str
    args: tuple[str, ...]
    line: int | None = None
    column: int | None = None

    @property
    def text(self) -> str:
        return "(" + " ".join((self.action, *self.args)) + ")"

    @property
    def name(self) -> str:
        """The ground action's name, as a Task's operators spell it."""
        return self.text


@dataclass(frozen=True)
class PlanText:
    steps: tuple[PlanStep, ...]
    declared_cost: float | None = None


_TOKEN = re.compile(
    r"(?P<comment>;[^\n]*)"
    r"|(?P<space>\s+)"
    r"|(?P<lpar>\()|(?P<rpar>\))"
    r"|(?P<time>\d+(?:\.\d+)?\s*:)"
    r"|(?P<duration>\[\s*\d+(?:\.\d+)?\s*\])"
    r"|(?P<name>[^\s();\[\]]+)"
)
_COST = re.compile(r";\s*cost\s*=\s*([-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)", re.IGNORECASE)


def parse_plan(text: str, path: str | None = None, line_offset: int = 0) -> PlanText:
    """Parse a whole plan file; raise PlanSyntaxError at the offending place."""
    steps: list[PlanStep] = []
    declared: float | None = None
    current: list[str] | None = None
    start = (0, 0)
    pos, line, line_start = 0, 1, 0

    def error(message: str, at: int) -> PlanSyntaxError:
        ln = text.count("\n", 0, at) + 1
        col = at - (text.rfind("\n", 0, at) + 1) + 1
        return PlanSyntaxError(message, path, ln + line_offset, col, source_line_at(text, ln))

    while pos < len(text):
        match = _TOKEN.match(text, pos)
        if match is None:  # only a lone "[" or "]" gets here
            raise error(f'unexpected "{text[pos]}"', pos)
        kind, value = match.lastgroup, match.group()
        if kind == "comment":
            cost = _COST.match(value)
            if cost and current is None:
                declared = float(cost.group(1))
        elif kind == "space":
            pass
        elif kind == "lpar":
            if current is not None:
                raise error('unexpected "(" inside a step: steps do not nest', pos)
            current, start = [], (line, pos - line_start + 1)
        elif kind == "rpar":
            if current is None:
                raise error('unexpected ")" with no step open', pos)
            if not current:
                raise error("an empty step `()`: expected `(action arg ...)`", pos)
            steps.append(PlanStep(current[0], tuple(current[1:]), start[0] + line_offset,
                                  start[1]))
            current = None
        elif kind in ("time", "duration"):
            if current is not None:
                raise error(f'unexpected "{value}" inside a step', pos)
        else:
            if current is None:
                raise error(f'unexpected "{value}" outside a step: expected `(action arg ...)` '
                            "or a `;` comment", pos)
            current.append(value.lower())
        newlines = value.count("\n")
        if newlines:
            line += newlines
            line_start = pos + value.rfind("\n") + 1
        pos = match.end()
    if current is not None:
        raise error("unexpected end of plan: a step is not closed (missing `)`)", len(text))
    return PlanText(tuple(steps), declared)


def parse_step(text: str, path: str | None = None, key: str | None = None) -> PlanStep:
    """One `(action arg ...)` string, e.g. an entry of a solution.json `plan` list.

    The one reader of action names outside plan files: verify and the video's
    replay take an action's schema and arguments from here too.
    """
    try:
        parsed = parse_plan(text, path)
    except PlanSyntaxError as err:
        err.key = key
        err.line = err.column = None
        raise
    if len(parsed.steps) != 1:
        raise PlanSyntaxError(f"expected one step `(action arg ...)`, found {len(parsed.steps)}: "
                              f"{text!r}", path, key=key)
    step = parsed.steps[0]
    return PlanStep(step.action, step.args)
