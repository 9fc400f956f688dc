"""TOML text with locations: parse it, and find the line of a table or key.

`tomllib` keeps no positions, so semantic errors are located by scanning the
text once for table headers and `key =` lines. That is exact for the files
tampcli reads (one key a line, no nested inline tables in the located keys).
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass

from tampcli.errors import SceneError, source_line_at

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

_HEADER = re.compile(r"^\s*(\[\[?)\s*([A-Za-z0-9_.\-\"' ]+?)\s*\]\]?\s*(#.*)?$")
_KEY = re.compile(r"^\s*([A-Za-z0-9_\-\"']+)\s*=")
_AT = re.compile(r"\(at line (\d+), column (\d+)\)")


@dataclass(frozen=True)
class TomlSource:
    """A parsed TOML file and an index (table, entry, key) -> line."""

    path: str
    text: str
    data: dict
    lines: dict  # (table, index, key or None) -> 1-based line

    def line(self, table: str | None, index: int = 0, key: str | None = None) -> int | None:
        """Line of `key` in the `index`-th `[table]`/`[[table]]` (or of the header)."""
        found = self.lines.get((table, index, key))
        if found is None and key is not None:
            found = self.lines.get((table, index, None))
        return found

    def error(self, message: str, table: str | None, index: int = 0,
              key: str | None = None, name: str | None = None) -> SceneError:
        """A SceneError located at the key (or its table); `name` is the reported key."""
        line = self.line(table, index, key)
        shown = name or ".".join(p for p in (table, key) if p) or None
        return SceneError(message, path=self.path, line=line, key=shown,
                          source_line=source_line_at(self.text, line))


def read_toml(path: str, text: str | None = None) -> TomlSource:
    """Parse a TOML file; a syntax error becomes a located SceneError."""
    if text is None:
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            raise SceneError(f"cannot read file: {e.strerror}", path=path) from None
        except UnicodeDecodeError as e:
            raise SceneError(f"not UTF-8 text: {e.reason}", path=path) from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        msg = str(e)
        m = _AT.search(msg)
        if m:
            line, column = int(m.group(1)), int(m.group(2))
        else:  # "at end of document"
            line, column = max(1, len(text.splitlines())), None
        message = "TOML syntax error: " + _AT.sub("", msg).replace("(at end of document)", "").strip()
        raise SceneError(message, path=path, line=line, column=column,
                         source_line=source_line_at(text, line)) from None
    return TomlSource(path, text, data, _index_lines(text))


def _index_lines(text: str) -> dict:
    lines: dict = {}
    counts: dict = {}
    table: str | None = None
    index = 0
    depth = 0  # open brackets of a multi-line array: its lines hold no keys
    for number, raw in enumerate(text.splitlines(), start=1):
        stripped = _strip_comment(raw)
        if depth == 0:
            header = _HEADER.match(stripped)
            if header:
                table = header.group(2).strip().strip("\"'")
                if header.group(1) == "[[":
                    index = counts.get(table, -1) + 1
                    counts[table] = index
                else:
                    index = 0
                lines.setdefault((table, index, None), number)
                continue
            key = _KEY.match(stripped)
            if key:
                lines.setdefault((table, index, key.group(1).strip("\"'")), number)
        depth += _bracket_balance(stripped) if depth or _KEY.match(stripped) else 0
        depth = max(depth, 0)
    return lines


def _strip_comment(line: str) -> str:
    out = []
    quote = None
    for ch in line:
        if quote:
            if ch == quote:
                quote = None
        elif ch in "\"'":
            quote = ch
        elif ch == "#":
            break
        out.append(ch)
    return "".join(out)


def _bracket_balance(line: str) -> int:
    balance = 0
    quote = None
    for ch in line:
        if quote:
            if ch == quote:
                quote = None
        elif ch in "\"'":
            quote = ch
        elif ch == "[":
            balance += 1
        elif ch == "]":
            balance -= 1
    return balance
