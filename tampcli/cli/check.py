"""`tampcli check DOMAIN [PROBLEM] [--scene FILE] [--modes FILE]`: parse, type-check, summarize.

The summary is one dict (printed as tables, or as one JSON object with
--json) with a part per stage: the PDDL files, the grounded task when
grounding is available, and the scene when the problem has one.
"""

from __future__ import annotations

import math
import time
from collections import Counter
from pathlib import Path

from rich.table import Table

from tampcli.cli.check_warnings import scene_warnings
from tampcli.errors import ExitCode, InputError
from tampcli.pddl import ast
from tampcli.pddl import check as semantic
from tampcli.pddl.load import load

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
    loaded = load(args.domain, args.problem)
    domain, problem, warnings = loaded.domain, loaded.problem, list(loaded.warnings)
    summary = {"status": "ok", "domain": domain_summary(domain)}
    if problem is not None:
        summary["problem"] = problem_summary(problem)
        summary["grounded"] = grounded_summary(domain, problem)
        scene = scene_part(domain, problem, args)
        summary["scene"] = scene
        if scene:
            warnings += scene.get("warnings", []) + scene_warnings(scene)
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
        # A type under itself is read under object (pddl/check.py warns).
        "types": {t.name: [p for p in t.types if p != t.name] or ["object"]
                  for t in domain.types},
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
    from tampcli.geometry import report
    from tampcli.geometry.locate import find_modes
    from tampcli.optimize.modes import load_modes

    modes_path = args.modes or find_modes(args.domain)
    modes = load_modes(modes_path, domain) if modes_path else None
    return report.scene_summary(domain, problem, args.problem, args.scene, modes)


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
        for table in _scene_tables(scene):
            ui.print(table)


def _listing(title: str, rows: dict[str, str]) -> Table:
    table = Table(title=f"{title} ({len(rows)})", title_justify="left")
    table.add_column("name")
    table.add_column("arity", justify="right")
    for name, arity in list(rows.items())[:TABLE_ROWS]:
        table.add_row(name, arity)
    if len(rows) > TABLE_ROWS:
        table.add_row(f"... {len(rows) - TABLE_ROWS} more (see --json)", "")
    return table


def _scene_tables(scene: dict) -> list[Table]:
    """The scene as tables: an overview, then joints, bodies, regions, start-state pairs."""
    table = Table(title=f"scene {scene.get('scene', '')}", show_header=False,
                  title_justify="left")
    table.add_column(style="bold")
    table.add_column()
    robot = scene.get("robot") or {}
    if robot:
        table.add_row("robot", f"{robot.get('model')} ({len(robot.get('joints', []))} joints, "
                               f"tool {robot.get('tool_link')})")
        table.add_row("base", _pose(robot.get("base", ())))
        if "gripper_opening" in robot:
            table.add_row("gripper", f"opening {100 * robot['gripper_opening']:.1f} cm, "
                                     f"fingertips {100 * robot['fingertip_depth']:.1f} cm "
                                     "beyond the tool origin")
    if scene.get("modes"):
        table.add_row("modes", str(scene["modes"]))
    if "support" in scene:
        table.add_row("robot stands on", ", ".join(scene["support"]) or "-")
    if "self_collision_pairs" in scene:
        table.add_row("self-collision pairs",
                      f"{len(scene['self_collision_pairs'])} link pairs checked (see --json)")
    modes = scene.get("action_modes", {})
    if modes:
        table.add_row("action modes", ", ".join(f"{a}: {m}" for a, m in modes.items()))
    contacts = scene.get("start_contacts", [])
    close, within = len(contacts), f"{scene.get('start_contacts_within', 0.05) * 100:g} cm"
    table.add_row("start state", f"{close} pair{'s' * (close != 1)} closer than {within}, no "
                  "overlap" if close else f"no pairs closer than {within}")
    shown = {"scene", "robot", "modes", "support", "self_collision_pairs", "bodies", "regions",
             "action_modes", "start_contacts", "start_contacts_within", "warnings"}
    for key in sorted(set(scene) - shown):
        table.add_row(key, str(scene[key]))
    tables = [table]
    if robot.get("joints"):
        tables.append(_joints_table(robot))
    if scene.get("bodies"):
        tables.append(_bodies_table(scene["bodies"]))
    if scene.get("regions"):
        tables.append(_regions_table(scene["regions"]))
    if contacts:
        tables.append(_contacts_table(contacts, scene.get("start_contacts_within", 0.05)))
    return tables


def _joints_table(robot: dict) -> Table:
    names = robot["joints"]
    table = Table(title=f"joints ({len(names)}; rad, or m for prismatic)", title_justify="left")
    table.add_column("joint")
    for column in ("lower", "upper", "start"):
        table.add_column(column, justify="right")
    for name, lo, hi, q in zip(names, robot["lower"], robot["upper"], robot["start"],
                               strict=True):
        table.add_row(name, f"{lo:.3f}", f"{hi:.3f}", f"{q:.3f}")
    return table


def _bodies_table(bodies: list[dict]) -> Table:
    table = Table(title=f"bodies ({len(bodies)}; m; an obstacle is fixed and not in the problem)",
                  title_justify="left")
    rotated = any(_rotation(b["pose"][3:7]) != "-" for b in bodies)
    weighed = any("mass" in b for b in bodies)
    columns = ["name", "shape, size", "position"] + ["rotation"] * rotated + ["fixed"] \
        + ["mass (kg)"] * weighed
    for column in columns:
        # Nothing is cut on a narrow terminal: numbers stay on one line, names fold.
        table.add_column(column, no_wrap=column in ("shape, size", "position"), overflow="fold")
    for b in bodies[:TABLE_ROWS]:
        fixed = ("obstacle" if b.get("obstacle") else "yes") if b["fixed"] else "no"
        rotation = [_rotation(b["pose"][3:7])] * rotated
        mass = [f"{b['mass']:g}" if "mass" in b else "-"] * weighed
        table.add_row(b["name"], f"{b['shape']} {_size(b)}", _xyz(b["pose"][:3]), *rotation,
                      fixed, *mass)
    if len(bodies) > TABLE_ROWS:
        table.add_row(f"... {len(bodies) - TABLE_ROWS} more (see --json)",
                      *[""] * (len(columns) - 1))
    return table


def _regions_table(regions: list[dict]) -> Table:
    table = Table(title=f"regions ({len(regions)}; m)", title_justify="left")
    for column in ("name", "on", "centre", "size"):
        table.add_column(column)
    for r in regions[:TABLE_ROWS]:
        table.add_row(r["name"], r["on"], _xyz(r["center"]),
                      "x".join(_mm(v) for v in r["size"]))
    if len(regions) > TABLE_ROWS:
        table.add_row(f"... {len(regions) - TABLE_ROWS} more (see --json)", "", "", "")
    return table


def _contacts_table(contacts: list[dict], within: float, rows: int = 10) -> Table:
    """Robot-body, robot-robot and body-body pairs; parts named link:NAME or body:NAME."""
    table = Table(title=f"start state: pairs closer than {within * 100:g} cm, closest first "
                        "(two obstacles are not paired)", title_justify="left")
    table.add_column("pair")
    table.add_column("part")
    table.add_column("other part")
    table.add_column("distance (mm)", justify="right")
    for c in contacts[:rows]:
        mm = c["distance"] * 1000
        table.add_row(c.get("kind", ""), c["a"], c["b"], f"{0.0 if abs(mm) < 0.05 else mm:.1f}")
    if len(contacts) > rows:
        table.add_row(f"... {len(contacts) - rows} more (see --json)", "", "", "")
    return table


def _size(body: dict) -> str:
    size = body.get("size") or []
    if body["shape"] == "box":
        return "x".join(_mm(v) for v in size)
    if body["shape"] == "cylinder":
        return f"r {_mm(size[0])} h {_mm(size[1])}"
    if body["shape"] == "sphere":
        return f"r {_mm(size[0])}"
    scale = body.get("scale") or [1.0]
    factor = f"{scale[0]:g}" if len(set(scale)) == 1 else " ".join(f"{v:g}" for v in scale)
    return f"{Path(body.get('file') or '?').name} x {factor}"


def _xyz(values) -> str:
    return " ".join(_mm(v) for v in values)


def _pose(values) -> str:
    """[x, y, z] or [x, y, z, qx, qy, qz, qw] as the position, then the turn when there is one."""
    rotation = _rotation(values[3:7]) if len(values) == 7 else "-"
    return _xyz(values[:3]) + ("" if rotation == "-" else f", {rotation}")


def _mm(value: float) -> str:
    """Metres to the millimetre, without trailing zeros (and without "-0")."""
    return f"{round(value, 3) + 0.0:g}"


def _rotation(quat: list[float]) -> str:
    """A quaternion (x, y, z, w) as yaw, or roll pitch yaw, in degrees; "-" when identity."""
    qx, qy, qz, qw = quat
    roll = math.degrees(math.atan2(2 * (qw * qx + qy * qz), 1 - 2 * (qx * qx + qy * qy)))
    pitch = math.degrees(math.asin(max(-1.0, min(1.0, 2 * (qw * qy - qz * qx)))))
    yaw = math.degrees(math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz)))
    if abs(roll) >= 0.05 or abs(pitch) >= 0.05:
        return f"rpy {roll:.1f} {pitch:.1f} {yaw:.1f}°"
    if abs(yaw) >= 0.05:
        return f"yaw {yaw:.1f}°"
    return "-"


def _types_text(types: dict[str, list[str]]) -> str:
    if not types:
        return "-"
    return ", ".join(name if parents == ["object"] else f"{name} < {'|'.join(parents)}"
                     for name, parents in types.items())


def _arities(table: dict[str, int]) -> str:
    return ", ".join(f"{name}/{arity}" for name, arity in table.items())
