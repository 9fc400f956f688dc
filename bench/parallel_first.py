"""`solve --jobs`: time to the first answer and to the end, serial against two jobs, on
problems whose search is long (skeletons that fail and teach the ones after them).

Each problem is solved by fresh `tampcli solve --json` processes, `--jobs 1` then
`--jobs 2`, `--time-limit` as given; per run: outcome, actions, objective, the
first answer (`first_solution_since_start`), wall time, skeletons drawn, stop.

    .venv/bin/python bench/parallel_first.py [--limit S] [--only SUBSTRING]

writes bench/results/parallel-first.md.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
OUT = Path(__file__).parent / "results" / "parallel-first.md"

# (folder, stem): library problems have their domain under domains/, blind ones beside.
PROBLEMS = (("blind27", "p04"), ("blind18", "p04"), ("blind28", "p04"), ("blind29", "p03"),
            ("blind27", "p05"), ("blind29", "p02"), ("blind31", "p06"), ("arm-sort", "p01"),
            ("arm-kitchen", "p01"))


def files(folder: str, stem: str) -> tuple[Path, Path]:
    own = ROOT / "problems" / folder / stem
    if own.is_dir():
        return own / "domain.pddl", own / f"{stem}.pddl"
    return ROOT / "domains" / folder / "domain.pddl", ROOT / "problems" / folder / f"{stem}.pddl"


def solve(folder: str, stem: str, jobs: int, limit: float) -> dict:
    domain, problem = files(folder, stem)
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "tampcli", "solve", str(domain), str(problem),
                           "--json", "--quiet", "--time-limit", str(limit), "--jobs", str(jobs)],
                          capture_output=True, text=True, env=env, cwd=ROOT)
    wall = time.perf_counter() - start
    try:
        data = json.loads(proc.stdout)
    except json.JSONDecodeError:
        return {"status": f"exit {proc.returncode}", "wall": wall}
    stats = data.get("stats") or {}
    return {"status": data["status"], "actions": len(data.get("plan") or []),
            "objective": data.get("objective"), "first": stats.get("first_solution_since_start"),
            "wall": wall, "skeletons": stats.get("skeletons_generated"),
            "stop": stats.get("stop")}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--limit", type=float, default=60.0, help="seconds per solve")
    parser.add_argument("--only", default="", help="the problems whose id contains this")
    args = parser.parse_args()
    started, load = time.time(), os.getloadavg()
    rows = []
    for folder, stem in PROBLEMS:
        if args.only not in f"{folder}/{stem}":
            continue
        for jobs in (1, 2):
            row = solve(folder, stem, jobs, args.limit)
            rows.append((f"{folder}/{stem}", jobs, row))
            print(f"{folder}/{stem} -j {jobs}: {row}", flush=True)

    def num(value, fmt):
        return "-" if value is None else format(value, fmt)

    lines = ["# `solve --jobs`: the first answer and the end, serial against two jobs", "",
             f"`bench/parallel_first.py --limit {args.limit:g}` on {platform.machine()}, "
             f"{os.cpu_count()} cores, Python {platform.python_version()}; load average "
             f"{load[0]:.2f} at the start, {os.getloadavg()[0]:.2f} at the end; "
             f"{time.time() - started:.0f} s in all. One fresh process per row, `--jobs 1` "
             "then `--jobs 2`. *first s*: the first verified answer, from the process start; "
             "*wall s*: the whole process.", "",
             "| problem | jobs | outcome | actions | objective | first s | wall s | skeletons "
             "| stop |", "| --- | ---: | --- | ---: | ---: | ---: | ---: | ---: | --- |"]
    for key, jobs, r in rows:
        lines.append(f"| {key} | {jobs} | {r['status']} | {r.get('actions', '-')} | "
                     f"{num(r.get('objective'), '.4f')} | {num(r.get('first'), '.2f')} | "
                     f"{r['wall']:.1f} | {r.get('skeletons', '-')} | {r.get('stop', '-')} |")
    out = OUT if not args.only else OUT.with_name(f"parallel-first-{args.only.replace('/', '-')}.md")
    out.write_text("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
