"""The one PDDL front end of every command: parse, then check, then (for a
problem) the same grounding.

`check` and `plan` (and whatever else reads PDDL) go through `load`, so a
domain one of them accepts the other accepts too, with the same warnings.
"""

from __future__ import annotations

from dataclasses import dataclass

from tampcli.pddl import ast, check, parser


@dataclass(frozen=True)
class Loaded:
    domain: ast.Domain
    problem: ast.Problem | None
    warnings: tuple[str, ...]  # each `path:line:col: text`


def load(domain_path: str, problem_path: str | None = None) -> Loaded:
    """Parse and check; raises the InputError of the first mistake."""
    domain = parser.parse_domain_file(str(domain_path))
    problem = parser.parse_problem_file(str(problem_path)) if problem_path else None
    warnings = check.check(domain, problem)
    return Loaded(domain, problem, tuple(warnings))
