"""The MINLP method of `tampcli solve` (`solve --method minlp`): one SCIP model over T steps.

`add_arguments` adds the MINLP's own flags to a parser that already has the
solve command's positional arguments; `add_parser` adds those too, so the
module also stands alone as a command. `run(args, ui)` solves, writes `--out`
and reports like `solve`.
"""

from __future__ import annotations

from tampcli import solution as solution_file
from tampcli.cli.restriction import add_restriction
from tampcli.errors import ExitCode, UsageError


def add_parser(p) -> None:
    p.add_argument("domain", help="PDDL domain file")
    p.add_argument("problem", help="PDDL problem file")
    p.add_argument("--scene", help="scene.toml (default: PROBLEM's name + .scene.toml beside it)")
    p.add_argument("--modes", help="modes.toml (default: beside the domain file)")
    p.add_argument("--time-limit", type=float, default=120.0, metavar="S",
                   help="CPU seconds SCIP may spend (default 120)")
    p.add_argument("--symbolic-weight", type=float, default=0.1, metavar="W",
                   help="objective = trajectory cost + W * symbolic cost (default 0.1)")
    p.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    p.add_argument("--out", metavar="FILE", help="write solution.json here (whatever the outcome)")
    add_restriction(p)
    add_arguments(p)


def add_arguments(p) -> None:
    """The MINLP's own flags."""
    p.add_argument("--steps", type=int, default=8, metavar="T",
                   help="motion steps of the time-indexed model; T + 1 waypoints (default 8)")
    p.add_argument("--gap", type=float, default=1e-4,
                   help="stop at this relative gap between SCIP's solution and bound "
                        "(default 1e-4)")
    p.add_argument("--polygon-sides", type=int, default=16, metavar="N",
                   help="sides of the polygon standing for a disk or cylinder (default 16)")
    p.add_argument("--collision-model", choices=("outer", "inner"), default="outer",
                   help="outer: circumscribed polygons, collision-free solutions, bound for "
                        "that model; inner: inscribed, a relaxation (default outer)")
    p.add_argument("--warm-start", metavar="SOLUTION",
                   help="a solution.json (e.g. branch and bound's) to start SCIP from")
    p.add_argument("--schedule", metavar="SOLUTION",
                   help="a solution.json whose actions stay at its waypoints: optimize only "
                        "the trajectory of that schedule")


def options_from_args(args):
    from tampcli.minlp import MinlpOptions

    try:
        return MinlpOptions(steps=args.steps, time_limit=args.time_limit,
                            symbolic_weight=args.symbolic_weight, gap=args.gap,
                            polygon_sides=args.polygon_sides,
                            collision_model=args.collision_model, warm_start=args.warm_start,
                            schedule=args.schedule,
                            forced=tuple(args.forced), forbidden=tuple(args.forbidden),
                            seed=args.seed)
    except ValueError as err:
        raise UsageError(str(err), "tampcli solve --method minlp") from None


def run(args, ui) -> int:
    options = options_from_args(args)
    try:
        from tampcli.minlp.solve import solve_minlp
    except ModuleNotFoundError as err:
        if err.name != "pyscipopt":
            raise
        raise UsageError("the MINLP needs PySCIPOpt: pip install 'tampcli[minlp]'",
                         "tampcli solve --method minlp") from None
    sol = solve_minlp(args.domain, args.problem, args.scene, args.modes, options)
    if args.out:
        solution_file.write(sol, args.out)
    if ui.json:
        ui.emit_json(solution_file.to_dict(sol))
    else:
        _summary(sol, ui)
    return ExitCode.OK if sol.solved else ExitCode.NO_SOLUTION


def _summary(sol, ui) -> None:
    stats = sol.stats
    if sol.solved:
        ui.plain("\n".join(sol.plan))
        ui.plain(f"; symbolic cost = {sol.symbolic_cost:g}")
        ui.info(f"solved: trajectory cost {sol.cost:.4f}, objective {sol.objective:.4f}, "
                f"{len(sol.trajectory)} waypoints")
    else:
        ui.error(f"{sol.status}: {sol.reason}")
    bound = "-" if sol.lower_bound is None else f"{sol.lower_bound:.4f}"
    gap = "-" if stats.get("gap") is None else f"{100 * stats['gap']:.2f} %"
    ui.info(f"SCIP {stats['scip_status']}: dual bound {bound} (proved for the "
            f"{stats['steps']}-step model, {stats['collision_model']} polygons of "
            f"{stats['polygon_sides']} sides), gap {gap}, {stats['nodes']} nodes, "
            f"{stats['seconds']['scip']:.2f} s")
