"""TAMP benchmark: `tampcli solve` on every geometric problem of problems/.

Per problem, the median of N runs (each a fresh `tampcli solve` process, as a
user runs it): outcome, plan length, cost; wall time of the process; the
pipeline's own stage times (setup = imports, simulator and collision
geometry, paid once per process; solve = parse, ground, search and branch and
bound); skeletons generated / optimized / pruned / infeasible; NLP solves and
SLSQP iterations. Each run's solution.json is then checked by `tampcli
validate` (symbolic and geometric).

Targets (issue 6) are PDDLStream's adaptive algorithm on its own versions of
five of these problems, run on this machine: 2D tight <= 0.58 s, 2D blocked
<= 1.02 s, 2D cook <= 2.53 s, 2D dual <= 2.27 s, arm kitchen clean+cook
(10 actions) <= 0.70 s. PDDLStream's times are its planner's (after its
imports), so ours are compared by the solve time, setup excluded; the
process wall time is reported too.

Run: .venv/bin/python bench/tamp.py [--runs 3] [--time-limit 300] [--only SUBSTRING]
writes bench/results/tamp.md.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
OUT = Path(__file__).parent / "results" / "tamp.md"

# problem -> (PDDLStream's name, its time on this machine, s)
TARGETS = {
    "planar-tamp/p01": ("2D tight", 0.58),
    "planar-tamp/p02": ("2D blocked", 1.02),
    "planar-tamp/p03": ("2D cook", 2.53),
    "planar-tamp/p04": ("2D dual", 2.27),
    "arm-kitchen/p01": ("arm kitchen clean+cook", 0.70),
}


# The sets written blind have their own bench (bench/robustness.py).
BLIND_SETS = ("robust", "blind")


def problems(only: str | None) -> list[Path]:
    found = sorted(p for p in (ROOT / "problems").glob("*/p*.pddl")
                   if p.with_name(p.stem + ".scene.toml").exists()
                   and not p.parent.name.startswith(BLIND_SETS))
    return [p for p in found if only is None or only in _key(p)]


def _key(problem: Path) -> str:
    return f"{problem.parent.name}/{problem.stem}"


def _domain(problem: Path) -> Path:
    return ROOT / "domains" / problem.parent.name / "domain.pddl"


def run_once(problem: Path, time_limit: float, seed: int) -> dict:
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1", MKL_NUM_THREADS="1")
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "solution.json"
        start = time.perf_counter()
        proc = subprocess.run([sys.executable, "-m", "tampcli", "solve", str(_domain(problem)),
                               str(problem), "--quiet", "--time-limit", f"{time_limit:g}",
                               "--seed", str(seed), "--out", str(out)],
                              capture_output=True, text=True, cwd=ROOT, env=env)
        wall = time.perf_counter() - start
        if not out.exists():
            return {"status": f"exit {proc.returncode}", "wall": wall, "valid": False,
                    "error": proc.stderr.strip().splitlines()[-1:]}
        solution = json.loads(out.read_text())
        valid = None
        if solution["status"] == "solved":
            check = subprocess.run([sys.executable, "-m", "tampcli", "validate",
                                    str(_domain(problem)), str(problem), str(out)],
                                   capture_output=True, text=True, cwd=ROOT, env=env)
            valid = check.returncode == 0
    stats = solution.get("stats", {})
    seconds = stats.get("seconds", {})
    setup = seconds.get("setup", 0.0)
    return {
        "status": solution["status"], "wall": wall, "valid": valid,
        "actions": len(solution.get("plan") or []), "cost": solution.get("cost"),
        "total": seconds.get("total"), "setup": setup,
        "solve": (seconds.get("total") or 0.0) - setup,
        "optimize": seconds.get("optimize", 0.0), "search": seconds.get("search", 0.0),
        "first": _first_solution(stats, seconds),
        "generated": stats.get("skeletons_generated", 0),
        "optimized": stats.get("skeletons_optimized", 0),
        "pruned": stats.get("skeletons_pruned", 0),
        "infeasible": stats.get("skeletons_infeasible", 0),
        "nlp": stats.get("nlp_solves", 0), "iterations": stats.get("nlp_iterations", 0),
        "stop": stats.get("stop"), "reason": solution.get("reason"),
    }


def _first_solution(stats: dict, seconds: dict) -> float | None:
    """Seconds from the start of the solve (setup excluded) to the first solution."""
    first = stats.get("first_solution_seconds")
    if first is None:
        return None
    return sum(seconds.get(k, 0.0) for k in ("parse", "ground", "scene")) + first


def _median_run(runs: list[dict]) -> dict:
    """The run of median solve time (its other figures belong to the same run)."""
    ordered = sorted(runs, key=lambda r: r.get("solve", r["wall"]))
    return ordered[len(ordered) // 2]


def _fmt(value, digits=2) -> str:
    return "-" if value is None else f"{value:.{digits}f}"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--time-limit", type=float, default=300.0)
    ap.add_argument("--only", help="only problems whose domain/pNN contains this")
    args = ap.parse_args(argv)
    load_start = os.getloadavg()[0]
    began = time.perf_counter()
    rows = []
    for problem in problems(args.only):
        runs = [run_once(problem, args.time_limit, seed=0) for _ in range(args.runs)]
        rows.append((_key(problem), runs))
        med = _median_run(runs)
        print(f"{_key(problem)}: {med['status']} {med.get('actions')} actions, solve "
              f"{_fmt(med.get('solve'))} s (wall {med['wall']:.2f} s)", flush=True)
    lines = [
        "# TAMP benchmark: `tampcli solve` on problems/",
        "",
        f"`bench/tamp.py --runs {args.runs} --time-limit {args.time_limit:g}"
        f"{f' --only {args.only}' if args.only else ''}` on {platform.machine()}, "
        f"{os.cpu_count()} cores, Python {platform.python_version()}; load average "
        f"{load_start:.1f} at the start, {os.getloadavg()[0]:.1f} at the end; "
        f"{time.perf_counter() - began:.0f} s in all. Each run is a fresh process with seed 0; "
        "the row shows the run of median solve time. *solve* = the pipeline's total minus "
        "*setup* (imports of numpy/scipy/pybullet/FCL, the simulator, the collision "
        "geometry: paid once per process); *first solution* = solve time until branch and "
        "bound had its first solution (the rest proves or improves it); *wall* = the whole `tampcli solve` process. "
        "*valid*: `tampcli validate` accepts the solution.json of every run.",
        "",
        "| problem | outcome | actions | cost | solve s (min-max) | first solution s | setup s "
        "| wall s | optimize s | skeletons gen / opt / pruned / infeasible | NLP solves | "
        "SLSQP iterations | valid |",
        "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: | ---: | --- |",
    ]
    for key, runs in rows:
        med = _median_run(runs)
        solves = [r["solve"] for r in runs if r.get("solve") is not None]
        spread = f" ({min(solves):.2f}-{max(solves):.2f})" if len(solves) > 1 else ""
        valid = "yes" if all(r["valid"] for r in runs) else (
            "no" if any(r["valid"] is False for r in runs) else "-")
        lines.append(
            f"| {key} | {med['status']} | {med.get('actions', '-')} | "
            f"{_fmt(med.get('cost'), 3)} | {_fmt(med.get('solve'))}{spread} | "
            f"{_fmt(med.get('first'))} | "
            f"{_fmt(med.get('setup'))} | {med['wall']:.2f} | {_fmt(med.get('optimize'))} | "
            f"{med.get('generated', 0)} / {med.get('optimized', 0)} / {med.get('pruned', 0)} / "
            f"{med.get('infeasible', 0)} | {med.get('nlp', 0)} | {med.get('iterations', 0)} | "
            f"{valid} |")
    lines += ["", "## Against PDDLStream (adaptive), same machine", "",
              "| problem | PDDLStream | its time s | ours: solve s | ours / it | ours: first "
              "solution s | ours: wall s | target met |",
              "| --- | --- | ---: | ---: | ---: | ---: | ---: | --- |"]
    for key, runs in rows:
        if key not in TARGETS:
            continue
        name, theirs = TARGETS[key]
        med = _median_run(runs)
        solve = med.get("solve")
        ratio = f"{solve / theirs:.1f}x" if solve is not None else "-"
        met = "yes" if med["status"] == "solved" and solve is not None and solve <= theirs \
            else "no"
        lines.append(f"| {key} | {name} | {theirs:.2f} | {_fmt(solve)} | {ratio} | "
                     f"{_fmt(med.get('first'))} | {med['wall']:.2f} | {met} |")
    slower = [(key, _median_run(runs)) for key, runs in rows if key in TARGETS
              and not (_median_run(runs).get("solve") or 1e9) <= TARGETS[key][1]]
    if slower:
        lines += ["", "Where the time goes where we are slower (the median run):", ""]
        for key, med in slower:
            name, theirs = TARGETS[key]
            rest = med["solve"] - med["optimize"]
            first = med.get("first")
            lines.append(
                f"- {key} ({name}): {med['solve']:.2f} s against {theirs:.2f} s "
                f"({med['solve'] / theirs:.1f}x). The first solution came after "
                f"{_fmt(first)} s; then branch and bound drew {med['generated']} skeletons in "
                f"all: {med['optimized']} optimized (of which "
                f"{med['pruned'] - (med['generated'] - med['optimized'])} pruned at their "
                f"keyframe bound and {med['infeasible']} infeasible), "
                f"{med['generated'] - med['optimized']} pruned without an NLP (a twin of an "
                f"optimized skeleton, or an infeasible prefix); "
                f"{med['optimize']:.2f} s in {med['nlp']} NLP solves ({med['iterations']} "
                f"SLSQP iterations), {rest:.2f} s in parsing, grounding, the scene and the "
                "search. PDDLStream stops at its first solution; we stop when no skeleton left "
                "can beat the incumbent or at the skeleton limit (-k 20).")
    unsolved = [(key, _median_run(runs)) for key, runs in rows
                if _median_run(runs)["status"] != "solved"]
    if unsolved:
        lines += ["", "## Not solved", ""]
        for key, med in unsolved:
            lines.append(f"- {key}: {med['status']} ({med.get('stop')}): {med.get('reason')}")
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
