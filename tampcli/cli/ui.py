"""Console output: rich on a terminal, plain lines when piped, JSON on request.

Commands receive a UI; tests build one around StringIO consoles to capture
what a user would see.
"""

from __future__ import annotations

import json
import sys
from typing import Any

from rich.console import Console
from rich.markup import escape

from tampcli.errors import InputError


class UI:
    def __init__(self, out: Console | None = None, err: Console | None = None):
        self.out = out or Console(highlight=False, soft_wrap=True)
        self.err = err or Console(stderr=True, highlight=False, soft_wrap=True)
        self.json = False
        self.quiet = False

    def configure(self, json: bool = False, quiet: bool = False) -> None:
        self.json, self.quiet = json, quiet

    @property
    def interactive(self) -> bool:
        return self.out.is_terminal and not self.json and not self.quiet

    def print(self, *objects: Any, **kwargs: Any) -> None:
        """Human output on stdout (suppressed by --json and --quiet)."""
        if not self.json and not self.quiet:
            self.out.print(*objects, **kwargs)

    def info(self, message: str) -> None:
        """Progress and statistics on stderr (suppressed by --quiet)."""
        if not self.quiet:
            self.err.print(message, markup=False)

    def warn(self, message: str) -> None:
        if not self.quiet:
            self.err.print(f"[yellow]warning:[/] {escape(message)}")

    def error(self, message: str) -> None:
        self.err.print(f"[red]error:[/] {escape(message)}")

    def input_error(self, err: InputError) -> None:
        if self.json:
            self.emit_json({"status": "error", "error": err.to_json(), "message": err.render()})
        self.err.print(escape(err.render()), markup=True)

    def emit_json(self, data: Any) -> None:
        text = json.dumps(data, indent=None, default=_jsonable)
        self.out.file.write(text + "\n")
        self.out.file.flush()

    def plain(self, text: str) -> None:
        """Exact text on stdout (plans in IPC format), no markup."""
        if not self.json and not self.quiet:
            self.out.file.write(text if text.endswith("\n") else text + "\n")
            self.out.file.flush()


def _jsonable(value: Any) -> Any:
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, (set, frozenset)):
        return sorted(value)
    raise TypeError(f"not JSON serializable: {type(value).__name__}")


def stdout_is_terminal() -> bool:
    return sys.stdout.isatty()
