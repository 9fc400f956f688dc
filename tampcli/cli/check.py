"""`tampcli check DOMAIN [PROBLEM] [--scene FILE] [--modes FILE]`: parse, type-check, summarize.

The summary is one dict (printed as tables, or as one JSON object with
--json) with a part per stage: the PDDL files, the grounded task when
grounding is available, and the scene when the problem has one.
"""

from __future__ import annotations

import time
from collections import Counter
from pathlib import Path

from rich.table import Table

from tampcli.errors import ExitCode, InputError
from tampcli.pddl import ast, parser
from tampcli.pddl import check as semantic

# Long lists (a grounded domain has thousands of actions) are cut in tables;
# --json always has everything.
TABLE_ROWS = 25


def add_parser(p) -> None:
    p.add_argument("domain", help="PDDL domain file")
    p.add_argument("problem", nargs="?", help="PDDL problem file")
    p.add_argument("--scene", help="scene file (default: PROBLEM.scene.toml beside the problem)")
    p.add_argument("--modes", help="modes file (default: modes.toml beside the domain)")


def run(args, ui) -> int:
    if (args.scene or args.modes) and not args.problem:
        raise InputError("--scene and --modes need a PROBLEM to check against", path="check")
    domain = parser.parse_domain_file(args.domain)
    problem = parser.parse_problem_file(args.problem) if args.problem else None
    warnings = semantic.check(domain, problem)
    summary = {"status": "ok", "domain": domain_summary(domain)}
    if problem is not None:
        summary["problem"] = problem_summary(problem)
        summary["grounded"] = grounded_summary(domain, problem)
        scene = scene_part(domain, problem, args)
        summary["scene"] = scene
        if scene:
            warnings += scene.get("warnings", [])
        elif args.modes:
            warnings.append(f"{args.modes}: not checked, the problem has no scene")
    summary["warnings"] = warnings
    for warning in warnings:
        ui.warn(warning)
    if ui.json:
        ui.emit_json(summary)
    else:
        _print_tables(ui, summary)
    return ExitCode.OK


# ---------------------------------------------------------------- the parts


def domain_summary(domain: ast.Domain) -> dict:
    report = semantic.requirements(domain)
    derived = {axiom.name for axiom in domain.axioms}
    return {
        "name": domain.name,
        "path": domain.path,
        "requirements": {"declared": list(report.declared), "used": list(report.used)},
        "types": {t.name: list(t.types) for t in domain.types},
        "constants": len(domain.constants),
        "predicates": {p.name: len(p.params) for p in domain.predicates},
        "derived": sorted(derived),
        "functions": {f.name: len(f.params) for f in domain.functions},
        "actions": {a.name: len(a.params) for a in domain.actions},
        "axioms": len(domain.axioms),
    }


def problem_summary(problem: ast.Problem) -> dict:
    by_type = Counter(" ".join(o.types) if len(o.types) == 1 else f"(either {' '.join(o.types)})"
                      for o in problem.objects)
    return {
        "name": problem.name,
        "path": problem.path,
        "objects": dict(sorted(by_type.items())),
        "init_facts": len(problem.init),
        "init_values": len(problem.init_values),
        "goal_atoms": _count_atoms(problem.goal),
        "metric": (f"{problem.metric.direction} ({problem.metric.expression.name})"
                   if problem.metric else None),
    }


def grounded_summary(domain: ast.Domain, problem: ast.Problem) -> dict | None:
    """Facts and operators after grounding, when the grounder is installed."""
    try:
        from tampcli.task.ground import ground
    except ImportError:
        return None
    start = time.perf_counter()
    task = ground(domain, problem)
    return {
        "facts": len(task.facts),
        "operators": len(task.operators),
        "axioms": len(getattr(task, "axioms", ())),
        "unit_cost": task.unit_cost,
        "seconds": round(time.perf_counter() - start, 3),
    }


def scene_part(domain: ast.Domain, problem: ast.Problem, args) -> dict | None:
    """The geometry report (tampcli.geometry.report.scene_summary), when there is a scene.

    Importing the geometry stack costs about a second, so it is skipped
    when no scene was given and none lies beside the problem.
    """
    if not args.scene and not _scene_beside(args.problem):
        return None
    try:
        from tampcli.geometry import report
    except ImportError:
        return None
    scene_summary = getattr(report, "scene_summary", None)
    if scene_summary is None:
        return None
    return scene_summary(domain, problem, args.domain, args.problem, args.scene, args.modes)


def _scene_beside(problem_path: str) -> bool:
    path = Path(problem_path)
    return path.with_name(path.stem + ".scene.toml").is_file()


def _count_atoms(formula: ast.Formula) -> int:
    count, todo = 0, [formula]
    while todo:
        f = todo.pop()
        if isinstance(f, ast.Atom):
            count += 1
        elif isinstance(f, ast.Not):
            todo.append(f.part)
        elif isinstance(f, (ast.And, ast.Or)):
            todo.extend(f.parts)
        elif isinstance(f, ast.Imply):
            todo.extend((f.antecedent, f.consequent))
        elif isinstance(f, (ast.Exists, ast.Forall)):
            todo.append(f.body)
    return count


# ---------------------------------------------------------------- tables


def _print_tables(ui, summary: dict) -> None:
    d = summary["domain"]
    head = Table(title=f"domain {d['name']}", show_header=False, title_justify="left")
    head.add_column(style="bold")
    head.add_column()
    head.add_row("file", str(d["path"]))
    head.add_row("requirements declared", " ".join(d["requirements"]["declared"]) or "-")
    head.add_row("requirements used", " ".join(d["requirements"]["used"]))
    head.add_row("types", _types_text(d["types"]))
    head.add_row("constants", str(d["constants"]))
    head.add_row("functions", _arities(d["functions"]) or "-")
    head.add_row("axioms", str(d["axioms"]))
    ui.print(head)
    derived = set(d["derived"])
    ui.print(_listing("predicates", {n: f"{a}" + (" (derived)" if n in derived else "")
                                     for n, a in d["predicates"].items()}))
    ui.print(_listing("actions", {n: str(a) for n, a in d["actions"].items()}))
    if "problem" in summary:
        p = summary["problem"]
        table = Table(title=f"problem {p['name']}", show_header=False, title_justify="left")
        table.add_column(style="bold")
        table.add_column()
        table.add_row("file", str(p["path"]))
        for type_name, count in p["objects"].items():
            table.add_row(f"objects: {type_name}", str(count))
        table.add_row("init facts", str(p["init_facts"]))
        if p["init_values"]:
            table.add_row("init function values", str(p["init_values"]))
        table.add_row("goal atoms", str(p["goal_atoms"]))
        if p["metric"]:
            table.add_row("metric", p["metric"])
        g = summary.get("grounded")
        if g:
            table.add_row("grounded facts", str(g["facts"]))
            table.add_row("grounded operators", str(g["operators"]))
            if g["axioms"]:
                table.add_row("grounded axioms", str(g["axioms"]))
            table.add_row("costs", "unit" if g["unit_cost"] else "general")
        ui.print(table)
    scene = summary.get("scene")
    if scene:
        ui.print(_scene_table(scene))


def _listing(title: str, rows: dict[str, str]) -> Table:
    table = Table(title=f"{title} ({len(rows)})", title_justify="left")
    table.add_column("name")
    table.add_column("arity", justify="right")
    for name, arity in list(rows.items())[:TABLE_ROWS]:
        table.add_row(name, arity)
    if len(rows) > TABLE_ROWS:
        table.add_row(f"... {len(rows) - TABLE_ROWS} more (see --json)", "")
    return table


def _scene_table(scene: dict) -> Table:
    table = Table(title=f"scene {scene.get('scene', '')}", show_header=False,
                  title_justify="left")
    table.add_column(style="bold")
    table.add_column()
    robot = scene.get("robot") or {}
    if robot:
        table.add_row("robot", f"{robot.get('model')} ({len(robot.get('joints', []))} joints, "
                               f"tool {robot.get('tool_link')})")
    bodies = scene.get("bodies", [])
    if bodies:
        table.add_row("bodies", ", ".join(b["name"] + ("" if b.get("fixed") else "*")
                                          for b in bodies) + "   (* movable)")
    regions = scene.get("regions", [])
    if regions:
        table.add_row("regions", ", ".join(r["name"] for r in regions))
    modes = scene.get("action_modes", {})
    if modes:
        table.add_row("action modes", ", ".join(f"{a}: {m}" for a, m in modes.items()))
    contacts = scene.get("start_contacts", [])
    table.add_row("start state", "no close pairs" if not contacts else
                  "; ".join(f"{c['a']} / {c['b']}: {c['distance']:.4f} m" for c in contacts[:5]))
    for key in sorted(set(scene) - {"scene", "robot", "bodies", "regions", "action_modes",
                                    "start_contacts", "warnings"}):
        table.add_row(key, str(scene[key]))
    return table


def _types_text(types: dict[str, list[str]]) -> str:
    if not types:
        return "-"
    return ", ".join(name if parents == ["object"] else f"{name} < {'|'.join(parents)}"
                     for name, parents in types.items())


def _arities(table: dict[str, int]) -> str:
    return ", ".join(f"{name}/{arity}" for name, arity in table.items())
