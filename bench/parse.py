"""Parse speed: ours vs the `pddl` package (0.5.1) vs Fast Downward's translator, per IPC file.

Every file of benchmarks/ipc is parsed by the three, interleaved,
in one run; time is CPU time of this process (`time.process_time`, robust to
the other jobs sharing the machine), the best of a few repeats for small
files. The `pddl` package parses a file alone (a problem without its domain)
and refuses some; Fast Downward parses a problem against its domain's
tables, built beforehand and not timed. Medians are per file, over the files
that all three accept. Writes bench/results/parse.md.

    .venv/bin/python bench/parse.py [--every N] [--out FILE]
"""

from __future__ import annotations

import argparse
import contextlib
import io
import os
import platform
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tampcli.pddl import parser as ours  # noqa: E402

IPC = ROOT / "benchmarks" / "ipc"
SMALL = 100_000  # bytes: files below are timed as the best of REPEATS runs
REPEATS = 3


def natural_key(path: Path) -> list:
    return [int(p) if p.isdigit() else p for p in re.split(r"(\d+)", path.name)]


def domain_of(problem: Path) -> Path:
    folder, stem = problem.parent, problem.stem
    number = re.match(r"p\d+", stem)
    for key in [stem] + ([number.group()] if number else []):
        for name in (f"{key}-domain.pddl", f"domain_{key}.pddl", f"domain-{key}.pddl"):
            if (folder / name).is_file():
                return folder / name
    return folder / "domain.pddl"


def cpu_time(fn, text: str) -> float | None:
    """Best CPU seconds of `fn(text)` over the repeats; None when it refuses the text."""
    best = float("inf")
    for _ in range(REPEATS if len(text) < SMALL else 1):
        start = time.process_time()
        try:
            fn(text)
        except Exception:  # noqa: BLE001 - a refusal is a result here
            return None
        best = min(best, time.process_time() - start)
    return best


class PddlPackage:
    def __init__(self):
        from pddl.parser.domain import DomainParser
        from pddl.parser.problem import ProblemParser

        self.domain, self.problem = DomainParser(), ProblemParser()

    def parser_for(self, is_domain: bool):
        return self.domain if is_domain else self.problem


class FastDownward:
    """The translator's two steps: text -> nested lists -> its task objects."""

    def __init__(self):
        from fast_downward.translate import options
        from fast_downward.translate.pddl_parser import lisp_parser, parsing_functions

        options.set_options(["domain.pddl", "problem.pddl"])  # read by parse_action
        self.lisp, self.functions = lisp_parser, parsing_functions
        self.tables: dict[Path, tuple | None] = {}

    def domain(self, text: str):
        with contextlib.redirect_stdout(io.StringIO()):  # it prints warnings
            nested = self.lisp.parse_nested_list(text.splitlines(True))
            return tuple(self.functions.parse_domain_pddl(self.functions.Context(), nested))

    def problem_parser(self, domain_path: Path):
        if domain_path not in self.tables:
            try:
                parsed = self.domain(domain_path.read_text())
                self.tables[domain_path] = (parsed[3], parsed[6], {c.name for c in parsed[4]})
            except Exception:  # noqa: BLE001
                self.tables[domain_path] = None
        tables = self.tables[domain_path]
        if tables is None:
            return None

        def parse(text: str):
            with contextlib.redirect_stdout(io.StringIO()):
                nested = self.lisp.parse_nested_list(text.splitlines(True))
                return tuple(self.functions.parse_problem_pddl(
                    self.functions.Context(), nested, *tables))

        return parse


def run(every: int) -> list[dict]:
    ours._lark()
    pkg, fd = PddlPackage(), FastDownward()
    files = sorted(IPC.rglob("*.pddl"), key=lambda p: (p.parent.name, natural_key(p)))[::every]
    rows = []
    for i, path in enumerate(files):
        text = path.read_text()
        is_domain = "domain" in path.name
        fd_parse = fd.domain if is_domain else fd.problem_parser(domain_of(path))
        rows.append({
            "domain": path.parent.name,
            "file": path.name,
            "bytes": len(text.encode()),
            "ours": cpu_time(ours.parse, text),
            "pddl": cpu_time(pkg.parser_for(is_domain), text),
            "fd": cpu_time(fd_parse, text) if fd_parse else None,
        })
        if (i + 1) % 100 == 0:
            print(f"{i + 1}/{len(files)} files", file=sys.stderr)
    return rows


def extra_figures() -> dict:
    """Grammar build, import cost, and the deep-nesting guard on 5 MB."""
    ours._lark.cache_clear()
    start = time.perf_counter()
    ours._lark()
    build = time.perf_counter() - start
    code = ("import sys, time; t = time.perf_counter(); import tampcli.pddl.parser; "
            "print(time.perf_counter() - t, 'numpy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=ROOT, check=True).stdout.split()
    deep = "(" * 2_500_000 + ")" * 2_500_000
    start = time.perf_counter()
    try:
        ours.parse(deep)
    except ours.InputError:
        pass
    return {"build": build, "import": float(out[0]), "numpy": out[1] == "True",
            "deep": time.perf_counter() - start}


def _ms(seconds: float) -> str:
    return f"{seconds * 1e3:.2f}"


def _seconds(value: float | None) -> str:
    if value is None:
        return "refused"
    return f"{value:.2f} s" if value >= 1 else f"{value * 1e3:.1f} ms"


def report(rows: list[dict], extra: dict, wall: float) -> str:
    common = [r for r in rows if r["ours"] is not None and r["pddl"] is not None
              and r["fd"] is not None]
    med = {k: statistics.median(r[k] for r in common) for k in ("ours", "pddl", "fd")}
    lines = [
        "# Parse speed: ours vs `pddl` 0.5.1 vs Fast Downward's translator",
        "",
        f"Generated by `bench/parse.py` on {time.strftime('%Y-%m-%d %H:%M')}, "
        f"Python {platform.python_version()}, {os.cpu_count()} cores shared with other jobs "
        f"(load average {os.getloadavg()[0]:.1f}); CPU time of the process, best of "
        f"{REPEATS} for files under {SMALL // 1000} kB; {wall:.0f} s in all.",
        "",
        f"Files: {len(rows)}; accepted by ours {sum(r['ours'] is not None for r in rows)}, "
        f"by `pddl` {sum(r['pddl'] is not None for r in rows)}, "
        f"by Fast Downward {sum(r['fd'] is not None for r in rows)}; "
        f"all three: {len(common)}.",
        "",
        "| parser | median ms per file (common files) | ours / it | total MB/s (common files) |",
        "| --- | ---: | ---: | ---: |",
    ]
    size = sum(r["bytes"] for r in common) / 1e6
    names = {"ours": "ours (lark LALR + own lexer)", "pddl": "`pddl` 0.5.1 (lark LALR)",
             "fd": "Fast Downward translator"}
    for key in ("ours", "pddl", "fd"):
        total = sum(r[key] for r in common)
        lines.append(f"| {names[key]} | {_ms(med[key])} | {med['ours'] / med[key]:.2f} | "
                     f"{size / total:.2f} |")
    lines += [
        "",
        f"Target: ours at most half of `pddl`'s median: ratio {med['ours'] / med['pddl']:.2f} "
        f"({'met' if med['ours'] <= med['pddl'] / 2 else 'NOT met'}).",
        "",
        f"Also: grammar build {_ms(extra['build'])} ms (once per process); "
        f"`import tampcli.pddl.parser` {_ms(extra['import'])} ms, numpy imported: "
        f"{extra['numpy']}; 5 MB of nested parentheses refused in {_ms(extra['deep'])} ms.",
        "",
        "## Per domain (median ms per file, files all three accept)",
        "",
        "| domain | files | ours | `pddl` | FD | ours / `pddl` |",
        "| --- | ---: | ---: | ---: | ---: | ---: |",
    ]
    for domain in sorted({r["domain"] for r in rows}):
        sub = [r for r in common if r["domain"] == domain]
        if not sub:
            refused = sum(r["pddl"] is None for r in rows if r["domain"] == domain)
            lines.append(f"| {domain} | 0 | | | | (`pddl` refuses {refused}) |")
            continue
        m = {k: statistics.median(r[k] for r in sub) for k in ("ours", "pddl", "fd")}
        lines.append(f"| {domain} | {len(sub)} | {_ms(m['ours'])} | {_ms(m['pddl'])} | "
                     f"{_ms(m['fd'])} | {m['ours'] / m['pddl']:.2f} |")
    largest = max(rows, key=lambda r: r["bytes"])
    every = [r for r in rows if r["ours"] is not None]
    lines += ["", f"Largest file: {largest['domain']}/{largest['file']} "
              f"({largest['bytes'] / 1e6:.1f} MB): ours {_seconds(largest['ours'])}, "
              f"`pddl` {_seconds(largest['pddl'])}, Fast Downward {_seconds(largest['fd'])}. "
              f"Ours over all {len(every)} files: "
              f"{sum(r['bytes'] for r in every) / 1e6 / sum(r['ours'] for r in every):.2f} MB/s."]
    refused = [r for r in rows if r["pddl"] is None]
    lines += ["", f"`pddl` refuses {len(refused)} files (mostly problems whose requirements "
              "are declared only in their domain, e.g. miconic-fulladl, psr).", ""]
    return "\n".join(lines)


def main() -> None:
    args = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    args.add_argument("--every", type=int, default=1, help="time every N-th file only")
    args.add_argument("--out", default=str(ROOT / "bench" / "results" / "parse.md"))
    opts = args.parse_args()
    start = time.perf_counter()
    rows = run(opts.every)
    text = report(rows, extra_figures(), time.perf_counter() - start)
    Path(opts.out).parent.mkdir(parents=True, exist_ok=True)
    Path(opts.out).write_text(text)
    print(text)


if __name__ == "__main__":
    main()
