"""Progress of a long render: a rich bar on a terminal, plain lines otherwise."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager

from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    TextColumn,
    TimeRemainingColumn,
)

PLAIN_STEPS = 10  # plain output prints a line every tenth of the work


@contextmanager
def progress(ui, total: int, description: str) -> Iterator[Callable[[], None]]:
    """Yields `advance()`; silent without a UI or with --quiet / --json."""
    if ui is None or ui.quiet or ui.json or total <= 0:
        yield lambda: None
        return
    if ui.interactive:
        bar = Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                       TimeRemainingColumn(), console=ui.err, transient=True)
        with bar:
            task = bar.add_task(description, total=total)
            yield lambda: bar.advance(task)
        return
    done = 0
    next_report = 1

    def advance() -> None:
        nonlocal done, next_report
        done += 1
        if done * PLAIN_STEPS >= next_report * total or done == total:
            ui.info(f"{description}: {done}/{total} frames")
            next_report = done * PLAIN_STEPS // total + 1

    yield advance
