"""Before and after a refactoring: the same solves on two commits, side by side.

Each library problem is solved by `python -m tampcli solve --json` from a
checkout of the old commit and from this tree, alternating old and new for
each run, so that the machine's load falls on both alike. Reported per side:
the objective (the same skeleton and trajectory are expected: a refactoring
keeps behaviour), the skeletons drawn, NLP solves, and the CPU seconds of the
child process (less sensitive to other jobs than wall time), median of the
runs; the ratio new/old of the median CPU seconds.

    .venv/bin/python bench/redesign.py OLD_CHECKOUT [--new NEW_CHECKOUT] [--runs 3]

OLD_CHECKOUT (and NEW_CHECKOUT, default this tree) are work trees of the two
commits (`git worktree add --detach DIR COMMIT`); both sides run with this
tree's interpreter and libraries.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
OUT = ROOT / "bench" / "results" / "redesign.md"
PROBLEMS = ["planar-push/p01", "planar-push/p02", "planar-tamp/p01", "planar-tamp/p02",
            "planar-tamp/p03", "arm-pick-place/p01", "arm-pick-place/p02",
            "arm-pick-place/p04", "arm-hanoi/p01"]


def solve(tree: Path, key: str, limit: float) -> dict:
    domain, stem = key.split("/")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.perf_counter()
    run = subprocess.run(
        [sys.executable, "-m", "tampcli", "solve", f"domains/{domain}/domain.pddl",
         f"problems/{domain}/{stem}.pddl", "--json", "--time-limit", str(limit)],
        cwd=tree, capture_output=True, text=True, timeout=limit + 120,
        env=dict(os.environ, OPENBLAS_NUM_THREADS="1", PYTHONPATH=str(tree)))
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    try:
        out = json.loads(run.stdout)
    except json.JSONDecodeError:
        out = {"status": "error", "stats": {}}
    stats = out.get("stats") or {}
    return {"cpu": cpu, "wall": time.perf_counter() - started, "status": out.get("status"),
            "objective": out.get("objective"), "plan": tuple(out.get("plan") or ()),
            "skeletons": stats.get("skeletons_generated"), "nlp": stats.get("nlp_solves")}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("old", type=Path, help="a work tree of the old commit")
    ap.add_argument("--new", type=Path, default=ROOT, help="a work tree of the new commit")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--time-limit", type=float, default=300.0)
    ap.add_argument("--only", default="")
    args = ap.parse_args()
    old_commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=args.old,
                                capture_output=True, text=True).stdout.strip()
    new_commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=args.new,
                                capture_output=True, text=True).stdout.strip()
    rows = []
    for key in PROBLEMS:
        if args.only not in key:
            continue
        runs = {"old": [], "new": []}
        for _ in range(args.runs):
            runs["old"].append(solve(args.old, key, args.time_limit))
            runs["new"].append(solve(args.new, key, args.time_limit))
        rows.append((key, runs))
        old_cpu = statistics.median(r["cpu"] for r in runs["old"])
        new_cpu = statistics.median(r["cpu"] for r in runs["new"])
        print(f"{key}: cpu old {old_cpu:.2f} s, new {new_cpu:.2f} s", flush=True)
    write(rows, old_commit, new_commit, args.runs)
    return 0


def write(rows, old_commit: str, new_commit: str, runs: int) -> None:
    def fmt(v, spec=".4f"):
        return "-" if v is None else format(v, spec)

    lines = [
        f"# Before and after: {old_commit} (old) vs {new_commit} (new)",
        "",
        f"`bench/redesign.py`, {time.strftime('%Y-%m-%d')}, Python "
        f"{platform.python_version()}, {os.cpu_count()} cores, load average "
        f"{os.getloadavg()[0]:.1f} at the end (other jobs ran: CPU seconds of the solve "
        f"process are compared, median of {runs} alternating runs).",
        "",
        "| problem | objective old | objective new | same plan | skeletons old / new "
        "| NLPs old / new | CPU s old | CPU s new | new / old |",
        "| --- | ---: | ---: | --- | --- | --- | ---: | ---: | ---: |",
    ]
    ratios = []
    for key, runs in rows:
        old, new = runs["old"][0], runs["new"][0]
        old_cpu = statistics.median(r["cpu"] for r in runs["old"])
        new_cpu = statistics.median(r["cpu"] for r in runs["new"])
        ratio = new_cpu / old_cpu if old_cpu else float("nan")
        ratios.append(ratio)
        lines.append(f"| {key} | {fmt(old['objective'])} | {fmt(new['objective'])} | "
                     f"{'yes' if old['plan'] == new['plan'] else 'no'} | "
                     f"{old['skeletons']} / {new['skeletons']} | {old['nlp']} / {new['nlp']} | "
                     f"{old_cpu:.2f} | {new_cpu:.2f} | {ratio:.2f} |")
    if ratios:
        lines += ["", f"Median ratio new / old: {statistics.median(ratios):.2f}."]
    OUT.write_text("\n".join(lines) + "\n")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    raise SystemExit(main())
