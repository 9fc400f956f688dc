"""SLSQP against Ipopt on the path stage of library problems, at several waypoint counts.

Per problem: its plan is found once by `tampcli solve --first --nlp slsqp` (in
process); per waypoint count T the plan is lowered and its keyframes solved once
(SLSQP, as every backend's path stage starts from them); then the path stage
(one NLP per motion, lazy points between waypoints, the margin schedule, `verify`
at 10x) is solved from those keyframes by each backend in turn, alternating, so a
change in the machine's load falls on both. Figures: CPU seconds of the path
stage, its status and cost (sum of squared joint steps), NLP solves and solver
iterations, and the variables of one motion's NLP ((T - 1) x joints).

Run: .venv/bin/python bench/ipopt.py [--runs 2] [--ts 8,14,20,40] [--only SUBSTRING]
writes bench/results/ipopt.md (needs cyipopt: pip install -e '.[ipopt]').
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import platform
import statistics
import sys
import time
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from tampcli.bnb import BnBOptions  # noqa: E402
from tampcli.geometry.collision import CollisionChecker  # noqa: E402
from tampcli.geometry.world import World  # noqa: E402
from tampcli.optimize.backends import IPOPT_FROM  # noqa: E402
from tampcli.optimize.options import OptimizeOptions  # noqa: E402
from tampcli.optimize.problem import lower  # noqa: E402
from tampcli.optimize.solve import solve  # noqa: E402
from tampcli.pipeline import InputPaths, SolveOptions, Timers, read_inputs  # noqa: E402
from tampcli.pipeline import solve as solve_pipeline  # noqa: E402

OUT = ROOT / "bench" / "results" / "ipopt.md"
PROBLEMS = ("planar-tamp/p01", "arm-pick-place/p02", "arm-kitchen/p01")
BACKENDS = ("slsqp", "ipopt")
STAGE_LIMIT = 120.0  # s per path stage: a backend that needs more is reported at its limit


@dataclasses.dataclass(frozen=True)
class Op:
    """A ground action as lower() takes it, from a plan line."""

    name: str
    action: str
    args: tuple[str, ...]


def plan_ops(plan) -> list[Op]:
    return [Op(line, *_split(line)) for line in plan]


def _split(line: str):
    head, *args = line.strip("()").split()
    return head, tuple(args)


def paths_of(key: str) -> InputPaths:
    domain, name = key.split("/")
    return InputPaths(str(ROOT / "domains" / domain / "domain.pddl"),
                      str(ROOT / "problems" / domain / f"{name}.pddl"))


def find_plan(key: str) -> tuple[str, ...]:
    options = SolveOptions(BnBOptions(first=True, time_limit=120.0),
                           OptimizeOptions(nlp="slsqp"))
    sol = solve_pipeline(paths_of(key), options)
    if not sol.solved:
        raise SystemExit(f"{key}: no plan ({sol.status}: {sol.reason})")
    return sol.plan


def measure(key: str, plan, ts, runs: int) -> list[dict]:
    inputs = read_inputs(paths_of(key), Timers())
    rows = []
    with World(inputs.scene) as world:
        checker = CollisionChecker(world)
        for T in ts:
            options = OptimizeOptions(waypoints=T, time_limit=STAGE_LIMIT, nlp="slsqp")
            problem = lower(plan_ops(plan), inputs.scene, inputs.modes, world, options,
                            domain=inputs.domain, checker=checker)
            keyframes = solve(problem, "keyframes")
            if not keyframes.solved:
                raise SystemExit(f"{key} T={T}: keyframes {keyframes.status}")
            for run in range(runs):
                order = BACKENDS if run % 2 == 0 else BACKENDS[::-1]
                for name in order:
                    opts = dataclasses.replace(options, nlp=name)
                    t = time.process_time()
                    result = solve(problem, "path", warm=keyframes, options=opts)
                    rows.append({"key": key, "T": T, "nlp": name, "cpu": time.process_time() - t,
                                 "status": result.status, "cost": result.cost,
                                 "solves": result.nlp_solves, "iterations": result.iterations,
                                 "variables": (T - 1) * problem.n})
                    print(f"{key} T={T} {name}: {rows[-1]['cpu']:.2f} s {result.status} "
                          f"cost {result.cost}", flush=True)
    return rows


def table(rows: list[dict]) -> list[str]:
    lines = ["| problem | T | variables per motion | SLSQP CPU s (runs) | Ipopt CPU s (runs) | "
             "SLSQP / Ipopt | SLSQP status, cost | Ipopt status, cost | NLP solves S / I | "
             "iterations S / I |",
             "| --- | ---: | ---: | --- | --- | ---: | --- | --- | --- | --- |"]
    groups: dict[tuple, dict[str, list[dict]]] = {}
    for r in rows:
        groups.setdefault((r["key"], r["T"]), {}).setdefault(r["nlp"], []).append(r)
    for (key, T), by in groups.items():
        s, i = by["slsqp"], by["ipopt"]
        ms, mi = (statistics.median(r["cpu"] for r in g) for g in (s, i))
        lines.append(
            f"| {key} | {T} | {s[0]['variables']} | {ms:.2f} ({_runs(s)}) | "
            f"{mi:.2f} ({_runs(i)}) | {ms / max(mi, 1e-9):.1f}x | {_outcome(s)} | "
            f"{_outcome(i)} | {s[0]['solves']} / {i[0]['solves']} | "
            f"{s[0]['iterations']} / {i[0]['iterations']} |")
    return lines


def _runs(group) -> str:
    return ", ".join(f"{r['cpu']:.2f}" for r in group)


def _outcome(group) -> str:
    statuses = sorted({r["status"] for r in group})
    costs = sorted({round(r["cost"], 4) for r in group if r["cost"] is not None})
    return "/".join(statuses) + (", " + "/".join(f"{c:.4f}" for c in costs) if costs else "")


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=2)
    ap.add_argument("--ts", default="8,14,20,40")
    ap.add_argument("--only", default=None)
    args = ap.parse_args()
    ts = [int(t) for t in args.ts.split(",")]
    start, load = time.perf_counter(), os.getloadavg()[0]
    rows = []
    for key in PROBLEMS:
        if args.only and args.only not in key:
            continue
        rows += measure(key, find_plan(key), ts, args.runs)
    lines = ["# Path stage: SLSQP against Ipopt", "",
             f"`bench/ipopt.py --runs {args.runs} --ts {args.ts}` on {platform.machine()}, "
             f"{os.cpu_count()} cores, OPENBLAS_NUM_THREADS={os.environ['OPENBLAS_NUM_THREADS']}, "
             f"load average {load:.1f} at the start, {os.getloadavg()[0]:.1f} at the end, "
             f"{time.perf_counter() - start:.0f} s in all (a shared machine: read the ratios).",
             "Each row: one plan, its keyframes solved once, then the path stage from them by "
             "each backend, alternating; CPU seconds of the path stage (every motion's NLPs, "
             "the lazy rounds, `verify` at 10x), median of the runs.", "", *table(rows), "",
             ("`--nlp auto` (the default) solves every path NLP with SLSQP"
              if IPOPT_FROM is None else
              f"`--nlp auto` (the default) solves a path NLP of at least {IPOPT_FROM} "
              "variables with Ipopt where cyipopt is installed, with SLSQP otherwise")
             + " (tampcli/optimize/backends.py: IPOPT_FROM)."]
    OUT.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
