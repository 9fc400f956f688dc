"""Classical planning: `tampcli plan` (LAMA's first search) against Fast Downward's lama-first.

    .venv/bin/python bench/classical.py [--per-domain 15] [--limit 30] [--jobs 2]
                                        [--anytime-per-domain 2] [--anytime-limit 10]
                                        [--out bench/results/classical.md]

Every run is a fresh process timed from start to exit (parsing, grounding or
translation, search): `python -m tampcli plan DOMAIN PROBLEM --json` against
up-fast-downward's packaged driver with `--alias lama-first`. Both get the
same limit as CPU time (RLIMIT_CPU on the process and its children) and a
wall-clock cap of 4x the limit: the machine is shared, and a wall-clock limit
would measure the other jobs as much as the planners. `--jobs` problems run
at a time, each problem's two runs back to back in one worker, so both
planners see the same load. Afterwards `plan --anytime --time-limit
ANYTIME_LIMIT` runs on the first ANYTIME_PER_DOMAIN problems of each domain.
Our plans are validated (tampcli's validator, outside the timing); an invalid
one would count as unsolved.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import re
import resource
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
IPC = ROOT / "benchmarks" / "ipc"
PY = sys.executable
WALL_FACTOR = 4
FD_SLOW = 0.5  # time ratios are taken over the problems FD needs at least this long for
# PYTHONPATH: this checkout's tampcli, whatever the venv has installed
ENV = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1", PYTHONHASHSEED="0",
           PYTHONPATH=str(ROOT))


def natural(path: Path) -> list:
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", path.name)]


def domain_of(problem: Path) -> Path:
    """`domain.pddl`, or the per-problem `pNN-domain.pddl`, `domain_pNN.pddl`, `domain-pNN.pddl`."""
    number = re.match(r"p\d+", problem.stem)
    for key in [problem.stem] + ([number.group()] if number else []):
        for name in (f"{key}-domain.pddl", f"domain_{key}.pddl", f"domain-{key}.pddl"):
            if (problem.parent / name).is_file():
                return problem.parent / name
    return problem.parent / "domain.pddl"


def problems(per_domain: int) -> list[tuple[str, Path, Path]]:
    """The first problems of every domain, first ones first: a run cut short has
    measured the first k problems of every domain rather than a few domains."""
    out = []
    for folder in sorted(p for p in IPC.iterdir() if p.is_dir()):
        found = sorted((p for p in folder.glob("*.pddl") if "domain" not in p.name), key=natural)
        out += [(i, folder.name, domain_of(p), p) for i, p in enumerate(found[:per_domain])]
    return [(name, domain, problem) for _, name, domain, problem in sorted(out)]


def fd_driver() -> Path:
    import up_fast_downward

    return Path(up_fast_downward.__file__).parent / "downward" / "fast-downward.py"


def timed(cmd: list[str], limit: float, workdir: Path) -> tuple[subprocess.CompletedProcess | None,
                                                                 float, float]:
    """(process or None when the wall cap struck, wall seconds, CPU seconds).

    The command runs under `--measure`, which reports the CPU time of it and
    all its descendants (FD's driver runs the translator and the search as
    two processes): the two workers' processes would mix in this process's
    own children usage.
    """
    cpu_limit = math.ceil(limit)
    usage = workdir / "cpu-seconds"

    def limit_cpu():
        resource.setrlimit(resource.RLIMIT_CPU, (cpu_limit, cpu_limit + 1))

    start = time.perf_counter()
    proc = subprocess.Popen([PY, __file__, "--measure", str(usage), *cmd], cwd=workdir,
                            env=ENV, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=limit_cpu, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=WALL_FACTOR * limit)
        done = subprocess.CompletedProcess(cmd, proc.returncode, out, err)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        done = None
    seconds = time.perf_counter() - start
    cpu = float(usage.read_text()) if usage.exists() else float(cpu_limit)
    if done is not None and cpu > limit and done.returncode == 0:
        done = subprocess.CompletedProcess(cmd, 128 + signal.SIGXCPU, "", "")
    return done, seconds, cpu


def measure(out: str, cmd: list[str]) -> int:
    """Run `cmd`; write the CPU seconds of it and its descendants to `out`."""
    code = subprocess.run(cmd, check=False).returncode
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    Path(out).write_text(f"{used.ru_utime + used.ru_stime:.3f}")
    return code if code >= 0 else 128 - code


def run_ours(domain: Path, problem: Path, limit: float) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [PY, "-m", "tampcli", "plan", str(domain), str(problem), "--json"]
        proc, seconds, cpu = timed(cmd, limit, Path(tmp))
    if proc is None or proc.returncode != 0 or not proc.stdout.strip():
        return {"solved": False, "seconds": seconds, "cpu": cpu, "note": _why(proc)}
    data = json.loads(proc.stdout.strip().splitlines()[-1])
    plan = data["plans"][0]
    problem_text = validated(domain, problem, plan["actions"], plan["cost"])
    if problem_text:
        return {"solved": False, "seconds": seconds, "cpu": cpu,
                "note": f"invalid plan: {problem_text}"}
    return {"solved": True, "seconds": seconds, "cpu": cpu, "cost": plan["cost"],
            "expanded": data["stats"].get("expanded"),
            "eliminated": data["stats"].get("eliminated", 0)}


def validated(domain: Path, problem: Path, actions: list[str], cost: float) -> str | None:
    """Why our plan is not a valid plan of the stated cost (None when it is), checked
    in this process with tampcli's own validator, outside the timing."""
    if str(ROOT) not in sys.path:
        sys.path.insert(0, str(ROOT))
    from tampcli.pddl import parser
    from tampcli.search.validate import validate_plan

    report = validate_plan(parser.parse_domain_file(str(domain)),
                           parser.parse_problem_file(str(problem)), actions)
    if not report.valid:
        return report.failure.describe()
    if abs(report.cost - cost) > 1e-6:
        return f"cost {report.cost:g}, not the {cost:g} stated"
    return None


def run_fd(domain: Path, problem: Path, limit: float) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        plan = Path(tmp) / "plan"
        cmd = [PY, str(fd_driver()), "--alias", "lama-first", "--plan-file", str(plan),
               str(domain), str(problem)]
        proc, seconds, cpu = timed(cmd, limit, Path(tmp))
        match = re.search(r"; cost = (\S+)", plan.read_text()) if plan.exists() else None
    if proc is None or proc.returncode != 0 or match is None:
        return {"solved": False, "seconds": seconds, "cpu": cpu, "note": _why(proc)}
    expanded = re.search(r"Expanded (\d+) state", proc.stdout)
    return {"solved": True, "seconds": seconds, "cpu": cpu, "cost": float(match.group(1)),
            "expanded": int(expanded.group(1)) if expanded else None}


def run_anytime(domain: Path, problem: Path, limit: float) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        cmd = [PY, "-m", "tampcli", "plan", str(domain), str(problem), "--json", "--anytime",
               "--time-limit", str(limit)]
        # the process gets the limit plus its start-up and grounding
        proc, seconds, cpu = timed(cmd, limit + 30, Path(tmp))
    if proc is None or proc.returncode != 0 or not proc.stdout.strip():
        return {"solved": False, "seconds": seconds, "note": _why(proc)}
    data = json.loads(proc.stdout.strip().splitlines()[-1])
    found = data["stats"].get("anytime", [])
    return {"solved": True, "seconds": seconds, "costs": [f["cost"] for f in found],
            "end": data["stats"].get("anytime_end", "limit")}


def _why(proc) -> str:
    if proc is None:
        return "wall-clock cap reached"
    if proc.returncode in (128 + signal.SIGXCPU, 128 + signal.SIGKILL):
        return "CPU limit reached"
    tail = (proc.stderr or proc.stdout).strip().splitlines()[-1:] or [""]
    return f"exit {proc.returncode}: {tail[0][:90]}"


def fmt(result: dict) -> str:
    return f"{result['seconds']:.2f} s ({result['cost']:g})" if result["solved"] else "—"


def median(values) -> float | None:
    values = list(values)
    return statistics.median(values) if values else None


def summary(rows: list[dict]) -> dict:
    ours = sum(r["ours"]["solved"] for r in rows)
    fd = sum(r["fd"]["solved"] for r in rows)
    both = [r for r in rows if r["ours"]["solved"] and r["fd"]["solved"]]
    costs = [r["ours"]["cost"] / r["fd"]["cost"] for r in both if r["fd"]["cost"] > 0]
    slow = [r for r in both if r["fd"]["seconds"] >= FD_SLOW]
    return {"n": len(rows), "ours": ours, "fd": fd, "both": len(both),
            "cost_ratio": median(costs), "cost_count": len(costs),
            "wall_ratio": median(r["ours"]["seconds"] / r["fd"]["seconds"] for r in slow),
            "cpu_ratio": median(r["ours"]["cpu"] / r["fd"]["cpu"] for r in slow if r["fd"]["cpu"]),
            "slow_count": len(slow)}


def gap_lines(rows: list[dict]) -> list[str]:
    """Search effort side by side: is a miss a matter of guidance or of speed?"""
    both = [r for r in rows if r["ours"]["solved"] and r["fd"]["solved"]
            and r["ours"].get("expanded") and r["fd"].get("expanded")]
    effort = median(r["ours"]["expanded"] / r["fd"]["expanded"] for r in both)
    missed = [r for r in rows if r["fd"]["solved"] and not r["ours"]["solved"]]
    missed_fd = median(r["fd"]["expanded"] for r in missed if r["fd"].get("expanded"))
    both_fd = median(r["fd"]["expanded"] for r in both)
    def num(x, form="{:.2f}"):
        return "—" if x is None else form.format(x)
    return [
        f"Median expansions ours / FD over the {len(both)} problems both solve: "
        f"{num(effort)} (the two searches are the same algorithm; what differs is the "
        "landmarks, FD's SAS+ encoding and the tie-breaking). FD's median expansions: "
        f"{num(both_fd, '{:.0f}')} on those, {num(missed_fd, '{:.0f}')} on the "
        f"{len(missed)} problems only FD solves. Our search is Python and expands on the "
        "order of a hundred times fewer states per second than FD's C++ search, so the "
        "problems FD needs tens of thousands of expansions for are the ones we miss.",
    ]


def report(rows: list[dict], anytime: list[dict], args, minutes: float, loads: list) -> str:
    s = summary(rows)
    domains = sorted({r["domain"] for r in rows})
    per = max(len([r for r in rows if r["domain"] == d]) for d in domains) if rows else 0
    def num(x, form="{:.2f}"):
        return "—" if x is None else form.format(x)
    coverage_ok = s["fd"] and s["ours"] >= 0.95 * s["fd"]
    lines = [
        "# Classical planning: `tampcli plan` (lama) vs Fast Downward lama-first",
        "",
        f"Generated by `bench/classical.py --per-domain {args.per_domain} --limit {args.limit:g} "
        f"--jobs {args.jobs} --anytime-per-domain {args.anytime_per_domain} --anytime-limit "
        f"{args.anytime_limit:g}` ({time.strftime('%Y-%m-%d %H:%M')} UTC, {minutes:.0f} min). "
        f"{s['n']} problems: the first {per} (natural sort) of each of the {len(domains)} "
        "domains in benchmarks/ipc"
        + ("." if s["n"] == len(problems(args.per_domain)) else
           f" (**partial run**: {s['n']} of the {len(problems(args.per_domain))} problems "
           "asked for were measured before it was stopped; problems are taken first ones "
           "first, so the last index is incomplete)."),
        "",
        f"**The machine was loaded**: {os.cpu_count()} cores shared with other jobs (other "
        "helpers were running tests at the same time); load average "
        + ", ".join(f"{x:.1f}" for x in loads) + " (start, end). "
        f"{args.jobs} problems ran at a time; each problem's two runs ran back to back in one "
        "worker. Times are start-to-exit of a fresh process (ours: `python -m tampcli plan "
        "DOMAIN PROBLEM --json`, the default search, i.e. parse, check, ground, lama search, "
        "action elimination; FD: up-fast-downward's `fast-downward.py --alias lama-first`, "
        "translation included). Limit: "
        f"{args.limit:g} s of CPU time per process (RLIMIT_CPU), wall-clock cap "
        f"{WALL_FACTOR * args.limit:g} s. Wall times include the waiting caused by the load; "
        "CPU times less so.",
        "",
        "## Targets",
        "",
        "| target | measured | wanted | met |",
        "| --- | --- | --- | --- |",
        f"| coverage | {s['ours']}/{s['n']} vs FD {s['fd']}/{s['n']} "
        f"({num(100 * s['ours'] / s['fd'] if s['fd'] else None, '{:.0f}')} % of FD's) | "
        f">= 95 % of FD's | {'yes' if coverage_ok else 'no'} |",
        f"| median first-plan cost ours / FD | {num(s['cost_ratio'], '{:.3f}')} "
        f"(over {s['cost_count']} problems both solve) | <= 1.1 | "
        f"{'yes' if s['cost_ratio'] is not None and s['cost_ratio'] <= 1.1 else 'no'} |",
        f"| median wall time ours / FD, problems FD needs >= {FD_SLOW:g} s for | "
        f"{num(s['wall_ratio'])} (over {s['slow_count']}; CPU {num(s['cpu_ratio'])}) | <= 2 | "
        f"{'yes' if s['wall_ratio'] is not None and s['wall_ratio'] <= 2 else 'no'} |",
        "",
        "## Where the difference is",
        "",
        *gap_lines(rows),
        "",
        "## Coverage per domain",
        "",
        "| domain | ours | FD | median cost ours / FD | median wall ours / FD |",
        "| --- | --- | --- | --- | --- |",
    ]
    for d in domains:
        mine = [r for r in rows if r["domain"] == d]
        both = [r for r in mine if r["ours"]["solved"] and r["fd"]["solved"]]
        cost = median(r["ours"]["cost"] / r["fd"]["cost"] for r in both if r["fd"]["cost"] > 0)
        wall = median(r["ours"]["seconds"] / r["fd"]["seconds"] for r in both)
        lines.append(f"| {d} | {sum(r['ours']['solved'] for r in mine)}/{len(mine)} | "
                     f"{sum(r['fd']['solved'] for r in mine)}/{len(mine)} | {num(cost)} | "
                     f"{num(wall)} |")
    if anytime:
        lines += ["", "## Anytime", "",
                  f"`tampcli plan --anytime --time-limit {args.anytime_limit:g}` on the first "
                  f"{args.anytime_per_domain} problems of each domain: the cost of every plan "
                  "it printed, first to last, against FD lama-first's (first) plan. `end`: "
                  "`optimal` when a bounded restart exhausted its space (no cheaper plan "
                  "exists), `weights` when the four restarts finished, `limit` at the time "
                  "limit.", "",
                  "| domain | problem | costs found | end | FD lama-first |",
                  "| --- | --- | --- | --- | --- |"]
        fd_cost = {(r["domain"], r["problem"]): r["fd"] for r in rows}
        finals = []
        for a in anytime:
            fd = fd_cost.get((a["domain"], a["problem"]), {"solved": False})
            res = a["result"]
            costs = " → ".join(f"{c:g}" for c in res.get("costs", [])) or "—"
            lines.append(f"| {a['domain']} | {a['problem']} | {costs} | {res.get('end', '—')} "
                         f"| {fd['cost']:g} |" if fd["solved"] else
                         f"| {a['domain']} | {a['problem']} | {costs} | {res.get('end', '—')} "
                         "| — |")
            if res.get("costs") and fd["solved"] and fd["cost"] > 0:
                finals.append(res["costs"][-1] / fd["cost"])
        lines += ["", f"Median final anytime cost / FD lama-first cost: {num(median(finals), '{:.3f}')}"
                  f" over {len(finals)} problems."]
    lines += ["", "## Per problem: wall time (cost)", "",
              "| domain | problem | ours | FD | ours expanded | FD expanded | ours CPU | FD CPU |",
              "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        o, f = r["ours"], r["fd"]
        lines.append(f"| {r['domain']} | {r['problem']} | {fmt(o)} | {fmt(f)} | "
                     f"{o.get('expanded', '—') if o['solved'] else '—'} | "
                     f"{f.get('expanded', '—') if f['solved'] else '—'} | {o['cpu']:.2f} | "
                     f"{f['cpu']:.2f} |")
    failures = [f"- {r['domain']}/{r['problem']} {who}: {r[who]['note']}" for r in rows
                for who in ("ours", "fd") if not r[who]["solved"]]
    if failures:
        lines += ["", "## Unsolved runs", "", *failures]
    return "\n".join(lines) + "\n"


def main() -> int:
    if len(sys.argv) > 2 and sys.argv[1] == "--measure":
        return measure(sys.argv[2], sys.argv[3:])
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--per-domain", type=int, default=15)
    ap.add_argument("--limit", type=float, default=30.0, help="CPU seconds per run (default 30)")
    ap.add_argument("--jobs", type=int, default=2, help="problems at a time (default 2)")
    ap.add_argument("--anytime-per-domain", type=int, default=2)
    ap.add_argument("--anytime-limit", type=float, default=10.0)
    ap.add_argument("--out", default=str(ROOT / "bench" / "results" / "classical.md"))
    args = ap.parse_args()
    started = time.perf_counter()
    load_start = os.getloadavg()[0]
    todo = problems(args.per_domain)

    def one(item):
        name, domain, problem = item
        row = {"domain": name, "problem": problem.name,
               "ours": run_ours(domain, problem, args.limit),
               "fd": run_fd(domain, problem, args.limit)}
        print(f"{name} {problem.name}: ours {fmt(row['ours'])}, FD {fmt(row['fd'])}", flush=True)
        return row

    rows: list[dict] = []
    anytime: list[dict] = []

    def write():
        minutes = (time.perf_counter() - started) / 60
        Path(args.out).write_text(report(rows, anytime, args, minutes,
                                         [load_start, os.getloadavg()[0]]))

    def any_one(item):
        name, domain, problem = item
        result = run_anytime(domain, problem, args.anytime_limit)
        print(f"anytime {name} {problem.name}: {result.get('costs')}", flush=True)
        return {"domain": name, "problem": problem.name, "result": result}

    # the anytime runs are short and go first; the report is rewritten after
    # every problem, so a run stopped early leaves an honest partial report
    with ThreadPoolExecutor(args.jobs) as pool:
        for entry in pool.map(any_one, problems(args.anytime_per_domain)):
            anytime.append(entry)
        for row in pool.map(one, todo):
            rows.append(row)
            write()
    write()
    return 0


if __name__ == "__main__":
    sys.exit(main())
