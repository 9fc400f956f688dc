"""`tampcli check DOMAIN [PROBLEM]`: parse, type-check and summarize."""

from __future__ import annotations

from rich.table import Table

from tampcli.errors import ExitCode
from tampcli.pddl import parser


def add_parser(p) -> None:
    p.add_argument("domain", help="PDDL domain file")
    p.add_argument("problem", nargs="?", help="PDDL problem file")


def run(args, ui) -> int:
    domain = parser.parse_domain_file(args.domain)
    problem = parser.parse_problem_file(args.problem) if args.problem else None
    summary = {
        "domain": domain.name,
        "requirements": list(domain.requirements),
        "types": len(domain.types),
        "predicates": len(domain.predicates),
        "functions": len(domain.functions),
        "actions": {a.name: len(a.params) for a in domain.actions},
        "axioms": len(domain.axioms),
    }
    if problem is not None:
        summary["problem"] = problem.name
        summary["objects"] = len(problem.objects)
        summary["init_facts"] = len(problem.init)
    if ui.json:
        ui.emit_json(summary)
        return ExitCode.OK
    table = Table(title=f"domain {domain.name}", show_header=False)
    for key, value in summary.items():
        table.add_row(key, str(value))
    ui.print(table)
    return ExitCode.OK
