"""Results -> counts per status, median and total time, per domain; table and CSV."""

from __future__ import annotations

import csv
import statistics
from collections.abc import Iterable
from typing import Any

from tampcli.batch.discover import domain_label
from tampcli.batch.results import STATUSES

_CSV_FIELDS = ("problem", "domain", "domain_name", "status", "cost", "plan_length", "wall_s",
               "cpu_s", "peak_rss_mb", "exit_code", "error")

_SHORT = {"unsolvable": "unsolv", "crashed": "crash"}


def summarize(records: Iterable[dict[str, Any]]) -> dict[str, Any]:
    records = list(records)
    groups: dict[str, list[dict[str, Any]]] = {}
    for record in records:
        groups.setdefault(_label(record), []).append(record)
    summary = _totals(records)
    summary["domains"] = [{"domain": label, **_totals(rows)} for label, rows in sorted(groups.items())]
    return summary


def _totals(records: list[dict[str, Any]]) -> dict[str, Any]:
    counts = dict.fromkeys(STATUSES, 0)
    for record in records:
        counts[record.get("status")] = counts.get(record.get("status"), 0) + 1
    times = [float(r["wall_s"]) for r in records if isinstance(r.get("wall_s"), (int, float))]
    rss = [float(r["peak_rss_mb"]) for r in records
           if isinstance(r.get("peak_rss_mb"), (int, float))]
    return {
        "problems": len(records),
        "counts": counts,
        "median_wall_s": round(statistics.median(times), 3) if times else None,
        "total_wall_s": round(sum(times), 3),
        "total_cpu_s": round(sum(r["cpu_s"] for r in records
                                 if isinstance(r.get("cpu_s"), (int, float))), 3),
        "max_peak_rss_mb": max(rss) if rss else None,
    }


def table(summary: dict[str, Any], title: str):
    from rich import box
    from rich.table import Table

    # Short headers and no vertical rules: the table fits 80 columns when piped.
    t = Table(title=title, box=box.SIMPLE_HEAD, show_edge=False, padding=(0, 1, 0, 0))
    t.add_column("domain", overflow="fold")
    headers = ["n", *(_SHORT.get(s, s) for s in STATUSES), "med s", "tot s"]
    for header in headers:
        t.add_column(header, justify="right", no_wrap=True, min_width=len(header))
    rows = summary["domains"]
    for i, row in enumerate(rows + [{"domain": "all", **summary}]):
        t.add_row(row["domain"], str(row["problems"]), *(str(row["counts"][s]) for s in STATUSES),
                  _seconds(row["median_wall_s"]), _seconds(row["total_wall_s"]),
                  end_section=(i == len(rows) - 1))
    return t


def write_csv(path: str, records: Iterable[dict[str, Any]]) -> None:
    """One row per problem; scalar stats flattened into `stats.<key>` columns."""
    records = list(records)
    stat_keys = sorted({key for r in records for key, value in (r.get("stats") or {}).items()
                        if isinstance(value, (int, float, str, bool)) or value is None})
    with open(path, "w", newline="", encoding="utf-8") as f:
        writer = csv.writer(f)
        writer.writerow(list(_CSV_FIELDS) + [f"stats.{k}" for k in stat_keys])
        for r in records:
            error = r.get("error")
            row = [r.get("problem"), r.get("domain"), _label(r), r.get("status"), r.get("cost"),
                   r.get("plan_length"), r.get("wall_s"), r.get("cpu_s"), r.get("peak_rss_mb"),
                   r.get("exit_code"), error.splitlines()[0] if error else None]
            stats = r.get("stats") or {}
            row += [stats.get(k) for k in stat_keys]
            writer.writerow(["" if v is None else v for v in row])


def _label(record: dict[str, Any]) -> str:
    return domain_label(record.get("domain"), record["problem"])


def _seconds(value: float | None) -> str:
    return "-" if value is None else f"{value:.2f}"
