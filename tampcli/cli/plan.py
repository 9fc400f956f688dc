"""`tampcli plan DOMAIN PROBLEM`: symbolic planning, plans in IPC format.

Defaults: with -k 1, greedy best-first search with h_FF (satisficing: fast,
not necessarily cheapest); `--search astar` alone uses LM-cut (optimal), or
h_max when the task has conditional effects. With -k > 1 the top-k planner
returns the K cheapest plans and --search/--heuristic do not apply.
"""

from __future__ import annotations

import time
from pathlib import Path

from tampcli.errors import ExitCode, InputError, UsageError
from tampcli.pddl.load import load
from tampcli.search.heuristics import HEURISTICS
from tampcli.search.searches import SEARCHES, SearchLimits
from tampcli.task.ground import ground

OPTIMAL_HEURISTIC = "lmcut"
FALLBACK_OPTIMAL_HEURISTIC = "hmax"


def add_parser(p) -> None:
    p.add_argument("domain", help="PDDL domain file")
    p.add_argument("problem", help="PDDL problem file")
    p.add_argument("-k", type=int, default=1, metavar="K", help="number of plans, cheapest first (default 1)")
    p.add_argument("--search", choices=sorted(SEARCHES), default=None,
                   help="search algorithm (default gbfs; astar for optimal plans)")
    p.add_argument("--heuristic", choices=sorted(HEURISTICS), default=None,
                   help="heuristic (default hff; lmcut with astar/wastar)")
    p.add_argument("--weight", type=float, default=2.0, help="weight of h in wastar (default 2)")
    p.add_argument("--time-limit", type=float, default=None, metavar="S",
                   help="seconds for the search (default none)")
    p.add_argument("--max-expansions", type=int, default=None, metavar="N",
                   help="stop after N expansions (k = 1 only)")
    p.add_argument("--out", default=None, metavar="FILE",
                   help="write the best plan to FILE (with -k: the others to FILE.1, FILE.2, ...)")
    p.add_argument("--loopless", action="store_true",
                   help="with -k: only plans that never revisit a state")


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
    task = ground(loaded.domain, loaded.problem)
    seconds["ground"] = time.perf_counter() - start
    stats: dict = {"facts": len(task.facts), "operators": len(task.operators),
                   "axioms": len(task.axioms)}

    start = time.perf_counter()
    if args.k == 1:
        status, plans, search_stats, reason = _single(task, args, limits, ui)
    else:
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
        if plans:
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
    search = args.search or "gbfs"
    name = args.heuristic
    if name is None:
        name = OPTIMAL_HEURISTIC if search in ("astar", "wastar") else "hff"
        if name == OPTIMAL_HEURISTIC and task.has_conditional_effects:
            name = FALLBACK_OPTIMAL_HEURISTIC
    try:
        heuristic = HEURISTICS[name](task)
    except InputError as err:
        err.path = err.path or "tampcli plan"
        raise
    if search == "astar" and not heuristic.admissible:
        ui.warn(f"A* with the inadmissible heuristic {name}: the plan may not be optimal")
    result = SEARCHES[search](task, heuristic, limits)
    stats = dict(result.stats)
    stats["search"], stats["heuristic"] = search, name
    reason = stats.pop("reason", None)
    if result.status == "solved":
        return "solved", [([op.name for op in result.plan], result.cost)], stats, None
    word = "unsolvable" if result.status == "unsolvable" else "limit"
    return result.status, [], stats, f"no plan: {word} ({reason})"


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

