"""Trajectory optimization speed: a Panda picks a cube and places it over a 30 cm wall.

Figures (written to bench/results/trajopt.md):
- the whole pipeline of one skeleton (final -> keyframes -> path, verify at 10x)
  at T = 10 waypoints per phase: median wall time over N runs (target <= 1 s), and
  collisions found by the 10x check (target 0);
- scaling in T (5, 10, 20, 40);
- where the time goes: inside SLSQP itself vs in our callbacks (collision
  queries, FK and Jacobians, the rest of the row assembly);
- peer, in the same process: the carry phase's path NLP with scipy's default
  finite-difference Jacobian instead of ours (same rows, same start).

Run: .venv/bin/python bench/trajopt.py [--runs 5] [--ts 5,10,20,40] [--no-peer]
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests" / "optimize"))

from helpers import load, ops  # noqa: E402

from tampcli.geometry.collision import CollisionChecker  # noqa: E402
from tampcli.geometry.world import World  # noqa: E402
from tampcli.optimize import nlp as nlp_mod  # noqa: E402
from tampcli.optimize.grips import Kinematics  # noqa: E402
from tampcli.optimize.options import OptimizeOptions  # noqa: E402
from tampcli.optimize.problem import lower  # noqa: E402
from tampcli.optimize.solve import solve  # noqa: E402
from tampcli.optimize.verify import verify  # noqa: E402

OUT = ROOT / "bench" / "results" / "trajopt.md"
PLAN = ("(pick a start)", "(place a goal)")


class Clock:
    """CPU seconds spent in named places (wrappers installed by this script only).

    A name's time is counted once even when calls nest (SLSQP's callbacks call
    the checker); `inside` tells whether SLSQP is running, so the collision time
    of the callbacks is told apart from the one of init, screening and verify.
    """

    def __init__(self):
        self.seconds: dict[str, float] = {}
        self.calls: dict[str, int] = {}
        self.depth: dict[str, int] = {}

    def wrap(self, name, fn):
        def timed(*args, **kwargs):
            if name != "SLSQP incl. callbacks" and self.depth.get("SLSQP incl. callbacks"):
                key = f"{name} in SLSQP"
            else:
                key = name
            outer = self.depth.get(key, 0) == 0
            self.calls[key] = self.calls.get(key, 0) + 1
            self.depth[key] = self.depth.get(key, 0) + 1
            t = time.process_time()
            try:
                return fn(*args, **kwargs)
            finally:
                self.depth[key] -= 1
                if outer:
                    self.seconds[key] = self.seconds.get(key, 0.0) + time.process_time() - t
        return timed


class TimedChecker:
    def __init__(self, checker, clock):
        self._checker = checker
        self.distances = clock.wrap("collision queries", checker.distances)
        self.distances_many = clock.wrap("collision queries", checker.distances_many)

    def __getattr__(self, name):
        return getattr(self._checker, name)


def run_once(scene, modes, world, checker, T: int, clock: Clock | None):
    options = OptimizeOptions(waypoints=T, time_limit=600.0)
    problem = lower(ops(*PLAN), scene, modes, world, options, checker=checker)
    t, w = time.process_time(), time.perf_counter()
    result = solve(problem, "path")
    seconds = (time.process_time() - t, time.perf_counter() - w)
    collisions = None
    if result.solved:
        collisions = sum("collision" in v for v in verify(problem, result, factor=10))
    return seconds, result, collisions


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--ts", default="5,10,20,40")
    ap.add_argument("--no-peer", action="store_true")
    args = ap.parse_args()
    _, _, scene, modes = load("wall")
    lines = ["# Trajectory optimization benchmark", "",
             f"`bench/trajopt.py --runs {args.runs} --ts {args.ts}` on {platform.machine()}, "
             f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f} when it started "
             "(a shared machine: read the ratios, not the absolute seconds).",
             "Skeleton: (pick a start) (place a goal), Panda, cube a carried over a 30 cm "
             "wall (tests/optimize/scenes/wall.scene.toml). Each run solves final -> "
             "keyframes -> path from scratch and runs `verify` at 10x.", ""]
    with World(scene) as world:
        plain = CollisionChecker(world)
        # The headline runs are not instrumented (the wrappers cost time themselves);
        # the split comes from as many runs again with the wrappers in place.
        runs = [run_once(scene, modes, world, plain, 10, None) for _ in range(args.runs)]
        clock = Clock()
        checker = TimedChecker(plain, clock)
        original_eval = nlp_mod._Evaluator.__call__
        original_min = nlp_mod.minimize
        original_frame = Kinematics.frame
        nlp_mod._Evaluator.__call__ = clock.wrap("callbacks (all)", original_eval)
        nlp_mod.minimize = clock.wrap("SLSQP incl. callbacks", original_min)
        Kinematics.frame = clock.wrap("tool FK + Jacobians", original_frame)
        try:
            timed = [run_once(scene, modes, world, checker, 10, clock) for _ in range(args.runs)]
        finally:
            nlp_mod._Evaluator.__call__ = original_eval
            nlp_mod.minimize = original_min
            Kinematics.frame = original_frame
        secs = [r[0][0] for r in runs]
        walls = [r[0][1] for r in runs]
        solved = sum(r[1].solved for r in runs)
        collisions = [r[2] for r in runs if r[2] is not None]
        lines += ["## T = 10 waypoints per phase", "",
                  "| figure | target | measured |", "| --- | --- | ---: |",
                  f"| median CPU time per skeleton (final+keyframes+path+verify), "
                  f"{args.runs} runs | <= 1 s | {statistics.median(secs):.2f} s |",
                  f"| min / max CPU time | | {min(secs):.2f} / {max(secs):.2f} s |",
                  f"| median wall time (shared machine) | | {statistics.median(walls):.2f} s |",
                  f"| solved | {args.runs}/{args.runs} | {solved}/{args.runs} |",
                  f"| collisions found by the 10x check | 0 | {sum(collisions)} |",
                  f"| path cost (sum of squared joint steps) | | "
                  f"{statistics.median(r[1].cost for r in runs if r[1].solved):.3f} rad^2 |",
                  f"| SLSQP iterations (all NLPs of a run), median | | "
                  f"{statistics.median(r[1].iterations for r in runs)} |",
                  f"| NLP solves per run | | {runs[0][1].nlp_solves} |", ""]
        s = clock.seconds
        total = sum(r[0][0] for r in timed)
        inside = s.get("SLSQP incl. callbacks", 0.0)
        cb = s.get("callbacks (all) in SLSQP", 0.0)
        coll_in = s.get("collision queries in SLSQP", 0.0)
        coll_out = s.get("collision queries", 0.0)
        fk = s.get("tool FK + Jacobians in SLSQP", 0.0)
        lines += ["## Where the CPU time goes (T = 10, instrumented runs together)", "",
                  f"{args.runs} more runs with timing wrappers around the callbacks, the "
                  f"collision queries and SLSQP: {total:.2f} s CPU in all.", "",
                  "| part | seconds | share of the total |", "| --- | ---: | ---: |"]
        for name, value in (("SLSQP itself (minimize minus our callbacks)", inside - cb),
                            ("callbacks: collision queries (CollisionChecker.distances_many)",
                             coll_in),
                            ("callbacks: tool FK + Jacobians (numpy chain)", fk),
                            ("callbacks: the rest (rows, Jacobian assembly)",
                             cb - coll_in - fk),
                            ("outside SLSQP: collision queries (IK choice, lazy sampling, "
                             "verify at 10x)", coll_out),
                            ("outside SLSQP: the rest (IK, via points, glue)",
                             total - inside - coll_out)):
            lines.append(f"| {name} | {value:.2f} | {100 * value / total:.0f}% |")
        queries = clock.calls.get("collision queries in SLSQP", 0) + clock.calls.get(
            "collision queries", 0)
        lines += ["", f"Collision queries: {queries / args.runs:.0f} calls per run, "
                  f"{1e3 * (coll_in + coll_out) / max(queries, 1):.2f} ms CPU each (one call = "
                  "the whole robot and the held object against the scene, with gradients, at "
                  "every sample point of one NLP evaluation at once). "
                  "The wrappers that take these figures cost a little themselves: the last "
                  "row can come out slightly negative."]
        lines += ["", "## Scaling in T", "",
                  "| T | CPU time (s) | status | cost | iterations | collisions at 10x |",
                  "| ---: | ---: | --- | ---: | ---: | ---: |"]
        for T in [int(t) for t in args.ts.split(",")]:
            sec, result, col = run_once(scene, modes, world, checker, T, None)
            cost = f"{result.cost:.3f}" if result.cost is not None else "-"
            lines.append(f"| {T} | {sec[0]:.2f} | {result.status} | {cost} | "
                         f"{result.iterations} | {col if col is not None else '-'} |")
        if not args.no_peer:
            lines += ["", *peer(scene, modes, world)]
    OUT.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


def peer(scene, modes, world) -> list[str]:
    """The carry phase's path NLP at T = 5: exact Jacobians vs scipy's finite differences."""
    from scipy.optimize import minimize

    from tampcli.optimize.assemble import walk
    from tampcli.optimize.path import phase_rows_fn, via_points

    T = 5
    options = OptimizeOptions(waypoints=T, time_limit=600.0)
    problem = lower(ops(*PLAN), scene, modes, world, options)
    kf = solve(problem, "keyframes")
    ctx = walk(problem, kf.keyframes, kf.choices, world.start)[1]
    m = problem.motions[1]
    kin = Kinematics(world)
    evaluate, layout = phase_rows_fn(problem, m, ctx.q_a, ctx.q_b, ctx.held, ctx.moved, kin,
                                     problem.checker, T, 0, None, "carry")
    x0 = via_points(problem, ctx.q_a, ctx.q_b, T, 0.05, ctx.moved,
                    np.random.default_rng(0)).reshape(-1)
    bounds = list(zip(np.tile(world.lower, T - 1), np.tile(world.upper, T - 1), strict=True))
    t = time.process_time()
    ours = nlp_mod.solve_nlp(evaluate, layout, x0, bounds, 200, time.perf_counter() + 600)
    t_ours = time.process_time() - t
    ev = nlp_mod._Evaluator(evaluate, layout)
    cons = [{"type": "ineq", "fun": lambda x: ev(x)[4]}]
    t = time.process_time()
    res = minimize(lambda x: ev(x)[0], x0, method="SLSQP", bounds=bounds, constraints=cons,
                   options={"maxiter": 200, "ftol": 1e-6})
    t_fd = time.process_time() - t
    v = nlp_mod.violation_of(np.zeros(0), ev(res.x)[4])[0]
    return ["## Peer: exact Jacobians vs finite differences", "",
            f"Carry phase only, T = {T}, waypoints-only collision rows, same start.", "",
            "| variant | CPU seconds | status | cost | callback evaluations |",
            "| --- | ---: | --- | ---: | ---: |",
            f"| exact Jacobians (ours) | {t_ours:.2f} | {ours.status} | {ours.cost:.4f} | - |",
            f"| scipy 2-point finite differences | {t_fd:.2f} | "
            f"{'solved' if v <= nlp_mod.FEASIBILITY else 'infeasible'} | {res.fun:.4f} | "
            f"{ev.calls} |",
            f"| ratio (finite differences / ours) | {t_fd / max(t_ours, 1e-9):.1f}x | | | |"]


if __name__ == "__main__":
    sys.exit(main())
