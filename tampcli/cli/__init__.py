"""The command line: the only place that parses flags, prints and picks exit codes.

Each command lives in its own module with `add_parser(subparsers)` and
`run(args, ui) -> int`; errors are caught here and only here.
"""

from __future__ import annotations

import argparse
import importlib
import sys
import traceback

from tampcli import __version__
from tampcli.cli.ui import UI
from tampcli.errors import ExitCode, InputError

# Command name -> module; modules are imported lazily so that `tampcli plan`
# never pays for numpy, scipy or pybullet.
COMMANDS = {
    "check": "tampcli.cli.check",
    "plan": "tampcli.cli.plan",
    "validate": "tampcli.cli.validate",
    "solve": "tampcli.cli.solve",
    "render": "tampcli.cli.render",
    "batch": "tampcli.cli.batch",
}

_HELP = {
    "check": "parse and type-check a domain (and problem, and scene)",
    "plan": "symbolic planning, plans in IPC format: one (-k 1; LAMA by default, not "
            "necessarily the cheapest) or the K cheapest (-k K)",
    "validate": "check a plan or a solution.json",
    "solve": "full TAMP: ranked skeletons + trajectory optimization",
    "render": "replay a solution.json headlessly and export a video",
    "batch": "run solve (or plan) over problem sets, one JSON line per problem",
}


class _ArgumentParser(argparse.ArgumentParser):
    """argparse that raises instead of exiting, so usage errors share our path."""

    def error(self, message):
        raise InputError(message + f"\n  (see `{self.prog} --help`)", path=self.prog)


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The argument parser; with `only`, just that command's module is imported."""
    parser = _ArgumentParser(
        prog="tampcli",
        description="Optimization-based Task and Motion Planning from the command line.")
    parser.add_argument("--version", action="version", version=f"tampcli {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_ArgumentParser)
    for name, module_name in COMMANDS.items():
        if only is not None and name != only:
            sub.add_parser(name, help=_HELP[name])
            continue
        module = importlib.import_module(module_name)
        p = sub.add_parser(name, help=_HELP[name], description=_HELP[name])
        add_common(p)
        module.add_parser(p)
        p.set_defaults(run=module.run)
    return parser


def add_common(p: argparse.ArgumentParser) -> None:
    p.add_argument("--json", action="store_true", help="print machine-readable JSON instead")
    p.add_argument("--quiet", "-q", action="store_true", help="print only errors")
    p.add_argument("--traceback", action="store_true", help="show a traceback on internal errors")


def main(argv: list[str] | None = None, ui: UI | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    ui = ui or UI()
    traceback_wanted = "--traceback" in argv
    try:
        command = next((a for a in argv if not a.startswith("-")), None)
        parser = build_parser(command if command in COMMANDS else None)
        args = parser.parse_args(argv)
        if not getattr(args, "command", None):
            parser.print_help(ui.out.file)
            return ExitCode.BAD_INPUT
        ui.configure(json=args.json, quiet=args.quiet)
        return int(args.run(args, ui))
    except InputError as err:
        ui.input_error(err)
        return ExitCode.BAD_INPUT
    except KeyboardInterrupt:
        ui.error("interrupted")
        return 130
    except Exception as err:  # a bug: say so, point at --traceback
        if traceback_wanted:
            # The traceback, and the same exit code as without it (blind29: 1 before).
            traceback.print_exc(file=sys.stderr)
            ui.error(f"internal error: {type(err).__name__}: {err}")
            return ExitCode.INTERNAL
        ui.error(f"internal error: {type(err).__name__}: {err} (rerun with --traceback)")
        return ExitCode.INTERNAL
