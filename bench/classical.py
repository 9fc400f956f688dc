"""Classical planning: ours vs pyperplan vs Fast Downward, same problems, same limit.

    .venv/bin/python bench/classical.py [--limit 60] [--per-domain 6] [--out bench/results/classical.md]

Every run is a fresh subprocess timed from start to exit (parse, ground or
translate, and search included). The limit is CPU time (RLIMIT_CPU on every
process of the run), with a wall-clock cap of 4x the limit: the machine is
shared, and a wall-clock limit would measure the other jobs as much as ours.
  ours       parse + ground + GBFS/h_FF, and A*/LM-cut (h_max where the task has
             conditional effects, which LM-cut refuses), as a library, like pyperplan;
             the start-up of the `tampcli plan` command itself is measured apart
  pyperplan  `search_plan(..., gbf, hff)` and `(astar, lmcut)`, as a library
  FD         up-fast-downward's packaged driver: `--alias lama-first`, `astar(lmcut())`
Reported: coverage per configuration, median wall-time ratios ours/peer over
the problems both solve, and every cost (optimal costs must agree).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
IPC = ROOT / "benchmarks" / "ipc"
PY = sys.executable
DOMAINS = ["gripper", "blocks", "logistics00", "miconic", "driverlog", "rovers", "satellite",
           "visitall-opt11-strips", "elevators-opt08-strips", "miconic-fulladl"]
CONFIGS = ["ours-sat", "pyperplan-sat", "fd-sat", "ours-opt", "pyperplan-opt", "fd-opt"]
WALL_FACTOR = 4
LOAD_AT_START = os.getloadavg()[0]
ENV = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1", PYTHONHASHSEED="0")


def natural(name: str):
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", name)]


def problems(per_domain: int):
    for domain in DOMAINS:
        folder = IPC / domain
        names = sorted((p.name for p in folder.glob("*.pddl") if "domain" not in p.name), key=natural)
        for name in names[:per_domain]:
            yield domain, folder / "domain.pddl", folder / name


def fd_driver() -> Path:
    import up_fast_downward

    return Path(up_fast_downward.__file__).parent / "downward" / "fast-downward.py"


def command(config: str, domain: Path, problem: Path, limit: float, workdir: Path) -> list[str]:
    if config == "ours-cli":
        return [PY, "-m", "tampcli", "plan", str(domain), str(problem), "--json", "--time-limit", str(limit)]
    if config.startswith("ours"):
        return [PY, __file__, "--ours", config, str(domain), str(problem)]
    if config.startswith("pyperplan"):
        return [PY, __file__, "--pyperplan", config, str(domain), str(problem)]
    plan = str(workdir / "plan")
    if config == "fd-sat":
        return [PY, str(fd_driver()), "--alias", "lama-first", "--plan-file", plan, str(domain), str(problem)]
    return [PY, str(fd_driver()), "--plan-file", plan, str(domain), str(problem), "--search", "astar(lmcut())"]


def run(config: str, domain: Path, problem: Path, limit: float) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        workdir = Path(tmp)
        cmd = command(config, domain, problem, limit, workdir)
        start = time.perf_counter()
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu_limit = math.ceil(limit)

        def limit_cpu():
            resource.setrlimit(resource.RLIMIT_CPU, (cpu_limit, cpu_limit + 1))

        try:
            proc = subprocess.run(cmd, cwd=workdir, env=ENV, capture_output=True, text=True,
                                  timeout=WALL_FACTOR * limit, preexec_fn=limit_cpu)
        except subprocess.TimeoutExpired:
            return {"solved": False, "seconds": WALL_FACTOR * limit, "cpu": None,
                    "note": "wall-clock cap reached"}
        seconds = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        cost, inside = None, {}
        if config == "ours-cli" and proc.returncode == 0:
            cost = json.loads(proc.stdout)["plans"][0]["cost"]
        elif config.startswith(("ours", "pyperplan")) and proc.returncode == 0:
            inside = json.loads(proc.stdout.strip().splitlines()[-1])
            cost = inside["cost"]
        elif config.startswith("fd") and proc.returncode == 0:
            plan_file = workdir / "plan"
            if plan_file.exists():
                match = re.search(r"; cost = (\S+)", plan_file.read_text())
                cost = float(match.group(1)) if match else None
        if cost is None:
            tail = (proc.stderr or proc.stdout).strip().splitlines()[-1:] or [""]
            return {"solved": False, "seconds": seconds, "cpu": cpu,
                    "note": f"exit {proc.returncode}: {tail[0][:80]}"}
        result = {"solved": True, "seconds": seconds, "cpu": cpu, "cost": float(cost)}
        if config.startswith(("ours-sat", "ours-opt", "pyperplan")):
            result["solve"] = inside["solve"]
        return result


def ours_main(config: str, domain: str, problem: str) -> int:
    """Run inside the subprocess: parse, ground, search as a library, print the cost as JSON."""
    from tampcli.pddl import parser
    from tampcli.search.heuristics import HEURISTICS
    from tampcli.search.searches import SEARCHES, SearchLimits
    from tampcli.task.ground import ground

    start = time.process_time()
    parsed = parser.parse_domain_file(domain), parser.parse_problem_file(problem)
    parsed_at = time.process_time()
    task = ground(*parsed)
    if config == "ours-sat":
        search, heuristic = "gbfs", "hff"
    else:
        search, heuristic = "astar", "hmax" if task.has_conditional_effects else "lmcut"
    result = SEARCHES[search](task, HEURISTICS[heuristic](task), SearchLimits())
    if result.status != "solved":
        return 1
    print(json.dumps({"cost": result.cost, "parse": parsed_at - start,
                      "solve": time.process_time() - parsed_at}))
    return 0


def pyperplan_main(config: str, domain: str, problem: str) -> int:
    """Run inside the subprocess: pyperplan as a library, print the cost as JSON."""
    import logging

    from pyperplan import planner

    logging.disable(logging.CRITICAL)
    search, heuristic = ("gbf", "hff") if config == "pyperplan-sat" else ("astar", "lmcut")
    start = time.process_time()
    parsed = planner._parse(domain, problem)
    parsed_at = time.process_time()
    task = planner._ground(parsed)
    plan = planner._search(task, planner.SEARCHES[search], planner.HEURISTICS[heuristic](task))
    if plan is None:
        return 1
    # pyperplan ignores action costs: its cost is the plan length
    print(json.dumps({"cost": len(plan), "parse": parsed_at - start,
                      "solve": time.process_time() - parsed_at}))
    return 0


def fmt(result: dict) -> str:
    if not result["solved"]:
        return "—"
    return f"{result['seconds']:.2f} s ({result['cost']:g})"


def ratio(results, ours: str, peer: str, key: str = "seconds") -> tuple[float | None, int]:
    ratios = [r[ours][key] / r[peer][key] for r in results
              if r[ours]["solved"] and r[peer]["solved"] and r[peer][key]]
    return (statistics.median(ratios) if ratios else None), len(ratios)


def startup(limit: float, repeats: int = 3) -> dict:
    """Median wall/CPU of `tampcli plan` vs the library run on the smallest problem."""
    domain = IPC / "gripper" / "domain.pddl"
    problem = IPC / "gripper" / "prob01.pddl"
    out = {}
    for config in ("ours-cli", "ours-sat", "pyperplan-sat"):
        runs = [run(config, domain, problem, limit) for _ in range(repeats)]
        out[config] = {key: statistics.median(r[key] for r in runs) for key in ("seconds", "cpu")}
    # The floor under every start-to-exit time here: an interpreter that does nothing.
    for label, code in (("python -c pass", "pass"),
                        ("import tampcli.pddl.parser", "import tampcli.pddl.parser")):
        walls = []
        for _ in range(repeats):
            start = time.perf_counter()
            subprocess.run([PY, "-c", code], check=True, cwd=ROOT, env=ENV)
            walls.append(time.perf_counter() - start)
        out[label] = {"seconds": statistics.median(walls), "cpu": None}
    return out


def report(results: list[dict], limit: float, per_domain: int, total_seconds: float,
           start_up: dict | None = None) -> str:
    n = len(results)
    lines = [
        "# Classical planning: ours vs pyperplan vs Fast Downward",
        "",
        f"Generated by `bench/classical.py --limit {limit:g} --per-domain {per_domain}` "
        f"({time.strftime('%Y-%m-%d %H:%M')}, {total_seconds / 60:.0f} min). "
        f"{n} problems: the first {per_domain} (natural sort) of {', '.join(DOMAINS)}.",
        f"Each run is a fresh process, timed from start to exit (parsing, grounding or "
        f"translation, search). Limit: {limit:g} s of CPU time per process (RLIMIT_CPU), and a "
        f"wall-clock cap of {WALL_FACTOR * limit:g} s. Machine: {os.cpu_count()} cores, load "
        f"average {LOAD_AT_START:.1f} when the run started and {os.getloadavg()[0]:.1f} at this "
        "report; ratios are medians over the problems both planners solve, the "
        "configurations of one problem run back to back.",
        "",
        "Configurations: ours-sat = parse + ground + GBFS with h_FF; ours-opt = A* with LM-cut "
        "(h_max on miconic-fulladl, whose conditional effects LM-cut refuses), both run as a "
        "library in a fresh interpreter like pyperplan (the start-up of the `tampcli plan` "
        "command is measured apart below); pyperplan-sat = gbf + hff, pyperplan-opt = astar + lmcut "
        "(pyperplan parses neither action costs nor ADL, and its cost is the plan length); "
        "fd-sat = `--alias lama-first`, fd-opt = `astar(lmcut())` (up-fast-downward's build).",
        "",
        "## Coverage",
        "",
        "| configuration | solved |",
        "| --- | --- |",
    ]
    for config in CONFIGS:
        lines.append(f"| {config} | {sum(r[config]['solved'] for r in results)}/{n} |")
    lines += ["", "## Median time ratios (lower is faster for us)", "",
              "Wall: start to exit. CPU: user + system time of the process and its children "
              "(less sensitive to the other jobs on the machine).", "",
              "| ratio | median wall | median CPU | over problems |", "| --- | --- | --- | --- |"]
    for ours, peer in (("ours-sat", "pyperplan-sat"), ("ours-opt", "pyperplan-opt"),
                       ("ours-sat", "fd-sat"), ("ours-opt", "fd-opt")):
        wall, count = ratio(results, ours, peer)
        cpu, _ = ratio(results, ours, peer, "cpu")
        lines.append(f"| {ours} / {peer} | {'—' if wall is None else f'{wall:.2f}'} | "
                     f"{'—' if cpu is None else f'{cpu:.2f}'} | {count} |")
    sat = sum(r["ours-sat"]["solved"] for r in results)
    opt = sum(r["ours-opt"]["solved"] for r in results)
    checks = [("satisficing coverage", f"{sat}/{n}", f"{n}/{n}", sat == n),
              ("optimal coverage", f"{opt}/{n}", f">= {round(0.8 * n)}/{n}", opt >= 0.8 * n)]
    for ours, peer, target in (("ours-sat", "pyperplan-sat", 0.33), ("ours-opt", "pyperplan-opt", 0.33),
                               ("ours-sat", "fd-sat", 2.0), ("ours-opt", "fd-opt", 2.0)):
        wall, _ = ratio(results, ours, peer)
        checks.append((f"median wall {ours} / {peer}", "—" if wall is None else f"{wall:.2f}",
                       f"<= {target:g}", wall is not None and wall <= target))
    lines += ["", "## Targets (issue 3)", "", "| target | measured | wanted | met |",
              "| --- | --- | --- | --- |"]
    lines += [f"| {name} | {got} | {want} | {'yes' if ok else 'no'} |"
              for name, got, want, ok in checks]
    lines += ["", "Grounding + search only (CPU inside the process, after parsing; imports, "
              "interpreter start-up and the parser excluded):", "",
              "| ratio | median | over problems |", "| --- | --- | --- |"]
    for ours, peer in (("ours-sat", "pyperplan-sat"), ("ours-opt", "pyperplan-opt")):
        value, count = ratio(results, ours, peer, "solve")
        lines.append(f"| {ours} / {peer} | {'—' if value is None else f'{value:.2f}'} | {count} |")
    if start_up:
        lines += ["", "## Start-up", "",
                  "gripper prob01 (11 steps, solved in milliseconds), median of 3 runs: "
                  "the `tampcli plan` command against the library run, and a bare interpreter "
                  "(the floor of every start-to-exit time in this file).", "",
                  "| run | wall | CPU |", "| --- | --- | --- |"]
        for config, value in start_up.items():
            cpu = "-" if value["cpu"] is None else f"{value['cpu']:.2f} s"
            lines.append(f"| {config} | {value['seconds']:.2f} s | {cpu} |")
        floor = start_up["python -c pass"]["seconds"]
        both = [r["pyperplan-sat"]["seconds"] for r in results
                if r["ours-sat"]["solved"] and r["pyperplan-sat"]["solved"]]
        if both:
            med = statistics.median(both)
            lines += ["", f"Reading the pyperplan ratio: pyperplan's median start-to-exit time on "
                      f"the problems both solve is {med:.2f} s; 0.33x of it is "
                      f"{0.33 * med:.2f} s, against {floor:.2f} s for an interpreter that does "
                      f"nothing and {start_up['import tampcli.pddl.parser']['seconds']:.2f} s "
                      "for one that imports our parser (lark and the AST): no faster search "
                      "brings ours under that on those problems. The in-process ratio above "
                      "(grounding + search) is the planners' own speed."]
    mismatches = [f"{r['domain']}/{r['problem']}: ours {r['ours-opt']['cost']:g}, FD {r['fd-opt']['cost']:g}"
                  for r in results if r["ours-opt"]["solved"] and r["fd-opt"]["solved"]
                  and abs(r["ours-opt"]["cost"] - r["fd-opt"]["cost"]) > 1e-6]
    lines += ["", "## Optimal costs", "",
              "ours-opt and fd-opt agree on every problem both solve." if not mismatches
              else "Disagreements between ours-opt and fd-opt: " + "; ".join(mismatches)]
    lines += ["", "## Per problem: wall time (cost)", "",
              "| domain | problem | " + " | ".join(CONFIGS) + " |",
              "| --- | --- | " + " | ".join("---" for _ in CONFIGS) + " |"]
    for r in results:
        lines.append(f"| {r['domain']} | {r['problem']} | " + " | ".join(fmt(r[c]) for c in CONFIGS) + " |")
    failures = [f"- {r['domain']}/{r['problem']} {c}: {r[c]['note']}" for r in results for c in CONFIGS
                if not r[c]["solved"]]
    if failures:
        lines += ["", "## Unsolved runs", "", *failures]
    return "\n".join(lines) + "\n"


def main() -> int:
    if len(sys.argv) > 1 and sys.argv[1] == "--pyperplan":
        return pyperplan_main(*sys.argv[2:5])
    if len(sys.argv) > 1 and sys.argv[1] == "--ours":
        return ours_main(*sys.argv[2:5])
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--limit", type=float, default=60.0, help="seconds per run (default 60)")
    ap.add_argument("--per-domain", type=int, default=6)
    ap.add_argument("--out", default=str(ROOT / "bench" / "results" / "classical.md"))
    args = ap.parse_args()
    started = time.perf_counter()
    start_up = startup(args.limit)
    results = []
    for domain_name, domain, problem in problems(args.per_domain):
        row = {"domain": domain_name, "problem": problem.name}
        for config in CONFIGS:
            row[config] = run(config, domain, problem, args.limit)
        results.append(row)
        print(f"{domain_name} {problem.name}: " + ", ".join(f"{c} {fmt(row[c])}" for c in CONFIGS),
              flush=True)
        Path(args.out).write_text(report(results, args.limit, args.per_domain,
                                         time.perf_counter() - started, start_up))
    return 0


if __name__ == "__main__":
    sys.exit(main())
