"""Batch throughput: the IPC main suite, symbolic, with 1 job and with 2 jobs.

Target: 2 jobs give >= 1.8x the throughput (problems per second) of 1 job.
Both configurations run the same problems in the same script, alternating
(1, 2, 1, 2, ...), and each keeps its best repetition, so a passing load from
other users hurts both alike; the load average is recorded with each run.
The ceiling column is what a perfect 2-way split of the 1-job work could
reach given the longest single problem (the last one cannot be shared).

Run: .venv/bin/python bench/batch.py [--per-domain 6] [--reps 2]; writes
bench/results/batch.md.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
IPC = ROOT / "benchmarks" / "ipc"
OUT = Path(__file__).parent / "results" / "batch.md"
SUITE = ("gripper", "blocks", "logistics00", "miconic", "driverlog", "rovers", "satellite",
         "visitall-opt11-strips", "elevators-opt08-strips", "miconic-fulladl")

sys.path.insert(0, str(ROOT))
from tampcli.batch.discover import discover  # noqa: E402


def suite(per_domain: int) -> list[str]:
    return [job.problem for name in SUITE for job in discover([str(IPC / name)])[:per_domain]]


def run_batch(files: list[str], jobs: int, time_limit: float) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "results.jsonl"
        load_before = os.getloadavg()[0]
        start = time.monotonic()
        proc = subprocess.run([sys.executable, "-m", "tampcli", "batch", *files, "--symbolic",
                               "--jobs", str(jobs), "--time-limit", f"{time_limit:g}",
                               "--out", str(out), "--json"],
                              capture_output=True, text=True, cwd=ROOT,
                              env=dict(os.environ, OPENBLAS_NUM_THREADS="1",
                                       OMP_NUM_THREADS="1"))
        wall = time.monotonic() - start
        if proc.returncode != 0:
            raise SystemExit(f"batch failed ({proc.returncode}):\n{proc.stderr}")
        records = [json.loads(line) for line in out.read_text().splitlines()]
    summary = json.loads(proc.stdout)
    walls = [r["wall_s"] for r in records]
    return {"jobs": jobs, "wall": wall, "throughput": len(records) / wall,
            "counts": summary["counts"], "sum_problem_s": sum(walls),
            "sum_cpu_s": sum(r["cpu_s"] or 0 for r in records),
            "occupancy": sum(walls) / (jobs * wall),
            "longest_s": max(walls), "median_problem_s": statistics.median(walls),
            "load_before": load_before, "load_after": os.getloadavg()[0],
            "statuses": {r["problem"]: r["status"] for r in records},
            "walls": {r["problem"]: r["wall_s"] for r in records}}


def machine_ceiling(problem: str, rounds: int = 3) -> dict:
    """The peer: the same `tampcli plan` child, alone vs two copies at once.

    Two copies share nothing but the hardware (cores, caches, memory), so what
    they gain over one is the most any 2-job batch of such children can reach
    on this machine. Alone and paired runs alternate, each keeps its best.
    """
    domain = str(Path(problem).with_name("domain.pddl"))
    cmd = [sys.executable, "-m", "tampcli", "plan", domain, problem, "--quiet"]
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")

    def wall(parallel: int) -> float:
        start = time.monotonic()
        procs = [subprocess.Popen(cmd, cwd=ROOT, env=env, stdout=subprocess.DEVNULL)
                 for _ in range(parallel)]
        for proc in procs:
            proc.wait()
        return time.monotonic() - start

    alone, paired = [], []
    for _ in range(rounds):
        alone.append(wall(1))
        paired.append(wall(2))
    one, two = min(alone), min(paired)
    return {"problem": problem, "one": one, "two": two, "ratio": 2 * one / two}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--per-domain", type=int, default=6)
    ap.add_argument("--reps", type=int, default=2)
    ap.add_argument("--time-limit", type=float, default=60)
    args = ap.parse_args()
    files = suite(args.per_domain)
    runs: dict[int, list[dict]] = {1: [], 2: []}
    for rep in range(args.reps):
        for jobs in (1, 2):
            run = run_batch(files, jobs, args.time_limit)
            runs[jobs].append(run)
            print(f"rep {rep + 1} jobs {jobs}: {run['wall']:.1f} s, "
                  f"{run['throughput']:.2f} problems/s, load {run['load_before']:.1f}",
                  file=sys.stderr)
    # The peer problem: the one whose 1-job time is nearest 3 s (long enough to time).
    walls = runs[1][0]["walls"]
    peer = machine_ceiling(min(walls, key=lambda p: abs(walls[p] - 3.0)))
    print(f"machine: 2 processes give {peer['ratio']:.2f}x of 1", file=sys.stderr)
    best = {jobs: min(rs, key=lambda r: r["wall"]) for jobs, rs in runs.items()}
    speedup = best[2]["throughput"] / best[1]["throughput"]
    one = best[1]
    ceiling = one["sum_problem_s"] / max(one["sum_problem_s"] / 2, one["longest_s"])
    same = best[1]["statuses"] == best[2]["statuses"]
    write(files, runs, best, speedup, ceiling, same, args, peer)
    print(f"speedup {speedup:.2f}x (target >= 1.8, ceiling {ceiling:.2f}); wrote {OUT}")


def write(files, runs, best, speedup, ceiling, same, args, peer) -> None:
    counts = best[1]["counts"]
    lines = [
        "# Batch benchmark",
        "",
        f"`bench/batch.py --per-domain {args.per_domain} --reps {args.reps}` on "
        f"{platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}. "
        "The machine is shared with other engineers: the load average (1 min) before each "
        "run is in the table; each configuration keeps its best repetition.",
        "",
        f"Suite: the first {args.per_domain} problems (natural order) of "
        f"{', '.join(SUITE)} — {len(files)} problems, `tampcli batch --symbolic "
        f"--time-limit {args.time_limit:g}` (each problem: a fresh `python -m tampcli plan` "
        "child, gbfs + hff). Outcome with 1 job: "
        + ", ".join(f"{k} {v}" for k, v in counts.items() if v) + ".",
        "",
        "| jobs | rep | batch wall s | problems/s | sum of problem walls s | sum of problem CPU s "
        "| slots busy | median problem s | longest s | load before | load after |",
        "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |",
    ]
    for jobs, rs in runs.items():
        for i, r in enumerate(rs, 1):
            mark = " (best)" if r is best[jobs] else ""
            lines.append(f"| {jobs} | {i}{mark} | {r['wall']:.1f} | {r['throughput']:.3f} | "
                         f"{r['sum_problem_s']:.1f} | {r['sum_cpu_s']:.1f} | "
                         f"{100 * r['occupancy']:.0f}% | {r['median_problem_s']:.2f} | "
                         f"{r['longest_s']:.1f} | {r['load_before']:.1f} | "
                         f"{r['load_after']:.1f} |")
    verdict = "met" if speedup >= 1.8 else "NOT met"
    medians = {jobs: statistics.median(r["throughput"] for r in rs) for jobs, rs in runs.items()}
    lines += [
        "",
        f"Median repetition of each: {medians[2] / medians[1]:.2f}x. The machine's speed "
        "drifts between runs (the same 1-job run varies by several percent in CPU time, and "
        "a ratio above the ceiling below means the 2-job run met a faster machine): read "
        "the ratio to a few tenths.",
        "",
        f"**Throughput, 2 jobs / 1 job: {speedup:.2f}x** (best repetitions; target >= 1.8x: "
        f"{verdict}). "
        f"Ceiling for this suite (perfect split of the 1-job work, bounded by its longest "
        f"problem): {ceiling:.2f}x.",
        f"Same status for every problem in both best runs: {'yes' if same else 'no'}.",
        "",
        f"Peer, same script: two copies of one `tampcli plan` child "
        f"({Path(peer['problem']).parent.name}/{Path(peer['problem']).name}) at once finish "
        f"in {peer['two']:.2f} s against {peer['one']:.2f} s for one alone (best of 3, "
        f"alternating): 2 processes give **{peer['ratio']:.2f}x** the throughput of 1 on "
        f"this machine (they share caches and memory), the most a 2-job batch of such "
        f"children can reach here. The batch reaches {speedup / peer['ratio']:.0%} of it.",
        "",
        "Reading: *slots busy* = sum of problem walls / (jobs x batch wall): the share of "
        "the batch's time during which each of its job slots had a child running; what is "
        "missing is the batch's own start (imports, discovery) and summary, and the gap "
        "between one child's exit and the next one's start. When the two cores are not both "
        "free (other users: see the load), each problem's own wall time grows with 2 jobs "
        "while its CPU time does not: compare the sums of problem walls and of CPU.",
        "",
        "History: before the batch ran the largest problem files first (natural order "
        "instead), 2 jobs kept their slots only 85-87% busy on this suite (one slot idle "
        "while the other finished a long problem near the end); with largest-first they "
        "stay 98-99% busy.",
        "",
    ]
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text("\n".join(lines))


if __name__ == "__main__":
    main()
