import io
from pathlib import Path

import pytest
from rich.console import Console

from tampcli.cli import main
from tampcli.cli.ui import UI

ROOT = Path(__file__).resolve().parent.parent
IPC = ROOT / "benchmarks" / "ipc"


class Run:
    def __init__(self, code: int, out: str, err: str):
        self.code, self.out, self.err = code, out, err


@pytest.fixture
def cli():
    """Run the CLI in-process; returns exit code and captured stdout/stderr."""

    def run(*argv: str) -> Run:
        out, err = io.StringIO(), io.StringIO()
        ui = UI(Console(file=out, width=200, highlight=False, soft_wrap=True),
                Console(file=err, width=200, highlight=False, soft_wrap=True))
        code = main([str(a) for a in argv], ui)
        return Run(code, out.getvalue(), err.getvalue())

    return run
