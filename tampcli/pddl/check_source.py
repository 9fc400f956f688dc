"""Where a semantic mistake is: a file's text read lazily, spans to `path:line:col`
and to the source line with a caret (pddl/check.py's errors)."""

from __future__ import annotations

import re
from bisect import bisect_right
from pathlib import Path

from tampcli.errors import InputError, PDDLSemanticError
from tampcli.pddl import ast


def located(path: str | None, span: ast.Span) -> str:
    return f"{path or '<input>'}:{span.line}:{span.column}"


class Source:
    """The text of a file, read only when an error needs its lines."""

    _TOKEN = re.compile(r"\(|\)|;[^\n]*|[^\s();]+")

    def __init__(self, path: str | None):
        self.path = path
        self._lines: list[str] | None = None
        self._text = ""
        self._starts: list[int] = []

    def lines(self) -> list[str]:
        """The lines without their "\n" (the only line end the lexer counts)."""
        if self._lines is None:
            try:
                # Decoded as parser.read_file does: no newline translation, so
                # offsets match the lexer's.
                self._text = Path(self.path).read_bytes().decode("utf-8") if self.path else ""
            except (OSError, UnicodeDecodeError):
                self._text = ""
            self._lines = self._text.split("\n")
            pos = 0
            for line in self._lines:
                self._starts.append(pos)
                pos += len(line) + 1
        return self._lines

    def error(self, message: str, span: ast.Span, item: int | None = None,
              cls: type[InputError] = PDDLSemanticError) -> InputError:
        """An error at `span`, or at the `item`-th element inside the list `span` opens
        (0: its head, 1: its first argument...)."""
        line, column = span.line, span.column
        if item is not None:
            line, column = self._item(span, item)
        lines = self.lines()
        source = lines[line - 1].removesuffix("\r") if 0 < line <= len(lines) else None
        return cls(message, self.path, line or None, column or None, source)

    def _item(self, span: ast.Span, item: int) -> tuple[int, int]:
        lines = self.lines()
        if not 0 < span.line <= len(lines):
            return span.line, span.column
        text = self._text
        start = self._starts[span.line - 1] + span.column - 1
        if text[start:start + 1] != "(":
            return span.line, span.column
        index = -1
        for match in self._TOKEN.finditer(text, start + 1):
            tok = match.group()
            if tok.startswith(";"):
                continue
            if tok == ")" or tok == "(" and index >= 0:
                break
            index += 1
            if index == item:
                pos = match.start()
                row = bisect_right(self._starts, pos) - 1
                return row + 1, pos - self._starts[row] + 1
        return span.line, span.column


# ---------------------------------------------------------------- domain
