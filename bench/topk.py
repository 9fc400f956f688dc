"""Ranked plans: tampcli's TopK against K* (kstar-planner), k = 10 and 100.

Both start from the PDDL files: ours parses, grounds and enumerates in this
process; K* (Fast Downward based, C++) is run through its Python API, which
starts its driver (translator + search) in a subprocess. Measured in CPU
seconds (ours: process time; K*: the user + system time of its child
processes), best of --repeat runs, because the machine is shared and wall
time depends on the load; wall seconds are listed too. The cost lists are
compared (they must be equal).
Run: .venv/bin/python bench/topk.py [--repeat N]; writes bench/results/topk.md.
"""

from __future__ import annotations

import argparse
import itertools
import os
import platform
import resource
import time
from pathlib import Path

from kstar_planner import planners

from tampcli.pddl import parser
from tampcli.search.topk import TopK
from tampcli.task.ground import ground

IPC = Path(__file__).resolve().parents[1] / "benchmarks" / "ipc"
OUT = Path(__file__).parent / "results" / "topk.md"
PROBLEMS = [("gripper", "prob01"), ("blocks", "probBLOCKS-4-0"),
            ("logistics00", "probLOGISTICS-4-0"), ("elevators-opt08-strips", "p01")]
TARGET = 3.0


def ours(domain: Path, problem: Path, k: int):
    wall, cpu = time.perf_counter(), time.process_time()
    task = ground(parser.parse_domain_file(domain), parser.parse_problem_file(problem))
    topk = TopK(task)
    costs = [p.cost for p in itertools.islice(topk, k)]
    return time.process_time() - cpu, time.perf_counter() - wall, costs, topk.stats


def children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def kstar(domain: Path, problem: Path, k: int):
    wall, cpu = time.perf_counter(), children_cpu()
    result = planners.plan_topk(domain, problem, k, timeout=600)
    costs = sorted(float(p["cost"]) for p in result["plans"])
    return children_cpu() - cpu, time.perf_counter() - wall, costs


def best_of(fn, repeat: int):
    runs = [fn() for _ in range(repeat)]
    return min(runs, key=lambda r: r[0])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=1)
    args = ap.parse_args()
    ours(IPC / "blocks" / "domain.pddl", IPC / "blocks" / "probBLOCKS-4-0.pddl", 1)  # warm up
    rows = []
    for name, prob in PROBLEMS:
        domain, problem = IPC / name / "domain.pddl", IPC / name / f"{prob}.pddl"
        for k in (10, 100):
            mine, mine_wall, costs, stats = best_of(
                lambda d=domain, p=problem, k=k: ours(d, p, k), args.repeat)
            theirs, theirs_wall, ref = best_of(
                lambda d=domain, p=problem, k=k: kstar(d, p, k), args.repeat)
            ratio = mine / theirs
            rows.append((f"{name}/{prob}", k, mine, theirs, ratio, mine_wall, theirs_wall,
                         costs == ref, f"{costs[0]:g}..{costs[-1]:g}" if costs else "-", stats))
            print(f"{name}/{prob} k={k}: ours {mine:.2f} s CPU ({mine_wall:.2f} wall), "
                  f"K* {theirs:.2f} s CPU ({theirs_wall:.2f} wall), ratio {ratio:.2f}, "
                  f"costs equal: {costs == ref}", flush=True)
    write(rows, args.repeat)


def write(rows, repeat: int) -> None:
    load = os.getloadavg()[0]
    lines = [
        "# Top-k benchmark",
        "",
        f"`bench/topk.py --repeat {repeat}` on {platform.machine()}, {os.cpu_count()} cores, "
        f"load average {load:.1f} when it ran (shared machine: read the ratio). "
        "CPU seconds from the PDDL files to the k-th plan (K*: its subprocesses' CPU "
        "time, translator included); K* = kstar-planner (`plan_topk`, its default LM-cut + "
        f"symmetries), run in the same script. Target: ours / K* <= {TARGET:g} (CPU).",
        "",
        "| problem | k | tampcli CPU (s) | K* CPU (s) | ours / K* | within target "
        "| tampcli wall (s) | K* wall (s) | same costs | costs | states | h evaluations "
        "| phases |",
        "| --- | ---: | ---: | ---: | ---: | --- | ---: | ---: | --- | --- | ---: | ---: | ---: |",
    ]
    for prob, k, mine, theirs, ratio, mine_wall, theirs_wall, same, span, stats in rows:
        lines.append(f"| {prob} | {k} | {mine:.2f} | {theirs:.2f} | {ratio:.2f} | "
                     f"{'yes' if ratio <= TARGET else 'no'} | {mine_wall:.2f} | "
                     f"{theirs_wall:.2f} | {'yes' if same else 'NO'} | "
                     f"{span} | {stats['states']} | {stats['evaluations']} | "
                     f"{stats['phases']} |")
    OUT.write_text("\n".join(lines) + "\n")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
