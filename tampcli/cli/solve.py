"""`tampcli solve DOMAIN PROBLEM`: ranked skeletons x trajectory optimization."""

from __future__ import annotations

from contextlib import ExitStack
from dataclasses import dataclass

from rich.live import Live
from rich.table import Table

from tampcli import solution as solution_file
from tampcli.bnb import BnBOptions, Event
from tampcli.bnb.values import DEFAULT_SKELETONS
from tampcli.errors import ExitCode, OptionError, UsageError
from tampcli.optimize.backends import BACKENDS
from tampcli.optimize.grasp_report import grasp_words
from tampcli.optimize.options import OptimizeOptions
from tampcli.pipeline import InputPaths, SolveOptions, solving

# The options value of each SolveOptions field a flag sets.
_STAGES = {"bnb": BnBOptions, "optimize": OptimizeOptions}


@dataclass(frozen=True)
class Flag:
    """A flag of `tampcli solve` and the options field it sets; its default is
    that field's (the only copy of it)."""

    name: str
    stage: str  # a key of _STAGES
    field: str
    type: type | None  # None: a switch
    metavar: str | None
    help: str
    short: str | None = None
    choices: tuple[str, ...] | None = None
    default_help: str | None = None  # how --help states the default, where not a value

    @property
    def default(self):
        # A dataclass keeps each plain field default as a class attribute.
        return getattr(_STAGES[self.stage], self.field)


FLAGS = (
    Flag("--skeletons", "bnb", "max_skeletons", int, "K", "skeletons to draw at most", "-k",
         default_help=f"{DEFAULT_SKELETONS} once a solution is found, no cap before one: the "
         "time limit ends a search that finds nothing"),
    Flag("--time-limit", "bnb", "time_limit", float, "S", "seconds for the whole solve"),
    Flag("--symbolic-weight", "bnb", "symbolic_weight", float, "W",
         "objective = trajectory cost + W * symbolic cost"),
    Flag("--waypoints", "optimize", "waypoints", int, "T", "waypoints per motion phase"),
    Flag("--anytime", "bnb", "anytime", None, None,
         "keep improving until a limit; report each improvement"),
    Flag("--first", "bnb", "first", None, None,
         "stop at the first verified solution (no search for a better skeleton)"),
    Flag("--seed", "optimize", "seed", int, None, "random seed"),
    Flag("--nlp", "optimize", "nlp", str, None,
         "solver of the path stage's NLPs: slsqp, ipopt (needs cyipopt: pip install "
         "'tampcli[ipopt]'), or auto (SLSQP, the faster at every size measured; "
         "docs/ipopt.md)", choices=tuple(BACKENDS)),
    Flag("--jobs", "bnb", "jobs", int, "N",
         "skeletons solved at once once there is a first solution: one in this process, "
         "the others in N - 1 worker processes, set up while this process looks for the "
         "first solution alone, as the serial search does (each skeleton drawn knowing "
         "every failure before it); 1: serial throughout",
         short="-j", default_help="0: one per core, at most 4"),
)


def add_parser(p) -> None:
    p.add_argument("domain", help="PDDL domain file")
    p.add_argument("problem", help="PDDL problem file")
    p.add_argument("--scene", help="scene.toml (default: PROBLEM's name + .scene.toml beside it)")
    p.add_argument("--modes", help="modes.toml (default: beside the domain file)")
    for flag in FLAGS:
        names = (flag.short, flag.name) if flag.short else (flag.name,)
        if flag.type is None:
            p.add_argument(*names, dest=flag.field, action="store_true", help=flag.help)
        else:
            shown = "g" if flag.type in (int, float) else "s"
            default = flag.default_help or f"%(default){shown}"
            p.add_argument(*names, dest=flag.field, type=flag.type, default=flag.default,
                           choices=flag.choices, metavar=flag.metavar,
                           help=f"{flag.help} (default {default})")
    p.add_argument("--out", metavar="FILE", help="write solution.json here (whatever the outcome)")
    p.add_argument("--video", metavar="FILE", help="render the solution to FILE (.mp4 or .gif)")
    p.add_argument("--method", choices=sorted(METHODS), default="bnb",
                   help="bnb: ranked skeletons x trajectory NLPs (any robot); minlp: the "
                        "lesson's time-indexed MINLP solved to global optimality by SCIP "
                        "(planar robot; docs/minlp.md) (default bnb)")
    from tampcli.cli import minlp
    from tampcli.cli.restriction import add_restriction

    add_restriction(p)
    minlp.add_arguments(p.add_argument_group("with --method minlp"))


def options_from_args(args) -> SolveOptions:
    """SolveOptions from the parsed flags; a bad value is a UsageError naming its flag."""
    parts = {}
    for stage, options_type in _STAGES.items():
        flags = [flag for flag in FLAGS if flag.stage == stage]
        try:
            parts[stage] = options_type(**{flag.field: getattr(args, flag.field)
                                           for flag in flags})
        except OptionError as err:
            flag = next((flag.name for flag in flags if flag.field == err.field), None)
            raise UsageError(err.message, "tampcli solve", key=flag) from None
    return SolveOptions(**parts, forced=tuple(args.forced), forbidden=tuple(args.forbidden))


def run(args, ui) -> int:
    return METHODS[args.method](args, ui)


def _run_minlp(args, ui) -> int:
    from tampcli.cli import minlp

    if args.video:
        raise UsageError("--video is for --method bnb; render the --out file with "
                         "`tampcli render`", "tampcli solve", key="--video")
    return minlp.run(args, ui)


def _run_bnb(args, ui) -> int:
    options = options_from_args(args)
    missing = BACKENDS[options.optimize.nlp].missing()
    if missing:  # refused before any solving, not at the first path stage
        raise UsageError(missing, "tampcli solve", key="--nlp")
    render_options = None
    if args.video:  # refuse a bad video path before minutes of solving
        from tampcli.render.options import RenderOptions
        from tampcli.render.video import check_writable, video_format

        render_options = RenderOptions()
        video_format(args.video, render_options.width, render_options.height)
        check_writable(args.video, "--video")
    paths = InputPaths(args.domain, args.problem, args.scene, args.modes)
    view = _LiveView(ui)
    with ExitStack() as keep_open:
        # The live view ends with the search; the World stays open for the video.
        with view:
            solved = keep_open.enter_context(solving(paths, options, view.on_event,
                                                     visuals=bool(args.video)))
        sol = solved.solution
        if args.out:
            solution_file.write(sol, args.out)
        if args.video and sol.solved and sol.trajectory:
            _render(solved, args.out, args.video, render_options, ui)
    if ui.json:
        ui.emit_json(solution_file.to_dict(sol))
    else:
        _summary(sol, ui, args)
    return ExitCode.OK if sol.solved else ExitCode.NO_SOLUTION


def _render(solved, out_path, video, options, ui) -> None:
    """Render from what the solve holds: its inputs and its open World."""
    from tampcli.render.inputs import RenderInputs
    from tampcli.render.video import render_solution
    from tampcli.solution_read import check_solution

    inputs = solved.inputs
    # The arm's columns for the replay, the finger columns (if any) beside them.
    checked = check_solution(solved.solution, out_path or "<solution>")
    source = RenderInputs(checked.canonical, checked.path, inputs.scene,
                          inputs.problem.name, inputs.modes, checked)
    info = render_solution(source, video, options, ui=ui, world=solved.world)
    ui.info(f"video: {info.get('path', video)}")


def _summary(sol, ui, args) -> None:
    stats = sol.stats
    seconds = stats.get("seconds", {})
    if sol.solved:
        if sol.scene is None:
            ui.info("no scene: solved symbolically")
        ui.plain("\n".join(sol.plan))
        ui.plain(f"; symbolic cost = {sol.symbolic_cost:g}")
        if sol.scene is not None:
            ui.info(f"solved: trajectory cost {sol.cost:.4f}, objective {sol.objective:.4f}, "
                    f"{len(sol.trajectory)} waypoints")
            for entry in sol.grasps:
                ui.info(f"{entry['family'] if 'pusher' in entry else 'grasp'} "
                        f"{grasp_words(entry)}")
            _certificate(sol, ui)
    else:
        ui.error(f"{sol.status}: {sol.reason}")
    if sol.skeletons and not ui.quiet:
        rows = [(str(s.rank), _short(s.plan), f"{s.symbolic_cost:g}",
                 _fmt(s.bound) + (" (h)" if s.bound_kind == "heuristic" else ""),
                 s.stage or "-", s.outcome, _fmt(s.nlp_cost), _kkt(s), f"{s.seconds:.2f}")
                for s in sol.skeletons]
        if ui.err.is_terminal:
            table = Table(title="skeletons", caption=KKT_CAPTION)
            for col in ("#", "plan", "sym", "bound", "stage", "outcome", "nlp cost", "KKT", "s"):
                table.add_column(col)
            for row in rows:
                table.add_row(*row)
            ui.err.print(table)
        else:
            # Piped: one plain line per skeleton, easy to grep.
            for rank, plan, sym, bound, stage, outcome, cost, kkt, secs in rows:
                where = f" at {stage}" if stage != "-" else \
                    ("" if outcome == "not reached" else " before any NLP")
                ui.err.print(f"skeleton #{rank}: {outcome}{where}, symbolic cost {sym}, "
                             f"bound {bound}, nlp cost {cost}, kkt {kkt}, {secs} s: {plan}",
                             markup=False, highlight=False)
    ui.info("time: " + ", ".join(f"{k} {v:.2f}s" for k, v in seconds.items())
            + f"; skeletons {stats.get('skeletons_generated', 0)} generated, "
            f"{stats.get('skeletons_optimized', 0)} optimized, "
            f"{stats.get('skeletons_pruned', 0)} pruned, "
            f"{stats.get('skeletons_infeasible', 0)} infeasible"
            + (f", {stats['elimination_skeletons']} more by action elimination"
               if stats.get("elimination_skeletons") else "")
            + f"; NLP solves {stats.get('nlp_solves', 0)}")
    for key, words in (("proved_first_moves", "proved before any skeleton (each action "
                        "needs its object moved by an earlier one)"),
                       ("learned", "learned (the skeletons moving the body first came next)")):
        if stats.get(key):
            ui.info(f"{words}: " + "; ".join(stats[key]))
    if args.out:
        ui.info(f"solution: {args.out}")


KKT_CAPTION = ("KKT: the stationarity residual at the answer of the stage reached "
               "(- where it failed); ! where only wrong-signed multipliers explain it")
CARRIERS = 3  # active constraints named in the solution's KKT line
CARRIES = 1e-9  # a multiplier above this (in magnitude) carries part of the gradient


def _kkt(record) -> str:
    """The skeleton table's KKT cell: see KKT_CAPTION."""
    c = record.kkt.of(record.stage)
    if c is None:
        return "-"
    return f"{c.stationarity:.1e}" + ("" if c.dual_feasible else " !")


def _certificate(sol, ui) -> None:
    """One line per stage of the answer's KKT certificate, with what carries it."""
    for stage, c in sol.kkt.items():
        least = "-" if c.min_multiplier is None else f"{c.min_multiplier:.3g}"
        dual = "dual feasible" if c.dual_feasible else "NOT dual feasible"
        carriers = [a for a in c.active if abs(a.multiplier) > CARRIES][:CARRIERS]
        held = "; ".join(f"{a.name} ({a.multiplier:.3g})" for a in carriers)
        ui.info(f"KKT {stage}: stationarity {c.stationarity:.1e} (|grad f| "
                f"{c.gradient:.2g}), complementarity {c.complementarity:.1e}, min multiplier "
                f"{least}, {dual}" + (f"; carried by {held}" if held else ""))


def _short(plan, width=70) -> str:
    text = " ".join(plan)
    return text if len(text) <= width else text[: width - 1] + "…"


def _fmt(value) -> str:
    return "-" if value is None else f"{value:.4g}"


class _LiveView:
    """A live table of skeletons on a terminal; plain progress lines otherwise."""

    def __init__(self, ui):
        self.ui = ui
        self.rows: dict[int, list[str]] = {}
        self.live = None

    def __enter__(self):
        if self.ui.interactive:
            self.live = Live(self._table(), console=self.ui.err, refresh_per_second=8,
                             transient=True)
            self.live.__enter__()
        return self

    def __exit__(self, *exc):
        if self.live is not None:
            self.live.__exit__(*exc)

    def on_event(self, event: Event) -> None:
        row = self.rows.setdefault(event.rank, [str(event.rank), _short(event.plan, 50),
                                                _fmt(event.symbolic_cost), "-", "-", "…", "-"])
        if event.kind == "stage":
            row[3] = event.stage
        elif event.kind == "outcome":
            row[3] = event.stage or row[3]
            row[4] = event.outcome
            row[5] = _fmt(event.cost)
            row[6] = f"{event.seconds:.1f}"
        elif event.kind == "incumbent" and self.live is None:
            self.ui.info(f"[{event.seconds:6.1f}s] new incumbent from skeleton #{event.rank}: "
                         f"objective {event.bound:.4f}")
        if self.live is not None:
            self.live.update(self._table())
        elif event.kind == "outcome":
            self.ui.info(f"[{event.seconds:6.1f}s] skeleton #{event.rank} "
                         f"({len(event.plan)} actions, cost {event.symbolic_cost:g}): "
                         f"{event.outcome} "
                         + (f"at {event.stage}" if event.stage else "before any NLP")
                         + (f" - {event.message}" if event.message else ""))

    def _table(self) -> Table:
        table = Table(title="branch and bound")
        for col in ("#", "plan", "sym", "stage", "outcome", "nlp cost", "t"):
            table.add_column(col)
        for row in list(self.rows.values())[-15:]:
            table.add_row(*row)
        return table


METHODS = {"bnb": _run_bnb, "minlp": _run_minlp}
