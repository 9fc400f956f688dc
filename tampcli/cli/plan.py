"""`tampcli plan DOMAIN PROBLEM`: symbolic planning, plans in IPC format.

Defaults: with -k 1, LAMA's first search (`lama`: lazy greedy search
alternating h_FF, whose relaxed plans give the preferred operators, with the
landmark count; satisficing: fast, not necessarily cheapest), then greedy
action elimination drops every redundant step. `--anytime` then keeps
improving the plan with weighted A* restarts (weights 5, 3, 2, 1) bounded by
the incumbent's cost, printing each better plan, until the time limit.
`--search astar` alone uses LM-cut (optimal), or h_max when the task has
conditional effects. With -k > 1 the top-k planner returns the K cheapest
plans and --search/--heuristic do not apply; --loopless keeps only those that
pass no state twice, the enumeration `solve` draws its skeletons from first.
"""

from __future__ import annotations

import time
from pathlib import Path

from tampcli.cli.restriction import add_restriction
from tampcli.errors import ExitCode, InputError, UsageError
from tampcli.pddl.load import load
from tampcli.search.eliminate import eliminate_redundant
from tampcli.search.heuristics import HEURISTICS, HFF
from tampcli.search.searches import SEARCHES, SearchLimits
from tampcli.task.ground import ground
from tampcli.task.restrict import restrict

OPTIMAL_HEURISTIC = "lmcut"
FALLBACK_OPTIMAL_HEURISTIC = "hmax"


def add_parser(p) -> None:
    p.add_argument("domain", help="PDDL domain file")
    p.add_argument("problem", help="PDDL problem file")
    p.add_argument("-k", type=int, default=1, metavar="K",
                   help="number of plans (default 1). -k 1: one plan from --search; with the "
                        "default lama not necessarily the cheapest (--search astar: a cheapest "
                        "one). -k K >= 2: the K cheapest plans, exactly, cheapest first (the "
                        "top-k planner; --search and --heuristic do not apply), plans that "
                        "pass a state twice included unless --loopless")
    p.add_argument("--search", choices=sorted(SEARCHES), default=None,
                   help="search algorithm (default lama: lazy greedy search alternating h_FF "
                        "with the landmark count, preferred operators from h_FF, as Fast "
                        "Downward's lama-first; astar for optimal plans); with -k 1 every "
                        "redundant step is then removed (greedy action elimination)")
    p.add_argument("--heuristic", choices=sorted(HEURISTICS), default=None,
                   help="heuristic (default: lmcount with lama, alternated with h_FF; lmcut "
                        "with astar/wastar; hff otherwise)")
    p.add_argument("--anytime", action="store_true",
                   help="after the first plan, search for cheaper ones (weighted A* with "
                        "weights 5, 3, 2, 1, bounded by the best cost so far) until the time "
                        "limit, printing each; --out keeps the best (-k 1 only)")
    p.add_argument("--weight", type=float, default=2.0, help="weight of h in wastar (default 2)")
    p.add_argument("--time-limit", type=float, default=None, metavar="S",
                   help="seconds for the search (default none)")
    p.add_argument("--max-expansions", type=int, default=None, metavar="N",
                   help="stop after N expansions (k = 1 only)")
    p.add_argument("--out", default=None, metavar="FILE",
                   help="write the plan to FILE (with -k K >= 2: the cheapest, the others "
                        "to FILE.1, FILE.2, ...; with --anytime: the best so far)")
    p.add_argument("--loopless", action="store_true",
                   help="with -k K >= 2: only plans that never revisit a state, the "
                        "skeletons solve draws first, in its order")
    add_restriction(p)


def _format_cost(cost: float) -> str:
    return str(int(cost)) if float(cost).is_integer() else f"{cost:g}"


def plan_text(actions, cost: float, unit_cost: bool) -> str:
    kind = "unit cost" if unit_cost else "general cost"
    return "".join(a + "\n" for a in actions) + f"; cost = {_format_cost(cost)} ({kind})\n"


def run(args, ui) -> int:
    if args.k < 1:
        raise UsageError(f"-k must be at least 1, got {args.k}", key="-k")
    limits = SearchLimits(time_limit=args.time_limit, max_expansions=args.max_expansions,
                          weight=args.weight)
    seconds: dict[str, float] = {}

    start = time.perf_counter()
    loaded = load(args.domain, args.problem)
    seconds["parse"] = time.perf_counter() - start
    for warning in loaded.warnings:
        ui.warn(warning)

    start = time.perf_counter()
    task = restrict(ground(loaded.domain, loaded.problem), args.forced, args.forbidden)
    seconds["ground"] = time.perf_counter() - start
    stats: dict = {"facts": len(task.facts), "operators": len(task.operators),
                   "axioms": len(task.axioms)}

    start = time.perf_counter()
    if args.k == 1:
        status, plans, search_stats, reason = _single(task, args, limits, ui)
    else:
        if args.anytime:
            raise UsageError("--anytime applies to -k 1 only", key="--anytime")
        status, plans, search_stats, reason = _top_k(task, args, ui)
    seconds["search"] = time.perf_counter() - start
    stats.update(search_stats)
    stats["seconds"] = {k: round(v, 4) for k, v in seconds.items()}

    if args.out and plans:
        _write_plans(args.out, plans, task.unit_cost)

    if ui.json:
        out = {"status": status,
               "plans": [{"cost": cost, "actions": list(actions)} for actions, cost in plans],
               "stats": stats}
        if reason:
            out["message"] = reason
        ui.emit_json(out)
    else:
        if plans and not args.anytime:
            ui.plain("\n".join(plan_text(actions, cost, task.unit_cost) for actions, cost in plans))
        ui.info(f"parse {seconds['parse']:.3f} s, ground {seconds['ground']:.3f} s "
                f"({stats['facts']} facts, {stats['operators']} operators"
                + (f", {stats['axioms']} axioms" if stats["axioms"] else "")
                + f"), search {seconds['search']:.3f} s"
                + "".join(f", {key} {stats[key]}" for key in ("expanded", "generated") if key in stats))
    if status == "solved":
        if args.k > 1 and len(plans) < args.k:
            ui.warn(f"only {len(plans)} plan(s) found of the {args.k} asked for: {reason}")
        return ExitCode.OK
    if not ui.json:
        ui.error(reason)
    return ExitCode.NO_SOLUTION


def _single(task, args, limits: SearchLimits, ui):
    search = args.search or "lama"
    name = args.heuristic
    if name is None:
        name = {"lama": "lmcount", "astar": OPTIMAL_HEURISTIC,
                "wastar": OPTIMAL_HEURISTIC}.get(search, "hff")
        if name == OPTIMAL_HEURISTIC and task.has_conditional_effects:
            name = FALLBACK_OPTIMAL_HEURISTIC
    heuristic = _heuristic(name, task)
    if search == "astar" and not heuristic.admissible:
        ui.warn(f"A* with the inadmissible heuristic {name}: the plan may not be optimal")
    start = time.perf_counter()
    result = SEARCHES[search](task, heuristic, limits)
    stats = dict(result.stats)
    stats["search"], stats["heuristic"] = search, name
    reason = stats.pop("reason", None)
    if result.status != "solved":
        word = "unsolvable" if result.status == "unsolvable" else "limit"
        return result.status, [], stats, f"no plan: {word} ({reason})"
    deadline = None if args.time_limit is None else start + args.time_limit
    plan = eliminate_redundant(task, result.plan, deadline)
    stats["eliminated"] = len(result.plan) - len(plan)
    best = ([op.name for op in plan], float(sum(op.cost for op in plan)))
    if args.anytime:
        best = _anytime(task, plan, best, args, deadline, stats, ui)
    return "solved", [best], stats, None


def _heuristic(name: str, task):
    try:
        return HEURISTICS[name](task)
    except InputError as err:
        err.path = err.path or "tampcli plan"
        raise


def _anytime(task, plan, best, args, deadline, stats: dict, ui):
    """Improve `best` until the deadline; each better plan is printed (and written) at once."""
    from tampcli.search.anytime import Improvement, improve

    found = [{"cost": best[1], "weight": None, "seconds": stats["seconds"]}]
    _show(best, args, task, ui)
    left = None if deadline is None else max(deadline - time.perf_counter(), 1e-3)
    if args.heuristic and args.heuristic != "lmcount":
        def make(t):
            return _heuristic(args.heuristic, t)
    else:
        # h_FF on real costs, aware of what conditions need false, as lama's is
        def make(t):
            return HFF(t, negations=True)
    for step in improve(task, plan, make, left):
        if not isinstance(step, Improvement):
            stats["anytime_end"] = step.reason
            break
        best = ([op.name for op in step.plan], step.cost)
        found.append({"cost": step.cost, "weight": step.weight,
                      "seconds": round(stats["seconds"] + step.seconds, 4)})
        _show(best, args, task, ui)
        if not ui.json:
            ui.info(f"anytime: weight {step.weight:g} found cost {_format_cost(step.cost)}")
    stats["anytime"] = found
    return best


def _show(best, args, task, ui) -> None:
    if not ui.json:
        ui.plain(plan_text(best[0], best[1], task.unit_cost))
    if args.out:
        _write_plans(args.out, [best], task.unit_cost)


def _top_k(task, args, ui):
    from tampcli.search.topk import TopK

    if args.search or args.heuristic:
        ui.warn("--search and --heuristic do not apply with -k > 1 (the top-k planner is used)")
    if args.max_expansions is not None:
        raise UsageError("--max-expansions applies to -k 1 only", key="--max-expansions")
    deadline = None if args.time_limit is None else time.perf_counter() + args.time_limit
    topk = TopK(task, loopless=args.loopless, time_limit=args.time_limit)
    plans = []
    for found in topk:
        plans.append(([op.name for op in found.operators], float(found.cost)))
        if len(plans) >= args.k:
            break
    out_of_time = deadline is not None and time.perf_counter() >= deadline
    topk_status = getattr(topk, "status", None)
    limited = topk_status == "limit" or (topk_status is None and out_of_time)
    stats = {"search": "topk", "plans": len(plans)}
    stats.update({k: v for k, v in (getattr(topk, "stats", None) or {}).items()
                  if isinstance(v, (int, float)) and k != "plans"})
    if plans:
        reason = None
        if len(plans) < args.k:
            reason = "time limit reached" if limited else "no other plan exists"
        return "solved", plans, stats, reason
    if limited:
        return "limit", [], stats, "no plan: limit (time limit reached)"
    return "unsolvable", [], stats, "no plan: unsolvable (search space exhausted)"


def _write_plans(out: str, plans, unit_cost: bool) -> None:
    targets = [Path(out)] + [Path(f"{out}.{i}") for i in range(1, len(plans))]
    for path, (actions, cost) in zip(targets, plans, strict=True):
        try:
            path.write_text(plan_text(actions, cost, unit_cost))
        except OSError as err:
            raise InputError(f"cannot write the plan: {err.strerror}", str(path), key="--out") from None

